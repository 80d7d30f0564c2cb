//! Precomputed constrained kernels: the reduced term lists of the kernels the predefined
//! modules declare, committed as text (`precomputed.txt`), so the `algebra!` macro emits them
//! without GMP (the reduction needs `rug`). Each entry is keyed by everything the kernel
//! depends on (operation, basis, metric, the two types' elements and constraints);
//! `algebra-codegen`'s test `constraint_table` recomputes every entry with the Gröbner
//! reduction and fails when the file is stale (regenerate with `BLESS=1`).
//!
//! Format, one entry:
//! ```text
//! kernel <key>
//! left <monomial> ...           shared left monomials, `i^e*j^f`
//! out <mask> <n/d@L@R> ...      L: left monomial index or `-`; R: right monomial or `1`
//! vanishing <mask> ...
//! full <outputs> <terms> <mul> <setup_mul> <apply_mul> <add> <mask> ...
//! end
//! ```

use super::{ConstrainedKernel, ConstraintError, Counts, KTerm, Monomial, Request};
use crate::ModuleSpec;
use algebra_core::rational::format_rational;
use std::fmt::Write;

/// The committed table.
pub const PRECOMPUTED: &str = include_str!("precomputed.txt");

/// The key of a kernel request: operation, basis, metric, and the two types' elements and
/// constraints (names are not part of it).
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::ModuleSpec;
/// use algebra_codegen::constraint::{KernelOp, Request, table};
/// let alg = Algebra::builtin("g3").unwrap();
/// let types = ModuleSpec::parse_types("Rotor=even where unit;Vector=grade1", &alg).unwrap();
/// let spec = ModuleSpec::new("g3", alg.metric().clone(), Basis::Blade, types).unwrap();
/// let key = table::key(&spec, Request { op: KernelOp::Sandwich, left: 0, right: 1 });
/// assert!(key.starts_with("sandwich blade labels=1,2,3") && key.ends_with("right=1,2,4:-"));
/// ```
pub fn key(spec: &ModuleSpec, r: Request) -> String {
    let metric = spec.algebra.metric();
    let n = metric.labels().len();
    let gram: Vec<String> = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| format_rational(metric.gram(i, j).expect("indices below the metric's size")))
                .collect::<Vec<_>>()
                .join(",")
        })
        .collect();
    let ty = |t: usize| {
        let els: Vec<String> = spec.types[t].elements.iter().map(u32::to_string).collect();
        format!("{}:{}", els.join(","), spec.types[t].constraint.map_or("-", |k| k.keyword()))
    };
    format!(
        "{} {} labels={} gram={} left={} right={}",
        r.op.name(),
        spec.basis,
        metric.labels().join(","),
        gram.join(";"),
        ty(r.left),
        ty(r.right)
    )
}

fn mono_text(m: &[(usize, u32)]) -> String {
    if m.is_empty() {
        return "1".to_string();
    }
    m.iter().map(|(i, e)| format!("{i}^{e}")).collect::<Vec<_>>().join("*")
}

/// One table entry for a kernel (the spec-dependent fields — type indices, names, output
/// types — are recomputed when read).
pub fn entry(key: &str, k: &ConstrainedKernel) -> String {
    let mut s = format!("kernel {key}\nleft");
    for m in &k.left_monomials {
        write!(s, " {}", mono_text(m)).expect("string");
    }
    for (mask, ts) in &k.outputs {
        write!(s, "\nout {mask}").expect("string");
        for t in ts {
            let l = t.left.map_or_else(|| "-".to_string(), |i| i.to_string());
            write!(s, " {}/{}@{l}@{}", t.coeff.0, t.coeff.1, mono_text(&t.right)).expect("string");
        }
    }
    s.push_str("\nvanishing");
    for m in &k.vanishing {
        write!(s, " {m}").expect("string");
    }
    let f = k.full.counts;
    write!(s, "\nfull {} {} {} {} {} {}", f.outputs, f.terms, f.mul, f.setup_mul, f.apply_mul, f.add).expect("string");
    for m in &k.full.masks {
        write!(s, " {m}").expect("string");
    }
    s.push_str("\nend\n");
    s
}

fn bad(what: &str) -> ConstraintError {
    ConstraintError::BadTable(what.to_string())
}

