//! The exponential of a hexanion in closed form (Angelidis eqs. 14 and 66) and the point and
//! normal transforms (16)-(19), (29), (30), (35), (36).
//!
//! With `θ = |ω|`, `a = (1 - cos θ)/θ²`, `b = sin θ/θ`, `c = (θ - sin θ)/θ³ = (1 - b)/θ²`,
//! (66) reads `exp(ω, m) = I + M + a M² + c M³`; since `[ω]׳ = -θ² [ω]×` this is
//! `[[R, V m], [0, 1]]` with `R = I + b[ω]× + a[ω]ײ` and `V = I + a[ω]× + c[ω]ײ`, which is what
//! is evaluated (no 4x4 products). The three cases of (14) are this formula with `θ = 0`
//! (`a, b, c = ½, 1, ⅙`, and `M² m`-terms vanishing) resp. `ω·m = 0` (`M³ = -θ² M`); one
//! formula serves all of them here. `a`, `b`, `c` are power series in `θ²` for `θ² ≤ 1`, so
//! small angles (1e-9) lose nothing to cancellation and dual-number derivatives stay finite.
//!
//! ```
//! use motion::repr::hexanion::Hexanion;
//! let h = Hexanion::new([0.0, 0.0, std::f64::consts::PI], [0.0, 0.0, 2.0]);
//! let m = h.exp_matrix();
//! assert!((m[0][0] + 1.0).abs() < 1e-15 && (m[2][3] - 2.0).abs() < 1e-15);
//! ```

use super::Hexanion;
use crate::repr::vec3::{add, cross, dot, scale};
use crate::{Matrix4, MotionError, Pose};
use algebra_core::{Real, Ring};

/// `[a, b, c] = [(1 - cos θ)/θ², sin θ/θ, (θ - sin θ)/θ³]` for `u = θ²`: series
/// `Σ (-u)^k/(2k+2)!`, `Σ (-u)^k/(2k+1)!`, `Σ (-u)^k/(2k+3)!` for `u ≤ 1`.
pub(crate) fn coefficients<T: Real>(u: &T) -> [T; 3] {
    if *u > T::one() {
        let th = Real::sqrt(u);
        let b = Real::sin(&th).div_ref(&th);
        let a = T::one().sub_ref(&Real::cos(&th)).div_ref(u);
        let c = T::one().sub_ref(&b).div_ref(u);
        return [a, b, c];
    }
    let neg_u = u.neg_ref();
    // term_k = (-u)^k / k!-style terms: t_n = (-u)^k/n! for n = 2k + 1, 2k + 2, 2k + 3
    let (mut ta, mut tb, mut tc) = (T::from_ratio(1, 2), T::one(), T::from_ratio(1, 6));
    let (mut a, mut b, mut c) = (ta.clone(), tb.clone(), tc.clone());
    for k in 1..2000i64 {
        tb = tb.mul_ref(&neg_u).mul_ref(&T::from_ratio(1, (2 * k) * (2 * k + 1)));
        ta = ta.mul_ref(&neg_u).mul_ref(&T::from_ratio(1, (2 * k + 1) * (2 * k + 2)));
        tc = tc.mul_ref(&neg_u).mul_ref(&T::from_ratio(1, (2 * k + 2) * (2 * k + 3)));
        a.add_assign_ref(&ta);
        b.add_assign_ref(&tb);
        c.add_assign_ref(&tc);
        let small = |x: &T| x.is_negligible(&T::from_ratio(1, 16), 1);
        if small(&ta) && small(&tb) && small(&tc) {
            break;
        }
    }
    [a, b, c]
}

impl<T: Real> Hexanion<T> {
    /// `exp(ω, m)` (eqs. 13, 14, 66) as a 4x4 homogeneous matrix (column vectors).
    ///
    /// ```
    /// use motion::repr::hexanion::Hexanion;
    /// // a pure translation: I + (0, m) (first case of (14))
    /// let m = Hexanion::new([0.0; 3], [1.0, 2.0, 3.0]).exp_matrix();
    /// assert_eq!(m[1], [0.0, 1.0, 0.0, 2.0]);
    /// ```
    pub fn exp_matrix(&self) -> Matrix4<T> {
        let w = &self.omega;
        let [a, b, c] = coefficients(&dot(w, w));
        let col = |e: [T; 3]| self.transform_direction_with(&e, &a, &b);
        let [x, y, z] = [0, 1, 2].map(|k| col(std::array::from_fn(|i| if i == k { T::one() } else { T::zero() })));
        let wm = cross(w, &self.m);
        let o = add(&add(&self.m, &scale(&a, &wm)), &scale(&c, &cross(w, &wm)));
        let z0 = T::zero;
        [
            [x[0].clone(), y[0].clone(), z[0].clone(), o[0].clone()],
            [x[1].clone(), y[1].clone(), z[1].clone(), o[1].clone()],
            [x[2].clone(), y[2].clone(), z[2].clone(), o[2].clone()],
            [z0(), z0(), z0(), T::one()],
        ]
    }

