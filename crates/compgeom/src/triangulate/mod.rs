//! Polygon triangulation and the art gallery (book chapter 3).
//!
//! * [`classify_vertices`], [`is_y_monotone`]: the vertex types of §3.2 under the book's
//!   order (y, then x: of two vertices at equal height the left one is "above").
//! * [`monotone_partition`]: MAKEMONOTONE (§3.2), a plane sweep with helper(e) in a
//!   balanced search tree keyed by exact orientation tests; O(n log n) time, O(n) space.
//!   [`MonotonePartition::to_dcel`] gives the pieces as the book's DCEL.
//! * [`triangulate_monotone_polygon`]: TRIANGULATEMONOTONEPOLYGON (§3.3), linear time.
//! * [`triangulate`]: both together for simple polygons and polygons with holes
//!   (Theorem 3.8), O(n log n); a polygon that is already monotone skips the sweep (O(n)).
//!   [`triangulate_multipolygon`] does each polygon of a multipolygon.
//! * [`triangulate_subdivision`] (and [`triangulate_segments`]): every face of a planar
//!   subdivision inside its bounding box (Theorem 3.9), one MAKEMONOTONE sweep over the
//!   whole plane graph, O(n log n); each triangle knows its face. Verifier:
//!   [`verify_subdivision_triangulation`].
//! * [`art_gallery`]: the dual graph, a 3-colouring by depth-first search and the
//!   smallest colour class as guards (§3.1, Theorem 3.3): at most ⌊n/3⌋ guards for a
//!   simple polygon; see [`guards`](art_gallery) for holes.
//! * Verifiers: [`verify_triangulation`] (n − 2 + 2h counter-clockwise triangles with
//!   every edge a boundary edge or a diagonal with a triangle on each side, which makes
//!   them tile the polygon exactly) and [`verify_art_gallery`].
//!
//! ## Degenerate input
//!
//! Every decision is exact ([`crate::kernel::orient2d`] and coordinate comparisons).
//! * Equal y: the left vertex comes first (the book's rule); nothing assumes strict
//!   monotonicity.
//! * Collinear vertices (angles of exactly π) stay vertices and the diagonal set is
//!   maximal: no triangle is flat and no vertex lies inside a triangle edge.
//! * Repeated consecutive vertices (and a closing copy of the first) are dropped.
//! * A vertex of one ring lying inside an edge of another ring (or a non-adjacent edge of
//!   its own ring), exactly by [`crate::kernel::orient2d`]: that edge is split there, so
//!   the point becomes a vertex of both rings (touching at a vertex, below) and appears in
//!   [`Triangulation::vertices`] once more, inside the split edge's ring.
//! * Rings touching at a vertex — a hole touching the outer ring, holes touching each
//!   other, a ring touching itself — are allowed: such a point is one vertex per visit
//!   (it appears twice in [`Triangulation::vertices`]); the rings are relinked there so
//!   each visit is one corner, and ties between visits are broken by a symbolic
//!   perturbation moving each visit into its own corner. Triangles use whichever visit's
//!   index lies on their side.
//! * Errors ([`crate::Error::InvalidInput`]): a non-finite coordinate, a ring with fewer
//!   than 3 distinct vertices or no area, rings crossing (the message names the two edges
//!   and the point), edges overlapping, rings crossing at a shared vertex, and a hole
//!   outside the outer ring or inside another hole.
//!
//! ```
//! use compgeom::triangulate::{triangulate, verify_triangulation};
//! use compgeom::{Point2, Polygon};
//! let p = |x, y| Point2::new(x, y);
//! let square = vec![p(0., 0.), p(4., 0.), p(4., 4.), p(0., 4.)];
//! let hole = vec![p(1., 1.), p(1., 3.), p(3., 3.), p(3., 1.)];
//! let polygon = Polygon::new(square, vec![hole]);
//! let t = triangulate(&polygon).unwrap();
//! assert_eq!(t.triangles.len(), 8 - 2 + 2 * 1);
//! verify_triangulation(&polygon, &t).unwrap();
//! ```
mod classify;
mod geometry;
mod guards;
mod make_monotone;
mod monotone;
mod planar;
mod planar_verify;
mod status;
mod subdivision;
mod touching;
mod verify;

pub use classify::VertexType;
pub use guards::{art_gallery, verify_art_gallery, ArtGallery};
pub use planar::{triangulate_segments, triangulate_subdivision, SubdivisionTriangulation};
pub use planar_verify::verify_subdivision_triangulation;
pub use verify::verify_triangulation;

use crate::dcel::{Dcel, Source};
use crate::kernel::{MultiPolygon, Point2, Polygon, Segment2};
use crate::{Error, Result};
use geometry::Geometry;

