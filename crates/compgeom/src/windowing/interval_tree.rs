//! The interval tree of §10.1: stabbing queries on closed intervals of the line.
//!
//! Each node keeps a median endpoint `x_mid`, the intervals containing it (sorted once by
//! left endpoint ascending and once by right endpoint descending), and two subtrees: the
//! intervals entirely left of `x_mid` and those entirely right. A query at `q` walks one
//! root-to-leaf path and, at each node, reports a prefix of one of the two lists.
//! Build O(n log n); storage O(n); query O(log n + k). Endpoint comparisons are exact;
//! degenerate intervals (`lo == hi`) and duplicates are ordinary input.

use crate::Result;

/// One node's split: the median endpoint, the intervals containing it, and the children.
#[derive(Debug, Clone)]
pub(crate) struct Split {
    pub x_mid: f64,
    /// Indices of the intervals that contain `x_mid`.
    pub mid: Vec<u32>,
    pub left: Option<u32>,
    pub right: Option<u32>,
}

/// Check intervals and build the node splits (shared with the windowing structure, which
/// attaches other associated structures to the same nodes). Node 0 is the root.
pub(crate) fn build_splits(intervals: &[(f64, f64)]) -> Result<Vec<Split>> {
    super::segment_tree::check_intervals(intervals)?;
    let mut nodes = Vec::new();
    let ids: Vec<u32> = (0..intervals.len() as u32).collect();
    if !ids.is_empty() {
        build(intervals, ids, &mut nodes);
    }
    Ok(nodes)
}

fn build(iv: &[(f64, f64)], ids: Vec<u32>, nodes: &mut Vec<Split>) -> u32 {
    let mut ends: Vec<f64> = ids
        .iter()
        .flat_map(|&i| [iv[i as usize].0, iv[i as usize].1])
        .collect();
    let k = ends.len() / 2;
    // (Any endpoint would do as the split, -0 or 0: the median only balances the tree.)
    let (_, &mut x_mid, _) = ends.select_nth_unstable_by(k, |a, b| a.total_cmp(b));
    let x_mid = x_mid + 0.0; // -0.0 and 0.0 are the same point
    let (mut mid, mut l, mut r) = (Vec::new(), Vec::new(), Vec::new());
    for i in ids {
        let (lo, hi) = iv[i as usize];
        if hi < x_mid {
            l.push(i);
        } else if lo > x_mid {
            r.push(i);
        } else {
            mid.push(i);
        }
    }
    let me = nodes.len() as u32;
    nodes.push(Split {
        x_mid,
        mid,
        left: None,
        right: None,
    });
    // The median endpoint lies in at least one interval, so both sides shrink.
    let left = (!l.is_empty()).then(|| build(iv, l, nodes));
    let right = (!r.is_empty()).then(|| build(iv, r, nodes));
    nodes[me as usize].left = left;
    nodes[me as usize].right = right;
    me
}

/// A static interval tree over closed intervals `[lo, hi]`; queries report input indices.
///
/// ```
/// use compgeom::windowing::IntervalTree;
/// let t = IntervalTree::new(&[(0.0, 2.0), (1.0, 1.0), (3.0, 5.0), (2.0, 3.0)]).unwrap();
/// assert_eq!(t.stab(2.0), vec![0, 3]);
/// assert_eq!(t.stab(1.0), vec![0, 1]);
/// assert!(t.stab(6.0).is_empty());
/// ```
#[derive(Debug, Clone)]
pub struct IntervalTree {
    intervals: Vec<(f64, f64)>,
    nodes: Vec<Split>,
    /// Per node: `mid` by left end ascending, and by right end descending.
    by_lo: Vec<Vec<u32>>,
    by_hi: Vec<Vec<u32>>,
}

impl IntervalTree {
    /// Build the tree. `Err(NonFinite)` / `Err(InvalidInput)` name the first interval with
    /// a non-finite end or with `lo > hi`.
    pub fn new(intervals: &[(f64, f64)]) -> Result<IntervalTree> {
        let nodes = build_splits(intervals)?;
        let iv = intervals;
        // (Sorted by `total_cmp` is sorted by `<=` too, all the queries' early stops need.)
        let by_lo = nodes
            .iter()
            .map(|n| {
                let mut v = n.mid.clone();
                v.sort_by(|&a, &b| iv[a as usize].0.total_cmp(&iv[b as usize].0));
                v
            })
            .collect();
        let by_hi = nodes
            .iter()
            .map(|n| {
                let mut v = n.mid.clone();
                v.sort_by(|&a, &b| iv[b as usize].1.total_cmp(&iv[a as usize].1));
                v
            })
            .collect();
        Ok(IntervalTree {
            intervals: intervals.iter().map(|&(a, b)| (a + 0.0, b + 0.0)).collect(),
            nodes,
            by_lo,
            by_hi,
        })
    }

    /// Number of intervals.
    pub fn len(&self) -> usize {
        self.intervals.len()
    }

    /// True when there are no intervals.
    pub fn is_empty(&self) -> bool {
        self.intervals.is_empty()
    }

    /// Calls `f` with the index of every interval containing `q` (QUERYINTERVALTREE).
    /// A NaN `q` reports nothing.
    pub fn for_each_stabbed(&self, q: f64, mut f: impl FnMut(usize)) {
        let mut node = (!self.nodes.is_empty()).then_some(0u32);
        while let Some(k) = node {
            let n = &self.nodes[k as usize];
            let k = k as usize;
            if q < n.x_mid {
                for &i in &self.by_lo[k] {
                    if self.intervals[i as usize].0 > q {
                        break;
                    }
                    f(i as usize);
                }
                node = n.left;
            } else if q > n.x_mid {
                for &i in &self.by_hi[k] {
                    if self.intervals[i as usize].1 < q {
                        break;
                    }
                    f(i as usize);
                }
                node = n.right;
            } else {
                // q == x_mid: every interval of the node contains it; none below does.
                n.mid.iter().for_each(|&i| f(i as usize));
                node = None;
            }
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
