//! Few boxes sorted into strips along each axis as sets of bits, for the rounding
//! check's search for near pairs on small results.

use super::Box2;
use crate::kernel::steps::Steps;

/// Strips per axis.
const STRIPS: usize = 16;

/// The boxes of the moved items of a small result, by strips: the extent of the boxes is
/// cut into [`STRIPS`] equal strips in x and as many in y, and each strip keeps the set
/// of boxes that reach into it, as bits. A box meets another only where both reach into
/// one x-strip and into one y-strip (the strip of a coordinate is monotone in it), so the
/// candidates for a query are the boxes in the union of its x-strips' sets and in the
/// union of its y-strips' sets: a few words of bits instead of a test of every box.
pub(super) struct Strips<'a> {
    boxes: &'a [Box2],
    xs: Steps,
    ys: Steps,
    /// Words of bits per set.
    words: usize,
    /// The x-strips' sets, then the y-strips' (`words` each).
    sets: Vec<u64>,
}

impl<'a> Strips<'a> {
    pub(super) fn new(boxes: &'a [Box2]) -> Strips<'a> {
        let words = boxes.len().div_ceil(64);
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for b in boxes {
            (x0, x1) = (x0.min(b.x0), x1.max(b.x1));
            (y0, y1) = (y0.min(b.y0), y1.max(b.y1));
        }
        // (A zero or infinite extent puts everything in the first or the last strip:
        // still monotone, so still right, only without pruning.)
        let steps = |lo: f64, hi: f64| {
            let width = hi - lo;
            if width > 0.0 && width.is_finite() {
                Steps::new(lo, hi, STRIPS as u32)
            } else {
                Steps::per_unit(lo, 0.0, 1)
            }
        };
        let (xs, ys) = (steps(x0, x1), steps(y0, y1));
        let mut sets = vec![0u64; 2 * STRIPS * words];
        for (k, b) in boxes.iter().enumerate() {
            let (word, bit) = (k / 64, 1u64 << (k % 64));
            for s in xs.index(b.x0)..=xs.index(b.x1) {
                sets[s * words + word] |= bit;
            }
            for s in ys.index(b.y0)..=ys.index(b.y1) {
                sets[(STRIPS + s) * words + word] |= bit;
            }
        }
        Strips {
            boxes,
            xs,
            ys,
            words,
            sets,
        }
    }

    /// Calls `f(k)` for each box `k` that overlaps `b`, in increasing order.
    #[inline(always)]
    pub(super) fn for_each_overlapping(&self, b: &Box2, mut f: impl FnMut(usize)) {
        let (x0, x1) = (self.xs.index(b.x0), self.xs.index(b.x1));
        let (y0, y1) = (self.ys.index(b.y0), self.ys.index(b.y1));
        let words = self.words;
        for w in 0..words {
            let union = |from: usize, to: usize| {
                (from..=to).fold(0u64, |m, s| m | self.sets[s * words + w])
            };
            let mut candidates = union(x0, x1) & union(STRIPS + y0, STRIPS + y1);
            while candidates != 0 {
                let k = 64 * w + candidates.trailing_zeros() as usize;
                if self.boxes[k].overlaps(b) {
                    f(k);
                }
                candidates &= candidates - 1;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The strips give exactly the overlapping boxes, in order: boxes on a small grid
    /// (shared sides, points, equal boxes), long thin ones, more than 64 of them, all at
    /// one x, and infinite sides.
    #[test]
    fn strips_find_every_overlapping_box_in_order() {
        let mut below = crate::testing::below(0x57_a1b5);
        let mut total = 0;
        for round in 0..600 {
            let mut boxes = |n: u64| -> Vec<Box2> {
                (0..below(n) + 1)
                    .map(|_| {
                        let mut v = || below(24) as f64 - 12.0;
                        let (mut x, y) = (v(), v());
                        if round % 7 == 0 {
                            x = 3.0;
                        }
                        let (w, h) = match below(6) {
                            0 => (0.0, 0.0),
                            1 => (below(24) as f64, 0.5),
                            2 if round % 5 == 0 => (f64::INFINITY, 1.0),
                            _ => (below(4) as f64, below(4) as f64),
                        };
                        Box2 {
                            x0: x,
                            x1: x + w,
                            y0: y,
                            y1: y + h,
                        }
                    })
                    .collect()
            };
            let items = boxes(if round % 3 == 0 { 150 } else { 40 });
            let queries = boxes(30);
            let strips = Strips::new(&items);
            for q in &queries {
                let mut got = Vec::new();
                strips.for_each_overlapping(q, |k| got.push(k));
                let want: Vec<usize> = (0..items.len()).filter(|&k| items[k].overlaps(q)).collect();
                assert_eq!(got, want, "round {round}");
                total += want.len();
            }
        }
        assert!(total > 10_000, "only {total} pairs");
    }
}
