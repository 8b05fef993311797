//! Terrain interpolation (book §9.1): the piecewise-linear terrain over the Delaunay
//! triangulation of height samples, and heights at query points.
//!
//! Locating a query is a visibility walk over the triangles (exact orientations), starting
//! from the triangle of the previous query, so sorted or clustered queries are fast. A query
//! strictly outside the convex hull of the samples has no height (`None`). The height
//! itself is the barycentric combination of the three corner heights, rounded (the only
//! rounded step; which triangle is used is decided exactly). Points on an edge or vertex
//! get the value of either incident triangle, which agree up to rounding.
//!
//! Samples with equal (x, y) are merged; the first one's height is used. With fewer than
//! three distinct sites, or all on one line, there are no triangles: only queries equal to a
//! site get a height.

use super::delaunay;
use super::pred::orient;
use super::triangulation::{Triangulation, NO_NEIGHBOR};
use crate::kernel::ensure_finite;
use crate::{Error, Point2, Point3, Result};
use std::cell::Cell;

/// A piecewise-linear terrain (a TIN) over the Delaunay triangulation of its samples.
#[derive(Debug, Clone)]
pub struct Terrain {
    tri: Triangulation,
    z: Vec<f64>,
    last: Cell<u32>,
}

impl Terrain {
    /// The terrain of `samples` (x, y, height).
    ///
    /// ```
    /// use compgeom::delaunay::Terrain;
    /// use compgeom::{Point2, Point3};
    /// let s = [Point3::new(0.0, 0.0, 0.0), Point3::new(4.0, 0.0, 4.0), Point3::new(0.0, 4.0, 8.0)];
    /// let t = Terrain::new(&s)?;
    /// assert_eq!(t.height_at(Point2::new(1.0, 1.0)), Some(3.0));
    /// assert_eq!(t.height_at(Point2::new(5.0, 5.0)), None);
    /// # Ok::<(), compgeom::Error>(())
    /// ```
    ///
    /// # Errors
    /// `NonFinite` for a NaN/infinite coordinate or height (naming the sample).
    pub fn new(samples: &[Point3]) -> Result<Terrain> {
        if let Some(i) = samples.iter().position(|p| !p.z.is_finite()) {
            return Err(Error::NonFinite {
                what: format!("sample {i}"),
                value: samples[i].z,
            });
        }
        let xy: Vec<Point2> = samples.iter().map(|p| Point2::new(p.x, p.y)).collect();
        ensure_finite(&xy, "sample")?;
        let tri = delaunay(&xy)?;
        let mut z = vec![f64::NAN; tri.vertices().len()];
        for (i, &v) in tri.input_to_vertex().iter().enumerate() {
            if z[v as usize].is_nan() {
                z[v as usize] = samples[i].z;
            }
        }
        Ok(Terrain {
            tri,
            z,
            last: Cell::new(0),
        })
    }

    /// The triangulation underneath.
    pub fn triangulation(&self) -> &Triangulation {
        &self.tri
    }

    /// The height of each vertex of [`Terrain::triangulation`].
    pub fn vertex_heights(&self) -> &[f64] {
        &self.z
    }

    /// The height at `q`, or `None` outside the convex hull of the samples (or for a
    /// non-finite query).
    pub fn height_at(&self, q: Point2) -> Option<f64> {
        if !q.is_finite() {
            return None;
        }
        let v = self.tri.vertices();
        if self.tri.is_degenerate() {
            return v.iter().position(|&p| p == q).map(|i| self.z[i]);
        }
        let t = self.locate(q)?;
        self.last.set(t);
        let [a, b, c] = self.tri.triangles()[t as usize];
        let (pa, pb, pc) = (v[a as usize], v[b as usize], v[c as usize]);
        for (p, i) in [(pa, a), (pb, b), (pc, c)] {
            if p == q {
                return Some(self.z[i as usize]);
            }
        }
        let area =
            |p: Point2, r: Point2, s: Point2| (r.x - p.x) * (s.y - p.y) - (r.y - p.y) * (s.x - p.x);
        let (wa, wb, wc) = (area(q, pb, pc), area(pa, q, pc), area(pa, pb, q));
        let sum = wa + wb + wc;
        Some((wa * self.z[a as usize] + wb * self.z[b as usize] + wc * self.z[c as usize]) / sum)
    }

    /// Heights at many points ([`Terrain::height_at`] each, walking from the previous one).
    pub fn heights(&self, queries: &[Point2]) -> Vec<Option<f64>> {
        queries.iter().map(|&q| self.height_at(q)).collect()
    }

    /// The triangle containing `q` (closed), by a visibility walk; `None` outside the hull.
    fn locate(&self, q: Point2) -> Option<u32> {
        let v = self.tri.vertices();
        let tris = self.tri.triangles();
        let nbs = self.tri.neighbors();
        let mut t = self.last.get().min(tris.len() as u32 - 1);
        let mut steps = 0usize;
        'walk: loop {
            steps += 1;
            if steps > 4 * tris.len() + 16 {
                // A straight walk cannot cycle in a Delaunay triangulation; fall back to a
                // scan if it ever did.
                return (0..tris.len() as u32).find(|&t| {
                    let [a, b, c] = tris[t as usize].map(|i| v[i as usize]);
                    orient(a, b, q) >= 0 && orient(b, c, q) >= 0 && orient(c, a, q) >= 0
                });
            }
            let tri = tris[t as usize];
            for k in 0..3 {
                // Edge opposite vertex k: from tri[k+1] to tri[k+2].
                let (a, b) = (v[tri[(k + 1) % 3] as usize], v[tri[(k + 2) % 3] as usize]);
                if orient(a, b, q) < 0 {
                    let n = nbs[t as usize][k];
                    if n == NO_NEIGHBOR {
                        return None; // beyond a hull edge of a convex region
                    }
                    t = n;
                    continue 'walk;
                }
            }
            return Some(t);
        }
    }
}
