//! [`Pose`]: an element `S` of G_{123inf}^+ seen as a rigid-body transform (Sec. 2 of the main
//! paper), with its constructors and algebra: the pseudoscalar norm `|S|` (Lemma 2.4), unitize
//! and inverse (Lemma 2.6), and the equivalence test of Theorem 2.8.
//!
//! `S` acts on R^3 by `F_S = P f_S E` with `f_S(x) = rev(S) x S` (see [`crate::action`]), so a
//! product acts right to left in reading order: `F_{UV} = F_V F_U` (Lemma 2.3), i.e. `U * V`
//! applies `U` first, then `V`. Non-unit poses are first-class: additive motions
//! `(1 - t) A + t B` leave the unit poses, and every non-singular `S` is *equivalent* to its
//! unitization (`S = |S| U`, same transform).
//!
//! ```
//! use motion::Pose;
//! use std::f64::consts::FRAC_PI_2;
//! // Rotate a quarter turn about e3, then translate by (1, 0, 0): S = R T.
//! let s = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &FRAC_PI_2, &[1.0, 0.0, 0.0]).unwrap();
//! let p = s.transform_point(&[1.0, 0.0, 0.0]).unwrap();
//! assert!((p[0] - 1.0).abs() < 1e-15 && (p[1] - 1.0).abs() < 1e-15 && p[2].abs() < 1e-15);
//! ```

use crate::MotionError;
use algebra_core::{Field, Real, Ring};
use gam_algebras::g123inf::Motor;

algebra_macros::algebra! {
    /// The main paper's G_{123inf} (e1² = e2² = e3² = 1, einf² = 0) with the types the motion
    /// layer speaks in: [`Pose`] (G_{123inf}^+), [`Bivector`] and [`Pseudoscalar`]. Generated
    /// here, in the crate that gives them their methods, so the pose is the generated type
    /// itself (named fields `scalar, e12, e13, e23, e1inf, e2inf, e3inf, e123inf`), with the
    /// generated products, sums, `reverse`, `scale`, embeddings (`Pose::from(&bivector)`) and
    /// projections (`pose.project_to_bivector()`).
    pub mod elements {
        metric builtin "g123inf";
        // motion's own `Pose::log`/`Pose::exp` (exp_log.rs, with `MotionError` and the paper's
        // conventions) are the pose layer's; the generated ones stay in gam_algebras::g123inf
        closed_forms off;
        types {
            /// The paper's pose `S`: any element of G_{123inf}^+ (eq. 4), unit or not, in the
            /// paper's order `[S∅, S12, S13, S23, S1∞, S2∞, S3∞, Sω]`. The same type carries the
            /// even elements that are not read as poses (`log S`, the velocity indicatrix `Ψ`):
            /// see [`crate::Even`].
            ///
            /// Generated, no wrapper: every even element is a valid pose value; singular ones
            /// (zero transform) are rejected by the operations that need an inverse. Three
            /// generated methods keep the algebra's general meaning: `norm_squared` is the scalar
            /// `<S rev(S)>_0` (the paper's `|S|² = rev(S) S` is [`Pose::pseudo_norm_squared`]),
            /// `inverse` solves `S y = 1` by elimination (the closed form of Lemma 2.6 with a
            /// [`crate::MotionError`] is [`Pose::try_inverse`]), and `dual` is the algebra's dual.
            ///
            /// ```
            /// use motion::Pose;
            /// let s = Pose::new(1.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0); // 1 + ½ e1inf
            /// assert_eq!(s, Pose::translation(&[1.0, 0.0, 0.0]));
            /// assert_eq!(s.e1inf, 0.5);
            /// ```
            Pose = [1, e12, e13, e23, e1inf, e2inf, e3inf, e123inf];
            /// A bivector `a e123 + c einf` of G_{123inf}: the velocity bivector `ν = Ω e123 + u einf`
            /// (Theorem 3.2), the bivector part of `Ψ` and of `log S`.
            Bivector = grade 2;
            /// A pseudoscalar `α + βω` (`ω = e123inf`, `ω² = 0`): `|S|`, `rev(S) S` (eq. 5), `γ`.
            Pseudoscalar = [1, e123inf];
        }
    }
}

