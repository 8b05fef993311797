//! Helpers shared by the integration tests: fixture-suite location, the exact area and
//! validity checks of the boolean-operation tests, and deterministic random numbers.
#![allow(dead_code)]
use compgeom::intersect::find_intersections;
use compgeom::io::ring_orientation;
use compgeom::kernel::{orient2d, Orientation};
use compgeom::{MultiPolygon, Point2, Segment2};
use num_rational::BigRational;
use num_traits::Zero;

/// The generator's next state (a 64-bit linear congruential generator, Knuth's MMIX
/// constants: the same numbers on every machine, no dependency).
fn step(state: &mut u64) -> u64 {
    *state = state
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    *state
}

/// Uniform `f64` numbers in `[0, 1)` from `seed` (the top 53 bits of each state).
pub fn units(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed;
    move || (step(&mut state) >> 11) as f64 / (1u64 << 53) as f64
}

/// The top 53 bits of each state, from `seed`.
pub fn bits(seed: u64) -> impl FnMut() -> u64 {
    let mut state = seed;
    move || step(&mut state) >> 11
}

/// Numbers below `n` (the top 31 bits of each state modulo `n`), from `seed`.
pub fn below(seed: u64) -> impl FnMut(u64) -> u64 {
    let mut state = seed;
    move |n| (step(&mut state) >> 33) % n
}

pub fn shoelace(r: &[Point2]) -> f64 {
    (0..r.len())
        .map(|i| {
            let (a, b) = (r[i], r[(i + 1) % r.len()]);
            a.x * b.y - b.x * a.y
        })
        .sum::<f64>()
        / 2.0
}

pub fn exact_shoelace2(r: &[Point2]) -> BigRational {
    let q = |v: f64| BigRational::from_float(v).unwrap();
    (0..r.len())
        .map(|i| {
            let (a, b) = (r[i], r[(i + 1) % r.len()]);
            q(a.x) * q(b.y) - q(b.x) * q(a.y)
        })
        .fold(BigRational::zero(), |x, y| x + y)
}

pub fn area(m: &MultiPolygon) -> f64 {
    m.0.iter()
        .map(|p| p.rings().map(|r| shoelace(r)).sum::<f64>())
        .sum()
}

/// OGC-style validity of an output: rings of ≥ 3 distinct points, shells CCW and holes
/// CW, no collinear vertex, no two edges crossing or overlapping: edges meet only at
/// common endpoints.
pub fn assert_valid(m: &MultiPolygon) {
    assert_valid_with(m, true)
}

/// [`assert_valid`]; `collinear_check: false` skips the collinear-vertex test (a rounded
/// crossing can land exactly on the line through its rounded neighbours).
pub fn assert_valid_with(m: &MultiPolygon, collinear_check: bool) {
    let mut segs = Vec::new();
    // Vertices used by several rings: where rings touch (a collinear vertex is kept there).
    let mut uses = std::collections::HashMap::new();
    for r in m.0.iter().flat_map(|p| p.rings()) {
        for p in r {
            *uses.entry((p.x.to_bits(), p.y.to_bits())).or_insert(0) += 1;
        }
    }
    for poly in &m.0 {
        for (k, r) in poly.rings().enumerate() {
            assert!(r.len() >= 3, "short ring {r:?}");
            let mut sorted: Vec<(u64, u64)> =
                r.iter().map(|p| (p.x.to_bits(), p.y.to_bits())).collect();
            sorted.sort_unstable();
            sorted.dedup();
            assert_eq!(sorted.len(), r.len(), "repeated vertex in {r:?}");
            let want = if k == 0 {
                Orientation::CounterClockwise
            } else {
                Orientation::Clockwise
            };
            assert_eq!(ring_orientation(r), want, "ring {k} orientation: {r:?}");
            for i in 0..r.len() {
                let (a, b, c) = (r[i], r[(i + 1) % r.len()], r[(i + 2) % r.len()]);
                let shared = uses[&(b.x.to_bits(), b.y.to_bits())] > 1;
                assert!(
                    !collinear_check || shared || orient2d(a, b, c) != Orientation::Collinear,
                    "collinear vertex {b:?}"
                );
                segs.push(Segment2::new(a, b));
            }
        }
    }
    let found = find_intersections(&segs).unwrap();
    assert!(
        found.overlaps.is_empty(),
        "overlapping edges {:?}",
        found.overlaps
    );
    for p in &found.points {
        // Rings touch only at vertices of both.
        assert!(
            p.interior().is_empty(),
            "edges cross or touch inside at {:?}",
            p.point
        );
    }
}

/// Where the shared fixture suites live: `$COMPGEOM_CASES`, else `../shared/cases` beside the
/// workspace. Tests that read them print "skipped" when the folder is absent.
pub fn cases_dir() -> std::path::PathBuf {
    std::env::var_os("COMPGEOM_CASES").map_or_else(
        || {
            std::path::PathBuf::from(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/../../../shared/cases"
            ))
        },
        std::path::PathBuf::from,
    )
}

/// [`cases_dir`] if it exists; otherwise says the fixtures were skipped.
pub fn existing_cases_dir() -> Option<std::path::PathBuf> {
    let dir = cases_dir();
    if dir.is_dir() {
        Some(dir)
    } else {
        println!("skipped: {} not found", dir.display());
        None
    }
}

/// Brute force, O(n⁴): the circles through three or more of `sites` with no site on the
/// `excluded` side, each given by the set of sites on it (indices into `sites`, ascending).
/// With `excluded = Inside` these are the Voronoi vertices (empty circles); with `Outside`
/// the farthest-point Voronoi vertices (circles containing every site).
pub fn site_circles(
    sites: &[Point2],
    excluded: compgeom::kernel::CircleSide,
) -> std::collections::BTreeSet<Vec<usize>> {
    use compgeom::kernel::{incircle, CircleSide};
    let n = sites.len();
    let mut out = std::collections::BTreeSet::new();
    for a in 0..n {
        for b in a + 1..n {
            for c in b + 1..n {
                let (pa, mut pb, mut pc) = (sites[a], sites[b], sites[c]);
                match orient2d(pa, pb, pc) {
                    Orientation::Collinear => continue,
                    Orientation::Clockwise => std::mem::swap(&mut pb, &mut pc),
                    Orientation::CounterClockwise => {}
                }
                let mut on = Vec::new();
                let mut ok = true;
                for (s, &p) in sites.iter().enumerate() {
                    match incircle(pa, pb, pc, p) {
                        side if side == excluded => {
                            ok = false;
                            break;
                        }
                        CircleSide::OnCircle => on.push(s),
                        _ => {}
                    }
                }
                if ok {
                    out.insert(on);
                }
            }
        }
    }
    out
}
