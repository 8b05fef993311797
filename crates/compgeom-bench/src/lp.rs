//! Chapter 4: 2D linear programming, half-plane intersection and the smallest enclosing
//! disc.
//!
//! - `lp2d` (exact, randomized incremental, expected O(n)) against microlp (a general
//!   simplex solver, f64) and against a scan-based O(n log n) half-plane intersection
//!   (sort by angle + deque, plain f64, written here) followed by a pass over its corners.
//! - `intersect_halfplanes` (exact: one exact slope sort and one sweep) against the same f64
//!   scan and geo's convex hull of the dual points; the book's divide and conquer
//!   (`intersect_halfplanes_dc`, exact) is timed beside it.
//! - `smallest_enclosing_disc` (exact MINIDISC): geo 0.33 has no minimum bounding circle,
//!   so the peer is the same MINIDISC in plain f64 (written here): the price of exactness.
//!
//! Parts (env `COMPGEOM_LP_PARTS=lp2d,halfplanes,disc,lpd,cast`, default all) run in that
//! order. `lpd` (d = 3, planes tangent to the unit sphere) and `cast` (a prism over a
//! regular k-gon, k + 2 facets) have no peer here: they show growth only.
//!
//! Input: constraints tangent to the unit circle at random angles, offset by up to 1e-3
//! (every constraint can matter), random objective; points uniform in a disc.
//! Answers are compared once, outside the clock.
//!
//! Measured (release, shared 2-core machine, load average 3.7–4.5, one full run; ms;
//! ratio = peer / compgeom, > 1 = compgeom faster; lp2d alternates with the scan 7 times,
//! "median" is the median of the per-round ratios):
//!
//! | part | n | compgeom | peer | ratio |
//! |---|---|---|---|---|
//! | lp2d | 1e5 | 2.33 | scan 9.60 / microlp 612 | 4.1 (median 3.1) / 262 |
//! | lp2d | 1e6 | 18.0 | scan 95.5 | 5.3 (median 5.0); growth ×7.7 |
//! | halfplanes tangent | 1e4 / 1e5 / 1e6 | 1.25 / 13.3 / 232 | scan 0.69 / 7.62 / 89.8 | 0.55 / 0.57 / 0.39 |
//! | halfplanes tangent | 1e4 / 1e5 / 1e6 | | geo dual 1.69 / 21.4 / 254 | 1.35 / 1.61 / 1.10 |
//! | halfplanes random | 1e4 / 1e5 / 1e6 | 0.13 / 1.23 / 10.5 | scan 0.77 / 8.55 / 95.9; geo 0.14 / 1.84 / 21.7 | 6.1 / 6.9 / 9.1; 1.09 / 1.49 / 2.06 |
//! | disc | 1e5 / 1e6 | 1.44 / 13.8 | plain-f64 MINIDISC 13.7 / 66.1 | 9.5 / 4.8 |
//! | lp_d d=3 | 1e3 / 1e4 / 1e5 | 0.11 / 1.34 / 13.0 | (exact path 2.39 / 70.1 / 983) | growth ×11.6 / ×9.7 |
//! | cast | 102 / 302 / 1002 facets | 19.2 / 67.7 / 355 | — | |
//!
//! On the tangent inputs the f64 scan finds only 901,458 of the 999,990 corners at 1e6.
//! There about a fifth of the exact side tests at 1e5, and most of the envelope tests at
//! 1e6, cannot be settled in `f64` and go to double-double arithmetic (callgrind), and a
//! correctly rounded corner costs ~800 instructions (no FMA in the default target): the
//! scan stays ahead.

use crate::util::{best_of, ms, Rng};
use compgeom::lp::{
    intersect_halfplanes, intersect_halfplanes_dc, intersect_halfplanes_incremental, lp2d,
    smallest_enclosing_disc, HalfPlane, Lp2Options, Lp2Solution,
};
use compgeom::{Point2, Vector2};
use geo::algorithm::convex_hull::quick_hull;
use geo::Coord;
use microlp::{ComparisonOp, OptimizationDirection, Problem};
use std::time::Duration;

fn constraints(n: usize, seed: u64) -> Vec<HalfPlane> {
    let mut r = Rng::new(seed);
    (0..n)
        .map(|_| {
            let t = r.unit() * std::f64::consts::TAU;
            HalfPlane::new(t.cos(), t.sin(), 1.0 + 1e-3 * r.unit())
        })
        .collect()
}

