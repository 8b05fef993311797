//! Exact decisions on half-planes and on the constructed points where their lines meet.
//!
//! A line here is `a·x + b·y = c + m·M` where `a, b, c` are input `f64`s and `m` is 0 for
//! input lines or ±1 for the four sides of a **symbolic bounding box** `|x|, |y| <= M`,
//! with `M` larger than any finite quantity. The box makes every linear program bounded
//! and every half-plane intersection a polygon; a result that still touches the box is
//! unbounded, and the coefficient of `M` says in which direction.
//!
//! Every decision is the sign of a polynomial in the inputs (and in `M`, whose leading
//! coefficient decides). It is evaluated first in `f64` with a rigorous running error bound
//! ([`Filt`]); when that cannot tell, in double-double arithmetic with a bound ([`Dd`]);
//! when that cannot tell either, exactly with big rationals ([`Ex`]; every `f64` converts
//! to a rational exactly). Corners are rounded to the nearest `f64` in 128-bit integer
//! arithmetic where the scales allow ([`meet_f64`]), else through rationals.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use std::cmp::Ordering;

/// Ring operations on a filtered or an exact value.
pub(crate) trait Num: Sized {
    /// The exact value of a finite `f64`.
    fn val(a: f64) -> Self;
    /// `self + o`.
    fn add(&self, o: &Self) -> Self;
    /// `self - o`.
    fn sub(&self, o: &Self) -> Self;
    /// `self · o`.
    fn mul(&self, o: &Self) -> Self;
    /// The certain sign, or `None` when the filter cannot tell.
    fn sign(&self) -> Option<Ordering>;
}

/// `f64` value `v` with a bound `e >= |v - exact|`.
///
/// With `u = 2^-53`: a sum or difference adds `u·|v|` to the propagated bounds, a product
/// `|x|·e_y + |y|·e_x + e_x·e_y + u·|v|`; each product adds `ETA` for underflow (sums are
/// exact on underflow; a product with an exact zero factor is an exact zero). The final test
/// asks `|v| > e·(1 + 2^-40)`, which covers the roundings of the bound itself for the
/// short expressions used here (under 60 steps). Overflow gives `inf`/`NaN`: undecided.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Filt {
    v: f64,
    e: f64,
}

/// 2^-53, the unit roundoff.
pub(crate) const U: f64 = 1.0 / 9_007_199_254_740_992.0;
/// A bound on the absolute error of one underflowing operation.
pub(crate) const ETA: f64 = 5e-320;
const SAFETY: f64 = 1.0 + 1.0 / 1_099_511_627_776.0;

impl Num for Filt {
    #[inline]
    fn val(a: f64) -> Self {
        Filt { v: a, e: 0.0 }
    }
    #[inline]
    fn add(&self, o: &Self) -> Self {
        // A sum never underflows (sums of subnormals are exact): no `ETA` term, so exact
        // zeros stay exact.
        let v = self.v + o.v;
        Filt {
            v,
            e: self.e + o.e + v.abs() * U,
        }
    }
    #[inline]
    fn sub(&self, o: &Self) -> Self {
        let v = self.v - o.v;
        Filt {
            v,
            e: self.e + o.e + v.abs() * U,
        }
    }
    #[inline]
    fn mul(&self, o: &Self) -> Self {
        // An exact zero factor gives an exact zero (no underflow term): box sides and
        // axis-parallel lines produce many of these.
        if (self.v == 0.0 && self.e == 0.0) || (o.v == 0.0 && o.e == 0.0) {
            return Filt { v: 0.0, e: 0.0 };
        }
        let v = self.v * o.v;
        Filt {
            v,
            e: self.v.abs() * o.e + o.v.abs() * self.e + self.e * o.e + v.abs() * U + ETA,
        }
    }
    #[inline]
    fn sign(&self) -> Option<Ordering> {
        let bound = self.e * SAFETY;
        if self.v > bound {
            Some(Ordering::Greater)
        } else if -self.v > bound {
            Some(Ordering::Less)
        } else if self.v == 0.0 && self.e == 0.0 {
            Some(Ordering::Equal)
        } else {
            None
        }
    }
}

