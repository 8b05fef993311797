//! The common middle of the WKT and GeoJSON readers: geometries flattened into parts
//! (a point, a line string, a polygon's rings), each remembering where it came from, and
//! the conversions from parts to points, segments, polygons and 3D points.

use super::OpenRing;
use crate::kernel::{MultiPolygon, Point2, Point3, Polygon, Segment2};
use crate::{Error, Location, Result};

/// A coordinate as read: x, y and, when the input gave one, z (M values are dropped).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Coord {
    pub x: f64,
    pub y: f64,
    pub z: Option<f64>,
}

/// The shape of one part.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Body {
    Point(Coord),
    Line(Vec<Coord>),
    /// Rings as read (possibly closed); the first is the exterior.
    Polygon(Vec<Vec<Coord>>),
}

/// One part of the input and where it came from.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Part {
    pub body: Body,
    /// The geometry type as the input spelled it, e.g. `MULTIPOINT` or `LineString`.
    pub kind: String,
    /// The element of the input, e.g. "geometry 3" or "feature 2".
    pub what: String,
    /// 1-based line, when known.
    pub line: Option<usize>,
    /// The 0-based index of the GeoJSON Feature it belongs to (`None` outside features).
    pub feature: Option<usize>,
    /// Whether the format closes polygon rings (WKT and GeoJSON geometries repeat a
    /// ring's first position at its end; bare JSON arrays of rings need not): an open
    /// ring is then an error where rings are read as rings.
    pub rings_closed: bool,
}

impl Part {
    fn error(&self, source: &str, message: &str) -> Error {
        Error::parse(
            format!("{} ({}): {message}", self.what, self.kind),
            Location {
                source: Some(source.to_string()),
                line: self.line,
            },
        )
    }

    fn coords(&self) -> Box<dyn Iterator<Item = &Coord> + '_> {
        match &self.body {
            Body::Point(c) => Box::new(std::iter::once(c)),
            Body::Line(cs) => Box::new(cs.iter()),
            Body::Polygon(rings) => Box::new(rings.iter().flatten()),
        }
    }
}

/// `Err` naming the part if any coordinate is NaN or infinite.
pub(crate) fn check_finite(parts: &[Part], source: &str) -> Result<()> {
    for part in parts {
        for c in part.coords() {
            let bad = [Some(c.x), Some(c.y), c.z]
                .into_iter()
                .flatten()
                .find(|v| !v.is_finite());
            if let Some(v) = bad {
                return Err(part.error(source, &format!("non-finite coordinate {v}")));
            }
        }
    }
    Ok(())
}

fn p2(c: &Coord) -> Point2 {
    Point2::new(c.x, c.y)
}

/// The first and last positions of `ring` when the format closes rings
/// ([`Part::rings_closed`]) and the ring does not end at its first position (all
/// coordinates compared, z too where given: -0 equals 0). A ring of one position is left
/// to the vertex count.
fn unclosed<'a>(part: &Part, ring: &'a [Coord]) -> Option<(&'a Coord, &'a Coord)> {
    match ring {
        [first, .., last] if part.rings_closed && first != last => Some((first, last)),
        _ => None,
    }
}

/// How a ring's first and last positions `(x, y, z)` differ, in words (see
/// [`super::OpenRing::how_open`]).
pub(crate) fn how_open(first: (f64, f64, Option<f64>), last: (f64, f64, Option<f64>)) -> String {
    match (first, last) {
        ((x0, y0, Some(z0)), (x1, y1, Some(z1))) if (x0, y0) == (x1, y1) => {
            format!("it ends at ({x1}, {y1}) as it starts, but at z = {z1}, not its first z = {z0}")
        }
        ((x0, y0, _), (x1, y1, _)) => {
            format!("it ends at ({x1}, {y1}), not at its first position ({x0}, {y0})")
        }
    }
}

