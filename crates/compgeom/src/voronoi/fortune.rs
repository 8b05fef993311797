//! VORONOIDIAGRAM (book §7.2): Fortune's plane sweep, O(n log n) time, O(n) space.
//!
//! The sweep line moves downwards. The event queue holds the sites (sorted once, by
//! decreasing `y`, then increasing `x`) and the circle events (a binary heap of 24-byte
//! records — the enclosure of the event's `y` and its index — ordered by the exact
//! comparison of their lowest points, [`super::predicates::cmp_events`], which usually
//! needs only the enclosures). The beach line is a balanced tree of arcs
//! ([`super::beach_line`]). Each breakpoint traces a Voronoi edge (DCEL half-edges); a
//! circle event removes the vanishing arc and creates a vertex. An arc's pending circle
//! event is cancelled (a false alarm) when its neighbours change: the arc forgets it, and
//! the heap drops it lazily when it reaches the top (an event is valid only while its arc
//! still points to it; event indices are never reused). The bounding box of §7.2 is applied
//! afterwards by [`super::clip_cells`] to the unbounded edges.
//!
//! When all sites are small integers (within a `2¹¹` box) every predicate runs in exact
//! machine integers ([`super::predicates`]); otherwise floating-point filters with proven
//! bounds decide almost everything and exact arithmetic the rest.
//!
//! ## Degenerate input
//!
//! - Duplicate sites are merged first (each input index maps to its site).
//! - Several sites with the largest `y` (the book's special case): while every arc's site
//!   lies on the sweep line, a new site is appended to the right with a vertical bisector,
//!   instead of splitting an arc.
//! - A site exactly below a breakpoint splits the arc to the right; the arc left of it has
//!   zero length and disappears in a circle event at the same moment. Ties between events
//!   are broken lexicographically (`y` then `x`, circle events first), a consistent limit
//!   of an infinitesimally tilted sweep line.
//! - Four or more cocircular sites produce several vertices at the same point joined by
//!   zero-length edges; these are contracted afterwards, giving one vertex of degree > 3.
//!   The "same point" test is the exact equality of the two end events in the sweep order:
//!   both circles pass through the edge's two sites, and two such circles with the same
//!   lowest point are the same circle.
//! - Collinear sites: no circle events, parallel edges, no vertices.

use super::beach_line::{Arc, BeachLine, NIL};
use super::diagram::{HalfEdge, Vertex, VoronoiDiagram};
use super::predicates::{
    circle_event, circumcentre, cmp_event_site, cmp_event_site_int, cmp_events, cmp_events_int,
    left_of_breakpoint, Circle, Exact, IntCircle, IntFrame,
};
use crate::kernel::arith::ordered_key as key;
use crate::kernel::{ensure_finite, Point2};
use crate::Result;
use std::cmp::Ordering;

/// Distinct sites in first-seen order, each site's first input index, the input-to-site
/// map, and the sweep order (decreasing `y`, then increasing `x`) of the sites.
///
/// One unstable sort of `(y, x, index)` keys: coordinates become order-preserving `u64`s
/// (`-0.0` is first made `+0.0`, so equal values get equal keys; inputs are finite), `y`
/// negated for the decreasing order; the index makes the order total, so the first index
/// of each group of equal points is its smallest. Renumbering groups by first index is a
/// linear pass over a marker array.
pub(crate) fn dedupe(points: &[Point2]) -> (Vec<Point2>, Vec<usize>, Vec<usize>, Vec<usize>) {
    let n = points.len();
    let mut keys: Vec<(u64, u64, u32)> = points
        .iter()
        .enumerate()
        .map(|(i, p)| (!key(p.y), key(p.x), i as u32))
        .collect();
    keys.sort_unstable();
    // Groups of equal points, in sweep order.
    const NONE: usize = usize::MAX;
    let mut group_of = vec![0usize; n];
    let mut first_of_group: Vec<usize> = Vec::new();
    let mut group_at_first = vec![NONE; n];
    for (k, &(ky, kx, i)) in keys.iter().enumerate() {
        let i = i as usize;
        if k == 0 || (keys[k - 1].0, keys[k - 1].1) != (ky, kx) {
            group_at_first[i] = first_of_group.len();
            first_of_group.push(i);
        }
        group_of[i] = first_of_group.len() - 1;
    }
    // Site ids in first-seen order.
    let mut site_of_group = vec![0usize; first_of_group.len()];
    let mut sites = Vec::with_capacity(first_of_group.len());
    let mut site_input = Vec::with_capacity(first_of_group.len());
    for (i, &g) in group_at_first.iter().enumerate() {
        if g != NONE {
            site_of_group[g] = sites.len();
            sites.push(points[i]);
            site_input.push(i);
        }
    }
    let input_to_site: Vec<usize> = group_of.iter().map(|&g| site_of_group[g]).collect();
    (sites, site_input, input_to_site, site_of_group)
}

