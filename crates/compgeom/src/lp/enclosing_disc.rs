//! Smallest enclosing disc (book §4.7): MINIDISC, MINIDISCWITHPOINT and
//! MINIDISCWITH2POINTS, randomized incremental, expected O(n).
//!
//! The disc is always defined by one to three input points on its boundary (its
//! *support*), so "is `p` in the current disc" is an exact predicate on input points:
//! for three support points the kernel's [`incircle`] together with [`orient2d`], for two
//! the exact sign of `(p - a)·(p - b)` (inside the disc with diameter `ab` iff `<= 0`),
//! for one `p == a`. Points on the circle count as inside. The centre and radius are
//! computed once, at the end, from the support in exact rationals and rounded to the
//! nearest `f64` (the radius within one ulp: the square root of the exact squared radius,
//! correctly rounded before the root).
//!
//! Degenerate input: duplicates, collinear and cocircular sets are ordinary input. When a
//! minimal disc has several possible supports (cocircular points), which one is reported
//! depends on the seed; the disc does not.

use super::exact::{rat, sign, to_f64, Num, SignExpr};
use super::Shuffler;
use crate::kernel::{ensure_finite, incircle, orient2d, CircleSide, Orientation, Point2};
use crate::{Error, Result};
use num_rational::BigRational;
use std::cmp::Ordering;

/// A disc and the input points on its boundary that define it.
#[derive(Debug, Clone, PartialEq)]
pub struct Disc {
    /// Centre (nearest `f64` of the exact centre).
    pub center: Point2,
    /// Radius (nearest `f64`, within one ulp).
    pub radius: f64,
    /// One to three input points on the boundary that define the disc: one point (all
    /// input points equal), two (a diameter), or three (the circumcircle).
    pub support: Vec<Point2>,
}

impl Disc {
    /// True when `p` lies in the disc defined by the support (boundary included), decided
    /// exactly.
    pub fn contains(&self, p: Point2) -> bool {
        contains(&self.support, p)
    }
}

/// `(p - a)·(p - b)`.
struct DiametralExpr(Point2, Point2, Point2);

impl SignExpr for DiametralExpr {
    fn eval<N: Num>(&self) -> N {
        let (p, a, b) = (self.0, self.1, self.2);
        let d = |u: f64, v: f64| N::val(u).sub(&N::val(v));
        d(p.x, a.x)
            .mul(&d(p.x, b.x))
            .add(&d(p.y, a.y).mul(&d(p.y, b.y)))
    }
}

/// Exact containment in the disc defined by `support` (boundary included).
fn contains(support: &[Point2], p: Point2) -> bool {
    match *support {
        [a] => p.x == a.x && p.y == a.y,
        [a, b] => sign(&DiametralExpr(p, a, b)) != Ordering::Greater,
        [a, b, c] => match orient2d(a, b, c) {
            Orientation::CounterClockwise => incircle(a, b, c, p) != CircleSide::Outside,
            Orientation::Clockwise => incircle(a, b, c, p) != CircleSide::Inside,
            // Never built (see `through3`); answer as for the diametral disc of the ends.
            Orientation::Collinear => {
                sign(&DiametralExpr(p, a, b)) != Ordering::Greater
                    || sign(&DiametralExpr(p, a, c)) != Ordering::Greater
                    || sign(&DiametralExpr(p, b, c)) != Ordering::Greater
            }
        },
        _ => false,
    }
}

/// The disc through `q1`, `q2` and `p`. Three collinear points cannot arise here with exact
/// decisions (a disc with `q1`, `q2` on its boundary contains `p`); should they, the
/// diametral disc of the farthest pair is used, which keeps the algorithm total.
fn through3(q1: Point2, q2: Point2, p: Point2) -> Vec<Point2> {
    if orient2d(q1, q2, p) != Orientation::Collinear {
        return vec![q1, q2, p];
    }
    for (a, b, c) in [(q1, q2, p), (q1, p, q2), (q2, p, q1)] {
        if sign(&DiametralExpr(c, a, b)) != Ordering::Greater {
            return vec![a, b];
        }
    }
    vec![q1, q2]
}

/// The smallest disc containing every point (seeded random order; the disc does not depend
/// on the seed).
///
/// Errors: no points ([`Error::InvalidInput`]) or a non-finite coordinate
/// ([`Error::NonFinite`]).
///
/// ```
/// use compgeom::lp::smallest_enclosing_disc;
/// use compgeom::Point2;
/// let pts = [(0.0, 0.0), (4.0, 0.0), (2.0, 1.0), (1.0, -1.0)].map(Point2::from);
/// let d = smallest_enclosing_disc(&pts, 1)?;
/// assert_eq!(d.center, Point2::new(2.0, 0.0));
/// assert_eq!(d.radius, 2.0);
/// assert_eq!(d.support.len(), 2);
/// # Ok::<(), compgeom::Error>(())
/// ```
pub fn smallest_enclosing_disc(points: &[Point2], seed: u64) -> Result<Disc> {
    ensure_finite(points, "point")?;
    if points.is_empty() {
        return Err(Error::InvalidInput(
            "the smallest enclosing disc of no points is undefined".into(),
        ));
    }
    let mut p = points.to_vec();
    let mut rng = Shuffler::new(seed);
    rng.shuffle(&mut p);
    let mut support = vec![p[0]];
    for i in 1..p.len() {
        if !contains(&support, p[i]) {
            support = with_point(&p[..i], p[i]);
        }
    }
    Ok(finish(support))
}

