//! A lean exact noding for the arrangement builders (book §2.3: the segments of both maps
//! cut at every point where they meet): the cuts each segment needs, found from the
//! candidate pairs of an x-interval sweep (or the intersection grid), without building the
//! full answer of [`crate::intersect::find_intersections`] (whose U(p)/L(p)/C(p) lists
//! cost four vectors per point, and whose points include every shared endpoint: every
//! vertex of every ring).
//!
//! 0. Input vertices: input of many short rings (which share vertices: maps, dissolves;
//!    see [`HASH_RINGS_BELOW`]) has its segment ends grouped into vertices once, by an
//!    exact hash of their coordinates, so that the pair tests compare vertex numbers, not
//!    points, and no pair of equal ends is recorded and joined later. On other input
//!    (long rings meet rarely at their vertices) each end is its own item, consecutive
//!    ring edges are joined at their common end, and the pair tests compare the ends'
//!    points and record the equal ones.
//! 1. Candidate pairs: the segments sorted by the bucket of the left end of their boxes
//!    (a counting sort; buckets of equal width, so the order is monotone in x), each
//!    paired with the later ones whose left bucket is at most the bucket of its right
//!    end, kept when the boxes overlap (exact `f64` comparisons). This is every pair of
//!    overlapping boxes, each once. Ring edges are short, so the pairs looked at are a few
//!    per segment (about 4.5 on the bench's stars); the sweep stops when it would look at
//!    more than [`SWEEP_PAIRS_PER_SEGMENT`] per segment (long segments, columns of boxes
//!    apart in y only) and the grid of [`crate::intersect`]'s pairwise method, which also
//!    separates boxes in y, proposes the pairs instead. Large inputs test their pairs on
//!    the rayon pool; the result does not depend on how the work was split.
//! 2. Pair tests: consecutive ring edges (the common pair) are joined at their shared end
//!    and meet nowhere else unless collinear: one orientation decided by the
//!    static-bound filter ([`static_orient_bound`], exact fallback when it cannot tell).
//!    Other pairs sharing an end vertex likewise; two segments with the same two end
//!    vertices overlap with no cut. The rest go through four filtered orientations and,
//!    when those cannot decide, [`segment_intersection`]; a *contact* is recorded when
//!    the meeting point lies in the interior of one or both segments (a proper crossing,
//!    a T-junction, the ends of a collinear overlap).
//! 3. Vertices without a global point sort: the *items* (input vertices and contacts) at
//!    one point are joined by union–find from facts the scan already knows exactly: equal
//!    ends of a tested pair (when not one vertex already), a T-contact and the end it
//!    touches, and contacts on one segment found equal when its cuts are sorted along it.
//!    Every pair of segments through a point p has overlapping boxes, so it is tested,
//!    and it links its items at p (a shared end, or a contact on the segment p is
//!    interior to): the items at p form one class. A vertex is an input point whenever
//!    one of its items is.
//! 4. Each segment is cut at its contacts, sorted along it (exact lexicographic order,
//!    decided by the rounded points where they differ — rounding is monotone, crossings
//!    are correctly rounded — and exactly where they tie). Only segments in a collinear
//!    overlap can give pieces with the same two ends; only those go through a merge.
//!    Vertices are numbered at their first use by the edges, in segment order.
//!
//! The result is the arrangement [`Flat::general`] builds from the sweep (tested against
//! it and against a brute-force oracle on degenerate input; the x-sweep and the grid give
//! the same arrangement, numbered alike). When the grid too would test too many pairs
//! (see [`crate::intersect::prefer_pairwise`]) the intersection sweep does it all.
//!
//! Cost: O(n + m + K log K) for n segments, m candidate pairs looked at and K contacts
//! (expected, for the hash of the ends; near-linear union–find); the work over all
//! segments is a few plain passes.
use super::build::Source;
use super::flat::{ExactVertices, Flat, Pieces, Vertices};
use super::holes::{compare_xy_filtered, Rounded};
use crate::delaunay::EdgeMap;
use crate::intersect::{prefer_pairwise, round_crossing, PARALLEL_SCAN_FROM};
use crate::kernel::steps::Steps;
use crate::kernel::{
    compare_xy, orient2d, orient_static, quick_crossing_static, static_orient_bound, Crossing,
    ExactPoint, Orientation, Point2, Segment2, SegmentIntersection,
};
use crate::scratch::{self, Scratch};
use crate::Result;
use rayon::prelude::*;
use std::borrow::Cow;
use std::cmp::Ordering;

const NONE: u32 = u32::MAX;

/// A point where two segments meet that lies in the interior of segment `a` (and of `b`
/// unless `b` is `NONE`).
#[derive(Clone, Copy, Debug)]
struct Contact {
    /// The input point, or the correctly rounded crossing.
    point: Point2,
    a: u32,
    b: u32,
    /// A proper crossing of `a < b` (the exact point is their [`Crossing`]).
    crossing: bool,
    /// For an input point: the vertex (see [`Ends`]) of the segment end it is, or `NONE`.
    end: u32,
}
scratch::reusable!(Contact);

/// A segment, its number and its end vertices.
type Seg = (Segment2, u32, [u32; 2]);

/// The vertices of the segment ends, below `count`. When `exact`, equal points are one
/// vertex, numbered in order of first appearance: `of[k]` = the vertices of segment k's
/// ends `a` and `b`, `points[v]` the point of vertex v. Else (`of` and `points` empty)
/// vertex `2k` or `2k + 1` is end `a` or `b` of segment k: the start of a segment equal
/// to the end of the one before (consecutive ring edges) is joined to it in the
/// assembly, other equal ends by the pair tests, which compare their points.
struct Ends {
    of: Vec<[u32; 2]>,
    points: Vec<Point2>,
    count: usize,
    exact: bool,
}

/// Input of rings shorter than this on average (in edges) has its ends hashed into exact
/// vertices: many rings share vertices (maps, dissolves), and comparing vertex numbers
/// in the pair tests pays for the hash; long rings (few starts) rarely meet at their
/// vertices, and the hash would cost more than the equal ends it finds.
const HASH_RINGS_BELOW: usize = 16;

/// Whether `sub` looks like many short rings (fewer than [`HASH_RINGS_BELOW`] edges on
/// average): maps and dissolves, whose rings share vertices and sides. The ring starts
/// (segments not joined to the one before) are all counted: a count over a sample of 32
/// segments called the GEOS-837 dissolve (487 rings of 5.3 edges on average)
/// long-ringed once its polygons came in another order (2 of the 32 were starts), which
/// cost it 66% more instructions.
pub(super) fn short_rings(sub: &[Segment2]) -> bool {
    let joins = sub.len().saturating_sub(1);
    let starts = sub.windows(2).filter(|w| w[0].b != w[1].a).count();
    joins < HASH_RINGS_BELOW * starts
}

impl Ends {
    fn of(sub: &[Segment2]) -> Ends {
        if short_rings(sub) {
            Ends::hashed(sub)
        } else {
            Ends::by_segments(sub.len())
        }
    }

    /// The ends of `n` segments numbered by segment (not exact).
    fn by_segments(n: usize) -> Ends {
        Ends {
            of: Vec::new(),
            points: Vec::new(),
            count: 2 * n,
            exact: false,
        }
    }

    /// Equal points (exact `f64` equality, so -0 = 0) get one vertex: found by an
    /// open-addressing hash of the coordinates' bits (-0 folded into 0), O(n) expected.
    fn hashed(sub: &[Segment2]) -> Ends {
        let n = sub.len();
        // At most 2n vertices: a table at most 2/3 full.
        let bits = (3 * n).max(16).next_power_of_two().trailing_zeros();
        let mut table = PointTable {
            slots: vec![NONE; 1 << bits],
            shift: 64 - bits,
            points: Vec::with_capacity(2 * n),
        };
        let mut of: Vec<[u32; 2]> = Vec::with_capacity(n);
        let mut last = Point2::new(f64::NAN, f64::NAN);
        let mut last_v = NONE;
        for s in sub {
            let a = if s.a == last {
                last_v
            } else {
                table.vertex(s.a)
            };
            last = s.b;
            last_v = table.vertex(s.b);
            of.push([a, last_v]);
        }
        Ends {
            of,
            count: table.points.len(),
            points: table.points,
            exact: true,
        }
    }
}

/// An open-addressing (linear probing) hash of points to their vertex numbers.
struct PointTable {
    slots: Vec<u32>,
    shift: u32,
    points: Vec<Point2>,
}

impl PointTable {
    /// The vertex of `p`, a new one when `p` is new.
    #[inline(always)]
    fn vertex(&mut self, p: Point2) -> u32 {
        let (x, y) = ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits());
        let h = (x.wrapping_mul(0x9E37_79B9_7F4A_7C15).rotate_left(29) ^ y)
            .wrapping_mul(0xD6E8_FEB8_6659_FD93);
        let mask = self.slots.len() - 1;
        let mut at = (h >> self.shift) as usize;
        loop {
            let v = self.slots[at & mask];
            if v == NONE {
                let v = self.points.len() as u32;
                self.slots[at & mask] = v;
                self.points.push(p);
                return v;
            }
            if self.points[v as usize] == p {
                return v;
            }
            at += 1;
        }
    }
}

