//! Builders: the arrangement of a set of segments, and the DCEL linked from it.
//!
//! 1. [`Arrangement::of_segments`]: the exact intersection sweep gives every point where
//!    segments meet; each segment is cut at the points in its interior (they come in
//!    sweep order, so along the segment) and pieces with the same two end vertices
//!    (overlapping collinear segments) become one edge remembering all its sources
//!    (built in flat arrays, with an exact axis-parallel path: see `flat.rs`).
//! 2. [`Dcel::from_arrangement`]: half-edges are sorted counter-clockwise around each
//!    vertex — exactly, from the directions of the input segments carrying them (a piece
//!    starting at a crossing points the way its input segment points, so no constructed
//!    point enters the test) — and `next(e)` is the outgoing half-edge just clockwise of
//!    `twin(e)`. The boundary cycles follow. A cycle is an outer boundary iff it turns
//!    left (strictly) at each visit of its lexicographically smallest vertex; the others
//!    are the outer boundaries of connected components, i.e. holes of the face of the
//!    half-edge just left of that vertex, found by one sweep (the book's graph G; see
//!    `holes.rs`). The cycle walks run over compact copies of `next` and `origin`
//!    (4 bytes per half-edge): a walk is a chain of dependent loads.
use super::flat::Flat;
use super::{Dcel, Face, FaceId, HalfEdge, HalfEdgeId, Vertex, VertexId};
use crate::kernel::MultiPolygon;
use crate::kernel::{compare_slopes, compare_xy, ExactPoint, Orientation, Point2, Segment2};
use crate::{Error, Result};
use std::cmp::Ordering;

/// One input segment carrying an edge, and whether it points the same way as the
/// half-edge that stores it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Source {
    /// Index of the input segment.
    pub segment: usize,
    /// True when the segment runs the same way as the half-edge.
    pub forward: bool,
}

/// The arrangement of a set of segments: vertices (exact) and edges between them, each
/// edge with the input segments covering it.
#[derive(Debug, Clone, Default)]
pub struct Arrangement {
    /// The exact vertices.
    pub vertices: Vec<ExactPoint>,
    /// Edges `(u, v, sources)`, `u < v`; `forward` in a source is relative to `u → v`.
    pub edges: Vec<(usize, usize, Vec<Source>)>,
    /// The input segments.
    pub segments: Vec<Segment2>,
}

fn key(p: Point2) -> (u64, u64) {
    // +0.0 folds -0.0 into 0.0 so that equal points get one vertex.
    ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits())
}

impl Arrangement {
    /// The arrangement of `segments`. Zero-length segments are ignored (they add no
    /// edge). Non-finite coordinates are an error naming the segment.
    pub fn of_segments(segments: &[Segment2]) -> Result<Arrangement> {
        let flat = Flat::of_segments(segments)?;
        let vertices = flat.vertices.exact();
        let edges = (0..flat.edge_count())
            .map(|i| {
                let [u, v] = flat.edges[i];
                let (u, v) = (u as usize, v as usize);
                let flip = u > v;
                let sources = flat
                    .sources_of(i)
                    .iter()
                    .map(|s| Source {
                        segment: s.segment,
                        forward: s.forward != flip,
                    })
                    .collect();
                (u.min(v), u.max(v), sources)
            })
            .collect();
        Ok(Arrangement {
            vertices,
            edges,
            segments: segments.to_vec(),
        })
    }
}

/// The sign of `d1 × d2` for the directions of two half-edges, each given by its carrier
/// segment and whether it runs the segment's way. Exact (input points only).
fn cross_dirs(s1: Segment2, f1: bool, s2: Segment2, f2: bool) -> Ordering {
    // Both axis-parallel: one coordinate of each direction is zero, so at most one of
    // the two products is non-zero and the signs of the (exact in sign) differences
    // decide.
    let dir = |s: Segment2, f: bool| {
        let (dx, dy) = (s.b.x - s.a.x, s.b.y - s.a.y);
        let sign = |v: f64| i32::from(v > 0.0) - i32::from(v < 0.0);
        let k = if f { 1 } else { -1 };
        (k * sign(dx), k * sign(dy))
    };
    if (s1.a.x == s1.b.x || s1.a.y == s1.b.y) && (s2.a.x == s2.b.x || s2.a.y == s2.b.y) {
        let ((x1, y1), (x2, y2)) = (dir(s1, f1), dir(s2, f2));
        return (x1 * y2 - y1 * x2).cmp(&0);
    }
    cross_dirs_filtered(s1, f1, s2, f2).unwrap_or_else(|| cross_dirs_slopes(s1, f1, s2, f2))
}

