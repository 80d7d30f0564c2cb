//! [`Checker`]: records the comparisons a statement's check makes.

use algebra_core::{Multivector, Real, Ring};
use std::fmt::{Debug, Display};

/// Collects the comparisons of one statement: how many were made, which failed, and notes
/// (counterexamples found, hypotheses confirmed) for the report.
///
/// ```
/// let mut c = gam_verify::Checker::new();
/// c.equal("1 + 1 = 2", &(1 + 1), &2);
/// c.counterexample("2 + 2 = 5 fails", 2 + 2 == 5, "2 + 2 = 4");
/// let out = c.finish();
/// assert!(out.holds());
/// assert_eq!(out.checks, 2);
/// ```
#[derive(Debug, Default)]
pub struct Checker {
    checks: usize,
    failures: Vec<String>,
    notes: Vec<String>,
}

/// What a statement's checks found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Outcome {
    /// Number of comparisons made.
    pub checks: usize,
    /// One line per failed comparison.
    pub failures: Vec<String>,
    /// Findings worth reporting (counterexamples, which hypothesis was needed).
    pub notes: Vec<String>,
}

impl Outcome {
    /// True when at least one comparison was made and none failed.
    ///
    /// ```
    /// let out = gam_verify::Checker::new().finish();
    /// assert!(!out.holds(), "a check that compares nothing proves nothing");
    /// ```
    pub fn holds(&self) -> bool {
        self.checks > 0 && self.failures.is_empty()
    }
}

impl Checker {
    /// An empty checker.
    ///
    /// ```
    /// assert_eq!(gam_verify::Checker::new().finish().checks, 0);
    /// ```
    pub fn new() -> Self {
        Self::default()
    }

    /// Records a comparison that passed when `ok`.
    ///
    /// ```
    /// let mut c = gam_verify::Checker::new();
    /// c.check("3 > 2", 3 > 2);
    /// assert!(c.finish().holds());
    /// ```
    pub fn check(&mut self, what: impl Display, ok: bool) -> bool {
        self.checks += 1;
        if !ok {
            self.failures.push(what.to_string());
        }
        ok
    }

    /// Records a failure that is not a comparison (e.g. an unexpected error).
    ///
    /// ```
    /// let mut c = gam_verify::Checker::new();
    /// c.fail("log of a singular pose");
    /// assert!(!c.finish().holds());
    /// ```
    pub fn fail(&mut self, what: impl Display) {
        self.checks += 1;
        self.failures.push(what.to_string());
    }

    /// Records an exact equality; on failure both sides are printed.
    ///
    /// ```
    /// let mut c = gam_verify::Checker::new();
    /// c.equal("x", &1, &2);
    /// assert_eq!(c.finish().failures, vec!["x: 1 != 2".to_string()]);
    /// ```
    pub fn equal<T: PartialEq + Debug + ?Sized>(&mut self, what: impl Display, lhs: &T, rhs: &T) -> bool {
        let ok = lhs == rhs;
        self.checks += 1;
        if !ok {
            self.failures.push(format!("{what}: {lhs:?} != {rhs:?}"));
        }
        ok
    }

    /// Records an exact equality of multivectors, printing them in basis notation on failure.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector, Ring, rational::Q};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let e1 = Multivector::<Q>::basis_element(&alg, Basis::Blade, "e1").unwrap();
    /// let mut c = gam_verify::Checker::new();
    /// c.equal_mv("e1 e1 = 1", &(&e1 * &e1), &Multivector::scalar(&alg, Basis::Blade, Q::one()));
    /// assert!(c.finish().holds());
    /// ```
    pub fn equal_mv<T: Ring>(&mut self, what: impl Display, lhs: &Multivector<T>, rhs: &Multivector<T>) -> bool {
        let ok = lhs == rhs;
        self.checks += 1;
        if !ok {
            self.failures.push(format!("{what}: {lhs} != {rhs}"));
        }
        ok
    }

