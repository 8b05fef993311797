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
//! From 512 constraints on, an evenly spread sample of about `4·√n` is intersected first.
//! Its region contains the answer: if it is empty, so is the answer; if it is a bounded
//! polygon, a constraint whose open half-plane contains the polygon's bounding box (an
//! `f64` test with a rigorous error bound, answering "unsure" rather than wrongly) cannot
//! touch the answer and is left out before sorting. On typical input most constraints
//! are redundant and go here in a few operations each; on input where every constraint
//! counts (tangents of a circle) the test costs a few operations and removes nothing.
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
use super::{check_finite, HalfPlane, Region, RegionKind};
use crate::kernel::Point2;
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
    let n = halfplanes.len();
    if n < PRUNE_MIN {
        return Ok(sweep(halfplanes, 0..n));
    }
    // The region of an evenly spread sample contains the answer: if it is empty, so is the
    // answer; if it is a bounded polygon, every constraint whose half-plane strictly
    // contains the polygon's bounding box cannot touch the answer and is left out.
    let m = ((4.0 * (n as f64).sqrt()) as usize).clamp(64, n / 4);
    let sample: Vec<HalfPlane> = (0..m).map(|t| halfplanes[t * n / m]).collect();
    let r = sweep(&sample, 0..m);
    match r.kind {
        RegionKind::Empty => Ok(r),
        RegionKind::Polygon => {
            let b = Bounds::around(&r.vertices);
            Ok(sweep(
                halfplanes,
                (0..n).filter(|&k| !b.strictly_inside(&halfplanes[k])),
            ))
        }
        _ => Ok(sweep(halfplanes, 0..n)),
    }
}

/// Inputs with at least this many constraints are pruned with a sample's region first.
const PRUNE_MIN: usize = 512;

/// A box `[x0, x1] × [y0, y1]` containing a set of exact points of which we know the
/// nearest `f64`s.
struct Bounds {
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
}

impl Bounds {
    /// Each exact point lies within half a gap of its rounded value, and a gap is at most
    /// `2^-52·|v|` (or `2^-1074` near zero): widening by `2^-50·|v| + 1e-300` covers it with
    /// room for the rounding of the widening itself.
    fn around(ps: &[Point2]) -> Bounds {
        let lo = |v: f64| v - (v.abs() * (1.0 / 1_125_899_906_842_624.0) + 1e-300);
        let hi = |v: f64| v + (v.abs() * (1.0 / 1_125_899_906_842_624.0) + 1e-300);
        let mut b = Bounds {
            x0: f64::INFINITY,
            x1: f64::NEG_INFINITY,
            y0: f64::INFINITY,
            y1: f64::NEG_INFINITY,
        };
        for p in ps {
            b.x0 = b.x0.min(lo(p.x));
            b.x1 = b.x1.max(hi(p.x));
            b.y0 = b.y0.min(lo(p.y));
            b.y1 = b.y1.max(hi(p.y));
        }
        b
    }

    /// True when the box lies in the open half-plane `a·x + b·y < c`: the box corner
    /// furthest along `(a, b)` satisfies it by more than the rounding error of the `f64`
    /// evaluation (four operations, `4u` times the sum of absolute values, plus underflow).
    /// False when unsure.
    #[inline]
    fn strictly_inside(&self, h: &HalfPlane) -> bool {
        let x = if h.a > 0.0 { self.x1 } else { self.x0 };
        let y = if h.b > 0.0 { self.y1 } else { self.y0 };
        let (px, py) = (h.a * x, h.b * y);
        let v = px + py - h.c;
        let e = (px.abs() + py.abs() + h.c.abs()) * (4.0 / 9_007_199_254_740_992.0) + 1e-300;
        v < -e
    }
}

/// The intersection of the half-planes `ids` (increasing) of `halfplanes` (all finite):
/// sort the chains, then one INTERSECTCONVEXREGIONS with the box.
fn sweep(halfplanes: &[HalfPlane], ids: impl Iterator<Item = usize>) -> Region {
    let mut input: Vec<Line> = Vec::with_capacity(halfplanes.len());
    let mut at: Vec<usize> = Vec::with_capacity(halfplanes.len());
    let (mut left, mut right, mut flat) = (Vec::new(), Vec::new(), Vec::new());
    for k in ids {
        let h = &halfplanes[k];
        let slot = input.len();
        if h.a < 0.0 {
            left.push(slot);
        } else if h.a > 0.0 {
            right.push(slot);
        } else if h.b != 0.0 {
            flat.push(slot);
        } else if h.c < 0.0 {
            // 0·x + 0·y <= c < 0: nothing satisfies it.
            return empty();
        } else {
            continue;
        }
        input.push(Line::input(h.a, h.b, h.c));
        at.push(k);
    }
    sort_chain(&input, &mut left);
    sort_chain(&input, &mut right);
    // Box sides first, then the left chain, the right chain and the horizontal constraints,
    // each in sorted (resp. input) order; `orig` maps back to the input.
    let mut lines = Line::bbox().to_vec();
    lines.reserve(input.len());
    let mut orig = Vec::with_capacity(input.len());
    for &s in left.iter().chain(&right).chain(&flat) {
        lines.push(input[s]);
        orig.push(at[s]);
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
    match intersect_regions(&lines, &Conv::whole(), &c) {
        None => empty(),
        Some(r) => describe(&lines, &orig, &corners(&lines, &r)),
    }
}
