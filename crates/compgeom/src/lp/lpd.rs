//! Linear programming in any fixed dimension (book §4.5, RANDOMIZEDLP).
//!
//! Maximize `c·x` subject to `a_i·x <= b_i`, `x ∈ R^d`. Constraints are added in a seeded
//! random order; when the current optimum violates the next constraint, the new optimum
//! lies on its hyperplane, found by a recursive `(d-1)`-dimensional program (one variable
//! eliminated) over the earlier constraints. Expected time O(d!·n).
//!
//! Exactness, in two passes:
//!
//! 1. **Fast path.** The algorithm runs in `f64` and proposes the `d` constraints that
//!    define its optimum; that basis is then *certified exactly* (the vertex by integer
//!    Cramer's rule, feasibility of every constraint by an `f64` filter with a rigorous
//!    error bound and exact integers where it cannot tell, optimality by the lexicographic
//!    dual certificate). A certified basis gives exactly the exact algorithm's answer
//!    (the unique lexicographic optimum, same tight constraints).
//! 2. **Exact path**, when the certificate fails (infeasible, unbounded, a box side in the
//!    basis, or a degenerate basis the `f64` run got wrong): the same algorithm on
//!    integers. Points are homogeneous (`X / W`) and variables are eliminated
//!    fraction-free, so no rational normalisation happens in the inner loop and the
//!    numbers grow with the depth of the recursion (at most `d`), not with `n`.
//!
//! Unboundedness is handled as in two dimensions: a symbolic box `|x_j| <= M` (numbers are
//! `u + v·M` with `M` larger than everything finite), re-created for the remaining
//! variables at each level of the recursion.
//!
//! Ties are broken lexicographically (maximize `c·x`, then minimize `x_1`, then `x_2`, …),
//! so the answer is the **lexicographically smallest optimal point** whenever it exists
//! (then it is a vertex). When the objective is bounded but the optimal set runs off toward
//! smaller coordinates, another optimal point is reported: the first point of the ray the
//! symbolic optimum moves along that satisfies every constraint.

use super::certify::{certify, f64_row, ints_from_f64, irow_from_f64, Certified, IRow};
use super::exact::{rat, to_f64};
use super::seidel::{solve, Mq, Ring, Rows};
use super::Shuffler;
use crate::{Error, Result};
use num_bigint::BigInt;
use num_rational::BigRational as Q;
use num_traits::{Signed, Zero};

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
    lp_d_with(rows, objective, seed, true)
}

/// [`lp_d`] without the `f64` fast path: always the exact integer algorithm. The answers
/// are the same (tests check it); for tests and benchmarks.
#[doc(hidden)]
pub fn lp_d_exact(rows: &[Vec<f64>], objective: &[f64], seed: u64) -> Result<LpSolution> {
    lp_d_with(rows, objective, seed, false)
}

fn lp_d_with(rows: &[Vec<f64>], objective: &[f64], seed: u64, fast: bool) -> Result<LpSolution> {
    let d = objective.len();
    if d == 0 || objective.iter().any(|c| !c.is_finite()) || objective.iter().all(|&c| c == 0.0) {
        return Err(Error::InvalidInput(
            "the objective must have at least one coefficient, all finite, not all zero".into(),
        ));
    }
    let mut kept: Vec<usize> = Vec::with_capacity(rows.len());
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
        kept.push(i);
    }
    let c_int = ints_from_f64(objective);
    let c_q: Vec<Q> = objective.iter().map(|&c| rat(c)).collect();
    let mut order = kept.clone();
    Shuffler::new(seed).shuffle(&mut order);
    // Fast path: the same algorithm in f64 proposes a basis; certified exactly or dropped.
    if let Some(cert) = fast
        .then(|| fast_optimum(rows, &order, objective, &c_int))
        .flatten()
    {
        let x: Vec<Q> = cert
            .x
            .iter()
            .map(|v| Q::new(v.clone(), cert.w.clone()))
            .collect();
        FAST_HITS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        return Ok(optimal(&x, &c_q, cert.tight.iter().map(|&k| order[k])));
    }
    let irows: Vec<IRow> = order
        .iter()
        .map(|&i| irow_from_f64(&rows[i][..d], rows[i][d]))
        .collect();
    match run_exact(&irows, &order, &c_int) {
        Exact::Infeasible(certificate) => Ok(LpSolution::Infeasible { certificate }),
        Exact::Solved { x, ray, grows, hom } => {
            let point: Vec<f64> = x.iter().map(to_f64).collect();
            if grows {
                let scale = ray.iter().map(|q| q.abs()).max().unwrap_or_else(Q::zero);
                let direction = ray.iter().map(|q| to_f64(&(q / &scale))).collect();
                return Ok(LpSolution::Unbounded { point, direction });
            }
            // Integer tests when the point is X / W, rational ones otherwise (rare).
            let on = |r: &IRow| match &hom {
                Some((xs, w)) => r.a.iter().zip(xs).map(|(a, b)| a * b).sum::<BigInt>() == &r.b * w,
                None => {
                    r.a.iter().zip(&x).map(|(a, b)| b * a).sum::<Q>()
                        == Q::from_integer(r.b.clone())
                }
            };
            let tight = irows
                .iter()
                .zip(&order)
                .filter_map(|(r, &id)| on(r).then_some(id));
            Ok(optimal(&x, &c_q, tight))
        }
    }
}

