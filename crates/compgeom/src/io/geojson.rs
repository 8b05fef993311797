//! GeoJSON input (RFC 7946) through the `geojson` crate, plus bare JSON coordinate arrays.
//! Errors found after parsing carry the line where the offending feature starts.

use super::records::{Body, Coord, Part};
use crate::{Error, Location, Result};
use geojson::{GeoJson, Geometry, GeometryValue, Position};
use serde_json::Value;

/// A parse error from serde_json, with its line.
fn json_error(e: &serde_json::Error, source: &str) -> Error {
    let text = e.to_string();
    // serde_json appends " at line L column C"; the location carries the line instead.
    let message = match text.rfind(" at line ") {
        Some(k) => text[..k].to_string(),
        None => text,
    };
    let column = e.column();
    let message = if e.line() > 0 {
        format!("invalid GeoJSON: {message} (column {column})")
    } else {
        format!("invalid GeoJSON: {message}")
    };
    Error::parse(message, json_location(e, source))
}

/// The file and line of a serde_json error.
fn json_location(e: &serde_json::Error, source: &str) -> Location {
    Location {
        source: Some(source.to_string()),
        line: (e.line() > 0).then_some(e.line()),
    }
}

fn coord(p: &Position) -> Coord {
    let s = p.as_slice();
    Coord {
        x: s[0],
        y: s[1],
        z: s.get(2).copied(),
    }
}

fn line_coords(ps: &[Position]) -> Vec<Coord> {
    ps.iter().map(coord).collect()
}

fn rings(rs: &[Vec<Position>]) -> Vec<Vec<Coord>> {
    rs.iter().map(|r| line_coords(r)).collect()
}

/// The line where each element of the top-level `"features"` array starts, found by a
/// scan of the JSON structure (strings and nesting), so that errors found after parsing
/// can name a line. Only meaningful for text serde_json has accepted.
fn feature_lines(text: &str) -> Vec<usize> {
    let b = text.as_bytes();
    let mut lines = Vec::new();
    let (mut i, mut line, mut depth) = (0, 1, 0usize);
    let mut key_is_features = false;
    let mut in_features = false;
    while i < b.len() {
        match b[i] {
            b'\n' => line += 1,
            b'"' => {
                let start = i + 1;
                i += 1;
                while i < b.len() && b[i] != b'"' {
                    i += if b[i] == b'\\' { 2 } else { 1 };
                }
                let end = i.min(b.len());
                if depth == 1 {
                    key_is_features = &b[start..end] == b"features";
                }
            }
            b',' if depth == 1 => key_is_features = false,
            b'{' | b'[' => {
                if in_features && depth == 2 {
                    lines.push(line);
                }
                depth += 1;
                if depth == 2 && b[i] == b'[' && key_is_features {
                    in_features = true;
                }
            }
            b'}' | b']' => {
                depth = depth.saturating_sub(1);
                if depth < 2 {
                    in_features = false;
                }
            }
            _ => {}
        }
        i += 1;
    }
    lines
}

/// Flatten a geometry into parts (empty members contribute nothing).
fn flatten(
    g: &Geometry,
    what: &str,
    line: Option<usize>,
    feature: Option<usize>,
    out: &mut Vec<Part>,
) {
    let mut push = |body: Body, kind: &str| {
        out.push(Part {
            body,
            kind: kind.to_string(),
            what: what.to_string(),
            line,
            feature,
            rings_closed: true,
        })
    };
    match &g.value {
        GeometryValue::Point { coordinates } => push(Body::Point(coord(coordinates)), "Point"),
        GeometryValue::MultiPoint { coordinates } => {
            for p in coordinates {
                push(Body::Point(coord(p)), "MultiPoint");
            }
        }
        GeometryValue::LineString { coordinates } => {
            if !coordinates.is_empty() {
                push(Body::Line(line_coords(coordinates)), "LineString");
            }
        }
        GeometryValue::MultiLineString { coordinates } => {
            for l in coordinates.iter().filter(|l| !l.is_empty()) {
                push(Body::Line(line_coords(l)), "MultiLineString");
            }
        }
        GeometryValue::Polygon { coordinates } => {
            if !coordinates.is_empty() {
                push(Body::Polygon(rings(coordinates)), "Polygon");
            }
        }
        GeometryValue::MultiPolygon { coordinates } => {
            for p in coordinates.iter().filter(|p| !p.is_empty()) {
                push(Body::Polygon(rings(p)), "MultiPolygon");
            }
        }
        GeometryValue::GeometryCollection { geometries } => {
            for member in geometries {
                flatten(member, what, line, feature, out);
            }
        }
    }
}

