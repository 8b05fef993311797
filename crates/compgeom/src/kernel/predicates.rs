//! Exact predicates on input points: Shewchuk's adaptive predicates (the `robust`
//! crate) where they are provably exact, an exact dyadic fallback elsewhere.
//!
//! ## Why a range check
//!
//! Shewchuk's expansion arithmetic and his error bounds are exact provided no
//! intermediate result overflows and none underflows. Each predicate therefore first
//! checks that every coordinate is `0` or has magnitude in `[2^LO, 2^HI)`, with bounds
//! chosen per predicate from its degree `D` (orient2d 2, orient3d 3, incircle 4,
//! insphere 5):
//!
//! * **No underflow.** A float `x` with `|x| >= 2^LO` is an integer multiple of its ulp,
//!   hence of `g = 2^(LO-52)`; so are `0` and every difference of coordinates (a
//!   difference can be as small as one ulp of the smaller coordinate, which is still a
//!   multiple of `g`). Sums, products and their round-to-nearest results preserve
//!   "multiple of `2^k`" (rounding only drops bits below the result's ulp, which is a
//!   power of two), and so do Dekker's splits (the splitter `2^27 + 1` is an integer).
//!   Every intermediate of degree `k <= D` is thus `0` or at least `g^k >= g^D` in
//!   magnitude. The only other products are the error bounds: constants no smaller than
//!   `9·2^-106 > 2^-103` (`ccwerrboundC`) times a nonzero degree-`D` quantity. Requiring
//!   `D·(LO-52) - 103 >= -1022` keeps every nonzero intermediate normal, so the
//!   computation is bit-for-bit the one Shewchuk proves exact for an unbounded exponent
//!   range. This gives `LO >= 52 - 919/D`.
//! * **No overflow.** With `|x| < 2^HI`, differences are below `2^(HI+1)`, and every
//!   intermediate is bounded by a sum of at most 72 (insphere; fewer for the others)
//!   degree-`D` products of differences, or by a Dekker split (`< 2^28` times a
//!   degree-`D-1` quantity, smaller as `HI >= 27`): at most `2^(D·(HI+1) + 8)`.
//!   Requiring that to stay `<= 2^1022` (a factor two left for rounding) gives
//!   `HI <= 1014/D - 1`. (insphere's last, exact stage multiplies raw coordinates
//!   instead of differences: its at most 360 degree-5 monomials stay below
//!   `2^(5·HI + 9)`, inside the same bound; raw coordinates are multiples of `g` too.)
//!
//! | predicate | degree | safe magnitudes (or 0) |
//! |---|---|---|
//! | orient2d | 2 | `[2^-400, 2^500)` |
//! | orient3d | 3 | `[2^-250, 2^330)` |
//! | incircle | 4 | `[2^-170, 2^250)` |
//! | insphere | 5 | `[2^-125, 2^200)` |
//!
//! Outside the range, when all nonzero coordinates span fewer binades than the range
//! does, they are scaled by one common power of two (exact, and sign-preserving since
//! each predicate is a homogeneous polynomial) into the range and `robust` is used.
//! Otherwise (mixed extreme magnitudes) the determinant is evaluated exactly with
//! dyadic big-integer arithmetic ([`super::exact`]).
//!
//! ## A float filter first (orient2d)
//!
//! Before the range check, `orient2d` evaluates its determinant once in plain `f64`
//! and takes the sign where it exceeds Shewchuk's first error bound `ccwerrboundA`
//! (plus an absolute term covering the underflow of a product, for sums of the
//! products' magnitudes from 1e-290 up to `f64::MAX`; non-finite values fail that
//! range and go on). Only what it cannot decide, nearly collinear triples, pays for the
//! range check and `robust` (which then evaluates its own float filter again). On the
//! intersections of the JTS robustness pairs the orientations took half the
//! instructions they did (1.5% of the whole). Segment intersection used the same
//! filter already ([`super::intersection`]).
//!
//! ## Non-finite input
//!
//! All coordinates are assumed finite (algorithms call [`super::ensure_finite`] first).
//! With a NaN or infinite coordinate the predicates do not panic: they return the
//! degenerate answer (`Collinear`, `OnCircle`, `Coplanar`, `OnSphere`).

