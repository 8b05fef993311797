//! `compgeom locate`: point location (book chapter 6) via `compgeom::locate`: the
//! trapezoidal map of a polygon layer or of segments, with its randomized search
//! structure, answering which feature holds each query point.

use crate::cli::{InputArgs, InputFormat, OutputArgs, OutputFormat};
use crate::error::CliError;
use crate::output;
use clap::Args;
use compgeom::dcel::{Dcel, FaceId, HalfEdgeId};
use compgeom::io::{read_polygon_features, read_segments};
use compgeom::kernel::{orient2d, orient_exact, ExactPoint, Orientation};
use compgeom::locate::{
    polygons_at, polygons_dcel, segments_dcel, Location, PointLocator, SlabLocator, DEFAULT_SEED,
};
use compgeom::render::{Layer, Picture, Style};
use compgeom::{Bbox2, Point2};
use serde_json::{json, Value};
use std::path::PathBuf;

/// `--help` text describing the JSON output.
pub const JSON_HELP: &str = "\
MAP is a polygon layer (GeoJSON (Multi)Polygon features; WKT (MULTI)POLYGON or CSV rings,
each polygon a feature), or a set of segments (WKT (MULTI)LINESTRING, GeoJSON, CSV
x1,y1,x2,y2 lines); polygons are tried first. Polygons may share edges and vertices,
segments may touch and overlap, but boundaries must not cross (an error names the first
crossing pair). POINTS holds the query points (any points format).

