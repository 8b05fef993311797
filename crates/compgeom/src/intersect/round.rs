//! Correct rounding of proper crossings, fast: the nearest `f64` point to the exact
//! crossing of two segments, bit for bit what [`Crossing::approx`] returns, in about a
//! tenth of its time for the common case (dense crossings make this the hot spot of
//! segment intersection).
//!
//! One straight-line double-double evaluation with an error bound fixed in advance
//! (no error term carried along, no branches on the way), then one certificate per
//! coordinate; when the certificate fails (the exact value is within about 2^-100 of
//! it relative to the inputs of a midpoint between two `f64`s, or the input is out of
//! the range below) the kernel's [`Crossing::approx`] decides. The code is written over
//! `L` lanes of crossings, each lane doing exactly the scalar operations of the analysis
//! below; [`round_crossing`] uses one lane.
//!
//! ## What was measured and not kept (session 7, long random 1e3, 251k crossings)
//!
//! About 40–55 ns per crossing on this machine (load 4–7) for the path below, ~430
//! instructions. Tried, each bit-equal to [`Crossing::approx`] in the proptests, and
//! dropped because no faster:
//! - eight crossings per call in eight lanes (independent dependency chains): faster
//!   in isolation (`time_rounding_paths`), but 3–5% slower inside the pairwise scan,
//!   whose own work already overlaps the rounding;
//! - FMA through `f64::mul_add` without the target feature (a libm call, resolved by
//!   glibc to the hardware instruction): no faster than Dekker's product (54.8 against
//!   53.8 ns), the calls cost what the instructions save;
//! - exact fixed point: the eight coordinates as `i64` in a common unit, `D` and `N` as
//!   exact `i128` products, the residual `2^σ·(X - f·D)` of a plain-`f64` estimate in
//!   wrapping 128-bit arithmetic, one certified correction: fewer instructions (~390)
//!   but 1.4–1.5× slower, bound by the many `f64`/integer conversions.
//!
//! With `-C target-cpu=native` (FMA, three-operand AVX) the whole `find` on that input
//! is about 1.2× faster.
//!
//! ## Two instantiations, chosen at run time (session 8)
//!
//! The arithmetic is written once, generic over how it forms the exact products
//! `a·b = p + e` ([`Products`]): Dekker's product from Veltkamp's splits, or one fused
//! multiply-add (`e = fl(a·b - p)`, exact). A build for the x86-64 baseline (no FMA)
//! also compiles the fused instantiation inside functions with the `fma` and `avx`
//! target features (the `fma` module) and calls them when the processor has
//! those features (detected once); elsewhere, and in builds whose target has FMA,
//! the target's own choice is the only one. Both give the same bits: the analysis
//! below needs only that the products are exact. On long random 1e3 the fused
//! rounding takes about 175 instructions per crossing against about 380.
//!
//! With fused products the lanes pay off inside the pair scan too (unlike the eight
//! Dekker lanes above): the scan keeps its crossings and rounds eight at a time
//! ([`round_crossings_of`]), about 10% less processor time for the whole single-thread
//! `find` on long random 1e3 (task-clock, best and mean of 10 alternated runs, load
//! 7–9), where the isolated rounding goes from about 40 to 15 ns per crossing.
//!
//! The pair scans call [`round_crossing_of`] with a table of [`Prepared`] segments:
//! each segment's direction, the splits of its leading parts and its range check are
//! computed once per segment rather than once per crossing (478 → 408 instructions per
//! crossing). They are functions of the segment alone, so every lane still performs
//! exactly the operations analysed below, some of them earlier.
//!
//! ## Why it is exact
//!
//! With `u = 2^-53`, the crossing of `s = (a, b)` and `t = (c, d)` is
//! `x = a.x + dx·T`, `T = N/D`, with `dx = b.x - a.x`, `D = dx·ey - dy·ex`,
//! `N = wx·ey - wy·ex` (`e = d - c`, `w = c - a`). Differences of inputs are exact as
//! two `f64`s (two-sum); products of their leading parts are exact (Dekker's
//! two-product, or a fused multiply-add: exact either way, so everything below holds
//! for both instantiations); only the cross terms and the final sums of small parts round. With
//! `M_D = |dx·ey| + |dy·ex|` (leading parts) the computed double-double `D~` is within
//! `22u²·M_D` of `D` (likewise `N~`; the code allows `32u²`).
//!
//! `T` is evaluated once, shared by both coordinates: `t_hi = fl(N.hi / D.hi)`, the
//! remainder `r ≈ N~ - t_hi·D~` (one exact two-product, error at most `13u²·|N.hi|`),
//! `t_lo = fl(r / D.hi)`. Then `|t_hi + t_lo - N~/D~| ≤ 28u²·|t_hi|` (the rounding of
//! `t_lo`, the error of `r`, and `D.lo` dropped from the divisor, each a few `u²|t_hi|`),
//! and `|N~/D~ - N/D| ≤ (e_N + |T|·e_D) / |D~|`: together `E_T`. The code uses `32u²`
//! and bounds `|T|` by `1.01·|t_hi|`, checking `E_T < 0.001·|t_hi|`: the `|T|` term of
//! `E_T` then has a factor below `0.001`, so `|T| ≤ (|t_hi + t_lo| + 0.001·|t_hi|) /
//! 0.999 < 1.01·|t_hi|` indeed.
//!
//! A coordinate is `a.x + dx·(t_hi + t_lo)`: `dx.hi·t_hi` exactly (two-product), the
//! cross terms `dx.hi·t_lo + dx.lo·t_hi` rounded (`dx.lo·t_lo`, below `6u²·Q` with
//! `Q = |dx.hi·t_hi|`, dropped), `a.x + dx.hi·t_hi` exactly (two-sum), the small parts
//! summed: within `37u²·Q + u²·|s|` of `a.x + dx·(t_hi + t_lo)` (`s` the two-sum's
//! leading part), and then `|dx|·E_T` from `T`. The code uses `48u²·Q + 2u²·|s|` and adds
//! `10^-300` for subnormal cross terms. The value is split exactly into
//! `f + fe` (two-sum); when `|fe| + E_x < h` with `h` half the smaller gap between `f`
//! and its neighbours, the exact `x` lies strictly within `h` of `f`, so `f` is the
//! nearest `f64` (no tie is possible). A `1 + 2^-40` factor covers the roundings in
//! evaluating the bounds themselves.
//!
//! The range condition (every input coordinate `0` or of magnitude in
//! `[2^-200, 2^200]`, `|t_hi| ≥ 2^-800`, the result of magnitude at least `2^-300`)
//! keeps every product and every rounding error that matters a normal `f64`: inputs are
//! then multiples of `2^-252`, so every intermediate value is zero or above `2^-1000`
//! and below `2^700`, except cross terms of the coordinate, which the `10^-300` covers.

