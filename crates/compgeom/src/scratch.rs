//! Temporary arrays reused from call to call on the same thread.
//!
//! A boolean operation on small polygons makes about eighty short-lived arrays (per
//! vertex, per half-edge, per cycle, …); on the JTS robustness pairs, allocating and
//! freeing them was about 7% of the instructions of a call. A [`Scratch`] array is a
//! `Vec` taken from a per-thread pool and handed back to it when dropped, so the next
//! call finds its arrays already allocated.
//!
//! The pool holds memory between calls, so it is bounded: an array larger than
//! [`MAX_KEPT_BYTES`] (1 MiB) is freed as usual, each element type keeps at most
//! [`MAX_KEPT`] arrays per thread, and of the arrays above [`SMALL_BYTES`] (64 KiB) a
//! thread keeps at most [`MAX_KEPT_LARGE`] (2 MiB) in all; larger inputs allocate as
//! before. (The small arrays are not counted: counting every one cost a call on two
//! squares 3% more instructions.) An array is always handed out cleared and filled as
//! asked: nothing of an earlier call shows (a test runs the same calls in different
//! orders on fresh threads and compares every result). Arrays dropped on another thread
//! (the rayon pool) go to that thread's pool. Where the pool cannot be reached (a thread
//! being torn down), arrays are allocated and freed as usual.
//!
//! Keeping the arrays of up to a mebibyte is for inputs of a few thousand vertices,
//! called again and again: freed at the end of a call, their blocks left a free stretch
//! at the top of the heap, which glibc's allocator hands back to the system (it trims
//! above 128 KiB), and the next call took every page back with a page fault. Measured,
//! consecutive calls in one process (`BOOLEAN_ONE`, wall time with `perf stat`, against
//! arrays of at most 64 KiB kept): the GEOS-837 dissolve, 400 calls, 11 540 → 480 page
//! faults, 250 → 200 ms; two stars of 10⁴ vertices, 20 unions, 19 970 → 2 550 page
//! faults, 84.5 → 50.4 ms (i_overlay 100 ms, geo 103 ms on the same calls); the water map
//! union, 40 calls, 431–461 → 453–464 ms (the same within noise); the JTS pairs +0.3%
//! instructions (the counting of large arrays). The bench's tables time the best of
//! alternating single calls and did not move.
//!
//! Measured on the bench's JTS pairs: 79 → 47 allocations a call, 2–3% fewer
//! instructions, about 6% less time (the allocator's own work and the counting
//! allocator's atomics). Which sites take from it is a matter of measure: the nudge of
//! the rounding check, which runs in some calls only, made the others' arrays come back
//! in the wrong sizes (+0.9% instructions on the JTS xor) and keeps plain vectors.
use std::cell::{Cell, RefCell};
use std::ops::{Deref, DerefMut};
use std::thread::LocalKey;

/// Arrays above this many bytes are not kept.
pub(crate) const MAX_KEPT_BYTES: usize = 1 << 20;

/// At most this many arrays of one element type are kept per thread.
pub(crate) const MAX_KEPT: usize = 16;

/// Arrays of at most this many bytes are kept without counting them (at most
/// [`MAX_KEPT`] per element type).
pub(crate) const SMALL_BYTES: usize = 64 * 1024;

/// At most this many bytes of arrays above [`SMALL_BYTES`], of all element types, are
/// kept per thread.
pub(crate) const MAX_KEPT_LARGE: usize = 2 << 20;

std::thread_local! {
    /// The bytes of the arrays above [`SMALL_BYTES`] this thread's pools hold.
    static KEPT_LARGE: Cell<usize> = const { Cell::new(0) };
}

/// The bytes of `vec`'s room.
fn bytes_of<T>(vec: &Vec<T>) -> usize {
    vec.capacity() * std::mem::size_of::<T>()
}

/// The arrays of one element type kept by this thread.
pub(crate) type Pool<T> = RefCell<Vec<Vec<T>>>;

/// An element type with a per-thread pool of arrays.
pub(crate) trait Reusable: Copy + 'static {
    /// This thread's pool of arrays of `Self`.
    fn pool() -> &'static LocalKey<Pool<Self>>;
}

/// A `Vec<T>` that goes back to this thread's pool when dropped.
pub(crate) struct Scratch<T: Reusable> {
    vec: Vec<T>,
}

