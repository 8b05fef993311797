//! Exact predicates on the constructed objects of Fortune's sweep: breakpoints of the beach
//! line and circle events.
//!
//! ## Breakpoints (no square root needed)
//!
//! A new site `q` is located on the beach line at the moment the sweep line is at
//! `ℓ = q.y`. The parabola of a site `p` above `ℓ`, evaluated at `x = q.x`, has height
//! `y_p − ℓ = |q − p|² / (2 (p.y − ℓ))`. So "which of the arcs of `pi`, `pj` is lower above
//! `q`" is the sign of the cubic polynomial
//! `F = |q − pi|² (pj.y − q.y) − |q − pj|² (pi.y − q.y)` in the input coordinates. The two
//! parabolas meet in two points `x1 < x2`; the one of the site nearer to `ℓ` (narrower) is
//! lower between them, and the focus of the narrower one lies between them. Hence
//! "`q` is left of the breakpoint of the arcs (`pi`, `pj`)" is decided by `F` and one
//! coordinate comparison (`left_of_breakpoint`); sites on the sweep line (degenerate
//! arcs, vertical rays) are handled as the limit case.
//!
//! ## Circle events (one or two square roots)
//!
//! The event of the triple `a, b, c` is the lowest point of their circle:
//! `y = c_y − r`. With `B = b − a`, `C = c − a`, `D = 2 (B × C)`,
//! `N_x = C_y|B|² − B_y|C|²`, `N_y = B_x|C|² − C_x|B|²`, the centre is
//! `a + (N_x, N_y)/D` and `r = √(N_x² + N_y²)/|D|`. Comparing such a value with a site's
//! `y`, or two of them, is the sign of `P − √Q` or of `X + √B − √A` with polynomial
//! `P, Q, X, A, B`; these are decided by squaring with sign analysis (every step exact),
//! see `cmp_event_site` and `cmp_events`.
//!
//! ## Evaluation stages
//!
//! 1. **Cheap filters** in plain `f64` with error bounds derived once (proofs at
//!    `lower_sign` and `circle_event`): the breakpoint sign `F`, and each circle
//!    event's enclosures of its `y` and centre `x`. Two events (or an event and a site)
//!    whose enclosures are disjoint are ordered without further work — nearly always on
//!    random input.
//! 2. **Small-integer input** (`IntFrame`: all sites integers in a `2¹¹` box, e.g. the
//!    1000 × 1000 grid, where every square gives exact ties): `F` is exact in `f64`, and
//!    events carry an exact integer form (`IntCircle`) compared in `i128` (one 256-bit
//!    product in the rarest branch), with the bounds proved where they are used.
//! 3. Otherwise every polynomial, written once generically over the kernel's arithmetic
//!    interface, is evaluated with a rigorous running error bound (the kernel's filter),
//!    then exactly in `f64` when every operation happens to be exact (ties on dyadic
//!    grids), and only then with exact dyadic big-integer arithmetic.
//!
//! Unit proptests hold the first two stages to the dyadic one on degenerate input (grids,
//! lattice circles, ±1 ulp, scales 2⁻¹⁰⁰⁰ … 2⁹⁰⁰, offsets, points on a rounded breakpoint).

use crate::kernel::arith::Arith;
use crate::kernel::exact::Dyadic;
use crate::kernel::filter::Bounded;
use crate::kernel::{orient2d, Orientation, Point2};
use std::cmp::Ordering;
use std::sync::atomic::{AtomicU64, Ordering as MemOrder};

/// Number of exact fallbacks taken by the Voronoi predicates (for tests and benchmarks).
static FALLBACKS: AtomicU64 = AtomicU64::new(0);

/// Number of decisions of the Voronoi predicates that went to the exact fallback, summed
/// over all threads. For tests and benchmarks.
#[doc(hidden)]
pub fn voronoi_fallbacks() -> u64 {
    FALLBACKS.load(MemOrder::Relaxed)
}

/// The filter, else (counted) the exact evaluation.
fn decide(fast: impl FnOnce() -> Option<Ordering>, exact: impl FnOnce() -> Ordering) -> Ordering {
    if let Some(o) = fast() {
        return o;
    }
    FALLBACKS.fetch_add(1, MemOrder::Relaxed);
    exact()
}

/// `f64` arithmetic that knows whether every operation so far was exact (error-free
/// transformations: a sum is exact when its TwoSum error is zero, a product when
/// `fma(a, b, −p)` is zero). When all were exact, the value is exact and its sign —
/// including zero — is decided. This settles exact ties (grids, cocircular sites) with
/// small integer-like values without big integers; otherwise the caller goes on to the
/// dyadic fallback.
#[derive(Debug, Clone, Copy)]
struct Exactish {
    v: f64,
    exact: bool,
}

/// Results below this magnitude may have lost bits to underflow unnoticed: not trusted.
const TINY: f64 = 1e-290;

impl Exactish {
    fn sum(a: f64, b: f64, exact: bool) -> Self {
        let s = a + b;
        let bb = s - a;
        let err = (a - (s - bb)) + (b - bb);
        let ok = exact && err == 0.0 && s.is_finite() && (s == 0.0 || s.abs() >= TINY);
        Exactish { v: s, exact: ok }
    }
}

impl Arith for Exactish {
    fn val(a: f64) -> Self {
        Exactish { v: a, exact: true }
    }
    fn diff(a: f64, b: f64) -> Self {
        Exactish::sum(a, -b, true)
    }
    fn plus(&self, o: &Self) -> Self {
        Exactish::sum(self.v, o.v, self.exact && o.exact)
    }
    fn minus(&self, o: &Self) -> Self {
        Exactish::sum(self.v, -o.v, self.exact && o.exact)
    }
    fn times(&self, o: &Self) -> Self {
        let p = self.v * o.v;
        let ok = self.exact
            && o.exact
            && p.is_finite()
            && ((p == 0.0 && (self.v == 0.0 || o.v == 0.0)) || p.abs() >= TINY)
            && self.v.mul_add(o.v, -p) == 0.0;
        Exactish { v: p, exact: ok }
    }
    fn sign(&self) -> Option<Ordering> {
        if self.exact {
            self.v.partial_cmp(&0.0)
        } else {
            None
        }
    }
}

fn sign_exact(d: &Dyadic) -> Ordering {
    d.sign().unwrap_or(Ordering::Equal)
}

fn neg<T: Arith>(x: &T) -> T {
    T::val(0.0).minus(x)
}

/// `|q − p|²` with exact differences.
fn dist2<T: Arith>(q: Point2, p: Point2) -> T {
    let dx = T::diff(q.x, p.x);
    let dy = T::diff(q.y, p.y);
    dx.times(&dx).plus(&dy.times(&dy))
}

/// `F = |q − pi|² (pj.y − q.y) − |q − pj|² (pi.y − q.y)`: negative when the arc of `pi`
/// is lower than the arc of `pj` above `q` with the sweep line through `q`.
fn lower_poly<T: Arith>(q: Point2, pi: Point2, pj: Point2) -> T {
    let di: T = dist2(q, pi);
    let dj: T = dist2(q, pj);
    di.times(&T::diff(pj.y, q.y))
        .minus(&dj.times(&T::diff(pi.y, q.y)))
}

