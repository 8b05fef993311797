//! The constraint engine shared by the constrained Delaunay triangulation and refinement:
//! a [`Mesh`] with a set of constrained edges, Steiner-point insertion that respects the
//! constraints, and constraint insertion by Sloan's flips that splits at vertices on the
//! segment and at crossings with earlier constraints.
//!
//! # Crossing constraints
//!
//! Constraints that properly cross are snap-rounded before they are inserted (see
//! `snap.rs`): each becomes a chain of pieces through the rounded crossings whose rounding
//! cell it meets, and those chains do not cross. The engine still handles a crossing it
//! meets (`Walk::Blocked`; the first pass of `cdt.rs` stops there instead): the pieces
//! are made to meet at a vertex (see `Constrained::meeting_vertex`) — an end of one piece
//! whose rounding cell the other's input segment meets, or else the crossing of the input
//! segments (or of the pieces) rounded to `f64` — and both are split there; if a bent
//! piece then crosses a third constraint, that crossing is split the same way (the number
//! of such splits is bounded, else `Err`). A bent piece is also routed through every
//! vertex alongside it whose rounding cell its input segment meets: otherwise pieces meet
//! at angles of ~10⁻¹⁶ that Delaunay refinement splits without end. So every vertex of a
//! constraint's chain lies on its input segment or within half an ulp of it per
//! coordinate. The result is the exact constrained Delaunay triangulation of the vertices
//! (inputs and Steiner points) and the pieces: every piece is an edge and every other edge
//! is locally Delaunay by the exact in-circle test.
//!
//! Collinear overlapping constraints merge: a constraint is split at every vertex lying on
//! it (found exactly by the walk), so the overlap becomes shared pieces.

use super::mesh::{next, prev, Found, Mesh, GHOST};
use super::pred::{dot_sign, in_circle, orient, segment_meets_cell};
use crate::kernel::Crossing;
use crate::{Error, Point2, Result, Segment2};
use std::collections::{HashMap, VecDeque};
use std::hash::{BuildHasherDefault, Hasher};

/// The unordered key of an edge.
pub(crate) fn key(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

/// A fast hasher for edge keys (pairs of `u32` vertex ids; no adversary chooses them):
/// multiply–rotate mixing as in rustc's FxHash. The default SipHash was a tenth of the
/// constrained triangulation's time.
#[derive(Default, Clone, Copy)]
pub(crate) struct EdgeHasher(u64);

impl Hasher for EdgeHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }
    fn write_u32(&mut self, x: u32) {
        self.write_u64(u64::from(x));
    }
    fn write_u64(&mut self, x: u64) {
        self.0 = (self.0.rotate_left(5) ^ x).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
}

/// The map of constrained edges.
pub(crate) type EdgeMap = HashMap<(u32, u32), u32, BuildHasherDefault<EdgeHasher>>;

/// A mesh with constrained edges (`fixed`: piece → id of the constraint it comes from).
pub(crate) struct Constrained<'a> {
    pub(crate) mesh: Mesh<'a>,
    pub(crate) fixed: EdgeMap,
    /// Triangles changed since the mesh was last known to be constrained Delaunay (by
    /// Sloan's flips and by Steiner points): [`Constrained::restore_dirty`] starts there.
    dirty: Vec<u32>,
    /// One half-edge leaving each vertex (kept valid through every change).
    vmap: Vec<u32>,
    /// Edges to a ghost vertex are constrained too (a domain with holes: never grow it).
    ghost_fixed: bool,
    /// Crossing splits still allowed (a guard against an endless cascade).
    pub(crate) crossing_budget: usize,
    /// The input segment of each constraint id (its ends when first inserted): a piece
    /// bent through a rounded crossing is still split at the vertices on this segment.
    origin: HashMap<u32, (Point2, Point2), BuildHasherDefault<EdgeHasher>>,
    /// Whether a proper crossing of two constraints ends the insertion (with an `Err`,
    /// and `met_crossing` set) instead of being split: the constrained Delaunay
    /// triangulation then starts again with snap-rounded constraints.
    pub(crate) stop_at_crossing: bool,
    pub(crate) met_crossing: bool,
}

