//! Segment intersection (book chapter 2.1): the Bentley–Ottmann plane sweep, exact, with
//! every degenerate case.
//!
//! [`sweep_intersections`] is the book's FINDINTERSECTIONS / HANDLEEVENTPOINT /
//! FINDNEWEVENT on **closed** segments: for n segments and I intersection points it takes
//! O((n + I) log n) time (expected: the status is a treap) and O(n) working space beyond
//! the output (only crossings of segments adjacent on the sweep line stay queued).
//! [`find_intersections`], the default, gives the same answer by the fastest exact method
//! for the input: the sweep, or [`pairwise_intersections`] (exact tests of the pairs with
//! overlapping bounding boxes, found with a uniform grid, or for long segments by a sort
//! and sweep along one axis when that looks at fewer pairs) unless many pairs share grid
//! cells without meeting ([`IntersectAlgorithm`]).
//!
//! ## Sweep order
//!
//! As in the book, the sweep line is horizontal and moves **down**: point `p` comes before
//! `q` when `p.y > q.y`, or `p.y = q.y` and `p.x < q.x`. A segment's *upper* endpoint is the
//! one met first (for a horizontal segment the left one). Results come out in this order,
//! so output is reproducible byte for byte.
//!
//! ## What is reported
//!
//! * An **intersection point** is a point that lies on two or more segments and is either
//!   an endpoint of some segment or a proper crossing (a point where two segments that are
//!   not collinear meet). For each: the nearest `f64` point, the segments through it split
//!   as in the book into U(p) (upper endpoint is p), L(p) (lower endpoint is p) and C(p)
//!   (p in the interior), and for a crossing the two segments that define it (the exact
//!   point, [`IntersectionPoint::exact`]). A zero-length segment at p is in both
//!   U(p) and L(p). Interior points of an overlap are not intersection points (there are
//!   infinitely many) unless something else happens there.
//! * An **overlap** is a maximal piece of positive length along which the set of segments
//!   covering it stays the same, with two or more segments in the set (collinear
//!   overlapping segments, duplicates). Its two ends are segment endpoints, hence also
//!   reported as intersection points.
//!
//! ## Degenerate cases
//!
//! Horizontal segments (left endpoint upper; ordered last among segments through a
//! point), vertical segments, three or more segments through a point, endpoints in other
//! segments' interiors, shared endpoints, duplicate segments, zero-length segments (a
//! point segment meets whatever passes through it; two equal point segments meet each
//! other), overlapping collinear segments. Non-finite coordinates are an
//! [`Error::NonFinite`](crate::Error::NonFinite) naming the segment.
//!
//! ## Exactness
//!
//! Every decision (event order, the side of a segment at the event point, the order just
//! below a point, whether two segments meet, which crossings coincide) is exact: the
//! kernel's predicates on input points and on crossings kept as their two segments
//! ([`crate::kernel::Crossing`]), behind cheaper exact shortcuts that only decide when
//! they are sure: an error-bounded box around each crossing (disjoint boxes order two
//! points), an orientation filter at a crossing, and `i128` arithmetic when every
//! coordinate involved is an integer below 2^20 (grid data). The pairwise method tests
//! each candidate pair with four `f64` orientations against one static error bound for
//! the whole input first (one comparison each; it decides only where the kernel's
//! dynamic filter decides, and the same way), then the dynamic filter, then the exact
//! test. Reported coordinates are the nearest `f64` to the exact point (the kernel's
//! correctly rounded [`Crossing::approx`](crate::kernel::Crossing::approx); the pairwise
//! method first tries a certified straight-line double-double evaluation that gives the
//! same bits faster).
//!
//! ## Output size
//!
//! An [`IntersectionPoint`] is 40 bytes: the rounded point, its lists (inline, as ranges
//! into the sorted pair, when at most two segments meet there: a crossing, a shared
//! endpoint, a T-junction), and for a crossing the defining pair of segments, from which
//! the exact point is rebuilt on demand.
//!
//! ## Also here
//!
//! * [`any_intersection`] / [`any_intersection_where`]: the sweep stopped at the first
//!   intersection in sweep order (the Shamos–Hoey idea), and [`is_simple`] for polygons
//!   built on it.
//! * [`red_blue_intersections`]: two sets whose members do not cross within their own set
//!   (the map-overlay case); one sweep, only red–blue intersections are reported.
//! * [`sweep_status_at`]: the status structure after a given event, for pictures.
//! * [`count_intersections`]: the numbers of points, overlaps and meeting pairs, exactly,
//!   without building the points (no rounding, no segment lists).
//! * [`brute_force_intersections`] and [`verify_intersections`]: the exact O(n²) oracle.
//!
//! ```
//! use compgeom::intersect::find_intersections;
//! use compgeom::{Point2, Segment2};
//! let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
//! let segs = [s((0.0, 0.0), (2.0, 2.0)), s((0.0, 2.0), (2.0, 0.0)), s((1.0, 1.0), (1.0, 5.0))];
//! let found = find_intersections(&segs).unwrap();
//! assert_eq!(found.points.len(), 1);
//! let p = &found.points[0];
//! assert_eq!(p.point, Point2::new(1.0, 1.0));
//! assert_eq!(p.segments(), [0, 1, 2]);
//! assert_eq!(p.lower(), [2]); // (1, 1) is the lower endpoint of segment 2
//! assert_eq!(p.interior(), [0, 1]);
//! ```
mod bins;
mod brute_force;
mod bucket;
mod count;
mod list;
mod order;
pub(crate) use order::sweep_cmp_points;
mod pairwise;
mod red_blue;
mod round;
mod simple;
mod small_int;
mod status;
mod sweep;

