//! The scalar layer that separates arithmetic and elementary functions from decisions, so the
//! same code runs over one value (`f64`, dual numbers, MPFR) and over SIMD lanes (several
//! values at once, feature `lanes`):
//!
//! | trait | gives | scalars (`Real` types) | lane types |
//! |---|---|---|---|
//! | [`Elementary`] | `sqrt exp ln sin cos atan2 abs`, `pi`, `from_f64` over a [`Field`], no ordering | the [`Real`] functions | lane by lane |
//! | [`Select`] | a [`Mask`] type, comparisons returning masks, `select(mask, a, b)` | `Mask = bool`, `PartialOrd` | one bit per lane |
//! | [`Diagnostics`] | lane count, a lane as f64, largest/smallest lane | one lane | every lane, honestly |
//! | [`LaneReal`] | all three: what branch-free closed forms are bounded on | every [`Real`] | the lane types |
//!
//! A [`Real`] type gets all of them by blanket impl from what it has, so nothing changes for
//! `f32`, `f64`, num-dual, [`Jet`](crate::Jet), `MpFloat`: [`Real`] keeps its meaning (an
//! ordered field), and a lane type is never `PartialOrd` and never `Real` (an ordering of
//! vectors would silently decide for one lane what the others need decided differently).
//! Code bounded on [`LaneReal`] decides with masks instead of `if`: it computes every case and
//! [`Select::select`]s per lane.
//!
//! ```
//! use algebra_core::scalar::{LaneReal, Select};
//! /// sin x / x, with the limit 1 at x = 0, without a branch on the value.
//! fn sinc<T: LaneReal>(x: &T) -> T {
//!     let zero = x.eq_mask(&T::zero());
//!     let safe = T::select(&zero, &T::one(), x);
//!     T::select(&zero, &T::one(), &safe.sin().div_ref(&safe))
//! }
//! assert_eq!(sinc(&0.0f64), 1.0);
//! assert!((sinc(&0.5f64) - 0.5f64.sin() / 0.5).abs() < 1e-16);
//! ```

use super::{Field, Real, Ring};
use std::fmt::Debug;
use std::ops::{BitAnd, BitOr, Not};

/// The elementary functions over a [`Field`] without an ordering: what closed-form exp and log
/// compute. Every [`Real`] has them (blanket impl, the [`Real`] functions); lane types apply
/// them lane by lane.
///
/// ```
/// use algebra_core::scalar::Elementary;
/// fn unit_circle<T: Elementary>(t: &T) -> T {
///     t.sin().mul_ref(&t.sin()) + t.cos().mul_ref(&t.cos())
/// }
/// assert!((unit_circle(&0.7f64) - 1.0).abs() < 1e-15);
/// ```
pub trait Elementary: Field {
    /// Square root (of a non-negative value).
    fn sqrt(&self) -> Self;
    /// Exponential.
    fn exp(&self) -> Self;
    /// Natural logarithm (of a positive value).
    fn ln(&self) -> Self;
    /// Sine.
    fn sin(&self) -> Self;
    /// Cosine.
    fn cos(&self) -> Self;
    /// Four-quadrant arctangent of `self / x`.
    fn atan2(&self, x: &Self) -> Self;
    /// Absolute value.
    fn abs(&self) -> Self;
    /// The nearest value to `x` (in every lane).
    fn from_f64(x: f64) -> Self;
    /// π at the type's precision.
    fn pi() -> Self;
}

impl<T: Real> Elementary for T {
    fn sqrt(&self) -> Self {
        Real::sqrt(self)
    }
    fn exp(&self) -> Self {
        Real::exp(self)
    }
    fn ln(&self) -> Self {
        Real::ln(self)
    }
    fn sin(&self) -> Self {
        Real::sin(self)
    }
    fn cos(&self) -> Self {
        Real::cos(self)
    }
    fn atan2(&self, x: &Self) -> Self {
        Real::atan2(self, x)
    }
    fn abs(&self) -> Self {
        Real::abs(self)
    }
    fn from_f64(x: f64) -> Self {
        <T as Real>::from_f64(x)
    }
    fn pi() -> Self {
        <T as Real>::pi()
    }
}

/// The outcome of a comparison: `bool` for scalars, one bit per lane for lane types.
///
/// ```
/// use algebra_core::scalar::Mask;
/// assert!(Mask::all(&true) && !Mask::any(&false) && <bool as Mask>::splat(true));
/// ```
pub trait Mask: Copy + Debug + BitAnd<Output = Self> + BitOr<Output = Self> + Not<Output = Self> {
    /// The same answer in every lane.
    fn splat(value: bool) -> Self;
    /// True when every lane is set.
    fn all(&self) -> bool;
    /// True when some lane is set.
    fn any(&self) -> bool;
}

impl Mask for bool {
    fn splat(value: bool) -> Self {
        value
    }
    fn all(&self) -> bool {
        *self
    }
    fn any(&self) -> bool {
        *self
    }
}

