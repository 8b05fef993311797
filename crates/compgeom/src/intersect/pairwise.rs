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
//! O(n + m + K log K) time for m candidate pairs (pairs sharing a cell) and K meeting
//! pairs; O(n + K) space. It beats the sweep whenever m is not much larger than n + K
//! (short segments, grids, dense crossings), and loses when many long segments share
//! cells without meeting; [`super::find_intersections`] decides between the two from m
//! and an estimate of K ([`prefer_pairwise`]).

use super::brute_force::{check_count, PairResults};
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
        let boxes: Vec<[f64; 4]> = segments
            .iter()
            .map(|s| {
                [
                    s.a.x.min(s.b.x),
                    s.a.x.max(s.b.x),
                    s.a.y.min(s.b.y),
                    s.a.y.max(s.b.y),
                ]
            })
            .collect();
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
    Ok(intersections_on(segments, &Grid::new(segments)))
}

/// [`pairwise_intersections`] on finite segments (fewer than 2^31) already bucketed.
pub(crate) fn intersections_on(segments: &[Segment2], grid: &Grid) -> Intersections {
    let scan = |k: usize, found: &mut PairResults| {
        grid.scan_from(k, |i, j| found.test(segments, i, j, grid.orient_bound));
    };
    let candidates = grid.candidates();
    let found = if candidates < PARALLEL_SCAN_FROM {
        let mut found = PairResults::with_capacity(reserve_for(candidates));
        (0..grid.entries.len()).for_each(|k| scan(k, &mut found));
        found
    } else {
        // Independent scans on the rayon pool; the grouping sorts everything, so the
        // result does not depend on how the work was split.
        let parts: Vec<PairResults> = (0..grid.entries.len())
            .into_par_iter()
            .with_min_len(16)
            .fold(PairResults::default, |mut found, k| {
                scan(k, &mut found);
                found
            })
            .collect();
        PairResults::concat(parts)
    };
    found.assemble(segments)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point2;

    fn seg(a: (f64, f64), b: (f64, f64)) -> Segment2 {
        Segment2::new(Point2::new(a.0, a.1), Point2::new(b.0, b.1))
    }

    #[test]
    fn the_choice_follows_candidates_and_meetings() {
        let mut state = 3u64;
        let mut unit = move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
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
