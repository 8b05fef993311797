//! Casting (book §4.1): which facets of a polyhedron can be the top facet of a one-piece
//! mould from which the cast object is removed by a single translation.
//!
//! By Lemma 4.1, with facet `t` on top the object can be removed in direction `d` iff
//! `d` makes an angle of at least 90° with the outward normal of every other (ordinary)
//! facet and points out of the top facet: `n_f·d <= 0` for all `f != t` and `n_t·d > 0`.
//! That is a linear feasibility problem in `d` (the book fixes the top facet's direction
//! and intersects half-planes in two dimensions; we solve the equivalent homogeneous
//! program in three). Per top facet the program is solved by the randomized LP of §4.5
//! over the facets' exact normals (integers): first in `f64` with the optimal basis
//! certified exactly, else exactly on integers — so the whole run takes O(n²) expected
//! time (Theorem 4.2) and every decision is exact. A unit box `|d_j| <= 1` keeps both
//! programs bounded.
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

use super::certify::{common_denominator, f64_row, irow_from_q, IRow};
use super::exact::{rat, to_f64};
use super::lpd::{run_fast_then_exact, Exact};
use super::Shuffler;
use crate::io::Polyhedron;
use crate::{Error, Location, Result};
use num_bigint::BigInt;
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
/// `at(f)` is where face `f` was read, if known: errors about a face then name that line.
pub(crate) fn check_closed_manifold(
    p: &Polyhedron,
    at: &dyn Fn(usize) -> Option<Location>,
) -> Result<Vec<[Q; 3]>> {
    let bad = |m: String| Err(Error::InvalidInput(m));
    let bad_face = |f: usize, m: String| match at(f) {
        Some(location) => Err(Error::parse(m, location)),
        None => Err(Error::InvalidInput(m)),
    };
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
                return bad_face(f, format!("face {f} uses a vertex index out of range"));
            }
            if u == v {
                return bad_face(f, format!("face {f} repeats vertex {u}"));
            }
            if let Some(g) = edges.insert((u, v), f) {
                return bad_face(
                    f,
                    format!(
                        "edge {u}-{v} is used in the same direction by faces {g} and {f}: the \
                         surface is not a consistently oriented 2-manifold"
                    ),
                );
            }
        }
    }
    // Faces in input order (not the map's order), so the same file gives the same message.
    for (f, face) in p.faces.iter().enumerate() {
        for k in 0..face.len() {
            let (u, v) = (face[k], face[(k + 1) % face.len()]);
            if !edges.contains_key(&(v, u)) {
                return bad_face(
                    f,
                    format!(
                        "edge {u}-{v} of face {f} has no opposite face: the surface is not \
                         closed (or not consistently oriented)"
                    ),
                );
            }
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
            return bad_face(f, format!("face {f} has zero area"));
        }
        let o = pt(face[0]);
        let h = dot(&n, &o);
        if face.iter().any(|&i| dot(&n, &pt(i)) != h) {
            return bad_face(f, format!("face {f} is not planar"));
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
    castability_with(p, &|_| None)
}

/// As [`castability`], for a polyhedron read from `source` with each face's line
/// ([`read_off_with_lines`](crate::io::read_off_with_lines)): an error about one face
/// ([`Error::Parse`]) names the file and that face's line.
///
/// ```
/// use compgeom::io::read_off_with_lines;
/// use compgeom::lp::castability_at;
/// // A cube without its top face: open.
/// let open = "OFF\n8 5 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n\
///             4 0 3 2 1\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
/// let (p, lines) = read_off_with_lines(open, "open.off")?;
/// let err = castability_at(&p, "open.off", &lines).unwrap_err().to_string();
/// assert!(err.contains("(open.off:12)"), "{err}");
/// # Ok::<(), compgeom::Error>(())
/// ```
pub fn castability_at(p: &Polyhedron, source: &str, face_lines: &[usize]) -> Result<Castability> {
    castability_with(p, &|f| {
        face_lines.get(f).map(|&line| Location::new(source, line))
    })
}

fn castability_with(p: &Polyhedron, at: &dyn Fn(usize) -> Option<Location>) -> Result<Castability> {
    let normals = check_closed_manifold(p, at)?;
    let facets: Vec<Facet> = normals.iter().map(Facet::new).collect();
    let mut top_facets = Vec::new();
    for t in 0..normals.len() {
        if let Some((d, interior)) = direction_for(&facets, t) {
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

/// A facet's outward normal `n = N / L` in integers (`L > 0`), with `f64` rows ready for
/// the two programs below: `[N, L, 0]` (margin rows) and `[N, 0]` (plain rows).
struct Facet {
    n: [BigInt; 3],
    l: BigInt,
    margin: Vec<f64>,
    plain: Vec<f64>,
}

impl Facet {
    fn new(n: &[Q; 3]) -> Facet {
        let l = common_denominator(n.iter());
        let r = irow_from_q(n, &Q::zero());
        let [n0, n1, n2]: [BigInt; 3] = [r.a[0].clone(), r.a[1].clone(), r.a[2].clone()];
        let margin = f64_row(&IRow {
            a: vec![n0.clone(), n1.clone(), n2.clone(), l.clone()],
            b: BigInt::zero(),
        });
        let plain = f64_row(&IRow {
            a: vec![n0.clone(), n1.clone(), n2.clone()],
            b: BigInt::zero(),
        });
        Facet {
            n: [n0, n1, n2],
            l,
            margin,
            plain,
        }
    }
}

/// A removal direction for top facet `t`: `(d, interior)`, or `None`.
fn direction_for(facets: &[Facet], t: usize) -> Option<(V3, bool)> {
    let z = BigInt::zero;
    let ft = &facets[t];
    let neg_t = Facet {
        n: [-&ft.n[0], -&ft.n[1], -&ft.n[2]],
        l: ft.l.clone(),
        margin: Vec::new(),
        plain: Vec::new(),
    };
    // First: maximize a margin s with n_f·d + s <= 0 (f != t), s - n_t·d <= 0,
    // n_t·d <= 1, s <= 1 — in integers N_f·d + L_f·s <= 0 and so on.
    let k = facets.len();
    let mut extra = vec![
        IRow {
            a: vec![
                neg_t.n[0].clone(),
                neg_t.n[1].clone(),
                neg_t.n[2].clone(),
                ft.l.clone(),
            ],
            b: z(),
        },
        IRow {
            a: vec![ft.n[0].clone(), ft.n[1].clone(), ft.n[2].clone(), z()],
            b: ft.l.clone(),
        },
        IRow {
            a: vec![z(), z(), z(), BigInt::from(1)],
            b: BigInt::from(1),
        },
    ];
    extra.extend(unit_box(4));
    let extra_f: Vec<Vec<f64>> = extra.iter().map(f64_row).collect();
    let margin_row = |f: usize| -> IRow {
        if f < k {
            let g = &facets[f];
            IRow {
                a: vec![g.n[0].clone(), g.n[1].clone(), g.n[2].clone(), g.l.clone()],
                b: z(),
            }
        } else {
            extra[f - k].clone()
        }
    };
    let ids = shuffled((0..k + extra.len()).filter(|&f| f != t).collect(), t as u64);
    let frows: Vec<&[f64]> = ids
        .iter()
        .map(|&f| {
            if f < k {
                facets[f].margin.as_slice()
            } else {
                extra_f[f - k].as_slice()
            }
        })
        .collect();
    let objective = [z(), z(), z(), BigInt::from(1)];
    if let Exact::Solved { x, .. } =
        run_fast_then_exact(&frows, EPS, |i| margin_row(ids[i]), &ids, &objective)
    {
        if x[3].is_positive() {
            return Some(([x[0].clone(), x[1].clone(), x[2].clone()], true));
        }
    }
    // No interior: maximize n_t·d with n_f·d <= 0 (f != t) and n_t·d <= 1.
    let top = IRow {
        a: ft.n.to_vec(),
        b: ft.l.clone(),
    };
    let mut extra = vec![top];
    extra.extend(unit_box(3));
    let extra_f: Vec<Vec<f64>> = extra.iter().map(f64_row).collect();
    let plain_row = |f: usize| -> IRow {
        if f < k {
            IRow {
                a: facets[f].n.to_vec(),
                b: z(),
            }
        } else {
            extra[f - k].clone()
        }
    };
    let ids = shuffled((0..k + extra.len()).filter(|&f| f != t).collect(), t as u64);
    let frows: Vec<&[f64]> = ids
        .iter()
        .map(|&f| {
            if f < k {
                facets[f].plain.as_slice()
            } else {
                extra_f[f - k].as_slice()
            }
        })
        .collect();
    match run_fast_then_exact(&frows, EPS, |i| plain_row(ids[i]), &ids, &ft.n) {
        Exact::Solved { x, .. } => {
            let d = [x[0].clone(), x[1].clone(), x[2].clone()];
            let nt = [
                Q::from_integer(ft.n[0].clone()),
                Q::from_integer(ft.n[1].clone()),
                Q::from_integer(ft.n[2].clone()),
            ];
            dot(&nt, &d).is_positive().then_some((d, false))
        }
        _ => None,
    }
}

/// Entries of [`f64_row`] are within `2^-50` of the row's largest entry.
const EPS: f64 = 1.0 / (1u64 << 50) as f64;

/// `±d_j <= 1` for the first three of `k` variables: keeps both programs bounded, so their
/// lexicographic optimum exists (and the fast path can certify it).
fn unit_box(k: usize) -> Vec<IRow> {
    let mut out = Vec::with_capacity(6);
    for j in 0..3 {
        for s in [1, -1] {
            let mut a = vec![BigInt::zero(); k];
            a[j] = BigInt::from(s);
            out.push(IRow {
                a,
                b: BigInt::from(1),
            });
        }
    }
    out
}

/// `v` in a seeded random order.
fn shuffled(mut v: Vec<usize>, seed: u64) -> Vec<usize> {
    Shuffler::new(seed).shuffle(&mut v);
    v
}
