//! Intersection of half-planes (book §4.2).
//!
//! The region starts as a *symbolic* box `|x|, |y| <= M` (`M` larger than any finite
//! number) and is clipped by each half-plane in a seeded random order. A corner is kept
//! as the two lines that meet there, so every test "is this corner inside that half-plane"
//! is one exact sign ([`side`]); corners on the box are at infinity and make the region
//! unbounded. Time O(n·h), where h is the size of the region while it is built (expected
//! small for random order on typical input; O(n²) in the worst case, e.g. all lines
//! tangent to one circle).
//!
//! # Result
//!
//! A [`Region`]: its [`RegionKind`] (empty, point, segment, ray, line, bounded polygon, or
//! unbounded two-dimensional region), its finite corners counter-clockwise (region on the
//! left; a bounded polygon starts at its lexicographically smallest corner, an unbounded
//! boundary starts where it comes in from infinity), and the input constraints that bound
//! it in boundary order. Redundant, parallel and identical constraints are ordinary input;
//! of identical boundary lines the one added first is reported.

use super::exact::{meet_exact, side, to_f64, Line};
use super::filter::side_of;
use super::round_meet::meet_rounded;
use super::{check_finite, HalfPlane, Shuffler};
use crate::kernel::{Point2, Vector2};
use crate::Result;
use std::cmp::Ordering;

/// What kind of set a half-plane intersection is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum RegionKind {
    /// No point satisfies every constraint.
    Empty,
    /// A single point.
    Point,
    /// A segment of positive length.
    Segment,
    /// A ray (a half-line).
    Ray,
    /// A whole line.
    Line,
    /// A bounded convex polygon with interior.
    Polygon,
    /// An unbounded region with interior (also the whole plane, with no constraints).
    Unbounded,
}

impl RegionKind {
    /// The lower-case name used in JSON output (`"polygon"`, `"empty"`, …).
    pub fn name(self) -> &'static str {
        match self {
            RegionKind::Empty => "empty",
            RegionKind::Point => "point",
            RegionKind::Segment => "segment",
            RegionKind::Ray => "ray",
            RegionKind::Line => "line",
            RegionKind::Polygon => "polygon",
            RegionKind::Unbounded => "unbounded",
        }
    }
}

/// The intersection of a set of half-planes.
#[derive(Debug, Clone, PartialEq)]
pub struct Region {
    /// Which kind of set it is.
    pub kind: RegionKind,
    /// The finite corners, counter-clockwise (nearest `f64` of each exact corner). For a
    /// segment: its two ends; for a ray: its apex; for a line: none.
    pub vertices: Vec<Point2>,
    /// The input constraints whose lines carry the boundary, in boundary order (for a
    /// polygon, constraint `k` runs from `vertices[k]` to `vertices[k + 1]`; for a segment
    /// or ray, the constraints that cut off its ends are listed too, each before the edge
    /// leaving that end). For a point: two constraints whose lines meet there — together
    /// they need not pin the point down, and which two may differ between the algorithms.
    pub constraints: Vec<usize>,
    /// The whole boundary as corners `base + M·dir` of the region clipped to the symbolic
    /// box (`dir` zero for finite corners), counter-clockwise. Used for drawing.
    pub outline: Vec<(Point2, Vector2)>,
}

impl Region {
    /// The region clipped to the square `|x|, |y| <= r` for a large `r` (the symbolic `M`
    /// replaced by `r`): a polygon to draw. Exact only in its combinatorics, for `r` beyond
    /// every finite corner.
    pub fn clipped(&self, r: f64) -> Vec<Point2> {
        self.outline
            .iter()
            .map(|(p, d)| Point2::new(p.x + r * d.x, p.y + r * d.y))
            .collect()
    }
}

/// A corner (the two lines meeting there) and the line of the edge leaving it.
#[derive(Debug, Clone, Copy)]
pub(super) struct Corner {
    pub(super) v: (usize, usize),
    pub(super) edge: usize,
}

