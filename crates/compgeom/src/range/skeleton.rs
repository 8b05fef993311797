//! What the 2D range tree (§5.3) and the layered range tree (§5.6) share: the points in
//! composite x-order (§5.5), the implicit balanced binary tree over that order (node
//! `[a, b)` has children `[a, m)` and `[m, b)` with `m = a + (b - a) / 2`; subsets of at
//! most [`LEAF`] points are leaves, scanned directly), and one array per depth holding, for
//! every node at that depth, its points in composite y-order (`(y | x | i)`): the
//! associated structures, stored level by level.
//!
//! Built top-down by stable partition (each level from the one above in O(n)), so the
//! whole build is O(n log n) after the initial sort; levels are partitioned on the rayon
//! pool for large inputs.

use super::composite::{check_points, cmp_composite_y, order_by_x, PARALLEL};
use crate::kernel::{Bbox2, Point2};
use crate::Result;
use rayon::prelude::*;

/// Subsets of at most this many points are leaves: scanning them beats descending.
pub(crate) const LEAF: usize = 32;

/// The shared part of the 2D range trees.
#[derive(Debug, Clone)]
pub(crate) struct Skeleton {
    /// The points in composite x-order.
    pub pts: Vec<Point2>,
    /// `ids[r]`: the input index of `pts[r]`.
    pub ids: Vec<u32>,
    /// `level_ids[d][j]`: input indices; per node of depth `d`, its points in y-order.
    pub level_ids: Vec<Vec<u32>>,
    /// `level_ranks[d][j]`: the x-rank of `level_ids[d][j]` (layered tree only): lets a
    /// node with few candidates be filtered by a contiguous scan instead of descending.
    pub level_ranks: Vec<Vec<u32>>,
    /// Every `SAMPLE`-th x-coordinate of `pts`.
    pub x_samples: Vec<f64>,
}

/// One partition job: a node's ranks, the destination, its range, its cascade pointers.
type Job<'a> = (
    (&'a [u32], &'a mut [u32]),
    (&'a (u32, u32), Option<&'a mut [u32]>),
);

/// Every `SAMPLE`-th key of a large sorted array, kept apart so that the first steps of a
/// binary search stay in cache (a search over millions of entries otherwise pays a cache
/// miss per step).
pub(crate) const SAMPLE: usize = 64;

/// `(0..len).partition_point(pred ∘ key)` for keys sorted so that `pred` holds on a prefix,
/// narrowed first with `samples[j] = key(j * SAMPLE)`.
#[inline]
pub(crate) fn sampled_partition(
    samples: &[f64],
    len: usize,
    key: impl Fn(usize) -> f64,
    pred: impl Fn(f64) -> bool,
) -> usize {
    let s = samples.partition_point(|&v| pred(v));
    if s == 0 {
        return 0;
    }
    let from = (s - 1) * SAMPLE + 1;
    let to = (s * SAMPLE).min(len);
    let (mut lo, mut hi) = (from, to);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if pred(key(mid)) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    lo
}

/// Number of depths that hold an internal node.
pub(crate) fn internal_depths(n: usize) -> usize {
    let (mut d, mut s) = (0, n);
    while s > LEAF {
        s = s.div_ceil(2);
        d += 1;
    }
    d
}

/// The node ranges `[a, b)` of one depth, in order, from those of the depth above.
fn next_ranges(ranges: &[(u32, u32)]) -> Vec<(u32, u32)> {
    let mut out = Vec::with_capacity(2 * ranges.len());
    for &(a, b) in ranges {
        let m = a + (b - a) / 2;
        out.push((a, m));
        out.push((m, b));
    }
    out
}

/// Cut `v` into the consecutive pieces given by `ranges` (which tile `0..v.len()`).
fn pieces<'a, T>(mut v: &'a mut [T], ranges: &[(u32, u32)]) -> Vec<&'a mut [T]> {
    let mut out = Vec::with_capacity(ranges.len());
    for &(a, b) in ranges {
        let (head, tail) = v.split_at_mut((b - a) as usize);
        out.push(head);
        v = tail;
    }
    out
}

