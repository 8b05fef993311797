//! The doubly-connected edge list (book §2.2): a planar subdivision as vertex, half-edge
//! and face records linked by typed indices.
//!
//! * A [`Vertex`] keeps its exact point ([`ExactPoint`]: an input point or a constructed
//!   crossing) and the nearest `f64` point for reporting; one incident half-edge.
//! * A [`HalfEdge`] has its origin, twin, next and previous half-edge along the boundary
//!   of its incident face, and the face, which lies to its **left**.
//! * A [`Face`] has its outer component (`None` for the one unbounded face, always
//!   [`FaceId::UNBOUNDED`]) and its inner components (one half-edge per hole or isolated
//!   part).
//!
//! Each record carries user data (`V`, `E`, `F`). Every topological decision in the
//! builders (angular order around a vertex, which boundary cycle is outer, which face a
//! hole lies in) is exact; the rounded coordinates are never consulted (DESIGN §2).
//!
//! Builders: [`Dcel::from_segments`] (the arrangement of arbitrary segments, split at
//! crossings and with overlaps merged: exact tests of the pairs of segments with
//! overlapping boxes from the grid of [`crate::intersect`]'s pairwise method, or its
//! sweep [`crate::intersect::find_intersections`] when that grid would test too many
//! pairs, or,
//! for horizontal and vertical segments only, by an exact sweep whose crossings are
//! `f64` points) and
//! [`Dcel::from_polygons`] (faces labelled with the polygons containing them). Cost:
//! O((n + k) log n) for the sweep and the angular sorts; the components that do not touch
//! any other are linked to the faces containing them by one more sweep (the half-edge
//! just left of each component's leftmost vertex, read from the sweep status), O(V log V
//! + V·s) for a status of at most s edges.
//!
//! [`Dcel::validate`] checks every invariant; [`Dcel::face_polygon`] exports a face.
//!
//! ```
//! use compgeom::dcel::Dcel;
//! use compgeom::{Point2, Segment2};
//! let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
//! // A square with both diagonals: 5 vertices, 8 edges, 4 triangles + the outside.
//! let segs = [s((0., 0.), (2., 0.)), s((2., 0.), (2., 2.)), s((2., 2.), (0., 2.)),
//!             s((0., 2.), (0., 0.)), s((0., 0.), (2., 2.)), s((0., 2.), (2., 0.))];
//! let d = Dcel::from_segments(&segs).unwrap();
//! d.validate().unwrap();
//! assert_eq!((d.vertex_count(), d.edge_count(), d.face_count()), (5, 8, 5));
//! ```
mod build;
mod cancel;
mod export;
mod flat;
mod holes;
mod noding;
mod validate;

pub(crate) use build::push_ring_segments;
pub use build::{polygon_segments, Arrangement, Carrier, PolygonLabel, Source};
pub use export::exact_coords;
pub(crate) use flat::{rounded_away, Flat};
pub(crate) use holes::{
    compare_xy_filtered, compare_xy_filtered_by, compare_y_filtered, faces_left_of, side, Rounded,
};

use crate::kernel::{ExactPoint, Point2};

macro_rules! handle {
    ($name:ident, $what:literal) => {
        #[doc = concat!("Typed index of a ", $what, " in a [`Dcel`].")]
        #[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
        pub struct $name(pub usize);

        impl $name {
            /// The index as `usize`.
            pub fn index(self) -> usize {
                self.0
            }
        }
    };
}
handle!(VertexId, "vertex");
handle!(HalfEdgeId, "half-edge");
handle!(FaceId, "face");

impl FaceId {
    /// The unbounded face, present in every subdivision.
    pub const UNBOUNDED: FaceId = FaceId(0);
}

/// A vertex record.
#[derive(Debug, Clone)]
pub struct Vertex<V> {
    /// The exact point.
    pub point: ExactPoint,
    /// The `f64` point the vertex is drawn at: the nearest one (equal to the point for
    /// input points), or for a crossing in an overlay one float from it per axis where
    /// that keeps the edges apart ([`crate::overlay::mend_rounding`]).
    pub approx: Point2,
    /// One half-edge with this origin, `None` for an isolated vertex.
    pub incident: Option<HalfEdgeId>,
    /// User data.
    pub data: V,
}

/// A half-edge record.
#[derive(Debug, Clone)]
pub struct HalfEdge<E> {
    /// The vertex it starts at.
    pub origin: VertexId,
    /// The oppositely directed half-edge of the same edge.
    pub twin: HalfEdgeId,
    /// The next half-edge along the boundary of `face`.
    pub next: HalfEdgeId,
    /// The previous half-edge along the boundary of `face`.
    pub prev: HalfEdgeId,
    /// The face to its left.
    pub face: FaceId,
    /// User data.
    pub data: E,
}

/// A face record.
#[derive(Debug, Clone)]
pub struct Face<F> {
    /// A half-edge of the outer boundary (counter-clockwise), `None` for the unbounded face.
    pub outer: Option<HalfEdgeId>,
    /// One half-edge of each inner boundary (clockwise): holes and isolated parts.
    pub inner: Vec<HalfEdgeId>,
    /// User data.
    pub data: F,
}

