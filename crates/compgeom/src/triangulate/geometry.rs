//! The polygon as the sweep sees it: every ring vertex once, boundary links with the
//! interior on the left, and the exact predicates (event order, orientation) under the
//! symbolic perturbation that separates the visits of a point where rings touch.
//!
//! Preparation (O(n log n)): drop consecutive repeated vertices, orient the outer ring
//! counter-clockwise and the holes clockwise, sort the vertices into sweep order, and
//! relink the boundary at every point visited more than once (equal neighbours in that
//! order). Crossings are found by the sweeps themselves: MAKEMONOTONE checks every pair of
//! edges that become neighbours in its status (Shamos–Hoey), and the monotone
//! triangulation checks each vertex against the other chain; either names the two edges.
//!
//! ## Points visited more than once
//!
//! Rings may touch each other, or themselves, at vertices (a hole touching the outer ring,
//! two holes touching, a figure-eight ring). Such a point stays one vertex per visit. Around
//! it, the edges must alternate "leaving" and "arriving" in angular order (else two rings
//! cross there, or two edges overlap: an error); each arriving edge is then relinked to the
//! leaving edge next to it clockwise, so every visit becomes one corner whose wedge of
//! interior is disjoint from the others. The predicates then decide every tie between
//! visits of one point as if visit `k` were moved by `δ^k · d_k` (δ → 0) in a direction
//! `d_k` inside its own wedge and on the interior side of both its edges (exact; see
//! `direction`), so the moved edges stay inside the wedge. That moved polygon is simple, and its triangulation is one of the original polygon
//! (a triangle never joins two visits of one point).
use crate::intersect::{any_intersection_where, clean_ring};
use crate::kernel::arith::Arith;
use crate::kernel::exact::Dyadic;
use crate::kernel::{ensure_finite, orient2d, Orientation, Point2, Polygon, Segment2};
use crate::{Error, Result};
use std::cmp::Ordering;

/// No vertex.
pub(crate) const NONE: u32 = u32::MAX;

/// The prepared polygon.
#[derive(Debug, Clone)]
pub(crate) struct Geometry {
    /// Every vertex, ring by ring (outer ring first), in input order.
    pub pts: Vec<Point2>,
    /// Ring `r` is `pts[ring_starts[r]..ring_starts[r + 1]]`.
    pub ring_starts: Vec<usize>,
    /// The boundary successor with the interior on the left (after relinking).
    pub next: Vec<u32>,
    /// The boundary predecessor.
    pub prev: Vec<u32>,
    /// Whether some point is visited more than once.
    pub pinched: bool,
    /// Every vertex in sweep order (top to bottom, equal y left to right, visits of one
    /// point by the perturbation).
    pub order: Vec<u32>,
    /// The input edge number (ring by ring, edge k from vertex k to k + 1) of edge u (from
    /// u to `next[u]`), for messages.
    input_edge: Vec<u32>,
    /// The input rings (after dropping repeated vertices), for messages.
    rings: Vec<Vec<Point2>>,
}

/// "ring r edge k (a → b)" for error messages; edges numbered as in the input ring.
fn edge_name(rings: &[Vec<Point2>], starts: &[usize], e: usize) -> String {
    let r = starts.partition_point(|&s| s <= e) - 1;
    let k = e - starts[r];
    let ring = &rings[r];
    let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
    format!("ring {r} edge {k} ({} {} -> {} {})", a.x, a.y, b.x, b.y)
}

