//! Velocities at the key poses for Jüttler's Algorithm 2 (Sec. 6): the velocity `v_i` of the
//! origin of the moving space and the angular velocity `ω_i` (fixed frame) at each position
//! `P_i`, with respect to the global parameter `t`; given ([`KeyVelocity`]) or estimated by
//! step 1 of the algorithm ([`estimate_velocities`]).
//!
//! **The estimate.** Jüttler's step 1 says the velocities "can be computed from the
//! translations and rotations connecting the translational and the rotational part of the
//! position `P_i` with those of the neighbouring positions". We take, on each interval
//! `[t_k, t_{k+1}]` (`Δt_k = t_{k+1} - t_k`), the uniform motion that connects the neighbours:
//!
//! * translation: the difference quotient `d_k = (s_{k+1} - s_k)/Δt_k` of the translations
//!   `s_k` of (14);
//! * rotation: the connecting rotation `D_k = R_{k+1} R̃_k` (fixed frame: `R_{k+1} = D_k R_k`
//!   up to scale) with angle `θ_k ∈ [0, π]` about the unit axis `a_k`, run at constant speed:
//!   `d_k = θ_k a_k / Δt_k`;
//!
//! and combine the two quotients next to `t_i` by Bessel's rule ([`bessel`], Hoschek–Lasser,
//! Jüttler's ref. \[7\]): the derivative at `t_i` of the parabola through the three neighbouring
//! values. It reproduces the velocities of every motion whose translation and rotation vector
//! (about a fixed axis) are quadratic in `t` (tests `juttler_spline.rs`). With two positions
//! both velocities are `d_0`.
//!
//! ```
//! use motion::{Pose, juttler::velocity::estimate_velocities};
//! let poses = [Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0]), Pose::translation(&[3.0, 0.0, 0.0])];
//! let v = estimate_velocities(&poses, &[0.0, 1.0, 2.0]).unwrap();
//! assert_eq!(v[1].velocity, [1.5, 0.0, 0.0]); // s(t) = t + t²/2
//! assert_eq!(v[2].velocity, [2.5, 0.0, 0.0]);
//! ```

use super::JuttlerError;
use super::tr::rotation_translation;
use crate::repr::dual_quaternion::{DualQuaternion, Quaternion};
use crate::{MotionError, Pose};
use algebra_core::{Field, Real, Ring};

/// The velocity of the body origin `v_i` and the angular velocity `ω_i` (fixed frame) of a
/// motion at a key pose, both `d/dt` in the motion's global parameter: Jüttler's `v⃗_i`, `ω⃗_i`
/// of Algorithm 2, the `{"velocity", "angular_velocity"}` of a key pose in `gam interpolate`.
///
/// ```
/// let v = motion::juttler::KeyVelocity::new([1.0, 0.0, 0.0], [0.0, 0.0, 2.0]);
/// assert_eq!(v.angular_velocity, [0.0, 0.0, 2.0]);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct KeyVelocity<T> {
    /// `v⃗_i`: the velocity of the origin of the moving space.
    pub velocity: [T; 3],
    /// `ω⃗_i`: the angular velocity, in the fixed frame.
    pub angular_velocity: [T; 3],
}

impl<T> KeyVelocity<T> {
    /// The pair `(v⃗_i, ω⃗_i)`.
    ///
    /// ```
    /// let v = motion::juttler::KeyVelocity::new([1, 2, 3], [0, 0, 0]);
    /// assert_eq!(v.velocity, [1, 2, 3]);
    /// ```
    pub fn new(velocity: [T; 3], angular_velocity: [T; 3]) -> Self {
        KeyVelocity { velocity, angular_velocity }
    }
}

