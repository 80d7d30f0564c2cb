//! Trajectories of body points under a Q-motion as rational Bézier curves (Jüttler Sec. 1,
//! after (13)): by (12) the image of `x` is `y0 = |Q⁰(t)|²`, `y = Du Vec(Q(t) (2 + ε x) Q̃⁰(t))`,
//! a product of two Bézier polynomials of degree `n`, so its homogeneous control points
//! (weight first) follow from the product formula (29): degree `2n`, exact over rationals.
//!
//! ```
//! use algebra_core::rational::{q, ratio};
//! use gam_algebras::DualQuaternion;
//! use motion::juttler::QMotion;
//! // a quarter turn about z: the trajectory of (1, 0, 0) is a rational quadratic circle arc
//! let d = |c: [i64; 8]| DualQuaternion::from_coeffs(c.map(q));
//! let m = QMotion::new_exact(vec![d([1, 0, 0, 0, 0, 0, 0, 0]), d([1, 0, 0, 1, 0, 0, 0, 0])]).unwrap();
//! let arc = m.trajectory(&[q(1), q(0), q(0)]);
//! assert_eq!(arc.degree(), 2);
//! assert_eq!(arc.weights(), [q(1), q(1), q(2)]);
//! assert_eq!(arc.point(&q(1)).unwrap(), [q(0), q(1), q(0)]);
//! ```

use super::{JuttlerError, QMotion, bernstein_product, de_casteljau_with, elevate_with};
use crate::repr::dual_quaternion::{DualQuaternion, Quaternion};
use algebra_core::{Field, Ring};

/// A rational Bézier curve in R³ by its homogeneous control points `(w_i, w_i p_i)`, weight
/// first (Jüttler's coordinates (1)), on `[0, 1]`.
///
/// ```
/// use algebra_core::rational::{q, ratio};
/// use motion::juttler::RationalBezier;
/// // the quarter circle (1 - t², 2t)/(1 + t²)
/// let c = RationalBezier::new(vec![[q(1), q(1), q(0), q(0)], [q(1), q(1), q(1), q(0)], [q(2), q(0), q(2), q(0)]]).unwrap();
/// assert_eq!(c.point(&ratio(1, 2)).unwrap(), [ratio(3, 5), ratio(4, 5), q(0)]);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct RationalBezier<T> {
    control: Vec<[T; 4]>,
}

pub(crate) fn lerp4<T: Ring>(a: &[T; 4], b: &[T; 4], s: &T, t: &T) -> [T; 4] {
    std::array::from_fn(|k| a[k].mul_ref(s).add_ref(&b[k].mul_ref(t)))
}

impl<T: Ring> RationalBezier<T> {
    /// The curve with homogeneous control points `(w_i, w_i p_i)`; fails when there are none.
    ///
    /// ```
    /// let c = motion::juttler::RationalBezier::new(vec![[1.0, 2.0, 3.0, 4.0]]).unwrap();
    /// assert_eq!(c.degree(), 0);
    /// assert!(motion::juttler::RationalBezier::<f64>::new(vec![]).is_err());
    /// ```
    pub fn new(control: Vec<[T; 4]>) -> Result<Self, JuttlerError> {
        if control.is_empty() {
            return Err(JuttlerError::TooFewPositions { need: 1, got: 0 });
        }
        Ok(RationalBezier { control })
    }

    /// The curve with these (non-empty) homogeneous control points, unchecked.
    pub(crate) fn from_control_unchecked(control: Vec<[T; 4]>) -> Self {
        RationalBezier { control }
    }

    /// The homogeneous control points `(w_i, w_i p_i)`.
    ///
    /// ```
    /// let c = motion::juttler::RationalBezier::new(vec![[2.0, 2.0, 0.0, 0.0]]).unwrap();
    /// assert_eq!(c.control(), [[2.0, 2.0, 0.0, 0.0]]);
    /// ```
    pub fn control(&self) -> &[[T; 4]] {
        &self.control
    }

    /// The degree.
    ///
    /// ```
    /// let c = motion::juttler::RationalBezier::new(vec![[1.0, 0.0, 0.0, 0.0]; 3]).unwrap();
    /// assert_eq!(c.degree(), 2);
    /// ```
    pub fn degree(&self) -> usize {
        self.control.len() - 1
    }