use super::arith::Arith;
use super::exact::Dyadic;
use super::filter::{count, PREDICATE_FALLBACKS};
use super::types::{Point2, Point3};
use std::cmp::Ordering;

/// The turn made by three points in the plane.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Orientation {
    /// `a, b, c` turn left (positive signed area).
    CounterClockwise,
    /// `a, b, c` turn right (negative signed area).
    Clockwise,
    /// `a, b, c` lie on one line (includes repeated points).
    Collinear,
}

/// Where `d` lies with respect to the circle through `a, b, c`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CircleSide {
    /// Inside the circle (for `a, b, c` counter-clockwise).
    Inside,
    /// On the circle (or `a, b, c` collinear and `d` on their line).
    OnCircle,
    /// Outside the circle.
    Outside,
}

/// Where `d` lies with respect to the oriented plane through `a, b, c`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PlaneSide {
    /// Below: `a, b, c` appear counter-clockwise seen from above, `d` is below
    /// (Shewchuk's positive orient3d).
    Below,
    /// On the plane.
    Coplanar,
    /// Above.
    Above,
}

/// Where `e` lies with respect to the sphere through `a, b, c, d`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SphereSide {
    /// Inside (for `a, b, c, d` positively oriented, i.e. `orient3d` = [`PlaneSide::Below`]).
    Inside,
    /// On the sphere.
    OnSphere,
    /// Outside.
    Outside,
}

/// The range of magnitudes where `robust` is exact for a predicate (see module doc).
#[derive(Clone, Copy)]
struct SafeRange {
    /// Smallest allowed binary exponent of a nonzero coordinate.
    lo: i32,
    /// Every coordinate is below `2^hi`.
    hi: i32,
}

const ORIENT2D_RANGE: SafeRange = SafeRange { lo: -400, hi: 500 };
const ORIENT3D_RANGE: SafeRange = SafeRange { lo: -250, hi: 330 };
const INCIRCLE_RANGE: SafeRange = SafeRange { lo: -170, hi: 250 };
const INSPHERE_RANGE: SafeRange = SafeRange { lo: -125, hi: 200 };

/// How a predicate should be evaluated.
enum Route {
    /// All coordinates are in the safe range: call `robust` directly.
    Robust,
    /// Multiply every coordinate by `2^k` (exact), then call `robust`.
    Scaled(i64),
    /// Evaluate exactly.
    Exact,
    /// A coordinate is NaN or infinite.
    NonFinite,
}

/// The binary exponent `floor(log2 |x|)` of a finite nonzero `x` (subnormals included).
fn exponent(x: f64) -> i64 {
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i64;
    if biased == 0 {
        let frac = bits & ((1u64 << 52) - 1);
        63 - i64::from(frac.leading_zeros()) - 1074
    } else {
        biased - 1023
    }
}

/// True when every coordinate is 0 or has magnitude in `[2^lo, 2^hi)`: one subtraction
/// and comparison on the biased exponent per coordinate, no branches.
#[inline(always)]
fn in_range(coords: &[f64], r: SafeRange) -> bool {
    let lo_biased = (r.lo + 1023) as u64;
    let span = (r.hi - r.lo) as u64;
    coords.iter().fold(true, |ok, &x| {
        let bits = x.to_bits();
        let biased = (bits >> 52) & 0x7ff;
        ok & ((biased.wrapping_sub(lo_biased) < span) | (bits << 1 == 0))
    })
}

/// The route for coordinates that failed [`in_range`].
#[cold]
#[inline(never)]
fn slow_route(coords: &[f64], r: SafeRange) -> Route {
    let (mut emin, mut emax) = (i64::MAX, i64::MIN);
    for &x in coords {
        if !x.is_finite() {
            return Route::NonFinite;
        }
        if x != 0.0 {
            let e = exponent(x);
            emin = emin.min(e);
            emax = emax.max(e);
        }
    }
    let (lo, hi) = (i64::from(r.lo), i64::from(r.hi));
    if emax - emin < hi - lo {
        // Any k with emin + k >= lo and emax + k < hi works; centre the data in the
        // range. The bounds are compatible because emax - emin < hi - lo.
        let k = ((lo + hi) / 2 - (emin + emax) / 2).clamp(lo - emin, hi - 1 - emax);
        Route::Scaled(k)
    } else {
        Route::Exact
    }
}

