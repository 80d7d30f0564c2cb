//! Work budgets checked *before* work starts, so that a small input cannot make `gam` run for
//! days or exhaust memory: one `error:` line (exit 2) names the estimate and the limit.
//!
//! The limit is [`DEFAULT_WORK_BUDGET`] units of work; the environment variable
//! `GAM_WORK_BUDGET` raises (or lowers) it for one run, e.g. `GAM_WORK_BUDGET=1e10 gam ...`.
//! Commands call [`check`] with their estimate; `gam sample`, `gam plot` and `gam interpolate`
//! (per body point) estimate `samples × (degree + 1)²` (a multiplicative segment's de Casteljau tableau has
//! `(degree + 1)(degree + 2)/2` slerps per sample, each a dual-number evaluation); every
//! command that loads an algebra checks the work of its product tables ([`algebra`]), and
//! `gam eval` checks every `poly` product's term products before forming them.

use crate::error::CliError;

/// The default number of work units allowed per command (about a minute on one core).
pub const DEFAULT_WORK_BUDGET: f64 = 2e8;

/// The environment variable that replaces [`DEFAULT_WORK_BUDGET`].
pub const BUDGET_VAR: &str = "GAM_WORK_BUDGET";

/// The budget in force: `GAM_WORK_BUDGET` (a positive number, `2e9` accepted) or the default.
pub fn limit() -> Result<f64, CliError> {
    match std::env::var(BUDGET_VAR) {
        Err(_) => Ok(DEFAULT_WORK_BUDGET),
        Ok(text) => match text.trim().parse::<f64>() {
            Ok(x) if x.is_finite() && x > 0.0 => Ok(x),
            _ => Err(CliError::usage(format!("{BUDGET_VAR}=`{text}` must be a positive number"))),
        },
    }
}

/// `Ok` when `estimate` (in work units) is within the budget; otherwise the usage error
/// `WHAT needs about N units of work, more than the budget of M (set GAM_WORK_BUDGET to raise it)`.
pub fn check(what: &str, estimate: f64) -> Result<(), CliError> {
    let max = limit()?;
    if estimate <= max {
        Ok(())
    } else {
        Err(CliError::usage(format!(
            "{what} needs about {estimate:.2e} units of work, more than the budget of {max:.2e} (set {BUDGET_VAR} to raise it)"
        )))
    }
}

/// Work units per coefficient term product of a `--scalar poly` product (an exact rational
/// multiply and a monomial merge cost about 20 table units).
pub const UNITS_PER_TERM_PRODUCT: f64 = 20.0;

/// Work units per exact multiply-add of the product tables ([`algebra_core::Tables::build_work`]).
pub const UNITS_PER_TABLE_TERM: f64 = 10.0;

/// The algebra named `arg` (a built-in name or a TOML file), refused before its product tables
/// are built when their work exceeds the budget (a dense metric costs `8^n`).
pub fn algebra(arg: &str) -> Result<std::sync::Arc<algebra_core::Algebra>, CliError> {
    let alg = algebra_codegen::metric_toml::algebra_from_name_or_path(arg)?;
    let work = algebra_core::Tables::build_work(alg.metric()) * UNITS_PER_TABLE_TERM;
    check(&format!("building the product tables of {} generators", alg.generators()), work)?;
    Ok(alg)
}

/// The estimate for sampling a Bezier segment of `degree` at `samples` parameter values.
pub fn sampling_work(degree: usize, samples: usize) -> f64 {
    let d = degree as f64 + 1.0;
    samples as f64 * d * d
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn estimates_and_limit() {
        assert_eq!(sampling_work(3, 100), 1600.0);
        assert!(check("x", 1.0).is_ok());
        let e = check("sampling", 1e12).unwrap_err();
        assert_eq!(e.code, crate::error::EXIT_USAGE);
        assert!(e.message.contains("GAM_WORK_BUDGET"), "{}", e.message);
    }
}
