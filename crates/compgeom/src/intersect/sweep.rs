//! The plane sweep of book §2.1: FINDINTERSECTIONS, HANDLEEVENTPOINT and FINDNEWEVENT,
//! with the degenerate cases the book sets aside handled as ordinary input.
//!
//! * **Event queue** 𝒬: a `BTreeMap` keyed by [`EventPoint`] (exact sweep order), so
//!   insert, delete-min and "is this point already there" are O(log n). An event holds
//!   the segments whose upper endpoint it is (linked through an array, no allocation),
//!   the zero-length segments at it, whether it is an endpoint, and how many adjacent
//!   pairs in the status currently *hold* it as their crossing.
//! * **O(n) working space.** The book's exercise: only crossings of pairs that are
//!   adjacent in the status stay in the queue. Each status segment remembers the crossing
//!   it holds with its right neighbour; when that adjacency ends the hold is released and a
//!   crossing event nobody holds is deleted (it will be found again if the pair becomes
//!   adjacent again). The queue thus holds at most the 2n endpoints plus n crossings.
//! * **Status** 𝒯: [`Status`], split around the event point with exact predicates
//!   (`orient2d` / [`orient_exact`] for the side of a segment, exact x comparisons for a
//!   horizontal one) and joined back with the segments through `p` reordered as they
//!   cross the sweep line just below `p` ([`compare_slopes`], horizontal segments last).
//!
//! Overlapping collinear segments are tied in the status (then ordered by index); the
//! sweep tracks, for every line with two or more segments running along it, the set of
//! segments covering the piece below the current event and reports a maximal piece when
//! that set changes.

use super::list::defining_second;
use super::order::{sweep_cmp_points, EventPoint, Oriented};
use super::small_int;
use super::status::Status;
use super::{IntersectionPoint, Overlap};
use crate::kernel::{
    compare_slopes, orient2d, orient_exact, segment_intersection, ExactPoint, Orientation, Point2,
    Segment2, SegmentIntersection,
};
use crate::{Error, Result};
use std::cmp::Ordering;
use std::collections::btree_map::Entry;
use std::collections::BTreeMap;

const NONE: u32 = u32::MAX;

/// Whether the sweep goes on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Flow {
    /// Keep sweeping.
    Continue,
    /// Stop now (the caller found what it wanted).
    Stop,
}

/// Receives the sweep's output, in sweep order.
pub(crate) trait Sink {
    /// An intersection point (two or more segments contain it).
    fn point(&mut self, point: IntersectionPoint) -> Flow;
    /// A maximal overlap piece, reported when the sweep reaches its lower end.
    fn overlap(&mut self, overlap: Overlap) -> Flow;
    /// Called after every event with its number (from 0), the event point and the status
    /// just below it (only when [`Sink::wants_status`] says so).
    fn status(&mut self, _event: usize, _at: Point2, _status: &[usize]) {}
    /// Whether [`Sink::status`] should be called after event `event`.
    fn wants_status(&self, _event: usize) -> bool {
        false
    }
}

/// What the sweep measured about itself (tests check the space bound with it).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct SweepStats {
    /// Events handled.
    pub events: usize,
    /// The largest number of events in the queue at one time.
    pub max_queue: usize,
    /// Crossing events that were queued and later deleted because their pair stopped
    /// being adjacent.
    pub released: usize,
}

/// The data of one event point.
#[derive(Debug, Clone, Copy)]
struct Event {
    /// First segment whose upper endpoint this is (then `next_upper[...]`), or `NONE`.
    upper: u32,
    /// First zero-length segment at this point (then `next_point[...]`), or `NONE`.
    points: u32,
    /// True when the point is an endpoint of some segment (never deleted early).
    endpoint: bool,
    /// Adjacent status pairs that hold this point as their crossing.
    holders: u32,
}

impl Default for Event {
    fn default() -> Self {
        Event {
            upper: NONE,
            points: NONE,
            endpoint: false,
            holders: 0,
        }
    }
}

