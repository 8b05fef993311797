//! The Voronoi diagram as the dual of the Delaunay triangulation: it agrees with Fortune's
//! sweep (same sites, the same vertices as sets of sites and to rounding as points, the
//! same directed edges between the same cells and vertices), passes the exact verifier, and
//! is dual to the triangulation; on random, grid, cocircular, collinear and duplicate input.

use compgeom::delaunay::{delaunay, verify_delaunay};
use compgeom::kernel::{incircle, CircleSide};
use compgeom::voronoi::{
    dual_voronoi, fortune_voronoi, from_triangulation, verify_voronoi, voronoi_diagram,
    VoronoiAlgorithm, VoronoiDiagram,
};
use compgeom::Point2;
use proptest::prelude::*;
use std::collections::{BTreeMap, BTreeSet};

/// A directed half-edge by what defines it exactly: (left site, right site, origin vertex
/// sites, destination vertex sites); `None` at infinity.
type EdgeKey = (usize, usize, Option<Vec<usize>>, Option<Vec<usize>>);

fn edge_keys(d: &VoronoiDiagram) -> Vec<EdgeKey> {
    let vs = |v: Option<usize>| v.map(|v| d.vertices[v].sites.clone());
    let mut k: Vec<EdgeKey> = (0..d.half_edges.len())
        .map(|h| {
            let e = &d.half_edges[h];
            (
                e.site,
                d.half_edges[e.twin].site,
                vs(e.origin),
                vs(d.destination(h)),
            )
        })
        .collect();
    k.sort();
    k
}

/// Fortune and the dual agree, both verify, and the dual is dual to the triangulation.
fn agree(points: &[Point2]) -> VoronoiDiagram {
    let f = fortune_voronoi(points).unwrap();
    let d = dual_voronoi(points).unwrap();
    let shown = || {
        if points.len() <= 40 {
            format!("{points:?}")
        } else {
            format!("{} points", points.len())
        }
    };
    verify_voronoi(points, &d).unwrap_or_else(|e| panic!("dual: {e} for {}", shown()));
    assert_eq!(d.sites, f.sites, "sites for {}", shown());
    assert_eq!(d.input_to_site, f.input_to_site);
    assert_eq!(d.site_input_index, f.site_input_index);
    // Vertices: the same site sets, each once, at the same place up to rounding.
    let fv: BTreeMap<Vec<usize>, Point2> = f
        .vertices
        .iter()
        .map(|v| (v.sites.clone(), v.point))
        .collect();
    let dv: BTreeMap<Vec<usize>, Point2> = d
        .vertices
        .iter()
        .map(|v| (v.sites.clone(), v.point))
        .collect();
    assert_eq!(dv.len(), d.vertices.len(), "repeated vertex in the dual");
    assert_eq!(
        fv.keys().collect::<Vec<_>>(),
        dv.keys().collect::<Vec<_>>(),
        "vertices differ for {}",
        shown()
    );
    for (k, p) in &dv {
        let q = fv[k];
        let scale = p.x.abs().max(p.y.abs()).max(f64::MIN_POSITIVE);
        let err = (p.x - q.x).abs().max((p.y - q.y).abs());
        assert!(err <= 1e-9 * scale, "vertex {k:?}: {p:?} vs {q:?}");
    }
    assert_eq!(edge_keys(&d), edge_keys(&f), "edges differ for {}", shown());
    // The cells' neighbours (the Delaunay graph) are the same.
    assert_eq!(d.neighbours(), f.neighbours());
    d
}

