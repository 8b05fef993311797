//! The gallery's chapter 2.1 section: segment intersection by the exact plane sweep on
//! random segments, on a degenerate integer grid (shared endpoints, overlaps, horizontal and
//! vertical segments, many segments through one point), and long segments with many
//! crossings; each picture shows the sweep line at the middle event with the status.

use super::samples::Rng;
use super::{format_duration, timed, Demo};
use crate::commands::intersect::{intersect_picture, intersect_title};
use crate::error::CliError;
use compgeom::intersect::{sweep_intersections_with_stats, sweep_status_at, verify_intersections};
use compgeom::render::Section;
use compgeom::{Point2, Segment2};

fn seg(a: (f64, f64), b: (f64, f64)) -> Segment2 {
    Segment2::new(Point2::new(a.0, a.1), Point2::new(b.0, b.1))
}

/// `n` random segments in a square of side 100, each up to `len` long.
fn random_segments(n: usize, len: f64, seed: u64) -> Vec<Segment2> {
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|_| {
            let (x, y) = (rng.range(0.0, 100.0), rng.range(0.0, 100.0));
            let (l, t) = (rng.range(0.0, len), rng.range(0.0, std::f64::consts::TAU));
            seg((x, y), (x + l * t.cos(), y + l * t.sin()))
        })
        .collect()
}

/// Degenerate input on a 10×10 grid: a star through (5, 5), horizontal and vertical
/// segments, collinear overlaps, a duplicate and a zero-length segment.
fn degenerate_segments(seed: u64) -> Vec<Segment2> {
    let mut v = vec![
        seg((0.0, 0.0), (10.0, 10.0)),
        seg((0.0, 10.0), (10.0, 0.0)),
        seg((5.0, 0.0), (5.0, 10.0)),
        seg((0.0, 5.0), (10.0, 5.0)),
        seg((2.0, 5.0), (7.0, 5.0)),
        seg((3.0, 3.0), (8.0, 8.0)),
        seg((3.0, 3.0), (8.0, 8.0)),
        seg((5.0, 5.0), (5.0, 5.0)),
        seg((1.0, 9.0), (5.0, 5.0)),
    ];
    let mut rng = Rng::new(seed);
    let mut coord = || (rng.next_u64() % 11) as f64;
    for _ in 0..16 {
        let (x, y) = (coord(), coord());
        let (u, w) = (coord(), coord());
        v.push(seg((x, y), (u, w)));
    }
    v
}

/// `n` segments from the left side to the right side: about n²/4 crossings.
fn long_segments(n: usize, seed: u64) -> Vec<Segment2> {
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|_| seg((0.0, rng.range(0.0, 100.0)), (100.0, rng.range(0.0, 100.0))))
        .collect()
}

/// Build the "Chapter 2.1 — segment intersection" section.
pub fn section(demo: &Demo) -> Result<Section, CliError> {
    let runs = [
        ("intersect-random.svg", "80 random segments", random_segments(80, 30.0, 21)),
        (
            "intersect-degenerate.svg",
            "degenerate grid input: a star, horizontal and vertical segments, overlaps, a duplicate, a point segment",
            degenerate_segments(22),
        ),
        ("intersect-long.svg", "40 long segments, about n²/4 crossings", long_segments(40, 23)),
    ];
    let mut section = Section::new(
        "Chapter 2.1 — segment intersection",
        "The book's plane sweep (FINDINTERSECTIONS): a horizontal sweep line moves down; the \
         event queue holds segment endpoints and the crossings of segments that are neighbours \
         on the sweep line; the status structure holds the segments crossing the sweep line, \
         left to right. Each picture shows the sweep line (green) after its middle event and \
         the status segments (blue) numbered in status order.\n\n\
         Every decision is exact, including the order of crossing events and the order of \
         segments just below a crossing; reported crossing coordinates are the nearest double. \
         Degenerate input is ordinary: shared endpoints, endpoints on other segments, three \
         or more segments through a point, horizontal and vertical segments, zero-length \
         segments, and overlapping collinear segments (orange: maximal overlap pieces). Each \
         result is checked against an exact brute force.",
    );
    for (file, caption, segments) in runs {
        let (result, time) = timed(|| sweep_intersections_with_stats(&segments));
        let (found, stats) = result?;
        verify_intersections(&segments, &found)?;
        let snapshot = sweep_status_at(&segments, stats.events / 2)?;
        let picture = intersect_picture(
            &segments,
            &found,
            snapshot.as_ref(),
            &intersect_title(&segments, &found),
        );
        let figure = demo
            .figure(file, caption, &picture)?
            .with_fact("n", segments.len().to_string())
            .with_fact("intersection points", found.points.len().to_string())
            .with_fact("overlaps", found.overlaps.len().to_string())
            .with_fact("events", stats.events.to_string())
            .with_fact("largest queue", stats.max_queue.to_string())
            .with_fact("time", format_duration(time))
            .with_fact("verified", "yes");
        section.push(figure);
    }
    Ok(section)
}
