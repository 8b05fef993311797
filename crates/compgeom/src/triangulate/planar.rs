//! Triangulation of a planar subdivision inside a bounding box (book Theorem 3.9).
//!
//! The box becomes the outer boundary and the subdivision's edges extra edges; one
//! MAKEMONOTONE sweep over the whole plane graph adds the diagonals that make every face
//! y-monotone, and TRIANGULATEMONOTONEPOLYGON triangulates each piece. O(n log n) time,
//! O(n) space for n vertices.
//!
//! The sweep is the book's, written for vertices of any degree (its five vertex types are
//! the cases below). The status holds every edge crossing the sweep line and helper(e),
//! the lowest vertex seen so far in the gap just right of e. At vertex v, with incoming
//! edges (from above) I₁ … I_k and outgoing ones (below) O₁ … O_m, left to right, and L
//! the edge just left of v:
//! * every gap closed at v (right of L, right of each I_j) whose helper has no outgoing
//!   edge (a merge vertex, or a vertex like an end vertex with the gap below it) gets a
//!   diagonal to v;
//! * with no incoming edge (a start or split vertex), v gets a diagonal up to helper(L);
//! * v becomes the helper of L and of every O_j.
//!
//! Afterwards every vertex but the first and last has an edge up and an edge down, so
//! every face is bounded by one simple y-monotone cycle.
//!
//! Degenerate input: equal y (the left vertex is above: the book's order), collinear
//! vertices and edges along the box (vertices on the box split its sides), vertices of
//! any degree, dangling edges and isolated components (a dangling end gets a diagonal like
//! any other vertex). Every decision is exact ([`orient2d`] and coordinate comparisons);
//! the points are distinct, so no perturbation is needed.
use super::monotone::{triangulate_monotone, Pieces};
use super::status::{Side, Status};
use crate::dcel::{Dcel, FaceId};
use crate::intersect::sweep_cmp_points;
use crate::kernel::{orient2d, ExactPoint, Orientation, Point2, Segment2};
use crate::{Error, Result};
use std::cmp::Ordering;
use std::collections::HashMap;

/// A triangulation of a planar subdivision clipped to a box (see
/// [`triangulate_subdivision`]).
#[derive(Debug, Clone, PartialEq)]
pub struct SubdivisionTriangulation {
    /// The subdivision's vertices (index `i` is the DCEL's `VertexId(i)`), then the box
    /// corners that are not already vertices.
    pub vertices: Vec<Point2>,
    /// Counter-clockwise triangles, as indices into `vertices`.
    pub triangles: Vec<[usize; 3]>,
    /// For every triangle, the face of the subdivision containing it
    /// ([`FaceId::UNBOUNDED`] for the part of the unbounded face inside the box).
    pub faces: Vec<FaceId>,
    /// The subdivision's edges: edge `i` (half-edges `2i` and `2i + 1`) as
    /// `[origin of 2i, origin of 2i + 1]`. Each is a triangle edge.
    pub edges: Vec<[usize; 2]>,
    /// The box boundary: every vertex on it, counter-clockwise from the lower-left corner.
    pub boundary: Vec<usize>,
}

/// The box: the bounding box of `points` grown by `margin` on every side.
pub(crate) fn bounding_box(points: &[Point2], margin: f64) -> Result<[f64; 4]> {
    if !margin.is_finite() || margin < 0.0 {
        return Err(Error::InvalidInput(format!(
            "the box margin must be finite and non-negative (got {margin})"
        )));
    }
    let Some(first) = points.first() else {
        return Err(Error::InvalidInput("the subdivision has no vertex".into()));
    };
    let mut b = [first.x, first.y, first.x, first.y];
    for p in points {
        b = [b[0].min(p.x), b[1].min(p.y), b[2].max(p.x), b[3].max(p.y)];
    }
    let b = [b[0] - margin, b[1] - margin, b[2] + margin, b[3] + margin];
    if !b.iter().all(|v| v.is_finite()) {
        return Err(Error::InvalidInput(
            "the box overflows f64 (margin too large)".into(),
        ));
    }
    if b[0] >= b[2] || b[1] >= b[3] {
        return Err(Error::InvalidInput(
            "the box has no area (the vertices are collinear along an axis): give a \
             positive margin"
                .into(),
        ));
    }
    Ok(b)
}

