//! The gallery's chapter 3 section: an art gallery floor plan cut into monotone pieces by
//! MAKEMONOTONE (vertex types marked), its triangulation, and the guards of the
//! 3-colouring; every result checked by the exact verifiers.

use super::{format_duration, timed, Demo};
use crate::commands::guard::{guard_all, picture as guard_picture};
use crate::commands::triangulate::{picture, pieces_of, triangulate_all};
use crate::error::CliError;
use compgeom::render::Section;
use compgeom::{MultiPolygon, Point2, Polygon};

fn ring(pts: &[(f64, f64)]) -> Vec<Point2> {
    pts.iter().map(|&(x, y)| Point2::new(x, y)).collect()
}

/// A gallery floor plan: a hall with alcoves on both sides, a corridor and a side room.
fn gallery() -> Polygon {
    Polygon::new(
        ring(&[
            (0., 0.),
            (4., 0.),
            (4., 2.),
            (5., 2.),
            (5., 0.),
            (9., 0.),
            (9., 1.),
            (12., 1.),
            (12., -1.),
            (15., -1.),
            (15., 4.),
            (12., 4.),
            (12., 2.),
            (9., 2.),
            (9., 6.),
            (7., 6.),
            (7., 4.),
            (6., 6.),
            (3., 6.),
            (2., 4.),
            (1., 6.),
            (0., 6.),
        ]),
        vec![],
    )
}

/// The same plan with a square pillar in the hall.
fn gallery_with_pillar() -> Polygon {
    let mut p = gallery();
    p.holes
        .push(ring(&[(2., 2.), (2., 3.), (3., 3.), (3., 2.)]));
    p
}

/// The plan with two pillars in the hall, the second touching the first at a corner.
fn gallery_with_pillars() -> Polygon {
    let mut p = gallery_with_pillar();
    p.holes
        .push(ring(&[(3., 3.), (4., 4.), (5., 3.), (4., 3.5)]));
    p
}

/// The section.
pub fn section(demo: &Demo) -> Result<Section, CliError> {
    let mut section = Section::new(
        "Chapter 3 — polygon triangulation and the art gallery",
        "A gallery floor plan with a pillar, cut into y-monotone pieces by the MAKEMONOTONE \
         sweep (start, end, split, merge and regular vertices marked), each piece \
         triangulated in linear time; then the plan without the pillar, 3-coloured along \
         the dual tree, with guards at the smallest colour class (at most ⌊n/3⌋). With \
         pillars (holes) the dual graph has cycles: the colouring follows a spanning tree, \
         so each triangle still has three colours and a guard, with at most ⌊(n + 2h)/3⌋ \
         guards, but a vertex may carry two colours (ringed). Every triangulation and \
         colouring is checked exactly.",
    );
    let pillar = MultiPolygon(vec![gallery_with_pillar()]);
    let (t, time) = timed(|| triangulate_all(pillar.clone(), true));
    let t = t?;
    let (parts, pieces) = pieces_of(&pillar)?;
    let title = format!(
        "monotone pieces: {} pieces, {} diagonals",
        pieces.len(),
        parts.iter().map(|m| m.diagonals.len()).sum::<usize>()
    );
    section.push(demo.figure(
        "triangulate-pieces.svg",
        "Monotone pieces and vertex types",
        &picture(&t, Some(&parts), title),
    )?);
    let title = format!(
        "triangulation: {} vertices, 1 hole, {} triangles",
        t.vertices.len(),
        t.triangles.len()
    );
    section.push(
        demo.figure(
            "triangulate-triangles.svg",
            "Triangulation (n − 2 + 2h triangles)",
            &picture(&t, None, title),
        )?
        .with_fact("time", format_duration(time)),
    );
    let plain = MultiPolygon(vec![gallery()]);
    let t = triangulate_all(plain, true)?;
    let (g, time) = timed(|| guard_all(&t, true));
    let g = g?;
    let title = format!(
        "art gallery: {} vertices, {} guards (bound {})",
        t.vertices.len(),
        g.guards.len(),
        t.vertices.len() / 3
    );
    section.push(
        demo.figure(
            "guard-gallery.svg",
            "Guards of the 3-colouring",
            &guard_picture(&t, &g, title),
        )?
        .with_fact("time", format_duration(time)),
    );
    let pillars = MultiPolygon(vec![gallery_with_pillars()]);
    let t = triangulate_all(pillars, true)?;
    let g = guard_all(&t, true)?;
    let h = t.parts[0].holes();
    let title = format!(
        "art gallery with {h} pillars: {} vertices, {} guards (bound {})",
        t.vertices.len(),
        g.guards.len(),
        (t.vertices.len() + 2 * h) / 3
    );
    section.push(demo.figure(
        "guard-gallery-pillars.svg",
        "Guards with holes: the colouring is cut open along h diagonals",
        &guard_picture(&t, &g, title),
    )?);
    Ok(section)
}
