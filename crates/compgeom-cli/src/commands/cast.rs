//! `compgeom cast`: castability of a polyhedron (book §4.1), via `compgeom::lp::castability`.

use super::halfplanes::{read_source, region_picture};
use crate::cli::OutputArgs;
use crate::error::CliError;
use crate::output;
use clap::Args;
use compgeom::io::{read_off_with_lines, Polyhedron};
use compgeom::lp::{castability_at, intersect_halfplanes, Castability, HalfPlane};
use compgeom::render::{Layer, Picture, Style};
use serde::Serialize;
use std::path::PathBuf;

/// `--help` text describing the JSON output.
pub const JSON_HELP: &str = "\
Input: a polyhedron in OFF; it must be a closed, consistently oriented 2-manifold with
planar faces (faces wound inward are flipped).

JSON output (--format json, the only format) is one object:
  castable     true when some facet can be the top facet of a one-piece mould
  top_facets   [{\"facet\": i, \"direction\": [x, y, z], \"interior\": bool}, ...]  every
               facet that works (0-based face index), with a unit removal direction
               (nearest f64); interior: the direction is strictly away from every other
               facet (false when only boundary directions exist, e.g. a cube pulled
               straight out)
  input_facets number of faces read

--svg draws, for one top facet (--facet, default the first castable one), the region of
removal directions d in the plane through n_top perpendicular to it, in coordinates of
that plane (the region's kind is exact for integer coordinates).

Examples:
  compgeom cast part.off
  compgeom cast part.off --svg directions.svg --facet 3";

/// Arguments of `compgeom cast`.
#[derive(Debug, Clone, Args)]
pub struct CastArgs {
    /// Input OFF file, or `-` for standard input.
    #[arg(value_name = "MESH")]
    pub input: PathBuf,

    /// Output, picture and verification.
    #[command(flatten)]
    pub output: OutputArgs,

    /// The top facet whose removal directions `--svg` draws.
    #[arg(long)]
    pub facet: Option<usize>,
}

#[derive(Debug, Serialize)]
struct CastJson<'a> {
    #[serde(flatten)]
    result: &'a Castability,
    input_facets: usize,
}

/// Run `compgeom cast`.
pub fn run(args: &CastArgs) -> Result<(), CliError> {
    if args.output.verify {
        return Err(CliError::bad_input("cast has no --verify check"));
    }
    let (text, name) = read_source(&args.input)?;
    let (mesh, face_lines) = read_off_with_lines(&text, &name)?;
    // Errors about one face already name the file and line; the others get the file.
    let result = castability_at(&mesh, &name, &face_lines).map_err(|e| match e {
        e @ compgeom::Error::Parse { .. } => CliError::from(e),
        e => CliError::bad_input(format!("{name}: {e}")),
    })?;
    if args.output.format().geometry_format().is_some() {
        return Err(args.output.unsupported("cast", "json only"));
    }
    let text = serde_json::to_string(&CastJson {
        result: &result,
        input_facets: mesh.faces.len(),
    })
    .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?;
    if let Some(svg) = &args.output.svg {
        let facet = args
            .facet
            .or_else(|| result.top_facets.first().map(|t| t.facet))
            .unwrap_or(0);
        if facet >= mesh.faces.len() {
            return Err(CliError::bad_input(format!(
                "--facet {facet}: the mesh has {} faces",
                mesh.faces.len()
            )));
        }
        let picture = direction_picture(&mesh, facet)?;
        output::write_atomic(svg, picture.to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

/// Newell normal of a face in `f64` (drawing only).
fn normal(mesh: &Polyhedron, f: usize) -> [f64; 3] {
    let face = &mesh.faces[f];
    let mut n = [0.0; 3];
    for k in 0..face.len() {
        let a = mesh.vertices[face[k]];
        let b = mesh.vertices[face[(k + 1) % face.len()]];
        n[0] += a.y * b.z - a.z * b.y;
        n[1] += a.z * b.x - a.x * b.z;
        n[2] += a.x * b.y - a.y * b.x;
    }
    n
}

/// The removal directions of top facet `t` in the plane through `n_t` perpendicular to it
/// (coordinates along two orthogonal vectors of that plane): one half-plane per other
/// facet, intersected with the library's exact half-plane intersection.
///
/// Why no unit vectors: normalizing takes square roots, and the rounded half-planes of a
/// degenerate cone (a single removal direction, a flat wedge) then meet in a tiny sliver
/// drawn and titled "polygon" while `castability` says the cone has no interior. The
/// constraints `n_f·d <= 0` are homogeneous, so the raw Newell normals (integers, hence
/// exact, for meshes with integer coordinates of moderate size) and the exact cross
/// products `u = n_t × e`, `v = n_t × u` give half-planes whose intersection has the true
/// kind. Only afterwards, for drawing, is `y` stretched by `|n_t|` (as `|v| = |n_t|·|u|`)
/// so the picture is not distorted.
pub fn direction_picture(mesh: &Polyhedron, t: usize) -> Result<Picture, CliError> {
    // Orient outward with the signed volume.
    let vol: f64 = (0..mesh.faces.len())
        .map(|f| {
            let n = normal(mesh, f);
            let a = mesh.vertices[mesh.faces[f][0]];
            n[0] * a.x + n[1] * a.y + n[2] * a.z
        })
        .sum();
    let s = if vol < 0.0 { -1.0 } else { 1.0 };
    let nt = normal(mesh, t).map(|x| s * x);
    let stretch = (nt[0] * nt[0] + nt[1] * nt[1] + nt[2] * nt[2]).sqrt();
    if !(stretch > 0.0 && stretch.is_finite()) {
        return Err(CliError::bad_input(format!("face {t} has no normal")));
    }
    // The coordinate axis most nearly perpendicular to n_t.
    let k = (0..3)
        .min_by(|&i, &j| nt[i].abs().total_cmp(&nt[j].abs()))
        .unwrap_or(0);
    let mut helper = [0.0; 3];
    helper[k] = 1.0;
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let u = cross(nt, helper);
    let v = cross(nt, u);
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let hs: Vec<HalfPlane> = (0..mesh.faces.len())
        .filter(|&f| f != t)
        .filter_map(|f| {
            let n = normal(mesh, f).map(|x| s * x);
            if n == [0.0; 3] {
                return None;
            }
            // d = nt + x·u + y·v: n·d <= 0  <=>  (n·u)·x + (n·v)·y <= -(n·nt).
            Some(HalfPlane::new(dot(n, u), dot(n, v), -dot(n, nt)))
        })
        .collect();
    let mut region = intersect_halfplanes(&hs, 0)?;
    let title = format!(
        "removal directions for top facet {t}: d = n + x·u + y·v ({})",
        region.kind.name()
    );
    // Drawing only: stretch y by |n_t| so that x and y have the same length unit.
    let hs: Vec<HalfPlane> = hs
        .iter()
        .map(|h| HalfPlane::new(h.a, h.b / stretch, h.c))
        .collect();
    for p in &mut region.vertices {
        p.y *= stretch;
    }
    for (p, d) in &mut region.outline {
        p.y *= stretch;
        d.y *= stretch;
    }
    let origin = compgeom::Point2::new(0.0, 0.0);
    let mut pic = region_picture(&hs, &region, &[origin], &title);
    pic.add(
        Layer::new(
            "d = n (straight out of the top facet)",
            Style::points("#ff7f0e").with_radius(4.0),
        )
        .point(origin),
    );
    Ok(pic)
}
