//! Counting without materialising: the numbers of intersection points, overlaps and
//! meeting pairs that [`super::find_intersections`] would report, exactly, without
//! building the points, their segment lists or their rounded coordinates.
//!
//! On the pairwise path (the default for most inputs) each meeting pair gives one record
//! per point (two for an overlapping pair) holding a certified interval around the exact
//! point's y (plain `f64` arithmetic with a rigorous error bound: the crossing box of the
//! sweep's event points; a single value for an input point). Records are sorted by the
//! intervals' lower ends; a run of records whose intervals chain together is a *cluster*, and
//! only inside a cluster can two records be the same point. Clusters of one record are
//! one point; larger clusters are sorted exactly (the sweep's exact event order) and
//! their distinct points counted. For proper crossings at distinct points (the common
//! case) nothing is rounded and nothing exact runs. When the candidate pairs come from
//! the axis sweep (long segments, up to quadratically many points) and no pair
//! overlaps, there is no global sort: each segment's records are grouped along it in a
//! small buffer and the points counted as the groups of one record
//! ([`count_along_segments`], which has the proof); with an overlap the records are
//! sorted as above. On the sweep path the sweep's output is counted as it comes.
//!
//! O(n + m + K log K) time for m candidate pairs and K meeting pairs on the pairwise
//! path, O(n + K) space (24 bytes per (point, pair)); O(n) space per segment grouping.

use super::bucket;
use super::order::{crossing_interval, crossing_y_interval, EventPoint, Oriented};
use super::pairwise::{self, Grid, Pairs};
use super::sweep::{self, Flow, Sink};
use super::{brute_force, IntersectAlgorithm, IntersectionPoint, Overlap};
use crate::kernel::{
    quick_crossing_static, segment_intersection, Crossing, ExactPoint, Point2, Segment2,
    SegmentIntersection,
};
use crate::Result;

/// How many intersection points, overlaps and meeting pairs there are: the sizes of what
/// [`super::find_intersections`] reports.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct IntersectionCount {
    /// The number of intersection points (`Intersections::points.len()`).
    pub points: usize,
    /// The number of maximal overlap pieces (`Intersections::overlaps.len()`).
    pub overlaps: usize,
    /// The number of distinct pairs of segments that meet
    /// ([`super::Intersections::pair_count`]).
    pub pairs: usize,
}

/// One (point, pair) record: a y-interval `[lo, hi]` that surely contains the exact
/// point's y, and what the point is: the crossing of segments `i` and `j`, or an input
/// point, an endpoint of segment `i`.
#[derive(Clone, Copy)]
struct Rec {
    lo: f64,
    hi: f64,
    /// `i << 32 | CROSSING | j` for a crossing, `i << 32 | end` (0: `a`, 1: `b`) for an
    /// input point.
    pair: u64,
}

const CROSSING: u64 = 1 << 31;

impl Rec {
    fn i(&self) -> usize {
        (self.pair >> 32) as usize
    }

    fn j(&self) -> usize {
        (self.pair & (CROSSING - 1)) as usize
    }

    /// The exact point of the record, with its certified box.
    fn event(&self, segments: &[Segment2]) -> EventPoint {
        let s = segments[self.i()];
        if self.pair & CROSSING != 0 {
            let t = segments[self.j()];
            EventPoint::new(ExactPoint::Crossing(Crossing { s, t }))
        } else if self.pair & 1 != 0 {
            EventPoint::input(s.b)
        } else {
            EventPoint::input(s.a)
        }
    }
}

/// The records and overlapping pairs one scan produced.
#[derive(Default)]
struct Found {
    recs: Vec<Rec>,
    overlapping: Vec<(usize, usize)>,
}

impl Found {
    /// A record for the input point `p`, named as an endpoint of segment `i` or `j`.
    fn input(&mut self, segments: &[Segment2], p: Point2, i: usize, j: usize) {
        self.recs.push(Rec {
            lo: p.y,
            hi: p.y,
            pair: input_pair(segments, p, i, j),
        });
    }

