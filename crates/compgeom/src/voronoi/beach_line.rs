//! The beach line of Fortune's sweep: the sequence of parabolic arcs, left to right, kept
//! in a balanced binary search tree (a treap: a search tree on the arcs' order with random
//! heap priorities, expected depth O(log n)) whose nodes are also linked as a doubly-linked
//! list for O(1) neighbours.
//!
//! The tree stores the arcs themselves (the book stores arcs in the leaves and breakpoints
//! in the inner nodes; an arc node with its two neighbours gives both of its breakpoints,
//! which is the same information). The order of arcs never changes during the sweep
//! (arcs are only inserted and removed), so no key is stored: [`BeachLine::locate`] descends
//! by comparing the new site with the breakpoints at each node, decided exactly by the
//! caller's predicate.

/// "No node".
pub(crate) const NIL: usize = usize::MAX;

/// One arc of the beach line.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Arc {
    /// The site (index into the distinct sites) whose parabola this arc is part of.
    pub site: usize,
    /// The half-edge (face = `site`) traced by the breakpoint between this arc and the
    /// next one, or [`NIL`] for the last arc.
    pub right_edge: usize,
    /// The pending circle event in which this arc would disappear, or [`NIL`].
    pub event: usize,
}

#[derive(Debug, Clone)]
struct Node {
    arc: Arc,
    left: usize,
    right: usize,
    parent: usize,
    prev: usize,
    next: usize,
    prio: u64,
}

/// The beach line: a treap of arcs plus neighbour links.
#[derive(Debug, Clone)]
pub(crate) struct BeachLine {
    nodes: Vec<Node>,
    root: usize,
    rng: u64,
}

impl BeachLine {
    /// An empty beach line.
    pub(crate) fn new() -> Self {
        BeachLine {
            nodes: Vec::new(),
            root: NIL,
            rng: 0x9E37_79B9_7F4A_7C15,
        }
    }

    /// True before the first site.
    pub(crate) fn is_empty(&self) -> bool {
        self.root == NIL
    }

    /// The arc of node `id`.
    pub(crate) fn arc(&self, id: usize) -> &Arc {
        &self.nodes[id].arc
    }

    /// The arc of node `id`, mutably.
    pub(crate) fn arc_mut(&mut self, id: usize) -> &mut Arc {
        &mut self.nodes[id].arc
    }

    /// The arc to the left of `id`, or [`NIL`].
    pub(crate) fn prev(&self, id: usize) -> usize {
        self.nodes[id].prev
    }

    /// The arc to the right of `id`, or [`NIL`].
    pub(crate) fn next(&self, id: usize) -> usize {
        self.nodes[id].next
    }

    /// The arcs from left to right (for pictures and tests).
    pub(crate) fn arcs(&self) -> Vec<Arc> {
        let mut out = Vec::new();
        let mut x = self.root;
        if x == NIL {
            return out;
        }
        while self.nodes[x].left != NIL {
            x = self.nodes[x].left;
        }
        while x != NIL {
            out.push(self.nodes[x].arc);
            x = self.nodes[x].next;
        }
        out
    }