/// MINIDISCWITHPOINT: the smallest disc of `p ∪ {q}` with `q` on its boundary.
fn with_point(p: &[Point2], q: Point2) -> Vec<Point2> {
    let mut support = vec![q, p[0]];
    for j in 1..p.len() {
        if !contains(&support, p[j]) {
            support = with_two_points(&p[..j], p[j], q);
        }
    }
    support
}

/// MINIDISCWITH2POINTS: the smallest disc of `p ∪ {q1, q2}` with both on its boundary.
fn with_two_points(p: &[Point2], q1: Point2, q2: Point2) -> Vec<Point2> {
    let mut support = vec![q1, q2];
    for &pk in p {
        if !contains(&support, pk) {
            support = through3(q1, q2, pk);
        }
    }
    support
}

/// Centre and radius from the support, in exact rationals, rounded once.
fn finish(mut support: Vec<Point2>) -> Disc {
    if support.len() == 2 && support[0] == support[1] {
        support.truncate(1);
    }
    let (cx, cy) = center_exact(&support);
    let a = support[0];
    let dx = to_f64(&(rat(a.x) - &cx));
    let dy = to_f64(&(rat(a.y) - &cy));
    Disc {
        center: Point2::new(to_f64(&cx), to_f64(&cy)),
        radius: dx.hypot(dy),
        support,
    }
}

/// The exact centre of the disc defined by `support`.
pub(crate) fn center_exact(support: &[Point2]) -> (BigRational, BigRational) {
    let two = BigRational::from_integer(2.into());
    match *support {
        [a] => (rat(a.x), rat(a.y)),
        [a, b] => ((rat(a.x) + rat(b.x)) / &two, (rat(a.y) + rat(b.y)) / &two),
        [a, b, c] => {
            let (ax, ay, bx, by, cx, cy) =
                (rat(a.x), rat(a.y), rat(b.x), rat(b.y), rat(c.x), rat(c.y));
            let d = &two * (&ax * (&by - &cy) + &bx * (&cy - &ay) + &cx * (&ay - &by));
            let (na, nb, nc) = (
                &ax * &ax + &ay * &ay,
                &bx * &bx + &by * &by,
                &cx * &cx + &cy * &cy,
            );
            let ux = (&na * (&by - &cy) + &nb * (&cy - &ay) + &nc * (&ay - &by)) / &d;
            let uy = (&na * (&cx - &bx) + &nb * (&ax - &cx) + &nc * (&bx - &ax)) / &d;
            (ux, uy)
        }
        _ => (rat(0.0), rat(0.0)),
    }
}

/// Check exactly that `disc` is the smallest disc enclosing `points`: every point is in the
/// disc its support defines, and the support forces it (one point: all points equal it; two:
/// they are diametral; three: they are not collinear and their triangle has no obtuse
/// angle, so no smaller disc has them all inside).
pub fn verify_enclosing_disc(points: &[Point2], disc: &Disc) -> Result<()> {
    let fail = |m: String| Err(Error::Verification(m));
    if disc.support.is_empty() || disc.support.len() > 3 {
        return fail(format!("support has {} points", disc.support.len()));
    }
    for s in &disc.support {
        if !points.contains(s) {
            return fail(format!(
                "support point ({}, {}) is not an input point",
                s.x, s.y
            ));
        }
    }
    for (i, p) in points.iter().enumerate() {
        if !disc.contains(*p) {
            return fail(format!("point {i} lies outside the disc"));
        }
    }
    if let [a, b, c] = disc.support[..] {
        if orient2d(a, b, c) == Orientation::Collinear {
            return fail("the three support points are collinear".into());
        }
        // An obtuse angle at any corner: the diametral disc of the opposite side is smaller.
        for (p, q, r) in [(a, b, c), (b, c, a), (c, a, b)] {
            let e = AngleExpr(p, q, r);
            if sign(&e) == Ordering::Less {
                return fail("the support triangle is obtuse: the disc is not minimal".into());
            }
        }
    }
    Ok(())
}

/// `(q - p)·(r - p)`: negative when the angle at `p` is obtuse.
struct AngleExpr(Point2, Point2, Point2);

impl SignExpr for AngleExpr {
    fn eval<N: Num>(&self) -> N {
        let (p, q, r) = (self.0, self.1, self.2);
        let d = |u: f64, v: f64| N::val(u).sub(&N::val(v));
        d(q.x, p.x)
            .mul(&d(r.x, p.x))
            .add(&d(q.y, p.y).mul(&d(r.y, p.y)))
    }
}