/// What the walk from `a` towards `b` found.
enum Walk {
    /// `a–b` is already an edge.
    Edge,
    /// Vertex `c` lies on the open segment `a–b`.
    Split(u32),
    /// The segment properly crosses the constrained edge `u–w` (the first one from `a`).
    Blocked(u32, u32),
    /// The (unconstrained) edges crossed, as vertex pairs, in order from `a`.
    Crossed(Vec<(u32, u32)>),
}

impl<'a> Constrained<'a> {
    pub(crate) fn new(mesh: Mesh<'a>, ghost_fixed: bool) -> Self {
        let mut vmap = vec![u32::MAX; mesh.pts.len()];
        for (h, &v) in mesh.v.iter().enumerate() {
            if v != GHOST {
                vmap[v as usize] = h as u32;
            }
        }
        Constrained {
            mesh,
            fixed: EdgeMap::default(),
            dirty: Vec::new(),
            vmap,
            ghost_fixed,
            crossing_budget: 0,
            origin: HashMap::default(),
            stop_at_crossing: false,
            met_crossing: false,
        }
    }

    /// Is the edge `a–b` constrained (edges to the ghost vertex count when `ghost_fixed`)?
    pub(crate) fn is_fixed(&self, a: u32, b: u32) -> bool {
        if a == GHOST || b == GHOST {
            return self.ghost_fixed;
        }
        self.fixed.contains_key(&key(a, b))
    }

    /// Every half-edge leaving `a` (ghost triangles included), by rotation: O(degree).
    pub(crate) fn out_edges(&self, a: u32) -> Vec<u32> {
        self.out_iter(a).collect()
    }

