//! Why a polygon set is not valid (OGC simple-features rules), decided exactly.
//!
//! Checks, in order: finite coordinates and at least three distinct points per ring;
//! edges crossing or overlapping (within a ring or between rings; found by the exact
//! intersection sweep); a ring passing twice through a point (self-touching: at a vertex
//! of its own, or a vertex of it on another of its edges); the rings of a polygon
//! touching in a loop (two rings meeting at two points, or a chain of rings back to the
//! first: the interior is not connected); a hole outside its shell, and a hole inside
//! another hole of its polygon ([`nesting`]); interiors of two polygons overlapping (a
//! face of the arrangement covered twice, after orienting every polygon, named by the
//! polygons covering a point inside it); and, as RFC 7946 asks, shells
//! counter-clockwise and holes clockwise. As the OGC rules allow, two rings of a polygon
//! may touch at one point (a vertex of both, or a vertex of one on an edge of the
//! other), and two polygons at points. Cost: one intersection sweep and one labelled
//! arrangement, O((n + k) log n); the nesting tests O(n log n) plus the pairs of holes
//! of a polygon whose boxes overlap along the axis swept; naming the polygons of each
//! overlap, a sweep over the shells' boxes and a point inside each face covered twice.
mod nesting;
mod overlaps;

use super::boolean::{boolean_dcel, FillRule};
use crate::intersect::find_intersections;
use crate::io::{ring_orientation, OpenRing};
use crate::kernel::{orient2d, MultiPolygon, Orientation, Point2, Polygon, Segment2};
use crate::Result;
use nesting::{holes_inside_holes, holes_outside_shells, Touches};
use overlaps::overlapping_polygons;
use std::borrow::Cow;
use std::ops::Range;

/// One reason a polygon set is invalid.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    /// What is wrong, naming the polygon and ring.
    pub message: String,
    /// Where, when there is one point to show.
    pub at: Option<Point2>,
    /// The polygon it is in (the first one named, where it names two), when it names
    /// one: its index in the polygon set.
    pub polygon: Option<usize>,
}

fn ring_name(p: usize, r: usize) -> String {
    if r == 0 {
        format!("polygon {p} exterior")
    } else {
        format!("polygon {p} hole {}", r - 1)
    }
}

/// [`validity_problems`] of polygons read by [`crate::io::read_polygons_as_written`],
/// with the rings the input left open first (each at its last position, and judged
/// further as if closed).
///
/// ```
/// use compgeom::io::{read_polygons_as_written, Format};
/// use compgeom::overlay::validity_problems_as_written;
/// let text = "POLYGON ((0 0, 4 0, 4 4, 0 4))";
/// let read = read_polygons_as_written(text, Format::Wkt, "in").unwrap();
/// let problems = validity_problems_as_written(&read.polygons, &read.open_rings).unwrap();
/// assert_eq!(problems.len(), 1);
/// assert!(problems[0].message.starts_with("polygon 0 exterior: not closed"));
/// assert_eq!(problems[0].polygon, Some(0));
/// ```
pub fn validity_problems_as_written(
    polygons: &MultiPolygon,
    open: &[OpenRing],
) -> Result<Vec<Problem>> {
    let mut out: Vec<Problem> = open
        .iter()
        .map(|r| Problem {
            message: format!(
                "{}: not closed: {}",
                ring_name(r.polygon, r.ring),
                r.how_open()
            ),
            at: Some(r.last),
            polygon: Some(r.polygon),
        })
        .collect();
    out.extend(validity_problems(polygons)?);
    Ok(out)
}

