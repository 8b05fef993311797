//! The arrangement of a set of segments in flat arrays (no hash maps, no list per edge):
//! what the DCEL builders link.
//!
//! Three ways to the same arrangement, all exact:
//!
//! * [`Flat::noded`] (`noding.rs`, the default for segments that are not all
//!   axis-parallel): the cuts each segment needs, from the exact tests of the pairs an
//!   x-interval sweep (or the intersection grid) proposes, vertices joined by
//!   union–find; it falls back to the sweep below when the grid would test too many
//!   pairs.
//! * [`Flat::general`]: the exact intersection sweep ([`find_intersections`]) reports
//!   every point lying on two or more segments, with U(p), L(p) and C(p). Each reported
//!   point becomes one vertex (they are distinct exact points), so no point look-up is
//!   needed: an endpoint not reported lies on its segment only and gets a vertex of its
//!   own. Each segment is cut at its interior points (reported in sweep order, i.e. along
//!   it). Pieces of different segments can only share both ends when the segments
//!   overlap collinearly, so only segments in a reported overlap go through a merge.
//! * [`Flat::axis_parallel`]: when every segment is horizontal or vertical, a crossing is
//!   the point (x of the vertical, y of the horizontal): exact `f64` coordinates, no
//!   constructed point. One sweep in x over the horizontal segments (ordered by y)
//!   reports every horizontal–vertical contact; each line (the segments sharing one
//!   horizontal or vertical line) is then cut at its segments' endpoints and contacts,
//!   and every piece between consecutive cuts gets the segments covering it (collinear
//!   overlaps merged on the way). O((n + k) log n) for k contacts. Every vertex is an
//!   input-precision point, so everything after (angular order, hole linking, output)
//!   runs on plain `f64` comparisons.
//!
//! All give the same vertices (as exact points), the same edges and the same sources
//! per edge; they differ only in numbering (tested against each other and against a
//! brute-force oracle).
use super::build::Source;
use super::holes::{compare_xy_filtered_by, Rounded};
use crate::intersect::find_intersections;
use crate::kernel::arith::ordered_key as okey;
use crate::kernel::{orient2d, Crossing, ExactPoint, Orientation, Point2, Segment2};
use crate::{Error, Result};
use std::cmp::Ordering;
use std::collections::HashMap;

/// The arrangement of `segments`: edge `i` runs `edges[i][0] → edges[i][1]` and is carried
/// by `sources[src_start[i]..src_start[i + 1]]` (ascending segment index; `forward` is
/// relative to the edge's direction), or by `sources[i]` alone when `src_start` is empty
/// (every edge on one segment: read them through [`Flat::sources_of`]). Segment indices refer to the caller's list
/// (zero-length segments are skipped and carry nothing).
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct Flat {
    pub vertices: Vertices,
    pub edges: Vec<[u32; 2]>,
    pub src_start: Vec<u32>,
    pub sources: Vec<Source>,
}

/// The sources of a [`Flat`]'s edges without the rest of it ([`Flat::sources_by_edge`]).
pub(crate) struct EdgeSources {
    src_start: Vec<u32>,
    sources: Vec<Source>,
}

impl EdgeSources {
    /// The sources of edge `i`, as [`Flat::sources_of`] gives them.
    pub(crate) fn of(&self, i: usize) -> &[Source] {
        sources_in(&self.src_start, &self.sources, i)
    }
}

/// Edge `i`'s sources in the lists of a [`Flat`].
#[inline]
fn sources_in<'a>(src_start: &[u32], sources: &'a [Source], i: usize) -> &'a [Source] {
    if src_start.is_empty() {
        return std::slice::from_ref(&sources[i]);
    }
    &sources[src_start[i] as usize..src_start[i + 1] as usize]
}

/// The vertices of a [`Flat`], each with its nearest `f64` point: exact points stored
/// compactly (a crossing's two segments only where the vertex is one), or, when every
/// vertex is an input point (the axis-parallel path), plain points.
///
/// The vertices are the largest array of the arrangement, written once and read again by
/// every later pass; most are input points, so a crossing's 64 bytes are kept apart, for
/// the crossings only, and an input vertex takes 20 bytes instead of 88 (its exact point
/// and its nearest point). Stored whole, they were the largest block an overlay held at
/// its peak (2.1 of 9 MB on the water map), and memory beyond what the allocator keeps
/// between calls costs a page fault per page, every call.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Vertices {
    /// Vertex `i` is the input point `approx[i]` where `crossing[i]` is
    /// [`NOT_A_CROSSING`], else the crossing `crossings[crossing[i]]`, whose correctly
    /// rounded point is `approx[i]` (the exact tests filter on it). (Fewer than 2³² − 1
    /// crossings: the noding caps its contacts below 2³¹, and more would not fit in
    /// memory, at 64 bytes each.)
    Exact {
        approx: Vec<Point2>,
        crossing: Vec<u32>,
        crossings: Vec<Crossing>,
    },
    Input(Vec<Point2>),
}

/// [`Vertices::Exact`]'s mark of an input vertex.
const NOT_A_CROSSING: u32 = u32::MAX;

impl Default for Vertices {
    fn default() -> Self {
        Vertices::Input(Vec::new())
    }
}

impl From<Vec<ExactPoint>> for Vertices {
    /// (Each crossing rounded here: about 1.8 k instructions each.)
    fn from(points: Vec<ExactPoint>) -> Self {
        let mut v = ExactVertices::with_capacity(points.len(), 0);
        for p in points {
            v.push(p, p.approx());
        }
        v.into()
    }
}

impl From<Vec<Point2>> for Vertices {
    fn from(v: Vec<Point2>) -> Self {
        Vertices::Input(v)
    }
}

/// [`Vertices::Exact`] built vertex by vertex.
pub(crate) struct ExactVertices {
    approx: Vec<Point2>,
    crossing: Vec<u32>,
    crossings: Vec<Crossing>,
}

impl ExactVertices {
    /// Room for `n` vertices, `crossings` of them crossings.
    pub(crate) fn with_capacity(n: usize, crossings: usize) -> ExactVertices {
        ExactVertices {
            approx: Vec::with_capacity(n),
            crossing: Vec::with_capacity(n),
            crossings: Vec::with_capacity(crossings),
        }
    }

    /// The next vertex, `p`, whose nearest `f64` point is `approx` (correctly rounded:
    /// the exact tests filter on it).
    #[inline]
    pub(crate) fn push(&mut self, p: ExactPoint, approx: Point2) {
        debug_assert!(p.approx() == approx);
        self.approx.push(approx);
        match p {
            ExactPoint::Input(_) => self.crossing.push(NOT_A_CROSSING),
            ExactPoint::Crossing(c) => {
                self.crossing.push(self.crossings.len() as u32);
                self.crossings.push(c);
            }
        }
    }

    /// The number of vertices so far.
    pub(crate) fn len(&self) -> usize {
        self.approx.len()
    }
}

impl From<ExactVertices> for Vertices {
    fn from(v: ExactVertices) -> Self {
        Vertices::Exact {
            approx: v.approx,
            crossing: v.crossing,
            crossings: v.crossings,
        }
    }
}

/// Whether `q` differs from the exact point `p`, exactly: an input point is itself, and
/// a crossing is `q` iff `q` lies on both its lines.
pub(crate) fn rounded_away(p: &ExactPoint, q: Point2) -> bool {
    match p {
        ExactPoint::Input(a) => *a != q,
        ExactPoint::Crossing(c) => {
            orient2d(c.s.a, c.s.b, q) != Orientation::Collinear
                || orient2d(c.t.a, c.t.b, q) != Orientation::Collinear
        }
    }
}

