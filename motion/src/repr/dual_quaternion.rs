//! Dual quaternions in Jüttler's conventions (his Sec. 1), on the workspace's
//! [`DualQuaternion`] (Hamilton products, `Q = Q⁰ + ε Q^ε`).
//!
//! **The pose map, stated once.** A pose `S` of the main paper and the dual quaternion `Q`
//! describe the same rigid motion `x ↦ R x + t` when `Q` acts by Jüttler's eq. (12),
//! `y0 = (Q⁰ Q̃⁰) x0`, `y = Du Vec(Q (2x0 + ε x) Q̃⁰)`; the map is
//! [`DualQuaternion::from_pose`] (the Appendix 2 isomorphism followed by the combined
//! conjugate, because `F_{UV} = F_V F_U`), giving for the unit `S = R T` the unit
//! `Q = q + ε ½ t q` (`q` the rotation's unit quaternion, the same sign as `S`'s scalar part),
//! i.e. Jüttler's `(2 + ε t) * q` of eq. (7) halved ([`to_dual_quaternion`],
//! [`from_dual_quaternion`]). Proportional dual quaternions are the same motion.
//!
//! ```
//! use motion::{Pose, repr::dual_quaternion::{from_dual_quaternion, point_image, to_dual_quaternion}};
//! let s = Pose::<f64>::from_axis_angle_translation(&[0.0, 0.0, 1.0], &1.0, &[1.0, 2.0, 3.0]).unwrap();
//! let q = to_dual_quaternion(&s).unwrap();
//! let y = point_image(&q, &[1.0, 0.5, 0.0, 0.0]);
//! let p = s.transform_point(&[0.5, 0.0, 0.0]).unwrap();
//! assert!((0..3).all(|i| (y[i + 1] / y[0] - p[i]).abs() < 1e-15));
//! assert!(from_dual_quaternion(&q, &1e-9).unwrap().is_equivalent(&s, &1e-15).unwrap());
//! ```

use crate::repr::ReprError;
use crate::{Motor, Pose};
use algebra_core::{Field, Real, Ring};
pub use gam_algebras::DualQuaternion;
pub use gam_algebras::dual_quaternion::Quaternion;

/// Plücker's (Study's) relation (8): `Du(Q Q̃) = q⁰ q^ε + q⁰·q^ε`, zero for a rigid motion.
///
/// ```
/// use gam_algebras::DualQuaternion;
/// let q = DualQuaternion::from_coeffs([1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0]);
/// assert_eq!(motion::repr::dual_quaternion::study_residual(&q), 0.0);
/// ```
pub fn study_residual<T: Ring>(q: &DualQuaternion<T>) -> T {
    q.real.dot(&q.dual)
}

/// The residual of (8) relative to `|Q⁰| |Q^ε|`: the cosine of the angle between the real and
/// dual parts as 4-vectors (zero when the dual part is zero). Invariant under scaling `Q` and
/// under the choice of length unit.
///
/// ```
/// use gam_algebras::DualQuaternion;
/// let q = DualQuaternion::from_coeffs([1.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0]);
/// assert_eq!(motion::repr::dual_quaternion::study_cosine(&q), 1.0);
/// ```
pub fn study_cosine<T: Real>(q: &DualQuaternion<T>) -> T {
    // the dot product of the two directions, so that no square under- or overflows (a dual
    // quaternion of size 1e-200 or 1e200 has the cosine of its unit multiple, issue 30)
    let parts = |x: &Quaternion<T>| [x.w.clone(), x.x.clone(), x.y.clone(), x.z.clone()];
    match (crate::scaled::direction(&parts(&q.real)), crate::scaled::direction(&parts(&q.dual))) {
        (Some(r), Some(d)) => r.iter().zip(&d).fold(T::zero(), |acc, (a, b)| acc.add_ref(&a.mul_ref(b))),
        _ => T::zero(),
    }
}

/// The closest point of the Study quadric with the same real part: `Q^ε - (Q⁰·Q^ε/|Q⁰|²) Q⁰`
/// (the orthogonal projection of the dual part onto the complement of the real part). Exact
/// over rationals. Fails when the real part is zero.
///
/// ```
/// use algebra_core::rational::q;
/// use gam_algebras::DualQuaternion;
/// use motion::repr::dual_quaternion::{project_to_study, study_residual};
/// let x = DualQuaternion::from_coeffs([q(1), q(1), q(0), q(0), q(3), q(1), q(2), q(0)]);
/// assert_eq!(study_residual(&project_to_study(&x).unwrap()), q(0));
/// ```
pub fn project_to_study<T: Field>(q: &DualQuaternion<T>) -> Result<DualQuaternion<T>, ReprError> {
    let inv = q.real.norm_squared().try_recip().ok_or(ReprError::ZeroRealPart)?;
    let k = study_residual(q).mul_ref(&inv);
    let (r, d) = (&q.real, &q.dual);
    let f = |x: &T, y: &T| x.sub_ref(&k.mul_ref(y));
    let dual = Quaternion::new(f(&d.w, &r.w), f(&d.x, &r.x), f(&d.y, &r.y), f(&d.z, &r.z));
    Ok(DualQuaternion::new(r.clone(), dual))
}

