//! A shape's GeoJSON geometry for serde: JSON documents that hold geometries (the CLI's
//! results) are written straight from the shapes, without a text or `Value` copy of each.

use super::write::{geojson_rings, push_f64};
use super::Shape;
use crate::kernel::{Point2, Polygon};
use serde::ser::{Error as _, Serialize, SerializeMap, Serializer};
use serde_json::Number;

/// `shape` serialized as the GeoJSON geometry object that [`super::write_shape`] writes
/// with [`super::Format::GeoJson`] (the same rings, orientation and closing), keys in
/// alphabetical order, each coordinate the number a JSON reader gets from that text
/// (serde_json prints it back bit for bit): a [`super::to_geojson_value`] that builds
/// nothing. A NaN or infinite coordinate it writes is a serialization error (the
/// holes of a polygon without an exterior are not written, nor checked; `write_shape`
/// and `to_geojson_value` reject any non-finite vertex).
///
/// ```
/// use compgeom::io::{GeoJsonGeometry, Shape};
/// use compgeom::{Point2, Polygon};
/// let square = Polygon::new(vec![Point2::new(0.0, 0.0), Point2::new(0.0, 1.0),
///                                Point2::new(1.0, 1.0), Point2::new(1.0, 0.5)], vec![]);
/// let text = serde_json::to_string(&GeoJsonGeometry(&Shape::Polygon(square))).unwrap();
/// assert_eq!(text, r#"{"coordinates":[[[0,0],[1,0.5],[1,1],[0,1],[0,0]]],"type":"Polygon"}"#);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct GeoJsonGeometry<'a>(pub &'a Shape);

impl Serialize for GeoJsonGeometry<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(2))?;
        let kind = match self.0 {
            Shape::Empty => {
                map.serialize_entry("geometries", &[0u8; 0])?;
                "GeometryCollection"
            }
            Shape::Point(p) => {
                map.serialize_entry("coordinates", &Position(*p))?;
                "Point"
            }
            Shape::MultiPoint(ps) => {
                map.serialize_entry("coordinates", &Seq(ps.iter().map(|&p| Position(p))))?;
                "MultiPoint"
            }
            Shape::LineString(ps) => {
                map.serialize_entry("coordinates", &Seq(ps.iter().map(|&p| Position(p))))?;
                "LineString"
            }
            Shape::Polygon(p) => {
                map.serialize_entry("coordinates", &Rings(p))?;
                "Polygon"
            }
            Shape::MultiPolygon(mp) => {
                let parts = mp.0.iter().filter(|p| !p.exterior.is_empty());
                map.serialize_entry("coordinates", &Seq(parts.map(Rings)))?;
                "MultiPolygon"
            }
        };
        map.serialize_entry("type", kind)?;
        map.end()
    }
}

/// A sequence serialized from (a copy of) an iterator.
struct Seq<I>(I);

impl<I: Iterator + Clone> Serialize for Seq<I>
where
    I::Item: Serialize,
{
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq(self.0.clone())
    }
}

/// A polygon's coordinates: its rings as GeoJSON has them ([`geojson_rings`]).
struct Rings<'a>(&'a Polygon);

impl Serialize for Rings<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq(geojson_rings(self.0).map(|ring| Seq(ring.map(Position))))
    }
}

/// A position `[x, y]`.
struct Position(Point2);

impl Serialize for Position {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let number = |v: f64| {
            json_number(v).ok_or_else(|| S::Error::custom(format!("non-finite coordinate {v}")))
        };
        [number(self.0.x)?, number(self.0.y)?].serialize(serializer)
    }
}

/// The number serde_json reads from [`super::format_f64`]`(x)` (`None` for NaN and the
/// infinities): the float itself, except where the text is an integer without exponent
/// (`3`, `-0`, `100`), which it reads as an integer where one holds it. Only integral
/// values can be written so; their text is made and read as the writer's would be.
fn json_number(x: f64) -> Option<Number> {
    if !x.is_finite() {
        return None;
    }
    if x.fract() == 0.0 {
        let mut text = String::with_capacity(24);
        push_f64(&mut text, x);
        if !text.contains('e') {
            return serde_json::from_str(&text).ok();
        }
    }
    Number::from_f64(x)
}
