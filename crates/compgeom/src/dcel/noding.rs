//! A lean exact noding for the arrangement builders: the cuts each segment needs, found
//! from the candidate pairs of the intersection grid, without building the full answer
//! of [`crate::intersect::find_intersections`] (whose U(p)/L(p)/C(p) lists cost four
//! vectors per point, and whose points include every shared endpoint: every vertex of
//! every ring).
//!
//! 1. The pairs of segments whose bounding boxes overlap come from the grid of
//!    [`crate::intersect`]'s pairwise method (scanned on the rayon pool when there are
//!    many). A pair sharing an endpoint whose far ends are not collinear with it meets
//!    only there (two lines meet at most once): one exact orientation test and nothing to
//!    record — the common case of consecutive ring edges. Every other pair is decided by
//!    [`segment_intersection`]; a *contact* is recorded when the meeting point lies in the
//!    interior of one or both segments (a proper crossing, a T-junction, the ends of a
//!    collinear overlap).
//! 2. Vertices without a global point sort: the *items* (segment ends and contacts) at
//!    one point are joined by union–find from facts the scan already knows exactly: two
//!    tested segments with equal ends (the start of a segment equal to the end of the one
//!    before, consecutive ring edges, needs no test), a T-contact and the end it touches,
//!    and contacts on one segment found equal when its cuts are sorted along it. Every
//!    pair of segments through a point p has overlapping boxes, so it is tested, and it
//!    links its items at p (a shared end, or a contact on the segment p is interior to):
//!    the items at p form one class. A vertex is an input point whenever one of its items
//!    is.
//! 3. Each segment is cut at its contacts, sorted along it (exact lexicographic order,
//!    decided by the rounded points where they differ — rounding is monotone, crossings
//!    are correctly rounded — and exactly where they tie). Only segments in a collinear
//!    overlap can give pieces with the same two ends; only those go through a merge.
//!
//! The result is the arrangement [`Flat::general`] builds from the sweep (tested against
//! it and against a brute-force oracle on degenerate input). When the grid would test too
//! many pairs (long segments: see [`crate::intersect::prefer_pairwise`]) the sweep path
//! is used instead.
//!
//! Cost: O(n + m + K log K) for m candidate pairs and K contacts (near-linear union–find).
use super::build::Source;
use super::flat::{Flat, Pieces};
use super::holes::{compare_xy_filtered, Rounded};
use crate::intersect::{prefer_pairwise, round_crossing, PARALLEL_SCAN_FROM};
use crate::kernel::{
    compare_xy, orient2d, Crossing, ExactPoint, Orientation, Point2, Segment2, SegmentIntersection,
};
use crate::Result;
use rayon::prelude::*;
use std::cmp::Ordering;
use std::collections::HashMap;

const NONE: u32 = u32::MAX;

/// A point where two segments meet that lies in the interior of segment `a` (and of `b`
/// unless `b` is `NONE`).
#[derive(Clone, Copy, Debug)]
struct Contact {
    /// The input point, or the correctly rounded crossing.
    point: Point2,
    a: u32,
    b: u32,
    /// A proper crossing of `a < b` (the exact point is their [`Crossing`]).
    crossing: bool,
    /// For an input point: the segment end it is (item `2k` or `2k + 1` for segment `k`'s
    /// `a` or `b`), or `NONE`.
    end: u32,
}

/// What the scanned pairs contribute.
#[derive(Default)]
struct Found {
    contacts: Vec<Contact>,
    /// Pairs overlapping collinearly.
    overlapping: Vec<(u32, u32)>,
    /// Pairs of equal segment ends (items `2k`, `2k + 1`), except the consecutive ones.
    same: Vec<(u32, u32)>,
}

impl Found {
    /// Test segments `i < j` exactly and record the cuts and equal ends they give.
    fn test(&mut self, segs: &[Segment2], i: usize, j: usize) {
        let (s, t) = (segs[i], segs[j]);
        let (i32_, j32) = (i as u32, j as u32);
        let mut shared = None;
        for (x, p, far_s) in [(0, s.a, s.b), (1, s.b, s.a)] {
            for (y, q, far_t) in [(0, t.a, t.b), (1, t.b, t.a)] {
                if p == q {
                    // The end of segment i = the start of i + 1 is joined anyway.
                    if !(j == i + 1 && x == 1 && y == 0) {
                        self.same.push((2 * i32_ + x, 2 * j32 + y));
                    }
                    shared = Some((p, far_s, far_t));
                }
            }
        }
        if let Some((p, far_s, far_t)) = shared {
            // Not collinear: the lines meet only at p, an end of both.
            if orient2d(p, far_s, far_t) != Orientation::Collinear {
                return;
            }
        }
        match crate::kernel::segment_intersection(s, t) {
            SegmentIntersection::None => {}
            SegmentIntersection::Endpoint(q) => self.touch(q, s, i32_, t, j32),
            SegmentIntersection::Crossing(c) => self.contacts.push(Contact {
                point: round_crossing(&c),
                a: i32_,
                b: j32,
                crossing: true,
                end: NONE,
            }),
            SegmentIntersection::Overlap(p, q) => {
                self.touch(p, s, i32_, t, j32);
                self.touch(q, s, i32_, t, j32);
                self.overlapping.push((i32_, j32));
            }
        }
    }

