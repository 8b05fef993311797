//! Constructed points: segment crossings, kept as the two segments that define them,
//! and exact comparisons mixing them with input points.
//!
//! A crossing `c` of the lines through `s = (a, b)` and `t` is
//! `a + (b - a) · num / den` with `den = (b - a) × (t.b - t.a)` and
//! `num = (t.a - a) × (t.b - t.a)` (both of degree 2), so relative to any input point
//! `r` it has the homogeneous coordinates `((a - r)·den + (b - a)·num, den)`: a
//! numerator of degree 3 over a denominator of degree 2. Every decision below is the
//! sign of a polynomial in differences of input coordinates built from these
//! (degree 3 for crossing vs point, 4 for an orientation with two input points or with
//! two points on one input segment, 5 for crossing vs crossing, up to 8 for an
//! orientation of three crossings otherwise).
//!
//! Each sign is first evaluated in `f64` with a rigorous running error bound
//! ([`super::filter::Bounded`]), then, when that bound does not exclude zero, in
//! double-double arithmetic with its own bound ([`super::filter::DoubleDouble`]); only
//! when neither excludes zero is it evaluated again exactly ([`super::exact`]). The
//! number of exact evaluations is counted (`crossing_fallbacks()`, hidden from the docs).
//!
//! All coordinates are assumed finite. With NaN or infinite coordinates nothing panics,
//! but the answers are unspecified. A `Crossing` built by hand from parallel or
//! degenerate segments (bypassing [`Crossing::new`]) likewise gives unspecified
//! comparisons, and [`Crossing::approx`] returns NaN for it.

use super::arith::{mul_sign, Arith};
use super::exact::{nearest_f64, Dyadic};
use super::filter::{count, Bounded, DoubleDouble, CROSSING_FALLBACKS};
use super::predicates::{compare_xy as compare_input_xy, orient2d, Orientation};
use super::types::{Point2, Segment2};
use num_rational::BigRational;
use std::cmp::Ordering;

/// The crossing point of two non-parallel segments' supporting lines, represented by
/// the segments themselves. Comparisons are exact; [`Crossing::approx`] rounds.
///
/// ```
/// use compgeom::kernel::Crossing;
/// use compgeom::{Point2, Segment2};
/// let s = Segment2::new(Point2::new(0.0, 0.0), Point2::new(3.0, 3.0));
/// let t = Segment2::new(Point2::new(0.0, 1.0), Point2::new(1.0, 0.0));
/// let c = Crossing::new(s, t).unwrap();
/// assert_eq!(c.approx(), Point2::new(0.5, 0.5));
/// // Exactly on the diagonal, exactly left of (0.5, 0.6):
/// assert_eq!(c.compare_xy_point(Point2::new(0.5, 0.6)), std::cmp::Ordering::Less);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crossing {
    /// First defining segment.
    pub s: Segment2,
    /// Second defining segment.
    pub t: Segment2,
}

/// A point an algorithm works with: an input point, or a constructed crossing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ExactPoint {
    /// An input point (its coordinates are exact `f64` values).
    Input(Point2),
    /// The crossing of two segments' supporting lines.
    Crossing(Crossing),
}

impl From<Point2> for ExactPoint {
    fn from(p: Point2) -> Self {
        ExactPoint::Input(p)
    }
}

impl From<Crossing> for ExactPoint {
    fn from(c: Crossing) -> Self {
        ExactPoint::Crossing(c)
    }
}

/// Homogeneous coordinates `(u / w, v / w)` of a point relative to a reference point.
struct Hom<T> {
    u: T,
    v: T,
    w: T,
}

/// The numerator and denominator of the line parameter of a crossing along `s`, and
/// the direction of `s`.
struct Param<T> {
    dx: T,
    dy: T,
    num: T,
    den: T,
}

fn param<T: Arith>(c: &Crossing) -> Param<T> {
    let (s, t) = (c.s, c.t);
    let dx = T::diff(s.b.x, s.a.x);
    let dy = T::diff(s.b.y, s.a.y);
    let ex = T::diff(t.b.x, t.a.x);
    let ey = T::diff(t.b.y, t.a.y);
    let wx = T::diff(t.a.x, s.a.x);
    let wy = T::diff(t.a.y, s.a.y);
    let den = dx.times(&ey).minus(&dy.times(&ex));
    let num = wx.times(&ey).minus(&wy.times(&ex));
    Param { dx, dy, num, den }
}

fn hom<T: Arith>(p: &ExactPoint, r: Point2) -> Hom<T> {
    match p {
        ExactPoint::Input(q) => Hom {
            u: T::diff(q.x, r.x),
            v: T::diff(q.y, r.y),
            w: T::val(1.0),
        },
        ExactPoint::Crossing(c) => {
            let Param { dx, dy, num, den } = param::<T>(c);
            let ax = T::diff(c.s.a.x, r.x);
            let ay = T::diff(c.s.a.y, r.y);
            Hom {
                u: ax.times(&den).plus(&dx.times(&num)),
                v: ay.times(&den).plus(&dy.times(&num)),
                w: den,
            }
        }
    }
}

/// A good reference point for a set of points: an input point among them, else the
/// first endpoint of the first crossing (keeps the differences small).
fn reference(points: &[&ExactPoint]) -> Point2 {
    points
        .iter()
        .find_map(|p| match p {
            ExactPoint::Input(q) => Some(*q),
            ExactPoint::Crossing(_) => None,
        })
        .unwrap_or(match points[0] {
            ExactPoint::Input(q) => *q,
            ExactPoint::Crossing(c) => c.s.a,
        })
}

/// The `f64` filter, then the double-double one, then (counted) the exact evaluation of
/// the same expression. The second filter costs a few times the first and decides
/// nearly every sign the first leaves open: a point within a float gap of a line, say
/// a rounded crossing beside an edge, is still far from it at double-double precision.
/// Only values that are zero, or below about 2^-100 times the size of their terms, reach
/// the big numbers.
fn decide(
    fast: impl FnOnce() -> Option<Ordering>,
    refined: impl FnOnce() -> Option<Ordering>,
    exact: impl FnOnce() -> Option<Ordering>,
) -> Ordering {
    if let Some(o) = fast().or_else(refined) {
        return o;
    }
    count(&CROSSING_FALLBACKS);
    exact().unwrap_or(Ordering::Equal)
}