    /// A record for the proper crossing of segments `i < j`.
    #[inline(always)]
    fn crossing(&mut self, c: &Crossing, i: usize, j: usize) {
        let (lo, hi) = crossing_y_interval(c);
        self.recs.push(Rec {
            lo,
            hi,
            pair: ((i as u64) << 32) | CROSSING | j as u64,
        });
    }

    /// Test segments `i < j` (`bound`: a static orientation bound for the input, or
    /// infinity) and record how they meet.
    #[inline]
    fn test(&mut self, segments: &[Segment2], i: usize, j: usize, bound: f64) {
        let (s, t) = (segments[i], segments[j]);
        // Most pairs are decided by the inlined filters; the rest by the exact test.
        match quick_crossing_static(s, t, bound) {
            Some(false) => return,
            Some(true) => return self.crossing(&Crossing { s, t }, i, j),
            None => {}
        }
        match segment_intersection(s, t) {
            SegmentIntersection::None => {}
            SegmentIntersection::Endpoint(q) => self.input(segments, q, i, j),
            SegmentIntersection::Crossing(c) => self.crossing(&c, i, j),
            SegmentIntersection::Overlap(a, b) => {
                self.input(segments, a, i, j);
                self.input(segments, b, i, j);
                self.overlapping.push((i, j));
            }
        }
    }

    /// All parts in one, the records sorted by their lower ends straight from the parts
    /// ([`bucket::sort_parts`]), without concatenating them first.
    fn sorted(parts: Vec<Found>) -> Found {
        let overlapping = parts
            .iter()
            .flat_map(|p| p.overlapping.iter().copied())
            .collect();
        let recs = parts.into_iter().map(|p| p.recs).collect();
        Found {
            recs: bucket::sort_parts(recs, |r| r.lo, lower_end_cmp),
            overlapping,
        }
    }
}

/// The order of records by their lower ends (`total_cmp`: an unbounded `-inf` first).
fn lower_end_cmp(a: &Rec, b: &Rec) -> std::cmp::Ordering {
    a.lo.total_cmp(&b.lo)
}

/// Sort records by their lower ends (`total_cmp`: an unbounded `-inf` comes first), by
/// buckets: O(K) for spread-out points.
fn sort_by_lower_end(recs: &mut [Rec]) {
    bucket::sort_by_key_then(recs, |r| r.lo, lower_end_cmp);
}

/// The number of distinct exact points among the records, sorted by their lower ends
/// ([`sort_by_lower_end`]).
fn distinct_points(segments: &[Segment2], recs: &[Rec]) -> usize {
    clusters(recs)
        .map(|cluster| {
            if cluster.len() == 1 {
                1
            } else {
                let events = sorted_events(segments, cluster);
                1 + events.windows(2).filter(|w| w[0] != w[1]).count()
            }
        })
        .sum()
}

/// The clusters of records sorted by their lower ends ([`sort_by_lower_end`]): maximal
/// runs in which every record's interval meets the union of those before it, so that
/// records of one exact point always share a cluster (total_cmp orders -0.0 before
/// 0.0: harmless, the running top still chains them).
fn clusters(recs: &[Rec]) -> impl Iterator<Item = &[Rec]> {
    let mut k = 0;
    std::iter::from_fn(move || {
        if k == recs.len() {
            return None;
        }
        let mut top = recs[k].hi;
        let mut end = k + 1;
        while end < recs.len() && recs[end].lo <= top {
            top = top.max(recs[end].hi);
            end += 1;
        }
        let cluster = &recs[k..end];
        k = end;
        Some(cluster)
    })
}

/// The exact points of a cluster's records, sorted (equal points adjacent).
fn sorted_events(segments: &[Segment2], cluster: &[Rec]) -> Vec<EventPoint> {
    let mut events: Vec<EventPoint> = cluster.iter().map(|r| r.event(segments)).collect();
    events.sort_unstable();
    events
}

