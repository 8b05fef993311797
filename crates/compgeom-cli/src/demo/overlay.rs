//! The gallery's chapter 2.2–2.4 section: the overlay of two small maps (vegetation ×
//! rivers as regions), every face labelled and checked with the DCEL's `validate`, and
//! the boolean operations on the same maps.

use super::{format_duration, timed, Demo};
use crate::commands::boolean::boolean_picture;
use crate::commands::overlay::overlay_picture;
use crate::error::CliError;
use compgeom::dcel::PolygonLabel;
use compgeom::overlay::{boolean, overlay_polygons, validity_problems, BooleanOp};
use compgeom::render::Section;
use compgeom::{MultiPolygon, Point2, Polygon};

fn poly(pts: &[(f64, f64)]) -> Polygon {
    Polygon::new(
        pts.iter().map(|&(x, y)| Point2::new(x, y)).collect(),
        vec![],
    )
}

/// Vegetation: forest (with a clearing), meadow, marsh.
fn vegetation() -> MultiPolygon {
    let mut forest = poly(&[(0., 0.), (6., 0.), (6., 5.), (3., 7.), (0., 5.)]);
    forest.holes.push(vec![
        Point2::new(2., 2.),
        Point2::new(2., 3.),
        Point2::new(3., 3.),
        Point2::new(3., 2.),
    ]);
    MultiPolygon(vec![
        forest,
        poly(&[(6., 0.), (10., 0.), (10., 6.), (6., 5.)]),
        poly(&[(3., 7.), (6., 5.), (10., 6.), (10., 9.), (3., 9.)]),
    ])
}

/// Rivers as regions: a winding river and a lake.
fn rivers() -> MultiPolygon {
    MultiPolygon(vec![
        poly(&[
            (-1., 3.),
            (4., 4.),
            (7., 2.),
            (11., 3.),
            (11., 4.),
            (7., 3.),
            (4., 5.),
            (-1., 4.),
        ]),
        poly(&[(7., 6.5), (8.5, 6.5), (8.5, 8.), (7., 8.)]),
    ])
}

/// The section.
pub fn section(demo: &Demo) -> Result<Section, CliError> {
    let (a, b) = (vegetation(), rivers());
    let mut section = Section::new(
        "2.2–2.4 Map overlay and boolean operations",
        "A vegetation map (three polygons, the forest with a clearing) overlaid with rivers \
         as regions: every face of the exact overlay is labelled with the polygon of each \
         map containing it (or none), each pair of labels in a colour of its own. Then the \
         boolean operations of the two maps; every result is checked valid.",
    );
    let (o, time) = timed(|| overlay_polygons(&a, &b));
    let o = o?;
    o.validate()?;
    let label = |la: &PolygonLabel, lb: &PolygonLabel| (la.first().copied(), lb.first().copied());
    let pic = overlay_picture(&o, label, ("vegetation", "river"));
    // Times go in the facts, not the pictures, so the pictures are reproducible.
    section.push(
        demo.figure("overlay-maps.svg", "Overlay of vegetation and rivers", &pic)?
            .with_fact("time", format_duration(time)),
    );
    for (name, op) in [
        ("intersection", BooleanOp::Intersection),
        ("union", BooleanOp::Union),
        ("difference", BooleanOp::Difference),
        ("xor", BooleanOp::Xor),
    ] {
        let (r, time) = timed(|| boolean(&a, &b, op));
        let r = r?;
        let problems = validity_problems(&r)?;
        if let Some(p) = problems.first() {
            return Err(CliError::failure(format!(
                "{name}: invalid result: {}",
                p.message
            )));
        }
        let title = format!("vegetation {name} rivers: {} polygons", r.0.len());
        let pic = boolean_picture(&a, &b, &r, &title);
        section.push(
            demo.figure(&format!("boolean-{name}.svg"), &title, &pic)?
                .with_fact("time", format_duration(time)),
        );
    }
    Ok(section)
}