/// Sign of a product of values, or `None` if one sign is unknown.
fn signs<T: Arith>(values: &[&T]) -> Option<Ordering> {
    values
        .iter()
        .try_fold(Ordering::Greater, |acc, v| Some(mul_sign(acc, v.sign()?)))
}

#[derive(Clone, Copy)]
enum Axis {
    X,
    Y,
}

/// One homogeneous coordinate `(u, w)` of a point relative to `r` (`u / w` along `axis`).
fn hom_axis<T: Arith>(p: &ExactPoint, r: Point2, axis: Axis) -> (T, T) {
    let pick = |q: Point2| match axis {
        Axis::X => q.x,
        Axis::Y => q.y,
    };
    match p {
        ExactPoint::Input(q) => (T::diff(pick(*q), pick(r)), T::val(1.0)),
        ExactPoint::Crossing(c) => {
            let Param { dx, dy, num, den } = param::<T>(c);
            let d = match axis {
                Axis::X => dx,
                Axis::Y => dy,
            };
            let a = T::diff(pick(c.s.a), pick(r));
            (a.times(&den).plus(&d.times(&num)), den)
        }
    }
}

fn compare_coord_with<T: Arith>(p: &ExactPoint, q: &ExactPoint, axis: Axis) -> Option<Ordering> {
    let r = reference(&[p, q]);
    let ((up, wp), (uq, wq)) = (hom_axis::<T>(p, r, axis), hom_axis::<T>(q, r, axis));
    // up/wp - uq/wq has the sign of (up·wq - uq·wp)·wp·wq.
    let n = up.times(&wq).minus(&uq.times(&wp));
    signs(&[&n, &wp, &wq])
}

/// True when `p` and `q` are the same point by construction (equal input points, or
/// crossings of the same two segments in either order): no arithmetic needed.
fn same_by_construction(p: &ExactPoint, q: &ExactPoint) -> bool {
    match (p, q) {
        (ExactPoint::Crossing(a), ExactPoint::Crossing(b)) => {
            (a.s == b.s && a.t == b.t) || (a.s == b.t && a.t == b.s)
        }
        _ => p == q,
    }
}

/// True when the lines through `u` and `v` are the same line (exact input predicates).
fn same_line(u: Segment2, v: Segment2) -> bool {
    u == v
        || (u.a != u.b
            && orient2d(u.a, u.b, v.a) == Orientation::Collinear
            && orient2d(u.a, u.b, v.b) == Orientation::Collinear)
}

/// True when `p` and `q` are crossings of the same two lines, each given by possibly
/// different collinear segments (a segment crossing two overlapping collinear edges, as
/// where polygons share an edge): the same point, though not by construction. Decided
/// by at most four orientations of input points instead of a big-number evaluation of
/// degree 5, which is what an exactly equal pair costs otherwise. Two crossings' lines
/// are never parallel (their denominators are nonzero), so the point is unique.
fn same_lines(p: &ExactPoint, q: &ExactPoint) -> bool {
    match (p, q) {
        (ExactPoint::Crossing(a), ExactPoint::Crossing(b)) => {
            (same_line(a.s, b.s) && same_line(a.t, b.t))
                || (same_line(a.s, b.t) && same_line(a.t, b.s))
        }
        _ => false,
    }
}

/// True when `p` lies on the line through `l` (a segment of positive length): an input
/// point by one orientation, a crossing when one of its segments is on that line.
fn on_line(l: Segment2, p: &ExactPoint) -> bool {
    match p {
        ExactPoint::Input(q) => orient2d(l.a, l.b, *q) == Orientation::Collinear,
        ExactPoint::Crossing(c) => same_line(l, c.s) || same_line(l, c.t),
    }
}

/// True when `a`, `b` and `c` all lie on the line of a segment of one of the crossings
/// among them (crossings along one edge, and that edge's ends: the collinear triples
/// rounding checks meet): collinear, decided by a few orientations of input points
/// where the exact evaluation has degree 8. False says nothing.
fn on_one_line(a: &ExactPoint, b: &ExactPoint, c: &ExactPoint) -> bool {
    let points = [a, b, c];
    let lines = points.iter().flat_map(|p| match p {
        ExactPoint::Crossing(x) => [Some(x.s), Some(x.t)],
        ExactPoint::Input(_) => [None, None],
    });
    lines
        .flatten()
        .any(|l| l.a != l.b && points.iter().all(|p| on_line(l, p)))
}

fn compare_coord(p: &ExactPoint, q: &ExactPoint, axis: Axis) -> Ordering {
    if same_by_construction(p, q) {
        return Ordering::Equal;
    }
    if let (ExactPoint::Input(a), ExactPoint::Input(b)) = (p, q) {
        let (x, y) = match axis {
            Axis::X => (a.x, b.x),
            Axis::Y => (a.y, b.y),
        };
        return x.partial_cmp(&y).unwrap_or(Ordering::Equal);
    }
    // The filter first: equal pairs are rare on most input, and the filter never
    // answers for them (its error bound cannot exclude zero).
    decide(
        || compare_coord_with::<Bounded>(p, q, axis),
        || compare_coord_with::<DoubleDouble>(p, q, axis),
        || {
            if same_lines(p, q) {
                return Some(Ordering::Equal);
            }
            compare_coord_with::<Dyadic>(p, q, axis)
        },
    )
}

fn orient_with<T: Arith>(a: &ExactPoint, b: &ExactPoint, c: &ExactPoint) -> Option<Ordering> {
    let r = reference(&[a, b, c]);
    let (ha, hb, hc) = (hom::<T>(a, r), hom::<T>(b, r), hom::<T>(c, r));
    // det [ua va wa; ub vb wb; uc vc wc] = orientation scaled by wa·wb·wc.
    let m1 = hb.v.times(&hc.w).minus(&hb.w.times(&hc.v));
    let m2 = hb.u.times(&hc.w).minus(&hb.w.times(&hc.u));
    let m3 = hb.u.times(&hc.v).minus(&hb.v.times(&hc.u));
    let det =
        ha.u.times(&m1)
            .minus(&ha.v.times(&m2))
            .plus(&ha.w.times(&m3));
    signs(&[&det, &ha.w, &hb.w, &hc.w])
}

