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
//! coordinate comparison ([`left_of_breakpoint`]); sites on the sweep line (degenerate
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
//! see [`cmp_event_site`] and [`cmp_events`].
//!
//! Every polynomial is written once, generically over the kernel's arithmetic interface,
//! and evaluated first in `f64` with a rigorous running error bound (the kernel's filter)
//! and only when that cannot decide, with exact dyadic big-integer arithmetic.

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

/// Sign of `F` (see [`lower_poly`]), exactly.
fn lower_sign(q: Point2, pi: Point2, pj: Point2) -> Ordering {
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
pub(crate) fn left_of_breakpoint(q: Point2, pi: Point2, pj: Point2) -> bool {
    let l = q.y;
    match (pi.y == l, pj.y == l) {
        // Both on the sweep line (the start of the sweep): the breakpoint is on their
        // bisector, a vertical line.
        (true, true) => cmp_dist(q, pi, pj) == Ordering::Less,
        // A site on the sweep line has a degenerate arc: the vertical ray above it.
        (true, false) => q.x < pi.x,
        (false, true) => q.x < pj.x,
        (false, false) => {
            let f = lower_sign(q, pi, pj);
            match pi.y.partial_cmp(&pj.y) {
                // Equal heights: one crossing; left of it the left site's arc is lower.
                Some(Ordering::Equal) | None => f == Ordering::Less,
                // pi farther from the sweep (wider arc): the breakpoint is the left
                // crossing x1, and the focus of pj lies between the crossings.
                Some(Ordering::Greater) => q.x < pj.x && f == Ordering::Less,
                // pi nearer (narrower): the breakpoint is the right crossing x2, and the
                // focus of pi lies between the crossings.
                Some(Ordering::Less) => q.x < pi.x || f == Ordering::Less,
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

/// A circle event: the triple of sites (in beach-line order, turning clockwise) whose
/// circle's lowest point is the event point.
#[derive(Debug, Clone, Copy)]
pub(crate) struct CircleKey {
    /// The defining sites.
    pub sites: [Point2; 3],
    /// Enclosure `[lo, hi]` of the event's `y` (lowest point of the circle).
    pub y: (f64, f64),
    /// Enclosure of the centre's `x`.
    pub x: (f64, f64),
    /// `(D, N_x, N_y)` when they are exactly representable in `f64` (computed without any
    /// rounding, e.g. for integer grids): comparisons then start from these exact values
    /// instead of recomputing them.
    pub exact_parts: Option<[f64; 3]>,
}

/// The circle parts of an event: the cached exact values, or computed in `T`.
fn parts<T: Arith>(e: &CircleKey) -> (T, T, T) {
    match e.exact_parts {
        Some([d, x, y]) => (T::val(d), T::val(x), T::val(y)),
        None => {
            let [a, b, c] = e.sites;
            circle_parts::<T>(a, b, c)
        }
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

impl CircleKey {
    /// The event of `a, b, c` if their breakpoints converge (`a, b, c` turn clockwise),
    /// else `None`.
    pub(crate) fn new(a: Point2, b: Point2, c: Point2) -> Option<CircleKey> {
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
        let (x, y) = if ok {
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
                (x, y)
            } else {
                (wide, wide)
            }
        } else {
            (wide, wide)
        };
        let (ed, ex, ey) = circle_parts::<Exactish>(a, b, c);
        let exact_parts = (ed.exact && ex.exact && ey.exact).then_some([ed.v, ex.v, ey.v]);
        Some(CircleKey {
            sites: [a, b, c],
            y,
            x,
            exact_parts,
        })
    }

    /// The centre, rounded (for output only; topology never depends on it).
    pub(crate) fn approx_centre(&self) -> Point2 {
        circumcentre(self.sites[0], self.sites[1], self.sites[2])
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
fn cmp_event_y_site<T: Arith>(e: &CircleKey, s: Point2) -> Option<Ordering> {
    // y_e − s.y = (a.y − s.y) + N_y/D − √(N_x²+N_y²)/|D|; times |D| = −D:
    //   P − √Q with P = −D (a.y − s.y) − N_y, Q = N_x² + N_y².
    let a = e.sites[0];
    let (d, nx, ny) = parts::<T>(e);
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
fn cmp_event_x_site<T: Arith>(e: &CircleKey, s: Point2) -> Option<Ordering> {
    // (a.x − s.x) + N_x/D, times −D > 0.
    let a = e.sites[0];
    let (d, nx, _) = parts::<T>(e);
    neg(&d).times(&T::diff(a.x, s.x)).minus(&nx).sign()
}

/// Order of a circle event and a site event in the sweep (`Less` = processed first):
/// larger `y` first, then smaller `x`; on an exact tie the circle event comes first.
pub(crate) fn cmp_event_site(e: &CircleKey, s: Point2) -> Ordering {
    if e.y.0 > s.y {
        return Ordering::Less;
    }
    if e.y.1 < s.y {
        return Ordering::Greater;
    }
    let dy = decide(
        || cmp_event_y_site::<Bounded>(e, s),
        || {
            cmp_event_y_site::<Exactish>(e, s)
                .or_else(|| cmp_event_y_site::<Dyadic>(e, s))
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
                    || cmp_event_x_site::<Bounded>(e, s),
                    || {
                        cmp_event_x_site::<Exactish>(e, s)
                            .or_else(|| cmp_event_x_site::<Dyadic>(e, s))
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

/// Sign of `y_e − y_f` for two events, exactly.
fn cmp_events_y<T: Arith>(e: &CircleKey, f: &CircleKey) -> Option<Ordering> {
    // y = a.y + (−N_y − √Q)/(−D) with −D > 0. Let E = −D_e, G = −D_f (both > 0),
    // P_e = −N_ye, P_f = −N_yf. Times E·G:
    //   X + √(E² Q_f) − √(G² Q_e), X = E G (a_e.y − a_f.y) + G P_e − E P_f.
    let (a1, a2) = (e.sites[0], f.sites[0]);
    let (d1, nx1, ny1) = parts::<T>(e);
    let (d2, nx2, ny2) = parts::<T>(f);
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
fn cmp_events_x<T: Arith>(e: &CircleKey, f: &CircleKey) -> Option<Ordering> {
    // x = a.x + (−N_x)/(−D); times E·G: E G (a_e.x − a_f.x) − G N_xe + E N_xf.
    let (a1, a2) = (e.sites[0], f.sites[0]);
    let (d1, nx1, _) = parts::<T>(e);
    let (d2, nx2, _) = parts::<T>(f);
    let ee = neg(&d1);
    let gg = neg(&d2);
    ee.times(&gg)
        .times(&T::diff(a1.x, a2.x))
        .minus(&gg.times(&nx1))
        .plus(&ee.times(&nx2))
        .sign()
}

/// Order of two circle events in the sweep (`Less` = processed first): larger `y` first,
/// then smaller centre `x`; `Equal` when both coincide.
pub(crate) fn cmp_events(e: &CircleKey, f: &CircleKey) -> Ordering {
    let dy = if e.y.0 > f.y.1 {
        Ordering::Greater
    } else if e.y.1 < f.y.0 {
        Ordering::Less
    } else {
        decide(
            || cmp_events_y::<Bounded>(e, f),
            || {
                cmp_events_y::<Exactish>(e, f)
                    .or_else(|| cmp_events_y::<Dyadic>(e, f))
                    .unwrap_or(Ordering::Equal)
            },
        )
    };
    match dy {
        Ordering::Greater => Ordering::Less,
        Ordering::Less => Ordering::Greater,
        Ordering::Equal => {
            if e.x.1 < f.x.0 {
                Ordering::Less
            } else if e.x.0 > f.x.1 {
                Ordering::Greater
            } else {
                decide(
                    || cmp_events_x::<Bounded>(e, f),
                    || {
                        cmp_events_x::<Exactish>(e, f)
                            .or_else(|| cmp_events_x::<Dyadic>(e, f))
                            .unwrap_or(Ordering::Equal)
                    },
                )
            }
        }
    }
}
