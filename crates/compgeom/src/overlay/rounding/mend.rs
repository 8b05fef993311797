//! Mending the pairs that fail the rounding check (see the parent module): a crossing
//! may take any float point around its exact one, not only the nearest.

use super::{down, passes, up, ExactPoints, ExactSides, Pair, PointIds, RoundedRings, Toward};
use crate::kernel::{Orientation, Point2};
use std::cmp::Ordering;

/// Moves the points of failing pairs to other floats around their exact points where
/// that makes the pair pass and no other pair fail; `failing` keeps the pairs that still
/// fail.
///
/// A moved vertex `v` of a failing pair (the pair's point or an end of its edge, not one
/// standing for a collapsed edge) may take any float point within one float of its
/// rounded point per axis on the exact point's side (the corners of the float box the
/// exact point is in), at all its points at once (rings touching at it stay touching).
/// Such a point is within the reach [`super::reach`] gives a moved point, so the module's
/// argument holds for it as for the nearest one; the pairs near its points are found
/// again (`near_pairs` made its boxes wide enough) and decided with it. Where the exact
/// vertex is on the wrong side of a line through a rounded edge, one of these corners is
/// on its side (the exact point is a convex combination of them, and the side is
/// linear in each end), so a pair that fails on a side flip with only one of its points
/// moved can be made to pass alone; a pair whose exact vertex is on the edge's line
/// cannot. One vertex is moved at a time, so a pair whose mend needs two of its points
/// moved together is not mended (its polygons are united again; a random search of
/// points within a few floats of each other found that for about 0.7% of failing
/// pairs, none on the JTS suites). Pairs are taken in the order of their exact vertices, their vertices in a
/// fixed order (the point, then the edge's ends) and each vertex's candidates too, so
/// the result does not depend on how the arrangement numbered things.
pub(super) fn nudge(
    r: &mut RoundedRings,
    pairs: &[Pair],
    failing: &mut Vec<usize>,
    sides: &mut ExactSides<impl Fn(u32, u32, u32) -> Orientation>,
    exact: &ExactPoints<impl Fn(u32, Point2) -> Toward, impl Fn(u32, u32) -> Ordering>,
) {
    let toward = &exact.toward;
    let ends = |&(x, e): &Pair| {
        let (x, i, j) = (x as usize, e.i, e.j);
        [
            Some(x),
            (i != x).then_some(i),
            (j != x && j != i).then_some(j),
        ]
    };
    // The places of the failing pairs' moved points: the vertices a point stands for.
    // A place moves as one, at all its points (rings touching at it stay touching).
    type Place = (u32, u32);
    let place = |id: PointIds| (id.enter, id.leave);
    let mut places: Vec<Place> = failing
        .iter()
        .flat_map(|&k| ends(&pairs[k]).into_iter().flatten())
        .map(|i| r.ids[i])
        .filter(|id| id.moved)
        .map(place)
        .collect();
    places.sort_unstable();
    places.dedup();
    // A place is not moved where one of its vertices is elsewhere on a point standing
    // for others too (a vertex in two places: neither).
    let mut kept_whole = vec![true; places.len()];
    // (Per vertex number, its place: a hash per point would cost more than the rest.)
    let top = r
        .ids
        .iter()
        .map(|id| id.enter.max(id.leave))
        .max()
        .unwrap_or(0);
    let mut place_of = vec![NONE; top as usize + 1];
    for (k, &(enter, leave)) in places.iter().enumerate() {
        for v in [enter, leave] {
            match place_of[v as usize] {
                NONE => place_of[v as usize] = k as u32,
                other if other != k as u32 => {
                    (kept_whole[other as usize], kept_whole[k]) = (false, false);
                }
                _ => {}
            }
        }
    }
    // The points of each place, as (place, point) in increasing order.
    let mut members: Vec<(u32, u32)> = Vec::new();
    for (i, &id) in r.ids.iter().enumerate() {
        let mut seen = NONE;
        for v in [id.enter, id.leave] {
            let at = place_of[v as usize];
            if at == NONE || at == seen {
                continue;
            }
            seen = at;
            if place(id) == places[at as usize] {
                members.push((at, i as u32));
            } else {
                kept_whole[at as usize] = false;
            }
        }
    }
    members.retain(|&(at, _)| kept_whole[at as usize]);
    if members.is_empty() {
        // (No point may move: the failing pairs stay as they are.)
        return;
    }
    members.sort_unstable();
    let points_of = |at: u32| run_of(&members, at);
    // The pairs at each point that may move (as the point or an end of the edge), as
    // (point, pair) in increasing order.
    let mut movable_points: Vec<u32> = members.iter().map(|&(_, i)| i).collect();
    movable_points.sort_unstable();
    let mut incident: Vec<(u32, u32)> = Vec::new();
    for (k, pair) in pairs.iter().enumerate() {
        for i in ends(pair).into_iter().flatten() {
            if movable_points.binary_search(&(i as u32)).is_ok() {
                incident.push((i as u32, k as u32));
            }
        }
    }
    incident.sort_unstable();
    let pairs_at = |i: u32| run_of(&incident, i).iter().map(|&(_, k)| k as usize);
    // In the order of the pairs' exact vertices (the point's, the edge's ends).
    let mut order = failing.clone();
    order.sort_by(|&k, &l| {
        let vertices = |(x, e): Pair| [r.ids[x as usize].enter, e.a, e.b];
        let (a, b) = (vertices(pairs[k]), vertices(pairs[l]));
        a.iter()
            .zip(&b)
            .map(|(&u, &v)| {
                if u == v {
                    Ordering::Equal
                } else {
                    (exact.order)(u, v)
                }
            })
            .find(|o| o.is_ne())
            .unwrap_or(Ordering::Equal)
    });
    let mut fails: Vec<bool> = vec![false; pairs.len()];
    for &k in failing.iter() {
        fails[k] = true;
    }
    let mut now: Vec<usize> = Vec::new();
    // (Up to three places per pair.)
    let mut movable: Vec<(u32, Corners)> = Vec::with_capacity(3);
    if r.nearest.is_empty() {
        r.nearest = r.points.clone();
    }
    for k in order {
        if !fails[k] {
            continue;
        }
        // The places to move, with their candidate points.
        movable.clear();
        for i in ends(&pairs[k]).into_iter().flatten() {
            let id = r.ids[i];
            let Some(at) = places.binary_search(&place(id)).ok().filter(|_| id.moved) else {
                continue;
            };
            let at = at as u32;
            if kept_whole[at as usize] && movable.iter().all(|&(p, _)| p != at) {
                let q = r.points[i];
                let a = toward(id.enter, q);
                let b = if id.leave == id.enter {
                    a
                } else {
                    toward(id.leave, q)
                };
                // (A point for two vertices: only where both exact ones are.)
                let same = |s: Ordering, t: Ordering| if s == t { s } else { Ordering::Equal };
                movable.push((at, corners(q, (same(a.0, b.0), same(a.1, b.1)))));
            }
        }
        // One point at a time, each to each of its other floats, the others where they
        // are. (Every pair the JTS robustness suites' results mended was mended so;
        // trying the combinations of two or three points as well made each pair that
        // no move mends cost up to 63 tries instead of at most 9.)
        'moves: for (at, candidates) in &movable {
            let list = points_of(*at);
            let Some(&(_, first)) = list.first() else {
                continue;
            };
            let before = r.points[first as usize];
            for &q in candidates.others() {
                for &(_, i) in list {
                    r.points[i as usize] = q;
                }
                // A point onto a neighbour of its ring would collapse an edge: not taken.
                let collapses = list.iter().any(|&(_, i)| {
                    let i = i as usize;
                    let ring = r.starts.partition_point(|&s| s <= i) - 1;
                    let (s, e) = (r.starts[ring], r.starts[ring + 1]);
                    let prev = if i == s { e - 1 } else { i - 1 };
                    let next = if i + 1 == e { s } else { i + 1 };
                    r.points[prev] == r.points[i] || r.points[next] == r.points[i]
                });
                // Taken when the pair passes and no pair that passed fails (the pair
                // itself first: most candidates fail there).
                let taken = !collapses && passes(r, pairs, k, sides) && {
                    now.clear();
                    now.extend(list.iter().flat_map(|&(_, i)| pairs_at(i)));
                    now.sort_unstable();
                    now.dedup();
                    now.iter().all(|&m| fails[m] || passes(r, pairs, m, sides))
                };
                if taken {
                    // (A pair that failed may pass now.)
                    for &m in &now {
                        if fails[m] {
                            fails[m] = !passes(r, pairs, m, sides);
                        }
                    }
                    r.nudged += list.len();
                    break 'moves;
                }
                for &(_, i) in list {
                    r.points[i as usize] = before;
                }
            }
        }
    }
    failing.retain(|&k| fails[k]);
}