/// A circle event in the queue: the enclosure of its `y` (so that most comparisons need
/// nothing else) and its index in the event table.
#[derive(Debug, Clone, Copy)]
struct Queued {
    y_lo: f64,
    y_hi: f64,
    id: u32,
}

/// A circle event: its key, its defining sites and the arc that would vanish. It is a
/// false alarm (cancelled) unless that arc's `event` is still this event's index; indices
/// are never reused, so a cancelled event can never look valid again.
#[derive(Debug, Clone, Copy)]
struct Event {
    circle: Circle,
    sites: [u32; 3],
    arc: u32,
}

/// The state of the sweep.
pub(crate) struct Sweep<'a> {
    sites: &'a [Point2],
    /// Set when every site is a small integer: exact integer predicates.
    frame: Option<IntFrame>,
    pub(crate) beach: BeachLine,
    /// Binary min-heap (earliest event first) of the pending circle events.
    heap: Vec<Queued>,
    events: Vec<Event>,
    /// The integer form of each event (only with `frame`).
    ints: Vec<IntCircle>,
    origin: Vec<u32>,
    next: Vec<u32>,
    face: Vec<u32>,
    /// Per Voronoi vertex: the circle event that created it.
    vertex_event: Vec<u32>,
}

impl<'a> Sweep<'a> {
    pub(crate) fn new(sites: &'a [Point2]) -> Self {
        // Capacities: at most 3n edges (6n half-edges) and 2n vertices; about two circle
        // events (most of them false alarms) per site and per vertex.
        let n = sites.len();
        let frame = IntFrame::detect(sites);
        Sweep {
            sites,
            frame,
            beach: BeachLine::new(),
            heap: Vec::with_capacity(n / 4),
            events: Vec::with_capacity(4 * n),
            ints: Vec::with_capacity(if frame.is_some() { 4 * n } else { 0 }),
            origin: Vec::with_capacity(6 * n),
            next: Vec::with_capacity(6 * n),
            face: Vec::with_capacity(6 * n),
            vertex_event: Vec::with_capacity(2 * n),
        }
    }

    /// The exact data of event `id`.
    fn exact(&self, id: u32) -> Exact {
        let e = &self.events[id as usize];
        Exact {
            sites: e.sites.map(|s| self.sites[s as usize]),
            int: self.frame.map(|f| (self.ints[id as usize], f)),
        }
    }

    /// Exact order of two events (`Less` = processed first).
    fn cmp_ids(&self, a: u32, b: u32) -> Ordering {
        if self.frame.is_some() {
            let (e, f) = (&self.events[a as usize], &self.events[b as usize]);
            return cmp_events_int(
                &e.circle,
                &self.ints[a as usize],
                &f.circle,
                &self.ints[b as usize],
            );
        }
        cmp_events(
            &self.events[a as usize].circle,
            || self.exact(a),
            &self.events[b as usize].circle,
            || self.exact(b),
        )
    }

    /// Is queued event `a` processed before `b`? Equal keys: the older event first.
    #[inline]
    fn before(&self, a: &Queued, b: &Queued) -> bool {
        if a.y_lo > b.y_hi {
            return true;
        }
        if a.y_hi < b.y_lo {
            return false;
        }
        match self.cmp_ids(a.id, b.id) {
            Ordering::Less => true,
            Ordering::Greater => false,
            Ordering::Equal => a.id < b.id,
        }
    }

