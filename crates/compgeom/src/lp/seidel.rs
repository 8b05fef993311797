//! The recursive randomized LP of book §4.5 (RANDOMIZEDLP), written once over a ring so it
//! runs both exactly (on integers) and as a fast `f64` heuristic.
//!
//! Points are kept in *homogeneous* form `x = X / W` (`W > 0`) and a violated constraint's
//! variable is eliminated fraction-free (`g' = h_p·g - g_p·h`), so the exact instance only
//! multiplies and adds integers: no rational normalisation (gcd) in the inner loop, and the
//! numbers grow with the recursion depth (at most `d`), never with the number of
//! constraints. Each coordinate carries a symbolic part: `c + m·M` with the symbolic box
//! `|x_j| <= M` (`M` larger than everything finite).
//!
//! The `f64` instance makes the same decisions approximately; its answer is only a
//! candidate basis, certified exactly in [`super::certify`].

use num_bigint::BigInt;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

/// The arithmetic the solver needs: a ring with a sign.
pub(crate) trait Ring: Clone {
    fn zero() -> Self;
    fn one() -> Self;
    fn add(&self, o: &Self) -> Self;
    fn sub(&self, o: &Self) -> Self;
    fn mul(&self, o: &Self) -> Self;
    fn neg(&self) -> Self;
    /// The sign (`f64`: NaN counts as zero; its answers are certified anyway).
    fn sign(&self) -> Ordering;
    /// Preference as a pivot (larger is better; zero never chosen).
    fn pivot_score(&self) -> f64;
}

impl Ring for BigInt {
    fn zero() -> Self {
        Zero::zero()
    }
    fn one() -> Self {
        BigInt::from(1)
    }
    fn add(&self, o: &Self) -> Self {
        self + o
    }
    fn sub(&self, o: &Self) -> Self {
        self - o
    }
    fn mul(&self, o: &Self) -> Self {
        self * o
    }
    fn neg(&self) -> Self {
        -self
    }
    fn sign(&self) -> Ordering {
        self.sign_cmp()
    }
    fn pivot_score(&self) -> f64 {
        // Exact: any non-zero pivot; the shortest keeps the numbers small.
        if self.is_zero() {
            0.0
        } else {
            1.0 / (1.0 + self.bits() as f64)
        }
    }
}

trait SignCmp {
    fn sign_cmp(&self) -> Ordering;
}

impl SignCmp for BigInt {
    fn sign_cmp(&self) -> Ordering {
        if self.is_positive() {
            Ordering::Greater
        } else if self.is_negative() {
            Ordering::Less
        } else {
            Ordering::Equal
        }
    }
}

impl Ring for f64 {
    fn zero() -> Self {
        0.0
    }
    fn one() -> Self {
        1.0
    }
    fn add(&self, o: &Self) -> Self {
        self + o
    }
    fn sub(&self, o: &Self) -> Self {
        self - o
    }
    fn mul(&self, o: &Self) -> Self {
        self * o
    }
    fn neg(&self) -> Self {
        -self
    }
    fn sign(&self) -> Ordering {
        if *self > 0.0 {
            Ordering::Greater
        } else if *self < 0.0 {
            Ordering::Less
        } else {
            Ordering::Equal
        }
    }
    fn pivot_score(&self) -> f64 {
        // Approximate: the largest pivot is the most stable (NaN is never chosen).
        let a = self.abs();
        if a > 0.0 {
            a
        } else {
            0.0
        }
    }
}

/// `c + m·M` with the symbolic `M`; ordered by `m` first.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Mq<R> {
    pub(crate) m: R,
    pub(crate) c: R,
}

