//! Snap rounding of crossing constraints on the `f64` grid (Hobby 1999; Guibas & Marimont
//! 1998), before they are inserted.
//!
//! Two constraints that properly cross meet at a Steiner vertex, their exact crossing
//! rounded to an `f64` point, and both bend through it. Bending them one crossing at a
//! time, as the crossings are met, is not enough where several segments pass through
//! (nearly) one point: their pairwise crossings round to points an ulp apart, each on the
//! wrong side of a third segment, and the bent pieces cross again near every one of them.
//! Snap rounding decides all the bends at once: every proper crossing is a *hot* point,
//! and every segment becomes the chain through the hot points whose rounding cell (the
//! closed box of reals that round to the point) it meets, in order along the segment,
//! together with the input vertices lying exactly on it. Chains made that way meet only
//! at shared vertices and along shared pieces, never crossing; so the constraint engine
//! inserts them without new crossings. (Its crossing rules remain for what this leaves
//! out: a segment passing through the cell of an input vertex but not through the vertex
//! is routed through it only if a bent piece would cross it.)
//!
//! Snapping is done only when some crossing does not round to a point exactly on both
//! segments: otherwise every constraint is split exactly at the vertices on it and
//! nothing bends.
//!
//! Cost: the intersection sweep, O((n + I) log n) for n segments and I crossings, plus the
//! search for cells met, a uniform grid of about I cells walked along each segment.

use super::pred::{along_cmp, orient, segment_meets_cell};
use crate::intersect::find_intersections;
use crate::{Point2, Result, Segment2};
use std::cmp::Ordering;

/// The snap-rounded constraints.
pub(crate) struct Snapped {
    /// The hot points (rounded proper crossings), distinct, in an order that keeps
    /// consecutive points near each other (for point location by walking).
    pub(crate) hot: Vec<Point2>,
    /// For each segment, the points its chain passes through strictly between its two
    /// ends, in order from `a` to `b`.
    pub(crate) inner: Vec<Vec<Point2>>,
}

/// Snap-rounds `segs` (see the module docs), or `None` when no crossing bends a segment.
///
/// # Errors
/// As [`find_intersections`] (a non-finite coordinate, too many segments).
pub(crate) fn snap_round(segs: &[Segment2]) -> Result<Option<Snapped>> {
    if segs.len() < 2 {
        return Ok(None);
    }
    let found = find_intersections(segs)?;
    let mut hot = Vec::new();
    let mut bends = false;
    let mut inner: Vec<Vec<Point2>> = vec![Vec::new(); segs.len()];
    for p in &found.points {
        let x = p.point;
        if p.is_crossing() {
            hot.push(x);
            bends |= p
                .segments()
                .iter()
                .any(|&i| orient(segs[i].a, segs[i].b, x) != 0);
        }
        for &i in p.interior() {
            inner[i].push(x);
        }
    }
    if !bends {
        return Ok(None);
    }
    hot.sort_unstable_by(|p, q| lex(*p, *q));
    hot.dedup();
    let grid = Grid::new(&hot);
    for (s, chain) in segs.iter().zip(&mut inner) {
        chain.sort_unstable_by(|p, q| lex(*p, *q));
        chain.dedup();
        add_cells_met(*s, &grid, &hot, chain);
        chain.retain(|&p| p != s.a && p != s.b);
        chain.sort_unstable_by(|&p, &q| along_cmp(p, q, s.a, s.b).then_with(|| lex(p, q)));
        chain.dedup();
    }
    // Row by row, alternating direction: each point is inserted near the one before.
    let cell = |p: Point2| {
        let (r, c) = (grid.row(p.y), grid.col(p.x));
        (r, if r % 2 == 0 { c } else { grid.cols - 1 - c })
    };
    hot.sort_by_cached_key(|&p| cell(p));
    Ok(Some(Snapped { hot, inner }))
}

/// (`total_cmp` puts -0 before 0: at worst a point is kept twice, which the dedup after
/// the sort along a segment and `add_point`, finding the vertex already there, absorb.)
fn lex(p: Point2, q: Point2) -> Ordering {
    p.x.total_cmp(&q.x).then(p.y.total_cmp(&q.y))
}

/// Adds to the segment's list `known` (its crossings and the vertices on it, sorted
/// lexicographically) the other hot points whose cell it meets: the exact test, on the
/// candidates the grid finds near the segment.
fn add_cells_met(s: Segment2, grid: &Grid, hot: &[Point2], known: &mut Vec<Point2>) {
    let mut met = Vec::new();
    grid.near(s, |k| {
        let h = hot[k];
        if known.binary_search_by(|p| lex(*p, h)).is_err() && segment_meets_cell(h, s.a, s.b) {
            met.push(h);
        }
    });
    known.extend(met);
}