/// `Err` naming ring `i` (0-based) of `part` when it is [`unclosed`].
fn check_closed(part: &Part, i: usize, ring: &[Coord], source: &str) -> Result<()> {
    match unclosed(part, ring) {
        Some((first, last)) => Err(part.error(
            source,
            &format!(
                "ring {} is not closed: {}; a WKT or GeoJSON polygon ring repeats its first \
                 position at its end",
                i + 1,
                how_open((first.x, first.y, first.z), (last.x, last.y, last.z))
            ),
        )),
        None => Ok(()),
    }
}

/// The ring without its repeated closing vertex (if the last vertex equals the first).
pub(crate) fn open_ring<T: PartialEq + Copy>(ring: &[T]) -> &[T] {
    match ring {
        [first, .., last] if first == last => &ring[..ring.len() - 1],
        _ => ring,
    }
}

/// Every vertex: points, all line-string vertices, ring vertices without the closing one.
pub(crate) fn points(parts: &[Part], source: &str) -> Result<Vec<Point2>> {
    check_finite(parts, source)?;
    let mut out = Vec::new();
    for part in parts {
        match &part.body {
            Body::Point(c) => out.push(p2(c)),
            Body::Line(cs) => out.extend(cs.iter().map(p2)),
            Body::Polygon(rings) => {
                for ring in rings {
                    let ring: Vec<Point2> = ring.iter().map(p2).collect();
                    out.extend_from_slice(open_ring(&ring));
                }
            }
        }
    }
    Ok(out)
}

/// Every vertex in space; each must have a z value.
pub(crate) fn points3(parts: &[Part], source: &str) -> Result<Vec<Point3>> {
    check_finite(parts, source)?;
    let mut out = Vec::new();
    for part in parts {
        let mut coords: Vec<Coord> = Vec::new();
        match &part.body {
            Body::Point(c) => coords.push(*c),
            Body::Line(cs) => coords.extend_from_slice(cs),
            Body::Polygon(rings) => {
                for ring in rings {
                    coords.extend_from_slice(open_ring(ring));
                }
            }
        }
        for c in coords {
            let z =
                c.z.ok_or_else(|| part.error(source, "a coordinate has no z value"))?;
            out.push(Point3::new(c.x, c.y, z));
        }
    }
    Ok(out)
}

/// Edges of the polyline `vs`, skipping zero-length ones.
fn push_edges(vs: &[Point2], out: &mut Vec<Segment2>) {
    out.extend(
        vs.windows(2)
            .filter(|w| w[0] != w[1])
            .map(|w| Segment2::new(w[0], w[1])),
    );
}

/// Every edge of line strings and polygon rings (closing edges included, zero-length
/// edges skipped). Points are an error, and so is a ring the format should have closed
/// and did not.
pub(crate) fn segments(parts: &[Part], source: &str) -> Result<Vec<Segment2>> {
    check_finite(parts, source)?;
    let mut out = Vec::new();
    for part in parts {
        match &part.body {
            Body::Point(_) => {
                return Err(part.error(
                    source,
                    "a point has no edges; segments come from line strings and polygon rings",
                ))
            }
            Body::Line(cs) => push_edges(&cs.iter().map(p2).collect::<Vec<_>>(), &mut out),
            Body::Polygon(rings) => {
                for (i, ring) in rings.iter().enumerate() {
                    check_closed(part, i, ring, source)?;
                    let ring: Vec<Point2> = ring.iter().map(p2).collect();
                    let mut ring = open_ring(&ring).to_vec();
                    if ring.len() >= 3 {
                        ring.push(ring[0]);
                    }
                    push_edges(&ring, &mut out);
                }
            }
        }
    }
    Ok(out)
}

/// For every polygon [`polygons`] makes of `parts`, the index of its input feature: the
/// GeoJSON Feature it came from, else the polygon's own index.
pub(crate) fn polygon_features(parts: &[Part]) -> Vec<usize> {
    parts
        .iter()
        .filter(|p| matches!(&p.body, Body::Polygon(rings) if !all_empty(rings)))
        .enumerate()
        .map(|(i, p)| p.feature.unwrap_or(i))
        .collect()
}

