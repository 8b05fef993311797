//! CSV and whitespace-separated lines: `x,y`, `x y`, `x;y`, `x,y,z`, `x1,y1,x2,y2`.
//! The rules are in the [module documentation](super).

use super::records::{excerpt, open_ring, strip_comment};
use crate::kernel::{MultiPolygon, Point2, Point3, Polygon, Segment2};
use crate::{Error, Location, Result};

/// One data line: its number, its values, and how many blank lines came just before it
/// (since the previous data line; comment lines neither count nor interrupt).
struct Row {
    line: usize,
    values: Vec<f64>,
    blanks_before: usize,
}

/// The fields of a line (comment already removed): split on `;` if present, else `,`,
/// else whitespace.
fn split_fields(s: &str) -> Vec<&str> {
    let s = s.trim();
    if s.contains(';') {
        s.split(';').map(str::trim).collect()
    } else if s.contains(',') {
        s.split(',').map(str::trim).collect()
    } else {
        s.split_whitespace().collect()
    }
}

fn is_header_field(f: &str) -> bool {
    f.parse::<f64>().is_err()
        && f.chars()
            .next()
            .is_some_and(|c| c.is_alphabetic() || c == '_' || c == '"')
}

/// True when every field of `line` is a header word (`x,y`, `"lon" "lat"`).
pub(crate) fn is_header_line(line: &str) -> bool {
    let fields = split_fields(strip_comment(line));
    !fields.is_empty() && fields.iter().all(|f| is_header_field(f))
}

/// True when `line` holds at least two fields and all are numbers (finite or not).
pub(crate) fn is_numeric_line(line: &str) -> bool {
    let fields = split_fields(strip_comment(line));
    fields.len() >= 2 && fields.iter().all(|f| f.parse::<f64>().is_ok())
}

/// All data lines of `text`, each with exactly `want` finite numbers (`names` says which,
/// for the error message).
fn rows(text: &str, source: &str, want: usize, names: &str) -> Result<Vec<Row>> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut rows = Vec::new();
    let mut blanks = 0;
    let mut seen_data = false;
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        if raw.trim().is_empty() {
            blanks += 1;
            continue;
        }
        let content = strip_comment(raw);
        if content.trim().is_empty() {
            continue; // a comment line
        }
        let fields = split_fields(content);
        if !seen_data {
            seen_data = true;
            if fields.iter().all(|f| is_header_field(f)) {
                continue; // the optional header line
            }
        }
        let at = || Location::new(source, line);
        if let Some(k) = fields.iter().position(|f| f.is_empty()) {
            return Err(Error::parse(
                format!("field {} is empty in `{}`", k + 1, excerpt(content)),
                at(),
            ));
        }
        if fields.len() != want {
            return Err(Error::parse(
                format!(
                    "expected {want} fields ({names}), found {} in `{}`",
                    fields.len(),
                    excerpt(content)
                ),
                at(),
            ));
        }
        let mut values = Vec::with_capacity(want);
        for (k, f) in fields.iter().enumerate() {
            let v = parse_number(f, k + 1).map_err(|m| Error::parse(m, at()))?;
            values.push(v);
        }
        rows.push(Row {
            line,
            values,
            blanks_before: blanks,
        });
        blanks = 0;
    }
    Ok(rows)
}

/// A finite number, or a message saying what is wrong with field `k`.
pub(crate) fn parse_number(f: &str, k: usize) -> std::result::Result<f64, String> {
    if f.is_empty() {
        return Err(format!("field {k} is empty"));
    }
    match f.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(format!(
            "non-finite coordinate `{}` in field {k}",
            excerpt(f)
        )),
        Err(_) => Err(format!("malformed number `{}` in field {k}", excerpt(f))),
    }
}

/// `x,y` lines.
pub(crate) fn read_points(text: &str, source: &str) -> Result<Vec<Point2>> {
    Ok(rows(text, source, 2, "x,y")?
        .into_iter()
        .map(|r| Point2::new(r.values[0], r.values[1]))
        .collect())
}

/// `x,y,z` lines.
pub(crate) fn read_points3(text: &str, source: &str) -> Result<Vec<Point3>> {
    Ok(rows(text, source, 3, "x,y,z")?
        .into_iter()
        .map(|r| Point3::new(r.values[0], r.values[1], r.values[2]))
        .collect())
}

/// `x1,y1,x2,y2` lines. A zero-length segment written out is kept: it is what the line says.
pub(crate) fn read_segments(text: &str, source: &str) -> Result<Vec<Segment2>> {
    Ok(rows(text, source, 4, "x1,y1,x2,y2")?
        .into_iter()
        .map(|r| {
            Segment2::new(
                Point2::new(r.values[0], r.values[1]),
                Point2::new(r.values[2], r.values[3]),
            )
        })
        .collect())
}

/// Rings of `x,y` lines: one blank line between the rings of a polygon, two or more
/// between polygons. A ring of fewer than `min_vertices` vertices (not counting a
/// closing repeat) is an error.
pub(crate) fn read_polygons(text: &str, source: &str, min_vertices: usize) -> Result<MultiPolygon> {
    let mut polygons = Vec::new();
    let mut rings: Vec<Vec<Point2>> = Vec::new();
    let mut ring: Vec<Point2> = Vec::new();
    let mut ring_line = 0;
    let finish_ring = |ring: &mut Vec<Point2>, rings: &mut Vec<Vec<Point2>>, line: usize| {
        let open = open_ring(ring).to_vec();
        ring.clear();
        if open.len() < min_vertices {
            return Err(Error::parse(
                format!(
                    "a polygon ring has {} vertices (not counting a closing repeat); it needs at least {min_vertices}",
                    open.len()
                ),
                Location::new(source, line),
            ));
        }
        rings.push(open);
        Ok(())
    };
    let finish_polygon = |rings: &mut Vec<Vec<Point2>>, polygons: &mut Vec<Polygon>| {
        let mut it = std::mem::take(rings).into_iter();
        if let Some(exterior) = it.next() {
            polygons.push(Polygon::new(exterior, it.collect()));
        }
    };
    for row in rows(text, source, 2, "x,y")? {
        if !ring.is_empty() && row.blanks_before >= 1 {
            finish_ring(&mut ring, &mut rings, ring_line)?;
            if row.blanks_before >= 2 {
                finish_polygon(&mut rings, &mut polygons);
            }
        }
        if ring.is_empty() {
            ring_line = row.line;
        }
        ring.push(Point2::new(row.values[0], row.values[1]));
    }
    if !ring.is_empty() {
        finish_ring(&mut ring, &mut rings, ring_line)?;
    }
    finish_polygon(&mut rings, &mut polygons);
    Ok(MultiPolygon(polygons))
}
