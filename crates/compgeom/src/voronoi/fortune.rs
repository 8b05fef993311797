//! VORONOIDIAGRAM (book §7.2): Fortune's plane sweep, O(n log n) time, O(n) space.
//!
//! The sweep line moves downwards. The event queue holds the sites (sorted once, by
//! decreasing `y`, then increasing `x`) and the circle events (a binary heap ordered by the
//! exact comparison of their lowest points, [`super::predicates::cmp_events`]). The beach
//! line is a balanced tree of arcs ([`super::beach_line`]). Each breakpoint traces a
//! Voronoi edge; a circle event removes the vanishing arc and creates a vertex. An arc's
//! pending circle event is cancelled (a false alarm, marked invalid and skipped when it
//! reaches the top of the heap) when its neighbours change.
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
//!   zero-length edges; these are contracted afterwards (the "same point" test is the exact
//!   in-circle test on the defining sites), giving one vertex of degree > 3.
//! - Collinear sites: no circle events, parallel edges, no vertices.

use super::beach_line::{Arc, BeachLine, NIL};
use super::diagram::{HalfEdge, Vertex, VoronoiDiagram};
use super::predicates::{cmp_event_site, cmp_events, left_of_breakpoint, CircleKey};
use crate::kernel::{ensure_finite, incircle, CircleSide, Point2};
use crate::Result;
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// Distinct sites in first-seen order, each site's first input index, the input-to-site
/// map, and the sweep order (decreasing `y`, then increasing `x`) of the sites.
pub(crate) fn dedupe(points: &[Point2]) -> (Vec<Point2>, Vec<usize>, Vec<usize>, Vec<usize>) {
    let sweep_cmp = |a: &Point2, b: &Point2| {
        b.y.partial_cmp(&a.y)
            .unwrap_or(Ordering::Equal)
            .then(a.x.partial_cmp(&b.x).unwrap_or(Ordering::Equal))
    };
    let mut idx: Vec<usize> = (0..points.len()).collect();
    idx.sort_by(|&i, &j| sweep_cmp(&points[i], &points[j]).then(i.cmp(&j)));
    // Groups of equal points; the first index in each group is the smallest.
    let mut group_of = vec![0usize; points.len()];
    let mut firsts: Vec<usize> = Vec::new();
    for (k, &i) in idx.iter().enumerate() {
        if k > 0 && sweep_cmp(&points[idx[k - 1]], &points[i]) == Ordering::Equal {
            group_of[i] = firsts.len() - 1;
        } else {
            firsts.push(i);
            group_of[i] = firsts.len() - 1;
        }
    }
    // Site ids in first-seen order.
    let mut by_first: Vec<usize> = (0..firsts.len()).collect();
    by_first.sort_by_key(|&g| firsts[g]);
    let mut site_of_group = vec![0usize; firsts.len()];
    for (s, &g) in by_first.iter().enumerate() {
        site_of_group[g] = s;
    }
    let sites: Vec<Point2> = by_first.iter().map(|&g| points[firsts[g]]).collect();
    let site_input: Vec<usize> = by_first.iter().map(|&g| firsts[g]).collect();
    let input_to_site: Vec<usize> = group_of.iter().map(|&g| site_of_group[g]).collect();
    let order: Vec<usize> = (0..firsts.len()).map(|g| site_of_group[g]).collect();
    (sites, site_input, input_to_site, order)
}

/// A circle event in the heap (max-heap: ordered so that the earliest event is greatest).
struct QueuedEvent {
    key: CircleKey,
    id: usize,
}

