//! Delaunay refinement (Ruppert's algorithm, with Shewchuk's concentric shells): Steiner
//! points are added to a constrained Delaunay triangulation until every triangle has all
//! angles at least a bound (and, optionally, area at most a bound).
//!
//! # Method
//!
//! The domain is the set of triangles of the given [`Cdt`] (for a polygon: its interior;
//! otherwise the convex hull). Its boundary edges and the constrained edges are the
//! *segments*; the domain never grows.
//!
//! 1. A segment piece is *encroached* when a vertex that sees it lies strictly inside its
//!    diametral circle (exact dot-product sign). Encroached pieces are split first.
//! 2. A *bad* triangle (an angle below the bound, or area above the bound) gets a vertex at
//!    its circumcentre — unless the circumcentre lies beyond a segment, or would encroach
//!    on a segment, in which case those segments are split instead (the triangle is tried
//!    again later).
//! 3. A piece is split at its midpoint, or — when exactly one end is a vertex of the
//!    input — at the power-of-two distance from that end nearest to the midpoint
//!    (concentric shells), so that splits around a small input angle stay in step.
//!
//! Every decision is exact: in-circle and orientation by the filtered predicates, the angle
//! test compares `(u·v)²` with `cos²θ |u|² |v|²` (θ the bound, `cos²θ` rounded once to
//! `f64`, so the bound actually enforced is within 10⁻¹⁵ degrees of θ) and the area test
//! compares the exact cross product with twice the bound — both by an `f64` enclosure with
//! an exact dyadic fallback. Steiner points (circumcentres, split points) are rounded to
//! `f64`; when a split point is not exactly on its piece, the piece becomes two pieces
//! through the rounded point (they bend by at most half an ulp), and the result is the exact
//! constrained Delaunay triangulation of its vertices and pieces.
//!
//! # Guarantee
//!
//! For a bound up to 20.7° (arcsin(1/(2√2))) and input whose segments meet at angles of
//! at least 60°, the algorithm terminates with every triangle meeting the bound (Ruppert
//! 1995; Shewchuk 2002 with concentric shells). Larger bounds, up to [`MAX_MIN_ANGLE`]°,
//! usually terminate as well; [`RefineOptions::max_steiner`] caps the work in any case
//! ([`Refinement::complete`] says whether it was reached).
//!
//! **Small input angles.** Near two segments that meet at an angle below 60°, refinement
//! could cascade forever. The rule used: a bad triangle whose shortest edge joins two
//! vertices lying on two different segments that share an endpoint, where those segments
//! meet at less than 60°, is left as it is. Such triangles are listed in
//! [`Refinement::exempt`]; every other triangle meets the bound when `complete` is true.
//! The same happens for a triangle whose circumcentre rounds onto an existing vertex, or
//! whose split point rounds onto an end of its piece (the f64 resolution is reached).
//!
//! Time: O(n log n + m) expected in practice, m the number of Steiner points (no worst-case
//! bound beyond the cap is claimed).

use super::cdt::{finish, Cdt};
use super::constrain::{key, Constrained, WalkTo};
use super::mesh::{next, prev, Found, Mesh, GHOST};
use super::pred::{angle_below, area_above, dot_sign, in_circle, orient};
use super::triangulation::{circumcenter, NO_NEIGHBOR};
use crate::{Error, Point2, Result};
use std::cmp::Ordering;
use std::collections::{HashMap, HashSet, VecDeque};

/// The largest minimum-angle bound accepted, in degrees.
pub const MAX_MIN_ANGLE: f64 = 34.0;

/// Options for [`refine`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct RefineOptions {
    /// The minimum angle in degrees (0 for none), at most [`MAX_MIN_ANGLE`]. Default 20.
    pub min_angle: f64,
    /// The largest triangle area allowed, if any.
    pub max_area: Option<f64>,
    /// The most Steiner points to add (the work cap). Default 10⁷.
    pub max_steiner: usize,
}

impl Default for RefineOptions {
    fn default() -> Self {
        RefineOptions::new(20.0)
    }
}

impl RefineOptions {
    /// A minimum angle bound (degrees), no area bound, the default cap.
    pub const fn new(min_angle: f64) -> Self {
        RefineOptions {
            min_angle,
            max_area: None,
            max_steiner: 10_000_000,
        }
    }

    /// The same options with an area bound.
    pub const fn with_max_area(mut self, max_area: f64) -> Self {
        self.max_area = Some(max_area);
        self
    }

