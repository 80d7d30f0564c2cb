//! Overflow-safe norms: every length is computed as `m · √Σ (x/m)²` with `m` the largest
//! absolute component, so no finite non-zero input becomes zero or infinity through an
//! intermediate square (an axis `[1e200, 1e200, 0]` or `[1e-200, 0, 0]` has a direction).

use crate::{MotionError, pose::Pose};
use algebra_core::{Real, Ring};

/// The component of largest absolute value, as a non-negative value (zero for no input).
pub(crate) fn largest_abs<'a, T: Real + 'a>(xs: impl IntoIterator<Item = &'a T>) -> T {
    xs.into_iter().map(Real::abs).fold(T::zero(), |m, x| if x > m { x } else { m })
}

/// `|x|` (Euclidean) without overflow or underflow of the squares; `None` when every
/// component is zero.
pub(crate) fn length<T: Real>(x: &[T]) -> Option<T> {
    let m = largest_abs(x);
    let inv = m.try_recip()?;
    let s = x.iter().fold(T::zero(), |acc, c| {
        let r = c.mul_ref(&inv);
        acc.add_ref(&r.mul_ref(&r))
    });
    Some(m.mul_ref(&Real::sqrt(&s)))
}

/// `x / max|x_i|`, `None` for the zero vector. Subnormal components (whose reciprocal
/// overflows) are first scaled up by exact powers of two.
fn by_largest<T: Real, const N: usize>(x: &[T; N]) -> Option<[T; N]> {
    let mut x = x.clone();
    let up = T::from_i64(1 << 62);
    for _ in 0..8 {
        let m = largest_abs(&x);
        if m.is_exact_zero() {
            return None;
        }
        if let Some(inv) = m.try_recip() {
            return Some(x.map(|c| c.mul_ref(&inv)));
        }
        x = x.map(|c| c.mul_ref(&up));
    }
    None
}

/// `x / |x|`, `None` for the zero vector.
pub(crate) fn direction<T: Real, const N: usize>(x: &[T; N]) -> Option<[T; N]> {
    let y = by_largest(x)?;
    let inv_len = length(&y)?.try_recip()?;
    Some(y.map(|c| c.mul_ref(&inv_len)))
}

/// `(m, S/m)` with `m` the largest absolute value of the rotational part
/// `S∅, S12, S13, S23`: then `rev(S/m) (S/m)` has scalar part in `[1, 4]`, so norms and logs
/// of huge or tiny poses neither overflow nor underflow. `None` when that part is exactly
/// zero (a singular pose).
pub(crate) fn rotational_scale<T: Real>(s: &Pose<T>) -> Option<(T, Pose<T>)> {
    let c = s.components();
    let m = largest_abs([c[0], c[1], c[2], c[3]]);
    let inv = m.try_recip()?;
    Some((m, s.scale(&inv)))
}

/// [`MotionError::NotFinite`] unless the pose and every value are finite (for code generic
/// over a [`Ring`], where exact scalars are always finite).
pub(crate) fn require_finite<'a, T: Ring + 'a>(
    op: &'static str,
    s: &Pose<T>,
    values: impl IntoIterator<Item = &'a T>,
) -> Result<(), MotionError> {
    if s.components().into_iter().all(Ring::is_finite_value) && values.into_iter().all(Ring::is_finite_value) {
        Ok(())
    } else {
        Err(MotionError::NotFinite { op, value: s.to_string() })
    }
}
