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

impl Bounded {
    /// The computed value and its error bound `(v, e)`, `|v - exact| <= e` (up to the
    /// bound's own roundings, covered by a factor `1 + 2^-40`).
    pub(crate) fn parts(&self) -> (f64, f64) {
        (self.v, self.e)
    }
}

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

    #[test]
    fn double_double_decides_what_f64_cannot() {
        // fl(1/3)·3 - 1 = -2^-54: the two-product keeps the product exact.
        let third = DoubleDouble::val(1.0 / 3.0);
        let d = third
            .times(&DoubleDouble::val(3.0))
            .minus(&DoubleDouble::val(1.0));
        assert_eq!(d.sign(), Some(Ordering::Less));
        assert_eq!(d.head(), -(2f64.powi(-54)));
        // (1 + 2^-60) - 1 is exact as a difference of inputs.
        let x = DoubleDouble::diff(1.0, -(2f64.powi(-60))).minus(&DoubleDouble::val(1.0));
        assert_eq!(x.sign(), Some(Ordering::Greater));
        assert_eq!(DoubleDouble::diff(2.0, 2.0).sign(), Some(Ordering::Equal));
        let big = DoubleDouble::val(1e300).times(&DoubleDouble::val(1e300));
        assert_eq!(big.sign(), None); // overflow
                                      // The two-product is exact.
        let cases = [
            (0.1, 0.3),
            (1.0 / 3.0, 3.0),
            (1e150, 7e-151),
            (-2.5e-7, 9.75e13),
            (1e-320, 1e300),
            (0.0, 5.0),
            (1e200, 1e200),
        ];
        for (a, b) in cases {
            let p = a * b;
            assert_eq!(product_error(a, b, p), a.mul_add(b, -p), "{a} * {b}");
        }
        // times_f64 agrees with times by an exact f64.
        let x = DoubleDouble::diff(0.1, -(2f64.powi(-70)));
        let (a, b) = (x.times_f64(3.0), x.times(&DoubleDouble::val(3.0)));
        assert_eq!((a.hi, a.lo), (b.hi, b.lo));
        assert!(a.e <= b.e);
    }
}

/// A double-double value `hi + lo` (`|lo| <= ulp(hi)/2`) with a rigorous bound `e` on
/// its distance to the exact value: about 106 bits of precision. Used where plain `f64`
/// cannot decide by construction (rounding a crossing to the nearest `f64` needs to
/// place it relative to midpoints half an ulp away).
///
/// Error terms, with `u = 2^-53` and `eta` as for [`Bounded`]: differences of inputs
/// are exact (two-sum); a sum adds at most `3u·(|x.lo| + |y.lo| + |t1|)` where `t1` is
/// the exact error of `x.hi + y.hi`; a product (its `hi·hi` part is exact through a
/// two-product, up to underflow) adds at most
/// `4u·(|x.hi·y.lo| + |x.lo·y.hi| + |p_err|) + |x.lo·y.lo|` besides the propagated
/// `|x|·e_y + |y|·e_x + e_x·e_y`. Each step adds `eta` for underflow, and the final test
/// applies the same `1 + 2^-40` safety factor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct DoubleDouble {
    hi: f64,
    lo: f64,
    e: f64,
}

/// Veltkamp's splitting constant `2^27 + 1`.
const SPLITTER: f64 = 134_217_729.0;

