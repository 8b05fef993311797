//! `compgeom delaunay`: the Delaunay triangulation of points in the plane (book chapter 9),
//! via `compgeom::delaunay`.

use crate::cli::{InputArgs, OutputArgs};
use crate::error::CliError;
use crate::output;
use crate::progress::{Spinner, LARGE_INPUT};
use clap::{Args, ValueEnum};
use compgeom::delaunay::{
    constrained_delaunay, delaunay_with, polygon_delaunay_with_points, refine, verify_cdt,
    verify_delaunay, Cdt, DelaunayAlgorithm, DelaunayOptions, InsertionOrder, RefineOptions,
    Triangulation,
};
use compgeom::io::{write_shape, Shape};
use compgeom::render::{Layer, Picture, Style};
use compgeom::{MultiPolygon, Point2, Polygon};
use serde::Serialize;

/// `--help` text describing the JSON output.
pub const JSON_HELP: &str = "\
JSON output (--format json, the default) is one object:
  vertices         [[x, y], ...]   the distinct input points in first-seen order (exact values),
                                   then Steiner points (constraint crossings, refinement)
  triangles        [[i, j, k], ...] counter-clockwise, indices into vertices
  input_to_vertex  [v, ...]        for every input point, its vertex (duplicates share one)
  algorithm        \"default\" | \"incremental\"
  input_points     number of points read (duplicates included)
  note             present when there are no triangles (fewer than 3 distinct points, or all
                   collinear): not an error
  constraints      [[u, v], ...]  constrained edges (with --constraints or --polygon; pieces of a
                                 constraint split at input points or crossings are listed
                                 separately)
  steiner          with --refine or --max-area: the number of Steiner points added (they are the
                   last vertices)
  exempt           with --refine: triangles left below the angle bound by the small-input-angle
                   rule (indices into triangles; empty for inputs without angles below 60 degrees)
  verified         true; present only with --verify (a failed check exits 1 instead)

With --constraints or --polygon, input_to_vertex covers the points, then the constraint
endpoints (segment 0's two ends, segment 1's, ...) or the ring vertices in order, and
--algorithm is ignored (the default triangulation is constrained).

Other formats print the triangles as a multipolygon.

Four or more cocircular points: one valid Delaunay triangulation is chosen, the same on every
run for the same input.

Examples:
  compgeom delaunay points.csv --svg delaunay.svg --verify
  compgeom delaunay points.csv --algorithm incremental --format geojson -o tin.geojson
  compgeom delaunay empty.csv --polygon shape.wkt --refine 25 --max-area 0.5 --svg mesh.svg";

/// Arguments of `compgeom delaunay`.
#[derive(Debug, Clone, Args)]
pub struct DelaunayArgs {
    /// Input and its format.
    #[command(flatten)]
    pub input: InputArgs,

    /// Output, picture and verification.
    #[command(flatten)]
    pub output: OutputArgs,

    /// Algorithm: `default` (fastest exact: spatial sort, walking location, flips) or
    /// `incremental` (the book's randomized incremental algorithm with the history DAG).
    #[arg(long, value_enum, default_value_t = AlgorithmArg::Default)]
    pub algorithm: AlgorithmArg,

    /// Insertion order of `--algorithm incremental`: `biased` (randomized rounds, each in
    /// Hilbert-curve order: much faster on large inputs) or `uniform` (a uniform random
    /// permutation, as in the book). Both are seeded, so runs are reproducible.
    #[arg(long, value_enum, default_value_t = OrderArg::Biased)]
    pub insertion_order: OrderArg,

    /// Segment constraints (x1,y1,x2,y2 lines, WKT or GeoJSON): the constrained Delaunay
    /// triangulation, with every segment a union of edges (split where input points lie on
    /// it, and at crossings with other segments: each crossing is a Steiner vertex at the
    /// nearest f64 point, listed after the input vertices).
    #[arg(long, value_name = "SEGMENTS", conflicts_with = "polygon")]
    pub constraints: Option<std::path::PathBuf>,

    /// Polygons (with holes) as WKT or GeoJSON: the constrained Delaunay triangulation of
    /// their rings and POINTS (which may be an empty file), keeping only the triangles inside.
    #[arg(long, value_name = "POLY")]
    pub polygon: Option<std::path::PathBuf>,

