//! Integration tests of `compgeom::io`: every reader on good and bad input of each format
//! (errors checked for their line), writers that round-trip exactly, RFC 7946 ring
//! orientation against an exact rational oracle, and real fixture files read in place.

mod common;
use common::cases_dir;
use compgeom::io::{
    detect_format, format_f64, read_off, read_points, read_points3, read_polygon_features,
    read_polygon_layer, read_polygons, read_polygons_as_written, read_segments, read_text,
    ring_orientation, write_off, write_points3, write_segments, write_shape, Format, OpenRing,
    Polyhedron, Shape,
};
use compgeom::{Error, MultiPolygon, Orientation, Point2, Point3, Polygon, Segment2};
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use proptest::prelude::*;
use std::path::{Path, PathBuf};

// ---------------------------------------------------------------- helpers

fn p(x: f64, y: f64) -> Point2 {
    Point2::new(x, y)
}

/// The message and line of a parse error; panics (failing the test) on anything else.
fn parse_error<T: std::fmt::Debug>(r: compgeom::Result<T>) -> (String, Option<usize>) {
    match r {
        Err(Error::Parse { message, location }) => (message, location.line),
        other => panic!("expected a parse error, got {other:?}"),
    }
}

/// Assert a parse error at `line` whose message contains `needle`.
fn assert_parse_error<T: std::fmt::Debug>(r: compgeom::Result<T>, line: usize, needle: &str) {
    let (message, at) = parse_error(r);
    assert_eq!(at, Some(line), "wrong line for `{message}`");
    assert!(
        message.contains(needle),
        "message `{message}` lacks `{needle}`"
    );
}

fn same_bits(a: &[Point2], b: &[Point2]) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(u, v)| u.x.to_bits() == v.x.to_bits() && u.y.to_bits() == v.y.to_bits())
}

// ---------------------------------------------------------------- formats

/// A polygon layer carries each Feature's properties from the same parse: one per
/// Feature in order (null where absent, also for a Feature without geometry), a single
/// Feature's, none for a bare geometry or WKT; polygons and features as
/// `read_polygon_features` gives them; bad input the same error.
#[test]
fn polygon_layers_carry_feature_properties() {
    let square = "[[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]]";
    let fc = format!(
        r#"{{"type": "FeatureCollection", "features": [
  {{"type": "Feature", "properties": {{"id": 7}}, "geometry": {{"type": "MultiPolygon",
    "coordinates": [[{square}], [{square}]]}}}},
  {{"type": "Feature", "geometry": null}},
  {{"type": "Feature", "properties": {{"id": 9}}, "geometry": {{"type": "Polygon",
    "coordinates": [{square}]}}}}]}}"#
    );
    let layer = read_polygon_layer(&fc, Format::GeoJson, "in").unwrap();
    let (polygons, features) = read_polygon_features(&fc, Format::GeoJson, "in").unwrap();
    assert_eq!((&layer.polygons, &layer.features), (&polygons, &features));
    assert_eq!(layer.features, vec![0, 0, 2]);
    let ids: Vec<String> = layer
        .properties
        .iter()
        .map(|v| v["id"].to_string())
        .collect();
    assert_eq!(ids, ["7", "null", "9"]);
    let one = format!(
        r#"{{"type": "Feature", "properties": {{"id": 3}}, "geometry": {{"type": "Polygon",
    "coordinates": [{square}]}}}}"#
    );
    let layer = read_polygon_layer(&one, Format::GeoJson, "in").unwrap();
    assert_eq!(layer.properties.len(), 1);
    assert_eq!(layer.properties[0]["id"], 3);
    let bare = format!(r#"{{"type": "Polygon", "coordinates": [{square}]}}"#);
    assert!(read_polygon_layer(&bare, Format::GeoJson, "in")
        .unwrap()
        .properties
        .is_empty());
    let wkt = read_polygon_layer("POLYGON ((0 0, 1 0, 0 1, 0 0))", Format::Wkt, "in").unwrap();
    assert_eq!((wkt.features, wkt.properties.len()), (vec![0], 0));
    let bad = r#"{"type": "Feature", "properties": {}, "geometry": {"type": "Polygon",
    "coordinates": [[[0, 0], [1, 0], [0, 0]]]}}"#;
    assert_eq!(
        read_polygon_layer(bad, Format::GeoJson, "in")
            .unwrap_err()
            .to_string(),
        read_polygon_features(bad, Format::GeoJson, "in")
            .unwrap_err()
            .to_string()
    );
}

#[test]
fn format_names_and_extensions() {
    for (name, f) in [
        ("csv", Format::Csv),
        ("TXT", Format::Csv),
        ("xyz", Format::Csv),
        ("wkt", Format::Wkt),
        ("geojson", Format::GeoJson),
        ("off", Format::Off),
        ("json", Format::Json),
    ] {
        assert_eq!(Format::from_name(name), Some(f), "{name}");
        let path = format!("dir/file.{name}");
        assert_eq!(Format::from_extension(Path::new(&path)), Some(f), "{path}");
    }
    assert_eq!(Format::from_name("svg"), None);
    assert_eq!(Format::from_extension(Path::new("README")), None);
    assert_eq!(
        Format::from_name(Format::GeoJson.name()),
        Some(Format::GeoJson)
    );
}

#[test]
fn detect_format_extension_first_then_content() {
    // Extension wins over content; `.json` input is GeoJSON.
    assert_eq!(
        detect_format(Some(Path::new("a.csv")), "POINT (1 2)").unwrap(),
        Format::Csv
    );
    assert_eq!(
        detect_format(Some(Path::new("a.json")), "{}").unwrap(),
        Format::GeoJson
    );
    let sniff = |t: &str| detect_format(Some(Path::new("-")), t);
    assert_eq!(sniff("  {\"type\": \"Point\"}").unwrap(), Format::GeoJson);
    assert_eq!(sniff("[[0, 0], [1, 1]]").unwrap(), Format::GeoJson);
    assert_eq!(sniff("# comment\nOFF\n0 0 0\n").unwrap(), Format::Off);
    assert_eq!(sniff("\n\nmultipolygon EMPTY").unwrap(), Format::Wkt);
    assert_eq!(sniff("POINTZ (1 2 3)").unwrap(), Format::Wkt);
    assert_eq!(sniff("1 2\n3 4").unwrap(), Format::Csv);
    assert_eq!(sniff("x,y\n1,2").unwrap(), Format::Csv);
    assert_eq!(sniff("-1.5e3;2").unwrap(), Format::Csv);
    assert_eq!(sniff("").unwrap(), Format::Csv);
    // `.txt` is sniffed, CSV when unsure.
    let txt = |t: &str| detect_format(Some(Path::new("in.txt")), t).unwrap();
    assert_eq!(txt("LINESTRING (0 0, 1 1)"), Format::Wkt);
    assert_eq!(txt("1 2"), Format::Csv);
    assert_eq!(txt("what is this"), Format::Csv);
    assert_eq!(sniff("# only a comment\n\n").unwrap(), Format::Csv);
    for bad in ["hello there\nworld", "x,y\nfoo,bar", "<svg/>", "17"] {
        match sniff(bad) {
            Err(Error::UnknownFormat(m)) => assert!(m.contains('-'), "{m}"),
            other => panic!("{bad:?}: expected UnknownFormat, got {other:?}"),
        }
    }
}