/// What the scanned pairs contribute.
#[derive(Default)]
struct Found {
    contacts: Scratch<Contact>,
    /// Pairs overlapping collinearly.
    overlapping: Scratch<(u32, u32)>,
    /// Pairs of different vertices at one point (only when the [`Ends`] are not exact).
    same: Scratch<(u32, u32)>,
    /// When not empty, per segment the first segment with its two end vertices when it is
    /// a copy, else `NONE` (see [`Copies`]): its pieces are its first's.
    copies: Vec<u32>,
}

impl Found {
    /// Empty records with room for what the scan of `n` segments usually finds (growing
    /// them pair by pair was ~8 reallocations per call on the JTS pairs); `same` only when
    /// the ends are not `exact`.
    fn for_segments(n: usize, exact: bool) -> Found {
        let n = n.min(1 << 16);
        Found {
            contacts: scratch::with_capacity(n / 4 + 16),
            overlapping: scratch::with_capacity(n / 8 + 8),
            same: if exact {
                Scratch::default()
            } else {
                scratch::with_capacity(n / 2 + 16)
            },
            copies: Vec::new(),
        }
    }

    /// Test segments `s` = number `i` < `j` = `t` with the `ends` (by their vertices where
    /// those are exact, else by their points).
    #[inline]
    fn test_with(&mut self, s: Segment2, t: Segment2, i: u32, j: u32, ends: &Ends, bound: f64) {
        if ends.exact {
            let (ei, ej) = (ends.of[i as usize], ends.of[j as usize]);
            self.test_by_vertices(s, t, i, j, ei, ej, bound)
        } else {
            self.test_by_points(s, t, i, j, bound)
        }
    }

    /// Test segments `s` = number `i` < `j` = `t`, with end vertices `ei` and `ej` (exact
    /// [`Ends`]: equal points are equal vertices), exactly and record the cuts they
    /// give. `bound` is the [`static_orient_bound`] of the input.
    #[allow(clippy::too_many_arguments)]
    fn test_by_vertices(
        &mut self,
        s: Segment2,
        t: Segment2,
        i: u32,
        j: u32,
        ei: [u32; 2],
        ej: [u32; 2],
        bound: f64,
    ) {
        // Shared ends, by vertex number.
        let (aa, ab, ba, bb) = (
            ei[0] == ej[0],
            ei[0] == ej[1],
            ei[1] == ej[0],
            ei[1] == ej[1],
        );
        if (aa & bb) | (ab & ba) {
            // The same segment twice (an edge two rings share, common in maps): an
            // overlap whose ends are ends of both, so it cuts neither.
            return self.overlapping.push((i, j));
        }
        let shared = if aa {
            Some((s.a, s.b, t.b))
        } else if ab {
            Some((s.a, s.b, t.a))
        } else if ba {
            Some((s.b, s.a, t.b))
        } else if bb {
            Some((s.b, s.a, t.a))
        } else {
            None
        };
        self.test_rest((s, i, ei), (t, j, ej), shared, bound);
    }

    /// [`Found::test_by_vertices`] for ends numbered by segment (vertices `2k`, `2k + 1`,
    /// not exact: see [`Ends`]): equal ends are found by comparing points and recorded
    /// but for the joined ones.
    fn test_by_points(&mut self, s: Segment2, t: Segment2, i: u32, j: u32, bound: f64) {
        // Consecutive ring edges (the common pair): joined at s.b = t.a without a record,
        // and meeting only there unless collinear (then s.a ≠ t.b too).
        if j == i + 1 && s.b == t.a && orient_static(s.a, s.b, t.b, bound) != 0 {
            return;
        }
        let mut shared = None;
        let mut ends_shared = 0;
        for (x, p, far_s) in [(0, s.a, s.b), (1, s.b, s.a)] {
            for (y, q, far_t) in [(0, t.a, t.b), (1, t.b, t.a)] {
                if p == q {
                    // The end of segment i = the start of i + 1 is joined anyway.
                    if !(j == i + 1 && x == 1 && y == 0) {
                        self.same.push((2 * i + x, 2 * j + y));
                    }
                    shared = Some((p, far_s, far_t));
                    ends_shared += 1;
                }
            }
        }
        if ends_shared == 2 {
            // The same segment twice (an edge two rings share, common in maps): an
            // overlap whose ends are ends of both, so it cuts neither.
            return self.overlapping.push((i, j));
        }
        let (ei, ej) = ([2 * i, 2 * i + 1], [2 * j, 2 * j + 1]);
        self.test_rest((s, i, ei), (t, j, ej), shared, bound);
    }

    /// The rest of a pair test once the shared ends are known: `shared` is `(p, far_s,
    /// far_t)` for an end `p` of both (the other ends `far_s` of `s` and `far_t` of `t`).
    /// Not collinear, the two meet only at `p`; else, and for pairs sharing no end, the
    /// filtered crossing test, then the exact intersection, whose cuts are recorded.
    #[inline(always)]
    fn test_rest(
        &mut self,
        (s, i, ei): Seg,
        (t, j, ej): Seg,
        shared: Option<(Point2, Point2, Point2)>,
        bound: f64,
    ) {
        if let Some((p, far_s, far_t)) = shared {
            // Not collinear: the lines meet only at p, an end of both (the static filter
            // first: it decides the sign wherever it is not 0).
            if orient_static(p, far_s, far_t, bound) != 0
                || orient2d(p, far_s, far_t) != Orientation::Collinear
            {
                return;
            }
        } else {
            // Most pairs are decided by four filtered orientations.
            match quick_crossing_static(s, t, bound) {
                Some(false) => return,
                Some(true) => {
                    return self.contacts.push(Contact {
                        point: round_crossing(&Crossing { s, t }),
                        a: i,
                        b: j,
                        crossing: true,
                        end: NONE,
                    })
                }
                None => {}
            }
        }
        self.intersect((s, i, ei), (t, j, ej));
    }

    /// The exact intersection of `s` and `t` (each with its number and end vertices), its
    /// cuts recorded. Out of line: the filters before it decide most pairs.
    #[inline(never)]
    fn intersect(&mut self, (s, i, ei): Seg, (t, j, ej): Seg) {
        match crate::kernel::segment_intersection(s, t) {
            SegmentIntersection::None => {}
            SegmentIntersection::Endpoint(q) => self.touch(q, (s, i, ei), (t, j, ej)),
            SegmentIntersection::Crossing(c) => self.contacts.push(Contact {
                point: round_crossing(&c),
                a: i,
                b: j,
                crossing: true,
                end: NONE,
            }),
            SegmentIntersection::Overlap(p, q) => {
                self.touch(p, (s, i, ei), (t, j, ej));
                self.touch(q, (s, i, ei), (t, j, ej));
                self.overlapping.push((i, j));
            }
        }
    }

    /// Input point `q` lies on both segments (each with its number and end vertices): it
    /// cuts each it is not an end of.
    fn touch(&mut self, q: Point2, (s, i, ei): Seg, (t, j, ej): Seg) {
        let end_of = |s: Segment2, e: [u32; 2]| {
            if q == s.a {
                e[0]
            } else if q == s.b {
                e[1]
            } else {
                NONE
            }
        };
        let (es, et) = (end_of(s, ei), end_of(t, ej));
        let (a, b, end) = match (es == NONE, et == NONE) {
            (true, true) => (i, j, NONE),
            (true, false) => (i, NONE, et),
            (false, true) => (j, NONE, es),
            (false, false) => return,
        };
        self.contacts.push(Contact {
            point: q,
            a,
            b,
            crossing: false,
            end,
        });
    }

    /// All parts' records together, in no fixed order: the assembly's output does not
    /// depend on the order of contacts (classes are sets, roots are smallest ids, cuts
    /// are sorted), which keeps the parallel scan deterministic. Each record is copied
    /// once, into arrays of the total size (merged two by two, the larger part's records
    /// were copied again at every level, into arrays grown by doubling: at 10⁶ turned
    /// squares 2.00 M → 1.91 M page faults for the whole call).
    fn concat(mut parts: Vec<Found>) -> Found {
        if parts.len() <= 1 {
            return parts.pop().unwrap_or_default();
        }
        let total = |len: fn(&Found) -> usize| parts.iter().map(len).sum::<usize>();
        let mut all = Found {
            contacts: scratch::with_capacity(total(|f| f.contacts.len())),
            overlapping: scratch::with_capacity(total(|f| f.overlapping.len())),
            same: scratch::with_capacity(total(|f| f.same.len())),
            copies: Vec::new(),
        };
        for part in parts {
            all.contacts.extend_from_slice(&part.contacts);
            all.overlapping.extend_from_slice(&part.overlapping);
            all.same.extend_from_slice(&part.same);
        }
        all
    }
}

/// The x-interval sweep keeps at most this many x-overlapping pairs per segment (plus a
/// constant); beyond that the grid, which also separates boxes in y, is cheaper.
const SWEEP_PAIRS_PER_SEGMENT: usize = 24;

/// When one strip would look at more than this many pairs per segment, strips are tried
/// (stars look at about 5 per segment in one strip and keep it).
const STRIPS_FROM_PAIRS_PER_SEGMENT: u64 = 8;