/// A triangulation of a polygon (with holes).
#[derive(Debug, Clone, PartialEq)]
pub struct Triangulation {
    /// The polygon's vertices, ring by ring (outer ring first, then each hole), each ring
    /// in input order with repeated consecutive vertices (and a closing copy) dropped, and
    /// with a copy of every vertex of another ring lying inside one of its edges inserted
    /// into that edge (module docs).
    pub vertices: Vec<Point2>,
    /// Ring `r` is `vertices[ring_starts[r]..ring_starts[r + 1]]`.
    pub ring_starts: Vec<usize>,
    /// Counter-clockwise triangles, as indices into `vertices`.
    pub triangles: Vec<[usize; 3]>,
    /// Boundary successor of every vertex, interior on the left (after relinking at
    /// points where rings touch).
    next: Vec<u32>,
}

impl Triangulation {
    fn new(g: Geometry, triangles: Vec<[u32; 3]>) -> Triangulation {
        Triangulation {
            vertices: g.pts,
            ring_starts: g.ring_starts,
            triangles: triangles
                .into_iter()
                .map(|t| t.map(|v| v as usize))
                .collect(),
            next: g.next,
        }
    }

    /// The number of holes.
    pub fn holes(&self) -> usize {
        self.ring_starts.len().saturating_sub(2)
    }

    /// Whether `a → b` is a boundary edge with the interior on its left.
    pub fn is_boundary_edge(&self, a: usize, b: usize) -> bool {
        self.next.get(a).is_some_and(|&w| w as usize == b)
    }

    /// The diagonals: every triangle edge that is not a boundary edge, once each, as
    /// `[i, j]` with `i < j`, sorted.
    pub fn diagonals(&self) -> Vec<[usize; 2]> {
        let mut out: Vec<[usize; 2]> = self
            .triangles
            .iter()
            .flat_map(|t| [[t[0], t[1]], [t[1], t[2]], [t[2], t[0]]])
            .filter(|&[a, b]| a < b && !self.is_boundary_edge(a, b) && !self.is_boundary_edge(b, a))
            .collect();
        out.sort_unstable();
        out
    }
}

/// The monotone pieces of a polygon after MAKEMONOTONE (§3.2).
#[derive(Debug, Clone, PartialEq)]
pub struct MonotonePartition {
    /// The polygon's vertices, as in [`Triangulation::vertices`].
    pub vertices: Vec<Point2>,
    /// The type of every vertex (see [`classify_vertices`]).
    pub types: Vec<VertexType>,
    /// The diagonals added by the sweep, as `[i, j]`.
    pub diagonals: Vec<[usize; 2]>,
    /// The y-monotone pieces: counter-clockwise vertex index cycles.
    pub pieces: Vec<Vec<usize>>,
}

impl MonotonePartition {
    /// The partition as the book's DCEL: the polygon's edges and the diagonals as a
    /// planar subdivision (built exactly by [`Dcel::from_segments`]); every bounded face
    /// inside the polygon is one monotone piece.
    pub fn to_dcel(&self) -> Result<Dcel<(), Vec<Source>, ()>> {
        let mut diagonals: Vec<[usize; 2]> = self
            .diagonals
            .iter()
            .map(|&[a, b]| [a.min(b), a.max(b)])
            .collect();
        diagonals.sort_unstable();
        let mut segments: Vec<Segment2> = Vec::new();
        for piece in &self.pieces {
            for k in 0..piece.len() {
                let (a, b) = (piece[k], piece[(k + 1) % piece.len()]);
                let diagonal = diagonals.binary_search(&[a.min(b), a.max(b)]).is_ok();
                // A diagonal borders two pieces: keep it once.
                if !diagonal || a < b {
                    segments.push(Segment2::new(self.vertices[a], self.vertices[b]));
                }
            }
        }
        Dcel::from_segments(&segments)
    }
}

/// The type of every vertex (§3.2), indexed like [`Triangulation::vertices`].
///
/// ```
/// use compgeom::triangulate::{classify_vertices, VertexType};
/// use compgeom::{Point2, Polygon};
/// let p = |x, y| Point2::new(x, y);
/// // A notch cut down into the top edge: its tip is a merge vertex.
/// let poly = Polygon::new(vec![p(0., 0.), p(4., 0.), p(4., 4.), p(2., 2.), p(0., 4.)], vec![]);
/// let types = classify_vertices(&poly).unwrap();
/// assert_eq!(types[3], VertexType::Merge);
/// assert_eq!(types[2], VertexType::Start);
/// assert_eq!(types[1], VertexType::End);
/// // (0, 0) is above (4, 0): equal y, smaller x.
/// assert_eq!(types[0], VertexType::Regular);
/// ```
pub fn classify_vertices(polygon: &Polygon) -> Result<Vec<VertexType>> {
    let g = Geometry::new(polygon)?;
    Ok((0..g.len() as u32)
        .map(|v| classify::vertex_type(&g, v))
        .collect())
}

/// Whether the polygon is y-monotone in the book's order (no split and no merge
/// vertex). A polygon with holes never is. O(n log n) (the simplicity check).
pub fn is_y_monotone(polygon: &Polygon) -> Result<bool> {
    let g = Geometry::new(polygon)?;
    Ok(monotone_without_sweep(&g))
}

