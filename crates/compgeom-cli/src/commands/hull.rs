//! `compgeom hull`: the convex hull of points in the plane (book chapter 1), via
//! `compgeom::hull::convex_hull`.

use crate::cli::{InputArgs, OutputArgs};
use crate::error::CliError;
use crate::output;
use crate::progress::{Spinner, LARGE_INPUT};
use clap::{Args, ValueEnum};
use compgeom::hull::{convex_hull, verify_convex_hull, HullAlgorithm, HullOptions};
use compgeom::io::{write_shape, Shape};
use compgeom::render::{Layer, Picture, Style};
use compgeom::{Point2, Polygon};
use serde::Serialize;

/// `--help` text describing the JSON output.
pub const JSON_HELP: &str = "\
JSON output (--format json, the default) is one object:
  hull            [[x, y], ...]  hull vertices, clockwise from the lexicographically smallest
                                 (smallest x, then smallest y); coordinates are the input's
                                 exact values, printed so they parse back to the same f64
  algorithm       \"default\" | \"andrew\" | \"slow\"
  input_points    number of points read (duplicates included)
  keep_collinear  whether points on hull edges were kept as vertices
  verified        true; present only with --verify (a failed check exits 1 instead)

Other formats print only the hull geometry: nothing (no points), a point (all points equal),
a two-point line string (all points collinear), or a polygon.

Examples:
  compgeom hull points.csv
  compgeom hull points.wkt --format geojson -o hull.geojson --svg hull.svg --verify
  cat points.csv | compgeom hull - --algorithm andrew --keep-collinear";

/// Hull vertex labels are drawn up to this many vertices; beyond, they would be unreadable.
const MAX_LABELS: usize = 1000;

/// Arguments of `compgeom hull`.
#[derive(Debug, Clone, Args)]
pub struct HullArgs {
    /// Input and its format.
    #[command(flatten)]
    pub input: InputArgs,

    /// Output, picture and verification.
    #[command(flatten)]
    pub output: OutputArgs,

    /// Algorithm: `default` (fastest exact), `andrew` (the book's CONVEXHULL, monotone
    /// chain, O(n log n)) or `slow` (the book's SLOWCONVEXHULL, O(n³): small inputs only).
    #[arg(long, value_enum, default_value_t = AlgorithmArg::Default)]
    pub algorithm: AlgorithmArg,

    /// Keep input points that lie on hull edges as hull vertices.
    #[arg(long)]
    pub keep_collinear: bool,
}

/// The `--algorithm` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum AlgorithmArg {
    /// The fastest exact method.
    Default,
    /// Andrew's monotone chain, the book's CONVEXHULL.
    Andrew,
    /// The book's SLOWCONVEXHULL, O(n³).
    Slow,
}

impl AlgorithmArg {
    /// The name printed in JSON output and titles.
    pub fn name(self) -> &'static str {
        match self {
            AlgorithmArg::Default => "default",
            AlgorithmArg::Andrew => "andrew",
            AlgorithmArg::Slow => "slow",
        }
    }

    /// The library's algorithm.
    pub fn algorithm(self) -> HullAlgorithm {
        match self {
            AlgorithmArg::Default => HullAlgorithm::Default,
            AlgorithmArg::Andrew => HullAlgorithm::Andrew,
            AlgorithmArg::Slow => HullAlgorithm::Slow,
        }
    }
}

/// Library options for `algorithm` and `keep_collinear`.
pub fn hull_options(algorithm: AlgorithmArg, keep_collinear: bool) -> HullOptions {
    // `HullOptions` is non-exhaustive: start from the default and set the fields.
    let mut options = HullOptions::default();
    options.algorithm = algorithm.algorithm();
    options.keep_collinear = keep_collinear;
    options
}

/// The JSON result object (fields documented in [`JSON_HELP`]).
#[derive(Debug, Serialize)]
struct HullJson {
    hull: Vec<[f64; 2]>,
    algorithm: &'static str,
    input_points: usize,
    keep_collinear: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    verified: Option<bool>,
}

/// Run `compgeom hull`.
pub fn run(args: &HullArgs) -> Result<(), CliError> {
    let points = {
        let _spin = Spinner::start("reading points", is_large_file(&args.input));
        args.input.read_points()?
    };
    let options = hull_options(args.algorithm, args.keep_collinear);
    let hull = {
        let _spin = Spinner::start("computing the hull", points.len() >= LARGE_INPUT);
        convex_hull(&points, &options)?
    };
    if args.output.verify {
        let _spin = Spinner::start("verifying", points.len() >= LARGE_INPUT);
        verify_convex_hull(&points, &hull, args.keep_collinear)?;
    }

    // Everything is computed and checked before anything is written.
    let text = match args.output.format().geometry_format() {
        None => {
            let json = HullJson {
                hull: hull.iter().map(|p| [p.x, p.y]).collect(),
                algorithm: args.algorithm.name(),
                input_points: points.len(),
                keep_collinear: args.keep_collinear,
                verified: args.output.verify.then_some(true),
            };
            serde_json::to_string(&json)
                .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?
        }
        Some(format) => write_shape(&hull_shape(&hull), format)?,
    };
    if let Some(svg) = &args.output.svg {
        let title = hull_title(args.algorithm, points.len(), hull.len());
        let picture = hull_picture(&points, &hull, &title);
        output::write_atomic(svg, picture.to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

/// True when the input is a file big enough that reading it takes a while.
fn is_large_file(input: &InputArgs) -> bool {
    std::fs::metadata(&input.input).is_ok_and(|m| m.len() > 32 << 20)
}

/// The hull as an output geometry: empty, a point, a segment, or a polygon.
pub fn hull_shape(hull: &[Point2]) -> Shape {
    match hull {
        [] => Shape::Empty,
        [p] => Shape::Point(*p),
        [_, _] => Shape::LineString(hull.to_vec()),
        _ => Shape::Polygon(Polygon::new(hull.to_vec(), Vec::new())),
    }
}

/// The picture title: algorithm, n and h.
pub fn hull_title(algorithm: AlgorithmArg, n: usize, h: usize) -> String {
    format!("convex hull ({}): n = {n}, h = {h}", algorithm.name())
}

/// The input points, the hull polygon, and the hull vertices numbered in output order.
pub fn hull_picture(points: &[Point2], hull: &[Point2], title: &str) -> Picture {
    let mut pic = Picture::new(800, 640).with_title(title);
    let radius = if points.len() > 10_000 { 1.0 } else { 2.0 };
    pic.add(
        Layer::new(
            format!("input points ({})", points.len()),
            Style::points("#8c8c8c").with_radius(radius),
        )
        .points(points),
    );
    if hull.len() >= 2 {
        pic.add(
            Layer::new(
                "convex hull",
                Style::area("#1f77b4").with_fill_opacity(0.15),
            )
            .ring(hull),
        );
    }
    let vertices = Layer::new(
        if hull.len() <= MAX_LABELS {
            "hull vertices, numbered in output order".to_string()
        } else {
            format!("hull vertices (labels omitted: more than {MAX_LABELS})")
        },
        Style::points("#d62728").with_radius(3.5),
    );
    pic.add(if hull.len() <= MAX_LABELS {
        vertices.numbered_points(hull)
    } else {
        vertices.points(hull)
    });
    pic
}
