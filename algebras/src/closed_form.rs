//! Closed-form `exp`, `log`, `normalize`, `sqrt` and `pow` on the motors of the predefined
//! algebras whose motors are the dual quaternions: the main paper's `G_{123inf}`
//! ([`crate::g123inf`], Appendix 2), PGA `R^{3,0,1}` ([`crate::pga3`]) and the poses
//! `G_{123inf}^+` inside the main paper's `G_{0123inf}` ([`crate::cga_null`]: `Motor` and
//! `PoseBivector`).
//!
//! Hand-written (not emitted), because the closed form depends on the algebra's structure, not
//! only on its tables: in both algebras a bivector `B` squares to a *dual number*
//! `B² = a + c I` with `I` the pseudoscalar (`I² = 0`, `I` central in the even subalgebra), so
//! `B² = -(θ + δI)²` with `θ² = -a`, `δ = -c/(2θ)`, and the series of `exp` sums to
//!
//! `exp(B) = cos θ + (c/2) sinc θ I + (sinc θ - (c/2) k(θ) I) B`, `k(θ) = (cos θ - sinc θ)/θ²`,
//!
//! (the dual-angle formula `cos θ̂ + B sin θ̂ / θ̂` written without dividing by `θ`, so pure
//! translations need no special case). `log` inverts it for unit motors; `normalize` divides by
//! the dual-number norm `sqrt(M rev(M))`; `sqrt` and `pow` go through `log`. The generic
//! reference is the runtime series ([`algebra_core::Multivector::exp`]), which the tests compare
//! against.
//!
//! Non-finite input (docs/robustness.md): `exp` is an unchecked kernel, NaN in, NaN out, like
//! the generated products; `try_exp` is the checked entry point and returns
//! `MvError::Undefined` ("coefficients are not finite") for a NaN or infinite coefficient, as
//! the runtime `exp` does. `normalize`, `log`, `log_unit`, `sqrt` and `pow` already return a
//! `Result`, and refuse non-finite input (and a non-finite `t`) with the same error.
//!
//! ```
//! use gam_algebras::g123inf::{Bivector, Motor};
//! // a quarter turn about e12 with a translation along e3inf
//! let b = Bivector::<f64>::e12() * std::f64::consts::FRAC_PI_4 + Bivector::e3inf() * 0.5;
//! let m: Motor<f64> = b.exp();
//! let back = m.log().unwrap();
//! assert!(back.iter().zip(b.iter()).all(|(x, y)| (x - y).abs() < 1e-15));
//! let half = m.sqrt().unwrap();
//! let twice = half * half;
//! assert!(twice.iter().zip(m.iter()).all(|(x, y)| (x - y).abs() < 1e-15));
//! assert!((m.pow(&0.5).unwrap().e12 - half.e12).abs() < 1e-15);
//! assert!((m.scale(&2.0).normalize().unwrap().scalar - m.scalar).abs() < 1e-15);
//! ```

use algebra_core::{MvError, Real};

/// Below this `θ` the series of `sinc` and `k` are used (their truncation error is `θ⁶`).
const SMALL: f64 = 1e-3;

/// `(sinc θ, (cos θ - sinc θ)/θ², cos θ)` from `θ² >= 0`.
fn exp_factors<T: Real>(theta2: &T) -> (T, T, T) {
    let theta = theta2.sqrt();
    if theta.to_f64() < SMALL {
        let r = |n, d| T::from_ratio(n, d);
        // sinc θ = 1 - θ²/6 + θ⁴/120; k = -1/3 + θ²/30 - θ⁴/840; cos θ = 1 - θ²/2 + θ⁴/24
        let t4 = theta2.mul_ref(theta2);
        let sinc = T::one() - r(1, 6) * theta2.clone() + r(1, 120) * t4.clone();
        let k = r(-1, 3) + r(1, 30) * theta2.clone() - r(1, 840) * t4.clone();
        let cos = T::one() - r(1, 2) * theta2.clone() + r(1, 24) * t4;
        (sinc, k, cos)
    } else {
        let (s, c) = (theta.sin(), theta.cos());
        let sinc = s / theta;
        let k = (c.clone() - sinc.clone()) / theta2.clone();
        (sinc, k, c)
    }
}

