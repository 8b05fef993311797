//! The book's DELAUNAYTRIANGULATION (§9.3) with the history DAG and the symbolic points of
//! §9.4.
//!
//! - p₀ is the lexicographically highest point (largest y, then largest x).
//! - p₋₁ and p₋₂ are never given coordinates. p₋₁ stands for a point on a horizontal line
//!   below P, so far to the right that the clockwise order of P around it is the
//!   lexicographic order; p₋₂ for a point on a horizontal line above P, so far to the left
//!   (farther than p₋₁ is to the right) that the counter-clockwise order of P around it is
//!   the lexicographic order. Every orientation involving them therefore reduces to a
//!   lexicographic comparison (see [`orient_symbolic`]): exact, no big coordinates.
//! - LEGALIZEEDGE uses the exact in-circle test when all four points are real and otherwise
//!   the book's rule: the edge `pᵢpⱼ` (between `pᵢpⱼpₖ` and `pᵢpⱼpₗ`) is legal iff
//!   `min(k, l) < min(i, j)` (indices −2, −1 for the symbolic points); edges of the initial
//!   triangle are always legal.
//! - Point location descends the history DAG D. Its leaves are the triangles of the
//!   current triangulation; every destroyed triangle is an inner node whose children are
//!   the triangles that replaced it. All children of a node share the new point q as a
//!   corner and fan around it, so "which child contains p" is decided by the side of p
//!   relative to rays from q: one ray for the two children of an edge split or a flip, two
//!   rays for the three children of a face split. The DAG is stored as those ray tests
//!   ([`Ray`]: q, the ray's far end, and two successors), with the coordinates copied into
//!   the node so that a descent reads one 40-byte record per step and never the point
//!   array; a face split is three ray nodes (first ray, then one of two), a flip one ray
//!   node shared by both destroyed triangles (they have the same two children).
//! - A descent is a chain of dependent loads and tests, so its latency, not its
//!   instruction count, is the cost: each step evaluates a node and both children at once
//!   (two levels), and points are located in pairs by one interleaved descent, the second
//!   finishing its descent after the first is inserted (see [`insert_all`]). Neither
//!   changes the DAG, which is exactly that of one insertion at a time.
//!
//! # Exactness of the descent
//!
//! A ray test is `orient(q, x, p)`. With a symbolic `x` it is the lexicographic rule (the
//! node stores `x` as NaN, so no arithmetic path can mistake it for a real point). With
//! real points it is the `f64` determinant with Shewchuk's static error bound
//! ([`pred::orient_filter`](super::pred::orient_filter)), the exact predicate when the
//! bound cannot decide, and, when the whole input is a
//! [`small_integer_grid`](super::pred::small_integer_grid), the unfiltered determinant,
//! which is then exact. Every answer is the exact sign, so the descent is exact.
//!
//! # Storage
//!
//! The current triangulation is a half-edge mesh in which a destroyed triangle's slot is
//! reused by one of its successors (so it holds ~2n triangles, not all ~9n ever created);
//! `up[t]` records which DAG successor entries point at leaf `t` (two for the third child
//! of a face split), to be redirected when `t` is destroyed. Points are copied in
//! insertion order (−0.0 made +0.0), so the points near in time are near in memory. About
//! 4–6n ray nodes (40 bytes each; 3.9n on a grid, 6.0n on uniform points) and 2n mesh
//! triangles (32 bytes each), against the ~9n 36-byte nodes of a DAG of all triangles.
//!
//! Expected O(n log n) time and O(n) space for a random insertion order. By default the
//! order is a biased randomized insertion order (`brio`), which keeps that bound (Amenta,
//! Choi & Rote 2003) and is much faster on large inputs (4–5× at 1e6 points) because
//! consecutive points follow nearby DAG paths; [`InsertionOrder::Uniform`] gives the
//! book's uniform random permutation. Both use a fixed seed, so runs are reproducible.
//! Duplicates are merged during insertion: a copy of a vertex is located on two edges of
//! a triangle, i.e. at their common corner, and changes nothing (no separate sorting pass);
//! every vertex then stands for the smallest input index among its copies. Collinear input
//! (checked first) gives no triangles.

use super::fast::{dedup, hilbert_order};
use super::mesh::{next, prev, NONE};
use super::pred::{
    in_circle, in_circle_grid, orient, orient_filter, orient_grid, small_integer_grid,
};
use super::triangulation::{Triangulation, NO_NEIGHBOR};
use super::InsertionOrder;
use crate::Point2;
use std::cmp::Ordering;

/// Symbolic p₋₁.
const M1: u32 = u32::MAX - 1;
/// Symbolic p₋₂.
const M2: u32 = u32::MAX - 2;