/// The `Optimal` answer at the exact point `x`, tight constraints `tight` (input ids).
fn optimal(x: &[Q], c: &[Q], tight: impl Iterator<Item = usize>) -> LpSolution {
    let value: Q = c.iter().zip(x).map(|(a, b)| a * b).sum();
    let mut constraints: Vec<usize> = tight.collect();
    constraints.sort_unstable();
    LpSolution::Optimal {
        point: x.iter().map(to_f64).collect(),
        value: to_f64(&value),
        constraints,
    }
}

/// Answers of [`lp_d`] (all threads) given by a certified fast-path basis.
static FAST_HITS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);

/// How many [`lp_d`] answers so far came from the certified `f64` fast path. For tests and
/// benchmarks.
#[doc(hidden)]
pub fn lp_d_fast_hits() -> u64 {
    FAST_HITS.load(std::sync::atomic::Ordering::Relaxed)
}

/// The lexicographic objectives: `c`, then minimize `x_1`, `x_2`, ... (the book's rule).
fn objectives<R: Ring>(c: Vec<R>) -> Vec<Vec<R>> {
    let d = c.len();
    let mut objs = vec![c];
    for j in 0..d {
        let mut t = vec![R::zero(); d];
        t[j] = R::one().neg();
        objs.push(t);
    }
    objs
}

/// Run the algorithm in `f64` over `rows[order[k]]` and certify the basis it ends on;
/// `tight` in the answer holds positions into `order`.
fn fast_optimum(
    rows: &[Vec<f64>],
    order: &[usize],
    objective: &[f64],
    c_int: &[BigInt],
) -> Option<Certified> {
    let d = objective.len();
    let mut frows = Rows::new(d, order.len());
    for (k, &i) in order.iter().enumerate() {
        frows.push(
            rows[i][..d].iter().copied(),
            Mq::finite(rows[i][d]),
            Some(k),
        );
    }
    let v = solve(&frows, &objectives(objective.to_vec())).ok()?;
    let basis: Vec<usize> = v.basis.iter().copied().collect::<Option<Vec<usize>>>()?;
    let plain: Vec<&[f64]> = order.iter().map(|&i| rows[i].as_slice()).collect();
    certify(&basis, c_int, &plain, 0.0, |k| {
        irow_from_f64(&rows[order[k]][..d], rows[order[k]][d])
    })
}

