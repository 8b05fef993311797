//! The default Delaunay triangulation: spatial sort + walking location + Lawson flips.
//!
//! 1. The points are put in Hilbert-curve order (the curve over a 2^16 × 2^16 grid laid on
//!    the bounding box; keys by a two-levels-per-lookup table, sorted by an O(n) radix
//!    sort), then split into rounds along the curve (every 8th point first, …, the odd
//!    positions last; see [`rounds_along_the_curve`]), a deterministic BRIO. The order only
//!    affects speed: every decision below is exact.
//! 2. Each point is located by a visibility walk from the last triangle created, which is
//!    next to the previous point (a few steps on average within a round).
//! 3. It is inserted by splitting its triangle (or edge) and restoring the Delaunay property
//!    with the book's LEGALIZEEDGE flips (§9.3), on a mesh closed by ghost triangles (see
//!    `mesh.rs`), so outside points need no symbolic or huge bounding points. On a small
//!    integer grid (all coordinates integers, span at most 2^12) the predicates are the
//!    unfiltered exact ones of `pred.rs`.
//!
//! O(n) for the order and expected O(n) for the rest on uniform input (O(n²) flips in the
//! worst case, as for any incremental method). A point equal to an existing vertex is
//! found as `Found::Vertex` and merged.

use super::mesh::{Found, Mesh};
use super::pred::{orient, small_integer_grid};
use crate::Point2;

/// One level of the Hilbert curve as a state machine. The state says how the coordinate
/// bits below the current level are transformed before they are read: bit 0 = swap x and
/// y, bit 1 = complement both. Reading the raw bits `(bx, by)` of a level gives the
/// transformed bits `(tx, ty)`, the curve digit `(3 tx) ^ ty` (the quadrant's rank along
/// the curve), and the next state: quadrants with `ty = 0` swap the axes below, and the
/// one with `tx = 1` also complements them (the classic xy→d recursion, one level).
const fn hilbert_level(state: u8, bx: u8, by: u8) -> (u8, u8) {
    let (sw, cm) = (state & 1, state >> 1);
    let (tx, ty) = if sw == 1 {
        (by ^ cm, bx ^ cm)
    } else {
        (bx ^ cm, by ^ cm)
    };
    let digit = (3 * tx) ^ ty;
    let (sw, cm) = if ty == 0 { (sw ^ 1, cm ^ tx) } else { (sw, cm) };
    (digit, sw | (cm << 1))
}

/// Two levels at once: entry `state << 4 | bx << 2 | by` (two bits of each coordinate)
/// holds the two digits (4 bits) and, above them, the next state.
const HILBERT2: [u8; 64] = {
    let mut table = [0u8; 64];
    let mut e = 0;
    while e < 64 {
        let (state, bx, by) = ((e >> 4) as u8, ((e >> 2) & 3) as u8, (e & 3) as u8);
        let (d1, s1) = hilbert_level(state, bx >> 1, by >> 1);
        let (d0, s0) = hilbert_level(s1, bx & 1, by & 1);
        table[e] = (d1 << 2) | d0 | (s0 << 4);
        e += 1;
    }
    table
};

/// Hilbert index of (x, y) on a 2^16 grid (x, y < 2^16), two levels per table look-up.
#[inline]
fn hilbert(x: u32, y: u32) -> u32 {
    let mut state = 0u32;
    let mut d = 0u32;
    let mut shift = 16;
    while shift > 0 {
        shift -= 2;
        let e = HILBERT2[((state << 4) | (((x >> shift) & 3) << 2) | ((y >> shift) & 3)) as usize];
        d = (d << 4) | u32::from(e & 15);
        state = u32::from(e >> 4);
    }
    d
}

/// `hilbert << 32 | index` for every point, sorted: the Hilbert order with ties by index.
/// Equal points (`==`, so `-0.0` and `0.0` too) get equal Hilbert indices.
fn hilbert_keys(pts: &[Point2]) -> Vec<u64> {
    let (mut x0, mut y0, mut x1, mut y1) = (f64::MAX, f64::MAX, f64::MIN, f64::MIN);
    for p in pts {
        x0 = x0.min(p.x);
        y0 = y0.min(p.y);
        x1 = x1.max(p.x);
        y1 = y1.max(p.y);
    }
    // Scale in two steps so that extreme ranges (up to ±f64::MAX) do not overflow.
    let w = (x1 / 2.0 - x0 / 2.0).max(f64::MIN_POSITIVE);
    let h = (y1 / 2.0 - y0 / 2.0).max(f64::MIN_POSITIVE);
    // `as u32` truncates (= floor here, the value being >= 0 up to rounding; a tiny
    // negative one truncates to 0 as the clamp would) and saturates an infinite quotient.
    let q = |v: f64, lo: f64, span: f64| -> u32 {
        (((v / 2.0 - lo / 2.0) / span * 65535.0) as u32).min(65535)
    };
    let keys: Vec<u64> = pts
        .iter()
        .enumerate()
        .map(|(i, p)| (u64::from(hilbert(q(p.x, x0, w), q(p.y, y0, h))) << 32) | i as u64)
        .collect();
    radix_sort_high(keys)
}

