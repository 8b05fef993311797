//! The Object File Format (OFF) for polyhedral surfaces in space.

use super::csv::parse_number;
use super::records::{excerpt, significant_lines};
use super::write::format_f64;
use crate::kernel::Point3;
use crate::{Error, Location, Result};
use std::fmt::Write as _;

/// A polyhedral surface: vertices in space and faces given as cycles of vertex indices
/// (0-based). Read from and written to OFF.
///
/// The type checks nothing by itself; [`read_off`] guarantees that every face has at least
/// 3 indices and that every index is in range.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Polyhedron {
    /// The vertices.
    pub vertices: Vec<Point3>,
    /// The faces, each a cycle of indices into `vertices`.
    pub faces: Vec<Vec<usize>>,
}

/// Read an OFF file.
///
/// Layout: an `OFF` header line (the counts may follow on the same line), then
/// `nv nf [ne]`, then `nv` lines `x y z`, then `nf` lines `n i1 … in`, where each `ik` is a
/// 0-based vertex index and up to four trailing numbers (a face colour) are allowed and
/// ignored. `#` starts a comment; blank lines are skipped. The edge count is ignored.
///
/// Empty input (nothing but blank and comment lines) gives an empty polyhedron.
/// Errors (with the line): a missing header, malformed or non-finite numbers, wrong field
/// counts, faces with fewer than 3 vertices, an index out of range, fewer lines than the
/// counts promise, or content after the last face. O(size of the text).
///
/// ```
/// use compgeom::io::read_off;
/// let tetra = "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
/// let p = read_off(tetra, "tetra.off").unwrap();
/// assert_eq!((p.vertices.len(), p.faces.len()), (4, 4));
/// let err = read_off("OFF\n1 1 0\n0 0 0\n3 0 1 2\n", "bad.off").unwrap_err();
/// assert!(err.to_string().contains("bad.off:4"));
/// ```
pub fn read_off(text: &str, source: &str) -> Result<Polyhedron> {
    read_off_with_lines(text, source).map(|(p, _)| p)
}

/// As [`read_off`], and also the 1-based line of each face, so that later checks of the
/// surface (e.g. [`castability_at`](crate::lp::castability_at)) can name the line of a
/// bad face.
///
/// ```
/// use compgeom::io::read_off_with_lines;
/// let tetra = "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n\n3 0 3 2\n3 1 2 3\n";
/// let (p, lines) = read_off_with_lines(tetra, "tetra.off").unwrap();
/// assert_eq!(p.faces.len(), 4);
/// assert_eq!(lines, vec![7, 8, 10, 11]);
/// ```
pub fn read_off_with_lines(text: &str, source: &str) -> Result<(Polyhedron, Vec<usize>)> {
    let err = |message: String, line: usize| Error::parse(message, Location::new(source, line));
    let mut lines = significant_lines(text);
    let last_line = text.lines().count().max(1);

    let Some((header_line, header)) = lines.next() else {
        return Ok((Polyhedron::default(), Vec::new())); // empty input: nothing, not an error
    };
    let mut header_fields = header.split_whitespace();
    if header_fields.next() != Some("OFF") {
        return Err(err(
            format!("expected an `OFF` header, found `{}`", excerpt(header)),
            header_line,
        ));
    }
    let rest: Vec<&str> = header_fields.collect();
    let (counts_line, counts) = if rest.is_empty() {
        lines
            .next()
            .map(|(l, s)| (l, s.split_whitespace().collect::<Vec<_>>()))
            .ok_or_else(|| err("missing the `nv nf ne` counts line".into(), last_line))?
    } else {
        (header_line, rest)
    };
    if !(2..=3).contains(&counts.len()) {
        return Err(err(
            format!("expected counts `nv nf ne`, found {} fields", counts.len()),
            counts_line,
        ));
    }
    let count = |f: &str, name: &str| {
        f.parse::<usize>().map_err(|_| {
            err(
                format!("{name} count `{}` is not a whole number", excerpt(f)),
                counts_line,
            )
        })
    };
    let nv = count(counts[0], "vertex")?;
    let nf = count(counts[1], "face")?;

    // Capacities are capped: a count is a promise the text may not keep.
    let mut vertices = Vec::with_capacity(nv.min(1 << 20));
    for k in 0..nv {
        let (line, s) = lines.next().ok_or_else(|| {
            err(
                format!("expected {nv} vertices, the input ends after {k}"),
                last_line,
            )
        })?;
        let fields: Vec<&str> = s.split_whitespace().collect();
        if fields.len() != 3 {
            return Err(err(
                format!(
                    "vertex {k}: expected 3 fields (x y z), found {}",
                    fields.len()
                ),
                line,
            ));
        }
        let mut xyz = [0.0; 3];
        for (j, f) in fields.iter().enumerate() {
            xyz[j] = parse_number(f, j + 1).map_err(|m| err(format!("vertex {k}: {m}"), line))?;
        }
        vertices.push(Point3::from(xyz));
    }

    let mut faces = Vec::with_capacity(nf.min(1 << 20));
    let mut face_lines = Vec::with_capacity(nf.min(1 << 20));
    for k in 0..nf {
        let (line, s) = lines.next().ok_or_else(|| {
            err(
                format!("expected {nf} faces, the input ends after {k}"),
                last_line,
            )
        })?;
        let fields: Vec<&str> = s.split_whitespace().collect();
        let n = fields[0].parse::<usize>().map_err(|_| {
            err(
                format!(
                    "face {k}: vertex count `{}` is not a whole number",
                    excerpt(fields[0])
                ),
                line,
            )
        })?;
        if n < 3 {
            return Err(err(
                format!("face {k} has {n} vertices; a face needs at least 3"),
                line,
            ));
        }
        if fields.len() < 1 + n || fields.len() > 1 + n + 4 {
            return Err(err(
                format!(
                    "face {k}: expected {n} indices (and at most 4 colour values), found {} fields after the count",
                    fields.len() - 1
                ),
                line,
            ));
        }
        let mut face = Vec::with_capacity(n);
        for f in &fields[1..=n] {
            let i = f.parse::<usize>().map_err(|_| {
                err(
                    format!(
                        "face {k}: vertex index `{}` is not a whole number",
                        excerpt(f)
                    ),
                    line,
                )
            })?;
            if i >= nv {
                return Err(err(
                    format!("face {k}: vertex index {i} is out of range (there are {nv} vertices)"),
                    line,
                ));
            }
            face.push(i);
        }
        for (j, f) in fields[1 + n..].iter().enumerate() {
            parse_number(f, 2 + n + j).map_err(|m| err(format!("face {k} colour: {m}"), line))?;
        }
        faces.push(face);
        face_lines.push(line);
    }
    if let Some((line, s)) = lines.next() {
        return Err(err(
            format!("unexpected content after the last face: `{}`", excerpt(s)),
            line,
        ));
    }
    Ok((Polyhedron { vertices, faces }, face_lines))
}

/// `p` as OFF text (edge count written as 0, as most writers do); reads back with
/// [`read_off`] to an equal polyhedron.
pub fn write_off(p: &Polyhedron) -> String {
    let mut out = format!("OFF\n{} {} 0\n", p.vertices.len(), p.faces.len());
    for v in &p.vertices {
        let _ = writeln!(
            out,
            "{} {} {}",
            format_f64(v.x),
            format_f64(v.y),
            format_f64(v.z)
        );
    }
    for f in &p.faces {
        let _ = write!(out, "{}", f.len());
        for i in f {
            let _ = write!(out, " {i}");
        }
        out.push('\n');
    }
    out
}
