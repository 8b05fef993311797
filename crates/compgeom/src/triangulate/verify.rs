//! The exact verifier of a polygon triangulation.
//!
//! Checks, all exact:
//! 1. the vertices are the polygon's (repeated consecutive vertices dropped);
//! 2. every triangle is strictly counter-clockwise ([`orient2d`]);
//! 3. every boundary edge (interior on its left) is an edge of exactly one triangle, in
//!    its direction, and no triangle uses it backwards;
//! 4. every other triangle edge `a → b` is matched by exactly one triangle with `b → a`
//!    (so it is a diagonal with a triangle on each side);
//! 5. the number of triangles is n − 2 + 2h (in general, with rings touching at
//!    vertices: the sum over boundary cycles of length − 2 for an outer cycle and length
//!    + 2 for a hole cycle).
//!
//! Together, 2–4 say the triangles' boundaries add up to the polygon's boundary, so the
//! number of triangles covering a point is the polygon's winding number there: 1 inside,
//! 0 outside. Hence no two triangles overlap, they cover the polygon, their areas sum
//! exactly to its area, and every diagonal lies inside it; as no triangle is flat and
//! boundary points are not interior points, no vertex lies inside a triangle edge.
//! O(n log n).
use super::geometry::Geometry;
use super::subdivision::boundary_cycles;
use super::Triangulation;
use crate::kernel::{orient2d, Orientation, Polygon};
use crate::{Error, Result};
use std::cmp::Ordering;

/// Verify `t` as a triangulation of `polygon` (see the module docs); the error names the
/// first broken invariant.
pub fn verify_triangulation(polygon: &Polygon, t: &Triangulation) -> Result<()> {
    // The triangulation may be of the normalised polygon (edges split at vertices lying
    // inside them: see `touching`).
    let g = match Geometry::new(polygon) {
        Ok(g) if g.pts == t.vertices => g,
        first => match super::touching::split_touching(polygon)? {
            Some(split) => Geometry::new(&split)?,
            None => first?,
        },
    };
    let fail = |m: String| Err(Error::Verification(m));
    if g.pts != t.vertices {
        return fail("the vertices are not the polygon's".into());
    }
    let n = g.len();
    let mut edges: Vec<u64> = Vec::with_capacity(3 * t.triangles.len());
    for (i, tri) in t.triangles.iter().enumerate() {
        if tri.iter().any(|&v| v >= n) {
            return fail(format!("triangle {i} has a vertex index out of range"));
        }
        let [a, b, c] = tri.map(|v| t.vertices[v]);
        if orient2d(a, b, c) != Orientation::CounterClockwise {
            return fail(format!("triangle {i} {tri:?} is not counter-clockwise"));
        }
        for s in 0..3 {
            edges.push(((tri[s] as u64) << 32) | tri[(s + 1) % 3] as u64);
        }
    }
    edges.sort_unstable();
    if let Some(w) = edges.windows(2).find(|w| w[0] == w[1]) {
        return fail(format!(
            "edge {} -> {} is used by two triangles in the same direction",
            w[0] >> 32,
            w[0] & 0xffff_ffff
        ));
    }
    let has = |a: usize, b: usize| {
        edges
            .binary_search(&(((a as u64) << 32) | b as u64))
            .is_ok()
    };
    for v in 0..n {
        let w = g.next[v] as usize;
        if !has(v, w) {
            return fail(format!("boundary edge {v} -> {w} is not covered"));
        }
    }
    for &e in &edges {
        let (a, b) = ((e >> 32) as usize, (e & 0xffff_ffff) as usize);
        if g.next[a] as usize == b {
            continue;
        }
        if g.next[b] as usize == a {
            return fail(format!(
                "a triangle lies outside the polygon along edge {b} -> {a}"
            ));
        }
        if !has(b, a) {
            return fail(format!(
                "diagonal {a} -> {b} has a triangle on one side only"
            ));
        }
    }
    let expected = expected_triangles(&g);
    if t.triangles.len() as i64 != expected {
        return fail(format!(
            "{} triangles, expected {expected}",
            t.triangles.len()
        ));
    }
    Ok(())
}

/// The number of triangles of any triangulation: the sum over boundary cycles of length
/// − 2 (outer) or + 2 (hole), a cycle's kind read from the turn at its top vertex.
pub(crate) fn expected_triangles(g: &Geometry) -> i64 {
    let mut total = 0i64;
    for cycle in boundary_cycles(g) {
        let top = cycle
            .iter()
            .copied()
            .min_by(|&a, &b| g.cmp_event(a, b))
            .unwrap_or(0);
        let (p, q) = (g.prev[top as usize], g.next[top as usize]);
        let outer = g.orient(p, top, q) == Ordering::Greater;
        total += cycle.len() as i64 + if outer { -2 } else { 2 };
    }
    total
}
