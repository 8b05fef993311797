//! The art gallery (§3.1, Theorem 3.3): the dual graph of a triangulation, a 3-colouring
//! of the vertices by depth-first search over it, and the guards = the smallest colour
//! class.
//!
//! For a simple polygon the dual graph is a tree, every vertex gets one colour, the
//! colouring is proper on every edge and diagonal, and the guards number at most ⌊n/3⌋.
//!
//! For a polygon with `h` holes the dual graph has `h` independent cycles. The search
//! colours along a spanning tree of it, which amounts to cutting the polygon open along
//! the `h` diagonals left out of the tree. The colours are then given per triangle corner
//! ([`ArtGallery::corner_colors`]): every triangle's three corners have three different
//! colours, and a vertex may carry more than one colour (one per side of a cut). The
//! guards of a colour are the vertices with a corner of that colour; every triangle has
//! such a corner, so every triangle — and hence the whole polygon — is seen, and the
//! smallest class has at most ⌊(n + 2h)/3⌋ guards (the cut-open polygon has n + 2h
//! corners on its boundary). What is *not* guaranteed with holes: one colour per vertex
//! that is proper on every edge (a polygon with holes need not be 3-colourable at all),
//! nor the ⌊n/3⌋ bound. O(n log n) (sorting the diagonals).
//!
//! Where rings touch, one point is several vertices (one per visit, see
//! [`super::Triangulation::vertices`]); a guard there is listed once.
use super::Triangulation;
use crate::kernel::Point2;
use crate::{Error, Result};
use std::cmp::Ordering;

/// Lexicographic order on points, consistent with `==` (so 0 and −0 are one
/// coordinate); coordinates are finite (the triangulation rejected the rest).
fn cmp_point(a: Point2, b: Point2) -> Ordering {
    let c = |u: f64, v: f64| u.partial_cmp(&v).unwrap_or(Ordering::Equal);
    c(a.x, b.x).then(c(a.y, b.y))
}

/// A 3-colouring of a triangulation and the guards it gives.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ArtGallery {
    /// One colour (0, 1 or 2) per vertex. For a polygon without holes every corner of a
    /// vertex has this colour, so it is a proper 3-colouring. With holes a vertex may
    /// carry several colours ([`corner_colors`](Self::corner_colors)): it is given the
    /// guard colour if it has a corner of that colour, else its first corner's colour, so
    /// that the guards are exactly the vertices whose colour is
    /// [`guard_color`](Self::guard_color) (up to repeated points, see `guards`).
    pub colors: Vec<u8>,
    /// The colours of every triangle's corners, in the triangle's vertex order.
    pub corner_colors: Vec<[u8; 3]>,
    /// The guards: vertex indices, ascending, one per guard position (of the visits of
    /// a point where rings touch, the first one of the guard colour).
    pub guards: Vec<usize>,
    /// The colour class the guards were taken from.
    pub guard_color: u8,
    /// The number of diagonals the search left out of its spanning tree (the holes).
    pub cuts: usize,
}

/// The diagonals as (triangle, corner of the edge start) pairs matched across each
/// diagonal: for every triangle edge that is not a boundary edge, the triangle on the
/// other side and the index of the edge there.
pub(crate) fn dual_graph(t: &Triangulation) -> Vec<[u32; 3]> {
    const NONE: u32 = u32::MAX;
    let mut keyed: Vec<(u64, u32)> = Vec::with_capacity(3 * t.triangles.len());
    for (i, tri) in t.triangles.iter().enumerate() {
        for s in 0..3 {
            let (a, b) = (tri[s], tri[(s + 1) % 3]);
            if !t.is_boundary_edge(a, b) {
                let (lo, hi) = (a.min(b) as u64, a.max(b) as u64);
                keyed.push(((lo << 32) | hi, (i as u32) * 3 + s as u32));
            }
        }
    }
    keyed.sort_unstable();
    let mut adj = vec![[NONE; 3]; t.triangles.len()];
    for w in keyed.windows(2) {
        if w[0].0 == w[1].0 {
            let (x, y) = (w[0].1, w[1].1);
            adj[(x / 3) as usize][(x % 3) as usize] = y;
            adj[(y / 3) as usize][(y % 3) as usize] = x;
        }
    }
    adj
}

