//! A uniform grid over boxes and long segments, for the rounding check's search for
//! near pairs.

use super::{Box2, ItemIndex};
use crate::kernel::steps::Steps;
use crate::kernel::Point2;

/// A uniform grid over the moved items (about two cells per item), each listed in the
/// cells its footprint overlaps: a box, or for a [`Line`] across many cells the cells
/// along it (its box would be most of the grid for a long diagonal edge: listed in all
/// of it, or met by every query, the search was quadratic on many long edges).
pub(super) struct Grid {
    xs: Steps,
    ys: Steps,
    /// The powers of two the coordinates are scaled by before their steps ([`prescale`]).
    sx: f64,
    sy: f64,
    nx: usize,
    ny: usize,
    extent: Box2,
    starts: Vec<u32>,
    items: Vec<u32>,
    /// Per segment item, whether it is listed along its length.
    long: Vec<bool>,
    count: usize,
}

/// Inclusive cell ranges `(x0, x1, y0, y1)`.
type Span = (usize, usize, usize, usize);

/// A segment widened by `pad` per axis (the points within `pad.0` of it in x and
/// `pad.1` in y): the footprint of an item whose box is `Box2::around(a, b, pad)`.
#[derive(Clone, Copy)]
pub(super) struct Line {
    pub(super) a: Point2,
    pub(super) b: Point2,
    pub(super) pad: (f64, f64),
}

/// Columns and rows for `count` items over an extent whose width is `ratio` times its
/// height: about two cells per item, cut in proportion to the sides, at most
/// `2 · count + 1` along either (so never more than about `4 · count + 3` cells). From
/// the sides' ratio, not their product or their sizes: at extreme scales (coordinates
/// near 1e-300 or subnormal) those under- or overflow, which once made grids of
/// billions of cells.
fn cells_for(ratio: f64, count: usize) -> (usize, usize) {
    let most = 2 * count + 1;
    let target = (2 * count.max(1)) as f64;
    if ratio.is_nan() {
        // (0 / 0, or both sides infinite: one cell. A negative side, for no boxes, makes
        // square roots of NaN below: one cell too.)
        return (1, 1);
    }
    // (`as usize` saturates: infinity gives the cap, zero one.)
    let along = |v: f64| (v.sqrt().ceil() as usize).clamp(1, most);
    (along(target * ratio), along(target / ratio))
}

/// A power of two that brings the side `lo..=hi` of an extent to a size whose steps
/// are finite: ½ where `hi − lo` overflows (coordinates near ±`f64::MAX` on both sides),
/// 2¹⁰⁰⁰ where it is positive and below 2⁻⁹⁰⁰ (subnormal coordinates: `count / side`
/// could overflow), else 1. Without it such an extent was one cell, and the search
/// quadratic. Scaling by a power of two is exact, or monotone where it under- or
/// overflows (a query far outside a tiny extent goes to ±∞, into the first or last
/// cell), so the cells stay monotone in the coordinates and overlapping boxes still
/// share one. (A positive side is at least a float gap of its ends, so scaled by
/// 2¹⁰⁰⁰ the ends stay far below the overflow.)
fn prescale(lo: f64, hi: f64) -> f64 {
    let side = hi - lo;
    if side == f64::INFINITY {
        0.5
    } else if side > 0.0 && side < 2f64.powi(-900) {
        2f64.powi(1000)
    } else {
        1.0
    }
}

/// A segment whose box spans more than this many cells along both axes is listed (and
/// looked up) along its length, not by its box.
const LINE_FROM_CELLS: usize = 2;

/// At most this many entries per item (and [`MOST_ENTRIES_BEYOND`]): where the
/// footprints cover more cells (many long edges, each across the grid), the grid is
/// made coarser, so that the memory stays linear; queries then meet more items per
/// cell, but no item is met by every query.
const MOST_ENTRIES_PER_ITEM: usize = 64;
const MOST_ENTRIES_BEYOND: usize = 1 << 24;

