//! The farthest-point Voronoi diagram (book §7.4, notes and comments; exercise 7.13).
//!
//! The farthest-point cell of a site `s` is the set of points for which `s` is the farthest
//! site. Only the corners of the convex hull have non-empty cells, all unbounded; the
//! diagram is a tree. It is the dual of the *farthest-point Delaunay triangulation* of the
//! hull corners: every triangle's circumcircle contains all sites.
//!
//! Method, O(n log n) in all:
//!
//! 1. the convex hull ([`crate::hull`], exact, O(n log n)); its `h` corners are in convex
//!    position;
//! 2. the farthest-point Delaunay triangulation of the corners by randomized incremental
//!    insertion in the style of Chew's algorithm for convex polygons, expected O(h): remove
//!    the corners from the hull polygon in random order, remembering each one's neighbours
//!    at removal; insert them back in the opposite order — each new corner forms a triangle
//!    with its two remembered neighbours, which are adjacent on the current polygon — and
//!    restore the farthest-point Delaunay property by flips (an edge is flipped when the
//!    opposite corner lies strictly *outside* the circle, the exact in-circle test);
//! 3. the dual, exactly as for the nearest-site diagram ([`super::from_triangulation`]):
//!    adjacent triangles with the same circumcircle (exact in-circle test) become one vertex
//!    of degree > 3.
//!
//! ## Degenerate input
//!
//! Duplicates are merged (every input point maps to its site). Sites inside the hull or on
//! its edges between corners have empty cells. All sites on one line: the two extreme
//! sites share one edge (their bisector), no vertices. One distinct site: no edges. All
//! corners on one circle: one vertex of degree `h`.

use super::clip::{cut, ClipRegion};
use super::clip_polygon::check_polygon;
use super::diagram::{HalfEdge, Vertex, VoronoiDiagram};
use super::dual::from_triangulation;
use super::fortune::dedupe;
use super::predicates::cmp_dist;
use crate::delaunay::Triangulation;
use crate::hull::{convex_hull_indices, HullOptions};
use crate::kernel::{ensure_finite, incircle, CircleSide, MultiPolygon, Point2, Polygon};
use crate::overlay::{boolean, BooleanOp};
use crate::{Error, Result};
use std::cmp::Ordering;

const NIL: usize = usize::MAX;

/// A farthest-point Voronoi diagram: the same half-edge structure as [`VoronoiDiagram`],
/// where the site of a half-edge is the site whose *farthest-point* cell lies on its left.
///
/// Unlike the nearest-site diagram, a half-edge runs in the direction of the right site
/// minus the left site rotated clockwise (the opposite of [`VoronoiDiagram::direction`]),
/// and sites that are not corners of the convex hull have no cell
/// (`site_half_edge[s] == None`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FarthestVoronoi {
    /// The distinct sites, in the order of their first occurrence in the input.
    pub sites: Vec<Point2>,
    /// For each distinct site, the input index of its first occurrence.
    pub site_input_index: Vec<usize>,
    /// For each input point, the index of its site (duplicates share a site).
    pub input_to_site: Vec<usize>,
    /// The sites with a non-empty cell (the convex hull's corners), counter-clockwise.
    pub hull: Vec<usize>,
    /// The vertices: centres of circles through three or more sites containing all sites.
    pub vertices: Vec<Vertex>,
    /// The half-edges, in twin pairs `(2k, 2k + 1)`.
    pub half_edges: Vec<HalfEdge>,
    /// For each site, one half-edge of its cell (the first of its boundary chain), `None`
    /// for a site whose cell is empty (or with fewer than two corners).
    pub site_half_edge: Vec<Option<usize>>,
}

impl FarthestVoronoi {
    /// Number of edges (half-edge pairs).
    pub fn edge_count(&self) -> usize {
        self.half_edges.len() / 2
    }

    /// The end vertex of half-edge `h` (`None` at infinity).
    pub fn destination(&self, h: usize) -> Option<usize> {
        self.half_edges[self.half_edges[h].twin].origin
    }

