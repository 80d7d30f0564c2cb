//! Rational motions of minimal order (Jüttler Sec. 5, Theorem 6, eqs. 35-39). The *order* of a
//! rational motion is the maximal degree of its (irreducible) trajectories. Theorem 6: for
//! polynomials `w0*(t)` of degree `n - 2k`, `w(t) ∈ R³` of degree `n` and `D(t) = d0 + d` of
//! degree `k` (`0 ≤ k ≤ n/2`) the matrix-valued polynomial of degree `n`
//!
//! `M(t) = [[w0* |D|², 0], [w, w0* U]]`  (35, homogeneous coordinates weight first; `U` of (11))
//!
//! is a rational motion of order `n`: the body point `x` moves on `(w0*|D|², w + w0* U x)`,
//! degree `n`, although the corresponding Q-motion (36), `[2 w0*|D|² + ε w] * D`, has degree
//! `k + n` (its trajectories of degree `2(k + n)` carry the common factor `|D|^2 …`).
//! (The OCR of the paper lost the display (35); the form above is (10) with `v0 = w0*`,
//! `|D|² v = w`, the only one consistent with (36).)
//!
//! Interpolation (37)-(39): `w0* ≡ 1`, `D = Q_rot` from a rotational method (degree `k`), and
//! `w(t) = Σ b_j^m(t) p_j` through `|Q_rot(t_i)|² s_i` (39): order `n = max(2k, m)`, i.e. `2m`
//! with the elliptic method (`k = m`).
//!
//! ```
//! use algebra_core::rational::{q, ratio};
//! use motion::Pose;
//! use motion::juttler::{RationalMotion, minimal::minimal_method, rotational::affine, tr::rotation_translation};
//! let poses = [
//!     Pose::translation(&[q(0), q(0), q(0)]),
//!     Pose::rotor_from_parts(&q(1), &q(1), &[q(0), q(0), q(1)]) * Pose::translation(&[q(2), q(0), q(0)]),
//!     Pose::rotor_from_parts(&q(2), &q(1), &[q(1), q(0), q(0)]) * Pose::translation(&[q(0), q(1), q(3)]),
//! ];
//! let t = [q(0), ratio(1, 2), q(1)];
//! let rots: Vec<_> = poses.iter().map(|p| rotation_translation(p).unwrap().0).collect();
//! let m = minimal_method(&affine(&rots, &t).unwrap(), &poses, &t).unwrap();
//! assert_eq!(m.order(), 4); // 2m
//! assert!(m.pose_exact(&t[1]).unwrap().is_equivalent_exact(&poses[1]));
//! let path = m.rational_trajectory(&[q(1), q(0), q(0)]).unwrap();
//! assert_eq!(path.degree(), 4);
//! ```

use super::q_motion::pose_of;
use super::rotational::{check_count, elliptic, solve_bernstein};
use super::tr::{rotation_translation, rotations};
use super::trt::rotation_curve;
use super::{
    JuttlerError, QMotion, RationalBezier, RationalMotion, bernstein_product, check_finite_distinct, de_casteljau_with,
    elevate_with,
};
use crate::repr::dual_quaternion::{DualQuaternion, Quaternion, from_dual_quaternion_exact, matrix_u};
use crate::{CurveError, MapScalar, Motion, Pose};
use algebra_core::{Field, Real, Ring};

/// A rational motion of order `n` in Jüttler's representation (35) (Theorem 6): the scalar
/// polynomial `w0*` (degree `n - 2k`), the vector polynomial `w` (degree `n`) and the rotation
/// `D = d0 + d` (degree `k ≤ n/2`), all in Bernstein form on `[0, 1]`.
///
/// ```
/// use algebra_core::rational::{q, ratio};
/// use gam_algebras::dual_quaternion::Quaternion;
/// use motion::juttler::minimal::MinimalMotion;
/// // D = 1 (k = 0), w0* = 1, w(t) = (t, 0, 0) in degree 1: a translation of order 1
/// let m = MinimalMotion::new(vec![q(1), q(1)], vec![[q(0), q(0), q(0)], [q(1), q(0), q(0)]], vec![Quaternion::one()]).unwrap();
/// assert_eq!(m.order(), 1);
/// assert_eq!(m.pose_exact(&ratio(1, 2)).unwrap().transform_point(&[q(0), q(0), q(0)]).unwrap(), [ratio(1, 2), q(0), q(0)]);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct MinimalMotion<T> {
    w0: Vec<T>,
    w: Vec<[T; 3]>,
    /// `D` as a rotational Q-motion (zero dual parts), for its evaluation and products.
    d: QMotion<T>,
}