impl Vertices {
    /// Exact points with their nearest `f64` points (`approx[i]` is `points[i].approx()`,
    /// correctly rounded: the exact tests filter on it).
    pub(crate) fn rounded_exact(points: Vec<ExactPoint>, approx: Vec<Point2>) -> Self {
        debug_assert_eq!(points.len(), approx.len());
        let mut v = ExactVertices::with_capacity(points.len(), 0);
        for (p, a) in points.into_iter().zip(approx) {
            v.push(p, a);
        }
        v.into()
    }

    /// The number of vertices.
    #[inline]
    pub(crate) fn len(&self) -> usize {
        match self {
            Vertices::Exact { approx, .. } => approx.len(),
            Vertices::Input(v) => v.len(),
        }
    }

    /// Vertex `i` when it is an input point.
    #[inline]
    pub(crate) fn input(&self, i: usize) -> Option<Point2> {
        match self {
            Vertices::Exact {
                approx, crossing, ..
            } => (crossing[i] == NOT_A_CROSSING).then(|| approx[i]),
            Vertices::Input(v) => Some(v[i]),
        }
    }

    /// The nearest `f64` point of vertex `i`.
    #[inline]
    pub(crate) fn approx(&self, i: usize) -> Point2 {
        match self {
            Vertices::Exact { approx, .. } => approx[i],
            Vertices::Input(v) => v[i],
        }
    }

    /// The rounded point of vertex `i` with its exactness flags.
    #[inline(always)]
    pub(crate) fn rounded(&self, i: usize) -> Rounded {
        match self {
            Vertices::Exact {
                approx,
                crossing,
                crossings,
            } => match crossing[i] {
                NOT_A_CROSSING => Rounded::input(approx[i]),
                k => Rounded::crossing(&crossings[k as usize], approx[i]),
            },
            Vertices::Input(v) => Rounded::input(v[i]),
        }
    }

    /// Vertex `i` as an exact point.
    #[inline(always)]
    pub(crate) fn exact_point(&self, i: usize) -> ExactPoint {
        match self {
            Vertices::Exact {
                approx,
                crossing,
                crossings,
            } => match crossing[i] {
                NOT_A_CROSSING => ExactPoint::Input(approx[i]),
                k => ExactPoint::Crossing(crossings[k as usize]),
            },
            Vertices::Input(v) => ExactPoint::Input(v[i]),
        }
    }

    /// Whether vertex `i`'s rounded point `r` (from [`Vertices::rounded`]) differs from
    /// its exact point, exactly: a crossing is `r` iff `r` lies on both its lines.
    pub(crate) fn moved(&self, i: usize, r: &Rounded) -> bool {
        !r.surely_exact() && rounded_away(&self.exact_point(i), r.point())
    }

    /// [`compare_xy_filtered_by`] of vertices `a` and `b` with their rounded points (the
    /// exact points are made from the compact ones, and read only where the rounded ones
    /// do not decide).
    #[inline]
    pub(crate) fn compare_xy(&self, a: usize, ra: &Rounded, b: usize, rb: &Rounded) -> Ordering {
        compare_xy_filtered_by(ra, rb, || (self.exact_point(a), self.exact_point(b)))
    }

    /// All vertices as exact points.
    pub(crate) fn exact(&self) -> Vec<ExactPoint> {
        (0..self.len()).map(|i| self.exact_point(i)).collect()
    }

    /// All vertices as exact points.
    pub(crate) fn into_exact(self) -> Vec<ExactPoint> {
        match self {
            Vertices::Exact { .. } => self.exact(),
            Vertices::Input(v) => v.into_iter().map(ExactPoint::Input).collect(),
        }
    }
}

/// True when `a` comes first in sweep order (higher y, then smaller x).
fn sweep_first(a: Point2, b: Point2) -> bool {
    a.y > b.y || (a.y == b.y && a.x < b.x)
}

/// Sorted keys with every [`SAMPLE_EVERY`]th of them beside, for binary searches that
/// touch few cache lines: one in the sample (small enough to stay in the caches), one
/// in a block of keys. The axis-parallel sweep searches the horizontal sides' keys for
/// each vertical side, at random; on 4 × 10⁶ sides (`union_all` of 10⁶ squares) the
/// plain searches' cache misses were a seventh of the call.
struct SampledKeys<'a> {
    keys: &'a [u64],
    sample: Vec<u64>,
}

/// See [`SampledKeys`].
const SAMPLE_EVERY: usize = 64;

impl<'a> SampledKeys<'a> {
    fn new(keys: &'a [u64]) -> Self {
        SampledKeys {
            keys,
            sample: keys.iter().step_by(SAMPLE_EVERY).copied().collect(),
        }
    }

    /// `keys.partition_point(below)`, for `below` true up to some key and false after.
    fn partition_point(&self, below: impl Fn(u64) -> bool) -> usize {
        // The blocks whose first key is below: the point is past the first key of the
        // last of them, and not past the first key of the next.
        let blocks = self.sample.partition_point(|&k| below(k));
        if blocks == 0 {
            return 0;
        }
        let from = (blocks - 1) * SAMPLE_EVERY;
        let to = (blocks * SAMPLE_EVERY).min(self.keys.len());
        from + self.keys[from..to].partition_point(|&k| below(k))
    }
}

/// A set of numbers below a bound, as bits, with one summary bit per word of bits
/// (set iff the word is not zero), so that listing the members in a range skips empty
/// stretches 4096 numbers at a time: O(range / 4096 + words touched + members).
struct BitSet {
    words: Vec<u64>,
    summary: Vec<u64>,
}

impl BitSet {
    fn new(bound: usize) -> Self {
        let words = bound.div_ceil(64);
        BitSet {
            words: vec![0; words],
            summary: vec![0; words.div_ceil(64)],
        }
    }

    fn insert(&mut self, i: usize) {
        let w = i >> 6;
        self.words[w] |= 1 << (i & 63);
        self.summary[w >> 6] |= 1 << (w & 63);
    }

    fn remove(&mut self, i: usize) {
        let w = i >> 6;
        self.words[w] &= !(1 << (i & 63));
        if self.words[w] == 0 {
            self.summary[w >> 6] &= !(1 << (w & 63));
        }
    }

    /// Calls `f` on the members in `a..b`, ascending.
    fn for_each_in(&self, a: usize, b: usize, mut f: impl FnMut(usize)) {
        if a >= b {
            return;
        }
        let (w0, w1) = (a >> 6, (b - 1) >> 6);
        let mut w = w0;
        while w <= w1 {
            // The next non-empty word at or after w, by the summary.
            let pending = self.summary[w >> 6] >> (w & 63);
            if pending == 0 {
                w = ((w >> 6) + 1) << 6;
                continue;
            }
            w += pending.trailing_zeros() as usize;
            if w > w1 {
                break;
            }
            let mut bits = self.words[w];
            if w == w0 {
                bits &= !0u64 << (a & 63);
            }
            if w == w1 {
                bits &= !0u64 >> (63 - ((b - 1) & 63));
            }
            while bits != 0 {
                f((w << 6) + bits.trailing_zeros() as usize);
                bits &= bits - 1;
            }
            w += 1;
        }
    }
}

