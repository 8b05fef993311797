//! The exact O(n²) oracle: every pair of segments through the kernel's
//! [`segment_intersection`], then grouping of equal points (exact comparisons) and the
//! maximal overlap pieces of each family of collinear overlapping segments. It defines
//! the expected answer of [`super::find_intersections`] and backs `--verify`.
//!
//! O(n² + K log K) time for K meeting pairs, O(n + K) space.

use super::order::{sweep_cmp_points, EventPoint, Oriented};
use super::pairwise::PARALLEL_GROUPING_FROM;
use super::small_int::{self, Hom};
use super::sweep::check_finite;
use super::{sort_overlaps, IntersectionPoint, Intersections, Overlap};
use crate::kernel::{segment_intersection, ExactPoint, Segment2, SegmentIntersection};
use crate::{Error, Result};
use rayon::prelude::*;
use std::cmp::Ordering;

/// All intersection points and overlaps by testing every pair of segments: the same
/// answer as [`super::find_intersections`], in O(n²) time.
pub fn brute_force_intersections(segments: &[Segment2]) -> Result<Intersections> {
    check_finite(segments)?;
    let mut found = PairResults::default();
    for i in 0..segments.len() {
        for j in i + 1..segments.len() {
            found.test(segments, i, j);
        }
    }
    Ok(found.assemble(segments))
}

/// What the pairs that meet contribute: one record per (point, pair), and the pairs that
/// overlap.
#[derive(Default)]
pub(crate) struct PairResults {
    records: Vec<(EventPoint, usize, usize)>,
    overlapping: Vec<(usize, usize)>,
}

impl PairResults {
    /// Test segments `i < j` exactly and record how they meet.
    pub(crate) fn test(&mut self, segments: &[Segment2], i: usize, j: usize) {
        match segment_intersection(segments[i], segments[j]) {
            SegmentIntersection::None => {}
            SegmentIntersection::Endpoint(q) => self.records.push((EventPoint::input(q), i, j)),
            SegmentIntersection::Crossing(c) => {
                self.records
                    .push((EventPoint::new(ExactPoint::Crossing(c)), i, j))
            }
            SegmentIntersection::Overlap(a, b) => {
                self.records.push((EventPoint::input(a), i, j));
                self.records.push((EventPoint::input(b), i, j));
                self.overlapping.push((i, j));
            }
        }
    }

    /// Both sets of results.
    pub(crate) fn merge(mut self, mut other: PairResults) -> PairResults {
        self.records.append(&mut other.records);
        self.overlapping.append(&mut other.overlapping);
        self
    }

    /// Group equal points (exactly), split their segments into U/L/C, and build the
    /// maximal overlap pieces.
    pub(crate) fn assemble(self, segments: &[Segment2]) -> Intersections {
        let segs: Vec<Oriented> = segments.iter().map(|&s| Oriented::of(s)).collect();
        let records = &self.records;
        // Sort a permutation, not the (large) records themselves.
        let mut order: Vec<usize> = (0..records.len()).collect();
        // Small-integer homogeneous coordinates, computed once per record: equal points
        // are common (grids) and each comparison would otherwise recompute them.
        let homs: Vec<Option<Hom>> = records.iter().map(|r| small_int::hom(&r.0.exact)).collect();
        let same_point = |a: usize, b: usize| match (homs[a], homs[b]) {
            (Some(p), Some(q)) => small_int::sweep_cmp(p, q),
            _ => records[a].0.cmp(&records[b].0),
        };
        let by_point = |a: &usize, b: &usize| {
            same_point(*a, *b)
                .then((records[*a].1, records[*a].2).cmp(&(records[*b].1, records[*b].2)))
        };
        // (rayon's parallel sort measured slower than this one on 2 cores.)
        order.sort_unstable_by(by_point);
        let parallel = records.len() >= PARALLEL_GROUPING_FROM;
        // Runs of equal points, then one intersection point per run.
        let mut starts = Vec::new();
        for k in 0..order.len() {
            if k == 0 || same_point(order[k], order[k - 1]) != Ordering::Equal {
                starts.push(k);
            }
        }
        starts.push(order.len());
        let point = |w: &[usize]| {
            let group: Vec<_> = order[w[0]..w[1]].iter().map(|&r| records[r]).collect();
            point_of(&segs, &group)
        };
        let points: Vec<IntersectionPoint> = if parallel {
            starts.par_windows(2).map(point).collect()
        } else {
            starts.windows(2).map(point).collect()
        };
        let mut overlaps = overlap_pieces(&segs, &self.overlapping);
        sort_overlaps(&mut overlaps);
        Intersections {
            points,
            overlaps,
            segments: segments.len(),
        }
    }
}

