//! The Voronoi diagram as the dual of the Delaunay triangulation (book §9.2, Theorem 9.6):
//! the fast default of [`super::voronoi_diagram`].
//!
//! Every Delaunay triangle gives the Voronoi vertex at its circumcentre, every Delaunay
//! edge the Voronoi edge between the cells of its two end points: bounded between the
//! centres of its two triangles, a ray for a hull edge. The triangulation comes from
//! [`crate::delaunay::delaunay`] (spatial sort, walking location, exact flips).
//!
//! O(n log n) in all (the triangulation), O(n) for the conversion, which goes through the
//! compact [`VoronoiCells`] (one pass, grouped by cell).
//!
//! ## Degenerate input
//!
//! - Four or more cocircular sites: the triangulation splits their empty circle into
//!   several triangles with the same circumcircle. Adjacent triangles whose circles
//!   coincide (decided by the exact in-circle test of one triangle against the opposite
//!   vertex of the other) are merged into one vertex of degree > 3, and the Delaunay edges
//!   between them are dropped. Triangles with one empty circle always form a connected
//!   triangulated convex polygon, so merging across shared edges finds all of them.
//! - Duplicates are merged by the triangulation; [`VoronoiDiagram::input_to_site`] maps
//!   every input point to its site, sites are in first-seen order.
//! - Collinear sites (no triangles): the sites sorted along their line, consecutive ones
//!   separated by parallel edges without vertices.
//! - Fewer than two distinct sites: no edges.

#[cfg(test)]
use super::cells::cocircular;
use super::cells::VoronoiCells;
use super::diagram::VoronoiDiagram;
#[cfg(test)]
use super::diagram::{HalfEdge, Vertex};
#[cfg(test)]
use super::predicates::circumcentre;
#[cfg(test)]
use crate::delaunay::NO_NEIGHBOR;
use crate::delaunay::{delaunay, Triangulation};
#[cfg(test)]
use crate::kernel::compare_xy;
use crate::kernel::Point2;
use crate::Result;

#[cfg(test)]
const NIL: usize = usize::MAX;

/// The Voronoi diagram of `points` as the dual of their Delaunay triangulation.
///
/// The same diagram as [`super::fortune_voronoi`] (same sites, vertices given by the same
/// site sets, same edges), O(n log n) and several times faster.
///
/// ```
/// use compgeom::voronoi::{dual_voronoi, fortune_voronoi};
/// use compgeom::Point2;
/// // A 3 × 3 grid: four degree-4 vertices.
/// let pts: Vec<Point2> = (0..9).map(|i| Point2::new((i % 3) as f64, (i / 3) as f64)).collect();
/// let d = dual_voronoi(&pts).unwrap();
/// d.validate().unwrap();
/// assert_eq!(d.vertices.len(), 4);
/// assert!(d.vertices.iter().all(|v| v.sites.len() == 4));
/// assert_eq!(d.edge_count(), fortune_voronoi(&pts).unwrap().edge_count());
/// ```
///
/// # Errors
/// `Error::NonFinite` naming the first point with a NaN or infinite coordinate; too many
/// points for the triangulation (see [`crate::delaunay::MAX_POINTS`]).
pub fn dual_voronoi(points: &[Point2]) -> Result<VoronoiDiagram> {
    let t = delaunay(points)?;
    Ok(from_triangulation(&t))
}

/// The Voronoi diagram dual to a Delaunay triangulation (for example one already computed
/// with [`crate::delaunay::delaunay`]). Sites are the triangulation's vertices, in its
/// order; the input-to-site map is its `input_to_vertex`.
///
/// The triangulation must be Delaunay (check with [`crate::delaunay::verify_delaunay`]);
/// otherwise the result is a well-formed structure of circumcentres but not a Voronoi
/// diagram (and [`super::verify_voronoi`] says so).
pub fn from_triangulation(t: &Triangulation) -> VoronoiDiagram {
    VoronoiCells::from_triangulation(t).to_diagram()
}