/// Triangulate a planar subdivision inside its bounding box grown by `margin` (book
/// Theorem 3.9): every face, the unbounded one clipped to the box, with the faces of the
/// subdivision recorded per triangle. The box has 2V − b − 2 triangles for V vertices of
/// which b lie on the box. O(n log n).
///
/// Errors: a vertex at a constructed crossing that is not an `f64` point (the
/// subdivision of crossing segments: such points cannot be triangle corners exactly), a
/// negative or non-finite margin, a box without area (margin 0 and all vertices on one
/// horizontal or vertical line), an empty subdivision.
///
/// ```
/// use compgeom::dcel::{Dcel, FaceId};
/// use compgeom::triangulate::{triangulate_subdivision, verify_subdivision_triangulation};
/// use compgeom::{Point2, Segment2};
/// let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
/// // A triangle with a dangling edge into it, inside a box with margin 1.
/// let dcel = Dcel::from_segments(&[
///     s((0., 0.), (4., 0.)), s((4., 0.), (2., 3.)), s((2., 3.), (0., 0.)),
///     s((2., 0.), (2., 1.)),
/// ]).unwrap();
/// let t = triangulate_subdivision(&dcel, 1.0).unwrap();
/// verify_subdivision_triangulation(&dcel, &t).unwrap();
/// // 5 + 4 box corners = 9 vertices, all 4 corners on the box: 2·9 − 4 − 2 triangles.
/// assert_eq!(t.triangles.len(), 12);
/// let inside = t.faces.iter().filter(|&&f| f != FaceId::UNBOUNDED).count();
/// assert_eq!(inside, 4); // the triangle (4 vertices, one dangling edge) in 4 pieces
/// ```
pub fn triangulate_subdivision<V, E, F>(
    dcel: &Dcel<V, E, F>,
    margin: f64,
) -> Result<SubdivisionTriangulation> {
    let mut pts = Vec::with_capacity(dcel.vertex_count() + 4);
    for v in dcel.vertex_ids() {
        let exact = &dcel.vertex(v).point;
        let p = exact.approx();
        if ExactPoint::Input(p).compare_xy(exact) != Ordering::Equal {
            return Err(Error::InvalidInput(format!(
                "the subdivision has a vertex at a crossing near ({}, {}) that is not an \
                 f64 point: triangulate segments that do not cross",
                p.x, p.y
            )));
        }
        pts.push(p);
    }
    let bx = bounding_box(&pts, margin)?;
    let n_input = dcel.edge_count();
    let mut edges: Vec<[u32; 2]> = (0..n_input)
        .map(|i| {
            let h = dcel.half_edge(crate::dcel::HalfEdgeId(2 * i));
            let t = dcel.half_edge(crate::dcel::HalfEdgeId(2 * i + 1));
            [h.origin.0 as u32, t.origin.0 as u32]
        })
        .collect();
    let boundary = add_box(&mut pts, &mut edges, bx);
    let out = triangulate_graph(&pts, &edges, &boundary)?;
    // Each face component takes the face of any subdivision half-edge on its boundary.
    let mut component_face = vec![FaceId::UNBOUNDED; out.components];
    for h in 0..2 * n_input {
        let c = out.half_edge_component[h];
        if c != NONE {
            component_face[c as usize] = dcel.half_edge(crate::dcel::HalfEdgeId(h)).face;
        }
    }
    Ok(SubdivisionTriangulation {
        vertices: pts,
        triangles: out
            .triangles
            .iter()
            .map(|t| t.map(|v| v as usize))
            .collect(),
        faces: out
            .triangle_component
            .iter()
            .map(|&c| component_face[c as usize])
            .collect(),
        edges: edges[..n_input]
            .iter()
            .map(|e| e.map(|v| v as usize))
            .collect(),
        boundary: boundary.iter().map(|&v| v as usize).collect(),
    })
}

/// [`triangulate_subdivision`] of the subdivision the segments induce
/// ([`Dcel::from_segments`]: `faces` index that DCEL's faces). The segments may touch and
/// overlap but not cross.
pub fn triangulate_segments(
    segments: &[Segment2],
    margin: f64,
) -> Result<SubdivisionTriangulation> {
    triangulate_subdivision(&Dcel::from_segments(segments)?, margin)
}

const NONE: u32 = u32::MAX;

