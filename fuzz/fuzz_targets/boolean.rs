//! Boolean operations on arbitrary polygon sets: rings of raw f64 bit patterns (NaN,
//! infinities, subnormals, huge values) or of points snapped to a half-integer grid
//! (shared edges, touching vertices, spikes, repeated points, self-crossings), every
//! operation, fill rule and `keep_collinear` setting. Finite input must give a result,
//! non-finite input an error, never a panic, and the result must be valid
//! (`validity_problems`, its rounded crossings included). On the grid the result's area must match
//! the exact area of the faces the fill rule and the operation select in the labelled
//! arrangement (`boolean_dcel`), whose labels must also sum to the rings' exact signed
//! areas.
#![no_main]

use compgeom::overlay::{
    boolean_dcel, boolean_with, validity_problems, BooleanOp, BooleanOptions, FillRule,
};
use compgeom::{MultiPolygon, Point2, Polygon};
use libfuzzer_sys::fuzz_target;
use num_rational::BigRational;
use num_traits::{ToPrimitive, Zero};

const OPS: [BooleanOp; 4] = [
    BooleanOp::Intersection,
    BooleanOp::Union,
    BooleanOp::Difference,
    BooleanOp::Xor,
];
const RULES: [FillRule; 3] = [FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive];

/// Reads the polygon sets from the bytes: per set a count of polygons, per polygon a
/// count of rings (its shell and holes), per ring a count of points, then the points.
struct Reader<'a> {
    bytes: &'a [u8],
    snap: bool,
}

impl Reader<'_> {
    fn byte(&mut self) -> u8 {
        let (&b, rest) = self.bytes.split_first().unwrap_or((&0, &[]));
        self.bytes = rest;
        b
    }

    fn coordinate(&mut self) -> f64 {
        if self.snap {
            f64::from(self.byte() % 16) / 2.0
        } else {
            let mut word = [0u8; 8];
            for w in &mut word {
                *w = self.byte();
            }
            f64::from_le_bytes(word)
        }
    }

    fn ring(&mut self) -> Vec<Point2> {
        let len = 3 + usize::from(self.byte() % 8);
        (0..len)
            .map(|_| Point2::new(self.coordinate(), self.coordinate()))
            .collect()
    }

    fn set(&mut self) -> MultiPolygon {
        let polygons = usize::from(self.byte() % 4);
        MultiPolygon(
            (0..polygons)
                .map(|_| {
                    let holes = usize::from(self.byte() % 3);
                    let shell = self.ring();
                    Polygon::new(shell, (0..holes).map(|_| self.ring()).collect())
                })
                .collect(),
        )
    }
}

fn area(m: &MultiPolygon) -> f64 {
    let ring = |r: &Vec<Point2>| {
        (0..r.len())
            .map(|i| {
                let (a, b) = (r[i], r[(i + 1) % r.len()]);
                a.x * b.y - b.x * a.y
            })
            .sum::<f64>()
            / 2.0
    };
    m.0.iter().flat_map(|p| p.rings()).map(ring).sum()
}

fn exact(v: f64) -> BigRational {
    BigRational::from_float(v).expect("finite")
}

/// Twice the exact signed area of a ring.
fn shoelace2(r: &[Point2]) -> BigRational {
    (0..r.len()).fold(BigRational::zero(), |acc, i| {
        let (a, b) = (r[i], r[(i + 1) % r.len()]);
        acc + exact(a.x) * exact(b.y) - exact(b.x) * exact(a.y)
    })
}

fuzz_target!(|data: &[u8]| {
    let Some((&flags, rest)) = data.split_first() else {
        return;
    };
    let mut reader = Reader {
        bytes: rest,
        snap: flags & 1 == 1,
    };
    let (a, b) = (reader.set(), reader.set());
    let op = OPS[usize::from(flags >> 1) % 4];
    let rule = RULES[usize::from(flags >> 3) % 3];
    let options = BooleanOptions {
        fill_rule: rule,
        keep_collinear: flags & 0x40 != 0,
    };
    let points = || a.0.iter().chain(&b.0).flat_map(|p| p.rings()).flatten();
    let finite = points().all(|p| p.is_finite());
    // (Finite input can be an error too: a ring of fewer than three distinct points.)
    let Ok(out) = boolean_with(&a, &b, op, &options) else {
        return;
    };
    assert!(finite, "non-finite input accepted");
    let problems = validity_problems(&out).expect("finite output");
    assert!(problems.is_empty(), "{op:?} {rule:?}: {problems:?}");
    if !reader.snap {
        return;
    }
    // The labelled arrangement: Σ_f w(f)·area(f) is each input's signed ring area, and
    // the faces selected by the rule and the operation make up the result's area.
    let d = boolean_dcel(&a, &b, rule).expect("the operation succeeded");
    let (mut wa, mut wb, mut selected) = (
        BigRational::zero(),
        BigRational::zero(),
        BigRational::zero(),
    );
    for f in d.face_ids().skip(1) {
        let face_area = d.face_area_exact(f);
        let (x, y) = d.face(f).data;
        wa += BigRational::from_integer(x.into()) * &face_area;
        wb += BigRational::from_integer(y.into()) * &face_area;
        if op.apply(rule.inside(x), rule.inside(y)) {
            selected += face_area;
        }
    }
    let rings_of = |m: &MultiPolygon| {
        let two = BigRational::from_integer(2.into());
        m.0.iter()
            .flat_map(|p| p.rings())
            .fold(BigRational::zero(), |acc, r| acc + shoelace2(r))
            / two
    };
    if rule != FillRule::Positive {
        // (Positive turns rings first: the labels then count the turned rings.)
        assert_eq!(wa, rings_of(&a), "labels of A");
        assert_eq!(wb, rings_of(&b), "labels of B");
    }
    let want = selected.to_f64().expect("small");
    let got = area(&out);
    assert!(
        (got - want).abs() <= 1e-9 * (1.0 + want.abs()),
        "{op:?} {rule:?}: area {got}, exact {want}"
    );
});