/// The height of a strip in average box heights: lower strips pair fewer boxes that are
/// apart in y, taller ones copy fewer boxes into two strips (3 looked at the fewest
/// pairs on the GEOS-837 dissolve and the water map, about 5.7 and 4.2 per segment
/// against 23 and 96 in one strip, with a third more entries).
const STRIP_BOXES: f64 = 3.0;

/// The box tests of the sweep run in chunks of this many candidates.
const CHUNK: usize = 32;

/// Up to this many segments every pair's boxes are tested, without the sweep.
const EVERY_PAIR_UP_TO: usize = 24;

/// From this many segments on, the pair tests run on the rayon pool.
const PARALLEL_SWEEP_FROM: usize = 16_384;

/// The counts of one layout, before its entries are placed: `rows` strips, each cut into
/// `cols` x-buckets; cell `(r, c)` is number `r · cols + c`.
struct Plan {
    rows: u32,
    cols: u32,
    /// Per segment `[first strip, last strip, bucket of min x, bucket of max x]`.
    spans: Scratch<[u32; 4]>,
    /// `start[c]`: the entries in the cells before `c` (`rows · cols + 1` values).
    start: Scratch<u32>,
    entries: usize,
    /// The pairs the scan will look at (box tests).
    looked: u64,
}

impl Plan {
    /// Count the entries (a segment is an entry in every strip its box spans) and the
    /// pairs the scan would look at, without placing them; `None` beyond `max_entries`.
    /// O(n + cells).
    fn new(spans: Scratch<[u32; 4]>, rows: u32, cols: u32, max_entries: usize) -> Option<Plan> {
        let cells = rows as usize * cols as usize;
        let cols_ = cols as usize;
        let mut start = scratch::filled(cells + 1, 0u32);
        let mut entries = 0usize;
        let mut looked = 0u64;
        if rows == 1 {
            // One strip (the usual case): one entry per segment, no loop over strips.
            entries = spans.len();
            for sp in &spans {
                start[sp[2] as usize + 1] += 1;
            }
            prefix_sums(&mut start);
            for sp in &spans {
                looked += u64::from(start[sp[3] as usize + 1]);
            }
        } else {
            for &[r0, r1, c0, _] in &spans {
                entries += (r1 - r0) as usize + 1;
                if entries > max_entries {
                    return None;
                }
                for r in r0 as usize..r1 as usize + 1 {
                    start[r * cols_ + c0 as usize + 1] += 1;
                }
            }
            prefix_sums(&mut start);
            for &[r0, r1, _, c1] in &spans {
                for r in r0 as usize..r1 as usize + 1 {
                    looked += u64::from(start[r * cols_ + c1 as usize + 1]);
                }
            }
        }
        // Entry p in strip r with right bucket c1 is scanned against p + 1..end of cell
        // (r, c1): summed over the entries, Σ end − Σ (p + 1).
        let n = entries as u64;
        looked -= n * (n + 1) / 2;
        Some(Plan {
            rows,
            cols,
            spans,
            start,
            entries,
            looked,
        })
    }
}

/// Running sums in place: `v[k]` becomes `v[0] + … + v[k]`.
fn prefix_sums(v: &mut [u32]) {
    let mut sum = 0;
    for x in v {
        sum += *x;
        *x = sum;
    }
}

/// Which layouts [`XSweep::new`] may use.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Layout {
    /// One strip, or strips when one would look at many pairs and strips at fewer.
    Auto,
    /// One strip.
    One,
    /// Strips (at least 5 where the y-extent allows: tests force many).
    Strips,
}

/// The segments in sweep order: by strip, then by the bucket of the left end of their
/// boxes, then by index; a segment whose box spans several strips is an entry in each.
/// Within a strip the bucket is a monotone function of `x`, so entry `p` is a candidate
/// against the entries `p + 1..stop[p]`, the later ones of its strip whose left bucket is
/// at most the bucket of its right end: every pair whose boxes overlap meets in the strip
/// of the lower edge of their intersection, the larger of their first strips, where both
/// are entries and one is listed against the other; the pair is tested there only, so
/// once. Usually one strip (an x-interval sweep); strips when boxes share x-ranges but
/// are apart in y (columns of map tiles, long horizontal edges).
struct XSweep {
    /// `[min x, max x, min y, max y]`, in sweep order.
    boxes: Scratch<[f64; 4]>,
    segs: Scratch<Segment2>,
    ids: Scratch<u32>,
    stop: Scratch<u32>,
    /// Whether the entry is in the first strip of its segment (empty for one strip).
    lead: Scratch<bool>,
}

/// The smaller of two finite values (a plain compare: no NaN to care for).
#[inline(always)]
fn min2(a: f64, b: f64) -> f64 {
    if a < b {
        a
    } else {
        b
    }
}

