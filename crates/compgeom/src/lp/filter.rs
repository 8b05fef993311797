//! Fast exact predicates for the half-plane intersection (book §4.2): the same signs as
//! `exact::side`, `exact::cross_sign` and `exact::cmp_meet_y`, first computed in plain `f64`
//! with a *static* error bound (a constant times the permanent, no per-operation error
//! tracking), and handed to the filtered/exact versions in `exact` only when that bound
//! cannot decide or the inputs are outside the range where the bound is proved.
//!
//! # The bounds
//!
//! With `u = 2^-53` and every input coefficient zero or of magnitude in `[2^-250, 2^250]`,
//! no product overflows, and the only products that can underflow are the last ones of
//! `cmp_meet_y` (each then off by at most `2^-1075`, covered by an absolute term).
//! A 2×2 minor `x·y - z·w` computed in `f64` is within `2u·(|x·y| + |z·w|)·(1 + u)` of the
//! exact value; the 3×3 determinant of `side` (three products of an input and a minor, two
//! sums) is within `5u·perm·(1 + 4u)` where `perm` is the same expression with every
//! product and difference replaced by the sum of absolute values; the degree-4 difference
//! of `cmp_meet_y` is within `6u·perm·(1 + 4u)`. The tests below use `6u` and `7u`, and
//! compare the computed bound with a strict inequality, after rounding the bound up.

use super::exact::{cmp_meet_y, cross_sign, side, two_sum, Line, U};
use super::round_meet::{minor as minor_dd, prod_err};
use std::cmp::Ordering;

/// 2^250 and 2^-250: the coefficient range in which the static bounds are proved.
const BIG: f64 = 1.809_251_394_333_065_6e75;
const SMALL: f64 = 5.527_147_875_260_444e-76;
/// Twice the largest error of an underflowing product.
const ETA2: f64 = 1e-323;

/// Zero, or a magnitude inside `[2^-250, 2^250]`.
#[inline]
fn ok(v: f64) -> bool {
    let a = v.abs();
    a < BIG && (a > SMALL || a == 0.0)
}

/// Every coefficient of an input line (not a box side) in range.
#[inline]
fn in_range(l: &Line) -> bool {
    l.m == 0.0 && ok(l.a) && ok(l.b) && ok(l.c)
}

/// The sign of `v` when `|v|` exceeds the bound `e` (computed with rounding; enlarged a
/// little to cover that), else `None`.
#[inline(always)]
fn decide(v: f64, e: f64) -> Option<Ordering> {
    let e = e * (1.0 + 8.0 * U);
    if v > e {
        Some(Ordering::Greater)
    } else if -v > e {
        Some(Ordering::Less)
    } else {
        None
    }
}

/// `ai·bj - aj·bi` in `f64` and its permanent.
#[inline(always)]
fn minor(ai: f64, bj: f64, aj: f64, bi: f64) -> (f64, f64) {
    let (p, q) = (ai * bj, aj * bi);
    (p - q, p.abs() + q.abs())
}

/// As `exact::cross_sign`: the sign of `ai·bj - aj·bi`, exactly.
#[inline]
pub(super) fn cross(i: &Line, j: &Line) -> Ordering {
    if ok(i.a) && ok(i.b) && ok(j.a) && ok(j.b) {
        let (d, p) = minor(i.a, j.b, j.a, i.b);
        if let Some(s) = decide(d, 3.0 * U * p) {
            return s;
        }
    }
    cross_sign(i, j)
}

/// As `exact::side`: where the meeting point of lines `i`, `j` (not parallel) lies relative
/// to the half-plane `k` (`Less` strictly inside, `Equal` on its line, `Greater` outside).
#[inline]
pub(super) fn side_of(i: &Line, j: &Line, k: &Line) -> Ordering {
    if in_range(i) && in_range(j) && in_range(k) {
        let (x, px) = minor(i.c, j.b, j.c, i.b);
        let (y, py) = minor(i.a, j.c, j.a, i.c);
        let (d, pd) = minor(i.a, j.b, j.a, i.b);
        if let Some(ds) = decide(d, 3.0 * U * pd) {
            let v = k.a * x + k.b * y - k.c * d;
            let perm = k.a.abs() * px + k.b.abs() * py + k.c.abs() * pd;
            let s = decide(v, 6.0 * U * perm).or_else(|| side_dd(i, j, k));
            if let Some(s) = s {
                return if ds == Ordering::Less { s.reverse() } else { s };
            }
        }
    }
    side(i, j, k)
}

