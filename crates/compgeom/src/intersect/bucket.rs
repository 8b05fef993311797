//! A cache-friendly bucket sort for the pair records of the pairwise method and of
//! counting: records spread over a range of `f64` keys are sorted in O(K) expected time.
//!
//! Each record goes to one of about K fine buckets by a monotone map of its key; fine
//! buckets are grouped into at most [`COARSE`] coarse ones, and the records are first
//! partitioned by coarse bucket (a counting table that stays in the L1 cache), then each
//! coarse bucket is spread over its fine buckets (a table that stays in L2), and each
//! fine bucket is sorted by the full order. One pass with random writes over millions
//! of buckets was memory-bound (two cache misses per record at 25 million records).

use rayon::prelude::*;
use std::cmp::Ordering;

/// At most this many coarse buckets (each part of a parallel sort writes one stream per
/// coarse bucket: 512 scattered about 1.8× faster than 2048 on long 1e3, one thread,
/// and buckets of ~500 records still spread within L1).
const COARSE: usize = 512;

/// From this many items on, the coarse buckets are finished on the rayon pool.
const PARALLEL_FROM: usize = 1 << 16;

/// Sort `items` by `cmp`, where `key` is a monotone `f64` summary of the order:
/// `key(a) < key(b)` implies `cmp(a, b) == Less` (`-inf` allowed, NaN not expected: it
/// goes to the first bucket). O(K) for keys spread over their range, O(K log K) at worst.
/// Large inputs finish their coarse buckets in parallel (the result does not depend on
/// it: each bucket is sorted by `cmp`, as an unstable sort would).
pub(super) fn sort_by_key_then<T: Copy + Send + Sync>(
    items: &mut [T],
    key: impl Fn(&T) -> f64 + Sync,
    cmp: impl Fn(&T, &T) -> Ordering + Copy + Sync,
) {
    let n = items.len();
    // (Bucket offsets are u32: beyond that, a plain sort.)
    if n < 64 || n >= u32::MAX as usize {
        items.sort_unstable_by(cmp);
        return;
    }
    let (lo, hi) = items
        .iter()
        .map(&key)
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    let scale = if hi > lo { n as f64 / (hi - lo) } else { 0.0 };
    // `as usize` saturates (and maps NaN, from an infinite scale, to 0): monotone.
    let fine = |t: &T| (((key(t) - lo) * scale) as usize).min(n - 1);
    // Coarse bucket = fine bucket >> shift, at most COARSE of them.
    let mut shift = 0;
    while (n - 1) >> shift >= COARSE {
        shift += 1;
    }
    let coarse_count = ((n - 1) >> shift) + 1;
    // Each item's fine bucket, computed once (n < 2^32).
    let fines: Vec<u32> = items.iter().map(|t| fine(t) as u32).collect();
    let mut start = vec![0u32; coarse_count + 1];
    for &f in &fines {
        start[(f as usize >> shift) + 1] += 1;
    }
    for c in 0..coarse_count {
        start[c + 1] += start[c];
    }
    let mut fill = start.clone();
    let mut parted = items.to_vec();
    let mut parted_fines = vec![0u32; n];
    for (t, &f) in items.iter().zip(&fines) {
        let c = f as usize >> shift;
        parted[fill[c] as usize] = *t;
        parted_fines[fill[c] as usize] = f;
        fill[c] += 1;
    }
    drop(fines);
    // Each coarse bucket spread over its fine buckets, back into `items`: disjoint
    // pieces, so they can be finished independently.
    let width = 1usize << shift;
    let finish =
        |c: usize, (from, from_fines): (&[T], &[u32]), to: &mut [T], local: &mut Vec<u32>| {
            if from.len() <= 1 {
                to.copy_from_slice(from);
                return;
            }
            spread_and_sort(from, from_fines, to, c << shift, width, cmp, local);
        };
    let mut pieces = Vec::with_capacity(coarse_count);
    let mut rest = &mut items[..];
    for c in 0..coarse_count {
        let len = (start[c + 1] - start[c]) as usize;
        let (piece, tail) = rest.split_at_mut(len);
        rest = tail;
        pieces.push((c, piece));
    }
    let from = |c: usize| {
        let r = start[c] as usize..start[c + 1] as usize;
        (&parted[r.clone()], &parted_fines[r])
    };
    if n >= PARALLEL_FROM {
        pieces
            .into_par_iter()
            .with_min_len(16)
            .for_each_init(Vec::new, |local, (c, to)| finish(c, from(c), to, local));
    } else {
        let mut local = Vec::new();
        for (c, to) in pieces {
            finish(c, from(c), to, &mut local);
        }
    }
}

