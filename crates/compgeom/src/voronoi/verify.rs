//! Exact verifiers for Voronoi diagrams and clipped cells.

use super::clip::{ring_area_scaled, ClipRegion};
use super::diagram::VoronoiDiagram;
use crate::kernel::{incircle, orient2d, CircleSide, Orientation, Point2};
use crate::{Error, Result};

/// Up to this many sites, every vertex's circle is tested against every site; above, the
/// test is local (against the sites of adjacent vertices), which together with the
/// structural checks implies global emptiness (the dual is then locally Delaunay).
const BRUTE_FORCE_SITES: usize = 1500;

fn fail<T>(m: String) -> Result<T> {
    Err(Error::Verification(m))
}

/// Three sites of a vertex, counter-clockwise (cocircular distinct points: no three are
/// collinear).
fn ccw_triple(d: &VoronoiDiagram, v: usize) -> Result<[Point2; 3]> {
    let s = &d.vertices[v].sites;
    if s.len() < 3 {
        return fail(format!("vertex {v} has fewer than three sites"));
    }
    let (a, b, c) = (d.sites[s[0]], d.sites[s[1]], d.sites[s[2]]);
    match orient2d(a, b, c) {
        Orientation::CounterClockwise => Ok([a, b, c]),
        Orientation::Clockwise => Ok([a, c, b]),
        Orientation::Collinear => fail(format!("vertex {v}: its sites are collinear")),
    }
}

/// Verify a Voronoi diagram of `points`:
///
/// - the structure ([`VoronoiDiagram::validate`]) and the input-to-site map (every input
///   point equals its site; sites are distinct is implied by the exact tests below);
/// - every vertex's sites lie exactly on one circle (exact in-circle test) and that circle
///   is empty: no site strictly inside (exact; against all sites up to 1500 sites, else
///   against the sites of the adjacent vertices);
/// - every vertex's rounded position is equidistant from its sites up to rounding
///   (relative `1e-9`), and every bounded edge runs in its direction (left site on the left),
///   up to rounding.
pub fn verify_voronoi(points: &[Point2], d: &VoronoiDiagram) -> Result<()> {
    d.validate()?;
    if d.input_to_site.len() != points.len() {
        return fail("input-to-site map has the wrong length".into());
    }
    for (i, &s) in d.input_to_site.iter().enumerate() {
        if d.sites[s] != points[i] {
            return fail(format!("input point {i} maps to site {s} at another place"));
        }
    }
    for (s, &i) in d.site_input_index.iter().enumerate() {
        if d.input_to_site.get(i) != Some(&s) {
            return fail(format!("site {s}: first input index {i} does not map back"));
        }
    }
    let brute = d.sites.len() <= BRUTE_FORCE_SITES;
    let mut neighbour_vertices: Vec<Vec<usize>> = vec![Vec::new(); d.vertices.len()];
    for h in &d.half_edges {
        if let (Some(u), Some(w)) = (h.origin, d.half_edges[h.twin].origin) {
            neighbour_vertices[u].push(w);
        }
    }
    for (v, vert) in d.vertices.iter().enumerate() {
        let [a, b, c] = ccw_triple(d, v)?;
        for &s in &vert.sites {
            if incircle(a, b, c, d.sites[s]) != CircleSide::OnCircle {
                return fail(format!("vertex {v}: site {s} is not on its circle"));
            }
        }
        let check = |s: usize| -> Result<()> {
            if incircle(a, b, c, d.sites[s]) == CircleSide::Inside {
                return fail(format!("vertex {v}: site {s} lies inside its circle"));
            }
            Ok(())
        };
        if brute {
            (0..d.sites.len()).try_for_each(check)?;
        } else {
            for &w in &neighbour_vertices[v] {
                d.vertices[w].sites.iter().try_for_each(|&s| check(s))?;
            }
        }
        // Rounded position: equidistant to rounding.
        let p = vert.point;
        let dist = |s: usize| (d.sites[s].x - p.x).hypot(d.sites[s].y - p.y);
        let r0 = dist(vert.sites[0]);
        let scale = r0 + p.x.abs().max(p.y.abs());
        for &s in &vert.sites {
            if (dist(s) - r0).abs() > 1e-9 * scale {
                return fail(format!(
                    "vertex {v} at {p:?} is not equidistant from site {s}"
                ));
            }
        }
    }
    for (i, h) in d.half_edges.iter().enumerate() {
        if let (Some(u), Some(w)) = (h.origin, d.destination(i)) {
            let (pu, pw) = (d.vertices[u].point, d.vertices[w].point);
            let dir = d.direction(i);
            let along = dir.x * (pw.x - pu.x) + dir.y * (pw.y - pu.y);
            let len = dir.x.hypot(dir.y) * (pw.x - pu.x).hypot(pw.y - pu.y);
            if along < -1e-9 * len.max(f64::MIN_POSITIVE) {
                return fail(format!("half-edge {i} runs against its direction"));
            }
        }
    }
    Ok(())
}

/// Verify clipped cells: one per site, each a convex counter-clockwise ring (up to
/// rounding), the cells' areas sum to the region's area (relative `1e-9`), and every site
/// strictly inside the region has a non-empty cell.
pub fn verify_cells(d: &VoronoiDiagram, region: &ClipRegion, cells: &[Vec<Point2>]) -> Result<()> {
    if cells.len() != d.sites.len() {
        return fail(format!("{} cells for {} sites", cells.len(), d.sites.len()));
    }
    // Areas in units of a power of two near the region's size (no overflow).
    let ring = region.ring();
    let big = ring
        .iter()
        .fold(f64::MIN_POSITIVE, |m, p| m.max(p.x.abs()).max(p.y.abs()));
    let scale = 2f64.powi(big.log2().floor() as i32);
    let total: f64 = cells.iter().map(|c| ring_area_scaled(c, scale)).sum();
    let want = ring_area_scaled(ring, scale);
    if (total - want).abs() > 1e-9 * want {
        return fail(format!("cells cover area {total}, the region {want}"));
    }
    let k = ring.len();
    for (s, cell) in cells.iter().enumerate() {
        if ring_area_scaled(cell, scale) < -1e-12 * want {
            return fail(format!("cell {s} is clockwise"));
        }
        let inside = (0..k).all(|i| {
            orient2d(ring[i], ring[(i + 1) % k], d.sites[s]) == Orientation::CounterClockwise
        });
        if inside && cell.is_empty() {
            return fail(format!(
                "site {s} lies inside the region but its cell is empty"
            ));
        }
    }
    Ok(())
}
