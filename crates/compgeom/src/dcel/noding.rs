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
//! 2. Vertices: the segment ends and the contacts, sorted by their rounded points (input
//!    points as they are, crossings correctly rounded). Correct rounding is a function of
//!    the exact point, so equal points have equal keys; runs of equal keys holding a
//!    crossing are split exactly ([`ExactPoint::compare_xy`]); elsewhere equal keys are
//!    equal input points. A vertex is an input point whenever one of its items is.
//! 3. Each segment is cut at its contacts, sorted along it (exact lexicographic order,
//!    decided by the rounded points where they differ — rounding is monotone — and
//!    exactly where they tie). Only segments in a collinear overlap can give pieces with
//!    the same two ends; only those go through a merge.
//!
//! The result is the arrangement [`Flat::general`] builds from the sweep (tested against
//! it and against a brute-force oracle on degenerate input). When the grid would test too
//! many pairs (long segments: see [`crate::intersect::prefer_pairwise`]) the sweep path
//! is used instead.
//!
//! Cost: O(n + m + (n + K) log(n + K)) for m candidate pairs and K contacts.
use super::build::Source;
use super::flat::{okey, Flat, Pieces};
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

/// From this many items on, the vertex sort runs on the rayon pool.
const PARALLEL_SORT_FROM: usize = 100_000;

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
}

/// What the scanned pairs contribute.
#[derive(Default)]
struct Found {
    contacts: Vec<Contact>,
    /// Pairs overlapping collinearly.
    overlapping: Vec<(u32, u32)>,
}

