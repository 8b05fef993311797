//! Records put in coarse bins by a monotone `f64` key as they are produced, then each bin
//! sorted on its own: the bucket sort of [`super::bucket`] with its first pass (a read
//! of every record to find its coarse bucket, and a scattered write of it into a second
//! buffer) done by the producer at the moment it writes the record.
//!
//! Dense inputs produce hundreds of thousands of crossing records at random keys. Sorted
//! after the fact they were read three times and written twice from memory that no
//! cache holds; binned as they are made, each record is written once, and each bin is
//! sorted while it fits in the L2 cache. Long random 1e3 (251k records), one thread,
//! session 25 (`examples/intersect_profile`-like driver, phases timed apart): the scan
//! with its rounding 5.7 → 7.0–7.8 ms, the sort 6.1 → 3.1–4.1 ms; the whole `find`
//! 3–8% faster in paired runs, more when the call follows other work (see
//! [`RECORDS_PER_BIN`]). On one thread, [`each_sorted_bin`] sorts each bin into a
//! scratch buffer and hands it on from there, for the caller to consume while it is in
//! cache (session 26: the points built bin by bin, see `brute_force::assemble_fused`).

use super::bucket::spread_and_sort;
use rayon::prelude::*;
use std::cmp::Ordering;

/// At most this many bins (inputs with millions of records: bins of up to ~50k).
pub(super) const MAX_BINS: usize = 512;

/// About this many records per bin are aimed for (~100 KiB of 24-byte records, sorted
/// within the L2 cache). Each producer writes one stream per bin, and few streams
/// matter: with 490 bins of 512 records on long random 1e3 the scan took 10.4 ms when
/// the call followed 30 ms of other work (the bins' memory no longer cached: each
/// stream's new cache line a miss the prefetchers do not hide), against 7.0 ms right
/// after another call; with 61 bins of ~4100, 7.6–8.2 ms; with 16 bins the scan is no
/// faster and the sort of the larger bins 1 ms slower.
const RECORDS_PER_BIN: usize = 4096;

/// Items in bins by key: bin `b` holds the keys in `[lo + b / scale, lo + (b + 1) /
/// scale)`, the first and the last also those below and above (the map from key to bin
/// is monotone, so the bins in order hold the items in key order up to the order within
/// each bin).
#[derive(Clone)]
pub(super) struct Bins<T> {
    lo: f64,
    scale: f64,
    bins: Vec<Vec<T>>,
}

impl<T: Copy> Default for Bins<T> {
    fn default() -> Self {
        Bins::single(0)
    }
}

impl<T: Copy> Bins<T> {
    /// One bin (a plain list) with room for `capacity` items.
    pub(super) fn single(capacity: usize) -> Bins<T> {
        Bins {
            lo: 0.0,
            scale: 0.0,
            bins: vec![Vec::with_capacity(capacity)],
        }
    }

    /// The layout for about `expected` items with keys in `lo..=hi`: how many bins
    /// ([`Bins::laid_out`] takes it), at most [`MAX_BINS`].
    pub(super) fn count_for(expected: usize) -> usize {
        (expected / RECORDS_PER_BIN).clamp(1, MAX_BINS)
    }

    /// `count` empty bins over the keys `lo..=hi`, bin `b` with room for `room(b)` items.
    pub(super) fn laid_out(
        lo: f64,
        hi: f64,
        count: usize,
        room: impl Fn(usize) -> usize,
    ) -> Bins<T> {
        let count = count.max(1);
        let scale = if hi > lo && count > 1 {
            count as f64 / (hi - lo)
        } else {
            0.0
        };
        Bins {
            lo,
            scale,
            bins: (0..count).map(|b| Vec::with_capacity(room(b))).collect(),
        }
    }

    /// The bin of `key` (NaN, or an infinite product, goes to the first).
    #[inline(always)]
    pub(super) fn bin_of(&self, key: f64) -> usize {
        // `as usize` saturates: keys below `lo` go to 0, above `hi` past the last.
        (((key - self.lo) * self.scale) as usize).min(self.bins.len() - 1)
    }

