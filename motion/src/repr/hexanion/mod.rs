//! Angelidis' hexanions `<ω, m>` ("Hexanions: 6D space for twists"): a real vector space of
//! twists (eqs. 8-12) whose exponential is a rigid motion.
//!
//! * the type, its vector-space operations (8)-(12), the matrix form (4), the inverse (22) and
//!   the Rot/Trs split (32)-(33) and classification (27): this file;
//! * the exponential (14)/(66) as a 4x4 matrix and as a pose, the point and normal transforms
//!   (16)-(19), (29), (30), (35), (36): [`exp`];
//! * conversions: the pose (principal logarithm) and the matrix -> hexanion algorithm of Sec. 6
//!   (43)-(53): [`convert`];
//! * interpolation (56), weighted blending (57) and the decoupled motion (58)-(60), and the
//!   piecewise linear motion through key poses of `gam interpolate`'s `hexanion-linear`:
//!   [`blend`].
//!
//! The hexanion `<ω, m>` is the pose `exp(½(ω e123 + m einf))` of the main paper (with
//! `a e123 = a1 e23 - a2 e13 + a3 e12`): both are the rigid motion `p ↦ R p + V m` with `R` the
//! rotation by `|ω|` about `ω` and `V = I + a[ω]× + c[ω]×²` (`a = (1 - cos|ω|)/|ω|²`,
//! `c = (|ω| - sin|ω|)/|ω|³`).
//!
//! ```
//! use motion::repr::hexanion::Hexanion;
//! use std::f64::consts::FRAC_PI_2;
//! // a quarter turn about the z axis through (1, 0, 0): <ω, c × ω> (eq. 26)
//! let h = Hexanion::new([0.0, 0.0, FRAC_PI_2], [0.0, -FRAC_PI_2, 0.0]);
//! let p = h.transform_point(&[1.0, 0.0, 0.0]);
//! assert!((p[0] - 1.0).abs() < 1e-15 && p[1].abs() < 1e-15);
//! ```

pub mod blend;
pub mod convert;
pub mod exp;

use crate::repr::vec3::{add, cross, dot, scale, sub, zero};
use algebra_core::{Field, Real, Ring};
use std::ops::{Add, Neg, Sub};

/// Angelidis' hexanion `<ω, m>` (his Sec. 3): the rotation vector `ω` and the "moment" `m`.
/// Its matrix form is `(ω, m) = [[ [ω]×, m ], [0, 0]]` (eq. 4) and the rigid motion it stands
/// for is `exp(ω, m)` (eq. 13).
///
/// ```
/// use motion::repr::hexanion::Hexanion;
/// let a = Hexanion::new([1.0, 0.0, 0.0], [0.0, 2.0, 0.0]);
/// let b = Hexanion::new([0.0, 1.0, 0.0], [1.0, 0.0, 0.0]);
/// assert_eq!(&a + &b, Hexanion::new([1.0, 1.0, 0.0], [1.0, 2.0, 0.0]));
/// assert_eq!(a.scale(&2.0), Hexanion::new([2.0, 0.0, 0.0], [0.0, 4.0, 0.0]));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Hexanion<T> {
    /// `ω`: the rotation axis scaled by the angle `θ` (`ω = θ n`).
    pub omega: [T; 3],
    /// `m = θ c × n + t n` for a twist about the axis through `c` along `n` with translation
    /// `t` along it (eq. 5).
    pub m: [T; 3],
}

/// What a hexanion is (Angelidis Sec. 4): a translation `<0, m>` (23), a rotation about an axis
/// (`ω·m = 0`, (26)-(27)) or a general twist (Sec. 4.3).
///
/// ```
/// use motion::repr::hexanion::{Hexanion, Kind};
/// let h = Hexanion::new([0.0, 0.0, 2.0], [2.0, 0.0, 0.0]); // c = ω × m/|ω|² = (0, 1, 0)
/// assert_eq!(h.classify(&0.0), Kind::Rotation { centre: [0.0, 1.0, 0.0], angle: 2.0, axis: [0.0, 0.0, 1.0] });
/// ```
#[derive(Clone, Debug, PartialEq)]
pub enum Kind<T> {
    /// `<0, 0>`, the neutral element (20)-(21).
    Identity,
    /// `<0, m>`: the translation by `m` (23)-(25).
    Translation {
        /// The translation vector `m`.
        by: [T; 3],
    },
    /// `<ω, c × ω>` (26): the rotation by `angle` `θ = |ω|` about the unit `axis` `n = ω/|ω|`
    /// through `centre` `c = ω × m/|ω|²` (27), the point of the axis nearest the origin.
    Rotation {
        /// `c` of (27).
        centre: [T; 3],
        /// `θ` of (27).
        angle: T,
        /// `n` of (27).
        axis: [T; 3],
    },
    /// A twist: the rotation of (27) followed by the translation `t n` along its axis,
    /// `t = (ω·m)/|ω|` (the `Trs` part (33) is `<0, t n>`).
    Twist {
        /// `c` of (27).
        centre: [T; 3],
        /// `θ` of (27).
        angle: T,
        /// `n` of (27).
        axis: [T; 3],
        /// `t`: the translation along the axis.
        translation: T,
    },
}