/// The most entries a grid (or [`super::tree::Tree`]) over `count` items may list (at
/// most `u32::MAX`: entries are counted in u32).
pub(super) fn most_entries(count: usize) -> usize {
    (MOST_ENTRIES_PER_ITEM * count + MOST_ENTRIES_BEYOND).min(u32::MAX as usize)
}

/// The relative error bound of the points [`Grid::line_ranges`] computes along a
/// segment (a few float gaps; 2⁻⁴⁸), and its absolute term (for subnormal coordinates).
const REL_ALONG: (f64, f64) = (1.0 / (1u64 << 48) as f64, f64::MIN_POSITIVE);

/// A query over more cells than the items plus this many visits every item instead.
const ALL_ITEMS_BEYOND: usize = 64;

/// What the grids over some boxes are laid on: the boxes' extent, the powers of two
/// the coordinates are scaled by ([`prescale`]), the scaled extent's corner and sides,
/// and the cells a grid starts with.
struct Frame {
    extent: Box2,
    sx: f64,
    sy: f64,
    x0: f64,
    y0: f64,
    w: f64,
    h: f64,
    nx: usize,
    ny: usize,
    count: usize,
}

impl Frame {
    fn of(boxes: &[Box2]) -> Frame {
        let mut extent = Box2 {
            x0: f64::INFINITY,
            x1: f64::NEG_INFINITY,
            y0: f64::INFINITY,
            y1: f64::NEG_INFINITY,
        };
        for b in boxes {
            extent.x0 = extent.x0.min(b.x0);
            extent.x1 = extent.x1.max(b.x1);
            extent.y0 = extent.y0.min(b.y0);
            extent.y1 = extent.y1.max(b.y1);
        }
        let count = boxes.len();
        // The steps span the finite coordinates: boxes widened outward from points
        // within a few floats of ±`f64::MAX` end at ±∞, which would stretch a side to
        // infinity (one cell); those ends go to the first or last cell, still in order.
        let (mut ex0, mut ex1, mut ey0, mut ey1) = (extent.x0, extent.x1, extent.y0, extent.y1);
        if [ex0, ex1, ey0, ey1].iter().any(|v| v.is_infinite()) && count > 0 {
            (ex0, ex1, ey0, ey1) = (
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::INFINITY,
                f64::NEG_INFINITY,
            );
            for b in boxes {
                for x in [b.x0, b.x1].into_iter().filter(|v| v.is_finite()) {
                    (ex0, ex1) = (ex0.min(x), ex1.max(x));
                }
                for y in [b.y0, b.y1].into_iter().filter(|v| v.is_finite()) {
                    (ey0, ey1) = (ey0.min(y), ey1.max(y));
                }
            }
        }
        let (sx, sy) = (prescale(ex0, ex1), prescale(ey0, ey1));
        let (x0, y0) = (ex0 * sx, ey0 * sy);
        let (w, h) = (ex1 * sx - x0, ey1 * sy - y0);
        // (The ratio of the true sides, w / sx over h / sy.)
        let (nx, ny) = cells_for(w / h * (sy / sx), count);
        Frame {
            extent,
            sx,
            sy,
            x0,
            y0,
            w,
            h,
            nx,
            ny,
            count,
        }
    }

    /// The grid of `nx` × `ny` cells over the frame, or `None` where it would list more
    /// than `most` entries ([`Grid::fill`]).
    fn grid(
        &self,
        nx: usize,
        ny: usize,
        boxes: &[Box2],
        segments: usize,
        line_of: &impl Fn(usize) -> Line,
        most: usize,
    ) -> Option<Grid> {
        // (A zero side gives steps that put everything in one: still monotone, so still
        // right, and the one cell that side needs.)
        let steps = |lo: f64, len: f64, n: usize| {
            let per_unit = n as f64 / len;
            let per_unit = if per_unit.is_finite() { per_unit } else { 0.0 };
            Steps::per_unit(lo, per_unit, n as u32)
        };
        let mut grid = Grid {
            xs: steps(self.x0, self.w, nx),
            ys: steps(self.y0, self.h, ny),
            sx: self.sx,
            sy: self.sy,
            nx,
            ny,
            extent: self.extent,
            starts: Vec::new(),
            items: Vec::new(),
            long: Vec::new(),
            count: self.count,
        };
        grid.fill(boxes, segments, line_of, most).then_some(grid)
    }
}

