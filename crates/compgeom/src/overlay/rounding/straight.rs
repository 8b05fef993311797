//! Points that rounding left on a straight line between their neighbours.
//!
//! A result is minimal exactly: the tracing drops every vertex where the boundary goes
//! straight on, unless another ring passes through it or the caller keeps them. Rounding
//! can make a vertex that turned a little go straight in floats: a crossing a fraction
//! of a float gap from its neighbours' line, or a vertex where a sliver ring touched,
//! the sliver rounded away. Such a point lies inside the segment between its
//! neighbours, so the ring without it is the same closed curve: it stays valid, and its
//! point set, and so every decision of the rounding check, is unchanged. The rule, on
//! the rounded result alone: a point strictly inside the segment between the points
//! kept before and after it, and in no other ring, is dropped.

use super::PointIds;
use crate::kernel::arith::ordered_key;
use crate::kernel::{orient2d, Orientation, Point2, Polygon};
use foldhash::fast::RandomState;
use std::collections::HashMap;

/// The ring `points` (with what the check knows of each point, `ids`) from its point
/// `lowest` (the smallest in x, then y), without the points that lie strictly inside
/// the segment between the points kept before and after them, where `may_drop` allows
/// it (the point is in no other ring). O(n), and `may_drop` asked of straight points
/// only.
///
/// Only the points that may go straight are looked at: those next to a moved one, and
/// the `crowded` ones (where a ring that rounded away touched this one: the tracing
/// keeps a point where rings touch, even where each goes straight). Other points and
/// their neighbours are the exact vertices, which turn. The lowest point never lies
/// inside a segment between two others (one of them would be lower), so the ring
/// starts there.
pub(in crate::overlay) fn without_straight_points(
    points: &[Point2],
    ids: &[PointIds],
    lowest: usize,
    crowded: impl Fn(&PointIds) -> bool,
    may_drop: impl Fn(Point2) -> bool,
) -> Vec<Point2> {
    let n = points.len();
    // (Most rings have none: the first point dropped below is straight between its
    // neighbours as they are. Looked for first, each point that may be once: those
    // inside the array, then the two whose neighbours wrap around.)
    let look = |a: &PointIds, b: &PointIds, c: &PointIds| a.moved | b.moved | c.moved || crowded(b);
    let wrap = [(n - 1, 0, 1 % n), (n - 2, n - 1, 0)];
    let some = points
        .windows(3)
        .zip(ids.windows(3))
        .any(|(p, id)| look(&id[0], &id[1], &id[2]) && strictly_inside(p[0], p[1], p[2]))
        || wrap.iter().any(|&(a, b, c)| {
            look(&ids[a], &ids[b], &ids[c]) && strictly_inside(points[a], points[b], points[c])
        });
    let rotated = [&points[lowest..], &points[..lowest]].concat();
    if !some {
        return rotated;
    }
    // (Every point looked at now: the others turn, as above.)
    straightened(&rotated, may_drop).unwrap_or(rotated)
}

/// Whether the point `id` stands for one of the arrangement vertices `sorted`
/// (ascending): either of the two vertices of a point where an edge collapsed. The
/// `crowded` rule of [`without_straight_points`], with `sorted` the vertices of the rings
/// that rounded away. O(log n).
pub(in crate::overlay) fn stands_for_any(id: &PointIds, sorted: &[u32]) -> bool {
    !sorted.is_empty()
        && (sorted.binary_search(&id.enter).is_ok() || sorted.binary_search(&id.leave).is_ok())
}

