//! Reading constraints: one per line, `a b c` (meaning `a·x + b·y <= c`), or in `d`
//! dimensions `a1 … ad c`; fields separated by whitespace, `,` or `;`; `#` starts a comment.

use super::HalfPlane;
use crate::{Error, Location, Result};

/// Read half-planes `a b c` (`a·x + b·y <= c`), one per line. Errors name the line.
///
/// ```
/// use compgeom::lp::{read_halfplanes, HalfPlane};
/// let hs = read_halfplanes("# box\n1 0 1\n-1,0,1\n", "box.txt")?;
/// assert_eq!(hs, vec![HalfPlane::new(1.0, 0.0, 1.0), HalfPlane::new(-1.0, 0.0, 1.0)]);
/// assert!(read_halfplanes("1 2\n", "bad.txt").unwrap_err().to_string().contains("bad.txt:1"));
/// # Ok::<(), compgeom::Error>(())
/// ```
pub fn read_halfplanes(text: &str, source: &str) -> Result<Vec<HalfPlane>> {
    Ok(read_constraints(text, source, Some(3))?
        .into_iter()
        .map(|r| HalfPlane::new(r[0], r[1], r[2]))
        .collect())
}

/// Read constraints `a1 … ad c` (`a·x <= c`), one per line, each with the same number of
/// fields (`fields`, or that of the first data line when `None`). Every number must be
/// finite. Returns the rows.
pub fn read_constraints(text: &str, source: &str, fields: Option<usize>) -> Result<Vec<Vec<f64>>> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut want = fields;
    let mut out = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let loc = || Location::new(source, i + 1);
        let line = raw.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let parts: Vec<&str> = if line.contains(';') {
            line.split(';').map(str::trim).collect()
        } else if line.contains(',') {
            line.split(',').map(str::trim).collect()
        } else {
            line.split_whitespace().collect()
        };
        let mut row = Vec::with_capacity(parts.len());
        for p in &parts {
            let v: f64 = p
                .parse()
                .map_err(|_| Error::parse(format!("not a number: {p:?}"), loc()))?;
            if !v.is_finite() {
                return Err(Error::parse(format!("non-finite number {p:?}"), loc()));
            }
            row.push(v);
        }
        let n = *want.get_or_insert(row.len());
        if n < 2 {
            return Err(Error::parse(
                "a constraint needs at least one coefficient and a right-hand side",
                loc(),
            ));
        }
        if row.len() != n {
            // Name the fields the way the user writes them for the dimension at hand.
            let form = match n - 1 {
                1 => "a c, meaning a·x <= c".to_string(),
                2 => "a b c, meaning a·x + b·y <= c".to_string(),
                3 => "a1 a2 a3 c, meaning a1·x1 + a2·x2 + a3·x3 <= c".to_string(),
                d => format!("a1 .. a{d} c, meaning a1·x1 + .. + a{d}·x{d} <= c"),
            };
            return Err(Error::parse(
                format!("expected {n} numbers ({form}), found {}", row.len()),
                loc(),
            ));
        }
        out.push(row);
    }
    Ok(out)
}
