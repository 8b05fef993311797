//! Exact verifiers for range answers (used by `--verify` and the tests): brute force,
//! O(n) per query.

use super::distance::compare_distance;
use crate::kernel::{Bbox2, Point2};
use crate::{Error, Result};
use std::cmp::Ordering;

/// Check that `result` is exactly the ascending list of indices of the points of `points`
/// in the closed rectangle `rect`. `Err(Verification)` names the first discrepancy.
///
/// ```
/// use compgeom::range::verify_query;
/// use compgeom::{Bbox2, Point2};
/// let pts = [Point2::new(0.0, 0.0), Point2::new(1.0, 1.0)];
/// let r = Bbox2 { min: Point2::new(1.0, 1.0), max: Point2::new(2.0, 2.0) };
/// assert!(verify_query(&pts, &r, &[1]).is_ok());
/// assert!(verify_query(&pts, &r, &[0, 1]).is_err());
/// ```
pub fn verify_query(points: &[Point2], rect: &Bbox2, result: &[usize]) -> Result<()> {
    let want = (0..points.len()).filter(|&i| rect.contains(points[i]));
    let mut got = result.iter().copied();
    for w in want {
        match got.next() {
            Some(g) if g == w => {}
            Some(g) => {
                return Err(Error::Verification(format!(
                    "query {rect:?}: reported {g} where point {w} was expected"
                )))
            }
            None => {
                return Err(Error::Verification(format!(
                    "query {rect:?}: point {w} is inside but not reported"
                )))
            }
        }
    }
    match got.next() {
        Some(g) => Err(Error::Verification(format!(
            "query {rect:?}: reported {g}, which is not inside (or out of order)"
        ))),
        None => Ok(()),
    }
}

/// Check a k-nearest-neighbour answer: `min(k, n)` distinct indices, ordered by exact
/// distance to `q` and then by index, and no other point strictly before the last one in
/// that order.
pub fn verify_nearest(points: &[Point2], q: Point2, k: usize, result: &[usize]) -> Result<()> {
    let key = |a: usize, b: usize| compare_distance(q, points[a], points[b]).then(a.cmp(&b));
    if result.len() != k.min(points.len()) {
        return Err(Error::Verification(format!(
            "k-NN of {q:?}: {} points reported, expected {}",
            result.len(),
            k.min(points.len())
        )));
    }
    if result.iter().any(|&i| i >= points.len()) {
        return Err(Error::Verification("k-NN: index out of range".into()));
    }
    for w in result.windows(2) {
        if key(w[0], w[1]) != Ordering::Less {
            return Err(Error::Verification(format!(
                "k-NN of {q:?}: {} and {} are out of order",
                w[0], w[1]
            )));
        }
    }
    if let Some(&last) = result.last() {
        let mut chosen = vec![false; points.len()];
        result.iter().for_each(|&i| chosen[i] = true);
        if let Some(i) = (0..points.len()).find(|&i| !chosen[i] && key(i, last) == Ordering::Less) {
            return Err(Error::Verification(format!(
                "k-NN of {q:?}: point {i} is nearer than reported point {last}"
            )));
        }
    }
    Ok(())
}
