//! The exact O(n²) oracle: every pair of segments through the kernel's
//! [`segment_intersection`], then grouping of equal points (exact comparisons) and the
//! maximal overlap pieces of each family of collinear overlapping segments. It defines
//! the expected answer of [`super::find_intersections`] and backs `--verify`.
//!
//! O(n² + K log K) time for K meeting pairs, O(n + K) space.

use super::bins::{self, Bins};
use super::bucket;
use super::list::defining_second;
use super::order::{sweep_cmp_points, EventPoint, Oriented};
use super::round::{round_crossing_of, round_crossings_of, Prepared};
use super::small_int::{self, Hom};
use super::sweep::check_finite;
use super::{sort_overlaps, IntersectionPoint, Intersections, Overlap};
use crate::kernel::arith::ordered_key as key;
use crate::kernel::{
    quick_crossing_static, segment_intersection, Crossing, ExactPoint, Point2, Segment2,
    SegmentIntersection,
};
use crate::{Error, Result};
use rayon::prelude::*;
use std::cmp::Ordering;

/// All intersection points and overlaps by testing every pair of segments: the same
/// answer as [`super::find_intersections`], in O(n²) time.
pub fn brute_force_intersections(segments: &[Segment2]) -> Result<Intersections> {
    check_finite(segments)?;
    check_count(segments)?;
    let mut found = PairResults::default();
    let table = Prepared::table(segments);
    for i in 0..segments.len() {
        for j in i + 1..segments.len() {
            found.test(segments, &table, i, j, f64::INFINITY);
        }
    }
    found.flush(segments, &table);
    Ok(found.assemble(segments))
}

/// One (point, pair) record, 24 bytes, ordered for the grouping: the point as two
/// order-preserving integer keys (y descending, then x ascending), then the pair.
/// The point is the input point itself, or for a proper crossing its nearest `f64` point
/// (correct rounding is monotone, so crossings whose rounded points differ are
/// ordered as the rounded points are, and equal exact points have equal rounded points).
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Debug)]
pub(crate) struct Record {
    ky: u64,
    kx: u64,
    /// `i << 32 | crossing << 31 | j` for the pair `i < j < 2^31`; once sorted, bit 63
    /// may mark the first record of a group of equal points ([`GROUP_START`]).
    pair: u64,
}

const CROSSING_BIT: u64 = 1 << 31;

/// Marks the first record of a group ([`mark_groups`]); not set while sorting.
const GROUP_START: u64 = 1 << 63;

/// The inverse of [`key`].
fn unkey(k: u64) -> f64 {
    if k >> 63 == 1 {
        f64::from_bits(k & !(1 << 63))
    } else {
        f64::from_bits(!k)
    }
}

impl Record {
    fn new(p: Point2, i: usize, j: usize, crossing: bool) -> Record {
        let flag = if crossing { CROSSING_BIT } else { 0 };
        Record {
            ky: !key(p.y),
            kx: key(p.x),
            pair: ((i as u64) << 32) | flag | j as u64,
        }
    }

    fn point(&self) -> Point2 {
        Point2::new(unkey(self.kx), unkey(!self.ky))
    }

    fn i(&self) -> usize {
        ((self.pair & !GROUP_START) >> 32) as usize
    }

    fn starts_group(&self) -> bool {
        self.pair & GROUP_START != 0
    }

    fn j(&self) -> usize {
        (self.pair & (CROSSING_BIT - 1)) as usize
    }

    fn is_crossing(&self) -> bool {
        self.pair & CROSSING_BIT != 0
    }

    /// The exact point.
    fn exact(&self, segments: &[Segment2]) -> ExactPoint {
        if self.is_crossing() {
            ExactPoint::Crossing(Crossing {
                s: segments[self.i()],
                t: segments[self.j()],
            })
        } else {
            ExactPoint::Input(self.point())
        }
    }
}

/// The most segments the pair records can name.
pub(crate) const MAX_SEGMENTS: usize = 1 << 31;

/// `Err` when there are too many segments for [`Record`].
pub(crate) fn check_count(segments: &[Segment2]) -> Result<()> {
    if segments.len() >= MAX_SEGMENTS {
        return Err(Error::InvalidInput(format!(
            "{} segments: at most {} are supported",
            segments.len(),
            MAX_SEGMENTS - 1
        )));
    }
    Ok(())
}

/// What the pairs that meet contribute: one record per (point, pair), and the pairs that
/// overlap.
#[derive(Default)]
pub(crate) struct PairResults {
    /// In one bin, or (the large parallel scans) in bins by the points' y, descending:
    /// [`record_key`].
    records: Bins<Record>,
    overlapping: Vec<(usize, usize)>,
    /// Proper crossings found and not yet rounded (the first `pending_len`): rounded
    /// [`LANES`] at a time, whose independent lanes overlap; the rest by
    /// [`PairResults::flush`].
    pending: [(usize, usize); LANES],
    pending_len: usize,
}

