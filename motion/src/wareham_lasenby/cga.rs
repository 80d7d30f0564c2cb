//! Wareham–Lasenby's vocabulary in R^{4,1} (Sec. 2.1-2.2): the null vectors `n`, `n̄`, the
//! embedding `F(x)` and its inverse, translators, rotation rotors, planes and the twist
//! `τ(ψ, P, a)` (Definition 4), all as generated [`gam_algebras::cga`] values.
//!
//! `cga` names: `e4` is the paper's `e` (`e² = 1`), `e5` its `ē` (`ē² = -1`), so `n = e4 + e5`,
//! `n̄ = e4 - e5`, `F(x) = (x² n + 2x - n̄)/2`. Rotors act by `X ↦ R X rev(R)`
//! ([`Motor::apply`]); `T_a = 1 + n a/2` maps `F(y)` to `F(y + a)`; the rotation rotor of angle
//! `ψ` about the unit axis `â` (right-handed) is `cos(ψ/2) + sin(ψ/2) P` with the plane
//! `P = -â e123` ([`plane`]).
//!
//! ```
//! use motion::wareham_lasenby::cga::{embed, embed_inverse, rotor, translator};
//! let r = &translator(&[1.0, 2.0, 3.0]) * &rotor(&[0.0, 0.0, 1.0], &std::f64::consts::FRAC_PI_2).unwrap();
//! let x = embed_inverse(&r.apply(&embed(&[1.0, 0.0, 0.0]))).unwrap();
//! assert!((x[0] - 1.0).abs() < 1e-15 && (x[1] - 3.0).abs() < 1e-15 && (x[2] - 3.0).abs() < 1e-15);
//! ```

use super::WlError;
use algebra_core::{Field, Real, Ring};
use gam_algebras::cga::{Bivector, Motor, Vector};

/// `n = e + ē = e4 + e5` (the point at infinity; `n² = 0`).
///
/// ```
/// let n = motion::wareham_lasenby::cga::n::<f64>();
/// assert_eq!((n * n).to_array().iter().map(|x: &f64| x.abs()).sum::<f64>(), 0.0);
/// ```
pub fn n<T: Ring>() -> Vector<T> {
    Vector::new(T::zero(), T::zero(), T::zero(), T::one(), T::one())
}

/// `n̄ = e - ē = e4 - e5` (the origin up to scale: `F(0) = -n̄/2`; `n·n̄ = 2`).
///
/// ```
/// use motion::wareham_lasenby::cga::{embed, nbar};
/// assert_eq!(embed(&[0.0, 0.0, 0.0]), nbar::<f64>() * -0.5);
/// ```
pub fn nbar<T: Ring>() -> Vector<T> {
    Vector::new(T::zero(), T::zero(), T::zero(), T::one(), T::one().neg_ref())
}

/// The embedding `F(x) = (x² n + 2x - n̄)/2` of a point of R^3 (a null vector, `F(x)·n = -1`).
///
/// ```
/// let f = motion::wareham_lasenby::cga::embed(&[1.0, 2.0, 2.0]);
/// assert_eq!(f.to_array(), [1.0, 2.0, 2.0, 4.0, 5.0]); // e4 = (x² - 1)/2, e5 = (x² + 1)/2
/// ```
pub fn embed<T: Ring>(x: &[T; 3]) -> Vector<T> {
    let x2 = dot(x, x);
    let half = T::from_ratio(1, 2);
    Vector::new(
        x[0].clone(),
        x[1].clone(),
        x[2].clone(),
        x2.sub_ref(&T::one()).mul_ref(&half),
        x2.add_ref(&T::one()).mul_ref(&half),
    )
}

/// The inverse of [`embed`] on homogeneous points: `X = λ F(x)` with `λ = -X·n = X5 - X4 ≠ 0`
/// gives `x = (X1, X2, X3)/λ`. Fails ([`WlError::NotAPoint`]) when `X·n = 0` (a point at infinity,
/// a plane through it, or zero). The null condition `X² = 0` is not checked.
///
/// ```
/// use motion::wareham_lasenby::cga::{embed, embed_inverse, n};
/// assert_eq!(embed_inverse(&(embed(&[1.0, -2.0, 0.5]) * 3.0)).unwrap(), [1.0, -2.0, 0.5]);
/// assert!(embed_inverse(&n::<f64>()).is_err());
/// ```
pub fn embed_inverse<T: Field>(x: &Vector<T>) -> Result<[T; 3], WlError> {
    let lambda = x.e5.sub_ref(&x.e4);
    let inv =
        lambda.try_recip().filter(Ring::is_finite_value).ok_or_else(|| WlError::NotAPoint { value: x.to_string() })?;
    Ok([x.e1.mul_ref(&inv), x.e2.mul_ref(&inv), x.e3.mul_ref(&inv)])
}

