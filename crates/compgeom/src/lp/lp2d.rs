//! Two-dimensional linear programming (book §4.3–4.4): 2DRANDOMIZEDBOUNDEDLP with the
//! unbounded case handled by a symbolic bounding box.
//!
//! Maximize `c·p` subject to half-planes `a·x + b·y <= c`. The constraints are added in a
//! random order (a seeded generator: the same seed gives the same run); the current optimum
//! stays put while it satisfies the next constraint, and otherwise the new optimum is found
//! by a one-dimensional LP on the new constraint's line against all earlier ones
//! (expected O(n) in total, Theorem 4.10).
//!
//! Instead of the book's separate unboundedness test, the four sides of a *symbolic* box
//! `|x|, |y| <= M` (with `M` larger than any finite number) are inserted first. The problem
//! is then always bounded; if the final optimum still lies on the box and the objective
//! grows with `M`, the LP is unbounded, and the box corner's direction is a ray along which
//! the objective grows without bound.
//!
//! # Which optimum
//!
//! When several points are optimal, the answer is the **lexicographically smallest
//! optimal vertex** (smallest x, then smallest y) — the book's rule. (When the optimal set is
//! a ray that runs toward smaller x, its apex is the only optimal vertex and is reported;
//! when it is a whole line, the point of that line nearest the origin is reported.)

use super::exact::{
    cross2_sign, cross_sign, meet_exact, parallel_side, rat, side, to_f64, Filt, Line, Num,
    VertexFilter,
};
use super::{check_finite, HalfPlane, Shuffler};
use crate::kernel::{Point2, Vector2};
use crate::{Error, Result};
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

/// Options for [`lp2d`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Lp2Options {
    /// Seed of the random insertion order (the answer does not depend on it; the running
    /// time does, in expectation only).
    pub seed: u64,
}

impl Default for Lp2Options {
    fn default() -> Self {
        Lp2Options { seed: 0x5eed }
    }
}

/// The outcome of a two-dimensional linear program.
#[derive(Debug, Clone, PartialEq)]
pub enum Lp2Solution {
    /// A finite optimum.
    Optimal {
        /// The optimal point (lexicographically smallest optimal vertex), nearest `f64`.
        point: Point2,
        /// The objective value there, nearest `f64` of the exact value.
        value: f64,
        /// The input constraints whose lines define `point` (two, or one when the optimal
        /// set is a whole line).
        constraints: Vec<usize>,
    },
    /// The objective grows without bound.
    Unbounded {
        /// A feasible point (nearest `f64` of an exact feasible point) from which
        /// `direction` stays feasible.
        point: Point2,
        /// A direction `d` with `c·d > 0` and `a_i·d <= 0` for every constraint (exact:
        /// either a constraint line's direction or a box diagonal `(±1, ±1)`).
        direction: Vector2,
    },
    /// No point satisfies all constraints.
    Infeasible {
        /// Input constraints (one, two or three) that alone have no common point.
        certificate: Vec<usize>,
    },
}

/// A vertex: the two lines (indices into the solver's line list) that meet there.
type Vertex = (usize, usize);

struct Solver {
    /// Box sides 0..4, then the input constraints with non-zero normals.
    lines: Vec<Line>,
    /// Input index of `lines[4 + k]`.
    orig: Vec<usize>,
    cx: f64,
    cy: f64,
}

impl Solver {
    /// The start vertex: the corner of the box that is best for the objective, ties broken
    /// toward the tie-break direction `s·(x, y)` (`s = -1`: lexicographically smallest).
    fn corner(&self, s: f64) -> Vertex {
        let pick = |c: f64, plus: usize, minus: usize| {
            if c > 0.0 || (c == 0.0 && s > 0.0) {
                plus
            } else {
                minus
            }
        };
        (pick(self.cx, 0, 1), pick(self.cy, 2, 3))
    }

