//! The gallery's chapter 7 section: Voronoi diagrams of a random disc, a degenerate grid
//! with duplicates (degree-4 vertices), exactly cocircular lattice points (one vertex of
//! high degree), and Fortune's sweep caught in the middle: the beach line and the sweep line.

use super::samples::{disc, grid_with_duplicates};
use super::{format_duration, timed, Demo};
use crate::commands::voronoi::voronoi_picture;
use crate::error::CliError;
use compgeom::render::{Layer, Section, Style};
use compgeom::voronoi::{
    beach_line_at, clip_cells, fortune_voronoi, verify_cells, verify_voronoi, ClipRegion,
};
use compgeom::{Point2, Segment2};

/// Integer points on the circle x² + y² = r2.
fn lattice_circle(r2: i64) -> Vec<Point2> {
    let r = (r2 as f64).sqrt() as i64 + 1;
    let mut v = Vec::new();
    for x in -r..=r {
        for y in -r..=r {
            if x * x + y * y == r2 {
                v.push(Point2::new(x as f64, y as f64));
            }
        }
    }
    v
}

/// Build the "Chapter 7 — Voronoi diagram" section.
pub fn section(demo: &Demo) -> Result<Section, CliError> {
    let mut circle = lattice_circle(5525);
    circle.push(Point2::new(0.0, 0.0));
    let runs = [
        (
            "voronoi-disc.svg",
            "300 random points in a disc",
            disc(300, 100.0, 7),
        ),
        (
            "voronoi-grid.svg",
            "9×9 integer grid with duplicates: every inner vertex has degree 4",
            grid_with_duplicates(9, 11),
        ),
        (
            "voronoi-cocircular.svg",
            "the 48 integer points on x² + y² = 5525 and the centre: exactly cocircular",
            circle,
        ),
    ];
    let mut section = Section::new(
        "Chapter 7 — Voronoi diagram",
        "The Voronoi diagram splits the plane into cells, one per site: the points nearer to \
         that site than to any other. compgeom computes it with Fortune's sweep (the book's \
         VORONOIDIAGRAM, O(n log n)): a horizontal line sweeps down, the beach line of \
         parabolic arcs follows it, site events insert arcs and circle events remove them and \
         create vertices. Voronoi vertices and breakpoints are constructed points, and every \
         decision about them is exact (a floating-point filter, then exact big-integer \
         arithmetic), so duplicates, grids and cocircular sites come out right: four or more \
         sites on one empty circle give one vertex of higher degree. Cells are clipped to a \
         box around the sites and listed in input order.",
    );
    for (file, caption, points) in runs {
        let (d, time) = timed(|| fortune_voronoi(&points));
        let d = d?;
        verify_voronoi(&points, &d)?;
        let region = ClipRegion::around(&d.sites, 0.1)?;
        let cells = clip_cells(&d, &region);
        verify_cells(&d, &region, &cells)?;
        let title = format!(
            "Voronoi diagram: n = {}, {} vertices, {} edges",
            d.sites.len(),
            d.vertices.len(),
            d.edge_count()
        );
        let picture = voronoi_picture(&d, &cells, &region, &title);
        let max_degree = d.vertices.iter().map(|v| v.sites.len()).max().unwrap_or(0);
        section.push(
            demo.figure(file, caption, &picture)?
                .with_fact("n", points.len().to_string())
                .with_fact("sites", d.sites.len().to_string())
                .with_fact("vertices", d.vertices.len().to_string())
                .with_fact("max vertex degree", max_degree.to_string())
                .with_fact("time", format_duration(time))
                .with_fact("verified", "yes"),
        );
    }
    section.push(beach_line_figure(demo)?);
    Ok(section)
}

/// Fortune's sweep halted half-way: the final cells faintly, the sweep line, the beach
/// line, and the sites already swept past.
fn beach_line_figure(demo: &Demo) -> Result<compgeom::render::Figure, CliError> {
    let points = disc(40, 100.0, 5);
    let sweep_y = -10.0;
    let d = fortune_voronoi(&points)?;
    verify_voronoi(&points, &d)?;
    let region = ClipRegion::rect(-110.0, -110.0, 110.0, 110.0)?;
    let cells = clip_cells(&d, &region);
    let snap = beach_line_at(&points, sweep_y)?;
    let mut pic = voronoi_picture(
        &d,
        &cells,
        &region,
        &format!("Fortune's sweep at y = {sweep_y}: {} arcs", snap.arcs.len()),
    );
    let beach: Vec<Point2> = (0..=440)
        .map(|i| -110.0 + i as f64 * 0.5)
        .filter_map(|x| snap.height_at(x).map(|y| Point2::new(x, y.min(110.0))))
        .collect();
    pic.add(
        Layer::new("beach line", Style::lines("#000000").with_stroke_width(2.0)).polyline(&beach),
    );
    pic.add(
        Layer::new("sweep line", Style::lines("#d62728").with_dash("6 4")).segment(Segment2::new(
            Point2::new(-110.0, sweep_y),
            Point2::new(110.0, sweep_y),
        )),
    );
    let swept: Vec<Point2> = snap
        .sites
        .iter()
        .copied()
        .filter(|p| p.y >= sweep_y)
        .collect();
    pic.add(
        Layer::new(
            "sites above the sweep line",
            Style::points("#2ca02c").with_radius(4.0),
        )
        .points(&swept),
    );
    Ok(demo
        .figure(
            "voronoi-beach-line.svg",
            "Fortune's sweep half-way: the beach line (black) of parabolic arcs above the \
             sweep line (red); its breakpoints trace the Voronoi edges",
            &pic,
        )?
        .with_fact("arcs", snap.arcs.len().to_string())
        .with_fact("sweep y", sweep_y.to_string()))
}