/// Intersect the half-planes (every `a·x + b·y <= c`): exact, O(n log n), by one exact
/// slope sort and one sweep ([`intersect_halfplanes_scan`](super::intersect_halfplanes_scan),
/// several times faster than the book's divide and conquer
/// [`intersect_halfplanes_dc`](super::intersect_halfplanes_dc), whose answer it equals).
/// `seed` is kept for compatibility and does not change anything; the randomized
/// incremental method is [`intersect_halfplanes_incremental`].
///
/// Errors: a non-finite coefficient ([`Error::NonFinite`](crate::Error::NonFinite)).
///
/// ```
/// use compgeom::lp::{intersect_halfplanes, HalfPlane, RegionKind};
/// use compgeom::Point2;
/// // The triangle x >= 0, y >= 0, x + y <= 2, plus a redundant x <= 5.
/// let hs = [
///     HalfPlane::new(-1.0, 0.0, 0.0),
///     HalfPlane::new(0.0, -1.0, 0.0),
///     HalfPlane::new(1.0, 1.0, 2.0),
///     HalfPlane::new(1.0, 0.0, 5.0),
/// ];
/// let r = intersect_halfplanes(&hs, 0)?;
/// assert_eq!(r.kind, RegionKind::Polygon);
/// assert_eq!(r.vertices, [(0.0, 0.0), (2.0, 0.0), (0.0, 2.0)].map(Point2::from));
/// assert_eq!(r.constraints, vec![1, 2, 0]);
/// // x <= 0 and x >= 0: the line x = 0.
/// let r = intersect_halfplanes(&[HalfPlane::new(1.0, 0.0, 0.0), HalfPlane::new(-1.0, 0.0, 0.0)], 0)?;
/// assert_eq!(r.kind, RegionKind::Line);
/// # Ok::<(), compgeom::Error>(())
/// ```
pub fn intersect_halfplanes(halfplanes: &[HalfPlane], seed: u64) -> Result<Region> {
    let _ = seed;
    super::intersect_halfplanes_scan(halfplanes)
}

/// Intersect the half-planes by randomized incremental clipping of the symbolic box
/// (expected O(n·h), O(n²) in the worst case); `seed` fixes the random order (the answer
/// does not depend on it, except which of identical boundary lines is reported).
///
/// Errors: a non-finite coefficient ([`Error::NonFinite`](crate::Error::NonFinite)).
///
/// ```
/// use compgeom::lp::{intersect_halfplanes_incremental, HalfPlane, RegionKind};
/// use compgeom::Point2;
/// // The triangle x >= 0, y >= 0, x + y <= 2, plus a redundant x <= 5.
/// let hs = [
///     HalfPlane::new(-1.0, 0.0, 0.0),
///     HalfPlane::new(0.0, -1.0, 0.0),
///     HalfPlane::new(1.0, 1.0, 2.0),
///     HalfPlane::new(1.0, 0.0, 5.0),
/// ];
/// let r = intersect_halfplanes_incremental(&hs, 7)?;
/// assert_eq!(r.kind, RegionKind::Polygon);
/// assert_eq!(r.vertices, [(0.0, 0.0), (2.0, 0.0), (0.0, 2.0)].map(Point2::from));
/// assert_eq!(r.constraints, vec![1, 2, 0]);
/// // x <= 0 and x >= 0: the line x = 0.
/// let r = intersect_halfplanes_incremental(&[HalfPlane::new(1.0, 0.0, 0.0), HalfPlane::new(-1.0, 0.0, 0.0)], 0)?;
/// assert_eq!(r.kind, RegionKind::Line);
/// # Ok::<(), compgeom::Error>(())
/// ```
pub fn intersect_halfplanes_incremental(halfplanes: &[HalfPlane], seed: u64) -> Result<Region> {
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
    let mut order: Vec<usize> = (4..lines.len()).collect();
    Shuffler::new(seed).shuffle(&mut order);
    // The box, counter-clockwise from (-M, -M); edges y >= -M, x <= M, y <= M, x >= -M.
    let mut poly = vec![
        Corner { v: (1, 3), edge: 3 },
        Corner { v: (3, 0), edge: 0 },
        Corner { v: (0, 2), edge: 2 },
        Corner { v: (2, 1), edge: 1 },
    ];
    let mut sides = Vec::new();
    for &i in &order {
        if !clip(&lines, &mut poly, i, &mut sides) {
            return Ok(empty());
        }
    }
    Ok(describe(&lines, &orig, &poly))
}