/// How many crossings are rounded together.
const LANES: usize = 8;

/// From this many records on, sorting and building the points run on the rayon pool
/// (on a pool of at most [`FUSED_UP_TO_THREADS`] threads: bin by bin, [`assemble_fused`]).
const PARALLEL_ASSEMBLY_FROM: usize = 50_000;

/// On a pool of at most this many threads the large assembly runs bin by bin on the
/// calling thread ([`assemble_fused`]) after the parallel scan, rather than on the pool
/// ([`assemble_marked`]). Session 26, long random 1e3 in `compgeom-bench intersect`, two
/// threads, six alternated runs each: `find` 7.0–7.9 ms fused against 8.8–10.2 ms on
/// the pool (the pool's assembly reads every record twice and builds each point apart).
/// Larger pools keep the pool's assembly (not measured: the machines here have 2 cores).
const FUSED_UP_TO_THREADS: usize = 2;

impl PairResults {
    /// Test segments `i < j` exactly and record how they meet (`bound`: a static
    /// orientation bound for the input, or infinity; `table`: [`Prepared::table`] of
    /// `segments`, the per-segment part of rounding crossings).
    // (Always inlined into the scans: as a call it cost a sixth more than its body.)
    #[inline(always)]
    pub(crate) fn test(
        &mut self,
        segments: &[Segment2],
        table: &[Prepared],
        i: usize,
        j: usize,
        bound: f64,
    ) {
        let (s, t) = (segments[i], segments[j]);
        // Most pairs are decided by the inlined filters; the rest by the exact test.
        match quick_crossing_static(s, t, bound) {
            Some(false) => return,
            Some(true) => return self.push_crossing(segments, table, i, j),
            None => {}
        }
        match segment_intersection(s, t) {
            SegmentIntersection::None => {}
            SegmentIntersection::Endpoint(q) => self.push(Record::new(q, i, j, false)),
            // (The crossing point does not depend on the order of the two segments.)
            SegmentIntersection::Crossing(_) => self.push_crossing(segments, table, i, j),
            SegmentIntersection::Overlap(a, b) => {
                self.push(Record::new(a, i, j, false));
                self.push(Record::new(b, i, j, false));
                self.overlapping.push((i, j));
            }
        }
    }

    /// Record the proper crossing of `i < j`, rounded now or with the next ones.
    #[inline]
    pub(crate) fn push_crossing(
        &mut self,
        segments: &[Segment2],
        table: &[Prepared],
        i: usize,
        j: usize,
    ) {
        self.pending[self.pending_len] = (i, j);
        self.pending_len += 1;
        if self.pending_len == LANES {
            let points = round_crossings_of(segments, table, &self.pending);
            let pending = self.pending;
            for (&p, &(i, j)) in points.iter().zip(&pending) {
                self.push(Record::new(p, i, j, true));
            }
            self.pending_len = 0;
        }
    }

    /// Record the proper crossings of `a` with `bs[k]`, already rounded to `points[k]`
    /// ([`super::round::round_crossings_sharing`]), in one append.
    #[inline]
    pub(crate) fn push_rounded<const L: usize>(
        &mut self,
        points: &[Point2; L],
        a: usize,
        bs: &[usize; L],
    ) {
        // The bins first, all lanes together (vector instructions), then the appends.
        let records: [Record; L] =
            std::array::from_fn(|k| Record::new(points[k], a.min(bs[k]), a.max(bs[k]), true));
        let bins: [usize; L] =
            std::array::from_fn(|k| self.records.bin_of(record_key(&records[k])));
        for (&b, &r) in bins.iter().zip(&records) {
            self.records.push_to(b, r);
        }
    }

    #[inline(always)]
    fn push(&mut self, r: Record) {
        self.records.push(record_key(&r), r);
    }

    /// Round and record the crossings still pending: due after the last
    /// [`PairResults::test`], before the records are read.
    pub(crate) fn flush(&mut self, segments: &[Segment2], table: &[Prepared]) {
        let pending = self.pending;
        for &(i, j) in &pending[..self.pending_len] {
            let p = round_crossing_of(segments, table, i, j);
            self.push(Record::new(p, i, j, true));
        }
        self.pending_len = 0;
    }

    /// Empty results with room for `records` records.
    pub(crate) fn with_capacity(records: usize) -> PairResults {
        PairResults {
            records: Bins::single(records),
            ..PairResults::default()
        }
    }