pub use brute_force::{brute_force_intersections, verify_intersections};
pub use count::{count_intersections, count_intersections_with, IntersectionCount};
pub use list::IntersectionPoint;
pub use pairwise::pairwise_intersections;
// For the overlay's own noding (crate::dcel), which needs the candidate pairs only.
pub(crate) use pairwise::{prefer_pairwise, PARALLEL_SCAN_FROM};
pub use red_blue::{red_blue_intersections, RedBlueIntersections, RedBlueOverlap, RedBluePoint};
pub(crate) use round::round_crossing;
pub(crate) use simple::clean_ring;
pub use simple::{any_intersection, any_intersection_where, is_simple};
pub use sweep::SweepStats;

use crate::kernel::{Point2, Segment2};
use crate::Result;
use sweep::{Flow, Sink};

/// A maximal piece of positive length covered by the same two or more segments.
#[derive(Debug, Clone, PartialEq)]
pub struct Overlap {
    /// The segments covering the piece, ascending.
    pub segments: Vec<usize>,
    /// The end met first in sweep order (an input endpoint).
    pub from: Point2,
    /// The other end (an input endpoint).
    pub to: Point2,
}

/// Everything [`find_intersections`] found.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Intersections {
    /// The intersection points, in sweep order.
    pub points: Vec<IntersectionPoint>,
    /// The overlaps, ordered by `from`, then `to` (sweep order), then segments.
    pub overlaps: Vec<Overlap>,
    /// The number of input segments.
    pub segments: usize,
}

impl Intersections {
    /// The number of distinct pairs of segments that meet (a pair meeting at several
    /// points, or along an overlap, counts once).
    pub fn pair_count(&self) -> usize {
        let mut pairs = Vec::new();
        for p in &self.points {
            let s = p.segments();
            for (k, &i) in s.iter().enumerate() {
                for &j in &s[k + 1..] {
                    pairs.push((i, j));
                }
            }
        }
        pairs.sort_unstable();
        pairs.dedup();
        pairs.len()
    }
}

/// Sort overlaps into their documented order.
pub(crate) fn sort_overlaps(overlaps: &mut [Overlap]) {
    overlaps.sort_by(|a, b| {
        sweep_cmp_points(a.from, b.from)
            .then(sweep_cmp_points(a.to, b.to))
            .then_with(|| a.segments.cmp(&b.segments))
    });
}

/// Collects everything.
struct Collect {
    out: Intersections,
}

impl Sink for Collect {
    fn point(&mut self, point: IntersectionPoint) -> Flow {
        self.out.points.push(point);
        Flow::Continue
    }
    fn overlap(&mut self, overlap: Overlap) -> Flow {
        self.out.overlaps.push(overlap);
        Flow::Continue
    }
}

/// Which method [`find_intersections_with`] uses. All give the same answer, exactly.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum IntersectAlgorithm {
    /// Choose from the number m of candidate pairs (pairs of segments sharing a cell of
    /// a uniform grid, counted in O(n)) and an estimate of the number K of meeting pairs
    /// (from a sample of segments): [`Pairwise`](IntersectAlgorithm::Pairwise) when
    /// m is at most [`PAIRWISE_LIMIT_PER_SEGMENT`] times `n + K`, else the sweep.
    #[default]
    Default,
    /// The book's plane sweep (FINDINTERSECTIONS): O((n + I) log n), output-sensitive.
    Sweep,
    /// Exact tests of the pairs with overlapping bounding boxes, found with a uniform
    /// grid: O(n + m + K log K) for m candidate pairs and K meeting pairs.
    Pairwise,
}

