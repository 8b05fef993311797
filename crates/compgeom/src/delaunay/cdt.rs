//! Constrained Delaunay triangulations: segment constraints and polygons with holes.
//!
//! Method: the Delaunay triangulation of all points and constraint endpoints (the default
//! algorithm), then each constraint `a–b` is inserted by Sloan's flipping method: the edges
//! it crosses are found by walking from `a` to `b` and flipped (those whose quadrilateral is
//! strictly convex first) until none crosses; then the constrained Delaunay property is
//! restored by Lawson flips that never flip a constrained edge. Every test is an exact
//! orientation or in-circle predicate.
//!
//! Degenerate input: a vertex lying exactly on a constraint splits it there (both pieces
//! are constrained); repeated and zero-length constraints are merged / ignored; constraints
//! that share endpoints are fine. Two constraints that **cross** at a point that is not an
//! input vertex are reported as `Error::InvalidInput` naming both (splitting at constructed
//! crossings is not implemented yet).
//!
//! [`polygon_delaunay`] constrains every ring edge and keeps the triangles inside the
//! polygons (odd nesting depth of constraint loops: holes removed).
//!
//! Time: O(n log n) for the triangulation plus O(k) flips per constraint crossing k edges
//! (worst case O(n²) overall).

use super::fast;
use super::mesh::{next, prev, Mesh, GHOST};
use super::pred::{in_circle, orient};
use super::triangulation::{Triangulation, NO_NEIGHBOR};
use super::verify::check_locally_delaunay;
use crate::kernel::ensure_finite;
use crate::{Error, Point2, Polygon, Result, Segment2};
use std::collections::{HashSet, VecDeque};

/// A constrained Delaunay triangulation: the triangulation and its constrained edges.
#[derive(Debug, Clone, PartialEq)]
pub struct Cdt {
    /// The triangles. `input_to_vertex` covers the points, then the constraint endpoints
    /// (`a`, `b` of segment 0, then of segment 1, …) or the ring vertices in order.
    pub triangulation: Triangulation,
    /// The constrained edges as vertex pairs `(u, v)`, `u < v`, sorted (split pieces listed
    /// separately).
    pub constraints: Vec<(u32, u32)>,
}

/// The constrained Delaunay triangulation of `points` and `segments` (whole convex hull).
///
/// ```
/// use compgeom::delaunay::{constrained_delaunay, verify_cdt};
/// use compgeom::{Point2, Segment2};
/// let pts = [(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0), (2.0, 1.0), (2.0, 3.0)]
///     .map(Point2::from);
/// // Without the constraint the Delaunay edge would be (2,1)-(2,3); force (0,0)-(4,4).
/// let seg = [Segment2::new(Point2::new(0.0, 0.0), Point2::new(4.0, 4.0))];
/// let cdt = constrained_delaunay(&pts, &seg)?;
/// verify_cdt(&cdt)?;
/// assert_eq!(cdt.constraints, vec![(0, 2)]);
/// # Ok::<(), compgeom::Error>(())
/// ```
///
/// # Errors
/// `NonFinite` for a NaN/infinite coordinate; `InvalidInput` for crossing constraints.
pub fn constrained_delaunay(points: &[Point2], segments: &[Segment2]) -> Result<Cdt> {
    ensure_finite(points, "point")?;
    let mut all = points.to_vec();
    for (i, s) in segments.iter().enumerate() {
        ensure_finite(&[s.a, s.b], &format!("segment {i} endpoint"))?;
        all.push(s.a);
        all.push(s.b);
    }
    let pairs: Vec<(usize, usize)> = (0..segments.len())
        .map(|i| (points.len() + 2 * i, points.len() + 2 * i + 1))
        .collect();
    build(&all, &pairs, false)
}

