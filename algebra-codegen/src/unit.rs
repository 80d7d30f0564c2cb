//! The versor action specialised to *unit* versors (`S rev(S) = 1`): the one unit-action
//! family, `UnitAction::{sandwich_unit, apply_unit}`, for every fused (versor, operand) pair.
//!
//! For a unit versor `x S rev(S) = x`, so
//!
//! - `S x rev(S) = x + (S x - x S) rev(S)` (`apply_unit`), and
//! - `rev(S) x S = x + (rev(S) x - x rev(S)) S` (`sandwich_unit`).
//!
//! The commutator `S x - x S` drops every term of `S` that commutes with `x` (the scalar
//! always, the pseudoscalar of an odd-dimensional algebra, ...), and output components whose
//! correction expands to the zero polynomial are copied from `x` (the weight of a PGA point).
//! This is the structural form of Rodrigues' `v + 2 w (q × v) + 2 q × (q × v)`: for the pose
//! on a PGA point it needs 22 multiplications instead of the general kernel's 48. Both forms
//! are identities over any ring once `S rev(S) = 1` holds exactly; for a non-unit versor the
//! result is not the action (use `apply`/`sandwich`).
//!
//! When the versor type is declared `where unit`, the pair also has a kernel reduced modulo
//! `rev(S) S = 1` ([`crate::constraint`]); each convention then takes whichever of the two term
//! lists needs fewer multiplications (the commutator form on a tie), and the impl's rustdoc
//! states what the reduction proved: whether the components of the full product outside the
//! operand type vanish on unit versors (then the result *is* the action, e.g. a unit
//! `cga_null::Motor` on a `Vector`) or not (then it is the projection onto the operand type).
//! Those impls are emitted by [`crate::constraint::methods`], which reads the reduced kernels;
//! every other pair's by the Rust emitter's `emit::unit` (this module is the plan: the kernels).

use super::versor::{ActionKernel, Convention, action_kernel};
use super::{CodegenError, ModuleSpec};
use crate::ratio::Ratio;
use algebra_core::rational::Q;
use num_traits::{One, Zero};
use std::collections::BTreeMap;

/// One unit-versor action kernel: `out_j = x_j + scale · Σ_(k, a, c) c · t_k · s_a`, with
/// `t_k = Σ_(a, b, c) c · s_a · x_b` (the commutator divided by `scale`).
#[derive(Debug, Clone)]
pub struct UnitKernel {
    /// The two stages (stage 1 the scaled commutator; an empty stage-2 row means `out_j = x_j`).
    pub kernel: ActionKernel,
    /// The common factor taken out of stage 1 (2 for rotors and motors).
    pub scale: Ratio,
}

impl UnitKernel {
    /// Multiplications and additions, counted as [`ActionKernel::counts`] does plus one
    /// addition per corrected output and the scale (an addition when it is 2).
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis};
    /// use algebra_codegen::{ModuleSpec, unit::plan_unit_actions, versor::{Convention, plan_actions}};
    /// let alg = Algebra::builtin("pga3").unwrap();
    /// let types = ModuleSpec::parse_types("Motor=even;Point=grade3", &alg).unwrap();
    /// let spec = ModuleSpec::new("pga", alg.metric().clone(), Basis::Blade, types).unwrap();
    /// let k = plan_unit_actions(&spec, &plan_actions(&spec, usize::MAX).unwrap()).unwrap();
    /// let k = k.iter().find(|k| (k.kernel.versor, k.kernel.operand, k.kernel.convention) == (0, 1, Convention::Apply)).unwrap();
    /// // the general fused kernel needs 48 multiplications; the point's weight is copied
    /// assert_eq!(k.counts(), (22, 21));
    /// assert!(k.kernel.stage2[3].is_empty());
    /// ```
    pub fn counts(&self) -> (usize, usize) {
        let (m, a) = self.kernel.counts();
        let corrected = self.kernel.stage2.iter().filter(|r| !r.is_empty()).count();
        match self.scale {
            (1, 1) => (m, a + corrected),
            (2, 1) => (m, a + 2 * corrected),
            _ => (m + corrected, a + corrected),
        }
    }
}

/// The unit-versor kernels of every fused (versor type, operand type) pair of the module, in
/// both conventions: the pairs of `actions` (the module's fused kernels,
/// [`super::versor::plan_actions`]; pairs that [`super::versor::keeps_operand`] refuses have
/// neither kind).
pub fn plan_unit_actions(spec: &ModuleSpec, actions: &[ActionKernel]) -> Result<Vec<UnitKernel>, CodegenError> {
    let mut out = Vec::new();
    for k in actions.iter().filter(|k| k.convention == Convention::Sandwich) {
        for convention in [Convention::Sandwich, Convention::Apply] {
            out.push(unit_kernel(spec, convention, k.versor, k.operand)?);
        }
    }
    Ok(out)
}

fn q(c: Ratio) -> Q {
    Q::new(c.0.into(), c.1.into())
}

fn gcd(a: i64, b: i64) -> i64 {
    if b == 0 { a.abs() } else { gcd(b, a % b) }
}

pub(crate) fn unit_kernel(
    spec: &ModuleSpec,
    convention: Convention,
    v: usize,
    x: usize,
) -> Result<UnitKernel, CodegenError> {
    let mut k = action_kernel(spec, convention, v, x, true)?;
    // an output whose correction expands to zero is x's own component
    for row in &mut k.stage2 {
        let mut poly: BTreeMap<(usize, usize, usize), Q> = BTreeMap::new();
        for &(t, a, c) in row.iter() {
            for &(a1, b, c1) in &k.stage1[t] {
                *poly.entry((a.min(a1), a.max(a1), b)).or_insert_with(Q::zero) += q(c) * q(c1);
            }
        }
        if poly.values().all(Zero::is_zero) {
            row.clear();
        }
    }
    // the common factor of stage 1: gcd of the numerators over the lcm of the denominators
    let all = k.stage1.iter().flatten();
    let (num, den) = all.fold((0, 1), |(n, d), &(_, _, (cn, cd))| (gcd(n, cn), d / gcd(d, cd) * cd));
    let scale = if num == 0 { (1, 1) } else { (num, den) };
    let factor = Q::one() / q(scale);
    for row in &mut k.stage1 {
        for term in row.iter_mut() {
            let c = q(term.2) * &factor;
            term.2 = crate::ratio::to_ratio(&c)?;
        }
    }
    // the fields of renamed blades (`e31`, `e021`) hold the coefficient in their orientation
    let signs: Vec<Vec<i64>> = spec.types.iter().map(crate::TypeSpec::signs).collect();
    super::orient::fold_action(&mut k, &signs);
    Ok(UnitKernel { kernel: k, scale })
}
