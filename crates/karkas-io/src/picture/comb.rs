//! The scale of a curvature comb in a picture.
//!
//! A comb scaled to its longest tooth shows only the sharpest bend (an airfoil's leading
//! edge) and is flat everywhere else. Here the teeth (equally spaced along the curve) are
//! scaled so that the `PERCENTILE` (0.8) percentile of their lengths is `TOOTH_FRACTION` (0.07) of
//! the curve's extent, the factor rounded to two significant digits so that the legend reads
//! "tooth length = curvature x S". The 80th rather than the 90th percentile: on an airfoil
//! the tenth of the arc round the nose holds the top decile of the curvature, so the 90th
//! percentile still lets the nose set the scale and leaves the aft third flat. The few teeth
//! that the scale makes longer than `CLIP` (3) times the percentile tooth (on an airfoil, the
//! nose: about a tenth of the teeth) are clipped to that length, drawn in a darker colour and
//! counted in the legend, so that no tooth leaves the picture and the clipped ones stay
//! recognisable.

/// The percentile of the curvature magnitudes that sets the scale.
const PERCENTILE: f64 = 0.8;
/// The length of the percentile tooth as a fraction of the curve's extent.
const TOOTH_FRACTION: f64 = 0.07;
/// Teeth are clipped at this many times the percentile tooth.
const CLIP: f64 = 3.0;
/// The most teeth drawn as lines (every so many of the teeth; the envelope runs through the
/// tips of all of them).
pub(crate) const DRAWN_TEETH: usize = 300;

/// A comb ready to draw.
#[derive(Clone, Debug, PartialEq)]
pub struct ScaledComb {
    /// The teeth from the curve to their tips, in model units, and whether each was clipped.
    pub teeth: Vec<([(f64, f64); 2], bool)>,
    /// Every how many teeth one is drawn as a line (at most `DRAWN_TEETH` (300) drawn).
    pub stride: usize,
    /// Model units of tooth length per unit of curvature (square model units).
    pub factor: f64,
    /// The longest tooth drawn, in model units.
    pub cap: f64,
    /// How many of the drawn teeth were clipped.
    pub clipped: usize,
}

impl ScaledComb {
    /// The comb of the `teeth` (each a foot on the curve and the curvature vector there:
    /// length the curvature, pointing away from the centre of curvature) of a curve whose
    /// extent (the larger side of its bounding box) is `extent`.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::Point;
    /// use karkas_io::picture::comb::ScaledComb;
    ///
    /// // Two teeth of curvature 1 and 2 on a curve 10 across.
    /// let teeth = [[Point([0.0, 0.0]), Point([0.0, 1.0])], [Point([1.0, 0.0]), Point([0.0, 2.0])]];
    /// let comb = ScaledComb::new(&teeth, 10.0);
    /// assert_eq!(comb.teeth.len(), 2);
    /// assert!(comb.factor > 0.0 && comb.clipped == 0);
    /// ```
    pub fn new(teeth: &[[karkas::Point2; 2]], extent: f64) -> ScaledComb {
        let finite: Vec<&[karkas::Point2; 2]> = teeth
            .iter()
            .filter(|t| t[0].is_finite() && t[1].is_finite())
            .collect();
        let mut lengths: Vec<f64> = finite.iter().map(|t| t[1].norm()).collect();
        lengths.sort_by(f64::total_cmp);
        let reference = percentile(&lengths, PERCENTILE)
            .filter(|&k| k > 0.0)
            .or_else(|| lengths.last().copied().filter(|&k| k > 0.0));
        let factor = match reference {
            Some(k) if extent > 0.0 && extent.is_finite() => {
                two_digits(TOOTH_FRACTION * extent / k)
            }
            _ => 0.0,
        };
        let cap = CLIP * TOOTH_FRACTION * extent;
        let teeth: Vec<([(f64, f64); 2], bool)> = finite
            .into_iter()
            .map(|t| {
                let (p, v) = (t[0], t[1] * factor);
                let length = v.norm();
                let over = length > cap;
                let v = if over { v * (cap / length) } else { v };
                ([(p[0], p[1]), (p[0] + v[0], p[1] + v[1])], over)
            })
            .collect();
        let stride = teeth.len().div_ceil(DRAWN_TEETH).max(1);
        let clipped = teeth.iter().step_by(stride).filter(|t| t.1).count();
        ScaledComb {
            teeth,
            stride,
            factor,
            cap,
            clipped,
        }
    }

