//! Reading and writing geometry at the edge of the library: CSV/whitespace lines, WKT,
//! GeoJSON (RFC 7946) and OFF.
//!
//! This module owns file formats and nothing else: it turns text into kernel types
//! ([`Point2`], [`Segment2`], [`Polygon`], [`Point3`], [`Polyhedron`]) and results
//! ([`Shape`]) back into text. It makes one geometric decision, the orientation of polygon
//! rings written as GeoJSON, and makes it exactly ([`ring_orientation`]).
//!
//! # Errors
//!
//! Malformed input never panics: every reader returns [`Error::Parse`]
//! with a [`Location`](crate::Location) naming the source and, where the format is line
//! oriented or the parser knows it, the 1-based line; its message prints as, e.g.,
//! ``malformed number `1.2.3` in field 1 (points.csv:7)``. NaN and infinite coordinates,
//! including text such as
//! `nan`, `inf` or `1e999` (which overflows to infinity), are parse errors at their line.
//! Empty input (or input holding only comments) is not an error: it gives an empty result.
//!
//! # Formats read
//!
//! | format | points | segments | polygons | 3D points |
//! |---|---|---|---|---|
//! | [`Format::Csv`] | `x,y` lines | `x1,y1,x2,y2` lines | rings of `x,y` lines, see below | `x,y,z` lines |
//! | [`Format::Wkt`] | every vertex | every edge of lines and rings | (MULTI)POLYGON | Z coordinates |
//! | [`Format::GeoJson`] | every vertex | every edge of lines and rings | (Multi)Polygon | 3-element positions |
//! | [`Format::Off`] | — | — | — | the vertices |
//!
//! **CSV / whitespace lines.** Fields are separated by `;` if the line holds one, else by
//! `,` if it holds one, else by spaces and tabs; spaces around a field are ignored (so
//! `1, 2` and `1;2` work, and a decimal comma such as `1,5;2,5` is an error rather than a
//! silent misreading). `#` starts a comment that runs to the end of the line. Blank lines
//! are skipped. The first non-comment line may be a header of words (`x,y`), recognised
//! because none of its fields is a number and each starts with a letter, `_` or `"`; a
//! header anywhere else is an error. Every data line must have exactly the number of
//! fields the reader expects (2, 3 or 4); the error names the line.
//! For polygons (the convention of gnuplot data files), a ring is a run of `x,y` lines;
//! **one** blank line starts the next ring of the same polygon (the first ring is the
//! exterior, the others holes) and **two or more** blank lines start the next polygon.
//! A ring may repeat its first vertex at the end; the repeat is dropped.
//!
//! **WKT.** A file may hold several geometries, one after the other (usually one per
//! line; a geometry may span lines). `#` comments are allowed between them. POINT,
//! MULTIPOINT, LINESTRING, LINEARRING, POLYGON, MULTILINESTRING, MULTIPOLYGON,
//! GEOMETRYCOLLECTION and `EMPTY` are understood; Z and M coordinates are accepted and
//! dropped by the planar readers; an EWKT `SRID=n;` prefix is skipped. An error names the
//! line where the bad geometry starts (or the line of a non-finite number). Hex WKB is
//! not read.
//!
//! **GeoJSON.** A Geometry, Feature or FeatureCollection; features without geometry are
//! skipped; altitudes are dropped by the planar readers. Syntax errors carry serde_json's
//! line; errors found after parsing name the feature ("feature 3") and the line where it
//! starts. As an extension, a
//! bare JSON array is read as coordinates: an array of `[x, y]` positions is a set of
//! points (delaunator's fixture format), an array of rings is one polygon (earcut's), an
//! array of such polygons is a multipolygon.
//!
//! **OFF.** `OFF` header, `#` comments, `nv nf ne` counts, `nv` vertex lines `x y z`,
//! `nf` face lines `n i1 … in` (0-based indices, checked to be in range; trailing colour
//! values allowed). See [`read_off`]. The planar readers refuse OFF
//! ([`Error::InvalidInput`]).
//!
//! # Semantics of the geometry readers
//!
//! - [`read_points`] collects every vertex: points, line-string vertices (all of them,
//!   repeats included) and ring vertices (without the repeated closing vertex).
//! - [`read_segments`] collects every edge of line strings and polygon rings, including
//!   the closing edge of each ring; edges of zero length (from a repeated vertex) are
//!   skipped. Points in a segment input are an error.
//! - [`read_polygons`] collects polygons with rings stored open (the closing vertex
//!   dropped); each ring must have at least 3 vertices. Other geometries are an error.
//! - A WKT or GeoJSON polygon ring must be closed (its last position its first, as both
//!   standards ask): [`read_segments`] and [`read_polygons`] name a ring that is not
//!   (rather than guess whether it was cut short). Bare JSON arrays of rings and CSV
//!   rings may leave the repeat out. [`read_polygons_as_written`] reads open and short
//!   rings for validation, listing the open ones.
//!   `EMPTY` geometries of any kind contribute nothing. [`read_polygon_features`] also
//!   gives each polygon's input feature (its GeoJSON Feature; a MultiPolygon feature
//!   gives several polygons of one feature); [`read_polygon_layer`] the Features'
//!   properties as well, from the same parse.
//!
//! # Formats written
//!
//! [`write_shape`] writes a [`Shape`], [`write_segments`] segments, [`write_points3`]
//! points in space and [`write_off`] a [`Polyhedron`]. Numbers are written with
//! [`format_f64`], so every coordinate reads back bit for bit through the matching reader.
//! See [`write_shape`] for the layout of each format.
//!
//! # Also here
//!
//! - [`read_text`]: a file's (or standard input's) text, with located UTF-8 errors.
//! - `From` conversions between the kernel types and `geo-types` (`Point2` ↔ `Coord` /
//!   `Point`, `Segment2` ↔ `Line`, `Polygon` ↔ `Polygon` with open ↔ closed rings,
//!   `MultiPolygon` ↔ `MultiPolygon`, and `Shape` → `Geometry`).
//!
//! # Complexity
//!
//! Reading and writing are linear in the size of the text (the GeoJSON orientation test is
//! linear in the ring size, with an exact big-integer fallback only for near-zero areas).
//! Measured (opt-level 1, 1,000,000 points, about 40 MB, on a loaded 2-core machine):
//! writing 0.4–0.9 s in each format; reading CSV 0.3–0.7 s, GeoJSON 0.4–0.8 s, WKT
//! 0.8–1.8 s (the ranges are run-to-run noise of the shared machine).