/// Bessel's derivative estimates at `t_0, …, t_m` from the difference quotients `d_k` on the
/// intervals `[t_k, t_{k+1}]` (`m` of them): at `t_i` the derivative of the parabola through
/// the three neighbouring values, i.e. `(Δt_i d_{i-1} + Δt_{i-1} d_i)/(Δt_{i-1} + Δt_i)`
/// inside, `((2Δt_0 + Δt_1) d_0 - Δt_0 d_1)/(Δt_0 + Δt_1)` at `t_0` (and mirrored at `t_m`);
/// `d_0` at both ends for one interval. Exact over rationals. Fails unless `params` are
/// strictly increasing and one more than `diffs` (at least two).
///
/// ```
/// use algebra_core::rational::{q, ratio};
/// use motion::juttler::velocity::bessel;
/// // s(t) = t² at t = 0, 1, 3: quotients 1 and 4; s'(t) = 2t exactly
/// let v = bessel(&[q(0), q(1), q(3)], &[[q(1)], [q(4)]]).unwrap();
/// assert_eq!(v, [[q(0)], [q(2)], [q(6)]]);
/// assert!(bessel(&[q(0), q(0), q(3)], &[[q(1)], [q(4)]]).is_err());
/// ```
pub fn bessel<T: Field + PartialOrd, const N: usize>(
    params: &[T],
    diffs: &[[T; N]],
) -> Result<Vec<[T; N]>, JuttlerError> {
    let m = diffs.len();
    check_spline_parameters(m + 1, params)?;
    if m == 1 {
        return Ok(vec![diffs[0].clone(), diffs[0].clone()]);
    }
    let dt: Vec<T> = params.windows(2).map(|w| w[1].sub_ref(&w[0])).collect();
    // (a d_j + b d_k)/(a + b)
    let mix = |a: T, j: usize, b: T, k: usize, den: &T| -> [T; N] {
        let inv = den.try_recip().unwrap_or_else(T::zero);
        std::array::from_fn(|c| a.mul_ref(&diffs[j][c]).add_ref(&b.mul_ref(&diffs[k][c])).mul_ref(&inv))
    };
    let mut out = Vec::with_capacity(m + 1);
    let two = |x: &T| x.add_ref(x);
    out.push(mix(two(&dt[0]).add_ref(&dt[1]), 0, dt[0].neg_ref(), 1, &dt[0].add_ref(&dt[1])));
    for i in 1..m {
        out.push(mix(dt[i].clone(), i - 1, dt[i - 1].clone(), i, &dt[i - 1].add_ref(&dt[i])));
    }
    let (a, b) = (&dt[m - 2], &dt[m - 1]);
    out.push(mix(two(b).add_ref(a), m - 1, b.neg_ref(), m - 2, &a.add_ref(b)));
    Ok(out)
}

/// The rotation vector `θ a` (angle `θ ∈ [0, π]` times the unit axis) of the rotation of the
/// non-zero quaternion `d` (any scale; `d` and `-d` give the same).
fn rotation_vector<T: Real>(d: &Quaternion<T>) -> [T; 3] {
    let (mut c, mut v) = (d.w.clone(), d.vector());
    if c < T::zero() {
        c = c.neg_ref();
        v = v.map(|x| x.neg_ref());
    }
    let n = Real::sqrt(&v.iter().fold(T::zero(), |acc, x| acc.add_ref(&x.mul_ref(x))));
    let two = T::from_i64(2);
    // 2 atan2(n, c)/n → 2/c as n → 0
    let f = if n.is_exact_zero() {
        two.mul_ref(&c.try_recip().unwrap_or_else(T::zero))
    } else {
        two.mul_ref(&n.atan2(&c)).mul_ref(&n.try_recip().unwrap_or_else(T::zero))
    };
    v.map(|x| x.mul_ref(&f))
}

/// Step 1 of Algorithm 2 (module docs): the velocities `v⃗_i` and angular velocities `ω⃗_i`
/// at the positions `poses` with parameters `params` (at least two, strictly increasing and
/// finite), from the connecting translations and rotations by Bessel's rule. Fails for too few
/// positions, bad parameters, and poses with a zero rotational part.
///
/// ```
/// use motion::{Pose, juttler::velocity::estimate_velocities};
/// // a uniform quarter turn per unit of t about z
/// let r = |k: f64| Pose::<f64>::rotation(&[0.0, 0.0, 1.0], &(k * std::f64::consts::FRAC_PI_2)).unwrap();
/// let v = estimate_velocities(&[r(0.0), r(1.0), r(2.0)], &[0.0, 1.0, 2.0]).unwrap();
/// assert!((v[0].angular_velocity[2] - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
/// ```
pub fn estimate_velocities<T: Real>(poses: &[Pose<T>], params: &[T]) -> Result<Vec<KeyVelocity<T>>, JuttlerError> {
    check_spline_parameters(poses.len(), params)?;
    let parts = poses.iter().map(rotation_translation).collect::<Result<Vec<_>, JuttlerError>>()?;
    let mut trans = Vec::with_capacity(parts.len() - 1);
    let mut rot = Vec::with_capacity(parts.len() - 1);
    for (k, w) in parts.windows(2).enumerate() {
        let inv = params[k + 1].sub_ref(&params[k]).try_recip().unwrap_or_else(T::zero);
        trans.push(std::array::from_fn(|c| w[1].1[c].sub_ref(&w[0].1[c]).mul_ref(&inv)));
        let d = &w[1].0 * &w[0].0.conjugate();
        rot.push(rotation_vector(&d).map(|x| x.mul_ref(&inv)));
    }
    let (v, w) = (bessel(params, &trans)?, bessel(params, &rot)?);
    Ok(v.into_iter().zip(w).map(|(v, w)| KeyVelocity::new(v, w)).collect())
}

