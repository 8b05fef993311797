//! The boolean-only path (book §2.4 without building the DCEL records): from the flat
//! arrangement of both inputs' rings straight to the result's rings, on compact arrays.
//!
//! 1. *Arrangement*: [`Flat::of_segments`] (exact noding: vertices, edges, the ring edges
//!    carrying each edge), of the ring edges left once those whose contributions to the
//!    winding numbers cancel are dropped (sides neighbouring polygons of one input share,
//!    run both ways: `dcel/cancel.rs`; not when every boundary vertex is to be kept).
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
//!    left of that vertex (the book's graph G): the face east of the nearest edge met
//!    going west from it, found among the edges of its horizontal strip, sorted by x (one
//!    radix sort of 32-bit monotone keys for all strips) so that only a few are tested
//!    ([`faces_left_by_strips`]); where the strips would be too large, winding counts
//!    over strips of input segments (over all segments when there are few components;
//!    with at most 64 components, each segment looks up the smallest vertices in its y
//!    range) or one sweep (`dcel/holes.rs`) are used instead. Components are resolved in
//!    lexicographic order of their smallest vertex, so the face found is already
//!    labelled. All decisions are exact; the rounded crossings are those the noding made
//!    (kept in the arrangement), used only as filters and for the output.
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
//! sorts at vertices of degree > 2, plus, with several components, the strips (O(V + E)
//! and a few tests per component on map-like data) or the hole sweep.
use super::boolean::{oriented_segments, FillRule};
use super::rounding::{
    down, failing_rings, stands_for_any, straighten_all, up, without_straight_points, ExactPoints,
    PointIds, RoundedRings, REPAIRS,
};
use crate::dcel::{
    compare_xy_filtered_by, compare_y_filtered, faces_left_of, side, Carrier, Flat, Rounded,
};
use crate::kernel::arith::ordered_key as okey;
use crate::kernel::steps::Steps;
use crate::kernel::{
    compare_xy, orient2d, orient_exact, ExactPoint, MultiPolygon, Orientation, Point2, Polygon,
    Segment2,
};
use crate::scratch::{self, Scratch};
use crate::Result;
use foldhash::fast::RandomState;
use std::cmp::Ordering;
use std::collections::HashMap;

const NONE: u32 = u32::MAX;
/// Not an axis direction (see [`EdgeInfo::quad`]).
const AXIS_NONE: u8 = 4;

/// A region of the result: its shell (once found) and its holes, as ring numbers of the
/// result's rounded rings.
type Region = (Option<usize>, Vec<usize>);

/// 0 for directions in [0°, 180°), 1 for [180°, 360°) (as [`Carrier::angle_cmp`]).
fn half(c: &Carrier) -> u8 {
    let (a, b) = if c.forward {
        (c.seg.a, c.seg.b)
    } else {
        (c.seg.b, c.seg.a)
    };
    u8::from(!(b.y > a.y || (b.y == a.y && b.x > a.x)))
}

/// `list` (half-edges leaving one vertex) in counter-clockwise order from +x, as
/// [`Carrier::angle_cmp`] orders their carriers: by half-plane, then by the exact turn
/// from one direction to the other. Each entry's carrier and half-plane are made once
/// (`keyed` is scratch space), not at each of the O(k log k) comparisons. Kept out of
/// line: the caller's loop over all vertices rarely comes here.
#[inline(never)]
fn sort_by_angle(
    list: &mut [u32],
    keyed: &mut Vec<(u8, Carrier, u32)>,
    carrier: impl Fn(u32) -> Carrier,
) {
    // `x` before `y`: a smaller half-plane, or the same and a left turn from x to y.
    let before = |x: &(u8, Carrier, u32), y: &(u8, Carrier, u32)| {
        x.0 < y.0 || (x.0 == y.0 && x.1.turn(&y.1) == Orientation::CounterClockwise)
    };
    const SMALL: usize = 8;
    if list.len() <= SMALL {
        // Few entries (the usual vertex of a map has 3 or 4): an insertion sort of
        // indices into a stack array of keys, entries moved as 4-byte numbers.
        let mut keys = [(0u8, carrier(list[0]), 0u32); SMALL];
        for (k, &h) in keys.iter_mut().zip(list.iter()) {
            let c = carrier(h);
            *k = (half(&c), c, h);
        }
        let mut order = [0u8; SMALL];
        for i in 1..list.len() {
            let x = &keys[i];
            let mut j = i;
            while j > 0 && before(x, &keys[order[j - 1] as usize]) {
                order[j] = order[j - 1];
                j -= 1;
            }
            order[j] = i as u8;
        }
        for (slot, &o) in list.iter_mut().zip(order.iter()) {
            *slot = keys[o as usize].2;
        }
        return;
    }
    keyed.clear();
    keyed.extend(list.iter().map(|&h| {
        let c = carrier(h);
        (half(&c), c, h)
    }));
    keyed.sort_unstable_by(|x, y| {
        x.0.cmp(&y.0).then_with(|| match x.1.turn(&y.1) {
            Orientation::CounterClockwise => Ordering::Less,
            Orientation::Clockwise => Ordering::Greater,
            Orientation::Collinear => Ordering::Equal,
        })
    });
    for (slot, k) in list.iter_mut().zip(keyed.iter()) {
        *slot = k.2;
    }
}

/// Two [`pseudo_angle`]s further apart than this are in the order of their exact angles.
///
/// Each rounded difference `b − a` of a direction has its exact sign (so the quadrant is
/// exact) and a relative error of at most u = 2⁻⁵³; within a quadrant the key is
/// `q + t` with `t = p / (p + r)` for the two magnitudes `p, r ≥ 0`, whose rounded value
/// has a relative error below 4.01u (the rounded sum of two non-negative values with
/// errors ≤ u has error ≤ u before its own rounding; one more rounding each for the sum
/// and the quotient), so an absolute error below 4.01u as t ≤ 1; the sum `q + t` < 4
/// rounds by at most 2⁻⁵¹ / 2. Two keys are each within 7·10⁻¹⁶ of their exact values,
/// whose order (the key is a strictly increasing function of the angle from +x) is the
/// angular one; their rounded difference is off by at most 2⁻⁵¹ more. 2⁻⁴⁴ leaves a
/// margin of more than 10.
const KEY_GAP: f64 = 1.0 / (1u64 << 44) as f64;

/// A key for direction `(dx, dy)` (not zero) increasing with its angle from +x
/// counter-clockwise in [0, 4]: quadrant + `t` in [0, 1] (`t` is 0 on the axes). NaN
/// when `|dx| + |dy|` is not finite (an overflowed difference).
#[inline(always)]
fn pseudo_angle(dx: f64, dy: f64) -> f64 {
    let (ax, ay) = (dx.abs(), dy.abs());
    let sum = ax + ay;
    let sum = if sum < f64::INFINITY { sum } else { f64::NAN };
    if dy >= 0.0 {
        if dx > 0.0 {
            ay / sum
        } else {
            1.0 + ax / sum
        }
    } else if dx < 0.0 {
        2.0 + ay / sum
    } else {
        3.0 + ax / sum
    }
}

/// `list` (half-edges leaving one vertex, at most 8) in counter-clockwise order from +x
/// by [`pseudo_angle`] keys, when all are finite and further apart than [`KEY_GAP`] (then
/// this is the exact order); `false`, with `list` untouched, otherwise.
#[inline(always)]
fn sort_by_keys(list: &mut [u32], dir: impl Fn(u32) -> (f64, f64)) -> bool {
    const SMALL: usize = 8;
    if list.len() > SMALL {
        return false;
    }
    let mut keys = [(0.0f64, 0u32); SMALL];
    for (k, &h) in keys.iter_mut().zip(list.iter()) {
        let (dx, dy) = dir(h);
        *k = (pseudo_angle(dx, dy), h);
    }
    let keys = &mut keys[..list.len()];
    for i in 1..keys.len() {
        let x = keys[i];
        let mut j = i;
        while j > 0 && x.0 < keys[j - 1].0 {
            keys[j] = keys[j - 1];
            j -= 1;
        }
        keys[j] = x;
    }
    // (A NaN key makes its gaps NaN, which fail the test.)
    let mut ok = true;
    for w in keys.windows(2) {
        ok &= w[1].0 - w[0].0 > KEY_GAP;
    }
    if ok {
        for (slot, k) in list.iter_mut().zip(keys.iter()) {
            *slot = k.1;
        }
    }
    ok
}

/// The half-edges leaving each vertex (half-edge `2i` runs `edges[i][0] → edges[i][1]`,
/// `2i + 1` back) as `(starts, lists)`: vertex `v`'s are `lists[starts[v]..starts[v + 1]]`,
/// in the order of the edges.
fn outgoing(edges: &[[u32; 2]], nv: usize) -> (Scratch<u32>, Scratch<u32>) {
    // Counted one place up, so that starts[v + 1] is v's fill cursor and, once filled,
    // v's end, i.e. the start of v + 1 (no copy of the starts to fill with).
    let mut starts = scratch::filled(nv + 2, 0u32);
    for [u, v] in edges {
        starts[*u as usize + 2] += 1;
        starts[*v as usize + 2] += 1;
    }
    for v in 0..nv {
        starts[v + 2] += starts[v + 1];
    }
    let mut lists = scratch::filled(2 * edges.len(), 0u32);
    for (i, [u, v]) in edges.iter().enumerate() {
        for h in [2 * i as u32, 2 * i as u32 + 1] {
            let o = if h & 1 == 0 { *u } else { *v } as usize;
            let at = &mut starts[o + 1];
            lists[*at as usize] = h;
            *at += 1;
        }
    }
    starts.pop();
    (starts, lists)
}

/// [`outgoing`] for an arrangement of axis-parallel edges (`quads[i]`, the direction of
/// half-edge `2i`, not
/// [`AXIS_NONE`]), each list in counter-clockwise order from +x: the half-edges go
/// into four slots per vertex, one per direction (two edges leaving a vertex the same
/// way would overlap, and the arrangement has none), read out vertex by vertex. The
/// slots' buffer is returned too, for the caller's next array of numbers (on big input
/// fresh pages cost as much as the work).
fn outgoing_by_axis(
    edges: &[[u32; 2]],
    quads: &[u8],
    nv: usize,
) -> (Scratch<u32>, Scratch<u32>, Scratch<u32>) {
    let mut slots = scratch::filled(4 * nv, NONE);
    for (i, ([u, v], &q)) in edges.iter().zip(quads).enumerate() {
        let q = q as usize;
        debug_assert!(q < 4);
        debug_assert_eq!(slots[4 * *u as usize + q], NONE);
        debug_assert_eq!(slots[4 * *v as usize + (q ^ 2)], NONE);
        slots[4 * *u as usize + q] = 2 * i as u32;
        slots[4 * *v as usize + (q ^ 2)] = 2 * i as u32 + 1;
    }
    let mut starts = scratch::with_capacity(nv + 1);
    let mut lists = scratch::with_capacity(2 * edges.len());
    starts.push(0);
    for four in slots.chunks_exact(4) {
        lists.extend(four.iter().copied().filter(|&h| h != NONE));
        starts.push(lists.len() as u32);
    }
    (starts, lists, slots)
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
    let first = traced(segs, na, inside, keep_collinear, true, &[])?;
    let (mut fresh, mut flags) = (first.polygons, first.context_suspect);
    // Rounding may have broken the result near some polygons (see `rounding`): unite
    // those again, each its shell minus its holes, and check the new ones among the
    // others (which can be found near them in turn).
    let mut settled: Vec<Polygon> = Vec::new();
    let mut repaired = false;
    for _ in 0..REPAIRS {
        let (mut again, mut kept) = (Vec::new(), Vec::new());
        let flagged = fresh
            .drain(..)
            .chain(settled.drain(..).zip(flags.drain(..)));
        for (polygon, suspect) in flagged {
            if suspect {
                again.push(polygon);
            } else {
                kept.push(polygon);
            }
        }
        settled = kept;
        if again.is_empty() {
            break;
        }
        repaired = true;
        let again = MultiPolygon(again);
        let (segs, na) = oriented_segments(&again, &MultiPolygon::default(), FillRule::Positive)?;
        let united = traced(&segs, na, |w, _| w > 0, keep_collinear, true, &settled)?;
        (fresh, flags) = (united.polygons, united.context_suspect);
    }
    settled.extend(fresh.into_iter().map(|(polygon, _)| polygon));
    if repaired && !keep_collinear {
        // (Each union dropped the straight points no other ring of its own had; a
        // settled polygon may have kept one for a ring united again since.)
        straighten_all(&mut settled);
    }
    Ok(canonical_order(settled))
}

