//! Exact certification of a candidate optimal basis (the fast path of [`super::lp_d`] and
//! [`super::castability`]).
//!
//! A basis is `d` constraints. It certifies the point `x` where their hyperplanes meet as
//! the **lexicographic optimum** (maximize `c·x`, then minimize `x_1`, `x_2`, …) when
//!
//! 1. the `d` normals are independent (`x` is a vertex, computed exactly by Cramer's rule
//!    on integers),
//! 2. `x` satisfies every constraint — an `f64` filter with a rigorous error bound decides
//!    each one and exact integer arithmetic the few it cannot (those through `x`), and
//! 3. the perturbed objective `c - ε·e_1 - ε²·e_2 - …` lies, for all small `ε > 0`, in the
//!    cone of the basis normals: each row of `A_B^{-T}·[c, -e_1, …, -e_d]` is
//!    lexicographically positive (its sign pattern is read off exact determinants).
//!
//! Then for every feasible `y ≠ x`, `r = y - x` has `a_i·r <= 0` on the basis and
//! `(c·r, -r_1, …, -r_d)` is lexicographically negative: `x` is the unique lexicographic
//! optimum, so it is exactly the answer of the exact algorithm. A basis that fails any test
//! proves nothing; the caller then runs the exact algorithm.

use super::exact::{to_f64, U};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

/// An exact constraint `a·x <= b` in integers (a positive multiple of the input one).
#[derive(Debug, Clone)]
pub(crate) struct IRow {
    pub(crate) a: Vec<BigInt>,
    pub(crate) b: BigInt,
}

/// `(m, e)` with `v = m·2^e` exactly (`v` finite).
fn split(v: f64) -> (i64, i32) {
    if v == 0.0 {
        return (0, 0);
    }
    let bits = v.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i32;
    let frac = (bits & ((1u64 << 52) - 1)) as i64;
    let (m, e) = if exp == 0 {
        (frac, -1074)
    } else {
        (frac | (1i64 << 52), exp - 1075)
    };
    (if v < 0.0 { -m } else { m }, e)
}

/// The numbers `vs` (finite) times a common power of two, as integers.
pub(crate) fn ints_from_f64(vs: &[f64]) -> Vec<BigInt> {
    let parts: Vec<(i64, i32)> = vs.iter().map(|&v| split(v)).collect();
    let e0 = parts
        .iter()
        .filter(|p| p.0 != 0)
        .map(|p| p.1)
        .min()
        .unwrap_or(0);
    parts
        .iter()
        .map(|&(m, e)| BigInt::from(m) << ((e - e0) as usize))
        .collect()
}

/// The exact row `a·x <= b` of `f64` numbers as integers.
pub(crate) fn irow_from_f64(a: &[f64], b: f64) -> IRow {
    let mut all = a.to_vec();
    all.push(b);
    let mut v = ints_from_f64(&all);
    let b = v.pop().unwrap_or_default();
    IRow { a: v, b }
}

/// A positive common multiple of the denominators (their least one when they are powers of
/// two, as for sums of products of `f64` numbers).
pub(crate) fn common_denominator<'a>(qs: impl Iterator<Item = &'a BigRational>) -> BigInt {
    let mut l = BigInt::from(1);
    for q in qs {
        if !(&l % q.denom()).is_zero() {
            l *= q.denom();
        }
    }
    l
}

/// The exact row `a·x <= b` of rationals as integers, times [`common_denominator`].
pub(crate) fn irow_from_q(a: &[BigRational], b: &BigRational) -> IRow {
    let l = common_denominator(a.iter().chain(std::iter::once(b)));
    let int = |q: &BigRational| q.numer() * (&l / q.denom());
    IRow {
        a: a.iter().map(int).collect(),
        b: int(b),
    }
}

/// A nearby `f64` row `[a_1, …, a_d, b]` for an integer row, scaled by a power of two so it
/// cannot overflow: each entry is within `2^-50` times the row's largest entry of the
/// (scaled) exact one.
pub(crate) fn f64_row(r: &IRow) -> Vec<f64> {
    let bits =
        r.a.iter()
            .chain(std::iter::once(&r.b))
            .map(|v| v.bits())
            .max()
            .unwrap_or(0);
    let shift = bits.saturating_sub(60);
    r.a.iter()
        .chain(std::iter::once(&r.b))
        .map(|v| {
            let s: BigInt = v >> shift;
            num_traits::ToPrimitive::to_f64(&s).unwrap_or(0.0)
        })
        .collect()
}

