//! The segment tree of §10.3: stabbing queries on closed intervals.
//!
//! The sorted distinct endpoints `p_0 < … < p_{m−1}` cut the line into *elementary
//! intervals*: the points `[p_k, p_k]` and the open gaps `(p_k, p_{k+1})` (the unbounded
//! ends hold no interval and are left out). A balanced binary tree has them as leaves, in
//! order; each interval is stored at the O(log n) nodes whose elementary intervals it
//! covers but whose parent's it does not (its canonical nodes). A query at `q` finds the
//! leaf containing `q` and reports the lists of the nodes on its path: O(log n + k), storage
//! O(n log n), build O(n log n). Decisions compare endpoints with `q`: exact.
//!
//! [`SegmentWindow`](super::SegmentWindow) uses the same tree with each node's list sorted
//! by the exact above/below relation.

use crate::range::PARALLEL;
use crate::{Error, Result};
use rayon::prelude::*;

/// The tree skeleton over elementary intervals, with the canonical lists.
#[derive(Debug, Clone)]
pub(crate) struct Skeleton {
    /// Distinct endpoints, ascending.
    pub xs: Vec<f64>,
    /// Node `k`'s canonical list is `items[starts[k]..starts[k + 1]]` (heap-indexed nodes
    /// over the units `0..2m-1`; one flat array, as a `Vec` per node would cost 24 bytes
    /// per node).
    starts: Vec<u32>,
    items: Vec<u32>,
}

impl Skeleton {
    /// Build over closed intervals (checked: finite, `lo <= hi`), with every distinct
    /// endpoint a boundary.
    pub fn new(intervals: &[(f64, f64)]) -> Skeleton {
        let mut xs: Vec<f64> = intervals
            .iter()
            .flat_map(|&(a, b)| [a + 0.0, b + 0.0])
            .collect();
        xs.sort_unstable_by(f64::total_cmp);
        xs.dedup();
        Skeleton::with_bounds(xs, intervals)
    }

    /// Build over closed intervals (checked) lying within `[xs[0], xs[last]]`, with the
    /// given boundaries (ascending, distinct, `-0.0` normalised). Each interval is stored
    /// at the canonical nodes of the units it covers whole; an endpoint strictly inside an
    /// open unit leaves that unit partly covered, which is the caller's business (see
    /// [`partial_units`](Skeleton::partial_units)).
    pub fn with_bounds(xs: Vec<f64>, intervals: &[(f64, f64)]) -> Skeleton {
        let spans = Skeleton::spans(&xs, intervals);
        Skeleton::from_spans(xs, &spans)
    }

    /// The whole units `[ua, ub)` of each interval over the boundaries `xs`: from the point
    /// unit of the first boundary at or after `a` to the point unit of the last boundary at
    /// or before `b` (empty when no boundary lies in `[a, b]`).
    pub fn spans(xs: &[f64], intervals: &[(f64, f64)]) -> Vec<(usize, usize)> {
        let span = |&(a, b): &(f64, f64)| {
            let ua = 2 * xs.partition_point(|&x| x < a);
            let ub = (2 * xs.partition_point(|&x| x <= b)).saturating_sub(1);
            (ua, ub)
        };
        if intervals.len() >= PARALLEL {
            intervals.par_iter().map(span).collect()
        } else {
            intervals.iter().map(span).collect()
        }
    }

    /// The tree over boundaries `xs` with interval `i` stored at the canonical nodes of
    /// `spans[i]`.
    pub fn from_spans(xs: Vec<f64>, spans: &[(usize, usize)]) -> Skeleton {
        let units = (2 * xs.len()).saturating_sub(1);
        let nodes = 2 * units.next_power_of_two().max(1);
        // Two passes: count each node's list, then fill the flat array.
        let mut starts = vec![0u32; nodes + 1];
        for &(ua, ub) in spans {
            canonical(0, 0, units, ua, ub, &mut |k| starts[k + 1] += 1);
        }
        for k in 0..nodes {
            starts[k + 1] += starts[k];
        }
        let mut cursor = starts.clone();
        let mut items = vec![0u32; starts[nodes] as usize];
        for (i, &(ua, ub)) in spans.iter().enumerate() {
            canonical(0, 0, units, ua, ub, &mut |k| {
                items[cursor[k] as usize] = i as u32;
                cursor[k] += 1;
            });
        }
        Skeleton { xs, starts, items }
    }

    /// Every node's slab (see [`slab`](Skeleton::slab)) with its list, to sort the lists
    /// (in parallel).
    pub fn lists_mut(&mut self) -> Vec<((f64, f64), &mut [u32])> {
        let mut spans = Vec::new();
        self.for_each_node(|k, u0, u1| spans.push((k, self.slab(u0, u1))));
        spans.sort_unstable_by_key(|s| s.0);
        let mut rest: &mut [u32] = &mut self.items;
        let mut done = 0usize;
        let mut out = Vec::with_capacity(spans.len());
        for (k, slab) in spans {
            let (from, to) = (self.starts[k] as usize, self.starts[k + 1] as usize);
            let (_, tail) = std::mem::take(&mut rest).split_at_mut(from - done);
            let (list, tail) = tail.split_at_mut(to - from);
            rest = tail;
            done = to;
            out.push((slab, list));
        }
        out
    }

    /// Approximate heap bytes.
    pub fn memory_bytes(&self) -> usize {
        self.xs.capacity() * 8 + (self.starts.capacity() + self.items.capacity()) * 4
    }

