//! Intersection of half-planes by divide and conquer (book §4.2, INTERSECTHALFPLANES).
//!
//! Split the half-planes in two halves, intersect each half recursively, and combine the
//! two convex regions with INTERSECTCONVEXREGIONS in time linear in their sizes: O(n log n)
//! overall, whatever the input (also for n lines tangent to one circle, where incremental
//! clipping takes O(n²)).
//!
//! # Regions
//!
//! As in the book, a convex region `C` is kept as its left boundary `L_left(C)` and its right
//! boundary `L_right(C)`, each the list of constraint lines carrying it sorted from bottom
//! to top, plus the lowest top and highest bottom horizontal constraint. Every region lies in
//! the *symbolic* box `|x|, |y| <= M` (`M` larger than any finite number; see
//! `exact`), so every region is bounded and every chain is finite; a result still touching
//! the box is unbounded. A left (right) constraint `a·x + b·y <= c` has `a < 0` (`a > 0`):
//! along a chain, from bottom to top, the normals turn clockwise (left) or
//! counter-clockwise (right), so the bottom-to-top order of a chain is the order of its
//! slopes and needs no constructed coordinate.
//!
//! # INTERSECTCONVEXREGIONS
//!
//! With four pointers, one into each of `L_left(C1)`, `L_left(C2)`, `L_right(C1)`,
//! `L_right(C2)`, the two left chains are merged in bottom-to-top order while a stack keeps
//! the pieces that form the new left boundary (the larger of the two left boundaries at every
//! height), and likewise on the right (the smaller); both are cut to the common height range.
//! A last sweep upwards over the breakpoints of the new left and right boundary (compared
//! exactly by height) finds where left <= right starts and stops: there the region has a
//! vertex where a left and a right edge cross, or a horizontal edge. All steps are linear.
//!
//! # Exactness and degenerate input
//!
//! Every decision — which of two parallel constraints is tighter, does an edge still show
//! between its neighbours, which of two breakpoints is lower, is a constructed corner left
//! of an edge — is one exact sign (`exact::side`, `exact::cmp_meet_y`,
//! `exact::parallel_side`, `exact::cross_sign`): an `f64` filter with exact rational
//! fallback. Parallel and identical constraints (the one with the smallest index is kept),
//! redundant constraints, many constraints through one point, and results that are a
//! segment, ray, line, point or empty need no special case: a zero-length edge shows up
//! as two equal neighbouring corners, merged exactly.

use super::exact::{parallel_side, Line};
use super::filter::{cross as cross_sign, meet_y as cmp_meet_y, side_of as side};
use super::halfplanes::{describe, empty, merge_equal_known, Corner};
use super::slope_sort::sort_chain;
use super::{check_finite, HalfPlane, Region};
use crate::Result;
use std::cmp::Ordering;

/// Indices of the box sides in the line list (see `Line::bbox`).
pub(super) const BOX_RIGHT: usize = 0;
pub(super) const BOX_LEFT: usize = 1;
pub(super) const BOX_TOP: usize = 2;
pub(super) const BOX_BOTTOM: usize = 3;

/// A non-empty convex region inside the symbolic box (see the module docs).
#[derive(Debug, Clone)]
pub(super) struct Conv {
    /// Left boundary lines (`a < 0`), bottom to top.
    pub(super) left: Vec<usize>,
    /// Right boundary lines (`a > 0`), bottom to top.
    pub(super) right: Vec<usize>,
    /// The highest bottom constraint (`a = 0`, `b < 0`).
    pub(super) bot: usize,
    /// The lowest top constraint (`a = 0`, `b > 0`).
    pub(super) top: usize,
    /// True when the region's lowest point(s) lie on `bot`; false when the bottom is a
    /// vertex where `left[0]` and `right[0]` cross above `bot`.
    pub(super) bot_edge: bool,
    /// As `bot_edge`, at the top.
    pub(super) top_edge: bool,
}

impl Conv {
    /// The whole symbolic box.
    pub(super) fn whole() -> Conv {
        Conv {
            left: vec![BOX_LEFT],
            right: vec![BOX_RIGHT],
            bot: BOX_BOTTOM,
            top: BOX_TOP,
            bot_edge: true,
            top_edge: true,
        }
    }
}

