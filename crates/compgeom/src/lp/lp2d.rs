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
//! # Speed
//!
//! Every decision is exact, but almost all are made in plain `f64`: the current optimum
//! is kept as its three 2×2 minors with static error bounds (`filter::Meet`), so the test
//! "is the optimum inside the next constraint" is one three-term dot product and one
//! three-term bound; each 1D re-solve runs the same test against the interval end it may
//! replace, choosing that end without a branch (the side a constraint bounds is a coin
//! flip, a mispredicted branch cost more than the arithmetic). Only undecided tests go to
//! the filtered exact predicates of `exact`. Vertices on the symbolic box are tested by
//! the exact sign of their leading `M` coefficient. Large inputs are shuffled bucket-wise
//! (Rao–Sandelius) so that the random order is drawn in cache. Measured (bench `lp`): about
//! 25 ns per constraint, linear from 1e5 to 1e6 constraints.
//!
//! # Which optimum
//!
//! When several points are optimal, the answer is the **lexicographically smallest
//! optimal vertex** (smallest x, then smallest y) — the book's rule. (When the optimal set is
//! a ray that runs toward smaller x, its apex is the only optimal vertex and is reported;
//! when it is a whole line, the point of that line nearest the origin is reported.)

use super::exact::U;
use super::exact::{
    cross2_sign, cross_sign, meet_exact, parallel_side, rat, side, to_f64, Filt, Line, Num,
};
use super::filter::{coefficients_in_range, cross_in_range, Meet};
use super::{HalfPlane, Shuffler};
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

/// A vertex: the two lines (indices: 0..4 the box sides, `4 + k` the input row `k`) that
/// meet there.
type Vertex = (usize, usize);

/// One end of the interval of a 1D LP: the line bounding it and the fast form of its
/// meeting point with the line of the 1D LP (`None` for a box side or when the filter
/// does not apply).
#[derive(Clone, Copy)]
struct Bound {
    id: usize,
    meet: Option<Meet>,
}

/// The coefficients of a row as a tuple, for [`Meet`].
#[inline]
fn abc(h: &HalfPlane) -> (f64, f64, f64) {
    (h.a, h.b, h.c)
}

struct Solver {
    /// The input constraints with non-zero normals, in insertion (shuffled) order; line
    /// `4 + k` is `rows[k]`, lines 0..4 are the sides of the symbolic box.
    rows: Vec<HalfPlane>,
    /// Input index of `rows[k]`.
    orig: Vec<usize>,
    /// Use the static `f64` filters ([`Meet`], [`cross_in_range`]) where they apply;
    /// false runs every decision through the filtered exact predicates of `exact` (the
    /// reference the tests compare the fast path with).
    fast: bool,
    /// Every row's coefficients are in the static filters' range (else each row is
    /// checked before the fast tests are used on it).
    all_in_range: bool,
    cx: f64,
    cy: f64,
}

impl Solver {
    /// Line `k` (a box side or an input row) for the exact predicates.
    #[inline]
    fn line(&self, k: usize) -> Line {
        if k < 4 {
            Line::bbox()[k]
        } else {
            let h = &self.rows[k - 4];
            Line::input(h.a, h.b, h.c)
        }
    }

    /// True when the fast filters may be used on row `h`.
    #[inline(always)]
    fn in_range(&self, h: &HalfPlane) -> bool {
        self.fast && (self.all_in_range || coefficients_in_range(h.a, h.b, h.c))
    }

    /// The fast form of vertex `v`, when both lines are input rows in range.
    #[inline]
    fn meet(&self, v: Vertex) -> Option<Meet> {
        if !self.fast || v.0 < 4 || v.1 < 4 {
            return None;
        }
        Meet::new(abc(&self.rows[v.0 - 4]), abc(&self.rows[v.1 - 4]))
    }

