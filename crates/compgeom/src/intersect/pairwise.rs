//! The fast default for most inputs: exact tests of the pairs of segments whose bounding
//! boxes overlap, found with a uniform grid of cells, then the same exact grouping as the
//! brute-force oracle.
//!
//! The grid's cells are about the size of the average bounding box (at most about 2n
//! cells, and about 6n (segment, cell) entries at most: it coarsens when segments are
//! long). A pair is tested in one cell only: the one holding the lower-left corner of
//! the intersection of the two boxes (cell coordinates are a monotone function of the
//! coordinates, so that cell is the pair of the larger cell coordinates of the two
//! boxes' lower-left corners, and both boxes cover it).
//!
//! When the grid would look at many pairs per segment (long segments: every pair shares
//! cells, a pair sharing k cells is looked at k times), a sort and sweep along one axis
//! ([`AxisSweep`]) is used instead if it looks at fewer pairs: segments sorted by the
//! lower end of their boxes, each scanned against the later ones whose lower end lies
//! within its box, the other axis tested per pair; O(n log n + m') for the m' pairs
//! overlapping along that axis, each looked at once ([`Pairs`] chooses). Its scan is
//! batched ([`SweepLanes`]): the candidates of a segment are the items right after it in
//! the sorted order, tested eight at a time by a branch-free, vectorized static filter.
//!
//! O(n + m + K log K) time for m candidate pairs (pairs sharing a cell) and K meeting
//! pairs; O(n + K) space. It beats the sweep whenever m is not much larger than n + K
//! (short segments, grids, dense crossings), and loses when many long segments share
//! cells without meeting; [`super::find_intersections`] decides between the two from m
//! and an estimate of K ([`prefer_pairwise`]).

use super::bins::Bins;
use super::brute_force::{check_count, PairResults};
#[cfg(target_arch = "x86_64")]
use super::round::AlwaysFused;
use super::round::{Dispatched, Prepared, RoundSharing};
use super::sweep::check_finite;
use super::Intersections;
use crate::kernel::{segment_intersection, static_orient_bound, Segment2, SegmentIntersection};
use crate::Result;
use rayon::prelude::*;

/// From this many candidate pairs on, the scan runs on the rayon pool.
pub(crate) const PARALLEL_SCAN_FROM: u64 = 100_000;

/// A segment in a cell: its bounding box `[min x, max x, min y, max y]`, its index and
/// the cell coordinates of the box's lower-left corner.
#[derive(Clone, Copy)]
struct Entry {
    b: [f64; 4],
    id: u32,
    cx: u32,
    cy: u32,
}

/// The segments bucketed by the cells their bounding boxes cover.
pub(crate) struct Grid {
    min: [f64; 2],
    inv: [f64; 2],
    n: [usize; 2],
    /// Cell `c` holds `entries[start[c]..start[c + 1]]` (cells row by row).
    start: Vec<usize>,
    entries: Vec<Entry>,
    /// For each entry, its cell.
    cell_of: Vec<u32>,
    /// The boxes, by segment.
    boxes: Vec<[f64; 4]>,
    /// The static orientation bound for every coordinate of the input
    /// ([`crate::kernel::static_orient_bound`]).
    pub(super) orient_bound: f64,
}

impl Grid {
    /// The cell coordinate of `v` along `axis` (monotone in `v`).
    fn cell(&self, v: f64, axis: usize) -> usize {
        // `as usize` saturates: values below `min` (none) or NaN (none: finite input) go to 0.
        (((v - self.min[axis]) * self.inv[axis]) as usize).min(self.n[axis] - 1)
    }

    /// The cell ranges `[x0, x1, y0, y1]` (inclusive) a box covers.
    fn span(&self, b: &[f64; 4]) -> [usize; 4] {
        [
            self.cell(b[0], 0),
            self.cell(b[1], 0),
            self.cell(b[2], 1),
            self.cell(b[3], 1),
        ]
    }

    /// Total (segment, cell) entries for `n` cells along the axes.
    fn entries_for(boxes: &[[f64; 4]], min: [f64; 2], size: [f64; 2], n: [usize; 2]) -> u64 {
        let g = Grid::shell(min, size, n);
        boxes
            .iter()
            .map(|b| {
                let s = g.span(b);
                ((s[1] - s[0] + 1) * (s[3] - s[2] + 1)) as u64
            })
            .sum()
    }

    /// A grid without contents.
    fn shell(min: [f64; 2], size: [f64; 2], n: [usize; 2]) -> Grid {
        let inv = |axis: usize| {
            if size[axis] > 0.0 {
                n[axis] as f64 / size[axis]
            } else {
                0.0
            }
        };
        Grid {
            min,
            inv: [inv(0), inv(1)],
            n,
            start: Vec::new(),
            entries: Vec::new(),
            cell_of: Vec::new(),
            boxes: Vec::new(),
            orient_bound: f64::INFINITY,
        }
    }

