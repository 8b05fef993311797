//! The Voronoi diagram as a half-edge structure (the book's DCEL of §7.2, without a
//! separate face record: faces are the sites).
//!
//! - [`Vertex`]: a Voronoi vertex, its rounded position and the sites of the faces around
//!   it (three or more: cocircular sites give one vertex of higher degree, never a cluster
//!   of coincident vertices).
//! - [`HalfEdge`]: one side of a Voronoi edge, with the site of the face on its left, its
//!   `twin`, its origin vertex (`None` at infinity) and `next`/`prev` along its face
//!   (`None` where the edge goes to/comes from infinity). Faces are traversed
//!   counter-clockwise.
//! - Half-edges come in pairs: the twin of `h` is `h ^ 1`.
//!
//! Converting to a general DCEL: vertices map one to one, half-edges one to one (unbounded
//! half-edges get a vertex at infinity or are clipped first, see [`super::clip`]), and each
//! site becomes a face whose outer component is `site_half_edge[s]`.

use crate::kernel::{Point2, Vector2};
use crate::{Error, Result};

/// A Voronoi vertex.
#[derive(Debug, Clone, PartialEq)]
pub struct Vertex {
    /// The centre of the empty circle through its sites, rounded to `f64` (the exact point
    /// is defined by the sites; topology never depends on this value).
    pub point: Point2,
    /// The sites (indices into [`VoronoiDiagram::sites`]) on the vertex's circle, ascending;
    /// at least three.
    pub sites: Vec<usize>,
}

/// One directed side of a Voronoi edge.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct HalfEdge {
    /// Start vertex, `None` when the half-edge comes from infinity.
    pub origin: Option<usize>,
    /// The opposite half-edge (always `self_index ^ 1`).
    pub twin: usize,
    /// The next half-edge around the same face (counter-clockwise), `None` when this
    /// half-edge goes to infinity.
    pub next: Option<usize>,
    /// The previous half-edge around the same face, `None` when this half-edge comes from
    /// infinity.
    pub prev: Option<usize>,
    /// The site whose cell lies to the left of this half-edge.
    pub site: usize,
}

/// A Voronoi diagram of point sites.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct VoronoiDiagram {
    /// The distinct sites, in the order of their first occurrence in the input.
    pub sites: Vec<Point2>,
    /// For each distinct site, the input index of its first occurrence.
    pub site_input_index: Vec<usize>,
    /// For each input point, the index of its site (duplicates share a site).
    pub input_to_site: Vec<usize>,
    /// The Voronoi vertices.
    pub vertices: Vec<Vertex>,
    /// The half-edges, in twin pairs `(2k, 2k + 1)`.
    pub half_edges: Vec<HalfEdge>,
    /// For each site, one half-edge of its cell (`None` only with fewer than two sites).
    /// For an unbounded cell it is the first half-edge of a boundary chain (`prev == None`).
    pub site_half_edge: Vec<Option<usize>>,
}

impl VoronoiDiagram {
    /// Number of Voronoi edges (half-edge pairs).
    pub fn edge_count(&self) -> usize {
        self.half_edges.len() / 2
    }

    /// The end vertex of half-edge `h` (`None` at infinity).
    pub fn destination(&self, h: usize) -> Option<usize> {
        self.half_edges[self.half_edges[h].twin].origin
    }

    /// The direction in which half-edge `h` runs: its face's site is on the left, so it is
    /// the left site minus the right site rotated clockwise by 90°. Not normalised.
    pub fn direction(&self, h: usize) -> Vector2 {
        let s = self.sites[self.half_edges[h].site];
        let t = self.sites[self.half_edges[self.half_edges[h].twin].site];
        Vector2::new(s.y - t.y, t.x - s.x)
    }

    /// The Voronoi neighbours of each site (sites whose cells share an edge), ascending.
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

    /// The half-edges of the cell of `site`, as boundary chains in counter-clockwise order:
    /// one closed chain for a bounded cell; one open chain (from infinity to infinity) for an
    /// unbounded cell, or two for a strip between parallel edges (collinear sites).
    pub fn cell_chains(&self, site: usize) -> Vec<Vec<usize>> {
        let own: Vec<usize> = (0..self.half_edges.len())
            .filter(|&i| self.half_edges[i].site == site)
            .collect();
        self.chains_of(site, &own)
    }