/// Voronoi ↔ Delaunay duality: every Voronoi vertex is the circumcentre (to rounding) of
/// the Delaunay triangles it merges, and they are exactly cocircular; every Delaunay edge is
/// a Voronoi edge unless it lies inside such a group; every Voronoi edge is a Delaunay edge.
fn duality(points: &[Point2]) {
    let t = delaunay(points).unwrap();
    verify_delaunay(&t).unwrap();
    let d = from_triangulation(&t);
    let vp = t.vertices();
    let vertex_of: BTreeMap<Vec<usize>, usize> = d
        .vertices
        .iter()
        .enumerate()
        .map(|(i, v)| (v.sites.clone(), i))
        .collect();
    let mut covered = vec![0usize; d.vertices.len()];
    for (k, tri) in t.triangles().iter().enumerate() {
        let s: BTreeSet<usize> = tri.iter().map(|&v| v as usize).collect();
        let owner: Vec<usize> = d
            .vertices
            .iter()
            .enumerate()
            .filter(|(_, v)| s.iter().all(|x| v.sites.contains(x)))
            .map(|(i, _)| i)
            .collect();
        assert_eq!(owner.len(), 1, "triangle {tri:?} lies in {owner:?}");
        let v = &d.vertices[owner[0]];
        covered[owner[0]] += 1;
        let [a, b, c] = tri.map(|i| vp[i as usize]);
        for &x in &v.sites {
            assert_eq!(incircle(a, b, c, vp[x]), CircleSide::OnCircle);
        }
        let cc = t.circumcenter(k);
        let scale = cc.x.abs().max(cc.y.abs()).max(1.0);
        assert!((cc.x - v.point.x).abs() <= 1e-9 * scale);
        assert!((cc.y - v.point.y).abs() <= 1e-9 * scale);
    }
    // A vertex of degree k merges k - 2 triangles.
    for (i, v) in d.vertices.iter().enumerate() {
        assert_eq!(covered[i], v.sites.len() - 2, "vertex {i}");
    }
    let del: BTreeSet<(u32, u32)> = t.edges().into_iter().collect();
    let vor: BTreeSet<(u32, u32)> = (0..d.edge_count())
        .map(|k| {
            let e = &d.half_edges[2 * k];
            let (a, b) = (e.site as u32, d.half_edges[e.twin].site as u32);
            (a.min(b), a.max(b))
        })
        .collect();
    assert_eq!(
        vor.len(),
        d.edge_count(),
        "two Voronoi edges between one pair"
    );
    if !t.triangles().is_empty() {
        assert!(vor.is_subset(&del));
        for &(a, b) in del.difference(&vor) {
            // Inside a group: both ends on one vertex's circle of degree > 3.
            let inside = vertex_of
                .keys()
                .any(|s| s.len() > 3 && s.contains(&(a as usize)) && s.contains(&(b as usize)));
            assert!(inside, "Delaunay edge ({a}, {b}) has no Voronoi edge");
        }
    }
}

fn pts(v: &[(f64, f64)]) -> Vec<Point2> {
    v.iter().map(|&(x, y)| Point2::new(x, y)).collect()
}

fn lattice_circle(r2: i64) -> Vec<Point2> {
    let r = (r2 as f64).sqrt() as i64 + 1;
    let mut v = Vec::new();
    for x in -r..=r {
        for y in -r..=r {
            if x * x + y * y == r2 {
                v.push(Point2::new(x as f64, y as f64));
            }
        }
    }
    v
}

fn rng(seed: u64) -> impl FnMut() -> f64 {
    let mut s = seed;
    move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[test]
fn small_cases_agree() {
    for p in [
        vec![],
        pts(&[(1.0, 2.0)]),
        pts(&[(1.0, 2.0), (1.0, 2.0)]),
        pts(&[(0.0, 0.0), (1.0, 0.0)]),
        pts(&[(0.0, 0.0), (4.0, 0.0), (0.0, 4.0)]),
        pts(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]),
        pts(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0), (1.0, 1.0)]),
        pts(&[(0.0, -0.0), (-0.0, 0.0), (3.0, 1.0), (1.0, 3.0)]),
    ] {
        agree(&p);
        duality(&p);
    }
}

