//! `compgeom interpolate`: heights of the piecewise-linear terrain over the Delaunay
//! triangulation of (x, y, z) samples (book §9.1), via `compgeom::delaunay::Terrain`.

use crate::cli::{InputArgs, OutputArgs};
use crate::error::CliError;
use crate::output;
use clap::Args;
use compgeom::delaunay::{verify_delaunay, Terrain};
use serde::Serialize;
use std::path::PathBuf;

/// `--help` text describing the JSON output.
pub const JSON_HELP: &str = "\
JSON output is one object:
  heights   [z or null, ...]  one per query point, in input order: the height of the
                              piecewise-linear terrain over the Delaunay triangulation of the
                              samples' (x, y); null outside the samples' convex hull
  samples   number of samples read (equal (x, y) merged: the first one's z is used)
  verified  true; present only with --verify (the triangulation was checked exactly)

SAMPLES are x,y,z lines (or OFF); --at POINTS are x,y lines, WKT or GeoJSON.

Example:
  compgeom interpolate samples.csv --at queries.csv";

/// Arguments of `compgeom interpolate`.
#[derive(Debug, Clone, Args)]
pub struct InterpolateArgs {
    /// The samples (x, y, z) and their format.
    #[command(flatten)]
    pub input: InputArgs,

    /// Output and verification (only JSON output; --svg is not drawn for this command).
    #[command(flatten)]
    pub output: OutputArgs,

    /// The query points.
    #[arg(long, value_name = "POINTS")]
    pub at: PathBuf,
}

#[derive(Debug, Serialize)]
struct HeightsJson {
    heights: Vec<Option<f64>>,
    samples: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    verified: Option<bool>,
}

/// Run `compgeom interpolate`.
pub fn run(args: &InterpolateArgs) -> Result<(), CliError> {
    let src = args.input.read()?;
    let samples = compgeom::io::read_points3(&src.text, src.format, &src.name)?;
    let queries = InputArgs {
        input: args.at.clone(),
        input_format: None,
    }
    .read_points()?;
    let terrain = Terrain::new(&samples)?;
    if args.output.verify {
        verify_delaunay(terrain.triangulation())?;
    }
    let json = HeightsJson {
        heights: terrain.heights(&queries),
        samples: samples.len(),
        verified: args.output.verify.then_some(true),
    };
    let text = serde_json::to_string(&json)
        .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?;
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}