/// A doubly-connected edge list with user data `V` on vertices, `E` on half-edges and
/// `F` on faces. Half-edges `2i` and `2i + 1` are twins (edge `i`).
#[derive(Debug, Clone)]
pub struct Dcel<V = (), E = (), F = ()> {
    pub(crate) vertices: Vec<Vertex<V>>,
    pub(crate) half_edges: Vec<HalfEdge<E>>,
    pub(crate) faces: Vec<Face<F>>,
    /// The input segment under each half-edge and whether it runs the segment's way
    /// (what makes a result composable: see [`crate::overlay::overlay`]).
    pub(crate) carriers: Vec<Carrier>,
}

impl<V, E, F> Dcel<V, E, F> {
    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.vertices.len()
    }
    /// Number of edges (half the number of half-edges).
    pub fn edge_count(&self) -> usize {
        self.half_edges.len() / 2
    }
    /// Number of faces, the unbounded one included.
    pub fn face_count(&self) -> usize {
        self.faces.len()
    }
    /// The vertex record.
    pub fn vertex(&self, v: VertexId) -> &Vertex<V> {
        &self.vertices[v.0]
    }
    /// The half-edge record.
    pub fn half_edge(&self, h: HalfEdgeId) -> &HalfEdge<E> {
        &self.half_edges[h.0]
    }
    /// The face record.
    pub fn face(&self, f: FaceId) -> &Face<F> {
        &self.faces[f.0]
    }
    /// Mutable user data of a face.
    pub fn face_data_mut(&mut self, f: FaceId) -> &mut F {
        &mut self.faces[f.0].data
    }
    /// All vertex handles.
    pub fn vertex_ids(&self) -> impl Iterator<Item = VertexId> {
        (0..self.vertices.len()).map(VertexId)
    }
    /// All half-edge handles.
    pub fn half_edge_ids(&self) -> impl Iterator<Item = HalfEdgeId> {
        (0..self.half_edges.len()).map(HalfEdgeId)
    }
    /// All face handles, the unbounded face first.
    pub fn face_ids(&self) -> impl Iterator<Item = FaceId> {
        (0..self.faces.len()).map(FaceId)
    }
    /// The input segment carrying half-edge `h` and whether `h` runs the segment's way:
    /// its exact direction, also for a piece between constructed points.
    pub fn carrier(&self, h: HalfEdgeId) -> Carrier {
        self.carriers[h.0]
    }
    /// The twin of `h`.
    pub fn twin(&self, h: HalfEdgeId) -> HalfEdgeId {
        self.half_edges[h.0].twin
    }
    /// The vertex `h` ends at.
    pub fn destination(&self, h: HalfEdgeId) -> VertexId {
        self.half_edges[self.twin(h).0].origin
    }
    /// The exact point where `h` starts.
    pub fn origin_point(&self, h: HalfEdgeId) -> &ExactPoint {
        &self.vertices[self.half_edges[h.0].origin.0].point
    }
    /// The boundary cycle starting at `h`, following `next`.
    pub fn cycle(&self, h: HalfEdgeId) -> Cycle<'_, V, E, F> {
        Cycle {
            dcel: self,
            start: h,
            cur: Some(h),
        }
    }
    /// The outgoing half-edges of `v` in counter-clockwise angular order, starting at
    /// `v`'s incident half-edge (each step is `twin(prev(h))`).
    pub fn around(&self, v: VertexId) -> Around<'_, V, E, F> {
        let start = self.vertices[v.0].incident;
        Around {
            dcel: self,
            start,
            cur: start,
        }
    }
    /// Every boundary cycle of a face: the outer one first (if any), then the inner ones.
    pub fn face_cycles(&self, f: FaceId) -> impl Iterator<Item = HalfEdgeId> + '_ {
        let face = &self.faces[f.0];
        face.outer.into_iter().chain(face.inner.iter().copied())
    }
}

/// Iterator over a boundary cycle (see [`Dcel::cycle`]).
pub struct Cycle<'a, V, E, F> {
    dcel: &'a Dcel<V, E, F>,
    start: HalfEdgeId,
    cur: Option<HalfEdgeId>,
}

impl<V, E, F> Iterator for Cycle<'_, V, E, F> {
    type Item = HalfEdgeId;
    fn next(&mut self) -> Option<HalfEdgeId> {
        let h = self.cur?;
        let n = self.dcel.half_edges[h.0].next;
        self.cur = (n != self.start).then_some(n);
        Some(h)
    }
}

/// Iterator over the outgoing half-edges of a vertex in counter-clockwise order (see
/// [`Dcel::around`]).
pub struct Around<'a, V, E, F> {
    dcel: &'a Dcel<V, E, F>,
    start: Option<HalfEdgeId>,
    cur: Option<HalfEdgeId>,
}

impl<V, E, F> Iterator for Around<'_, V, E, F> {
    type Item = HalfEdgeId;
    fn next(&mut self) -> Option<HalfEdgeId> {
        let h = self.cur?;
        // `prev(h)` arrives at v just clockwise of... its twin leaves v right after `h`
        // counter-clockwise (the face left of `h` lies between them).
        let n = self.dcel.twin(self.dcel.half_edges[h.0].prev);
        self.cur = (Some(n) != self.start).then_some(n);
        Some(h)
    }
}