/// `ring`, which starts at its lowest point, without the points strictly inside the
/// segment between the points kept before and after them where `may_drop` allows it;
/// `None` when none is dropped or fewer than three points would be left (a flat ring,
/// which the check never passes: left as it was). O(n).
///
/// One pass suffices: a point kept next to a dropped one is straight between its new
/// neighbours only if it was between the old ones (the dropped point lies on the
/// segment, so the direction to the new neighbour is the old one).
fn straightened(ring: &[Point2], may_drop: impl Fn(Point2) -> bool) -> Option<Vec<Point2>> {
    let n = ring.len();
    let mut kept = Vec::with_capacity(n);
    kept.push(ring[0]);
    for i in 1..n {
        let (p, q, r) = (kept[kept.len() - 1], ring[i], ring[(i + 1) % n]);
        if !(strictly_inside(p, q, r) && may_drop(q)) {
            kept.push(q);
        }
    }
    (kept.len() < n && kept.len() >= 3).then_some(kept)
}

/// The polygons, whose rings start at their lowest points, without the points strictly
/// inside the segment between their kept neighbours that no other ring has: after a
/// repair, where a point a settled polygon kept for a ring through it may now be in no
/// other ring (the ring's polygon was united again, and the union went straight there).
/// O(n) expected.
pub(in crate::overlay) fn straighten_all(polygons: &mut [Polygon]) {
    // (Most results have no straight point at all: looked for first, without the
    // count of uses.)
    let straight_in = |ring: &[Point2]| {
        let n = ring.len();
        (0..n).any(|i| strictly_inside(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]))
    };
    if !polygons
        .iter()
        .flat_map(|p| p.rings())
        .any(|r| straight_in(r))
    {
        return;
    }
    let key = |q: Point2| (ordered_key(q.x), ordered_key(q.y));
    let mut uses: HashMap<(u64, u64), u32, RandomState> = HashMap::default();
    for q in polygons.iter().flat_map(|p| p.rings()).flatten() {
        *uses.entry(key(*q)).or_insert(0) += 1;
    }
    let alone = |q: Point2| uses[&key(q)] == 1;
    for polygon in polygons.iter_mut() {
        if let Some(ring) = straightened(&polygon.exterior, alone) {
            polygon.exterior = ring;
        }
        for hole in &mut polygon.holes {
            if let Some(ring) = straightened(hole, alone) {
                *hole = ring;
            }
        }
    }
}

/// Whether `q` lies on segment `p r` and is neither end (exactly).
#[inline]
fn strictly_inside(p: Point2, q: Point2, r: Point2) -> bool {
    let within = |a: f64, b: f64, c: f64| (a <= b && b <= c) || (c <= b && b <= a);
    q != p
        && q != r
        && within(p.x, q.x, r.x)
        && within(p.y, q.y, r.y)
        && !clearly_turns(p, q, r)
        && orient2d(p, q, r) == Orientation::Collinear
}

