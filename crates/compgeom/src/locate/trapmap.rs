//! The core of the trapezoidal map (book §6.1–6.3): trapezoid records with their
//! neighbours, the search structure D (a DAG of x-nodes, y-nodes and leaves), the
//! randomized incremental construction TRAPEZOIDALMAP and the query.
//!
//! Everything lives in flat `Vec` arenas indexed by `u32`; [`NONE`] marks a missing
//! neighbour, the bounding box's top or bottom (a trapezoid with no segment above or
//! below) and the box's left or right side (no defining point: the map extends to
//! x = ±∞, so no bounding box is ever computed and every finite query is inside).
//!
//! ## Degeneracies (§6.3)
//!
//! The book removes the general-position assumption with the shear `(x, y) ↦ (x + εy, y)`:
//! points are ordered lexicographically (x, then y) and a vertical segment becomes an
//! ordinary one running from its lower to its upper end. The shear has determinant 1, so
//! "is r above segment s" is the exact orientation of `(s.left, s.right, r)` with
//! `s.left <_lex s.right`. Both tests are exact: coordinate comparisons, and an inline
//! floating-point filter for the orientation that falls back to
//! [`crate::kernel::orient2d`] (adaptive exact) when it cannot decide.
//!
//! Segments sharing endpoints: while inserting `s = (p, q)`, the search for `p` goes
//! right at an x-node holding `p` itself, and at a y-node of a segment through `p` it
//! compares the other endpoint `q` with that segment (the segment leaving `p` more
//! steeply is above). A query that hits an x-node's point exactly is reported as that
//! vertex; one on a y-node's segment (orientation zero) as that segment.
use crate::kernel::{orient2d, orient_exact, ExactPoint, Orientation, Point2};
use crate::{Error, Result};
use std::cmp::Ordering;

/// Marks "none": a missing neighbour, the box's top/bottom, the box's left/right side.
pub(crate) const NONE: u32 = u32::MAX;

/// A trapezoid record (§6.1): the segments above and below, the points defining its
/// left and right vertical sides, and its neighbours across those sides (the upper one
/// is across the part of the side above the defining point, the lower one below it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Trap {
    pub top: u32,
    pub bottom: u32,
    pub leftp: u32,
    pub rightp: u32,
    pub ul: u32,
    pub ll: u32,
    pub ur: u32,
    pub lr: u32,
}

impl Trap {
    fn new(top: u32, bottom: u32, leftp: u32, rightp: u32) -> Trap {
        Trap {
            top,
            bottom,
            leftp,
            rightp,
            ul: NONE,
            ll: NONE,
            ur: NONE,
            lr: NONE,
        }
    }
}

pub(crate) const LEAF: u32 = 0;
pub(crate) const XNODE: u32 = 1;
pub(crate) const YNODE: u32 = 2;

/// A node of the search structure. Leaf: `idx` is the trapezoid. X-node: `idx` is a
/// point, `a` the subtree left of it, `b` right. Y-node: `idx` is a segment, `a` the
/// subtree above it, `b` below. Children always have larger indices than their parent.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Node {
    pub kind: u32,
    pub idx: u32,
    pub a: u32,
    pub b: u32,
}

/// What a query hit in the core structure.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum CoreHit {
    Trap(u32),
    Seg(u32),
    Point(u32),
}

/// The trapezoidal map and its search structure over points and segments given by index.
#[derive(Debug, Clone, Default)]
pub(crate) struct Core {
    /// The points, rounded to `f64` where constructed.
    pub points: Vec<Point2>,
    /// The exact points when some are constructed (crossings), else empty: then every
    /// decision about the points uses the exact predicates of [`crate::kernel`].
    pub exact: Vec<ExactPoint>,
    /// Endpoints `[left, right]` in lexicographic order.
    pub segs: Vec<[u32; 2]>,
    pub traps: Vec<Trap>,
    /// The search structure as built (dropped by [`Core::freeze`]).
    pub nodes: Vec<Node>,
    /// The search structure laid out for queries.
    pub frozen: Frozen,
}

/// Lexicographic (x, then y) comparison: the x-order after the shear.
#[inline(always)]
pub(crate) fn lex(a: Point2, b: Point2) -> Ordering {
    if a.x < b.x {
        Ordering::Less
    } else if a.x > b.x {
        Ordering::Greater
    } else if a.y < b.y {
        Ordering::Less
    } else if a.y > b.y {
        Ordering::Greater
    } else {
        Ordering::Equal
    }
}