use crate::kernel::{Crossing, Point2, Segment2};

/// `2^-53`.
const U: f64 = 1.0 / 9_007_199_254_740_992.0;
/// The bound on `den`'s (and `num`'s) error, as a multiple of its magnitude.
const ERR_DEN: f64 = 32.0 * U * U;
/// `1 + 2^-40`: covers the roundings in evaluating the certificate itself.
const SAFE: f64 = 1.0 + 1.0 / 1_099_511_627_776.0;
/// Input magnitudes accepted by the fast path.
const LO: f64 = 6.223_015_277_861_142e-61; // 2^-200
const HI: f64 = 1.606_938_044_258_990_3e60; // 2^200
/// The smallest result magnitude the fast path certifies.
const TINY: f64 = 4.909_093_465_297_727e-91; // 2^-300

/// Veltkamp's splitting constant `2^27 + 1`.
const SPLITTER: f64 = 134_217_729.0;

/// Half the smaller gap between `f` and its neighbours (`f` normal, `|f| > 2^-900`;
/// 0 or less for smaller `f`).
#[inline(always)]
fn half_gap(f: f64) -> f64 {
    let bits = f.abs().to_bits();
    let exp = bits >> 52;
    // ulp(f) = 2^(exp - 1075); half of it has exponent field exp - 53, and a quarter
    // (half the gap below a power of two) exp - 54.
    let shift = if bits & ((1 << 52) - 1) == 0 { 54 } else { 53 };
    // (Saturating: zero, subnormal or tiny `f` give 0, which certifies nothing.)
    f64::from_bits(exp.saturating_sub(shift) << 52)
}

#[inline(always)]
fn in_range(v: f64) -> bool {
    // (Non-short-circuit: no branches.)
    (v == 0.0) | ((v.abs() >= LO) & (v.abs() <= HI))
}

/// `2^-800`: the smallest `|t_hi|` the fast path certifies.
const T_MIN: f64 = 1.499_696_813_895_631_3e-241;

/// Lanes over crossings: `L` crossings at once, one per lane, every operation applied
/// lane by lane (each lane performs exactly the scalar operations of the analysis in
/// the module docs).
type V<const L: usize> = [f64; L];

#[inline(always)]
fn zip<const L: usize>(a: V<L>, b: V<L>, f: impl Fn(f64, f64) -> f64) -> V<L> {
    std::array::from_fn(|k| f(a[k], b[k]))
}

#[inline(always)]
fn vadd<const L: usize>(a: V<L>, b: V<L>) -> V<L> {
    zip(a, b, |x, y| x + y)
}

#[inline(always)]
fn vsub<const L: usize>(a: V<L>, b: V<L>) -> V<L> {
    zip(a, b, |x, y| x - y)
}

#[inline(always)]
fn vmul<const L: usize>(a: V<L>, b: V<L>) -> V<L> {
    zip(a, b, |x, y| x * y)
}

#[inline(always)]
fn vdiv<const L: usize>(a: V<L>, b: V<L>) -> V<L> {
    zip(a, b, |x, y| x / y)
}

#[inline(always)]
fn vabs<const L: usize>(a: V<L>) -> V<L> {
    a.map(f64::abs)
}

#[inline(always)]
fn vneg<const L: usize>(a: V<L>) -> V<L> {
    a.map(|x| -x)
}

/// `a + b = s + e` exactly (Knuth's two-sum), per lane.
#[inline(always)]
fn vtwo_sum<const L: usize>(a: V<L>, b: V<L>) -> (V<L>, V<L>) {
    let s = vadd(a, b);
    let bb = vsub(s, a);
    (s, vadd(vsub(a, vsub(s, bb)), vsub(b, bb)))
}

/// A value with its Veltkamp split `v = hi + lo` (each half of at most 26 bits), the
/// operands of Dekker's product. A split is a function of `v` alone, so splitting a
/// segment's direction once ([`Prepared`]) gives exactly the halves a split per
/// crossing would.
#[derive(Clone, Copy)]
struct Split<const L: usize> {
    v: V<L>,
    hi: V<L>,
    lo: V<L>,
}

/// Veltkamp's split of `v`, per lane.
#[inline(always)]
fn vsplit<const L: usize>(v: V<L>) -> Split<L> {
    let c = vmul([SPLITTER; L], v);
    let hi = vsub(c, vsub(c, v));
    Split {
        v,
        hi,
        lo: vsub(v, hi),
    }
}

/// How the fast path forms exact products `a·b = p + e`: the one thing its two
/// instantiations differ in. Both are exact, so either gives bit for bit the same
/// result (the analysis in the module docs only uses that the products are exact).
trait Products {
    /// `a·b = p + e` exactly, per lane.
    fn two_prod<const L: usize>(a: Split<L>, b: Split<L>) -> (V<L>, V<L>);
}

/// Dekker's product from Veltkamp's splits of both operands: plain `f64` operations,
/// for any processor (only the tests use it in builds whose target has FMA).
#[cfg_attr(target_feature = "fma", allow(dead_code))]
struct Dekker;

impl Products for Dekker {
    #[inline(always)]
    fn two_prod<const L: usize>(a: Split<L>, b: Split<L>) -> (V<L>, V<L>) {
        let p = vmul(a.v, b.v);
        let e = vadd(
            vadd(
                vadd(vsub(vmul(a.hi, b.hi), p), vmul(a.hi, b.lo)),
                vmul(a.lo, b.hi),
            ),
            vmul(a.lo, b.lo),
        );
        (p, e)
    }
}

/// One fused multiply-add per product (`e = fl(a·b - p)` is exact); the splits are
/// unused, so the compiler drops them. Only fast in code compiled with the FMA target
/// feature (whole build, or the functions of [`fma`]): elsewhere `mul_add` is a call
/// into libm, exact but measured no faster than [`Dekker`].
#[cfg_attr(
    not(any(target_feature = "fma", target_arch = "x86_64")),
    allow(dead_code)
)]
struct Fused;

impl Products for Fused {
    #[inline(always)]
    fn two_prod<const L: usize>(a: Split<L>, b: Split<L>) -> (V<L>, V<L>) {
        let (a, b) = (a.v, b.v);
        let p = vmul(a, b);
        (p, std::array::from_fn(|k| a[k].mul_add(b[k], -p[k])))
    }
}

/// The products of code compiled for the build's own target: fused where the target
/// has FMA (`-C target-cpu=native` on most x86-64, all aarch64), Dekker's otherwise.
#[cfg(target_feature = "fma")]
type Native = Fused;
#[cfg(not(target_feature = "fma"))]
type Native = Dekker;