    /// Input point `q` lies on both segments: it cuts each it is not an end of.
    fn touch(&mut self, q: Point2, s: Segment2, i: u32, t: Segment2, j: u32) {
        let end_of = |s: Segment2, k: u32| {
            if q == s.a {
                2 * k
            } else if q == s.b {
                2 * k + 1
            } else {
                NONE
            }
        };
        let (es, et) = (end_of(s, i), end_of(t, j));
        let (a, b, end) = match (es == NONE, et == NONE) {
            (true, true) => (i, j, NONE),
            (true, false) => (i, NONE, et),
            (false, true) => (j, NONE, es),
            (false, false) => return,
        };
        self.contacts.push(Contact {
            point: q,
            a,
            b,
            crossing: false,
            end,
        });
    }

    fn merge(mut self, mut other: Found) -> Found {
        if self.contacts.len() < other.contacts.len() {
            std::mem::swap(&mut self, &mut other);
        }
        self.contacts.append(&mut other.contacts);
        self.overlapping.append(&mut other.overlapping);
        self.same.append(&mut other.same);
        self
    }
}

impl Flat {
    /// The arrangement of `segments` (finite, checked by the caller) by the lean noding
    /// of the module docs; the sweep path ([`Flat::general`]) where the grid would test
    /// too many pairs.
    pub(crate) fn noded(segments: &[Segment2]) -> Result<Flat> {
        let kept: Vec<usize> = (0..segments.len())
            .filter(|&i| !segments[i].is_degenerate())
            .collect();
        // Item ids below are u32: 2 per segment plus the contacts.
        if kept.len() >= 1 << 29 {
            return Flat::general(segments);
        }
        let sub: Vec<Segment2> = kept.iter().map(|&i| segments[i]).collect();
        let Some(grid) = prefer_pairwise(&sub) else {
            return Flat::general(segments);
        };
        let entries = grid.entry_count();
        let found = if grid.candidates() < PARALLEL_SCAN_FROM {
            let mut f = Found::default();
            for k in 0..entries {
                grid.scan_from(k, |i, j| f.test(&sub, i, j));
            }
            f
        } else {
            (0..entries)
                .into_par_iter()
                .fold(Found::default, |mut f, k| {
                    grid.scan_from(k, |i, j| f.test(&sub, i, j));
                    f
                })
                .reduce(Found::default, Found::merge)
        };
        drop(grid);
        if found.contacts.len() >= (1 << 31) - 2 * sub.len() {
            return Flat::general(segments);
        }
        Ok(assemble(&sub, &kept, found))
    }
}

fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let up = parent[parent[x as usize] as usize];
        parent[x as usize] = up;
        x = up;
    }
    x
}

fn union(parent: &mut [u32], a: u32, b: u32) {
    let (ra, rb) = (find(parent, a), find(parent, b));
    // The smaller id stays the root (deterministic classes and numbering).
    if ra < rb {
        parent[rb as usize] = ra;
    } else if rb < ra {
        parent[ra as usize] = rb;
    }
}

