//! Overflow-safe norms: every length is computed as `m · √Σ (x/m)²` with `m` the largest
//! absolute component, so no finite non-zero input becomes zero or infinity through an
//! intermediate square (an axis `[1e200, 1e200, 0]` or `[1e-200, 0, 0]` has a direction).

use crate::{MotionError, pose::Pose};
use algebra_core::{Real, Ring};

/// Binary exponents of the rotational part within `±TAME_LOG2`, with every coefficient below
/// `2^(2·TAME_LOG2)`, are used as they are: the products of the action (eqs. 6-9) and of
/// `rev(S) S` then stay far inside f64's normal range.
const TAME_LOG2: i32 = 250;

/// Whether `α = rev(S) S`'s scalar part can be divided by without care: non-zero for exact
/// scalars; for fixed-precision scalars within `2^±(2·TAME_LOG2)` (the square of a tame
/// rotational part), so that no product of the direct paths of `Pose::transform_point` and
/// `Pose::log` over- or underflows for poses and points of ordinary size.
pub(crate) fn tame<T: Ring>(alpha: &T) -> bool {
    if T::relative_epsilon() == 0.0 {
        return !alpha.is_exact_zero();
    }
    // `LO <= m < HI` on the bits (one integer comparison, off the floating-point ports): the
    // order of non-negative floats is their bits' order, and a NaN's bits lie above `HI`'s
    let m = alpha.magnitude().to_bits();
    m.wrapping_sub(TAME_ALPHA_LO.to_bits()) < TAME_ALPHA_HI.to_bits() - TAME_ALPHA_LO.to_bits()
}

/// `2^(-2·TAME_LOG2)`, exactly.
const TAME_ALPHA_LO: f64 = f64::from_bits(((1023 - 2 * TAME_LOG2) as u64) << 52);
/// `2^(2·TAME_LOG2)`, exactly.
const TAME_ALPHA_HI: f64 = f64::from_bits(((1023 + 2 * TAME_LOG2) as u64) << 52);

/// `S · 2^-e` with `2^e` the scale of the rotational part `S∅, S12, S13, S23`, when `S` is of
/// fixed precision (f64, f32, dual numbers) and far from unit scale; `None` for ordinary
/// poses (one pass over the magnitudes), exact scalars, singular and non-finite poses. The
/// scaling is by an exact power of two, so every scale-invariant result (matrix, action,
/// equivalence, unitization) is unchanged and no square under- or overflows.
pub(crate) fn unusual_scale<T: Ring>(s: &Pose<T>) -> Option<(i32, Pose<T>)> {
    if T::relative_epsilon() == 0.0 {
        return None;
    }
    let c = s.components();
    let rot = c[..4].iter().map(|x| x.magnitude()).fold(0.0, f64::max);
    let all = c[4..].iter().map(|x| x.magnitude()).fold(rot, f64::max);
    let (lo, hi) = (2f64.powi(-TAME_LOG2), 2f64.powi(TAME_LOG2));
    if !(rot > 0.0 && all.is_finite()) || (rot >= lo && rot < hi && all < hi * hi) {
        return None;
    }
    // e = 0: the rotational part is already of unit scale (only the translation is large)
    let e = rot.log2().floor() as i32;
    (e != 0).then(|| (e, scale_pow2(s, -e)))
}

/// `x · 2^e` for a pose, exactly (two factors, each within f64's range, for `|e|` up to about 2000).
pub(crate) fn scale_pow2<T: Ring>(s: &Pose<T>, e: i32) -> Pose<T> {
    let factor = |k: i32| {
        if k >= 0 { T::from_i64(2).pow_u32(k.unsigned_abs()) } else { T::from_ratio(1, 2).pow_u32(k.unsigned_abs()) }
    };
    let h = e / 2;
    s.scale(&factor(h)).scale(&factor(e - h))
}

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
/// `S∅, S12, S13, S23` (for floats far from unit scale rounded down to a power of two): then
/// `rev(S/m) (S/m)` has scalar part in `[1, 16)`, so norms and logs
/// of huge or tiny poses neither overflow nor underflow. `None` when that part is exactly
/// zero (a singular pose).
pub(crate) fn rotational_scale<T: Real>(s: &Pose<T>) -> Option<(T, Pose<T>)> {
    let c = s.components();
    let m = largest_abs([c[0], c[1], c[2], c[3]]);
    if m.is_exact_zero() {
        return None;
    }
    // far from unit scale, m rounded down to a power of two 2^e: S/2^e is exact, and a
    // subnormal m (no finite reciprocal) works too; ordinary poses keep S·(1/m)
    let f = m.to_f64();
    let ordinary = f >= 2f64.powi(-TAME_LOG2) && f < 2f64.powi(TAME_LOG2);
    if !ordinary && T::relative_epsilon() > 0.0 && f > 0.0 && f.is_finite() {
        let e = if f.is_normal() { ((f.to_bits() >> 52) & 0x7ff) as i32 - 1023 } else { f.log2().floor() as i32 };
        let scaled = match e {
            0 => s.clone(),
            -1022..=1022 => s.scale(&T::from_f64(f64::from_bits(((1023 - e) as u64) << 52))),
            _ => scale_pow2(s, -e),
        };
        return Some((T::from_f64(2f64.powi(e)), scaled));
    }
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

#[cfg(test)]
mod tests {
    use super::{TAME_ALPHA_HI, TAME_ALPHA_LO, tame};

    /// `tame` on the bits agrees with the range it stands for, `LO <= |α| < HI`, at and beside
    /// both ends and on the values that are not numbers.
    #[test]
    fn tame_is_the_range_test() {
        let up = |x: f64| f64::from_bits(x.to_bits() + 1);
        let down = |x: f64| f64::from_bits(x.to_bits() - 1);
        let values = [
            0.0,
            -0.0,
            f64::MIN_POSITIVE,
            5e-324,
            1.0,
            -1.0,
            TAME_ALPHA_LO,
            down(TAME_ALPHA_LO),
            up(TAME_ALPHA_LO),
            TAME_ALPHA_HI,
            down(TAME_ALPHA_HI),
            -down(TAME_ALPHA_HI),
            f64::MAX,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            -f64::NAN,
        ];
        for a in values {
            let by_range = (TAME_ALPHA_LO..TAME_ALPHA_HI).contains(&a.abs());
            assert_eq!(tame(&a), by_range, "{a:e}");
        }
        assert!(tame(&1.0) && tame(&TAME_ALPHA_LO) && !tame(&TAME_ALPHA_HI) && !tame(&down(TAME_ALPHA_LO)));
        // f32 through its magnitude (an f64)
        assert!(tame(&1.5f32) && !tame(&0.0f32));
    }
}
