//! Rings meeting inside edges: a vertex of one ring lying inside an edge of another (a
//! hole touching the outer ring, or another hole, at a point that is a vertex of one ring
//! only), and edges running along each other with the polygon on neither side (a hole
//! sharing a stretch of boundary with the outer ring or another hole, a zero-width spike).
//!
//! Such a polygon still bounds a well-defined region, but the sweeps see a vertex on an
//! edge. It is normalised exactly:
//! 1. every edge is split at the input vertices lying inside it (the intersection sweep of
//!    [`crate::intersect`], exact by `orient2d`); a crossing of two edge interiors leaves
//!    the input invalid;
//! 2. with every ring oriented so the polygon lies on its left, two pieces running along
//!    each other in opposite directions have the polygon on neither side: both go (two in
//!    the same direction would be a doubly covered stretch: invalid);
//! 3. the remaining directed edges are linked into boundary cycles, at a point with several
//!    continuations taking the one just clockwise of the way back (the sharpest left
//!    turn), so every cycle keeps one corner of the region on its left; the one
//!    counter-clockwise cycle is the new outer ring, the clockwise ones the holes.
//!
//! Points where the new rings touch are then handled as touching at a vertex
//! ([`super::geometry`]). Only done on the error path of a first attempt, so valid input
//! without such contacts pays nothing; O((n + k) log n) then.
use crate::intersect::{clean_ring, find_intersections};
use crate::kernel::{orient2d, Orientation, Point2, Polygon, Segment2};
use crate::Result;
use std::cmp::Ordering;
use std::collections::HashMap;

/// The normalised polygon (module docs), or `None` when there is nothing to normalise or
/// the input is invalid in another way (left to the caller's error).
pub(crate) fn split_touching(polygon: &Polygon) -> Result<Option<Polygon>> {
    let mut rings: Vec<Vec<Point2>> = Vec::new();
    for (r, ring) in polygon.rings().enumerate() {
        let mut ring = clean_ring(ring);
        if ring.len() < 3 {
            return Ok(None);
        }
        match lowest_turn(&ring) {
            Orientation::Collinear => return Ok(None),
            o => {
                // Outer ring counter-clockwise, holes clockwise: the polygon on the left.
                if (o == Orientation::CounterClockwise) != (r == 0) {
                    ring.reverse();
                }
            }
        }
        rings.push(ring);
    }
    let mut segments = Vec::new();
    for ring in &rings {
        for k in 0..ring.len() {
            segments.push(Segment2::new(ring[k], ring[(k + 1) % ring.len()]));
        }
    }
    let found = find_intersections(&segments)?;
    let mut splits: Vec<(usize, Point2)> = Vec::new();
    for p in &found.points {
        if p.interior().is_empty() {
            continue;
        }
        // The point must be a vertex (an endpoint of some edge), else two edges cross.
        if p.upper().is_empty() && p.lower().is_empty() {
            return Ok(None);
        }
        splits.extend(p.interior().iter().map(|&s| (s, p.point)));
    }
    splits.sort_by_key(|a| a.0);
    // The directed edges after splitting.
    let mut edges: Vec<(Point2, Point2)> = Vec::with_capacity(segments.len() + splits.len());
    let mut i = 0;
    for (s, seg) in segments.iter().enumerate() {
        let from = i;
        while i < splits.len() && splits[i].0 == s {
            i += 1;
        }
        let inside = &mut splits[from..i];
        inside.sort_by(|p, q| along(seg.a, seg.b, p.1, q.1));
        let mut a = seg.a;
        for &(_, p) in inside.iter() {
            edges.push((a, p));
            a = p;
        }
        edges.push((a, seg.b));
    }
    // Cancel opposite pairs; a stretch covered twice the same way is invalid.
    let mut count: HashMap<(Key, Key), u32> = HashMap::new();
    for &(a, b) in &edges {
        let c = count.entry((key(a), key(b))).or_insert(0);
        *c += 1;
        if *c > 1 {
            return Ok(None);
        }
    }
    let before = edges.len();
    edges.retain(|&(a, b)| !count.contains_key(&(key(b), key(a))));
    if splits.is_empty() && edges.len() == before {
        return Ok(None);
    }
    match cycles(&edges) {
        Some(rings) => Ok(Some(rings)),
        None => Ok(None),
    }
}