pub use elements::{Bivector, Pose, Pseudoscalar};

/// An element of G_{123inf}^+ that is not read as a pose: the velocity indicatrix `Ψ`
/// (eq. 11), `log S`, the argument of [`Pose::exp`]. The same type as [`Pose`]; the name says
/// how to read it.
///
/// ```
/// use motion::{Even, Pose};
/// let psi: Even<f64> = Pose::translation(&[2.0, 0.0, 0.0]).log().unwrap();
/// assert_eq!(psi.e1inf, 1.0);
/// ```
pub type Even<T> = elements::Pose<T>;

impl<T: Ring> Pose<T> {
    /// The identity pose `1`.
    ///
    /// ```
    /// let i = motion::Pose::<f64>::identity();
    /// assert_eq!(i.transform_point(&[1.0, 2.0, 3.0]).unwrap(), [1.0, 2.0, 3.0]);
    /// ```
    pub fn identity() -> Self {
        Pose::one()
    }

    /// The pose of an element of gam-algebras' `g123inf::Motor` (the same coefficients; for
    /// interoperation with [`gam_algebras::DualQuaternion`] and code generated there).
    ///
    /// ```
    /// use gam_algebras::g123inf::Motor;
    /// assert_eq!(motion::Pose::from_motor(Motor::<f64>::one()), motion::Pose::identity());
    /// ```
    pub fn from_motor(m: Motor<T>) -> Self {
        let Motor { scalar, e12, e13, e23, e1inf, e2inf, e3inf, e123inf } = m;
        Pose { scalar, e12, e13, e23, e1inf, e2inf, e3inf, e123inf }
    }

    /// The same coefficients as gam-algebras' `g123inf::Motor` (see [`Pose::from_motor`]).
    ///
    /// ```
    /// assert_eq!(motion::Pose::<f64>::identity().to_motor().scalar, 1.0);
    /// ```
    pub fn to_motor(&self) -> Motor<T> {
        self.clone().into_motor()
    }

    /// The same coefficients as gam-algebras' `g123inf::Motor`, by value.
    ///
    /// ```
    /// assert_eq!(motion::Pose::<f64>::identity().into_motor().e12, 0.0);
    /// ```
    pub fn into_motor(self) -> Motor<T> {
        let Pose { scalar, e12, e13, e23, e1inf, e2inf, e3inf, e123inf } = self;
        Motor { scalar, e12, e13, e23, e1inf, e2inf, e3inf, e123inf }
    }

    /// The translation `T = 1 + ½ v einf` by `v` (exact over exact scalars).
    ///
    /// ```
    /// use algebra_core::rational::{q, Q};
    /// let t = motion::Pose::<Q>::translation(&[q(2), q(0), q(-4)]);
    /// assert_eq!(t.transform_point(&[q(1), q(1), q(1)]).unwrap(), [q(3), q(1), q(-3)]);
    /// ```
    pub fn translation(v: &[T; 3]) -> Self {
        let half = T::from_ratio(1, 2);
        let z = T::zero;
        Pose::new(T::one(), z(), z(), z(), v[0].mul_ref(&half), v[1].mul_ref(&half), v[2].mul_ref(&half), z())
    }

