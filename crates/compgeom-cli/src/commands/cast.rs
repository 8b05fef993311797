//! `compgeom cast`: castability of a polyhedron (book §4.1), via `compgeom::lp::castability`.

use super::halfplanes::{read_source, region_picture};
use crate::cli::OutputArgs;
use crate::error::CliError;
use crate::output;
use clap::Args;
use compgeom::io::{read_off, Polyhedron};
use compgeom::lp::{castability, intersect_halfplanes, Castability, HalfPlane};
use compgeom::render::Picture;
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
removal directions d with n_top·d = 1, in coordinates of that plane.

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
    let mesh = read_off(&text, &name)?;
    let result = castability(&mesh).map_err(|e| CliError::bad_input(format!("{name}: {e}")))?;
    if args.output.format.geometry_format().is_some() {
        return Err(CliError::bad_input(
            "cast writes JSON only; use --format json",
        ));
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

/// The removal directions of top facet `t` in the plane `n_t·d = 1` (coordinates along two
/// unit vectors of that plane): one half-plane per other facet, drawn with the library's
/// half-plane intersection. The picture is computed in `f64` (for looking, not deciding).
pub fn direction_picture(mesh: &Polyhedron, t: usize) -> Result<Picture, CliError> {
    let unit = |v: [f64; 3]| {
        let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        [v[0] / l, v[1] / l, v[2] / l]
    };
    let mut nt = unit(normal(mesh, t));
    // Orient outward with the signed volume.
    let vol: f64 = (0..mesh.faces.len())
        .map(|f| {
            let n = normal(mesh, f);
            let a = mesh.vertices[mesh.faces[f][0]];
            n[0] * a.x + n[1] * a.y + n[2] * a.z
        })
        .sum();
    let s = if vol < 0.0 { -1.0 } else { 1.0 };
    nt = [s * nt[0], s * nt[1], s * nt[2]];
    let helper = if nt[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let u = unit(cross(nt, helper));
    let v = cross(nt, u);
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let hs: Vec<HalfPlane> = (0..mesh.faces.len())
        .filter(|&f| f != t)
        .filter_map(|f| {
            let n = normal(mesh, f);
            let n = [s * n[0], s * n[1], s * n[2]];
            let l = dot(n, n).sqrt();
            if l == 0.0 {
                return None;
            }
            let n = [n[0] / l, n[1] / l, n[2] / l];
            // d = nt + x·u + y·v: n·d <= 0  <=>  (n·u)·x + (n·v)·y <= -(n·nt).
            Some(HalfPlane::new(dot(n, u), dot(n, v), -dot(n, nt)))
        })
        .collect();
    let region = intersect_halfplanes(&hs, 0)?;
    let title = format!(
        "removal directions for top facet {t}: d = n + x·u + y·v ({})",
        region.kind.name()
    );
    Ok(region_picture(
        &hs,
        &region,
        &[compgeom::Point2::new(0.0, 0.0)],
        &title,
    ))
}