/// The larger of two finite values.
#[inline(always)]
fn max2(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

/// The bounding box `[min x, max x, min y, max y]` of a segment.
#[inline(always)]
fn box_of(s: &Segment2) -> [f64; 4] {
    [
        min2(s.a.x, s.b.x),
        max2(s.a.x, s.b.x),
        min2(s.a.y, s.b.y),
        max2(s.a.y, s.b.y),
    ]
}

/// The number of strips for boxes of heights summing to `heights` over the extent `e`:
/// about [`STRIP_BOXES`] average heights each, at most one per 16 segments (so that the
/// buckets of a strip still separate boxes in x; the cap also for zero heights).
fn strips_for(e: &[f64; 4], heights: f64, n: usize) -> u32 {
    let rows = (e[3] - e[2]) / (STRIP_BOXES * heights / n as f64);
    // (`as u32` saturates: NaN and infinity give 0 or the cap.)
    (rows.min((n / 16) as f64) as u32).max(1)
}

/// `map` over `items` in order, on the rayon pool when `parallel`.
fn map_scratch<T: Sync, U: scratch::Reusable + Send>(
    items: &[T],
    parallel: bool,
    f: impl Fn(&T) -> U + Sync + Send,
) -> Scratch<U> {
    if parallel {
        Scratch::from(items.par_iter().map(f).collect::<Vec<U>>())
    } else {
        scratch::collected(items.iter().map(f))
    }
}

impl XSweep {
    /// The sweep order of the segments `sub` with extent `e` = `[min x, max x, min y,
    /// max y]` and box heights summing to `heights`, or `None` when it would look at more
    /// than `budget` pairs (long segments, or many separated in y only) or the x-extent
    /// is zero or overflows. O(n + entries + pairs looked at). With `PICK`, only the
    /// segments `sub[k]` for `k` in `pick` (ascending) are entries, numbered `k`.
    fn new<const PICK: bool>(
        sub: &[Segment2],
        pick: &[u32],
        e: &[f64; 4],
        heights: f64,
        layout: Layout,
        budget: u64,
    ) -> Option<XSweep> {
        let n = if PICK { pick.len() } else { sub.len() };
        if !(e[1] - e[0]).is_finite() || e[1] - e[0] <= 0.0 {
            return None;
        }
        let picked = || (0..n).map(|i| &sub[if PICK { pick[i] as usize } else { i }]);
        // About one bucket per segment in one strip.
        let xs = Steps::new(e[0], e[1], n as u32);
        let spans = scratch::collected(
            picked().map(|s| [0, 0, xs.of(min2(s.a.x, s.b.x)), xs.of(max2(s.a.x, s.b.x))]),
        );
        let mut plan = Plan::new(spans, 1, n as u32, usize::MAX)?;
        let many = plan.looked > STRIPS_FROM_PAIRS_PER_SEGMENT * n as u64;
        let rows = match layout {
            Layout::One => 1,
            Layout::Auto if !many => 1,
            Layout::Auto => strips_for(e, heights, n),
            Layout::Strips => strips_for(e, heights, n).max(5),
        };
        if rows > 1 && (e[3] - e[2]).is_finite() && e[3] > e[2] {
            // Buckets 2^shift times wider than in one strip (the same order, coarser),
            // about two per segment over all strips.
            let shift = (rows / 2).max(1).ilog2();
            let cols = ((n as u32 - 1) >> shift) + 1;
            let ys = Steps::new(e[2], e[3], rows);
            let spans = scratch::collected(picked().zip(plan.spans.iter()).map(|(s, sp)| {
                let (lo, hi) = (min2(s.a.y, s.b.y), max2(s.a.y, s.b.y));
                [ys.of(lo), ys.of(hi), sp[2] >> shift, sp[3] >> shift]
            }));
            // Auto takes the strips only when they copy few boxes and look at fewer pairs.
            let cap = if layout == Layout::Auto {
                2 * n
            } else {
                usize::MAX
            };
            if let Some(strips) = Plan::new(spans, rows, cols, cap) {
                if layout == Layout::Strips || strips.looked < plan.looked {
                    plan = strips;
                }
            }
        }
        (plan.looked <= budget).then(|| XSweep::placed::<PICK>(sub, pick, plan))
    }

    /// The entries of `plan`, placed by a counting sort (index order within a cell);
    /// `PICK` and `pick` as in [`XSweep::new`].
    fn placed<const PICK: bool>(sub: &[Segment2], pick: &[u32], plan: Plan) -> XSweep {
        let Plan {
            rows,
            cols,
            spans,
            mut start,
            entries,
            ..
        } = plan;
        let cols = cols as usize;
        let strips = rows > 1;
        let mut ids = scratch::filled(entries, 0u32);
        let mut stop = scratch::filled(entries, 0u32);
        let mut lead = scratch::filled(if strips { entries } else { 0 }, false);
        for (i, &[r0, r1, c0, c1]) in spans.iter().enumerate() {
            let i = if PICK { pick[i] as usize } else { i };
            if !strips {
                // One strip: one entry, no loop.
                let slot = &mut start[c0 as usize];
                ids[*slot as usize] = i as u32;
                stop[*slot as usize] = c1;
                *slot += 1;
                continue;
            }
            for r in r0 as usize..r1 as usize + 1 {
                let slot = &mut start[r * cols + c0 as usize];
                let at = *slot as usize;
                *slot += 1;
                ids[at] = i as u32;
                // For now the cell of the right end, in this strip.
                stop[at] = (r * cols + c1 as usize) as u32;
                lead[at] = r == r0 as usize;
            }
        }
        drop(spans);
        // Each `start[c]` has moved to the end of cell c.
        for s in &mut stop {
            *s = start[*s as usize];
        }
        drop(start);
        let parallel = entries >= PARALLEL_SWEEP_FROM;
        let segs = map_scratch(&ids, parallel, |&i| sub[i as usize]);
        // The boxes only in sweep order (built here, not permuted: less memory).
        let boxes = map_scratch(&ids, parallel, |&i| box_of(&sub[i as usize]));
        XSweep {
            boxes,
            segs,
            ids,
            stop,
            lead,
        }
    }

    /// The number of entries.
    fn len(&self) -> usize {
        self.ids.len()
    }

    /// Test the candidates of the entries `ps` whose boxes overlap their own; `ends` are
    /// the end vertices of the segments, `EXACT` when equal points have equal vertices.
    fn scan<const EXACT: bool>(
        &self,
        ps: std::ops::Range<usize>,
        ends: &[[u32; 2]],
        found: &mut Found,
        bound: f64,
    ) {
        // One buffer for all entries (zeroing one per entry showed in profiles).
        let mut hits = [0u32; CHUNK];
        for p in ps {
            let (s, i) = (self.segs[p], self.ids[p]);
            self.pairs_of(p, &mut hits, |q| {
                self.test_pair::<EXACT>(s, i, q, ends, found, bound)
            });
        }
    }

    /// Call `f(q)` for the entries `q` that entry `p` is tested against: the candidates
    /// whose boxes overlap its own, in order. An entry past the first strip of its
    /// segment is tested only against entries whose segments start in this strip (the
    /// pair's strip).
    #[inline(always)]
    fn pairs_of(&self, p: usize, hits: &mut [u32; CHUNK], f: impl FnMut(usize)) {
        if self.lead.is_empty() || self.lead[p] {
            self.pairs_of_by::<false>(p, hits, f);
        } else {
            self.pairs_of_by::<true>(p, hits, f);
        }
    }

    /// [`XSweep::pairs_of`], with `LEADS`: only entries that are the first of their
    /// segments.
    #[inline(always)]
    fn pairs_of_by<const LEADS: bool>(
        &self,
        p: usize,
        hits: &mut [u32; CHUNK],
        mut f: impl FnMut(usize),
    ) {
        let a = self.boxes[p];
        let end = self.stop[p] as usize;
        // The box tests first, without branches (their outcome is a coin toss for the
        // branch predictor: most of the scan's time was mispredictions), writing the
        // overlapping entries to `hits` in order; then the pair tests in that order.
        let mut from = p + 1;
        while from < end {
            let to = end.min(from + CHUNK);
            let mut k = 0;
            for (q, b) in self.boxes[from..to].iter().enumerate() {
                let mut apart = (b[0] > a[1]) | (a[0] > b[1]) | (b[2] > a[3]) | (a[2] > b[3]);
                if LEADS {
                    apart |= !self.lead[from + q];
                }
                // (k < CHUNK always; the mask lets the compiler drop the bounds check.)
                hits[k & (CHUNK - 1)] = (from + q) as u32;
                k += usize::from(!apart);
            }
            from = to;
            for &q in &hits[..k] {
                f(q as usize);
            }
        }
    }

    /// Test entry `q` against segment `s` = number `i` (their boxes overlap).
    #[inline(always)]
    fn test_pair<const EXACT: bool>(
        &self,
        s: Segment2,
        i: u32,
        q: usize,
        ends: &[[u32; 2]],
        found: &mut Found,
        bound: f64,
    ) {
        let (t, j) = (self.segs[q], self.ids[q]);
        let (s, t, i, j) = if i < j { (s, t, i, j) } else { (t, s, j, i) };
        // Consecutive ring edges (the common pair), inlined here: joined at
        // s.b = t.a, and meeting only there unless collinear.
        if j == i + 1 && s.b == t.a && orient_static(s.a, s.b, t.b, bound) != 0 {
            return;
        }
        if EXACT {
            let (ei, ej) = (ends[i as usize], ends[j as usize]);
            found.test_by_vertices(s, t, i, j, ei, ej, bound);
        } else {
            found.test_by_points(s, t, i, j, bound);
        }
    }
}

/// Which candidate pairs [`Flat::noded_by`] tests (tests force each path).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(not(test), allow(dead_code))]
pub(crate) enum Candidates {
    /// The x-interval sweep (in strips when they look at fewer pairs) unless it would
    /// look at too many pairs, else the grid.
    Auto,
    /// The x-interval sweep in one strip whatever it costs (the grid for a zero
    /// x-extent).
    Sweep,
    /// The sweep in strips (at least 5 where the y-extent is positive), whatever it costs.
    Strips,
    /// The grid (the intersection sweep when the grid would test too many pairs).
    Grid,
}

impl Flat {
    /// The arrangement of `segments` (finite, checked by the caller) by the lean noding
    /// of the module docs.
    pub(crate) fn noded(segments: &[Segment2]) -> Result<Flat> {
        Flat::noded_by(segments, Candidates::Auto)
    }

    /// [`Flat::noded`] with the candidate pairs from `how`; every choice gives the same
    /// arrangement, numbered alike.
    pub(crate) fn noded_by(segments: &[Segment2], how: Candidates) -> Result<Flat> {
        Flat::noded_then(
            segments,
            how,
            None,
            |pieces, vertices| pieces.finish_numbered(vertices, true),
            Flat::general,
        )
    }

    /// [`Flat::noded`] summed up for the winding numbers: [`Flat::summed`] (the first
    /// source of each edge and its winding changes), without sorting every source to its
    /// edge first.
    pub(crate) fn noded_summed(
        segments: &[Segment2],
        na: usize,
    ) -> Result<(Flat, Vec<(i32, i32)>)> {
        Flat::noded_then(
            segments,
            Candidates::Auto,
            None,
            |pieces, vertices| pieces.finish_summed(vertices, na),
            |segments| Flat::general(segments).map(|f| f.summed(na)),
        )
    }

    /// [`Flat::of_segments_summed`] of the segments left when those whose contributions
    /// to the winding numbers cancel are left out ([`super::cancel`]), and, when some
    /// were, the segments left and how many of them are from A. Only input of many short
    /// rings ([`short_rings`]: maps, dissolves) is looked at; its ends are hashed into
    /// vertices once, for the cancelling and the noding both, and the classes of equal
    /// segments left are the noding's copies.
    #[allow(clippy::type_complexity)]
    pub(crate) fn of_segments_summed_cancelling(
        segments: &[Segment2],
        na: usize,
    ) -> Result<(Option<(Vec<Segment2>, usize)>, Flat, Vec<(i32, i32)>)> {
        // (Horizontal and vertical segments only: their own arrangement, without a hash,
        // is cheaper than looking for shared sides first.)
        let axis_parallel = |s: &Segment2| s.a.y == s.b.y || s.a.x == s.b.x;
        let hashed = short_rings(segments)
            && segments.len() < 1 << 29
            && !segments.iter().all(axis_parallel)
            && !segments.iter().any(Segment2::is_degenerate);
        if !hashed {
            let (flat, deltas) = Flat::of_segments_summed(segments, na)?;
            return Ok((None, flat, deltas));
        }
        super::flat::check_finite(segments)?;
        let mut ends = Ends::hashed(segments);
        let (first_of, left) = super::cancel::classes(&ends.of, |k| k < na);
        // The segments left, their ends and classes (numbered as before).
        let (segs, na, classes): (Cow<[Segment2]>, usize, Vec<u32>) = match &left {
            None => (Cow::Borrowed(segments), na, first_of),
            Some(left) => {
                ends.of = left.iter().map(|&k| ends.of[k]).collect();
                (
                    Cow::Owned(left.iter().map(|&k| segments[k]).collect()),
                    left.partition_point(|&k| k < na),
                    left.iter().map(|&k| first_of[k]).collect(),
                )
            }
        };
        let (flat, deltas) = match Flat::axis_parallel(&segs) {
            Some(f) => f.summed(na),
            None => {
                let copies = Copies::of_classes(&classes, segments.len());
                Flat::noded_then(
                    &segs,
                    Candidates::Auto,
                    Some((ends, copies)),
                    |pieces, vertices| pieces.finish_summed(vertices, na),
                    |segments| Flat::general(segments).map(|f| f.summed(na)),
                )?
            }
        };
        let left = left.is_some().then(|| (segs.into_owned(), na));
        Ok((left, flat, deltas))
    }

    /// The noding of [`Flat::noded_by`], its pieces made into the result by `finish`, or
    /// `general` when the lean noding does not apply. `prepared`: the exact ends of
    /// `segments` and their copies, already found (none of them is a point).
    fn noded_then<T>(
        segments: &[Segment2],
        how: Candidates,
        prepared: Option<(Ends, Option<Copies>)>,
        finish: impl FnOnce(Pieces, Vertices) -> T,
        general: impl FnOnce(&[Segment2]) -> Result<T>,
    ) -> Result<T> {
        debug_assert!(prepared.is_none() || !segments.iter().any(Segment2::is_degenerate));
        // The segments that are not points, and their input numbers (`None`: all of
        // them, the usual case, with no copy).
        let (sub, kept): (Cow<[Segment2]>, Option<Vec<usize>>) =
            if segments.iter().any(Segment2::is_degenerate) {
                let kept: Vec<usize> = (0..segments.len())
                    .filter(|&i| !segments[i].is_degenerate())
                    .collect();
                let sub = kept.iter().map(|&i| segments[i]).collect();
                (Cow::Owned(sub), Some(kept))
            } else {
                (Cow::Borrowed(segments), None)
            };
        // Item ids below are u32: 2 per segment plus the contacts.
        if sub.len() >= 1 << 29 {
            return general(segments);
        }
        // With exact ends, an edge given more than once (neighbouring rings share their
        // common edges) is tested once: its copies take its pieces.
        let (ends, copies) = match prepared {
            Some(prepared) => prepared,
            None => {
                let ends = Ends::of(&sub);
                let copies = ends.exact.then(|| Copies::of(&ends.of)).flatten();
                (ends, copies)
            }
        };
        let found = match copies {
            Some(copies) => found_by_once(&sub, &ends, copies, how),
            None => found_by(&sub, &ends, how),
        };
        let Some(found) = found else {
            return general(segments);
        };
        let (pieces, vertices) = if ends.exact {
            assemble::<true>(&sub, kept.as_deref(), &ends, found)
        } else {
            assemble::<false>(&sub, kept.as_deref(), &ends, found)
        };
        Ok(finish(pieces, vertices))
    }
}

/// The segments with the same two end vertices as an earlier one (exact [`Ends`]):
/// `first` the segments that are the first with their pair of vertices, in order;
/// `copy_of[k]` the first segment with the pair of `k` when `k` is a copy (or `NONE`).
struct Copies {
    first: Vec<u32>,
    copy_of: Vec<u32>,
}

impl Copies {
    /// The copies among the segments with end vertices `of`, or `None` when there are
    /// none. An open-addressing hash of the vertex pairs, O(n) expected.
    fn of(of: &[[u32; 2]]) -> Option<Copies> {
        let n = of.len();
        let bits = (2 * n).max(16).next_power_of_two().trailing_zeros();
        let mask = (1usize << bits) - 1;
        // Per slot the first segment with that pair (its key read from `of`).
        let mut slots = vec![NONE; 1 << bits];
        let key = |e: [u32; 2]| {
            let (u, v) = if e[0] < e[1] {
                (e[0], e[1])
            } else {
                (e[1], e[0])
            };
            u64::from(u) << 32 | u64::from(v)
        };
        let mut copy_of = vec![NONE; n];
        let mut first = Vec::with_capacity(n);
        for (k, &e) in of.iter().enumerate() {
            let want = key(e);
            let mut at = (want.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> (64 - bits)) as usize;
            loop {
                let f = slots[at];
                if f == NONE {
                    slots[at] = k as u32;
                    first.push(k as u32);
                    break;
                }
                if key(of[f as usize]) == want {
                    copy_of[k] = f;
                    break;
                }
                at = (at + 1) & mask;
            }
        }
        (first.len() < n).then_some(Copies { first, copy_of })
    }

    /// The copies among segments of the given classes (`classes[k]` below `bound`, equal
    /// for segments with the same two end vertices): [`Copies::of`] from classes already
    /// found, without a hash.
    fn of_classes(classes: &[u32], bound: usize) -> Option<Copies> {
        let n = classes.len();
        let mut first_in = vec![NONE; bound];
        let mut copy_of = vec![NONE; n];
        let mut first = Vec::with_capacity(n);
        for (k, &c) in classes.iter().enumerate() {
            let slot = &mut first_in[c as usize];
            if *slot == NONE {
                *slot = k as u32;
                first.push(k as u32);
            } else {
                copy_of[k] = *slot;
            }
        }
        (first.len() < n).then_some(Copies { first, copy_of })
    }
}

/// [`found_by`] testing only the first segment with each pair of end vertices (exact
/// `ends`): the records of the others are those of their first, which is the same
/// segment up to direction. The found records are numbered by `sub`; the copies are
/// listed in [`Found::copies`], so that the assembly gives them their first's pieces
/// (the same edges, cut at the same points). A pair with a copy gives the contacts at
/// the same points as with its first, and the first (the smaller number) is the one the
/// representative of a class of crossings would be chosen from: the arrangement is the
/// one of testing every pair, numbered alike.
fn found_by_once(sub: &[Segment2], ends: &Ends, copies: Copies, how: Candidates) -> Option<Found> {
    // (The firsts keep their numbers in `sub`: no copy of them, no renumbering after.)
    let mut found = found_by_picked::<true>(sub, &copies.first, ends, how)?;
    found.copies = copies.copy_of;
    Some(found)
}

/// The contacts, overlaps and equal ends of the pairs of `sub` (at most 2^29 segments)
/// from the candidates of `how`; `None` when the grid would test too many pairs or the
/// item ids would not fit in `u32` (the intersection sweep then does it all).
fn found_by(sub: &[Segment2], ends: &Ends, how: Candidates) -> Option<Found> {
    found_by_picked::<false>(sub, &[], ends, how)
}

/// [`found_by`] of the segments `sub[k]` for `k` in `pick` (ascending) when `PICK`, with
/// the records numbered by `sub`.
fn found_by_picked<const PICK: bool>(
    sub: &[Segment2],
    pick: &[u32],
    ends: &Ends,
    how: Candidates,
) -> Option<Found> {
    let n = if PICK { pick.len() } else { sub.len() };
    let picked = || (0..n).map(|i| &sub[if PICK { pick[i] as usize } else { i }]);
    let inf = f64::INFINITY;
    let mut heights = 0.0;
    let e = picked().fold([inf, -inf, inf, -inf], |e, s| {
        let b = box_of(s);
        heights += b[3] - b[2];
        [
            min2(e[0], b[0]),
            max2(e[1], b[1]),
            min2(e[2], b[2]),
            max2(e[3], b[3]),
        ]
    });
    // The largest coordinate magnitude (-inf for no segments: an infinite bound).
    let m = max2(max2(-e[0], e[1]), max2(-e[2], e[3]));
    let bound = static_orient_bound(m);
    if n <= EVERY_PAIR_UP_TO && how == Candidates::Auto {
        // Few segments (small polygons): every pair's boxes, cheaper than building the
        // sweep (two squares: 38.4 k instructions a boolean call before, 35.6 k after).
        let mut boxes = [[0.0; 4]; EVERY_PAIR_UP_TO];
        for (b, s) in boxes.iter_mut().zip(picked()) {
            *b = box_of(s);
        }
        let boxes = &boxes[..n];
        let mut f = Found::for_segments(n, ends.exact);
        for (p, a) in boxes.iter().enumerate() {
            for (q, b) in boxes.iter().enumerate().skip(p + 1) {
                if (b[0] > a[1]) | (a[0] > b[1]) | (b[2] > a[3]) | (a[2] > b[3]) {
                    continue;
                }
                // (`pick` ascends: i < j, as the tests want.)
                let (i, j) = if PICK {
                    (pick[p] as usize, pick[q] as usize)
                } else {
                    (p, q)
                };
                f.test_with(sub[i], sub[j], i as u32, j as u32, ends, bound);
            }
        }
        return Some(f);
    }
    let budget = (SWEEP_PAIRS_PER_SEGMENT * n + 1024) as u64;
    let new = |layout, budget| XSweep::new::<PICK>(sub, pick, &e, heights, layout, budget);
    let sweep = match how {
        Candidates::Auto => new(Layout::Auto, budget),
        Candidates::Sweep => new(Layout::One, u64::MAX),
        Candidates::Strips => new(Layout::Strips, u64::MAX),
        Candidates::Grid => None,
    };
    let found = if let Some(sweep) = sweep {
        let n = sweep.len();
        if n < PARALLEL_SWEEP_FROM {
            let mut f = Found::for_segments(n, ends.exact);
            if ends.exact {
                sweep.scan::<true>(0..n, &ends.of, &mut f, bound);
            } else {
                sweep.scan::<false>(0..n, &ends.of, &mut f, bound);
            }
            f
        } else {
            // Blocks of entries on the pool (the result does not depend on the split:
            // the assembly sorts what it needs).
            const BLOCK: usize = 2048;
            let parts: Vec<Found> = (0..n.div_ceil(BLOCK))
                .into_par_iter()
                .fold(Found::default, |mut f, k| {
                    let ps = k * BLOCK..n.min((k + 1) * BLOCK);
                    if ends.exact {
                        sweep.scan::<true>(ps, &ends.of, &mut f, bound);
                    } else {
                        sweep.scan::<false>(ps, &ends.of, &mut f, bound);
                    }
                    f
                })
                .collect();
            Found::concat(parts)
        }
    } else {
        // (The grid numbers the segments it is given: the picked ones in a copy.)
        let once: Cow<[Segment2]> = if PICK {
            Cow::Owned(picked().copied().collect())
        } else {
            Cow::Borrowed(sub)
        };
        let grid = prefer_pairwise(&once)?;
        let num = |i: usize| if PICK { pick[i] as usize } else { i };
        let test = |f: &mut Found, i: usize, j: usize| {
            f.test_with(once[i], once[j], num(i) as u32, num(j) as u32, ends, bound)
        };
        let entries = grid.entry_count();
        if grid.candidates() < PARALLEL_SCAN_FROM {
            let mut f = Found::for_segments(sub.len(), ends.exact);
            for k in 0..entries {
                grid.scan_from(k, |i, j| test(&mut f, i, j));
            }
            f
        } else {
            let parts: Vec<Found> = (0..entries)
                .into_par_iter()
                .fold(Found::default, |mut f, k| {
                    grid.scan_from(k, |i, j| test(&mut f, i, j));
                    f
                })
                .collect();
            Found::concat(parts)
        }
    };
    (found.contacts.len() < (1 << 31) - 2 * sub.len()).then_some(found)
}

#[inline]
fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let up = parent[parent[x as usize] as usize];
        parent[x as usize] = up;
        x = up;
    }
    x
}