    /// Empty results for one part of a large parallel scan: records binned by y
    /// ([`Bins::laid_out`] over the keys of `y_range`, the input's range of y), in
    /// `bins` bins, bin `b` with room `room(b)` (bins in y descending). All parts of a
    /// scan take the same layout.
    pub(crate) fn binned(
        y_range: (f64, f64),
        bins: usize,
        room: impl Fn(usize) -> usize,
    ) -> PairResults {
        PairResults {
            records: Bins::laid_out(-y_range.1, -y_range.0, bins, room),
            ..PairResults::default()
        }
    }

    /// [`PairResults::assemble`] of the parts of a parallel scan taken together: the
    /// records are sorted straight from the parts ([`bucket::sort_parts`], or for many
    /// records [`bins::sort_bins_then`] from their bins, or on one thread
    /// [`bins::each_sorted_bin`] with the points built bin by bin), without
    /// concatenating them first.
    pub(crate) fn assemble_parts(parts: Vec<PairResults>, segments: &[Segment2]) -> Intersections {
        debug_assert!(
            parts.iter().all(|p| p.pending_len == 0),
            "unflushed crossings"
        );
        let overlapping = parts
            .iter()
            .flat_map(|p| p.overlapping.iter().copied())
            .collect();
        let n: usize = parts.iter().map(|p| p.records.len()).sum();
        let records: Vec<Bins<Record>> = parts.into_iter().map(|p| p.records).collect();
        if n < PARALLEL_ASSEMBLY_FROM {
            let records = records.into_iter().map(Bins::into_items).collect();
            let sorted = bucket::sort_parts(records, record_key, Record::cmp);
            return assemble_sorted(sorted, overlapping, segments);
        }
        if rayon::current_num_threads() <= FUSED_UP_TO_THREADS {
            return assemble_fused(records, overlapping, segments);
        }
        assemble_marked(records, overlapping, segments)
    }

    /// Group equal points (exactly), split their segments into U/L/C, and build the
    /// maximal overlap pieces.
    pub(crate) fn assemble(self, segments: &[Segment2]) -> Intersections {
        debug_assert_eq!(self.pending_len, 0, "unflushed crossings");
        let mut records = self.records.into_items();
        sort_records(&mut records);
        assemble_sorted(records, self.overlapping, segments)
    }
}

/// [`PairResults::assemble`] of records already in their order ([`sort_records`]).
fn assemble_sorted(
    mut records: Vec<Record>,
    overlapping: Vec<(usize, usize)>,
    segments: &[Segment2],
) -> Intersections {
    let segs: Vec<Oriented> = segments.iter().map(|&s| Oriented::of(s)).collect();
    let parallel = records.len() >= PARALLEL_ASSEMBLY_FROM;
    // Sorted by rounded points, which is the exact sweep order except within a run
    // of equal rounded y that holds a crossing: there the exact y may differ. Such
    // runs are re-sorted exactly; elsewhere equal keys mean equal points. Runs are
    // independent: large inputs are cut into pieces at run starts, done in parallel.
    let pieces = if parallel { 64 } else { 1 };
    let mut cuts: Vec<usize> = (0..pieces)
        .map(|k| {
            let mut at = k * records.len() / pieces;
            while at > 0 && at < records.len() && records[at].ky == records[at - 1].ky {
                at += 1;
            }
            at
        })
        .collect();
    cuts.push(records.len());
    cuts.dedup();
    let mut parts: Vec<(usize, &mut [Record])> = Vec::with_capacity(cuts.len());
    let mut rest = &mut records[..];
    for w in cuts.windows(2) {
        let (piece, tail) = rest.split_at_mut(w[1] - w[0]);
        rest = tail;
        parts.push((w[0], piece));
    }
    let group = |(offset, piece): (usize, &mut [Record])| {
        let mut starts = Vec::new();
        group_starts(segments, piece, &mut starts);
        starts.iter_mut().for_each(|s| *s += offset);
        starts
    };
    let mut starts: Vec<usize> = if parallel {
        let per: Vec<Vec<usize>> = parts.into_par_iter().map(group).collect();
        per.concat()
    } else {
        parts.into_iter().flat_map(group).collect()
    };
    starts.push(records.len());
    let records = &records;
    let point = |w: &[usize]| point_of(segments, &segs, &records[w[0]..w[1]]);
    let points: Vec<IntersectionPoint> = if parallel {
        starts.par_windows(2).map(point).collect()
    } else {
        starts.windows(2).map(point).collect()
    };
    with_overlaps(points, &segs, &overlapping)
}

/// The answer from its points: the maximal overlap pieces of the `overlapping` pairs
/// added, in their order.
fn with_overlaps(
    points: Vec<IntersectionPoint>,
    segs: &[Oriented],
    overlapping: &[(usize, usize)],
) -> Intersections {
    let mut overlaps = overlap_pieces(segs, overlapping);
    sort_overlaps(&mut overlaps);
    Intersections {
        points,
        overlaps,
        segments: segs.len(),
    }
}