    /// The sites whose cells share an edge with the cell of each site, ascending.
    pub fn neighbours(&self) -> Vec<Vec<usize>> {
        let mut adj = vec![Vec::new(); self.sites.len()];
        for h in &self.half_edges {
            adj[h.site].push(self.half_edges[h.twin].site);
        }
        for a in &mut adj {
            a.sort_unstable();
            a.dedup();
        }
        adj
    }

    /// A site farthest from `q` (among equally far sites, the first hull corner), decided
    /// exactly; `None` without sites or for a non-finite `q`. O(h) for `h` hull corners.
    ///
    /// ```
    /// use compgeom::voronoi::farthest_point_voronoi;
    /// use compgeom::Point2;
    /// let pts = [(0.0, 0.0), (10.0, 0.0), (5.0, 8.0), (5.0, 2.0)].map(Point2::from);
    /// let f = farthest_point_voronoi(&pts).unwrap();
    /// assert_eq!(f.farthest(Point2::new(9.0, 1.0)), Some(0));
    /// ```
    pub fn farthest(&self, q: Point2) -> Option<usize> {
        if !q.is_finite() {
            return None;
        }
        let mut best = *self.hull.first()?;
        for &s in &self.hull[1..] {
            if cmp_dist(q, self.sites[s], self.sites[best]) == Ordering::Greater {
                best = s;
            }
        }
        Some(best)
    }

    /// The cell of every site clipped to `region` (in site order; empty for sites without a
    /// cell or whose cell misses the region): the region cut by the half-planes "nearer to
    /// `t` than to `s`" of the cell's neighbours `t`. Corners are computed in `f64`.
    pub fn cells(&self, region: &ClipRegion) -> Vec<Vec<Point2>> {
        let adj = self.neighbours();
        (0..self.sites.len())
            .map(|s| {
                if self.site_half_edge[s].is_none() {
                    return Vec::new();
                }
                let mut poly = region.ring().to_vec();
                for &t in &adj[s] {
                    if poly.is_empty() {
                        break;
                    }
                    poly = cut(&poly, self.sites[t], self.sites[s]);
                }
                poly
            })
            .collect()
    }

    /// The cells clipped to the polygon set `clip` (any polygons, read even-odd), in site
    /// order: [`Self::cells`] on the polygon's bounding box, each then intersected with
    /// `clip` by the exact boolean operation (only the `h` hull corners have cells).
    ///
    /// # Errors
    /// As [`super::clip_cells_to_polygon`].
    pub fn cells_in_polygon(&self, clip: &MultiPolygon) -> Result<Vec<MultiPolygon>> {
        let segs = check_polygon(clip)?;
        let pts: Vec<Point2> = segs.iter().map(|s| s.a).collect();
        let region = ClipRegion::from_bbox(crate::kernel::Bbox2::of_points(&pts))?;
        self.cells(&region)
            .into_iter()
            .map(|c| {
                if c.is_empty() {
                    Ok(MultiPolygon::default())
                } else {
                    let c = MultiPolygon(vec![Polygon::new(c, Vec::new())]);
                    boolean(&c, clip, BooleanOp::Intersection)
                }
            })
            .collect()
    }