    /// Where vertex `v` (with its fast form `m`, if any) lies relative to line `k`, exactly.
    #[inline(always)]
    fn side(&self, v: Vertex, m: Option<&Meet>, k: usize) -> Ordering {
        if let Some(m) = m {
            // (`m` exists only on the fast path.)
            if k >= 4 {
                let h = &self.rows[k - 4];
                if self.all_in_range || coefficients_in_range(h.a, h.b, h.c) {
                    if let Some(s) = m.side(h.a, h.b, h.c) {
                        return s;
                    }
                }
            }
        }
        self.side_exact(v, k)
    }

    #[inline(never)]
    fn side_exact(&self, v: Vertex, k: usize) -> Ordering {
        if self.fast && k >= 4 && (v.0 < 4 || v.1 < 4) {
            return self.side_on_box(v, k);
        }
        side(&self.line(v.0), &self.line(v.1), &self.line(k))
    }

    /// [`Solver::side`] for a vertex on the symbolic box and an input row `k`, by the
    /// leading coefficient in `M` and then the constant term, each a sign decided exactly
    /// (an unbounded LP keeps such a vertex while every row is tested).
    ///
    /// - A box corner `(σM, τM)`: `a_k·σM + b_k·τM - c_k`; the sign of the `f64` sum
    ///   `σ·a_k + τ·b_k` is exact (rounding is monotone and keeps zero), then `-c_k`.
    /// - The meeting point of row `i` and `x = σM` (`b_i != 0`): `x = σM`,
    ///   `y = (c_i - a_i·σM) / b_i`, so the test is the sign of
    ///   `σM·(a_k·b_i - b_k·a_i) + (b_k·c_i - c_k·b_i)` times the sign of `b_i`; with
    ///   `y = τM` (`a_i != 0`) the roles of `a` and `b` swap. The two minors are exact signs.
    fn side_on_box(&self, v: Vertex, k: usize) -> Ordering {
        let h = &self.rows[k - 4];
        // σ of box side 0, 1 (x <= M, -x <= M) and τ of 2, 3 (y <= M, -y <= M).
        let sign_of = |b: usize| if b % 2 == 0 { 1.0 } else { -1.0 };
        let then = |lead: Ordering, rest: Ordering| match lead {
            Ordering::Equal => rest,
            o => o,
        };
        let sgn = |x: f64| {
            if x > 0.0 {
                Ordering::Greater
            } else if x < 0.0 {
                Ordering::Less
            } else {
                Ordering::Equal
            }
        };
        if v.0 < 4 && v.1 < 4 {
            let (xs, ys) = if v.0 < 2 { (v.0, v.1) } else { (v.1, v.0) };
            if xs >= 2 || ys < 2 {
                // (Two parallel box sides meet nowhere; never asked.)
                return side(&self.line(v.0), &self.line(v.1), &self.line(k));
            }
            let lead = sign_of(xs) * h.a + sign_of(ys) * h.b;
            return then(sgn(lead), sgn(-h.c));
        }
        let (bx, i) = if v.0 < 4 { (v.0, v.1) } else { (v.1, v.0) };
        let r = &self.rows[i - 4];
        if (bx < 2 && r.b == 0.0) || (bx >= 2 && r.a == 0.0) {
            // (Parallel to the box side: no meeting point; never asked.)
            return side(&self.line(v.0), &self.line(v.1), &self.line(k));
        }
        let minor = |p: f64, q: f64, r2: f64, s2: f64| -> Ordering {
            // The sign of p·q - r2·s2.
            if self.all_in_range {
                if let Some(o) = cross_in_range(p, s2, r2, q) {
                    return o;
                }
            }
            cross2_sign(p, s2, r2, q)
        };
        let (lead, rest, den) = if bx < 2 {
            (minor(h.a, r.b, h.b, r.a), minor(h.b, r.c, h.c, r.b), r.b)
        } else {
            (minor(h.b, r.a, h.a, r.b), minor(h.a, r.c, h.c, r.a), r.a)
        };
        let lead = if sign_of(bx) < 0.0 {
            lead.reverse()
        } else {
            lead
        };
        let s = then(lead, rest);
        if den < 0.0 {
            s.reverse()
        } else {
            s
        }
    }

