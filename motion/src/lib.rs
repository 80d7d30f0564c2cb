//! Rigid-body motions in the conformal geometric algebra of Cross, Cripps and Mullineux (2022).
//!
//! This crate is a placeholder until the motion-layer issue: it re-exports the algebra engine
//! it will build on.
pub use algebra_core;