/// The count from the pairwise scan's records.
fn count_found(segments: &[Segment2], found: Found) -> IntersectionCount {
    let pairs = found.recs.len() - found.overlapping.len();
    let points = distinct_points(segments, &found.recs);
    let segs: Vec<Oriented> = segments.iter().map(|&s| Oriented::of(s)).collect();
    let overlaps = brute_force::overlap_pieces(&segs, &found.overlapping).len();
    IntersectionCount {
        points,
        overlaps,
        pairs,
    }
}

/// The pairwise scan over a bucketed input.
fn count_on(segments: &[Segment2], pairs: &Pairs) -> IntersectionCount {
    let bound = pairs.orient_bound();
    let scan = |k: usize, found: &mut Found| {
        pairs.scan_from(k, |i, j| found.test(segments, i, j, bound));
    };
    let candidates = pairs.candidates();
    let found = if candidates < pairwise::PARALLEL_SCAN_FROM {
        let mut found = Found::default();
        found.recs.reserve(pairwise::reserve_for(candidates));
        (0..pairs.units()).for_each(|k| scan(k, &mut found));
        sort_by_lower_end(&mut found.recs);
        found
    } else {
        let make = |visits| Found {
            recs: Vec::with_capacity(pairwise::reserve_for(visits)),
            overlapping: Vec::new(),
        };
        let parts = pairs.scan_parts(make, scan);
        Found::sorted(parts)
    };
    count_found(segments, found)
}

/// What the per-segment count of one chunk of units found.
struct AlongSegments {
    /// Groups of exactly one record (see [`count_along_segments`]).
    points: usize,
    /// Records (one per meeting pair: no overlaps).
    records: usize,
    /// Whether some pair overlaps (the method then does not apply).
    overlap: bool,
    /// The current unit's records (reused).
    local: Vec<Rec>,
    /// Scratch for sorting them (reused).
    sorted: Vec<Rec>,
    counts: Vec<u32>,
}

/// [`count_along_segments`]'s sink for the batched filter of the axis sweep
/// ([`pairwise::SweepLanes::scan_batched`]): the crossings it certifies recorded
/// straight away, the pairs it leaves open tested by [`AlongSegments::test`].
struct AlongSink<'a> {
    acc: &'a mut AlongSegments,
    segments: &'a [Segment2],
    /// The unit's segment.
    a: usize,
    bound: f64,
    axis: usize,
}

impl pairwise::BatchSink for AlongSink<'_> {
    #[inline(always)]
    fn cross(&mut self, b: usize) {
        let (i, j) = (self.a.min(b), self.a.max(b));
        let (s, t) = (self.segments[i], self.segments[j]);
        self.acc
            .local
            .push(crossing_rec(&Crossing { s, t }, i, j, self.axis));
    }

    #[inline(always)]
    fn open(&mut self, b: usize) {
        let (i, j) = (self.a.min(b), self.a.max(b));
        self.acc.test(self.segments, i, j, self.bound, self.axis);
    }
}

/// The record of the proper crossing `c` of segments `i < j`, by coordinate `axis`.
#[inline]
fn crossing_rec(c: &Crossing, i: usize, j: usize, axis: usize) -> Rec {
    let (lo, hi) = crossing_interval(c, axis);
    Rec {
        lo,
        hi,
        pair: ((i as u64) << 32) | CROSSING | j as u64,
    }
}