/// A uniform grid of buckets over the hot points' bounding box.
struct Grid {
    x0: f64,
    y0: f64,
    /// Cell width and height (0 for a single column or row).
    w: f64,
    h: f64,
    cols: usize,
    rows: usize,
    /// Bucket `c` holds `items[start[c]..start[c + 1]]` (indices of hot points).
    start: Vec<usize>,
    items: Vec<usize>,
}

impl Grid {
    fn new(hot: &[Point2]) -> Grid {
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for p in hot {
            (x0, x1, y0, y1) = (x0.min(p.x), x1.max(p.x), y0.min(p.y), y1.max(p.y));
        }
        let side = ((hot.len() as f64).sqrt().ceil() as usize).clamp(1, 2048);
        // Cells far wider than the rounding error of locating a point in them (about
        // 10⁻¹⁵ of the coordinates): then looking one cell beyond the computed range on
        // each side cannot miss a point.
        let scale = x0.abs().max(x1.abs()).max(y0.abs()).max(y1.abs());
        let fit = |extent: f64| {
            let most = (extent / (1e-9 * scale)).floor();
            if most >= 1.0 {
                side.min(most as usize).max(1)
            } else {
                1
            }
        };
        let (cols, rows) = (fit(x1 - x0), fit(y1 - y0));
        let w = if cols > 1 {
            (x1 - x0) / cols as f64
        } else {
            0.0
        };
        let h = if rows > 1 {
            (y1 - y0) / rows as f64
        } else {
            0.0
        };
        let mut grid = Grid {
            x0,
            y0,
            w,
            h,
            cols,
            rows,
            start: vec![0; cols * rows + 1],
            items: vec![0; hot.len()],
        };
        let cells: Vec<usize> = hot
            .iter()
            .map(|p| grid.row(p.y) * cols + grid.col(p.x))
            .collect();
        for &c in &cells {
            grid.start[c + 1] += 1;
        }
        for c in 0..cols * rows {
            grid.start[c + 1] += grid.start[c];
        }
        let mut fill = grid.start.clone();
        for (k, &c) in cells.iter().enumerate() {
            grid.items[fill[c]] = k;
            fill[c] += 1;
        }
        grid
    }

    fn col(&self, x: f64) -> usize {
        index(x, self.x0, self.w, self.cols)
    }

    fn row(&self, y: f64) -> usize {
        index(y, self.y0, self.h, self.rows)
    }

    /// Calls `f` with every hot point in the cells the segment passes through, and in the
    /// cells around those.
    fn near(&self, s: Segment2, mut f: impl FnMut(usize)) {
        let (lo, hi) = if s.a.x <= s.b.x {
            (s.a, s.b)
        } else {
            (s.b, s.a)
        };
        let (c0, c1) = (
            self.col(lo.x).saturating_sub(1),
            (self.col(hi.x) + 1).min(self.cols - 1),
        );
        for c in c0..=c1 {
            // The segment's y-range over this column (its whole range when vertical or
            // when the grid has one column).
            let (ya, yb) = if self.w > 0.0 && hi.x > lo.x {
                let xa = (self.x0 + c as f64 * self.w).max(lo.x);
                let xb = (self.x0 + (c + 1) as f64 * self.w).min(hi.x);
                let t = |x: f64| lo.y + (hi.y - lo.y) * ((x - lo.x) / (hi.x - lo.x));
                (t(xa.min(xb)), t(xb.max(xa)))
            } else {
                (lo.y, hi.y)
            };
            let (r0, r1) = (
                self.row(ya.min(yb)).saturating_sub(1),
                (self.row(ya.max(yb)) + 1).min(self.rows - 1),
            );
            for r in r0..=r1 {
                let cell = r * self.cols + c;
                for &k in &self.items[self.start[cell]..self.start[cell + 1]] {
                    f(k);
                }
            }
        }
    }
}

/// The bucket of coordinate `v` on an axis from `origin` in `n` steps of `step`, clamped.
fn index(v: f64, origin: f64, step: f64, n: usize) -> usize {
    if step <= 0.0 {
        return 0;
    }
    let k = ((v - origin) / step).floor();
    if k <= 0.0 {
        0
    } else {
        (k as usize).min(n - 1)
    }
}