/// `2⁻⁹⁶⁰`: products and sums at least this large are normal numbers whose rounding is
/// relative; below it the cheap filter does not answer.
const NORMAL_ENOUGH: f64 = 1.0261342003245941e-289; // 2^-960 (checked in a unit test)

/// Sign of `F` (see [`lower_poly`]), exactly.
///
/// First a static-style filter in plain `f64`: `F = t₁ − t₂` with `t₁ = |q − pj|²·(q.y −
/// pi.y)` and `t₂ = |q − pi|²·(q.y − pj.y)`. Each input difference carries one rounding,
/// each `|·|²` (a sum of two squares, all terms positive) at most four, each `t` at most
/// six, the final difference one more, so `|fl(F) − F| ≤ γ₆(|T₁| + |T₂|) + u|fl(t₁) −
/// fl(t₂)| ≤ 7.01·u·(|fl(t₁)| + |fl(t₂)|)` with `u = 2⁻⁵³`, as long as nothing underflows:
/// guaranteed when `|q − pi|²`, `|q − pj|²`, `|t₁|`, `|t₂|` are all at least `2⁻⁹⁶⁰` (an
/// underflowed square then errs by at most `2⁻¹⁰⁷⁵`, a relative `2⁻¹¹⁵`; differences of
/// floats are exact in the subnormal range). The bound used, `8u·fl(|t₁| + |t₂|)`, is
/// larger even after its own rounding. Overflow gives `inf`/`NaN`, which never passes the
/// test. With `exact_f64` (all sites small integers, [`IntFrame`]) every operation is exact
/// (`|F| < 2³⁵`) and the sign is taken directly.
fn lower_sign(q: Point2, pi: Point2, pj: Point2, exact_f64: bool) -> Ordering {
    let (dxi, dyi) = (q.x - pi.x, q.y - pi.y);
    let (dxj, dyj) = (q.x - pj.x, q.y - pj.y);
    let di = dxi * dxi + dyi * dyi;
    let dj = dxj * dxj + dyj * dyj;
    let t1 = dj * dyi;
    let t2 = di * dyj;
    let f = t1 - t2;
    if exact_f64 {
        return f.partial_cmp(&0.0).unwrap_or(Ordering::Equal);
    }
    let bound = (t1.abs() + t2.abs()) * (8.0 / 9_007_199_254_740_992.0);
    if di.min(dj).min(t1.abs()).min(t2.abs()) >= NORMAL_ENOUGH {
        if f > bound {
            return Ordering::Greater;
        }
        if -f > bound {
            return Ordering::Less;
        }
    }
    lower_sign_slow(q, pi, pj)
}

/// Sign of `F` by the running-error filter, then exactly.
fn lower_sign_slow(q: Point2, pi: Point2, pj: Point2) -> Ordering {
    decide(
        || lower_poly::<Bounded>(q, pi, pj).sign(),
        || {
            lower_poly::<Exactish>(q, pi, pj)
                .sign()
                .unwrap_or_else(|| sign_exact(&lower_poly::<Dyadic>(q, pi, pj)))
        },
    )
}

/// Sign of `|q − a|² − |q − b|²`, exactly: `Less` when `q` is strictly nearer to `a`.
pub(crate) fn cmp_dist(q: Point2, a: Point2, b: Point2) -> Ordering {
    fn poly<T: Arith>(q: Point2, a: Point2, b: Point2) -> T {
        dist2::<T>(q, a).minus(&dist2::<T>(q, b))
    }
    decide(
        || poly::<Bounded>(q, a, b).sign(),
        || {
            poly::<Exactish>(q, a, b)
                .sign()
                .unwrap_or_else(|| sign_exact(&poly::<Dyadic>(q, a, b)))
        },
    )
}

/// Is the site `q` strictly left of the breakpoint between the arc of `pi` (left) and the
/// arc of `pj` (right), with the sweep line at `q.y`? Sites are above or on the sweep line
/// (`pi.y, pj.y >= q.y`), and `pi != pj`. A site exactly on the breakpoint is not left.
/// `exact_f64`: all sites are small integers ([`IntFrame`]).
#[inline]
pub(crate) fn left_of_breakpoint(q: Point2, pi: Point2, pj: Point2, exact_f64: bool) -> bool {
    let l = q.y;
    match (pi.y == l, pj.y == l) {
        // Both on the sweep line (the start of the sweep): the breakpoint is on their
        // bisector, a vertical line.
        (true, true) => cmp_dist(q, pi, pj) == Ordering::Less,
        // A site on the sweep line has a degenerate arc: the vertical ray above it.
        (true, false) => q.x < pi.x,
        (false, true) => q.x < pj.x,
        (false, false) => {
            // Cheap coordinate tests first: they settle the wide-arc cases without F.
            match pi.y.partial_cmp(&pj.y) {
                // Equal heights: one crossing; left of it the left site's arc is lower.
                Some(Ordering::Equal) | None => lower_sign(q, pi, pj, exact_f64) == Ordering::Less,
                // pi farther from the sweep (wider arc): the breakpoint is the left
                // crossing x1, and the focus of pj lies between the crossings.
                Some(Ordering::Greater) => {
                    q.x < pj.x && lower_sign(q, pi, pj, exact_f64) == Ordering::Less
                }
                // pi nearer (narrower): the breakpoint is the right crossing x2, and the
                // focus of pi lies between the crossings.
                Some(Ordering::Less) => {
                    q.x < pi.x || lower_sign(q, pi, pj, exact_f64) == Ordering::Less
                }
            }
        }
    }
}

/// The polynomial parts of the circle through `a, b, c`: `(D, N_x, N_y)` (see the module
/// docs); the centre is `a + (N_x, N_y) / D`.
fn circle_parts<T: Arith>(a: Point2, b: Point2, c: Point2) -> (T, T, T) {
    let bx = T::diff(b.x, a.x);
    let by = T::diff(b.y, a.y);
    let cx = T::diff(c.x, a.x);
    let cy = T::diff(c.y, a.y);
    let b2 = bx.times(&bx).plus(&by.times(&by));
    let c2 = cx.times(&cx).plus(&cy.times(&cy));
    let two = T::val(2.0);
    let d = two.times(&bx.times(&cy).minus(&by.times(&cx)));
    let nx = cy.times(&b2).minus(&by.times(&c2));
    let ny = bx.times(&c2).minus(&cx.times(&b2));
    (d, nx, ny)
}

/// A circle event's place in the sweep order, as enclosures: `y` of the lowest point of
/// the circle (the event point) and `x` of its centre. Exact comparisons, needed only when
/// enclosures overlap, get the defining data from an [`Exact`].
#[derive(Debug, Clone, Copy)]
pub(crate) struct Circle {
    /// Enclosure `[lo, hi]` of the event's `y`.
    pub y: (f64, f64),
    /// Enclosure of the centre's `x`.
    pub x: (f64, f64),
}

/// What defines a circle event exactly: its three sites (in beach-line order, turning
/// clockwise), and in the small-integer case also its integer form.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Exact {
    /// The defining sites.
    pub sites: [Point2; 3],
    /// The integer form, when every site is a small integer ([`IntFrame`]).
    pub int: Option<(IntCircle, IntFrame)>,
}

