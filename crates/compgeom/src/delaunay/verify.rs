//! The exact verifier of Delaunay triangulations.
//!
//! [`verify_delaunay`] checks, with exact predicates only:
//!
//! 1. structure ([`Triangulation::validate`]) and that the vertices are distinct;
//! 2. every triangle is strictly counter-clockwise (exact `orient2d`);
//! 3. every interior edge is locally Delaunay: the vertex across it is not strictly inside
//!    the circumcircle (exact `incircle`) — by the Delaunay lemma (book Theorem 9.8) this makes
//!    the triangulation Delaunay;
//! 4. the triangles tile the convex hull: the boundary edges form one closed cycle that
//!    turns only left or straight and has a single lexicographic minimum (a convex polygon,
//!    wound once); every vertex is used; V − E + F = 1 (a disk); and the triangles around
//!    every interior vertex turn exactly once (no folded or doubly covered region). A
//!    positively oriented disk mesh with these properties covers its convex boundary polygon
//!    exactly once, which is the exact form of "the areas add up to the hull's area". Since
//!    all vertices lie in the polygon and its corners are vertices, it is the convex hull;
//! 5. with no triangles: fewer than three vertices, or all of them collinear.
//!
//! O(n log n) (one sort for distinctness), O(n) predicates.

use super::pred::{in_circle, orient};
use super::triangulation::{Triangulation, NO_NEIGHBOR};
use crate::kernel::compare_xy;
use crate::{Error, Point2, Result};
use std::cmp::Ordering;

/// Checks exactly that `t` is a Delaunay triangulation of its vertices (see the module
/// docs of `verify.rs` for the list of checks).
///
/// ```
/// use compgeom::delaunay::{delaunay, verify_delaunay};
/// use compgeom::Point2;
/// let mut t = delaunay(&[(0.0, 0.0), (3.0, 0.0), (0.0, 3.0), (3.0, 3.5)].map(Point2::from))?;
/// verify_delaunay(&t)?;
/// // Any other diagonal of the quadrilateral is not Delaunay:
/// let q = t.clone();
/// let other = compgeom::delaunay::Triangulation::from_parts(
///     q.vertices().to_vec(), vec![[0, 1, 2], [2, 1, 3]], q.input_to_vertex().to_vec())?;
/// verify_delaunay(&other)?;
/// let bad = compgeom::delaunay::Triangulation::from_parts(
///     q.vertices().to_vec(), vec![[0, 1, 3], [0, 3, 2]], q.input_to_vertex().to_vec())?;
/// assert!(verify_delaunay(&bad).is_err());
/// # t = q; let _ = t;
/// # Ok::<(), compgeom::Error>(())
/// ```
///
/// # Errors
/// `Error::Verification` naming the first broken property.
pub fn verify_delaunay(t: &Triangulation) -> Result<()> {
    t.validate()?;
    check_distinct(t.vertices())?;
    let v = t.vertices();
    let tris = t.triangles();
    if tris.is_empty() {
        return check_collinear(v);
    }
    for (i, tri) in tris.iter().enumerate() {
        if orient(v[tri[0] as usize], v[tri[1] as usize], v[tri[2] as usize]) <= 0 {
            return fail(format!("triangle {i} {tri:?} is not counter-clockwise"));
        }
    }
    check_locally_delaunay(t, |_, _| false)?;
    check_tiles_hull(t)
}

/// Check 3, skipping the edges `skip(a, b)` says are constrained.
pub(crate) fn check_locally_delaunay(
    t: &Triangulation,
    skip: impl Fn(u32, u32) -> bool,
) -> Result<()> {
    let v = t.vertices();
    for (i, tri) in t.triangles().iter().enumerate() {
        for k in 0..3 {
            let n = t.neighbors()[i][k];
            if n == NO_NEIGHBOR || (n as usize) < i {
                continue;
            }
            let (a, b) = (tri[(k + 1) % 3], tri[(k + 2) % 3]);
            if skip(a, b) {
                continue;
            }
            let other = t.triangles()[n as usize];
            let Some(&d) = other.iter().find(|&&x| x != a && x != b) else {
                return fail(format!("triangles {i} and {n} are equal"));
            };
            let [p, q, r] = tri.map(|x| v[x as usize]);
            if in_circle(p, q, r, v[d as usize]) > 0 {
                return fail(format!(
                    "edge ({a}, {b}) is not locally Delaunay: vertex {d} is inside the circumcircle of triangle {i}"
                ));
            }
        }
    }
    Ok(())
}