/// Vertices, cuts and pieces from the scan's findings (steps 2 and 3 of the module docs).
fn assemble(sub: &[Segment2], kept: &[usize], found: Found) -> Flat {
    let m = sub.len();
    let contacts = &found.contacts;
    let total = 2 * m + contacts.len();
    // Items: 2k and 2k + 1 are the ends a and b of segment k; 2m + c is contact c.
    let mut parent: Vec<u32> = (0..total as u32).collect();
    for k in 1..m {
        if sub[k - 1].b == sub[k].a {
            parent[2 * k] = (2 * k - 1) as u32;
        }
    }
    for &(x, y) in &found.same {
        union(&mut parent, x, y);
    }
    for (c, contact) in contacts.iter().enumerate() {
        if contact.end != NONE {
            union(&mut parent, (2 * m + c) as u32, contact.end);
        }
    }
    // The exact contact points.
    let exact: Vec<ExactPoint> = contacts
        .iter()
        .map(|c| {
            if c.crossing {
                ExactPoint::Crossing(Crossing {
                    s: sub[c.a as usize],
                    t: sub[c.b as usize],
                })
            } else {
                ExactPoint::Input(c.point)
            }
        })
        .collect();
    let rounded: Vec<Rounded> = exact
        .iter()
        .zip(contacts)
        .map(|(e, c)| Rounded::of(e, c.point))
        .collect();
    // Cuts per segment (contact indices), flat (counted first).
    let mut in_start = vec![0u32; m + 1];
    for c in contacts {
        in_start[c.a as usize + 1] += 1;
        if c.b != NONE {
            in_start[c.b as usize + 1] += 1;
        }
    }
    for i in 0..m {
        in_start[i + 1] += in_start[i];
    }
    let mut fill: Vec<u32> = in_start[..m].to_vec();
    let mut inner = vec![0u32; in_start[m] as usize];
    for (c, contact) in contacts.iter().enumerate() {
        for s in [contact.a, contact.b] {
            if s != NONE {
                inner[fill[s as usize] as usize] = c as u32;
                fill[s as usize] += 1;
            }
        }
    }
    drop(fill);
    // Along each segment from a: lexicographic order, reversed when a is the larger end;
    // equal neighbours are one point.
    for (k, s) in sub.iter().enumerate() {
        let cuts = &mut inner[in_start[k] as usize..in_start[k + 1] as usize];
        if cuts.len() < 2 {
            continue;
        }
        let a_low = compare_xy(s.a, s.b) == Ordering::Less;
        let cmp = |u: u32, v: u32| {
            let (u, v) = (u as usize, v as usize);
            compare_xy_filtered(&exact[u], &rounded[u], &exact[v], &rounded[v])
        };
        cuts.sort_unstable_by(|&u, &v| if a_low { cmp(u, v) } else { cmp(v, u) });
        for w in 1..cuts.len() {
            if cmp(cuts[w - 1], cuts[w]) == Ordering::Equal {
                union(
                    &mut parent,
                    (2 * m) as u32 + cuts[w - 1],
                    (2 * m) as u32 + cuts[w],
                );
            }
        }
    }
    // One vertex per class, represented by an input point where the class has one (ends
    // come first in id order), else by the crossing of the smallest pair.
    let is_crossing = |id: u32| id as usize >= 2 * m && contacts[id as usize - 2 * m].crossing;
    let pair = |id: u32| {
        let c = &contacts[id as usize - 2 * m];
        (c.a, c.b)
    };
    let mut rep = vec![NONE; total];
    for id in 0..total as u32 {
        let r = find(&mut parent, id) as usize;
        let better = rep[r] == NONE
            || (is_crossing(rep[r]) && (!is_crossing(id) || pair(id) < pair(rep[r])));
        if better {
            rep[r] = id;
        }
    }
    let mut vertices: Vec<ExactPoint> = Vec::with_capacity(m + contacts.len());
    let mut vertex_of = vec![NONE; total];
    for id in 0..total {
        let r = parent[id] as usize; // fully compressed by the pass above
        let r = if parent[r] as usize == r {
            r
        } else {
            find(&mut parent, id as u32) as usize
        };
        if vertex_of[r] == NONE {
            vertex_of[r] = vertices.len() as u32;
            let e = rep[r] as usize;
            vertices.push(if e < 2 * m {
                ExactPoint::Input(if e % 2 == 0 {
                    sub[e / 2].a
                } else {
                    sub[e / 2].b
                })
            } else {
                exact[e - 2 * m]
            });
        }
        vertex_of[id] = vertex_of[r];
    }
    drop(parent);
    let mut shared = vec![false; m];
    for &(i, j) in &found.overlapping {
        shared[i as usize] = true;
        shared[j as usize] = true;
    }
    let mut merged: HashMap<(u32, u32), u32> = HashMap::new();
    let mut pieces = Pieces {
        edges: Vec::with_capacity(m + inner.len()),
        pairs: Vec::with_capacity(m + inner.len()),
    };
    let mut chain: Vec<u32> = Vec::new();
    for k in 0..m {
        chain.clear();
        chain.push(vertex_of[2 * k]);
        for &c in &inner[in_start[k] as usize..in_start[k + 1] as usize] {
            // The same point may cut a segment for several pairs.
            let v = vertex_of[2 * m + c as usize];
            if chain.last() != Some(&v) {
                chain.push(v);
            }
        }
        chain.push(vertex_of[2 * k + 1]);
        for w in chain.windows(2) {
            let (u, v) = (w[0], w[1]);
            if !shared[k] {
                pieces.pairs.push((
                    pieces.edges.len() as u32,
                    Source {
                        segment: kept[k],
                        forward: true,
                    },
                ));
                pieces.edges.push([u, v]);
                continue;
            }
            let e = *merged.entry((u.min(v), u.max(v))).or_insert_with(|| {
                pieces.edges.push([u, v]);
                pieces.edges.len() as u32 - 1
            });
            let forward = pieces.edges[e as usize][0] == u;
            pieces.pairs.push((
                e,
                Source {
                    segment: kept[k],
                    forward,
                },
            ));
        }
    }
    pieces.finish(vertices)
}
