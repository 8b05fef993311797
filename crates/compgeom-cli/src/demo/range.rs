//! The gallery's chapter 5 and 10 section: a kd-tree's splitting lines with a range
//! query, the layered range tree on a grid with duplicates (equal coordinates handled by
//! composite numbers), k nearest neighbours, and a windowing query on non-crossing
//! segments that finds segments crossing the window with no endpoint inside.

use super::samples::{disc, grid_with_duplicates, Rng};
use super::{format_duration, timed, Demo};
use crate::commands::range::{range_picture, Structure, StructureArg};
use crate::commands::window::{window_picture, window_queries, WindowStructure};
use crate::error::CliError;
use compgeom::range::{verify_nearest, verify_query, KdTree};
use compgeom::render::Section;
use compgeom::windowing::verify_window;
use compgeom::{Bbox2, Point2, Segment2};

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Bbox2 {
    Bbox2 {
        min: Point2::new(x0, y0),
        max: Point2::new(x1, y1),
    }
}

/// Build the "Chapters 5 and 10 — range searching and windowing" section.
pub fn section(demo: &Demo) -> Result<Section, CliError> {
    let mut section = Section::new(
        "Chapters 5 and 10 — range searching and windowing",
        "Range queries report the input points inside closed axis-parallel rectangles \
         (points on the boundary count). compgeom offers the book's kd-tree (§5.2), range \
         tree (§5.3) and layered range tree with fractional cascading (§5.6); equal \
         coordinates and duplicates are handled with the composite numbers of §5.5. \
         Windowing (chapter 10) reports the segments that meet a rectangle, including those \
         that cross it without an endpoint inside, decided with exact orientation tests.",
    );

    // 1. kd-tree splitting lines and two range queries.
    let pts = disc(300, 100.0, 5);
    let rects = vec![
        rect(-60.0, -20.0, 0.0, 40.0),
        rect(20.0, -80.0, 70.0, -30.0),
    ];
    let (tree, time) = timed(|| KdTree::new(&pts));
    let tree = tree?;
    let mut reported = Vec::new();
    for r in &rects {
        let res = tree.query(r);
        verify_query(&pts, r, &res)?;
        reported.push(res);
    }
    let pic = range_picture(
        &pts,
        &rects,
        &[],
        &reported,
        Some(&tree),
        "kd-tree: splitting lines and two range queries",
    );
    section.push(
        demo.figure("range-kdtree.svg", "kd-tree on 300 random points: median splits alternate x and y; two closed range queries", &pic)?
            .with_fact("n", pts.len().to_string())
            .with_fact("reported", reported.iter().map(Vec::len).sum::<usize>().to_string())
            .with_fact("build time", format_duration(time))
            .with_fact("verified", "yes"),
    );

    // 2. Layered range tree on a grid with duplicates; query edges on grid lines.
    let grid = grid_with_duplicates(12, 6);
    let rects = vec![
        rect(2.0, 3.0, 6.0, 3.0),
        rect(7.0, 6.0, 10.0, 10.0),
        rect(0.0, 0.0, 1.0, 11.0),
    ];
    let (s, time) = timed(|| Structure::build(StructureArg::Layered, &grid));
    let s = s?;
    let mut reported = Vec::new();
    for r in &rects {
        let res = s.query(r);
        verify_query(&grid, r, &res)?;
        reported.push(res);
    }
    let pic = range_picture(
        &grid,
        &rects,
        &[],
        &reported,
        None,
        "layered range tree: boundaries on grid lines, duplicates",
    );
    section.push(
        demo.figure("range-layered.svg", "layered range tree (fractional cascading) on a 12×12 grid with duplicates; one query is a zero-height rectangle", &pic)?
            .with_fact("n", grid.len().to_string())
            .with_fact("reported", reported.iter().map(Vec::len).sum::<usize>().to_string())
            .with_fact("build time", format_duration(time))
            .with_fact("verified", "yes"),
    );

    // 3. k nearest neighbours.
    let probes = vec![Point2::new(0.0, 0.0), Point2::new(60.0, 50.0)];
    let mut reported = Vec::new();
    for &q in &probes {
        let res = tree.nearest(q, 8);
        verify_nearest(&pts, q, 8, &res)?;
        reported.push(res);
    }
    let pic = range_picture(
        &pts,
        &[],
        &probes,
        &reported,
        None,
        "kd-tree: 8 nearest neighbours of two query points",
    );
    section.push(
        demo.figure(
            "range-knn.svg",
            "8 nearest neighbours (distances compared exactly; ties by index)",
            &pic,
        )?
        .with_fact("n", pts.len().to_string())
        .with_fact("k", "8")
        .with_fact("verified", "yes"),
    );

    // 4. Windowing on non-crossing segments: short segments, one per grid cell.
    let mut rng = Rng::new(9);
    let mut segs = Vec::new();
    for i in 0..12 {
        for j in 0..12 {
            let (x, y) = (i as f64 * 10.0, j as f64 * 10.0);
            let a = Point2::new(x + rng.range(0.0, 9.0), y + rng.range(0.0, 9.0));
            let b = Point2::new(x + rng.range(0.0, 9.0), y + rng.range(0.0, 9.0));
            segs.push(Segment2::new(a, b));
        }
    }
    // A long segment across everything, in the gaps between cells (y = 59.5 crosses no cell).
    segs.push(Segment2::new(
        Point2::new(-5.0, 59.5),
        Point2::new(125.0, 59.5),
    ));
    let windows = vec![rect(33.0, 33.0, 71.0, 64.0)];
    let (res, time) = timed(|| window_queries(WindowStructure::SegmentTree, &segs, &windows));
    let res = res?;
    for (w, r) in windows.iter().zip(&res) {
        verify_window(&segs, w, r)?;
    }
    let reported: Vec<usize> = res.iter().flatten().copied().collect();
    let pic = window_picture(
        &segs,
        &windows,
        &reported,
        "windowing: segments meeting the window",
    );
    section.push(
        demo.figure("window-segments.svg", "windowing on 145 non-crossing segments: those crossing the window's boundary are found too", &pic)?
            .with_fact("segments", segs.len().to_string())
            .with_fact("reported", reported.len().to_string())
            .with_fact("time (build + query)", format_duration(time))
            .with_fact("verified", "yes"),
    );
    Ok(section)
}
