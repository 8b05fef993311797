//! Equal steps along one axis: the bucket, strip or grid cell of a coordinate.

/// Equal steps along one axis from `lo`: a monotone (non-decreasing) function of the
/// coordinate onto `0..steps`, values below `lo` (and NaN) in the first step and values
/// beyond the last in the last.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Steps {
    lo: f64,
    inv: f64,
    last: u32,
}

impl Steps {
    /// `steps` (at least one) over `lo..=hi` (`hi - lo` positive; when it overflows, all
    /// in step 0).
    pub(crate) fn new(lo: f64, hi: f64, steps: u32) -> Steps {
        Steps::per_unit(lo, steps as f64 / (hi - lo), steps)
    }

    /// `steps` (at least one) from `lo`, `per_unit` of them to a unit of the coordinate.
    pub(crate) fn per_unit(lo: f64, per_unit: f64, steps: u32) -> Steps {
        Steps {
            lo,
            inv: per_unit,
            last: steps - 1,
        }
    }

    /// The step of `v`. (`as u32` saturates, negatives and NaN to 0, in a few
    /// instructions; a conversion to usize or u64 took about 16. The min keeps the upper
    /// end in range.)
    #[inline(always)]
    pub(crate) fn of(&self, v: f64) -> u32 {
        (((v - self.lo) * self.inv) as u32).min(self.last)
    }

    /// [`Steps::of`] as an index.
    #[inline(always)]
    pub(crate) fn index(&self, v: f64) -> usize {
        self.of(v) as usize
    }
}