    /// The exact sign of the cross product of the normals of lines `i` and `j`.
    #[inline(always)]
    fn cross(&self, i: usize, j: usize) -> Ordering {
        if i >= 4 && j >= 4 {
            let (hi, hj) = (&self.rows[i - 4], &self.rows[j - 4]);
            if self.in_range(hi) && self.in_range(hj) {
                if let Some(s) = cross_in_range(hi.a, hi.b, hj.a, hj.b) {
                    return s;
                }
            }
        }
        self.cross_exact(i, j)
    }

    #[inline(never)]
    fn cross_exact(&self, i: usize, j: usize) -> Ordering {
        cross_sign(&self.line(i), &self.line(j))
    }

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

    /// Run the incremental algorithm (box sides first, then the rows in order).
    fn run(&self, s: f64) -> std::result::Result<Vertex, Vec<usize>> {
        let mut v = self.corner(s);
        let mut m = self.meet(v);
        let quick = self.fast && self.all_in_range;
        for k in 4..4 + self.rows.len() {
            if quick {
                if let Some(f) = &m {
                    // The common case, decided by the static filter: the optimum stays.
                    let h = &self.rows[k - 4];
                    let (val, err) = f.value(h.a, h.b, h.c);
                    if -val > err {
                        continue;
                    }
                }
            }
            if self.side(v, m.as_ref(), k) == Ordering::Greater {
                (v, m) = self.solve_1d(k, s)?;
            }
        }
        Ok(v)
    }

    /// The best point on line `i` subject to the box and the rows before it (§4.3's 1D
    /// LP), with its fast form.
    ///
    /// Along the line, points are `p(t)` for the direction `u = (b_i, -a_i)`; a constraint
    /// `j` with `cross(i, j) < 0` bounds `t` from above at its meeting point `t_j`, one with
    /// `cross(i, j) > 0` from below. The bound `h` kept so far is replaced by `j` exactly
    /// when `t_j` is strictly tighter, i.e. when the vertex `(i, h)` lies strictly outside
    /// `j`: one vertex test, as in the main loop. The box sides come first and bound every
    /// line from both sides; the first input row bounding a side replaces the box side (its
    /// meeting point is finite).
    fn solve_1d(
        &self,
        i: usize,
        s: f64,
    ) -> std::result::Result<(Vertex, Option<Meet>), Vec<usize>> {
        let li = self.line(i);
        // Go up (increasing t) if the objective, or else the tie-break, grows along u.
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
        // `b[0]` bounds t from below, `b[1]` from above: a line and the fast form of its
        // meeting point with line i. The box sides first, exactly (all symbolic).
        let mut b: [Option<Bound>; 2] = [None, None];
        for j in 0..4 {
            self.step_box(&li, i, j, &mut b)?;
        }
        // (The box bounds every line with a non-zero normal from both sides.)
        let [Some(lo), Some(hi)] = b else {
            return Err(self.inputs(&[i]));
        };
        let mut b = [lo, hi];
        if self.fast && self.all_in_range {
            self.scan_quick(i, &mut b)?;
        } else {
            for j in 4..i {
                self.step(&li, i, j, &mut b)?;
            }
        }
        let [lo, hi] = b;
        // Empty when the lower bound's meeting point lies strictly beyond the upper one.
        if self.side((i, lo.id), lo.meet.as_ref(), hi.id) == Ordering::Greater {
            return Err(self.inputs(&[i, lo.id, hi.id]));
        }
        let best = if up { hi } else { lo };
        Ok(((i, best.id), best.meet))
    }

    /// A box side `j` as a bound on line `i` (exact; the box sides are symbolic).
    fn step_box(
        &self,
        li: &Line,
        i: usize,
        j: usize,
        b: &mut [Option<Bound>; 2],
    ) -> std::result::Result<(), Vec<usize>> {
        let lj = self.line(j);
        let t = match cross_sign(li, &lj) {
            Ordering::Less => 1,
            Ordering::Greater => 0,
            Ordering::Equal => {
                if parallel_side(li, &lj) == Ordering::Greater {
                    return Err(self.inputs(&[i, j]));
                }
                return Ok(());
            }
        };
        let keep = matches!(&b[t], Some(h) if side(li, &lj, &self.line(h.id)) != Ordering::Less);
        if !keep {
            b[t] = Some(Bound { id: j, meet: None });
        }
        Ok(())
    }