/// An orientation as an ordering: `Greater` is counter-clockwise (left, above).
#[inline]
pub(crate) fn ordering(o: Orientation) -> Ordering {
    match o {
        Orientation::CounterClockwise => Ordering::Greater,
        Orientation::Clockwise => Ordering::Less,
        Orientation::Collinear => Ordering::Equal,
    }
}

/// Exact orientation of `c` relative to the directed line `a → b`: `Greater` when `c` is
/// to the left (above, for `a <_lex b`). A floating-point filter (Shewchuk's first
/// error bound, valid while nothing under- or overflows) and the adaptive exact
/// predicate otherwise.
#[inline(always)]
pub(crate) fn orient(a: Point2, b: Point2, c: Point2) -> Ordering {
    let detl = (a.x - c.x) * (b.y - c.y);
    let detr = (a.y - c.y) * (b.x - c.x);
    let det = detl - detr;
    let sum = detl.abs() + detr.abs();
    // Far from underflow the relative bound holds; inf/NaN fail both tests.
    if sum > 1e-200 && sum < 1e300 {
        let bound = 3.330_669_073_875_472e-16 * sum;
        if det > bound {
            return Ordering::Greater;
        }
        if -det > bound {
            return Ordering::Less;
        }
    }
    ordering(orient2d(a, b, c))
}

fn broken(what: String) -> Error {
    Error::InvalidInput(format!(
        "the segments are not interior-disjoint ({what}); point location needs segments that meet only at common endpoints"
    ))
}

impl Core {
    /// Build the map of `segs` over `points`, inserting the segments in `order`.
    /// Preconditions (checked by the callers, exactly): points distinct and finite,
    /// each segment's endpoints distinct and lexicographically sorted, segments meeting
    /// only at common endpoints. A violated precondition met on the way gives an `Err`.
    pub fn build(
        points: Vec<Point2>,
        exact: Vec<ExactPoint>,
        segs: Vec<[u32; 2]>,
        order: &[u32],
    ) -> Result<Core> {
        let mut core = Core {
            points,
            exact,
            segs,
            traps: Vec::with_capacity(4 * order.len() + 1),
            nodes: Vec::with_capacity(8 * order.len() + 1),
            frozen: Frozen::default(),
        };
        core.traps.push(Trap::new(NONE, NONE, NONE, NONE));
        core.nodes.push(Node {
            kind: LEAF,
            idx: 0,
            a: NONE,
            b: NONE,
        });
        let mut b = Builder {
            leaf: vec![0],
            ds: Vec::new(),
            old: Vec::new(),
            up: Vec::new(),
            lo: Vec::new(),
        };
        for &s in order {
            core.insert(s, &mut b)?;
        }
        core.compact(&b.leaf);
        core.freeze();
        Ok(core)
    }

    /// Lexicographic comparison of points `a` and `b`, exact.
    #[inline]
    pub fn cmp(&self, a: u32, b: u32) -> Ordering {
        if self.exact.is_empty() {
            lex(self.points[a as usize], self.points[b as usize])
        } else {
            self.exact[a as usize].compare_xy(&self.exact[b as usize])
        }
    }

    /// Orientation of point `c` relative to the line from point `a` to point `b`, exact.
    #[inline]
    pub fn side(&self, a: u32, b: u32, c: u32) -> Ordering {
        if self.exact.is_empty() {
            let p = &self.points;
            orient(p[a as usize], p[b as usize], p[c as usize])
        } else {
            let e = &self.exact;
            ordering(orient_exact(&e[a as usize], &e[b as usize], &e[c as usize]))
        }
    }

    /// The trapezoid containing the point just to the right of `p` along segment `s`
    /// (whose left endpoint is `p` and right endpoint `q`).
    fn find_start(&self, p: u32, q: u32) -> Result<u32> {
        let mut n = 0usize;
        loop {
            let node = self.nodes[n];
            n = match node.kind {
                LEAF => return Ok(node.idx),
                XNODE => {
                    // Equal goes right: the segment leaves p to the right.
                    if self.cmp(p, node.idx) == Ordering::Less {
                        node.a
                    } else {
                        node.b
                    }
                }
                _ => {
                    let [l, r] = self.segs[node.idx as usize];
                    let side = match self.side(l, r, p) {
                        // p on the segment: a shared left endpoint; compare q instead.
                        Ordering::Equal => self.side(l, r, q),
                        o => o,
                    };
                    let (l, r) = (self.points[l as usize], self.points[r as usize]);
                    match side {
                        Ordering::Greater => node.a,
                        Ordering::Less => node.b,
                        Ordering::Equal => {
                            return Err(broken(format!(
                                "a segment overlaps segment from ({}, {}) to ({}, {})",
                                l.x, l.y, r.x, r.y
                            )))
                        }
                    }
                }
            } as usize;
        }
    }