    /// [`Self::cell_chains`] given the half-edges `own` of the cell (O(|own|)).
    fn chains_of(&self, site: usize, own: &[usize]) -> Vec<Vec<usize>> {
        let mut chains = Vec::new();
        let Some(start) = self.site_half_edge.get(site).copied().flatten() else {
            return chains;
        };
        let mut seen = std::collections::HashSet::new();
        // Starts: the given half-edge, and for open chains every half-edge without prev.
        let mut starts = vec![start];
        starts.extend(
            own.iter()
                .copied()
                .filter(|&i| i != start && self.half_edges[i].prev.is_none()),
        );
        for s in starts {
            if seen.contains(&s) {
                continue;
            }
            let mut chain = Vec::new();
            let mut h = s;
            while seen.insert(h) {
                chain.push(h);
                match self.half_edges[h].next {
                    Some(n) => h = n,
                    None => break,
                }
            }
            chains.push(chain);
        }
        chains
    }

    /// Check the structure: twins pair up with different sites, `next`/`prev` are inverse
    /// and stay on one face, origins and destinations agree along `next`, every vertex has
    /// degree at least 3 and lists exactly the sites around it, every site has a cell, and
    /// Euler's formula holds (with one vertex at infinity: `V + 1 − E + F = 2`).
    pub fn validate(&self) -> Result<()> {
        let fail = |m: String| Err(Error::Verification(m));
        let n = self.half_edges.len();
        if n % 2 != 0 {
            return fail("odd number of half-edges".into());
        }
        let mut degree = vec![0usize; self.vertices.len()];
        let mut around: Vec<Vec<usize>> = vec![Vec::new(); self.vertices.len()];
        for (i, h) in self.half_edges.iter().enumerate() {
            if h.twin != (i ^ 1) || h.twin >= n {
                return fail(format!("half-edge {i}: twin is {} not {}", h.twin, i ^ 1));
            }
            let t = &self.half_edges[h.twin];
            if h.site >= self.sites.len() || t.site == h.site {
                return fail(format!("half-edge {i}: bad site {}", h.site));
            }
            if let Some(v) = h.origin {
                if v >= self.vertices.len() {
                    return fail(format!("half-edge {i}: origin {v} out of range"));
                }
                degree[v] += 1;
                around[v].push(h.site);
                if h.prev.is_none() {
                    return fail(format!(
                        "half-edge {i} starts at vertex {v} but has no prev"
                    ));
                }
            } else if h.prev.is_some() {
                return fail(format!("half-edge {i} comes from infinity but has a prev"));
            }
            match (h.next, t.origin) {
                (Some(nx), Some(d)) => {
                    let m = &self.half_edges[nx];
                    if m.prev != Some(i) || m.site != h.site || m.origin != Some(d) {
                        return fail(format!("half-edge {i}: next {nx} does not continue it"));
                    }
                }
                (None, None) => {}
                _ => return fail(format!("half-edge {i}: next and destination disagree")),
            }
        }
        for (v, vert) in self.vertices.iter().enumerate() {
            let mut s = around[v].clone();
            s.sort_unstable();
            if degree[v] < 3 || s != vert.sites {
                return fail(format!(
                    "vertex {v}: degree {} with sites {:?}, listed {:?}",
                    degree[v], s, vert.sites
                ));
            }
        }
        if self.sites.len() >= 2 {
            let mut own: Vec<Vec<usize>> = vec![Vec::new(); self.sites.len()];
            for (i, h) in self.half_edges.iter().enumerate() {
                own[h.site].push(i);
            }
            for (s, own_s) in own.iter().enumerate() {
                match self.site_half_edge[s] {
                    Some(h) if self.half_edges[h].site == s => {}
                    _ => return fail(format!("site {s} has no cell boundary")),
                }
                let chains = self.chains_of(s, own_s);
                let total: usize = chains.iter().map(|c| c.len()).sum();
                let count = own_s.len();
                let closed = chains.len() == 1
                    && self.half_edges[*chains[0].last().unwrap_or(&0)]
                        .next
                        .is_some();
                let ok_shape = closed
                    || (chains.len() == 1)
                    || (chains.len() == 2 && self.vertices.is_empty());
                if total != count || !ok_shape {
                    return fail(format!(
                        "site {s}: boundary chains {chains:?} do not form one cell"
                    ));
                }
            }
            let (v, e, f) = (self.vertices.len(), self.edge_count(), self.sites.len());
            if v + 1 + f != e + 2 {
                return fail(format!("Euler: V={v}, E={e}, F={f}"));
            }
        }
        if self.input_to_site.iter().any(|&s| s >= self.sites.len())
            || self.site_input_index.len() != self.sites.len()
        {
            return fail("input-to-site map out of range".into());
        }
        Ok(())
    }
}