impl Filt {
    /// A value known only to lie within `err` of `v`.
    pub(crate) fn approx(v: f64, err: f64) -> Filt {
        Filt { v, e: err }
    }

    /// The `f64` value.
    pub(crate) fn value(&self) -> f64 {
        self.v
    }

    /// The bound on its distance from the exact value.
    pub(crate) fn error(&self) -> f64 {
        self.e
    }

    /// An upper bound on the exact value (`+inf` if unknown).
    pub(crate) fn upper(&self) -> f64 {
        let u = self.v + self.e * SAFETY;
        if u.is_nan() {
            f64::INFINITY
        } else {
            u + u.abs() * 4.0 * U + ETA
        }
    }

    /// A lower bound on the exact value (`-inf` if unknown).
    pub(crate) fn lower(&self) -> f64 {
        let l = self.v - self.e * SAFETY;
        if l.is_nan() {
            f64::NEG_INFINITY
        } else {
            l - l.abs() * 4.0 * U - ETA
        }
    }
}

/// An exact rational value.
#[derive(Debug, Clone)]
pub(crate) struct Ex(pub(crate) BigRational);

impl Num for Ex {
    fn val(a: f64) -> Self {
        Ex(rat(a))
    }
    fn add(&self, o: &Self) -> Self {
        Ex(&self.0 + &o.0)
    }
    fn sub(&self, o: &Self) -> Self {
        Ex(&self.0 - &o.0)
    }
    fn mul(&self, o: &Self) -> Self {
        Ex(&self.0 * &o.0)
    }
    fn sign(&self) -> Option<Ordering> {
        Some(self.0.cmp(&BigRational::zero()))
    }
}

/// The exact rational value of a finite `f64` (zero for a non-finite one; callers reject
/// those first).
pub(crate) fn rat(a: f64) -> BigRational {
    BigRational::from_float(a).unwrap_or_else(|| BigRational::from_integer(BigInt::zero()))
}

/// The nearest `f64` to an exact rational (`±inf` beyond the range).
pub(crate) fn to_f64(r: &BigRational) -> f64 {
    r.to_f64().unwrap_or(if r.is_negative() {
        f64::NEG_INFINITY
    } else {
        f64::INFINITY
    })
}

/// Something whose sign is a polynomial in `f64` inputs.
pub(crate) trait SignExpr {
    /// Evaluate in the ring `N`.
    fn eval<N: Num>(&self) -> N;
}

/// The exact sign: `f64` filter first, then a double-double filter, exact rationals when
/// neither can tell.
#[inline]
pub(crate) fn sign<E: SignExpr>(e: &E) -> Ordering {
    match e.eval::<Filt>().sign() {
        Some(s) => s,
        None => sign_slow(e),
    }
}

#[inline(never)]
fn sign_slow<E: SignExpr>(e: &E) -> Ordering {
    if let Some(s) = e.eval::<Dd>().sign() {
        return s;
    }
    FALLBACKS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    e.eval::<Ex>().sign().unwrap_or(Ordering::Equal)
}

/// `hi + lo` (about 106 bits) with a bound `e >= |hi + lo - exact|`: the second filter,
/// for near-degenerate decisions (e.g. three tangents of a circle a millionth of a radian
/// apart) that plain `f64` cannot settle but that are far from exactly zero.
///
/// Products use the exact `two_prod` (fused multiply-add) and sums the exact `two_sum`;
/// what is dropped or rounded is at most `16·u²` times the operands' magnitudes (the
/// analysis gives under `10·u²`), plus `ETA` per product for underflow (sums of
/// subnormals are exact); bounds propagate as
/// in [`Filt`].
#[derive(Debug, Clone, Copy)]
pub(crate) struct Dd {
    hi: f64,
    lo: f64,
    e: f64,
}

const U2: f64 = 16.0 * U * U;

/// `a + b` as the rounded sum and its exact rounding error (Knuth's two-sum).
#[inline]
pub(super) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

