//! Filtered exact predicates for the triangulation hot loops.
//!
//! Each predicate first evaluates the determinant in `f64` with Shewchuk's static error
//! bound (stage A); when the sign is certain it is returned, otherwise (or when the
//! magnitudes are so small that products may underflow, or so large that they overflow)
//! the kernel's exact predicate decides — except when all coordinate differences are small
//! integers (integer grids, the common degenerate input), where the `f64` evaluation is
//! itself exact and its sign, zero included, is the answer. So every answer is exact; the filter only saves
//! the kernel's range checks on the common case.

use crate::kernel::arith::Arith;
use crate::kernel::exact::Dyadic;
use crate::kernel::filter::Bounded;
use crate::kernel::{incircle, orient2d, CircleSide, Orientation};
use crate::{Bbox2, Point2};
use std::cmp::Ordering;

const EPS: f64 = f64::EPSILON / 2.0;
const CCW_BOUND: f64 = (3.0 + 16.0 * EPS) * EPS;
const ICC_BOUND: f64 = (10.0 + 96.0 * EPS) * EPS;
/// Below this permanent, products may be subnormal and the static bound no longer holds.
const TINY: f64 = 1e-250;

/// Sign of orient2d(a, b, c): > 0 counter-clockwise, < 0 clockwise, 0 collinear. Exact.
#[inline(always)]
pub(crate) fn orient(a: Point2, b: Point2, c: Point2) -> i8 {
    let l = (a.x - c.x) * (b.y - c.y);
    let r = (a.y - c.y) * (b.x - c.x);
    let det = l - r;
    let sum = l.abs() + r.abs();
    if det.abs() > CCW_BOUND * sum && sum > TINY && sum < f64::MAX {
        return if det > 0.0 { 1 } else { -1 };
    }
    // Integer coordinates with differences up to 2^25: the differences, both products and
    // their difference are exact integers below 2^53.
    let d = [a.x - c.x, b.y - c.y, a.y - c.y, b.x - c.x];
    if integral(&[a, b, c]) && d.iter().all(|&v| v.abs() <= 33_554_432.0) {
        return if det > 0.0 {
            1
        } else if det < 0.0 {
            -1
        } else {
            0
        };
    }
    match orient2d(a, b, c) {
        Orientation::CounterClockwise => 1,
        Orientation::Clockwise => -1,
        Orientation::Collinear => 0,
    }
}

/// Stage A of [`orient`] alone: the sign of orient2d(a, b, c) when the static error bound
/// certifies it, `None` otherwise (also for non-finite or NaN input, where every comparison
/// fails). A `Some` is always the exact sign (nonzero); the caller decides the `None` cases.
#[inline(always)]
pub(crate) fn orient_filter(a: Point2, b: Point2, c: Point2) -> Option<i8> {
    let l = (a.x - c.x) * (b.y - c.y);
    let r = (a.y - c.y) * (b.x - c.x);
    let det = l - r;
    let sum = l.abs() + r.abs();
    if det.abs() > CCW_BOUND * sum && sum > TINY && sum < f64::MAX {
        Some(if det > 0.0 { 1 } else { -1 })
    } else {
        None
    }
}

