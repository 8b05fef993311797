//! The same check for the faces of a subdivision (an overlay): its vertices' rounded
//! points, with the crossings that break it moved to other floats around their exact
//! points where that mends it.
//!
//! Every boundary cycle of every face is a ring of the check (each edge is then in two
//! rings, which only repeats pairs). Where a pair still fails, nothing is united again
//! (the faces are a partition with labels): the faces near it are reported.

use super::{failing_rings, ExactPoints, PointIds, RoundedRings};
use crate::dcel::{Dcel, FaceId};
use crate::kernel::{orient2d, orient_exact, ExactPoint, Orientation, Point2};

/// Whether rounding moved `p` to `q`: a crossing is on both its lines exactly when it
/// is the crossing itself.
fn moved(p: &ExactPoint, q: Point2) -> bool {
    match p {
        ExactPoint::Input(_) => false,
        ExactPoint::Crossing(c) => {
            orient2d(c.s.a, c.s.b, q) != Orientation::Collinear
                || orient2d(c.t.a, c.t.b, q) != Orientation::Collinear
        }
    }
}

/// Checks the rounded points of `d`'s vertices ([`failing_rings`]) and moves crossings
/// to other floats around their exact points where that makes a failing pair pass.
/// Returns the faces near which rounding may still have made edges touch or cross
/// (each once, ascending): see [`crate::overlay::mend_rounding`].
pub(in crate::overlay) fn mend_faces<V, E, F>(d: &mut Dcel<V, E, F>) -> Vec<FaceId> {
    let mut r = RoundedRings {
        starts: vec![0],
        ..RoundedRings::default()
    };
    let mut owner: Vec<FaceId> = Vec::new();
    // Faces with a cycle the check cannot follow (three vertices on one point, or fewer
    // than three points left: a face thinner than a float) are suspect as they are; the
    // other cycles are checked without them (a point moved there can only add to what
    // is suspect already).
    let mut collapsed: Vec<FaceId> = Vec::new();
    for f in d.face_ids() {
        for start in d.face_cycles(f) {
            let mut ok = true;
            let (mut pts, mut ids): (Vec<Point2>, Vec<PointIds>) = (Vec::new(), Vec::new());
            for h in d.cycle(start) {
                let v = d.half_edge(h).origin;
                let vertex = d.vertex(v);
                let id = PointIds::of(v.0 as u32, moved(&vertex.point, vertex.approx));
                match ids.last_mut() {
                    Some(last) if pts.last() == Some(&vertex.approx) => ok &= last.merge(id),
                    _ => {
                        pts.push(vertex.approx);
                        ids.push(id);
                    }
                }
            }
            while pts.len() > 1 && pts.first() == pts.last() {
                pts.pop();
                let mut last = ids.pop().expect("one per point");
                ok &= last.merge(ids[0]);
                ids[0] = last;
            }
            if !ok || pts.len() < 3 {
                collapsed.push(f);
                continue;
            }
            r.points.extend_from_slice(&pts);
            r.ids.extend_from_slice(&ids);
            r.starts.push(r.points.len());
            owner.push(f);
        }
    }
    let failing = {
        let vertices = &d.vertices;
        let exact = |v: u32| &vertices[v as usize].point;
        let exact_points = Some(ExactPoints {
            toward: |v: u32, q: Point2| {
                let (e, q) = (exact(v), ExactPoint::Input(q));
                (e.compare_x(&q), e.compare_y(&q))
            },
            order: |u: u32, v: u32| exact(u).compare_xy(exact(v)),
        });
        failing_rings(
            &mut r,
            |a, b, c| orient_exact(exact(a), exact(b), exact(c)),
            exact_points,
        )
    };
    // The moved points back into the vertices (every occurrence of a vertex moved
    // with the others).
    for (q, id) in r.points.iter().zip(&r.ids) {
        for v in [id.enter, id.leave] {
            d.vertices[v as usize].approx = *q;
        }
    }
    let mut suspect: Vec<FaceId> = failing.into_iter().map(|k| owner[k]).collect();
    suspect.extend(collapsed);
    suspect.sort_unstable_by_key(|f| f.0);
    suspect.dedup();
    suspect
}
