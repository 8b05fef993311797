//! Voronoi cells as polygons, clipped to a rectangle or to a convex polygon.
//!
//! The book (§7.2) bounds the unbounded edges by a box containing all vertices. Here each
//! cell of site `s` is computed as the clip region cut by the half-planes "nearer to `s`
//! than to `t`" for the Voronoi neighbours `t` of `s` (Sutherland–Hodgman, convex region),
//! O(k·m) for a cell with `k` neighbours and a region with `m` corners; O(n + m·n) in all.
//!
//! Supported regions: axis-parallel rectangles and convex polygons (checked exactly;
//! a non-convex polygon is rejected with an error). The combinatorics come from the exact
//! diagram; the clipped corners are computed in `f64` and are therefore rounded (a cell
//! that touches the region in a single point or a sliver below rounding may come out empty).

use super::diagram::VoronoiDiagram;
use crate::kernel::{orient2d, Bbox2, Orientation, Point2};
use crate::{Error, Result};

/// A convex clip region, stored as a counter-clockwise ring (no repeated closing point).
#[derive(Debug, Clone, PartialEq)]
pub struct ClipRegion {
    ring: Vec<Point2>,
}

impl ClipRegion {
    /// The rectangle `[xmin, xmax] × [ymin, ymax]`; `Err` unless finite with `min < max`.
    pub fn rect(xmin: f64, ymin: f64, xmax: f64, ymax: f64) -> Result<Self> {
        if ![xmin, ymin, xmax, ymax].iter().all(|v| v.is_finite()) || xmin >= xmax || ymin >= ymax {
            return Err(Error::InvalidInput(format!(
                "clip rectangle {xmin},{ymin},{xmax},{ymax} must be finite with min < max"
            )));
        }
        Ok(ClipRegion {
            ring: vec![
                Point2::new(xmin, ymin),
                Point2::new(xmax, ymin),
                Point2::new(xmax, ymax),
                Point2::new(xmin, ymax),
            ],
        })
    }

    /// The rectangle of a bounding box (see [`ClipRegion::rect`]).
    pub fn from_bbox(b: Bbox2) -> Result<Self> {
        Self::rect(b.min.x, b.min.y, b.max.x, b.max.y)
    }

    /// The bounding box of `points` enlarged by `margin` times its larger side on every
    /// side (by 1 if all points coincide); `Err` for no points or non-finite ones.
    pub fn around(points: &[Point2], margin: f64) -> Result<Self> {
        crate::kernel::ensure_finite(points, "point")?;
        if points.is_empty() {
            return Err(Error::InvalidInput("no points to clip around".into()));
        }
        let b = Bbox2::of_points(points);
        let size = b.width().max(b.height());
        let pad = if size > 0.0 {
            size * margin.max(0.0)
        } else {
            1.0
        };
        let pad = if pad > 0.0 { pad } else { size.max(1.0) };
        Self::rect(b.min.x - pad, b.min.y - pad, b.max.x + pad, b.max.y + pad)
    }

    /// A convex polygon (either orientation; a repeated closing point and repeated
    /// consecutive points are dropped). `Err` if it is not convex (decided exactly), has
    /// fewer than three corners, zero area, or non-finite coordinates.
    pub fn convex_polygon(ring: &[Point2]) -> Result<Self> {
        crate::kernel::ensure_finite(ring, "clip polygon vertex")?;
        let mut r: Vec<Point2> = Vec::with_capacity(ring.len());
        for &p in ring {
            if r.last() != Some(&p) {
                r.push(p);
            }
        }
        while r.len() > 1 && r.first() == r.last() {
            r.pop();
        }
        let k = r.len();
        let bad = |m: &str| Err(Error::InvalidInput(format!("clip polygon {m}")));
        if k < 3 {
            return bad("needs at least three distinct corners");
        }
        // Orientation from the first strict turn; then every corner must be on the inner
        // side (or on the line) of every edge: convex and simple, winding once.
        let turn = (0..k)
            .map(|i| orient2d(r[i], r[(i + 1) % k], r[(i + 2) % k]))
            .find(|o| *o != Orientation::Collinear);
        match turn {
            None => return bad("has zero area"),
            Some(Orientation::Clockwise) => r.reverse(),
            Some(_) => {}
        }
        for i in 0..k {
            let (a, b) = (r[i], r[(i + 1) % k]);
            if r.iter()
                .any(|&p| orient2d(a, b, p) == Orientation::Clockwise)
            {
                return bad("is not convex (only convex clip polygons are supported)");
            }
        }
        Ok(ClipRegion { ring: r })
    }

    /// The corners, counter-clockwise.
    pub fn ring(&self) -> &[Point2] {
        &self.ring
    }

    /// The area (shoelace formula, `f64`).
    pub fn area(&self) -> f64 {
        ring_area(&self.ring)
    }
}

/// Signed area of a ring (positive when counter-clockwise), in `f64` (the kernel's).
pub use crate::kernel::ring_area;
pub(crate) use crate::kernel::ring_area_scaled;