    /// Bucket the segments (finite coordinates).
    pub(super) fn new(segments: &[Segment2]) -> Grid {
        let boxes: Vec<[f64; 4]> = segments.iter().map(Segment2::bounds).collect();
        let count = boxes.len().max(1);
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        let mut mean = [0.0f64; 2];
        for b in &boxes {
            lo = [lo[0].min(b[0]), lo[1].min(b[2])];
            hi = [hi[0].max(b[1]), hi[1].max(b[3])];
            mean = [mean[0] + (b[1] - b[0]), mean[1] + (b[3] - b[2])];
        }
        if boxes.is_empty() {
            (lo, hi) = ([0.0; 2], [0.0; 2]);
        }
        // The extent may overflow to infinity for huge coordinates: then one cell.
        let size = [hi[0] - lo[0], hi[1] - lo[1]];
        let cap = 2 * count + 16;
        // Cells about the size of the average box, at most `cap` cells in all.
        let mut n = [0usize; 2];
        for axis in 0..2 {
            let avg = mean[axis] / count as f64;
            let want = if !(size[axis] > 0.0 && size[axis].is_finite()) {
                1.0
            } else if avg > 0.0 {
                size[axis] / avg
            } else {
                cap as f64
            };
            n[axis] = (want.min(cap as f64) as usize).max(1);
        }
        while n[0] * n[1] > cap {
            let k = usize::from(n[1] > n[0]);
            n[k] = n[k].div_ceil(2);
        }
        // Coarser while long segments make too many entries.
        while (n[0] > 1 || n[1] > 1) && Grid::entries_for(&boxes, lo, size, n) > 6 * count as u64 {
            let k = usize::from(n[1] > n[0]);
            n[k] = n[k].div_ceil(2);
        }
        let mut g = Grid::shell(lo, size, n);
        // Counting sort of the (segment, cell) entries, segments in index order per cell.
        let cells = n[0] * n[1];
        let spans: Vec<[usize; 4]> = boxes.iter().map(|b| g.span(b)).collect();
        let mut start = vec![0usize; cells + 1];
        for s in &spans {
            for cy in s[2]..=s[3] {
                for cx in s[0]..=s[1] {
                    start[cy * n[0] + cx + 1] += 1;
                }
            }
        }
        for c in 0..cells {
            start[c + 1] += start[c];
        }
        let total = start[cells];
        let mut fill = start.clone();
        let blank = Entry {
            b: [0.0; 4],
            id: 0,
            cx: 0,
            cy: 0,
        };
        let mut entries = vec![blank; total];
        let mut cell_of = vec![0u32; total];
        for (i, (b, s)) in boxes.iter().zip(&spans).enumerate() {
            let e = Entry {
                b: *b,
                id: i as u32,
                cx: s[0] as u32,
                cy: s[2] as u32,
            };
            for cy in s[2]..=s[3] {
                for cx in s[0]..=s[1] {
                    let c = cy * n[0] + cx;
                    entries[fill[c]] = e;
                    cell_of[fill[c]] = c as u32;
                    fill[c] += 1;
                }
            }
        }
        g.start = start;
        g.entries = entries;
        g.cell_of = cell_of;
        let m = boxes.iter().fold(0.0f64, |m, b| {
            m.max(b[0].abs())
                .max(b[1].abs())
                .max(b[2].abs())
                .max(b[3].abs())
        });
        g.orient_bound = static_orient_bound(m);
        g.boxes = boxes;
        g
    }

    /// The number of (segment, cell) entries: [`Grid::scan_from`] takes `0..` this.
    pub(crate) fn entry_count(&self) -> usize {
        self.entries.len()
    }

    /// The number of pairs sharing a cell (pairs sharing several cells count once per
    /// cell): an upper bound on the pairs [`Grid::scan`] tests exactly.
    pub(crate) fn candidates(&self) -> u64 {
        self.start
            .windows(2)
            .map(|w| {
                let k = (w[1] - w[0]) as u64;
                k * k.saturating_sub(1) / 2
            })
            .sum()
    }

    /// Call `f(i, j)` (`i < j`) for the pairs after entry `k` in its cell whose boxes
    /// overlap and whose test belongs to this cell.
    pub(crate) fn scan_from(&self, k: usize, mut f: impl FnMut(usize, usize)) {
        let a = self.entries[k];
        let c = self.cell_of[k] as usize;
        let here = ((c % self.n[0]) as u32, (c / self.n[0]) as u32);
        for b in &self.entries[k + 1..self.start[c + 1]] {
            if b.b[0] > a.b[1] || a.b[0] > b.b[1] || b.b[2] > a.b[3] || a.b[2] > b.b[3] {
                continue;
            }
            // The cell of the lower-left corner of the boxes' intersection.
            if (a.cx.max(b.cx), a.cy.max(b.cy)) == here {
                let (i, j) = (a.id.min(b.id) as usize, a.id.max(b.id) as usize);
                f(i, j);
            }
        }
    }
}

/// The segments sorted by the lower end of their boxes along one axis (sort and sweep):
/// the candidate pairs are the pairs whose boxes overlap along that axis, found by
/// scanning forward from each segment while the later lower ends stay within its box;
/// the other axis is tested per pair. When many long segments span most of the input
/// (the dense case: every pair shares grid cells, and a pair sharing k cells is looked
/// at k times), this looks at each pair at most once and only at pairs overlapping
/// along the axis, fewer than the grid's.
pub(crate) struct AxisSweep {
    /// Sorted by `lo` (ties in index order, so that the scan is deterministic).
    items: Vec<SweepItem>,
    /// Pairs overlapping along the axis: what the scan looks at.
    visits: u64,
    /// For each item, the pairs its scan looks at.
    visits_from: Vec<u64>,
}

/// A segment's box along the sweep axis (`lo`, `hi`) and the other axis, and its index.
#[derive(Clone, Copy)]
struct SweepItem {
    lo: f64,
    hi: f64,
    other: [f64; 2],
    id: u32,
}

impl AxisSweep {
    /// The sweep along `axis` (0: x, 1: y) of the boxes `[min x, max x, min y, max y]`.
    fn new(boxes: &[[f64; 4]], axis: usize) -> AxisSweep {
        let o = 2 - 2 * axis;
        let mut items: Vec<SweepItem> = boxes
            .iter()
            .enumerate()
            .map(|(i, b)| SweepItem {
                lo: b[2 * axis],
                hi: b[2 * axis + 1],
                other: [b[o], b[o + 1]],
                id: i as u32,
            })
            .collect();
        // Finite coordinates: `total_cmp` is the numeric order there except that it puts
        // -0.0 before 0.0, which only reorders equal keys (the scan compares with `>`).
        items.sort_unstable_by(|a, b| a.lo.total_cmp(&b.lo).then(a.id.cmp(&b.id)));
        let visits_from: Vec<u64> = (0..items.len())
            .map(|k| {
                let hi = items[k].hi;
                items[k + 1..].partition_point(|b| b.lo <= hi) as u64
            })
            .collect();
        AxisSweep {
            items,
            visits: visits_from.iter().sum(),
            visits_from,
        }
    }

    /// Call `f(i, j)` (`i < j`) for the pairs of item `k` with later items whose boxes
    /// overlap. Over all `k`, every pair of overlapping boxes comes exactly once: the
    /// pair is met from the one of the two that comes first in the sorted order.
    #[inline]
    fn scan_from(&self, k: usize, mut f: impl FnMut(usize, usize)) {
        let a = self.items[k];
        for b in &self.items[k + 1..] {
            // Sorted by `lo`: no later box starts within `a` either.
            if b.lo > a.hi {
                break;
            }
            if b.other[0] > a.other[1] || a.other[0] > b.other[1] {
                continue;
            }
            let (i, j) = (a.id.min(b.id) as usize, a.id.max(b.id) as usize);
            f(i, j);
        }
    }
}