/// `a·b = p + e` exactly, per lane, splitting both operands here (the splits are dead
/// code for [`Fused`]).
#[inline(always)]
fn vtwo_prod<P: Products, const L: usize>(a: V<L>, b: V<L>) -> (V<L>, V<L>) {
    P::two_prod(vsplit(a), vsplit(b))
}

/// Double-double values `hi + lo`, one per lane.
#[derive(Clone, Copy)]
struct Dd<const L: usize> {
    hi: V<L>,
    lo: V<L>,
}

/// `a - b` exactly, per lane.
#[inline(always)]
fn vdiff<const L: usize>(a: V<L>, b: V<L>) -> Dd<L> {
    let (hi, lo) = vtwo_sum(a, vneg(b));
    Dd { hi, lo }
}

/// A difference of inputs (exact as a double-double) with the split of its leading
/// part.
#[derive(Clone, Copy)]
struct Diff<const L: usize> {
    d: Dd<L>,
    split: Split<L>,
}

/// `a - b` exactly with its leading part split, per lane.
#[inline(always)]
fn vdiff_split<const L: usize>(a: V<L>, b: V<L>) -> Diff<L> {
    let d = vdiff(a, b);
    Diff {
        d,
        split: vsplit(d.hi),
    }
}

/// `x·y - z·w` per lane, normalised; error at most `22u²·(|x.hi·y.hi| + |z.hi·w.hi|)`.
#[inline(always)]
fn vcross<P: Products, const L: usize>(x: Diff<L>, y: Diff<L>, z: Diff<L>, w: Diff<L>) -> Dd<L> {
    let (p1, e1) = P::two_prod(x.split, y.split);
    let (p2, e2) = P::two_prod(z.split, w.split);
    let (x, y, z, w) = (x.d, y.d, z.d, w.d);
    let c1 = vadd(vmul(x.hi, y.lo), vmul(x.lo, y.hi));
    let c2 = vadd(vmul(z.hi, w.lo), vmul(z.lo, w.hi));
    let (s, r) = vtwo_sum(p1, vneg(p2));
    let lo = vadd(vadd(r, vsub(e1, e2)), vsub(c1, c2));
    let (hi, lo) = vtwo_sum(s, lo);
    Dd { hi, lo }
}

/// Per lane, the nearest `f64` to `a + d·T` for `T = t_hi + t_lo` within `e_t`, and
/// whether the certificate holds.
#[inline(always)]
fn vcoordinate<P: Products, const L: usize>(
    a: V<L>,
    dir: Diff<L>,
    t_hi: V<L>,
    t_lo: V<L>,
    e_t: V<L>,
) -> (V<L>, [bool; L]) {
    let (p, pe) = P::two_prod(dir.split, vsplit(t_hi));
    let d = dir.d;
    let c = vadd(vmul(d.hi, t_lo), vmul(d.lo, t_hi));
    let (s, sl) = vtwo_sum(a, p);
    let lo = vadd(sl, vadd(pe, c));
    let (f, fe) = vtwo_sum(s, lo);
    let ok = std::array::from_fn(|k| {
        let bound = (d.hi[k].abs() * (1.0 + 2.0 * U) * e_t[k]
            + 48.0 * U * U * p[k].abs()
            + 2.0 * U * U * s[k].abs()
            + 1e-300)
            * SAFE;
        // (Non-short-circuit `&`: no branches.)
        (f[k].abs() >= TINY) & (f[k].abs() <= HI) & ((fe[k].abs() + bound) * SAFE < half_gap(f[k]))
    });
    (f, ok)
}

/// What the fast path needs of one segment `(a, b)` per lane, all of it a function of
/// the segment alone: its first endpoint, its direction `b - a` (exact, with the split
/// of its leading parts), and whether its coordinates are in range.
#[derive(Clone, Copy)]
struct Side<const L: usize> {
    ax: V<L>,
    ay: V<L>,
    dx: Diff<L>,
    dy: Diff<L>,
    in_range: [bool; L],
}

/// [`Side`] of segments `(a, b)` given per lane.
#[inline(always)]
fn vside<const L: usize>(ax: V<L>, ay: V<L>, bx: V<L>, by: V<L>) -> Side<L> {
    Side {
        ax,
        ay,
        dx: vdiff_split(bx, ax),
        dy: vdiff_split(by, ay),
        in_range: std::array::from_fn(|k| {
            in_range(ax[k]) & in_range(ay[k]) & in_range(bx[k]) & in_range(by[k])
        }),
    }
}

/// The certified fast path for `L` crossings given by their segments' sides: per lane
/// the coordinates and whether they are certified (else [`Crossing::approx`] must
/// decide).
#[inline(always)]
fn certified_sides<P: Products, const L: usize>(
    s: &Side<L>,
    t: &Side<L>,
) -> (V<L>, V<L>, [bool; L]) {
    let mut ok: [bool; L] = std::array::from_fn(|k| s.in_range[k] & t.in_range[k]);
    // d = s.b - s.a, e = t.b - t.a (both from the sides), w = t.a - s.a, each exact.
    let (dx, dy) = (s.dx, s.dy);
    let (ex, ey) = (t.dx, t.dy);
    let (wx, wy) = (vdiff_split(t.ax, s.ax), vdiff_split(t.ay, s.ay));
    // den = dx·ey - dy·ex, num = wx·ey - wy·ex.
    let den = vcross::<P, L>(dx, ey, dy, ex);
    let num = vcross::<P, L>(wx, ey, wy, ex);
    let (dx_hi, dy_hi, ex_hi, ey_hi) = (dx.d.hi, dy.d.hi, ex.d.hi, ey.d.hi);
    let m_den = vadd(vabs(vmul(dx_hi, ey_hi)), vabs(vmul(dy_hi, ex_hi)));
    let m_num = vadd(vabs(vmul(wx.d.hi, ey_hi)), vabs(vmul(wy.d.hi, ex_hi)));
    // The parameter T = num / den as t_hi + t_lo within e_t (module docs).
    let t_hi = vdiv(num.hi, den.hi);
    let (p, pe) = vtwo_prod::<P, L>(t_hi, den.hi);
    let (s1, s1l) = vtwo_sum(num.hi, vneg(p));
    let r = vadd(s1, vsub(vadd(s1l, num.lo), vadd(pe, vmul(t_hi, den.lo))));
    let t_lo = vdiv(r, den.hi);
    let e_t: V<L> = std::array::from_fn(|k| {
        let den_low = den.hi[k].abs() - den.lo[k].abs();
        (32.0 * U * U * t_hi[k].abs()
            + ERR_DEN * (m_num[k] + 1.01 * t_hi[k].abs() * m_den[k]) / den_low)
            * SAFE
    });
    for k in 0..L {
        // A crossing of segments that meet has a nonzero denominator well above its
        // error; NaN (from overflow) fails every test.
        ok[k] &= (den.hi[k].abs() > 4.0 * ERR_DEN * m_den[k])
            & (t_hi[k].abs() >= T_MIN)
            & (t_hi[k].abs() <= HI)
            & (e_t[k] < 0.001 * t_hi[k].abs());
    }
    let (x, ok_x) = vcoordinate::<P, L>(s.ax, dx, t_hi, t_lo, e_t);
    let (y, ok_y) = vcoordinate::<P, L>(s.ay, dy, t_hi, t_lo, e_t);
    for k in 0..L {
        ok[k] &= ok_x[k] & ok_y[k];
    }
    (x, y, ok)
}

