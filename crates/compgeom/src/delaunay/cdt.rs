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
//! are constrained); repeated and zero-length constraints are merged / ignored; collinear
//! overlapping constraints merge into shared pieces; constraints that share endpoints are
//! fine. Constraints that **cross** are split at their crossings, snap-rounded: each
//! exact crossing is rounded to the nearest `f64` point, which becomes a Steiner vertex
//! (listed after the input vertices), and every constraint becomes the chain of pieces
//! through the rounded crossings whose rounding cell it passes through (so segments
//! through nearly one point meet at one vertex, not at several an ulp apart that bent
//! pieces would cross again). The result is the exact CDT of the vertices and the pieces,
//! which deviate from the input segments by at most half an ulp per coordinate at their
//! vertices (see `snap.rs` and `constrain.rs`). Input with no crossings costs nothing
//! extra; at the first crossing met, the constraints are snap-rounded (one intersection
//! sweep) and inserted again.
//!
//! [`polygon_delaunay`] constrains every ring edge and keeps the triangles inside the
//! polygons (odd nesting depth of constraint loops: holes removed).
//!
//! Time: O(n log n) for the triangulation plus O(k) flips per constraint crossing k edges
//! (worst case O(n²) overall).

use super::constrain::{key, Constrained};
use super::fast;
use super::pred::orient;
use super::snap;
use super::triangulation::{Triangulation, NO_NEIGHBOR};
use super::verify::check_locally_delaunay;
use crate::kernel::ensure_finite;
use crate::{Error, Point2, Polygon, Result, Segment2};
use std::collections::{HashMap, HashSet, VecDeque};

