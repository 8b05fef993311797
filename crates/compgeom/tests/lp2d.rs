//! 2D linear programming against an exact brute-force oracle (every pairwise meeting point
//! of constraint lines, in exact rationals), on random and deliberately degenerate input.

mod lp_oracle;

use compgeom::lp::{lp2d, verify_lp2d, HalfPlane, Lp2Options, Lp2Solution};
use compgeom::{Error, Point2, Vector2};
use lp_oracle::*;
use proptest::prelude::*;

fn solve(hs: &[HalfPlane], c: (f64, f64), seed: u64) -> Lp2Solution {
    lp2d(hs, Vector2::new(c.0, c.1), &Lp2Options { seed }).expect("valid input")
}

/// Check the solver's answer against the oracle, exactly where the answer is exact.
fn check(hs: &[HalfPlane], c: (f64, f64), seed: u64) -> Result<(), TestCaseError> {
    let got = solve(hs, c, seed);
    verify_lp2d(hs, Vector2::new(c.0, c.1), &got)
        .map_err(|e| TestCaseError::fail(e.to_string()))?;
    match (oracle_lp(hs, c), &got) {
        (Expected::Infeasible, Lp2Solution::Infeasible { certificate }) => {
            prop_assert!(!certificate.is_empty() && certificate.len() <= 3);
            let sub: Vec<HalfPlane> = certificate.iter().map(|&i| hs[i]).collect();
            prop_assert!(!feasible(&sub), "certificate {certificate:?} is feasible");
        }
        (Expected::Unbounded, Lp2Solution::Unbounded { point, direction }) => {
            let (dx, dy) = (r(direction.x), r(direction.y));
            prop_assert!(r(c.0) * &dx + r(c.1) * &dy > r(0.0));
            // No negative zero in the output (JSON would show `-0.0`).
            for v in [direction.x, direction.y] {
                prop_assert!(v != 0.0 || v.is_sign_positive(), "{direction:?}");
            }
            for h in hs {
                prop_assert!(
                    r(h.a) * &dx + r(h.b) * &dy <= r(0.0),
                    "{h:?} vs {direction:?}"
                );
            }
            // The rounded start point is feasible up to rounding.
            for h in hs {
                let v = h.a * point.x + h.b * point.y - h.c;
                let scale = (h.a * point.x).abs() + (h.b * point.y).abs() + h.c.abs() + 1.0;
                prop_assert!(v <= 1e-9 * scale, "{h:?} at {point:?}: {v}");
            }
        }
        (
            Expected::Optimal { point, value },
            Lp2Solution::Optimal {
                point: p, value: v, ..
            },
        ) => {
            prop_assert_eq!(*p, Point2::new(f(&point.0), f(&point.1)));
            prop_assert_eq!(*v, f(&value));
        }
        (e, g) => prop_assert!(false, "expected {e:?}, got {g:?}"),
    }
    Ok(())
}

fn small_hp() -> impl Strategy<Value = HalfPlane> {
    (-4i8..=4, -4i8..=4, -6i8..=6)
        .prop_map(|(a, b, c)| HalfPlane::new(a as f64, b as f64, c as f64))
}

fn objective() -> impl Strategy<Value = (f64, f64)> {
    (-3i8..=3, -3i8..=3)
        .prop_filter("non-zero", |(a, b)| *a != 0 || *b != 0)
        .prop_map(|(a, b)| (a as f64, b as f64))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn small_integer_lps_match_the_oracle(hs in prop::collection::vec(small_hp(), 0..10), c in objective(), seed in any::<u64>()) {
        check(&hs, c, seed)?;
    }

    #[test]
    fn constraints_through_one_point(p in (-3i8..=3, -3i8..=3), ns in prop::collection::vec((-4i8..=4, -4i8..=4, 0i8..=2), 1..10), c in objective(), seed in any::<u64>()) {
        // Many lines through p (slack 0), some shifted outward by 1 or 2.
        let hs: Vec<HalfPlane> = ns.iter().map(|&(a, b, s)| {
            let (a, b) = (a as f64, b as f64);
            HalfPlane::new(a, b, a * p.0 as f64 + b * p.1 as f64 + s as f64)
        }).collect();
        check(&hs, c, seed)?;
    }

    #[test]
    fn parallel_and_duplicate_constraints(base in prop::collection::vec(small_hp(), 1..5), picks in prop::collection::vec((0usize..5, -2i8..=2, 0i8..=2), 0..8), c in objective(), seed in any::<u64>()) {
        let mut hs = base.clone();
        for (k, scale, shift) in picks {
            let h = base[k % base.len()];
            let s = if scale == 0 { 1.0 } else { scale as f64 };
            hs.push(HalfPlane::new(h.a * s, h.b * s, h.c * s + shift as f64));
        }
        check(&hs, c, seed)?;
    }

    #[test]
    fn fractional_coefficients(hs in prop::collection::vec((-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0).prop_map(|(a, b, c)| HalfPlane::new(a, b, c)), 0..9), c in (-1.0f64..1.0, -1.0f64..1.0), seed in any::<u64>()) {
        prop_assume!(c.0 != 0.0 || c.1 != 0.0);
        check(&hs, c, seed)?;
    }
}

#[test]
fn the_answer_does_not_depend_on_the_seed() {
    let hs: Vec<HalfPlane> = (0..60)
        .map(|k| {
            let t = k as f64 * 0.1;
            HalfPlane::new(t.cos(), t.sin(), 1.0)
        })
        .collect();
    let first = solve(&hs, (0.3, 0.7), 0);
    for seed in 1..20 {
        assert_eq!(solve(&hs, (0.3, 0.7), seed), first);
    }
}

