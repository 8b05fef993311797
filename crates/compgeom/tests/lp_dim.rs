//! LP in d dimensions: against the 2D solver and the 2D oracle, and in 3D against an exact
//! brute force (every triple of constraint planes).

mod lp_oracle;

use compgeom::lp::{lp2d, lp_d, HalfPlane, Lp2Options, Lp2Solution, LpSolution};
use compgeom::Vector2;
use lp_oracle::*;
use num_traits::Zero;
use proptest::prelude::*;

/// Solve a 3x3 system exactly (Cramer), if regular.
fn solve3(m: [[Q; 3]; 3], b: [Q; 3]) -> Option<[Q; 3]> {
    let det = |m: &[[Q; 3]; 3]| {
        &m[0][0] * (&m[1][1] * &m[2][2] - &m[1][2] * &m[2][1])
            - &m[0][1] * (&m[1][0] * &m[2][2] - &m[1][2] * &m[2][0])
            + &m[0][2] * (&m[1][0] * &m[2][1] - &m[1][1] * &m[2][0])
    };
    let d = det(&m);
    if d.is_zero() {
        return None;
    }
    let mut x: [Q; 3] = [Q::zero(), Q::zero(), Q::zero()];
    for (k, xk) in x.iter_mut().enumerate() {
        let mut mk = m.clone();
        for i in 0..3 {
            mk[i][k] = b[i].clone();
        }
        *xk = det(&mk) / &d;
    }
    Some(x)
}

fn box3(rows: &mut Vec<Vec<f64>>, r: f64) {
    for j in 0..3 {
        let mut up = vec![0.0; 4];
        up[j] = 1.0;
        up[3] = r;
        let mut down = vec![0.0; 4];
        down[j] = -1.0;
        down[3] = r;
        rows.push(up);
        rows.push(down);
    }
}

fn row3() -> impl Strategy<Value = Vec<f64>> {
    (-3i8..=3, -3i8..=3, -3i8..=3, -4i8..=6)
        .prop_map(|(a, b, c, d)| vec![a as f64, b as f64, c as f64, d as f64])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(150))]

    #[test]
    fn three_d_bounded_against_brute_force(mut rows in prop::collection::vec(row3(), 0..7), c in (-2i8..=2, -2i8..=2, -2i8..=2), seed in any::<u64>()) {
        prop_assume!(c != (0, 0, 0));
        box3(&mut rows, 5.0);
        let cv = [c.0 as f64, c.1 as f64, c.2 as f64];
        let got = lp_d(&rows, &cv, seed).unwrap();
        let q: Vec<Vec<Q>> = rows.iter().map(|r| r.iter().map(|&v| r_(v)).collect()).collect();
        let mut best: Option<(Q, [Q; 3])> = None;
        for i in 0..q.len() {
            for j in i + 1..q.len() {
                for k in j + 1..q.len() {
                    let m = [0, 1, 2].map(|t| [q[i][t].clone(), q[j][t].clone(), q[k][t].clone()]);
                    let m = [[m[0][0].clone(), m[1][0].clone(), m[2][0].clone()], [m[0][1].clone(), m[1][1].clone(), m[2][1].clone()], [m[0][2].clone(), m[1][2].clone(), m[2][2].clone()]];
                    let Some(x) = solve3(m, [q[i][3].clone(), q[j][3].clone(), q[k][3].clone()]) else { continue };
                    if !q.iter().all(|r| &r[0] * &x[0] + &r[1] * &x[1] + &r[2] * &x[2] <= r[3]) { continue; }
                    let val = r_(cv[0]) * &x[0] + r_(cv[1]) * &x[1] + r_(cv[2]) * &x[2];
                    let better = match &best {
                        None => true,
                        Some((bv, bx)) => val > *bv || (val == *bv && x < *bx),
                    };
                    if better { best = Some((val, x)); }
                }
            }
        }
        match (best, got) {
            (None, LpSolution::Infeasible { certificate }) => prop_assert!(!certificate.is_empty()),
            (Some((val, x)), LpSolution::Optimal { point, value, constraints }) => {
                prop_assert_eq!(value, f(&val));
                prop_assert_eq!(point, x.iter().map(f).collect::<Vec<_>>());
                prop_assert!(constraints.len() >= 3);
            }
            (b, g) => prop_assert!(false, "expected {b:?}, got {g:?}"),
        }
    }

    #[test]
    fn two_d_agrees_with_the_oracle(hs in prop::collection::vec((-3i8..=3, -3i8..=3, -4i8..=4).prop_map(|(a, b, c)| HalfPlane::new(a as f64, b as f64, c as f64)), 0..8), c in (-2i8..=2, -2i8..=2), seed in any::<u64>()) {
        prop_assume!(c != (0, 0));
        let cv = (c.0 as f64, c.1 as f64);
        let rows: Vec<Vec<f64>> = hs.iter().map(|h| vec![h.a, h.b, h.c]).collect();
        let got = lp_d(&rows, &[cv.0, cv.1], seed).unwrap();
        let two = lp2d(&hs, Vector2::new(cv.0, cv.1), &Lp2Options { seed }).unwrap();
        match (oracle_lp(&hs, cv), got) {
            (Expected::Infeasible, LpSolution::Infeasible { certificate }) => {
                let sub: Vec<HalfPlane> = certificate.iter().map(|&i| hs[i]).collect();
                prop_assert!(!feasible(&sub));
            }
            (Expected::Unbounded, LpSolution::Unbounded { direction, .. }) => {
                let (dx, dy) = (direction[0], direction[1]);
                prop_assert!(cv.0 * dx + cv.1 * dy > 0.0);
                for h in &hs {
                    prop_assert!(h.a * dx + h.b * dy <= 1e-12);
                }
            }
            (Expected::Optimal { value, .. }, LpSolution::Optimal { value: v, point, .. }) => {
                prop_assert_eq!(v, f(&value));
                // Where the lexicographically smallest optimum exists both solvers report it.
                if let Lp2Solution::Optimal { point: p2, .. } = two {
                    if vertices(&hs).iter().any(|p| (f(&p.0), f(&p.1)) == (point[0], point[1])) {
                        prop_assert_eq!((p2.x, p2.y), (point[0], point[1]));
                    }
                }
            }
            (e, g) => prop_assert!(false, "expected {e:?}, got {g:?}"),
        }
    }
}