/// Intersect the half-planes by divide and conquer (book §4.2): exact, O(n log n).
/// The result is the same set, described the same way, as
/// [`intersect_halfplanes_incremental`](super::intersect_halfplanes_incremental); of identical
/// boundary lines the one with the smallest index is reported.
///
/// Errors: a non-finite coefficient ([`Error::NonFinite`](crate::Error::NonFinite)).
///
/// ```
/// use compgeom::lp::{intersect_halfplanes_dc, HalfPlane, RegionKind};
/// use compgeom::Point2;
/// // The unit square, each side given twice, plus a redundant constraint.
/// let mut hs = Vec::new();
/// for _ in 0..2 {
///     hs.extend([(-1.0, 0.0, 0.0), (1.0, 0.0, 1.0), (0.0, -1.0, 0.0), (0.0, 1.0, 1.0)]
///         .map(|(a, b, c)| HalfPlane::new(a, b, c)));
/// }
/// hs.push(HalfPlane::new(1.0, 1.0, 5.0));
/// let r = intersect_halfplanes_dc(&hs)?;
/// assert_eq!(r.kind, RegionKind::Polygon);
/// assert_eq!(r.vertices, [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)].map(Point2::from));
/// assert_eq!(r.constraints, vec![2, 1, 3, 0]);
/// # Ok::<(), compgeom::Error>(())
/// ```
pub fn intersect_halfplanes_dc(halfplanes: &[HalfPlane]) -> Result<Region> {
    intersect_halfplanes_dc_leaf(halfplanes, LEAF)
}

/// As [`intersect_halfplanes_dc`], splitting down to groups of at most `leaf` half-planes
/// (at least 1): `leaf = 1` is the book's recursion all the way down. For tests.
#[doc(hidden)]
pub fn intersect_halfplanes_dc_leaf(halfplanes: &[HalfPlane], leaf: usize) -> Result<Region> {
    check_finite(halfplanes)?;
    let mut lines = Line::bbox().to_vec();
    let mut orig = Vec::with_capacity(halfplanes.len());
    for (k, h) in halfplanes.iter().enumerate() {
        if h.a == 0.0 && h.b == 0.0 {
            if h.c < 0.0 {
                return Ok(empty());
            }
            continue;
        }
        lines.push(Line::input(h.a, h.b, h.c));
        orig.push(k);
    }
    let ids: Vec<usize> = (4..lines.len()).collect();
    let whole = Conv::whole();
    let region = if ids.is_empty() {
        Some(whole)
    } else {
        intersect_rec(&lines, &ids, &whole, leaf.max(1))
    };
    Ok(match region {
        None => empty(),
        Some(c) => describe(&lines, &orig, &corners(&lines, &c)),
    })
}

/// The intersection of the box with the half-planes `ids` (non-empty), or `None` if empty.
fn intersect_rec(lines: &[Line], ids: &[usize], whole: &Conv, leaf: usize) -> Option<Conv> {
    if ids.len() <= leaf {
        return intersect_regions(lines, whole, &small(lines, ids));
    }
    let (a, b) = ids.split_at(ids.len() / 2);
    let c1 = intersect_rec(lines, a, whole, leaf)?;
    let c2 = intersect_rec(lines, b, whole, leaf)?;
    intersect_regions(lines, &c1, &c2)
}

/// At most this many half-planes are sorted directly instead of split further (the same
/// chains, fewer small merges).
const LEAF: usize = 16;

/// A few half-planes as raw chains: left and right constraints sorted bottom to top (by
/// slope, exactly), the tightest bottom and top. Not yet reduced: intersecting with the
/// box by `intersect_regions` drops what does not show.
fn small(lines: &[Line], ids: &[usize]) -> Conv {
    let mut c = Conv {
        left: Vec::new(),
        right: Vec::new(),
        bot: BOX_BOTTOM,
        top: BOX_TOP,
        bot_edge: true,
        top_edge: true,
    };
    for &i in ids {
        let l = &lines[i];
        if l.a < 0.0 {
            c.left.push(i);
        } else if l.a > 0.0 {
            c.right.push(i);
        } else if l.b < 0.0 {
            c.bot = tighter(lines, c.bot, i);
        } else {
            c.top = tighter(lines, c.top, i);
        }
    }
    // Bottom-to-top order of each chain: exact, by slope (see `slope_sort`).
    sort_chain(lines, &mut c.left);
    sort_chain(lines, &mut c.right);
    c
}

