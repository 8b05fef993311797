//! Map overlay (book §2.3) and polygon boolean operations (§2.4).
//!
//! [`overlay`] computes the overlay of two subdivisions S1 and S2: every face of the
//! result is labelled with the face of S1 and the face of S2 containing it.
//!
//! ## Correspondence with the book's MAPOVERLAY
//!
//! The book sweeps the edges of both subdivisions at once, splits edges where edges of
//! both meet, relinks `next`/`prev` around the new vertices in angular order, then finds
//! the boundary cycles, builds the graph G (each hole cycle linked to the half-edge
//! immediately left of its leftmost vertex) and creates the face records with their
//! labels. Here the same steps are done in that order, exactly, with these choices:
//!
//! 1. *Sweep and split*: the edges of S1 and S2 go through one run of the exact
//!    intersection sweep ([`crate::intersect::find_intersections`]); each edge is cut at
//!    the points in its interior and collinear overlapping pieces become one edge that
//!    remembers the half-edge of S1 and of S2 it came from. Constructed crossings become
//!    vertices holding their exact point ([`crate::kernel::ExactPoint`]). When every
//!    edge is horizontal or vertical, a crossing has exact `f64` coordinates and a
//!    dedicated sweep over the contacts of horizontal and vertical edges gives the same
//!    arrangement without constructed points. Either way the arrangement is kept in
//!    flat arrays (vertices from the reported points, no point look-ups).
//! 2. *Relink*: the half-edges around each vertex are sorted counter-clockwise and
//!    `next(e)` is the one just clockwise of `twin(e)` (records are rebuilt rather than
//!    patched; the order is decided exactly from input-segment directions).
//! 3. *Cycles and G*: a cycle is an outer boundary iff it turns left at its leftmost
//!    vertex; each other cycle is linked to the face of the half-edge immediately left of
//!    its leftmost vertex, read from the status of a sweep (see [`crate::dcel`]).
//! 4. *Labels*: instead of locating each face, labels spread from the unbounded face
//!    across edges: crossing a piece of an S1 edge into the face on its left enters the
//!    S1 face left of that edge; crossing a piece of an S2-only edge keeps the S1 label.
//!    This is exact and linear.
//!
//! Cost: O((n + k) log n) for n edges and k intersection points, plus the hole-linking
//! sweep (see [`crate::dcel`]).
//!
//! [`boolean`] builds the arrangement of the rings of both polygon sets once, labels
//! each face with its winding numbers with respect to A and B (crossing a ring edge from
//! right to left adds one), reads them with a [`FillRule`], and returns the boundary
//! between faces inside and outside the result as valid polygons. It works on the flat
//! arrangement directly (no DCEL records: cycles of compact `next` links, labels spread
//! across twins, rings traced from the edges whose two sides differ); [`boolean_dcel`]
//! gives the same labels as a DCEL.
//!
//! ## Validity of the output
//!
//! The result is valid in the OGC sense: closed simple rings, shells counter-clockwise
//! and holes clockwise (RFC 7946), holes inside their shell, rings meeting only at
//! isolated points, polygons touching only at points, no vertex where a ring goes
//! straight on (unless [`BooleanOptions::keep_collinear`]). Exactly, before rounding,
//! it always is. Output coordinates are the nearest `f64` to the exact vertices, and
//! rounding a constructed crossing moves it by up to half an ulp, which can carry it
//! across an edge that passes closer than that (thin parts, near-coincident crossings:
//! a fifth of the results on some test inputs built for it, rare on random ones). So
//! the rounded result is checked, exactly and conservatively: when no vertex and edge
//! not incident to it, one of them moved, come within a float gap of each other, the
//! rounded result is the exact one deformed, hence valid (O(n) after the crossings,
//! and nothing at all when no vertex moved); a vertex near such an edge must be on its
//! exact side of it. Where it is not, the crossings involved are moved to another of
//! the (at most four) floats around their exact points where that puts every near
//! vertex on its side: such a crossing is one float, not the nearest, from its exact
//! point per axis. Where no such float does, the rounded polygons there are united
//! again (the [`FillRule::Positive`] rule: each shell minus its holes), which makes the
//! new crossings vertices, and checked the same way among the others. The region then
//! differs from the exact one by slivers within rounding. Vertices from the input are
//! never moved. A point that rounding left straight between its neighbours (a crossing
//! rounded onto their line) is dropped where no other ring passes through it: the ring
//! is the same curve without it. The vertices of an [`overlay`] are checked and moved the same way
//! ([`mend_rounding`]), but its faces cannot be united again: where no float mends a
//! failure, the faces near it are reported (on the overlays of the JTS and GEOS test
//! suites' polygon pairs, 54 of 117 places where rounding made edges meet are left,
//! each beside reported faces).
//! [`faces_to_polygons`] on a subdivision of your own rounds without a check.
//!
mod boolean;
mod locality;
mod result;
mod rounding;
mod trace;
mod validate;