/// `Trans(Q) = Q Q̃⁰` (eq. 9): `|Q⁰|² + ε Q^ε Q̃⁰`, the translation `2 v0 + ε v` of (5) with
/// displacement `2 Vec(Q^ε Q̃⁰)/|Q⁰|²`.
///
/// ```
/// use gam_algebras::DualQuaternion;
/// let t = DualQuaternion::from_coeffs([0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0]);
/// let tr = motion::repr::dual_quaternion::trans(&t);
/// assert_eq!(tr.coeffs(), [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0]); // translation by (0, 2, 0)
/// ```
pub fn trans<T: Ring>(q: &DualQuaternion<T>) -> DualQuaternion<T> {
    let rc = q.real.conjugate();
    DualQuaternion::new(&q.real * &rc, &q.dual * &rc)
}

/// `Rot(Q) = Q⁰/(Q⁰ Q̃⁰)` (eq. 9), as printed (a quaternion of norm `1/|Q⁰|`; its rotation is
/// that of `Q`). Fails when the real part is zero.
///
/// ```
/// use gam_algebras::{DualQuaternion, dual_quaternion::Quaternion};
/// let q = DualQuaternion::from_coeffs([2.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
/// assert_eq!(motion::repr::dual_quaternion::rot(&q).unwrap(), Quaternion::new(0.5, 0.0, 0.0, 0.0));
/// ```
pub fn rot<T: Field>(q: &DualQuaternion<T>) -> Result<Quaternion<T>, ReprError> {
    let inv = q.real.norm_squared().try_recip().ok_or(ReprError::ZeroRealPart)?;
    Ok(q.real.scale(&inv))
}

/// Jüttler's rotation matrix `U` (eq. 11) of a quaternion `D = d0 + d`: `|D|²` times the
/// rotation matrix of `D`; no square root, exact over rationals.
///
/// ```
/// use gam_algebras::dual_quaternion::Quaternion;
/// let u = motion::repr::dual_quaternion::matrix_u(&Quaternion::new(1.0, 0.0, 0.0, 1.0));
/// assert_eq!(u, [[0.0, -2.0, 0.0], [2.0, 0.0, 0.0], [0.0, 0.0, 2.0]]); // 2 × quarter turn about z
/// ```
pub fn matrix_u<T: Ring>(d: &Quaternion<T>) -> [[T; 3]; 3] {
    let (d0, d1, d2, d3) = (&d.w, &d.x, &d.y, &d.z);
    let sq = |x: &T| x.mul_ref(x);
    let two = |x: T| x.add_ref(&x);
    let (s0, s1, s2, s3) = (sq(d0), sq(d1), sq(d2), sq(d3));
    [
        [
            s0.add_ref(&s1).sub_ref(&s2).sub_ref(&s3),
            two(d1.mul_ref(d2).sub_ref(&d0.mul_ref(d3))),
            two(d0.mul_ref(d2).add_ref(&d1.mul_ref(d3))),
        ],
        [
            two(d0.mul_ref(d3).add_ref(&d1.mul_ref(d2))),
            s0.add_ref(&s2).sub_ref(&s1).sub_ref(&s3),
            two(d2.mul_ref(d3).sub_ref(&d0.mul_ref(d1))),
        ],
        [
            two(d1.mul_ref(d3).sub_ref(&d0.mul_ref(d2))),
            two(d0.mul_ref(d1).add_ref(&d2.mul_ref(d3))),
            s0.add_ref(&s3).sub_ref(&s1).sub_ref(&s2),
        ],
    ]
}

