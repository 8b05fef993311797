//! [`VoronoiCells`]: the Voronoi diagram in a compact form grouped by cell, built in one
//! pass from the Delaunay triangulation (book §9.2, Theorem 9.6: the Voronoi diagram is the
//! dual of the Delaunay triangulation).
//!
//! Layout: the Voronoi vertices (one circumcentre per Delaunay triangle, or per group of
//! triangles with one circumcircle), and for every site the edges of its cell,
//! counter-clockwise, stored contiguously (`offsets` in the style of compressed sparse rows;
//! no allocation per cell or per vertex). An edge is two `u32`s: its origin vertex (or
//! infinity) and the site across it; its destination is the origin of the next edge of
//! the same cell. [`VoronoiCells::to_diagram`] turns it into the half-edge
//! [`VoronoiDiagram`]; [`VoronoiCells::clip`] gives the cells as polygons clipped to a
//! region, cutting only the cells that reach the region's boundary.
//!
//! Construction: circumcentres are computed once per triangle in one loop; adjacent
//! triangles with the same circumcircle (four or more cocircular sites) are grouped with a
//! filtered, then exact, in-circle test (see `cocircular`); then each site's triangles are
//! visited counter-clockwise around it through the neighbour links, starting, for a hull
//! site, at the triangle after the hull edge. O(n) after the triangulation.
//!
//! ## Degenerate input
//!
//! - Cocircular sites: one vertex of degree > 3; edges between triangles of one group are
//!   not emitted.
//! - Duplicates: merged by the triangulation ([`VoronoiCells::input_to_site`]).
//! - Collinear sites (no triangles): sorted along their line; each cell is a strip or
//!   half-plane bounded by lines (edges from infinity to infinity).
//! - A vertex of the triangulation without triangles (only possible for a triangulation
//!   made with [`Triangulation::from_parts`]): an empty cell.

use super::clip::{cut, ClipRegion};
use super::diagram::{HalfEdge, Vertex, VoronoiDiagram};
use super::predicates::circumcentre;
use crate::delaunay::pred::{in_circle_grid, small_integer_grid};
use crate::delaunay::{delaunay, Triangulation, NO_NEIGHBOR};
use crate::kernel::{compare_xy, incircle, CircleSide, Point2};
use crate::Result;
use rayon::prelude::*;

/// From this many sites on, [`VoronoiCells::clip`] runs on the rayon pool.
const PARALLEL_CLIP: usize = 20_000;

/// Marks "at infinity" in [`CellEdge`]'s origin (and "unset" during construction).
const NONE: u32 = u32::MAX;
/// High bit of a site's start triangle: the site is on the hull.
const HULL: u32 = 1 << 31;

/// One edge of a Voronoi cell, 8 bytes: where it starts and which site is across it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct CellEdge {
    origin: u32,
    neighbour: u32,
}

impl CellEdge {
    /// The Voronoi vertex where the edge starts (index into [`VoronoiCells::vertices`]),
    /// `None` when it comes from infinity.
    #[inline]
    pub fn origin(&self) -> Option<usize> {
        (self.origin != NONE).then_some(self.origin as usize)
    }

    /// The site whose cell is on the other side of the edge.
    #[inline]
    pub fn neighbour(&self) -> usize {
        self.neighbour as usize
    }
}