/// The concatenation of `parts` (the pieces a parallel scan produced), sorted as
/// [`sort_by_key_then`] sorts (same contract for `key` and `cmp`).
pub(super) fn sort_parts<T: Copy + Send + Sync>(
    parts: Vec<Vec<T>>,
    key: impl Fn(&T) -> f64 + Sync,
    cmp: impl Fn(&T, &T) -> Ordering + Copy + Sync,
) -> Vec<T> {
    let n: usize = parts.iter().map(Vec::len).sum();
    if n < PARALLEL_FROM {
        let mut all = Vec::with_capacity(n);
        for p in &parts {
            all.extend_from_slice(p);
        }
        sort_by_key_then(&mut all, key, cmp);
        return all;
    }
    sort_parts_large(parts, key, cmp)
}

/// [`sort_parts`] for many items, each pass on the rayon pool: each part counts its
/// records per coarse bucket, then scatters them straight into its own sub-range of
/// each coarse bucket of the output (the output is cut into one slice per (bucket,
/// part), so the parts write disjoint memory), then each coarse bucket is spread over
/// its fine buckets through a small scratch buffer that stays in cache. Two buffers of
/// the records in all (the parts and the output) instead of four, and no serial pass
/// over them. (Producers that know their keys' range up front bin their records as
/// they make them instead: [`super::bins`].)
fn sort_parts_large<T: Copy + Send + Sync>(
    parts: Vec<Vec<T>>,
    key: impl Fn(&T) -> f64 + Sync,
    cmp: impl Fn(&T, &T) -> Ordering + Copy + Sync,
) -> Vec<T> {
    let n: usize = parts.iter().map(Vec::len).sum();
    let Some(&filler) = parts.iter().find_map(|p| p.first()) else {
        return Vec::new();
    };
    // (Bucket offsets are u32: beyond that, a plain sort.)
    if n >= u32::MAX as usize {
        let mut all = parts.concat();
        all.sort_unstable_by(cmp);
        return all;
    }
    let part_range = |p: &Vec<T>| {
        p.iter()
            .map(&key)
            .filter(|v| v.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            })
    };
    let (lo, hi) = parts.par_iter().map(part_range).reduce(
        || (f64::INFINITY, f64::NEG_INFINITY),
        |a, b| (a.0.min(b.0), a.1.max(b.1)),
    );
    let scale = if hi > lo { n as f64 / (hi - lo) } else { 0.0 };
    // Monotone in the key (`as usize` saturates, NaN from an infinite scale goes to 0).
    let fine = |t: &T| (((key(t) - lo) * scale) as usize).min(n - 1);
    let mut shift = 0;
    while (n - 1) >> shift >= COARSE {
        shift += 1;
    }
    let coarse_count = ((n - 1) >> shift) + 1;
    // Each record's fine bucket, computed once (the key is most of the cost of a pass),
    // and each part's count per coarse bucket.
    let (fines, counts): (Vec<Vec<u32>>, Vec<Vec<u32>>) = parts
        .par_iter()
        .map(|p| {
            let fines: Vec<u32> = p.iter().map(|t| fine(t) as u32).collect();
            let mut c = vec![0u32; coarse_count];
            for &f in &fines {
                c[f as usize >> shift] += 1;
            }
            (fines, c)
        })
        .unzip();
    // Filled on the pool: a serial fill of fresh memory was a pass of its own.
    let mut out = Vec::with_capacity(n);
    out.par_extend(rayon::iter::repeat_n(filler, n));
    let mut out_fines = Vec::with_capacity(n);
    out_fines.par_extend(rayon::iter::repeat_n(0u32, n));
    // Bucket c holds out[start[c]..start[c + 1]]; within it, part 0's records first.
    let mut start = vec![0usize; coarse_count + 1];
    for c in 0..coarse_count {
        start[c + 1] = start[c] + counts.iter().map(|k| k[c] as usize).sum::<usize>();
    }
    {
        let mut rows: Vec<Vec<(&mut [T], &mut [u32])>> = (0..parts.len())
            .map(|_| Vec::with_capacity(coarse_count))
            .collect();
        let (mut rest, mut rest_fines) = (&mut out[..], &mut out_fines[..]);
        for c in 0..coarse_count {
            for (row, k) in rows.iter_mut().zip(&counts) {
                let (piece, tail) = rest.split_at_mut(k[c] as usize);
                let (piece_fines, tail_fines) = rest_fines.split_at_mut(k[c] as usize);
                (rest, rest_fines) = (tail, tail_fines);
                row.push((piece, piece_fines));
            }
        }
        parts
            .par_iter()
            .zip(&fines)
            .zip(rows.into_par_iter())
            .for_each(|((part, part_fines), mut row)| {
                let mut fill = vec![0usize; coarse_count];
                for (t, &f) in part.iter().zip(part_fines) {
                    let c = f as usize >> shift;
                    let (to, to_fines) = &mut row[c];
                    to[fill[c]] = *t;
                    to_fines[fill[c]] = f;
                    fill[c] += 1;
                }
            });
    }
    drop(parts);
    drop(fines);
    let mut buckets = Vec::with_capacity(coarse_count);
    let (mut rest, mut rest_fines) = (&mut out[..], &out_fines[..]);
    for c in 0..coarse_count {
        let len = start[c + 1] - start[c];
        let (piece, tail) = rest.split_at_mut(len);
        let (piece_fines, tail_fines) = rest_fines.split_at(len);
        (rest, rest_fines) = (tail, tail_fines);
        buckets.push((c, piece, piece_fines));
    }
    let width = 1usize << shift;
    buckets.into_par_iter().with_min_len(16).for_each_init(
        || (Vec::new(), Vec::new()),
        |(scratch, local): &mut (Vec<T>, Vec<u32>), (c, bucket, fines)| {
            finish_bucket(bucket, fines, c << shift, width, cmp, scratch, local);
        },
    );
    out
}