/// Candidates tested together by [`SweepLanes::scan_from`].
const BLOCK: usize = 8;

/// The segments of an [`AxisSweep`] in its sorted order as a structure of arrays (each
/// padded with [`BLOCK`] zeros), for [`SweepLanes::scan_from`]: a unit's candidates are
/// the items right after it, so a block of them is a run of each array, which the
/// compiler turns into vector loads and vector arithmetic (SSE2: two lanes).
pub(crate) struct SweepLanes<'a> {
    sweep: &'a AxisSweep,
    /// First endpoint, and direction `b - a` (rounded: the same `f64` operations as
    /// [`crate::kernel::orient_static`]'s first differences).
    ax: Vec<f64>,
    ay: Vec<f64>,
    dx: Vec<f64>,
    dy: Vec<f64>,
    /// Second endpoint.
    bx: Vec<f64>,
    by: Vec<f64>,
    /// The box along the other axis.
    olo: Vec<f64>,
    ohi: Vec<f64>,
}

impl<'a> SweepLanes<'a> {
    fn new(sweep: &'a AxisSweep, segments: &[Segment2]) -> SweepLanes<'a> {
        let col = |f: &dyn Fn(&SweepItem) -> f64| -> Vec<f64> {
            let mut v: Vec<f64> = sweep.items.iter().map(f).collect();
            v.resize(v.len() + BLOCK, 0.0);
            v
        };
        let seg = |it: &SweepItem| segments[it.id as usize];
        SweepLanes {
            sweep,
            ax: col(&|it| seg(it).a.x),
            ay: col(&|it| seg(it).a.y),
            dx: col(&|it| seg(it).b.x - seg(it).a.x),
            dy: col(&|it| seg(it).b.y - seg(it).a.y),
            bx: col(&|it| seg(it).b.x),
            by: col(&|it| seg(it).b.y),
            olo: col(&|it| it.other[0]),
            ohi: col(&|it| it.other[1]),
        }
    }

    /// Test the pairs of unit `k` ([`AxisSweep::scan_from`]'s pairs) into `found`:
    /// [`BLOCK`] candidates at a time, four orientations each against the static bound
    /// in one branch-free loop (most pairs of long segments cross: the early exit of
    /// [`crate::kernel::quick_crossing_static`] after two orientations mostly does not
    /// happen and its branches mispredict), then the proper crossings recorded and the
    /// few undecided pairs given to [`PairResults::test`].
    ///
    /// Exact: an orientation counts as decided only when its absolute value is above
    /// `bound`, a [`crate::kernel::static_orient_bound`] for every coordinate of the
    /// input, which certifies its sign (the same evaluation as
    /// [`crate::kernel::orient_static`]). A pair is apart when both ends of one segment
    /// are certified strictly on one side of the other's line, a proper crossing when
    /// each segment's ends are certified strictly on both sides of the other's line
    /// (then the lines are not parallel and meet in a point interior to both); anything
    /// else goes to the exact test.
    #[inline]
    pub(crate) fn scan_from(
        &self,
        k: usize,
        segments: &[Segment2],
        table: &[Prepared],
        bound: f64,
        found: &mut PairResults,
    ) {
        // Where the scan runs compiled for wider vectors, the rounding inlined into it
        // takes the fused products directly.
        #[cfg(target_arch = "x86_64")]
        if wide::available() {
            return self.scan_from_rounding::<AlwaysFused>(k, segments, table, bound, found, true);
        }
        self.scan_from_rounding::<Dispatched>(k, segments, table, bound, found, false)
    }

    /// [`SweepLanes::scan_from`] with the crossings of unit `k`'s segment rounded by
    /// `R` (every instantiation gives the same bits), by
    /// [`SweepLanes::scan_batched_widest`] if `widest`, else the plain scan.
    #[inline(always)]
    fn scan_from_rounding<R: RoundSharing>(
        &self,
        k: usize,
        segments: &[Segment2],
        table: &[Prepared],
        bound: f64,
        found: &mut PairResults,
        widest: bool,
    ) {
        let mut sink = Rounding::<R> {
            segments,
            table,
            bound,
            a: self.sweep.items[k].id as usize,
            mine: [0; BLOCK],
            len: 0,
            found,
            rounding: std::marker::PhantomData,
        };
        if widest {
            self.scan_batched_widest(k, bound, &mut sink);
        } else {
            self.scan_batched(k, bound, &mut sink);
        }
        let Rounding { a, mine, len, .. } = sink;
        for &b in &mine[..len] {
            found.push_crossing(segments, table, a.min(b), a.max(b));
        }
    }

    /// [`SweepLanes::scan_batched`], compiled for wider vectors where the processor has
    /// them ([`wide`]).
    #[inline]
    pub(crate) fn scan_batched_widest(&self, k: usize, bound: f64, sink: &mut impl BatchSink) {
        #[cfg(target_arch = "x86_64")]
        if wide::scan_batched(self, k, bound, sink) {
            return;
        }
        self.scan_batched(k, bound, sink)
    }

    /// The pairs of unit `k` ([`AxisSweep::scan_from`]'s pairs, with unit `k`'s segment
    /// `a`), by the batched static filter of [`SweepLanes::scan_from`], into `sink`:
    /// [`BatchSink::cross`] for each other segment certified to cross `a` properly,
    /// [`BatchSink::open`] for each one the filter leaves undecided (to be tested
    /// exactly); pairs certified apart, or whose boxes do not overlap, are skipped.
    #[inline(always)]
    pub(crate) fn scan_batched(&self, k: usize, bound: f64, sink: &mut impl BatchSink) {
        let sweep = self.sweep;
        let end = k + 1 + sweep.visits_from[k] as usize;
        let (aax, aay, adx, ady) = (self.ax[k], self.ay[k], self.dx[k], self.dy[k]);
        let (abx, aby) = (self.bx[k], self.by[k]);
        let (aolo, aohi) = (self.olo[k], self.ohi[k]);
        // Every column cut to the same length once, so that one range check per block
        // covers all eight loads.
        let n = self.ax.len();
        fn cut_to(v: &[f64], n: usize) -> &[f64] {
            &v[..n]
        }
        let col = |v| cut_to(v, n);
        let (ax, ay, dx, dy) = (col(&self.ax), col(&self.ay), col(&self.dx), col(&self.dy));
        let (bx, by, olo, ohi) = (col(&self.bx), col(&self.by), col(&self.olo), col(&self.ohi));
        let mut p = k + 1;
        while p < end {
            let m = (end - p).min(BLOCK);
            assert!(p + BLOCK <= n);
            let run = |v: &[f64]| -> [f64; BLOCK] { v[p..p + BLOCK].try_into().unwrap() };
            let (bax, bay, bdx, bdy) = (run(ax), run(ay), run(dx), run(dy));
            let (bbx, bby, bolo, bohi) = (run(bx), run(by), run(olo), run(ohi));
            // Bit l: lane l is a certified proper crossing / is undecided.
            let (mut crossing_lanes, mut open_lanes) = (0u32, 0u32);
            for l in 0..BLOCK {
                // orient(a.a, a.b, b.a), orient(a.a, a.b, b.b), orient(b.a, b.b, a.a),
                // orient(b.a, b.b, a.b), each (q - p) × (r - p) as orient_static has it.
                let o1 = adx * (bay[l] - aay) - ady * (bax[l] - aax);
                let o2 = adx * (bby[l] - aay) - ady * (bbx[l] - aax);
                let o3 = bdx[l] * (aay - bay[l]) - bdy[l] * (aax - bax[l]);
                let o4 = bdx[l] * (aby - bay[l]) - bdy[l] * (abx - bax[l]);
                // Both certified on one side: the smaller above the bound, or the larger
                // below its negative; certified on both sides: the smaller below the
                // negative bound and the larger above it. (Plain selects: min/max
                // instructions.)
                let (lo12, hi12) = if o1 < o2 { (o1, o2) } else { (o2, o1) };
                let (lo34, hi34) = if o3 < o4 { (o3, o4) } else { (o4, o3) };
                let apart = (lo12 > bound) | (hi12 < -bound) | (lo34 > bound) | (hi34 < -bound);
                let crossing = (lo12 < -bound) & (hi12 > bound) & (lo34 < -bound) & (hi34 > bound);
                // The boxes also overlap along the other axis.
                let live = (bolo[l] <= aohi) & (aolo <= bohi[l]);
                crossing_lanes |= u32::from(live & crossing) << l;
                open_lanes |= u32::from(live & !crossing & !apart) << l;
            }
            // Only the lanes in range.
            let valid = (1u32 << m) - 1;
            let (mut crossing_lanes, mut open_lanes) = (crossing_lanes & valid, open_lanes & valid);
            while crossing_lanes != 0 {
                let l = crossing_lanes.trailing_zeros() as usize;
                crossing_lanes &= crossing_lanes - 1;
                sink.cross(sweep.items[p + l].id as usize);
            }
            while open_lanes != 0 {
                let l = open_lanes.trailing_zeros() as usize;
                open_lanes &= open_lanes - 1;
                sink.open(sweep.items[p + l].id as usize);
            }
            p += m;
        }
    }
}

/// What [`SweepLanes::scan_batched`] reports, segment by segment (input indices). A
/// trait rather than closures: its methods are inlined into the scan even where the scan
/// is compiled for wider vectors ([`wide`]); a closure would be compiled apart, without
/// the target features.
pub(crate) trait BatchSink {
    /// The unit's segment and `b` cross properly (certified).
    fn cross(&mut self, b: usize);
    /// The filter did not decide the unit's segment and `b`.
    fn open(&mut self, b: usize);
}

/// [`SweepLanes::scan_from_rounding`]'s sink: crossings of `a` rounded eight at a time
/// by `R`, undecided pairs tested exactly, into `found`.
struct Rounding<'a, R> {
    segments: &'a [Segment2],
    table: &'a [Prepared],
    bound: f64,
    a: usize,
    /// Crossings of `a` not yet rounded.
    mine: [usize; BLOCK],
    len: usize,
    found: &'a mut PairResults,
    rounding: std::marker::PhantomData<R>,
}