struct Sweep {
    segs: Vec<Oriented>,
    queue: BTreeMap<EventPoint, Event>,
    status: Status,
    next_upper: Vec<u32>,
    next_point: Vec<u32>,
    /// The crossing event each status segment holds with its right neighbour.
    held: Vec<Option<EventPoint>>,
    /// For a run of collinear segments below the current point, keyed by its smallest
    /// index: where its overlap piece started.
    open: Vec<Option<Point2>>,
    stats: SweepStats,
}

/// Where segment `s` (in the status, so it crosses the sweep line through `p`) lies
/// relative to `p`: `Less` = passes left of `p`, `Equal` = contains `p`, `Greater` = right.
fn side(s: &Oriented, p: &EventPoint) -> Ordering {
    if s.is_horizontal() {
        // Horizontal, on the sweep line: compare p.x with its x-range.
        let cmp_x = |x: f64| p.compare_x_with(x);
        return if cmp_x(s.upper.x) == Ordering::Less {
            Ordering::Greater
        } else if cmp_x(s.lower.x) == Ordering::Greater {
            Ordering::Less
        } else {
            Ordering::Equal
        };
    }
    // The segment crosses the sweep line through p, so if p is left (right) of its whole
    // x-range it passes right (left) of p: plain comparisons, exact.
    let (lo, hi) = if s.upper.x <= s.lower.x {
        (s.upper.x, s.lower.x)
    } else {
        (s.lower.x, s.upper.x)
    };
    if p.mid.x + p.rad.x < lo {
        return Ordering::Greater;
    }
    if p.mid.x - p.rad.x > hi {
        return Ordering::Less;
    }
    let o = match p.exact {
        ExactPoint::Input(q) => orient2d(s.upper, s.lower, q),
        ExactPoint::Crossing(c) => {
            let seg = s.segment();
            if c.s == seg || c.t == seg {
                // p is on the segment by construction (and within its y-range, since the
                // segment is in the status).
                return Ordering::Equal;
            }
            match orient_near(s, p) {
                Some(o) => o,
                None => match small_int::orient(s.upper, s.lower, &p.exact) {
                    Some(Ordering::Greater) => Orientation::CounterClockwise,
                    Some(Ordering::Less) => Orientation::Clockwise,
                    Some(Ordering::Equal) => Orientation::Collinear,
                    None => orient_exact(&s.upper.into(), &s.lower.into(), &p.exact),
                },
            }
        }
    };
    // Walking down from upper to lower, p on the right-hand side (cw) is west of the
    // segment: the segment passes to the right of p.
    match o {
        Orientation::Clockwise => Ordering::Greater,
        Orientation::CounterClockwise => Ordering::Less,
        Orientation::Collinear => Ordering::Equal,
    }
}

/// A floating-point filter for the orientation of `(s.upper, s.lower, p)` with `p` a
/// crossing: evaluate at the centre of `p`'s box and bound both the rounding of the
/// evaluation (Shewchuk's `ccwerrboundA`, doubled) and the distance to the exact point
/// (within the box). `None` when the bound does not decide the sign.
fn orient_near(s: &Oriented, p: &EventPoint) -> Option<Orientation> {
    let (u, l, q) = (s.upper, s.lower, p.mid);
    let (dx, dy) = (l.x - u.x, l.y - u.y);
    let (qx, qy) = (q.x - u.x, q.y - u.y);
    let (t1, t2) = (dx * qy, dy * qx);
    let det = t1 - t2;
    // The rounded differences dx, dy are within a factor (1 + 2^-52) of the exact ones.
    let moved = (dx.abs() * p.rad.y + dy.abs() * p.rad.x) * (1.0 + 1e-12);
    let bound = 6.7e-16 * (t1.abs() + t2.abs()) + moved + 1e-300;
    if !(det.is_finite() && bound.is_finite()) {
        return None;
    }
    if det > bound {
        Some(Orientation::CounterClockwise)
    } else if det < -bound {
        Some(Orientation::Clockwise)
    } else {
        None
    }
}