/// Jüttler's 4x4 matrix `M` (eq. 10), homogeneous coordinates **weight first**
/// (`x = (x0, x1, x2, x3)`, eq. 1), for `Q = (2 v0 + ε v) * D` written with `D = Q⁰`,
/// `v0 = ½`, `v = Q^ε Q̃⁰/|Q⁰|²`: `M = [[|Q⁰|²/2, 0], [Vec(Q^ε Q̃⁰), U(Q⁰)/2]]`. `Q` should
/// satisfy (8) (then `Q^ε Q̃⁰` is a pure vector). Exact over rationals.
///
/// ```
/// use gam_algebras::DualQuaternion;
/// // Q = 1 + ε(1/2)(2, 0, 0): the translation by (2, 0, 0)
/// let m = motion::repr::dual_quaternion::matrix_m(&DualQuaternion::from_coeffs([1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0]));
/// assert_eq!(m[0], [0.5, 0.0, 0.0, 0.0]);
/// assert_eq!(m[1], [1.0, 0.5, 0.0, 0.0]); // y1 = (x0 + 0.5 x1)/0.5 x0 = x + 2 for x0 = 1
/// ```
pub fn matrix_m<T: Field>(q: &DualQuaternion<T>) -> [[T; 4]; 4] {
    let half = T::from_ratio(1, 2);
    let u = matrix_u(&q.real);
    let v = (&q.dual * &q.real.conjugate()).vector();
    let z = T::zero;
    let row = |i: usize| [v[i].clone(), u[i][0].mul_ref(&half), u[i][1].mul_ref(&half), u[i][2].mul_ref(&half)];
    [[q.real.norm_squared().mul_ref(&half), z(), z(), z()], row(0), row(1), row(2)]
}

/// Euler's parameters of a rotation quaternion `D ≠ 0` (eq. 6): `E = D/|D|`.
///
/// ```
/// use gam_algebras::dual_quaternion::Quaternion;
/// let e = motion::repr::dual_quaternion::euler_parameters(&Quaternion::new(0.0, 0.0, 0.0, 2.0)).unwrap();
/// assert_eq!(e, Quaternion::new(0.0, 0.0, 0.0, 1.0));
/// ```
pub fn euler_parameters<T: Real>(d: &Quaternion<T>) -> Result<Quaternion<T>, ReprError> {
    let n =
        crate::scaled::length(&[d.w.clone(), d.x.clone(), d.y.clone(), d.z.clone()]).ok_or(ReprError::ZeroRealPart)?;
    Ok(d.scale(&T::one().div_ref(&n)))
}

/// Axis `r` (unit) and angle `φ ∈ [0, 2π]` of `D = |D| (cos φ/2 + sin φ/2 r)` (eq. 6); the
/// axis is `[0, 0, 0]` when `D` is real (no rotation, or a full turn).
///
/// ```
/// use gam_algebras::dual_quaternion::Quaternion;
/// let (r, phi) = motion::repr::dual_quaternion::axis_angle(&Quaternion::new(1.0, 0.0, 0.0, 1.0)).unwrap();
/// assert_eq!(r, [0.0, 0.0, 1.0]);
/// assert!((phi - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
/// ```
pub fn axis_angle<T: Real>(d: &Quaternion<T>) -> Result<([T; 3], T), ReprError> {
    let e = euler_parameters(d)?;
    let v = e.vector();
    let s = crate::repr::vec3::norm(&v);
    let axis = crate::scaled::direction(&v).unwrap_or_else(crate::repr::vec3::zero);
    Ok((axis, Real::atan2(&s, &e.w).mul_ref(&T::from_i64(2))))
}

/// The image (12) of the point with homogeneous coordinates `x = (x0, x1, x2, x3)` (weight
/// first): `y0 = (Q⁰ Q̃⁰) x0`, `y = Du Vec(Q (2x0 + ε x) Q̃⁰)`; for `Q` on the Study quadric
/// `y/y0` is the affine image of `x/x0`.
///
/// ```
/// use gam_algebras::DualQuaternion;
/// let t = DualQuaternion::from_coeffs([1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0]); // by (2, 0, 0)
/// let y = motion::repr::dual_quaternion::point_image(&t, &[1.0, 1.0, 1.0, 1.0]);
/// assert_eq!([y[1] / y[0], y[2] / y[0], y[3] / y[0]], [3.0, 1.0, 1.0]);
/// ```
pub fn point_image<T: Ring>(q: &DualQuaternion<T>, x: &[T; 4]) -> [T; 4] {
    let two_x0 = x[0].add_ref(&x[0]);
    let p = DualQuaternion::new(
        Quaternion::new(two_x0, T::zero(), T::zero(), T::zero()),
        Quaternion::pure(&[x[1].clone(), x[2].clone(), x[3].clone()]),
    );
    let rc = DualQuaternion::from_real(q.real.conjugate());
    let image = &(q * &p) * &rc;
    let y0 = q.real.norm_squared().mul_ref(&x[0]);
    let [yx, yy, yz] = image.dual.vector();
    [y0, yx, yy, yz]
}

