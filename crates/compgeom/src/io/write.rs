//! Writers: numbers that read back bit for bit, and shapes as CSV, WKT and GeoJSON.

use super::orient::ring_orientation;
use super::{Format, Shape};
use crate::kernel::{ensure_finite, Orientation, Point2, Point3, Polygon, Segment2};
use crate::{Error, Result};
use std::fmt::Write as _;

/// Shortest decimal text that parses back to exactly `x`.
///
/// Among the plain form (`0.1`, `123`) and the scientific form (`1e-7`, `1e200`), both
/// with the fewest significant digits that identify `x`, the shorter is chosen (the plain
/// one on a tie). Integral values have no `.0`; negative zero is `-0`. Every output is a
/// valid JSON and WKT number for finite `x` (`NaN`, `inf` and `-inf` for the others, which
/// the writers never emit: they reject non-finite coordinates).
///
/// ```
/// use compgeom::io::format_f64;
/// assert_eq!(format_f64(0.1), "0.1");
/// assert_eq!(format_f64(3.0), "3");
/// assert_eq!(format_f64(1e15), "1e15");
/// assert_eq!(format_f64(5e-324), "5e-324");
/// assert_eq!(format_f64(-0.0), "-0");
/// assert_eq!(format_f64(0.1 + 0.2).parse::<f64>().unwrap(), 0.1 + 0.2);
/// ```
pub fn format_f64(x: f64) -> String {
    let mut s = String::new();
    push_f64(&mut s, x);
    s
}

/// Append [`format_f64`]`(x)` to `out` without allocating.
pub(crate) fn push_f64(out: &mut String, x: f64) {
    if !x.is_finite() {
        let _ = write!(out, "{x}");
        return;
    }
    // The scientific form carries the shortest digits (at most 17) and the exponent; the
    // plain form is laid out from them when it is not longer.
    let start = out.len();
    let _ = write!(out, "{x:e}");
    let sci = &out[start..];
    let (mantissa, exponent) = sci.split_once('e').unwrap_or((sci, "0"));
    let exponent: i64 = exponent.parse().unwrap_or(0);
    let mut digits = [0u8; 24];
    let mut d = 0;
    for c in mantissa.bytes().filter(u8::is_ascii_digit) {
        digits[d] = c;
        d += 1;
    }
    let negative = x.is_sign_negative();
    let di = d as i64;
    let body_len = if exponent >= 0 {
        if di <= exponent + 1 {
            exponent + 1
        } else {
            di + 1
        }
    } else {
        // "0." then −exponent−1 zeros then the digits.
        2 + (-exponent - 1) + di
    };
    if body_len + i64::from(negative) > sci.len() as i64 {
        return; // the scientific form is shorter
    }
    out.truncate(start);
    if negative {
        out.push('-');
    }
    let digits = std::str::from_utf8(&digits[..d]).unwrap_or("0");
    if exponent >= 0 {
        let int_len = (exponent + 1) as usize;
        if d <= int_len {
            out.push_str(digits);
            out.extend(std::iter::repeat('0').take(int_len - d));
        } else {
            out.push_str(&digits[..int_len]);
            out.push('.');
            out.push_str(&digits[int_len..]);
        }
    } else {
        out.push_str("0.");
        out.extend(std::iter::repeat('0').take((-exponent - 1) as usize));
        out.push_str(digits);
    }
}

/// `Err(NonFinite)` if any vertex of `shape` is NaN or infinite.
pub(crate) fn ensure_finite_shape(shape: &Shape) -> Result<()> {
    let check = |ps: &[Point2]| ensure_finite(ps, "output vertex");
    match shape {
        Shape::Empty => Ok(()),
        Shape::Point(p) => check(std::slice::from_ref(p)),
        Shape::MultiPoint(ps) | Shape::LineString(ps) => check(ps),
        Shape::Polygon(p) => p.rings().try_for_each(|r| check(r)),
        Shape::MultiPolygon(mp) => {
            mp.0.iter()
                .try_for_each(|p| p.rings().try_for_each(|r| check(r)))
        }
    }
}