/// Add the box corners that are not vertices yet and the box sides between consecutive
/// vertices on them (unless an edge is already there); the boundary, counter-clockwise
/// from the lower-left corner.
fn add_box(pts: &mut Vec<Point2>, edges: &mut Vec<[u32; 2]>, b: [f64; 4]) -> Vec<u32> {
    let [x0, y0, x1, y1] = b;
    let key = |p: Point2| ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits());
    let index: HashMap<(u64, u64), u32> = pts
        .iter()
        .enumerate()
        .map(|(i, &p)| (key(p), i as u32))
        .collect();
    for c in [
        Point2::new(x0, y0),
        Point2::new(x1, y0),
        Point2::new(x1, y1),
        Point2::new(x0, y1),
    ] {
        if !index.contains_key(&key(c)) {
            pts.push(c);
        }
    }
    // Sides in counter-clockwise order, each from its first corner, corners once.
    let mut sides: [Vec<u32>; 4] = Default::default();
    for (i, p) in pts.iter().enumerate() {
        let i = i as u32;
        if p.y == y0 && p.x < x1 {
            sides[0].push(i);
        }
        if p.x == x1 && p.y < y1 {
            sides[1].push(i);
        }
        if p.y == y1 && p.x > x0 {
            sides[2].push(i);
        }
        if p.x == x0 && p.y > y0 {
            sides[3].push(i);
        }
    }
    // (-0 and 0 one value: `total_cmp` alone puts -0 first.)
    let (x, y) = (
        |i: u32| pts[i as usize].x + 0.0,
        |i: u32| pts[i as usize].y + 0.0,
    );
    sides[0].sort_by(|&a, &b| x(a).total_cmp(&x(b)));
    sides[1].sort_by(|&a, &b| y(a).total_cmp(&y(b)));
    sides[2].sort_by(|&a, &b| x(b).total_cmp(&x(a)));
    sides[3].sort_by(|&a, &b| y(b).total_cmp(&y(a)));
    let boundary: Vec<u32> = sides.concat();
    let existing: std::collections::HashSet<(u32, u32)> =
        edges.iter().map(|&[a, b]| (a.min(b), a.max(b))).collect();
    for k in 0..boundary.len() {
        let (a, b) = (boundary[k], boundary[(k + 1) % boundary.len()]);
        if !existing.contains(&(a.min(b), a.max(b))) {
            edges.push([a, b]);
        }
    }
    boundary
}

/// Distinct points: the sweep order and plain orientation.
struct Plane<'a> {
    pts: &'a [Point2],
}

impl Plane<'_> {
    #[inline]
    fn cmp(&self, a: u32, b: u32) -> Ordering {
        // (y decreasing, then x increasing; -0 and 0 one value, as for every exact test.)
        sweep_cmp_points(self.pts[a as usize], self.pts[b as usize])
    }
}

impl Pieces for Plane<'_> {
    #[inline]
    fn above(&self, a: u32, b: u32) -> bool {
        self.cmp(a, b) == Ordering::Less
    }
    #[inline]
    fn orient(&self, a: u32, b: u32, c: u32) -> Ordering {
        match orient2d(
            self.pts[a as usize],
            self.pts[b as usize],
            self.pts[c as usize],
        ) {
            Orientation::CounterClockwise => Ordering::Greater,
            Orientation::Clockwise => Ordering::Less,
            Orientation::Collinear => Ordering::Equal,
        }
    }
    fn chains_meet(&self, a: u32, _b: u32, c: u32) -> Error {
        let (p, q) = (self.pts[a as usize], self.pts[c as usize]);
        Error::InvalidInput(format!(
            "edges cross near ({}, {}) and ({}, {})",
            p.x, p.y, q.x, q.y
        ))
    }
    fn not_monotone(&self, cycle: &[u32]) -> Error {
        let p = self.pts[cycle[0] as usize];
        Error::InvalidInput(format!(
            "the face through ({}, {}) is not monotone (edges cross)",
            p.x, p.y
        ))
    }
}

/// What [`triangulate_graph`] gives.
pub(crate) struct GraphTriangulation {
    pub triangles: Vec<[u32; 3]>,
    /// The face component (faces of the input graph) of every triangle.
    pub triangle_component: Vec<u32>,
    /// The component to the left of every input half-edge (`2e`: `edges[e][0] →
    /// edges[e][1]`), `NONE` outside the box.
    pub half_edge_component: Vec<u32>,
    pub components: usize,
}

