//! `compgeom lp`: linear programming (book §4.3–4.5) — maximize `c·x` subject to
//! `a·x <= b` — via `compgeom::lp::lp2d` (two dimensions) and `compgeom::lp::lp_d`.

use super::halfplanes::{read_source, region_picture};
use crate::cli::OutputArgs;
use crate::error::CliError;
use crate::output;
use clap::Args;
use compgeom::io::{write_shape, Shape};
use compgeom::lp::{
    intersect_halfplanes, lp2d, lp_d, read_constraints, verify_lp2d, HalfPlane, Lp2Options,
    Lp2Solution, LpSolution,
};
use compgeom::render::{Layer, Style};
use compgeom::{Point2, Segment2, Vector2};
use serde::Serialize;
use std::path::PathBuf;

/// `--help` text describing the input and the JSON output.
pub const JSON_HELP: &str = "\
Input: one constraint per line, `a1 .. ad b` meaning a1·x1 + .. + ad·xd <= b, where d is the
number of objective coefficients given to --maximize; `#` comments.

JSON output (--format json, the default) is one object:
  status       \"optimal\" | \"unbounded\" | \"infeasible\"
  point        [x1, ..]  optimal: the lexicographically smallest optimal vertex (nearest f64);
                         unbounded: a feasible point from which `ray` stays feasible
  value        c·point at the optimum (nearest f64 of the exact value)
  ray          [d1, ..]  unbounded: a direction with c·d > 0 keeping every constraint
  certificate  [i, ..]   infeasible: 0-based indices of constraints that alone contradict
  constraints  [i, ..]   optimal: constraints tight at the optimal point; in two dimensions
                         the two whose lines meet there (one when the optimal set is a
                         whole line: then `point` is its point nearest the origin), in d
                         dimensions every tight constraint
  verified     true; only with --verify (two dimensions; a failed check exits 1)
Fields that do not apply are left out.

Other formats print the optimal point (or nothing), in two dimensions only.

Examples:
  compgeom lp constraints.txt --maximize 1,2
  compgeom lp constraints3d.txt --maximize 0,0,1 --seed 3
  compgeom lp constraints.txt --maximize=-1,0 --svg lp.svg";

/// Arguments of `compgeom lp`.
#[derive(Debug, Clone, Args)]
pub struct LpArgs {
    /// Input file (lines `a1 .. ad b`), or `-` for standard input.
    #[arg(value_name = "INPUT")]
    pub input: PathBuf,

    /// Objective coefficients `c1,..,cd` (maximize c·x); their number fixes the dimension.
    #[arg(long, value_name = "C1,..,CD", allow_hyphen_values = true)]
    pub maximize: String,

    /// Seed of the random insertion order (the result does not depend on it).
    #[arg(long, default_value_t = 0)]
    pub seed: u64,

    /// Output, picture and verification.
    #[command(flatten)]
    pub output: OutputArgs,
}

/// The JSON result object (fields in [`JSON_HELP`]).
#[derive(Debug, Serialize, Default)]
struct LpJson {
    status: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    point: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    value: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    ray: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    certificate: Option<Vec<usize>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    constraints: Option<Vec<usize>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    verified: Option<bool>,
}

/// Parse `c1,..,cd`.
pub fn parse_objective(s: &str) -> Result<Vec<f64>, CliError> {
    let c: Vec<f64> = s
        .split(',')
        .map(|t| {
            t.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| {
                    CliError::bad_input(format!("--maximize: not a finite number: {t:?}"))
                })
        })
        .collect::<Result<_, _>>()?;
    if c.is_empty() {
        return Err(CliError::bad_input(
            "--maximize needs at least one coefficient",
        ));
    }
    Ok(c)
}

/// Solve as the JSON object; two dimensions go to `lp2d`, others to `lp_d`.
fn solve(rows: &[Vec<f64>], c: &[f64], seed: u64, verify: bool) -> Result<LpJson, CliError> {
    if c.len() == 2 {
        let hs: Vec<HalfPlane> = rows
            .iter()
            .map(|r| HalfPlane::new(r[0], r[1], r[2]))
            .collect();
        let sol = lp2d(&hs, Vector2::new(c[0], c[1]), &Lp2Options { seed })?;
        if verify {
            verify_lp2d(&hs, Vector2::new(c[0], c[1]), &sol)?;
        }
        return Ok(match sol {
            Lp2Solution::Optimal {
                point,
                value,
                constraints,
            } => LpJson {
                status: "optimal",
                point: Some(vec![point.x, point.y]),
                value: Some(value),
                constraints: Some(constraints),
                ..Default::default()
            },
            Lp2Solution::Unbounded { point, direction } => LpJson {
                status: "unbounded",
                point: Some(vec![point.x, point.y]),
                ray: Some(vec![direction.x, direction.y]),
                ..Default::default()
            },
            Lp2Solution::Infeasible { certificate } => LpJson {
                status: "infeasible",
                certificate: Some(certificate),
                ..Default::default()
            },
        });
    }
    if verify {
        return Err(CliError::bad_input(
            "--verify is available for two-dimensional programs only",
        ));
    }
    Ok(match lp_d(rows, c, seed)? {
        LpSolution::Optimal {
            point,
            value,
            constraints,
        } => LpJson {
            status: "optimal",
            point: Some(point),
            value: Some(value),
            constraints: Some(constraints),
            ..Default::default()
        },
        LpSolution::Unbounded { point, direction } => LpJson {
            status: "unbounded",
            point: Some(point),
            ray: Some(direction),
            ..Default::default()
        },
        LpSolution::Infeasible { certificate } => LpJson {
            status: "infeasible",
            certificate: Some(certificate),
            ..Default::default()
        },
    })
}

