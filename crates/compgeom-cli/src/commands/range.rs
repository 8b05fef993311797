//! `compgeom range`: orthogonal range queries (book chapter 5) via `compgeom::range`:
//! which input points lie in each query rectangle, how many, or which are nearest.

use crate::cli::{InputArgs, OutputArgs};
use crate::error::CliError;
use crate::output;
use clap::{Args, ValueEnum};
use compgeom::io::{write_shape, Shape};
use compgeom::range::{read_rects, verify_query, KdTree, LayeredRangeTree, RangeTree};
use compgeom::render::{Layer, Picture, Style};
use compgeom::{Bbox2, Point2, Segment2};
use serde::Serialize;
use std::path::PathBuf;

/// `--help` text describing the JSON output.
pub const JSON_HELP: &str = "\
RECTS holds one query rectangle per line: xmin,ymin,xmax,ymax (closed: points on the
boundary are inside; a rectangle with xmin > xmax or ymin > ymax is empty).

JSON output (--format json, the default) is one object:
  results       [[i, ...], ...]  per query, the 0-based indices of the input points inside,
                                 ascending (with --knn: the K nearest, nearest first, equal
                                 distances by index; distances compared exactly)
  counts        [c, ...]         instead of results, with --count
  structure     \"kdtree\" | \"rangetree\" | \"layered\"
  input_points  number of points read
  queries       number of queries
  verified      true; present only with --verify (each answer checked against brute force)

Other formats print the reported points (of all queries) as a multipoint (--count: json
only).

Examples:
  compgeom range points.csv --queries rects.csv
  compgeom range points.csv --queries rects.csv --structure kdtree --count
  compgeom range points.csv --knn 3 --at probes.csv --svg knn.svg";

/// Arguments of `compgeom range`.
#[derive(Debug, Clone, Args)]
pub struct RangeArgs {
    /// Input points and their format.
    #[command(flatten)]
    pub input: InputArgs,

    /// Output, picture and verification.
    #[command(flatten)]
    pub output: OutputArgs,

    /// Query rectangles, one `xmin,ymin,xmax,ymax` line each (`-` for standard input).
    #[arg(long, value_name = "RECTS", required_unless_present = "knn")]
    pub queries: Option<PathBuf>,

    /// The structure: `layered` (fractional cascading, O(log n + k)), `rangetree`
    /// (O(log² n + k)) or `kdtree` (O(√n + k)).
    #[arg(long, value_enum, default_value_t = StructureArg::Layered)]
    pub structure: StructureArg,

    /// Print only the number of points in each rectangle.
    #[arg(long, conflicts_with = "knn")]
    pub count: bool,

    /// K nearest neighbours (kd-tree) of each point in --at, instead of rectangles.
    #[arg(long, value_name = "K", requires = "at", conflicts_with = "queries")]
    pub knn: Option<usize>,

    /// Query points for --knn (a points file, any input format).
    #[arg(long, value_name = "POINTS")]
    pub at: Option<PathBuf>,
}

/// The `--structure` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum StructureArg {
    /// kd-tree (§5.2).
    Kdtree,
    /// 2D range tree (§5.3).
    Rangetree,
    /// Layered range tree with fractional cascading (§5.6).
    Layered,
}

impl StructureArg {
    /// The name printed in JSON output and titles.
    pub fn name(self) -> &'static str {
        match self {
            StructureArg::Kdtree => "kdtree",
            StructureArg::Rangetree => "rangetree",
            StructureArg::Layered => "layered",
        }
    }
}

/// A built structure of any kind.
pub enum Structure {
    /// kd-tree.
    Kd(KdTree),
    /// Range tree.
    Range(RangeTree),
    /// Layered range tree.
    Layered(LayeredRangeTree),
}