/// 3-colour the vertices of a triangulation by depth-first search over its dual graph,
/// and pick the smallest colour class as guards (see the module docs).
///
/// ```
/// use compgeom::triangulate::{art_gallery, triangulate};
/// use compgeom::{Point2, Polygon};
/// let p = |x, y| Point2::new(x, y);
/// // A comb with three teeth: 9 vertices.
/// let comb = Polygon::new(vec![p(0., 0.), p(6., 0.), p(6., 3.), p(5., 1.), p(4., 3.),
///                              p(3., 1.), p(2., 3.), p(1., 1.), p(0., 3.)], vec![]);
/// let t = triangulate(&comb).unwrap();
/// let gallery = art_gallery(&t);
/// assert!(gallery.guards.len() <= 9 / 3);
/// ```
pub fn art_gallery(t: &Triangulation) -> ArtGallery {
    const UNSET: u8 = u8::MAX;
    let adj = dual_graph(t);
    let n = t.vertices.len();
    let mut corner = vec![[UNSET; 3]; t.triangles.len()];
    let mut colors = vec![UNSET; n];
    let mut tree_edges = 0usize;
    let mut stack: Vec<usize> = Vec::new();
    for root in 0..t.triangles.len() {
        if corner[root][0] != UNSET {
            continue;
        }
        corner[root] = [0, 1, 2];
        stack.push(root);
        while let Some(i) = stack.pop() {
            for s in 0..3 {
                let other = adj[i][s];
                if other == u32::MAX {
                    continue;
                }
                let (j, js) = ((other / 3) as usize, (other % 3) as usize);
                if corner[j][0] != UNSET {
                    continue;
                }
                // Edge s of i runs tri[s] -> tri[s+1]; edge js of j runs the other way.
                let (ca, cb) = (corner[i][s], corner[i][(s + 1) % 3]);
                let mut c = [UNSET; 3];
                c[js] = cb;
                c[(js + 1) % 3] = ca;
                c[(js + 2) % 3] = 3 - ca - cb;
                corner[j] = c;
                tree_edges += 1;
                stack.push(j);
            }
        }
    }
    let diagonals = adj.iter().flatten().filter(|&&x| x != u32::MAX).count() / 2;
    let components = t.triangles.len() - tree_edges;
    let cuts = diagonals - (t.triangles.len() - components);
    // Guards of colour c: vertices with a corner of colour c.
    let mut has = vec![0u8; n];
    for (tri, c) in t.triangles.iter().zip(&corner) {
        for s in 0..3 {
            has[tri[s]] |= 1 << c[s];
        }
    }
    let guard_color = (0..3u8)
        .min_by_key(|&c| has.iter().filter(|&&m| m & (1 << c) != 0).count())
        .unwrap_or(0);
    // A vertex shows the guard colour when it carries it (only possible with holes to
    // carry more than one), else its first corner's colour.
    for (tri, c) in t.triangles.iter().zip(&corner) {
        for s in 0..3 {
            if colors[tri[s]] == UNSET || c[s] == guard_color {
                colors[tri[s]] = c[s];
            }
        }
    }
    for c in colors.iter_mut() {
        if *c == UNSET {
            *c = 0;
        }
    }
    // One guard per point: visits of a point where rings touch are equal points.
    let mut guards: Vec<usize> = (0..n)
        .filter(|&v| has[v] & (1 << guard_color) != 0)
        .collect();
    let mut by_point = guards.clone();
    by_point.sort_by(|&a, &b| cmp_point(t.vertices[a], t.vertices[b]).then(a.cmp(&b)));
    by_point.dedup_by(|b, a| t.vertices[*a] == t.vertices[*b]);
    if by_point.len() < guards.len() {
        by_point.sort_unstable();
        guards = by_point;
    }
    ArtGallery {
        colors,
        corner_colors: corner,
        guards,
        guard_color,
        cuts,
    }
}

/// Check a colouring and its guards against a triangulation, exactly: every triangle's
/// corners have three different colours; without cuts (no holes) every corner of a vertex
/// has the vertex's colour, so the colouring is proper on every edge and diagonal; every
/// vertex's colour is one of its corners' colours; every triangle has a corner of the
/// guard colour at a guard's position; the guards are distinct points of the guard
/// colour; and there are at most ⌊(n + 2·cuts)/3⌋ guards (⌊n/3⌋ for a simple polygon).
pub fn verify_art_gallery(t: &Triangulation, g: &ArtGallery) -> Result<()> {
    let fail = |m: String| Err(Error::Verification(m));
    if g.corner_colors.len() != t.triangles.len() || g.colors.len() != t.vertices.len() {
        return fail("colouring does not match the triangulation".into());
    }
    if g.guard_color > 2 {
        return fail(format!("guard colour {} is not 0, 1 or 2", g.guard_color));
    }
    let mut carries = vec![0u8; t.vertices.len()];
    for (tri, c) in t.triangles.iter().zip(&g.corner_colors) {
        for s in 0..3 {
            if c[s] <= 2 {
                carries[tri[s]] |= 1 << c[s];
            }
        }
    }
    let carried = |v: usize| g.colors[v] <= 2 && carries[v] & (1 << g.colors[v]) != 0;
    if let Some(v) = (0..t.vertices.len()).find(|&v| carries[v] != 0 && !carried(v)) {
        return fail(format!(
            "vertex {v} has colour {} on none of its corners",
            g.colors[v]
        ));
    }
    let mut guard_points: Vec<Point2> = Vec::with_capacity(g.guards.len());
    for &v in &g.guards {
        if v >= t.vertices.len() {
            return fail(format!("guard {v} is not a vertex"));
        }
        if g.colors[v] != g.guard_color {
            return fail(format!("guard {v} does not have the guard colour"));
        }
        guard_points.push(t.vertices[v]);
    }
    guard_points.sort_by(|&a, &b| cmp_point(a, b));
    if guard_points.windows(2).any(|w| w[0] == w[1]) {
        return fail("two guards stand at the same point".into());
    }
    let is_guard = |v: usize| {
        guard_points
            .binary_search_by(|&q| cmp_point(q, t.vertices[v]))
            .is_ok()
    };
    for (i, (tri, c)) in t.triangles.iter().zip(&g.corner_colors).enumerate() {
        let mut seen = [false; 3];
        for s in 0..3 {
            if c[s] > 2 || seen[c[s] as usize] {
                return fail(format!("triangle {i} is not properly coloured: {c:?}"));
            }
            seen[c[s] as usize] = true;
            if g.cuts == 0 && g.colors[tri[s]] != c[s] {
                return fail(format!("vertex {} has two colours", tri[s]));
            }
        }
        if !(0..3).any(|s| c[s] == g.guard_color && is_guard(tri[s])) {
            return fail(format!("triangle {i} has no guard"));
        }
    }
    let bound = (t.vertices.len() + 2 * g.cuts) / 3;
    if g.guards.len() > bound {
        return fail(format!("{} guards, more than {bound}", g.guards.len()));
    }
    Ok(())
}