/// Every reason `polygons` is not valid; empty when it is. A ring's closing point equal
/// to its first is ignored. Never fails on bad coordinates: they are reported.
///
/// ```
/// use compgeom::overlay::validity_problems;
/// use compgeom::{MultiPolygon, Point2, Polygon};
/// let p = |x, y| Point2::new(x, y);
/// let bow = MultiPolygon(vec![Polygon::new(vec![p(0., 0.), p(2., 2.), p(2., 0.), p(0., 2.)], vec![])]);
/// let problems = validity_problems(&bow).unwrap();
/// assert!(problems[0].message.contains("cross"));
/// ```
pub fn validity_problems(polygons: &MultiPolygon) -> Result<Vec<Problem>> {
    let mut out = Vec::new();
    let mut rings: Vec<Ring> = Vec::new();
    for (pi, poly) in polygons.0.iter().enumerate() {
        // (An empty hole is no hole, and a polygon of empty rings no polygon, as the
        // readers take `EMPTY`.)
        let empty = poly.rings().all(Vec::is_empty);
        for (ri, ring) in poly.rings().enumerate() {
            if ring.is_empty() && (ri > 0 || empty) {
                continue;
            }
            let mut r = ring.clone();
            if r.len() > 1 && r[0] == r[r.len() - 1] {
                r.pop();
            }
            if let Some(p) = r.iter().find(|p| !p.is_finite()) {
                out.push(Problem {
                    message: format!("{}: non-finite coordinate", ring_name(pi, ri)),
                    at: Some(*p),
                    polygon: Some(pi),
                });
                continue;
            }
            r.dedup();
            while r.len() > 1 && r[0] == r[r.len() - 1] {
                r.pop();
            }
            if r.len() < 3 {
                out.push(Problem {
                    message: format!("{}: fewer than 3 distinct points", ring_name(pi, ri)),
                    at: r.first().copied(),
                    polygon: Some(pi),
                });
                continue;
            }
            rings.push((pi, ri, r));
        }
    }
    if !out.is_empty() {
        return Ok(out);
    }
    // Crossings, overlaps and self-touching rings.
    let mut segs = Vec::new();
    let mut owner = Vec::new();
    for (k, (_, _, r)) in rings.iter().enumerate() {
        for i in 0..r.len() {
            segs.push(Segment2::new(r[i], r[(i + 1) % r.len()]));
            owner.push(k);
        }
    }
    let found = find_intersections(&segs)?;
    let name = |k: usize| ring_name(rings[k].0, rings[k].1);
    for o in &found.overlaps {
        out.push(Problem {
            message: format!(
                "edges overlap ({} and {})",
                name(owner[o.segments[0]]),
                name(owner[o.segments[o.segments.len() - 1]])
            ),
            at: Some(o.from),
            polygon: Some(rings[owner[o.segments[0]]].0),
        });
    }
    // Rings of one polygon touching at points: joined into classes as they touch, a
    // touch between rings already joined (through other touches: two rings meeting at
    // two points, or a shell and two holes in a chain) closes a loop of boundary that
    // cuts the interior apart.
    let mut joined: Vec<usize> = (0..rings.len()).collect();
    // (Ring and passes per ring at one point, reused: every ring vertex is a meeting
    // point.)
    let mut passes: Vec<(usize, usize)> = Vec::new();
    let mut at_point: Vec<(usize, usize)> = Vec::new();
    let mut touches = Touches::default();
    for p in &found.points {
        // Edges crossing (two through the point, or one with nothing else there); one
        // edge through a vertex of another ring is a touch, below.
        let ends = p.upper().len() + p.lower().len();
        if p.interior().len() >= 2 || (p.interior().len() == 1 && ends == 0) {
            let other = p
                .segments()
                .iter()
                .map(|&s| owner[s])
                .find(|&k| k != owner[p.interior()[0]]);
            out.push(Problem {
                message: format!(
                    "edges cross ({}{})",
                    name(owner[p.interior()[0]]),
                    other
                        .map(|k| format!(" and {}", name(k)))
                        .unwrap_or_default()
                ),
                at: Some(p.point),
                polygon: Some(rings[owner[p.interior()[0]]].0),
            });
            continue;
        }
        // Each ring's passes through the point: an edge through it once, a vertex once
        // (its two edges end there).
        passes.clear();
        for &s in p.interior() {
            passes.push((owner[s], 2));
        }
        for &s in p.upper().iter().chain(p.lower()) {
            passes.push((owner[s], 1));
        }
        passes.sort_unstable();
        at_point.clear();
        for &(k, ends) in &passes {
            match at_point.last_mut() {
                Some((last, n)) if *last == k => *n += ends,
                _ => at_point.push((k, ends)),
            }
        }
        if let Some(&(k, _)) = at_point.iter().find(|&&(_, ends)| ends > 2) {
            out.push(Problem {
                message: format!("{}: ring touches itself", name(k)),
                at: Some(p.point),
                polygon: Some(rings[k].0),
            });
            continue;
        }
        // The rings of each polygon here (consecutive: the rings are numbered polygon by
        // polygon), each joined to the first. (Not where edges overlap, reported above:
        // the ends of an overlap are touches, and the loop they make says nothing more.)
        let groups = at_point.chunk_by(|a, b| rings[a.0].0 == rings[b.0].0);
        for group in groups.filter(|_| found.overlaps.is_empty()) {
            for (i, &(a, _)) in group.iter().enumerate() {
                for &(b, _) in &group[i + 1..] {
                    touches.add(a, b, p.point);
                }
            }
            let first = group[0].0;
            for &(k, _) in &group[1..] {
                let (a, b) = (find(&mut joined, first), find(&mut joined, k));
                if a == b {
                    out.push(Problem {
                        message: format!(
                            "{} and {} meet here and are joined elsewhere too (directly or \
                             through other rings): the interior of polygon {} is not connected",
                            name(first),
                            name(k),
                            rings[k].0
                        ),
                        at: Some(p.point),
                        polygon: Some(rings[k].0),
                    });
                } else {
                    joined[a] = b;
                }
            }
        }
    }
    if !out.is_empty() {
        return Ok(out);
    }
    touches.sort();
    // The rings of each polygon (numbered polygon by polygon, the shell first).
    let mut spans: Vec<Range<usize>> = Vec::new();
    for group in rings.chunk_by(|a, b| a.0 == b.0) {
        let start = spans.last().map_or(0, |s| s.end);
        spans.push(start..start + group.len());
    }
    let before = out.len();
    let outside = holes_outside_shells(&rings, &spans, &touches, &mut out);
    holes_inside_holes(&rings, &spans, &touches, &outside, &mut out);
    let hole_problems = out.len() > before;
    // Interiors of polygons overlapping: a face covered twice.
    let d = boolean_dcel(
        &without_empty_rings(polygons),
        &MultiPolygon::default(),
        FillRule::Positive,
    )?;
    overlapping_polygons(&d, &rings, &spans, &mut out);
    // (With every hole inside its shell and none inside another, no face is inside more
    // holes than shells: shells count +1, holes -1.)
    debug_assert!(
        hole_problems || d.face_ids().all(|f| d.face(f).data.0 >= 0),
        "a face inside more holes than shells, and no hole reported"
    );
    // Orientation (RFC 7946).
    for (pi, ri, r) in &rings {
        let want = if *ri == 0 {
            Orientation::CounterClockwise
        } else {
            Orientation::Clockwise
        };
        if ring_orientation(r) != want {
            out.push(Problem {
                message: format!(
                    "{}: should be {} (RFC 7946)",
                    ring_name(*pi, *ri),
                    if *ri == 0 {
                        "counter-clockwise"
                    } else {
                        "clockwise"
                    }
                ),
                at: r.first().copied(),
                polygon: Some(*pi),
            });
        }
    }
    Ok(out)
}