fn csv_point(out: &mut String, p: Point2) {
    push_f64(out, p.x);
    out.push(',');
    push_f64(out, p.y);
    out.push('\n');
}

/// Closed copy of a ring (first vertex repeated at the end), for formats that close rings.
fn closed(ring: &[Point2]) -> impl Iterator<Item = Point2> + '_ {
    ring.iter().copied().chain(ring.first().copied())
}

fn csv_polygon(out: &mut String, p: &Polygon) {
    let mut first = true;
    for ring in p.rings().filter(|r| !r.is_empty()) {
        if !first {
            out.push('\n');
        }
        first = false;
        for v in closed(ring) {
            csv_point(out, v);
        }
    }
}

/// CSV: one `x,y` line per vertex; see [`super::write_shape`].
pub(crate) fn csv_shape(shape: &Shape) -> String {
    let mut out = String::new();
    match shape {
        Shape::Empty => {}
        Shape::Point(p) => csv_point(&mut out, *p),
        Shape::MultiPoint(ps) | Shape::LineString(ps) => {
            ps.iter().for_each(|p| csv_point(&mut out, *p))
        }
        Shape::Polygon(p) => csv_polygon(&mut out, p),
        Shape::MultiPolygon(mp) => {
            let mut first = true;
            for p in mp.0.iter().filter(|p| !p.exterior.is_empty()) {
                if !first {
                    out.push_str("\n\n");
                }
                first = false;
                csv_polygon(&mut out, p);
            }
        }
    }
    out
}

fn wkt_coords(out: &mut String, vs: impl Iterator<Item = Point2>) {
    out.push('(');
    for (i, v) in vs.enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        push_f64(out, v.x);
        out.push(' ');
        push_f64(out, v.y);
    }
    out.push(')');
}

fn wkt_polygon_body(out: &mut String, p: &Polygon) {
    out.push('(');
    for (i, ring) in p.rings().filter(|r| !r.is_empty()).enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        wkt_coords(out, closed(ring));
    }
    out.push(')');
}

/// WKT; see [`super::write_shape`].
pub(crate) fn wkt_shape(shape: &Shape) -> String {
    let mut out = String::new();
    match shape {
        Shape::Empty => out.push_str("GEOMETRYCOLLECTION EMPTY"),
        Shape::Point(p) => {
            out.push_str("POINT ");
            wkt_coords(&mut out, std::iter::once(*p));
        }
        Shape::MultiPoint(ps) if ps.is_empty() => out.push_str("MULTIPOINT EMPTY"),
        Shape::MultiPoint(ps) => {
            out.push_str("MULTIPOINT (");
            for (i, p) in ps.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                wkt_coords(&mut out, std::iter::once(*p));
            }
            out.push(')');
        }
        Shape::LineString(ps) if ps.is_empty() => out.push_str("LINESTRING EMPTY"),
        Shape::LineString(ps) => {
            out.push_str("LINESTRING ");
            wkt_coords(&mut out, ps.iter().copied());
        }
        Shape::Polygon(p) if p.exterior.is_empty() => out.push_str("POLYGON EMPTY"),
        Shape::Polygon(p) => {
            out.push_str("POLYGON ");
            wkt_polygon_body(&mut out, p);
        }
        Shape::MultiPolygon(mp) => {
            let parts: Vec<&Polygon> = mp.0.iter().filter(|p| !p.exterior.is_empty()).collect();
            if parts.is_empty() {
                out.push_str("MULTIPOLYGON EMPTY");
            } else {
                out.push_str("MULTIPOLYGON (");
                for (i, p) in parts.iter().enumerate() {
                    if i > 0 {
                        out.push_str(", ");
                    }
                    wkt_polygon_body(&mut out, p);
                }
                out.push(')');
            }
        }
    }
    out.push('\n');
    out
}

fn json_position(out: &mut String, p: Point2) {
    out.push('[');
    push_f64(out, p.x);
    out.push(',');
    push_f64(out, p.y);
    out.push(']');
}