fn r_(x: f64) -> Q {
    r(x)
}

#[test]
fn one_and_four_dimensions() {
    // 1D: 2 <= x <= 7, maximize -x -> 2.
    let rows = vec![vec![1.0, 7.0], vec![-1.0, -2.0]];
    match lp_d(&rows, &[-1.0], 0).unwrap() {
        LpSolution::Optimal { point, value, .. } => {
            assert_eq!(point, vec![2.0]);
            assert_eq!(value, -2.0);
        }
        other => panic!("{other:?}"),
    }
    // 4D simplex x_i >= 0, sum x_i <= 1: maximize x_3.
    let mut rows = vec![vec![1.0, 1.0, 1.0, 1.0, 1.0]];
    for j in 0..4 {
        let mut r = vec![0.0; 5];
        r[j] = -1.0;
        rows.push(r);
    }
    match lp_d(&rows, &[0.0, 0.0, 1.0, 0.0], 3).unwrap() {
        LpSolution::Optimal { point, value, .. } => {
            assert_eq!(point, vec![0.0, 0.0, 1.0, 0.0]);
            assert_eq!(value, 1.0);
        }
        other => panic!("{other:?}"),
    }
    // Unbounded in 3D: only x >= 0.
    match lp_d(&[vec![-1.0, 0.0, 0.0, 0.0]], &[1.0, 0.0, 0.0], 0).unwrap() {
        LpSolution::Unbounded { direction, .. } => assert!(direction[0] > 0.0),
        other => panic!("{other:?}"),
    }
    // Infeasible: x <= 0 and x >= 1 in 3D.
    match lp_d(
        &[vec![1.0, 0.0, 0.0, 0.0], vec![-1.0, 0.0, 0.0, -1.0]],
        &[0.0, 1.0, 0.0],
        0,
    )
    .unwrap()
    {
        LpSolution::Infeasible { certificate } => assert_eq!(certificate, vec![0, 1]),
        other => panic!("{other:?}"),
    }
    assert!(lp_d(&[vec![1.0, 2.0]], &[1.0, 1.0], 0).is_err());
    assert!(lp_d(&[], &[0.0, 0.0], 0).is_err());
    assert!(lp_d(&[vec![1.0, f64::INFINITY, 0.0]], &[1.0, 1.0], 0).is_err());
}
