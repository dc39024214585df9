//! The whole body from a loft of its half ([`Loft::mirrored`]): a ship's hull from the half
//! sections of its table of offsets, mirrored about the centre plane (docs/methods.md §7.2).
//!
//! One smooth knot vector through a whole hull section rounds its V at the keel (a Wigley
//! section's two sides meet there at an angle). The half sections are fitted instead, and the
//! surface's control net is mirrored: the whole section runs from the mirrored deck edge
//! (`v = 0`) down to the keel (`v = 1/2`, a knot of full multiplicity, so the section may have a
//! corner there) and up to the deck edge (`v = 1`). Its halves are the half loft and its mirror
//! image exactly, so the whole surface is symmetric to rounding and as close to the offsets as
//! the half loft. Where the half sections start off the centre plane (a flat bottom) the two
//! halves are joined by the straight line between the mirrored start points, over
//! `[0.45, 0.55]` of `v`.

use super::surface::Loft;
use crate::bspline::BSplineSurface;
use crate::core::Grid;
use crate::{Error, Point3, Result};

/// Half the `v` range of a flat bottom between the two halves (when there is one).
const FLAT_HALF_WIDTH: f64 = 0.05;

impl Loft {
    /// The whole body: this loft (its sections starting at `v = 0` on or near the mirror
    /// plane) and its mirror image about the plane where coordinate `axis` is 0, as one
    /// surface (see the module docs). The sections' start points lie on the plane when their
    /// coordinate `axis` is within `1e-12` of the body's size of 0 on every row of the control
    /// net; they are then put on it exactly and shared by both halves. Otherwise a flat bottom
    /// joins the halves.
    ///
    /// Errors: an `axis` other than 0, 1 or 2 ([`Error::InvalidSetting`]); a loft whose
    /// sections have a point fixed at `v = 1/2` (a wing, already whole).
    pub fn mirrored(&self, axis: usize) -> Result<Loft> {
        if axis > 2 {
            return Err(Error::InvalidSetting {
                name: "mirror axis",
                value: axis as f64,
                reason: "must be 0, 1 or 2",
            });
        }
        if self.split {
            return Err(Error::InvalidSetting {
                name: "mirror of sections with a middle point at v",
                value: 0.5,
                reason: "only a half body (sections from the mirror plane out) can be mirrored",
            });
        }
        let half = &self.surface;
        let net = half.control_points();
        let (rows, n) = (net.rows(), net.cols());
        let size = net
            .as_slice()
            .iter()
            .flat_map(|p| p.0)
            .fold(0.0f64, |m, c| m.max(c.abs()));
        let on_plane = (0..rows).all(|i| net.get(i, 0)[axis].abs() <= 1e-12 * size);
        let mirror = |p: Point3| {
            let mut q = p;
            q[axis] = -q[axis];
            q
        };
        let interior = &half.knots_v()[4..half.knots_v().len() - 4];
        let (a, b) = if on_plane {
            (0.5, 0.5)
        } else {
            (0.5 - FLAT_HALF_WIDTH, 0.5 + FLAT_HALF_WIDTH)
        };
        // Port half over [0, a] (the half's knots reversed), starboard half over [b, 1].
        let mut knots = vec![0.0; 4];
        knots.extend(interior.iter().rev().map(|t| a * (1.0 - t)));
        knots.extend([a; 3]);
        if !on_plane {
            knots.extend([b; 3]);
        }
        knots.extend(interior.iter().map(|t| b + (1.0 - b) * t));
        knots.extend([1.0; 4]);
        let cols = if on_plane { 2 * n - 1 } else { 2 * n + 2 };
        let control = Grid::from_fn(rows, cols, |i, j| {
            let keel = {
                let mut p = *net.get(i, 0);
                if on_plane {
                    p[axis] = 0.0;
                }
                p
            };
            let at = |k: usize| if k == 0 { keel } else { *net.get(i, k) };
            if j < n {
                mirror(at(n - 1 - j))
            } else if on_plane {
                at(j - (n - 1))
            } else if j < n + 2 {
                // The flat bottom: a straight segment, its inner control points at thirds.
                let t = (j + 1 - n) as f64 / 3.0;
                mirror(keel) * (1.0 - t) + keel * t
            } else {
                at(j - (n + 2))
            }
        });
        let surface = BSplineSurface::new(
            (half.degree_u(), half.knots_u().to_vec()),
            (3, knots),
            control,
        )?;
        Ok(Loft {
            surface,
            split: true,
            ..self.clone()
        })
    }
}
