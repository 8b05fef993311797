//! [`SlabLocator`]: the slab method (book §6.1, introduction): vertical lines through
//! every vertex cut the plane into slabs; inside a slab the edges crossing it are
//! totally ordered from bottom to top, so a query is two binary searches.
//!
//! O(log n) query; O(n log n + S) build and O(n + S) space where S is the total number
//! of (slab, edge) pairs: O(n²) in the worst case (n edges crossing n slabs), about
//! n^1.5 for a triangulation of uniform random points. Kept as the simple, obviously
//! correct comparison for [`super::PointLocator`], with the same answers.
//!
//! Degenerate input: slabs are taken in the sheared order of §6.3 (points compared
//! lexicographically), so equal x coordinates and vertical edges need no special case
//! (a vertical edge spans the zero-width slab between its ends). Every test is exact,
//! on input points and on constructed crossings alike ([`crate::kernel::orient_exact`],
//! [`ExactPoint::compare_xy`]).
use super::locator::{polygons_dcel, segments_dcel, Location, PolygonsDcel, SegmentsDcel};
use super::map::check_query;
use crate::dcel::{Dcel, FaceId, HalfEdgeId, VertexId};
use crate::kernel::{orient_exact, ExactPoint, MultiPolygon, Orientation, Point2, Segment2};
use crate::{Error, Result};
use rayon::prelude::*;
use std::cmp::Ordering;

/// Most (slab, edge) pairs a [`SlabLocator`] stores (4 bytes each: 1 GiB); beyond, the
/// build is an `Err` (the slab method's worst case is quadratic).
pub const SLAB_MAX_ENTRIES: usize = 1 << 28;

/// Point location in a planar subdivision by the slab method (see the module docs).
/// Same answers as [`super::PointLocator`].
///
/// ```
/// use compgeom::dcel::Dcel;
/// use compgeom::locate::{Location, PointLocator, SlabLocator};
/// use compgeom::{MultiPolygon, Point2, Polygon};
/// let p = |x, y| Point2::new(x, y);
/// let tri = MultiPolygon(vec![Polygon::new(vec![p(0., 0.), p(4., 0.), p(0., 4.)], vec![])]);
/// let dcel = Dcel::from_polygons(&tri).unwrap();
/// let slab = SlabLocator::from_dcel(&dcel).unwrap();
/// let map = PointLocator::from_dcel(&dcel).unwrap();
/// for q in [p(1., 1.), p(2., 2.), p(0., 0.), p(0., 2.), p(5., 1.)] {
///     assert_eq!(slab.locate(q).unwrap(), map.locate(q).unwrap());
/// }
/// assert!(matches!(slab.locate(p(2., 2.)).unwrap(), Location::Edge(_)));
/// ```
#[derive(Debug, Clone)]
pub struct SlabLocator {
    /// The edges' endpoints in lexicographic order (the slab boundaries).
    xs: Vec<ExactPoint>,
    /// The DCEL vertex of each of `xs`.
    xs_vertex: Vec<u32>,
    /// Slab i (between `xs[i - 1]` and `xs[i]`; 0 and `xs.len()` unbounded) holds
    /// `entries[start[i]..start[i + 1]]`, its edges from bottom to top.
    start: Vec<usize>,
    entries: Vec<u32>,
    /// Per edge: its endpoints, left to right, as indices into `xs`.
    ends: Vec<[u32; 2]>,
    /// Per edge: the face above it and the face below it.
    faces: Vec<[u32; 2]>,
    /// Per edge: the half-edge running left to right.
    forward: Vec<u32>,
}