impl Grid {
    /// The grid of the items with boxes `boxes`, the first `segments` of them segments
    /// `line_of(k)` (`boxes[k]` is `Box2::around(l.a, l.b, l.pad)` for `l = line_of(k)`;
    /// asked only for those whose boxes span many cells).
    pub(super) fn new(boxes: &[Box2], segments: usize, line_of: impl Fn(usize) -> Line) -> Grid {
        Grid::at_most(boxes, segments, line_of, most_entries(boxes.len()))
    }

    /// The most items any one cell lists.
    pub(super) fn fullest_cell(&self) -> usize {
        self.starts
            .windows(2)
            .map(|w| (w[1] - w[0]) as usize)
            .max()
            .unwrap_or(0)
    }

    /// How many items the cells of `points` list in all (each point's own cell; points
    /// outside the items' extent none): about how many items a search of the points
    /// meets.
    pub(super) fn listed_at(&self, points: &[Point2]) -> usize {
        let e = &self.extent;
        points
            .iter()
            .filter(|p| e.x0 <= p.x && p.x <= e.x1 && e.y0 <= p.y && p.y <= e.y1)
            .map(|p| {
                let x = self.xs.index(p.x * self.sx);
                let y = self.ys.index(p.y * self.sy);
                let cell = y * self.nx + x;
                (self.starts[cell + 1] - self.starts[cell]) as usize
            })
            .sum()
    }

    /// [`Grid::new`] with at most `most` entries (unless in one cell).
    fn at_most(
        boxes: &[Box2],
        segments: usize,
        line_of: impl Fn(usize) -> Line,
        most: usize,
    ) -> Grid {
        let frame = Frame::of(boxes);
        let (mut nx, mut ny) = (frame.nx, frame.ny);
        loop {
            // (One cell holds each item once, whatever the bound.)
            let most = if nx * ny == 1 { usize::MAX } else { most };
            if let Some(grid) = frame.grid(nx, ny, boxes, segments, &line_of, most) {
                return grid;
            }
            // Too many entries: half as many cells per axis, a quarter in all (long
            // footprints then cover about half as many).
            (nx, ny) = (nx.div_ceil(2), ny.div_ceil(2));
        }
    }

    /// The grid [`Grid::new`] tries first (about two cells per item), or `None` where it
    /// would list more than `most` entries.
    pub(super) fn first_at_most(
        boxes: &[Box2],
        segments: usize,
        line_of: impl Fn(usize) -> Line,
        most: usize,
    ) -> Option<Grid> {
        let frame = Frame::of(boxes);
        frame.grid(frame.nx, frame.ny, boxes, segments, &line_of, most)
    }

    /// The cell range of a box, clamped to the grid (monotone in the box's bounds, so
    /// boxes that overlap share a cell).
    fn range(&self, b: &Box2) -> Span {
        let (xs, ys, sx, sy) = (&self.xs, &self.ys, self.sx, self.sy);
        (
            xs.index(b.x0 * sx),
            xs.index(b.x1 * sx),
            ys.index(b.y0 * sy),
            ys.index(b.y1 * sy),
        )
    }

    /// Whether a segment whose box spans the cells `span` (as [`Grid::range`] gives
    /// them) is listed or looked up along its length ([`Grid::line_ranges`]).
    fn span_is_long((x0, x1, y0, y1): Span) -> bool {
        (x1 - x0).min(y1 - y0) >= LINE_FROM_CELLS
    }

