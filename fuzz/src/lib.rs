//! Shared input decoding for the fuzz targets: fuzz bytes turned into counts, flags and
//! floating-point numbers that reach the interesting values (zero, tiny, huge, non-finite)
//! often, not only by chance.

use karkas::{Grid, Point};

/// Reads small numbers and floats off the fuzz input; yields zeros once it is exhausted.
pub struct Input<'a> {
    bytes: &'a [u8],
}

impl<'a> Input<'a> {
    /// Wraps the fuzz input.
    pub fn new(bytes: &'a [u8]) -> Self {
        Input { bytes }
    }

    /// The next byte (0 when exhausted).
    pub fn byte(&mut self) -> u8 {
        match self.bytes.split_first() {
            Some((&b, rest)) => {
                self.bytes = rest;
                b
            }
            None => 0,
        }
    }

    /// A count in `lo..=hi`.
    pub fn count(&mut self, lo: usize, hi: usize) -> usize {
        lo + usize::from(self.byte()) % (hi - lo + 1)
    }

    /// A flag.
    pub fn flag(&mut self) -> bool {
        self.byte() & 1 == 1
    }

    /// A float: mostly small multiples of 1/16 (realistic coordinates, with repeats), sometimes
    /// an arbitrary bit pattern or a special value.
    pub fn float(&mut self) -> f64 {
        let tag = self.byte();
        match tag {
            0..=199 => {
                let hi = self.byte();
                f64::from(i16::from_le_bytes([tag, hi])) / 16.0 - 8.0
            }
            200..=229 => {
                let mut b = [0u8; 8];
                for x in &mut b {
                    *x = self.byte();
                }
                f64::from_le_bytes(b)
            }
            230 => 0.0,
            231 => 1e150,
            232 => -1e150,
            233 => 1e-150,
            234 => f64::NAN,
            235 => f64::INFINITY,
            236 => f64::NEG_INFINITY,
            237 => f64::MIN_POSITIVE,
            238 => f64::MAX,
            239 => 1e-300,
            _ => f64::from(tag) - 240.0,
        }
    }

    /// A point of `D` floats.
    pub fn point<const D: usize>(&mut self) -> Point<D> {
        let mut p = [0.0; D];
        for x in &mut p {
            *x = self.float();
        }
        Point(p)
    }

    /// `n` points.
    pub fn points<const D: usize>(&mut self, n: usize) -> Vec<Point<D>> {
        (0..n).map(|_| self.point()).collect()
    }

    /// A `rows x cols` grid of points.
    pub fn grid<const D: usize>(&mut self, rows: usize, cols: usize) -> Grid<Point<D>> {
        Grid::from_fn(rows, cols, |_, _| self.point())
    }

    /// `n` floats.
    pub fn floats(&mut self, n: usize) -> Vec<f64> {
        (0..n).map(|_| self.float()).collect()
    }
}

/// Every value of a result that is `Ok` must be finite: a constructor either refuses the
/// input or builds something whose evaluation is finite.
pub fn assert_finite<const D: usize>(what: &str, p: Point<D>) {
    assert!(p.is_finite(), "{what} returned a non-finite point {p:?}");
}
