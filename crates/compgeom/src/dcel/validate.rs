//! [`Dcel::validate`]: every invariant of the structure, checked exactly.
use super::{Dcel, HalfEdgeId};
use crate::kernel::{orient_exact, ExactPoint, Orientation};
use crate::{Error, Result};
use std::cmp::Ordering;

fn fail<T>(msg: String) -> Result<T> {
    Err(Error::Verification(msg))
}

/// 0 for directions in [0°, 180°), 1 for [180°, 360°), from `o` towards `d`.
fn half(o: &ExactPoint, d: &ExactPoint) -> u8 {
    match d.compare_y(o) {
        Ordering::Greater => 0,
        Ordering::Less => 1,
        Ordering::Equal => u8::from(d.compare_x(o) != Ordering::Greater),
    }
}

impl<V, E, F> Dcel<V, E, F> {
    /// Check every invariant, exactly: `twin(twin(h)) = h` and a twin starts where `h`
    /// ends (and elsewhere); `next`/`prev` are inverse and `next(h)` starts where `h`
    /// ends; all half-edges of a cycle have the same face and every cycle is listed
    /// exactly once, as the outer component of its face or as an inner one; exactly one
    /// face (the first) is unbounded; each vertex's incident half-edge starts there; the
    /// half-edges around each vertex are in strict counter-clockwise order (and the
    /// boundary walk turns to the next one clockwise); outer boundaries are
    /// counter-clockwise and inner ones clockwise (decided at each cycle's
    /// lexicographically smallest vertex); Euler's formula `V − E + (outer cycles) = 1`
    /// for each connected component. `Err(Verification)` names the first violation.
    /// O(n) exact tests for n half-edges (each pair of neighbours around a vertex once;
    /// the components by union–find).
    ///
    /// ```
    /// use compgeom::dcel::Dcel;
    /// use compgeom::{Point2, Segment2};
    /// let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(a.into(), b.into());
    /// let d = Dcel::from_segments(&[s((0., 0.), (2., 2.)), s((0., 2.), (2., 0.))]).unwrap();
    /// assert!(d.validate().is_ok());
    /// ```
    pub fn validate(&self) -> Result<()> {
        let m = self.half_edges.len();
        if m % 2 != 0 {
            return fail(format!("odd number of half-edges ({m})"));
        }
        let (nv, nf) = (self.vertices.len(), self.faces.len());
        for (i, h) in self.half_edges.iter().enumerate() {
            let ok = h.twin.0 < m && h.next.0 < m && h.prev.0 < m;
            if !ok || h.origin.0 >= nv || h.face.0 >= nf {
                return fail(format!("half-edge {i}: a link is out of range"));
            }
            let t = &self.half_edges[h.twin.0];
            if h.twin.0 == i || t.twin.0 != i {
                return fail(format!("half-edge {i}: twin(twin(h)) != h"));
            }
            if t.origin == h.origin {
                return fail(format!("half-edge {i}: starts and ends at the same vertex"));
            }
            if self.half_edges[h.next.0].prev.0 != i || self.half_edges[h.prev.0].next.0 != i {
                return fail(format!("half-edge {i}: next and prev are not inverse"));
            }
            if self.half_edges[h.next.0].origin != t.origin {
                return fail(format!(
                    "half-edge {i}: next(h) does not start where h ends"
                ));
            }
            if self.half_edges[h.next.0].face != h.face {
                return fail(format!("half-edge {i}: next(h) has another face"));
            }
        }
        for (i, v) in self.vertices.iter().enumerate() {
            if let Some(h) = v.incident {
                if h.0 >= m || self.half_edges[h.0].origin.0 != i {
                    return fail(format!(
                        "vertex {i}: incident half-edge does not start there"
                    ));
                }
            }
        }
        // Every half-edge leaving a vertex is reached by the rotation around it, in
        // strict counter-clockwise order, and the rotation is consistent with next.
        let mut seen_out = vec![false; m];
        for v in self.vertex_ids() {
            let o = &self.vertices[v.0].point;
            let hs: Vec<HalfEdgeId> = self.around(v).take(m + 1).collect();
            if hs.len() > m {
                return fail(format!("vertex {}: rotation does not close", v.0));
            }
            let mut descents = 0;
            for (k, &h) in hs.iter().enumerate() {
                if self.half_edges[h.0].origin != v {
                    return fail(format!("vertex {}: rotation leaves the vertex", v.0));
                }
                seen_out[h.0] = true;
                let g = hs[(k + 1) % hs.len()];
                if hs.len() == 1 {
                    break;
                }
                let (a, b) = (self.dest_point(h), self.dest_point(g));
                let ord = half(o, a)
                    .cmp(&half(o, b))
                    .then_with(|| match orient_exact(o, a, b) {
                        Orientation::CounterClockwise => Ordering::Less,
                        Orientation::Clockwise => Ordering::Greater,
                        Orientation::Collinear => Ordering::Equal,
                    });
                match ord {
                    Ordering::Equal => {
                        return fail(format!("vertex {}: two edges leave in one direction", v.0))
                    }
                    Ordering::Greater => descents += 1,
                    Ordering::Less => {}
                }
            }
            if descents > 1 {
                return fail(format!("vertex {}: edges not in angular order", v.0));
            }
        }
        if let Some(h) = seen_out.iter().position(|s| !s) {
            return fail(format!("half-edge {h}: not reached around its origin"));
        }
        // Faces and cycles.
        if self.faces.is_empty() || self.faces[0].outer.is_some() {
            return fail("face 0 must be the unbounded face".into());
        }
        let mut listed = vec![false; m];
        for f in self.face_ids() {
            let face = &self.faces[f.0];
            if f.0 > 0 && face.outer.is_none() {
                return fail(format!("face {}: a second unbounded face", f.0));
            }
            for (k, start) in self.face_cycles(f).enumerate() {
                let outer = k == 0 && face.outer.is_some();
                let mut len = 0;
                for h in self.cycle(start) {
                    len += 1;
                    if len > m || listed[h.0] {
                        return fail(format!("face {}: cycle listed twice or open", f.0));
                    }
                    listed[h.0] = true;
                    if self.half_edges[h.0].face != f {
                        return fail(format!("face {}: half-edge {} has another face", f.0, h.0));
                    }
                }
                if self.cycle_is_ccw(start) != outer {
                    let what = if outer { "outer" } else { "inner" };
                    return fail(format!("face {}: {what} boundary wrongly oriented", f.0));
                }
            }
        }
        if let Some(h) = listed.iter().position(|s| !s) {
            return fail(format!(
                "half-edge {h}: its cycle is not listed in any face"
            ));
        }
        self.check_euler()
    }