    /// Calls `f` with cell ranges (as [`Grid::range`] gives them) that together hold
    /// every cell the segment `a b` widened by `pad` meets, where its box spans `whole`
    /// (long, [`Grid::span_is_long`]): those of the boxes of pieces of it, one or two
    /// cells long each (its box's where the segment's sides overflow).
    ///
    /// The pieces end at the points computed at `k / m` of the way (`a` and `b` exactly
    /// at the ends), within [`REL_ALONG`] of the exact ones per axis; so each exact piece
    /// lies in the box of the computed ends widened by that, and the widened segment in
    /// the union of those boxes widened by `pad` too.
    fn line_ranges(&self, l: &Line, whole: Span, mut f: impl FnMut(Span)) {
        let Line { a, b, pad } = *l;
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        if !(dx.is_finite() && dy.is_finite()) {
            f(whole);
            return;
        }
        let (x0, x1, y0, y1) = whole;
        let m = (x1 - x0).max(y1 - y0) + 1;
        let (rel, abs) = REL_ALONG;
        let pad = (
            // (Each end scaled on its own: their sum can overflow.)
            pad.0 + a.x.abs() * rel + b.x.abs() * rel + abs,
            pad.1 + a.y.abs() * rel + b.y.abs() * rel + abs,
        );
        let mut p = a;
        for k in 1..=m {
            let q = if k == m {
                b
            } else {
                let t = k as f64 / m as f64;
                Point2::new(a.x + dx * t, a.y + dy * t)
            };
            f(self.range(&Box2::around(p, q, pad)));
            p = q;
        }
    }

    /// Calls `f(cell)` once for each cell of item `k`'s footprint, whose box spans
    /// `span`; `last[cell]` marks the long item last listed there (items come in
    /// increasing order; a box's cells are distinct, a line's pieces share some).
    fn cells_of(
        &self,
        k: usize,
        span: Span,
        line_of: impl Fn(usize) -> Line,
        last: &mut [u32],
        mut f: impl FnMut(usize),
    ) {
        let nx = self.nx;
        if !self.is_long(k) {
            let (x0, x1, y0, y1) = span;
            for y in y0..y1 + 1 {
                for x in x0..x1 + 1 {
                    f(y * nx + x);
                }
            }
            return;
        }
        self.line_ranges(&line_of(k), span, |(x0, x1, y0, y1)| {
            for y in y0..y1 + 1 {
                for x in x0..x1 + 1 {
                    let cell = y * nx + x;
                    if last[cell] != k as u32 {
                        last[cell] = k as u32;
                        f(cell);
                    }
                }
            }
        });
    }

    /// Lists each item in the cells of its footprint; false (and nothing listed) when
    /// that would make more than `most` entries.
    fn fill(
        &mut self,
        boxes: &[Box2],
        segments: usize,
        line_of: &impl Fn(usize) -> Line,
        most: usize,
    ) -> bool {
        let spans: Vec<Span> = boxes.iter().map(|b| self.range(b)).collect();
        self.long = (0..segments)
            .map(|k| Grid::span_is_long(spans[k]))
            .collect();
        let cells = self.nx * self.ny;
        let mut starts = vec![0u32; cells + 1];
        let mut last = vec![u32::MAX; if self.long.contains(&true) { cells } else { 0 }];
        let mut total = 0;
        for (k, &span) in spans.iter().enumerate() {
            self.cells_of(k, span, line_of, &mut last, |cell| {
                starts[cell + 1] += 1;
                total += 1;
            });
            if total > most {
                return false;
            }
        }
        for k in 1..starts.len() {
            starts[k] += starts[k - 1];
        }
        let mut at = starts.clone();
        let mut items = vec![0u32; total];
        last.fill(u32::MAX);
        for (k, &span) in spans.iter().enumerate() {
            self.cells_of(k, span, line_of, &mut last, |cell| {
                let slot = &mut at[cell];
                items[*slot as usize] = k as u32;
                *slot += 1;
            });
        }
        self.starts = starts;
        self.items = items;
        true
    }

