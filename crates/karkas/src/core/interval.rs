//! Closed parameter intervals.

/// A closed interval `[start, end]` of a parameter, `start <= end`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// Lower end.
    pub start: f64,
    /// Upper end.
    pub end: f64,
}

impl Interval {
    /// The interval `[start, end]`.
    ///
    /// ```
    /// use karkas::Interval;
    ///
    /// let domain = Interval::new(0.0, 2.0);
    /// assert_eq!(domain.length(), 2.0);
    /// assert!(domain.contains(1.5));
    /// assert_eq!(domain.uniform(1, 3), 1.0); // the middle of three uniform parameters
    /// ```
    pub const fn new(start: f64, end: f64) -> Self {
        Interval { start, end }
    }

    /// `end - start`.
    #[inline]
    pub fn length(&self) -> f64 {
        self.end - self.start
    }

    /// True when `t` lies in the interval, ends included.
    #[inline]
    pub fn contains(&self, t: f64) -> bool {
        t >= self.start && t <= self.end
    }

    /// `t` clamped into the interval (NaN stays NaN).
    #[inline]
    pub fn clamp(&self, t: f64) -> f64 {
        if t < self.start {
            self.start
        } else if t > self.end {
            self.end
        } else {
            t
        }
    }

    /// `t` wrapped into `[start, end)` by whole periods `end - start`.
    #[inline]
    pub fn wrap(&self, t: f64) -> f64 {
        let len = self.length();
        let w = self.start + (t - self.start).rem_euclid(len);
        // rem_euclid may round up to `len` itself for t just below a period boundary.
        if w >= self.end {
            self.start
        } else {
            w
        }
    }

    /// The `k`-th of `n` uniformly spaced values from `start` to `end`, ends included
    /// (`n >= 2`; `n == 1` gives `start`). The last value is exactly `end`.
    #[inline]
    pub fn uniform(&self, k: usize, n: usize) -> f64 {
        if n < 2 {
            return self.start;
        }
        if k + 1 == n {
            return self.end;
        }
        self.start + self.length() * (k as f64 / (n - 1) as f64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrap_clamp_uniform() {
        let i = Interval::new(0.25, 0.75);
        assert_eq!(i.length(), 0.5);
        assert_eq!(i.clamp(1.0), 0.75);
        assert_eq!(i.clamp(-1.0), 0.25);
        assert!(i.clamp(f64::NAN).is_nan());
        assert!((i.wrap(0.8) - 0.3).abs() < 1e-15);
        assert!((i.wrap(0.2) - 0.7).abs() < 1e-15);
        assert_eq!(i.wrap(0.75), 0.25);
        assert_eq!(i.uniform(0, 3), 0.25);
        assert_eq!(i.uniform(1, 3), 0.5);
        assert_eq!(i.uniform(2, 3), 0.75);
    }
}