impl Found {
    /// Test segments `i < j` exactly and record the cuts they cause.
    fn test(&mut self, segs: &[Segment2], i: usize, j: usize) {
        let (s, t) = (segs[i], segs[j]);
        let shared = if s.a == t.a || s.a == t.b {
            Some((s.a, s.b))
        } else if s.b == t.a || s.b == t.b {
            Some((s.b, s.a))
        } else {
            None
        };
        if let Some((p, far_s)) = shared {
            let far_t = if t.a == p { t.b } else { t.a };
            // Not collinear: the lines meet only at p, an end of both.
            if orient2d(p, far_s, far_t) != Orientation::Collinear {
                return;
            }
        }
        let (i32_, j32) = (i as u32, j as u32);
        match crate::kernel::segment_intersection(s, t) {
            SegmentIntersection::None => {}
            SegmentIntersection::Endpoint(q) => self.touch(q, s, i32_, t, j32),
            SegmentIntersection::Crossing(c) => self.contacts.push(Contact {
                point: round_crossing(&c),
                a: i32_,
                b: j32,
                crossing: true,
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
        let inner = |s: Segment2| q != s.a && q != s.b;
        let (a, b) = match (inner(s), inner(t)) {
            (true, true) => (i, j),
            (true, false) => (i, NONE),
            (false, true) => (j, NONE),
            (false, false) => return,
        };
        self.contacts.push(Contact {
            point: q,
            a,
            b,
            crossing: false,
        });
    }

    fn merge(mut self, mut other: Found) -> Found {
        if self.contacts.len() < other.contacts.len() {
            std::mem::swap(&mut self, &mut other);
        }
        self.contacts.append(&mut other.contacts);
        self.overlapping.append(&mut other.overlapping);
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

/// Vertices, cuts and pieces from the contacts (steps 2 and 3 of the module docs).
fn assemble(sub: &[Segment2], kept: &[usize], found: Found) -> Flat {
    let m = sub.len();
    let contacts = &found.contacts;
    // Items: 2k and 2k + 1 are the ends a and b of segment k; 2m + c is contact c.
    let item_point = |id: u32| -> Point2 {
        let id = id as usize;
        if id < 2 * m {
            let s = &sub[id / 2];
            if id % 2 == 0 {
                s.a
            } else {
                s.b
            }
        } else {
            contacts[id - 2 * m].point
        }
    };
    let is_crossing = |id: u32| id as usize >= 2 * m && contacts[id as usize - 2 * m].crossing;
    let mut items: Vec<(u64, u64, u32)> = (0..(2 * m + contacts.len()) as u32)
        .map(|id| {
            let p = item_point(id);
            (okey(p.x), okey(p.y), id)
        })
        .collect();
    if items.len() >= PARALLEL_SORT_FROM {
        items.par_sort_unstable();
    } else {
        items.sort_unstable();
    }
    let exact_of = |id: u32| -> ExactPoint {
        if is_crossing(id) {
            let c = &contacts[id as usize - 2 * m];
            ExactPoint::Crossing(Crossing {
                s: sub[c.a as usize],
                t: sub[c.b as usize],
            })
        } else {
            ExactPoint::Input(item_point(id))
        }
    };
    let mut vertices: Vec<ExactPoint> = Vec::with_capacity(m + contacts.len());
    let mut rounded: Vec<Rounded> = Vec::with_capacity(m + contacts.len());
    let mut vertex_of = vec![NONE; items.len()];
    // One vertex for a group of items at one exact point: an input point if any is.
    let mut add_vertex = |group: &[u32], vertices: &mut Vec<ExactPoint>| {
        let rep = group
            .iter()
            .copied()
            .filter(|&id| !is_crossing(id))
            .min()
            .or_else(|| {
                group.iter().copied().min_by_key(|&id| {
                    let c = &contacts[id as usize - 2 * m];
                    (c.a, c.b)
                })
            })
            .expect("a group is not empty");
        let e = exact_of(rep);
        rounded.push(Rounded::of(&e, item_point(rep)));
        let v = vertices.len() as u32;
        vertices.push(e);
        for &id in group {
            vertex_of[id as usize] = v;
        }
    };
    let mut group: Vec<u32> = Vec::new();
    let mut k = 0;
    while k < items.len() {
        let mut end = k + 1;
        while end < items.len() && items[end].0 == items[k].0 && items[end].1 == items[k].1 {
            end += 1;
        }
        let run = &items[k..end];
        if run.iter().any(|it| is_crossing(it.2)) && run.len() > 1 {
            // Equal rounded points, not necessarily equal: split exactly.
            let mut exact: Vec<(ExactPoint, u32)> =
                run.iter().map(|it| (exact_of(it.2), it.2)).collect();
            exact.sort_by(|x, y| x.0.compare_xy(&y.0).then(x.1.cmp(&y.1)));
            let mut g0 = 0;
            for g in 1..=exact.len() {
                if g == exact.len() || exact[g].0.compare_xy(&exact[g0].0) != Ordering::Equal {
                    group.clear();
                    group.extend(exact[g0..g].iter().map(|x| x.1));
                    add_vertex(&group, &mut vertices);
                    g0 = g;
                }
            }
        } else {
            group.clear();
            group.extend(run.iter().map(|it| it.2));
            add_vertex(&group, &mut vertices);
        }
        k = end;
    }
    drop(items);
    // Cuts per segment, flat (counted first).
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
        let v = vertex_of[2 * m + c];
        for s in [contact.a, contact.b] {
            if s != NONE {
                inner[fill[s as usize] as usize] = v;
                fill[s as usize] += 1;
            }
        }
    }
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
    for (k, s) in sub.iter().enumerate() {
        chain.clear();
        chain.push(vertex_of[2 * k]);
        let cuts = &mut inner[in_start[k] as usize..in_start[k + 1] as usize];
        if cuts.len() > 1 {
            // Along the segment from a: lexicographic order, reversed when a is the
            // larger end.
            let a_low = compare_xy(s.a, s.b) == Ordering::Less;
            cuts.sort_unstable_by(|&u, &v| {
                let (u, v) = (u as usize, v as usize);
                let o = compare_xy_filtered(&vertices[u], &rounded[u], &vertices[v], &rounded[v]);
                if a_low {
                    o
                } else {
                    o.reverse()
                }
            });
        }
        for &v in cuts.iter() {
            // The same point may cut a segment for several pairs.
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