    fn new_trap(&mut self, t: Trap, b: &mut Builder) -> u32 {
        self.traps.push(t);
        b.leaf.push(NONE);
        (self.traps.len() - 1) as u32
    }

    /// The leaf node of trapezoid `t`, created on first use.
    fn leaf_of(&mut self, t: u32, b: &mut Builder) -> u32 {
        if b.leaf[t as usize] == NONE {
            self.nodes.push(Node {
                kind: LEAF,
                idx: t,
                a: NONE,
                b: NONE,
            });
            b.leaf[t as usize] = (self.nodes.len() - 1) as u32;
        }
        b.leaf[t as usize]
    }

    fn push_node(&mut self, n: Node) -> u32 {
        self.nodes.push(n);
        (self.nodes.len() - 1) as u32
    }

    /// In trapezoid `t` (if any), make the right neighbours equal to `old` point to `new`.
    fn replace_right(&mut self, t: u32, old: u32, new: u32) {
        if t != NONE {
            let r = &mut self.traps[t as usize];
            if r.ur == old {
                r.ur = new;
            }
            if r.lr == old {
                r.lr = new;
            }
        }
    }

    /// In trapezoid `t` (if any), make the left neighbours equal to `old` point to `new`.
    fn replace_left(&mut self, t: u32, old: u32, new: u32) {
        if t != NONE {
            let r = &mut self.traps[t as usize];
            if r.ul == old {
                r.ul = new;
            }
            if r.ll == old {
                r.ll = new;
            }
        }
    }