impl Geometry {
    /// Prepare a polygon (see the module docs). Errors name what is wrong and where.
    pub fn new(polygon: &Polygon) -> Result<Geometry> {
        let mut rings = Vec::with_capacity(1 + polygon.holes.len());
        for (r, ring) in polygon.rings().enumerate() {
            ensure_finite(ring, &format!("polygon ring {r}"))?;
            let ring = clean_ring(ring);
            if ring.len() < 3 {
                return Err(Error::InvalidInput(format!(
                    "polygon ring {r} has fewer than 3 distinct vertices"
                )));
            }
            rings.push(ring);
        }
        let n: usize = rings.iter().map(Vec::len).sum();
        if n >= NONE as usize / 2 {
            return Err(Error::InvalidInput(format!(
                "polygon has too many vertices ({n})"
            )));
        }
        let mut pts = Vec::with_capacity(n);
        let mut starts = vec![0];
        let mut next = vec![0u32; n];
        let mut prev = vec![0u32; n];
        for (r, ring) in rings.iter().enumerate() {
            let s = pts.len();
            pts.extend_from_slice(ring);
            starts.push(pts.len());
            let len = ring.len();
            // Orientation from the lowest vertex (y, then x): a strict corner of the hull.
            let low = (0..len)
                .min_by(|&a, &b| {
                    let (p, q) = (ring[a], ring[b]);
                    // (-0 and 0 one value: `total_cmp` alone puts -0 first.)
                    (p.y + 0.0)
                        .total_cmp(&(q.y + 0.0))
                        .then((p.x + 0.0).total_cmp(&(q.x + 0.0)))
                })
                .unwrap_or(0);
            let turn = orient2d(
                ring[(low + len - 1) % len],
                ring[low],
                ring[(low + 1) % len],
            );
            if turn == Orientation::Collinear {
                let q = ring[low];
                return Err(Error::InvalidInput(format!(
                    "polygon is not simple: ring {r} doubles back on itself at ({}, {})",
                    q.x, q.y
                )));
            }
            // Outer ring counter-clockwise, holes clockwise: interior on the left.
            let forward = (turn == Orientation::CounterClockwise) == (r == 0);
            for k in 0..len {
                let (a, b) = ((s + k) as u32, (s + (k + 1) % len) as u32);
                if forward {
                    next[a as usize] = b;
                    prev[b as usize] = a;
                } else {
                    next[b as usize] = a;
                    prev[a as usize] = b;
                }
            }
        }
        // Edge u (from u to next[u]) is input edge u on a forward ring, else the input
        // edge arriving at u.
        let input_edge: Vec<u32> = (0..n as u32)
            .map(|u| {
                let w = next[u as usize];
                let r = starts.partition_point(|&s| s <= u as usize) - 1;
                let len = starts[r + 1] - starts[r];
                if w as usize == starts[r] + (u as usize - starts[r] + 1) % len {
                    u
                } else {
                    w
                }
            })
            .collect();
        // The sweep order by coordinates; runs of equal points are the points visited
        // more than once.
        let mut order: Vec<u32> = (0..n as u32).collect();
        order.sort_unstable_by(|&a, &b| {
            let (p, q) = (pts[a as usize], pts[b as usize]);
            q.y.partial_cmp(&p.y)
                .unwrap_or(Ordering::Equal)
                .then(p.x.partial_cmp(&q.x).unwrap_or(Ordering::Equal))
        });
        let mut runs: Vec<(usize, usize)> = Vec::new();
        let mut i = 0;
        while i < n {
            let mut j = i + 1;
            while j < n && pts[order[j] as usize] == pts[order[i] as usize] {
                j += 1;
            }
            if j - i > 1 {
                runs.push((i, j));
            }
            i = j;
        }
        let mut g = Geometry {
            pts,
            ring_starts: starts,
            next,
            prev,
            pinched: !runs.is_empty(),
            order,
            input_edge,
            rings,
        };
        for &(i, j) in &runs {
            let mut visits = g.order[i..j].to_vec();
            visits.sort_unstable();
            g.relink(&visits)?;
        }
        for &(i, j) in &runs {
            let mut run = g.order[i..j].to_vec();
            run.sort_unstable_by(|&a, &b| g.cmp_event(a, b));
            g.order[i..j].copy_from_slice(&run);
        }
        Ok(g)
    }

