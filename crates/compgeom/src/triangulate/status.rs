//! The sweep status of MAKEMONOTONE: the polygon edges crossing the sweep line, left to
//! right, in a treap (a randomized balanced search tree, O(log n) expected per operation).
//!
//! Nodes live in an arena indexed by edge (edge `u` runs from vertex `u` to its boundary
//! successor), with parent links so an edge is removed by its index, without any
//! geometric search. Searches compare a query vertex with a node's edge by one exact
//! orientation test; the comparisons are passed in by the sweep.
use super::geometry::NONE;

#[derive(Clone, Copy)]
struct Node {
    left: u32,
    right: u32,
    parent: u32,
    priority: u32,
}

/// The status tree.
pub(crate) struct Status {
    nodes: Vec<Node>,
    root: u32,
    seed: u32,
}

/// Where a query lies relative to a node's edge.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Side {
    /// Left of the edge.
    Left,
    /// Right of the edge.
    Right,
    /// Neither (the caller treats this as an error).
    On,
}

impl Status {
    /// An empty status for edges `0..n`.
    pub fn new(n: usize) -> Status {
        Status {
            nodes: vec![
                Node {
                    left: NONE,
                    right: NONE,
                    parent: NONE,
                    priority: 0,
                };
                n
            ],
            root: NONE,
            seed: 0x9E37_79B9,
        }
    }

    fn random(&mut self) -> u32 {
        // xorshift32: a fixed seed keeps runs reproducible.
        let mut x = self.seed;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        self.seed = x;
        x
    }

    /// The rightmost edge that `side` says lies left of the query (the query is to its
    /// right), if any.
    pub fn left_of(&self, mut side: impl FnMut(u32) -> Side) -> Result<Option<u32>, u32> {
        let mut t = self.root;
        let mut best = None;
        while t != NONE {
            match side(t) {
                Side::Right => {
                    best = Some(t);
                    t = self.nodes[t as usize].right;
                }
                Side::Left => t = self.nodes[t as usize].left,
                Side::On => return Err(t),
            }
        }
        Ok(best)
    }

    /// Insert edge `e`; `side(t)` says on which side of edge `t` the new edge lies.
    pub fn insert(&mut self, e: u32, mut side: impl FnMut(u32) -> Side) -> Result<(), u32> {
        let priority = self.random();
        let mut parent = NONE;
        let mut go_right = false;
        let mut t = self.root;
        while t != NONE {
            parent = t;
            match side(t) {
                Side::Right => {
                    go_right = true;
                    t = self.nodes[t as usize].right;
                }
                Side::Left => {
                    go_right = false;
                    t = self.nodes[t as usize].left;
                }
                Side::On => return Err(t),
            }
        }
        self.nodes[e as usize] = Node {
            left: NONE,
            right: NONE,
            parent,
            priority,
        };
        if parent == NONE {
            self.root = e;
        } else if go_right {
            self.nodes[parent as usize].right = e;
        } else {
            self.nodes[parent as usize].left = e;
        }
        // Restore the heap order on priorities.
        loop {
            let p = self.nodes[e as usize].parent;
            if p == NONE || self.nodes[p as usize].priority <= priority {
                break;
            }
            self.rotate_up(e);
        }
        Ok(())
    }

    /// The edges just left and right of edge `e` (in the tree).
    pub fn neighbours(&self, e: u32) -> (u32, u32) {
        (self.step(e, true), self.step(e, false))
    }

    /// The in-order predecessor (`left`) or successor of `e`, or `NONE`.
    fn step(&self, e: u32, left: bool) -> u32 {
        let down = |n: &Node| if left { n.left } else { n.right };
        let up = |n: &Node| if left { n.right } else { n.left };
        let mut t = down(&self.nodes[e as usize]);
        if t != NONE {
            while up(&self.nodes[t as usize]) != NONE {
                t = up(&self.nodes[t as usize]);
            }
            return t;
        }
        let mut c = e;
        let mut p = self.nodes[e as usize].parent;
        while p != NONE && down(&self.nodes[p as usize]) == c {
            c = p;
            p = self.nodes[p as usize].parent;
        }
        p
    }

    /// Remove edge `e` (which must be in the tree).
    pub fn remove(&mut self, e: u32) {
        // Rotate e down until it has at most one child, then splice it out.
        loop {
            let Node { left, right, .. } = self.nodes[e as usize];
            if left == NONE || right == NONE {
                let child = if left == NONE { right } else { left };
                let p = self.nodes[e as usize].parent;
                if child != NONE {
                    self.nodes[child as usize].parent = p;
                }
                self.replace_child(p, e, child);
                return;
            }
            let up = if self.nodes[left as usize].priority < self.nodes[right as usize].priority {
                left
            } else {
                right
            };
            self.rotate_up(up);
        }
    }

    fn replace_child(&mut self, p: u32, old: u32, new: u32) {
        if p == NONE {
            self.root = new;
        } else if self.nodes[p as usize].left == old {
            self.nodes[p as usize].left = new;
        } else {
            self.nodes[p as usize].right = new;
        }
    }

    /// Rotate `x` above its parent.
    fn rotate_up(&mut self, x: u32) {
        let p = self.nodes[x as usize].parent;
        let g = self.nodes[p as usize].parent;
        if self.nodes[p as usize].left == x {
            let b = self.nodes[x as usize].right;
            self.nodes[p as usize].left = b;
            if b != NONE {
                self.nodes[b as usize].parent = p;
            }
            self.nodes[x as usize].right = p;
        } else {
            let b = self.nodes[x as usize].left;
            self.nodes[p as usize].right = b;
            if b != NONE {
                self.nodes[b as usize].parent = p;
            }
            self.nodes[x as usize].left = p;
        }
        self.nodes[p as usize].parent = x;
        self.nodes[x as usize].parent = g;
        self.replace_child(g, p, x);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Keys are plain integers here: the tree must keep them sorted through any sequence
    /// of inserts and removals.
    #[test]
    fn treap_keeps_order() {
        let n = 200u32;
        let key = |e: u32| (e * 37) % 211;
        let mut s = Status::new(n as usize);
        let mut present = Vec::new();
        for e in 0..n {
            s.insert(e, |t| {
                if key(e) > key(t) {
                    Side::Right
                } else {
                    Side::Left
                }
            })
            .unwrap();
            present.push(e);
            if e % 3 == 0 {
                let r = present.remove((e as usize * 7) % present.len());
                s.remove(r);
            }
            let mut sorted = present.clone();
            sorted.sort_by_key(|&t| key(t));
            for (i, &t) in sorted.iter().enumerate() {
                let want = (
                    if i > 0 { sorted[i - 1] } else { NONE },
                    sorted.get(i + 1).copied().unwrap_or(NONE),
                );
                assert_eq!(s.neighbours(t), want);
            }
            for q in [0u32, 50, 105, 210] {
                let got = s
                    .left_of(|t| if q > key(t) { Side::Right } else { Side::Left })
                    .unwrap();
                let want = present
                    .iter()
                    .copied()
                    .filter(|&t| key(t) < q)
                    .max_by_key(|&t| key(t));
                assert_eq!(got, want);
            }
        }
    }
}
