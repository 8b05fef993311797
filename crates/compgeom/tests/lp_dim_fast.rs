//! `lp_d`'s certified `f64` fast path against the exact integer algorithm (`lp_d_exact`):
//! identical answers on random and deliberately degenerate input (parallel, identical and
//! redundant constraints, integer grids, optima through many constraints), and the
//! treatment of zero normals.

mod common;
use compgeom::lp::{lp2d, lp_d, lp_d_exact, HalfPlane, Lp2Options, Lp2Solution, LpSolution};
use compgeom::Vector2;
use proptest::prelude::*;

/// A row of small integers `a1 .. ad b` (many parallel, identical, degenerate ones).
fn int_row(d: usize) -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(-3i8..=3, d + 1).prop_map(|v| v.into_iter().map(f64::from).collect())
}

/// A row of random reals (generic position) with the origin strictly inside.
fn real_row(d: usize) -> impl Strategy<Value = Vec<f64>> {
    (prop::collection::vec(-1.0f64..1.0, d), 0.1f64..2.0).prop_map(|(mut a, b)| {
        a.push(b);
        a
    })
}

/// The same program with its constraints repeated, scaled and shuffled by `k`.
fn with_duplicates(rows: &[Vec<f64>], k: usize) -> Vec<Vec<f64>> {
    let mut out = rows.to_vec();
    for (i, r) in rows.iter().enumerate() {
        if i % 3 == k % 3 {
            out.push(r.iter().map(|v| v * 2.0).collect());
            out.push(r.clone());
        }
    }
    out
}

fn same(rows: &[Vec<f64>], c: &[f64], seed: u64) -> Result<(), TestCaseError> {
    let fast = lp_d(rows, c, seed).unwrap();
    let exact = lp_d_exact(rows, c, seed).unwrap();
    match (&fast, &exact) {
        (LpSolution::Infeasible { .. }, LpSolution::Infeasible { .. }) => {}
        _ => prop_assert_eq!(&fast, &exact),
    }
    // The answer does not depend on the insertion order (except infeasibility witnesses).
    if let LpSolution::Optimal { .. } = exact {
        prop_assert_eq!(&lp_d(rows, c, seed ^ 0xabc).unwrap(), &exact);
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(120))]

    #[test]
    fn integer_grid_three_d(rows in prop::collection::vec(int_row(3), 0..14), c in prop::collection::vec(-2i8..=2, 3), seed in any::<u64>(), k in 0usize..3) {
        prop_assume!(c.iter().any(|&v| v != 0));
        let c: Vec<f64> = c.into_iter().map(f64::from).collect();
        same(&rows, &c, seed)?;
        same(&with_duplicates(&rows, k), &c, seed)?;
    }

    #[test]
    fn bounded_cube_with_cuts(cuts in prop::collection::vec(int_row(3), 0..10), c in prop::collection::vec(-2i8..=2, 3), seed in any::<u64>()) {
        prop_assume!(c.iter().any(|&v| v != 0));
        // A box -2 <= x_j <= 2 plus integer cuts: bounded, often degenerate optima.
        let mut rows = Vec::new();
        for j in 0..3 {
            for s in [1.0, -1.0] {
                let mut r = vec![0.0; 4];
                r[j] = s;
                r[3] = 2.0;
                rows.push(r);
            }
        }
        rows.extend(cuts);
        let c: Vec<f64> = c.into_iter().map(f64::from).collect();
        same(&rows, &c, seed)?;
    }

    #[test]
    fn random_reals_two_to_four_d(d in 2usize..=4, rows in prop::collection::vec(real_row(4), 1..60), c in prop::collection::vec(-1.0f64..1.0, 4), seed in any::<u64>()) {
        let rows: Vec<Vec<f64>> = rows.iter().map(|r| { let mut v = r[..d].to_vec(); v.push(r[4]); v }).collect();
        let c = &c[..d];
        prop_assume!(c.iter().any(|&v| v != 0.0));
        same(&rows, c, seed)?;
    }

    #[test]
    fn two_d_matches_lp2d(hs in prop::collection::vec(int_row(2), 0..12), c in (-2i8..=2, -2i8..=2), seed in any::<u64>()) {
        prop_assume!(c != (0, 0));
        let (cx, cy) = (f64::from(c.0), f64::from(c.1));
        same(&hs, &[cx, cy], seed)?;
        // Where both promise the lexicographically smallest optimal vertex, they agree.
        let planes: Vec<HalfPlane> = hs.iter().map(|r| HalfPlane::new(r[0], r[1], r[2])).collect();
        let two = lp2d(&planes, Vector2::new(cx, cy), &Lp2Options::default()).unwrap();
        let many = lp_d(&hs, &[cx, cy], seed).unwrap();
        match (&two, &many) {
            (Lp2Solution::Infeasible { .. }, r) => {
                let ok = matches!(r, LpSolution::Infeasible { .. });
                prop_assert!(ok, "{:?}", r);
            }
            (Lp2Solution::Unbounded { .. }, r) => {
                let ok = matches!(r, LpSolution::Unbounded { .. });
                prop_assert!(ok, "{:?}", r);
            }
            (Lp2Solution::Optimal { value, .. }, LpSolution::Optimal { value: v, .. }) => prop_assert_eq!(value, v),
            (a, b) => prop_assert!(false, "{a:?} vs {b:?}"),
        }
    }
}