    /// Check the structure (as [`VoronoiDiagram::validate`], over the sites with cells:
    /// twins, `next`/`prev`, vertex degrees and sites, Euler's formula) and that the sites
    /// with cells are exactly the hull corners.
    pub fn validate(&self) -> Result<()> {
        let fail = |m: String| Err(Error::Verification(m));
        let mut id = vec![NIL; self.sites.len()];
        for (k, &s) in self.hull.iter().enumerate() {
            if s >= self.sites.len() || id[s] != NIL {
                return fail(format!("hull corner {s} out of range or repeated"));
            }
            id[s] = k;
        }
        if self.hull.len() >= 2 {
            for (s, h) in self.site_half_edge.iter().enumerate() {
                if h.is_some() != (id[s] != NIL) {
                    return fail(format!("site {s}: has a cell iff it is a hull corner"));
                }
            }
        }
        let mut half_edges = self.half_edges.clone();
        for h in &mut half_edges {
            match id.get(h.site) {
                Some(&k) if k != NIL => h.site = k,
                _ => return fail(format!("a half-edge bounds site {} off the hull", h.site)),
            }
        }
        let mut vertices = self.vertices.clone();
        for v in &mut vertices {
            for s in &mut v.sites {
                *s = id.get(*s).copied().unwrap_or(NIL);
            }
            v.sites.sort_unstable();
        }
        VoronoiDiagram {
            sites: self.hull.iter().map(|&s| self.sites[s]).collect(),
            site_input_index: self
                .hull
                .iter()
                .map(|&s| self.site_input_index[s])
                .collect(),
            input_to_site: Vec::new(),
            vertices,
            half_edges,
            site_half_edge: self.hull.iter().map(|&s| self.site_half_edge[s]).collect(),
        }
        .validate()
    }
}

/// The farthest-point Voronoi diagram of `points`, O(n log n) (see the module docs).
///
/// ```
/// use compgeom::voronoi::farthest_point_voronoi;
/// use compgeom::Point2;
/// // A square and its centre: the centre has no cell; one vertex of degree 4.
/// let pts = [(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0), (1.0, 1.0)].map(Point2::from);
/// let f = farthest_point_voronoi(&pts).unwrap();
/// assert_eq!(f.hull.len(), 4);
/// assert_eq!(f.site_half_edge[4], None);
/// assert_eq!(f.vertices.len(), 1);
/// assert_eq!(f.vertices[0].point, Point2::new(1.0, 1.0));
/// assert_eq!(f.edge_count(), 4);
/// f.validate().unwrap();
/// ```
///
/// # Errors
/// `Error::NonFinite` naming the first point with a NaN or infinite coordinate.
pub fn farthest_point_voronoi(points: &[Point2]) -> Result<FarthestVoronoi> {
    ensure_finite(points, "point")?;
    let (sites, site_input_index, input_to_site, _) = dedupe(points);
    // Hull corners as site indices (the hull is clockwise; make it counter-clockwise).
    let mut hull = if sites.is_empty() {
        Vec::new()
    } else {
        convex_hull_indices(&sites, &HullOptions::default())?
    };
    hull.reverse();
    let mut out = FarthestVoronoi {
        site_half_edge: vec![None; sites.len()],
        sites,
        site_input_index,
        input_to_site,
        hull,
        vertices: Vec::new(),
        half_edges: Vec::new(),
    };
    match out.hull.len() {
        0 | 1 => {}
        2 => {
            // Collinear sites: only the two extremes have cells, split by their bisector.
            let (a, b) = (out.hull[0], out.hull[1]);
            out.half_edges = vec![
                HalfEdge {
                    origin: None,
                    twin: 1,
                    next: None,
                    prev: None,
                    site: a,
                },
                HalfEdge {
                    origin: None,
                    twin: 0,
                    next: None,
                    prev: None,
                    site: b,
                },
            ];
            out.site_half_edge[a] = Some(0);
            out.site_half_edge[b] = Some(1);
        }
        _ => {
            let triangles = farthest_delaunay(&out.sites, &out.hull);
            let t = Triangulation::from_parts(out.sites.clone(), triangles, Vec::new())?;
            let d = from_triangulation(&t);
            out.vertices = d.vertices;
            out.half_edges = d.half_edges;
            out.site_half_edge = d.site_half_edge;
        }
    }
    Ok(out)
}