/// [`compare_slopes`], with the small-integer fast path first.
fn slopes(s: &Oriented, t: &Oriented) -> Ordering {
    // compare_slopes(s, t) is the sign of dir(t) × dir(s), each directed from its
    // lexicographically smaller endpoint.
    let lex = |o: &Oriented| {
        let (a, b) = (o.upper, o.lower);
        if (a.x, a.y) <= (b.x, b.y) {
            (a, b)
        } else {
            (b, a)
        }
    };
    let ((sa, sb), (ta, tb)) = (lex(s), lex(t));
    small_int::cross(ta, tb, sa, sb).unwrap_or_else(|| compare_slopes(s.segment(), t.segment()))
}

/// The order of two segments through a common point just below it (left to right),
/// horizontal segments last, ties (collinear) by index.
fn below_cmp(segs: &[Oriented], i: usize, j: usize) -> Ordering {
    let (s, t) = (&segs[i], &segs[j]);
    let (cs, ct) = (s.direction_class(), t.direction_class());
    cs.cmp(&ct)
        .then_with(|| {
            if cs == 2 {
                Ordering::Equal
            } else {
                slopes(s, t)
            }
        })
        .then(i.cmp(&j))
}

/// True when two segments through a common point run along one line.
fn collinear(segs: &[Oriented], i: usize, j: usize) -> bool {
    let (s, t) = (&segs[i], &segs[j]);
    s.direction_class() == t.direction_class()
        && (s.direction_class() == 2 || slopes(s, t) == Ordering::Equal)
}

/// The runs of two or more consecutive collinear segments of `list`, each sorted.
fn collinear_runs(segs: &[Oriented], list: &[usize]) -> Vec<Vec<usize>> {
    let mut runs = Vec::new();
    let mut start = 0;
    for k in 1..=list.len() {
        if k == list.len() || !collinear(segs, list[k - 1], list[k]) {
            if k - start >= 2 {
                let mut run = list[start..k].to_vec();
                run.sort_unstable();
                runs.push(run);
            }
            start = k;
        }
    }
    runs
}

/// `Err(NonFinite)` naming the first segment with a NaN or infinite coordinate.
pub(crate) fn check_finite(segments: &[Segment2]) -> Result<()> {
    for (i, s) in segments.iter().enumerate() {
        for v in [s.a.x, s.a.y, s.b.x, s.b.y] {
            if !v.is_finite() {
                return Err(Error::NonFinite {
                    what: format!("segment {i}"),
                    value: v,
                });
            }
        }
    }
    Ok(())
}

/// Run the sweep over `segments`, sending every intersection point and overlap to `sink`.
pub(crate) fn sweep(segments: &[Segment2], sink: &mut impl Sink) -> Result<SweepStats> {
    if segments.len() >= NONE as usize {
        return Err(Error::InvalidInput(format!(
            "{} segments: at most {} are supported",
            segments.len(),
            NONE - 1
        )));
    }
    check_finite(segments)?;
    let n = segments.len();
    let mut sw = Sweep {
        segs: segments.iter().map(|&s| Oriented::of(s)).collect(),
        queue: BTreeMap::new(),
        status: Status::new(n),
        next_upper: vec![NONE; n],
        next_point: vec![NONE; n],
        held: vec![None; n],
        open: vec![None; n],
        stats: SweepStats::default(),
    };
    sw.init();
    let mut scratch = Scratch::default();
    while let Some((p, ev)) = sw.queue.pop_first() {
        let number = sw.stats.events;
        sw.stats.events += 1;
        if sw.handle(&p, ev, sink, &mut scratch) == Flow::Stop {
            break;
        }
        if sink.wants_status(number) {
            let order = sw.status.in_order();
            sink.status(number, p.approx(), &order);
        }
    }
    Ok(sw.stats)
}

/// Buffers reused from event to event.
#[derive(Default)]
struct Scratch {
    mid: Vec<usize>,
    upper: Vec<usize>,
    lower: Vec<usize>,
    interior: Vec<usize>,
    points: Vec<usize>,
    newmid: Vec<usize>,
    /// The sorted lists of a reported point: all segments, U(p), L(p).
    all: Vec<usize>,
    up: Vec<usize>,
    low: Vec<usize>,
}