    /// The same options with another cap on Steiner points.
    pub const fn with_max_steiner(mut self, max_steiner: usize) -> Self {
        self.max_steiner = max_steiner;
        self
    }
}

/// The result of [`refine`].
#[derive(Debug, Clone, PartialEq)]
pub struct Refinement {
    /// The refined constrained Delaunay triangulation: the input's vertices first (same
    /// indices, same `input_to_vertex`), then the Steiner points; constraints are the pieces
    /// of the input's constraints and of the domain boundary.
    pub cdt: Cdt,
    /// How many Steiner points were added.
    pub steiner: usize,
    /// Triangles (indices into `cdt.triangulation.triangles()`) that do not meet the bound
    /// and were left by the small-angle rule (see the module docs).
    pub exempt: Vec<u32>,
    /// False when `max_steiner` stopped the refinement early.
    pub complete: bool,
}

/// Refines `cdt` (from [`constrained_delaunay`](super::constrained_delaunay),
/// [`polygon_delaunay`](super::polygon_delaunay), or a Delaunay triangulation wrapped with
/// no constraints) until every triangle meets the options' bounds; see the module docs.
///
/// ```
/// use compgeom::delaunay::{polygon_delaunay, refine, verify_cdt, RefineOptions};
/// use compgeom::{Point2, Polygon};
/// let sq = Polygon::new(
///     vec![Point2::new(0.0, 0.0), Point2::new(10.0, 0.0), Point2::new(10.0, 1.0), Point2::new(0.0, 1.0)],
///     vec![],
/// );
/// let r = refine(&polygon_delaunay(&[sq])?, &RefineOptions::new(25.0))?;
/// verify_cdt(&r.cdt)?;
/// assert!(r.complete && r.exempt.is_empty() && r.steiner > 0);
/// # Ok::<(), compgeom::Error>(())
/// ```
///
/// # Errors
/// `InvalidInput` for a bound out of range (angle not in `[0, MAX_MIN_ANGLE]`, area not
/// positive and finite), or when a rounded Steiner point cannot be connected (features at
/// the scale of `f64` resolution).
pub fn refine(cdt: &Cdt, options: &RefineOptions) -> Result<Refinement> {
    let a = options.min_angle;
    if !(0.0..=MAX_MIN_ANGLE).contains(&a) {
        return Err(Error::InvalidInput(format!(
            "minimum angle {a}° is not in [0, {MAX_MIN_ANGLE}]"
        )));
    }
    if let Some(m) = options.max_area {
        if !(m > 0.0 && m.is_finite()) {
            return Err(Error::InvalidInput(format!(
                "maximum area {m} is not positive and finite"
            )));
        }
    }
    let t = &cdt.triangulation;
    if t.is_degenerate() {
        return Ok(Refinement {
            cdt: cdt.clone(),
            steiner: 0,
            exempt: Vec::new(),
            complete: true,
        });
    }
    let mut r = Refiner::new(cdt, options)?;
    let complete = r.run()?;
    let n0 = t.vertices().len();
    let rep: Vec<u32> = (0..n0 as u32).collect();
    let (mut tri, constraints) = finish(&r.c, n0, &rep);
    let steiner = tri.vertices().len() - n0;
    tri.input_to_vertex = t.input_to_vertex().to_vec();
    let exempt = (0..tri.triangles().len() as u32)
        .filter(|&i| {
            let [a, b, c] = tri.triangles()[i as usize];
            r.bad(a, b, c)
        })
        .collect();
    Ok(Refinement {
        cdt: Cdt {
            triangulation: tri,
            constraints,
        },
        steiner,
        exempt,
        complete,
    })
}

/// Exact: does triangle `a b c` (counter-clockwise) have an angle below `min_angle`
/// degrees? `cos²` of the bound is rounded once to `f64` (see the module docs).
///
/// ```
/// use compgeom::delaunay::has_angle_below;
/// use compgeom::Point2;
/// let (a, b, c) = (Point2::new(0.0, 0.0), Point2::new(1.0, 0.0), Point2::new(0.5, 0.866));
/// assert!(!has_angle_below(a, b, c, 59.0));
/// assert!(has_angle_below(a, b, Point2::new(0.5, 0.1), 20.0));
/// ```
pub fn has_angle_below(a: Point2, b: Point2, c: Point2, min_angle: f64) -> bool {
    let cos2 = cos2_of(min_angle);
    min_angle > 0.0
        && (angle_below(a, b, c, cos2) || angle_below(b, c, a, cos2) || angle_below(c, a, b, cos2))
}