mod csv;
mod geo_types;
mod geojson;
mod geojson_value;
mod off;
mod orient;
mod records;
mod wkt;
mod write;

use crate::kernel::{MultiPolygon, Point2, Point3, Polygon, Segment2};
use crate::{Error, Result};
use std::path::Path;

pub use geojson_value::GeoJsonGeometry;
pub use off::{read_off, read_off_with_lines, write_off, Polyhedron};
pub use orient::ring_orientation;
pub use write::{format_f64, write_points3, write_segments};

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
    /// compgeom's JSON result objects (output only). Given to a reader, `Json` reads
    /// GeoJSON: a `.json` input file is taken to be GeoJSON.
    Json,
}

impl Format {
    /// The format named `name` (`csv`, `wkt`, `geojson`, `off`, `json`), if any.
    /// Case-insensitive; `txt`, `xy`, `xyz` name CSV too.
    ///
    /// ```
    /// use compgeom::io::Format;
    /// assert_eq!(Format::from_name("GeoJSON"), Some(Format::GeoJson));
    /// assert_eq!(Format::from_name("svg"), None);
    /// ```
    pub fn from_name(name: &str) -> Option<Format> {
        match name.to_ascii_lowercase().as_str() {
            "csv" | "txt" | "xy" | "xyz" | "tsv" => Some(Format::Csv),
            "wkt" => Some(Format::Wkt),
            "geojson" => Some(Format::GeoJson),
            "off" => Some(Format::Off),
            "json" => Some(Format::Json),
            _ => None,
        }
    }