/// A ring of the polygons checked: its polygon, its number in the polygon (0 the shell),
/// its points.
type Ring = (usize, usize, Vec<Point2>);

/// `polygons` without their empty holes and empty polygons (which the checks skip).
fn without_empty_rings(polygons: &MultiPolygon) -> Cow<'_, MultiPolygon> {
    if !polygons.0.iter().flat_map(|p| p.rings()).any(Vec::is_empty) {
        return Cow::Borrowed(polygons);
    }
    let kept = polygons.0.iter().filter(|p| !p.rings().all(Vec::is_empty));
    Cow::Owned(MultiPolygon(
        kept.map(|p| {
            let holes = p.holes.iter().filter(|h| !h.is_empty()).cloned();
            Polygon::new(p.exterior.clone(), holes.collect())
        })
        .collect(),
    ))
}

/// The class of ring `k` in the union–find `parent`.
fn find(parent: &mut [usize], mut k: usize) -> usize {
    while parent[k] != k {
        parent[k] = parent[parent[k]];
        k = parent[k];
    }
    k
}

fn on_ring(ring: &[Point2], q: Point2) -> bool {
    (0..ring.len()).any(|i| {
        let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
        orient2d(a, b, q) == Orientation::Collinear
            && q.x >= a.x.min(b.x)
            && q.x <= a.x.max(b.x)
            && q.y >= a.y.min(b.y)
            && q.y <= a.y.max(b.y)
    })
}