    /// One step of TRAPEZOIDALMAP: add segment `s` to the map and to D.
    fn insert(&mut self, s: u32, b: &mut Builder) -> Result<()> {
        let [p, q] = self.segs[s as usize];
        // 1. FOLLOWSEGMENT: the trapezoids d0, ..., dk crossed by s.
        b.ds.clear();
        b.ds.push(self.find_start(p, q)?);
        loop {
            let t = self.traps[*b.ds.last().unwrap_or(&0) as usize];
            if t.rightp == NONE || self.cmp(q, t.rightp) != Ordering::Greater {
                break;
            }
            let r = self.points[t.rightp as usize];
            let next = match self.side(p, q, t.rightp) {
                Ordering::Greater => t.lr,
                Ordering::Less => t.ur,
                Ordering::Equal => {
                    return Err(broken(format!(
                        "a segment passes through the endpoint ({}, {})",
                        r.x, r.y
                    )))
                }
            };
            if next == NONE {
                return Err(broken(format!(
                    "a segment crosses another near ({}, {})",
                    r.x, r.y
                )));
            }
            b.ds.push(next);
        }
        b.old.clear();
        for &d in &b.ds {
            b.old.push(self.traps[d as usize]);
        }
        let k = b.ds.len();
        let (d0, dk) = (b.old[0], b.old[k - 1]);
        let (id0, idk) = (b.ds[0], b.ds[k - 1]);
        let has_a = d0.leftp != p;
        let has_b = dk.rightp != q;

        // 2. The new trapezoids. U and L: the current trapezoids above and below s.
        let mut u = self.new_trap(Trap::new(d0.top, s, p, NONE), b);
        let mut l = self.new_trap(Trap::new(s, d0.bottom, p, NONE), b);
        let a = if has_a {
            let mut at = Trap::new(d0.top, d0.bottom, d0.leftp, p);
            (at.ul, at.ll, at.ur, at.lr) = (d0.ul, d0.ll, u, l);
            let a = self.new_trap(at, b);
            self.replace_right(d0.ul, id0, a);
            self.replace_right(d0.ll, id0, a);
            self.traps[u as usize].ul = a;
            self.traps[l as usize].ll = a;
            a
        } else {
            // p was already a vertex: d0's left side is split at p.
            self.traps[u as usize].ul = d0.ul;
            self.replace_right(d0.ul, id0, u);
            self.traps[l as usize].ll = d0.ll;
            self.replace_right(d0.ll, id0, l);
            NONE
        };
        b.up.clear();
        b.lo.clear();
        b.up.push(u);
        b.lo.push(l);
        for i in 1..k {
            let (prev, cur) = (b.old[i - 1], b.old[i]);
            let (iprev, icur) = (b.ds[i - 1], b.ds[i]);
            let r = prev.rightp;
            if self.side(p, q, r) == Ordering::Greater {
                // r above s: its extension now stops at s, splitting the part above s;
                // the parts below s merge.
                let u2 = self.new_trap(Trap::new(cur.top, s, r, NONE), b);
                let ut = &mut self.traps[u as usize];
                (ut.rightp, ut.ur, ut.lr) = (r, prev.ur, u2);
                self.replace_left(prev.ur, iprev, u);
                let u2t = &mut self.traps[u2 as usize];
                (u2t.ul, u2t.ll) = (cur.ul, u);
                self.replace_right(cur.ul, icur, u2);
                u = u2;
            } else {
                let l2 = self.new_trap(Trap::new(s, cur.bottom, r, NONE), b);
                let lt = &mut self.traps[l as usize];
                (lt.rightp, lt.lr, lt.ur) = (r, prev.lr, l2);
                self.replace_left(prev.lr, iprev, l);
                let l2t = &mut self.traps[l2 as usize];
                (l2t.ll, l2t.ul) = (cur.ll, l);
                self.replace_right(cur.ll, icur, l2);
                l = l2;
            }
            b.up.push(u);
            b.lo.push(l);
        }
        self.traps[u as usize].rightp = q;
        self.traps[l as usize].rightp = q;
        let bt = if has_b {
            let mut bt = Trap::new(dk.top, dk.bottom, q, dk.rightp);
            (bt.ul, bt.ll, bt.ur, bt.lr) = (u, l, dk.ur, dk.lr);
            let bt = self.new_trap(bt, b);
            self.replace_left(dk.ur, idk, bt);
            self.replace_left(dk.lr, idk, bt);
            self.traps[u as usize].ur = bt;
            self.traps[l as usize].lr = bt;
            bt
        } else {
            self.traps[u as usize].ur = dk.ur;
            self.replace_left(dk.ur, idk, u);
            self.traps[l as usize].lr = dk.lr;
            self.replace_left(dk.lr, idk, l);
            NONE
        };

        // 3. D: each old leaf becomes the root of its replacement subtree.
        for i in 0..k {
            let slot = b.leaf[b.ds[i] as usize];
            let (ui, li) = (b.up[i], b.lo[i]);
            let above = self.leaf_of(ui, b);
            let below = self.leaf_of(li, b);
            let mut node = Node {
                kind: YNODE,
                idx: s,
                a: above,
                b: below,
            };
            if i == k - 1 && has_b {
                let inner = self.push_node(node);
                let right = self.leaf_of(bt, b);
                node = Node {
                    kind: XNODE,
                    idx: q,
                    a: inner,
                    b: right,
                };
            }
            if i == 0 && has_a {
                let inner = self.push_node(node);
                let left = self.leaf_of(a, b);
                node = Node {
                    kind: XNODE,
                    idx: p,
                    a: left,
                    b: inner,
                };
            }
            self.nodes[slot as usize] = node;
            b.leaf[b.ds[i] as usize] = NONE;
        }
        Ok(())
    }

    /// Drop the replaced trapezoids and renumber the living ones (those with a leaf).
    fn compact(&mut self, leaf: &[u32]) {
        let mut map = vec![NONE; self.traps.len()];
        let mut traps = Vec::with_capacity(self.traps.len() / 2);
        for (t, &n) in leaf.iter().enumerate() {
            if n != NONE {
                map[t] = traps.len() as u32;
                traps.push(self.traps[t]);
            }
        }
        let re = |x: u32| if x == NONE { NONE } else { map[x as usize] };
        for t in &mut traps {
            (t.ul, t.ll, t.ur, t.lr) = (re(t.ul), re(t.ll), re(t.ur), re(t.lr));
        }
        for n in &mut self.nodes {
            if n.kind == LEAF {
                n.idx = map[n.idx as usize];
            }
        }
        self.traps = traps;
    }

    /// Locate a finite query point: the trapezoid containing it, or the segment or
    /// vertex it lies on.
    #[inline]
    pub fn locate(&self, q: Point2) -> CoreHit {
        self.frozen.locate(q, &self.segs)
    }

    /// Lay D out for queries (see [`Frozen`]) and drop the construction's nodes.
    fn freeze(&mut self) {
        self.frozen = Frozen::new(self);
        self.nodes = Vec::new();
    }
}

