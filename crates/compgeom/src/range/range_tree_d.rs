//! The d-dimensional range tree of §5.4: a balanced binary search tree on the first
//! coordinate whose every node carries a (d−1)-dimensional range tree on the remaining
//! coordinates of its subset; the last coordinate is a sorted array (the 1D range tree).
//!
//! Keys are composite numbers (§5.5): at the level of coordinate `k` the order is
//! `(x_k | x_{k+1} | … | x_{d−1} | x_0 | … | i)`, so equal coordinates and duplicates need
//! no assumption. Query `[lo_0, hi_0] × … × [lo_{d−1}, hi_{d−1}]` (closed):
//! O(log^d n + k); storage O(n log^{d−1} n). Build: each associated tree is built from its
//! subset by sorting, O(n log^d n) (the book's presorting trick would save a log factor;
//! the 2D case has the faster [`RangeTree`](super::RangeTree) and
//! [`LayeredRangeTree`](super::LayeredRangeTree)). Subsets of at most 8 points are scanned.

use super::composite::{check_len, cmp_f64};
use crate::{Error, Result};
use std::cmp::Ordering;

const LEAF: usize = 8;

/// A static range tree on points with `dim >= 1` coordinates; queries report input indices.
///
/// ```
/// use compgeom::range::RangeTreeD;
/// let pts = vec![vec![0.0, 0.0, 0.0], vec![1.0, 2.0, 3.0], vec![1.0, 2.0, 4.0]];
/// let tree = RangeTreeD::new(3, &pts).unwrap();
/// assert_eq!(tree.query(&[1.0, 0.0, 0.0], &[1.0, 2.0, 3.0]).unwrap(), vec![1]);
/// assert_eq!(tree.count(&[0.0; 3], &[9.0; 3]).unwrap(), 3);
/// ```
#[derive(Debug, Clone)]
pub struct RangeTreeD {
    dim: usize,
    /// Row-major coordinates, `dim` per point.
    coords: Vec<f64>,
    root: Option<Level>,
}

/// The tree (or, for the last coordinate, the sorted array) of one coordinate over a subset.
#[derive(Debug, Clone)]
struct Level {
    axis: usize,
    /// The subset in composite order starting at `axis`.
    ids: Vec<u32>,
    /// Associated structures of the internal nodes, heap-indexed; empty on the last axis.
    assoc: Vec<Option<Box<Level>>>,
}

impl RangeTreeD {
    /// Build the tree over `points`, each with exactly `dim` finite coordinates.
    /// `Err(InvalidInput)` for `dim == 0` or a point of the wrong length; `Err(NonFinite)`
    /// names the first point with a NaN or infinite coordinate.
    pub fn new<P: AsRef<[f64]>>(dim: usize, points: &[P]) -> Result<RangeTreeD> {
        if dim == 0 {
            return Err(Error::InvalidInput("dimension 0".into()));
        }
        check_len(points.len())?;
        let mut coords = Vec::with_capacity(points.len() * dim);
        for (i, p) in points.iter().enumerate() {
            let p = p.as_ref();
            if p.len() != dim {
                return Err(Error::InvalidInput(format!(
                    "point {i} has {} coordinates, expected {dim}",
                    p.len()
                )));
            }
            if let Some(&v) = p.iter().find(|v| !v.is_finite()) {
                return Err(Error::NonFinite {
                    what: format!("point {i}"),
                    value: v,
                });
            }
            coords.extend_from_slice(p);
        }
        let mut t = RangeTreeD {
            dim,
            coords,
            root: None,
        };
        let ids: Vec<u32> = (0..points.len() as u32).collect();
        t.root = Some(t.build(ids, 0));
        Ok(t)
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        self.coords.len() / self.dim
    }

    /// True when there are no points.
    pub fn is_empty(&self) -> bool {
        self.coords.is_empty()
    }

    /// The dimension.
    pub fn dim(&self) -> usize {
        self.dim
    }

    #[inline]
    fn c(&self, id: u32, axis: usize) -> f64 {
        self.coords[id as usize * self.dim + axis]
    }

    fn cmp_from(&self, axis: usize, a: u32, b: u32) -> Ordering {
        (0..self.dim)
            .map(|k| (axis + k) % self.dim)
            .map(|k| cmp_f64(self.c(a, k), self.c(b, k)))
            .find(|o| o.is_ne())
            .unwrap_or(Ordering::Equal)
            .then(a.cmp(&b))
    }

    fn build(&self, mut ids: Vec<u32>, axis: usize) -> Level {
        ids.sort_unstable_by(|&a, &b| self.cmp_from(axis, a, b));
        let mut assoc = Vec::new();
        if axis + 1 < self.dim && ids.len() > LEAF {
            let mut size = ids.len();
            let mut depth = 0;
            while size > LEAF {
                size = size.div_ceil(2);
                depth += 1;
            }
            assoc = vec![None; (1usize << depth) - 1];
            self.build_assoc(&ids, &mut assoc, 0, 0, ids.len(), axis);
        }
        Level { axis, ids, assoc }
    }