/// Of two parallel constraints with the same direction, the tighter one (on ties the
/// smaller index, which is the earlier input constraint).
pub(super) fn tighter(lines: &[Line], i: usize, j: usize) -> usize {
    if i == j {
        return i;
    }
    match parallel_side(&lines[i], &lines[j]) {
        Ordering::Less => i,
        Ordering::Greater => j,
        Ordering::Equal => i.min(j),
    }
}

/// INTERSECTCONVEXREGIONS: the intersection of two regions, or `None` if it is empty.
pub(super) fn intersect_regions(lines: &[Line], c1: &Conv, c2: &Conv) -> Option<Conv> {
    let bot = tighter(lines, c1.bot, c2.bot);
    let top = tighter(lines, c1.top, c2.top);
    // The top line below the bottom line: nothing in between.
    if parallel_side(&lines[top], &lines[bot]) == Ordering::Greater {
        return None;
    }
    let left = merge_chains(lines, &c1.left, &c2.left, bot, top, Ordering::Less);
    let right = merge_chains(lines, &c1.right, &c2.right, bot, top, Ordering::Greater);
    cut(lines, left, right, bot, top)
}

/// The boundary of the intersection of two left (`turn = Less`) or two right (`turn =
/// Greater`) boundaries, bottom to top, over the heights between `bot` and `top`:
/// `turn` is the sign of the cross product of consecutive normals along a chain.
fn merge_chains(
    lines: &[Line],
    a: &[usize],
    b: &[usize],
    bot: usize,
    top: usize,
    turn: Ordering,
) -> Vec<usize> {
    let mut out: Vec<usize> = Vec::with_capacity(a.len() + b.len());
    let (mut p, mut q) = (0, 0);
    while p < a.len() || q < b.len() {
        // The next line in slope (= bottom-to-top) order; of parallel ones the tighter.
        let next = if q == b.len() {
            p += 1;
            a[p - 1]
        } else if p == a.len() {
            q += 1;
            b[q - 1]
        } else {
            let (i, j) = (a[p], b[q]);
            let s = cross_sign(&lines[i], &lines[j]);
            if s == turn {
                p += 1;
                i
            } else if s == Ordering::Equal {
                p += 1;
                q += 1;
                tighter(lines, i, j)
            } else {
                q += 1;
                j
            }
        };
        push_envelope(lines, &mut out, next);
    }
    // Keep only the pieces inside the height range: drop a first piece ending at or below
    // `bot`, a last piece starting at or above `top`.
    let mut first = 0;
    while first + 1 < out.len()
        && side(&lines[out[first]], &lines[out[first + 1]], &lines[bot]) != Ordering::Less
    {
        first += 1;
    }
    out.drain(..first);
    while out.len() >= 2
        && side(
            &lines[out[out.len() - 2]],
            &lines[out[out.len() - 1]],
            &lines[top],
        ) != Ordering::Less
    {
        out.pop();
    }
    out
}

/// Add line `l` (next in slope order, possibly parallel to the last) to the boundary
/// `out`, dropping the pieces it hides.
fn push_envelope(lines: &[Line], out: &mut Vec<usize>, l: usize) {
    if let Some(&t) = out.last() {
        if cross_sign(&lines[t], &lines[l]) == Ordering::Equal {
            // Parallel (same direction): only the tighter can show.
            let k = tighter(lines, t, l);
            if k == t {
                return;
            }
            out.pop();
        }
    }
    // The last piece shows only if the corner of its lower neighbour and `l` is strictly
    // outside it.
    while out.len() >= 2 {
        let (s, t) = (out[out.len() - 2], out[out.len() - 1]);
        if side(&lines[s], &lines[l], &lines[t]) == Ordering::Greater {
            break;
        }
        out.pop();
    }
    out.push(l);
}

