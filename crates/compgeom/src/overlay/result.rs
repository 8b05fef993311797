//! From labelled faces to valid polygons.
//!
//! The boundary of the chosen region is the set of edges with a chosen face on one side
//! only. They are walked in place in the subdivision (after a boundary half-edge comes
//! the first boundary half-edge clockwise around its end, so nothing is re-sorted and no
//! new structure is built). The connected parts of the region are the classes of faces
//! joined across non-boundary edges (union–find, linear; no geometry), and each cycle
//! belongs to the part on its left. Each part gives one polygon: its boundary cycles are
//! split at repeated vertices into simple rings (a cycle touching itself at a vertex
//! becomes a shell plus a hole touching it, or two holes touching each other, as OGC
//! requires); the one counter-clockwise ring is the shell, the clockwise ones are holes. Vertices where
//! the boundary goes straight on are dropped unless asked to keep them. All decisions
//! are exact; only the final coordinates are rounded (see [`crate::overlay`] for what
//! that means for validity).
use crate::dcel::{compare_xy_filtered, Carrier, Dcel, FaceId, HalfEdgeId, Rounded};
use crate::kernel::{MultiPolygon, Orientation, Point2, Polygon};
use std::cmp::Ordering;

/// The region made of the faces `inside` says yes to, as polygons: shells
/// counter-clockwise, holes clockwise, rings open (first point not repeated), rounded
/// coordinates; collinear vertices dropped unless `keep_collinear`. `carrier` gives each
/// half-edge's exact direction. O(n) for n half-edges (walks in place, no sorting). The
/// coordinates are rounded without the check the boolean
/// operations make (see [`crate::overlay`]).
///
/// ```
/// use compgeom::overlay::{boolean_dcel, faces_to_polygons, FillRule};
/// use compgeom::{MultiPolygon, Point2, Polygon};
/// let sq = |x: f64, y: f64| Polygon::new(vec![Point2::new(x, y), Point2::new(x + 2.0, y),
///     Point2::new(x + 2.0, y + 2.0), Point2::new(x, y + 2.0)], vec![]);
/// let a = MultiPolygon(vec![sq(0.0, 0.0), sq(1.0, 1.0)]);
/// let d = boolean_dcel(&a, &MultiPolygon::default(), FillRule::NonZero).unwrap();
/// // The faces covered twice: the overlap of the two squares.
/// let twice = faces_to_polygons(&d, |f| d.face(f).data.0 == 2, |e| e.carrier, false);
/// assert_eq!(twice.0.len(), 1);
/// assert_eq!(twice.0[0].exterior.len(), 4);
/// ```
pub fn faces_to_polygons<V, E, F>(
    d: &Dcel<V, E, F>,
    inside: impl Fn(FaceId) -> bool,
    carrier: impl Fn(&E) -> Carrier,
    keep_collinear: bool,
) -> MultiPolygon {
    let nf = d.face_count();
    let chosen: Vec<bool> = (0..nf).map(|f| inside(FaceId(f))).collect();
    let face_in = |h: HalfEdgeId| chosen[d.half_edge(h).face.0];
    // Boundary half-edges: the region on the left, the rest on the right.
    let on_boundary = |h: HalfEdgeId| face_in(h) && !face_in(d.twin(h));
    // The regions of the result are the classes of faces joined across edges that are
    // not on the boundary (containment from the subdivision itself, no geometry).
    let mut class: Vec<usize> = (0..nf).collect();
    fn find(p: &mut [usize], mut x: usize) -> usize {
        while p[x] != x {
            p[x] = p[p[x]];
            x = p[x];
        }
        x
    }
    // Number of boundary edges at each vertex (a vertex where more than two meet is
    // kept even where a ring goes straight on, so rings only touch at common vertices).
    let mut degree = vec![0u32; d.vertex_count()];
    let mut any = false;
    for i in 0..d.edge_count() {
        let (h, t) = (HalfEdgeId(2 * i), HalfEdgeId(2 * i + 1));
        let (f, g) = (d.half_edge(h).face.0, d.half_edge(t).face.0);
        if chosen[f] == chosen[g] {
            let (a, b) = (find(&mut class, f), find(&mut class, g));
            class[a] = b;
        } else {
            degree[d.half_edge(h).origin.0] += 1;
            degree[d.half_edge(t).origin.0] += 1;
            any = true;
        }
    }
    if !any {
        return MultiPolygon::default();
    }
    // The boundary after boundary half-edge h: turn clockwise around its end, from
    // twin(h), over edges inside the region, to the first boundary edge (the region
    // stays on the left all the way).
    let boundary_next = |h: HalfEdgeId| {
        let mut e = d.half_edge(h).next;
        while !on_boundary(e) {
            e = d.half_edge(d.twin(e)).next;
        }
        e
    };
    let mut seen = vec![false; d.half_edges.len()];
    let mut region_of = vec![usize::MAX; nf];
    let mut regions: Vec<(Option<Ring>, Vec<Ring>)> = Vec::new();
    let mut pos = vec![usize::MAX; d.vertex_count()];
    let mut cycle: Vec<HalfEdgeId> = Vec::new();
    for start in d.half_edge_ids() {
        if seen[start.0] || !on_boundary(start) {
            continue;
        }
        cycle.clear();
        let mut h = start;
        loop {
            seen[h.0] = true;
            cycle.push(h);
            h = boundary_next(h);
            if h == start {
                break;
            }
        }
        let r = find(&mut class, d.half_edge(start).face.0);
        if region_of[r] == usize::MAX {
            region_of[r] = regions.len();
            regions.push((None, Vec::new()));
        }
        let k = region_of[r];
        for ring in split_cycle(d, &cycle, &mut pos) {
            let ccw = ring_is_ccw(d, &ring, &carrier);
            let pts = ring_points(d, &ring, &carrier, &degree, keep_collinear);
            if pts.len() < 3 {
                continue;
            }
            if ccw && regions[k].0.is_none() {
                regions[k].0 = Some(pts);
            } else {
                regions[k].1.push(pts);
            }
        }
    }
    let out = regions
        .into_iter()
        .filter_map(|(shell, holes)| shell.map(|s| Polygon::new(s, holes)))
        .collect();
    MultiPolygon(out)
}

