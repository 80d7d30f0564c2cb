//! A `cga` displacement rotor and the main paper's pose, both ways. For the pose `x ↦ Rot x + v`
//! (the main paper's unit `S = R_m T`, `R_m = cos(θ/2) + sin(θ/2) â e123` acting by
//! `rev(S) x S`) the displacement rotor is `R = T_v R_rot` with `R_rot = rev(R_m)` read in
//! `cga` names: `R F(x) rev(R) = F(Rot x + v)` for every `x` (the contract's `cga_rotor`).
//! The sign is kept: `S ↦ R` and `-S ↦ -R`.
//!
//! ```
//! use motion::Pose;
//! use motion::wareham_lasenby::{cga::{embed, embed_inverse}, from_pose, to_pose};
//! let s = Pose::<f64>::from_axis_angle_translation(&[1.0, 2.0, 2.0], &0.7, &[1.0, -2.0, 4.0]).unwrap();
//! let r = from_pose(&s).unwrap();
//! let x = [0.5, 1.0, -2.0];
//! let (a, b) = (embed_inverse(&r.apply(&embed(&x))).unwrap(), s.transform_point(&x).unwrap());
//! assert!(a.iter().zip(&b).all(|(p, q)| (p - q).abs() < 1e-14));
//! assert!(to_pose(&r).is_equivalent(&s, &1e-15).unwrap());
//! ```

use super::WlError;
use super::cga::translator;
use crate::Pose;
use algebra_core::{Field, Real};
use gam_algebras::cga::Motor;

/// The displacement rotor of a pose (module docs): the pose is unitized first (a non-unit
/// pose is the same transform). Fails for a singular or non-finite pose.
///
/// ```
/// use motion::{Pose, wareham_lasenby::{cga::translator, from_pose}};
/// assert_eq!(from_pose(&Pose::translation(&[1.0, 2.0, 3.0])).unwrap(), translator(&[1.0, 2.0, 3.0]));
/// ```
pub fn from_pose<T: Real>(s: &Pose<T>) -> Result<Motor<T>, WlError> {
    let u = s.unitize()?;
    let v = u.transform_point(&[T::zero(), T::zero(), T::zero()])?;
    let [c, b12, b13, b23, ..] = u.to_array();
    let mut rot = Motor::zero();
    (rot.scalar, rot.e12, rot.e13, rot.e23) = (c, b12.neg_ref(), b13.neg_ref(), b23.neg_ref());
    Ok(&translator(&v) * &rot)
}

/// The pose of a displacement rotor `R = T_v R_rot` (module docs): `R_rot` is the part of `R`
/// without `e4`, `e5`; `v_i = -2 (R rev(R_rot))_{i4} / |R_rot|²`. A unit rotor gives a unit
/// pose. Only the displacement part of `R` is read (no check: see [`super::log()`]).
///
/// ```
/// use motion::{Pose, wareham_lasenby::{cga::rotor, to_pose}};
/// let s = to_pose(&rotor(&[0.0, 0.0, 1.0], &0.5).unwrap());
/// assert!(s.is_equivalent(&Pose::rotation(&[0.0, 0.0, 1.0], &0.5).unwrap(), &1e-16).unwrap());
/// ```
pub fn to_pose<T: Field>(r: &Motor<T>) -> Pose<T> {
    let mut rot = Motor::zero();
    (rot.scalar, rot.e12, rot.e13, rot.e23) = (r.scalar.clone(), r.e12.clone(), r.e13.clone(), r.e23.clone());
    let norm2 = rot
        .scalar
        .mul_ref(&rot.scalar)
        .add_ref(&rot.e12.mul_ref(&rot.e12))
        .add_ref(&rot.e13.mul_ref(&rot.e13))
        .add_ref(&rot.e23.mul_ref(&rot.e23));
    let tr = r * &rot.reverse();
    let k = T::from_i64(-2).div_ref(&norm2);
    let v = [tr.e14.mul_ref(&k), tr.e24.mul_ref(&k), tr.e34.mul_ref(&k)];
    let z = T::zero;
    let main =
        Pose::from_array([rot.scalar, rot.e12.neg_ref(), rot.e13.neg_ref(), rot.e23.neg_ref(), z(), z(), z(), z()]);
    &main * &Pose::translation(&v)
}

/// The sign the contract prints (`gam pose`'s `cga_rotor`): `R` or `-R` (the same
/// displacement), whichever has scalar part `> 0`; at scalar part `0`, the one whose first
/// non-zero coefficient in basis order (`1, e12, e13, e23, e14, ...`) is positive.
///
/// ```
/// use motion::wareham_lasenby::{cga::rotor, convert::canonical_sign};
/// let half_turn = rotor(&[0.0, 0.0, 1.0], &std::f64::consts::PI).unwrap(); // 0 - e12 (+ rounding)
/// let mut r = half_turn;
/// r.scalar = 0.0;
/// assert_eq!(canonical_sign(r).e12, 1.0);
/// assert_eq!(canonical_sign(-rotor(&[1.0, 0.0, 0.0], &0.5).unwrap()).scalar, (0.25f64).cos());
/// ```
pub fn canonical_sign<T: Real>(r: Motor<T>) -> Motor<T> {
    let zero = T::zero();
    let first = r.iter().find(|x| **x != zero).cloned().unwrap_or_else(T::zero);
    if first < zero { -r } else { r }
}