fn add3<T: Ring>(a: &[T; 3], b: &[T; 3]) -> [T; 3] {
    std::array::from_fn(|k| a[k].add_ref(&b[k]))
}

impl<T: Ring> MinimalMotion<T> {
    /// The motion (35) from the Bernstein coefficients of `w0*` (`n - 2k + 1` of them), `w`
    /// (`n + 1`) and `D` (`k + 1`). Fails unless `0 ≤ 2k ≤ n` and the counts match
    /// ([`JuttlerError::Parameters`]).
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// use motion::juttler::minimal::MinimalMotion;
    /// let d = vec![Quaternion::one(), Quaternion::one()]; // k = 1 needs n >= 2
    /// assert!(MinimalMotion::new(vec![q(1)], vec![[q(0), q(0), q(0)]; 2], d).is_err());
    /// ```
    pub fn new(w0: Vec<T>, w: Vec<[T; 3]>, d: Vec<Quaternion<T>>) -> Result<Self, JuttlerError> {
        let bad = |why: String| Err(JuttlerError::Parameters { why });
        if w.is_empty() || d.is_empty() {
            return bad("(35) needs w and D (at least one coefficient each)".into());
        }
        let coefficients = w0.iter().chain(w.iter().flatten()).chain(d.iter().flat_map(|r| [&r.w, &r.x, &r.y, &r.z]));
        if coefficients.into_iter().any(|x| !x.is_finite_value()) {
            return bad("(35) has a coefficient that is not finite".into());
        }
        let (n, k) = (w.len() - 1, d.len() - 1);
        if 2 * k > n {
            return bad(format!("(35) needs 2k <= n, got k = {k}, n = {n}"));
        }
        if w0.len() != n - 2 * k + 1 {
            return bad(format!("(35): w0* has degree n - 2k = {}, got {} coefficients", n - 2 * k, w0.len()));
        }
        let d = QMotion::from_control_unchecked(d.into_iter().map(DualQuaternion::from_real).collect());
        Ok(MinimalMotion { w0, w, d })
    }

    /// The order `n` (the degree of (35) and of the trajectories).
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// let m = motion::juttler::minimal::MinimalMotion::new(vec![q(1)], vec![[q(0), q(0), q(0)]], vec![Quaternion::one()]).unwrap();
    /// assert_eq!(m.order(), 0);
    /// ```
    pub fn order(&self) -> usize {
        self.w.len() - 1
    }

    /// The Bernstein coefficients of `w0*`, `w` and `D`.
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// let m = motion::juttler::minimal::MinimalMotion::new(vec![q(2)], vec![[q(0), q(1), q(0)]], vec![Quaternion::one()]).unwrap();
    /// let (w0, w, d) = m.coefficients();
    /// assert_eq!((w0, w, d), (vec![q(2)], vec![[q(0), q(1), q(0)]], vec![Quaternion::one()]));
    /// ```
    pub fn coefficients(&self) -> (Vec<T>, Vec<[T; 3]>, Vec<Quaternion<T>>) {
        (self.w0.clone(), self.w.clone(), self.d.control().iter().map(|c| c.real.clone()).collect())
    }

    /// The matrix `M(t)` of (35) (weight first): `[[w0*|D|², 0], [w, w0* U]]`.
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// let m = motion::juttler::minimal::MinimalMotion::new(vec![q(1)], vec![[q(1), q(2), q(3)]], vec![Quaternion::one()]).unwrap();
    /// assert_eq!(m.matrix(&q(0))[1], [q(1), q(1), q(0), q(0)]);
    /// ```
    pub fn matrix(&self, t: &T) -> [[T; 4]; 4] {
        let w0 = de_casteljau_with(&self.w0, t, |a, b, s, t| a.mul_ref(s).add_ref(&b.mul_ref(t)));
        let w = self.w_at(t);
        let dt = self.d.eval(t).real;
        let u = matrix_u(&dt);
        let row = |i: usize| [w[i].clone(), w0.mul_ref(&u[i][0]), w0.mul_ref(&u[i][1]), w0.mul_ref(&u[i][2])];
        [[w0.mul_ref(&dt.norm_squared()), T::zero(), T::zero(), T::zero()], row(0), row(1), row(2)]
    }

    fn w_at(&self, t: &T) -> [T; 3] {
        de_casteljau_with(&self.w, t, |a, b, s, t| {
            add3(&a.clone().map(|x| x.mul_ref(s)), &b.clone().map(|x| x.mul_ref(t)))
        })
    }