impl<R: RoundSharing> BatchSink for Rounding<'_, R> {
    #[inline(always)]
    fn cross(&mut self, b: usize) {
        self.mine[self.len] = b;
        self.len += 1;
        if self.len == BLOCK {
            let points = R::round(self.segments, self.table, self.a, &self.mine);
            self.found.push_rounded(&points, self.a, &self.mine);
            self.len = 0;
        }
    }

    #[inline(always)]
    fn open(&mut self, b: usize) {
        let (i, j) = (self.a.min(b), self.a.max(b));
        self.found.test(self.segments, self.table, i, j, self.bound);
    }
}

/// The candidate pairs of the pairwise method: from the grid, or from a sort and sweep
/// along one axis when that looks at fewer pairs (long segments).
pub(crate) struct Pairs {
    grid: Grid,
    sweep: Option<AxisSweep>,
}

/// The axis sweep is considered from this many grid candidates per segment on: below,
/// the grid is near one look per meeting pair and sorting would cost more than it saves.
const SWEEP_FROM_PER_SEGMENT: u64 = 16;

impl Pairs {
    /// The grid's pairs, or an axis sweep's when it looks at fewer (estimated from the
    /// boxes' extents first, so that the sort runs only when it is likely to pay).
    pub(crate) fn new(grid: Grid) -> Pairs {
        let n = grid.boxes.len() as u64;
        let candidates = grid.candidates();
        let mut sweep = None;
        if candidates > SWEEP_FROM_PER_SEGMENT * n {
            let axis = usize::from(axis_overlaps(&grid.boxes, 1) < axis_overlaps(&grid.boxes, 0));
            // (The estimate counts boundary buckets: it is high by up to about 2n.)
            if axis_overlaps(&grid.boxes, axis) < candidates + 2 * n {
                let s = AxisSweep::new(&grid.boxes, axis);
                if s.visits < candidates {
                    sweep = Some(s);
                }
            }
        }
        Pairs { grid, sweep }
    }

    /// The static orientation bound for the input ([`Grid::orient_bound`]).
    pub(crate) fn orient_bound(&self) -> f64 {
        self.grid.orient_bound
    }

    /// Whether the axis sweep was chosen.
    pub(crate) fn is_sweep(&self) -> bool {
        self.sweep.is_some()
    }

    /// The axis sweep whatever it costs (for tests of the paths that need it).
    #[cfg(test)]
    pub(crate) fn sweep_for_tests(segments: &[Segment2]) -> Pairs {
        let grid = Grid::new(segments);
        let sweep = AxisSweep::new(&grid.boxes, 1);
        Pairs {
            grid,
            sweep: Some(sweep),
        }
    }

