//! Signs. A pose `S` and `-S` are the same rigid motion (as are `q` and `-q` for quaternions);
//! this file fixes the sign where a representation must be unique (`gam pose`), aligns the
//! signs of a sequence the short way (Jüttler's rule (24)), and gives the short-way slerp.
//!
//! ```
//! use motion::{Pose, repr::sign::align_signs};
//! let a = Pose::rotation(&[0.0, 0.0, 1.0], &3.0).unwrap();
//! let b = Pose::rotation(&[0.0, 0.0, 1.0], &3.5).unwrap(); // scalar part cos(1.75) < 0
//! let aligned = align_signs(&[a.clone(), -&b]);
//! assert_eq!(aligned, vec![a, b]);
//! ```

use crate::repr::bridge::{pose_from_array, pose_to_array};
use crate::{MotionError, Pose};
use algebra_core::{Real, Ring};

/// `S∅ R∅ + S12 R12 + S13 R13 + S23 R23`: the 4-space inner product of the rotational parts
/// (Jüttler's quaternions `R_i^(0)` up to positive factors).
fn rotational_dot<T: Ring>(a: &[T; 8], b: &[T; 8]) -> T {
    (0..4).fold(T::zero(), |s, i| s.add_ref(&a[i].mul_ref(&b[i])))
}

/// Jüttler's sign rule (24) on a sequence: the first pose is kept, every later one takes the
/// sign (`±S_i`, the same motion) whose rotational part is nearer its (already aligned)
/// predecessor's, i.e. a non-negative inner product; a tie (inner product exactly zero) keeps
/// the sign as given. Exact over rationals.
///
/// ```
/// use algebra_core::rational::q;
/// use motion::{Pose, repr::sign::align_signs};
/// let a = Pose::<algebra_core::rational::Q>::rotor_from_parts(&q(1), &q(1), &[q(0), q(0), q(1)]);
/// let b = Pose::rotor_from_parts(&q(-1), &q(1), &[q(0), q(0), q(-1)]);
/// assert_eq!(align_signs(&[a.clone(), b.clone()])[1], -&b);
/// ```
pub fn align_signs<T: Ring + PartialOrd>(poses: &[Pose<T>]) -> Vec<Pose<T>> {
    let mut out: Vec<Pose<T>> = Vec::with_capacity(poses.len());
    for p in poses {
        let flip = match out.last() {
            Some(prev) => rotational_dot(&pose_to_array(prev), &pose_to_array(p)) < T::zero(),
            None => false,
        };
        out.push(if flip { -p } else { p.clone() });
    }
    out
}

/// The slerp of eq. (15) the short way: with `b` replaced by `-b` (the same pose) when the
/// rotational parts of `a` and `b` have a negative inner product (the `q0·q1 ≥ 0` rule), so the
/// rotation angle of the motion is at most π.
///
/// ```
/// use motion::{Pose, repr::sign::slerp_short};
/// let a = Pose::<f64>::identity();
/// let b = -&Pose::rotation(&[0.0, 0.0, 1.0], &1.0).unwrap();
/// let mid = slerp_short(&a, &b, &0.5).unwrap();
/// assert!(mid.is_equivalent(&Pose::rotation(&[0.0, 0.0, 1.0], &0.5).unwrap(), &1e-15).unwrap());
/// ```
pub fn slerp_short<T: Real>(a: &Pose<T>, b: &Pose<T>, t: &T) -> Result<Pose<T>, MotionError> {
    let aligned = align_signs(&[a.clone(), b.clone()]);
    Pose::slerp(a, &aligned[1], t)
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
    pose_from_array(canonical_sign(pose_to_array(s)))
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