impl Num for Dd {
    #[inline]
    fn val(a: f64) -> Self {
        Dd {
            hi: a,
            lo: 0.0,
            e: 0.0,
        }
    }
    #[inline]
    fn add(&self, o: &Self) -> Self {
        let (s, err) = two_sum(self.hi, o.hi);
        let t = self.lo + o.lo + err;
        let (hi, lo) = two_sum(s, t);
        Dd {
            hi,
            lo,
            e: self.e + o.e + U2 * (self.hi.abs() + o.hi.abs()),
        }
    }
    #[inline]
    fn sub(&self, o: &Self) -> Self {
        self.add(&Dd {
            hi: -o.hi,
            lo: -o.lo,
            e: o.e,
        })
    }
    #[inline]
    fn mul(&self, o: &Self) -> Self {
        let zero = |d: &Dd| d.hi == 0.0 && d.lo == 0.0 && d.e == 0.0;
        if zero(self) || zero(o) {
            return Dd::val(0.0);
        }
        let p = self.hi * o.hi;
        let err = self.hi.mul_add(o.hi, -p);
        let t = self.hi * o.lo + self.lo * o.hi + err;
        let (hi, lo) = two_sum(p, t);
        let (ma, mb) = (self.hi.abs() + self.lo.abs(), o.hi.abs() + o.lo.abs());
        Dd {
            hi,
            lo,
            e: ma * o.e + mb * self.e + self.e * o.e + U2 * ma * mb + ETA,
        }
    }
    #[inline]
    fn sign(&self) -> Option<Ordering> {
        // |lo| <= u·|hi| after two_sum, so hi carries the sign when it beats the bound.
        let bound = (self.e + self.lo.abs()) * SAFETY;
        if self.hi > bound {
            Some(Ordering::Greater)
        } else if -self.hi > bound {
            Some(Ordering::Less)
        } else if self.hi == 0.0 && self.lo == 0.0 && self.e == 0.0 {
            Some(Ordering::Equal)
        } else {
            None
        }
    }
}

/// Decisions the filter could not make (exact rational fallbacks), for tests and benchmarks.
pub(crate) static FALLBACKS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);

/// A line `a·x + b·y = c + m·M` and the closed half-plane `a·x + b·y <= c + m·M`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Line {
    pub(crate) a: f64,
    pub(crate) b: f64,
    pub(crate) c: f64,
    /// Coefficient of the symbolic `M` (0 for input half-planes).
    pub(crate) m: f64,
}

impl Line {
    /// An input half-plane.
    pub(crate) fn input(a: f64, b: f64, c: f64) -> Line {
        Line { a, b, c, m: 0.0 }
    }

    /// The four sides of the symbolic box: `x <= M`, `-x <= M`, `y <= M`, `-y <= M`.
    pub(crate) fn bbox() -> [Line; 4] {
        [
            Line {
                a: 1.0,
                b: 0.0,
                c: 0.0,
                m: 1.0,
            },
            Line {
                a: -1.0,
                b: 0.0,
                c: 0.0,
                m: 1.0,
            },
            Line {
                a: 0.0,
                b: 1.0,
                c: 0.0,
                m: 1.0,
            },
            Line {
                a: 0.0,
                b: -1.0,
                c: 0.0,
                m: 1.0,
            },
        ]
    }

    /// True for a side of the symbolic box.
    pub(crate) fn is_box(&self) -> bool {
        self.m != 0.0
    }
}

/// `x·y - z·w`.
#[inline]
fn det2<N: Num>(x: f64, y: f64, z: f64, w: f64) -> N {
    N::val(x).mul(&N::val(y)).sub(&N::val(z).mul(&N::val(w)))
}

/// `a_k·X + b_k·Y - c_k·D` for the meeting point `(X/D, Y/D)` of lines `i`, `j`, with the
/// constant column `c` (`use_m = false`) or the `M` column (`use_m = true`).
struct SideExpr<'a> {
    i: &'a Line,
    j: &'a Line,
    k: &'a Line,
    use_m: bool,
}

