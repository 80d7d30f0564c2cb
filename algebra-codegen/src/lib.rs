//! The code generator behind the `algebra!` macro and `gam codegen`: from a [`ModuleSpec`]
//! (an algebra, a basis and named types, each a set of basis elements) to a Rust module of
//! types generic over the scalar with fully unrolled, sparse kernels, or the same kernels in C,
//! WGSL or GLSL.
//!
//! The pipeline is visible in three steps:
//! 1. [`spec::ModuleSpec`]: what the user declared (validated);
//! 2. [`plan::Plan`]: the structural analysis — for every pair of types and every product,
//!    which output coefficients receive which `(lhs, rhs, rational)` terms, and which declared
//!    type is the smallest holding the result (decided here, at expansion time). The plan's
//!    parts are language-free: [`versor`] (fused actions), [`unit`](mod@unit) (unit-versor
//!    actions), [`matrix`] (action matrices), [`closed`] and [`closed_inv`] (closed-form
//!    detection), [`constraint`] (kernels reduced modulo constraints), [`orient`], [`size`],
//!    `sums` (the summation shapes every emitter uses) and [`naming`];
//! 3. an emitter, which depends on the plan and on which nothing depends: [`emit`] (the Rust
//!    token stream: structs, constructors, Display, conversions, operator and trait impls,
//!    unary operations, actions, closed forms; [`standalone`] and [`paths`] rewrite it) or
//!    [`lang`] (C, WGSL, GLSL, one file per language).
//!
//! Kernels contain only structurally non-zero terms, fold rational constants into
//! `T::from_ratio`, never compare values, and report their operation counts
//! ([`plan::KernelStats`]).
//!
//! The `toml` feature adds
#![cfg_attr(feature = "toml", doc = "[`metric_toml`]:")]
#![cfg_attr(not(feature = "toml"), doc = "`metric_toml`:")]
//! algebra descriptions read from TOML files (the
//! CLI's `--algebra file.toml`). This crate is a build-time dependency only: kernels (from the
//! macro or vendored) need `algebra-core` at run time, never this crate.
//!
//! ```
//! use algebra_core::{Algebra, Basis};
//! use algebra_codegen::{ModuleSpec, emit, plan::Plan};
//! let alg = Algebra::builtin("pga3").unwrap();
//! let types = ModuleSpec::parse_types("Motor=even;Point=grade3", &alg).unwrap();
//! let plan = Plan::new(ModuleSpec::new("pga", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
//! assert!(emit::module(&plan).to_string().contains("struct Motor"));
//! ```

pub mod closed;
pub mod closed_inv;
pub mod constraint;
pub mod emit;
pub mod fallback;
pub mod lang;
pub mod matrix;
#[cfg(feature = "toml")]
pub mod metric_toml;
pub mod named;
pub mod naming;
pub mod orient;
pub mod paths;
pub mod plan;
pub mod product_order;
mod ratio;
pub mod size;
pub mod spec;
pub mod standalone;
pub(crate) mod sums;
pub mod unit;
pub mod versor;

pub use spec::{CodegenError, ModuleSpec, TypeSpec};

/// FNV-1a of `text`: the key of the measured-order tables ([`versor::fingerprint`],
/// [`product_order::fingerprint`]), stable across builds and platforms.
pub(crate) fn fnv1a(text: &str) -> u64 {
    text.bytes().fold(0xcbf2_9ce4_8422_2325_u64, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3))
}
