//! The reference LL surface of docs/methods.md §1.3 and its test grids.

use super::{extend, RefKernel};
use crate::common::max_abs;
use karkas::{Grid, Point};

// ------------------------------------------------------------------------------------------
// Reference surface (§1.3)
// ------------------------------------------------------------------------------------------

/// A 3-D test grid: open directions are a generic bent sheet, closed ones go round
/// (a perturbed torus when both are closed). No repeated row or column.
pub fn surface_grid(kx: usize, ky: usize, closed_u: bool, closed_v: bool) -> Grid<Point<3>> {
    use std::f64::consts::TAU;
    Grid::from_fn(kx, ky, |i, j| {
        let a = if closed_u {
            TAU * i as f64 / kx as f64
        } else {
            0.45 * i as f64
        };
        let b = if closed_v {
            TAU * j as f64 / ky as f64
        } else {
            0.5 * j as f64
        };
        let r = 2.0 + 0.6 * b.cos() + 0.15 * (2.0 * a + 3.0 * b).sin();
        Point([
            r * a.cos() + 0.05 * (j * j) as f64,
            r * a.sin(),
            0.6 * b.sin() + 0.1 * (a + 1.7 * b).cos(),
        ])
    })
}

/// `grid` with its first row appended (`rows`) and/or its first column appended (`cols`).
pub fn with_repeats<const D: usize>(g: &Grid<Point<D>>, rows: bool, cols: bool) -> Grid<Point<D>> {
    let (r, c) = (g.rows() + rows as usize, g.cols() + cols as usize);
    Grid::from_fn(r, c, |i, j| *g.get(i % g.rows(), j % g.cols()))
}

/// An LL surface from the definition of §1.3: closing, extension (20) with the explicit
/// corner rule `r_00 = 4 r_11 - 2 r_21 - 2 r_12 + r_22` for open-open corners, and the
/// tensor product of the curve weights.
pub struct RefSurface<const D: usize> {
    pub kernel: RefKernel,
    /// `ext[i][j]`, i = 0..Kx+1, j = 0..Ky+1.
    pub ext: Vec<Vec<Point<D>>>,
}

impl<const D: usize> RefSurface<D> {
    pub fn new(g: &Grid<Point<D>>, l: usize, closed_u: bool, closed_v: bool) -> Self {
        let mut rows: Vec<Vec<Point<D>>> = (0..g.rows()).map(|i| g.row(i).to_vec()).collect();
        if closed_v && rows.iter().any(|r| r[0] != r[r.len() - 1]) {
            for r in &mut rows {
                r.push(r[0]);
            }
        }
        if closed_u && rows[0] != rows[rows.len() - 1] {
            rows.push(rows[0].clone());
        }
        Self::from_control(&rows, l, closed_u, closed_v)
    }

    /// From a control grid that already repeats in its closed directions.
    pub fn from_control(rows: &[Vec<Point<D>>], l: usize, closed_u: bool, closed_v: bool) -> Self {
        let (kx, ky) = (rows.len(), rows[0].len());
        let vext: Vec<Vec<Point<D>>> = rows.iter().map(|r| extend(r, closed_v)).collect();
        let mut ext = vec![vec![Point::ZERO; ky + 2]; kx + 2];
        for j in 0..ky + 2 {
            let col: Vec<Point<D>> = vext.iter().map(|r| r[j]).collect();
            for (i, p) in extend(&col, closed_u).into_iter().enumerate() {
                ext[i][j] = p;
            }
        }
        if !closed_u && !closed_v {
            // The corner rule of (20), written out.
            for (ci, a, a2) in [(0, 1, 2), (kx + 1, kx, kx - 1)] {
                for (cj, b, b2) in [(0, 1, 2), (ky + 1, ky, ky - 1)] {
                    ext[ci][cj] =
                        ext[a][b] * 4.0 - ext[a2][b] * 2.0 - ext[a][b2] * 2.0 + ext[a2][b2];
                }
            }
        }
        RefSurface {
            kernel: RefKernel::new(l),
            ext,
        }
    }

    pub fn kx(&self) -> usize {
        self.ext.len() - 2
    }

    pub fn ky(&self) -> usize {
        self.ext[0].len() - 2
    }

    pub fn scale_u(&self) -> f64 {
        (self.kx() + 1) as f64
    }

    pub fn scale_v(&self) -> f64 {
        (self.ky() + 1) as f64
    }

    /// The control point `r_ij` (1-based, 0 and K+1 are the extension).
    pub fn r(&self, i: usize, j: usize) -> Point<D> {
        self.ext[i][j]
    }

    /// `d^(ku+kv) P / du^ku dv^kv` on cell (i, j) at local (xi, eta).
    pub fn cell(
        &self,
        (i, xi): (usize, f64),
        (j, eta): (usize, f64),
        ku: usize,
        kv: usize,
    ) -> Point<D> {
        let wu = self.kernel.weights(xi, ku);
        let wv = self.kernel.weights(eta, kv);
        let mut p = Point::ZERO;
        for (a, wa) in wu.iter().enumerate() {
            for (b, wb) in wv.iter().enumerate() {
                p += self.ext[i - 1 + a][j - 1 + b] * (wa * wb);
            }
        }
        p * (self.scale_u().powi(ku as i32) * self.scale_v().powi(kv as i32))
    }

    fn locate(x: f64, scale: f64, k: usize) -> (usize, f64) {
        let s = x * scale + 0.5;
        let near = s.round();
        let i = if (s - near).abs() < 1e-13 {
            near
        } else {
            s.floor()
        };
        let i = (i as usize).clamp(1, k);
        (i, s - i as f64)
    }

    pub fn locate_u(&self, u: f64) -> (usize, f64) {
        Self::locate(u, self.scale_u(), self.kx())
    }

    pub fn locate_v(&self, v: f64) -> (usize, f64) {
        Self::locate(v, self.scale_v(), self.ky())
    }

    /// The partial derivative at (u, v) inside the domain.
    pub fn at(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point<D> {
        self.cell(self.locate_u(u), self.locate_v(v), ku, kv)
    }

    pub fn size(&self) -> f64 {
        self.ext.iter().fold(1.0, |m, r| m.max(max_abs(r)))
    }

    /// A magnitude for the (ku, kv) partial derivative.
    pub fn deriv_scale(&self, ku: usize, kv: usize) -> f64 {
        self.scale_u().powi(ku as i32)
            * self.scale_v().powi(kv as i32)
            * self.size()
            * self.kernel.max_abs(ku).max(3.0)
            * self.kernel.max_abs(kv).max(3.0)
    }

    /// Error allowance for the (ku, kv) partial (see `deriv_tol`).
    pub fn tol(&self, ku: usize, kv: usize) -> f64 {
        let drift = 64.0 * f64::EPSILON;
        1e-12 * self.deriv_scale(ku, kv)
            + drift * self.kx() as f64 * self.deriv_scale(ku + 1, kv) / self.scale_u()
            + drift * self.ky() as f64 * self.deriv_scale(ku, kv + 1) / self.scale_v()
    }
}
