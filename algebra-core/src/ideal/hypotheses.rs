//! Deciding polynomial claims under hypotheses: equations `h = 0` and non-vanishing conditions
//! `g != 0` (by the Rabinowitsch trick: a new variable `t` with `1 - t g = 0`).

use super::{Budget, IdealError, Meter, MonomialOrder, PolyRing};
use crate::Ring;
use crate::poly::Poly;
use std::time::Instant;

/// Hypotheses of a claim: polynomials assumed to vanish and polynomials assumed not to vanish.
///
/// ```
/// use algebra_core::ideal::Hypotheses;
/// use algebra_core::{Poly, Ring};
/// let h = Hypotheses { equations: vec![Poly::var("x") * Poly::var("y") - Poly::one()], nonzero: vec![] };
/// assert_eq!(h.equations.len(), 1);
/// ```
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Hypotheses {
    /// `h = 0` for each `h`.
    pub equations: Vec<Poly>,
    /// `g != 0` for each `g`.
    pub nonzero: Vec<Poly>,
}

/// The answer of [`decide`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Decision {
    /// Every claim polynomial lies in the ideal of the hypotheses (with the Rabinowitsch
    /// variables): the claim follows from the hypotheses over the rationals.
    pub holds: bool,
    /// Size of the reduced Gröbner basis of the hypotheses.
    pub basis_size: usize,
    /// The hypotheses are contradictory (the basis is `[1]`): every claim holds vacuously.
    pub inconsistent: bool,
    /// For each claim that does not follow: its index and its non-zero normal form.
    pub failures: Vec<(usize, Poly)>,
    /// Wall-clock time of the decision in milliseconds.
    pub time_ms: u128,
}

/// The name of the `i`-th Rabinowitsch variable (not a valid identifier of the CLI grammar, so
/// it cannot clash with a user symbol).
fn rabinowitsch_var(i: usize) -> String {
    format!("rabinowitsch#{i}")
}

/// Decides whether every `claims[i] = 0` follows from `hyps`: builds the ideal of the equations
/// and of `1 - t_j g_j` for the non-vanishing `g_j`, computes its reduced grevlex Gröbner basis
/// and reduces each claim. "Holds" is ideal membership, a sufficient condition for the claim to
/// hold at every complex point satisfying the hypotheses; "does not hold" means not in the ideal
/// (the claim may still hold on the solution set when the ideal is not radical).
///
/// ```
/// use algebra_core::ideal::{Budget, Hypotheses, decide};
/// use algebra_core::{Poly, Ring};
/// let (x, y) = (Poly::var("x"), Poly::var("y"));
/// // x y = x and x != 0 give y = 1; without x != 0 it does not follow.
/// let eq = x.clone() * y.clone() - x.clone();
/// let claim = y.clone() - Poly::one();
/// let with = Hypotheses { equations: vec![eq.clone()], nonzero: vec![x.clone()] };
/// assert!(decide(&[claim.clone()], &with, &Budget::default()).unwrap().holds);
/// let without = Hypotheses { equations: vec![eq], nonzero: vec![] };
/// assert!(!decide(&[claim], &without, &Budget::default()).unwrap().holds);
/// ```
pub fn decide(claims: &[Poly], hyps: &Hypotheses, budget: &Budget) -> Result<Decision, IdealError> {
    let start = Instant::now();
    let mut gens: Vec<Poly> = hyps.equations.iter().filter(|p| !p.is_exact_zero()).cloned().collect();
    for (i, g) in hyps.nonzero.iter().enumerate() {
        gens.push(Poly::one() - Poly::var(&rabinowitsch_var(i)) * g.clone());
    }
    let all: Vec<Poly> = gens.iter().chain(claims).cloned().collect();
    let ring = PolyRing::of(&all, MonomialOrder::GrevLex);
    // One meter for the basis and every normal form: the budget bounds the whole decision.
    let mut meter = Meter::new(budget);
    let basis = ring.groebner_metered(&gens, &mut meter)?;
    let mut failures = Vec::new();
    for (i, c) in claims.iter().enumerate() {
        meter.check_time()?;
        let r = basis.normal_form_metered(c, &mut meter)?;
        if !r.is_exact_zero() {
            failures.push((i, r));
        }
    }
    Ok(Decision {
        holds: failures.is_empty(),
        basis_size: basis.len(),
        inconsistent: basis.is_unit(),
        failures,
        time_ms: start.elapsed().as_millis(),
    })
}
