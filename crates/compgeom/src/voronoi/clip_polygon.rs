//! Voronoi cells clipped to any polygon: non-convex, with holes, several parts.
//!
//! A convex cell and a non-convex polygon can meet in several pieces, so every cell comes
//! out as a [`MultiPolygon`]. Method:
//!
//! 1. the cells clipped to the polygon's bounding box ([`super::clip_cells`]; convex rings
//!    with `f64` corners);
//! 2. the polygon's edges in a uniform grid (about one edge per grid cell);
//! 3. per cell, the polygon edges near it (from the grid) are tested exactly against the
//!    cell's ring (exact segment intersection and orientation tests). A cell that meets no
//!    edge lies wholly inside or wholly outside the polygon: one of its corners is
//!    classified exactly by even-odd ray crossing (orientation tests on the edges in its
//!    grid row) and the cell is kept whole or dropped;
//! 4. a cell that meets the boundary is intersected with the polygon by the exact boolean
//!    operation ([`crate::overlay::boolean`]): decisions exact, constructed crossings
//!    rounded to the nearest `f64`.
//!
//! Cost: O(n + m) for the grid and the cells away from the boundary (m polygon edges),
//! plus O((k + m) log m) for each of the cells that the boundary crosses. The polygon is
//! read with the even-odd rule, like [`crate::overlay::boolean`]; its rings need not be
//! oriented.

use super::clip::{clip_cells, ring_area_scaled, ClipRegion};
use super::diagram::VoronoiDiagram;
use crate::kernel::{
    ensure_finite, orient2d, segment_intersection, Bbox2, MultiPolygon, Orientation, Point2,
    Polygon, Segment2, SegmentIntersection,
};
use crate::overlay::{boolean, BooleanOp};
use crate::{Error, Result};

/// The polygon's edges bucketed in a uniform grid over its bounding box.
struct EdgeGrid {
    segs: Vec<Segment2>,
    bbox: Bbox2,
    cols: usize,
    rows: usize,
    /// For grid cell `r * cols + c`, the indices of the edges whose boxes overlap it.
    cells: Vec<Vec<u32>>,
}

impl EdgeGrid {
    fn new(segs: Vec<Segment2>, bbox: Bbox2) -> Self {
        let side = ((segs.len() as f64).sqrt().ceil() as usize).clamp(1, 1024);
        let mut g = EdgeGrid {
            segs,
            bbox,
            cols: side,
            rows: side,
            cells: vec![Vec::new(); side * side],
        };
        for (i, s) in g.segs.iter().enumerate() {
            let (c0, c1) = (g.col(s.a.x.min(s.b.x)), g.col(s.a.x.max(s.b.x)));
            let (r0, r1) = (g.row(s.a.y.min(s.b.y)), g.row(s.a.y.max(s.b.y)));
            for r in r0..=r1 {
                for c in c0..=c1 {
                    g.cells[r * g.cols + c].push(i as u32);
                }
            }
        }
        g
    }

    /// The grid column of `x` (monotone in `x`, clamped).
    fn col(&self, x: f64) -> usize {
        let w = self.bbox.max.x / 2.0 - self.bbox.min.x / 2.0;
        let t = ((x / 2.0 - self.bbox.min.x / 2.0) / w * self.cols as f64).floor();
        t.clamp(0.0, (self.cols - 1) as f64) as usize
    }

    /// The grid row of `y` (monotone in `y`, clamped).
    fn row(&self, y: f64) -> usize {
        let h = self.bbox.max.y / 2.0 - self.bbox.min.y / 2.0;
        let t = ((y / 2.0 - self.bbox.min.y / 2.0) / h * self.rows as f64).floor();
        t.clamp(0.0, (self.rows - 1) as f64) as usize
    }

    /// The edges whose grid cells overlap `b`, each once (`stamp` marks the ones seen).
    fn near(&self, b: &Bbox2, stamp: &mut [u32], round: u32, out: &mut Vec<u32>) {
        out.clear();
        for r in self.row(b.min.y)..=self.row(b.max.y) {
            for c in self.col(b.min.x)..=self.col(b.max.x) {
                for &e in &self.cells[r * self.cols + c] {
                    if stamp[e as usize] != round {
                        stamp[e as usize] = round;
                        out.push(e);
                    }
                }
            }
        }
    }

