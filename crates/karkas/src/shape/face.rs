//! The parts of a shape: faces bounded by loops of edges, and free curves.

use super::{NurbsCurve, NurbsSurface};
use crate::core::Curve;
use crate::Point3;

/// One edge of a face's loop: a curve over the edge's own stretch of parameter (its ends are
/// the edge's vertices) and the direction the loop runs along it.
#[derive(Clone, Debug, PartialEq)]
pub struct Edge {
    /// The edge's curve over the edge's stretch of its parameter (its domain's ends are the
    /// edge's vertices).
    pub curve: NurbsCurve<3>,
    /// True when the loop runs along the curve from the start of its domain to the end.
    pub forward: bool,
}

impl Edge {
    /// The point of the edge at the share `s` in `[0, 1]` of its way along the loop.
    pub fn point_along(&self, s: f64) -> Point3 {
        self.curve.eval(self.parameter_along(s))
    }

    /// The curve parameter at the share `s` in `[0, 1]` of the edge's way along the loop.
    pub fn parameter_along(&self, s: f64) -> f64 {
        let d = self.curve.domain();
        let s = if self.forward { s } else { 1.0 - s };
        d.start + s * d.length()
    }
}

/// A closed loop of edges bounding a face.
#[derive(Clone, Debug, PartialEq)]
pub struct EdgeLoop {
    /// The edges in the order the loop runs through them.
    pub edges: Vec<Edge>,
    /// True for the outer boundary when the file says which loop it is (STEP
    /// `FACE_OUTER_BOUND`, IGES 144's outer boundary).
    pub outer: bool,
    /// The same loop in the parameters `(u, v)` of the face's surface, curves in loop order
    /// each run from its domain's start to its end, when the file gives it (IGES entity 142);
    /// empty when the parameters are to be found by inverting the edges onto the surface.
    pub parameter_curves: Vec<NurbsCurve<2>>,
}

impl EdgeLoop {
    /// A loop of `edges` (in loop order), without parameter curves.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::shape::EdgeLoop;
    ///
    /// let outer = EdgeLoop::new(Vec::new(), true);
    /// assert!(outer.outer && outer.edges.is_empty() && outer.parameter_curves.is_empty());
    /// ```
    pub fn new(edges: Vec<Edge>, outer: bool) -> EdgeLoop {
        EdgeLoop {
            edges,
            outer,
            parameter_curves: Vec::new(),
        }
    }

    /// The loop run the other way: the edges in the opposite order, each reversed.
    pub fn reversed(mut self) -> EdgeLoop {
        self.edges.reverse();
        for e in &mut self.edges {
            e.forward = !e.forward;
        }
        self.parameter_curves.reverse();
        self.parameter_curves = self
            .parameter_curves
            .iter()
            .map(NurbsCurve::reversed)
            .collect();
        self
    }
}

/// A face: the part of a surface bounded by its loops.
///
/// The loops run so that the face lies to their left seen from the side its normal points
/// to (ISO 10303-42); which loop is outer does not matter to the inside test, which counts
/// crossings of all loops (even-odd).
#[derive(Clone, Debug, PartialEq)]
pub struct Face {
    /// The surface the face lies on.
    pub surface: NurbsSurface<3>,
    /// The bounding loops; none for a face that is the whole surface.
    pub loops: Vec<EdgeLoop>,
    /// True when the face's normal is the surface's `S_u x S_v`, false when it is its
    /// opposite (STEP `ADVANCED_FACE`'s `same_sense`).
    pub same_sense: bool,
    /// True when the face bounds a solid (a closed shell): its normal then points out of it,
    /// and distances to it are signed.
    pub bounds_solid: bool,
}

impl Face {
    /// A face that is the whole of `surface`, normal `S_u x S_v`, bounding no solid.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::{BSplineSurface, NurbsSurface};
    /// use karkas::shape::Face;
    /// use karkas::{Grid, Point};
    ///
    /// let control = Grid::from_fn(2, 2, |i, j| Point([i as f64, j as f64, 0.0]));
    /// let square = BSplineSurface::new((1, vec![0.0, 0.0, 1.0, 1.0]), (1, vec![0.0, 0.0, 1.0, 1.0]), control)?;
    /// let face = Face::whole(NurbsSurface::from_bspline(&square));
    /// assert!(face.loops.is_empty() && !face.bounds_solid);
    /// // Its normal is S_u x S_v: +z for this square.
    /// assert!(face.normal(0.5, 0.5).unwrap().distance(Point([0.0, 0.0, 1.0])) < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn whole(surface: NurbsSurface<3>) -> Face {
        Face {
            surface,
            loops: Vec::new(),
            same_sense: true,
            bounds_solid: false,
        }
    }

    /// The unit normal of the face at `(u, v)` (the surface's, turned over when the face's
    /// sense is opposite), or `None` where `S_u x S_v` vanishes.
    pub fn normal(&self, u: f64, v: f64) -> Option<Point3> {
        let s = self.surface.second_order(u, v);
        let n = s[1].cross(s[2]);
        let len = n.norm();
        (len > 0.0 && len.is_finite()).then(|| n * (if self.same_sense { 1.0 } else { -1.0 } / len))
    }
}

/// What a CAD file holds, as karkas reads it: faces (of shells, solids, or free surfaces) and
/// free curves (wireframes, curve sets).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Shape {
    /// The faces.
    pub faces: Vec<Face>,
    /// The curves that bound no face.
    pub curves: Vec<NurbsCurve<3>>,
}

impl Shape {
    /// The smallest and largest coordinates of the control points of every face and curve
    /// (a box holding the shape: curves and surfaces lie in their control points' hull);
    /// `None` for an empty shape.
    pub fn bounding_box(&self) -> Option<(Point3, Point3)> {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        let mut any = false;
        let faces = self
            .faces
            .iter()
            .flat_map(|f| f.surface.control_points().as_slice());
        let curves = self.curves.iter().flat_map(|c| c.control_points());
        for p in faces.chain(curves) {
            any = true;
            for c in 0..3 {
                lo[c] = lo[c].min(p[c]);
                hi[c] = hi[c].max(p[c]);
            }
        }
        any.then(|| (Point3::new(lo), Point3::new(hi)))
    }

    /// The length of the diagonal of [`bounding_box`](Shape::bounding_box) (0 when empty):
    /// the shape's size, for relative tolerances.
    pub fn size(&self) -> f64 {
        self.bounding_box().map_or(0.0, |(lo, hi)| lo.distance(hi))
    }
}