/// The dual quaternion of a pose (module docs): the unit `q + ε ½ t q` of its unitization, of
/// the same sign as the pose's scalar part. Fails for singular poses.
///
/// ```
/// use motion::{Pose, repr::dual_quaternion::to_dual_quaternion};
/// let q = to_dual_quaternion(&Pose::translation(&[2.0, 0.0, 0.0])).unwrap();
/// assert_eq!(q.coeffs(), [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
/// ```
pub fn to_dual_quaternion<T: Real>(s: &Pose<T>) -> Result<DualQuaternion<T>, ReprError> {
    let [a, b, c, d, e, f, g, h] = (s.unitize()?).to_array();
    Ok(DualQuaternion::from_pose(&Motor::new(a, b, c, d, e, f, g, h)))
}

/// The dual quaternion of a pose without normalising (the pose map of the module docs applied
/// to the coefficients): exact over rationals, linear, and on the Study quadric exactly when
/// `rev(S) S` has no `ω` part.
///
/// ```
/// use algebra_core::rational::q;
/// use motion::{Pose, repr::dual_quaternion::{study_residual, to_dual_quaternion_exact}};
/// let s = Pose::rotor_from_parts(&q(1), &q(2), &[q(0), q(1), q(0)]) * Pose::translation(&[q(1), q(2), q(3)]);
/// assert_eq!(study_residual(&to_dual_quaternion_exact(&s)), q(0));
/// ```
pub fn to_dual_quaternion_exact<T: Ring>(s: &Pose<T>) -> DualQuaternion<T> {
    let [a, b, c, d, e, f, g, h] = s.to_array();
    DualQuaternion::from_pose(&Motor::new(a, b, c, d, e, f, g, h))
}

/// The pose of a dual quaternion on the Study quadric, exactly (over rationals): Plücker's
/// relation (8) must hold exactly and the real part be non-zero; the inverse of
/// [`to_dual_quaternion_exact`].
///
/// ```
/// use algebra_core::rational::q;
/// use motion::{Pose, repr::dual_quaternion::{from_dual_quaternion_exact, to_dual_quaternion_exact}};
/// let s = Pose::rotor_from_parts(&q(1), &q(2), &[q(0), q(1), q(0)]) * Pose::translation(&[q(1), q(2), q(3)]);
/// assert_eq!(from_dual_quaternion_exact(&to_dual_quaternion_exact(&s)).unwrap(), s);
/// ```
pub fn from_dual_quaternion_exact<T: Field>(q: &DualQuaternion<T>) -> Result<Pose<T>, ReprError> {
    if q.real.norm_squared().is_exact_zero() {
        return Err(ReprError::ZeroRealPart);
    }
    let residual = study_residual(q);
    if !residual.is_exact_zero() {
        // |cosine| in f64, for the message
        let den = (q.real.norm_squared().magnitude() * q.dual.norm_squared().magnitude()).sqrt();
        return Err(ReprError::OffStudyQuadric { cosine: residual.magnitude() / den });
    }
    Ok(Pose::from_motor(q.to_pose()))
}

/// The pose of a dual quaternion acting by (12) (module docs): any `Q` with a non-zero real
/// part on the Study quadric, to `tol` in [`study_cosine`]; proportional `Q` give equivalent
/// poses (the result is `Q`'s image, not unitized).
///
/// ```
/// use gam_algebras::DualQuaternion;
/// use motion::repr::{ReprError, dual_quaternion::from_dual_quaternion};
/// let off = DualQuaternion::from_coeffs([1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
/// assert!(matches!(from_dual_quaternion(&off, &1e-9), Err(ReprError::OffStudyQuadric { .. })));
/// ```
pub fn from_dual_quaternion<T: Real>(q: &DualQuaternion<T>, tol: &T) -> Result<Pose<T>, ReprError> {
    if q.coeffs().iter().any(|x| !Real::is_finite(x)) {
        return Err(ReprError::NotFinite);
    }
    // zero means every component zero: |Q⁰|² of a real part of size 1e-200 underflows to 0
    if [&q.real.w, &q.real.x, &q.real.y, &q.real.z].into_iter().all(Ring::is_exact_zero) {
        return Err(ReprError::ZeroRealPart);
    }
    let cosine = study_cosine(q);
    if Real::abs(&cosine) > *tol {
        return Err(ReprError::OffStudyQuadric { cosine: cosine.to_f64() });
    }
    Ok(Pose::from_motor(q.to_pose()))
}