pub(super) fn empty() -> Region {
    Region {
        kind: RegionKind::Empty,
        vertices: Vec::new(),
        constraints: Vec::new(),
        outline: Vec::new(),
    }
}

/// Clip the convex region by half-plane `i`; false when nothing is left.
fn clip(lines: &[Line], poly: &mut Vec<Corner>, i: usize, sides: &mut Vec<Ordering>) -> bool {
    let li = &lines[i];
    sides.clear();
    sides.extend(poly.iter().map(|c| side(&lines[c.v.0], &lines[c.v.1], li)));
    if sides.iter().all(|&s| s != Ordering::Greater) {
        return true;
    }
    if sides.iter().all(|&s| s == Ordering::Greater) {
        poly.clear();
        return false;
    }
    let n = poly.len();
    let mut out: Vec<Corner> = Vec::with_capacity(n + 2);
    for k in 0..n {
        let (p, sp, sq) = (poly[k], sides[k], sides[(k + 1) % n]);
        use Ordering::*;
        match (sp, sq) {
            (Less, Greater) => {
                out.push(p);
                out.push(Corner {
                    v: (p.edge, i),
                    edge: i,
                });
            }
            (Equal, Greater) => out.push(Corner { v: p.v, edge: i }),
            (Less | Equal, _) => out.push(p),
            (Greater, Less) => out.push(Corner {
                v: (p.edge, i),
                edge: p.edge,
            }),
            (Greater, _) => {}
        }
    }
    // A degenerate (two-corner) region crossed by the line yields the same point twice,
    // once on each of its two coincident edges: merge equal neighbours.
    let merged = merge_equal(lines, out);
    *poly = merged;
    !poly.is_empty()
}

/// Merge neighbouring corners at the same exact point (the edge between them has length
/// zero): the first keeps its lines and takes the later outgoing edge.
pub(super) fn merge_equal(lines: &[Line], out: Vec<Corner>) -> Vec<Corner> {
    merge_equal_known(lines, out, |_| false)
}

/// As [`merge_equal`], where `distinct(k)` true means corners `k` and `k + 1` of `out` are
/// known to be different points (then they are not tested).
pub(super) fn merge_equal_known(
    lines: &[Line],
    out: Vec<Corner>,
    distinct: impl Fn(usize) -> bool,
) -> Vec<Corner> {
    // (A corner is trivially on its own lines; testing those would only cost exact zeros.)
    let same = |a: &Corner, b: &Corner| {
        [b.v.0, b.v.1].iter().all(|&k| {
            k == a.v.0
                || k == a.v.1
                || side_of(&lines[a.v.0], &lines[a.v.1], &lines[k]) == Ordering::Equal
        })
    };
    let mut merged: Vec<Corner> = Vec::with_capacity(out.len());
    for (k, c) in out.into_iter().enumerate() {
        // The last merged corner is at the point of corner k - 1 (only equal points are
        // merged into it).
        match merged.last_mut() {
            Some(last) if !distinct(k - 1) && same(last, &c) => last.edge = c.edge,
            _ => merged.push(c),
        }
    }
    while merged.len() > 1 && same(&merged[merged.len() - 1], &merged[0]) {
        // The last corner is merged[0] again: the edge between them has length zero.
        merged.pop();
    }
    merged
}

