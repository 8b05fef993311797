//! Benchmarks against peer libraries.
fn main() {}
