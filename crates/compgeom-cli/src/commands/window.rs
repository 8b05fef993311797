//! `compgeom window`: windowing queries (book chapter 10) via `compgeom::windowing`: which
//! input segments meet each query rectangle.

use crate::cli::{InputArgs, OutputArgs};
use crate::error::CliError;
use crate::output;
use clap::{Args, ValueEnum};
use compgeom::io::write_segments;
use compgeom::range::read_rects;
use compgeom::render::{Layer, Picture, Style};
use compgeom::windowing::{AxisParallelWindow, SegmentWindow};
use compgeom::{Bbox2, Segment2};
use serde::Serialize;
use std::path::PathBuf;

/// `--help` text describing the JSON output.
pub const JSON_HELP: &str = "\
SEGMENTS are x1,y1,x2,y2 lines (or WKT/GeoJSON lines and polygons: every edge); they must
not cross one another (touching and shared endpoints are fine). RECTS holds one window per
line: xmin,ymin,xmax,ymax (closed; xmin > xmax or ymin > ymax makes an empty window).

JSON output (--format json, the default) is one object:
  results         [[i, ...], ...]  per window, the 0-based indices of the segments that
                                   meet it (an endpoint inside, or crossing its boundary),
                                   each once, ascending
  structure       \"segment-tree\" | \"interval-tree\"
  input_segments  number of segments read
  queries         number of windows
  verified        true; present only with --verify (each answer checked by brute force)

Other formats print the reported segments (of all windows) as x1,y1,x2,y2 lines, WKT or
GeoJSON.

Examples:
  compgeom window roads.csv --queries windows.csv
  compgeom window grid.csv --queries windows.csv --structure interval-tree --svg w.svg";

/// Arguments of `compgeom window`.
#[derive(Debug, Clone, Args)]
pub struct WindowArgs {
    /// Input segments and their format.
    #[command(flatten)]
    pub input: InputArgs,

    /// Output, picture and verification.
    #[command(flatten)]
    pub output: OutputArgs,

    /// Query windows, one `xmin,ymin,xmax,ymax` line each (`-` for standard input).
    #[arg(long, value_name = "RECTS")]
    pub queries: PathBuf,

    /// The structure: `segment-tree` (any non-crossing segments, §10.3) or `interval-tree`
    /// (axis-parallel segments only, §10.1–10.2).
    #[arg(long, value_enum, default_value_t = WindowStructure::SegmentTree)]
    pub structure: WindowStructure,
}

/// The `--structure` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum WindowStructure {
    /// Segment tree with ordered associated lists (§10.3).
    SegmentTree,
    /// Interval tree with priority search trees (§10.1–10.2), axis-parallel segments only.
    IntervalTree,
}

impl WindowStructure {
    /// The name printed in JSON output.
    pub fn name(self) -> &'static str {
        match self {
            WindowStructure::SegmentTree => "segment-tree",
            WindowStructure::IntervalTree => "interval-tree",
        }
    }
}

#[derive(Debug, Serialize)]
struct WindowJson {
    results: Vec<Vec<usize>>,
    structure: &'static str,
    input_segments: usize,
    queries: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    verified: Option<bool>,
}

/// Run `compgeom window`.
pub fn run(args: &WindowArgs) -> Result<(), CliError> {
    let src = args.input.read()?;
    let segments = compgeom::io::read_segments(&src.text, src.format, &src.name)?;
    let text =
        compgeom::io::read_text(&args.queries).map_err(|e| CliError::bad_input(e.to_string()))?; // missing file: bad input, exit 2
    let name = if args.queries.as_os_str() == "-" {
        "<stdin>".to_string()
    } else {
        args.queries.display().to_string()
    };
    let rects = read_rects(&text, &name)?;
    let results = window_queries(args.structure, &segments, &rects)?;
    if args.output.verify {
        for (w, r) in rects.iter().zip(&results) {
            compgeom::windowing::verify_window(&segments, w, r)?;
        }
    }
    let text = match args.output.format().geometry_format() {
        None => {
            let json = WindowJson {
                results: results.clone(),
                structure: args.structure.name(),
                input_segments: segments.len(),
                queries: rects.len(),
                verified: args.output.verify.then_some(true),
            };
            serde_json::to_string(&json)
                .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?
        }
        Some(format) => {
            let mut ids: Vec<usize> = results.iter().flatten().copied().collect();
            ids.sort_unstable();
            ids.dedup();
            let chosen: Vec<Segment2> = ids.iter().map(|&i| segments[i]).collect();
            write_segments(&chosen, format)?
        }
    };
    if let Some(svg) = &args.output.svg {
        let reported: Vec<usize> = results.iter().flatten().copied().collect();
        let title = format!(
            "windowing ({}): {} segments, {} windows",
            args.structure.name(),
            segments.len(),
            rects.len()
        );
        let picture = window_picture(&segments, &rects, &reported, &title);
        output::write_atomic(svg, picture.to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

/// Answer every window with the chosen structure.
pub fn window_queries(
    structure: WindowStructure,
    segments: &[Segment2],
    rects: &[Bbox2],
) -> Result<Vec<Vec<usize>>, CliError> {
    Ok(match structure {
        WindowStructure::SegmentTree => {
            let w = SegmentWindow::new(segments)?;
            rects.iter().map(|r| w.query(r)).collect()
        }
        WindowStructure::IntervalTree => {
            let w = AxisParallelWindow::new(segments)?;
            rects.iter().map(|r| w.query(r)).collect()
        }
    })
}

/// Segments, windows, and the reported segments highlighted.
pub fn window_picture(
    segments: &[Segment2],
    rects: &[Bbox2],
    reported: &[usize],
    title: &str,
) -> Picture {
    let mut pic = Picture::new(800, 640).with_title(title);
    // Zero-length segments and point windows would draw as nothing: mark them as rings.
    let with_points = |mut layer: Layer, segs: &[Segment2]| {
        for s in segs.iter().filter(|s| s.a == s.b) {
            layer = layer.point(s.a);
        }
        layer.segments(segs)
    };
    pic.add(with_points(
        Layer::new(
            format!("input segments ({})", segments.len()),
            Style::lines("#8c8c8c").with_stroke_width(1.0),
        ),
        segments,
    ));
    pic.add(super::range::query_rect_layer(
        format!("query windows ({})", rects.len()),
        rects,
        0.1,
    ));
    let mut ids = reported.to_vec();
    ids.sort_unstable();
    ids.dedup();
    let hits: Vec<Segment2> = ids.iter().map(|&i| segments[i]).collect();
    pic.add(with_points(
        Layer::new(
            format!("reported segments ({})", hits.len()),
            Style::lines("#d62728").with_stroke_width(2.5),
        ),
        &hits,
    ));
    pic
}
