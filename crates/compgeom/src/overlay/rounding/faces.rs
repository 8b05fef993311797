//! The same check for the faces of a subdivision (an overlay): its vertices' rounded
//! points, with the crossings that break it moved to other floats around their exact
//! points where that mends it.
//!
//! Every boundary cycle of every face is a ring of the check (each edge is then in two
//! rings, which only repeats pairs). Where a pair still fails, nothing is united again
//! (the faces are a partition with labels): the faces near it are reported.

use super::{failing_rings, ExactPoints, PointIds, RoundedRings};
use crate::dcel::{rounded_away, Dcel, FaceId};
use crate::kernel::{orient_exact, Point2};

/// At most this many passes of [`mend_faces`] (each checks again after moving points:
/// a point moved can let another failing pair be mended); then the points stay.
const PASSES: usize = 8;

/// Checks the rounded points of `d`'s vertices ([`failing_rings`]) and, pass after
/// pass, moves crossings to other floats around their exact points where that makes a
/// failing pair pass, until a pass moves nothing. Returns the faces near which
/// rounding may still have made edges touch or cross (each once, ascending): see
/// [`crate::overlay::mend_rounding`]. A second call moves nothing more (unless the
/// first stopped at [`PASSES`]).
pub(in crate::overlay) fn mend_faces<V, E, F>(d: &mut Dcel<V, E, F>) -> Vec<FaceId> {
    for _ in 0..PASSES {
        let (suspect, moves) = checked(d, true);
        if moves.is_empty() {
            return suspect;
        }
        for (v, q) in moves {
            d.vertices[v].approx = q;
        }
    }
    checked(d, false).0
}

/// The faces near which rounding may have made edges touch or cross, as `d` is (no
/// point moved).
pub(in crate::overlay) fn suspect_faces<V, E, F>(d: &Dcel<V, E, F>) -> Vec<FaceId> {
    checked(d, false).0
}

/// One pass of the check over every boundary cycle of `d`: the suspect faces, and
/// (with `mend`) the vertices to move and where.
fn checked<V, E, F>(d: &Dcel<V, E, F>, mend: bool) -> (Vec<FaceId>, Vec<(usize, Point2)>) {
    let mut r = RoundedRings {
        starts: vec![0].into(),
        ..RoundedRings::default()
    };
    let mut owner: Vec<FaceId> = Vec::new();
    // Faces with a cycle whose consecutive points the check cannot merge (three
    // vertices on one point, or fewer than three points left: a face thinner than a
    // float) are suspect as they are. Such a cycle still goes into the check with every
    // vertex a point of its own (its edges of no length meet everything near), so that
    // what comes near its edges is found: the faces on their other sides may be
    // checked ones.
    let mut collapsed: Vec<FaceId> = Vec::new();
    // The rounded point of the origin of half-edge h and what the check knows of it.
    let point_of = |h| {
        let v = d.half_edge(h).origin;
        let vertex = d.vertex(v);
        let id = PointIds::of(v.0 as u32, rounded_away(&vertex.point, vertex.approx));
        (vertex.approx, id)
    };
    // One cycle's points and their ids (reused from cycle to cycle).
    let (mut pts, mut ids): (Vec<Point2>, Vec<PointIds>) = (Vec::new(), Vec::new());
    for f in d.face_ids() {
        for start in d.face_cycles(f) {
            let mut ok = true;
            pts.clear();
            ids.clear();
            for h in d.cycle(start) {
                let (q, id) = point_of(h);
                match ids.last_mut() {
                    Some(last) if pts.last() == Some(&q) => ok &= last.merge(id),
                    _ => {
                        pts.push(q);
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
                (pts, ids) = d.cycle(start).map(point_of).unzip();
            }
            r.points.extend_from_slice(&pts);
            r.ids.extend_from_slice(&ids);
            r.starts.push(r.points.len());
            owner.push(f);
        }
    }
    let vertices = &d.vertices;
    let exact = |v: u32| &vertices[v as usize].point;
    let exact_points = mend.then_some(ExactPoints {
        toward: |v: u32, q: Point2| exact(v).compare_with_point(q),
        order: |u: u32, v: u32| exact(u).compare_xy(exact(v)),
    });
    let failing = failing_rings(
        &mut r,
        |a, b, c| orient_exact(exact(a), exact(b), exact(c)),
        exact_points,
    );
    // The points moved (every occurrence of a vertex moved with the others).
    let mut moves = Vec::new();
    for (q, id) in r.points.iter().zip(&r.ids) {
        for v in [id.enter, id.leave] {
            if vertices[v as usize].approx != *q {
                moves.push((v as usize, *q));
            }
        }
    }
    moves.sort_unstable_by_key(|&(v, _)| v);
    moves.dedup_by_key(|&mut (v, _)| v);
    let mut suspect: Vec<FaceId> = failing.into_iter().map(|k| owner[k]).collect();
    suspect.extend(collapsed);
    suspect.sort_unstable_by_key(|f| f.0);
    suspect.dedup();
    (suspect, moves)
}
