//! The beach line of Fortune's sweep: the sequence of parabolic arcs, left to right, kept
//! in a balanced binary search tree (a treap: a search tree on the arcs' order with random
//! heap priorities, expected depth O(log n)) whose nodes are also linked as a doubly-linked
//! list for O(1) neighbours.
//!
//! The tree stores the arcs themselves (the book stores arcs in the leaves and breakpoints
//! in the inner nodes; an arc node with its right neighbour gives the breakpoint to its
//! right, which is the same information). The order of arcs never changes during the sweep
//! (arcs are only inserted and removed), so no key is stored: [`BeachLine::locate`] descends
//! by comparing the new site with one breakpoint per node, decided exactly by the caller's
//! predicate.
//!
//! Layout: nodes live in one arena with `u32` links and a free list (a removed arc's slot is
//! reused by the next insertion), and each node carries its site's coordinates, so a descent
//! touches only the few hundred to few thousand live nodes and never the site array.

use crate::kernel::Point2;

/// "No node" (also "no edge", "no event" in the sweep's `u32` fields).
pub(crate) const NIL: u32 = u32::MAX;

/// One arc of the beach line.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Arc {
    /// The site (index into the distinct sites) whose parabola this arc is part of.
    pub site: u32,
    /// The half-edge (face = `site`) traced by the breakpoint between this arc and the
    /// next one, or [`NIL`] for the last arc.
    pub right_edge: u32,
    /// The pending circle event in which this arc would disappear, or [`NIL`].
    pub event: u32,
    /// The site's coordinates (a copy, so that a descent reads no other array).
    pub p: Point2,
}

#[derive(Debug, Clone)]
struct Node {
    arc: Arc,
    left: u32,
    right: u32,
    parent: u32,
    prev: u32,
    next: u32,
    prio: u32,
}

/// The beach line: a treap of arcs plus neighbour links.
#[derive(Debug, Clone)]
pub(crate) struct BeachLine {
    nodes: Vec<Node>,
    free: Vec<u32>,
    root: u32,
    rng: u64,
}

impl BeachLine {
    /// An empty beach line.
    pub(crate) fn new() -> Self {
        BeachLine {
            nodes: Vec::new(),
            free: Vec::new(),
            root: NIL,
            rng: 0x9E37_79B9_7F4A_7C15,
        }
    }

    /// True before the first site.
    pub(crate) fn is_empty(&self) -> bool {
        self.root == NIL
    }

    #[inline]
    fn node(&self, id: u32) -> &Node {
        &self.nodes[id as usize]
    }

    #[inline]
    fn node_mut(&mut self, id: u32) -> &mut Node {
        &mut self.nodes[id as usize]
    }

    /// The arc of node `id`.
    #[inline]
    pub(crate) fn arc(&self, id: u32) -> &Arc {
        &self.node(id).arc
    }

    /// The arc of node `id`, mutably.
    #[inline]
    pub(crate) fn arc_mut(&mut self, id: u32) -> &mut Arc {
        &mut self.node_mut(id).arc
    }

    /// The arc to the left of `id`, or [`NIL`].
    #[inline]
    pub(crate) fn prev(&self, id: u32) -> u32 {
        self.node(id).prev
    }

    /// The arc to the right of `id`, or [`NIL`].
    #[inline]
    pub(crate) fn next(&self, id: u32) -> u32 {
        self.node(id).next
    }

    /// The arcs from left to right (for pictures and tests).
    pub(crate) fn arcs(&self) -> Vec<Arc> {
        let mut out = Vec::new();
        let mut x = self.root;
        if x == NIL {
            return out;
        }
        while self.node(x).left != NIL {
            x = self.node(x).left;
        }
        while x != NIL {
            out.push(self.node(x).arc);
            x = self.node(x).next;
        }
        out
    }

    fn priority(&mut self) -> u32 {
        // xorshift64*: deterministic, so runs are reproducible.
        self.rng ^= self.rng >> 12;
        self.rng ^= self.rng << 25;
        self.rng ^= self.rng >> 27;
        (self.rng.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 32) as u32
    }

    fn alloc(&mut self, arc: Arc) -> u32 {
        let prio = self.priority();
        let node = Node {
            arc,
            left: NIL,
            right: NIL,
            parent: NIL,
            prev: NIL,
            next: NIL,
            prio,
        };
        match self.free.pop() {
            Some(id) => {
                self.nodes[id as usize] = node;
                id
            }
            None => {
                self.nodes.push(node);
                (self.nodes.len() - 1) as u32
            }
        }
    }

    /// The first arc, when the beach line is empty.
    pub(crate) fn insert_first(&mut self, arc: Arc) -> u32 {
        let n = self.alloc(arc);
        self.root = n;
        n
    }