/// Where `p` lies along segment `l` when it does by construction (an end of `l`, or a
/// crossing one of whose segments is `l`): its parameter from `l.a` towards `l.b` as
/// `(num, den)`, else `None`.
fn along<T: Arith>(p: &ExactPoint, l: Segment2) -> Option<(T, T)> {
    match p {
        ExactPoint::Input(q) if *q == l.a => Some((T::val(0.0), T::val(1.0))),
        ExactPoint::Input(q) if *q == l.b => Some((T::val(1.0), T::val(1.0))),
        ExactPoint::Input(_) => None,
        ExactPoint::Crossing(c) => {
            let other = if c.s == l {
                c.t
            } else if c.t == l {
                c.s
            } else {
                return None;
            };
            let Param { num, den, .. } = param::<T>(&Crossing { s: l, t: other });
            Some((num, den))
        }
    }
}

/// A segment on whose line both `a` and `b` lie by construction ([`along`]).
fn common_segment(a: &ExactPoint, b: &ExactPoint) -> Option<Segment2> {
    let segments = |p: &ExactPoint| match p {
        ExactPoint::Crossing(c) => [Some(c.s), Some(c.t)],
        ExactPoint::Input(_) => [None, None],
    };
    let on = |p: &ExactPoint, l: Segment2| match p {
        ExactPoint::Input(q) => *q == l.a || *q == l.b,
        ExactPoint::Crossing(c) => c.s == l || c.t == l,
    };
    segments(a)
        .into_iter()
        .chain(segments(b))
        .flatten()
        .find(|&l| on(a, l) && on(b, l))
}

/// `orient(a, b, c)` for `a` and `b` on the line of segment `l` ([`common_segment`]):
/// `(μ_b − μ_a) · orient(l.a, l.b, c)` for their parameters `μ` along `l`, since the
/// orientation is linear in each point. For a crossing `c` of `p` with another segment,
/// `orient(l.a, l.b, c)` is affine along `p`: `(A·(den − num) + B·num) / den` with
/// `A`, `B` the orientations of `p`'s ends. Degree 4 where the general form has
/// degree up to 8, and no homogeneous coordinates: the rounding check asks this of
/// every vertex near an edge, whose ends are crossings along one input segment.
fn orient_along_with<T: Arith>(
    a: &ExactPoint,
    b: &ExactPoint,
    c: &ExactPoint,
    l: Segment2,
) -> Option<Ordering> {
    let (na, da) = along::<T>(a, l)?;
    let (nb, db) = along::<T>(b, l)?;
    // μ_b − μ_a = nb/db − na/da has the sign of (nb·da − na·db)·da·db.
    let step = nb.times(&da).minus(&na.times(&db));
    let direction = signs(&[&step, &da, &db])?;
    let (lx, ly) = (T::diff(l.b.x, l.a.x), T::diff(l.b.y, l.a.y));
    let side_of = |q: Point2| {
        lx.times(&T::diff(q.y, l.a.y))
            .minus(&ly.times(&T::diff(q.x, l.a.x)))
    };
    let side = match c {
        ExactPoint::Input(q) => side_of(*q).sign()?,
        ExactPoint::Crossing(x) => {
            let Param { num, den, .. } = param::<T>(x);
            let (first, second) = (side_of(x.s.a), side_of(x.s.b));
            let value = first.times(&den.minus(&num)).plus(&second.times(&num));
            signs(&[&value, &den])?
        }
    };
    Some(mul_sign(direction, side))
}

/// [`orient_along_with`] through the filters, then exactly (a crossing with one of its
/// segments on `l`'s line is on it: decided by orientations of input points first).
fn orient_along(a: &ExactPoint, b: &ExactPoint, c: &ExactPoint, l: Segment2) -> Ordering {
    // `c` on `l` by construction too (an end of it, or a crossing of it): collinear,
    // which the filters cannot tell (a zero is only certain exactly).
    let on_l = match c {
        ExactPoint::Input(q) => *q == l.a || *q == l.b,
        ExactPoint::Crossing(x) => x.s == l || x.t == l,
    };
    if on_l {
        return Ordering::Equal;
    }
    decide(
        || orient_along_with::<Bounded>(a, b, c, l),
        || orient_along_with::<DoubleDouble>(a, b, c, l),
        || {
            if let ExactPoint::Crossing(x) = c {
                if same_line(l, x.s) || same_line(l, x.t) {
                    return Some(Ordering::Equal);
                }
            }
            orient_along_with::<Dyadic>(a, b, c, l)
        },
    )
}

/// The exact orientation of three points, each an input point or a crossing.
///
/// ```
/// use compgeom::kernel::{orient_exact, Crossing, ExactPoint, Orientation};
/// use compgeom::{Point2, Segment2};
/// let p = |x, y| Point2::new(x, y);
/// let c = Crossing::new(Segment2::new(p(0.0, 0.0), p(2.0, 2.0)), Segment2::new(p(0.0, 2.0), p(2.0, 0.0))).unwrap();
/// let (a, b) = (ExactPoint::from(p(0.0, 1.0)), ExactPoint::from(p(2.0, 1.0)));
/// assert_eq!(orient_exact(&a, &b, &c.into()), Orientation::Collinear);
/// ```
pub fn orient_exact(a: &ExactPoint, b: &ExactPoint, c: &ExactPoint) -> Orientation {
    let sign = match (a, b, c) {
        (ExactPoint::Input(a), ExactPoint::Input(b), ExactPoint::Input(c)) => {
            return orient2d(*a, *b, *c)
        }
        _ if same_by_construction(a, b)
            || same_by_construction(b, c)
            || same_by_construction(a, c) =>
        {
            Ordering::Equal
        }
        _ => match [(a, b, c), (b, c, a), (c, a, b)]
            .into_iter()
            .find_map(|(p, q, r)| common_segment(p, q).map(|l| (p, q, r, l)))
        {
            // Two of them on one input segment (taken in cyclic order, which keeps the
            // sign).
            Some((p, q, r, l)) => orient_along(p, q, r, l),
            None => orient_general(a, b, c),
        },
    };
    match sign {
        Ordering::Greater => Orientation::CounterClockwise,
        Ordering::Less => Orientation::Clockwise,
        Ordering::Equal => Orientation::Collinear,
    }
}