/// Whether `p q r` turns, decided in floats where the rounding error of the
/// determinant is smaller than its size (Shewchuk's first bound, with margin; `false`
/// where it cannot tell: tiny products, ties, overflow).
#[inline]
fn clearly_turns(p: Point2, q: Point2, r: Point2) -> bool {
    let (a, b) = ((q.x - p.x) * (r.y - p.y), (q.y - p.y) * (r.x - p.x));
    let size = a.abs() + b.abs();
    // (Where the products are tiny, underflow may have cost them more than the bound's
    // share: there `orient2d` decides. 4e-16 is above the bound's 3.33e-16 by far more
    // than what underflow costs above 1e-270. Where a product overflowed, `size` is
    // infinite or NaN and the test is false.)
    size > 1e-270 && (a - b).abs() > 4e-16 * size
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ids(moved: &[bool]) -> Vec<PointIds> {
        moved
            .iter()
            .enumerate()
            .map(|(v, &m)| PointIds::of(v as u32, m))
            .collect()
    }

    fn p(x: f64, y: f64) -> Point2 {
        Point2::new(x, y)
    }

    /// No point where other boundary edges meet.
    fn calm(_: &PointIds) -> bool {
        false
    }

    #[test]
    fn straight_points_next_to_a_moved_one_are_dropped() {
        // A square with a point on its right side (moved), and one that turns a float
        // on its top, not moved.
        let top = f64::from_bits(4.0f64.to_bits() + 1);
        let pts = [
            p(0.0, 0.0),
            p(4.0, 0.0),
            p(4.0, 1.5),
            p(4.0, 4.0),
            p(2.0, top),
            p(0.0, 4.0),
        ];
        let all = |_: Point2| true;
        let out = without_straight_points(
            &pts,
            &ids(&[false, false, true, false, false, false]),
            0,
            calm,
            all,
        );
        assert_eq!(
            out,
            vec![
                p(0.0, 0.0),
                p(4.0, 0.0),
                p(4.0, 4.0),
                p(2.0, top),
                p(0.0, 4.0)
            ]
        );
        // A neighbour moved: dropped too. Two in a row on one side: both.
        let pts = [
            p(0.0, 0.0),
            p(1.0, 0.0),
            p(3.0, 0.0),
            p(4.0, 0.0),
            p(0.0, 4.0),
        ];
        let out = without_straight_points(
            &pts,
            &ids(&[false, true, false, false, false]),
            0,
            calm,
            all,
        );
        assert_eq!(out, vec![p(0.0, 0.0), p(4.0, 0.0), p(0.0, 4.0)]);
    }

    /// A point where other rings met (they rounded away) is looked at though nothing
    /// moved near it.
    #[test]
    fn crowded_straight_points_are_dropped() {
        let pts = [
            p(0.0, 0.0),
            p(4.0, 0.0),
            p(4.0, 4.0),
            p(2.0, 4.0),
            p(0.0, 4.0),
        ];
        let still = ids(&[false; 5]);
        let at_2_4 = |id: &PointIds| id.enter == 3;
        let out = without_straight_points(&pts, &still, 0, at_2_4, |_| true);
        assert_eq!(
            out,
            vec![p(0.0, 0.0), p(4.0, 0.0), p(4.0, 4.0), p(0.0, 4.0)]
        );
        // Another ring still has it: kept.
        let out = without_straight_points(&pts, &still, 0, at_2_4, |q| q != p(2.0, 4.0));
        assert_eq!(out, pts.to_vec());
    }

    #[test]
    fn turning_shared_and_folded_points_stay() {
        // The right side x = 4 with a moved point in the middle: left as it is.
        let kept_as_is = |middle: Point2, may_drop: fn(Point2) -> bool| {
            let pts = [p(0.0, 0.0), p(4.0, 0.0), middle, p(4.0, 4.0), p(0.0, 4.0)];
            let moved = ids(&[false, false, true, false, false]);
            let out = without_straight_points(&pts, &moved, 0, calm, may_drop);
            assert_eq!(out, pts.to_vec(), "{middle:?}");
        };
        // A point a float off the line turns.
        kept_as_is(p(f64::from_bits(4.0f64.to_bits() + 1), 2.0), |_| true);
        // Straight but shared (`may_drop` says no).
        kept_as_is(p(4.0, 2.0), |_| false);
        // On the line but beyond its neighbour (the ring folds back there).
        kept_as_is(p(4.0, 5.0), |_| true);
    }

    /// A point where an edge collapsed stands for two vertices: it is crowded when
    /// either of them was in a ring that rounded away.
    #[test]
    fn a_point_for_two_vertices_is_crowded_by_either() {
        let mut merged = PointIds::of(5, true);
        assert!(merged.merge(PointIds::of(9, true)));
        assert!(stands_for_any(&merged, &[1, 5]));
        assert!(stands_for_any(&merged, &[9, 12]));
        assert!(!stands_for_any(&merged, &[6, 7, 8]));
        assert!(!stands_for_any(&merged, &[]));
        assert!(stands_for_any(&PointIds::of(7, false), &[7]));
    }

    /// Where dropping the straight points would leave fewer than three, the ring is
    /// left as it is (flat: the check never passes it, and it is united again).
    #[test]
    fn a_ring_that_would_go_flat_is_left_as_it_is() {
        let pts = [p(0.0, 0.0), p(2.0, 0.0), p(1.0, 0.0)];
        let out = without_straight_points(&pts, &ids(&[false, false, true]), 0, calm, |_| true);
        assert_eq!(out, pts.to_vec());
        let mut polygons = [Polygon::new(
            vec![p(0.0, 0.0), p(4.0, 0.0), p(4.0, 4.0), p(0.0, 4.0)],
            vec![pts.to_vec()],
        )];
        straighten_all(&mut polygons);
        assert_eq!(polygons[0].holes[0], pts.to_vec());
    }

    /// Where the float filter says "turns", the exact orientation is not collinear
    /// and has the sign of the float determinant the filter bounded, at every scale
    /// from the subnormals to near overflow, on triples within a few floats of
    /// collinear; and it does decide ordinary turns (else it would only cost time).
    /// Random triples rarely need the guard against tiny products: an exactly collinear
    /// triple whose products are subnormal (about 9e-310, so one ulp apart after
    /// rounding) does, and is asked first.
    #[test]
    fn clearly_turns_is_sound_at_every_scale() {
        let (p0, q, r) = (
            p(3.3028386082133376e-155, 2.4771289561600032e-155),
            p(-1.667247075273027e-155, -1.2504353064547702e-155),
            p(8.951089137594957e-156, 6.713316853196218e-156),
        );
        assert_eq!(orient2d(p0, q, r), Orientation::Collinear);
        assert!(!clearly_turns(p0, q, r));
        let float_sign = |p0: Point2, q: Point2, r: Point2| {
            let d = (q.x - p0.x) * (r.y - p0.y) - (q.y - p0.y) * (r.x - p0.x);
            if d > 0.0 {
                Orientation::CounterClockwise
            } else {
                Orientation::Clockwise
            }
        };
        let mut unit = crate::testing::units(0x57_7a19);
        let mut below = crate::testing::below(0x57_7a1a);
        let (mut near, mut decided) = (0, 0);
        for exp in (-1074..1000).step_by(7) {
            let scale = 2f64.powi(exp);
            for _ in 0..40 {
                let mut v = || (unit() - 0.5) * scale;
                let (p0, r, off) = (p(v(), v()), p(v(), v()), p(v(), v()));
                // A float point on the segment, rounded, then moved a float or none
                // per axis.
                let t = unit();
                let step = |x: f64, k: u64| match k {
                    0 => x,
                    1 => super::super::up(x),
                    _ => super::super::down(x),
                };
                let on = p(p0.x + t * (r.x - p0.x), p0.y + t * (r.y - p0.y));
                let q = p(step(on.x, below(3)), step(on.y, below(3)));
                // Three points of a line through the origin, one far smaller than the
                // others: their differences are rounded too.
                let small = 2f64.powi(-(below(60) as i32) - 20);
                let q2 = p(step(p0.x * small, below(3)), step(p0.y * small, below(3)));
                let r2 = p(-p0.x * (1.0 + t), -p0.y * (1.0 + t));
                for (a, b, c) in [(p0, q, r), (p0, q2, r2), (p0, off, r)] {
                    if clearly_turns(a, b, c) {
                        let exact = orient2d(a, b, c);
                        assert_ne!(exact, Orientation::Collinear, "{a:?} {b:?} {c:?}");
                        assert_eq!(exact, float_sign(a, b, c), "{a:?} {b:?} {c:?}");
                        if b != off {
                            near += 1;
                        } else {
                            decided += 1;
                        }
                    }
                }
            }
        }
        assert!(near > 100, "only {near} near-collinear triples decided");
        assert!(decided > 4_000, "the filter decided only {decided} turns");
    }

    #[test]
    fn the_ring_starts_at_its_lowest_point() {
        let pts = [
            p(4.0, 4.0),
            p(0.0, 4.0),
            p(0.0, 0.0),
            p(4.0, 0.0),
            p(4.0, 2.0),
        ];
        let moved = ids(&[false, false, false, false, true]);
        let out = without_straight_points(&pts, &moved, 2, calm, |_| true);
        assert_eq!(
            out,
            vec![p(0.0, 0.0), p(4.0, 0.0), p(4.0, 4.0), p(0.0, 4.0)]
        );
    }
}