    /// [`Constrained::out_edges`] without collecting them.
    fn out_iter(&self, a: u32) -> impl Iterator<Item = u32> + '_ {
        let m = &self.mesh;
        let start = self.vmap[a as usize];
        let mut h = start;
        let mut count = 0usize;
        std::iter::from_fn(move || {
            // Stop after a full turn (or, never expected, after more steps than edges).
            if count > 0 && (h == start || count > m.v.len()) {
                return None;
            }
            let out = h;
            count += 1;
            h = m.twin[prev(h) as usize];
            Some(out)
        })
    }

    /// The half-edge `u → w`, if it is an edge.
    pub(crate) fn find(&self, u: u32, w: u32) -> Option<u32> {
        self.out_iter(u)
            .find(|&h| self.mesh.v[next(h) as usize] == w)
    }

    fn touch(&mut self, t: u32) {
        for h in [3 * t, 3 * t + 1, 3 * t + 2] {
            let v = self.mesh.v[h as usize];
            if v != GHOST {
                self.vmap[v as usize] = h;
            }
        }
    }

    /// Flips half-edge `e` and keeps the vertex map valid.
    pub(crate) fn flip(&mut self, e: u32) {
        let f = self.mesh.twin[e as usize];
        self.mesh.flip(e);
        self.touch(e / 3);
        self.touch(f / 3);
    }

    /// Inserts the point `p` (or finds the vertex equal to it) keeping every constraint:
    /// a constrained edge through `p` is split into two constrained pieces. Returns the
    /// vertex id and whether it is new.
    pub(crate) fn add_point(&mut self, p: Point2) -> (u32, bool) {
        let at = self.mesh.locate_any(p);
        self.add_point_at(p, at)
    }

    /// [`Constrained::add_point`] for a point already located at `at`.
    pub(crate) fn add_point_at(&mut self, p: Point2, at: Found) -> (u32, bool) {
        if let Found::Vertex(v) = at {
            return (v, false);
        }
        let id = self.mesh.push_point(p);
        self.vmap.push(u32::MAX);
        let split = match at {
            Found::Edge(h) => {
                let (a, b) = (self.mesh.v[h as usize], self.mesh.v[next(h) as usize]);
                self.fixed.remove(&key(a, b)).map(|c| (a, b, c))
            }
            _ => None,
        };
        let fixed = &self.fixed;
        let ghost_fixed = self.ghost_fixed;
        self.mesh.insert_with(id, at, |a, b| {
            if a == GHOST || b == GHOST {
                ghost_fixed
            } else {
                fixed.contains_key(&key(a, b))
            }
        });
        if let Some((a, b, c)) = split {
            self.fixed.insert(key(a, id), c);
            self.fixed.insert(key(id, b), c);
        }
        self.refresh_around(id);
        let star = self.star(id);
        self.dirty.extend(star);
        (id, true)
    }

    /// After inserting `p`, every changed triangle has `p` as a corner: re-point the map of
    /// their vertices.
    fn refresh_around(&mut self, p: u32) {
        let last = self.mesh.last;
        let h0 = (0..3)
            .map(|k| 3 * last + k)
            .find(|&h| self.mesh.v[h as usize] == p)
            .or_else(|| (0..self.mesh.v.len() as u32).find(|&h| self.mesh.v[h as usize] == p));
        let Some(h0) = h0 else { return };
        self.vmap[p as usize] = h0;
        for h in self.out_edges(p) {
            self.touch(h / 3);
        }
        self.vmap[p as usize] = h0;
    }

    /// Records that constraint `ci` comes from the input segment `o` (for a constraint
    /// inserted as a chain of pieces; else its first piece is taken for the segment).
    pub(crate) fn set_origin(&mut self, ci: u32, o: (Point2, Point2)) {
        self.origin.insert(ci, o);
    }

    /// Inserts the constraint `a–b` (vertex ids) with id `ci`, splitting it at vertices on
    /// it and at crossings with constrained edges (see the module docs).
    pub(crate) fn insert_segment(&mut self, a: u32, b: u32, ci: u32) -> Result<()> {
        let (pa, pb) = (self.mesh.pt(a), self.mesh.pt(b));
        let (oa, ob) = *self.origin.entry(ci).or_insert((pa, pb));
        let mut work = vec![(a, b)];
        while let Some((a, b)) = work.pop() {
            if a == b {
                continue;
            }
            match self.walk(a, b, ci)? {
                Walk::Edge => {
                    let m = &self.mesh;
                    let apexes = self.find(a, b).map(|h| {
                        let t = m.twin[h as usize];
                        (m.v[prev(h) as usize], m.v[prev(t) as usize])
                    });
                    let near = apexes.into_iter().flat_map(|(p, q)| [p, q]);
                    if let Some(z) = self.on_input_segment(a, b, (oa, ob), near) {
                        work.extend_from_slice(&[(z, b), (a, z)]);
                        continue;
                    }
                    self.fixed.insert(key(a, b), ci);
                }
                Walk::Split(c) => work.extend_from_slice(&[(c, b), (a, c)]),
                Walk::Blocked(u, w) => {
                    if self.stop_at_crossing {
                        self.met_crossing = true;
                        return Err(internal(ci, "crossing (first pass)"));
                    }
                    if self.crossing_budget == 0 {
                        return Err(Error::InvalidInput(format!(
                            "constraint {ci}: too many crossings split (rounded crossing points keep creating new crossings)"
                        )));
                    }
                    self.crossing_budget -= 1;
                    let cu = *self.fixed.get(&key(u, w)).unwrap_or(&ci);
                    let xv = self.meeting_vertex((a, b, (oa, ob)), (u, w, cu), ci)?;
                    if xv != u && xv != w && self.fixed.remove(&key(u, w)).is_some() {
                        self.insert_segment(u, xv, cu)?;
                        self.insert_segment(xv, w, cu)?;
                    }
                    work.extend_from_slice(&[(xv, b), (a, xv)]);
                }
                Walk::Crossed(list) => {
                    let near = list.iter().flat_map(|&(u, w)| [u, w]);
                    if let Some(z) = self.on_input_segment(a, b, (oa, ob), near) {
                        work.extend_from_slice(&[(z, b), (a, z)]);
                        continue;
                    }
                    self.flip_out(a, b, list.into(), ci)?;
                    self.fixed.insert(key(a, b), ci);
                }
            }
        }
        Ok(())
    }

    /// The vertex where the piece `a–b` (of the input segment `o`, constraint `ci`) and the
    /// constrained piece `u–w` it properly crosses (of constraint `cu`) are made to meet:
    /// * an end of one piece that lies exactly on the other's input segment, inside the
    ///   circle with diameter the other piece (a bent piece passes within rounding of a
    ///   vertex its input segment goes through: the pieces meet there, as the inputs do);
    /// * else the crossing of the two input segments, when they properly cross (so that
    ///   every constraint through the same input crossing meets at the same rounded point,
    ///   not at several points an ulp apart), rounded to `f64`;
    /// * else the crossing of the two pieces, rounded.
    ///
    /// The rounded point is inserted (or is the vertex equal to it).
    fn meeting_vertex(
        &mut self,
        (a, b, (oa, ob)): (u32, u32, (Point2, Point2)),
        (u, w, cu): (u32, u32, u32),
        ci: u32,
    ) -> Result<u32> {
        let m = &self.mesh;
        let (pa, pb, pu, pw) = (m.pt(a), m.pt(b), m.pt(u), m.pt(w));
        let (ta, tb) = self.origin.get(&cu).copied().unwrap_or((pu, pw));
        for (z, pz) in [(u, pu), (w, pw)] {
            if on_segment_near_piece(pz, (oa, ob), (pa, pb)) {
                return Ok(z);
            }
        }
        for (z, pz) in [(a, pa), (b, pb)] {
            if on_segment_near_piece(pz, (ta, tb), (pu, pw)) {
                return Ok(z);
            }
        }
        let (s, t) = if crosses(oa, ob, ta, tb) {
            (Segment2::new(oa, ob), Segment2::new(ta, tb))
        } else {
            (Segment2::new(pa, pb), Segment2::new(pu, pw))
        };
        let Some(c) = Crossing::new(s, t) else {
            return Err(internal(ci, "crossing of parallel segments"));
        };
        let x = c.approx();
        if !x.is_finite() {
            return Err(internal(ci, "crossing beyond the f64 range"));
        }
        Ok(self.add_point(x).0)
    }

    /// For a piece `a–b` of the input segment `o` that was bent through a rounded crossing
    /// (an end off `o`): a vertex among `near` (the corners of the triangles the piece
    /// crosses or borders) lying exactly on `o` and strictly inside the circle with
    /// diameter `a–b`. Such a vertex is within rounding of the piece but not on it; the
    /// piece goes through it instead, as the input segment does (else the piece and a
    /// constraint from that vertex along the segment would meet at an angle of ~10⁻¹⁶,
    /// which refinement cannot resolve). An unbent piece finds such vertices by its walk.
    fn on_input_segment(
        &self,
        a: u32,
        b: u32,
        (oa, ob): (Point2, Point2),
        near: impl Iterator<Item = u32>,
    ) -> Option<u32> {
        let m = &self.mesh;
        let (pa, pb) = (m.pt(a), m.pt(b));
        if orient(oa, ob, pa) == 0 && orient(oa, ob, pb) == 0 {
            return None;
        }
        near.filter(|&z| z != GHOST && z != a && z != b)
            .find(|&z| on_segment_near_piece(m.pt(z), (oa, ob), (pa, pb)))
    }

    /// Walks from `a` to `b` through the triangles the segment crosses (exact orientations).
    fn walk(&self, a: u32, b: u32, ci: u32) -> Result<Walk> {
        let m = &self.mesh;
        let (pa, pb) = (m.pt(a), m.pt(b));
        for h in self.out_iter(a) {
            let x = m.v[next(h) as usize];
            if x == b {
                return Ok(Walk::Edge);
            }
            if x != GHOST {
                let px = m.pt(x);
                if orient(pa, px, pb) == 0 && same_direction(pa, px, pb) {
                    return Ok(Walk::Split(x));
                }
            }
        }
        for h in self.out_iter(a) {
            if m.is_ghost(h / 3) {
                continue;
            }
            let x = m.v[next(h) as usize];
            let y = m.v[prev(h) as usize];
            if !(orient(pa, m.pt(x), pb) > 0 && orient(pa, m.pt(y), pb) < 0) {
                continue;
            }
            // b is beyond edge x -> y (x right of a->b, y left).
            let mut crossed = Vec::new();
            let mut e = next(h);
            loop {
                let (u, w) = (m.v[e as usize], m.v[next(e) as usize]);
                if self.is_fixed(u, w) {
                    return Ok(Walk::Blocked(u, w));
                }
                crossed.push((u, w));
                let f = m.twin[e as usize];
                let z = m.v[prev(f) as usize];
                if z == b {
                    return Ok(Walk::Crossed(crossed));
                }
                if z == GHOST {
                    break;
                }
                let oz = orient(pa, pb, m.pt(z));
                if oz == 0 {
                    return Ok(Walk::Split(z));
                }
                // f = w -> u in triangle (w, u, z): leave through u–z when z is on w's
                // (left) side, else through z–w.
                e = if oz > 0 { next(f) } else { prev(f) };
            }
            break;
        }
        Err(internal(ci, "no path through the triangulation"))
    }

    /// Sloan's flips for `a–b`: a crossed edge whose quadrilateral is strictly convex is
    /// flipped (its new diagonal re-queued if it still crosses), otherwise it waits.
    fn flip_out(&mut self, a: u32, b: u32, mut queue: VecDeque<(u32, u32)>, ci: u32) -> Result<()> {
        let (pa, pb) = (self.mesh.pt(a), self.mesh.pt(b));
        let limit = 16 * queue.len() * queue.len() + 1000;
        let mut steps = 0;
        while let Some((u, w)) = queue.pop_front() {
            steps += 1;
            if steps > limit {
                return Err(internal(ci, "flipping did not converge"));
            }
            let Some(e) = self.find(u, w) else {
                continue;
            };
            let m = &self.mesh;
            let f = m.twin[e as usize];
            let p = m.v[prev(e) as usize];
            let d = m.v[prev(f) as usize];
            if p == GHOST || d == GHOST {
                queue.push_back((u, w));
                continue;
            }
            let (pu, pw, pp, pd) = (m.pt(u), m.pt(w), m.pt(p), m.pt(d));
            if orient(pp, pu, pd) > 0 && orient(pp, pd, pw) > 0 {
                self.flip(e);
                self.dirty.extend_from_slice(&[e / 3, f / 3]);
                if crosses(pa, pb, pp, pd) {
                    queue.push_back((p, d));
                }
            } else {
                queue.push_back((u, w));
            }
        }
        match self.walk(a, b, ci)? {
            Walk::Edge => Ok(()),
            _ => Err(internal(ci, "not an edge after flipping")),
        }
    }

    /// Lawson flips from the half-edges in `stack` (and those they expose) until every
    /// unconstrained edge is locally Delaunay. Returns the triangles changed by flips.
    pub(crate) fn restore(&mut self, mut stack: Vec<u32>) -> Vec<u32> {
        let mut touched = Vec::new();
        while let Some(h) = stack.pop() {
            let m = &self.mesh;
            let f = m.twin[h as usize];
            let (a, b) = (m.v[h as usize], m.v[next(h) as usize]);
            let p = m.v[prev(h) as usize];
            let d = m.v[prev(f) as usize];
            if p == GHOST || d == GHOST || a == GHOST || b == GHOST || self.is_fixed(a, b) {
                continue;
            }
            if in_circle(m.pt(b), m.pt(a), m.pt(d), m.pt(p)) > 0 {
                self.flip(h);
                let (t, u) = (h / 3, f / 3);
                touched.extend_from_slice(&[t, u]);
                stack.extend_from_slice(&[3 * t, 3 * t + 1, 3 * u + 1, 3 * u + 2]);
            }
        }
        touched
    }

    /// [`Constrained::restore`] from the edges of the triangles changed since the mesh was
    /// Delaunay (the flips of constraint insertion, the stars of Steiner points), for a mesh
    /// that started as a Delaunay triangulation. Enough: an edge whose two triangles never
    /// changed is still locally Delaunay, and Lawson's flips queue the edges they expose.
    pub(crate) fn restore_dirty(&mut self) {
        let mut stack = Vec::with_capacity(3 * self.dirty.len());
        for &t in &self.dirty {
            stack.extend_from_slice(&[3 * t, 3 * t + 1, 3 * t + 2]);
        }
        self.dirty.clear();
        self.restore(stack);
    }

    /// The triangles around vertex `v` (ghosts included).
    pub(crate) fn star(&self, v: u32) -> Vec<u32> {
        self.out_edges(v).into_iter().map(|h| h / 3).collect()
    }
}

