//! The composite-number space of §5.5: how the structures handle equal coordinates.
//!
//! The book assumes no two points share an x- or a y-coordinate, then removes the
//! assumption by replacing each coordinate with a *composite number*: x becomes the pair
//! `(x | y)` compared lexicographically, y becomes `(y | x)`. compgeom goes one step
//! further and appends the input index, `(x | y | i)` and `(y | x | i)`, so that even
//! duplicate points get distinct keys and every order the structures use is a strict
//! total order. A query range `[x, x']` on the first coordinate becomes the composite range
//! `[(x | -inf | 0), (x' | +inf | max)]`, which selects exactly the points with
//! `x <= px <= x'`; in code this is a search on the leading coordinate's value alone,
//! because the points it selects are contiguous in composite order.
//!
//! Coordinates are finite (checked when a structure is built), so the `f64` comparisons
//! below are exact total orders, with `-0.0 == 0.0`.

use crate::kernel::{ensure_finite, Point2};
use crate::{Error, Result};
use std::cmp::Ordering;

/// Compare two finite values (`-0.0 == 0.0`).
#[inline]
pub(crate) fn cmp_f64(a: f64, b: f64) -> Ordering {
    // Adding 0.0 turns -0.0 into 0.0 and changes nothing else; on the result `total_cmp`
    // (an integer comparison, branch-free) agrees with `<` for finite values and is
    // several times faster than `partial_cmp` inside selection and sorting.
    (a + 0.0).total_cmp(&(b + 0.0))
}

/// `(x | y | i)` order: the composite x-coordinate of §5.5 with the index as a last key.
#[inline]
pub fn cmp_composite_x(p: Point2, i: usize, q: Point2, j: usize) -> Ordering {
    cmp_f64(p.x, q.x)
        .then_with(|| cmp_f64(p.y, q.y))
        .then(i.cmp(&j))
}

/// `(y | x | i)` order: the composite y-coordinate of §5.5 with the index as a last key.
#[inline]
pub fn cmp_composite_y(p: Point2, i: usize, q: Point2, j: usize) -> Ordering {
    cmp_f64(p.y, q.y)
        .then_with(|| cmp_f64(p.x, q.x))
        .then(i.cmp(&j))
}

/// Check what every structure of this module requires of its input: finite coordinates
/// and an index that fits in 32 bits (indices are stored as `u32` to halve memory).
pub(crate) fn check_points(points: &[Point2]) -> Result<()> {
    ensure_finite(points, "point")?;
    check_len(points.len())
}

/// At most `u32::MAX` items.
pub(crate) fn check_len(n: usize) -> Result<()> {
    if n > u32::MAX as usize {
        return Err(Error::InvalidInput(format!(
            "{n} items: at most {} are supported",
            u32::MAX
        )));
    }
    Ok(())
}

/// Indices `0..n` sorted in `(x | y | i)` order; in parallel above `PARALLEL` points.
pub(crate) fn order_by_x(points: &[Point2]) -> Vec<u32> {
    use rayon::prelude::*;
    let mut ids: Vec<u32> = (0..points.len() as u32).collect();
    let cmp = |&a: &u32, &b: &u32| {
        cmp_composite_x(
            points[a as usize],
            a as usize,
            points[b as usize],
            b as usize,
        )
    };
    if points.len() >= PARALLEL {
        ids.par_sort_unstable_by(cmp);
    } else {
        ids.sort_unstable_by(cmp);
    }
    ids
}

/// Inputs at least this large are built on the rayon pool.
pub(crate) const PARALLEL: usize = 1 << 15;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn composite_orders_are_strict_and_lexicographic() {
        let p = Point2::new(1.0, 2.0);
        let q = Point2::new(1.0, 3.0);
        assert_eq!(cmp_composite_x(p, 5, q, 0), Ordering::Less);
        assert_eq!(cmp_composite_y(q, 0, p, 5), Ordering::Greater);
        assert_eq!(cmp_composite_x(p, 1, p, 2), Ordering::Less);
        assert_eq!(
            cmp_composite_x(Point2::new(-0.0, 0.0), 0, Point2::new(0.0, 0.0), 0),
            Ordering::Equal
        );
    }
}