/// The Voronoi diagram as cells: vertices, and each site's edges counter-clockwise.
///
/// Same diagram as [`super::dual_voronoi`] and [`super::fortune_voronoi`] (the tests hold
/// them to it), in about a quarter of the memory of [`VoronoiDiagram`].
///
/// ```
/// use compgeom::voronoi::{voronoi_cells, ClipRegion};
/// use compgeom::Point2;
/// // A 3 × 3 grid: four degree-4 vertices; the middle cell is the square around (1, 1).
/// let pts: Vec<Point2> = (0..9).map(|i| Point2::new((i % 3) as f64, (i / 3) as f64)).collect();
/// let c = voronoi_cells(&pts).unwrap();
/// assert_eq!(c.vertices().len(), 4);
/// assert_eq!(c.cell(4).len(), 4);
/// assert!(c.cell(4).iter().all(|e| e.origin().is_some()));
/// let clipped = c.clip(&ClipRegion::rect(0.0, 0.0, 2.0, 2.0).unwrap());
/// assert_eq!(clipped[0], vec![Point2::new(0.0, 0.0), Point2::new(0.5, 0.0), Point2::new(0.5, 0.5), Point2::new(0.0, 0.5)]);
/// assert_eq!(clipped[4].len(), 4);
/// c.to_diagram().validate().unwrap();
/// ```
#[derive(Debug, Clone, PartialEq, Default)]
pub struct VoronoiCells {
    sites: Vec<Point2>,
    input_to_site: Vec<u32>,
    vertices: Vec<Point2>,
    offsets: Vec<u32>,
    edges: Vec<CellEdge>,
    /// The sites with a cell, in the order their cells were built (spatially coherent):
    /// [`VoronoiCells::to_diagram`] visits them in this order for locality.
    order: Vec<u32>,
}

/// The Voronoi cells of `points`, as the dual of their Delaunay triangulation
/// ([`crate::delaunay::delaunay`]). O(n log n).
///
/// # Errors
/// `Error::NonFinite` naming the first point with a NaN or infinite coordinate; too many
/// points for the triangulation (see [`crate::delaunay::MAX_POINTS`]).
pub fn voronoi_cells(points: &[Point2]) -> Result<VoronoiCells> {
    Ok(VoronoiCells::from_triangulation(&delaunay(points)?))
}

impl VoronoiCells {
    /// The cells dual to a Delaunay triangulation. Sites are the triangulation's vertices,
    /// in its order. If the triangulation is not Delaunay the result is well formed but not
    /// a Voronoi diagram.
    pub fn from_triangulation(t: &Triangulation) -> VoronoiCells {
        let sites = t.vertices().to_vec();
        let input_to_site = t.input_to_vertex().to_vec();
        let (vertices, offsets, edges, order) = if t.triangles().is_empty() {
            collinear(&sites)
        } else {
            build(t)
        };
        VoronoiCells {
            sites,
            input_to_site,
            vertices,
            offsets,
            edges,
            order,
        }
    }

    /// The distinct sites, in the order of their first occurrence in the input.
    pub fn sites(&self) -> &[Point2] {
        &self.sites
    }

    /// For each input point, the index of its site.
    pub fn input_to_site(&self) -> &[u32] {
        &self.input_to_site
    }

    /// The Voronoi vertices (circumcentres, rounded to `f64`; topology never depends on
    /// these values).
    pub fn vertices(&self) -> &[Point2] {
        &self.vertices
    }

    /// The edges of the cell of `site`, counter-clockwise. Edge `k` runs from its origin to
    /// the origin of edge `k + 1` (cyclically). A bounded cell has no origin at infinity;
    /// an unbounded one starts with the edge from infinity and ends with the edge to
    /// infinity; a strip between parallel lines has two edges, both lines.
    ///
    /// # Panics
    /// If `site` is out of range.
    pub fn cell(&self, site: usize) -> &[CellEdge] {
        &self.edges[self.offsets[site] as usize..self.offsets[site + 1] as usize]
    }

    /// Number of Voronoi edges (each shared by two cells).
    pub fn edge_count(&self) -> usize {
        self.edges.len() / 2
    }