impl<R: Ring> Mq<R> {
    pub(crate) fn finite(c: R) -> Self {
        Mq { m: R::zero(), c }
    }
    fn big(s: R) -> Self {
        Mq { m: s, c: R::zero() }
    }
    fn add(&self, o: &Self) -> Self {
        Mq {
            m: self.m.add(&o.m),
            c: self.c.add(&o.c),
        }
    }
    fn sub(&self, o: &Self) -> Self {
        Mq {
            m: self.m.sub(&o.m),
            c: self.c.sub(&o.c),
        }
    }
    fn scale(&self, s: &R) -> Self {
        Mq {
            m: self.m.mul(s),
            c: self.c.mul(s),
        }
    }
    fn neg(&self) -> Self {
        Mq {
            m: self.m.neg(),
            c: self.c.neg(),
        }
    }
    fn sign(&self) -> Ordering {
        match self.m.sign() {
            Ordering::Equal => self.c.sign(),
            s => s,
        }
    }
}

/// Constraints `a·x <= b` in `k` variables, stored flat; `id` is the input index, `None`
/// for a side of the symbolic box.
#[derive(Debug, Clone)]
pub(crate) struct Rows<R> {
    k: usize,
    a: Vec<R>,
    b: Vec<Mq<R>>,
    id: Vec<Option<usize>>,
}

impl<R: Ring> Rows<R> {
    /// No constraints yet, room for `n`, in `k` variables.
    pub(crate) fn new(k: usize, n: usize) -> Self {
        Rows {
            k,
            a: Vec::with_capacity(n * k),
            b: Vec::with_capacity(n),
            id: Vec::with_capacity(n),
        }
    }
    /// Add `a·x <= b` (`a` has `k` entries).
    pub(crate) fn push(&mut self, a: impl IntoIterator<Item = R>, b: Mq<R>, id: Option<usize>) {
        self.a.extend(a);
        self.b.push(b);
        self.id.push(id);
    }
    fn len(&self) -> usize {
        self.b.len()
    }
    fn a(&self, i: usize) -> &[R] {
        &self.a[i * self.k..(i + 1) * self.k]
    }
}

/// A point `X / W` (`W > 0`) and the constraints (input ids, `None` for box sides) whose
/// hyperplanes define it, one per variable.
pub(crate) struct Vertex<R> {
    pub(crate) x: Vec<Mq<R>>,
    pub(crate) w: R,
    pub(crate) basis: Vec<Option<usize>>,
}

/// Constraints that contradict (input ids; `None` for box sides).
pub(crate) type Cert = Vec<Option<usize>>;

/// `a·X - b·W` (positive: the point violates the constraint).
fn excess<R: Ring>(ga: &[R], gb: &Mq<R>, x: &[Mq<R>], w: &R) -> Mq<R> {
    let mut s = gb.scale(w).neg();
    for (aj, xj) in ga.iter().zip(x) {
        if aj.sign() != Ordering::Equal {
            s = s.add(&xj.scale(aj));
        }
    }
    s
}

/// The lexicographic optimum over `cons` (in this order) in `k = objs[0].len()` variables,
/// inside the symbolic box: maximize `objs[0]·x`, then `objs[1]·x`, ... (the objectives
/// must span all `k` directions).
pub(crate) fn solve<R: Ring>(
    cons: &Rows<R>,
    objs: &[Vec<R>],
) -> std::result::Result<Vertex<R>, Cert> {
    solve_prefix(cons, cons.len(), objs)
}

