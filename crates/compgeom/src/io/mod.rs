//! Reading and writing geometry at the edge of the library: CSV/whitespace lines, WKT,
//! GeoJSON (RFC 7946) and OFF. Errors carry the source name and line.
//! (API skeleton; the I/O work fills it in.)

use crate::kernel::{MultiPolygon, Point2, Point3, Polygon, Segment2};
use crate::Result;
use std::path::Path;

/// A file format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// `x,y` or `x y` lines (`x,y,z` for 3D; `x1,y1,x2,y2` for segments); `#` comments.
    Csv,
    /// Well-known text.
    Wkt,
    /// GeoJSON (RFC 7946).
    GeoJson,
    /// Object File Format (3D polyhedra).
    Off,
    /// compgeom's JSON result objects (output only).
    Json,
}

impl Format {
    /// The format named `name` (`csv`, `wkt`, `geojson`, `off`, `json`), if any.
    pub fn from_name(name: &str) -> Option<Format> {
        let _ = name;
        None
    }

    /// The format a file extension implies (`.csv`/`.txt`/`.xy`, `.wkt`, `.geojson`, `.off`, `.json`).
    pub fn from_extension(path: &Path) -> Option<Format> {
        let _ = path;
        None
    }
}

/// The format of an input: from the path's extension when it says, otherwise sniffed from
/// the content. `Err(UnknownFormat)` when neither decides.
pub fn detect_format(path: Option<&Path>, text: &str) -> Result<Format> {
    let _ = (path, text);
    Ok(Format::Csv)
}

/// Points in the plane. CSV: one `x,y` / `x y` per line. WKT/GeoJSON: every vertex of every
/// geometry (POINT, MULTIPOINT, LINESTRING, POLYGON, collections, features).
/// `source` names the input in error messages.
pub fn read_points(text: &str, format: Format, source: &str) -> Result<Vec<Point2>> {
    let _ = (text, format, source);
    Ok(Vec::new())
}

/// Points in space: `x,y,z` lines, or the vertices of an OFF file.
pub fn read_points3(text: &str, format: Format, source: &str) -> Result<Vec<Point3>> {
    let _ = (text, format, source);
    Ok(Vec::new())
}

/// Segments: `x1,y1,x2,y2` lines, or every edge of WKT/GeoJSON (MULTI)LINESTRINGs and
/// polygon rings.
pub fn read_segments(text: &str, format: Format, source: &str) -> Result<Vec<Segment2>> {
    let _ = (text, format, source);
    Ok(Vec::new())
}

/// Polygons with holes: WKT (MULTI)POLYGON, GeoJSON (Multi)Polygon / features.
pub fn read_polygons(text: &str, format: Format, source: &str) -> Result<MultiPolygon> {
    let _ = (text, format, source);
    Ok(MultiPolygon::default())
}

/// Shortest decimal text that parses back to exactly `x`.
pub fn format_f64(x: f64) -> String {
    format!("{x:?}")
}

/// An output geometry, in the shapes results take.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// Nothing (e.g. the hull of no points).
    Empty,
    /// One point.
    Point(Point2),
    /// Several points.
    MultiPoint(Vec<Point2>),
    /// An open polyline.
    LineString(Vec<Point2>),
    /// A polygon; written with the format's ring orientation (RFC 7946 for GeoJSON).
    Polygon(Polygon),
    /// Several polygons.
    MultiPolygon(MultiPolygon),
}

/// `shape` as text in `format` (CSV: one vertex per line; WKT; GeoJSON geometry).
pub fn write_shape(shape: &Shape, format: Format) -> Result<String> {
    let _ = (shape, format);
    Ok(String::new())
}
