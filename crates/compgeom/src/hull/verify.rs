//! The exact hull verifier (DESIGN §2.4).
//!
//! Checks, with exact comparisons and [`orient2d`] only, that a claimed hull is the convex
//! hull of the input in compgeom's output convention. Time O(n log h + h) after an O(n)
//! hashing pass: each input point is located in the fan of triangles around the first
//! vertex by binary search.

use crate::kernel::{compare_xy, ensure_finite, orient2d, Orientation, Point2};
use crate::{Error, Result};
use std::cmp::Ordering;
use std::collections::HashSet;

/// A hashable key for a point: its coordinate bits, with `-0.0` folded into `0.0` so that
/// equal points (by `==`) get equal keys.
pub(crate) fn key(p: Point2) -> (u64, u64) {
    ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits())
}

fn fail(msg: String) -> Result<()> {
    Err(Error::Verification(msg))
}

fn show(p: Point2) -> String {
    format!("({}, {})", p.x, p.y)
}

/// See [`super::verify_convex_hull`].
pub(crate) fn verify(points: &[Point2], hull: &[Point2], keep_collinear: bool) -> Result<()> {
    ensure_finite(points, "point")?;
    ensure_finite(hull, "hull vertex")?;
    let Some(&min) = points.iter().min_by(|a, b| compare_xy(**a, **b)) else {
        if hull.is_empty() {
            return Ok(());
        }
        return fail(format!(
            "the input is empty but the hull has {} vertices",
            hull.len()
        ));
    };
    if hull.is_empty() {
        return fail("the hull is empty but the input is not".into());
    }
    // Made of input points, none repeated.
    let input: HashSet<(u64, u64)> = points.iter().map(|&p| key(p)).collect();
    let mut seen = HashSet::with_capacity(hull.len());
    for (i, &v) in hull.iter().enumerate() {
        if !input.contains(&key(v)) {
            return fail(format!("hull vertex {i} {} is not an input point", show(v)));
        }
        if !seen.insert(key(v)) {
            return fail(format!(
                "hull vertex {i} {} repeats an earlier vertex",
                show(v)
            ));
        }
    }
    if hull[0] != min {
        return fail(format!(
            "the hull starts at {}, not at the lexicographically smallest input point {}",
            show(hull[0]),
            show(min)
        ));
    }
    if hull.len() == 1 {
        return match points.iter().position(|&p| p != hull[0]) {
            None => Ok(()),
            Some(j) => fail(format!(
                "input point {j} {} is not the single hull point",
                show(points[j])
            )),
        };
    }
    let (a, b) = (hull[0], hull[1]);
    if hull
        .iter()
        .all(|&v| orient2d(a, b, v) == Orientation::Collinear)
    {
        verify_flat(points, hull, keep_collinear, &seen)
    } else {
        verify_polygon(points, hull, keep_collinear, &seen)
    }
}

/// A hull with no area: the distinct points of a segment, from its smaller end.
fn verify_flat(
    points: &[Point2],
    hull: &[Point2],
    keep_collinear: bool,
    hull_keys: &HashSet<(u64, u64)>,
) -> Result<()> {
    let (first, last) = (hull[0], hull[hull.len() - 1]);
    if !keep_collinear && hull.len() > 2 {
        return fail(format!(
            "the hull is a segment but lists {} points (expected its 2 ends)",
            hull.len()
        ));
    }
    for i in 1..hull.len() {
        if compare_xy(hull[i - 1], hull[i]) != Ordering::Less {
            return fail(format!(
                "the segment hull is not in increasing order at vertex {i} {}",
                show(hull[i])
            ));
        }
    }
    for (j, &p) in points.iter().enumerate() {
        let on_segment = orient2d(first, last, p) == Orientation::Collinear
            && compare_xy(first, p) != Ordering::Greater
            && compare_xy(p, last) != Ordering::Greater;
        if !on_segment {
            return fail(format!(
                "input point {j} {} lies outside the segment hull {}–{}",
                show(p),
                show(first),
                show(last)
            ));
        }
        if keep_collinear && !hull_keys.contains(&key(p)) {
            return fail(format!(
                "input point {j} {} lies on the hull boundary but is missing (keep_collinear)",
                show(p)
            ));
        }
    }
    Ok(())
}