/// All sites lie on a small grid: `(x0 + i·2⁻ᵏ, y0 + j·2⁻ᵏ)` with integers
/// `0 ≤ i, j < S = 2¹¹` and `0 ≤ k ≤ 300` (integer input has `k = 0`; `k > 0` covers dyadic
/// steps such as 0.5). Then the sweep's polynomials are evaluated in machine integers on
/// `(i, j)` (`i64`/`i128`, one 256-bit product at the very end of one predicate), exactly and
/// without any filter — signs do not change under translation and scaling by `2ᵏ`; the
/// bounds are stated where they are used. In `f64` every difference of two sites is a
/// multiple of `2⁻ᵏ` below `2¹¹·2⁻ᵏ`, so it is representable and computed exactly, and
/// the breakpoint polynomial (degree 3, at least `2⁻³ᵏ ≥ 2⁻⁹⁰⁰` when nonzero, below `2³⁵`
/// units) is exact too.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct IntFrame {
    x0: f64,
    y0: f64,
    /// `2ᵏ`.
    scale: f64,
    /// `2⁻ᵏ`.
    inv: f64,
}

/// A circle event in integer form (coordinates relative to the [`IntFrame`]): with
/// `D = 2 (B × C)` and `N` as in the module docs, `den = −D > 0`, the centre is
/// `(cxn, cyn) / den` and the radius `√(nx² + ny²) / den`. Bounds (`S = 2¹¹`, all
/// offsets below `S` in magnitude): `den ≤ 4S² = 2²⁴`, `|nx|, |ny| < 4S³ = 2³⁵`,
/// `|cxn|, |cyn| < S·den + 4S³ ≤ 2³⁶`, `Q = nx² + ny² < 2⁷¹`.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct IntCircle {
    den: i64,
    cxn: i64,
    cyn: i64,
    /// `Q = nx² + ny²`.
    q: i128,
}

impl IntCircle {
    #[inline]
    fn q(&self) -> i128 {
        self.q
    }
}

/// A rigorous enclosure of the computed interval `[lo, hi]` whose ends each carry at most a
/// few roundings relative to their own magnitude (the relative slack `1e-14` is ≫ `2^-53`).
fn widen(lo: f64, hi: f64) -> (f64, f64) {
    (
        lo - lo.abs() * 1e-14 - 1e-300,
        hi + hi.abs() * 1e-14 + 1e-300,
    )
}

/// Enclosure of a filter value `v` with error bound `e`.
fn enclose(v: f64, e: f64) -> (f64, f64) {
    let e = e * (1.0 + 1e-10);
    widen(v - e, v + e)
}

/// Enclosure of `a + [lo, hi]`: the sum may cancel, so the slack is relative to the
/// operands' magnitude.
fn shift(a: f64, lo: f64, hi: f64) -> (f64, f64) {
    let mag = (a.abs() + lo.abs().max(hi.abs())) * 1e-14 + 1e-300;
    (a + lo - mag, a + hi + mag)
}

/// Sign of `x + y √z` (with `z >= 0`) from the signs of `x`, `y` and of `x² − y² z`.
fn sign_plus_root(sx: Ordering, sy: Ordering, sq: impl FnOnce() -> Ordering) -> Ordering {
    if sy == Ordering::Equal {
        return sx;
    }
    if sx == Ordering::Equal || sx == sy {
        return if sx == Ordering::Equal { sy } else { sx };
    }
    match sq() {
        Ordering::Greater => sx,
        Ordering::Less => sy,
        Ordering::Equal => Ordering::Equal,
    }
}

impl IntFrame {
    /// The side of the box, `2¹¹`.
    const SPAN: f64 = 2048.0;

    /// The frame of `sites` if they lie on a small grid (see [`IntFrame`]). Offsets from
    /// the lower-left corner are checked to be exact (two-sum error zero), then the finest
    /// binary step `2⁻ᵏ` among them is found; the spans times `2ᵏ` must stay below 2048.
    /// (Spans are computed in `f64`: rounding is monotone and 2048 is a float, so the test
    /// `< 2048` is exact; scaling by `2ᵏ` is exact.) Random input fails at its first point.
    pub(crate) fn detect(sites: &[Point2]) -> Option<IntFrame> {
        const KMAX: i32 = 300;
        let first = sites.first()?;
        let (mut x0, mut y0, mut x1, mut y1) = (first.x, first.y, first.x, first.y);
        for p in sites {
            x0 = x0.min(p.x);
            x1 = x1.max(p.x);
            y0 = y0.min(p.y);
            y1 = y1.max(p.y);
        }
        let (wx, wy) = (x1 - x0, y1 - y0);
        // The exact offset v − o, or None if the subtraction rounds.
        let offset = |v: f64, o: f64| {
            let d = v - o;
            let bb = d - v;
            let err = (v - (d - bb)) + (-o - bb);
            (err == 0.0).then_some(d)
        };
        let mut k = 0i32;
        let mut scale = 1.0f64;
        for p in sites {
            for d in [offset(p.x, x0)?, offset(p.y, y0)?] {
                let mut t = d * scale;
                while t != t.trunc() {
                    t *= 2.0;
                    scale *= 2.0;
                    k += 1;
                    if k > KMAX {
                        return None;
                    }
                }
            }
            if !(wx * scale < Self::SPAN && wy * scale < Self::SPAN) {
                return None;
            }
        }
        Some(IntFrame {
            x0,
            y0,
            scale,
            inv: 2f64.powi(-k),
        })
    }

    /// Integer coordinates of a site relative to the frame (exact: the offset is exact, see
    /// [`IntFrame::detect`], and scaling by `2ᵏ` is exact).
    #[inline]
    fn coords(&self, p: Point2) -> (i64, i64) {
        (
            ((p.x - self.x0) * self.scale) as i64,
            ((p.y - self.y0) * self.scale) as i64,
        )
    }

    /// The circle event of the sites `a, b, c` (in beach-line order) if their breakpoints
    /// converge (`a, b, c` turn clockwise), in integer form and with enclosures.
    pub(crate) fn circle_event(
        &self,
        a: Point2,
        b: Point2,
        c: Point2,
    ) -> Option<(Circle, IntCircle)> {
        let (ax, ay) = self.coords(a);
        let (bx, by) = self.coords(b);
        let (cx, cy) = self.coords(c);
        let (bx, by, cx, cy) = (bx - ax, by - ay, cx - ax, cy - ay);
        let d = 2 * (bx * cy - by * cx);
        if d >= 0 {
            return None; // counter-clockwise or collinear: the breakpoints do not converge
        }
        let b2 = bx * bx + by * by;
        let c2 = cx * cx + cy * cy;
        let nx = cy * b2 - by * c2;
        let ny = bx * c2 - cx * b2;
        let den = -d;
        let ic = IntCircle {
            den,
            cxn: ax * den - nx,
            cyn: ay * den - ny,
            q: nx as i128 * nx as i128 + ny as i128 * ny as i128,
        };
        // Enclosures: den, cxn, cyn are exact in f64 (< 2⁵³); each of the quotients, the
        // conversion of Q, the square root and the final sums rounds once, a relative
        // error of at most 2⁻⁵³ of its own result, far inside the 1e-14 slack.
        let fd = den as f64;
        let cxr = ic.cxn as f64 / fd;
        let cyr = ic.cyn as f64 / fd;
        let r = (ic.q() as f64).sqrt() / fd;
        let y = cyr - r;
        let slack = (cyr.abs() + r + y.abs()) * 1e-14 + 1e-300;
        // Back to coordinates: times 2⁻ᵏ (exact unless it underflows, which the 1e-300 of
        // `shift` covers), plus the corner.
        let inv = self.inv;
        let xs = cxr.abs() * 1e-14 + 1e-300;
        let circle = Circle {
            y: shift(self.y0, (y - slack) * inv, (y + slack) * inv),
            x: shift(self.x0, (cxr - xs) * inv, (cxr + xs) * inv),
        };
        Some((circle, ic))
    }
}

