//! Casting (book §4.1): which facets of a polyhedron can be the top facet of a one-piece
//! mould from which the cast object is removed by a single translation.
//!
//! By Lemma 4.1, with facet `t` on top the object can be removed in direction `d` iff
//! `d` makes an angle of at least 90° with the outward normal of every other (ordinary)
//! facet and points out of the top facet: `n_f·d <= 0` for all `f != t` and `n_t·d > 0`.
//! That is a linear feasibility problem in `d` (the book fixes the top facet's direction
//! and intersects half-planes in two dimensions; we solve the equivalent homogeneous
//! program in three). Per top facet the program is solved exactly by the randomized LP of
//! §4.5 over the facets' exact rational normals, so the whole run takes O(n²) expected time
//! (Theorem 4.2), with exact rational arithmetic (a large constant).
//!
//! The reported direction is an interior direction of the feasible cone (strictly away from
//! every ordinary facet) when the cone has interior, found by maximizing a common margin;
//! otherwise the cone is a ray or a flat wedge and a direction on it is reported. It is
//! returned as the nearest `f64` unit vector.
//!
//! # Checks on the input
//!
//! The polyhedron must be a closed, consistently oriented 2-manifold surface: every
//! directed edge used by exactly one face and its reverse by exactly one other, every face
//! planar with a non-zero area. Faces wound inward (negative volume) are flipped; zero
//! volume is an error. Self-intersections and vertices where two sheets touch are not
//! detected.

use super::exact::{rat, to_f64};
use super::lpd::{run_exact, Exact};
use crate::io::Polyhedron;
use crate::{Error, Result};
use num_rational::BigRational as Q;
use num_traits::{Signed, Zero};
use std::collections::HashMap;

/// A facet that can be the top facet, and a removal direction.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct TopFacet {
    /// Index of the facet (face) in the input.
    pub facet: usize,
    /// A unit removal direction (nearest `f64`).
    pub direction: [f64; 3],
    /// True when the direction is strictly away from every ordinary facet.
    pub interior: bool,
}

/// The castability of a polyhedron.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Castability {
    /// True when some facet works as the top facet.
    pub castable: bool,
    /// Every facet that works, in input order, each with a direction.
    pub top_facets: Vec<TopFacet>,
}

type V3 = [Q; 3];

