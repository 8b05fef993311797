//! The post-office problem (book §7.1): the site nearest to a query point.
//!
//! A greedy walk on the Voronoi neighbour graph (the Delaunay graph, so this is a walk in
//! the triangulation): from a start site, move to any neighbour strictly nearer to the
//! query until none is; in the Delaunay graph such a site is a nearest site (a site whose
//! neighbours are all at least as far is nearest: its Voronoi cell contains the query).
//! Every distance comparison is exact, so the answer is exact; only the start is chosen
//! in floating point, which affects speed, never the answer.
//!
//! The start is the site stored in the query's bucket of a uniform grid over the sites
//! (about two sites per bucket), or the previous answer when the bucket is empty. Building
//! is O(n) (compressed neighbour lists and the grid); a query takes O(1) expected steps on
//! uniformly spread sites, more on very uneven sets (never more than the walk length).

use super::diagram::VoronoiDiagram;
use super::predicates::cmp_dist;
use crate::kernel::{Bbox2, Point2};
use std::cell::Cell;
use std::cmp::Ordering;

const EMPTY: u32 = u32::MAX;

/// Nearest-site queries on a Voronoi diagram.
#[derive(Debug, Clone)]
pub struct NearestSite<'a> {
    diagram: &'a VoronoiDiagram,
    /// Neighbours of site `s`: `adj[offset[s]..offset[s + 1]]`.
    offset: Vec<u32>,
    adj: Vec<u32>,
    bbox: Bbox2,
    side: usize,
    /// One site per grid bucket (`EMPTY` if none).
    bucket: Vec<u32>,
    last: Cell<usize>,
}

impl<'a> NearestSite<'a> {
    /// Prepare queries on `diagram` (O(n)).
    pub fn new(diagram: &'a VoronoiDiagram) -> Self {
        let n = diagram.sites.len();
        let mut offset = vec![0u32; n + 1];
        for h in &diagram.half_edges {
            offset[h.site + 1] += 1;
        }
        for s in 0..n {
            offset[s + 1] += offset[s];
        }
        let mut fill: Vec<u32> = offset[..n].to_vec();
        let mut adj = vec![0u32; diagram.half_edges.len()];
        for h in &diagram.half_edges {
            let t = diagram.half_edges[h.twin].site as u32;
            adj[fill[h.site] as usize] = t;
            fill[h.site] += 1;
        }
        let bbox = Bbox2::of_points(&diagram.sites);
        let side = ((n as f64 / 2.0).sqrt().ceil() as usize).clamp(1, 4096);
        let mut me = NearestSite {
            diagram,
            offset,
            adj,
            bbox,
            side,
            bucket: vec![EMPTY; side * side],
            last: Cell::new(0),
        };
        for (s, &p) in diagram.sites.iter().enumerate() {
            let b = me.bucket_of(p);
            if me.bucket[b] == EMPTY {
                me.bucket[b] = s as u32;
            }
        }
        me
    }

    /// The grid bucket of `p` (clamped; any finite point has one).
    fn bucket_of(&self, p: Point2) -> usize {
        let cell = |v: f64, lo: f64, hi: f64| {
            let w = hi / 2.0 - lo / 2.0;
            if w > 0.0 {
                let t = ((v / 2.0 - lo / 2.0) / w * self.side as f64).floor();
                t.clamp(0.0, (self.side - 1) as f64) as usize
            } else {
                0
            }
        };
        let c = cell(p.x, self.bbox.min.x, self.bbox.max.x);
        let r = cell(p.y, self.bbox.min.y, self.bbox.max.y);
        r * self.side + c
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
        let b = self.bucket[self.bucket_of(q)];
        let mut cur = if b != EMPTY {
            b as usize
        } else {
            self.last.get().min(sites.len() - 1)
        };
        'walk: loop {
            let (lo, hi) = (self.offset[cur] as usize, self.offset[cur + 1] as usize);
            for &t in &self.adj[lo..hi] {
                let t = t as usize;
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
