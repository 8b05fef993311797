//! Reading query rectangles: `xmin,ymin,xmax,ymax` lines.

use crate::kernel::{Bbox2, Point2};
use crate::{Error, Location, Result};

/// Rectangles from `xmin,ymin,xmax,ymax` lines (fields separated by `;`, `,` or spaces as
/// in [`crate::io`]'s CSV; `#` comments and blank lines skipped; an optional header line of
/// words first). A rectangle with `xmin > xmax` or `ymin > ymax` is read as given (it is
/// empty and contains nothing). Errors name `source:line`: a wrong field count, a malformed
/// or non-finite number.
///
/// ```
/// use compgeom::range::read_rects;
/// let r = read_rects("xmin,ymin,xmax,ymax\n0,0,2,1 # first\n\n1 1 1 1\n", "q.csv").unwrap();
/// assert_eq!(r.len(), 2);
/// assert_eq!(r[1].min.x, 1.0);
/// let err = read_rects("0,0,1\n", "q.csv").unwrap_err();
/// assert!(err.to_string().contains("q.csv:1"));
/// ```
pub fn read_rects(text: &str, source: &str) -> Result<Vec<Bbox2>> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut out = Vec::new();
    let mut seen_data = false;
    for (i, raw) in text.lines().enumerate() {
        let at = || Location::new(source, i + 1);
        let content = raw.split('#').next().unwrap_or("").trim();
        if content.is_empty() {
            continue;
        }
        let fields: Vec<&str> = if content.contains(';') {
            content.split(';').map(str::trim).collect()
        } else if content.contains(',') {
            content.split(',').map(str::trim).collect()
        } else {
            content.split_whitespace().collect()
        };
        let first = !seen_data;
        seen_data = true;
        if first
            && fields.iter().all(|f| {
                f.parse::<f64>().is_err()
                    && f.chars()
                        .next()
                        .is_some_and(|c| c.is_alphabetic() || c == '_' || c == '"')
            })
        {
            continue; // the optional header
        }
        if fields.len() != 4 {
            return Err(Error::parse(
                format!(
                    "expected 4 fields (xmin,ymin,xmax,ymax), found {} in `{}`",
                    fields.len(),
                    excerpt(content)
                ),
                at(),
            ));
        }
        let mut v = [0.0; 4];
        for (k, f) in fields.iter().enumerate() {
            v[k] = match f.parse::<f64>() {
                Ok(x) if x.is_finite() => x,
                Ok(_) => {
                    return Err(Error::parse(
                        format!("non-finite coordinate `{}` in field {}", excerpt(f), k + 1),
                        at(),
                    ))
                }
                Err(_) if f.is_empty() => {
                    return Err(Error::parse(format!("field {} is empty", k + 1), at()))
                }
                Err(_) => {
                    return Err(Error::parse(
                        format!("malformed number `{}` in field {}", excerpt(f), k + 1),
                        at(),
                    ))
                }
            };
        }
        out.push(Bbox2 {
            min: Point2::new(v[0], v[1]),
            max: Point2::new(v[2], v[3]),
        });
    }
    Ok(out)
}

fn excerpt(s: &str) -> String {
    if s.chars().count() > 40 {
        format!("{}…", s.chars().take(40).collect::<String>())
    } else {
        s.to_string()
    }
}