/// The constrained Delaunay triangulation of polygons with holes: every ring edge is a
/// constraint and only the triangles inside the polygons are kept.
///
/// ```
/// use compgeom::delaunay::{polygon_delaunay, verify_cdt};
/// use compgeom::{Point2, Polygon};
/// let sq = |s: f64, o: f64| vec![Point2::new(o, o), Point2::new(s, o), Point2::new(s, s), Point2::new(o, s)];
/// let with_hole = Polygon::new(sq(10.0, 0.0), vec![sq(6.0, 4.0)]);
/// let cdt = polygon_delaunay(&[with_hole])?;
/// verify_cdt(&cdt)?;
/// assert_eq!(cdt.triangulation.triangles().len(), 8); // n + 2h - 2 = 8 + 2 - 2
/// # Ok::<(), compgeom::Error>(())
/// ```
///
/// # Errors
/// As [`constrained_delaunay`].
pub fn polygon_delaunay(polygons: &[Polygon]) -> Result<Cdt> {
    polygon_delaunay_with_points(&[], polygons)
}

/// As [`polygon_delaunay`], with extra `points` (Steiner points given by the caller) inserted
/// first; those outside the polygons end up in no kept triangle. `input_to_vertex` covers the
/// points, then the ring vertices.
///
/// # Errors
/// As [`constrained_delaunay`].
pub fn polygon_delaunay_with_points(points: &[Point2], polygons: &[Polygon]) -> Result<Cdt> {
    ensure_finite(points, "point")?;
    let mut all = points.to_vec();
    let mut pairs = Vec::new();
    for (pi, poly) in polygons.iter().enumerate() {
        for (ri, ring) in poly.rings().enumerate() {
            ensure_finite(ring, &format!("polygon {pi} ring {ri} vertex"))?;
            let mut ring = ring.as_slice();
            if ring.len() > 1 && ring.first() == ring.last() {
                ring = &ring[..ring.len() - 1];
            }
            let base = all.len();
            all.extend_from_slice(ring);
            for k in 0..ring.len() {
                pairs.push((base + k, base + (k + 1) % ring.len()));
            }
        }
    }
    build(&all, &pairs, true)
}

fn build(all: &[Point2], pairs: &[(usize, usize)], interior_only: bool) -> Result<Cdt> {
    if all.len() > super::MAX_POINTS {
        return Err(Error::InvalidInput(format!(
            "{} points and constraint endpoints: at most {} are supported",
            all.len(),
            super::MAX_POINTS
        )));
    }
    let (mesh, rep) = fast::triangulate(all);
    let Some(mut mesh) = mesh else {
        let t = Triangulation::from_mesh(all, None, &rep);
        return Ok(Cdt {
            triangulation: t,
            constraints: Vec::new(),
        });
    };
    let mut fixed: HashSet<(u32, u32)> = HashSet::new();
    let mut star = Star::new(&mesh);
    for (ci, &(i, j)) in pairs.iter().enumerate() {
        let (a, b) = (rep[i], rep[j]);
        if a != b {
            insert_constraint(&mut mesh, &mut star, &mut fixed, a, b, ci)?;
        }
    }
    restore(&mut mesh, &fixed);
    let mut t = Triangulation::from_mesh(all, Some(&mesh), &rep);
    // Vertex ids in `fixed` are input indices: map them like the triangles.
    let map = |v: u32| t.input_to_vertex[v as usize];
    let mut constraints: Vec<(u32, u32)> = fixed
        .iter()
        .map(|&(u, v)| (map(u).min(map(v)), map(u).max(map(v))))
        .collect();
    constraints.sort_unstable();
    if interior_only {
        keep_inside(&mut t, &constraints);
    }
    Ok(Cdt {
        triangulation: t,
        constraints,
    })
}