    /// Row `j` as a bound on line `i`, every decision exact (filtered where possible).
    #[inline]
    fn step(
        &self,
        li: &Line,
        i: usize,
        j: usize,
        b: &mut [Bound; 2],
    ) -> std::result::Result<(), Vec<usize>> {
        let t = match self.cross(i, j) {
            // nj·u = -(ai·bj - aj·bi) > 0: j bounds t from above.
            Ordering::Less => 1,
            Ordering::Greater => 0,
            Ordering::Equal => {
                if parallel_side(li, &self.line(j)) == Ordering::Greater {
                    return Err(self.inputs(&[i, j]));
                }
                return Ok(());
            }
        };
        let h = b[t];
        if h.id < 4 || self.side((i, h.id), h.meet.as_ref(), j) == Ordering::Greater {
            b[t] = Bound {
                id: j,
                meet: self.meet((i, j)),
            };
        }
        Ok(())
    }

    /// The rows before line `i` as bounds on it, when every row is in the static filters'
    /// range: the cross product and the vertex test in plain `f64` with their static
    /// bounds, branch-free in which side is bounded (that is a coin flip per row); any row
    /// the filters cannot settle goes through [`Solver::step`].
    fn scan_quick(&self, i: usize, b: &mut [Bound; 2]) -> std::result::Result<(), Vec<usize>> {
        let li = self.line(i);
        let (ai, bi) = (li.a, li.b);
        // The error of `ai·bj - aj·bi` is at most `2u·(|ai·bj| + |aj·bi|)·(1 + u)`.
        const CROSS: f64 = 3.0 * U * (1.0 + 8.0 * U);
        for (k, h) in self.rows[..i - 4].iter().enumerate() {
            let (p, q) = (ai * h.b, h.a * bi);
            let d = p - q;
            if d.abs() > (p.abs() + q.abs()) * CROSS {
                let t = (d < 0.0) as usize;
                if let Some(m) = &b[t].meet {
                    let (v, e) = m.value(h.a, h.b, h.c);
                    if -v > e {
                        continue; // (i, b[t]) is strictly inside row k: nothing changes.
                    }
                    if v > e {
                        b[t] = Bound {
                            id: k + 4,
                            meet: Meet::new(abc(&self.rows[i - 4]), abc(h)),
                        };
                        continue;
                    }
                } else if b[t].id < 4 {
                    b[t] = Bound {
                        id: k + 4,
                        meet: Meet::new(abc(&self.rows[i - 4]), abc(h)),
                    };
                    continue;
                }
            }
            self.step(&li, i, k + 4, b)?;
        }
        Ok(())
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
        let ((x, y), _) = meet_exact(&self.line(v.0), &self.line(v.1));
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
    solve(constraints, objective, options, true)
}

/// As [`lp2d`], with every decision made by the filtered exact predicates alone (no static
/// `f64` filter): the reference the fast path is tested against. Same answer, including
/// which certificate is reported.
#[doc(hidden)]
pub fn lp2d_exact(
    constraints: &[HalfPlane],
    objective: Vector2,
    options: &Lp2Options,
) -> Result<Lp2Solution> {
    solve(constraints, objective, options, false)
}

fn solve(
    constraints: &[HalfPlane],
    objective: Vector2,
    options: &Lp2Options,
    fast: bool,
) -> Result<Lp2Solution> {
    // One pass: non-finite numbers are errors (the first one named), zero normals are
    // always true (`0 <= c`, dropped) or always false (`c < 0`: infeasible by itself); for
    // large inputs the same pass draws each row's bucket of the shuffle.
    let mut shuffle = Shuffle::new(constraints.len(), options.seed);
    let mut zero_infeasible = None;
    let mut all_in_range = true;
    for (k, h) in constraints.iter().enumerate() {
        for v in [h.a, h.b, h.c] {
            if !v.is_finite() {
                return Err(Error::NonFinite {
                    what: format!("constraint {k}"),
                    value: v,
                });
            }
        }
        if h.a == 0.0 && h.b == 0.0 {
            if h.c < 0.0 && zero_infeasible.is_none() {
                zero_infeasible = Some(k);
            }
            shuffle.skip();
            continue;
        }
        all_in_range &= coefficients_in_range(h.a, h.b, h.c);
        shuffle.keep();
    }
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
    if let Some(k) = zero_infeasible {
        return Ok(Lp2Solution::Infeasible {
            certificate: vec![k],
        });
    }
    let (rows, orig) = shuffle.apply(constraints);
    let solver = Solver {
        rows,
        orig,
        fast,
        all_in_range,
        cx: objective.x,
        cy: objective.y,
    };

    let v = match solver.run(-1.0) {
        Ok(v) => v,
        Err(certificate) => return Ok(Lp2Solution::Infeasible { certificate }),
    };
    if v.0 >= 4 && v.1 >= 4 {
        return Ok(solver.optimal(v));
    }
    let ((x0, y0), (x1, y1)) = meet_exact(&solver.line(v.0), &solver.line(v.1));
    let grow = solver.objective(&x1, &y1);
    if grow.is_positive() {
        return Ok(unbounded(&solver, v, (x0, y0), (x1, y1)));
    }
    // The objective is bounded but the optimal set runs off toward smaller x (or y):
    // its apex, if any, is the lexicographically largest optimal point.
    if let Ok(w) = solver.run(1.0) {
        if w.0 >= 4 && w.1 >= 4 {
            return Ok(solver.optimal(w));
        }
    }
    // The optimal set is a whole line: the input line through the vertex.
    let k = if v.0 < 4 { v.1 } else { v.0 };
    let lk = &solver.line(k);
    let (a, b, c) = (rat(lk.a), rat(lk.b), rat(lk.c));
    let nn = &a * &a + &b * &b;
    let (x, y) = (&c * &a / &nn, &c * &b / &nn);
    Ok(Lp2Solution::Optimal {
        point: Point2::new(to_f64(&x), to_f64(&y)),
        value: to_f64(&solver.objective(&x, &y)),
        constraints: solver.inputs(&[k]),
    })
}

/// Below this many constraints a plain Fisher–Yates shuffle runs in cache anyway.
const BUCKETED_MIN: usize = 1 << 14;

/// The random insertion order of the constraints with non-zero normals, fixed by a seed.
///
/// The constraints are stored in that order (not an index list) so that every 1D scan over
/// the earlier constraints reads memory in order. A Fisher–Yates shuffle of a large array
/// misses the cache on almost every swap; from [`BUCKETED_MIN`] constraints on, the order
/// is drawn as Rao and Sandelius do instead: every row goes to one of `B` buckets chosen
/// uniformly and independently (drawn while the input is validated, then one sequential
/// pass writing `B` streams), and each bucket, small enough for the cache, is shuffled by
/// Fisher–Yates. Bucket sizes are then multinomial and each bucket's order is uniform,
/// which makes the whole permutation uniform.
struct Shuffle {
    rng: Shuffler,
    /// `log2 B` (0: plain Fisher–Yates).
    bits: u32,
    /// Bucket of every input constraint (`B` for a dropped one); empty when `bits == 0`.
    which: Vec<u16>,
    /// Rows per bucket.
    count: Vec<usize>,
    kept: usize,
}

impl Shuffle {
    fn new(n: usize, seed: u64) -> Shuffle {
        // About 4096 rows (128 KiB with their indices) per bucket, at most 4096 buckets.
        let bits = if n < BUCKETED_MIN {
            0
        } else {
            (n / 4096).next_power_of_two().trailing_zeros().clamp(1, 12)
        };
        Shuffle {
            rng: Shuffler::new(seed),
            bits,
            which: Vec::with_capacity(if bits > 0 { n } else { 0 }),
            count: vec![0; (1 << bits) + 1],
            kept: 0,
        }
    }

