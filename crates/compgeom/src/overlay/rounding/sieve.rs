//! A bitmap of where the moved items are, to pass over the points and edges of a
//! result that are nowhere near them without the near-pair search proper.
//!
//! The search looks at every point and every edge of a result; on large results only a
//! few are near a moved item (a star of 10⁴ vertices: 24 moved items among 4·10⁴ queries),
//! and most of the search's time was spent finding that out, query by query, on the
//! grid. Here each moved item's box, widened by [`Sieve::pad`], sets the bits of the
//! cells it covers on a finer grid of bits; a query is passed over when the bits of its
//! cells are clear. Cells are a monotone function of the coordinates (as in
//! [`super::grid`]), so two boxes that overlap share a cell: a query that meets an item
//! finds its bit set. The widening lets a point be looked up by the one cell of its
//! centre: every box the search tests around a point lies within `pad` of it.

use super::{Box2, REL_ROUGH};
use crate::kernel::steps::Steps;
use crate::kernel::Point2;
use crate::scratch::{self, Scratch};

/// About this many cells per item.
const CELLS_PER_ITEM: usize = 16;

/// A sieve is made only where there are at most this many moved items per point of the
/// result (where they are denser, most points are near one: the water map's results
/// have one moved item for each two points, half of their points near one).
const ITEMS_PER_POINT: (usize, usize) = (1, 4);

/// At most this many cell marks per item on average: items over more cells (long
/// edges) fill the bitmap, which then sieves nothing; past it there is no sieve.
const MARKS_PER_ITEM: usize = 64;

/// A box over more cells than this is not sieved.
const LOOKED_AT_MOST: usize = 16;

/// Bits over a grid of about [`CELLS_PER_ITEM`] cells per item, set where a widened
/// item box covers the cell.
pub(super) struct Sieve {
    xs: Steps,
    ys: Steps,
    nx: usize,
    /// The items' extent, widened by `pad`: queries outside it meet no item.
    extent: Box2,
    bits: Scratch<u64>,
}

impl Sieve {
    /// How far around a point `c` with coordinates of magnitude at most `m` the search's
    /// boxes reach: twice the rough box's `m · 2⁻⁴⁸` (and its absolute term). A point
    /// whose rough box meets a box within `m` has coordinates below `m` plus that
    /// half-size, so its own half-size is below `(m · 2⁻⁴⁸ + abs) / (1 − 2⁻⁴⁸)`; the
    /// factor 2 covers that and the rounding of the widened bounds (at most a float gap
    /// of `m`, 2⁻⁵² of it).
    fn pad(m: f64) -> f64 {
        2.0 * (m * REL_ROUGH.0 + REL_ROUGH.1)
    }

    /// The sieve of `boxes` (the moved items) for a result of `points` points, or `None`
    /// where it would not pay or not be sound: no boxes, more than
    /// [`ITEMS_PER_POINT`] of them, items over so many cells that the marks would cost
    /// more than they save ([`MARKS_PER_ITEM`]), or coordinates too large for the
    /// widening to stay finite.
    pub(super) fn new(boxes: &[Box2], points: usize) -> Option<Sieve> {
        if boxes.len() * ITEMS_PER_POINT.1 > points * ITEMS_PER_POINT.0 {
            return None;
        }
        let e = boxes.iter().copied().reduce(|a, b| a.union(&b))?;
        let m = [e.x0, e.x1, e.y0, e.y1]
            .iter()
            .fold(0.0f64, |m, v| m.max(v.abs()));
        // (Infinite or huge bounds, or NaN: the search alone.)
        if m.is_nan() || m >= f64::MAX / 4.0 {
            return None;
        }
        let pad = Sieve::pad(m);
        let extent = Box2 {
            x0: e.x0 - pad,
            x1: e.x1 + pad,
            y0: e.y0 - pad,
            y1: e.y1 + pad,
        };
        let (w, h) = (extent.x1 - extent.x0, extent.y1 - extent.y0);
        let target = (CELLS_PER_ITEM * boxes.len()) as f64;
        // Columns and rows in proportion to the sides (both positive: `pad` is), from
        // their ratio: `target · w` and `target · h` can both overflow at large
        // coordinates, which gave both axes the cap and (16 n)² cells.
        let ratio = w / h;
        let along = |v: f64| (v.sqrt().ceil() as usize).clamp(1, CELLS_PER_ITEM * boxes.len());
        let (nx, ny) = (along(target * ratio), along(target / ratio));
        let xs = Steps::new(extent.x0, extent.x1, nx as u32);
        let ys = Steps::new(extent.y0, extent.y1, ny as u32);
        let mut bits = scratch::filled((nx * ny).div_ceil(64), 0u64);
        let mut marks = 0usize;
        for b in boxes {
            let (x0, x1) = (xs.index(b.x0 - pad), xs.index(b.x1 + pad));
            let (y0, y1) = (ys.index(b.y0 - pad), ys.index(b.y1 + pad));
            marks += (x1 - x0 + 1) * (y1 - y0 + 1);
            if marks > MARKS_PER_ITEM * boxes.len() {
                return None;
            }
            for y in y0..=y1 {
                for x in x0..=x1 {
                    let cell = y * nx + x;
                    bits[cell / 64] |= 1 << (cell % 64);
                }
            }
        }
        Some(Sieve {
            xs,
            ys,
            nx,
            extent,
            bits,
        })
    }

    fn set(&self, x: usize, y: usize) -> bool {
        let cell = y * self.nx + x;
        self.bits[cell / 64] & (1 << (cell % 64)) != 0
    }