fn key(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

/// The half-edges leaving each vertex: one per vertex (`vmap`), rotated through twins.
struct Star {
    vmap: Vec<u32>,
}

impl Star {
    fn new(mesh: &Mesh<'_>) -> Self {
        let mut vmap = vec![u32::MAX; mesh.pts.len()];
        for (h, &v) in mesh.v.iter().enumerate() {
            if v != GHOST {
                vmap[v as usize] = h as u32;
            }
        }
        Star { vmap }
    }

    /// Every half-edge leaving `a` (ghost triangles included), by rotation: O(degree).
    fn out_edges(&self, mesh: &Mesh<'_>, a: u32) -> Vec<u32> {
        let start = self.vmap[a as usize];
        let mut out = vec![start];
        let mut h = mesh.twin[prev(start) as usize];
        while h != start && out.len() <= mesh.v.len() {
            out.push(h);
            h = mesh.twin[prev(h) as usize];
        }
        out
    }

    fn find(&self, mesh: &Mesh<'_>, u: u32, w: u32) -> Option<u32> {
        self.out_edges(mesh, u)
            .into_iter()
            .find(|&h| mesh.v[next(h) as usize] == w)
    }

    /// Flips half-edge `e` and keeps the map valid.
    fn flip(&mut self, mesh: &mut Mesh<'_>, e: u32) {
        let f = mesh.twin[e as usize];
        mesh.flip(e);
        let (t, u) = (e / 3, f / 3);
        for h in [3 * t, 3 * t + 1, 3 * t + 2, 3 * u, 3 * u + 1, 3 * u + 2] {
            let v = mesh.v[h as usize];
            if v != GHOST {
                self.vmap[v as usize] = h;
            }
        }
    }
}

/// What the walk from `a` towards `b` found.
enum Walk {
    /// `a–b` is already an edge.
    Edge,
    /// Vertex `c` lies on the open segment `a–b`.
    Split(u32),
    /// The edges crossed, as vertex pairs, in order from `a`.
    Crossed(Vec<(u32, u32)>),
}

/// Walks from `a` to `b` through the triangles the segment crosses (exact orientations).
fn walk(
    mesh: &Mesh<'_>,
    star: &Star,
    fixed: &HashSet<(u32, u32)>,
    a: u32,
    b: u32,
    ci: usize,
) -> Result<Walk> {
    let (pa, pb) = (mesh.pt(a), mesh.pt(b));
    let out = star.out_edges(mesh, a);
    for &h in &out {
        let x = mesh.v[next(h) as usize];
        if x == b {
            return Ok(Walk::Edge);
        }
        if x != GHOST {
            let px = mesh.pt(x);
            if orient(pa, px, pb) == 0 && dot_positive(pa, px, pb) {
                return Ok(Walk::Split(x));
            }
        }
    }
    for &h in &out {
        if mesh.is_ghost(h / 3) {
            continue;
        }
        let x = mesh.v[next(h) as usize];
        let y = mesh.v[prev(h) as usize];
        if !(orient(pa, mesh.pt(x), pb) > 0 && orient(pa, mesh.pt(y), pb) < 0) {
            continue;
        }
        // b is beyond edge x -> y (x right of a->b, y left).
        let mut crossed = Vec::new();
        let mut e = next(h);
        loop {
            let (u, w) = (mesh.v[e as usize], mesh.v[next(e) as usize]);
            if fixed.contains(&key(u, w)) {
                return Err(Error::InvalidInput(format!(
                    "constraint {ci} crosses another constraint (at the edge between input points {u} and {w}); crossing constraints are not supported"
                )));
            }
            crossed.push((u, w));
            let f = mesh.twin[e as usize];
            let z = mesh.v[prev(f) as usize];
            if z == b {
                return Ok(Walk::Crossed(crossed));
            }
            if z == GHOST {
                break;
            }
            let oz = orient(pa, pb, mesh.pt(z));
            if oz == 0 {
                return Ok(Walk::Split(z));
            }
            // f = w -> u in triangle (w, u, z): leave through u–z when z is on w's (left)
            // side, else through z–w.
            e = if oz > 0 { next(f) } else { prev(f) };
        }
        break;
    }
    Err(Error::InvalidInput(format!(
        "constraint {ci}: no path through the triangulation (internal error)"
    )))
}

/// Sloan's insertion of constraint `a–b` (input vertex ids): a queue of the crossed edges;
/// an edge whose quadrilateral is strictly convex is flipped (its new diagonal re-queued if
/// it still crosses), otherwise it goes to the back of the queue.
fn insert_constraint(
    mesh: &mut Mesh<'_>,
    star: &mut Star,
    fixed: &mut HashSet<(u32, u32)>,
    a: u32,
    b: u32,
    ci: usize,
) -> Result<()> {
    let (pa, pb) = (mesh.pt(a), mesh.pt(b));
    let mut queue: VecDeque<(u32, u32)> = match walk(mesh, star, fixed, a, b, ci)? {
        Walk::Edge => {
            fixed.insert(key(a, b));
            return Ok(());
        }
        Walk::Split(c) => {
            insert_constraint(mesh, star, fixed, a, c, ci)?;
            return insert_constraint(mesh, star, fixed, c, b, ci);
        }
        Walk::Crossed(list) => list.into(),
    };
    let limit = 16 * queue.len() * queue.len() + 1000;
    let mut steps = 0;
    while let Some((u, w)) = queue.pop_front() {
        steps += 1;
        if steps > limit {
            return Err(Error::InvalidInput(format!(
                "constraint {ci}: flipping did not converge (internal error)"
            )));
        }
        let Some(e) = star.find(mesh, u, w) else {
            continue;
        };
        let f = mesh.twin[e as usize];
        let p = mesh.v[prev(e) as usize];
        let d = mesh.v[prev(f) as usize];
        if p == GHOST || d == GHOST {
            queue.push_back((u, w));
            continue;
        }
        let (pu, pw, pp, pd) = (mesh.pt(u), mesh.pt(w), mesh.pt(p), mesh.pt(d));
        if orient(pp, pu, pd) > 0 && orient(pp, pd, pw) > 0 {
            star.flip(mesh, e);
            if crosses(pa, pb, pp, pd) {
                queue.push_back((p, d));
            }
        } else {
            queue.push_back((u, w));
        }
    }
    match walk(mesh, star, fixed, a, b, ci)? {
        Walk::Edge => {
            fixed.insert(key(a, b));
            Ok(())
        }
        _ => Err(Error::InvalidInput(format!(
            "constraint {ci}: not an edge after flipping (internal error)"
        ))),
    }
}

fn dot_positive(a: Point2, x: Point2, b: Point2) -> bool {
    // x on the ray from a towards b (x != a), for collinear a, x, b: same direction.
    // (exact: only coordinate comparisons)
    let sign = |p: f64, q: f64| i8::from(p > q) - i8::from(p < q);
    sign(x.x, a.x) * sign(b.x, a.x) > 0 || sign(x.y, a.y) * sign(b.y, a.y) > 0
}

/// Does segment p–d properly cross segment a–b (interiors meet in one point)?
fn crosses(a: Point2, b: Point2, p: Point2, d: Point2) -> bool {
    orient(a, b, p) * orient(a, b, d) < 0 && orient(p, d, a) * orient(p, d, b) < 0
}

/// Lawson flips of every non-constrained, non-Delaunay edge until none is left.
fn restore(mesh: &mut Mesh<'_>, fixed: &HashSet<(u32, u32)>) {
    let mut stack: Vec<u32> = (0..mesh.v.len() as u32).collect();
    while let Some(h) = stack.pop() {
        let f = mesh.twin[h as usize];
        let (a, b) = (mesh.v[h as usize], mesh.v[next(h) as usize]);
        let p = mesh.v[prev(h) as usize];
        let d = mesh.v[prev(f) as usize];
        if p == GHOST || d == GHOST || a == GHOST || b == GHOST || fixed.contains(&key(a, b)) {
            continue;
        }
        if in_circle(mesh.pt(b), mesh.pt(a), mesh.pt(d), mesh.pt(p)) > 0 {
            mesh.flip(h);
            let (t, u) = (h / 3, f / 3);
            stack.extend_from_slice(&[3 * t, 3 * t + 1, 3 * u + 1, 3 * u + 2]);
        }
    }
}

/// Keeps the triangles at odd nesting depth of constraint loops (inside the polygons).
fn keep_inside(t: &mut Triangulation, constraints: &[(u32, u32)]) {
    let fixed: HashSet<(u32, u32)> = constraints.iter().copied().collect();
    let n = t.triangles.len();
    let mut depth = vec![u32::MAX; n];
    for (i, nb) in t.neighbors.iter().enumerate() {
        for k in 0..3 {
            if nb[k] == NO_NEIGHBOR {
                let tri = t.triangles[i];
                let e = key(tri[(k + 1) % 3], tri[(k + 2) % 3]);
                let d = if fixed.contains(&e) { 1 } else { 0 };
                if depth[i] == u32::MAX || d < depth[i] {
                    depth[i] = d;
                }
            }
        }
    }
    // Dijkstra-like by levels (0/1 weights): crossing a constraint costs 1.
    let mut dq: VecDeque<usize> = (0..n).filter(|&i| depth[i] != u32::MAX).collect();
    while let Some(i) = dq.pop_front() {
        for k in 0..3 {
            let j = t.neighbors[i][k];
            if j == NO_NEIGHBOR {
                continue;
            }
            let tri = t.triangles[i];
            let w = u32::from(fixed.contains(&key(tri[(k + 1) % 3], tri[(k + 2) % 3])));
            let nd = depth[i] + w;
            if nd < depth[j as usize] {
                depth[j as usize] = nd;
                if w == 0 {
                    dq.push_front(j as usize);
                } else {
                    dq.push_back(j as usize);
                }
            }
        }
    }
    let keep: Vec<bool> = depth.iter().map(|&d| d % 2 == 1).collect();
    let mut new_id = vec![NO_NEIGHBOR; n];
    let mut c = 0;
    for (i, &k) in keep.iter().enumerate() {
        if k {
            new_id[i] = c;
            c += 1;
        }
    }
    let mut tris = Vec::new();
    let mut nbs = Vec::new();
    for (i, &k) in keep.iter().enumerate() {
        if k {
            tris.push(t.triangles[i]);
            nbs.push(t.neighbors[i].map(|j| {
                if j == NO_NEIGHBOR {
                    j
                } else {
                    new_id[j as usize]
                }
            }));
        }
    }
    t.triangles = tris;
    t.neighbors = nbs;
}

/// Checks a constrained Delaunay triangulation exactly: structure, counter-clockwise
/// triangles, every constraint is an edge, and every non-constrained interior edge is
/// locally Delaunay (which makes the triangulation constrained Delaunay).
///
/// # Errors
/// `Error::Verification` naming the first broken property.
pub fn verify_cdt(cdt: &Cdt) -> Result<()> {
    let t = &cdt.triangulation;
    t.validate()?;
    let v = t.vertices();
    for (i, tri) in t.triangles().iter().enumerate() {
        if orient(v[tri[0] as usize], v[tri[1] as usize], v[tri[2] as usize]) <= 0 {
            return Err(Error::Verification(format!(
                "triangle {i} is not counter-clockwise"
            )));
        }
    }
    let edges: HashSet<(u32, u32)> = t.edges().into_iter().collect();
    for &(u, w) in &cdt.constraints {
        if !edges.contains(&(u, w)) {
            return Err(Error::Verification(format!(
                "constraint {u}–{w} is not an edge"
            )));
        }
    }
    let fixed: HashSet<(u32, u32)> = cdt.constraints.iter().copied().collect();
    check_locally_delaunay(t, |a, b| fixed.contains(&key(a, b)))
}