    /// The format a file extension implies (`.csv`/`.tsv`/`.txt`/`.xy`/`.xyz` → CSV,
    /// `.wkt`, `.geojson`, `.off`, `.json`). Case-insensitive.
    ///
    /// `.json` gives [`Format::Json`], the right answer for an output file; for an input
    /// file use [`detect_format`], which reads `.json` as GeoJSON (readers also accept
    /// `Json` as GeoJSON).
    ///
    /// ```
    /// use compgeom::io::Format;
    /// use std::path::Path;
    /// assert_eq!(Format::from_extension(Path::new("a/b.WKT")), Some(Format::Wkt));
    /// assert_eq!(Format::from_extension(Path::new("out.json")), Some(Format::Json));
    /// assert_eq!(Format::from_extension(Path::new("noext")), None);
    /// ```
    pub fn from_extension(path: &Path) -> Option<Format> {
        Format::from_name(path.extension()?.to_str()?)
    }

    /// The name of the format, as [`Format::from_name`] reads it.
    pub fn name(self) -> &'static str {
        match self {
            Format::Csv => "csv",
            Format::Wkt => "wkt",
            Format::GeoJson => "geojson",
            Format::Off => "off",
            Format::Json => "json",
        }
    }
}

/// The format of an input: from the path's extension when it says, otherwise sniffed from
/// the content. `Err(UnknownFormat)` when neither decides.
///
/// An input with extension `.json` is GeoJSON. A `.txt` input is sniffed and taken as CSV
/// when sniffing does not decide. Sniffing skips blank lines and `#` comment
/// lines, then: `{` or `[` → GeoJSON; an `OFF` header → OFF; a WKT keyword → WKT; a line of
/// numbers (possibly after one header line of words) → CSV. Empty input (nothing but blank
/// and comment lines) is CSV, which reads as empty.
///
/// ```
/// use compgeom::io::{detect_format, Format};
/// use std::path::Path;
/// assert_eq!(detect_format(Some(Path::new("p.json")), "").unwrap(), Format::GeoJson);
/// assert_eq!(detect_format(None, "# pts\nPOINT (1 2)").unwrap(), Format::Wkt);
/// assert_eq!(detect_format(None, "x y\n1 2\n").unwrap(), Format::Csv);
/// assert_eq!(detect_format(Some(Path::new("a.txt")), "POINT (1 2)").unwrap(), Format::Wkt);
/// assert!(detect_format(None, "hello world\n").is_err());
/// ```
pub fn detect_format(path: Option<&Path>, text: &str) -> Result<Format> {
    let by_extension = path.and_then(Format::from_extension);
    let is_txt = path
        .and_then(|p| p.extension())
        .is_some_and(|e| e.eq_ignore_ascii_case("txt"));
    match by_extension {
        // `.txt` says little: trust the content, and fall back to CSV.
        Some(_) if is_txt => return Ok(sniff(text).unwrap_or(Format::Csv)),
        Some(Format::Json) => return Ok(Format::GeoJson),
        Some(format) => return Ok(format),
        None => {}
    }
    sniff(text).ok_or_else(|| {
        let name = path.map_or_else(|| "input".to_string(), |p| p.display().to_string());
        let first = records::significant_lines(text)
            .next()
            .map(|(_, l)| records::excerpt(l))
            .unwrap_or_default();
        Error::UnknownFormat(format!(
            "cannot tell the format of {name} from its extension or its first line `{first}`; \
             name it (csv, wkt, geojson, off)"
        ))
    })
}

/// The format the content suggests, if any.
fn sniff(text: &str) -> Option<Format> {
    let mut lines = records::significant_lines(text);
    let Some((_, first)) = lines.next() else {
        return Some(Format::Csv);
    };
    let first = first.trim();
    if first.starts_with('{') || first.starts_with('[') {
        return Some(Format::GeoJson);
    }
    let word: String = first
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric())
        .collect();
    if word == "OFF" {
        return Some(Format::Off);
    }
    if wkt::is_keyword(&word) || word.eq_ignore_ascii_case("SRID") {
        return Some(Format::Wkt);
    }
    if csv::is_numeric_line(first) {
        return Some(Format::Csv);
    }
    if csv::is_header_line(first) {
        if let Some((_, second)) = lines.next() {
            if csv::is_numeric_line(second.trim()) {
                return Some(Format::Csv);
            }
        }
    }
    None
}

