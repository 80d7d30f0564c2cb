//! # gam-ga: GAM as a library, in one dependency
//!
//! The crate a user adds to get GAM's generated geometric-algebra kernels:
//!
//! ```toml
//! [dependencies]
//! gam-ga = { git = "...", package = "gam-ga" }            # macro + traits + scalars
//! # gam-ga = { ..., features = ["motion"] }               # + poses, exp/log, Bezier motions
//! # gam-ga = { ..., features = ["mpfr"] }                 # + MPFR/GMP scalars (needs m4)
//! ```
//!
//! - [`algebra!`] (feature `macros`, on by default): declares an algebra and the types to
//!   generate; the generated code reaches the engine through this crate, so no other GAM
//!   crate is needed.
//! - the product traits ([`GeometricProduct`], [`OuterProduct`], ...), the scalar traits
//!   ([`Ring`], [`Field`], [`Real`]), the scalars ([`Jet`], [`rational::Q`]; `f32`/`f64`
//!   implement the traits), the runtime [`Multivector`] over an [`Algebra`] (the reference for
//!   generated kernels, and exp/log).
//! - features: `mpfr` (GMP/MPFR scalars
#![cfg_attr(feature = "mpfr", doc = "  [`MpFloat`], [`MpRational`], [`Poly`];")]
#![cfg_attr(not(feature = "mpfr"), doc = "  `MpFloat`, `MpRational`, `Poly`;")]
//!   off by default because it builds GMP/MPFR from source), `algebras` (the predefined modules
#![cfg_attr(feature = "algebras", doc = "  [`algebras::g3`], [`algebras::pga3`], ...),")]
#![cfg_attr(not(feature = "algebras"), doc = "  `algebras::g3`, `algebras::pga3`, ...),")]
#![cfg_attr(feature = "motion", doc = "  `motion` (the [`motion`] crate), `nalgebra`, `glam`.")]
#![cfg_attr(not(feature = "motion"), doc = "  `motion` (the `motion` crate), `nalgebra`, `glam`.")]
//! - proofs (feature `mpfr`): `gam_ga::ideal` (Gröbner bases, `ideal::decide` under
//!   hypotheses) with the generated types over `Poly` (`X::<Poly>::symbolic("m")`).
//!
//! The package is called `gam-ga`, not `gam`: `gam` is the command-line tool's package
//! (`cargo run -p gam -- ...` is the documented way to run it) and stays so.
//!
//! ```
//! gam_ga::algebra! {
//!     /// 2D projective geometric algebra R(2,0,1).
//!     pub mod pga2 {
//!         generators { e0, e1, e2 }
//!         metric { (e1, e1) = 1, (e2, e2) = 1 }
//!         types {
//!             Point = grade 2;
//!             Motor = even;
//!         }
//!     }
//! }
//! use gam_ga::GeometricProduct;
//! // T = 1 + e01/2 (blade basis); by hand, rev(T) e12 T = e12 - e02: the origin e12 moves to
//! // x = 1 in the convention P = e12 + x e20 + y e01 (e20 = -e02).
//! let t = pga2::Motor::<f32>::new(1.0, 0.5, 0.0, 0.0);
//! let origin = pga2::Point::<f32>::new(0.0, 0.0, 1.0);
//! let moved: pga2::Point<f32> = t.reverse().gp(&origin).gp(&t).project_to_point();
//! assert_eq!(moved.to_string(), "-e02 + e12");
//! ```

pub use algebra_core::Symbolic;
pub use algebra_core::ops::{
    ActionMatrix, AnticommutatorProduct, CommutatorProduct, GeometricProduct, GeometricProductInto, LeftContraction,
    OuterProduct, RegressiveProduct, RightContraction, ScalarProduct, UnitAction,
};
pub use algebra_core::{
    Algebra, Basis, BasisError, Field, Jet, Metric, MetricError, Multivector, MvError, Product, Real, Ring, Unary, ops,
    rational,
};
#[cfg(feature = "mpfr")]
pub use algebra_core::{MpFloat, MpRational, Poly, PrecisionGuard, default_precision, set_default_precision};