/// Widening product of two `u128`: `(high, low)` halves of the 256-bit result.
fn mul_wide(a: u128, b: u128) -> (u128, u128) {
    const M: u128 = u64::MAX as u128;
    let (a1, a0) = (a >> 64, a & M);
    let (b1, b0) = (b >> 64, b & M);
    let p00 = a0 * b0;
    let p01 = a0 * b1;
    let p10 = a1 * b0;
    let p11 = a1 * b1;
    // < 3·2⁶⁴: no overflow.
    let mid = (p00 >> 64) + (p01 & M) + (p10 & M);
    let lo = (p00 & M) | (mid << 64);
    let hi = p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64);
    (hi, lo)
}

/// Offsets between sites at most this large (and, if nonzero, at least [`OFFSET_MIN`])
/// keep every product of up to three of them a normal number: no underflow, no overflow.
const OFFSET_MAX: f64 = 2.037035976334486e90; // 2^300
/// See [`OFFSET_MAX`].
const OFFSET_MIN: f64 = 4.909093465297727e-91; // 2^-300
/// `2⁻⁴⁸⁰`: a radius numerator at least this large has a square far above underflow.
const NORM_MIN: f64 = 3.2138760885179806e-145; // 2^-480

/// The circle event of the sites `a, b, c` (in beach-line order) if their breakpoints
/// converge (`a, b, c` turn clockwise), else `None`.
///
/// Fast path, plain `f64` with error bounds computed alongside (`u = 2⁻⁵³`; products and
/// sums named by their computed values). When the four offsets `b − a`, `c − a` are zero
/// or within `[2⁻³⁰⁰, 2³⁰⁰]`, no product below underflows or overflows and every rounding
/// is relative:
/// - `D = 2(p₁ − p₂)`, `p₁ = B_x C_y`, `p₂ = B_y C_x`: each `p` carries three roundings,
///   the difference one, so `|D̃ − D| ≤ e_D = 9u(|p₁| + |p₂|)`; `|D̃| > 4e_D` settles the
///   orientation (`D < 0`: clockwise) and gives `|D| ≥ ¾|D̃|`.
/// - `N_x = t₁ − t₂` with `t₁ = C_y|B|²`, `t₂ = B_y|C|²`: six roundings per term and one
///   more, `e_N = 8u(|t₁| + |t₂|)`; likewise `N_y`.
/// - `N/D − Ñ/D̃ = (ΔN·D − N·ΔD)/(D D̃)`, so the centre offset errs by at most
///   `(e_N + (|Ñ| + e_N)·e_D·(4/3)/|D̃|)/|D̃|` plus the division's `u|ũ|`.
/// - The radius numerator `R = |N|`: `||Ñ| − |N|| ≤ e_Nx + e_Ny` (triangle inequality) and
///   computing `|Ñ|` (two squares, a sum, a square root) errs by `2.1u·R̃` once
///   `R̃ ≥ 2⁻⁴⁸⁰` (an underflowed square is then negligible); `r = R/|D|` as for `ũ`.
/// - `y = a.y + u_y − r` and `x = a.x + u_x`: two and one more roundings.
///
/// The total is scaled by `1 + 2⁻²⁰` for the bound's own roundings and padded by `1e-300`
/// absolute (underflow in the bound). Anything else (tiny or huge offsets, nearly collinear
/// sites, overflow) goes to [`circle_event_filtered`].
pub(crate) fn circle_event(a: Point2, b: Point2, c: Point2) -> Option<Circle> {
    const U: f64 = 1.0 / 9_007_199_254_740_992.0;
    let (bx, by) = (b.x - a.x, b.y - a.y);
    let (cx, cy) = (c.x - a.x, c.y - a.y);
    let in_range = |v: f64| v == 0.0 || (v.abs() >= OFFSET_MIN && v.abs() <= OFFSET_MAX);
    if !(in_range(bx) && in_range(by) && in_range(cx) && in_range(cy)) {
        return circle_event_filtered(a, b, c);
    }
    let (p1, p2) = (bx * cy, by * cx);
    let d = 2.0 * (p1 - p2);
    let ed = 9.0 * U * (p1.abs() + p2.abs());
    if d > 4.0 * ed {
        return None; // counter-clockwise, certainly
    }
    // Also catches NaN (overflowed products).
    if (-d).partial_cmp(&(4.0 * ed)) != Some(Ordering::Greater) {
        return circle_event_filtered(a, b, c);
    }
    let b2 = bx * bx + by * by;
    let c2 = cx * cx + cy * cy;
    let (tx1, tx2) = (cy * b2, by * c2);
    let (ty1, ty2) = (bx * c2, cx * b2);
    let nx = tx1 - tx2;
    let ny = ty1 - ty2;
    let enx = 8.0 * U * (tx1.abs() + tx2.abs());
    let eny = 8.0 * U * (ty1.abs() + ty2.abs());
    let ad = d.abs();
    let k = ed * (4.0 / 3.0) / ad;
    let ux = nx / d;
    let uy = ny / d;
    let eux = (enx + (nx.abs() + enx) * k) / ad + U * ux.abs();
    let euy = (eny + (ny.abs() + eny) * k) / ad + U * uy.abs();
    let rn = (nx * nx + ny * ny).sqrt();
    // Also catches NaN.
    if !matches!(
        rn.partial_cmp(&NORM_MIN),
        Some(Ordering::Greater | Ordering::Equal)
    ) {
        return circle_event_filtered(a, b, c);
    }
    let er_n = enx + eny + 2.1 * U * rn;
    let r = rn / ad;
    let er = (er_n + (rn + er_n) * k) / ad + U * r;
    let x = a.x + ux;
    let y = (a.y + uy) - r;
    let safety = 1.0 + 1.0 / 1_048_576.0;
    let ex = (eux + U * x.abs()) * safety + 1e-300;
    let ey = (euy + er + 1.01 * U * (a.y.abs() + uy.abs() + y.abs())) * safety + 1e-300;
    let circle = Circle {
        y: (y - ey, y + ey),
        x: (x - ex, x + ex),
    };
    if [circle.x.0, circle.x.1, circle.y.0, circle.y.1]
        .iter()
        .all(|v| v.is_finite())
    {
        Some(circle)
    } else {
        circle_event_filtered(a, b, c)
    }
}

