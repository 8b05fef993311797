//! The book's DELAUNAYTRIANGULATION (§9.3) with the history DAG and the symbolic points of
//! §9.4.
//!
//! - p₀ is the lexicographically highest point (largest y, then largest x).
//! - p₋₁ and p₋₂ are never given coordinates. p₋₁ stands for a point on a horizontal line
//!   below P, so far to the right that the clockwise order of P around it is the
//!   lexicographic order; p₋₂ for a point on a horizontal line above P, so far to the left
//!   (farther than p₋₁ is to the right) that the counter-clockwise order of P around it is
//!   the lexicographic order. Every orientation involving them therefore reduces to a
//!   lexicographic comparison (see [`orient_sym`]): exact, no big coordinates.
//! - LEGALIZEEDGE uses the exact in-circle test when all four points are real and otherwise
//!   the book's rule: the edge `pᵢpⱼ` (between `pᵢpⱼpₖ` and `pᵢpⱼpₗ`) is legal iff
//!   `min(k, l) < min(i, j)` (indices −2, −1 for the symbolic points); edges of the initial
//!   triangle are always legal.
//! - Point location descends the history DAG: every triangle ever created is a node; a
//!   split or flip makes the new triangles children of the destroyed ones.
//!
//! Expected O(n log n) time and O(n) space for a random insertion order; the order is a
//! biased randomized insertion order (`brio`, fixed seed, so runs are reproducible). Duplicates are merged before insertion (by sorting);
//! collinear input gives no triangles.

use super::fast::{dedup, hilbert_order};
use super::mesh::{next, prev, Corners, NONE};
use super::pred::{in_circle, in_circle_grid, orient, orient_grid, small_integer_grid};
use super::triangulation::{Triangulation, NO_NEIGHBOR};
use crate::Point2;
use std::cmp::Ordering;

/// Symbolic p₋₁.
const M1: u32 = u32::MAX - 1;
/// Symbolic p₋₂.
const M2: u32 = u32::MAX - 2;

/// Lexicographic order of the book: by y, then by x.
fn lex(a: Point2, b: Point2) -> Ordering {
    a.y.total_cmp(&b.y).then(a.x.total_cmp(&b.x))
}

struct Dag<'a> {
    pts: &'a [Point2],
    v: Vec<u32>,
    twin: Vec<u32>,
    children: Vec<[u32; 3]>,
    stack: Vec<u32>,
    /// All points form a small integer grid: the unfiltered exact grid predicates apply
    /// (see `pred::small_integer_grid`).
    grid: bool,
}

/// The book's index of a vertex for the legality rule: −2, −1, or ≥ 0.
fn book_index(v: u32) -> i64 {
    match v {
        M1 => -1,
        M2 => -2,
        _ => i64::from(v),
    }
}

impl<'a> Dag<'a> {
    fn p(&self, v: u32) -> Point2 {
        self.pts[v as usize]
    }

    fn add(&mut self, a: u32, b: u32, c: u32) -> u32 {
        let t = self.children.len() as u32;
        self.v.extend_from_slice(&[a, b, c]);
        self.twin.extend_from_slice(&[NONE, NONE, NONE]);
        self.children.push([NONE; 3]);
        t
    }

    fn link(&mut self, h: u32, g: u32) {
        self.twin[h as usize] = g;
        if g != NONE {
            self.twin[g as usize] = h;
        }
    }

