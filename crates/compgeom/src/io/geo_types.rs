//! Conversions between compgeom's kernel types and the `geo-types` crate (the types of
//! the georust ecosystem), so compgeom can sit beside `geo`, `wkt` and `geojson` users.
//!
//! Rings: compgeom stores them open, geo-types closed; converting adds or drops the
//! closing vertex (a ring whose last vertex equals its first loses that last vertex when
//! coming from geo-types). Values are copied exactly; nothing is reoriented.

use super::records::open_ring;
use super::Shape;
use crate::kernel::{MultiPolygon, Point2, Polygon, Segment2};

impl From<Point2> for ::geo_types::Coord<f64> {
    fn from(p: Point2) -> Self {
        ::geo_types::Coord { x: p.x, y: p.y }
    }
}

impl From<::geo_types::Coord<f64>> for Point2 {
    fn from(c: ::geo_types::Coord<f64>) -> Self {
        Point2::new(c.x, c.y)
    }
}

impl From<Point2> for ::geo_types::Point<f64> {
    fn from(p: Point2) -> Self {
        ::geo_types::Point::new(p.x, p.y)
    }
}

impl From<::geo_types::Point<f64>> for Point2 {
    fn from(p: ::geo_types::Point<f64>) -> Self {
        Point2::new(p.x(), p.y())
    }
}

impl From<Segment2> for ::geo_types::Line<f64> {
    fn from(s: Segment2) -> Self {
        ::geo_types::Line::new(::geo_types::Coord::from(s.a), ::geo_types::Coord::from(s.b))
    }
}

impl From<::geo_types::Line<f64>> for Segment2 {
    fn from(l: ::geo_types::Line<f64>) -> Self {
        Segment2::new(l.start.into(), l.end.into())
    }
}

fn to_line_string(ring: &[Point2]) -> ::geo_types::LineString<f64> {
    ::geo_types::LineString::new(ring.iter().map(|&p| p.into()).collect())
}

fn from_ring(ls: &::geo_types::LineString<f64>) -> Vec<Point2> {
    let pts: Vec<Point2> = ls.0.iter().map(|&c| c.into()).collect();
    open_ring(&pts).to_vec()
}

/// Rings are closed on the way (geo-types' `Polygon::new` closes them).
impl From<Polygon> for ::geo_types::Polygon<f64> {
    fn from(p: Polygon) -> Self {
        ::geo_types::Polygon::new(
            to_line_string(&p.exterior),
            p.holes.iter().map(|h| to_line_string(h)).collect(),
        )
    }
}

/// Rings come back open (the closing vertex dropped).
impl From<::geo_types::Polygon<f64>> for Polygon {
    fn from(p: ::geo_types::Polygon<f64>) -> Self {
        Polygon::new(
            from_ring(p.exterior()),
            p.interiors().iter().map(from_ring).collect(),
        )
    }
}

impl From<MultiPolygon> for ::geo_types::MultiPolygon<f64> {
    fn from(mp: MultiPolygon) -> Self {
        ::geo_types::MultiPolygon::new(mp.0.into_iter().map(Into::into).collect())
    }
}

impl From<::geo_types::MultiPolygon<f64>> for MultiPolygon {
    fn from(mp: ::geo_types::MultiPolygon<f64>) -> Self {
        MultiPolygon(mp.0.into_iter().map(Into::into).collect())
    }
}

/// `Empty` becomes an empty `GeometryCollection`.
impl From<Shape> for ::geo_types::Geometry<f64> {
    fn from(s: Shape) -> Self {
        use ::geo_types::Geometry as G;
        match s {
            Shape::Empty => G::GeometryCollection(::geo_types::GeometryCollection::default()),
            Shape::Point(p) => G::Point(p.into()),
            Shape::MultiPoint(ps) => G::MultiPoint(::geo_types::MultiPoint::new(
                ps.into_iter().map(Into::into).collect(),
            )),
            Shape::LineString(ps) => G::LineString(to_line_string(&ps)),
            Shape::Polygon(p) => G::Polygon(p.into()),
            Shape::MultiPolygon(mp) => G::MultiPolygon(mp.into()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polygon_rings_close_and_reopen() {
        let square = Polygon::new(
            vec![
                Point2::new(0.0, 0.0),
                Point2::new(1.0, 0.0),
                Point2::new(1.0, 1.0),
                Point2::new(0.0, 1.0),
            ],
            vec![vec![
                Point2::new(0.25, 0.25),
                Point2::new(0.25, 0.5),
                Point2::new(0.5, 0.25),
            ]],
        );
        let g: ::geo_types::Polygon<f64> = square.clone().into();
        assert_eq!(g.exterior().0.len(), 5);
        assert_eq!(g.exterior().0[4], g.exterior().0[0]);
        assert_eq!(g.interiors()[0].0.len(), 4);
        assert_eq!(Polygon::from(g), square);
    }

    #[test]
    fn shapes_map_to_geometries() {
        let g: ::geo_types::Geometry<f64> = Shape::Empty.into();
        assert!(matches!(g, ::geo_types::Geometry::GeometryCollection(ref c) if c.0.is_empty()));
        let s = Segment2::new(Point2::new(1.0, 2.0), Point2::new(3.0, 4.0));
        let l: ::geo_types::Line<f64> = s.into();
        assert_eq!((l.start.x, l.end.y), (1.0, 4.0));
        assert_eq!(Segment2::from(l), s);
        let g: ::geo_types::Geometry<f64> = Shape::LineString(vec![s.a, s.b]).into();
        assert!(matches!(g, ::geo_types::Geometry::LineString(ref ls) if ls.0.len() == 2));
    }
}