impl Sweep {
    /// Queue every endpoint: sort them once and build the map in bulk.
    fn init(&mut self) {
        // (point, segment, is the upper endpoint of a proper segment / zero-length).
        let mut ends: Vec<(Point2, u32, u8)> = Vec::with_capacity(2 * self.segs.len());
        for (i, s) in self.segs.iter().enumerate() {
            if s.is_point() {
                ends.push((s.upper, i as u32, 2));
            } else {
                ends.push((s.upper, i as u32, 0));
                ends.push((s.lower, i as u32, 1));
            }
        }
        ends.sort_unstable_by(|a, b| sweep_cmp_points(a.0, b.0));
        let mut events: Vec<(EventPoint, Event)> = Vec::new();
        for &(p, i, kind) in &ends {
            let same = matches!(events.last(), Some((q, _)) if q.mid == p);
            if !same {
                let e = Event {
                    endpoint: true,
                    ..Event::default()
                };
                events.push((EventPoint::input(p), e));
            }
            let e = &mut events.last_mut().expect("pushed above").1;
            match kind {
                0 => {
                    self.next_upper[i as usize] = e.upper;
                    e.upper = i;
                }
                2 => {
                    self.next_point[i as usize] = e.points;
                    e.points = i;
                }
                _ => {}
            }
        }
        self.queue = events.into_iter().collect();
        self.stats.max_queue = self.queue.len();
    }

    /// HANDLEEVENTPOINT(p).
    fn handle(
        &mut self,
        p: &EventPoint,
        ev: Event,
        sink: &mut impl Sink,
        sc: &mut Scratch,
    ) -> Flow {
        let segs = &self.segs;
        // The segments containing p are contiguous in the status: cut them out.
        let whole = self.status.take();
        let (left, rest) = self
            .status
            .split(whole, &mut |i| side(&segs[i], p) == Ordering::Less);
        let (mid, right) = self
            .status
            .split(rest, &mut |i| side(&segs[i], p) != Ordering::Greater);
        sc.mid.clear();
        self.status.collect(mid, &mut sc.mid);

        // U(p), L(p), C(p), and the zero-length segments at p (in both U and L).
        sc.upper.clear();
        let mut u = ev.upper;
        while u != NONE {
            sc.upper.push(u as usize);
            u = self.next_upper[u as usize];
        }
        sc.points.clear();
        let mut z = ev.points;
        while z != NONE {
            sc.points.push(z as usize);
            z = self.next_point[z as usize];
        }
        sc.lower.clear();
        sc.interior.clear();
        let at = p.as_input();
        for &i in &sc.mid {
            if Some(segs[i].lower) == at {
                sc.lower.push(i);
            } else {
                sc.interior.push(i);
            }
        }
        let total = sc.upper.len() + sc.mid.len() + sc.points.len();
        if total >= 2 {
            // Each list sorted in its scratch buffer, then stored (inline when short).
            let sort = |list: &mut Vec<usize>, parts: [&[usize]; 3]| {
                list.clear();
                for part in parts {
                    list.extend_from_slice(part);
                }
                list.sort_unstable();
            };
            sort(&mut sc.all, [&sc.upper, &sc.mid, &sc.points]);
            sort(&mut sc.up, [&sc.upper, &sc.points, &[]]);
            sort(&mut sc.low, [&sc.lower, &sc.points, &[]]);
            sc.interior.sort_unstable();
            // At a crossing every segment through p is interior.
            let second = at
                .is_none()
                .then(|| defining_second(&sc.all, |k| Segment2::new(segs[k].upper, segs[k].lower)));
            let point = IntersectionPoint::new(
                p.approx(),
                &sc.all,
                [&sc.up, &sc.low, &sc.interior],
                second,
            );
            if sink.point(point) == Flow::Stop {
                return Flow::Stop;
            }
        }

        // The new middle: U(p) ∪ C(p) in the order just below p.
        sc.newmid.clear();
        sc.newmid.extend_from_slice(&sc.upper);
        sc.newmid.extend_from_slice(&sc.interior);
        sc.newmid.sort_by(|&i, &j| below_cmp(segs, i, j));

        if self.track_overlaps(p, &sc.mid, &sc.newmid, sink) == Flow::Stop {
            return Flow::Stop;
        }

        let sl = self.status.last(left);
        let sr = self.status.first(right);
        if !(sc.mid.is_empty() && sc.newmid.is_empty()) {
            // Every adjacency touching the middle ends here.
            if let Some(l) = sl {
                self.release(l);
            }
            for k in 0..sc.mid.len() {
                self.release(sc.mid[k]);
            }
        }
        let new_piece = self.status.build(&sc.newmid);
        let joined = self.status.join(new_piece, right);
        let whole = self.status.join(left, joined);
        self.status.set(whole);

        match (sc.newmid.first(), sc.newmid.last()) {
            (Some(&first), Some(&last)) => {
                if let Some(l) = sl {
                    self.find_new_event(l, first, p);
                }
                if let Some(r) = sr {
                    self.find_new_event(last, r, p);
                }
            }
            _ => {
                if let (Some(l), Some(r)) = (sl, sr) {
                    if !sc.mid.is_empty() {
                        self.find_new_event(l, r, p);
                    }
                }
            }
        }
        self.stats.max_queue = self.stats.max_queue.max(self.queue.len());
        Flow::Continue
    }

