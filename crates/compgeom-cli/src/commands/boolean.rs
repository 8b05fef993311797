//! `compgeom boolean` (book §2.4: intersection, union, difference, xor of polygon sets via
//! `compgeom::overlay::boolean_with`) and `compgeom make-valid` (`compgeom::overlay::make_valid`,
//! or `make_valid_per_polygon`).

use crate::cli::{InputArgs, OutputArgs, OutputFormat};
use crate::error::CliError;
use crate::output;
use clap::{Args, ValueEnum};
use compgeom::io::{self, write_shape, GeoJsonGeometry, Shape};
use compgeom::overlay::{
    boolean_with, make_valid, make_valid_per_polygon, BooleanOp, BooleanOptions, FillRule,
};
use compgeom::render::{Layer, Picture, Style};
use compgeom::MultiPolygon;
use serde::Serialize;
use std::path::PathBuf;

/// `--help` text describing the JSON output of `boolean`.
pub const JSON_HELP: &str = "\
JSON output (--format json, the default) is one object:
  operation   \"intersection\" | \"union\" | \"difference\" | \"xor\"
  fill_rule   \"evenodd\" | \"nonzero\" | \"positive\"
  result      the result as a GeoJSON MultiPolygon geometry: valid (outer rings
              counter-clockwise, holes clockwise, rings closed, touching only at points),
              no vertex where a ring goes straight on unless --keep-collinear
  polygons    number of polygons in the result

A and B are each read as one polygon set (all features of the file together), with the
fill rule: evenodd (default; an odd number of ring crossings is inside), nonzero
(winding number not zero, rings as given), positive (each polygon its shell
minus its holes, the polygons united). With only A, `union` unites all of A's polygons
(its default fill rule is then positive; with evenodd, where two overlap is a hole).
Coordinates of constructed crossings are the nearest f64 to the exact point; where that
rounding could make the result invalid, the crossing takes another float around its exact
point (one float away per axis) that keeps it valid, or else the rounded result is united
again.

Examples:
  compgeom boolean intersection a.geojson b.geojson --format geojson -o out.geojson
  compgeom boolean union parcels.wkt --svg union.svg";

/// The operation argument.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum OpArg {
    /// A ∩ B.
    Intersection,
    /// A ∪ B (or the union of all of A's polygons with one input).
    Union,
    /// A − B.
    Difference,
    /// Symmetric difference.
    Xor,
}

impl OpArg {
    fn op(self) -> BooleanOp {
        match self {
            OpArg::Intersection => BooleanOp::Intersection,
            OpArg::Union => BooleanOp::Union,
            OpArg::Difference => BooleanOp::Difference,
            OpArg::Xor => BooleanOp::Xor,
        }
    }
    fn name(self) -> &'static str {
        match self {
            OpArg::Intersection => "intersection",
            OpArg::Union => "union",
            OpArg::Difference => "difference",
            OpArg::Xor => "xor",
        }
    }
}

/// The `--fill-rule` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FillRuleArg {
    /// Odd number of ring crossings is inside.
    Evenodd,
    /// Winding number not zero (rings as given).
    Nonzero,
    /// Winding number positive: each polygon its shell minus its holes, polygons united.
    Positive,
}

impl FillRuleArg {
    /// The library rule.
    pub fn rule(self) -> FillRule {
        match self {
            FillRuleArg::Evenodd => FillRule::EvenOdd,
            FillRuleArg::Nonzero => FillRule::NonZero,
            FillRuleArg::Positive => FillRule::Positive,
        }
    }
    fn name(self) -> &'static str {
        match self {
            FillRuleArg::Evenodd => "evenodd",
            FillRuleArg::Nonzero => "nonzero",
            FillRuleArg::Positive => "positive",
        }
    }
}

/// Arguments of `compgeom boolean`.
#[derive(Debug, Clone, Args)]
pub struct BooleanArgs {
    /// The operation.
    #[arg(value_enum)]
    pub operation: OpArg,

    /// Input A and its format.
    #[command(flatten)]
    pub input: InputArgs,

    /// Input B (same format rules as A). Optional for `union`.
    #[arg(value_name = "B")]
    pub b: Option<PathBuf>,

    /// How rings define the inside of each input [default: evenodd; positive for
    /// `union` with one input, which unites its polygons].
    #[arg(long, value_enum)]
    pub fill_rule: Option<FillRuleArg>,

    /// Keep vertices where the result's boundary goes straight on.
    #[arg(long)]
    pub keep_collinear: bool,

    /// Output, picture and verification.
    #[command(flatten)]
    pub output: OutputArgs,
}

/// Read a polygon layer.
pub fn read_layer(input: &InputArgs) -> Result<MultiPolygon, CliError> {
    let src = input.read()?;
    Ok(io::read_polygons(&src.text, src.format, &src.name)?)
}