fn cos2_of(deg: f64) -> f64 {
    let c = deg.to_radians().cos();
    c * c
}

struct Refiner<'a> {
    c: Constrained<'a>,
    /// Vertices of the input triangulation: ids below `n0`.
    n0: u32,
    cos2: f64,
    check_angle: bool,
    twice_area: Option<f64>,
    max_steiner: usize,
    /// The original segments (vertex pairs of the input's pieces and boundary edges).
    segs: Vec<(u32, u32)>,
    /// Segments through each input vertex.
    at_vertex: HashMap<u32, Vec<u32>>,
    /// The segment each Steiner vertex on a segment was created on.
    on_seg: HashMap<u32, u32>,
    /// Triangles left alone (circumcentre not insertable), by their vertex triple.
    skipped: HashSet<[u32; 3]>,
    /// Pieces that cannot be split further (f64 resolution).
    unsplittable: HashSet<(u32, u32)>,
}

impl<'a> Refiner<'a> {
    fn new(cdt: &Cdt, o: &RefineOptions) -> Result<Refiner<'a>> {
        let t = &cdt.triangulation;
        let mesh = domain_mesh(t.vertices().to_vec(), t.triangles(), t.neighbors());
        let mut c = Constrained::new(mesh, true);
        let mut segs = Vec::new();
        let mut at_vertex: HashMap<u32, Vec<u32>> = HashMap::new();
        let mut add_seg = |c: &mut Constrained<'_>, u: u32, w: u32| {
            if let std::collections::hash_map::Entry::Vacant(e) = c.fixed.entry(key(u, w)) {
                let id = segs.len() as u32;
                e.insert(id);
                segs.push(key(u, w));
                at_vertex.entry(u).or_default().push(id);
                at_vertex.entry(w).or_default().push(id);
            }
        };
        for &(u, w) in &cdt.constraints {
            add_seg(&mut c, u, w);
        }
        for (i, tri) in t.triangles().iter().enumerate() {
            for k in 0..3 {
                if t.neighbors()[i][k] == NO_NEIGHBOR {
                    add_seg(&mut c, tri[(k + 1) % 3], tri[(k + 2) % 3]);
                }
            }
        }
        c.crossing_budget = 1000 + 16 * segs.len();
        Ok(Refiner {
            c,
            n0: t.vertices().len() as u32,
            cos2: cos2_of(o.min_angle),
            check_angle: o.min_angle > 0.0,
            twice_area: o.max_area.map(|a| 2.0 * a),
            max_steiner: o.max_steiner,
            segs,
            at_vertex,
            on_seg: HashMap::new(),
            skipped: HashSet::new(),
            unsplittable: HashSet::new(),
        })
    }

    fn pt(&self, v: u32) -> Point2 {
        self.c.mesh.pt(v)
    }

    fn tri(&self, t: u32) -> [u32; 3] {
        let i = 3 * t as usize;
        [self.c.mesh.v[i], self.c.mesh.v[i + 1], self.c.mesh.v[i + 2]]
    }

    fn too_big(&self, a: u32, b: u32, c: u32) -> bool {
        self.twice_area
            .is_some_and(|tw| area_above(self.pt(a), self.pt(b), self.pt(c), tw))
    }

    fn skinny(&self, a: u32, b: u32, c: u32) -> bool {
        let (pa, pb, pc) = (self.pt(a), self.pt(b), self.pt(c));
        self.check_angle
            && (angle_below(pa, pb, pc, self.cos2)
                || angle_below(pb, pc, pa, self.cos2)
                || angle_below(pc, pa, pb, self.cos2))
    }

    /// Does triangle `a b c` fail the bounds (and need a Steiner point)?
    fn bad(&self, a: u32, b: u32, c: u32) -> bool {
        self.skinny(a, b, c) || self.too_big(a, b, c)
    }

    /// The segments vertex `v` lies on.
    fn segs_of(&self, v: u32) -> Vec<u32> {
        if v < self.n0 {
            self.at_vertex.get(&v).cloned().unwrap_or_default()
        } else {
            self.on_seg.get(&v).map(|&s| vec![s]).unwrap_or_default()
        }
    }

    /// The small-angle rule: the shortest edge of the skinny triangle joins two vertices
    /// on two segments meeting at an input vertex at less than 60°.
    fn exempt(&self, tri: [u32; 3]) -> bool {
        if self.too_big(tri[0], tri[1], tri[2]) {
            return false;
        }
        let len2 = |a: u32, b: u32| {
            let (p, q) = (self.pt(a), self.pt(b));
            (p.x - q.x).powi(2) + (p.y - q.y).powi(2)
        };
        let k = (0..3)
            .min_by(|&i, &j| {
                len2(tri[(i + 1) % 3], tri[(i + 2) % 3])
                    .total_cmp(&len2(tri[(j + 1) % 3], tri[(j + 2) % 3]))
            })
            .unwrap_or(0);
        let (p, q) = (tri[(k + 1) % 3], tri[(k + 2) % 3]);
        let cos2_60 = 0.25;
        for s in self.segs_of(p) {
            for t in self.segs_of(q) {
                if s == t {
                    continue;
                }
                let ((s0, s1), (t0, t1)) = (self.segs[s as usize], self.segs[t as usize]);
                let apex = if s0 == t0 || s0 == t1 {
                    s0
                } else if s1 == t0 || s1 == t1 {
                    s1
                } else {
                    continue;
                };
                if apex == p || apex == q {
                    continue;
                }
                let far = |(x, y): (u32, u32)| if x == apex { y } else { x };
                let (a, b) = (self.pt(far((s0, s1))), self.pt(far((t0, t1))));
                if angle_below(self.pt(apex), a, b, cos2_60) {
                    return true;
                }
            }
        }
        false
    }

    /// Is piece `u–w` encroached by a vertex that sees it (an opposite vertex)?
    fn encroached(&self, u: u32, w: u32) -> bool {
        let m = &self.c.mesh;
        let (pu, pw) = (m.pt(u), m.pt(w));
        [self.c.find(u, w), self.c.find(w, u)]
            .into_iter()
            .flatten()
            .any(|h| {
                let x = m.v[prev(h) as usize];
                x != GHOST && dot_sign(m.pt(x), pu, pw) == Ordering::Less
            })
    }

    fn run(&mut self) -> Result<bool> {
        let mut seg_queue: Vec<(u32, u32, bool)> = self
            .c
            .fixed
            .keys()
            .filter(|&&(u, w)| self.encroached(u, w))
            .map(|&(u, w)| (u, w, false))
            .collect();
        seg_queue.sort_unstable();
        let mut bad: VecDeque<(u32, [u32; 3])> = VecDeque::new();
        for t in 0..self.c.mesh.slots() {
            self.queue_if_bad(t, &mut bad);
        }
        let mut steiner = 0usize;
        loop {
            if steiner >= self.max_steiner {
                return Ok(false);
            }
            if let Some((u, w, force)) = seg_queue.pop() {
                if !self.c.fixed.contains_key(&key(u, w))
                    || self.unsplittable.contains(&key(u, w))
                    || !(force || self.encroached(u, w))
                {
                    continue;
                }
                if let Some(v) = self.split(u, w)? {
                    steiner += 1;
                    self.after_insert(v, &mut seg_queue, &mut bad);
                }
                continue;
            }
            let Some((t, tri)) = bad.pop_front() else {
                return Ok(true);
            };
            if self.tri(t) != tri || self.skipped.contains(&tri) || self.exempt(tri) {
                continue;
            }
            let [a, b, c] = tri.map(|v| self.pt(v));
            let cc = circumcenter(a, b, c);
            if !cc.is_finite() {
                self.skipped.insert(tri);
                continue;
            }
            match self.place(t, cc) {
                Place::Blocked(u, w) => {
                    self.split_instead(vec![(u, w)], t, tri, &mut seg_queue, &mut bad)
                }
                Place::Encroaches(list) => {
                    self.split_instead(list, t, tri, &mut seg_queue, &mut bad)
                }
                Place::Free(at) => {
                    let (v, new) = self.c.add_point_at(cc, at);
                    if new {
                        steiner += 1;
                        self.after_insert(v, &mut seg_queue, &mut bad);
                    } else {
                        self.skipped.insert(tri);
                    }
                }
                Place::Lost => {
                    self.skipped.insert(tri);
                }
            }
        }
    }

    /// Queues the segments to split instead of inserting the circumcentre of `tri`, and
    /// the triangle again; when none can be split (f64 resolution) the triangle is left.
    fn split_instead(
        &mut self,
        list: Vec<(u32, u32)>,
        t: u32,
        tri: [u32; 3],
        seg_queue: &mut Vec<(u32, u32, bool)>,
        bad: &mut VecDeque<(u32, [u32; 3])>,
    ) {
        let before = seg_queue.len();
        seg_queue.extend(
            list.into_iter()
                .filter(|&(u, w)| !self.unsplittable.contains(&key(u, w)))
                .map(|(u, w)| (u, w, true)),
        );
        if seg_queue.len() > before {
            bad.push_back((t, tri));
        } else {
            self.skipped.insert(tri);
        }
    }

    fn queue_if_bad(&self, t: u32, bad: &mut VecDeque<(u32, [u32; 3])>) {
        let tri = self.tri(t);
        if !tri.contains(&GHOST) && self.bad(tri[0], tri[1], tri[2]) {
            bad.push_back((t, tri));
        }
    }

    /// After adding vertex `v`: restore the constrained Delaunay property around it, queue
    /// the new bad triangles and the encroached pieces nearby.
    fn after_insert(
        &mut self,
        v: u32,
        seg_queue: &mut Vec<(u32, u32, bool)>,
        bad: &mut VecDeque<(u32, [u32; 3])>,
    ) {
        let mut around: Vec<u32> = self.c.star(v);
        let stack: Vec<u32> = around
            .iter()
            .flat_map(|&t| [3 * t, 3 * t + 1, 3 * t + 2])
            .collect();
        around.extend(self.c.restore(stack));
        around.extend(self.c.star(v));
        around.sort_unstable();
        around.dedup();
        for &t in &around {
            self.queue_if_bad(t, bad);
            for k in 0..3 {
                let h = 3 * t + k;
                let (a, b) = (self.c.mesh.v[h as usize], self.c.mesh.v[next(h) as usize]);
                if a != GHOST && b != GHOST && self.c.fixed.contains_key(&key(a, b)) {
                    seg_queue.push((a, b, false));
                }
            }
        }
    }

    /// Splits piece `u–w`; returns the new vertex (`None` at the f64 resolution).
    fn split(&mut self, u: u32, w: u32) -> Result<Option<u32>> {
        let seg = self.c.fixed[&key(u, w)];
        let m = self.split_point(u, w);
        // Split the edge itself at m (combinatorially), which is valid when the rounded m
        // lies strictly inside both triangles' union as seen from their far corners (exact
        // orientations); the pieces u–m, m–w stay constrained.
        let Some(h) = self.c.find(u, w) else {
            return Err(Error::InvalidInput(format!(
                "segment piece {u}-{w} is not an edge (internal error)"
            )));
        };
        let h = if self.c.mesh.is_ghost(h / 3) {
            self.c.mesh.twin[h as usize]
        } else {
            h
        };
        let mesh = &self.c.mesh;
        let (a, b) = (mesh.v[h as usize], mesh.v[next(h) as usize]);
        let c = mesh.v[prev(h) as usize];
        let d = mesh.v[prev(mesh.twin[h as usize]) as usize];
        let ccw = |x: u32, y: u32| orient(mesh.pt(x), mesh.pt(y), m) > 0;
        let fits = ccw(b, c) && ccw(c, a) && (d == GHOST || (ccw(a, d) && ccw(d, b)));
        if !fits {
            self.unsplittable.insert(key(u, w));
            return Ok(None);
        }
        let (v, _) = self.c.add_point_at(m, Found::Edge(h));
        self.on_seg.insert(v, seg);
        Ok(Some(v))
    }

    /// The midpoint, or the concentric-shell point when exactly one end is an input
    /// vertex (rounded to f64).
    fn split_point(&self, u: u32, w: u32) -> Point2 {
        let (pu, pw) = (self.pt(u), self.pt(w));
        let mid = Point2::new(0.5 * pu.x + 0.5 * pw.x, 0.5 * pu.y + 0.5 * pw.y);
        let (apex, other) = match (u < self.n0, w < self.n0) {
            (true, false) => (pu, pw),
            (false, true) => (pw, pu),
            _ => return mid,
        };
        let len = ((other.x - apex.x).powi(2) + (other.y - apex.y).powi(2)).sqrt();
        if !(len.is_finite() && len > 0.0) {
            return mid;
        }
        let d = (0.5 * len).log2().round().exp2();
        let f = d / len;
        if !(0.25..=0.75).contains(&f) {
            return mid;
        }
        Point2::new(
            apex.x + (other.x - apex.x) * f,
            apex.y + (other.y - apex.y) * f,
        )
    }

    /// Where the circumcentre `p` of triangle `t` goes: walks from `t` towards `p` without
    /// crossing segments, then checks which segments `p` would encroach on.
    fn place(&self, t: u32, p: Point2) -> Place {
        let m = &self.c.mesh;
        let found = match self.c.walk_to(t, p, None) {
            WalkTo::At(f) => f,
            WalkTo::Blocked(a, b) => return Place::Blocked(a, b),
            WalkTo::Lost => return Place::Lost,
        };
        let start = match found {
            Found::Vertex(_) => return Place::Free(found),
            Found::Face(f) => f,
            Found::Edge(h) => {
                let (a, b) = (m.v[h as usize], m.v[next(h) as usize]);
                if self.c.is_fixed(a, b) {
                    return Place::Encroaches(vec![(a, b)]);
                }
                h / 3
            }
        };
        // The cavity: triangles whose circumcircle holds p, reached without crossing a
        // segment; the segments on its boundary that p encroaches.
        let mut seen = HashSet::from([start]);
        let mut stack = vec![start];
        let mut hits = Vec::new();
        while let Some(f) = stack.pop() {
            for k in 0..3 {
                let h = 3 * f + k;
                let (a, b) = (m.v[h as usize], m.v[next(h) as usize]);
                if self.c.is_fixed(a, b) {
                    if a != GHOST && b != GHOST && dot_sign(p, m.pt(a), m.pt(b)) == Ordering::Less {
                        hits.push((a, b));
                    }
                    continue;
                }
                let g = m.twin[h as usize] / 3;
                if seen.contains(&g) {
                    continue;
                }
                let [x, y, z] = self.tri(g);
                if [x, y, z].contains(&GHOST) {
                    continue;
                }
                if in_circle(m.pt(x), m.pt(y), m.pt(z), p) > 0 {
                    seen.insert(g);
                    stack.push(g);
                }
            }
        }
        if hits.is_empty() {
            Place::Free(found)
        } else {
            Place::Encroaches(hits)
        }
    }
}

