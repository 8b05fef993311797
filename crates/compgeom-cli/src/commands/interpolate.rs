//! `compgeom interpolate`: heights of the piecewise-linear terrain over the Delaunay
//! triangulation of (x, y, z) samples (book §9.1), via `compgeom::delaunay::Terrain`.

use crate::cli::{InputArgs, OutputArgs, OutputFormat};
use crate::error::CliError;
use crate::output;
use clap::Args;
use compgeom::delaunay::{verify_delaunay, Terrain};
use compgeom::render::{Layer, Picture, Style};
use compgeom::{Point2, Polygon};
use serde::Serialize;
use std::path::PathBuf;

/// `--help` text describing the JSON output.
pub const JSON_HELP: &str = "\
JSON output (--format json, the only format) is one object:
  heights   [z or null, ...]  one per query point, in input order: the height of the
                              piecewise-linear terrain over the Delaunay triangulation of the
                              samples' (x, y); null outside the samples' convex hull
  samples   number of samples read (equal (x, y) merged: the first one's z is used)
  verified  true; present only with --verify (the triangulation was checked exactly)

SAMPLES are x,y,z lines (or OFF); --at POINTS are x,y lines, WKT or GeoJSON.

--svg FILE draws the terrain's triangles coloured by mean height (six bands, legend with
their ranges), the samples, and the query points (black: inside, with a height; red
crosses: outside the hull).

Example:
  compgeom interpolate samples.csv --at queries.csv --svg terrain.svg";

/// Arguments of `compgeom interpolate`.
#[derive(Debug, Clone, Args)]
pub struct InterpolateArgs {
    /// The samples (x, y, z) and their format.
    #[command(flatten)]
    pub input: InputArgs,

    /// Output, picture and verification (only JSON output).
    #[command(flatten)]
    pub output: OutputArgs,

    /// The query points.
    #[arg(long, value_name = "POINTS")]
    pub at: PathBuf,
}

#[derive(Debug, Serialize)]
struct HeightsJson {
    heights: Vec<Option<f64>>,
    samples: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    verified: Option<bool>,
}

/// Run `compgeom interpolate`.
pub fn run(args: &InterpolateArgs) -> Result<(), CliError> {
    if args.output.format() != OutputFormat::Json {
        return Err(args.output.unsupported("interpolate", "json only"));
    }
    let src = args.input.read()?;
    let samples = compgeom::io::read_points3(&src.text, src.format, &src.name)?;
    let queries = InputArgs {
        input: args.at.clone(),
        input_format: None,
    }
    .read_points()?;
    let terrain = Terrain::new(&samples)?;
    if args.output.verify {
        verify_delaunay(terrain.triangulation())?;
    }
    let heights = terrain.heights(&queries);
    if let Some(svg) = &args.output.svg {
        let pic = terrain_picture(&terrain, &queries, &heights);
        output::write_atomic(svg, pic.to_svg_string().as_bytes())?;
    }
    let json = HeightsJson {
        heights,
        samples: samples.len(),
        verified: args.output.verify.then_some(true),
    };
    let text = serde_json::to_string(&json)
        .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?;
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

/// Colours of the height bands, low to high.
const BANDS: [&str; 6] = [
    "#313695", "#4575b4", "#74add1", "#fdae61", "#f46d43", "#a50026",
];

/// The terrain's triangles coloured by mean height, the samples, and the queries.
pub fn terrain_picture(terrain: &Terrain, queries: &[Point2], heights: &[Option<f64>]) -> Picture {
    let t = terrain.triangulation();
    let v = t.vertices();
    let z = terrain.vertex_heights();
    let mut pic = Picture::new(800, 640).with_title(format!(
        "terrain: {} samples, {} triangles, {} queries",
        v.len(),
        t.triangles().len(),
        queries.len()
    ));
    let (lo, hi) = z
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &h| {
            (a.min(h), b.max(h))
        });
    let span = (hi - lo).max(f64::MIN_POSITIVE);
    let mut bands: Vec<Vec<Polygon>> = vec![Vec::new(); BANDS.len()];
    for tri in t.triangles() {
        let mean = tri.iter().map(|&i| z[i as usize]).sum::<f64>() / 3.0;
        let k = (((mean - lo) / span) * BANDS.len() as f64) as usize;
        let ring = tri.iter().map(|&i| v[i as usize]).collect();
        bands[k.min(BANDS.len() - 1)].push(Polygon::new(ring, Vec::new()));
    }
    for (k, polys) in bands.iter().enumerate() {
        if polys.is_empty() {
            continue;
        }
        let a = lo + span * k as f64 / BANDS.len() as f64;
        let b = lo + span * (k + 1) as f64 / BANDS.len() as f64;
        pic.add(
            Layer::new(
                format!("height {a:.3} to {b:.3} ({} triangles)", polys.len()),
                Style::area(BANDS[k]).with_stroke_width(0.4),
            )
            .polygons(polys),
        );
    }
    pic.add(
        Layer::new(
            format!("samples ({})", v.len()),
            Style::points("#222222").with_radius(1.5),
        )
        .points(v),
    );
    let (inside, outside): (Vec<(Point2, Option<f64>)>, Vec<_>) = queries
        .iter()
        .copied()
        .zip(heights.iter().copied())
        .partition(|(_, h)| h.is_some());
    let inside: Vec<Point2> = inside.into_iter().map(|(p, _)| p).collect();
    let outside: Vec<Point2> = outside.into_iter().map(|(p, _)| p).collect();
    pic.add(
        Layer::new(
            format!("queries with a height ({})", inside.len()),
            Style::points("#000000")
                .with_radius(3.5)
                .with_fill("#ffffff"),
        )
        .points(&inside),
    );
    let mut crosses = Layer::new(
        format!("queries outside the hull ({})", outside.len()),
        Style::lines("#d62728").with_stroke_width(1.5),
    );
    let bb = compgeom::Bbox2::of_points(v.iter().chain(queries));
    let r = (0.01 * bb.width().max(bb.height())).max(f64::MIN_POSITIVE);
    for p in outside {
        crosses = crosses
            .segment(compgeom::Segment2::new(
                Point2::new(p.x - r, p.y - r),
                Point2::new(p.x + r, p.y + r),
            ))
            .segment(compgeom::Segment2::new(
                Point2::new(p.x - r, p.y + r),
                Point2::new(p.x + r, p.y - r),
            ));
    }
    pic.add(crosses);
    pic
}
