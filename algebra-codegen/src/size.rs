//! The size policy: a kernel with more terms than its module's threshold (default
//! [`TABLE_THRESHOLD`], the DSL's `table_above N;`) is emitted as a compact loop over a constant term
//! table instead of straight-line code, and so is every kernel over a type the module added on
//! its own (the full multivector, a parity type): the operands' types decide, so a product of
//! declared types landing in an added type stays straight-line code. Declaring the type
//! (`Odd = odd;`, `Multivector = all;`) gives it straight-line kernels.
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
/// // the text of the `GeometricProduct<Y> for X` impl
/// let gp2 = |code: &str, x: &str, y: &str| {
///     let head = format!("GeometricProduct < {y} < T >> for {x} < T >");
///     let body = &code[code.find(&head).unwrap()..];
///     body[..body[1..].find("impl").unwrap()].to_string()
/// };
/// let gp = |code: &str, x: &str| gp2(code, x, x);
/// assert_eq!(TABLE_THRESHOLD, 128);
/// // the 48-term motor product of G_{123inf} stays straight-line code ...
/// assert!(!gp(&code("g123inf", "Motor=even", TABLE_THRESHOLD), "Motor").contains("bilinear"));
/// // ... the 256-term motor product of R^{4,1} is a loop over a table by default, straight-line
/// // code under `table_above 256;`
/// assert!(gp(&code("cga", "Motor=even", TABLE_THRESHOLD), "Motor").contains("bilinear"));
/// assert!(!gp(&code("cga", "Motor=even", 256), "Motor").contains("bilinear"));
/// assert!(gp(&code("cga", "Motor=even", 255), "Motor").contains("bilinear"));
/// // ... and the 1024-term full product of a 5-generator algebra is a table at either
/// assert!(gp(&code("cga", "Multivector=all", 256), "Multivector").contains("bilinear"));
/// // the types a module adds on its own (here the full `Multivector` and `Odd` of a 3D PGA
/// // declaring planes and motors) get tables whatever their size; a product of declared
/// // types stays straight-line code when it lands in one of them (`Motor * Plane` is `Odd`)
/// let pga = code("pga3", "Plane=grade1;Motor=even", TABLE_THRESHOLD);
/// assert!(gp(&pga, "Odd").contains("bilinear"));
/// assert!(gp2(&pga, "Motor", "Multivector").contains("bilinear"));
/// assert!(!gp2(&pga, "Motor", "Plane").contains("bilinear"));
/// assert!(!gp(&pga, "Motor").contains("bilinear"));
/// ```
pub const TABLE_THRESHOLD: usize = 128;

/// Whether a kernel over the types `types` (indices into the plan's types, of which the first
/// `declared` were declared by the user, [`crate::plan::Plan::declared`]), with these
/// per-output (or per-stage) term counts, is table-driven: with more terms than `table_above`
/// ([`crate::ModuleSpec::table_above`]), or with any term at all when one of the types was
/// added by the module (the full multivector, a parity type). Those types exist so that every
/// product has a type; as straight-line code their kernels were 60 % of a 3D PGA module's
/// source and of its rebuild time (docs/performance.md, "Rebuilding a crate that declares an
/// algebra"). The Rust emitter and the other languages' emitters ask the same question, so a C
/// kernel adds in the Rust kernel's order.
pub(crate) fn table_driven<I: IntoIterator<Item = usize>>(
    table_above: usize,
    declared: usize,
    types: &[usize],
    lens: I,
) -> bool {
    let threshold = if types.iter().any(|&t| t >= declared) { 0 } else { table_above };
    lens.into_iter().sum::<usize>() > threshold
}
