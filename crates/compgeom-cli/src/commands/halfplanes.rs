//! `compgeom halfplanes`: the intersection of half-planes `a·x + b·y <= c` (book §4.2), via
//! `compgeom::lp::intersect_halfplanes`. Also home of the small helpers the chapter 4
//! commands share (reading constraint text, drawing constraint lines).

use crate::cli::OutputArgs;
use crate::error::CliError;
use crate::output;
use clap::{Args, ValueEnum};
use compgeom::io::{write_shape, Shape};
use compgeom::lp::{
    intersect_halfplanes, intersect_halfplanes_dc, intersect_halfplanes_incremental,
    read_halfplanes, verify_region, HalfPlane, Region, RegionKind,
};
use compgeom::render::{Layer, Picture, Style};
use compgeom::{Point2, Polygon, Segment2};
use serde::Serialize;
use std::io::Read as _;
use std::path::{Path, PathBuf};

/// `--help` text describing the input and the JSON output.
pub const JSON_HELP: &str = "\
Input: one half-plane per line, `a b c` (or `a,b,c`) meaning a·x + b·y <= c; `#` comments.

JSON output (--format json, the default) is one object:
  kind         \"polygon\" | \"unbounded\" | \"segment\" | \"ray\" | \"line\" | \"point\" | \"empty\"
  vertices     [[x, y], ...]  finite corners counter-clockwise (nearest f64 of the exact
                              corner); a polygon starts at its lexicographically smallest corner,
                              an unbounded boundary where it comes in from infinity
  constraints  [i, ...]       0-based indices of the half-planes carrying the boundary, in
                              boundary order (for a polygon, constraint k runs from vertex k
                              to vertex k+1)
  input_constraints           number of half-planes read
  verified     true; present only with --verify (a failed check exits 1 instead)

Other formats print the region's geometry: a polygon, a segment (line string), a point or
nothing; unbounded regions, rays and lines have no such form (use JSON).

Examples:
  compgeom halfplanes constraints.txt
  compgeom halfplanes constraints.txt --svg region.svg
  compgeom halfplanes constraints.txt --algorithm dc
  compgeom halfplanes constraints.txt --incremental --seed 7";

/// Arguments of `compgeom halfplanes`.
#[derive(Debug, Clone, Args)]
pub struct HalfplanesArgs {
    /// Input file (lines `a b c`), or `-` for standard input.
    #[arg(value_name = "INPUT")]
    pub input: PathBuf,

    /// Output, picture and verification.
    #[command(flatten)]
    pub output: OutputArgs,

    /// Seed of the random insertion order of --incremental (the result does not depend on it).
    #[arg(long, default_value_t = 0)]
    pub seed: u64,

    /// Use randomized incremental clipping (expected O(n·h)); the same as
    /// `--algorithm incremental`.
    #[arg(long)]
    pub incremental: bool,

    /// Which exact method computes the region (all give the same answer).
    #[arg(long, value_enum, default_value_t = AlgorithmArg::Scan)]
    pub algorithm: AlgorithmArg,
}

/// The `--algorithm` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum AlgorithmArg {
    /// One exact slope sort and one linear sweep, pruned by a sample's region (the
    /// fastest; O(n log n)).
    Scan,
    /// The book's divide and conquer, INTERSECTHALFPLANES (§4.2; O(n log n)).
    Dc,
    /// Randomized incremental clipping (expected O(n·h), O(n²) worst case).
    Incremental,
}

/// The JSON result object (fields in [`JSON_HELP`]).
#[derive(Debug, Serialize)]
struct RegionJson {
    kind: &'static str,
    vertices: Vec<[f64; 2]>,
    constraints: Vec<usize>,
    input_constraints: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    verified: Option<bool>,
}

/// Read the whole input (a file or `-`) as text; returns the text and its name for errors.
pub fn read_source(path: &Path) -> Result<(String, String), CliError> {
    if path.as_os_str() == "-" {
        let mut buf = Vec::new();
        std::io::stdin()
            .lock()
            .read_to_end(&mut buf)
            .map_err(|e| CliError::bad_input(format!("cannot read standard input: {e}")))?;
        let text = String::from_utf8(buf)
            .map_err(|e| CliError::bad_input(format!("standard input is not UTF-8 text: {e}")))?;
        return Ok((text, "<stdin>".into()));
    }
    let name = path.display().to_string();
    let bytes =
        std::fs::read(path).map_err(|e| CliError::bad_input(format!("cannot read {name}: {e}")))?;
    let text = String::from_utf8(bytes)
        .map_err(|e| CliError::bad_input(format!("{name} is not UTF-8 text: {e}")))?;
    Ok((text, name))
}

