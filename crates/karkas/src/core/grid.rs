//! Rectangular grids of values (points of a surface frame, samples of a surface).

use crate::Error;

/// A `rows x cols` grid stored row-major: element `(i, j)` is at `i * cols + j`.
///
/// For a surface frame, row `i` is the i-th section (the paper's `x = const` line, parameter u)
/// and column `j` runs along it (parameter v).
#[derive(Clone, Debug, PartialEq)]
pub struct Grid<T> {
    rows: usize,
    cols: usize,
    data: Vec<T>,
}

impl<T> Grid<T> {
    /// Wraps row-major `data`; fails unless `data.len() == rows * cols`.
    ///
    /// ```
    /// use karkas::Grid;
    ///
    /// let grid = Grid::from_row_major(2, 2, vec![1, 2, 3, 4])?;
    /// assert_eq!(*grid.get(1, 0), 3);
    /// assert!(Grid::from_row_major(2, 3, vec![1, 2, 3]).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn from_row_major(rows: usize, cols: usize, data: Vec<T>) -> Result<Self, Error> {
        if rows.checked_mul(cols) != Some(data.len()) {
            return Err(Error::GridShape {
                rows,
                cols,
                len: data.len(),
            });
        }
        Ok(Grid { rows, cols, data })
    }

    /// A grid filled by `f(i, j)`.
    ///
    /// ```
    /// use karkas::Grid;
    ///
    /// let grid = Grid::from_fn(2, 3, |i, j| 10 * i + j);
    /// assert_eq!((grid.rows(), grid.cols()), (2, 3));
    /// assert_eq!(*grid.get(1, 2), 12);
    /// ```
    pub fn from_fn(rows: usize, cols: usize, mut f: impl FnMut(usize, usize) -> T) -> Self {
        let mut data = Vec::with_capacity(rows * cols);
        for i in 0..rows {
            for j in 0..cols {
                data.push(f(i, j));
            }
        }
        Grid { rows, cols, data }
    }

    /// Number of rows.
    #[inline]
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Number of columns.
    #[inline]
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Element `(i, j)`; panics when out of range.
    #[inline]
    pub fn get(&self, i: usize, j: usize) -> &T {
        &self.data[i * self.cols + j]
    }

    /// Mutable element `(i, j)`; panics when out of range.
    #[inline]
    pub fn get_mut(&mut self, i: usize, j: usize) -> &mut T {
        &mut self.data[i * self.cols + j]
    }

    /// Row `i` as a slice.
    #[inline]
    pub fn row(&self, i: usize) -> &[T] {
        &self.data[i * self.cols..(i + 1) * self.cols]
    }

    /// The elements, row-major.
    #[inline]
    pub fn as_slice(&self) -> &[T] {
        &self.data
    }

    /// The elements, row-major, mutable.
    #[inline]
    pub fn as_mut_slice(&mut self) -> &mut [T] {
        &mut self.data
    }

    /// Consumes the grid, returning the row-major elements.
    pub fn into_vec(self) -> Vec<T> {
        self.data
    }
}

impl<T: Clone> Grid<T> {
    /// The transposed grid (`cols x rows`).
    pub fn transposed(&self) -> Self {
        Grid::from_fn(self.cols, self.rows, |i, j| self.get(j, i).clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layout_is_row_major() {
        let g = Grid::from_fn(2, 3, |i, j| 10 * i + j);
        assert_eq!(g.as_slice(), &[0, 1, 2, 10, 11, 12]);
        assert_eq!(g.row(1), &[10, 11, 12]);
        assert_eq!(*g.get(1, 2), 12);
        assert_eq!(g.transposed().row(2), &[2, 12]);
        assert!(Grid::from_row_major(2, 2, vec![1, 2, 3]).is_err());
    }
}