    /// Calls `f` for each item `stamp` does not mark for `query` in the cells of
    /// `(x0, x1, y0, y1)`, marking it.
    #[inline(always)]
    fn visit_cells(
        &self,
        (x0, x1, y0, y1): Span,
        query: usize,
        stamp: &mut [usize],
        f: &mut impl FnMut(usize),
    ) {
        for y in y0..y1 + 1 {
            for x in x0..x1 + 1 {
                let cell = y * self.nx + x;
                let list = &self.items[self.starts[cell] as usize..self.starts[cell + 1] as usize];
                for &item in list {
                    let item = item as usize;
                    if stamp[item] != query {
                        stamp[item] = query;
                        f(item);
                    }
                }
            }
        }
    }

    /// [`Grid::visit`] of the cells `span`.
    #[inline(always)]
    fn visit_span(&self, span: Span, query: usize, stamp: &mut [usize], mut f: impl FnMut(usize)) {
        let (x0, x1, y0, y1) = span;
        if (x1 - x0 + 1) * (y1 - y0 + 1) > self.count + ALL_ITEMS_BEYOND {
            (0..self.count).for_each(f);
            return;
        }
        if x0 == x1 && y0 == y1 {
            // (One cell: each item once, no marks needed.)
            let cell = y0 * self.nx + x0;
            let list = &self.items[self.starts[cell] as usize..self.starts[cell + 1] as usize];
            list.iter().for_each(|&item| f(item as usize));
            return;
        }
        self.visit_cells((x0, x1, y0, y1), query, stamp, &mut f);
    }
}

impl ItemIndex for Grid {
    /// Whether item `k` (a segment) is listed along its length: its box holds many cells
    /// it does not meet.
    fn is_long(&self, k: usize) -> bool {
        self.long.get(k).is_some_and(|&l| l)
    }

    /// Calls `f` once for each item listed in a cell that box `b` overlaps (every item
    /// whose footprint meets `b`, and others), or for every item when `b` covers more
    /// cells than there are items; `stamp[item] == query` marks an item already met by
    /// this query. (Inlined: called for every point and edge of a result; as a call it
    /// cost the GEOS-837 dissolve about 1%.)
    #[inline(always)]
    fn visit(&self, b: &Box2, query: usize, stamp: &mut [usize], f: impl FnMut(usize)) {
        if !b.overlaps(&self.extent) {
            return;
        }
        self.visit_span(self.range(b), query, stamp, f);
    }

    /// [`Grid::visit`] for the segment `a b` (whose box is `bx`), along it where it is
    /// long: every item whose footprint meets the segment is met (and others), not
    /// every one in its box. `f(item, long)` says whether it was looked up along its
    /// length.
    #[inline(always)]
    fn visit_segment(
        &self,
        a: Point2,
        b: Point2,
        bx: &Box2,
        query: usize,
        stamp: &mut [usize],
        mut f: impl FnMut(usize, bool),
    ) {
        if !bx.overlaps(&self.extent) {
            return;
        }
        let span = self.range(bx);
        if !Grid::span_is_long(span) {
            self.visit_span(span, query, stamp, |k| f(k, false));
            return;
        }
        let line = Line {
            a,
            b,
            pad: (0.0, 0.0),
        };
        self.line_ranges(&line, span, |range| {
            self.visit_cells(range, query, stamp, &mut |k| f(k, true));
        });
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::super::{fat_segment_meets_box, segment_meets_box};
    use super::*;

    /// A search's `visit(query box, query number, stamp, f)`.
    pub(in super::super) type Visit<'a> =
        dyn Fn(&Box2, usize, &mut [usize], &mut dyn FnMut(usize)) + 'a;

    fn visits(grid: &Grid) -> impl Fn(&Box2, usize, &mut [usize], &mut dyn FnMut(usize)) + '_ {
        |b, q, stamp, f| grid.visit(b, q, stamp, f)
    }

    /// Each `step`-th box, as a query, is visited by exactly the boxes that overlap it
    /// (brute force), each once.
    fn assert_visits_every_overlapping_box(grid: &Grid, boxes: &[Box2], step: usize, round: usize) {
        assert_visits_every_footprint(&visits(grid), boxes, &[], boxes, step, round);
    }

