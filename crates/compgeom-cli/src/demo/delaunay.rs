//! The gallery's chapter 9 section: Delaunay triangulations of a random disc (with a few
//! circumcircles), of a cocircular integer set and of a grid with duplicates; the book's
//! incremental algorithm; a constrained triangulation of a polygon with holes, its Ruppert
//! refinement, and a constrained triangulation with crossing constraints.

use super::samples::{disc, grid_with_duplicates};
use super::{format_duration, timed, Demo};
use crate::commands::delaunay::{add_constraints, delaunay_picture, AlgorithmArg, OrderArg};
use crate::error::CliError;
use compgeom::delaunay::{
    constrained_delaunay, delaunay_with, polygon_delaunay, refine, verify_cdt, verify_delaunay,
    RefineOptions,
};
use compgeom::render::{Layer, Section, Style};
use compgeom::{Point2, Polygon, Segment2};

/// Integer points on the circle x² + y² = 65² (many lattice points: all cocircular).
fn lattice_circle() -> Vec<Point2> {
    let r2: i64 = 65 * 65;
    let mut pts = Vec::new();
    for x in -65i64..=65 {
        let y2 = r2 - x * x;
        let y = (y2 as f64).sqrt().round() as i64;
        if y * y == y2 {
            pts.push(Point2::new(x as f64, y as f64));
            if y != 0 {
                pts.push(Point2::new(x as f64, -y as f64));
            }
        }
    }
    pts.push(Point2::new(0.0, 0.0));
    pts
}

