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
    // The pairs each point is in (as the point or an end of the edge).
    let n = r.points.len();
    let mut starts = vec![0u32; n + 1];
    let ends = |&(x, e): &Pair| {
        let (x, i, j) = (x as usize, e.i, e.j);
        [
            Some(x),
            (i != x).then_some(i),
            (j != x && j != i).then_some(j),
        ]
    };
    for pair in pairs {
        for i in ends(pair).into_iter().flatten() {
            starts[i + 1] += 1;
        }
    }
    for i in 1..=n {
        starts[i] += starts[i - 1];
    }
    let mut at = starts.clone();
    let mut of_point = vec![0u32; starts[n] as usize];
    for (k, pair) in pairs.iter().enumerate() {
        for i in ends(pair).into_iter().flatten() {
            of_point[at[i] as usize] = k as u32;
            at[i] += 1;
        }
    }
    let pairs_at = |i: usize| &of_point[starts[i] as usize..starts[i + 1] as usize];
    // Where each moved point of a failing pair is in the rings, by the vertices it
    // stands for (`None`: one of them is elsewhere on a point standing for others too,
    // and is not moved).
    type Place = (u32, u32);
    let place = |id: PointIds| (id.enter, id.leave);
    type Map<K, V> = std::collections::HashMap<K, V, foldhash::fast::RandomState>;
    // (Up to three moved points per failing pair, two vertices each.)
    let mut places: Map<Place, Option<Vec<usize>>> =
        Map::with_capacity_and_hasher(3 * failing.len(), Default::default());
    let mut place_of: Map<u32, Place> =
        Map::with_capacity_and_hasher(6 * failing.len(), Default::default());
    for &k in failing.iter() {
        for i in ends(&pairs[k]).into_iter().flatten() {
            let id = r.ids[i];
            if id.moved {
                places.entry(place(id)).or_insert(Some(Vec::new()));
                for v in [id.enter, id.leave] {
                    // (A vertex on two different points: neither is moved.)
                    if let Some(other) = place_of.insert(v, place(id)) {
                        if other != place(id) {
                            places.insert(other, None);
                            places.insert(place(id), None);
                        }
                    }
                }
            }
        }
    }
    // (Which vertices to look up, by number: a hash per point would cost more than the
    // rest of this.)
    let top = r
        .ids
        .iter()
        .map(|id| id.enter.max(id.leave))
        .max()
        .unwrap_or(0);
    let mut wanted = vec![false; top as usize + 1];
    for &v in place_of.keys() {
        wanted[v as usize] = true;
    }
    for (i, &id) in r.ids.iter().enumerate() {
        if !wanted[id.enter as usize] && !wanted[id.leave as usize] {
            continue;
        }
        let mut seen = None;
        for v in [id.enter, id.leave] {
            let Some(&at) = place_of.get(&v) else {
                continue;
            };
            if seen == Some(at) {
                continue;
            }
            seen = Some(at);
            let entry = places.entry(at).or_insert(None);
            match entry {
                Some(list) if place(id) == at => list.push(i),
                _ => *entry = None,
            }
        }
    }
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
    if r.nearest.is_empty() {
        r.nearest = r.points.clone();
    }
    for k in order {
        if !fails[k] {
            continue;
        }
        // The vertices to move, with their places and their candidate points.
        let mut movable: Vec<(&Vec<usize>, Vec<Point2>)> = Vec::new();
        for i in ends(&pairs[k]).into_iter().flatten() {
            let id = r.ids[i];
            let found = places.get(&place(id)).filter(|_| id.moved);
            if let Some(Some(list)) = found.filter(|l| l.as_ref().is_some_and(|l| !l.is_empty())) {
                if !movable.iter().any(|(l, _)| std::ptr::eq(*l, list)) {
                    let q = r.points[i];
                    let a = toward(id.enter, q);
                    let b = if id.leave == id.enter {
                        a
                    } else {
                        toward(id.leave, q)
                    };
                    // (A point for two vertices: only where both exact ones are.)
                    let same = |s: Ordering, t: Ordering| if s == t { s } else { Ordering::Equal };
                    movable.push((list, corners(q, (same(a.0, b.0), same(a.1, b.1)))));
                }
            }
        }
        if movable.is_empty() {
            continue;
        }
        // One point at a time, each to each of its other floats, the others where they
        // are. (Every pair the JTS robustness suites' results mended was mended so;
        // trying the combinations of two or three points as well made each pair that
        // no move mends cost up to 63 tries instead of at most 9.)
        'moves: for (list, candidates) in &movable {
            let before = r.points[list[0]];
            for &q in &candidates[1..] {
                for &i in list.iter() {
                    r.points[i] = q;
                }
                // A point onto a neighbour of its ring would collapse an edge: not taken.
                let collapses = list.iter().any(|&i| {
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
                    now.extend(
                        list.iter()
                            .flat_map(|&i| pairs_at(i).iter().map(|&m| m as usize)),
                    );
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
                for &i in list.iter() {
                    r.points[i] = before;
                }
            }
        }
    }
    failing.retain(|&k| fails[k]);
}

/// The float points around an exact point, from its rounded point `q` and the exact
/// point's side of it per axis: `q` first, then the neighbours towards it.
fn corners(q: Point2, (tx, ty): Toward) -> Vec<Point2> {
    let step = |v: f64, t: Ordering| match t {
        Ordering::Less => Some(down(v)),
        Ordering::Greater => Some(up(v)),
        Ordering::Equal => None,
    };
    let (x1, y1) = (step(q.x, tx), step(q.y, ty));
    let xs = std::iter::once(q.x).chain(x1);
    std::iter::once(q.y)
        .chain(y1)
        .flat_map(|y| xs.clone().map(move |x| Point2::new(x, y)))
        .collect()
}