#[test]
fn many_constraints_through_the_optimum() {
    // 40 planes through (1, 1, 1) bounding a cone, objective along the axis: the optimum
    // is tight for all of them (highly degenerate); fast path and exact path agree.
    let mut rows = Vec::new();
    for i in 0..40 {
        let t = i as f64 * 0.15;
        let (a, b) = (t.cos(), t.sin());
        // a·(x - 1) + b·(y - 1) + (z - 1) <= 0 (rounded coefficients, exact right side).
        rows.push(vec![a, b, 1.0, a + b + 1.0]);
    }
    for seed in 0..5 {
        let f = lp_d(&rows, &[0.0, 0.0, 1.0], seed).unwrap();
        assert_eq!(f, lp_d_exact(&rows, &[0.0, 0.0, 1.0], seed).unwrap());
    }
}

#[test]
fn zero_normals_are_true_or_infeasible() {
    let square = vec![
        vec![1.0, 0.0, 1.0],
        vec![-1.0, 0.0, 0.0],
        vec![0.0, 1.0, 1.0],
        vec![0.0, -1.0, 0.0],
    ];
    // 0·x <= 3 is always true: ignored, never reported as tight.
    let mut rows = square.clone();
    rows.push(vec![0.0, 0.0, 3.0]);
    rows.push(vec![0.0, 0.0, 0.0]);
    match lp_d(&rows, &[1.0, 1.0], 0).unwrap() {
        LpSolution::Optimal {
            point, constraints, ..
        } => {
            assert_eq!(point, vec![1.0, 1.0]);
            assert_eq!(constraints, vec![0, 2]);
        }
        other => panic!("{other:?}"),
    }
    // 0·x <= -1 is always false: infeasible, that constraint the certificate.
    rows.push(vec![0.0, 0.0, -1.0]);
    assert_eq!(
        lp_d(&rows, &[1.0, 1.0], 0).unwrap(),
        LpSolution::Infeasible {
            certificate: vec![6]
        }
    );
    // The two-dimensional solver decides the same way.
    let planes: Vec<HalfPlane> = rows
        .iter()
        .map(|r| HalfPlane::new(r[0], r[1], r[2]))
        .collect();
    assert_eq!(
        lp2d(&planes, Vector2::new(1.0, 1.0), &Lp2Options::default()).unwrap(),
        Lp2Solution::Infeasible {
            certificate: vec![6]
        }
    );
}

#[test]
fn generic_input_takes_the_fast_path() {
    // Planes tangent to the unit sphere: a unique, non-degenerate optimum every time.
    let before = compgeom::lp::lp_d_fast_hits();
    let mut unit = common::units(7);
    for _ in 0..5 {
        let rows: Vec<Vec<f64>> = (0..300)
            .map(|_| {
                let (z, t) = (2.0 * unit() - 1.0, unit() * std::f64::consts::TAU);
                let r = (1.0 - z * z).sqrt();
                vec![r * t.cos(), r * t.sin(), z, 1.0]
            })
            .collect();
        let c = [0.2, -0.5, 0.7];
        assert_eq!(
            lp_d(&rows, &c, 1).unwrap(),
            lp_d_exact(&rows, &c, 1).unwrap()
        );
    }
    assert!(compgeom::lp::lp_d_fast_hits() >= before + 5);
}
