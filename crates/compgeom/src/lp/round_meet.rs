//! The meeting point of two constraint lines rounded to the nearest `f64`, fast: a
//! double-double quotient with a rigorous error bound, accepted only when the bound proves
//! which `f64` is nearest; otherwise the exact integer/rational rounding of `exact`.
//!
//! For lines `i`, `j` the point is `(X/D, Y/D)` with `X = ci·bj - cj·bi`,
//! `Y = ai·cj - aj·ci`, `D = ai·bj - aj·bi`. Each 2×2 minor is the sum of four `f64`s
//! exactly (two products and their fused-multiply-add remainders, exact while no product
//! comes near underflow), summed to a pair `hi + lo` within `4u²·(|p| + |q|)`. The quotient
//! `q1 + q2` (`q1 = hi_X / hi_D`, `q2` the correction from the exactly computed remainder)
//! is within a bound `E` of `X/D` (derivation in [`quotient`]); with `h + l` its normalized
//! form, `h` is the nearest `f64` exactly when `[h + l - E, h + l + E]` lies strictly
//! between the midpoints from `h` to its two neighbours. The tests compare every answer with
//! the rational rounding, also at exact midpoints (where the fast path must decline).

use super::exact::{meet_exact, meet_f64, to_f64, two_sum, Line, U};

/// Magnitudes of every product and quotient on the fast path: inside `[2^-900, 2^900]`.
const LO: f64 = 1.178_389_470_208_022_3e-271;
const HI: f64 = 8.486_248_724_898_15e270;