/// `n` half-planes tangent to the unit circle at random angles: every one bounds the region
/// (the worst case of incremental clipping).
fn tangent_lines(n: usize, seed: u64) -> Vec<HalfPlane> {
    let mut r = Rng::new(seed);
    (0..n)
        .map(|_| {
            let t = r.unit() * std::f64::consts::TAU;
            HalfPlane::new(t.cos(), t.sin(), 1.0)
        })
        .collect()
}

/// `n` half-planes with random normals in the unit square and right-hand sides in [0.5, 1.5]
/// (the origin inside; most are redundant).
fn random_halfplanes(n: usize, seed: u64) -> Vec<HalfPlane> {
    let mut r = Rng::new(seed);
    (0..n)
        .map(|_| HalfPlane::new(2.0 * r.unit() - 1.0, 2.0 * r.unit() - 1.0, 0.5 + r.unit()))
        .collect()
}

/// The peer through duality: for half-planes `a·x + b·y <= c` with `c > 0` the region is the
/// polar of the convex hull of the points `(a/c, b/c)`; geo's quickhull, one corner per hull
/// vertex (plain f64).
fn dual_hull_hpi(hs: &[HalfPlane]) -> usize {
    let mut pts: Vec<Coord<f64>> = hs
        .iter()
        .map(|h| Coord {
            x: h.a / h.c,
            y: h.b / h.c,
        })
        .collect();
    quick_hull(&mut pts).0.len().saturating_sub(1)
}

/// Half-plane intersection: the default (exact slope sort + sweep) against the angular f64
/// scan and the dual hull through geo; the book's divide and conquer and (small n) the
/// incremental clipping beside it.
fn halfplanes(quick: bool) -> Result<(), String> {
    let sizes: &[usize] = if quick {
        &[10_000, 100_000]
    } else {
        &[10_000, 100_000, 1_000_000]
    };
    println!("half-plane intersection: ms (best of 3, 1 at 1e6), ratio = peer / compgeom (> 1 = compgeom faster)");
    println!(
        "{:>9} {:>8} {:>8} {:>10} {:>10} {:>6} {:>10} {:>6} {:>10} {:>6} {:>11} {:>7}",
        "input",
        "n",
        "corners",
        "compgeom",
        "d&c",
        "x",
        "scan f64",
        "ratio",
        "geo dual",
        "ratio",
        "incremental",
        "ratio"
    );
    for (name, gen) in [
        ("tangent", tangent_lines as fn(usize, u64) -> Vec<HalfPlane>),
        ("random", random_halfplanes),
    ] {
        let mut prev: Option<f64> = None;
        for &n in sizes {
            let hs = gen(n, 5);
            let region = intersect_halfplanes(&hs, 0).map_err(|e| e.to_string())?;
            let scan = scan_hpi(&hs);
            let dual = dual_hull_hpi(&hs);
            // The f64 peers can miss or invent corners when neighbouring tangents are close:
            // report their counts instead of failing.
            if region.vertices.len() != scan.len() || region.vertices.len() != dual {
                println!(
                    "          note: corner counts compgeom {} (exact), scan {}, geo dual {}",
                    region.vertices.len(),
                    scan.len(),
                    dual
                );
            }
            let runs = if n >= 1_000_000 { 1 } else { 3 };
            if intersect_halfplanes_dc(&hs).map_err(|e| e.to_string())? != region {
                return Err(format!("{name} n={n}: divide and conquer differs"));
            }
            let t_ours = best_of(runs, || intersect_halfplanes(&hs, 0));
            let t_dc = best_of(runs, || intersect_halfplanes_dc(&hs));
            let t_scan = best_of(runs, || scan_hpi(&hs));
            let t_dual = best_of(runs, || dual_hull_hpi(&hs));
            // Incremental clipping is quadratic on tangent lines: only at the smallest size.
            let inc = if n <= 10_000 {
                let r = intersect_halfplanes_incremental(&hs, 0).map_err(|e| e.to_string())?;
                if r != region {
                    return Err(format!("{name} n={n}: incremental differs"));
                }
                Some(best_of(1, || intersect_halfplanes_incremental(&hs, 0)))
            } else {
                None
            };
            println!(
                "{:>9} {:>8} {:>8} {:>10.2} {:>10.2} {:>6.2} {:>10.2} {:>6.2} {:>10.2} {:>6.2} {:>11} {:>7}",
                name,
                n,
                region.vertices.len(),
                ms(t_ours),
                ms(t_dc),
                ms(t_dc) / ms(t_ours),
                ms(t_scan),
                ms(t_scan) / ms(t_ours),
                ms(t_dual),
                ms(t_dual) / ms(t_ours),
                inc.map_or("-".into(), |t| format!("{:.1}", ms(t))),
                inc.map_or("-".into(), |t| format!("{:.1}", ms(t) / ms(t_ours))),
            );
            if let Some(p) = prev {
                println!(
                    "          compgeom growth x{:.1} for 10x the constraints (n log n: x{:.1})",
                    ms(t_ours) / p,
                    10.0 * (n as f64).ln() / (n as f64 / 10.0).ln()
                );
            }
            prev = Some(ms(t_ours));
        }
    }
    Ok(())
}