    /// Exact orientation with the symbolic points (see the module docs): > 0 ccw.
    #[inline]
    fn orient_sym(&self, a: u32, b: u32, c: u32) -> i8 {
        // M2 < M1 are the two largest ids below the unused u32::MAX: one comparison
        // each tells a real vertex from a symbolic one.
        if a < M2 && b < M2 && c < M2 {
            let (pa, pb, pc) = (self.p(a), self.p(b), self.p(c));
            return if self.grid {
                orient_grid(pa, pb, pc)
            } else {
                orient(pa, pb, pc)
            };
        }
        let sym = |v: u32| v == M1 || v == M2;
        match (sym(a), sym(b), sym(c)) {
            (false, false, false) => orient(self.p(a), self.p(b), self.p(c)),
            (true, false, false) => self.orient_one(a, b, c),
            (false, true, false) => self.orient_one(b, c, a),
            (false, false, true) => self.orient_one(c, a, b),
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

    /// orient(s, i, j) for symbolic `s` and real `i`, `j`.
    fn orient_one(&self, s: u32, i: u32, j: u32) -> i8 {
        let o = lex(self.p(j), self.p(i));
        let s_sign = if s == M1 { -1 } else { 1 };
        match o {
            Ordering::Greater => s_sign,
            Ordering::Less => -s_sign,
            Ordering::Equal => 0,
        }
    }

    /// Zero mask of `p` against the edges of node `t`, or `None` if `p` is outside it.
    fn test(&self, t: u32, p: u32) -> Option<u32> {
        let mut mask = 0;
        for k in 0..3 {
            let h = 3 * t + k;
            let s = self.orient_sym(self.v[h as usize], self.v[next(h) as usize], p);
            if s < 0 {
                return None;
            }
            if s == 0 {
                mask |= 1 << k;
            }
        }
        Some(mask)
    }

    /// Descends the history DAG to the leaf containing `p`; returns it with its zero mask.
    ///
    /// Every node's children form a fan around the point whose insertion destroyed it,
    /// stored as the last corner of each child, in counter-clockwise order: `(x₀, x₁, q)`,
    /// `(x₁, x₂, q)`, … (three children for a face split, two for an edge split or a flip).
    /// Since `p` lies in the (closed) parent, the child is decided by the side of `p`
    /// relative to the rays from `q` — one orientation for two children, two for three —
    /// instead of testing every edge of every child. The full zero mask is computed only at
    /// the leaf.
    fn locate(&self, p: u32) -> (u32, u32) {
        let mut t = 0u32;
        loop {
            let c = self.children[t as usize];
            if c[0] == NONE {
                break;
            }
            let q = self.v[3 * c[0] as usize + 2];
            let x1 = self.v[3 * c[0] as usize + 1];
            if c[2] == NONE {
                // Two wedges, each under a half-turn: the ray q -> x1 separates them.
                t = if self.orient_sym(q, x1, p) <= 0 {
                    c[0]
                } else {
                    c[1]
                };
                continue;
            }
            let s1 = self.orient_sym(q, x1, p);
            t = if s1 <= 0 {
                let x0 = self.v[3 * c[0] as usize];
                if self.orient_sym(q, x0, p) >= 0 {
                    c[0]
                } else {
                    c[2]
                }
            } else {
                let x2 = self.v[3 * c[1] as usize + 1];
                if self.orient_sym(q, x2, p) <= 0 {
                    c[1]
                } else {
                    c[2]
                }
            };
        }
        (t, self.test(t, p).unwrap_or(0))
    }

    fn insert(&mut self, p: u32) {
        let (t, mask) = self.locate(p);
        match mask.count_ones() {
            0 => self.split_face(t, p),
            1 => self.split_edge(3 * t + mask.trailing_zeros(), p),
            _ => return, // equal to a vertex: impossible after merging duplicates
        }
        while let Some(h) = self.stack.pop() {
            self.legalize(h);
        }
    }

    fn split_face(&mut self, t: u32, p: u32) {
        let i = 3 * t as usize;
        let (a, b, c) = (self.v[i], self.v[i + 1], self.v[i + 2]);
        let (ta, tb, tc) = (self.twin[i], self.twin[i + 1], self.twin[i + 2]);
        let t0 = self.add(a, b, p);
        let t1 = self.add(b, c, p);
        let t2 = self.add(c, a, p);
        self.children[t as usize] = [t0, t1, t2];
        self.link(3 * t0, ta);
        self.link(3 * t1, tb);
        self.link(3 * t2, tc);
        self.link(3 * t0 + 1, 3 * t1 + 2);
        self.link(3 * t1 + 1, 3 * t2 + 2);
        self.link(3 * t2 + 1, 3 * t0 + 2);
        self.stack.extend_from_slice(&[3 * t0, 3 * t1, 3 * t2]);
    }

    fn split_edge(&mut self, h: u32, p: u32) {
        let f = self.twin[h as usize];
        let a = self.v[h as usize];
        let b = self.v[next(h) as usize];
        let c = self.v[prev(h) as usize];
        let tw_bc = self.twin[next(h) as usize];
        let tw_ca = self.twin[prev(h) as usize];
        let t0 = self.add(b, c, p);
        let t1 = self.add(c, a, p);
        self.children[(h / 3) as usize] = [t0, t1, NONE];
        self.link(3 * t0, tw_bc);
        self.link(3 * t1, tw_ca);
        self.link(3 * t0 + 1, 3 * t1 + 2);
        self.stack.extend_from_slice(&[3 * t0, 3 * t1]);
        if f == NONE {
            // p on an edge of the initial triangle cannot happen (those edges have a
            // symbolic endpoint, so no real point is on them); kept total for safety.
            return;
        }
        let d = self.v[prev(f) as usize];
        let tw_ad = self.twin[next(f) as usize];
        let tw_db = self.twin[prev(f) as usize];
        let t2 = self.add(a, d, p);
        let t3 = self.add(d, b, p);
        self.children[(f / 3) as usize] = [t2, t3, NONE];
        self.link(3 * t2, tw_ad);
        self.link(3 * t3, tw_db);
        self.link(3 * t1 + 1, 3 * t2 + 2);
        self.link(3 * t2 + 1, 3 * t3 + 2);
        self.link(3 * t3 + 1, 3 * t0 + 2);
        self.stack.extend_from_slice(&[3 * t2, 3 * t3]);
    }

    /// LEGALIZEEDGE(p, a→b) where `p` is opposite half-edge `h`.
    fn legalize(&mut self, h: u32) {
        let f = self.twin[h as usize];
        if f == NONE {
            return;
        }
        let (e, g) = (Corners::of(h), Corners::of(f));
        let a = self.v[h as usize];
        let b = self.v[e.next as usize];
        let p = self.v[e.prev as usize];
        let d = self.v[g.prev as usize];
        let real = |v: u32| v < M2;
        let illegal = if real(a) && real(b) && real(p) && real(d) {
            let q = [b, a, d, p].map(|x| self.p(x));
            if self.grid {
                in_circle_grid(q[0], q[1], q[2], q[3]) > 0
            } else {
                in_circle(q[0], q[1], q[2], q[3]) > 0
            }
        } else if !real(a) && !real(b) {
            false
        } else {
            let kl = book_index(p).min(book_index(d));
            let ij = book_index(a).min(book_index(b));
            kl >= ij
        };
        // The flip must keep both triangles counter-clockwise (the book shows it does for
        // an illegal edge; checked exactly so that no inverted triangle can ever appear).
        if !illegal || self.orient_sym(p, a, d) <= 0 || self.orient_sym(p, d, b) <= 0 {
            return;
        }
        let tw_pa = self.twin[e.prev as usize];
        let tw_bp = self.twin[e.next as usize];
        let tw_ad = self.twin[g.next as usize];
        let tw_db = self.twin[g.prev as usize];
        // The new point last in both children (see `locate`).
        let t0 = self.add(a, d, p);
        let t1 = self.add(d, b, p);
        self.children[(e.base / 3) as usize] = [t0, t1, NONE];
        self.children[(g.base / 3) as usize] = [t0, t1, NONE];
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

/// Triangulates finite `pts` (fewer than `u32::MAX - 2`) by the book's algorithm.
pub(crate) fn triangulate(pts: &[Point2]) -> Triangulation {
    let n = pts.len();
    let rep = dedup(pts);
    let mut distinct: Vec<u32> = (0..n as u32).filter(|&i| rep[i as usize] == i).collect();
    let collinear = distinct.len() < 3 || {
        let (a, b) = (pts[distinct[0] as usize], pts[distinct[1] as usize]);
        distinct[2..]
            .iter()
            .all(|&i| orient(a, b, pts[i as usize]) == 0)
    };
    if collinear {
        return Triangulation::from_triangles(pts, &[], &rep);
    }
    // p0: the lexicographically highest point.
    let k0 = (0..distinct.len())
        .max_by(|&i, &j| lex(pts[distinct[i] as usize], pts[distinct[j] as usize]))
        .unwrap_or(0);
    let p0 = distinct.swap_remove(k0);
    let distinct = brio(pts, distinct);
    let mut dag = Dag {
        pts,
        v: Vec::with_capacity(27 * n),
        twin: Vec::with_capacity(27 * n),
        children: Vec::with_capacity(9 * n),
        stack: Vec::new(),
        grid: small_integer_grid(pts),
    };
    dag.add(p0, M2, M1);
    for &p in &distinct {
        dag.insert(p);
    }
    // The leaves with real corners are the triangles; their twins give the neighbours
    // directly (no edge matching).
    let nodes = dag.children.len();
    let mut id = vec![NO_NEIGHBOR; nodes];
    let mut tris: Vec<[u32; 3]> = Vec::with_capacity(2 * n);
    for (t, slot) in id.iter_mut().enumerate() {
        let c = [dag.v[3 * t], dag.v[3 * t + 1], dag.v[3 * t + 2]];
        if dag.children[t][0] == NONE && c.iter().all(|&v| v < M2) {
            *slot = tris.len() as u32;
            tris.push(c);
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