/// The sign of `ka·X + kb·Y - kc·D` (as in [`side_of`], before the sign of `D`) in
/// double-double arithmetic, for the near-degenerate cases the `f64` bound cannot settle
/// (e.g. tangents of a circle a millionth of a radian apart). Each minor is `hi + lo`
/// within its bound `e`; `k·hi` is split exactly into `p + pe`, `k·lo` is rounded; the
/// large parts are summed exactly (`two_sum`), the small ones in `f64`.
#[inline(never)]
fn side_dd(i: &Line, j: &Line, k: &Line) -> Option<Ordering> {
    let (xh, xl, ex) = minor_dd(i.c, j.b, j.c, i.b)?;
    let (yh, yl, ey) = minor_dd(i.a, j.c, j.a, i.c)?;
    let (dh, dl, ed) = minor_dd(i.a, j.b, j.a, i.b)?;
    let (p1, p2, p3) = (k.a * xh, k.b * yh, k.c * dh);
    let (e1, e2, e3) = (
        prod_err(k.a, xh, p1)?,
        prod_err(k.b, yh, p2)?,
        prod_err(k.c, dh, p3)?,
    );
    let (l1, l2, l3) = (k.a * xl, k.b * yl, k.c * dl);
    let (s1, r1) = two_sum(p1, p2);
    let (s2, r2) = two_sum(s1, -p3);
    let small = [r1, r2, e1, e2, -e3, l1, l2, -l3];
    let rest: f64 = small.iter().sum();
    let mag: f64 = small.iter().map(|v| v.abs()).sum();
    let v = s2 + rest;
    let e = k.a.abs() * ex
        + k.b.abs() * ey
        + k.c.abs() * ed
        + U * (l1.abs() + l2.abs() + l3.abs())
        + 8.0 * U * mag
        + U * v.abs()
        + ETA2;
    decide(v, e)
}

/// As `exact::cmp_meet_y`: compare the heights of the meeting point of `i`, `j` and that of
/// `k`, `l` (neither pair parallel), exactly.
#[inline]
pub(super) fn meet_y(i: &Line, j: &Line, k: &Line, l: &Line) -> Ordering {
    if in_range(i) && in_range(j) && in_range(k) && in_range(l) {
        let (yij, pyij) = minor(i.a, j.c, j.a, i.c);
        let (dij, pdij) = minor(i.a, j.b, j.a, i.b);
        let (ykl, pykl) = minor(k.a, l.c, l.a, k.c);
        let (dkl, pdkl) = minor(k.a, l.b, l.a, k.b);
        let sd = (decide(dij, 3.0 * U * pdij), decide(dkl, 3.0 * U * pdkl));
        if let (Some(s1), Some(s2)) = sd {
            let v = yij * dkl - ykl * dij;
            let perm = pyij * pdkl + pykl * pdij;
            if let Some(s) = decide(v, 7.0 * U * perm + ETA2) {
                // y_ij - y_kl = v / (D_ij·D_kl).
                return if s1 == s2 { s } else { s.reverse() };
            }
        }
    }
    cmp_meet_y(i, j, k, l)
}

/// True when `a`, `b`, `c` are all zero or inside `[2^-250, 2^250]` in magnitude: the range
/// in which [`Meet`] and [`cross_in_range`] are proved.
#[inline(always)]
pub(super) fn coefficients_in_range(a: f64, b: f64, c: f64) -> bool {
    ok(a) && ok(b) && ok(c)
}

/// The sign of `ai·bj - aj·bi` for coefficients in range ([`coefficients_in_range`]), or
/// `None` when the `f64` value is within its error bound `3u·(|ai·bj| + |aj·bi|)` of zero.
#[inline(always)]
pub(super) fn cross_in_range(ai: f64, bi: f64, aj: f64, bj: f64) -> Option<Ordering> {
    let (d, p) = minor(ai, bj, aj, bi);
    decide(d, 3.0 * U * p)
}

/// The meeting point `(X/D, Y/D)` of two input lines with coefficients in range, kept as
/// its three `f64` minors (times the sign of `D`) and their permanents (pre-multiplied by
/// the error constant of [`side_of`]), so that testing it against a half-plane costs one
/// three-term dot product and one three-term bound: the vertex test of the 2D LP (book
/// §4.3), made once per constraint and once per constraint of each 1D re-solve.
///
/// The bound is the one of [`side_of`]: `|computed - exact| <= 5u·perm·(1 + 4u)` for
/// `perm = |ka|·PX + |kb|·PY + |kc|·PD` (`PX = |ci·bj| + |cj·bi|` as computed, etc.);
/// the test uses `6u·(1 + 8u)·perm`, evaluated with four more roundings (each at most a
/// factor `1 - u`), which still exceeds the error. Negating the minors when `D < 0` is
/// exact. In range no product under- or overflows (see the module docs).
#[derive(Debug, Clone, Copy)]
pub(super) struct Meet {
    x: f64,
    y: f64,
    d: f64,
    px: f64,
    py: f64,
    pd: f64,
}

