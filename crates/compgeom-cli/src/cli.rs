//! The command line: a clap-derive [`Command`] enum with one args struct per subcommand.
//!
//! Every command that reads geometry flattens [`InputArgs`] (INPUT, `--input-format`) and
//! [`OutputArgs`] (`--format`, `-o`, `--svg`, `--verify`) into its own args struct, so the
//! flags mean the same everywhere.
//!
//! ## Adding a command
//!
//! 1. Create `src/commands/NAME.rs` with `pub struct NAMEArgs` (`#[derive(clap::Args)]`,
//!    with `#[command(flatten)] input: InputArgs` and `#[command(flatten)] output: OutputArgs`,
//!    plus its own flags) and `pub fn run(args: &NAMEArgs) -> Result<(), CliError>`:
//!    read with [`crate::input`], call the library, verify when asked, then write with
//!    [`crate::output`] (JSON via serde, other formats via `compgeom::io::write_shape`) and
//!    draw with `compgeom::render`.
//! 2. Add `pub mod NAME;` in `src/commands/mod.rs`, a variant here (its doc comment is the
//!    one-line help; document the JSON fields in `after_long_help`), and a match arm in
//!    `main.rs`'s `run`.
//! 3. Add `src/demo/NAME.rs` with `pub fn section(demo: &Demo) -> Result<Section, CliError>`
//!    and list it in `demo::SECTIONS`.
//! 4. Add tests to `tests/cli.rs`.

use crate::commands::boolean::{BooleanArgs, MakeValidArgs, ValidateArgs};
use crate::commands::delaunay::DelaunayArgs;
use crate::commands::hull::HullArgs;
use crate::commands::interpolate::InterpolateArgs;
use crate::commands::intersect::IntersectArgs;
use crate::commands::overlay::OverlayArgs;
use crate::commands::range::RangeArgs;
use crate::commands::voronoi::VoronoiArgs;
use crate::commands::window::WindowArgs;
use crate::demo::DemoArgs;
use crate::error::CliError;
use clap::{Args, Parser, Subcommand, ValueEnum};
use std::path::PathBuf;

/// Exact computational geometry: the algorithms of de Berg, Cheong, van Kreveld & Overmars,
/// "Computational Geometry: Algorithms and Applications" (3rd ed.), every decision exact.
///
/// Exit codes: 0 success, 1 failure (writing output, verification), 2 bad input or usage.
#[derive(Debug, Parser)]
#[command(
    name = "compgeom",
    version,
    propagate_version = true,
    max_term_width = 100
)]
pub struct Cli {
    /// The command to run.
    #[command(subcommand)]
    pub command: Command,
}

/// The commands, in book order; `demo` last.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Convex hull of points in the plane (book chapter 1).
    #[command(after_long_help = crate::commands::hull::JSON_HELP)]
    Hull(HullArgs),
    /// All intersection points and overlaps of line segments (book chapter 2.1).
    #[command(after_long_help = crate::commands::intersect::JSON_HELP)]
    Intersect(IntersectArgs),
    /// Overlay of two polygon layers, faces labelled by the polygons containing them (book 2.3).
    #[command(after_long_help = crate::commands::overlay::JSON_HELP)]
    Overlay(OverlayArgs),
    /// Boolean operation on polygon sets: intersection, union, difference, xor (book 2.4).
    #[command(after_long_help = crate::commands::boolean::JSON_HELP)]
    Boolean(BooleanArgs),
    /// Report why polygons are not valid (OGC rules, RFC 7946 orientation); JSON
    /// `{"valid", "problems": [{"message", "at"}]}`.
    #[command(after_long_help = crate::commands::boolean::VALIDATE_HELP)]
    Validate(ValidateArgs),
    /// Repair polygons into valid ones, reading rings by a fill rule (book 2.4).
    #[command(after_long_help = crate::commands::boolean::MAKE_VALID_HELP)]
    MakeValid(MakeValidArgs),
    /// Triangulation of polygons with holes by monotone pieces (book chapter 3).
    #[command(after_long_help = crate::commands::triangulate::JSON_HELP)]
    Triangulate(crate::commands::triangulate::TriangulateArgs),
    /// Art gallery: guards at the smallest class of a 3-colouring (book chapter 3.1).
    #[command(after_long_help = crate::commands::guard::JSON_HELP)]
    Guard(crate::commands::guard::GuardArgs),
    /// Intersection of half-planes a·x + b·y <= c (book chapter 4).
    #[command(after_long_help = crate::commands::halfplanes::JSON_HELP)]
    Halfplanes(crate::commands::halfplanes::HalfplanesArgs),
    /// Linear programming: maximize c·x subject to a·x <= b (book chapter 4).
    #[command(after_long_help = crate::commands::lp::JSON_HELP)]
    Lp(crate::commands::lp::LpArgs),
    /// Smallest disc enclosing points in the plane (book chapter 4).
    #[command(after_long_help = crate::commands::enclose::JSON_HELP)]
    Enclose(crate::commands::enclose::EncloseArgs),
    /// Castability of a polyhedron: top facets and removal directions (book chapter 4).
    #[command(after_long_help = crate::commands::cast::JSON_HELP)]
    Cast(crate::commands::cast::CastArgs),
    /// Orthogonal range queries: points in rectangles, counts, k nearest (book chapter 5).
    #[command(after_long_help = crate::commands::range::JSON_HELP)]
    Range(RangeArgs),
    /// Point location in a polygon layer or segments: trapezoidal map (book chapter 6).
    #[command(after_long_help = crate::commands::locate::JSON_HELP)]
    Locate(crate::commands::locate::LocateArgs),
    /// Voronoi diagram of points (nearest or farthest site), cells clipped to a rectangle or any polygon (chapter 7).
    #[command(after_long_help = crate::commands::voronoi::JSON_HELP)]
    Voronoi(VoronoiArgs),
    /// Delaunay triangulation of points in the plane (book chapter 9).
    #[command(after_long_help = crate::commands::delaunay::JSON_HELP)]
    Delaunay(DelaunayArgs),
    /// Heights of the terrain over (x, y, z) samples at query points (book chapter 9).
    #[command(after_long_help = crate::commands::interpolate::JSON_HELP)]
    Interpolate(InterpolateArgs),
    /// Windowing: segments meeting query rectangles (book chapter 10).
    #[command(after_long_help = crate::commands::window::JSON_HELP)]
    Window(WindowArgs),
    /// Run the commands on built-in samples; write one SVG per run and an index.html gallery.
    Demo(DemoArgs),
}

