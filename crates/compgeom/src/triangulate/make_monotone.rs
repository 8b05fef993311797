//! MAKEMONOTONE (§3.2): a downward plane sweep that adds a diagonal at every split and
//! merge vertex, so the polygon falls apart into y-monotone pieces.
//!
//! The handlers are the book's HANDLESTARTVERTEX ... HANDLEREGULARVERTEX, with
//! helper(e) kept for every edge with the interior to its right. The status holds every
//! edge crossing the sweep line (those with the interior on their left too): the extra
//! edges cost a constant factor and let the sweep check, exactly and for free, that the
//! edge directly left of a split, merge or right-chain vertex has the interior on its
//! right, which is exactly the statement that the rings are nested properly (every hole
//! inside the outer ring, no hole inside another). O(n log n) time, O(n) space.
use super::classify::{vertex_type, VertexType};
use super::geometry::{Geometry, NONE};
use super::status::{Side, Status};
use crate::kernel::{segment_intersection, Point2, Segment2, SegmentIntersection};
use crate::{Error, Result};
use std::cmp::Ordering;

/// Everything MAKEMONOTONE produces: the diagonals and every vertex's type.
pub(crate) struct Partition {
    /// The added diagonals.
    pub diagonals: Vec<[u32; 2]>,
    /// The type of every vertex.
    pub types: Vec<VertexType>,
}

/// Whether edges `a` and `b` (each from u to `next[u]`) meet other than at a common
/// endpoint: a crossing, a vertex inside the other edge, or an overlap (exact).
fn check_pair(g: &Geometry, a: u32, b: u32) -> Result<()> {
    if a == NONE || b == NONE {
        return Ok(());
    }
    let seg = |u: u32| Segment2::new(g.pts[u as usize], g.pts[g.next[u as usize] as usize]);
    let (sa, sb) = (seg(a), seg(b));
    let is_end = |s: &Segment2, p: Point2| s.a == p || s.b == p;
    let (how, at) = match segment_intersection(sa, sb) {
        SegmentIntersection::None => return Ok(()),
        SegmentIntersection::Endpoint(p) if is_end(&sa, p) && is_end(&sb, p) => return Ok(()),
        SegmentIntersection::Endpoint(p) => ("touch (a vertex inside an edge) at", p),
        SegmentIntersection::Crossing(c) => ("cross at", c.approx()),
        SegmentIntersection::Overlap(p, _) => ("overlap from", p),
    };
    Err(Error::InvalidInput(format!(
        "polygon is not simple: {} and {} {how} ({}, {})",
        g.edge_name(a),
        g.edge_name(b),
        at.x,
        at.y
    )))
}

/// Run the sweep. Every pair of edges that become neighbours in the status is checked
/// for contact (Shamos–Hoey), so a boundary that is not simple is reported with the two
/// edges before the status order could go wrong.
pub(crate) fn make_monotone(g: &Geometry) -> Result<Partition> {
    let order = &g.order;
    let n = g.len();
    let mut status = Status::new(n);
    let mut helper = vec![0u32; n];
    let mut types = vec![VertexType::Regular; n];
    let mut diagonals = Vec::new();
    // Edge u runs from u to next[u]; its upper and lower end in the sweep order.
    let down = |u: u32| g.above(u, g.next[u as usize]);
    let ends = |u: u32| {
        let w = g.next[u as usize];
        if down(u) {
            (u, w)
        } else {
            (w, u)
        }
    };
    let side = |t: u32, v: u32| {
        let (a, b) = ends(t);
        match g.orient(a, b, v) {
            Ordering::Greater => Side::Right,
            Ordering::Less => Side::Left,
            Ordering::Equal => Side::On,
        }
    };
    // Insert edge e whose upper end is the event vertex v.
    let on_edge = |v: u32, t: u32| {
        let p = g.pts[v as usize];
        Error::InvalidInput(format!(
            "polygon is not simple: vertex ({}, {}) lies on {}",
            p.x,
            p.y,
            g.edge_name(t)
        ))
    };
    let insert = |status: &mut Status, e: u32, v: u32| -> Result<()> {
        let (_, w) = ends(e);
        status
            .insert(e, |t| {
                let s = side(t, v);
                if s == Side::On && ends(t).0 == v {
                    side(t, w)
                } else {
                    s
                }
            })
            .map_err(|t| on_edge(v, t))?;
        let (l, r) = status.neighbours(e);
        check_pair(g, l, e)?;
        check_pair(g, e, r)
    };
    let remove = |status: &mut Status, e: u32| -> Result<()> {
        let (l, r) = status.neighbours(e);
        status.remove(e);
        check_pair(g, l, r)
    };
    // The edge directly left of v; it must have the interior on its right.
    let left_of = |status: &Status, v: u32| -> Result<u32> {
        match status.left_of(|t| side(t, v)).map_err(|t| on_edge(v, t))? {
            Some(e) if down(e) => Ok(e),
            _ => {
                let p = g.pts[v as usize];
                Err(Error::InvalidInput(format!(
                    "polygon rings are not nested properly: vertex ({}, {}) is outside \
                     the polygon (a hole outside the outer ring or inside another hole)",
                    p.x, p.y
                )))
            }
        }
    };
    for &v in order {
        let p = g.prev[v as usize];
        let ty = vertex_type(g, v);
        types[v as usize] = ty;
        let (e_in, e_out) = (p, v);
        match ty {
            VertexType::Start => {
                insert(&mut status, e_out, v)?;
                insert(&mut status, e_in, v)?;
                helper[e_out as usize] = v;
            }
            VertexType::End => {
                let h = helper[e_in as usize];
                if types[h as usize] == VertexType::Merge {
                    diagonals.push([v, h]);
                }
                remove(&mut status, e_in)?;
                remove(&mut status, e_out)?;
            }
            VertexType::Split => {
                let ej = left_of(&status, v)?;
                diagonals.push([v, helper[ej as usize]]);
                helper[ej as usize] = v;
                insert(&mut status, e_out, v)?;
                insert(&mut status, e_in, v)?;
                helper[e_out as usize] = v;
            }
            VertexType::Merge => {
                let h = helper[e_in as usize];
                if types[h as usize] == VertexType::Merge {
                    diagonals.push([v, h]);
                }
                remove(&mut status, e_in)?;
                remove(&mut status, e_out)?;
                let ej = left_of(&status, v)?;
                let h = helper[ej as usize];
                if types[h as usize] == VertexType::Merge {
                    diagonals.push([v, h]);
                }
                helper[ej as usize] = v;
            }
            VertexType::Regular => {
                if g.above(p, v) {
                    // The interior lies to the right of v.
                    let h = helper[e_in as usize];
                    if types[h as usize] == VertexType::Merge {
                        diagonals.push([v, h]);
                    }
                    remove(&mut status, e_in)?;
                    insert(&mut status, e_out, v)?;
                    helper[e_out as usize] = v;
                } else {
                    remove(&mut status, e_out)?;
                    let ej = left_of(&status, v)?;
                    let h = helper[ej as usize];
                    if types[h as usize] == VertexType::Merge {
                        diagonals.push([v, h]);
                    }
                    helper[ej as usize] = v;
                    insert(&mut status, e_in, v)?;
                }
            }
        }
    }
    Ok(Partition { diagonals, types })
}