fn json_positions(out: &mut String, vs: impl Iterator<Item = Point2>) {
    out.push('[');
    for (i, v) in vs.enumerate() {
        if i > 0 {
            out.push(',');
        }
        json_position(out, v);
    }
    out.push(']');
}

/// A ring (not empty) closed and turned to the orientation RFC 7946 wants (`want`),
/// unless its area is zero, in which case it is kept as given; reversed, the first
/// vertex stays first.
fn oriented_closed(
    ring: &[Point2],
    want: Orientation,
) -> impl Iterator<Item = Point2> + Clone + '_ {
    let o = ring_orientation(ring);
    let reverse = o != Orientation::Collinear && o != want;
    let n = ring.len();
    // Position k of the closed ring (k = 0..=n): k mod n, or (n − k) mod n reversed.
    (0..=n).map(move |k| ring[if reverse { (n - k) % n } else { k % n }])
}

/// The rings of a GeoJSON polygon's coordinates: the exterior counter-clockwise and the
/// holes clockwise, each closed; empty rings (and every ring of a polygon whose exterior
/// is empty) left out.
pub(super) fn geojson_rings(
    p: &Polygon,
) -> impl Iterator<Item = impl Iterator<Item = Point2> + Clone + '_> + '_ {
    let holes = if p.exterior.is_empty() {
        &p.holes[..0]
    } else {
        &p.holes[..]
    };
    let exterior = std::iter::once((&p.exterior, Orientation::CounterClockwise));
    let holes = holes.iter().map(|h| (h, Orientation::Clockwise));
    exterior
        .chain(holes)
        .filter(|(ring, _)| !ring.is_empty())
        .map(|(ring, want)| oriented_closed(ring, want))
}

fn json_polygon_rings(out: &mut String, p: &Polygon) {
    out.push('[');
    for (i, ring) in geojson_rings(p).enumerate() {
        if i > 0 {
            out.push(',');
        }
        json_positions(out, ring);
    }
    out.push(']');
}