#[test]
fn default_is_the_dual() {
    let p = pts(&[(0.0, 0.0), (3.0, 1.0), (1.0, 4.0), (5.0, 5.0), (2.0, 2.0)]);
    let d = voronoi_diagram(&p, VoronoiAlgorithm::Default).unwrap();
    assert_eq!(d, dual_voronoi(&p).unwrap());
    let f = voronoi_diagram(&p, VoronoiAlgorithm::Fortune).unwrap();
    assert_eq!(f, fortune_voronoi(&p).unwrap());
}

#[test]
fn collinear_sites_give_parallel_edges() {
    let mut r = rng(3);
    let line: Vec<Point2> = (0..30)
        .map(|_| {
            let t = (r() * 40.0).floor();
            Point2::new(2.0 * t - 7.0, -t + 1.0)
        })
        .collect();
    let d = agree(&line);
    assert!(d.vertices.is_empty());
    assert_eq!(d.edge_count(), d.sites.len() - 1);
    agree(&pts(&[(0.0, 5.0), (0.0, 1.0), (0.0, 3.0), (0.0, 1.0)]));
    agree(&pts(&[(5.0, 0.0), (1.0, 0.0), (3.0, 0.0)]));
    duality(&line);
}

#[test]
fn cocircular_lattice_points_agree() {
    let c = lattice_circle(5525);
    let d = agree(&c);
    assert_eq!(d.vertices.len(), 1);
    assert_eq!(d.vertices[0].sites.len(), c.len());
    duality(&c);
    let mut w = c.clone();
    w.push(Point2::new(0.0, 0.0));
    agree(&w);
    // Several lattice circles, shifted so that circles overlap.
    let mut many = Vec::new();
    for (k, r2) in [25, 65, 325, 1105].iter().enumerate() {
        many.extend(
            lattice_circle(*r2)
                .iter()
                .map(|p| Point2::new(p.x + 7.0 * k as f64, p.y - 3.0 * k as f64)),
        );
    }
    agree(&many);
    duality(&many);
}

#[test]
fn grids_and_duplicates_agree() {
    for (w, h) in [(2, 2), (3, 5), (12, 9), (30, 30)] {
        let mut g = Vec::new();
        for i in 0..w {
            for j in 0..h {
                g.push(Point2::new(i as f64, j as f64));
            }
        }
        // Every point once more, in reverse order.
        let dup: Vec<Point2> = g.iter().rev().copied().collect();
        g.extend(dup);
        let d = agree(&g);
        assert_eq!(d.vertices.len(), (w - 1) * (h - 1));
        assert!(d.vertices.iter().all(|v| v.sites.len() == 4));
        duality(&g);
    }
    // A triangular lattice: six cocircular points around each vertex? No: degree-3 vertices,
    // but many equal circumradii.
    let mut tri = Vec::new();
    for i in 0..15 {
        for j in 0..15 {
            tri.push(Point2::new(2.0 * i as f64 + (j % 2) as f64, 2.0 * j as f64));
        }
    }
    agree(&tri);
}

#[test]
fn random_inputs_agree() {
    let mut r = rng(99);
    let p: Vec<Point2> = (0..4000).map(|_| Point2::new(r(), r())).collect();
    let d = agree(&p);
    assert_eq!(d.sites.len(), 4000);
    duality(&p[..600]);
    // Huge and tiny magnitudes.
    let big: Vec<Point2> = p[..400]
        .iter()
        .map(|q| Point2::new(q.x * 1e250, q.y * 1e250))
        .collect();
    agree(&big);
    let tiny: Vec<Point2> = p[..400]
        .iter()
        .map(|q| Point2::new(q.x * 1e-250, q.y * 1e-250))
        .collect();
    agree(&tiny);
}

#[test]
fn non_finite_is_an_error() {
    let e = dual_voronoi(&pts(&[(0.0, 0.0), (1.0, f64::INFINITY)])).unwrap_err();
    assert!(e.to_string().contains("point 1"), "{e}");
}