/// The farthest-point Delaunay triangulation of the convex polygon `corners` (site
/// indices, counter-clockwise, strictly convex, at least three): counter-clockwise
/// triangles whose circumcircles contain every corner. Expected O(h) (see the module docs).
fn farthest_delaunay(sites: &[Point2], corners: &[usize]) -> Vec<[u32; 3]> {
    let h = corners.len();
    // A reproducible random order of the polygon positions 0..h.
    let mut order: Vec<usize> = (0..h).collect();
    let mut seed = 0x9E37_79B9_7F4A_7C15u64 ^ (h as u64);
    for i in (1..h).rev() {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        order.swap(i, (seed % (i as u64 + 1)) as usize);
    }
    // The first three in the order stay; remove the others last-first, remembering the
    // neighbours each had on the polygon when it was removed.
    let mut prev: Vec<usize> = (0..h).map(|i| (i + h - 1) % h).collect();
    let mut next: Vec<usize> = (0..h).map(|i| (i + 1) % h).collect();
    let mut at_removal = vec![(0, 0); h];
    for &p in order[3..].iter().rev() {
        let (q, r) = (prev[p], next[p]);
        at_removal[p] = (q, r);
        next[q] = r;
        prev[r] = q;
    }
    let mut m = Mesh {
        sites,
        corners,
        tri: Vec::with_capacity(2 * h),
        adj: Vec::with_capacity(2 * h),
        boundary: vec![NIL; h],
    };
    // The first triangle, counter-clockwise in polygon order.
    let mut first = [order[0], order[1], order[2]];
    first.sort_unstable();
    m.tri.push(first);
    m.adj.push([NIL; 3]);
    for &v in &first {
        m.boundary[v] = 0;
    }
    let mut stack = Vec::new();
    for &p in &order[3..] {
        let (q, r) = at_removal[p];
        // q -> r is a boundary edge of the current polygon; p lies to its right.
        let inner = m.boundary[q];
        let t = m.tri.len();
        // New triangle (p, r, q): side opposite p is r -> q, across it the inner triangle.
        m.tri.push([p, r, q]);
        m.adj.push([inner, NIL, NIL]);
        let i = m.side_of(inner, q);
        m.adj[inner][i] = t;
        m.boundary[q] = t;
        m.boundary[p] = t;
        stack.push(t);
        while let Some(t) = stack.pop() {
            if let Some(n) = m.flip_if_illegal(t) {
                stack.push(t);
                stack.push(n);
            }
        }
    }
    m.tri.iter().map(|t| t.map(|i| corners[i] as u32)).collect()
}

/// The triangulation under construction: triangles over polygon positions, counter-clockwise,
/// with the new corner first in triangles that are still being legalized.
struct Mesh<'a> {
    sites: &'a [Point2],
    corners: &'a [usize],
    tri: Vec<[usize; 3]>,
    /// `adj[t][i]`: the triangle across the side opposite corner `i` (`NIL` on the boundary).
    adj: Vec<[usize; 3]>,
    /// For each polygon position `v` on the current polygon, the triangle holding the
    /// boundary edge from `v` to its successor.
    boundary: Vec<usize>,
}

