//! Real-map inputs of the `boolean` group, read in place from the shared cases folder
//! (`COMPGEOM_CASES`, else `../shared/cases` beside the workspace; never copied into the
//! repository). Skipped with a message when the folder is absent.
//!
//! * `water ∩ shifted`: mapbox/earcut's `water-huge3` fixture (a real water body, 12.9 k
//!   vertices, one shell and 1443 island holes, integer coordinates) against a copy of
//!   itself moved by a non-integer offset of about 1/20 of its size: two real-looking maps
//!   with crossings all along both coastlines and among the islands. All four operations.
//! * `jts robust AA`: every polygon–polygon pair of JTS's `robust/overlay` regressions
//!   (real-world inputs from GEOS / PostGIS / Shapely tickets and isochrone maps; WKT or
//!   hex WKB), all four operations, the times of all pairs summed.
//! * `geos-837 dissolve`: the unary union of GEOS ticket 837's real multipolygon
//!   (hex WKB, about 3.4 k vertices).

use compgeom::{MultiPolygon, Point2, Polygon};
use std::path::PathBuf;

/// The cases folder, if present.
pub fn cases_dir() -> Option<PathBuf> {
    let dir = std::env::var_os("COMPGEOM_CASES")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared/cases"));
    dir.is_dir().then_some(dir)
}

/// One named input pair (b empty for a dissolve).
pub struct MapPair {
    pub name: String,
    pub a: MultiPolygon,
    pub b: MultiPolygon,
}

/// An earcut fixture (array of rings: shell, then holes) as one polygon.
fn earcut_polygon(text: &str) -> Option<Polygon> {
    let v: serde_json::Value = serde_json::from_str(text).ok()?;
    let mut rings = v.as_array()?.iter().map(|r| {
        r.as_array()?
            .iter()
            .map(|p| Some(Point2::new(p.get(0)?.as_f64()?, p.get(1)?.as_f64()?)))
            .collect::<Option<Vec<_>>>()
    });
    let shell = rings.next()??;
    let holes = rings.collect::<Option<Vec<_>>>()?;
    Some(Polygon::new(shell, holes))
}

/// Polygonal hex WKB / EWKB (Polygon, MultiPolygon; Z and M dropped) as a polygon set;
/// `None` for anything else.
fn wkb_polygons(hex: &str) -> Option<MultiPolygon> {
    let bytes = (0..hex.len() / 2)
        .map(|i| u8::from_str_radix(hex.get(2 * i..2 * i + 2)?, 16).ok())
        .collect::<Option<Vec<u8>>>()?;
    let mut r = WkbReader {
        bytes: &bytes,
        at: 0,
        little: true,
    };
    let mut out = Vec::new();
    r.geometry(&mut out, 0)?;
    Some(MultiPolygon(out))
}

struct WkbReader<'a> {
    bytes: &'a [u8],
    at: usize,
    little: bool,
}

impl WkbReader<'_> {
    fn take<const N: usize>(&mut self) -> Option<[u8; N]> {
        let s = self.bytes.get(self.at..self.at + N)?;
        self.at += N;
        let mut a: [u8; N] = s.try_into().ok()?;
        if !self.little {
            a.reverse();
        }
        Some(a)
    }

    fn u32(&mut self) -> Option<u32> {
        self.take::<4>().map(u32::from_le_bytes)
    }

    fn f64(&mut self) -> Option<f64> {
        self.take::<8>().map(f64::from_le_bytes)
    }

    /// One geometry with its header; polygons appended to `out`.
    fn geometry(&mut self, out: &mut Vec<Polygon>, depth: usize) -> Option<()> {
        self.little = *self.bytes.get(self.at)? == 1;
        self.at += 1;
        let code = self.u32()?;
        if code & 0x2000_0000 != 0 {
            self.u32()?; // EWKB SRID
        }
        let iso = code & 0xffff;
        let dims = 2
            + usize::from(code & 0x8000_0000 != 0 || (1000..2000).contains(&iso) || iso >= 3000)
            + usize::from(code & 0x4000_0000 != 0 || iso >= 2000);
        match iso % 1000 {
            3 => {
                let rings = (0..self.u32()?)
                    .map(|_| {
                        let n = self.u32()? as usize;
                        let mut ring = Vec::with_capacity(n);
                        for _ in 0..n {
                            let (x, y) = (self.f64()?, self.f64()?);
                            for _ in 2..dims {
                                self.f64()?;
                            }
                            ring.push(Point2::new(x, y));
                        }
                        if ring.len() > 1 && ring.first() == ring.last() {
                            ring.pop();
                        }
                        Some(ring)
                    })
                    .collect::<Option<Vec<_>>>()?;
                let mut rings = rings.into_iter();
                if let Some(shell) = rings.next() {
                    out.push(Polygon::new(shell, rings.collect()));
                }
                Some(())
            }
            6 if depth == 0 => {
                for _ in 0..self.u32()? {
                    self.geometry(out, depth + 1)?;
                }
                Some(())
            }
            _ => None,
        }
    }
}

