//! [`TrapezoidalMap`]: the public face of the trapezoidal map of a set of segments.
use super::check::check_interior_disjoint;
use super::trapmap::{lex, Core, CoreHit, NONE};
use crate::kernel::{Bbox2, ExactPoint, Point2, Segment2};
use crate::lp::Shuffler;
use crate::{Error, Result};
use std::cmp::Ordering;
use std::collections::HashMap;

/// The seed used when none is given: construction is deterministic by default.
pub const DEFAULT_SEED: u64 = 0x5EED_0F7A_9E20;

/// What a query point hit in a [`TrapezoidalMap`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MapHit {
    /// The point lies in the interior of trapezoid `i` (or on one of its vertical
    /// sides that no segment bounds: those belong to the trapezoid on their right, in
    /// the sheared order of §6.3).
    Trapezoid(usize),
    /// The point lies in the relative interior of segment `i` (an input index).
    Segment(usize),
    /// The point is endpoint `i` ([`TrapezoidalMap::vertices`]).
    Vertex(usize),
}

/// A trapezoid of the map (§6.1). Segments are input indices, points are indices into
/// [`TrapezoidalMap::vertices`]; `None` stands for the unbounded sides of the map (it
/// extends to infinity in every direction, so every finite point is inside).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Trapezoid {
    /// top(Δ): the segment bounding it from above.
    pub top: Option<usize>,
    /// bottom(Δ): the segment bounding it from below.
    pub bottom: Option<usize>,
    /// leftp(Δ): the point defining its left side.
    pub left: Option<usize>,
    /// rightp(Δ): the point defining its right side.
    pub right: Option<usize>,
    /// The neighbour across the left side above `left`.
    pub upper_left: Option<usize>,
    /// The neighbour across the left side below `left`.
    pub lower_left: Option<usize>,
    /// The neighbour across the right side above `right`.
    pub upper_right: Option<usize>,
    /// The neighbour across the right side below `right`.
    pub lower_right: Option<usize>,
}

/// Size and depth of the search structure D (§6.2: expected O(n) size, O(log n) query).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct DagStats {
    /// Segments inserted.
    pub segments: usize,
    /// Trapezoids of the map (= leaves of D).
    pub trapezoids: usize,
    /// x-nodes (one per endpoint).
    pub x_nodes: usize,
    /// y-nodes.
    pub y_nodes: usize,
    /// All nodes of D.
    pub nodes: usize,
    /// The longest root-to-leaf path, counted in internal nodes: the worst query cost.
    pub depth: usize,
}

/// The trapezoidal map of a set of interior-disjoint segments and its search structure
/// (book §6.1–6.3), built by the randomized incremental TRAPEZOIDALMAP.
///
/// ```
/// use compgeom::locate::{MapHit, TrapezoidalMap};
/// use compgeom::{Point2, Segment2};
/// let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
/// // Two segments sharing the endpoint (2, 2), and a vertical one.
/// let map = TrapezoidalMap::new(&[s((0., 0.), (2., 2.)), s((2., 2.), (4., 0.)), s((5., 0.), (5., 3.))]).unwrap();
/// map.validate().unwrap();
/// assert_eq!(map.locate(Point2::new(1.0, 1.0)).unwrap(), MapHit::Segment(0));
/// assert_eq!(map.locate(Point2::new(5.0, 1.0)).unwrap(), MapHit::Segment(2));
/// let MapHit::Trapezoid(t) = map.locate(Point2::new(2.0, 1.0)).unwrap() else { panic!() };
/// // (2, 1) is just left of the vertex (2, 2) in the sheared order: under segment 0.
/// assert_eq!(map.trapezoid(t).top, Some(0));
/// assert_eq!(map.trapezoid(t).bottom, None);
/// let hit = map.locate(Point2::new(2.0, 2.0)).unwrap();
/// assert_eq!(hit, MapHit::Vertex(map.vertex_index(Point2::new(2.0, 2.0)).unwrap()));
/// ```
#[derive(Debug, Clone)]
pub struct TrapezoidalMap {
    pub(crate) core: Core,
    /// Input index of each segment of the core.
    pub(crate) seg_input: Vec<usize>,
    pub(crate) seed: u64,
}

/// The map key of a point (-0.0 folded into 0.0 so that equal points are one vertex).
fn key(p: Point2) -> (u64, u64) {
    ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits())
}

impl TrapezoidalMap {
    /// The map of `segments` with the default seed. See [`TrapezoidalMap::with_seed`].
    pub fn new(segments: &[Segment2]) -> Result<TrapezoidalMap> {
        Self::with_seed(segments, DEFAULT_SEED)
    }