impl SignExpr for SideExpr<'_> {
    #[inline]
    fn eval<N: Num>(&self) -> N {
        let (i, j, k) = (self.i, self.j, self.k);
        let (ci, cj, ck) = if self.use_m {
            (i.m, j.m, k.m)
        } else {
            (i.c, j.c, k.c)
        };
        // X = ci·bj - cj·bi, Y = ai·cj - aj·ci, D = ai·bj - aj·bi.
        let x: N = det2(ci, j.b, cj, i.b);
        let y: N = det2(i.a, cj, j.a, ci);
        let d: N = det2(i.a, j.b, j.a, i.b);
        N::val(k.a)
            .mul(&x)
            .add(&N::val(k.b).mul(&y))
            .sub(&N::val(ck).mul(&d))
    }
}

/// `ai·bj - aj·bi`: the sign of the cross product of the two normals.
struct CrossExpr(f64, f64, f64, f64);

impl SignExpr for CrossExpr {
    #[inline]
    fn eval<N: Num>(&self) -> N {
        det2(self.0, self.3, self.2, self.1)
    }
}

/// The exact sign of `ai·bj - aj·bi` (zero: parallel normals).
#[inline]
pub(crate) fn cross_sign(i: &Line, j: &Line) -> Ordering {
    sign(&CrossExpr(i.a, i.b, j.a, j.b))
}

/// The exact sign of `x1·y2 - x2·y1` for arbitrary finite values.
#[inline]
pub(crate) fn cross2_sign(x1: f64, y1: f64, x2: f64, y2: f64) -> Ordering {
    sign(&CrossExpr(x1, y1, x2, y2))
}

/// Where the meeting point of lines `i` and `j` (not parallel) lies relative to the
/// half-plane `k`: `Less` strictly inside, `Equal` on its line, `Greater` strictly outside.
#[inline]
pub(crate) fn side(i: &Line, j: &Line, k: &Line) -> Ordering {
    let d = cross_sign(i, j);
    let s = if i.m == 0.0 && j.m == 0.0 && k.m == 0.0 {
        sign(&SideExpr {
            i,
            j,
            k,
            use_m: false,
        })
    } else {
        match sign(&SideExpr {
            i,
            j,
            k,
            use_m: true,
        }) {
            Ordering::Equal => sign(&SideExpr {
                i,
                j,
                k,
                use_m: false,
            }),
            s => s,
        }
    };
    match d {
        Ordering::Greater => s,
        Ordering::Less => s.reverse(),
        // Parallel lines have no meeting point; callers never ask. Answer "on".
        Ordering::Equal => Ordering::Equal,
    }
}

/// `Y_ij·D_kl - Y_kl·D_ij` for the meeting points `(·, Y/D)` of lines `i, j` and `k, l`,
/// with the constant column (`use_m = false`) or the `M` column (`use_m = true`) in `Y`.
struct MeetYExpr<'a> {
    i: &'a Line,
    j: &'a Line,
    k: &'a Line,
    l: &'a Line,
    use_m: bool,
}

impl SignExpr for MeetYExpr<'_> {
    #[inline]
    fn eval<N: Num>(&self) -> N {
        let (i, j, k, l) = (self.i, self.j, self.k, self.l);
        let col = |p: &Line, q: &Line| -> N {
            if self.use_m {
                det2(p.a, q.m, q.a, p.m)
            } else {
                det2(p.a, q.c, q.a, p.c)
            }
        };
        let d_ij: N = det2(i.a, j.b, j.a, i.b);
        let d_kl: N = det2(k.a, l.b, l.a, k.b);
        col(i, j).mul(&d_kl).sub(&col(k, l).mul(&d_ij))
    }
}