    /// Even-odd inside test of `p`, exact; `p` must not lie on an edge. Counts the edges
    /// crossing the ray from `p` to the right (half-open in `y`), using the grid row of `p`.
    fn inside(&self, p: Point2, stamp: &mut [u32], round: u32) -> bool {
        let r = self.row(p.y);
        let mut odd = false;
        for c in self.col(p.x)..self.cols {
            for &e in &self.cells[r * self.cols + c] {
                if stamp[e as usize] == round {
                    continue;
                }
                stamp[e as usize] = round;
                let s = self.segs[e as usize];
                let (lo, hi) = if s.a.y <= s.b.y {
                    (s.a, s.b)
                } else {
                    (s.b, s.a)
                };
                if lo.y <= p.y && p.y < hi.y && orient2d(lo, hi, p) == Orientation::CounterClockwise
                {
                    odd = !odd;
                }
            }
        }
        odd
    }
}

/// Does the segment `s` meet the closed convex counter-clockwise ring `cell`? Exact.
fn meets(cell: &[Point2], s: Segment2) -> bool {
    let k = cell.len();
    let inside = |p: Point2| {
        (0..k).all(|i| orient2d(cell[i], cell[(i + 1) % k], p) != Orientation::Clockwise)
    };
    inside(s.a)
        || inside(s.b)
        || (0..k).any(|i| {
            segment_intersection(s, Segment2::new(cell[i], cell[(i + 1) % k]))
                != SegmentIntersection::None
        })
}

/// The clip polygon's rings, checked: finite coordinates, at least three distinct points.
pub(crate) fn check_polygon(clip: &MultiPolygon) -> Result<Vec<Segment2>> {
    let mut segs = Vec::new();
    for (i, poly) in clip.0.iter().enumerate() {
        for (j, ring) in poly.rings().enumerate() {
            ensure_finite(ring, &format!("clip polygon {i} ring {j} vertex"))?;
            let mut r: Vec<Point2> = ring.clone();
            r.dedup();
            while r.len() > 1 && r.first() == r.last() {
                r.pop();
            }
            if r.len() < 3 {
                return Err(Error::InvalidInput(format!(
                    "clip polygon {i} ring {j} has fewer than three distinct points"
                )));
            }
            for k in 0..r.len() {
                segs.push(Segment2::new(r[k], r[(k + 1) % r.len()]));
            }
        }
    }
    if segs.is_empty() {
        return Err(Error::InvalidInput("the clip polygon is empty".into()));
    }
    Ok(segs)
}

/// The cell of every site (in [`VoronoiDiagram::sites`] order) clipped to the polygon set
/// `clip` (any polygons, read even-odd): valid polygons, shells counter-clockwise and
/// holes clockwise; empty where the cell misses the region. See the module docs.
///
/// ```
/// use compgeom::voronoi::{clip_cells_to_polygon, fortune_voronoi};
/// use compgeom::{MultiPolygon, Point2, Polygon};
/// let d = fortune_voronoi(&[Point2::new(1.0, 1.0), Point2::new(3.0, 1.0)]).unwrap();
/// // A U shape: the left arm, the right arm and the base bar.
/// let u = [(0., 0.), (4., 0.), (4., 3.), (3., 3.), (3., 1.), (1., 1.), (1., 3.), (0., 3.)]
///     .map(Point2::from).to_vec();
/// let cells = clip_cells_to_polygon(&d, &MultiPolygon(vec![Polygon::new(u, vec![])])).unwrap();
/// assert_eq!(cells[0].0.len(), 1); // x <= 2: the left arm and half the bar, one piece
/// let area: f64 = cells.iter().flat_map(|c| &c.0).map(|p| compgeom::voronoi::clip::ring_area(&p.exterior)).sum();
/// assert_eq!(area, 8.0);
/// ```
///
/// # Errors
/// `InvalidInput` for an empty polygon, a ring with fewer than three distinct points or a
/// zero-area bounding box; `NonFinite` for a NaN or infinite coordinate.
pub fn clip_cells_to_polygon(d: &VoronoiDiagram, clip: &MultiPolygon) -> Result<Vec<MultiPolygon>> {
    let segs = check_polygon(clip)?;
    let pts: Vec<Point2> = segs.iter().map(|s| s.a).collect();
    let bbox = Bbox2::of_points(&pts);
    let region = ClipRegion::from_bbox(bbox)?;
    let boxed = clip_cells(d, &region);
    let grid = EdgeGrid::new(segs, bbox);
    let mut stamp = vec![0u32; grid.segs.len()];
    let mut round = 0u32;
    let mut near = Vec::new();
    let mut out = Vec::with_capacity(boxed.len());
    for cell in boxed {
        if cell.is_empty() {
            out.push(MultiPolygon::default());
            continue;
        }
        round += 1;
        grid.near(&Bbox2::of_points(&cell), &mut stamp, round, &mut near);
        let touched = near.iter().any(|&e| meets(&cell, grid.segs[e as usize]));
        if !touched {
            // Wholly inside or wholly outside: classify one corner.
            round += 1;
            let keep = grid.inside(cell[0], &mut stamp, round);
            out.push(if keep {
                MultiPolygon(vec![Polygon::new(cell, Vec::new())])
            } else {
                MultiPolygon::default()
            });
            continue;
        }
        let c = MultiPolygon(vec![Polygon::new(cell, Vec::new())]);
        out.push(boolean(&c, clip, BooleanOp::Intersection)?);
    }
    Ok(out)
}