/// [`cross_dirs`] by a floating-point filter, `None` when it cannot tell. The
/// determinant `dx·ey − dy·ex` of four rounded differences is the form of Shewchuk's
/// orient2d stage A (whose bound does not use that its differences share a point), so
/// its error is at most `(3 + 16ε)ε (|dx·ey| + |dy·ex|)`; the absolute term covers the
/// products' underflow (each at most 2^-1075 off), and overflow gives an infinite or
/// NaN sum that fails the test. Reversing one direction reverses the sign.
#[inline]
fn cross_dirs_filtered(s1: Segment2, f1: bool, s2: Segment2, f2: bool) -> Option<Ordering> {
    const EPS: f64 = f64::EPSILON / 2.0;
    const BOUND: f64 = (3.0 + 16.0 * EPS) * EPS;
    const TINY: f64 = 1e-300;
    let left = (s1.b.x - s1.a.x) * (s2.b.y - s2.a.y);
    let right = (s1.b.y - s1.a.y) * (s2.b.x - s2.a.x);
    let det = left - right;
    let err = BOUND * (left.abs() + right.abs()) + TINY;
    let sign = if det > err {
        Ordering::Greater
    } else if det < -err {
        Ordering::Less
    } else {
        return None;
    };
    Some(if f1 == f2 { sign } else { sign.reverse() })
}

/// [`cross_dirs`] by the kernel's exact slope comparison (any directions).
fn cross_dirs_slopes(s1: Segment2, f1: bool, s2: Segment2, f2: bool) -> Ordering {
    // compare_slopes(s, t) = sign(sorted(t) × sorted(s)); sorted flips a segment whose
    // first endpoint is lexicographically greater.
    let flip = |s: Segment2| compare_xy(s.a, s.b) == Ordering::Greater;
    let c = compare_slopes(s1, s2).reverse(); // sign(sorted(s1) × sorted(s2))
    if flip(s1) ^ flip(s2) ^ !f1 ^ !f2 {
        c.reverse()
    } else {
        c
    }
}

/// 0 for directions in [0°, 180°), 1 for [180°, 360°).
fn half_plane(s: Segment2, forward: bool) -> u8 {
    let (a, b) = if forward { (s.a, s.b) } else { (s.b, s.a) };
    let up = b.y > a.y || (b.y == a.y && b.x > a.x);
    u8::from(!up)
}

/// The input segment a half-edge lies on, and whether the half-edge runs its way: the
/// half-edge's direction, exactly, even when it starts or ends at a crossing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Carrier {
    /// The input segment.
    pub seg: Segment2,
    /// True when the half-edge runs from `seg.a` towards `seg.b`.
    pub forward: bool,
}

impl Carrier {
    fn half(&self) -> u8 {
        half_plane(self.seg, self.forward)
    }
    /// The same line, the other way.
    pub fn reversed(self) -> Carrier {
        Carrier {
            seg: self.seg,
            forward: !self.forward,
        }
    }
    /// Counter-clockwise angular order of two directions from a common origin, starting
    /// at direction +x (included).
    pub fn angle_cmp(&self, other: &Carrier) -> Ordering {
        self.half().cmp(&other.half()).then_with(|| {
            match cross_dirs(self.seg, self.forward, other.seg, other.forward) {
                Ordering::Greater => Ordering::Less,
                Ordering::Less => Ordering::Greater,
                Ordering::Equal => Ordering::Equal,
            }
        })
    }
    /// Orientation of the turn from `self` (arriving) to `out` (leaving).
    pub fn turn(&self, out: &Carrier) -> Orientation {
        match cross_dirs(self.seg, self.forward, out.seg, out.forward) {
            Ordering::Greater => Orientation::CounterClockwise,
            Ordering::Less => Orientation::Clockwise,
            Ordering::Equal => Orientation::Collinear,
        }
    }
}

