//! `compgeom triangulate`: triangulation of polygons with holes (book chapter 3) via
//! `compgeom::triangulate::triangulate`, optionally with the monotone pieces of
//! MAKEMONOTONE.

use crate::cli::{InputArgs, OutputArgs, OutputFormat};
use crate::commands::boolean::read_layer;
use crate::error::CliError;
use crate::output;
use clap::Args;
use compgeom::io::{read_polygons, read_segments, write_shape, Shape};
use compgeom::render::{Layer, Picture, Style};
use compgeom::triangulate::{
    monotone_partition, triangulate, triangulate_subdivision, verify_subdivision_triangulation,
    verify_triangulation, MonotonePartition, Triangulation, VertexType,
};
use compgeom::{MultiPolygon, Point2, Polygon, Segment2};
use serde_json::{json, Value};

/// `--help` text describing the JSON output.
pub const JSON_HELP: &str = "\
JSON output (--format json, the default) is one object:
  vertices   [[x, y], ...]: the input ring vertices in input order, outer ring first, then
             each hole, polygon after polygon (repeated consecutive vertices and closing
             copies dropped; a point where rings touch is listed once per ring visit)
  triangles  [[i, j, k], ...]: counter-clockwise triangles, indices into `vertices`;
             n - 2 + 2h per polygon with n vertices and h holes
  diagonals  [[i, j], ...]: the triangle edges that are not polygon edges (i < j)
  pieces     [[i, ...], ...]: with --monotone-pieces, the y-monotone pieces of the
             MAKEMONOTONE sweep (counter-clockwise index cycles)
  verified   true; present only with --verify (checked exactly: counter-clockwise
             triangles tiling the polygon, every edge a polygon edge or a diagonal)

--format geojson / wkt prints the triangles as a MultiPolygon. A self-intersecting
polygon is an error naming the two edges and the point.