    /// On an error path: the first contact of two edges inside an edge, found by the general
    /// intersection sweep of [`crate::intersect`], as an error naming both edges; `None`
    /// when the boundary has none (then the caller's own error stands).
    pub fn contact_error(&self) -> Option<Error> {
        let mut segments = Vec::with_capacity(self.len());
        for ring in &self.rings {
            for k in 0..ring.len() {
                segments.push(Segment2::new(ring[k], ring[(k + 1) % ring.len()]));
            }
        }
        let p = any_intersection_where(&segments, |p| !p.interior().is_empty()).ok()??;
        let a = p.interior()[0];
        let b = p.segments().iter().copied().find(|&s| s != a).unwrap_or(a);
        let how = if p.interior().contains(&b) {
            "cross at"
        } else {
            "touch (a vertex inside the second edge) at"
        };
        Some(Error::InvalidInput(format!(
            "polygon is not simple: {} and {} {how} ({}, {})",
            edge_name(&self.rings, &self.ring_starts, b),
            edge_name(&self.rings, &self.ring_starts, a),
            p.point.x,
            p.point.y
        )))
    }

    /// "ring r edge k (a -> b)" for edge u (from u to `next[u]`).
    pub fn edge_name(&self, u: u32) -> String {
        edge_name(
            &self.rings,
            &self.ring_starts,
            self.input_edge[u as usize] as usize,
        )
    }

    /// Number of vertices.
    pub fn len(&self) -> usize {
        self.pts.len()
    }

    /// Number of holes.
    pub fn holes(&self) -> usize {
        self.ring_starts.len() - 2
    }

    /// Relink the boundary at a point where the given edges (input numbering) meet.
    fn relink(&mut self, visits: &[u32]) -> Result<()> {
        let p = self.pts[visits[0] as usize];
        // Rays: (far end, visit, leaving?).
        let mut rays: Vec<(Point2, u32, bool)> = Vec::with_capacity(2 * visits.len());
        for &v in visits {
            rays.push((self.pts[self.next[v as usize] as usize], v, true));
            rays.push((self.pts[self.prev[v as usize] as usize], v, false));
        }
        let upper = |q: Point2| q.y > p.y || (q.y == p.y && q.x > p.x);
        rays.sort_by(|a, b| {
            upper(b.0)
                .cmp(&upper(a.0))
                .then_with(|| match orient2d(p, a.0, b.0) {
                    Orientation::CounterClockwise => Ordering::Less,
                    Orientation::Clockwise => Ordering::Greater,
                    Orientation::Collinear => Ordering::Equal,
                })
        });
        let m = rays.len();
        let here = format!("({}, {})", p.x, p.y);
        for i in 0..m {
            let (a, b) = (rays[i], rays[(i + 1) % m]);
            if upper(a.0) == upper(b.0) && orient2d(p, a.0, b.0) == Orientation::Collinear {
                return Err(Error::InvalidInput(format!(
                    "polygon is not simple: two edges overlap at {here}"
                )));
            }
            if a.2 == b.2 {
                return Err(Error::InvalidInput(format!(
                    "polygon is not simple: rings cross at the shared vertex {here}"
                )));
            }
        }
        // Each arriving edge continues with the leaving edge just clockwise of it (all
        // read before any is written).
        let links: Vec<(u32, u32)> = (0..m)
            .filter(|&i| !rays[i].2)
            .map(|i| (self.prev[rays[i].1 as usize], rays[(i + m - 1) % m].1))
            .collect();
        for (from, w) in links {
            self.next[from as usize] = w;
            self.prev[w as usize] = from;
        }
        Ok(())
    }

    /// `a` comes before `b` in the sweep (top to bottom; equal y: left to right; visits of
    /// one point by the perturbation). `Less` = `a` is above `b`.
    #[inline]
    pub fn cmp_event(&self, a: u32, b: u32) -> Ordering {
        let (p, q) = (self.pts[a as usize], self.pts[b as usize]);
        match q.y.partial_cmp(&p.y) {
            Some(Ordering::Equal) | None => {}
            Some(o) => return o,
        }
        match p.x.partial_cmp(&q.x) {
            Some(Ordering::Equal) | None => {}
            Some(o) => return o,
        }
        if a == b {
            return Ordering::Equal;
        }
        // Two visits of one point: the lower index is moved further, along its direction.
        let m = a.min(b);
        let up = self.direction_up(m);
        if (m == a) == up {
            Ordering::Less
        } else {
            Ordering::Greater
        }
    }

    /// `a` is above `b` in the sweep order.
    #[inline]
    pub fn above(&self, a: u32, b: u32) -> bool {
        self.cmp_event(a, b) == Ordering::Less
    }