/// Decisions as data: comparisons that return a [`Mask`] and a per-lane choice between two
/// values. For a [`Real`] (blanket impl) the mask is `bool` and the comparisons are its
/// `PartialOrd` (for dual numbers: the real parts, as their `<` does); lane types compare lane
/// by lane. A comparison involving NaN is false in that lane.
///
/// ```
/// use algebra_core::scalar::Select;
/// let m = 1.0f64.lt_mask(&2.0);
/// assert_eq!(f64::select(&m, &10.0, &20.0), 10.0);
/// ```
pub trait Select: Sized {
    /// One bit per lane (`bool` for scalars).
    type Mask: Mask;
    /// `if_true` in the lanes where `mask` is set, `if_false` in the others.
    fn select(mask: &Self::Mask, if_true: &Self, if_false: &Self) -> Self;
    /// `self < other`, per lane.
    fn lt_mask(&self, other: &Self) -> Self::Mask;
    /// `self <= other`, per lane.
    fn le_mask(&self, other: &Self) -> Self::Mask;
    /// `self > other`, per lane.
    fn gt_mask(&self, other: &Self) -> Self::Mask {
        other.lt_mask(self)
    }
    /// `self >= other`, per lane.
    fn ge_mask(&self, other: &Self) -> Self::Mask {
        other.le_mask(self)
    }
    /// `self == other`, per lane (for dual numbers: the real parts).
    fn eq_mask(&self, other: &Self) -> Self::Mask;
    /// Set in the lanes whose value is finite (every component, for dual numbers).
    fn finite_mask(&self) -> Self::Mask;
}

impl<T: Real> Select for T {
    type Mask = bool;
    fn select(mask: &bool, if_true: &Self, if_false: &Self) -> Self {
        if *mask { if_true.clone() } else { if_false.clone() }
    }
    fn lt_mask(&self, other: &Self) -> bool {
        self < other
    }
    fn le_mask(&self, other: &Self) -> bool {
        self <= other
    }
    fn eq_mask(&self, other: &Self) -> bool {
        self.partial_cmp(other) == Some(std::cmp::Ordering::Equal)
    }
    fn finite_mask(&self) -> bool {
        Real::is_finite(self)
    }
}

/// Sizes for diagnostics, reports and tests, in f64, that a lane type can give honestly:
/// per lane, or the largest / smallest over the lanes. ([`Ring::magnitude`] and
/// [`Ring::relative_epsilon`] are the others: a lane type's magnitude is its largest lane's,
/// its epsilon its element type's.) A [`Real`] is one lane (blanket impl).
///
/// ```
/// use algebra_core::scalar::Diagnostics;
/// assert_eq!(<f64 as Diagnostics>::LANES, 1);
/// assert_eq!((-2.5f64).lane_to_f64(0), Some(-2.5));
/// assert_eq!((-2.5f64).max_to_f64(), -2.5);
/// ```
pub trait Diagnostics: Ring {
    /// How many values one scalar holds.
    const LANES: usize;
    /// The value in `lane` (the real part, for dual numbers), rounded to f64; `None` past the
    /// last lane.
    fn lane_to_f64(&self, lane: usize) -> Option<f64>;
    /// The largest lane value (NaN when a lane is NaN).
    fn max_to_f64(&self) -> f64 {
        fold_lanes(self, f64::max)
    }
    /// The smallest lane value (NaN when a lane is NaN).
    fn min_to_f64(&self) -> f64 {
        fold_lanes(self, f64::min)
    }
}

fn fold_lanes<T: Diagnostics>(x: &T, f: fn(f64, f64) -> f64) -> f64 {
    let mut acc: Option<f64> = None;
    for lane in 0..T::LANES {
        let v = x.lane_to_f64(lane).unwrap_or(f64::NAN);
        if v.is_nan() {
            return f64::NAN;
        }
        acc = Some(acc.map_or(v, |a| f(a, v)));
    }
    acc.unwrap_or(f64::NAN)
}

impl<T: Real> Diagnostics for T {
    const LANES: usize = 1;
    fn lane_to_f64(&self, lane: usize) -> Option<f64> {
        (lane == 0).then(|| self.to_f64())
    }
}

/// A field with the elementary functions and decisions by mask: what the branch-free closed
/// forms (exp, log, pow, slerp of poses) are bounded on. Every [`Real`] is one, and so are the
/// lane types (feature `lanes`) and [`LaneDual`](crate::scalar::LaneDual) over either.
///
/// ```
/// use algebra_core::scalar::LaneReal;
/// fn clamp_below<T: LaneReal>(x: &T, hi: &T) -> T {
///     T::select(&x.gt_mask(hi), hi, x)
/// }
/// assert_eq!(clamp_below(&3.0f64, &2.0), 2.0);
/// ```
pub trait LaneReal: Elementary + Select + Diagnostics {}

impl<T: Elementary + Select + Diagnostics> LaneReal for T {}