impl<E> Dcel<(), E, ()> {
    /// The DCEL of an arrangement; `edge_data(sources, carrier)` gives the data of each
    /// half-edge from its sources (relative to the half-edge's direction) and carrier.
    /// Half-edge `2i` runs `edges[i].0 → edges[i].1`, `2i + 1` is its twin.
    pub fn from_arrangement(
        arr: &Arrangement,
        edge_data: impl FnMut(&[Source], Carrier) -> E,
    ) -> Result<Dcel<(), E, ()>> {
        Ok(Self::linked(arr, edge_data, true))
    }

    /// As [`Dcel::from_arrangement`]; with `resolve_holes` false every inner cycle is put
    /// in the unbounded face (no ray shooting: for callers that know the containment).
    pub(crate) fn linked(
        arr: &Arrangement,
        edge_data: impl FnMut(&[Source], Carrier) -> E,
        resolve_holes: bool,
    ) -> Dcel<(), E, ()> {
        let mut flat = Flat {
            vertices: arr.vertices.clone().into(),
            edges: Vec::with_capacity(arr.edges.len()),
            src_start: Vec::with_capacity(arr.edges.len() + 1),
            sources: Vec::with_capacity(arr.edges.len()),
        };
        flat.src_start.push(0);
        for (u, v, sources) in &arr.edges {
            flat.edges.push([*u as u32, *v as u32]);
            flat.sources.extend_from_slice(sources);
            flat.src_start.push(flat.sources.len() as u32);
        }
        Self::linked_flat(flat, &arr.segments, edge_data, resolve_holes)
    }

    /// The DCEL of a flat arrangement of `segments` (see [`Dcel::from_arrangement`]).
    pub(crate) fn linked_flat(
        flat: Flat,
        segments: &[Segment2],
        mut edge_data: impl FnMut(&[Source], Carrier) -> E,
        resolve_holes: bool,
    ) -> Dcel<(), E, ()> {
        let n = flat.vertices.len();
        let ne = flat.edge_count();
        let mut half_edges = Vec::with_capacity(2 * ne);
        let mut carriers = Vec::with_capacity(2 * ne);
        // Outgoing half-edges per vertex, as one array cut into slices (no list per vertex).
        let mut out_start = vec![0usize; n + 1];
        for [u, v] in &flat.edges {
            out_start[*u as usize + 1] += 1;
            out_start[*v as usize + 1] += 1;
        }
        for i in 0..n {
            out_start[i + 1] += out_start[i];
        }
        let mut fill = out_start.clone();
        let mut out = vec![0usize; 2 * ne];
        let mut back: Vec<Source> = Vec::new();
        for i in 0..ne {
            let [u, v] = flat.edges[i];
            let sources = flat.sources_of(i);
            let s0 = sources[0];
            let seg = segments[s0.segment];
            back.clear();
            back.extend(sources.iter().map(|s| Source {
                segment: s.segment,
                forward: !s.forward,
            }));
            for (h, (o, src)) in [(u as usize, sources), (v as usize, back.as_slice())]
                .into_iter()
                .enumerate()
            {
                let id = 2 * i + h;
                let carrier = Carrier {
                    seg,
                    forward: s0.forward == (h == 0),
                };
                half_edges.push(HalfEdge {
                    origin: VertexId(o),
                    twin: HalfEdgeId(id ^ 1),
                    next: HalfEdgeId(usize::MAX),
                    prev: HalfEdgeId(usize::MAX),
                    face: FaceId(usize::MAX),
                    data: edge_data(src, carrier),
                });
                carriers.push(carrier);
                out[fill[o]] = id;
                fill[o] += 1;
            }
        }
        link(
            flat.vertices.into_exact(),
            half_edges,
            carriers,
            &out_start,
            &mut out,
            resolve_holes,
        )
    }
}

impl Dcel<(), Vec<Source>, ()> {
    /// The arrangement of `segments` as a DCEL: each half-edge lists the input segments
    /// carrying it. Face data is `()`. O((n + k) log n) for n segments and k crossings
    /// (see the module docs; an example there).
    pub fn from_segments(segments: &[Segment2]) -> Result<Self> {
        let arr = Arrangement::of_segments(segments)?;
        Dcel::from_arrangement(&arr, |s, _| s.to_vec())
    }
}

/// Which polygons of a [`MultiPolygon`] contain a face (even-odd per polygon), ascending.
pub type PolygonLabel = Vec<usize>;

