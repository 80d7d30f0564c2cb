//! Powers and the two pairwise interpolations of Sec. 4 of the main paper: the multiplicative
//! slerp `Φ(A, B; t) = A (rev(A) B)^t` (eq. 15; the OCR of the paper lost the bar) and the
//! additive `Φ(A, B; t) = (1 - t) A + t B` (eq. 17). The de Casteljau tableaux of Bezier
//! motions are built from these.
//!
//! ```
//! use motion::Pose;
//! let a = Pose::<f64>::identity();
//! let b = Pose::translation(&[2.0, 0.0, 0.0]);
//! let half = Pose::slerp(&a, &b, &0.5).unwrap();
//! assert!((half.transform_point(&[0.0, 0.0, 0.0]).unwrap()[0] - 1.0).abs() < 1e-15);
//! assert_eq!(Pose::lerp(&a, &b, &0.5), Pose::translation(&[1.0, 0.0, 0.0]));
//! ```

use crate::{MotionError, Pose};
use algebra_core::{Real, Ring};

impl<T: Real> Pose<T> {
    /// `S^t = exp(t log S)` with the logarithm of the element ([`Pose::log`]), so
    /// `S^0 = 1`, `S^1 = S`, `S^s S^t = S^{s+t}`, and for non-unit `S = |S| U`,
    /// `S^t = |S|^t U^t`. Fails for singular `S`.
    ///
    /// ```
    /// use motion::Pose;
    /// let r = Pose::rotation(&[0.0, 0.0, 1.0], &1.2).unwrap();
    /// let half = r.power(&0.5).unwrap();
    /// assert!(half.is_equivalent(&Pose::rotation(&[0.0, 0.0, 1.0], &0.6).unwrap(), &1e-15).unwrap());
    /// ```
    pub fn power(&self, t: &T) -> Result<Self, MotionError> {
        if let Some(p) = self.power_direct(t) {
            return Ok(p);
        }
        crate::scaled::require_finite("power", self, [t])?;
        let l = self.log()?;
        Pose::exp(&l.scale(t))
    }

    /// The slerp `A (rev(A) B)^t` of eq. (15). `S(0) = A`; `S(1) = A rev(A) B = |A|² B`, which
    /// is `B` only when `A` is unitary (otherwise an equivalent pose, the same transform; eq. 16
    /// gives `Φ(αA, βB; t) = α^{1+t} β^t Φ(A, B; t)` for pseudoscalars). The power uses the
    /// element's logarithm, so when `rev(A) B` has negative scalar part the motion turns the
    /// long way (rotation angle above π); pass `-B` (the same pose) for the short way.
    /// Fails when `rev(A) B` is singular (A or B singular).
    ///
    /// ```
    /// use motion::Pose;
    /// let a = Pose::<f64>::rotation(&[1.0, 0.0, 0.0], &0.3).unwrap();
    /// let b = Pose::from_axis_angle_translation(&[0.0, 1.0, 0.0], &2.0, &[1.0, 2.0, 3.0]).unwrap();
    /// let end = Pose::slerp(&a, &b, &1.0).unwrap();
    /// assert!((&end - &b).components().iter().all(|x| x.abs() < 1e-14f64));
    /// ```
    pub fn slerp(a: &Self, b: &Self, t: &T) -> Result<Self, MotionError> {
        if crate::series::at_most_f64::<T>() {
            // the direct path: a non-finite `a`, `b` or `t` cannot give a finite result (every
            // coefficient enters a product), so one test of the result replaces the checks
            let out = (&a.reverse() * b).power_direct(t).map(|p| a * &p);
            if let Some(out) = out.filter(Pose::is_finite) {
                return Ok(out);
            }
        }
        crate::scaled::require_finite("slerp", a, [t])?;
        crate::scaled::require_finite("slerp", b, [])?;
        let rel = &a.reverse() * b;
        Ok(a * &rel.power(t)?)
    }
}

impl<T: Real> Pose<T> {
    /// [`Pose::power`] by the direct paths of `log` and `exp` alone (ordinary input at `f64`
    /// precision or less); `None` sends the input to the careful path, which names a failure.
    fn power_direct(&self, t: &T) -> Option<Self> {
        let l = self.log_direct()?;
        Pose::exp_direct(&l.scale(t))
    }
}

impl<T: Ring> Pose<T> {
    /// The additive interpolation `(1 - t) A + t B` of eq. (17): polynomial in `t`, exact over
    /// exact scalars; generally not unitary, and singular where it passes through a singular
    /// pseudoscalar (the zero transform).
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio, Q};
    /// use motion::Pose;
    /// let a = Pose::<Q>::identity();
    /// let b = Pose::rotor_from_parts(&q(0), &q(1), &[q(0), q(0), q(1)]); // e12: half turn
    /// let m = Pose::lerp(&a, &b, &ratio(1, 2)); // ½(1 + e12): quarter turn, |S|² = ½
    /// assert_eq!(m.transform_point(&[q(1), q(0), q(0)]).unwrap(), [q(0), q(1), q(0)]);
    /// ```
    pub fn lerp(a: &Self, b: &Self, t: &T) -> Self {
        let one_minus_t = T::one().sub_ref(t);
        &a.scale(&one_minus_t) + &b.scale(t)
    }
}
