//! The working triangulation: triangles as half-edge triples, closed by ghost triangles.
//!
//! Triangle `t` owns half-edges `3t, 3t+1, 3t+2`; half-edge `h` runs from `v[h]` to
//! `v[next(h)]`, counter-clockwise around its triangle, and `twin[h]` is the opposite
//! half-edge in the neighbouring triangle. Every hull edge `a → b` of a real triangle
//! has a *ghost* triangle `(b, a, GHOST)` on its outer side, so every half-edge has a twin
//! and the hull needs no special cases. The ghost vertex is the "point at infinity" of the
//! closed surface: a ghost triangle `(u, w, GHOST)` contains the open half-plane to the left
//! of `u → w` (outside the hull), and the in-circle test against it is the orientation
//! test of `u → w` — the exact limit of a circle through `u`, `w` and a point moving to
//! infinity, with no big coordinates anywhere.
//!
//! Vertex ids are indices into the point list (`u32`): the caller's slice, borrowed, or an
//! owned copy when an operation (constraint crossings, refinement) adds Steiner points.

use super::pred::{in_circle, in_circle_grid, orient, orient_grid, strictly_between};
use crate::Point2;
use std::borrow::Cow;

/// The vertex at infinity of ghost triangles.
pub(crate) const GHOST: u32 = u32::MAX;
/// "No half-edge / triangle".
pub(crate) const NONE: u32 = u32::MAX;

#[inline(always)]
pub(crate) fn next(h: u32) -> u32 {
    if h % 3 == 2 {
        h - 2
    } else {
        h + 1
    }
}

#[inline(always)]
pub(crate) fn prev(h: u32) -> u32 {
    if h % 3 == 0 {
        h + 2
    } else {
        h - 1
    }
}

/// Where a point was found by [`Mesh::locate`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Found {
    /// Strictly inside real triangle `t`, or strictly outside the hull beyond the real edge of
    /// ghost triangle `t`.
    Face(u32),
    /// In the relative interior of the edge of half-edge `h` (`h` in a real triangle).
    Edge(u32),
    /// Equal to vertex `v`.
    Vertex(u32),
}

/// A Delaunay triangulation under construction (see the module docs).
pub(crate) struct Mesh<'a> {
    pub(crate) pts: Cow<'a, [Point2]>,
    pub(crate) v: Vec<u32>,
    pub(crate) twin: Vec<u32>,
    /// Some real triangle (a start for walks).
    pub(crate) last: u32,
    /// Flip stack, kept to avoid reallocation.
    stack: Vec<u32>,
    /// Every point is in a [`small_integer_grid`](super::pred::small_integer_grid), so the
    /// unfiltered grid predicates are exact (set by the builder; cleared by `push_point`).
    pub(crate) grid: bool,
    /// Optional rank of every point along the Hilbert curve (empty when unknown): the
    /// result lists triangles in this order, so that consumers walking the triangle array
    /// (the Voronoi cells) stay spatially coherent.
    pub(crate) rank: Vec<u32>,
}

impl<'a> Mesh<'a> {
    /// The triangle `a, b, c` (counter-clockwise, distinct, not collinear) with its three
    /// ghosts.
    pub(crate) fn new(pts: &'a [Point2], a: u32, b: u32, c: u32, capacity: usize) -> Self {
        let mut m = Mesh {
            pts: Cow::Borrowed(pts),
            v: Vec::with_capacity(capacity * 6),
            twin: Vec::with_capacity(capacity * 6),
            last: 0,
            stack: Vec::new(),
            grid: false,
            rank: Vec::new(),
        };
        let t = m.add(a, b, c);
        let g_ab = m.add(b, a, GHOST);
        let g_bc = m.add(c, b, GHOST);
        let g_ca = m.add(a, c, GHOST);
        m.link(3 * t, 3 * g_ab);
        m.link(3 * t + 1, 3 * g_bc);
        m.link(3 * t + 2, 3 * g_ca);
        m.link(3 * g_ab + 2, 3 * g_bc + 1);
        m.link(3 * g_bc + 2, 3 * g_ca + 1);
        m.link(3 * g_ca + 2, 3 * g_ab + 1);
        m.last = t;
        m
    }