impl Mesh<'_> {
    fn pt(&self, v: usize) -> Point2 {
        self.sites[self.corners[v]]
    }

    /// The index `i` of the side of `t` that starts at corner `v` (the side from `v` to the
    /// next corner is opposite the corner after that).
    fn side_of(&self, t: usize, v: usize) -> usize {
        let k = (0..3).find(|&k| self.tri[t][k] == v).unwrap_or(0);
        (k + 2) % 3
    }

    /// Triangle `t = (p, u, w)` with the new corner `p` first: if the triangle across
    /// `u -> w` has `p` strictly outside its circle, flip the edge to `p -> s`, making
    /// `t = (p, u, s)` and returning the other triangle, now `(p, s, w)`.
    fn flip_if_illegal(&mut self, t: usize) -> Option<usize> {
        let [p, u, w] = self.tri[t];
        let n = self.adj[t][0];
        if n == NIL {
            return None;
        }
        let j = (0..3).find(|&j| self.tri[n][j] != u && self.tri[n][j] != w)?;
        let s = self.tri[n][j];
        let [a, b, c] = self.tri[n].map(|v| self.pt(v));
        if incircle(a, b, c, self.pt(p)) != CircleSide::Outside {
            return None;
        }
        // Outer neighbours: across (w, p) and (p, u) in t; across (u, s) and (s, w) in n.
        let ta = self.adj[t][1];
        let tb = self.adj[t][2];
        let nc = self.adj[n][(j + 1) % 3];
        let nd = self.adj[n][(j + 2) % 3];
        self.tri[t] = [p, u, s];
        self.adj[t] = [nc, n, tb];
        self.tri[n] = [p, s, w];
        self.adj[n] = [nd, ta, t];
        if nc == NIL {
            self.boundary[u] = t;
        } else {
            self.relink(nc, n, t);
        }
        if ta == NIL {
            self.boundary[w] = n;
        } else {
            self.relink(ta, t, n);
        }
        Some(n)
    }

    /// In triangle `x`, the neighbour link to `from` now goes to `to`.
    fn relink(&mut self, x: usize, from: usize, to: usize) {
        for k in 0..3 {
            if self.adj[x][k] == from {
                self.adj[x][k] = to;
            }
        }
    }
}

/// Verify a farthest-point Voronoi diagram of `points`: the structure
/// ([`FarthestVoronoi::validate`]), the input-to-site map, the hull corners (exactly the
/// sites not inside or on the hull of the others), every vertex's sites exactly on one
/// circle that contains every site (exact in-circle tests; against all hull corners), and
/// the vertices' rounded positions equidistant from their sites up to rounding.
pub fn verify_farthest(points: &[Point2], f: &FarthestVoronoi) -> Result<()> {
    let fail = |m: String| Err(Error::Verification(m));
    f.validate()?;
    if f.input_to_site.len() != points.len() {
        return fail("input-to-site map has the wrong length".into());
    }
    for (i, &s) in f.input_to_site.iter().enumerate() {
        if f.sites.get(s) != Some(&points[i]) {
            return fail(format!("input point {i} maps to site {s} at another place"));
        }
    }
    let want = if f.sites.is_empty() {
        Vec::new()
    } else {
        let mut h = convex_hull_indices(&f.sites, &HullOptions::default())?;
        h.reverse();
        h
    };
    let mut got = f.hull.clone();
    got.sort_unstable();
    let mut want_sorted = want;
    want_sorted.sort_unstable();
    if got != want_sorted {
        return fail("the sites with cells are not the hull corners".into());
    }
    for (v, vert) in f.vertices.iter().enumerate() {
        let s = &vert.sites;
        if s.len() < 3 {
            return fail(format!("vertex {v} has fewer than three sites"));
        }
        let (a, mut b, mut c) = (f.sites[s[0]], f.sites[s[1]], f.sites[s[2]]);
        match crate::kernel::orient2d(a, b, c) {
            crate::kernel::Orientation::Collinear => {
                return fail(format!("vertex {v}: its sites are collinear"))
            }
            crate::kernel::Orientation::Clockwise => std::mem::swap(&mut b, &mut c),
            _ => {}
        }
        for &x in s {
            if incircle(a, b, c, f.sites[x]) != CircleSide::OnCircle {
                return fail(format!("vertex {v}: site {x} is not on its circle"));
            }
        }
        for &x in &f.hull {
            if incircle(a, b, c, f.sites[x]) == CircleSide::Outside {
                return fail(format!("vertex {v}: site {x} lies outside its circle"));
            }
        }
        let p = vert.point;
        let dist = |x: usize| (f.sites[x].x - p.x).hypot(f.sites[x].y - p.y);
        let r0 = dist(s[0]);
        let scale = r0 + p.x.abs().max(p.y.abs());
        if s.iter().any(|&x| (dist(x) - r0).abs() > 1e-9 * scale) {
            return fail(format!(
                "vertex {v} at {p:?} is not equidistant from its sites"
            ));
        }
    }
    Ok(())
}