    /// The next input constraint is dropped.
    #[inline]
    fn skip(&mut self) {
        if self.bits > 0 {
            self.which.push(1 << self.bits);
        }
    }

    /// The next input constraint is a row: draw its bucket.
    #[inline]
    fn keep(&mut self) {
        self.kept += 1;
        if self.bits > 0 {
            let b = (self.rng.next() >> (64 - self.bits)) as usize;
            self.which.push(b as u16);
            self.count[b] += 1;
        }
    }

    /// The kept constraints in the random order, with their input indices.
    fn apply(mut self, constraints: &[HalfPlane]) -> (Vec<HalfPlane>, Vec<usize>) {
        let nonzero = |h: &HalfPlane| h.a != 0.0 || h.b != 0.0;
        let mut rows = Vec::with_capacity(self.kept);
        let mut orig = Vec::with_capacity(self.kept);
        if self.bits == 0 {
            for (k, h) in constraints.iter().enumerate() {
                if nonzero(h) {
                    rows.push(*h);
                    orig.push(k);
                }
            }
            fisher_yates(&mut self.rng, &mut rows, &mut orig);
            return (rows, orig);
        }
        let buckets = 1usize << self.bits;
        // Bucket b fills [start[b], start[b + 1]).
        let mut start = Vec::with_capacity(buckets + 1);
        let mut sum = 0;
        for &c in &self.count[..buckets] {
            start.push(sum);
            sum += c;
        }
        start.push(sum);
        rows.resize(self.kept, HalfPlane::new(0.0, 0.0, 0.0));
        orig.resize(self.kept, 0);
        let mut at = start.clone();
        for (k, (h, &b)) in constraints.iter().zip(&self.which).enumerate() {
            let b = b as usize;
            if b < buckets {
                rows[at[b]] = *h;
                orig[at[b]] = k;
                at[b] += 1;
            }
        }
        for b in 0..buckets {
            let r = start[b]..start[b + 1];
            let (rs, os) = (&mut rows[r.clone()], &mut orig[r]);
            // Read the bucket in order first: the prefetcher brings it into the cache
            // faster than the shuffle's random accesses would.
            let warm = rs.iter().fold(0.0, |s, h| s + h.c) + os.iter().sum::<usize>() as f64;
            std::hint::black_box(warm);
            fisher_yates(&mut self.rng, rs, os);
        }
        (rows, orig)
    }
}

/// Shuffle `rows` uniformly, applying the same swaps to `orig`.
fn fisher_yates(rng: &mut Shuffler, rows: &mut [HalfPlane], orig: &mut [usize]) {
    for i in (1..rows.len()).rev() {
        let j = rng.below(i + 1);
        rows.swap(i, j);
        orig.swap(i, j);
    }
}

/// The unbounded answer for a final vertex `v0 + M·v1` on the box.
fn unbounded(
    solver: &Solver,
    v: Vertex,
    (x0, y0): (BigRational, BigRational),
    (x1, y1): (BigRational, BigRational),
) -> Lp2Solution {
    // An exact f64 direction parallel to v1: a box diagonal, or the input line's direction.
    let direction = if v.0 < 4 && v.1 < 4 {
        Vector2::new(
            if x1.is_negative() { -1.0 } else { 1.0 },
            if y1.is_negative() { -1.0 } else { 1.0 },
        )
    } else {
        let k = &solver.line(if v.0 < 4 { v.1 } else { v.0 });
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
    for li in &solver.rows {
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
        for li in &solver.rows {
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
        // A line direction `(-b, a)` can carry a negative zero; `+ 0.0` makes it `0.0`
        // (and changes nothing else), so output does not show `-0.0`.
        direction: Vector2::new(direction.x + 0.0, direction.y + 0.0),
    }
}