fn union(parent: &mut [u32], a: u32, b: u32) {
    let (ra, rb) = (find(parent, a), find(parent, b));
    // The smaller id stays the root (deterministic classes and numbering).
    if ra < rb {
        parent[rb as usize] = ra;
    } else if rb < ra {
        parent[ra as usize] = rb;
    }
}

/// Vertices, cuts and pieces from the scan's findings (steps 2 and 3 of the module docs).
///
/// Work over all segments is a few plain passes; everything that depends on the contacts
/// (exact points, cut order, representatives) is O(K log K) for K contacts. Vertices are
/// numbered in order of first use by the edges, as they are made.
/// `EXACT`: `ends.exact`. The pieces come with their sources pushed segment by segment
/// (ascending within each edge), the vertices numbered in order of first use.
fn assemble<const EXACT: bool>(
    sub: &[Segment2],
    kept: Option<&[usize]>,
    ends: &Ends,
    found: Found,
) -> (Pieces, Vertices) {
    // The input number of segment k of `sub`.
    let input = |k: usize| kept.map_or(k, |kept| kept[k]);
    let m = sub.len();
    let contacts = &found.contacts;
    let k_count = contacts.len();
    // Items: v < nv is input vertex v; nv + c is contact c. A union keeps the smaller id
    // as the root, so a root is the smallest item of its class: its input vertex when it
    // has one. A contact at an input point starts in that vertex's class.
    let nv = ends.count;
    let total = nv + k_count;
    let mut parent: Scratch<u32> = scratch::with_capacity(total);
    if EXACT {
        parent.extend(0..nv as u32);
    } else {
        for k in 0..m {
            let joined = k > 0 && sub[k - 1].b == sub[k].a;
            parent.push(if joined {
                2 * k as u32 - 1
            } else {
                2 * k as u32
            });
            parent.push(2 * k as u32 + 1);
        }
    }
    parent.extend(
        contacts
            .iter()
            .enumerate()
            .map(|(c, contact)| match contact.end {
                NONE => (nv + c) as u32,
                v => v,
            }),
    );
    for &(u, v) in &found.same {
        union(&mut parent, u, v);
    }
    // The exact contact points.
    let exact: Scratch<ExactPoint> = scratch::collected(contacts.iter().map(|c| {
        if c.crossing {
            ExactPoint::Crossing(Crossing {
                s: sub[c.a as usize],
                t: sub[c.b as usize],
            })
        } else {
            ExactPoint::Input(c.point)
        }
    }));
    let rounded: Scratch<Rounded> = scratch::collected(
        exact
            .iter()
            .zip(contacts.iter())
            .map(|(e, c)| Rounded::of(e, c.point)),
    );
    // The cuts (segment << 32 | contact), grouped by segment.
    let mut cuts: Scratch<u64> = scratch::with_capacity(2 * k_count);
    for (c, contact) in contacts.iter().enumerate() {
        for s in [contact.a, contact.b] {
            if s != NONE {
                // (Copies are not cut: they take their first's pieces.)
                cuts.push(u64::from(s) << 32 | c as u64);
            }
        }
    }
    cuts.sort_unstable();
    // Along each segment from a: lexicographic order, reversed when a is the larger end;
    // equal neighbours are one point.
    let mut from = 0;
    while from < cuts.len() {
        let k = (cuts[from] >> 32) as usize;
        let to = from + cuts[from..].partition_point(|&u| (u >> 32) as usize == k);
        let run = &mut cuts[from..to];
        from = to;
        if run.len() < 2 {
            continue;
        }
        let s = sub[k];
        let a_low = compare_xy(s.a, s.b) == Ordering::Less;
        let cmp = |u: u64, v: u64| {
            let (u, v) = (u as u32 as usize, v as u32 as usize);
            compare_xy_filtered(&exact[u], &rounded[u], &exact[v], &rounded[v])
        };
        run.sort_unstable_by(|&u, &v| if a_low { cmp(u, v) } else { cmp(v, u) });
        for w in 1..run.len() {
            if cmp(run[w - 1], run[w]) == Ordering::Equal {
                union(
                    &mut parent,
                    nv as u32 + run[w - 1] as u32,
                    nv as u32 + run[w] as u32,
                );
            }
        }
    }
    // The representative of each class: an input point where the class has one (its
    // root, when an end: ends come first in id order), else the crossing of the smallest
    // pair. Only classes of contacts alone need a look at their members, and those are all
    // crossings (a contact at an input point is joined to that end), so the choice does
    // not depend on the contacts' order.
    let is_crossing = |c: u32| contacts[c as usize].crossing;
    let pair = |c: u32| (contacts[c as usize].a, contacts[c as usize].b);
    let mut rep = scratch::filled(k_count, NONE);
    for c in 0..k_count as u32 {
        let r = find(&mut parent, nv as u32 + c) as usize;
        if r < nv {
            continue;
        }
        let slot = &mut rep[r - nv];
        if *slot == NONE || (is_crossing(*slot) && (!is_crossing(c) || pair(c) < pair(*slot))) {
            *slot = c;
        }
    }
    // (With its nearest f64 point: the contact's, rounded when it was found.)
    let point_of = |r: usize| {
        if r < nv {
            let q = if EXACT {
                ends.points[r]
            } else if r % 2 == 0 {
                sub[r / 2].a
            } else {
                sub[r / 2].b
            };
            (ExactPoint::Input(q), q)
        } else {
            let c = rep[r - nv] as usize;
            (exact[c], contacts[c].point)
        }
    };
    let mut shared = scratch::filled(m, false);
    for &(i, j) in &found.overlapping {
        shared[i as usize] = true;
        shared[j as usize] = true;
    }
    // The pieces, segment by segment; a class gets its vertex at its first use.
    let mut vertex_of = scratch::filled(total, NONE);
    // (With their nearest f64 points, handed to the tracer, which would round them
    // again.)
    let mut vertices = ExactVertices::with_capacity(m + k_count, k_count);
    let mut vertex = |item: u32, parent: &mut [u32]| {
        let r = find(parent, item) as usize;
        if vertex_of[r] == NONE {
            vertex_of[r] = vertices.len() as u32;
            let (p, a) = point_of(r);
            vertices.push(p, a);
        }
        vertex_of[r]
    };
    // Keyed by vertex pair; a multiply–rotate hash (SipHash was most of the merge).
    // (Sized once: growing it was the most frequent allocation of small calls.)
    let mut merged = EdgeMap::with_capacity_and_hasher(m + cuts.len(), Default::default());
    let mut pieces = Pieces {
        edges: Vec::with_capacity(m + cuts.len()),
        pairs: Vec::with_capacity(m + cuts.len()),
    };
    let mut chain: Scratch<u32> = scratch::with_capacity(16);
    let mut next_cut = 0;
    let mut prev_end = NONE;
    // With copies: where each segment's pairs start in `pieces.pairs` (one per piece).
    let copy_of = &found.copies;
    let mut piece_from: Scratch<u32> =
        scratch::with_capacity(if copy_of.is_empty() { 0 } else { m });
    for k in 0..m {
        if EXACT && !copy_of.is_empty() {
            piece_from.push(pieces.pairs.len() as u32);
            let f = copy_of[k] as usize;
            if f != NONE as usize {
                // A copy of segment f < k (the same two end vertices, so the same
                // pieces: its cuts are f's): f's edges, the same way or reversed.
                let same = ends.of[k] == ends.of[f];
                let (p0, p1) = (piece_from[f] as usize, piece_from[f + 1] as usize);
                for p in p0..p1 {
                    let forward = pieces.pairs[p].1.forward == same;
                    let e = pieces.pairs[p].0;
                    pieces.pairs.push((
                        e,
                        Source {
                            segment: input(k),
                            forward,
                        },
                    ));
                }
                // Its end: f's end (the head of f's last piece along f) or f's start.
                let (e, src) = pieces.pairs[if same { p1 - 1 } else { p0 }];
                let [u, v] = pieces.edges[e as usize];
                prev_end = if src.forward == same { v } else { u };
                continue;
            }
        }
        chain.clear();
        let [a, b] = if EXACT {
            ends.of[k]
        } else {
            [2 * k as u32, 2 * k as u32 + 1]
        };
        // The start of a segment joined to the end of the one before is that vertex (with
        // exact ends: the same input vertex, as at every step along a ring).
        let joined = k > 0
            && if EXACT {
                ends.of[k - 1][1] == a
            } else {
                sub[k - 1].b == sub[k].a
            };
        chain.push(if joined {
            prev_end
        } else {
            vertex(a, &mut parent)
        });
        while next_cut < cuts.len() && (cuts[next_cut] >> 32) as usize == k {
            // The same point may cut a segment for several pairs.
            let v = vertex(nv as u32 + cuts[next_cut] as u32, &mut parent);
            next_cut += 1;
            if chain.last() != Some(&v) {
                chain.push(v);
            }
        }
        prev_end = vertex(b, &mut parent);
        chain.push(prev_end);
        for w in chain.windows(2) {
            let (u, v) = (w[0], w[1]);
            if !shared[k] {
                pieces.pairs.push((
                    pieces.edges.len() as u32,
                    Source {
                        segment: input(k),
                        forward: true,
                    },
                ));
                pieces.edges.push([u, v]);
                continue;
            }
            let e = *merged.entry((u.min(v), u.max(v))).or_insert_with(|| {
                pieces.edges.push([u, v]);
                pieces.edges.len() as u32 - 1
            });
            let forward = pieces.edges[e as usize][0] == u;
            pieces.pairs.push((
                e,
                Source {
                    segment: input(k),
                    forward,
                },
            ));
        }
    }
    (pieces, vertices.into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dcel::flat::canonical;

    /// A closed ring of `n` vertices at sorted pseudo-random angles around `(cx, 0)`, radius
    /// `0.8 + 0.15 sin 5θ` plus noise of the order of the spacing (the bench's stars), its
    /// coordinates rounded to multiples of `1 / 2^grid` (coarse grids: repeated vertices,
    /// collinear runs, edges shared between the two rings).
    fn star(n: usize, cx: f64, seed: u64, grid: i32) -> Vec<Segment2> {
        let mut unit = crate::testing::units(seed);
        let mut angles: Vec<f64> = (0..n).map(|_| std::f64::consts::TAU * unit()).collect();
        angles.sort_by(f64::total_cmp);
        let snap = |v: f64| (v * 2f64.powi(grid)).round() / 2f64.powi(grid);
        let pts: Vec<Point2> = angles
            .iter()
            .map(|&a| {
                let r = 0.8 + 0.15 * (5.0 * a).sin() + 2.0 / n as f64 * unit();
                Point2::new(snap(cx + r * a.cos()), snap(r * a.sin()))
            })
            .collect();
        (0..n)
            .map(|k| Segment2::new(pts[k], pts[(k + 1) % n]))
            .collect()
    }

    /// Above [`PARALLEL_SWEEP_FROM`] segments the sweep's pairs are tested on the rayon
    /// pool: the arrangement is the grid path's, numbered alike, and the intersection
    /// sweep's; on floats and on grids coarse enough for shared edges and overlaps.
    #[test]
    fn parallel_sweep_agrees_with_the_grid_and_the_sweep() {
        for grid in [60, 9] {
            let mut segs = star(9000, 0.0, 7, grid);
            segs.extend(star(9000, 0.3, 8, grid));
            // A copy of part of the first ring, reversed: collinear overlaps everywhere.
            let copy: Vec<Segment2> = segs[..500]
                .iter()
                .map(|s| Segment2::new(s.b, s.a))
                .collect();
            segs.extend(copy);
            assert!(segs.len() >= PARALLEL_SWEEP_FROM);
            let sweep = Flat::noded_by(&segs, Candidates::Sweep).unwrap();
            assert_eq!(sweep, Flat::noded_by(&segs, Candidates::Grid).unwrap());
            assert_eq!(sweep, Flat::noded_by(&segs, Candidates::Strips).unwrap());
            assert_eq!(sweep, Flat::noded(&segs).unwrap());
            assert_eq!(canonical(&sweep), canonical(&Flat::general(&segs).unwrap()));
        }
    }

    /// Up to [`EVERY_PAIR_UP_TO`] segments every pair's boxes are tested, without the
    /// sweep: the same arrangement, numbered alike, as the sweep's, the strips' and the
    /// grid's, and the intersection sweep's, on two small rings on grids from halves
    /// (repeated vertices, shared edges either way round, collinear overlaps,
    /// T-junctions) to floats (crossings), with a ring's copy reversed now and then.
    #[test]
    fn every_pair_agrees_with_the_sweep_and_the_grid() {
        for seed in 0..600u64 {
            let grid = [1, 2, 3, 40][seed as usize % 4];
            let n = 3 + seed as usize % 10;
            let mut segs = star(n, 0.0, seed, grid);
            segs.extend(star(n + seed as usize % 3, 0.3, seed + 1000, grid));
            if seed % 5 == 0 {
                let copy: Vec<Segment2> =
                    segs[..n].iter().map(|s| Segment2::new(s.b, s.a)).collect();
                segs.extend(copy);
            }
            segs.retain(|s| s.a != s.b);
            segs.truncate(EVERY_PAIR_UP_TO);
            let auto = Flat::noded(&segs).unwrap();
            assert_eq!(
                auto,
                Flat::noded_by(&segs, Candidates::Sweep).unwrap(),
                "seed {seed}"
            );
            assert_eq!(
                auto,
                Flat::noded_by(&segs, Candidates::Strips).unwrap(),
                "seed {seed}"
            );
            assert_eq!(
                auto,
                Flat::noded_by(&segs, Candidates::Grid).unwrap(),
                "seed {seed}"
            );
            assert_eq!(
                canonical(&auto),
                canonical(&Flat::general(&segs).unwrap()),
                "seed {seed}"
            );
            for exact in [true, false] {
                assert_eq!(
                    canonical(&noded_with_ends(&segs, exact)),
                    canonical(&auto),
                    "seed {seed}"
                );
            }
        }
    }

    /// The arrangement of `segs` (no points among them) with the ends hashed into exact
    /// vertices or numbered by segment.
    fn noded_with_ends(segs: &[Segment2], exact: bool) -> Flat {
        let ends = if exact {
            Ends::hashed(segs)
        } else {
            Ends::by_segments(segs.len())
        };
        let found = found_by(segs, &ends, Candidates::Auto).unwrap();
        let (pieces, vertices) = if exact {
            assemble::<true>(segs, None, &ends, found)
        } else {
            assemble::<false>(segs, None, &ends, found)
        };
        pieces.finish_numbered(vertices, true)
    }

    /// Small rings on a coarse grid, many meeting at their vertices and sharing edges
    /// (either way round), with collinear overlaps, T-junctions and crossings: the
    /// hashed ends and the ends numbered by segment give the same arrangement, numbered
    /// alike, and the intersection sweep's; `Ends::of` hashes such input and not the
    /// stars.
    #[test]
    fn hashed_ends_agree_with_ends_by_segment() {
        let mut next = crate::testing::below(99u64);
        for grid in [3u64, 6, 12] {
            let mut segs = Vec::new();
            for _ in 0..150 {
                let k = 3 + next(3) as usize;
                let (cx, cy) = (next(grid) as f64, next(grid) as f64);
                let ring: Vec<Point2> = (0..k)
                    .map(|_| Point2::new(cx + next(3) as f64, cy + next(3) as f64))
                    .collect();
                for w in 0..k {
                    let s = Segment2::new(ring[w], ring[(w + 1) % k]);
                    if !s.is_degenerate() {
                        segs.push(s);
                    }
                }
            }
            // Collinear overlaps from a shared end, for each pair of ends (a·a, a·b,
            // b·a, b·b), apart from the rings and from each other.
            let mut at = 40.0;
            for (u, v, w) in [
                ((5., 5.), (3., 3.), (4., 4.)),
                ((5., 0.), (7., 0.), (6., 0.)),
            ] {
                for (first, second) in [(false, false), (false, true), (true, false), (true, true)]
                {
                    let p = |q: (f64, f64)| Point2::new(q.0 + at, q.1);
                    let (u, v, w) = (p(u), p(v), p(w));
                    let long = if first {
                        Segment2::new(v, u)
                    } else {
                        Segment2::new(u, v)
                    };
                    let short = if second {
                        Segment2::new(w, u)
                    } else {
                        Segment2::new(u, w)
                    };
                    segs.extend([long, short]);
                    at += 10.0;
                }
            }
            // -0 and 0 are one point.
            segs.push(Segment2::new(Point2::new(-0.0, 0.0), Point2::new(2.0, 1.0)));
            segs.push(Segment2::new(Point2::new(2.0, 1.0), Point2::new(0.0, -0.0)));
            assert!(Ends::of(&segs).exact);
            let hashed = noded_with_ends(&segs, true);
            assert_eq!(hashed, noded_with_ends(&segs, false));
            assert_eq!(hashed, Flat::noded(&segs).unwrap());
            assert_eq!(
                canonical(&hashed),
                canonical(&Flat::general(&segs).unwrap())
            );
        }
        assert!(!Ends::of(&star(500, 0.0, 3, 9)).exact);
    }

    /// -0 and 0 are one coordinate: rings around the origin with zeros of either sign
    /// give the arrangement of the same rings with +0 only (the cuts along a segment
    /// were once sorted with -0 before 0 where both rounded points were exact: an
    /// inconsistent order, cuts out of place, and sometimes a panic in the sort).
    #[test]
    fn negative_zeros_are_zeros() {
        let mut next = crate::testing::below(0x5eed);
        for round in 0..300 {
            let mut signed = Vec::new();
            for _ in 0..2 + next(12) {
                let k = 3 + next(3) as usize;
                let ring: Vec<Point2> = (0..k)
                    .map(|_| {
                        let c = |v: u64| v as f64 * 0.5 - 1.0;
                        Point2::new(c(next(5)), c(next(5)))
                    })
                    .collect();
                for w in 0..k {
                    let s = Segment2::new(ring[w], ring[(w + 1) % k]);
                    if !s.is_degenerate() {
                        signed.push(s);
                    }
                }
            }
            let plus = signed.clone();
            for s in &mut signed {
                for p in [&mut s.a, &mut s.b] {
                    for v in [&mut p.x, &mut p.y] {
                        if *v == 0.0 && next(2) == 0 {
                            *v = -0.0;
                        }
                    }
                }
            }
            let (got, want) = (Flat::noded(&signed).unwrap(), Flat::noded(&plus).unwrap());
            assert_eq!(got.edges.len(), want.edges.len(), "round {round}");
            assert_eq!(got.vertices.len(), want.vertices.len(), "round {round}");
            let general = Flat::general(&signed).unwrap();
            assert_eq!(canonical(&got), canonical(&general), "round {round}");
        }
    }

    #[test]
    fn cancelling_then_noding_is_the_noding_of_what_is_left() {
        let mut next = crate::testing::below(7u64);
        let mut cancelled = 0;
        for round in 0..60 {
            let grid = [3u64, 6, 12][round % 3];
            let mut segs = Vec::new();
            for _ in 0..40 + next(80) {
                let k = 3 + next(3) as usize;
                let (cx, cy) = (next(grid) as f64, next(grid) as f64);
                let ring: Vec<Point2> = (0..k)
                    .map(|_| Point2::new(cx + next(3) as f64, cy + next(3) as f64 * 0.5))
                    .collect();
                for w in 0..k {
                    let s = Segment2::new(ring[w], ring[(w + 1) % k]);
                    if !s.is_degenerate() {
                        segs.push(s);
                    }
                }
                // Shared sides: some run back, some again the same way.
                if next(2) == 0 && segs.len() > 1 {
                    let s = segs[next(segs.len() as u64) as usize];
                    segs.push(if next(3) == 0 {
                        s
                    } else {
                        Segment2::new(s.b, s.a)
                    });
                }
            }
            // (-0 and 0 are one point.)
            segs.push(Segment2::new(Point2::new(-0.0, 0.0), Point2::new(2.0, 1.0)));
            segs.push(Segment2::new(Point2::new(2.0, 1.0), Point2::new(0.0, -0.0)));
            let na = next(segs.len() as u64 + 1) as usize;
            assert!(short_rings(&segs));
            let (left, flat, deltas) = Flat::of_segments_summed_cancelling(&segs, na).unwrap();
            let (kept, kept_na) = left.clone().unwrap_or((segs.clone(), na));
            if left.is_some() {
                cancelled += segs.len() - kept.len();
            }
            // What is left is what the cancelling of equal points leaves.
            let ends = Ends::hashed(&segs);
            let (first_of, by_classes) = super::super::cancel::classes(&ends.of, |k| k < na);
            let listed: Vec<Segment2> = by_classes
                .as_ref()
                .map_or(segs.clone(), |l| l.iter().map(|&k| segs[k]).collect());
            assert_eq!(kept, listed, "round {round}");
            // The same arrangement as noding it from scratch.
            assert_eq!(
                (flat, deltas),
                Flat::of_segments_summed(&kept, kept_na).unwrap(),
                "round {round}"
            );
            // The classes' copies are the hash's.
            let copies = |c: Option<Copies>| c.map(|c| (c.first, c.copy_of));
            assert_eq!(
                copies(Copies::of_classes(&first_of, segs.len())),
                copies(Copies::of(&ends.of)),
                "round {round}"
            );
        }
        assert!(cancelled > 200, "only {cancelled} segments cancelled");
    }

    fn sweep_of(segs: &[Segment2], layout: Layout, budget: u64) -> Option<XSweep> {
        let inf = f64::INFINITY;
        let e = segs
            .iter()
            .map(box_of)
            .fold([inf, -inf, inf, -inf], |e, b| {
                [
                    e[0].min(b[0]),
                    e[1].max(b[1]),
                    e[2].min(b[2]),
                    e[3].max(b[3]),
                ]
            });
        let heights = segs.iter().map(|s| box_of(s)[3] - box_of(s)[2]).sum();
        XSweep::new::<false>(segs, &[], &e, heights, layout, budget)
    }

    /// Long segments spanning the x-extent make the sweep look at Θ(n²) pairs: the budget
    /// sends them to the grid, with the same answer.
    #[test]
    fn long_segments_leave_the_sweep() {
        let segs: Vec<Segment2> = (0..400)
            .map(|i| {
                let y = (i * 7919 % 401) as f64 / 401.0;
                Segment2::new(Point2::new(0.0, y), Point2::new(1.0, 1.0 - y))
            })
            .collect();
        let budget = SWEEP_PAIRS_PER_SEGMENT * segs.len() + 1024;
        assert!(sweep_of(&segs, Layout::Auto, budget as u64).is_none());
        assert!(sweep_of(&segs, Layout::One, u64::MAX).is_some());
        let auto = Flat::noded(&segs).unwrap();
        assert_eq!(auto, Flat::noded_by(&segs, Candidates::Sweep).unwrap());
        assert_eq!(canonical(&auto), canonical(&Flat::general(&segs).unwrap()));
        // All on one vertical line (zero x-extent): no sweep, the same arrangement.
        let column: Vec<Segment2> = (0..50)
            .map(|i| Segment2::new(Point2::new(2.0, i as f64), Point2::new(2.0, i as f64 + 1.5)))
            .collect();
        assert!(sweep_of(&column, Layout::One, u64::MAX).is_none());
        assert_eq!(
            canonical(&Flat::noded(&column).unwrap()),
            canonical(&Flat::general(&column).unwrap())
        );
    }

    /// The pairs the sweep tests, by segment index (smaller first), in test order.
    fn tested(sweep: &XSweep) -> Vec<(u32, u32)> {
        let mut out = Vec::new();
        let mut hits = [0u32; CHUNK];
        for p in 0..sweep.len() {
            sweep.pairs_of(p, &mut hits, |q| {
                let (i, j) = (sweep.ids[p], sweep.ids[q]);
                out.push((i.min(j), i.max(j)));
            });
        }
        out
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(200))]

        /// In one strip and in strips, the sweep tests exactly the pairs of distinct
        /// segments whose boxes overlap, each once: on a small integer grid (boxes
        /// touching at strip and bucket edges, horizontal and vertical segments,
        /// duplicates) and on long and short random segments.
        #[test]
        fn the_sweep_tests_each_overlapping_pair_once(
            v in proptest::collection::vec((0..9i32, 0..9i32, 0..9i32, 0..9i32), 1..40),
            scale in proptest::sample::select(vec![1.0, 0.37, 1e-300, 1e300]),
            long in 0..3usize,
        ) {
            let p = |x: i32, y: i32| Point2::new(x as f64 * scale, y as f64 * scale);
            let mut segs: Vec<Segment2> =
                v.iter().map(|c| Segment2::new(p(c.0, c.1), p(c.2, c.3))).collect();
            for k in 0..long {
                segs.push(Segment2::new(p(0, k as i32), p(8, 8 - k as i32)));
            }
            segs.retain(|s| !s.is_degenerate());
            let mut want = Vec::new();
            for i in 0..segs.len() {
                for j in i + 1..segs.len() {
                    let (a, b) = (box_of(&segs[i]), box_of(&segs[j]));
                    if !(b[0] > a[1] || a[0] > b[1] || b[2] > a[3] || a[2] > b[3]) {
                        want.push((i as u32, j as u32));
                    }
                }
            }
            for layout in [Layout::One, Layout::Strips, Layout::Auto] {
                let Some(sweep) = sweep_of(&segs, layout, u64::MAX) else {
                    // A zero x-extent only.
                    proptest::prop_assert!(segs.iter().all(|s| s.a.x == segs[0].a.x));
                    continue;
                };
                let mut got = tested(&sweep);
                got.sort_unstable();
                proptest::prop_assert_eq!(&got, &want);
            }
        }
    }
}