/// `(sinc θ, (cos θ - sinc θ)/(θ sin θ), θ)` from `sin θ = |b| >= 0` and `cos θ = s`.
fn log_factors<T: Real>(sin: &T, cos: &T) -> (T, T) {
    let theta = sin.atan2(cos);
    if theta.to_f64() < SMALL {
        let r = |n, d| T::from_ratio(n, d);
        let t2 = theta.mul_ref(&theta);
        // sinc θ = 1 - θ²/6 + θ⁴/120; (cos θ - sinc θ)/(θ sin θ) = -1/3 - θ²/45 - 2θ⁴/945
        let t4 = t2.mul_ref(&t2);
        let sinc = T::one() - r(1, 6) * t2.clone() + r(1, 120) * t4.clone();
        let k = r(-1, 3) - r(1, 45) * t2 - r(2, 945) * t4;
        (sinc, k)
    } else {
        let sinc = sin.clone() / theta.clone();
        let k = (cos.clone() - sinc.clone()) / (theta * sin.clone());
        (sinc, k)
    }
}

fn undefined(op: &'static str, value: String, why: &str) -> MvError {
    MvError::Undefined { op, value, why: why.to_string() }
}

/// `Ok` when every coefficient is finite, else the runtime's "coefficients are not finite".
fn check_finite<'a, T: Real + 'a>(
    op: &'static str,
    value: &dyn std::fmt::Display,
    mut coeffs: impl Iterator<Item = &'a T>,
) -> Result<(), MvError> {
    if coeffs.all(T::is_finite) { Ok(()) } else { Err(undefined(op, value.to_string(), "coefficients are not finite")) }
}