fn cross(a: &V3, b: &V3) -> V3 {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

fn dot(a: &V3, b: &V3) -> Q {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

/// Check the surface and return each face's exact outward normal (twice its vector area).
pub(crate) fn check_closed_manifold(p: &Polyhedron) -> Result<Vec<[Q; 3]>> {
    let bad = |m: String| Err(Error::InvalidInput(m));
    if p.faces.len() < 4 {
        return bad(format!(
            "a closed polyhedron needs at least 4 faces, found {}",
            p.faces.len()
        ));
    }
    for (i, v) in p.vertices.iter().enumerate() {
        if !v.is_finite() {
            return Err(Error::NonFinite {
                what: format!("vertex {i}"),
                value: if v.x.is_finite() {
                    if v.y.is_finite() {
                        v.z
                    } else {
                        v.y
                    }
                } else {
                    v.x
                },
            });
        }
    }
    let mut edges: HashMap<(usize, usize), usize> = HashMap::new();
    for (f, face) in p.faces.iter().enumerate() {
        for k in 0..face.len() {
            let (u, v) = (face[k], face[(k + 1) % face.len()]);
            if u >= p.vertices.len() || v >= p.vertices.len() {
                return bad(format!("face {f} uses a vertex index out of range"));
            }
            if u == v {
                return bad(format!("face {f} repeats vertex {u}"));
            }
            if let Some(g) = edges.insert((u, v), f) {
                return bad(format!(
                    "edge {u}-{v} is used in the same direction by faces {g} and {f}: the \
                     surface is not a consistently oriented 2-manifold"
                ));
            }
        }
    }
    for (&(u, v), &f) in &edges {
        if !edges.contains_key(&(v, u)) {
            return bad(format!(
                "edge {u}-{v} of face {f} has no opposite face: the surface is not closed \
                 (or not consistently oriented)"
            ));
        }
    }
    let pt = |i: usize| -> V3 {
        let v = p.vertices[i];
        [rat(v.x), rat(v.y), rat(v.z)]
    };
    let mut normals = Vec::with_capacity(p.faces.len());
    let mut volume = Q::zero();
    for (f, face) in p.faces.iter().enumerate() {
        // Newell: the sum of v_k × v_{k+1} is twice the vector area of a planar polygon.
        let mut n: V3 = [Q::zero(), Q::zero(), Q::zero()];
        for k in 0..face.len() {
            let c = cross(&pt(face[k]), &pt(face[(k + 1) % face.len()]));
            for j in 0..3 {
                n[j] += &c[j];
            }
        }
        if n.iter().all(|x| x.is_zero()) {
            return bad(format!("face {f} has zero area"));
        }
        let o = pt(face[0]);
        let h = dot(&n, &o);
        if face.iter().any(|&i| dot(&n, &pt(i)) != h) {
            return bad(format!("face {f} is not planar"));
        }
        volume += h;
        normals.push(n);
    }
    if volume.is_zero() {
        return bad("the polyhedron has zero volume".into());
    }
    if volume.is_negative() {
        for n in &mut normals {
            for x in n.iter_mut() {
                *x = -x.clone();
            }
        }
    }
    Ok(normals)
}

/// For every facet as the top facet, decide castability (Lemma 4.1) and find a direction.
///
/// Errors ([`Error::InvalidInput`]): the surface is not a closed, consistently oriented
/// 2-manifold with planar faces (see the module docs).
///
/// ```
/// use compgeom::io::read_off;
/// use compgeom::lp::castability;
/// let cube = "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n\
///             4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
/// let r = castability(&read_off(cube, "cube.off")?)?;
/// assert!(r.castable);
/// assert_eq!(r.top_facets.len(), 6);
/// assert_eq!(r.top_facets[1].direction, [0.0, 0.0, 1.0]); // the top face: straight up
/// # Ok::<(), compgeom::Error>(())
/// ```
pub fn castability(p: &Polyhedron) -> Result<Castability> {
    let normals = check_closed_manifold(p)?;
    let mut top_facets = Vec::new();
    for t in 0..normals.len() {
        if let Some((d, interior)) = direction_for(&normals, t) {
            let len = d.iter().map(|x| to_f64(x).powi(2)).sum::<f64>().sqrt();
            let unit = [
                to_f64(&d[0]) / len,
                to_f64(&d[1]) / len,
                to_f64(&d[2]) / len,
            ];
            top_facets.push(TopFacet {
                facet: t,
                direction: unit,
                interior,
            });
        }
    }
    Ok(Castability {
        castable: !top_facets.is_empty(),
        top_facets,
    })
}

/// A removal direction for top facet `t`: `(d, interior)`, or `None`.
fn direction_for(normals: &[[Q; 3]], t: usize) -> Option<(V3, bool)> {
    let one = Q::from_integer(1.into());
    let nt = &normals[t];
    // First: maximize a margin s with n_f·d + s <= 0, s - n_t·d <= 0, n_t·d <= 1, s <= 1.
    let mut rows: Vec<(Vec<Q>, Q, usize)> = Vec::with_capacity(normals.len() + 2);
    for (f, n) in normals.iter().enumerate() {
        if f != t {
            rows.push((
                vec![n[0].clone(), n[1].clone(), n[2].clone(), one.clone()],
                Q::zero(),
                f,
            ));
        }
    }
    let k = normals.len();
    rows.push((
        vec![-nt[0].clone(), -nt[1].clone(), -nt[2].clone(), one.clone()],
        Q::zero(),
        k,
    ));
    rows.push((
        vec![nt[0].clone(), nt[1].clone(), nt[2].clone(), Q::zero()],
        one.clone(),
        k + 1,
    ));
    rows.push((
        vec![Q::zero(), Q::zero(), Q::zero(), one.clone()],
        one.clone(),
        k + 2,
    ));
    let objective = [Q::zero(), Q::zero(), Q::zero(), one.clone()];
    if let Exact::Solved { x, .. } = run_exact(rows, &objective, t as u64) {
        if x[3].is_positive() {
            return Some(([x[0].clone(), x[1].clone(), x[2].clone()], true));
        }
    }
    // No interior: maximize n_t·d with n_f·d <= 0 and n_t·d <= 1.
    let mut rows: Vec<(Vec<Q>, Q, usize)> = normals
        .iter()
        .enumerate()
        .filter(|&(f, _)| f != t)
        .map(|(f, n)| (n.to_vec(), Q::zero(), f))
        .collect();
    rows.push((nt.to_vec(), one, k));
    match run_exact(rows, nt, t as u64) {
        Exact::Solved { x, .. }
            if dot(nt, &[x[0].clone(), x[1].clone(), x[2].clone()]).is_positive() =>
        {
            Some(([x[0].clone(), x[1].clone(), x[2].clone()], false))
        }
        _ => None,
    }
}
