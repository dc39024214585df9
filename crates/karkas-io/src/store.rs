//! Where a streaming reader keeps its points, and how that storage grows.
//!
//! The points of a curve file go either into a `Vec<Point<D>>` (the library's type) or into
//! one flat `Vec<f64>` (the layout NumPy takes): [`Store`] is what both offer, so a reader
//! fills either directly, without a second copy.
//!
//! Growth ([`Growth`]): a vector that doubles holds up to twice the points, and while it
//! moves, three times. When the size of the input is known (a regular file), the number of
//! points is estimated from the bytes read so far and reserved once, with 3 % to spare, so
//! that the memory of a read stays close to the points' own size. Growth never reserves more
//! than the memory cap allows ([`crate::input::max_input_bytes`]); asking for more fails with
//! the cap's error.
//!
//! Hand-written: the policy depends on the input's size and on the cap, which no collection
//! crate knows.

use std::path::Path;

use karkas::Point;

use crate::error::IoError;
use crate::error::Location;
use crate::input::max_input_bytes;
use crate::lines::check_held_at;

/// A growable list of points of dimension `D`.
pub(crate) trait Store<const D: usize>: Default {
    /// Appends a point.
    fn push(&mut self, p: [f64; D]);
    /// Appends points.
    fn extend_from(&mut self, points: &[[f64; D]]);
    /// The number of points.
    fn len(&self) -> usize;
    /// How many points fit without reallocating.
    fn capacity(&self) -> usize;
    /// Makes room for exactly `additional` more points.
    fn reserve_exact(&mut self, additional: usize);
}

impl<const D: usize> Store<D> for Vec<Point<D>> {
    fn push(&mut self, p: [f64; D]) {
        Vec::push(self, Point(p));
    }
    fn extend_from(&mut self, points: &[[f64; D]]) {
        self.extend(points.iter().map(|&p| Point(p)));
    }
    fn len(&self) -> usize {
        Vec::len(self)
    }
    fn capacity(&self) -> usize {
        Vec::capacity(self)
    }
    fn reserve_exact(&mut self, additional: usize) {
        Vec::reserve_exact(self, additional);
    }
}

/// Points stored as one flat array of coordinates, point after point.
#[derive(Debug, Default)]
pub(crate) struct Flat(pub Vec<f64>);

impl<const D: usize> Store<D> for Flat {
    fn push(&mut self, p: [f64; D]) {
        self.0.extend_from_slice(&p);
    }
    fn extend_from(&mut self, points: &[[f64; D]]) {
        self.0.extend_from_slice(points.as_flattened());
    }
    fn len(&self) -> usize {
        self.0.len() / D
    }
    fn capacity(&self) -> usize {
        self.0.capacity() / D
    }
    fn reserve_exact(&mut self, additional: usize) {
        self.0.reserve_exact(additional.saturating_mul(D));
    }
}

/// The growth policy of a store filled from an input of (maybe) known size.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Growth {
    /// The input's size in bytes, when known.
    pub size: Option<u64>,
}

impl Growth {
    /// Makes room for `additional` more points in `store` of dimension `D`, given that the
    /// points up to those take the first `consumed` bytes of the input; fails when the points
    /// would exceed the memory cap, naming the place `at`.
    pub fn grow<const D: usize, S: Store<D>>(
        &self,
        store: &mut S,
        additional: usize,
        consumed: u64,
        at: Location<'_>,
    ) -> Result<(), IoError> {
        let len = store.len();
        let needed = len.saturating_add(additional);
        let point_bytes = (D * std::mem::size_of::<f64>()) as u128;
        check_held_at(at.path, at.line, needed as u128 * point_bytes)?;
        let limit =
            usize::try_from(u128::from(max_input_bytes()) / point_bytes + 1).unwrap_or(usize::MAX);
        let estimate = match self.size {
            Some(size) if needed >= 1024 && consumed > 0 && size > consumed => {
                let total = needed as f64 * size as f64 / consumed as f64;
                (total * 1.03) as usize + 16
            }
            _ => 0,
        };
        let wanted = if estimate > needed {
            estimate
        } else {
            needed.max(len.saturating_mul(2)).max(1024)
        };
        let new_capacity = wanted.min(limit).max(needed);
        store.reserve_exact(new_capacity - len);
        Ok(())
    }
}

/// The size of the input `path` (`-`: standard input) when it is a regular file: what
/// [`Growth`] estimates from.
pub(crate) fn input_size(path: &Path) -> Option<u64> {
    let target = if crate::input::is_stdin(path) {
        Path::new("/dev/stdin")
    } else {
        path
    };
    std::fs::metadata(target)
        .ok()
        .filter(|m| m.is_file())
        .map(|m| m.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn growth_follows_the_estimate() {
        let mut points: Vec<Point<2>> = Vec::new();
        let growth = Growth {
            size: Some(100_000),
        };
        growth
            .grow(&mut points, 1, 0, Location::new(Path::new("p"), 1))
            .unwrap();
        assert_eq!(points.capacity(), 1024);
        for _ in 0..1024 {
            Store::push(&mut points, [0.0, 0.0]);
        }
        // 1025 points in 10 000 bytes: 10 250 in the whole input, 3 % more reserved.
        growth
            .grow(&mut points, 1, 10_000, Location::new(Path::new("p"), 1))
            .unwrap();
        assert_eq!(points.capacity(), 10_573);
        // More than the cap allows: refused, naming the line.
        let e = growth
            .grow(
                &mut points,
                usize::MAX / 2,
                10_000,
                Location::new(Path::new("p"), 7),
            )
            .unwrap_err();
        assert!(e
            .to_string()
            .starts_with("p:7: the input needs more than the memory cap"));
        let mut flat = Flat::default();
        Growth { size: None }
            .grow::<3, _>(&mut flat, 1, 0, Location::new(Path::new("p"), 1))
            .unwrap();
        assert_eq!(Store::<3>::capacity(&flat), 1024);
    }
}