#[test]
fn read_text_reads_files_and_locates_bad_utf8() {
    let dir = std::env::temp_dir().join(format!("compgeom-io-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let good = dir.join("pts.csv");
    std::fs::write(&good, "0,0\n1,1\n").unwrap();
    let text = read_text(&good).unwrap();
    assert_eq!(read_points(&text, Format::Csv, "pts.csv").unwrap().len(), 2);
    let bad = dir.join("bad.csv");
    std::fs::write(&bad, b"0,0\n1,1\n2,\xff\n").unwrap();
    assert_eq!(parse_error(read_text(&bad)).1, Some(3));
    assert!(matches!(
        read_text(&dir.join("missing.csv")),
        Err(Error::Io { .. })
    ));
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---------------------------------------------------------------- CSV

#[test]
fn csv_points_with_every_separator_comment_and_header() {
    let text = "\u{feff}# survey points\nx, y\n0,0\n1.5 -2\n\n3\t4 # trailing comment\n5;6\n  7 ,  8  \n1e3,-0.25\n";
    let pts = read_points(text, Format::Csv, "pts.csv").unwrap();
    assert_eq!(
        pts,
        vec![
            p(0.0, 0.0),
            p(1.5, -2.0),
            p(3.0, 4.0),
            p(5.0, 6.0),
            p(7.0, 8.0),
            p(1000.0, -0.25)
        ]
    );
}

#[test]
fn csv_points3_and_segments() {
    let pts = read_points3("x y z\n1 2 3\n-1,0,0.5\n", Format::Csv, "p3").unwrap();
    assert_eq!(
        pts,
        vec![Point3::new(1.0, 2.0, 3.0), Point3::new(-1.0, 0.0, 0.5)]
    );
    let segs = read_segments("# segs\n0,0,1,1\n2 2 2 2\n", Format::Csv, "s").unwrap();
    assert_eq!(
        segs,
        vec![
            Segment2::new(p(0.0, 0.0), p(1.0, 1.0)),
            // A zero-length segment written out is kept.
            Segment2::new(p(2.0, 2.0), p(2.0, 2.0)),
        ]
    );
}

#[test]
fn csv_polygons_blank_line_between_rings_two_between_polygons() {
    let text = "\
0,0\n4,0\n4,4\n0,4\n0,0\n\
\n\
1,1\n1,2\n2,1\n\
# a comment does not separate\n\
\n\n\
10,10\n11,10\n10,11\n";
    let mp = read_polygons(text, Format::Csv, "poly.csv").unwrap();
    assert_eq!(mp.0.len(), 2);
    assert_eq!(
        mp.0[0].exterior,
        vec![p(0.0, 0.0), p(4.0, 0.0), p(4.0, 4.0), p(0.0, 4.0)]
    );
    assert_eq!(
        mp.0[0].holes,
        vec![vec![p(1.0, 1.0), p(1.0, 2.0), p(2.0, 1.0)]]
    );
    assert_eq!(mp.0[1].exterior.len(), 3);
    assert!(mp.0[1].holes.is_empty());
}

#[test]
fn csv_errors_name_the_line() {
    let src = "pts.csv";
    assert_parse_error(
        read_points("0,0\n1,2\n1.2.3,4\n", Format::Csv, src),
        3,
        "malformed number `1.2.3` in field 1",
    );
    assert_parse_error(
        read_points("0,0\n\n# c\n1,2,3\n", Format::Csv, src),
        4,
        "expected 2 fields",
    );
    assert_parse_error(read_points("1\n", Format::Csv, src), 1, "found 1");
    assert_parse_error(
        read_points("0 0\n1 nan\n", Format::Csv, src),
        2,
        "non-finite coordinate `nan` in field 2",
    );
    assert_parse_error(
        read_points("0 0\n-inf 0\n", Format::Csv, src),
        2,
        "non-finite",
    );
    assert_parse_error(
        read_points("0 0\n1e999 0\n", Format::Csv, src),
        2,
        "non-finite",
    );
    assert_parse_error(read_points("0 0\nx y\n", Format::Csv, src), 2, "malformed");
    assert_parse_error(read_points("1,,2\n", Format::Csv, src), 1, "empty");
    // A decimal comma is an error, not a silent misreading.
    assert_parse_error(
        read_segments("1,5;2,5;0;0\n", Format::Csv, src),
        1,
        "malformed",
    );
    assert_parse_error(read_segments("0,0,1\n", Format::Csv, src), 1, "expected 4");
    assert_parse_error(read_points3("0,0\n", Format::Csv, src), 1, "expected 3");
    assert_parse_error(
        read_polygons("0,0\n1,0\n\n2,2\n3,3\n4,2\n", Format::Csv, src),
        1,
        "at least 3",
    );
    // The error prints as `message (file:line)`.
    let e = read_points("0,0\nz,1\n", Format::Csv, "in.csv").unwrap_err();
    assert!(e.to_string().ends_with("(in.csv:2)"), "{e}");
}

#[test]
fn empty_input_is_an_empty_result_in_every_format() {
    for text in ["", "\n\n", "# nothing here\n"] {
        for f in [Format::Csv, Format::Wkt] {
            assert!(read_points(text, f, "e").unwrap().is_empty());
            assert!(read_segments(text, f, "e").unwrap().is_empty());
            assert!(read_polygons(text, f, "e").unwrap().0.is_empty());
        }
        assert!(read_points3(text, Format::Csv, "e").unwrap().is_empty());
        assert!(read_points3(text, Format::Off, "e").unwrap().is_empty());
        assert_eq!(read_off(text, "e").unwrap(), Polyhedron::default());
    }
    for text in ["", "  \n"] {
        assert!(read_points(text, Format::GeoJson, "e").unwrap().is_empty());
    }
    let fc = r#"{"type":"FeatureCollection","features":[]}"#;
    assert!(read_polygons(fc, Format::GeoJson, "e")
        .unwrap()
        .0
        .is_empty());
    assert!(read_points("[]", Format::GeoJson, "e").unwrap().is_empty());
    assert!(read_points("GEOMETRYCOLLECTION EMPTY", Format::Wkt, "e")
        .unwrap()
        .is_empty());
}

// ---------------------------------------------------------------- WKT

const WKT_MIX: &str = "\
# a mixed file
POINT (1 2)
MULTIPOINT ((3 4), (5 6))
multipoint (7 8, 9 10)
LINESTRING (0 0, 1 0, 1 0, 2 1)
POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0),
         (1 1, 1 2, 2 2, 1 1))
POINT EMPTY
POINT Z (100 200 300)
SRID=4326;POINT (-1 -2)
";

#[test]
fn wkt_points_collect_every_vertex() {
    let pts = read_points(WKT_MIX, Format::Wkt, "mix.wkt").unwrap();
    let want = vec![
        p(1.0, 2.0),
        p(3.0, 4.0),
        p(5.0, 6.0),
        p(7.0, 8.0),
        p(9.0, 10.0),
        // Line-string vertices, repeats included.
        p(0.0, 0.0),
        p(1.0, 0.0),
        p(1.0, 0.0),
        p(2.0, 1.0),
        // Ring vertices without the closing repeat.
        p(0.0, 0.0),
        p(4.0, 0.0),
        p(4.0, 4.0),
        p(0.0, 4.0),
        p(1.0, 1.0),
        p(1.0, 2.0),
        p(2.0, 2.0),
        // Z dropped.
        p(100.0, 200.0),
        // EWKT prefix skipped.
        p(-1.0, -2.0),
    ];
    assert_eq!(pts, want);
}

#[test]
fn wkt_segments_include_closing_edges_and_skip_zero_length() {
    let text = "LINESTRING (0 0, 1 0, 1 0, 2 1)\nLINEARRING (5 5, 6 5, 5 6, 5 5)\n\
                MULTILINESTRING ((0 9, 9 9), EMPTY)\nPOLYGON ((0 0, 1 0, 0 1, 0 0))";
    let segs = read_segments(text, Format::Wkt, "s.wkt").unwrap();
    let s = |a: (f64, f64), b: (f64, f64)| Segment2::new(p(a.0, a.1), p(b.0, b.1));
    assert_eq!(
        segs,
        vec![
            s((0.0, 0.0), (1.0, 0.0)),
            s((1.0, 0.0), (2.0, 1.0)),
            // LINEARRING is a line string: its edges as written.
            s((5.0, 5.0), (6.0, 5.0)),
            s((6.0, 5.0), (5.0, 6.0)),
            s((5.0, 6.0), (5.0, 5.0)),
            s((0.0, 9.0), (9.0, 9.0)),
            // The polygon ring's edges, its closing one once.
            s((0.0, 0.0), (1.0, 0.0)),
            s((1.0, 0.0), (0.0, 1.0)),
            s((0.0, 1.0), (0.0, 0.0)),
        ]
    );
}

/// WKT and GeoJSON polygon rings repeat their first position at the end; a ring that
/// does not is an error naming it, for polygons and for segments alike. Bare JSON arrays
/// of rings (earcut's fixtures) need not repeat it.
#[test]
fn open_wkt_and_geojson_rings_are_errors() {
    let open = [
        (
            "POLYGON ((0 0, 1 0, 1 1))",
            Format::Wkt,
            "ring 1 is not closed",
        ),
        (
            "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 0)), ((5 5, 9 5, 9 9, 5 5), (6 5.5, 8 5.5, 8 8)))",
            Format::Wkt,
            "ring 2 is not closed: it ends at (8, 8), not at its first position (6, 5.5)",
        ),
        (
            r#"{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1]]]}"#,
            Format::GeoJson,
            "ring 1 is not closed",
        ),
        (
            r#"{"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
                "geometry": {"type": "MultiPolygon", "coordinates": [[[[0, 0], [1, 0], [1, 1]]]]}}]}"#,
            Format::GeoJson,
            "feature 1",
        ),
    ];
    for (text, format, want) in open {
        for e in [
            read_polygons(text, format, "in").unwrap_err(),
            read_segments(text, format, "in").unwrap_err(),
        ] {
            let e = e.to_string();
            assert!(e.contains(want) && e.contains("not closed"), "{text}: {e}");
        }
    }
    // Closed in x and y but not in z is not closed.
    let z = read_polygons(
        "POLYGON Z ((0 0 1, 1 0 1, 1 1 1, 0 0 2))",
        Format::Wkt,
        "in",
    );
    let e = z.unwrap_err().to_string();
    assert!(e.contains("ring 1 is not closed: it ends at (0, 0) as it starts, but at z = 2, not its first z = 1"), "{e}");
    let open = read_polygons_as_written(
        "POLYGON Z ((0 0 1, 1 0 1, 1 1 1, 0 0 2))",
        Format::Wkt,
        "in",
    )
    .unwrap()
    .open_rings;
    assert_eq!((open.len(), open[0].z), (1, Some((1.0, 2.0))));
    assert!(open[0].how_open().contains("z = 2"));
    assert!(read_polygons(
        "POLYGON Z ((0 0 1, 1 0 1, 1 1 1, 0 0 1))",
        Format::Wkt,
        "in"
    )
    .is_ok());
    // Closed, the same rings read; a ring too short to close still gets the count error.
    assert!(read_polygons("POLYGON ((0 0, 1 0, 1 1, 0 0))", Format::Wkt, "in").is_ok());
    let short = read_polygons("POLYGON ((0 0, 1 0, 0 0))", Format::Wkt, "in").unwrap_err();
    assert!(short.to_string().contains("needs at least 3"), "{short}");
    // A bare array of rings may leave the repeat out.
    let bare = read_polygons("[[[0, 0], [1, 0], [1, 1]]]", Format::GeoJson, "in").unwrap();
    assert_eq!(
        bare.0[0].exterior,
        vec![p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0)]
    );
}