/// The input indices in Hilbert order (ties by index, so the order is deterministic).
pub(crate) fn hilbert_order(pts: &[Point2]) -> Vec<u32> {
    hilbert_keys(pts).into_iter().map(|k| k as u32).collect()
}

/// Sorts keys by their high 32 bits with a stable LSD radix sort (three passes of 11 bits),
/// so equal high halves keep their input order: the low halves here are the increasing
/// input indices, and the result equals a full sort of the `u64` keys. O(n), against the
/// O(n log n) comparisons of a comparison sort.
fn radix_sort_high(mut keys: Vec<u64>) -> Vec<u64> {
    if keys.len() < 256 {
        keys.sort_unstable();
        return keys;
    }
    let mut buf = vec![0u64; keys.len()];
    for pass in 0..3 {
        let shift = 32 + 11 * pass;
        let mut count = [0usize; 2048];
        for &k in &keys {
            count[((k >> shift) & 2047) as usize] += 1;
        }
        let mut sum = 0;
        for c in count.iter_mut() {
            let n = *c;
            *c = sum;
            sum += n;
        }
        for &k in &keys {
            let slot = &mut count[((k >> shift) & 2047) as usize];
            buf[*slot] = k;
            *slot += 1;
        }
        std::mem::swap(&mut keys, &mut buf);
    }
    keys
}

/// The last of [`rounds_along_the_curve`]'s levels (rounds of 1/16, 1/16, 1/8, 1/4, 1/2).
const COARSEST: u32 = 3;

/// A deterministic biased insertion order in the spirit of BRIO (Amenta, Choi & Rote):
/// the point at position `i` of the Hilbert order goes to round `min(trailing_zeros(i), 3)`
/// (position 0 to the coarsest), and rounds run from the coarsest (every 8th point along
/// the curve: an even sample of the whole set, the curve being space-filling) to the finest
/// (the odd positions, half of the points), each in Hilbert order.
///
/// Why: in plain Hilbert order every new point lies on the frontier of the inserted region,
/// next to long triangles spanning the not-yet-inserted part, so it gets many flips (5.6 per
/// point on an integer grid, 4.6 on uniform points). After the coarse rounds most points
/// fall inside a triangulation of about their own density: fewer flips (38% fewer
/// instructions on a 300 × 300 grid, 13% on uniform points) while each round still walks
/// in curve order. Only the order changes; every decision stays exact.
fn rounds_along_the_curve(order: Vec<u32>) -> Vec<u32> {
    let level = |i: usize| {
        if i == 0 {
            COARSEST
        } else {
            i.trailing_zeros().min(COARSEST)
        }
    };
    // Counting sort by level, coarsest first, stable (curve order within a round).
    let mut start = [0usize; COARSEST as usize + 2];
    for i in 0..order.len() {
        start[(COARSEST - level(i)) as usize + 1] += 1;
    }
    for k in 1..start.len() {
        start[k] += start[k - 1];
    }
    let mut out = vec![0u32; order.len()];
    for (i, &o) in order.iter().enumerate() {
        let slot = &mut start[(COARSEST - level(i)) as usize];
        out[*slot] = o;
        *slot += 1;
    }
    out
}