    /// `c + s (a e123)` for a vector `a` (not normalised): with `a` a unit vector,
    /// `c = cos(φ/2)` and `s = sin(φ/2)` this is the paper's rotor `R` for the rotation by `φ`
    /// about `a`. Uses `a e123 = a1 e23 - a2 e13 + a3 e12`. Exact over exact scalars (e.g.
    /// the quarter turn `c = s = 1` up to the scale `√2`, which is a non-unit pose).
    ///
    /// ```
    /// use algebra_core::rational::{q, Q};
    /// // (1 + e12): a quarter turn about e3, non-unit (|S|² = 2), acting exactly.
    /// let r = motion::Pose::<Q>::rotor_from_parts(&q(1), &q(1), &[q(0), q(0), q(1)]);
    /// assert_eq!(r.transform_point(&[q(1), q(0), q(0)]).unwrap(), [q(0), q(1), q(0)]);
    /// ```
    pub fn rotor_from_parts(c: &T, s: &T, a: &[T; 3]) -> Self {
        let z = T::zero;
        Pose::new(c.clone(), s.mul_ref(&a[2]), s.mul_ref(&a[1]).neg_ref(), s.mul_ref(&a[0]), z(), z(), z(), z())
    }

    /// `rev(S) S = α + βω` in closed form (eq. 5):
    /// `α = S∅² + S12² + S13² + S23²`, `β = 2(S∅Sω - S12S3∞ + S13S2∞ - S23S1∞)`.
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use motion::{Pose, Pseudoscalar};
    /// let s = Pose::new(q(1), q(2), q(0), q(0), q(0), q(0), q(3), q(1));
    /// assert_eq!(s.pseudo_norm_squared(), Pseudoscalar::new(q(5), q(2 * (1 - 2 * 3))));
    /// assert_eq!(s.norm_squared(), q(5)); // the generated scalar part <S rev(S)>_0 = α
    /// ```
    pub fn pseudo_norm_squared(&self) -> Pseudoscalar<T> {
        let half_beta = self.half_beta();
        Pseudoscalar::new(self.alpha(), half_beta.add_ref(&half_beta))
    }

    /// `β/2 = S∅ Sω - S12 S3∞ + S13 S2∞ - S23 S1∞`, half the ω part of
    /// [`Pose::pseudo_norm_squared`].
    pub(crate) fn half_beta(&self) -> T {
        let s = self;
        s.scalar.mul_ref(&s.e123inf) - s.e12.mul_ref(&s.e3inf) + s.e13.mul_ref(&s.e2inf) - s.e23.mul_ref(&s.e1inf)
    }

    /// `α = S∅² + S12² + S13² + S23²`, the scalar part of [`Pose::pseudo_norm_squared`] alone
    /// (what the point action divides by). Summed in pairs of the fields' memory order,
    /// `(S∅² + S12²) + (S13² + S23²)`, so that `f64` code squares two lanes at a time and adds
    /// them with one shuffle: 2 % of the inlined `Pose::transform_point` and 3 % of the slerp of
    /// non-unit poses (docs/performance.md, "thirteenth session"). As accurate as the sequential
    /// sum over random poses; of the orders tried, the one that keeps the CLI contract
    /// example's end position exact.
    pub(crate) fn alpha(&self) -> T {
        let s = self;
        (s.scalar.mul_ref(&s.scalar) + s.e12.mul_ref(&s.e12)) + (s.e13.mul_ref(&s.e13) + s.e23.mul_ref(&s.e23))
    }

    /// True when `S` is exactly singular: the scalar part of `rev(S) S` is exactly zero, so
    /// `F_S` is the zero transform (Lemma 2.6). Floats that are merely tiny are not singular here.
    ///
    /// ```
    /// assert!(motion::Pose::new(0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0).is_singular());
    /// assert!(!motion::Pose::<f64>::identity().is_singular());
    /// ```
    pub fn is_singular(&self) -> bool {
        // α of a tiny pose (1e-300) underflows: then decided again at unit scale
        self.pseudo_norm_squared().scalar.is_exact_zero()
            && crate::scaled::unusual_scale(self).is_none_or(|(_, s)| s.pseudo_norm_squared().scalar.is_exact_zero())
    }

    /// `γ S` for a pseudoscalar `γ` (an equivalent pose when `γ` is non-singular, Theorem 2.8).
    ///
    /// ```
    /// use motion::Pseudoscalar;
    /// let s = motion::Pose::<f64>::identity().scale_pseudoscalar(&Pseudoscalar::new(2.0, 1.0));
    /// assert_eq!((s.scalar, s.e123inf), (2.0, 1.0));
    /// ```
    pub fn scale_pseudoscalar(&self, gamma: &Pseudoscalar<T>) -> Self {
        gamma * self
    }

