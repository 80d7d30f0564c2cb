//! `gam prove` (shared/cli.md, "Wave 2 contract"): a multivector claim decided symbolically
//! under hypotheses by ideal membership over the rationals (algebra_core::ideal), plus the
//! relations `==` / `!=` of `gam eval` and `diff(x, v)`.
//!
//! A script is `let NAME = EXPR; ...; CLAIM` with `CLAIM` `EXPR = EXPR`. The builders
//! `even("P")`, `odd("P")`, `vector("P")`, `grade("P", k)` and `all("P")` are general elements
//! with coefficient symbols `P`, `P12`, ... (algebra_core's `Multivector::symbolic`); they are
//! replaced by bound names before the `gam eval` parser sees the text.

use crate::error::CliError;
use crate::eval::Evaluator;
use crate::expr::{self, Node};
use crate::scalar::{CliScalar, Failure, ScalarKind};
use algebra_core::ideal::{Budget, Decision, Hypotheses, IdealError, Limit, decide};
use algebra_core::multivector::symbolic::Part;
use algebra_core::rational::Q;
use algebra_core::{Algebra, Basis, Multivector, Poly, Ring};
use serde_json::{Value, json};
use std::collections::HashMap;
use std::sync::Arc;
use std::time::{Duration, Instant};

/// The options of `gam prove`.
#[derive(Debug, Clone)]
pub struct ProveArgs {
    /// `--algebra`.
    pub algebra: String,
    /// `--basis`.
    pub basis: Basis,
    /// `--assume`, each `EXPR = EXPR` or `EXPR != 0`.
    pub assume: Vec<String>,
    /// `--timeout` in seconds: the whole run (parsing, evaluation, Gröbner basis, normal
    /// forms, witness search) stops with "undecided" when it is spent.
    pub timeout: f64,
    /// `--max-basis`: the largest Gröbner basis ([`Budget::max_basis`]).
    pub max_basis: usize,
    /// `--max-terms`: the most terms of one polynomial ([`Budget::max_terms`]).
    pub max_terms: usize,
    /// `--json`.
    pub json: bool,
    /// `let ...; CLAIM`.
    pub claim: String,
}

/// `=`, `!=` or `==` between two expressions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Rel {
    Eq,
    EqEq,
    Ne,
}