/// Points in the plane. CSV: one `x,y` / `x y` per line. WKT/GeoJSON: every vertex of every
/// geometry (POINT, MULTIPOINT, LINESTRING, POLYGON, collections, features).
/// `source` names the input in error messages.
///
/// ```
/// use compgeom::io::{read_points, Format};
/// use compgeom::Point2;
/// let pts = read_points("x,y\n0,0\n# a comment\n1.5 2\n", Format::Csv, "pts.csv").unwrap();
/// assert_eq!(pts, vec![Point2::new(0.0, 0.0), Point2::new(1.5, 2.0)]);
/// let err = read_points("0,0\n1,nan\n", Format::Csv, "pts.csv").unwrap_err();
/// assert!(err.to_string().contains("pts.csv:2"));
/// ```
pub fn read_points(text: &str, format: Format, source: &str) -> Result<Vec<Point2>> {
    match format {
        Format::Csv => csv::read_points(text, source),
        Format::Wkt => records::points(&wkt::read(text, source)?, source),
        Format::GeoJson | Format::Json => records::points(&geojson::read(text, source)?, source),
        Format::Off => Err(not_planar(source)),
    }
}

/// Points in space: `x,y,z` lines, or the vertices of an OFF file. WKT and GeoJSON inputs
/// must give every coordinate a z value (`POINT Z (1 2 3)`, `[1, 2, 3]`).
pub fn read_points3(text: &str, format: Format, source: &str) -> Result<Vec<Point3>> {
    match format {
        Format::Csv => csv::read_points3(text, source),
        Format::Off => Ok(read_off(text, source)?.vertices),
        Format::Wkt => records::points3(&wkt::read(text, source)?, source),
        Format::GeoJson | Format::Json => records::points3(&geojson::read(text, source)?, source),
    }
}

/// Segments: `x1,y1,x2,y2` lines, or every edge of WKT/GeoJSON (MULTI)LINESTRINGs and
/// polygon rings.
///
/// ```
/// use compgeom::io::{read_segments, Format};
/// let segs = read_segments("POLYGON ((0 0, 1 0, 0 1, 0 0))", Format::Wkt, "in").unwrap();
/// assert_eq!(segs.len(), 3); // the closing edge included, no zero-length edge
/// ```
pub fn read_segments(text: &str, format: Format, source: &str) -> Result<Vec<Segment2>> {
    match format {
        Format::Csv => csv::read_segments(text, source),
        Format::Wkt => records::segments(&wkt::read(text, source)?, source),
        Format::GeoJson | Format::Json => records::segments(&geojson::read(text, source)?, source),
        Format::Off => Err(not_planar(source)),
    }
}

/// Polygons with holes: WKT (MULTI)POLYGON, GeoJSON (Multi)Polygon / features, or CSV rings
/// (one blank line between rings, two between polygons). Rings come back open.
///
/// ```
/// use compgeom::io::{read_polygons, Format};
/// let mp = read_polygons("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 1 1))",
///                        Format::Wkt, "in").unwrap();
/// assert_eq!(mp.0[0].exterior.len(), 4);
/// assert_eq!(mp.0[0].holes[0].len(), 3);
/// ```
pub fn read_polygons(text: &str, format: Format, source: &str) -> Result<MultiPolygon> {
    match format {
        Format::Csv => csv::read_polygons(text, source, 3),
        Format::Wkt => records::polygons(&wkt::read(text, source)?, source),
        Format::GeoJson | Format::Json => records::polygons(&geojson::read(text, source)?, source),
        Format::Off => Err(not_planar(source)),
    }
}