    /// With the axis sweep, the segment of unit `k`: every pair [`Pairs::scan_from`]
    /// reports for `k` holds it (`None` on the grid, whose units are cell entries).
    pub(crate) fn unit_segment(&self, k: usize) -> Option<usize> {
        self.sweep.as_ref().map(|s| s.items[k].id as usize)
    }

    /// The number of scan units: [`Pairs::scan_from`] takes `0..` this.
    pub(crate) fn units(&self) -> usize {
        match &self.sweep {
            Some(s) => s.items.len(),
            None => self.grid.entry_count(),
        }
    }

    /// An upper bound on the pairs the scan tests exactly (the pairs it looks at).
    pub(crate) fn candidates(&self) -> u64 {
        match &self.sweep {
            Some(s) => s.visits,
            None => self.grid.candidates(),
        }
    }

    /// With the axis sweep, its segments laid out for the batched scan
    /// ([`SweepLanes::scan_from`]).
    pub(crate) fn sweep_lanes(&self, segments: &[Segment2]) -> Option<SweepLanes<'_>> {
        self.sweep.as_ref().map(|s| SweepLanes::new(s, segments))
    }

    /// The pairs unit `k` looks at.
    fn visits_of(&self, k: usize) -> u64 {
        match &self.sweep {
            Some(s) => s.visits_from[k],
            None => {
                let g = &self.grid;
                (g.start[g.cell_of[k] as usize + 1] - k - 1) as u64
            }
        }
    }

    /// Scan every unit on the rayon pool, in a few chunks of consecutive units that
    /// look at about as many pairs each (for the load balance), each chunk into its own
    /// accumulator `make(pairs the chunk looks at)` (to reserve room up front: no
    /// regrowth copies). The parts come in unit order.
    pub(crate) fn scan_parts<A: Send>(
        &self,
        make: impl Fn(u64) -> A + Sync,
        scan: impl Fn(usize, &mut A) + Sync,
    ) -> Vec<A> {
        // (One thread: one chunk, whose parts need no merging.)
        let threads = rayon::current_num_threads();
        let chunks = if threads == 1 { 1 } else { 8 * threads as u64 };
        let per = (self.candidates() / chunks).max(1);
        let mut ranges = Vec::new();
        let (mut from, mut visits) = (0, 0);
        for k in 0..self.units() {
            visits += self.visits_of(k);
            if visits >= per {
                ranges.push((from..k + 1, visits));
                (from, visits) = (k + 1, 0);
            }
        }
        if from < self.units() {
            ranges.push((from..self.units(), visits));
        }
        ranges
            .into_par_iter()
            .map(|(range, visits)| {
                let mut acc = make(visits);
                range.for_each(|k| scan(k, &mut acc));
                acc
            })
            .collect()
    }

    /// Call `f(i, j)` (`i < j`) for the pairs of unit `k`; over all units every pair of
    /// segments whose boxes overlap comes exactly once.
    #[inline]
    pub(crate) fn scan_from(&self, k: usize, f: impl FnMut(usize, usize)) {
        match &self.sweep {
            Some(s) => s.scan_from(k, f),
            None => self.grid.scan_from(k, f),
        }
    }
}

/// An estimate (from above, by about `2n`) of the pairs an [`AxisSweep`] along `axis`
/// looks at: for each box, the boxes whose lower ends fall within it, counted with a
/// histogram of the lower ends over `n` buckets. O(n).
fn axis_overlaps(boxes: &[[f64; 4]], axis: usize) -> u64 {
    let n = boxes.len();
    if n < 2 {
        return 0;
    }
    let (lo, hi) = boxes
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(x[2 * axis]), b.max(x[2 * axis + 1]))
        });
    let scale = if hi > lo && (hi - lo).is_finite() {
        n as f64 / (hi - lo)
    } else {
        0.0
    };
    // `as usize` saturates: monotone, within 0..n.
    let bucket = |v: f64| (((v - lo) * scale) as usize).min(n - 1);
    let mut prefix = vec![0u64; n + 1];
    for b in boxes {
        prefix[bucket(b[2 * axis]) + 1] += 1;
    }
    for k in 0..n {
        prefix[k + 1] += prefix[k];
    }
    // For each box, the boxes whose lower end is in its range, less itself: the pairs
    // the sweep looks at, plus those sharing the two end buckets (about 2 per box).
    boxes
        .iter()
        .map(|b| prefix[bucket(b[2 * axis + 1]) + 1] - prefix[bucket(b[2 * axis])] - 1)
        .sum()
}

/// The records to reserve for a scan of `candidates` pairs: at most one per pair (the
/// few overlaps add a second; the vector grows then), capped so that a huge bound does
/// not reserve much memory it will not use.
pub(super) fn reserve_for(candidates: u64) -> usize {
    candidates.min(1 << 22) as usize
}

/// Whether [`super::find_intersections`] should use the pairwise method: when the
/// candidate pairs are at most [`super::PAIRWISE_LIMIT_PER_SEGMENT`] times `n + K`, with
/// the number K of meeting pairs estimated from up to 64 segments spread over the input
/// (each tested against every candidate it has).
/// Returns the grid (for [`intersections_on`]) when the pairwise method is preferred.
pub(crate) fn prefer_pairwise(segments: &[Segment2]) -> Option<Grid> {
    let n = segments.len() as u64;
    let grid = Grid::new(segments);
    let candidates = grid.candidates();
    let limit = super::PAIRWISE_LIMIT_PER_SEGMENT as u64;
    if candidates <= limit.saturating_mul(n) {
        return Some(grid);
    }
    let samples = segments.len().min(64);
    let mut hits = 0u64;
    for k in 0..samples {
        let i = k * segments.len() / samples;
        let s = grid.span(&grid.boxes[i]);
        for cy in s[2]..=s[3] {
            for cx in s[0]..=s[1] {
                let c = cy * grid.n[0] + cx;
                for e in &grid.entries[grid.start[c]..grid.start[c + 1]] {
                    let j = e.id as usize;
                    let (a, b) = (&grid.boxes[i], &e.b);
                    let overlap = !(b[0] > a[1] || a[0] > b[1] || b[2] > a[3] || a[2] > b[3]);
                    let owned =
                        (e.cx.max(s[0] as u32), e.cy.max(s[2] as u32)) == (cx as u32, cy as u32);
                    if j != i && overlap && owned {
                        let meet = segment_intersection(segments[i], segments[j]);
                        hits += u64::from(meet != SegmentIntersection::None);
                    }
                }
            }
        }
    }
    // Each meeting pair has two segments.
    let estimate = hits * n / (2 * samples.max(1) as u64);
    (candidates <= limit.saturating_mul(n + estimate)).then_some(grid)
}

