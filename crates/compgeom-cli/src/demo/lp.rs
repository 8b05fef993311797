//! The gallery's chapter 4 section: a 2D linear program, an unbounded half-plane
//! intersection, the smallest enclosing disc, and the removal directions of a casting.

use super::samples::{disc, Rng};
use super::{format_duration, timed, Demo};
use crate::commands::cast::direction_picture;
use crate::commands::enclose::disc_picture;
use crate::commands::halfplanes::region_picture;
use crate::commands::lp::lp_picture;
use crate::error::CliError;
use compgeom::io::Polyhedron;
use compgeom::lp::{
    castability, intersect_halfplanes, lp2d, smallest_enclosing_disc, verify_enclosing_disc,
    HalfPlane, Lp2Options, Lp2Solution,
};
use compgeom::render::{Layer, Section, Style};
use compgeom::{Point3, Vector2};

/// Constraints at random angles, each tangent to a circle about the origin of radius 8–10.
fn tangents(n: usize, seed: u64) -> Vec<HalfPlane> {
    let mut r = Rng::new(seed);
    (0..n)
        .map(|_| {
            let t = r.unit() * std::f64::consts::TAU;
            HalfPlane::new(t.cos(), t.sin(), r.range(8.0, 10.0))
        })
        .collect()
}

/// A pyramid over the square [0, 4]² with its apex at (1, 2, 3) (leaning).
fn pyramid() -> Polyhedron {
    let vertices = vec![
        Point3::new(0.0, 0.0, 0.0),
        Point3::new(4.0, 0.0, 0.0),
        Point3::new(4.0, 4.0, 0.0),
        Point3::new(0.0, 4.0, 0.0),
        Point3::new(1.0, 2.0, 3.0),
    ];
    let faces = vec![
        vec![0, 3, 2, 1],
        vec![0, 1, 4],
        vec![1, 2, 4],
        vec![2, 3, 4],
        vec![3, 0, 4],
    ];
    Polyhedron { vertices, faces }
}

/// Build the "Chapter 4 — linear programming" section.
pub fn section(demo: &Demo) -> Result<Section, CliError> {
    let mut section = Section::new(
        "Chapter 4 — linear programming",
        "Half-planes a·x + b·y <= c, their intersection, and the randomized incremental linear \
         program of the book (§4.3–4.4): expected linear time, every decision exact — corners \
         of the region are constructed points, compared with a floating-point filter and exact \
         rationals when it cannot tell. Unboundedness is handled with a symbolic bounding box. \
         Among several optimal points the lexicographically smallest vertex is reported. The \
         smallest enclosing disc (§4.7) uses exact in-circle tests; casting (§4.1) decides for \
         every facet whether it can be the top facet of a mould.",
    );

    let hs = tangents(40, 4);
    let c = (0.3, 1.0);
    let (sol, time) = timed(|| lp2d(&hs, Vector2::new(c.0, c.1), &Lp2Options::default()));
    let (point, value) = match sol? {
        Lp2Solution::Optimal { point, value, .. } => (point, value),
        other => return Err(CliError::failure(format!("demo LP not optimal: {other:?}"))),
    };
    let pic = lp_picture(&hs, c, &Some(point), "optimal", 0, None, &[])?;
    section.push(
        demo.figure(
            "lp-2d.svg",
            "maximize 0.3·x + y over 40 half-planes tangent to circles of radius 8–10 about the origin",
            &pic,
        )?
        .with_fact("n", "40")
        .with_fact("optimum", format!("({:.4}, {:.4})", point.x, point.y))
        .with_fact("value", format!("{value:.6}"))
        .with_fact("time", format_duration(time)),
    );

    // y >= 0, y <= x + 2, x + 2y >= 1 and the redundant y >= -1: open to the right.
    let open = [
        HalfPlane::new(0.0, -1.0, 0.0),
        HalfPlane::new(-1.0, 1.0, 2.0),
        HalfPlane::new(-1.0, -2.0, -1.0),
        HalfPlane::new(0.0, -1.0, 1.0),
    ];
    let (region, time) = timed(|| intersect_halfplanes(&open, 0));
    let region = region?;
    let title = format!("half-plane intersection: {}", region.kind.name());
    section.push(
        demo.figure(
            "halfplanes-unbounded.svg",
            "four half-planes with an unbounded intersection (a redundant one included)",
            &region_picture(&open, &region, &[], &title),
        )?
        .with_fact("kind", region.kind.name())
        .with_fact("corners", region.vertices.len().to_string())
        .with_fact("time", format_duration(time)),
    );

    // Divide and conquer (§4.2): the two halves' regions C1, C2 and their intersection.
    let hs = tangents(30, 6);
    let (lo, hi) = hs.split_at(hs.len() / 2);
    let c1 = intersect_halfplanes(lo, 0)?;
    let c2 = intersect_halfplanes(hi, 0)?;
    let (merged, time) = timed(|| intersect_halfplanes(&hs, 0));
    let merged = merged?;
    let mut pic = region_picture(&hs, &merged, &[], "INTERSECTHALFPLANES: C = C1 ∩ C2");
    for (name, c, colour) in [
        ("C1 (first 15)", &c1, "#1f77b4"),
        ("C2 (last 15)", &c2, "#ff7f0e"),
    ] {
        pic.add(
            Layer::new(
                name,
                Style::lines(colour).with_stroke_width(2.0).with_dash("6 4"),
            )
            .ring(&c.clipped(40.0)),
        );
    }
    section.push(
        demo.figure(
            "halfplanes-divide.svg",
            "divide and conquer: the regions of the two halves (dashed) and their intersection, merged by sweeping their left and right boundary chains",
            &pic,
        )?
        .with_fact("n", hs.len().to_string())
        .with_fact("corners C1 / C2 / C", format!("{} / {} / {}", c1.vertices.len(), c2.vertices.len(), merged.vertices.len()))
        .with_fact("time", format_duration(time)),
    );

    let pts = disc(300, 50.0, 9);
    let (d, time) = timed(|| smallest_enclosing_disc(&pts, 0));
    let d = d?;
    verify_enclosing_disc(&pts, &d)?;
    let title = format!("smallest enclosing disc: n = 300, radius {:.4}", d.radius);
    section.push(
        demo.figure(
            "enclose-disc.svg",
            "smallest enclosing disc of 300 random points (support points in red)",
            &disc_picture(&pts, &d, &title),
        )?
        .with_fact("support", d.support.len().to_string())
        .with_fact("time", format_duration(time))
        .with_fact("verified", "yes"),
    );

    let mesh = pyramid();
    let (cast, time) = timed(|| castability(&mesh));
    let cast = cast?;
    let top = 0; // the square base
    section.push(
        demo.figure(
            "cast-directions.svg",
            "a leaning pyramid with its base as the top facet: the removal directions d = n + x·u + y·v",
            &direction_picture(&mesh, top)?,
        )?
        .with_fact("facets", mesh.faces.len().to_string())
        .with_fact(
            "castable top facets",
            cast.top_facets
                .iter()
                .map(|t| t.facet.to_string())
                .collect::<Vec<_>>()
                .join(", "),
        )
        .with_fact("time", format_duration(time)),
    );
    Ok(section)
}