/// Keep the part of convex `poly` where `(p − m)·n <= 0`, i.e. nearer to `s` than to `t`
/// with `m` their midpoint and `n = t − s`.
pub(crate) fn cut(poly: &[Point2], s: Point2, t: Point2) -> Vec<Point2> {
    let (nx, ny) = (t.x - s.x, t.y - s.y);
    let (mx, my) = (s.x + nx / 2.0, s.y + ny / 2.0);
    // Normalise the normal so that products cannot overflow for huge coordinates.
    let k = nx.abs().max(ny.abs());
    let (nx, ny) = (nx / k, ny / k);
    let f = |p: Point2| (p.x - mx) * nx + (p.y - my) * ny;
    let mut out = Vec::with_capacity(poly.len() + 1);
    let k = poly.len();
    for i in 0..k {
        let (a, b) = (poly[i], poly[(i + 1) % k]);
        let (fa, fb) = (f(a), f(b));
        if fa <= 0.0 {
            out.push(a);
        }
        if (fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0) {
            let u = fa / (fa - fb);
            out.push(Point2::new(a.x + u * (b.x - a.x), a.y + u * (b.y - a.y)));
        }
    }
    out.dedup();
    while out.len() > 1 && out.first() == out.last() {
        out.pop();
    }
    if out.len() < 3 {
        out.clear();
    }
    out
}

/// Is a point strictly inside the region? Decided in `f64` on the rounded point: a
/// vertex within rounding of the boundary is treated as outside, and its cell is cut,
/// which gives the same polygon up to rounding.
pub(crate) fn inside_test(region: &ClipRegion) -> impl Fn(Point2) -> bool + '_ {
    let ring = &region.ring;
    let k = ring.len();
    move |p: Point2| {
        (0..k).all(|i| {
            let (a, b) = (ring[i], ring[(i + 1) % k]);
            (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) > 0.0
        })
    }
}

/// The cell of every site (in [`VoronoiDiagram::sites`] order, i.e. the order of first
/// occurrence in the input), clipped to `region`: a counter-clockwise ring without a
/// repeated closing point, empty where the cell misses the region.
///
/// ```
/// use compgeom::voronoi::{clip_cells, fortune_voronoi, ClipRegion};
/// use compgeom::Point2;
/// let d = fortune_voronoi(&[Point2::new(1.0, 1.0), Point2::new(3.0, 1.0)]).unwrap();
/// let cells = clip_cells(&d, &ClipRegion::rect(0.0, 0.0, 4.0, 2.0).unwrap());
/// assert_eq!(cells[0], vec![Point2::new(0.0, 0.0), Point2::new(2.0, 0.0), Point2::new(2.0, 2.0), Point2::new(0.0, 2.0)]);
/// ```
pub fn clip_cells(d: &VoronoiDiagram, region: &ClipRegion) -> Vec<Vec<Point2>> {
    let ring = &region.ring;
    let inside = inside_test(region);
    let flags: Vec<bool> = d.vertices.iter().map(|v| inside(v.point)).collect();
    let inside = |v: usize| flags[v];
    let one = |s: usize| -> Vec<Point2> {
        // A bounded cell whose vertices are all inside: its own vertices, in order.
        if let Some(start) = d.site_half_edge[s] {
            let mut poly = Vec::with_capacity(8);
            let mut h = start;
            loop {
                let e = &d.half_edges[h];
                match (e.origin, e.next) {
                    (Some(v), Some(n)) if inside(v) => {
                        poly.push(d.vertices[v].point);
                        h = n;
                    }
                    _ => {
                        poly.clear();
                        break;
                    }
                }
                if h == start || poly.len() > d.half_edges.len() {
                    break;
                }
            }
            if h == start && poly.len() >= 3 {
                return poly;
            }
        }
        // Otherwise: the region cut by the bisector half-planes of the neighbours.
        let mut poly = ring.clone();
        let mut h = d.site_half_edge[s];
        let mut neighbours: Vec<usize> = Vec::new();
        if let Some(start) = h {
            // Neighbours along the chain from `start`; a strip (collinear sites) or a
            // cell with a second chain needs the full list.
            let mut count = 0;
            while let Some(x) = h {
                neighbours.push(d.half_edges[d.half_edges[x].twin].site);
                count += 1;
                h = d.half_edges[x].next;
                if h == Some(start) || count > d.half_edges.len() {
                    break;
                }
            }
            if h.is_none() && d.vertices.is_empty() {
                neighbours = d
                    .half_edges
                    .iter()
                    .filter(|e| e.site == s)
                    .map(|e| d.half_edges[e.twin].site)
                    .collect();
            }
        }
        for &t in &neighbours {
            if poly.is_empty() {
                break;
            }
            poly = cut(&poly, d.sites[s], d.sites[t]);
        }
        poly
    };
    // Visit the cells in the order of their first half-edge (which follows the diagram's
    // memory layout) rather than in site order (the input order, at random in memory).
    let mut order: Vec<(usize, usize)> = d
        .site_half_edge
        .iter()
        .enumerate()
        .map(|(s, h)| (h.unwrap_or(usize::MAX), s))
        .collect();
    order.sort_unstable();
    let mut cells = vec![Vec::new(); d.sites.len()];
    for (_, s) in order {
        cells[s] = one(s);
    }
    cells
}
