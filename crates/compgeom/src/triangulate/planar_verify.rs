//! The exact verifier of a subdivision triangulation ([`super::triangulate_subdivision`]).
//!
//! Checks, all exact:
//! 1. the vertices are the subdivision's, then box corners, all distinct; the box is their
//!    bounding box and [`SubdivisionTriangulation::boundary`] lists exactly the vertices
//!    on it, counter-clockwise from the lower-left corner;
//! 2. every triangle is strictly counter-clockwise;
//! 3. every box side piece is an edge of exactly one triangle, in its counter-clockwise
//!    direction, and every other triangle edge `a → b` is matched by exactly one `b → a`;
//! 4. there are 2V − b − 2 triangles (Euler's formula for V vertices, b on the box), and
//!    their areas sum exactly to the box's;
//! 5. every subdivision edge is a triangle edge, or a union of collinear triangle edges;
//! 6. faces: a triangle along a subdivision half-edge lies in that half-edge's face, one
//!    along a box side that is not a subdivision edge in the unbounded face, and two
//!    triangles sharing any other edge in the same face.
//!
//! 2 and 3 say the triangles' boundaries add up to the box's, so every point of the box
//! is covered once (the winding number): no two triangles overlap and together they tile
//! the box. With 6, every face of the subdivision is tiled by the triangles labelled with
//! it (a region bounded by subdivision edges and the box). O(n log n).
use super::planar::SubdivisionTriangulation;
use crate::dcel::{Dcel, FaceId, HalfEdgeId};
use crate::kernel::arith::Arith;
use crate::kernel::exact::Dyadic;
use crate::kernel::{orient2d, Orientation, Point2};
use crate::{Error, Result};
use std::cmp::Ordering;
use std::collections::HashMap;

fn fail<T>(m: String) -> Result<T> {
    Err(Error::Verification(m))
}

