//! Which polygons' interiors overlap, for [`super::validity_problems`]: the faces of the
//! arrangement of all rings covered twice or more, and the polygons covering a point
//! inside each.

use super::nesting::{point_inside, windings};
use super::{Problem, Ring};
use crate::dcel::Dcel;
use crate::kernel::Point2;
use crate::overlay::trace::box_of;
use crate::overlay::BooleanEdge;
use std::ops::Range;

/// Reports overlapping polygons from the faces of `d` (the arrangement of all rings,
/// each face's count of polygons covering it) covered twice or more: at a point inside
/// each, a polygon covering it that no problem names yet is named with another one
/// covering it (so every polygon whose interior overlaps another's there is named,
/// each pair once, without listing every pair where many polygons pile up). Where no
/// inside point is found (a face thinner than the rounding of one, or whose first
/// convex corners all fail), the first such face is reported without names.
pub(super) fn overlapping_polygons(
    d: &Dcel<(), BooleanEdge, (i32, i32)>,
    rings: &[Ring],
    spans: &[Range<usize>],
    out: &mut Vec<Problem>,
) {
    let mut inside = Vec::new();
    // (The first face without an inside point, and its first vertex.)
    let mut unnamed: Option<Option<Point2>> = None;
    for f in d.face_ids().filter(|&f| d.face(f).data.0 > 1) {
        let Some(face) = d.face_polygon(f) else {
            continue;
        };
        match point_inside(&face.exterior, &face.holes) {
            Some(q) => inside.push(q),
            None => {
                unnamed.get_or_insert(face.exterior.first().copied());
            }
        }
    }
    // Per point, the first polygon found covering it; per polygon, whether a problem
    // names it.
    let mut first: Vec<Option<usize>> = vec![None; inside.len()];
    let mut named = vec![false; spans.len()];
    let mut pairs: Vec<(usize, usize, usize)> = Vec::new();
    for_each_cover(rings, spans, &inside, |point, polygon| match first[point] {
        None => first[point] = Some(polygon),
        Some(other) => {
            if !named[polygon] || !named[other] {
                pairs.push((other.min(polygon), other.max(polygon), point));
                (named[polygon], named[other]) = (true, true);
            }
        }
    });
    pairs.sort_unstable();
    pairs.dedup_by_key(|&mut (a, b, _)| (a, b));
    let polygon_of = |s: usize| rings[spans[s].start].0;
    out.extend(pairs.into_iter().map(|(a, b, point)| {
        let (a, b) = (polygon_of(a), polygon_of(b));
        Problem {
            message: format!("interiors of polygon {a} and polygon {b} overlap"),
            at: Some(inside[point]),
            polygon: Some(a),
        }
    }));
    if let Some(at) = unnamed {
        out.push(Problem {
            message: "polygon interiors overlap".into(),
            at,
            polygon: None,
        });
    }
}

/// Candidate (polygon, point) pairs [`for_each_cover`] collects before it tests them.
const COVER_BATCH: usize = 1 << 14;

/// Calls `f(point, polygon)` for each of `points` (none on a ring) and each polygon (its
/// number in `spans`) covering it. The candidates come from a sweep in x over the points
/// and the shells' boxes; they are tested in batches, each batch by polygon: one pass
/// over each of its rings for all its candidate points ([`windings`]), so a large
/// polygon over many small ones is not walked once per point.
fn for_each_cover(
    rings: &[Ring],
    spans: &[Range<usize>],
    points: &[Point2],
    mut f: impl FnMut(usize, usize),
) {
    let boxes: Vec<_> = spans.iter().map(|s| box_of(&rings[s.start].2)).collect();
    let mut by_x0: Vec<usize> = (0..spans.len()).collect();
    by_x0.sort_unstable_by(|&i, &j| boxes[i][0].total_cmp(&boxes[j][0]));
    let mut by_x: Vec<usize> = (0..points.len()).collect();
    by_x.sort_unstable_by(|&i, &j| points[i].x.total_cmp(&points[j].x));
    let (mut active, mut next, mut batch) = (Vec::new(), 0, Vec::new());
    for i in by_x {
        let q = points[i];
        while next < by_x0.len() && boxes[by_x0[next]][0] <= q.x {
            active.push(by_x0[next]);
            next += 1;
        }
        active.retain(|&s| boxes[s][1] >= q.x);
        for &s in &active {
            if boxes[s][2] <= q.y && q.y <= boxes[s][3] {
                batch.push((s, i));
                if batch.len() == COVER_BATCH {
                    test_covers(rings, spans, points, &mut batch, &mut f);
                }
            }
        }
    }
    test_covers(rings, spans, points, &mut batch, &mut f);
}

/// The pairs `(polygon, point)` of `batch` where the polygon covers the point, to `f`
/// (as `f(point, polygon)`); `batch` is left empty.
fn test_covers(
    rings: &[Ring],
    spans: &[Range<usize>],
    points: &[Point2],
    batch: &mut Vec<(usize, usize)>,
    f: &mut impl FnMut(usize, usize),
) {
    batch.sort_unstable();
    for group in batch.chunk_by(|a, b| a.0 == b.0) {
        let span = &spans[group[0].0];
        let queries: Vec<Point2> = group.iter().map(|&(_, i)| points[i]).collect();
        let shell = windings(&rings[span.start].2, &queries);
        let mut covered: Vec<bool> = shell.iter().map(|&w| w != 0).collect();
        for hole in &rings[span.start + 1..span.end] {
            // (Only the points in the hole's box: most holes are far from most points.)
            let b = box_of(&hole.2);
            let near: Vec<usize> = (0..queries.len())
                .filter(|&k| covered[k])
                .filter(|&k| {
                    let q = queries[k];
                    b[0] <= q.x && q.x <= b[1] && b[2] <= q.y && q.y <= b[3]
                })
                .collect();
            let in_hole = windings(
                &hole.2,
                &near.iter().map(|&k| queries[k]).collect::<Vec<_>>(),
            );
            for (k, w) in near.into_iter().zip(in_hole) {
                if w != 0 {
                    covered[k] = false;
                }
            }
        }
        for (&(polygon, point), covered) in group.iter().zip(covered) {
            if covered {
                f(point, polygon);
            }
        }
    }
    batch.clear();
}