/// Run `compgeom halfplanes`.
pub fn run(args: &HalfplanesArgs) -> Result<(), CliError> {
    let (text, name) = read_source(&args.input)?;
    let hs = read_halfplanes(&text, &name)?;
    let algorithm = if args.incremental {
        AlgorithmArg::Incremental
    } else {
        args.algorithm
    };
    let region = match algorithm {
        AlgorithmArg::Scan => intersect_halfplanes(&hs, args.seed)?,
        AlgorithmArg::Dc => intersect_halfplanes_dc(&hs)?,
        AlgorithmArg::Incremental => intersect_halfplanes_incremental(&hs, args.seed)?,
    };
    if args.output.verify {
        verify_region(&hs, &region)?;
    }
    let text = match args.output.format().geometry_format() {
        None => serde_json::to_string(&RegionJson {
            kind: region.kind.name(),
            vertices: region.vertices.iter().map(|p| [p.x, p.y]).collect(),
            constraints: region.constraints.clone(),
            input_constraints: hs.len(),
            verified: args.output.verify.then_some(true),
        })
        .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?,
        Some(format) => {
            let shape = match region.kind {
                RegionKind::Empty => Shape::Empty,
                RegionKind::Point => Shape::Point(region.vertices[0]),
                RegionKind::Segment => Shape::LineString(region.vertices.clone()),
                RegionKind::Polygon => {
                    Shape::Polygon(Polygon::new(region.vertices.clone(), Vec::new()))
                }
                k => {
                    let what = match k {
                        RegionKind::Ray => "a ray",
                        RegionKind::Line => "a line",
                        _ => "an unbounded region",
                    };
                    return Err(CliError::bad_input(format!(
                        "the intersection is {what} (unbounded): it has no {} form; use --format json",
                        format.name()
                    )));
                }
            };
            write_shape(&shape, format)?
        }
    };
    if let Some(svg) = &args.output.svg {
        let corners = match region.vertices.len() {
            1 => "1 corner".to_string(),
            k => format!("{k} corners"),
        };
        let title = format!(
            "half-plane intersection: n = {}, {} with {corners}",
            hs.len(),
            region.kind.name(),
        );
        let picture = region_picture(&hs, &region, &[], &title);
        output::write_atomic(svg, picture.to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

/// Half the side of the square the pictures show: twice the extent of the interesting points.
pub fn view_radius(points: &[Point2]) -> f64 {
    let m = points
        .iter()
        .flat_map(|p| [p.x.abs(), p.y.abs()])
        .filter(|v| v.is_finite())
        .fold(0.0f64, f64::max);
    if m > 0.0 {
        2.0 * m
    } else {
        10.0
    }
}

/// The boundary line of `h` as a segment across the square of half-side `r`.
pub fn line_segment(h: &HalfPlane, r: f64) -> Option<Segment2> {
    let nn = h.a * h.a + h.b * h.b;
    if nn == 0.0 || !nn.is_finite() {
        return None;
    }
    let (px, py) = (h.c * h.a / nn, h.c * h.b / nn);
    let len = nn.sqrt();
    let (dx, dy) = (-h.b / len * 1.5 * r, h.a / len * 1.5 * r);
    Some(Segment2::new(
        Point2::new(px - dx, py - dy),
        Point2::new(px + dx, py + dy),
    ))
}

/// The constraint lines (up to 300), the region (clipped to the view), its corners, and
/// `extra` points of interest that also set the view.
pub fn region_picture(hs: &[HalfPlane], region: &Region, extra: &[Point2], title: &str) -> Picture {
    let mut pic = Picture::new(800, 640).with_title(title);
    let mut interesting = region.vertices.clone();
    interesting.extend_from_slice(extra);
    let r = view_radius(&interesting);
    if hs.len() <= 300 {
        let lines: Vec<Segment2> = hs.iter().filter_map(|h| line_segment(h, r)).collect();
        pic.add(
            Layer::new(
                format!("constraint lines ({})", hs.len()),
                Style::lines("#b0b0b0").with_stroke_width(0.8),
            )
            .segments(&lines),
        );
    }
    let outline = region.clipped(r);
    let layer = Layer::new(
        format!("feasible region ({})", region.kind.name()),
        Style::area("#2ca02c").with_fill_opacity(0.25),
    );
    match outline.len() {
        0 => {}
        1 => {}
        2 => {
            pic.add(layer.polyline(&outline));
        }
        _ => {
            pic.add(layer.ring(&outline));
        }
    }
    if !region.vertices.is_empty() {
        pic.add(
            Layer::new("corners", Style::points("#1f77b4").with_radius(3.0))
                .points(&region.vertices),
        );
    }
    pic
}