/// The vertices renumbered in order of first use by `edges` (whose ends are renamed in
/// place); vertices on no edge are appended.
fn renumber_vertices<P: Copy>(edges: &mut [[u32; 2]], vertices: &[P]) -> Vec<P> {
    let mut new_v = vec![u32::MAX; vertices.len()];
    let mut renumbered: Vec<P> = Vec::with_capacity(vertices.len());
    for e in edges.iter_mut() {
        for v in e.iter_mut() {
            let slot = &mut new_v[*v as usize];
            if *slot == u32::MAX {
                *slot = renumbered.len() as u32;
                renumbered.push(vertices[*v as usize]);
            }
            *v = *slot;
        }
    }
    // Vertices on no edge (none are made, but keep the invariant).
    for (v, p) in vertices.iter().enumerate() {
        if new_v[v] == u32::MAX {
            renumbered.push(*p);
        }
    }
    renumbered
}

/// Edges with their sources, collected piece by piece.
pub(super) struct Pieces {
    pub(super) edges: Vec<[u32; 2]>,
    /// `(edge, source)` in any order.
    pub(super) pairs: Vec<(u32, Source)>,
}

impl Pieces {
    /// [`Pieces::finish_numbered`] summed up as [`Flat::summed`] does, for pairs pushed
    /// in ascending segment order within each edge (the first one pushed for an edge is
    /// its first source), without sorting the pairs by edge.
    pub(super) fn finish_summed(
        self,
        vertices: impl Into<Vertices>,
        na: usize,
    ) -> (Flat, Vec<(i32, i32)>) {
        let Pieces { edges, pairs } = self;
        let ne = edges.len();
        let unset = Source {
            segment: usize::MAX,
            forward: false,
        };
        let mut firsts = vec![unset; ne];
        let mut deltas = vec![(0, 0); ne];
        for (e, src) in &pairs {
            let e = *e as usize;
            if firsts[e].segment == usize::MAX {
                firsts[e] = *src;
            }
            deltas[e] = add_source(deltas[e], src, na);
        }
        debug_assert!(firsts.iter().all(|s| s.segment != usize::MAX));
        let flat = Flat {
            vertices: vertices.into(),
            edges,
            src_start: Vec::new(),
            sources: firsts,
        };
        (flat, deltas)
    }

    /// The flat arrangement, vertices already numbered in order of first use by the edges;
    /// `in_order` when the pairs of each edge come in ascending segment order (then the
    /// stable placement by edge below leaves them so, and they are not sorted again).
    pub(super) fn finish_numbered(self, vertices: impl Into<Vertices>, in_order: bool) -> Flat {
        let Pieces { edges, pairs } = self;
        // One source per edge, in edge order (no overlaps): nothing to sort.
        let vertices = vertices.into();
        if pairs.len() == edges.len() && pairs.iter().enumerate().all(|(i, p)| p.0 == i as u32) {
            return Flat {
                vertices,
                edges,
                src_start: (0..=pairs.len() as u32).collect(),
                sources: pairs.into_iter().map(|(_, s)| s).collect(),
            };
        }
        // Counting sort by edge, sources ascending by segment within an edge.
        let mut src_start = vec![0u32; edges.len() + 1];
        for (e, _) in &pairs {
            src_start[*e as usize + 1] += 1;
        }
        for i in 0..edges.len() {
            src_start[i + 1] += src_start[i];
        }
        let blank = Source {
            segment: 0,
            forward: false,
        };
        let mut sources = vec![blank; pairs.len()];
        let mut fill: Vec<u32> = src_start[..edges.len()].to_vec();
        for (e, src) in pairs {
            sources[fill[e as usize] as usize] = src;
            fill[e as usize] += 1;
        }
        if !in_order {
            for i in 0..edges.len() {
                let (a, b) = (src_start[i] as usize, src_start[i + 1] as usize);
                if b - a > 1 {
                    sources[a..b].sort_unstable_by_key(|s| s.segment);
                }
            }
        }
        debug_assert!((0..edges.len()).all(|i| {
            let (a, b) = (src_start[i] as usize, src_start[i + 1] as usize);
            sources[a..b]
                .windows(2)
                .all(|w| w[0].segment < w[1].segment)
        }));
        Flat {
            vertices,
            edges,
            src_start,
            sources,
        }
    }
}

impl Flat {
    /// The arrangement by the fastest exact path for the input.
    /// Non-finite coordinates are an error naming the segment.
    pub(crate) fn of_segments(segments: &[Segment2]) -> Result<Flat> {
        check_finite(segments)?;
        match Flat::axis_parallel(segments) {
            Some(f) => Ok(f),
            None => Flat::noded(segments),
        }
    }

    /// [`Flat::of_segments`] summed up for winding numbers ([`Flat::summed`]), the first
    /// `na` segments from one input, the rest from the other.
    pub(crate) fn of_segments_summed(
        segments: &[Segment2],
        na: usize,
    ) -> Result<(Flat, Vec<(i32, i32)>)> {
        check_finite(segments)?;
        match Flat::axis_parallel(segments) {
            Some(f) => Ok(f.summed(na)),
            None => Flat::noded_summed(segments, na),
        }
    }

    /// The arrangement with only the first source of each edge (`src_start` empty), and
    /// per edge the changes `(da, db)` of the winding numbers with respect to the first
    /// `na` segments and the rest when crossing it from right to left (edge `i` running
    /// `edges[i][0] → edges[i][1]`; a source running the same way adds one, the other
    /// way subtracts one): all a boolean operation needs of the sources.
    pub(crate) fn summed(self, na: usize) -> (Flat, Vec<(i32, i32)>) {
        let ne = self.edges.len();
        if self.src_start.is_empty() {
            // One source per edge already: kept as it is (on big input a copy is as
            // many fresh pages).
            let deltas = self
                .sources
                .iter()
                .map(|s| add_source((0, 0), s, na))
                .collect();
            return (self, deltas);
        }
        let mut firsts = Vec::with_capacity(ne);
        let mut deltas = Vec::with_capacity(ne);
        for i in 0..ne {
            let src = self.sources_of(i);
            firsts.push(src[0]);
            deltas.push(src.iter().fold((0, 0), |d, s| add_source(d, s, na)));
        }
        let flat = Flat {
            src_start: Vec::new(),
            sources: firsts,
            ..self
        };
        (flat, deltas)
    }
}

/// `d` with source `s` added ([`Flat::summed`]).
#[inline(always)]
fn add_source((da, db): (i32, i32), s: &Source, na: usize) -> (i32, i32) {
    let w = if s.forward { 1 } else { -1 };
    if s.segment < na {
        (da + w, db)
    } else {
        (da, db + w)
    }
}

/// `Err` naming the first segment with a non-finite coordinate.
pub(super) fn check_finite(segments: &[Segment2]) -> Result<()> {
    {
        // x · 0 is 0 (or −0) for finite x, NaN for infinities and NaN: one sum without
        // branches tells whether all are finite; only then the segment is looked for.
        let zero = segments.iter().fold(0.0, |acc, s| {
            acc + (s.a.x * 0.0 + s.a.y * 0.0) + (s.b.x * 0.0 + s.b.y * 0.0)
        });
        if zero != 0.0 {
            for (i, s) in segments.iter().enumerate() {
                for p in [s.a, s.b] {
                    if !p.is_finite() {
                        let value = if p.x.is_finite() { p.y } else { p.x };
                        return Err(Error::NonFinite {
                            what: format!("segment {i}"),
                            value,
                        });
                    }
                }
            }
        }
    }
    Ok(())
}

impl Flat {
    /// The number of edges.
    pub(crate) fn edge_count(&self) -> usize {
        self.edges.len()
    }