/// [`solve`] over the first `n` constraints.
fn solve_prefix<R: Ring>(
    cons: &Rows<R>,
    n: usize,
    objs: &[Vec<R>],
) -> std::result::Result<Vertex<R>, Cert> {
    let k = objs[0].len();
    // The box corner best for the objectives: each variable to ±M by the sign of its first
    // non-zero objective coefficient.
    let mut v = Vertex {
        x: (0..k)
            .map(|j| {
                let s = objs
                    .iter()
                    .map(|o| o[j].sign())
                    .find(|&s| s != Ordering::Equal)
                    .unwrap_or(Ordering::Less);
                Mq::big(if s == Ordering::Greater {
                    R::one()
                } else {
                    R::one().neg()
                })
            })
            .collect(),
        w: R::one(),
        basis: vec![None; k],
    };
    for i in 0..n {
        let (h_a, h_b, h_id) = (cons.a(i), &cons.b[i], cons.id[i]);
        if excess(h_a, h_b, &v.x, &v.w).sign() != Ordering::Greater {
            continue;
        }
        let mut p = 0;
        let mut best = 0.0;
        for (j, aj) in h_a.iter().enumerate() {
            let s = aj.pivot_score();
            if s > best {
                best = s;
                p = j;
            }
        }
        if best == 0.0 {
            return Err(vec![h_id]);
        }
        // Orient the hyperplane h·x = b so that h_p > 0 (an equality, so either sign).
        let (ha, hb) = if h_a[p].sign() == Ordering::Less {
            (h_a.iter().map(R::neg).collect::<Vec<R>>(), h_b.neg())
        } else {
            (h_a.to_vec(), h_b.clone())
        };
        let hp = ha[p].clone();
        if k == 1 {
            // x = b / h_p, inside the box and feasible for every earlier constraint.
            let x = vec![hb];
            let w = hp;
            let bound = Mq::big(w.clone());
            if x[0].sub(&bound).sign() == Ordering::Greater
                || x[0].neg().sub(&bound).sign() == Ordering::Greater
            {
                return Err(vec![h_id]);
            }
            if let Some(g) =
                (0..i).find(|&g| excess(cons.a(g), &cons.b[g], &x, &w).sign() == Ordering::Greater)
            {
                return Err(vec![h_id, cons.id[g]]);
            }
            v = Vertex {
                x,
                w,
                basis: vec![h_id],
            };
            continue;
        }
        // Eliminate x_p on h: every g becomes h_p·g - g_p·h (a positive multiple of g
        // plus a multiple of the equality), in the other variables.
        let mut sub = Rows::new(k - 1, i + 2);
        for s in [R::one(), R::one().neg()] {
            let mut a = vec![R::zero(); k];
            a[p] = s.clone();
            sub.push(
                project(&a, &ha, &hp, p),
                Mq::big(hp.clone()).sub(&hb.scale(&s)),
                None,
            );
        }
        for g in 0..i {
            let ga = cons.a(g);
            sub.push(
                project(ga, &ha, &hp, p),
                cons.b[g].scale(&hp).sub(&hb.scale(&ga[p])),
                cons.id[g],
            );
        }
        let sub_objs: Vec<Vec<R>> = objs
            .iter()
            .map(|o| project(o, &ha, &hp, p).collect())
            .collect();
        match solve(&sub, &sub_objs) {
            Ok(y) => {
                // x_j = Y_j / W_y (j != p), x_p = (b·W_y - Σ h_j·Y_j) / (h_p·W_y).
                let mut x = Vec::with_capacity(k);
                let mut rest = y.x.iter();
                let mut xp = hb.scale(&y.w);
                for (j, hj) in ha.iter().enumerate() {
                    if j == p {
                        x.push(Mq::finite(R::zero()));
                    } else {
                        let yj = rest
                            .next()
                            .cloned()
                            .unwrap_or_else(|| Mq::finite(R::zero()));
                        xp = xp.sub(&yj.scale(hj));
                        x.push(yj.scale(&hp));
                    }
                }
                x[p] = xp;
                let mut basis = y.basis;
                basis.push(h_id);
                v = Vertex {
                    x,
                    w: hp.mul(&y.w),
                    basis,
                };
            }
            Err(mut cert) => {
                cert.push(h_id);
                return Err(cert);
            }
        }
    }
    Ok(v)
}

/// `h_p·g - g_p·h` without entry `p` (the elimination of `x_p` on `h`).
fn project<'a, R: Ring>(
    ga: &'a [R],
    ha: &'a [R],
    hp: &'a R,
    p: usize,
) -> impl Iterator<Item = R> + 'a {
    let gp = &ga[p];
    (0..ga.len())
        .filter(move |&j| j != p)
        .map(move |j| hp.mul(&ga[j]).sub(&gp.mul(&ha[j])))
}