/// Where a circumcentre goes.
enum Place {
    /// Beyond segment `u–w` (seen from the triangle).
    Blocked(u32, u32),
    /// Inside the domain, but it would encroach on these segments.
    Encroaches(Vec<(u32, u32)>),
    /// Insert it (it is there).
    Free(Found),
    /// The walk did not settle (leave the triangle).
    Lost,
}

/// A mesh over `pts` with the given counter-clockwise triangles (and their neighbours) and a
/// ghost triangle beyond every boundary edge, the ghosts of each boundary cycle linked in
/// order (a domain with holes or pinched vertices is fine).
pub(crate) fn domain_mesh(pts: Vec<Point2>, tris: &[[u32; 3]], nbs: &[[u32; 3]]) -> Mesh<'static> {
    let mut m = Mesh::empty(pts);
    for t in tris {
        m.add(t[0], t[1], t[2]);
    }
    // Half-edge 3t + (k + 1) % 3 runs opposite vertex k.
    for (t, tri) in tris.iter().enumerate() {
        for k in 0..3 {
            let n = nbs[t][k];
            let h = (3 * t + (k + 1) % 3) as u32;
            if n == NO_NEIGHBOR {
                let (a, b) = (tri[(k + 1) % 3], tri[(k + 2) % 3]);
                let g = m.add(b, a, GHOST);
                m.link(h, 3 * g);
            } else if (n as usize) > t {
                let (a, b) = (tri[(k + 1) % 3], tri[(k + 2) % 3]);
                let other = tris[n as usize];
                if let Some(j) = (0..3).find(|&j| other[j] == b && other[(j + 1) % 3] == a) {
                    m.link(h, 3 * n + j as u32);
                }
            }
        }
    }
    // Ghost (b, a, G) of boundary edge a -> b: its edge a -> G pairs with G -> a of the
    // ghost of the boundary edge x -> a found by turning clockwise around a.
    let real = 3 * tris.len() as u32;
    for g in (real / 3)..m.slots() {
        let h = m.twin[3 * g as usize]; // a -> b, real
        let mut e = prev(h); // c -> a
        let mut guard = 0;
        while !m.is_ghost(m.twin[e as usize] / 3) && guard < m.v.len() {
            e = prev(m.twin[e as usize]);
            guard += 1;
        }
        let g2 = m.twin[e as usize] / 3;
        m.link(3 * g + 1, 3 * g2 + 2);
    }
    m.last = 0;
    m
}