    fn heap_push(&mut self, q: Queued) {
        let mut i = self.heap.len();
        self.heap.push(q);
        while i > 0 {
            let p = (i - 1) / 2;
            if !self.before(&q, &self.heap[p]) {
                break;
            }
            self.heap[i] = self.heap[p];
            i = p;
        }
        self.heap[i] = q;
    }

    /// Remove the earliest event. Floyd's variant: the hole at the root moves down along
    /// the earlier child to a leaf (one comparison per level), then the last element is
    /// sifted up from there (usually a step or two), about half the comparisons of the
    /// textbook sift-down.
    fn heap_pop(&mut self) -> Option<Queued> {
        let top = *self.heap.first()?;
        let last = self.heap.pop()?;
        let n = self.heap.len();
        if n == 0 {
            return Some(top);
        }
        let mut i = 0;
        loop {
            let l = 2 * i + 1;
            if l >= n {
                break;
            }
            let c = if l + 1 < n && self.before(&self.heap[l + 1], &self.heap[l]) {
                l + 1
            } else {
                l
            };
            self.heap[i] = self.heap[c];
            i = c;
        }
        while i > 0 {
            let p = (i - 1) / 2;
            if !self.before(&last, &self.heap[p]) {
                break;
            }
            self.heap[i] = self.heap[p];
            i = p;
        }
        self.heap[i] = last;
        Some(top)
    }

    /// The earliest pending event that is not a false alarm (cancelled ones are dropped).
    fn peek_valid(&mut self) -> Option<Queued> {
        while let Some(&top) = self.heap.first() {
            let arc = self.events[top.id as usize].arc;
            if self.beach.arc(arc).event == top.id {
                return Some(top);
            }
            self.heap_pop();
        }
        None
    }

    /// A new edge between the cells of `a` and `b`: returns `h` (face `a`); `h ^ 1` has
    /// face `b`.
    fn new_edge(&mut self, a: u32, b: u32) -> u32 {
        let h = self.face.len() as u32;
        self.face.extend([a, b]);
        self.origin.extend([NIL, NIL]);
        self.next.extend([NIL, NIL]);
        h
    }

    /// Cancel the pending circle event of `arc` (a false alarm).
    fn invalidate(&mut self, arc: u32) {
        self.beach.arc_mut(arc).event = NIL;
    }

    /// Queue the circle event of arc `m` if its breakpoints converge.
    fn check(&mut self, m: u32) {
        let (l, r) = (self.beach.prev(m), self.beach.next(m));
        if l == NIL || r == NIL {
            return;
        }
        let (al, am, ar) = (*self.beach.arc(l), *self.beach.arc(m), *self.beach.arc(r));
        let circle = match self.frame {
            Some(f) => match f.circle_event(al.p, am.p, ar.p) {
                Some((c, ic)) => {
                    self.ints.push(ic);
                    c
                }
                None => return,
            },
            None => match circle_event(al.p, am.p, ar.p) {
                Some(c) => c,
                None => return,
            },
        };
        let id = self.events.len() as u32;
        self.events.push(Event {
            circle,
            sites: [al.site, am.site, ar.site],
            arc: m,
        });
        self.heap_push(Queued {
            y_lo: circle.y.0,
            y_hi: circle.y.1,
            id,
        });
        self.beach.arc_mut(m).event = id;
    }

    fn site_event(&mut self, q: u32) {
        let sites = self.sites;
        let p = sites[q as usize];
        let arc = |right_edge| Arc {
            site: q,
            right_edge,
            event: NIL,
            p,
        };
        if self.beach.is_empty() {
            self.beach.insert_first(arc(NIL));
            return;
        }
        let exact_f64 = self.frame.is_some();
        let found = self
            .beach
            .locate(|l, r| left_of_breakpoint(p, l.p, r.p, exact_f64));
        let old = *self.beach.arc(found);
        if old.p.y == p.y && self.beach.next(found) == NIL {
            // All arcs so far lie on the sweep line (the start of the sweep): append.
            let h = self.new_edge(old.site, q);
            self.beach.arc_mut(found).right_edge = h;
            self.beach.insert_after(found, arc(NIL));
            return;
        }
        self.invalidate(found);
        let h = self.new_edge(old.site, q);
        self.beach.arc_mut(found).right_edge = h;
        let qn = self.beach.insert_after(found, arc(h ^ 1));
        let a2 = self.beach.insert_after(qn, Arc { event: NIL, ..old });
        self.check(found);
        self.check(a2);
    }

