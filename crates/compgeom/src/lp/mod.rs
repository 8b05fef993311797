//! Linear programming and its applications (book chapter 4).
//!
//! | function | book | method | time |
//! |---|---|---|---|
//! | [`lp2d`] | §4.3–4.4 2DRANDOMIZEDBOUNDEDLP + unbounded case | randomized incremental, symbolic bounding box; static `f64` filters, exact when undecided | expected O(n) |
//! | [`intersect_halfplanes`] = [`intersect_halfplanes_scan`] | §4.2 half-plane intersection | prune by a sample's region, exact slope sort (radix on the correctly rounded slope), one INTERSECTCONVEXREGIONS sweep | O(n log n) |
//! | [`intersect_halfplanes_dc`] | §4.2 INTERSECTHALFPLANES | the book's divide and conquer, linear merge of left/right boundary chains | O(n log n) |
//! | [`intersect_halfplanes_incremental`] | §4.2 half-plane intersection | randomized incremental clipping of a symbolic box | expected O(n·h), h the size of the intermediate regions (worst case O(n²)) |
//! | [`lp_d`] | §4.5 RANDOMIZEDLP | recursive randomized incremental; `f64` run with an exactly certified basis, else exact integers | expected O(d!·n) |
//! | [`smallest_enclosing_disc`] | §4.7 MINIDISC | randomized incremental; `f64` disc filter, exact `incircle`/`orient2d` near the circle | expected O(n) |
//! | [`castability`] | §4.1 casting | per top facet a feasibility problem (Lemma 4.1), the LP of [`lp_d`] with its certified fast path | O(n²) expected |
//! | [`verify_lp2d`], [`verify_region`], [`verify_enclosing_disc`] | | exact checks of a claimed answer | O(n) / O(n·h) / O(n) |
//!
//! # Input
//!
//! A half-plane is `a·x + b·y <= c` ([`HalfPlane`]); [`read_halfplanes`] reads lines
//! `a b c` (or `a,b,c`), `#` comments. Higher-dimensional constraints
//! `a1·x1 + … + ad·xd <= c` are read by [`read_constraints`].
//!
//! # Exactness and degenerate input
//!
//! Corners of half-plane intersections and LP optima are *constructed* points (where two
//! constraint lines meet). Every decision about them — is this corner inside that
//! half-plane, which end of an interval is better for the objective, is the interval empty —
//! is the sign of a small polynomial in the input numbers, decided by an `f64` filter with a
//! rigorous error bound and, when the filter cannot tell, by exact rational arithmetic.
//! Unboundedness is handled with a *symbolic* bounding box `|x|, |y| <= M` (`M` larger
//! than every finite quantity), so no magic constant can cut a real answer off.
//! Coordinates are reported as the nearest `f64` of the exact value.
//!
//! Parallel, identical and redundant constraints are ordinary input. A constraint with a
//! **zero normal** (`0·x <= c`) is accepted, the same way by [`lp2d`], [`lp_d`] and the
//! half-plane intersections: when `c >= 0` it is always true and ignored (never reported
//! as tight or bounding); when `c < 0` it is always false, so the answer is infeasible
//! (`Infeasible { certificate: [that constraint] }`, or the empty region). Non-finite numbers are rejected with
//! [`Error::NonFinite`] naming the constraint.

mod casting;
mod certify;
mod enclosing_disc;
mod exact;
mod filter;
mod halfplanes;
mod halfplanes_dc;
mod halfplanes_scan;
mod lp2d;
mod lpd;
mod read;
mod round_meet;
mod seidel;
mod slope_sort;
mod verify;

pub use casting::{castability, castability_at, Castability, TopFacet};
pub use enclosing_disc::{smallest_enclosing_disc, verify_enclosing_disc, Disc};
pub use halfplanes::{intersect_halfplanes, intersect_halfplanes_incremental, Region, RegionKind};
pub use halfplanes_dc::{intersect_halfplanes_dc, intersect_halfplanes_dc_leaf};
pub use halfplanes_scan::intersect_halfplanes_scan;
pub use lp2d::{lp2d, lp2d_exact, Lp2Options, Lp2Solution};
pub use lpd::{lp_d, lp_d_exact, lp_d_fast_hits, LpSolution};
pub use read::{read_constraints, read_halfplanes};
pub use verify::{verify_lp2d, verify_region};

use crate::{Error, Result};

/// Number of decisions so far (all threads) that the floating-point filter of this module
/// could not make and that went to exact rational arithmetic. For tests and benchmarks.
#[doc(hidden)]
pub fn exact_fallbacks() -> u64 {
    exact::FALLBACKS.load(std::sync::atomic::Ordering::Relaxed)
}

/// The closed half-plane `a·x + b·y <= c`.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct HalfPlane {
    /// Coefficient of x.
    pub a: f64,
    /// Coefficient of y.
    pub b: f64,
    /// Right-hand side.
    pub c: f64,
}

impl HalfPlane {
    /// The half-plane `a·x + b·y <= c`.
    pub const fn new(a: f64, b: f64, c: f64) -> Self {
        HalfPlane { a, b, c }
    }

    /// True when `p` satisfies the constraint, decided exactly.
    ///
    /// ```
    /// use compgeom::lp::HalfPlane;
    /// use compgeom::Point2;
    /// let h = HalfPlane::new(0.1, 0.2, 0.3);
    /// // The binary numbers nearest 0.1 and 0.2 add up to slightly more than the one
    /// // nearest 0.3: the exact test says so.
    /// assert!(!h.contains(Point2::new(1.0, 1.0)));
    /// assert!(HalfPlane::new(1.0, 1.0, 2.0).contains(Point2::new(1.0, 1.0)));
    /// assert!(!HalfPlane::new(1.0, 1.0, 2.0).contains(Point2::new(1.0, 1.0 + 1e-15)));
    /// ```
    pub fn contains(&self, p: Point2) -> bool {
        let e = exact::AffineExpr {
            a: self.a,
            b: self.b,
            c: self.c,
            x: p.x,
            y: p.y,
        };
        exact::sign(&e) != std::cmp::Ordering::Greater
    }
}

use crate::kernel::Point2;

/// Reject non-finite coefficients, naming the constraint.
pub(crate) fn check_finite(hs: &[HalfPlane]) -> Result<()> {
    for (i, h) in hs.iter().enumerate() {
        for v in [h.a, h.b, h.c] {
            if !v.is_finite() {
                return Err(Error::NonFinite {
                    what: format!("constraint {i}"),
                    value: v,
                });
            }
        }
    }
    Ok(())
}

/// A small deterministic generator (splitmix64) for the random insertion orders.
pub(crate) struct Shuffler(u64);

impl Shuffler {
    pub(crate) fn new(seed: u64) -> Self {
        Shuffler(seed ^ 0x9e37_79b9_7f4a_7c15)
    }

    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A uniform index below `n` (`n > 0`).
    pub(crate) fn below(&mut self, n: usize) -> usize {
        ((self.next() as u128 * n as u128) >> 64) as usize
    }

    /// Shuffle in place (Fisher–Yates).
    pub(crate) fn shuffle<T>(&mut self, v: &mut [T]) {
        for i in (1..v.len()).rev() {
            let j = self.below(i + 1);
            v.swap(i, j);
        }
    }
}