    /// Theorem 2.8, exactly: `self` and `other` are non-singular and `other = γ self` for a
    /// pseudoscalar `γ`, i.e. `other rev(self)` (= `γ |self|²`) has a zero bivector part.
    /// Equivalent poses generate the same transform and conversely.
    ///
    /// ```
    /// use algebra_core::rational::{q, Q};
    /// use motion::{Pose, Pseudoscalar};
    /// let s = Pose::<Q>::rotor_from_parts(&q(1), &q(2), &[q(0), q(1), q(0)]) * Pose::translation(&[q(1), q(2), q(3)]);
    /// let v = s.scale_pseudoscalar(&Pseudoscalar::new(q(-3), q(7)));
    /// assert!(s.is_equivalent_exact(&v));
    /// assert!(!s.is_equivalent_exact(&Pose::translation(&[q(1), q(0), q(0)])));
    /// ```
    pub fn is_equivalent_exact(&self, other: &Self) -> bool {
        if self.is_singular() || other.is_singular() {
            return false;
        }
        let w = other * &self.reverse();
        [&w.e12, &w.e13, &w.e23, &w.e1inf, &w.e2inf, &w.e3inf].into_iter().all(Ring::is_exact_zero)
    }

    /// The eight coefficients in the paper's order (eq. 4):
    /// `[S∅, S12, S13, S23, S1∞, S2∞, S3∞, Sω]`.
    ///
    /// ```
    /// assert_eq!(motion::Pose::translation(&[2.0, 0.0, 0.0]).components()[4], &1.0);
    /// ```
    pub fn components(&self) -> [&T; 8] {
        let s = self;
        [&s.scalar, &s.e12, &s.e13, &s.e23, &s.e1inf, &s.e2inf, &s.e3inf, &s.e123inf]
    }

    pub(crate) fn singular(&self, op: &'static str) -> MotionError {
        MotionError::Singular { op, value: self.to_string() }
    }

    /// [`MotionError::NotFinite`] about a result of `op` on `self` that overflowed (the pose
    /// is not printed: its huge coefficients would fill the error line).
    pub(crate) fn overflow(&self, op: &'static str) -> MotionError {
        MotionError::NotFinite { op, value: "the result (an overflow)".to_string() }
    }
}

impl<T: Field> Pose<T> {
    /// The inverse `S⁻¹ = rev(S)/|S|²` with `1/|S|² = (α - βω)/α²` (Lemmas 2.6(ii) and
    /// 2.4(i)); no square root, so exact over exact scalars. Fails for singular `S`.
    ///
    /// ```
    /// use algebra_core::rational::{q, Q};
    /// use motion::Pose;
    /// let s = Pose::<Q>::rotor_from_parts(&q(1), &q(2), &[q(1), q(0), q(0)]) * Pose::translation(&[q(3), q(0), q(1)]);
    /// assert_eq!(&s * &s.try_inverse().unwrap(), Pose::identity());
    /// assert_eq!(s.try_inverse().unwrap(), s.inverse().unwrap()); // the generated elimination agrees
    /// ```
    pub fn try_inverse(&self) -> Result<Self, MotionError> {
        crate::scaled::require_finite("inverse", self, [])?;
        if let Some((e, s)) = crate::scaled::unusual_scale(self) {
            // (2^e S')⁻¹ = 2^-e S'⁻¹
            let inv = crate::scaled::scale_pow2(&s.try_inverse().map_err(|_| self.singular("inverse"))?, -e);
            return crate::scaled::require_finite("inverse", &inv, [])
                .map(|()| inv)
                .map_err(|_| self.overflow("inverse"));
        }
        let inv_n2 = self.pseudo_norm_squared().try_inverse().map_err(|_| self.singular("inverse"))?;
        Ok(&inv_n2 * &self.reverse())
    }
}