/// `read_polygons_as_written` reads what `read_polygons` rejects as a ring: open rings
/// (listed, with their polygon and ring and both end positions, read as if closed) and
/// short rings; the polygons it reads otherwise are the same.
#[test]
fn polygons_as_written_list_open_rings_and_keep_short_ones() {
    let text =
        "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 0)), ((5 5, 9 5, 9 9, 5 9), (6 5.5, 8 5.5, 8 8)))\n\
                POLYGON EMPTY\n\
                POLYGON ((0 0, 1 0, 0 0))";
    let read = read_polygons_as_written(text, Format::Wkt, "in").unwrap();
    assert_eq!(read.features, [0, 1, 2]);
    let (polygons, open) = (read.polygons, read.open_rings);
    assert_eq!(polygons.0.len(), 3);
    assert_eq!(
        open,
        vec![
            OpenRing {
                polygon: 1,
                ring: 0,
                first: p(5.0, 5.0),
                last: p(5.0, 9.0),
                z: None,
            },
            OpenRing {
                polygon: 1,
                ring: 1,
                first: p(6.0, 5.5),
                last: p(8.0, 8.0),
                z: None,
            },
        ]
    );
    assert_eq!(polygons.0[1].exterior.len(), 4);
    assert_eq!(polygons.0[1].holes[0].len(), 3);
    assert_eq!(polygons.0[2].exterior, vec![p(0.0, 0.0), p(1.0, 0.0)]);
    // GeoJSON alike; closed input reads as `read_polygons` reads it, with nothing listed.
    let json = r#"{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1]]]}"#;
    let open = read_polygons_as_written(json, Format::GeoJson, "in")
        .unwrap()
        .open_rings;
    assert_eq!((open.len(), open[0].last), (1, p(1.0, 1.0)));
    for (text, format) in [
        (
            "POLYGON ((0 0, 4 0, 4 4, 0 0), (1 1, 2 1, 1 2, 1 1))",
            Format::Wkt,
        ),
        ("[[[0, 0], [1, 0], [1, 1]]]", Format::GeoJson),
        ("0,0\n1,0\n1,1\n", Format::Csv),
    ] {
        let read = read_polygons_as_written(text, format, "in").unwrap();
        let (polygons, open) = (read.polygons, read.open_rings);
        assert!(open.is_empty(), "{text}");
        assert_eq!(
            polygons,
            read_polygons(text, format, "in").unwrap(),
            "{text}"
        );
    }
    // An EMPTY hole is no hole, to both readers.
    let text = "POLYGON ((0 0, 4 0, 4 4, 0 0), EMPTY, (1 0.5, 3 2.5, 3 0.5, 1 0.5))";
    let read = read_polygons_as_written(text, Format::Wkt, "in").unwrap();
    let (polygons, open) = (read.polygons, read.open_rings);
    assert!(open.is_empty());
    assert_eq!(polygons.0[0].holes.len(), 1);
    assert_eq!(polygons, read_polygons(text, Format::Wkt, "in").unwrap());
    // A short CSV ring too; what is not a polygon is still an error.
    let short = read_polygons_as_written("0,0\n1,0\n", Format::Csv, "in")
        .unwrap()
        .polygons;
    assert_eq!(short.0[0].exterior.len(), 2);
    assert!(read_polygons("0,0\n1,0\n", Format::Csv, "in").is_err());
    assert!(read_polygons_as_written("POINT (1 2)", Format::Wkt, "in").is_err());
}