/// Compare the heights (y) of the meeting point of lines `i`, `j` and that of `k`, `l`
/// (neither pair parallel), exactly; box sides count with their symbolic `M`.
#[inline]
pub(crate) fn cmp_meet_y(i: &Line, j: &Line, k: &Line, l: &Line) -> Ordering {
    let e = |use_m| sign(&MeetYExpr { i, j, k, l, use_m });
    let s = if i.m == 0.0 && j.m == 0.0 && k.m == 0.0 && l.m == 0.0 {
        e(false)
    } else {
        match e(true) {
            Ordering::Equal => e(false),
            s => s,
        }
    };
    // y_ij - y_kl = (Y_ij·D_kl - Y_kl·D_ij) / (D_ij·D_kl).
    match (cross_sign(i, j), cross_sign(k, l)) {
        (Ordering::Equal, _) | (_, Ordering::Equal) => Ordering::Equal,
        (a, b) if a == b => s,
        _ => s.reverse(),
    }
}

/// `a·x + b·y - c` at an input point.
pub(crate) struct AffineExpr {
    pub(crate) a: f64,
    pub(crate) b: f64,
    pub(crate) c: f64,
    pub(crate) x: f64,
    pub(crate) y: f64,
}

impl SignExpr for AffineExpr {
    fn eval<N: Num>(&self) -> N {
        N::val(self.a)
            .mul(&N::val(self.x))
            .add(&N::val(self.b).mul(&N::val(self.y)))
            .sub(&N::val(self.c))
    }
}

/// `(ni·nj)·ci - |ni|²·cj` (one column of `c` or `m`).
struct ParallelExpr<'a> {
    i: &'a Line,
    j: &'a Line,
    use_m: bool,
}

impl SignExpr for ParallelExpr<'_> {
    fn eval<N: Num>(&self) -> N {
        let (i, j) = (self.i, self.j);
        let (ci, cj) = if self.use_m { (i.m, j.m) } else { (i.c, j.c) };
        let dot = N::val(i.a)
            .mul(&N::val(j.a))
            .add(&N::val(i.b).mul(&N::val(j.b)));
        let nn = N::val(i.a)
            .mul(&N::val(i.a))
            .add(&N::val(i.b).mul(&N::val(i.b)));
        dot.mul(&N::val(ci)).sub(&nn.mul(&N::val(cj)))
    }
}

/// For parallel lines `i` and `j` (normals parallel, `i` with a non-zero normal): where the
/// line `i` lies relative to the half-plane `j` (`Less` strictly inside, `Equal` on its
/// line, `Greater` strictly outside).
pub(crate) fn parallel_side(i: &Line, j: &Line) -> Ordering {
    let e = |use_m| sign(&ParallelExpr { i, j, use_m });
    let s = if i.m == 0.0 && j.m == 0.0 {
        e(false)
    } else {
        match e(true) {
            Ordering::Equal => e(false),
            s => s,
        }
    };
    // With nj = λ·ni the line i satisfies `nj·p = λ·ci`, and the expression equals
    // |ni|²·(λ·ci - cj): its sign says whether line i is inside j, whatever the sign of λ.
    s
}

/// The meeting point of lines `i`, `j` (not parallel) as exact rationals
/// `(x0 + x1·M, y0 + y1·M)`: returns `((x0, y0), (x1, y1))`.
pub(crate) fn meet_exact(
    i: &Line,
    j: &Line,
) -> ((BigRational, BigRational), (BigRational, BigRational)) {
    let (ai, bi, aj, bj) = (rat(i.a), rat(i.b), rat(j.a), rat(j.b));
    let d = &ai * &bj - &aj * &bi;
    let col = |ci: f64, cj: f64| {
        let (ci, cj) = (rat(ci), rat(cj));
        if d.is_zero() {
            return (BigRational::zero(), BigRational::zero());
        }
        let x = (&ci * &bj - &cj * &bi) / &d;
        let y = (&ai * &cj - &aj * &ci) / &d;
        (x, y)
    };
    (col(i.c, j.c), col(i.m, j.m))
}

/// A finite `f64` as `m·2^e` with `|m| < 2^53` (sign in `m`).
#[inline]
fn split(v: f64) -> (i128, i32) {
    let bits = v.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i32;
    let frac = (bits & ((1u64 << 52) - 1)) as i128;
    let (m, e) = if exp == 0 {
        (frac, -1074)
    } else {
        (frac | (1i128 << 52), exp - 1075)
    };
    (if v < 0.0 { -m } else { m }, e)
}