/// Check 4 (see the module docs).
pub(crate) fn check_tiles_hull(t: &Triangulation) -> Result<()> {
    check_disk(t)?;
    let v = t.vertices();
    let hull = t.hull();
    let boundary_edges = t
        .neighbors()
        .iter()
        .flatten()
        .filter(|&&n| n == NO_NEIGHBOR)
        .count();
    if hull.len() != boundary_edges {
        return fail(format!(
            "the {boundary_edges} boundary edges do not form one cycle (a cycle of {} found)",
            hull.len()
        ));
    }
    let m = hull.len();
    let mut minima = 0;
    for i in 0..m {
        let (a, b, c) = (
            v[hull[(i + m - 1) % m] as usize],
            v[hull[i] as usize],
            v[hull[(i + 1) % m] as usize],
        );
        if orient(a, b, c) < 0 {
            return fail(format!(
                "the boundary turns right at vertex {}: not convex",
                hull[i]
            ));
        }
        if compare_xy(b, a) == Ordering::Less && compare_xy(b, c) == Ordering::Less {
            minima += 1;
        }
    }
    if minima != 1 {
        return fail(format!("the boundary winds {minima} times around the hull"));
    }
    Ok(())
}

/// The mesh is a disk: every vertex used, V − E + F = 1, and every interior vertex's fan
/// turns exactly once (exact: only coordinate comparisons and orientations).
pub(crate) fn check_disk(t: &Triangulation) -> Result<()> {
    let v = t.vertices();
    let nv = v.len();
    let mut used = vec![false; nv];
    let mut on_boundary = vec![false; nv];
    // Lower-to-upper crossings of the positive x-ray, per vertex, over its fan.
    let mut crossings = vec![0u32; nv];
    let upper = |c: Point2, d: Point2| d.y > c.y || (d.y == c.y && d.x > c.x);
    for (i, tri) in t.triangles().iter().enumerate() {
        for k in 0..3 {
            let c = tri[k] as usize;
            used[c] = true;
            if t.neighbors()[i][k] == NO_NEIGHBOR {
                on_boundary[tri[(k + 1) % 3] as usize] = true;
                on_boundary[tri[(k + 2) % 3] as usize] = true;
            }
            // Turning at c from direction to tri[k+1] to direction to tri[k+2] (left turn).
            let (p, q) = (v[tri[(k + 1) % 3] as usize], v[tri[(k + 2) % 3] as usize]);
            if !upper(v[c], p) && upper(v[c], q) {
                crossings[c] += 1;
            }
        }
    }
    if let Some(i) = used.iter().position(|&u| !u) {
        return fail(format!("vertex {i} is in no triangle"));
    }
    if let Some(i) = (0..nv).find(|&i| !on_boundary[i] && crossings[i] != 1) {
        return fail(format!(
            "the triangles around interior vertex {i} wind {} times",
            crossings[i]
        ));
    }
    let e = t.edges().len();
    let f = t.triangles().len();
    if nv + f != e + 1 {
        return fail(format!("V - E + F = {nv} - {e} + {f} is not 1: not a disk"));
    }
    Ok(())
}

fn check_distinct(v: &[Point2]) -> Result<()> {
    let mut idx: Vec<usize> = (0..v.len()).collect();
    idx.sort_by(|&a, &b| compare_xy(v[a], v[b]));
    for w in idx.windows(2) {
        if v[w[0]] == v[w[1]] {
            return fail(format!("vertices {} and {} are equal", w[0], w[1]));
        }
    }
    Ok(())
}

fn check_collinear(v: &[Point2]) -> Result<()> {
    if v.len() >= 3 {
        if let Some(i) = (2..v.len()).find(|&i| orient(v[0], v[1], v[i]) != 0) {
            return fail(format!(
                "no triangles, but vertices 0, 1, {i} are not collinear"
            ));
        }
    }
    Ok(())
}

fn fail(msg: String) -> Result<()> {
    Err(Error::Verification(msg))
}