JSON output (--format json, the default) is one object:
  results  [{\"feature\": i | null, \"on\": \"face\" | \"edge\" | \"vertex\"}, ...], one per query
           in query order. For a polygon layer, feature is the index of the input
           feature containing the point (the lowest, where several contain it;
           boundaries included), null outside all; for segments, the index of the
           lowest segment through the point, null when the point is on none, and then
           also \"face\": the index of the face of the segments' subdivision holding the point
           (0 = the unbounded face). `on` says whether the point is inside a face, on an
           edge, or at a vertex of the subdivision.
Features are numbered from 0 in reading order (a GeoJSON MultiPolygon feature is one
feature: all its polygons answer with its index; in WKT and CSV every polygon is one
feature, a MULTIPOLYGON giving several). Every decision is exact. --seed picks the
random insertion order (the answers do not depend on it, only the search structure
does). --locator picks the structure answering the queries: trap (the trapezoidal map
and its randomized search structure, expected O(n log n) build, O(n) space) or slab (the
slab method: O(n log n + S) build and O(n + S) space for S (slab, edge) pairs, quadratic
in the worst case; an error beyond 2^28 pairs); both give the same answers in O(log n)
per query. --verify checks the subdivision's and the trapezoidal map's invariants, and
the answers: every query (or 2000 spread over the input, if more; fewer for maps over
10^4 edges, about 2*10^7 / edges) against an exact brute force over all vertices and
edges (the vertex equal to the point, else the edge holding it) and, in a polygon layer,
exact point-in-polygon over every polygon for the features; every query (or 20000
spread) is also answered by the other locator, which must agree (skipped when the slab
method would exceed its size limit). --svg draws the trapezoidal map with its vertical
extensions and the query points coloured by answer (whatever the locator).

Examples:
  compgeom locate districts.geojson --queries stops.csv
  compgeom locate walls.wkt --queries probes.csv --seed 7 --svg map.svg
  compgeom locate districts.geojson --queries stops.csv --locator slab --verify";

/// Arguments of `compgeom locate`.
#[derive(Debug, Clone, Args)]
pub struct LocateArgs {
    /// The map: a polygon layer or segments, or `-` for standard input.
    #[arg(value_name = "MAP")]
    pub map: PathBuf,

    /// Format of MAP. Default: from the file extension, otherwise from the content.
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub input_format: Option<InputFormat>,

    /// Query points (`-` for standard input).
    #[arg(long, value_name = "POINTS")]
    pub queries: PathBuf,

    /// Seed of the random insertion order of the segments.
    #[arg(long, value_name = "N", default_value_t = DEFAULT_SEED)]
    pub seed: u64,

    /// The point-location structure: the trapezoidal map or the slab method.
    #[arg(long, value_enum, value_name = "KIND", default_value = "trap")]
    pub locator: LocatorKind,

    /// Output, picture and verification.
    #[command(flatten)]
    pub output: OutputArgs,
}

/// Which structure answers the queries.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum LocatorKind {
    /// The trapezoidal map with its randomized search structure (book §6.1–6.3).
    Trap,
    /// The slab method (book §6.1, introduction).
    Slab,
}

/// Locate the queries in `dcel` with the chosen structure; the trapezoidal map too when
/// it is used or needed for the picture.
fn answer<V, E, F>(
    dcel: &Dcel<V, E, F>,
    args: &LocateArgs,
    queries: &[Point2],
) -> Result<(Vec<Location>, Option<PointLocator>), CliError> {
    let trap = if args.locator == LocatorKind::Trap || args.output.svg.is_some() {
        Some(PointLocator::from_dcel_with_seed(dcel, args.seed)?)
    } else {
        None
    };
    let found = match (&trap, args.locator) {
        (Some(t), LocatorKind::Trap) => t.locate_all(queries)?,
        _ => SlabLocator::from_dcel(dcel)?.locate_all(queries)?,
    };
    if args.output.verify {
        verify(dcel, args, queries, &found)?;
    }
    Ok((found, trap))
}

/// How many queries the O(n)-per-query brute force checks for a map of `edges` edges:
/// 2000, fewer for large maps (about 2·10⁷ edge tests in all).
fn brute_sample(edges: usize) -> usize {
    (20_000_000 / edges.max(1)).clamp(20, 2000)
}

/// The indices of at most `most` queries spread over `0..n` (all when n <= most).
fn sample(n: usize, most: usize) -> impl Iterator<Item = usize> {
    let step = n.div_ceil(most).max(1);
    (0..n).step_by(step)
}

/// `--verify`: the subdivision's and the map's invariants, the answers against exact brute
/// force on a sample, and against the other locator.
fn verify<V, E, F>(
    dcel: &Dcel<V, E, F>,
    args: &LocateArgs,
    queries: &[Point2],
    found: &[Location],
) -> Result<(), CliError> {
    dcel.validate()?;
    let trap = PointLocator::from_dcel_with_seed(dcel, args.seed)?;
    trap.map().validate()?;
    let fail = |i: usize, what: String| {
        let q = queries[i];
        CliError::failure(format!(
            "verification failed at query {i} ({}, {}): {what}",
            q.x, q.y
        ))
    };
    for i in sample(queries.len(), brute_sample(dcel.edge_count())) {
        let want = brute_location(dcel, queries[i]);
        let ok = match (want, found[i]) {
            (Some(Location::Edge(h)), Location::Edge(g)) => h.0 / 2 == g.0 / 2,
            (Some(w), g) => w == g,
            (None, g) => matches!(g, Location::Face(_)),
        };
        if !ok {
            return Err(fail(
                i,
                format!("answered {:?}, brute force {:?}", found[i], want),
            ));
        }
    }
    let idx: Vec<usize> = sample(queries.len(), 20_000).collect();
    let qs: Vec<Point2> = idx.iter().map(|&i| queries[i]).collect();
    let other = match args.locator {
        // Beyond the slab method's size limit only the brute force checks the answers.
        LocatorKind::Trap => match SlabLocator::from_dcel(dcel) {
            Ok(slab) => slab.locate_all(&qs)?,
            Err(_) => return Ok(()),
        },
        LocatorKind::Slab => trap.locate_all(&qs)?,
    };
    for (k, &i) in idx.iter().enumerate() {
        if other[k] != found[i] {
            return Err(fail(
                i,
                format!("the locators disagree: {:?} and {:?}", found[i], other[k]),
            ));
        }
    }
    Ok(())
}

/// Exact brute force over every vertex and edge: the vertex equal to `q`, else the edge
/// (its left-to-right half-edge) holding `q` in its interior, else `None` (in a face).
fn brute_location<V, E, F>(d: &Dcel<V, E, F>, q: Point2) -> Option<Location> {
    let qe = ExactPoint::Input(q);
    if let Some(v) = d
        .vertex_ids()
        .find(|&v| d.vertex(v).point.compare_xy(&qe).is_eq())
    {
        return Some(Location::Vertex(v));
    }
    (0..d.edge_count()).find_map(|e| {
        let h = HalfEdgeId(2 * e);
        let (a, b) = (d.origin_point(h), d.origin_point(d.twin(h)));
        let (lo, hi, fwd) = if a.compare_xy(b).is_lt() {
            (a, b, h)
        } else {
            (b, a, d.twin(h))
        };
        (orient_exact(a, b, &qe) == Orientation::Collinear
            && lo.compare_xy(&qe).is_lt()
            && qe.compare_xy(hi).is_lt())
        .then_some(Location::Edge(fwd))
    })
}

/// The polygons whose closed region holds `q`, by exact point-in-polygon (crossing number
/// of the rightward ray; boundary points count as inside).
fn brute_polygons(polys: &compgeom::MultiPolygon, q: Point2) -> Vec<usize> {
    let on = |a: Point2, b: Point2| {
        orient2d(a, b, q) == Orientation::Collinear
            && q.x >= a.x.min(b.x)
            && q.x <= a.x.max(b.x)
            && q.y >= a.y.min(b.y)
            && q.y <= a.y.max(b.y)
    };
    let mut out = Vec::new();
    for (i, poly) in polys.0.iter().enumerate() {
        let (mut boundary, mut inside) = (false, false);
        for ring in poly.rings() {
            for j in 0..ring.len() {
                let (a, b) = (ring[j], ring[(j + 1) % ring.len()]);
                boundary |= on(a, b);
                if (a.y > q.y) != (b.y > q.y) {
                    let o = orient2d(a, b, q);
                    let wanted = if b.y > a.y {
                        Orientation::CounterClockwise
                    } else {
                        Orientation::Clockwise
                    };
                    if o == wanted {
                        inside = !inside;
                    }
                }
            }
        }
        if boundary || inside {
            out.push(i);
        }
    }
    out
}

/// The map read: polygons, or segments.
enum Map {
    /// The polygons and the input feature of each (ascending).
    Polygons(compgeom::MultiPolygon, Vec<usize>),
    Segments(Vec<compgeom::Segment2>),
}

fn read_map(args: &LocateArgs) -> Result<Map, CliError> {
    let src = InputArgs {
        input: args.map.clone(),
        input_format: args.input_format,
    }
    .read()?;
    match read_polygon_features(&src.text, src.format, &src.name) {
        Ok((p, features)) => Ok(Map::Polygons(p, features)),
        Err(pe) => match read_segments(&src.text, src.format, &src.name) {
            Ok(s) => Ok(Map::Segments(s)),
            Err(_) => Err(pe.into()),
        },
    }
}

/// Run `compgeom locate`.
pub fn run(args: &LocateArgs) -> Result<(), CliError> {
    if args.output.format() != OutputFormat::Json {
        return Err(args.output.unsupported("locate", "json only"));
    }
    let map = read_map(args)?;
    let queries = InputArgs {
        input: args.queries.clone(),
        input_format: None,
    }
    .read_points()?;
    // (locator, per-query JSON, per-query colour key for the picture)
    let (loc, results, faces) = match &map {
        Map::Polygons(polys, features) => {
            let dcel = polygons_dcel(polys)?;
            let (found, loc) = answer(&dcel, args, &queries)?;
            let mut results = Vec::with_capacity(found.len());
            let mut keys = Vec::with_capacity(found.len());
            if args.output.verify {
                for i in sample(queries.len(), brute_sample(dcel.edge_count())) {
                    let (got, want) = (
                        polygons_at(&dcel, found[i]),
                        brute_polygons(polys, queries[i]),
                    );
                    if got != want {
                        let q = queries[i];
                        return Err(CliError::failure(format!(
                            "verification failed at query {i} ({}, {}): polygons {got:?}, brute force {want:?}",
                            q.x, q.y
                        )));
                    }
                }
            }
            for l in found {
                // Features ascend with the polygons: the lowest polygon's is the lowest.
                let feature = polygons_at(&dcel, l).first().map(|&p| features[p]);
                results.push(json!({"feature": feature, "on": on(l)}));
                keys.push((feature, l));
            }
            (loc, results, keys)
        }
        Map::Segments(segs) => {
            let dcel = segments_dcel(segs)?;
            let (found, loc) = answer(&dcel, args, &queries)?;
            let mut results = Vec::with_capacity(found.len());
            let mut keys = Vec::with_capacity(found.len());
            for l in found {
                let through = |h: compgeom::dcel::HalfEdgeId| {
                    dcel.half_edge(h).data.iter().map(|s| s.segment).min()
                };
                let v = match l {
                    Location::Face(f) => {
                        keys.push((Some(f.0), l));
                        json!({"feature": Value::Null, "on": "face", "face": f.0})
                    }
                    Location::Edge(h) => {
                        keys.push((None, l));
                        json!({"feature": through(h), "on": "edge"})
                    }
                    Location::Vertex(v) => {
                        keys.push((None, l));
                        json!({"feature": dcel.around(v).filter_map(through).min(), "on": "vertex"})
                    }
                };
                results.push(v);
            }
            (loc, results, keys)
        }
    };
    if let (Some(svg), Some(loc)) = (&args.output.svg, &loc) {
        let (segs, is_polygons) = match &map {
            Map::Polygons(p, _) => (polygon_edges(p), true),
            Map::Segments(s) => (s.clone(), false),
        };
        let pic = locate_picture(loc, &segs, is_polygons, &queries, &faces);
        output::write_atomic(svg, pic.to_svg_string().as_bytes())?;
    }
    let mut value = json!({ "results": results });
    if args.output.verify {
        value["verified"] = json!(true);
    }
    let text = serde_json::to_string(&value)
        .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?;
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

fn on(l: Location) -> &'static str {
    match l {
        Location::Face(_) => "face",
        Location::Edge(_) => "edge",
        Location::Vertex(_) => "vertex",
    }
}

const PALETTE: [&str; 8] = [
    "#1f77b4", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#ff7f0e",
];

/// The edges of every ring of a polygon layer.
pub fn polygon_edges(p: &compgeom::MultiPolygon) -> Vec<compgeom::Segment2> {
    p.0.iter()
        .flat_map(|poly| poly.rings())
        .flat_map(|r| {
            (0..r.len()).map(move |i| compgeom::Segment2::new(r[i], r[(i + 1) % r.len()]))
        })
        .collect()
}

/// The trapezoidal map (trapezoids with their vertical sides), the map's segments `segs`,
/// and the queries coloured by answer: `keys` gives per query the feature (polygon
/// layers) or face (segments) and the location; red on an edge, black at a vertex, grey
/// outside every feature.
pub fn locate_picture(
    loc: &PointLocator,
    segs: &[compgeom::Segment2],
    is_polygons: bool,
    queries: &[Point2],
    keys: &[(Option<usize>, Location)],
) -> Picture {
    let m = loc.map();
    let st = m.stats();
    let mut bbox = Bbox2::of_points(m.vertices().iter().chain(queries));
    if bbox.is_empty() {
        bbox = Bbox2::of_points(&[Point2::new(0.0, 0.0), Point2::new(1.0, 1.0)]);
    }
    let pad = 0.08 * bbox.width().max(bbox.height()).max(1e-9);
    let bbox = Bbox2::of_points(&[
        Point2::new(bbox.min.x - pad, bbox.min.y - pad),
        Point2::new(bbox.max.x + pad, bbox.max.y + pad),
    ]);
    let mut pic = Picture::new(800, 640).with_title(format!(
        "trapezoidal map: {} segments, {} trapezoids, search structure {} nodes, depth {}",
        st.segments, st.trapezoids, st.nodes, st.depth
    ));
    let mut traps = Layer::new(
        format!(
            "trapezoids ({}) and vertical extensions",
            m.trapezoid_count()
        ),
        Style::area("#7f7f7f")
            .with_fill("#c6dbef")
            .with_fill_opacity(0.35)
            .with_stroke_width(0.8)
            .with_dash("4 3"),
    );
    for t in 0..m.trapezoid_count() {
        let poly = m.trapezoid_polygon(t, &bbox);
        let (a, b) = (poly[0].x, poly[1].x);
        if b > a {
            traps = traps.ring(&poly);
        }
    }
    pic.add(traps);
    pic.add(Layer::new("map", Style::lines("#333333").with_stroke_width(1.6)).segments(segs));
    // Legend order: features (faces) ascending, then edge, vertex, outside.
    type Group<'a> = ((u8, usize), String, &'a str, Vec<Point2>);
    let mut groups: Vec<Group> = Vec::new();
    let mut add = |order: (u8, usize), name: String, colour: &'static str, q: Point2| {
        if let Some(g) = groups.iter_mut().find(|g| g.0 == order) {
            g.3.push(q);
        } else {
            groups.push((order, name, colour, vec![q]));
        }
    };
    for (&q, &(key, l)) in queries.iter().zip(keys) {
        match l {
            Location::Vertex(_) => add((2, 0), "queries at a vertex".into(), "#000000", q),
            Location::Edge(_) => add((1, 0), "queries on an edge".into(), "#d62728", q),
            Location::Face(f) => match key {
                Some(k) if f != FaceId::UNBOUNDED || is_polygons => {
                    let what = if is_polygons { "feature" } else { "face" };
                    add(
                        (0, k),
                        format!("queries in {what} {k}"),
                        PALETTE[k % PALETTE.len()],
                        q,
                    )
                }
                _ => add((3, 0), "queries outside".into(), "#999999", q),
            },
        }
    }
    groups.sort_by_key(|g| g.0);
    for (_, name, colour, pts) in groups {
        pic.add(Layer::new(name, Style::points(colour).with_radius(3.5)).points(&pts));
    }
    pic
}
