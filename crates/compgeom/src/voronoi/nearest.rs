//! The post-office problem (book §7.1): the site nearest to a query point.
//!
//! A greedy walk on the Voronoi neighbour graph (the Delaunay graph): from a start site,
//! move to any neighbour strictly nearer to the query until none is; in the Delaunay graph
//! such a site is a nearest site. Distances are compared exactly. Building is O(n); a query
//! walks O(√n) steps on uniform data from a fixed start, fewer when queries are coherent
//! (each query starts at the previous answer).

use super::diagram::VoronoiDiagram;
use super::predicates::cmp_dist;
use crate::kernel::Point2;
use std::cell::Cell;
use std::cmp::Ordering;

/// Nearest-site queries on a Voronoi diagram.
#[derive(Debug, Clone)]
pub struct NearestSite<'a> {
    diagram: &'a VoronoiDiagram,
    adj: Vec<Vec<usize>>,
    last: Cell<usize>,
}

impl<'a> NearestSite<'a> {
    /// Prepare queries on `diagram` (O(n)).
    pub fn new(diagram: &'a VoronoiDiagram) -> Self {
        NearestSite {
            diagram,
            adj: diagram.neighbours(),
            last: Cell::new(0),
        }
    }

    /// A site nearest to `q` (index into [`VoronoiDiagram::sites`]; among equally near
    /// sites, one of them), or `None` if there are no sites or `q` is not finite.
    ///
    /// ```
    /// use compgeom::voronoi::{fortune_voronoi, NearestSite};
    /// use compgeom::Point2;
    /// let d = fortune_voronoi(&[Point2::new(0.0, 0.0), Point2::new(10.0, 0.0), Point2::new(5.0, 9.0)]).unwrap();
    /// let post = NearestSite::new(&d);
    /// assert_eq!(post.nearest(Point2::new(6.0, 7.0)), Some(2));
    /// ```
    pub fn nearest(&self, q: Point2) -> Option<usize> {
        let sites = &self.diagram.sites;
        if sites.is_empty() || !q.is_finite() {
            return None;
        }
        let mut cur = self.last.get().min(sites.len() - 1);
        'walk: loop {
            for &t in &self.adj[cur] {
                if cmp_dist(q, sites[t], sites[cur]) == Ordering::Less {
                    cur = t;
                    continue 'walk;
                }
            }
            break;
        }
        self.last.set(cur);
        Some(cur)
    }
}