/// Scratch space of the construction.
struct Builder {
    /// Leaf node of each trapezoid (`NONE` once replaced, or before first use).
    leaf: Vec<u32>,
    ds: Vec<u32>,
    old: Vec<Trap>,
    up: Vec<u32>,
    lo: Vec<u32>,
}

/// Child reference flag: a leaf, whose low 30 bits are the trapezoid.
const LEAF_REF: u32 = 1 << 31;
/// Flag in a node's `a`: the node is an x-node.
const X_FLAG: u32 = 1 << 30;
const REF_MASK: u32 = !X_FLAG;
/// Flag in a node's `b`: the node's point or segment has a constructed point, so the
/// node is decided by the exact predicates on [`ExactPoint`]s (its `c` is rounded).
const EXACT_FLAG: u32 = 1 << 30;

/// A node of the query layout: two child references (a leaf is folded into its
/// parent's reference, so a query never loads it) and the coordinates it tests inline:
/// an x-node's point in `c[0..2]`, a y-node's left and right endpoints in `c[0..4]`.
/// One node is one 40-byte record: about one cache miss per level.
#[derive(Debug, Clone, Copy, Default)]
struct QNode {
    a: u32,
    b: u32,
    c: [f64; 4],
}

/// D in depth-first preorder (a node's first child usually follows it), with the
/// statistics computed on the way.
#[derive(Debug, Clone, Default)]
pub(crate) struct Frozen {
    nodes: Vec<QNode>,
    /// The point (x-node) or segment (y-node) of each node, for reporting hits.
    item: Vec<u32>,
    root: u32,
    /// The exact points and the segments, kept only when some points are constructed.
    exact: Vec<ExactPoint>,
    segs: Vec<[u32; 2]>,
    /// Where to start the search, per cell of a uniform grid over the points.
    grid: Grid,
    pub x_nodes: usize,
    pub y_nodes: usize,
    /// The longest root-to-leaf path, in internal nodes.
    pub depth: usize,
}

impl Frozen {
    fn new(core: &Core) -> Frozen {
        let old = &core.nodes;
        if old.is_empty() {
            return Frozen::default();
        }
        let mut id = vec![NONE; old.len()];
        let mut order = Vec::new();
        // Iterative DFS: preorder numbering and postorder (for the depths).
        let mut post = Vec::new();
        let mut stack = vec![(0u32, false)];
        while let Some((n, done)) = stack.pop() {
            let node = old[n as usize];
            if node.kind == LEAF {
                continue;
            }
            if done {
                post.push(n);
                continue;
            }
            if id[n as usize] != NONE {
                continue;
            }
            id[n as usize] = order.len() as u32;
            order.push(n);
            stack.push((n, true));
            stack.push((node.b, false));
            stack.push((node.a, false));
        }
        let mut depth = vec![0u32; old.len()];
        for &n in &post {
            let node = old[n as usize];
            depth[n as usize] = 1 + depth[node.a as usize].max(depth[node.b as usize]);
        }
        let reference = |n: u32| {
            let node = old[n as usize];
            if node.kind == LEAF {
                LEAF_REF | node.idx
            } else {
                id[n as usize]
            }
        };
        let mut f = Frozen {
            nodes: Vec::with_capacity(order.len()),
            item: Vec::with_capacity(order.len()),
            root: reference(0),
            exact: core.exact.clone(),
            segs: if core.exact.is_empty() {
                Vec::new()
            } else {
                core.segs.clone()
            },
            grid: Grid::default(),
            x_nodes: 0,
            y_nodes: 0,
            depth: depth[0] as usize,
        };
        for &n in &order {
            let node = old[n as usize];
            let (a, mut b) = (reference(node.a), reference(node.b));
            let constructed =
                |p: u32| matches!(core.exact.get(p as usize), Some(ExactPoint::Crossing(_)));
            let flagged = if node.kind == XNODE {
                constructed(node.idx)
            } else {
                core.segs[node.idx as usize].into_iter().any(constructed)
            };
            if flagged {
                b |= EXACT_FLAG;
            }
            let q = if node.kind == XNODE {
                f.x_nodes += 1;
                let p = core.points[node.idx as usize];
                QNode {
                    a: a | X_FLAG,
                    b,
                    c: [p.x, p.y, 0.0, 0.0],
                }
            } else {
                f.y_nodes += 1;
                let [l, r] = core.segs[node.idx as usize];
                let (l, r) = (core.points[l as usize], core.points[r as usize]);
                QNode {
                    a,
                    b,
                    c: [l.x, l.y, r.x, r.y],
                }
            };
            f.nodes.push(q);
            f.item.push(node.idx);
        }
        f.grid = Grid::new(&f, &core.points, core.segs.len());
        f.relayout();
        f
    }

