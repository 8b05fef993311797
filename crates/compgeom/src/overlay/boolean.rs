//! Boolean operations on polygon sets (book §2.4) from one labelled arrangement.
//!
//! The rings of both inputs (any orientation, any number of polygons, overlapping or
//! self-intersecting) go through one exact intersection sweep; every face of the
//! resulting subdivision gets its winding numbers with respect to A and B (crossing a
//! ring edge from its right to its left adds one, counted per set). A [`FillRule`]
//! turns a winding number into inside/outside: even-odd (the default: odd winding, i.e.
//! an odd number of boundary crossings, is inside; ring orientation is irrelevant) or
//! non-zero (rings as given; inside when the winding is not zero) or positive (each
//! polygon first oriented with its exterior counter-clockwise and holes clockwise by the
//! exact sign of its area; inside when the winding is positive: polygons united, each its
//! shell minus its holes).
//! The result is the boundary between chosen and other faces, made into valid polygons.
//! [`boolean_with`] does this without building DCEL records (`trace.rs`: winding numbers
//! per boundary cycle on compact arrays, rings traced from the edges whose two sides
//! differ); [`boolean_dcel`] builds the labelled DCEL, from which
//! [`super::faces_to_polygons`] gives the same polygons (tested against each other).
//!
//! ## Validity of the output
//!
//! The result is valid in the OGC sense: closed simple rings, shells counter-clockwise
//! and holes clockwise (RFC 7946), holes inside their shell, rings meeting only at
//! isolated points, polygons touching only at points, no vertex where a ring goes
//! straight on (unless [`BooleanOptions::keep_collinear`]). Exactly, before rounding,
//! it always is. Output coordinates are the nearest `f64` to the exact vertices, and
//! rounding a constructed crossing moves it by up to half an ulp, which can carry it
//! across an edge that passes closer than that (thin parts, near-coincident crossings:
//! a fifth of the results on some test inputs built for it, rare on random ones). So
//! the rounded result is checked, exactly and conservatively: when no vertex and edge
//! not incident to it, one of them moved, come within a float gap of each other, the
//! rounded result is the exact one deformed, hence valid (O(n) after the crossings,
//! and nothing at all when no vertex moved); a vertex near such an edge must be on its
//! exact side of it. Where it is not, the crossings involved are moved to another of
//! the (at most four) floats around their exact points where that puts every near
//! vertex on its side: such a crossing is one float, not the nearest, from its exact
//! point per axis. Where no such float does, the rounded polygons there are united
//! again (the [`FillRule::Positive`] rule: each shell minus its holes), which makes the
//! new crossings vertices, and checked the same way among the others. The region then
//! differs from the exact one by slivers within rounding. Vertices from the input are
//! never moved. A point that rounding left straight between its neighbours (a crossing
//! rounded onto their line) is dropped where no other ring passes through it: the ring
//! is the same curve without it.
//!
//! ## Order of the output
//!
//! Canonical, so that the same region gives the same output whatever the order of the
//! input's polygons, where its rings start, or the library's internal numbering: every
//! ring starts at its smallest vertex (by x, then y), and a polygon's holes, and the
//! polygons by their shells, come in increasing order of their points' coordinates
//! (compared lexicographically).
//!
//! Cost: O((n + k) log n) for n input edges and k intersection points, plus the
//! hole-linking sweep (see [`crate::dcel`]).
use super::locality;
#[cfg(test)]
use super::result::faces_to_polygons;
use crate::dcel::{polygon_segments, push_ring_segments, Carrier, Dcel, Flat};
use crate::io::ring_orientation;
use crate::kernel::{MultiPolygon, Orientation, Segment2};
use crate::scratch::{self, Scratch};
use crate::Result;

/// The four operations.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BooleanOp {
    /// A ∩ B.
    Intersection,
    /// A ∪ B.
    Union,
    /// A − B.
    Difference,
    /// A △ B (symmetric difference).
    Xor,
}

impl BooleanOp {
    /// Whether a point in `a`/`b` is in the result.
    pub fn apply(self, a: bool, b: bool) -> bool {
        match self {
            BooleanOp::Intersection => a && b,
            BooleanOp::Union => a || b,
            BooleanOp::Difference => a && !b,
            BooleanOp::Xor => a != b,
        }
    }
}