/// No place, in `nudge`'s tables.
const NONE: u32 = u32::MAX;

/// The entries of `sorted` (ascending) whose first element is `key`.
fn run_of(sorted: &[(u32, u32)], key: u32) -> &[(u32, u32)] {
    let from = sorted.partition_point(|&(k, _)| k < key);
    let to = from + sorted[from..].partition_point(|&(k, _)| k == key);
    &sorted[from..to]
}

/// The float points around an exact point: its rounded point first, then up to three
/// neighbours towards it.
struct Corners {
    points: [Point2; 4],
    len: usize,
}

impl Corners {
    /// The points other than the rounded one.
    fn others(&self) -> &[Point2] {
        &self.points[1..self.len]
    }
}

/// The float points around an exact point, from its rounded point `q` and the exact
/// point's side of it per axis: `q` first, then the neighbours towards it.
fn corners(q: Point2, (tx, ty): Toward) -> Corners {
    let step = |v: f64, t: Ordering| match t {
        Ordering::Less => Some(down(v)),
        Ordering::Greater => Some(up(v)),
        Ordering::Equal => None,
    };
    let (x1, y1) = (step(q.x, tx), step(q.y, ty));
    let mut c = Corners {
        points: [q; 4],
        len: 0,
    };
    for y in std::iter::once(q.y).chain(y1) {
        for x in std::iter::once(q.x).chain(x1) {
            c.points[c.len] = Point2::new(x, y);
            c.len += 1;
        }
    }
    c
}