impl AlongSegments {
    /// Record how segments `i < j` meet, by the coordinate `axis` of the point (along
    /// the unit's segment, on which every point of the unit lies).
    #[inline]
    fn test(&mut self, segments: &[Segment2], i: usize, j: usize, bound: f64, axis: usize) {
        let (s, t) = (segments[i], segments[j]);
        let crossing = |c: &Crossing| crossing_rec(c, i, j, axis);
        match quick_crossing_static(s, t, bound) {
            Some(false) => return,
            Some(true) => return self.local.push(crossing(&Crossing { s, t })),
            None => {}
        }
        match segment_intersection(s, t) {
            SegmentIntersection::None => {}
            SegmentIntersection::Endpoint(q) => {
                let v = if axis == 0 { q.x } else { q.y };
                let pair = input_pair(segments, q, i, j);
                self.local.push(Rec { lo: v, hi: v, pair });
            }
            SegmentIntersection::Crossing(c) => self.local.push(crossing(&c)),
            SegmentIntersection::Overlap(..) => self.overlap = true,
        }
    }

    /// The groups of exactly one record among the unit's records (all on one segment).
    fn single_groups(&mut self, segments: &[Segment2]) -> usize {
        sort_local(&self.local, &mut self.sorted, &mut self.counts);
        clusters(&self.sorted)
            .map(|cluster| {
                if cluster.len() == 1 {
                    return 1;
                }
                // Runs of equal points of length one.
                let events = sorted_events(segments, cluster);
                let mut run = 1;
                let mut n = 0;
                for w in 1..=events.len() {
                    if w < events.len() && events[w] == events[w - 1] {
                        run += 1;
                    } else {
                        n += usize::from(run == 1);
                        run = 1;
                    }
                }
                n
            })
            .sum()
    }
}

/// `recs` sorted by their lower ends into `out`: a counting sort over `recs.len()`
/// buckets of the lower ends' range (a monotone map, so buckets come in order), then
/// each bucket sorted by [`lower_end_cmp`]. O(m) for spread-out points on a segment,
/// with buffers that are reused (no allocation per unit).
fn sort_local(recs: &[Rec], out: &mut Vec<Rec>, counts: &mut Vec<u32>) {
    out.clear();
    let m = recs.len();
    if m < 32 {
        out.extend_from_slice(recs);
        out.sort_unstable_by(lower_end_cmp);
        return;
    }
    let (lo, hi) = recs
        .iter()
        .filter(|r| r.lo.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), r| {
            (a.min(r.lo), b.max(r.lo))
        });
    let scale = if hi > lo { m as f64 / (hi - lo) } else { 0.0 };
    // Monotone in `lo` (`as usize` saturates; -inf and NaN from an infinite scale go
    // to bucket 0).
    let bucket = |r: &Rec| (((r.lo - lo) * scale) as usize).min(m - 1);
    counts.clear();
    counts.resize(m + 1, 0);
    for r in recs {
        counts[bucket(r) + 1] += 1;
    }
    for b in 0..m {
        counts[b + 1] += counts[b];
    }
    out.resize(m, recs[0]);
    for r in recs {
        let b = bucket(r);
        out[counts[b] as usize] = *r;
        counts[b] += 1;
    }
    // counts[b] is now where bucket b ends.
    let mut start = 0;
    for &end in counts[..m].iter() {
        let end = end as usize;
        if end - start > 1 {
            out[start..end].sort_unstable_by(lower_end_cmp);
        }
        start = end;
    }
}

/// The pair field of a record for the input point `p`, named as an endpoint of segment
/// `i` or `j` (it is one of their four endpoints).
fn input_pair(segments: &[Segment2], p: Point2, i: usize, j: usize) -> u64 {
    let (s, t) = (segments[i], segments[j]);
    let (owner, end) = if p == s.a {
        (i, 0)
    } else if p == s.b {
        (i, 1)
    } else if p == t.a {
        (j, 0)
    } else {
        (j, 1)
    };
    ((owner as u64) << 32) | end
}

