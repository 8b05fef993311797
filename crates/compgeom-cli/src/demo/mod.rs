//! `compgeom demo --out DIR`: runs each command on built-in samples, writes one SVG per run
//! and `DIR/index.html`, a gallery with the pictures and their figures (sizes, times).
//!
//! Each chapter's section lives in its own file (`hull.rs`, …) as
//! `pub fn section(demo: &Demo) -> Result<Section, CliError>` and is listed in [`SECTIONS`].
//! A section computes with the library, verifies its results (a failure exits 1), draws with
//! `compgeom::render`, and saves each picture with [`Demo::figure`].

mod delaunay;
mod hull;
mod intersect;
mod locate;
mod lp;
mod overlay;
mod range;
pub mod samples;
mod triangulate;
mod voronoi;

use crate::error::CliError;
use crate::output;
use clap::Args;
use compgeom::render::{Figure, FigureImage, Gallery, Picture, Section};
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// Arguments of `compgeom demo`.
#[derive(Debug, Clone, Args)]
pub struct DemoArgs {
    /// Directory for the SVGs and index.html (created if missing; files in it are replaced).
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
}

/// A function that builds one section of the gallery.
type SectionFn = fn(&Demo) -> Result<Section, CliError>;

/// The sections of the gallery, in book order. A new command appends its own.
const SECTIONS: &[SectionFn] = &[
    hull::section,
    intersect::section,
    overlay::section,
    triangulate::section,
    lp::section,
    range::section,
    locate::section,
    voronoi::section,
    delaunay::section,
];

/// What a section needs: where to put its pictures.
pub struct Demo {
    out: PathBuf,
}

impl Demo {
    /// Save `picture` as `DIR/file` (atomically) and return a figure linking to it.
    pub fn figure(&self, file: &str, caption: &str, picture: &Picture) -> Result<Figure, CliError> {
        output::write_atomic(&self.out.join(file), picture.to_svg_string().as_bytes())?;
        Ok(Figure::new(caption, FigureImage::Linked(file.to_string())))
    }
}

/// Run `compgeom demo`.
pub fn run(args: &DemoArgs) -> Result<(), CliError> {
    std::fs::create_dir_all(&args.out).map_err(|e| {
        CliError::failure(format!(
            "cannot create directory {}: {e}",
            args.out.display()
        ))
    })?;
    let demo = Demo {
        out: args.out.clone(),
    };
    let mut gallery = Gallery::new("compgeom demo").with_intro(
        "Every command of compgeom run on built-in sample inputs (the same on every run). \
         Each result was checked by the library's exact verifier before it was drawn. \
         Times are wall-clock times of the library call alone, on this machine, in this build.",
    );
    for section in SECTIONS {
        gallery.push(section(&demo)?);
    }
    let index = args.out.join("index.html");
    output::write_atomic(&index, gallery.to_html_string().as_bytes())?;
    output::write_stdout(&format!("{}\n", index.display()))
}

/// Run `f`, returning its result and how long it took.
pub fn timed<T>(f: impl FnOnce() -> T) -> (T, Duration) {
    let start = Instant::now();
    let r = f();
    (r, start.elapsed())
}

/// A duration for people: `850 ns`, `12.3 µs`, `4.56 ms`, `1.23 s`.
pub fn format_duration(d: Duration) -> String {
    let ns = d.as_nanos() as f64;
    if ns < 1e3 {
        format!("{ns:.0} ns")
    } else if ns < 1e6 {
        format!("{:.1} µs", ns / 1e3)
    } else if ns < 1e9 {
        format!("{:.2} ms", ns / 1e6)
    } else {
        format!("{:.2} s", ns / 1e9)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn durations_read_well() {
        assert_eq!(format_duration(Duration::from_nanos(850)), "850 ns");
        assert_eq!(format_duration(Duration::from_nanos(12_345)), "12.3 µs");
        assert_eq!(format_duration(Duration::from_micros(4_560)), "4.56 ms");
        assert_eq!(format_duration(Duration::from_millis(1_234)), "1.23 s");
    }
}
