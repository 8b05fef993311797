//! Exact brute-force oracles for the chapter 4 tests (big rationals throughout).
#![allow(dead_code)]

use compgeom::lp::HalfPlane;
use num_rational::BigRational;
use num_traits::{ToPrimitive, Zero};

pub type Q = BigRational;

/// The exact value of an f64.
pub fn r(x: f64) -> Q {
    BigRational::from_float(x).expect("finite")
}

/// Nearest f64 of an exact rational.
pub fn f(q: &Q) -> f64 {
    q.to_f64().expect("in range")
}

/// The meeting point of two constraint lines, if they are not parallel.
pub fn meet(h: &HalfPlane, g: &HalfPlane) -> Option<(Q, Q)> {
    let d = r(h.a) * r(g.b) - r(g.a) * r(h.b);
    if d.is_zero() {
        return None;
    }
    let x = (r(h.c) * r(g.b) - r(g.c) * r(h.b)) / &d;
    let y = (r(h.a) * r(g.c) - r(g.a) * r(h.c)) / &d;
    Some((x, y))
}

/// `a·x + b·y - c` exactly.
pub fn slack(h: &HalfPlane, p: &(Q, Q)) -> Q {
    r(h.a) * &p.0 + r(h.b) * &p.1 - r(h.c)
}

pub fn inside(hs: &[HalfPlane], p: &(Q, Q)) -> bool {
    hs.iter().all(|h| slack(h, p) <= Q::zero())
}

/// Candidate points: every pairwise meeting point, the point of each line nearest the
/// origin, and the origin. A non-empty intersection contains one of them.
pub fn candidates(hs: &[HalfPlane]) -> Vec<(Q, Q)> {
    let mut out = vec![(Q::zero(), Q::zero())];
    for (i, h) in hs.iter().enumerate() {
        if h.a != 0.0 || h.b != 0.0 {
            let nn = r(h.a) * r(h.a) + r(h.b) * r(h.b);
            out.push((r(h.c) * r(h.a) / &nn, r(h.c) * r(h.b) / &nn));
        }
        for g in &hs[i + 1..] {
            if let Some(p) = meet(h, g) {
                out.push(p);
            }
        }
    }
    out
}

pub fn vertices(hs: &[HalfPlane]) -> Vec<(Q, Q)> {
    let mut out = Vec::new();
    for (i, h) in hs.iter().enumerate() {
        for g in &hs[i + 1..] {
            if let Some(p) = meet(h, g) {
                if inside(hs, &p) {
                    out.push(p);
                }
            }
        }
    }
    out.sort();
    out.dedup();
    out
}

pub fn feasible(hs: &[HalfPlane]) -> bool {
    candidates(hs).iter().any(|p| inside(hs, p))
}

/// Is there a direction d with c·d > 0 and a·d <= 0 for all constraints?
pub fn has_improving_ray(hs: &[HalfPlane], c: (f64, f64)) -> bool {
    let mut dirs = vec![(r(c.0), r(c.1))];
    for h in hs {
        dirs.push((r(h.b), -r(h.a)));
        dirs.push((-r(h.b), r(h.a)));
        dirs.push((-r(h.a), -r(h.b)));
    }
    dirs.iter().any(|d| {
        r(c.0) * &d.0 + r(c.1) * &d.1 > Q::zero()
            && hs
                .iter()
                .all(|h| r(h.a) * &d.0 + r(h.b) * &d.1 <= Q::zero())
    })
}

#[derive(Debug)]
pub enum Expected {
    Infeasible,
    Unbounded,
    Optimal { point: (Q, Q), value: Q },
}

/// The exact answer of the LP, with the book's rule: the lexicographically smallest
/// optimal vertex, or (no optimal vertex) the point of the optimal line nearest the origin.
pub fn oracle_lp(hs: &[HalfPlane], c: (f64, f64)) -> Expected {
    if !feasible(hs) {
        return Expected::Infeasible;
    }
    if has_improving_ray(hs, c) {
        return Expected::Unbounded;
    }
    let val = |p: &(Q, Q)| r(c.0) * &p.0 + r(c.1) * &p.1;
    let vs = vertices(hs);
    if !vs.is_empty() {
        let best = vs.iter().map(val).max().expect("non-empty");
        let point = vs.into_iter().find(|p| val(p) == best).expect("attained");
        return Expected::Optimal { point, value: best };
    }
    // No optimal vertex: the optimal set is the line c·p = best; its point nearest 0.
    let value = candidates(hs)
        .iter()
        .filter(|p| inside(hs, p))
        .map(val)
        .max()
        .expect("feasible");
    let cc = r(c.0) * r(c.0) + r(c.1) * r(c.1);
    let point = (&value * r(c.0) / &cc, &value * r(c.1) / &cc);
    Expected::Optimal { point, value }
}
