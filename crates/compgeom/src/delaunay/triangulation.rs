//! [`Triangulation`]: the compact result type (vertex, triangle and neighbour arrays).

use super::mesh::{Mesh, GHOST};
use crate::{Error, Point2, Result};
use std::collections::HashMap;

/// Marks "no triangle across this edge" (a hull edge) in [`Triangulation::neighbors`].
pub const NO_NEIGHBOR: u32 = u32::MAX;

/// A triangulation of distinct points: vertices, counter-clockwise triangles and their
/// neighbours, and the map from input indices to vertices (see the [module docs](super)).
///
/// Indices are `u32`. `neighbors()[t][i]` is the triangle across the edge opposite
/// `triangles()[t][i]`, i.e. across the edge from vertex `i + 1` to vertex `i + 2` (mod 3).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Triangulation {
    pub(crate) vertices: Vec<Point2>,
    pub(crate) triangles: Vec<[u32; 3]>,
    pub(crate) neighbors: Vec<[u32; 3]>,
    pub(crate) input_to_vertex: Vec<u32>,
}

impl Triangulation {
    /// The vertices: distinct input points in first-seen order (then Steiner points, if an
    /// operation added any).
    pub fn vertices(&self) -> &[Point2] {
        &self.vertices
    }

    /// The triangles, as counter-clockwise triples of vertex indices.
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// The neighbours: `neighbors()[t][i]` is the triangle across the edge opposite vertex `i`
    /// of triangle `t`, or [`NO_NEIGHBOR`].
    pub fn neighbors(&self) -> &[[u32; 3]] {
        &self.neighbors
    }

    /// For every input point, the index of its vertex.
    pub fn input_to_vertex(&self) -> &[u32] {
        &self.input_to_vertex
    }

    /// True when there are no triangles: fewer than three distinct points, or all collinear.
    pub fn is_degenerate(&self) -> bool {
        self.triangles.is_empty()
    }

    /// The triangles with each triple rotated to start at its smallest index, sorted: a
    /// canonical form for comparing triangulations.
    pub fn canonical_triangles(&self) -> Vec<[u32; 3]> {
        let mut v: Vec<[u32; 3]> = self.triangles.iter().map(|&t| rotate_min(t)).collect();
        v.sort_unstable();
        v
    }

    /// Every edge once, as `(u, v)` with `u < v`, sorted.
    pub fn edges(&self) -> Vec<(u32, u32)> {
        let mut e = Vec::with_capacity(self.triangles.len() * 3 / 2 + 3);
        for (t, tri) in self.triangles.iter().enumerate() {
            for i in 0..3 {
                let (a, b) = (tri[(i + 1) % 3], tri[(i + 2) % 3]);
                let n = self.neighbors[t][i];
                // Interior edges are listed by the triangle with the smaller index.
                if n == NO_NEIGHBOR || (n as usize) > t {
                    e.push((a.min(b), a.max(b)));
                }
            }
        }
        e.sort_unstable();
        e
    }

    /// The hull boundary as a counter-clockwise cycle of vertex indices (collinear boundary
    /// vertices included), starting at the smallest index; empty when degenerate.
    pub fn hull(&self) -> Vec<u32> {
        let mut succ: HashMap<u32, u32> = HashMap::new();
        for (t, tri) in self.triangles.iter().enumerate() {
            for i in 0..3 {
                if self.neighbors[t][i] == NO_NEIGHBOR {
                    succ.insert(tri[(i + 1) % 3], tri[(i + 2) % 3]);
                }
            }
        }
        let Some(&start) = succ.keys().min() else {
            return Vec::new();
        };
        let mut cycle = vec![start];
        let mut v = succ[&start];
        while v != start && cycle.len() <= succ.len() {
            cycle.push(v);
            v = match succ.get(&v) {
                Some(&w) => w,
                None => break,
            };
        }
        cycle
    }

    /// The circumcentre of triangle `t`, rounded to `f64` (for drawing and Voronoi output;
    /// no decision in this crate depends on it).
    ///
    /// ```
    /// use compgeom::delaunay::delaunay;
    /// use compgeom::Point2;
    /// let t = delaunay(&[(0.0, 0.0), (2.0, 0.0), (0.0, 2.0)].map(Point2::from))?;
    /// assert_eq!(t.circumcenter(0), Point2::new(1.0, 1.0));
    /// # Ok::<(), compgeom::Error>(())
    /// ```
    pub fn circumcenter(&self, t: usize) -> Point2 {
        let [a, b, c] = self.triangles[t].map(|i| self.vertices[i as usize]);
        circumcenter(a, b, c)
    }