    fn dest_point(&self, h: HalfEdgeId) -> &ExactPoint {
        &self.vertices[self.destination(h).0].point
    }

    /// True when the cycle turns strictly left at every visit of its lexicographically
    /// smallest vertex (an outer, counter-clockwise boundary).
    pub(crate) fn cycle_is_ccw(&self, start: HalfEdgeId) -> bool {
        let mut low = start;
        for h in self.cycle(start) {
            if self.origin_point(h).compare_xy(self.origin_point(low)) == Ordering::Less {
                low = h;
            }
        }
        let v = self.half_edges[low.0].origin;
        self.cycle(start)
            .filter(|&h| self.half_edges[h.0].origin == v)
            .all(|h| {
                let p = self.origin_point(self.half_edges[h.0].prev);
                orient_exact(p, self.origin_point(h), self.dest_point(h))
                    == Orientation::CounterClockwise
            })
    }

    fn check_euler(&self) -> Result<()> {
        let nv = self.vertices.len();
        let mut parent: Vec<usize> = (0..nv).collect();
        fn find(p: &mut [usize], mut x: usize) -> usize {
            while p[x] != x {
                p[x] = p[p[x]];
                x = p[x];
            }
            x
        }
        for h in (0..self.half_edges.len()).step_by(2) {
            let a = find(&mut parent, self.half_edges[h].origin.0);
            let b = find(&mut parent, self.half_edges[h + 1].origin.0);
            parent[a] = b;
        }
        let mut count = vec![0i64; nv];
        for v in 0..nv {
            let r = find(&mut parent, v);
            count[r] += 1;
        }
        for h in (0..self.half_edges.len()).step_by(2) {
            let r = find(&mut parent, self.half_edges[h].origin.0);
            count[r] -= 1;
        }
        for f in self.faces.iter().skip(1) {
            let o = f.outer.expect("checked");
            let r = find(&mut parent, self.half_edges[o.0].origin.0);
            count[r] += 1;
        }
        for (v, &c) in count.iter().enumerate() {
            if find(&mut parent, v) == v && c != 1 {
                return fail(format!(
                    "Euler's formula fails for the component of vertex {v} (V - E + F - 1 = {c})"
                ));
            }
        }
        Ok(())
    }
}