    fn circle_event(&mut self, id: u32) {
        let m = self.events[id as usize].arc;
        let (l, r) = (self.beach.prev(m), self.beach.next(m));
        if l == NIL || r == NIL {
            return; // cannot happen for a valid event; never panic
        }
        let (ls, rs) = (self.beach.arc(l).site, self.beach.arc(r).site);
        let v = self.vertex_event.len() as u32;
        self.vertex_event.push(id);
        let a = self.beach.arc(l).right_edge as usize;
        let b = self.beach.arc(m).right_edge as usize;
        self.origin[a] = v;
        self.origin[b] = v;
        let c = self.new_edge(ls, rs) as usize;
        self.origin[c ^ 1] = v;
        self.next[a ^ 1] = b as u32;
        self.next[c] = a as u32;
        self.next[b ^ 1] = (c ^ 1) as u32;
        self.beach.arc_mut(l).right_edge = c as u32;
        self.invalidate(l);
        self.invalidate(r);
        self.beach.remove(m);
        self.check(l);
        self.check(r);
    }

    /// Process events until the next one is below `stop` (all of them if `None`): a site
    /// at `y < stop`, or a circle event whose lowest point is below `stop`.
    pub(crate) fn run(&mut self, order: &[usize], stop: Option<f64>) {
        let mut i = 0;
        loop {
            let top = self.peek_valid();
            let site = order.get(i).map(|&q| q as u32);
            let event_first = match (site, top) {
                (Some(q), Some(t)) => {
                    let e = &self.events[t.id as usize].circle;
                    let s = self.sites[q as usize];
                    let o = match &self.frame {
                        Some(f) => cmp_event_site_int(e, &self.ints[t.id as usize], f, s),
                        None => cmp_event_site(e, || self.exact(t.id), s),
                    };
                    o == Ordering::Less
                }
                (None, Some(_)) => true,
                (_, None) => false,
            };
            if event_first {
                if let (Some(stop), Some(t)) = (stop, top) {
                    if t.y_hi < stop {
                        return;
                    }
                }
                if let Some(t) = self.heap_pop() {
                    self.circle_event(t.id);
                }
            } else if let Some(q) = site {
                if stop.is_some_and(|s| self.sites[q as usize].y < s) {
                    return;
                }
                self.site_event(q);
                i += 1;
            } else {
                return;
            }
        }
    }