fn microlp_value(hs: &[HalfPlane], c: (f64, f64)) -> Result<f64, String> {
    let mut p = Problem::new(OptimizationDirection::Maximize);
    let x = p.add_var(c.0, (f64::NEG_INFINITY, f64::INFINITY));
    let y = p.add_var(c.1, (f64::NEG_INFINITY, f64::INFINITY));
    for h in hs {
        p.add_constraint([(x, h.a), (y, h.b)], ComparisonOp::Le, h.c);
    }
    p.solve().map(|s| s.objective()).map_err(|e| e.to_string())
}

/// Half-plane intersection by the angular scan (plain f64; bounded input assumed).
fn scan_hpi(hs: &[HalfPlane]) -> Vec<(f64, f64)> {
    let mut v: Vec<(f64, HalfPlane)> = hs.iter().map(|h| (h.b.atan2(h.a), *h)).collect();
    v.sort_by(|a, b| a.0.total_cmp(&b.0));
    // Of equal angles keep the tightest (smallest c / |n|).
    let mut lines: Vec<HalfPlane> = Vec::with_capacity(v.len());
    for (t, h) in v {
        if let Some(last) = lines.last() {
            if (last.b.atan2(last.a) - t).abs() < 1e-15 {
                let (cl, ch) = (last.c / last.a.hypot(last.b), h.c / h.a.hypot(h.b));
                if ch < cl {
                    *lines.last_mut().unwrap() = h;
                }
                continue;
            }
        }
        lines.push(h);
    }
    let meet = |p: &HalfPlane, q: &HalfPlane| {
        let d = p.a * q.b - q.a * p.b;
        ((p.c * q.b - q.c * p.b) / d, (p.a * q.c - q.a * p.c) / d)
    };
    let out = |h: &HalfPlane, p: (f64, f64)| h.a * p.0 + h.b * p.1 > h.c;
    let mut dq: std::collections::VecDeque<HalfPlane> = Default::default();
    for h in lines {
        while dq.len() >= 2 && out(&h, meet(&dq[dq.len() - 1], &dq[dq.len() - 2])) {
            dq.pop_back();
        }
        while dq.len() >= 2 && out(&h, meet(&dq[0], &dq[1])) {
            dq.pop_front();
        }
        dq.push_back(h);
    }
    while dq.len() >= 3 && out(&dq[0], meet(&dq[dq.len() - 1], &dq[dq.len() - 2])) {
        dq.pop_back();
    }
    while dq.len() >= 3 && out(&dq[dq.len() - 1], meet(&dq[0], &dq[1])) {
        dq.pop_front();
    }
    let n = dq.len();
    (0..n).map(|k| meet(&dq[k], &dq[(k + 1) % n])).collect()
}

fn scan_lp(hs: &[HalfPlane], c: (f64, f64)) -> f64 {
    scan_hpi(hs)
        .iter()
        .map(|p| c.0 * p.0 + c.1 * p.1)
        .fold(f64::NEG_INFINITY, f64::max)
}

/// MINIDISC in plain f64 (the peer for the price of exactness).
fn f64_minidisc(p: &[Point2]) -> (f64, f64, f64) {
    type D = (f64, f64, f64);
    let inside = |d: &D, q: &Point2| (q.x - d.0).hypot(q.y - d.1) <= d.2 * (1.0 + 1e-12);
    let two = |a: &Point2, b: &Point2| -> D {
        (
            (a.x + b.x) / 2.0,
            (a.y + b.y) / 2.0,
            (a.x - b.x).hypot(a.y - b.y) / 2.0,
        )
    };
    let three = |a: &Point2, b: &Point2, c: &Point2| -> D {
        let d = 2.0 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
        let (na, nb, nc) = (
            a.x * a.x + a.y * a.y,
            b.x * b.x + b.y * b.y,
            c.x * c.x + c.y * c.y,
        );
        let ux = (na * (b.y - c.y) + nb * (c.y - a.y) + nc * (a.y - b.y)) / d;
        let uy = (na * (c.x - b.x) + nb * (a.x - c.x) + nc * (b.x - a.x)) / d;
        (ux, uy, (a.x - ux).hypot(a.y - uy))
    };
    let mut d = two(&p[0], &p[1]);
    for i in 2..p.len() {
        if inside(&d, &p[i]) {
            continue;
        }
        d = two(&p[0], &p[i]);
        for j in 1..i {
            if inside(&d, &p[j]) {
                continue;
            }
            d = two(&p[i], &p[j]);
            for k in 0..j {
                if !inside(&d, &p[k]) {
                    d = three(&p[i], &p[j], &p[k]);
                }
            }
        }
    }
    d
}