/// Verify cells clipped to a polygon set: one entry per site, shells counter-clockwise
/// and holes clockwise (by signed area), the pieces' areas sum to the area of `clip` read
/// even-odd (relative `1e-9`; computed with the exact boolean union of `clip` with
/// nothing), and every site strictly inside `clip` has a non-empty cell.
pub fn verify_polygon_cells(
    d: &VoronoiDiagram,
    clip: &MultiPolygon,
    cells: &[MultiPolygon],
) -> Result<()> {
    let fail = |m: String| Err(Error::Verification(m));
    if cells.len() != d.sites.len() {
        return fail(format!("{} cells for {} sites", cells.len(), d.sites.len()));
    }
    let segs = check_polygon(clip)?;
    let pts: Vec<Point2> = segs.iter().map(|s| s.a).collect();
    let bbox = Bbox2::of_points(&pts);
    let big = bbox
        .min
        .x
        .abs()
        .max(bbox.min.y.abs())
        .max(bbox.max.x.abs())
        .max(bbox.max.y.abs())
        .max(f64::MIN_POSITIVE);
    let scale = 2f64.powi(big.log2().floor() as i32);
    let area = |m: &MultiPolygon| -> f64 {
        m.0.iter()
            .map(|p| {
                ring_area_scaled(&p.exterior, scale)
                    + p.holes
                        .iter()
                        .map(|h| ring_area_scaled(h, scale))
                        .sum::<f64>()
            })
            .sum()
    };
    let region = boolean(clip, &MultiPolygon::default(), BooleanOp::Union)?;
    let want = area(&region);
    let mut total = 0.0;
    for (s, cell) in cells.iter().enumerate() {
        for p in &cell.0 {
            if ring_area_scaled(&p.exterior, scale) <= 0.0
                || p.holes.iter().any(|h| ring_area_scaled(h, scale) >= 0.0)
            {
                return fail(format!("cell {s}: a ring has the wrong orientation"));
            }
        }
        total += area(cell);
    }
    if (total - want).abs() > 1e-9 * want.abs().max(f64::MIN_POSITIVE) {
        return fail(format!("cells cover area {total}, the region {want}"));
    }
    let grid = EdgeGrid::new(segs, bbox);
    let mut stamp = vec![0u32; grid.segs.len()];
    for (s, &p) in d.sites.iter().enumerate() {
        // Only sites with an empty cell need the (slower) exact inside test.
        if !cells[s].0.is_empty() || !bbox.contains(p) {
            continue;
        }
        let on_edge = grid.segs.iter().any(|e| {
            orient2d(e.a, e.b, p) == Orientation::Collinear
                && segment_intersection(*e, Segment2::new(p, p)) != SegmentIntersection::None
        });
        if !on_edge && grid.inside(p, &mut stamp, s as u32 + 1) {
            return fail(format!(
                "site {s} lies inside the region but its cell is empty"
            ));
        }
    }
    Ok(())
}
