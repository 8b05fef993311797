//! The boolean-only path (book §2.4 without building the DCEL records): from the flat
//! arrangement of both inputs' rings straight to the result's rings, on compact arrays.
//!
//! 1. *Arrangement*: [`Flat::of_segments`] (exact noding: vertices, edges, the ring edges
//!    carrying each edge).
//! 2. *Links*: the outgoing half-edges of each vertex; only at vertices of degree > 2 are
//!    they sorted by exact angle (from the directions of the input segments carrying them,
//!    as in [`crate::dcel`]); `next(e)` is the half-edge just clockwise of `twin(e)`.
//!    Half-edges `2i` and `2i + 1` are the two ways along edge `i`.
//! 3. *Winding numbers*: the cycles of `next` are face boundaries; crossing half-edge `h`
//!    from its right to its left changes the winding numbers `(w_A, w_B)` by the sum of
//!    ±1 over the ring edges carrying it. One walk over all half-edges labels every cycle
//!    relative to the first cycle of its connected component (a depth-first search across
//!    twins). Each component's exterior is the cycle left of the out-edge just clockwise
//!    of direction −x at the component's lexicographically smallest vertex (an input
//!    point: a crossing lies inside a segment, whose smaller end is in the component).
//!    When there is more than one component, the face around each one is the face just
//!    left of that vertex, read from one sweep (the book's graph G, `dcel/holes.rs`);
//!    components are resolved in lexicographic order of their smallest vertex, so the
//!    face found is already labelled. All decisions are exact; no point is rounded here.
//! 4. *Rings*: an edge is on the result's boundary when the fill rule puts exactly one of
//!    its sides in the result. The boundary is traced with the result on the left (after
//!    boundary half-edge `h` comes the first boundary half-edge clockwise around its end),
//!    cycles are split at repeated vertices into simple rings, each ring is oriented by its
//!    turn at its lowest vertex, and each belongs to the region (classes of chosen cycles
//!    joined across non-boundary edges and around holes, union–find) on its left: one
//!    counter-clockwise shell per region, the clockwise rings are its holes. Vertices where
//!    the ring goes straight on are dropped unless asked to keep them or where more than
//!    two boundary edges meet.
//!
//! The output is the same as the DCEL path ([`super::boolean_dcel`] with
//! [`super::faces_to_polygons`]) up to ring start, ring order and polygon order (tested
//! against it on degenerate input). Cost: that of the noding plus O(V + E) and the angular
//! sorts at vertices of degree > 2, plus the hole sweep when there are several components.
use crate::dcel::{compare_xy_filtered, faces_left_of, Carrier, Flat, Rounded};
use crate::kernel::{orient2d, ExactPoint, MultiPolygon, Orientation, Point2, Polygon, Segment2};
use crate::Result;
use std::cmp::Ordering;

const NONE: u32 = u32::MAX;
/// Not an axis direction (see [`EdgeInfo::quad`]).
const AXIS_NONE: u8 = 4;

/// A region of the result: its shell (once found) and its holes.
type Region = (Option<Vec<Point2>>, Vec<Vec<Point2>>);

/// Per edge: the input segment of its first source and whether half-edge `2i` runs that
/// segment's way, and the winding changes `(da, db)` across half-edge `2i`.
#[derive(Clone, Copy)]
struct EdgeInfo {
    seg: u32,
    fwd: bool,
    /// The direction of half-edge `2i` when axis-parallel: 0 = +x, 1 = +y, 2 = −x,
    /// 3 = −y (counter-clockwise order from +x), else [`AXIS_NONE`].
    quad: u8,
    da: i32,
    db: i32,
}

/// 0 for directions in [0°, 180°), 1 for [180°, 360°) (as [`Carrier::angle_cmp`]).
fn half(c: &Carrier) -> u8 {
    let (a, b) = if c.forward {
        (c.seg.a, c.seg.b)
    } else {
        (c.seg.b, c.seg.a)
    };
    u8::from(!(b.y > a.y || (b.y == a.y && b.x > a.x)))
}