/// [`orient_exact`] by homogeneous coordinates, through the filters, then exactly.
fn orient_general(a: &ExactPoint, b: &ExactPoint, c: &ExactPoint) -> Ordering {
    decide(
        || orient_with::<Bounded>(a, b, c),
        || orient_with::<DoubleDouble>(a, b, c),
        || {
            if same_lines(a, b) || same_lines(b, c) || same_lines(a, c) || on_one_line(a, b, c) {
                return Some(Ordering::Equal);
            }
            orient_with::<Dyadic>(a, b, c)
        },
    )
}

fn cross_sign_with<T: Arith>(s: Segment2, t: Segment2) -> Option<Ordering> {
    // (s.b - s.a) × (t.b - t.a)
    let dx = T::diff(s.b.x, s.a.x);
    let dy = T::diff(s.b.y, s.a.y);
    let ex = T::diff(t.b.x, t.a.x);
    let ey = T::diff(t.b.y, t.a.y);
    dx.times(&ey).minus(&dy.times(&ex)).sign()
}

/// Exact sign of the cross product of the directions of `s` and `t`.
fn cross_sign(s: Segment2, t: Segment2) -> Ordering {
    decide(
        || cross_sign_with::<Bounded>(s, t),
        || cross_sign_with::<DoubleDouble>(s, t),
        || cross_sign_with::<Dyadic>(s, t),
    )
}

/// `s` with its endpoints in lexicographic (x, then y) order.
fn sorted(s: Segment2) -> Segment2 {
    if compare_input_xy(s.a, s.b) == Ordering::Greater {
        Segment2::new(s.b, s.a)
    } else {
        s
    }
}

/// Exact comparison of the slopes of two segments, each directed from its
/// lexicographically smaller endpoint; a vertical segment has slope `+inf`
/// (so two vertical segments compare `Equal`). This is the order of two segments just
/// to the right of a point where both pass (CGAL's `compare_y_at_x_right`).
/// A degenerate (point) segment compares `Equal` to everything.
pub fn compare_slopes(s: Segment2, t: Segment2) -> Ordering {
    // slope(s) < slope(t) iff t turns left from s iff (t.dir × s.dir) < 0.
    cross_sign(sorted(t), sorted(s))
}

/// Where `p` lies relative to the segment `s` at `p`'s x: `Greater` if above, `Less`
/// if below, `Equal` if on the line of `s`. For a vertical `s`, `Equal` means that `p`'s
/// y is within `s`'s y-range; for a point segment, it compares y with that point.
/// `p`'s x is meant to lie within `s`'s x-range (not checked: outside it, the answer
/// is the side of `s`'s supporting line).
pub fn compare_y_at_x(p: &ExactPoint, s: Segment2) -> Ordering {
    let s = sorted(s);
    if s.a.x == s.b.x {
        let lo = ExactPoint::Input(s.a);
        let hi = ExactPoint::Input(s.b);
        return match compare_coord(p, &lo, Axis::Y) {
            Ordering::Less => Ordering::Less,
            _ => match compare_coord(p, &hi, Axis::Y) {
                Ordering::Greater => Ordering::Greater,
                _ => Ordering::Equal,
            },
        };
    }
    match orient_exact(&ExactPoint::Input(s.a), &ExactPoint::Input(s.b), p) {
        Orientation::CounterClockwise => Ordering::Greater,
        Orientation::Clockwise => Ordering::Less,
        Orientation::Collinear => Ordering::Equal,
    }
}

/// True when `p` lies on the closed segment `s` (exactly).
pub fn on_segment(p: &ExactPoint, s: Segment2) -> bool {
    let s = sorted(s);
    let (a, b) = (ExactPoint::Input(s.a), ExactPoint::Input(s.b));
    p.compare_xy(&a) != Ordering::Less
        && p.compare_xy(&b) != Ordering::Greater
        && (s.a == s.b || orient_exact(&a, &b, p) == Orientation::Collinear)
}

impl ExactPoint {
    /// Exact comparison of x coordinates.
    pub fn compare_x(&self, other: &ExactPoint) -> Ordering {
        compare_coord(self, other, Axis::X)
    }

    /// Exact comparison of y coordinates.
    pub fn compare_y(&self, other: &ExactPoint) -> Ordering {
        compare_coord(self, other, Axis::Y)
    }

    /// Exact comparison with the `f64` point `q` per axis: `(x vs q.x, y vs q.y)`, as
    /// [`ExactPoint::compare_x`] and [`ExactPoint::compare_y`] with `q` as an input
    /// point. For a crossing one double-double evaluation of its parameter serves both
    /// axes (the plain `f64` filter is skipped: this is asked about points within a
    /// float or two of the crossing, where it cannot decide).
    pub fn compare_with_point(&self, q: Point2) -> (Ordering, Ordering) {
        let c = match self {
            ExactPoint::Input(p) => {
                let cmp = |a: f64, b: f64| a.partial_cmp(&b).unwrap_or(Ordering::Equal);
                return (cmp(p.x, q.x), cmp(p.y, q.y));
            }
            ExactPoint::Crossing(c) => c,
        };
        // Relative to q: x - q.x = ((a.x - q.x)·den + dx·num) / den, and so for y.
        let Param { dx, dy, num, den } = param::<DoubleDouble>(c);
        let side = |a: f64, r: f64, d: &DoubleDouble| {
            let u = DoubleDouble::diff(a, r).times(&den).plus(&d.times(&num));
            signs(&[&u, &den])
        };
        let point = ExactPoint::Input(q);
        let x = side(c.s.a.x, q.x, &dx).unwrap_or_else(|| self.compare_x(&point));
        let y = side(c.s.a.y, q.y, &dy).unwrap_or_else(|| self.compare_y(&point));
        (x, y)
    }

    /// Exact lexicographic comparison (x, then y): the sweep-line event order.
    pub fn compare_xy(&self, other: &ExactPoint) -> Ordering {
        self.compare_x(other).then_with(|| self.compare_y(other))
    }

    /// The point itself, or the nearest `f64` point to a crossing.
    pub fn approx(&self) -> Point2 {
        match self {
            ExactPoint::Input(p) => *p,
            ExactPoint::Crossing(c) => c.approx(),
        }
    }
}