    /// The sources of edge `i`.
    #[inline]
    pub(crate) fn sources_of(&self, i: usize) -> &[Source] {
        sources_in(&self.src_start, &self.sources, i)
    }

    /// A copy of the edges' sources, to read after the arrangement is made into a DCEL
    /// (a few bytes per edge).
    pub(crate) fn sources_by_edge(&self) -> EdgeSources {
        EdgeSources {
            src_start: self.src_start.clone(),
            sources: self.sources.clone(),
        }
    }

    /// The arrangement from the exact intersection sweep (any segments). Segments must be
    /// finite (checked by the caller).
    pub(crate) fn general(segments: &[Segment2]) -> Result<Flat> {
        let kept: Vec<usize> = (0..segments.len())
            .filter(|&i| !segments[i].is_degenerate())
            .collect();
        let sub: Vec<Segment2> = kept.iter().map(|&i| segments[i]).collect();
        let found = find_intersections(&sub)?;
        let m = sub.len();
        const NONE: u32 = u32::MAX;
        let mut vertices: Vec<ExactPoint> = Vec::with_capacity(found.points.len() + 16);
        let (mut up_v, mut low_v) = (vec![NONE; m], vec![NONE; m]);
        // Interior points per segment, flat (counted first).
        let mut in_start = vec![0u32; m + 1];
        for p in &found.points {
            for &s in p.interior() {
                in_start[s + 1] += 1;
            }
        }
        for i in 0..m {
            in_start[i + 1] += in_start[i];
        }
        let mut fill: Vec<u32> = in_start[..m].to_vec();
        let mut inner = vec![0u32; in_start[m] as usize];
        // Their nearest f64 points, from the sweep (which rounded the crossings).
        let mut approx: Vec<Point2> = Vec::with_capacity(vertices.capacity());
        for (id, p) in found.points.iter().enumerate() {
            vertices.push(p.exact(&sub));
            approx.push(p.point);
            let id = id as u32;
            for &s in p.upper() {
                up_v[s] = id;
            }
            for &s in p.lower() {
                low_v[s] = id;
            }
            for &s in p.interior() {
                inner[fill[s] as usize] = id;
                fill[s] += 1;
            }
        }
        // Segments in an overlap: only their pieces can coincide with other pieces.
        let mut shared = vec![false; m];
        for o in &found.overlaps {
            for &s in &o.segments {
                shared[s] = true;
            }
        }
        let mut merged: HashMap<(u32, u32), u32> = HashMap::new();
        let mut pieces = Pieces {
            edges: Vec::with_capacity(m + inner.len()),
            pairs: Vec::with_capacity(m + inner.len()),
        };
        let mut chain: Vec<u32> = Vec::new();
        for (k, s) in sub.iter().enumerate() {
            let a_first = sweep_first(s.a, s.b);
            let (up, low) = if a_first { (s.a, s.b) } else { (s.b, s.a) };
            // An endpoint not reported lies on this segment only: a vertex of its own.
            for (slot, q) in [(&mut up_v[k], up), (&mut low_v[k], low)] {
                if *slot == NONE {
                    *slot = vertices.len() as u32;
                    vertices.push(ExactPoint::Input(q));
                    approx.push(q);
                }
            }
            chain.clear();
            chain.push(up_v[k]);
            chain.extend_from_slice(&inner[in_start[k] as usize..in_start[k + 1] as usize]);
            chain.push(low_v[k]);
            for w in chain.windows(2) {
                // Pieces run down the segment: like it iff a is its upper end.
                let (u, v) = (w[0], w[1]);
                let src = Source {
                    segment: kept[k],
                    forward: a_first,
                };
                if !shared[k] {
                    pieces.pairs.push((pieces.edges.len() as u32, src));
                    pieces.edges.push([u, v]);
                    continue;
                }
                let pair = (u.min(v), u.max(v));
                let e = *merged.entry(pair).or_insert_with(|| {
                    pieces.edges.push([u, v]);
                    pieces.edges.len() as u32 - 1
                });
                let forward = if pieces.edges[e as usize][0] == u {
                    a_first
                } else {
                    !a_first
                };
                pieces.pairs.push((
                    e,
                    Source {
                        segment: kept[k],
                        forward,
                    },
                ));
            }
        }
        let both: Vec<(ExactPoint, Point2)> = vertices.into_iter().zip(approx).collect();
        let both = renumber_vertices(&mut pieces.edges, &both);
        let (vertices, approx) = both.into_iter().unzip();
        // (Sources were pushed segment by segment: ascending within each edge.)
        Ok(pieces.finish_numbered(Vertices::rounded_exact(vertices, approx), true))
    }