/// The same input options for another file.
pub fn other_input(input: &InputArgs, path: &std::path::Path) -> InputArgs {
    InputArgs {
        input: path.to_path_buf(),
        input_format: input.input_format,
    }
}

#[derive(Serialize)]
struct BooleanJson<'a> {
    operation: &'static str,
    fill_rule: &'static str,
    result: GeoJsonGeometry<'a>,
    polygons: usize,
}

/// `make-valid`'s JSON document (keys in alphabetical order, as it has always written
/// them).
#[derive(Serialize)]
struct MakeValidJson<'a> {
    fill_rule: &'static str,
    operation: &'static str,
    per_polygon: bool,
    polygons: usize,
    result: GeoJsonGeometry<'a>,
}

/// Run `compgeom boolean`.
pub fn run(args: &BooleanArgs) -> Result<(), CliError> {
    let a = read_layer(&args.input)?;
    let b = match &args.b {
        Some(p) => read_layer(&other_input(&args.input, p))?,
        None if args.operation == OpArg::Union => MultiPolygon::default(),
        None => {
            return Err(CliError::bad_input(format!(
                "{} needs two inputs A and B",
                args.operation.name()
            )))
        }
    };
    // (One input is read as polygons to unite: even-odd would make where two of them
    // overlap a hole.)
    let fill_rule = args.fill_rule.unwrap_or(if args.b.is_none() {
        FillRuleArg::Positive
    } else {
        FillRuleArg::Evenodd
    });
    let opts = BooleanOptions {
        fill_rule: fill_rule.rule(),
        keep_collinear: args.keep_collinear,
    };
    let result = boolean_with(&a, &b, args.operation.op(), &opts)?;
    let shape = Shape::MultiPolygon(result.clone());
    let text = match args.output.format().geometry_format() {
        None => serde_json::to_string(&BooleanJson {
            operation: args.operation.name(),
            fill_rule: fill_rule.name(),
            result: GeoJsonGeometry(&shape),
            polygons: result.0.len(),
        })
        .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?,
        Some(format) => write_shape(&shape, format)?,
    };
    if let Some(svg) = &args.output.svg {
        let title = format!(
            "{} ({}): {} polygons",
            args.operation.name(),
            fill_rule.name(),
            result.0.len()
        );
        let pic = boolean_picture(&a, &b, &result, &title);
        output::write_atomic(svg, pic.to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

/// A and B in two colours, the result on top.
pub fn boolean_picture(
    a: &MultiPolygon,
    b: &MultiPolygon,
    result: &MultiPolygon,
    title: &str,
) -> Picture {
    let mut pic = Picture::new(800, 640).with_title(title);
    pic.add(Layer::new("A", Style::area("#1f77b4").with_fill_opacity(0.15)).polygons(&a.0));
    if !b.0.is_empty() {
        pic.add(Layer::new("B", Style::area("#ff7f0e").with_fill_opacity(0.15)).polygons(&b.0));
    }
    pic.add(
        Layer::new(
            "result",
            Style::area("#2ca02c")
                .with_fill_opacity(0.45)
                .with_stroke_width(2.0),
        )
        .polygons(&result.0),
    );
    pic
}

/// `--help` text describing what `make-valid` does and prints.
pub const MAKE_VALID_HELP: &str = "\
JSON output (--format json, the default) is one object:
  operation    \"make-valid\"
  fill_rule    \"evenodd\" | \"nonzero\" | \"positive\"
  per_polygon  whether each polygon was repaired on its own, then all united
  result       the repaired region as a GeoJSON MultiPolygon geometry, valid as for
               `boolean` (outer rings counter-clockwise, holes clockwise)
  polygons     number of polygons in the result

By default all rings of the input are read together by the fill rule: with even-odd a
bow tie becomes two triangles, and where two polygons overlap the place is outside
(covered twice). --per-polygon repairs each polygon on its own (its shell and holes by
the fill rule) and unites the results: overlapping parts, and a polygon drawn twice,
stay inside. Other formats print the result's geometry.

Examples:
  compgeom make-valid parcels.geojson -o fixed.geojson
  compgeom make-valid parcels.wkt --per-polygon --svg fixed.svg";

/// Arguments of `compgeom make-valid`.
#[derive(Debug, Clone, Args)]
pub struct MakeValidArgs {
    /// Input and its format.
    #[command(flatten)]
    pub input: InputArgs,

    /// How rings define the inside.
    #[arg(long, value_enum, default_value_t = FillRuleArg::Evenodd)]
    pub fill_rule: FillRuleArg,

    /// Repair each polygon on its own (its rings by the fill rule), then unite them:
    /// where polygons overlap the result is inside (by default all rings are read
    /// together, and with even-odd two polygons covering a place cancel out).
    #[arg(long)]
    pub per_polygon: bool,

    /// Output, picture and verification.
    #[command(flatten)]
    pub output: OutputArgs,
}

/// Run `compgeom make-valid`: the input's region under the fill rule, as valid polygons
/// (JSON: as for `boolean`, operation "make-valid").
pub fn run_make_valid(args: &MakeValidArgs) -> Result<(), CliError> {
    let a = read_layer(&args.input)?;
    let result = if args.per_polygon {
        make_valid_per_polygon(&a, args.fill_rule.rule())?
    } else {
        make_valid(&a, args.fill_rule.rule())?
    };
    let shape = Shape::MultiPolygon(result.clone());
    let text = match args.output.format().geometry_format() {
        None => serde_json::to_string(&MakeValidJson {
            fill_rule: args.fill_rule.name(),
            operation: "make-valid",
            per_polygon: args.per_polygon,
            polygons: result.0.len(),
            result: GeoJsonGeometry(&shape),
        })
        .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?,
        Some(format) => write_shape(&shape, format)?,
    };
    if let Some(svg) = &args.output.svg {
        let pic = boolean_picture(&a, &MultiPolygon::default(), &result, "make-valid");
        output::write_atomic(svg, pic.to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

/// `--help` text describing what `validate` checks and prints.
pub const VALIDATE_HELP: &str = "\
JSON output (--format json, the only format) is one object:
  valid     true when there is no problem
  problems  [{\"message\", \"at\": [x, y] | null, \"polygon\", \"feature\"}], in the order
            checked; polygons and rings are numbered from 0 in reading order, holes
            from 0 in their polygon; \"polygon\" is the index of the polygon the problem
            is in (the first one named) and \"feature\" that of its GeoJSON Feature (for
            other input, the polygon's own index), null where it names none

Checked (OGC simple features, as JTS's isValid judges them): rings closed (WKT and
GeoJSON; in z too, where given, unlike JTS) with at least 3 distinct points; no edges
crossing or overlapping; no ring passing twice through a point; the rings of a polygon
meeting at most once each and not in a loop (else its interior is cut apart); holes
inside their shell, not overlapping or nested (each hole inside another named once);
polygon interiors not overlapping (every polygon that overlaps another named, with one
it overlaps, at a point inside both; an overlap too thin for such a point is reported
without names). Two rings of a polygon may touch at one point, polygons at points.
Then, as RFC 7946 asks (OGC does not): shells counter-clockwise, holes clockwise.
Exact throughout.

Rings other commands reject as bad input (not closed, too short) are reported here.

Examples:
  compgeom validate parcels.geojson
  compgeom validate parcels.wkt --svg problems.svg";

/// Arguments of `compgeom validate`.
#[derive(Debug, Clone, Args)]
pub struct ValidateArgs {
    /// Input and its format.
    #[command(flatten)]
    pub input: InputArgs,

    /// Output (JSON only) and picture.
    #[command(flatten)]
    pub output: OutputArgs,
}

/// Run `compgeom validate`: JSON `{"valid": bool, "problems": [{"message", "at": [x, y] |
/// null, "polygon", "feature"}]}`; exit 0 either way (the answer is the output).
pub fn run_validate(args: &ValidateArgs) -> Result<(), CliError> {
    if args.output.format() != OutputFormat::Json {
        return Err(args.output.unsupported("validate", "json only"));
    }
    // (As written: a ring the other commands reject as bad input is a problem to report.)
    let src = args.input.read()?;
    let read = io::read_polygons_as_written(&src.text, src.format, &src.name)?;
    let problems =
        compgeom::overlay::validity_problems_as_written(&read.polygons, &read.open_rings)?;
    let list: Vec<serde_json::Value> = problems
        .iter()
        .map(|p| {
            serde_json::json!({
                "message": p.message,
                "at": p.at.map(|q| [q.x, q.y]),
                "polygon": p.polygon,
                "feature": p.polygon.map(|k| read.features[k]),
            })
        })
        .collect();
    let a = read.polygons;
    let text = serde_json::to_string(&serde_json::json!({
        "valid": problems.is_empty(),
        "problems": list,
    }))
    .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?;
    if let Some(svg) = &args.output.svg {
        let title = match problems.len() {
            0 => "validate: valid".to_string(),
            n => format!("validate: {n} problem(s)"),
        };
        let mut pic = Picture::new(800, 640).with_title(title);
        pic.add(Layer::new("input", Style::area("#1f77b4").with_fill_opacity(0.15)).polygons(&a.0));
        let pts: Vec<compgeom::Point2> = problems.iter().filter_map(|p| p.at).collect();
        pic.add(Layer::new("problems", Style::points("#d62728").with_radius(5.0)).points(&pts));
        output::write_atomic(svg, pic.to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}