    /// Run the incremental algorithm over `order` (box sides first).
    fn run(&self, order: &[usize], s: f64) -> std::result::Result<Vertex, Vec<usize>> {
        let l = &self.lines;
        let mut v = self.corner(s);
        let mut fast = VertexFilter::new(&l[v.0], &l[v.1]);
        for pos in 4..order.len() {
            let i = order[pos];
            let out = match fast.as_ref().and_then(|f| f.side(&l[i])) {
                Some(o) => o,
                None => side(&l[v.0], &l[v.1], &l[i]),
            };
            if out == Ordering::Greater {
                v = self.solve_1d(i, &order[..pos], s)?;
                fast = VertexFilter::new(&l[v.0], &l[v.1]);
            }
        }
        Ok(v)
    }

    /// The best point on line `i` subject to the constraints `prev` (§4.3's 1D LP).
    fn solve_1d(
        &self,
        i: usize,
        prev: &[usize],
        s: f64,
    ) -> std::result::Result<Vertex, Vec<usize>> {
        let l = &self.lines;
        let li = &l[i];
        // Direction along the line: u = (b, -a). Go up (increasing t) if the objective, or
        // else the tie-break, grows along u.
        let up = match cross2_sign(self.cx, self.cy, li.a, li.b) {
            Ordering::Equal => {
                if li.b != 0.0 {
                    (s * li.b) > 0.0
                } else {
                    (s * -li.a) > 0.0
                }
            }
            o => o == Ordering::Greater,
        };
        let (mut lo, mut hi): (Option<usize>, Option<usize>) = (None, None);
        for &j in prev {
            let lj = &l[j];
            match cross_sign(li, lj) {
                // nj·u = -(ai·bj - aj·bi) > 0: j bounds t from above.
                Ordering::Less => {
                    hi = Some(match hi {
                        Some(h) if side(li, lj, &l[h]) != Ordering::Less => h,
                        _ => j,
                    });
                }
                Ordering::Greater => {
                    lo = Some(match lo {
                        Some(h) if side(li, lj, &l[h]) != Ordering::Less => h,
                        _ => j,
                    });
                }
                Ordering::Equal => {
                    if parallel_side(li, lj) == Ordering::Greater {
                        return Err(self.inputs(&[i, j]));
                    }
                }
            }
        }
        match (lo, hi) {
            (Some(a), Some(b)) => {
                if side(li, &l[a], &l[b]) == Ordering::Greater {
                    return Err(self.inputs(&[i, a, b]));
                }
                Ok(if up { (i, b) } else { (i, a) })
            }
            // The box bounds every line from both sides; kept total for safety.
            (Some(a), None) => Ok((i, a)),
            (None, Some(b)) => Ok((i, b)),
            (None, None) => Err(self.inputs(&[i])),
        }
    }

    /// Input indices of the non-box lines among `ls`.
    fn inputs(&self, ls: &[usize]) -> Vec<usize> {
        let mut v: Vec<usize> = ls
            .iter()
            .filter(|&&k| k >= 4)
            .map(|&k| self.orig[k - 4])
            .collect();
        v.sort_unstable();
        v.dedup();
        v
    }

    fn objective(&self, x: &BigRational, y: &BigRational) -> BigRational {
        rat(self.cx) * x + rat(self.cy) * y
    }

    /// A finite optimal vertex as the answer.
    fn optimal(&self, v: Vertex) -> Lp2Solution {
        let ((x, y), _) = meet_exact(&self.lines[v.0], &self.lines[v.1]);
        Lp2Solution::Optimal {
            point: Point2::new(to_f64(&x), to_f64(&y)),
            value: to_f64(&self.objective(&x, &y)),
            constraints: self.inputs(&[v.0, v.1]),
        }
    }
}

