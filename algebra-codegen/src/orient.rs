//! Orientation-aware basis names: a type may list a basis blade under a reordering of its
//! generators (`e20`, `e31`, `e021` in PGA), meaning the blade in that orientation
//! (`e20 = e2 ∧ e0 = -e02`). The field is named as written and holds the coefficient in that
//! orientation; the sign is folded into every kernel's constants here, after the plan is
//! built on the canonical basis, so generated code never multiplies by it at run time.
//!
//! Only the blade basis accepts reordered names: in the product basis `e2 e0` is not
//! `-e0 e2` unless the two generators are orthogonal.
//!
//! ```
//! use algebra_core::{Algebra, Basis};
//! use algebra_codegen::{CodegenError, ModuleSpec, plan::Plan};
//! let alg = Algebra::builtin("pga3").unwrap();
//! let types = ModuleSpec::parse_types("Line=e01,e02,e03,e12,e31,e23", &alg).unwrap();
//! assert_eq!(types[0].renamed[&0b1010], ("e31".to_string(), -1));
//! let plan = Plan::new(ModuleSpec::new("pga", alg.metric().clone(), Basis::Blade, types.clone()).unwrap()).unwrap();
//! assert!(algebra_codegen::emit::module(&plan).to_string().contains("pub e31 : T"));
//! assert!(matches!(
//!     ModuleSpec::new("pga", alg.metric().clone(), Basis::Product, types),
//!     Err(CodegenError::OrientedInProductBasis { .. })
//! ));
//! ```

use crate::ratio::Ratio;
use algebra_core::algebra::Algebra;

/// The blade and orientation of a name: `Some((mask, sign))` when `name` is `e` followed by
/// distinct generator labels in any order (`sign` is the parity of the reordering from the
/// canonical, ascending order), `None` otherwise.
///
/// ```
/// use algebra_core::Algebra;
/// use algebra_codegen::orient::oriented_mask;
/// let alg = Algebra::builtin("pga3").unwrap();
/// assert_eq!(oriented_mask(&alg, "e02"), Some((0b0101, 1)));
/// assert_eq!(oriented_mask(&alg, "e20"), Some((0b0101, -1)));
/// assert_eq!(oriented_mask(&alg, "e021"), Some((0b0111, -1)));
/// assert_eq!(oriented_mask(&alg, "e22"), None);
/// let alg = Algebra::builtin("g123inf").unwrap();
/// assert_eq!(oriented_mask(&alg, "einf1"), Some((0b1001, -1)));
/// ```
pub fn oriented_mask(algebra: &Algebra, name: &str) -> Option<(u32, i64)> {
    let labels = algebra.metric().labels();
    let rest = name.strip_prefix('e')?;
    if rest.is_empty() {
        return None;
    }
    // every way of reading `rest` as labels; the first without repeats wins
    fn parse(rest: &str, labels: &[String], seq: &mut Vec<usize>) -> Option<Vec<usize>> {
        if rest.is_empty() {
            return Some(seq.clone());
        }
        for (i, l) in labels.iter().enumerate() {
            if !l.is_empty() && rest.starts_with(l.as_str()) && !seq.contains(&i) {
                seq.push(i);
                if let Some(found) = parse(&rest[l.len()..], labels, seq) {
                    return Some(found);
                }
                seq.pop();
            }
        }
        None
    }
    let seq = parse(rest, labels, &mut Vec::new())?;
    let inversions =
        (0..seq.len()).flat_map(|i| (i + 1..seq.len()).map(move |j| (i, j))).filter(|&(i, j)| seq[i] > seq[j]);
    let sign = if inversions.count() % 2 == 0 { 1 } else { -1 };
    Some((seq.iter().fold(0, |m, &i| m | 1 << i), sign))
}

pub(crate) fn times((n, d): Ratio, s: i64) -> Ratio {
    (n * s, d)
}

/// Folds the field signs into one two-stage action kernel (the fused actions of the plan and
/// the unit-versor kernels of [`crate::unit`]): stage 1 sums `c · s[a] · x[b]` into canonical
/// intermediates, stage 2 sums `c · t[k] · s[a]` into the operand's fields.
pub(crate) fn fold_action(k: &mut crate::versor::ActionKernel, signs: &[Vec<i64>]) {
    for (a, b, c) in k.stage1.iter_mut().flatten() {
        *c = times(*c, signs[k.versor][*a] * signs[k.operand][*b]);
    }
    for (o, terms) in k.stage2.iter_mut().enumerate() {
        for (_, a, c) in terms {
            *c = times(*c, signs[k.versor][*a] * signs[k.operand][o]);
        }
    }
}