    /// Insert `arc` immediately to the right of node `at`; returns the new node.
    pub(crate) fn insert_after(&mut self, at: u32, arc: Arc) -> u32 {
        let n = self.alloc(arc);
        if self.node(at).right == NIL {
            self.node_mut(at).right = n;
            self.node_mut(n).parent = at;
        } else {
            let mut m = self.node(at).right;
            while self.node(m).left != NIL {
                m = self.node(m).left;
            }
            self.node_mut(m).left = n;
            self.node_mut(n).parent = m;
        }
        let after = self.node(at).next;
        self.node_mut(n).prev = at;
        self.node_mut(n).next = after;
        self.node_mut(at).next = n;
        if after != NIL {
            self.node_mut(after).prev = n;
        }
        while self.node(n).parent != NIL && self.node(n).prio > self.node(self.node(n).parent).prio
        {
            self.rotate_up(n);
        }
        n
    }

    /// Remove node `x` from the beach line (its slot is reused later).
    pub(crate) fn remove(&mut self, x: u32) {
        loop {
            let (l, r) = (self.node(x).left, self.node(x).right);
            let c = match (l, r) {
                (NIL, NIL) => break,
                (c, NIL) | (NIL, c) => c,
                (l, r) => {
                    if self.node(l).prio > self.node(r).prio {
                        l
                    } else {
                        r
                    }
                }
            };
            self.rotate_up(c);
        }
        let p = self.node(x).parent;
        if p == NIL {
            self.root = NIL;
        } else if self.node(p).left == x {
            self.node_mut(p).left = NIL;
        } else {
            self.node_mut(p).right = NIL;
        }
        let (pv, nx) = (self.node(x).prev, self.node(x).next);
        if pv != NIL {
            self.node_mut(pv).next = nx;
        }
        if nx != NIL {
            self.node_mut(nx).prev = pv;
        }
        let node = self.node_mut(x);
        node.parent = NIL;
        node.prev = NIL;
        node.next = NIL;
        node.arc.event = NIL;
        self.free.push(x);
    }

    /// Rotate `x` above its parent.
    fn rotate_up(&mut self, x: u32) {
        let p = self.node(x).parent;
        let g = self.node(p).parent;
        if self.node(p).left == x {
            let b = self.node(x).right;
            self.node_mut(p).left = b;
            if b != NIL {
                self.node_mut(b).parent = p;
            }
            self.node_mut(x).right = p;
        } else {
            let b = self.node(x).left;
            self.node_mut(p).right = b;
            if b != NIL {
                self.node_mut(b).parent = p;
            }
            self.node_mut(x).left = p;
        }
        self.node_mut(p).parent = x;
        self.node_mut(x).parent = g;
        if g == NIL {
            self.root = x;
        } else if self.node(g).left == p {
            self.node_mut(g).left = x;
        } else {
            self.node_mut(g).right = x;
        }
    }

    /// The arc above a new site: the leftmost arc whose right breakpoint the site is
    /// strictly left of (the last arc if none). `left_of(a, b)` says whether the new site
    /// is strictly left of the breakpoint between the arcs `a` (left) and `b` (right); it
    /// is monotone along the beach line (false, …, false, true, …, true), so the descent
    /// is a lower-bound search with one breakpoint test per level. A site exactly under a
    /// breakpoint goes to the right.
    pub(crate) fn locate(&self, mut left_of: impl FnMut(&Arc, &Arc) -> bool) -> u32 {
        let mut x = self.root;
        let mut best = NIL;
        let mut last = NIL;
        while x != NIL {
            let node = self.node(x);
            last = x;
            if node.next != NIL && !left_of(&node.arc, &self.node(node.next).arc) {
                x = node.right;
            } else {
                best = x;
                x = node.left;
            }
        }
        if best == NIL {
            // Only reached if every breakpoint is left of the site: `last` is the last arc.
            last
        } else {
            best
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn arc(site: u32) -> Arc {
        Arc {
            site,
            right_edge: NIL,
            event: NIL,
            p: Point2::new(site as f64, 0.0),
        }
    }

    #[test]
    fn inserts_and_removes_keep_order() {
        let mut b = BeachLine::new();
        let first = b.insert_first(arc(0));
        let mut ids = vec![first];
        for round in 0..3u32 {
            for s in 1..200u32 {
                let at = ids[(s as usize * 7919) % ids.len()];
                let n = b.insert_after(at, arc(s + 1000 * round));
                let pos = ids.iter().position(|&i| i == at).unwrap();
                ids.insert(pos + 1, n);
            }
            for k in 0..150usize {
                let i = (k * 31) % ids.len();
                b.remove(ids[i]);
                ids.remove(i);
            }
        }
        let want: Vec<u32> = ids.iter().map(|&i| b.arc(i).site).collect();
        let got: Vec<u32> = b.arcs().iter().map(|a| a.site).collect();
        assert_eq!(got, want);
        // Slots were reused: fewer nodes than insertions.
        assert!(b.nodes.len() < 3 * 200);
        // locate by position: for every rank, find the arc of that rank.
        let rank = |site: u32| want.iter().position(|&s| s == site).unwrap();
        for target in 0..want.len() {
            let found = b.locate(|l, _r| rank(l.site) >= target);
            assert_eq!(rank(b.arc(found).site), target);
        }
    }
}
