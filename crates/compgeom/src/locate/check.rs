//! The precondition of point location: segments that do not cross, checked exactly
//! with the intersection sweep of [`crate::intersect`] (O((n + k) log n), stopping at the
//! first offending point).
use crate::intersect::{any_intersection_where, IntersectionPoint};
use crate::kernel::{Point2, Segment2};
use crate::{Error, Result};

/// The two segments to name for an intersection point: one having it in its interior
/// (or the first) and another one through it.
fn pair(p: &IntersectionPoint) -> (usize, usize) {
    let first = p.interior().first().copied().unwrap_or(p.segments()[0]);
    let other = p
        .segments()
        .iter()
        .copied()
        .find(|&s| s != first)
        .unwrap_or(first);
    (first.min(other), first.max(other))
}

/// `Ok` when no two of the closed `segments` share a point other than a common endpoint
/// (no crossing, no overlap, no endpoint inside another segment); zero-length segments
/// are not looked at. Otherwise `Err` naming the first offending pair (by input index,
/// in sweep order) and the point.
///
/// ```
/// use compgeom::locate::check_interior_disjoint_segments;
/// use compgeom::Segment2;
/// let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
/// assert!(check_interior_disjoint_segments(&[s((0., 0.), (1., 1.)), s((1., 1.), (2., 0.))]).is_ok());
/// let e = check_interior_disjoint_segments(&[s((0., 0.), (2., 2.)), s((0., 2.), (2., 0.))]).unwrap_err();
/// assert!(e.to_string().contains("segments 0 and 1"));
/// ```
pub fn check_interior_disjoint_segments(segments: &[Segment2]) -> Result<()> {
    let kept: Vec<usize> = (0..segments.len())
        .filter(|&i| segments[i].a != segments[i].b)
        .collect();
    let segs: Vec<Segment2> = kept.iter().map(|&i| segments[i]).collect();
    report(&segs, &kept, |p| !p.interior().is_empty())
}

/// As [`check_interior_disjoint_segments`] for the prepared segments of a map (distinct
/// points; duplicates removed). `seg_input` gives the input index of each segment.
pub(crate) fn check_interior_disjoint(
    points: &[Point2],
    segs: &[[u32; 2]],
    seg_input: &[usize],
) -> Result<()> {
    let segments: Vec<Segment2> = segs
        .iter()
        .map(|&[a, b]| Segment2::new(points[a as usize], points[b as usize]))
        .collect();
    report(&segments, seg_input, |p| !p.interior().is_empty())
}

/// `Ok` when no two `segments` cross at a point interior to both (touching, shared
/// endpoints, an endpoint on another segment and collinear overlaps are allowed: a
/// subdivision built from them has only input points as vertices). Otherwise `Err`
/// naming the first crossing pair (by input index) and the crossing, rounded.
///
/// ```
/// use compgeom::locate::check_no_crossings;
/// use compgeom::Segment2;
/// let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
/// // A T-junction and an overlap are fine; a proper crossing is not.
/// assert!(check_no_crossings(&[s((0., 0.), (2., 0.)), s((1., 0.), (1., 1.)), s((1., 0.), (3., 0.))]).is_ok());
/// assert!(check_no_crossings(&[s((0., 0.), (2., 2.)), s((0., 2.), (2., 0.))]).is_err());
/// ```
pub fn check_no_crossings(segments: &[Segment2]) -> Result<()> {
    match first_crossing(segments)? {
        None => Ok(()),
        Some((a, b, at)) => Err(Error::InvalidInput(format!(
            "segments {a} and {b} cross at about ({}, {}); point location needs non-crossing segments",
            at.x, at.y
        ))),
    }
}

/// The first pair of `segments` (by index, `a < b`) crossing at a point interior to
/// both, and the crossing rounded; `None` when no two cross (as [`check_no_crossings`]).
pub(crate) fn first_crossing(segments: &[Segment2]) -> Result<Option<(usize, usize, Point2)>> {
    let p = any_intersection_where(segments, IntersectionPoint::is_crossing)?;
    Ok(p.map(|p| {
        let (a, b) = pair(&p);
        (a, b, p.point)
    }))
}

fn report(
    segments: &[Segment2],
    input: &[usize],
    counts: impl FnMut(&IntersectionPoint) -> bool,
) -> Result<()> {
    match any_intersection_where(segments, counts)? {
        None => Ok(()),
        Some(p) => {
            let (a, b) = pair(&p);
            let (a, b) = (input[a].min(input[b]), input[a].max(input[b]));
            let what = if p.interior().len() >= 2 {
                "cross at about"
            } else {
                "share a point that is not a common endpoint:"
            };
            Err(Error::InvalidInput(format!(
                "segments {a} and {b} {what} ({}, {}); point location needs non-crossing segments",
                p.point.x, p.point.y
            )))
        }
    }
}