/// The former conversion (triangle sides to half-edges, then `next` links by turning
/// around each site), kept as an independent reference for the tests of
/// [`VoronoiCells`].
#[cfg(test)]
pub(crate) fn reference_from_triangulation(t: &Triangulation) -> VoronoiDiagram {
    let sites = t.vertices().to_vec();
    let input_to_site: Vec<usize> = t.input_to_vertex().iter().map(|&v| v as usize).collect();
    let mut site_input_index = vec![NIL; sites.len()];
    for (i, &s) in input_to_site.iter().enumerate() {
        if site_input_index[s] == NIL {
            site_input_index[s] = i;
        }
    }
    let (vertices, half_edges, site_half_edge) = if t.triangles().is_empty() {
        collinear(&sites)
    } else {
        Dual::new(t).build()
    };
    VoronoiDiagram {
        sites,
        site_input_index,
        input_to_site,
        vertices,
        half_edges,
        site_half_edge,
    }
}

#[cfg(test)]
type Parts = (Vec<Vertex>, Vec<HalfEdge>, Vec<Option<usize>>);

#[cfg(test)]
/// Collinear (or fewer than two) sites: parallel bisectors between neighbours along the
/// line, no vertices.
fn collinear(sites: &[Point2]) -> Parts {
    let mut order: Vec<usize> = (0..sites.len()).collect();
    order.sort_by(|&a, &b| compare_xy(sites[a], sites[b]));
    let mut half_edges = Vec::with_capacity(2 * sites.len());
    let mut site_half_edge = vec![None; sites.len()];
    for w in order.windows(2) {
        let (a, b) = (w[0], w[1]);
        let h = half_edges.len();
        for (site, twin) in [(a, h + 1), (b, h)] {
            half_edges.push(HalfEdge {
                origin: None,
                twin,
                next: None,
                prev: None,
                site,
            });
        }
        site_half_edge[a].get_or_insert(h);
        site_half_edge[b].get_or_insert(h + 1);
    }
    (Vec::new(), half_edges, site_half_edge)
}

/// The conversion state: triangles, their groups (one per Voronoi vertex), and for every
/// triangle side `3t + i` (the edge opposite corner `i`) its Voronoi half-edge.
#[cfg(test)]
struct Dual<'a> {
    t: &'a Triangulation,
    /// Voronoi vertex of each triangle.
    group: Vec<usize>,
    /// Half-edge of each triangle side (`NIL` for a side inside a group).
    side: Vec<usize>,
}

#[cfg(test)]
fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let p = parent[parent[x as usize] as usize];
        parent[x as usize] = p;
        x = p;
    }
    x
}

#[cfg(test)]
impl<'a> Dual<'a> {
    fn new(t: &'a Triangulation) -> Self {
        Dual {
            t,
            group: Vec::new(),
            side: Vec::new(),
        }
    }

    fn corner(&self, tri: usize, i: usize) -> usize {
        self.t.triangles()[tri][i % 3] as usize
    }

    /// The side of triangle `tri` that ends at vertex `v` (a corner of `tri`): the edge
    /// from the corner before `v` to `v`, i.e. opposite the corner after `v`.
    fn side_ending_at(&self, tri: usize, v: usize) -> usize {
        let k = (0..3).find(|&k| self.corner(tri, k) == v).unwrap_or(0);
        3 * tri + (k + 1) % 3
    }