impl<T: Real> Pose<T> {
    /// The rotation `R = cos(φ/2) + sin(φ/2) (a e123)` by `angle` φ about the axis through the
    /// origin along `axis` (normalised here; right-handed: a positive angle about e3 turns e1
    /// towards e2).
    ///
    /// ```
    /// let r = motion::Pose::rotation(&[0.0, 0.0, 2.0], &std::f64::consts::PI).unwrap();
    /// let p = r.transform_point(&[1.0, 0.0, 0.0]).unwrap();
    /// assert!((p[0] + 1.0).abs() < 1e-15 && p[1].abs() < 1e-15);
    /// assert!(motion::Pose::rotation(&[0.0, 0.0, 0.0], &1.0).is_err());
    /// ```
    pub fn rotation(axis: &[T; 3], angle: &T) -> Result<Self, MotionError> {
        let a = unit_axis(axis)?;
        check_finite_scalar("rotation", angle)?;
        let half = angle.mul_ref(&T::from_ratio(1, 2));
        Ok(Pose::rotor_from_parts(&Real::cos(&half), &Real::sin(&half), &a))
    }

    /// `S = R T`: the rotation by `angle` about `axis` (through the origin) followed by the
    /// translation by `translation` (`F_{RT} = F_T F_R`, Lemma 2.3), so
    /// `F_S(p) = Rot(p) + translation`.
    ///
    /// ```
    /// let s = motion::Pose::from_axis_angle_translation(&[1.0, 0.0, 0.0], &0.0, &[0.0, 5.0, 0.0]).unwrap();
    /// assert_eq!(s.transform_point(&[1.0, 1.0, 1.0]).unwrap(), [1.0, 6.0, 1.0]);
    /// ```
    pub fn from_axis_angle_translation(axis: &[T; 3], angle: &T, translation: &[T; 3]) -> Result<Self, MotionError> {
        for x in translation {
            check_finite_scalar("from_axis_angle_translation", x)?;
        }
        Ok(Pose::rotation(axis, angle)? * Pose::translation(translation))
    }