/// Where [`Constrained::walk_to`] ended.
pub(crate) enum WalkTo {
    /// The point is here.
    At(Found),
    /// The way is barred by the constrained edge `a–b`.
    Blocked(u32, u32),
    /// The walk did not settle (it may cycle in a constrained triangulation).
    Lost,
}

impl Constrained<'_> {
    /// The visibility walk from triangle `t` towards `p` that never crosses a constrained
    /// edge, except `allow` (entering the ghost beyond it means `p` is outside there).
    pub(crate) fn walk_to(&self, t: u32, p: Point2, allow: Option<(u32, u32)>) -> WalkTo {
        let m = &self.mesh;
        let mut cur = t;
        let mut from = u32::MAX;
        let limit = 64 + 4 * u64::from(m.slots());
        let mut steps = 0u64;
        loop {
            steps += 1;
            if steps > limit {
                return WalkTo::Lost;
            }
            if m.is_ghost(cur) {
                return WalkTo::At(Found::Face(cur));
            }
            let base = 3 * cur;
            let mut zero_mask = 0u32;
            let mut moved = false;
            for k in 0..3 {
                let h = base + k;
                if h == from {
                    continue;
                }
                let (a, b) = (m.v[h as usize], m.v[next(h) as usize]);
                let s = orient(m.pt(a), m.pt(b), p);
                if s < 0 {
                    if self.is_fixed(a, b) && allow != Some(key(a, b)) {
                        return WalkTo::Blocked(a, b);
                    }
                    from = m.twin[h as usize];
                    cur = from / 3;
                    moved = true;
                    break;
                } else if s == 0 {
                    zero_mask |= 1 << k;
                }
            }
            if !moved {
                return WalkTo::At(m.classify(base, zero_mask));
            }
        }
    }
}

