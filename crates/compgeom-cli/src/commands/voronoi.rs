//! `compgeom voronoi`: the Voronoi diagram of points (book chapter 7), via
//! `compgeom::voronoi` (Fortune's sweep), with cells clipped to a rectangle or a convex
//! polygon.

use crate::cli::{InputArgs, OutputArgs};
use crate::error::CliError;
use crate::output;
use crate::progress::{Spinner, LARGE_INPUT};
use clap::{Args, ValueEnum};
use compgeom::io::{read_polygons, read_text, write_shape, Format, Shape};
use compgeom::render::{Layer, Picture, Style};
use compgeom::voronoi::{
    clip_cells, verify_cells, verify_voronoi, voronoi_diagram, ClipRegion, VoronoiAlgorithm,
    VoronoiDiagram,
};
use compgeom::{MultiPolygon, Point2, Polygon};
use serde::Serialize;
use serde_json::json;
use std::path::PathBuf;

/// `--help` text describing the JSON output.
pub const JSON_HELP: &str = "\
JSON output (--format json, the default) is one object:
  cells          [{\"site\": i, \"polygon\": [[x, y], ...]}, ...]  one per distinct input point,
                 in input order; i is the input index of its first occurrence; the polygon is
                 the cell clipped to the clip region, a counter-clockwise ring without a
                 repeated closing vertex ([] when the cell misses the region)
  input_to_cell  [c, ...]  for each input point, the index in \"cells\" of its cell
                 (duplicate points share a cell)
  vertices       [[x, y], ...]  Voronoi vertices (rounded; each is the centre of an empty
                 circle through three or more sites)
  vertex_sites   [[i, j, k, ...], ...]  for each vertex, the input indices of the sites on its
                 circle (more than three for cocircular sites)
  edges          [{\"sites\": [i, j], \"vertices\": [u, v]}, ...]  Voronoi edges: the bisector
                 of sites i and j (input indices), from vertex u to vertex v (indices into
                 \"vertices\", null at infinity); site i is on the left going from u to v
  clip           [[x, y], ...]  the clip region, counter-clockwise
  algorithm      \"default\" | \"fortune\"
  input_points   number of points read (duplicates included)
  verified       true; present only with --verify (a failed check exits 1 instead)

--format geojson prints a FeatureCollection with one Polygon feature per non-empty cell
(property \"site\"); csv and wkt print the cells as a multipolygon.

Without --clip or --clip-polygon the cells are clipped to the points' bounding box enlarged
by 10% on every side.

Examples:
  compgeom voronoi points.csv --clip 0,0,100,100 --svg voronoi.svg --verify
  compgeom voronoi points.csv --clip-polygon region.wkt --format geojson";

/// Arguments of `compgeom voronoi`.
#[derive(Debug, Clone, Args)]
pub struct VoronoiArgs {
    /// Input and its format.
    #[command(flatten)]
    pub input: InputArgs,

    /// Output, picture and verification.
    #[command(flatten)]
    pub output: OutputArgs,

    /// Algorithm: `default` (fastest exact; currently Fortune's sweep) or `fortune` (the
    /// book's VORONOIDIAGRAM, O(n log n)).
    #[arg(long, value_enum, default_value_t = VoronoiAlgorithmArg::Default)]
    pub algorithm: VoronoiAlgorithmArg,

    /// Clip the cells to the rectangle `xmin,ymin,xmax,ymax`.
    #[arg(
        long,
        value_name = "XMIN,YMIN,XMAX,YMAX",
        conflicts_with = "clip_polygon"
    )]
    pub clip: Option<String>,

    /// Clip the cells to the convex polygon in this file (WKT, GeoJSON or CSV ring).
    #[arg(long, value_name = "POLY")]
    pub clip_polygon: Option<PathBuf>,
}

/// The `--algorithm` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum VoronoiAlgorithmArg {
    /// The fastest exact method.
    Default,
    /// Fortune's sweep, the book's VORONOIDIAGRAM.
    Fortune,
}

impl VoronoiAlgorithmArg {
    /// The name printed in JSON output and titles.
    pub fn name(self) -> &'static str {
        match self {
            VoronoiAlgorithmArg::Default => "default",
            VoronoiAlgorithmArg::Fortune => "fortune",
        }
    }

    /// The library's algorithm.
    pub fn algorithm(self) -> VoronoiAlgorithm {
        match self {
            VoronoiAlgorithmArg::Default => VoronoiAlgorithm::Default,
            VoronoiAlgorithmArg::Fortune => VoronoiAlgorithm::Fortune,
        }
    }
}

/// Parse `xmin,ymin,xmax,ymax`.
pub fn parse_rect(text: &str) -> Result<ClipRegion, CliError> {
    let v: Vec<f64> = text
        .split(',')
        .map(|s| s.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|e| CliError::bad_input(format!("--clip {text}: {e}")))?;
    if v.len() != 4 {
        return Err(CliError::bad_input(format!(
            "--clip {text}: expected xmin,ymin,xmax,ymax"
        )));
    }
    Ok(ClipRegion::rect(v[0], v[1], v[2], v[3])?)
}

/// Read the clip polygon file: exactly one polygon without holes, convex.
fn read_clip_polygon(path: &std::path::Path) -> Result<ClipRegion, CliError> {
    let text = read_text(path)?;
    let name = path.display().to_string();
    let format = compgeom::io::detect_format(Some(path), &text)?;
    let mp = read_polygons(&text, format, &name)?;
    match mp.0.as_slice() {
        [p] if p.holes.is_empty() => Ok(ClipRegion::convex_polygon(&p.exterior)
            .map_err(|e| CliError::bad_input(format!("{name}: {e}")))?),
        _ => Err(CliError::bad_input(format!(
            "{name}: the clip polygon must be one polygon without holes"
        ))),
    }
}

#[derive(Serialize)]
struct CellJson {
    site: usize,
    polygon: Vec<[f64; 2]>,
}

#[derive(Serialize)]
struct EdgeJson {
    sites: [usize; 2],
    vertices: [Option<usize>; 2],
}

#[derive(Serialize)]
struct VoronoiJson {
    cells: Vec<CellJson>,
    input_to_cell: Vec<usize>,
    vertices: Vec<[f64; 2]>,
    vertex_sites: Vec<Vec<usize>>,
    edges: Vec<EdgeJson>,
    clip: Vec<[f64; 2]>,
    algorithm: &'static str,
    input_points: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    verified: Option<bool>,
}

fn xy(p: &Point2) -> [f64; 2] {
    [p.x, p.y]
}

/// The JSON object for a diagram and its clipped cells.
fn to_json(
    d: &VoronoiDiagram,
    cells: &[Vec<Point2>],
    region: &ClipRegion,
    algorithm: VoronoiAlgorithmArg,
    verified: bool,
) -> VoronoiJson {
    let input = |s: usize| d.site_input_index[s];
    VoronoiJson {
        cells: cells
            .iter()
            .enumerate()
            .map(|(s, c)| CellJson {
                site: input(s),
                polygon: c.iter().map(xy).collect(),
            })
            .collect(),
        input_to_cell: d.input_to_site.clone(),
        vertices: d.vertices.iter().map(|v| xy(&v.point)).collect(),
        vertex_sites: d
            .vertices
            .iter()
            .map(|v| v.sites.iter().map(|&s| input(s)).collect())
            .collect(),
        edges: (0..d.edge_count())
            .map(|k| {
                let h = 2 * k;
                let e = &d.half_edges[h];
                EdgeJson {
                    sites: [input(e.site), input(d.half_edges[e.twin].site)],
                    vertices: [e.origin, d.destination(h)],
                }
            })
            .collect(),
        clip: region.ring().iter().map(xy).collect(),
        algorithm: algorithm.name(),
        input_points: d.input_to_site.len(),
        verified: verified.then_some(true),
    }
}

/// The cells as a GeoJSON FeatureCollection (RFC 7946: exterior rings counter-clockwise,
/// closed).
fn to_geojson(d: &VoronoiDiagram, cells: &[Vec<Point2>]) -> serde_json::Value {
    let features: Vec<serde_json::Value> = cells
        .iter()
        .enumerate()
        .filter(|(_, c)| !c.is_empty())
        .map(|(s, c)| {
            let mut ring: Vec<[f64; 2]> = c.iter().map(xy).collect();
            ring.push(xy(&c[0]));
            json!({
                "type": "Feature",
                "properties": {"site": d.site_input_index[s]},
                "geometry": {"type": "Polygon", "coordinates": [ring]},
            })
        })
        .collect();
    json!({"type": "FeatureCollection", "features": features})
}

/// Run `compgeom voronoi`.
pub fn run(args: &VoronoiArgs) -> Result<(), CliError> {
    let points = {
        let _spin = Spinner::start("reading points", false);
        args.input.read_points()?
    };
    let region = match (&args.clip, &args.clip_polygon) {
        (Some(r), _) => Some(parse_rect(r)?),
        (None, Some(p)) => Some(read_clip_polygon(p)?),
        (None, None) => None,
    };
    let big = points.len() >= LARGE_INPUT;
    let d = {
        let _spin = Spinner::start("computing the Voronoi diagram", big);
        voronoi_diagram(&points, args.algorithm.algorithm())?
    };
    let region = match region {
        Some(r) => r,
        None if points.is_empty() => ClipRegion::rect(0.0, 0.0, 1.0, 1.0)?,
        None => ClipRegion::around(&d.sites, 0.1)?,
    };
    let cells = clip_cells(&d, &region);
    if args.output.verify {
        let _spin = Spinner::start("verifying", big);
        verify_voronoi(&points, &d)?;
        verify_cells(&d, &region, &cells)?;
    }
    let text = match args.output.format.geometry_format() {
        None => serde_json::to_string(&to_json(
            &d,
            &cells,
            &region,
            args.algorithm,
            args.output.verify,
        ))
        .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?,
        Some(Format::GeoJson) => to_geojson(&d, &cells).to_string(),
        Some(format) => write_shape(&cells_shape(&cells), format)?,
    };
    if let Some(svg) = &args.output.svg {
        let title = format!(
            "Voronoi diagram ({}): n = {}, {} vertices, {} edges",
            args.algorithm.name(),
            d.sites.len(),
            d.vertices.len(),
            d.edge_count()
        );
        let picture = voronoi_picture(&d, &cells, &region, &title);
        output::write_atomic(svg, picture.to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

/// The non-empty cells as one multipolygon.
pub fn cells_shape(cells: &[Vec<Point2>]) -> Shape {
    Shape::MultiPolygon(MultiPolygon(
        cells
            .iter()
            .filter(|c| !c.is_empty())
            .map(|c| Polygon::new(c.clone(), Vec::new()))
            .collect(),
    ))
}

/// Cell colours (cycled).
const PALETTE: [&str; 8] = [
    "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#17becf",
];

/// Cells coloured, the clip region, the sites and the Voronoi vertices.
pub fn voronoi_picture(
    d: &VoronoiDiagram,
    cells: &[Vec<Point2>],
    region: &ClipRegion,
    title: &str,
) -> Picture {
    let mut pic = Picture::new(800, 640).with_title(title);
    for (k, color) in PALETTE.iter().enumerate() {
        let mut layer = Layer::new(
            if k == 0 {
                "Voronoi cells (coloured)".to_string()
            } else {
                String::new()
            },
            Style::area(color).with_fill_opacity(0.25),
        );
        for c in cells.iter().skip(k).step_by(PALETTE.len()) {
            if !c.is_empty() {
                layer = layer.ring(c);
            }
        }
        pic.add(layer);
    }
    pic.add(Layer::new("clip region", Style::lines("#333333")).ring(region.ring()));
    let radius = if d.sites.len() > 10_000 { 1.0 } else { 2.5 };
    pic.add(
        Layer::new(
            format!("sites ({})", d.sites.len()),
            Style::points("#000000").with_radius(radius),
        )
        .points(&d.sites),
    );
    // Only the vertices inside the clip region (far-away ones would shrink the picture).
    let bbox = compgeom::Bbox2::of_points(region.ring());
    let vs: Vec<Point2> = d
        .vertices
        .iter()
        .map(|v| v.point)
        .filter(|p| bbox.contains(*p))
        .collect();
    pic.add(
        Layer::new(
            format!("Voronoi vertices in the region ({})", vs.len()),
            Style::points("#d62728").with_radius(radius * 0.8),
        )
        .points(&vs),
    );
    pic
}