    /// The arrangement of horizontal and vertical segments (zero-length ones skipped),
    /// or `None` when some segment is neither. Segments must be finite.
    pub(crate) fn axis_parallel(segments: &[Segment2]) -> Option<Flat> {
        // Per segment: axis (0 = horizontal: runs along x; 1 = vertical), the fixed
        // coordinate, and the range along the axis.
        #[derive(Clone, Copy)]
        struct Seg {
            axis: u8,
            across: f64,
            lo: f64,
            hi: f64,
            index: u32,
            /// True when the segment runs from `lo` to `hi`.
            increasing: bool,
        }
        // (Most inputs have an oblique segment near the front: found before allocating.)
        let axis_parallel = |s: &Segment2| s.a.y == s.b.y || s.a.x == s.b.x;
        if !segments.iter().all(axis_parallel) {
            return None;
        }
        let mut segs: Vec<Seg> = Vec::with_capacity(segments.len());
        for (i, s) in segments.iter().enumerate() {
            if s.is_degenerate() {
                continue;
            }
            let (axis, across, a, b) = if s.a.y == s.b.y {
                (0, s.a.y, s.a.x, s.b.x)
            } else if s.a.x == s.b.x {
                (1, s.a.x, s.a.y, s.b.y)
            } else {
                return None;
            };
            segs.push(Seg {
                axis,
                across: across + 0.0,
                lo: a.min(b) + 0.0,
                hi: a.max(b) + 0.0,
                index: i as u32,
                increasing: a < b,
            });
        }
        // The point at `along` on a line of `axis` through `across`.
        let point = |axis: u8, across: f64, along: f64| {
            if axis == 0 {
                Point2::new(along, across)
            } else {
                Point2::new(across, along)
            }
        };
        // Lines: segments grouped by (axis, across), ordered by `lo` within a line.
        // The keys are sorted themselves (not indices looking them up per comparison);
        // `k` last: segments are in input order, so it breaks ties as `index` would.
        // The segments are then copied into that order: every later pass (the sweep,
        // the cuts, the pieces) reads them front to back instead of at random.
        // The key is narrow (16 bytes, not 32 for (axis, across, lo, k)): the axis is
        // a split of the array (horizontals first), `lo` a second sort of each run of
        // equal `across` (a line holds few segments), so the big sort moves half the bytes.
        let segs: Vec<Seg> = {
            let horizontal_count = segs.iter().filter(|s| s.axis == 0).count();
            let mut keyed: Vec<(u64, u32)> = vec![(0, 0); segs.len()];
            let (mut h, mut v) = (0, horizontal_count);
            for (k, s) in segs.iter().enumerate() {
                let slot = if s.axis == 0 { &mut h } else { &mut v };
                keyed[*slot] = (okey(s.across), k as u32);
                *slot += 1;
            }
            let (horizontal, vertical) = keyed.split_at_mut(horizontal_count);
            for part in [horizontal, vertical] {
                part.sort_unstable();
                let mut a = 0;
                while a < part.len() {
                    let mut b = a + 1;
                    while b < part.len() && part[b].0 == part[a].0 {
                        b += 1;
                    }
                    if b - a > 1 {
                        part[a..b].sort_unstable_by_key(|t| (okey(segs[t.1 as usize].lo), t.1));
                    }
                    a = b;
                }
            }
            keyed.iter().map(|t| segs[t.1 as usize]).collect()
        };
        let n = segs.len();
        let mut line_of = vec![0u32; n];
        let mut lines: Vec<usize> = Vec::with_capacity(n + 1); // line starts in `segs`
        for r in 0..n {
            let same = r > 0 && {
                let (s, t) = (&segs[r], &segs[r - 1]);
                t.axis == s.axis && t.across == s.across
            };
            if !same {
                lines.push(r);
            }
            line_of[r] = lines.len() as u32 - 1;
        }
        let line_count = lines.len();
        lines.push(n);
        // Horizontals first (by y, then x), then verticals (by x, then y).
        let first_vertical_seg = segs.partition_point(|s| s.axis == 0);
        // Contacts of horizontal and vertical segments (closed), as (horizontal,
        // vertical) positions in `segs`: sweep in x; at equal x, horizontals enter, then
        // verticals query [lo, hi] in y, then horizontals leave. The horizontals are
        // numbered in y order, so the active ones are a bit set and the horizontals in a
        // y range are a range of numbers (two binary searches in their y keys). The
        // sweep's records are dropped before the cuts are built (peak memory decides
        // the page faults of the whole call).
        let contacts: Vec<(u32, u32)> = {
            let horizontals = &segs[..first_vertical_seg];
            let hy: Vec<u64> = horizontals.iter().map(|s| okey(s.across)).collect();
            let by_y = SampledKeys::new(&hy);
            let mut enter: Vec<(u64, u32)> = Vec::with_capacity(horizontals.len());
            let mut leave: Vec<(u64, u32)> = Vec::with_capacity(horizontals.len());
            for (h, s) in horizontals.iter().enumerate() {
                enter.push((okey(s.lo), h as u32));
                leave.push((okey(s.hi), h as u32));
            }
            enter.sort_unstable();
            leave.sort_unstable();
            let mut active = BitSet::new(horizontals.len());
            let (mut ei, mut li) = (0, 0);
            let mut contacts = Vec::with_capacity(2 * n);
            for (v, s) in segs.iter().enumerate().skip(first_vertical_seg) {
                let x = okey(s.across);
                while ei < enter.len() && enter[ei].0 <= x {
                    active.insert(enter[ei].1 as usize);
                    ei += 1;
                }
                while li < leave.len() && leave[li].0 < x {
                    active.remove(leave[li].1 as usize);
                    li += 1;
                }
                let (lo, hi) = (okey(s.lo), okey(s.hi));
                let (a, b) = (
                    by_y.partition_point(|y| y < lo),
                    by_y.partition_point(|y| y <= hi),
                );
                active.for_each_in(a, b, |h| contacts.push((h as u32, v as u32)));
            }
            contacts
        };
        // Cuts: the positions (keys) along each line of its segments' endpoints and
        // contacts, one array cut into per-line runs by a counting sort on the line (the
        // line is implied by the run, so a cut is one key), each run then sorted and
        // deduplicated (a line holds few cuts), and each cut given its vertex.
        let mut cut_start = vec![0usize; line_count + 1];
        for &l in &line_of {
            cut_start[l as usize + 1] += 2;
        }
        for &(h, v) in &contacts {
            cut_start[line_of[h as usize] as usize + 1] += 1;
            cut_start[line_of[v as usize] as usize + 1] += 1;
        }
        for l in 0..line_count {
            cut_start[l + 1] += cut_start[l];
        }
        let unkey = |k: u64| {
            if k >> 63 == 1 {
                f64::from_bits(k & !(1 << 63))
            } else {
                f64::from_bits(!k)
            }
        };
        let first_vertical = line_of
            .get(first_vertical_seg)
            .map_or(line_count, |&l| l as usize);
        let mut cuts = vec![0u64; cut_start[line_count]];
        let mut cut_vertex = vec![0u32; cut_start[line_count]];
        // Each line's fill cursor; once its run is deduplicated, the run's end.
        let mut cut_end: Vec<usize> = cut_start[..line_count].to_vec();
        let mut vertices: Vec<Point2> = Vec::with_capacity(cuts.len());
        // The vertical lines first: their endpoints and contacts, each distinct cut a
        // vertex (a point lies on at most one vertical line).
        for (s, &l) in segs.iter().zip(&line_of).skip(first_vertical_seg) {
            for key in [okey(s.lo), okey(s.hi)] {
                cuts[cut_end[l as usize]] = key;
                cut_end[l as usize] += 1;
            }
        }
        for &(h, v) in &contacts {
            let l = line_of[v as usize] as usize;
            cuts[cut_end[l]] = okey(segs[h as usize].across);
            cut_end[l] += 1;
        }
        for l in first_vertical..line_count {
            let a = cut_start[l];
            cuts[a..cut_end[l]].sort_unstable();
            let x = segs[lines[l]].across;
            let mut kept = a;
            for c in a..cut_end[l] {
                if c == a || cuts[c] != cuts[kept - 1] {
                    cuts[kept] = cuts[c];
                    cut_vertex[kept] = vertices.len() as u32;
                    vertices.push(point(1, x, unkey(cuts[c])));
                    kept += 1;
                }
            }
            cut_end[l] = kept;
        }
        // Then the horizontal lines: a cut at (x, y) is a vertex of the vertical line
        // through x exactly when it is a contact (a vertical segment's cut at y lies on
        // that segment, which then touches the horizontal one there), so contacts carry
        // their vertex over and only endpoints touching no vertical segment are new
        // points. The contacts come by vertical segment, then ascending y (the sweep
        // lists them so): each segment's vertices are found in one forward walk along
        // its line's run, reading the vertical lines' cuts front to back.
        const NO_VERTEX: u32 = u32::MAX;
        let mut walk = (u32::MAX, 0usize); // (vertical segment, position in its line)
        for &(h, v) in &contacts {
            let (sh, sv) = (&segs[h as usize], &segs[v as usize]);
            let lv = line_of[v as usize] as usize;
            let run = &cuts[cut_start[lv]..cut_end[lv]];
            if walk.0 != v {
                walk = (v, run.partition_point(|&k| k < okey(sv.lo)));
            }
            let ky = okey(sh.across);
            while walk.1 < run.len() && run[walk.1] < ky {
                walk.1 += 1;
            }
            if run.get(walk.1) != Some(&ky) {
                // (Not in ascending y after all: a search, still exact.)
                walk.1 = run.partition_point(|&k| k < ky);
            }
            debug_assert_eq!(run[walk.1], ky);
            let lh = line_of[h as usize] as usize;
            cuts[cut_end[lh]] = okey(sv.across);
            cut_vertex[cut_end[lh]] = cut_vertex[cut_start[lv] + walk.1];
            cut_end[lh] += 1;
        }
        drop(contacts);
        for (s, &l) in segs[..first_vertical_seg].iter().zip(&line_of) {
            for key in [okey(s.lo), okey(s.hi)] {
                cuts[cut_end[l as usize]] = key;
                cut_vertex[cut_end[l as usize]] = NO_VERTEX;
                cut_end[l as usize] += 1;
            }
        }
        // (Sorted by key, then vertex: a contact's vertex comes before NO_VERTEX.)
        let mut run: Vec<(u64, u32)> = Vec::new();
        for l in 0..first_vertical {
            let a = cut_start[l];
            run.clear();
            run.extend((a..cut_end[l]).map(|c| (cuts[c], cut_vertex[c])));
            run.sort_unstable();
            let y = segs[lines[l]].across;
            let mut kept = a;
            for (i, &(key, vertex)) in run.iter().enumerate() {
                if i > 0 && key == run[i - 1].0 {
                    continue;
                }
                cuts[kept] = key;
                cut_vertex[kept] = if vertex == NO_VERTEX {
                    vertices.push(point(0, y, unkey(key)));
                    vertices.len() as u32 - 1
                } else {
                    vertex
                };
                kept += 1;
            }
            cut_end[l] = kept;
        }
        drop(run);
        // The runs closed up: line l's cuts are cut_start[l]..cut_start[l + 1] again.
        let mut kept = 0;
        for l in 0..line_count {
            let (a, b) = (cut_start[l], cut_end[l]);
            cut_start[l] = kept;
            cuts.copy_within(a..b, kept);
            cut_vertex.copy_within(a..b, kept);
            kept += b - a;
        }
        cut_start[line_count] = kept;
        cuts.truncate(kept);
        cut_vertex.truncate(kept);
        drop(cut_end);
        // Pieces, line by line: between consecutive cuts, the segments covering them.
        // Each edge keeps its first source beside it; only collinear overlaps (a second
        // segment over the same piece) go to a list of further sources, so without
        // overlaps the sources need no sort and no (edge, source) list.
        let pieces_bound = cuts.len();
        let mut edges: Vec<[u32; 2]> = Vec::with_capacity(pieces_bound);
        // Each edge's first source (the sources of the arrangement when there are no
        // overlaps: made once, in place, not copied from a narrower list).
        let mut first: Vec<Source> = Vec::with_capacity(pieces_bound);
        let mut further: Vec<(u32, Source)> = Vec::new();
        // Per cut gap of the line: its edge or NONE.
        let mut first_edge: Vec<u32> = Vec::new();
        for line in 0..line_count {
            let c0 = cut_start[line];
            let along = &cuts[c0..cut_start[line + 1]];
            first_edge.clear();
            first_edge.resize(along.len().saturating_sub(1), u32::MAX);
            for s in &segs[lines[line]..lines[line + 1]] {
                let find = |v: f64| along.binary_search(&okey(v)).expect("endpoints are cuts");
                let (i0, i1) = (find(s.lo), find(s.hi));
                let src = Source {
                    segment: s.index as usize,
                    forward: s.increasing,
                };
                for g in i0..i1 {
                    if first_edge[g] == u32::MAX {
                        first_edge[g] = edges.len() as u32;
                        edges.push([cut_vertex[c0 + g], cut_vertex[c0 + g + 1]]);
                        first.push(src);
                    } else {
                        further.push((first_edge[g], src));
                    }
                }
            }
        }
        drop((
            cuts, cut_vertex, cut_start, first_edge, segs, line_of, lines,
        ));
        // The edges stay in line order (the horizontal lines by y, then the vertical ones
        // by x, each along its line) and the vertices in the order made (the vertical
        // lines' cuts, then the points on horizontal lines only): the order of the plane,
        // so the face cycles walked later touch nearby records. (Renumbered along the
        // input segments instead, the records of one small face of many overlapping
        // squares lay far apart: union of 1e5 random squares 20% slower.)
        let vertices = Vertices::Input(vertices);
        if further.is_empty() {
            return Some(Flat {
                vertices,
                edges,
                src_start: Vec::new(),
                sources: first,
            });
        }
        // Overlaps: all sources as (edge, source) pairs, sorted by segment per edge.
        let mut pairs: Vec<(u32, Source)> = Vec::with_capacity(first.len() + further.len());
        pairs.extend((0..).zip(first));
        pairs.append(&mut further);
        Some(Pieces { edges, pairs }.finish_numbered(vertices, false))
    }
}