/// The closed forms for one module: the pseudoscalar field `$ps`, the Euclidean bivector
/// fields `e12, e13, e23` and the ideal ones `$i1, $i2, $i3` with `I e23 = -$i1`,
/// `I e13 = $i2`, `I e12 = -$i3` (the same pattern in both algebras).
macro_rules! closed_form {
    ($m:ident, $b:ident, $proj:ident, $ps:ident, [$i1:ident, $i2:ident, $i3:ident]) => {
        impl<T: Real> crate::$m::$b<T> {
            /// `I self` (only the Euclidean part contributes, since `I² = 0`).
            fn i_times(&self) -> Self {
                let mut out = Self::zero();
                out.$i1 = -self.e23.clone();
                out.$i2 = self.e13.clone();
                out.$i3 = -self.e12.clone();
                out
            }

            /// [`Self::exp`] after checking that every coefficient is finite:
            /// `MvError::Undefined` ("coefficients are not finite") otherwise, and "the result is
            /// not finite" when a finite bivector is too large for the scalar (the unchecked
            /// kernel would return NaN).
            pub fn try_exp(&self) -> Result<crate::$m::Motor<T>, MvError> {
                check_finite("exp", self, self.iter())?;
                let out = self.exp();
                check_finite("exp", self, out.iter()).map_err(|_| {
                    undefined(
                        "exp",
                        self.to_string(),
                        "the result is not finite (the bivector is too large for this scalar)",
                    )
                })?;
                Ok(out)
            }

            /// The exponential in closed form (see [`crate::closed_form`]): a unit motor. An
            /// unchecked kernel: a NaN or infinite coefficient gives NaN coefficients (use
            /// [`Self::try_exp`] for input of unknown origin).
            pub fn exp(&self) -> crate::$m::Motor<T> {
                let theta2 = self.e12.mul_ref(&self.e12) + self.e13.mul_ref(&self.e13) + self.e23.mul_ref(&self.e23);
                // B² = -θ² + c I, c = 2 (b12 i3 - b13 i2 + b23 i1)
                let half_c = self.e12.mul_ref(&self.$i3) - self.e13.mul_ref(&self.$i2) + self.e23.mul_ref(&self.$i1);
                let (sinc, k, cos) = exp_factors(&theta2);
                let v = self.scale(&sinc) - self.i_times().scale(&half_c.mul_ref(&k));
                let mut out = crate::$m::Motor::from(&v);
                out.scalar = cos;
                out.$ps = half_c * sinc;
                out
            }
        }

        impl<T: Real> crate::$m::Motor<T> {
            /// `self / sqrt(self rev(self))`, the dual-number norm `α + βI` inverted in closed
            /// form: a unit motor (`m rev(m) = 1`) when `self` satisfies the Study condition
            /// (every product of unit motors does). Fails when `α <= 0`.
            pub fn normalize(&self) -> Result<Self, MvError> {
                check_finite("normalize", self, self.iter())?;
                let alpha = self.norm_squared();
                if alpha.to_f64().is_nan() || alpha.to_f64() <= 0.0 {
                    return Err(undefined("normalize", self.to_string(), "the norm self rev(self) is not positive"));
                }
                // β/2 = s p - b12 i3 + b13 i2 - b23 i1 (the main paper's eq. 5)
                let half_beta = self.scalar.mul_ref(&self.$ps) - self.e12.mul_ref(&self.$i3)
                    + self.e13.mul_ref(&self.$i2)
                    - self.e23.mul_ref(&self.$i1);
                // 1/sqrt(α + βI) = u + w I with u = 1/√α, w = -β/(2α√α)
                let u = T::one() / alpha.sqrt();
                let w = -(half_beta * u.clone()) / alpha;
                let b = self.$proj();
                let ib = b.i_times();
                let mut out = self.scale(&u);
                out.$ps = out.$ps.clone() + self.scalar.mul_ref(&w);
                out.$i1 = out.$i1.clone() + ib.$i1.mul_ref(&w);
                out.$i2 = out.$i2.clone() + ib.$i2.mul_ref(&w);
                out.$i3 = out.$i3.clone() + ib.$i3.mul_ref(&w);
                Ok(out)
            }

            /// The logarithm of `normalize(self)` in closed form: the bivector `B` with
            /// `exp(B) = normalize(self)` and rotation half-angle `θ ∈ [0, π)`. Fails when
            /// `normalize` does, and for a rotation by a full turn (`θ = π`, no unique axis).
            pub fn log(&self) -> Result<crate::$m::$b<T>, MvError> {
                self.normalize()?.log_unit()
            }

            /// The logarithm of a motor that is already unit (`self rev(self) = 1`, as every
            /// `exp` and product of unit motors is, up to rounding): [`Self::log`] without the
            /// normalisation (one square root, a division and 24 multiplications fewer). For a
            /// motor that is not unit the result is not a logarithm of anything; use
            /// [`Self::log`]. Fails for a full turn.
            pub fn log_unit(&self) -> Result<crate::$m::$b<T>, MvError> {
                check_finite("log", self, self.iter())?;
                let n = self;
                let sin = (n.e12.mul_ref(&n.e12) + n.e13.mul_ref(&n.e13) + n.e23.mul_ref(&n.e23)).sqrt();
                if sin.to_f64() == 0.0 && n.scalar.to_f64() < 0.0 {
                    return Err(undefined("log", self.to_string(), "a full turn has no unique rotation axis"));
                }
                let (sinc, k) = log_factors(&sin, &n.scalar);
                let b = n.$proj();
                let inv = T::one() / sinc;
                let ib = b.i_times().scale(&(n.$ps.mul_ref(&k) * inv.clone() * inv.clone()));
                Ok(b.scale(&inv) + ib)
            }

            /// The square root of `normalize(self)`: `exp(log(self)/2)`, whose square is the
            /// normalised motor.
            pub fn sqrt(&self) -> Result<Self, MvError> {
                Ok((self.log()? * T::from_ratio(1, 2)).exp())
            }

            /// `normalize(self)^t = exp(t log(self))`.
            pub fn pow(&self, t: &T) -> Result<Self, MvError> {
                check_finite("pow", t, std::iter::once(t))?;
                Ok((self.log()? * t.clone()).exp())
            }
        }
    };
}

closed_form!(g123inf, Bivector, project_to_bivector, e123inf, [e1inf, e2inf, e3inf]);
closed_form!(pga3, Bivector, project_to_bivector, e0123, [e01, e02, e03]);
// the poses inside the main paper's G_{0123inf}: the same subalgebra, product basis elements of
// orthogonal generators (so the same coefficients as g123inf's blades)
closed_form!(cga_null, PoseBivector, project_to_pose_bivector, e123inf, [e1inf, e2inf, e3inf]);
