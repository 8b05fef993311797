//! TRIANGULATEMONOTONEPOLYGON (§3.3): merge the two chains into one sequence in sweep
//! order, then a single pass with a stack of vertices that still need diagonals.
//!
//! * A vertex on the other chain than the stack's top sees every stack vertex: one
//!   triangle per consecutive pair of popped vertices.
//! * A vertex on the same chain: triangles while the diagonal to the next stack vertex
//!   lies inside the polygon, i.e. while the turn is strictly convex (exact
//!   [`orient2d`](crate::kernel::orient2d)). A collinear turn counts as "not inside", so no
//!   triangle is ever flat and no vertex ends up inside a triangle edge: the triangulation
//!   uses a maximal set of diagonals.
//!
//! Vertices of equal y are ordered left to right (the sweep order), so the polygon need
//! not be strictly monotone. Linear time.
use super::geometry::Geometry;
use crate::{Error, Result};
use std::cmp::Ordering;

/// What the monotone triangulation asks of the vertices it works on: the sweep order,
/// exact orientation, and the errors to report when a piece is not monotone after all.
pub(crate) trait Pieces {
    /// `a` comes before `b` in the sweep order (top to bottom, equal y left to right).
    fn above(&self, a: u32, b: u32) -> bool;
    /// Exact orientation: `Greater` for a left turn.
    fn orient(&self, a: u32, b: u32, c: u32) -> Ordering;
    /// The two chains meet: edge `a → b` (or `b → a`) and the edge leaving `c`.
    fn chains_meet(&self, a: u32, b: u32, c: u32) -> Error;
    /// The piece `cycle` is not monotone.
    fn not_monotone(&self, cycle: &[u32]) -> Error;
}

impl Pieces for Geometry {
    #[inline]
    fn above(&self, a: u32, b: u32) -> bool {
        Geometry::above(self, a, b)
    }
    #[inline]
    fn orient(&self, a: u32, b: u32, c: u32) -> Ordering {
        Geometry::orient(self, a, b, c)
    }
    fn chains_meet(&self, a: u32, b: u32, c: u32) -> Error {
        chains_meet(self, a, b, c)
    }
    fn not_monotone(&self, cycle: &[u32]) -> Error {
        not_monotone(self, cycle)
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Chain {
    Left,
    Right,
}

/// Triangulate the monotone piece `cycle` (counter-clockwise, interior on the left),
/// appending counter-clockwise triangles to `out`. An error if the piece is not monotone.
pub(crate) fn triangulate_monotone<G: Pieces>(
    g: &G,
    cycle: &[u32],
    out: &mut Vec<[u32; 3]>,
) -> Result<()> {
    let k = cycle.len();
    if k < 3 {
        return Err(g.not_monotone(cycle));
    }
    if k == 3 {
        out.push([cycle[0], cycle[1], cycle[2]]);
        return Ok(());
    }
    let mut top = 0;
    let mut bottom = 0;
    for i in 1..k {
        if g.above(cycle[i], cycle[top]) {
            top = i;
        }
        if g.above(cycle[bottom], cycle[i]) {
            bottom = i;
        }
    }
    // Left chain: forward from the top; right chain: backward from the top.
    let mut merged: Vec<(u32, Chain)> = Vec::with_capacity(k);
    merged.push((cycle[top], Chain::Left));
    let mut l = (top + 1) % k;
    let mut r = (top + k - 1) % k;
    let (mut l_last, mut r_last) = (top, top);
    while l != bottom || r != bottom {
        let take_left = if l == bottom {
            false
        } else if r == bottom {
            true
        } else {
            g.above(cycle[l], cycle[r])
        };
        let (v, chain) = if take_left {
            let v = cycle[l];
            // The chains must not meet: v lies strictly left of the right chain's edge.
            if g.orient(cycle[r_last], cycle[r], v) != Ordering::Less {
                return Err(g.chains_meet(cycle[l_last], v, cycle[r]));
            }
            l_last = l;
            l = (l + 1) % k;
            (v, Chain::Left)
        } else {
            let v = cycle[r];
            if g.orient(cycle[l_last], cycle[l], v) != Ordering::Greater {
                return Err(g.chains_meet(v, cycle[r_last], cycle[l_last]));
            }
            r_last = r;
            r = (r + k - 1) % k;
            (v, Chain::Right)
        };
        merged.push((v, chain));
    }
    let b = cycle[bottom];
    if !g.above(merged[merged.len() - 1].0, b) {
        return Err(g.not_monotone(cycle));
    }
    let mut stack: Vec<(u32, Chain)> = vec![merged[0], merged[1]];
    for &(u, c) in &merged[2..] {
        let top_chain = stack[stack.len() - 1].1;
        if c != top_chain {
            fan(&stack, u, top_chain, out);
            let last = stack[stack.len() - 1];
            stack.clear();
            stack.push(last);
            stack.push((u, c));
        } else {
            let mut last = stack.pop().unwrap_or((u, c));
            while let Some(&(t, _)) = stack.last() {
                let convex = match c {
                    Chain::Left => g.orient(t, last.0, u) == Ordering::Greater,
                    Chain::Right => g.orient(u, last.0, t) == Ordering::Greater,
                };
                if !convex {
                    break;
                }
                out.push(match c {
                    Chain::Left => [t, last.0, u],
                    Chain::Right => [u, last.0, t],
                });
                last = stack.pop().unwrap_or(last);
            }
            stack.push(last);
            stack.push((u, c));
        }
    }
    let top_chain = stack[stack.len() - 1].1;
    fan(&stack, b, top_chain, out);
    Ok(())
}

/// Triangles from `u` to every consecutive pair of stack vertices (whose top lies on
/// chain `c`, `u` on the other chain or the bottom).
fn fan(stack: &[(u32, Chain)], u: u32, c: Chain, out: &mut Vec<[u32; 3]>) {
    for w in stack.windows(2) {
        let (s0, s1) = (w[0].0, w[1].0);
        out.push(match c {
            Chain::Right => [u, s1, s0],
            Chain::Left => [s0, s1, u],
        });
    }
}

/// The chains of a monotone polygon meet: edge `a → b` of the boundary and the edge
/// leaving `c` touch or cross.
fn chains_meet(g: &Geometry, a: u32, b: u32, c: u32) -> Error {
    let e = if g.next[a as usize] == b { a } else { b };
    Error::InvalidInput(format!(
        "polygon is not simple: {} and {} touch or cross",
        g.edge_name(e),
        g.edge_name(c)
    ))
}

fn not_monotone(g: &Geometry, cycle: &[u32]) -> Error {
    let p = g.pts[cycle[0] as usize];
    Error::InvalidInput(format!(
        "the piece through vertex ({}, {}) is not monotone",
        p.x, p.y
    ))
}
