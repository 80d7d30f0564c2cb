//! Operators and conversions for [`Pose`]: the geometric product (composition, Lemma 2.3),
//! sums and differences (additive motions, eq. 17), negation (an equivalent pose), printing,
//! and `From` both ways with the generated [`Motor`].
//!
//! ```
//! use motion::{Motor, Pose};
//! let u = Pose::translation(&[1.0, 0.0, 0.0]);
//! let v = Pose::rotation(&[0.0, 0.0, 1.0], &std::f64::consts::PI).unwrap();
//! // U * V applies U first, then V: (0,0,0) -> (1,0,0) -> (-1,0,0).
//! let p = (&u * &v).transform_point(&[0.0, 0.0, 0.0]).unwrap();
//! assert!((p[0] + 1.0).abs() < 1e-15 && p[1].abs() < 1e-15);
//! let m: Motor<f64> = (&u + &v).into();
//! assert_eq!(m.scalar, 1.0 + v.as_motor().scalar);
//! ```

use crate::Pose;
use algebra_core::Ring;
use gam_algebras::g123inf::Motor;
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};

impl<T: Ring> fmt::Debug for Pose<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Pose({})", self.0)
    }
}

impl<T: Ring> fmt::Display for Pose<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.0, f)
    }
}

impl<T: Ring> From<Motor<T>> for Pose<T> {
    fn from(m: Motor<T>) -> Self {
        Pose(m)
    }
}

impl<T: Ring> From<Pose<T>> for Motor<T> {
    fn from(p: Pose<T>) -> Self {
        p.0
    }
}

/// The geometric product: `U * V` applies `U` first, then `V` (`F_{UV} = F_V F_U`, Lemma 2.3).
impl<T: Ring> Mul<&Pose<T>> for &Pose<T> {
    type Output = Pose<T>;
    fn mul(self, rhs: &Pose<T>) -> Pose<T> {
        Pose(&self.0 * &rhs.0)
    }
}

/// The geometric product: `U * V` applies `U` first, then `V` (Lemma 2.3).
impl<T: Ring> Mul for Pose<T> {
    type Output = Pose<T>;
    fn mul(self, rhs: Pose<T>) -> Pose<T> {
        &self * &rhs
    }
}

/// The sum of even elements (additive motions, eq. 17).
impl<T: Ring> Add<&Pose<T>> for &Pose<T> {
    type Output = Pose<T>;
    fn add(self, rhs: &Pose<T>) -> Pose<T> {
        Pose(&self.0 + &rhs.0)
    }
}

/// The sum of even elements (additive motions, eq. 17).
impl<T: Ring> Add for Pose<T> {
    type Output = Pose<T>;
    fn add(self, rhs: Pose<T>) -> Pose<T> {
        Pose(self.0 + rhs.0)
    }
}

/// The difference of even elements.
impl<T: Ring> Sub<&Pose<T>> for &Pose<T> {
    type Output = Pose<T>;
    fn sub(self, rhs: &Pose<T>) -> Pose<T> {
        Pose(&self.0 - &rhs.0)
    }
}

/// The difference of even elements.
impl<T: Ring> Sub for Pose<T> {
    type Output = Pose<T>;
    fn sub(self, rhs: Pose<T>) -> Pose<T> {
        Pose(self.0 - rhs.0)
    }
}

/// `-S`: an equivalent pose (Theorem 2.8 with γ = -1).
impl<T: Ring> Neg for &Pose<T> {
    type Output = Pose<T>;
    fn neg(self) -> Pose<T> {
        Pose(-&self.0)
    }
}

/// `-S`: an equivalent pose (Theorem 2.8 with γ = -1).
impl<T: Ring> Neg for Pose<T> {
    type Output = Pose<T>;
    fn neg(self) -> Pose<T> {
        Pose(-self.0)
    }
}