/// [`IntersectAlgorithm::Default`] uses the pairwise method while the number of candidate
/// pairs is at most this many per segment or meeting pair. A candidate test costs about a
/// thousandth of a sweep event (measured with `compgeom-bench intersect`), so below this
/// the pairwise scan is the faster exact method; above it the sweep's output sensitivity
/// wins (many long segments that share cells but do not meet).
pub const PAIRWISE_LIMIT_PER_SEGMENT: usize = 1000;

/// All intersection points and overlaps of the closed segments (see the
/// [module docs](self) for exactly what is reported), by the fastest exact method for
/// the input ([`IntersectAlgorithm::Default`]).
///
/// Errors: a non-finite coordinate (naming the segment).
pub fn find_intersections(segments: &[Segment2]) -> Result<Intersections> {
    find_intersections_with(segments, IntersectAlgorithm::Default)
}

/// [`find_intersections`] with a chosen method; every method gives the same answer.
pub fn find_intersections_with(
    segments: &[Segment2],
    algorithm: IntersectAlgorithm,
) -> Result<Intersections> {
    match algorithm {
        IntersectAlgorithm::Sweep => sweep_intersections(segments),
        IntersectAlgorithm::Pairwise => pairwise_intersections(segments),
        IntersectAlgorithm::Default => {
            sweep::check_finite(segments)?;
            brute_force::check_count(segments)?;
            match pairwise::prefer_pairs(segments) {
                Some(pairs) => Ok(pairwise::intersections_on(segments, &pairs)),
                None => sweep_intersections(segments),
            }
        }
    }
}

/// All intersection points and overlaps by the book's plane sweep (FINDINTERSECTIONS /
/// HANDLEEVENTPOINT / FINDNEWEVENT): O((n + I) log n) expected time for I intersection
/// points, O(n) working space beyond the output.
pub fn sweep_intersections(segments: &[Segment2]) -> Result<Intersections> {
    sweep_intersections_with_stats(segments).map(|(r, _)| r)
}

/// [`sweep_intersections`], also returning what the sweep measured (events handled, the
/// largest queue size).
pub fn sweep_intersections_with_stats(
    segments: &[Segment2],
) -> Result<(Intersections, SweepStats)> {
    let mut sink = Collect {
        out: Intersections {
            segments: segments.len(),
            ..Intersections::default()
        },
    };
    let stats = sweep::sweep(segments, &mut sink)?;
    sort_overlaps(&mut sink.out.overlaps);
    Ok((sink.out, stats))
}

/// The sweep-line status at one moment, for pictures: the event point and the segments
/// crossing the sweep line just below it, left to right.
#[derive(Debug, Clone, PartialEq)]
pub struct StatusSnapshot {
    /// The number of the event (0 = first in sweep order).
    pub event: usize,
    /// The event point (nearest `f64`).
    pub at: Point2,
    /// The status just below the event point, left to right.
    pub status: Vec<usize>,
}

struct Snapshot {
    want: usize,
    got: Option<StatusSnapshot>,
}

impl Sink for Snapshot {
    fn point(&mut self, _: IntersectionPoint) -> Flow {
        Flow::Continue
    }
    fn overlap(&mut self, _: Overlap) -> Flow {
        Flow::Continue
    }
    fn wants_status(&self, event: usize) -> bool {
        event == self.want
    }
    fn status(&mut self, event: usize, at: Point2, status: &[usize]) {
        self.got = Some(StatusSnapshot {
            event,
            at,
            status: status.to_vec(),
        });
    }
}

/// The status structure right after the sweep handled event number `event` (`None` if
/// there are fewer events). For drawing the sweep (the book's figures).
///
/// ```
/// use compgeom::intersect::sweep_status_at;
/// use compgeom::Segment2;
/// let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
/// let segs = [s((0.0, 4.0), (4.0, 0.0)), s((3.0, 3.0), (1.0, 0.0))];
/// // Event 1 is (3, 3), the upper endpoint of segment 1: below it, 0 is left of 1.
/// let snap = sweep_status_at(&segs, 1).unwrap().unwrap();
/// assert_eq!(snap.status, vec![0, 1]);
/// ```
pub fn sweep_status_at(segments: &[Segment2], event: usize) -> Result<Option<StatusSnapshot>> {
    let mut sink = Snapshot {
        want: event,
        got: None,
    };
    sweep::sweep(segments, &mut sink)?;
    Ok(sink.got)
}