/// Splits `text` at its one top-level relation (outside parentheses and string literals).
fn split_relation(text: &str) -> Result<Option<(String, Rel, String)>, CliError> {
    let chars: Vec<char> = text.chars().collect();
    let (mut depth, mut quoted, mut found) = (0i64, false, None);
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        match c {
            '"' => quoted = !quoted,
            '(' if !quoted => depth += 1,
            ')' if !quoted => depth -= 1,
            '=' | '!' if !quoted && depth == 0 => {
                let (rel, len) = match (c, chars.get(i + 1)) {
                    ('=', Some('=')) => (Rel::EqEq, 2),
                    ('!', Some('=')) => (Rel::Ne, 2),
                    ('=', _) => (Rel::Eq, 1),
                    _ => return Err(CliError::usage(format!("unexpected `!` at column {} (use `!=`)", i + 1))),
                };
                if found.is_some() {
                    return Err(CliError::usage(format!("a second relation at column {} in `{text}`", i + 1)));
                }
                found = Some((i, rel, len));
                i += len;
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    Ok(found.map(|(at, rel, len)| {
        let lhs: String = chars[..at].iter().collect();
        let rhs: String = chars[at + len..].iter().collect();
        (lhs, rel, rhs)
    }))
}

/// The builders of symbolic elements, by name.
fn builder_part(name: &str, grade: Option<usize>) -> Option<Part> {
    Some(match name {
        "even" => Part::Even,
        "odd" => Part::Odd,
        "vector" => Part::Grade(1),
        "all" => Part::All,
        "grade" => Part::Grade(grade?),
        _ => return None,
    })
}

const BUILDER_PREFIX: &str = "zzbuilder";

/// Script state: the algebra, the bound names and the builder count.
struct Script {
    deadline: Instant,
    algebra: Arc<Algebra>,
    basis: Basis,
    bindings: HashMap<String, Multivector<Poly>>,
    lets: Vec<String>,
    builders: usize,
}

impl Script {
    /// Replaces each builder call `name("P"[, k])` in `text` by a fresh bound name.
    fn expand_builders(&mut self, text: &str) -> Result<String, CliError> {
        if text.contains(BUILDER_PREFIX) {
            return Err(CliError::usage(format!("names starting with `{BUILDER_PREFIX}` are reserved")));
        }
        let chars: Vec<char> = text.chars().collect();
        let mut out = String::new();
        let mut i = 0;
        while i < chars.len() {
            if !chars[i].is_ascii_alphabetic()
                || (i > 0 && (chars[i - 1].is_ascii_alphanumeric() || chars[i - 1] == '_'))
            {
                out.push(chars[i]);
                i += 1;
                continue;
            }
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            let name: String = chars[start..i].iter().collect();
            let mut j = i;
            let skip = |j: &mut usize| {
                while *j < chars.len() && chars[*j].is_whitespace() {
                    *j += 1;
                }
            };
            skip(&mut j);
            let is_builder_call = chars.get(j) == Some(&'(') && {
                let mut k = j + 1;
                skip(&mut k);
                chars.get(k) == Some(&'"')
            };
            if !is_builder_call {
                out.push_str(&name);
                continue;
            }
            let close = chars[j..]
                .iter()
                .position(|&c| c == ')')
                .map(|p| p + j)
                .ok_or_else(|| CliError::usage(format!("unclosed call of `{name}` at column {}", start + 1)))?;
            let inner: String = chars[j + 1..close].iter().collect();
            let mut args = inner.split(',').map(str::trim);
            let prefix = args.next().unwrap_or("").trim_matches('"');
            let grade = args.next().map(|k| {
                k.parse::<usize>().map_err(|_| {
                    CliError::usage(format!("`{name}` at column {}: k must be a non-negative integer", start + 1))
                })
            });
            let grade = grade.transpose()?;
            let valid_prefix = prefix.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
                && prefix.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
            let part = builder_part(&name, grade).filter(|_| valid_prefix && args.next().is_none());
            let Some(part) = part else {
                return Err(CliError::usage(format!(
                    "bad builder `{name}({inner})` at column {}: use even(\"P\"), odd(\"P\"), vector(\"P\"), \
                     grade(\"P\", k) or all(\"P\") with P a name",
                    start + 1
                )));
            };
            let value = Multivector::<Poly>::symbolic(&self.algebra, self.basis, prefix, &part)
                .map_err(|e| CliError::usage(e.to_string()))?;
            let bound = format!("{BUILDER_PREFIX}{}", self.builders);
            self.builders += 1;
            self.bindings.insert(bound.clone(), value);
            out.push_str(&bound);
            i = close + 1;
        }
        Ok(out)
    }

    fn eval(&mut self, text: &str) -> Result<Multivector<Poly>, CliError> {
        let text = self.expand_builders(text)?;
        let ast = expr::parse(&text, &self.algebra)
            .map_err(|e| CliError::usage(format!("in `{}`: {}", text.trim(), e.message)))?;
        Evaluator::with_bindings(&self.algebra, self.basis, &self.bindings).until(self.deadline).eval::<Poly>(&ast)
    }

    fn define(&mut self, stmt: &str) -> Result<(), CliError> {
        let body = stmt.trim_start().strip_prefix("let").unwrap_or_default();
        let (name, rel, value) = split_relation(body)?
            .ok_or_else(|| CliError::usage(format!("`{}`: expected `let NAME = EXPR`", stmt.trim())))?;
        let name = name.trim().to_string();
        let is_name = name.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
            && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
        if rel != Rel::Eq || !is_name {
            return Err(CliError::usage(format!("`{}`: expected `let NAME = EXPR`", stmt.trim())));
        }
        if self.algebra.mask_of(&name).is_ok() || expr::Func::from_name(&name).is_some() {
            return Err(CliError::usage(format!("`let {name}`: {name} is a basis element or function name")));
        }
        if self.bindings.contains_key(&name) {
            return Err(CliError::usage(format!("`let {name}`: {name} is already defined")));
        }
        let v = self.eval(&value)?;
        self.bindings.insert(name.clone(), v);
        self.lets.push(name);
        Ok(())
    }

    /// `lhs - rhs`, and the relation.
    fn relation(&mut self, text: &str, what: &str) -> Result<(Multivector<Poly>, Rel), CliError> {
        let (lhs, rel, rhs) = split_relation(text)?
            .ok_or_else(|| CliError::usage(format!("{what} `{}` is not `EXPR = EXPR` or `EXPR != 0`", text.trim())))?;
        let (l, r) = (self.eval(&lhs)?, self.eval(&rhs)?);
        Ok((&l - &r, rel))
    }
}

/// The parsed problem: claim components and hypotheses.
struct Problem {
    claim: Vec<(String, Poly)>,
    hyps: Hypotheses,
}

fn parse_problem(args: &ProveArgs, deadline: Instant) -> Result<Problem, CliError> {
    let algebra = crate::budget::algebra(&args.algebra)?;
    let mut s =
        Script { deadline, algebra, basis: args.basis, bindings: HashMap::new(), lets: Vec::new(), builders: 0 };
    let stmts: Vec<&str> = args.claim.split(';').map(str::trim).filter(|t| !t.is_empty()).collect();
    let Some((claim, lets)) = stmts.split_last() else {
        return Err(CliError::usage("empty claim: expected `[let NAME = EXPR;]... EXPR = EXPR`"));
    };
    for stmt in lets {
        if !stmt.starts_with("let ") {
            return Err(CliError::usage(format!("`{stmt}`: only `let NAME = EXPR` may come before the claim")));
        }
        s.define(stmt)?;
    }
    if claim.starts_with("let ") {
        return Err(CliError::usage("the script ends with a `let`: the claim `EXPR = EXPR` must come last"));
    }
    let (diff, rel) = s.relation(claim, "the claim")?;
    if rel != Rel::Eq {
        return Err(CliError::usage("the claim must be an equation `EXPR = EXPR`"));
    }
    let mut hyps = Hypotheses::default();
    for a in &args.assume {
        let (d, rel) = s.relation(a, "--assume")?;
        match rel {
            Rel::Eq => hyps.equations.extend(d.components().into_iter().map(|(_, p)| p)),
            Rel::Ne => {
                if d.terms().any(|(m, _, _)| m != 0) {
                    return Err(CliError::usage(format!(
                        "--assume `{a}`: a non-vanishing hypothesis must be a scalar (`EXPR != 0`), got {d}"
                    )));
                }
                hyps.nonzero.push(d.scalar_part());
            }
            Rel::EqEq => return Err(CliError::usage(format!("--assume `{a}`: use `=` or `!=`, not `==`"))),
        }
    }
    let problem = Problem { claim: diff.components(), hyps };
    // A let name must not also be a symbol of the claim or hypotheses.
    let symbols: std::collections::HashSet<String> = problem
        .claim
        .iter()
        .map(|(_, p)| p)
        .chain(&problem.hyps.equations)
        .chain(&problem.hyps.nonzero)
        .flat_map(Poly::variables)
        .collect();
    let symbols_of_lets: std::collections::HashSet<String> = s
        .lets
        .iter()
        .flat_map(|l| s.bindings[l].coeffs().iter().flat_map(Poly::variables).collect::<Vec<_>>())
        .collect();
    if let Some(clash) = s.lets.iter().find(|l| symbols.contains(*l) || symbols_of_lets.contains(*l)) {
        return Err(CliError::usage(format!("`let {clash}`: {clash} is also a coefficient symbol")));
    }
    Ok(problem)
}

/// A rational point (small integers) where `p != 0` and every `nonzero` hypothesis is non-zero;
/// only meaningful when there are no equations. Each attempt evaluates the polynomials once
/// ([`Poly::evaluate`], linear in their size); the search stops at `deadline`.
fn witness_point(p: &Poly, nonzero: &[Poly], deadline: Instant) -> Option<Vec<(String, i64)>> {
    let mut vars: Vec<String> = std::iter::once(p).chain(nonzero).flat_map(Poly::variables).collect();
    vars.sort();
    vars.dedup();
    (0..40i64).find_map(|attempt| {
        if Instant::now() > deadline {
            return None;
        }
        let point: HashMap<&str, i64> =
            vars.iter().enumerate().map(|(i, v)| (v.as_str(), ((i as i64 * 7 + attempt * 3) % 11) - 5)).collect();
        let at = |q: &Poly| q.evaluate(|v| point.get(v).and_then(|x| Poly::from_i64(*x).as_constant()));
        let non_zero = |q: &Poly| at(q).is_some_and(|x| x != 0);
        let ok = non_zero(p) && nonzero.iter().all(non_zero);
        ok.then(|| vars.iter().map(|v| (v.clone(), point[v.as_str()])).collect())
    })
}

fn witness(problem: &Problem, d: &Decision, deadline: Instant) -> Value {
    let Some((i, nf)) = d.failures.first() else { return Value::Null };
    let (component, poly) = &problem.claim[*i];
    let mut w = json!({"component": component, "normal_form": nf.to_string()});
    if problem.hyps.equations.is_empty()
        && let Some(point) = witness_point(poly, &problem.hyps.nonzero, deadline)
    {
        let map: serde_json::Map<String, Value> = point.into_iter().map(|(v, x)| (v, json!(x))).collect();
        w["point"] = Value::Object(map);
    }
    w
}

/// The output of `gam prove` when a budget ran out (exit 1 after printing it); `options`: the
/// limit is one of the budget's options (not the engine's largest degree).
fn undecided(args: &ProveArgs, reason: &str, options: bool) -> (String, Option<CliError>) {
    let out = if args.json {
        json!({"holds": false, "undecided": true, "method": "groebner", "basis_size": null,
               "time_ms": null, "witness": null, "reason": reason})
        .to_string()
    } else {
        format!("undecided: {reason}")
    };
    let hint = if options { " (raise --timeout, --max-basis or --max-terms)" } else { "" };
    (out, Some(CliError::math(format!("{reason}{hint}"))))
}

/// `gam prove`: the output, and the failure (exit 1) to report after printing it.
pub fn prove(args: &ProveArgs) -> Result<(String, Option<CliError>), CliError> {
    let start = Instant::now();
    if !(args.timeout.is_finite() && args.timeout > 0.0) {
        return Err(CliError::usage(format!("--timeout must be a positive number of seconds, got {}", args.timeout)));
    }
    if args.max_basis == 0 || args.max_terms == 0 {
        return Err(CliError::usage("--max-basis and --max-terms must be positive"));
    }
    let limit = Duration::from_secs_f64(args.timeout.min(1e6));
    let deadline = start + limit;
    let problem = match parse_problem(args, deadline) {
        Ok(p) => p,
        Err(e) if crate::eval::is_timeout(&e) => return Ok(undecided(args, &e.message, true)),
        Err(e) => return Err(e),
    };
    let remaining = deadline.saturating_duration_since(Instant::now());
    let budget = Budget { time: Some(remaining), max_basis: args.max_basis, max_terms: args.max_terms };
    let claims: Vec<Poly> = problem.claim.iter().map(|(_, p)| p.clone()).collect();
    let d = match decide(&claims, &problem.hyps, &budget) {
        Ok(d) => d,
        Err(IdealError::Undecided { limit: which, .. }) => {
            let e = IdealError::Undecided { limit: which, elapsed_ms: start.elapsed().as_millis() };
            return Ok(undecided(args, &e.to_string(), which != Limit::Degree));
        }
        Err(e) => return Err(CliError::usage(e.to_string())),
    };
    let w = witness(&problem, &d, deadline);
    let out = if args.json {
        json!({"holds": d.holds, "method": "groebner", "basis_size": d.basis_size, "time_ms": d.time_ms,
               "witness": w, "components": problem.claim.len(), "inconsistent": d.inconsistent})
        .to_string()
    } else if d.holds {
        let vacuous = if d.inconsistent { "; the hypotheses are inconsistent, so it holds vacuously" } else { "" };
        format!(
            "holds: all {} components follow from the hypotheses (groebner, basis of {} polynomials, {} ms{vacuous})",
            problem.claim.len(),
            d.basis_size,
            d.time_ms
        )
    } else {
        let lines: Vec<String> =
            d.failures.iter().map(|(i, nf)| format!("  component {}: normal form {nf}", problem.claim[*i].0)).collect();
        let point = w.get("point").map(|p| format!("\n  witness point: {p}")).unwrap_or_default();
        format!(
            "does not hold: {} of {} components are not in the ideal of the hypotheses (groebner, basis of {} polynomials, {} ms)\n{}{point}",
            d.failures.len(),
            problem.claim.len(),
            d.basis_size,
            d.time_ms,
            lines.join("\n")
        )
    };
    let failure = (!d.holds).then(|| CliError::math("the claim does not follow from the hypotheses"));
    Ok((out, failure))
}

/// `gam eval` with a relation `A == B` or `A != B` (exact scalars only): prints `true` or
/// `false` (JSON: `{"value": ...}`), and fails with exit 1 when the relation is false. `None`
/// when `expr` has no relation (an ordinary `gam eval`).
pub fn eval_relation(
    algebra: &str,
    basis: Basis,
    scalar: &ScalarKind,
    json: bool,
    text: &str,
) -> Option<Result<(String, Option<CliError>), CliError>> {
    let (lhs, rel, rhs) = match split_relation(text) {
        Ok(Some(parts)) => parts,
        Ok(None) => return None,
        Err(e) => return Some(Err(e)),
    };
    Some((|| {
        if rel == Rel::Eq {
            return Err(CliError::usage("`=` is not an expression: compare with `==` or `!=`"));
        }
        let alg = crate::budget::algebra(algebra)?;
        let (l, r) = (expr::parse(&lhs, &alg)?, expr::parse(&rhs, &alg)?);
        let ev = Evaluator::new(&alg, basis);
        let equal = match scalar {
            ScalarKind::Poly => (&ev.eval::<Poly>(&l)? - &ev.eval::<Poly>(&r)?).is_zero(),
            ScalarKind::Rational => (&ev.eval::<Q>(&l)? - &ev.eval::<Q>(&r)?).is_zero(),
            _ => return Err(CliError::usage("`==` and `!=` need an exact scalar: --scalar poly or rational")),
        };
        let value = equal == (rel == Rel::EqEq);
        let out = if json { json!({"value": value}).to_string() } else { value.to_string() };
        Ok((out, (!value).then(|| CliError::math("the relation is false"))))
    })())
}

/// `diff(x, v)`: every coefficient of `x` differentiated by the variable `v`.
pub fn differentiate<T: CliScalar>(x: &Multivector<T>, var: &Node, col: usize) -> Result<Multivector<T>, CliError> {
    let Node::Ident { name, .. } = var else {
        return Err(CliError::usage(format!("diff at column {col}: the second argument must be a variable name")));
    };
    let coeffs =
        x.coeffs().iter().map(|c| c.derivative(name)).collect::<Result<Vec<T>, Failure>>().map_err(|f| match f {
            Failure::Unsupported(why) => {
                CliError::usage(format!("diff at column {col} is not available for --scalar {}: {why}", T::NAME))
            }
            Failure::Math(why) => CliError::math(format!("diff at column {col}: {why}")),
        })?;
    Multivector::from_coeffs(x.algebra(), x.basis(), coeffs).map_err(|e| CliError::math(e.to_string()))
}