    /// The Bernstein coefficients (degree `n`) of `(w0*|D|², w0* U x)` for the body point `x`:
    /// `D (1 + x) D̃ = |D|² + U x` by (29), times `w0*` by (29).
    fn rotated(&self, x: &[T; 3]) -> Vec<[T; 4]> {
        let one_x = DualQuaternion::from_real(Quaternion::new(T::one(), x[0].clone(), x[1].clone(), x[2].clone()));
        let left: Vec<_> = self.d.control().iter().map(|c| c * &one_x).collect();
        let right: Vec<_> = self.d.control().iter().map(|c| c.conjugate()).collect();
        let dxd =
            bernstein_product(&left, &right, DualQuaternion::zero(), |a, b| a * b, |acc, x, f: &T| acc + &x.scale(f));
        let zero: [T; 4] = std::array::from_fn(|_| T::zero());
        bernstein_product(
            &self.w0,
            &dxd,
            zero,
            |a, p| [a.mul_ref(&p.real.w), a.mul_ref(&p.real.x), a.mul_ref(&p.real.y), a.mul_ref(&p.real.z)],
            |acc, h, f: &T| std::array::from_fn(|k| acc[k].add_ref(&h[k].mul_ref(f))),
        )
    }

    /// The corresponding Q-motion (36), `[2 w0*|D|² + ε w] * D`, of degree `k + n`.
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio};
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// let d = vec![Quaternion::one(), Quaternion::new(q(1), q(0), q(0), q(1))];
    /// let m = motion::juttler::minimal::MinimalMotion::new(vec![q(1)], vec![[q(0), q(0), q(0)]; 3], d).unwrap();
    /// let qm = m.q_motion();
    /// assert_eq!(qm.degree(), 3);
    /// let t = ratio(1, 3);
    /// assert!(qm.pose_exact(&t).unwrap().is_equivalent_exact(&m.pose_exact(&t).unwrap()));
    /// ```
    pub fn q_motion(&self) -> QMotion<T> {
        let weight = self.rotated(&[T::zero(), T::zero(), T::zero()]);
        let trans = weight
            .iter()
            .zip(&self.w)
            .map(|(h, w)| {
                DualQuaternion::new(
                    Quaternion::new(h[0].add_ref(&h[0]), T::zero(), T::zero(), T::zero()),
                    Quaternion::pure(w),
                )
            })
            .collect();
        QMotion::from_control_unchecked(trans).product(&self.d)
    }

    /// The dual quaternion `Q(t)` of (36) at `t`, without the product formula.
    fn q_at(&self, t: &T) -> DualQuaternion<T> {
        let m = self.matrix(t);
        let trans = DualQuaternion::new(
            Quaternion::new(m[0][0].add_ref(&m[0][0]), T::zero(), T::zero(), T::zero()),
            Quaternion::pure(&self.w_at(t)),
        );
        &trans * &self.d.eval(t)
    }

    /// The trajectory of the body point `x`: the rational Bézier curve `M(t) (1, x)` of degree
    /// `n` (homogeneous control points `(w0*|D|², w + w0* U x)` by (29)); exact over rationals.
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio};
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// let d = vec![Quaternion::one(), Quaternion::new(q(1), q(0), q(0), q(1))];
    /// let m = motion::juttler::minimal::MinimalMotion::new(vec![q(1)], vec![[q(0), q(0), q(0)]; 3], d).unwrap();
    /// let arc = m.trajectory(&[q(1), q(0), q(0)]);
    /// assert_eq!(arc.degree(), 2);
    /// assert_eq!(arc.point(&q(1)).unwrap(), [q(0), q(1), q(0)]);
    /// ```
    pub fn trajectory(&self, x: &[T; 3]) -> RationalBezier<T> {
        let control = self
            .rotated(x)
            .into_iter()
            .zip(&self.w)
            .map(|(h, w)| {
                let [h0, h1, h2, h3] = h;
                let [y1, y2, y3] = add3(&[h1, h2, h3], w);
                [h0, y1, y2, y3]
            })
            .collect();
        RationalBezier::from_control_unchecked(control)
    }

    /// The same motion over `U`, each coefficient mapped by `f`.
    fn map_ring<U: Ring>(&self, f: &dyn Fn(&T) -> U) -> MinimalMotion<U> {
        MinimalMotion {
            w0: self.w0.iter().map(f).collect(),
            w: self.w.iter().map(|w| w.clone().map(|x| f(&x))).collect(),
            d: self.d.map_ring(f),
        }
    }
}

