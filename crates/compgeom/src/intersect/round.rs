//! Correct rounding of proper crossings, fast: the nearest `f64` point to the exact
//! crossing of two segments, bit for bit what [`Crossing::approx`] returns, in about a
//! tenth of its time for the common case (dense crossings make this the hot spot of
//! segment intersection).
//!
//! One straight-line double-double evaluation with an error bound fixed in advance
//! (no error term carried along, no branches on the way), then one certificate per
//! coordinate. The work comes in pairs (the denominator and the numerator of the
//! parameter; the two coordinates), so it is written in two lanes that the compiler
//! maps onto two-wide vector instructions (SSE2, the default x86-64 target; each lane
//! does exactly the scalar operations of the analysis below); when the certificate fails (the exact value is within about 2^-100 of
//! it relative to the inputs of a midpoint between two `f64`s, or the input is out of the
//! range below) the kernel's [`Crossing::approx`] decides.
//!
//! ## Why it is exact
//!
//! With `u = 2^-53`, the crossing of `s = (a, b)` and `t = (c, d)` is
//! `x = a.x + dx·T`, `T = N/D`, with `dx = b.x - a.x`, `D = dx·ey - dy·ex`,
//! `N = wx·ey - wy·ex` (`e = d - c`, `w = c - a`). Differences of inputs are exact as
//! two `f64`s (two-sum); products of their leading parts are exact (Dekker's
//! two-product); only the cross terms and the final sums of small parts round. With
//! `M_D = |dx·ey| + |dy·ex|` (leading parts) the computed double-double `D~` is within
//! `22u²·M_D` of `D` (likewise `N~`; the code allows `32u²`).
//!
//! `T` is evaluated once, shared by both coordinates: `t_hi = fl(N.hi / D.hi)`, the
//! remainder `r ≈ N~ - t_hi·D~` (one exact two-product, error at most `13u²·|N.hi|`),
//! `t_lo = fl(r / D.hi)`. Then `|t_hi + t_lo - N~/D~| ≤ 28u²·|t_hi|` (the rounding of
//! `t_lo`, the error of `r`, and `D.lo` dropped from the divisor, each a few `u²|t_hi|`),
//! and `|N~/D~ - N/D| ≤ (e_N + |T|·e_D) / |D~|`: together `E_T`. The code uses `32u²`
//! and bounds `|T|` by `1.01·|t_hi|`, checking `E_T < 0.001·|t_hi|`: the `|T|` term of
//! `E_T` then has a factor below `0.001`, so `|T| ≤ (|t_hi + t_lo| + 0.001·|t_hi|) /
//! 0.999 < 1.01·|t_hi|` indeed.
//!
//! A coordinate is `a.x + dx·(t_hi + t_lo)`: `dx.hi·t_hi` exactly (two-product), the
//! cross terms `dx.hi·t_lo + dx.lo·t_hi` rounded (`dx.lo·t_lo`, below `6u²·Q` with
//! `Q = |dx.hi·t_hi|`, dropped), `a.x + dx.hi·t_hi` exactly (two-sum), the small parts
//! summed: within `37u²·Q + u²·|s|` of `a.x + dx·(t_hi + t_lo)` (`s` the two-sum's
//! leading part), and then `|dx|·E_T` from `T`. The code uses `48u²·Q + 2u²·|s|` and adds
//! `10^-300` for subnormal cross terms. The value is split exactly into
//! `f + fe` (two-sum); when `|fe| + E_x < h` with `h` half the smaller gap between `f`
//! and its neighbours, the exact `x` lies strictly within `h` of `f`, so `f` is the
//! nearest `f64` (no tie is possible). A `1 + 2^-40` factor covers the roundings in
//! evaluating the bounds themselves.
//!
//! The range condition (every input coordinate `0` or of magnitude in
//! `[2^-200, 2^200]`, `|t_hi| ≥ 2^-800`, the result of magnitude at least `2^-300`)
//! keeps every product and every rounding error that matters a normal `f64`: inputs are
//! then multiples of `2^-252`, so every intermediate value is zero or above `2^-1000`
//! and below `2^700`, except cross terms of the coordinate, which the `10^-300` covers.

use crate::kernel::{Crossing, Point2};