/// Sort one coarse bucket, whose items are in fine buckets `fines` (within
/// `base..base + width`): small ones directly, the others spread over their fine
/// buckets through `scratch`, then each sorted.
fn finish_bucket<T: Copy>(
    bucket: &mut [T],
    fines: &[u32],
    base: usize,
    width: usize,
    cmp: impl Fn(&T, &T) -> Ordering + Copy,
    scratch: &mut Vec<T>,
    local: &mut Vec<u32>,
) {
    if bucket.len() <= 16 {
        bucket.sort_unstable_by(cmp);
        return;
    }
    scratch.clear();
    scratch.extend_from_slice(bucket);
    spread_and_sort(scratch, fines, bucket, base, width, cmp, local);
}

/// Spread `from`, whose items are in fine buckets `fines` (within `base..base + width`),
/// over those buckets in `to` (a counting sort, stable), then sort each fine bucket.
pub(super) fn spread_and_sort<T: Copy>(
    from: &[T],
    fines: &[u32],
    to: &mut [T],
    base: usize,
    width: usize,
    cmp: impl Fn(&T, &T) -> Ordering,
    local: &mut Vec<u32>,
) {
    local.clear();
    local.resize(width + 1, 0);
    // The largest fine bucket, tracked while counting: when none is above `SMALL` (the
    // common case, about one record per fine bucket) the pass over the buckets below
    // that looks for large ones is skipped.
    let mut largest = 0;
    for &f in fines {
        let count = &mut local[f as usize - base + 1];
        *count += 1;
        largest = largest.max(*count);
    }
    // (A running sum in a register: `local[f + 1] += local[f]` waited on the store of
    // the step before, a store-forwarding latency per fine bucket.)
    let mut sum = 0;
    for c in local.iter_mut() {
        sum += *c;
        *c = sum;
    }
    let mut at = local.clone();
    for (t, &f) in from.iter().zip(fines) {
        let f = f as usize - base;
        to[at[f] as usize] = *t;
        at[f] += 1;
    }
    // The fine buckets are in order; within them, only large ones are sorted on their
    // own, then one insertion sort over the whole range finishes the small ones: the
    // lengths of the fine buckets (mostly 0, 1 or 2, at random) are no longer branched
    // on, which mispredicted about once per record. At most `SMALL` records per
    // unsorted fine bucket bound the insertion sort's work by `SMALL` per record.
    if largest > SMALL as u32 {
        for w in local.windows(2) {
            if w[1] - w[0] > SMALL as u32 {
                to[w[0] as usize..w[1] as usize].sort_unstable_by(&cmp);
            }
        }
    }
    insertion_sort(to, &cmp);
}