/// Where the sweep is: the next breakpoint of the left or right boundary, or the top.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Event {
    Left,
    Right,
    Top,
}

/// Cut the left and right boundaries (each over the whole height range `bot..top`) to
/// the heights where left <= right: one sweep upwards over their breakpoints.
fn cut(lines: &[Line], l: Vec<usize>, r: Vec<usize>, bot: usize, top: usize) -> Option<Conv> {
    let ln = |k: usize| &lines[k];
    let (mut i, mut j) = (0usize, 0usize);
    let next = |i: usize, j: usize| -> Event {
        match (i + 1 < l.len(), j + 1 < r.len()) {
            (true, true) => match cmp_meet_y(ln(l[i]), ln(l[i + 1]), ln(r[j]), ln(r[j + 1])) {
                Ordering::Greater => Event::Right,
                _ => Event::Left,
            },
            (true, false) => Event::Left,
            (false, true) => Event::Right,
            (false, false) => Event::Top,
        }
    };
    // Is left <= right at the height of the event (edges l[i], r[j] active below it)?
    let fits = |ev: Event, i: usize, j: usize| -> bool {
        match ev {
            Event::Left => side(ln(l[i]), ln(l[i + 1]), ln(r[j])) != Ordering::Greater,
            Event::Right => side(ln(r[j]), ln(r[j + 1]), ln(l[i])) != Ordering::Greater,
            Event::Top => side(ln(l[i]), ln(top), ln(r[j])) != Ordering::Greater,
        }
    };
    let bot_edge = side(ln(l[0]), ln(bot), ln(r[0])) != Ordering::Greater;
    if !bot_edge {
        // Up to the first height where left <= right; the edges active just below it
        // cross there (a vertex).
        loop {
            let ev = next(i, j);
            if fits(ev, i, j) {
                break;
            }
            match ev {
                Event::Left => i += 1,
                Event::Right => j += 1,
                Event::Top => return None,
            }
        }
    }
    let (i0, j0) = (i, j);
    // Up to the last height where left <= right.
    let top_edge = loop {
        let ev = next(i, j);
        if !fits(ev, i, j) {
            break false;
        }
        match ev {
            Event::Left => i += 1,
            Event::Right => j += 1,
            Event::Top => break true,
        }
    };
    Some(Conv {
        left: l[i0..=i].to_vec(),
        right: r[j0..=j].to_vec(),
        bot,
        top,
        bot_edge,
        top_edge,
    })
}

/// The region's corners counter-clockwise (bottom edge, right boundary upwards, top edge,
/// left boundary downwards), zero-length edges merged away.
///
/// Inside one chain no edge has length zero: `push_envelope` keeps a line `y` between its
/// neighbours `x` and `z` only when the corner of `x` and `z` is strictly outside `y`,
/// which `z` through the corner of `x` and `y` would contradict (that corner would then
/// lie on `y`). Only corners where the chains meet the bottom, the top or each other are
/// tested.
pub(super) fn corners(lines: &[Line], c: &Conv) -> Vec<Corner> {
    let mut edges = Vec::with_capacity(c.left.len() + c.right.len() + 2);
    if c.bot_edge {
        edges.push(c.bot);
    }
    let right = edges.len()..edges.len() + c.right.len();
    edges.extend_from_slice(&c.right);
    if c.top_edge {
        edges.push(c.top);
    }
    let left = edges.len()..edges.len() + c.left.len();
    edges.extend(c.left.iter().rev());
    let n = edges.len();
    let out: Vec<Corner> = (0..n)
        .map(|k| Corner {
            v: (edges[(k + n - 1) % n], edges[k]),
            edge: edges[k],
        })
        .collect();
    // Corners k and k + 1 are (edges[k - 1], edges[k]) and (edges[k], edges[k + 1]).
    let inside = |r: &std::ops::Range<usize>, k: usize| k > r.start && k + 1 < r.end;
    merge_equal_known(lines, out, |k| inside(&right, k) || inside(&left, k))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_only_is_the_whole_plane() {
        let r = intersect_halfplanes_dc(&[]).unwrap();
        assert_eq!(r.kind, super::super::RegionKind::Unbounded);
        assert!(r.vertices.is_empty());
    }
}
