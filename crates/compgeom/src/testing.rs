//! Deterministic random numbers for the unit tests: a 64-bit linear congruential
//! generator (Knuth's MMIX constants), the same numbers on every machine and no
//! dependency. Each function returns a generator seeded with `seed`.

/// The generator's next state.
fn step(state: &mut u64) -> u64 {
    *state = state
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    *state
}

/// Uniform `f64` numbers in `[0, 1)` (the top 53 bits of each state).
pub(crate) fn units(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed;
    move || (step(&mut state) >> 11) as f64 / (1u64 << 53) as f64
}

/// The top 53 bits of each state.
pub(crate) fn bits(seed: u64) -> impl FnMut() -> u64 {
    let mut state = seed;
    move || step(&mut state) >> 11
}

/// Numbers below `n` (the top 31 bits of each state modulo `n`).
pub(crate) fn below(seed: u64) -> impl FnMut(u64) -> u64 {
    let mut state = seed;
    move |n| (step(&mut state) >> 33) % n
}