impl<T: Ring> Hexanion<T> {
    /// `<ω, m>`.
    ///
    /// ```
    /// let h = motion::repr::hexanion::Hexanion::new([1.0, 2.0, 3.0], [4.0, 5.0, 6.0]);
    /// assert_eq!(h.m[2], 6.0);
    /// ```
    pub fn new(omega: [T; 3], m: [T; 3]) -> Self {
        Hexanion { omega, m }
    }

    /// The neutral element `<0, 0>` (eqs. 20-21).
    ///
    /// ```
    /// let z = motion::repr::hexanion::Hexanion::<f64>::zero();
    /// assert_eq!(z.transform_point(&[1.0, 2.0, 3.0]), [1.0, 2.0, 3.0]);
    /// ```
    pub fn zero() -> Self {
        Hexanion { omega: zero(), m: zero() }
    }

    /// `λ · <ω, m> = <λω, λm>` (eqs. 9-12).
    ///
    /// ```
    /// let h = motion::repr::hexanion::Hexanion::new([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    /// assert_eq!(h.scale(&-1.0), h.inverse());
    /// ```
    pub fn scale(&self, lambda: &T) -> Self {
        Hexanion { omega: scale(lambda, &self.omega), m: scale(lambda, &self.m) }
    }

    /// The inverse `<-ω, -m>`, the backward motion (eq. 22): `exp(-ω, -m) = exp(ω, m)⁻¹`.
    ///
    /// ```
    /// use motion::repr::hexanion::Hexanion;
    /// let h = Hexanion::<f64>::new([0.3, -0.2, 0.9], [1.0, 2.0, -1.0]);
    /// let p = h.inverse().transform_point(&h.transform_point(&[1.0, 1.0, 1.0]));
    /// assert!(p.iter().all(|x| (x - 1.0).abs() < 1e-14));
    /// ```
    pub fn inverse(&self) -> Self {
        Hexanion { omega: self.omega.clone().map(|x| x.neg_ref()), m: self.m.clone().map(|x| x.neg_ref()) }
    }

    /// The matrix form (eq. 4): `[[0, -ωz, ωy, mx], [ωz, 0, -ωx, my], [-ωy, ωx, 0, mz], [0, 0, 0, 0]]`.
    ///
    /// ```
    /// let h = motion::repr::hexanion::Hexanion::new([1.0, 2.0, 3.0], [4.0, 5.0, 6.0]);
    /// assert_eq!(h.matrix()[1], [3.0, 0.0, -1.0, 5.0]);
    /// ```
    pub fn matrix(&self) -> [[T; 4]; 4] {
        let (w, m, z) = (&self.omega, &self.m, T::zero);
        [
            [z(), w[2].neg_ref(), w[1].clone(), m[0].clone()],
            [w[2].clone(), z(), w[0].neg_ref(), m[1].clone()],
            [w[1].neg_ref(), w[0].clone(), z(), m[2].clone()],
            [z(), z(), z(), z()],
        ]
    }

    /// The hexanion of a 4x4 matrix of the form (4) (the inverse of [`Hexanion::matrix`]; the
    /// skew part is read from the lower triangle).
    ///
    /// ```
    /// let h = motion::repr::hexanion::Hexanion::new([1.0, 2.0, 3.0], [4.0, 5.0, 6.0]);
    /// assert_eq!(motion::repr::hexanion::Hexanion::from_matrix_form(&h.matrix()), h);
    /// ```
    pub fn from_matrix_form(x: &[[T; 4]; 4]) -> Self {
        Hexanion {
            omega: [x[2][1].clone(), x[0][2].clone(), x[1][0].clone()],
            m: [x[0][3].clone(), x[1][3].clone(), x[2][3].clone()],
        }
    }
}

impl<T: Field> Hexanion<T> {
    /// The split `<ω, m> = Rot + Trs` (eqs. 32-33): `Rot = <ω, ω × m × ω/|ω|²>` (a rotation,
    /// `ω·m' = 0`) and `Trs = <0, (m·ω)/|ω|² ω>`. No square root: exact over rationals.
    /// `None` when `ω = 0` exactly (a translation is all `Trs`, but (33) divides by `|ω|²`).
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use motion::repr::hexanion::Hexanion;
    /// let h = Hexanion::new([q(0), q(0), q(2)], [q(1), q(0), q(3)]);
    /// let (rot, trs) = h.rot_trs().unwrap();
    /// assert_eq!(rot, Hexanion::new([q(0), q(0), q(2)], [q(1), q(0), q(0)]));
    /// assert_eq!(trs, Hexanion::new([q(0), q(0), q(0)], [q(0), q(0), q(3)]));
    /// assert_eq!(&rot + &trs, h);
    /// ```
    pub fn rot_trs(&self) -> Option<(Self, Self)> {
        let w2 = dot(&self.omega, &self.omega);
        let inv = w2.try_recip()?;
        // ω × m × ω = |ω|² m - (ω·m) ω
        let k = dot(&self.omega, &self.m).mul_ref(&inv);
        let along = scale(&k, &self.omega);
        Some((Hexanion::new(self.omega.clone(), sub(&self.m, &along)), Hexanion::new(zero(), along)))
    }
}