/// Sign of incircle(a, b, c, d) for counter-clockwise a, b, c: > 0 inside, < 0 outside,
/// 0 on the circle. Exact.
#[inline(always)]
pub(crate) fn in_circle(a: Point2, b: Point2, c: Point2, d: Point2) -> i8 {
    let (adx, ady) = (a.x - d.x, a.y - d.y);
    let (bdx, bdy) = (b.x - d.x, b.y - d.y);
    let (cdx, cdy) = (c.x - d.x, c.y - d.y);
    let bdxcdy = bdx * cdy;
    let cdxbdy = cdx * bdy;
    let alift = adx * adx + ady * ady;
    let cdxady = cdx * ady;
    let adxcdy = adx * cdy;
    let blift = bdx * bdx + bdy * bdy;
    let adxbdy = adx * bdy;
    let bdxady = bdx * ady;
    let clift = cdx * cdx + cdy * cdy;
    let det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
    let perm = (bdxcdy.abs() + cdxbdy.abs()) * alift
        + (cdxady.abs() + adxcdy.abs()) * blift
        + (adxbdy.abs() + bdxady.abs()) * clift;
    if det.abs() > ICC_BOUND * perm && perm > TINY && perm < f64::MAX {
        return if det > 0.0 { 1 } else { -1 };
    }
    // Integer coordinates with small differences (integer grids): the differences are then
    // exact integers and every product and sum above is exact (|d| <= 2^12 gives
    // |det| < 3 * 2^50 < 2^53), so `det` is the exact value, zero included.
    if integral(&[a, b, c, d])
        && [adx, ady, bdx, bdy, cdx, cdy]
            .iter()
            .all(|&d| d.abs() <= 4096.0)
    {
        return if det > 0.0 {
            1
        } else if det < 0.0 {
            -1
        } else {
            0
        };
    }
    match incircle(a, b, c, d) {
        CircleSide::Inside => 1,
        CircleSide::Outside => -1,
        CircleSide::OnCircle => 0,
    }
}

/// The largest coordinate span (in x and in y) of a [`small_integer_grid`].
const GRID_SPAN: f64 = 4096.0;

/// True when every coordinate is an integer and the points span at most 2^12 in x and in
/// y (integer grids up to 4097 × 4097, at any integer offset). Then [`orient_grid`] and
/// [`in_circle_grid`] are exact for every triple and quadruple of these points.
///
/// The span test is exact: for integers `hi >= lo` the exact difference `D` is an integer;
/// if `D <= 2^12` it is representable and IEEE subtraction returns it; if `2^12 < D < 2^53`
/// it is representable too; if `D >= 2^53` the rounded difference is at least 2^53. So
/// `hi - lo <= 4096` in `f64` holds exactly when `D <= 4096`.
pub(crate) fn small_integer_grid(pts: &[Point2]) -> bool {
    if !integral(pts) {
        return false;
    }
    let b = Bbox2::of_points(pts);
    b.max.x - b.min.x <= GRID_SPAN && b.max.y - b.min.y <= GRID_SPAN
}

/// [`orient`] for points of a [`small_integer_grid`], without a filter: every coordinate
/// difference is an integer of magnitude at most 2^12, computed exactly (it is
/// representable, and IEEE subtraction is correctly rounded); the two products are below
/// 2^24 and their difference below 2^25, all exact. So the sign, zero included, is exact.
#[inline(always)]
pub(crate) fn orient_grid(a: Point2, b: Point2, c: Point2) -> i8 {
    let det = (a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x);
    sign(det)
}

/// [`in_circle`] for points of a [`small_integer_grid`], without a filter: the differences
/// are exact integers with `|d| <= 2^12`; lifts `dx² + dy² <= 2^25`, cross products
/// `<= 2^24` and their differences `<= 2^25`; each of the three terms `<= 2^50` and their
/// sum `<= 3 · 2^50 < 2^53`. Every intermediate is an integer below 2^53, so the
/// evaluation is exact and its sign, zero included, is the exact answer.
#[inline(always)]
pub(crate) fn in_circle_grid(a: Point2, b: Point2, c: Point2, d: Point2) -> i8 {
    let (adx, ady) = (a.x - d.x, a.y - d.y);
    let (bdx, bdy) = (b.x - d.x, b.y - d.y);
    let (cdx, cdy) = (c.x - d.x, c.y - d.y);
    let alift = adx * adx + ady * ady;
    let blift = bdx * bdx + bdy * bdy;
    let clift = cdx * cdx + cdy * cdy;
    let det = alift * (bdx * cdy - cdx * bdy)
        + blift * (cdx * ady - adx * cdy)
        + clift * (adx * bdy - bdx * ady);
    sign(det)
}

#[inline(always)]
fn sign(v: f64) -> i8 {
    i8::from(v > 0.0) - i8::from(v < 0.0)
}

