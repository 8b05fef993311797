//! Exact dyadic arithmetic: the slow path of every exact decision.
//!
//! Each finite `f64` is exactly `m · 2^e` with an integer `m`; sums, differences and
//! products of such numbers stay of that form, so determinants (which need no
//! division) are computed exactly with a big-integer mantissa and an `i64` exponent.
//! [`nearest_f64`] rounds an exact quotient of two such numbers to the nearest `f64`.

use super::arith::Arith;
use num_bigint::{BigInt, BigUint, Sign};
use num_traits::{ToPrimitive, Zero};
use std::cmp::Ordering;

/// An exact dyadic rational `m · 2^e`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Dyadic {
    m: BigInt,
    e: i64,
}

impl Dyadic {
    /// Zero.
    pub(crate) fn zero() -> Dyadic {
        Dyadic {
            m: BigInt::zero(),
            e: 0,
        }
    }

    /// The exact value of a finite `f64`; a non-finite `x` gives zero (callers check
    /// finiteness first; this keeps the arithmetic total and panic-free).
    pub(crate) fn from_f64(x: f64) -> Dyadic {
        if !x.is_finite() || x == 0.0 {
            return Dyadic::zero();
        }
        let bits = x.to_bits();
        let biased = ((bits >> 52) & 0x7ff) as i64;
        let frac = bits & ((1u64 << 52) - 1);
        let (mut mant, mut exp) = if biased == 0 {
            (frac, -1074)
        } else {
            (frac | (1u64 << 52), biased - 1075)
        };
        // Strip trailing zeros so that mantissas stay short.
        let tz = mant.trailing_zeros();
        mant >>= tz;
        exp += i64::from(tz);
        let m = BigInt::from(mant);
        Dyadic {
            m: if x < 0.0 { -m } else { m },
            e: exp,
        }
    }

    /// True when the value is zero.
    pub(crate) fn is_zero(&self) -> bool {
        self.m.is_zero()
    }

    /// The exact value as a big rational.
    pub(crate) fn to_rational(&self) -> num_rational::BigRational {
        use num_traits::One;
        if self.e >= 0 {
            num_rational::BigRational::from_integer(&self.m << (self.e as usize))
        } else {
            num_rational::BigRational::new(self.m.clone(), BigInt::one() << ((-self.e) as usize))
        }
    }

    /// `(negative, |mantissa|, exponent)`.
    pub(crate) fn parts(&self) -> (bool, &BigUint, i64) {
        (self.m.sign() == Sign::Minus, self.m.magnitude(), self.e)
    }

    /// The two mantissas brought to a common exponent (the smaller one).
    fn aligned(&self, o: &Dyadic) -> (BigInt, BigInt, i64) {
        if self.is_zero() {
            return (BigInt::zero(), o.m.clone(), o.e);
        }
        if o.is_zero() {
            return (self.m.clone(), BigInt::zero(), self.e);
        }
        match self.e.cmp(&o.e) {
            Ordering::Equal => (self.m.clone(), o.m.clone(), self.e),
            // Exponent gaps are bounded by the f64 exponent range times the degree,
            // so the shifts below stay small (a few thousand bits at worst).
            Ordering::Greater => (&self.m << ((self.e - o.e) as usize), o.m.clone(), o.e),
            Ordering::Less => (self.m.clone(), &o.m << ((o.e - self.e) as usize), self.e),
        }
    }
}

impl Arith for Dyadic {
    fn val(a: f64) -> Self {
        Dyadic::from_f64(a)
    }

    fn diff(a: f64, b: f64) -> Self {
        Dyadic::from_f64(a).minus(&Dyadic::from_f64(b))
    }

    fn plus(&self, o: &Self) -> Self {
        let (a, b, e) = self.aligned(o);
        Dyadic { m: a + b, e }
    }

    fn minus(&self, o: &Self) -> Self {
        let (a, b, e) = self.aligned(o);
        Dyadic { m: a - b, e }
    }

    fn times(&self, o: &Self) -> Self {
        if self.is_zero() || o.is_zero() {
            return Dyadic::zero();
        }
        Dyadic {
            m: &self.m * &o.m,
            e: self.e + o.e,
        }
    }

    fn sign(&self) -> Option<Ordering> {
        Some(match self.m.sign() {
            Sign::Minus => Ordering::Less,
            Sign::NoSign => Ordering::Equal,
            Sign::Plus => Ordering::Greater,
        })
    }
}