    /// Delaunay refinement (Ruppert): add Steiner points until every triangle has all angles
    /// at least MIN_ANGLE degrees (0..=34; guaranteed to finish up to 20.7 when input
    /// segments meet at 60 degrees or more; near smaller input angles some triangles are
    /// left and listed in "exempt"). Only the domain (polygon interior or convex hull) is
    /// refined.
    #[arg(long, value_name = "MIN_ANGLE")]
    pub refine: Option<f64>,

    /// With refinement: also split every triangle of area above A.
    #[arg(long, value_name = "A")]
    pub max_area: Option<f64>,

    /// Draw the circumcircles of this many triangles in the SVG.
    #[arg(long, value_name = "N", default_value_t = 0)]
    pub circumcircles: usize,
}

/// The `--insertion-order` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum OrderArg {
    /// Biased randomized insertion order (BRIO).
    Biased,
    /// A uniform random permutation.
    Uniform,
}

/// The `--algorithm` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum AlgorithmArg {
    /// The fastest exact method.
    Default,
    /// The book's DELAUNAYTRIANGULATION (§9.3).
    Incremental,
}

impl AlgorithmArg {
    /// The name printed in JSON output and titles.
    pub fn name(self) -> &'static str {
        match self {
            AlgorithmArg::Default => "default",
            AlgorithmArg::Incremental => "incremental",
        }
    }

    /// The library options.
    pub fn options(self, order: OrderArg) -> DelaunayOptions {
        DelaunayOptions::new()
            .with_algorithm(match self {
                AlgorithmArg::Default => DelaunayAlgorithm::Default,
                AlgorithmArg::Incremental => DelaunayAlgorithm::Incremental,
            })
            .with_insertion_order(match order {
                OrderArg::Biased => InsertionOrder::Biased,
                OrderArg::Uniform => InsertionOrder::Uniform,
            })
    }
}

/// The JSON result object (fields documented in [`JSON_HELP`]).
#[derive(Debug, Serialize)]
struct DelaunayJson<'a> {
    vertices: Vec<[f64; 2]>,
    triangles: &'a [[u32; 3]],
    input_to_vertex: &'a [u32],
    algorithm: &'static str,
    input_points: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    constraints: Option<&'a [(u32, u32)]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    steiner: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    exempt: Option<&'a [u32]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    note: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    verified: Option<bool>,
}