    /// Add `item`, whose key is `key`.
    #[inline(always)]
    pub(super) fn push(&mut self, key: f64, item: T) {
        self.push_to(self.bin_of(key), item);
    }

    /// Add `item` to bin `bin`, the [`Bins::bin_of`] its key.
    #[inline(always)]
    pub(super) fn push_to(&mut self, bin: usize, item: T) {
        self.bins[bin].push(item);
    }

    /// The number of items.
    pub(super) fn len(&self) -> usize {
        self.bins.iter().map(Vec::len).sum()
    }

    /// All the items, bin after bin.
    pub(super) fn into_items(self) -> Vec<T> {
        let mut bins = self.bins.into_iter();
        let mut all = bins.next().unwrap_or_default();
        for b in bins {
            all.extend_from_slice(&b);
        }
        all
    }
}

/// What [`sort_bins_then`] returns.
pub(super) struct SortedBins<T> {
    /// The items, sorted: bin after bin.
    pub(super) bins: Vec<Vec<T>>,
    /// What `then` returned for each bin.
    pub(super) tallies: Vec<usize>,
}

/// The items of `parts` (bins of the same layout, one per producer), sorted by `cmp`,
/// where `key` is the key they were binned by and a monotone summary of `cmp`
/// (`key(a) < key(b)` implies `cmp(a, b) == Less`); then `then` on every sorted bin
/// while it is in cache (items with equal keys are in the same bin). The bins are done
/// on the rayon pool, each on its own: it gathers its items from the parts, spreads them
/// over about as many fine buckets by key, and sorts those. O(K) for spread-out keys.
pub(super) fn sort_bins_then<T: Copy + Send + Sync>(
    parts: Vec<Bins<T>>,
    key: impl Fn(&T) -> f64 + Sync,
    cmp: impl Fn(&T, &T) -> Ordering + Copy + Sync,
    then: impl Fn(&mut [T]) -> usize + Sync,
) -> SortedBins<T> {
    let Some(first) = parts.first() else {
        return SortedBins {
            bins: Vec::new(),
            tallies: Vec::new(),
        };
    };
    let (lo, scale, count) = (first.lo, first.scale, first.bins.len());
    debug_assert!(parts
        .iter()
        .all(|p| (p.lo, p.scale, p.bins.len()) == (lo, scale, count)));
    // Bin b's pieces, one per part.
    let mut columns: Vec<Vec<Vec<T>>> = (0..count)
        .map(|_| Vec::with_capacity(parts.len()))
        .collect();
    for part in parts {
        for (column, bin) in columns.iter_mut().zip(part.bins) {
            column.push(bin);
        }
    }
    let mut bins = Vec::with_capacity(count);
    let mut tallies = Vec::with_capacity(count);
    columns
        .into_par_iter()
        .enumerate()
        .with_min_len(8)
        .map_init(
            || (Vec::new(), Vec::new(), Vec::new()),
            |(scratch, fines, local): &mut (Vec<T>, Vec<u32>, Vec<u32>), (b, pieces)| {
                let mut bin = gather(pieces);
                // The bin's own share of the key range, spread over one fine bucket per
                // item (monotone in the key; keys outside go to the ends).
                let bin_lo = if scale > 0.0 {
                    lo + b as f64 / scale
                } else {
                    lo
                };
                let fine_scale = if scale > 0.0 {
                    bin.len() as f64 * scale
                } else {
                    0.0
                };
                sort_bin(
                    &mut bin, &key, cmp, bin_lo, fine_scale, scratch, fines, local,
                );
                let tally = then(&mut bin);
                (bin, tally)
            },
        )
        .unzip_into_vecs(&mut bins, &mut tallies);
    SortedBins { bins, tallies }
}