#[inline(always)]
fn route(coords: &[f64], r: SafeRange) -> Route {
    if in_range(coords, r) {
        Route::Robust
    } else {
        slow_route(coords, r)
    }
}

/// `x · 2^k`, exact when the result is a normal number (as guaranteed by [`route`]).
fn scale(x: f64, k: i64) -> f64 {
    // |k| can exceed the exponent range of one factor: split in two. Both halves move
    // the same way, so the intermediate lies between x and the (normal) result: exact.
    let half = k / 2;
    x * super::exact::pow2(half) * super::exact::pow2(k - half)
}

fn c2(p: Point2) -> robust::Coord<f64> {
    robust::Coord { x: p.x, y: p.y }
}

fn c3(p: Point3) -> robust::Coord3D<f64> {
    robust::Coord3D {
        x: p.x,
        y: p.y,
        z: p.z,
    }
}

fn s2(p: Point2, k: i64) -> Point2 {
    Point2::new(scale(p.x, k), scale(p.y, k))
}

fn s3(p: Point3, k: i64) -> Point3 {
    Point3::new(scale(p.x, k), scale(p.y, k), scale(p.z, k))
}

fn sign_of(v: f64) -> Ordering {
    v.partial_cmp(&0.0).unwrap_or(Ordering::Equal)
}

fn exact_sign(d: Dyadic) -> Ordering {
    d.sign().unwrap_or(Ordering::Equal)
}

/// The orient2d determinant `(a - c) x (b - c)`, generic over the arithmetic.
pub(crate) fn orient2d_det<T: Arith>(a: Point2, b: Point2, c: Point2) -> T {
    let acx = T::diff(a.x, c.x);
    let acy = T::diff(a.y, c.y);
    let bcx = T::diff(b.x, c.x);
    let bcy = T::diff(b.y, c.y);
    acx.times(&bcy).minus(&acy.times(&bcx))
}

fn incircle_det<T: Arith>(a: Point2, b: Point2, c: Point2, d: Point2) -> T {
    let (adx, ady) = (T::diff(a.x, d.x), T::diff(a.y, d.y));
    let (bdx, bdy) = (T::diff(b.x, d.x), T::diff(b.y, d.y));
    let (cdx, cdy) = (T::diff(c.x, d.x), T::diff(c.y, d.y));
    let alift = adx.times(&adx).plus(&ady.times(&ady));
    let blift = bdx.times(&bdx).plus(&bdy.times(&bdy));
    let clift = cdx.times(&cdx).plus(&cdy.times(&cdy));
    let bc = bdx.times(&cdy).minus(&cdx.times(&bdy));
    let ca = cdx.times(&ady).minus(&adx.times(&cdy));
    let ab = adx.times(&bdy).minus(&bdx.times(&ady));
    alift
        .times(&bc)
        .plus(&blift.times(&ca))
        .plus(&clift.times(&ab))
}

fn orient3d_det<T: Arith>(a: Point3, b: Point3, c: Point3, d: Point3) -> T {
    let (adx, ady, adz) = (T::diff(a.x, d.x), T::diff(a.y, d.y), T::diff(a.z, d.z));
    let (bdx, bdy, bdz) = (T::diff(b.x, d.x), T::diff(b.y, d.y), T::diff(b.z, d.z));
    let (cdx, cdy, cdz) = (T::diff(c.x, d.x), T::diff(c.y, d.y), T::diff(c.z, d.z));
    let t1 = adx.times(&bdy.times(&cdz).minus(&bdz.times(&cdy)));
    let t2 = bdx.times(&cdy.times(&adz).minus(&cdz.times(&ady)));
    let t3 = cdx.times(&ady.times(&bdz).minus(&adz.times(&bdy)));
    t1.plus(&t2).plus(&t3)
}