/// Where the groups of equal points of sorted `records` (whole runs of equal rounded
/// y) start; runs of equal rounded y holding a crossing are re-sorted exactly first.
fn group_starts(segments: &[Segment2], records: &mut [Record], starts: &mut Vec<usize>) {
    each_group_start(segments, records, |_, m| starts.push(m));
}

/// Mark the first record of each group of equal points of sorted `records` (whole runs
/// of equal rounded y; runs holding a crossing are re-sorted exactly first, as
/// [`group_starts`] does) with [`GROUP_START`], and return the number of groups.
fn mark_groups(segments: &[Segment2], records: &mut [Record]) -> usize {
    let mut groups = 0;
    each_group_start(segments, records, |r, m| {
        r[m].pair |= GROUP_START;
        groups += 1;
    });
    groups
}

/// Call `start(records, m)` for every `m` where a group of equal points of sorted
/// `records` starts, in order, after re-sorting runs of equal rounded y that hold a
/// crossing exactly.
fn each_group_start(
    segments: &[Segment2],
    records: &mut [Record],
    mut start: impl FnMut(&mut [Record], usize),
) {
    let mut k = 0;
    while k < records.len() {
        let ky = records[k].ky;
        let mut end = k + 1;
        while end < records.len() && records[end].ky == ky {
            end += 1;
        }
        let run = &mut records[k..end];
        if end == k + 1 {
            // Most runs are one record (dense crossings): a group of its own.
            start(records, k);
        } else if run.iter().any(Record::is_crossing) {
            for g in exact_groups(segments, run) {
                start(records, k + g);
            }
        } else {
            for m in k..end {
                if m == k || records[m].kx != records[m - 1].kx {
                    start(records, m);
                }
            }
        }
        k = end;
    }
}

/// [`PairResults::assemble_parts`] for many records on the calling thread (pools of at
/// most [`FUSED_UP_TO_THREADS`]): each bin is sorted
/// ([`bins::each_sorted_bin`]), its groups found and its points built and appended to
/// the result while its records are in cache, bin after bin (a group lies within one
/// bin). The result is reserved for one point per record, a bound, and filled in place:
/// no list of group starts, no lookup of a group from its number, no second read of
/// the records from memory. Long random 1e3 (251k records), one thread, session 26,
/// against [`assemble_marked`]: callgrind per `find` 139.1M → 117.9M instructions,
/// driver best of 20 10.8–11.0 → 10.1–10.6 ms (interleaved runs, shared machine).
/// Stretches of lone crossings appended by one `extend` each rather than a `push` per
/// point (which built each 40-byte point on the stack with narrow stores and copied it
/// with wide loads, two failed store forwardings per point: 60% of this function's
/// samples): 117.9M → 111.8M, 10.1 → 8.9 ms.
fn assemble_fused(
    parts: Vec<Bins<Record>>,
    overlapping: Vec<(usize, usize)>,
    segments: &[Segment2],
) -> Intersections {
    let segs: Vec<Oriented> = segments.iter().map(|&s| Oriented::of(s)).collect();
    let n: usize = parts.iter().map(Bins::len).sum();
    let mut points = Vec::with_capacity(n);
    bins::each_sorted_bin(parts, record_key, Record::cmp, |bin| {
        each_group(segments, bin, |groups, lone| {
            if lone {
                // (An `extend` from a slice writes each point straight into its place;
                // a `push` built it on the stack and copied it, stalling on the copy.)
                points.extend(
                    groups
                        .iter()
                        .map(|r| IntersectionPoint::crossing(r.point(), r.i(), r.j())),
                );
            } else {
                points.push(point_of(segments, &segs, groups));
            }
        });
    });
    // (Many records per point, as where many segments meet: give the room back.)
    if points.len() < points.capacity() / 2 {
        points.shrink_to_fit();
    }
    with_overlaps(points, &segs, &overlapping)
}