impl PartialEq for QueuedEvent {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for QueuedEvent {}
impl PartialOrd for QueuedEvent {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for QueuedEvent {
    fn cmp(&self, other: &Self) -> Ordering {
        // Earlier in the sweep = greater; equal keys: the older event first.
        cmp_events(&other.key, &self.key).then(other.id.cmp(&self.id))
    }
}

/// The state of the sweep.
pub(crate) struct Sweep<'a> {
    sites: &'a [Point2],
    pub(crate) beach: BeachLine,
    heap: BinaryHeap<QueuedEvent>,
    /// Per event: the arc that vanishes, and whether the event is still valid.
    events: Vec<(usize, bool)>,
    origin: Vec<usize>,
    next: Vec<usize>,
    face: Vec<usize>,
    vertex_sites: Vec<[usize; 3]>,
    vertex_point: Vec<Point2>,
}

impl<'a> Sweep<'a> {
    pub(crate) fn new(sites: &'a [Point2]) -> Self {
        Sweep {
            sites,
            beach: BeachLine::new(),
            heap: BinaryHeap::new(),
            events: Vec::new(),
            origin: Vec::new(),
            next: Vec::new(),
            face: Vec::new(),
            vertex_sites: Vec::new(),
            vertex_point: Vec::new(),
        }
    }

    /// A new edge between the cells of `a` and `b`: returns `h` (face `a`); `h ^ 1` has
    /// face `b`.
    fn new_edge(&mut self, a: usize, b: usize) -> usize {
        let h = self.face.len();
        self.face.extend([a, b]);
        self.origin.extend([NIL, NIL]);
        self.next.extend([NIL, NIL]);
        h
    }

    fn invalidate(&mut self, arc: usize) {
        let e = self.beach.arc(arc).event;
        if e != NIL {
            self.events[e].1 = false;
            self.beach.arc_mut(arc).event = NIL;
        }
    }

    /// Queue the circle event of arc `m` if its breakpoints converge.
    fn check(&mut self, m: usize) {
        let (l, r) = (self.beach.prev(m), self.beach.next(m));
        if l == NIL || r == NIL {
            return;
        }
        let s = |x: usize| self.sites[self.beach.arc(x).site];
        if let Some(key) = CircleKey::new(s(l), s(m), s(r)) {
            let id = self.events.len();
            self.events.push((m, true));
            self.heap.push(QueuedEvent { key, id });
            self.beach.arc_mut(m).event = id;
        }
    }

    fn site_event(&mut self, q: usize) {
        let arc = |site, right_edge| Arc {
            site,
            right_edge,
            event: NIL,
        };
        if self.beach.is_empty() {
            self.beach.insert_first(arc(q, NIL));
            return;
        }
        let sites = self.sites;
        let p = sites[q];
        let found = self
            .beach
            .locate(|l, r| left_of_breakpoint(p, sites[l], sites[r]));
        let a = self.beach.arc(found).site;
        if sites[a].y == p.y && self.beach.next(found) == NIL {
            // All arcs so far lie on the sweep line (the start of the sweep): append.
            let h = self.new_edge(a, q);
            self.beach.arc_mut(found).right_edge = h;
            self.beach.insert_after(found, arc(q, NIL));
            return;
        }
        self.invalidate(found);
        let h = self.new_edge(a, q);
        let old_right = self.beach.arc(found).right_edge;
        self.beach.arc_mut(found).right_edge = h;
        let qn = self.beach.insert_after(found, arc(q, h ^ 1));
        let a2 = self.beach.insert_after(qn, arc(a, old_right));
        self.check(found);
        self.check(a2);
    }