/// Counting on the axis sweep's pairs without sorting all records: each unit's records
/// lie on its segment and are grouped there, in a small buffer that stays in cache
/// (the global sort of the K records was memory-bound: 139 ns per point at 25 million).
/// `None` when some pair overlaps: then the count below does not apply.
///
/// Why it counts every point once: order the segments as the sweep's units are, and
/// let a point p lie on the segments `s_0 < s_1 < ... < s_k` (k ≥ 1). Without overlaps,
/// every two of them meet at p only, so each pair `(s_a, s_b)`, `a < b`, gives one
/// record at p, found from the unit of `s_a`: at p the unit of `s_a` holds a group of
/// `k - a` records. Exactly one of those groups (that of `s_(k-1)`) has one record, so
/// the points are the groups of one record. Only inside a cluster of overlapping
/// intervals along the segment can two records be the same point: those are sorted
/// exactly.
fn count_along_segments(segments: &[Segment2], pairs: &Pairs) -> Option<IntersectionCount> {
    let bound = pairs.orient_bound();
    // The batched filter of the axis sweep (this method runs on the axis sweep only).
    let lanes = pairs.sweep_lanes(segments);
    let extent = |s: &Segment2| ((s.b.x - s.a.x).abs(), (s.b.y - s.a.y).abs());
    let scan = |k: usize, acc: &mut AlongSegments| {
        let Some(a) = pairs.unit_segment(k) else {
            acc.overlap = true;
            return;
        };
        if acc.overlap {
            return;
        }
        // Along the segment's longer extent, where its points spread the most (a
        // vertical segment's points all have one x).
        let (dx, dy) = extent(&segments[a]);
        let axis = usize::from(dy > dx);
        acc.local.clear();
        match &lanes {
            Some(lanes) => {
                let mut sink = AlongSink {
                    acc: &mut *acc,
                    segments,
                    a,
                    bound,
                    axis,
                };
                lanes.scan_batched_widest(k, bound, &mut sink);
            }
            None => pairs.scan_from(k, |i, j| acc.test(segments, i, j, bound, axis)),
        }
        acc.records += acc.local.len();
        acc.points += acc.single_groups(segments);
    };
    let make = |_| AlongSegments {
        points: 0,
        records: 0,
        overlap: false,
        local: Vec::new(),
        sorted: Vec::new(),
        counts: Vec::new(),
    };
    let parts = if pairs.candidates() < pairwise::PARALLEL_SCAN_FROM {
        let mut acc = make(0);
        (0..pairs.units()).for_each(|k| scan(k, &mut acc));
        vec![acc]
    } else {
        pairs.scan_parts(make, scan)
    };
    if parts.iter().any(|p| p.overlap) {
        return None;
    }
    Some(IntersectionCount {
        points: parts.iter().map(|p| p.points).sum(),
        overlaps: 0,
        pairs: parts.iter().map(|p| p.records).sum(),
    })
}

/// The pairwise count: per segment on the axis sweep when no pair overlaps, else from
/// all records sorted.
fn count_pairs(segments: &[Segment2], pairs: &Pairs) -> IntersectionCount {
    if pairs.is_sweep() {
        if let Some(count) = count_along_segments(segments, pairs) {
            return count;
        }
    }
    count_on(segments, pairs)
}

/// Counts what the sweep reports, as it comes.
#[derive(Default)]
struct Tally {
    points: usize,
    overlaps: usize,
    pairs: Vec<(u32, u32)>,
}

impl Sink for Tally {
    fn point(&mut self, point: IntersectionPoint) -> Flow {
        self.points += 1;
        let s = point.segments();
        for (k, &i) in s.iter().enumerate() {
            self.pairs
                .extend(s[k + 1..].iter().map(|&j| (i as u32, j as u32)));
        }
        Flow::Continue
    }
    fn overlap(&mut self, _: Overlap) -> Flow {
        self.overlaps += 1;
        Flow::Continue
    }
}

fn count_by_sweep(segments: &[Segment2]) -> Result<IntersectionCount> {
    let mut tally = Tally::default();
    sweep::sweep(segments, &mut tally)?;
    // A pair meets at one point, or at both ends of an overlap: dedup.
    tally.pairs.sort_unstable();
    tally.pairs.dedup();
    Ok(IntersectionCount {
        points: tally.points,
        overlaps: tally.overlaps,
        pairs: tally.pairs.len(),
    })
}

