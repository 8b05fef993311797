//! The sweep-line status (book §2.1, the structure 𝒯): the segments that cross the
//! sweep line, in left-to-right order along it.
//!
//! A treap (a binary search tree balanced by random priorities: expected depth
//! O(log n)) whose nodes are the segment indices themselves, so it needs no allocation
//! after construction and O(n) space. It never compares two segments directly: the
//! sweep splits it with a predicate that is monotone along the current order ("passes
//! left of the event point", "contains the event point"), and joins the pieces back with
//! the reordered middle. Split and join each take expected O(log n) time, which gives
//! the book's operations: find the segments containing `p` and the neighbours left and
//! right of them, delete, and insert in the order just below `p`.

const NIL: u32 = u32::MAX;

/// A treap over segment indices `0..n`.
pub(crate) struct Status {
    left: Vec<u32>,
    right: Vec<u32>,
    root: u32,
}

/// A deterministic pseudo-random priority (a 32-bit mix of the index), so results
/// and running times are reproducible.
fn priority(i: u32) -> u32 {
    let mut x = i.wrapping_add(0x9e37_79b9);
    x = (x ^ (x >> 16)).wrapping_mul(0x85eb_ca6b);
    x = (x ^ (x >> 13)).wrapping_mul(0xc2b2_ae35);
    x ^ (x >> 16)
}

/// A piece of the status: the root of a sub-treap, possibly empty.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) struct Piece(u32);

impl Piece {
    /// The empty piece.
    pub const EMPTY: Piece = Piece(NIL);
}

impl Status {
    /// An empty status for segments `0..n`.
    pub fn new(n: usize) -> Self {
        Status {
            left: vec![NIL; n],
            right: vec![NIL; n],
            root: NIL,
        }
    }

    /// Detach the whole status.
    pub fn take(&mut self) -> Piece {
        Piece(std::mem::replace(&mut self.root, NIL))
    }

    /// Make `piece` the whole status.
    pub fn set(&mut self, piece: Piece) {
        self.root = piece.0;
    }

    /// Split `piece` into the prefix whose segments satisfy `pred` and the rest.
    /// `pred` must be true on a prefix of the order and false after it.
    pub fn split(&mut self, piece: Piece, pred: &mut impl FnMut(usize) -> bool) -> (Piece, Piece) {
        let t = piece.0;
        if t == NIL {
            return (Piece::EMPTY, Piece::EMPTY);
        }
        let i = t as usize;
        if pred(i) {
            let (l, r) = self.split(Piece(self.right[i]), pred);
            self.right[i] = l.0;
            (Piece(t), r)
        } else {
            let (l, r) = self.split(Piece(self.left[i]), pred);
            self.left[i] = r.0;
            (l, Piece(t))
        }
    }

    /// The concatenation of `a` and then `b`.
    pub fn join(&mut self, a: Piece, b: Piece) -> Piece {
        if a.0 == NIL {
            return b;
        }
        if b.0 == NIL {
            return a;
        }
        let (i, j) = (a.0 as usize, b.0 as usize);
        if priority(a.0) >= priority(b.0) {
            let r = self.join(Piece(self.right[i]), b);
            self.right[i] = r.0;
            a
        } else {
            let l = self.join(a, Piece(self.left[j]));
            self.left[j] = l.0;
            b
        }
    }

    /// A piece holding `items` in the given order (each must be absent from the status).
    pub fn build(&mut self, items: &[usize]) -> Piece {
        let mut piece = Piece::EMPTY;
        for &i in items {
            self.left[i] = NIL;
            self.right[i] = NIL;
            piece = self.join(piece, Piece(i as u32));
        }
        piece
    }

    /// The first segment of `piece`.
    pub fn first(&self, piece: Piece) -> Option<usize> {
        let mut t = piece.0;
        if t == NIL {
            return None;
        }
        while self.left[t as usize] != NIL {
            t = self.left[t as usize];
        }
        Some(t as usize)
    }

    /// The last segment of `piece`.
    pub fn last(&self, piece: Piece) -> Option<usize> {
        let mut t = piece.0;
        if t == NIL {
            return None;
        }
        while self.right[t as usize] != NIL {
            t = self.right[t as usize];
        }
        Some(t as usize)
    }

    /// Append the segments of `piece` in order to `out`.
    pub fn collect(&self, piece: Piece, out: &mut Vec<usize>) {
        // Iterative in-order walk (the piece is small, but keep the stack bounded).
        let mut stack = Vec::new();
        let mut t = piece.0;
        loop {
            while t != NIL {
                stack.push(t);
                t = self.left[t as usize];
            }
            match stack.pop() {
                None => break,
                Some(u) => {
                    out.push(u as usize);
                    t = self.right[u as usize];
                }
            }
        }
    }

    /// All segments in order (for pictures and tests).
    pub fn in_order(&self) -> Vec<usize> {
        let mut out = Vec::new();
        self.collect(Piece(self.root), &mut out);
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn split_and_join_keep_the_order() {
        let mut st = Status::new(100);
        let items: Vec<usize> = (0..100).rev().collect();
        let p = st.build(&items);
        // Split by position: the first 30 of the order.
        let mut seen = 0;
        let (a, b) = st.split(p, &mut |i| {
            let _ = i;
            seen += 1;
            i >= 70
        });
        assert!(seen > 0);
        let (mut va, mut vb) = (Vec::new(), Vec::new());
        st.collect(a, &mut va);
        st.collect(b, &mut vb);
        assert_eq!(va, (70..100).rev().collect::<Vec<_>>());
        assert_eq!(vb, (0..70).rev().collect::<Vec<_>>());
        assert_eq!(st.first(b), Some(69));
        assert_eq!(st.last(a), Some(70));
        let j = st.join(a, b);
        st.set(j);
        assert_eq!(st.in_order(), items);
        let whole = st.take();
        assert_ne!(whole, Piece::EMPTY);
        assert!(st.in_order().is_empty());
    }
}