/// The edges of `f` as `(lower point, higher point, sources relative to lower → higher)`
/// with points compared exactly, sorted: the arrangement independent of numbering.
#[cfg(test)]
pub(crate) fn canonical(f: &Flat) -> Vec<CanonicalEdge> {
    let mut out = Vec::new();
    let vertices = f.vertices.exact();
    for i in 0..f.edge_count() {
        let [u, v] = f.edges[i];
        let (pu, pv) = (&vertices[u as usize], &vertices[v as usize]);
        let flip = pu.compare_xy(pv) == std::cmp::Ordering::Greater;
        let (a, b) = if flip { (pv, pu) } else { (pu, pv) };
        let mut src: Vec<(usize, bool)> = f
            .sources_of(i)
            .iter()
            .map(|s| (s.segment, s.forward != flip))
            .collect();
        src.sort_unstable();
        out.push((ExactPointKey::of(a), ExactPointKey::of(b), src));
    }
    out.sort_by(|x, y| {
        x.0.cmp(&y.0)
            .then_with(|| x.1.cmp(&y.1))
            .then_with(|| x.2.cmp(&y.2))
    });
    out
}

/// An edge as `(lower end, higher end, (segment, runs lower → higher))`, for tests.
#[cfg(test)]
pub(crate) type CanonicalEdge = (ExactPointKey, ExactPointKey, Vec<(usize, bool)>);

/// A point key for tests: exact points compared exactly, via their nearest `f64` point
/// (correct rounding keeps distinct points of these tests apart).
#[cfg(test)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct ExactPointKey(u64, u64);