    /// Structural validation: indices in range, neighbour links symmetric and sharing the
    /// edge, `input_to_vertex` in range. (Geometry is checked by
    /// [`verify_delaunay`](super::verify_delaunay).)
    ///
    /// # Errors
    /// `Error::Verification` naming the first broken invariant.
    pub fn validate(&self) -> Result<()> {
        let nv = self.vertices.len() as u32;
        let nt = self.triangles.len();
        if self.neighbors.len() != nt {
            return fail("neighbour array length differs from the triangle count".into());
        }
        if let Some(i) = self.input_to_vertex.iter().position(|&v| v >= nv) {
            return fail(format!("input point {i} maps to a missing vertex"));
        }
        for (t, tri) in self.triangles.iter().enumerate() {
            if tri.iter().any(|&v| v >= nv)
                || tri[0] == tri[1]
                || tri[1] == tri[2]
                || tri[0] == tri[2]
            {
                return fail(format!("triangle {t} has a bad vertex index: {tri:?}"));
            }
            for i in 0..3 {
                let n = self.neighbors[t][i];
                if n == NO_NEIGHBOR {
                    continue;
                }
                if n as usize >= nt {
                    return fail(format!("triangle {t} has a missing neighbour {n}"));
                }
                let (a, b) = (tri[(i + 1) % 3], tri[(i + 2) % 3]);
                let other = self.triangles[n as usize];
                let Some(j) = (0..3).find(|&j| other[(j + 1) % 3] == b && other[(j + 2) % 3] == a)
                else {
                    return fail(format!(
                        "triangles {t} and {n} do not share edge ({a}, {b}) in opposite directions"
                    ));
                };
                if self.neighbors[n as usize][j] != t as u32 {
                    return fail(format!("neighbour link {t} -> {n} is not symmetric"));
                }
            }
        }
        Ok(())
    }

    /// The result from a finished mesh (`None` when degenerate) and the representative map
    /// (input index → input index of its vertex).
    pub(crate) fn from_mesh(pts: &[Point2], mesh: Option<&Mesh<'_>>, rep: &[u32]) -> Self {
        let (vertices, input_to_vertex, new_id) = number_vertices(pts, rep);
        let Some(m) = mesh else {
            return Triangulation {
                vertices,
                input_to_vertex,
                ..Default::default()
            };
        };
        let (v, twin) = (&m.v[..], &m.twin[..]);
        let real = |h: usize| v[h] != GHOST && v[h + 1] != GHOST && v[h + 2] != GHOST;
        let mut tri_id = vec![NO_NEIGHBOR; v.len() / 3];
        let mut count = 0u32;
        for (t, id) in tri_id.iter_mut().enumerate() {
            if real(3 * t) {
                *id = count;
                count += 1;
            }
        }
        // List the triangles by the curve rank of their first corner (a counting sort), when
        // every vertex has one: the slots themselves follow the insertion rounds, which
        // visit the whole set several times.
        let rank = &m.rank;
        if rank.len() == m.pts.len() && !rank.is_empty() {
            let mut start = vec![0u32; rank.len() + 1];
            for (t, &id) in tri_id.iter().enumerate() {
                if id != NO_NEIGHBOR {
                    start[rank[v[3 * t] as usize] as usize + 1] += 1;
                }
            }
            for k in 1..start.len() {
                start[k] += start[k - 1];
            }
            for (t, id) in tri_id.iter_mut().enumerate() {
                if *id != NO_NEIGHBOR {
                    let slot = &mut start[rank[v[3 * t] as usize] as usize];
                    *id = *slot;
                    *slot += 1;
                }
            }
            let mut triangles = vec![[0u32; 3]; count as usize];
            let mut neighbors = vec![[0u32; 3]; count as usize];
            let identity = vertices.len() == pts.len();
            for (t, &id) in tri_id.iter().enumerate() {
                if id == NO_NEIGHBOR {
                    continue;
                }
                let h = 3 * t;
                let (a, b, c) = (v[h], v[h + 1], v[h + 2]);
                triangles[id as usize] = if identity {
                    [a, b, c]
                } else {
                    [new_id[a as usize], new_id[b as usize], new_id[c as usize]]
                };
                neighbors[id as usize] = [
                    tri_id[(twin[h + 1] / 3) as usize],
                    tri_id[(twin[h + 2] / 3) as usize],
                    tri_id[(twin[h] / 3) as usize],
                ];
            }
            return Triangulation {
                vertices,
                triangles,
                neighbors,
                input_to_vertex,
            };
        }
        let mut triangles = Vec::with_capacity(count as usize);
        let mut neighbors = Vec::with_capacity(count as usize);
        // Without merged points the numbering is the identity (first-seen order = input
        // order), so the triples are copied as they are.
        let identity = vertices.len() == pts.len();
        for (t, &id) in tri_id.iter().enumerate() {
            if id == NO_NEIGHBOR {
                continue;
            }
            let h = 3 * t;
            let (a, b, c) = (v[h], v[h + 1], v[h + 2]);
            triangles.push(if identity {
                [a, b, c]
            } else {
                [new_id[a as usize], new_id[b as usize], new_id[c as usize]]
            });
            // Neighbour opposite vertex i = across half-edge i + 1.
            neighbors.push([
                tri_id[(twin[h + 1] / 3) as usize],
                tri_id[(twin[h + 2] / 3) as usize],
                tri_id[(twin[h] / 3) as usize],
            ]);
        }
        Triangulation {
            vertices,
            triangles,
            neighbors,
            input_to_vertex,
        }
    }