/// Lexicographic order of the book: by y, then by x. (The points are normalized so that
/// no coordinate is −0.0, which `total_cmp` would order before +0.0.)
fn lex(a: Point2, b: Point2) -> Ordering {
    a.y.total_cmp(&b.y).then(a.x.total_cmp(&b.x))
}

/// orient(s, i, j) for a symbolic `s` (p₋₁ or p₋₂) and real points `pi`, `pj` (module docs).
fn orient_symbolic(s: u32, pi: Point2, pj: Point2) -> i8 {
    let s_sign = if s == M1 { -1 } else { 1 };
    match lex(pj, pi) {
        Ordering::Greater => s_sign,
        Ordering::Less => -s_sign,
        Ordering::Equal => 0,
    }
}

/// The stand-in coordinates of a symbolic point in a [`Ray`]: x is NaN (every arithmetic
/// test on it fails and is sent to the symbolic rule), y names the point.
fn symbolic_coords(s: u32) -> Point2 {
    Point2::new(f64::NAN, if s == M1 { -1.0 } else { -2.0 })
}

/// One ray test of the history DAG: p goes to `next[1]` when it is strictly to the left of
/// the ray q → x, else to `next[0]`. Successors are [`Ray`] indices or `LEAF | triangle`.
#[derive(Clone, Copy)]
struct Ray {
    q: Point2,
    x: Point2,
    next: [u32; 2],
}

/// Marks a successor that is a leaf (a current triangle) rather than a ray node.
const LEAF: u32 = 1 << 31;
/// `up` of the initial triangle: the DAG root itself (distinct from `NONE`).
const ROOT: u32 = u32::MAX - 1;

/// Sign of orient(q, x, p) for real `q`, `p` and a real or symbolic (NaN-coded) `x`;
/// `G`: all points form a small integer grid. Exact.
#[inline(always)]
fn ray_side<const G: bool>(q: Point2, x: Point2, p: Point2) -> i8 {
    if x.x.is_nan() {
        return ray_side_symbolic(q, x, p);
    }
    if G {
        orient_grid(q, x, p)
    } else {
        match orient_filter(q, x, p) {
            Some(s) => s,
            None => orient(q, x, p),
        }
    }
}

#[cold]
#[inline(never)]
fn ray_side_symbolic(q: Point2, x: Point2, p: Point2) -> i8 {
    // orient(q, s, p) = orient(s, p, q) (cyclic).
    let s = if x.y == -1.0 { M1 } else { M2 };
    orient_symbolic(s, p, q)
}

struct Dag {
    /// The points in insertion order (local ids), p₀ first.
    pts: Vec<Point2>,
    /// Current triangles: half-edge `h` of triangle `h / 3` runs from `v[h]` to the next
    /// corner; `twin[h]` is the opposite half-edge or `NONE` on the initial triangle.
    v: Vec<u32>,
    twin: Vec<u32>,
    /// For each current triangle, the successor entries that name it (`2r + k` for
    /// `rays[r].next[k]`, or `ROOT`; the second is `NONE` unless the triangle is the
    /// third child of a face split, which two ray nodes lead to).
    up: Vec<[u32; 2]>,
    rays: Vec<Ray>,
    root: u32,
    stack: Vec<u32>,
}

/// The book's index of a vertex for the legality rule: −2, −1, or ≥ 0.
fn book_index(v: u32) -> i64 {
    match v {
        M1 => -1,
        M2 => -2,
        _ => i64::from(v),
    }
}

fn real(v: u32) -> bool {
    v < M2
}

impl Dag {
    fn p(&self, v: u32) -> Point2 {
        self.pts[v as usize]
    }

    fn coords(&self, v: u32) -> Point2 {
        if real(v) {
            self.p(v)
        } else {
            symbolic_coords(v)
        }
    }

    /// Exact orientation with the symbolic points (see the module docs): > 0 ccw.
    #[inline]
    fn orient_sym<const G: bool>(&self, a: u32, b: u32, c: u32) -> i8 {
        if real(a) && real(b) && real(c) {
            let (pa, pb, pc) = (self.p(a), self.p(b), self.p(c));
            return if G {
                orient_grid(pa, pb, pc)
            } else {
                orient(pa, pb, pc)
            };
        }
        self.orient_sym_slow(a, b, c)
    }