    /// An empty mesh over `pts` (the caller adds and links triangles).
    pub(crate) fn empty(pts: Vec<Point2>) -> Self {
        Mesh {
            pts: Cow::Owned(pts),
            v: Vec::new(),
            twin: Vec::new(),
            last: 0,
            stack: Vec::new(),
            grid: false,
            rank: Vec::new(),
        }
    }

    /// Appends a point (a Steiner point) and returns its vertex id; the mesh owns its
    /// points from then on.
    pub(crate) fn push_point(&mut self, p: Point2) -> u32 {
        // A Steiner point may leave the grid: back to the filtered predicates.
        self.grid = false;
        let pts = self.pts.to_mut();
        pts.push(p);
        (pts.len() - 1) as u32
    }

    #[inline(always)]
    pub(crate) fn add(&mut self, a: u32, b: u32, c: u32) -> u32 {
        let t = (self.v.len() / 3) as u32;
        self.v.extend_from_slice(&[a, b, c]);
        self.twin.extend_from_slice(&[NONE, NONE, NONE]);
        t
    }

    #[inline(always)]
    fn set(&mut self, t: u32, a: u32, b: u32, c: u32) {
        let i = 3 * t as usize;
        self.v[i] = a;
        self.v[i + 1] = b;
        self.v[i + 2] = c;
    }

    #[inline(always)]
    pub(crate) fn link(&mut self, h: u32, g: u32) {
        self.twin[h as usize] = g;
        self.twin[g as usize] = h;
    }

    #[inline(always)]
    pub(crate) fn pt(&self, v: u32) -> Point2 {
        self.pts[v as usize]
    }

    /// Number of triangle slots (real and ghost).
    pub(crate) fn slots(&self) -> u32 {
        (self.v.len() / 3) as u32
    }

    #[inline(always)]
    pub(crate) fn is_ghost(&self, t: u32) -> bool {
        let i = 3 * t as usize;
        self.v[i] == GHOST || self.v[i + 1] == GHOST || self.v[i + 2] == GHOST
    }

    /// Walks from `self.last` towards `p` (the visibility walk; it terminates in a Delaunay
    /// triangulation). Every test is an exact orientation.
    pub(crate) fn locate(&self, p: Point2) -> Found {
        // In a Delaunay triangulation the walk always terminates.
        self.walk(p, u64::MAX).unwrap_or(Found::Face(self.last))
    }

    /// [`Mesh::locate`] for any triangulation (e.g. constrained, where the visibility walk
    /// may cycle) and any query point: the walk for at most a bounded number of steps, then
    /// an exhaustive scan. The walk uses the filtered predicates even on a grid mesh: `p`
    /// may be a Steiner point off the grid (a rounded constraint crossing), for which the
    /// unfiltered grid predicates are not exact.
    pub(crate) fn locate_any(&self, p: Point2) -> Found {
        let steps = 64 + 4 * u64::from(self.slots());
        if let Some(f) = self.walk_with::<false>(p, steps) {
            return f;
        }
        for t in 0..self.slots() {
            let base = 3 * t;
            if self.is_ghost(t) {
                // The open half-plane beyond the ghost's real edge.
                let h = (0..3)
                    .map(|k| base + k)
                    .find(|&h| self.v[h as usize] != GHOST && self.v[next(h) as usize] != GHOST);
                if let Some(h) = h {
                    let (a, b) = (self.v[h as usize], self.v[next(h) as usize]);
                    if orient(self.pt(b), self.pt(a), p) > 0 {
                        return Found::Face(t);
                    }
                }
                continue;
            }
            let mut zero_mask = 0;
            let mut inside = true;
            for k in 0..3 {
                let h = base + k;
                let s = orient(
                    self.pt(self.v[h as usize]),
                    self.pt(self.v[next(h) as usize]),
                    p,
                );
                if s < 0 {
                    inside = false;
                    break;
                }
                if s == 0 {
                    zero_mask |= 1 << k;
                }
            }
            if inside {
                return self.classify(base, zero_mask);
            }
        }
        Found::Face(self.last)
    }

