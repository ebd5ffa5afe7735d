//! NaN-keeping reductions: the one way a measurement folds many errors into
//! one number.
//!
//! `f64::max` and `f64::min` return the *other* argument when one is NaN, so
//! `errors.fold(0.0, f64::max)` over a computation that failed everywhere
//! measures 0 and passes. Every reduction here returns NaN as soon as one
//! input is NaN, and [`crate::check::Check`] fails a NaN measurement, so a
//! failed computation fails its check. `tests/it/nan.rs` scans the check
//! code for `f64::max`/`f64::min` folds and bare `.max(`/`.min(`
//! accumulators, and feeds NaN into each check kind's measurement path.
//!
//! Use [`Worst::worst`] / [`Worst::least`] where code wrote `a.max(b)` /
//! `a.min(b)` on measured values, and the [`Measure`] iterator methods
//! where it wrote a fold.

/// NaN-keeping `max`/`min` on `f64`.
pub trait Worst: Copy {
    /// The larger of `self` and `e`; NaN when either is NaN.
    fn worst(self, e: f64) -> f64;
    /// The smaller of `self` and `e`; NaN when either is NaN.
    fn least(self, e: f64) -> f64;
}

impl Worst for f64 {
    #[inline]
    fn worst(self, e: f64) -> f64 {
        if self.is_nan() || e.is_nan() {
            f64::NAN
        } else {
            self.max(e)
        }
    }

    #[inline]
    fn least(self, e: f64) -> f64 {
        if self.is_nan() || e.is_nan() {
            f64::NAN
        } else {
            self.min(e)
        }
    }
}

/// `acc.worst(e)` as a function, for folds: `.fold(0.0, worst)`.
#[inline]
pub fn worst(acc: f64, e: f64) -> f64 {
    acc.worst(e)
}

/// `acc.least(e)` as a function, for folds.
#[inline]
pub fn least(acc: f64, e: f64) -> f64 {
    acc.least(e)
}

/// NaN-keeping reductions of an iterator of measured values.
pub trait Measure: Iterator<Item = f64> + Sized {
    /// Largest value, 0 for none (errors are non-negative); NaN when any
    /// value is NaN.
    fn max_nan(self) -> f64 {
        self.fold(0.0, worst)
    }

    /// Largest `|value|`, 0 for none; NaN when any value is NaN.
    fn max_abs(self) -> f64 {
        self.map(f64::abs).fold(0.0, worst)
    }

    /// Smallest value, `+inf` for none; NaN when any value is NaN.
    fn min_nan(self) -> f64 {
        self.fold(f64::INFINITY, least)
    }

    /// Root mean square; NaN for none (no samples is no measurement) and
    /// when any value is NaN.
    fn rms(self) -> f64 {
        let (n, s) = self.fold((0usize, 0.0f64), |(n, s), x| (n + 1, s + x * x));
        if n == 0 {
            f64::NAN
        } else {
            (s / n as f64).sqrt()
        }
    }
}

impl<I: Iterator<Item = f64>> Measure for I {}

/// Largest `|a_i - b_i|` over two equally long slices; NaN when a value is
/// NaN or the lengths differ (a missing value is not a zero error).
pub fn max_abs_diff(a: &[f64], b: &[f64]) -> f64 {
    if a.len() != b.len() {
        return f64::NAN;
    }
    a.iter().zip(b).map(|(x, y)| x - y).max_abs()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_reduction_keeps_nan() {
        let with_nan = [1.0, f64::NAN, 3.0];
        assert!(with_nan.iter().copied().max_nan().is_nan());
        assert!(with_nan.iter().copied().max_abs().is_nan());
        assert!(with_nan.iter().copied().min_nan().is_nan());
        assert!(with_nan.iter().copied().rms().is_nan());
        assert!(max_abs_diff(&with_nan, &[0.0; 3]).is_nan());
        assert!(max_abs_diff(&[1.0], &[1.0, 2.0]).is_nan());
        assert!(2.0f64.worst(f64::NAN).is_nan());
        assert!(f64::NAN.worst(2.0).is_nan());
        assert!(2.0f64.least(f64::NAN).is_nan());
        assert_eq!(3.0f64.worst(2.0), 3.0);
        assert_eq!(3.0f64.least(2.0), 2.0);
        assert_eq!([-4.0, 2.0].iter().copied().max_abs(), 4.0);
        assert!(std::iter::empty().rms().is_nan());
    }
}