/// `a = hi + lo` with both halves of at most 26 significant bits (for `|a|` well
/// inside the normal range).
#[inline]
fn split(a: f64) -> (f64, f64) {
    let c = SPLITTER * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

/// Magnitudes between these keep every step of [`product_error`] free of underflow and
/// overflow (then Dekker's two-product is exact).
const TWO_PRODUCT_RANGE: (f64, f64) = (1e-250, 1e250);

/// The rounding error `a·b - p` of `p = fl(a·b)`, exactly: Dekker's two-product in plain
/// arithmetic when `|a|`, `|b|` and `|p|` lie in [`TWO_PRODUCT_RANGE`] (the common case;
/// `f64::mul_add` is a library call on targets built without FMA, several times
/// slower), else the fused multiply-add.
#[inline]
pub(crate) fn product_error(a: f64, b: f64, p: f64) -> f64 {
    let (lo, hi) = TWO_PRODUCT_RANGE;
    let fits = |v: f64| v.abs() > lo && v.abs() < hi;
    if fits(a) && fits(b) && fits(p) {
        let (ah, al) = split(a);
        let (bh, bl) = split(b);
        ((ah * bh - p) + ah * bl + al * bh) + al * bl
    } else if a == 0.0 || b == 0.0 {
        0.0
    } else {
        a.mul_add(b, -p)
    }
}

/// `a + b = s + err` exactly (no overflow).
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

impl DoubleDouble {
    /// The leading `f64` of the value.
    pub(crate) fn head(&self) -> f64 {
        self.hi
    }

    /// A lower and an upper bound on the magnitude of the exact value (the lower bound
    /// may be negative: no information).
    pub(crate) fn magnitude_bounds(&self) -> (f64, f64) {
        // Each bound is one or two roundings from the real expression; the factors
        // `1 ± 2^-48` cover them with a wide margin.
        const WIDE: f64 = 1.0 / 281_474_976_710_656.0; // 2^-48
        let off = (self.lo.abs() + self.e * SAFETY) * (1.0 + WIDE);
        let low = (self.hi.abs() - off) * (1.0 - WIDE);
        let high = (self.hi.abs() + off) * (1.0 + WIDE);
        (low, high)
    }

    /// `self · k` for an `f64` `k`: [`Arith::times`] with `DoubleDouble::val(k)`, the
    /// terms that vanish for an exact `f64` factor (`lo = e = 0`) left out, so the same
    /// error bound holds.
    pub(crate) fn times_f64(&self, k: f64) -> DoubleDouble {
        let p = self.hi * k;
        let p_err = product_error(self.hi, k, p);
        let b = self.lo * k;
        let c = b + p_err;
        let (hi, lo) = two_sum(p, c);
        let e = k.abs() * self.e + 4.0 * U * (b.abs() + p_err.abs()) + ETA;
        DoubleDouble { hi, lo, e }
    }
}

impl Arith for DoubleDouble {
    fn val(a: f64) -> Self {
        DoubleDouble {
            hi: a,
            lo: 0.0,
            e: 0.0,
        }
    }

    fn diff(a: f64, b: f64) -> Self {
        let (hi, lo) = two_sum(a, -b);
        DoubleDouble { hi, lo, e: 0.0 }
    }

    fn plus(&self, o: &Self) -> Self {
        let (s, t1) = two_sum(self.hi, o.hi);
        let t = (self.lo + o.lo) + t1;
        let (hi, lo) = two_sum(s, t);
        let e = self.e + o.e + 3.0 * U * (self.lo.abs() + o.lo.abs() + t1.abs()) + ETA;
        DoubleDouble { hi, lo, e }
    }

    fn minus(&self, o: &Self) -> Self {
        self.plus(&DoubleDouble {
            hi: -o.hi,
            lo: -o.lo,
            e: o.e,
        })
    }

    fn times(&self, o: &Self) -> Self {
        let p = self.hi * o.hi;
        let p_err = product_error(self.hi, o.hi, p);
        let (a, b) = (self.hi * o.lo, self.lo * o.hi);
        let c = (a + b) + p_err;
        let (hi, lo) = two_sum(p, c);
        let (xm, ym) = (self.hi.abs() + self.lo.abs(), o.hi.abs() + o.lo.abs());
        let e = xm * o.e
            + ym * self.e
            + self.e * o.e
            + 4.0 * U * (a.abs() + b.abs() + p_err.abs())
            + (self.lo * o.lo).abs()
            + ETA;
        DoubleDouble { hi, lo, e }
    }

    fn sign(&self) -> Option<Ordering> {
        if !(self.hi.is_finite() && self.e.is_finite()) {
            return None;
        }
        // |hi + lo| >= |hi|·(1 - u); the factor below is smaller even after rounding.
        let low = self.hi.abs() * (1.0 - 1.0 / 1_125_899_906_842_624.0); // 1 - 2^-50
        if low > self.e * SAFETY {
            Some(if self.hi > 0.0 {
                Ordering::Greater
            } else {
                Ordering::Less
            })
        } else if self.hi == 0.0 && self.lo == 0.0 && self.e == 0.0 {
            Some(Ordering::Equal)
        } else {
            None
        }
    }
}