impl Structure {
    /// Build `kind` over `points`.
    pub fn build(kind: StructureArg, points: &[Point2]) -> Result<Structure, CliError> {
        Ok(match kind {
            StructureArg::Kdtree => Structure::Kd(KdTree::new(points)?),
            StructureArg::Rangetree => Structure::Range(RangeTree::new(points)?),
            StructureArg::Layered => Structure::Layered(LayeredRangeTree::new(points)?),
        })
    }

    /// The points in `rect`, ascending indices.
    pub fn query(&self, rect: &Bbox2) -> Vec<usize> {
        match self {
            Structure::Kd(t) => t.query(rect),
            Structure::Range(t) => t.query(rect),
            Structure::Layered(t) => t.query(rect),
        }
    }

    /// The number of points in `rect`.
    pub fn count(&self, rect: &Bbox2) -> usize {
        match self {
            Structure::Kd(t) => t.count(rect),
            Structure::Range(t) => t.count(rect),
            Structure::Layered(t) => t.count(rect),
        }
    }
}

#[derive(Debug, Serialize)]
struct RangeJson {
    #[serde(skip_serializing_if = "Option::is_none")]
    results: Option<Vec<Vec<usize>>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    counts: Option<Vec<usize>>,
    structure: &'static str,
    input_points: usize,
    queries: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    verified: Option<bool>,
}