/// A polygon ring that a WKT or GeoJSON input did not close: it does not end at its first
/// position. [`read_polygons_as_written`] lists them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OpenRing {
    /// The polygon's index among the polygons read.
    pub polygon: usize,
    /// The ring's index in its polygon: 0 for the exterior, `k` for hole `k - 1`.
    pub ring: usize,
    /// The ring's first position.
    pub first: Point2,
    /// Its last position, which should have repeated the first.
    pub last: Point2,
    /// The first and the last position's z, where the input gave them (a ring whose
    /// last position repeats the first in x and y but not in z is open too).
    pub z: Option<(f64, f64)>,
}

impl OpenRing {
    /// How the ring's ends differ, in words: "it ends at (x, y), not at its first
    /// position (x, y)", or, where only z differs, the two z values.
    pub fn how_open(&self) -> String {
        records::how_open(
            (self.first.x, self.first.y, self.z.map(|z| z.0)),
            (self.last.x, self.last.y, self.z.map(|z| z.1)),
        )
    }
}

/// Polygons as an input wrote them, with the input feature of each and the rings it left
/// open: what [`read_polygons_as_written`] reads.
#[derive(Debug, Clone, PartialEq)]
pub struct PolygonsAsWritten {
    /// The polygons, rings open as [`read_polygons`] stores them.
    pub polygons: MultiPolygon,
    /// Per polygon, its input feature, as [`read_polygon_features`] gives it.
    pub features: Vec<usize>,
    /// The WKT and GeoJSON rings that do not end at their first position.
    pub open_rings: Vec<OpenRing>,
}

/// Polygons as the input wrote them, for validation
/// ([`crate::overlay::validity_problems_as_written`] reports what is wrong with them):
/// what [`read_polygons`] rejects as a ring is read here. A ring of fewer than three
/// vertices and a WKT or GeoJSON ring that does not end at its first position (read as
/// if it did, and listed) are not errors. Input that is not polygons at all, or not
/// WKT, GeoJSON or CSV, still is, and so is a non-finite number (every reader rejects
/// the number itself).
///
/// ```
/// use compgeom::io::{read_polygons, read_polygons_as_written, Format};
/// let text = "POLYGON ((0 0, 4 0, 4 4, 0 4))";
/// assert!(read_polygons(text, Format::Wkt, "in").is_err());
/// let read = read_polygons_as_written(text, Format::Wkt, "in").unwrap();
/// assert_eq!(read.polygons.0[0].exterior.len(), 4);
/// let open = &read.open_rings[0];
/// assert_eq!((open.polygon, open.ring), (0, 0));
/// assert_eq!(open.last, compgeom::Point2::new(0.0, 4.0));
/// ```
pub fn read_polygons_as_written(
    text: &str,
    format: Format,
    source: &str,
) -> Result<PolygonsAsWritten> {
    let parts = match format {
        Format::Csv => {
            let polygons = csv::read_polygons(text, source, 1)?;
            return Ok(PolygonsAsWritten {
                features: (0..polygons.0.len()).collect(),
                polygons,
                open_rings: Vec::new(),
            });
        }
        Format::Wkt => wkt::read(text, source)?,
        Format::GeoJson | Format::Json => geojson::read(text, source)?,
        Format::Off => return Err(not_planar(source)),
    };
    let (polygons, open_rings) = records::polygons_as_written(&parts, source)?;
    Ok(PolygonsAsWritten {
        polygons,
        features: records::polygon_features(&parts),
        open_rings,
    })
}

/// A polygon layer: polygons as [`read_polygons`] reads them, with the input feature of
/// each and the features' attributes, from one parse of the text
/// ([`read_polygon_layer`]).
#[derive(Debug, Clone, PartialEq)]
pub struct PolygonLayer {
    /// The polygons.
    pub polygons: MultiPolygon,
    /// Per polygon, its input feature, as [`read_polygon_features`] gives it.
    pub features: Vec<usize>,
    /// Per GeoJSON Feature, in order, its `properties` (null where it has none); empty
    /// for WKT, CSV and GeoJSON without Features.
    pub properties: Vec<serde_json::Value>,
}