    /// The diagram: contract zero-length edges (cocircular sites), then compact.
    pub(crate) fn finish(self) -> (Vec<Vertex>, Vec<HalfEdge>, Vec<Option<usize>>) {
        let sites = self.sites;
        let nh = self.face.len();
        let nv = self.vertex_event.len();
        let mut next = self.next.clone();
        let mut prev = vec![NIL; nh];
        for h in 0..nh {
            if next[h] != NIL {
                prev[next[h] as usize] = h as u32;
            }
        }
        let mut parent: Vec<u32> = (0..nv as u32).collect();
        fn find(parent: &mut [u32], mut x: u32) -> u32 {
            while parent[x as usize] != x {
                parent[x as usize] = parent[parent[x as usize] as usize];
                x = parent[x as usize];
            }
            x
        }
        // An edge joins two vertices whose circles pass through its two sites; two such
        // circles with the same lowest point are one circle. So an edge has zero length
        // exactly when its end events compare equal in the sweep order.
        let same_point = |u: u32, w: u32| {
            let (eu, ew) = (self.vertex_event[u as usize], self.vertex_event[w as usize]);
            self.cmp_ids(eu, ew) == Ordering::Equal
        };
        let mut removed = vec![false; nh];
        for h in (0..nh).step_by(2) {
            let (u, w) = (self.origin[h], self.origin[h ^ 1]);
            if u == NIL || w == NIL {
                continue;
            }
            let (ru, rw) = (find(&mut parent, u), find(&mut parent, w));
            if ru != rw && !same_point(u, w) {
                continue;
            }
            // Contract: ph -> h -> nh becomes ph -> nh, likewise around the twin.
            for e in [h, h ^ 1] {
                let (p, n) = (prev[e], next[e]);
                if p != NIL {
                    next[p as usize] = n;
                }
                if n != NIL {
                    prev[n as usize] = p;
                }
                removed[e] = true;
            }
            parent[rw as usize] = ru;
        }
        // Compact vertices (roots) and half-edges.
        let mut vmap = vec![NIL; nv];
        let mut vertices: Vec<Vertex> = Vec::with_capacity(nv);
        for v in 0..nv as u32 {
            let r = find(&mut parent, v);
            if vmap[r as usize] == NIL {
                vmap[r as usize] = vertices.len() as u32;
                let [a, b, c] = self.events[self.vertex_event[r as usize] as usize].sites;
                vertices.push(Vertex {
                    point: circumcentre(sites[a as usize], sites[b as usize], sites[c as usize]),
                    sites: Vec::with_capacity(3),
                });
            }
            vmap[v as usize] = vmap[r as usize];
        }
        let mut hmap = vec![NIL; nh];
        let mut k = 0u32;
        for h in 0..nh {
            if !removed[h] {
                hmap[h] = k;
                k += 1;
            }
        }
        let opt = |x: u32, map: &[u32]| (x != NIL).then(|| map[x as usize] as usize);
        let mut half_edges = Vec::with_capacity(k as usize);
        for h in 0..nh {
            if removed[h] {
                continue;
            }
            let site = self.face[h] as usize;
            let origin = opt(self.origin[h], &vmap);
            if let Some(v) = origin {
                vertices[v].sites.push(site);
            }
            half_edges.push(HalfEdge {
                origin,
                twin: hmap[h ^ 1] as usize,
                next: opt(next[h], &hmap),
                prev: opt(prev[h], &hmap),
                site,
            });
        }
        for v in &mut vertices {
            v.sites.sort_unstable();
        }
        let mut site_half_edge = vec![None; sites.len()];
        for (i, h) in half_edges.iter().enumerate() {
            // Prefer the start of an open chain, so a walk along `next` covers the chain.
            match site_half_edge[h.site] {
                None => site_half_edge[h.site] = Some(i),
                Some(_) if h.prev.is_none() => site_half_edge[h.site] = Some(i),
                _ => {}
            }
        }
        (vertices, half_edges, site_half_edge)
    }
}

/// The Voronoi diagram of `points` by Fortune's sweep (book §7.2), O(n log n).
///
/// Duplicates are merged ([`VoronoiDiagram::input_to_site`]); non-finite coordinates are an
/// error naming the point.
///
/// ```
/// use compgeom::voronoi::fortune_voronoi;
/// use compgeom::Point2;
/// let pts = [Point2::new(0.0, 0.0), Point2::new(2.0, 0.0), Point2::new(0.0, 2.0), Point2::new(2.0, 2.0)];
/// let d = fortune_voronoi(&pts).unwrap();
/// // Four cocircular sites: one vertex of degree 4 at the centre.
/// assert_eq!(d.vertices.len(), 1);
/// assert_eq!(d.vertices[0].point, Point2::new(1.0, 1.0));
/// assert_eq!(d.vertices[0].sites, vec![0, 1, 2, 3]);
/// d.validate().unwrap();
/// ```
pub fn fortune_voronoi(points: &[Point2]) -> Result<VoronoiDiagram> {
    ensure_finite(points, "point")?;
    let (sites, site_input_index, input_to_site, order) = dedupe(points);
    let mut sweep = Sweep::new(&sites);
    sweep.run(&order, None);
    let (vertices, half_edges, site_half_edge) = sweep.finish();
    Ok(VoronoiDiagram {
        sites,
        site_input_index,
        input_to_site,
        vertices,
        half_edges,
        site_half_edge,
    })
}