impl Meet {
    /// The meeting point of `a_i·x + b_i·y = c_i` and `a_j·x + b_j·y = c_j`; `None` when a
    /// coefficient is out of range or the sign of `D` is not certain in `f64` (parallel or
    /// nearly parallel lines: the caller then decides exactly).
    #[inline]
    pub(super) fn new(i: (f64, f64, f64), j: (f64, f64, f64)) -> Option<Meet> {
        if !(coefficients_in_range(i.0, i.1, i.2) && coefficients_in_range(j.0, j.1, j.2)) {
            return None;
        }
        let (x, px) = minor(i.2, j.1, j.2, i.1);
        let (y, py) = minor(i.0, j.2, j.0, i.2);
        let (d, pd) = minor(i.0, j.1, j.0, i.1);
        let s = match decide(d, 3.0 * U * pd)? {
            Ordering::Less => -1.0,
            _ => 1.0,
        };
        const K: f64 = 6.0 * U * (1.0 + 8.0 * U);
        Some(Meet {
            x: s * x,
            y: s * y,
            d: s * d,
            px: px * K,
            py: py * K,
            pd: pd * K,
        })
    }

    /// Where the point lies relative to the half-plane `a·x + b·y <= c` (coefficients in
    /// range): `Less` strictly inside, `Greater` strictly outside, `None` when the filter
    /// cannot tell (on or very near the line).
    #[inline(always)]
    pub(super) fn side(&self, a: f64, b: f64, c: f64) -> Option<Ordering> {
        let (v, e) = self.value(a, b, c);
        if v > e {
            Some(Ordering::Greater)
        } else if -v > e {
            Some(Ordering::Less)
        } else {
            None
        }
    }

    /// The computed `sign(D)·(a·X + b·Y - c·D)` and its error bound: strictly outside the
    /// half-plane when the value exceeds the bound, strictly inside when it is below minus
    /// the bound, else undecided.
    #[inline(always)]
    pub(super) fn value(&self, a: f64, b: f64, c: f64) -> (f64, f64) {
        let v = a * self.x + b * self.y - c * self.d;
        let e = a.abs() * self.px + b.abs() * self.py + c.abs() * self.pd;
        (v, e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Random lines at many scales, and near-degenerate triples (a third line through the
    /// meeting point of two, moved by an ulp): the fast answers equal the exact ones.
    #[test]
    fn agrees_with_the_exact_predicates() {
        let mut unit = crate::testing::units(3);
        let mut next = || unit() - 0.5;
        let bx = Line::bbox();
        let mut decided = 0;
        for t in 0..20000 {
            let scale = [1.0, 1e-70, 1e70, 1e-200, 3.0][t % 5];
            let mut l = || Line::input(next(), next(), next() * scale);
            let (i, j, mut k, m) = (l(), l(), l(), l());
            if t % 3 == 0 {
                // k through the meeting point of i and j (as nearly as f64 allows).
                let d = i.a * j.b - j.a * i.b;
                let x = (i.c * j.b - j.c * i.b) / d;
                let y = (i.a * j.c - j.a * i.c) / d;
                k.c = k.a * x + k.b * y;
                if t % 2 == 0 {
                    k.c = f64::from_bits(k.c.to_bits() + 1);
                }
            }
            if t % 7 == 0 {
                k = bx[t % 4];
            }
            assert_eq!(cross(&i, &j), cross_sign(&i, &j));
            if cross_sign(&i, &j) != Ordering::Equal {
                assert_eq!(side_of(&i, &j, &k), side(&i, &j, &k), "{i:?} {j:?} {k:?}");
                if cross_sign(&k, &m) != Ordering::Equal {
                    assert_eq!(meet_y(&i, &j, &k, &m), cmp_meet_y(&i, &j, &k, &m));
                    assert_eq!(meet_y(&i, &j, &i, &j), Ordering::Equal);
                }
            }
            // The LP's precomputed vertex and cross product: never a wrong sign.
            let t3 = |l: &Line| (l.a, l.b, l.c);
            if let Some(s) = cross_in_range(i.a, i.b, j.a, j.b) {
                assert_eq!(s, cross_sign(&i, &j));
            }
            if k.m == 0.0 && coefficients_in_range(k.a, k.b, k.c) {
                if let Some(v) = Meet::new(t3(&i), t3(&j)) {
                    if let Some(s) = v.side(k.a, k.b, k.c) {
                        assert_eq!(s, side(&i, &j, &k), "{i:?} {j:?} {k:?}");
                        decided += 1;
                    }
                }
            }
        }
        assert!(decided > 5000, "{decided}");

        // Integer lines through one point: exact zeros.
        let (i, j, k) = (
            Line::input(1.0, 2.0, 3.0),
            Line::input(2.0, -1.0, 1.0),
            Line::input(3.0, 1.0, 4.0),
        );
        assert_eq!(side_of(&i, &j, &k), Ordering::Equal);
    }
}