/// One intersection point from the records of the pairs that meet there.
fn point_of(segs: &[Oriented], group: &[(EventPoint, usize, usize)]) -> IntersectionPoint {
    // Prefer the input-point representation when the point is an endpoint.
    let at = group
        .iter()
        .map(|r| r.0)
        .find(|e| e.as_input().is_some())
        .unwrap_or(group[0].0);
    let mut all: Vec<usize> = group.iter().flat_map(|r| [r.1, r.2]).collect();
    all.sort_unstable();
    all.dedup();
    let (mut upper, mut lower, mut interior) = (Vec::new(), Vec::new(), Vec::new());
    for &s in &all {
        let (is_upper, is_lower) = match at.as_input() {
            Some(q) => (segs[s].upper == q, segs[s].lower == q),
            None => (false, false),
        };
        if is_upper {
            upper.push(s);
        }
        if is_lower {
            lower.push(s);
        }
        if !is_upper && !is_lower {
            interior.push(s);
        }
    }
    IntersectionPoint {
        point: at.approx(),
        exact: at.exact,
        segments: all,
        upper,
        lower,
        interior,
    }
}

fn find(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

/// The maximal pieces covered by the same two or more segments, per family of segments
/// linked by overlaps (such a family lies on one line).
fn overlap_pieces(segs: &[Oriented], overlapping: &[(usize, usize)]) -> Vec<Overlap> {
    let mut parent: Vec<usize> = (0..segs.len()).collect();
    for &(i, j) in overlapping {
        let (a, b) = (find(&mut parent, i), find(&mut parent, j));
        parent[a] = b;
    }
    let mut families: Vec<(usize, usize)> = Vec::new();
    let mut involved: Vec<usize> = overlapping.iter().flat_map(|&(i, j)| [i, j]).collect();
    involved.sort_unstable();
    involved.dedup();
    for &i in &involved {
        families.push((find(&mut parent, i), i));
    }
    families.sort_unstable();
    let mut out = Vec::new();
    let mut k = 0;
    while k < families.len() {
        let mut end = k + 1;
        while end < families.len() && families[end].0 == families[k].0 {
            end += 1;
        }
        let members: Vec<usize> = families[k..end].iter().map(|f| f.1).collect();
        let mut stops: Vec<_> = members
            .iter()
            .flat_map(|&m| [segs[m].upper, segs[m].lower])
            .collect();
        stops.sort_by(|a, b| sweep_cmp_points(*a, *b));
        stops.dedup_by(|a, b| sweep_cmp_points(*a, *b) == Ordering::Equal);
        let mut current: Option<Overlap> = None;
        for w in stops.windows(2) {
            let (a, b) = (w[0], w[1]);
            let cover: Vec<usize> = members
                .iter()
                .copied()
                .filter(|&m| {
                    sweep_cmp_points(segs[m].upper, a) != Ordering::Greater
                        && sweep_cmp_points(b, segs[m].lower) != Ordering::Greater
                })
                .collect();
            match &mut current {
                Some(o) if o.segments == cover => o.to = b,
                _ => {
                    out.extend(current.take());
                    if cover.len() >= 2 {
                        current = Some(Overlap {
                            segments: cover,
                            from: a,
                            to: b,
                        });
                    }
                }
            }
        }
        out.extend(current);
        k = end;
    }
    out
}

fn list(v: &[usize]) -> String {
    format!("{v:?}")
}

/// Check `found` against the exact brute-force answer (O(n²): meant for inputs of up to a
/// few thousand segments). The error names the first difference.
pub fn verify_intersections(segments: &[Segment2], found: &Intersections) -> Result<()> {
    let expected = brute_force_intersections(segments)?;
    let fail = |m: String| Err(Error::Verification(m));
    if found.segments != segments.len() {
        return fail(format!(
            "result is for {} segments, input has {}",
            found.segments,
            segments.len()
        ));
    }
    for (k, (f, e)) in found.points.iter().zip(&expected.points).enumerate() {
        let same_point = EventPoint::new(f.exact) == EventPoint::new(e.exact);
        if !same_point || f.point != e.point {
            return fail(format!(
                "intersection point {k} is ({}, {}), expected ({}, {})",
                f.point.x, f.point.y, e.point.x, e.point.y
            ));
        }
        let fields = [
            ("segments", &f.segments, &e.segments),
            ("upper", &f.upper, &e.upper),
            ("lower", &f.lower, &e.lower),
            ("interior", &f.interior, &e.interior),
        ];
        for (name, a, b) in fields {
            if a != b {
                return fail(format!(
                    "at intersection point {k} ({}, {}) {name} is {}, expected {}",
                    f.point.x,
                    f.point.y,
                    list(a),
                    list(b)
                ));
            }
        }
    }
    if found.points.len() != expected.points.len() {
        return fail(format!(
            "{} intersection points found, expected {}",
            found.points.len(),
            expected.points.len()
        ));
    }
    if found.overlaps != expected.overlaps {
        let k = found
            .overlaps
            .iter()
            .zip(&expected.overlaps)
            .position(|(a, b)| a != b)
            .unwrap_or(found.overlaps.len().min(expected.overlaps.len()));
        return fail(format!(
            "overlaps differ at {k}: found {:?}, expected {:?}",
            found.overlaps.get(k),
            expected.overlaps.get(k)
        ));
    }
    Ok(())
}
