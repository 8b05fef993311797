//! `compgeom overlay`: the overlay of two polygon layers (book §2.3, MAPOVERLAY) via
//! `compgeom::overlay::overlay_polygons`, each face labelled with the polygons of A and B
//! containing it.

use crate::cli::{InputArgs, OutputArgs, OutputFormat};
use crate::commands::boolean::other_input;
use crate::error::CliError;
use crate::output;
use clap::Args;
use compgeom::dcel::{Dcel, FaceId, PolygonLabel};
use compgeom::io::{read_polygon_layer, GeoJsonGeometry, PolygonLayer, Shape};
use compgeom::overlay::{overlay_polygons, rounding_suspects, OverlayEdge};
use compgeom::render::{Layer, Picture, Style};
use compgeom::Polygon;
use serde::ser::{SerializeSeq, Serializer};
use serde::Serialize;
use serde_json::Value;
use std::path::PathBuf;

/// `--help` text describing the JSON output.
pub const JSON_HELP: &str = "\
JSON output (--format json, the default) is one object:
  faces     [{\"polygon\": <GeoJSON Polygon, or null for the unbounded face>,
              \"a\": <index of A's feature containing the face, or null>,
              \"b\": <the same for B>}, ...]; the unbounded face first. A face's polygon
            is its outer boundary (counter-clockwise) and one hole per inner boundary
            (clockwise), every vertex kept; crossings are rounded to the nearest f64,
            or one float from it per axis where that keeps the edges apart.
  vertices  number of vertices of the overlay
  edges     number of edges of the overlay
  verified  true; present only with --verify (the DCEL's invariants were checked)
  rounding_suspect_faces
            present only with --verify: indices of the faces near which rounding to
            f64 may have made edges touch or cross (faces thinner than a float; also
            printed as a warning); usually empty

Features are numbered from 0 in reading order: the GeoJSON Features of a
FeatureCollection (a single Feature is feature 0, whatever its geometry), else each
polygon (a WKT MULTIPOLYGON gives several). Where features
of one layer overlap, `a`/`b` is the lowest index containing the face.
--format geojson prints a FeatureCollection with one feature per bounded face and
properties `a` and `b`, and `a_properties` and `b_properties`: the properties of those
GeoJSON input features (null where there are none), so attributes of both layers reach
each face.
--svg FILE draws the bounded faces coloured by label: each pair (A's feature, B's
feature) in a colour of its own, named in the legend, up to ten pairs; with more, by
which layers contain the face (both, A only, B only, neither), with the counts.

Examples:
  compgeom overlay vegetation.geojson rivers.geojson --svg overlay.svg
  compgeom overlay a.wkt b.wkt --format geojson -o faces.geojson --verify";

/// Arguments of `compgeom overlay`.
#[derive(Debug, Clone, Args)]
pub struct OverlayArgs {
    /// Input A and its format.
    #[command(flatten)]
    pub input: InputArgs,

    /// Input B.
    #[arg(value_name = "B")]
    pub b: PathBuf,

    /// Output, picture and verification.
    #[command(flatten)]
    pub output: OutputArgs,
}

/// Run `compgeom overlay`.
pub fn run(args: &OverlayArgs) -> Result<(), CliError> {
    // (An output format the command does not write is an error before any work.)
    let geojson = match args.output.format() {
        OutputFormat::Json => false,
        OutputFormat::Geojson => true,
        _ => return Err(args.output.unsupported("overlay", "json or geojson")),
    };
    let a = InputLayer::read(&args.input)?;
    let b = InputLayer::read(&other_input(&args.input, &args.b))?;
    let d = overlay_polygons(&a.0.polygons, &b.0.polygons)?;
    // With --verify: the structure's invariants, and the faces near which rounding may
    // have made edges meet (the overlay mended what it could; listed, not an error).
    let suspects = if args.output.verify {
        d.validate()?;
        rounding_suspects(&d)
    } else {
        Vec::new()
    };
    if !suspects.is_empty() {
        eprintln!(
            "warning: rounding to f64 may have made edges meet near {} face(s): {:?}",
            suspects.len(),
            suspects.iter().map(|f| f.0).collect::<Vec<_>>()
        );
    }
    // The document is serialized straight from the overlay, face by face (a JSON value
    // of every face's polygon first took most of the command's memory).
    let faces = Faces {
        d: &d,
        a: &a,
        b: &b,
        geojson,
    };
    let text = if geojson {
        serde_json::to_string(&FeatureCollection {
            features: faces,
            kind: "FeatureCollection",
        })
    } else {
        let verified = args.output.verify;
        serde_json::to_string(&OverlayJson {
            edges: d.edge_count(),
            faces,
            rounding_suspect_faces: verified.then(|| suspects.iter().map(|f| f.0).collect()),
            verified: verified.then_some(true),
            vertices: d.vertex_count(),
        })
    }
    .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?;
    if let Some(svg) = &args.output.svg {
        let label =
            |la: &PolygonLabel, lb: &PolygonLabel| (a.feature(la.first()), b.feature(lb.first()));
        let pic = overlay_picture(&d, label, ("A", "B"));
        output::write_atomic(svg, pic.to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

/// The `--format json` document. (Every object here has its keys in alphabetical order,
/// as the command wrote them when it built a `serde_json::Value`.)
#[derive(Serialize)]
struct OverlayJson<'a> {
    edges: usize,
    faces: Faces<'a>,
    #[serde(skip_serializing_if = "Option::is_none")]
    rounding_suspect_faces: Option<Vec<usize>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    verified: Option<bool>,
    vertices: usize,
}

/// The `--format geojson` document.
#[derive(Serialize)]
struct FeatureCollection<'a> {
    features: Faces<'a>,
    #[serde(rename = "type")]
    kind: &'static str,
}

/// The faces of an overlay as the format lists them: JSON records of all faces, or
/// GeoJSON Features of the bounded ones with both layers' attributes; each face's
/// polygon made as it is written.
struct Faces<'a> {
    d: &'a Dcel<(), OverlayEdge, (PolygonLabel, PolygonLabel)>,
    a: &'a InputLayer,
    b: &'a InputLayer,
    geojson: bool,
}

/// A face in `--format json`.
#[derive(Serialize)]
struct FaceRecord<'a> {
    a: Option<usize>,
    b: Option<usize>,
    polygon: Option<GeoJsonGeometry<'a>>,
}

/// A bounded face in `--format geojson`.
#[derive(Serialize)]
struct Feature<'a> {
    geometry: Option<GeoJsonGeometry<'a>>,
    properties: FaceProperties<'a>,
    #[serde(rename = "type")]
    kind: &'static str,
}

#[derive(Serialize)]
struct FaceProperties<'a> {
    a: Option<usize>,
    a_properties: &'a Value,
    b: Option<usize>,
    b_properties: &'a Value,
}