/// Triangulates `pts` (finite, at most `u32::MAX - 1` of them). Returns the mesh (or `None`
/// when all points are collinear or fewer than three are distinct) and, for every input
/// index, the input index of the vertex it was merged into.
pub(crate) fn triangulate(pts: &[Point2]) -> (Option<Mesh<'_>>, Vec<u32>) {
    let n = pts.len();
    let mut rep: Vec<u32> = (0..n as u32).collect();
    if n < 3 {
        if n == 2 && pts[0] == pts[1] {
            rep[1] = 0;
        }
        return (None, rep);
    }
    // Equal points share a Hilbert key and, ordered by index within it, are usually
    // adjacent in the curve order: merge those here, into the first of the run. (Left in,
    // the rounds would separate them and each copy would cost a walk; the rest are found
    // as vertices by the walk.) A dropped point's representative is resolved at the end.
    let mut order = hilbert_order(pts);
    let mut kept = 0;
    for k in 0..order.len() {
        let i = order[k];
        if kept > 0 && pts[order[kept - 1] as usize] == pts[i as usize] {
            rep[i as usize] = order[kept - 1];
            continue;
        }
        order[kept] = i;
        kept += 1;
    }
    order.truncate(kept);
    let mut rank = vec![u32::MAX; n];
    for (k, &i) in order.iter().enumerate() {
        rank[i as usize] = k as u32;
    }
    let order = rounds_along_the_curve(order);
    // The first triangle: the first point, the next distinct one, the next not on their line.
    let a = order[0];
    let Some(ib) = order
        .iter()
        .position(|&i| pts[i as usize] != pts[a as usize])
    else {
        return (None, dedup(pts));
    };
    let b = order[ib];
    let Some(ic) = order[ib + 1..]
        .iter()
        .position(|&i| orient(pts[a as usize], pts[b as usize], pts[i as usize]) != 0)
    else {
        return (None, dedup(pts));
    };
    let ic = ib + 1 + ic;
    let c = order[ic];
    let mut mesh = if orient(pts[a as usize], pts[b as usize], pts[c as usize]) > 0 {
        Mesh::new(pts, a, b, c, n)
    } else {
        Mesh::new(pts, a, c, b, n)
    };
    // Integer grids (the common degenerate input, all squares cocircular) make the filters
    // fail constantly; their exact unfiltered predicates are cheaper still.
    mesh.grid = small_integer_grid(pts);
    mesh.rank = rank;
    for (k, &i) in order.iter().enumerate() {
        if k == 0 || k == ib || k == ic {
            continue;
        }
        let p = pts[i as usize];
        match mesh.locate(p) {
            Found::Vertex(v) => rep[i as usize] = v,
            at => mesh.insert(i, at),
        }
    }
    // A point dropped above maps to a kept one, whose own entry is final (itself, or the
    // vertex the walk merged it into).
    for i in 0..n {
        rep[i] = rep[rep[i] as usize];
    }
    (Some(mesh), rep)
}

/// Merges equal points (`==`): every input index mapped to the smallest index of a point
/// equal to it. Equal points have equal Hilbert indices, so only runs of equal keys in the
/// (radix-sorted, O(n)) Hilbert order can hold duplicates; each such run is sorted
/// lexicographically and split into groups of equal points. O(n) plus the sorts of the
/// runs (tiny unless very many points share one of the 2^32 grid cells).
pub(crate) fn dedup(pts: &[Point2]) -> Vec<u32> {
    let mut rep: Vec<u32> = (0..pts.len() as u32).collect();
    let keys = hilbert_keys(pts);
    let mut run: Vec<u32> = Vec::new();
    let mut k = 0;
    while k < keys.len() {
        let cell = keys[k] >> 32;
        let mut m = k + 1;
        while m < keys.len() && keys[m] >> 32 == cell {
            m += 1;
        }
        if m - k > 1 {
            run.clear();
            run.extend(keys[k..m].iter().map(|&key| key as u32));
            run.sort_by(|&i, &j| {
                crate::kernel::compare_xy(pts[i as usize], pts[j as usize]).then(i.cmp(&j))
            });
            let mut g = 0;
            while g < run.len() {
                let first = run[g];
                let mut e = g;
                while e < run.len() && pts[run[e] as usize] == pts[first as usize] {
                    rep[run[e] as usize] = first;
                    e += 1;
                }
                g = e;
            }
        }
        k = m;
    }
    rep
}

