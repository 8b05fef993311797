//! From labelled faces to valid polygons.
//!
//! The boundary of the chosen region is the set of edges with a chosen face on one side
//! only. These edges (no new intersections: they are edges of the subdivision) are linked
//! into boundary cycles of their own. The connected parts of the region are the classes
//! of faces joined across non-boundary edges (union–find, linear; no ray shooting), and
//! each cycle belongs to the part on its left. Each part gives one polygon: its boundary cycles are split
//! at repeated vertices into simple rings (a cycle touching itself at a vertex becomes a
//! shell plus a hole touching it, or two holes touching each other, as OGC requires); the
//! one counter-clockwise ring is the shell, the clockwise ones are holes. Vertices where
//! the boundary goes straight on are dropped unless asked to keep them. All decisions
//! are exact; only the final coordinates are rounded (see [`crate::overlay`] for what
//! that means for validity).
use crate::dcel::{Arrangement, Carrier, Dcel, FaceId, HalfEdgeId, Source};
use crate::kernel::{MultiPolygon, Orientation, Point2, Polygon};
use std::cmp::Ordering;

/// The region made of the faces `inside` says yes to, as polygons: shells
/// counter-clockwise, holes clockwise, rings open (first point not repeated), rounded
/// coordinates; collinear vertices dropped unless `keep_collinear`. `carrier` gives each
/// half-edge's exact direction.
pub fn faces_to_polygons<V, E, F>(
    d: &Dcel<V, E, F>,
    inside: impl Fn(FaceId) -> bool,
    carrier: impl Fn(&E) -> Carrier,
    keep_collinear: bool,
) -> MultiPolygon {
    let ne = d.edge_count();
    let on_boundary = |i: usize| {
        let h = d.half_edge(HalfEdgeId(2 * i));
        let t = d.half_edge(HalfEdgeId(2 * i + 1));
        inside(h.face) != inside(t.face)
    };
    let chosen: Vec<usize> = (0..ne).filter(|&i| on_boundary(i)).collect();
    if chosen.is_empty() {
        return MultiPolygon::default();
    }
    // Renumber the vertices in use, keeping their order (so u < v stays true).
    let mut new_id = vec![usize::MAX; d.vertex_count()];
    for &i in &chosen {
        for h in [2 * i, 2 * i + 1] {
            new_id[d.half_edge(HalfEdgeId(h)).origin.0] = 0;
        }
    }
    let mut vertices = Vec::new();
    for (v, id) in new_id.iter_mut().enumerate() {
        if *id == 0 {
            *id = vertices.len();
            vertices.push(d.vertex(crate::dcel::VertexId(v)).point);
        }
    }
    let mut segments = Vec::with_capacity(chosen.len());
    let mut edges = Vec::with_capacity(chosen.len());
    for (k, &i) in chosen.iter().enumerate() {
        let h = d.half_edge(HalfEdgeId(2 * i));
        let c = carrier(&h.data);
        segments.push(c.seg);
        let u = new_id[h.origin.0];
        let v = new_id[d.half_edge(HalfEdgeId(2 * i + 1)).origin.0];
        let (u, v, forward) = if u < v {
            (u, v, c.forward)
        } else {
            (v, u, !c.forward)
        };
        edges.push((
            u,
            v,
            vec![Source {
                segment: k,
                forward,
            }],
        ));
    }
    let arr = Arrangement {
        vertices,
        edges,
        segments,
    };
    // Containment comes from the subdivision itself, not from ray shooting: the regions
    // of the result are the classes of faces joined across edges that are not on the
    // boundary, and each boundary cycle lies in the region on its left.
    let mut class: Vec<usize> = (0..d.face_count()).collect();
    fn find(p: &mut [usize], mut x: usize) -> usize {
        while p[x] != x {
            p[x] = p[p[x]];
            x = p[x];
        }
        x
    }
    for i in 0..ne {
        let f = d.half_edge(HalfEdgeId(2 * i)).face.0;
        let g = d.half_edge(HalfEdgeId(2 * i + 1)).face.0;
        if inside(FaceId(f)) == inside(FaceId(g)) {
            let (a, b) = (find(&mut class, f), find(&mut class, g));
            class[a] = b;
        }
    }
    let sub = Dcel::linked(&arr, |_, c| c, false);
    // Sub half-edge 2k + s lies on original edge chosen[k]; find which original
    // half-edge runs the same way to read the face on its left.
    let orig_half = |h: HalfEdgeId| -> HalfEdgeId {
        let i = chosen[h.0 / 2];
        let o = HalfEdgeId(2 * i);
        if new_id[d.half_edge(o).origin.0] == sub.half_edge(h).origin.0 {
            o
        } else {
            HalfEdgeId(2 * i + 1)
        }
    };
    // Every cycle of the boundary DCEL: outer cycles of its faces and the inner cycles
    // (all put in its face 0).
    let cycles: Vec<HalfEdgeId> = sub
        .face_ids()
        .flat_map(|g| sub.face_cycles(g).collect::<Vec<_>>())
        .collect();
    let mut region_of: std::collections::HashMap<usize, usize> = std::collections::HashMap::new();
    let mut regions: Vec<(Option<Ring>, Vec<Ring>)> = Vec::new();
    for start in cycles {
        let left = d.half_edge(orig_half(start)).face;
        if !inside(left) {
            continue;
        }
        let r = find(&mut class, left.0);
        let k = *region_of.entry(r).or_insert_with(|| {
            regions.push((None, Vec::new()));
            regions.len() - 1
        });
        for ring in split_cycle(&sub, start) {
            let ccw = ring_is_ccw(&sub, &ring);
            let pts = ring_points(&sub, &ring, keep_collinear);
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

/// Split a boundary cycle into simple rings at repeated vertices.
fn split_cycle<V, F>(d: &Dcel<V, Carrier, F>, start: HalfEdgeId) -> Vec<Vec<HalfEdgeId>> {
    let mut rings = Vec::new();
    let mut stack: Vec<HalfEdgeId> = Vec::new();
    let mut pos: std::collections::HashMap<usize, usize> = std::collections::HashMap::new();
    for h in d.cycle(start) {
        let v = d.half_edge(h).origin.0;
        if let Some(&p) = pos.get(&v) {
            let ring: Vec<HalfEdgeId> = stack.drain(p..).collect();
            for e in &ring {
                pos.remove(&d.half_edge(*e).origin.0);
            }
            rings.push(ring);
        }
        pos.insert(v, stack.len());
        stack.push(h);
    }
    if !stack.is_empty() {
        rings.push(stack);
    }
    rings
}

/// A simple ring is counter-clockwise iff it turns left at its lowest vertex.
fn ring_is_ccw<V, F>(d: &Dcel<V, Carrier, F>, ring: &[HalfEdgeId]) -> bool {
    let mut low = 0;
    for k in 1..ring.len() {
        if d.origin_point(ring[k])
            .compare_xy(d.origin_point(ring[low]))
            == Ordering::Less
        {
            low = k;
        }
    }
    let prev = ring[(low + ring.len() - 1) % ring.len()];
    let a = d.half_edge(prev).data;
    let b = d.half_edge(ring[low]).data;
    a.turn(&b) == Orientation::CounterClockwise
}

/// The rounded points of a ring, dropping vertices where it goes straight on (unless
/// `keep`) and repeated rounded points.
fn ring_points<V, F>(d: &Dcel<V, Carrier, F>, ring: &[HalfEdgeId], keep: bool) -> Vec<Point2> {
    let n = ring.len();
    let mut pts: Vec<Point2> = Vec::with_capacity(n);
    for k in 0..n {
        let h = ring[k];
        let p = d.half_edge(ring[(k + n - 1) % n]).data;
        let c = d.half_edge(h).data;
        let straight = p.turn(&c) == Orientation::Collinear && p.angle_cmp(&c) == Ordering::Equal;
        // A vertex where other boundary edges meet (rings touching there) is kept, so
        // that rings only ever touch at vertices of both.
        if straight && !keep && d.around(d.half_edge(h).origin).nth(2).is_none() {
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
