//! Work budgets checked *before* work starts, so that a small input cannot make `gam` run for
//! days or exhaust memory: one `error:` line (exit 2) names the estimate and the limit.
//!
//! The limit is [`DEFAULT_WORK_BUDGET`] units of work; the environment variable
//! `GAM_WORK_BUDGET` raises (or lowers) it for one run, e.g. `GAM_WORK_BUDGET=1e10 gam ...`.
//! Commands call [`check`] with their estimate; `gam sample`, `gam plot` and `gam interpolate`
//! (per body point) estimate `samples × (degree + 1)²` (a multiplicative segment's de Casteljau tableau has
//! `(degree + 1)(degree + 2)/2` slerps per sample, each a dual-number evaluation); every
//! command that loads an algebra checks the work of its product tables ([`algebra`]), and
//! `gam eval` checks every `poly` product's term products before forming them, and the memory
//! its result may take against a second budget, [`DEFAULT_MEMORY_BUDGET`] bytes
//! (`GAM_MEMORY_BUDGET`), so that a product is refused before an allocation could fail.

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

/// The default memory a single value may take, in bytes (1 GB).
pub const DEFAULT_MEMORY_BUDGET: f64 = 1e9;

/// The environment variable that replaces [`DEFAULT_MEMORY_BUDGET`].
pub const MEMORY_VAR: &str = "GAM_MEMORY_BUDGET";

/// About how many work units one second of one core does (the default work budget is about a
/// minute): `gam prove --timeout` refuses a product whose work would not fit in the time left.
pub const UNITS_PER_SECOND: f64 = 3e6;

/// `Ok` when a value of about `bytes` bytes is within the memory budget (`GAM_MEMORY_BUDGET`,
/// default [`DEFAULT_MEMORY_BUDGET`]); otherwise the usage error `WHAT needs about N bytes of
/// memory, more than the budget of M (set GAM_MEMORY_BUDGET to raise it)`, before the
/// allocation, so that a large product is refused instead of aborting when memory runs out.
pub fn check_memory(what: &str, bytes: f64) -> Result<(), CliError> {
    let max = match std::env::var(MEMORY_VAR) {
        Err(_) => DEFAULT_MEMORY_BUDGET,
        Ok(text) => match text.trim().parse::<f64>() {
            Ok(x) if x.is_finite() && x > 0.0 => x,
            _ => return Err(CliError::usage(format!("{MEMORY_VAR}=`{text}` must be a positive number of bytes"))),
        },
    };
    if bytes <= max {
        Ok(())
    } else {
        Err(CliError::usage(format!(
            "{what} needs about {bytes:.2e} bytes of memory, more than the budget of {max:.2e} (set {MEMORY_VAR} to raise it)"
        )))
    }
}

/// Bytes of one term of a `--scalar poly` result with `vars` variables: the map entry with
/// its node share (about 100), the coefficient's two limbs (about 50) and 8 per variable.
pub fn poly_term_bytes(vars: usize) -> f64 {
    150.0 + 8.0 * vars as f64
}

/// Work units per coefficient term product of a `--scalar poly` product (an exact rational
/// multiply and a monomial merge cost about 20 table units).
pub const UNITS_PER_TERM_PRODUCT: f64 = 20.0;

/// Work units per bit of an exact number formed by a power `x ** k` (its size is known before
/// the work: the base's bits times `k`); the default budget allows numbers of 2e8 bits (25 MB).
pub const UNITS_PER_BIT: f64 = 1.0;

/// Pairs of 64-bit limbs per work unit in an exact rational product (num-bigint's multiply
/// and the gcds of the normalisation): about 9e7 limb pairs a second with the release build,
/// against [`UNITS_PER_SECOND`]; `cargo bench -p gam --bench work_estimate` checks products
/// of 100,000-digit and 30,000-digit rationals within 2x of the time.
pub const LIMB_PAIRS_PER_UNIT: f64 = 30.0;

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

/// What one sample of a motion evaluates, for the work estimate of sampling
/// ([`sampling_work`]): each kind's units per `(degree + 1)²` of the de Casteljau tableau and
/// per sample (the pose, its twists and the body point over dual numbers, and the sample's
/// output), measured with the release build by `cargo bench -p gam --bench work_estimate`
/// (docs/performance.md) so that the estimate is within 2x of the time.
///
/// ```
/// use gam::budget::Tableau;
/// assert!(Tableau::Slerp.units_per_entry() > 10.0 * Tableau::Linear.units_per_entry());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tableau {
    /// Additive Bézier segments (a few multiply-adds per coefficient and entry), the
    /// Wareham–Lasenby and hexanion motions (no tableau: an exponential per sample).
    Linear,
    /// Multiplicative Bézier segments: a logarithm and an exponential per entry.
    Slerp,
    /// Jüttler's rational motions (Q-motions, the minimal-order motion): a dual-quaternion
    /// tableau and its normalisation to a pose.
    Rational,
}

impl Tableau {
    /// The tableau of a Bézier segment of `kind`.
    ///
    /// ```
    /// use gam::budget::Tableau;
    /// assert_eq!(Tableau::of_segment(motion::SegmentKind::Multiplicative), Tableau::Slerp);
    /// ```
    pub fn of_segment(kind: motion::SegmentKind) -> Self {
        match kind {
            motion::SegmentKind::Additive => Tableau::Linear,
            motion::SegmentKind::Multiplicative => Tableau::Slerp,
        }
    }