impl Dcel<(), Vec<Source>, PolygonLabel> {
    /// The subdivision induced by the rings of `polygons` (in any orientation); each face
    /// is labelled with the indices of the polygons containing it, each polygon read
    /// with the even-odd rule. Half-edge sources are ring edges, numbered ring by ring
    /// in [`polygon_segments`] order. Cost as [`Dcel::from_segments`]; the labels then
    /// spread across the edges in linear time.
    ///
    /// ```
    /// use compgeom::dcel::Dcel;
    /// use compgeom::{MultiPolygon, Point2, Polygon};
    /// let p = |x, y| Point2::new(x, y);
    /// // A square with a square hole: the hole's face is in no polygon.
    /// let frame = Polygon::new(vec![p(0., 0.), p(4., 0.), p(4., 4.), p(0., 4.)],
    ///     vec![vec![p(1., 1.), p(1., 3.), p(3., 3.), p(3., 1.)]]);
    /// let d = Dcel::from_polygons(&MultiPolygon(vec![frame])).unwrap();
    /// d.validate().unwrap();
    /// let labels: Vec<_> = d.face_ids().map(|f| d.face(f).data.clone()).collect();
    /// assert_eq!(labels.iter().filter(|l| l.is_empty()).count(), 2);
    /// assert_eq!(labels.iter().filter(|l| *l == &vec![0]).count(), 1);
    /// ```
    pub fn from_polygons(polygons: &MultiPolygon) -> Result<Self> {
        let (segs, owner) = polygon_segments(polygons)?;
        let d = Dcel::from_segments(&segs)?;
        Ok(d.label_faces(Vec::new(), |label, h| {
            let mut l = label.clone();
            for s in h {
                let p = owner[s.segment];
                match l.binary_search(&p) {
                    Ok(i) => {
                        l.remove(i);
                    }
                    Err(i) => l.insert(i, p),
                }
            }
            l
        }))
    }
}

/// The edges of every ring of `polygons` as segments (ring by ring, exterior first; a
/// closing point equal to the first is dropped) and the polygon owning each. Errors:
/// non-finite coordinates, rings with fewer than 3 distinct points.
pub fn polygon_segments(polygons: &MultiPolygon) -> Result<(Vec<Segment2>, Vec<usize>)> {
    let mut segs = Vec::new();
    let mut owner = Vec::new();
    for (pi, poly) in polygons.0.iter().enumerate() {
        for (ri, ring) in poly.rings().enumerate() {
            push_ring_segments(pi, ri, ring, false, &mut segs)?;
            owner.resize(segs.len(), pi);
        }
    }
    Ok((segs, owner))
}

/// Append the segments [`polygon_segments`] gives for ring `ri` of polygon `pi` (the
/// same checks and errors), or with `reversed` those it gives for the reversed ring,
/// without building that ring.
pub(crate) fn push_ring_segments(
    pi: usize,
    ri: usize,
    ring: &[Point2],
    reversed: bool,
    segs: &mut Vec<Segment2>,
) -> Result<()> {
    let what = || {
        if ri == 0 {
            format!("polygon {pi} exterior")
        } else {
            format!("polygon {pi} hole {}", ri - 1)
        }
    };
    // The first non-finite point in ring order (a reversed ring reports its own first).
    let mut bad = ring.iter().filter(|p| !p.is_finite());
    if let Some(p) = if reversed {
        bad.next_back()
    } else {
        bad.next()
    } {
        let value = if p.x.is_finite() { p.y } else { p.x };
        return Err(Error::NonFinite {
            what: what(),
            value,
        });
    }
    let mut r: &[Point2] = ring;
    // Reversed or not, the ring is closed exactly when its two ends are equal; reversed,
    // the end dropped is `ring[0]`, so the remaining points start at `ring[len − 1]`.
    let closed = r.len() > 1 && r[0] == r[r.len() - 1];
    if closed {
        r = if reversed { &r[1..] } else { &r[..r.len() - 1] };
    }
    // Three distinct points, found in one pass: the first point, the first one different
    // from it, the first one different from both (whether there are three does not
    // depend on the order, nor does the count in the error).
    let first = r.first().map(|&p| key(p));
    let second = first.and_then(|f| r.iter().map(|&p| key(p)).find(|&k| k != f));
    let third = second.and_then(|s| {
        r.iter()
            .map(|&p| key(p))
            .find(|&k| Some(k) != first && k != s)
    });
    if third.is_none() {
        let distinct = usize::from(first.is_some()) + usize::from(second.is_some());
        return Err(Error::InvalidInput(format!(
            "{}: a ring needs at least 3 distinct points, found {distinct}",
            what(),
        )));
    }
    let n = r.len();
    segs.reserve(n);
    if reversed {
        // The reversed sequence r[n − 1], …, r[0]: segment i runs from r[n − 1 − i] to
        // r[n − 2 − i], the last from r[0] back to r[n − 1].
        // (Pairs of neighbours without a division per point: the windows from the end,
        // then r[0] → r[n − 1].)
        for w in r.windows(2).rev() {
            let s = Segment2::new(w[1], w[0]);
            if !s.is_degenerate() {
                segs.push(s);
            }
        }
        let s = Segment2::new(r[0], r[n - 1]);
        if !s.is_degenerate() {
            segs.push(s);
        }
    } else {
        for w in r.windows(2) {
            let s = Segment2::new(w[0], w[1]);
            if !s.is_degenerate() {
                segs.push(s);
            }
        }
        let s = Segment2::new(r[n - 1], r[0]);
        if !s.is_degenerate() {
            segs.push(s);
        }
    }
    Ok(())
}