#[cfg(test)]
impl ExactPointKey {
    fn of(p: &ExactPoint) -> Self {
        let a = p.approx();
        ExactPointKey(okey(a.x), okey(a.y))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sampled_keys_search_as_the_slice_does() {
        // Sizes around the block size, keys with long runs of duplicates, every bound
        // from below the first key to above the last.
        let mut seed = 7u64;
        let mut next = || {
            seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
            seed >> 33
        };
        for n in [0, 1, 2, 63, 64, 65, 127, 128, 129, 200, 640, 1000] {
            for spread in [3, 50, 1 << 20] {
                let mut keys: Vec<u64> = (0..n).map(|_| next() % spread).collect();
                keys.sort_unstable();
                let sampled = SampledKeys::new(&keys);
                for bound in 0..=spread.min(60) + 1 {
                    let bound = if spread > 60 {
                        bound * (spread / 60)
                    } else {
                        bound
                    };
                    for strict in [true, false] {
                        let below = |k: u64| if strict { k < bound } else { k <= bound };
                        assert_eq!(
                            sampled.partition_point(below),
                            keys.partition_point(|&k| below(k)),
                            "n {n}, spread {spread}, bound {bound}, strict {strict}"
                        );
                    }
                }
            }
        }
    }
    use crate::kernel::{on_segment, segment_intersection, SegmentIntersection};
    use proptest::prelude::*;

    /// The arrangement by definition, O(n²) per vertex: vertices are the endpoints and
    /// the proper crossings; each segment is cut at the vertices on it (exact tests),
    /// pieces with the same two ends merged.
    fn oracle(segs: &[Segment2]) -> Vec<CanonicalEdge> {
        let mut verts: Vec<ExactPoint> = Vec::new();
        let add = |p: ExactPoint, verts: &mut Vec<ExactPoint>| {
            if !verts
                .iter()
                .any(|q| q.compare_xy(&p) == std::cmp::Ordering::Equal)
            {
                verts.push(p);
            }
        };
        for (i, s) in segs.iter().enumerate() {
            if s.is_degenerate() {
                continue;
            }
            add(ExactPoint::Input(s.a), &mut verts);
            add(ExactPoint::Input(s.b), &mut verts);
            for t in &segs[i + 1..] {
                if let SegmentIntersection::Crossing(c) = segment_intersection(*s, *t) {
                    add(ExactPoint::Crossing(c), &mut verts);
                }
            }
        }
        type Piece = (ExactPoint, ExactPoint, Vec<(usize, bool)>);
        let mut pieces: Vec<Piece> = Vec::new();
        for (i, s) in segs.iter().enumerate() {
            if s.is_degenerate() {
                continue;
            }
            let mut on: Vec<ExactPoint> = verts
                .iter()
                .filter(|v| on_segment(v, *s))
                .copied()
                .collect();
            on.sort_by(|p, q| p.compare_xy(q));
            // Along the sorted points the segment runs forward iff a is the smaller end.
            let forward = crate::kernel::compare_xy(s.a, s.b) == std::cmp::Ordering::Less;
            for w in on.windows(2) {
                let same = pieces.iter_mut().find(|p| {
                    p.0.compare_xy(&w[0]) == std::cmp::Ordering::Equal
                        && p.1.compare_xy(&w[1]) == std::cmp::Ordering::Equal
                });
                match same {
                    Some(p) => p.2.push((i, forward)),
                    None => pieces.push((w[0], w[1], vec![(i, forward)])),
                }
            }
        }
        let mut out: Vec<_> = pieces
            .into_iter()
            .map(|(a, b, mut s)| {
                s.sort_unstable();
                (ExactPointKey::of(&a), ExactPointKey::of(&b), s)
            })
            .collect();
        out.sort();
        out
    }

    fn seg(c: (i32, i32, i32, i32)) -> Segment2 {
        Segment2::new(
            Point2::new(c.0 as f64, c.1 as f64),
            Point2::new(c.2 as f64, c.3 as f64),
        )
    }

    /// Horizontal and vertical segments on a small integer grid (collinear overlaps,
    /// duplicates, shared endpoints, T-junctions, zero-length segments).
    fn grid_segments() -> impl Strategy<Value = Vec<Segment2>> {
        prop::collection::vec((0..8i32, 0..8i32, 0..6i32, any::<bool>()), 0..24).prop_map(|v| {
            v.into_iter()
                .map(|(x, y, len, vertical)| {
                    if vertical {
                        seg((x, y, x, y + len))
                    } else {
                        seg((x + len, y, x, y))
                    }
                })
                .collect()
        })
    }

    /// [`Flat::noded`] by each candidate path; all must give the same arrangement,
    /// numbered alike.
    fn noded_all(segs: &[Segment2]) -> Result<Flat, TestCaseError> {
        use crate::dcel::noding::Candidates;
        let auto = Flat::noded(segs).unwrap();
        for how in [Candidates::Sweep, Candidates::Strips, Candidates::Grid] {
            prop_assert_eq!(&Flat::noded_by(segs, how).unwrap(), &auto, "{:?}", how);
        }
        // Summed up straight from the pieces as from the sorted sources, for inputs split
        // anywhere into A and B.
        for na in [0, segs.len() / 3, segs.len()] {
            let summed = Flat::noded_summed(segs, na).unwrap();
            prop_assert_eq!(&summed, &auto.clone().summed(na), "na {}", na);
        }
        Ok(auto)
    }

    fn check(segs: &[Segment2], f: &Flat) -> Result<(), TestCaseError> {
        // Sources ascending, every vertex used, edges non-degenerate.
        for i in 0..f.edge_count() {
            let s = f.sources_of(i);
            prop_assert!(!s.is_empty());
            prop_assert!(s.windows(2).all(|w| w[0].segment < w[1].segment));
            prop_assert!(f.edges[i][0] != f.edges[i][1]);
        }
        prop_assert_eq!(canonical(f), oracle(segs));
        Ok(())
    }

    #[test]
    fn a_square_grid_is_cut_at_every_contact() {
        // Two overlapping squares: 8 crossing-free vertices + 2 contacts.
        let sq = |x: i32, y: i32| {
            vec![
                seg((x, y, x + 2, y)),
                seg((x + 2, y, x + 2, y + 2)),
                seg((x + 2, y + 2, x, y + 2)),
                seg((x, y + 2, x, y)),
            ]
        };
        let mut segs = sq(0, 0);
        segs.extend(sq(1, 1));
        let f = Flat::axis_parallel(&segs).unwrap();
        assert_eq!((f.vertices.len(), f.edge_count()), (10, 12));
        assert_eq!(canonical(&f), oracle(&segs));
        assert!(Flat::axis_parallel(&[seg((0, 0, 1, 1))]).is_none());
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]

        #[test]
        fn axis_parallel_path_is_the_general_arrangement(segs in grid_segments()) {
            let fast = Flat::axis_parallel(&segs).expect("all axis-parallel");
            check(&segs, &fast)?;
            prop_assert_eq!(canonical(&fast), canonical(&Flat::general(&segs).unwrap()));
        }

        /// Rings of axis-parallel squares on a small grid (shared edges, duplicate
        /// squares, touching corners, T-junctions), zeros sometimes `-0.0`, in many lines:
        /// the contacts' vertex walk gives the general path's arrangement.
        #[test]
        fn axis_parallel_path_agrees_on_square_rings(
            v in prop::collection::vec((-3..5i32, -3..5i32, 1..4i32, any::<bool>()), 0..20)
        ) {
            let c = |k: i32, neg: bool| if k == 0 && neg { -0.0 } else { k as f64 };
            let mut segs = Vec::new();
            for (x, y, w, neg) in v {
                let p = [
                    Point2::new(c(x, neg), c(y, !neg)),
                    Point2::new(c(x + w, neg), c(y, neg)),
                    Point2::new(c(x + w, !neg), c(y + w, neg)),
                    Point2::new(c(x, !neg), c(y + w, !neg)),
                ];
                for i in 0..4 {
                    segs.push(Segment2::new(p[i], p[(i + 1) % 4]));
                }
            }
            let fast = Flat::axis_parallel(&segs).expect("all axis-parallel");
            check(&segs, &fast)?;
            prop_assert_eq!(canonical(&fast), canonical(&Flat::general(&segs).unwrap()));
        }

        /// Squares at random float positions (lines almost never shared, so edges carry
        /// one source each: the path without the (edge, source) list), now and then a
        /// duplicate square (overlaps: the other path), at tiny to huge magnitudes: the
        /// general path's arrangement, vertices kept as plain input points.
        #[test]
        fn axis_parallel_path_agrees_on_float_squares(
            v in prop::collection::vec((-1.0..1.0f64, -1.0..1.0f64, 0.01..0.5f64), 1..14),
            dup in any::<bool>(),
            scale in prop::sample::select(vec![1.0, 1e-300, 1e300, 3.0e-10]),
        ) {
            let mut segs = Vec::new();
            let mut square = |x: f64, y: f64, w: f64| {
                let p = [
                    Point2::new(x * scale, y * scale),
                    Point2::new((x + w) * scale, y * scale),
                    Point2::new((x + w) * scale, (y + w) * scale),
                    Point2::new(x * scale, (y + w) * scale),
                ];
                for i in 0..4 {
                    segs.push(Segment2::new(p[i], p[(i + 1) % 4]));
                }
            };
            for &(x, y, w) in &v {
                square(x, y, w);
            }
            if dup {
                square(v[0].0, v[0].1, v[0].2);
            }
            let fast = Flat::axis_parallel(&segs).expect("all axis-parallel");
            prop_assert!(matches!(fast.vertices, Vertices::Input(_)));
            check(&segs, &fast)?;
            prop_assert_eq!(canonical(&fast), canonical(&Flat::general(&segs).unwrap()));
        }

        /// Axis-parallel segments on a small grid whose zero coordinates are sometimes
        /// -0.0 (either end, either axis): the axis path agrees with the general
        /// arrangement, and so do the summed sources and winding deltas of every edge.
        #[test]
        fn axis_segments_with_negative_zeros_agree_with_the_general_path(
            v in prop::collection::vec((-3..4i32, -3..4i32, -3..4i32, any::<bool>(), 0..16u8), 0..30),
            na in 0..30usize,
        ) {
            let c = |k: i32, neg: bool| if k == 0 && neg { -0.0 } else { k as f64 };
            let segs: Vec<Segment2> = v.iter().map(|&(x, y, len, vertical, n)| {
                let (a, b) = if vertical {
                    (Point2::new(c(x, n & 1 != 0), c(y, n & 2 != 0)), Point2::new(c(x, n & 4 != 0), c(y + len, n & 8 != 0)))
                } else {
                    (Point2::new(c(x, n & 1 != 0), c(y, n & 2 != 0)), Point2::new(c(x + len, n & 4 != 0), c(y, n & 8 != 0)))
                };
                Segment2::new(a, b)
            }).collect();
            let fast = Flat::axis_parallel(&segs).expect("all axis-parallel");
            check(&segs, &fast)?;
            let general = Flat::general(&segs).unwrap();
            prop_assert_eq!(canonical(&fast), canonical(&general));
            // Summed: the same single source and delta per edge, edges keyed by their ends
            // in exact order (a delta read against the edge's direction is negated).
            let na = na.min(segs.len());
            let (fs, fd) = Flat::of_segments_summed(&segs, na).unwrap();
            let (gs, gd) = general.summed(na);
            let by_ends = |f: &Flat, d: &[(i32, i32)]| {
                let vx = f.vertices.exact();
                let mut out: Vec<_> = (0..f.edge_count()).map(|i| {
                    let [u, w] = f.edges[i];
                    let (pu, pw) = (ExactPointKey::of(&vx[u as usize]), ExactPointKey::of(&vx[w as usize]));
                    let s = f.sources_of(i);
                    prop_assert_eq!(s.len(), 1);
                    if pu < pw { Ok((pu, pw, s[0].segment, s[0].forward, d[i])) }
                    else { Ok((pw, pu, s[0].segment, !s[0].forward, (-d[i].0, -d[i].1))) }
                }).collect::<Result<Vec<_>, TestCaseError>>()?;
                out.sort();
                Ok::<_, TestCaseError>(out)
            };
            prop_assert_eq!(by_ends(&fs, &fd)?, by_ends(&gs, &gd)?);
        }

        /// The bit set lists exactly the members of a range (a sorted set as oracle),
        /// across word and summary boundaries.
        #[test]
        fn bit_set_lists_the_members_of_a_range(
            ops in prop::collection::vec((0..9000usize, 0..300usize, any::<bool>()), 0..60),
            a in 0..9100usize, len in 0..9100usize,
        ) {
            let bound = 9000;
            let mut set = BitSet::new(bound);
            let mut oracle = std::collections::BTreeSet::new();
            // Runs of inserts and removes: dense and empty words and summary words.
            for (start, count, add) in ops {
                for i in start..(start + count).min(bound) {
                    if add {
                        set.insert(i);
                        oracle.insert(i);
                    } else {
                        set.remove(i);
                        oracle.remove(&i);
                    }
                }
            }
            let (a, b) = (a.min(bound), (a + len).min(bound));
            let mut got = Vec::new();
            set.for_each_in(a, b, |i| got.push(i));
            let want: Vec<usize> = oracle.range(a..b.max(a)).copied().collect();
            prop_assert_eq!(got, want);
        }


        #[test]
        fn general_path_is_the_arrangement_on_grids(
            v in prop::collection::vec((0..6i32, 0..6i32, 0..6i32, 0..6i32), 0..16)
        ) {
            // Small integer coordinates: collinear overlaps, duplicates, shared and
            // repeated vertices, crossings at endpoints.
            let segs: Vec<Segment2> = v.into_iter().map(seg).collect();
            let general = Flat::general(&segs).unwrap();
            check(&segs, &general)?;
            let noded = noded_all(&segs)?;
            check(&segs, &noded)?;
            prop_assert_eq!(canonical(&noded), canonical(&general));
        }

        #[test]
        fn noded_path_is_the_arrangement_of_degenerate_rings(
            rings in prop::collection::vec(prop::collection::vec((0..5i32, 0..5i32), 3..7), 1..4),
            spokes in prop::collection::vec((0..5i32, 0..5i32), 0..4),
        ) {
            // Closed rings on a small grid (shared endpoints everywhere, self-touching,
            // repeated edges, collinear overlaps) plus segments through the centre
            // (2, 2) from opposite grid points: many segments through one crossing.
            let mut segs: Vec<Segment2> = Vec::new();
            for r in &rings {
                for k in 0..r.len() {
                    let (p, q) = (r[k], r[(k + 1) % r.len()]);
                    segs.push(seg((p.0, p.1, q.0, q.1)));
                }
            }
            for &(x, y) in &spokes {
                segs.push(seg((x, y, 4 - x, 4 - y)));
            }
            let noded = noded_all(&segs)?;
            check(&segs, &noded)?;
            prop_assert_eq!(canonical(&noded), canonical(&Flat::general(&segs).unwrap()));
        }

        #[test]
        fn noded_path_agrees_on_near_degenerate_crossings(
            v in prop::collection::vec((-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64), 1..10),
            scale in prop::sample::select(vec![1.0, 1e-300, 1e300, 3.0e-10]),
        ) {
            // Random segments, each also copied through the midpoint of the first with
            // an ulp-sized nudge: crossings whose rounded points tie or nearly tie.
            let p = |x: f64, y: f64| Point2::new(x * scale, y * scale);
            let mut segs: Vec<Segment2> =
                v.iter().map(|c| Segment2::new(p(c.0, c.1), p(c.2, c.3))).collect();
            let m = Point2::new((segs[0].a.x + segs[0].b.x) / 2.0, (segs[0].a.y + segs[0].b.y) / 2.0);
            for c in &v {
                let d = (c.2 - c.0, c.3 - c.1);
                let q = Point2::new(m.x + d.0 * scale, m.y + d.1 * scale);
                let r = Point2::new(m.x - d.0 * scale, f64::from_bits((m.y - d.1 * scale).to_bits() ^ 1));
                segs.push(Segment2::new(q, r));
            }
            let noded = noded_all(&segs)?;
            check(&segs, &noded)?;
            prop_assert_eq!(canonical(&noded), canonical(&Flat::general(&segs).unwrap()));
        }

        #[test]
        fn general_path_is_the_arrangement_on_random_input(
            v in prop::collection::vec(
                (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64), 0..14)
        ) {
            let mut segs: Vec<Segment2> = v
                .into_iter()
                .map(|c| Segment2::new(Point2::new(c.0, c.1), Point2::new(c.2, c.3)))
                .collect();
            // A duplicate and a reversed copy: overlaps to merge.
            if let Some(&s) = segs.first() {
                segs.push(s);
                segs.push(Segment2::new(s.b, s.a));
            }
            check(&segs, &Flat::general(&segs).unwrap())?;
            check(&segs, &noded_all(&segs)?)?;
        }
    }
}