    /// Renumber the nodes for the queries' memory traffic: a query starts at its grid
    /// cell's node, so the nodes below each cell's start (in preorder) are stored
    /// together, cell after cell, and the nodes above every start come last.
    fn relayout(&mut self) {
        let n = self.nodes.len();
        if self.grid.start.is_empty() || n == 0 {
            return;
        }
        let mut id = vec![NONE; n];
        let mut order: Vec<u32> = Vec::with_capacity(n);
        let mut stack = Vec::new();
        let mut place = |from: u32, id: &mut Vec<u32>, order: &mut Vec<u32>| {
            stack.push(from);
            while let Some(r) = stack.pop() {
                if r & LEAF_REF != 0 || id[r as usize] != NONE {
                    continue;
                }
                id[r as usize] = order.len() as u32;
                order.push(r);
                let node = &self.nodes[r as usize];
                stack.push(node.b & !EXACT_FLAG);
                stack.push(node.a & REF_MASK);
            }
        };
        let mut last = NONE;
        for &s in &self.grid.start {
            if s != last {
                place(s, &mut id, &mut order);
                last = s;
            }
        }
        place(self.root, &mut id, &mut order);
        let re = |r: u32| if r & LEAF_REF != 0 { r } else { id[r as usize] };
        let nodes = order
            .iter()
            .map(|&o| {
                let q = self.nodes[o as usize];
                QNode {
                    a: re(q.a & REF_MASK) | (q.a & X_FLAG),
                    b: re(q.b & !EXACT_FLAG) | (q.b & EXACT_FLAG),
                    c: q.c,
                }
            })
            .collect();
        self.item = order.iter().map(|&o| self.item[o as usize]).collect();
        self.nodes = nodes;
        self.root = re(self.root);
        for s in &mut self.grid.start {
            *s = re(*s);
        }
    }

    /// The deepest node on the common search path, below `from`, of every point of the
    /// closed box `[x0, x1] × [y0, y1]` (whose points all reach `from`), and the number
    /// of nodes passed: below it, points of the box part ways. Exact: an x-node is
    /// passed when the box is strictly on one side of its vertical line, a y-node when
    /// all four corners are strictly on one side of its segment's line (then, by
    /// convexity, so is the whole box).
    fn common_start(&self, from: u32, x0: f64, x1: f64, y0: f64, y1: f64) -> (u32, usize) {
        let (mut r, mut steps) = (from, 0);
        while r & LEAF_REF == 0 {
            let n = &self.nodes[r as usize];
            if n.b & EXACT_FLAG != 0 {
                match self.exact_box_step(r, x0, x1, y0, y1) {
                    Some(next) => r = next,
                    None => break,
                }
                steps += 1;
                continue;
            }
            r = if n.a & X_FLAG != 0 {
                if x1 < n.c[0] {
                    n.a & REF_MASK
                } else if x0 > n.c[0] {
                    n.b
                } else {
                    break;
                }
            } else {
                let (l, rp) = (Point2::new(n.c[0], n.c[1]), Point2::new(n.c[2], n.c[3]));
                let first = orient(l, rp, Point2::new(x0, y0));
                let same = first != Ordering::Equal
                    && [(x1, y0), (x0, y1), (x1, y1)]
                        .iter()
                        .all(|&(x, y)| orient(l, rp, Point2::new(x, y)) == first);
                match (same, first) {
                    (true, Ordering::Greater) => n.a,
                    (true, _) => n.b,
                    _ => break,
                }
            };
            steps += 1;
        }
        (r, steps)
    }

    /// [`Frozen::common_start`]'s step at a node with constructed points: the child
    /// every point of the box goes to, if they all go the same way.
    #[cold]
    fn exact_box_step(&self, r: u32, x0: f64, x1: f64, y0: f64, y1: f64) -> Option<u32> {
        let n = &self.nodes[r as usize];
        let item = self.item[r as usize] as usize;
        let corners = [(x0, y0), (x1, y0), (x0, y1), (x1, y1)];
        let sides: Vec<Ordering> = if n.a & X_FLAG != 0 {
            let p = &self.exact[item];
            corners
                .iter()
                .map(|&(x, y)| ExactPoint::Input(Point2::new(x, y)).compare_x(p))
                .collect()
        } else {
            let [l, rp] = self.segs[item];
            let (l, rp) = (&self.exact[l as usize], &self.exact[rp as usize]);
            corners
                .iter()
                .map(|&(x, y)| {
                    // Above the segment is the first child, like "left of" an x-node.
                    ordering(orient_exact(l, rp, &ExactPoint::Input(Point2::new(x, y)))).reverse()
                })
                .collect()
        };
        match sides[0] {
            Ordering::Equal => None,
            o if sides.iter().any(|&x| x != o) => None,
            Ordering::Less => Some(n.a & REF_MASK),
            _ => Some(n.b & !EXACT_FLAG),
        }
    }