    #[cold]
    fn orient_sym_slow(&self, a: u32, b: u32, c: u32) -> i8 {
        match (real(a), real(b), real(c)) {
            (true, true, true) => orient(self.p(a), self.p(b), self.p(c)),
            (false, true, true) => orient_symbolic(a, self.p(b), self.p(c)),
            (true, false, true) => orient_symbolic(b, self.p(c), self.p(a)),
            (true, true, false) => orient_symbolic(c, self.p(a), self.p(b)),
            // Two symbolic points: (p₋₂, p₋₁, p) is counter-clockwise for every real p.
            _ => {
                let cyc = [a, b, c];
                let k = (0..3).find(|&k| cyc[k] == M2).unwrap_or(0);
                if cyc[(k + 1) % 3] == M1 {
                    1
                } else {
                    -1
                }
            }
        }
    }

    /// A new current triangle `(a, b, c)` in slot `t` (a new slot if `t == NONE`), named by
    /// successor entry `up`; twins unset. Returns the slot.
    fn put(&mut self, t: u32, [a, b, c]: [u32; 3], up: [u32; 2]) -> u32 {
        if t == NONE {
            let s = self.up.len() as u32;
            self.v.extend_from_slice(&[a, b, c]);
            self.twin.extend_from_slice(&[NONE; 3]);
            self.up.push(up);
            s
        } else {
            let i = 3 * t as usize;
            self.v[i..i + 3].copy_from_slice(&[a, b, c]);
            self.up[t as usize] = up;
            t
        }
    }

    fn link(&mut self, h: u32, g: u32) {
        self.twin[h as usize] = g;
        if g != NONE {
            self.twin[g as usize] = h;
        }
    }

    /// Points every successor entry naming the current triangle `t` (about to be
    /// destroyed) to ray node `to`.
    fn redirect(&mut self, t: u32, to: u32) {
        for at in self.up[t as usize] {
            if at == ROOT {
                self.root = to;
            } else if at != NONE {
                self.rays[(at / 2) as usize].next[(at % 2) as usize] = to;
            }
        }
    }

    /// A ray node from `q` towards vertex `x`; successors set by the caller.
    fn ray(&mut self, q: u32, x: u32) -> u32 {
        let r = self.rays.len() as u32;
        self.rays.push(Ray {
            q: self.p(q),
            x: self.coords(x),
            next: [NONE; 2],
        });
        r
    }

    /// One step of a descent from inner node `r` towards point `p`: returns the successor
    /// reached and the entry (`2r + k`) that names it.
    ///
    /// A descent is a chain of dependent loads and tests, so a step takes two levels: the
    /// node's test and both of its children's tests are independent and overlap, and only
    /// the chosen grandchild is followed. (The unused child's test is a wasted but
    /// harmless orientation.) Steps next to the leaves take one level.
    #[inline(always)]
    fn step<const G: bool>(&self, p: Point2, r: u32) -> (u32, u32) {
        let rays = &self.rays[..];
        let n = &rays[r as usize];
        let [c0, c1] = n.next;
        if (c0 | c1) & LEAF != 0 {
            let k = u32::from(ray_side::<G>(n.q, n.x, p) > 0);
            return (n.next[k as usize], 2 * r + k);
        }
        let (a, b) = (&rays[c0 as usize], &rays[c1 as usize]);
        let s = ray_side::<G>(n.q, n.x, p) > 0;
        let ka = u32::from(ray_side::<G>(a.q, a.x, p) > 0);
        let kb = u32::from(ray_side::<G>(b.q, b.x, p) > 0);
        if s {
            (b.next[kb as usize], 2 * c1 + kb)
        } else {
            (a.next[ka as usize], 2 * c0 + ka)
        }
    }

    /// The successor named by entry `at` (`2r + k`, or `ROOT`).
    fn entry(&self, at: u32) -> u32 {
        if at == ROOT {
            self.root
        } else {
            self.rays[(at / 2) as usize].next[(at % 2) as usize]
        }
    }

    /// Descends the history DAG from entry `at` to the current triangle containing point
    /// `p` (closed). `at` may come from an earlier descent of `p` in a smaller DAG: the
    /// region an entry names never changes (a destroyed leaf's entries are redirected to
    /// the nodes that partition it), so the descent just continues from there.
    fn locate_from<const G: bool>(&self, p: Point2, at: u32) -> u32 {
        let mut r = self.entry(at);
        while r & LEAF == 0 {
            r = self.step::<G>(p, r).0;
        }
        r & !LEAF
    }