/// [`read_polygon_features`] with the GeoJSON Features' properties, which attributes of
/// the input carry to results (as `compgeom overlay` does to its faces). One parse of
/// the text. O(n) for n bytes.
///
/// ```
/// use compgeom::io::{read_polygon_layer, Format};
/// let fc = r#"{"type": "FeatureCollection", "features": [
///   {"type": "Feature", "properties": {"name": "pond"}, "geometry": {"type": "Polygon",
///     "coordinates": [[[0, 0], [1, 0], [0, 1], [0, 0]]]}},
///   {"type": "Feature", "properties": null, "geometry": null}]}"#;
/// let layer = read_polygon_layer(fc, Format::GeoJson, "in").unwrap();
/// assert_eq!(layer.features, vec![0]);
/// assert_eq!(layer.properties[0]["name"], "pond");
/// assert!(layer.properties[1].is_null());
/// ```
pub fn read_polygon_layer(text: &str, format: Format, source: &str) -> Result<PolygonLayer> {
    let (parts, properties) = match format {
        Format::GeoJson | Format::Json => geojson::read_with_properties(text, source)?,
        _ => {
            let (polygons, features) = read_polygon_features(text, format, source)?;
            return Ok(PolygonLayer {
                polygons,
                features,
                properties: Vec::new(),
            });
        }
    };
    Ok(PolygonLayer {
        polygons: records::polygons(&parts, source)?,
        features: records::polygon_features(&parts),
        properties,
    })
}

/// Polygons as [`read_polygons`] reads them, with the input feature of each: the index of
/// the GeoJSON Feature it belongs to (a MultiPolygon feature gives several polygons of one
/// feature), or, for WKT, CSV and bare GeoJSON geometries, its own index (every polygon is
/// a feature).
///
/// ```
/// use compgeom::io::{read_polygon_features, Format};
/// let fc = r#"{"type": "FeatureCollection", "features": [
///   {"type": "Feature", "properties": {}, "geometry": {"type": "MultiPolygon", "coordinates":
///     [[[[0, 0], [1, 0], [0, 1], [0, 0]]], [[[5, 0], [6, 0], [5, 1], [5, 0]]]]}},
///   {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates":
///     [[[2, 0], [3, 0], [2, 1], [2, 0]]]}}]}"#;
/// let (polygons, features) = read_polygon_features(fc, Format::GeoJson, "in").unwrap();
/// assert_eq!(polygons.0.len(), 3);
/// assert_eq!(features, vec![0, 0, 1]);
/// ```
pub fn read_polygon_features(
    text: &str,
    format: Format,
    source: &str,
) -> Result<(MultiPolygon, Vec<usize>)> {
    let parts = match format {
        Format::GeoJson | Format::Json => geojson::read(text, source)?,
        _ => {
            let polygons = read_polygons(text, format, source)?;
            let features = (0..polygons.0.len()).collect();
            return Ok((polygons, features));
        }
    };
    let polygons = records::polygons(&parts, source)?;
    Ok((polygons, records::polygon_features(&parts)))
}

/// The text of the file at `path`, or of standard input when `path` is `-`, ready for the
/// readers. A failure to read is [`Error::Io`] naming the path; bytes
/// that are not UTF-8 are a parse error at the line where they occur.
///
/// ```
/// use compgeom::io::read_text;
/// use std::path::Path;
/// let err = read_text(Path::new("/no/such/file.csv")).unwrap_err();
/// assert!(err.to_string().starts_with("/no/such/file.csv: "));
/// ```
pub fn read_text(path: &Path) -> Result<String> {
    use std::io::Read as _;
    let name = path.display().to_string();
    let io_error = |source| Error::Io {
        path: name.clone(),
        source,
    };
    let mut bytes = Vec::new();
    if path == Path::new("-") {
        std::io::stdin()
            .lock()
            .read_to_end(&mut bytes)
            .map_err(io_error)?;
    } else {
        bytes = std::fs::read(path).map_err(io_error)?;
    }
    String::from_utf8(bytes).map_err(|e| {
        let valid = e.utf8_error().valid_up_to();
        let line = 1 + e.as_bytes()[..valid]
            .iter()
            .filter(|&&b| b == b'\n')
            .count();
        Error::parse(
            "the input is not UTF-8 text",
            crate::Location::new(name.clone(), line),
        )
    })
}

