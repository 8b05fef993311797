//! Intersection of half-planes by one exact slope sort and one linear sweep (book §4.2).
//!
//! The divide-and-conquer method ([`intersect_halfplanes_dc`](super::intersect_halfplanes_dc))
//! spends its O(n log n) on merging boundary chains level by level. Here the chains are
//! sorted once instead, exactly (`slope_sort`: the correctly rounded slope `b / |a|` as a
//! radix-sort key, exact cross products only between equal keys), and the book's
//! INTERSECTCONVEXREGIONS is run once, between the symbolic box and the sorted chains: a
//! stack pass per chain keeps the pieces that show (the upper envelope of the left
//! constraints, the lower one of the right constraints) and one sweep upwards over their
//! breakpoints cuts them where left <= right. Time O(n log n) for the sort in the worst case
//! (O(n) radix passes plus exact sorting of slopes that round alike), O(n) for the rest.
//!
//! The lines are copied into sorted order before the sweep, so that it reads memory in
//! order; of identical lines the one from the earliest input constraint still comes first.
//!
//! The answer is the same [`Region`], described the same way, as the divide-and-conquer and
//! the incremental methods give (the same exact decisions, `exact` and `filter`): parallel,
//! identical and redundant constraints, many constraints through one point, and results
//! that are a segment, ray, line, point or empty need no special case.

use super::exact::Line;
use super::halfplanes::{describe, empty};
use super::halfplanes_dc::{corners, intersect_regions, tighter, Conv, BOX_BOTTOM, BOX_TOP};
use super::slope_sort::sort_chain;
use super::{check_finite, HalfPlane, Region};
use crate::Result;

/// Intersect the half-planes (every `a·x + b·y <= c`) by one exact slope sort and one
/// linear sweep: exact, O(n log n) worst case, and in practice several times faster than
/// [`intersect_halfplanes_dc`](super::intersect_halfplanes_dc), whose result it equals
/// (of identical boundary lines the one with the smallest index is reported).
///
/// Errors: a non-finite coefficient ([`Error::NonFinite`](crate::Error::NonFinite)).
///
/// ```
/// use compgeom::lp::{intersect_halfplanes_dc, intersect_halfplanes_scan, HalfPlane, RegionKind};
/// use compgeom::Point2;
/// // The unit square, each side given twice, plus a redundant constraint.
/// let mut hs = Vec::new();
/// for _ in 0..2 {
///     hs.extend([(-1.0, 0.0, 0.0), (1.0, 0.0, 1.0), (0.0, -1.0, 0.0), (0.0, 1.0, 1.0)]
///         .map(|(a, b, c)| HalfPlane::new(a, b, c)));
/// }
/// hs.push(HalfPlane::new(1.0, 1.0, 5.0));
/// let r = intersect_halfplanes_scan(&hs)?;
/// assert_eq!(r.kind, RegionKind::Polygon);
/// assert_eq!(r.vertices, [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)].map(Point2::from));
/// assert_eq!(r.constraints, vec![2, 1, 3, 0]);
/// assert_eq!(r, intersect_halfplanes_dc(&hs)?);
/// # Ok::<(), compgeom::Error>(())
/// ```
pub fn intersect_halfplanes_scan(halfplanes: &[HalfPlane]) -> Result<Region> {
    check_finite(halfplanes)?;
    let input: Vec<Line> = halfplanes
        .iter()
        .map(|h| Line::input(h.a, h.b, h.c))
        .collect();
    let (mut left, mut right, mut flat) = (Vec::new(), Vec::new(), Vec::new());
    for (k, h) in halfplanes.iter().enumerate() {
        if h.a < 0.0 {
            left.push(k);
        } else if h.a > 0.0 {
            right.push(k);
        } else if h.b != 0.0 {
            flat.push(k);
        } else if h.c < 0.0 {
            // 0·x + 0·y <= c < 0: nothing satisfies it.
            return Ok(empty());
        }
    }
    sort_chain(&input, &mut left);
    sort_chain(&input, &mut right);
    // Box sides first, then the left chain, the right chain and the horizontal constraints,
    // each in sorted (resp. input) order; `orig` maps back to the input.
    let mut lines = Line::bbox().to_vec();
    let mut orig = Vec::with_capacity(halfplanes.len());
    for &k in left.iter().chain(&right).chain(&flat) {
        lines.push(input[k]);
        orig.push(k);
    }
    drop(input);
    let (nl, nr) = (left.len(), right.len());
    let mut c = Conv {
        left: (4..4 + nl).collect(),
        right: (4 + nl..4 + nl + nr).collect(),
        bot: BOX_BOTTOM,
        top: BOX_TOP,
        bot_edge: true,
        top_edge: true,
    };
    for i in 4 + nl + nr..lines.len() {
        if lines[i].b < 0.0 {
            c.bot = tighter(&lines, c.bot, i);
        } else {
            c.top = tighter(&lines, c.top, i);
        }
    }
    Ok(match intersect_regions(&lines, &Conv::whole(), &c) {
        None => empty(),
        Some(r) => describe(&lines, &orig, &corners(&lines, &r)),
    })
}