    /// A query's step at a node with constructed points: the child it goes to, or what
    /// it hit.
    #[cold]
    fn exact_step(&self, r: u32, q: Point2) -> std::result::Result<u32, CoreHit> {
        let n = &self.nodes[r as usize];
        let item = self.item[r as usize];
        let qe = ExactPoint::Input(q);
        if n.a & X_FLAG != 0 {
            return match qe.compare_xy(&self.exact[item as usize]) {
                Ordering::Less => Ok(n.a & REF_MASK),
                Ordering::Greater => Ok(n.b & !EXACT_FLAG),
                Ordering::Equal => Err(CoreHit::Point(item)),
            };
        }
        let [li, ri] = self.segs[item as usize];
        let (l, rp) = (&self.exact[li as usize], &self.exact[ri as usize]);
        match ordering(orient_exact(l, rp, &qe)) {
            Ordering::Greater => Ok(n.a),
            Ordering::Less => Ok(n.b & !EXACT_FLAG),
            Ordering::Equal => Err(if qe.compare_xy(l) == Ordering::Equal {
                CoreHit::Point(li)
            } else if qe.compare_xy(rp) == Ordering::Equal {
                CoreHit::Point(ri)
            } else {
                CoreHit::Seg(item)
            }),
        }
    }

    /// Every trapezoid referenced by a leaf, with repetitions (for validation).
    pub fn leaves(&self) -> Vec<u32> {
        let mut out: Vec<u32> = self
            .nodes
            .iter()
            .flat_map(|n| [n.a & REF_MASK, n.b & !EXACT_FLAG])
            .filter(|r| r & LEAF_REF != 0)
            .map(|r| r & !LEAF_REF)
            .collect();
        if self.root & LEAF_REF != 0 || self.nodes.is_empty() {
            out.push(self.root & !LEAF_REF);
        }
        out
    }

    #[inline]
    fn locate(&self, q: Point2, segs: &[[u32; 2]]) -> CoreHit {
        let nodes = &self.nodes[..];
        let mut r = self.grid.start(q).unwrap_or(self.root);
        while r & LEAF_REF == 0 {
            let n = &nodes[r as usize];
            if n.b & EXACT_FLAG != 0 {
                match self.exact_step(r, q) {
                    Ok(next) => r = next,
                    Err(hit) => return hit,
                }
                continue;
            }
            let next = if n.a & X_FLAG != 0 {
                match lex(q, Point2::new(n.c[0], n.c[1])) {
                    Ordering::Less => n.a & REF_MASK,
                    Ordering::Greater => n.b,
                    Ordering::Equal => return CoreHit::Point(self.item[r as usize]),
                }
            } else {
                let (l, rp) = (Point2::new(n.c[0], n.c[1]), Point2::new(n.c[2], n.c[3]));
                match orient(l, rp, q) {
                    Ordering::Greater => n.a,
                    Ordering::Less => n.b,
                    Ordering::Equal => {
                        // Within the segment's x-range and on its line.
                        let s = self.item[r as usize];
                        let [li, ri] = segs[s as usize];
                        return if q == l {
                            CoreHit::Point(li)
                        } else if q == rp {
                            CoreHit::Point(ri)
                        } else {
                            CoreHit::Seg(s)
                        };
                    }
                }
            };
            r = next;
        }
        CoreHit::Trap(r & !LEAF_REF)
    }
}

/// A uniform grid over the points' bounding box giving, per cell, the node where the
/// searches of all the cell's points part ways ([`Frozen::common_start`]): a query
/// skips the top of D. The cell bounds are stored; a query uses a cell only after
/// checking, exactly, that it lies in the cell's closed box (else it starts at the root).
#[derive(Debug, Clone, Default)]
struct Grid {
    xs: Vec<f64>,
    ys: Vec<f64>,
    inv_w: f64,
    inv_h: f64,
    start: Vec<u32>,
}

