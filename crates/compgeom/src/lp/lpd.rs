//! Linear programming in any fixed dimension (book §4.5, RANDOMIZEDLP).
//!
//! Maximize `c·x` subject to `a_i·x <= b_i`, `x ∈ R^d`. Constraints are added in a seeded
//! random order; when the current optimum violates the next constraint, the new optimum
//! lies on its hyperplane, found by a recursive `(d-1)`-dimensional program (one variable
//! eliminated) over the earlier constraints. Expected time O(d!·n).
//!
//! Exactness: everything is computed in **exact rational arithmetic** (`BigRational`)
//! — slower than the filtered two-dimensional [`lp2d`](super::lp2d) by a large constant,
//! but never wrong. Unboundedness is handled as in two dimensions: a symbolic box
//! `|x_j| <= M` (numbers are `u + v·M` with `M` larger than everything finite), re-created
//! for the remaining variables at each level of the recursion.
//!
//! Ties are broken lexicographically (maximize `c·x`, then minimize `x_1`, then `x_2`, …),
//! so the answer is the **lexicographically smallest optimal point** whenever it exists
//! (then it is a vertex). When the objective is bounded but the optimal set runs off toward
//! smaller coordinates, another optimal point is reported: the first point of the ray the
//! symbolic optimum moves along that satisfies every constraint.

use super::exact::{rat, to_f64};
use super::Shuffler;
use crate::{Error, Result};
use num_rational::BigRational as Q;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

/// The outcome of a linear program in `d` dimensions.
#[derive(Debug, Clone, PartialEq)]
pub enum LpSolution {
    /// A finite optimum.
    Optimal {
        /// An optimal point (see the module docs for which), nearest `f64` per coordinate.
        point: Vec<f64>,
        /// The optimal value, nearest `f64` of the exact value.
        value: f64,
        /// The input constraints tight at `point`.
        constraints: Vec<usize>,
    },
    /// The objective grows without bound.
    Unbounded {
        /// A feasible point (nearest `f64`) from which `direction` stays feasible.
        point: Vec<f64>,
        /// A direction `r` with `c·r > 0` and `a_i·r <= 0` for every constraint (rounded
        /// from the exact direction, scaled so its largest coordinate is ±1).
        direction: Vec<f64>,
    },
    /// No point satisfies every constraint.
    Infeasible {
        /// Input constraints that, with the others' help at most, contradict: every set
        /// containing them is infeasible.
        certificate: Vec<usize>,
    },
}

/// `c + m·M` with the symbolic `M`; ordered by `m` first.
#[derive(Debug, Clone, PartialEq, Eq)]
struct Mq {
    m: Q,
    c: Q,
}

impl Mq {
    fn finite(c: Q) -> Mq {
        Mq { m: Q::zero(), c }
    }
    fn sub(&self, o: &Mq) -> Mq {
        Mq {
            m: &self.m - &o.m,
            c: &self.c - &o.c,
        }
    }
    fn add(&self, o: &Mq) -> Mq {
        Mq {
            m: &self.m + &o.m,
            c: &self.c + &o.c,
        }
    }
    fn scale(&self, s: &Q) -> Mq {
        Mq {
            m: &self.m * s,
            c: &self.c * s,
        }
    }
}

