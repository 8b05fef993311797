//! `compgeom intersect`: all intersection points and overlaps of line segments (book §2.1),
//! via `compgeom::intersect::find_intersections` (the exact Bentley–Ottmann sweep, or
//! exact pairwise tests), or `count_intersections` for `--count-only`.

use crate::cli::{InputArgs, OutputArgs};
use crate::error::CliError;
use crate::output;
use crate::progress::{Spinner, LARGE_INPUT};
use clap::{Args, ValueEnum};
use compgeom::intersect::{
    count_intersections_with, find_intersections_with, sweep_intersections_with_stats,
    sweep_status_at, verify_intersections, IntersectAlgorithm, Intersections, StatusSnapshot,
};
use compgeom::io::{self, write_shape, Shape};
use compgeom::render::{Layer, Picture, Style};
use compgeom::{Bbox2, Point2, Segment2};
use serde::Serialize;

/// `--help` text describing the JSON output.
pub const JSON_HELP: &str = "\
Input: segments as `x1,y1,x2,y2` lines, or every edge of WKT/GeoJSON (MULTI)LINESTRINGs and
polygon rings. Segment ids are their 0-based order in the input. Segments are closed: a
touching endpoint counts. Every decision is exact; coordinates of crossings are the nearest
double to the exact point. Results are in sweep order: y decreasing, then x increasing.