/// No holes, no touching rings, no split or merge vertex, and one start and one end
/// vertex (a ring that is not simple can avoid split and merge vertices with several of
/// each; with one of each, the two chains are monotone and the chain merge of the monotone
/// triangulation checks that they never meet).
fn monotone_without_sweep(g: &Geometry) -> bool {
    if g.holes() > 0 || g.pinched {
        return false;
    }
    let (mut starts, mut ends) = (0, 0);
    for v in 0..g.len() as u32 {
        match classify::vertex_type(g, v) {
            VertexType::Split | VertexType::Merge => return false,
            VertexType::Start => starts += 1,
            VertexType::End => ends += 1,
            VertexType::Regular => {}
        }
    }
    starts == 1 && ends == 1
}

/// MAKEMONOTONE (§3.2): the diagonals that cut the polygon into y-monotone pieces, and
/// the pieces. O(n log n).
pub fn monotone_partition(polygon: &Polygon) -> Result<MonotonePartition> {
    prepared(polygon, monotone_partition_of)
}

fn monotone_partition_of(g: Geometry) -> Result<MonotonePartition> {
    let part = make_monotone::make_monotone(&g).map_err(|e| g.contact_error().unwrap_or(e))?;
    let pieces = subdivision::faces(&g, &part.diagonals);
    Ok(MonotonePartition {
        vertices: g.pts.clone(),
        types: part.types,
        diagonals: part
            .diagonals
            .iter()
            .map(|d| d.map(|v| v as usize))
            .collect(),
        pieces: pieces
            .into_iter()
            .map(|c| c.into_iter().map(|v| v as usize).collect())
            .collect(),
    })
}

/// TRIANGULATEMONOTONEPOLYGON (§3.3) alone: an error if the polygon is not y-monotone
/// (see [`is_y_monotone`]). Linear time after the O(n log n) input check.
pub fn triangulate_monotone_polygon(polygon: &Polygon) -> Result<Triangulation> {
    prepared(polygon, triangulate_monotone_of)
}

fn triangulate_monotone_of(g: Geometry) -> Result<Triangulation> {
    if !monotone_without_sweep(&g) {
        return Err(Error::InvalidInput(
            "the polygon is not y-monotone (it has a split or merge vertex, or holes)".into(),
        ));
    }
    let mut triangles = Vec::with_capacity(g.len() - 2);
    let cycle: Vec<u32> = subdivision::boundary_cycles(&g).swap_remove(0);
    monotone::triangulate_monotone(&g, &cycle, &mut triangles)
        .map_err(|e| g.contact_error().unwrap_or(e))?;
    Ok(Triangulation::new(g, triangles))
}

/// Triangulate a simple polygon or a polygon with holes (Theorem 3.8): MAKEMONOTONE, then
/// every piece by TRIANGULATEMONOTONEPOLYGON; an already monotone polygon goes straight
/// to the second step. n − 2 + 2h counter-clockwise triangles (module docs for touching
/// rings), O(n log n) time. Errors: see the module docs.
pub fn triangulate(polygon: &Polygon) -> Result<Triangulation> {
    prepared(polygon, triangulate_of)
}

/// Run `f` on the prepared polygon; if that fails and some vertex lies inside another
/// ring's edge (or a non-adjacent edge of its own ring), once more with those edges split
/// there (see [`touching`]). If the second attempt fails too, the first error stands (it
/// names the input's own edges).
fn prepared<T>(polygon: &Polygon, f: impl Fn(Geometry) -> Result<T>) -> Result<T> {
    let first = match Geometry::new(polygon).and_then(&f) {
        Ok(t) => return Ok(t),
        Err(e) => e,
    };
    match touching::split_touching(polygon) {
        Ok(Some(split)) => Geometry::new(&split).and_then(&f).map_err(|_| first),
        _ => Err(first),
    }
}

fn triangulate_of(g: Geometry) -> Result<Triangulation> {
    let mut triangles = Vec::with_capacity(g.len() + 2 * g.holes());
    if monotone_without_sweep(&g) {
        let cycle: Vec<u32> = subdivision::boundary_cycles(&g).swap_remove(0);
        monotone::triangulate_monotone(&g, &cycle, &mut triangles)
            .map_err(|e| g.contact_error().unwrap_or(e))?;
    } else {
        let part = make_monotone::make_monotone(&g).map_err(|e| g.contact_error().unwrap_or(e))?;
        for piece in subdivision::faces(&g, &part.diagonals) {
            monotone::triangulate_monotone(&g, &piece, &mut triangles)?;
        }
    }
    Ok(Triangulation::new(g, triangles))
}

/// Triangulate every polygon of a multipolygon (independently; the polygons are not
/// checked against each other).
pub fn triangulate_multipolygon(polygons: &MultiPolygon) -> Result<Vec<Triangulation>> {
    polygons
        .0
        .iter()
        .enumerate()
        .map(|(i, p)| {
            triangulate(p).map_err(|e| match e {
                Error::InvalidInput(m) => Error::InvalidInput(format!("polygon {i}: {m}")),
                other => other,
            })
        })
        .collect()
}