fn insphere_det<T: Arith>(a: Point3, b: Point3, c: Point3, d: Point3, e: Point3) -> T {
    let rel = |p: Point3| (T::diff(p.x, e.x), T::diff(p.y, e.y), T::diff(p.z, e.z));
    let (aex, aey, aez) = rel(a);
    let (bex, bey, bez) = rel(b);
    let (cex, cey, cez) = rel(c);
    let (dex, dey, dez) = rel(d);
    let cross = |px: &T, py: &T, qx: &T, qy: &T| px.times(qy).minus(&qx.times(py));
    let ab = cross(&aex, &aey, &bex, &bey);
    let bc = cross(&bex, &bey, &cex, &cey);
    let cd = cross(&cex, &cey, &dex, &dey);
    let da = cross(&dex, &dey, &aex, &aey);
    let ac = cross(&aex, &aey, &cex, &cey);
    let bd = cross(&bex, &bey, &dex, &dey);
    let abc = aez.times(&bc).minus(&bez.times(&ac)).plus(&cez.times(&ab));
    let bcd = bez.times(&cd).minus(&cez.times(&bd)).plus(&dez.times(&bc));
    let cda = cez.times(&da).plus(&dez.times(&ac)).plus(&aez.times(&cd));
    let dab = dez.times(&ab).plus(&aez.times(&bd)).plus(&bez.times(&da));
    let lift = |x: &T, y: &T, z: &T| x.times(x).plus(&y.times(y)).plus(&z.times(z));
    let alift = lift(&aex, &aey, &aez);
    let blift = lift(&bex, &bey, &bez);
    let clift = lift(&cex, &cey, &cez);
    let dlift = lift(&dex, &dey, &dez);
    dlift
        .times(&abc)
        .minus(&clift.times(&dab))
        .plus(&blift.times(&cda).minus(&alift.times(&bcd)))
}

#[inline]
fn orient2d_sign(a: Point2, b: Point2, c: Point2) -> Ordering {
    // Plain `f64` with Shewchuk's first error bound decides all but nearly collinear
    // triples and extreme magnitudes, in a dozen instructions; the range check and
    // `robust` (with its own float filter) the rest.
    match super::intersection::orient_filtered(a, b, c) {
        1 => return Ordering::Greater,
        -1 => return Ordering::Less,
        _ => {}
    }
    match route(&[a.x, a.y, b.x, b.y, c.x, c.y], ORIENT2D_RANGE) {
        Route::Robust => sign_of(robust::orient2d(c2(a), c2(b), c2(c))),
        Route::Scaled(k) => sign_of(robust::orient2d(c2(s2(a, k)), c2(s2(b, k)), c2(s2(c, k)))),
        Route::Exact => {
            count(&PREDICATE_FALLBACKS);
            exact_sign(orient2d_det::<Dyadic>(a, b, c))
        }
        Route::NonFinite => Ordering::Equal,
    }
}

/// The exact orientation of the triple `a, b, c`, for every finite input.
///
/// With a non-finite coordinate the answer is `Collinear` (no panic).
///
/// ```
/// use compgeom::kernel::{orient2d, Orientation};
/// use compgeom::Point2;
/// let (a, b) = (Point2::new(0.0, 0.0), Point2::new(1e200, 1e200));
/// // A point one ulp above the diagonal, at a scale where naive products overflow.
/// let c = Point2::new(3e200, f64::from_bits(3e200f64.to_bits() + 1));
/// assert_eq!(orient2d(a, b, c), Orientation::CounterClockwise);
/// ```
#[inline]
pub fn orient2d(a: Point2, b: Point2, c: Point2) -> Orientation {
    match orient2d_sign(a, b, c) {
        Ordering::Greater => Orientation::CounterClockwise,
        Ordering::Less => Orientation::Clockwise,
        Ordering::Equal => Orientation::Collinear,
    }
}