JSON output (--format json, the default) is one object:
  intersections  [{\"point\": [x, y], \"segments\": [i, ...], \"upper\": [...], \"lower\": [...],
                  \"interior\": [...]}, ...]  every point on two or more segments that is an
                 endpoint or a crossing; upper / lower: segments whose upper (first in sweep
                 order) / lower endpoint it is (a zero-length segment is in both); interior:
                 segments passing through it. All lists ascending.
  overlaps       [{\"segments\": [i, j, ...], \"from\": [x, y], \"to\": [x, y]}, ...]  maximal
                 pieces covered by the same two or more collinear segments
  segments       number of input segments
  verified       true; present only with --verify (a failed check exits 1 instead)

With --count-only, JSON is {\"intersections\": count, \"overlaps\": count, \"segments\": n};
other formats print the number of intersection points. Without it, other formats print the
intersection points as a multipoint.

--verify compares the result with an exact O(n²) brute force (at most 5000 segments).
--svg draws the segments, the intersection points, the overlaps, and the sweep line at the
middle event with the status structure (the segments crossing it, numbered left to right).

Examples:
  compgeom intersect segments.csv
  compgeom intersect roads.geojson --count-only
  compgeom intersect lines.wkt --svg sweep.svg --verify";

/// The largest input `--verify` accepts (the check is quadratic).
pub const VERIFY_LIMIT: usize = 5000;

/// Arguments of `compgeom intersect`.
#[derive(Debug, Clone, Args)]
pub struct IntersectArgs {
    /// Input and its format.
    #[command(flatten)]
    pub input: InputArgs,

    /// Output, picture and verification.
    #[command(flatten)]
    pub output: OutputArgs,

    /// Print only the numbers of intersection points and overlaps.
    #[arg(long)]
    pub count_only: bool,

    /// Method: `default` (the fastest exact one for the input), `sweep` (the book's
    /// Bentley–Ottmann plane sweep, O((n + I) log n)) or `pairwise` (exact tests of the pairs
    /// whose bounding boxes overlap). All give the same answer.
    #[arg(long, value_enum, default_value_t = AlgorithmArg::Default)]
    pub algorithm: AlgorithmArg,
}

/// The `--algorithm` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum AlgorithmArg {
    /// The fastest exact method for the input.
    Default,
    /// The book's plane sweep.
    Sweep,
    /// Exact tests of the pairs with overlapping bounding boxes.
    Pairwise,
}

impl AlgorithmArg {
    /// The library's algorithm.
    pub fn algorithm(self) -> IntersectAlgorithm {
        match self {
            AlgorithmArg::Default => IntersectAlgorithm::Default,
            AlgorithmArg::Sweep => IntersectAlgorithm::Sweep,
            AlgorithmArg::Pairwise => IntersectAlgorithm::Pairwise,
        }
    }
}

#[derive(Debug, Serialize)]
struct PointJson {
    point: [f64; 2],
    segments: Vec<usize>,
    upper: Vec<usize>,
    lower: Vec<usize>,
    interior: Vec<usize>,
}

#[derive(Debug, Serialize)]
struct OverlapJson {
    segments: Vec<usize>,
    from: [f64; 2],
    to: [f64; 2],
}

/// The JSON result object (fields documented in [`JSON_HELP`]).
#[derive(Debug, Serialize)]
struct IntersectJson {
    intersections: Vec<PointJson>,
    overlaps: Vec<OverlapJson>,
    segments: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    verified: Option<bool>,
}

#[derive(Debug, Serialize)]
struct CountJson {
    intersections: usize,
    overlaps: usize,
    segments: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    verified: Option<bool>,
}

fn xy(p: Point2) -> [f64; 2] {
    [p.x, p.y]
}

/// Run `compgeom intersect`.
pub fn run(args: &IntersectArgs) -> Result<(), CliError> {
    let segments = {
        let _spin = Spinner::start("reading segments", false);
        let src = args.input.read()?;
        io::read_segments(&src.text, src.format, &src.name)?
    };
    if args.output.verify && segments.len() > VERIFY_LIMIT {
        return Err(CliError::bad_input(format!(
            "--verify compares with an O(n²) brute force and accepts at most {VERIFY_LIMIT} \
             segments; the input has {}",
            segments.len()
        )));
    }
    // Counting alone needs neither the points nor their coordinates.
    if args.count_only && !args.output.verify && args.output.svg.is_none() {
        let count = {
            let _spin = Spinner::start("counting", segments.len() >= LARGE_INPUT);
            count_intersections_with(&segments, args.algorithm.algorithm())?
        };
        let text = match args.output.format().geometry_format() {
            None => to_json(&CountJson {
                intersections: count.points,
                overlaps: count.overlaps,
                segments: segments.len(),
                verified: None,
            })?,
            Some(_) => count.points.to_string(),
        };
        return output::emit(args.output.output.as_deref(), &output::with_newline(text));
    }
    let found = {
        let _spin = Spinner::start("intersecting", segments.len() >= LARGE_INPUT);
        find_intersections_with(&segments, args.algorithm.algorithm())?
    };
    if args.output.verify {
        let _spin = Spinner::start("verifying", false);
        verify_intersections(&segments, &found)?;
    }
    let verified = args.output.verify.then_some(true);

    // Everything is computed and checked before anything is written.
    let text = match (args.count_only, args.output.format().geometry_format()) {
        (true, None) => to_json(&CountJson {
            intersections: found.points.len(),
            overlaps: found.overlaps.len(),
            segments: segments.len(),
            verified,
        })?,
        (true, Some(_)) => found.points.len().to_string(),
        (false, None) => to_json(&IntersectJson {
            intersections: found
                .points
                .iter()
                .map(|p| PointJson {
                    point: xy(p.point),
                    segments: p.segments().to_vec(),
                    upper: p.upper().to_vec(),
                    lower: p.lower().to_vec(),
                    interior: p.interior().to_vec(),
                })
                .collect(),
            overlaps: found
                .overlaps
                .iter()
                .map(|o| OverlapJson {
                    segments: o.segments.clone(),
                    from: xy(o.from),
                    to: xy(o.to),
                })
                .collect(),
            segments: segments.len(),
            verified,
        })?,
        (false, Some(format)) => {
            let pts: Vec<Point2> = found.points.iter().map(|p| p.point).collect();
            let shape = if pts.is_empty() {
                Shape::Empty
            } else {
                Shape::MultiPoint(pts)
            };
            write_shape(&shape, format)?
        }
    };
    if let Some(svg) = &args.output.svg {
        // The picture shows the book's sweep at its middle event.
        let (_, stats) = sweep_intersections_with_stats(&segments)?;
        let snapshot = sweep_status_at(&segments, stats.events / 2)?;
        let picture = intersect_picture(
            &segments,
            &found,
            snapshot.as_ref(),
            &intersect_title(&segments, &found),
        );
        output::write_atomic(svg, picture.to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

fn to_json(value: &impl Serialize) -> Result<String, CliError> {
    serde_json::to_string(value).map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))
}

/// The picture title: n, intersection points, overlaps.
pub fn intersect_title(segments: &[Segment2], found: &Intersections) -> String {
    format!(
        "segment intersection: n = {}, {} intersection points, {} overlaps",
        segments.len(),
        found.points.len(),
        found.overlaps.len()
    )
}

/// Where a segment crosses the horizontal line at `y` (for drawing only).
fn x_at(s: Segment2, y: f64) -> f64 {
    if s.a.y == s.b.y {
        return (s.a.x + s.b.x) / 2.0;
    }
    let t = ((y - s.a.y) / (s.b.y - s.a.y)).clamp(0.0, 1.0);
    s.a.x + t * (s.b.x - s.a.x)
}

/// The segments, overlaps, intersection points and, if given, the sweep line at one
/// event with the status segments numbered left to right along it.
pub fn intersect_picture(
    segments: &[Segment2],
    found: &Intersections,
    snapshot: Option<&StatusSnapshot>,
    title: &str,
) -> Picture {
    let mut pic = Picture::new(800, 640).with_title(title);
    pic.add(
        Layer::new(
            format!("segments ({})", segments.len()),
            Style::lines("#8c8c8c").with_stroke_width(1.0),
        )
        .segments(segments),
    );
    if let Some(snap) = snapshot {
        let bbox = Bbox2::of_points(segments.iter().flat_map(|s| [&s.a, &s.b]));
        let y = snap.at.y;
        pic.add(
            Layer::new(
                format!("sweep line after event {} (y = {:.4})", snap.event, y),
                Style::lines("#2ca02c").with_stroke_width(1.0),
            )
            .segment(Segment2::new(
                Point2::new(bbox.min.x, y),
                Point2::new(bbox.max.x, y),
            )),
        );
        let status: Vec<Segment2> = snap.status.iter().map(|&i| segments[i]).collect();
        pic.add(
            Layer::new(
                format!("status structure: {} segments, left to right", status.len()),
                Style::lines("#1f77b4").with_stroke_width(2.0),
            )
            .segments(&status),
        );
        // Numbers just below the sweep line, where segments through the event point have
        // already separated (the status order is the order just below the event).
        let below = y - 0.04 * bbox.height().max(f64::MIN_POSITIVE);
        let mut labels = Layer::new(
            "status order (numbered just below the sweep line)",
            Style::text("#1f77b4"),
        );
        for (k, s) in status.iter().enumerate() {
            let (lo, hi) = (s.a.y.min(s.b.y), s.a.y.max(s.b.y));
            let at = below.clamp(lo, hi);
            labels = labels.text(Point2::new(x_at(*s, at), at), format!("{k}"));
        }
        pic.add(labels);
    }
    if !found.overlaps.is_empty() {
        let pieces: Vec<Segment2> = found
            .overlaps
            .iter()
            .map(|o| Segment2::new(o.from, o.to))
            .collect();
        pic.add(
            Layer::new(
                format!("overlaps ({})", pieces.len()),
                Style::lines("#ff7f0e")
                    .with_stroke_width(4.0)
                    .with_opacity(0.7),
            )
            .segments(&pieces),
        );
    }
    let pts: Vec<Point2> = found.points.iter().map(|p| p.point).collect();
    pic.add(
        Layer::new(
            format!("intersection points ({})", pts.len()),
            Style::points("#d62728").with_radius(if pts.len() > 5000 { 1.5 } else { 3.0 }),
        )
        .points(&pts),
    );
    pic
}