    fn build(mut self) -> Parts {
        let tris = self.t.triangles();
        let nbr = self.t.neighbors();
        let pts = self.t.vertices();
        let nt = tris.len();
        // 1. Group triangles with the same circumcircle (exact in-circle test).
        let mut parent: Vec<u32> = (0..nt as u32).collect();
        let mut merged = false;
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
                if cocircular(p(tri[0]), p(tri[1]), p(tri[2]), p(d)) {
                    let (ra, rb) = (find(&mut parent, a as u32), find(&mut parent, b));
                    if ra != rb {
                        parent[ra.max(rb) as usize] = ra.min(rb);
                    }
                    merged = true;
                }
            }
        }
        let mut vertices: Vec<Vertex> = Vec::with_capacity(nt);
        self.group = vec![NIL; nt];
        for a in 0..nt {
            let r = if merged {
                find(&mut parent, a as u32) as usize
            } else {
                a
            };
            if self.group[r] == NIL {
                self.group[r] = vertices.len();
                vertices.push(Vertex {
                    point: circumcentre(
                        pts[tris[r][0] as usize],
                        pts[tris[r][1] as usize],
                        pts[tris[r][2] as usize],
                    ),
                    sites: Vec::with_capacity(3),
                });
            }
            self.group[a] = self.group[r];
            let g = self.group[a];
            for &v in &tris[a] {
                vertices[g].sites.push(v as usize);
            }
        }
        for v in &mut vertices {
            v.sites.sort_unstable();
            v.sites.dedup();
        }
        // 2. Half-edges: side i of triangle a runs u -> w (u, w its corners i+1, i+2); its
        //    Voronoi half-edge starts at a's vertex, has w on its left and ends at the
        //    vertex of the triangle across (at infinity for a hull side).
        let mut half_edges: Vec<HalfEdge> = Vec::with_capacity(3 * nt + 6);
        self.side = vec![NIL; 3 * nt];
        let mut hull_twins: Vec<(usize, usize)> = Vec::new();
        for a in 0..nt {
            for i in 0..3 {
                let b = nbr[a][i];
                let w = self.corner(a, i + 2);
                let u = self.corner(a, i + 1);
                if b == NO_NEIGHBOR {
                    let h = half_edges.len();
                    half_edges.push(edge(Some(self.group[a]), h + 1, w));
                    half_edges.push(edge(None, h, u));
                    self.side[3 * a + i] = h;
                    hull_twins.push((h + 1, a));
                } else if (b as usize) > a && self.group[b as usize] != self.group[a] {
                    let b = b as usize;
                    let j = (0..3)
                        .find(|&j| nbr[b][j] == a as u32 && self.corner(b, j + 1) == w)
                        .unwrap_or(0);
                    let h = half_edges.len();
                    half_edges.push(edge(Some(self.group[a]), h + 1, w));
                    half_edges.push(edge(Some(self.group[b]), h, u));
                    self.side[3 * a + i] = h;
                    self.side[3 * b + j] = h + 1;
                }
            }
        }
        // 3. `next`: from the triangle reached, the side ending at the same site, skipping
        //    sides inside a group (turning counter-clockwise around the site).
        for (a, across) in nbr.iter().enumerate() {
            for (i, &b) in across.iter().enumerate() {
                let h = self.side[3 * a + i];
                if h == NIL || b == NO_NEIGHBOR {
                    continue;
                }
                if let Some(n) = self.next_side(b as usize, half_edges[h].site) {
                    half_edges[h].next = Some(n);
                    half_edges[n].prev = Some(h);
                }
            }
        }
        for &(h, a) in &hull_twins {
            if let Some(n) = self.next_side(a, half_edges[h].site) {
                half_edges[h].next = Some(n);
                half_edges[n].prev = Some(h);
            }
        }
        let mut site_half_edge = vec![None; pts.len()];
        for (i, h) in half_edges.iter().enumerate() {
            match site_half_edge[h.site] {
                None => site_half_edge[h.site] = Some(i),
                Some(_) if h.prev.is_none() => site_half_edge[h.site] = Some(i),
                _ => {}
            }
        }
        (vertices, half_edges, site_half_edge)
    }

    /// The half-edge of the cell of `site` leaving the vertex of triangle `tri` (a
    /// triangle with corner `site`): the side of `tri` ending at `site`, or, while that
    /// side is inside a group, the same in the triangle across it.
    /// `None` only for a triangulation that is not a valid one (never for Delaunay).
    fn next_side(&self, mut tri: usize, site: usize) -> Option<usize> {
        let nbr = self.t.neighbors();
        // A vertex's degree bounds the turns; the bound only guards against bad input.
        for _ in 0..=self.side.len() {
            let s = self.side_ending_at(tri, site);
            if self.side[s] != NIL {
                return Some(self.side[s]);
            }
            let b = nbr[s / 3][s % 3];
            if b == NO_NEIGHBOR {
                return None;
            }
            tri = b as usize;
        }
        None
    }
}

#[cfg(test)]
fn edge(origin: Option<usize>, twin: usize, site: usize) -> HalfEdge {
    HalfEdge {
        origin,
        twin,
        next: None,
        prev: None,
        site,
    }
}