/// The exact sign of a polynomial written once over [`Arith`]: the `f64` enclosure first,
/// exact dyadic arithmetic when it cannot decide.
macro_rules! exact_sign {
    ($f:ident ( $($arg:expr),* )) => {
        $f::<Bounded>($($arg),*)
            .sign()
            .or_else(|| $f::<Dyadic>($($arg),*).sign())
            .unwrap_or(Ordering::Equal)
    };
}

fn dot_det<T: Arith>(p: Point2, a: Point2, b: Point2) -> T {
    let (ax, ay) = (T::diff(a.x, p.x), T::diff(a.y, p.y));
    let (bx, by) = (T::diff(b.x, p.x), T::diff(b.y, p.y));
    ax.times(&bx).plus(&ay.times(&by))
}

/// The exact sign of the dot product `(a - p) · (b - p)`: `Less` when `p` is strictly
/// inside the circle with diameter `a b` (the angle `a p b` is obtuse).
pub(crate) fn dot_sign(p: Point2, a: Point2, b: Point2) -> Ordering {
    exact_sign!(dot_det(p, a, b))
}

fn sharp_det<T: Arith>(p: Point2, a: Point2, b: Point2, cos2: f64) -> T {
    let (ax, ay) = (T::diff(a.x, p.x), T::diff(a.y, p.y));
    let (bx, by) = (T::diff(b.x, p.x), T::diff(b.y, p.y));
    let dot = ax.times(&bx).plus(&ay.times(&by));
    let la = ax.times(&ax).plus(&ay.times(&ay));
    let lb = bx.times(&bx).plus(&by.times(&by));
    dot.times(&dot).minus(&T::val(cos2).times(&la).times(&lb))
}

/// Exact: is the angle `a p b` strictly smaller than the angle whose squared cosine is
/// `cos2` (`0 < cos2 < 1`, an acute angle)? That is `(a-p)·(b-p) > 0` and
/// `((a-p)·(b-p))² > cos2 |a-p|² |b-p|²`, decided exactly for the given `f64` `cos2`.
pub(crate) fn angle_below(p: Point2, a: Point2, b: Point2, cos2: f64) -> bool {
    dot_sign(p, a, b) == Ordering::Greater
        && exact_sign!(sharp_det(p, a, b, cos2)) == Ordering::Greater
}

fn area_det<T: Arith>(a: Point2, b: Point2, c: Point2, twice: f64) -> T {
    let (bx, by) = (T::diff(b.x, a.x), T::diff(b.y, a.y));
    let (cx, cy) = (T::diff(c.x, a.x), T::diff(c.y, a.y));
    bx.times(&cy).minus(&by.times(&cx)).minus(&T::val(twice))
}

/// Exact: is the area of the counter-clockwise triangle `a b c` strictly larger than
/// `twice / 2`?
pub(crate) fn area_above(a: Point2, b: Point2, c: Point2, twice: f64) -> bool {
    exact_sign!(area_det(a, b, c, twice)) == Ordering::Greater
}

/// True only when every coordinate is an integer (of magnitude at most 2^63; larger
/// integers answer `false`, which merely sends the caller to the general exact path).
///
/// `v as i64` truncates towards zero and saturates, so `(v as i64) as f64 == v` holds exactly
/// for the integers in [-2^63, 2^63] and fails for every other value (NaN gives 0). It is two
/// conversions, where `f64::trunc` is a library call on the baseline x86-64 target.
#[inline(always)]
fn integral(p: &[Point2]) -> bool {
    p.iter()
        .all(|p| (p.x as i64) as f64 == p.x && (p.y as i64) as f64 == p.y)
}

/// True when `q` lies strictly between `a` and `b` on their (common) line; the caller
/// knows the three are collinear. Exact (coordinate comparisons only).
#[inline]
pub(crate) fn strictly_between(a: Point2, b: Point2, q: Point2) -> bool {
    let (lo, hi) = if (a.x, a.y) < (b.x, b.y) {
        (a, b)
    } else {
        (b, a)
    };
    (lo.x, lo.y) < (q.x, q.y) && (q.x, q.y) < (hi.x, hi.y)
}

