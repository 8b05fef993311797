//! Built-in sample inputs, the same on every run: a small seeded generator (SplitMix64)
//! instead of a random-number crate, so the gallery is reproducible.

use compgeom::Point2;

/// SplitMix64: tiny, fast, and good enough to scatter sample points.
pub struct Rng(u64);

impl Rng {
    /// A generator with a fixed seed.
    pub fn new(seed: u64) -> Rng {
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

    /// Uniform in [0, 1), on a grid of 2⁻⁵³.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
}

/// `n` points uniform in the disc of radius `r` about the origin.
pub fn disc(n: usize, r: f64, seed: u64) -> Vec<Point2> {
    let mut rng = Rng::new(seed);
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let (x, y) = (rng.range(-r, r), rng.range(-r, r));
        if x * x + y * y <= r * r {
            out.push(Point2::new(x, y));
        }
    }
    out
}

/// The integer grid `0..k × 0..k` (so every side of the hull has k collinear points) plus a
/// duplicate of every fifth point, shuffled: the degenerate case in miniature.
pub fn grid_with_duplicates(k: u32, seed: u64) -> Vec<Point2> {
    let mut out: Vec<Point2> = (0..k)
        .flat_map(|i| (0..k).map(move |j| Point2::new(f64::from(i), f64::from(j))))
        .collect();
    let dups: Vec<Point2> = out.iter().step_by(5).copied().collect();
    out.extend(dups);
    shuffle(&mut out, seed);
    out
}

/// `n` points on the circle of radius `r` (rounded to f64, so in convex position but only
/// approximately cocircular), shuffled.
pub fn circle(n: usize, r: f64, seed: u64) -> Vec<Point2> {
    let mut out: Vec<Point2> = (0..n)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / n as f64;
            Point2::new(r * t.cos(), r * t.sin())
        })
        .collect();
    shuffle(&mut out, seed);
    out
}

/// Fisher–Yates shuffle with a seeded generator.
pub fn shuffle<T>(v: &mut [T], seed: u64) {
    let mut rng = Rng::new(seed);
    for i in (1..v.len()).rev() {
        let j = (rng.next_u64() % (i as u64 + 1)) as usize;
        v.swap(i, j);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn samples_are_deterministic_and_in_range() {
        assert_eq!(disc(50, 10.0, 7), disc(50, 10.0, 7));
        assert_ne!(disc(50, 10.0, 7), disc(50, 10.0, 8));
        assert!(disc(500, 10.0, 1)
            .iter()
            .all(|p| p.x * p.x + p.y * p.y <= 100.0));
        let g = grid_with_duplicates(5, 3);
        assert_eq!(g.len(), 25 + 5);
        assert!(g
            .iter()
            .all(|p| (0.0..5.0).contains(&p.x) && (0.0..5.0).contains(&p.y)));
        let c = circle(16, 2.0, 1);
        assert_eq!(c.len(), 16);
        assert!(c
            .iter()
            .all(|p| ((p.x * p.x + p.y * p.y).sqrt() - 2.0).abs() < 1e-12));
        let mut rng = Rng::new(0);
        assert!((0..1000)
            .map(|_| rng.unit())
            .all(|u| (0.0..1.0).contains(&u)));
    }
}