impl Skeleton {
    /// Sort the points and build the y-ordered levels. With `cascade`, also return for each
    /// level the left-child counts that fractional cascading needs.
    pub fn build(points: &[Point2], cascade: bool) -> Result<(Skeleton, Vec<Vec<u32>>)> {
        check_points(points)?;
        let n = points.len();
        let ids = order_by_x(points);
        let pts: Vec<Point2> = ids.iter().map(|&i| points[i as usize]).collect();
        let depths = internal_depths(n);
        let parallel = n >= PARALLEL;
        // Level 0: all x-ranks in (y | x | i) order; ranks follow (x | y | i), so the rank
        // breaks ties exactly as the input index does within equal points.
        let mut ranks: Vec<u32> = (0..n as u32).collect();
        let cmp = |&a: &u32, &b: &u32| {
            cmp_composite_y(pts[a as usize], a as usize, pts[b as usize], b as usize)
        };
        if parallel {
            ranks.par_sort_unstable_by(cmp);
        } else {
            ranks.sort_unstable_by(cmp);
        }
        let mut level_ids = Vec::with_capacity(depths);
        let mut level_ranks = Vec::new();
        let mut lefts = Vec::new();
        let mut ranges = vec![(0u32, n as u32)];
        for d in 0..depths {
            level_ids.push(if parallel {
                ranks.par_iter().map(|&r| ids[r as usize]).collect()
            } else {
                ranks.iter().map(|&r| ids[r as usize]).collect()
            });
            if cascade {
                level_ranks.push(ranks.clone());
            }
            if d + 1 == depths && !cascade {
                break;
            }
            let mut next = vec![0u32; n];
            let mut left = if cascade { vec![0u32; n] } else { Vec::new() };
            let src = pieces_ref(&ranks, &ranges);
            let dst = pieces(&mut next, &ranges);
            // Stable partition of each node's y-ordered ranks into its children; with
            // `cascade`, record where each position's successor lies in the left child.
            let work = |((s, t), (&(a, b), l)): Job<'_>| {
                let m = a + (b - a) / 2;
                let (mut i, mut k) = (0usize, (m - a) as usize);
                let mut l = l;
                for (j, &r) in s.iter().enumerate() {
                    if let Some(l) = l.as_deref_mut() {
                        l[j] = a + i as u32;
                    }
                    if r < m {
                        t[i] = r;
                        i += 1;
                    } else {
                        t[k] = r;
                        k += 1;
                    }
                }
            };
            let lp: Vec<Option<&mut [u32]>> = if cascade {
                pieces(&mut left, &ranges).into_iter().map(Some).collect()
            } else {
                ranges.iter().map(|_| None).collect()
            };
            let jobs: Vec<_> = src
                .into_iter()
                .zip(dst)
                .zip(ranges.iter().zip(lp))
                .collect();
            if parallel {
                jobs.into_par_iter().for_each(work);
            } else {
                jobs.into_iter().for_each(work);
            }
            if cascade {
                lefts.push(left);
            }
            ranks = next;
            ranges = next_ranges(&ranges);
        }
        let x_samples = pts.iter().step_by(SAMPLE).map(|p| p.x).collect();
        Ok((
            Skeleton {
                x_samples,
                pts,
                ids,
                level_ids,
                level_ranks,
            },
            lefts,
        ))
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        self.pts.len()
    }

    /// The x-ranks `[lo, hi)` of the points with `xmin <= x <= xmax` (contiguous in
    /// composite x-order).
    pub fn x_span(&self, rect: &Bbox2) -> (usize, usize) {
        let n = self.pts.len();
        let x = |i: usize| self.pts[i].x;
        let lo = sampled_partition(&self.x_samples, n, x, |v| v < rect.min.x);
        let hi = sampled_partition(&self.x_samples, n, x, |v| v <= rect.max.x);
        (lo, hi.max(lo))
    }

    /// Heap memory in bytes (without what the caller adds).
    pub fn memory_bytes(&self) -> usize {
        self.pts.capacity() * 16
            + self.ids.capacity() * 4
            + self
                .level_ids
                .iter()
                .map(|v| v.capacity() * 4)
                .sum::<usize>()
    }
}