/// Build the "Chapter 9 — Delaunay triangulation" section.
pub fn section(demo: &Demo) -> Result<Section, CliError> {
    let mut section = Section::new(
        "Chapter 9 — Delaunay triangulation",
        "The Delaunay triangulation maximizes the smallest angle: no vertex lies inside the \
         circumcircle of any triangle (a few are drawn dashed). The default method inserts the \
         points in Hilbert-curve order, finds each by walking, and restores the Delaunay \
         property by the book's edge flips; 'incremental' is the book's randomized \
         DELAUNAYTRIANGULATION with the history DAG and the symbolic points p₋₁, p₋₂. Every \
         in-circle and orientation test is exact, so cocircular points (the lattice circle) \
         and grids with duplicates are triangulated correctly; each result was checked by the \
         exact verifier.",
    );
    let runs = [
        (
            "delaunay-disc.svg",
            "300 random points in a disc",
            disc(300, 100.0, 4),
            AlgorithmArg::Default,
            4,
        ),
        (
            "delaunay-book.svg",
            "the same points, the book's incremental algorithm",
            disc(300, 100.0, 4),
            AlgorithmArg::Incremental,
            0,
        ),
        (
            "delaunay-cocircular.svg",
            "lattice points on x² + y² = 65² and the centre (all cocircular)",
            lattice_circle(),
            AlgorithmArg::Default,
            2,
        ),
        (
            "delaunay-grid.svg",
            "9×9 integer grid with duplicates",
            grid_with_duplicates(9, 5),
            AlgorithmArg::Default,
            0,
        ),
    ];
    for (file, caption, points, algorithm, circles) in runs {
        let (tri, time) = timed(|| delaunay_with(&points, &algorithm.options(OrderArg::Biased)));
        let tri = tri?;
        verify_delaunay(&tri)?;
        let title = format!(
            "Delaunay ({}): n = {}, {} triangles",
            algorithm.name(),
            tri.vertices().len(),
            tri.triangles().len()
        );
        let picture = delaunay_picture(&tri, &title, circles);
        section.push(
            demo.figure(file, caption, &picture)?
                .with_fact("n", points.len().to_string())
                .with_fact("triangles", tri.triangles().len().to_string())
                .with_fact("algorithm", algorithm.name())
                .with_fact("time", format_duration(time))
                .with_fact("verified", "yes"),
        );
    }

    // Constrained: a square with two holes.
    let sq = |lo: f64, hi: f64| {
        vec![
            Point2::new(lo, lo),
            Point2::new(hi, lo),
            Point2::new(hi, hi),
            Point2::new(lo, hi),
        ]
    };
    let mut outer = sq(0.0, 100.0);
    outer.insert(1, Point2::new(50.0, 10.0));
    let poly = Polygon::new(outer, vec![sq(15.0, 40.0), sq(55.0, 85.0)]);
    let (cdt, time) = timed(|| polygon_delaunay(std::slice::from_ref(&poly)));
    let cdt = cdt?;
    verify_cdt(&cdt)?;
    let title = format!(
        "constrained Delaunay of a polygon with 2 holes: {} triangles",
        cdt.triangulation.triangles().len()
    );
    let mut picture = delaunay_picture(&cdt.triangulation, &title, 0);
    let v = cdt.triangulation.vertices();
    let fixed: Vec<Segment2> = cdt
        .constraints
        .iter()
        .map(|&(a, b)| Segment2::new(v[a as usize], v[b as usize]))
        .collect();
    picture.add(
        Layer::new(
            "constrained edges (polygon rings)",
            Style::lines("#2ca02c").with_stroke_width(2.5),
        )
        .segments(&fixed),
    );
    section.push(
        demo.figure(
            "delaunay-cdt.svg",
            "constrained Delaunay triangulation of a polygon with holes",
            &picture,
        )?
        .with_fact("n", v.len().to_string())
        .with_fact("triangles", cdt.triangulation.triangles().len().to_string())
        .with_fact("algorithm", "constrained")
        .with_fact("time", format_duration(time))
        .with_fact("verified", "yes"),
    );

    // Refinement of the same polygon: every angle at least 25°, area at most 40.
    let opts = RefineOptions::new(25.0).with_max_area(40.0);
    let (r, time) = timed(|| refine(&cdt, &opts));
    let r = r?;
    verify_cdt(&r.cdt)?;
    let t = &r.cdt.triangulation;
    let title = format!(
        "Ruppert refinement, angles ≥ 25°, area ≤ 40: {} triangles, {} Steiner points",
        t.triangles().len(),
        r.steiner
    );
    let mut picture = delaunay_picture(t, &title, 0);
    add_constraints(&mut picture, t, &r.cdt.constraints);
    section.push(
        demo.figure(
            "delaunay-refined.svg",
            "the polygon refined: Steiner points until every angle is at least 25°",
            &picture,
        )?
        .with_fact("n", t.vertices().len().to_string())
        .with_fact("steiner", r.steiner.to_string())
        .with_fact("triangles", t.triangles().len().to_string())
        .with_fact("exempt", r.exempt.len().to_string())
        .with_fact("time", format_duration(time))
        .with_fact("verified", "yes"),
    );

    // Crossing constraints: a star of chords over random points, split at the crossings.
    let pts = disc(60, 100.0, 9);
    let chords: Vec<Segment2> = (0..7)
        .map(|k| {
            let a = k as f64 * std::f64::consts::TAU / 7.0;
            let b = (k + 3) as f64 * std::f64::consts::TAU / 7.0;
            Segment2::new(
                Point2::new(95.0 * a.cos(), 95.0 * a.sin()),
                Point2::new(95.0 * b.cos(), 95.0 * b.sin()),
            )
        })
        .collect();
    let (cdt, time) = timed(|| constrained_delaunay(&pts, &chords));
    let cdt = cdt?;
    verify_cdt(&cdt)?;
    let t = &cdt.triangulation;
    let steiner = t.vertices().len()
        - (t.input_to_vertex()
            .iter()
            .max()
            .map_or(0, |&m| m as usize + 1));
    let title =
        format!("constrained Delaunay with 7 crossing chords: {steiner} crossings became vertices");
    let mut picture = delaunay_picture(t, &title, 0);
    add_constraints(&mut picture, t, &cdt.constraints);
    section.push(
        demo.figure(
            "delaunay-crossing.svg",
            "crossing constraints split at their (rounded) crossings",
            &picture,
        )?
        .with_fact("n", pts.len().to_string())
        .with_fact("constraints", chords.len().to_string())
        .with_fact("steiner", steiner.to_string())
        .with_fact("time", format_duration(time))
        .with_fact("verified", "yes"),
    );
    Ok(section)
}