/// `2^k` as an `f64`, for `-1074 <= k <= 1023` (exact: subnormal below `-1022`).
pub(crate) fn pow2(k: i64) -> f64 {
    debug_assert!((-1074..=1023).contains(&k));
    if k >= -1022 {
        f64::from_bits(((k + 1023) as u64) << 52)
    } else {
        f64::from_bits(1u64 << (k + 1074))
    }
}

/// The `f64` nearest to `num / den` (ties to even), with IEEE round-to-nearest
/// behaviour at the ends of the range: results below half the smallest subnormal
/// become `±0`, subnormal results are rounded at `2^-1074`, and results at or beyond
/// `f64::MAX + ulp/2` become `±inf`. A zero denominator gives NaN.
pub(crate) fn nearest_f64(num: &Dyadic, den: &Dyadic) -> f64 {
    let (nneg, n, ne) = num.parts();
    let (dneg, d, de) = den.parts();
    if d.is_zero() {
        return f64::NAN;
    }
    let neg = nneg != dneg;
    let signed = |x: f64| if neg { -x } else { x };
    if n.is_zero() {
        return 0.0;
    }
    let exp = ne - de;
    let ln = n.bits() as i64;
    let ld = d.bits() as i64;
    // n / d lies in (2^(ln-ld-1), 2^(ln-ld+1)); scaling by 2^s makes the integer
    // quotient q have 55 or 56 bits: two guard bits beyond the 53 kept.
    let s = 55 - (ln - ld);
    let (a, b) = if s >= 0 {
        (n << (s as usize), d.clone())
    } else {
        (n.clone(), d << ((-s) as usize))
    };
    let q_big = &a / &b;
    let sticky = &q_big * &b != a;
    let q = q_big.to_u64().unwrap_or(u64::MAX);
    // The value is (q + f) · 2^lsb with 0 <= f < 1 (f > 0 iff sticky).
    let lsb = exp - s;
    let nb = 64 - i64::from(q.leading_zeros());
    let top = nb - 1 + lsb; // floor(log2 |value|)
    if top > 1023 {
        return signed(f64::INFINITY);
    }
    let ulp = (top - 52).max(-1074);
    let drop = ulp - lsb; // >= 2 always
    if drop > nb {
        // |value| < 2^(lsb + nb) <= 2^(ulp - 1): below half an ulp of zero.
        return signed(0.0);
    }
    let mut m = if drop >= 64 { 0 } else { q >> drop };
    let rest = q & ((1u64 << drop) - 1);
    let half = 1u64 << (drop - 1);
    if rest > half || (rest == half && (sticky || m & 1 == 1)) {
        m += 1;
    }
    // m <= 2^53 is exact in f64; the product is exact or overflows to inf.
    signed(m as f64 * pow2(ulp))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ratio(n: f64, d: f64) -> f64 {
        nearest_f64(&Dyadic::from_f64(n), &Dyadic::from_f64(d))
    }

    #[test]
    fn from_f64_round_trips_through_rounding() {
        for x in [
            1.0,
            -3.5,
            f64::MIN_POSITIVE,
            5e-324,
            -1e-310,
            f64::MAX,
            0.1,
            1e300,
        ] {
            assert_eq!(ratio(x, 1.0), x, "{x}");
        }
    }

    #[test]
    fn quotients_round_to_nearest() {
        assert_eq!(ratio(1.0, 3.0), 1.0 / 3.0);
        assert_eq!(ratio(2.0, 3.0), 2.0 / 3.0);
        assert_eq!(ratio(-7.0, 10.0), -0.7);
        assert_eq!(ratio(1e300, 1e-300), f64::INFINITY);
        assert_eq!(ratio(-1e300, 1e-300), f64::NEG_INFINITY);
        assert_eq!(ratio(1e-300, 1e300), 0.0);
        assert_eq!(ratio(1e-300, 1e10), 1e-300 / 1e10);
        assert_eq!(ratio(5e-324, 2.0), 0.0); // tie to even (zero)
        assert_eq!(ratio(3.0 * 5e-324, 2.0), 2.0 * 5e-324); // 1.5 ulp -> 2 (even)
        assert!(ratio(1.0, 0.0).is_nan());
    }

    #[test]
    fn arithmetic_is_exact() {
        let a = Dyadic::from_f64(1e300);
        let b = Dyadic::from_f64(1e-300);
        let s = a.plus(&b).minus(&a);
        assert_eq!(s, b);
        let p = a.times(&a).minus(&a.times(&a));
        assert_eq!(p.sign(), Some(Ordering::Equal));
        assert_eq!(
            Dyadic::diff(1.0, 1.0 + f64::EPSILON).sign(),
            Some(Ordering::Less)
        );
    }
}