/// The polygons of `context` (by number, ascending) whose boxes meet the box of `segs`
/// widened by 2⁻⁴⁰ of its largest coordinate (and the smallest normal `f64`): more than
/// the ten float gaps within which the rounding check looks for near pairs, so a
/// polygon left out has no point on a result made from `segs` (whose vertices, rounded
/// to nearest, stay in that box) and nothing near it. All of `context` when it is
/// small.
fn near_context(segs: &[Segment2], context: &[Polygon]) -> Vec<usize> {
    if context.len() <= 4 || segs.is_empty() {
        return (0..context.len()).collect();
    }
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for p in segs.iter().flat_map(|s| [s.a, s.b]) {
        (x0, x1, y0, y1) = (x0.min(p.x), x1.max(p.x), y0.min(p.y), y1.max(p.y));
    }
    let largest = [x0, x1, y0, y1].iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let pad = largest / (1u64 << 40) as f64 + f64::MIN_POSITIVE;
    let (x0, x1, y0, y1) = (x0 - pad, x1 + pad, y0 - pad, y1 + pad);
    (0..context.len())
        .filter(|&c| {
            // (Holes are inside the exterior: its box is the polygon's.)
            let [lo_x, hi_x, lo_y, hi_y] = box_of(&context[c].exterior);
            lo_x <= x1 && x0 <= hi_x && lo_y <= y1 && y0 <= hi_y
        })
        .collect()
}

/// The polygons [`traced_boolean`] finds before any repair, each with whether rounding
/// may have broken the result near it, and the same for each polygon of `context`
/// (polygons of the result found before, which are checked with these as they are).
#[derive(Default)]
struct Traced {
    polygons: Vec<(Polygon, bool)>,
    context_suspect: Vec<bool>,
    /// How many points the check moved off their nearest floats (`rounding::mend`;
    /// tests read it).
    #[cfg_attr(not(test), allow(dead_code))]
    nudged: usize,
    /// The polygons as rounded and checked, before the points left straight are
    /// dropped (tests compare them with the DCEL path's).
    #[cfg(test)]
    undropped: Vec<Polygon>,
}