impl Serialize for Faces<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut seq = serializer.serialize_seq(None)?;
        for f in self.d.face_ids() {
            if self.geojson && f == FaceId::UNBOUNDED {
                continue;
            }
            let (la, lb) = &self.d.face(f).data;
            let (fa, fb) = (self.a.feature(la.first()), self.b.feature(lb.first()));
            let shape = self.d.face_polygon(f).map(Shape::Polygon);
            let polygon = shape.as_ref().map(GeoJsonGeometry);
            if self.geojson {
                seq.serialize_element(&Feature {
                    geometry: polygon,
                    properties: FaceProperties {
                        a: fa,
                        a_properties: self.a.properties(fa),
                        b: fb,
                        b_properties: self.b.properties(fb),
                    },
                    kind: "Feature",
                })?;
            } else {
                seq.serialize_element(&FaceRecord {
                    a: fa,
                    b: fb,
                    polygon,
                })?;
            }
        }
        seq.end()
    }
}

/// A face's labels in [`overlay_picture`]: the feature (or polygon) of A and of B
/// containing it.
type LabelPair = (Option<usize>, Option<usize>);

/// Colours of the label pairs of [`overlay_picture`], when there are few.
const PAIR_COLOURS: [&str; 10] = [
    "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f",
    "#bcbd22", "#17becf",
];

