//! The default Delaunay triangulation: spatial sort + walking location + Lawson flips.
//!
//! 1. The points are put in Hilbert-curve order (the curve over a 2^16 × 2^16 grid laid on
//!    the bounding box). The order only affects speed: every decision below is exact.
//! 2. Each point is located by a visibility walk from the last triangle created, which is
//!    next to the previous point (a few steps on average in Hilbert order).
//! 3. It is inserted by splitting its triangle (or edge) and restoring the Delaunay property
//!    with the book's LEGALIZEEDGE flips (§9.3), on a mesh closed by ghost triangles (see
//!    `mesh.rs`), so outside points need no symbolic or huge bounding points.
//!
//! Expected O(n log n) (the sort) and O(n) for the rest on uniform input. A point equal to
//! an existing vertex is found as `Found::Vertex` and merged.

use super::mesh::{Found, Mesh};
use super::pred::orient;
use crate::Point2;

/// Hilbert index of (x, y) on a 2^16 grid.
fn hilbert(mut x: u32, mut y: u32) -> u32 {
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

/// The input indices in Hilbert order (ties by index, so the order is deterministic).
pub(crate) fn hilbert_order(pts: &[Point2]) -> Vec<u32> {
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
    let q = |v: f64, lo: f64, span: f64| -> u32 {
        let t = ((v / 2.0 - lo / 2.0) / span * 65535.0).floor();
        t.clamp(0.0, 65535.0) as u32
    };
    let mut keys: Vec<u64> = pts
        .iter()
        .enumerate()
        .map(|(i, p)| (u64::from(hilbert(q(p.x, x0, w), q(p.y, y0, h))) << 32) | i as u64)
        .collect();
    keys.sort_unstable();
    keys.into_iter().map(|k| k as u32).collect()
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
    let order = hilbert_order(pts);
    // The first triangle: the first point, the next distinct one, the next not on their line.
    let a = order[0];
    let Some(ib) = order
        .iter()
        .position(|&i| pts[i as usize] != pts[a as usize])
    else {
        return (None, dedup_sorted(pts, rep));
    };
    let b = order[ib];
    let Some(ic) = order[ib + 1..]
        .iter()
        .position(|&i| orient(pts[a as usize], pts[b as usize], pts[i as usize]) != 0)
    else {
        return (None, dedup_sorted(pts, rep));
    };
    let ic = ib + 1 + ic;
    let c = order[ic];
    let mut mesh = if orient(pts[a as usize], pts[b as usize], pts[c as usize]) > 0 {
        Mesh::new(pts, a, b, c, n)
    } else {
        Mesh::new(pts, a, c, b, n)
    };
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
    (Some(mesh), rep)
}

/// For degenerate input (no triangles): merge equal points by sorting.
pub(crate) fn dedup_sorted(pts: &[Point2], mut rep: Vec<u32>) -> Vec<u32> {
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