    /// The visibility walk of [`Mesh::locate`], giving up (`None`) after `max_steps`.
    fn walk(&self, p: Point2, max_steps: u64) -> Option<Found> {
        if self.grid {
            self.walk_with::<true>(p, max_steps)
        } else {
            self.walk_with::<false>(p, max_steps)
        }
    }

    /// [`Mesh::walk`] with the grid predicates (`GRID`) or the filtered ones.
    fn walk_with<const GRID: bool>(&self, p: Point2, max_steps: u64) -> Option<Found> {
        // Plain slices: the hot loop then pays no `Cow` dispatch per point read.
        let pts: &[Point2] = &self.pts;
        let (v, twin) = (&self.v[..], &self.twin[..]);
        let mut steps = 0u64;
        let mut t = self.last;
        if self.is_ghost(t) {
            t = self.real_neighbour_of_ghost(t);
        }
        // The half-edge we entered through; p is known to be strictly left of it.
        let mut from = NONE;
        // A cheap, deterministic rotation of the first edge tested, so that the walk cannot
        // be steered into a long zig-zag by the same edge order each time.
        let mut rot = 0u32;
        loop {
            let base = 3 * t;
            let b3 = base as usize;
            // `t` is real here, so all three vertices are points.
            let tri = [v[b3], v[b3 + 1], v[b3 + 2]];
            let mut zero_mask = 0u32;
            let mut moved = false;
            for k in 0..3u32 {
                let mut e = k + rot;
                if e >= 3 {
                    e -= 3;
                }
                let h = base + e;
                if h == from {
                    continue;
                }
                let a = tri[e as usize];
                let b = tri[if e == 2 { 0 } else { e as usize + 1 }];
                let (pa, pb) = (pts[a as usize], pts[b as usize]);
                let s = if GRID {
                    orient_grid(pa, pb, p)
                } else {
                    orient(pa, pb, p)
                };
                if s < 0 {
                    let g = twin[h as usize];
                    t = g / 3;
                    from = g;
                    moved = true;
                    break;
                } else if s == 0 {
                    zero_mask |= 1 << e;
                }
            }
            rot = if rot == 2 { 0 } else { rot + 1 };
            if !moved {
                return Some(self.classify(base, zero_mask));
            }
            if self.is_ghost(t) {
                return Some(Found::Face(t));
            }
            steps += 1;
            if steps > max_steps {
                return None;
            }
        }
    }

    pub(crate) fn classify(&self, base: u32, zero_mask: u32) -> Found {
        match zero_mask.count_ones() {
            0 => Found::Face(base / 3),
            1 => Found::Edge(base + zero_mask.trailing_zeros()),
            _ => {
                // Two edges through p: p is their common vertex.
                let i = if zero_mask & 1 != 0 && zero_mask & 2 != 0 {
                    1
                } else if zero_mask & 2 != 0 && zero_mask & 4 != 0 {
                    2
                } else {
                    0
                };
                Found::Vertex(self.v[(base + i) as usize])
            }
        }
    }

    pub(crate) fn real_neighbour_of_ghost(&self, t: u32) -> u32 {
        for k in 0..3 {
            let h = 3 * t + k;
            if self.v[h as usize] != GHOST && self.v[next(h) as usize] != GHOST {
                return self.twin[h as usize] / 3;
            }
        }
        unreachable_ghost()
    }

    /// Inserts vertex `p` (an index into `pts`) found at `at`, then restores the Delaunay
    /// property by flips. `at` must not be `Found::Vertex`.
    pub(crate) fn insert(&mut self, p: u32, at: Found) {
        self.insert_with(p, at, |_, _| false);
    }