/// Link half-edges around vertices, form cycles and faces.
fn link<E>(
    points: Vec<ExactPoint>,
    mut half_edges: Vec<HalfEdge<E>>,
    carriers: Vec<Carrier>,
    out_start: &[usize],
    out: &mut [usize],
    resolve_holes: bool,
) -> Dcel<(), E, ()> {
    // Compact copies of the links (4 bytes per half-edge) for the walks below: a boundary
    // walk is a chain of dependent loads, cheap when they hit a small array.
    let m = half_edges.len();
    let origin: Vec<u32> = half_edges.iter().map(|h| h.origin.0 as u32).collect();
    let mut next = vec![0u32; m];
    // Angular order and next/prev.
    for v in 0..points.len() {
        let list = &mut out[out_start[v]..out_start[v + 1]];
        // With two half-edges either order gives the same `next` links: they are put
        // in order only if the hole sweep below needs it.
        if list.len() > 2 {
            list.sort_unstable_by(|&a, &b| carriers[a].angle_cmp(&carriers[b]));
        }
        let k = list.len();
        for j in 0..k {
            let incoming = list[j] ^ 1;
            next[incoming] = list[(j + k - 1) % k] as u32;
        }
    }
    for (h, &n) in next.iter().enumerate() {
        half_edges[h].next = HalfEdgeId(n as usize);
        half_edges[n as usize].prev = HalfEdgeId(h);
    }
    let vertices: Vec<Vertex<()>> = points
        .iter()
        .enumerate()
        .map(|(v, p)| Vertex {
            point: *p,
            approx: p.approx(),
            incident: (out_start[v] < out_start[v + 1]).then(|| HalfEdgeId(out[out_start[v]])),
            data: (),
        })
        .collect();
    let approx: Vec<super::holes::Rounded> = points
        .iter()
        .zip(&vertices)
        .map(|(p, v)| super::holes::Rounded::of(p, v.approx))
        .collect();
    // Cycles, each with a half-edge leaving its lexicographically smallest vertex.
    let mut cycle_of = vec![usize::MAX; m];
    let mut cycles: Vec<usize> = Vec::new(); // a start half-edge per cycle
    let mut lowest: Vec<usize> = Vec::new();
    for h in 0..m {
        if cycle_of[h] != usize::MAX {
            continue;
        }
        let c = cycles.len();
        cycles.push(h);
        let mut low = h;
        let mut e = h;
        loop {
            cycle_of[e] = c;
            let (a, b) = (origin[e] as usize, origin[low] as usize);
            if a != b
                && super::holes::compare_xy_filtered(&points[a], &approx[a], &points[b], &approx[b])
                    == Ordering::Less
            {
                low = e;
            }
            e = next[e] as usize;
            if e == h {
                break;
            }
        }
        lowest.push(low);
    }
    // Classify each cycle at its smallest vertex: outer iff it turns left at each visit.
    let mut is_outer = vec![true; cycles.len()];
    for h in 0..m {
        let c = cycle_of[h];
        if origin[h] != origin[lowest[c]] {
            continue;
        }
        let p = half_edges[h].prev.0;
        if carriers[p].turn(&carriers[h]) != Orientation::CounterClockwise {
            is_outer[c] = false;
        }
    }
    let mut faces: Vec<Face<()>> = vec![Face {
        outer: None,
        inner: Vec::new(),
        data: (),
    }];
    let mut face_of_cycle = vec![usize::MAX; cycles.len()];
    for (c, &h) in cycles.iter().enumerate() {
        if is_outer[c] {
            face_of_cycle[c] = faces.len();
            faces.push(Face {
                outer: Some(HalfEdgeId(h)),
                inner: Vec::new(),
                data: (),
            });
        }
    }
    // Holes (the book's graph G): each inner cycle is linked to the half-edge just left
    // of its leftmost vertex, read from the status of one sweep. With a single inner
    // cycle there is nothing to decide: it lies in the unbounded face.
    let inner_count = is_outer.iter().filter(|&&o| !o).count();
    let hit: Vec<Option<usize>> = if resolve_holes && inner_count > 1 {
        let mut query = vec![false; points.len()];
        for c in 0..cycles.len() {
            if !is_outer[c] {
                query[origin[lowest[c]] as usize] = true;
            }
        }
        for v in 0..points.len() {
            let list = &mut out[out_start[v]..out_start[v + 1]];
            if list.len() == 2
                && carriers[list[0]].angle_cmp(&carriers[list[1]]) == Ordering::Greater
            {
                list.swap(0, 1);
            }
        }
        let left = super::holes::faces_left_of(
            &points, &approx, &origin, &carriers, out_start, out, &query,
        );
        (0..cycles.len())
            .map(|c| {
                if is_outer[c] {
                    None
                } else {
                    left[origin[lowest[c]] as usize].map(|h| cycle_of[h])
                }
            })
            .collect()
    } else {
        vec![None; cycles.len()]
    };
    for c in 0..cycles.len() {
        if is_outer[c] {
            continue;
        }
        // Follow the chain of hits (strictly leftwards, so it ends).
        let mut d = c;
        let face = loop {
            if is_outer[d] {
                break face_of_cycle[d];
            }
            if face_of_cycle[d] != usize::MAX && d != c {
                break face_of_cycle[d];
            }
            match hit[d] {
                None => break 0,
                Some(next) => d = next,
            }
        };
        face_of_cycle[c] = face;
        faces[face].inner.push(HalfEdgeId(cycles[c]));
    }
    for h in 0..m {
        half_edges[h].face = FaceId(face_of_cycle[cycle_of[h]]);
    }
    Dcel {
        vertices,
        half_edges,
        faces,
        carriers,
    }
}

