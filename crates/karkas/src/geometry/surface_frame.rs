//! The unit normal, principal curvatures and principal directions of a surface in 3-D, from
//! the first and second fundamental forms.
//!
//! With `S_u, S_v, S_uu, S_uv, S_vv` at `(u, v)`, the unit normal is
//! `n = S_u x S_v / |S_u x S_v|`, the first form `E = S_u . S_u`, `F = S_u . S_v`,
//! `G = S_v . S_v`, the second `L = S_uu . n`, `M = S_uv . n`, `N = S_vv . n`. The principal
//! curvatures are the eigenvalues of the shape operator `I^{-1} II`:
//! `k = H ± sqrt(H^2 - K)` with the mean curvature `H = (E N - 2 F M + G L) / (2 (E G - F^2))`
//! and the Gaussian curvature `K = (L N - M^2) / (E G - F^2)`. Curvatures are signed with
//! respect to `n` (do Carmo's convention): positive where the surface bends towards `n`
//! (a sphere with its outward normal has `k1 = k2 = -1/r`).

use super::curvature::cross;
use crate::core::Surface;
use crate::Point3;

/// Principal curvatures and directions at a point of a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PrincipalCurvatures {
    /// The larger principal curvature.
    pub k1: f64,
    /// The smaller principal curvature.
    pub k2: f64,
    /// The unit tangent direction of `k1`.
    pub dir1: Point3,
    /// The unit tangent direction of `k2` (`dir1 x dir2 = normal`).
    pub dir2: Point3,
    /// The unit normal `S_u x S_v / |S_u x S_v|`.
    pub normal: Point3,
}

impl PrincipalCurvatures {
    /// Gaussian curvature `k1 k2`.
    pub fn gaussian(&self) -> f64 {
        self.k1 * self.k2
    }

    /// Mean curvature `(k1 + k2) / 2`.
    pub fn mean(&self) -> f64 {
        0.5 * (self.k1 + self.k2)
    }

    const UNDEFINED: Self = PrincipalCurvatures {
        k1: f64::NAN,
        k2: f64::NAN,
        dir1: Point3::new([f64::NAN; 3]),
        dir2: Point3::new([f64::NAN; 3]),
        normal: Point3::new([f64::NAN; 3]),
    };
}

/// The unit normal `S_u x S_v / |S_u x S_v|` at `(u, v)`; NaN where the surface is singular
/// (`S_u x S_v = 0`).
pub fn normal<S: Surface<3> + ?Sized>(surface: &S, u: f64, v: f64) -> Point3 {
    let (su, sv) = (surface.deriv(u, v, 1, 0), surface.deriv(u, v, 0, 1));
    let scale = 1.0 / largest_coordinate(su, sv);
    let n = cross(su * scale, sv * scale);
    let len = n.norm();
    if len > 0.0 {
        n * (1.0 / len)
    } else {
        Point3::new([f64::NAN; 3])
    }
}

/// The principal curvatures and directions at `(u, v)`; every field NaN where the surface is
/// singular. At an umbilic (`k1 = k2`) the directions are `S_u / |S_u|` and `n x` it.
pub fn principal_curvatures<S: Surface<3> + ?Sized>(
    surface: &S,
    u: f64,
    v: f64,
) -> PrincipalCurvatures {
    // The derivatives are divided by the largest coordinate of the first ones, which is the
    // surface scaled by `1 / sigma`: its curvatures are `sigma` times the true ones. Products
    // of derivatives then neither overflow (coordinates near 1e150) nor underflow (near
    // 1e-150).
    let (su, sv) = (surface.deriv(u, v, 1, 0), surface.deriv(u, v, 0, 1));
    let sigma = largest_coordinate(su, sv);
    if !(sigma.is_finite() && sigma > 0.0) {
        return PrincipalCurvatures::UNDEFINED;
    }
    let scale = 1.0 / sigma;
    let (su, sv) = (su * scale, sv * scale);
    let cr = cross(su, sv);
    let len = cr.norm();
    if len.is_nan() || len <= 0.0 {
        return PrincipalCurvatures::UNDEFINED;
    }
    let n = cr * (1.0 / len);
    let (e, f, g) = (su.dot(su), su.dot(sv), sv.dot(sv));
    let l = (surface.deriv(u, v, 2, 0) * scale).dot(n);
    let m = (surface.deriv(u, v, 1, 1) * scale).dot(n);
    let nn = (surface.deriv(u, v, 0, 2) * scale).dot(n);
    let det = e * g - f * f;
    if det.is_nan() || det <= 0.0 {
        return PrincipalCurvatures::UNDEFINED;
    }
    let h = (e * nn - 2.0 * f * m + g * l) / (2.0 * det);
    // The shape operator in the basis (S_u, S_v); H^2 - K from its entries keeps accuracy
    // near umbilics.
    let (a11, a12, a21, a22) = (
        (g * l - f * m) / det,
        (g * m - f * nn) / det,
        (e * m - f * l) / det,
        (e * nn - f * m) / det,
    );
    let half_diff = 0.5 * (a11 - a22);
    let disc = (half_diff * half_diff + a12 * a21).max(0.0).sqrt();
    let (k1, k2) = (h + disc, h - disc);
    let dir1 = direction(su, sv, n, a11, a12, a21, a22, k1);
    let dir2 = cross(n, dir1);
    PrincipalCurvatures {
        k1: k1 * scale,
        k2: k2 * scale,
        dir1,
        dir2,
        normal: n,
    }
}

/// The unit tangent `a S_u + b S_v` with `(a, b)` an eigenvector of the shape operator
/// `[[a11, a12], [a21, a22]]` (acting on the coordinates `(a, b)`) for `k`; `S_u / |S_u|`
/// at an umbilic.
#[allow(clippy::too_many_arguments)]
fn direction(
    su: Point3,
    sv: Point3,
    n: Point3,
    a11: f64,
    a12: f64,
    a21: f64,
    a22: f64,
    k: f64,
) -> Point3 {
    // Rows of (A - k I): (a11 - k, a12) and (a21, a22 - k); an eigenvector is orthogonal to
    // the larger row.
    let r1 = (a11 - k, a12);
    let r2 = (a21, a22 - k);
    let scale = a11.abs() + a12.abs() + a21.abs() + a22.abs();
    let (row, size) = if r1.0.hypot(r1.1) >= r2.0.hypot(r2.1) {
        (r1, r1.0.hypot(r1.1))
    } else {
        (r2, r2.0.hypot(r2.1))
    };
    let t = if size > 1e-10 * scale {
        su * (-row.1) + sv * row.0
    } else {
        su
    };
    let t = t - n * t.dot(n);
    let len = t.norm();
    if len > 0.0 {
        t * (1.0 / len)
    } else {
        su * (1.0 / su.norm())
    }
}

/// The largest absolute coordinate of `a` and `b` (the scale of the first derivatives).
fn largest_coordinate(a: Point3, b: Point3) -> f64 {
    a.0.iter().chain(&b.0).fold(0.0, |m: f64, x| m.max(x.abs()))
}