fn small_grid_points() -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((0i32..7, 0i32..7), 0..30).prop_map(|v| {
        v.into_iter()
            .map(|(x, y)| Point2::new(x as f64, y as f64))
            .collect()
    })
}

fn random_points() -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((-1e3f64..1e3, -1e3f64..1e3), 0..60)
        .prop_map(|v| v.into_iter().map(|(x, y)| Point2::new(x, y)).collect())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(120))]

    #[test]
    fn grid_points_agree(p in small_grid_points()) {
        agree(&p);
        duality(&p);
    }

    #[test]
    fn random_points_agree(p in random_points()) {
        agree(&p);
        duality(&p);
    }

    #[test]
    fn collinear_runs_and_duplicates_agree(
        base in prop::collection::vec((-20i32..20, -20i32..20), 0..8),
        run in prop::collection::vec(-10i32..10, 0..12),
        (dx, dy) in (-3i32..4, -3i32..4),
    ) {
        let mut p: Vec<Point2> = base.iter().map(|&(x, y)| Point2::new(x as f64, y as f64)).collect();
        p.extend(run.iter().map(|&t| Point2::new((t * dx) as f64, (t * dy) as f64 + 0.5)));
        let copy = p.clone();
        p.extend(copy.iter().step_by(3));
        agree(&p);
        duality(&p);
    }

    #[test]
    fn lattice_circle_subsets_agree(
        mask in prop::collection::vec(any::<bool>(), 48),
        extra in prop::collection::vec((-80i32..80, -80i32..80), 0..5),
    ) {
        let c = lattice_circle(5525);
        let mut p: Vec<Point2> = c.iter().zip(mask.iter().cycle()).filter(|(_, &m)| m).map(|(p, _)| *p).collect();
        p.extend(extra.iter().map(|&(x, y)| Point2::new(x as f64, y as f64)));
        agree(&p);
        duality(&p);
    }
}

/// Post-office queries on the dual against brute force (small dyadic coordinates, so the
/// oracle's squared distances are exact in `f64`), including ties on grids.
#[test]
fn nearest_site_queries_match_brute_force() {
    use compgeom::voronoi::NearestSite;
    let mut r = rng(5);
    let mut inputs: Vec<Vec<Point2>> = vec![
        (0..2000)
            .map(|_| Point2::new((r() * 800.0).floor() / 8.0, (r() * 800.0).floor() / 8.0))
            .collect(),
        (0..400)
            .map(|i| Point2::new((i % 20) as f64, (i / 20) as f64))
            .collect(),
        lattice_circle(5525),
        (0..30)
            .map(|i| Point2::new(i as f64, 2.0 * i as f64))
            .collect(),
    ];
    // Very uneven: a dense cluster and a few far sites.
    let mut uneven: Vec<Point2> = (0..500)
        .map(|_| Point2::new((r() * 64.0).floor() / 64.0, (r() * 64.0).floor() / 64.0))
        .collect();
    uneven.extend([(1000.0, 0.0), (0.0, 1000.0), (-1000.0, -1000.0)].map(Point2::from));
    inputs.push(uneven);
    for p in &inputs {
        let d = dual_voronoi(p).unwrap();
        let post = NearestSite::new(&d);
        let d2 = |a: Point2, b: Point2| (a.x - b.x).powi(2) + (a.y - b.y).powi(2);
        for _ in 0..500 {
            let q = Point2::new(
                (r() * 1600.0).floor() / 8.0 - 50.0,
                (r() * 1600.0).floor() / 8.0 - 50.0,
            );
            let best = d
                .sites
                .iter()
                .map(|&s| d2(q, s))
                .fold(f64::INFINITY, f64::min);
            let got = post.nearest(q).unwrap();
            assert_eq!(d2(q, d.sites[got]), best, "query {q:?}");
        }
    }
    let empty = dual_voronoi(&[]).unwrap();
    assert_eq!(
        NearestSite::new(&empty).nearest(Point2::new(0.0, 0.0)),
        None
    );
}