/// The certified fast path for `L` crossings, everything computed here.
#[inline(always)]
fn certified<P: Products, const L: usize>(cs: &[Crossing; L]) -> (V<L>, V<L>, [bool; L]) {
    let get = |f: fn(&Crossing) -> f64| -> V<L> { std::array::from_fn(|k| f(&cs[k])) };
    let s = vside(
        get(|c| c.s.a.x),
        get(|c| c.s.a.y),
        get(|c| c.s.b.x),
        get(|c| c.s.b.y),
    );
    let t = vside(
        get(|c| c.t.a.x),
        get(|c| c.t.a.y),
        get(|c| c.t.b.x),
        get(|c| c.t.b.y),
    );
    certified_sides::<P, L>(&s, &t)
}

/// The nearest `f64` point to the exact crossing: equal to [`Crossing::approx`], faster.
#[inline]
pub(crate) fn round_crossing(c: &Crossing) -> Point2 {
    #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
    if let Some(p) = fma::round_crossing(c) {
        return p;
    }
    round_crossing_with::<Native>(c)
}

/// [`round_crossing`] with the products of `P`.
#[inline(always)]
fn round_crossing_with<P: Products>(c: &Crossing) -> Point2 {
    let (x, y, ok) = certified::<P, 1>(&[*c]);
    if ok[0] {
        Point2::new(x[0], y[0])
    } else {
        c.approx()
    }
}

/// The per-segment part of [`round_crossing`], computed once per input segment instead
/// of once per crossing: the segment's direction `b - a` as an exact double-double, the
/// Veltkamp splits of its leading parts, and the range check of its coordinates. Each
/// is a function of the segment alone, so the crossing's rounding performs exactly the
/// operations analysed in the module docs, some of them earlier.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Prepared {
    ax: f64,
    ay: f64,
    /// `dx.hi, dx.lo, dx.hi`'s split `hi, lo`; then the same for `dy`.
    dx: [f64; 4],
    dy: [f64; 4],
    in_range: bool,
}

impl Prepared {
    /// The entry of segment `s`.
    pub(crate) fn of(s: &Segment2) -> Prepared {
        let side = vside([s.a.x], [s.a.y], [s.b.x], [s.b.y]);
        let pack = |d: Diff<1>| [d.d.hi[0], d.d.lo[0], d.split.hi[0], d.split.lo[0]];
        Prepared {
            ax: s.a.x,
            ay: s.a.y,
            dx: pack(side.dx),
            dy: pack(side.dy),
            in_range: side.in_range[0],
        }
    }

    /// One entry per segment.
    pub(crate) fn table(segments: &[Segment2]) -> Vec<Prepared> {
        segments.iter().map(Prepared::of).collect()
    }

    /// The [`Side`] of the entries, one per lane.
    #[inline(always)]
    fn sides<const L: usize>(e: [&Prepared; L]) -> Side<L> {
        let unpack = |d: fn(&Prepared) -> [f64; 4]| {
            let d: [[f64; 4]; L] = std::array::from_fn(|k| d(e[k]));
            let part = |m: usize| -> V<L> { std::array::from_fn(|k| d[k][m]) };
            Diff {
                d: Dd {
                    hi: part(0),
                    lo: part(1),
                },
                split: Split {
                    v: part(0),
                    hi: part(2),
                    lo: part(3),
                },
            }
        };
        Side {
            ax: std::array::from_fn(|k| e[k].ax),
            ay: std::array::from_fn(|k| e[k].ay),
            dx: unpack(|p| p.dx),
            dy: unpack(|p| p.dy),
            in_range: std::array::from_fn(|k| e[k].in_range),
        }
    }
}

/// [`round_crossing`] of the proper crossing of `segments[i]` and `segments[j]`, with
/// the per-segment part taken from `table` (`table[k] = Prepared::of(&segments[k])`).
#[inline]
pub(crate) fn round_crossing_of(
    segments: &[Segment2],
    table: &[Prepared],
    i: usize,
    j: usize,
) -> Point2 {
    #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
    if let Some(p) = fma::round_crossing_of(segments, table, i, j) {
        return p;
    }
    round_crossing_of_with::<Native>(segments, table, i, j)
}

/// [`round_crossing_of`] with the products of `P`.
#[inline(always)]
fn round_crossing_of_with<P: Products>(
    segments: &[Segment2],
    table: &[Prepared],
    i: usize,
    j: usize,
) -> Point2 {
    round_crossings_of_with::<P, 1>(segments, table, &[(i, j)])[0]
}

/// [`round_crossing_of`] of `L` crossings at once, the pair `pairs[k] = (i, j)` in lane
/// `k`: independent lanes overlap their long dependency chains.
#[inline]
pub(crate) fn round_crossings_of<const L: usize>(
    segments: &[Segment2],
    table: &[Prepared],
    pairs: &[(usize, usize); L],
) -> [Point2; L] {
    #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
    if let Some(p) = fma::round_crossings_of(segments, table, pairs) {
        return p;
    }
    round_crossings_of_with::<Native, L>(segments, table, pairs)
}

/// [`round_crossings_of`] with the products of `P`.
#[inline(always)]
fn round_crossings_of_with<P: Products, const L: usize>(
    segments: &[Segment2],
    table: &[Prepared],
    pairs: &[(usize, usize); L],
) -> [Point2; L] {
    let s = Prepared::sides(std::array::from_fn(|k| &table[pairs[k].0]));
    let t = Prepared::sides(std::array::from_fn(|k| &table[pairs[k].1]));
    let (x, y, ok) = certified_sides::<P, L>(&s, &t);
    std::array::from_fn(|k| {
        if ok[k] {
            Point2::new(x[k], y[k])
        } else {
            let (i, j) = pairs[k];
            Crossing {
                s: segments[i],
                t: segments[j],
            }
            .approx()
        }
    })
}