fn number<T: std::str::FromStr>(s: &str) -> Result<T, ConstraintError> {
    s.parse().map_err(|_| bad(&format!("`{s}` is not a number")))
}

fn parse_mono(s: &str) -> Result<Monomial, ConstraintError> {
    if s == "1" {
        return Ok(Vec::new());
    }
    s.split('*')
        .map(|f| {
            let (i, e) = f.split_once('^').ok_or_else(|| bad(&format!("monomial factor `{f}`")))?;
            Ok((number(i)?, number(e)?))
        })
        .collect()
}

fn parse_term(s: &str) -> Result<KTerm, ConstraintError> {
    let mut parts = s.split('@');
    let (Some(c), Some(l), Some(r), None) = (parts.next(), parts.next(), parts.next(), parts.next()) else {
        return Err(bad(&format!("term `{s}`")));
    };
    let (n, d) = c.split_once('/').ok_or_else(|| bad(&format!("coefficient `{c}`")))?;
    let left = if l == "-" { None } else { Some(number(l)?) };
    Ok(KTerm { coeff: (number(n)?, number(d)?), left, right: parse_mono(r)? })
}

/// Parses one entry's lines after `kernel <key>` (up to `end`).
fn parse_entry<'a>(lines: &mut impl Iterator<Item = &'a str>) -> Result<ConstrainedKernel, ConstraintError> {
    let mut k = ConstrainedKernel::empty();
    for line in lines.by_ref() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("left") => k.left_monomials = words.map(parse_mono).collect::<Result<_, _>>()?,
            Some("out") => {
                let mask = number(words.next().ok_or_else(|| bad("`out` without a mask"))?)?;
                k.outputs.push((mask, words.map(parse_term).collect::<Result<_, _>>()?));
            }
            Some("vanishing") => k.vanishing = words.map(number).collect::<Result<_, _>>()?,
            Some("full") => {
                let v: Vec<usize> = words.map(number).collect::<Result<_, _>>()?;
                let [outputs, terms, mul, setup_mul, apply_mul, add, ..] = v[..] else {
                    return Err(bad("`full` needs six counts"));
                };
                k.full.counts = Counts { outputs, terms, mul, setup_mul, apply_mul, add };
                k.full.masks = v[6..].iter().map(|&m| m as u32).collect();
            }
            Some("end") => return Ok(k),
            _ => return Err(bad(&format!("unexpected line `{line}`"))),
        }
    }
    Err(bad("entry without `end`"))
}

/// The kernel stored under `key` in `table` (its spec-dependent fields unset), if any.
///
/// ```
/// use algebra_codegen::constraint::table::{PRECOMPUTED, lookup};
/// assert!(lookup(PRECOMPUTED, "no such key").unwrap().is_none());
/// ```
///
/// # Errors
/// [`ConstraintError::BadTable`] when the entry does not parse.
pub fn lookup(table: &str, key: &str) -> Result<Option<ConstrainedKernel>, ConstraintError> {
    let mut lines = table.lines();
    while let Some(line) = lines.next() {
        if line.strip_prefix("kernel ") == Some(key) {
            return parse_entry(&mut lines).map(Some);
        }
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_entry_parses_and_round_trips() {
        let mut lines = PRECOMPUTED.lines();
        let mut regenerated = String::new();
        while let Some(line) = lines.next() {
            let key = line.strip_prefix("kernel ").expect("an entry starts with `kernel`");
            let k = parse_entry(&mut lines).unwrap();
            assert_eq!(lookup(&entry(key, &k), key).unwrap().unwrap(), k);
            regenerated.push_str(&entry(key, &k));
        }
        assert!(!regenerated.is_empty());
        assert_eq!(regenerated, PRECOMPUTED);
    }

    #[test]
    fn malformed_entries_are_typed_errors() {
        for text in [
            "kernel k\nout x\nend\n",
            "kernel k\nout 1 1/1@-\nend\n",
            "kernel k\nleft 1^1\n",
            "kernel k\nfull 1 2\nend\n",
        ] {
            assert!(matches!(lookup(text, "k"), Err(ConstraintError::BadTable(_))), "{text}");
        }
    }
}
