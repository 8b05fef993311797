//! The gallery's chapter 6 section: the trapezoidal map of a small subdivision (polygons
//! sharing edges, a hole, vertical edges and equal x coordinates), with query points
//! located exactly (in a face, on an edge, at a vertex).

use super::samples::Rng;
use super::{format_duration, timed, Demo};
use crate::commands::locate::{locate_picture, polygon_edges};
use crate::error::CliError;
use compgeom::locate::{polygons_at, Location, PointLocator};
use compgeom::render::Section;
use compgeom::{MultiPolygon, Point2, Polygon};

/// Build the "Chapter 6 — point location" section.
pub fn section(demo: &Demo) -> Result<Section, CliError> {
    let mut section = Section::new(
        "Chapter 6 — point location",
        "The trapezoidal map (§6.1) of a subdivision: every segment endpoint sends vertical \
         extensions up and down to the next segment. TRAPEZOIDALMAP (§6.2) builds it by \
         inserting the segments in random order while maintaining a search structure of \
         x-nodes and y-nodes; points with equal x and vertical edges are handled by the \
         lexicographic order of §6.3. Queries are answered exactly: the feature holding the \
         point, or the edge or vertex it lies on.",
    );
    let p = |x: f64, y: f64| Point2::new(x, y);
    // Five rooms of a floor plan: shared walls, a courtyard (hole) with a fountain in it,
    // and vertical walls at equal x.
    let layer = MultiPolygon(vec![
        Polygon::new(vec![p(0., 0.), p(4., 0.), p(4., 3.), p(0., 3.)], vec![]),
        Polygon::new(
            vec![p(4., 0.), p(10., 0.), p(10., 3.), p(7., 3.), p(4., 3.)],
            vec![],
        ),
        Polygon::new(
            vec![
                p(0., 3.),
                p(4., 3.),
                p(7., 3.),
                p(10., 3.),
                p(10., 8.),
                p(0., 8.),
            ],
            vec![vec![p(3., 4.), p(3., 7.), p(7., 7.), p(7., 4.)]],
        ),
        Polygon::new(vec![p(4., 5.), p(6., 5.), p(5., 6.5)], vec![]),
        Polygon::new(
            vec![p(10., 0.), p(13., 2.), p(13., 6.), p(10., 8.), p(10., 3.)],
            vec![],
        ),
    ]);
    let ((loc, dcel), time) = match timed(|| PointLocator::from_polygons(&layer)) {
        (Ok(v), t) => (v, t),
        (Err(e), _) => return Err(e.into()),
    };
    loc.map().validate()?;
    dcel.validate()?;
    let mut rng = Rng::new(6);
    let mut queries: Vec<Point2> = (0..60)
        .map(|_| {
            p(
                (rng.range(-1.0, 14.0) * 2.0).round() / 2.0,
                rng.range(-1.0, 9.0),
            )
        })
        .collect();
    // Exactly on edges and at vertices.
    queries.extend([
        p(4., 1.5),
        p(10., 3.),
        p(5., 5.),
        p(3., 5.5),
        p(7., 3.),
        p(11.5, 1.),
    ]);
    let found = loc.locate_all(&queries)?;
    let keys: Vec<(Option<usize>, Location)> = found
        .iter()
        .map(|&l| (polygons_at(&dcel, l).first().copied(), l))
        .collect();
    let on = |k: fn(&Location) -> bool| found.iter().filter(|l| k(l)).count();
    let st = loc.stats();
    let pic = locate_picture(&loc, &polygon_edges(&layer), true, &queries, &keys);
    section.push(
        demo.figure(
            "locate-trapezoidal-map.svg",
            "The trapezoidal map of five polygons (a hole holding a triangle, shared walls, vertical walls) and query points coloured by the polygon holding them",
            &pic,
        )?
        .with_fact("segments", st.segments.to_string())
        .with_fact("trapezoids", st.trapezoids.to_string())
        .with_fact("search structure nodes", st.nodes.to_string())
        .with_fact("depth", st.depth.to_string())
        .with_fact("queries", queries.len().to_string())
        .with_fact("on an edge", on(|l| matches!(l, Location::Edge(_))).to_string())
        .with_fact("at a vertex", on(|l| matches!(l, Location::Vertex(_))).to_string())
        .with_fact("build", format_duration(time)),
    );
    Ok(section)
}