    /// Descends for two points at once, alternating their steps so that the two chains of
    /// dependent loads overlap; returns the entries naming the leaves they reach.
    fn locate2<const G: bool>(&self, p: Point2, q: Point2) -> (u32, u32) {
        let (mut r, mut at_r) = (self.root, ROOT);
        let (mut s, mut at_s) = (self.root, ROOT);
        while r & LEAF == 0 && s & LEAF == 0 {
            (r, at_r) = self.step::<G>(p, r);
            (s, at_s) = self.step::<G>(q, s);
        }
        while r & LEAF == 0 {
            (r, at_r) = self.step::<G>(p, r);
        }
        while s & LEAF == 0 {
            (s, at_s) = self.step::<G>(q, s);
        }
        (at_r, at_s)
    }

    /// Inserts point `p`, located from entry `at` on; returns `NONE`, or the vertex `p`
    /// is equal to (then nothing changes: duplicates are merged here, where the location
    /// finds them anyway).
    fn insert<const G: bool>(&mut self, p: u32, at: u32) -> u32 {
        let t = self.locate_from::<G>(self.p(p), at);
        // The zero mask of p against the edges of t.
        let mut mask = 0u32;
        for k in 0..3 {
            let h = 3 * t as usize + k;
            let b = self.v[3 * t as usize + (k + 1) % 3];
            if self.orient_sym::<G>(self.v[h], b, p) == 0 {
                mask |= 1 << k;
            }
        }
        match mask {
            0 => self.split_face(t, p),
            1 | 2 | 4 => self.split_edge(3 * t + mask.trailing_zeros(), p),
            // On two edges: p is their common corner (edge k runs from corner k to k + 1).
            3 => return self.v[3 * t as usize + 1],
            6 => return self.v[3 * t as usize + 2],
            _ => return self.v[3 * t as usize],
        }
        while let Some(h) = self.stack.pop() {
            self.legalize::<G>(h);
        }
        NONE
    }

    /// p strictly inside triangle t = (a, b, c): children (a, b, p), (b, c, p), (c, a, p),
    /// which fan counter-clockwise around p. The ray p → b comes first: right of it (or on
    /// it) lie (a, b, p) and part of (c, a, p), told apart by the ray p → a; left of it
    /// (b, c, p) and the rest of (c, a, p), told apart by p → c. A point on the line of
    /// p → a in the first case is on that ray itself (its backward extension runs inside
    /// (b, c, p), left of p → b), so either side is a closed child containing it; likewise
    /// for p → c.
    fn split_face(&mut self, t: u32, p: u32) {
        let i = 3 * t as usize;
        let [a, b, c] = [self.v[i], self.v[i + 1], self.v[i + 2]];
        let [ta, tb, tc] = [self.twin[i], self.twin[i + 1], self.twin[i + 2]];
        let (r0, r1, r2) = (self.ray(p, b), self.ray(p, a), self.ray(p, c));
        self.redirect(t, r0);
        let t0 = self.put(t, [a, b, p], [2 * r1 + 1, NONE]);
        let t1 = self.put(NONE, [b, c, p], [2 * r2, NONE]);
        let t2 = self.put(NONE, [c, a, p], [2 * r1, 2 * r2 + 1]);
        self.rays[r0 as usize].next = [r1, r2];
        self.rays[r1 as usize].next = [LEAF | t2, LEAF | t0];
        self.rays[r2 as usize].next = [LEAF | t1, LEAF | t2];
        self.link(3 * t0, ta);
        self.link(3 * t1, tb);
        self.link(3 * t2, tc);
        self.link(3 * t0 + 1, 3 * t1 + 2);
        self.link(3 * t1 + 1, 3 * t2 + 2);
        self.link(3 * t2 + 1, 3 * t0 + 2);
        self.stack.extend_from_slice(&[3 * t0, 3 * t1, 3 * t2]);
    }