    /// The cell of every site clipped to `region`: the same polygons as
    /// [`super::clip_cells`] on [`Self::to_diagram`] (counter-clockwise rings, empty where a
    /// cell misses the region). A bounded cell whose vertices are all strictly inside the
    /// region is copied; only the others are cut (by the bisectors of their neighbours).
    /// Cells are independent, so large diagrams are clipped on the rayon pool (the result
    /// is the same, in the same order).
    pub fn clip(&self, region: &ClipRegion) -> Vec<Vec<Point2>> {
        let inside = super::clip::inside_test(region);
        let flags: Vec<bool> = self.vertices.iter().map(|&p| inside(p)).collect();
        let one = |s: usize| -> Vec<Point2> {
            let cell = self.cell(s);
            let whole = cell.len() >= 3
                && cell
                    .iter()
                    .all(|e| e.origin != NONE && flags[e.origin as usize]);
            if whole {
                return cell
                    .iter()
                    .map(|e| self.vertices[e.origin as usize])
                    .collect();
            }
            let mut poly = region.ring().to_vec();
            for e in cell {
                if poly.is_empty() {
                    break;
                }
                poly = cut(&poly, self.sites[s], self.sites[e.neighbour as usize]);
            }
            poly
        };
        if self.sites.len() < PARALLEL_CLIP {
            (0..self.sites.len()).map(one).collect()
        } else {
            (0..self.sites.len()).into_par_iter().map(one).collect()
        }
    }

    /// The half-edge [`VoronoiDiagram`] of the same diagram.
    pub fn to_diagram(&self) -> VoronoiDiagram {
        let n = self.sites.len();
        let m = self.edges.len();
        // Number the twin pairs in cell order; the twin of an edge of cell `v` with
        // neighbour `b` is the edge of cell `b` with neighbour `v` (two cells share at most
        // one edge, except strips, whose two edges have different neighbours).
        let mut he = vec![NONE; m];
        let mut pairs = 0u32;
        for &v in &self.order {
            let v = v as usize;
            for e in self.offsets[v] as usize..self.offsets[v + 1] as usize {
                if he[e] != NONE {
                    continue;
                }
                let b = self.edges[e].neighbour as usize;
                let (lo, hi) = (self.offsets[b] as usize, self.offsets[b + 1] as usize);
                let Some(t) = (lo..hi).find(|&f| self.edges[f].neighbour as usize == v) else {
                    continue;
                };
                he[e] = 2 * pairs;
                he[t] = 2 * pairs + 1;
                pairs += 1;
            }
        }
        let mut half_edges = vec![
            HalfEdge {
                origin: None,
                twin: 0,
                next: None,
                prev: None,
                site: 0,
            };
            2 * pairs as usize
        ];
        let mut vertices: Vec<Vertex> = self
            .vertices
            .iter()
            .map(|&point| Vertex {
                point,
                sites: Vec::with_capacity(3),
            })
            .collect();
        let mut site_half_edge = vec![None; n];
        for &v in &self.order {
            let v = v as usize;
            let (lo, hi) = (self.offsets[v] as usize, self.offsets[v + 1] as usize);
            let k = hi - lo;
            for e in lo..hi {
                if he[e] == NONE {
                    continue;
                }
                let edge = self.edges[e];
                let next = lo + (e - lo + 1) % k;
                let prev = lo + (e - lo + k - 1) % k;
                let h = he[e] as usize;
                if edge.origin != NONE {
                    vertices[edge.origin as usize].sites.push(v);
                }
                half_edges[h] = HalfEdge {
                    origin: edge.origin(),
                    twin: h ^ 1,
                    next: (self.edges[next].origin != NONE).then(|| he[next] as usize),
                    prev: (edge.origin != NONE).then(|| he[prev] as usize),
                    site: v,
                };
                site_half_edge[v].get_or_insert(h);
            }
        }
        for v in &mut vertices {
            v.sites.sort_unstable();
        }
        let input_to_site: Vec<usize> = self.input_to_site.iter().map(|&v| v as usize).collect();
        let mut site_input_index = vec![usize::MAX; n];
        for (i, &s) in input_to_site.iter().enumerate() {
            if site_input_index[s] == usize::MAX {
                site_input_index[s] = i;
            }
        }
        VoronoiDiagram {
            sites: self.sites.clone(),
            site_input_index,
            input_to_site,
            vertices,
            half_edges,
            site_half_edge,
        }
    }
}