/// [`traced_boolean`]; with `strips` false the labels of components always come from the
/// hole sweep (tests check both ways agree).
fn traced(
    segs: &[Segment2],
    na: usize,
    inside: impl Fn(i32, i32) -> bool,
    keep_collinear: bool,
    strips: bool,
    context: &[Polygon],
) -> Result<Traced> {
    // Segments whose contributions to the winding numbers cancel (the sides neighbouring
    // polygons of one input share) go first, unless every vertex on the boundary is to
    // be kept: the faces' winding numbers stay the same, from fewer edges. Per edge its
    // first source and the winding changes across it (crossing a ring edge a → b from
    // its right to its left adds one).
    let (left, flat, deltas) = if keep_collinear {
        let (flat, deltas) = Flat::of_segments_summed(segs, na)?;
        (None, flat, deltas)
    } else {
        Flat::of_segments_summed_cancelling(segs, na)?
    };
    let (segs, na) = left
        .as_ref()
        .map_or((segs, na), |(s, n)| (s.as_slice(), *n));
    let nv = flat.vertices.len();
    let ne = flat.edge_count();
    let m = 2 * ne;
    if ne == 0 {
        return Ok(Traced {
            context_suspect: vec![false; context.len()],
            ..Traced::default()
        });
    }
    // Per edge its first source (the arrangement's, kept: on big input a copy is as
    // many fresh pages) and the axis direction of half-edge 2i: 0 = +x, 1 = +y, 2 = −x,
    // 3 = −y (counter-clockwise order from +x), else AXIS_NONE.
    let sources: &[crate::dcel::Source] = &flat.sources;
    debug_assert!(flat.src_start.is_empty());
    let quads: Scratch<u8> = scratch::collected(sources.iter().map(|src| {
        // The axis direction of the segment a → b (a ≠ b: the arrangement has no
        // zero-length segments), turned for a half-edge running it backwards.
        let (a, b) = (segs[src.segment].a, segs[src.segment].b);
        let quad = if a.y == b.y {
            if b.x > a.x {
                0
            } else {
                2
            }
        } else if a.x == b.x {
            if b.y > a.y {
                1
            } else {
                3
            }
        } else {
            AXIS_NONE
        };
        if quad == AXIS_NONE || src.forward {
            quad
        } else {
            quad ^ 2
        }
    }));
    let carrier = |h: u32| {
        let e = &sources[(h >> 1) as usize];
        Carrier {
            seg: segs[e.segment],
            forward: e.forward == (h & 1 == 0),
        }
    };
    // The direction of half-edge h, rounded: its input segment's `b − a`, negated when
    // running it backwards (exact signs, see [`KEY_GAP`]).
    let dir = |h: u32| {
        let e = &sources[(h >> 1) as usize];
        let s = &segs[e.segment];
        let (dx, dy) = (s.b.x - s.a.x, s.b.y - s.a.y);
        if e.forward == (h & 1 == 0) {
            (dx, dy)
        } else {
            (-dx, -dy)
        }
    };
    // The axis direction of half-edge h (the reverse of 2i's for 2i + 1).
    let quad = |h: u32| {
        let q = quads[(h >> 1) as usize];
        if q == AXIS_NONE || h & 1 == 0 {
            q
        } else {
            q ^ 2
        }
    };
    // Winding change crossing half-edge h from its right to its left.
    let delta = |h: u32| {
        let (da, db) = deltas[(h >> 1) as usize];
        if h & 1 == 0 {
            (da, db)
        } else {
            (-da, -db)
        }
    };
    let origin = |h: u32| flat.edges[(h >> 1) as usize][(h & 1) as usize];
    // Outgoing half-edges per vertex (one array cut into slices). When every edge is
    // axis-parallel, each vertex has at most one per axis direction, so the lists come
    // already in counter-clockwise order from a table of four slots per vertex, without
    // a sort (which would look up every half-edge's segment for its direction).
    let axis_only = quads.iter().all(|&q| q != AXIS_NONE);
    let (out_start, mut out, spare) = if axis_only {
        outgoing_by_axis(&flat.edges, &quads, nv)
    } else {
        let (starts, lists) = outgoing(&flat.edges, nv);
        (starts, lists, scratch::with_capacity(0))
    };
    let slice = |v: usize| (out_start[v] as usize, out_start[v + 1] as usize);
    let mut next = if spare.capacity() >= m {
        let mut reused = spare;
        reused.clear();
        reused.resize(m, 0);
        reused
    } else {
        scratch::filled(m, 0u32)
    };
    // One list's entries with their half-plane and carrier, each made once (the sort
    // compares them O(k log k) times).
    let mut keyed: Vec<(u8, Carrier, u32)> = Vec::new();
    for v in 0..nv {
        let (a, b) = slice(v);
        let list = &mut out[a..b];
        let k = list.len();
        if k > 2 && !axis_only {
            // By filtered keys (exact on the axes: grid data), else by the exact angle
            // comparison.
            if !sort_by_keys(list, dir) {
                sort_by_angle(list, &mut keyed, carrier);
            }
        }
        // (The one before the first is the last; no division per half-edge.)
        if let Some(&last) = list.last() {
            let mut before = last;
            for &h in list.iter() {
                next[(h ^ 1) as usize] = before;
                before = h;
            }
        }
    }
    // Cycles labelled relative to their component (depth-first across twins).
    let mut cyc = scratch::filled(m, NONE);
    // (A connected plane graph has E − V + 2 face cycles; more components add cycles.)
    let cycles_hint = (ne + 2).saturating_sub(nv);
    let mut label: Scratch<(i32, i32)> = scratch::with_capacity(cycles_hint);
    let mut comp_of: Scratch<u32> = scratch::with_capacity(cycles_hint);
    let mut ncomp = 0u32;
    // (Sized once: at most one entry per edge; growing it was a few reallocations a call.)
    let mut stack: Scratch<(u32, i32, i32)> = scratch::with_capacity(ne);
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
    let mut low = scratch::filled(ncomp as usize, NONE);
    // The smallest point so far beside each (no second look-up of the vertex).
    let mut low_p = scratch::filled(ncomp as usize, Point2::new(f64::INFINITY, f64::INFINITY));
    for v in 0..nv {
        let (a, b) = slice(v);
        if a == b {
            continue;
        }
        let Some(p) = flat.vertices.input(v) else {
            continue;
        };
        let k = comp_of[cyc[out[a] as usize] as usize] as usize;
        let q = low_p[k];
        if low[k] == NONE || p.x < q.x || (p.x == q.x && p.y < q.y) {
            low[k] = v as u32;
            low_p[k] = p;
        }
    }
    drop(low_p);
    // The exterior cycle of each component: left of the out-edge at its smallest vertex
    // just clockwise of direction −x (all out-edges point into (−90°, 90°]).
    let exterior: Scratch<u32> = scratch::collected(low.iter().map(|&v| {
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
    }));
    // Offsets making the labels absolute: the exterior of a component gets the label of
    // the face around it.
    let mut offset: Scratch<(i32, i32)> = scratch::collected(exterior.iter().map(|&c| {
        let (wa, wb) = label[c as usize];
        (-wa, -wb)
    }));
    // The cycle (of another component) whose face holds each component whose smallest
    // vertex is in `queries`, from the hole sweep: its exterior is joined to it in the
    // regions below.
    let sweep_around = |queries: &[u32]| -> Vec<u32> {
        let points = &flat.vertices.exact();
        let approx: Vec<Rounded> = (0..nv).map(|v| flat.vertices.rounded(v)).collect();
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
        for &v in queries {
            query[v as usize] = true;
        }
        let left = faces_left_of(points, &approx, &origins, &carriers, &starts, &outs, &query);
        queries
            .iter()
            .map(|&v| left[v as usize].map_or(NONE, |h| cyc[h]))
            .collect()
    };
    // The cycle around each component whose smallest vertex is in `queries`: from the
    // nearest edge west of that vertex (over x-sorted strips for many queries), or,
    // where the strips would be too large, from the sweep.
    let faces_around = |queries: &[u32]| -> Vec<u32> {
        let seg_of = |i: usize| segs[sources[i].segment];
        match faces_left_by_strips(&flat, seg_of, queries).filter(|_| strips) {
            Some(found) => found
                .into_iter()
                .map(|h| if h == NONE { NONE } else { cyc[h as usize] })
                .collect(),
            None => sweep_around(queries),
        }
    };
    let mut around: Scratch<u32> = scratch::filled(ncomp as usize, NONE);
    let mut swept = false;
    // Labels from the face around each component: components in lexicographic order of
    // their smallest vertex, so the face found for one (which lies left of it) is in a
    // component already resolved.
    let resolve = |around: &[u32], offset: &mut [(i32, i32)]| {
        // (The smallest vertices are distinct input points: their integer keys order
        // them as the coordinates do.)
        let mut order: Vec<(u64, u64, u32)> = (0..ncomp)
            .map(|k| {
                let p = flat.vertices.approx(low[k as usize] as usize);
                (okey(p.x), okey(p.y), k)
            })
            .collect();
        order.sort_unstable();
        for (_, _, k) in order {
            let c = around[k as usize];
            if c != NONE {
                let o = offset[comp_of[c as usize] as usize];
                let (wa, wb) = label[c as usize];
                let (ea, eb) = label[exterior[k as usize] as usize];
                offset[k as usize] = (wa + o.0 - ea, wb + o.1 - eb);
            }
        }
    };
    if ncomp > 1 {
        let input = |v: u32| match flat.vertices.input(v as usize) {
            Some(p) => p,
            None => unreachable!("a component's smallest vertex is an input point"),
        };
        let queries: Vec<Point2> = low.iter().map(|&v| input(v)).collect();
        if let Some(w) = windings_left_of(segs, na, &queries).filter(|_| strips) {
            for k in 0..ncomp as usize {
                let (ea, eb) = label[exterior[k] as usize];
                offset[k] = (w[k].0 - ea, w[k].1 - eb);
            }
        } else {
            around.copy_from_slice(&faces_around(&low));
            swept = true;
            resolve(&around, &mut offset);
        }
    }
    let chosen: Scratch<bool> = scratch::collected((0..ncycles).map(|c| {
        let (wa, wb) = label[c];
        let o = offset[comp_of[c] as usize];
        inside(wa + o.0, wb + o.1)
    }));
    // Regions: chosen cycles joined across non-boundary edges and around holes.
    let mut class: Scratch<u32> = scratch::collected(0..ncycles as u32);
    let mut degree = scratch::filled(nv, 0u32);
    // Per half-edge: 0 off the boundary, BOUNDARY when the result is on its left and
    // not on its right, TRACED once its ring is traced (one byte instead of the two
    // look-ups through `cyc` and `chosen`, and of a separate `seen` array).
    const BOUNDARY: u8 = 1;
    const TRACED: u8 = 2;
    let mut state = scratch::filled(m, 0u8);
    // (Boundary half-edges: each gives a ring at most one point.)
    let mut boundary = 0usize;
    let mut has_boundary = scratch::filled(ncomp as usize, false);
    for i in 0..ne {
        let (f, g) = (cyc[2 * i], cyc[2 * i + 1]);
        let (cf, cg) = (chosen[f as usize], chosen[g as usize]);
        if cf != cg {
            let [u, v] = flat.edges[i];
            degree[u as usize] += 1;
            degree[v as usize] += 1;
            state[2 * i + usize::from(cg)] = BOUNDARY;
            boundary += 1;
            has_boundary[comp_of[f as usize] as usize] = true;
        } else if cf && f != g {
            let (a, b) = (find(&mut class, f), find(&mut class, g));
            class[a as usize] = b;
        }
    }
    if boundary == 0 {
        return Ok(Traced {
            context_suspect: vec![false; context.len()],
            ..Traced::default()
        });
    }
    // A component inside a chosen face with boundary edges gives a hole of the region
    // around it: only then are the cycles around components needed, and only around
    // those inside chosen faces (the face around a component whose exterior is not
    // chosen is not chosen either: the two have the same winding numbers). Those
    // without boundary edges count too: a hole may lie in one of their faces.
    if !swept && (0..ncomp as usize).any(|k| has_boundary[k] && chosen[exterior[k] as usize]) {
        let inside: Vec<usize> = (0..ncomp as usize)
            .filter(|&k| chosen[exterior[k] as usize])
            .collect();
        let queries: Vec<u32> = inside.iter().map(|&k| low[k]).collect();
        for (k, c) in inside.into_iter().zip(faces_around(&queries)) {
            around[k] = c;
        }
    }
    for k in 0..ncomp as usize {
        let (c, e) = (around[k], exterior[k]);
        if c != NONE && chosen[c as usize] {
            let (a, b) = (find(&mut class, c), find(&mut class, e));
            class[a as usize] = b;
        }
    }
    let on_boundary = |state: &[u8], h: u32| state[h as usize] != 0;
    let mut region_of = scratch::filled(ncycles, NONE);
    // (Rings have three points or more: room for that many rings, up to a few hundred,
    // saves the first reallocations of the lists per ring.)
    let rings_hint = (boundary / 3 + 2).min(256);
    let mut regions: Vec<Region> = Vec::with_capacity(rings_hint);
    let mut pos = scratch::filled(nv, NONE);
    // (A boundary cycle has at most one half-edge per edge: sized once, not grown.)
    let mut cycle: Scratch<u32> = scratch::with_capacity(ne);
    let mut stack: Scratch<u32> = scratch::with_capacity(ne);
    let mut rings: Scratch<(usize, usize)> = scratch::with_capacity(rings_hint);
    let mut flat_rings: Scratch<u32> = scratch::with_capacity(ne);
    // The rounded points (and exactness flags) of one ring's vertices, computed once per
    // ring: a vertex is on few rings, so no cache over all vertices is needed.
    let mut ring_r: Scratch<Rounded> = scratch::with_capacity(boundary);
    // What the check that rounding kept the result valid needs of each kept point (its
    // vertices, whether it moved), and all rings' points.
    let mut ids: Scratch<PointIds> = scratch::with_capacity(boundary);
    let mut pts: Scratch<Point2> = scratch::with_capacity(boundary);
    // The regions where rounding made three vertices of a ring one point (the check does
    // not follow these: they are always united again).
    let mut three_on_one: Vec<usize> = Vec::new();
    // The holes rounded away (below), by region, each with a box holding the exact hole:
    // a polygon inside one would now overlap that region.
    let mut holes_gone: Vec<(usize, [f64; 4])> = Vec::new();
    // The vertices of the rings dropped below for rounding to fewer than three points
    // (another ring through one of them may go straight there).
    let mut dropped_vertices: Vec<u32> = Vec::new();
    // Per ring checked, its region (then the context's polygons).
    let mut owner: Scratch<usize> = scratch::with_capacity(rings_hint);
    // The context's polygons that may touch or come near this result (the others
    // cannot touch its rings, nor be near them in the check), and their points: where
    // they touch this result's rings.
    let near: Vec<usize> = near_context(segs, context);
    let near_points = || near.iter().flat_map(|&c| context[c].rings()).flatten();
    let mut context_points: std::collections::HashSet<(u64, u64), foldhash::fast::RandomState> =
        Default::default();
    // (Sized once: the result's points, then the near context's.)
    let points = boundary + near_points().count();
    context_points.reserve(points - boundary);
    context_points.extend(near_points().map(|q| (okey(q.x), okey(q.y))));
    let mut rounded = RoundedRings {
        points: scratch::with_capacity(points),
        ids: scratch::with_capacity(points),
        starts: scratch::with_capacity(rings_hint + 1),
        at_nearest: true,
        ..RoundedRings::default()
    };
    rounded.starts.push(0);
    for start in 0..m as u32 {
        if state[start as usize] != BOUNDARY {
            continue;
        }
        cycle.clear();
        let mut h = start;
        loop {
            state[h as usize] = TRACED;
            cycle.push(h);
            // Clockwise around the end of h, over edges inside the region, to the first
            // boundary edge.
            let mut e = next[h as usize];
            while !on_boundary(&state, e) {
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
            ring_r.clear();
            ring_r.extend(
                ring.iter()
                    .map(|&h| flat.vertices.rounded(origin(h) as usize)),
            );
            // Counter-clockwise iff it turns left at its lowest vertex.
            let mut lowest = 0;
            let mut best_v = origin(ring[0]) as usize;
            for (j, &h) in ring.iter().enumerate().skip(1) {
                let v = origin(h) as usize;
                let o = flat
                    .vertices
                    .compare_xy(v, &ring_r[j], best_v, &ring_r[lowest]);
                if o == Ordering::Less {
                    lowest = j;
                    best_v = v;
                }
            }
            let before = if lowest == 0 { n - 1 } else { lowest - 1 };
            let ccw =
                carrier(ring[before]).turn(&carrier(ring[lowest])) == Orientation::CounterClockwise;
            pts.clear();
            ids.clear();
            // Where the lowest vertex lands in `pts`: the ring starts there (it turns
            // there, so it is never dropped as straight).
            let mut first = 0;
            for j in 0..n {
                let h = ring[j];
                if j == lowest {
                    // (Its rounded point may equal the one before, which then stands for it.)
                    let q = ring_r[j].point();
                    first = if pts.last() == Some(&q) {
                        pts.len() - 1
                    } else {
                        pts.len()
                    };
                }
                let v = origin(h) as usize;
                if !keep_collinear && degree[v] <= 2 {
                    let prev = ring[if j == 0 { n - 1 } else { j - 1 }];
                    let (qp, qc) = (quad(prev), quad(h));
                    let straight = if qp != AXIS_NONE && qc != AXIS_NONE {
                        qp == qc
                    } else {
                        let (p, c) = (carrier(prev), carrier(h));
                        p.turn(&c) == Orientation::Collinear && p.angle_cmp(&c) == Ordering::Equal
                    };
                    // (A point of the context stays: a polygon there touches this ring.)
                    let q = ring_r[j].point();
                    let touched =
                        !context.is_empty() && context_points.contains(&(okey(q.x), okey(q.y)));
                    if straight && !touched {
                        continue;
                    }
                }
                let q = ring_r[j].point();
                let id = PointIds::of(v as u32, flat.vertices.moved(v, &ring_r[j]));
                match ids.last_mut() {
                    // Two vertices rounded onto one point: the edge between them
                    // collapsed.
                    Some(last) if pts.last() == Some(&q) => {
                        if !last.merge(id) {
                            three_on_one.push(k);
                        }
                    }
                    _ => {
                        pts.push(q);
                        ids.push(id);
                    }
                }
            }
            while pts.len() > 1 && pts.first() == pts.last() {
                pts.pop();
                // (The ring's last point is its first: entered at the last's vertex.)
                let mut last = ids.pop().expect("one per point");
                if !last.merge(ids[0]) {
                    three_on_one.push(k);
                }
                ids[0] = last;
            }
            if pts.len() < 3 {
                // The ring rounded to a point or a segment: it was thinner than the
                // rounding (a sliver between near-coincident edges) and is dropped, as
                // a union again would drop it. What is left is the exact result without
                // that ring, valid (but for polygons inside a dropped hole, below), and
                // the check decides its rounded rings as any others.
                if !ccw {
                    // (Its exact vertices are each within a float of one of these
                    // points, and the hole is in their hull.)
                    let b = box_of(&pts);
                    let around = [down(b[0]), up(b[1]), down(b[2]), up(b[3])];
                    holes_gone.push((k, around));
                }
                dropped_vertices.extend(ring.iter().map(|&h| origin(h)));
                continue;
            }
            // (A popped last point equals the first.)
            let first = if first < pts.len() { first } else { 0 };
            pts.rotate_left(first);
            ids.rotate_left(first);
            let ring = owner.len();
            rounded.points.extend_from_slice(&pts);
            rounded.ids.extend_from_slice(&ids);
            rounded.starts.push(rounded.points.len());
            owner.push(k);
            if ccw && regions[k].0.is_none() {
                regions[k].0 = Some(ring);
            } else {
                regions[k].1.push(ring);
            }
        }
    }
    // The context's rings, as they are (their points are exact and do not move), after
    // this result's, with vertex numbers from nv on.
    let own_rings = owner.len();
    let mut context_at = Vec::new();
    for &c in &near {
        for ring in context[c].rings() {
            for &q in ring {
                let id = (nv + context_at.len()) as u32;
                context_at.push(q);
                rounded.points.push(q);
                rounded.ids.push(PointIds::of(id, false));
            }
            rounded.starts.push(rounded.points.len());
            owner.push(c);
        }
    }
    let exact = |i: u32| match (i as usize).checked_sub(nv) {
        Some(c) => ExactPoint::Input(context_at[c]),
        None => flat.vertices.exact_point(i as usize),
    };
    let mut suspect = scratch::filled(regions.len(), false);
    let mut context_suspect = vec![false; context.len()];
    for &k in &three_on_one {
        suspect[k] = true;
    }
    // (The boxes of the regions' shells and of the context polygons near this result,
    // for the two rules below.)
    let (shell_boxes, near_boxes): (Vec<Option<[f64; 4]>>, Vec<[f64; 4]>) =
        if three_on_one.is_empty() && holes_gone.is_empty() {
            (Vec::new(), Vec::new())
        } else {
            let shell_box =
                |s: usize| box_of(&rounded.points[rounded.starts[s]..rounded.starts[s + 1]]);
            (
                regions
                    .iter()
                    .map(|(shell, _)| shell.map(shell_box))
                    .collect(),
                near.iter().map(|&c| box_of(&context[c].exterior)).collect(),
            )
        };
    // Nor does it follow such a ring against its neighbours: rounding may have carried
    // it into a polygon near it (a chord from the point of a sliver to a far vertex,
    // over a polygon's corner), which the next union, where nothing moves, would not
    // see. The polygons near it, this result's and the context's, are united with it.
    if !three_on_one.is_empty() {
        for &k in &three_on_one {
            let Some(b) = shell_boxes[k] else { continue };
            for (j, other) in shell_boxes.iter().enumerate() {
                if other.is_some_and(|o| boxes_near(&b, &o)) {
                    suspect[j] = true;
                }
            }
            for (&c, other) in near.iter().zip(&near_boxes) {
                if boxes_near(&b, other) {
                    context_suspect[c] = true;
                }
            }
        }
    }
    // A polygon inside a hole that rounded away (an island in a sliver of a lake) would
    // overlap the hole's polygon: both are united again, which merges them. Rounding to
    // nearest is monotone, so the island's rounded points are in the hole's box too.
    if !holes_gone.is_empty() {
        let within = |b: &[f64; 4], c: [f64; 4]| {
            b[0] <= c[0] && c[1] <= b[1] && b[2] <= c[2] && c[3] <= b[3]
        };
        for &(k, b) in &holes_gone {
            for (j, shell) in shell_boxes.iter().enumerate() {
                if j != k && shell.is_some_and(|s| within(&b, s)) {
                    (suspect[j], suspect[k]) = (true, true);
                }
            }
            for (&c, &shell) in near.iter().zip(&near_boxes) {
                if within(&b, shell) {
                    (context_suspect[c], suspect[k]) = (true, true);
                }
            }
        }
    }
    // Points are moved off their nearest floats only where no three vertices of a ring
    // rounded onto one point: which two of them the tracing merged depends on where it
    // started the ring, and the points moved should not (those results are united
    // again anyway).
    // (The order is decided on the rounded points where they differ: rounding to
    // nearest is monotone.)
    let rounded_of = |i: u32| match (i as usize).checked_sub(nv) {
        Some(c) => Rounded::input(context_at[c]),
        None => flat.vertices.rounded(i as usize),
    };
    let exact_points = three_on_one.is_empty().then_some(ExactPoints {
        toward: |v: u32, q: Point2| exact(v).compare_with_point(q),
        order: |u: u32, v: u32| {
            compare_xy_filtered_by(&rounded_of(u), &rounded_of(v), || (exact(u), exact(v)))
        },
    });
    let failing = failing_rings(
        &mut rounded,
        |a, b, c| orient_exact(&exact(a), &exact(b), &exact(c)),
        exact_points,
    );
    for ring in failing {
        if ring < own_rings {
            suspect[owner[ring]] = true;
        } else {
            context_suspect[owner[ring]] = true;
        }
    }
    // (Counted only when a ring has a straight point.)
    let point_uses = std::cell::OnceCell::new();
    dropped_vertices.sort_unstable();
    // Where a dropped ring touched another ring: the tracing kept the point (other
    // boundary edges met there), and that ring may go straight there, rounded or not.
    let crowded = |id: &PointIds| stands_for_any(id, &dropped_vertices);
    // Ring k's points and where its lowest point (x, then y) is among them.
    let from_lowest = |k: usize| {
        let pts = &rounded.points[rounded.starts[k]..rounded.starts[k + 1]];
        let lowest = (0..pts.len())
            .min_by(|&i, &j| compare_xy(pts[i], pts[j]))
            .unwrap_or(0);
        (pts, lowest)
    };
    #[cfg(test)]
    let undropped = {
        let ring = |k: usize| {
            let (pts, lowest) = from_lowest(k);
            [&pts[lowest..], &pts[..lowest]].concat()
        };
        regions
            .iter()
            .filter_map(|(shell, holes)| {
                shell.map(|s| Polygon::new(ring(s), holes.iter().map(|&h| ring(h)).collect()))
            })
            .collect()
    };
    let polygons = regions
        .into_iter()
        .zip(suspect.iter().copied())
        .filter_map(|((shell, holes), suspect)| {
            // Each ring from its lowest point (x, then y). The rings start at the rounded
            // point of their exact lowest vertex, which is not always the lowest rounded
            // point: rounding can make two x equal and reverse their points' y order,
            // and the check may have moved points.
            // Unless collinear vertices are kept, without the points rounding left
            // straight between their neighbours where no other ring passes.
            let ring = |k: usize| {
                let (pts, lowest) = from_lowest(k);
                if keep_collinear {
                    return [&pts[lowest..], &pts[..lowest]].concat();
                }
                let ids = &rounded.ids[rounded.starts[k]..rounded.starts[k + 1]];
                without_straight_points(pts, ids, lowest, crowded, |q| {
                    let uses = point_uses.get_or_init(|| own_point_uses(&rounded, own_rings));
                    let key = (okey(q.x), okey(q.y));
                    uses[&key] == 1 && !context_points.contains(&key)
                })
            };
            shell.map(|s| {
                (
                    Polygon::new(ring(s), holes.into_iter().map(ring).collect()),
                    suspect,
                )
            })
        })
        .collect();
    Ok(Traced {
        polygons,
        context_suspect,
        nudged: rounded.nudged,
        #[cfg(test)]
        undropped,
    })
}

/// How many times the result's own rings (the first `own_rings` of `rounded`) have
/// each point (by [`okey`]).
fn own_point_uses(
    rounded: &RoundedRings,
    own_rings: usize,
) -> HashMap<(u64, u64), u32, RandomState> {
    let mut uses = HashMap::default();
    for q in &rounded.points[..rounded.starts[own_rings]] {
        *uses.entry((okey(q.x), okey(q.y))).or_insert(0) += 1;
    }
    uses
}

/// Whether boxes `a` and `b` (`[min x, max x, min y, max y]`) meet once widened by
/// 2⁻⁴⁰ of their largest coordinate (and the smallest normal `f64`), as in
/// [`near_context`]: more than rounding moves a point.
fn boxes_near(a: &[f64; 4], b: &[f64; 4]) -> bool {
    let largest = a.iter().chain(b).fold(0.0f64, |m, v| m.max(v.abs()));
    let pad = largest / (1u64 << 40) as f64 + f64::MIN_POSITIVE;
    a[0] - pad <= b[1] && b[0] - pad <= a[1] && a[2] - pad <= b[3] && b[2] - pad <= a[3]
}

/// `[min x, max x, min y, max y]` of `points`.
pub(super) fn box_of(points: &[Point2]) -> [f64; 4] {
    let mut b = [
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    ];
    for p in points {
        b = [b[0].min(p.x), b[1].max(p.x), b[2].min(p.y), b[3].max(p.y)];
    }
    b
}

/// The polygons in a canonical order, independent of how the arrangement numbered its
/// vertices and edges: every ring already starts at its lowest vertex (smallest x, then
/// smallest y); the holes of each polygon, and the polygons by their shells, are sorted
/// by their points' coordinates, lexicographically (rings of a valid result are
/// distinct, so this is a total order on them). The same region gives the same output
/// whatever the input's order or the library's internals.
fn canonical_order(mut polygons: Vec<Polygon>) -> MultiPolygon {
    fn by_points(a: &[Point2], b: &[Point2]) -> Ordering {
        a.iter()
            .zip(b)
            .map(|(p, q)| compare_xy(*p, *q))
            .find(|o| o.is_ne())
            .unwrap_or_else(|| a.len().cmp(&b.len()))
    }
    // (Rings are told apart by their first, lowest, points as integer keys, made once
    // per polygon; only rings sharing that point are compared further.)
    let first = |ring: &[Point2]| ring.first().map_or((0, 0), |p| (okey(p.x), okey(p.y)));
    for p in &mut polygons {
        p.holes
            .sort_unstable_by(|a, b| first(a).cmp(&first(b)).then_with(|| by_points(a, b)));
    }
    let mut keyed: Vec<((u64, u64), Polygon)> = polygons
        .into_iter()
        .map(|p| (first(&p.exterior), p))
        .collect();
    keyed.sort_unstable_by(|(ka, a), (kb, b)| {
        ka.cmp(kb).then_with(|| by_points(&a.exterior, &b.exterior))
    });
    MultiPolygon(keyed.into_iter().map(|(_, p)| p).collect())
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
/// upward edge, right for a downward one). With few queries (at most
/// [`SORTED_QUERIES`]) each edge finds the queries with `y_min ≤ q.y < y_max` among
/// the queries sorted by y; with more, only the edges of q's horizontal strip are
/// looked at: an edge is listed in every strip its y range meets, the strip of a y value
/// is a monotone function of it (rounding is monotone), so the edges whose closed y
/// range holds q.y are all in q's strip.
fn windings_left_of(segs: &[Segment2], na: usize, queries: &[Point2]) -> Option<Vec<(i32, i32)>> {
    windings_left_of_by(segs, na, queries, Windings::Auto)
}

/// How [`windings_left_of_by`] finds the segments that count at each query.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Windings {
    /// By the number of queries (below).
    Auto,
    /// Every segment for every query.
    Direct,
    /// Each segment looks up the queries in its y range among the queries sorted by y.
    Sorted,
    /// The segments of each query's horizontal strip.
    Strips,
}

/// At most this many queries are looked up per segment ([`Windings::Sorted`]): a binary
/// search over a few heights per segment costs less than listing the segments by
/// strips, and only the segments that count are tested (GEOS-837 dissolve, 18 queries:
/// -4.9% of the call; squares 1e4, 48 queries: -0.3%).
const SORTED_QUERIES: usize = 64;

/// [`windings_left_of`] the way `how` says (tests compare the ways).
fn windings_left_of_by(
    segs: &[Segment2],
    na: usize,
    queries: &[Point2],
    how: Windings,
) -> Option<Vec<(i32, i32)>> {
    // The winding change of segment s at q when its y range [y_min, y_max) holds q.y
    // (the only segments that cross the line y = q.y + δ).
    fn crossing(s: Segment2, q: Point2) -> i32 {
        if s.a.y <= q.y && s.b.y > q.y {
            i32::from(orient2d(s.a, s.b, q) != Orientation::Clockwise)
        } else if s.b.y <= q.y && s.a.y > q.y {
            -i32::from(orient2d(s.a, s.b, q) != Orientation::CounterClockwise)
        } else {
            0
        }
    }
    // The winding numbers at q from the segments `items` (all that can cross q's line).
    fn winding(
        segs: &[Segment2],
        na: usize,
        q: Point2,
        items: impl Iterator<Item = usize>,
    ) -> (i32, i32) {
        let (mut wa, mut wb) = (0, 0);
        for i in items {
            let w = crossing(segs[i], q);
            if i < na {
                wa += w;
            } else {
                wb += w;
            }
        }
        (wa, wb)
    }
    let n = segs.len();
    // Few queries: every segment for each of them costs less than the strips (same
    // answers: the strips only leave out segments that cannot count).
    let how = match how {
        Windings::Auto if queries.len().saturating_mul(n) <= 4 * n + 4096 => Windings::Direct,
        Windings::Auto if queries.len() <= SORTED_QUERIES => Windings::Sorted,
        Windings::Auto => Windings::Strips,
        how => how,
    };
    if how == Windings::Direct {
        return Some(
            queries
                .iter()
                .map(|&q| winding(segs, na, q, 0..n))
                .collect(),
        );
    }
    if how == Windings::Sorted {
        let mut order: Vec<u32> = (0..queries.len() as u32).collect();
        order.sort_unstable_by(|&i, &j| queries[i as usize].y.total_cmp(&queries[j as usize].y));
        let ys: Vec<f64> = order.iter().map(|&k| queries[k as usize].y).collect();
        let mut w = vec![(0, 0); queries.len()];
        let (Some(&y_min), Some(&y_max)) = (ys.first(), ys.last()) else {
            return Some(w);
        };
        // The strips' scan budget: past it the nearest-edge search is cheaper (long
        // segments across many queries' lines).
        let mut budget = 4 * n + 4096;
        // Equal buckets over [y_min, y_max]: `bucket` is monotone in y (rounding is),
        // so the queries in buckets below lo's are all below lo, and `first[b]` (the
        // number of queries in buckets below b) is where the search for lo starts: a
        // few steps instead of a binary search per segment. (−0 and 0 share a bucket.)
        let buckets = 4 * ys.len();
        let steps = Steps::new(y_min, y_max, buckets as u32);
        let bucket = |y: f64| steps.index(y);
        let mut first = vec![0u32; buckets + 1];
        for &y in &ys {
            first[bucket(y) + 1] += 1;
        }
        for b in 0..buckets {
            first[b + 1] += first[b];
        }
        for (i, &s) in segs.iter().enumerate() {
            let (lo, hi) = (s.a.y.min(s.b.y), s.a.y.max(s.b.y));
            // Only queries with lo <= q.y < hi can count (never for horizontal ones).
            if hi <= y_min || lo > y_max {
                continue;
            }
            // (total_cmp orders as < does here: only -0 and 0 differ, on which `<`
            // agrees, so the predicate is monotone along `ys`.)
            let mut from = first[bucket(lo)] as usize;
            while from < ys.len() && ys[from] < lo {
                from += 1;
            }
            debug_assert_eq!(from, ys.partition_point(|&y| y < lo));
            for (&y, &k) in ys[from..].iter().zip(&order[from..]) {
                if y >= hi {
                    break;
                }
                budget = budget.checked_sub(1)?;
                let c = crossing(s, queries[k as usize]);
                let slot = &mut w[k as usize];
                if i < na {
                    slot.0 += c;
                } else {
                    slot.1 += c;
                }
            }
        }
        return Some(w);
    }
    let ranges: Vec<(f64, f64)> = segs
        .iter()
        .map(|s| (s.a.y.min(s.b.y), s.a.y.max(s.b.y)))
        .collect();
    let ys: Vec<f64> = queries.iter().map(|q| q.y).collect();
    let strips = Strips::new(&ranges, &ys)?;
    Some(
        queries
            .iter()
            .map(|&q| winding(segs, na, q, strips.items(q.y).iter().map(|&i| i as usize)))
            .collect(),
    )
}

/// For each query vertex (a component's smallest vertex: an input point `q`), the
/// half-edge whose face holds the points just left of it (`(q.x − ε, q.y + δ)` for
/// infinitesimals `0 < δ ≪ ε`), or [`NONE`] for the unbounded face; `None` when the
/// strips would do too much work (the caller then sweeps). `seg_of(i)` is the input
/// segment carrying edge `i`.
///
/// Going west from those points along `y = q.y + δ`, the first edge met bounds their
/// face, which lies east of it: the face left of its half-edge running down. An edge
/// crosses that line iff its lower end has `y ≤ q.y` and its upper end `y > q.y`
/// (horizontal edges never do); it lies west of q iff q is strictly east of its carrier.
/// No such edge of q's own component exists (q is its smallest vertex; an edge of it
/// ending at q is on q's line and excluded), and q is on no edge of another component
/// (edges do not pass through vertices), so that side test is strict. Of two crossing
/// edges (which do not cross each other), the one further east is found by testing an
/// end of one that lies in the other's y range and is not one of its ends: the higher
/// lower end, or, where the lower ends are the same vertex, the lower upper end. All
/// tests are exact (vertex heights by [`compare_y_filtered`], sides by [`side`]), filtered
/// by the rounded points the arrangement keeps.
///
/// Cost: O(V + E) for the strips plus the entries the queries scan, at most
/// [`SCAN_PER_EDGE`] per edge (else `None`), instead of a sweep over every vertex; for at most
/// [`DIRECT_FACE_QUERIES`] queries Q, O(E log Q) plus the queries in each edge's y range,
/// without the strips.
fn faces_left_by_strips(
    flat: &Flat,
    seg_of: impl Fn(usize) -> Segment2,
    queries: &[u32],
) -> Option<Vec<u32>> {
    faces_left_by(flat, seg_of, queries, DIRECT_FACE_QUERIES)
}

/// [`faces_left_by_strips`], looking at every edge for each query when there are at
/// most `direct_up_to` queries (tests compare both ways).
fn faces_left_by(
    flat: &Flat,
    seg_of: impl Fn(usize) -> Segment2,
    queries: &[u32],
    direct_up_to: usize,
) -> Option<Vec<u32>> {
    // (Exact and rounded points are kept in the arrangement: no copy of all vertices.)
    let point = |v: u32| flat.vertices.exact_point(v as usize);
    let rounded = |v: u32| flat.vertices.rounded(v as usize);
    let ne = flat.edge_count();
    let (mut ranges, mut xr) = (Vec::with_capacity(ne), Vec::with_capacity(ne));
    for i in 0..ne {
        let s = seg_of(i);
        ranges.push((s.a.y.min(s.b.y), s.a.y.max(s.b.y)));
        xr.push((s.a.x.min(s.b.x), s.a.x.max(s.b.x)));
    }
    let cmp_y = |a: u32, b: u32| compare_y_filtered(&point(a), &rounded(a), &point(b), &rounded(b));
    // The side of vertex v of edge i (non-horizontal); an end of the edge is on it.
    let side_of = |v: u32, i: usize| {
        let [a, b] = flat.edges[i];
        if a == v || b == v {
            return Orientation::Collinear;
        }
        let s = seg_of(i);
        let (up, low) = if s.a.y > s.b.y {
            (s.a, s.b)
        } else {
            (s.b, s.a)
        };
        side(&point(v), rounded(v).point(), up, low)
    };
    // (edge, lower end, upper end); true when c lies east of b along the line.
    let east_of = |(ci, cl, cu): (usize, u32, u32), (bi, bl, bu): (usize, u32, u32)| {
        if cl != bl {
            if cmp_y(cl, bl) != Ordering::Less {
                side_of(cl, bi) == Orientation::CounterClockwise
            } else {
                side_of(bl, ci) == Orientation::Clockwise
            }
        } else if cmp_y(cu, bu) != Ordering::Greater {
            side_of(cu, bi) == Orientation::CounterClockwise
        } else {
            side_of(bu, ci) == Orientation::Clockwise
        }
    };
    // Edge i as the candidate nearest west of query vertex q at height y, with the best
    // so far: `best` and `bound` (its carrier's x_min) updated when i crosses the line
    // west of q and east of the best.
    let consider =
        |q: u32, y: f64, i: usize, best: &mut Option<(usize, u32, u32)>, bound: &mut f64| {
            let (lo, hi) = ranges[i];
            if !(lo <= y && y < hi) {
                return; // the carrier misses the line, so does the edge
            }
            let [a, b] = flat.edges[i];
            let (l, u) = if cmp_y(a, b) == Ordering::Less {
                (a, b)
            } else {
                (b, a)
            };
            if cmp_y(l, q) == Ordering::Greater
                || cmp_y(q, u) != Ordering::Less
                || side_of(q, i) != Orientation::CounterClockwise
            {
                return;
            }
            let c = (i, l, u);
            if best.map_or(true, |b| east_of(c, b)) {
                *best = Some(c);
                *bound = xr[i].0;
            }
        };
    // The half-edge of the nearest edge running down (leaving its upper end).
    let half_edge = |best: Option<(usize, u32, u32)>| {
        best.map_or(NONE, |(i, _, u)| {
            2 * i as u32 + u32::from(flat.edges[i][0] != u)
        })
    };
    if queries.len() <= direct_up_to {
        // Few queries: every edge is looked at once, against the queries in its
        // carrier's y range (a binary search among them sorted by y), each by its
        // carrier's box first.
        let mut by_y: Vec<(Point2, usize)> = queries
            .iter()
            .enumerate()
            .map(|(k, &q)| (flat.vertices.approx(q as usize), k))
            .collect();
        by_y.sort_unstable_by(|s, t| s.0.y.total_cmp(&t.0.y));
        let mut found = vec![(None, f64::NEG_INFINITY); queries.len()];
        let (Some(&(lowest, _)), Some(&(highest, _))) = (by_y.first(), by_y.last()) else {
            return Some(Vec::new());
        };
        for (i, (&(lo, hi), &(x_min, x_max))) in ranges.iter().zip(&xr).enumerate() {
            // (Below or above every query: none of them in its range, no search.)
            if hi <= lowest.y || lo > highest.y {
                continue;
            }
            // (total_cmp orders as < does here: only -0 and 0 differ, on which `<`
            // agrees, so the predicate is monotone along `by_y`.)
            let from = by_y.partition_point(|t| t.0.y < lo);
            for &(Point2 { x, y }, k) in &by_y[from..] {
                if y >= hi {
                    break;
                }
                let (best, bound) = &mut found[k];
                // Wholly east of q's rounded point (so of q: rounding is monotone), or
                // wholly west of the best edge found: not nearer.
                if x_min > x || x_max < *bound {
                    continue;
                }
                consider(queries[k], y, i, best, bound);
            }
        }
        return Some(found.into_iter().map(|(best, _)| half_edge(best)).collect());
    }
    // The queries' scans have their own budget (below): pass no queries to the strips'.
    let strips = Strips::counted(&ranges, &[])?;
    // Each strip's entries by decreasing x_min, up to a 32-bit monotone key of it (the
    // offset from the smallest x_min, scaled to the key range; rounding and the
    // saturating cast keep the order, ties may join near values). Listed in that order
    // overall: one radix sort of the keys instead of a comparison sort per strip. The
    // queries below cut their strip with the same key, so the order needs no more than
    // that (see there).
    let x_lo = xr.iter().fold(f64::INFINITY, |m, r| m.min(r.0));
    let x_hi = xr.iter().fold(f64::NEG_INFINITY, |m, r| m.max(r.0));
    let x_scale = f64::from(u32::MAX) / (x_hi - x_lo);
    let x_scale = if x_scale.is_finite() { x_scale } else { 0.0 };
    let x_key = |x: f64| ((x - x_lo) * x_scale) as u32;
    let by_x = radix_sort(
        (0..ne as u32)
            .filter(|&i| listed(ranges[i as usize]))
            .map(|i| (!x_key(xr[i as usize].0), i))
            .collect(),
    );
    let strips = strips.fill(&ranges, by_x.iter().map(|&(_, i)| i));
    drop(by_x);
    let reach = strips.reach(&xr);
    // A long edge late in a strip (wide in x: the long side of a triangle over a field
    // of holes) keeps `reach` high for every entry before it, and the queries then scan
    // their strips edge by edge: past this budget the sweep is cheaper.
    let mut budget = SCAN_PER_EDGE * ne + 4096;
    let mut found = Vec::with_capacity(queries.len());
    for &q in queries {
        let Point2 { x, y } = flat.vertices.approx(q as usize);
        let (from, to) = strips.range(y);
        let items = &strips.list[from..to];
        // Entries by decreasing key of x_min: those with a larger key than q.x's lie
        // wholly east of q and come first (the key is monotone); the rest is tested
        // edge by edge, and `reach` bounds it whatever its order.
        let qk = x_key(x);
        let first = from + items.partition_point(|&i| x_key(xr[i as usize].0) > qk);
        let (mut best, mut bound) = (None, f64::NEG_INFINITY);
        for (&i, &far) in strips.list[first..to].iter().zip(&reach[first..to]) {
            // Every carrier from here on ends west of `bound`, which is at most the
            // best edge's x on the line: none of them is nearer.
            if far < bound {
                break;
            }
            budget = budget.checked_sub(1)?;
            consider(q, y, i as usize, &mut best, &mut bound);
        }
        found.push(half_edge(best));
    }
    Some(found)
}

/// The entries [`faces_left_by_strips`]' queries may test, per edge of the arrangement,
/// before it leaves them to the sweep.
const SCAN_PER_EDGE: usize = 8;

/// Up to this many queries, [`faces_left_by_strips`] looks at every edge for each
/// instead of building the strips (about 1.3 ns per edge and query against some 45 ns
/// per edge for the strips). GEOS-837 dissolve, session 27 (1556 edges, 38 components,
/// 20 of them inside chosen faces): asked for those 20 only and looking at every edge,
/// the whole call went from 0.461 to 0.444 ms (median of 7 alternated runs); for all
/// 38, looking at every edge was 1.6% slower than the strips.
const DIRECT_FACE_QUERIES: usize = 32;

/// Whether an item with y range `r` is listed in [`Strips`] (horizontal ones are not).
fn listed(r: (f64, f64)) -> bool {
    r.0 < r.1
}

/// `(key, item)` pairs sorted by key, equal keys in their given order: a stable
/// least-significant-digit radix sort by bytes, skipping a byte that all keys share.
/// O(n) (four passes at most), where a comparison sort costs O(n log n).
fn radix_sort(mut v: Vec<(u32, u32)>) -> Vec<(u32, u32)> {
    let mut counts = [[0u32; 256]; 4];
    for &(k, _) in &v {
        for (d, c) in counts.iter_mut().enumerate() {
            c[(k >> (8 * d)) as usize & 255] += 1;
        }
    }
    let mut buf = vec![(0, 0); v.len()];
    for (d, c) in counts.iter_mut().enumerate() {
        if c.iter().any(|&x| x as usize == v.len()) {
            continue; // one value of this byte: the pass would keep the order
        }
        let mut sum = 0;
        for x in c.iter_mut() {
            sum += std::mem::replace(x, sum);
        }
        for &(k, i) in &v {
            let slot = &mut c[(k >> (8 * d)) as usize & 255];
            buf[*slot as usize] = (k, i);
            *slot += 1;
        }
        std::mem::swap(&mut v, &mut buf);
    }
    v
}

/// Items listed by horizontal strips: item `i` with `ranges[i] = (y_min, y_max)` (only
/// those with `y_min < y_max`) is in every strip its closed y range meets. The strip of a
/// y value is a monotone function of it (rounding is monotone), so every item whose
/// closed range holds y is in y's strip.
struct Strips {
    steps: Steps,
    count: usize,
    start: Vec<u32>,
    list: Vec<u32>,
}

impl Strips {
    /// The strips for the queries at heights `ys`, or `None` when listing or scanning
    /// would do too much work (more than 8n + 4096 entries, or than 4n + 4096 entries
    /// scanned by the queries, for n items) or the y range is too small to cut. (The
    /// winding counts scan whole strips; past that budget the x-sorted nearest-edge
    /// search of [`faces_left_by_strips`], a few tests per query, is cheaper: on a real
    /// map with 1.7 k components and ~150 edges per strip it is.)
    fn new(ranges: &[(f64, f64)], ys: &[f64]) -> Option<Strips> {
        let listed = (0..ranges.len() as u32).filter(|&i| listed(ranges[i as usize]));
        Some(Strips::counted(ranges, ys)?.fill(ranges, listed))
    }

    /// [`Strips::new`] with the strip sizes counted and the lists not yet filled.
    fn counted(ranges: &[(f64, f64)], ys: &[f64]) -> Option<Strips> {
        let n = ranges.len();
        let listed = |&r: &&(f64, f64)| listed(*r);
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        let mut heights = 0.0;
        for r in ranges.iter().filter(listed) {
            lo = lo.min(r.0);
            hi = hi.max(r.1);
            heights += r.1 - r.0;
        }
        if lo > hi {
            // Nothing listed (all items horizontal).
            return Some(Strips {
                steps: Steps::per_unit(0.0, 0.0, 1),
                count: 1,
                start: vec![0, 0],
                list: Vec::new(),
            });
        }
        // As many strips as keep the items' spans near one strip each on average (the
        // count is a heuristic; correctness does not depend on it).
        let count = (n as f64 / (heights / (hi - lo)).max(1.0)).clamp(1.0, 65536.0) as usize;
        let scale = count as f64 / (hi - lo);
        if !(scale.is_finite() && scale > 0.0) {
            return None;
        }
        let mut strips = Strips {
            steps: Steps::per_unit(lo, scale, count as u32),
            count,
            start: vec![0u32; count + 1],
            list: Vec::new(),
        };
        let mut total = 0usize;
        for r in ranges.iter().filter(listed) {
            let (a, b) = (strips.strip(r.0), strips.strip(r.1));
            total += b - a + 1;
            if total > 8 * n + 4096 {
                return None;
            }
            for c in &mut strips.start[a + 1..=b + 1] {
                *c += 1;
            }
        }
        // (start[k + 1] holds the count of strip k here.)
        let work: usize = ys
            .iter()
            .map(|&y| strips.start[strips.strip(y) + 1] as usize)
            .sum();
        if work > 4 * n + 4096 {
            return None;
        }
        for k in 0..count {
            strips.start[k + 1] += strips.start[k];
        }
        strips.list = Vec::with_capacity(total);
        Some(strips)
    }

    /// The strips of [`Strips::counted`] with their items listed in the order of `order`
    /// (a permutation of the listed items, i.e. of those with `y_min < y_max`): each
    /// strip's list is then in that order too.
    fn fill(mut self, ranges: &[(f64, f64)], order: impl Iterator<Item = u32>) -> Strips {
        let total = self.list.capacity();
        let mut fill = self.start.clone();
        self.list.resize(total, 0);
        for i in order {
            let r = ranges[i as usize];
            let (a, b) = (self.strip(r.0), self.strip(r.1));
            for f in &mut fill[a..=b] {
                self.list[*f as usize] = i;
                *f += 1;
            }
        }
        debug_assert!(fill[..self.count] == self.start[1..]);
        self
    }

    /// For each list entry, the largest `xr[i].1` (x_max) from it to the end of its strip.
    fn reach(&self, xr: &[(f64, f64)]) -> Vec<f64> {
        let mut reach = vec![f64::NEG_INFINITY; self.list.len()];
        for k in 0..self.count {
            let (a, b) = (self.start[k] as usize, self.start[k + 1] as usize);
            let mut m = f64::NEG_INFINITY;
            for e in (a..b).rev() {
                m = m.max(xr[self.list[e] as usize].1);
                reach[e] = m;
            }
        }
        reach
    }

    /// The list range of the strip of `y`.
    fn range(&self, y: f64) -> (usize, usize) {
        let k = self.strip(y);
        (self.start[k] as usize, self.start[k + 1] as usize)
    }

    fn strip(&self, y: f64) -> usize {
        self.steps.index(y)
    }

    /// The items whose closed y range may hold `y` (all those that do, and others).
    fn items(&self, y: f64) -> &[u32] {
        let (a, b) = self.range(y);
        &self.list[a..b]
    }
}

#[cfg(test)]
mod tests {
    use super::super::boolean::{boolean_via_dcel, boolean_with, oriented_segments};
    use super::super::{BooleanOp, BooleanOptions, FillRule};
    use super::{near_context, sort_by_angle, sort_by_keys, Carrier, Orientation};
    use crate::kernel::{MultiPolygon, Point2, Polygon, Segment2};
    use proptest::prelude::*;
    use std::cmp::Ordering;

    /// The context polygons a re-union looks at: those touching, overlapping or within
    /// a few floats of the new segments' box; not those a little further.
    #[test]
    fn near_context_keeps_what_may_touch_or_come_near() {
        // The rectangle [x, x + w] × [y, y + w] scaled by (sx, sy), and its sides.
        let rect = |x: f64, y: f64, w: f64, (sx, sy): (f64, f64)| {
            Polygon::new(
                vec![
                    Point2::new(x * sx, y * sy),
                    Point2::new((x + w) * sx, y * sy),
                    Point2::new((x + w) * sx, (y + w) * sy),
                    Point2::new(x * sx, (y + w) * sy),
                ],
                vec![],
            )
        };
        let sides = |p: &Polygon| -> Vec<Segment2> {
            let ring = &p.exterior;
            (0..4)
                .map(|k| Segment2::new(ring[k], ring[(k + 1) % 4]))
                .collect()
        };
        let square = |x: f64, y: f64, w: f64| rect(x, y, w, (1.0, 1.0));
        let segs = sides(&square(0.0, 0.0, 1.0));
        let ulp = f64::EPSILON;
        let context = [
            square(2.0, 2.0, 1.0),               // far
            square(1.0, 1.0, 1.0),               // touches a corner
            square(0.25, 0.25, 0.5),             // inside
            square(1.0 + 4.0 * ulp, 0.0, 1.0),   // four floats right
            square(1.0 + 1e-9, 0.0, 1.0),        // a little further
            square(-3.0, -3.0, 3.0 - 8.0 * ulp), // eight ulps of 1 below-left
            square(-5.0, 0.0, 9.0),              // around it all
        ];
        assert_eq!(near_context(&segs, &context), [1, 2, 3, 5, 6]);
        // Few context polygons: all of them, without a look.
        assert_eq!(near_context(&segs, &context[..4]), [0, 1, 2, 3]);
        // At other scales (huge, subnormal, and x and y of very different sizes): a
        // box 16 floats right of the segments' box is kept, one a millionth of its size
        // away is not (five far ones make the look happen); subnormal, all are kept.
        for (sx, sy) in [
            (1e300, 1e300),
            (1e-310, 1e-310),
            (1e300, 1e-300),
            (1e-300, 1e300),
        ] {
            let segs = sides(&rect(0.0, 0.0, 1.0, (sx, sy)));
            let mut right = 1.0 * sx;
            for _ in 0..16 {
                right = right.next_up();
            }
            let mut context: Vec<Polygon> = (0..5)
                .map(|k| rect(5.0 + k as f64, 5.0, 1.0, (sx, sy)))
                .collect();
            context.push(Polygon::new(
                vec![
                    Point2::new(right, 0.0),
                    Point2::new(2.0 * sx, 0.0),
                    Point2::new(2.0 * sx, sy),
                ],
                vec![],
            ));
            context.push(rect(1.000001, 0.0, 1.0, (sx, sy)));
            // (Below the normal range the widening, the smallest normal, holds them all;
            // it is taken from the largest coordinate on either axis, so a tiny x range
            // next to huge y values is widened by far more than its own floats.)
            let want: Vec<usize> = if sx < f64::MIN_POSITIVE {
                (0..7).collect()
            } else if sx < sy {
                vec![5, 6]
            } else {
                vec![5]
            };
            assert_eq!(near_context(&segs, &context), want, "{sx} {sy}");
        }
    }

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

    /// A ring up to its start vertex (orientation kept: it is part of the answer): its
    /// least rotation, so that a ring through one rounded point twice (two exact
    /// vertices rounded alike) has one key whatever its start.
    fn ring_key(r: &[Point2]) -> Vec<Key> {
        let k: Vec<Key> = r.iter().map(|&p| key(p)).collect();
        (0..k.len())
            .map(|s| k[s..].iter().chain(&k[..s]).copied().collect::<Vec<Key>>())
            .min()
            .unwrap_or_default()
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

    /// Per polygon its rings' point counts (shell first, holes sorted), polygons sorted.
    fn ring_sizes(m: &MultiPolygon) -> Vec<Vec<usize>> {
        let mut v: Vec<Vec<usize>> =
            m.0.iter()
                .map(|p| {
                    let mut holes: Vec<usize> = p.holes.iter().map(|h| h.len()).collect();
                    holes.sort_unstable();
                    std::iter::once(p.exterior.len()).chain(holes).collect()
                })
                .collect();
        v.sort();
        v
    }

    /// `m` without the points strictly inside the segment between the points kept
    /// before and after them that no other ring has: the rule the traced path applies
    /// after rounding (the DCEL path only rounds), written plainly.
    fn without_straight(m: &MultiPolygon) -> MultiPolygon {
        let mut uses = std::collections::HashMap::new();
        for &q in m.0.iter().flat_map(|p| p.rings()).flatten() {
            *uses.entry(key(q)).or_insert(0) += 1;
        }
        let inside = |p: Point2, q: Point2, r: Point2| {
            let between = |a: f64, b: f64, c: f64| a.min(c) <= b && b <= a.max(c);
            q != p
                && q != r
                && between(p.x, q.x, r.x)
                && between(p.y, q.y, r.y)
                && crate::kernel::orient2d(p, q, r) == Orientation::Collinear
        };
        let ring = |r: &Vec<Point2>| {
            let n = r.len();
            let low = (0..n)
                .min_by(|&i, &j| crate::kernel::compare_xy(r[i], r[j]))
                .unwrap();
            let at = |k: usize| r[(low + k) % n];
            let mut kept = vec![at(0)];
            for k in 1..n {
                let (p, q) = (*kept.last().unwrap(), at(k));
                if !(uses[&key(q)] == 1 && inside(p, q, at(k + 1))) {
                    kept.push(q);
                }
            }
            if kept.len() < 3 {
                r.clone()
            } else {
                kept
            }
        };
        MultiPolygon(
            m.0.iter()
                .map(|p| Polygon::new(ring(&p.exterior), p.holes.iter().map(ring).collect()))
                .collect(),
        )
    }

    /// Every point of `a` is within one float per axis of a point of `b`.
    fn within_a_float(a: &MultiPolygon, b: &MultiPolygon) -> bool {
        let points: std::collections::HashSet<Key> =
            b.0.iter()
                .flat_map(|p| p.rings())
                .flatten()
                .map(|&q| key(q))
                .collect();
        let around = |v: f64| [v.next_down(), v, v.next_up()];
        a.0.iter().flat_map(|p| p.rings()).flatten().all(|q| {
            around(q.x).iter().any(|&x| {
                around(q.y)
                    .iter()
                    .any(|&y| points.contains(&key(Point2::new(x, y))))
            })
        })
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
                    let rounded = boolean_via_dcel(a, b, op, &opts).unwrap();
                    let slow = if keep_collinear {
                        rounded.clone()
                    } else {
                        without_straight(&rounded)
                    };
                    let (segs, na) = oriented_segments(a, b, rule).unwrap();
                    let inside = |wa, wb| op.apply(rule.inside(wa), rule.inside(wb));
                    let unflagged = |t: super::Traced| {
                        let kept = t.polygons.iter().all(|(_, suspect)| !suspect);
                        let polygons = t.polygons.into_iter().map(|(p, _)| p).collect();
                        (
                            MultiPolygon(polygons),
                            kept,
                            t.nudged,
                            MultiPolygon(t.undropped),
                        )
                    };
                    let (swept, _, _, _) = unflagged(
                        super::traced(&segs, na, inside, keep_collinear, false, &[]).unwrap(),
                    );
                    let (traced, kept, nudged, undropped) = unflagged(
                        super::traced(&segs, na, inside, keep_collinear, true, &[]).unwrap(),
                    );
                    // (Both check the same rings, and move the same points.)
                    prop_assert_eq!(canonical(&swept), canonical(&traced));
                    // The result is its rounded rings without the points left straight
                    // (the rule written plainly above).
                    let straightened = if keep_collinear {
                        undropped.clone()
                    } else {
                        without_straight(&undropped)
                    };
                    prop_assert_eq!(canonical(&traced), canonical(&straightened));
                    // The DCEL path rounds to nearest; the check may have moved points
                    // to other floats around their exact ones: then the rounded rings
                    // are the same rings, point for point, each within a float of the
                    // DCEL path's per axis (their straight points can differ: a moved
                    // point may go straight where its nearest float does not).
                    if nudged == 0 {
                        prop_assert_eq!(
                            canonical(&traced),
                            canonical(&slow),
                            "{:?} {:?} keep {}",
                            op,
                            rule,
                            keep_collinear
                        );
                    } else {
                        prop_assert_eq!(ring_sizes(&undropped), ring_sizes(&rounded));
                        prop_assert!(within_a_float(&undropped, &rounded));
                        prop_assert!(within_a_float(&rounded, &undropped));
                    }
                    // Unless rounding may have broken it (then it was united again, and
                    // must be valid), the result is the traced one.
                    if kept {
                        prop_assert_eq!(canonical(&fast), canonical(&traced));
                    }
                    if !kept || nudged > 0 {
                        let problems = crate::overlay::validity_problems(&fast).unwrap();
                        prop_assert!(problems.is_empty(), "{:?}", problems);
                    }
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

    /// A hole thinner than the rounding: the square with a triangular hole H, united
    /// with a dart B covering H but for a sliver between H's bottom side and B's apex
    /// just above it. The exact union is the square with that sliver as its hole; the
    /// sliver's crossings round so that it keeps two points. It is dropped, and the
    /// square is not flagged for a second union (nothing else moved); and every such
    /// union, the apex a few floats above or below the side, comes out valid.
    #[test]
    fn a_ring_rounded_to_two_points_is_dropped_without_a_second_union() {
        let f = Point2::new;
        let square = vec![
            f(-10.0, -10.0),
            f(10.0, -10.0),
            f(10.0, 10.0),
            f(-10.0, 10.0),
        ];
        let hole = vec![f(0.0, 0.0), f(0.677, 1.241), f(1.433, 0.09160000000000001)];
        let dart = |apex: Point2| {
            vec![
                f(apex.x - 3.319, -0.80391992),
                apex,
                f(apex.x + 3.319, -1.46891992),
                f(apex.x + 0.304, 5.0),
            ]
        };
        let a = MultiPolygon(vec![Polygon::new(square.clone(), vec![hole.clone()])]);
        let b = MultiPolygon(vec![Polygon::new(
            vec![
                f(-2.9266446, -0.80391992),
                f(0.3923554, 0.025080080000000008),
                f(3.7113554, -1.46891992),
                f(0.6963554000000001, 5.0),
            ],
            vec![],
        )]);
        let (segs, na) = oriented_segments(&a, &b, FillRule::EvenOdd).unwrap();
        let t = super::traced(
            &segs,
            na,
            |wa, wb| wa % 2 != 0 || wb % 2 != 0,
            false,
            true,
            &[],
        )
        .unwrap();
        assert_eq!(t.polygons.len(), 1);
        let (polygon, suspect) = &t.polygons[0];
        assert!(!suspect, "flagged for a second union");
        assert_eq!((&polygon.exterior, polygon.holes.len()), (&square, 0));
        let union = boolean_with(&a, &b, BooleanOp::Union, &BooleanOptions::default()).unwrap();
        assert_eq!(union, MultiPolygon(vec![polygon.clone()]));
        // The apex on the side's line at nine x, moved up to four floats either way.
        for i in 1..10 {
            let s = f64::from(i) / 10.0;
            let on_side = f(1.433 * s, 0.09160000000000001 * s);
            let mut apex = on_side;
            for _ in 0..4 {
                apex.y = apex.y.next_down();
            }
            for _ in 0..9 {
                let b = MultiPolygon(vec![Polygon::new(dart(apex), vec![])]);
                let union =
                    boolean_with(&a, &b, BooleanOp::Union, &BooleanOptions::default()).unwrap();
                let problems = crate::overlay::validity_problems(&union).unwrap();
                assert!(problems.is_empty(), "{apex:?}: {problems:?}");
                apex.y = apex.y.next_up();
            }
        }
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

    /// Nested islands: at each centre, diamonds of radius r, r − 1, …, each odd level a
    /// hole of the one around it and each even level a new polygon (an island in a lake
    /// in an island …), optionally a triangle tilted off the axes; translated by
    /// `shift` (grid, half-grid, thirds: crossings off the grid, shared vertices, shared
    /// edges, vertices of one map on edges of the other).
    fn nested_set(cells: &[(i32, i32, i32, bool)], shift: (f64, f64)) -> MultiPolygon {
        let diamond = |cx: f64, cy: f64, r: f64, tilt: bool| {
            let mut v = vec![
                Point2::new(cx + r, cy),
                Point2::new(cx, cy + r),
                Point2::new(cx - r, cy),
                Point2::new(cx, cy - r),
            ];
            if tilt {
                v.remove(1);
            }
            v
        };
        let mut polys = Vec::new();
        for &(x, y, levels, tilt) in cells {
            let (cx, cy) = (f64::from(4 * x) + shift.0, f64::from(4 * y) + shift.1);
            let mut r = f64::from(levels);
            while r > 0.0 {
                let hole = (r > 1.0).then(|| diamond(cx, cy, r - 1.0, tilt));
                polys.push(Polygon::new(
                    diamond(cx, cy, r, tilt),
                    hole.into_iter().collect(),
                ));
                r -= 2.0;
            }
        }
        MultiPolygon(polys)
    }

    /// Holes in rows beside a long edge (a field of square holes and a triangle whose
    /// long side crosses every strip): that edge comes last in each strip of the
    /// nearest-edge search and keeps every query scanning its strip, so the search gives
    /// up past its budget and the hole sweep labels the components; the results agree.
    #[test]
    fn holes_beside_a_long_edge_agree() {
        let f = |x: f64, y: f64| Point2::new(x, y);
        let k = 50;
        let side = f64::from(2 * k + 1);
        let holes: Vec<Vec<Point2>> = (0..k * k)
            .map(|h| {
                let (x, y) = (f64::from(2 * (h % k) + 1), f64::from(2 * (h / k) + 1));
                vec![f(x, y), f(x, y + 1.0), f(x + 1.0, y + 1.0), f(x + 1.0, y)]
            })
            .collect();
        let corners: Vec<Point2> = holes.iter().map(|h| h[0]).collect();
        let field = vec![f(0.0, 0.0), f(side, 0.0), f(side, side), f(0.0, side)];
        let a = MultiPolygon(vec![Polygon::new(field, holes)]);
        let triangle = vec![f(0.5, 0.25), f(side - 0.25, 0.75), f(0.75, side - 0.5)];
        let b = MultiPolygon(vec![Polygon::new(triangle, vec![])]);
        let (segs, _) = oriented_segments(&a, &b, FillRule::EvenOdd).unwrap();
        // (The holes' lowest corners: the components' smallest vertices.)
        assert!(
            !nearest_edges_within_budget(&segs, &corners),
            "the nearest-edge search should be over budget here"
        );
        agree(&a, &b).unwrap();
    }

    /// Many components deep in one another's strips (slanted bars side by side, each with
    /// a hole holding an island): the winding counts are over budget, so the labels come
    /// from the nearest-edge search ([`super::faces_left_by_strips`]) alone.
    #[test]
    fn many_components_in_deep_strips_agree() {
        let f = |x: f64, y: f64| Point2::new(x, y);
        let bars = |dx: f64, dy: f64| {
            let mut v = Vec::new();
            for i in 0..120 {
                let x = 2.0 * f64::from(i) + dx;
                v.push(Polygon::new(
                    vec![
                        f(x, dy),
                        f(x + 1.5, dy),
                        f(x + 1.75, 60.0 + dy),
                        f(x + 0.25, 60.0 + dy),
                    ],
                    vec![vec![
                        f(x + 0.3, 10.0 + dy),
                        f(x + 0.6, 50.0 + dy),
                        f(x + 1.2, 10.0 + dy),
                    ]],
                ));
                v.push(Polygon::new(
                    vec![
                        f(x + 0.5, 15.0 + dy),
                        f(x + 0.9, 15.0 + dy),
                        f(x + 0.6, 30.0 + dy),
                    ],
                    vec![],
                ));
            }
            MultiPolygon(v)
        };
        let (a, b) = (bars(0.0, 0.0), bars(0.5, 1.0 / 3.0));
        let (segs, _) = oriented_segments(&a, &b, FillRule::EvenOdd).unwrap();
        let low: Vec<Point2> = [a.0.clone(), b.0.clone()]
            .concat()
            .iter()
            .map(|p| p.exterior[0])
            .collect();
        assert!(
            super::windings_left_of(&segs, 0, &low).is_none(),
            "the winding strips should be over budget here"
        );
        // (The components' smallest vertices: each ring's first point here.)
        let firsts: Vec<Point2> = [a.0.clone(), b.0.clone()]
            .concat()
            .iter()
            .flat_map(|p| p.rings().map(|r| r[0]).collect::<Vec<_>>())
            .collect();
        assert!(
            nearest_edges_within_budget(&segs, &firsts),
            "the nearest-edge search should be within its budget here"
        );
        agree(&a, &b).unwrap();
    }

    /// Whether the strips' nearest-edge search answers (within its budget) for the
    /// vertices of the arrangement of `segs` at `points` (each point a vertex).
    fn nearest_edges_within_budget(segs: &[Segment2], points: &[Point2]) -> bool {
        let flat = crate::dcel::Flat::of_segments(segs).unwrap();
        let seg_of = |i: usize| segs[flat.sources_of(i)[0].segment];
        let queries: Vec<u32> = (0..flat.vertices.len() as u32)
            .filter(|&v| points.contains(&flat.vertices.approx(v as usize)))
            .collect();
        assert_eq!(queries.len(), points.len());
        super::faces_left_by(&flat, seg_of, &queries, 0).is_some()
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(300))]

        /// The filtered keys give the exact angular order whenever they decide: on
        /// directions with small integer and with huge or tiny float coordinates, nearly
        /// collinear ones (one ulp apart) and overflowing differences.
        #[test]
        fn key_sort_is_the_exact_angular_sort(
            v in proptest::collection::vec(
                (-4i32..5, -4i32..5, -3i32..4, 0u8..4, 0u32..3), 5..12),
        ) {
            let mut segs: Vec<Segment2> = Vec::new();
            for &(x, y, e, kind, ulps) in &v {
                let scale = [1.0, 1e300, 1e-300, 1.0][kind as usize] * 2f64.powi(e);
                let (mut bx, by) = (x as f64 * scale, y as f64 * scale);
                if kind == 3 {
                    for _ in 0..ulps {
                        bx = f64::from_bits(bx.to_bits() + 1);
                    }
                }
                // (Kind 1 with even x: ends far apart, some differences overflow.)
                let s = if kind == 1 && x % 2 == 0 {
                    let a = Point2::new(-1.7e308, 1.6e308);
                    Segment2::new(a, Point2::new(x as f64 * 4e307, y as f64 * -4e307))
                } else {
                    let a = Point2::new(0.5, -0.25);
                    Segment2::new(a, Point2::new(a.x + bx, a.y + by))
                };
                let dup = segs.iter().any(|t| {
                    let c = |s: &Segment2| Carrier { seg: *s, forward: true };
                    c(t).turn(&c(&s)) == Orientation::Collinear
                        && c(t).angle_cmp(&c(&s)) == Ordering::Equal
                });
                if !s.is_degenerate() && !dup {
                    segs.push(s);
                }
            }
            proptest::prop_assume!(segs.len() > 2);
            let carrier = |h: u32| Carrier { seg: segs[h as usize], forward: true };
            let dir = |h: u32| {
                let s = segs[h as usize];
                (s.b.x - s.a.x, s.b.y - s.a.y)
            };
            let mut exact: Vec<u32> = (0..segs.len() as u32).collect();
            sort_by_angle(&mut exact, &mut Vec::new(), carrier);
            let mut keyed: Vec<u32> = (0..segs.len() as u32).rev().collect();
            if sort_by_keys(&mut keyed, dir) {
                proptest::prop_assert_eq!(keyed, exact);
            }
        }

        #[test]
        fn radix_sort_is_the_stable_sort(
            keys in prop::collection::vec(any::<u32>(), 0..600),
            mask in prop::sample::select(vec![u32::MAX, 0, 0xff, 0xff00_00ff, 0x0f0f_0000, 3]),
        ) {
            // Full-range keys, all equal, few distinct, bytes shared by all.
            let v: Vec<(u32, u32)> = keys.iter().enumerate().map(|(i, &k)| (k & mask, i as u32)).collect();
            let mut want = v.clone();
            want.sort_by_key(|&(k, _)| k);
            prop_assert_eq!(super::radix_sort(v), want);
        }

        #[test]
        fn nearest_edges_west_by_strips_are_the_direct_ones(
            ends in prop::collection::vec((0..8i32, 0..8i32, 0..8i32, 0..8i32), 1..40),
            scale in prop::sample::select(vec![1.0, 1.0 / 3.0, 1e-300, -0.5]),
        ) {
            // Grid segments (crossings at constructed points, overlaps, T-junctions),
            // every vertex of their arrangement a query.
            let f = |v: i32| f64::from(v) * scale;
            let segs: Vec<Segment2> = ends
                .iter()
                .map(|&(a, b, c, d)| Segment2::new(Point2::new(f(a), f(b)), Point2::new(f(c), f(d))))
                .collect();
            let flat = crate::dcel::Flat::of_segments(&segs).unwrap();
            let seg_of = |i: usize| segs[flat.sources_of(i)[0].segment];
            let queries: Vec<u32> = (0..flat.vertices.len() as u32).collect();
            let direct = super::faces_left_by(&flat, seg_of, &queries, usize::MAX);
            prop_assert!(direct.is_some());
            if let Some(strips) = super::faces_left_by(&flat, seg_of, &queries, 0) {
                prop_assert_eq!(direct.unwrap(), strips);
            }
        }

        #[test]
        fn winding_counts_by_strips_are_the_direct_counts(
            segs in prop::collection::vec((0..6i32, 0..6i32, 0..6i32, 0..6i32), 1..40),
            queries in prop::collection::vec((0..6i32, 0..6i32), 1..12),
            na in 0..40usize,
            scale in prop::sample::select(vec![1.0, 1e-300, 1e300, -0.5]),
        ) {
            // Grid segments (horizontal, vertical, collinear, repeated, zero-length) and
            // queries on their ends and lines; huge and tiny scales.
            let f = |x: i32| f64::from(x) * scale;
            let segs: Vec<Segment2> = segs
                .iter()
                .map(|&(a, b, c, d)| Segment2::new(Point2::new(f(a), f(b)), Point2::new(f(c), f(d))))
                .collect();
            let queries: Vec<Point2> = queries.iter().map(|&(x, y)| Point2::new(f(x), f(y))).collect();
            use super::Windings;
            let direct = super::windings_left_of_by(&segs, na, &queries, Windings::Direct);
            prop_assert!(direct.is_some());
            if let Some(sorted) = super::windings_left_of_by(&segs, na, &queries, Windings::Sorted) {
                prop_assert_eq!(direct.as_ref(), Some(&sorted));
            }
            if let Some(strips) = super::windings_left_of_by(&segs, na, &queries, Windings::Strips) {
                prop_assert_eq!(direct.unwrap(), strips);
            }
        }

        #[test]
        fn traced_path_agrees_on_nested_islands(
            cells in prop::collection::vec((0..3i32, 0..3i32, 1..6i32, any::<bool>()), 1..5),
            other in prop::collection::vec((0..3i32, 0..3i32, 1..6i32, any::<bool>()), 0..4),
            sx in 0..4usize,
            sy in 0..4usize,
        ) {
            let steps = [0.0, 1.0, 0.5, 1.0 / 3.0];
            let a = nested_set(&cells, (0.0, 0.0));
            let mut b = nested_set(&cells, (steps[sx], steps[sy]));
            b.0.extend(nested_set(&other, (steps[sy], 0.0)).0);
            agree(&a, &b)?;
            agree(&b, &a)?;
        }

        #[test]
        fn traced_path_agrees_on_tiny_islands_beside_a_far_square(
            cells in prop::collection::vec((0..3i32, 0..3i32, 1..6i32, any::<bool>()), 1..4),
            sx in 0..4usize,
        ) {
            // The islands span ~1e-8 beside a square 1e3 away: the strips' 32-bit x keys
            // of nearby edges coincide, so ties of the key hold edges on both sides of a
            // query.
            let steps = [0.0, 1.0, 0.5, 1.0 / 3.0];
            let tiny = |m: MultiPolygon| {
                let f = |r: &Vec<Point2>| r.iter().map(|q| Point2::new(q.x * 1e-9, q.y * 1e-9)).collect();
                let far = Polygon::new(vec![p(1000, 1000), p(1001, 1000), p(1001, 1001)], vec![]);
                let mut v: Vec<Polygon> = m.0.iter().map(|g| Polygon::new(f(&g.exterior), g.holes.iter().map(f).collect())).collect();
                v.push(far);
                MultiPolygon(v)
            };
            let a = tiny(nested_set(&cells, (0.0, 0.0)));
            let b = tiny(nested_set(&cells, (steps[sx], 0.5)));
            agree(&a, &b)?;
        }

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
        fn traced_path_agrees_on_triangulated_coverages(
            cells in prop::collection::vec((0..4i32, 0..4i32, any::<bool>(), 0..4u8, any::<bool>()), 1..24),
            step in prop::sample::select(vec![1.0, 0.1, 1.0 / 3.0]),
        ) {
            // Grid cells cut by a diagonal into two triangles: neighbouring triangles share
            // their sides (diagonal ones too, so the noding, not the axis-parallel path,
            // builds the arrangement), run the other way, the sides whose contributions
            // cancel. Each triangle goes to A, to B, to both, or to neither; some turned
            // clockwise (same-way sides, which do not cancel).
            let q = |x: i32, y: i32| Point2::new(f64::from(x) * step, f64::from(y) * step);
            let (mut a, mut b) = (Vec::new(), Vec::new());
            for &(x, y, rising, to, turned) in &cells {
                let (p00, p10, p11, p01) = (q(x, y), q(x + 1, y), q(x + 1, y + 1), q(x, y + 1));
                let halves = if rising {
                    [vec![p00, p10, p11], vec![p00, p11, p01]]
                } else {
                    [vec![p00, p10, p01], vec![p10, p11, p01]]
                };
                for (k, mut ring) in halves.into_iter().enumerate() {
                    if turned && k == 0 {
                        ring.reverse();
                    }
                    let t = Polygon::new(ring, vec![]);
                    if to & 1 != 0 {
                        a.push(t.clone());
                    }
                    if to & 2 != 0 {
                        b.push(t);
                    }
                }
            }
            let (a, b) = (MultiPolygon(a), MultiPolygon(b));
            agree(&a, &b)?;
            agree(&a, &MultiPolygon::default())?;
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
