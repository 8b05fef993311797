//! The floating-point filter: interval arithmetic with outward rounding.
//!
//! Each operation rounds to nearest and then widens the result by one ulp on each side
//! (`next_down` / `next_up`, done on the bit pattern). Under round-to-nearest the exact
//! result lies between the neighbours of the rounded one, also for subnormal results and
//! for results that underflow to zero, so every interval encloses the exact value. An
//! overflow (an infinite endpoint) or an `inf - inf` makes the interval the whole line,
//! which never decides a sign. The filter therefore needs no range assumption: it is
//! rigorous for every finite input, and merely undecided when it cannot tell.
//!
//! Differences of input coordinates (the leaves of every expression) are enclosed
//! exactly when they are representable, using the classic two-difference error term.

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

/// The next `f64` above `x` (`+inf` and NaN stay; `-inf` gives `-f64::MAX`).
pub(crate) fn next_up(x: f64) -> f64 {
    if x.is_nan() || x == f64::INFINITY {
        return x;
    }
    if x == 0.0 {
        return f64::from_bits(1);
    }
    let b = x.to_bits();
    if x > 0.0 {
        f64::from_bits(b + 1)
    } else {
        f64::from_bits(b - 1)
    }
}

/// The next `f64` below `x`.
pub(crate) fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

/// A closed interval `[lo, hi]` that encloses an exact real value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Interval {
    lo: f64,
    hi: f64,
}

impl Interval {
    const WHOLE: Interval = Interval {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };

    fn point(x: f64) -> Interval {
        Interval { lo: x, hi: x }
    }

    fn is_zero(&self) -> bool {
        self.lo == 0.0 && self.hi == 0.0
    }

    fn widened(lo: f64, hi: f64) -> Interval {
        if lo.is_nan() || hi.is_nan() {
            return Interval::WHOLE;
        }
        Interval {
            lo: next_down(lo),
            hi: next_up(hi),
        }
    }
}

impl Arith for Interval {
    fn val(a: f64) -> Self {
        Interval::point(a)
    }

    fn diff(a: f64, b: f64) -> Self {
        let s = a - b;
        if !s.is_finite() {
            return Interval::WHOLE;
        }
        // Exact error of the rounded difference (Knuth / Dekker two-difference).
        let bv = a - s;
        let av = s + bv;
        let err = (a - av) + (bv - b);
        if err > 0.0 {
            Interval {
                lo: s,
                hi: next_up(s),
            }
        } else if err < 0.0 {
            Interval {
                lo: next_down(s),
                hi: s,
            }
        } else {
            Interval::point(s)
        }
    }

    fn plus(&self, o: &Self) -> Self {
        if self.is_zero() {
            return *o;
        }
        if o.is_zero() {
            return *self;
        }
        Interval::widened(self.lo + o.lo, self.hi + o.hi)
    }

    fn minus(&self, o: &Self) -> Self {
        if o.is_zero() {
            return *self;
        }
        if self.is_zero() {
            return Interval {
                lo: -o.hi,
                hi: -o.lo,
            };
        }
        Interval::widened(self.lo - o.hi, self.hi - o.lo)
    }

    fn times(&self, o: &Self) -> Self {
        if self.is_zero() || o.is_zero() {
            return Interval::point(0.0);
        }
        if !(self.lo.is_finite() && self.hi.is_finite() && o.lo.is_finite() && o.hi.is_finite()) {
            return Interval::WHOLE;
        }
        // Common cases first: both factors of known sign need only two products.
        if self.lo >= 0.0 && o.lo >= 0.0 {
            return Interval::widened(self.lo * o.lo, self.hi * o.hi);
        }
        if self.hi <= 0.0 && o.hi <= 0.0 {
            return Interval::widened(self.hi * o.hi, self.lo * o.lo);
        }
        if self.lo >= 0.0 && o.hi <= 0.0 {
            return Interval::widened(self.hi * o.lo, self.lo * o.hi);
        }
        if self.hi <= 0.0 && o.lo >= 0.0 {
            return Interval::widened(self.lo * o.hi, self.hi * o.lo);
        }
        let (a, b, c, d) = (
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        );
        Interval::widened(a.min(b).min(c).min(d), a.max(b).max(c).max(d))
    }

    fn sign(&self) -> Option<Ordering> {
        if self.lo > 0.0 {
            Some(Ordering::Greater)
        } else if self.hi < 0.0 {
            Some(Ordering::Less)
        } else if self.is_zero() {
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
    fn next_up_and_down_step_one_ulp() {
        assert_eq!(next_up(1.0), 1.0 + f64::EPSILON);
        assert_eq!(next_down(1.0), 1.0 - f64::EPSILON / 2.0);
        assert_eq!(next_up(0.0), 5e-324);
        assert_eq!(next_down(0.0), -5e-324);
        assert_eq!(next_up(-5e-324), -0.0);
        assert_eq!(next_up(f64::MAX), f64::INFINITY);
        assert_eq!(next_down(f64::NEG_INFINITY), f64::NEG_INFINITY);
    }

    #[test]
    fn intervals_enclose_and_decide() {
        let x = Interval::diff(1.0, 1e-20);
        assert_eq!(x.sign(), Some(Ordering::Greater));
        assert!(x.lo < 1.0 && x.hi >= 1.0);
        let zero = Interval::diff(3.0, 3.0);
        assert_eq!(zero.sign(), Some(Ordering::Equal));
        let big = Interval::val(1e300).times(&Interval::val(1e300));
        assert_eq!(big.minus(&big).sign(), None);
        let tiny = Interval::val(1e-300).times(&Interval::val(1e-300));
        assert_eq!(tiny.sign(), None); // underflowed to 0: widened, undecided
    }
}
