//! The Euclidean minimum spanning tree from the Delaunay edges (book §9.6 notes: the EMST
//! is a subgraph of the Delaunay graph).
//!
//! Kruskal's algorithm on the Delaunay edges, with union–find. Edge lengths are compared
//! exactly: squared lengths in `f64` first, and when two are within the rounding margin,
//! again in exact rational arithmetic from the input coordinates; equal lengths are ordered
//! by their vertex pair, so the tree is deterministic. O(n log n).
//!
//! Degenerate input: duplicates are merged (the tree spans the distinct points); collinear
//! points give the path along the line (the Delaunay graph has no triangles then, so the
//! tree is built from consecutive points in lexicographic order).

use super::{delaunay, Triangulation};
use crate::kernel::compare_xy;
use crate::{Point2, Result};
use num_rational::BigRational;
use std::cmp::Ordering;

/// The Euclidean minimum spanning tree of `points`: the Delaunay triangulation (for its
/// vertex numbering) and the tree's edges as vertex pairs `(u, v)`, `u < v`, shortest first.
///
/// ```
/// use compgeom::delaunay::euclidean_mst;
/// use compgeom::Point2;
/// let pts = [(0.0, 0.0), (1.0, 0.0), (5.0, 0.0), (1.0, 1.0)].map(Point2::from);
/// let (_, tree) = euclidean_mst(&pts)?;
/// assert_eq!(tree, vec![(0, 1), (1, 3), (1, 2)]);
/// # Ok::<(), compgeom::Error>(())
/// ```
///
/// # Errors
/// As [`delaunay`].
pub fn euclidean_mst(points: &[Point2]) -> Result<(Triangulation, Vec<(u32, u32)>)> {
    let t = delaunay(points)?;
    let v = t.vertices();
    let mut edges = if t.is_degenerate() {
        let mut idx: Vec<u32> = (0..v.len() as u32).collect();
        idx.sort_by(|&a, &b| compare_xy(v[a as usize], v[b as usize]));
        idx.windows(2)
            .map(|w| (w[0].min(w[1]), w[0].max(w[1])))
            .collect()
    } else {
        t.edges()
    };
    edges.sort_by(|&e, &f| compare_lengths(v, e, f).then(e.cmp(&f)));
    let mut parent: Vec<u32> = (0..v.len() as u32).collect();
    fn root(p: &mut [u32], mut x: u32) -> u32 {
        while p[x as usize] != x {
            p[x as usize] = p[p[x as usize] as usize];
            x = p[x as usize];
        }
        x
    }
    let mut tree = Vec::with_capacity(v.len().saturating_sub(1));
    for (a, b) in edges {
        let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
        if ra != rb {
            parent[ra as usize] = rb;
            tree.push((a, b));
        }
    }
    Ok((t, tree))
}

/// Exact comparison of the lengths of edges `e` and `f`.
fn compare_lengths(v: &[Point2], e: (u32, u32), f: (u32, u32)) -> Ordering {
    let sq = |(a, b): (u32, u32)| {
        let (p, q) = (v[a as usize], v[b as usize]);
        let (dx, dy) = (p.x - q.x, p.y - q.y);
        dx * dx + dy * dy
    };
    let (le, lf) = (sq(e), sq(f));
    // Each squared length carries a relative error below 4 ulp; outside that margin (and
    // with no overflow or underflow) the f64 order is the exact order.
    let margin = 1e-14 * le.max(lf);
    if le.is_finite() && lf.is_finite() && (le - lf).abs() > margin && le.min(lf) > 1e-250 {
        return le.total_cmp(&lf);
    }
    let exact = |(a, b): (u32, u32)| {
        let r = |x: f64| BigRational::from_float(x).unwrap_or_default();
        let (p, q) = (v[a as usize], v[b as usize]);
        let dx = r(p.x) - r(q.x);
        let dy = r(p.y) - r(q.y);
        &dx * &dx + &dy * &dy
    };
    exact(e).cmp(&exact(f))
}
