//! Axis ticks in model units: round values (1, 2 or 5 times a power of ten) at least a given
//! number of pixels apart, and their labels with as many decimals as the step needs and never
//! a negative zero ("-0", "-0.0").

/// The tick values of `range` (start below end) when one model unit is `pixels_per_unit`
/// pixels and ticks are at least `min_gap` pixels apart: the multiples of the step inside the
/// range, and the step.
pub fn tick_values(range: (f64, f64), pixels_per_unit: f64, min_gap: f64) -> (Vec<f64>, f64) {
    let (start, end) = range;
    if !(end > start && pixels_per_unit > 0.0 && start.is_finite() && end.is_finite()) {
        return (Vec::new(), 1.0);
    }
    let step = nice_step(min_gap / pixels_per_unit);
    // A tick on the range's end stays in despite rounding (-0.3 / 0.1 is -2.9999999999999996).
    let (first, last) = ((start / step - 1e-9).ceil(), (end / step + 1e-9).floor());
    let count = last - first;
    if count.is_nan() || count >= 1000.0 {
        return (Vec::new(), step);
    }
    let values = (0..=count as i64)
        .map(|k| (first + k as f64) * step)
        .collect();
    (values, step)
}

/// The smallest of 1, 2, 5 times a power of ten that is at least `least`.
pub fn nice_step(least: f64) -> f64 {
    if !(least > 0.0 && least.is_finite()) {
        return 1.0;
    }
    let power = 10f64.powf(least.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * power)
        .find(|&s| s >= least * (1.0 - 1e-12))
        .unwrap_or(10.0 * power)
}

/// The label of the tick `value` on an axis whose ticks are `step` apart: fixed notation with
/// the decimals the step needs (scientific for very large or small values), a value that
/// rounds to zero written "0".
pub fn tick_label(value: f64, step: f64) -> String {
    let decimals = (-step.log10().floor()).max(0.0) as usize;
    let magnitude = value.abs().max(step);
    let text = if decimals > 6 || magnitude >= 1e7 {
        let digits = ((magnitude / step).log10().ceil().max(0.0) as usize).min(15);
        format!("{value:.digits$e}")
    } else {
        format!("{value:.decimals$}")
    };
    without_negative_zero(text)
}

/// `text` without the sign when it is a negative zero ("-0", "-0.00", "-0e0").
pub fn without_negative_zero(text: String) -> String {
    match text.strip_prefix('-') {
        Some(rest)
            if rest
                .chars()
                .all(|c| matches!(c, '0' | '.' | 'e' | '+' | '-')) =>
        {
            rest.to_owned()
        }
        _ => text,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_are_round() {
        assert_eq!(nice_step(0.13), 0.2);
        assert_eq!(nice_step(3.0), 5.0);
        assert_eq!(nice_step(0.05), 0.05);
        assert_eq!(nice_step(7.0), 10.0);
    }

    #[test]
    fn labels_never_show_a_negative_zero() {
        // -0.1 + 0.1 in steps of 0.1 is not exactly zero.
        let (values, step) = tick_values((-0.3, 0.3), 1000.0, 100.0);
        let labels: Vec<String> = values.iter().map(|&v| tick_label(v, step)).collect();
        assert_eq!(labels, ["-0.3", "-0.2", "-0.1", "0.0", "0.1", "0.2", "0.3"]);
        assert_eq!(tick_label(-1e-17, 0.01), "0.00");
        assert_eq!(tick_label(-0.0, 1.0), "0");
        assert_eq!(tick_label(-2.0, 1.0), "-2");
        assert_eq!(tick_label(1.5e-8, 1e-8), "1.5e-8");
        assert_eq!(without_negative_zero("-0e0".into()), "0e0");
    }
}