    /// p in the relative interior of the edge `h` = a → b of t = (a, b, c), whose twin
    /// (if any) is in (b, a, d): t becomes (b, c, p), (c, a, p), split by the ray p → c;
    /// (b, a, d) becomes (a, d, p), (d, b, p), split by p → d.
    fn split_edge(&mut self, h: u32, p: u32) {
        let t = h / 3;
        let f = self.twin[h as usize];
        let (a, b, c) = (
            self.v[h as usize],
            self.v[next(h) as usize],
            self.v[prev(h) as usize],
        );
        let tw_bc = self.twin[next(h) as usize];
        let tw_ca = self.twin[prev(h) as usize];
        let r = self.ray(p, c);
        self.redirect(t, r);
        let t0 = self.put(t, [b, c, p], [2 * r, NONE]);
        let t1 = self.put(NONE, [c, a, p], [2 * r + 1, NONE]);
        self.rays[r as usize].next = [LEAF | t0, LEAF | t1];
        self.link(3 * t0, tw_bc);
        self.link(3 * t1, tw_ca);
        self.link(3 * t0 + 1, 3 * t1 + 2);
        self.twin[3 * t0 as usize + 2] = NONE;
        self.twin[3 * t1 as usize + 1] = NONE;
        self.stack.extend_from_slice(&[3 * t0, 3 * t1]);
        if f == NONE {
            // p on an edge of the initial triangle cannot happen (those edges have a
            // symbolic endpoint, so no real point is on them); kept total for safety.
            return;
        }
        let g = f / 3;
        let d = self.v[prev(f) as usize];
        let tw_ad = self.twin[next(f) as usize];
        let tw_db = self.twin[prev(f) as usize];
        let r = self.ray(p, d);
        self.redirect(g, r);
        let t2 = self.put(g, [a, d, p], [2 * r, NONE]);
        let t3 = self.put(NONE, [d, b, p], [2 * r + 1, NONE]);
        self.rays[r as usize].next = [LEAF | t2, LEAF | t3];
        self.link(3 * t2, tw_ad);
        self.link(3 * t3, tw_db);
        self.link(3 * t1 + 1, 3 * t2 + 2);
        self.link(3 * t2 + 1, 3 * t3 + 2);
        self.link(3 * t3 + 1, 3 * t0 + 2);
        self.stack.extend_from_slice(&[3 * t2, 3 * t3]);
    }

    /// LEGALIZEEDGE(p, a → b) for the half-edge `h` = 3t (a → b) of a triangle t = (a, b, p)
    /// made by the insertion of p.
    fn legalize<const G: bool>(&mut self, h: u32) {
        let f = self.twin[h as usize];
        if f == NONE {
            return;
        }
        let t = h / 3;
        let g = f / 3;
        let a = self.v[h as usize];
        let b = self.v[h as usize + 1];
        let p = self.v[h as usize + 2];
        let d = self.v[prev(f) as usize];
        if real(a) && real(b) && real(p) && real(d) {
            let q = [b, a, d, p].map(|x| self.p(x));
            let inside = if G {
                in_circle_grid(q[0], q[1], q[2], q[3])
            } else {
                in_circle(q[0], q[1], q[2], q[3])
            };
            // A real d strictly inside the circle through b, a, p (and across a b from p)
            // makes the quadrilateral a d b p strictly convex: the segment p d runs inside
            // the open disc, so it leaves p's side through the open chord a b. So the flip
            // below keeps both triangles counter-clockwise; no orientation test is needed.
            if inside <= 0 {
                return;
            }
        } else {
            if !real(a) && !real(b) {
                return;
            }
            let kl = book_index(p).min(book_index(d));
            let ij = book_index(a).min(book_index(b));
            // The flip must keep both triangles counter-clockwise (the book shows it does
            // for an illegal edge; checked exactly so that no inverted triangle can appear).
            if kl < ij || self.orient_sym::<G>(p, a, d) <= 0 || self.orient_sym::<G>(p, d, b) <= 0 {
                return;
            }
        }
        let tw_pa = self.twin[h as usize + 2];
        let tw_bp = self.twin[h as usize + 1];
        let tw_ad = self.twin[next(f) as usize];
        let tw_db = self.twin[prev(f) as usize];
        // Both destroyed triangles get the same two children, split by the ray p → d.
        let r = self.ray(p, d);
        self.redirect(t, r);
        self.redirect(g, r);
        let t0 = self.put(t, [a, d, p], [2 * r, NONE]);
        let t1 = self.put(g, [d, b, p], [2 * r + 1, NONE]);
        self.rays[r as usize].next = [LEAF | t0, LEAF | t1];
        self.link(3 * t0, tw_ad);
        self.link(3 * t0 + 1, 3 * t1 + 2);
        self.link(3 * t0 + 2, tw_pa);
        self.link(3 * t1, tw_db);
        self.link(3 * t1 + 1, tw_bp);
        self.stack.push(3 * t0);
        self.stack.push(3 * t1);
    }
}

/// A fixed-seed SplitMix64 generator for the random insertion order.
struct SplitMix(u64);

impl SplitMix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
}

/// Inserts points 1, 2, … in order, recording repeated points in `copies`. Points are
/// located in pairs by one interleaved descent of the same DAG; the second of a pair then
/// finishes its descent after the first is inserted (usually a few steps, as the first
/// insertion changed only the triangles near it). The insertions, and so the DAG, are
/// those of one point at a time.
fn insert_all<const G: bool>(dag: &mut Dag, copies: &mut Vec<(u32, u32)>) {
    let m = dag.pts.len() as u32;
    let mut p = 1;
    while p < m {
        let (at_p, at_q) = if p + 1 < m {
            dag.locate2::<G>(dag.p(p), dag.p(p + 1))
        } else {
            (ROOT, ROOT)
        };
        for (k, at) in [(p, at_p), (p + 1, at_q)] {
            if k < m {
                let v = dag.insert::<G>(k, at);
                if v != NONE {
                    copies.push((k, v));
                }
            }
        }
        p += 2;
    }
}