    /// [`Mesh::insert`] that never flips an edge `fixed(a, b)` calls constrained: in a
    /// constrained Delaunay triangulation this restores the constrained Delaunay property
    /// (the flips are those of LEGALIZEEDGE, stopped at constraints).
    #[inline(always)]
    pub(crate) fn insert_with<F: Fn(u32, u32) -> bool>(&mut self, p: u32, at: Found, fixed: F) {
        match at {
            Found::Face(t) => self.split_face(t, p),
            Found::Edge(h) => self.split_edge(h, p),
            Found::Vertex(_) => {}
        }
        if self.grid {
            self.legalize_all::<true, F>(p, fixed);
        } else {
            self.legalize_all::<false, F>(p, fixed);
        }
    }

    fn split_face(&mut self, t: u32, p: u32) {
        let i = 3 * t as usize;
        let (a, b, c) = (self.v[i], self.v[i + 1], self.v[i + 2]);
        let (ta, tb, tc) = (self.twin[i], self.twin[i + 1], self.twin[i + 2]);
        self.set(t, a, b, p);
        let t1 = self.add(b, c, p);
        let t2 = self.add(c, a, p);
        self.link(3 * t, ta);
        self.link(3 * t1, tb);
        self.link(3 * t2, tc);
        self.link(3 * t + 1, 3 * t1 + 2);
        self.link(3 * t1 + 1, 3 * t2 + 2);
        self.link(3 * t2 + 1, 3 * t + 2);
        self.stack.extend_from_slice(&[3 * t, 3 * t1, 3 * t2]);
        self.last = if self.is_ghost(t) { t1 } else { t };
        if self.is_ghost(self.last) {
            self.last = t2;
        }
    }

    fn split_edge(&mut self, h: u32, p: u32) {
        let f = self.twin[h as usize];
        let (t, u) = (h / 3, f / 3);
        let a = self.v[h as usize];
        let b = self.v[next(h) as usize];
        let c = self.v[prev(h) as usize];
        let d = self.v[prev(f) as usize];
        let tw_bc = self.twin[next(h) as usize];
        let tw_ca = self.twin[prev(h) as usize];
        let tw_ad = self.twin[next(f) as usize];
        let tw_db = self.twin[prev(f) as usize];
        self.set(t, b, c, p);
        self.set(u, c, a, p);
        let t2 = self.add(a, d, p);
        let t3 = self.add(d, b, p);
        self.link(3 * t, tw_bc);
        self.link(3 * u, tw_ca);
        self.link(3 * t2, tw_ad);
        self.link(3 * t3, tw_db);
        self.link(3 * t + 1, 3 * u + 2);
        self.link(3 * u + 1, 3 * t2 + 2);
        self.link(3 * t2 + 1, 3 * t3 + 2);
        self.link(3 * t3 + 1, 3 * t + 2);
        self.stack
            .extend_from_slice(&[3 * t, 3 * u, 3 * t2, 3 * t3]);
        self.last = t;
    }

    /// LEGALIZEEDGE for every half-edge on the stack (each has the new point `p` opposite).
    #[inline(always)]
    fn legalize_all<const GRID: bool, F: Fn(u32, u32) -> bool>(&mut self, p: u32, fixed: F) {
        // Split borrows: the points are read through a plain slice (no `Cow` dispatch per
        // read) while the flips rewrite the triangle arrays.
        let Mesh {
            pts,
            v,
            twin,
            last,
            stack,
            ..
        } = self;
        let pts: &[Point2] = pts;
        let pp = pts[p as usize];
        while let Some(h) = stack.pop() {
            let f = twin[h as usize];
            let e = Corners::of(h);
            let g = Corners::of(f);
            let a = v[e.h as usize];
            let b = v[e.next as usize];
            let d = v[g.prev as usize];
            if d == GHOST || fixed(a, b) || !inside_of::<GRID>(pts, b, a, d, pp) {
                continue;
            }
            flip_at(v, twin, last, e, g);
            stack.push(e.base + 1);
            stack.push(g.base + 1);
        }
    }