impl<V, E, F> Dcel<V, E, F> {
    /// The same subdivision with new half-edge data, `data[h]` for half-edge `h`
    /// (`data.len()` must be the number of half-edges).
    pub(crate) fn map_edge_data<G>(self, data: Vec<G>) -> Dcel<V, G, F> {
        debug_assert_eq!(data.len(), self.half_edges.len());
        let half_edges = self
            .half_edges
            .into_iter()
            .zip(data)
            .map(|(h, d)| HalfEdge {
                origin: h.origin,
                twin: h.twin,
                next: h.next,
                prev: h.prev,
                face: h.face,
                data: d,
            })
            .collect();
        Dcel {
            vertices: self.vertices,
            half_edges,
            faces: self.faces,
            carriers: self.carriers,
        }
    }

    /// Replace the face data by labels propagated from the unbounded face (labelled
    /// `outside`) across edges: the face left of half-edge `h` gets `cross(label of the
    /// face right of h, data of h)`. Every face is reached (each component's outer
    /// boundary belongs to the face containing it), in breadth-first order.
    pub fn label_faces<G: Clone>(
        self,
        outside: G,
        mut cross: impl FnMut(&G, &E) -> G,
    ) -> Dcel<V, E, G> {
        let nf = self.faces.len();
        let mut labels: Vec<Option<G>> = vec![None; nf];
        labels[0] = Some(outside);
        // The walks use compact copies of `next` and `face` (8 bytes per half-edge).
        let links: Vec<(u32, u32)> = self
            .half_edges
            .iter()
            .map(|h| (h.next.0 as u32, h.face.0 as u32))
            .collect();
        let mut queue = std::collections::VecDeque::from([FaceId(0)]);
        while let Some(f) = queue.pop_front() {
            for start in self.face_cycles(f) {
                let mut h = start.0;
                loop {
                    let t = h ^ 1; // half-edges 2i and 2i + 1 are twins
                    let g = links[t].1 as usize;
                    if labels[g].is_none() {
                        let from = labels[f.0].as_ref().expect("labelled");
                        labels[g] = Some(cross(from, &self.half_edges[t].data));
                        queue.push_back(FaceId(g));
                    }
                    h = links[h].0 as usize;
                    if h == start.0 {
                        break;
                    }
                }
            }
        }
        let Dcel {
            vertices,
            half_edges,
            faces,
            carriers,
        } = self;
        let faces = faces
            .into_iter()
            .zip(labels)
            .map(|(f, l)| Face {
                outer: f.outer,
                inner: f.inner,
                data: l.expect("every face is reachable from the unbounded face"),
            })
            .collect();
        Dcel {
            vertices,
            half_edges,
            faces,
            carriers,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axis_parallel_turns_agree_with_the_slope_comparison() {
        let p = |x: f64, y: f64| Point2::new(x, y);
        // Every pair of the four axis directions (with tiny and huge lengths), both ways.
        let segs = [
            Segment2::new(p(0.0, 0.0), p(1e-300, 0.0)),
            Segment2::new(p(3.0, 5.0), p(-1e300, 5.0)),
            Segment2::new(p(-2.0, 0.5), p(-2.0, 7.0)),
            Segment2::new(p(1.0, 1.0), p(1.0, -0.25)),
            Segment2::new(p(0.0, 0.0), p(2.0, 3.0)),
        ];
        for s in segs {
            for t in segs {
                for (f1, f2) in [(true, true), (true, false), (false, true), (false, false)] {
                    assert_eq!(
                        cross_dirs(s, f1, t, f2),
                        cross_dirs_slopes(s, f1, t, f2),
                        "{s:?} {f1} {t:?} {f2}"
                    );
                }
            }
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(500))]

        /// Where the filter answers, it is the exact slope comparison: on a small integer
        /// grid (parallel and anti-parallel directions, equal segments), on random input
        /// and at tiny and huge magnitudes (underflowing and overflowing products).
        #[test]
        fn the_filtered_turn_is_the_exact_one(
            c in proptest::collection::vec(-4..5i32, 8),
            r in proptest::collection::vec(-1.0..1.0f64, 8),
            grid in proptest::bool::ANY,
            scale in proptest::sample::select(vec![1.0, 3.0e-10, 1e-160, 1e-300, 1e150, 1e300]),
            f1 in proptest::bool::ANY,
            f2 in proptest::bool::ANY,
        ) {
            let v: Vec<f64> = (0..8)
                .map(|k| if grid { c[k] as f64 } else { r[k] } * scale)
                .collect();
            let s = Segment2::new(Point2::new(v[0], v[1]), Point2::new(v[2], v[3]));
            let t = Segment2::new(Point2::new(v[4], v[5]), Point2::new(v[6], v[7]));
            if let Some(fast) = cross_dirs_filtered(s, f1, t, f2) {
                proptest::prop_assert_eq!(fast, cross_dirs_slopes(s, f1, t, f2));
            }
            // A nearly parallel copy: the filter must not answer wrongly either.
            let u = Segment2::new(s.a, Point2::new(f64::from_bits(s.b.x.to_bits() ^ 1), s.b.y));
            if let Some(fast) = cross_dirs_filtered(s, f1, u, f2) {
                proptest::prop_assert_eq!(fast, cross_dirs_slopes(s, f1, u, f2));
            }
            // Directions parallel up to rounding (a scaled copy, and one through a far
            // point): products that nearly cancel.
            let (dx, dy) = (s.b.x - s.a.x, s.b.y - s.a.y);
            for k in [3.0, 0.1, -7.3] {
                let o = Point2::new(v[4] * 1e3, v[5]);
                let w = Segment2::new(o, Point2::new(o.x + k * dx, o.y + k * dy));
                if let Some(fast) = cross_dirs_filtered(s, f1, w, f2) {
                    proptest::prop_assert_eq!(fast, cross_dirs_slopes(s, f1, w, f2));
                }
            }
            proptest::prop_assert_eq!(cross_dirs(s, f1, t, f2), cross_dirs_slopes(s, f1, t, f2));
        }
    }
}