/// Solve the linear program: maximize `objective · p` subject to every half-plane.
///
/// Errors: a non-finite coefficient ([`Error::NonFinite`]), or a zero or non-finite
/// objective ([`Error::InvalidInput`]; use [`intersect_halfplanes`](super::intersect_halfplanes)
/// for feasibility).
///
/// ```
/// use compgeom::lp::{lp2d, HalfPlane, Lp2Options, Lp2Solution};
/// use compgeom::{Point2, Vector2};
/// // x <= 2, y <= 3, x + y <= 4: maximize x + y; the optimal edge runs from (1, 3) to (2, 2).
/// let hs = [HalfPlane::new(1.0, 0.0, 2.0), HalfPlane::new(0.0, 1.0, 3.0), HalfPlane::new(1.0, 1.0, 4.0)];
/// match lp2d(&hs, Vector2::new(1.0, 1.0), &Lp2Options::default())? {
///     Lp2Solution::Optimal { point, value, .. } => {
///         assert_eq!(point, Point2::new(1.0, 3.0)); // lexicographically smallest
///         assert_eq!(value, 4.0);
///     }
///     other => panic!("{other:?}"),
/// }
/// // Without x + y <= 4 but maximizing x - y the problem is unbounded (y -> -inf).
/// let r = lp2d(&hs[..2], Vector2::new(1.0, -1.0), &Lp2Options::default())?;
/// assert!(matches!(r, Lp2Solution::Unbounded { .. }));
/// # Ok::<(), compgeom::Error>(())
/// ```
pub fn lp2d(
    constraints: &[HalfPlane],
    objective: Vector2,
    options: &Lp2Options,
) -> Result<Lp2Solution> {
    check_finite(constraints)?;
    if !(objective.x.is_finite() && objective.y.is_finite()) {
        return Err(Error::InvalidInput(
            "the objective has a non-finite coefficient".into(),
        ));
    }
    if objective.x == 0.0 && objective.y == 0.0 {
        return Err(Error::InvalidInput(
            "the objective is zero (for feasibility, intersect the half-planes)".into(),
        ));
    }
    let mut lines = Line::bbox().to_vec();
    let mut orig = Vec::with_capacity(constraints.len());
    for (k, h) in constraints.iter().enumerate() {
        if h.a == 0.0 && h.b == 0.0 {
            if h.c < 0.0 {
                return Ok(Lp2Solution::Infeasible {
                    certificate: vec![k],
                });
            }
            continue; // 0 <= c: always true.
        }
        lines.push(Line::input(h.a, h.b, h.c));
        orig.push(k);
    }
    // Shuffle the constraints themselves (not an index list) so that every 1D scan over the
    // earlier constraints reads memory in order.
    let mut perm: Vec<usize> = (0..orig.len()).collect();
    Shuffler::new(options.seed).shuffle(&mut perm);
    let lines: Vec<Line> = lines[..4]
        .iter()
        .copied()
        .chain(perm.iter().map(|&k| lines[4 + k]))
        .collect();
    let orig: Vec<usize> = perm.iter().map(|&k| orig[k]).collect();
    let solver = Solver {
        lines,
        orig,
        cx: objective.x,
        cy: objective.y,
    };
    let order: Vec<usize> = (0..solver.lines.len()).collect();

    let v = match solver.run(&order, -1.0) {
        Ok(v) => v,
        Err(certificate) => return Ok(Lp2Solution::Infeasible { certificate }),
    };
    let l = &solver.lines;
    if !l[v.0].is_box() && !l[v.1].is_box() {
        return Ok(solver.optimal(v));
    }
    let ((x0, y0), (x1, y1)) = meet_exact(&l[v.0], &l[v.1]);
    let grow = solver.objective(&x1, &y1);
    if grow.is_positive() {
        return Ok(unbounded(&solver, v, (x0, y0), (x1, y1)));
    }
    // The objective is bounded but the optimal set runs off toward smaller x (or y):
    // its apex, if any, is the lexicographically largest optimal point.
    if let Ok(w) = solver.run(&order, 1.0) {
        if !l[w.0].is_box() && !l[w.1].is_box() {
            return Ok(solver.optimal(w));
        }
    }
    // The optimal set is a whole line: the input line through the vertex.
    let k = if l[v.0].is_box() { v.1 } else { v.0 };
    let lk = &l[k];
    let (a, b, c) = (rat(lk.a), rat(lk.b), rat(lk.c));
    let nn = &a * &a + &b * &b;
    let (x, y) = (&c * &a / &nn, &c * &b / &nn);
    Ok(Lp2Solution::Optimal {
        point: Point2::new(to_f64(&x), to_f64(&y)),
        value: to_f64(&solver.objective(&x, &y)),
        constraints: solver.inputs(&[k]),
    })
}