/// All intersection points and overlaps (the answer of [`super::find_intersections`]) by
/// exact tests of the pairs whose bounding boxes overlap.
///
/// ```
/// use compgeom::intersect::{pairwise_intersections, sweep_intersections};
/// use compgeom::Segment2;
/// let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
/// let segs = [s((0.0, 0.0), (2.0, 2.0)), s((0.0, 2.0), (2.0, 0.0)), s((1.0, 0.0), (1.0, 3.0))];
/// assert_eq!(pairwise_intersections(&segs).unwrap(), sweep_intersections(&segs).unwrap());
/// ```
pub fn pairwise_intersections(segments: &[Segment2]) -> Result<Intersections> {
    check_finite(segments)?;
    check_count(segments)?;
    Ok(intersections_on(segments, &Pairs::new(Grid::new(segments))))
}

/// [`prefer_pairwise`] with the candidate pairs chosen ([`Pairs::new`]).
pub(crate) fn prefer_pairs(segments: &[Segment2]) -> Option<Pairs> {
    prefer_pairwise(segments).map(Pairs::new)
}

/// [`pairwise_intersections`] on finite segments (fewer than 2^31) already bucketed.
pub(crate) fn intersections_on(segments: &[Segment2], pairs: &Pairs) -> Intersections {
    let bound = pairs.orient_bound();
    // The per-segment part of rounding crossings, once per segment (n) rather than once
    // per crossing (up to n²/2).
    let table = Prepared::table(segments);
    // (Two instantiations of the scan: the grid's keeps its own code.)
    match pairs.sweep_lanes(segments) {
        Some(lanes) => scan_with(segments, pairs, &table, |k, found| {
            lanes.scan_from(k, segments, &table, bound, found)
        }),
        None => scan_with(segments, pairs, &table, |k, found| {
            pairs.scan_from(k, |i, j| found.test(segments, &table, i, j, bound))
        }),
    }
}

/// [`intersections_on`] with `test(k, found)` testing the pairs of unit `k`.
#[inline]
fn scan_with(
    segments: &[Segment2],
    pairs: &Pairs,
    table: &[Prepared],
    test: impl Fn(usize, &mut PairResults) + Sync,
) -> Intersections {
    let scan = |k: usize, found: &mut PairResults| {
        test(k, found);
        found.flush(segments, table);
    };
    let candidates = pairs.candidates();
    let found = if candidates < PARALLEL_SCAN_FROM {
        let mut found = PairResults::with_capacity(reserve_for(candidates));
        (0..pairs.units()).for_each(|k| scan(k, &mut found));
        found
    } else {
        // Independent scans on the rayon pool; the grouping sorts everything, so the
        // result does not depend on how the work was split. The records go straight
        // into bins by y ([`super::bins`]), as many as about half the candidates need
        // (long random segments: half the pairs cross).
        let y_range = segments
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |r, s| {
                (r.0.min(s.a.y).min(s.b.y), r.1.max(s.a.y).max(s.b.y))
            });
        let bins = Bins::<()>::count_for(reserve_for(candidates / 2));
        let shares = crossing_shares(segments, y_range, bins);
        let make = |visits: u64| {
            let total = reserve_for(visits / 2) as f64;
            let even = 0.5 / bins as f64;
            PairResults::binned(y_range, bins, |b| {
                (total * (1.5 * shares[b] + even)) as usize + 4
            })
        };
        let parts = pairs.scan_parts(make, scan);
        return PairResults::assemble_parts(parts, segments);
    };
    found.assemble(segments)
}

/// Each of `bins` bins' share of the crossings (the layout of [`PairResults::binned`]
/// over `y_range`), estimated as proportional to the square of the number of segments
/// whose range of y meets the bin (the pairs that can cross there); even shares when no
/// segment has a range of y. O(n + bins).
///
/// The crossings are not spread evenly in y (long random 1e3: the fullest of 61 bins
/// holds 2.1 times the mean, the emptiest almost nothing), and half the candidate pairs
/// underestimates them (long random 1e3: 242k crossings of ~400k candidates). With room
/// for 1.25 times the mean in every bin, 17 of the 39 bins grew (a copy of each) per
/// `find`; with room for 1.5 times the estimated share plus half the mean (twice the
/// half-candidates in all), one. Session 26, long random 1e3, one thread: callgrind per
/// `find` 109.9M → 102.8M, driver best of 20 8.6 → 8.3–8.4 ms.
fn crossing_shares(segments: &[Segment2], y_range: (f64, f64), bins: usize) -> Vec<f64> {
    let layout = Bins::<()>::laid_out(-y_range.1, -y_range.0, bins, |_| 0);
    let mut starts = vec![0i64; bins + 1];
    for s in segments {
        let (lo, hi) = (s.a.y.min(s.b.y), s.a.y.max(s.b.y));
        // (Keys are -y: the bins run from the top down.)
        starts[layout.bin_of(-hi)] += 1;
        starts[layout.bin_of(-lo) + 1] -= 1;
    }
    let mut meeting = 0;
    let weights: Vec<f64> = starts[..bins]
        .iter()
        .map(|&d| {
            meeting += d;
            (meeting as f64).powi(2)
        })
        .collect();
    let sum: f64 = weights.iter().sum();
    if sum > 0.0 && sum.is_finite() {
        weights.iter().map(|w| w / sum).collect()
    } else {
        vec![1.0 / bins as f64; bins]
    }
}

/// The axis sweep's batched scan compiled a second time for x86-64 processors with AVX2
/// and FMA (nearly all since 2013), chosen at run time, with the rounding of
/// [`super::round`] inlined in its fused instantiation: the eight lanes of the static
/// filter and of the rounding in 256-bit registers. The same operations in the same
/// order (Rust does not reassociate or contract floating point), so the same bits; only
/// the instructions differ. Long random 1e3, one thread (callgrind): 142.9M → 131.3M
/// instructions per `find`. Compiled for AVX-512 instead it was slower (512-bit
/// registers, 15.0 against 14.3 ms); passing the rounding as a function value kept it
/// out of line, compiled without FMA (`mul_add` as a libm call): 17.5 ms.
///
/// The crate's other `unsafe` place is [`super::round`]'s `fma` module; the same
/// argument: sound exactly when the processor has the features, checked first.
#[cfg(target_arch = "x86_64")]
#[allow(unsafe_code)]
mod wide {
    use super::*;