/// How the rings of a polygon set define its interior.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
pub enum FillRule {
    /// Inside iff a ray from the point crosses the rings an odd number of times.
    #[default]
    EvenOdd,
    /// Inside iff the winding number is not zero, rings taken in the orientation given
    /// (the rule of SVG, Clipper and iOverlay).
    NonZero,
    /// Inside iff the winding number is positive, after orienting each polygon's exterior
    /// counter-clockwise and its holes clockwise: each polygon is its exterior minus its
    /// holes (a hole reaching outside its shell removes nothing there) and the polygons
    /// of a set are united. The rule of GeoJSON-style polygon sets.
    Positive,
}

impl FillRule {
    /// Whether winding number `w` is inside.
    pub fn inside(self, w: i32) -> bool {
        match self {
            FillRule::EvenOdd => w % 2 != 0,
            FillRule::NonZero => w != 0,
            FillRule::Positive => w > 0,
        }
    }
}

/// Options of [`boolean_with`].
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct BooleanOptions {
    /// How to read the inputs.
    pub fill_rule: FillRule,
    /// Keep vertices where the result's boundary goes straight on.
    pub keep_collinear: bool,
}

/// Half-edge data of [`boolean_dcel`]: how the winding numbers change when crossing the
/// edge into the face on the half-edge's left, and its exact direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BooleanEdge {
    /// Change of the winding number with respect to A.
    pub da: i32,
    /// Change with respect to B.
    pub db: i32,
    /// The direction, exactly.
    pub carrier: Carrier,
}

/// The segments of the polygon sets `a` and `b`, each oriented for the fill rule, in one
/// vector, and the number from `a`: [`crate::dcel::polygon_segments`] of each (of each with its rings
/// turned, for [`FillRule::Positive`]), without copying rings or listing owners; the
/// polygons of a large set in Z-order (see [`push_oriented`]).
pub(super) fn oriented_segments(
    a: &MultiPolygon,
    b: &MultiPolygon,
    rule: FillRule,
) -> Result<(Scratch<Segment2>, usize)> {
    let points =
        |p: &MultiPolygon| -> usize { p.0.iter().flat_map(|q| q.rings()).map(Vec::len).sum() };
    let (points_a, points_b) = (points(a), points(b));
    let mut segs = scratch::with_capacity(points_a + points_b);
    push_oriented(a, points_a, rule, &mut segs)?;
    let na = segs.len();
    push_oriented(b, points_b, rule, &mut segs)?;
    Ok((segs, na))
}

/// Append the segments of `p`'s rings (`points` points in all); for [`FillRule::Positive`] each exterior turned
/// counter-clockwise and each hole clockwise first, by the exact sign of its area. With
/// [`locality::REORDER_FROM`] polygons and [`locality::REORDER_FROM_POINTS`] points or
/// more, the polygons in Z-order, each one's segments together ([`locality`]; errors
/// still name the first bad polygon in the given order: they are found while pushing).
fn push_oriented(
    p: &MultiPolygon,
    points: usize,
    rule: FillRule,
    segs: &mut Vec<Segment2>,
) -> Result<()> {
    let from = segs.len();
    let reorder = p.0.len() >= locality::REORDER_FROM && points >= locality::REORDER_FROM_POINTS;
    let mut starts = Vec::with_capacity(if reorder { p.0.len() + 1 } else { 0 });
    for (pi, poly) in p.0.iter().enumerate() {
        if reorder {
            starts.push(segs.len() - from);
        }
        for (ri, ring) in poly.rings().enumerate() {
            let reversed = rule == FillRule::Positive && {
                let o = ring_orientation(ring);
                let ccw = ri == 0;
                (o == Orientation::Clockwise && ccw) || (o == Orientation::CounterClockwise && !ccw)
            };
            push_ring_segments(pi, ri, ring, reversed, segs)?;
        }
    }
    if reorder {
        starts.push(segs.len() - from);
        locality::reorder_blocks(&mut segs[from..], &starts);
    }
    Ok(())
}