/// Every geometry of a GeoJSON text (or bare coordinate array), flattened into parts.
pub(crate) fn read(text: &str, source: &str) -> Result<Vec<Part>> {
    Ok(read_with_properties(text, source)?.0)
}

/// [`read`], with the `properties` of each Feature (null where it has none): a
/// FeatureCollection's in order, or a single Feature's; none for anything else. One
/// parse of the text.
pub(crate) fn read_with_properties(text: &str, source: &str) -> Result<(Vec<Part>, Vec<Value>)> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let trimmed = text.trim_start();
    if trimmed.is_empty() {
        return Ok((Vec::new(), Vec::new()));
    }
    if trimmed.starts_with('[') {
        let value: Value = serde_json::from_str(text).map_err(|e| json_error(&e, source))?;
        return Ok((bare_arrays(&value, source)?, Vec::new()));
    }
    let doc: GeoJson = match serde_json::from_str(text) {
        Ok(doc) => doc,
        Err(e) => without_empty_polygons(text, &e, source)?,
    };
    let (mut parts, mut properties) = (Vec::new(), Vec::new());
    // The line of the opening brace.
    let leading = &text[..text.len() - trimmed.len()];
    let first_line = Some(1 + leading.matches('\n').count());
    let properties_of = |f: geojson::Feature| f.properties.map_or(Value::Null, Value::Object);
    match doc {
        GeoJson::Geometry(g) => flatten(&g, "geometry", first_line, None, &mut parts),
        GeoJson::Feature(f) => {
            if let Some(g) = &f.geometry {
                flatten(g, "feature 1", first_line, Some(0), &mut parts);
            }
            properties.push(properties_of(f));
        }
        GeoJson::FeatureCollection(fc) => {
            let lines = feature_lines(text);
            for (i, f) in fc.features.into_iter().enumerate() {
                if let Some(g) = &f.geometry {
                    let what = format!("feature {}", i + 1);
                    flatten(g, &what, lines.get(i).copied(), Some(i), &mut parts);
                }
                properties.push(properties_of(f));
            }
        }
    }
    Ok((parts, properties))
}

/// The document `text`, which failed to parse with `error`, with the empty polygons of
/// its MultiPolygons left out, where there are any. (The `geojson` crate tells how
/// deeply coordinates nest from their first element, so a MultiPolygon whose first
/// polygon is `[]` fails to parse; empty members are nothing, as [`flatten`] reads
/// them.) Where there are none, or the document still fails, the error is the parse's:
/// the first one, else the message of the second (which names what is wrong with the
/// mended document) at the line of the first. Only tried on text that failed: none of
/// this costs valid input anything.
fn without_empty_polygons(text: &str, error: &serde_json::Error, source: &str) -> Result<GeoJson> {
    /// Leaves out the empty polygons of the MultiPolygons at `v`, where GeoJSON puts
    /// geometries (not in properties); whether there were any.
    fn mend(v: &mut Value) -> bool {
        let Value::Object(o) = v else {
            return false;
        };
        let mut mended = false;
        if o.get("type").and_then(Value::as_str) == Some("MultiPolygon") {
            if let Some(Value::Array(polygons)) = o.get_mut("coordinates") {
                let before = polygons.len();
                polygons.retain(|p| p.as_array().map_or(true, |rings| !rings.is_empty()));
                mended |= polygons.len() < before;
            }
        }
        if let Some(g) = o.get_mut("geometry") {
            mended |= mend(g);
        }
        for list in ["geometries", "features"] {
            if let Some(Value::Array(items)) = o.get_mut(list) {
                for item in items {
                    mended |= mend(item);
                }
            }
        }
        mended
    }
    let first = || json_error(error, source);
    let mut value: Value = serde_json::from_str(text).map_err(|_| first())?;
    if !mend(&mut value) {
        return Err(first());
    }
    serde_json::from_value(value).map_err(|e| {
        Error::parse(
            format!("invalid GeoJSON: {e}"),
            json_location(error, source),
        )
    })
}

