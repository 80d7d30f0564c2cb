//! # algebra-core
//!
//! The exact engine of GAM: Clifford algebras over **any** symmetric bilinear form (diagonal,
//! non-diagonal, degenerate), in the *blade* basis (outer products of generators) and in the
//! *product* basis (geometric products of generators, the basis of Cross, Cripps and
//! Mullineux 2022), with exact product tables, layered scalar traits, and a runtime
//! [`Multivector`] that serves as the reference for generated kernels.
//!
//! ```
//! use algebra_core::{Algebra, Basis, Multivector, rational::Q};
//! let alg = Algebra::builtin("cga-null").unwrap();
//! let e0 = Multivector::<Q>::basis_element(&alg, Basis::Product, "e0").unwrap();
//! let einf = Multivector::<Q>::basis_element(&alg, Basis::Product, "einf").unwrap();
//! // einf e0 = -2 - e0inf in the product basis (e0 . einf = -1).
//! assert_eq!((&einf * &e0).to_string(), "-2 - e0inf");
//! ```

pub mod algebra;
pub mod basis;
pub mod closed_form;
mod closed_form_inv;
#[cfg(feature = "rug")]
pub mod ideal;
pub mod kernels;
pub mod linalg;
pub mod metric;
pub mod multivector;
pub mod ops;
#[cfg(feature = "rug")]
pub mod poly;
pub mod rational;
pub mod scalar;
pub mod symbol;
pub mod tables;
#[cfg(feature = "test-support")]
pub mod test_support;

pub use algebra::Algebra;
pub use basis::{Basis, BasisError};
pub use metric::{Metric, MetricError};
pub use multivector::F64_GENERAL_BOUND;
pub use multivector::{Multivector, MvError};
#[cfg(feature = "rug")]
pub use poly::Poly;
pub use scalar::{Field, Jet, Real, Ring};
#[cfg(feature = "rug")]
pub use scalar::{MpFloat, MpRational, PrecisionGuard, default_precision, set_default_precision};
pub use symbol::Symbolic;
pub use tables::{Product, Tables, Unary};

/// The source text of the product traits, the scalar traits, the solver, the printing helper, the
/// table-driven kernels' loops and the closed-form factors, which
/// `gam codegen --standalone` inlines (reduced) into its dependency-free files, so that those
/// files and this crate share one definition. Not a stable API.
#[doc(hidden)]
pub mod sources {
    /// `ops.rs`.
    pub const OPS: &str = include_str!("ops.rs");
    /// `scalar/mod.rs`.
    pub const SCALAR: &str = include_str!("scalar/mod.rs");
    /// `linalg.rs`.
    pub const LINALG: &str = include_str!("linalg.rs");
    /// `multivector/display.rs`.
    pub const DISPLAY: &str = include_str!("multivector/display.rs");
    /// `closed_form.rs`.
    pub const CLOSED_FORM: &str = include_str!("closed_form.rs");
    /// `closed_form_inv.rs`.
    pub const CLOSED_FORM_INV: &str = include_str!("closed_form_inv.rs");
    /// `kernels.rs`.
    pub const KERNELS: &str = include_str!("kernels.rs");
}