/// Proofs: polynomial ideals over the rationals (Gröbner bases, ideal membership) and
/// [`ideal::decide`], which decides a polynomial claim under hypotheses (equations and
/// non-vanishing conditions). Feature `mpfr` (the polynomials are [`Poly`], over GMP).
/// Build the claim with the generated types over `Poly` (`X::<Poly>::symbolic("m")`, the
/// front door's [`Symbolic`]): e.g. a unit rotor preserves the length of a vector.
///
/// ```
/// gam_ga::algebra! {
///     pub mod g3 {
///         generators { e1, e2, e3 }
///         metric { (e1, e1) = 1, (e2, e2) = 1, (e3, e3) = 1 }
///         types { Vector = grade 1; Rotor = even; }
///     }
/// }
/// use gam_ga::ideal::{Budget, Hypotheses, decide};
/// use gam_ga::{Poly, Ring};
/// let (r, x) = (g3::Rotor::<Poly>::symbolic("r"), g3::Vector::<Poly>::symbolic("x"));
/// let claim = r.apply(&x).norm_squared() - x.norm_squared(); // |R x rev(R)|² - |x|²
/// let unit = Hypotheses { equations: vec![r.norm_squared() - Poly::one()], nonzero: vec![] };
/// assert!(decide(&[claim.clone()], &unit, &Budget::default())?.holds);
/// assert!(!decide(&[claim], &Hypotheses::default(), &Budget::default())?.holds); // needs |R| = 1
/// # Ok::<(), gam_ga::ideal::IdealError>(())
/// ```
#[cfg(feature = "mpfr")]
pub use algebra_core::ideal;

/// The predefined generated algebras (feature `algebras`).
#[cfg(feature = "algebras")]
pub use gam_algebras as algebras;

/// Rigid-body motions (feature `motion`).
#[cfg(feature = "motion")]
pub use motion;

/// The README's Rust examples, compiled and run as doc tests with the features they use:
/// `cargo test -p gam-ga --doc --features nalgebra,mpfr`.
#[cfg(all(doctest, feature = "nalgebra", feature = "mpfr"))]
#[doc = include_str!("../../README.md")]
pub struct ReadmeExamples;

/// The engine that generated code refers to (`$crate::__engine::...`); not a stable API.
#[doc(hidden)]
pub use algebra_core as __engine;

/// The proc-macro behind [`algebra!`]; not a stable API.
#[cfg(feature = "macros")]
#[doc(hidden)]
pub use algebra_macros as __macros;

/// Declares an algebra and generates its types and kernels, reaching the engine through
/// `gam_ga` (so a crate depending only on `gam-ga` can use it). The DSL is the one of
/// `algebra_macros::algebra!`, documented in docs/codegen.md:
/// `generators { ... }`, `metric { (a, b) = v, ... }` or `metric builtin "name";`,
/// `basis blade|product;`, `types { Name = selector; ... }`.
///
/// ```
/// gam_ga::algebra! {
///     /// Spacetime algebra (+, -, -, -).
///     pub mod sta {
///         generators { e0, e1, e2, e3 }
///         metric { (e0, e0) = 1, (e1, e1) = -1, (e2, e2) = -1, (e3, e3) = -1 }
///         types { Vector = grade 1; Bivector = grade 2; Rotor = even; }
///     }
/// }
/// let g0 = sta::Vector::<f64>::new(1.0, 0.0, 0.0, 0.0);
/// assert_eq!(g0.norm_squared(), 1.0);
/// ```
#[cfg(feature = "macros")]
#[macro_export]
macro_rules! algebra {
    ($($decl:tt)*) => {
        $crate::__macros::algebra! { crate $crate::__engine; $($decl)* }
    };
}