/// The arrangement of both inputs with every face labelled by its winding numbers
/// `(w_A, w_B)` (see the module docs); the basis of [`boolean_with`], exposed for exact
/// checks (e.g. [`Dcel::face_area_exact`]). Rings are turned first for
/// [`FillRule::Positive`] (shells counter-clockwise, holes clockwise) and read as given
/// otherwise. O((n + k) log n) for n edges and k crossings, as [`boolean_with`].
///
/// ```
/// use compgeom::overlay::{boolean_dcel, FillRule};
/// use compgeom::{MultiPolygon, Point2, Polygon};
/// use num_rational::BigRational;
/// let sq = |x: f64, y: f64| Polygon::new(vec![Point2::new(x, y), Point2::new(x + 2.0, y),
///     Point2::new(x + 2.0, y + 2.0), Point2::new(x, y + 2.0)], vec![]);
/// let d = boolean_dcel(&MultiPolygon(vec![sq(0.0, 0.0)]), &MultiPolygon(vec![sq(1.0, 1.0)]),
///     FillRule::EvenOdd).unwrap();
/// // The face inside both squares has winding numbers (1, 1) and area 1, exactly.
/// let both: Vec<_> = d.face_ids().filter(|&f| d.face(f).data == (1, 1)).collect();
/// assert_eq!(both.len(), 1);
/// assert_eq!(d.face_area_exact(both[0]), BigRational::from_integer(1.into()));
/// ```
pub fn boolean_dcel(
    a: &MultiPolygon,
    b: &MultiPolygon,
    rule: FillRule,
) -> Result<Dcel<(), BooleanEdge, (i32, i32)>> {
    let (segs, na) = oriented_segments(a, b, rule)?;
    let flat = Flat::of_segments(&segs)?;
    let d = Dcel::linked_flat(
        flat,
        &segs,
        |sources, carrier| {
            let (mut da, mut db) = (0, 0);
            for s in sources {
                // Crossing a ring edge a → b from its right to its left adds one.
                let w = if s.forward { 1 } else { -1 };
                if s.segment < na {
                    da += w;
                } else {
                    db += w;
                }
            }
            BooleanEdge { da, db, carrier }
        },
        true,
    );
    Ok(d.label_faces((0, 0), |&(wa, wb), e| (wa + e.da, wb + e.db)))
}

/// `op(A, B)` with the default options (even-odd, collinear vertices dropped).
///
/// ```
/// use compgeom::overlay::{boolean, BooleanOp};
/// use compgeom::{MultiPolygon, Point2, Polygon};
/// let sq = |x: f64, y: f64| Polygon::new(vec![Point2::new(x, y), Point2::new(x + 2.0, y),
///     Point2::new(x + 2.0, y + 2.0), Point2::new(x, y + 2.0)], vec![]);
/// let a = MultiPolygon(vec![sq(0.0, 0.0)]);
/// let b = MultiPolygon(vec![sq(1.0, 1.0)]);
/// let u = boolean(&a, &b, BooleanOp::Union).unwrap();
/// assert_eq!(u.0.len(), 1);
/// assert_eq!(u.0[0].exterior.len(), 8);
/// let i = boolean(&a, &b, BooleanOp::Intersection).unwrap();
/// assert_eq!(i.0[0].exterior.len(), 4);
/// ```
pub fn boolean(a: &MultiPolygon, b: &MultiPolygon, op: BooleanOp) -> Result<MultiPolygon> {
    boolean_with(a, b, op, &BooleanOptions::default())
}

