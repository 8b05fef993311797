//! The gallery's chapter 7 section: Voronoi diagrams of a random disc, a degenerate grid
//! with duplicates (degree-4 vertices), exactly cocircular lattice points (one vertex of
//! high degree), the default (dual of the Delaunay triangulation) drawn over Fortune's sweep,
//! cells clipped to a non-convex polygon with a hole, the farthest-point diagram, and
//! Fortune's sweep caught in the middle: the beach line and the sweep line.

use super::samples::{disc, grid_with_duplicates};
use super::{format_duration, timed, Demo};
use crate::commands::voronoi::voronoi_picture;
use crate::error::CliError;
use compgeom::render::{Layer, Section, Style};
use compgeom::voronoi::{
    beach_line_at, clip_cells, fortune_voronoi, verify_cells, verify_voronoi, ClipRegion,
};
use compgeom::voronoi::{
    clip_cells_to_polygon, dual_voronoi, farthest_point_voronoi, verify_farthest,
    verify_polygon_cells, VoronoiDiagram,
};
use compgeom::{MultiPolygon, Polygon};
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
         box around the sites and listed in input order. The default method is faster: the \
         dual of the exact Delaunay triangulation (adjacent triangles with exactly the same \
         circumcircle merge into one vertex); both give the same diagram. Cells can be \
         clipped to any polygon, and the farthest-point diagram comes from the convex hull.",
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
        let picture = voronoi_picture(&d, &whole(cells), &[region.ring().to_vec()], &title);
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
    section.push(dual_figure(demo)?);
    section.push(clip_figure(demo)?);
    section.push(farthest_figure(demo)?);
    section.push(beach_line_figure(demo)?);
    Ok(section)
}

/// Rings as one-piece cells.
fn whole(rings: Vec<Vec<Point2>>) -> Vec<MultiPolygon> {
    rings
        .into_iter()
        .map(|r| {
            if r.is_empty() {
                MultiPolygon::default()
            } else {
                MultiPolygon(vec![Polygon::new(r, Vec::new())])
            }
        })
        .collect()
}

/// The edges of a diagram clipped to a box, as segments (rays cut at the box).
fn edge_segments(d: &VoronoiDiagram, reach: f64) -> Vec<Segment2> {
    (0..d.edge_count())
        .filter_map(|k| {
            let h = 2 * k;
            let (u, w) = (d.half_edges[h].origin, d.destination(h));
            let dir = d.direction(h);
            let len = dir.x.hypot(dir.y).max(f64::MIN_POSITIVE);
            let far = |p: Point2, sign: f64| {
                Point2::new(
                    p.x + sign * dir.x / len * reach,
                    p.y + sign * dir.y / len * reach,
                )
            };
            match (u, w) {
                (Some(u), Some(w)) => Some(Segment2::new(d.vertices[u].point, d.vertices[w].point)),
                (Some(u), None) => Some(Segment2::new(
                    d.vertices[u].point,
                    far(d.vertices[u].point, 1.0),
                )),
                (None, Some(w)) => Some(Segment2::new(
                    far(d.vertices[w].point, -1.0),
                    d.vertices[w].point,
                )),
                (None, None) => None,
            }
        })
        .collect()
}

/// The default (dual of Delaunay) over Fortune's sweep on a jittered grid: the same edges.
fn dual_figure(demo: &Demo) -> Result<compgeom::render::Figure, CliError> {
    // A grid with duplicates (degree-4 vertices) next to random points.
    let mut points = grid_with_duplicates(6, 3);
    points.extend(
        disc(30, 3.0, 9)
            .iter()
            .map(|p| Point2::new(p.x + 9.0, p.y + 2.5)),
    );
    let (f, t_fortune) = timed(|| fortune_voronoi(&points));
    let f = f?;
    let (d, t_dual) = timed(|| dual_voronoi(&points));
    let d = d?;
    verify_voronoi(&points, &d)?;
    verify_voronoi(&points, &f)?;
    let same = d.vertices.len() == f.vertices.len()
        && d.edge_count() == f.edge_count()
        && d.neighbours() == f.neighbours();
    if !same {
        return Err(CliError::failure(
            "the dual and Fortune's sweep differ".to_string(),
        ));
    }
    let region = ClipRegion::around(&d.sites, 0.1)?;
    let cells = clip_cells(&d, &region);
    let mut pic = voronoi_picture(
        &d,
        &whole(cells),
        &[region.ring().to_vec()],
        &format!(
            "Dual of Delaunay (thick) over Fortune's sweep (dashed): {} vertices, {} edges each",
            d.vertices.len(),
            d.edge_count()
        ),
    );
    let reach = 100.0;
    let mut thick = Layer::new(
        "default: dual of the Delaunay triangulation",
        Style::lines("#1f77b4").with_stroke_width(3.0),
    );
    for s in edge_segments(&d, reach)
        .into_iter()
        .filter_map(|s| clip_segment(s, &region))
    {
        thick = thick.segment(s);
    }
    let mut dashed = Layer::new(
        "Fortune's sweep",
        Style::lines("#d62728")
            .with_dash("5 4")
            .with_stroke_width(1.5),
    );
    for s in edge_segments(&f, reach)
        .into_iter()
        .filter_map(|s| clip_segment(s, &region))
    {
        dashed = dashed.segment(s);
    }
    pic.add(thick);
    pic.add(dashed);
    Ok(demo
        .figure(
            "voronoi-dual-vs-fortune.svg",
            "The default method (the dual of the Delaunay triangulation, thick blue) and \
             Fortune's sweep (dashed red) give the same diagram, vertex for vertex and edge \
             for edge, here on a grid with duplicates plus random points",
            &pic,
        )?
        .with_fact("n", points.len().to_string())
        .with_fact("vertices", d.vertices.len().to_string())
        .with_fact("time, dual", format_duration(t_dual))
        .with_fact("time, Fortune", format_duration(t_fortune))
        .with_fact("same diagram", "yes"))
}