/// Verify `t` as a triangulation of `dcel` inside a box (see the module docs); the error
/// names the first broken invariant.
pub fn verify_subdivision_triangulation<V, E, F>(
    dcel: &Dcel<V, E, F>,
    t: &SubdivisionTriangulation,
) -> Result<()> {
    let nv = dcel.vertex_count();
    let pts = &t.vertices;
    let n = pts.len();
    if n < nv || n > nv + 4 {
        return fail(format!("{n} vertices for a subdivision of {nv}"));
    }
    for v in dcel.vertex_ids() {
        if dcel.vertex(v).point.compare_xy(&pts[v.0].into()) != Ordering::Equal {
            return fail(format!("vertex {} is not the subdivision's", v.0));
        }
    }
    let mut sorted: Vec<(u64, u64)> = pts
        .iter()
        .map(|p| ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits()))
        .collect();
    sorted.sort_unstable();
    if sorted.windows(2).any(|w| w[0] == w[1]) {
        return fail("two vertices coincide".into());
    }
    // 1. The box and its boundary.
    let x0 = pts.iter().map(|p| p.x).fold(f64::INFINITY, f64::min);
    let y0 = pts.iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
    let x1 = pts.iter().map(|p| p.x).fold(f64::NEG_INFINITY, f64::max);
    let y1 = pts.iter().map(|p| p.y).fold(f64::NEG_INFINITY, f64::max);
    for c in [(x0, y0), (x1, y0), (x1, y1), (x0, y1)] {
        if !pts.contains(&Point2::new(c.0, c.1)) {
            return fail(format!("box corner ({}, {}) is not a vertex", c.0, c.1));
        }
    }
    if pts[nv..]
        .iter()
        .any(|p| !((p.x == x0 || p.x == x1) && (p.y == y0 || p.y == y1)))
    {
        return fail("an added vertex is not a box corner".into());
    }
    // Position along the boundary, counter-clockwise from (x0, y0).
    let place = |p: Point2| -> Option<(u8, f64)> {
        if p.y == y0 && p.x < x1 {
            Some((0, p.x))
        } else if p.x == x1 && p.y < y1 {
            Some((1, p.y))
        } else if p.y == y1 && p.x > x0 {
            Some((2, -p.x))
        } else if p.x == x0 && p.y > y0 {
            Some((3, -p.y))
        } else {
            None
        }
    };
    let mut on_box: Vec<(u8, f64, usize)> = (0..n)
        .filter_map(|i| place(pts[i]).map(|(s, c)| (s, c, i)))
        .collect();
    // (`total_cmp` is safe: the vertices are distinct with -0 as 0, so two on one side
    // differ in the coordinate along it and -0 never meets 0 there.)
    on_box.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.total_cmp(&b.1)));
    let boundary: Vec<usize> = on_box.iter().map(|x| x.2).collect();
    if boundary != t.boundary {
        return fail("the boundary is not the box's vertices in counter-clockwise order".into());
    }
    // 2. Triangles.
    if t.faces.len() != t.triangles.len() {
        return fail("not one face per triangle".into());
    }
    let mut area2 = Dyadic::zero();
    // (edge a -> b as a u64, triangle)
    let mut edges: Vec<(u64, usize)> = Vec::with_capacity(3 * t.triangles.len());
    let code = |a: usize, b: usize| ((a as u64) << 32) | b as u64;
    for (i, tri) in t.triangles.iter().enumerate() {
        if tri.iter().any(|&v| v >= n) {
            return fail(format!("triangle {i} has a vertex index out of range"));
        }
        let [a, b, c] = tri.map(|v| pts[v]);
        if orient2d(a, b, c) != Orientation::CounterClockwise {
            return fail(format!("triangle {i} {tri:?} is not counter-clockwise"));
        }
        let d = Dyadic::diff(b.x, a.x)
            .times(&Dyadic::diff(c.y, a.y))
            .minus(&Dyadic::diff(b.y, a.y).times(&Dyadic::diff(c.x, a.x)));
        area2 = area2.plus(&d);
        for s in 0..3 {
            edges.push((code(tri[s], tri[(s + 1) % 3]), i));
        }
    }
    edges.sort_unstable();
    if let Some(w) = edges.windows(2).find(|w| w[0].0 == w[1].0) {
        return fail(format!(
            "edge {} -> {} is used by two triangles in the same direction",
            w[0].0 >> 32,
            w[0].0 & 0xffff_ffff
        ));
    }
    let find = |a: usize, b: usize| {
        edges
            .binary_search_by(|x| x.0.cmp(&code(a, b)))
            .ok()
            .map(|i| edges[i].1)
    };
    // 3. Box sides once, counter-clockwise; every other edge matched.
    let b = boundary.len();
    let mut is_side: HashMap<u64, ()> = HashMap::with_capacity(b);
    for k in 0..b {
        let (u, w) = (boundary[k], boundary[(k + 1) % b]);
        if find(u, w).is_none() {
            return fail(format!("box side {u} -> {w} is not covered"));
        }
        is_side.insert(code(u, w), ());
    }
    // Subdivision half-edges by their ends.
    let mut half: HashMap<u64, HalfEdgeId> = HashMap::with_capacity(2 * dcel.edge_count());
    for h in dcel.half_edge_ids() {
        let (a, z) = (dcel.half_edge(h).origin.0, dcel.destination(h).0);
        half.insert(code(a, z), h);
    }
    for &(e, i) in &edges {
        let (u, w) = ((e >> 32) as usize, (e & 0xffff_ffff) as usize);
        let face = t.faces[i];
        if let Some(&h) = half.get(&e) {
            if dcel.half_edge(h).face != face {
                return fail(format!(
                    "triangle {i} lies along a half-edge of face {} but is labelled {}",
                    dcel.half_edge(h).face.0,
                    face.0
                ));
            }
        }
        if is_side.contains_key(&e) {
            if !half.contains_key(&e) && face != FaceId::UNBOUNDED {
                return fail(format!(
                    "triangle {i} on the box side {u} -> {w} is not in the unbounded face"
                ));
            }
            continue;
        }
        if is_side.contains_key(&code(w, u)) {
            return fail(format!("a triangle lies outside the box along {w} -> {u}"));
        }
        match find(w, u) {
            None => return fail(format!("edge {u} -> {w} has a triangle on one side only")),
            Some(j) if !half.contains_key(&e) && t.faces[j] != face => {
                return fail(format!(
                    "triangles {i} and {j} share the edge {u} -> {w}, which is no \
                     subdivision edge, but lie in different faces"
                ))
            }
            _ => {}
        }
    }
    // 4. Euler and the area.
    let want = 2 * n as i64 - b as i64 - 2;
    if t.triangles.len() as i64 != want {
        return fail(format!("{} triangles, expected {want}", t.triangles.len()));
    }
    let box2 = Dyadic::diff(x1, x0)
        .times(&Dyadic::diff(y1, y0))
        .plus(&Dyadic::diff(x1, x0).times(&Dyadic::diff(y1, y0)));
    if area2.minus(&box2).sign() != Some(Ordering::Equal) {
        return fail("the triangles' areas do not sum to the box's".into());
    }
    // 5. Every subdivision edge along triangle edges.
    if t.edges.len() != dcel.edge_count() {
        return fail("not one entry per subdivision edge".into());
    }
    // Triangle edges in both directions (a subdivision edge on the box has a triangle on
    // one side only).
    let mut both: Vec<u64> = edges
        .iter()
        .flat_map(|&(e, _)| [e, e.rotate_right(32)])
        .collect();
    both.sort_unstable();
    both.dedup();
    for (i, &[a, z]) in t.edges.iter().enumerate() {
        let h = HalfEdgeId(2 * i);
        if [a, z] != [dcel.half_edge(h).origin.0, dcel.destination(h).0] {
            return fail(format!("edge {i} is not the subdivision's edge {i}"));
        }
        let (pa, pz) = (pts[a], pts[z]);
        let mut cur = a;
        while cur != z {
            // The triangle edge leaving `cur` along a → z, towards z.
            let lo = both.partition_point(|&x| x < code(cur, 0));
            let hi = both.partition_point(|&x| x <= code(cur, u32::MAX as usize));
            let step = both[lo..hi]
                .iter()
                .map(|&x| (x & 0xffff_ffff) as usize)
                .find(|&w| {
                    let pw = pts[w];
                    orient2d(pa, pz, pw) == Orientation::Collinear && between(pts[cur], pw, pz)
                });
            match step {
                Some(w) => cur = w,
                None => return fail(format!("subdivision edge {i} is not a triangle edge")),
            }
        }
    }
    Ok(())
}

/// `q` lies on the segment from `p` (excluded) to `r` (included), for collinear points.
fn between(p: Point2, q: Point2, r: Point2) -> bool {
    let inside = |a: f64, b: f64, c: f64| (a < b && b <= c) || (a > b && b >= c);
    if p.x != r.x {
        inside(p.x, q.x, r.x)
    } else {
        inside(p.y, q.y, r.y)
    }
}