#[test]
fn wkt_polygons_and_collections() {
    let text = "GEOMETRYCOLLECTION (POLYGON ((0 0, 2 0, 2 2, 0 0)), \
                MULTIPOLYGON (((10 10, 12 10, 12 12, 10 10), (10.5 10.2, 11.5 10.2, 11.5 11, 10.5 10.2)), EMPTY))\n\
                POLYGON EMPTY\n";
    let mp = read_polygons(text, Format::Wkt, "p.wkt").unwrap();
    assert_eq!(mp.0.len(), 2);
    assert_eq!(
        mp.0[0].exterior,
        vec![p(0.0, 0.0), p(2.0, 0.0), p(2.0, 2.0)]
    );
    assert_eq!(mp.0[1].holes.len(), 1);
    assert_eq!(mp.0[1].holes[0].len(), 3);
}

#[test]
fn wkt_errors_name_the_line() {
    let src = "bad.wkt";
    assert_parse_error(
        read_points("POINT (1 2)\nPOINT (3 4)\nPOINT (5 x)\n", Format::Wkt, src),
        3,
        "invalid WKT",
    );
    assert_parse_error(
        read_points(
            "POINT (1 2)\n\nTRIANGLE ((0 0, 1 0, 0 1, 0 0))\n",
            Format::Wkt,
            src,
        ),
        3,
        "unknown WKT geometry type `TRIANGLE`",
    );
    assert_parse_error(
        read_points("POINT (1 2)\nLINESTRING (0 0,\n 1 1\n", Format::Wkt, src),
        2,
        "never closed",
    );
    assert_parse_error(
        read_points("LINESTRING (0 0,\n nan 1)\n", Format::Wkt, src),
        2,
        "non-finite coordinate `nan`",
    );
    assert_parse_error(
        read_points("POINT (inf 1)", Format::Wkt, src),
        1,
        "non-finite",
    );
    // 401 digits overflow to infinity.
    let digits = format!("1{}", "0".repeat(400));
    let long = format!("POINT ({digits} 1)");
    assert_parse_error(read_points(&long, Format::Wkt, src), 1, "non-finite");
    let long = format!("0 0\n{digits} 1");
    assert_parse_error(read_points(&long, Format::Csv, src), 2, "non-finite");
    assert_parse_error(
        read_points("\nPOINT (1e999 1)", Format::Wkt, src),
        2,
        "non-finite",
    );
    assert_parse_error(
        read_points("POINT (1 2) garbage", Format::Wkt, src),
        1,
        "garbage",
    );
    assert_parse_error(read_points("POINT (1 2))", Format::Wkt, src), 1, "keyword");
    assert_parse_error(read_points("POINT", Format::Wkt, src), 1, "EMPTY");
    assert_parse_error(read_points("POINT FOO (1 2)", Format::Wkt, src), 1, "FOO");
    assert_parse_error(
        read_segments("LINESTRING (0 0, 1 1)\nMULTIPOINT (1 1)", Format::Wkt, src),
        2,
        "no edges",
    );
    assert_parse_error(
        read_polygons(
            "POLYGON ((0 0, 1 0, 1 1, 0 0))\nLINESTRING (0 0, 1 1)",
            Format::Wkt,
            src,
        ),
        2,
        "not a polygon",
    );
    assert_parse_error(
        read_polygons("POLYGON ((0 0, 1 0, 0 0))", Format::Wkt, src),
        1,
        "at least 3",
    );
    assert_parse_error(
        read_points3("POINT Z (1 2 3)\nPOINT (1 2)", Format::Wkt, src),
        2,
        "no z value",
    );
    let deep = format!(
        "{}POINT (1 2){}",
        "GEOMETRYCOLLECTION (".repeat(40),
        ")".repeat(40)
    );
    assert_parse_error(read_points(&deep, Format::Wkt, src), 1, "nested");
}

// ---------------------------------------------------------------- GeoJSON

#[test]
fn geojson_geometry_feature_and_collection() {
    let g = r#"{"type": "MultiPoint", "coordinates": [[1, 2], [3, 4, 99]]}"#;
    assert_eq!(
        read_points(g, Format::GeoJson, "g").unwrap(),
        vec![p(1.0, 2.0), p(3.0, 4.0)]
    );
    let f = r#"{"type": "Feature", "properties": {"name": "tri"},
               "geometry": {"type": "Polygon", "coordinates": [[[0,0],[1,0],[0,1],[0,0]]]}}"#;
    let mp = read_polygons(f, Format::GeoJson, "f").unwrap();
    assert_eq!(
        mp.0[0].exterior,
        vec![p(0.0, 0.0), p(1.0, 0.0), p(0.0, 1.0)]
    );
    let fc = r#"{"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": null, "geometry": null},
        {"type": "Feature", "properties": {}, "geometry":
            {"type": "LineString", "coordinates": [[0,0],[2,0],[2,0],[2,2]]}},
        {"type": "Feature", "properties": {}, "geometry":
            {"type": "GeometryCollection", "geometries": [
                {"type": "MultiPolygon", "coordinates": [[[[5,5],[6,5],[6,6],[5,5]]]]}]}}
    ]}"#;
    let segs = read_segments(fc, Format::Json, "fc.json").unwrap();
    assert_eq!(segs.len(), 2 + 3);
    assert_eq!(read_points(fc, Format::GeoJson, "fc").unwrap().len(), 4 + 3);
    // The second feature starts on line 3 of `fc`.
    assert_parse_error(
        read_polygons(fc, Format::GeoJson, "fc"),
        3,
        "feature 2 (LineString): not a polygon",
    );
    assert_parse_error(
        read_segments(
            "\n\n  {\"type\": \"Point\", \"coordinates\": [1, 2]}",
            Format::GeoJson,
            "pt",
        ),
        3,
        "no edges",
    );
    let z = r#"{"type": "Point", "coordinates": [1, 2, 3]}"#;
    assert_eq!(
        read_points3(z, Format::GeoJson, "z").unwrap(),
        vec![Point3::new(1.0, 2.0, 3.0)]
    );
}