    /// The map of `segments`, inserted in the random order drawn from `seed` (the same
    /// seed gives the same structure). The segments must be interior-disjoint: two may
    /// share an endpoint but not cross, overlap, or touch another's interior (checked
    /// exactly with the intersection sweep, O(n log n)). Exact duplicates are kept once
    /// (the lowest index is reported); zero-length segments are ignored. Errors:
    /// non-finite coordinates, and the first offending pair, named by input index.
    /// Expected O(n log n) time, O(n) space.
    pub fn with_seed(segments: &[Segment2], seed: u64) -> Result<TrapezoidalMap> {
        let mut points = Vec::new();
        let mut index: HashMap<(u64, u64), u32> = HashMap::new();
        let mut seen: HashMap<(u32, u32), usize> = HashMap::new();
        let mut segs = Vec::new();
        let mut seg_input = Vec::new();
        for (i, s) in segments.iter().enumerate() {
            crate::kernel::ensure_finite(&[s.a, s.b], "segment").map_err(|_| non_finite(i, s))?;
            if s.a == s.b {
                continue;
            }
            let mut id = |p: Point2| {
                *index.entry(key(p)).or_insert_with(|| {
                    points.push(p);
                    (points.len() - 1) as u32
                })
            };
            let (a, b) = (id(s.a), id(s.b));
            let (l, r) = if lex(s.a, s.b) == Ordering::Less {
                (a, b)
            } else {
                (b, a)
            };
            if seen.insert((l, r), i).is_none() {
                segs.push([l, r]);
                seg_input.push(i);
            }
        }
        check_interior_disjoint(&points, &segs, &seg_input)?;
        Self::from_parts(points, Vec::new(), segs, seg_input, seed)
    }

    /// Build from prepared parts (distinct points, lexicographically sorted distinct
    /// endpoints, interior-disjoint segments). `exact`: the exact points when some are
    /// constructed (`points` then holds them rounded), else empty.
    pub(crate) fn from_parts(
        points: Vec<Point2>,
        exact: Vec<ExactPoint>,
        segs: Vec<[u32; 2]>,
        seg_input: Vec<usize>,
        seed: u64,
    ) -> Result<TrapezoidalMap> {
        if points.len() >= NONE as usize || segs.len() >= (NONE as usize) / 8 {
            return Err(Error::InvalidInput(format!(
                "{} segments are more than the trapezoidal map's 32-bit indices hold",
                segs.len()
            )));
        }
        let mut order: Vec<u32> = (0..segs.len() as u32).collect();
        Shuffler::new(seed).shuffle(&mut order);
        let core = Core::build(points, exact, segs, &order)?;
        Ok(TrapezoidalMap {
            core,
            seg_input,
            seed,
        })
    }

    /// Locate `q`: the trapezoid containing it, or the segment or endpoint it lies on.
    /// Exact. Expected O(log n) time. Error: a non-finite coordinate.
    pub fn locate(&self, q: Point2) -> Result<MapHit> {
        check_query(q, 0)?;
        Ok(self.hit(q))
    }

    pub(crate) fn hit(&self, q: Point2) -> MapHit {
        match self.core.locate(q) {
            CoreHit::Trap(t) => MapHit::Trapezoid(t as usize),
            CoreHit::Seg(s) => MapHit::Segment(self.seg_input[s as usize]),
            CoreHit::Point(p) => MapHit::Vertex(p as usize),
        }
    }

    /// The distinct endpoints of the (non-degenerate) segments.
    pub fn vertices(&self) -> &[Point2] {
        &self.core.points
    }

    /// The index of `p` among [`TrapezoidalMap::vertices`], if it is an endpoint.
    pub fn vertex_index(&self, p: Point2) -> Option<usize> {
        self.core.points.iter().position(|&v| v == p)
    }

    /// Number of segments in the map (duplicates and zero-length ones left out).
    pub fn segment_count(&self) -> usize {
        self.core.segs.len()
    }

    /// The input index of each segment in the map.
    pub fn segment_indices(&self) -> &[usize] {
        &self.seg_input
    }

    /// The seed of the insertion order.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// Number of trapezoids (at most 3n + 1 for n segments, Lemma 6.2).
    pub fn trapezoid_count(&self) -> usize {
        self.core.traps.len()
    }

    /// Trapezoid `i`.
    pub fn trapezoid(&self, i: usize) -> Trapezoid {
        let t = self.core.traps[i];
        let opt = |x: u32| (x != NONE).then_some(x as usize);
        let seg = |x: u32| (x != NONE).then(|| self.seg_input[x as usize]);
        Trapezoid {
            top: seg(t.top),
            bottom: seg(t.bottom),
            left: opt(t.leftp),
            right: opt(t.rightp),
            upper_left: opt(t.ul),
            lower_left: opt(t.ll),
            upper_right: opt(t.ur),
            lower_right: opt(t.lr),
        }
    }

    /// Size and depth of the search structure.
    pub fn stats(&self) -> DagStats {
        let f = &self.core.frozen;
        DagStats {
            segments: self.core.segs.len(),
            trapezoids: self.core.traps.len(),
            x_nodes: f.x_nodes,
            y_nodes: f.y_nodes,
            nodes: f.x_nodes + f.y_nodes + self.core.traps.len(),
            depth: f.depth,
        }
    }

