//! The gallery's chapter 1 section: convex hulls of a random disc, a degenerate grid with
//! duplicates (with and without collinear boundary points), points on a circle, and the
//! book's slow hull on a small set.

use super::samples::{circle, disc, grid_with_duplicates};
use super::{format_duration, timed, Demo};
use crate::commands::hull::{hull_options, hull_picture, hull_title, AlgorithmArg};
use crate::error::CliError;
use compgeom::hull::{convex_hull, verify_convex_hull};
use compgeom::render::Section;
use compgeom::Point2;

/// One hull run of the section.
struct Run {
    file: &'static str,
    caption: &'static str,
    points: Vec<Point2>,
    algorithm: AlgorithmArg,
    keep_collinear: bool,
}

/// Build the "Chapter 1 — convex hull" section.
pub fn section(demo: &Demo) -> Result<Section, CliError> {
    let grid = grid_with_duplicates(9, 11);
    let runs = [
        Run {
            file: "hull-disc.svg",
            caption: "200 random points in a disc",
            points: disc(200, 100.0, 1),
            algorithm: AlgorithmArg::Default,
            keep_collinear: false,
        },
        Run {
            file: "hull-grid.svg",
            caption: "9×9 integer grid with duplicates: corners only",
            points: grid.clone(),
            algorithm: AlgorithmArg::Default,
            keep_collinear: false,
        },
        Run {
            file: "hull-grid-collinear.svg",
            caption: "the same grid, Andrew's algorithm keeping collinear boundary points",
            points: grid,
            algorithm: AlgorithmArg::Andrew,
            keep_collinear: true,
        },
        Run {
            file: "hull-circle.svg",
            caption: "64 points on a circle: every point is a vertex",
            points: circle(64, 50.0, 2),
            algorithm: AlgorithmArg::Default,
            keep_collinear: false,
        },
        Run {
            file: "hull-slow.svg",
            caption: "the book's slow hull (O(n³)) on 40 random points",
            points: disc(40, 10.0, 3),
            algorithm: AlgorithmArg::Slow,
            keep_collinear: false,
        },
    ];
    let mut section = Section::new(
        "Chapter 1 — convex hull",
        "The convex hull of a set of points is the smallest convex polygon containing them. \
         compgeom reports its vertices clockwise, starting from the lexicographically smallest \
         point (smallest x, then smallest y); vertices are numbered in that order.\n\n\
         The default method is the fastest exact one; 'andrew' is the book's CONVEXHULL \
         (Andrew's monotone chain, O(n log n)), and 'slow' is the book's SLOWCONVEXHULL, \
         which tests every ordered pair of points in O(n³). Every orientation test is exact, \
         so the grid's collinear boundary points and duplicates are handled correctly: they \
         are dropped, or kept as vertices when asked (keep collinear).",
    );
    for run in runs {
        let options = hull_options(run.algorithm, run.keep_collinear);
        let (hull, time) = timed(|| convex_hull(&run.points, &options));
        let hull = hull?;
        verify_convex_hull(&run.points, &hull, run.keep_collinear)?;
        let title = hull_title(run.algorithm, run.points.len(), hull.len());
        let picture = hull_picture(&run.points, &hull, &title);
        let figure = demo
            .figure(run.file, run.caption, &picture)?
            .with_fact("n", run.points.len().to_string())
            .with_fact("h", hull.len().to_string())
            .with_fact("algorithm", run.algorithm.name())
            .with_fact(
                "keep collinear",
                if run.keep_collinear { "yes" } else { "no" },
            )
            .with_fact("time", format_duration(time))
            .with_fact("verified", "yes");
        section.push(figure);
    }
    Ok(section)
}