With --subdivision, INPUT is a polygon layer (polygons may share edges and overlap) or
segments (touching, not crossing), and every face of the subdivision they form is
triangulated inside its bounding box grown by --box MARGIN (default 0), the unbounded
face too (book Theorem 3.9). JSON: vertices (the subdivision's, then box corners),
triangles (counter-clockwise), faces (per triangle, the face of the subdivision, 0 =
unbounded), labels (polygon input only: per triangle the polygons containing it),
boundary (the box's vertices, counter-clockwise), verified (with --verify).

Examples:
  compgeom triangulate gallery.wkt --svg gallery.svg --verify
  compgeom triangulate map.geojson --monotone-pieces --svg pieces.svg
  compgeom triangulate parcels.geojson --subdivision --box 10 --svg parcels.svg";

/// Arguments of `compgeom triangulate`.
#[derive(Debug, Clone, Args)]
pub struct TriangulateArgs {
    /// Input polygons (Polygon / MultiPolygon, holes allowed) and their format.
    #[command(flatten)]
    pub input: InputArgs,

    /// Also report (and draw) the monotone pieces of the MAKEMONOTONE sweep.
    #[arg(long)]
    pub monotone_pieces: bool,

    /// Triangulate every face of the subdivision formed by the input (a polygon layer or
    /// segments) inside its bounding box, the unbounded face included.
    #[arg(long)]
    pub subdivision: bool,

    /// With --subdivision: grow the bounding box by MARGIN on every side (default 0).
    #[arg(long = "box", value_name = "MARGIN", requires = "subdivision")]
    pub box_margin: Option<f64>,

    /// Output, picture and verification.
    #[command(flatten)]
    pub output: OutputArgs,
}

/// Every polygon triangulated, with the vertex offset of each in the joint vertex list.
pub struct Triangulated {
    /// The input polygons.
    pub polygons: MultiPolygon,
    /// One triangulation per polygon.
    pub parts: Vec<Triangulation>,
    /// Joint vertex list.
    pub vertices: Vec<Point2>,
    /// Joint triangles (indices into `vertices`).
    pub triangles: Vec<[usize; 3]>,
    /// Joint diagonals.
    pub diagonals: Vec<[usize; 2]>,
}

/// Triangulate every polygon (errors name the polygon).
pub fn triangulate_all(polygons: MultiPolygon, verify: bool) -> Result<Triangulated, CliError> {
    let mut out = Triangulated {
        polygons: MultiPolygon(Vec::new()),
        parts: Vec::new(),
        vertices: Vec::new(),
        triangles: Vec::new(),
        diagonals: Vec::new(),
    };
    let many = polygons.0.len() > 1;
    for (i, p) in polygons.0.iter().enumerate() {
        let name = |e: compgeom::Error| -> CliError {
            let mut c = CliError::from(e);
            if many {
                c.message = format!("polygon {i}: {}", c.message);
            }
            c
        };
        let t = triangulate(p).map_err(name)?;
        if verify {
            verify_triangulation(p, &t).map_err(name)?;
        }
        let off = out.vertices.len();
        out.vertices.extend_from_slice(&t.vertices);
        out.triangles
            .extend(t.triangles.iter().map(|tri| tri.map(|v| v + off)));
        out.diagonals
            .extend(t.diagonals().into_iter().map(|d| d.map(|v| v + off)));
        out.parts.push(t);
    }
    out.polygons = polygons;
    Ok(out)
}

/// The monotone pieces of every polygon, with indices into the joint vertex list.
pub fn pieces_of(
    polygons: &MultiPolygon,
) -> Result<(Vec<MonotonePartition>, Vec<Vec<usize>>), CliError> {
    let mut parts = Vec::new();
    let mut pieces = Vec::new();
    let mut off = 0;
    for p in &polygons.0 {
        let m = monotone_partition(p)?;
        pieces.extend(m.pieces.iter().map(|c| c.iter().map(|v| v + off).collect()));
        off += m.vertices.len();
        parts.push(m);
    }
    Ok((parts, pieces))
}

/// Run `compgeom triangulate`.
pub fn run(args: &TriangulateArgs) -> Result<(), CliError> {
    if args.subdivision {
        return run_subdivision(args);
    }
    let polygons = read_layer(&args.input)?;
    let t = triangulate_all(polygons, args.output.verify)?;
    let pieces = if args.monotone_pieces {
        Some(pieces_of(&t.polygons)?)
    } else {
        None
    };
    let text = match args.output.format() {
        OutputFormat::Json => {
            let mut v = json!({
                "vertices": t.vertices.iter().map(|p| [p.x, p.y]).collect::<Vec<_>>(),
                "triangles": t.triangles,
                "diagonals": t.diagonals,
            });
            if let Some((_, pieces)) = &pieces {
                v["pieces"] = json!(pieces);
            }
            if args.output.verify {
                v["verified"] = json!(true);
            }
            serde_json::to_string(&v)
                .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?
        }
        OutputFormat::Csv => {
            return Err(args
                .output
                .unsupported("triangulate", "json, geojson or wkt"))
        }
        other => {
            let tris = MultiPolygon(
                t.triangles
                    .iter()
                    .map(|tri| Polygon::new(tri.iter().map(|&v| t.vertices[v]).collect(), vec![]))
                    .collect(),
            );
            let format = other.geometry_format().unwrap_or(compgeom::io::Format::Wkt);
            write_shape(&Shape::MultiPolygon(tris), format)?
        }
    };
    if let Some(svg) = &args.output.svg {
        let title = format!(
            "triangulate: {} vertices, {} triangles",
            t.vertices.len(),
            t.triangles.len()
        );
        let pic = picture(&t, pieces.as_ref().map(|p| p.0.as_slice()), title);
        output::write_atomic(svg, pic.to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

/// Distinct fill colours for pieces.
pub const PALETTE: [&str; 8] = [
    "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#17becf",
];

/// The picture: monotone pieces (when given) in distinct colours with the vertex types,
/// else the triangles; the diagonals dashed; the polygon outlines.
pub fn picture(t: &Triangulated, parts: Option<&[MonotonePartition]>, title: String) -> Picture {
    let mut pic = Picture::new(800, 640).with_title(title);
    match parts {
        Some(parts) => {
            let mut k = 0;
            for m in parts {
                for piece in &m.pieces {
                    let ring: Vec<Point2> = piece.iter().map(|&v| m.vertices[v]).collect();
                    let style = Style::area(PALETTE[k % PALETTE.len()]).with_fill_opacity(0.35);
                    pic.add(Layer::new(format!("monotone piece {k}"), style).ring(&ring));
                    k += 1;
                }
            }
        }
        None => {
            let mut layer = Layer::new("triangles", Style::area("#9ecae1").with_fill_opacity(0.5));
            for tri in &t.triangles {
                let ring: Vec<Point2> = tri.iter().map(|&v| t.vertices[v]).collect();
                layer = layer.ring(&ring);
            }
            pic.add(layer);
        }
    }
    // With pieces: the sweep's diagonals; otherwise every diagonal of the triangulation.
    let diagonals: Vec<Segment2> = match parts {
        Some(parts) => parts
            .iter()
            .flat_map(|m| {
                m.diagonals
                    .iter()
                    .map(|&[a, b]| Segment2::new(m.vertices[a], m.vertices[b]))
            })
            .collect(),
        None => t
            .diagonals
            .iter()
            .map(|&[a, b]| Segment2::new(t.vertices[a], t.vertices[b]))
            .collect(),
    };
    pic.add(Layer::new("diagonals", Style::lines("#555555").with_dash("4 3")).segments(&diagonals));
    pic.add(
        Layer::new("polygon", Style::lines("#000000").with_stroke_width(2.0))
            .polygons(&t.polygons.0),
    );
    if let Some(parts) = parts {
        let kinds = [
            (VertexType::Start, "#2ca02c"),
            (VertexType::End, "#d62728"),
            (VertexType::Split, "#1f77b4"),
            (VertexType::Merge, "#ff7f0e"),
            (VertexType::Regular, "#7f7f7f"),
        ];
        for (kind, colour) in kinds {
            let pts: Vec<Point2> = parts
                .iter()
                .flat_map(|m| {
                    m.types
                        .iter()
                        .zip(&m.vertices)
                        .filter(|(ty, _)| **ty == kind)
                        .map(|(_, p)| *p)
                })
                .collect();
            if !pts.is_empty() {
                let name = format!("{} vertices", kind.name());
                pic.add(Layer::new(name, Style::points(colour).with_radius(4.0)).points(&pts));
            }
        }
    }
    pic
}

/// JSON of a point list.
pub fn points_json(points: &[Point2]) -> Value {
    json!(points.iter().map(|p| [p.x, p.y]).collect::<Vec<_>>())
}

/// `--subdivision`: every face of the subdivision formed by a polygon layer or segments,
/// inside the (grown) bounding box.
fn run_subdivision(args: &TriangulateArgs) -> Result<(), CliError> {
    if args.monotone_pieces {
        return Err(CliError::bad_input(
            "--monotone-pieces is not available with --subdivision",
        ));
    }
    let margin = args.box_margin.unwrap_or(0.0);
    let src = args.input.read()?;
    let (t, labels) = match read_polygons(&src.text, src.format, &src.name) {
        Ok(layer) => {
            let dcel = compgeom::dcel::Dcel::from_polygons(&layer)?;
            let t = triangulate_subdivision(&dcel, margin)?;
            if args.output.verify {
                verify_subdivision_triangulation(&dcel, &t)?;
            }
            let labels: Vec<Vec<usize>> =
                t.faces.iter().map(|&f| dcel.face(f).data.clone()).collect();
            (t, Some(labels))
        }
        Err(pe) => {
            let segs = read_segments(&src.text, src.format, &src.name).map_err(|_| pe)?;
            let dcel = compgeom::dcel::Dcel::from_segments(&segs)?;
            let t = triangulate_subdivision(&dcel, margin)?;
            if args.output.verify {
                verify_subdivision_triangulation(&dcel, &t)?;
            }
            (t, None)
        }
    };
    let text = match args.output.format() {
        OutputFormat::Json => {
            let mut v = json!({
                "vertices": t.vertices.iter().map(|p| [p.x, p.y]).collect::<Vec<_>>(),
                "triangles": t.triangles,
                "faces": t.faces.iter().map(|f| f.0).collect::<Vec<_>>(),
                "boundary": t.boundary,
            });
            if let Some(labels) = &labels {
                v["labels"] = json!(labels);
            }
            if args.output.verify {
                v["verified"] = json!(true);
            }
            serde_json::to_string(&v)
                .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?
        }
        OutputFormat::Csv => {
            return Err(args
                .output
                .unsupported("triangulate", "json, geojson or wkt"))
        }
        other => {
            let tris = MultiPolygon(
                t.triangles
                    .iter()
                    .map(|tri| Polygon::new(tri.iter().map(|&v| t.vertices[v]).collect(), vec![]))
                    .collect(),
            );
            let format = other.geometry_format().unwrap_or(compgeom::io::Format::Wkt);
            write_shape(&Shape::MultiPolygon(tris), format)?
        }
    };
    if let Some(svg) = &args.output.svg {
        let title = format!(
            "triangulate --subdivision: {} vertices, {} triangles",
            t.vertices.len(),
            t.triangles.len()
        );
        let mut pic = Picture::new(800, 640).with_title(title);
        // Triangles coloured by face (the unbounded face grey), subdivision edges on top.
        let mut layers: Vec<Option<Layer>> = Vec::new();
        for (tri, f) in t.triangles.iter().zip(&t.faces) {
            let k = f.0;
            if layers.len() <= k {
                layers.resize_with(k + 1, || None);
            }
            let layer = layers[k].take().unwrap_or_else(|| {
                let colour = if k == 0 {
                    "#dddddd"
                } else {
                    PALETTE[k % PALETTE.len()]
                };
                Layer::new(
                    format!("face {k}"),
                    Style::area(colour).with_fill_opacity(0.45),
                )
            });
            let ring: Vec<Point2> = tri.iter().map(|&v| t.vertices[v]).collect();
            layers[k] = Some(layer.ring(&ring));
        }
        for layer in layers.into_iter().flatten() {
            pic.add(layer);
        }
        let mut edges = Layer::new("subdivision edges", Style::lines("#000000"));
        for &[a, b] in &t.edges {
            edges = edges.segment(Segment2::new(t.vertices[a], t.vertices[b]));
        }
        pic.add(edges);
        output::write_atomic(svg, pic.to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}
