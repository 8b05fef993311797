//! A uniform grid over boxes, for the rounding check's search for near pairs.

use super::Box2;
use crate::kernel::steps::Steps;

/// A uniform grid over the boxes of the moved items (about two cells per item), each
/// item listed in the cells its box overlaps, except items over more than
/// [`ALWAYS_LISTED_CELLS`] cells where those would make more than [`ENTRIES_PER_ITEM`]
/// entries per item: then the largest of them are listed once, in `wide`, and met by
/// every query.
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
    wide: Vec<u32>,
    count: usize,
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

/// An item over at most this many cells is always listed in them.
const ALWAYS_LISTED_CELLS: usize = 64;

/// Items over more cells are listed too while the entries stay within this many per
/// item on average; past it, the largest of them are `wide` (items of one size alike),
/// as few as bring the others within it. (Listed, an item costs an entry per cell under
/// it, once; wide, a visit by every query. Dense results have small cells: edges of an
/// overlay of 2 × 10⁴ random squares spanned up to 399 cells, 6 per item on average,
/// and with every item over 64 cells wide, 26 706 of them were met by each of 1.6 M
/// queries.)
const ENTRIES_PER_ITEM: usize = 16;

/// A query over more cells than the items plus this many visits every item instead.
const ALL_ITEMS_BEYOND: usize = 64;

/// The most cells an item is listed in, when the items are over `cells[k]` cells each:
/// at least [`ALWAYS_LISTED_CELLS`], and beyond it the largest count such that all items
/// over at most that many cells make at most `budget` entries (`usize::MAX` when all of
/// them do).
fn most_cells_listed(mut cells: Vec<usize>, budget: usize) -> usize {
    if cells.iter().sum::<usize>() <= budget {
        return usize::MAX;
    }
    cells.sort_unstable();
    let (mut most, mut total) = (ALWAYS_LISTED_CELLS, 0);
    for run in cells.chunk_by(|a, b| a == b) {
        total += run[0] * run.len();
        if run[0] > ALWAYS_LISTED_CELLS {
            if total > budget {
                break;
            }
            most = run[0];
        }
    }
    most
}

impl Grid {
    pub(super) fn new(boxes: &[Box2]) -> Grid {
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
        // (A zero side gives steps that put everything in one: still monotone, so still
        // right, and the one cell that side needs.)
        let steps = |lo: f64, len: f64, n: usize| {
            let per_unit = n as f64 / len;
            let per_unit = if per_unit.is_finite() { per_unit } else { 0.0 };
            Steps::per_unit(lo, per_unit, n as u32)
        };
        let mut grid = Grid {
            xs: steps(x0, w, nx),
            ys: steps(y0, h, ny),
            sx,
            sy,
            nx,
            ny,
            extent,
            starts: Vec::new(),
            items: Vec::new(),
            wide: Vec::new(),
            count,
        };
        grid.fill(boxes);
        grid
    }

    /// The cell range of a box, clamped to the grid (monotone in the box's bounds, so
    /// boxes that overlap share a cell).
    fn range(&self, b: &Box2) -> (usize, usize, usize, usize) {
        let (xs, ys, sx, sy) = (&self.xs, &self.ys, self.sx, self.sy);
        (
            xs.index(b.x0 * sx),
            xs.index(b.x1 * sx),
            ys.index(b.y0 * sy),
            ys.index(b.y1 * sy),
        )
    }

    fn fill(&mut self, boxes: &[Box2]) {
        let nx = self.nx;
        let mut starts = vec![0u32; nx * self.ny + 1];
        // Each box's cells (half-open), found once for both passes (`None`: wide).
        let mut total = 0;
        let mut spans: Vec<Option<[u32; 4]>> = boxes
            .iter()
            .map(|b| {
                let (x0, x1, y0, y1) = self.range(b);
                total += (x1 - x0 + 1) * (y1 - y0 + 1);
                Some([x0 as u32, x1 as u32 + 1, y0 as u32, y1 as u32 + 1])
            })
            .collect();
        let budget = ENTRIES_PER_ITEM * boxes.len();
        if total > budget {
            let size = |s: &[u32; 4]| (s[1] - s[0]) as usize * (s[3] - s[2]) as usize;
            let most = most_cells_listed(spans.iter().flatten().map(size).collect(), budget);
            for span in &mut spans {
                if span.is_some_and(|s| size(&s) > most) {
                    *span = None;
                }
            }
        }
        // (Half-open ranges: an inclusive range checks for its end at every step.)
        let cells = |[x0, x1, y0, y1]: [u32; 4]| {
            (y0 as usize..y1 as usize)
                .flat_map(move |y| (x0 as usize..x1 as usize).map(move |x| y * nx + x))
        };
        for span in spans.iter().flatten() {
            for cell in cells(*span) {
                starts[cell + 1] += 1;
            }
        }
        for k in 1..starts.len() {
            starts[k] += starts[k - 1];
        }
        let mut at = starts.clone();
        let mut items = vec![0u32; starts[starts.len() - 1] as usize];
        let mut wide_items = Vec::new();
        for (item, span) in spans.iter().enumerate() {
            let Some(span) = span else {
                wide_items.push(item as u32);
                continue;
            };
            for cell in cells(*span) {
                let slot = &mut at[cell];
                items[*slot as usize] = item as u32;
                *slot += 1;
            }
        }
        self.starts = starts;
        self.items = items;
        self.wide = wide_items;
    }