/// A segment cut to the clip box (for drawing rays); `None` when it misses the box.
fn clip_segment(s: Segment2, region: &ClipRegion) -> Option<Segment2> {
    let b = compgeom::Bbox2::of_points(region.ring());
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    let (dx, dy) = (s.b.x - s.a.x, s.b.y - s.a.y);
    for (p, q) in [
        (-dx, s.a.x - b.min.x),
        (dx, b.max.x - s.a.x),
        (-dy, s.a.y - b.min.y),
        (dy, b.max.y - s.a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
            continue;
        }
        let r = q / p;
        if p < 0.0 {
            t0 = t0.max(r);
        } else {
            t1 = t1.min(r);
        }
    }
    if t0 >= t1 {
        return None;
    }
    let at = |t: f64| Point2::new(s.a.x + t * dx, s.a.y + t * dy);
    Some(Segment2::new(at(t0), at(t1)))
}

/// Cells clipped to a non-convex polygon with a hole (an E shape with a window).
fn clip_figure(demo: &Demo) -> Result<compgeom::render::Figure, CliError> {
    let points = disc(120, 100.0, 21);
    let p = |x: f64, y: f64| Point2::new(x, y);
    let shape = vec![
        p(-90.0, -90.0),
        p(90.0, -90.0),
        p(90.0, -50.0),
        p(-30.0, -50.0),
        p(-30.0, -15.0),
        p(60.0, -15.0),
        p(60.0, 20.0),
        p(-30.0, 20.0),
        p(-30.0, 50.0),
        p(90.0, 50.0),
        p(90.0, 90.0),
        p(-90.0, 90.0),
    ];
    let window = vec![
        p(-70.0, -30.0),
        p(-70.0, 30.0),
        p(-50.0, 30.0),
        p(-50.0, -30.0),
    ];
    let clip = MultiPolygon(vec![Polygon::new(shape, vec![window])]);
    let d = dual_voronoi(&points)?;
    let (cells, time) = timed(|| clip_cells_to_polygon(&d, &clip));
    let cells = cells?;
    verify_polygon_cells(&d, &clip, &cells)?;
    let split = cells.iter().filter(|c| c.0.len() > 1).count();
    let rings: Vec<Vec<Point2>> = clip.0.iter().flat_map(|q| q.rings().cloned()).collect();
    let pic = voronoi_picture(
        &d,
        &cells,
        &rings,
        &format!(
            "Cells clipped to a non-convex polygon with a hole: {split} cells in several pieces"
        ),
    );
    Ok(demo
        .figure(
            "voronoi-clip-polygon.svg",
            "Voronoi cells clipped to a non-convex polygon with a hole: cells away from the \
             boundary are classified exactly and kept whole or dropped, cells the boundary \
             crosses are intersected with it by the exact boolean operation (some fall apart \
             into several pieces)",
            &pic,
        )?
        .with_fact("sites", d.sites.len().to_string())
        .with_fact("cells in pieces", split.to_string())
        .with_fact("time", format_duration(time))
        .with_fact("verified", "yes"))
}

/// The farthest-point Voronoi diagram of a random disc.
fn farthest_figure(demo: &Demo) -> Result<compgeom::render::Figure, CliError> {
    let points = disc(60, 100.0, 17);
    let (f, time) = timed(|| farthest_point_voronoi(&points));
    let f = f?;
    verify_farthest(&points, &f)?;
    let region = ClipRegion::rect(-160.0, -160.0, 160.0, 160.0)?;
    let cells = whole(f.cells(&region));
    let hull: Vec<Point2> = f.hull.iter().map(|&s| f.sites[s]).collect();
    let d = VoronoiDiagram {
        sites: f.sites.clone(),
        site_input_index: f.site_input_index.clone(),
        input_to_site: f.input_to_site.clone(),
        vertices: f.vertices.clone(),
        half_edges: f.half_edges.clone(),
        site_half_edge: f.site_half_edge.clone(),
    };
    let mut pic = voronoi_picture(
        &d,
        &cells,
        &[region.ring().to_vec()],
        &format!(
            "Farthest-point Voronoi diagram: {} hull corners have cells, {} vertices",
            f.hull.len(),
            f.vertices.len()
        ),
    );
    pic.add(
        Layer::new(
            "convex hull",
            Style::lines("#2ca02c").with_stroke_width(2.0),
        )
        .ring(&hull),
    );
    Ok(demo
        .figure(
            "voronoi-farthest.svg",
            "The farthest-point Voronoi diagram: each cell holds the points for which its site \
             is the farthest; only hull corners have cells, all unbounded, and the diagram is a \
             tree (from the farthest-point Delaunay triangulation of the hull, built by \
             randomized incremental insertion with exact flips)",
            &pic,
        )?
        .with_fact("n", points.len().to_string())
        .with_fact("hull corners", f.hull.len().to_string())
        .with_fact("vertices", f.vertices.len().to_string())
        .with_fact("time", format_duration(time))
        .with_fact("verified", "yes"))
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
        &whole(cells),
        &[region.ring().to_vec()],
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