/// Where the input comes from and how to read it.
#[derive(Debug, Clone, Args)]
pub struct InputArgs {
    /// Input file, or `-` for standard input.
    #[arg(value_name = "INPUT")]
    pub input: PathBuf,

    /// Input format. Default: from the file extension (.csv/.txt/.xy, .wkt, .geojson),
    /// otherwise detected from the content.
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub input_format: Option<InputFormat>,
}

/// How results are checked, written and drawn.
#[derive(Debug, Clone, Args)]
pub struct OutputArgs {
    /// Output format. Default: from the extension of the `-o` file (.json, .geojson,
    /// .wkt, .csv), otherwise json.
    #[arg(short = 'f', long = "format", value_enum, value_name = "FORMAT")]
    pub format_asked: Option<OutputFormat>,

    /// Write the result to this file (atomically: complete or not at all) instead of
    /// standard output. `-` means standard output.
    #[arg(short = 'o', long = "output", value_name = "OUT")]
    pub output: Option<PathBuf>,

    /// Also draw the input and the result as an SVG picture in this file.
    #[arg(long, value_name = "FILE")]
    pub svg: Option<PathBuf>,

    /// Check the result exactly with the library's verifier; exit 1 if it fails.
    #[arg(long)]
    pub verify: bool,
}

impl OutputArgs {
    /// The output format: `--format` where given, else the one the `-o` file's extension
    /// names (`out.geojson` is GeoJSON, as a reader of the file expects), else JSON.
    pub fn format(&self) -> OutputFormat {
        self.format_asked
            .or_else(|| self.format_of_extension())
            .unwrap_or(OutputFormat::Json)
    }

    /// The format the `-o` file's extension names, if any (case aside).
    fn format_of_extension(&self) -> Option<OutputFormat> {
        let extension = self.output.as_ref()?.extension()?.to_str()?;
        match extension.to_ascii_lowercase().as_str() {
            "json" => Some(OutputFormat::Json),
            "geojson" => Some(OutputFormat::Geojson),
            "wkt" => Some(OutputFormat::Wkt),
            "csv" => Some(OutputFormat::Csv),
            _ => None,
        }
    }

    /// The error for a command that cannot write the output format: `what` says what it
    /// writes (e.g. "json only"); where the format came from the `-o` file's name, so
    /// does the message.
    pub fn unsupported(&self, command: &str, what: &str) -> CliError {
        let name = self
            .format()
            .to_possible_value()
            .map(|v| v.get_name().to_string())
            .unwrap_or_default();
        let origin = match (&self.format_asked, &self.output) {
            (None, Some(out)) => format!(
                " (the format of {}'s extension; name the format with --format)",
                out.display()
            ),
            _ => String::new(),
        };
        CliError::bad_input(format!("{command} writes {what}, not {name}{origin}"))
    }
}

/// Input formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum InputFormat {
    /// `x,y` or `x y` per line; `#` starts a comment.
    Csv,
    /// Well-known text.
    Wkt,
    /// GeoJSON (RFC 7946).
    Geojson,
}

impl From<InputFormat> for compgeom::io::Format {
    fn from(f: InputFormat) -> Self {
        match f {
            InputFormat::Csv => compgeom::io::Format::Csv,
            InputFormat::Wkt => compgeom::io::Format::Wkt,
            InputFormat::Geojson => compgeom::io::Format::GeoJson,
        }
    }
}

/// Output formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum OutputFormat {
    /// One JSON object; each command documents its fields in `--help`.
    Json,
    /// The result geometry, one `x,y` vertex per line.
    Csv,
    /// The result geometry as well-known text.
    Wkt,
    /// The result geometry as a GeoJSON (RFC 7946) geometry.
    Geojson,
}

impl OutputFormat {
    /// The library format for geometry output (`None` for JSON, which each command builds).
    pub fn geometry_format(self) -> Option<compgeom::io::Format> {
        match self {
            OutputFormat::Json => None,
            OutputFormat::Csv => Some(compgeom::io::Format::Csv),
            OutputFormat::Wkt => Some(compgeom::io::Format::Wkt),
            OutputFormat::Geojson => Some(compgeom::io::Format::GeoJson),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn command_line_definition_is_consistent() {
        Cli::command().debug_assert();
    }
}