impl Grid {
    /// The grid of a search structure over `points` (the segments' endpoints). The
    /// early levels of D are dominated by the long vertical extensions of the first
    /// endpoints, so square cells are split early; cells taller than wide start
    /// deeper. The aspect ratio is chosen by trying a few on a coarse grid and keeping
    /// the one whose cells start deepest on average; the final grid has about eight
    /// cells per segment (4 bytes each).
    fn new(f: &Frozen, points: &[Point2], segments: usize) -> Grid {
        if segments < 64 || points.is_empty() {
            return Grid::default();
        }
        let (mut lo, mut hi) = (points[0], points[0]);
        for p in points {
            lo = Point2::new(lo.x.min(p.x), lo.y.min(p.y));
            hi = Point2::new(hi.x.max(p.x), hi.y.max(p.y));
        }
        let (w, h) = (hi.x - lo.x, hi.y - lo.y);
        if !(w > 0.0 && h > 0.0 && w.is_finite() && h.is_finite()) {
            return Grid::default();
        }
        let n = segments as f64;
        let mut best = (f64::MIN, 1.0);
        for aspect in [1.0, 4.0, 16.0, 64.0, 256.0, 1024.0] {
            let (_, mean) = Self::build(f, lo, w, h, n, aspect);
            if mean > best.0 {
                best = (mean, aspect);
            }
        }
        Self::build(f, lo, w, h, 8.0 * n, best.1).0
    }

    /// A grid of about `cells` cells over the box at `lo` of size `w × h`, cells
    /// `aspect` times taller than wide (relative to the box), and the mean depth of
    /// its cells' start nodes.
    fn build(f: &Frozen, lo: Point2, w: f64, h: f64, cells: f64, aspect: f64) -> (Grid, f64) {
        let nx = ((cells * aspect * w / h).sqrt().ceil() as usize).clamp(1, 1 << 16);
        let ny = ((cells / aspect * h / w).sqrt().ceil() as usize).clamp(1, 1 << 16);
        let xs: Vec<f64> = (0..=nx)
            .map(|i| lo.x + w * (i as f64 / nx as f64))
            .collect();
        let ys: Vec<f64> = (0..=ny)
            .map(|j| lo.y + h * (j as f64 / ny as f64))
            .collect();
        let mut start = vec![NONE; nx * ny];
        let mut total = 0usize;
        // Coarse to fine: a block's common path is a prefix of each of its cells' paths.
        let mut stack = vec![(0usize, nx, 0usize, ny, f.root, 0usize)];
        while let Some((i0, i1, j0, j1, from, depth)) = stack.pop() {
            let (r, steps) = f.common_start(from, xs[i0], xs[i1], ys[j0], ys[j1]);
            let depth = depth + steps;
            if (i1 - i0 == 1 && j1 - j0 == 1) || r & LEAF_REF != 0 {
                for j in j0..j1 {
                    start[j * nx + i0..j * nx + i1].fill(r);
                }
                total += depth * (i1 - i0) * (j1 - j0);
            } else if i1 - i0 >= j1 - j0 {
                let m = (i0 + i1) / 2;
                stack.push((i0, m, j0, j1, r, depth));
                stack.push((m, i1, j0, j1, r, depth));
            } else {
                let m = (j0 + j1) / 2;
                stack.push((i0, i1, j0, m, r, depth));
                stack.push((i0, i1, m, j1, r, depth));
            }
        }
        let grid = Grid {
            inv_w: nx as f64 / w,
            inv_h: ny as f64 / h,
            xs,
            ys,
            start,
        };
        (grid, total as f64 / (nx * ny) as f64)
    }

    /// The start node for `q`, if `q` is (exactly) inside the cell its coordinates round to.
    #[inline(always)]
    fn start(&self, q: Point2) -> Option<u32> {
        let (nx, ny) = (self.xs.len().checked_sub(1)?, self.ys.len().checked_sub(1)?);
        let fx = (q.x - self.xs[0]) * self.inv_w;
        let fy = (q.y - self.ys[0]) * self.inv_h;
        if !(fx >= 0.0 && fy >= 0.0) {
            return None;
        }
        let (i, j) = ((fx as usize).min(nx - 1), (fy as usize).min(ny - 1));
        if self.xs[i] <= q.x && q.x <= self.xs[i + 1] && self.ys[j] <= q.y && q.y <= self.ys[j + 1]
        {
            Some(self.start[j * nx + i])
        } else {
            None
        }
    }
}