    fn circle_event(&mut self, key: &CircleKey, m: usize) {
        let (l, r) = (self.beach.prev(m), self.beach.next(m));
        if l == NIL || r == NIL {
            return; // cannot happen for a valid event; never panic
        }
        let (ls, ms, rs) = (
            self.beach.arc(l).site,
            self.beach.arc(m).site,
            self.beach.arc(r).site,
        );
        let v = self.vertex_sites.len();
        self.vertex_sites.push([ls, ms, rs]);
        self.vertex_point.push(key.approx_centre());
        let a = self.beach.arc(l).right_edge;
        let b = self.beach.arc(m).right_edge;
        self.origin[a] = v;
        self.origin[b] = v;
        let c = self.new_edge(ls, rs);
        self.origin[c ^ 1] = v;
        self.next[a ^ 1] = b;
        self.next[c] = a;
        self.next[b ^ 1] = c ^ 1;
        self.beach.arc_mut(l).right_edge = c;
        self.invalidate(m);
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
            while let Some(top) = self.heap.peek() {
                if self.events[top.id].1 {
                    break;
                }
                self.heap.pop();
            }
            let site = order.get(i).copied();
            let event_first = match (site, self.heap.peek()) {
                (Some(q), Some(top)) => cmp_event_site(&top.key, self.sites[q]) == Ordering::Less,
                (None, Some(_)) => true,
                (_, None) => false,
            };
            if event_first {
                if let Some(stop) = stop {
                    if self.heap.peek().is_some_and(|t| t.key.y.1 < stop) {
                        return;
                    }
                }
                if let Some(top) = self.heap.pop() {
                    let m = self.events[top.id].0;
                    self.circle_event(&top.key, m);
                }
            } else if let Some(q) = site {
                if stop.is_some_and(|s| self.sites[q].y < s) {
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
        let nv = self.vertex_sites.len();
        let mut next = self.next;
        let mut prev = vec![NIL; nh];
        for h in 0..nh {
            if next[h] != NIL {
                prev[next[h]] = h;
            }
        }
        let mut parent: Vec<usize> = (0..nv).collect();
        fn find(parent: &mut [usize], mut x: usize) -> usize {
            while parent[x] != x {
                parent[x] = parent[parent[x]];
                x = parent[x];
            }
            x
        }
        let mut removed = vec![false; nh];
        let same_point = |u: usize, w: usize| {
            let [a, b, c] = self.vertex_sites[u];
            self.vertex_sites[w].iter().all(|&s| {
                s == a
                    || s == b
                    || s == c
                    || incircle(sites[a], sites[b], sites[c], sites[s]) == CircleSide::OnCircle
            })
        };
        for h in (0..nh).step_by(2) {
            let (u, w) = (self.origin[h], self.origin[h ^ 1]);
            if u == NIL || w == NIL {
                continue;
            }
            let (ru, rw) = (find(&mut parent, u), find(&mut parent, w));
            if ru != rw && !same_point(ru, rw) {
                continue;
            }
            // Contract: ph -> h -> nh becomes ph -> nh, likewise around the twin.
            for e in [h, h ^ 1] {
                let (p, n) = (prev[e], next[e]);
                if p != NIL {
                    next[p] = n;
                }
                if n != NIL {
                    prev[n] = p;
                }
                removed[e] = true;
            }
            parent[rw] = ru;
        }
        // Compact vertices (roots) and half-edges.
        let mut vmap = vec![NIL; nv];
        let mut vertices: Vec<Vertex> = Vec::new();
        for v in 0..nv {
            let r = find(&mut parent, v);
            if vmap[r] == NIL {
                vmap[r] = vertices.len();
                vertices.push(Vertex {
                    point: self.vertex_point[r],
                    sites: Vec::new(),
                });
            }
            vmap[v] = vmap[r];
        }
        let mut hmap = vec![NIL; nh];
        let mut k = 0;
        for h in 0..nh {
            if !removed[h] {
                hmap[h] = k;
                k += 1;
            }
        }
        let opt = |x: usize, map: &[usize]| (x != NIL).then(|| map[x]);
        let mut half_edges = Vec::with_capacity(k);
        for h in 0..nh {
            if removed[h] {
                continue;
            }
            let origin = opt(self.origin[h], &vmap);
            if let Some(v) = origin {
                vertices[v].sites.push(self.face[h]);
            }
            half_edges.push(HalfEdge {
                origin,
                twin: hmap[h ^ 1],
                next: opt(next[h], &hmap),
                prev: opt(prev[h], &hmap),
                site: self.face[h],
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