impl<T: Real> Hexanion<T> {
    /// The classification of Sec. 4 with the centre, angle and axis of (27). With `tol = 0` the
    /// tests are exact (`ω = 0`, `ω·m = 0`), as printed; otherwise `|ω| ≤ tol` counts as a
    /// translation and `|ω·m| ≤ tol |ω| |m|` as a rotation.
    ///
    /// ```
    /// use motion::repr::hexanion::{Hexanion, Kind};
    /// assert_eq!(Hexanion::new([0.0; 3], [1.0, 0.0, 0.0]).classify(&0.0), Kind::Translation { by: [1.0, 0.0, 0.0] });
    /// let twist = Hexanion::new([0.0, 0.0, 2.0], [0.0, 0.0, 3.0]).classify(&0.0);
    /// assert_eq!(twist, Kind::Twist { centre: [0.0; 3], angle: 2.0, axis: [0.0, 0.0, 1.0], translation: 3.0 });
    /// ```
    pub fn classify(&self, tol: &T) -> Kind<T> {
        let theta = crate::repr::vec3::norm(&self.omega);
        let m_len = crate::repr::vec3::norm(&self.m);
        if theta <= *tol {
            return if m_len.is_exact_zero() { Kind::Identity } else { Kind::Translation { by: self.m.clone() } };
        }
        let inv = T::one().div_ref(&theta);
        let axis = scale(&inv, &self.omega);
        let centre = scale(&inv.mul_ref(&inv), &cross(&self.omega, &self.m));
        let wm = dot(&self.omega, &self.m);
        if Real::abs(&wm) <= tol.mul_ref(&theta).mul_ref(&m_len) {
            Kind::Rotation { centre, angle: theta, axis }
        } else {
            Kind::Twist { centre, angle: theta, axis, translation: wm.mul_ref(&inv) }
        }
    }

    /// The twist (eqs. 5, 31, 44) of the rotation by `angle` `θ` about the axis through `centre`
    /// along the unit `axis` `n`, then the translation `t n`: `<θ n, θ c × n + t n>`.
    ///
    /// ```
    /// use motion::repr::hexanion::Hexanion;
    /// let h = Hexanion::twist(&[0.0, 1.0, 0.0], &2.0, &[0.0, 0.0, 1.0], &3.0);
    /// assert_eq!(h, Hexanion::new([0.0, 0.0, 2.0], [2.0, 0.0, 3.0]));
    /// ```
    pub fn twist(centre: &[T; 3], angle: &T, axis: &[T; 3], translation: &T) -> Self {
        let m = add(&scale(angle, &cross(centre, axis)), &scale(translation, axis));
        Hexanion::new(scale(angle, axis), m)
    }
}

impl<T: Ring> Add<&Hexanion<T>> for &Hexanion<T> {
    type Output = Hexanion<T>;
    /// `A + B`, componentwise (eq. 8).
    ///
    /// ```
    /// use motion::repr::hexanion::Hexanion;
    /// let a = Hexanion::new([1.0, 0.0, 0.0], [0.0; 3]);
    /// assert_eq!(&a + &a, a.scale(&2.0));
    /// ```
    fn add(self, rhs: &Hexanion<T>) -> Hexanion<T> {
        Hexanion::new(add(&self.omega, &rhs.omega), add(&self.m, &rhs.m))
    }
}

impl<T: Ring> Sub<&Hexanion<T>> for &Hexanion<T> {
    type Output = Hexanion<T>;
    /// `A - B`, componentwise.
    ///
    /// ```
    /// use motion::repr::hexanion::Hexanion;
    /// let a = Hexanion::new([1.0, 0.0, 0.0], [0.0; 3]);
    /// assert_eq!(&a - &a, Hexanion::zero());
    /// ```
    fn sub(self, rhs: &Hexanion<T>) -> Hexanion<T> {
        Hexanion::new(sub(&self.omega, &rhs.omega), sub(&self.m, &rhs.m))
    }
}

impl<T: Ring> Neg for &Hexanion<T> {
    type Output = Hexanion<T>;
    /// `-A`, the inverse (22).
    ///
    /// ```
    /// use motion::repr::hexanion::Hexanion;
    /// let a = Hexanion::new([1.0, 0.0, 0.0], [0.0; 3]);
    /// assert_eq!(-&a, a.inverse());
    /// ```
    fn neg(self) -> Hexanion<T> {
        self.inverse()
    }
}