type Parts = (Vec<Point2>, Vec<u32>, Vec<CellEdge>, Vec<u32>);

/// Collinear (or fewer than two) sites: each separated from its neighbours along the line
/// by a bisector line.
fn collinear(sites: &[Point2]) -> Parts {
    let n = sites.len();
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| compare_xy(sites[a], sites[b]));
    let mut rank = vec![0usize; n];
    for (r, &s) in order.iter().enumerate() {
        rank[s] = r;
    }
    let mut offsets = Vec::with_capacity(n + 1);
    let mut edges = Vec::with_capacity(2 * n);
    for &r in &rank {
        offsets.push(edges.len() as u32);
        // The next site along the line, then the previous one.
        for nb in [r.checked_add(1).filter(|&x| x < n), r.checked_sub(1)]
            .into_iter()
            .flatten()
        {
            edges.push(CellEdge {
                origin: NONE,
                neighbour: order[nb] as u32,
            });
        }
    }
    offsets.push(edges.len() as u32);
    (
        Vec::new(),
        offsets,
        edges,
        order.iter().map(|&s| s as u32).collect(),
    )
}

/// Union-find root with path halving.
fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let p = parent[parent[x as usize] as usize];
        parent[x as usize] = p;
        x = p;
    }
    x
}

/// For each triangle, its Voronoi vertex, and the vertices' points; triangles with one
/// circumcircle share a vertex. Without cocircular neighbours the map is the identity
/// (`None`) and the points are the circumcentres themselves.
fn group(t: &Triangulation, centres: Vec<Point2>) -> (Option<Vec<u32>>, Vec<Point2>) {
    let (tris, nbr, pts) = (t.triangles(), t.neighbors(), t.vertices());
    let nt = tris.len();
    // On a small integer grid (all squares cocircular, the filter failing on each) the
    // unfiltered grid in-circle test is exact (see `delaunay::pred`).
    let grid = small_integer_grid(pts);
    let mut parent: Vec<u32> = Vec::new();
    for (a, tri) in tris.iter().enumerate() {
        for i in 0..3 {
            let b = nbr[a][i];
            if b == NO_NEIGHBOR || (b as usize) < a {
                continue;
            }
            let (u, w) = (tri[(i + 1) % 3], tri[(i + 2) % 3]);
            let other = tris[b as usize];
            let Some(&d) = other.iter().find(|&&x| x != u && x != w) else {
                continue;
            };
            let p = |x: u32| pts[x as usize];
            let (pa, pb, pc, pd) = (p(tri[0]), p(tri[1]), p(tri[2]), p(d));
            let on_circle = if grid {
                in_circle_grid(pa, pb, pc, pd) == 0
            } else {
                cocircular(pa, pb, pc, pd)
            };
            if on_circle {
                if parent.is_empty() {
                    parent = (0..nt as u32).collect();
                }
                let (ra, rb) = (find(&mut parent, a as u32), find(&mut parent, b));
                if ra != rb {
                    parent[ra.max(rb) as usize] = ra.min(rb);
                }
            }
        }
    }
    if parent.is_empty() {
        return (None, centres);
    }
    // Roots are the smallest triangle of their group, so numbering groups by first
    // appearance keeps the vertices in triangle order.
    let mut id = vec![NONE; nt];
    let mut points = Vec::with_capacity(nt);
    for a in 0..nt {
        let r = find(&mut parent, a as u32) as usize;
        if id[r] == NONE {
            id[r] = points.len() as u32;
            points.push(centres[r]);
        }
        id[a] = id[r];
    }
    (Some(id), points)
}