    /// Each `step`-th query box is visited by every item whose footprint meets it
    /// (brute force: boxes overlap, and the widened segment meets the query for a
    /// line), each once.
    pub(in super::super) fn assert_visits_every_footprint(
        visit: &Visit,
        boxes: &[Box2],
        lines: &[Line],
        queries: &[Box2],
        step: usize,
        round: usize,
    ) {
        let meets = |k: usize, q: &Box2| {
            boxes[k].overlaps(q)
                && lines
                    .get(k)
                    .map_or(true, |l| fat_segment_meets_box(l.a, l.b, l.pad, q))
        };
        let mut stamp = vec![usize::MAX; boxes.len()];
        for (q, b) in queries.iter().enumerate().step_by(step) {
            let mut got = Vec::new();
            let mut seen = vec![false; boxes.len()];
            visit(b, q, &mut stamp, &mut |k| {
                assert!(!seen[k], "round {round}, query {q}: {k} twice");
                seen[k] = true;
                if meets(k, b) {
                    got.push(k);
                }
            });
            got.sort_unstable();
            let want: Vec<usize> = (0..boxes.len()).filter(|&k| meets(k, b)).collect();
            assert_eq!(got, want, "round {round}, query {q}");
        }
    }

    /// The grid keeps about two cells per item at every scale (coordinates near 1e-300,
    /// subnormal ones, near 1e300, from near −`f64::MAX` to near `f64::MAX`, extents
    /// flat in x or in y, all boxes on one point): never more than `4 · count + 3`
    /// cells, where the product or the quotients of the sides once under- or overflowed
    /// into grids of billions of cells, and, but for the boxes on one point, at least
    /// one per item, where a subnormal or overflowing extent once made one cell (and the
    /// search quadratic). And each query meets every box that overlaps it.
    #[test]
    fn cells_stay_about_two_per_item_at_every_scale() {
        let mut below = crate::testing::below(0x9_12d5);
        type Scale = fn(u64) -> f64;
        // (Coordinates 0 to about 100 300 apart from the scales' origins.)
        let huge: Scale = |k| (k as f64 - 50_150.0) * 3.5e303;
        let scales: [(Scale, Scale); 9] = [
            (|k| k as f64, |k| k as f64),
            (|k| k as f64 * 1e-300, |k| k as f64 * 1e-300),
            (|k| f64::from_bits(k * 1000), |k| f64::from_bits(k * 1000)),
            (|k| k as f64 * 1e300, |k| k as f64 * 1e300),
            (|k| k as f64, |k| k as f64 * 1e-300),
            (|k| f64::from_bits(k), |k| k as f64),
            (huge, huge),
            (huge, |k| f64::from_bits(k)),
            (|_| 3.0, |_| 3.0),
        ];
        let one_point = scales.len() - 1;
        // (And the scales near ±`f64::MAX` again, with one box ending at +∞ in x and one
        // at −∞ in y, as boxes widened outward from points next to `f64::MAX` do.)
        let rounds = scales.iter().chain(&scales[6..8]).enumerate();
        for (round, &(sx, sy)) in rounds {
            let count = 500;
            let mut boxes: Vec<Box2> = (0..count)
                .map(|_| {
                    let (x, y) = (below(100_000), below(100_000));
                    let (w, h) = (below(300), below(300));
                    Box2 {
                        x0: sx(x),
                        x1: sx(x + w),
                        y0: sy(y),
                        y1: sy(y + h),
                    }
                })
                .collect();
            if round > one_point {
                boxes[0].x1 = f64::INFINITY;
                boxes[1].y0 = f64::NEG_INFINITY;
            }
            let grid = Grid::new(&boxes, 0, |_| unreachable!());
            let cells = grid.nx * grid.ny;
            // (The boxes are about 1/300 of the extent per side: a few in a cell.)
            let fullest = grid.starts.windows(2).map(|w| w[1] - w[0]).max();
            assert!(
                cells <= 4 * count + 3
                    && (round == one_point || cells >= count && fullest < Some(20)),
                "round {round}: {} x {}, at most {fullest:?} in a cell",
                grid.nx,
                grid.ny
            );
            assert_visits_every_overlapping_box(&grid, &boxes, 7, round);
        }
    }

