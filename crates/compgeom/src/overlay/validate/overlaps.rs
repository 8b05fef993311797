//! Which polygons' interiors overlap, for [`super::validity_problems`]: the faces of the
//! arrangement of all rings covered twice or more, and the polygons covering a point
//! inside each.

use super::nesting::{bounds, point_inside, winding};
use super::{Problem, Ring};
use crate::dcel::Dcel;
use crate::kernel::Point2;
use crate::overlay::BooleanEdge;
use std::ops::Range;

/// Reports overlapping polygons from the faces of `d` (the arrangement of all rings,
/// each face's count of polygons covering it) covered twice or more: at a point inside
/// each, every polygon covering it that no problem names yet is named with another one
/// covering it (so every polygon whose interior overlaps another's is named, each pair
/// once, without listing every pair where many polygons pile up). A face where no
/// inside point is found (thinner than the rounding of one) is reported without names,
/// the first such.
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
    let polygons = spans.len();
    let mut named = vec![false; polygons];
    let mut pairs: Vec<(usize, usize, Point2)> = Vec::new();
    for_each_covering(rings, spans, &inside, |q, cover| {
        for &p in cover {
            if named[p] {
                continue;
            }
            let other = if p == cover[0] { cover[1] } else { cover[0] };
            pairs.push((p.min(other), p.max(other), q));
            (named[p], named[other]) = (true, true);
        }
    });
    pairs.sort_by_key(|&(a, b, _)| (a, b));
    pairs.dedup_by_key(|&mut (a, b, _)| (a, b));
    let polygon_of = |s: usize| rings[spans[s].start].0;
    out.extend(pairs.into_iter().map(|(a, b, q)| {
        let (a, b) = (polygon_of(a), polygon_of(b));
        Problem {
            message: format!("interiors of polygon {a} and polygon {b} overlap"),
            at: Some(q),
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

/// Calls `f(q, cover)` for each of `points` (none on a ring) covered by two polygons or
/// more, `cover` their numbers in `spans`, ascending: a sweep in x over the points and
/// the shells' boxes, each point tested against the shells whose boxes hold it.
fn for_each_covering(
    rings: &[Ring],
    spans: &[Range<usize>],
    points: &[Point2],
    mut f: impl FnMut(Point2, &[usize]),
) {
    let boxes: Vec<_> = spans.iter().map(|s| bounds(&rings[s.start].2)).collect();
    let covers = |span: &Range<usize>, q: Point2| {
        winding(&rings[span.start].2, q) != 0
            && (span.start + 1..span.end).all(|h| winding(&rings[h].2, q) == 0)
    };
    let mut by_x0: Vec<usize> = (0..spans.len()).collect();
    by_x0.sort_unstable_by(|&i, &j| boxes[i].0.total_cmp(&boxes[j].0));
    let mut by_x: Vec<usize> = (0..points.len()).collect();
    by_x.sort_unstable_by(|&i, &j| points[i].x.total_cmp(&points[j].x));
    let (mut active, mut next, mut cover) = (Vec::new(), 0, Vec::new());
    for i in by_x {
        let q = points[i];
        while next < by_x0.len() && boxes[by_x0[next]].0 <= q.x {
            active.push(by_x0[next]);
            next += 1;
        }
        active.retain(|&s| boxes[s].1 >= q.x);
        cover.clear();
        cover.extend(
            active
                .iter()
                .copied()
                .filter(|&s| boxes[s].2 <= q.y && q.y <= boxes[s].3 && covers(&spans[s], q)),
        );
        if cover.len() >= 2 {
            cover.sort_unstable();
            f(q, &cover);
        }
    }
}