/// `op(A, B)` with options. Errors: non-finite coordinates, rings with fewer than three
/// distinct points (named by polygon and ring).
///
/// Cost: O((n + k) log n) for n input edges and k crossings (one sweep of both sets),
/// plus the rounding check, O(n) after the crossings (see the module docs).
///
/// ```
/// use compgeom::overlay::{boolean_with, BooleanOp, BooleanOptions, FillRule};
/// use compgeom::{MultiPolygon, Point2, Polygon};
/// let p = |x, y| Point2::new(x, y);
/// // One ring that winds twice around the middle of a square.
/// let twice = Polygon::new(vec![p(0., 0.), p(4., 0.), p(4., 4.), p(0., 4.), p(0., 0.),
///     p(1., 1.), p(3., 1.), p(3., 3.), p(1., 3.), p(1., 1.)], vec![]);
/// let a = MultiPolygon(vec![twice]);
/// let none = MultiPolygon::default();
/// let union = |fill_rule| {
///     let opts = BooleanOptions { fill_rule, keep_collinear: false };
///     boolean_with(&a, &none, BooleanOp::Union, &opts).unwrap()
/// };
/// // Even-odd: the middle, wound twice, is a hole; non-zero: it is inside.
/// assert_eq!(union(FillRule::EvenOdd).0[0].holes.len(), 1);
/// assert_eq!(union(FillRule::NonZero).0[0].holes.len(), 0);
/// ```
pub fn boolean_with(
    a: &MultiPolygon,
    b: &MultiPolygon,
    op: BooleanOp,
    opts: &BooleanOptions,
) -> Result<MultiPolygon> {
    let rule = opts.fill_rule;
    let (segs, na) = oriented_segments(a, b, rule)?;
    super::trace::traced_boolean(
        &segs,
        na,
        |wa, wb| op.apply(rule.inside(wa), rule.inside(wb)),
        opts.keep_collinear,
    )
}

/// [`boolean_with`] by the DCEL: [`boolean_dcel`] and [`faces_to_polygons`] (the
/// reference the traced path is tested against).
#[cfg(test)]
pub(crate) fn boolean_via_dcel(
    a: &MultiPolygon,
    b: &MultiPolygon,
    op: BooleanOp,
    opts: &BooleanOptions,
) -> Result<MultiPolygon> {
    let d = boolean_dcel(a, b, opts.fill_rule)?;
    let rule = opts.fill_rule;
    let inside = |f| {
        let (wa, wb) = d.face(f).data;
        op.apply(rule.inside(wa), rule.inside(wb))
    };
    Ok(faces_to_polygons(
        &d,
        inside,
        |e| e.carrier,
        opts.keep_collinear,
    ))
}

/// The union of all polygons of a set in one sweep ([`FillRule::Positive`]): each
/// polygon is its exterior minus its holes, and a point is in the union when it lies in
/// at least one polygon. O((n + k) log n) for n edges and k crossings, not n − 1
/// pairwise unions.
///
/// ```
/// use compgeom::overlay::union_all;
/// use compgeom::{MultiPolygon, Point2, Polygon};
/// let sq = |x: f64| Polygon::new(vec![Point2::new(x, 0.0), Point2::new(x + 2.0, 0.0),
///     Point2::new(x + 2.0, 2.0), Point2::new(x, 2.0)], vec![]);
/// // Three overlapping squares in a row and one apart: two polygons.
/// let u = union_all(&MultiPolygon(vec![sq(0.0), sq(1.0), sq(2.0), sq(10.0)])).unwrap();
/// assert_eq!(u.0.len(), 2);
/// assert_eq!(u.0[0].exterior.len(), 4);
/// ```
pub fn union_all(polygons: &MultiPolygon) -> Result<MultiPolygon> {
    boolean_with(
        polygons,
        &MultiPolygon::default(),
        BooleanOp::Union,
        &BooleanOptions {
            fill_rule: FillRule::Positive,
            keep_collinear: false,
        },
    )
}

/// Repair a polygon set into a valid one: the region the fill rule reads from its rings
/// (self-crossing rings, overlapping parts, holes outside shells, wrong orientations,
/// repeated or collinear points), as valid polygons. Errors as [`boolean_with`].
///
/// ```
/// use compgeom::overlay::{make_valid, FillRule};
/// use compgeom::{MultiPolygon, Point2, Polygon};
/// // A bow tie: one self-crossing ring becomes two triangles.
/// let p = |x, y| Point2::new(x, y);
/// let bow = MultiPolygon(vec![Polygon::new(vec![p(0., 0.), p(2., 2.), p(2., 0.), p(0., 2.)], vec![])]);
/// let fixed = make_valid(&bow, FillRule::EvenOdd).unwrap();
/// assert_eq!(fixed.0.len(), 2);
/// ```
pub fn make_valid(polygons: &MultiPolygon, rule: FillRule) -> Result<MultiPolygon> {
    boolean_with(
        polygons,
        &MultiPolygon::default(),
        BooleanOp::Union,
        &BooleanOptions {
            fill_rule: rule,
            keep_collinear: false,
        },
    )
}