/// A ring's points.
type Ring = Vec<Point2>;

/// Split a boundary cycle into simple rings at repeated vertices (`pos` is scratch
/// space, one entry per vertex, all `usize::MAX` on entry and on exit).
fn split_cycle<V, E, F>(
    d: &Dcel<V, E, F>,
    cycle: &[HalfEdgeId],
    pos: &mut [usize],
) -> Vec<Vec<HalfEdgeId>> {
    let mut rings = Vec::new();
    let mut stack: Vec<HalfEdgeId> = Vec::with_capacity(cycle.len());
    for &h in cycle {
        let v = d.half_edge(h).origin.0;
        if pos[v] != usize::MAX {
            let ring: Vec<HalfEdgeId> = stack.drain(pos[v]..).collect();
            for e in &ring {
                pos[d.half_edge(*e).origin.0] = usize::MAX;
            }
            rings.push(ring);
        }
        pos[v] = stack.len();
        stack.push(h);
    }
    for e in &stack {
        pos[d.half_edge(*e).origin.0] = usize::MAX;
    }
    if !stack.is_empty() {
        rings.push(stack);
    }
    rings
}

/// A simple ring is counter-clockwise iff it turns left at its lowest vertex.
fn ring_is_ccw<V, E, F>(
    d: &Dcel<V, E, F>,
    ring: &[HalfEdgeId],
    carrier: &impl Fn(&E) -> Carrier,
) -> bool {
    let point = |h: HalfEdgeId| {
        let v = d.vertex(d.half_edge(h).origin);
        // (The nearest point, not `v.approx`: the filter needs rounding to nearest, and
        // `mend_rounding` may have moved a crossing one float from it.)
        (v.point, Rounded::of(&v.point, v.point.approx()))
    };
    let mut low = 0;
    let mut best = point(ring[0]);
    for (k, &h) in ring.iter().enumerate().skip(1) {
        let p = point(h);
        if compare_xy_filtered(&p.0, &p.1, &best.0, &best.1) == Ordering::Less {
            low = k;
            best = p;
        }
    }
    let prev = ring[(low + ring.len() - 1) % ring.len()];
    let a = carrier(&d.half_edge(prev).data);
    let b = carrier(&d.half_edge(ring[low]).data);
    a.turn(&b) == Orientation::CounterClockwise
}

/// The rounded points of a ring, dropping vertices where it goes straight on (unless
/// `keep`) and repeated rounded points.
fn ring_points<V, E, F>(
    d: &Dcel<V, E, F>,
    ring: &[HalfEdgeId],
    carrier: &impl Fn(&E) -> Carrier,
    degree: &[u32],
    keep: bool,
) -> Vec<Point2> {
    let n = ring.len();
    let mut pts: Vec<Point2> = Vec::with_capacity(n);
    for k in 0..n {
        let h = ring[k];
        let p = carrier(&d.half_edge(ring[(k + n - 1) % n]).data);
        let c = carrier(&d.half_edge(h).data);
        let straight = p.turn(&c) == Orientation::Collinear && p.angle_cmp(&c) == Ordering::Equal;
        // A vertex where other boundary edges meet (rings touching there) is kept, so
        // that rings only ever touch at vertices of both.
        if straight && !keep && degree[d.half_edge(h).origin.0] <= 2 {
            continue;
        }
        let q = d.vertex(d.half_edge(h).origin).approx;
        if pts.last() != Some(&q) {
            pts.push(q);
        }
    }
    while pts.len() > 1 && pts.first() == pts.last() {
        pts.pop();
    }
    pts
}