    /// `exp(ω, m)` as the main paper's unit pose: `Pose::exp(½(ω e123 + m einf))` (the closed
    /// form of `motion::exp_log`; the same rigid motion as [`Hexanion::exp_matrix`]). Fails
    /// only for non-finite input.
    ///
    /// ```
    /// use motion::{Pose, repr::hexanion::Hexanion};
    /// let s = Hexanion::new([0.0; 3], [2.0, 0.0, 0.0]).to_pose().unwrap();
    /// assert_eq!(s, Pose::translation(&[2.0, 0.0, 0.0]));
    /// ```
    pub fn to_pose(&self) -> Result<Pose<T>, MotionError> {
        let h = T::from_ratio(1, 2);
        let [w1, w2, w3] = scale(&h, &self.omega);
        let [m1, m2, m3] = scale(&h, &self.m);
        Pose::exp(&Pose::new(T::zero(), w3, w2.neg_ref(), w1, m1, m2, m3, T::zero()))
    }

    /// `<ω, m> * p = exp(ω, m) p` (eq. 16) in the closed form of the twist (35):
    /// `p + m + ω × (ω × (a p + c m) + a m + b p)`. Eq. (29) is the case `ω·m = 0` and the
    /// translation (25) the case `ω = 0`, both covered.
    ///
    /// ```
    /// use motion::repr::hexanion::Hexanion;
    /// let h = Hexanion::new([0.0; 3], [1.0, 2.0, 3.0]);
    /// assert_eq!(h.transform_point(&[1.0, 1.0, 1.0]), [2.0, 3.0, 4.0]);
    /// ```
    pub fn transform_point(&self, p: &[T; 3]) -> [T; 3] {
        let w = &self.omega;
        let [a, b, c] = coefficients(&dot(w, w));
        let inner = add(&scale(&a, p), &scale(&c, &self.m));
        let outer = add(&add(&cross(w, &inner), &scale(&a, &self.m)), &scale(&b, p));
        add(&add(p, &self.m), &cross(w, &outer))
    }

    /// `<ω, m> * v = exp(ω, m) v` for a vector (normal) `v` (eqs. 18, 30, 36):
    /// `v + a ω × (ω × v) + b ω × v`; the translation `m` does not act (25).
    ///
    /// ```
    /// use motion::repr::hexanion::Hexanion;
    /// let h = Hexanion::new([0.0, 0.0, std::f64::consts::FRAC_PI_2], [5.0, 0.0, 0.0]);
    /// let v = h.transform_direction(&[1.0, 0.0, 0.0]);
    /// assert!(v[0].abs() < 1e-15 && (v[1] - 1.0).abs() < 1e-15);
    /// ```
    pub fn transform_direction(&self, v: &[T; 3]) -> [T; 3] {
        let [a, b, _] = coefficients(&dot(&self.omega, &self.omega));
        self.transform_direction_with(v, &a, &b)
    }

    fn transform_direction_with(&self, v: &[T; 3], a: &T, b: &T) -> [T; 3] {
        let wv = cross(&self.omega, v);
        add(&add(v, &scale(a, &cross(&self.omega, &wv))), &scale(b, &wv))
    }
}

impl<T: Ring> Hexanion<T> {
    /// The first-order approximation `p + ω × p + m` of (17) (from `exp ≈ I + (ω, m)`, (15)).
    ///
    /// ```
    /// use motion::repr::hexanion::Hexanion;
    /// let h = Hexanion::new([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]);
    /// assert_eq!(h.transform_point_first_order(&[1.0, 0.0, 0.0]), [2.0, 1.0, 0.0]);
    /// ```
    pub fn transform_point_first_order(&self, p: &[T; 3]) -> [T; 3] {
        add(&add(p, &cross(&self.omega, p)), &self.m)
    }

    /// The first-order approximation `v + ω × v` of (19); it does not preserve `|v|`.
    ///
    /// ```
    /// use motion::repr::hexanion::Hexanion;
    /// let h = Hexanion::new([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]);
    /// assert_eq!(h.transform_direction_first_order(&[1.0, 0.0, 0.0]), [1.0, 1.0, 0.0]);
    /// ```
    pub fn transform_direction_first_order(&self, v: &[T; 3]) -> [T; 3] {
        add(v, &cross(&self.omega, v))
    }
}
