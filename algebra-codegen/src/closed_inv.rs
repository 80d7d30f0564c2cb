//! The third closed-form family: the *invariant decomposition* (Roelfs & De Keninck, "Graded
//! symmetry groups: plane and simple", 2021) for 4D and 5D algebras, detected from the exact
//! tables (never from names). A declared bivector type `B` and even type `M = 1 + B + W`
//! qualify when, identically in `B`'s coefficients,
//!
//! - `B² = s + Q` lies in the scalar plus the span of `W` (`Q` the "4-vector part");
//! - `Q² = q4` is a scalar, for every `Q` in `W`'s span;
//! - `B Q` lies in `B` (checked as a cubic polynomial: its other components vanish).
//!
//! Then `B = b1 + b2` with commuting `b_i`, `b_i² = λ_i` the roots of `λ² - s λ + q4/4`, and
//! `exp(B) = C1 C2 + B (D1 - D2 Q/2) + S1 S2 Q/2`
//! (`algebra_core::closed_form::invariant_exp_factors`). Complex roots (signature `(2, 2)`)
//! are detected at run time and go to the runtime series. This covers CGA `R^{4,1}` in the
//! diagonal and a null basis, spacetime algebra, `R^{3,1}` and Euclidean `R^4`. The two earlier
//! families ([`crate::closed`]) keep priority.

use super::{CodegenError, ModuleSpec};
use algebra_core::rational::Q;
use algebra_core::tables::{Product, ProductTable, Unary};
use num_traits::Zero;
use std::collections::BTreeMap;

/// A quadratic form: `(i, j, coefficient)` with `i <= j`, meaning `coefficient · x_i x_j`.
pub type Quadratic = Vec<(usize, usize, Q)>;

/// The tables of one detected invariant-decomposition pair, in canonical coefficients.
#[derive(Debug, Clone, PartialEq)]
pub struct Invariant {
    /// The masks of `W`: `M`'s elements other than `1` and `B`'s.
    pub quad: Vec<u32>,
    /// `s = <B²>_0` over `B`'s coefficients.
    pub s: Quadratic,
    /// Per element of `W`: its coefficient in `Q = <B²>_W`, over `B`'s coefficients.
    pub q: Vec<Quadratic>,
    /// `Q² = q4` over `W`'s coefficients.
    pub q4: Quadratic,
    /// Per element of `B`: its coefficient in `B Q`, as `(field of B, element of W, c)`.
    pub bq: Vec<Vec<(usize, usize, Q)>>,
}