/// [`sort_bins_then`] on this thread, for a `then` that consumes the sorted items:
/// `then` is called on every bin in order, sorted, while it is in cache. Each bin is
/// spread from its own memory straight into one scratch buffer, sorted there and handed
/// over from there (no copy back into the bin); the bin's memory is freed as it is done.
pub(super) fn each_sorted_bin<T: Copy>(
    parts: Vec<Bins<T>>,
    key: impl Fn(&T) -> f64,
    cmp: impl Fn(&T, &T) -> Ordering + Copy,
    mut then: impl FnMut(&mut [T]),
) {
    let Some(first) = parts.first() else {
        return;
    };
    let (lo, scale, count) = (first.lo, first.scale, first.bins.len());
    debug_assert!(parts
        .iter()
        .all(|p| (p.lo, p.scale, p.bins.len()) == (lo, scale, count)));
    let mut parts: Vec<std::vec::IntoIter<Vec<T>>> =
        parts.into_iter().map(|p| p.bins.into_iter()).collect();
    let (mut scratch, mut fines, mut local) = (Vec::new(), Vec::new(), Vec::new());
    for b in 0..count {
        let bin = gather(parts.iter_mut().filter_map(Iterator::next).collect());
        let n = bin.len();
        if n == 0 {
            continue;
        }
        if scratch.len() < n {
            scratch.resize(n, bin[0]);
        }
        let (bin_lo, fine_scale) = if scale > 0.0 {
            (lo + b as f64 / scale, (FINE * n) as f64 * scale)
        } else {
            (lo, 0.0)
        };
        let to = &mut scratch[..n];
        sort_bin_into(
            &bin, &key, cmp, bin_lo, fine_scale, to, &mut fines, &mut local,
        );
        drop(bin);
        then(to);
    }
}

/// One bin's pieces as one list (the first piece grown to hold the others).
fn gather<T: Copy>(pieces: Vec<Vec<T>>) -> Vec<T> {
    let total: usize = pieces.iter().map(Vec::len).sum();
    let mut pieces = pieces.into_iter();
    let mut bin = pieces.next().unwrap_or_default();
    bin.reserve(total - bin.len());
    for p in pieces {
        bin.extend_from_slice(&p);
    }
    bin
}

/// Sort `bin` by `cmp` in place ([`sort_bin_into`] through `scratch`).
#[allow(clippy::too_many_arguments)]
fn sort_bin<T: Copy>(
    bin: &mut [T],
    key: impl Fn(&T) -> f64,
    cmp: impl Fn(&T, &T) -> Ordering + Copy,
    lo: f64,
    scale: f64,
    scratch: &mut Vec<T>,
    fines: &mut Vec<u32>,
    local: &mut Vec<u32>,
) {
    if bin.len() <= 16 {
        bin.sort_unstable_by(cmp);
        return;
    }
    scratch.clear();
    scratch.extend_from_slice(bin);
    sort_bin_into(scratch, key, cmp, lo, scale, bin, fines, local);
}

/// `bin` sorted by `cmp` into `to` (of the same length): small bins copied and sorted
/// directly; the others spread over [`FINE`] `· bin.len()` fine buckets by `((key - lo) * scale)`
/// (or, with `scale` 0, by the bin's own range of keys), then each sorted
/// ([`spread_and_sort`]).
#[allow(clippy::too_many_arguments)]
fn sort_bin_into<T: Copy>(
    bin: &[T],
    key: impl Fn(&T) -> f64,
    cmp: impl Fn(&T, &T) -> Ordering + Copy,
    lo: f64,
    scale: f64,
    to: &mut [T],
    fines: &mut Vec<u32>,
    local: &mut Vec<u32>,
) {
    let n = bin.len();
    debug_assert_eq!(to.len(), n);
    if n <= 16 {
        to.copy_from_slice(bin);
        to.sort_unstable_by(cmp);
        return;
    }
    let (lo, scale) = if scale > 0.0 {
        (lo, scale)
    } else {
        // One bin over everything: its range from its keys.
        let (a, b) = bin
            .iter()
            .map(&key)
            .filter(|v| v.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            });
        (
            a,
            if b > a {
                (FINE * n) as f64 / (b - a)
            } else {
                0.0
            },
        )
    };
    fines.clear();
    let width = FINE * n;
    // `as usize` saturates (NaN from an infinite product goes to 0): monotone.
    fines.extend(
        bin.iter()
            .map(|t| (((key(t) - lo) * scale) as usize).min(width - 1) as u32),
    );
    spread_and_sort(bin, fines, to, 0, width, cmp, local);
}

