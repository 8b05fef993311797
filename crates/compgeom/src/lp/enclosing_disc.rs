//! Smallest enclosing disc (book §4.7): MINIDISC, MINIDISCWITHPOINT and
//! MINIDISCWITH2POINTS, randomized incremental, expected O(n).
//!
//! The disc is always defined by one to three input points on its boundary (its
//! *support*), so "is `p` in the current disc" is an exact predicate on input points:
//! for three support points the kernel's [`incircle`] together with [`orient2d`], for two
//! the exact sign of `(p - a)·(p - b)` (inside the disc with diameter `ab` iff `<= 0`),
//! for one `p == a`. Points on the circle count as inside. Those predicates are paid only
//! near the circle: the disc being built also carries an `f64` centre with a rigorous bound
//! on its error, and a point clearly inside or outside is decided by a squared distance. The centre and radius are
//! computed once, at the end, from the support in exact rationals and rounded to the
//! nearest `f64` (the radius within one ulp: the square root of the exact squared radius,
//! correctly rounded before the root).
//!
//! Degenerate input: duplicates, collinear and cocircular sets are ordinary input. When a
//! minimal disc has several possible supports (cocircular points), which one is reported
//! depends on the seed; the disc does not.

use super::exact::{rat, sign, to_f64, Filt, Num, SignExpr, ETA, U};
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
fn through3(q1: Point2, q2: Point2, p: Point2) -> Current {
    if orient2d(q1, q2, p) != Orientation::Collinear {
        return Current::new(&[q1, q2, p]);
    }
    for (a, b, c) in [(q1, q2, p), (q1, p, q2), (q2, p, q1)] {
        if sign(&DiametralExpr(c, a, b)) != Ordering::Greater {
            return Current::new(&[a, b]);
        }
    }
    Current::new(&[q1, q2])
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
    let mut disc = Current::new(&[p[0]]);
    for i in 1..p.len() {
        if !disc.contains(p[i]) {
            disc = with_point(&p[..i], p[i]);
        }
    }
    Ok(finish(disc.support[..disc.len].to_vec()))
}

/// The disc being built: its support (no allocation) and an `f64` picture of it with a
/// rigorous error bound, so that "is `p` in the disc" costs a few flops unless `p` is
/// within rounding distance of the circle; then the exact predicate decides.
#[derive(Debug, Clone, Copy)]
struct Current {
    support: [Point2; 3],
    len: usize,
    cx: f64,
    cy: f64,
    /// Squared distance from the approximate centre below which a point is surely inside.
    inside2: f64,
    /// Squared distance from the approximate centre above which a point is surely outside.
    outside2: f64,
}

/// Relative margin covering the rounding of the few operations in each bound (each well
/// under 10 units of 2^-53 ≈ 1.1e-16).
const MARGIN: f64 = 1e-13;

impl Current {
    fn new(support: &[Point2]) -> Current {
        let mut sp = [Point2::new(0.0, 0.0); 3];
        sp[..support.len()].copy_from_slice(support);
        // Approximate centre and a bound `delta` on its distance from the exact centre.
        let (cx, cy, delta) = match *support {
            [a] => (a.x, a.y, 0.0),
            [a, b] => {
                let (cx, cy) = ((a.x + b.x) * 0.5, (a.y + b.y) * 0.5);
                (cx, cy, 2.0 * U * (cx.abs() + cy.abs()) + ETA)
            }
            [a, b, c] => circumcentre(a, b, c),
            _ => (0.0, 0.0, f64::INFINITY),
        };
        // The exact radius is |a - c| for the exact centre c, within `delta` of |a - c̃|.
        let a = sp[0];
        let ra = (a.x - cx).hypot(a.y - cy);
        let lo = ra * (1.0 - MARGIN) - 2.0 * delta;
        let hi = ra * (1.0 + MARGIN) + 2.0 * delta;
        let (inside2, outside2) = if delta.is_finite() && hi.is_finite() {
            (
                if lo > 0.0 {
                    lo * lo * (1.0 - MARGIN)
                } else {
                    -1.0
                },
                hi * hi * (1.0 + MARGIN),
            )
        } else {
            (-1.0, f64::INFINITY)
        };
        Current {
            support: sp,
            len: support.len(),
            cx,
            cy,
            inside2,
            outside2,
        }
    }

    /// Exact containment (boundary included): the filter, else the exact predicate.
    #[inline]
    fn contains(&self, p: Point2) -> bool {
        let (dx, dy) = (p.x - self.cx, p.y - self.cy);
        // Computed with relative error under 6 units of 2^-53 (all terms non-negative).
        let d2 = dx * dx + dy * dy;
        if d2 * (1.0 + MARGIN) < self.inside2 {
            return true;
        }
        if d2 * (1.0 - MARGIN) > self.outside2 {
            return false;
        }
        contains(&self.support[..self.len], p)
    }
}

/// The circumcentre of `a, b, c` in `f64` (computed relative to `a`) and a bound on its
/// distance from the exact one (`inf` when the filter cannot bound it, e.g. nearly
/// collinear points).
fn circumcentre(a: Point2, b: Point2, c: Point2) -> (f64, f64, f64) {
    let f = Filt::val;
    let (bx, by) = (f(b.x).sub(&f(a.x)), f(b.y).sub(&f(a.y)));
    let (cx, cy) = (f(c.x).sub(&f(a.x)), f(c.y).sub(&f(a.y)));
    let nb = bx.mul(&bx).add(&by.mul(&by));
    let nc = cx.mul(&cx).add(&cy.mul(&cy));
    let den = bx.mul(&cy).sub(&by.mul(&cx));
    let den = den.add(&den);
    let nx = nb.mul(&cy).sub(&nc.mul(&by));
    let ny = nc.mul(&bx).sub(&nb.mul(&cx));
    let (dv, de) = (den.value(), den.error());
    if dv.is_nan() || de.is_nan() || dv.abs() <= 2.0 * de {
        return (0.0, 0.0, f64::INFINITY);
    }
    // |n/d - n~/d~| <= (|n~|·e_d + |d~|·e_n) / (|d~|·(|d~| - e_d)), plus the rounding
    // of the quotient and of the final sum.
    let quot = |n: &Filt| {
        let q = n.value() / dv;
        let e = (n.value().abs() * de + dv.abs() * n.error()) / (dv.abs() * (dv.abs() - de));
        (q, e + U * q.abs())
    };
    let ((qx, ex), (qy, ey)) = (quot(&nx), quot(&ny));
    let (ux, uy) = (a.x + qx, a.y + qy);
    let delta = (ex + ey + U * (ux.abs() + uy.abs())) * (1.0 + MARGIN) + ETA;
    (
        ux,
        uy,
        if delta.is_finite() {
            delta
        } else {
            f64::INFINITY
        },
    )
}

/// MINIDISCWITHPOINT: the smallest disc of `p ∪ {q}` with `q` on its boundary.
fn with_point(p: &[Point2], q: Point2) -> Current {
    let mut disc = Current::new(&[q, p[0]]);
    for j in 1..p.len() {
        if !disc.contains(p[j]) {
            disc = with_two_points(&p[..j], p[j], q);
        }
    }
    disc
}

/// MINIDISCWITH2POINTS: the smallest disc of `p ∪ {q1, q2}` with both on its boundary.
fn with_two_points(p: &[Point2], q1: Point2, q2: Point2) -> Current {
    let mut disc = Current::new(&[q1, q2]);
    for &pk in p {
        if !disc.contains(pk) {
            disc = through3(q1, q2, pk);
        }
    }
    disc
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