/// Per vertex, its neighbours (with the edge) sorted counter-clockwise starting just above
/// the rightward horizontal: first those above (in the sweep order), then those below.
fn around(plane: &Plane, n: usize, edges: &[[u32; 2]]) -> (Vec<usize>, Vec<(u32, u32)>) {
    let mut start = vec![0usize; n + 1];
    for e in edges {
        start[e[0] as usize + 1] += 1;
        start[e[1] as usize + 1] += 1;
    }
    for v in 0..n {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut adj = vec![(0u32, 0u32); 2 * edges.len()];
    for (i, e) in edges.iter().enumerate() {
        for s in 0..2 {
            let v = e[s] as usize;
            adj[fill[v]] = (e[1 - s], i as u32);
            fill[v] += 1;
        }
    }
    for v in 0..n {
        let vv = v as u32;
        adj[start[v]..start[v + 1]].sort_unstable_by(|a, b| {
            let (ua, ub) = (plane.above(a.0, vv), plane.above(b.0, vv));
            ub.cmp(&ua).then_with(|| plane.orient(vv, b.0, a.0))
        });
    }
    (start, adj)
}

/// Triangulate the plane graph `edges` on distinct points, whose outer boundary is the
/// counter-clockwise cycle `boundary` (module docs). Edges must not cross and no vertex
/// may lie inside an edge.
pub(crate) fn triangulate_graph(
    pts: &[Point2],
    edges: &[[u32; 2]],
    boundary: &[u32],
) -> Result<GraphTriangulation> {
    let n = pts.len();
    if n >= NONE as usize / 4 || edges.len() >= NONE as usize / 4 {
        return Err(Error::InvalidInput(format!(
            "the subdivision is too large ({n} vertices)"
        )));
    }
    let plane = Plane { pts };
    let mut order: Vec<u32> = (0..n as u32).collect();
    order.sort_unstable_by(|&a, &b| plane.cmp(a, b));
    let (start, adj) = around(&plane, n, edges);
    let upper = |e: u32| {
        let [a, b] = edges[e as usize];
        if plane.above(a, b) {
            (a, b)
        } else {
            (b, a)
        }
    };
    let side = |t: u32, v: u32| {
        let (a, b) = upper(t);
        match plane.orient(a, b, v) {
            Ordering::Greater => Side::Right,
            Ordering::Less => Side::Left,
            Ordering::Equal => Side::On,
        }
    };
    let on_edge = |v: u32, t: u32| {
        let (p, (a, b)) = (pts[v as usize], upper(t));
        let (a, b) = (pts[a as usize], pts[b as usize]);
        Error::InvalidInput(format!(
            "vertex ({}, {}) lies on the edge ({}, {}) -> ({}, {})",
            p.x, p.y, a.x, a.y, b.x, b.y
        ))
    };
    let mut status = Status::new(edges.len());
    let mut helper = vec![NONE; edges.len()];
    let mut no_down = vec![false; n];
    let mut diagonals: Vec<[u32; 2]> = Vec::new();
    let mut incoming: Vec<u32> = Vec::new();
    let mut outgoing: Vec<u32> = Vec::new();
    for (k, &v) in order.iter().enumerate() {
        let list = &adj[start[v as usize]..start[v as usize + 1]];
        // Counter-clockwise: above from right to left, then below from left to right.
        let split = list.partition_point(|&(w, _)| plane.above(w, v));
        incoming.clear();
        incoming.extend(list[..split].iter().rev().map(|&(_, e)| e));
        outgoing.clear();
        outgoing.extend(list[split..].iter().map(|&(_, e)| e));
        let left = if let Some(&first) = incoming.first() {
            let l = status.neighbours(first).0;
            let closing = std::iter::once(l)
                .chain(incoming.iter().copied())
                .filter(|&e| e != NONE);
            for e in closing {
                let h = helper[e as usize];
                if h != NONE && no_down[h as usize] {
                    diagonals.push([v, h]);
                }
            }
            for &e in &incoming {
                status.remove(e);
            }
            l
        } else {
            match status.left_of(|t| side(t, v)).map_err(|t| on_edge(v, t))? {
                Some(l) => {
                    let h = helper[l as usize];
                    if h != NONE {
                        diagonals.push([v, h]);
                    }
                    l
                }
                None if k == 0 => NONE,
                None => {
                    let p = pts[v as usize];
                    return Err(Error::InvalidInput(format!(
                        "vertex ({}, {}) lies outside the box",
                        p.x, p.y
                    )));
                }
            }
        };
        for (i, &e) in outgoing.iter().enumerate() {
            let before = &outgoing[..i];
            status
                .insert(e, |t| {
                    if before.contains(&t) {
                        Side::Right
                    } else {
                        side(t, v)
                    }
                })
                .map_err(|t| on_edge(v, t))?;
            helper[e as usize] = v;
        }
        if left != NONE {
            helper[left as usize] = v;
        }
        no_down[v as usize] = outgoing.is_empty();
    }
    // The faces of the graph with the diagonals: half-edge 2e runs edges[e][0] → [1].
    let m = edges.len();
    let mut all: Vec<[u32; 2]> = Vec::with_capacity(m + diagonals.len());
    all.extend_from_slice(edges);
    all.extend_from_slice(&diagonals);
    let (start, adj) = around(&plane, n, &all);
    let half = |v: u32, (_, e): (u32, u32)| 2 * e + u32::from(all[e as usize][0] != v);
    let mut slot = vec![0u32; 2 * all.len()];
    for v in 0..n {
        for i in start[v]..start[v + 1] {
            slot[half(v as u32, adj[i]) as usize] = (i - start[v]) as u32;
        }
    }
    let origin = |h: u32| all[(h / 2) as usize][(h % 2) as usize];
    // Next along the face to the left: at the head, the half-edge just clockwise of the
    // way back.
    let next = |h: u32| {
        let twin = h ^ 1;
        let v = origin(twin) as usize;
        let len = start[v + 1] - start[v];
        let i = (slot[twin as usize] as usize + len - 1) % len;
        half(v as u32, adj[start[v] + i])
    };
    // The outside of the box: the cycle through the reversed first boundary side.
    let (b0, b1) = (boundary[0], boundary[1 % boundary.len()]);
    let outside = (0..m as u32)
        .find(|&e| all[e as usize] == [b0, b1] || all[e as usize] == [b1, b0])
        .map(|e| {
            if all[e as usize][0] == b1 {
                2 * e
            } else {
                2 * e + 1
            }
        })
        .unwrap_or(NONE);
    let mut cycle_of = vec![NONE; 2 * all.len()];
    let mut triangles = Vec::with_capacity(2 * n);
    let mut piece_of_triangle = Vec::with_capacity(2 * n);
    let mut cycle = Vec::new();
    let mut pieces = 0u32;
    if outside != NONE {
        let mut h = outside;
        while cycle_of[h as usize] == NONE {
            cycle_of[h as usize] = NONE - 1;
            h = next(h);
        }
    }
    for h0 in 0..2 * all.len() as u32 {
        if cycle_of[h0 as usize] != NONE {
            continue;
        }
        cycle.clear();
        let mut h = h0;
        while cycle_of[h as usize] == NONE {
            cycle_of[h as usize] = pieces;
            cycle.push(origin(h));
            h = next(h);
        }
        triangulate_monotone(&plane, &cycle, &mut triangles)?;
        piece_of_triangle.resize(triangles.len(), pieces);
        pieces += 1;
    }
    // Pieces joined across diagonals are one face of the input graph.
    let mut parent: Vec<u32> = (0..pieces).collect();
    fn find(parent: &mut [u32], mut x: u32) -> u32 {
        while parent[x as usize] != x {
            parent[x as usize] = parent[parent[x as usize] as usize];
            x = parent[x as usize];
        }
        x
    }
    for d in m..all.len() {
        let (a, b) = (cycle_of[2 * d], cycle_of[2 * d + 1]);
        let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
        parent[ra as usize] = rb;
    }
    let mut number = vec![NONE; pieces as usize];
    let mut components = 0u32;
    let mut component = |parent: &mut [u32], p: u32| {
        let r = find(parent, p) as usize;
        if number[r] == NONE {
            number[r] = components;
            components += 1;
        }
        number[r]
    };
    let triangle_component = piece_of_triangle
        .iter()
        .map(|&p| component(&mut parent, p))
        .collect();
    let half_edge_component = (0..2 * m)
        .map(|h| match cycle_of[h] {
            c if c >= NONE - 1 => NONE,
            c => component(&mut parent, c),
        })
        .collect();
    Ok(GraphTriangulation {
        triangles,
        triangle_component,
        half_edge_component,
        components: components as usize,
    })
}