fn disc_points(n: usize, seed: u64) -> Vec<Point2> {
    let mut r = Rng::new(seed);
    let mut v = Vec::with_capacity(n);
    while v.len() < n {
        let (x, y) = (2.0 * r.unit() - 1.0, 2.0 * r.unit() - 1.0);
        if x * x + y * y < 1.0 {
            v.push(Point2::new(x * 1e3, y * 1e3));
        }
    }
    v
}

/// Run the group.
pub fn run(quick: bool) -> Result<(), String> {
    let sizes: &[usize] = if quick {
        &[10_000, 100_000]
    } else {
        &[100_000, 1_000_000]
    };
    // COMPGEOM_LP_PARTS=lp2d,halfplanes,disc,lpd,cast runs only those parts.
    let parts = std::env::var("COMPGEOM_LP_PARTS").unwrap_or_default();
    let want = |p: &str| parts.is_empty() || parts.split(',').any(|x| x == p);
    if want("lp2d") {
        lp2d_part(sizes)?;
    }
    if want("halfplanes") {
        halfplanes(quick)?;
    }
    if want("disc") {
        disc_part(sizes)?;
    }
    if want("lpd") {
        lpd_part(quick)?;
    }
    if want("cast") {
        cast_part(quick)?;
    }
    Ok(())
}

fn lp2d_part(sizes: &[usize]) -> Result<(), String> {
    let c = (0.3, 0.7);
    println!(
        "2D linear programming: ms (best of 7, alternating with the scan), ratio = peer / compgeom (> 1 = compgeom faster)"
    );
    println!(
        "{:>9} {:>12} {:>12} {:>8} {:>12} {:>8} {:>13}",
        "n", "compgeom", "microlp", "ratio", "scan hpi", "ratio", "median ratio"
    );
    let mut prev: Option<f64> = None;
    for &n in sizes {
        let hs = constraints(n, 42);
        let ours = match lp2d(&hs, Vector2::new(c.0, c.1), &Lp2Options::default())
            .map_err(|e| e.to_string())?
        {
            Lp2Solution::Optimal { value, .. } => value,
            other => return Err(format!("unexpected {other:?}")),
        };
        let scan = scan_lp(&hs, c);
        if (scan - ours).abs() > 1e-9 {
            return Err(format!("scan disagrees: {scan} vs {ours}"));
        }
        // Alternate the two, 7 rounds: best times, and the median of the per-round ratios
        // (robust to a loaded machine).
        let (mut t_ours, mut t_scan) = (Duration::MAX, Duration::MAX);
        let mut ratios = Vec::new();
        for _ in 0..7 {
            let a = best_of(1, || {
                lp2d(&hs, Vector2::new(c.0, c.1), &Lp2Options::default())
            });
            let b = best_of(1, || scan_lp(&hs, c));
            t_ours = t_ours.min(a);
            t_scan = t_scan.min(b);
            ratios.push(ms(b) / ms(a));
        }
        ratios.sort_by(f64::total_cmp);
        let median = ratios[ratios.len() / 2];
        // microlp: once per size (it is far slower); skipped where it would take minutes.
        let micro = if n <= 100_000 {
            let start = std::time::Instant::now();
            let v = microlp_value(&hs, c)?;
            if (v - ours).abs() > 1e-6 {
                return Err(format!("microlp disagrees: {v} vs {ours}"));
            }
            Some(start.elapsed())
        } else {
            None
        };
        let micro_s = micro.map_or("skipped".to_string(), |t| format!("{:.1}", ms(t)));
        let micro_r = micro.map_or("-".to_string(), |t| format!("{:.1}", ms(t) / ms(t_ours)));
        println!(
            "{:>9} {:>12.2} {:>12} {:>8} {:>12.2} {:>8.1} {:>13.1}",
            n,
            ms(t_ours),
            micro_s,
            micro_r,
            ms(t_scan),
            ms(t_scan) / ms(t_ours),
            median
        );
        if let Some(p) = prev {
            println!(
                "          compgeom growth x{:.1} for 10x the constraints",
                ms(t_ours) / p
            );
        }
        prev = Some(ms(t_ours));
    }

    Ok(())
}