/// How deeply arrays nest at the start of `v` (0 for a number).
fn depth(v: &Value) -> usize {
    match v {
        Value::Array(a) => 1 + a.first().map_or(0, depth),
        _ => 0,
    }
}

fn bare_error(source: &str, message: String) -> Error {
    Error::parse(message, Location::source(source))
}

fn bare_position(v: &Value, what: &str, source: &str) -> Result<Coord> {
    let bad = || {
        bare_error(
            source,
            format!("{what}: expected a position [x, y] or [x, y, z] of numbers"),
        )
    };
    let a = v.as_array().ok_or_else(bad)?;
    if a.len() < 2 {
        return Err(bad());
    }
    let nums: Vec<f64> = a
        .iter()
        .map(|n| n.as_f64().ok_or_else(bad))
        .collect::<Result<_>>()?;
    Ok(Coord {
        x: nums[0],
        y: nums[1],
        z: nums.get(2).copied(),
    })
}

fn bare_ring(v: &Value, what: &str, source: &str) -> Result<Vec<Coord>> {
    let a = v
        .as_array()
        .ok_or_else(|| bare_error(source, format!("{what}: expected an array of positions")))?;
    a.iter()
        .enumerate()
        .map(|(i, p)| bare_position(p, &format!("{what}, position {}", i + 1), source))
        .collect()
}

fn bare_polygon(v: &Value, what: &str, source: &str) -> Result<Vec<Vec<Coord>>> {
    let a = v
        .as_array()
        .ok_or_else(|| bare_error(source, format!("{what}: expected an array of rings")))?;
    a.iter()
        .enumerate()
        .map(|(i, r)| bare_ring(r, &format!("{what}, ring {}", i + 1), source))
        .collect()
}

/// A bare array: positions (points), rings (one polygon) or polygons, by nesting depth.
fn bare_arrays(v: &Value, source: &str) -> Result<Vec<Part>> {
    // (Bare arrays of rings, like earcut's fixtures, need not repeat the first position.)
    let part = |body: Body, kind: &str, what: String| Part {
        body,
        kind: kind.to_string(),
        what,
        line: None,
        feature: None,
        rings_closed: false,
    };
    let items = v.as_array().map(Vec::as_slice).unwrap_or_default();
    Ok(match depth(v) {
        1 if items.is_empty() => Vec::new(),
        1 => vec![part(
            Body::Point(bare_position(v, "the position", source)?),
            "position",
            "the position".into(),
        )],
        2 => items
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let what = format!("position {}", i + 1);
                Ok(part(
                    Body::Point(bare_position(p, &what, source)?),
                    "positions",
                    what,
                ))
            })
            .collect::<Result<_>>()?,
        3 => vec![part(
            Body::Polygon(bare_polygon(v, "the polygon", source)?),
            "rings",
            "the polygon".into(),
        )],
        4 => items
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let what = format!("polygon {}", i + 1);
                Ok(part(
                    Body::Polygon(bare_polygon(p, &what, source)?),
                    "polygons",
                    what,
                ))
            })
            .collect::<Result<_>>()?,
        _ => {
            return Err(bare_error(
                source,
                "a bare JSON array must hold positions, rings or polygons (nesting depth 2 to 4)"
                    .into(),
            ))
        }
    })
}