/// Run `compgeom lp`.
pub fn run(args: &LpArgs) -> Result<(), CliError> {
    let c = parse_objective(&args.maximize)?;
    let (text, name) = read_source(&args.input)?;
    let rows = read_constraints(&text, &name, Some(c.len() + 1))?;
    let mut result = solve(&rows, &c, args.seed, args.output.verify)?;
    result.verified = args.output.verify.then_some(true);
    let text = match args.output.format().geometry_format() {
        None => serde_json::to_string(&result)
            .map_err(|e| CliError::failure(format!("cannot encode JSON: {e}")))?,
        Some(format) => {
            if c.len() != 2 {
                return Err(CliError::bad_input(
                    "geometry output formats need a two-dimensional LP; use --format json",
                ));
            }
            let shape = match (&result.status, &result.point) {
                (&"optimal", Some(p)) => Shape::Point(Point2::new(p[0], p[1])),
                _ => Shape::Empty,
            };
            write_shape(&shape, format)?
        }
    };
    if let Some(svg) = &args.output.svg {
        if c.len() != 2 {
            return Err(CliError::bad_input("--svg needs a two-dimensional LP"));
        }
        let hs: Vec<HalfPlane> = rows
            .iter()
            .map(|r| HalfPlane::new(r[0], r[1], r[2]))
            .collect();
        let ray = result.ray.as_ref().map(|d| Vector2::new(d[0], d[1]));
        let picture = lp_picture(
            &hs,
            (c[0], c[1]),
            &result_point(&result),
            result.status,
            args.seed,
            ray,
            result.certificate.as_deref().unwrap_or(&[]),
        )?;
        output::write_atomic(svg, picture.to_svg_string().as_bytes())?;
    }
    output::emit(args.output.output.as_deref(), &output::with_newline(text))
}

fn result_point(r: &LpJson) -> Option<Point2> {
    r.point.as_ref().map(|p| Point2::new(p[0], p[1]))
}

/// The feasible region, the objective direction (an arrow from the optimum, or from the
/// region's centre), and the optimum; for an unbounded program the ray, for an infeasible
/// one the certificate's constraint lines (so the reader sees which constraints contradict).
pub fn lp_picture(
    hs: &[HalfPlane],
    c: (f64, f64),
    point: &Option<Point2>,
    status: &str,
    seed: u64,
    ray: Option<Vector2>,
    certificate: &[usize],
) -> Result<compgeom::render::Picture, CliError> {
    let region = intersect_halfplanes(hs, seed)?;
    let extra: Vec<Point2> = point.iter().copied().collect();
    let title = format!(
        "linear program: n = {}, maximize ({}, {}): {status}",
        hs.len(),
        c.0,
        c.1
    );
    let mut pic = region_picture(hs, &region, &extra, &title);
    let mut all = region.vertices.clone();
    all.extend(extra.iter().copied());
    let r = super::halfplanes::view_radius(&all);
    let from = point.unwrap_or(Point2::new(0.0, 0.0));
    let len = (c.0 * c.0 + c.1 * c.1).sqrt();
    let to = Point2::new(from.x + c.0 / len * r * 0.3, from.y + c.1 / len * r * 0.3);
    pic.add(
        Layer::new(
            "objective direction",
            Style::lines("#ff7f0e").with_stroke_width(2.0),
        )
        .segment(Segment2::new(from, to)),
    );
    if let (Some(p), Some(d)) = (point, ray) {
        let len = (d.x * d.x + d.y * d.y).sqrt();
        if len > 0.0 && len.is_finite() {
            let end = Point2::new(p.x + d.x / len * r, p.y + d.y / len * r);
            pic.add(
                Layer::new(
                    "ray: the objective grows without bound",
                    Style::lines("#d62728")
                        .with_stroke_width(2.0)
                        .with_dash("6 4"),
                )
                .segment(Segment2::new(*p, end)),
            );
        }
    }
    if !certificate.is_empty() {
        let lines: Vec<Segment2> = certificate
            .iter()
            .filter_map(|&i| hs.get(i))
            .filter_map(|h| super::halfplanes::line_segment(h, r))
            .collect();
        let names: Vec<String> = certificate.iter().map(|i| i.to_string()).collect();
        pic.add(
            Layer::new(
                format!("certificate: constraints {} contradict", names.join(", ")),
                Style::lines("#d62728").with_stroke_width(2.0),
            )
            .segments(&lines),
        );
    }
    if let Some(p) = point {
        let label = if status == "optimal" {
            "optimum"
        } else {
            "feasible start of the ray"
        };
        pic.add(Layer::new(label, Style::points("#d62728").with_radius(5.0)).point(*p));
    }
    Ok(pic)
}