/// The next `f64` above a finite normal `x` (callers keep away from the range ends).
fn next_up(x: f64) -> f64 {
    let b = x.to_bits();
    if x > 0.0 {
        f64::from_bits(b + 1)
    } else {
        f64::from_bits(b - 1)
    }
}

/// The next `f64` below a finite normal `x`.
fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

/// True for a value whose neighbours are normal and finite with exact half-gaps.
fn well_inside(f: f64) -> bool {
    f.abs() > 1e-290 && f.abs() < 1e300
}

/// The fast path of correct rounding for one coordinate `a + d·num/den` of a crossing,
/// in double-double arithmetic with an error bound: take `f`, the quotient of the
/// leading parts corrected once by the remainder (nearly always the nearest `f64`); done
/// when the remainder bounds `|x - f|` clearly below half a gap, else decide on which side of the midpoints `f ± half-gap` the exact value lies (a midpoint
/// is `f + h` with `f` and `h` exact `f64`s, so `x - (f + h)` has the sign of
/// `(N - f·D - h·D)·D`), stepping to a neighbour at most a few times.
/// `None` (use the exact path) when a sign is uncertain, on an exact tie, or near the
/// ends of the `f64` range (subnormal or huge results).
fn nearest_fast(a: f64, d: &DoubleDouble, num: &DoubleDouble, den: &DoubleDouble) -> Option<f64> {
    let n = den.times_f64(a).plus(&d.times(num));
    let den_sign = den.sign()?;
    let q = n.head() / den.head();
    if !well_inside(q) {
        return None;
    }
    let first = n.minus(&den.times_f64(q));
    let mut f = q + first.head() / den.head();
    if !well_inside(f) {
        return None;
    }
    // rest = N - f·D throughout.
    let mut rest = if f == q {
        first
    } else {
        n.minus(&den.times_f64(f))
    };
    // The common case: |x - f| = |rest| / |D| is clearly below half the smaller gap
    // around f (an exact power of two; h·|D|'s lower bound is exact when normal).
    let h = (next_up(f) - f).min(f - next_down(f)) * 0.5;
    let h_den = h * den.magnitude_bounds().0;
    if h_den > 1e-290 && h_den.is_finite() && rest.magnitude_bounds().1 < h_den {
        return Some(f);
    }
    for _ in 0..4 {
        let (up, down) = (next_up(f), next_down(f));
        let half_up = den.times_f64((up - f) * 0.5);
        match mul_sign(rest.minus(&half_up).sign()?, den_sign) {
            Ordering::Greater => {
                f = up;
                rest = n.minus(&den.times_f64(f));
                continue;
            }
            Ordering::Equal => return None,
            Ordering::Less => {}
        }
        let half_down = den.times_f64((f - down) * 0.5);
        match mul_sign(rest.plus(&half_down).sign()?, den_sign) {
            Ordering::Less => {
                f = down;
                rest = n.minus(&den.times_f64(f));
            }
            Ordering::Equal => return None,
            Ordering::Greater => return Some(f),
        }
    }
    None
}

impl Crossing {
    /// The crossing of the lines through `s` and `t`, or `None` when the lines are
    /// parallel (decided exactly), a segment is degenerate, or a coordinate is not
    /// finite. The segments need not actually meet: see [`super::segment_intersection`]
    /// for closed-segment intersection.
    pub fn new(s: Segment2, t: Segment2) -> Option<Crossing> {
        let finite = s.a.is_finite() && s.b.is_finite() && t.a.is_finite() && t.b.is_finite();
        if !finite || s.is_degenerate() || t.is_degenerate() {
            return None;
        }
        (cross_sign(s, t) != Ordering::Equal).then_some(Crossing { s, t })
    }

    /// The exact coordinates as (numerator, denominator) dyadic pairs.
    fn exact_parts(&self) -> (Dyadic, Dyadic, Dyadic) {
        let Param { dx, dy, num, den } = param::<Dyadic>(self);
        let x = Dyadic::val(self.s.a.x).times(&den).plus(&dx.times(&num));
        let y = Dyadic::val(self.s.a.y).times(&den).plus(&dy.times(&num));
        (x, y, den)
    }

    /// The nearest `f64` point to the exact crossing: each coordinate is correctly
    /// rounded (to nearest, ties to even). A coordinate beyond the `f64` range (nearly
    /// parallel lines far out) becomes `±inf`; one below half the smallest subnormal
    /// becomes `0`. For reporting only: decisions never use it.
    ///
    /// Cost: a double-double evaluation decides the rounding in all but near-tie cases
    /// (about the cost of two comparisons); the rest use exact rational rounding.
    pub fn approx(&self) -> Point2 {
        let Param { dx, dy, num, den } = param::<DoubleDouble>(self);
        let fast_x = nearest_fast(self.s.a.x, &dx, &num, &den);
        let fast_y = nearest_fast(self.s.a.y, &dy, &num, &den);
        if let (Some(x), Some(y)) = (fast_x, fast_y) {
            return Point2::new(x, y);
        }
        let (x, y, den) = self.exact_parts();
        Point2::new(nearest_f64(&x, &den), nearest_f64(&y, &den))
    }

    /// The exact coordinates as rationals, or `None` for a hand-made crossing of
    /// parallel lines (or non-finite input).
    pub fn exact(&self) -> Option<(BigRational, BigRational)> {
        let finite = self.s.a.is_finite()
            && self.s.b.is_finite()
            && self.t.a.is_finite()
            && self.t.b.is_finite();
        let (x, y, den) = self.exact_parts();
        if !finite || den.is_zero() {
            return None;
        }
        let d = den.to_rational();
        Some((x.to_rational() / &d, y.to_rational() / &d))
    }

    /// Exact lexicographic comparison (x, then y) of the crossing with an input point.
    pub fn compare_xy_point(&self, p: Point2) -> Ordering {
        ExactPoint::Crossing(*self).compare_xy(&ExactPoint::Input(p))
    }

    /// Exact lexicographic comparison (x, then y) of two crossings.
    pub fn compare_xy(&self, other: &Crossing) -> Ordering {
        ExactPoint::Crossing(*self).compare_xy(&ExactPoint::Crossing(*other))
    }