/// Triangulates finite `pts` (fewer than `u32::MAX - 2`) by the book's algorithm.
pub(crate) fn triangulate(pts: &[Point2], insertion: InsertionOrder) -> Triangulation {
    let n = pts.len();
    // Adding +0.0 turns −0.0 into +0.0 (and changes nothing else), so that `lex` orders
    // equal coordinates as equal.
    let norm = |i: u32| {
        let p = pts[i as usize];
        Point2::new(p.x + 0.0, p.y + 0.0)
    };
    // p0: the lexicographically highest point.
    let Some(k0) = (0..n as u32).max_by(|&i, &j| lex(norm(i), norm(j))) else {
        return Triangulation::from_triangles(pts, &[], &[]);
    };
    let a = pts[k0 as usize];
    let collinear = match pts.iter().find(|&&p| p != a) {
        None => true,
        Some(&b) => pts.iter().all(|&p| orient(a, b, p) == 0),
    };
    if collinear {
        return Triangulation::from_triangles(pts, &[], &dedup(pts));
    }
    // Local ids: 0 is p0, then the insertion order.
    let mut order = vec![k0];
    let rest: Vec<u32> = (0..n as u32).filter(|&i| i != k0).collect();
    order.extend(match insertion {
        InsertionOrder::Biased => brio(pts, rest),
        InsertionOrder::Uniform => shuffled(rest),
    });
    let m = order.len();
    let mut dag = Dag {
        pts: order.iter().map(|&i| norm(i)).collect(),
        v: Vec::with_capacity(6 * m),
        twin: Vec::with_capacity(6 * m),
        up: Vec::with_capacity(2 * m),
        rays: Vec::with_capacity(7 * m),
        root: LEAF,
        stack: Vec::new(),
    };
    dag.put(NONE, [0, M2, M1], [ROOT, NONE]);
    // (local id, the vertex it equals) for every repeated point.
    let mut copies: Vec<(u32, u32)> = Vec::new();
    if small_integer_grid(&dag.pts) {
        insert_all::<true>(&mut dag, &mut copies);
    } else {
        insert_all::<false>(&mut dag, &mut copies);
    }
    // Every vertex stands for the smallest input index among its copies (first seen).
    let mut first: Vec<u32> = order.clone();
    for &(p, v) in &copies {
        first[v as usize] = first[v as usize].min(order[p as usize]);
    }
    let mut rep = vec![0u32; n];
    for (l, &i) in order.iter().enumerate() {
        rep[i as usize] = first[l];
    }
    for &(p, v) in &copies {
        rep[order[p as usize] as usize] = first[v as usize];
    }
    // The current triangles with real corners are the result; their twins give the
    // neighbours directly (no edge matching).
    let slots = dag.up.len();
    let mut id = vec![NO_NEIGHBOR; slots];
    let mut tris: Vec<[u32; 3]> = Vec::with_capacity(2 * m);
    for (t, slot) in id.iter_mut().enumerate() {
        let c = [dag.v[3 * t], dag.v[3 * t + 1], dag.v[3 * t + 2]];
        if c.iter().all(|&v| real(v)) {
            *slot = tris.len() as u32;
            tris.push(c.map(|v| first[v as usize]));
        }
    }
    let mut nbs: Vec<[u32; 3]> = Vec::with_capacity(tris.len());
    for (t, &slot) in id.iter().enumerate() {
        if slot == NO_NEIGHBOR {
            continue;
        }
        // Neighbour opposite corner i = across half-edge i + 1.
        nbs.push([1, 2, 0].map(|k| {
            let g = dag.twin[3 * t + k];
            if g == NONE {
                NO_NEIGHBOR
            } else {
                id[(g / 3) as usize]
            }
        }));
    }
    Triangulation::from_triangles_and_neighbours(pts, tris, nbs, &rep)
}

/// A uniform random permutation of `ids` (Fisher–Yates, fixed seed): the book's order.
fn shuffled(mut ids: Vec<u32>) -> Vec<u32> {
    let mut rng = SplitMix(0x00C0_FFEE_D1CE_5EED);
    for i in (1..ids.len()).rev() {
        // Multiply-shift maps 64 random bits to 0..=i; its bias is below 2^-32 here.
        let j = ((u128::from(rng.next()) * (i as u128 + 1)) >> 64) as usize;
        ids.swap(i, j);
    }
    ids
}