/// The numbers of intersection points, overlaps and meeting pairs
/// [`super::find_intersections`] would report, exactly, without building them (no
/// rounded coordinates, no segment lists): what `compgeom intersect --count-only`
/// prints. Same method choice as [`super::find_intersections`].
///
/// Errors: a non-finite coordinate (naming the segment).
///
/// ```
/// use compgeom::intersect::{count_intersections, IntersectionCount};
/// use compgeom::Segment2;
/// let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
/// // Three segments through (1, 1) and a fourth overlapping the first.
/// let segs = [
///     s((0.0, 0.0), (2.0, 2.0)),
///     s((0.0, 2.0), (2.0, 0.0)),
///     s((1.0, 0.0), (1.0, 3.0)),
///     s((1.5, 1.5), (3.0, 3.0)),
/// ];
/// let count = count_intersections(&segs).unwrap();
/// assert_eq!(count, IntersectionCount { points: 3, overlaps: 1, pairs: 4 });
/// ```
pub fn count_intersections(segments: &[Segment2]) -> Result<IntersectionCount> {
    count_intersections_with(segments, IntersectAlgorithm::Default)
}

/// [`count_intersections`] with a chosen method; every method gives the same count.
pub fn count_intersections_with(
    segments: &[Segment2],
    algorithm: IntersectAlgorithm,
) -> Result<IntersectionCount> {
    sweep::check_finite(segments)?;
    brute_force::check_count(segments)?;
    match algorithm {
        IntersectAlgorithm::Sweep => count_by_sweep(segments),
        IntersectAlgorithm::Pairwise => Ok(count_pairs(segments, &Pairs::new(Grid::new(segments)))),
        IntersectAlgorithm::Default => match pairwise::prefer_pairs(segments) {
            Some(pairs) => Ok(count_pairs(segments, &pairs)),
            None => count_by_sweep(segments),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn seg(a: (f64, f64), b: (f64, f64)) -> Segment2 {
        Segment2::new(Point2::new(a.0, a.1), Point2::new(b.0, b.1))
    }

    /// The oracle's numbers.
    fn expected(segs: &[Segment2]) -> IntersectionCount {
        let want = brute_force::brute_force_intersections(segs).unwrap();
        IntersectionCount {
            points: want.points.len(),
            overlaps: want.overlaps.len(),
            pairs: want.pair_count(),
        }
    }

    /// The per-segment count (forced onto the axis sweep) agrees with the oracle, or
    /// declines exactly when some pair overlaps; the sorted count agrees too.
    fn check(segs: &[Segment2]) {
        let want = expected(segs);
        let pairs = Pairs::sweep_for_tests(segs);
        match count_along_segments(segs, &pairs) {
            Some(got) => assert_eq!(got, want, "{segs:?}"),
            None => {
                let meets = |i: usize, j: usize| {
                    matches!(
                        segment_intersection(segs[i], segs[j]),
                        SegmentIntersection::Overlap(..)
                    )
                };
                let any = (0..segs.len()).any(|i| (i + 1..segs.len()).any(|j| meets(i, j)));
                assert!(any, "declined without an overlap: {segs:?}");
            }
        }
        assert_eq!(count_on(segs, &pairs), want, "{segs:?}");
    }

    fn grid_segments(k: i32, n: usize) -> impl Strategy<Value = Vec<Segment2>> {
        prop::collection::vec((0..=k, 0..=k, 0..=k, 0..=k), 0..n).prop_map(|v| {
            v.into_iter()
                .map(|(a, b, c, d)| seg((a as f64, b as f64), (c as f64, d as f64)))
                .collect()
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(600))]

        /// Integer grids: shared endpoints, T-junctions, many segments through one
        /// point, zero-length, horizontal and vertical segments, overlaps (declined).
        #[test]
        fn along_segments_matches_the_oracle_on_grids(segs in grid_segments(4, 24)) {
            check(&segs);
        }

        /// Lines through one point that is not an `f64` point (scaled by 1/3), and long
        /// random segments across a square: clusters of crossings resolved exactly.
        #[test]
        fn along_segments_matches_the_oracle_on_concurrent_and_long_input(
            segs in grid_segments(9, 14),
            long in prop::collection::vec((0.0..1.0f64, 0.0..1.0f64, 0..3u8), 0..30),
        ) {
            let third: Vec<Segment2> = segs
                .iter()
                .map(|t| seg((t.a.x / 3.0, t.a.y / 3.0), (t.b.x / 3.0, t.b.y / 3.0)))
                .collect();
            check(&third);
            let long: Vec<Segment2> = long
                .iter()
                .map(|&(a, b, side)| match side {
                    0 => seg((0.0, a), (1.0, b)),
                    1 => seg((a, 0.0), (b, 1.0)),
                    _ => seg((0.0, a), (b, 1.0)),
                })
                .collect();
            check(&long);
        }
    }

    proptest! {
        /// The local sort orders lower ends as a plain sort does, with repeated keys,
        /// -inf (no usable box), -0.0 and +0.0, and sizes around its cut-over.
        #[test]
        fn the_local_sort_is_a_sort(keys in prop::collection::vec(0..12u8, 0..200)) {
            let recs: Vec<Rec> = keys
                .iter()
                .enumerate()
                .map(|(k, &v)| {
                    let lo = match v {
                        0 => f64::NEG_INFINITY,
                        1 => -0.0,
                        2 => 0.0,
                        v => (v as f64).powi(5) * 1e-3,
                    };
                    Rec { lo, hi: f64::INFINITY, pair: k as u64 }
                })
                .collect();
            let mut want: Vec<f64> = recs.iter().map(|r| r.lo).collect();
            want.sort_unstable_by(f64::total_cmp);
            let (mut out, mut counts) = (Vec::new(), Vec::new());
            sort_local(&recs, &mut out, &mut counts);
            let got: Vec<f64> = out.iter().map(|r| r.lo).collect();
            prop_assert_eq!(got.len(), want.len());
            prop_assert!(got.iter().zip(&want).all(|(a, b)| a.total_cmp(b).is_eq()));
            let mut ids: Vec<u64> = out.iter().map(|r| r.pair).collect();
            ids.sort_unstable();
            prop_assert_eq!(ids, (0..recs.len() as u64).collect::<Vec<_>>());
        }
    }

    #[test]
    fn along_segments_counts_a_star_and_many_crossings() {
        // Ten lines through (1/3, 1/3) (not an f64 point) among long random segments,
        // enough records for the parallel scan.
        let mut unit = crate::testing::units(21u64);
        let ends = [
            (0, 0),
            (1, 0),
            (0, 1),
            (2, 1),
            (1, 2),
            (2, -2),
            (5, 1),
            (4, 3),
            (2, 0),
            (0, 2),
        ];
        let mut segs: Vec<Segment2> = ends
            .iter()
            .map(|&(a, b)| {
                seg(
                    (a as f64, b as f64),
                    ((1 - 2 * a) as f64, (1 - 2 * b) as f64),
                )
            })
            .collect();
        for _ in 0..700 {
            segs.push(seg(
                (-10.0, 20.0 * unit() - 10.0),
                (10.0, 20.0 * unit() - 10.0),
            ));
        }
        let pairs = Pairs::new(Grid::new(&segs));
        assert!(pairs.is_sweep() && pairs.candidates() >= pairwise::PARALLEL_SCAN_FROM);
        let got = count_along_segments(&segs, &pairs).unwrap();
        assert_eq!(got, count_on(&segs, &pairs));
        let star = brute_force::brute_force_intersections(&segs[..10]).unwrap();
        assert_eq!(star.points.len(), 1);
        // The oracle on the whole input (about 120 000 pairs: still quick).
        assert_eq!(got, expected(&segs));
    }
}