    fn build_assoc(
        &self,
        ids: &[u32],
        assoc: &mut [Option<Box<Level>>],
        k: usize,
        a: usize,
        b: usize,
        axis: usize,
    ) {
        if b - a <= LEAF || k >= assoc.len() {
            return;
        }
        assoc[k] = Some(Box::new(self.build(ids[a..b].to_vec(), axis + 1)));
        let m = a + (b - a) / 2;
        self.build_assoc(ids, assoc, 2 * k + 1, a, m, axis);
        self.build_assoc(ids, assoc, 2 * k + 2, m, b, axis);
    }

    fn check_box(&self, lo: &[f64], hi: &[f64]) -> Result<bool> {
        if lo.len() != self.dim || hi.len() != self.dim {
            return Err(Error::InvalidInput(format!(
                "query box has {} and {} coordinates, expected {}",
                lo.len(),
                hi.len(),
                self.dim
            )));
        }
        if lo.iter().chain(hi).any(|v| v.is_nan()) {
            return Err(Error::InvalidInput("query box has a NaN coordinate".into()));
        }
        Ok(lo.iter().zip(hi).all(|(l, h)| l <= h))
    }

    fn contains(&self, id: u32, lo: &[f64], hi: &[f64]) -> bool {
        (0..self.dim).all(|k| lo[k] <= self.c(id, k) && self.c(id, k) <= hi[k])
    }

    /// Calls `f` with the input index of each point in the closed box `[lo, hi]`.
    /// `Err(InvalidInput)` if a bound has the wrong length or is NaN; an empty box (some
    /// `lo[k] > hi[k]`) reports nothing. Infinite bounds are allowed.
    pub fn for_each(&self, lo: &[f64], hi: &[f64], mut f: impl FnMut(usize)) -> Result<()> {
        if !self.check_box(lo, hi)? {
            return Ok(());
        }
        if let Some(root) = &self.root {
            self.search(root, lo, hi, &mut |run| {
                run.iter().for_each(|&id| f(id as usize))
            });
        }
        Ok(())
    }

    /// The points in the closed box, input indices ascending. Errors as [`Self::for_each`].
    pub fn query(&self, lo: &[f64], hi: &[f64]) -> Result<Vec<usize>> {
        let mut v = Vec::new();
        self.for_each(lo, hi, |i| v.push(i))?;
        v.sort_unstable();
        Ok(v)
    }

    /// The number of points in the closed box, in O(log^d n). Errors as [`Self::for_each`].
    pub fn count(&self, lo: &[f64], hi: &[f64]) -> Result<usize> {
        if !self.check_box(lo, hi)? {
            return Ok(0);
        }
        let mut c = 0;
        if let Some(root) = &self.root {
            self.search(root, lo, hi, &mut |run| c += run.len());
        }
        Ok(c)
    }

    /// Report the answer through `out` as runs of input indices, all inside the box.
    fn search(&self, level: &Level, lo: &[f64], hi: &[f64], out: &mut dyn FnMut(&[u32])) {
        let axis = level.axis;
        let ids = &level.ids;
        let from = ids.partition_point(|&i| self.c(i, axis) < lo[axis]);
        let to = ids
            .partition_point(|&i| self.c(i, axis) <= hi[axis])
            .max(from);
        if from >= to {
            return;
        }
        if axis + 1 == self.dim {
            // The 1D range tree: the run is the answer on the remaining (last) coordinate;
            // earlier coordinates were decided by the levels above.
            out(&ids[from..to]);
            return;
        }
        self.descend(level, 0, 0, ids.len(), (from, to), lo, hi, out);
    }

    #[allow(clippy::too_many_arguments)]
    fn descend(
        &self,
        level: &Level,
        k: usize,
        a: usize,
        b: usize,
        span: (usize, usize),
        lo: &[f64],
        hi: &[f64],
        out: &mut dyn FnMut(&[u32]),
    ) {
        let (from, to) = span;
        if b <= from || a >= to || a >= b {
            return;
        }
        let assoc = level.assoc.get(k).and_then(|x| x.as_deref());
        if from <= a && b <= to {
            if let Some(sub) = assoc {
                self.search(sub, lo, hi, out);
                return;
            }
        }
        if b - a <= LEAF || assoc.is_none() {
            for &i in &level.ids[a.max(from)..b.min(to)] {
                if self.contains(i, lo, hi) {
                    out(&[i]);
                }
            }
            return;
        }
        let m = a + (b - a) / 2;
        self.descend(level, 2 * k + 1, a, m, span, lo, hi, out);
        self.descend(level, 2 * k + 2, m, b, span, lo, hi, out);
    }
}