/// The exact LP over `n` integer rows `exact(k)` (inserted in the order `k = 0, 1, …`;
/// `ids[k]` the input index) maximizing `objective`: first the `f64` run over `frows[k]`
/// (each within `eps` times its largest entry of a positive multiple of `exact(k)`) with
/// a certified basis, else [`run_exact`]. The same answer either way.
pub(crate) fn run_fast_then_exact(
    frows: &[&[f64]],
    eps: f64,
    exact: impl Fn(usize) -> IRow,
    ids: &[usize],
    objective: &[BigInt],
) -> Exact {
    let d = objective.len();
    let mut rows = Rows::new(d, frows.len());
    for (k, r) in frows.iter().enumerate() {
        rows.push(r[..d].iter().copied(), Mq::finite(r[d]), Some(k));
    }
    let c: Vec<f64> = f64_row(&IRow {
        a: objective.to_vec(),
        b: <BigInt as Zero>::zero(),
    });
    if let Ok(v) = solve(&rows, &objectives(c[..d].to_vec())) {
        if let Some(basis) = v.basis.iter().copied().collect::<Option<Vec<usize>>>() {
            if let Some(cert) = certify(&basis, objective, frows, eps, &exact) {
                let x = cert
                    .x
                    .iter()
                    .map(|v| Q::new(v.clone(), cert.w.clone()))
                    .collect();
                return Exact::Solved {
                    x,
                    ray: vec![Q::zero(); d],
                    grows: false,
                    hom: Some((cert.x, cert.w)),
                };
            }
        }
    }
    let all: Vec<IRow> = (0..frows.len()).map(exact).collect();
    run_exact(&all, ids, objective)
}

/// The exact outcome of [`run_exact`].
pub(crate) enum Exact {
    /// Input constraints that contradict.
    Infeasible(Vec<usize>),
    /// `x` feasible; `ray` the direction the symbolic optimum moves along (zero when the
    /// lexicographic optimum is finite); `grows` when the objective increases along it.
    Solved {
        x: Vec<Q>,
        ray: Vec<Q>,
        grows: bool,
        /// `x` as `X / W` (`W > 0`) when `ray` is zero.
        hom: Option<(Vec<BigInt>, BigInt)>,
    },
}

/// Exact randomized LP over the integer constraints `rows` (inserted in this order; `ids`
/// their input indices) maximizing `objective`: `x` is the lexicographically smallest
/// optimum when it exists, else a feasible point on the ray.
pub(crate) fn run_exact(rows: &[IRow], ids: &[usize], objective: &[BigInt]) -> Exact {
    let mut cons = Rows::new(objective.len(), rows.len());
    for (r, &id) in rows.iter().zip(ids) {
        cons.push(r.a.iter().cloned(), Mq::finite(r.b.clone()), Some(id));
    }
    let v = match solve(&cons, &objectives(objective.to_vec())) {
        Ok(v) => v,
        Err(cert) => {
            let mut certificate: Vec<usize> = cert.into_iter().flatten().collect();
            certificate.sort_unstable();
            certificate.dedup();
            return Exact::Infeasible(certificate);
        }
    };
    let w = &v.w;
    let v1: Vec<Q> = v.x.iter().map(|x| Q::new(x.m.clone(), w.clone())).collect();
    let grow: BigInt = objective.iter().zip(&v.x).map(|(a, b)| a * &b.m).sum();
    if v1.iter().all(|q| q.is_zero()) {
        let x = v.x.iter().map(|x| Q::new(x.c.clone(), w.clone())).collect();
        let hom = Some((v.x.iter().map(|x| x.c.clone()).collect(), w.clone()));
        return Exact::Solved {
            x,
            ray: v1,
            grows: false,
            hom,
        };
    }
    // X.c / W + t·X.m / W is feasible for all large t: the smallest such t >= 0, from
    // a·X.c - b·W + t·(a·X.m) <= 0 for each constraint with a·X.m < 0.
    let mut t = Q::zero();
    for g in rows {
        let slope: BigInt = g.a.iter().zip(&v.x).map(|(a, b)| a * &b.m).sum();
        if slope.is_negative() {
            let at0: BigInt =
                g.a.iter().zip(&v.x).map(|(a, b)| a * &b.c).sum::<BigInt>() - &g.b * w;
            let need = Q::new(at0, -slope);
            if need > t {
                t = need;
            }
        }
    }
    let x: Vec<Q> =
        v.x.iter()
            .zip(&v1)
            .map(|(a, b)| Q::new(a.c.clone(), w.clone()) + &t * b)
            .collect();
    Exact::Solved {
        x,
        ray: v1,
        grows: grow.is_positive(),
        hom: None,
    }
}
