//! [`PointLocator`]: point location in a DCEL subdivision through its trapezoidal map.
use super::check::{check_no_crossings, first_crossing};
use super::map::{check_query, DagStats, MapHit, TrapezoidalMap, DEFAULT_SEED};
use super::trapmap::{lex, NONE};
use crate::dcel::{polygon_segments, Dcel, FaceId, HalfEdgeId, PolygonLabel, Source, VertexId};
use crate::kernel::{ExactPoint, MultiPolygon, Point2, Segment2};
use crate::{Error, Result};
use rayon::prelude::*;
use std::cmp::Ordering;

/// The subdivision of a set of segments ([`Dcel::from_segments`]).
pub type SegmentsDcel = Dcel<(), Vec<Source>, ()>;
/// The subdivision of a set of polygons ([`Dcel::from_polygons`]).
pub type PolygonsDcel = Dcel<(), Vec<Source>, PolygonLabel>;

/// Where a query point lies in a subdivision.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Location {
    /// In the interior of this face ([`FaceId::UNBOUNDED`] outside every bounded face).
    Face(FaceId),
    /// In the relative interior of this edge; the half-edge given runs from its
    /// lexicographically smaller end (x, then y) to the larger, so the face
    /// "above" the edge (left of it; for a vertical edge, its -x side) is its face.
    Edge(HalfEdgeId),
    /// Exactly at this vertex.
    Vertex(VertexId),
}

/// Point location in a planar subdivision (book chapter 6): the trapezoidal map of the
/// subdivision's edges with its search structure, each trapezoid labelled with the face
/// containing it. Queries are exact and take expected O(log n) time;
/// [`PointLocator::locate_all`] answers many in parallel.
///
/// ```
/// use compgeom::dcel::{Dcel, FaceId};
/// use compgeom::locate::{Location, PointLocator};
/// use compgeom::{MultiPolygon, Point2, Polygon};
/// let p = |x, y| Point2::new(x, y);
/// let squares = MultiPolygon(vec![
///     Polygon::new(vec![p(0., 0.), p(2., 0.), p(2., 2.), p(0., 2.)], vec![]),
///     Polygon::new(vec![p(2., 0.), p(4., 0.), p(4., 2.), p(2., 2.)], vec![]),
/// ]);
/// let (loc, dcel) = PointLocator::from_polygons(&squares).unwrap();
/// let Location::Face(f) = loc.locate(p(3.0, 1.0)).unwrap() else { panic!() };
/// assert_eq!(dcel.face(f).data, vec![1]);
/// assert_eq!(loc.locate(p(9.0, 1.0)).unwrap(), Location::Face(FaceId::UNBOUNDED));
/// // On the shared edge: both squares contain the point.
/// let on = loc.locate(p(2.0, 1.0)).unwrap();
/// assert!(matches!(on, Location::Edge(_)));
/// assert_eq!(compgeom::locate::polygons_at(&dcel, on), vec![0, 1]);
/// ```
#[derive(Debug, Clone)]
pub struct PointLocator {
    map: TrapezoidalMap,
    /// The face of each trapezoid.
    trap_face: Vec<u32>,
    /// The DCEL vertex of each map point.
    point_vertex: Vec<u32>,
    /// Per edge e: does half-edge 2e run left to right (lexicographically)?
    even_forward: Vec<bool>,
}

impl PointLocator {
    /// The locator of a subdivision, with the default seed.
    pub fn from_dcel<V, E, F>(dcel: &Dcel<V, E, F>) -> Result<PointLocator> {
        Self::from_dcel_with_seed(dcel, DEFAULT_SEED)
    }