    /// The segment (by its index in the map, not the input) as a `Segment2`, left to right.
    fn seg(&self, s: u32) -> Segment2 {
        let [l, r] = self.core.segs[s as usize];
        Segment2::new(self.core.points[l as usize], self.core.points[r as usize])
    }

    /// Trapezoid `i` drawn inside `bbox` (sides at infinity moved to the box): its
    /// corners counter-clockwise from the lower left, rounded. Trapezoids of zero width
    /// (beside vertical segments, or between segments sharing an endpoint) come out
    /// degenerate. For pictures only.
    pub fn trapezoid_polygon(&self, i: usize, bbox: &Bbox2) -> Vec<Point2> {
        let t = self.core.traps[i];
        let x = |p: u32, dflt: f64| {
            if p == NONE {
                dflt
            } else {
                self.core.points[p as usize].x.clamp(bbox.min.x, bbox.max.x)
            }
        };
        let (x0, x1) = (x(t.leftp, bbox.min.x), x(t.rightp, bbox.max.x));
        let y_at = |s: u32, x: f64, dflt: f64| {
            if s == NONE {
                return dflt;
            }
            let g = self.seg(s);
            if g.a.x == g.b.x {
                return if dflt > bbox.min.y { g.a.y } else { g.b.y };
            }
            let u = ((x - g.a.x) / (g.b.x - g.a.x)).clamp(0.0, 1.0);
            g.a.y + u * (g.b.y - g.a.y)
        };
        vec![
            Point2::new(x0, y_at(t.bottom, x0, bbox.min.y)),
            Point2::new(x1, y_at(t.bottom, x1, bbox.min.y)),
            Point2::new(x1, y_at(t.top, x1, bbox.max.y)),
            Point2::new(x0, y_at(t.top, x0, bbox.max.y)),
        ]
    }

    /// Check the map's invariants: neighbour links are mutual, every trapezoid's left
    /// point precedes its right point (lexicographically), its top and bottom segments
    /// span its x-range and the top is above the bottom, and every trapezoid is a leaf of D. Error: the first broken invariant.
    pub fn validate(&self) -> Result<()> {
        let c = &self.core;
        let bad = |m: String| Err(Error::Verification(m));
        let n = c.traps.len();
        for (i, t) in c.traps.iter().enumerate() {
            let i32 = i as u32;
            for (nb, back) in [(t.ur, 0), (t.lr, 1)] {
                if nb != NONE {
                    let o = c.traps[nb as usize];
                    if o.ul != i32 && o.ll != i32 {
                        return bad(format!("trapezoid {nb} does not link back to {i} ({back})"));
                    }
                    if o.leftp != t.rightp {
                        return bad(format!("trapezoids {i} and {nb} meet at different points"));
                    }
                }
            }
            for nb in [t.ul, t.ll] {
                if nb != NONE {
                    let o = c.traps[nb as usize];
                    if o.ur != i32 && o.lr != i32 {
                        return bad(format!("trapezoid {nb} does not link back to {i}"));
                    }
                }
            }
            if t.leftp != NONE && t.rightp != NONE && c.cmp(t.leftp, t.rightp) != Ordering::Less {
                return bad(format!(
                    "trapezoid {i} has its left point not before its right"
                ));
            }
            for s in [t.top, t.bottom] {
                if s == NONE {
                    continue;
                }
                let [l, r] = c.segs[s as usize];
                let inside = |p: u32, left: bool| {
                    if p == NONE {
                        return false;
                    }
                    if left {
                        c.cmp(l, p) != Ordering::Greater
                    } else {
                        c.cmp(p, r) != Ordering::Greater
                    }
                };
                if !inside(t.leftp, true) || !inside(t.rightp, false) {
                    return bad(format!("segment of trapezoid {i} does not span it"));
                }
            }
            if t.top != NONE && t.bottom != NONE && t.top == t.bottom {
                return bad(format!("trapezoid {i} has the same top and bottom"));
            }
        }
        let mut seen = vec![false; n];
        for t in c.frozen.leaves() {
            let t = t as usize;
            if t >= n {
                return bad(format!("a leaf names trapezoid {t} of {n}"));
            }
            seen[t] = true;
        }
        if let Some(t) = seen.iter().position(|s| !s) {
            return bad(format!("trapezoid {t} has no leaf"));
        }
        Ok(())
    }
}

fn non_finite(i: usize, s: &Segment2) -> Error {
    let v = [s.a.x, s.a.y, s.b.x, s.b.y]
        .into_iter()
        .find(|v| !v.is_finite())
        .unwrap_or(f64::NAN);
    Error::NonFinite {
        what: format!("segment {i}"),
        value: v,
    }
}

/// `Err` for a non-finite query point `i`.
pub(crate) fn check_query(q: Point2, i: usize) -> Result<()> {
    if q.is_finite() {
        Ok(())
    } else {
        Err(Error::NonFinite {
            what: format!("query point {i}"),
            value: if q.x.is_finite() { q.y } else { q.x },
        })
    }
}