/// The invariant-decomposition pair `(B, M)`, if the tables qualify (see the module docs): the
/// diagonal of `<B²>_0` (the `square` of [`crate::closed::ClosedForm`]) and the tables.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, closed::{Family, detect}, plan::Plan};
/// let alg = Algebra::builtin("cga").unwrap();
/// let types = ModuleSpec::parse_types("Bivector=grade2;Motor=even", &alg).unwrap();
/// let plan = Plan::new(ModuleSpec::new("c", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
/// let found = detect(&plan.spec, &plan.closed).unwrap();
/// let Family::Invariant(inv) = &found[0].family else { panic!() };
/// assert_eq!(inv.quad.len(), 5); // the five 4-vectors of R^{4,1}
/// ```
pub fn pair(spec: &ModuleSpec, b: usize, m: usize) -> Result<Option<(Vec<Q>, Invariant)>, CodegenError> {
    let Some(quad) = even_rest(spec, b, m) else { return Ok(None) };
    if quad.is_empty() {
        return Ok(None);
    }
    let bm = &spec.types[b].elements;
    let gp = spec.algebra.tables().product(spec.basis, Product::Geometric);
    // B² = s + Q with Q in span(W)
    let (mut s, mut q) = (Vec::new(), vec![Vec::new(); quad.len()]);
    for (i, &x) in bm.iter().enumerate() {
        for (j, &y) in bm.iter().enumerate().skip(i) {
            for (k, c) in sym(gp, x, y) {
                match quad.iter().position(|w| *w == k) {
                    _ if k == 0 => s.push((i, j, c)),
                    Some(a) => q[a].push((i, j, c)),
                    None => return Ok(None),
                }
            }
        }
    }
    // Q² scalar
    let mut q4 = Vec::new();
    for (a, &x) in quad.iter().enumerate() {
        for (bb, &y) in quad.iter().enumerate().skip(a) {
            for (k, c) in sym(gp, x, y) {
                if k != 0 {
                    return Ok(None);
                }
                q4.push((a, bb, c));
            }
        }
    }
    // B Q in B, identically: the cubic b_k Q_a(b) (e_k e_a) has no other component
    let mut bq = vec![Vec::new(); bm.len()];
    let mut outside: BTreeMap<(u32, [usize; 3]), Q> = BTreeMap::new();
    for (k, &x) in bm.iter().enumerate() {
        for (a, &w) in quad.iter().enumerate() {
            for (mask, c) in gp.get(x, w).expect("masks of the spec's algebra") {
                if c.is_zero() {
                    continue;
                }
                match bm.iter().position(|y| y == mask) {
                    Some(pos) => bq[pos].push((k, a, c.clone())),
                    None => {
                        for (i, j, d) in &q[a] {
                            let mut mono = [k, *i, *j];
                            mono.sort_unstable();
                            *outside.entry((*mask, mono)).or_insert_with(Q::zero) += c * d;
                        }
                    }
                }
            }
        }
    }
    if outside.values().any(|c| !c.is_zero()) {
        return Ok(None);
    }
    let square = (0..bm.len())
        .map(|i| s.iter().filter(|(a, b, _)| *a == i && *b == i).map(|(_, _, c)| c.clone()).sum())
        .collect();
    Ok(Some((square, Invariant { quad, s, q, q4, bq })))
}

/// (Shared with [`crate::closed`]'s families.) `W`, the elements of `M` other than `1` and `B`'s, when the pair can have a closed form of
/// any family: `B` not empty and made of two-generator elements inside `M`, `1` in `M`,
/// `rev(e) = -e` on `B` and `rev(w) = w` on `W`. `None` otherwise.
pub(crate) fn even_rest(spec: &ModuleSpec, b: usize, m: usize) -> Option<Vec<u32>> {
    let (bm, mm) = (&spec.types[b].elements, &spec.types[m].elements);
    if b == m || bm.is_empty() || !mm.contains(&0) || !bm.iter().all(|x| x.count_ones() == 2 && mm.contains(x)) {
        return None;
    }
    let rest: Vec<u32> = mm.iter().copied().filter(|x| *x != 0 && !bm.contains(x)).collect();
    let rev = spec.algebra.tables().unary(spec.basis, Unary::Reverse);
    let reversed = |x: u32, s: i64| {
        rev.image(x).is_ok_and(|im| im.len() == 1 && im[0].0 == x && im[0].1 == Q::from_integer(s.into()))
    };
    (bm.iter().all(|&x| reversed(x, -1)) && rest.iter().all(|&x| reversed(x, 1))).then_some(rest)
}

/// The symmetric square `x y + y x` (or `x x`) of two basis elements, as `(mask, coefficient)`
/// with the zero coefficients dropped.
pub(crate) fn sym(gp: &ProductTable, x: u32, y: u32) -> BTreeMap<u32, Q> {
    let mut out = BTreeMap::new();
    let mut add = |terms: &[(u32, Q)]| {
        for (k, c) in terms {
            *out.entry(*k).or_insert_with(Q::zero) += c.clone();
        }
    };
    add(gp.get(x, y).expect("masks of the spec's algebra"));
    if x != y {
        add(gp.get(y, x).expect("masks of the spec's algebra"));
    }
    out.retain(|_, c| !c.is_zero());
    out
}