/// Exactly where `d` lies relative to the circle through `a, b, c` (for every finite
/// input; a non-finite coordinate gives `OnCircle`).
#[inline]
pub fn incircle(a: Point2, b: Point2, c: Point2, d: Point2) -> CircleSide {
    let coords = [a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y];
    let sign = match route(&coords, INCIRCLE_RANGE) {
        Route::Robust => sign_of(robust::incircle(c2(a), c2(b), c2(c), c2(d))),
        Route::Scaled(k) => sign_of(robust::incircle(
            c2(s2(a, k)),
            c2(s2(b, k)),
            c2(s2(c, k)),
            c2(s2(d, k)),
        )),
        Route::Exact => {
            count(&PREDICATE_FALLBACKS);
            exact_sign(incircle_det::<Dyadic>(a, b, c, d))
        }
        Route::NonFinite => Ordering::Equal,
    };
    match sign {
        Ordering::Greater => CircleSide::Inside,
        Ordering::Less => CircleSide::Outside,
        Ordering::Equal => CircleSide::OnCircle,
    }
}

/// Exactly where `d` lies relative to the plane through `a, b, c` (for every finite
/// input; a non-finite coordinate gives `Coplanar`).
#[inline]
pub fn orient3d(a: Point3, b: Point3, c: Point3, d: Point3) -> PlaneSide {
    let coords = [a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z];
    let sign = match route(&coords, ORIENT3D_RANGE) {
        Route::Robust => sign_of(robust::orient3d(c3(a), c3(b), c3(c), c3(d))),
        Route::Scaled(k) => sign_of(robust::orient3d(
            c3(s3(a, k)),
            c3(s3(b, k)),
            c3(s3(c, k)),
            c3(s3(d, k)),
        )),
        Route::Exact => {
            count(&PREDICATE_FALLBACKS);
            exact_sign(orient3d_det::<Dyadic>(a, b, c, d))
        }
        Route::NonFinite => Ordering::Equal,
    };
    match sign {
        Ordering::Greater => PlaneSide::Below,
        Ordering::Less => PlaneSide::Above,
        Ordering::Equal => PlaneSide::Coplanar,
    }
}

/// Exactly where `e` lies relative to the sphere through `a, b, c, d` (for every finite
/// input; a non-finite coordinate gives `OnSphere`).
#[inline]
pub fn insphere(a: Point3, b: Point3, c: Point3, d: Point3, e: Point3) -> SphereSide {
    let coords = [
        a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z, e.x, e.y, e.z,
    ];
    let sign = match route(&coords, INSPHERE_RANGE) {
        Route::Robust => sign_of(robust::insphere(c3(a), c3(b), c3(c), c3(d), c3(e))),
        Route::Scaled(k) => sign_of(robust::insphere(
            c3(s3(a, k)),
            c3(s3(b, k)),
            c3(s3(c, k)),
            c3(s3(d, k)),
            c3(s3(e, k)),
        )),
        Route::Exact => {
            count(&PREDICATE_FALLBACKS);
            exact_sign(insphere_det::<Dyadic>(a, b, c, d, e))
        }
        Route::NonFinite => Ordering::Equal,
    };
    match sign {
        Ordering::Greater => SphereSide::Inside,
        Ordering::Less => SphereSide::Outside,
        Ordering::Equal => SphereSide::OnSphere,
    }
}

/// Lexicographic order: by x, then by y. Exact (it only compares values).
/// Both points must be finite (NaN compares as equal here).
pub fn compare_xy(a: Point2, b: Point2) -> Ordering {
    a.x.partial_cmp(&b.x)
        .unwrap_or(Ordering::Equal)
        .then(a.y.partial_cmp(&b.y).unwrap_or(Ordering::Equal))
}

/// Lexicographic order in space: by x, then y, then z.
pub fn compare_xyz(a: Point3, b: Point3) -> Ordering {
    a.x.partial_cmp(&b.x)
        .unwrap_or(Ordering::Equal)
        .then(a.y.partial_cmp(&b.y).unwrap_or(Ordering::Equal))
        .then(a.z.partial_cmp(&b.z).unwrap_or(Ordering::Equal))
}