/// An empty polygon in a MultiPolygon is no polygon, wherever it stands (the `geojson`
/// crate alone rejects one that comes first), also inside a collection; the polygons
/// after it keep their feature.
#[test]
fn geojson_multipolygons_with_empty_members() {
    let square = "[[[0,0],[4,0],[4,4],[0,4],[0,0]]]";
    let tri = "[[[5,5],[6,5],[5,6],[5,5]]]";
    for coordinates in [
        format!("[[], {square}]"),
        format!("[[], [], {square}, [], {tri}]"),
        format!("[[[]], {square}, [], {tri}]"),
    ] {
        let geometry = format!(r#"{{"type": "MultiPolygon", "coordinates": {coordinates}}}"#);
        let want = if coordinates.contains(tri) { 2 } else { 1 };
        let mp = read_polygons(&geometry, Format::GeoJson, "g").unwrap();
        assert_eq!(mp.0.len(), want, "{geometry}");
        assert_eq!(mp.0[0].exterior.len(), 4, "{geometry}");
        let fc = format!(
            r#"{{"type": "FeatureCollection", "features": [
                {{"type": "Feature", "properties": {{}}, "geometry": {{"type": "Polygon", "coordinates": {tri}}}}},
                {{"type": "Feature", "properties": {{}}, "geometry":
                    {{"type": "GeometryCollection", "geometries": [{geometry}]}}}}]}}"#
        );
        let read = compgeom::io::read_polygons_as_written(&fc, Format::GeoJson, "fc").unwrap();
        assert_eq!(read.polygons.0.len(), 1 + want, "{fc}");
        assert_eq!(read.features[0], 0);
        assert!(
            read.features[1..].iter().all(|&f| f == 1),
            "{:?}",
            read.features
        );
    }
    // Still an error where the coordinates are wrong for other reasons, naming that
    // reason; and the retry does not make other broken documents acceptable (a key given
    // twice).
    let (m, line) = parse_error(read_polygons(
        "{\"type\": \"MultiPolygon\",\n\"coordinates\": [[], [[[0, \"a\"]]]]}",
        Format::GeoJson,
        "g",
    ));
    assert!(m.contains("invalid GeoJSON") && m.contains("\"a\""), "{m}");
    assert_eq!(line, Some(2));
    let twice = r#"{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]],"coordinates":[[[5,5],[6,5],[6,6],[5,5]]]}"#;
    let (m, _) = parse_error(read_polygons(twice, Format::GeoJson, "g"));
    assert!(m.contains("duplicate field"), "{m}");
}

#[test]
fn bare_json_arrays_as_points_rings_and_polygons() {
    assert_eq!(
        read_points("[[0, 0], [1.5, 2]]", Format::GeoJson, "d").unwrap(),
        vec![p(0.0, 0.0), p(1.5, 2.0)]
    );
    let earcut = "[[[0,0],[10,0],[10,10],[0,10]], [[2,2],[2,4],[4,4]]]";
    let mp = read_polygons(earcut, Format::GeoJson, "e").unwrap();
    assert_eq!(mp.0.len(), 1);
    assert_eq!(mp.0[0].exterior.len(), 4);
    assert_eq!(mp.0[0].holes.len(), 1);
    let many = "[[[[0,0],[1,0],[0,1]]], [[[5,5],[6,5],[5,6]]]]";
    assert_eq!(
        read_polygons(many, Format::GeoJson, "m").unwrap().0.len(),
        2
    );
    assert!(read_points("[[0, \"a\"]]", Format::GeoJson, "d").is_err());
    assert!(read_points("[[[[[0, 0]]]]]", Format::GeoJson, "d").is_err());
}

#[test]
fn geojson_errors_carry_the_line() {
    let src = "bad.geojson";
    assert_parse_error(
        read_points(
            "{\n\"type\": \"Point\",\n\"coordinates\": [1, 2,]\n}",
            Format::GeoJson,
            src,
        ),
        3,
        "invalid GeoJSON",
    );
    assert_parse_error(
        read_points(
            "{\"type\": \"Point\",\n\"coordinates\": [1e999, 2]}",
            Format::GeoJson,
            src,
        ),
        2,
        "invalid GeoJSON",
    );
    assert_parse_error(
        read_points(
            "{\"type\": \"Point\",\n\"coordinates\": [NaN, 2]}",
            Format::GeoJson,
            src,
        ),
        2,
        "invalid GeoJSON",
    );
    // Well-formed JSON that is not GeoJSON.
    let (m, _) = parse_error(read_points("{\"type\": \"Circle\"}", Format::GeoJson, src));
    assert!(m.contains("invalid GeoJSON"), "{m}");
    let (m, _) = parse_error(read_points(
        "{\"type\": \"Point\", \"coordinates\": [1]}",
        Format::GeoJson,
        src,
    ));
    assert!(m.contains("invalid GeoJSON"), "{m}");
}

// ---------------------------------------------------------------- OFF

const CUBE_OFF: &str = "\
OFF
# a unit cube
8 6 12
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
4 0 3 2 1
4 4 5 6 7
4 0 1 5 4
4 1 2 6 5
4 2 3 7 6
4 3 0 4 7   255 0 0
";