/// The neighbouring `f64` values of a finite `v`: (below, above), infinite past the range.
fn neighbours(v: f64) -> (f64, f64) {
    let step = |x: f64, up: bool| {
        if x == 0.0 {
            let tiny = f64::from_bits(1);
            return if up { tiny } else { -tiny };
        }
        // Away from zero is one more in the bit pattern, towards zero one less.
        let away = (x > 0.0) == up;
        f64::from_bits(if away {
            x.to_bits() + 1
        } else {
            x.to_bits() - 1
        })
    };
    (step(v, false), step(v, true))
}

/// The closed rounding cell of the finite `v`: the reals within half a gap of `v`, as the
/// offsets `(below, above)` (both ≥ 0). Half a gap is exact except below the smallest
/// normal gap, where the whole gap is used (a slightly larger cell); at `±f64::MAX` the
/// inner gap is used on both sides.
fn cell_offsets(v: f64) -> (f64, f64) {
    let (lo, hi) = neighbours(v);
    let half = |gap: f64| {
        if (gap / 2.0) * 2.0 == gap {
            gap / 2.0
        } else {
            gap
        }
    };
    let (below, above) = (half(v - lo), half(hi - v));
    match (below.is_finite(), above.is_finite()) {
        (true, false) => (below, below),
        (false, true) => (above, above),
        _ => (below, above),
    }
}

/// `a - (z + d)`, exactly.
fn offset_diff<T: Arith>(a: f64, z: f64, d: f64) -> T {
    T::diff(a, z).minus(&T::val(d))
}

/// orient2d(o0, o1, z + (dx, dy)), exactly (the corner need not be an `f64` point).
fn corner_side<T: Arith>(o0: Point2, o1: Point2, z: Point2, dx: f64, dy: f64) -> T {
    let (ux, uy) = (T::diff(o1.x, o0.x), T::diff(o1.y, o0.y));
    let px = T::diff(z.x, o0.x).plus(&T::val(dx));
    let py = T::diff(z.y, o0.y).plus(&T::val(dy));
    ux.times(&py).minus(&uy.times(&px))
}

/// Does the closed segment `o0–o1` meet the rounding cell of the point `z` (the closed
/// box of reals that round to `z`, see `cell_offsets`)? Exact: the boxes overlap and the
/// cell's corners are not all strictly on one side of the segment's line.
pub(crate) fn segment_meets_cell(z: Point2, o0: Point2, o1: Point2) -> bool {
    let (xl, xh) = cell_offsets(z.x);
    let (yl, yh) = cell_offsets(z.y);
    let outside = |lo: f64, hi: f64, zc: f64, below: f64, above: f64| {
        exact_sign!(offset_diff(hi, zc, -below)) == Ordering::Less
            || exact_sign!(offset_diff(lo, zc, above)) == Ordering::Greater
    };
    if outside(o0.x.min(o1.x), o0.x.max(o1.x), z.x, xl, xh)
        || outside(o0.y.min(o1.y), o0.y.max(o1.y), z.y, yl, yh)
    {
        return false;
    }
    let sides = [(-xl, -yl), (xh, -yl), (xh, yh), (-xl, yh)]
        .map(|(dx, dy)| exact_sign!(corner_side(o0, o1, z, dx, dy)));
    !(sides.iter().all(|&s| s == Ordering::Greater) || sides.iter().all(|&s| s == Ordering::Less))
}

fn along_det<T: Arith>(p: Point2, q: Point2, a: Point2, b: Point2) -> T {
    let (dx, dy) = (T::diff(b.x, a.x), T::diff(b.y, a.y));
    T::diff(p.x, q.x)
        .times(&dx)
        .plus(&T::diff(p.y, q.y).times(&dy))
}

