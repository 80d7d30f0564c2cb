//! The size policy: a kernel with more terms than its module's threshold (default
//! [`TABLE_THRESHOLD`], the DSL's `table_above N;`) is emitted as a compact loop over a constant term
//! table instead of straight-line code.
//!
//! Straight-line code is fastest for the small kernels users call in loops (motor products,
//! versor actions), but a dense 5-generator product (`Multivector * Multivector`: 1024 terms)
//! unrolled for a big-number scalar is megabytes of inlined arithmetic and drop glue that takes
//! minutes to compile. The table form is a few lines per kernel whatever the scalar, and
//! computes the same sum term by term (exact over rationals, with the same constants).

/// The default threshold: kernels with more terms than this are table-driven (a module may
/// choose another with the DSL's `table_above N;`, [`crate::ModuleSpec::table_above`] or
/// `gam codegen --table-above N`).
///
/// 128 (was 64) from the measurements of docs/performance.md ("Size policy threshold"): at f64
/// straight-line code runs the 65-256-term kernels of `cga` (R^{4,1}) 4.7-9 × faster than the
/// table loop, and unrolling up to 128 terms costs the probe crate (the full 5-generator CGA)
/// about 10 % more compile time, while 256 costs 40-50 % (about 5 s of CPU: the 5 s target) and
/// doubles the compile time of a crate instantiating the 256-term kernels for `BigRational`.
/// The predefined `cga` module of `gam-algebras` declares `table_above 256;` (its motor product
/// and actions are the kernels users call in loops).
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, emit, plan::Plan, size::TABLE_THRESHOLD};
/// let code = |name: &str, types: &str, table_above: usize| {
///     let alg = Algebra::builtin(name).unwrap();
///     let types = ModuleSpec::parse_types(types, &alg).unwrap();
///     let mut spec = ModuleSpec::new(name, alg.metric().clone(), Basis::Blade, types).unwrap();
///     spec.table_above = table_above;
///     emit::module(&Plan::new(spec).unwrap()).to_string()
/// };
/// // the text of the `GeometricProduct<X> for X` impl
/// let gp = |code: &str, x: &str| {
///     let head = format!("GeometricProduct < {x} < T >> for {x} < T >");
///     let body = &code[code.find(&head).unwrap()..];
///     body[..body[1..].find("impl").unwrap()].to_string()
/// };
/// assert_eq!(TABLE_THRESHOLD, 128);
/// // the 48-term motor product of G_{123inf} stays straight-line code ...
/// assert!(!gp(&code("g123inf", "Motor=even", TABLE_THRESHOLD), "Motor").contains("TERMS"));
/// // ... the 256-term motor product of R^{4,1} is a loop over a table by default, straight-line
/// // code under `table_above 256;`
/// assert!(gp(&code("cga", "Motor=even", TABLE_THRESHOLD), "Motor").contains("const TERMS"));
/// assert!(!gp(&code("cga", "Motor=even", 256), "Motor").contains("TERMS"));
/// assert!(gp(&code("cga", "Motor=even", 255), "Motor").contains("const TERMS"));
/// // ... and the 1024-term full product of a 5-generator algebra is a table at either
/// assert!(gp(&code("cga", "Multivector=all", 256), "Multivector").contains("const TERMS"));
/// ```
pub const TABLE_THRESHOLD: usize = 128;

/// Whether a kernel with these per-output term counts is table-driven under the threshold
/// `table_above` ([`crate::ModuleSpec::table_above`]).
pub(crate) fn is_large<I: IntoIterator<Item = usize>>(table_above: usize, lens: I) -> bool {
    lens.into_iter().sum::<usize>() > table_above
}