/// The cells of a triangulation with at least one triangle.
///
/// Cells are stored in site order but filled in the order the sites first appear in the
/// triangle array, which follows the triangulation's spatial insertion order: the
/// triangles around consecutive sites are then near each other in memory, where site
/// order (the input order) would jump at random.
fn build(t: &Triangulation) -> Parts {
    let (tris, nbr, pts) = (t.triangles(), t.neighbors(), t.vertices());
    let (n, nt) = (pts.len(), tris.len());
    let p = |x: u32| pts[x as usize];
    let centres: Vec<Point2> = tris
        .iter()
        .map(|tr| circumcentre(p(tr[0]), p(tr[1]), p(tr[2])))
        .collect();
    let (ids, vertices) = group(t, centres);
    let gid = |tri: usize| ids.as_ref().map_or(tri as u32, |g| g[tri]);
    // 1. Each site's first triangle counter-clockwise (the one after its hull edge, if
    //    any) and its number of edges: one per triangle around it, one more from infinity
    //    on the hull, one fewer per side shared with a triangle of the same group.
    //    Triangle (v, a, b) (v at corner k) follows its clockwise neighbour across edge
    //    (v, a), which is opposite corner k + 2.
    //    Both are kept side by side (one cache line per site, sites being in input
    //    order, i.e. at random in memory).
    let mut site = vec![[NONE, 0u32]; n + 1];
    for (ti, tr) in tris.iter().enumerate() {
        for k in 0..3 {
            let v = tr[k] as usize;
            let across = nbr[ti][(k + 2) % 3];
            let [first, count] = &mut site[v];
            *count = count.wrapping_add(1);
            if across == NO_NEIGHBOR {
                *first = ti as u32 | HULL;
                *count = count.wrapping_add(1);
            } else if *first == NONE {
                *first = ti as u32;
            }
            if ids.is_some()
                && across != NO_NEIGHBOR
                && (across as usize) > ti
                && gid(across as usize) == gid(ti)
            {
                // Wrapping arithmetic: the other end's count may not have been raised
                // yet; the final counts are non-negative.
                *count = count.wrapping_sub(1);
                let c = &mut site[tr[(k + 1) % 3] as usize][1];
                *c = c.wrapping_sub(1);
            }
        }
    }
    // 2. Offsets: prefix sums of the counts.
    let mut total = 0u32;
    for s in site.iter_mut() {
        let k = s[1];
        s[1] = total;
        total += k;
    }
    let mut edges = vec![
        CellEdge {
            origin: NONE,
            neighbour: NONE,
        };
        total as usize
    ];
    // 3. Walk around each site, in order of first appearance in the triangle array; a
    //    visited site's first triangle is set to NONE. The order is kept for
    //    `to_diagram`.
    let mut order = Vec::with_capacity(n);
    for tr in tris {
        for &v in tr {
            let v = v as usize;
            let f = site[v][0];
            if f == NONE {
                continue;
            }
            site[v][0] = NONE;
            order.push(v as u32);
            let t0 = (f & !HULL) as usize;
            let corner = |tri: usize| (0..3).find(|&k| tris[tri][k] as usize == v).unwrap_or(0);
            let (mut at, end) = (site[v][1] as usize, site[v + 1][1] as usize);
            let mut put = |e: CellEdge| {
                // Bounded by the count (a triangulation that is not one could disagree).
                if at < end {
                    edges[at] = e;
                    at += 1;
                }
            };
            if f & HULL != 0 {
                let k = corner(t0);
                put(CellEdge {
                    origin: NONE,
                    neighbour: tris[t0][(k + 1) % 3],
                });
            }
            // Around v: from triangle (v, a, b) across edge (v, b) (opposite a, corner
            // k + 1) to the next triangle; the Voronoi edge between their centres has b
            // across it.
            let mut tri = t0;
            for _ in 0..nt {
                let k = corner(tri);
                let b = tris[tri][(k + 2) % 3];
                let next = nbr[tri][(k + 1) % 3];
                let g = gid(tri);
                if next == NO_NEIGHBOR || gid(next as usize) != g {
                    put(CellEdge {
                        origin: g,
                        neighbour: b,
                    });
                }
                if next == NO_NEIGHBOR {
                    break;
                }
                tri = next as usize;
                if tri == t0 {
                    break;
                }
            }
        }
    }
    let offsets = site.iter().map(|s| s[1]).collect();
    (vertices, offsets, edges, order)
}

