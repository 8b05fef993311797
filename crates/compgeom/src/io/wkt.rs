//! Well-known text: a file holds one or more geometries. A small scanner cuts the text into
//! geometries (tracking lines, skipping `#` comments, catching non-finite numbers and
//! unbalanced parentheses); the `wkt` crate parses each one.

use super::records::{excerpt, Body, Coord, Part};
use crate::{Error, Location, Result};
use std::borrow::Cow;
use std::str::FromStr;
use wkt::Wkt;

/// Deeper nesting than this is refused (it bounds the parser's recursion).
const MAX_DEPTH: usize = 32;

const BASE_KEYWORDS: [&str; 8] = [
    "POINT",
    "LINESTRING",
    "LINEARRING",
    "POLYGON",
    "MULTIPOINT",
    "MULTILINESTRING",
    "MULTIPOLYGON",
    "GEOMETRYCOLLECTION",
];

/// True when `word` is a WKT geometry keyword (any case, optionally with a `Z`, `M` or
/// `ZM` suffix written without a space).
pub(crate) fn is_keyword(word: &str) -> bool {
    let w = word.to_ascii_uppercase();
    let is_base = |s: &str| BASE_KEYWORDS.contains(&s);
    is_base(&w)
        || ["ZM", "Z", "M"]
            .iter()
            .any(|suffix| w.strip_suffix(suffix).is_some_and(is_base))
}

/// The text with every `#` comment blanked out (line structure kept) and a leading
/// byte-order mark removed.
fn blank_comments(text: &str) -> Cow<'_, str> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if !text.contains('#') {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len());
    let mut in_comment = false;
    for c in text.chars() {
        match c {
            '\n' => {
                in_comment = false;
                out.push(c);
            }
            '#' => {
                in_comment = true;
                out.push(' ');
            }
            _ if in_comment => out.push(' '),
            _ => out.push(c),
        }
    }
    Cow::Owned(out)
}

fn is_space(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | b'\n')
}

fn is_structural(b: u8) -> bool {
    is_space(b) || matches!(b, b'(' | b')' | b',')
}

/// A geometry's place in the text.
struct Span {
    start: usize,
    end: usize,
    line: usize,
}

/// Cut `text` (comments already blanked) into geometries.
fn split(text: &str, source: &str) -> Result<Vec<Span>> {
    let b = text.as_bytes();
    let n = b.len();
    let mut i = 0;
    let mut line = 1;
    let mut spans = Vec::new();
    let err = |message: String, line: usize| Error::parse(message, Location::new(source, line));
    let rest_of_line = |i: usize| excerpt(text[i..].lines().next().unwrap_or(""));
    loop {
        while i < n && is_space(b[i]) {
            line += usize::from(b[i] == b'\n');
            i += 1;
        }
        if i == n {
            break;
        }
        // EWKT's `SRID=n;` prefix: the reference system is not ours to interpret; skip it.
        if b.len() - i >= 5 && b[i..i + 5].eq_ignore_ascii_case(b"SRID=") {
            match text[i..].find(';') {
                Some(k) if !text[i..i + k].contains('\n') => {
                    i += k + 1;
                    continue;
                }
                _ => {
                    return Err(err(
                        "an EWKT `SRID=` prefix must end with `;` on its line".into(),
                        line,
                    ))
                }
            }
        }
        let (start, start_line) = (i, line);
        if !b[i].is_ascii_alphabetic() {
            return Err(err(
                format!(
                    "expected a WKT geometry keyword, found `{}`",
                    rest_of_line(i)
                ),
                line,
            ));
        }
        while i < n && b[i].is_ascii_alphanumeric() {
            i += 1;
        }
        let keyword = &text[start..i];
        if !is_keyword(keyword) {
            return Err(err(
                format!("unknown WKT geometry type `{}`", excerpt(keyword)),
                line,
            ));
        }
        // Optional dimension words, then EMPTY or a parenthesised body.
        loop {
            while i < n && is_space(b[i]) {
                line += usize::from(b[i] == b'\n');
                i += 1;
            }
            if i == n {
                return Err(err(
                    format!("{keyword} has neither coordinates nor EMPTY"),
                    start_line,
                ));
            }
            if b[i] == b'(' {
                i = scan_body(text, i, &mut line, start_line, source)?;
                break;
            }
            let word_start = i;
            while i < n && b[i].is_ascii_alphanumeric() {
                i += 1;
            }
            let word = &text[word_start..i];
            if word.eq_ignore_ascii_case("EMPTY") {
                break;
            }
            if !["Z", "M", "ZM"]
                .iter()
                .any(|d| word.eq_ignore_ascii_case(d))
            {
                return Err(err(
                    format!(
                        "expected `(` or EMPTY after {keyword}, found `{}`",
                        rest_of_line(word_start)
                    ),
                    line,
                ));
            }
        }
        spans.push(Span {
            start,
            end: i,
            line: start_line,
        });
    }
    Ok(spans)
}