    /// The perturbation direction `d_m` of visit `m` at `p` (exact): `r_out + r_in` for a
    /// convex corner, `−(r_out + r_in)` for a reflex one, `r_out` turned by +90° for a
    /// straight one, where `r_out`, `r_in` point from `p` to the corner's neighbours.
    /// Each lies strictly left of the leaving edge and strictly left of the arriving
    /// edge, so both edges of the moved corner stay inside its own wedge. (Ties are then
    /// broken by turning `d_m` counter-clockwise by an infinitesimal angle.)
    fn direction(&self, m: u32) -> (Dyadic, Dyadic) {
        let p = self.pts[m as usize];
        let o = self.pts[self.next[m as usize] as usize];
        let i = self.pts[self.prev[m as usize] as usize];
        let sum = || {
            (
                Dyadic::diff(o.x, p.x).plus(&Dyadic::diff(i.x, p.x)),
                Dyadic::diff(o.y, p.y).plus(&Dyadic::diff(i.y, p.y)),
            )
        };
        match orient2d(p, o, i) {
            Orientation::CounterClockwise => sum(),
            Orientation::Clockwise => {
                let (x, y) = sum();
                (Dyadic::zero().minus(&x), Dyadic::zero().minus(&y))
            }
            Orientation::Collinear => (Dyadic::diff(p.y, o.y), Dyadic::diff(o.x, p.x)),
        }
    }

    /// Whether the perturbation direction of visit `m` points up in the sweep order.
    fn direction_up(&self, m: u32) -> bool {
        let (dx, dy) = self.direction(m);
        match dy.sign() {
            Some(Ordering::Greater) => true,
            Some(Ordering::Less) => false,
            // Level: the infinitesimal counter-clockwise turn lifts a rightward direction.
            _ => dx.sign() == Some(Ordering::Greater),
        }
    }

    /// Exact orientation of three vertices under the perturbation: `Greater` for a left
    /// (counter-clockwise) turn.
    #[inline]
    pub fn orient(&self, a: u32, b: u32, c: u32) -> Ordering {
        let (pa, pb, pc) = (
            self.pts[a as usize],
            self.pts[b as usize],
            self.pts[c as usize],
        );
        match orient2d(pa, pb, pc) {
            Orientation::CounterClockwise => Ordering::Greater,
            Orientation::Clockwise => Ordering::Less,
            Orientation::Collinear => {
                if !self.pinched {
                    Ordering::Equal
                } else if pa == pc && a != c {
                    self.perturbed(a, b, c)
                } else if pa == pb && a != b {
                    self.perturbed(b, c, a)
                } else if pb == pc && b != c {
                    self.perturbed(c, a, b)
                } else {
                    Ordering::Equal
                }
            }
        }
    }

    /// The sign of orient(j', q, k') for two visits `j`, `k` of one point and a vertex `q`
    /// elsewhere: the visit moved further (lower index) decides.
    fn perturbed(&self, j: u32, q: u32, k: u32) -> Ordering {
        if q == j || q == k || self.pts[q as usize] == self.pts[j as usize] {
            return Ordering::Equal;
        }
        if k < j {
            self.side_of_direction(k, q)
        } else {
            self.side_of_direction(j, q).reverse()
        }
    }

    /// The sign of cross(q − p, d_m) for visit `m` at `p` (exact).
    fn side_of_direction(&self, m: u32, q: u32) -> Ordering {
        let p = self.pts[m as usize];
        let qq = self.pts[q as usize];
        let (dx, dy) = self.direction(m);
        let (wx, wy) = (Dyadic::diff(qq.x, p.x), Dyadic::diff(qq.y, p.y));
        match wx.times(&dy).minus(&wy.times(&dx)).sign() {
            Some(Ordering::Equal) | None => {
                // Along d_m: the counter-clockwise turn of d_m puts q on its left when q
                // lies ahead (dot product positive).
                let dot = wx.times(&dx).plus(&wy.times(&dy));
                if dot.sign() == Some(Ordering::Greater) {
                    Ordering::Greater
                } else {
                    Ordering::Less
                }
            }
            Some(o) => o,
        }
    }
}
