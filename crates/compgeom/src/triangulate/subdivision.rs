//! The faces of the polygon cut along a set of non-crossing diagonals (the monotone pieces
//! after MAKEMONOTONE).
//!
//! A compact half-edge structure: half-edge `v` is the boundary edge from `v` to its
//! successor, and diagonal `d` gives half-edges `n + 2d` and `n + 2d + 1`. The diagonals
//! leaving a vertex are sorted counter-clockwise inside its wedge (exact orientation
//! tests); an arriving half-edge continues with the leaving one just clockwise of it, so
//! every face lies to the left of its half-edges, as in the book's DCEL. O(n + d log d).
use super::geometry::{Geometry, NONE};
use std::cmp::Ordering;

/// The face cycles (vertex lists, counter-clockwise, interior on the left) of the polygon
/// cut along `diagonals`.
pub(crate) fn faces(g: &Geometry, diagonals: &[[u32; 2]]) -> Vec<Vec<u32>> {
    let n = g.len();
    if diagonals.is_empty() {
        return boundary_cycles(g);
    }
    let halves = n + 2 * diagonals.len();
    let origin = |h: usize| -> u32 {
        if h < n {
            h as u32
        } else {
            diagonals[(h - n) / 2][(h - n) % 2]
        }
    };
    let dest = |h: usize| -> u32 {
        if h < n {
            g.next[h]
        } else {
            diagonals[(h - n) / 2][1 - (h - n) % 2]
        }
    };
    // Diagonal half-edges grouped by origin (counting sort).
    let mut start = vec![0usize; n + 1];
    for d in diagonals {
        start[d[0] as usize + 1] += 1;
        start[d[1] as usize + 1] += 1;
    }
    for v in 0..n {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut out = vec![0usize; 2 * diagonals.len()];
    for h in n..halves {
        let v = origin(h) as usize;
        out[fill[v]] = h;
        fill[v] += 1;
    }
    let mut next = vec![NONE as usize; halves];
    for v in 0..n {
        let list = &mut out[start[v]..start[v + 1]];
        let vv = v as u32;
        let r0 = g.next[v];
        // Counter-clockwise angle from the leaving boundary edge: half 0 is (0, π).
        let half = |w: u32| {
            if g.orient(vv, r0, w) == Ordering::Greater {
                0
            } else {
                1
            }
        };
        list.sort_unstable_by(|&a, &b| {
            let (wa, wb) = (dest(a), dest(b));
            half(wa).cmp(&half(wb)).then_with(|| g.orient(vv, wb, wa))
        });
        let mut before = v; // the boundary half-edge leaving v
        for &h in list.iter() {
            next[twin(h, n)] = before;
            before = h;
        }
        next[g.prev[v] as usize] = before;
    }
    let mut seen = vec![false; halves];
    let mut cycles = Vec::new();
    for h0 in 0..halves {
        if seen[h0] {
            continue;
        }
        let mut cycle = Vec::new();
        let mut h = h0;
        while !seen[h] {
            seen[h] = true;
            cycle.push(origin(h));
            h = next[h];
        }
        cycles.push(cycle);
    }
    cycles
}

/// The twin of diagonal half-edge `h`.
fn twin(h: usize, n: usize) -> usize {
    n + ((h - n) ^ 1)
}

/// The boundary cycles alone.
pub(crate) fn boundary_cycles(g: &Geometry) -> Vec<Vec<u32>> {
    let n = g.len();
    let mut seen = vec![false; n];
    let mut cycles = Vec::new();
    for v0 in 0..n {
        if seen[v0] {
            continue;
        }
        let mut cycle = Vec::new();
        let mut v = v0;
        while !seen[v] {
            seen[v] = true;
            cycle.push(v as u32);
            v = g.next[v] as usize;
        }
        cycles.push(cycle);
    }
    cycles
}