/// Whether an array with room for `capacity` elements of `T` is small enough to keep.
fn keepable<T>(capacity: usize) -> bool {
    capacity <= MAX_KEPT_BYTES / std::mem::size_of::<T>().max(1)
}

/// An empty array with room for at least `capacity` elements.
pub(crate) fn with_capacity<T: Reusable>(capacity: usize) -> Scratch<T> {
    // The last array handed back: the calls of one operation take and hand back their
    // arrays in the same order each time, so a site mostly gets the array it had the
    // last time, already large enough (a best fit among the kept ones cost more than it
    // saved).
    if !keepable::<T>(capacity) {
        // (Too large to be kept: the pool's arrays stay for the small ones.)
        return Scratch {
            vec: Vec::with_capacity(capacity),
        };
    }
    let kept = T::pool()
        .try_with(|pool| pool.borrow_mut().pop())
        .ok()
        .flatten();
    if let Some(vec) = kept.as_ref().filter(|v| bytes_of(v) > SMALL_BYTES) {
        let _ = KEPT_LARGE.try_with(|k| k.set(k.get().saturating_sub(bytes_of(vec))));
    }
    let mut vec = kept.unwrap_or_default();
    vec.clear();
    vec.reserve(capacity);
    Scratch { vec }
}

/// An array of `len` copies of `value`.
pub(crate) fn filled<T: Reusable>(len: usize, value: T) -> Scratch<T> {
    if !keepable::<T>(len) {
        // (Too large to be kept, as in `with_capacity`; `vec!` of zeros gets fresh pages
        // from the allocator already zeroed, where a resize would write every one.)
        return Scratch {
            vec: vec![value; len],
        };
    }
    let mut s = with_capacity(len);
    s.vec.resize(len, value);
    s
}

/// An array of the items of `items`.
pub(crate) fn collected<T: Reusable>(items: impl ExactSizeIterator<Item = T>) -> Scratch<T> {
    let mut s = with_capacity(items.len());
    s.vec.extend(items);
    s
}

impl<T: Reusable> Drop for Scratch<T> {
    fn drop(&mut self) {
        let vec = std::mem::take(&mut self.vec);
        if vec.capacity() == 0 || !keepable::<T>(vec.capacity()) {
            return;
        }
        // (Past the thread's teardown the array is simply freed.)
        let bytes = bytes_of(&vec);
        let large = bytes > SMALL_BYTES;
        if large && KEPT_LARGE.try_with(|k| k.get() + bytes > MAX_KEPT_LARGE) != Ok(false) {
            return;
        }
        let _ = T::pool().try_with(|pool| {
            let mut pool = pool.borrow_mut();
            if pool.len() < MAX_KEPT {
                pool.push(vec);
                if large {
                    let _ = KEPT_LARGE.try_with(|k| k.set(k.get() + bytes));
                }
            }
        });
    }
}

impl<T: Reusable> Deref for Scratch<T> {
    type Target = Vec<T>;
    fn deref(&self) -> &Vec<T> {
        &self.vec
    }
}

impl<T: Reusable> DerefMut for Scratch<T> {
    fn deref_mut(&mut self) -> &mut Vec<T> {
        &mut self.vec
    }
}

impl<T: Reusable> Default for Scratch<T> {
    /// An empty array, not taken from the pool (it goes to the pool if it grows).
    fn default() -> Scratch<T> {
        Scratch { vec: Vec::new() }
    }
}

impl<T: Reusable> From<Vec<T>> for Scratch<T> {
    /// `vec`, handed to the pool when dropped.
    fn from(vec: Vec<T>) -> Scratch<T> {
        Scratch { vec }
    }
}

impl<'a, T: Reusable> IntoIterator for &'a Scratch<T> {
    type Item = &'a T;
    type IntoIter = std::slice::Iter<'a, T>;
    fn into_iter(self) -> Self::IntoIter {
        self.vec.iter()
    }
}

impl<'a, T: Reusable> IntoIterator for &'a mut Scratch<T> {
    type Item = &'a mut T;
    type IntoIter = std::slice::IterMut<'a, T>;
    fn into_iter(self) -> Self::IntoIter {
        self.vec.iter_mut()
    }
}