    fn priority(&mut self) -> u64 {
        // xorshift64*: deterministic, so runs are reproducible.
        self.rng ^= self.rng >> 12;
        self.rng ^= self.rng << 25;
        self.rng ^= self.rng >> 27;
        self.rng.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    fn alloc(&mut self, arc: Arc) -> usize {
        let prio = self.priority();
        self.nodes.push(Node {
            arc,
            left: NIL,
            right: NIL,
            parent: NIL,
            prev: NIL,
            next: NIL,
            prio,
        });
        self.nodes.len() - 1
    }

    /// The first arc, when the beach line is empty.
    pub(crate) fn insert_first(&mut self, arc: Arc) -> usize {
        let n = self.alloc(arc);
        self.root = n;
        n
    }

    /// Insert `arc` immediately to the right of node `at`; returns the new node.
    pub(crate) fn insert_after(&mut self, at: usize, arc: Arc) -> usize {
        let n = self.alloc(arc);
        if self.nodes[at].right == NIL {
            self.nodes[at].right = n;
            self.nodes[n].parent = at;
        } else {
            let mut m = self.nodes[at].right;
            while self.nodes[m].left != NIL {
                m = self.nodes[m].left;
            }
            self.nodes[m].left = n;
            self.nodes[n].parent = m;
        }
        let after = self.nodes[at].next;
        self.nodes[n].prev = at;
        self.nodes[n].next = after;
        self.nodes[at].next = n;
        if after != NIL {
            self.nodes[after].prev = n;
        }
        while self.nodes[n].parent != NIL
            && self.nodes[n].prio > self.nodes[self.nodes[n].parent].prio
        {
            self.rotate_up(n);
        }
        n
    }

    /// Remove node `x` from the beach line.
    pub(crate) fn remove(&mut self, x: usize) {
        loop {
            let (l, r) = (self.nodes[x].left, self.nodes[x].right);
            let c = match (l, r) {
                (NIL, NIL) => break,
                (c, NIL) | (NIL, c) => c,
                (l, r) => {
                    if self.nodes[l].prio > self.nodes[r].prio {
                        l
                    } else {
                        r
                    }
                }
            };
            self.rotate_up(c);
        }
        let p = self.nodes[x].parent;
        if p == NIL {
            self.root = NIL;
        } else if self.nodes[p].left == x {
            self.nodes[p].left = NIL;
        } else {
            self.nodes[p].right = NIL;
        }
        let (pv, nx) = (self.nodes[x].prev, self.nodes[x].next);
        if pv != NIL {
            self.nodes[pv].next = nx;
        }
        if nx != NIL {
            self.nodes[nx].prev = pv;
        }
        self.nodes[x].parent = NIL;
        self.nodes[x].prev = NIL;
        self.nodes[x].next = NIL;
    }

    /// Rotate `x` above its parent.
    fn rotate_up(&mut self, x: usize) {
        let p = self.nodes[x].parent;
        let g = self.nodes[p].parent;
        if self.nodes[p].left == x {
            let b = self.nodes[x].right;
            self.nodes[p].left = b;
            if b != NIL {
                self.nodes[b].parent = p;
            }
            self.nodes[x].right = p;
        } else {
            let b = self.nodes[x].left;
            self.nodes[p].right = b;
            if b != NIL {
                self.nodes[b].parent = p;
            }
            self.nodes[x].left = p;
        }
        self.nodes[p].parent = x;
        self.nodes[x].parent = g;
        if g == NIL {
            self.root = x;
        } else if self.nodes[g].left == p {
            self.nodes[g].left = x;
        } else {
            self.nodes[g].right = x;
        }
    }

    /// The arc above a new site: descend from the root; `left_of(a, b)` says whether the
    /// new site is strictly left of the breakpoint between arcs of sites `a` (left) and
    /// `b` (right). A site exactly under a breakpoint goes to the right.
    pub(crate) fn locate(&self, mut left_of: impl FnMut(usize, usize) -> bool) -> usize {
        let mut x = self.root;
        loop {
            let node = &self.nodes[x];
            if node.prev != NIL && left_of(self.nodes[node.prev].arc.site, node.arc.site) {
                if node.left == NIL {
                    return x;
                }
                x = node.left;
            } else if node.next != NIL && !left_of(node.arc.site, self.nodes[node.next].arc.site) {
                if node.right == NIL {
                    return x;
                }
                x = node.right;
            } else {
                return x;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn arc(site: usize) -> Arc {
        Arc {
            site,
            right_edge: NIL,
            event: NIL,
        }
    }

    #[test]
    fn inserts_and_removes_keep_order() {
        let mut b = BeachLine::new();
        let first = b.insert_first(arc(0));
        let mut ids = vec![first];
        for s in 1..200 {
            let at = ids[(s * 7919) % ids.len()];
            let n = b.insert_after(at, arc(s));
            let pos = ids.iter().position(|&i| i == at).unwrap();
            ids.insert(pos + 1, n);
        }
        for k in 0..100 {
            let i = (k * 31) % ids.len();
            b.remove(ids[i]);
            ids.remove(i);
        }
        let want: Vec<usize> = ids.iter().map(|&i| b.arc(i).site).collect();
        let got: Vec<usize> = b.arcs().iter().map(|a| a.site).collect();
        assert_eq!(got, want);
        // locate by position: find the arc whose rank is 37.
        let target = 37;
        let rank = |site: usize| want.iter().position(|&s| s == site).unwrap();
        let found = b.locate(|l, _r| rank(l) >= target);
        assert_eq!(rank(b.arc(found).site), target);
    }
}