/// [`round_crossings_of`] of the crossings of one segment `a` with `L` others, `bs[k]`
/// in lane `k` (the pair scan of one segment against its candidates): `a`'s entry is
/// read once for every lane. The nearest `f64` to a crossing does not depend on the
/// order of its two segments, nor does the certificate's analysis (module docs), so
/// the result is that of [`round_crossings_of`] for either order.
#[inline]
pub(crate) fn round_crossings_sharing<const L: usize>(
    segments: &[Segment2],
    table: &[Prepared],
    a: usize,
    bs: &[usize; L],
) -> [Point2; L] {
    #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
    if let Some(p) = fma::round_crossings_sharing(segments, table, a, bs) {
        return p;
    }
    round_crossings_sharing_with::<Native, L>(segments, table, a, bs)
}

/// How a pair scan rounds the crossings of one segment with `L` others: what
/// [`round_crossings_sharing`] computes, by one of two instantiations.
pub(crate) trait RoundSharing {
    /// [`round_crossings_sharing`]'s result.
    fn round<const L: usize>(
        segments: &[Segment2],
        table: &[Prepared],
        a: usize,
        bs: &[usize; L],
    ) -> [Point2; L];
}

/// [`round_crossings_sharing`] itself: the products chosen at run time.
pub(crate) struct Dispatched;

impl RoundSharing for Dispatched {
    #[inline(always)]
    fn round<const L: usize>(
        segments: &[Segment2],
        table: &[Prepared],
        a: usize,
        bs: &[usize; L],
    ) -> [Point2; L] {
        round_crossings_sharing(segments, table, a, bs)
    }
}

/// Fused products, always: for code compiled with the FMA target feature (the wide pair
/// scan of [`super::pairwise`]), into which it inlines as hardware fused multiply-adds.
/// Correct anywhere (`mul_add` is exact everywhere), only slow without the feature.
#[cfg(target_arch = "x86_64")]
pub(crate) struct AlwaysFused;

#[cfg(target_arch = "x86_64")]
impl RoundSharing for AlwaysFused {
    #[inline(always)]
    fn round<const L: usize>(
        segments: &[Segment2],
        table: &[Prepared],
        a: usize,
        bs: &[usize; L],
    ) -> [Point2; L] {
        round_crossings_sharing_with::<Fused, L>(segments, table, a, bs)
    }
}

/// [`round_crossings_sharing`] with the products of `P`.
#[inline(always)]
fn round_crossings_sharing_with<P: Products, const L: usize>(
    segments: &[Segment2],
    table: &[Prepared],
    a: usize,
    bs: &[usize; L],
) -> [Point2; L] {
    let e = &table[a];
    let s = Prepared::sides([e; L]);
    let t = Prepared::sides(std::array::from_fn(|k| &table[bs[k]]));
    let (x, y, ok) = certified_sides::<P, L>(&s, &t);
    std::array::from_fn(|k| {
        if ok[k] {
            Point2::new(x[k], y[k])
        } else {
            Crossing {
                s: segments[a],
                t: segments[bs[k]],
            }
            .approx()
        }
    })
}

/// The fast path compiled a second time, for x86-64 processors with FMA (nearly all
/// since 2013) in a build for the baseline target, which has none: the same generic
/// code with [`Fused`] products, in functions compiled with the target features and
/// chosen at run time. (FMA implies AVX, whose three-operand VEX encoding comes along;
/// adding AVX2 changed nothing in this scalar code.)
///
/// One of the crate's two `unsafe` places (the other is the wide pair scan of
/// [`super::pairwise`]): calling a function compiled for target features is sound
/// exactly when the processor has them, which each call checks first.
#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
#[allow(unsafe_code)]
mod fma {
    use super::*;

    /// Whether the processor has every feature these functions are compiled for (the
    /// detection runs once; `std` caches it).
    #[inline]
    pub(super) fn available() -> bool {
        std::arch::is_x86_feature_detected!("fma") && std::arch::is_x86_feature_detected!("avx")
    }

    /// [`super::round_crossing`] with fused products, where [`available`].
    #[inline]
    pub(super) fn round_crossing(c: &Crossing) -> Option<Point2> {
        #[target_feature(enable = "fma,avx")]
        unsafe fn fused(c: &Crossing) -> Point2 {
            round_crossing_with::<Fused>(c)
        }
        // SAFETY: the processor has the features `fused` is compiled for.
        available().then(|| unsafe { fused(c) })
    }

    /// [`super::round_crossing_of`] with fused products, where [`available`].
    #[inline]
    pub(super) fn round_crossing_of(
        segments: &[Segment2],
        table: &[Prepared],
        i: usize,
        j: usize,
    ) -> Option<Point2> {
        #[target_feature(enable = "fma,avx")]
        unsafe fn fused(segments: &[Segment2], table: &[Prepared], i: usize, j: usize) -> Point2 {
            round_crossing_of_with::<Fused>(segments, table, i, j)
        }
        // SAFETY: the processor has the features `fused` is compiled for.
        available().then(|| unsafe { fused(segments, table, i, j) })
    }

    /// [`super::round_crossings_of`] with fused products, where [`available`].
    #[inline]
    pub(super) fn round_crossings_of<const L: usize>(
        segments: &[Segment2],
        table: &[Prepared],
        pairs: &[(usize, usize); L],
    ) -> Option<[Point2; L]> {
        #[target_feature(enable = "fma,avx")]
        unsafe fn fused<const L: usize>(
            segments: &[Segment2],
            table: &[Prepared],
            pairs: &[(usize, usize); L],
        ) -> [Point2; L] {
            round_crossings_of_with::<Fused, L>(segments, table, pairs)
        }
        // SAFETY: the processor has the features `fused` is compiled for.
        available().then(|| unsafe { fused(segments, table, pairs) })
    }

    /// [`super::round_crossings_sharing`] with fused products, where [`available`].
    #[inline]
    pub(super) fn round_crossings_sharing<const L: usize>(
        segments: &[Segment2],
        table: &[Prepared],
        a: usize,
        bs: &[usize; L],
    ) -> Option<[Point2; L]> {
        #[target_feature(enable = "fma,avx")]
        unsafe fn fused<const L: usize>(
            segments: &[Segment2],
            table: &[Prepared],
            a: usize,
            bs: &[usize; L],
        ) -> [Point2; L] {
            round_crossings_sharing_with::<Fused, L>(segments, table, a, bs)
        }
        // SAFETY: the processor has the features `fused` is compiled for.
        available().then(|| unsafe { fused(segments, table, a, bs) })
    }