/// [`circle_event`] with the orientation from the exact `orient2d` and the enclosures from
/// the running-error filter (slower, but never undecided).
pub(crate) fn circle_event_filtered(a: Point2, b: Point2, c: Point2) -> Option<Circle> {
    if orient2d(a, b, c) != Orientation::Clockwise {
        return None;
    }
    // Enclosures from the filter: centre a + N/D (D < 0), radius √(Nx² + Ny²)/|D|.
    let (d, nx, ny) = circle_parts::<Bounded>(a, b, c);
    let (dv, de) = d.parts();
    let (nxv, nxe) = nx.parts();
    let (nyv, nye) = ny.parts();
    let (dl, dh) = enclose(dv, de);
    let (xl, xh) = enclose(nxv, nxe);
    let (yl, yh) = enclose(nyv, nye);
    let wide = (f64::NEG_INFINITY, f64::INFINITY);
    let ok = dh < 0.0 && [dl, xl, xh, yl, yh].iter().all(|v| v.is_finite());
    if !ok {
        return Some(Circle { y: wide, x: wide });
    }
    // Quotients of enclosures by a negative enclosure: extremes at the corners.
    let div = |lo: f64, hi: f64| {
        let cands = [lo / dl, lo / dh, hi / dl, hi / dh];
        let mn = cands.iter().cloned().fold(f64::INFINITY, f64::min);
        let mx = cands.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
        widen(mn, mx)
    };
    let (ux_l, ux_h) = div(xl, xh);
    let (uy_l, uy_h) = div(yl, yh);
    let sq = |l: f64, h: f64| {
        if l <= 0.0 && h >= 0.0 {
            (0.0, l.abs().max(h.abs()).powi(2))
        } else {
            let (a2, b2) = (l * l, h * h);
            (a2.min(b2), a2.max(b2))
        }
    };
    let (sxl, sxh) = sq(ux_l, ux_h);
    let (syl, syh) = sq(uy_l, uy_h);
    // Sums of non-negative terms and square roots: relative slack suffices.
    let (r2l, r2h) = widen(sxl + syl, sxh + syh);
    let (rl, rh) = widen(r2l.max(0.0).sqrt(), r2h.sqrt());
    let x = shift(a.x, ux_l, ux_h);
    // a.y + uy − r may cancel: slack relative to all three magnitudes.
    let mag = (a.y.abs() + uy_l.abs().max(uy_h.abs()) + rh) * 1e-14 + 1e-300;
    let y = (a.y + uy_l - rh - mag, a.y + uy_h - rl + mag);
    if [x.0, x.1, y.0, y.1].iter().all(|v| v.is_finite()) {
        Some(Circle { y, x })
    } else {
        Some(Circle { y: wide, x: wide })
    }
}

/// The circumcentre of `a, b, c` in `f64` (for output; `a, b, c` not collinear).
///
/// The offsets from `a` are scaled by a power of two to magnitude about 1 first (exact), so
/// that squares neither overflow for huge coordinates nor underflow for tiny ones.
#[inline]
pub(crate) fn circumcentre(a: Point2, b: Point2, c: Point2) -> Point2 {
    let (bx, by) = (b.x - a.x, b.y - a.y);
    let (cx, cy) = (c.x - a.x, c.y - a.y);
    // Offsets that are zero or between 2⁻¹⁰⁰ and 2¹⁰⁰ in magnitude: no operation below
    // underflows or overflows (products ≥ 2⁻²⁰⁰, nonzero differences of them ≥ 2⁻²⁵²,
    // quotients within 2^±560), so scaling by a power of two would change nothing and
    // is skipped — the result is bit for bit the same.
    let ok =
        |v: f64| v == 0.0 || (v.abs() >= 7.888609052210118e-31 && v.abs() <= 1.2676506002282294e30);
    if ok(bx) && ok(by) && ok(cx) && ok(cy) {
        let b2 = bx * bx + by * by;
        let c2 = cx * cx + cy * cy;
        let d = 2.0 * (bx * cy - by * cx);
        let (ux, uy) = ((cy * b2 - by * c2) / d, (bx * c2 - cx * b2) / d);
        return Point2::new(a.x + ux, a.y + uy);
    }
    let m = bx.abs().max(by.abs()).max(cx.abs()).max(cy.abs());
    let e = if m > 0.0 && m.is_finite() {
        m.log2().floor() as i32
    } else {
        0
    };
    // Two factors: 2^-e alone may not be representable at the ends of the range.
    let (k1, k2) = (2f64.powi(-e / 2), 2f64.powi(-e + e / 2));
    let (bx, by, cx, cy) = (bx * k1 * k2, by * k1 * k2, cx * k1 * k2, cy * k1 * k2);
    let b2 = bx * bx + by * by;
    let c2 = cx * cx + cy * cy;
    let d = 2.0 * (bx * cy - by * cx);
    let (ux, uy) = ((cy * b2 - by * c2) / d, (bx * c2 - cx * b2) / d);
    Point2::new(a.x + ux / k1 / k2, a.y + uy / k1 / k2)
}

/// Sign of `(event y) − s.y`, exactly.
fn cmp_event_y_site<T: Arith>(e: &[Point2; 3], s: Point2) -> Option<Ordering> {
    // y_e − s.y = (a.y − s.y) + N_y/D − √(N_x²+N_y²)/|D|; times |D| = −D:
    //   P − √Q with P = −D (a.y − s.y) − N_y, Q = N_x² + N_y².
    let [a, b, c] = *e;
    let (d, nx, ny) = circle_parts::<T>(a, b, c);
    let p = neg(&d).times(&T::diff(a.y, s.y)).minus(&ny);
    let q = nx.times(&nx).plus(&ny.times(&ny));
    let sp = p.sign()?;
    if sp != Ordering::Greater {
        // Q > 0 (distinct sites): P − √Q < 0.
        return Some(Ordering::Less);
    }
    p.times(&p).minus(&q).sign()
}

/// Sign of `(event centre x) − s.x`, exactly.
fn cmp_event_x_site<T: Arith>(e: &[Point2; 3], s: Point2) -> Option<Ordering> {
    // (a.x − s.x) + N_x/D, times −D > 0.
    let [a, b, c] = *e;
    let (d, nx, _) = circle_parts::<T>(a, b, c);
    neg(&d).times(&T::diff(a.x, s.x)).minus(&nx).sign()
}

/// [`cmp_event_y_site`] in integers: `y_e − s.y = (P − √Q)/den` with `P = cyn − s.y·den`,
/// `|P| < 2³⁶ + 2¹¹·2²⁴`, so `P² < 2⁷⁵`.
fn cmp_event_y_site_int(e: &IntCircle, sy: i64) -> Ordering {
    let p = e.cyn as i128 - sy as i128 * e.den as i128;
    if p <= 0 {
        return Ordering::Less;
    }
    (p * p).cmp(&e.q())
}

/// [`cmp_event_x_site`] in integers: the sign of `cxn − s.x·den`.
fn cmp_event_x_site_int(e: &IntCircle, sx: i64) -> Ordering {
    (e.cxn as i128 - sx as i128 * e.den as i128).cmp(&0)
}