    /// The locator of a subdivision; `seed` draws the insertion order. Vertices may be
    /// constructed crossings (as in the results of [`crate::overlay`]): the map then
    /// decides everything about them with the kernel's exact predicates on
    /// [`ExactPoint`]s (slower than on input points, still exact). Isolated vertices are
    /// not located (they are not on any edge). Expected O(n log n) time and O(n) space
    /// for n edges.
    pub fn from_dcel_with_seed<V, E, F>(dcel: &Dcel<V, E, F>, seed: u64) -> Result<PointLocator> {
        let mut points = Vec::with_capacity(dcel.vertex_count());
        let mut exact = Vec::new();
        let constructed = dcel
            .vertex_ids()
            .any(|v| matches!(dcel.vertex(v).point, ExactPoint::Crossing(_)));
        for v in dcel.vertex_ids() {
            let p = dcel.vertex(v).point;
            let a = p.approx();
            if !a.is_finite() {
                return Err(Error::NonFinite {
                    what: format!("vertex {}", v.0),
                    value: if a.x.is_finite() { a.y } else { a.x },
                });
            }
            points.push(a);
            if constructed {
                exact.push(p);
            }
        }
        let mut segs = Vec::with_capacity(dcel.edge_count());
        let mut seg_input = Vec::with_capacity(dcel.edge_count());
        for e in 0..dcel.edge_count() {
            let h = HalfEdgeId(2 * e);
            let (a, b) = (dcel.half_edge(h).origin.0, dcel.destination(h).0);
            let (a, b) = (a as u32, b as u32);
            let less = if constructed {
                exact[a as usize].compare_xy(&exact[b as usize]) == Ordering::Less
            } else {
                lex(points[a as usize], points[b as usize]) == Ordering::Less
            };
            let pair = if less { [a, b] } else { [b, a] };
            segs.push(pair);
            seg_input.push(e);
        }
        let map = TrapezoidalMap::from_parts(points, exact, segs, seg_input, seed)?;
        // The half-edge of edge e running left to right has the face above e.
        let even_forward: Vec<bool> = (0..dcel.edge_count())
            .map(|e| dcel.half_edge(HalfEdgeId(2 * e)).origin.0 as u32 == map.core.segs[e][0])
            .collect();
        let forward = |e: usize| HalfEdgeId(2 * e + usize::from(!even_forward[e]));
        let trap_face = map
            .core
            .traps
            .iter()
            .map(|t| {
                let f = if t.bottom != NONE {
                    dcel.half_edge(forward(t.bottom as usize)).face
                } else if t.top != NONE {
                    dcel.half_edge(dcel.twin(forward(t.top as usize))).face
                } else {
                    FaceId::UNBOUNDED
                };
                f.0 as u32
            })
            .collect();
        let point_vertex = (0..map.core.points.len() as u32).collect();
        Ok(PointLocator {
            map,
            trap_face,
            point_vertex,
            even_forward,
        })
    }

    /// The locator of the subdivision of [`Dcel::from_segments`]`(segments)`, returned
    /// with it (face, edge and vertex ids refer to it). The segments must not cross
    /// (shared endpoints, an endpoint on another segment and collinear overlaps are
    /// fine); the first crossing pair is an `Err`.
    pub fn from_segments(segments: &[Segment2]) -> Result<(PointLocator, SegmentsDcel)> {
        Self::from_segments_with_seed(segments, DEFAULT_SEED)
    }

    /// [`PointLocator::from_segments`] with the insertion order drawn from `seed`.
    pub fn from_segments_with_seed(
        segments: &[Segment2],
        seed: u64,
    ) -> Result<(PointLocator, SegmentsDcel)> {
        let d = segments_dcel(segments)?;
        Ok((Self::from_dcel_with_seed(&d, seed)?, d))
    }

    /// The locator of the subdivision of [`Dcel::from_polygons`]`(polygons)` (each face
    /// labelled with the polygons containing it), returned with it. Polygons may share
    /// edges and vertices but their boundaries must not cross; the first crossing is an
    /// `Err` naming the two polygons (numbered as in `polygons`).
    pub fn from_polygons(polygons: &MultiPolygon) -> Result<(PointLocator, PolygonsDcel)> {
        Self::from_polygons_with_seed(polygons, DEFAULT_SEED)
    }