/// Are `a, b, c, d` exactly on one circle? A floating-point filter settles the common
/// case (clearly not cocircular) with Shewchuk's error bound for the in-circle determinant;
/// small integer offsets (grids) are settled by the same evaluation, which is then exact;
/// otherwise the exact in-circle test decides.
#[inline]
pub(crate) fn cocircular(a: Point2, b: Point2, c: Point2, d: Point2) -> bool {
    let (adx, ady) = (a.x - d.x, a.y - d.y);
    let (bdx, bdy) = (b.x - d.x, b.y - d.y);
    let (cdx, cdy) = (c.x - d.x, c.y - d.y);
    let (bdxcdy, cdxbdy) = (bdx * cdy, cdx * bdy);
    let (cdxady, adxcdy) = (cdx * ady, adx * cdy);
    let (adxbdy, bdxady) = (adx * bdy, bdx * ady);
    let alift = adx * adx + ady * ady;
    let blift = bdx * bdx + bdy * bdy;
    let clift = cdx * cdx + cdy * cdy;
    let det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
    let permanent = (bdxcdy.abs() + cdxbdy.abs()) * alift
        + (cdxady.abs() + adxcdy.abs()) * blift
        + (adxbdy.abs() + bdxady.abs()) * clift;
    // (10 + 96ε)ε for ε = 2⁻⁵³, plus an absolute term covering underflow; only used
    // when nothing overflowed.
    const BOUND: f64 = (10.0 + 96.0 * f64::EPSILON / 2.0) * (f64::EPSILON / 2.0);
    if det.is_finite() && permanent.is_finite() && det.abs() > BOUND * permanent + 1e-300 {
        return false;
    }
    if small_integers(&[a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y]) {
        // Integers below 2¹¹ in magnitude: offsets below 2¹², squares and products below
        // 2²⁴, lifts below 2²⁵, each term below 2⁵⁰ and the sum below 2⁵³: every
        // operation above was exact.
        return det == 0.0;
    }
    incircle(a, b, c, d) == CircleSide::OnCircle
}

