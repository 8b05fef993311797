//! Shared helpers: a seeded generator and a best-of-k timer.

use std::time::{Duration, Instant};

/// SplitMix64: a small, seeded, reproducible generator (no extra crate needed).
pub struct Rng(u64);

impl Rng {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Self {
        Rng(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The best wall time of `runs` calls of `f` (each result is dropped outside the clock).
pub fn best_of<T>(runs: usize, mut f: impl FnMut() -> T) -> Duration {
    let mut best = Duration::MAX;
    for _ in 0..runs.max(1) {
        let start = Instant::now();
        let out = f();
        let t = start.elapsed();
        drop(std::hint::black_box(out));
        best = best.min(t);
    }
    best
}

/// Times each closure once per round, in turn, for `runs` rounds: `times[round][k]` is
/// closure `k`'s time in that round. Alternating keeps a changing machine load (other jobs)
/// from favouring whichever library happened to run in a quiet moment.
pub fn alternate(runs: usize, fs: &mut [&mut dyn FnMut()]) -> Vec<Vec<Duration>> {
    (0..runs.max(1))
        .map(|_| {
            fs.iter_mut()
                .map(|f| {
                    let start = Instant::now();
                    f();
                    start.elapsed()
                })
                .collect()
        })
        .collect()
}

/// The median of some values (the mean of the middle two for an even count).
pub fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    match n {
        0 => f64::NAN,
        _ if n % 2 == 1 => v[n / 2],
        _ => (v[n / 2 - 1] + v[n / 2]) / 2.0,
    }
}

/// Milliseconds, for tables.
pub fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}