/// The reference for [`dedup`]: one lexicographic sort of everything.
#[cfg(test)]
pub(crate) fn dedup_sorted(pts: &[Point2]) -> Vec<u32> {
    let mut rep: Vec<u32> = (0..pts.len() as u32).collect();
    let mut idx: Vec<u32> = (0..pts.len() as u32).collect();
    idx.sort_by(|&i, &j| {
        crate::kernel::compare_xy(pts[i as usize], pts[j as usize]).then(i.cmp(&j))
    });
    let mut k = 0;
    while k < idx.len() {
        let first = idx[k];
        let mut m = k;
        while m < idx.len() && pts[idx[m] as usize] == pts[first as usize] {
            rep[idx[m] as usize] = first;
            m += 1;
        }
        k = m;
    }
    rep
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The textbook xy→d recursion on a 2^16 grid, one level per step (the reference the
    /// table-driven `hilbert` must reproduce exactly, so the insertion order is unchanged).
    fn hilbert_reference(mut x: u32, mut y: u32) -> u32 {
        let n: u32 = 1 << 16;
        let mut d = 0u32;
        let mut s = n >> 1;
        while s > 0 {
            let rx = u32::from(x & s > 0);
            let ry = u32::from(y & s > 0);
            d = d.wrapping_add(s.wrapping_mul(s).wrapping_mul((3 * rx) ^ ry));
            if ry == 0 {
                if rx == 1 {
                    x = s.wrapping_sub(1).wrapping_sub(x) & (n - 1);
                    y = s.wrapping_sub(1).wrapping_sub(y) & (n - 1);
                }
                std::mem::swap(&mut x, &mut y);
            }
            s >>= 1;
        }
        d
    }

    #[test]
    fn table_hilbert_matches_the_reference_recursion() {
        let mut s = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 40) as u32 & 0xFFFF
        };
        for _ in 0..100_000 {
            let (x, y) = (next(), next());
            assert_eq!(hilbert(x, y), hilbert_reference(x, y), "({x}, {y})");
        }
        for x in (0..65536).step_by(257).chain([0, 1, 65534, 65535]) {
            for y in [0, 1, 2, 3, 255, 256, 32767, 32768, 65535] {
                assert_eq!(hilbert(x, y), hilbert_reference(x, y), "({x}, {y})");
            }
        }
        // A bijection on a small grid at the top levels: 4^2 distinct consecutive ranks.
        let mut seen: Vec<u32> = (0..4u32)
            .flat_map(|i| (0..4u32).map(move |j| hilbert(i << 14, j << 14) >> 28))
            .collect();
        seen.sort_unstable();
        assert_eq!(seen, (0..16).collect::<Vec<_>>());
    }

    #[test]
    fn dedup_by_hilbert_runs_equals_dedup_by_sorting() {
        let mut s = 77u64;
        let mut r = |m: u64| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s % m
        };
        let mut sets: Vec<Vec<Point2>> = Vec::new();
        // Small grids (many duplicates), signed zeros, a dense cluster sharing one cell
        // with a far outlier, tiny and huge scales.
        for scale in [1.0, 0.5, 1e-300, 1e300, 3.0e-7] {
            sets.push(
                (0..3000)
                    .map(|_| Point2::new(r(9) as f64 * scale, r(7) as f64 * scale))
                    .collect(),
            );
        }
        sets.push(vec![
            Point2::new(0.0, -0.0),
            Point2::new(-0.0, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(-0.0, -0.0),
        ]);
        let mut cluster: Vec<Point2> = (0..2000)
            .map(|_| Point2::new(1.0 + r(5) as f64 * 1e-12, 1.0 + r(3) as f64 * 1e-12))
            .collect();
        cluster.push(Point2::new(1e6, -1e6));
        sets.push(cluster);
        sets.push(Vec::new());
        for pts in &sets {
            let fast = dedup(pts);
            assert_eq!(fast, dedup_sorted(pts));
            for (i, &v) in fast.iter().enumerate() {
                assert!(pts[i] == pts[v as usize] && v as usize <= i);
            }
        }
    }

    #[test]
    fn rounds_are_a_permutation_coarsest_first() {
        for n in [0usize, 1, 2, 7, 8, 9, 100, 1000] {
            let order: Vec<u32> = (0..n as u32).rev().collect();
            let r = rounds_along_the_curve(order.clone());
            let mut sorted = r.clone();
            sorted.sort_unstable();
            assert_eq!(sorted, (0..n as u32).collect::<Vec<_>>());
            if n > 8 {
                // Positions 0, 8, 16, ... of the curve first, in curve order.
                assert_eq!(&r[..2], &[order[0], order[8]]);
                // The odd positions last, in curve order.
                assert_eq!(r[n - 1], order[if n % 2 == 0 { n - 1 } else { n - 2 }]);
            }
        }
    }

    #[test]
    fn radix_sort_equals_a_full_sort() {
        let mut s = 12345u64;
        for n in [0usize, 1, 255, 256, 257, 5000] {
            let keys: Vec<u64> = (0..n as u64)
                .map(|i| {
                    s ^= s << 13;
                    s ^= s >> 7;
                    s ^= s << 17;
                    // Few distinct high halves, so ties (broken by the index) are common.
                    ((s % 97) << 32 | ((s >> 20) % 3) << 50) | i
                })
                .collect();
            let mut want = keys.clone();
            want.sort_unstable();
            assert_eq!(radix_sort_high(keys), want);
        }
    }
}