fn internal(ci: u32, what: &str) -> Error {
    Error::InvalidInput(format!("constraint {ci}: {what} (internal error)"))
}

/// For collinear `a`, `x`, `b` (`x != a`): is `x` on the ray from `a` towards `b`? Exact
/// (coordinate comparisons only).
fn same_direction(a: Point2, x: Point2, b: Point2) -> bool {
    let sign = |p: f64, q: f64| i8::from(p > q) - i8::from(p < q);
    sign(x.x, a.x) * sign(b.x, a.x) > 0 || sign(x.y, a.y) * sign(b.y, a.y) > 0
}

/// Whether the vertex `z` is one that a (possibly bent) piece `p–q` of the input segment
/// `o` must pass through: `o` meets the rounding cell of `z` (passes within half an ulp of
/// it per coordinate, decided exactly) and `z` is strictly inside the circle with diameter
/// `p–q` (it lies alongside the piece, not beyond an end).
fn on_segment_near_piece(z: Point2, o: (Point2, Point2), (p, q): (Point2, Point2)) -> bool {
    segment_meets_cell(z, o.0, o.1) && dot_sign(z, p, q) == std::cmp::Ordering::Less
}

/// Does segment p–d properly cross segment a–b (interiors meet in one point)?
fn crosses(a: Point2, b: Point2, p: Point2, d: Point2) -> bool {
    orient(a, b, p) * orient(a, b, d) < 0 && orient(p, d, a) * orient(p, d, b) < 0
}
