//! Closed-form `exp`, `log`, `log_unit`, `normalize`, `sqrt` and `pow`, detected from the exact
//! product tables (never from the algebra's name) for a declared *bivector type* `B` (every
//! element made of two generators, `rev(e) = -e`) and a declared *even type* `M` (a subalgebra
//! holding `1` and `B`) with `M = 1 + B` or `M = 1 + B + I`:
//!
//! - [`Family::Scalar`]: every `B² = q(b)` is a scalar, `q` a diagonal quadratic form
//!   (Euclidean rotors in 2D and 3D, 2D PGA motors, complex numbers). `exp(B) = cos θ + sinc θ B`
//!   when `q <= 0` (`θ² = -q`), `cosh φ + (sinh φ/φ) B` when `q >= 0` (`φ² = q`); the generator
//!   knows the sign of `q` from its coefficients ([`Sign`]) and emits a run-time choice only
//!   when they have both signs;
//! - [`Family::Dual`]: `B² = q(b) + c(b) I` with `q <= 0`, `I` the one further element of `M`,
//!   central in `M`, `I² = 0`, `rev(I) = I` and `I B ⊂ B` (3D PGA, the dual quaternions
//!   `G_{123inf}^+`, in any basis orientation):
//!   `exp(B) = cos θ + (c/2) sinc θ I + (sinc θ - (c/2) k(θ) I) B`.
//!
//! The scalar factors live in `algebra_core::closed_form`; the emitted methods only assemble
//! them. Everything is computed in canonical coefficients and the fields' orientation signs
//! are folded into the emitted constants.

use super::closed_inv::{even_rest, sym};
use super::{CodegenError, ModuleSpec};
use algebra_core::rational::Q;
use algebra_core::tables::Product;
use num_traits::{Signed, Zero};

/// The sign of the quadratic form `q` with `B² = q` (or `q + cI`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sign {
    /// Every coefficient `<= 0`: `q = -θ² <= 0` (trigonometric).
    Elliptic,
    /// Every coefficient `>= 0`, one `> 0`: `q = φ² >= 0` (hyperbolic).
    Hyperbolic,
    /// Both signs: chosen at run time by the sign of `q`.
    Mixed,
}

/// `I e_b` for one field of `B`: `(field of B, coefficient)` terms.
pub type ITimes = Vec<(usize, Q)>;

/// Which closed form applies.
#[derive(Debug, Clone, PartialEq)]
pub enum Family {
    /// `M = 1 + B`, `B² = q`.
    Scalar(Sign),
    /// `M = 1 + B + I`, `B² = q + cI` (`q <= 0`, `I` central, `I² = 0`).
    Dual {
        /// The mask of `I`.
        i: u32,
        /// `(i, j, coefficient)` of `c/2` in `B`'s canonical coefficients (`i <= j`).
        half_c: Vec<(usize, usize, Q)>,
        /// Per field of `B`: `I e_b` as `(field of B, coefficient)`.
        i_times: Vec<ITimes>,
    },
    /// `M = 1 + B + W`, `B² = s + Q` with `Q` in `W`, `Q²` scalar, `B Q` in `B`: the invariant
    /// decomposition of 4D and 5D algebras ([`crate::closed_inv`]).
    Invariant(Box<crate::closed_inv::Invariant>),
}

/// One detected pair: `B::exp -> M`, `M::log -> B`.
#[derive(Debug, Clone, PartialEq)]
pub struct ClosedForm {
    /// The bivector type's index.
    pub bivector: usize,
    /// The even type's index.
    pub even: usize,
    /// Per field of `B`: `d` with `q = Σ d b²` (canonical coefficients).
    pub square: Vec<Q>,
    /// The family.
    pub family: Family,
}

/// Every (bivector type, even type) pair with a closed form, each type in at most one pair
/// (the first declared wins).
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, closed::{Family, detect}, plan::Plan};
/// let alg = Algebra::builtin("pga3").unwrap();
/// let types = ModuleSpec::parse_types("Line=e01,e20,e03,e12,e31,e23;Motor=even", &alg).unwrap();
/// let plan = Plan::new(ModuleSpec::new("pga", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
/// let found = detect(&plan.spec, &plan.closed).unwrap();
/// assert_eq!((found[0].bivector, found[0].even), (0, 1));
/// assert!(matches!(found[0].family, Family::Dual { i: 0b1111, .. }));
/// ```
pub fn detect(spec: &ModuleSpec, closed: &[bool]) -> Result<Vec<ClosedForm>, CodegenError> {
    let mut out: Vec<ClosedForm> = Vec::new();
    for m in (0..spec.types.len()).filter(|&m| closed[m]) {
        for b in 0..spec.types.len() {
            if out.iter().any(|c| c.bivector == b || c.even == m) {
                continue;
            }
            if let Some(c) = pair(spec, b, m)? {
                out.push(c);
            } else if let Some((square, inv)) = super::closed_inv::pair(spec, b, m)? {
                out.push(ClosedForm { bivector: b, even: m, square, family: Family::Invariant(Box::new(inv)) });
            }
        }
    }
    Ok(out)
}

fn pair(spec: &ModuleSpec, b: usize, m: usize) -> Result<Option<ClosedForm>, CodegenError> {
    let Some(rest) = even_rest(spec, b, m) else { return Ok(None) };
    if rest.len() > 1 {
        return Ok(None);
    }
    let (bm, mm) = (&spec.types[b].elements, &spec.types[m].elements);
    let i = rest.first().copied();
    let gp = spec.algebra.tables().product(spec.basis, Product::Geometric);
    let get = |x: u32, y: u32| gp.get(x, y).expect("masks of the spec's algebra").to_vec();
    let mut square = vec![Q::zero(); bm.len()];
    let mut half_c = Vec::new();
    for (ia, &x) in bm.iter().enumerate() {
        for (ib, &y) in bm.iter().enumerate().skip(ia) {
            let mut scalar = Q::zero();
            let mut ipart = Q::zero();
            for (k, c) in sym(gp, x, y) {
                match k {
                    0 => scalar = c,
                    k if Some(k) == i => ipart = c,
                    _ => return Ok(None),
                }
            }
            if ia == ib {
                square[ia] = scalar;
            } else if !scalar.is_zero() {
                return Ok(None); // not a diagonal form
            }
            if !ipart.is_zero() {
                half_c.push((ia, ib, ipart / int(2)));
            }
        }
    }
    let sign = if square.iter().all(|d| !d.is_positive()) {
        Sign::Elliptic
    } else if square.iter().all(|d| !d.is_negative()) {
        Sign::Hyperbolic
    } else {
        Sign::Mixed
    };
    let family = match i {
        None => Family::Scalar(sign),
        Some(i) => {
            let nilpotent = get(i, i).iter().all(|(_, c)| c.is_zero());
            let central = mm.iter().all(|&x| get(i, x) == get(x, i));
            let mut i_times = Vec::new();
            for &x in bm {
                let mut row = Vec::new();
                for (k, c) in get(i, x) {
                    match bm.iter().position(|y| *y == k) {
                        Some(pos) => row.push((pos, c)),
                        None if c.is_zero() => {}
                        None => return Ok(None),
                    }
                }
                i_times.push(row);
            }
            if !nilpotent || !central || sign != Sign::Elliptic {
                return Ok(None);
            }
            Family::Dual { i, half_c, i_times }
        }
    };
    Ok(Some(ClosedForm { bivector: b, even: m, square, family }))
}

fn int(n: i64) -> Q {
    Q::from_integer(n.into())
}