    /// Close the overlap pieces that end at `p` and open those that start there.
    fn track_overlaps(
        &mut self,
        p: &EventPoint,
        mid: &[usize],
        newmid: &[usize],
        sink: &mut impl Sink,
    ) -> Flow {
        if mid.len() < 2 && newmid.len() < 2 {
            return Flow::Continue;
        }
        let above = collinear_runs(&self.segs, mid);
        let below = collinear_runs(&self.segs, newmid);
        for run in &above {
            if below.contains(run) {
                continue;
            }
            if let Some(from) = self.open[run[0]].take() {
                let o = Overlap {
                    segments: run.clone(),
                    from,
                    to: p.approx(),
                };
                if sink.overlap(o) == Flow::Stop {
                    return Flow::Stop;
                }
            }
        }
        for run in &below {
            if !above.contains(run) {
                self.open[run[0]] = Some(p.approx());
            }
        }
        Flow::Continue
    }

    /// The adjacency of `i` with its right neighbour ends: release the crossing it held.
    fn release(&mut self, i: usize) {
        if let Some(key) = self.held[i].take() {
            if let Some(e) = self.queue.get_mut(&key) {
                e.holders -= 1;
                if e.holders == 0 && !e.endpoint {
                    self.queue.remove(&key);
                    self.stats.released += 1;
                }
            }
        }
    }

    /// FINDNEWEVENT(l, r, p): `l` and `r` are now adjacent, `l` left of `r`.
    fn find_new_event(&mut self, l: usize, r: usize, p: &EventPoint) {
        let (s, t) = (self.segs[l].segment(), self.segs[r].segment());
        // Disjoint bounding boxes (plain comparisons, exact): no common point.
        let x_apart = s.a.x.max(s.b.x) < t.a.x.min(t.b.x) || t.a.x.max(t.b.x) < s.a.x.min(s.b.x);
        let y_apart = s.a.y.max(s.b.y) < t.a.y.min(t.b.y) || t.a.y.max(t.b.y) < s.a.y.min(s.b.y);
        if x_apart || y_apart {
            return;
        }
        // A common endpoint, an endpoint on the other segment or an overlap are found at
        // the endpoint events; only a proper crossing needs a new event.
        if let SegmentIntersection::Crossing(c) = segment_intersection(s, t) {
            let e = EventPoint::new(ExactPoint::Crossing(c));
            if e > *p {
                // Hold the key as stored: if another pair (or an endpoint) defined this
                // point first, later look-ups then compare equal by construction.
                let stored = match self.queue.entry(e) {
                    Entry::Occupied(mut o) => {
                        o.get_mut().holders += 1;
                        *o.key()
                    }
                    Entry::Vacant(v) => {
                        v.insert(Event::default()).holders = 1;
                        e
                    }
                };
                self.held[l] = Some(stored);
            }
        }
    }
}