    /// Flips the edge of half-edge `h` (triangle `(a, b, p)` with `h = a → b`, and its twin
    /// triangle `(b, a, d)`) into `(p, a, d)`, `(p, d, b)`, reusing both slots.
    pub(crate) fn flip(&mut self, h: u32) {
        let f = self.twin[h as usize];
        flip_at(
            &mut self.v,
            &mut self.twin,
            &mut self.last,
            Corners::of(h),
            Corners::of(f),
        );
    }
}

/// Is `q` strictly inside the circumcircle of triangle `(a, b, c)` (ccw; one of them may
/// be the ghost vertex, whose circle is the half-plane left of the other two)? With the
/// grid predicates when `GRID` (see [`Mesh::grid`]).
#[inline(always)]
fn inside_of<const GRID: bool>(pts: &[Point2], a: u32, b: u32, c: u32, q: Point2) -> bool {
    let (u, w) = if c == GHOST {
        (a, b)
    } else if a == GHOST {
        (b, c)
    } else if b == GHOST {
        (c, a)
    } else {
        let (pa, pb, pc) = (pts[a as usize], pts[b as usize], pts[c as usize]);
        return if GRID {
            in_circle_grid(pa, pb, pc, q) > 0
        } else {
            in_circle(pa, pb, pc, q) > 0
        };
    };
    let (pu, pw) = (pts[u as usize], pts[w as usize]);
    let side = if GRID {
        orient_grid(pu, pw, q)
    } else {
        orient(pu, pw, q)
    };
    match side {
        1 => true,
        0 => strictly_between(pu, pw, q),
        _ => false,
    }
}

/// [`Mesh::flip`] over the parts of a mesh, with the corners of `h` and of its twin
/// already computed.
#[inline(always)]
fn flip_at(v: &mut [u32], twin: &mut [u32], last: &mut u32, e: Corners, g: Corners) {
    let (h, f) = (e.h, g.h);
    let a = v[h as usize];
    let b = v[e.next as usize];
    let p = v[e.prev as usize];
    let d = v[g.prev as usize];
    let tw_pa = twin[e.prev as usize];
    let tw_bp = twin[e.next as usize];
    let tw_ad = twin[g.next as usize];
    let tw_db = twin[g.prev as usize];
    debug_assert_eq!(twin[f as usize], h);
    let (t3, u3) = (e.base, g.base);
    let mut link = |h: u32, g: u32| {
        twin[h as usize] = g;
        twin[g as usize] = h;
    };
    v[t3 as usize..t3 as usize + 3].copy_from_slice(&[p, a, d]);
    v[u3 as usize..u3 as usize + 3].copy_from_slice(&[p, d, b]);
    link(t3, tw_pa);
    link(t3 + 1, tw_ad);
    link(t3 + 2, u3);
    link(u3 + 1, tw_db);
    link(u3 + 2, tw_bp);
    // Keep a real triangle as the walk start (`is_ghost` of the new triples, inlined).
    if a != GHOST && d != GHOST && p != GHOST {
        *last = t3 / 3;
    } else if d != GHOST && b != GHOST && p != GHOST {
        *last = u3 / 3;
    }
}

/// A half-edge with its triangle's first half-edge and its two companions, computed with
/// one division (the `% 3` of `next`/`prev` is the costly part of the flip loop).
#[derive(Clone, Copy)]
pub(crate) struct Corners {
    pub(crate) h: u32,
    pub(crate) base: u32,
    pub(crate) next: u32,
    pub(crate) prev: u32,
}

impl Corners {
    #[inline(always)]
    pub(crate) fn of(h: u32) -> Self {
        let base = 3 * (h / 3);
        let (next, prev) = match h - base {
            0 => (base + 1, base + 2),
            1 => (base + 2, base),
            _ => (base, base + 1),
        };
        Corners {
            h,
            base,
            next,
            prev,
        }
    }
}

#[cold]
fn unreachable_ghost() -> u32 {
    // A ghost triangle always has exactly one real edge; reaching here would be a bug in
    // the mesh updates, which the tests' validation would catch first.
    0
}