/// Fine buckets per item in [`sort_bin_into`]: with one per item (Poisson-distributed
/// loads) a quarter of the items share a fine bucket and the insertion sort moves them;
/// with two, about half as many. Session 26, long random 1e3, one thread, driver best
/// of 20, three alternated rounds: `find` 8.4–8.7 ms → 8.2–8.4 ms (four per item: no
/// better than two).
const FINE: usize = 2;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binned_items_sort_like_a_plain_sort() {
        let mut next = crate::testing::bits(7u64);
        for n in [0, 1, 17, 1000, 40_000, 300_000] {
            for kind in 0..4 {
                let v: Vec<(f64, u64)> = (0..n)
                    .map(|k| {
                        let r = next();
                        let key = match kind {
                            0 => r as f64 / (1u64 << 53) as f64,
                            1 => (r % 7) as f64,
                            // Keys outside the layout's range, at both ends.
                            2 if k % 10 == 0 => -5.0,
                            2 if k % 10 == 1 => f64::INFINITY,
                            2 => (r as f64 / (1u64 << 53) as f64).powi(3),
                            _ => 0.5,
                        };
                        (key, r % 100)
                    })
                    .collect();
                let cmp = |a: &(f64, u64), b: &(f64, u64)| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1));
                let mut want = v.clone();
                want.sort_unstable_by(cmp);
                for parts in [1, 3] {
                    let count = Bins::<(f64, u64)>::count_for(n);
                    let mut bins: Vec<Bins<(f64, u64)>> = (0..parts)
                        .map(|_| Bins::laid_out(0.0, 1.0, count, |_| 4))
                        .collect();
                    for (k, t) in v.iter().enumerate() {
                        bins[(k * k) % parts].push(t.0, *t);
                    }
                    assert_eq!(bins.iter().map(Bins::len).sum::<usize>(), n);
                    let bins_again = bins.clone();
                    let sorted = sort_bins_then(bins, |t| t.0, cmp, |b| b.len());
                    assert_eq!(sorted.tallies.iter().sum::<usize>(), n);
                    let got: Vec<(f64, u64)> = sorted.bins.concat();
                    assert_eq!(got.len(), n);
                    // The same from the serial pass, bin after bin.
                    let mut serial = Vec::new();
                    each_sorted_bin(bins_again, |t| t.0, cmp, |b| serial.extend_from_slice(b));
                    assert_eq!(serial, got, "n {n} kind {kind} parts {parts}");
                    assert!(
                        got.iter()
                            .zip(&want)
                            .all(|(a, b)| cmp(a, b) == Ordering::Equal),
                        "n {n} kind {kind} parts {parts}"
                    );
                }
                // One bin: its range comes from its keys.
                let mut one = Bins::single(0);
                v.iter().for_each(|t| one.push(t.0, *t));
                let mut serial = Vec::new();
                each_sorted_bin(
                    vec![one.clone()],
                    |t| t.0,
                    cmp,
                    |b| serial.extend_from_slice(b),
                );
                let got = sort_bins_then(vec![one], |t| t.0, cmp, |_| 0).bins.concat();
                assert_eq!(serial, got);
                assert!(got
                    .iter()
                    .zip(&want)
                    .all(|(a, b)| cmp(a, b) == Ordering::Equal));
            }
        }
    }
}