    /// [`super::certified`] with fused products, where [`available`] (for the tests'
    /// lanes).
    #[cfg(test)]
    pub(super) fn certified<const L: usize>(cs: &[Crossing; L]) -> Option<(V<L>, V<L>, [bool; L])> {
        #[target_feature(enable = "fma,avx")]
        unsafe fn fused<const L: usize>(cs: &[Crossing; L]) -> (V<L>, V<L>, [bool; L]) {
            super::certified::<Fused, L>(cs)
        }
        // SAFETY: the processor has the features `fused` is compiled for.
        available().then(|| unsafe { fused(cs) })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn crossings(mut coord: impl FnMut() -> f64, n: usize) -> Vec<Crossing> {
        let mut out = Vec::new();
        while out.len() < n {
            let mut p = || Point2::new(coord(), coord());
            let (s, t) = (Segment2::new(p(), p()), Segment2::new(p(), p()));
            if let crate::kernel::SegmentIntersection::Crossing(c) =
                crate::kernel::segment_intersection(s, t)
            {
                out.push(c);
            }
        }
        out
    }

    fn lcg(seed: u64) -> impl FnMut() -> u64 {
        crate::testing::bits(seed)
    }

    fn bits(p: Point2) -> (u64, u64) {
        (p.x.to_bits(), p.y.to_bits())
    }

    /// One way of forming the products, forced whatever the dispatch would choose.
    #[derive(Clone, Copy, Debug)]
    enum Path {
        Dekker,
        Fused,
    }

    /// A lane result: coordinates and certificates.
    type Lanes<const L: usize> = (V<L>, V<L>, [bool; L]);

    impl Path {
        /// [`certified`] by this path, or `None` where the processor cannot run it.
        fn certified<const L: usize>(self, cs: &[Crossing; L]) -> Option<Lanes<L>> {
            match self {
                Path::Dekker => Some(certified::<Dekker, L>(cs)),
                #[cfg(target_feature = "fma")]
                Path::Fused => Some(certified::<Fused, L>(cs)),
                #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
                Path::Fused => fma::certified(cs),
                #[cfg(not(any(target_feature = "fma", target_arch = "x86_64")))]
                Path::Fused => None,
            }
        }

        /// [`round_crossing`] by this path (where it runs).
        fn round(self, c: &Crossing) -> Point2 {
            match self {
                Path::Dekker => round_crossing_with::<Dekker>(c),
                #[cfg(target_feature = "fma")]
                Path::Fused => round_crossing_with::<Fused>(c),
                #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
                Path::Fused => fma::round_crossing(c).unwrap(),
                #[cfg(not(any(target_feature = "fma", target_arch = "x86_64")))]
                Path::Fused => unreachable!(),
            }
        }

        /// [`round_crossings_of`] by this path (where it runs).
        fn rounds_of<const L: usize>(
            self,
            segs: &[Segment2],
            table: &[Prepared],
            pairs: &[(usize, usize); L],
        ) -> [Point2; L] {
            match self {
                Path::Dekker => round_crossings_of_with::<Dekker, L>(segs, table, pairs),
                #[cfg(target_feature = "fma")]
                Path::Fused => round_crossings_of_with::<Fused, L>(segs, table, pairs),
                #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
                Path::Fused => fma::round_crossings_of(segs, table, pairs).unwrap(),
                #[cfg(not(any(target_feature = "fma", target_arch = "x86_64")))]
                Path::Fused => unreachable!(),
            }
        }

        /// [`round_crossing_of`] by this path (where it runs).
        fn round_of(self, segs: &[Segment2], table: &[Prepared], i: usize, j: usize) -> Point2 {
            match self {
                Path::Dekker => round_crossing_of_with::<Dekker>(segs, table, i, j),
                #[cfg(target_feature = "fma")]
                Path::Fused => round_crossing_of_with::<Fused>(segs, table, i, j),
                #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
                Path::Fused => fma::round_crossing_of(segs, table, i, j).unwrap(),
                #[cfg(not(any(target_feature = "fma", target_arch = "x86_64")))]
                Path::Fused => unreachable!(),
            }
        }
    }

    /// The paths this processor runs: Dekker's products always, fused ones where it has
    /// FMA (on this project's x86-64 machines, both).
    fn paths() -> Vec<Path> {
        let easy = [Crossing {
            s: Segment2::new(Point2::new(0.0, 0.0), Point2::new(2.0, 2.0)),
            t: Segment2::new(Point2::new(0.0, 2.0), Point2::new(2.0, 0.0)),
        }];
        [Path::Dekker, Path::Fused]
            .into_iter()
            .filter(|p| p.certified(&easy).is_some())
            .collect()
    }

    /// The crossing's two segments and their table, for [`round_crossing_of`].
    fn prepared(c: &Crossing) -> ([Segment2; 2], Vec<Prepared>) {
        let segs = [c.s, c.t];
        (segs, Prepared::table(&segs))
    }

    /// Rounding is bit-equal to the kernel's exact rounding, as dispatched and by every
    /// path this processor runs, and so is the certified path wherever it answers, in
    /// one lane and in eight (a lane never depends on its neighbours); both paths
    /// certify the same crossings. Returns how many crossings the certified path
    /// decided.
    fn check(cs: &[Crossing]) -> usize {
        let want: Vec<(u64, u64)> = cs.iter().map(|c| bits(c.approx())).collect();
        let mut hits = 0;
        for (c, w) in cs.iter().zip(&want) {
            assert_eq!(bits(round_crossing(c)), *w, "{c:?}");
            // Through the per-segment table, in both orders of the pair.
            let (segs, table) = prepared(c);
            assert_eq!(bits(round_crossing_of(&segs, &table, 0, 1)), *w, "{c:?}");
            assert_eq!(bits(round_crossing_of(&segs, &table, 1, 0)), *w, "{c:?}");
            let mut certified_by = Vec::new();
            for path in paths() {
                assert_eq!(bits(path.round(c)), *w, "{path:?}: {c:?}");
                assert_eq!(
                    bits(path.round_of(&segs, &table, 0, 1)),
                    *w,
                    "{path:?}: {c:?}"
                );
                assert_eq!(
                    bits(path.round_of(&segs, &table, 1, 0)),
                    *w,
                    "{path:?}: {c:?}"
                );
                let (x, y, ok) = path.certified(&[*c]).unwrap();
                if ok[0] {
                    let got = (x[0].to_bits(), y[0].to_bits());
                    assert_eq!(got, *w, "{path:?}, one lane: {c:?}");
                }
                certified_by.push(ok[0]);
            }
            // (Exact products either way: the same values, the same certificates.)
            assert!(
                certified_by.iter().all(|&ok| ok == certified_by[0]),
                "{c:?}"
            );
            hits += usize::from(certified_by[0]);
        }
        for path in paths() {
            for (chunk, w) in cs.chunks_exact(8).zip(want.chunks_exact(8)) {
                let chunk: &[Crossing; 8] = chunk.try_into().unwrap();
                let (x, y, ok) = path.certified(chunk).unwrap();
                for k in 0..8 {
                    if ok[k] {
                        let got = (x[k].to_bits(), y[k].to_bits());
                        assert_eq!(got, w[k], "{path:?}: {:?}", chunk[k]);
                    }
                }
            }
        }
        hits
    }

    #[test]
    fn bit_equal_to_the_kernel_on_random_crossings() {
        let mut r = lcg(7);
        let unit = move || (r() as f64) / (1u64 << 53) as f64;
        let cs = crossings(unit, 20_000);
        // Nearly every random crossing is certified by the fast path.
        assert!(check(&cs) > 19_900);
    }

    #[test]
    fn bit_equal_on_wide_magnitudes_and_grids() {
        let mut r = lcg(11);
        let wide = move || {
            let v = r();
            let m = (v % 1000) as f64 / 7.0;
            let e = ((v >> 20) % 120) as i32 - 60;
            let sign = if v & (1 << 40) == 0 { 1.0 } else { -1.0 };
            sign * m * 2f64.powi(e)
        };
        check(&crossings(wide, 5000));
        let mut r = lcg(13);
        let grid = move || (r() % 9) as f64;
        check(&crossings(grid, 5000));
        let mut r = lcg(17);
        // Huge offsets with tiny extents: heavy cancellation.
        let offset = move || 1e15 + (r() % 1000) as f64 * 0.001;
        check(&crossings(offset, 5000));
        let mut r = lcg(19);
        let extreme = move || {
            let v = r();
            [1e-300, 1e300, 3.0, -2.5e-250, 7e250][(v % 5) as usize]
                * (1.0 + (v >> 8) as f64 * 1e-40)
        };
        check(&crossings(extreme, 500));
    }

    #[test]
    fn bit_equal_on_long_and_nearly_parallel_segments() {
        // Segments across the unit square (the benchmark's dense case), crossings near
        // the ends (T close to 0 or 1), and nearly parallel pairs (small denominators).
        let mut r = lcg(23);
        let mut unit = move || (r() as f64) / (1u64 << 53) as f64;
        let mut cs = Vec::new();
        while cs.len() < 20_000 {
            let (a, b, c, d) = (unit(), unit(), unit(), unit());
            let k = cs.len() % 3;
            let (c, d) = match k {
                0 => (c, d),
                1 => (a + (c - 0.5) * 1e-9, b + (d - 0.5) * 1e-9),
                _ => (a + 1e-12, b - 1e-12 * c),
            };
            let s = Segment2::new(Point2::new(0.0, a), Point2::new(1.0, b));
            let t = Segment2::new(Point2::new(0.0, c), Point2::new(1.0, d));
            if let crate::kernel::SegmentIntersection::Crossing(x) =
                crate::kernel::segment_intersection(s, t)
            {
                cs.push(x);
            }
        }
        assert!(check(&cs) > 15_000);
    }

    /// A coordinate: a small integer, nudged by a few ulps, scaled by `2^scale`.
    fn nudged(v: i32, ulps: i64, scale: i32) -> f64 {
        let base = f64::from(v) * 2f64.powi(scale);
        if base == 0.0 {
            return base;
        }
        f64::from_bits((base.to_bits() as i64 + ulps) as u64)
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(2000))]
        /// Bit-equal to the kernel's exact rounding on crossings of grid segments nudged
        /// by ulps (near-ties, near-parallel pairs, crossings near endpoints) at scales
        /// from about 1e-300 to 1e300 (both segments at one scale, or at two).
        #[test]
        fn bit_equal_on_nudged_grids_at_every_scale(
            v in proptest::collection::vec(-8i32..=8, 8),
            u in proptest::collection::vec(-3i64..=3, 8),
            scale in -1000i32..=1000,
            other in -1000i32..=1000,
            same in proptest::bool::ANY,
        ) {
            let t_scale = if same { scale } else { other };
            let c = |k: usize, sc: i32| nudged(v[k], u[k], sc);
            let s = Segment2::new(Point2::new(c(0, scale), c(1, scale)), Point2::new(c(2, scale), c(3, scale)));
            let t = Segment2::new(Point2::new(c(4, t_scale), c(5, t_scale)), Point2::new(c(6, t_scale), c(7, t_scale)));
            if let crate::kernel::SegmentIntersection::Crossing(x) =
                crate::kernel::segment_intersection(s, t)
            {
                let want = bits(x.approx());
                proptest::prop_assert_eq!(bits(round_crossing(&x)), want, "{:?}", x);
                let (segs, table) = prepared(&x);
                proptest::prop_assert_eq!(bits(round_crossing_of(&segs, &table, 0, 1)), want, "{:?}", x);
                proptest::prop_assert_eq!(bits(round_crossing_of(&segs, &table, 1, 0)), want, "{:?}", x);
                // In every other lane of eight, beside an easy crossing.
                let easy = Crossing {
                    s: Segment2::new(Point2::new(0.0, 0.0), Point2::new(2.0, 2.0)),
                    t: Segment2::new(Point2::new(0.0, 2.0), Point2::new(2.0, 0.0)),
                };
                let lanes: [Crossing; 8] = std::array::from_fn(|k| if k % 2 == 1 { x } else { easy });
                let mut certified_by = Vec::new();
                for path in paths() {
                    proptest::prop_assert_eq!(bits(path.round(&x)), want, "{:?}: {:?}", path, x);
                    proptest::prop_assert_eq!(bits(path.round_of(&segs, &table, 0, 1)), want, "{:?}: {:?}", path, x);
                    proptest::prop_assert_eq!(bits(path.round_of(&segs, &table, 1, 0)), want, "{:?}: {:?}", path, x);
                    let (xs, ys, ok) = path.certified(&lanes).unwrap();
                    for k in 0..8 {
                        let w = if k % 2 == 1 { want } else { bits(Point2::new(1.0, 1.0)) };
                        if ok[k] {
                            proptest::prop_assert_eq!((xs[k].to_bits(), ys[k].to_bits()), w, "{:?}: {:?}", path, x);
                        }
                    }
                    // The easy crossing is certified beside any neighbour.
                    proptest::prop_assert!(ok[0]);
                    certified_by.push(ok);
                }
                proptest::prop_assert!(certified_by.iter().all(|ok| *ok == certified_by[0]), "{:?}", x);
            }
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// Through one table for a whole input of long random segments across the unit
        /// square (the benchmark's dense case), optionally snapped to a coarse grid
        /// and nudged by ulps: every crossing pair, bit-equal to the kernel's rounding.
        #[test]
        fn table_bit_equal_on_long_random_segments(
            seed in proptest::prelude::any::<u64>(),
            grid in proptest::bool::ANY,
            nudge in -2i64..=2,
        ) {
            let mut r = lcg(seed);
            let mut coord = move || {
                let v = (r() as f64) / (1u64 << 53) as f64;
                if grid {
                    let g = (v * 16.0).floor() / 16.0;
                    if g == 0.0 { g } else { f64::from_bits((g.to_bits() as i64 + nudge) as u64) }
                } else {
                    v
                }
            };
            let segs: Vec<Segment2> = (0..60)
                .map(|_| Segment2::new(Point2::new(0.0, coord()), Point2::new(1.0, coord())))
                .collect();
            let table = Prepared::table(&segs);
            let mut pairs = Vec::new();
            for i in 0..segs.len() {
                for j in i + 1..segs.len() {
                    if let crate::kernel::SegmentIntersection::Crossing(c) =
                        crate::kernel::segment_intersection(segs[i], segs[j])
                    {
                        pairs.push(((i, j), bits(c.approx())));
                        let want = bits(c.approx());
                        proptest::prop_assert_eq!(bits(round_crossing_of(&segs, &table, i, j)), want, "{:?}", c);
                        for path in paths() {
                            proptest::prop_assert_eq!(bits(path.round_of(&segs, &table, i, j)), want, "{:?}: {:?}", path, c);
                        }
                    }
                }
            }
            // Eight crossings at a time, as the pair scans round them (in a shuffled
            // order, so that lanes mix easy and hard crossings).
            let mut r = lcg(seed ^ 0x5eed);
            for k in (1..pairs.len()).rev() {
                pairs.swap(k, (r() % (k as u64 + 1)) as usize);
            }
            // Eight crossings of one segment at a time, that segment first (as the
            // batched axis-sweep scan rounds them), so in either order of the pair.
            for a in 0..segs.len() {
                let mine: Vec<(usize, (u64, u64))> = pairs
                    .iter()
                    .filter_map(|&((i, j), want)| {
                        (i == a).then_some((j, want)).or((j == a).then_some((i, want)))
                    })
                    .collect();
                for chunk in mine.chunks_exact(8) {
                    let bs: [usize; 8] = std::array::from_fn(|k| chunk[k].0);
                    let got = round_crossings_sharing(&segs, &table, a, &bs);
                    let dekker = round_crossings_sharing_with::<Dekker, 8>(&segs, &table, a, &bs);
                    for k in 0..8 {
                        proptest::prop_assert_eq!(bits(got[k]), chunk[k].1, "{} {}", a, bs[k]);
                        proptest::prop_assert_eq!(bits(dekker[k]), chunk[k].1, "{} {}", a, bs[k]);
                    }
                }
            }
            for chunk in pairs.chunks_exact(8) {
                let lanes: [(usize, usize); 8] = std::array::from_fn(|k| chunk[k].0);
                let got = round_crossings_of(&segs, &table, &lanes);
                for k in 0..8 {
                    proptest::prop_assert_eq!(bits(got[k]), chunk[k].1, "{:?}", lanes[k]);
                }
                for path in paths() {
                    let got = path.rounds_of(&segs, &table, &lanes);
                    for k in 0..8 {
                        proptest::prop_assert_eq!(bits(got[k]), chunk[k].1, "{:?}: {:?}", path, lanes[k]);
                    }
                }
            }
        }
    }