fn pieces_ref<'a, T>(mut v: &'a [T], ranges: &[(u32, u32)]) -> Vec<&'a [T]> {
    let mut out = Vec::with_capacity(ranges.len());
    for &(a, b) in ranges {
        let (head, tail) = v.split_at((b - a) as usize);
        out.push(head);
        v = tail;
    }
    out
}

/// A piece of a range-tree answer: input indices `level_ids[depth][from..to]` (all in the
/// rectangle), or x-ranks `from..to` to be tested against the rectangle one by one.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Piece {
    Whole {
        depth: u32,
        from: u32,
        to: u32,
    },
    Scan {
        from: u32,
        to: u32,
    },
    /// Entries `from..to` of level `depth` whose x-rank lies in `lo..hi` (all have y in range).
    Ranked {
        depth: u32,
        from: u32,
        to: u32,
        lo: u32,
        hi: u32,
    },
}

/// The lazy answer of a range-tree query: the canonical pieces are found first (O(log n) or
/// O(log² n) work), then reported one index at a time.
#[derive(Debug, Clone)]
pub struct RangeIter<'a> {
    skel: &'a Skeleton,
    rect: Bbox2,
    pieces: std::vec::IntoIter<Piece>,
    current: Option<Piece>,
}

impl<'a> RangeIter<'a> {
    pub(crate) fn new(skel: &'a Skeleton, rect: Bbox2, pieces: Vec<Piece>) -> Self {
        RangeIter {
            skel,
            rect,
            pieces: pieces.into_iter(),
            current: None,
        }
    }
}

impl Iterator for RangeIter<'_> {
    type Item = usize;

    fn next(&mut self) -> Option<usize> {
        loop {
            match &mut self.current {
                Some(Piece::Whole { depth, from, to }) if *from < *to => {
                    let id = self.skel.level_ids[*depth as usize][*from as usize];
                    *from += 1;
                    return Some(id as usize);
                }
                Some(Piece::Ranked {
                    depth,
                    from,
                    to,
                    lo,
                    hi,
                }) if *from < *to => {
                    let (d, j) = (*depth as usize, *from as usize);
                    *from += 1;
                    let r = self.skel.level_ranks[d][j];
                    if *lo <= r && r < *hi {
                        return Some(self.skel.level_ids[d][j] as usize);
                    }
                }
                Some(Piece::Scan { from, to }) if *from < *to => {
                    let r = *from as usize;
                    *from += 1;
                    if self.rect.contains(self.skel.pts[r]) {
                        return Some(self.skel.ids[r] as usize);
                    }
                }
                _ => self.current = Some(self.pieces.next()?),
            }
        }
    }
}

/// The number of points a piece holds.
#[inline]
pub(crate) fn count_piece(skel: &Skeleton, rect: &Bbox2, piece: Piece) -> usize {
    match piece {
        Piece::Whole { from, to, .. } => (to - from) as usize,
        Piece::Ranked {
            depth,
            from,
            to,
            lo,
            hi,
        } => skel.level_ranks[depth as usize][from as usize..to as usize]
            .iter()
            .filter(|&&r| lo <= r && r < hi)
            .count(),
        Piece::Scan { from, to } => skel.pts[from as usize..to as usize]
            .iter()
            .filter(|p| rect.contains(**p))
            .count(),
    }
}

/// Call `f` with every input index the piece holds.
#[inline]
pub(crate) fn for_each_piece(
    skel: &Skeleton,
    rect: &Bbox2,
    piece: Piece,
    f: &mut impl FnMut(usize),
) {
    match piece {
        Piece::Whole { depth, from, to } => {
            for &id in &skel.level_ids[depth as usize][from as usize..to as usize] {
                f(id as usize);
            }
        }
        Piece::Ranked {
            depth,
            from,
            to,
            lo,
            hi,
        } => {
            let (d, range) = (depth as usize, from as usize..to as usize);
            for (&r, &id) in skel.level_ranks[d][range.clone()]
                .iter()
                .zip(&skel.level_ids[d][range])
            {
                if lo <= r && r < hi {
                    f(id as usize);
                }
            }
        }
        Piece::Scan { from, to } => {
            for r in from as usize..to as usize {
                if rect.contains(skel.pts[r]) {
                    f(skel.ids[r] as usize);
                }
            }
        }
    }
}
