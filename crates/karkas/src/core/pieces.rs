//! How a curve or a blending family is made of polynomial pieces: what the exact B-spline
//! conversion of a Coons surface needs to know about its curves.

use super::Interval;

/// The piece structure of a piecewise polynomial function of one parameter: its degree (an
/// upper bound on every piece's degree), its breakpoints (the domain ends included,
/// strictly increasing) and its continuity at each inner breakpoint (`C^c` there).
#[derive(Clone, Debug, PartialEq)]
pub struct PolynomialPieces {
    /// The largest degree of a piece.
    pub degree: usize,
    /// Breakpoints `b_0 < .. < b_n`: the domain ends and the piece borders between them.
    pub breaks: Vec<f64>,
    /// The continuity order at `b_1 .. b_{n-1}` (`n - 1` values).
    pub continuity: Vec<usize>,
}

impl PolynomialPieces {
    /// Pieces of degree `degree` on `breaks` with the same continuity at every inner one.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::core::PolynomialPieces;
    ///
    /// let pieces = PolynomialPieces::uniform_continuity(3, vec![0.0, 1.0, 2.0, 3.0], 2);
    /// assert_eq!(pieces.continuity, vec![2, 2]); // one per inner breakpoint
    /// ```
    pub fn uniform_continuity(degree: usize, breaks: Vec<f64>, continuity: usize) -> Self {
        let inner = breaks.len().saturating_sub(2);
        PolynomialPieces {
            degree,
            breaks,
            continuity: vec![continuity; inner],
        }
    }

    /// The same pieces after the affine map sending `from` onto `to`.
    pub fn mapped(mut self, from: Interval, to: Interval) -> Self {
        let ratio = to.length() / from.length();
        for b in &mut self.breaks {
            *b = to.start + (*b - from.start) * ratio;
        }
        // Land exactly on the target ends.
        let n = self.breaks.len();
        if n >= 2 {
            self.breaks[0] = to.start;
            self.breaks[n - 1] = to.end;
        }
        self
    }

    /// The common refinement of `sources` over `domain`: breakpoints of all sources inside
    /// the domain (those closer than `1e-10` of the domain length to one already taken are
    /// merged into it), the largest degree, and at each breakpoint the smallest continuity
    /// of the sources that break there.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::core::PolynomialPieces;
    /// use karkas::Interval;
    ///
    /// let a = PolynomialPieces::uniform_continuity(3, vec![0.0, 1.0, 2.0], 2);
    /// let b = PolynomialPieces::uniform_continuity(1, vec![0.0, 0.5, 2.0], 0);
    /// let both = PolynomialPieces::merge(&[a, b], Interval::new(0.0, 2.0));
    /// assert_eq!(both.breaks, vec![0.0, 0.5, 1.0, 2.0]);
    /// assert_eq!((both.degree, both.continuity.clone()), (3, vec![0, 2]));
    /// ```
    pub fn merge(sources: &[PolynomialPieces], domain: Interval) -> Self {
        let tolerance = 1e-10 * domain.length();
        let degree = sources.iter().map(|s| s.degree).max().unwrap_or(1);
        let mut inner: Vec<(f64, usize)> = sources
            .iter()
            .flat_map(|s| {
                let n = s.breaks.len();
                (1..n.saturating_sub(1)).map(move |k| (s.breaks[k], s.continuity[k - 1]))
            })
            .filter(|(b, _)| *b > domain.start + tolerance && *b < domain.end - tolerance)
            .collect();
        inner.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut breaks = vec![domain.start];
        let mut continuity: Vec<usize> = Vec::new();
        for (b, c) in inner {
            let last = breaks.len() - 1;
            if last > 0 && b - breaks[last] <= tolerance {
                let k = continuity.len() - 1;
                continuity[k] = continuity[k].min(c);
            } else {
                breaks.push(b);
                continuity.push(c);
            }
        }
        breaks.push(domain.end);
        PolynomialPieces {
            degree,
            breaks,
            continuity,
        }
    }

    /// The knot multiplicities at the inner breakpoints for degree `degree`:
    /// `degree - continuity`, at least 1.
    pub(crate) fn multiplicities(&self, degree: usize) -> Vec<usize> {
        self.continuity
            .iter()
            .map(|&c| degree.saturating_sub(c).max(1))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn merging_takes_every_break_and_the_weakest_continuity() {
        let blend = PolynomialPieces::uniform_continuity(3, vec![0.0, 0.5, 1.0], 1);
        let curve =
            PolynomialPieces::uniform_continuity(3, vec![0.0, 0.25, 0.5 + 1e-13, 0.75, 1.0], 2);
        let line = PolynomialPieces::uniform_continuity(1, vec![0.0, 1.0], 0);
        let m = PolynomialPieces::merge(&[blend, curve, line], Interval::new(0.0, 1.0));
        assert_eq!(m.degree, 3);
        assert_eq!(m.breaks, vec![0.0, 0.25, 0.5, 0.75, 1.0]);
        assert_eq!(m.continuity, vec![2, 1, 2]);
        assert_eq!(m.multiplicities(3), vec![1, 2, 1]);
        assert_eq!(m.multiplicities(5), vec![3, 4, 3]);
    }

    #[test]
    fn mapping_lands_on_the_target_ends() {
        let p = PolynomialPieces::uniform_continuity(2, vec![0.0, 0.3, 1.0], 1)
            .mapped(Interval::new(0.0, 1.0), Interval::new(2.0, 4.0));
        assert_eq!(p.breaks, vec![2.0, 2.6, 4.0]);
    }
}