/// `a·b - p` exactly, where `p = fl(a·b)` is normal: a fused multiply-add where the target
/// has one, else Dekker's splitting (no library call), which is exact when both factors are
/// zero or inside `[2^-450, 2^450]` (`None` outside).
#[inline]
pub(super) fn prod_err(a: f64, b: f64, p: f64) -> Option<f64> {
    if cfg!(target_feature = "fma") {
        return Some(a.mul_add(b, -p));
    }
    let (lo, hi) = (
        f64::from_bits((1023 - 450) << 52),
        f64::from_bits((1023 + 450) << 52),
    );
    let ok = |v: f64| v == 0.0 || (v.abs() > lo && v.abs() < hi);
    if !ok(a) || !ok(b) {
        return None;
    }
    // 2^27 + 1 splits a 53-bit significand into two halves of at most 26 bits.
    let split = |v: f64| {
        let c = 134_217_729.0 * v;
        let h = c - (c - v);
        (h, v - h)
    };
    let ((ah, al), (bh, bl)) = (split(a), split(b));
    Some(((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

/// In `[2^-900, 2^900]` in magnitude (or zero when `zero_ok`).
#[inline]
fn fine(v: f64, zero_ok: bool) -> bool {
    let a = v.abs();
    (a > LO && a < HI) || (zero_ok && a == 0.0)
}

/// `x·y - z·w` as `hi + lo` and a bound on `|hi + lo - exact|`, or `None` near
/// underflow/overflow. `(0, 0, 0)` means exactly zero.
#[inline]
pub(super) fn minor(x: f64, y: f64, z: f64, w: f64) -> Option<(f64, f64, f64)> {
    let (p, q) = (x * y, z * w);
    if !fine(p, true) || !fine(q, true) {
        return None;
    }
    let (pe, qe) = (prod_err(x, y, p)?, prod_err(z, w, q)?);
    let (s, se) = two_sum(p, -q);
    let t = se + (pe - qe);
    let (hi, lo) = two_sum(s, t);
    Some((hi, lo, 4.0 * U * U * (p.abs() + q.abs())))
}

/// The `f64` nearest `(xh + xl ± ex) / (dh + dl ± ed)` when the bounds prove it.
///
/// `q1 = fl(xh / dh)`; `q1·dh = m + me` exactly (fma), and `xh - m` is exact (Sterbenz:
/// `m` is within a few ulps of `xh`). The remainder `r = xh + xl - q1·(dh + dl)` is
/// computed with at most four roundings, each at most `u` times the sum `S` of the absolute
/// values of its terms: `|r̂ - r| <= 4u·S`. Then `X̂/D̂ = q1 + r/D̂` exactly, and
/// `|r/D̂ - fl(r̂/dh)| <= (|r - r̂| + 3u·|r̂|)/|dh| + u·|q2|` (using `|dl| <= u·|dh|`), while
/// `|X/D - X̂/D̂| <= (ex + |X̂/D̂|·ed) / (|D̂| - ed)`.
#[inline]
fn quotient(xh: f64, xl: f64, ex: f64, dh: f64, dl: f64, ed: f64) -> Option<f64> {
    if xh == 0.0 && ex == 0.0 {
        return Some(0.0);
    }
    if !fine(xh, false) || !fine(dh, false) {
        return None;
    }
    let q1 = xh / dh;
    if !fine(q1, false) {
        return None;
    }
    let m = q1 * dh;
    let me = prod_err(q1, dh, m)?;
    let a = xh - m;
    let b = q1 * dl;
    let r = ((a - me) + xl) - b;
    let s = a.abs() + me.abs() + xl.abs() + b.abs();
    let er = 4.0 * U * s + 1e-300;
    let q2 = r / dh;
    let e2 = (er + 3.0 * U * r.abs()) / dh.abs() + U * q2.abs();
    let den = dh.abs() * (1.0 - 2.0 * U) - ed;
    if den <= 0.0 {
        return None;
    }
    let e1 = (ex + (q1.abs() + q2.abs()) * (1.0 + U) * ed) / den;
    // Rounding of the bound itself (a few operations, each a factor 1 + u).
    let e = (e1 + e2) * (1.0 + 16.0 * U);
    let (h, l) = two_sum(q1, q2);
    // Distances to the neighbours of `|h|` (normal: `q1` is, `h` is within a few ulps),
    // above and below, then as seen from `h`.
    let bits = h.abs().to_bits();
    let away = f64::from_bits(bits + 1) - h.abs();
    let toward = h.abs() - f64::from_bits(bits - 1);
    let (up, down) = if h > 0.0 {
        (away, toward)
    } else {
        (toward, away)
    };
    if !up.is_finite() || !down.is_finite() {
        return None;
    }
    // Rounding is monotone and half-gaps are powers of two: the computed comparisons
    // imply the exact ones.
    if l + e < 0.5 * up && l - e > -0.5 * down {
        Some(h)
    } else {
        None
    }
}

/// The meeting point of two input lines (not box sides, not parallel) rounded to the
/// nearest `f64`s. Never wrong: falls back to exact rounding.
pub(super) fn meet_rounded(i: &Line, j: &Line) -> Option<(f64, f64)> {
    if i.m == 0.0 && j.m == 0.0 {
        if let Some(p) = meet_fast(i, j) {
            return Some(p);
        }
    }
    meet_f64(i, j).or_else(|| {
        if i.m != 0.0 || j.m != 0.0 {
            return None;
        }
        let ((x, y), _) = meet_exact(i, j);
        Some((to_f64(&x), to_f64(&y)))
    })
}

/// The fast path alone (`None` when it cannot prove the rounding).
#[inline]
fn meet_fast(i: &Line, j: &Line) -> Option<(f64, f64)> {
    let (dh, dl, ed) = minor(i.a, j.b, j.a, i.b)?;
    let (xh, xl, ex) = minor(i.c, j.b, j.c, i.b)?;
    let (yh, yl, ey) = minor(i.a, j.c, j.a, i.c)?;
    Some((
        quotient(xh, xl, ex, dh, dl, ed)?,
        quotient(yh, yl, ey, dh, dl, ed)?,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exact(i: &Line, j: &Line) -> (f64, f64) {
        let ((x, y), _) = meet_exact(i, j);
        (to_f64(&x), to_f64(&y))
    }

    #[test]
    fn equals_the_exact_rounding() {
        let mut unit = crate::testing::units(11);
        let mut next = || unit() - 0.5;
        let mut fast = 0;
        for t in 0..20000 {
            let scale = [1.0, 1e-100, 1e100, 1e-280, 7.0][t % 5];
            let (i, j) = if t % 4 == 0 {
                // Tangents of the unit circle at nearby angles (the benchmark's input).
                let a = next() * 6.0;
                let b = a + next() * 1e-6;
                (
                    Line::input(a.cos(), a.sin(), 1.0),
                    Line::input(b.cos(), b.sin(), 1.0),
                )
            } else {
                (
                    Line::input(next(), next(), next() * scale),
                    Line::input(next(), next(), next() * scale),
                )
            };
            if i.a * j.b == j.a * i.b {
                continue;
            }
            if let Some(p) = meet_fast(&i, &j) {
                fast += 1;
                assert_eq!(p, exact(&i, &j), "{i:?} {j:?}");
            }
            assert_eq!(meet_rounded(&i, &j), Some(exact(&i, &j)));
        }
        assert!(fast > 15000, "{fast}");
        // Exact midpoints between neighbouring f64s (ties to even) and exact values.
        let e = f64::EPSILON;
        for (c, d) in [
            (1.0 + e, 2.0),
            (2.0 + 2.0 * e, 2.0),
            (3.0, 3.0),
            (1.0 + 3.0 * e, 2.0),
            (-1.0 - e, 2.0),
            (1.0, 3.0),
        ] {
            let i = Line::input(d, 0.0, c);
            let j = Line::input(0.0, 1.0, 0.0);
            assert_eq!(meet_rounded(&i, &j), Some(exact(&i, &j)), "{c} / {d}");
        }
    }
}