/// Call `found(groups, lone)` for the groups of equal points of sorted `records`, in
/// order, after re-sorting runs of equal rounded y that hold a crossing exactly (the
/// groups [`each_group_start`] starts): with `lone` false for one group, true for a
/// stretch of consecutive groups that are each one crossing record (most groups of
/// dense inputs: the caller builds their points in one `extend`).
#[inline]
fn each_group(
    segments: &[Segment2],
    records: &mut [Record],
    mut found: impl FnMut(&[Record], bool),
) {
    let n = records.len();
    let mut k = 0;
    while k < n {
        // `k` starts a run of equal rounded y: first the lone crossings from there.
        let mut end = k;
        while end < n
            && records[end].is_crossing()
            && (end + 1 == n || records[end + 1].ky != records[end].ky)
        {
            end += 1;
        }
        if end > k {
            found(&records[k..end], true);
            k = end;
            continue;
        }
        let ky = records[k].ky;
        end = k + 1;
        while end < n && records[end].ky == ky {
            end += 1;
        }
        let run = &mut records[k..end];
        if run.len() == 1 {
            // One record, an input point.
            found(run, false);
        } else if run.iter().any(Record::is_crossing) {
            let mut starts = exact_groups(segments, run);
            starts.push(run.len());
            for w in starts.windows(2) {
                found(&run[w[0]..w[1]], false);
            }
        } else {
            let mut from = 0;
            for m in 1..=run.len() {
                if m == run.len() || run[m].kx != run[m - 1].kx {
                    found(&run[from..m], false);
                    from = m;
                }
            }
        }
        k = end;
    }
}

/// [`PairResults::assemble_parts`] for many records: the groups of equal points are
/// found and marked inside the sort, per bin while it is in cache
/// ([`bins::sort_bins_then`]), and the points are built straight from the marks on the
/// pool, each into its place in the result (no list of group starts).
fn assemble_marked(
    parts: Vec<Bins<Record>>,
    overlapping: Vec<(usize, usize)>,
    segments: &[Segment2],
) -> Intersections {
    let sorted = bins::sort_bins_then(parts, record_key, Record::cmp, |bin| {
        mark_groups(segments, bin)
    });
    let segs: Vec<Oriented> = segments.iter().map(|&s| Oriented::of(s)).collect();
    let marked = Marked::new(&sorted.bins, &sorted.tallies);
    let mut points = Vec::new();
    (0..marked.groups())
        .into_par_iter()
        .with_min_len(1024)
        .map_init(
            || (usize::MAX, (0, 0)),
            |(next, at): &mut (usize, (usize, usize)), g| {
                // Within one job the groups come in order: the next group starts where
                // this one ends. Otherwise (a job's first group) it is looked up.
                let (bin, from) = if g == *next { *at } else { marked.start_of(g) };
                let records = &marked.bins[bin][..];
                // The common case first, without the search for the group's end: one
                // record (the next one starts a group) of two segments crossing.
                let single = records.get(from + 1).map_or(true, Record::starts_group);
                let to = if single {
                    from + 1
                } else {
                    marked.end_of(bin, from)
                };
                (*next, *at) = (g + 1, marked.next_start(bin, to));
                let first = records[from];
                if single && first.is_crossing() {
                    return IntersectionPoint::crossing(first.point(), first.i(), first.j());
                }
                shared_point_of(segments, &segs, &records[from..to])
            },
        )
        .collect_into_vec(&mut points);
    with_overlaps(points, &segs, &overlapping)
}

/// Sorted bins of records whose groups are marked ([`mark_groups`]), with the first
/// group of each bin, to find a group's records (a group lies within one bin).
struct Marked<'a> {
    bins: &'a [Vec<Record>],
    /// Bin `b` holds groups `group_base[b]..group_base[b + 1]`.
    group_base: Vec<usize>,
}