/// The determinant of a square integer matrix (fraction-free Bareiss elimination).
pub(crate) fn det(mut m: Vec<Vec<BigInt>>) -> BigInt {
    let n = m.len();
    let mut sign = false;
    let mut prev = BigInt::from(1);
    for k in 0..n {
        if m[k][k].is_zero() {
            match (k + 1..n).find(|&r| !m[r][k].is_zero()) {
                Some(r) => {
                    m.swap(k, r);
                    sign = !sign;
                }
                None => return BigInt::zero(),
            }
        }
        for i in k + 1..n {
            for j in k + 1..n {
                let v = (&m[i][j] * &m[k][k] - &m[i][k] * &m[k][j]) / &prev;
                m[i][j] = v;
            }
        }
        prev = m[k][k].clone();
    }
    let d = m
        .get(n.wrapping_sub(1))
        .and_then(|r| r.get(n - 1))
        .cloned()
        .unwrap_or_else(|| BigInt::from(1));
    if sign {
        -d
    } else {
        d
    }
}

/// A certified optimum `x = X / W` (`W > 0`) and the constraints tight there.
pub(crate) struct Certified {
    pub(crate) x: Vec<BigInt>,
    pub(crate) w: BigInt,
    /// Positions (into the row list) of every constraint through `x`, increasing.
    pub(crate) tight: Vec<usize>,
}

/// Certify `basis` (positions into the row list) as the lexicographic optimum of maximizing
/// `objective` over all rows. `frows[i]` is `[a_1, …, a_d, b]` in `f64`, a positive multiple
/// of the exact row `exact(i)` up to `eps` times its largest entry per entry (`eps = 0`
/// when exact). `None` when the basis does not certify.
pub(crate) fn certify(
    basis: &[usize],
    objective: &[BigInt],
    frows: &[&[f64]],
    eps: f64,
    exact: impl Fn(usize) -> IRow,
) -> Option<Certified> {
    let d = objective.len();
    if basis.len() != d {
        return None;
    }
    let rows: Vec<IRow> = basis.iter().map(|&i| exact(i)).collect();
    let a: Vec<Vec<BigInt>> = rows.iter().map(|r| r.a.clone()).collect();
    let dd = det(a.clone());
    if dd.is_zero() {
        return None;
    }
    let neg = dd.is_negative();
    // Lexicographic dual feasibility: λ_r(q) = det(A_B, row r := rhs_q) / det(A_B).
    for r in 0..d {
        let mut ok = false;
        for q in 0..=d {
            let rhs: Vec<BigInt> = if q == 0 {
                objective.to_vec()
            } else {
                (0..d)
                    .map(|j| BigInt::from(if j == q - 1 { -1 } else { 0 }))
                    .collect()
            };
            let mut m = a.clone();
            m[r] = rhs;
            let s = det(m);
            if s.is_zero() {
                continue;
            }
            ok = s.is_negative() == neg;
            break;
        }
        if !ok {
            return None;
        }
    }
    // The vertex: x_j = det(A_B, column j := b_B) / det(A_B).
    let mut x: Vec<BigInt> = (0..d)
        .map(|j| {
            let mut m = a.clone();
            for (row, ir) in m.iter_mut().zip(&rows) {
                row[j] = ir.b.clone();
            }
            det(m)
        })
        .collect();
    let mut w = dd;
    if neg {
        w = -w;
        for v in &mut x {
            *v = -&*v;
        }
    }
    let xf: Vec<f64> = x
        .iter()
        .map(|v| to_f64(&BigRational::new(v.clone(), w.clone())))
        .collect();
    let xsum: f64 = xf.iter().map(|v| v.abs()).sum::<f64>() + 1.0;
    let gamma = 4.0 * (d as f64 + 2.0) * U;
    let mut tight = Vec::new();
    for (i, fr) in frows.iter().enumerate() {
        let (fa, fb) = fr.split_at(d);
        let mut r = -fb[0];
        let mut s = fb[0].abs();
        let mut big = fb[0].abs();
        for (aj, xj) in fa.iter().zip(&xf) {
            r += aj * xj;
            s += (aj * xj).abs();
            big = big.max(aj.abs());
        }
        let err = gamma * s + 2.0 * eps * big * xsum + (d as f64 + 1.0) * 1e-300;
        let side = if r.is_finite() && err.is_finite() && r > err {
            Ordering::Greater
        } else if r.is_finite() && err.is_finite() && r < -err {
            Ordering::Less
        } else {
            let e = exact(i);
            let mut t = -(&e.b * &w);
            for (aj, xj) in e.a.iter().zip(&x) {
                t += aj * xj;
            }
            t.cmp(&BigInt::zero())
        };
        match side {
            Ordering::Greater => return None,
            Ordering::Equal => tight.push(i),
            Ordering::Less => {}
        }
    }
    Some(Certified { x, w, tight })
}
