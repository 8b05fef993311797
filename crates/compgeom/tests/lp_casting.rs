//! Casting (book §4.1) on hand-made solids, against an exact brute force over candidate
//! directions (the extreme rays of the removal cone), and on broken meshes.

use compgeom::io::{read_off, Polyhedron};
use compgeom::lp::castability;
use compgeom::Point3;
use num_rational::BigRational as Q;
use num_traits::{Signed, Zero};

fn r(x: f64) -> Q {
    Q::from_float(x).unwrap()
}

type V = [Q; 3];

fn cross(a: &V, b: &V) -> V {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

fn dot(a: &V, b: &V) -> Q {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

/// Outward normals (the test solids are wound counter-clockwise seen from outside).
fn normals(p: &Polyhedron) -> Vec<V> {
    p.faces
        .iter()
        .map(|f| {
            let mut n: V = [Q::zero(), Q::zero(), Q::zero()];
            for k in 0..f.len() {
                let (a, b) = (p.vertices[f[k]], p.vertices[f[(k + 1) % f.len()]]);
                let c = cross(&[r(a.x), r(a.y), r(a.z)], &[r(b.x), r(b.y), r(b.z)]);
                for j in 0..3 {
                    n[j] += &c[j];
                }
            }
            n
        })
        .collect()
}

/// Brute force: is there d with n_t·d > 0 and n_f·d <= 0 for f != t? The candidates are the
/// extreme rays of the cone: ±(n_i × n_j), -n_i, and ±(n_i × e_k).
fn castable_brute(ns: &[V], t: usize) -> bool {
    let axes: Vec<V> = (0..3)
        .map(|k| {
            let mut e = [Q::zero(), Q::zero(), Q::zero()];
            e[k] = r(1.0);
            e
        })
        .collect();
    let mut cands: Vec<V> = Vec::new();
    for (i, a) in ns.iter().enumerate() {
        cands.push([-a[0].clone(), -a[1].clone(), -a[2].clone()]);
        for b in ns[i + 1..].iter().chain(axes.iter()) {
            let c = cross(a, b);
            cands.push([-c[0].clone(), -c[1].clone(), -c[2].clone()]);
            cands.push(c);
        }
    }
    cands.push(ns[t].clone());
    cands.iter().any(|d| {
        dot(&ns[t], d).is_positive()
            && ns
                .iter()
                .enumerate()
                .all(|(f, n)| f == t || !dot(n, d).is_positive())
    })
}

/// Extrude a counter-clockwise polygon in the (x, z) plane along y from 0 to 1.
fn extrude(poly: &[(f64, f64)]) -> Polyhedron {
    let n = poly.len();
    let mut vertices: Vec<Point3> = poly.iter().map(|&(x, z)| Point3::new(x, 0.0, z)).collect();
    vertices.extend(poly.iter().map(|&(x, z)| Point3::new(x, 1.0, z)));
    let mut faces = vec![
        (0..n).collect::<Vec<_>>(),
        (0..n).rev().map(|i| n + i).collect(),
    ];
    for i in 0..n {
        let j = (i + 1) % n;
        faces.push(vec![j, i, n + i, n + j]);
    }
    Polyhedron { vertices, faces }
}

fn check_against_brute_force(p: &Polyhedron) -> Vec<usize> {
    let got = castability(p).unwrap();
    let ns = normals(p);
    // The solid may be wound either way: orient the normals outward by the volume sign.
    let vol: Q = p
        .faces
        .iter()
        .zip(&ns)
        .map(|(f, n)| {
            let a = p.vertices[f[0]];
            dot(n, &[r(a.x), r(a.y), r(a.z)])
        })
        .sum();
    let ns: Vec<V> = if vol.is_negative() {
        ns.into_iter()
            .map(|n| [-n[0].clone(), -n[1].clone(), -n[2].clone()])
            .collect()
    } else {
        ns
    };
    let want: Vec<usize> = (0..ns.len()).filter(|&t| castable_brute(&ns, t)).collect();
    let have: Vec<usize> = got.top_facets.iter().map(|t| t.facet).collect();
    assert_eq!(have, want);
    assert_eq!(got.castable, !want.is_empty());
    for tf in &got.top_facets {
        let d = tf.direction;
        let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        assert!((len - 1.0).abs() < 1e-12);
        // The rounded direction satisfies the constraints up to rounding.
        for (f, n) in ns.iter().enumerate() {
            let v: f64 = (0..3)
                .map(|k| num_traits::ToPrimitive::to_f64(&n[k]).unwrap() * d[k])
                .sum();
            let scale: f64 = (0..3)
                .map(|k| num_traits::ToPrimitive::to_f64(&n[k]).unwrap().abs())
                .sum();
            if f == tf.facet {
                assert!(v > 0.0);
            } else {
                assert!(v <= 1e-12 * scale, "facet {f}: {v}");
                if tf.interior {
                    assert!(v < 0.0);
                }
            }
        }
    }
    have
}

const CUBE: &str = "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n\
4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

#[test]
fn cube_is_castable_from_every_face() {
    let cube = read_off(CUBE, "cube.off").unwrap();
    assert_eq!(check_against_brute_force(&cube), vec![0, 1, 2, 3, 4, 5]);
    let r = castability(&cube).unwrap();
    assert_eq!(r.top_facets[0].direction, [0.0, 0.0, -1.0]);
    assert!(!r.top_facets[0].interior);
}

#[test]
fn pyramid_and_tetrahedron() {
    let pyramid = "OFF\n5 5 0\n0 0 0\n2 0 0\n2 2 0\n0 2 0\n1 1 1\n\
4 0 3 2 1\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n";
    let p = read_off(pyramid, "pyramid.off").unwrap();
    let have = check_against_brute_force(&p);
    assert!(
        have.contains(&0),
        "the base as top facet: pull straight down"
    );
    let r = castability(&p).unwrap();
    assert!(r.top_facets.iter().find(|t| t.facet == 0).unwrap().interior);
    let tetra = "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
    let t = read_off(tetra, "t.off").unwrap();
    assert_eq!(check_against_brute_force(&t), vec![0, 1, 2, 3]);
}

#[test]
fn a_t_shape_has_an_undercut() {
    // A T in the (x, z) plane: a stem 1 wide below a bar 3 wide, extruded along y.
    let t = [
        (1.0, 0.0),
        (2.0, 0.0),
        (2.0, 2.0),
        (3.0, 2.0),
        (3.0, 3.0),
        (0.0, 3.0),
        (0.0, 2.0),
        (1.0, 2.0),
    ];
    let p = extrude(&t);
    let have = check_against_brute_force(&p);
    // Faces: 0, 1 caps; 2 + i is the side from vertex i to i + 1. Side 2 + 0 is the stem's
    // bottom (z = 0): the bar's underside blocks pulling down. Side 2 + 4 is the bar's top.
    assert!(!have.contains(&2));
    assert!(have.contains(&6));
    // An L-shaped prism lying on its long leg, and a non-convex star-like prism.
    let l = [
        (0.0, 0.0),
        (3.0, 0.0),
        (3.0, 1.0),
        (1.0, 1.0),
        (1.0, 2.0),
        (0.0, 2.0),
    ];
    check_against_brute_force(&extrude(&l));
    let star = [
        (0.0, 0.0),
        (2.0, 1.0),
        (4.0, 0.0),
        (3.0, 2.0),
        (4.0, 4.0),
        (2.0, 3.0),
        (0.0, 4.0),
        (1.0, 2.0),
    ];
    check_against_brute_force(&extrude(&star));
}

#[test]
fn broken_meshes_are_errors() {
    // Open: the cube without its top.
    let open = "OFF\n8 5 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n\
4 0 3 2 1\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
    let e = castability(&read_off(open, "o.off").unwrap()).unwrap_err();
    assert!(
        e.to_string().contains("closed") || e.to_string().contains("faces"),
        "{e}"
    );
    // One face turned over.
    let flipped = CUBE.replace("4 4 5 6 7", "4 7 6 5 4");
    let e = castability(&read_off(&flipped, "f.off").unwrap()).unwrap_err();
    assert!(e.to_string().contains("oriented"), "{e}");
    // Non-manifold: a face used twice (three faces at an edge).
    let twice = CUBE.replace("8 6 0", "8 7 0").to_string() + "4 4 5 6 7\n";
    assert!(castability(&read_off(&twice, "t.off").unwrap()).is_err());
    // A non-planar quad.
    let bent = CUBE.replace("1 1 1\n0 1 1", "1 1 1.5\n0 1 1");
    let e = castability(&read_off(&bent, "b.off").unwrap()).unwrap_err();
    assert!(e.to_string().contains("planar"), "{e}");
    // Inward winding is accepted (flipped), with the same answer.
    let inward: String = {
        let p = read_off(CUBE, "c.off").unwrap();
        let q = Polyhedron {
            vertices: p.vertices.clone(),
            faces: p
                .faces
                .iter()
                .map(|f| f.iter().rev().copied().collect())
                .collect(),
        };
        let r = castability(&q).unwrap();
        format!("{}", r.top_facets.len())
    };
    assert_eq!(inward, "6");
}