    /// The weights `w_i`.
    ///
    /// ```
    /// let c = motion::juttler::RationalBezier::new(vec![[2.0, 2.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]]).unwrap();
    /// assert_eq!(c.weights(), [2.0, 1.0]);
    /// ```
    pub fn weights(&self) -> Vec<T> {
        self.control.iter().map(|c| c[0].clone()).collect()
    }

    /// The homogeneous point `(w(t), w(t) p(t))` by de Casteljau, at any `t`.
    ///
    /// ```
    /// let c = motion::juttler::RationalBezier::new(vec![[1.0, 0.0, 0.0, 0.0], [3.0, 3.0, 0.0, 0.0]]).unwrap();
    /// assert_eq!(c.homogeneous(&0.5), [2.0, 1.5, 0.0, 0.0]);
    /// ```
    pub fn homogeneous(&self, t: &T) -> [T; 4] {
        de_casteljau_with(&self.control, t, lerp4)
    }

    /// The same curve with degree one higher (exact).
    ///
    /// ```
    /// let c = motion::juttler::RationalBezier::new(vec![[1.0, 0.0, 0.0, 0.0], [3.0, 3.0, 0.0, 0.0]]).unwrap();
    /// assert_eq!(c.elevate().control()[1], [2.0, 1.5, 0.0, 0.0]);
    /// ```
    pub fn elevate(&self) -> Self {
        RationalBezier { control: elevate_with(&self.control, |a, s, b, t| lerp4(a, b, s, t)) }
    }

    /// The homogeneous derivative `d/dt (w, w p)`: `n Σ (H_{i+1} - H_i) b_i^{n-1}(t)`.
    fn hodograph(&self, t: &T) -> [T; 4] {
        if self.control.len() == 1 {
            return std::array::from_fn(|_| T::zero());
        }
        let n = T::from_i64(self.degree() as i64);
        let diff: Vec<[T; 4]> =
            self.control.windows(2).map(|w| std::array::from_fn(|k| w[1][k].sub_ref(&w[0][k]).mul_ref(&n))).collect();
        de_casteljau_with(&diff, t, lerp4)
    }
}

impl<T: Field> RationalBezier<T> {
    /// The affine control points `p_i`; fails for a weight zero (a control point at infinity).
    ///
    /// ```
    /// let c = motion::juttler::RationalBezier::new(vec![[2.0, 2.0, 4.0, 0.0]]).unwrap();
    /// assert_eq!(c.points().unwrap(), [[1.0, 2.0, 0.0]]);
    /// ```
    pub fn points(&self) -> Result<Vec<[T; 3]>, JuttlerError> {
        self.control.iter().enumerate().map(|(i, c)| affine(c, || format!("control point {i}"))).collect()
    }

    /// The point `p(t)` (exact over rationals); fails where the weight `w(t)` is zero.
    ///
    /// ```
    /// let c = motion::juttler::RationalBezier::new(vec![[1.0, 0.0, 0.0, 0.0], [-1.0, 0.0, 0.0, 0.0]]).unwrap();
    /// assert!(c.point(&0.5).is_err());
    /// ```
    pub fn point(&self, t: &T) -> Result<[T; 3], JuttlerError> {
        affine(&self.homogeneous(t), || format!("t = {t}"))
    }

    /// The velocity `p'(t) = (Y' w - Y w')/w²` of `p = Y/w` (exact over rationals); fails
    /// where `w(t)` is zero.
    ///
    /// ```
    /// // p(t) = (3t, 0, 0)/(1 + 2t): p'(0) = (3, 0, 0)
    /// let c = motion::juttler::RationalBezier::new(vec![[1.0, 0.0, 0.0, 0.0], [3.0, 3.0, 0.0, 0.0]]).unwrap();
    /// assert_eq!(c.derivative(&0.0).unwrap(), [3.0, 0.0, 0.0]);
    /// ```
    pub fn derivative(&self, t: &T) -> Result<[T; 3], JuttlerError> {
        let h = self.homogeneous(t);
        let d = self.hodograph(t);
        let inv = super::recip_or(&h[0].mul_ref(&h[0]), || format!("t = {t}"))?;
        Ok(std::array::from_fn(|k| d[k + 1].mul_ref(&h[0]).sub_ref(&h[k + 1].mul_ref(&d[0])).mul_ref(&inv)))
    }
}