pub use boolean::{
    boolean, boolean_dcel, boolean_with, make_valid, make_valid_per_polygon, union_all,
    BooleanEdge, BooleanOp, BooleanOptions, FillRule,
};
pub use result::faces_to_polygons;
pub use validate::{validity_problems, validity_problems_as_written, Problem};

use crate::dcel::Flat;
use crate::dcel::{Carrier, Dcel, FaceId, HalfEdgeId, PolygonLabel};
use crate::kernel::{compare_xy, ExactPoint, MultiPolygon, Segment2};
use crate::{Error, Result};
use std::cmp::Ordering;
use std::collections::HashMap;

/// Data of a half-edge of an overlay: the half-edges of S1 and S2 it is (a piece of),
/// running the same way.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OverlayEdge {
    /// The half-edge of S1, if the edge comes from S1.
    pub s1: Option<HalfEdgeId>,
    /// The half-edge of S2, if the edge comes from S2.
    pub s2: Option<HalfEdgeId>,
    /// The direction, exactly.
    pub carrier: Carrier,
}

/// The label of an overlay face: the faces of S1 and S2 containing it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OverlayFace {
    /// The face of S1.
    pub s1: FaceId,
    /// The face of S2.
    pub s2: FaceId,
}

/// How the segments fed to the sweep for one subdivision map back to its half-edges.
enum Fed {
    /// An edge between input points, fed as itself; the half-edge running its way.
    Edge(HalfEdgeId),
    /// An input segment carrying edges with constructed ends (a result of an earlier
    /// overlay), fed whole; its half-edges running its way, in order along it.
    Carrier(Segment2, Vec<HalfEdgeId>),
}

/// Compare two points along segment `seg`'s direction (exactly).
fn along(seg: Segment2, p: &ExactPoint, q: &ExactPoint) -> Ordering {
    let o = p.compare_xy(q);
    if compare_xy(seg.a, seg.b) == Ordering::Greater {
        o.reverse()
    } else {
        o
    }
}

/// The segments of a subdivision for the sweep: edges between input points as they are,
/// and the input segment under edges with constructed ends, cut at the input vertices of
/// those edges.
///
/// The cuts matter: a vertex of the layer inside such a segment is not always where
/// another fed segment crosses or ends (it may be the end of a collinear input segment
/// merged into this one, with only collinear edges at it); fed whole, the segment would
/// give a result piece spanning two of the layer's edges, and the overlay would lose the
/// vertex. Every cut point is an input vertex on the segment, so each piece is an exact
/// sub-segment running the same way.
fn layer_segments<V, E, F>(d: &Dcel<V, E, F>) -> (Vec<Segment2>, Vec<Fed>) {
    let mut segs = Vec::new();
    let mut fed = Vec::new();
    let mut carriers: Vec<(Segment2, Vec<HalfEdgeId>)> = Vec::new();
    let mut by_carrier: HashMap<[u64; 4], usize> = HashMap::new();
    for i in 0..d.edge_count() {
        let h = HalfEdgeId(2 * i);
        if let (ExactPoint::Input(a), ExactPoint::Input(b)) =
            (d.origin_point(h), d.origin_point(d.twin(h)))
        {
            segs.push(Segment2::new(*a, *b));
            fed.push(Fed::Edge(h));
            continue;
        }
        let c = d.carrier(h);
        let way = if c.forward { h } else { d.twin(h) };
        let key = [c.seg.a.x, c.seg.a.y, c.seg.b.x, c.seg.b.y].map(|x| (x + 0.0).to_bits());
        let k = *by_carrier.entry(key).or_insert_with(|| {
            carriers.push((c.seg, Vec::new()));
            carriers.len() - 1
        });
        carriers[k].1.push(way);
    }
    for (seg, mut list) in carriers {
        list.sort_by(|&x, &y| along(seg, d.origin_point(x), d.origin_point(y)));
        // Cut at each input vertex of the sorted edges; a piece ends at an input point
        // (the segment's far end for the last one) and keeps the edges it covers.
        let mut start = seg.a;
        let mut pending: Vec<HalfEdgeId> = Vec::new();
        for e in list {
            if let ExactPoint::Input(p) = d.origin_point(e) {
                if !pending.is_empty() {
                    segs.push(Segment2::new(start, *p));
                    fed.push(Fed::Carrier(
                        segs[segs.len() - 1],
                        std::mem::take(&mut pending),
                    ));
                }
                start = *p;
            }
            pending.push(e);
            if let ExactPoint::Input(q) = d.origin_point(d.twin(e)) {
                segs.push(Segment2::new(start, *q));
                fed.push(Fed::Carrier(
                    segs[segs.len() - 1],
                    std::mem::take(&mut pending),
                ));
                start = *q;
            }
        }
        if !pending.is_empty() {
            segs.push(Segment2::new(start, seg.b));
            fed.push(Fed::Carrier(segs[segs.len() - 1], pending));
        }
    }
    (segs, fed)
}

