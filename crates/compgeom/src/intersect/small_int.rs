//! An exact fast path for small-integer input (grid data, the most degenerate input in
//! practice): when every coordinate involved is an integer of magnitude below 2^20, the
//! homogeneous coordinates of a crossing and every comparison the sweep makes fit in
//! `i128`, so equalities (coinciding crossings, a crossing on a third segment, collinear
//! segments) are decided without the kernel's big-number fallback. Any other input returns
//! `None` and the caller uses the kernel.
//!
//! Bounds: coordinate differences are below 2^21; a crossing `(X / D, Y / D)` has
//! `|D| < 2^43` and `|X|, |Y| < 2^64` (`a·D + d·num`); the products compared below are
//! below 2^108.

use crate::kernel::{Crossing, ExactPoint, Point2};
use std::cmp::Ordering;

const LIMIT: f64 = (1u64 << 20) as f64;

fn int(v: f64) -> Option<i128> {
    // `as i64` saturates and maps NaN to 0; the round trip and the range test reject those.
    let i = v as i64;
    (v.abs() < LIMIT && i as f64 == v).then_some(i128::from(i))
}

/// Homogeneous integer coordinates `(X, Y, D)` of a point `(X / D, Y / D)`, `D > 0`.
pub(crate) type Hom = (i128, i128, i128);

/// The sweep order (y decreasing, then x increasing) of two points, exactly.
pub(crate) fn sweep_cmp(a: Hom, b: Hom) -> Ordering {
    (b.1 * a.2)
        .cmp(&(a.1 * b.2))
        .then_with(|| (a.0 * b.2).cmp(&(b.0 * a.2)))
}

/// Homogeneous integer coordinates `(X, Y, D)` with `D > 0`.
pub(crate) fn hom(p: &ExactPoint) -> Option<Hom> {
    match p {
        ExactPoint::Input(q) => Some((int(q.x)?, int(q.y)?, 1)),
        ExactPoint::Crossing(c) => crossing(c),
    }
}

fn crossing(c: &Crossing) -> Option<Hom> {
    let (s, t) = (c.s, c.t);
    let (ax, ay) = (int(s.a.x)?, int(s.a.y)?);
    let (dx, dy) = (int(s.b.x)? - ax, int(s.b.y)? - ay);
    let (tx, ty) = (int(t.a.x)?, int(t.a.y)?);
    let (ex, ey) = (int(t.b.x)? - tx, int(t.b.y)? - ty);
    let (wx, wy) = (tx - ax, ty - ay);
    let den = dx * ey - dy * ex;
    if den == 0 {
        return None;
    }
    let num = wx * ey - wy * ex;
    let (x, y) = (ax * den + dx * num, ay * den + dy * num);
    Some(if den > 0 { (x, y, den) } else { (-x, -y, -den) })
}

/// Exact comparison of the x (`axis` 0) or y (`axis` 1) coordinates.
pub(crate) fn compare_coord(p: &ExactPoint, q: &ExactPoint, axis: u8) -> Option<Ordering> {
    let (a, b) = (hom(p)?, hom(q)?);
    let (u, v) = if axis == 0 { (a.0, b.0) } else { (a.1, b.1) };
    // u / a.2 vs v / b.2 with positive denominators.
    Some((u * b.2).cmp(&(v * a.2)))
}

/// The exact sign of the orientation of `(u, l, p)` (`Greater` = counter-clockwise).
pub(crate) fn orient(u: Point2, l: Point2, p: &ExactPoint) -> Option<Ordering> {
    let (x, y, d) = hom(p)?;
    let (ux, uy) = (int(u.x)?, int(u.y)?);
    let (lx, ly) = (int(l.x)?, int(l.y)?);
    let det = (lx - ux) * (y - uy * d) - (ly - uy) * (x - ux * d);
    Some(det.cmp(&0))
}

/// The exact sign of `(b - a) × (d - c)`.
pub(crate) fn cross(a: Point2, b: Point2, c: Point2, d: Point2) -> Option<Ordering> {
    let (ax, ay, bx, by) = (int(a.x)?, int(a.y)?, int(b.x)?, int(b.y)?);
    let (cx, cy, dx, dy) = (int(c.x)?, int(c.y)?, int(d.x)?, int(d.y)?);
    Some(((bx - ax) * (dy - cy) - (by - ay) * (dx - cx)).cmp(&0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::{orient_exact, Orientation, Segment2};

    #[test]
    fn agrees_with_the_kernel_on_grid_crossings() {
        let mut state = 11u64;
        let mut coord = move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 33) % 9) as f64 * if state & 1 == 0 { 1.0 } else { 100_000.0 }
        };
        let mut checked = 0;
        for _ in 0..4000 {
            let mut seg =
                || Segment2::new(Point2::new(coord(), coord()), Point2::new(coord(), coord()));
            let (Some(c1), Some(c2)) = (Crossing::new(seg(), seg()), Crossing::new(seg(), seg()))
            else {
                continue;
            };
            let (p, q) = (ExactPoint::Crossing(c1), ExactPoint::Crossing(c2));
            assert_eq!(compare_coord(&p, &q, 0), Some(p.compare_x(&q)));
            let order = q.compare_y(&p).then_with(|| p.compare_x(&q));
            assert_eq!(sweep_cmp(hom(&p).unwrap(), hom(&q).unwrap()), order);
            assert_eq!(compare_coord(&p, &q, 1), Some(p.compare_y(&q)));
            let (u, l) = (c2.s.a, c2.t.b);
            let expected = match orient_exact(&u.into(), &l.into(), &p) {
                Orientation::CounterClockwise => Ordering::Greater,
                Orientation::Clockwise => Ordering::Less,
                Orientation::Collinear => Ordering::Equal,
            };
            assert_eq!(orient(u, l, &p), Some(expected));
            checked += 1;
        }
        assert!(checked > 1000);
        assert_eq!(hom(&ExactPoint::Input(Point2::new(0.5, 1.0))), None);
    }
}