/// Fine buckets up to this many records are left to [`insertion_sort`].
const SMALL: usize = 16;

/// Sort `v` by `cmp` by insertion: O(len + inversions), for nearly sorted `v`.
fn insertion_sort<T: Copy>(v: &mut [T], cmp: impl Fn(&T, &T) -> Ordering) {
    for i in 1..v.len() {
        let x = v[i];
        if cmp(&x, &v[i - 1]) == Ordering::Less {
            let mut j = i - 1;
            v[i] = v[j];
            while j > 0 && cmp(&x, &v[j - 1]) == Ordering::Less {
                v[j] = v[j - 1];
                j -= 1;
            }
            v[j] = x;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sorts_like_a_plain_sort() {
        let mut next = crate::testing::bits(3u64);
        for n in [0, 1, 63, 64, 65, 1000, 5000, 100_000, 300_000] {
            for kind in 0..4 {
                let v: Vec<(f64, u64)> = (0..n)
                    .map(|k| {
                        let r = next();
                        let key = match kind {
                            0 => r as f64 / (1u64 << 53) as f64,
                            1 => (r % 7) as f64,
                            2 if k % 10 == 0 => f64::NEG_INFINITY,
                            2 => (r as f64).powi(3),
                            _ => 1.0,
                        };
                        (key, r % 100)
                    })
                    .collect();
                let cmp = |a: &(f64, u64), b: &(f64, u64)| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1));
                let mut want = v.clone();
                want.sort_unstable_by(cmp);
                let mut got = v;
                sort_by_key_then(&mut got, |t| t.0, cmp);
                // The same records in uneven parts (some empty).
                let mut parts: Vec<Vec<(f64, u64)>> = vec![Vec::new(); 5];
                for (k, t) in got.iter().rev().enumerate() {
                    parts[(k * k) % 4].push(*t);
                }
                let from_parts = sort_parts(parts, |t| t.0, cmp);
                assert!(
                    from_parts
                        .iter()
                        .zip(&want)
                        .all(|(a, b)| cmp(a, b) == Ordering::Equal),
                    "parts: n {n} kind {kind}"
                );
                assert_eq!(from_parts.len(), want.len());
                assert!(
                    got.iter()
                        .zip(&want)
                        .all(|(a, b)| cmp(a, b) == Ordering::Equal),
                    "n {n} kind {kind}"
                );
                assert_eq!(got.len(), want.len());
            }
        }
    }
}
