//! # motion
//!
//! Rigid-body motions in the conformal geometric algebra of Cross, Cripps and Mullineux
//! (2022), generic over the scalar (`T: algebra_core::Real`: `f64`, num-dual numbers,
//! [`algebra_core::Jet`], `MpFloat` (feature `rug` of algebra-core); the parts that need no square root also
//! over exact rationals).
//!
//! A *pose* is an element `S` of G_{123inf}^+: [`Pose`], generated in this crate
//! ([`pose::elements`]) together with [`Bivector`] (`ν`, `log S`) and [`Pseudoscalar`] (`α + βω`);
//! it acts on R^3 by `F_S = P f_S E`, `f_S(x) = rev(S) x S`, so `F_{UV} = F_V F_U`
//! (Lemma 2.3: `U * V` applies `U` first; [`Pose::then`] and [`Pose::after`] say it in words). Conventions (paper and `docs`): `R = cos(φ/2) +
//! sin(φ/2) (a e123)` for a unit axis `a`; `T = 1 + ½ v einf`; `S = R T` rotates, then
//! translates; `ω = e123inf`; `|S| = √(rev(S) S)` is a pseudoscalar `α + βω`. Non-unit poses
//! are first-class.
//!
//! | module | contents |
//! |---|---|
//! | [`pose`] | [`Pose`], [`Bivector`], [`Pseudoscalar`] (generated), [`Even`]; constructors, norm, unitize, inverse, equivalence (Lemmas 2.4-2.6, Thm 2.8) |
//! | [`vec3`] | [`Vec3`]: dot, cross, `a ↦ a e123`, `c ↦ c einf`; `ν = Ω e123 + u einf` both ways |
//! | [`action`] | `F_S` on points and directions (eqs. 6-9) |
//! | [`unit_pose`] | [`UnitPose`]: a pose normalised once, whose action and slerp skip the normalisation |
//! | [`matrix`] | 4x4 homogeneous matrices both ways |
//! | `ops` (private) | [`Pose::then`], [`Pose::after`], `From` with gam-algebras' [`Motor`] |
//! | [`pseudoscalar`] | `a + bω`: inverse, square root, exp, ln, pow (Lemma 2.4) |
//! | [`exp_log`] | closed-form exp and log ("dual angle") |
//! | [`branch_free`] | exp, log, power, slerp with `select` instead of branches, over SIMD lanes (`LaneReal`) |
//! | [`interpolation`] | power, slerp (eq. 15), additive interpolation (eq. 17) |
//! | [`bezier`] | the [`Motion`] and [`MapScalar`] traits, [`Bezier`] motions: additive (eq. 18) and multiplicative (Fig. 2) |
//! | [`blend`] | [`Blend`]: [`Additive`] (eq. 17) or [`Multiplicative`] (eq. 15) as a type parameter, with the join rules (eqs. 20-23) |
//! | [`bspline`] | [`BSpline`] motions with knots (de Boor), either blend |
//! | [`piecewise`] | motions over parameter intervals: [`Reparametrized`], [`Piecewise`], [`AnyMotion`] |
//! | [`velocity`] | Ψ (eq. 11), γ, ν, Ω and u (Thm 3.2), point velocities (eq. 14), Cor. 3.3, second derivatives, all by dual numbers |
//! | [`joins`] | end conditions, `ν` and `Ψ = λ(ν + γ)`, control poses for C1/G1 joins (eqs. 22-23), [`Continuity`] check |
//! | [`hermite`] | Hermite interpolation through precision poses with velocities (Sec. 5.3) |
//! | [`error`] | [`MotionError`] (pose operations), [`CurveError`] (motion curves; also re-exported from [`bezier`]) |
//! | [`spec`] | the `gam hermite` spec: format, checks ([`spec::SpecError`]), segment |
//! | `schema` (feature `serde`) | the JSON format of pose objects and of the `gam interpolate` spec, with every check and message (`schema::SchemaError`) |
//! | [`trajectory`] | [`trajectory::Trajectory`]: a C1 motion through key poses at times in one call, velocity estimate, sampler |
//! | [`jacobian`] | [`jacobian::JetN`] (multi-directional duals), derivatives of a sampled body point and twist w.r.t. every key pose and time |
//! | [`method`] | the methods of `gam interpolate` by name ([`method::Method`]) |
//! | [`repr`] | the other papers' pose representations: quaternion, Jüttler's dual quaternions, Angelidis' hexanions, screw, signs |
//! | [`batch`] | [`batch::Points`], [`batch::Poses`]: many points and poses at once over SIMD lanes ([`batch::Lanes`]) and cores |
//! | [`paper`] | the paper's worked examples (Secs. 4, 5.1, 5.2, 5.3 Jaklič), once |
//! | [`wareham_lasenby`] | Wareham–Lasenby in `cga`: exp (Thm 3), log (Thm 9), rotor ↔ pose, helix (Sec. 4.1), interpolation (Sec. 3) |
//!
//! ```
//! use motion::Pose;
//! let a = Pose::<f64>::identity();
//! let b = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &std::f64::consts::FRAC_PI_2, &[1.0, 0.0, 0.0]).unwrap();
//! let mid = Pose::slerp(&a, &b, &0.5).unwrap();
//! let p = mid.transform_point(&[0.0, 0.0, 0.0]).unwrap();
//! assert!(p[2].abs() < 1e-15);
//! ```

pub mod action;
mod any_segment;
pub mod batch;
pub mod bezier;
pub mod blend;
pub mod branch_free;
pub mod bspline;
mod de_casteljau;
pub mod error;
pub mod exp_log;
#[cfg(feature = "glam")]
pub mod glam_conv;
pub mod hermite;
pub mod interpolation;
pub mod jacobian;
pub mod joins;
pub mod juttler;
pub mod matrix;
pub mod method;
#[cfg(feature = "nalgebra")]
pub mod nalgebra_conv;
#[cfg(feature = "nalgebra")]
pub mod nalgebra_generic;
mod names;
mod ops;
pub mod paper;
pub mod piecewise;
pub mod pose;
pub mod pseudoscalar;
pub mod quaternion;
pub mod repr;
mod scaled;
#[cfg(feature = "serde")]
pub mod schema;
mod series;
pub mod spec;
mod stable_slerp;
pub mod trajectory;
pub mod unit_pose;
pub mod vec3;
pub mod velocity;
pub mod wareham_lasenby;

pub use algebra_core;
pub use bezier::{AdditiveBezier, Bezier, CurveError, MapScalar, Motion, MultiplicativeBezier};
pub use blend::{Additive, Blend, Multiplicative};
pub use bspline::{AdditiveBSpline, BSpline, MultiplicativeBSpline};
pub use error::MotionError;
pub use gam_algebras::g123inf::Motor;
pub use hermite::{AnyHermiteSegment, HermiteSegment, HermiteShapes};
pub use joins::{Continuity, EndCondition, JoinCheck, JoinError, SegmentKind, Shape};
pub use matrix::Matrix4;
pub use piecewise::{AnyMotion, Piecewise, Reparametrized};
pub use pose::{Bivector, Even, Pose, Pseudoscalar};
pub use quaternion::Quaternion;
pub use unit_pose::UnitPose;
pub use vec3::Vec3;
pub use velocity::{Twist, velocity_bivector, velocity_indicatrix};
