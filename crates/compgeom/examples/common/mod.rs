//! Shared by the profiling examples: a seeded generator, so every run profiles the same input.

/// SplitMix64 (fixed seed given by the caller): small, fast, reproducible.
pub struct Rng(pub u64);

impl Rng {
    /// A uniform f64 in [0, 1) (a multiple of 2^-53).
    pub fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}