    /// Exact orientation of `(a, b, crossing)`.
    pub fn orient(a: Point2, b: Point2, c: &Crossing) -> Orientation {
        orient_exact(
            &ExactPoint::Input(a),
            &ExactPoint::Input(b),
            &ExactPoint::Crossing(*c),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The `same_lines` shortcut agrees with the exact evaluation on degenerate input:
    /// crossings of one segment with several overlapping collinear segments (equal
    /// points, different constructions), of collinear segments with each other's
    /// lines, near-equal crossings, and crossings against input points; on exactly
    /// representable lines (grid times powers of two) and rounded ones (times 0.1,
    /// where the "collinear" segments mostly are not). It must fire where the filter
    /// fails, else it tests nothing.
    #[test]
    fn same_lines_shortcut_agrees_with_exact() {
        let mut below = crate::testing::below(0x2545_f491_4f6c_dd1d);
        let mut int = move |n: u64| below(n) as f64;
        let (mut fired, mut checked, mut on_one) = (0usize, 0usize, 0usize);
        for k in 0..4_000 {
            let scale = [1.0, 0.1, 0.125, 1024.0, 3.0e-3][k % 5];
            let p = |x: f64, y: f64| Point2::new(x * scale, y * scale);
            // A line through (ox, oy) with direction (dx, dy); segments on it between
            // grid parameters, so they overlap and share the line exactly (scale exact).
            let (ox, oy) = (int(20) - 10.0, int(20) - 10.0);
            let (dx, dy) = (int(7) + 1.0, int(9) - 4.0);
            let on = |lo: f64, hi: f64| {
                Segment2::new(p(ox + lo * dx, oy + lo * dy), p(ox + hi * dx, oy + hi * dy))
            };
            let shared = [on(-3.0, 2.0), on(-1.0, 4.0), on(4.0, -2.0), on(0.0, 1.0)];
            let mut cut = || {
                let (ax, ay) = (int(30) - 15.0, int(30) - 15.0);
                Segment2::new(p(ax, ay), p(ax + int(11) - 5.0, ay + int(11) - 5.0 + 0.5))
            };
            let cuts = [cut(), cut(), cut()];
            let mut pts: Vec<ExactPoint> = Vec::new();
            for s in shared {
                for t in cuts {
                    if let Some(c) = Crossing::new(s, t) {
                        pts.push(c.into());
                    }
                    if let Some(c) = Crossing::new(t, s) {
                        pts.push(c.into());
                    }
                }
            }
            // Triples of points on the shared line (its crossings with the cuts, ends of
            // its segments; exactly on one line where the scale is exact), each also with
            // an off-line point in place of the third: `on_one_line` must fire often and
            // `orient_exact` agree with the exact sign.
            if k % 8 == 0 {
                let mut on: Vec<ExactPoint> = pts.clone();
                on.extend([shared[0].a, shared[2].b].map(ExactPoint::from));
                let off = ExactPoint::from(cuts[0].a);
                for (i, a) in on.iter().enumerate() {
                    for (j, b) in on.iter().enumerate().skip(i + 1) {
                        for c in [&on[(i + j + 1) % on.len()], &off] {
                            let exact = match orient_with::<Dyadic>(a, b, c) {
                                Some(Ordering::Greater) => Orientation::CounterClockwise,
                                Some(Ordering::Less) => Orientation::Clockwise,
                                _ => Orientation::Collinear,
                            };
                            assert_eq!(orient_exact(a, b, c), exact, "{a:?} {b:?} {c:?}");
                            // (Directly: the filters decide most triples before it runs.)
                            if on_one_line(a, b, c) {
                                assert_eq!(exact, Orientation::Collinear, "{a:?} {b:?} {c:?}");
                                on_one += 1;
                            }
                        }
                    }
                }
            }
            for (i, &t) in cuts.iter().enumerate() {
                for &u in &cuts[i + 1..] {
                    if let Some(c) = Crossing::new(t, u) {
                        pts.push(c.into());
                    }
                }
            }
            pts.extend([shared[0].a, shared[1].b, cuts[0].a].map(ExactPoint::from));
            for (i, a) in pts.iter().enumerate() {
                for b in &pts[i + 1..] {
                    for axis in [Axis::X, Axis::Y] {
                        let exact =
                            compare_coord_with::<Dyadic>(a, b, axis).unwrap_or(Ordering::Equal);
                        assert_eq!(compare_coord(a, b, axis), exact, "{a:?} {b:?}");
                        checked += 1;
                    }
                    fired += usize::from(
                        same_lines(a, b) && compare_coord_with::<Bounded>(a, b, Axis::X).is_none(),
                    );
                    let c = &pts[(i * 7 + 3) % pts.len()];
                    let exact = match orient_with::<Dyadic>(a, b, c).unwrap_or(Ordering::Equal) {
                        Ordering::Greater => Orientation::CounterClockwise,
                        Ordering::Less => Orientation::Clockwise,
                        Ordering::Equal => Orientation::Collinear,
                    };
                    assert_eq!(orient_exact(a, b, c), exact, "{a:?} {b:?} {c:?}");
                }
            }
        }
        assert!(
            checked > 100_000 && fired > 1_000 && on_one > 10_000,
            "checked {checked}, the shortcuts decided {fired} pairs and {on_one} triples"
        );
    }

    /// Orientations with two points on one input segment (its ends, its crossings with
    /// other segments) go by that segment's line (`orient_along`) and agree with the
    /// general exact evaluation: the third point a crossing within a few floats of the
    /// line, exactly on it (crossings of segments sharing its line, or of lines through
    /// grid points on it), or an input point; the two on the segment in either order,
    /// and each triple in all three cyclic orders, at scales from 1e-300 to 1e300.
    #[test]
    fn orientation_along_a_segment_agrees_with_exact() {
        let mut unit = crate::testing::units(0x5851_f42d_4c95_7f2d);
        let to_orientation = |o: Ordering| match o {
            Ordering::Greater => Orientation::CounterClockwise,
            Ordering::Less => Orientation::Clockwise,
            Ordering::Equal => Orientation::Collinear,
        };
        let (mut along, mut near, mut zero, mut all_on) = (0usize, 0usize, 0usize, 0usize);
        for k in 0..240 {
            let scale = [1.0, 1e-300, 1e300, 3.0e-7, 1e30, 0.1][k % 6];
            let grid = k % 3 == 0;
            let t = unit();
            let mut pt = || {
                let (x, y) = (unit(), unit());
                if grid {
                    Point2::new((x * 16.0).floor() * scale, (y * 16.0).floor() * scale)
                } else {
                    Point2::new(x * scale, y * scale)
                }
            };
            let l = Segment2::new(pt(), pt());
            if l.a == l.b {
                continue;
            }
            let at = |t: f64| Point2::new(l.a.x + t * (l.b.x - l.a.x), l.a.y + t * (l.b.y - l.a.y));
            // Segments through points of l (rounded: within a float or so of its line;
            // on it exactly for grid points at t = 0, 1/2, 1 where the halving is exact).
            let mut through = |t: f64| {
                let m = at(t);
                let q = pt();
                Segment2::new(Point2::new(2.0 * m.x - q.x, 2.0 * m.y - q.y), q)
            };
            let cuts: Vec<Segment2> = [0.25, 0.5, 0.75, 0.5, t]
                .into_iter()
                .map(&mut through)
                .collect();
            let mut on_l: Vec<ExactPoint> = vec![l.a.into(), l.b.into()];
            let mut others: Vec<ExactPoint> = vec![pt().into(), at(0.5).into()];
            for (i, &c) in cuts.iter().enumerate() {
                if let Some(x) = Crossing::new(l, c) {
                    on_l.push(x.into());
                }
                if let Some(x) = Crossing::new(c, l) {
                    on_l.push(x.into());
                }
                for &d in &cuts[i + 1..] {
                    if let Some(x) = Crossing::new(c, d) {
                        others.push(x.into());
                    }
                }
            }
            // A segment on l's line (overlapping it): its crossings are on the line.
            let shared = Segment2::new(at(0.5), l.b);
            if let Some(x) = Crossing::new(shared, cuts[4]) {
                others.push(x.into());
            }
            for (i, a) in on_l.iter().enumerate() {
                for b in &on_l[i + 1..] {
                    for c in &others {
                        for (p, q, r) in [(a, b, c), (b, c, a), (c, a, b), (b, a, c)] {
                            let exact = to_orientation(
                                orient_with::<Dyadic>(p, q, r).unwrap_or(Ordering::Equal),
                            );
                            assert_eq!(orient_exact(p, q, r), exact, "{p:?} {q:?} {r:?}");
                        }
                        if common_segment(a, b).is_some() && !same_by_construction(a, b) {
                            along += 1;
                            let l = common_segment(a, b).unwrap();
                            near += usize::from(orient_along_with::<Bounded>(a, b, c, l).is_none());
                            zero += usize::from(
                                orient_with::<Dyadic>(a, b, c) == Some(Ordering::Equal),
                            );
                        }
                    }
                }
            }
            // Three points on l by construction (its ends, its crossings): collinear
            // at once, as the exact evaluation says, in every order.
            for (i, a) in on_l.iter().enumerate() {
                for (j, b) in on_l.iter().enumerate().skip(i + 1) {
                    for c in &on_l[j + 1..] {
                        for (p, q, r) in [(a, b, c), (b, c, a), (c, a, b), (b, a, c)] {
                            let exact = orient_with::<Dyadic>(p, q, r);
                            assert_eq!(exact, Some(Ordering::Equal), "{p:?} {q:?} {r:?}");
                            assert_eq!(orient_exact(p, q, r), Orientation::Collinear);
                            all_on += 1;
                        }
                    }
                }
            }
        }
        assert!(
            along > 50_000 && near > 20_000 && zero > 3_000 && all_on > 10_000,
            "{along} triples along a segment, {near} left open by the f64 filter, {zero} on \
             it, {all_on} with all three on it"
        );
    }

    /// The double-double stage of `decide` agrees with the exact evaluation where the
    /// `f64` filter gives up: crossings within a few floats of a line through input
    /// points or through other crossings (the near pairs of the boolean operations'
    /// rounding check), at scales from 1e-300 to 1e300. Where its products neither
    /// overflow nor underflow (scales 1e-30 to 1e30 for these degrees) it must decide
    /// most of them, else it tests nothing.
    #[test]
    fn double_double_stage_agrees_with_exact_near_lines() {
        let mut unit = crate::testing::units(0x9e37_79b9_7f4a_7c15_u64);
        let to_orientation = |o: Ordering| match o {
            Ordering::Greater => Orientation::CounterClockwise,
            Ordering::Less => Orientation::Clockwise,
            Ordering::Equal => Orientation::Collinear,
        };
        let (mut open, mut decided) = (0usize, 0usize);
        for k in 0..20_000 {
            let scale = [1.0, 1e-300, 1e300, 3.0e-7, 1e30, 1e-30][k % 6];
            let in_range = ![1, 2].contains(&(k % 6));
            let mut pt = || Point2::new(unit() * scale, unit() * scale);
            let (a, b) = (pt(), pt());
            // Two segments crossing near a point of the line a b: the ends of each are
            // that point plus and minus a random offset, rounded.
            let near_line = |t: f64, u: &mut dyn FnMut() -> f64| {
                let m = Point2::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
                let (d, e) = ((u() - 0.5) * scale, (u() - 0.5) * scale);
                let (f, g) = ((u() - 0.5) * scale, (u() - 0.5) * scale);
                Crossing::new(
                    Segment2::new(Point2::new(m.x - d, m.y - e), Point2::new(m.x + d, m.y + e)),
                    Segment2::new(Point2::new(m.x - f, m.y - g), Point2::new(m.x + f, m.y + g)),
                )
            };
            let (t1, t2, t3) = (unit(), unit(), unit());
            let (Some(c1), Some(c2), Some(c3)) = (
                near_line(t1, &mut unit),
                near_line(t2, &mut unit),
                near_line(t3, &mut unit),
            ) else {
                continue;
            };
            let (a, b) = (ExactPoint::from(a), ExactPoint::from(b));
            let (c1, c2, c3) = (c1.into(), c2.into(), c3.into());
            for (p, q, r) in [(&a, &b, &c1), (&a, &c1, &c2), (&c1, &c2, &c3)] {
                let exact =
                    to_orientation(orient_with::<Dyadic>(p, q, r).unwrap_or(Ordering::Equal));
                assert_eq!(orient_exact(p, q, r), exact, "{p:?} {q:?} {r:?}");
                if in_range && orient_with::<Bounded>(p, q, r).is_none() {
                    open += 1;
                    decided += usize::from(orient_with::<DoubleDouble>(p, q, r).is_some());
                }
            }
            for axis in [Axis::X, Axis::Y] {
                let exact = compare_coord_with::<Dyadic>(&c1, &c2, axis).unwrap_or(Ordering::Equal);
                assert_eq!(compare_coord(&c1, &c2, axis), exact, "{c1:?} {c2:?}");
            }
        }
        assert!(
            open > 5_000 && decided * 10 >= open * 9,
            "double-double decided {decided} of the {open} signs the f64 filter left open"
        );
        // Exact zeros get no sign (at most `Equal`): three lines through (1/3, 1/3).
        let p = |x: f64, y: f64| Point2::new(x, y);
        let s1 = Segment2::new(p(1.0, 0.0), p(-1.0, 1.0));
        let s2 = Segment2::new(p(0.0, 1.0), p(1.0, -1.0));
        let s3 = Segment2::new(p(0.0, 0.0), p(1.0, 1.0));
        let c12: ExactPoint = Crossing::new(s1, s2).unwrap().into();
        let c13: ExactPoint = Crossing::new(s1, s3).unwrap().into();
        let on_s3 = [p(-2.0, -2.0), p(3.0, 3.0)].map(ExactPoint::from);
        let no_sign = |o: Option<Ordering>| matches!(o, None | Some(Ordering::Equal));
        assert!(no_sign(orient_with::<DoubleDouble>(
            &on_s3[0], &on_s3[1], &c12
        )));
        assert!(no_sign(compare_coord_with::<DoubleDouble>(
            &c12,
            &c13,
            Axis::X
        )));
        assert!(no_sign(compare_coord_with::<DoubleDouble>(
            &c12,
            &c13,
            Axis::Y
        )));
        let along = |k: f64| Segment2::new(p(0.0, 0.0), p(k, k));
        assert!(no_sign(cross_sign_with::<DoubleDouble>(
            along(1.0),
            along(3.0)
        )));
    }

    /// [`ExactPoint::compare_with_point`] agrees with the exact comparisons per axis on
    /// crossings against their rounded points and the floats around them, at many
    /// scales, and on crossings that are exactly float points.
    #[test]
    fn comparison_with_a_point_agrees_per_axis() {
        let mut unit = crate::testing::units(0x5eed_u64);
        let mut on_point = 0;
        for k in 0..6_000 {
            let scale = [1.0, 1e-200, 1e200, 3.0e-7, 1e-300, 1e250][k % 6];
            let grid = k % 3 == 0;
            let mut pt = || {
                let v = |u: f64| {
                    if grid {
                        (u * 8.0).floor() * scale
                    } else {
                        u * scale
                    }
                };
                Point2::new(v(unit()), v(unit()))
            };
            let (a, b, c, d) = (pt(), pt(), pt(), pt());
            let Some(cr) = Crossing::new(Segment2::new(a, b), Segment2::new(c, d)) else {
                continue;
            };
            let p = ExactPoint::Crossing(cr);
            let r = cr.approx();
            let steps = |v: f64| {
                let tiny = f64::from_bits(1);
                if v == 0.0 {
                    [-tiny, v, tiny]
                } else {
                    [next_down(v), v, next_up(v)]
                }
            };
            for x in steps(r.x) {
                for y in steps(r.y) {
                    let q = Point2::new(x, y);
                    let input = ExactPoint::Input(q);
                    let want = (p.compare_x(&input), p.compare_y(&input));
                    assert_eq!(p.compare_with_point(q), want, "{cr:?} {q:?}");
                    on_point += usize::from(want == (Ordering::Equal, Ordering::Equal));
                }
            }
            let i = ExactPoint::Input(a);
            let rounded = ExactPoint::Input(r);
            let want = (i.compare_x(&rounded), i.compare_y(&rounded));
            assert_eq!(i.compare_with_point(r), want);
        }
        assert!(on_point > 100, "only {on_point} crossings on float points");
    }

    /// The fast rounding path agrees with exact rational rounding on random crossings
    /// at many scales, including nearly parallel segments and mixed magnitudes.
    #[test]
    fn fast_rounding_agrees_with_exact_rounding() {
        let mut unit = crate::testing::units(0x1234_5678_u64);
        // Fast decisions at scale 1 (the others may underflow or overflow in double-double).
        let (mut fast, mut tried) = (0, 0);
        for k in 0..30_000 {
            let scale = [1.0, 1e-200, 1e200, 3.0e-7, 1e-300, 1e250][k % 6];
            let shift = [0.0, 1.0, -1e6, 0.5][k % 4] * scale;
            let mut pt = || Point2::new(shift + unit() * scale, shift + unit() * scale);
            let (a, b, c) = (pt(), pt(), pt());
            let d = if k % 5 == 0 {
                Point2::new(c.x + (b.x - a.x), c.y + (b.y - a.y) * (1.0 + 1e-12))
            } else {
                pt()
            };
            let Some(cr) = Crossing::new(Segment2::new(a, b), Segment2::new(c, d)) else {
                continue;
            };
            let Param { dx, dy, num, den } = param::<DoubleDouble>(&cr);
            let (x, y, dd) = cr.exact_parts();
            let want = Point2::new(nearest_f64(&x, &dd), nearest_f64(&y, &dd));
            let got = cr.approx();
            assert_eq!(
                (got.x.to_bits(), got.y.to_bits()),
                (want.x.to_bits(), want.y.to_bits()),
                "{cr:?}"
            );
            tried += usize::from(k % 6 == 0);
            let fx = nearest_fast(cr.s.a.x, &dx, &num, &den);
            let fy = nearest_fast(cr.s.a.y, &dy, &num, &den);
            if let (Some(fx), Some(fy)) = (fx, fy) {
                assert_eq!(
                    (fx.to_bits(), fy.to_bits()),
                    (want.x.to_bits(), want.y.to_bits())
                );
                fast += usize::from(k % 6 == 0);
            }
        }
        assert!(
            tried > 4000 && fast * 100 >= tried * 99,
            "fast path decided only {fast} of {tried}"
        );
    }
}