/// The unbounded answer for a final vertex `v0 + M·v1` on the box.
fn unbounded(
    solver: &Solver,
    v: Vertex,
    (x0, y0): (BigRational, BigRational),
    (x1, y1): (BigRational, BigRational),
) -> Lp2Solution {
    let l = &solver.lines;
    // An exact f64 direction parallel to v1: a box diagonal, or the input line's direction.
    let direction = if l[v.0].is_box() && l[v.1].is_box() {
        Vector2::new(
            if x1.is_negative() { -1.0 } else { 1.0 },
            if y1.is_negative() { -1.0 } else { 1.0 },
        )
    } else {
        let k = if l[v.0].is_box() { &l[v.1] } else { &l[v.0] };
        let (dx, dy) = (k.b, -k.a);
        let along = rat(dx) * &x1 + rat(dy) * &y1;
        if along.is_negative() {
            Vector2::new(-dx, -dy)
        } else {
            Vector2::new(dx, dy)
        }
    };
    // v0 + M·v1 is feasible for every M >= need_k = (n_k·v0 - c_k) / (-n_k·v1) (for each k
    // with n_k·v1 < 0). Any M above all of them gives a feasible point: bound each need_k
    // from above in interval arithmetic and take the exact value only where the interval
    // of the denominator is not clearly positive (rare), so the pass stays O(n) in f64.
    let enclose = |q: &BigRational| {
        let v = to_f64(q);
        Filt::approx(v, v.abs() * f64::EPSILON + f64::MIN_POSITIVE)
    };
    let (fx0, fy0, fx1, fy1) = (enclose(&x0), enclose(&y0), enclose(&x1), enclose(&y1));
    let mut bound = 0.0f64;
    let mut m = BigRational::zero();
    for li in &l[4..] {
        let (a, b) = (Filt::val(li.a), Filt::val(li.b));
        let den = a.mul(&fx1).add(&b.mul(&fy1)); // n·v1: we need -den > 0
        let num = a.mul(&fx0).add(&b.mul(&fy0)).sub(&Filt::val(li.c));
        if den.upper() < 0.0 && num.upper().is_finite() {
            if num.upper() > 0.0 {
                // need <= num_hi / (-den_hi), rounded up.
                let q = num.upper() / (-den.upper());
                bound = bound.max(q + q.abs() * 4.0 * f64::EPSILON);
            }
            continue;
        }
        if den.lower() > 0.0 {
            continue; // n·v1 > 0 cannot happen for a feasible ray; nothing to bound.
        }
        let (a, b) = (rat(li.a), rat(li.b));
        let slope = &a * &x1 + &b * &y1;
        if slope.is_negative() {
            let need = (&a * &x0 + &b * &y0 - rat(li.c)) / (-slope);
            if need > m {
                m = need;
            }
        }
    }
    if bound.is_finite() {
        let b = rat(bound);
        if b > m {
            m = b;
        }
    } else {
        // The f64 bound overflowed: fall back to the exact maximum over all constraints.
        for li in &l[4..] {
            let (a, b) = (rat(li.a), rat(li.b));
            let slope = &a * &x1 + &b * &y1;
            if slope.is_negative() {
                let need = (&a * &x0 + &b * &y0 - rat(li.c)) / (-slope);
                if need > m {
                    m = need;
                }
            }
        }
    }
    let (x, y) = (&x0 + &m * &x1, &y0 + &m * &y1);
    Lp2Solution::Unbounded {
        point: Point2::new(to_f64(&x), to_f64(&y)),
        direction,
    }
}
