//! Exact bottom-to-top order of the lines of one boundary chain of a half-plane
//! intersection (used by book §4.2, INTERSECTHALFPLANES), in O(n) for the bulk of the input
//! plus O(k log k) per group of `k` lines whose slopes round to the same `f64`.
//!
//! A right constraint `a·x + b·y <= c` (`a > 0`) comes higher on the right boundary the
//! larger `b / a` is; a left one (`a < 0`) the smaller `b / a` is. Both orders are the
//! increasing order of `b / |a|`. Division is correctly rounded and rounding is monotone,
//! so the `f64` quotient `fl(b / |a|)` never puts two lines in the wrong order: it can only
//! make different slopes *equal*. The lines are therefore sorted by that key (a radix sort
//! on its bits for large inputs), and only runs of equal keys are ordered by the exact sign
//! of the cross product of the normals (parallel lines stay next to each other). No
//! constructed value is compared, and the order is exact whatever the magnitudes:
//! overflow to `±inf` and underflow to zero are monotone roundings too.

use super::exact::{cross_sign, Line};
use std::cmp::Ordering;

/// Below this many lines a comparison sort beats the radix sort's fixed cost.
const RADIX_MIN: usize = 2048;

/// The `f64` key `fl(b / |a|)` (`a != 0`) as a `u64` with the same order (`-0` as `+0`).
#[inline]
fn key(l: &Line) -> u64 {
    let k = l.b / l.a.abs() + 0.0;
    let bits = k.to_bits();
    if bits >> 63 == 1 {
        !bits
    } else {
        bits | (1 << 63)
    }
}

/// Sort `ids` (lines with `a != 0`, all with the same sign of `a`) bottom to top along
/// their boundary chain: increasing `b / |a|`, exactly. Parallel lines end up next to each
/// other in some order.
pub(super) fn sort_chain(lines: &[Line], ids: &mut [usize]) {
    let n = ids.len();
    if n < 2 {
        return;
    }
    let mut keyed: Vec<(u64, usize)> = ids.iter().map(|&i| (key(&lines[i]), i)).collect();
    if n < RADIX_MIN {
        // (Ties in input order, as the stable radix sort leaves them.)
        keyed.sort_unstable();
    } else {
        radix_sort(&mut keyed);
    }
    // Runs of equal keys: order them by the exact sign of the cross product (for two lines
    // of one chain, `cross(i, j) > 0` exactly when `b_i / |a_i| < b_j / |a_j|` if `a > 0`,
    // and when `b_i / |a_i| > b_j / |a_j|` if `a < 0`).
    let flip = lines[keyed[0].1].a < 0.0;
    let mut start = 0;
    while start < n {
        let mut end = start + 1;
        while end < n && keyed[end].0 == keyed[start].0 {
            end += 1;
        }
        if end - start > 1 {
            keyed[start..end].sort_by(|&(_, i), &(_, j)| {
                let s = match cross_sign(&lines[i], &lines[j]) {
                    Ordering::Greater => Ordering::Less,
                    Ordering::Less => Ordering::Greater,
                    Ordering::Equal => Ordering::Equal,
                };
                if flip {
                    s.reverse()
                } else {
                    s
                }
            });
        }
        start = end;
    }
    for (slot, &(_, i)) in ids.iter_mut().zip(&keyed) {
        *slot = i;
    }
}

/// Stable least-significant-digit radix sort by the `u64` key, 11 bits a pass; passes in
/// which every key has the same digit are skipped.
fn radix_sort(v: &mut Vec<(u64, usize)>) {
    const BITS: u32 = 11;
    const BUCKETS: usize = 1 << BITS;
    let n = v.len();
    // One histogram per pass, all in one read of the keys.
    let passes = 64u32.div_ceil(BITS) as usize;
    let mut counts = vec![[0usize; BUCKETS]; passes];
    for &(k, _) in v.iter() {
        for (p, c) in counts.iter_mut().enumerate() {
            c[((k >> (p as u32 * BITS)) as usize) & (BUCKETS - 1)] += 1;
        }
    }
    let mut tmp: Vec<(u64, usize)> = vec![(0, 0); n];
    for (p, c) in counts.iter_mut().enumerate() {
        if c.contains(&n) {
            continue;
        }
        let mut sum = 0;
        for x in c.iter_mut() {
            let t = *x;
            *x = sum;
            sum += t;
        }
        let shift = p as u32 * BITS;
        for &(k, i) in v.iter() {
            let d = ((k >> shift) as usize) & (BUCKETS - 1);
            tmp[c[d]] = (k, i);
            c[d] += 1;
        }
        std::mem::swap(v, &mut tmp);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The exact order by comparisons only.
    fn reference(lines: &[Line], ids: &mut [usize]) {
        let flip = lines[ids[0]].a < 0.0;
        ids.sort_by(|&i, &j| {
            let s = cross_sign(&lines[j], &lines[i]);
            if flip {
                s.reverse()
            } else {
                s
            }
        });
    }

    fn check(lines: &[Line]) {
        for right in [true, false] {
            let mut ids: Vec<usize> = (0..lines.len())
                .filter(|&i| (lines[i].a > 0.0) == right && lines[i].a != 0.0)
                .collect();
            if ids.is_empty() {
                continue;
            }
            let mut want = ids.clone();
            reference(lines, &mut want);
            sort_chain(lines, &mut ids);
            // Same order up to permutations of parallel lines.
            for (&p, &q) in ids.iter().zip(&want) {
                assert_eq!(
                    cross_sign(&lines[p], &lines[q]),
                    Ordering::Equal,
                    "{:?} vs {:?}",
                    lines[p],
                    lines[q]
                );
            }
        }
    }

    #[test]
    fn matches_comparison_sort_on_large_and_tied_input() {
        let mut unit = crate::testing::units(99);
        let mut next = || unit() - 0.5;
        let mut lines = Vec::new();
        for t in 0..6000 {
            let (a, b) = match t % 4 {
                // Slopes that round alike: multiples of one direction, and neighbours one
                // ulp apart in `b` (different exact slopes, often the same quotient).
                0 => (3.0 * (t % 7 + 1) as f64, 1.0 * (t % 7 + 1) as f64),
                1 => (3.0, f64::from_bits(1.0f64.to_bits() + (t % 5) as u64)),
                2 => (next() * 1e-300, next() * 1e300),
                _ => (next(), next()),
            };
            let a = if a == 0.0 { 1.0 } else { a };
            lines.push(Line::input(a, b, 0.0));
            lines.push(Line::input(-a, b, 0.0));
        }
        check(&lines);
        check(&lines[..300]);
    }
}