/// Order of a circle event and a site event in the sweep (`Less` = processed first):
/// larger `y` first, then smaller `x`; on an exact tie the circle event comes first.
/// `exact` gives the event's defining data; it is called only when the enclosures do not
/// decide.
pub(crate) fn cmp_event_site(e: &Circle, exact: impl FnOnce() -> Exact, s: Point2) -> Ordering {
    if e.y.0 > s.y {
        return Ordering::Less;
    }
    if e.y.1 < s.y {
        return Ordering::Greater;
    }
    let ex = exact();
    if let Some((ic, frame)) = ex.int {
        return cmp_event_site_int(e, &ic, &frame, s);
    }
    let t = &ex.sites;
    let dy = decide(
        || cmp_event_y_site::<Bounded>(t, s),
        || {
            cmp_event_y_site::<Exactish>(t, s)
                .or_else(|| cmp_event_y_site::<Dyadic>(t, s))
                .unwrap_or(Ordering::Equal)
        },
    );
    match dy {
        Ordering::Greater => Ordering::Less,
        Ordering::Less => Ordering::Greater,
        Ordering::Equal => {
            let dx = if e.x.1 < s.x {
                Ordering::Less
            } else if e.x.0 > s.x {
                Ordering::Greater
            } else {
                decide(
                    || cmp_event_x_site::<Bounded>(t, s),
                    || {
                        cmp_event_x_site::<Exactish>(t, s)
                            .or_else(|| cmp_event_x_site::<Dyadic>(t, s))
                            .unwrap_or(Ordering::Equal)
                    },
                )
            };
            match dx {
                Ordering::Greater => Ordering::Greater,
                _ => Ordering::Less,
            }
        }
    }
}

/// [`cmp_event_site`] for an event in integer form (`s` a site of the frame).
#[inline]
pub(crate) fn cmp_event_site_int(
    e: &Circle,
    ic: &IntCircle,
    frame: &IntFrame,
    s: Point2,
) -> Ordering {
    if e.y.0 > s.y {
        return Ordering::Less;
    }
    if e.y.1 < s.y {
        return Ordering::Greater;
    }
    let (sx, sy) = frame.coords(s);
    match cmp_event_y_site_int(ic, sy) {
        Ordering::Greater => Ordering::Less,
        Ordering::Less => Ordering::Greater,
        Ordering::Equal => match cmp_event_x_site_int(ic, sx) {
            Ordering::Greater => Ordering::Greater,
            _ => Ordering::Less,
        },
    }
}

/// Sign of `y_e − y_f` for two events, exactly.
fn cmp_events_y<T: Arith>(e: &[Point2; 3], f: &[Point2; 3]) -> Option<Ordering> {
    // y = a.y + (−N_y − √Q)/(−D) with −D > 0. Let E = −D_e, G = −D_f (both > 0),
    // P_e = −N_ye, P_f = −N_yf. Times E·G:
    //   X + √(E² Q_f) − √(G² Q_e), X = E G (a_e.y − a_f.y) + G P_e − E P_f.
    let (a1, a2) = (e[0], f[0]);
    let (d1, nx1, ny1) = circle_parts::<T>(e[0], e[1], e[2]);
    let (d2, nx2, ny2) = circle_parts::<T>(f[0], f[1], f[2]);
    let ee = neg(&d1);
    let gg = neg(&d2);
    let q1 = nx1.times(&nx1).plus(&ny1.times(&ny1));
    let q2 = nx2.times(&nx2).plus(&ny2.times(&ny2));
    let x = ee
        .times(&gg)
        .times(&T::diff(a1.y, a2.y))
        .minus(&gg.times(&ny1))
        .plus(&ee.times(&ny2));
    let bb = ee.times(&ee).times(&q2);
    let aa = gg.times(&gg).times(&q1);
    // t = X + √B; its sign.
    let sx = x.sign()?;
    let st = match sx {
        Ordering::Greater => Ordering::Greater,
        _ => {
            // B > 0, so X = 0 gives t > 0; X < 0: sign(B − X²).
            if sx == Ordering::Equal {
                Ordering::Greater
            } else {
                bb.minus(&x.times(&x)).sign()?
            }
        }
    };
    if st != Ordering::Greater {
        // t <= 0 and √A > 0.
        return Some(Ordering::Less);
    }
    // t > 0: sign(t² − A) = sign(E + F√B), E = X² + B − A, F = 2X.
    let e2 = x.times(&x).plus(&bb).minus(&aa);
    let se = e2.sign()?;
    let sf = sx;
    let mut undecided = false;
    let r = sign_plus_root(se, sf, || {
        let two = T::val(2.0);
        let f2 = two.times(&x);
        match e2.times(&e2).minus(&f2.times(&f2).times(&bb)).sign() {
            Some(o) => o,
            None => {
                undecided = true;
                Ordering::Equal
            }
        }
    });
    if undecided {
        None
    } else {
        Some(r)
    }
}

/// Sign of `x_e − x_f` (centres), exactly.
fn cmp_events_x<T: Arith>(e: &[Point2; 3], f: &[Point2; 3]) -> Option<Ordering> {
    // x = a.x + (−N_x)/(−D); times E·G: E G (a_e.x − a_f.x) − G N_xe + E N_xf.
    let (a1, a2) = (e[0], f[0]);
    let (d1, nx1, _) = circle_parts::<T>(e[0], e[1], e[2]);
    let (d2, nx2, _) = circle_parts::<T>(f[0], f[1], f[2]);
    let ee = neg(&d1);
    let gg = neg(&d2);
    ee.times(&gg)
        .times(&T::diff(a1.x, a2.x))
        .minus(&gg.times(&nx1))
        .plus(&ee.times(&nx2))
        .sign()
}

/// [`cmp_events_y`] in integers, the same steps. `y_e − y_f` times `den_e·den_f` is
/// `X + √B − √A` with `X = cyn_e·den_f − cyn_f·den_e` (`|X| < 2⁶¹`), `A = Q_e·den_f²`,
/// `B = Q_f·den_e²` (both `< 2⁷¹·2⁴⁸ = 2¹¹⁹`); `E = X² + B − A` has `|E| < 2¹²³`, all in
/// `i128`. The last step compares `E²` (`< 2²⁴⁶`) with `4X²·B` (`< 2¹²⁴·2¹¹⁹`) as 256-bit
/// products.
fn cmp_events_y_int(e: &IntCircle, f: &IntCircle) -> Ordering {
    let (de, df) = (e.den as i128, f.den as i128);
    let x = e.cyn as i128 * df - f.cyn as i128 * de;
    let a = e.q() * df * df;
    let b = f.q() * de * de;
    let sx = x.cmp(&0);
    if sx == Ordering::Equal {
        // The common exact tie (a grid row): the sign of √B − √A.
        return b.cmp(&a);
    }
    let st = if sx == Ordering::Less {
        (b - x * x).cmp(&0)
    } else {
        Ordering::Greater // B > 0
    };
    if st != Ordering::Greater {
        return Ordering::Less;
    }
    let e2 = x * x + b - a;
    sign_plus_root(e2.cmp(&0), sx, || {
        let lhs = mul_wide(e2.unsigned_abs(), e2.unsigned_abs());
        let x2 = x.unsigned_abs() * x.unsigned_abs();
        let rhs = mul_wide(4 * x2, b.unsigned_abs());
        lhs.cmp(&rhs)
    })
}