impl<T: Field> MinimalMotion<T> {
    /// The pose at `t` (exact over rationals); fails where `w0*(t)|D(t)|² = 0` (a pole).
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// let m = motion::juttler::minimal::MinimalMotion::new(vec![q(1), q(-1)], vec![[q(0), q(0), q(0)]; 2], vec![Quaternion::one()]).unwrap();
    /// assert!(m.pose_exact(&(q(1) / q(2))).is_err()); // w0*(1/2) = 0
    /// ```
    pub fn pose_exact(&self, t: &T) -> Result<Pose<T>, JuttlerError> {
        Ok(from_dual_quaternion_exact(&self.q_at(t))?)
    }
}

/// A minimal-order motion is a [`Motion`] on `[0, 1]`: the pose of (36) at `t`.
impl<T: Real> Motion<T> for MinimalMotion<T> {
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        pose_of(&self.q_at(t))
    }

    fn domain(&self) -> [T; 2] {
        [T::zero(), T::one()]
    }
}

impl<T: Real, U: Real> MapScalar<T, U> for MinimalMotion<T> {
    type Mapped = MinimalMotion<U>;
    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> MinimalMotion<U> {
        self.map_ring(f)
    }
}

/// Trajectories of degree `n` (the order), [`MinimalMotion::trajectory`].
impl<T: Ring> RationalMotion<T> for MinimalMotion<T> {
    fn rational_trajectory(&self, x: &[T; 3]) -> Result<RationalBezier<T>, JuttlerError> {
        Ok(self.trajectory(x))
    }
}

/// Interpolation with a rational motion of minimal order (37)-(39) on a rotational Q-motion
/// `rot` (zero dual parts, degree `k`) through the rotational parts at `params`: `w0* ≡ 1`,
/// `w` of degree `m` through `|Q_rot(t_i)|² s_i` (39), order `max(2k, m)`; exact over
/// rationals. Fails for a `rot` with a dual part ([`JuttlerError::NotRotational`]) or
/// parameters that are not one per position and distinct.
///
/// ```
/// use algebra_core::rational::q;
/// use motion::{Pose, juttler::{minimal::minimal_method, rotational::affine, tr::rotation_translation}};
/// let poses = [Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(2), q(0), q(0)])];
/// let t = [q(0), q(1)];
/// let rots: Vec<_> = poses.iter().map(|p| rotation_translation(p).unwrap().0).collect();
/// let m = minimal_method(&affine(&rots, &t).unwrap(), &poses, &t).unwrap();
/// assert!(m.pose_exact(&q(1)).unwrap().is_equivalent_exact(&poses[1]));
/// ```
pub fn minimal_method<T: Field>(
    rot: &QMotion<T>,
    poses: &[Pose<T>],
    params: &[T],
) -> Result<MinimalMotion<T>, JuttlerError> {
    check_count(poses.len(), params)?;
    rotation_curve(rot)?;
    check_finite_distinct(params, poses.iter().flat_map(Pose::components))?;
    let rhs = poses
        .iter()
        .zip(params)
        .map(|(p, t)| {
            let norm = rot.eval(t).real.norm_squared();
            Ok(rotation_translation(p)?.1.map(|s| s.mul_ref(&norm)))
        })
        .collect::<Result<Vec<[T; 3]>, JuttlerError>>()?;
    let mut w = solve_bernstein(params, &rhs)?;
    let (k, m) = (rot.degree(), poses.len() - 1);
    let n = (2 * k).max(m);
    while w.len() < n + 1 {
        w = elevate_with(&w, |a, s, b, t: &T| add3(&a.clone().map(|x| x.mul_ref(s)), &b.clone().map(|x| x.mul_ref(t))));
    }
    let d = rot.control().iter().map(|c| c.real.clone()).collect();
    MinimalMotion::new(vec![T::one(); n - 2 * k + 1], w, d)
}

/// [`minimal_method`] with the elliptic method (22)-(25) for the rotational parts (`k = m`):
/// the interpolating rational motion of order `2m` (Sec. 5).
///
/// ```
/// use motion::{Motion, Pose, juttler::minimal::minimal};
/// let poses = [
///     Pose::<f64>::identity(),
///     Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &1.0, &[1.0, 2.0, 0.0]).unwrap(),
///     Pose::from_axis_angle_translation(&[1.0, 0.0, 0.0], &0.5, &[3.0, 0.0, 1.0]).unwrap(),
/// ];
/// let m = minimal(&poses, &[0.0, 0.4, 1.0]).unwrap();
/// assert_eq!(m.order(), 4);
/// assert!(m.pose(&0.4).unwrap().is_equivalent(&poses[1], &1e-12).unwrap());
/// ```
pub fn minimal<T: Real>(poses: &[Pose<T>], params: &[T]) -> Result<MinimalMotion<T>, JuttlerError> {
    check_count(poses.len(), params)?;
    let rots = rotations(poses)?;
    minimal_method(&elliptic(&rots, params)?, poses, params)
}