/// The half-edge of a layer under the piece `from → to` of the result, given one of the
/// piece's sources in that layer (`forward`: the piece runs the fed segment's way), or
/// `None` when the layer's edges on that segment do not cover the piece.
fn locate<V, E, F>(
    d: &Dcel<V, E, F>,
    fed: &Fed,
    forward: bool,
    from: &ExactPoint,
    to: &ExactPoint,
) -> Option<HalfEdgeId> {
    match fed {
        Fed::Edge(h) => Some(if forward { *h } else { d.twin(*h) }),
        Fed::Carrier(seg, list) => {
            let (u, v) = if forward { (from, to) } else { (to, from) };
            let i =
                list.partition_point(|&e| along(*seg, d.origin_point(e), u) != Ordering::Greater);
            let e = *list.get(i.checked_sub(1)?)?;
            if along(*seg, d.origin_point(d.twin(e)), v) == Ordering::Less {
                return None;
            }
            Some(if forward { e } else { d.twin(e) })
        }
    }
}

/// MAPOVERLAY(S1, S2): the overlay of two subdivisions, each face labelled with the
/// faces of S1 and S2 containing it, each half-edge with the half-edges it comes from.
///
/// Overlays compose: either subdivision may itself be an overlay (or any subdivision
/// built by this crate, whose vertices may be constructed crossings), as MAPOVERLAY
/// allows. An edge between input points is swept as itself; the input segment under
/// edges with constructed ends is swept whole (the edges on it cover it), and each piece
/// of the result finds the edge it lies in by an exact search along that segment. A
/// subdivision whose edges do not cover the segments under them is `Err(InvalidInput)`.
/// The vertices' rounded points (`approx`) are checked and mended as the boolean
/// operations' are ([`mend_rounding`]).
///
/// ```
/// use compgeom::dcel::Dcel;
/// use compgeom::overlay::overlay;
/// use compgeom::{MultiPolygon, Point2, Polygon};
/// let sq = |x: f64, y: f64| Polygon::new(vec![Point2::new(x, y), Point2::new(x + 2.0, y),
///     Point2::new(x + 2.0, y + 2.0), Point2::new(x, y + 2.0)], vec![]);
/// let a = Dcel::from_polygons(&MultiPolygon(vec![sq(0.0, 0.0)])).unwrap();
/// let b = Dcel::from_polygons(&MultiPolygon(vec![sq(1.0, 1.0)])).unwrap();
/// let o = overlay(&a, &b).unwrap();
/// o.validate().unwrap();
/// assert_eq!(o.face_count(), 4); // outside, A only, B only, both
/// ```
pub fn overlay<V1, E1, F1, V2, E2, F2>(
    s1: &Dcel<V1, E1, F1>,
    s2: &Dcel<V2, E2, F2>,
) -> Result<Dcel<(), OverlayEdge, OverlayFace>> {
    let (mut segs, fed1) = layer_segments(s1);
    let n1 = segs.len();
    let (segs2, fed2) = layer_segments(s2);
    segs.extend(segs2);
    let flat = Flat::of_segments(&segs)?;
    // The input segments under each edge, read from a copy of the arrangement's flat
    // lists (half-edge 2i + 1 runs those of 2i backwards): a list per half-edge in the
    // DCEL took as much memory as the DCEL and an allocation each.
    let edge_sources = flat.sources_by_edge();
    let d = Dcel::linked_flat(flat, &segs, |_, _| (), true);
    let mut data = Vec::with_capacity(2 * d.edge_count());
    for g in d.half_edge_ids() {
        let (from, to) = (d.origin_point(g), d.origin_point(d.twin(g)));
        let backwards = g.0 & 1 == 1;
        let sources = edge_sources.of(g.0 >> 1);
        let find = |in1: bool, which: &str| -> Result<Option<HalfEdgeId>> {
            let mut any = false;
            for s in sources.iter().filter(|s| (s.segment < n1) == in1) {
                any = true;
                let forward = s.forward != backwards;
                let found = if in1 {
                    locate(s1, &fed1[s.segment], forward, from, to)
                } else {
                    locate(s2, &fed2[s.segment - n1], forward, from, to)
                };
                if found.is_some() {
                    return Ok(found);
                }
            }
            if any {
                return Err(Error::InvalidInput(format!(
                    "{which}: an edge does not cover the input segment it lies on between \
                     two of its vertices (not a subdivision built by this crate)"
                )));
            }
            Ok(None)
        };
        data.push(OverlayEdge {
            s1: find(true, "S1")?,
            s2: find(false, "S2")?,
            carrier: d.carrier(g),
        });
    }
    let d = d.map_edge_data(data);
    let outside = OverlayFace {
        s1: FaceId::UNBOUNDED,
        s2: FaceId::UNBOUNDED,
    };
    let mut d = d.label_faces(outside, |from, e| OverlayFace {
        s1: e.s1.map_or(from.s1, |h| s1.half_edge(h).face),
        s2: e.s2.map_or(from.s2, |h| s2.half_edge(h).face),
    });
    rounding::mend_faces(&mut d);
    Ok(d)
}