    /// Node `k`'s list.
    #[inline]
    pub fn list(&self, k: usize) -> &[u32] {
        &self.items[self.list_range(k)]
    }

    /// Where node `k`'s list lies in the flat array of all lists (for data kept alongside).
    #[inline]
    pub fn list_range(&self, k: usize) -> std::ops::Range<usize> {
        self.starts[k] as usize..self.starts[k + 1] as usize
    }

    /// The flat array of all lists.
    #[inline]
    pub fn items(&self) -> &[u32] {
        &self.items
    }

    /// Number of elementary units.
    pub fn units(&self) -> usize {
        (2 * self.xs.len()).saturating_sub(1)
    }

    /// The elementary unit containing `q`, if any interval could contain it.
    pub fn unit_of(&self, q: f64) -> Option<usize> {
        let k = self.xs.partition_point(|&x| x < q);
        if k < self.xs.len() && self.xs[k] == q {
            Some(2 * k)
        } else if k == 0 || k == self.xs.len() {
            None
        } else {
            Some(2 * k - 1)
        }
    }

    /// Visit the nodes on the path to unit `u`: `f(node, first unit, last unit)`.
    pub fn path(&self, u: usize, mut f: impl FnMut(usize, usize, usize)) {
        let (mut k, mut a, mut b) = (0usize, 0usize, self.units());
        while a < b {
            f(k, a, b - 1);
            if b - a == 1 {
                break;
            }
            let m = a + (b - a) / 2;
            if u < m {
                k = 2 * k + 1;
                b = m;
            } else {
                k = 2 * k + 2;
                a = m;
            }
        }
    }

    /// The slab of a node with units `[u0, u1]`: its leftmost and rightmost x, both within
    /// every interval stored there.
    pub fn slab(&self, u0: usize, u1: usize) -> (f64, f64) {
        (self.xs[u0 / 2], self.xs[u1.div_ceil(2)])
    }

    /// Units `[a, b)` of heap node `k` found by walking from the root (for sorting lists).
    pub fn for_each_node(&self, mut f: impl FnMut(usize, usize, usize)) {
        fn rec(k: usize, a: usize, b: usize, f: &mut impl FnMut(usize, usize, usize)) {
            if a >= b {
                return;
            }
            f(k, a, b - 1);
            if b - a > 1 {
                let m = a + (b - a) / 2;
                rec(2 * k + 1, a, m, f);
                rec(2 * k + 2, m, b, f);
            }
        }
        rec(0, 0, self.units(), &mut f);
    }
}

/// Call `f` with each canonical node of the units `[ua, ub)` below node `k` (units `[a, b)`).
fn canonical(k: usize, a: usize, b: usize, ua: usize, ub: usize, f: &mut impl FnMut(usize)) {
    if ub <= a || b <= ua || a >= b {
        return;
    }
    if ua <= a && b <= ub {
        f(k);
        return;
    }
    let m = a + (b - a) / 2;
    canonical(2 * k + 1, a, m, ua, ub, f);
    canonical(2 * k + 2, m, b, ua, ub, f);
}

/// Check intervals: finite, `lo <= hi`, at most `u32::MAX`.
pub(crate) fn check_intervals(intervals: &[(f64, f64)]) -> Result<()> {
    crate::range::check_count(intervals.len())?;
    for (i, &(lo, hi)) in intervals.iter().enumerate() {
        if !lo.is_finite() || !hi.is_finite() {
            return Err(Error::NonFinite {
                what: format!("interval {i}"),
                value: if lo.is_finite() { hi } else { lo },
            });
        }
        if lo > hi {
            return Err(Error::InvalidInput(format!(
                "interval {i} has its left end {lo} after its right end {hi}"
            )));
        }
    }
    Ok(())
}

/// A static segment tree over closed intervals `[lo, hi]`; queries report input indices.
///
/// ```
/// use compgeom::windowing::SegmentTree;
/// let t = SegmentTree::new(&[(0.0, 2.0), (1.0, 1.0), (3.0, 5.0), (2.0, 3.0)]).unwrap();
/// assert_eq!(t.stab(2.0), vec![0, 3]);
/// assert_eq!(t.stab(2.5), vec![3]);
/// ```
#[derive(Debug, Clone)]
pub struct SegmentTree {
    skel: Skeleton,
}

impl SegmentTree {
    /// Build the tree. `Err(NonFinite)` / `Err(InvalidInput)` name the first interval with
    /// a non-finite end or with `lo > hi`.
    pub fn new(intervals: &[(f64, f64)]) -> Result<SegmentTree> {
        check_intervals(intervals)?;
        Ok(SegmentTree {
            skel: Skeleton::new(intervals),
        })
    }

    /// Calls `f` with the index of every interval containing `q` (each once).
    pub fn for_each_stabbed(&self, q: f64, mut f: impl FnMut(usize)) {
        if let Some(u) = self.skel.unit_of(q) {
            self.skel.path(u, |k, _, _| {
                self.skel.list(k).iter().for_each(|&i| f(i as usize))
            });
        }
    }

    /// The intervals containing `q`, indices ascending.
    pub fn stab(&self, q: f64) -> Vec<usize> {
        let mut v = Vec::new();
        self.for_each_stabbed(q, |i| v.push(i));
        v.sort_unstable();
        v
    }
}