    /// Whether the processor has every feature [`scan_from`]'s body is compiled for.
    #[inline]
    pub(super) fn available() -> bool {
        std::arch::is_x86_feature_detected!("avx2")
            && std::arch::is_x86_feature_detected!("fma")
            && std::arch::is_x86_feature_detected!("avx")
    }

    /// [`SweepLanes::scan_batched`] with wide vectors, where [`available`]; `false` (and
    /// nothing done) elsewhere.
    #[inline]
    pub(super) fn scan_batched<S: BatchSink>(
        lanes: &SweepLanes<'_>,
        k: usize,
        bound: f64,
        sink: &mut S,
    ) -> bool {
        #[target_feature(enable = "avx2,fma,avx")]
        unsafe fn wide<S: BatchSink>(lanes: &SweepLanes<'_>, k: usize, bound: f64, sink: &mut S) {
            lanes.scan_batched(k, bound, sink)
        }
        if !available() {
            return false;
        }
        // SAFETY: the processor has the features `wide` is compiled for.
        unsafe { wide(lanes, k, bound, sink) };
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point2;

    fn seg(a: (f64, f64), b: (f64, f64)) -> Segment2 {
        Segment2::new(Point2::new(a.0, a.1), Point2::new(b.0, b.1))
    }

    /// The wide instantiation of the axis sweep's scan reports exactly what the plain one
    /// does, on long segments (the axis sweep) with random and with degenerate
    /// crossings: integer ends on a small grid (crossings at input points, shared
    /// endpoints, collinear overlaps, undecided pairs for the exact test) and random
    /// ends scaled by awkward factors (crossings rounded near ties).
    #[test]
    #[cfg(target_arch = "x86_64")]
    fn the_wide_scan_reports_what_the_plain_one_does() {
        if !wide::available() {
            eprintln!("skipped: the processor has no AVX2/FMA");
            return;
        }
        let mut unit = crate::testing::units(11u64);
        for case in 0..6 {
            let scale = [1.0, 1.0 / 3.0, 1e-7, 7e9, 0.1, 1.0][case];
            let segs: Vec<Segment2> = (0..300)
                .map(|_| {
                    let (xa, xb) = ((unit() * 2.0).floor(), 8.0 - (unit() * 2.0).floor());
                    let (ya, yb) = if case % 2 == 0 {
                        ((unit() * 9.0).floor(), (unit() * 9.0).floor())
                    } else {
                        (unit() * 8.0, unit() * 8.0)
                    };
                    seg((xa * scale, ya * scale), (xb * scale, yb * scale))
                })
                .collect();
            let pairs = Pairs::new(Grid::new(&segs));
            let lanes = pairs
                .sweep_lanes(&segs)
                .expect("long segments: the axis sweep");
            let table = Prepared::table(&segs);
            let bound = pairs.orient_bound();
            let run = |wide: bool| {
                let mut found = PairResults::with_capacity(0);
                for k in 0..pairs.units() {
                    if wide {
                        let f = &mut found;
                        lanes.scan_from_rounding::<AlwaysFused>(k, &segs, &table, bound, f, true);
                    } else {
                        let f = &mut found;
                        lanes.scan_from_rounding::<Dispatched>(k, &segs, &table, bound, f, false);
                    }
                    found.flush(&segs, &table);
                }
                found.assemble(&segs)
            };
            let (plain, fast) = (run(false), run(true));
            assert!(
                plain.points.len() > 1000,
                "case {case}: {}",
                plain.points.len()
            );
            assert_eq!(plain, fast, "case {case}");
        }
    }

    #[test]
    fn the_choice_follows_candidates_and_meetings() {
        let mut unit = crate::testing::units(3u64);
        // Short segments: few candidates.
        let short: Vec<Segment2> = (0..5000)
            .map(|_| {
                let (x, y) = (unit(), unit());
                seg((x, y), (x + 0.01 * unit(), y + 0.01 * unit()))
            })
            .collect();
        assert!(prefer_pairwise(&short).is_some());
        let g = Grid::new(&short);
        assert!(g.candidates() < 20 * 5000, "{}", g.candidates());
        // Long parallel segments with nearly the same box: n²/2 candidates, no meetings.
        let parallel: Vec<Segment2> = (0..2500)
            .map(|i| seg((0.0, i as f64 * 0.01), (1000.0, 1000.0 + i as f64 * 0.01)))
            .collect();
        assert!(Grid::new(&parallel).candidates() > 3_000_000);
        assert!(prefer_pairwise(&parallel).is_none());
        // Stacked long segments whose boxes are thin: the grid separates them.
        let stacked: Vec<Segment2> = (0..2500)
            .map(|i| seg((0.0, i as f64 * 0.01), (1000.0, i as f64 * 0.01 + 0.5)))
            .collect();
        assert!(prefer_pairwise(&stacked).is_some());
        // Long crossing segments: as many candidates, but a quarter of them meet.
        let crossing: Vec<Segment2> = (0..2500)
            .map(|_| seg((0.0, unit()), (1.0, unit())))
            .collect();
        assert!(prefer_pairwise(&crossing).is_some());
    }

    /// The pairs of `segs` whose boxes overlap, by brute force.
    fn overlapping_boxes(segs: &[Segment2]) -> Vec<(usize, usize)> {
        let g = Grid::new(segs);
        let mut want = Vec::new();
        for i in 0..segs.len() {
            for j in i + 1..segs.len() {
                let (a, b) = (&g.boxes[i], &g.boxes[j]);
                if !(b[0] > a[1] || a[0] > b[1] || b[2] > a[3] || a[2] > b[3]) {
                    want.push((i, j));
                }
            }
        }
        want
    }

    /// The pairs an axis sweep looks at, sorted, after checking none comes twice and
    /// the visit count bounds them.
    fn swept(segs: &[Segment2], axis: usize) -> Vec<(usize, usize)> {
        let g = Grid::new(segs);
        let s = AxisSweep::new(&g.boxes, axis);
        let mut seen = Vec::new();
        for k in 0..s.items.len() {
            s.scan_from(k, |i, j| seen.push((i, j)));
        }
        assert!(seen.len() as u64 <= s.visits);
        assert!(axis_overlaps(&g.boxes, axis) >= s.visits);
        seen.sort_unstable();
        let n = seen.len();
        seen.dedup();
        assert_eq!(n, seen.len(), "a pair was swept twice");
        seen
    }

    proptest::proptest! {
        /// Degenerate boxes (integer grid: equal lower ends, nested and touching boxes,
        /// zero-length and axis-parallel segments, duplicates, -0.0): both axis sweeps
        /// look at exactly the pairs whose boxes overlap, each once.
        #[test]
        fn the_axis_sweep_scans_every_overlapping_box_pair_once(
            v in proptest::collection::vec((-3i32..4, -3i32..4, -3i32..4, -3i32..4), 0..40),
            negzero in proptest::bool::ANY,
        ) {
            let f = |k: i32| if k == 0 && negzero { -0.0 } else { k as f64 };
            let segs: Vec<Segment2> =
                v.iter().map(|&(a, b, c, d)| seg((f(a), f(b)), (f(c), f(d)))).collect();
            let want = overlapping_boxes(&segs);
            for axis in 0..2 {
                proptest::prop_assert_eq!(swept(&segs, axis), want.clone());
            }
        }
    }

    /// The pairwise answer with the axis sweep along `axis` forced (its batched scan).
    fn swept_answer(segs: &[Segment2], axis: usize) -> Intersections {
        let grid = Grid::new(segs);
        let sweep = AxisSweep::new(&grid.boxes, axis);
        intersections_on(
            segs,
            &Pairs {
                grid,
                sweep: Some(sweep),
            },
        )
    }

    proptest::proptest! {
        /// The batched scan of the axis sweep gives the brute-force answer on degenerate
        /// input: integer grids (shared endpoints, many segments through a point,
        /// collinear overlaps, duplicates, zero-length segments, -0.0), the same divided
        /// by 3, huge (the static bound is infinite: nothing is decided by it), tiny, and
        /// offset by 2^22 (orientations near the bound).
        #[test]
        fn the_batched_axis_sweep_scan_is_the_brute_force_answer(
            v in proptest::collection::vec((-3i32..4, -3i32..4, -3i32..4, -3i32..4), 0..40),
            how in 0u8..5,
        ) {
            let segs = super::super::brute_force::tests::grid_segments(&v, how);
            let want = super::super::brute_force_intersections(&segs).unwrap();
            for axis in 0..2 {
                proptest::prop_assert_eq!(swept_answer(&segs, axis), want.clone());
            }
        }
    }

    #[test]
    fn the_batched_scan_on_long_segments_is_the_brute_force_answer() {
        let mut unit = crate::testing::units(11u64);
        // Long random segments (most pairs cross), some through shared points, some
        // vertical and horizontal, some with boxes apart along the other axis.
        let mut segs: Vec<Segment2> = (0..300)
            .map(|_| seg((unit(), unit()), (unit(), unit())))
            .collect();
        segs.extend((0..20).map(|k| seg((0.5, 0.5), (k as f64 / 20.0, 1.0))));
        segs.extend((0..10).map(|k| seg((k as f64 / 10.0, 0.0), (k as f64 / 10.0, 1.0))));
        segs.extend((0..10).map(|k| seg((0.0, k as f64 / 10.0), (1.0, k as f64 / 10.0))));
        segs.push(seg((0.1, 0.2), (0.3, 0.4)));
        segs.push(seg((0.1, 0.2), (0.3, 0.4)));
        let want = super::super::brute_force_intersections(&segs).unwrap();
        for axis in 0..2 {
            assert_eq!(swept_answer(&segs, axis), want, "axis {axis}");
        }
        // More than the parallel threshold, so the scan runs in parallel parts too.
        let long: Vec<Segment2> = (0..1000)
            .map(|_| seg((0.0, unit()), (1.0, unit())))
            .collect();
        let pairs = Pairs::new(Grid::new(&long));
        assert!(pairs.is_sweep() && pairs.candidates() >= PARALLEL_SCAN_FROM);
        assert_eq!(
            intersections_on(&long, &pairs),
            super::super::brute_force_intersections(&long).unwrap()
        );
    }

    #[test]
    fn long_segments_use_the_axis_sweep() {
        let mut unit = crate::testing::units(7u64);
        let long: Vec<Segment2> = (0..400)
            .map(|_| seg((0.0, unit()), (1.0, unit())))
            .collect();
        let pairs = Pairs::new(Grid::new(&long));
        assert!(pairs.is_sweep());
        // It looks at fewer pairs than the grid, and at exactly the overlapping boxes.
        assert!(pairs.candidates() < Grid::new(&long).candidates());
        let mut seen = Vec::new();
        for k in 0..pairs.units() {
            pairs.scan_from(k, |i, j| seen.push((i, j)));
        }
        seen.sort_unstable();
        assert_eq!(seen, overlapping_boxes(&long));
        let short: Vec<Segment2> = (0..400)
            .map(|_| {
                let (x, y) = (unit(), unit());
                seg((x, y), (x + 0.01 * unit(), y + 0.01 * unit()))
            })
            .collect();
        assert!(!Pairs::new(Grid::new(&short)).is_sweep());
    }

    #[test]
    fn every_overlapping_box_pair_is_scanned_once() {
        let segs: Vec<Segment2> = (0..300)
            .map(|i| {
                let x = (i * 37 % 101) as f64;
                let y = (i * 53 % 97) as f64;
                seg((x, y), (x + (i % 7) as f64 * 3.0, y + (i % 5) as f64 * 4.0))
            })
            .collect();
        let g = Grid::new(&segs);
        let mut seen = Vec::new();
        for k in 0..g.entries.len() {
            g.scan_from(k, |i, j| seen.push((i, j)));
        }
        seen.sort_unstable();
        let n = seen.len();
        seen.dedup();
        assert_eq!(n, seen.len(), "a pair was scanned twice");
        let mut want = Vec::new();
        for i in 0..segs.len() {
            for j in i + 1..segs.len() {
                let (a, b) = (&g.boxes[i], &g.boxes[j]);
                if !(b[0] > a[1] || a[0] > b[1] || b[2] > a[3] || a[2] > b[3]) {
                    want.push((i, j));
                }
            }
        }
        assert_eq!(seen, want);
    }
}