    /// Whether a box the search makes around point `c` (its rough box, or a smaller
    /// one) may meet an item.
    #[inline(always)]
    pub(super) fn near_point(&self, c: Point2) -> bool {
        let e = &self.extent;
        e.x0 <= c.x
            && c.x <= e.x1
            && e.y0 <= c.y
            && c.y <= e.y1
            && self.set(self.xs.index(c.x), self.ys.index(c.y))
    }

    /// Whether box `b` may meet an item.
    #[inline(always)]
    pub(super) fn near_box(&self, b: &Box2) -> bool {
        if !b.overlaps(&self.extent) {
            return false;
        }
        let (x0, x1) = (self.xs.index(b.x0), self.xs.index(b.x1));
        let (y0, y1) = (self.ys.index(b.y0), self.ys.index(b.y1));
        if (x1 - x0 + 1) * (y1 - y0 + 1) > LOOKED_AT_MOST {
            // (A long edge: the search itself.)
            return true;
        }
        (y0..=y1).any(|y| (x0..=x1).any(|x| self.set(x, y)))
    }
}

#[cfg(test)]
mod tests {
    use super::super::rough_box;
    use super::*;

    /// Whatever the scale and wherever the queries are, a point whose rough box meets a
    /// box, and a box that meets one, are kept: on grids of small integers (boxes that
    /// touch, points on cell bounds), unit-scale floats, huge and tiny coordinates.
    #[test]
    fn what_meets_a_box_is_kept() {
        let mut int = crate::testing::below(0x0051_57e5);
        let mut unit = crate::testing::units(0x0051_57e6);
        let mut built = 0;
        for round in 0..3000 {
            let scale = [1.0, 1e-3, 1e12, 1e-300, 1e300, 3e-320][round % 6];
            let coord = |int: &mut dyn FnMut(u64) -> u64, unit: &mut dyn FnMut() -> f64| {
                if round % 2 == 0 {
                    (int(40) as f64 - 20.0) * scale
                } else {
                    (unit() * 40.0 - 20.0) * scale
                }
            };
            let mut boxes = Vec::new();
            for _ in 0..1 + int(12) {
                let (a, b) = (coord(&mut int, &mut unit), coord(&mut int, &mut unit));
                let (c, d) = (coord(&mut int, &mut unit), coord(&mut int, &mut unit));
                // (Mostly small boxes, as moved items' are.)
                let (c, d) = if int(3) == 0 { (c, d) } else { (a, b) };
                boxes.push(Box2::of(Point2::new(a, b), Point2::new(c, d)));
            }
            let points = 4 * boxes.len() + int(1000) as usize;
            let Some(sieve) = Sieve::new(&boxes, points) else {
                continue;
            };
            built += 1;
            for _ in 0..200 {
                let c = Point2::new(coord(&mut int, &mut unit), coord(&mut int, &mut unit));
                let rough = rough_box(c);
                if boxes.iter().any(|b| b.overlaps(&rough)) {
                    assert!(sieve.near_point(c), "round {round}: {c:?}");
                }
                // A point just beyond a corner of a box, within its rough box's reach.
                let b = boxes[int(boxes.len() as u64) as usize];
                let (x, y) = (
                    if int(2) == 0 { b.x0 } else { b.x1 },
                    if int(2) == 0 { b.y0 } else { b.y1 },
                );
                let (rel, abs) = REL_ROUGH;
                let (hx, hy) = (x.abs() * rel + abs, y.abs() * rel + abs);
                let f = 0.98 * unit();
                let (sx, sy) = (
                    if int(2) == 0 { -1.0 } else { 1.0 },
                    if int(2) == 0 { -1.0 } else { 1.0 },
                );
                let beyond = Point2::new(x + sx * f * hx, y + sy * f * hy);
                if boxes.iter().any(|b| b.overlaps(&rough_box(beyond))) {
                    assert!(sieve.near_point(beyond), "round {round}: {beyond:?}");
                }
                let d = Point2::new(coord(&mut int, &mut unit), coord(&mut int, &mut unit));
                let q = Box2::of(c, if int(2) == 0 { c } else { d });
                if boxes.iter().any(|b| b.overlaps(&q)) {
                    assert!(sieve.near_box(&q), "round {round}: {c:?} {d:?}");
                }
            }
        }
        assert!(built > 2000, "{built} sieves");
    }

    /// About 16 cells per item at every scale, in both axes. (Sized from the product of
    /// the count and each side, the sieve of 1 000 boxes spread over ±1e306 had
    /// 256 · 1 000² cells: both products overflowed and both axes took their cap.)
    #[test]
    fn cells_stay_about_sixteen_per_item_at_every_scale() {
        let mut unit = crate::testing::units(0x0051_57e7);
        for scale in [1.0, 1e306, 4e307, 1e-300, 3e-320] {
            for (sx, sy) in [(1.0, 1.0), (1.0, 1e-6), (1e-6, 1.0)] {
                let n = 1000;
                let boxes: Vec<Box2> = (0..n)
                    .map(|_| {
                        let c = Point2::new(
                            (2.0 * unit() - 1.0) * scale * sx,
                            (2.0 * unit() - 1.0) * scale * sy,
                        );
                        Box2::of(c, c)
                    })
                    .collect();
                let Some(sieve) = Sieve::new(&boxes, 4 * n) else {
                    continue;
                };
                let cells = sieve.bits.len() * 64;
                assert!(
                    cells <= 20 * n + 64,
                    "{scale:e} ({sx}, {sy}): {cells} cells"
                );
            }
        }
    }
}