/// Checks that rounding the vertices of the subdivision `d` to `f64` kept its edges
/// apart, exactly and conservatively, as the boolean operations do (module docs,
/// "Validity of the output"), and moves a crossing whose nearest `f64` point crosses or
/// touches an edge to another of the (at most four) floats around its exact point
/// where that keeps every near vertex on its exact side, pass after pass until nothing
/// moves (at most 8). Faces cannot be united again as a boolean result can, so where
/// no float does, the faces near the failure are returned (ascending; empty when every
/// edge stays apart). A face thinner than a float gap is always among them. [`overlay`]
/// calls this on its result; [`rounding_suspects`] lists what is left without moving
/// anything. O(n) after the vertices, plus exact work near failures.
///
/// ```
/// use compgeom::overlay::{mend_rounding, overlay_polygons, rounding_suspects};
/// use compgeom::{MultiPolygon, Point2, Polygon};
/// let square = |x: f64, y: f64, s: f64| {
///     let p = |a: f64, b: f64| Point2::new(a, b);
///     Polygon::new(vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)], vec![])
/// };
/// let a = MultiPolygon(vec![square(0.0, 0.0, 3.0)]);
/// let b = MultiPolygon(vec![square(1.0, 1.0, 3.0)]);
/// let mut d = overlay_polygons(&a, &b).unwrap();
/// assert!(rounding_suspects(&d).is_empty());
/// assert!(mend_rounding(&mut d).is_empty());
/// ```
pub fn mend_rounding<V, E, F>(d: &mut Dcel<V, E, F>) -> Vec<FaceId> {
    rounding::mend_faces(d)
}

/// The faces of `d` near which rounding its vertices to `f64` may have made edges touch
/// or cross (ascending), by the check of [`mend_rounding`], moving nothing.
pub fn rounding_suspects<V, E, F>(d: &Dcel<V, E, F>) -> Vec<FaceId> {
    rounding::suspect_faces(d)
}

/// The overlay of two polygon layers: each face labelled with the polygons of `a` and of
/// `b` containing it (indices, ascending; each polygon read even-odd). The subdivision of
/// each layer ([`Dcel::from_polygons`]), then [`overlay`]: O((n + k) log n) for n edges
/// and k crossings in all.
///
/// ```
/// use compgeom::overlay::overlay_polygons;
/// use compgeom::{MultiPolygon, Point2, Polygon};
/// let sq = |x: f64, y: f64| Polygon::new(vec![Point2::new(x, y), Point2::new(x + 2.0, y),
///     Point2::new(x + 2.0, y + 2.0), Point2::new(x, y + 2.0)], vec![]);
/// let a = MultiPolygon(vec![sq(0.0, 0.0), sq(4.0, 0.0)]);
/// let b = MultiPolygon(vec![sq(1.0, 1.0)]);
/// let d = overlay_polygons(&a, &b).unwrap();
/// d.validate().unwrap();
/// // Faces: the outside, square 0 of A alone, both, B alone, square 1 of A.
/// let mut labels: Vec<_> = d.face_ids().map(|f| d.face(f).data.clone()).collect();
/// labels.sort();
/// assert_eq!(labels, [(vec![], vec![]), (vec![], vec![0]), (vec![0], vec![]),
///                     (vec![0], vec![0]), (vec![1], vec![])]);
/// ```
pub fn overlay_polygons(
    a: &MultiPolygon,
    b: &MultiPolygon,
) -> Result<Dcel<(), OverlayEdge, (PolygonLabel, PolygonLabel)>> {
    let da = Dcel::from_polygons(a)?;
    let db = Dcel::from_polygons(b)?;
    let o = overlay(&da, &db)?;
    let Dcel {
        vertices,
        half_edges,
        faces,
        carriers,
    } = o;
    let faces = faces
        .into_iter()
        .map(|f| crate::dcel::Face {
            outer: f.outer,
            inner: f.inner,
            data: (
                da.face(f.data.s1).data.clone(),
                db.face(f.data.s2).data.clone(),
            ),
        })
        .collect();
    Ok(Dcel {
        vertices,
        half_edges,
        faces,
        carriers,
    })
}