    /// Deprecated: the bare array does not say its order. This is
    /// [`Pose::from_quaternion_wxyz`] (`[w, x, y, z]`, scalar first); nalgebra's
    /// `Quaternion::coords` and glam's `Quat::to_array` are `[x, y, z, w]` and would give a
    /// valid, different pose. Use [`Pose::from_quaternion`] with a named-field
    /// [`crate::Quaternion`], or the nalgebra/glam conversions, which take those types.
    ///
    /// ```
    /// # #![allow(deprecated)]
    /// use motion::Pose;
    /// let s = Pose::from_quaternion_translation(&[1.0, 0.0, 0.0, 0.0], &[1.0, 2.0, 3.0])?;
    /// assert_eq!(s, Pose::translation(&[1.0, 2.0, 3.0]));
    /// # Ok::<(), motion::MotionError>(())
    /// ```
    #[deprecated(
        since = "0.1.0",
        note = "the array order is ambiguous: use `Pose::from_quaternion_wxyz` ([w, x, y, z]) or `Pose::from_quaternion` (named fields)"
    )]
    pub fn from_quaternion_translation(q: &[T; 4], translation: &[T; 3]) -> Result<Self, MotionError> {
        Pose::from_quaternion_wxyz(q, translation)
    }

    /// The pseudoscalar norm `|S| = √(rev(S) S) = (2α + βω)/(2√α)` (Lemma 2.4(ii) with
    /// `rev(S) S = α + βω`, the root with positive scalar part). Fails for singular `S`.
    ///
    /// ```
    /// let s = motion::Pose::new(2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0); // 2 + ω
    /// let n = s.norm().unwrap(); // rev(S) S = 4 + 4ω, |S| = 2 + ω
    /// assert_eq!((n.scalar, n.e123inf), (2.0, 1.0));
    /// ```
    pub fn norm(&self) -> Result<Pseudoscalar<T>, MotionError> {
        self.check_finite("norm")?;
        // |m S'| = m |S'|: the squares of S' = S/m neither overflow nor underflow.
        let (m, s) = crate::scaled::rotational_scale(self).ok_or_else(|| self.singular("norm"))?;
        let n = s.pseudo_norm_squared().sqrt().map_err(|_| self.singular("norm"))?;
        let n = Pseudoscalar::new(n.scalar.mul_ref(&m), n.e123inf.mul_ref(&m));
        if Real::is_finite(&n.scalar) && Real::is_finite(&n.e123inf) {
            Ok(n)
        } else {
            Err(MotionError::NotFinite { op: "norm", value: self.to_string() })
        }
    }

    /// The unitary pose `U = S/|S|` (Lemma 2.6(i)): `rev(U) U = 1` and `U` generates the same
    /// transform as `S`.
    ///
    /// ```
    /// let s = motion::Pose::translation(&[1.0, 2.0, 3.0]).scale(&4.0);
    /// assert_eq!(s.unitize().unwrap(), motion::Pose::translation(&[1.0, 2.0, 3.0]));
    /// ```
    pub fn unitize(&self) -> Result<Self, MotionError> {
        self.check_finite("unitize")?;
        // S/|S| = S'/|S'| for S' = S/m (no overflow of |S| for huge S).
        let (_, s) = crate::scaled::rotational_scale(self).ok_or_else(|| self.singular("unitize"))?;
        let n = s.pseudo_norm_squared().sqrt().map_err(|_| self.singular("unitize"))?;
        let inv = n.try_inverse().map_err(|_| self.singular("unitize"))?;
        let u = s.scale_pseudoscalar(&inv);
        u.check_finite("unitize")?;
        Ok(u)
    }

    /// True when `rev(S) S = 1` within `tol` (each of `α - 1` and `β`).
    ///
    /// ```
    /// assert!(motion::Pose::translation(&[1.0, 2.0, 3.0]).is_unitary(&1e-15));
    /// assert!(!motion::Pose::<f64>::identity().scale(&2.0).is_unitary(&1e-15));
    /// ```
    pub fn is_unitary(&self, tol: &T) -> bool {
        let n2 = self.pseudo_norm_squared();
        Real::abs(&n2.scalar.sub_ref(&T::one())) <= *tol && Real::abs(&n2.e123inf) <= *tol
    }

    /// Theorem 2.8 with a tolerance: `self` and `other` are equivalent (`other = γ self` for a
    /// non-singular pseudoscalar `γ`), so they generate the same transform. The test is that
    /// the bivector part of `other rev(self)/√(α_self α_other)` has every component within
    /// `tol` (`α` = scalar part of `rev(S) S`); its einf components carry lengths, so with
    /// translations of size `L` expect rounding of order `L·ε`. Fails for singular input.
    ///
    /// ```
    /// use motion::{Pose, Pseudoscalar};
    /// let s = Pose::from_axis_angle_translation(&[1.0, 2.0, 3.0], &0.7, &[4.0, 5.0, 6.0]).unwrap();
    /// let v = s.scale_pseudoscalar(&Pseudoscalar::new(-2.0, 0.5));
    /// assert!(s.is_equivalent(&v, &1e-12).unwrap());
    /// assert!(!s.is_equivalent(&Pose::identity(), &1e-12).unwrap());
    /// ```
    pub fn is_equivalent(&self, other: &Self, tol: &T) -> Result<bool, MotionError> {
        let (us, uo) = (crate::scaled::unusual_scale(self), crate::scaled::unusual_scale(other));
        if us.is_some() || uo.is_some() {
            // equivalence does not depend on the scale: decided at unit scale (1e300 S, 1e-300 S)
            for p in [self, other] {
                if p.is_singular() {
                    return Err(p.singular("is_equivalent"));
                }
            }
            let (s, o) = (us.map_or_else(|| self.clone(), |u| u.1), uo.map_or_else(|| other.clone(), |u| u.1));
            return s.is_equivalent(&o, tol);
        }
        let a = self.pseudo_norm_squared().scalar;
        let b = other.pseudo_norm_squared().scalar;
        if !is_positive(&a) {
            return Err(self.singular("is_equivalent"));
        }
        if !is_positive(&b) {
            return Err(other.singular("is_equivalent"));
        }
        let scale = Real::sqrt(&a).mul_ref(&Real::sqrt(&b));
        let bound = tol.mul_ref(&scale);
        let w = other * &self.reverse();
        let parts = [&w.e12, &w.e13, &w.e23, &w.e1inf, &w.e2inf, &w.e3inf];
        if !parts.iter().all(|x| Real::is_finite(*x)) || !Real::is_finite(&bound) {
            return Err(self.overflow("is_equivalent"));
        }
        Ok(parts.into_iter().all(|x| Real::abs(x) <= bound))
    }

    /// True when every coefficient is finite.
    ///
    /// ```
    /// assert!(motion::Pose::<f64>::identity().is_finite());
    /// assert!(!motion::Pose::translation(&[f64::NAN, 0.0, 0.0]).is_finite());
    /// ```
    pub fn is_finite(&self) -> bool {
        self.components().into_iter().all(Real::is_finite)
    }

    /// [`Pose::is_finite`] as one test: every coefficient's finiteness and-ed without
    /// short-circuit (one branch for the direct paths instead of eight). Not `is_finite`
    /// under another name: `Pose::log`'s direct path with `is_finite` in its place measured
    /// 1.60x its kernel against 1.48x (the pose bench, Intel Xeon VM), though neither test runs
    /// for the bench's poses (`modest_f64` holds): the short-circuit chain compiles worse.
    #[inline]
    pub(crate) fn all_finite_value(&self) -> bool {
        self.components().iter().fold(true, |ok, x| ok & x.is_finite_value())
    }

    /// True when `T` is a plain `f64` (one component of `f64` precision: not a dual number,
    /// a jet or lanes) and every coefficient is finite and below `2^200` in magnitude: one
    /// integer comparison on the largest of the magnitudes' bits (a NaN's bits lie above those
    /// of every finite number). The direct paths then bound their results a priori instead of
    /// testing them.
    #[inline]
    pub(crate) fn modest_f64(&self) -> bool {
        if !crate::series::plain_f64::<T>() {
            return false;
        }
        let m = self.components().iter().fold(0u64, |m, x| m.max(x.to_f64().abs().to_bits()));
        m < MODEST.to_bits()
    }

    pub(crate) fn check_finite(&self, op: &'static str) -> Result<(), MotionError> {
        if self.is_finite() { Ok(()) } else { Err(MotionError::NotFinite { op, value: self.to_string() }) }
    }
}

/// `2^200`, the bound of [`Pose::modest_f64`].
const MODEST: f64 = f64::from_bits((1023 + 200) << 52);

/// `axis / |axis|`, or [`MotionError::ZeroAxis`].
pub(crate) fn unit_axis<T: Real>(axis: &[T; 3]) -> Result<[T; 3], MotionError> {
    for x in axis {
        check_finite_scalar("rotation axis", x)?;
    }
    // divided by the largest component first: [1e200, 1e200, 0] and [1e-200, 0, 0] have directions
    crate::scaled::direction(axis).ok_or(MotionError::ZeroAxis)
}

/// `x > 0`, false for NaN.
pub(crate) fn is_positive<T: Ring + PartialOrd>(x: &T) -> bool {
    x.partial_cmp(&T::zero()) == Some(std::cmp::Ordering::Greater)
}

pub(crate) fn check_finite_scalar<T: Real>(op: &'static str, x: &T) -> Result<(), MotionError> {
    if x.is_finite() { Ok(()) } else { Err(MotionError::NotFinite { op, value: x.to_string() }) }
}