#[test]
fn off_reads_vertices_and_faces() {
    let cube = read_off(CUBE_OFF, "cube.off").unwrap();
    assert_eq!(cube.vertices.len(), 8);
    assert_eq!(cube.vertices[6], Point3::new(1.0, 1.0, 1.0));
    assert_eq!(cube.faces.len(), 6);
    assert_eq!(cube.faces[5], vec![3, 0, 4, 7]);
    assert_eq!(
        read_points3(CUBE_OFF, Format::Off, "cube.off").unwrap(),
        cube.vertices
    );
    // Counts on the header line.
    let tri = read_off("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "t").unwrap();
    assert_eq!(tri.faces, vec![vec![0, 1, 2]]);
    assert_eq!(read_off(&write_off(&cube), "w").unwrap(), cube);
}

#[test]
fn off_errors_name_the_line() {
    let src = "bad.off";
    let base = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
    assert_parse_error(
        read_off(&format!("{base}3 0 1 3\n"), src),
        6,
        "out of range",
    );
    assert_parse_error(read_off(&format!("{base}2 0 1\n"), src), 6, "at least 3");
    assert_parse_error(
        read_off(&format!("{base}3 0 1\n"), src),
        6,
        "expected 3 indices",
    );
    assert_parse_error(read_off(&format!("{base}3 0 1 -2\n"), src), 6, "`-2`");
    assert_parse_error(
        read_off(&format!("{base}3 0 1 2\n9 9 9\n"), src),
        7,
        "after the last face",
    );
    assert_parse_error(read_off(base, src), 5, "expected 1 faces");
    assert_parse_error(
        read_off("OFF\n3 1 0\n0 0 0\n1 nan 0\n", src),
        4,
        "non-finite",
    );
    assert_parse_error(read_off("OFF\n3 1 0\n0 0\n", src), 3, "expected 3 fields");
    assert_parse_error(read_off("OFF\nx 1 0\n", src), 2, "not a whole number");
    assert_parse_error(read_off("COFF\n", src), 1, "header");
    assert_parse_error(read_off("# c\nOFF\n1e20 1 0\n", src), 3, "count");
    assert!(matches!(
        read_points(CUBE_OFF, Format::Off, src),
        Err(Error::InvalidInput(_))
    ));
}

// ---------------------------------------------------------------- writers

#[test]
fn format_f64_known_values() {
    for (x, s) in [
        (0.0, "0"),
        (-0.0, "-0"),
        (1.0, "1"),
        (-2.5, "-2.5"),
        (0.1, "0.1"),
        (1e200, "1e200"),
        (5e-324, "5e-324"),
        (1e-7, "1e-7"),
        (123456.0, "123456"),
        (1e21, "1e21"),
        (f64::MAX, "1.7976931348623157e308"),
    ] {
        assert_eq!(format_f64(x), s, "{x:e}");
        assert_eq!(s.parse::<f64>().unwrap().to_bits(), x.to_bits());
    }
}

#[test]
fn write_shape_layouts() {
    let sq = Polygon::new(
        vec![p(0.0, 0.0), p(4.0, 0.0), p(4.0, 4.0), p(0.0, 4.0)],
        vec![vec![p(1.0, 1.0), p(2.0, 1.0), p(1.0, 2.0)]],
    );
    let w = |s: &Shape, f| write_shape(s, f).unwrap();
    assert_eq!(w(&Shape::Empty, Format::Wkt), "GEOMETRYCOLLECTION EMPTY\n");
    assert_eq!(w(&Shape::Empty, Format::Csv), "");
    assert_eq!(
        w(&Shape::Empty, Format::GeoJson),
        "{\"type\":\"GeometryCollection\",\"geometries\":[]}\n"
    );
    assert_eq!(
        w(&Shape::Point(p(1.0, -0.5)), Format::Wkt),
        "POINT (1 -0.5)\n"
    );
    assert_eq!(
        w(
            &Shape::MultiPoint(vec![p(1.0, 2.0), p(3.0, 4.0)]),
            Format::Wkt
        ),
        "MULTIPOINT ((1 2), (3 4))\n"
    );
    assert_eq!(
        w(&Shape::MultiPoint(vec![]), Format::Wkt),
        "MULTIPOINT EMPTY\n"
    );
    assert_eq!(
        w(
            &Shape::LineString(vec![p(0.0, 0.0), p(1e200, 5e-324)]),
            Format::Wkt
        ),
        "LINESTRING (0 0, 1e200 5e-324)\n"
    );
    assert_eq!(
        w(&Shape::Polygon(sq.clone()), Format::Wkt),
        "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 2 1, 1 2, 1 1))\n"
    );
    assert_eq!(
        w(&Shape::MultiPolygon(MultiPolygon(vec![])), Format::Wkt),
        "MULTIPOLYGON EMPTY\n"
    );
    assert_eq!(
        w(&Shape::Polygon(sq.clone()), Format::Csv),
        "0,0\n4,0\n4,4\n0,4\n0,0\n\n1,1\n2,1\n1,2\n1,1\n"
    );
    // GeoJSON: the CCW exterior stays, the CCW hole is turned clockwise, first vertex kept.
    assert_eq!(
        w(&Shape::Polygon(sq.clone()), Format::GeoJson),
        "{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[4,0],[4,4],[0,4],[0,0]],\
         [[1,1],[1,2],[2,1],[1,1]]]}\n"
    );
    assert_eq!(
        w(&Shape::Polygon(sq.clone()), Format::Json),
        w(&Shape::Polygon(sq), Format::GeoJson)
    );
    assert!(matches!(
        write_shape(&Shape::Point(p(0.0, 0.0)), Format::Off),
        Err(Error::InvalidInput(_))
    ));
    assert!(matches!(
        write_shape(&Shape::LineString(vec![p(0.0, f64::NAN)]), Format::Wkt),
        Err(Error::NonFinite { .. })
    ));
    // Negative zero survives the trip through a serde_json value.
    let v = compgeom::io::to_geojson_value(&Shape::Point(p(-0.0, 1e200))).unwrap();
    let x = v["coordinates"][0].as_f64().unwrap();
    assert!(x == 0.0 && x.is_sign_negative(), "{v}");
    let back = read_points(&v.to_string(), Format::GeoJson, "v").unwrap();
    assert!(same_bits(&back, &[p(-0.0, 1e200)]), "{v}");
    // The writers' output is recognised by the sniffer.
    let pt = Shape::Point(p(1.0, 2.0));
    for f in [Format::Csv, Format::Wkt, Format::GeoJson] {
        assert_eq!(detect_format(None, &w(&pt, f)).unwrap(), f);
    }
}

/// `GeoJsonGeometry` serializes as the GeoJSON text `write_shape` writes, read into a
/// serde_json value and printed: every kind of shape, rings of either orientation, flat
/// and empty rings, and coordinates whose text is an integer (small, large, beyond
/// `u64`, negative zero), in scientific form, subnormal or extreme.
#[test]
fn geojson_geometry_serializes_as_the_written_text_reads() {
    let numbers = [
        0.0,
        -0.0,
        3.0,
        -7.0,
        100.0,
        1000.0,
        0.1,
        -2.5,
        1.5e-5,
        0.00015,
        1e15,
        9007199254740993.0,
        2f64.powi(60),
        -(2f64.powi(62)),
        2f64.powi(63),
        2f64.powi(64),
        1e20,
        1e300,
        -1e300,
        5e-324,
        f64::MIN_POSITIVE,
        f64::MAX,
        -f64::MAX,
        123456789.0,
        0.1 + 0.2,
    ];
    let mut shapes = vec![Shape::Empty];
    for (k, &x) in numbers.iter().enumerate() {
        let y = numbers[(k * 7 + 3) % numbers.len()];
        let (a, b, c) = (p(x, y), p(y, x), p(x, x));
        shapes.push(Shape::Point(a));
        shapes.push(Shape::MultiPoint(vec![a, b, c]));
        shapes.push(Shape::LineString(vec![a, b]));
        let ring = vec![p(0.0, 0.0), a, p(x, 0.5), b];
        let mut turned = ring.clone();
        turned.reverse();
        let flat = vec![p(0.0, 0.0), c, p(x / 2.0, x / 2.0)];
        let poly = Polygon::new(ring.clone(), vec![turned.clone(), vec![], flat.clone()]);
        shapes.push(Shape::Polygon(poly.clone()));
        shapes.push(Shape::MultiPolygon(MultiPolygon(vec![
            Polygon::new(turned, vec![ring]),
            Polygon::new(vec![], vec![flat]),
            poly,
        ])));
    }
    for shape in &shapes {
        let text = write_shape(shape, Format::GeoJson).unwrap();
        let read: serde_json::Value = serde_json::from_str(&text).unwrap();
        let direct = serde_json::to_string(&compgeom::io::GeoJsonGeometry(shape)).unwrap();
        assert_eq!(direct, read.to_string(), "{text}");
        assert_eq!(
            compgeom::io::to_geojson_value(shape).unwrap(),
            read,
            "{text}"
        );
    }
    // A non-finite coordinate is an error, not a number.
    let bad = Shape::LineString(vec![p(0.0, 1.0), p(f64::INFINITY, 0.0)]);
    assert!(serde_json::to_string(&compgeom::io::GeoJsonGeometry(&bad)).is_err());
}

#[test]
fn segments_round_trip_through_every_format() {
    let segs = vec![
        Segment2::new(p(0.0, 0.0), p(1.0, 1.0)),
        Segment2::new(p(-0.0, 1e-300), p(1e300, 0.1)),
    ];
    for f in [Format::Csv, Format::Wkt, Format::GeoJson] {
        let text = write_segments(&segs, f).unwrap();
        let back = read_segments(&text, f, "s").unwrap();
        let flat = |ss: &[Segment2]| ss.iter().flat_map(|s| [s.a, s.b]).collect::<Vec<_>>();
        assert!(same_bits(&flat(&back), &flat(&segs)), "{f:?}: {text}");
    }
    assert_eq!(
        write_segments(&[], Format::Wkt).unwrap(),
        "MULTILINESTRING EMPTY\n"
    );
    assert!(write_segments(&segs, Format::Off).is_err());
}

// ---------------------------------------------------------------- property tests

/// Finite f64 values: arbitrary bit patterns, small integers (many ties and repeats),
/// and the extremes.
fn coord() -> impl Strategy<Value = f64> {
    prop_oneof![
        any::<u64>()
            .prop_map(f64::from_bits)
            .prop_filter("finite", |x| x.is_finite()),
        (-3i32..=3).prop_map(f64::from),
        prop::sample::select(vec![
            0.0,
            -0.0,
            1e200,
            -1e200,
            5e-324,
            -5e-324,
            f64::MAX,
            f64::MIN_POSITIVE,
            0.1,
            1e-300
        ]),
    ]
}

fn point() -> impl Strategy<Value = Point2> {
    (coord(), coord()).prop_map(|(x, y)| Point2::new(x, y))
}

fn ring() -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec(point(), 3..9)
}