fn find(p: &mut [u32], mut x: u32) -> u32 {
    while p[x as usize] != x {
        let up = p[p[x as usize] as usize];
        p[x as usize] = up;
        x = up;
    }
    x
}

/// The region of the arrangement of `segs` (the first `na` from A, the rest from B) whose
/// winding numbers `inside` accepts, as valid polygons (see the module docs).
/// `inside(0, 0)` must be false (the unbounded face is never in a result).
pub(super) fn traced_boolean(
    segs: &[Segment2],
    na: usize,
    inside: impl Fn(i32, i32) -> bool,
    keep_collinear: bool,
) -> Result<MultiPolygon> {
    traced(segs, na, inside, keep_collinear, true)
}

/// [`traced_boolean`]; with `strips` false the labels of components always come from the
/// hole sweep (tests check both ways agree).
fn traced(
    segs: &[Segment2],
    na: usize,
    inside: impl Fn(i32, i32) -> bool,
    keep_collinear: bool,
    strips: bool,
) -> Result<MultiPolygon> {
    let flat = Flat::of_segments(segs)?;
    let nv = flat.vertices.len();
    let ne = flat.edge_count();
    let m = 2 * ne;
    if ne == 0 {
        return Ok(MultiPolygon::default());
    }
    let info: Vec<EdgeInfo> = (0..ne)
        .map(|i| {
            let src = flat.sources_of(i);
            let (mut da, mut db) = (0, 0);
            for s in src {
                // Crossing a ring edge a → b from its right to its left adds one.
                let w = if s.forward { 1 } else { -1 };
                if s.segment < na {
                    da += w;
                } else {
                    db += w;
                }
            }
            let seg = segs[src[0].segment];
            let (a, b) = if src[0].forward {
                (seg.a, seg.b)
            } else {
                (seg.b, seg.a)
            };
            let quad = match (b.x.partial_cmp(&a.x), b.y.partial_cmp(&a.y)) {
                (Some(Ordering::Greater), Some(Ordering::Equal)) => 0,
                (Some(Ordering::Equal), Some(Ordering::Greater)) => 1,
                (Some(Ordering::Less), Some(Ordering::Equal)) => 2,
                (Some(Ordering::Equal), Some(Ordering::Less)) => 3,
                _ => AXIS_NONE,
            };
            EdgeInfo {
                seg: src[0].segment as u32,
                fwd: src[0].forward,
                quad,
                da,
                db,
            }
        })
        .collect();
    let carrier = |h: u32| {
        let e = &info[(h >> 1) as usize];
        Carrier {
            seg: segs[e.seg as usize],
            forward: e.fwd == (h & 1 == 0),
        }
    };
    // The axis direction of half-edge h (the reverse of 2i's for 2i + 1).
    let quad = |h: u32| {
        let q = info[(h >> 1) as usize].quad;
        if q == AXIS_NONE || h & 1 == 0 {
            q
        } else {
            q ^ 2
        }
    };
    // Winding change crossing half-edge h from its right to its left.
    let delta = |h: u32| {
        let e = &info[(h >> 1) as usize];
        if h & 1 == 0 {
            (e.da, e.db)
        } else {
            (-e.da, -e.db)
        }
    };
    let origin = |h: u32| flat.edges[(h >> 1) as usize][(h & 1) as usize];
    // Outgoing half-edges per vertex (one array cut into slices).
    let mut out_start = vec![0u32; nv + 1];
    for [u, v] in &flat.edges {
        out_start[*u as usize + 1] += 1;
        out_start[*v as usize + 1] += 1;
    }
    for v in 0..nv {
        out_start[v + 1] += out_start[v];
    }
    let mut out = vec![0u32; m];
    // The axis direction of each entry of `out`, beside it (the sorts below then read
    // no per-edge record).
    let mut out_quad = vec![AXIS_NONE; m];
    {
        let mut fill = out_start.clone();
        for (i, [u, v]) in flat.edges.iter().enumerate() {
            for h in [2 * i as u32, 2 * i as u32 + 1] {
                let o = if h & 1 == 0 { *u } else { *v } as usize;
                out[fill[o] as usize] = h;
                out_quad[fill[o] as usize] = quad(h);
                fill[o] += 1;
            }
        }
    }
    let slice = |v: usize| (out_start[v] as usize, out_start[v + 1] as usize);
    let mut next = vec![0u32; m];
    for v in 0..nv {
        let (a, b) = slice(v);
        let list = &mut out[a..b];
        let k = list.len();
        if k > 2 {
            // Horizontal and vertical directions (grid data) sort by their quadrant
            // alone; any other list by the exact angle comparison.
            let mut slot = [NONE; 4];
            let placed = k <= 4
                && list.iter().zip(&out_quad[a..b]).all(|(&h, &q)| {
                    let q = q as usize;
                    q < 4 && std::mem::replace(&mut slot[q], h) == NONE
                });
            if placed {
                // Distinct quadrants: their order is the angular order.
                for (j, h) in slot.into_iter().filter(|&h| h != NONE).enumerate() {
                    list[j] = h;
                }
            } else {
                list.sort_unstable_by(|&x, &y| carrier(x).angle_cmp(&carrier(y)));
            }
        }
        for j in 0..k {
            next[(list[j] ^ 1) as usize] = list[(j + k - 1) % k];
        }
    }
    // Cycles labelled relative to their component (depth-first across twins).
    let mut cyc = vec![NONE; m];
    let mut label: Vec<(i32, i32)> = Vec::new();
    let mut comp_of: Vec<u32> = Vec::new();
    let mut ncomp = 0u32;
    let mut stack: Vec<(u32, i32, i32)> = Vec::new();
    for h0 in 0..m as u32 {
        if cyc[h0 as usize] != NONE {
            continue;
        }
        stack.push((h0, 0, 0));
        while let Some((s, wa, wb)) = stack.pop() {
            if cyc[s as usize] != NONE {
                continue;
            }
            let c = label.len() as u32;
            label.push((wa, wb));
            comp_of.push(ncomp);
            let mut e = s;
            loop {
                cyc[e as usize] = c;
                let t = e ^ 1;
                if cyc[t as usize] == NONE {
                    let (da, db) = delta(t);
                    stack.push((t, wa + da, wb + db));
                }
                e = next[e as usize];
                if e == s {
                    break;
                }
            }
        }
        ncomp += 1;
    }
    let ncycles = label.len();
    // Each component's smallest vertex (an input point, see the module docs).
    let mut low = vec![NONE; ncomp as usize];
    for v in 0..nv {
        let (a, b) = slice(v);
        if a == b {
            continue;
        }
        let ExactPoint::Input(p) = flat.vertices[v] else {
            continue;
        };
        let k = comp_of[cyc[out[a] as usize] as usize] as usize;
        let better = low[k] == NONE || {
            let ExactPoint::Input(q) = flat.vertices[low[k] as usize] else {
                unreachable!("only input points are kept")
            };
            p.x < q.x || (p.x == q.x && p.y < q.y)
        };
        if better {
            low[k] = v as u32;
        }
    }
    // The exterior cycle of each component: left of the out-edge at its smallest vertex
    // just clockwise of direction −x (all out-edges point into (−90°, 90°]).
    let exterior: Vec<u32> = low
        .iter()
        .map(|&v| {
            let (a, b) = slice(v as usize);
            let mut best = out[a];
            for &h in &out[a + 1..b] {
                let (cb, ch) = (carrier(best), carrier(h));
                let (hb, hh) = (half(&cb), half(&ch));
                let later = if hb != hh {
                    hh == 0
                } else {
                    cb.angle_cmp(&ch) == Ordering::Less
                };
                if later {
                    best = h;
                }
            }
            cyc[best as usize]
        })
        .collect();
    // Offsets making the labels absolute: the exterior of a component gets the label of
    // the face around it.
    let mut offset: Vec<(i32, i32)> = exterior
        .iter()
        .map(|&c| {
            let (wa, wb) = label[c as usize];
            (-wa, -wb)
        })
        .collect();
    // The cycle (of another component) whose face holds each component, from the hole
    // sweep: its exterior is joined to it in the regions below.
    let sweep_around = || -> Vec<u32> {
        let points = &flat.vertices;
        let approx: Vec<Rounded> = points.iter().map(|p| Rounded::of(p, p.approx())).collect();
        let origins: Vec<u32> = (0..m as u32).map(origin).collect();
        let carriers: Vec<Carrier> = (0..m as u32).map(carrier).collect();
        let starts: Vec<usize> = out_start.iter().map(|&s| s as usize).collect();
        // The sweep needs every list in counter-clockwise order (those of two too).
        let mut outs: Vec<usize> = out.iter().map(|&h| h as usize).collect();
        for v in 0..nv {
            let (a, b) = slice(v);
            if b - a == 2
                && carriers[outs[a]].angle_cmp(&carriers[outs[a + 1]]) == Ordering::Greater
            {
                outs.swap(a, a + 1);
            }
        }
        let mut query = vec![false; nv];
        for &v in &low {
            query[v as usize] = true;
        }
        let left = faces_left_of(points, &approx, &origins, &carriers, &starts, &outs, &query);
        low.iter()
            .map(|&v| left[v as usize].map_or(NONE, |h| cyc[h]))
            .collect()
    };
    let mut around: Vec<u32> = vec![NONE; ncomp as usize];
    let mut swept = false;
    if ncomp > 1 {
        let input = |v: u32| match flat.vertices[v as usize] {
            ExactPoint::Input(p) => p,
            ExactPoint::Crossing(_) => {
                unreachable!("a component's smallest vertex is an input point")
            }
        };
        let queries: Vec<Point2> = low.iter().map(|&v| input(v)).collect();
        if let Some(w) = windings_left_of(segs, na, &queries).filter(|_| strips) {
            for k in 0..ncomp as usize {
                let (ea, eb) = label[exterior[k] as usize];
                offset[k] = (w[k].0 - ea, w[k].1 - eb);
            }
        } else {
            around = sweep_around();
            swept = true;
            // Components in lexicographic order of their smallest vertex: the face found
            // for one lies left of it, in a component already resolved.
            let mut order: Vec<u32> = (0..ncomp).collect();
            order.sort_unstable_by(|&x, &y| {
                let (p, q) = (input(low[x as usize]), input(low[y as usize]));
                p.x.total_cmp(&q.x).then(p.y.total_cmp(&q.y))
            });
            for k in order {
                let c = around[k as usize];
                if c != NONE {
                    let o = offset[comp_of[c as usize] as usize];
                    let (wa, wb) = label[c as usize];
                    let (ea, eb) = label[exterior[k as usize] as usize];
                    offset[k as usize] = (wa + o.0 - ea, wb + o.1 - eb);
                }
            }
        }
    }
    let chosen: Vec<bool> = (0..ncycles)
        .map(|c| {
            let (wa, wb) = label[c];
            let o = offset[comp_of[c] as usize];
            inside(wa + o.0, wb + o.1)
        })
        .collect();
    // Regions: chosen cycles joined across non-boundary edges and around holes.
    let mut class: Vec<u32> = (0..ncycles as u32).collect();
    let mut degree = vec![0u32; nv];
    let mut any = false;
    let mut has_boundary = vec![false; ncomp as usize];
    for i in 0..ne {
        let (f, g) = (cyc[2 * i], cyc[2 * i + 1]);
        let (cf, cg) = (chosen[f as usize], chosen[g as usize]);
        if cf != cg {
            let [u, v] = flat.edges[i];
            degree[u as usize] += 1;
            degree[v as usize] += 1;
            any = true;
            has_boundary[comp_of[f as usize] as usize] = true;
        } else if cf && f != g {
            let (a, b) = (find(&mut class, f), find(&mut class, g));
            class[a as usize] = b;
        }
    }
    if !any {
        return Ok(MultiPolygon::default());
    }
    // A component inside a chosen face with boundary edges gives a hole of the region
    // around it: only then is the cycle around it needed.
    if !swept && (0..ncomp as usize).any(|k| has_boundary[k] && chosen[exterior[k] as usize]) {
        around = sweep_around();
    }
    for k in 0..ncomp as usize {
        let (c, e) = (around[k], exterior[k]);
        if c != NONE && chosen[c as usize] {
            let (a, b) = (find(&mut class, c), find(&mut class, e));
            class[a as usize] = b;
        }
    }
    // Rounded points and exactness flags of the boundary's vertices.
    let mut rounded: Vec<Option<Rounded>> = vec![None; nv];
    let point_of = |v: usize, rounded: &mut Vec<Option<Rounded>>| -> Rounded {
        *rounded[v].get_or_insert_with(|| {
            let p = &flat.vertices[v];
            Rounded::of(p, p.approx())
        })
    };
    let on_boundary =
        |h: u32| chosen[cyc[h as usize] as usize] && !chosen[cyc[(h ^ 1) as usize] as usize];
    let mut seen = vec![false; m];
    let mut region_of = vec![NONE; ncycles];
    let mut regions: Vec<Region> = Vec::new();
    let mut pos = vec![NONE; nv];
    let mut cycle: Vec<u32> = Vec::new();
    let mut stack: Vec<u32> = Vec::new();
    let mut rings: Vec<(usize, usize)> = Vec::new();
    let mut flat_rings: Vec<u32> = Vec::new();
    for start in 0..m as u32 {
        if seen[start as usize] || !on_boundary(start) {
            continue;
        }
        cycle.clear();
        let mut h = start;
        loop {
            seen[h as usize] = true;
            cycle.push(h);
            // Clockwise around the end of h, over edges inside the region, to the first
            // boundary edge.
            let mut e = next[h as usize];
            while !on_boundary(e) {
                e = next[(e ^ 1) as usize];
            }
            h = e;
            if h == start {
                break;
            }
        }
        let r = find(&mut class, cyc[start as usize]) as usize;
        if region_of[r] == NONE {
            region_of[r] = regions.len() as u32;
            regions.push((None, Vec::new()));
        }
        let k = region_of[r] as usize;
        // Split at repeated vertices into simple rings.
        rings.clear();
        flat_rings.clear();
        stack.clear();
        for &h in &cycle {
            let v = origin(h) as usize;
            if pos[v] != NONE {
                let at = pos[v] as usize;
                let from = flat_rings.len();
                for &e in &stack[at..] {
                    pos[origin(e) as usize] = NONE;
                    flat_rings.push(e);
                }
                stack.truncate(at);
                rings.push((from, flat_rings.len()));
            }
            pos[v] = stack.len() as u32;
            stack.push(h);
        }
        if !stack.is_empty() {
            let from = flat_rings.len();
            for &e in &stack {
                pos[origin(e) as usize] = NONE;
                flat_rings.push(e);
            }
            rings.push((from, flat_rings.len()));
        }
        for &(a, b) in &rings {
            let ring = &flat_rings[a..b];
            let n = ring.len();
            // Counter-clockwise iff it turns left at its lowest vertex.
            let mut lowest = 0;
            let mut best_v = origin(ring[0]) as usize;
            let mut best_r = point_of(best_v, &mut rounded);
            for (j, &h) in ring.iter().enumerate().skip(1) {
                let v = origin(h) as usize;
                let rv = point_of(v, &mut rounded);
                let o =
                    compare_xy_filtered(&flat.vertices[v], &rv, &flat.vertices[best_v], &best_r);
                if o == Ordering::Less {
                    lowest = j;
                    best_v = v;
                    best_r = rv;
                }
            }
            let ccw = carrier(ring[(lowest + n - 1) % n]).turn(&carrier(ring[lowest]))
                == Orientation::CounterClockwise;
            let mut pts: Vec<Point2> = Vec::with_capacity(n);
            for j in 0..n {
                let h = ring[j];
                let v = origin(h) as usize;
                if !keep_collinear && degree[v] <= 2 {
                    let prev = ring[(j + n - 1) % n];
                    let (qp, qc) = (quad(prev), quad(h));
                    let straight = if qp != AXIS_NONE && qc != AXIS_NONE {
                        qp == qc
                    } else {
                        let (p, c) = (carrier(prev), carrier(h));
                        p.turn(&c) == Orientation::Collinear && p.angle_cmp(&c) == Ordering::Equal
                    };
                    if straight {
                        continue;
                    }
                }
                let q = point_of(v, &mut rounded).point();
                if pts.last() != Some(&q) {
                    pts.push(q);
                }
            }
            while pts.len() > 1 && pts.first() == pts.last() {
                pts.pop();
            }
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
    Ok(MultiPolygon(
        regions
            .into_iter()
            .filter_map(|(shell, holes)| shell.map(|s| Polygon::new(s, holes)))
            .collect(),
    ))
}

/// The winding numbers `(w_A, w_B)` of the rings `segs` (the first `na` from A) at the
/// points just left of each query point `q` (`(q.x − ε, q.y + δ)` for infinitesimals
/// `0 < δ ≪ ε`), or `None` when the strips below would do too much work (the caller then
/// sweeps). A query must not lie in the interior of a face's boundary of another
/// component, which holds for a component's smallest vertex: the points just left of it
/// are inside one face, and its winding numbers are its label.
///
/// Exact and on input points only: a ring edge a → b counts +1 when it crosses the line
/// `y = q.y + δ` upwards (`a.y ≤ q.y < b.y`) with that point on its left, −1 when it
/// crosses downwards (`b.y ≤ q.y < a.y`) with the point on its right; the side is
/// `orient2d(a, b, q)`, and when q is on the edge's line the ε term decides (left for an
/// upward edge, right for a downward one). Only the edges of q's horizontal strip are
/// looked at: an edge is listed in every strip its y range meets, the strip of a y value
/// is a monotone function of it (rounding is monotone), so the edges whose closed y
/// range holds q.y are all in q's strip.
fn windings_left_of(segs: &[Segment2], na: usize, queries: &[Point2]) -> Option<Vec<(i32, i32)>> {
    let ns = segs.len();
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for s in segs {
        lo = lo.min(s.a.y.min(s.b.y));
        hi = hi.max(s.a.y.max(s.b.y));
    }
    // As many strips as keep the edges' spans near one strip each on average (the
    // count is a heuristic; correctness does not depend on it).
    let heights: f64 = segs.iter().map(|s| (s.a.y - s.b.y).abs()).sum::<f64>() / (hi - lo);
    let strips = (ns as f64 / heights.max(1.0)).clamp(1.0, 65536.0) as usize;
    let scale = strips as f64 / (hi - lo);
    if !(scale.is_finite() && scale > 0.0) {
        // All edges horizontal (no crossing anywhere), or a y range too small to cut.
        return (hi == lo).then(|| vec![(0, 0); queries.len()]);
    }
    let strip = |y: f64| (((y - lo) * scale) as usize).min(strips - 1);
    let mut start = vec![0u32; strips + 1];
    let mut total = 0usize;
    for s in segs {
        if s.a.y != s.b.y {
            let (a, b) = (strip(s.a.y.min(s.b.y)), strip(s.a.y.max(s.b.y)));
            total += b - a + 1;
            if total > 8 * ns + 4096 {
                return None;
            }
            for c in &mut start[a + 1..=b + 1] {
                *c += 1;
            }
        }
    }
    // (start[k + 1] holds the count of strip k here.)
    let work: usize = queries.iter().map(|q| start[strip(q.y) + 1] as usize).sum();
    if work > 16 * ns + 4096 {
        return None;
    }
    for k in 0..strips {
        start[k + 1] += start[k];
    }
    let mut fill = start.clone();
    let mut list = vec![0u32; total];
    for (i, s) in segs.iter().enumerate() {
        if s.a.y != s.b.y {
            for k in strip(s.a.y.min(s.b.y))..=strip(s.a.y.max(s.b.y)) {
                list[fill[k] as usize] = i as u32;
                fill[k] += 1;
            }
        }
    }
    Some(
        queries
            .iter()
            .map(|q| {
                let k = strip(q.y);
                let (mut wa, mut wb) = (0, 0);
                for &i in &list[start[k] as usize..start[k + 1] as usize] {
                    let s = segs[i as usize];
                    let w = if s.a.y <= q.y && s.b.y > q.y {
                        i32::from(orient2d(s.a, s.b, *q) != Orientation::Clockwise)
                    } else if s.b.y <= q.y && s.a.y > q.y {
                        -i32::from(orient2d(s.a, s.b, *q) != Orientation::CounterClockwise)
                    } else {
                        0
                    };
                    if (i as usize) < na {
                        wa += w;
                    } else {
                        wb += w;
                    }
                }
                (wa, wb)
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::super::boolean::{boolean_via_dcel, boolean_with, oriented_segments};
    use super::super::{BooleanOp, BooleanOptions, FillRule};
    use crate::kernel::{MultiPolygon, Point2, Polygon};
    use proptest::prelude::*;

    const OPS: [BooleanOp; 4] = [
        BooleanOp::Intersection,
        BooleanOp::Union,
        BooleanOp::Difference,
        BooleanOp::Xor,
    ];
    const RULES: [FillRule; 3] = [FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive];

    type Key = (u64, u64);

    fn key(p: Point2) -> Key {
        ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits())
    }

    /// A ring up to its start vertex (orientation kept: it is part of the answer).
    fn ring_key(r: &[Point2]) -> Vec<Key> {
        let k: Vec<Key> = r.iter().map(|&p| key(p)).collect();
        let s = (0..k.len()).min_by_key(|&i| k[i]).unwrap_or(0);
        k[s..].iter().chain(&k[..s]).copied().collect()
    }

    /// A polygon set up to ring start, hole order and polygon order.
    fn canonical(m: &MultiPolygon) -> Vec<(Vec<Key>, Vec<Vec<Key>>)> {
        let mut v: Vec<_> =
            m.0.iter()
                .map(|p| {
                    let mut holes: Vec<_> = p.holes.iter().map(|h| ring_key(h)).collect();
                    holes.sort();
                    (ring_key(&p.exterior), holes)
                })
                .collect();
        v.sort();
        v
    }

    fn agree(a: &MultiPolygon, b: &MultiPolygon) -> Result<(), TestCaseError> {
        for rule in RULES {
            for keep_collinear in [false, true] {
                let opts = BooleanOptions {
                    fill_rule: rule,
                    keep_collinear,
                };
                for op in OPS {
                    let fast = boolean_with(a, b, op, &opts).unwrap();
                    let slow = boolean_via_dcel(a, b, op, &opts).unwrap();
                    let mut segs = oriented_segments(a, rule).unwrap();
                    let na = segs.len();
                    segs.extend(oriented_segments(b, rule).unwrap());
                    let inside = |wa, wb| op.apply(rule.inside(wa), rule.inside(wb));
                    let swept = super::traced(&segs, na, inside, keep_collinear, false).unwrap();
                    prop_assert_eq!(canonical(&swept), canonical(&slow));
                    prop_assert_eq!(
                        canonical(&fast),
                        canonical(&slow),
                        "{:?} {:?} keep {}",
                        op,
                        rule,
                        keep_collinear
                    );
                }
            }
        }
        Ok(())
    }

    fn p(x: i32, y: i32) -> Point2 {
        Point2::new(x as f64, y as f64)
    }

    /// Rings on a small grid: self-crossing, self-touching, repeated and collinear edges.
    fn grid_ring(max: i32) -> impl Strategy<Value = Vec<Point2>> {
        prop::collection::vec((0..=max, 0..=max), 3..8)
            .prop_map(|v| v.into_iter().map(|(x, y)| p(x, y)).collect())
            .prop_filter("3 distinct points", |r: &Vec<Point2>| {
                let mut k: Vec<Key> = r.iter().map(|&q| key(q)).collect();
                k.sort();
                k.dedup();
                k.len() >= 3
            })
    }

    /// Polygons with holes on the grid: shells and holes share edges and vertices.
    fn grid_set(max: i32) -> impl Strategy<Value = MultiPolygon> {
        prop::collection::vec(
            (grid_ring(max), prop::collection::vec(grid_ring(max), 0..2)),
            0..3,
        )
        .prop_map(|v| MultiPolygon(v.into_iter().map(|(s, h)| Polygon::new(s, h)).collect()))
    }

    /// Axis-parallel rectangles (shared edges, T-junctions, identical copies), some with a
    /// rectangular hole touching the shell.
    fn rect_set() -> impl Strategy<Value = MultiPolygon> {
        prop::collection::vec((0..5i32, 0..5i32, 1..4i32, 1..4i32, any::<bool>()), 0..6).prop_map(
            |v| {
                MultiPolygon(
                    v.into_iter()
                        .map(|(x, y, w, h, hole)| {
                            let shell = vec![p(x, y), p(x + w, y), p(x + w, y + h), p(x, y + h)];
                            let holes = if hole && w > 1 && h > 1 {
                                // Touches the shell at (x, y).
                                vec![vec![p(x, y), p(x, y + 1), p(x + 1, y + 1)]]
                            } else {
                                vec![]
                            };
                            Polygon::new(shell, holes)
                        })
                        .collect(),
                )
            },
        )
    }

    #[test]
    fn identical_and_nested_inputs_agree() {
        let sq = |x: i32, y: i32, w: i32| {
            Polygon::new(
                vec![p(x, y), p(x + w, y), p(x + w, y + w), p(x, y + w)],
                vec![],
            )
        };
        let a = MultiPolygon(vec![sq(0, 0, 4), sq(10, 0, 2), sq(1, 1, 1)]);
        // Identical; nested islands inside holes; disjoint components in every face.
        agree(&a, &a).unwrap();
        let ring = MultiPolygon(vec![Polygon::new(
            vec![p(0, 0), p(9, 0), p(9, 9), p(0, 9)],
            vec![vec![p(2, 2), p(2, 7), p(7, 7), p(7, 2)]],
        )]);
        let island = MultiPolygon(vec![sq(3, 3, 3), sq(20, 20, 1), sq(4, 4, 1)]);
        agree(&ring, &island).unwrap();
        agree(&island, &ring).unwrap();
        agree(&MultiPolygon::default(), &ring).unwrap();
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(300))]

        #[test]
        fn traced_path_agrees_with_the_dcel_path_on_grid_rings(a in grid_set(5), b in grid_set(5)) {
            agree(&a, &b)?;
        }

        #[test]
        fn traced_path_agrees_on_rectangles(a in rect_set(), b in rect_set()) {
            agree(&a, &b)?;
            agree(&a, &a)?;
        }

        #[test]
        fn traced_path_agrees_on_concurrent_crossings(
            spokes in prop::collection::vec(
                (0..7i32, 0..7i32).prop_filter("not the centre", |&q| q != (3, 3)),
                2..6,
            ),
            shift in 0..3i32,
        ) {
            // Thin triangles through the centre (3, 3) from opposite grid points: many
            // edges through one crossing, which is a constructed point off the grid when
            // the spokes are shifted.
            let tri = |&(x, y): &(i32, i32)| {
                Polygon::new(vec![p(x, y), p(6 - x, 6 - y), p(6 - x + shift, 6 - y + 1)], vec![])
            };
            let a = MultiPolygon(spokes.iter().step_by(2).map(tri).collect());
            let b = MultiPolygon(spokes.iter().skip(1).step_by(2).map(tri).collect());
            agree(&a, &b)?;
        }

        #[test]
        fn traced_path_agrees_on_random_float_polygons(
            v in prop::collection::vec((-1.0..1.0f64, -1.0..1.0f64), 3..12),
            w in prop::collection::vec((-1.0..1.0f64, -1.0..1.0f64), 3..12),
        ) {
            let ring = |v: &[(f64, f64)]| v.iter().map(|&(x, y)| Point2::new(x, y)).collect::<Vec<_>>();
            let a = MultiPolygon(vec![Polygon::new(ring(&v), vec![])]);
            let b = MultiPolygon(vec![Polygon::new(ring(&w), vec![])]);
            agree(&a, &b)?;
        }
    }
}
