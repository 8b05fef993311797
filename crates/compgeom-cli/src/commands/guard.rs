//! `compgeom guard`: the art gallery (book §3.1) via `compgeom::triangulate::art_gallery`:
//! triangulate, 3-colour the vertices along the dual tree, and place guards at the
//! smallest colour class.

use crate::cli::{InputArgs, OutputArgs, OutputFormat};
use crate::commands::boolean::read_layer;
use crate::commands::triangulate::{points_json, triangulate_all, Triangulated};
use crate::error::CliError;
use crate::output;
use clap::Args;
use compgeom::io::{write_shape, Shape};
use compgeom::render::{Layer, Picture, Style};
use compgeom::triangulate::{art_gallery, verify_art_gallery, ArtGallery};
use compgeom::{Point2, Segment2};
use serde_json::json;

/// `--help` text describing the JSON output.
pub const JSON_HELP: &str = "\
JSON output (--format json, the default) is one object:
  guards     [[x, y], ...]: the guard vertices (the smallest colour class of each polygon;
             at most floor(n/3) for a polygon with n vertices and no holes)
  colors     [c0, c1, ...]: the colour (0, 1 or 2) of every vertex, in `vertices` order
  vertices   [[x, y], ...]: as in `compgeom triangulate`
  triangles  [[i, j, k], ...]: the triangulation the colouring follows
  verified   true; present only with --verify (every triangle has three colours and a
             guard; the guard bound holds)

With holes the dual graph is not a tree: the colouring follows a spanning tree of it
(cutting the polygon open along h diagonals), so every triangle still has three colours
and a guard, and there are at most floor((n + 2h)/3) guards, but a vertex may carry a
second colour on the other side of a cut (`colors` then gives the guard colour if it
carries it, else its first; the SVG rings such vertices). A polygon with holes need not
have a proper 3-colouring at all, and floor(n/3) guards need not suffice. Where rings
touch, a guard at the touching point is listed once. --format geojson / wkt prints the
guards as a MultiPoint.

Examples:
  compgeom guard gallery.wkt --svg guards.svg --verify";

/// Arguments of `compgeom guard`.
#[derive(Debug, Clone, Args)]
pub struct GuardArgs {
    /// Input polygons (Polygon / MultiPolygon, holes allowed) and their format.
    #[command(flatten)]
    pub input: InputArgs,

    /// Output, picture and verification.
    #[command(flatten)]
    pub output: OutputArgs,
}

/// Guards of every polygon, and the joint colours and guard points.
pub struct Guarded {
    /// One colouring per polygon.
    pub galleries: Vec<ArtGallery>,
    /// Joint colours.
    pub colors: Vec<u8>,
    /// Joint guard points.
    pub guards: Vec<Point2>,
}

/// Colour every triangulated polygon and pick its guards.
pub fn guard_all(t: &Triangulated, verify: bool) -> Result<Guarded, CliError> {
    let mut out = Guarded {
        galleries: Vec::new(),
        colors: Vec::new(),
        guards: Vec::new(),
    };
    for part in &t.parts {
        let g = art_gallery(part);
        if verify {
            verify_art_gallery(part, &g)?;
        }
        out.colors.extend_from_slice(&g.colors);
        out.guards
            .extend(g.guards.iter().map(|&v| part.vertices[v]));
        out.galleries.push(g);
    }
    Ok(out)
}

/// Run `compgeom guard`.
pub fn run(args: &GuardArgs) -> Result<(), CliError> {
    let polygons = read_layer(&args.input)?;
    let t = triangulate_all(polygons, args.output.verify)?;
    let g = guard_all(&t, args.output.verify)?;
    let text = match args.output.format() {
        OutputFormat::Json => {
            let mut v = json!({
                "guards": points_json(&g.guards),
                "colors": g.colors,
                "vertices": points_json(&t.vertices),
                "triangles": t.triangles,
            });
            if args.output.verify {
                v["verified"] = json!(true);
            }
            serde_json::to_string(&v)
                .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?
        }
        OutputFormat::Csv => return Err(args.output.unsupported("guard", "json, geojson or wkt")),
        other => {
            let format = other.geometry_format().unwrap_or(compgeom::io::Format::Wkt);
            write_shape(&Shape::MultiPoint(g.guards.clone()), format)?
        }
    };
    if let Some(svg) = &args.output.svg {
        let title = format!(
            "guard: {} vertices, {} guards",
            t.vertices.len(),
            g.guards.len()
        );
        output::write_atomic(svg, picture(&t, &g, title).to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

/// The three colours of the vertices.
pub const COLOURS: [&str; 3] = ["#d62728", "#2ca02c", "#1f77b4"];

/// The picture: triangles, diagonals, the polygon, the vertices in their three colours and
/// the guards as large rings.
pub fn picture(t: &Triangulated, g: &Guarded, title: String) -> Picture {
    let mut pic = Picture::new(800, 640).with_title(title);
    let mut layer = Layer::new("triangles", Style::area("#fdf6e3").with_fill_opacity(0.8));
    for tri in &t.triangles {
        let ring: Vec<Point2> = tri.iter().map(|&v| t.vertices[v]).collect();
        layer = layer.ring(&ring);
    }
    pic.add(layer);
    let diagonals: Vec<Segment2> = t
        .diagonals
        .iter()
        .map(|&[a, b]| Segment2::new(t.vertices[a], t.vertices[b]))
        .collect();
    pic.add(Layer::new("diagonals", Style::lines("#999999").with_dash("4 3")).segments(&diagonals));
    pic.add(
        Layer::new("polygon", Style::lines("#000000").with_stroke_width(2.0))
            .polygons(&t.polygons.0),
    );
    for (c, colour) in COLOURS.iter().enumerate() {
        let pts: Vec<Point2> = t
            .vertices
            .iter()
            .zip(&g.colors)
            .filter(|(_, &k)| k as usize == c)
            .map(|(p, _)| *p)
            .collect();
        pic.add(
            Layer::new(
                format!("colour {c}"),
                Style::points(colour).with_radius(3.5),
            )
            .points(&pts),
        );
    }
    // With holes: vertices whose corners carry more than one colour (the colouring is
    // cut open along the diagonals left out of the dual spanning tree).
    let mut several: Vec<Point2> = Vec::new();
    for (part, gallery) in t.parts.iter().zip(&g.galleries) {
        let mut carries = vec![0u8; part.vertices.len()];
        for (tri, c) in part.triangles.iter().zip(&gallery.corner_colors) {
            for s in 0..3 {
                carries[tri[s]] |= 1 << c[s];
            }
        }
        several.extend(
            part.vertices
                .iter()
                .zip(&carries)
                .filter(|(_, m)| m.count_ones() > 1)
                .map(|(p, _)| *p),
        );
    }
    if !several.is_empty() {
        pic.add(
            Layer::new(
                "vertex of two colours",
                Style::points("#ff7f0e")
                    .with_radius(5.5)
                    .without_fill()
                    .with_stroke_width(1.5),
            )
            .points(&several),
        );
    }
    pic.add(
        Layer::new(
            "guards",
            Style::points("#000000")
                .with_radius(8.0)
                .without_fill()
                .with_stroke_width(2.5),
        )
        .points(&g.guards),
    );
    pic
}
