//! `compgeom voronoi`: the Voronoi diagram of points (book chapter 7), via
//! `compgeom::voronoi` (the dual of the Delaunay triangulation by default, Fortune's sweep
//! on request), or the farthest-point diagram, with cells clipped to a rectangle or to any
//! polygon.

use crate::cli::{InputArgs, OutputArgs};
use crate::error::CliError;
use crate::output;
use crate::progress::{Spinner, LARGE_INPUT};
use clap::{Args, ValueEnum};
use compgeom::io::{read_polygons, read_text, write_shape, Format, Shape};
use compgeom::render::{Layer, Picture, Style};
use compgeom::voronoi::clip::ring_area;
use compgeom::voronoi::{
    clip_cells, clip_cells_to_polygon, farthest_point_voronoi, verify_cells, verify_farthest,
    verify_polygon_cells, verify_voronoi, voronoi_diagram, ClipRegion, FarthestVoronoi,
    VoronoiAlgorithm, VoronoiDiagram,
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
                 repeated closing vertex ([] when the cell misses the region). When a
                 non-convex --clip-polygon cuts a cell into several pieces (or a hole of it
                 lies in the cell), \"polygon\" is the largest piece's outer ring and
                 \"parts\": [[ring, hole, ...], ...] lists every piece (holes clockwise)
  input_to_cell  [c, ...]  for each input point, the index in \"cells\" of its cell
                 (duplicate points share a cell)
  vertices       [[x, y], ...]  Voronoi vertices (rounded; each is the centre of an empty
                 circle through three or more sites; with --farthest, of a circle through
                 three or more sites that contains all sites)
  vertex_sites   [[i, j, k, ...], ...]  for each vertex, the input indices of the sites on its
                 circle (more than three for cocircular sites)
  edges          [{\"sites\": [i, j], \"vertices\": [u, v]}, ...]  Voronoi edges: the bisector
                 of sites i and j (input indices), from vertex u to vertex v (indices into
                 \"vertices\", null at infinity); site i is on the left going from u to v
  clip           [[x, y], ...]  the clip region, counter-clockwise (for --clip-polygon: the
                 first ring read)
  algorithm      \"default\" | \"fortune\" | \"farthest\"
  input_points   number of points read (duplicates included)
  verified       true; present only with --verify (a failed check exits 1 instead)

--format geojson prints a FeatureCollection with one Polygon feature per non-empty cell
(property \"site\"); csv and wkt print the cells as a multipolygon.

Without --clip or --clip-polygon the cells are clipped to the points' bounding box enlarged
by 10% on every side. --clip-polygon takes any polygons (non-convex, with holes, several;
read even-odd); a cell cut into pieces is a MultiPolygon feature in GeoJSON.

--farthest computes the farthest-point Voronoi diagram instead: the cell of a site holds the
points for which it is the farthest site; only the corners of the convex hull have cells
(the other sites get []).

Examples:
  compgeom voronoi points.csv --clip 0,0,100,100 --svg voronoi.svg --verify
  compgeom voronoi points.csv --clip-polygon region.wkt --format geojson
  compgeom voronoi points.csv --farthest --svg farthest.svg";

/// Arguments of `compgeom voronoi`.
#[derive(Debug, Clone, Args)]
pub struct VoronoiArgs {
    /// Input and its format.
    #[command(flatten)]
    pub input: InputArgs,

    /// Output, picture and verification.
    #[command(flatten)]
    pub output: OutputArgs,

    /// Algorithm: `default` (fastest exact: the dual of the Delaunay triangulation) or
    /// `fortune` (the book's VORONOIDIAGRAM, O(n log n)).
    #[arg(long, value_enum, default_value_t = VoronoiAlgorithmArg::Default)]
    pub algorithm: VoronoiAlgorithmArg,

    /// Clip the cells to the rectangle `xmin,ymin,xmax,ymax`.
    #[arg(
        long,
        value_name = "XMIN,YMIN,XMAX,YMAX",
        conflicts_with = "clip_polygon"
    )]
    pub clip: Option<String>,

    /// Clip the cells to the polygon(s) in this file (WKT, GeoJSON or CSV ring; any
    /// polygon: non-convex, with holes).
    #[arg(long, value_name = "POLY")]
    pub clip_polygon: Option<PathBuf>,

    /// The farthest-point Voronoi diagram (each site's cell holds the points farthest from
    /// it); `--algorithm` is then ignored.
    #[arg(long)]
    pub farthest: bool,
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

/// Where the cells are clipped.
enum Clip {
    /// A rectangle or a convex polygon (the fast path).
    Convex(ClipRegion),
    /// Any polygon set, read even-odd.
    Polygon(MultiPolygon),
}

impl Clip {
    /// The rings to draw.
    fn rings(&self) -> Vec<Vec<Point2>> {
        match self {
            Clip::Convex(r) => vec![r.ring().to_vec()],
            Clip::Polygon(m) => m.0.iter().flat_map(|p| p.rings().cloned()).collect(),
        }
    }
}

/// Read the clip polygon file: one convex polygon without holes takes the fast path; any
/// other polygon set the general one.
fn read_clip_polygon(path: &std::path::Path) -> Result<Clip, CliError> {
    let text = read_text(path)?;
    let name = path.display().to_string();
    let format = compgeom::io::detect_format(Some(path), &text)?;
    let mp = read_polygons(&text, format, &name)?;
    if mp.0.is_empty() {
        return Err(CliError::bad_input(format!("{name}: no clip polygon")));
    }
    if let [p] = mp.0.as_slice() {
        if p.holes.is_empty() {
            if let Ok(r) = ClipRegion::convex_polygon(&p.exterior) {
                return Ok(Clip::Convex(r));
            }
        }
    }
    Ok(Clip::Polygon(mp))
}

#[derive(Serialize)]
struct CellJson {
    site: usize,
    polygon: Vec<[f64; 2]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    parts: Option<Vec<Vec<Vec<[f64; 2]>>>>,
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

/// The largest piece's outer ring (by area), or nothing.
fn main_ring(cell: &MultiPolygon) -> Vec<Point2> {
    cell.0
        .iter()
        .max_by(|a, b| ring_area(&a.exterior).total_cmp(&ring_area(&b.exterior)))
        .map(|p| p.exterior.clone())
        .unwrap_or_default()
}

/// The JSON object for a diagram and its clipped cells.
fn to_json(
    d: &VoronoiDiagram,
    cells: &[MultiPolygon],
    clip: &Clip,
    algorithm: &'static str,
    verified: bool,
) -> VoronoiJson {
    let input = |s: usize| d.site_input_index[s];
    let ring = |r: &[Point2]| r.iter().map(xy).collect::<Vec<_>>();
    VoronoiJson {
        cells: cells
            .iter()
            .enumerate()
            .map(|(s, c)| {
                let simple = c.0.len() <= 1 && c.0.iter().all(|p| p.holes.is_empty());
                CellJson {
                    site: input(s),
                    polygon: ring(&main_ring(c)),
                    parts: (!simple).then(|| {
                        c.0.iter()
                            .map(|p| p.rings().map(|r| ring(r)).collect())
                            .collect()
                    }),
                }
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
        clip: clip.rings().first().map(|r| ring(r)).unwrap_or_default(),
        algorithm,
        input_points: d.input_to_site.len(),
        verified: verified.then_some(true),
    }
}

/// The cells as a GeoJSON FeatureCollection (RFC 7946: exterior rings counter-clockwise,
/// holes clockwise, closed): a Polygon per cell in one piece, a MultiPolygon otherwise.
fn to_geojson(d: &VoronoiDiagram, cells: &[MultiPolygon]) -> serde_json::Value {
    let closed = |r: &Vec<Point2>| {
        let mut v: Vec<[f64; 2]> = r.iter().map(xy).collect();
        if let Some(&f) = v.first() {
            v.push(f);
        }
        v
    };
    let poly = |p: &Polygon| p.rings().map(closed).collect::<Vec<_>>();
    let features: Vec<serde_json::Value> = cells
        .iter()
        .enumerate()
        .filter(|(_, c)| !c.0.is_empty())
        .map(|(s, c)| {
            let geometry = match c.0.as_slice() {
                [p] => json!({"type": "Polygon", "coordinates": poly(p)}),
                ps => json!({
                    "type": "MultiPolygon",
                    "coordinates": ps.iter().map(poly).collect::<Vec<_>>(),
                }),
            };
            json!({
                "type": "Feature",
                "properties": {"site": d.site_input_index[s]},
                "geometry": geometry,
            })
        })
        .collect();
    json!({"type": "FeatureCollection", "features": features})
}

/// The farthest-point diagram in the nearest-site diagram's record, for output only.
fn as_diagram(f: FarthestVoronoi) -> VoronoiDiagram {
    VoronoiDiagram {
        sites: f.sites,
        site_input_index: f.site_input_index,
        input_to_site: f.input_to_site,
        vertices: f.vertices,
        half_edges: f.half_edges,
        site_half_edge: f.site_half_edge,
    }
}

/// Rings as one-piece cells.
fn whole(rings: Vec<Vec<Point2>>) -> Vec<MultiPolygon> {
    rings
        .into_iter()
        .map(|r| {
            if r.is_empty() {
                MultiPolygon::default()
            } else {
                MultiPolygon(vec![Polygon::new(r, Vec::new())])
            }
        })
        .collect()
}

/// Run `compgeom voronoi`.
pub fn run(args: &VoronoiArgs) -> Result<(), CliError> {
    let points = {
        let _spin = Spinner::start("reading points", false);
        args.input.read_points()?
    };
    let clip = match (&args.clip, &args.clip_polygon) {
        (Some(r), _) => Some(Clip::Convex(parse_rect(r)?)),
        (None, Some(p)) => Some(read_clip_polygon(p)?),
        (None, None) => None,
    };
    let big = points.len() >= LARGE_INPUT;
    let verify = args.output.verify;
    let (d, cells, clip, algorithm) = if args.farthest {
        let f = {
            let _spin = Spinner::start("computing the farthest-point Voronoi diagram", big);
            farthest_point_voronoi(&points)?
        };
        let clip = default_clip(clip, &f.sites)?;
        let cells = match &clip {
            Clip::Convex(r) => whole(f.cells(r)),
            Clip::Polygon(m) => f.cells_in_polygon(m)?,
        };
        if verify {
            let _spin = Spinner::start("verifying", big);
            verify_farthest(&points, &f)?;
        }
        (as_diagram(f), cells, clip, "farthest")
    } else {
        let d = {
            let _spin = Spinner::start("computing the Voronoi diagram", big);
            voronoi_diagram(&points, args.algorithm.algorithm())?
        };
        let clip = default_clip(clip, &d.sites)?;
        let cells = match &clip {
            Clip::Convex(r) => {
                let rings = clip_cells(&d, r);
                if verify {
                    verify_cells(&d, r, &rings)?;
                }
                whole(rings)
            }
            Clip::Polygon(m) => {
                let cells = {
                    let _spin = Spinner::start("clipping the cells", big);
                    clip_cells_to_polygon(&d, m)?
                };
                if verify {
                    verify_polygon_cells(&d, m, &cells)?;
                }
                cells
            }
        };
        if verify {
            let _spin = Spinner::start("verifying", big);
            verify_voronoi(&points, &d)?;
        }
        (d, cells, clip, args.algorithm.name())
    };
    let text = match args.output.format().geometry_format() {
        None => serde_json::to_string(&to_json(&d, &cells, &clip, algorithm, verify))
            .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?,
        Some(Format::GeoJson) => to_geojson(&d, &cells).to_string(),
        Some(format) => write_shape(&cells_shape(&cells), format)?,
    };
    if let Some(svg) = &args.output.svg {
        let kind = if args.farthest {
            "Farthest-point Voronoi diagram".to_string()
        } else {
            format!("Voronoi diagram ({algorithm})")
        };
        let title = format!(
            "{kind}: n = {}, {} vertices, {} edges",
            d.sites.len(),
            d.vertices.len(),
            d.edge_count()
        );
        let picture = voronoi_picture(&d, &cells, &clip.rings(), &title);
        output::write_atomic(svg, picture.to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

/// The clip region given, or the sites' bounding box enlarged by 10% (the unit square
/// without sites).
fn default_clip(clip: Option<Clip>, sites: &[Point2]) -> Result<Clip, CliError> {
    Ok(match clip {
        Some(c) => c,
        None if sites.is_empty() => Clip::Convex(ClipRegion::rect(0.0, 0.0, 1.0, 1.0)?),
        None => Clip::Convex(ClipRegion::around(sites, 0.1)?),
    })
}

/// The non-empty cells (all their pieces) as one multipolygon.
pub fn cells_shape(cells: &[MultiPolygon]) -> Shape {
    Shape::MultiPolygon(MultiPolygon(
        cells.iter().flat_map(|c| c.0.iter().cloned()).collect(),
    ))
}

/// Cell colours (cycled).
const PALETTE: [&str; 8] = [
    "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#17becf",
];

/// Cells coloured, the clip region's rings, the sites and the Voronoi vertices.
pub fn voronoi_picture(
    d: &VoronoiDiagram,
    cells: &[MultiPolygon],
    clip: &[Vec<Point2>],
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
            for r in c.0.iter().flat_map(|p| p.rings()) {
                layer = layer.ring(r);
            }
        }
        pic.add(layer);
    }
    let mut outline = Layer::new("clip region", Style::lines("#333333"));
    for r in clip {
        outline = outline.ring(r);
    }
    pic.add(outline);
    let radius = if d.sites.len() > 10_000 { 1.0 } else { 2.5 };
    pic.add(
        Layer::new(
            format!("sites ({})", d.sites.len()),
            Style::points("#000000").with_radius(radius),
        )
        .points(&d.sites),
    );
    // Only the vertices inside the clip region's box (far-away ones would shrink the
    // picture).
    let bbox = compgeom::Bbox2::of_points(clip.iter().flatten());
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