/// The order of `p` and `q` along the direction from `a` to `b`: the exact sign of
/// `(p - q) · (b - a)`.
pub(crate) fn along_cmp(p: Point2, q: Point2, a: Point2, b: Point2) -> Ordering {
    exact_sign!(along_det(p, q, a, b))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn filters_agree_with_the_kernel_on_near_degenerate_input() {
        let a = Point2::new(0.5, 0.5);
        let b = Point2::new(12.0, 12.0);
        for i in 0..200 {
            let c = Point2::new(24.0 + i as f64 * 1e-14, 24.0);
            let k = match orient2d(a, b, c) {
                Orientation::CounterClockwise => 1,
                Orientation::Clockwise => -1,
                Orientation::Collinear => 0,
            };
            assert_eq!(orient(a, b, c), k);
        }
        let (p, q, r) = (
            Point2::new(1.0, 0.0),
            Point2::new(0.0, 1.0),
            Point2::new(-1.0, 0.0),
        );
        assert_eq!(in_circle(p, q, r, Point2::new(0.0, -1.0)), 0);
        assert_eq!(in_circle(p, q, r, Point2::new(0.0, -1.0 + 1e-16)), 1);
        assert_eq!(in_circle(p, q, r, Point2::new(1e-300, 1e-300)), 1);
        // Integer grid with a huge offset: the differences are exact, zero is exact.
        let o = 1e17;
        let g = |x: f64, y: f64| Point2::new(o + x, o + y);
        assert_eq!(
            in_circle(g(0.0, 0.0), g(16.0, 0.0), g(16.0, 16.0), g(0.0, 16.0)),
            0
        );
        assert_eq!(orient(g(0.0, 0.0), g(16.0, 16.0), g(32.0, 32.0)), 0);
        // Non-integer tiny offsets must not take the integer path.
        let q = Point2::new(1048576.0, 0.0);
        let r = Point2::new(-1e-40, 0.0);
        assert_eq!(orient(q, Point2::new(0.0, 0.0), r), 0);
        assert_eq!(orient(q, Point2::new(0.0, 1e-300), r), 1);
        let t = 1e-300;
        assert_eq!(
            orient(
                Point2::new(0.0, 0.0),
                Point2::new(t, 0.0),
                Point2::new(0.0, t)
            ),
            1
        );
    }

    use proptest::prelude::*;

    fn k_orient(a: Point2, b: Point2, c: Point2) -> i8 {
        match orient2d(a, b, c) {
            Orientation::CounterClockwise => 1,
            Orientation::Clockwise => -1,
            Orientation::Collinear => 0,
        }
    }

    fn k_incircle(a: Point2, b: Point2, c: Point2, d: Point2) -> i8 {
        match incircle(a, b, c, d) {
            CircleSide::Inside => 1,
            CircleSide::Outside => -1,
            CircleSide::OnCircle => 0,
        }
    }

    /// One ulp up or down (or nothing), for near-degenerate versions of exact patterns.
    fn nudge(v: f64, k: u8) -> f64 {
        match k % 3 {
            0 => v,
            1 => v.next_up(),
            _ => v.next_down(),
        }
    }

    /// Degenerate quadruples: grid points (spacing `step`, offset `off`), so that integer,
    /// large-integer, beyond-2^53/2^63 and non-integer dyadic grids are all produced;
    /// duplicates, collinear triples and cocircular squares/rectangles are common; some
    /// coordinates are moved by one ulp.
    fn quad() -> impl Strategy<Value = [Point2; 4]> {
        let scale = prop_oneof![
            Just((1.0, 0.0)),
            Just((1.0, 1e6)),
            Just((1.0, 33_554_000.0)),
            Just((1.0, 9.007_199_254_740_992e15)),
            Just((1024.0, 2f64.powi(63))),
            Just((2048.0, -(2f64.powi(63)))),
            Just((0.5, 0.0)),
            Just((0.5, 1e6)),
            Just((2f64.powi(-30), 1.0)),
            Just((3.0, -1e12)),
            Just((2f64.powi(-1000), 0.0)),
            Just((2f64.powi(900), 0.0)),
        ];
        (
            scale,
            prop::collection::vec((-5000i32..5000, -5000i32..5000, any::<u8>()), 4),
            0..4u8,
        )
            .prop_map(|((step, off), v, small)| {
                let pts: Vec<Point2> = v
                    .iter()
                    .map(|&(x, y, k)| {
                        // Mostly tiny ranges, where ties abound; sometimes the full range.
                        let (x, y) = if small > 0 { (x % 4, y % 4) } else { (x, y) };
                        let (px, py) = (off + f64::from(x) * step, off + f64::from(y) * step);
                        if k < 40 {
                            Point2::new(nudge(px, k), nudge(py, k / 3))
                        } else {
                            Point2::new(px, py)
                        }
                    })
                    .collect();
                [pts[0], pts[1], pts[2], pts[3]]
            })
    }

    /// Integer points on the circle x² + y² = 5525 (many lattice points), shifted.
    fn lattice_circle() -> impl Strategy<Value = [Point2; 4]> {
        let mut on: Vec<(f64, f64)> = Vec::new();
        for x in -74i32..=74 {
            for y in -74i32..=74 {
                if x * x + y * y == 5525 {
                    on.push((f64::from(x), f64::from(y)));
                }
            }
        }
        let shift = prop_oneof![Just(0.0), Just(4000.0), Just(-1e9), Just(2f64.powi(60))];
        (prop::collection::vec(0..on.len(), 4), shift, any::<bool>()).prop_map(
            move |(ix, s, nudged)| {
                let mut q = ix.iter().map(|&i| Point2::new(on[i].0 + s, on[i].1 - s));
                let mut r = [(); 4].map(|_| q.next().unwrap_or_default());
                if nudged {
                    r[3].x = r[3].x.next_up();
                }
                r
            },
        )
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(4000))]

        /// The filtered predicates, including their integer stage, agree with the kernel's
        /// exact predicates on degenerate input at every scale.
        #[test]
        fn fast_paths_equal_the_exact_predicates(q in quad()) {
            let [a, b, c, d] = q;
            prop_assert_eq!(orient(a, b, c), k_orient(a, b, c));
            prop_assert_eq!(orient(b, d, a), k_orient(b, d, a));
            prop_assert_eq!(in_circle(a, b, c, d), k_incircle(a, b, c, d));
            prop_assert_eq!(in_circle(d, c, b, a), k_incircle(d, c, b, a));
        }

        /// The grid predicates equal the exact ones whenever the points qualify as a small
        /// integer grid (and the check refuses every other quadruple it is shown).
        #[test]
        fn grid_paths_equal_the_exact_predicates(q in quad()) {
            if small_integer_grid(&q) {
                let [a, b, c, d] = q;
                prop_assert_eq!(orient_grid(a, b, c), k_orient(a, b, c));
                prop_assert_eq!(orient_grid(d, a, c), k_orient(d, a, c));
                prop_assert_eq!(in_circle_grid(a, b, c, d), k_incircle(a, b, c, d));
                prop_assert_eq!(in_circle_grid(b, d, c, a), k_incircle(b, d, c, a));
            }
        }

        #[test]
        fn fast_paths_on_lattice_circles(q in lattice_circle()) {
            let [a, b, c, d] = q;
            prop_assert_eq!(orient(a, b, c), k_orient(a, b, c));
            prop_assert_eq!(in_circle(a, b, c, d), k_incircle(a, b, c, d));
            if small_integer_grid(&q) {
                prop_assert_eq!(in_circle_grid(a, b, c, d), k_incircle(a, b, c, d));
            }
        }
    }

    #[test]
    fn small_integer_grid_limits() {
        let p = |x: f64, y: f64| Point2::new(x, y);
        assert!(small_integer_grid(&[
            p(0.0, 0.0),
            p(4096.0, -4096.0 + 4096.0)
        ]));
        assert!(small_integer_grid(&[
            p(-2048.0, 1e18),
            p(2048.0, 1e18 + 4096.0)
        ]));
        assert!(!small_integer_grid(&[p(0.0, 0.0), p(4097.0, 0.0)]));
        assert!(!small_integer_grid(&[p(0.0, 0.0), p(0.5, 0.0)]));
        // Beyond 2^53 neighbouring integers are 2 or more apart; still exact differences.
        assert!(small_integer_grid(&[
            p(2f64.powi(60), 0.0),
            p(2f64.powi(60) + 4096.0, 0.0)
        ]));
        assert!(!small_integer_grid(&[
            p(2f64.powi(60), 0.0),
            p(2f64.powi(60) + 8192.0, 0.0)
        ]));
        // Integers beyond 2^63 are refused (conservatively) by the integer test.
        assert!(!small_integer_grid(&[p(2f64.powi(70), 0.0)]));
        // The extreme corners: every difference at the limit, lifts and terms the largest.
        let g = [
            p(0.0, 0.0),
            p(4096.0, 0.0),
            p(4096.0, 4096.0),
            p(0.0, 4096.0),
        ];
        assert!(small_integer_grid(&g));
        assert_eq!(in_circle_grid(g[0], g[1], g[2], g[3]), 0);
        assert_eq!(in_circle_grid(g[0], g[1], g[2], p(2048.0, 2048.0)), 1);
        assert_eq!(
            in_circle_grid(g[0], g[1], p(4096.0, 4095.0), g[3]),
            k_incircle(g[0], g[1], p(4096.0, 4095.0), g[3])
        );
    }

    #[test]
    fn rounding_cells_are_met_exactly() {
        let p = |x, y| Point2::new(x, y);
        // Around 1.0 the gap below is 2^-53, above 2^-52: the cell of (1, 1) is
        // [1 - 2^-54, 1 + 2^-53] in each coordinate.
        let z = p(1.0, 1.0);
        assert_eq!(cell_offsets(1.0), (2f64.powi(-54), 2f64.powi(-53)));
        // Horizontal segments on the point and through the next f64 above (beyond the
        // cell's top side 1 + 2^-53, which is not an f64 itself).
        let up = f64::from_bits(1f64.to_bits() + 1);
        assert!(segment_meets_cell(z, p(0.0, 1.0), p(2.0, 1.0)));
        assert!(!segment_meets_cell(z, p(0.0, up), p(2.0, up)));
        // The diagonal y = x goes through the centre; the anti-diagonal x + y = 2 + 2^-52
        // (between (1, 1 + 2^-52) and (1 + 2^-52, 1)) touches the cell only at its corner
        // (1 + 2^-53, 1 + 2^-53); x + y = 2 + 2^-51 passes beyond it.
        assert!(segment_meets_cell(z, p(0.0, 0.0), p(4.0, 4.0)));
        let (e1, e2) = (1.0 + 2f64.powi(-52), 1.0 + 2f64.powi(-51));
        assert!(segment_meets_cell(z, p(1.0, e1), p(e1, 1.0)));
        assert!(!segment_meets_cell(z, p(1.0, e2), p(e2, 1.0)));
        // Ends before the cell.
        assert!(!segment_meets_cell(z, p(0.0, 1.0), p(0.5, 1.0)));
        // Zero: half the smallest gap is not an f64, the whole gap is used.
        let tiny = f64::from_bits(1);
        assert_eq!(cell_offsets(0.0), (tiny, tiny));
        assert!(segment_meets_cell(p(0.0, 0.0), p(-1.0, tiny), p(1.0, tiny)));
        assert!(!segment_meets_cell(
            p(0.0, 0.0),
            p(-1.0, 2.0 * tiny),
            p(1.0, 2.0 * tiny)
        ));
        // The largest finite value: the inner gap on both sides.
        let (lo, hi) = cell_offsets(f64::MAX);
        assert!(lo.is_finite() && lo == hi);
    }

    #[test]
    fn order_along_a_direction_is_exact() {
        let p = |x, y| Point2::new(x, y);
        let (a, b) = (p(0.0, 0.0), p(1.0, 3.0));
        assert_eq!(along_cmp(p(1.0, 0.0), p(0.0, 0.0), a, b), Ordering::Greater);
        // (3, -1) is perpendicular to (1, 3): equal projections.
        assert_eq!(along_cmp(p(3.0, -1.0), p(0.0, 0.0), a, b), Ordering::Equal);
        assert_eq!(
            along_cmp(p(3.0, -1.0), p(0.0, -f64::from_bits(1)), a, b),
            Ordering::Greater
        );
    }
}