/// Run `compgeom range`.
pub fn run(args: &RangeArgs) -> Result<(), CliError> {
    let points = args.input.read_points()?;
    let (structure, results, counts, rects, probes) = if let Some(k) = args.knn {
        let at = InputArgs {
            input: args.at.clone().unwrap_or_default(),
            input_format: None,
        };
        let probes = at.read_points()?;
        let tree = KdTree::new(&points)?;
        let results: Vec<Vec<usize>> = probes.iter().map(|&q| tree.nearest(q, k)).collect();
        if args.output.verify {
            for (q, r) in probes.iter().zip(&results) {
                compgeom::range::verify_nearest(&points, *q, k, r)?;
            }
        }
        (
            StructureArg::Kdtree,
            Some(results),
            None,
            Vec::new(),
            probes,
        )
    } else {
        let path = args.queries.clone().unwrap_or_default();
        let text =
            compgeom::io::read_text(&path).map_err(|e| CliError::bad_input(e.to_string()))?; // missing file: bad input, exit 2
        let name = if path.as_os_str() == "-" {
            "<stdin>".to_string()
        } else {
            path.display().to_string()
        };
        let rects = read_rects(&text, &name)?;
        let s = Structure::build(args.structure, &points)?;
        if args.count {
            let counts: Vec<usize> = rects.iter().map(|r| s.count(r)).collect();
            if args.output.verify {
                for (r, &c) in rects.iter().zip(&counts) {
                    let want = points.iter().filter(|p| r.contains(**p)).count();
                    if want != c {
                        return Err(CliError::failure(format!(
                            "verification failed: count {c} for {r:?}, brute force finds {want}"
                        )));
                    }
                }
            }
            (args.structure, None, Some(counts), rects, Vec::new())
        } else {
            let results: Vec<Vec<usize>> = rects.iter().map(|r| s.query(r)).collect();
            if args.output.verify {
                for (r, res) in rects.iter().zip(&results) {
                    verify_query(&points, r, res)?;
                }
            }
            (args.structure, Some(results), None, rects, Vec::new())
        }
    };
    let queries = rects.len().max(probes.len());
    let text = match args.output.format().geometry_format() {
        None => {
            let json = RangeJson {
                results: results.clone(),
                counts,
                structure: structure.name(),
                input_points: points.len(),
                queries,
                verified: args.output.verify.then_some(true),
            };
            serde_json::to_string(&json)
                .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?
        }
        Some(_) if counts.is_some() => {
            return Err(CliError::bad_input(
                "--count prints numbers, not geometry: use --format json",
            ))
        }
        Some(format) => {
            let mut ids: Vec<usize> = results.iter().flatten().flatten().copied().collect();
            ids.sort_unstable();
            ids.dedup();
            write_shape(
                &Shape::MultiPoint(ids.iter().map(|&i| points[i]).collect()),
                format,
            )?
        }
    };
    if let Some(svg) = &args.output.svg {
        let reported: &[Vec<usize>] = results.as_deref().unwrap_or_default();
        let splits = (structure == StructureArg::Kdtree)
            .then(|| KdTree::new(&points))
            .transpose()?;
        let title = format!(
            "range search ({}): n = {}, {} queries",
            structure.name(),
            points.len(),
            queries
        );
        let picture = range_picture(&points, &rects, &probes, reported, splits.as_ref(), &title);
        output::write_atomic(svg, picture.to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

/// Points, query rectangles (or k-NN probes, each joined to its neighbours), reported
/// points highlighted (`results`: one list per query, may be empty with `--count`), and for
/// a kd-tree its splitting lines.
pub fn range_picture(
    points: &[Point2],
    rects: &[Bbox2],
    probes: &[Point2],
    results: &[Vec<usize>],
    kdtree: Option<&KdTree>,
    title: &str,
) -> Picture {
    let mut reported: Vec<usize> = results.iter().flatten().copied().collect();
    reported.sort_unstable();
    reported.dedup();
    let mut pic = Picture::new(800, 640).with_title(title);
    let mut bounds = Bbox2::of_points(points);
    for r in rects.iter().filter(|r| !r.is_empty()) {
        bounds.extend(r.min);
        bounds.extend(r.max);
    }
    // (A tree of at most one leaf bucket has no splitting lines: no empty legend entry.)
    let splits = kdtree.map(|t| t.splits(bounds)).unwrap_or_default();
    if !splits.is_empty() {
        pic.add(
            Layer::new(
                "kd-tree splitting lines",
                Style::lines("#bbbbbb").with_stroke_width(0.8),
            )
            .segments(&splits),
        );
    }
    let radius = if points.len() > 10_000 { 1.0 } else { 2.0 };
    pic.add(
        Layer::new(
            format!("input points ({})", points.len()),
            Style::points("#8c8c8c").with_radius(radius),
        )
        .points(points),
    );
    if !rects.is_empty() {
        pic.add(query_rect_layer(
            format!("query rectangles ({})", rects.len()),
            rects,
            0.08,
        ));
    }
    if !probes.is_empty() {
        let links: Vec<Segment2> = probes
            .iter()
            .zip(results)
            .flat_map(|(&q, r)| r.iter().map(move |&i| Segment2::new(q, points[i])))
            .collect();
        pic.add(
            Layer::new(
                "query point to its neighbours",
                Style::lines("#2ca02c").with_stroke_width(0.8),
            )
            .segments(&links),
        );
    }
    let hits: Vec<Point2> = reported.iter().map(|&i| points[i]).collect();
    pic.add(
        Layer::new(
            format!("reported points ({})", reported.len()),
            Style::points("#d62728").with_radius(radius + 1.5),
        )
        .points(&hits),
    );
    // Query points last, so that a query point equal to an input point stays visible.
    if !probes.is_empty() {
        pic.add(
            Layer::new(
                "k-NN query points",
                Style::points("#2ca02c")
                    .with_radius(5.0)
                    .without_fill()
                    .with_stroke_width(2.0),
            )
            .points(probes),
        );
    }
    pic
}

/// The query rectangles as one picture layer; a point rectangle (which would draw as
/// nothing) is drawn as a point, an empty one not at all. Shared with `window`.
pub(crate) fn query_rect_layer(name: String, rects: &[Bbox2], fill_opacity: f64) -> Layer {
    let mut layer = Layer::new(name, Style::area("#1f77b4").with_fill_opacity(fill_opacity));
    for r in rects.iter().filter(|r| !r.is_empty()) {
        if r.min == r.max {
            layer = layer.point(r.min);
        } else {
            layer = layer.ring(&[
                r.min,
                Point2::new(r.max.x, r.min.y),
                r.max,
                Point2::new(r.min.x, r.max.y),
            ]);
        }
    }
    layer
}