/// The bounded faces of an overlay coloured by label, `label` giving each face's pair
/// (A's feature or polygon containing it, B's): with at most ten different pairs, each
/// pair in a colour of its own, named in the legend ("A 0, B none"); with more, by which
/// maps contain the face (in both, in A only, in B only, in neither: a hole of both),
/// with the number of faces of each. `names` name the maps.
pub fn overlay_picture<E>(
    d: &Dcel<(), E, (PolygonLabel, PolygonLabel)>,
    label: impl Fn(&PolygonLabel, &PolygonLabel) -> LabelPair,
    names: (&str, &str),
) -> Picture {
    let mut pic = Picture::new(800, 640).with_title(format!(
        "overlay: {} faces, {} vertices, {} edges",
        d.face_count(),
        d.vertex_count(),
        d.edge_count()
    ));
    let faces: Vec<(Polygon, LabelPair)> = d
        .face_ids()
        .filter_map(|f| {
            let (la, lb) = &d.face(f).data;
            Some((d.face_polygon(f)?, label(la, lb)))
        })
        .collect();
    let mut pairs: Vec<_> = faces.iter().map(|f| f.1).collect();
    pairs.sort_unstable();
    pairs.dedup();
    let few = pairs.len() <= PAIR_COLOURS.len();
    let named = |name: &str, f: Option<usize>| match f {
        Some(k) => format!("{name} {k}"),
        None => format!("{name} none"),
    };
    // The groups (pairs, or classes by which maps contain the face), their colours and
    // legend names.
    let groups: Vec<(&str, String)> = if few {
        pairs
            .iter()
            .zip(PAIR_COLOURS)
            .map(|(&(a, b), colour)| {
                (
                    colour,
                    format!("{}, {}", named(names.0, a), named(names.1, b)),
                )
            })
            .collect()
    } else {
        vec![
            ("#2ca02c", format!("in {} and {}", names.0, names.1)),
            ("#1f77b4", format!("in {} only", names.0)),
            ("#ff7f0e", format!("in {} only", names.1)),
            ("#bbbbbb", "in neither".to_string()),
        ]
    };
    let group_of = |pair: LabelPair| match (few, pair) {
        (true, _) => pairs.partition_point(|&q| q < pair),
        (false, (Some(_), Some(_))) => 0,
        (false, (Some(_), None)) => 1,
        (false, (None, Some(_))) => 2,
        (false, (None, None)) => 3,
    };
    let mut members: Vec<Vec<Polygon>> = vec![Vec::new(); groups.len()];
    for (p, pair) in faces {
        members[group_of(pair)].push(p);
    }
    for ((colour, name), these) in groups.into_iter().zip(members) {
        if these.is_empty() {
            continue;
        }
        let name = if few {
            name
        } else {
            format!("{name} ({} faces)", these.len())
        };
        let style = Style::area(colour).with_fill_opacity(0.45);
        pic.add(Layer::new(name, style).polygons(&these));
    }
    pic
}

/// A polygon layer read from an input: its polygons, each one's input feature, and the
/// features' GeoJSON properties (none for other formats).
struct InputLayer(PolygonLayer);

impl InputLayer {
    fn read(input: &InputArgs) -> Result<InputLayer, CliError> {
        let src = input.read()?;
        Ok(InputLayer(read_polygon_layer(
            &src.text, src.format, &src.name,
        )?))
    }

    /// The feature of polygon `p`.
    fn feature(&self, p: Option<&usize>) -> Option<usize> {
        p.map(|&p| self.0.features[p])
    }

    /// The properties of feature `f` (null where it has none).
    fn properties(&self, f: Option<usize>) -> &Value {
        static NULL: Value = Value::Null;
        f.and_then(|f| self.0.properties.get(f)).unwrap_or(&NULL)
    }
}