    /// Random segments: long ones at every angle (axis-parallel, steep, flat), short
    /// ones and points, widened by pads from nothing to a few units.
    pub(in super::super) fn random_lines(
        below: &mut impl FnMut(u64) -> u64,
        count: usize,
    ) -> Vec<Line> {
        (0..count)
            .map(|k| {
                let a = Point2::new(below(10_000) as f64, below(10_000) as f64);
                let len = match k % 4 {
                    0 => 0,
                    1 => 30,
                    _ => 9_000,
                };
                let (dx, dy) = match k % 7 {
                    0 => (below(len + 1) as f64, 0.0),
                    1 => (0.0, below(len + 1) as f64),
                    2 => (below(len + 1) as f64, below(8) as f64),
                    _ => (
                        below(2 * len + 1) as f64 - len as f64,
                        below(2 * len + 1) as f64 - len as f64,
                    ),
                };
                let pad = (below(4) as f64 * 0.75, below(4) as f64 * 0.5);
                Line {
                    a,
                    b: Point2::new(a.x + dx, a.y + dy),
                    pad,
                }
            })
            .collect()
    }

    /// Long segments are listed along their length, not in every cell of their boxes
    /// (long diagonal edges over most of the grid once made it quadratic), and each
    /// query meets every item whose footprint meets it, once: point-sized queries,
    /// larger boxes, and segments looked up along their length ([`Grid::visit_segment`],
    /// against items that are boxes, as the search uses it).
    #[test]
    fn long_segments_are_listed_along_their_length() {
        let mut below = crate::testing::below(0x9_12d7);
        // Per round, the coordinates as units, near 1e-300, and 3e15 from the origin
        // (where the points along a segment round to integers).
        for (round, (offset, scale)) in [(0.0, 1.0), (0.0, 1.0), (0.0, 1e-300), (3e15, 1.0)]
            .into_iter()
            .enumerate()
        {
            let at = |q: Point2| Point2::new(offset + q.x * scale, offset + q.y * scale);
            let lines: Vec<Line> = random_lines(&mut below, 600)
                .iter()
                .map(|l| Line {
                    a: at(l.a),
                    b: at(l.b),
                    pad: (l.pad.0 * scale, l.pad.1 * scale),
                })
                .collect();
            let mut boxes: Vec<Box2> = lines
                .iter()
                .map(|l| Box2::around(l.a, l.b, l.pad))
                .collect();
            // (And small boxes, as the moved points are.)
            for _ in 0..600 {
                let c = at(Point2::new(below(10_000) as f64, below(10_000) as f64));
                let s = below(20) as f64 * scale;
                boxes.push(Box2 {
                    x0: c.x,
                    x1: c.x + s,
                    y0: c.y,
                    y1: c.y + s,
                });
            }
            let grid = Grid::new(&boxes, lines.len(), |k| lines[k]);
            // Entries: a few per cell along each long footprint, where its box holds
            // hundreds of cells.
            let mut entries = vec![0; boxes.len()];
            for &k in &grid.items {
                entries[k as usize] += 1;
            }
            let mut long = 0;
            for (k, b) in boxes.iter().enumerate() {
                let (x0, x1, y0, y1) = grid.range(b);
                let (w, h) = (x1 - x0 + 1, y1 - y0 + 1);
                if w.min(h) >= 10 {
                    long += 1;
                    assert!(
                        entries[k] <= 4 * (w + h) && 3 * entries[k] < w * h,
                        "round {round}: item {k} in {} cells, over {w} x {h}",
                        entries[k]
                    );
                }
            }
            assert!(long >= 20, "round {round}: {long} long items");
            let mut queries: Vec<Box2> = (0..3000)
                .map(|_| {
                    let (x, y) = (below(10_400) as f64 - 200.0, below(10_400) as f64 - 200.0);
                    let c = at(Point2::new(x, y));
                    let s = [0.0, 0.5, 3.0, 40.0][below(4) as usize] * scale;
                    Box2 {
                        x0: c.x,
                        x1: c.x + s,
                        y0: c.y,
                        y1: c.y + s * 0.5,
                    }
                })
                .collect();
            queries.extend_from_slice(&boxes);
            assert_visits_every_footprint(&visits(&grid), &boxes, &lines, &queries, 1, round);
            // Segments as queries, against the items that are boxes.
            let mut stamp = vec![usize::MAX; boxes.len()];
            for (q, s) in random_lines(&mut below, 400).iter().enumerate() {
                let s = Line {
                    a: at(s.a),
                    b: at(s.b),
                    pad: (0.0, 0.0),
                };
                let bx = Box2::around(s.a, s.b, (0.0, 0.0));
                let mut got = Vec::new();
                grid.visit_segment(s.a, s.b, &bx, q, &mut stamp, |k, _| {
                    if k >= lines.len() && segment_meets_box(s.a, s.b, &boxes[k]) {
                        got.push(k);
                    }
                });
                got.sort_unstable();
                let want: Vec<usize> = (lines.len()..boxes.len())
                    .filter(|&k| segment_meets_box(s.a, s.b, &boxes[k]))
                    .collect();
                assert_eq!(got, want, "round {round}, segment {q}");
            }
        }
    }