/// A constrained Delaunay triangulation: the triangulation and its constrained edges.
#[derive(Debug, Clone, PartialEq)]
pub struct Cdt {
    /// The triangles. `input_to_vertex` covers the points, then the constraint endpoints
    /// (`a`, `b` of segment 0, then of segment 1, …) or the ring vertices in order. Steiner
    /// vertices (rounded constraint crossings, refinement points) come after every vertex
    /// that an input maps to.
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
/// `NonFinite` for a NaN/infinite coordinate; `InvalidInput` when more points are given
/// than [`MAX_POINTS`](super::MAX_POINTS), or when rounded crossings keep creating new
/// crossings beyond a generous bound (k² + 64k + 1000 splits for k constraints).
pub fn constrained_delaunay(points: &[Point2], segments: &[Segment2]) -> Result<Cdt> {
    ensure_finite(points, "point")?;
    let mut all = points.to_vec();
    for (i, s) in segments.iter().enumerate() {
        // The error's name is formatted only for a bad segment (one allocation per
        // segment was a measurable part of the whole triangulation).
        if !(s.a.is_finite() && s.b.is_finite()) {
            ensure_finite(&[s.a, s.b], &format!("segment {i} endpoint"))?;
        }
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
    let Some(mesh) = mesh else {
        let t = Triangulation::from_mesh(all, None, &rep);
        return Ok(Cdt {
            triangulation: t,
            constraints: Vec::new(),
        });
    };
    // The constraints are inserted as they are, which is all there is to do unless two
    // of them cross. At the first crossing, start again with the snap-rounded constraints
    // (see `snap.rs`; finding every crossing first would cost a sweep on every input).
    let mut first = Constrained::new(mesh, false);
    first.stop_at_crossing = true;
    let mut c = match insert_all(first, all, &rep, pairs, None)? {
        Some(c) => c,
        None => {
            let segments: Vec<Segment2> = pairs
                .iter()
                .map(|&(i, j)| Segment2::new(all[i], all[j]))
                .collect();
            let snapped = snap::snap_round(&segments)?;
            let Some(mesh) = fast::triangulate(all).0 else {
                return Err(Error::InvalidInput(
                    "the triangulation of the points failed on the second pass (internal error)"
                        .into(),
                ));
            };
            let second = Constrained::new(mesh, false);
            match insert_all(second, all, &rep, pairs, Some(snapped.as_ref()))? {
                Some(c) => c,
                None => unreachable_crossing()?,
            }
        }
    };
    c.restore_dirty();
    let (t, constraints) = finish(&c, all.len(), &rep);
    let mut cdt = Cdt {
        triangulation: t,
        constraints,
    };
    if interior_only {
        keep_inside(&mut cdt.triangulation, &cdt.constraints);
    }
    Ok(cdt)
}

fn unreachable_crossing<T>() -> Result<T> {
    Err(Error::InvalidInput(
        "a crossing stopped the second pass (internal error)".into(),
    ))
}

/// Inserts the constraints `pairs` (indices into `all`, mesh vertices `rep`). On the first
/// pass (`snapped` is `None` and the engine stops at crossings) returns `None` at the first
/// proper crossing. On the second, `snapped` is the snap-rounding of the constraints (or
/// `Some(None)`: no crossing bends them) and each constraint is inserted as its chain.
fn insert_all<'a>(
    mut c: Constrained<'a>,
    all: &[Point2],
    rep: &[u32],
    pairs: &[(usize, usize)],
    snapped: Option<Option<&snap::Snapped>>,
) -> Result<Option<Constrained<'a>>> {
    // k constraints cross at most k(k-1)/2 times; the rest is slack for rounded crossings
    // that cross a third constraint.
    c.crossing_budget = pairs.len().saturating_mul(pairs.len()) + 64 * pairs.len() + 1000;
    let snapped = snapped.flatten();
    // The vertex of each point a chain goes through: a hot point or an input vertex.
    let mut vertex_at: HashMap<(u64, u64), u32> = HashMap::new();
    let bits = |p: Point2| (p.x.to_bits(), p.y.to_bits());
    if let Some(s) = snapped {
        vertex_at.extend(all.iter().zip(rep.iter()).map(|(&p, &v)| (bits(p), v)));
        for &p in &s.hot {
            let v = c.add_point(p).0;
            vertex_at.insert(bits(p), v);
        }
    }
    // A segment given twice is inserted once: its first insertion may have bent it through
    // a rounded crossing, and a second straight walk would then cross those pieces and
    // leave near-coincident vertices joined by sliver pieces (which refinement cannot
    // resolve: the pieces encroach on each other without end).
    let mut inserted = HashSet::with_capacity(pairs.len());
    let mut chain = Vec::new();
    for (ci, &(i, j)) in pairs.iter().enumerate() {
        let (a, b) = (rep[i], rep[j]);
        if a == b || !inserted.insert((a.min(b), a.max(b))) {
            continue;
        }
        chain.clear();
        chain.push(a);
        if let Some(s) = snapped {
            // The snap-rounded chain: its points are vertices already (hot points, inputs).
            for &p in &s.inner[ci] {
                let known = vertex_at.get(&bits(p)).copied();
                chain.push(known.unwrap_or_else(|| c.add_point(p).0));
            }
            c.set_origin(ci as u32, (all[i], all[j]));
        }
        chain.push(b);
        for piece in chain.windows(2) {
            if let Err(e) = c.insert_segment(piece[0], piece[1], ci as u32) {
                return if c.met_crossing { Ok(None) } else { Err(e) };
            }
        }
    }
    Ok(Some(c))
}

/// The result of a constrained mesh: the triangulation (the first `n_input` mesh points
/// mapped through `rep`, Steiner points after them) and the sorted constrained edges.
pub(crate) fn finish(
    c: &Constrained<'_>,
    n_input: usize,
    rep: &[u32],
) -> (Triangulation, Vec<(u32, u32)>) {
    let pts: &[Point2] = &c.mesh.pts;
    let mut rep = rep[..n_input].to_vec();
    rep.extend(n_input as u32..pts.len() as u32);
    let mut t = Triangulation::from_mesh(pts, Some(&c.mesh), &rep);
    let map = |v: u32| t.input_to_vertex[v as usize];
    let mut constraints: Vec<(u32, u32)> = c
        .fixed
        .keys()
        .map(|&(u, v)| (map(u).min(map(v)), map(u).max(map(v))))
        .collect();
    constraints.sort_unstable();
    t.input_to_vertex.truncate(n_input);
    (t, constraints)
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