    /// [`PointLocator::from_polygons`] with the insertion order drawn from `seed`.
    pub fn from_polygons_with_seed(
        polygons: &MultiPolygon,
        seed: u64,
    ) -> Result<(PointLocator, PolygonsDcel)> {
        let d = polygons_dcel(polygons)?;
        Ok((Self::from_dcel_with_seed(&d, seed)?, d))
    }

    /// Locate `q`, exactly. Expected O(log n) time. Error: a non-finite coordinate.
    pub fn locate(&self, q: Point2) -> Result<Location> {
        check_query(q, 0)?;
        Ok(self.answer(q))
    }

    #[inline]
    fn answer(&self, q: Point2) -> Location {
        match self.map.hit(q) {
            MapHit::Trapezoid(t) => Location::Face(FaceId(self.trap_face[t] as usize)),
            MapHit::Segment(e) => {
                let h = HalfEdgeId(2 * e);
                Location::Edge(if self.even_forward[e] {
                    h
                } else {
                    HalfEdgeId(2 * e + 1)
                })
            }
            MapHit::Vertex(p) => Location::Vertex(VertexId(self.point_vertex[p] as usize)),
        }
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

    /// The trapezoidal map behind the locator (its segments are the DCEL's edges:
    /// "segment" `e` is edge `e`, half-edges `2e` and `2e + 1`).
    pub fn map(&self) -> &TrapezoidalMap {
        &self.map
    }

    /// The face containing trapezoid `t` of [`PointLocator::map`].
    pub fn trapezoid_face(&self, t: usize) -> FaceId {
        FaceId(self.trap_face[t] as usize)
    }

    /// Size and depth of the search structure.
    pub fn stats(&self) -> DagStats {
        self.map.stats()
    }
}

/// The subdivision of non-crossing segments, as the locators' `from_segments` build it
/// (the first crossing pair is an `Err`).
pub fn segments_dcel(segments: &[Segment2]) -> Result<SegmentsDcel> {
    check_no_crossings(segments)?;
    Dcel::from_segments(segments)
}

/// The subdivision of polygons whose boundaries do not cross, as the locators'
/// `from_polygons` build it (the first crossing is an `Err` naming the two polygons).
pub fn polygons_dcel(polygons: &MultiPolygon) -> Result<PolygonsDcel> {
    let (segs, owner) = polygon_segments(polygons)?;
    if let Some((a, b, at)) = first_crossing(&segs)? {
        // Name polygons rather than segments.
        let (pa, pb) = (owner[a], owner[b]);
        let who = if pa == pb {
            format!("the boundary of polygon {pa} crosses itself")
        } else {
            format!("the boundaries of polygons {pa} and {pb} cross")
        };
        return Err(Error::InvalidInput(format!(
            "{who} at about ({}, {}) (edges {a} and {b}); point location needs non-crossing polygons",
            at.x, at.y
        )));
    }
    Dcel::from_polygons(polygons)
}

/// The polygons whose closed region contains a located point of a subdivision built by
/// [`Dcel::from_polygons`] (ascending): the face's label; for an edge or a vertex, the
/// union of the labels of the faces around it.
pub fn polygons_at<V, E>(dcel: &Dcel<V, E, PolygonLabel>, at: Location) -> Vec<usize> {
    let mut out: Vec<usize> = match at {
        Location::Face(f) => dcel.face(f).data.clone(),
        Location::Edge(h) => {
            let mut l = dcel.face(dcel.half_edge(h).face).data.clone();
            l.extend(&dcel.face(dcel.half_edge(dcel.twin(h)).face).data);
            l
        }
        Location::Vertex(v) => dcel
            .around(v)
            .flat_map(|h| dcel.face(dcel.half_edge(h).face).data.iter().copied())
            .collect(),
    };
    out.sort_unstable();
    out.dedup();
    out
}