    #[test]
    #[ignore]
    fn time_rounding_paths() {
        // (Run: `cargo test --release -p compgeom --lib time_rounding -- --ignored
        // --nocapture`; best of 15 alternating rounds per path and lane count.)
        let mut r = lcg(3);
        let mut unit = move || (r() as f64) / (1u64 << 53) as f64;
        let segs: Vec<Segment2> = (0..1000)
            .map(|_| Segment2::new(Point2::new(0.0, unit()), Point2::new(1.0, unit())))
            .collect();
        let mut cs = Vec::new();
        for i in 0..segs.len() {
            for j in i + 1..segs.len() {
                if let crate::kernel::SegmentIntersection::Crossing(c) =
                    crate::kernel::segment_intersection(segs[i], segs[j])
                {
                    cs.push(c);
                }
            }
        }
        fn run_lanes<const L: usize>(path: Path, cs: &[Crossing]) -> f64 {
            let mut acc = 0.0;
            for chunk in cs.chunks_exact(L) {
                let chunk: &[Crossing; L] = std::hint::black_box(chunk.try_into().unwrap());
                let (x, y, ok) = path.certified(chunk).unwrap();
                for k in 0..L {
                    acc += if ok[k] { x[k] + y[k] } else { 0.0 };
                }
            }
            acc
        }
        type Run = Box<dyn Fn(&[Crossing]) -> f64>;
        let mut runs: Vec<(String, Run)> = Vec::new();
        for path in paths() {
            let name = |l: usize| format!("{path:?} lanes L={l}");
            runs.push((name(1), Box::new(move |cs| run_lanes::<1>(path, cs))));
            runs.push((name(2), Box::new(move |cs| run_lanes::<2>(path, cs))));
            runs.push((name(4), Box::new(move |cs| run_lanes::<4>(path, cs))));
            runs.push((name(8), Box::new(move |cs| run_lanes::<8>(path, cs))));
        }
        let paths = runs;
        let mut best = vec![f64::MAX; paths.len()];
        for _ in 0..15 {
            for (k, (_, f)) in paths.iter().enumerate() {
                let t = std::time::Instant::now();
                std::hint::black_box(f(&cs));
                best[k] = best[k].min(t.elapsed().as_secs_f64() / cs.len() as f64);
            }
        }
        for (k, (name, _)) in paths.iter().enumerate() {
            println!(
                "{name}: {:.1} ns per crossing ({} crossings)",
                best[k] * 1e9,
                cs.len()
            );
        }
    }

    #[test]
    fn ties_and_near_ties_fall_back() {
        // x = 1 + 2^-53: exactly the midpoint between 1 and the next f64 (a tie to even).
        let e = 2f64.powi(-52);
        let s = Segment2::new(Point2::new(1.0, -1.0), Point2::new(1.0 + e, 1.0));
        let t = Segment2::new(Point2::new(0.0, 0.0), Point2::new(2.0, 0.0));
        let c = Crossing { s, t };
        for path in paths() {
            assert!(!path.certified(&[c]).unwrap().2[0], "{path:?}");
            assert_eq!(path.round(&c), c.approx(), "{path:?}");
        }
        assert_eq!(round_crossing(&c), c.approx());
    }
}