    /// The tableau of a `gam interpolate` method's samples.
    ///
    /// ```
    /// use gam::budget::Tableau;
    /// use motion::method::Method;
    /// assert_eq!(Tableau::of_method(Method::JuttlerSpline), Tableau::Rational);
    /// assert_eq!(Tableau::of_method(Method::WlQuadratic), Tableau::Linear);
    /// ```
    pub fn of_method(method: motion::method::Method) -> Self {
        // the multiplicative Bézier's slerps, the Jüttler methods' rational evaluation, and the
        // rest (additive Bézier, W-L, hexanion): a linear tableau
        if method == motion::method::Method::CcmMultiplicative {
            Tableau::Slerp
        } else if method.is_juttler() {
            Tableau::Rational
        } else {
            Tableau::Linear
        }
    }

    /// Units per `(degree + 1)²` of one sample.
    ///
    /// ```
    /// assert_eq!(gam::budget::Tableau::Slerp.units_per_entry(), 0.45);
    /// ```
    pub fn units_per_entry(self) -> f64 {
        match self {
            Tableau::Linear => 0.012,
            Tableau::Slerp => 0.45,
            Tableau::Rational => 0.03,
        }
    }

    /// Units per sample besides the tableau.
    ///
    /// ```
    /// assert_eq!(gam::budget::Tableau::Linear.units_per_sample(), 25.0);
    /// ```
    pub fn units_per_sample(self) -> f64 {
        match self {
            Tableau::Linear | Tableau::Slerp => 25.0,
            Tableau::Rational => 50.0,
        }
    }
}

/// The work of `passes` passes over `samples` samples of segments of degree `degree`:
/// `passes × samples × (e (degree + 1)² + s)` with `e` and `s` the [`Tableau`]'s units per
/// entry and per sample. Streamed output takes two passes (every sample is computed once to
/// check it, once to print it).
///
/// ```
/// use gam::budget::{Tableau, sampling_work};
/// assert_eq!(sampling_work(Tableau::Linear, 3, 100, 1), 100.0 * (16.0 * 0.012 + 25.0));
/// assert_eq!(sampling_work(Tableau::Slerp, 3, 100, 2), 200.0 * (16.0 * 0.45 + 25.0));
/// ```
pub fn sampling_work(tableau: Tableau, degree: usize, samples: usize, passes: usize) -> f64 {
    evaluation_work(tableau, degree, passes * samples, 1.0)
}

/// `evaluations × (e × entry_factor × (degree + 1)² + s)`: the one formula of
/// [`sampling_work`] and [`plotting_work`].
fn evaluation_work(tableau: Tableau, degree: usize, evaluations: usize, entry_factor: f64) -> f64 {
    let d = degree as f64 + 1.0;
    evaluations as f64 * (tableau.units_per_entry() * entry_factor * d * d + tableau.units_per_sample())
}

/// How much more a tableau entry costs over the second-order dual numbers of `gam plot` (its
/// speeds and accelerations) than over the first-order ones of `gam sample`: measured 2.5-2.8
/// with multiplicative segments of degree 100 and 400 (`cargo bench -p gam --bench
/// work_estimate`), which the first-order estimate promised 2.7 times too fast.
pub const SECOND_ORDER_ENTRY_FACTOR: f64 = 2.7;

/// [`sampling_work`] for one pass over `samples` evaluations over second-order dual numbers
/// (`gam plot`): each tableau entry [`SECOND_ORDER_ENTRY_FACTOR`] times dearer.
///
/// ```
/// use gam::budget::{Tableau, plotting_work};
/// assert_eq!(plotting_work(Tableau::Slerp, 3, 100), 100.0 * (16.0 * 0.45 * 2.7 + 25.0));
/// ```
pub fn plotting_work(tableau: Tableau, degree: usize, samples: usize) -> f64 {
    evaluation_work(tableau, degree, samples, SECOND_ORDER_ENTRY_FACTOR)
}

/// The work of building one of Jüttler's global interpolants (`juttler-q-motion`,
/// `juttler-trt`, `juttler-minimal`: one curve through all `m` key poses, degree growing with
/// `m`) before it is built: `c m⁴` units, `c` per method, measured as [`Tableau`]'s units
/// (the collocation and the check that the result hits every key pose). `None` for the other
/// methods, whose build is linear in `m`.
///
/// ```
/// use gam::budget::global_build_work;
/// use motion::method::Method;
/// assert_eq!(global_build_work(Method::JuttlerQMotion, 10), Some(1e4));
/// assert_eq!(global_build_work(Method::CcmAdditive, 10), None);
/// ```
pub fn global_build_work(method: motion::method::Method, m: usize) -> Option<f64> {
    use motion::method::Method;
    let c = match method {
        Method::JuttlerQMotion | Method::JuttlerAffine => 1.0,
        Method::JuttlerProjective => 2.0,
        Method::JuttlerTrt => 0.5,
        Method::JuttlerMinimal => 2.5,
        _ => return None,
    };
    Some(c * (m as f64).powi(4))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn estimates_and_limit() {
        assert_eq!(sampling_work(Tableau::Linear, 3, 100, 1), 100.0 * (16.0 * 0.012 + 25.0));
        assert_eq!(sampling_work(Tableau::Slerp, 99, 10, 2), 20.0 * (1e4 * 0.45 + 25.0));
        assert_eq!(sampling_work(Tableau::Rational, 0, 1, 1), 0.03 + 50.0);
        assert!(check("x", 1.0).is_ok());
        let e = check("sampling", 1e12).unwrap_err();
        assert_eq!(e.code, crate::error::EXIT_USAGE);
        assert!(e.message.contains("GAM_WORK_BUDGET"), "{}", e.message);
        assert!(check_memory("x", 1e6).is_ok());
        let e = check_memory("the product at column 3", 1e12).unwrap_err();
        assert_eq!(e.code, crate::error::EXIT_USAGE);
        assert!(e.message.contains("GAM_MEMORY_BUDGET") && e.message.contains("1.00e12 bytes"), "{}", e.message);
        assert_eq!(poly_term_bytes(2), 166.0);
    }
}
