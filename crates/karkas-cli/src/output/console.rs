//! The lines a command prints about its work ("wrote ...", warnings, its figures), and their
//! capture in a batch.
//!
//! A command run by `karkas batch` (or `karkas.batch` in Python) runs on a worker thread
//! inside [`capture`]: its lines are kept for the input's record instead of interleaving on the
//! terminal, and its figures ([`record`]) become the record's `summary`. Outside a capture the
//! lines go to standard error and the figures nowhere.

use serde_json::{Map, Value};
use std::cell::RefCell;

/// What a command said while captured: its lines (without the `karkas: ` prefix) and its
/// figures.
#[derive(Debug, Default)]
pub struct Captured {
    /// The lines the command would have printed on standard error.
    pub messages: Vec<String>,
    /// The figures the command recorded, by name.
    pub figures: Map<String, Value>,
}

thread_local! {
    static CAPTURE: RefCell<Option<Captured>> = const { RefCell::new(None) };
}

/// Prints `line` on standard error, or keeps it when captured.
pub fn note(line: String) {
    let kept = CAPTURE.with(|c| match c.borrow_mut().as_mut() {
        Some(captured) => {
            let text = line.strip_prefix("karkas: ").unwrap_or(&line);
            captured.messages.push(text.to_owned());
            true
        }
        None => false,
    });
    if !kept {
        eprintln!("{line}");
    }
}

/// True while the command runs inside [`capture`] (its standard output lines are then left
/// out: the figures are in the record).
pub fn is_capturing() -> bool {
    CAPTURE.with(|c| c.borrow().is_some())
}

/// Records the figure `name` of the command's result, when captured.
pub fn record(name: &str, value: impl Into<Value>) {
    CAPTURE.with(|c| {
        if let Some(captured) = c.borrow_mut().as_mut() {
            captured.figures.insert(name.to_owned(), value.into());
        }
    });
}

/// Records every field of the object `figures` (other values are ignored), when captured.
pub fn record_all(figures: Value) {
    if let Value::Object(map) = figures {
        for (name, value) in map {
            record(&name, value);
        }
    }
}

/// Runs `work` with its lines and figures captured on this thread, and returns them with its
/// result.
pub fn capture<R>(work: impl FnOnce() -> R) -> (R, Captured) {
    CAPTURE.with(|c| *c.borrow_mut() = Some(Captured::default()));
    // The capture ends even when `work` panics (the batch catches the panic).
    struct End;
    impl Drop for End {
        fn drop(&mut self) {
            let _ = CAPTURE.try_with(|c| c.borrow_mut().take());
        }
    }
    let end = End;
    let result = work();
    let captured = CAPTURE.with(|c| c.borrow_mut().take()).unwrap_or_default();
    drop(end);
    (result, captured)
}

/// Ends farther apart than this share of the points' size are taken for an open curve that
/// `--closed` (or periodic ends) joins on purpose, not for a near miss.
const NEAR_MISS_SHARE: f64 = 1e-2;

/// Warns when an option closes `points` (`option`, e.g. `--closed`) and their last point
/// misses the first by a little: more than rounding (`1e-12` of the largest coordinate) and at
/// most `NEAR_MISS_SHARE` (1e-2) of the diagonal of the points' bounding box. The curve then closes
/// through a short extra piece between them rather than at the point the user meant.
pub fn warn_near_miss<const D: usize>(option: &str, points: &[karkas::Point<D>]) {
    if let Some((gap, size)) = near_miss(points, 1e-12) {
        note(format!(
            "karkas: warning: {option}: the last point is {gap:.1e} from the first ({:.1e} of \
             the size): the curve closes through a short piece between them; repeat the first \
             point exactly to close at it",
            gap / size
        ));
    }
}

/// Warns when the ends of an open curve through `points` nearly meet: the last point misses
/// the first by more than the rule that makes them one point
/// ([`karkas::fit::SHARED_END_TOLERANCE`] of the diagonal of the points' bounding box) and by
/// at most `NEAR_MISS_SHARE` (1e-2) of it. The curve then stays open (a blunt trailing edge, or a
/// sharp one given with a small error); `remedy` names the option that closes it.
pub fn warn_open_near_miss<const D: usize>(points: &[karkas::Point<D>], remedy: &str) {
    if let Some((gap, size)) = near_miss(points, karkas::fit::SHARED_END_TOLERANCE) {
        note(format!(
            "karkas: warning: the last point is {gap:.1e} from the first ({:.1e} of the \
             size): the curve stays open there; {remedy}",
            gap / size
        ));
    }
}

/// The distance of the last of `points` from the first and the diagonal of their bounding
/// box, when the distance is above `least` of the diagonal (and of the largest coordinate)
/// and at most `NEAR_MISS_SHARE` (1e-2) of it.
fn near_miss<const D: usize>(points: &[karkas::Point<D>], least: f64) -> Option<(f64, f64)> {
    let (Some(&first), Some(&last)) = (points.first(), points.last()) else {
        return None;
    };
    let scale = points.iter().fold(0.0f64, |m, p| m.max(p.max_abs()));
    let (mut low, mut high) = ([f64::INFINITY; D], [f64::NEG_INFINITY; D]);
    for p in points {
        for c in 0..D {
            low[c] = low[c].min(p[c]);
            high[c] = high[c].max(p[c]);
        }
    }
    let size = (0..D).fold(0.0f64, |d, c| d.hypot(high[c] - low[c]));
    let gap = first.distance(last);
    (points.len() > 2 && gap > 1e-12 * scale && gap > least * size && gap <= NEAR_MISS_SHARE * size)
        .then_some((gap, size))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_and_figures_are_kept_only_inside_a_capture() {
        let ((), captured) = capture(|| {
            note("karkas: wrote a.csv (10 samples)".to_owned());
            record("samples", 10);
            record_all(serde_json::json!({"knots": 4, "max_deviation": 1e-5}));
            assert!(is_capturing());
        });
        assert_eq!(captured.messages, ["wrote a.csv (10 samples)"]);
        assert_eq!(captured.figures["samples"], 10);
        assert_eq!(captured.figures["knots"], 4);
        assert!(!is_capturing());
        record("samples", 11);
        let ((), again) = capture(|| ());
        assert!(again.figures.is_empty() && again.messages.is_empty());
    }
}