/// Run `compgeom delaunay`.
pub fn run(args: &DelaunayArgs) -> Result<(), CliError> {
    let points = args.input.read_points()?;
    let large = points.len() >= LARGE_INPUT;
    let read_other = |path: &std::path::Path| {
        InputArgs {
            input: path.to_path_buf(),
            input_format: None,
        }
        .read()
    };
    let mut constraints = None;
    let mut refined = None;
    let refining = args.refine.is_some() || args.max_area.is_some();
    let tri = {
        let _spin = Spinner::start("triangulating", large);
        let cdt = if let Some(path) = &args.constraints {
            let src = read_other(path)?;
            let segs = compgeom::io::read_segments(&src.text, src.format, &src.name)?;
            Some(constrained_delaunay(&points, &segs)?)
        } else if let Some(path) = &args.polygon {
            let src = read_other(path)?;
            let polys = compgeom::io::read_polygons(&src.text, src.format, &src.name)?;
            Some(polygon_delaunay_with_points(&points, &polys.0)?)
        } else if refining {
            Some(Cdt {
                triangulation: delaunay_with(
                    &points,
                    &args.algorithm.options(args.insertion_order),
                )?,
                constraints: Vec::new(),
            })
        } else {
            None
        };
        match cdt {
            Some(mut cdt) => {
                if refining {
                    let mut opts = RefineOptions::new(args.refine.unwrap_or(0.0));
                    if let Some(a) = args.max_area {
                        opts = opts.with_max_area(a);
                    }
                    let r = refine(&cdt, &opts)?;
                    cdt = r.cdt;
                    refined = Some((r.steiner, r.exempt));
                }
                if args.output.verify {
                    verify_cdt(&cdt)?;
                }
                constraints = Some(cdt.constraints);
                cdt.triangulation
            }
            None => {
                let t = delaunay_with(&points, &args.algorithm.options(args.insertion_order))?;
                if args.output.verify {
                    verify_delaunay(&t)?;
                }
                t
            }
        }
    };
    let text = match args.output.format().geometry_format() {
        None => {
            let json = DelaunayJson {
                vertices: tri.vertices().iter().map(|p| [p.x, p.y]).collect(),
                triangles: tri.triangles(),
                input_to_vertex: tri.input_to_vertex(),
                algorithm: args.algorithm.name(),
                input_points: points.len(),
                constraints: constraints.as_deref(),
                steiner: refined.as_ref().map(|r| r.0),
                exempt: refined.as_ref().map(|r| r.1.as_slice()),
                note: tri
                    .is_degenerate()
                    .then_some("no triangles: fewer than 3 distinct points, or all collinear"),
                verified: args.output.verify.then_some(true),
            };
            serde_json::to_string(&json)
                .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?
        }
        Some(format) => write_shape(&triangles_shape(&tri), format)?,
    };
    if let Some(svg) = &args.output.svg {
        let title = match &refined {
            Some((steiner, _)) => format!(
                "refined constrained Delaunay mesh: {} vertices ({steiner} Steiner), {} triangles",
                tri.vertices().len(),
                tri.triangles().len()
            ),
            None => format!(
                "Delaunay triangulation ({}): n = {}, {} triangles",
                args.algorithm.name(),
                tri.vertices().len(),
                tri.triangles().len()
            ),
        };
        let mut picture = delaunay_picture(&tri, &title, args.circumcircles);
        if let Some(c) = &constraints {
            add_constraints(&mut picture, &tri, c);
        }
        output::write_atomic(svg, picture.to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

/// The triangles as polygons.
pub fn triangle_polygons(tri: &Triangulation) -> Vec<Polygon> {
    let v = tri.vertices();
    tri.triangles()
        .iter()
        .map(|t| Polygon::new(t.iter().map(|&i| v[i as usize]).collect(), Vec::new()))
        .collect()
}

/// The triangles as an output multipolygon (empty when there are none).
pub fn triangles_shape(tri: &Triangulation) -> Shape {
    if tri.is_degenerate() {
        Shape::MultiPoint(tri.vertices().to_vec())
    } else {
        Shape::MultiPolygon(MultiPolygon(triangle_polygons(tri)))
    }
}

/// The constrained edges, drawn over the triangulation.
pub fn add_constraints(pic: &mut Picture, tri: &Triangulation, constraints: &[(u32, u32)]) {
    let v = tri.vertices();
    let segs: Vec<compgeom::Segment2> = constraints
        .iter()
        .map(|&(a, b)| compgeom::Segment2::new(v[a as usize], v[b as usize]))
        .collect();
    pic.add(
        Layer::new(
            format!("constrained edges ({})", segs.len()),
            Style::lines("#2ca02c").with_stroke_width(2.0),
        )
        .segments(&segs),
    );
}

/// A circle as a 64-gon (drawing only).
fn circle_ring(c: Point2, r: f64) -> Vec<Point2> {
    (0..64)
        .map(|k| {
            let a = k as f64 * std::f64::consts::TAU / 64.0;
            Point2::new(c.x + r * a.cos(), c.y + r * a.sin())
        })
        .collect()
}

/// Triangles, vertices, and the circumcircles of the first `circles` triangles.
pub fn delaunay_picture(tri: &Triangulation, title: &str, circles: usize) -> Picture {
    let mut pic = Picture::new(800, 640).with_title(title);
    let v = tri.vertices();
    let edges: Vec<compgeom::Segment2> = tri
        .edges()
        .iter()
        .map(|&(a, b)| compgeom::Segment2::new(v[a as usize], v[b as usize]))
        .collect();
    pic.add(
        Layer::new(
            format!("Delaunay edges ({})", edges.len()),
            Style::lines("#1f77b4").with_stroke_width(0.8),
        )
        .segments(&edges),
    );
    let k = circles.min(tri.triangles().len());
    if k > 0 {
        let mut layer = Layer::new(
            format!("circumcircles of {k} triangles (empty of vertices)"),
            Style::lines("#ff7f0e").with_dash("4 3"),
        );
        // Spread the chosen triangles over the list.
        let step = tri.triangles().len() / k;
        for i in 0..k {
            let t = i * step.max(1);
            let c = tri.circumcenter(t);
            let p = v[tri.triangles()[t][0] as usize];
            let r = ((p.x - c.x).powi(2) + (p.y - c.y).powi(2)).sqrt();
            layer = layer.ring(&circle_ring(c, r));
        }
        pic.add(layer);
    }
    let radius = if v.len() > 10_000 { 1.0 } else { 2.5 };
    pic.add(
        Layer::new(
            format!("vertices ({})", v.len()),
            Style::points("#d62728").with_radius(radius),
        )
        .points(v),
    );
    pic
}