/// At least two positions, one parameter each, finite (where the scalar can tell) and
/// strictly increasing.
pub(crate) fn check_spline_parameters<T: Field + PartialOrd>(
    positions: usize,
    params: &[T],
) -> Result<(), JuttlerError> {
    if positions < 2 {
        return Err(JuttlerError::TooFewPositions { need: 2, got: positions });
    }
    if params.len() != positions {
        return Err(JuttlerError::Parameters { why: format!("{} parameters for {positions} positions", params.len()) });
    }
    for (i, w) in params.windows(2).enumerate() {
        // not (a < b) also catches NaN
        if w[0].partial_cmp(&w[1]) != Some(std::cmp::Ordering::Less) {
            return Err(JuttlerError::Parameters {
                why: format!("t_{i} = {} and t_{} = {} are not strictly increasing finite values", w[0], i + 1, w[1]),
            });
        }
    }
    Ok(())
}

/// Fails with [`MotionError::NotFinite`] when a velocity component is not finite.
pub(crate) fn check_finite_velocities<T: Real>(velocities: &[KeyVelocity<T>]) -> Result<(), JuttlerError> {
    for (i, v) in velocities.iter().enumerate() {
        if let Some(x) = v.velocity.iter().chain(&v.angular_velocity).find(|x| !Real::is_finite(*x)) {
            return Err(
                MotionError::NotFinite { op: "Algorithm 2 velocities", value: format!("key pose {i}: {x}") }.into()
            );
        }
    }
    Ok(())
}

/// `d/du` of a Bézier curve of dual quaternions at `u`: `n Σ (B_{j+1} - B_j) b_j^{n-1}(u)`.
pub(crate) fn hodograph<T: Ring>(control: &[DualQuaternion<T>], u: &T) -> DualQuaternion<T> {
    if control.len() < 2 {
        return DualQuaternion::zero();
    }
    let n = T::from_i64((control.len() - 1) as i64);
    let diff: Vec<DualQuaternion<T>> = control.windows(2).map(|w| (&w[1] - &w[0]).scale(&n)).collect();
    super::de_casteljau_with(&diff, u, |a, b, s, t| &a.scale(s) + &b.scale(t))
}

/// The [`KeyVelocity`] of a curve `Q(t)` of dual quaternions on the Study quadric from its value
/// `q` and derivative `dq` at one `t` (Jüttler (42) for `ω`, the derivative of
/// `s = 2 Vec(Q^ε Q̃⁰)/|Q⁰|²` for `v`); exact over rationals. Fails where `Q⁰ = 0`.
///
/// ```
/// use algebra_core::rational::q;
/// use gam_algebras::DualQuaternion;
/// use motion::juttler::velocity::key_velocity;
/// let d = |c: [i64; 8]| DualQuaternion::from_coeffs(c.map(q));
/// // Q(t) = 2 + t k + ε t i at t = 0: the origin moves along x at unit speed, turning about z
/// let v = key_velocity(&d([2, 0, 0, 0, 0, 0, 0, 0]), &d([0, 0, 0, 1, 0, 1, 0, 0])).unwrap();
/// assert_eq!(v.velocity, [q(1), q(0), q(0)]);
/// assert_eq!(v.angular_velocity, [q(0), q(0), q(1)]);
/// ```
pub fn key_velocity<T: Field>(q: &DualQuaternion<T>, dq: &DualQuaternion<T>) -> Result<KeyVelocity<T>, JuttlerError> {
    let n = q.real.norm_squared();
    let inv = super::recip_or(&n, || "the rotational part (Q⁰ = 0)".into())?;
    let two = T::from_i64(2);
    let (r, dr) = (&q.real.conjugate(), &dq.real.conjugate());
    let omega = (&dq.real * r).vector().map(|x| x.mul_ref(&two).mul_ref(&inv));
    let s = (&q.dual * r).vector().map(|x| x.mul_ref(&two).mul_ref(&inv));
    let dn = q.real.dot(&dq.real).mul_ref(&two);
    let top = (&dq.dual * r).vector();
    let bottom = (&q.dual * dr).vector();
    let velocity = std::array::from_fn(|k| {
        two.mul_ref(&top[k].add_ref(&bottom[k])).mul_ref(&inv).sub_ref(&s[k].mul_ref(&dn).mul_ref(&inv))
    });
    Ok(KeyVelocity::new(velocity, omega))
}