impl SlabLocator {
    /// The slab locator of a subdivision (vertices may be constructed crossings).
    /// Isolated vertices are not located (they are on no edge). Error: more than
    /// [`SLAB_MAX_ENTRIES`] (slab, edge) pairs.
    pub fn from_dcel<V, E, F>(dcel: &Dcel<V, E, F>) -> Result<SlabLocator> {
        let m = dcel.edge_count();
        // The slab boundaries: edge endpoints in the sheared order.
        let mut used = vec![false; dcel.vertex_count()];
        for e in 0..m {
            let h = HalfEdgeId(2 * e);
            used[dcel.half_edge(h).origin.0] = true;
            used[dcel.destination(h).0] = true;
        }
        let mut order: Vec<usize> = (0..used.len()).filter(|&v| used[v]).collect();
        let pt = |v: usize| dcel.vertex(VertexId(v)).point;
        order.sort_by(|&a, &b| pt(a).compare_xy(&pt(b)));
        let mut rank = vec![u32::MAX; used.len()];
        for (i, &v) in order.iter().enumerate() {
            rank[v] = i as u32;
        }
        let xs: Vec<ExactPoint> = order.iter().map(|&v| pt(v)).collect();
        let mut ends = Vec::with_capacity(m);
        let mut faces = Vec::with_capacity(m);
        let mut forward = Vec::with_capacity(m);
        for e in 0..m {
            let h = HalfEdgeId(2 * e);
            let (a, b) = (
                rank[dcel.half_edge(h).origin.0],
                rank[dcel.destination(h).0],
            );
            let f = if a < b { h } else { dcel.twin(h) };
            ends.push([a.min(b), a.max(b)]);
            forward.push(f.0 as u32);
            let above = dcel.half_edge(f).face.0 as u32;
            let below = dcel.half_edge(dcel.twin(f)).face.0 as u32;
            faces.push([above, below]);
        }
        // Edges by left endpoint, then a sweep keeping the edges crossing the current
        // slab sorted from bottom to top.
        let mut starting: Vec<u32> = (0..m as u32).collect();
        starting.sort_by_key(|&e| ends[e as usize][0]);
        let mut next = 0;
        let mut active: Vec<u32> = Vec::new();
        let mut start = Vec::with_capacity(xs.len() + 2);
        let mut entries = Vec::new();
        start.push(0);
        start.push(0); // slab 0, left of every vertex: empty
        for i in 0..xs.len() as u32 {
            active.retain(|&e| ends[e as usize][1] != i);
            while next < starting.len() && ends[starting[next] as usize][0] == i {
                let e = starting[next];
                next += 1;
                let r = &xs[ends[e as usize][1] as usize];
                // Is the new edge (from xs[i] to r) above active edge f?
                let above = |f: u32| {
                    let [fl, fr] = ends[f as usize];
                    let (fl, fr) = (&xs[fl as usize], &xs[fr as usize]);
                    match orient_exact(fl, fr, &xs[i as usize]) {
                        Orientation::Collinear => {
                            orient_exact(fl, fr, r) == Orientation::CounterClockwise
                        }
                        o => o == Orientation::CounterClockwise,
                    }
                };
                let at = active.partition_point(|&f| above(f));
                active.insert(at, e);
            }
            entries.extend_from_slice(&active);
            if entries.len() > SLAB_MAX_ENTRIES {
                return Err(Error::InvalidInput(format!(
                    "the slab method needs more than {SLAB_MAX_ENTRIES} (slab, edge) pairs for these {m} edges; use the trapezoidal map (PointLocator)"
                )));
            }
            start.push(entries.len());
        }
        Ok(SlabLocator {
            xs_vertex: order.iter().map(|&v| v as u32).collect(),
            xs,
            start,
            entries,
            ends,
            faces,
            forward,
        })
    }

    /// The slab locator of [`Dcel::from_segments`]`(segments)`, returned with it; the
    /// same requirement and error as [`super::PointLocator::from_segments`].
    pub fn from_segments(segments: &[Segment2]) -> Result<(SlabLocator, SegmentsDcel)> {
        let d = segments_dcel(segments)?;
        Ok((Self::from_dcel(&d)?, d))
    }

    /// The slab locator of [`Dcel::from_polygons`]`(polygons)`, returned with it; the
    /// same requirement and error as [`super::PointLocator::from_polygons`].
    pub fn from_polygons(polygons: &MultiPolygon) -> Result<(SlabLocator, PolygonsDcel)> {
        let d = polygons_dcel(polygons)?;
        Ok((Self::from_dcel(&d)?, d))
    }

    /// Locate `q`, exactly, in O(log n). Error: a non-finite coordinate.
    pub fn locate(&self, q: Point2) -> Result<Location> {
        check_query(q, 0)?;
        Ok(self.answer(q))
    }

    fn answer(&self, q: Point2) -> Location {
        let qe = ExactPoint::Input(q);
        // The slab: the number of boundaries before q.
        let i = self
            .xs
            .partition_point(|x| x.compare_xy(&qe) == Ordering::Less);
        if i < self.xs.len() && self.xs[i].compare_xy(&qe) == Ordering::Equal {
            return Location::Vertex(VertexId(self.xs_vertex[i] as usize));
        }
        let slab = &self.entries[self.start[i]..self.start[i + 1]];
        let side = |e: u32| {
            let [l, r] = self.ends[e as usize];
            orient_exact(&self.xs[l as usize], &self.xs[r as usize], &qe)
        };
        // The first edge (from the bottom) not below q; q may lie on it.
        let k = slab.partition_point(|&e| side(e) == Orientation::CounterClockwise);
        if k < slab.len() && side(slab[k]) == Orientation::Collinear {
            return Location::Edge(HalfEdgeId(self.forward[slab[k] as usize] as usize));
        }
        let f = if k < slab.len() {
            self.faces[slab[k] as usize][1]
        } else if k > 0 {
            self.faces[slab[k - 1] as usize][0]
        } else {
            return Location::Face(FaceId::UNBOUNDED);
        };
        Location::Face(FaceId(f as usize))
    }

    /// Locate every query point, in parallel (rayon) for large batches; answers in
    /// query order. Error: the first non-finite query, by index.
    pub fn locate_all(&self, queries: &[Point2]) -> Result<Vec<Location>> {
        if let Some(i) = queries.iter().position(|q| !q.is_finite()) {
            check_query(queries[i], i)?;
        }
        Ok(if queries.len() < 4096 {
            queries.iter().map(|&q| self.answer(q)).collect()
        } else {
            queries
                .par_iter()
                .with_min_len(1024)
                .map(|&q| self.answer(q))
                .collect()
        })
    }

    /// Number of slabs (one more than the distinct edge endpoints).
    pub fn slab_count(&self) -> usize {
        self.start.len() - 1
    }

    /// Total (slab, edge) pairs stored: the method's space beyond O(n).
    pub fn entry_count(&self) -> usize {
        self.entries.len()
    }
}