/// [`cmp_events_x`] in integers: the sign of `cxn_e·den_f − cxn_f·den_e` (`< 2⁶¹`).
fn cmp_events_x_int(e: &IntCircle, f: &IntCircle) -> Ordering {
    (e.cxn as i128 * f.den as i128 - f.cxn as i128 * e.den as i128).cmp(&0)
}

/// Order of two circle events in the sweep (`Less` = processed first): larger `y` first,
/// then smaller centre `x`; `Equal` when the lowest points coincide (for two events that
/// share two sites this means the same circle). `exact_*` are called only when the
/// enclosures do not decide.
pub(crate) fn cmp_events(
    e: &Circle,
    exact_e: impl FnOnce() -> Exact,
    f: &Circle,
    exact_f: impl FnOnce() -> Exact,
) -> Ordering {
    let x_by_enclosure = || {
        if e.x.1 < f.x.0 {
            Some(Ordering::Less)
        } else if e.x.0 > f.x.1 {
            Some(Ordering::Greater)
        } else {
            None
        }
    };
    if e.y.0 > f.y.1 {
        return Ordering::Less;
    }
    if e.y.1 < f.y.0 {
        return Ordering::Greater;
    }
    let (ee, ff) = (exact_e(), exact_f());
    if let (Some((ie, _)), Some((jf, _))) = (ee.int, ff.int) {
        return cmp_events_int(e, &ie, f, &jf);
    }
    let (t, u) = (&ee.sites, &ff.sites);
    let dy = decide(
        || cmp_events_y::<Bounded>(t, u),
        || {
            cmp_events_y::<Exactish>(t, u)
                .or_else(|| cmp_events_y::<Dyadic>(t, u))
                .unwrap_or(Ordering::Equal)
        },
    );
    match dy {
        Ordering::Greater => Ordering::Less,
        Ordering::Less => Ordering::Greater,
        Ordering::Equal => x_by_enclosure().unwrap_or_else(|| {
            decide(
                || cmp_events_x::<Bounded>(t, u),
                || {
                    cmp_events_x::<Exactish>(t, u)
                        .or_else(|| cmp_events_x::<Dyadic>(t, u))
                        .unwrap_or(Ordering::Equal)
                },
            )
        }),
    }
}