    /// The result from counter-clockwise triangles over input indices (neighbours found by
    /// matching edges) and the representative map.
    pub(crate) fn from_triangles(pts: &[Point2], tris: &[[u32; 3]], rep: &[u32]) -> Self {
        let (vertices, input_to_vertex, new_id) = number_vertices(pts, rep);
        let triangles: Vec<[u32; 3]> = tris.iter().map(|t| t.map(|v| new_id[v as usize])).collect();
        let neighbors = neighbours_of(&triangles);
        Triangulation {
            vertices,
            triangles,
            neighbors,
            input_to_vertex,
        }
    }
}

impl Triangulation {
    /// The result from counter-clockwise triangles over input indices with their known
    /// neighbour arrays, and the representative map.
    pub(crate) fn from_triangles_and_neighbours(
        pts: &[Point2],
        tris: Vec<[u32; 3]>,
        neighbors: Vec<[u32; 3]>,
        rep: &[u32],
    ) -> Self {
        let (vertices, input_to_vertex, new_id) = number_vertices(pts, rep);
        let triangles = tris
            .into_iter()
            .map(|t| t.map(|v| new_id[v as usize]))
            .collect();
        Triangulation {
            vertices,
            triangles,
            neighbors,
            input_to_vertex,
        }
    }
}

/// Neighbour arrays for counter-clockwise triangles, by matching directed edges.
pub(crate) fn neighbours_of(triangles: &[[u32; 3]]) -> Vec<[u32; 3]> {
    let mut edge: HashMap<(u32, u32), (u32, usize)> = HashMap::with_capacity(triangles.len() * 3);
    for (t, tri) in triangles.iter().enumerate() {
        for i in 0..3 {
            edge.insert((tri[(i + 1) % 3], tri[(i + 2) % 3]), (t as u32, i));
        }
    }
    triangles
        .iter()
        .map(|tri| {
            [0, 1, 2].map(|i| {
                edge.get(&(tri[(i + 2) % 3], tri[(i + 1) % 3]))
                    .map_or(NO_NEIGHBOR, |&(n, _)| n)
            })
        })
        .collect()
}

/// Vertices in first-seen order: (vertices, input → vertex, representative → vertex).
fn number_vertices(pts: &[Point2], rep: &[u32]) -> (Vec<Point2>, Vec<u32>, Vec<u32>) {
    let mut new_id = vec![NO_NEIGHBOR; pts.len()];
    let mut vertices = Vec::with_capacity(pts.len());
    let mut input_to_vertex = Vec::with_capacity(pts.len());
    for (i, &r) in rep.iter().enumerate() {
        let r = r as usize;
        if new_id[r] == NO_NEIGHBOR {
            new_id[r] = vertices.len() as u32;
            vertices.push(pts[i]);
        }
        input_to_vertex.push(new_id[r]);
    }
    (vertices, input_to_vertex, new_id)
}

fn rotate_min(t: [u32; 3]) -> [u32; 3] {
    let k = (0..3).min_by_key(|&i| t[i]).unwrap_or(0);
    [t[k], t[(k + 1) % 3], t[(k + 2) % 3]]
}

/// The circumcentre of `a, b, c`, computed relative to `a` (rounded).
pub(crate) fn circumcenter(a: Point2, b: Point2, c: Point2) -> Point2 {
    let (bx, by) = (b.x - a.x, b.y - a.y);
    let (cx, cy) = (c.x - a.x, c.y - a.y);
    let d = 2.0 * (bx * cy - by * cx);
    let b2 = bx * bx + by * by;
    let c2 = cx * cx + cy * cy;
    Point2::new(a.x + (cy * b2 - by * c2) / d, a.y + (bx * c2 - cx * b2) / d)
}

fn fail(msg: String) -> Result<()> {
    Err(Error::Verification(msg))
}

impl Triangulation {
    /// A triangulation from its parts (neighbours are computed), e.g. to verify a
    /// triangulation made elsewhere.
    ///
    /// # Errors
    /// `Error::InvalidInput` when an index is out of range.
    pub fn from_parts(
        vertices: Vec<Point2>,
        triangles: Vec<[u32; 3]>,
        input_to_vertex: Vec<u32>,
    ) -> Result<Self> {
        let nv = vertices.len() as u32;
        if let Some(t) = triangles.iter().position(|t| t.iter().any(|&v| v >= nv)) {
            return Err(Error::InvalidInput(format!(
                "triangle {t} refers to a vertex beyond the {nv} given"
            )));
        }
        if let Some(i) = input_to_vertex.iter().position(|&v| v >= nv) {
            return Err(Error::InvalidInput(format!(
                "input point {i} maps to a vertex beyond the {nv} given"
            )));
        }
        let neighbors = neighbours_of(&triangles);
        Ok(Triangulation {
            vertices,
            triangles,
            neighbors,
            input_to_vertex,
        })
    }
}