/// `p·q - r·s` exactly as `m·2^e` in 128-bit integers, or `None` when the two products'
/// scales are too far apart to share one (then the caller uses rationals).
#[inline]
fn det2_int(p: f64, q: f64, r: f64, s: f64) -> Option<(i128, i32)> {
    let ((mp, ep), (mq, eq), (mr, er), (ms, es)) = (split(p), split(q), split(r), split(s));
    let (m1, e1) = (mp * mq, ep + eq);
    let (m2, e2) = (mr * ms, er + es);
    if m1 == 0 {
        return Some((-m2, e2));
    }
    if m2 == 0 {
        return Some((m1, e1));
    }
    // |m1|, |m2| < 2^106: a shift of up to 20 bits keeps the difference below 2^127.
    let d = e1 - e2;
    if d.abs() > 20 {
        return None;
    }
    Some(if d >= 0 {
        ((m1 << d) - m2, e2)
    } else {
        (m1 - (m2 << -d), e1)
    })
}

/// The `f64` nearest to `(xm·2^xe) / (dm·2^de)` (ties to even), or `None` if it would be
/// subnormal or overflow.
fn round_quotient(xm: i128, xe: i32, dm: i128, de: i32) -> Option<f64> {
    if dm == 0 {
        return None;
    }
    if xm == 0 {
        return Some(0.0);
    }
    let neg = (xm < 0) != (dm < 0);
    let (x, d) = (xm.unsigned_abs(), dm.unsigned_abs());
    // Long division until the quotient has at least 55 bits; `r` stays below `d < 2^127`.
    let (mut q, mut r) = (x / d, x % d);
    let mut shift = 0i32;
    while q < (1u128 << 54) {
        r <<= 1;
        q <<= 1;
        if r >= d {
            r -= d;
            q |= 1;
        }
        shift += 1;
    }
    // value = (q + r/d)·2^(xe - de - shift); round q to 53 bits.
    let extra = (128 - q.leading_zeros() as i32) - 53;
    let mut mant = q >> extra;
    let rest = q & ((1u128 << extra) - 1);
    let half = 1u128 << (extra - 1);
    if rest > half || (rest == half && (r != 0 || mant & 1 == 1)) {
        mant += 1;
    }
    let mut k = xe - de - shift + extra;
    if mant == 1u128 << 53 {
        mant >>= 1;
        k += 1;
    }
    // mant in [2^52, 2^53): the value's binary exponent is k + 52.
    if !(-1022..=1023).contains(&(k + 52)) {
        return None;
    }
    let pow = |e: i32| f64::from_bits(((e + 1023) as u64) << 52);
    // Two exact power-of-two scalings (each factor normal, the result normal).
    let (k1, k2) = (k / 2, k - k / 2);
    let v = mant as f64 * pow(k1) * pow(k2);
    Some(if neg { -v } else { v })
}