/// Whether a polygon has no points: no rings, or only empty ones (GeoJSON's `[[]]`), is
/// no polygon, as an EMPTY geometry contributes nothing.
fn all_empty(rings: &[Vec<Coord>]) -> bool {
    rings.iter().all(Vec::is_empty)
}

/// Polygons with open rings of at least 3 vertices; anything else is an error, and so
/// is a ring the format should have closed and did not.
pub(crate) fn polygons(parts: &[Part], source: &str) -> Result<MultiPolygon> {
    check_finite(parts, source)?;
    Ok(polygons_by(parts, source, Checks::All)?.0)
}

/// Polygons as written, for validation: rings of any length and coordinates of any
/// value, and rings the format should have closed and did not (read as if closed), listed.
/// Only what is not a polygon at all is an error.
pub(crate) fn polygons_as_written(
    parts: &[Part],
    source: &str,
) -> Result<(MultiPolygon, Vec<OpenRing>)> {
    polygons_by(parts, source, Checks::NotAPolygon)
}

/// What [`polygons_by`] treats as an error.
#[derive(Clone, Copy, PartialEq)]
enum Checks {
    /// Open rings (where the format closes them) and rings of fewer than 3 vertices.
    All,
    /// Only parts that are not polygons.
    NotAPolygon,
}

/// The polygons of `parts` (rings without their closing repeat) and the rings the format
/// should have closed and did not.
fn polygons_by(
    parts: &[Part],
    source: &str,
    checks: Checks,
) -> Result<(MultiPolygon, Vec<OpenRing>)> {
    let mut out = Vec::new();
    let mut open_rings = Vec::new();
    for part in parts {
        let Body::Polygon(rings) = &part.body else {
            return Err(part.error(source, "not a polygon"));
        };
        if all_empty(rings) {
            continue;
        }
        let mut open = Vec::with_capacity(rings.len());
        for (i, ring) in rings.iter().enumerate() {
            if i > 0 && ring.is_empty() {
                // (An EMPTY hole is no hole, as EMPTY geometries contribute nothing.)
                continue;
            }
            if checks == Checks::All {
                check_closed(part, i, ring, source)?;
            } else if let Some((first, last)) = unclosed(part, ring) {
                open_rings.push(OpenRing {
                    polygon: out.len(),
                    ring: open.len(),
                    first: p2(first),
                    last: p2(last),
                    z: first.z.zip(last.z),
                });
            }
            let ring: Vec<Point2> = ring.iter().map(p2).collect();
            let ring = open_ring(&ring).to_vec();
            if checks == Checks::All && ring.len() < 3 {
                return Err(part.error(
                    source,
                    &format!(
                        "ring {} has {} vertices (not counting a closing repeat); a polygon ring needs at least 3",
                        i + 1,
                        ring.len()
                    ),
                ));
            }
            open.push(ring);
        }
        let mut open = open.into_iter();
        if let Some(exterior) = open.next() {
            out.push(Polygon::new(exterior, open.collect()));
        }
    }
    Ok((MultiPolygon(out), open_rings))
}

/// Lines that hold something: `(1-based line number, line without its comment)`, skipping
/// blank and comment-only lines and a leading byte-order mark.
pub(crate) fn significant_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    text.lines()
        .enumerate()
        .map(|(i, l)| (i + 1, strip_comment(l)))
        .filter(|(_, l)| !l.trim().is_empty())
}

/// The line up to its `#` comment.
pub(crate) fn strip_comment(line: &str) -> &str {
    line.split_once('#').map_or(line, |(before, _)| before)
}

/// A short excerpt of `s` for an error message.
pub(crate) fn excerpt(s: &str) -> String {
    const MAX: usize = 40;
    let s = s.trim();
    if s.chars().count() <= MAX {
        s.to_string()
    } else {
        let cut: String = s.chars().take(MAX).collect();
        format!("{cut}…")
    }
}