    /// Calls `f` once for each item whose cells box `b` overlaps (and for each wide
    /// item), or for every item when `b` covers more cells than there are items;
    /// `stamp[item] == query` marks an item already met by this query. (Inlined: called
    /// for every point and edge of a result; as a call it cost the GEOS-837 dissolve
    /// about 1%.)
    #[inline(always)]
    pub(super) fn visit(
        &self,
        b: &Box2,
        query: usize,
        stamp: &mut [usize],
        mut f: impl FnMut(usize),
    ) {
        if !b.overlaps(&self.extent) {
            return;
        }
        let (x0, x1, y0, y1) = self.range(b);
        if (x1 - x0 + 1) * (y1 - y0 + 1) > self.count + ALL_ITEMS_BEYOND {
            (0..self.count).for_each(f);
            return;
        }
        for &item in &self.wide {
            f(item as usize);
        }
        if x0 == x1 && y0 == y1 {
            // (One cell: each item once, no marks needed.)
            let cell = y0 * self.nx + x0;
            let list = &self.items[self.starts[cell] as usize..self.starts[cell + 1] as usize];
            list.iter().for_each(|&item| f(item as usize));
            return;
        }
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
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each `step`-th box, as a query, is visited by exactly the boxes that overlap it
    /// (brute force), each once.
    fn assert_visits_every_overlapping_box(grid: &Grid, boxes: &[Box2], step: usize, round: usize) {
        let mut stamp = vec![usize::MAX; boxes.len()];
        for (q, b) in boxes.iter().enumerate().step_by(step) {
            let mut got = Vec::new();
            grid.visit(b, q, &mut stamp, |k| {
                if boxes[k].overlaps(b) {
                    got.push(k);
                }
            });
            got.sort_unstable();
            let want: Vec<usize> = (0..boxes.len()).filter(|&k| boxes[k].overlaps(b)).collect();
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
            let grid = Grid::new(&boxes);
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

    /// Boxes several cells across (dense short edges: cells are small) are listed in
    /// their cells, not met by every query: those over at most 64 cells always (equal
    /// boxes of 25 cells each, 27 entries per item: all listed), larger ones while the
    /// entries stay within the budget; past it the largest are wide, as few as needed.
    /// Either way each query is visited by every box that overlaps it, exactly once.
    #[test]
    fn boxes_over_many_cells_are_wide_only_past_the_budget() {
        let mut below = crate::testing::below(0x9_12d6);
        let budget = ENTRIES_PER_ITEM * 2000;
        // Per round: the boxes' side (`Some`: all alike), how many long diagonal boxes
        // among the 2 000, and whether some must be wide.
        let rounds = [
            (None, 40, 0, false),
            (None, 120, 0, false),
            (None, 40, 50, false),
            (None, 40, 400, true),
            (None, 400, 0, false),
            (Some(700.0), 0, 0, false),
            (Some(1000.0), 0, 0, false),
        ];
        for (round, &(alike, side, long, some_wide)) in rounds.iter().enumerate() {
            let count = 2000;
            let boxes: Vec<Box2> = (0..count)
                .map(|k| {
                    let (x, y) = (below(10_000) as f64, below(10_000) as f64);
                    let s = match alike {
                        Some(s) => s,
                        None if k < long => 5000.0,
                        None => (1 + below(side)) as f64,
                    };
                    Box2 {
                        x0: x,
                        x1: x + s,
                        y0: y,
                        y1: y + s,
                    }
                })
                .collect();
            let grid = Grid::new(&boxes);
            let sizes: Vec<usize> = boxes
                .iter()
                .map(|b| {
                    let (x0, x1, y0, y1) = grid.range(b);
                    (x1 - x0 + 1) * (y1 - y0 + 1)
                })
                .collect();
            let is_wide = |k: usize| grid.wide.contains(&(k as u32));
            // Items over at most 64 cells are listed, and the entries are within the
            // budget unless those alone pass it.
            let small: usize = sizes.iter().filter(|&&c| c <= ALWAYS_LISTED_CELLS).sum();
            let entries = grid.items.len();
            assert!(entries <= budget.max(small), "round {round}: {entries}");
            assert!(
                grid.wide
                    .iter()
                    .all(|&k| sizes[k as usize] > ALWAYS_LISTED_CELLS),
                "round {round}"
            );
            if let Some(smallest_wide) = grid.wide.iter().map(|&k| sizes[k as usize]).min() {
                // The wide ones are the largest (items of one size alike), and listing
                // those of the smallest wide size too would break the budget.
                let listed_most = (0..count).filter(|&k| !is_wide(k)).map(|k| sizes[k]).max();
                assert!(listed_most < Some(smallest_wide), "round {round}");
                let alike = (0..count).filter(|&k| sizes[k] == smallest_wide).count();
                assert!(entries + alike * smallest_wide > budget, "round {round}");
            }
            assert_eq!(!grid.wide.is_empty(), some_wide, "round {round}");
            assert_visits_every_overlapping_box(&grid, &boxes, 5, round);
        }
    }

    #[test]
    fn the_budget_lists_the_smallest_items() {
        // Within the budget: all listed.
        assert_eq!(most_cells_listed(vec![65, 65], 200), usize::MAX);
        // Items over at most 64 cells are listed past the budget, larger ones not.
        assert_eq!(most_cells_listed(vec![10; 100], 100), 64);
        assert_eq!(most_cells_listed(vec![70, 5], 10), 64);
        // Larger ones while they fit, items of one size alike.
        assert_eq!(most_cells_listed(vec![70, 100, 70, 5], 150), 70);
        assert_eq!(most_cells_listed(vec![70, 100, 70, 5], 144), 64);
        assert_eq!(most_cells_listed(vec![70, 100, 70, 5], 245), usize::MAX);
    }
}