/// Turn the clipped box into the public description.
pub(super) fn describe(lines: &[Line], orig: &[usize], poly: &[Corner]) -> Region {
    let n = poly.len();
    let finite: Vec<bool> = poly
        .iter()
        .map(|c| !lines[c.v.0].is_box() && !lines[c.v.1].is_box())
        .collect();
    // Each corner as `base + M·dir`: finite corners rounded in integer arithmetic where
    // the scales allow, else (and for corners on the box) through exact rationals.
    let exact = |c: &Corner| meet_exact(&lines[c.v.0], &lines[c.v.1]);
    let outline_of = |c: &Corner| -> (Point2, Vector2) {
        if let Some((x, y)) = meet_rounded(&lines[c.v.0], &lines[c.v.1]) {
            return (Point2::new(x, y), Vector2::new(0.0, 0.0));
        }
        let ((x0, y0), (x1, y1)) = exact(c);
        (
            Point2::new(to_f64(&x0), to_f64(&y0)),
            Vector2::new(to_f64(&x1), to_f64(&y1)),
        )
    };
    let rounded: Vec<(Point2, Vector2)> = poly.iter().map(outline_of).collect();
    let nf = finite.iter().filter(|&&f| f).count();
    let kind = match (n, nf) {
        (0, _) => RegionKind::Empty,
        (1, _) => RegionKind::Point,
        (2, 2) => RegionKind::Segment,
        (2, 1) => RegionKind::Ray,
        (2, _) => RegionKind::Line,
        (_, f) if f == n => RegionKind::Polygon,
        _ => RegionKind::Unbounded,
    };
    // Start: a bounded region at its lexicographically smallest corner; an unbounded one
    // where its boundary comes in from infinity (after the last box edge).
    let start = if nf == n {
        // Rounding to nearest is monotone: rounded keys decide unless they are equal.
        let cmp = |a: usize, b: usize| -> Ordering {
            let (p, q) = (rounded[a].0, rounded[b].0);
            match p.x.total_cmp(&q.x).then(p.y.total_cmp(&q.y)) {
                Ordering::Equal => exact(&poly[a]).0.cmp(&exact(&poly[b]).0),
                o => o,
            }
        };
        (0..n).min_by(|&a, &b| cmp(a, b)).unwrap_or(0)
    } else {
        // Where the boundary comes in from infinity (after a box edge); a strip has two
        // such places and a line none (then any end at infinity): of the candidates, the
        // one with the lexicographically smallest direction and base, whatever order the
        // corners came in.
        let key = |k: usize| {
            let (b, d) = rounded[k];
            [d.x, d.y, b.x, b.y]
        };
        let smallest = |a: &usize, b: &usize| {
            key(*a)
                .iter()
                .zip(key(*b).iter())
                .map(|(p, q)| p.total_cmp(q))
                .find(|o| o.is_ne())
                .unwrap_or(Ordering::Equal)
        };
        (0..n)
            .filter(|&k| {
                lines[poly[(k + n - 1) % n].edge].is_box() && !lines[poly[k].edge].is_box()
            })
            .min_by(smallest)
            .or_else(|| (0..n).filter(|&k| !finite[k]).min_by(smallest))
            .unwrap_or(0)
    };
    let mut vertices = Vec::new();
    let mut constraints = Vec::new();
    let mut outline = Vec::new();
    for t in 0..n {
        let k = (start + t) % n;
        let (base, dir) = rounded[k];
        if finite[k] {
            vertices.push(base);
        }
        outline.push((base, dir));
        let e = poly[k].edge;
        if n <= 2 {
            // A point, segment, ray or line: its corners are cut by constraints that carry
            // no edge; list them too, before the edge leaving the corner.
            let into = poly[(k + n - 1) % n].edge;
            for l in [poly[k].v.0, poly[k].v.1] {
                if (n == 1 || (l != e && l != into)) && !lines[l].is_box() {
                    constraints.push(orig[l - 4]);
                }
            }
        }
        if !lines[e].is_box() && n > 1 {
            constraints.push(orig[e - 4]);
        }
    }
    constraints.dedup();
    Region {
        kind,
        vertices,
        constraints,
        outline,
    }
}
