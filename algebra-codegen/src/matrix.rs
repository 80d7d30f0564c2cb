//! The matrix form of a fused versor action, for transforming many operands by one versor:
//! the action `x ↦ <rev(S) x S>_X` (or `<S x rev(S)>_X`) is linear in `x`, so its matrix
//! `M(S)` (entries quadratic in `S`'s coefficients) is computed once and applied per operand
//! with only the structurally non-zero entries: for a PGA motor on points 13 multiplications
//! per point instead of the fused kernel's 48.
//!
//! Built by composing the two stages of the fused kernel ([`super::versor::ActionKernel`],
//! after the orientation signs are folded in), so `transform(matrix(S), x)` computes the same
//! polynomial as the fused action, exactly. Emitted for pairs whose matrix has at most
//! [`MAX_TERMS`] quadratic terms (motors and rotors on points, vectors, lines, planes of
//! algebras up to 4 generators and conformal points); larger pairs keep only the fused kernel.

use super::versor::{ActionKernel, Convention};
use crate::ratio::Ratio;
use algebra_core::rational::{Q, ratio};
use num_traits::Zero;
use std::collections::BTreeMap;

/// Pairs whose matrix has more quadratic terms than this get no matrix form.
pub const MAX_TERMS: usize = 512;

/// One action matrix: `entries[j][b]` is `M_jb = Σ c · s[a] · s[a2]` as `(a, a2, c)`, `a <= a2`.
#[derive(Debug, Clone)]
pub struct MatrixKernel {
    /// The convention of the action.
    pub convention: Convention,
    /// Versor type index.
    pub versor: usize,
    /// Operand type index.
    pub operand: usize,
    /// The entries, row `j` (output field), column `b` (input field).
    pub entries: Vec<Vec<Vec<(usize, usize, Ratio)>>>,
}

/// The matrix of a fused action, or `None` when it is too large or a constant overflows.
pub(crate) fn compose(k: &ActionKernel) -> Option<MatrixKernel> {
    let n = k.stage2.len();
    let q = |(num, den): Ratio| ratio(num, den);
    let mut entries = Vec::with_capacity(n);
    let mut total = 0;
    for row in &k.stage2 {
        let mut cols: Vec<BTreeMap<(usize, usize), Q>> = vec![BTreeMap::new(); n];
        for &(t, a2, c2) in row {
            for &(a, b, c1) in &k.stage1[t] {
                let key = (a.min(a2), a.max(a2));
                *cols[b].entry(key).or_insert_with(Q::zero) += q(c1) * q(c2);
            }
        }
        let mut out_row = Vec::with_capacity(n);
        for col in cols {
            let mut terms = Vec::new();
            for ((a, a2), c) in col.into_iter().filter(|(_, c)| !c.is_zero()) {
                terms.push((a, a2, crate::ratio::to_ratio(&c).ok()?));
            }
            total += terms.len();
            out_row.push(terms);
        }
        entries.push(out_row);
    }
    (total <= MAX_TERMS).then_some(MatrixKernel {
        convention: k.convention,
        versor: k.versor,
        operand: k.operand,
        entries,
    })
}

/// The matrices of every fused action small enough.
pub(crate) fn plan_matrices(actions: &[ActionKernel]) -> Vec<MatrixKernel> {
    actions.iter().filter_map(compose).collect()
}
