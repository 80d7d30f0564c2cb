//! Closed-form `exp`, `log`, `normalize`, `sqrt` and `pow` on the motors of the predefined
//! algebras whose motors are the dual quaternions: the main paper's `G_{123inf}`
//! ([`crate::g123inf`], Appendix 2), PGA `R^{3,0,1}` ([`crate::pga3`]) and the poses
//! `G_{123inf}^+` inside the main paper's `G_{0123inf}` ([`crate::cga_null`]: `Motor` and
//! `PoseBivector`).
//!
//! The methods are emitted by the code generator (`algebra_codegen::closed`), which detects
//! from the exact product tables that in these algebras a bivector `B` squares to a *dual number*
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