/// A polygonal operand of a JTS XML case: WKT (MULTI)POLYGON or hex WKB.
fn operand(text: &str) -> Option<MultiPolygon> {
    let t = text.trim();
    if t.bytes().all(|b| b.is_ascii_hexdigit()) {
        return wkb_polygons(t);
    }
    let head = t.to_ascii_uppercase();
    if !(head.starts_with("POLYGON") || head.starts_with("MULTIPOLYGON")) || head.contains("EMPTY")
    {
        return None;
    }
    compgeom::io::read_polygons(t, compgeom::io::Format::Wkt, "case").ok()
}

fn element<'a>(case: &'a str, tag: &str) -> Option<&'a str> {
    let open = case.find(&format!("<{tag}>"))? + tag.len() + 2;
    let close = open + case[open..].find(&format!("</{tag}>"))?;
    Some(&case[open..close])
}

/// The water body against its shifted copy, or `None` when the fixture is missing.
pub fn water_pair(dir: &std::path::Path) -> Option<MapPair> {
    let text = std::fs::read_to_string(dir.join("earcut/fixtures/water-huge3.json")).ok()?;
    let a = earcut_polygon(&text)?;
    let (mut lo, mut hi) = (
        Point2::new(f64::MAX, f64::MAX),
        Point2::new(f64::MIN, f64::MIN),
    );
    for p in &a.exterior {
        (lo.x, lo.y, hi.x, hi.y) = (lo.x.min(p.x), lo.y.min(p.y), hi.x.max(p.x), hi.y.max(p.y));
    }
    // An offset that is not a multiple of the integer grid, so the copies cross in general
    // position (plus the odd exact tie the coordinates give).
    let (dx, dy) = ((hi.x - lo.x) * 0.0517, (hi.y - lo.y) * 0.0331);
    let shift = |r: &Vec<Point2>| r.iter().map(|p| Point2::new(p.x + dx, p.y + dy)).collect();
    let b = Polygon::new(shift(&a.exterior), a.holes.iter().map(shift).collect());
    let n = a.rings().map(Vec::len).sum::<usize>();
    Some(MapPair {
        name: format!("water∩shift {n}"),
        a: MultiPolygon(vec![a]),
        b: MultiPolygon(vec![b]),
    })
}

/// Every polygon–polygon pair of `jts-testxml/robust/overlay` (file order).
pub fn jts_robust_pairs(dir: &std::path::Path) -> Vec<MapPair> {
    let Ok(entries) = std::fs::read_dir(dir.join("jts-testxml/robust/overlay")) else {
        return Vec::new();
    };
    let mut files: Vec<PathBuf> = entries.filter_map(|e| Some(e.ok()?.path())).collect();
    files.sort();
    let mut pairs = Vec::new();
    for f in files {
        let Ok(text) = std::fs::read_to_string(&f) else {
            continue;
        };
        for (i, case) in text.split("<case").skip(1).enumerate() {
            let (Some(a), Some(b)) = (element(case, "a"), element(case, "b")) else {
                continue;
            };
            if let (Some(a), Some(b)) = (operand(a), operand(b)) {
                let stem = f
                    .file_stem()
                    .map_or(String::new(), |s| s.to_string_lossy().into());
                pairs.push(MapPair {
                    name: format!("{stem}#{i}"),
                    a,
                    b,
                });
            }
        }
    }
    pairs
}

/// GEOS ticket 837's multipolygon (unary union case).
pub fn geos_837(dir: &std::path::Path) -> Option<MapPair> {
    let text =
        std::fs::read_to_string(dir.join("jts-testxml/robust/overlay/TestOverlay-geos-837.xml"))
            .ok()?;
    let a = operand(element(&text, "a")?)?;
    let n =
        a.0.iter()
            .flat_map(|p| p.rings())
            .map(Vec::len)
            .sum::<usize>();
    Some(MapPair {
        name: format!("geos-837 {n}"),
        a,
        b: MultiPolygon::default(),
    })
}
