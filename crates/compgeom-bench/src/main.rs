//! Benchmarks of compgeom against the peer libraries users would pick instead, on the same
//! generated input in the same run. Answers are checked once, outside the clock.
//!
//! ```text
//! cargo run --release -p compgeom-bench -- <group> [--quick]
//! groups: see GROUPS below, or all
//! ```

mod boolean;
mod delaunay;
mod hull;
mod intersect;
mod kernel;
mod locate;
mod lp;
mod range;
mod real_maps;
mod triangulate;
mod util;
mod voronoi;

use std::process::ExitCode;

/// Every group, in the order `all` runs them.
const GROUPS: &[&str] = &[
    "kernel",
    "hull",
    "intersect",
    "boolean",
    "triangulate",
    "lp",
    "range",
    "locate",
    "voronoi",
    "delaunay",
];

/// Run one group; `None` if the name is unknown.
fn run_group(name: &str, quick: bool) -> Option<Result<(), String>> {
    match name {
        "hull" => Some(hull::run(quick)),
        "intersect" => Some(intersect::run(quick)),
        "range" => Some(range::run(quick)),
        "locate" => Some(locate::run(quick)),
        "lp" => Some(lp::run(quick)),
        "delaunay" => Some(delaunay::run(quick)),
        "voronoi" => Some(voronoi::run(quick)),
        "boolean" => Some(boolean::run(quick)),
        "triangulate" => Some(triangulate::run(quick)),
        "kernel" => {
            kernel::run();
            Some(Ok(()))
        }
        _ => None,
    }
}

fn usage() -> ExitCode {
    eprintln!("usage: compgeom-bench <{}|all> [--quick]", GROUPS.join("|"));
    ExitCode::from(2)
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let quick = args.iter().any(|a| a == "--quick");
    let Some(group) = args.iter().find(|a| !a.starts_with("--")) else {
        return usage();
    };
    let groups: Vec<&str> = if group == "all" {
        GROUPS.to_vec()
    } else {
        vec![group.as_str()]
    };
    for name in groups {
        match run_group(name, quick) {
            None => return usage(),
            Some(Ok(())) => {}
            Some(Err(e)) => {
                eprintln!("error: {name}: {e}");
                return ExitCode::FAILURE;
            }
        }
    }
    ExitCode::SUCCESS
}