/// The translator `T_a = 1 + n a/2`: `T_a F(y) rev(T_a) = F(y + a)`.
///
/// ```
/// use motion::wareham_lasenby::cga::{embed, translator};
/// let t = translator(&[1.0, 2.0, 3.0]);
/// assert_eq!(t.apply(&embed(&[0.0, 0.0, 0.0])), embed(&[1.0, 2.0, 3.0]));
/// ```
pub fn translator<T: Ring>(a: &[T; 3]) -> Motor<T> {
    // n a = Σ a_i (e4 e_i + e5 e_i) = -Σ a_i (e_i4 + e_i5)
    let h = a.each_ref().map(|x| x.mul_ref(&T::from_ratio(-1, 2)));
    let mut m = Motor::one();
    m.e14 = h[0].clone();
    m.e24 = h[1].clone();
    m.e34 = h[2].clone();
    m.e15 = h[0].clone();
    m.e25 = h[1].clone();
    m.e35 = h[2].clone();
    m
}

/// The unit plane `P = -â e123` (`P² = -1`) whose rotor `cos(ψ/2) + sin(ψ/2) P` turns by `ψ`
/// about `â` (right-handed); `â` is used as given (unit for a unit plane).
///
/// ```
/// let p = motion::wareham_lasenby::cga::plane(&[0.0, 0.0, 1.0]);
/// assert_eq!((p.e12, p.e13, p.e23), (-1.0, 0.0, 0.0));
/// ```
pub fn plane<T: Ring>(axis: &[T; 3]) -> Bivector<T> {
    let mut b = Bivector::zero();
    b.e12 = axis[2].neg_ref();
    b.e13 = axis[1].clone();
    b.e23 = axis[0].neg_ref();
    b
}

/// The rotation rotor `R = cos(ψ/2) + sin(ψ/2) P` (`P` = [`plane`] of the normalised axis):
/// `R F(x) rev(R) = F(Rot(â, ψ) x)`. Fails for a zero or non-finite axis.
///
/// ```
/// use motion::wareham_lasenby::cga::{embed, embed_inverse, rotor};
/// let r = rotor(&[0.0, 0.0, 2.0], &std::f64::consts::FRAC_PI_2).unwrap();
/// let y = embed_inverse(&r.apply(&embed(&[1.0, 0.0, 0.0]))).unwrap();
/// assert!(y[0].abs() < 1e-15 && (y[1] - 1.0).abs() < 1e-15);
/// ```
pub fn rotor<T: Real>(axis: &[T; 3], angle: &T) -> Result<Motor<T>, WlError> {
    let a = unit(axis).ok_or_else(|| WlError::ZeroAxis { value: format!("{axis:?}") })?;
    let half = angle.mul_ref(&T::from_ratio(1, 2));
    Ok(rotation_part(&half.cos(), &half.sin(), &a))
}

/// `c + s P` for the plane of `a`.
pub(crate) fn rotation_part<T: Ring>(c: &T, s: &T, a: &[T; 3]) -> Motor<T> {
    let p = plane(a);
    let mut m = Motor::zero();
    m.scalar = c.clone();
    m.e12 = p.e12.mul_ref(s);
    m.e13 = p.e13.mul_ref(s);
    m.e23 = p.e23.mul_ref(s);
    m
}

/// The twist `τ(ψ, P, a) = [cos(ψ/2) + sin(ψ/2) P][1 + n a/2]` of Definition 4 (W-L Sec. 2.4):
/// translate by `a`, then rotate by `ψ` in the plane `P` (given by its axis, normalised).
///
/// ```
/// use motion::wareham_lasenby::cga::{embed, embed_inverse, twist};
/// let tau = twist(&std::f64::consts::PI, &[0.0, 0.0, 1.0], &[1.0, 0.0, 5.0]).unwrap();
/// let y = embed_inverse(&tau.apply(&embed(&[0.0, 0.0, 0.0]))).unwrap();
/// assert!((y[0] + 1.0).abs() < 1e-15 && y[1].abs() < 1e-15 && (y[2] - 5.0).abs() < 1e-15);
/// ```
pub fn twist<T: Real>(psi: &T, axis: &[T; 3], a: &[T; 3]) -> Result<Motor<T>, WlError> {
    Ok(&rotor(axis, psi)? * &translator(a))
}

pub(crate) fn dot<T: Ring>(x: &[T; 3], y: &[T; 3]) -> T {
    x[0].mul_ref(&y[0]).add_ref(&x[1].mul_ref(&y[1])).add_ref(&x[2].mul_ref(&y[2]))
}

/// `x × y`: the one copy in the representations' vector helpers.
pub(crate) use crate::repr::vec3::cross;

/// `x/|x|` (divided by the largest component first), `None` for zero or non-finite `x`.
pub(crate) fn unit<T: Real>(x: &[T; 3]) -> Option<[T; 3]> {
    if !x.iter().all(Real::is_finite) {
        return None;
    }
    let m = x.iter().map(Real::abs).fold(T::zero(), |a, b| if b > a { b } else { a });
    let inv_m = m.try_recip()?;
    let y = x.each_ref().map(|c| c.mul_ref(&inv_m));
    let inv = Real::sqrt(&dot(&y, &y)).try_recip()?;
    Some(y.map(|c| c.mul_ref(&inv)))
}