    /// The teeth drawn as lines: every [`stride`](Self::stride)th.
    pub fn drawn(&self) -> impl Iterator<Item = &([(f64, f64); 2], bool)> {
        self.teeth.iter().step_by(self.stride)
    }

    /// The legend line: the scale, and the clipped teeth if any.
    pub fn legend(&self) -> String {
        let mut text = format!(
            "comb: tooth length = curvature \u{d7} {}",
            significant(self.factor),
        );
        if self.clipped > 0 {
            text.push_str(&format!(
                "; {} of {} teeth (dark) clipped at {}",
                self.clipped,
                self.drawn().count(),
                significant(self.cap)
            ));
        }
        text
    }
}

/// The `q` quantile of the sorted `values` (nearest rank), none for no values.
fn percentile(sorted: &[f64], q: f64) -> Option<f64> {
    let last = sorted.len().checked_sub(1)?;
    Some(sorted[((q * last as f64).round() as usize).min(last)])
}

/// `x` rounded to two significant digits.
fn two_digits(x: f64) -> f64 {
    // Through the decimal text, so that the factor is the double nearest its printed value.
    format!("{x:.1e}").parse().unwrap_or(x)
}

/// `x` with up to three significant digits, without trailing zeros.
fn significant(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return "0".to_owned();
    }
    let magnitude = x.abs().log10().floor();
    if !(-4.0..6.0).contains(&magnitude) {
        return format!("{x:.2e}");
    }
    let decimals = (2.0 - magnitude).max(0.0) as usize;
    let text = format!("{x:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use karkas::Point2;

    #[test]
    fn the_percentile_sets_the_scale_and_outliers_are_clipped() {
        // 100 teeth of curvature 1 to 100 (in steps of 1), and one of 10^4.
        let mut teeth: Vec<[Point2; 2]> = (1..=100)
            .map(|k| [Point2::new([k as f64, 0.0]), Point2::new([0.0, k as f64])])
            .collect();
        teeth.push([Point2::new([0.0, 0.0]), Point2::new([0.0, 1e4])]);
        let comb = ScaledComb::new(&teeth, 10.0);
        // The 80th percentile (nearest rank of 101 values) is 81: 0.7 / 81 = 0.00864...
        assert_eq!(comb.factor, 0.0086);
        assert!((comb.cap - 2.1).abs() < 1e-12);
        // Teeth over 2.1 / 0.0086 = 244 in curvature: only the last.
        assert_eq!(comb.clipped, 1);
        let (tooth, clipped) = comb.teeth[100];
        assert!(clipped && (tooth[1].1 - 2.1).abs() < 1e-12);
        let (tooth, clipped) = comb.teeth[49];
        assert!(!clipped && (tooth[1].1 - 50.0 * 0.0086).abs() < 1e-12);
        let legend = comb.legend();
        assert!(legend.contains("curvature \u{d7} 0.0086"), "{legend}");
        assert!(
            legend.contains("1 of 101 teeth (dark) clipped at 2.1"),
            "{legend}"
        );
    }

    #[test]
    fn a_straight_line_has_a_flat_comb() {
        let teeth = [[Point2::new([0.0, 0.0]), Point2::new([0.0, 0.0])]; 3];
        let comb = ScaledComb::new(&teeth, 1.0);
        assert_eq!((comb.factor, comb.clipped), (0.0, 0));
        assert_eq!(significant(1234.6), "1235");
        assert_eq!(significant(0.012345), "0.0123");
    }
}
