//! Faces out: as polygons with holes (rounded coordinates) and exact areas.
use super::{Dcel, FaceId, HalfEdgeId};
use crate::kernel::{ExactPoint, Point2, Polygon};
use num_rational::BigRational;
use num_traits::Zero;

/// The exact coordinates of a point as rationals.
pub fn exact_coords(p: &ExactPoint) -> (BigRational, BigRational) {
    match p {
        ExactPoint::Input(q) => (
            BigRational::from_float(q.x).unwrap_or_else(BigRational::zero),
            BigRational::from_float(q.y).unwrap_or_else(BigRational::zero),
        ),
        ExactPoint::Crossing(c) => c
            .exact()
            .unwrap_or_else(|| (BigRational::zero(), BigRational::zero())),
    }
}

impl<V, E, F> Dcel<V, E, F> {
    /// The rounded points of the cycle starting at `h`, in cycle order.
    pub fn cycle_points(&self, h: HalfEdgeId) -> Vec<Point2> {
        self.cycle(h)
            .map(|e| self.vertices[self.half_edges[e.0].origin.0].approx)
            .collect()
    }

    /// A bounded face as a polygon: its outer boundary (counter-clockwise) and one hole
    /// per inner component (clockwise), with rounded coordinates, every vertex kept.
    /// `None` for the unbounded face. A boundary that touches itself at a vertex is one
    /// ring here; [`crate::overlay`]'s output splits such rings. O(size of the face).
    ///
    /// ```
    /// use compgeom::dcel::{Dcel, FaceId};
    /// use compgeom::{MultiPolygon, Point2, Polygon};
    /// let p = |x, y| Point2::new(x, y);
    /// let frame = Polygon::new(vec![p(0., 0.), p(4., 0.), p(4., 4.), p(0., 4.)],
    ///     vec![vec![p(1., 1.), p(1., 3.), p(3., 3.), p(3., 1.)]]);
    /// let d = Dcel::from_polygons(&MultiPolygon(vec![frame])).unwrap();
    /// assert!(d.face_polygon(FaceId::UNBOUNDED).is_none());
    /// let inside = d.face_ids().find(|&f| d.face(f).data == vec![0]).unwrap();
    /// let polygon = d.face_polygon(inside).unwrap();
    /// assert_eq!((polygon.exterior.len(), polygon.holes.len()), (4, 1));
    /// ```
    pub fn face_polygon(&self, f: FaceId) -> Option<Polygon> {
        let face = &self.faces[f.0];
        let outer = face.outer?;
        Some(Polygon::new(
            self.cycle_points(outer),
            face.inner.iter().map(|&h| self.cycle_points(h)).collect(),
        ))
    }

    /// Twice the signed area enclosed by the cycle starting at `h`, exactly.
    pub fn cycle_area2_exact(&self, h: HalfEdgeId) -> BigRational {
        let pts: Vec<(BigRational, BigRational)> = self
            .cycle(h)
            .map(|e| exact_coords(self.origin_point(e)))
            .collect();
        let mut sum = BigRational::zero();
        for i in 0..pts.len() {
            let (a, b) = (&pts[i], &pts[(i + 1) % pts.len()]);
            sum += &a.0 * &b.1 - &b.0 * &a.1;
        }
        sum
    }

    /// The exact area of a bounded face (outer area minus holes); zero for the unbounded
    /// face.
    pub fn face_area_exact(&self, f: FaceId) -> BigRational {
        if self.faces[f.0].outer.is_none() {
            return BigRational::zero();
        }
        let two = BigRational::from_integer(2.into());
        self.face_cycles(f)
            .map(|h| self.cycle_area2_exact(h))
            .fold(BigRational::zero(), |a, b| a + b)
            / two
    }
}
