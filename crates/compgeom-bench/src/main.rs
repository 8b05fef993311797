//! Benchmarks against peer libraries.
//!
//! Usage: `compgeom-bench <group>`; groups: `kernel`.
mod intersect;
mod kernel;

fn main() {
    match std::env::args().nth(1).as_deref() {
        Some("kernel") => kernel::run(),
        Some("intersect") => intersect::run(),
        other => {
            eprintln!("unknown or missing bench group {other:?}; groups: kernel");
            std::process::exit(2);
        }
    }
}
