//! `compgeom enclose`: the smallest disc enclosing points in the plane (book §4.7), via
//! `compgeom::lp::smallest_enclosing_disc`.

use crate::cli::{InputArgs, OutputArgs};
use crate::error::CliError;
use crate::output;
use clap::Args;
use compgeom::io::{write_shape, Shape};
use compgeom::lp::{smallest_enclosing_disc, verify_enclosing_disc, Disc};
use compgeom::render::{Layer, Picture, Style};
use compgeom::Point2;
use serde::Serialize;

/// `--help` text describing the JSON output.
pub const JSON_HELP: &str = "\
JSON output (--format json, the default) is one object:
  center         [x, y]          centre of the smallest enclosing disc (nearest f64)
  radius         r               its radius (within one ulp)
  support        [[x, y], ...]   the 1-3 input points on the circle that define the disc
  input_points   number of points read
  verified       true; present only with --verify (a failed check exits 1 instead)

Other formats print the support points.

Examples:
  compgeom enclose points.csv
  compgeom enclose points.csv --svg disc.svg --verify";

/// Arguments of `compgeom enclose`.
#[derive(Debug, Clone, Args)]
pub struct EncloseArgs {
    /// Input and its format.
    #[command(flatten)]
    pub input: InputArgs,

    /// Output, picture and verification.
    #[command(flatten)]
    pub output: OutputArgs,

    /// Seed of the random insertion order (the disc does not depend on it).
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
}

#[derive(Debug, Serialize)]
struct DiscJson {
    center: [f64; 2],
    radius: f64,
    support: Vec<[f64; 2]>,
    input_points: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    verified: Option<bool>,
}

/// Run `compgeom enclose`.
pub fn run(args: &EncloseArgs) -> Result<(), CliError> {
    let src = args.input.read()?;
    let points = compgeom::io::read_points(&src.text, src.format, &src.name)?;
    if points.is_empty() {
        // Say which input was empty (the library cannot know the file).
        return Err(CliError::bad_input(format!(
            "{}: no points: the smallest enclosing disc of no points is undefined",
            src.name
        )));
    }
    let disc = smallest_enclosing_disc(&points, args.seed)?;
    if args.output.verify {
        verify_enclosing_disc(&points, &disc)?;
    }
    let text = match args.output.format().geometry_format() {
        None => serde_json::to_string(&DiscJson {
            center: [disc.center.x, disc.center.y],
            radius: disc.radius,
            support: disc.support.iter().map(|p| [p.x, p.y]).collect(),
            input_points: points.len(),
            verified: args.output.verify.then_some(true),
        })
        .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?,
        Some(format) => write_shape(&Shape::MultiPoint(disc.support.clone()), format)?,
    };
    if let Some(svg) = &args.output.svg {
        let title = format!(
            "smallest enclosing disc: n = {}, radius {}",
            points.len(),
            compgeom::io::format_f64(disc.radius)
        );
        let picture = disc_picture(&points, &disc, &title);
        output::write_atomic(svg, picture.to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

/// The points, the circle (a 256-gon), its centre and the support points.
pub fn disc_picture(points: &[Point2], disc: &Disc, title: &str) -> Picture {
    let mut pic = Picture::new(800, 640).with_title(title);
    let circle: Vec<Point2> = (0..256)
        .map(|k| {
            let t = k as f64 * std::f64::consts::TAU / 256.0;
            Point2::new(
                disc.center.x + disc.radius * t.cos(),
                disc.center.y + disc.radius * t.sin(),
            )
        })
        .collect();
    pic.add(
        Layer::new(
            "smallest enclosing disc",
            Style::area("#1f77b4").with_fill_opacity(0.12),
        )
        .ring(&circle),
    );
    let radius = if points.len() > 10_000 { 1.0 } else { 2.0 };
    pic.add(
        Layer::new(
            format!("input points ({})", points.len()),
            Style::points("#8c8c8c").with_radius(radius),
        )
        .points(points),
    );
    pic.add(Layer::new("centre", Style::points("#2ca02c").with_radius(3.0)).point(disc.center));
    pic.add(
        Layer::new("support points", Style::points("#d62728").with_radius(4.5))
            .points(&disc.support),
    );
    pic
}
