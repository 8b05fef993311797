//! [`SegmentList`]: the segment lists of an intersection point, kept inline when short.
//!
//! Nearly every intersection point of real input is two segments crossing: lists of
//! two entries (`segments`, `interior`) and two empty ones. Holding such lists inline
//! instead of in a `Vec` each saves two heap allocations per reported crossing (with
//! hundreds of thousands of crossings, the allocator was a tenth of the running time).

use std::fmt;
use std::ops::Deref;

/// How many indices a list holds without a heap allocation.
const INLINE: usize = 2;

/// A list of segment indices (ascending where [`super::IntersectionPoint`] says so).
///
/// Reads as a slice (`Deref<Target = [usize]>`): `list.len()`, `list[0]`,
/// `list.iter()`, `&list[..]`; compares equal to a `Vec`, an array or a slice with the
/// same entries. Lists of up to two entries are stored inline (no allocation).
///
/// ```
/// use compgeom::intersect::SegmentList;
/// let l = SegmentList::from(vec![3, 7]);
/// assert_eq!(l, vec![3, 7]);
/// assert_eq!(l, [3, 7]);
/// assert_eq!(l.iter().sum::<usize>(), 10);
/// assert_eq!(format!("{l:?}"), "[3, 7]");
/// ```
#[derive(Clone)]
pub struct SegmentList(Repr);

#[derive(Clone)]
enum Repr {
    Inline { len: u8, items: [usize; INLINE] },
    Heap(Box<[usize]>),
}

impl SegmentList {
    /// The empty list.
    pub const fn new() -> Self {
        SegmentList(Repr::Inline {
            len: 0,
            items: [0; INLINE],
        })
    }

    /// The list `[a, b]` (no allocation).
    pub const fn pair(a: usize, b: usize) -> Self {
        SegmentList(Repr::Inline {
            len: 2,
            items: [a, b],
        })
    }

    /// The list of the given indices, in the given order.
    pub fn from_slice(items: &[usize]) -> Self {
        if items.len() <= INLINE {
            let mut inline = [0; INLINE];
            inline[..items.len()].copy_from_slice(items);
            SegmentList(Repr::Inline {
                len: items.len() as u8,
                items: inline,
            })
        } else {
            SegmentList(Repr::Heap(items.into()))
        }
    }

    /// The entries as a slice.
    pub fn as_slice(&self) -> &[usize] {
        match &self.0 {
            Repr::Inline { len, items } => &items[..usize::from(*len)],
            Repr::Heap(items) => items,
        }
    }

    /// The entries as a `Vec`.
    pub fn to_vec(&self) -> Vec<usize> {
        self.as_slice().to_vec()
    }
}

impl Default for SegmentList {
    fn default() -> Self {
        SegmentList::new()
    }
}

impl Deref for SegmentList {
    type Target = [usize];
    fn deref(&self) -> &[usize] {
        self.as_slice()
    }
}

impl AsRef<[usize]> for SegmentList {
    fn as_ref(&self) -> &[usize] {
        self.as_slice()
    }
}

impl From<Vec<usize>> for SegmentList {
    fn from(v: Vec<usize>) -> Self {
        if v.len() <= INLINE {
            SegmentList::from_slice(&v)
        } else {
            SegmentList(Repr::Heap(v.into_boxed_slice()))
        }
    }
}

impl From<&[usize]> for SegmentList {
    fn from(v: &[usize]) -> Self {
        SegmentList::from_slice(v)
    }
}

impl From<SegmentList> for Vec<usize> {
    fn from(l: SegmentList) -> Self {
        match l.0 {
            Repr::Inline { .. } => l.as_slice().to_vec(),
            Repr::Heap(items) => items.into_vec(),
        }
    }
}

impl FromIterator<usize> for SegmentList {
    /// Collects inline while the list is short: no allocation for up to two entries.
    fn from_iter<I: IntoIterator<Item = usize>>(iter: I) -> Self {
        let mut iter = iter.into_iter();
        let mut items = [0; INLINE];
        let mut len = 0;
        for v in iter.by_ref() {
            if len == INLINE {
                let mut spill = items.to_vec();
                spill.push(v);
                spill.extend(iter);
                return SegmentList(Repr::Heap(spill.into_boxed_slice()));
            }
            items[len] = v;
            len += 1;
        }
        SegmentList(Repr::Inline {
            len: len as u8,
            items,
        })
    }
}

impl<'a> IntoIterator for &'a SegmentList {
    type Item = &'a usize;
    type IntoIter = std::slice::Iter<'a, usize>;
    fn into_iter(self) -> Self::IntoIter {
        self.as_slice().iter()
    }
}

impl fmt::Debug for SegmentList {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_list().entries(self.as_slice()).finish()
    }
}

impl PartialEq for SegmentList {
    fn eq(&self, other: &Self) -> bool {
        self.as_slice() == other.as_slice()
    }
}

impl Eq for SegmentList {}

impl std::hash::Hash for SegmentList {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.as_slice().hash(state);
    }
}

impl PartialEq<[usize]> for SegmentList {
    fn eq(&self, other: &[usize]) -> bool {
        self.as_slice() == other
    }
}

impl PartialEq<&[usize]> for SegmentList {
    fn eq(&self, other: &&[usize]) -> bool {
        self.as_slice() == *other
    }
}

impl PartialEq<Vec<usize>> for SegmentList {
    fn eq(&self, other: &Vec<usize>) -> bool {
        self.as_slice() == other.as_slice()
    }
}

impl<const N: usize> PartialEq<[usize; N]> for SegmentList {
    fn eq(&self, other: &[usize; N]) -> bool {
        self.as_slice() == other.as_slice()
    }
}

impl PartialEq<SegmentList> for Vec<usize> {
    fn eq(&self, other: &SegmentList) -> bool {
        self.as_slice() == other.as_slice()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inline_and_heap_lists_read_alike() {
        for n in 0..6 {
            let v: Vec<usize> = (0..n).map(|k| 10 * k + 1).collect();
            let a = SegmentList::from(v.clone());
            let b: SegmentList = v.iter().copied().collect();
            let c = SegmentList::from_slice(&v);
            assert_eq!(a, v);
            assert_eq!(b, a);
            assert_eq!(c.to_vec(), v);
            assert_eq!(Vec::from(a.clone()), v);
            assert_eq!(a.len(), n);
            assert_eq!(format!("{a:?}"), format!("{v:?}"));
            assert_eq!(matches!(a.0, Repr::Inline { .. }), n <= INLINE);
        }
        assert_eq!(SegmentList::pair(4, 2), [4, 2]);
        assert!(SegmentList::new().is_empty());
        assert_ne!(SegmentList::pair(1, 2), SegmentList::from_slice(&[1, 2, 3]));
    }
}
