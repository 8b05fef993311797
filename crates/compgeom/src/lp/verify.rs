//! Exact verifiers for the two-dimensional results (DESIGN §2.4).

use super::exact::{cross2_sign, meet_exact, side, to_f64, Line};
use super::{intersect_halfplanes, lp2d, HalfPlane, Lp2Options, Lp2Solution, Region, RegionKind};
use crate::kernel::Vector2;
use crate::{Error, Result};
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

fn fail<T>(m: String) -> Result<T> {
    Err(Error::Verification(m))
}

fn line(h: &HalfPlane) -> Line {
    Line::input(h.a, h.b, h.c)
}

/// The exact meeting point of constraints `i` and `j` is inside every half-plane.
fn corner_feasible(hs: &[HalfPlane], i: usize, j: usize) -> Result<()> {
    let (li, lj) = (line(&hs[i]), line(&hs[j]));
    if super::exact::cross_sign(&li, &lj) == Ordering::Equal {
        return fail(format!(
            "constraints {i} and {j} are parallel: they meet in no corner"
        ));
    }
    for (k, h) in hs.iter().enumerate() {
        if side(&li, &lj, &line(h)) == Ordering::Greater {
            return fail(format!(
                "the corner of constraints {i} and {j} violates constraint {k}"
            ));
        }
    }
    Ok(())
}

/// Check a two-dimensional LP answer exactly.
///
/// - optimal: the defining constraints meet in a corner that satisfies every constraint, it
///   rounds to the reported point, and the objective is a non-negative combination of the
///   defining constraints' normals (so no feasible point is better); for a one-constraint
///   (line) optimum, the objective is a positive multiple of its normal;
/// - unbounded: the direction keeps every constraint (`a·d <= 0`) and improves (`c·d > 0`);
/// - infeasible: the certificate's constraints alone have an empty intersection.
///
/// Errors: [`Error::Verification`] naming the first broken condition.
pub fn verify_lp2d(hs: &[HalfPlane], objective: Vector2, solution: &Lp2Solution) -> Result<()> {
    let q = |x: f64| super::exact::rat(x);
    let (cx, cy) = (q(objective.x), q(objective.y));
    match solution {
        Lp2Solution::Optimal {
            point, constraints, ..
        } => match constraints[..] {
            [i, j] if i < hs.len() && j < hs.len() => {
                corner_feasible(hs, i, j)?;
                let ((x, y), _) = meet_exact(&line(&hs[i]), &line(&hs[j]));
                if (to_f64(&x), to_f64(&y)) != (point.x, point.y) {
                    return fail("the reported point is not the defining corner".into());
                }
                // c = l1·n_i + l2·n_j (Cramer) with l1, l2 >= 0.
                let (ai, bi, aj, bj) = (q(hs[i].a), q(hs[i].b), q(hs[j].a), q(hs[j].b));
                let d = &ai * &bj - &aj * &bi;
                let l1 = (&cx * &bj - &aj * &cy) / &d;
                let l2 = (&ai * &cy - &cx * &bi) / &d;
                if l1.is_negative() || l2.is_negative() {
                    return fail("the objective is not in the cone of the tight normals".into());
                }
                Ok(())
            }
            [i] if i < hs.len() => {
                let (a, b) = (q(hs[i].a), q(hs[i].b));
                let cross = &cx * &b - &cy * &a;
                let dot = &cx * &a + &cy * &b;
                if !cross.is_zero() || !dot.is_positive() {
                    return fail("the objective is not a positive multiple of the normal".into());
                }
                if lp2d(hs, Vector2::new(-hs[i].b, hs[i].a), &Lp2Options::default())
                    .map(|s| matches!(s, Lp2Solution::Infeasible { .. }))?
                {
                    return fail("the constraints are infeasible".into());
                }
                Ok(())
            }
            _ => fail("an optimum needs one or two defining constraints".into()),
        },
        Lp2Solution::Unbounded { direction, .. } => {
            // u·d as the cross product (ux, uy) × (-dy, dx), decided exactly.
            let dot = |ux: f64, uy: f64| cross2_sign(ux, uy, -direction.y, direction.x);
            if dot(objective.x, objective.y) != Ordering::Greater {
                return fail("the ray does not improve the objective".into());
            }
            for (k, h) in hs.iter().enumerate() {
                if dot(h.a, h.b) == Ordering::Greater {
                    return fail(format!("the ray leaves constraint {k}"));
                }
            }
            Ok(())
        }
        Lp2Solution::Infeasible { certificate } => {
            if certificate.iter().any(|&k| k >= hs.len()) {
                return fail("certificate index out of range".into());
            }
            let sub: Vec<HalfPlane> = certificate.iter().map(|&k| hs[k]).collect();
            if intersect_halfplanes(&sub, 0)?.kind != RegionKind::Empty {
                return fail("the certificate's constraints have a common point".into());
            }
            Ok(())
        }
    }
}

/// Check a half-plane intersection exactly: consecutive boundary constraints meet in the
/// reported corners (rounded), and every corner satisfies every constraint (so the
/// region's corners are right and the convex hull of them lies in the intersection).
/// An empty result is checked by an independent LP (infeasible).
///
/// Errors: [`Error::Verification`] naming the first broken condition.
pub fn verify_region(hs: &[HalfPlane], region: &Region) -> Result<()> {
    if region.constraints.iter().any(|&k| k >= hs.len()) {
        return fail("constraint index out of range".into());
    }
    let cs = &region.constraints;
    match region.kind {
        RegionKind::Empty => {
            let s = lp2d(hs, Vector2::new(1.0, 0.0), &Lp2Options::default())?;
            if !matches!(s, Lp2Solution::Infeasible { .. }) {
                return fail("the half-planes have a common point".into());
            }
        }
        RegionKind::Polygon => {
            if cs.len() != region.vertices.len() || cs.len() < 3 {
                return fail("a polygon needs as many edges as corners, at least 3".into());
            }
            for k in 0..cs.len() {
                let (i, j) = (cs[(k + cs.len() - 1) % cs.len()], cs[k]);
                corner_feasible(hs, i, j)?;
                let ((x, y), _) = meet_exact(&line(&hs[i]), &line(&hs[j]));
                let v = region.vertices[k];
                if (to_f64(&x), to_f64(&y)) != (v.x, v.y) {
                    return fail(format!(
                        "corner {k} is not where constraints {i} and {j} meet"
                    ));
                }
            }
        }
        _ => {
            // Corners of the other kinds: each reported corner is the meeting point of two
            // listed constraints and is feasible.
            for v in &region.vertices {
                let ok = cs.iter().enumerate().any(|(a, &i)| {
                    cs[a + 1..].iter().any(|&j| {
                        super::exact::cross_sign(&line(&hs[i]), &line(&hs[j])) != Ordering::Equal
                            && corner_feasible(hs, i, j).is_ok()
                            && {
                                let ((x, y), _) = meet_exact(&line(&hs[i]), &line(&hs[j]));
                                (to_f64(&x), to_f64(&y)) == (v.x, v.y)
                            }
                    })
                });
                if !ok {
                    return fail(format!(
                        "corner ({}, {}) is not a feasible meeting point",
                        v.x, v.y
                    ));
                }
            }
        }
    }
    Ok(())
}