/// A point as a hash key (+0.0 folds −0.0 into 0.0, so equal points get one key).
type Key = (u64, u64);

fn key(p: Point2) -> Key {
    ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits())
}

/// The turn at a ring's lowest vertex (y, then x): its orientation.
fn lowest_turn(ring: &[Point2]) -> Orientation {
    let len = ring.len();
    let low = (0..len)
        .min_by(|&a, &b| {
            let (p, q) = (ring[a], ring[b]);
            // (-0 and 0 one value: `total_cmp` alone puts -0 first.)
            (p.y + 0.0)
                .total_cmp(&(q.y + 0.0))
                .then((p.x + 0.0).total_cmp(&(q.x + 0.0)))
        })
        .unwrap_or(0);
    orient2d(
        ring[(low + len - 1) % len],
        ring[low],
        ring[(low + 1) % len],
    )
}

/// Link directed edges into cycles (module docs, step 3) and sort them into one outer ring
/// and holes; `None` unless there is exactly one counter-clockwise cycle.
fn cycles(edges: &[(Point2, Point2)]) -> Option<Polygon> {
    let mut out: HashMap<Key, Vec<usize>> = HashMap::new();
    for (e, &(a, _)) in edges.iter().enumerate() {
        out.entry(key(a)).or_default().push(e);
    }
    // The successor of every edge; a bijection unless edges meet at a point without
    // alternating in and out around it (rings crossing there).
    let mut succ = vec![0usize; edges.len()];
    let mut taken = vec![false; edges.len()];
    for (e, &(u, v)) in edges.iter().enumerate() {
        let f = out
            .get(&key(v))?
            .iter()
            .copied()
            .min_by(|&f, &g| clockwise_from(v, u, edges[f].1, edges[g].1))?;
        if std::mem::replace(&mut taken[f], true) {
            return None;
        }
        succ[e] = f;
    }
    let mut used = vec![false; edges.len()];
    let mut outer: Option<Vec<Point2>> = None;
    let mut holes = Vec::new();
    for e0 in 0..edges.len() {
        if used[e0] {
            continue;
        }
        let mut ring = Vec::new();
        let mut e = e0;
        while !used[e] {
            used[e] = true;
            ring.push(edges[e].0);
            e = succ[e];
        }
        if ring.len() < 3 {
            return None;
        }
        match lowest_turn(&ring) {
            Orientation::CounterClockwise if outer.is_none() => outer = Some(ring),
            Orientation::Clockwise => holes.push(ring),
            _ => return None,
        }
    }
    Some(Polygon::new(outer?, holes))
}

/// Compare directions `v → a` and `v → b` by the clockwise angle from `v → u`, in
/// (0, 2π] (exact).
fn clockwise_from(v: Point2, u: Point2, a: Point2, b: Point2) -> Ordering {
    // 0: clockwise within (0, π); 1: exactly π; 2: (π, 2π); 3: along v → u.
    let class = |w: Point2| match orient2d(v, u, w) {
        Orientation::Clockwise => 0,
        Orientation::CounterClockwise => 2,
        Orientation::Collinear => {
            let same = if u.x != v.x {
                (u.x > v.x) == (w.x > v.x)
            } else {
                (u.y > v.y) == (w.y > v.y)
            };
            if same {
                3
            } else {
                1
            }
        }
    };
    let (ca, cb) = (class(a), class(b));
    ca.cmp(&cb).then_with(|| {
        // Same open half-turn: a first when b lies clockwise of it.
        match orient2d(v, a, b) {
            Orientation::Clockwise => Ordering::Less,
            Orientation::CounterClockwise => Ordering::Greater,
            Orientation::Collinear => Ordering::Equal,
        }
    })
}

/// The order of two points of segment `a → b` along it.
fn along(a: Point2, b: Point2, p: Point2, q: Point2) -> Ordering {
    // (`total_cmp` is safe: distinct points of one segment differ in the coordinate
    // compared, so -0 never meets 0 here.)
    let o = if a.x != b.x {
        p.x.total_cmp(&q.x)
    } else {
        p.y.total_cmp(&q.y)
    };
    if (a.x < b.x) || (a.x == b.x && a.y < b.y) {
        o
    } else {
        o.reverse()
    }
}