    /// Where the footprints would make more entries than allowed (many long edges
    /// across the grid), the grid is made coarser until they fit; every query still
    /// meets every item whose footprint meets it.
    #[test]
    fn too_many_entries_make_the_grid_coarser() {
        let mut below = crate::testing::below(0x9_12d8);
        // Long horizontal edges, one above the other, across the extent, and long
        // diagonal ones (listed along their length).
        let mut lines: Vec<Line> = (0..2000)
            .map(|k| Line {
                a: Point2::new(below(100) as f64, 5.0 * k as f64),
                b: Point2::new(
                    9_900.0 + below(100) as f64,
                    5.0 * k as f64 + below(3) as f64,
                ),
                pad: (0.5, 0.5),
            })
            .collect();
        lines.extend((0..300).map(|_| {
            let a = Point2::new(below(2000) as f64, below(2000) as f64);
            let (dx, dy) = (7_000.0 + below(500) as f64, 6_000.0 + below(2000) as f64);
            Line {
                a,
                b: Point2::new(a.x + dx, a.y + dy),
                pad: (0.25, 0.75),
            }
        }));
        let boxes: Vec<Box2> = lines
            .iter()
            .map(|l| Box2::around(l.a, l.b, l.pad))
            .collect();
        let fine = Grid::at_most(&boxes, lines.len(), |k| lines[k], usize::MAX);
        let most = fine.items.len() / 5;
        let coarse = Grid::at_most(&boxes, lines.len(), |k| lines[k], most);
        assert!(coarse.items.len() <= most, "{} entries", coarse.items.len());
        assert!(coarse.nx * coarse.ny < fine.nx * fine.ny);
        // (The diagonal ones are long on both grids.)
        assert!((2000..lines.len()).all(|k| fine.is_long(k) && coarse.is_long(k)));
        let queries: Vec<Box2> = (0..4000)
            .map(|_| {
                let (x, y) = (below(10_000) as f64, below(10_000) as f64);
                Box2 {
                    x0: x,
                    x1: x + 1.0,
                    y0: y,
                    y1: y + 1.0,
                }
            })
            .collect();
        for (round, grid) in [fine, coarse].iter().enumerate() {
            assert_visits_every_footprint(&visits(grid), &boxes, &lines, &queries, 1, round);
        }
        // At most one cell: every item, whatever the bound.
        let one = Grid::at_most(&boxes, lines.len(), |k| lines[k], 0);
        assert_eq!((one.nx, one.ny, one.items.len()), (1, 1, boxes.len()));
    }
}