fn disc_part(sizes: &[usize]) -> Result<(), String> {
    println!("smallest enclosing disc: ms (best of 3); geo 0.33 has no minimum bounding circle; peer = the same MINIDISC in plain f64");
    for &n in sizes {
        let pts = disc_points(n, 11);
        let d = smallest_enclosing_disc(&pts, 0).map_err(|e| e.to_string())?;
        let f = f64_minidisc(&pts);
        if (d.radius - f.2).abs() > 1e-9 * d.radius {
            return Err(format!("radius {} vs {}", d.radius, f.2));
        }
        let t_ours = best_of(3, || smallest_enclosing_disc(&pts, 0));
        let t_f64 = best_of(3, || f64_minidisc(&pts));
        println!(
            "{:>9} compgeom {:>9.2}  plain f64 {:>9.2}  ratio {:.2}",
            n,
            ms(t_ours),
            ms(t_f64),
            ms(t_f64) / ms(t_ours)
        );
    }
    Ok(())
}

/// d = 3 LP: planes tangent to the unit sphere at random points, random objective.
fn lpd_part(quick: bool) -> Result<(), String> {
    let sizes: &[usize] = if quick {
        &[1_000, 10_000]
    } else {
        &[1_000, 10_000, 100_000]
    };
    println!(
        "lp_d, d = 3: ms (best of 3); exact = the exact integer path alone (no f64 fast path)"
    );
    let mut prev: Option<f64> = None;
    for &n in sizes {
        let mut r = Rng::new(3);
        let rows: Vec<Vec<f64>> = (0..n)
            .map(|_| {
                let (z, t) = (2.0 * r.unit() - 1.0, r.unit() * std::f64::consts::TAU);
                let s = (1.0 - z * z).sqrt();
                vec![s * t.cos(), s * t.sin(), z, 1.0]
            })
            .collect();
        let c = [0.2, -0.5, 0.7];
        let r = compgeom::lp::lp_d(&rows, &c, 0).map_err(|e| e.to_string())?;
        if compgeom::lp::lp_d_exact(&rows, &c, 0).map_err(|e| e.to_string())? != r {
            return Err("lp_d fast and exact paths disagree".into());
        }
        let t = best_of(3, || compgeom::lp::lp_d(&rows, &c, 0));
        let te = best_of(1, || compgeom::lp::lp_d_exact(&rows, &c, 0));
        print!("{:>9} compgeom {:>10.2}  exact {:>10.2}", n, ms(t), ms(te));
        match prev {
            Some(p) => println!("  growth x{:.1} for 10x", ms(t) / p),
            None => println!(),
        }
        prev = Some(ms(t));
    }
    Ok(())
}

/// Casting a prism over a regular k-gon (k + 2 facets; castable from both caps).
fn cast_part(quick: bool) -> Result<(), String> {
    let sizes: &[usize] = if quick {
        &[100, 300]
    } else {
        &[100, 300, 1_000]
    };
    println!("castability of a k-gon prism: ms (best of 1)");
    let mut prev: Option<f64> = None;
    for &k in sizes {
        let mut vertices = Vec::with_capacity(2 * k);
        for z in [0.0, 1.0] {
            for i in 0..k {
                let t = i as f64 * std::f64::consts::TAU / k as f64;
                vertices.push(compgeom::Point3::new(t.cos(), t.sin(), z));
            }
        }
        let mut faces = vec![(0..k).rev().collect::<Vec<_>>(), (k..2 * k).collect()];
        for i in 0..k {
            let j = (i + 1) % k;
            faces.push(vec![i, j, k + j, k + i]);
        }
        let mesh = compgeom::io::Polyhedron { vertices, faces };
        let c = compgeom::lp::castability(&mesh).map_err(|e| e.to_string())?;
        let t = best_of(1, || compgeom::lp::castability(&mesh));
        print!(
            "{:>6} facets compgeom {:>10.2} ({} castable tops)",
            k + 2,
            ms(t),
            c.top_facets.len()
        );
        match prev {
            Some(p) => println!("  growth x{:.1}", ms(t) / p),
            None => println!(),
        }
        prev = Some(ms(t));
    }
    Ok(())
}