/// A pool per element type (a generic `thread_local!` is not possible): `reusable!(T, …)`
/// next to the type's definition.
macro_rules! reusable {
    ($($t:ty),* $(,)?) => {$(
        impl $crate::scratch::Reusable for $t {
            fn pool() -> &'static ::std::thread::LocalKey<$crate::scratch::Pool<$t>> {
                ::std::thread_local! {
                    static POOL: $crate::scratch::Pool<$t> =
                        const { ::std::cell::RefCell::new(Vec::new()) };
                }
                &POOL
            }
        }
    )*};
}
pub(crate) use reusable;

reusable!(
    crate::kernel::Point2,
    crate::kernel::Segment2,
    crate::kernel::ExactPoint,
    u64,
    [u32; 4],
    [f64; 4],
    u8,
    bool,
    u32,
    usize,
    (i32, i32),
    (u32, u32),
    (usize, usize),
    (u32, i32, i32),
);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arrays_come_back_cleared_and_filled_as_asked() {
        {
            let mut a = filled(100, 7u32);
            a[3] = 9;
            a.push(11);
        }
        let a = filled(50, 1u32);
        assert_eq!(a.len(), 50);
        assert!(a.iter().all(|&x| x == 1));
        let b = with_capacity::<u32>(10);
        assert!(b.is_empty());
        assert!(b.capacity() >= 10);
        let c = collected([4u32, 5, 6].into_iter());
        assert_eq!(&c[..], &[4, 5, 6]);
    }

    #[test]
    fn the_last_array_handed_back_is_reused_and_the_pool_stays_bounded() {
        // (A thread of its own: an empty pool to start from.)
        std::thread::spawn(|| {
            let a = with_capacity::<u8>(1000);
            let at = a.as_ptr();
            drop(a);
            // The array handed back, not a new one (its room kept).
            let b = with_capacity::<u8>(10);
            assert_eq!(b.as_ptr(), at);
            assert!(b.capacity() >= 1000);
            drop(b);
            // Too large to keep: not taken from the pool, not handed to it.
            let large = with_capacity::<u8>(MAX_KEPT_BYTES + 1);
            drop(large);
            assert_eq!(u8::pool().with(|pool| pool.borrow().len()), 1);
            let grown = {
                let mut c = with_capacity::<u8>(10);
                c.extend(std::iter::repeat_n(0, MAX_KEPT_BYTES + 1));
                c
            };
            drop(grown);
            assert_eq!(u8::pool().with(|pool| pool.borrow().len()), 0);
            let kept: Vec<_> = (0..3 * MAX_KEPT).map(|_| with_capacity::<u8>(8)).collect();
            drop(kept);
            u8::pool().with(|pool| {
                let pool = pool.borrow();
                assert_eq!(pool.len(), MAX_KEPT);
                assert!(pool.iter().all(|v| v.capacity() <= MAX_KEPT_BYTES));
            });
        })
        .join()
        .expect("the test thread");
    }

    /// The bytes of large arrays a thread keeps, over all element types, stay within
    /// [`MAX_KEPT_LARGE`]; arrays taken out are counted out, so the budget comes back.
    #[test]
    fn a_thread_keeps_a_bounded_number_of_bytes() {
        std::thread::spawn(|| {
            let kept = || KEPT_LARGE.with(Cell::get);
            // (The large arrays in the pools: the small ones are not counted.)
            fn large<T: Reusable>() -> usize {
                T::pool().with(|p| {
                    let p = p.borrow();
                    p.iter().map(bytes_of).filter(|&b| b > SMALL_BYTES).sum()
                })
            }
            let pooled = || large::<u8>() + large::<u64>();
            // Arrays of the largest size kept, of two types, more than the budget holds.
            let bytes: Vec<_> = (0..MAX_KEPT)
                .map(|_| with_capacity::<u8>(MAX_KEPT_BYTES))
                .collect();
            let words: Vec<_> = (0..MAX_KEPT)
                .map(|_| with_capacity::<u64>(MAX_KEPT_BYTES / 8))
                .collect();
            drop(bytes);
            drop(words);
            assert_eq!(kept(), pooled());
            assert!(kept() <= MAX_KEPT_LARGE, "{}", kept());
            assert!(
                kept() + MAX_KEPT_BYTES > MAX_KEPT_LARGE,
                "room left: {}",
                kept()
            );
            // Taking arrays out gives their bytes back to the budget.
            let again: Vec<_> = (0..4).map(|_| with_capacity::<u8>(1)).collect();
            assert_eq!(kept(), pooled());
            drop(again);
            assert_eq!(kept(), pooled());
        })
        .join()
        .expect("the test thread");
    }
}