fn not_planar(source: &str) -> Error {
    Error::InvalidInput(format!(
        "{source}: OFF holds a 3D polyhedron; this command reads planar geometry"
    ))
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
///
/// - **CSV**: one `x,y` line per vertex. Polygon rings are written closed (first vertex
///   repeated), one blank line between the rings of a polygon and two blank lines between
///   polygons, so [`read_polygons`] reads them back and gnuplot draws them. `Empty` is the
///   empty string.
/// - **WKT**: `POINT (x y)`, `MULTIPOINT ((x y), …)`, `LINESTRING (…)`, `POLYGON ((…), …)`
///   with closed rings, `MULTIPOLYGON (…)`, `… EMPTY` for empty ones, and
///   `GEOMETRYCOLLECTION EMPTY` for [`Shape::Empty`]. Rings keep their orientation.
/// - **GeoJSON** (and **Json**, which writes the same GeoJSON geometry object): a Geometry
///   object on one line. Rings are closed and oriented as RFC 7946 asks, exteriors
///   counter-clockwise and holes clockwise, decided exactly by [`ring_orientation`]
///   (rings of zero area are left as they are). [`Shape::Empty`] is an empty
///   GeometryCollection.
/// - **OFF**: an error (OFF holds polyhedra; see [`write_off`]).
///
/// Every output but the empty CSV ends with a newline. A NaN or infinite coordinate is an
/// `Err(NonFinite)` naming the vertex.
///
/// ```
/// use compgeom::io::{write_shape, Format, Shape};
/// use compgeom::{Point2, Polygon};
/// let square = Polygon::new(vec![Point2::new(0.0, 0.0), Point2::new(0.0, 1.0),
///                                Point2::new(1.0, 1.0), Point2::new(1.0, 0.0)], vec![]);
/// let wkt = write_shape(&Shape::Polygon(square.clone()), Format::Wkt).unwrap();
/// assert_eq!(wkt, "POLYGON ((0 0, 0 1, 1 1, 1 0, 0 0))\n");
/// // GeoJSON turns the clockwise exterior counter-clockwise.
/// let gj = write_shape(&Shape::Polygon(square), Format::GeoJson).unwrap();
/// assert_eq!(gj, "{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[1,0],[1,1],[0,1],[0,0]]]}\n");
/// ```
pub fn write_shape(shape: &Shape, format: Format) -> Result<String> {
    write::ensure_finite_shape(shape)?;
    match format {
        Format::Csv => Ok(write::csv_shape(shape)),
        Format::Wkt => Ok(write::wkt_shape(shape)),
        Format::GeoJson | Format::Json => Ok(write::geojson_shape(shape)),
        Format::Off => Err(Error::InvalidInput(
            "OFF holds 3D polyhedra; write a planar shape as csv, wkt or geojson".into(),
        )),
    }
}

/// `shape` as a GeoJSON geometry object in a [`serde_json::Value`], for embedding in a
/// larger JSON document (the CLI's `--format json` results). The same geometry, ring
/// orientation and numbers as [`write_shape`] with [`Format::GeoJson`]; serde_json prints
/// the numbers back bit for bit. `Err(NonFinite)` for NaN or infinite coordinates.
/// [`GeoJsonGeometry`] serializes the same without building the value.
///
/// ```
/// use compgeom::io::{to_geojson_value, Shape};
/// use compgeom::Point2;
/// let v = to_geojson_value(&Shape::Point(Point2::new(0.5, -2.0))).unwrap();
/// assert_eq!(v["type"], "Point");
/// assert_eq!(v["coordinates"][1].as_f64(), Some(-2.0));
/// ```
pub fn to_geojson_value(shape: &Shape) -> Result<serde_json::Value> {
    write::ensure_finite_shape(shape)?;
    serde_json::to_value(GeoJsonGeometry(shape))
        .map_err(|e| Error::Verification(format!("cannot make a GeoJSON value: {e}")))
}