impl PartialOrd for Mq {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

impl Ord for Mq {
    fn cmp(&self, o: &Self) -> Ordering {
        self.m.cmp(&o.m).then_with(|| self.c.cmp(&o.c))
    }
}

/// `a·y <= b`; `id` is the input index, `None` for a side of the symbolic box.
#[derive(Debug, Clone)]
struct Con {
    a: Vec<Q>,
    b: Mq,
    id: Option<usize>,
}

fn dot(a: &[Q], y: &[Mq]) -> Mq {
    let mut s = Mq::finite(Q::zero());
    for (aj, yj) in a.iter().zip(y) {
        if !aj.is_zero() {
            s = s.add(&yj.scale(aj));
        }
    }
    s
}

type Cert = Vec<Option<usize>>;

/// The lexicographic optimum over `cons` in `k` variables, inside the symbolic box.
fn solve(cons: &[Con], k: usize, objs: &[Vec<Q>]) -> std::result::Result<Vec<Mq>, Cert> {
    // The box corner that is best for the objectives: each variable to ±M by the sign of
    // its first non-zero objective coefficient (the objectives span, so one exists).
    let mut v: Vec<Mq> = (0..k)
        .map(|j| {
            let s = objs
                .iter()
                .map(|o| o[j].cmp(&Q::zero()))
                .find(|&s| s != Ordering::Equal)
                .unwrap_or(Ordering::Less);
            let one = if s == Ordering::Greater { 1 } else { -1 };
            Mq {
                m: Q::from_integer(one.into()),
                c: Q::zero(),
            }
        })
        .collect();
    for i in 0..cons.len() {
        let h = &cons[i];
        if dot(&h.a, &v) <= h.b {
            continue;
        }
        let Some(p) = h.a.iter().position(|x| !x.is_zero()) else {
            return Err(vec![h.id]);
        };
        if k == 1 {
            let y = vec![h.b.scale(&(Q::from_integer(1.into()) / &h.a[0]))];
            let bound = Mq {
                m: Q::from_integer(1.into()),
                c: Q::zero(),
            };
            if y[0] > bound || y[0].scale(&Q::from_integer((-1).into())) > bound {
                return Err(vec![h.id]);
            }
            if let Some(g) = cons[..i].iter().find(|g| dot(&g.a, &y) > g.b) {
                return Err(vec![h.id, g.id]);
            }
            v = y;
            continue;
        }
        // Eliminate variable p: y_p = (b - Σ_{j≠p} a_j·y_j) / a_p.
        let ap = h.a[p].clone();
        let project = |g: &Con| -> Con {
            let f = &g.a[p] / &ap;
            let a: Vec<Q> = (0..k)
                .filter(|&j| j != p)
                .map(|j| &g.a[j] - &f * &h.a[j])
                .collect();
            Con {
                a,
                b: g.b.sub(&h.b.scale(&f)),
                id: g.id,
            }
        };
        let mut sub: Vec<Con> = Vec::with_capacity(i + 2);
        for s in [1, -1] {
            let mut a = vec![Q::zero(); k];
            a[p] = Q::from_integer(s.into());
            sub.push(project(&Con {
                a,
                b: Mq {
                    m: Q::from_integer(1.into()),
                    c: Q::zero(),
                },
                id: None,
            }));
        }
        sub.extend(cons[..i].iter().map(project));
        let sub_objs: Vec<Vec<Q>> = objs
            .iter()
            .map(|o| {
                let f = &o[p] / &ap;
                (0..k)
                    .filter(|&j| j != p)
                    .map(|j| &o[j] - &f * &h.a[j])
                    .collect()
            })
            .collect();
        match solve(&sub, k - 1, &sub_objs) {
            Ok(y) => {
                let mut full = Vec::with_capacity(k);
                let mut rest = y.into_iter();
                for j in 0..k {
                    if j == p {
                        full.push(Mq::finite(Q::zero()));
                    } else {
                        full.push(rest.next().unwrap_or_else(|| Mq::finite(Q::zero())));
                    }
                }
                // a_p·y_p = b - Σ_{j≠p} a_j·y_j.
                let others = dot(&h.a, &full);
                full[p] = h.b.sub(&others).scale(&(Q::from_integer(1.into()) / &ap));
                v = full;
            }
            Err(mut cert) => {
                cert.push(h.id);
                return Err(cert);
            }
        }
    }
    Ok(v)
}

/// Solve: maximize `objective · x` subject to every row `[a_1, …, a_d, b]` (`a·x <= b`),
/// with `d = objective.len()`.
///
/// Errors ([`Error::InvalidInput`] / [`Error::NonFinite`]): rows of the wrong length,
/// non-finite numbers, an empty, zero or non-finite objective.
///
/// ```
/// use compgeom::lp::{lp_d, LpSolution};
/// // The unit cube 0 <= x, y, z <= 1: maximize x + y + z.
/// let mut rows = Vec::new();
/// for j in 0..3 {
///     let mut up = vec![0.0; 4];
///     up[j] = 1.0;
///     up[3] = 1.0;
///     let mut down = vec![0.0; 4];
///     down[j] = -1.0;
///     rows.push(up);
///     rows.push(down);
/// }
/// match lp_d(&rows, &[1.0, 1.0, 1.0], 0)? {
///     LpSolution::Optimal { point, value, .. } => {
///         assert_eq!(point, vec![1.0, 1.0, 1.0]);
///         assert_eq!(value, 3.0);
///     }
///     other => panic!("{other:?}"),
/// }
/// // Maximize x alone: the optimal face is a square; the lexicographically smallest point.
/// match lp_d(&rows, &[1.0, 0.0, 0.0], 0)? {
///     LpSolution::Optimal { point, .. } => assert_eq!(point, vec![1.0, 0.0, 0.0]),
///     other => panic!("{other:?}"),
/// }
/// # Ok::<(), compgeom::Error>(())
/// ```
pub fn lp_d(rows: &[Vec<f64>], objective: &[f64], seed: u64) -> Result<LpSolution> {
    let d = objective.len();
    if d == 0 || objective.iter().any(|c| !c.is_finite()) || objective.iter().all(|&c| c == 0.0) {
        return Err(Error::InvalidInput(
            "the objective must have at least one coefficient, all finite, not all zero".into(),
        ));
    }
    let mut cons = Vec::with_capacity(rows.len());
    for (i, r) in rows.iter().enumerate() {
        if r.len() != d + 1 {
            return Err(Error::InvalidInput(format!(
                "constraint {i} has {} numbers, expected {} (a1 .. a{d} b)",
                r.len(),
                d + 1
            )));
        }
        if let Some(&v) = r.iter().find(|v| !v.is_finite()) {
            return Err(Error::NonFinite {
                what: format!("constraint {i}"),
                value: v,
            });
        }
        if r[..d].iter().all(|&a| a == 0.0) {
            if r[d] < 0.0 {
                return Ok(LpSolution::Infeasible {
                    certificate: vec![i],
                });
            }
            continue;
        }
        cons.push((
            r[..d].iter().map(|&a| rat(a)).collect::<Vec<Q>>(),
            rat(r[d]),
            i,
        ));
    }
    let objective: Vec<Q> = objective.iter().map(|&c| rat(c)).collect();
    let (x, v1, grow) = match run_exact(cons.clone(), &objective, seed) {
        Exact::Infeasible(certificate) => return Ok(LpSolution::Infeasible { certificate }),
        Exact::Solved { x, ray, grows } => (x, ray, grows),
    };
    let point: Vec<f64> = x.iter().map(to_f64).collect();
    if grow {
        let scale = v1.iter().map(|q| q.abs()).max().unwrap_or_else(Q::zero);
        let direction = v1.iter().map(|q| to_f64(&(q / &scale))).collect();
        return Ok(LpSolution::Unbounded { point, direction });
    }
    let c = &objective;
    let value: Q = c.iter().zip(&x).map(|(a, b)| a * b).sum();
    let mut constraints: Vec<usize> = cons
        .iter()
        .filter(|(a, b, _)| a.iter().zip(&x).map(|(a, b)| a * b).sum::<Q>() == *b)
        .map(|(_, _, id)| *id)
        .collect();
    constraints.sort_unstable();
    Ok(LpSolution::Optimal {
        point,
        value: to_f64(&value),
        constraints,
    })
}

/// The exact outcome of [`run_exact`].
pub(crate) enum Exact {
    /// Input constraints that contradict.
    Infeasible(Vec<usize>),
    /// `x` feasible; `ray` the direction the symbolic optimum moves along (zero when the
    /// lexicographic optimum is finite); `grows` when the objective increases along it.
    Solved { x: Vec<Q>, ray: Vec<Q>, grows: bool },
}

/// Exact randomized LP over constraints `a·x <= b` (`(a, b, id)`); `x` is the
/// lexicographically smallest optimum when it exists, else a feasible point on the ray.
pub(crate) fn run_exact(rows: Vec<(Vec<Q>, Q, usize)>, objective: &[Q], seed: u64) -> Exact {
    let d = objective.len();
    let mut cons: Vec<Con> = rows
        .into_iter()
        .map(|(a, b, id)| Con {
            a,
            b: Mq::finite(b),
            id: Some(id),
        })
        .collect();
    Shuffler::new(seed).shuffle(&mut cons);
    // Objectives: c, then minimize x_1, x_2, ... (the book's lexicographic rule).
    let mut objs = vec![objective.to_vec()];
    for j in 0..d {
        let mut t = vec![Q::zero(); d];
        t[j] = Q::from_integer((-1).into());
        objs.push(t);
    }
    let v = match solve(&cons, d, &objs) {
        Ok(v) => v,
        Err(cert) => {
            let mut certificate: Vec<usize> = cert.into_iter().flatten().collect();
            certificate.sort_unstable();
            certificate.dedup();
            return Exact::Infeasible(certificate);
        }
    };
    let v0: Vec<Q> = v.iter().map(|x| x.c.clone()).collect();
    let v1: Vec<Q> = v.iter().map(|x| x.m.clone()).collect();
    let grow: Q = objective.iter().zip(&v1).map(|(a, b)| a * b).sum();
    // v0 + t·v1 is feasible for all large t: the smallest such t >= 0.
    let mut t = Q::zero();
    for g in &cons {
        let slope: Q = g.a.iter().zip(&v1).map(|(a, b)| a * b).sum();
        if slope.is_negative() {
            let at0: Q = g.a.iter().zip(&v0).map(|(a, b)| a * b).sum();
            let need = (at0 - &g.b.c) / (-slope);
            if need > t {
                t = need;
            }
        }
    }
    let x: Vec<Q> = v0.iter().zip(&v1).map(|(a, b)| a + &t * b).collect();
    Exact::Solved {
        x,
        ray: v1,
        grows: grow.is_positive(),
    }
}