fn polygon() -> impl Strategy<Value = Polygon> {
    (ring(), prop::collection::vec(ring(), 0..3)).prop_map(|(e, h)| Polygon::new(e, h))
}

/// The exact sign of a ring's signed area, in rationals (the oracle).
fn oracle_orientation(ring: &[Point2]) -> Orientation {
    let q = |x: f64| BigRational::from_float(x).unwrap();
    let mut sum = BigRational::zero();
    for (i, a) in ring.iter().enumerate() {
        let b = ring[(i + 1) % ring.len()];
        sum += q(a.x) * q(b.y) - q(b.x) * q(a.y);
    }
    if sum.is_zero() {
        Orientation::Collinear
    } else if sum.is_positive() {
        Orientation::CounterClockwise
    } else {
        Orientation::Clockwise
    }
}

/// `ring` as read back from GeoJSON: the same ring, or the same ring reversed keeping its
/// first vertex, oriented as `want` unless its area is zero.
fn check_geojson_ring(original: &[Point2], back: &[Point2], want: Orientation) {
    let o = oracle_orientation(original);
    if o == Orientation::Collinear || o == want {
        assert!(same_bits(back, original), "{original:?} -> {back:?}");
    } else {
        let mut rev = vec![original[0]];
        rev.extend(original[1..].iter().rev());
        assert!(same_bits(back, &rev), "{original:?} -> {back:?}");
        assert_eq!(oracle_orientation(back), want);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn format_f64_round_trips_every_finite_bit_pattern(bits in any::<u64>()) {
        let x = f64::from_bits(bits);
        prop_assume!(x.is_finite());
        let s = format_f64(x);
        prop_assert_eq!(s.parse::<f64>().unwrap().to_bits(), bits, "{}", s);
        // Also through serde_json, which reads the GeoJSON numbers.
        let j: f64 = serde_json::from_str(&s).unwrap();
        prop_assert_eq!(j.to_bits(), bits, "json {}", s);
        // No shorter text of Rust's shortest digits exists.
        let debug = format!("{:?}", x);
        prop_assert!(s.len() <= debug.trim_end_matches(".0").len(), "{} vs {}", s, debug);
    }

    #[test]
    fn ring_orientation_matches_the_rational_oracle(r in ring()) {
        prop_assert_eq!(ring_orientation(&r), oracle_orientation(&r));
    }

    #[test]
    fn points_and_lines_round_trip(pts in prop::collection::vec(point(), 0..12)) {
        for f in [Format::Csv, Format::Wkt, Format::GeoJson] {
            for shape in [Shape::MultiPoint(pts.clone()), Shape::LineString(pts.clone())] {
                let text = write_shape(&shape, f).unwrap();
                let back = read_points(&text, f, "rt").unwrap();
                prop_assert!(same_bits(&back, &pts), "{:?} {}", f, text);
            }
        }
        if let Some(&q) = pts.first() {
            for f in [Format::Csv, Format::Wkt, Format::GeoJson] {
                let text = write_shape(&Shape::Point(q), f).unwrap();
                prop_assert!(same_bits(&read_points(&text, f, "rt").unwrap(), &[q]));
            }
        }
    }

    #[test]
    fn polygons_round_trip_exactly_through_csv_and_wkt(polys in prop::collection::vec(polygon(), 1..4)) {
        for f in [Format::Csv, Format::Wkt] {
            let shape = Shape::MultiPolygon(MultiPolygon(polys.clone()));
            let text = write_shape(&shape, f).unwrap();
            let back = read_polygons(&text, f, "rt").unwrap();
            prop_assert_eq!(back.0.len(), polys.len());
            for (b, o) in back.0.iter().zip(&polys) {
                prop_assert!(same_bits(&b.exterior, &o.exterior), "{:?} {}", f, text);
                prop_assert_eq!(b.holes.len(), o.holes.len());
                for (bh, oh) in b.holes.iter().zip(&o.holes) {
                    prop_assert!(same_bits(bh, oh));
                }
            }
            let one = write_shape(&Shape::Polygon(polys[0].clone()), f).unwrap();
            prop_assert_eq!(read_polygons(&one, f, "rt").unwrap().0.len(), 1);
        }
    }

    #[test]
    fn geojson_polygons_follow_rfc7946(poly in polygon()) {
        let text = write_shape(&Shape::Polygon(poly.clone()), Format::GeoJson).unwrap();
        // Valid JSON, rings closed.
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        for ring in v["coordinates"].as_array().unwrap() {
            let ring = ring.as_array().unwrap();
            prop_assert_eq!(&ring[0], ring.last().unwrap());
        }
        let back = read_polygons(&text, Format::GeoJson, "rt").unwrap();
        prop_assert_eq!(back.0.len(), 1);
        let b = &back.0[0];
        check_geojson_ring(&poly.exterior, &b.exterior, Orientation::CounterClockwise);
        prop_assert_eq!(b.holes.len(), poly.holes.len());
        for (bh, oh) in b.holes.iter().zip(&poly.holes) {
            check_geojson_ring(oh, bh, Orientation::Clockwise);
        }
    }

    #[test]
    fn off_round_trips(
        verts in prop::collection::vec((coord(), coord(), coord()), 3..10),
        faces in prop::collection::vec(prop::collection::vec(any::<prop::sample::Index>(), 3..6), 0..5),
    ) {
        let vertices: Vec<Point3> = verts.iter().map(|&(x, y, z)| Point3::new(x, y, z)).collect();
        let faces: Vec<Vec<usize>> = faces
            .iter()
            .map(|f| f.iter().map(|i| i.index(vertices.len())).collect())
            .collect();
        let poly = Polyhedron { vertices, faces };
        let back = read_off(&write_off(&poly), "rt").unwrap();
        prop_assert_eq!(&back.faces, &poly.faces);
        for (a, b) in back.vertices.iter().zip(&poly.vertices) {
            prop_assert_eq!(
                (a.x.to_bits(), a.y.to_bits(), a.z.to_bits()),
                (b.x.to_bits(), b.y.to_bits(), b.z.to_bits())
            );
        }
    }

    #[test]
    fn points3_round_trip(pts in prop::collection::vec((coord(), coord(), coord()), 0..8)) {
        let pts: Vec<Point3> = pts.into_iter().map(|(x, y, z)| Point3::new(x, y, z)).collect();
        for f in [Format::Csv, Format::Wkt, Format::GeoJson, Format::Off] {
            let text = write_points3(&pts, f).unwrap();
            let back = read_points3(&text, f, "rt").unwrap();
            prop_assert_eq!(back.len(), pts.len());
            for (a, b) in back.iter().zip(&pts) {
                prop_assert_eq!(
                    (a.x.to_bits(), a.y.to_bits(), a.z.to_bits()),
                    (b.x.to_bits(), b.y.to_bits(), b.z.to_bits()),
                    "{:?}: {}", f, text
                );
            }
        }
    }

    #[test]
    fn geojson_value_matches_the_text(poly in polygon()) {
        let shape = Shape::Polygon(poly);
        let text = write_shape(&shape, Format::GeoJson).unwrap();
        let v = compgeom::io::to_geojson_value(&shape).unwrap();
        let from_text: serde_json::Value = serde_json::from_str(&text).unwrap();
        prop_assert_eq!(&v, &from_text);
        // Printed by serde_json, the value reads back to the same polygon.
        let again = read_polygons(&v.to_string(), Format::GeoJson, "v").unwrap();
        let direct = read_polygons(&text, Format::GeoJson, "t").unwrap();
        prop_assert!(same_bits(&again.0[0].exterior, &direct.0[0].exterior));
    }

    #[test]
    fn csv_garbage_never_panics(text in "[0-9a-z ,;#.\\-\\n]{0,60}") {
        let _ = read_points(&text, Format::Csv, "fz");
        let _ = read_polygons(&text, Format::Csv, "fz");
        let _ = read_off(&text, "fz");
        let _ = detect_format(None, &text);
    }

    #[test]
    fn wkt_garbage_never_panics(text in "(POINT|LINESTRING|POLYGON|MULTIPOINT|GEOMETRYCOLLECTION|EMPTY|Z|[()]|,| |[0-9]|\\.|nan|\\n){0,30}") {
        let _ = read_points(&text, Format::Wkt, "fz");
        let _ = read_segments(&text, Format::Wkt, "fz");
        let _ = read_polygons(&text, Format::Wkt, "fz");
    }
}

// ---------------------------------------------------------------- real fixture files

/// Read `rel` under the cases folder, or print a notice and return `None`.
fn fixture(rel: &str) -> Option<String> {
    let path = cases_dir().join(rel);
    match std::fs::read_to_string(&path) {
        Ok(t) => Some(t),
        Err(_) => {
            println!("skipped: {} not found", path.display());
            None
        }
    }
}

#[test]
fn reads_georust_convex_hull_fixture() {
    let Some(text) = fixture("georust-geo/convex-hull/poly1.wkt") else {
        return;
    };
    let f = detect_format(Some(Path::new("poly1.wkt")), &text).unwrap();
    let pts = read_points(&text, f, "poly1.wkt").unwrap();
    assert!(pts.len() > 10);
    assert_eq!(pts[0], p(-75.57274028771249, 110.01960141091608));
    let Some(hull) = fixture("georust-geo/convex-hull/poly1_hull.wkt") else {
        return;
    };
    let h = read_points(&hull, Format::Wkt, "poly1_hull.wkt").unwrap();
    // A closed LINESTRING: the repeat is kept for points, and every hull vertex is an input.
    assert_eq!(h.first(), h.last());
    assert!(h.iter().all(|v| pts.contains(v)));
}

#[test]
fn reads_jts_unit_wkt_strings() {
    let Some(text) = fixture("jts-unit/convex-hull.json") else {
        return;
    };
    let doc: serde_json::Value = serde_json::from_str(&text).unwrap();
    let mut n = 0;
    for case in doc["cases"].as_array().unwrap() {
        for key in ["input", "expected"] {
            let wkt = case[key].as_str().unwrap();
            let pts = read_points(wkt, detect_format(None, wkt).unwrap(), key).unwrap();
            assert!(!pts.is_empty() || wkt.contains("EMPTY"), "{wkt}");
            n += 1;
        }
    }
    assert!(n >= 8);
    if let Some(text) = fixture("jts-unit/constrained-delaunay-polygon.json") {
        let doc: serde_json::Value = serde_json::from_str(&text).unwrap();
        for case in doc["cases"].as_array().unwrap() {
            let wkt = case["input"].as_str().unwrap();
            if !wkt.starts_with(|c: char| c.is_ascii_alphabetic()) {
                continue; // hex WKB is not read
            }
            let mp = read_polygons(wkt, Format::Wkt, "cdt").unwrap();
            assert!(!mp.0.is_empty(), "{wkt}");
        }
    }
}

#[test]
fn reads_turf_convex_geojson() {
    for name in ["elevation1.geojson", "elevation4.geojson"] {
        let Some(text) = fixture(&format!("turf/convex/in/{name}")) else {
            return;
        };
        let f = detect_format(Some(Path::new(name)), &text).unwrap();
        assert_eq!(f, Format::GeoJson);
        let pts = read_points(&text, f, name).unwrap();
        assert!(pts.len() >= 3, "{name}: {} points", pts.len());
    }
    // A polygon-clipping case: FeatureCollection of (Multi)Polygons.
    if let Some(text) = fixture("polygon-clipping/almost-parrallel-segments-2/args.geojson") {
        let mp = read_polygons(&text, Format::GeoJson, "args.geojson").unwrap();
        assert!(!mp.0.is_empty());
    }
}

/// Every `*.json` file directly under `rel`, or `None` (with a notice) if absent.
fn fixture_dir(rel: &str) -> Option<Vec<PathBuf>> {
    let dir = cases_dir().join(rel);
    let Ok(entries) = std::fs::read_dir(&dir) else {
        println!("skipped: {} not found", dir.display());
        return None;
    };
    let mut files: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    Some(files)
}

#[test]
fn reads_bare_array_fixtures_of_earcut_and_delaunator() {
    if let Some(files) = fixture_dir("earcut/fixtures") {
        assert!(!files.is_empty());
        for path in files {
            let text = read_text(&path).unwrap();
            let f = detect_format(Some(&path), &text).unwrap();
            let name = path.display().to_string();
            let mp = read_polygons(&text, f, &name).unwrap();
            assert_eq!(mp.0.len(), 1, "{name}");
            assert!(mp.0[0].exterior.len() >= 3, "{name}");
            assert!(!read_points(&text, f, &name).unwrap().is_empty(), "{name}");
        }
    }
    if let Some(files) = fixture_dir("delaunator/fixtures") {
        assert!(!files.is_empty());
        for path in files {
            let text = read_text(&path).unwrap();
            let name = path.display().to_string();
            let pts = read_points(&text, Format::GeoJson, &name).unwrap();
            assert!(pts.len() >= 3, "{name}");
        }
    }
}