/// Repair each polygon of a set on its own, its shell and holes read together by `rule`
/// (as [`make_valid`] reads a set of one polygon), then unite the repaired polygons: where
/// polygons of the set overlap, the result is inside (with [`make_valid`] and the
/// even-odd rule, two polygons covering a place cancel out). For layers of parts that may
/// overlap and may cross themselves (a parcel drawn twice, a bow tie beside a square).
/// Errors as [`boolean_with`].
///
/// Each polygon's repair is rounded to `f64` (and checked, as every result is) before
/// the union, which is exact on those points: the result is the union of the repaired
/// polygons as written out. Cost: one [`make_valid`] per polygon and one [`union_all`].
///
/// ```
/// use compgeom::overlay::{make_valid, make_valid_per_polygon, FillRule};
/// use compgeom::{MultiPolygon, Point2, Polygon};
/// let p = |x, y| Point2::new(x, y);
/// let square = Polygon::new(vec![p(0., 0.), p(2., 0.), p(2., 2.), p(0., 2.)], vec![]);
/// // The same square twice: even-odd over the set cancels it, per polygon it stays.
/// let twice = MultiPolygon(vec![square.clone(), square]);
/// assert!(make_valid(&twice, FillRule::EvenOdd).unwrap().0.is_empty());
/// let kept = make_valid_per_polygon(&twice, FillRule::EvenOdd).unwrap();
/// assert_eq!(kept.0.len(), 1);
/// ```
pub fn make_valid_per_polygon(polygons: &MultiPolygon, rule: FillRule) -> Result<MultiPolygon> {
    // (Bad input is reported with its place in the whole set, before any polygon alone.)
    polygon_segments(polygons)?;
    let mut parts = Vec::new();
    for polygon in &polygons.0 {
        parts.extend(make_valid(&MultiPolygon(vec![polygon.clone()]), rule)?.0);
    }
    union_all(&MultiPolygon(parts))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Point2;
    use proptest::prelude::*;

    /// The segments as they were built before [`oriented_segments`] worked in place: each
    /// ring cloned and reversed where needed, then [`polygon_segments`] of each set.
    fn by_copies(a: &MultiPolygon, b: &MultiPolygon, rule: FillRule) -> Result<Vec<Segment2>> {
        let one = |p: &MultiPolygon| -> Result<Vec<Segment2>> {
            if rule != FillRule::Positive {
                return Ok(polygon_segments(p)?.0);
            }
            let orient = |r: &Vec<Point2>, ccw: bool| {
                let o = ring_orientation(r);
                let mut r = r.clone();
                if (o == Orientation::Clockwise && ccw)
                    || (o == Orientation::CounterClockwise && !ccw)
                {
                    r.reverse();
                }
                r
            };
            let fixed = MultiPolygon(
                p.0.iter()
                    .map(|q| {
                        crate::Polygon::new(
                            orient(&q.exterior, true),
                            q.holes.iter().map(|h| orient(h, false)).collect(),
                        )
                    })
                    .collect(),
            );
            Ok(polygon_segments(&fixed)?.0)
        };
        let mut segs = one(a)?;
        segs.extend(one(b)?);
        Ok(segs)
    }

    /// Large inputs' polygons go in Z-order before the arrangement is built
    /// ([`locality`]): every operation gives the same result as from the segments in the
    /// given order, and as from each input's segments in reverse order.
    #[test]
    fn reordering_large_inputs_changes_no_result() {
        // 80 quadrilaterals per input with float corners within one of random centres
        // in a square of side 8 (they overlap and cross), each side cut into 64 pieces
        // (2¹⁴ points or more).
        let mut seed = 11u64;
        let mut unit = || {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut set = || {
            let polygons = (0..80)
                .map(|_| {
                    let (cx, cy) = (8.0 * unit(), 8.0 * unit());
                    let corners: Vec<Point2> = (0..4)
                        .map(|_| Point2::new(cx + 2.0 * unit() - 1.0, cy + 2.0 * unit() - 1.0))
                        .collect();
                    let ring = (0..4)
                        .flat_map(|i| {
                            let (a, b) = (corners[i], corners[(i + 1) % 4]);
                            (0..64).map(move |k| {
                                let t = f64::from(k) / 64.0;
                                Point2::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y))
                            })
                        })
                        .collect();
                    crate::Polygon::new(ring, vec![])
                })
                .collect();
            MultiPolygon(polygons)
        };
        let (a, b) = (set(), set());
        for rule in [FillRule::EvenOdd, FillRule::Positive] {
            let (segs, na) = oriented_segments(&a, &b, rule).unwrap();
            let given = by_copies(&a, &b, rule).unwrap();
            assert_eq!(
                na,
                by_copies(&a, &MultiPolygon::default(), rule).unwrap().len()
            );
            assert_ne!(&segs[..], &given[..], "reordered");
            let mut reversed = given.clone();
            reversed[..na].reverse();
            reversed[na..].reverse();
            for op in [
                BooleanOp::Intersection,
                BooleanOp::Union,
                BooleanOp::Difference,
                BooleanOp::Xor,
            ] {
                let result = |segs: &[Segment2]| {
                    let inside = |wa, wb| op.apply(rule.inside(wa), rule.inside(wb));
                    super::super::trace::traced_boolean(segs, na, inside, false).unwrap()
                };
                let r = result(&segs);
                assert!(!r.0.is_empty());
                assert_eq!(r, result(&given), "{op:?} {rule:?}: given order");
                assert_eq!(r, result(&reversed), "{op:?} {rule:?}: reversed");
            }
        }
    }

    /// Rings on a coarse grid (repeated and collinear points, closed or open, too few
    /// distinct points), scaled to tiny or huge magnitudes, with `-0.0` and now and then
    /// a non-finite coordinate.
    fn ring() -> impl Strategy<Value = Vec<Point2>> {
        (
            prop::collection::vec((-2i32..3, -2i32..3), 0..8),
            any::<bool>(),
            prop::sample::select(vec![1.0, 1e-300, 1e300, -0.5]),
            0u8..20,
        )
            .prop_map(|(pts, close, scale, bad)| {
                let mut r: Vec<Point2> = pts
                    .iter()
                    .map(|&(x, y)| {
                        let c = |v: i32| if v == 0 { -0.0 } else { f64::from(v) * scale };
                        Point2::new(c(x), c(y))
                    })
                    .collect();
                if close && !r.is_empty() {
                    r.push(r[0]);
                }
                if bad == 0 && !r.is_empty() {
                    let k = pts.len() / 2;
                    r[k].y = f64::NAN;
                }
                r
            })
    }

    fn set() -> impl Strategy<Value = MultiPolygon> {
        prop::collection::vec((ring(), prop::collection::vec(ring(), 0..3)), 0..3).prop_map(|ps| {
            MultiPolygon(
                ps.into_iter()
                    .map(|(e, h)| crate::Polygon::new(e, h))
                    .collect(),
            )
        })
    }

    proptest! {
        /// In place (rings read backwards where they are turned) gives the segments, their
        /// order and the errors of copying the turned rings.
        #[test]
        fn oriented_segments_match_turned_copies(a in set(), b in set()) {
            for rule in [FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive] {
                let fast = oriented_segments(&a, &b, rule);
                match (fast, by_copies(&a, &b, rule)) {
                    (Ok((segs, na)), Ok(slow)) => {
                        prop_assert_eq!(&segs[..], &slow[..]);
                        let only_a = by_copies(&a, &MultiPolygon::default(), rule).unwrap();
                        prop_assert_eq!(na, only_a.len());
                    }
                    (Err(x), Err(y)) => prop_assert_eq!(x.to_string(), y.to_string()),
                    (x, y) => prop_assert!(false, "{:?} vs {:?}", x.map(|s| s.1), y.map(|s| s.len())),
                }
            }
        }
    }
}