    /// Records that `lhs` and `rhs` agree entry by entry to `digits` significant decimal
    /// digits: |a - b| <= 10^-digits * max(1, |a|, |b|).
    ///
    /// ```
    /// use algebra_core::{MpFloat, PrecisionGuard, Real, Ring};
    /// let _g = PrecisionGuard::new(256);
    /// let two = MpFloat::from_i64(2);
    /// let root = Real::sqrt(&two);
    /// let mut c = gam_verify::Checker::new();
    /// c.close("sqrt(2)^2 = 2", &[root.mul_ref(&root)], &[two], 70);
    /// assert!(c.finish().holds());
    /// ```
    pub fn close<T: Real + Display>(&mut self, what: impl Display, lhs: &[T], rhs: &[T], digits: u32) -> bool {
        self.checks += 1;
        if lhs.len() != rhs.len() {
            self.failures.push(format!("{what}: {} entries against {}", lhs.len(), rhs.len()));
            return false;
        }
        let tenth = T::from_ratio(1, 10);
        let mut tol = T::one();
        for _ in 0..digits {
            tol = tol.mul_ref(&tenth);
        }
        for (i, (a, b)) in lhs.iter().zip(rhs).enumerate() {
            let mut scale = T::one();
            for m in [a.abs(), b.abs()] {
                if m > scale {
                    scale = m;
                }
            }
            let diff = a.sub_ref(b).abs();
            // `partial_cmp` is None for NaN, which fails too.
            let within = matches!(
                diff.partial_cmp(&tol.mul_ref(&scale)),
                Some(std::cmp::Ordering::Less | std::cmp::Ordering::Equal)
            );
            if !within || !a.is_finite() || !b.is_finite() {
                self.failures.push(format!("{what}: entry {i}: {a} != {b} (to {digits} digits)"));
                return false;
            }
        }
        true
    }

    /// Records [`Checker::close`] on the coefficients of two multivectors in the same basis.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let x = Multivector::<f64>::basis_element(&alg, Basis::Blade, "e12").unwrap();
    /// let mut c = gam_verify::Checker::new();
    /// c.close_mv("x = x", &x, &x.clone(), 12);
    /// assert!(c.finish().holds());
    /// ```
    pub fn close_mv<T: Real + Display>(
        &mut self,
        what: impl Display,
        lhs: &Multivector<T>,
        rhs: &Multivector<T>,
        digits: u32,
    ) -> bool {
        if lhs.basis() != rhs.basis() {
            return self.close(what, lhs.coeffs(), rhs.in_basis(lhs.basis()).coeffs(), digits);
        }
        self.close(what, lhs.coeffs(), rhs.coeffs(), digits)
    }

    /// Records a counterexample to a statement *without* a hypothesis: passes when
    /// `holds_without_hypothesis` is false (the counterexample works), and keeps `found` as a
    /// note for the report.
    ///
    /// ```
    /// let mut c = gam_verify::Checker::new();
    /// c.counterexample("slerp(2, 1; 1) = 1 needs unit poses", 2.0f64.powf(0.0) == 2.0, "S0 = 2, S1 = 1");
    /// let out = c.finish();
    /// assert!(out.holds());
    /// assert!(out.notes[0].contains("S0 = 2"));
    /// ```
    pub fn counterexample(&mut self, what: impl Display, holds_without_hypothesis: bool, found: impl Display) -> bool {
        self.checks += 1;
        if holds_without_hypothesis {
            self.failures.push(format!("{what}: expected a counterexample ({found}) but the identity held"));
            false
        } else {
            self.notes.push(format!("counterexample: {what}: {found}"));
            true
        }
    }

    /// Unwraps a result, recording an error as a failure (a check never panics on bad luck).
    ///
    /// ```
    /// let mut c = gam_verify::Checker::new();
    /// assert_eq!(c.ok("parse", "4".parse::<i32>()), Some(4));
    /// assert_eq!(c.ok("parse", "x".parse::<i32>()), None);
    /// assert!(!c.finish().holds());
    /// ```
    pub fn ok<V, E: Display>(&mut self, what: impl Display, result: Result<V, E>) -> Option<V> {
        match result {
            Ok(v) => Some(v),
            Err(e) => {
                self.fail(format!("{what}: {e}"));
                None
            }
        }
    }

    /// Keeps a finding for the report.
    ///
    /// ```
    /// let mut c = gam_verify::Checker::new();
    /// c.note("printed value is rounded");
    /// assert_eq!(c.finish().notes.len(), 1);
    /// ```
    pub fn note(&mut self, text: impl Display) {
        self.notes.push(text.to_string());
    }

    /// The outcome.
    ///
    /// ```
    /// let mut c = gam_verify::Checker::new();
    /// c.check("ok", true);
    /// assert_eq!(c.finish().checks, 1);
    /// ```
    pub fn finish(self) -> Outcome {
        Outcome { checks: self.checks, failures: self.failures, notes: self.notes }
    }
}
