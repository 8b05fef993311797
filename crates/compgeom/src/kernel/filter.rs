//! The floating-point filter: `f64` evaluation with a running error bound.
//!
//! Each value is a pair `(v, e)`: the `f64` result `v` of evaluating the expression,
//! and a bound `e >= |v - exact|`. With `u = 2^-53` and round-to-nearest, one rounding
//! of a real `z` to `fl(z)` errs by at most `u·|fl(z)|`, plus (for products only) half
//! the smallest subnormal when the result underflows; sums and differences of floats
//! that land in the subnormal range are exact. So
//!
//! * a difference of inputs `fl(a - b)`: `e = u·|v| + eta` (exactly zero when `a == b`);
//! * `x ± y`: `e = e_x + e_y + u·|v| + eta`;
//! * `x · y`: `e = |x|·e_y + |y|·e_x + e_x·e_y + u·|v| + eta`.
//!
//! `e` is itself computed in floating point. Each step's at most six roundings lose at
//! most a relative `(1 - u)^6` or, where a term underflows, an absolute `2^-1075` each;
//! the added `eta` (about `2^-1060`) covers the absolute losses at that very step (before
//! any later product could magnify them), so by induction the computed final bound is
//! at least `(1 - u)^(6·n)` times a true bound, for an expression of `n` steps. Our
//! expressions have fewer than 100 steps, and the final test `|v| > e·(1 + 2^-40)`
//! covers `(1 - u)^-600` with a wide margin.
//! An overflow makes `v` or `e` infinite or NaN, and then no sign is decided. The
//! filter thus needs no range assumption: it is rigorous for every finite input and
//! merely undecided when it cannot tell.

use super::arith::Arith;
use std::cmp::Ordering;
use std::sync::atomic::{AtomicU64, Ordering as MemOrder};

/// Count of decisions on constructed points that the filter could not make and that
/// went to the exact fallback (for tests and benchmarks).
pub(crate) static CROSSING_FALLBACKS: AtomicU64 = AtomicU64::new(0);

/// Count of predicate calls on input points that went to the exact fallback because a
/// coordinate was outside the range where `robust` is exact.
pub(crate) static PREDICATE_FALLBACKS: AtomicU64 = AtomicU64::new(0);

/// Record one use of an exact fallback.
pub(crate) fn count(counter: &AtomicU64) {
    counter.fetch_add(1, MemOrder::Relaxed);
}

/// Number of exact fallbacks taken so far by comparisons of constructed points
/// (crossings), summed over all threads. For tests and benchmarks.
#[doc(hidden)]
pub fn crossing_fallbacks() -> u64 {
    CROSSING_FALLBACKS.load(MemOrder::Relaxed)
}

/// Number of exact fallbacks taken so far by the input-point predicates
/// (`orient2d`, `incircle`, `orient3d`, `insphere`). For tests and benchmarks.
#[doc(hidden)]
pub fn predicate_fallbacks() -> u64 {
    PREDICATE_FALLBACKS.load(MemOrder::Relaxed)
}

/// A floating-point value with a rigorous bound on its distance to the exact value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Bounded {
    v: f64,
    e: f64,
}

/// Unit roundoff of round-to-nearest `f64`.
const U: f64 = 1.0 / 9_007_199_254_740_992.0; // 2^-53
/// Absolute slack per operation (covers underflow in products and in the bound).
const ETA: f64 = 5e-320; // between 2^-1061 and 2^-1060: thousands of 2^-1075
/// Final relative safety factor on the bound (covers the bound's own roundings).
const SAFETY: f64 = 1.0 + 1.0 / 1_099_511_627_776.0; // 1 + 2^-40

impl Arith for Bounded {
    fn val(a: f64) -> Self {
        Bounded { v: a, e: 0.0 }
    }

    fn diff(a: f64, b: f64) -> Self {
        let v = a - b;
        // a == b exactly when v == 0: then the difference is exact.
        let e = if v == 0.0 { 0.0 } else { v.abs() * U + ETA };
        Bounded { v, e }
    }

    fn plus(&self, o: &Self) -> Self {
        let v = self.v + o.v;
        Bounded {
            v,
            e: self.e + o.e + v.abs() * U + ETA,
        }
    }

    fn minus(&self, o: &Self) -> Self {
        let v = self.v - o.v;
        Bounded {
            v,
            e: self.e + o.e + v.abs() * U + ETA,
        }
    }

    fn times(&self, o: &Self) -> Self {
        let v = self.v * o.v;
        let e = self.v.abs() * o.e + o.v.abs() * self.e + self.e * o.e + v.abs() * U + ETA;
        Bounded { v, e }
    }

    fn sign(&self) -> Option<Ordering> {
        let bound = self.e * SAFETY;
        if self.v > bound {
            Some(Ordering::Greater)
        } else if -self.v > bound {
            Some(Ordering::Less)
        } else if self.v == 0.0 && self.e == 0.0 {
            // Only exact operations on exact zeros lead here (e.g. a == b differences).
            Some(Ordering::Equal)
        } else {
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants_are_what_they_claim() {
        assert_eq!(U, 2f64.powi(-53));
        assert!(ETA > 0.0 && ETA < 2f64.powi(-1060) && ETA > 2f64.powi(-1070));
        assert_eq!(SAFETY, 1.0 + 2f64.powi(-40));
    }

    #[test]
    fn bounds_decide_clear_signs_and_defer_unclear_ones() {
        let x = Bounded::diff(1.0, 1e-20);
        assert_eq!(x.sign(), Some(Ordering::Greater));
        assert_eq!(Bounded::diff(3.0, 3.0).sign(), Some(Ordering::Equal));
        let big = Bounded::val(1e300).times(&Bounded::val(1e300));
        assert_eq!(big.minus(&big).sign(), None); // overflow: inf - inf
        let tiny = Bounded::val(1e-300).times(&Bounded::val(1e-300));
        assert_eq!(tiny.sign(), None); // underflowed to 0 with an error bound
                                       // fl(1/3)·3 - 1 = -2^-54 exactly, but the product rounds to 1: undecided.
        let d = Bounded::val(1.0 / 3.0)
            .times(&Bounded::val(3.0))
            .minus(&Bounded::val(1.0));
        assert_eq!(d.v, 0.0);
        assert_eq!(d.sign(), None);
    }
}
