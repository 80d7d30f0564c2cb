//! Signs. A pose `S` and `-S` are the same rigid motion (as are `q` and `-q` for quaternions);
//! this file fixes the sign where a representation must be unique (`gam pose`) and gives the
//! short-way slerp. The sign alignment of a sequence (Jüttler's rule (24)) is
//! [`crate::trajectory::align_signs`].
//!
//! ```
//! use motion::{Pose, repr::sign::canonical_pose};
//! let b = Pose::rotation(&[0.0, 0.0, 1.0], &3.5).unwrap(); // scalar part cos(1.75) < 0
//! assert_eq!(canonical_pose(&b), -&b);
//! ```

use crate::{MotionError, Pose};
use algebra_core::{Real, Ring};

/// The slerp of eq. (15) the short way: with `b` replaced by `-b` (the same pose) when the
/// rotational parts of `a` and `b` have a negative inner product (the `q0·q1 ≥ 0` rule, by
/// [`crate::trajectory::align_signs`]), so the rotation angle of the motion is at most π.
///
/// ```
/// use motion::{Pose, repr::sign::slerp_short};
/// let a = Pose::<f64>::identity();
/// let b = -&Pose::rotation(&[0.0, 0.0, 1.0], &1.0).unwrap();
/// let mid = slerp_short(&a, &b, &0.5).unwrap();
/// assert!(mid.is_equivalent(&Pose::rotation(&[0.0, 0.0, 1.0], &0.5).unwrap(), &1e-15).unwrap());
/// ```
pub fn slerp_short<T: Real>(a: &Pose<T>, b: &Pose<T>, t: &T) -> Result<Pose<T>, MotionError> {
    let mut pair = [a.clone(), b.clone()];
    crate::trajectory::align_signs(&mut pair);
    Pose::slerp(a, &pair[1], t)
}

/// `±c` with the first non-zero entry of `c[lead..]`'s sign rule: `c[0] > 0`, or at `c[0] = 0`
/// the first non-zero coefficient (in the given order) positive.
fn canonical_sign<T: Ring + PartialOrd, const N: usize>(c: [T; N]) -> [T; N] {
    let first = c.iter().find(|x| !x.is_exact_zero());
    match first {
        Some(x) if *x < T::zero() => c.map(|x| x.neg_ref()),
        _ => c,
    }
}

/// The sign of `gam pose`'s `motor`: scalar part `≥ 0`, at a scalar part of 0 the first
/// non-zero coefficient in basis order `[S∅, S12, S13, S23, S1∞, S2∞, S3∞, Sω]` positive.
///
/// ```
/// use motion::{Pose, repr::sign::canonical_pose};
/// let s = -&Pose::<f64>::identity();
/// assert_eq!(canonical_pose(&s), Pose::identity());
/// ```
pub fn canonical_pose<T: Ring + PartialOrd>(s: &Pose<T>) -> Pose<T> {
    Pose::from_array(canonical_sign(s.to_array()))
}

/// The sign of `gam pose`'s `quaternion` `[w, x, y, z]`: `w ≥ 0`, at `w = 0` the first
/// non-zero of `x, y, z` positive.
///
/// ```
/// assert_eq!(motion::repr::sign::canonical_quaternion([0.0, 0.0, -1.0, 1.0]), [0.0, 0.0, 1.0, -1.0]);
/// ```
pub fn canonical_quaternion<T: Ring + PartialOrd>(q: [T; 4]) -> [T; 4] {
    canonical_sign(q)
}