/// [`cmp_events`] for two events in integer form.
#[inline]
pub(crate) fn cmp_events_int(e: &Circle, ie: &IntCircle, f: &Circle, jf: &IntCircle) -> Ordering {
    if e.y.0 > f.y.1 {
        return Ordering::Less;
    }
    if e.y.1 < f.y.0 {
        return Ordering::Greater;
    }
    match cmp_events_y_int(ie, jf) {
        Ordering::Greater => Ordering::Less,
        Ordering::Less => Ordering::Greater,
        Ordering::Equal => {
            if e.x.1 < f.x.0 {
                Ordering::Less
            } else if e.x.0 > f.x.1 {
                Ordering::Greater
            } else {
                cmp_events_x_int(ie, jf)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigUint;

    #[test]
    fn constants() {
        assert_eq!(NORMAL_ENOUGH, 2f64.powi(-960));
    }

    use proptest::prelude::*;

    /// Lattice points on x² + y² = 5525 (many: a cocircular set).
    fn lattice_circle() -> Vec<(i32, i32)> {
        let mut v = Vec::new();
        for x in -75i32..=75 {
            for y in -75i32..=75 {
                if x * x + y * y == 5525 {
                    v.push((x, y));
                }
            }
        }
        v
    }

    /// Degenerate-on-purpose points: a small integer grid, lattice-circle points, random
    /// reals; then scaled by a power of two and offset (per test case, all points alike).
    fn raw_point() -> impl Strategy<Value = (f64, f64)> {
        let circle = lattice_circle();
        prop_oneof![
            (0i32..7, 0i32..7).prop_map(|(x, y)| (x as f64, y as f64)),
            (0..circle.len()).prop_map(move |i| (circle[i].0 as f64, circle[i].1 as f64)),
            (-1e3f64..1e3, -1e3f64..1e3),
            // One ulp away from a grid point.
            (0i32..7, 0i32..7, any::<bool>()).prop_map(|(x, y, up)| {
                let y = y as f64 + 1.0;
                (x as f64, if up { y.next_up() } else { y.next_down() })
            }),
        ]
    }

    fn frame() -> impl Strategy<Value = (f64, f64)> {
        prop_oneof![
            Just((1.0, 0.0)),
            Just((1.0, 1e6)),
            Just((1.0, 2f64.powi(40))),
            (-1000i32..900).prop_map(|k| (2f64.powi(k), 0.0)),
            Just((0.5, 0.0)),
            Just((2f64.powi(-1000), 0.0)),
            Just((2f64.powi(900), 0.0)),
        ]
    }

    fn points(n: usize) -> impl Strategy<Value = Vec<Point2>> {
        (frame(), prop::collection::vec(raw_point(), n)).prop_map(|((k, off), v)| {
            v.into_iter()
                .map(|(x, y)| Point2::new(x * k + off, y * k + off))
                .collect()
        })
    }

    /// The enclosures of `c` contain the exact event `y` and centre `x` (decided by the
    /// exact dyadic predicates).
    fn assert_encloses(t: &[Point2; 3], c: &Circle) {
        if !(c.y.0.is_finite() && c.y.1.is_finite() && c.x.0.is_finite() && c.x.1.is_finite()) {
            return; // the "undecided" enclosure
        }
        let ys = |y: f64| cmp_event_y_site::<Dyadic>(t, Point2::new(0.0, y)).unwrap();
        let xs = |x: f64| cmp_event_x_site::<Dyadic>(t, Point2::new(x, 0.0)).unwrap();
        assert_ne!(
            ys(c.y.0),
            Ordering::Less,
            "y below the enclosure for {t:?}: {c:?}"
        );
        assert_ne!(
            ys(c.y.1),
            Ordering::Greater,
            "y above the enclosure for {t:?}: {c:?}"
        );
        assert_ne!(
            xs(c.x.0),
            Ordering::Less,
            "x left of the enclosure for {t:?}: {c:?}"
        );
        assert_ne!(
            xs(c.x.1),
            Ordering::Greater,
            "x right of the enclosure for {t:?}: {c:?}"
        );
    }

    fn exact_order(e: &[Point2; 3], f: &[Point2; 3]) -> Ordering {
        match cmp_events_y::<Dyadic>(e, f).unwrap() {
            Ordering::Greater => Ordering::Less,
            Ordering::Less => Ordering::Greater,
            Ordering::Equal => cmp_events_x::<Dyadic>(e, f).unwrap(),
        }
    }

    fn exact_order_site(e: &[Point2; 3], s: Point2) -> Ordering {
        match cmp_event_y_site::<Dyadic>(e, s).unwrap() {
            Ordering::Greater => Ordering::Less,
            Ordering::Less => Ordering::Greater,
            Ordering::Equal => match cmp_event_x_site::<Dyadic>(e, s).unwrap() {
                Ordering::Greater => Ordering::Greater,
                _ => Ordering::Less,
            },
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]

        /// The fast circle event agrees with the exact orientation, and its enclosures
        /// (and those of the filtered and the integer versions) contain the exact values.
        #[test]
        fn fast_circle_events_enclose_the_exact_event(p in points(3)) {
            let t = [p[0], p[1], p[2]];
            let cw = orient2d(t[0], t[1], t[2]) == Orientation::Clockwise;
            let fast = circle_event(t[0], t[1], t[2]);
            let slow = circle_event_filtered(t[0], t[1], t[2]);
            prop_assert_eq!(fast.is_some(), cw);
            prop_assert_eq!(slow.is_some(), cw);
            if let (Some(f), Some(s)) = (fast, slow) {
                assert_encloses(&t, &f);
                assert_encloses(&t, &s);
            }
            if let Some(frame) = IntFrame::detect(&t) {
                let int = frame.circle_event(t[0], t[1], t[2]);
                prop_assert_eq!(int.is_some(), cw);
                if let Some((c, _)) = int {
                    assert_encloses(&t, &c);
                }
            }
        }

        /// The cheap breakpoint filter (and the integer shortcut) agree with the exact sign.
        #[test]
        fn fast_breakpoint_sign_is_exact(p in points(3)) {
            let (q, pi, pj) = (p[0], p[1], p[2]);
            let want = sign_exact(&lower_poly::<Dyadic>(q, pi, pj));
            prop_assert_eq!(lower_sign(q, pi, pj, false), want);
            if IntFrame::detect(&p).is_some() {
                prop_assert_eq!(lower_sign(q, pi, pj, true), want);
            }
        }

        /// Sites placed (to rounding) right on a breakpoint, and their float neighbours:
        /// the cheap filter must never give a wrong sign there.
        #[test]
        fn breakpoint_sign_near_the_breakpoint(p in points(2), drop in 0.01f64..100.0, k in 0usize..3) {
            let (pi, pj) = (p[0], p[1]);
            let l = pi.y.min(pj.y) - drop * (pi.y - pj.y).abs().max(pi.x - pj.x).abs().max(1e-300);
            prop_assume!(l.is_finite() && l < pi.y.min(pj.y));
            let (dyi, dyj) = (l - pi.y, l - pj.y);
            // F(x) = dyi·((x − pj.x)² + dyj²) − dyj·((x − pi.x)² + dyi²), a quadratic.
            let a = dyi - dyj;
            let b = -2.0 * (dyi * pj.x - dyj * pi.x);
            let c = dyi * (pj.x * pj.x + dyj * dyj) - dyj * (pi.x * pi.x + dyi * dyi);
            let mut roots = vec![];
            if a == 0.0 {
                roots.push(-c / b);
            } else {
                let disc = (b * b - 4.0 * a * c).max(0.0).sqrt();
                roots.push((-b + disc) / (2.0 * a));
                roots.push((-b - disc) / (2.0 * a));
            }
            for r in roots.into_iter().filter(|r| r.is_finite()) {
                let x = [r, r.next_up(), r.next_down()][k];
                let q = Point2::new(x, l);
                let want = sign_exact(&lower_poly::<Dyadic>(q, pi, pj));
                prop_assert_eq!(lower_sign(q, pi, pj, false), want);
                if IntFrame::detect(&[q, pi, pj]).is_some() {
                    prop_assert_eq!(lower_sign(q, pi, pj, true), want);
                }
            }
        }

        /// Integer event comparisons agree with the exact dyadic ones (grids, lattice
        /// circles: many exact ties).
        #[test]
        fn integer_event_order_is_exact(p in prop::collection::vec(raw_point(), 7), k in -20i32..20, off in prop_oneof![Just(0.0), Just(3.0), Just(1e9)]) {
            let s = 2f64.powi(k);
            let p: Vec<Point2> = p.into_iter().map(|(x, y)| Point2::new(x.round() * s + off, y.round() * s + off)).collect();
            let Some(frame) = IntFrame::detect(&p) else { return Ok(()) };
            let (e, f) = ([p[0], p[1], p[2]], [p[3], p[4], p[5]]);
            let (Some((ce, ie)), Some((cf, jf))) = (
                frame.circle_event(e[0], e[1], e[2]),
                frame.circle_event(f[0], f[1], f[2]),
            ) else {
                return Ok(());
            };
            prop_assert_eq!(cmp_events_int(&ce, &ie, &cf, &jf), exact_order(&e, &f));
            prop_assert_eq!(cmp_events_int(&ce, &ie, &ce, &ie), Ordering::Equal);
            // The same circle through other sites of it compares equal.
            let g = [e[1], e[2], e[0]];
            if let Some((cg, ig)) = frame.circle_event(g[0], g[1], g[2]) {
                prop_assert_eq!(cmp_events_int(&ce, &ie, &cg, &ig), Ordering::Equal);
            }
            prop_assert_eq!(cmp_event_site_int(&ce, &ie, &frame, p[6]), exact_order_site(&e, p[6]));
            // The general comparisons (filter, exact-in-f64, dyadic) agree too.
            let ex = |t: [Point2; 3]| move || Exact { sites: t, int: None };
            let (ge, gf) = (circle_event(e[0], e[1], e[2]).unwrap(), circle_event(f[0], f[1], f[2]).unwrap());
            prop_assert_eq!(cmp_events(&ge, ex(e), &gf, ex(f)), exact_order(&e, &f));
            prop_assert_eq!(cmp_event_site(&ge, ex(e), p[6]), exact_order_site(&e, p[6]));
        }
    }

    /// Events of a grid row tie exactly in `y`; at the same point they are equal.
    #[test]
    fn grid_ties() {
        let p = |x: f64, y: f64| Point2::new(x, y);
        let pts = [
            p(0.0, 1.0),
            p(0.0, 0.0),
            p(1.0, 0.0),
            p(5.0, 1.0),
            p(5.0, 0.0),
            p(6.0, 0.0),
            p(1.0, 1.0),
        ];
        let frame = IntFrame::detect(&pts).unwrap();
        // Clockwise triples (beach-line order).
        let (ca, ia) = frame.circle_event(pts[2], pts[1], pts[0]).unwrap();
        let (cb, ib) = frame.circle_event(pts[5], pts[4], pts[3]).unwrap();
        let (cc, ic) = frame.circle_event(pts[6], pts[2], pts[0]).unwrap();
        assert_eq!(cmp_events_y_int(&ia, &ib), Ordering::Equal);
        assert_eq!(cmp_events_int(&ca, &ia, &cb, &ib), Ordering::Less);
        assert_eq!(cmp_events_int(&cb, &ib, &ca, &ia), Ordering::Greater);
        assert_eq!(cmp_events_int(&ca, &ia, &cc, &ic), Ordering::Equal);
    }

    #[test]
    fn wide_products_are_exact() {
        let vals = [
            0u128,
            1,
            3,
            u64::MAX as u128,
            (u64::MAX as u128) + 1,
            u128::MAX,
            u128::MAX / 3,
            0x1234_5678_9abc_def0_1357_9bdf_2468_ace0,
            (1u128 << 124) - 1,
        ];
        for &a in &vals {
            for &b in &vals {
                let (hi, lo) = mul_wide(a, b);
                let got = (BigUint::from(hi) << 128u32) + BigUint::from(lo);
                assert_eq!(got, BigUint::from(a) * BigUint::from(b), "{a} * {b}");
            }
        }
    }
}