/// The meeting point of two input lines (not box sides, not parallel) rounded to the
/// nearest `f64`s, in 128-bit integer arithmetic; `None` when the scales do not fit (use
/// [`meet_exact`]).
pub(crate) fn meet_f64(i: &Line, j: &Line) -> Option<(f64, f64)> {
    if i.m != 0.0 || j.m != 0.0 {
        return None;
    }
    let (dm, de) = det2_int(i.a, j.b, j.a, i.b)?;
    let (xm, xe) = det2_int(i.c, j.b, j.c, i.b)?;
    let (ym, ye) = det2_int(i.a, j.c, j.a, i.c)?;
    Some((
        round_quotient(xm, xe, dm, de)?,
        round_quotient(ym, ye, dm, de)?,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn side_is_exact_near_degeneracy() {
        // x = 0 and y = 0 meet at the origin; the half-plane x + y <= tiny is decided exactly.
        let i = Line::input(1.0, 0.0, 0.0);
        let j = Line::input(0.0, 1.0, 0.0);
        assert_eq!(side(&i, &j, &Line::input(1.0, 1.0, 1e-300)), Ordering::Less);
        assert_eq!(
            side(&i, &j, &Line::input(1.0, 1.0, -1e-300)),
            Ordering::Greater
        );
        assert_eq!(side(&i, &j, &Line::input(1.0, 1.0, 0.0)), Ordering::Equal);
        // 0.1·x + 0.2·y = 0.3 and x = 1: y = (0.3 - 0.1)/0.2 in exact binary arithmetic.
        let a = Line::input(0.1, 0.2, 0.3);
        let b = Line::input(1.0, 0.0, 1.0);
        let ((x, y), _) = meet_exact(&a, &b);
        let k = Line::input(0.0, 1.0, to_f64(&y));
        assert_eq!(x, rat(1.0));
        // The rounded y is within half an ulp: the exact point is on one side or on it,
        // and the exact test agrees with the exact rational comparison.
        let expected = y.cmp(&rat(to_f64(&y)));
        assert_eq!(side(&a, &b, &k), expected);
    }

    #[test]
    fn integer_rounding_of_meets_matches_rationals() {
        let mut unit = crate::testing::units(7);
        let mut next = || (unit() - 0.5) * 4.0;
        let mut checked = 0;
        for t in 0..3000 {
            let scale = [1.0, 1e-3, 3e5, 1e-150, 1e150][t % 5];
            let i = Line::input(next(), next(), next() * scale);
            let j = Line::input(next(), next(), next() * scale);
            let ((x, y), _) = meet_exact(&i, &j);
            if let Some((fx, fy)) = meet_f64(&i, &j) {
                assert_eq!((fx, fy), (to_f64(&x), to_f64(&y)), "{i:?} {j:?}");
                checked += 1;
            }
        }
        assert!(checked > 1000);
        // Exact halfway cases round to even: x = 1 + 2^-53 (between 1 and its successor).
        let i = Line::input(1.0, 0.0, 1.0 + f64::EPSILON);
        let j = Line::input(0.0, 1.0, 0.0);
        let h = Line::input(2.0, 0.0, 2.0 + f64::EPSILON);
        assert_eq!(meet_f64(&i, &j), Some((1.0 + f64::EPSILON, 0.0)));
        let ((x, _), _) = meet_exact(&h, &j);
        assert_eq!(meet_f64(&h, &j).map(|p| p.0), Some(to_f64(&x)));
    }

    #[test]
    fn double_double_filter_agrees_with_rationals() {
        // Three tangents of the unit circle a tiny angle apart: the corner of the outer two
        // is outside the middle one by about δ³, far below what f64 can resolve.
        for k in 1..40 {
            let d = 1e-3 / (1u64 << k) as f64;
            let t = |a: f64| Line::input(a.cos(), a.sin(), 1.0);
            let (i, j, m) = (t(0.3), t(0.3 + 2.0 * d), t(0.3 + d));
            let e = SideExpr {
                i: &i,
                j: &j,
                k: &m,
                use_m: false,
            };
            let want = e.eval::<Ex>().sign().unwrap();
            if let Some(s) = e.eval::<Dd>().sign() {
                assert_eq!(s, want, "k = {k}");
            }
            assert_eq!(sign(&e), want);
            if k < 12 {
                assert!(e.eval::<Dd>().sign().is_some(), "k = {k}");
            }
        }
    }

    #[test]
    fn symbolic_box_is_larger_than_everything() {
        let bx = Line::bbox();
        let huge = Line::input(1.0, 0.0, 1e308);
        // The corner (M, M) is outside x <= 1e308.
        assert_eq!(side(&bx[0], &bx[2], &huge), Ordering::Greater);
        // x = 1e308 meets y = M inside the box side x <= M.
        assert_eq!(side(&huge, &bx[2], &bx[0]), Ordering::Less);
        assert_eq!(parallel_side(&huge, &bx[0]), Ordering::Less);
        assert_eq!(parallel_side(&bx[0], &huge), Ordering::Greater);
    }
}