/// A biased randomized insertion order (Amenta, Choi & Rote 2003): each point joins round
/// `k` with probability 2^-(k+1) (fixed seed); rounds run from the smallest to the largest,
/// each in Hilbert order. The insertion order stays random enough for the book's expected
/// O(n log n) analysis, and consecutive points are near each other, so the DAG paths they
/// follow share the cache.
fn brio(pts: &[Point2], ids: Vec<u32>) -> Vec<u32> {
    let mut rng = SplitMix(0x00C0_FFEE_D1CE_5EED);
    let rounds = (usize::BITS - ids.len().leading_zeros()).max(1);
    let mut by_round: Vec<Vec<u32>> = vec![Vec::new(); rounds as usize];
    for id in ids {
        let k = rng.next().trailing_zeros().min(rounds - 1);
        by_round[k as usize].push(id);
    }
    let mut out = Vec::new();
    for round in by_round.into_iter().rev() {
        let sub: Vec<Point2> = round.iter().map(|&i| pts[i as usize]).collect();
        out.extend(hilbert_order(&sub).into_iter().map(|k| round[k as usize]));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::delaunay::{delaunay, verify_delaunay};
    use crate::kernel::{orient2d, Orientation};
    use proptest::prelude::*;

    fn exact(a: Point2, b: Point2, c: Point2) -> i8 {
        match orient2d(a, b, c) {
            Orientation::CounterClockwise => 1,
            Orientation::Clockwise => -1,
            Orientation::Collinear => 0,
        }
    }

    /// The book variant, in both insertion orders, is Delaunay (exact verifier) and has the
    /// default's triangle count (unique even with cocircular points).
    fn check(pts: &[Point2]) -> Result<(), TestCaseError> {
        let fast = delaunay(pts).map_err(|e| TestCaseError::fail(e.to_string()))?;
        for order in [InsertionOrder::Biased, InsertionOrder::Uniform] {
            let book = triangulate(pts, order);
            prop_assert!(
                verify_delaunay(&book).is_ok(),
                "{:?} {:?}",
                order,
                verify_delaunay(&book)
            );
            prop_assert_eq!(book.triangles().len(), fast.triangles().len());
            prop_assert_eq!(book.input_to_vertex(), fast.input_to_vertex());
        }
        Ok(())
    }

    #[test]
    fn uniform_order_is_a_permutation() {
        let ids: Vec<u32> = (0..1000).collect();
        let mut order = shuffled(ids.clone());
        assert_ne!(order, ids, "the shuffle moved nothing");
        order.sort_unstable();
        assert_eq!(order, ids);
    }

    #[test]
    fn negative_zero_is_ordered_as_zero() {
        // (5, −0) and (3, +0) lie on one horizontal line: the symbolic rule must order them
        // by x, as `lex` does once −0.0 is normalized.
        let sets = [
            vec![(5.0, -0.0), (3.0, 0.0), (0.0, 1.0), (4.0, -1.0), (8.0, 0.0)],
            vec![
                (-0.0, 2.0),
                (0.0, -0.0),
                (1.0, -0.0),
                (-1.0, 0.0),
                (0.0, 1.0),
            ],
            vec![
                (-0.0, -0.0),
                (2.0, 0.0),
                (-2.0, -0.0),
                (0.0, 3.0),
                (0.0, -3.0),
            ],
        ];
        for s in sets {
            let pts: Vec<Point2> = s.into_iter().map(Point2::from).collect();
            check(&pts).unwrap();
        }
    }

    /// Real and symbolic vertex ids over a small point set, for the predicate tests.
    fn ids_and_points() -> impl Strategy<Value = (Vec<Point2>, [u32; 3])> {
        let scale = prop_oneof![
            Just((1.0, 0.0)),
            Just((1.0, 1e15)),
            Just((0.5, -3.0)),
            Just((2f64.powi(-40), 1.0)),
            Just((2f64.powi(-1000), 0.0)),
            Just((2f64.powi(900), 0.0)),
            Just((1e-3, 0.0)),
        ];
        (
            scale,
            prop::collection::vec((-3i32..4, -3i32..4, any::<bool>()), 3..7),
            prop::collection::vec(0u32..9, 3),
        )
            .prop_map(|((step, off), v, pick)| {
                let pts: Vec<Point2> = v
                    .iter()
                    .map(|&(x, y, nudge)| {
                        let px = off + f64::from(x) * step;
                        let py = off + f64::from(y) * step;
                        Point2::new(if nudge { px.next_up() } else { px }, py)
                    })
                    .collect();
                let n = pts.len() as u32;
                // Ids 0..n are real; 7 and 8 pick the symbolic points.
                let id = |k: u32| match k {
                    7 => M1,
                    8 => M2,
                    _ => k % n,
                };
                (pts, [id(pick[0]), id(pick[1]), id(pick[2])])
            })
    }

    fn dag(pts: &[Point2]) -> Dag {
        Dag {
            pts: pts
                .iter()
                .map(|p| Point2::new(p.x + 0.0, p.y + 0.0))
                .collect(),
            v: Vec::new(),
            twin: Vec::new(),
            up: Vec::new(),
            rays: Vec::new(),
            root: LEAF,
            stack: Vec::new(),
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]

        /// The descent's ray test (static filter, grid and NaN-coded symbolic paths) equals
        /// the general symbolic orientation on degenerate input: collinear and repeated
        /// points, equal x or y (ties of the lexicographic rule), ±1 ulp, tiny and huge
        /// dyadic grids, large offsets.
        #[test]
        fn ray_tests_equal_the_symbolic_orientation((pts, [q, x, p]) in ids_and_points()) {
            let d = dag(&pts);
            // The descent only tests real q and p.
            let (q, p) = (if real(q) { q } else { 0 }, if real(p) { p } else { 1 });
            let want = d.orient_sym_slow(q, x, p);
            let (cq, cx, cp) = (d.p(q), d.coords(x), d.p(p));
            prop_assert_eq!(ray_side::<false>(cq, cx, cp), want);
            if small_integer_grid(&d.pts) {
                prop_assert_eq!(ray_side::<true>(cq, cx, cp), want);
                prop_assert_eq!(d.orient_sym::<true>(q, x, p), want);
            }
            prop_assert_eq!(d.orient_sym::<false>(q, x, p), want);
            if real(x) {
                prop_assert_eq!(want, exact(cq, cx, cp));
                if let Some(s) = orient_filter(cq, cx, cp) {
                    prop_assert_eq!(s, want);
                }
            }
        }

        /// Whole triangulations on degenerate sets: small grids at several scales and
        /// offsets (integer, dyadic, beyond 2^53), with duplicates, collinear runs and
        /// points on common horizontal lines (the directions of p₋₁ and p₋₂).
        #[test]
        fn book_is_delaunay_on_degenerate_sets(
            v in prop::collection::vec((-4i32..5, -4i32..5), 0..45),
            scale in prop_oneof![
                Just((1.0, 0.0)),
                Just((1.0, 2f64.powi(60))),
                Just((0.25, 1e6)),
                Just((2f64.powi(-30), -0.0)),
                Just((2f64.powi(-1060), 0.0)),
                Just((1e250, 0.0)),
                Just((3.0, -4e15)),
            ],
        ) {
            let (step, off) = scale;
            let pts: Vec<Point2> = v
                .iter()
                .map(|&(x, y)| Point2::new(off + f64::from(x) * step, off + f64::from(y) * step))
                .collect();
            check(&pts)?;
        }

        /// Integer points on a circle with many lattice points (x² + y² = 5525), shifted,
        /// plus its centre and some duplicates: heavy cocircularity.
        #[test]
        fn book_is_delaunay_on_lattice_circles(
            pick in prop::collection::vec(0usize..64, 3..40),
            shift in prop_oneof![Just(0.0), Just(1e9), Just(-(2f64.powi(55)))],
            centre in any::<bool>(),
        ) {
            let mut on: Vec<(f64, f64)> = Vec::new();
            for x in -74i32..=74 {
                for y in -74i32..=74 {
                    if x * x + y * y == 5525 {
                        on.push((f64::from(x), f64::from(y)));
                    }
                }
            }
            let mut pts: Vec<Point2> = pick
                .iter()
                .map(|&k| {
                    let (x, y) = on[k % on.len()];
                    Point2::new(x + shift, y + shift)
                })
                .collect();
            if centre {
                pts.push(Point2::new(shift, shift));
            }
            check(&pts)?;
        }
    }

    #[test]
    fn larger_uniform_and_grid_inputs_verify() {
        let mut r = SplitMix(7);
        let u: Vec<Point2> = (0..3000)
            .map(|_| {
                let a = (r.next() >> 11) as f64 / (1u64 << 53) as f64;
                let b = (r.next() >> 11) as f64 / (1u64 << 53) as f64;
                Point2::new(a, b)
            })
            .collect();
        check(&u).unwrap();
        let g: Vec<Point2> = (0..60 * 60)
            .map(|i| Point2::new(f64::from(i % 60), f64::from(i / 60)))
            .collect();
        check(&g).unwrap();
    }
}
