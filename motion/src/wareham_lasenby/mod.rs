//! Wareham and Lasenby, "Rigid-body pose and position interpolation using geometric algebra",
//! in the built-in `cga` = R^{4,1} (generated [`gam_algebras::cga`] types):
//!
//! | module | contents |
//! |---|---|
//! | [`cga`] | `n`, `n̄`, `F(x)` and its inverse, translators, rotation rotors, planes, the twist `τ(ψ, P, a)` |
//! | [`generator`] | generators `B = φP + tn`, the closed-form exponential of Theorem 3, the parts `(ψ, P, t∥, t⊥)` of Sec. 2.6 |
//! | [`mod@log`] | the logarithm `ℓ(R)` of Theorem 9 with its edge cases (pure translation, `|φ| = π`) |
//! | [`convert`] | displacement rotor ↔ the main paper's [`Pose`](crate::Pose), both ways |
//! | [`helix`] | the closed-form screw path of a body point under `exp(λB)` (Sec. 4.1) |
//! | [`interp`] | the interpolation schemes of Sec. 3 as [`Motion`](crate::Motion)s |
//!
//! Rotors act by `X ↦ R X rev(R)`; a displacement rotor `R` of the pose `x ↦ Rot x + v`
//! satisfies `R F(x) rev(R) = F(Rot x + v)`.
//!
//! ```
//! use motion::Pose;
//! use motion::wareham_lasenby::{from_pose, log, to_pose};
//! let s = Pose::<f64>::from_axis_angle_translation(&[0.0, 1.0, 0.0], &1.0, &[1.0, 2.0, 3.0]).unwrap();
//! let b = log(&from_pose(&s).unwrap()).unwrap();        // ℓ(R): a bivector φP + tn
//! let back = to_pose(&b.exp().unwrap());                 // Theorem 3
//! assert!(back.is_equivalent(&s, &1e-14).unwrap());
//! ```

pub mod cga;
pub mod convert;
pub mod generator;
pub mod helix;
pub mod interp;
pub mod log;

pub use convert::{from_pose, to_pose};
pub use generator::{Generator, GeneratorParts};
pub use helix::helix_point;
pub use interp::{WlBivectorLinear, WlLinear, WlMotion, WlQuadratic};
pub use log::log;

use crate::{CurveError, MotionError};

/// Every way a Wareham–Lasenby operation can fail.
///
/// ```
/// use motion::wareham_lasenby::{WlError, cga::{embed_inverse, n}};
/// assert!(matches!(embed_inverse(&n::<f64>()), Err(WlError::NotAPoint { .. })));
/// ```
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum WlError {
    /// A pose operation failed (singular or non-finite pose).
    #[error(transparent)]
    Pose(#[from] MotionError),
    /// Bad key poses or times for an interpolation.
    #[error(transparent)]
    Curve(#[from] CurveError),
    /// A vector with `X·n = 0` (or non-finite) has no point of R^3.
    #[error("{value} is not a finite point (X·n = 0)")]
    NotAPoint {
        /// The vector, printed.
        value: String,
    },
    /// A zero or non-finite rotation axis.
    #[error("the rotation axis {value} is zero or not finite")]
    ZeroAxis {
        /// The axis, printed.
        value: String,
    },
    /// A bivector not of the form `φP + tn` with a Euclidean `P`.
    #[error("{value} is not a generator φP + tn (needs e45 = 0 and e_i4 = e_i5)")]
    NotAGenerator {
        /// The bivector, printed.
        value: String,
    },
    /// Not a unit displacement rotor.
    #[error("{value} is not a unit displacement rotor (R rev(R) = 1, R n rev(R) = n)")]
    NotADisplacementRotor {
        /// The rotor, printed.
        value: String,
    },
    /// Non-finite input or overflow.
    #[error("{op}: {value} is not finite")]
    NotFinite {
        /// The operation.
        op: &'static str,
        /// The input, printed.
        value: String,
    },
}