/// A hull with positive area.
fn verify_polygon(
    points: &[Point2],
    hull: &[Point2],
    keep_collinear: bool,
    hull_keys: &HashSet<(u64, u64)>,
) -> Result<()> {
    let h = hull.len();
    // Every turn is to the right; with keep_collinear a point may also sit straight between
    // its neighbours. Those that turn are the corners.
    let mut corners: Vec<Point2> = Vec::with_capacity(h);
    for i in 0..h {
        let (a, b, c) = (hull[(i + h - 1) % h], hull[i], hull[(i + 1) % h]);
        match orient2d(a, b, c) {
            Orientation::Clockwise => corners.push(b),
            Orientation::CounterClockwise => {
                return fail(format!(
                    "the hull turns counter-clockwise at vertex {i} {} (not clockwise convex)",
                    show(b)
                ))
            }
            Orientation::Collinear => {
                let forward =
                    compare_xy(a, b) != Ordering::Equal && compare_xy(a, b) == compare_xy(b, c);
                if !keep_collinear {
                    return fail(format!("hull vertex {i} {} is collinear", show(b)));
                }
                if !forward {
                    return fail(format!(
                        "hull vertex {i} {} doubles back along its edge",
                        show(b)
                    ));
                }
            }
        }
    }
    // hull[0] is the smallest input point, so it is a corner and corners[0]. The other
    // corners must be in clockwise angular order around it (this rules out a polygon that
    // winds around more than once).
    let m = corners.len();
    if m < 3 {
        return fail(format!("the hull has only {m} corners but is not flat"));
    }
    let o = corners[0];
    if o != hull[0] {
        return fail(format!("hull vertex 0 {} is not a corner", show(o)));
    }
    for i in 1..m - 1 {
        if orient2d(o, corners[i], corners[i + 1]) != Orientation::Clockwise {
            return fail(format!(
                "the hull winds around more than once (at corner {} {})",
                i + 1,
                show(corners[i + 1])
            ));
        }
    }
    // Containment, by binary search in the fan around `o`. Every input point is at least
    // `o` lexicographically, so all directions from `o` lie in a half-plane and angular
    // comparisons by orient2d are consistent.
    for (j, &p) in points.iter().enumerate() {
        let boundary = match locate(&corners, p) {
            Place::Inside => false,
            Place::Boundary => true,
            Place::Outside(k) => {
                return fail(format!(
                    "input point {j} {} lies outside the hull (beyond the edge from corner {k})",
                    show(p)
                ))
            }
        };
        if boundary && keep_collinear && !hull_keys.contains(&key(p)) {
            return fail(format!(
                "input point {j} {} lies on the hull boundary but is missing (keep_collinear)",
                show(p)
            ));
        }
    }
    Ok(())
}

enum Place {
    Inside,
    Boundary,
    /// Outside, beyond the edge that starts at this corner index.
    Outside(usize),
}

/// Where `p` lies relative to the strictly convex clockwise polygon `c` (c\[0\] its
/// lexicographically smallest vertex, `p` not smaller).
fn locate(c: &[Point2], p: Point2) -> Place {
    let m = c.len();
    let o = c[0];
    if p == o {
        return Place::Boundary;
    }
    if compare_xy(p, o) == Ordering::Less {
        return Place::Outside(m - 1);
    }
    // Right of the first edge o→c1 and left of the closing ray o→c[m-1].
    match orient2d(o, c[1], p) {
        Orientation::CounterClockwise => return Place::Outside(0),
        Orientation::Collinear => return on_edge_or_beyond(o, c[1], p, 0),
        Orientation::Clockwise => {}
    }
    match orient2d(o, c[m - 1], p) {
        Orientation::Clockwise => return Place::Outside(m - 1),
        Orientation::Collinear => return on_edge_or_beyond(o, c[m - 1], p, m - 1),
        Orientation::CounterClockwise => {}
    }
    // Strictly between the rays o→c1 and o→c[m-1]: find the wedge o, c[lo], c[lo+1].
    let (mut lo, mut hi) = (1, m - 1);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if orient2d(o, c[mid], p) == Orientation::CounterClockwise {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    match orient2d(c[lo], c[lo + 1], p) {
        Orientation::Clockwise => Place::Inside,
        Orientation::Collinear => Place::Boundary,
        Orientation::CounterClockwise => Place::Outside(lo),
    }
}

/// `p` is on the line through the corner `o` and the corner `v`, on `v`'s side of `o`:
/// on the edge up to `v`, outside beyond it.
fn on_edge_or_beyond(o: Point2, v: Point2, p: Point2, edge: usize) -> Place {
    let towards = compare_xy(o, v);
    if compare_xy(p, v) == towards || compare_xy(p, v) == Ordering::Equal {
        Place::Boundary
    } else {
        Place::Outside(edge)
    }
}
