//! The state of Fortune's sweep at one moment, for pictures and teaching (book Fig. 7.4).

use super::fortune::{dedupe, Sweep};
use crate::kernel::{ensure_finite, Point2};
use crate::Result;

/// The beach line when the sweep line is at `sweep_y`: every event above the line has been
/// processed.
#[derive(Debug, Clone, PartialEq)]
pub struct BeachLineSnapshot {
    /// The sweep line's height.
    pub sweep_y: f64,
    /// The distinct sites, in first-seen order.
    pub sites: Vec<Point2>,
    /// The sites of the arcs, left to right (a site may own several arcs).
    pub arcs: Vec<usize>,
}

impl BeachLineSnapshot {
    /// The beach line's height above `x`: the lowest of the arcs' parabolas (`f64`, for
    /// drawing); `None` before the first site.
    pub fn height_at(&self, x: f64) -> Option<f64> {
        let l = self.sweep_y;
        self.arcs
            .iter()
            .map(|&s| self.sites[s])
            .filter(|p| p.y > l)
            .map(|p| ((x - p.x).powi(2) + p.y * p.y - l * l) / (2.0 * (p.y - l)))
            .min_by(|a, b| a.total_cmp(b))
    }
}

/// Run Fortune's sweep on `points` down to `sweep_y` and return the beach line.
///
/// ```
/// use compgeom::voronoi::beach_line_at;
/// use compgeom::Point2;
/// let s = beach_line_at(&[Point2::new(0.0, 2.0), Point2::new(1.0, 1.0)], 0.0).unwrap();
/// assert_eq!(s.arcs, vec![0, 1, 0]);
/// ```
pub fn beach_line_at(points: &[Point2], sweep_y: f64) -> Result<BeachLineSnapshot> {
    ensure_finite(points, "point")?;
    let (sites, _, _, order) = dedupe(points);
    let mut sweep = Sweep::new(&sites);
    sweep.run(&order, Some(sweep_y));
    let arcs = sweep.beach.arcs().iter().map(|a| a.site as usize).collect();
    Ok(BeachLineSnapshot {
        sweep_y,
        sites,
        arcs,
    })
}