/// Scan a parenthesised body starting at `text[i] == '('`; returns the index after its
/// closing parenthesis. Checks nesting depth and that no number is NaN or infinite.
fn scan_body(
    text: &str,
    mut i: usize,
    line: &mut usize,
    start_line: usize,
    source: &str,
) -> Result<usize> {
    let b = text.as_bytes();
    let n = b.len();
    let mut depth = 0usize;
    while i < n {
        match b[i] {
            b'(' => {
                depth += 1;
                if depth > MAX_DEPTH {
                    return Err(Error::parse(
                        format!("geometry nested more than {MAX_DEPTH} levels deep"),
                        Location::new(source, *line),
                    ));
                }
                i += 1;
            }
            b')' => {
                depth -= 1;
                i += 1;
                if depth == 0 {
                    return Ok(i);
                }
            }
            b'\n' => {
                *line += 1;
                i += 1;
            }
            c if is_structural(c) => i += 1,
            _ => {
                let token_start = i;
                while i < n && !is_structural(b[i]) {
                    i += 1;
                }
                let token = &text[token_start..i];
                // Only an exponent, `inf`/`nan` or a very long digit string can be
                // non-finite; other tokens need no second parse.
                let suspicious = token.len() > 300
                    || token
                        .bytes()
                        .any(|c| matches!(c, b'e' | b'E' | b'i' | b'I' | b'n' | b'N'));
                if suspicious && token.parse::<f64>().is_ok_and(|v| !v.is_finite()) {
                    return Err(Error::parse(
                        format!("non-finite coordinate `{}`", excerpt(token)),
                        Location::new(source, *line),
                    ));
                }
            }
        }
    }
    Err(Error::parse(
        "unbalanced parentheses: the geometry starting here is never closed",
        Location::new(source, start_line),
    ))
}

fn coord(c: &wkt::types::Coord<f64>) -> Coord {
    Coord {
        x: c.x,
        y: c.y,
        z: c.z,
    }
}

fn line_coords(l: &wkt::types::LineString<f64>) -> Vec<Coord> {
    l.coords().iter().map(coord).collect()
}

fn polygon_rings(p: &wkt::types::Polygon<f64>) -> Vec<Vec<Coord>> {
    p.rings().iter().map(line_coords).collect()
}

/// Flatten `g` into parts (empty members contribute nothing).
fn flatten(g: &Wkt<f64>, what: &str, line: usize, out: &mut Vec<Part>) {
    let mut push = |body: Body, kind: &str| {
        out.push(Part {
            body,
            kind: kind.to_string(),
            what: what.to_string(),
            line: Some(line),
            feature: None,
            rings_closed: true,
        })
    };
    match g {
        Wkt::Point(p) => {
            if let Some(c) = p.coord() {
                push(Body::Point(coord(c)), "POINT");
            }
        }
        Wkt::MultiPoint(mp) => {
            for c in mp.points().iter().filter_map(|p| p.coord()) {
                push(Body::Point(coord(c)), "MULTIPOINT");
            }
        }
        Wkt::LineString(l) => {
            if !l.coords().is_empty() {
                push(Body::Line(line_coords(l)), "LINESTRING");
            }
        }
        Wkt::MultiLineString(ml) => {
            for l in ml.line_strings().iter().filter(|l| !l.coords().is_empty()) {
                push(Body::Line(line_coords(l)), "MULTILINESTRING");
            }
        }
        Wkt::Polygon(p) => {
            if !p.rings().is_empty() {
                push(Body::Polygon(polygon_rings(p)), "POLYGON");
            }
        }
        Wkt::MultiPolygon(mp) => {
            for p in mp.polygons().iter().filter(|p| !p.rings().is_empty()) {
                push(Body::Polygon(polygon_rings(p)), "MULTIPOLYGON");
            }
        }
        Wkt::GeometryCollection(gc) => {
            for member in gc.geometries() {
                flatten(member, what, line, out);
            }
        }
    }
}

/// Every geometry of a WKT text, flattened into parts.
pub(crate) fn read(text: &str, source: &str) -> Result<Vec<Part>> {
    let clean = blank_comments(text);
    let mut parts = Vec::new();
    for (k, span) in split(&clean, source)?.iter().enumerate() {
        let body = &clean[span.start..span.end];
        let g = Wkt::<f64>::from_str(body).map_err(|m| {
            Error::parse(
                format!("invalid WKT `{}`: {m}", excerpt(body)),
                Location::new(source, span.line),
            )
        })?;
        flatten(&g, &format!("geometry {}", k + 1), span.line, &mut parts);
    }
    Ok(parts)
}
