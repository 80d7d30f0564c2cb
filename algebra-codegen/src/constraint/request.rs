//! Which constrained kernels a module's declared constraints call for ([`Request`]), their
//! reduced kernels (precomputed or computed) and their method names: the plan side of the
//! constrained methods that [`super::methods`] emits.

use super::{ConstrainedKernel, ConstraintError, ConstraintKind, KernelOp, Request, smallest_type, table};
use crate::ModuleSpec;
use crate::plan::Plan;
use crate::versor::Convention;

/// The constrained kernels a module's declared constraints call for: the unit actions of a
/// `where unit` versor type on every operand it has a fused kernel for (the plan's actions;
/// [`crate::versor::keeps_operand`]), and the squares of `where null` and `where simple` types.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, plan::Plan};
/// use algebra_codegen::constraint::{KernelOp, Request, requests};
/// let alg = Algebra::builtin("pga3").unwrap();
/// let types = ModuleSpec::parse_types("Motor=even where unit;Line=grade2 where simple;Full=all", &alg).unwrap();
/// let plan = Plan::new(ModuleSpec::new("pga3", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
/// let r = requests(&plan);
/// assert!(r.contains(&Request { op: KernelOp::Sandwich, left: 0, right: 1 }));
/// assert!(r.contains(&Request { op: KernelOp::Square, left: 1, right: 1 }));
/// assert_eq!(r.len(), 5); // sandwich and apply on Motor and Line, the square of Line
/// ```
pub fn requests(plan: &Plan) -> Vec<Request> {
    let mut out = Vec::new();
    for (v, t) in plan.spec.types.iter().enumerate() {
        match t.constraint {
            Some(ConstraintKind::Unit) => {
                // the fused pairs of `v`, one per operand (each is planned in both conventions)
                for k in plan.actions.iter().filter(|k| k.versor == v && k.convention == Convention::Sandwich) {
                    for op in [KernelOp::Sandwich, KernelOp::Apply] {
                        out.push(Request { op, left: v, right: k.operand });
                    }
                }
            }
            Some(ConstraintKind::Null | ConstraintKind::Simple) if v != plan.full => {
                out.push(Request { op: KernelOp::Square, left: v, right: v });
            }
            _ => {}
        }
    }
    out
}

/// The reduced kernel of a request: from the precomputed [`table`], else computed (with the
/// `constraints` feature), else [`ConstraintError::NotPrecomputed`].
///
/// # Errors
/// As `constrained_action` (feature `constraints`), plus the two table errors.
pub fn kernel(spec: &ModuleSpec, r: Request) -> Result<ConstrainedKernel, ConstraintError> {
    match table::lookup(table::PRECOMPUTED, &table::key(spec, r))? {
        Some(mut k) => {
            finish(spec, r, &mut k);
            Ok(k)
        }
        None => compute(spec, r),
    }
}

/// Fills in a table kernel's spec-dependent fields as the reduction does.
fn finish(spec: &ModuleSpec, r: Request, k: &mut ConstrainedKernel) {
    (k.left, k.right) = (r.left, r.right);
    let mut tys = vec![r.left, r.right];
    tys.sort_unstable();
    tys.dedup();
    k.relies_on = tys
        .iter()
        .filter_map(|&t| spec.types[t].constraint.map(|c| format!("{}: {}", spec.types[t].name, c)))
        .collect();
    let kept: Vec<u32> = k.outputs.iter().map(|o| o.0).collect();
    k.output_type = smallest_type(spec, &kept);
    k.full.output_type = smallest_type(spec, &k.full.masks);
}

/// Computes a request's kernel with the Gröbner reduction (every declared constraint used).
///
/// # Errors
/// As [`super::constrained_action`].
#[cfg(feature = "constraints")]
pub fn compute(spec: &ModuleSpec, r: Request) -> Result<ConstrainedKernel, ConstraintError> {
    use crate::versor::Convention;
    let constraints: Vec<super::Constraint> = spec
        .types
        .iter()
        .enumerate()
        .filter_map(|(ty, t)| t.constraint.map(|kind| super::Constraint { ty, kind }))
        .collect();
    match r.op {
        KernelOp::Sandwich => super::constrained_action(spec, Convention::Sandwich, r.left, r.right, &constraints),
        KernelOp::Apply => super::constrained_action(spec, Convention::Apply, r.left, r.right, &constraints),
        KernelOp::Square => super::reduce::constrained_square(spec, r.left, &constraints),
    }
}

/// Without the `constraints` feature a kernel missing from the table is an error naming it.
///
/// # Errors
/// Always [`ConstraintError::NotPrecomputed`].
#[cfg(not(feature = "constraints"))]
pub fn compute(spec: &ModuleSpec, r: Request) -> Result<ConstrainedKernel, ConstraintError> {
    let (l, x) = (&spec.types[r.left].name, &spec.types[r.right].name);
    Err(ConstraintError::NotPrecomputed(format!("`{}` of {l} on {x} (key `{}`)", r.op.name(), table::key(spec, r))))
}

/// Whether the constraint changes the kernel (and a declared type holds its output).
pub(crate) fn worth_a_method(k: &ConstrainedKernel) -> bool {
    !k.outputs.is_empty() && k.output_type.is_some() && (k.stats().mul < k.full.stats().mul || !k.vanishing.is_empty())
}

/// The method name of a request (`sandwich_unit` and `apply_unit` are `UnitAction`'s).
pub fn method_name(spec: &ModuleSpec, r: Request) -> String {
    match r.op {
        KernelOp::Sandwich => "sandwich_unit".to_string(),
        KernelOp::Apply => "apply_unit".to_string(),
        KernelOp::Square => {
            format!("square_{}", spec.types[r.left].constraint.map_or("constrained", |c| c.keyword()))
        }
    }
}