impl<'a> Marked<'a> {
    fn new(bins: &'a [Vec<Record>], tallies: &[usize]) -> Marked<'a> {
        let mut group_base = Vec::with_capacity(tallies.len() + 1);
        group_base.push(0);
        for t in tallies {
            group_base.push(group_base[group_base.len() - 1] + t);
        }
        Marked { bins, group_base }
    }

    /// The number of groups.
    fn groups(&self) -> usize {
        self.group_base[self.group_base.len() - 1]
    }

    /// The bin and first record of group `g < self.groups()`: in the bin holding it (the
    /// last one whose first group is at or before it), the `g - group_base[b]`-th
    /// marked record.
    fn start_of(&self, g: usize) -> (usize, usize) {
        let b = self.group_base.partition_point(|&first| first <= g) - 1;
        let mut at = 0;
        for _ in self.group_base[b]..g {
            at = self.end_of(b, at);
        }
        (b, at)
    }

    /// Where the group starting at record `from` of bin `b` ends: the next marked
    /// record, or the end of the bin.
    fn end_of(&self, b: usize, from: usize) -> usize {
        let rest = &self.bins[b][from + 1..];
        from + 1
            + rest
                .iter()
                .position(Record::starts_group)
                .unwrap_or(rest.len())
    }

    /// Where the group after the one ending at record `to` of bin `b` starts: there, or
    /// at the start of the next bin with records (past the last bin after the last group).
    fn next_start(&self, b: usize, to: usize) -> (usize, usize) {
        if to < self.bins[b].len() {
            return (b, to);
        }
        let next = self.bins[b + 1..]
            .iter()
            .position(|bin| !bin.is_empty())
            .map_or(self.bins.len(), |k| b + 1 + k);
        (next, 0)
    }
}

/// Sort records into their order: a bucket sort by the points' y (descending, as the
/// keys are), then by the full key within buckets. O(K) for spread-out points.
fn sort_records(records: &mut [Record]) {
    bucket::sort_by_key_then(records, record_key, Record::cmp);
}

/// The bucket key of a record: its rounded y, negated (the order is y descending).
fn record_key(r: &Record) -> f64 {
    -unkey(!r.ky)
}

/// Sort `run` exactly (sweep order, then pair) and return where its groups of equal
/// points start.
fn exact_groups(segments: &[Segment2], run: &mut [Record]) -> Vec<usize> {
    let mut keyed: Vec<(EventPoint, Option<Hom>, Record)> = run
        .iter()
        .map(|r| {
            let e = r.exact(segments);
            (EventPoint::new(e), small_int::hom(&e), *r)
        })
        .collect();
    let same_point = |a: &(EventPoint, Option<Hom>, Record),
                      b: &(EventPoint, Option<Hom>, Record)| {
        match (a.1, b.1) {
            (Some(p), Some(q)) => small_int::sweep_cmp(p, q),
            _ => a.0.cmp(&b.0),
        }
    };
    keyed.sort_unstable_by(|a, b| same_point(a, b).then(a.2.pair.cmp(&b.2.pair)));
    let mut starts = Vec::new();
    for (m, r) in keyed.iter().enumerate() {
        run[m] = r.2;
        if m == 0 || same_point(&keyed[m - 1], r) != Ordering::Equal {
            starts.push(m);
        }
    }
    starts
}

/// The rounded point of crossing record `r`, with the sign of a zero coordinate that
/// rounding the exact one gives (`-0.0` for a tiny negative one, as
/// [`Crossing::approx`] and the sweep give): the record's keys hold `-0.0` as `0.0`
/// so that the two group together.
fn crossing_point(segments: &[Segment2], r: &Record) -> Point2 {
    let p = r.point();
    if p.x != 0.0 && p.y != 0.0 {
        return p;
    }
    let c = Crossing {
        s: segments[r.i()],
        t: segments[r.j()],
    };
    c.approx()
}

/// One intersection point from the records of the pairs that meet there.
#[inline]
fn point_of(segments: &[Segment2], segs: &[Oriented], group: &[Record]) -> IntersectionPoint {
    let first = group[0];
    if group.len() == 1 && first.is_crossing() {
        // The common case, without allocating: two segments crossing properly.
        let p = crossing_point(segments, &first);
        return IntersectionPoint::crossing(p, first.i(), first.j());
    }
    shared_point_of(segments, segs, group)
}

/// [`point_of`] for a point that is an input point or where more than two segments
/// cross.
#[inline(never)]
fn shared_point_of(
    segments: &[Segment2],
    segs: &[Oriented],
    group: &[Record],
) -> IntersectionPoint {
    let first = group[0];
    // The point is an input point when any pair meets there at an endpoint.
    let at = group.iter().find(|r| !r.is_crossing()).map(Record::point);
    let mut all: Vec<usize> = group.iter().flat_map(|r| [r.i(), r.j()]).collect();
    all.sort_unstable();
    all.dedup();
    // A segment's role at the point: upper end, lower end (both for a zero-length
    // segment), or interior. At a crossing that is no input point, every segment is
    // interior.
    let role = |s: usize| match at {
        Some(q) => (segs[s].upper == q, segs[s].lower == q),
        None => (false, false),
    };
    let pick = |keep: &dyn Fn((bool, bool)) -> bool| -> Vec<usize> {
        all.iter().copied().filter(|&s| keep(role(s))).collect()
    };
    let upper = pick(&|r| r.0);
    let lower = pick(&|r| r.1);
    let interior = pick(&|r| r == (false, false));
    let second = at.is_none().then(|| defining_second(&all, |k| segments[k]));
    // (A crossing of three or more segments: all of them round to the same point.)
    let point = at.unwrap_or_else(|| crossing_point(segments, &first));
    IntersectionPoint::new(point, &all, [&upper, &lower, &interior], second)
}

fn find(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

/// The maximal pieces covered by the same two or more segments, per family of segments
/// linked by overlaps (such a family lies on one line).
pub(super) fn overlap_pieces(segs: &[Oriented], overlapping: &[(usize, usize)]) -> Vec<Overlap> {
    let mut parent: Vec<usize> = (0..segs.len()).collect();
    for &(i, j) in overlapping {
        let (a, b) = (find(&mut parent, i), find(&mut parent, j));
        parent[a] = b;
    }
    let mut families: Vec<(usize, usize)> = Vec::new();
    let mut involved: Vec<usize> = overlapping.iter().flat_map(|&(i, j)| [i, j]).collect();
    involved.sort_unstable();
    involved.dedup();
    for &i in &involved {
        families.push((find(&mut parent, i), i));
    }
    families.sort_unstable();
    let mut out = Vec::new();
    let mut k = 0;
    while k < families.len() {
        let mut end = k + 1;
        while end < families.len() && families[end].0 == families[k].0 {
            end += 1;
        }
        let members: Vec<usize> = families[k..end].iter().map(|f| f.1).collect();
        let mut stops: Vec<_> = members
            .iter()
            .flat_map(|&m| [segs[m].upper, segs[m].lower])
            .collect();
        stops.sort_by(|a, b| sweep_cmp_points(*a, *b));
        stops.dedup_by(|a, b| sweep_cmp_points(*a, *b) == Ordering::Equal);
        let mut current: Option<Overlap> = None;
        for w in stops.windows(2) {
            let (a, b) = (w[0], w[1]);
            let cover: Vec<usize> = members
                .iter()
                .copied()
                .filter(|&m| {
                    sweep_cmp_points(segs[m].upper, a) != Ordering::Greater
                        && sweep_cmp_points(b, segs[m].lower) != Ordering::Greater
                })
                .collect();
            match &mut current {
                Some(o) if o.segments == cover => o.to = b,
                _ => {
                    out.extend(current.take());
                    if cover.len() >= 2 {
                        current = Some(Overlap {
                            segments: cover,
                            from: a,
                            to: b,
                        });
                    }
                }
            }
        }
        out.extend(current);
        k = end;
    }
    out
}

fn list(v: &[usize]) -> String {
    format!("{v:?}")
}

/// Check `found` against the exact brute-force answer (O(n²): meant for inputs of up to a
/// few thousand segments). The error names the first difference.
pub fn verify_intersections(segments: &[Segment2], found: &Intersections) -> Result<()> {
    let expected = brute_force_intersections(segments)?;
    let fail = |m: String| Err(Error::Verification(m));
    if found.segments != segments.len() {
        return fail(format!(
            "result is for {} segments, input has {}",
            found.segments,
            segments.len()
        ));
    }
    for (k, (f, e)) in found.points.iter().zip(&expected.points).enumerate() {
        let same_point = EventPoint::new(f.exact(segments)) == EventPoint::new(e.exact(segments));
        if !same_point || f.point != e.point {
            return fail(format!(
                "intersection point {k} is ({}, {}), expected ({}, {})",
                f.point.x, f.point.y, e.point.x, e.point.y
            ));
        }
        let fields = [
            ("segments", f.segments(), e.segments()),
            ("upper", f.upper(), e.upper()),
            ("lower", f.lower(), e.lower()),
            ("interior", f.interior(), e.interior()),
        ];
        for (name, a, b) in fields {
            if a != b {
                return fail(format!(
                    "at intersection point {k} ({}, {}) {name} is {}, expected {}",
                    f.point.x,
                    f.point.y,
                    list(a),
                    list(b)
                ));
            }
        }
    }
    if found.points.len() != expected.points.len() {
        return fail(format!(
            "{} intersection points found, expected {}",
            found.points.len(),
            expected.points.len()
        ));
    }
    if found.overlaps != expected.overlaps {
        let k = found
            .overlaps
            .iter()
            .zip(&expected.overlaps)
            .position(|(a, b)| a != b)
            .unwrap_or(found.overlaps.len().min(expected.overlaps.len()));
        return fail(format!(
            "overlaps differ at {k}: found {:?}, expected {:?}",
            found.overlaps.get(k),
            expected.overlaps.get(k)
        ));
    }
    Ok(())
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// The records of every meeting pair of `segments`, dealt into `parts` pieces, each
    /// with `bins` bins over the segments' range of y (one: a plain list).
    fn dealt(segments: &[Segment2], parts: usize, bins: usize) -> Vec<PairResults> {
        let table = Prepared::table(segments);
        let range = segments
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |r, s| {
                (r.0.min(s.a.y).min(s.b.y), r.1.max(s.a.y).max(s.b.y))
            });
        let mut out: Vec<PairResults> = (0..parts)
            .map(|_| PairResults::binned(range, bins, |_| 0))
            .collect();
        for i in 0..segments.len() {
            for j in i + 1..segments.len() {
                out[(i * 7 + j) % parts].test(segments, &table, i, j, f64::INFINITY);
            }
        }
        out.iter_mut().for_each(|p| p.flush(segments, &table));
        out
    }

    /// Segments from integer-grid end points `v` scaled by `how`: 0 the grid itself (with
    /// -0.0 for 0), 1 divided by 3 (distinct crossings round to the same point), 2 huge
    /// (×1e300: the static bound is infinite), 3 tiny (×1e-300), 4 offset by 2^22
    /// (orientations near the static bound). The degenerate inputs of the intersect tests.
    pub(crate) fn grid_segments(v: &[(i32, i32, i32, i32)], how: u8) -> Vec<Segment2> {
        let f = |k: i32| match how {
            0 if k == 0 => -0.0,
            0 => k as f64,
            1 => k as f64 / 3.0,
            2 => k as f64 * 1e300,
            3 => k as f64 * 1e-300,
            _ => k as f64 + 4_194_304.0,
        };
        v.iter()
            .map(|&(a, b, c, d)| Segment2::new(Point2::new(f(a), f(b)), Point2::new(f(c), f(d))))
            .collect()
    }

    proptest::proptest! {
        /// The marked assembly (groups found inside the sort, points built from the
        /// marks) gives exactly the plain one (sort, list of group starts, points) on
        /// degenerate input: integer grids (shared endpoints, many segments through one
        /// point, overlaps, duplicates, zero-length segments, -0.0) and the same grids
        /// divided by 3, where distinct crossings round to the same point; with huge and
        /// tiny magnitudes. The fused assembly too. (Up to 70 bins for at most 40
        /// segments: many empty bins; one bin: a plain list.)
        #[test]
        fn the_marked_assembly_is_the_plain_one(
            v in proptest::collection::vec((-3i32..4, -3i32..4, -3i32..4, -3i32..4), 0..40),
            how in 0u8..5,
            parts in 1usize..5,
            bins in 1usize..70,
        ) {
            let segs = grid_segments(&v, how);
            let plain = {
                let mut all = PairResults::default();
                for p in dealt(&segs, 1, 1) {
                    p.records.into_items().into_iter().for_each(|r| all.push(r));
                    all.overlapping.extend(p.overlapping);
                }
                all.assemble(&segs)
            };
            let split = dealt(&segs, parts, bins);
            let overlapping: Vec<(usize, usize)> =
                split.iter().flat_map(|p| p.overlapping.clone()).collect();
            let records = || split.iter().map(|p| p.records.clone()).collect();
            let marked = assemble_marked(records(), overlapping.clone(), &segs);
            proptest::prop_assert_eq!(&marked, &plain);
            // The fused assembly (one thread: groups found and points built per bin as
            // it is sorted) as well.
            let fused = assemble_fused(records(), overlapping, &segs);
            proptest::prop_assert_eq!(&fused, &plain);
        }
    }

    #[test]
    fn marked_groups_are_found_from_any_group() {
        // Three records of one input point, then 200 crossings at distinct points.
        let p = Point2::new(0.0, 0.0);
        let mut records = vec![Record::new(p, 0, 1, false); 3];
        records
            .extend((0..200).map(|k| Record::new(Point2::new(1.0, -1.0 - k as f64), 0, k, true)));
        let segs = [Segment2::new(p, p)];
        let n = mark_groups(&segs, &mut records);
        assert_eq!(n, 201);
        // Split over bins, some empty.
        let bins = vec![
            Vec::new(),
            records[..103].to_vec(),
            Vec::new(),
            Vec::new(),
            records[103..].to_vec(),
        ];
        // The groups as [`each_group`] finds them: the same.
        let mut groups = Vec::new();
        let mut again = records.clone();
        each_group(&segs, &mut again, |g, lone| {
            if lone {
                assert!(g.iter().all(Record::is_crossing));
                groups.extend(g.iter().map(|r| vec![*r]));
            } else {
                groups.push(g.to_vec());
            }
        });
        assert_eq!(groups.len(), 201);
        assert_eq!(groups.concat(), records);
        assert!(groups.iter().all(|g| g[0].starts_group()));
        assert!(groups
            .iter()
            .all(|g| g[1..].iter().all(|r| !r.starts_group())));
        let marked = Marked::new(&bins, &[0, 101, 0, 0, 100]);
        assert_eq!(marked.groups(), 201);
        assert_eq!((marked.start_of(0), marked.end_of(1, 0)), ((1, 0), 3));
        assert_eq!(marked.next_start(1, 3), (1, 3));
        assert_eq!(marked.next_start(1, 103), (4, 0));
        assert_eq!(marked.next_start(4, 100), (5, 0));
        for g in 1..201 {
            let (b, at) = if g <= 100 { (1, g + 2) } else { (4, g - 101) };
            assert_eq!(marked.start_of(g), (b, at));
            assert_eq!(marked.end_of(b, at), at + 1);
        }
    }
}