#[test]
fn hand_made_cases() {
    // Empty constraint set: unbounded along the box diagonal.
    assert!(matches!(
        solve(&[], (1.0, 0.0), 1),
        Lp2Solution::Unbounded { .. }
    ));
    // x <= 1 and x >= 2.
    let hs = [
        HalfPlane::new(1.0, 0.0, 1.0),
        HalfPlane::new(-1.0, 0.0, -2.0),
    ];
    match solve(&hs, (0.0, 1.0), 3) {
        Lp2Solution::Infeasible { certificate } => assert_eq!(certificate, vec![0, 1]),
        other => panic!("{other:?}"),
    }
    // A zero normal with a negative right-hand side is infeasible by itself.
    let hs = [
        HalfPlane::new(1.0, 0.0, 1.0),
        HalfPlane::new(0.0, 0.0, -1.0),
    ];
    assert_eq!(
        solve(&hs, (1.0, 0.0), 0),
        Lp2Solution::Infeasible {
            certificate: vec![1]
        }
    );
    // Optimal set is a whole line: y <= 1, maximize y -> the point of y = 1 nearest 0.
    let hs = [
        HalfPlane::new(0.0, 1.0, 1.0),
        HalfPlane::new(0.0, -1.0, 5.0),
    ];
    match solve(&hs, (0.0, 2.0), 0) {
        Lp2Solution::Optimal { point, value, .. } => {
            assert_eq!(point, Point2::new(0.0, 1.0));
            assert_eq!(value, 2.0);
        }
        other => panic!("{other:?}"),
    }
    // Optimal ray toward smaller x: y <= 0, x <= 3, maximize y: the apex (3, 0).
    let hs = [HalfPlane::new(0.0, 1.0, 0.0), HalfPlane::new(1.0, 0.0, 3.0)];
    match solve(&hs, (0.0, 1.0), 0) {
        Lp2Solution::Optimal { point, .. } => assert_eq!(point, Point2::new(3.0, 0.0)),
        other => panic!("{other:?}"),
    }
}

#[test]
fn huge_and_tiny_coefficients_are_exact() {
    // Nearly parallel lines meeting far away; magnitudes near the f64 limits.
    let hs = [
        HalfPlane::new(1.0, 1e-300, 1e300),
        HalfPlane::new(1.0, -1e-300, 1e300),
        HalfPlane::new(-1.0, 0.0, 1e300),
    ];
    check(&hs, (1.0, 0.0), 1).unwrap();
    check(&hs, (0.0, 1.0), 1).unwrap();
    let hs = [
        HalfPlane::new(1e-310, 1.0, 1e-310),
        HalfPlane::new(-1e-310, 1.0, 0.0),
        HalfPlane::new(0.0, -1.0, 1e308),
    ];
    check(&hs, (0.0, 1.0), 2).unwrap();
}

#[test]
fn bad_input_is_an_error() {
    let hs = [HalfPlane::new(1.0, f64::NAN, 0.0)];
    let e = lp2d(&hs, Vector2::new(1.0, 0.0), &Lp2Options::default()).unwrap_err();
    assert!(
        matches!(e, Error::NonFinite { ref what, .. } if what == "constraint 0"),
        "{e}"
    );
    let e = lp2d(&[], Vector2::new(0.0, 0.0), &Lp2Options::default()).unwrap_err();
    assert!(e.to_string().contains("zero"));
}

#[test]
fn the_verifier_rejects_wrong_answers() {
    let hs = [
        HalfPlane::new(1.0, 0.0, 2.0),
        HalfPlane::new(0.0, 1.0, 3.0),
        HalfPlane::new(1.0, 1.0, 4.0),
    ];
    let c = Vector2::new(1.0, 1.0);
    let good = solve(&hs, (1.0, 1.0), 0);
    verify_lp2d(&hs, c, &good).unwrap();
    // The corner of x <= 2 and y <= 3 is infeasible (x + y = 5 > 4).
    let bad = Lp2Solution::Optimal {
        point: Point2::new(2.0, 3.0),
        value: 5.0,
        constraints: vec![0, 1],
    };
    assert!(verify_lp2d(&hs, c, &bad).is_err());
    // A feasible but not optimal corner: (2, 2) is optimal for (1, 1) but not for (0, 1).
    let not_opt = Lp2Solution::Optimal {
        point: Point2::new(2.0, 2.0),
        value: 2.0,
        constraints: vec![0, 2],
    };
    assert!(verify_lp2d(&hs, Vector2::new(0.0, 1.0), &not_opt).is_err());
    let ray = Lp2Solution::Unbounded {
        point: Point2::new(0.0, 0.0),
        direction: Vector2::new(1.0, 0.0),
    };
    assert!(verify_lp2d(&hs, c, &ray).is_err());
    let cert = Lp2Solution::Infeasible {
        certificate: vec![0, 1],
    };
    assert!(verify_lp2d(&hs, c, &cert).is_err());
}

/// The line x = 1 (two opposite constraints) with objective (1, 1): unbounded along the
/// line, direction exactly (0, 1) — not (-0, 1), which JSON would print as `-0.0`.
#[test]
fn unbounded_direction_has_no_negative_zero() {
    let hs = [
        HalfPlane::new(1.0, 0.0, 1.0),
        HalfPlane::new(-1.0, 0.0, -1.0),
    ];
    for c in [(1.0, 1.0), (-1.0, -1.0), (0.0, 1.0)] {
        match solve(&hs, c, 0) {
            Lp2Solution::Unbounded { direction, .. } => {
                assert_eq!(direction.x, 0.0);
                assert!(direction.x.is_sign_positive(), "{c:?}: {direction:?}");
                assert_eq!(direction.y.abs(), 1.0);
            }
            other => panic!("{c:?}: {other:?}"),
        }
    }
}