/// All values integers of magnitude below 2¹¹.
#[inline]
fn small_integers(v: &[f64; 8]) -> bool {
    const LIMIT: f64 = 2048.0;
    // `(x as i64) as f64 == x` is the integer test without a `trunc` library call.
    v.iter().all(|&x| x.abs() < LIMIT && (x as i64) as f64 == x)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The filtered test agrees with the exact in-circle test on exactly cocircular points,
    /// points one ulp off the circle, huge and tiny scales, and small-integer quadruples.
    #[test]
    fn cocircular_filter_agrees_with_incircle() {
        let next = |v: f64| f64::from_bits(v.to_bits() + 1);
        let base = [(5.0, 0.0), (0.0, 5.0), (-3.0, 4.0), (4.0, -3.0)];
        for scale in [1.0, 1e-150, 1e150, 3.0e-300, 1e300] {
            let p: Vec<Point2> = base
                .iter()
                .map(|&(x, y)| Point2::new(x * scale, y * scale))
                .collect();
            let mut off = p.clone();
            off[3] = Point2::new(next(off[3].x), off[3].y);
            for q in [&p, &off] {
                let want = incircle(q[0], q[1], q[2], q[3]) == CircleSide::OnCircle;
                assert_eq!(cocircular(q[0], q[1], q[2], q[3]), want, "{q:?}");
            }
        }
        // Every quadruple from a small integer pattern near the limit of the integer stage.
        let mut below = crate::testing::below(7);
        let mut r = || below(4095) as f64 - 2047.0;
        for _ in 0..20_000 {
            let q: Vec<Point2> = (0..4).map(|_| Point2::new(r(), r())).collect();
            let want = incircle(q[0], q[1], q[2], q[3]) == CircleSide::OnCircle;
            assert_eq!(cocircular(q[0], q[1], q[2], q[3]), want, "{q:?}");
        }
        // Cocircular integer points on x² + y² = 5² shifted near the limit.
        for (dx, dy) in [(2040.0, -2040.0), (0.0, 0.0), (-2042.0, 1000.0)] {
            let q: Vec<Point2> = base
                .iter()
                .map(|&(x, y)| Point2::new(x + dx, y + dy))
                .collect();
            assert!(cocircular(q[0], q[1], q[2], q[3]), "{q:?}");
        }
    }

    /// A half-edge by what defines it exactly: (left site, right site, origin vertex
    /// sites and point, destination vertex sites); `None` at infinity.
    type Key = (
        usize,
        usize,
        Option<(Vec<usize>, [u64; 2])>,
        Option<Vec<usize>>,
    );

    fn keys(d: &VoronoiDiagram) -> Vec<Key> {
        let v = |x: Option<usize>| {
            x.map(|x| {
                let p = d.vertices[x].point;
                (d.vertices[x].sites.clone(), [p.x.to_bits(), p.y.to_bits()])
            })
        };
        let mut k: Vec<Key> = (0..d.half_edges.len())
            .map(|h| {
                let e = &d.half_edges[h];
                (
                    e.site,
                    d.half_edges[e.twin].site,
                    v(e.origin),
                    v(d.destination(h)).map(|x| x.0),
                )
            })
            .collect();
        k.sort();
        k
    }

    /// The new conversion gives exactly the diagram of the former one (same vertices with
    /// bit-identical points, same directed edges), a valid structure, and clipped cells
    /// identical to `clip_cells` on its diagram and equal in area to the former ones.
    fn same_as_reference(points: &[Point2]) {
        let t = delaunay(points).unwrap();
        let cells = VoronoiCells::from_triangulation(&t);
        let new = cells.to_diagram();
        let old = super::super::dual::reference_from_triangulation(&t);
        new.validate().unwrap();
        assert_eq!(new.sites, old.sites);
        assert_eq!(new.input_to_site, old.input_to_site);
        assert_eq!(new.site_input_index, old.site_input_index);
        assert_eq!(new.vertices.len(), old.vertices.len());
        assert_eq!(keys(&new), keys(&old), "{} points", points.len());
        assert_eq!(cells.edge_count(), old.edge_count());
        let region = ClipRegion::around(points, 0.1).unwrap();
        let mine = cells.clip(&region);
        let same = super::super::clip_cells(&new, &region);
        if !new.vertices.is_empty() {
            // (Strips of collinear sites are cut in another order: equal up to rounding.)
            assert_eq!(mine, same);
        }
        let theirs = super::super::clip_cells(&old, &region);
        assert_eq!(mine.len(), theirs.len());
        // Areas relative to the region's, scaled by a power of two (no overflow).
        let r = region.ring();
        let scale = 2f64.powi((r[2].x - r[0].x).log2().floor() as i32);
        let area = |ring: &[Point2]| super::super::clip::ring_area_scaled(ring, scale);
        let whole = area(r);
        for (a, b) in mine.iter().zip(&theirs).chain(mine.iter().zip(&same)) {
            let (x, y) = (area(a), area(b));
            assert!((x - y).abs() <= 1e-9 * whole, "{x} vs {y}");
        }
    }

    fn lcg(seed: u64) -> impl FnMut() -> u64 {
        crate::testing::bits(seed)
    }

    #[test]
    fn conversion_matches_the_former_one() {
        let mut r = lcg(3);
        let mut unit = move || (r() as f64) / (1u64 << 53) as f64;
        // Random.
        // (30 000 sites: `clip` takes its parallel path, see PARALLEL_CLIP.)
        for n in [3, 4, 10, 200, 3000, 30_000] {
            let p: Vec<Point2> = (0..n).map(|_| Point2::new(unit(), unit())).collect();
            same_as_reference(&p);
        }
        // Grids (every square cocircular), shuffled, with duplicates.
        let mut r = lcg(5);
        for k in [2usize, 3, 7, 40, 150] {
            let mut p: Vec<Point2> = (0..k * k)
                .map(|i| Point2::new((i % k) as f64, (i / k) as f64))
                .collect();
            for i in (1..p.len()).rev() {
                p.swap(i, (r() % (i as u64 + 1)) as usize);
            }
            let dup: Vec<Point2> = p.iter().step_by(3).copied().collect();
            same_as_reference(&p);
            p.extend(dup);
            same_as_reference(&p);
        }
        // Lattice points on x² + y² = 5⁴ (many cocircular), plus the centre and more.
        let mut c: Vec<Point2> = Vec::new();
        for x in -25i32..=25 {
            for y in -25i32..=25 {
                if x * x + y * y == 625 {
                    c.push(Point2::new(x.into(), y.into()));
                }
            }
        }
        same_as_reference(&c);
        c.push(Point2::new(0.0, 0.0));
        same_as_reference(&c);
        c.push(Point2::new(30.0, 1.0));
        same_as_reference(&c);
        // Collinear, with duplicates; two points; one point.
        let line: Vec<Point2> = (0..12)
            .map(|i| Point2::new(f64::from(i % 7), 2.0 * f64::from(i % 7)))
            .collect();
        same_as_reference(&line);
        same_as_reference(&line[..2]);
        let one = [Point2::new(1.0, 1.0)];
        let t = delaunay(&one).unwrap();
        let cells = VoronoiCells::from_triangulation(&t);
        assert_eq!(
            cells.to_diagram(),
            super::super::dual::reference_from_triangulation(&t)
        );
        assert_eq!(
            cells.clip(&ClipRegion::rect(0.0, 0.0, 2.0, 2.0).unwrap())[0].len(),
            4
        );
        // Huge and tiny coordinates (the scaled circumcentre path).
        for s in [1e-200, 1e200] {
            let p: Vec<Point2> = (0..300)
                .map(|_| Point2::new(unit() * s, unit() * s))
                .collect();
            same_as_reference(&p);
        }
    }

    /// The fast circumcentre path gives the same bits as the scaled computation.
    #[test]
    fn circumcentre_fast_path_is_bit_identical() {
        let mut r = lcg(11);
        for _ in 0..20_000 {
            let e = (r() % 160) as i32 - 80;
            let mut v = || ((r() as f64) / (1u64 << 53) as f64 - 0.5) * 2f64.powi(e);
            let (a, b, c) = (
                Point2::new(v(), v()),
                Point2::new(v(), v()),
                Point2::new(v(), v()),
            );
            let (bx, by, cx, cy) = (b.x - a.x, b.y - a.y, c.x - a.x, c.y - a.y);
            let m = bx.abs().max(by.abs()).max(cx.abs()).max(cy.abs());
            let e = m.log2().floor() as i32;
            let (k1, k2) = (2f64.powi(-e / 2), 2f64.powi(-e + e / 2));
            let (bx, by, cx, cy) = (bx * k1 * k2, by * k1 * k2, cx * k1 * k2, cy * k1 * k2);
            let b2 = bx * bx + by * by;
            let c2 = cx * cx + cy * cy;
            let d = 2.0 * (bx * cy - by * cx);
            let (ux, uy) = ((cy * b2 - by * c2) / d, (bx * c2 - cx * b2) / d);
            let want = Point2::new(a.x + ux / k1 / k2, a.y + uy / k1 / k2);
            let got = circumcentre(a, b, c);
            assert_eq!(
                (got.x.to_bits(), got.y.to_bits()),
                (want.x.to_bits(), want.y.to_bits())
            );
        }
    }
}
