//! `lp2d`'s static `f64` filters (vertex tests and cross products with a proven error
//! bound) against the same algorithm with every decision made by the filtered exact
//! predicates alone (`lp2d_exact`): identical answers — the same point, value, defining
//! constraints, ray and infeasibility certificate — on deliberately degenerate input
//! (parallel, identical and redundant constraints, many constraints through one point,
//! tangents of a circle a few ulps apart, huge and tiny scales in and out of the filters'
//! range) and on inputs large enough for the bucketed shuffle.

mod common;
use compgeom::lp::{lp2d, lp2d_exact, verify_lp2d, HalfPlane, Lp2Options, Lp2Solution};
use compgeom::Vector2;
use proptest::prelude::*;

fn both(hs: &[HalfPlane], c: (f64, f64), seed: u64) -> Result<Lp2Solution, TestCaseError> {
    let o = Lp2Options { seed };
    let obj = Vector2::new(c.0, c.1);
    let fast = lp2d(hs, obj, &o).map_err(|e| TestCaseError::fail(e.to_string()))?;
    let exact = lp2d_exact(hs, obj, &o).map_err(|e| TestCaseError::fail(e.to_string()))?;
    prop_assert_eq!(&fast, &exact);
    verify_lp2d(hs, obj, &fast).map_err(|e| TestCaseError::fail(e.to_string()))?;
    Ok(fast)
}

fn objective() -> impl Strategy<Value = (f64, f64)> {
    (-3i8..=3, -3i8..=3)
        .prop_filter("non-zero", |(a, b)| *a != 0 || *b != 0)
        .prop_map(|(a, b)| (a as f64, b as f64))
}

/// Small integer half-planes: many parallel, identical and concurrent ones.
fn int_hp() -> impl Strategy<Value = HalfPlane> {
    (-3i8..=3, -3i8..=3, -4i8..=4)
        .prop_map(|(a, b, c)| HalfPlane::new(a as f64, b as f64, c as f64))
}

/// Scales in the filters' range (2^-250..2^250) and outside it.
fn scale() -> impl Strategy<Value = f64> {
    prop::sample::select(vec![1.0, 1e-60, 1e60, 1e-200, 1e200, 3.0e-300, 0.1])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn integer_grids(hs in prop::collection::vec(int_hp(), 0..24), c in objective(), seed in any::<u64>()) {
        both(&hs, c, seed)?;
    }

    #[test]
    fn through_one_point_at_any_scale(p in (-3i8..=3, -3i8..=3), ns in prop::collection::vec((-4i8..=4, -4i8..=4, 0i8..=1), 1..24), s in scale(), t in scale(), c in objective(), seed in any::<u64>()) {
        // Lines through the point p·t (slack 0 or s), coefficients scaled by s: exact
        // ties everywhere, some rows in range and some (with t or s extreme) out of it.
        let hs: Vec<HalfPlane> = ns.iter().map(|&(a, b, slack)| {
            let (a, b) = (a as f64 * s, b as f64 * s);
            HalfPlane::new(a, b, a * (p.0 as f64 * t) + b * (p.1 as f64 * t) + slack as f64 * s)
        }).collect();
        prop_assume!(hs.iter().all(|h| h.c.is_finite()));
        both(&hs, c, seed)?;
    }

    #[test]
    fn parallel_duplicates_and_mixed_scales(base in prop::collection::vec(int_hp(), 1..6), picks in prop::collection::vec((0usize..6, -2i8..=2, 0i8..=2, scale()), 0..18), c in objective(), seed in any::<u64>()) {
        let mut hs = base.clone();
        for (k, m, shift, s) in picks {
            let h = base[k % base.len()];
            let m = if m == 0 { 1.0 } else { m as f64 } * s;
            hs.push(HalfPlane::new(h.a * m, h.b * m, h.c * m + shift as f64 * s));
        }
        both(&hs, c, seed)?;
    }

    #[test]
    fn open_regions_keep_box_vertices(hs in prop::collection::vec((-3i8..=3, -3i8..=-1, -4i8..=4, scale()), 0..24), c in objective(), seed in any::<u64>()) {
        // Every normal points downward: the region is open upward, so the optimum often
        // stays on the symbolic box (box corners, rows meeting a box side) while rows are
        // tested, and the answer is often unbounded.
        let hs: Vec<HalfPlane> = hs.iter().map(|&(a, b, c, s)| HalfPlane::new(a as f64 * s, b as f64 * s, c as f64)).collect();
        both(&hs, c, seed)?;
    }

    #[test]
    fn nearly_identical_tangents(t0 in 0.0f64..6.3, steps in prop::collection::vec((0u64..6, -2i64..=2), 2..30), c in (-1.0f64..1.0, -1.0f64..1.0), seed in any::<u64>()) {
        prop_assume!(c.0 != 0.0 || c.1 != 0.0);
        // Tangents of the unit circle whose angles and offsets differ by a few ulps: the
        // static filters must decline, and the exact path decide.
        let hs: Vec<HalfPlane> = steps.iter().map(|&(k, dc)| {
            let t = f64::from_bits(t0.to_bits() + k);
            let c = f64::from_bits((1.0f64.to_bits() as i64 + dc) as u64);
            HalfPlane::new(t.cos(), t.sin(), c)
        }).collect();
        both(&hs, c, seed)?;
    }
}

/// Random tangents of the unit circle, `n` of them (the benchmark's input).
fn tangents(n: usize, seed: u64) -> Vec<HalfPlane> {
    let mut unit = common::units(seed);
    (0..n)
        .map(|k| {
            let t = unit() * std::f64::consts::TAU;
            HalfPlane::new(
                t.cos(),
                t.sin(),
                1.0 + 1e-3 * ((k * 7919) % 1000) as f64 / 1e3,
            )
        })
        .collect()
}

#[test]
fn large_inputs_take_the_bucketed_shuffle() {
    // Above the bucketed shuffle's threshold (16384 rows): the same answer for every seed,
    // fast and exact paths equal, the answer verified exactly.
    let mut hs = tangents(40_000, 7);
    for k in (0..hs.len()).step_by(97) {
        let h = hs[k / 2];
        hs[k] = h;
    }
    for k in (0..hs.len()).step_by(89) {
        let h = hs[k / 3];
        hs[k] = HalfPlane::new(2.0 * h.a, 2.0 * h.b, 2.0 * h.c + 0.5);
    }
    // A few constraints that are always true (zero normals) are dropped by the shuffle.
    hs[5] = HalfPlane::new(0.0, 0.0, 1.0);
    hs[30_000] = HalfPlane::new(0.0, 0.0, 0.0);
    let first = both(&hs, (0.3, 0.7), 1).unwrap();
    assert!(matches!(first, Lp2Solution::Optimal { .. }));
    for seed in [2, 3, 0x5eed] {
        assert_eq!(both(&hs, (0.3, 0.7), seed).unwrap(), first);
    }
    // Unbounded and infeasible variants at the same size.
    let open: Vec<HalfPlane> = hs.iter().filter(|h| h.b < 0.0).copied().collect();
    assert!(open.len() > 16_384);
    assert!(matches!(
        both(&open, (0.0, 1.0), 4).unwrap(),
        Lp2Solution::Unbounded { .. }
    ));
    let mut shut = hs.clone();
    shut.push(HalfPlane::new(0.0, -1.0, -5.0)); // y >= 5, outside the circle
    assert!(matches!(
        both(&shut, (0.3, 0.7), 5).unwrap(),
        Lp2Solution::Infeasible { .. }
    ));
}
