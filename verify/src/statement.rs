//! The registry entry of one numbered statement and the report of running it.

use crate::check::{Checker, Outcome};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::{Duration, Instant};

/// The four papers (see `shared/papers/README.md` and docs/paper-map.md).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Paper {
    /// Cross, Cripps and Mullineux (2022): rational motions in the null-basis CGA G_{0123inf}.
    Cross2022,
    /// Wareham and Lasenby: pose interpolation in CGA R^{4,1}, the rotor logarithm.
    WarehamLasenby,
    /// Jüttler: dual-quaternion curves and rational motions.
    Juttler,
    /// Angelidis: hexanions, the closed-form exponential of se(3).
    Angelidis,
}

impl Paper {
    /// The short key used in statement ids (`cross2022`, `wareham-lasenby`, `juttler`, `angelidis`).
    ///
    /// ```
    /// assert_eq!(gam_verify::Paper::Cross2022.key(), "cross2022");
    /// ```
    pub fn key(self) -> &'static str {
        match self {
            Paper::Cross2022 => "cross2022",
            Paper::WarehamLasenby => "wareham-lasenby",
            Paper::Juttler => "juttler",
            Paper::Angelidis => "angelidis",
        }
    }

    /// Authors and title, as a reader would cite it.
    ///
    /// ```
    /// assert!(gam_verify::Paper::Juttler.citation().contains("Jüttler"));
    /// ```
    pub fn citation(self) -> &'static str {
        match self {
            Paper::Cross2022 => "Cross, Cripps, Mullineux (2022): rigid-body motions in conformal geometric algebra",
            Paper::WarehamLasenby => "Wareham, Lasenby: pose interpolation in conformal geometric algebra",
            Paper::Juttler => "Jüttler: dual-quaternion curves and rational motions",
            Paper::Angelidis => "Angelidis: hexanions, the algebra of twists",
        }
    }
}

/// How a statement is checked: the strongest scalar that fits it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method {
    /// Exact polynomial identities in fully symbolic coefficients (`Poly`).
    Symbolic,
    /// Exact rational arithmetic on chosen (often random) instances.
    Exact,
    /// MPFR floats at 256 bits; agreement to at least 70 decimal digits.
    MpFloat,
    /// MPFR floats at 256 bits with dual numbers (`Jet`) for exact derivatives; >= 70 digits.
    MpFloatDual,
}

impl Method {
    /// The key printed by `gam verify` (`symbolic`, `exact`, `mpfr-256`, `mpfr-256+dual`).
    ///
    /// ```
    /// assert_eq!(gam_verify::Method::MpFloatDual.key(), "mpfr-256+dual");
    /// ```
    pub fn key(self) -> &'static str {
        match self {
            Method::Symbolic => "symbolic",
            Method::Exact => "exact",
            Method::MpFloat => "mpfr-256",
            Method::MpFloatDual => "mpfr-256+dual",
        }
    }
}

/// One numbered statement of a paper and its check.
#[derive(Debug)]
pub struct Statement {
    /// `paper-key/kind-number[-part]`, e.g. `cross2022/lemma-2.2-ii`.
    pub id: &'static str,
    /// The paper.
    pub paper: Paper,
    /// The paper's label, e.g. `Lemma 2.2 (ii)` or `Eq. (9)`.
    pub label: &'static str,
    /// The statement in words (and formulas in plain text).
    pub statement: &'static str,
    /// How it is checked.
    pub method: Method,
    /// Hypotheses the text leaves implicit and what was found; empty if none.
    pub hypotheses: &'static str,
    /// Records every comparison in the checker.
    pub check: fn(&mut Checker),
}

/// The result of running one statement.
#[derive(Debug)]
pub struct Report {
    /// The statement that was run.
    pub statement: &'static Statement,
    /// What the checks found.
    pub outcome: Outcome,
    /// Wall time of the check.
    pub elapsed: Duration,
}

impl Statement {
    /// Runs the check; a panic inside it is reported as a failure, not propagated.
    ///
    /// ```
    /// let r = gam_verify::find("cross2022/lemma-2.4").unwrap().run();
    /// assert!(r.outcome.holds());
    /// assert!(r.outcome.checks > 0);
    /// ```
    pub fn run(&'static self) -> Report {
        let start = Instant::now();
        let mut checker = Checker::new();
        let result = catch_unwind(AssertUnwindSafe(|| (self.check)(&mut checker)));
        if let Err(payload) = result {
            let msg = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".to_string());
            checker.fail(format!("the check panicked: {msg}"));
        }
        Report { statement: self, outcome: checker.finish(), elapsed: start.elapsed() }
    }
}