/// `(w, w p) ↦ p`, or [`JuttlerError::ZeroWeight`].
pub(crate) fn affine<T: Field>(h: &[T; 4], what: impl FnOnce() -> String) -> Result<[T; 3], JuttlerError> {
    let inv = super::recip_or(&h[0], what)?;
    Ok([h[1].mul_ref(&inv), h[2].mul_ref(&inv), h[3].mul_ref(&inv)])
}

impl<T: Ring> QMotion<T> {
    /// The trajectory `t ↦ image of x` (eq. 12 with `x0 = 1`) as a rational Bézier curve of
    /// degree `2n` (exact over rationals): control points from the product formula (29)
    /// applied to `Q(t) (2 + ε x)` and `Q̃⁰(t)`.
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio};
    /// use gam_algebras::DualQuaternion;
    /// let d = |c: [i64; 8]| DualQuaternion::from_coeffs(c.map(q));
    /// let m = motion::juttler::QMotion::new_exact(vec![d([1, 0, 0, 0, 0, 0, 0, 0]), d([1, 0, 0, 1, 0, 0, 0, 0])]).unwrap();
    /// let x = [q(1), q(2), q(3)];
    /// let path = m.trajectory(&x);
    /// let t = ratio(1, 3);
    /// assert_eq!(path.point(&t).unwrap(), m.pose_exact(&t).unwrap().transform_point(&x).unwrap());
    /// ```
    pub fn trajectory(&self, x: &[T; 3]) -> RationalBezier<T> {
        let p =
            DualQuaternion::new(Quaternion::new(T::from_i64(2), T::zero(), T::zero(), T::zero()), Quaternion::pure(x));
        let left: Vec<DualQuaternion<T>> = self.control().iter().map(|b| b * &p).collect();
        let right: Vec<Quaternion<T>> = self.control().iter().map(|b| b.real.conjugate()).collect();
        let half = T::from_ratio(1, 2);
        let products = bernstein_product(
            &left,
            &right,
            DualQuaternion::zero(),
            |a, c| a * &DualQuaternion::from_real(c.clone()),
            |acc, h, f: &T| acc + &h.scale(f),
        );
        let control = products
            .iter()
            .map(|h| {
                let [y1, y2, y3] = h.dual.vector();
                [h.real.w.mul_ref(&half), y1, y2, y3]
            })
            .collect();
        RationalBezier { control }
    }
}

/// A motion whose body-point trajectories are rational Bézier curves (Jüttler's point of
/// view, Sec. 1): Q-motions (degree `2n`), his minimal-order motions (degree `2m`), the main
/// paper's additive Bézier motions (degree `2n` for a Bézier motion of degree `n`). One
/// segment, in its own parameter on `[0, 1]`; piecewise motions expose their segments.
///
/// ```
/// use algebra_core::rational::{q, ratio};
/// use gam_algebras::DualQuaternion;
/// use motion::juttler::{QMotion, RationalMotion};
/// let d = |c: [i64; 8]| DualQuaternion::from_coeffs(c.map(q));
/// let m = QMotion::new_exact(vec![d([1, 0, 0, 0, 0, 0, 0, 0]), d([1, 0, 0, 1, 0, 0, 0, 0])]).unwrap();
/// let path = m.rational_trajectory(&[q(1), q(0), q(0)]).unwrap();
/// assert_eq!(path.point(&q(1)).unwrap(), [q(0), q(1), q(0)]);
/// ```
pub trait RationalMotion<T: Ring> {
    /// The trajectory of the body point `x` as a rational Bézier curve on `[0, 1]`.
    fn rational_trajectory(&self, x: &[T; 3]) -> Result<RationalBezier<T>, JuttlerError>;
}

impl<T: Ring> RationalMotion<T> for QMotion<T> {
    fn rational_trajectory(&self, x: &[T; 3]) -> Result<RationalBezier<T>, JuttlerError> {
        Ok(self.trajectory(x))
    }
}