/// `2^-53`.
const U: f64 = 1.0 / 9_007_199_254_740_992.0;
/// The bound on `den`'s (and `num`'s) error, as a multiple of its magnitude.
const ERR_DEN: f64 = 32.0 * U * U;
/// `1 + 2^-40`: covers the roundings in evaluating the certificate itself.
const SAFE: f64 = 1.0 + 1.0 / 1_099_511_627_776.0;
/// Input magnitudes accepted by the fast path.
const LO: f64 = 6.223_015_277_861_142e-61; // 2^-200
const HI: f64 = 1.606_938_044_258_990_3e60; // 2^200
/// The smallest result magnitude the fast path certifies.
const TINY: f64 = 4.909_093_465_297_727e-91; // 2^-300

/// Veltkamp's splitting constant `2^27 + 1`.
#[cfg(not(target_feature = "fma"))]
const SPLITTER: f64 = 134_217_729.0;

#[cfg(not(target_feature = "fma"))]
#[inline(always)]
fn split(a: f64) -> (f64, f64) {
    let c = SPLITTER * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

/// `a·b = p + e` exactly, by one fused multiply-add where the build targets a processor
/// that has it (`-C target-cpu=native` on most x86-64 and all aarch64); the same value
/// as Dekker's product below (both are exact).
#[cfg(target_feature = "fma")]
#[inline(always)]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// `a·b = p + e` exactly (Dekker; no FMA needed: without the target feature,
/// `mul_add` is a slow library call).
#[cfg(not(target_feature = "fma"))]
#[inline(always)]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

/// `a + b = s + e` exactly.
#[inline(always)]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// Two lanes: the same operation on both (the `x` and `y` coordinates, or a
/// denominator and a numerator). Written as arrays so that the compiler can use one
/// two-wide vector instruction per operation; each lane performs exactly the operations
/// of the scalar analysis in the module docs.
type F2 = [f64; 2];

#[inline(always)]
fn add(a: F2, b: F2) -> F2 {
    [a[0] + b[0], a[1] + b[1]]
}

#[inline(always)]
fn sub(a: F2, b: F2) -> F2 {
    [a[0] - b[0], a[1] - b[1]]
}

#[inline(always)]
fn mul(a: F2, b: F2) -> F2 {
    [a[0] * b[0], a[1] * b[1]]
}

#[inline(always)]
fn abs2(a: F2) -> F2 {
    [a[0].abs(), a[1].abs()]
}

/// [`two_sum`] in both lanes.
#[inline(always)]
fn two_sum2(a: F2, b: F2) -> (F2, F2) {
    let s = add(a, b);
    let bb = sub(s, a);
    (s, add(sub(a, sub(s, bb)), sub(b, bb)))
}

/// [`two_prod`] in both lanes.
#[cfg(target_feature = "fma")]
#[inline(always)]
fn two_prod2(a: F2, b: F2) -> (F2, F2) {
    let p = mul(a, b);
    (p, [a[0].mul_add(b[0], -p[0]), a[1].mul_add(b[1], -p[1])])
}

/// [`two_prod`] in both lanes.
#[cfg(not(target_feature = "fma"))]
#[inline(always)]
fn two_prod2(a: F2, b: F2) -> (F2, F2) {
    let p = mul(a, b);
    let split2 = |v: F2| {
        let c = mul([SPLITTER; 2], v);
        let hi = sub(c, sub(c, v));
        (hi, sub(v, hi))
    };
    let (ah, al) = split2(a);
    let (bh, bl) = split2(b);
    let e = add(
        add(add(sub(mul(ah, bh), p), mul(ah, bl)), mul(al, bh)),
        mul(al, bl),
    );
    (p, e)
}

/// Double-double values `hi + lo`, one per lane.
#[derive(Clone, Copy)]
struct Dd2 {
    hi: F2,
    lo: F2,
}

/// `a - b` exactly, per lane.
#[inline(always)]
fn diff2(a: F2, b: F2) -> Dd2 {
    let (hi, lo) = two_sum2(a, [-b[0], -b[1]]);
    Dd2 { hi, lo }
}

/// `x·y - z·w` per lane, normalised; error at most `22u²·(|x.hi·y.hi| + |z.hi·w.hi|)`
/// in each lane (the scalar operations of the module docs, lane by lane).
#[inline(always)]
fn cross2(x: Dd2, y: Dd2, z: Dd2, w: Dd2) -> Dd2 {
    let (p1, e1) = two_prod2(x.hi, y.hi);
    let (p2, e2) = two_prod2(z.hi, w.hi);
    let c1 = add(mul(x.hi, y.lo), mul(x.lo, y.hi));
    let c2 = add(mul(z.hi, w.lo), mul(z.lo, w.hi));
    let (s, r) = two_sum2(p1, [-p2[0], -p2[1]]);
    let lo = add(add(r, sub(e1, e2)), sub(c1, c2));
    let (hi, lo) = two_sum2(s, lo);
    Dd2 { hi, lo }
}

/// Half the smaller gap between `f` and its neighbours (`f` normal, `|f| > 2^-900`;
/// 0 or less for smaller `f`).
#[inline(always)]
fn half_gap(f: f64) -> f64 {
    let bits = f.abs().to_bits();
    let exp = bits >> 52;
    // ulp(f) = 2^(exp - 1075); half of it has exponent field exp - 53, and a quarter
    // (half the gap below a power of two) exp - 54.
    let shift = if bits & ((1 << 52) - 1) == 0 { 54 } else { 53 };
    // (Saturating: zero, subnormal or tiny `f` give 0, which certifies nothing.)
    f64::from_bits(exp.saturating_sub(shift) << 52)
}

fn in_range(v: f64) -> bool {
    v == 0.0 || (v.abs() >= LO && v.abs() <= HI)
}

/// `2^-800`: the smallest `|t_hi|` the fast path certifies.
const T_MIN: f64 = 1.499_696_813_895_631_3e-241;

/// The parameter `T = N/D` of the crossing along `s` as `t_hi + t_lo`, with a bound on
/// `|T - (t_hi + t_lo)|` (see the module docs), or `None` when uncertain.
#[inline(always)]
fn parameter(num: (f64, f64), den: (f64, f64), m_num: f64, m_den: f64) -> Option<(f64, f64, f64)> {
    let ((num_hi, num_lo), (den_hi, den_lo)) = (num, den);
    let t_hi = num_hi / den_hi;
    let (p, pe) = two_prod(t_hi, den_hi);
    let (s1, s1l) = two_sum(num_hi, -p);
    let r = s1 + ((s1l + num_lo) - (pe + t_hi * den_lo));
    let t_lo = r / den_hi;
    let den_low = den_hi.abs() - den_lo.abs();
    let e_t = (32.0 * U * U * t_hi.abs() + ERR_DEN * (m_num + 1.01 * t_hi.abs() * m_den) / den_low)
        * SAFE;
    // (NaN fails the comparisons too.)
    let ok = t_hi.abs() >= T_MIN && t_hi.abs() <= HI && e_t < 0.001 * t_hi.abs();
    ok.then_some((t_hi, t_lo, e_t))
}

/// The nearest `f64` to `a + d·T` for `T = t_hi + t_lo` within `e_t`, in both lanes
/// (the two coordinates), or `None` when a lane's certificate does not hold.
#[inline(always)]
fn coordinates(a: F2, d: Dd2, t_hi: f64, t_lo: f64, e_t: f64) -> Option<F2> {
    let (p, pe) = two_prod2(d.hi, [t_hi; 2]);
    let c = add(mul(d.hi, [t_lo; 2]), mul(d.lo, [t_hi; 2]));
    let (s, sl) = two_sum2(a, p);
    let lo = add(sl, add(pe, c));
    let (f, fe) = two_sum2(s, lo);
    let q = abs2(mul(d.hi, [t_hi; 2]));
    let (ad, as_) = (abs2(d.hi), abs2(s));
    let mut ok = true;
    for k in 0..2 {
        let bound =
            (ad[k] * (1.0 + 2.0 * U) * e_t + 48.0 * U * U * q[k] + 2.0 * U * U * as_[k] + 1e-300)
                * SAFE;
        // (Non-short-circuit `&`: both lanes are checked the same way.)
        ok &= (f[k].abs() >= TINY)
            & (f[k].abs() <= HI)
            & ((fe[k].abs() + bound) * SAFE < half_gap(f[k]));
    }
    ok.then_some(f)
}

/// The certified fast path: `None` when [`Crossing::approx`] must decide.
fn fast(c: &Crossing) -> Option<Point2> {
    let (s, t) = (c.s, c.t);
    let coords = [s.a.x, s.a.y, s.b.x, s.b.y, t.a.x, t.a.y, t.b.x, t.b.y];
    if !coords.iter().all(|&v| in_range(v)) {
        return None;
    }
    // Lanes (x, y): d = s.b - s.a, e = t.b - t.a, w = t.a - s.a, each exact.
    let d = diff2([s.b.x, s.b.y], [s.a.x, s.a.y]);
    let e = diff2([t.b.x, t.b.y], [t.a.x, t.a.y]);
    let w = diff2([t.a.x, t.a.y], [s.a.x, s.a.y]);
    // Lanes (den, num): den = dx·ey - dy·ex, num = wx·ey - wy·ex.
    let lane = |a: &Dd2, b: &Dd2, k: usize, l: usize| Dd2 {
        hi: [a.hi[k], b.hi[l]],
        lo: [a.lo[k], b.lo[l]],
    };
    let (x, z) = (lane(&d, &w, 0, 0), lane(&d, &w, 1, 1));
    let (y, v) = (lane(&e, &e, 1, 1), lane(&e, &e, 0, 0));
    let dn = cross2(x, y, z, v);
    let m = add(abs2(mul(x.hi, y.hi)), abs2(mul(z.hi, v.hi)));
    let (m_den, m_num) = (m[0], m[1]);
    let (den, num) = ((dn.hi[0], dn.lo[0]), (dn.hi[1], dn.lo[1]));
    // A crossing of segments that meet has a nonzero denominator well above its error
    // (NaN, from overflow, fails the test too).
    let den_clear = den.0.abs() > 4.0 * ERR_DEN * m_den;
    if !den_clear {
        return None;
    }
    let (t_hi, t_lo, e_t) = parameter(num, den, m_num, m_den)?;
    let [x, y] = coordinates([s.a.x, s.a.y], d, t_hi, t_lo, e_t)?;
    Some(Point2::new(x, y))
}

/// The bits of the fixed-point window: every coordinate below `2^FIXED_BITS` units.
const FIXED_BITS: i32 = 61;
/// `2^125`: the largest residual magnitude the fixed-point path lets through.
const WRAP_LIMIT: f64 = 4.253_529_586_511_730_8e37;
/// `2^62`.
const TWO_62: f64 = 4.611_686_018_427_387_9e18;
/// `2^63`.
const TWO_63: f64 = 9.223_372_036_854_775_8e18;
/// `2^-1021`: twice the smallest normal `f64`.
const NORMAL_MIN2: f64 = 4.450_147_717_014_402_8e-308;

/// `2^k`, for `-1022 <= k <= 1023`.
#[inline(always)]
fn pow2(k: i32) -> f64 {
    f64::from_bits(((k + 1023) as u64) << 52)
}

/// `v` as an `f64` within relative error `2u + u²` (`|v| < 2^126`): the two halves
/// convert exactly-rounded and add without cancellation (both are non-negative).
#[inline(always)]
fn i128_to_f64(v: i128) -> f64 {
    let a = v.unsigned_abs();
    let hi = ((a >> 63) as i64) as f64;
    let lo = ((a as u64) & (u64::MAX >> 1)) as i64 as f64;
    let m = hi * TWO_63 + lo;
    if v < 0 {
        -m
    } else {
        m
    }
}

/// The fixed-point path: when the eight coordinates are integers in a common unit
/// `q = 2^k` below `2^61` units (nearly all input: any coordinates within a window of 61
/// bits), the denominator `D` and numerator `N` of the parameter are exact `i128`
/// products, and so is the residual `R = 2^σ·(X - f·D)` of a plain-`f64` estimate `f`
/// of the coordinate `x = X / D` (units, `X = a·D + d·N`, `σ` making `2^σ·f` an
/// integer): `R` is a few ulps of `f` times `D`, so although `X` has some 190 bits,
/// `R` fits in 125 and is computed exactly in wrapping 128-bit arithmetic (checked in
/// advance by a bound on `|x - f|`). One correction `f + R/(2^σ·D)`, evaluated in
/// `f64` (relative error at most `5u` of the tiny correction), is then the nearest
/// `f64` unless `x` lies within about `2^-50` ulp of a midpoint, which the certificate
/// detects. `None` when a condition fails (the double-double path then decides).
///
/// The estimate: `D~, N~` within `2u + u²` relative (`i128_to_f64`), `t = fl(N~/D~)`
/// within `5.001u·|T|`, `p = fl(fl(d)·t)` within `7.01u·|d·T|`, `f = fl(a + p)`: so
/// `|x - f| ≤ u·|f| + 7.02u·|p|`; the code bounds `|R| ≤ |D~|·2^σ·u·(|f| + 8|p|)·1.01`
/// below `2^125` (the true `|R| < 2^127`, so the wrapping result is exact). The
/// correction `c = fl(R~ / (D~·2^σ))` is within `5.002u·|c|` of `x - f`; with
/// `f + c = g + e` exactly (two-sum), `|x - g| ≤ |e| + 6u·|c|`, and when that is below
/// half the smaller gap around `g`, `g` is the nearest `f64` to `x` in units; scaled by
/// `q` it is the answer (rounding commutes with the scaling while the result is normal,
/// which the range check on the result ensures). Every `f64` operation above is on
/// normal or zero values: integers up to `2^125`, quotients of them, `σ ≤ 100`.
fn fixed(c: &Crossing) -> Option<Point2> {
    let (s, t) = (c.s, c.t);
    let v = [s.a.x, s.a.y, s.b.x, s.b.y, t.a.x, t.a.y, t.b.x, t.b.y];
    let m = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    // The exponent of the largest magnitude (m ≥ 0; 0 gives -1023, ±inf 1024; NaN is
    // ignored by `max` but fails the integer test below).
    let e_m = ((m.to_bits() >> 52) as i32) - 1023;
    if !(-960..=960).contains(&e_m) {
        return None;
    }
    // Units `q = 2^(e_m + 1 - 61)`: every |v| / q < 2^61.
    let inv = pow2(FIXED_BITS - 1 - e_m);
    let q = pow2(e_m + 1 - FIXED_BITS);
    let mut y = [0.0f64; 8];
    let mut n = [0i64; 8];
    let mut ok = true;
    for k in 0..8 {
        y[k] = v[k] * inv;
        n[k] = y[k] as i64;
        // An integer value is exact unless it underflowed to zero.
        ok &= (n[k] as f64 == y[k]) & ((y[k] != 0.0) | (v[k] == 0.0));
    }
    // The coarsest common unit: drop the trailing zero bits all eight share (keeps the
    // integers, `D` and the residuals small; exact shifts and power-of-two scalings).
    let zeros = n.iter().fold(0i64, |acc, &k| acc | k).trailing_zeros();
    if !ok || zeros >= 64 {
        return None;
    }
    let (q, coarse) = (q * pow2(zeros as i32), pow2(-(zeros as i32)));
    for k in 0..8 {
        n[k] >>= zeros;
        y[k] *= coarse;
    }
    // Exact differences (below 2^62) and 2x2 determinants (below 2^125).
    let (dx, dy) = (n[2] - n[0], n[3] - n[1]);
    let (ex, ey) = (n[6] - n[4], n[7] - n[5]);
    let (wx, wy) = (n[4] - n[0], n[5] - n[1]);
    let mul = |a: i64, b: i64| i128::from(a) * i128::from(b);
    let den = mul(dx, ey) - mul(dy, ex);
    let num = mul(wx, ey) - mul(wy, ex);
    if den == 0 {
        return None;
    }
    let den_f = i128_to_f64(den);
    let t_est = i128_to_f64(num) / den_f;
    let a = [y[0], y[1]];
    let d = [y[2] - y[0], y[3] - y[1]];
    let (ai, di) = ([n[0], n[1]], [dx, dy]);
    let mut out = [0.0f64; 2];
    for k in 0..2 {
        let p = d[k] * t_est;
        let f = a[k] + p;
        // σ = max(0, 52 - exponent of f): 2^σ·f is an integer below 2^62.
        let e_f = ((f.to_bits() >> 52) & 0x7ff) as i32 - 1023;
        let sigma = (52 - e_f).max(0);
        if sigma > 100 || f.abs() >= TWO_62 {
            return None;
        }
        let sc = pow2(sigma);
        // (NaN fails too.)
        let wrap = den_f.abs() * sc * (f.abs() + 8.0 * p.abs()) * (1.01 * U);
        if !(wrap < WRAP_LIMIT) {
            return None;
        }
        let big_f = i128::from((f * sc) as i64);
        let x_num = i128::from(ai[k])
            .wrapping_mul(den)
            .wrapping_add(i128::from(di[k]).wrapping_mul(num));
        let r = x_num
            .wrapping_shl(sigma as u32)
            .wrapping_sub(big_f.wrapping_mul(den));
        let corr = i128_to_f64(r) / (den_f * sc);
        let (g, e) = two_sum(f, corr);
        let bound = (e.abs() + 6.0 * U * corr.abs()) * SAFE;
        let x = g * q;
        // (Non-finite or tiny results fail the range test.)
        if !(bound < half_gap(g) && x.abs() >= NORMAL_MIN2 && x.abs() <= f64::MAX) {
            return None;
        }
        out[k] = x;
    }
    Some(Point2::new(out[0], out[1]))
}

/// The nearest `f64` point to the exact crossing: equal to [`Crossing::approx`], faster.
#[inline]
pub(crate) fn round_crossing(c: &Crossing) -> Point2 {
    fixed(c)
        .or_else(|| fast(c))
        .unwrap_or_else(|| c.approx())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Segment2;

    fn crossings(mut coord: impl FnMut() -> f64, n: usize) -> Vec<Crossing> {
        let mut out = Vec::new();
        while out.len() < n {
            let mut p = || Point2::new(coord(), coord());
            let (s, t) = (Segment2::new(p(), p()), Segment2::new(p(), p()));
            if let crate::kernel::SegmentIntersection::Crossing(c) =
                crate::kernel::segment_intersection(s, t)
            {
                out.push(c);
            }
        }
        out
    }

    fn lcg(seed: u64) -> impl FnMut() -> u64 {
        let mut state = seed;
        move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            state >> 11
        }
    }

    fn bits(p: Point2) -> (u64, u64) {
        (p.x.to_bits(), p.y.to_bits())
    }

    /// Each path that answers (the fixed-point path, the double-double path, and the
    /// combination) is bit-equal to the kernel's exact rounding; returns how many
    /// crossings the double-double and the fixed-point paths certified.
    fn check_paths(cs: &[Crossing]) -> (usize, usize) {
        let (mut fast_hits, mut fixed_hits) = (0, 0);
        for c in cs {
            let want = bits(c.approx());
            assert_eq!(bits(round_crossing(c)), want, "{c:?}");
            if let Some(p) = fast(c) {
                assert_eq!(bits(p), want, "double-double: {c:?}");
                fast_hits += 1;
            }
            if let Some(p) = fixed(c) {
                assert_eq!(bits(p), want, "fixed point: {c:?}");
                fixed_hits += 1;
            }
        }
        (fast_hits, fixed_hits)
    }

    fn check(cs: &[Crossing]) -> usize {
        check_paths(cs).0
    }

    #[test]
    fn bit_equal_to_the_kernel_on_random_crossings() {
        let mut r = lcg(7);
        let unit = move || (r() as f64) / (1u64 << 53) as f64;
        let cs = crossings(unit, 20_000);
        // Nearly every random crossing is certified by each fast path.
        let (fast_hits, fixed_hits) = check_paths(&cs);
        assert!(fast_hits > 19_900 && fixed_hits > 19_900, "{fast_hits} {fixed_hits}");
    }

    #[test]
    fn bit_equal_on_wide_magnitudes_and_grids() {
        let mut r = lcg(11);
        let wide = move || {
            let v = r();
            let m = (v % 1000) as f64 / 7.0;
            let e = ((v >> 20) % 120) as i32 - 60;
            let sign = if v & (1 << 40) == 0 { 1.0 } else { -1.0 };
            sign * m * 2f64.powi(e)
        };
        check(&crossings(wide, 5000));
        let mut r = lcg(13);
        let grid = move || (r() % 9) as f64;
        check(&crossings(grid, 5000));
        let mut r = lcg(17);
        // Huge offsets with tiny extents: heavy cancellation.
        let offset = move || 1e15 + (r() % 1000) as f64 * 0.001;
        check(&crossings(offset, 5000));
        let mut r = lcg(19);
        let extreme = move || {
            let v = r();
            [1e-300, 1e300, 3.0, -2.5e-250, 7e250][(v % 5) as usize]
                * (1.0 + (v >> 8) as f64 * 1e-40)
        };
        check(&crossings(extreme, 500));
    }

    #[test]
    fn bit_equal_on_long_and_nearly_parallel_segments() {
        // Segments across the unit square (the benchmark's dense case), crossings near
        // the ends (T close to 0 or 1), and nearly parallel pairs (small denominators).
        let mut r = lcg(23);
        let mut unit = move || (r() as f64) / (1u64 << 53) as f64;
        let mut cs = Vec::new();
        while cs.len() < 20_000 {
            let (a, b, c, d) = (unit(), unit(), unit(), unit());
            let k = cs.len() % 3;
            let (c, d) = match k {
                0 => (c, d),
                1 => (a + (c - 0.5) * 1e-9, b + (d - 0.5) * 1e-9),
                _ => (a + 1e-12, b - 1e-12 * c),
            };
            let s = Segment2::new(Point2::new(0.0, a), Point2::new(1.0, b));
            let t = Segment2::new(Point2::new(0.0, c), Point2::new(1.0, d));
            if let crate::kernel::SegmentIntersection::Crossing(x) =
                crate::kernel::segment_intersection(s, t)
            {
                cs.push(x);
            }
        }
        assert!(check(&cs) > 15_000);
    }

    /// A coordinate: a small integer, nudged by a few ulps, scaled by `2^scale`.
    fn nudged(v: i32, ulps: i64, scale: i32) -> f64 {
        let base = f64::from(v) * 2f64.powi(scale);
        if base == 0.0 {
            return base;
        }
        f64::from_bits((base.to_bits() as i64 + ulps) as u64)
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(2000))]
        /// Bit-equal to the kernel's exact rounding on crossings of grid segments nudged
        /// by ulps (near-ties, near-parallel pairs, crossings near endpoints) at scales
        /// from about 1e-300 to 1e300 (both segments at one scale, or at two).
        #[test]
        fn bit_equal_on_nudged_grids_at_every_scale(
            v in proptest::collection::vec(-8i32..=8, 8),
            u in proptest::collection::vec(-3i64..=3, 8),
            scale in -1000i32..=1000,
            other in -1000i32..=1000,
            same in proptest::bool::ANY,
        ) {
            let t_scale = if same { scale } else { other };
            let c = |k: usize, sc: i32| nudged(v[k], u[k], sc);
            let s = Segment2::new(Point2::new(c(0, scale), c(1, scale)), Point2::new(c(2, scale), c(3, scale)));
            let t = Segment2::new(Point2::new(c(4, t_scale), c(5, t_scale)), Point2::new(c(6, t_scale), c(7, t_scale)));
            if let crate::kernel::SegmentIntersection::Crossing(x) =
                crate::kernel::segment_intersection(s, t)
            {
                let want = bits(x.approx());
                proptest::prop_assert_eq!(bits(round_crossing(&x)), want, "{:?}", x);
                if let Some(p) = fixed(&x) {
                    proptest::prop_assert_eq!(bits(p), want, "fixed point: {:?}", x);
                }
                if let Some(p) = fast(&x) {
                    proptest::prop_assert_eq!(bits(p), want, "double-double: {:?}", x);
                }
            }
        }
    }

    #[test]
    fn ties_and_near_ties_fall_back() {
        // x = 1 + 2^-53: exactly the midpoint between 1 and the next f64 (a tie to even).
        let e = 2f64.powi(-52);
        let s = Segment2::new(Point2::new(1.0, -1.0), Point2::new(1.0 + e, 1.0));
        let t = Segment2::new(Point2::new(0.0, 0.0), Point2::new(2.0, 0.0));
        let c = Crossing { s, t };
        assert!(fast(&c).is_none());
        assert_eq!(round_crossing(&c), c.approx());
    }
}