/// A GeoJSON geometry object; see [`super::write_shape`].
pub(crate) fn geojson_shape(shape: &Shape) -> String {
    let mut out = String::new();
    match shape {
        Shape::Empty => out.push_str(r#"{"type":"GeometryCollection","geometries":[]}"#),
        Shape::Point(p) => {
            out.push_str(r#"{"type":"Point","coordinates":"#);
            json_position(&mut out, *p);
            out.push('}');
        }
        Shape::MultiPoint(ps) => {
            out.push_str(r#"{"type":"MultiPoint","coordinates":"#);
            json_positions(&mut out, ps.iter().copied());
            out.push('}');
        }
        Shape::LineString(ps) => {
            out.push_str(r#"{"type":"LineString","coordinates":"#);
            json_positions(&mut out, ps.iter().copied());
            out.push('}');
        }
        Shape::Polygon(p) => {
            out.push_str(r#"{"type":"Polygon","coordinates":"#);
            json_polygon_rings(&mut out, p);
            out.push('}');
        }
        Shape::MultiPolygon(mp) => {
            out.push_str(r#"{"type":"MultiPolygon","coordinates":["#);
            let parts = mp.0.iter().filter(|p| !p.exterior.is_empty());
            for (i, p) in parts.enumerate() {
                if i > 0 {
                    out.push(',');
                }
                json_polygon_rings(&mut out, p);
            }
            out.push_str("]}");
        }
    }
    out.push('\n');
    out
}

/// Segments as text: CSV `x1,y1,x2,y2` lines, a WKT `MULTILINESTRING` of two-point lines
/// (`MULTILINESTRING EMPTY` for none), or a GeoJSON `MultiLineString` geometry (also for
/// [`Format::Json`]). They read back with [`super::read_segments`] (zero-length segments
/// only through CSV: the WKT and GeoJSON readers skip zero-length edges).
/// `Err` for OFF and for non-finite coordinates.
///
/// ```
/// use compgeom::io::{write_segments, Format};
/// use compgeom::{Point2, Segment2};
/// let s = [Segment2::new(Point2::new(0.0, 0.0), Point2::new(1.5, 2.0))];
/// assert_eq!(write_segments(&s, Format::Wkt).unwrap(), "MULTILINESTRING ((0 0, 1.5 2))\n");
/// assert_eq!(write_segments(&s, Format::Csv).unwrap(), "0,0,1.5,2\n");
/// ```
pub fn write_segments(segments: &[Segment2], format: Format) -> Result<String> {
    let ends: Vec<Point2> = segments.iter().flat_map(|s| [s.a, s.b]).collect();
    ensure_finite(&ends, "segment endpoint")?;
    let mut out = String::new();
    match format {
        Format::Csv => {
            for s in segments {
                let _ = writeln!(
                    out,
                    "{},{},{},{}",
                    format_f64(s.a.x),
                    format_f64(s.a.y),
                    format_f64(s.b.x),
                    format_f64(s.b.y)
                );
            }
        }
        Format::Wkt if segments.is_empty() => out.push_str("MULTILINESTRING EMPTY\n"),
        Format::Wkt => {
            out.push_str("MULTILINESTRING (");
            for (i, s) in segments.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                wkt_coords(&mut out, [s.a, s.b].into_iter());
            }
            out.push_str(")\n");
        }
        Format::GeoJson | Format::Json => {
            out.push_str(r#"{"type":"MultiLineString","coordinates":["#);
            for (i, s) in segments.iter().enumerate() {
                if i > 0 {
                    out.push(',');
                }
                json_positions(&mut out, [s.a, s.b].into_iter());
            }
            out.push_str("]}\n");
        }
        Format::Off => {
            return Err(Error::InvalidInput(
                "OFF holds 3D polyhedra; write segments as csv, wkt or geojson".into(),
            ))
        }
    }
    Ok(out)
}

/// Points in space as text: CSV `x,y,z` lines, WKT `MULTIPOINT Z ((x y z), …)` (or
/// `MULTIPOINT Z EMPTY`), a GeoJSON `MultiPoint` with 3-element positions (also for
/// [`Format::Json`]), or OFF (the vertices, no faces). Reads back with
/// [`super::read_points3`] bit for bit. `Err(NonFinite)` for NaN or infinite coordinates.
///
/// ```
/// use compgeom::io::{write_points3, Format};
/// use compgeom::Point3;
/// let p = [Point3::new(1.0, 2.0, 0.5)];
/// assert_eq!(write_points3(&p, Format::Wkt).unwrap(), "MULTIPOINT Z ((1 2 0.5))\n");
/// ```
pub fn write_points3(points: &[Point3], format: Format) -> Result<String> {
    if let Some(i) = points.iter().position(|p| !p.is_finite()) {
        let p = points[i];
        let value = [p.x, p.y, p.z]
            .into_iter()
            .find(|v| !v.is_finite())
            .unwrap_or(f64::NAN);
        return Err(Error::NonFinite {
            what: format!("output point {i}"),
            value,
        });
    }
    let mut out = String::new();
    let push3 = |out: &mut String, p: &Point3, sep: char| {
        push_f64(out, p.x);
        out.push(sep);
        push_f64(out, p.y);
        out.push(sep);
        push_f64(out, p.z);
    };
    match format {
        Format::Csv => {
            for p in points {
                push3(&mut out, p, ',');
                out.push('\n');
            }
        }
        Format::Wkt if points.is_empty() => out.push_str("MULTIPOINT Z EMPTY\n"),
        Format::Wkt => {
            out.push_str("MULTIPOINT Z (");
            for (i, p) in points.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                out.push('(');
                push3(&mut out, p, ' ');
                out.push(')');
            }
            out.push_str(")\n");
        }
        Format::GeoJson | Format::Json => {
            out.push_str(r#"{"type":"MultiPoint","coordinates":["#);
            for (i, p) in points.iter().enumerate() {
                if i > 0 {
                    out.push(',');
                }
                out.push('[');
                push3(&mut out, p, ',');
                out.push(']');
            }
            out.push_str("]}\n");
        }
        Format::Off => {
            out = super::write_off(&super::Polyhedron {
                vertices: points.to_vec(),
                faces: Vec::new(),
            });
        }
    }
    Ok(out)
}
