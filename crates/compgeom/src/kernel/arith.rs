//! The small arithmetic interface shared by the floating-point filter
//! ([`super::filter::Bounded`]) and the exact fallback ([`super::exact::Dyadic`]).
//!
//! Every sign decision on constructed points is written once, generically over
//! [`Arith`], and evaluated first in `f64` with an error bound (fast, may be undecided) and then,
//! only if needed, with exact dyadic numbers (always decided).

use std::cmp::Ordering;

/// Ring operations on an enclosure (filter) or an exact value (fallback).
///
/// Callers only pass finite `f64` values to [`Arith::val`] and [`Arith::diff`].
pub(crate) trait Arith: Sized {
    /// The value `a` (exact for every finite `a`).
    fn val(a: f64) -> Self;
    /// The exact difference `a - b` (enclosed tightly by the filter).
    fn diff(a: f64, b: f64) -> Self;
    /// `self + o`.
    fn plus(&self, o: &Self) -> Self;
    /// `self - o`.
    fn minus(&self, o: &Self) -> Self;
    /// `self * o`.
    fn times(&self, o: &Self) -> Self;
    /// The sign of the exact value compared with zero, or `None` when it is not
    /// certain (only the filter ever answers `None`).
    fn sign(&self) -> Option<Ordering>;
}

/// The sign of a product, given the signs of its factors.
pub(crate) fn mul_sign(a: Ordering, b: Ordering) -> Ordering {
    match (a, b) {
        (Ordering::Equal, _) | (_, Ordering::Equal) => Ordering::Equal,
        (x, y) if x == y => Ordering::Greater,
        _ => Ordering::Less,
    }
}

/// An order-preserving integer key of a finite `f64` (`-0.0` and `0.0` share one): the
/// sign bit flipped for positive values, all bits for negative ones, so integer order
/// (and radix or counting sorts) gives the numeric order.
#[inline]
pub(crate) fn ordered_key(v: f64) -> u64 {
    let b = (v + 0.0).to_bits();
    if b >> 63 == 1 {
        !b
    } else {
        b | (1 << 63)
    }
}
