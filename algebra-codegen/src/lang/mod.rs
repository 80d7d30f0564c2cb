//! Kernels in other languages: the plan's kernels ([`kernels`], language-free [`ir`] programs) printed as
//! a C99 header ([`c`]), WGSL ([`wgsl`]) or GLSL 4.50 ([`glsl`]) source. The Rust module is
//! [`crate::emit::module`]; this module depends on the plan only, and each language is one
//! file implementing [`Dialect`].
//!
//! Every language gets the same items from the same declaration:
//! - each declared type (and the fallback types the plan adds) as a struct of scalars, the
//!   fields in the declared order (the `repr(C)` layout of the Rust type);
//! - every product of every ordered pair of declared types (of every type with
//!   [`Options::every_type`]) (`{m}_{lhs}_{op}_{rhs}`), the unary maps
//!   (`{m}_{type}_{reverse}`...) and `{m}_{type}_norm_squared`;
//! - the fused versor actions `{m}_{versor}_{sandwich|apply}_{operand}` and the unit-versor
//!   forms `..._{sandwich_unit|apply_unit}_...`;
//! - the closed forms `{m}_{bivector}_exp`, `{m}_{even}_log_unit` and `{m}_{even}_normalize`
//!   where the generator finds them for the trigonometric families (rotors, PGA motors, dual
//!   quaternions; `lang::closed`), with the helpers `{m}_exp_factors` and `{m}_log_factors`.
//!
//! `{m}` is the module name, `{lhs}` a type's name in snake case. C has a `double` and a
//! `float` version of everything (the `float` names end in `f`: `pga_Motorf`,
//! `pga_motor_gp_motorf`); WGSL and GLSL are `f32`/`float` only.
//!
//! ```
//! use algebra_core::{Algebra, Basis};
//! use algebra_codegen::{ModuleSpec, plan::Plan, lang::{Lang, Options, emit}};
//! let alg = Algebra::builtin("pga3").unwrap();
//! let types = ModuleSpec::parse_types("Motor=even;Point=grade3", &alg).unwrap();
//! let plan = Plan::new(ModuleSpec::new("pga", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
//! let c = emit(&plan, Lang::C, &Options::default()).unwrap();
//! assert!(c.contains("static inline pga_Point pga_motor_apply_unit_point(pga_Motor s, pga_Point x)"));
//! let wgsl = emit(&plan, Lang::Wgsl, &Options::default()).unwrap();
//! assert!(wgsl.contains("fn pga_motor_gp_motor(a: pga_Motor, b: pga_Motor) -> pga_Motor"));
//! ```

pub mod c;
mod closed;
pub mod glsl;
mod helpers;
pub mod ir;
mod linear;
pub mod wgsl;

use crate::CodegenError;
use crate::naming::{field_name, snake};
use crate::plan::{Plan, Ratio};
use ir::{Expr, Kernel, Op, Output};
use std::collections::BTreeSet;
use std::fmt::Write;

/// A target language other than Rust.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Lang {
    /// One C99 header: `static inline` functions, structs passed by value, `double` and
    /// `float` versions; no dependency (not even `<math.h>` for these kernels).
    C,
    /// WGSL (`f32`), for wgpu and the browsers' WebGPU.
    Wgsl,
    /// GLSL 4.50 (`float`), for Vulkan and OpenGL shaders.
    Glsl,
}

/// A scalar type of the emitted code.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scalar {
    /// IEEE double.
    F64,
    /// IEEE single.
    F32,
}

/// What to emit.
#[derive(Debug, Clone, Default)]
pub struct Options {
    /// Only the kernels of these operations (their [`Op::name`]s: `gp`, `op`, `apply`,
    /// `apply_unit`, `reverse`, `norm_squared`, ...); `None` for every kernel.
    pub ops: Option<BTreeSet<String>>,
    /// Comment lines at the top of the file (e.g. the command that regenerates it).
    pub header: Vec<String>,
    /// Kernels of every type, also those taking the types the plan adds (automatic
    /// `Even`/`Odd`, the full multivector) as parameters; by default only kernels among the
    /// declared types (the added types still appear as structs, as results).
    pub every_type: bool,
}

/// How one language writes the pieces of a kernel file.
pub trait Dialect {
    /// The scalar types emitted, in order.
    fn scalars(&self) -> &'static [Scalar];
    /// The scalar type's name (`double`, `float`, `f32`).
    fn scalar(&self, s: Scalar) -> &'static str;
    /// The suffix of every type and function name of the scalar (`f` for C's `float`).
    fn suffix(&self, s: Scalar) -> &'static str;
    /// A comment line.
    fn comment(&self, text: &str) -> String;
    /// The file's first lines (after the header comments): guards, includes.
    fn prologue(&self, module: &str) -> String;
    /// The file's last lines.
    fn epilogue(&self, module: &str) -> String;
    /// A literal of the scalar type (non-negative; the printer parenthesises negation).
    fn literal(&self, s: Scalar, value: &str) -> String;
    /// A struct definition.
    fn structure(&self, s: Scalar, name: &str, fields: &[String]) -> String;
    /// A function: signature, the locals `t0, t1, ...`, and the result (a struct built from
    /// its fields' expressions, or a scalar).
    fn function(&self, s: Scalar, f: &Function<'_>) -> String;
    /// The name of a math function (`sqrt`, `sin`, `cos`, `atan2`) at the scalar type.
    fn math(&self, s: Scalar, f: &str) -> String;
    /// The type of three scalars the closed-form helpers return (read as `.x`, `.y`, `.z`).
    fn triple(&self, s: Scalar, module: &str) -> String;
    /// The definition of [`Self::triple`], if the language needs one.
    fn triple_def(&self, s: Scalar, module: &str) -> String;
    /// `let name = value;` for a local of type `ty`.
    fn local(&self, ty: &str, name: &str, value: &str) -> String;
    /// The return of three scalars as [`Self::triple`].
    fn return_triple(&self, s: Scalar, module: &str, values: [&str; 3]) -> String;
    /// A helper's signature line (up to the opening brace): scalar parameters, a triple result.
    fn helper_head(&self, s: Scalar, module: &str, name: &str, params: &[&str]) -> String;
}

/// One function ready to print: every expression already written in the language.
pub struct Function<'a> {
    /// The function's name.
    pub name: String,
    /// `(parameter name, type name)`.
    pub params: Vec<(&'static str, String)>,
    /// The return type's name (the struct built from [`Self::fields`], or the scalar).
    pub ret: String,
    /// The locals' types and expressions (`t0`, `t1`, ...).
    pub lets: Vec<(String, String)>,
    /// The result struct's field names, `None` when the result is a scalar.
    pub fields: Option<&'a [String]>,
    /// The result: one expression per field, or the scalar.
    pub values: Vec<String>,
    /// The doc line.
    pub doc: &'a str,
    /// The parameters the function does not read (a structurally zero product).
    pub unused: Vec<&'static str>,
}

/// The source of a plan's kernels in `lang`.
///
/// # Errors
/// [`CodegenError`] when a kernel cannot be planned (a constant beyond 64 bits).
pub fn emit(plan: &Plan, lang: Lang, options: &Options) -> Result<String, CodegenError> {
    match lang {
        Lang::C => render(plan, &c::C, options),
        Lang::Wgsl => render(plan, &wgsl::Wgsl, options),
        Lang::Glsl => render(plan, &glsl::Glsl, options),
    }
}

/// Every kernel of a plan, in the order of the Rust module: the binary products (every pair
/// of types, every product), the unary maps and norms per type, the fused actions and the
/// unit-versor actions (`lang::linear`), then the closed forms (`exp`, `log_unit`, `normalize`;
/// `lang::closed`). Pairs without a fused action (a versor type on the full multivector) have no
/// action kernel: compose two geometric products.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, plan::Plan, lang::kernels};
/// let alg = Algebra::builtin("pga3").unwrap();
/// let types = ModuleSpec::parse_types("Motor=even;Point=grade3;Line=grade2", &alg).unwrap();
/// let plan = Plan::new(ModuleSpec::new("pga", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
/// let ks = kernels(&plan).unwrap();
/// let apply = ks.iter().find(|k| k.op.name() == "apply_unit" && k.params == [0, 1]).unwrap();
/// assert_eq!(apply.lets.len(), 7); // the commutator's four intermediates and three corrections
/// assert!(ks.iter().any(|k| k.op.name() == "exp" && k.params == [2]));
/// ```
///
/// # Errors
/// [`CodegenError`] when a kernel cannot be planned (a constant beyond 64 bits).
pub fn kernels(plan: &Plan) -> Result<Vec<Kernel>, CodegenError> {
    let mut out = linear::kernels(plan)?;
    out.extend(closed::kernels(plan)?);
    Ok(out)
}

/// The parameter names of a kernel (`a, b` for products, `s, x` for actions, `x` for unary).
fn param_names(op: &Op) -> &'static [&'static str] {
    match op {
        Op::Product(_) => &["a", "b"],
        Op::Action(_) | Op::UnitAction(_) => &["s", "x"],
        Op::Unary(_) | Op::NormSquared | Op::Exp | Op::LogUnit | Op::Normalize => &["x"],
    }
}

/// The kernel's function name without the scalar suffix: `{m}_{lhs}_{op}[_{rhs}]`.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, plan::Plan, lang::{function_name, kernels}};
/// let alg = Algebra::builtin("g3").unwrap();
/// let types = ModuleSpec::parse_types("Rotor=even;Vector=grade1", &alg).unwrap();
/// let plan = Plan::new(ModuleSpec::new("g3", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
/// let names: Vec<String> = kernels(&plan).unwrap().iter().map(|k| function_name(&plan, k)).collect();
/// assert!(names.contains(&"g3_rotor_sandwich_vector".to_string()));
/// assert!(names.contains(&"g3_vector_norm_squared".to_string()));
/// ```
pub fn function_name(plan: &Plan, k: &Kernel) -> String {
    let ty = |i: usize| snake(&plan.spec.types[i].name);
    match k.params.as_slice() {
        [x] => format!("{}_{}_{}", plan.spec.name, ty(*x), k.op.name()),
        [l, r] => format!("{}_{}_{}_{}", plan.spec.name, ty(*l), k.op.name(), ty(*r)),
        _ => unreachable!("kernels have one or two parameters"),
    }
}

/// The struct name of a type without the scalar suffix: `{m}_{Type}`.
pub fn type_name(plan: &Plan, i: usize) -> String {
    format!("{}_{}", plan.spec.name, plan.spec.types[i].name)
}

/// The field names of every type, in storage order (`scalar` for `1`, else the basis name as
/// declared, e.g. `e31`): the structs' fields in every language.
pub fn field_names(plan: &Plan) -> Vec<Vec<String>> {
    let alg = &plan.spec.algebra;
    plan.spec.types.iter().map(|t| t.element_names(alg).iter().map(|n| field_name(n)).collect()).collect()
}

/// `n / d` rounded once to the scalar, as the shortest decimal that reads back to it (the
/// value `T::from_ratio(n, d)` of the Rust kernels: `n as f64 / d as f64`, then `as f32`).
fn decimal(s: Scalar, (n, d): Ratio) -> String {
    let v = n.unsigned_abs() as f64 / d as f64;
    let text = match s {
        Scalar::F64 => format!("{v:?}"),
        Scalar::F32 => format!("{:?}", v as f32),
    };
    if text.contains(['.', 'e']) { text } else { format!("{text}.0") }
}

/// What [`expr`] needs to print names.
struct Names<'a> {
    module: &'a str,
    suffix: &'a str,
    params: &'a [&'a str],
    fields: &'a [&'a [String]],
}

fn expr(d: &dyn Dialect, s: Scalar, e: &Expr, n: &Names<'_>) -> String {
    let go = |e: &Expr| expr(d, s, e, n);
    match e {
        Expr::Field { param, field } => format!("{}.{}", n.params[*param], n.fields[*param][*field]),
        Expr::Local(i) => format!("t{i}"),
        Expr::Const(c) if c.0 < 0 => format!("(-{})", d.literal(s, &decimal(s, *c))),
        Expr::Const(c) => d.literal(s, &decimal(s, *c)),
        Expr::Add(a, b) => format!("({} + {})", go(a), go(b)),
        Expr::Sub(a, b) => format!("({} - {})", go(a), go(b)),
        Expr::Mul(a, b) => format!("({} * {})", go(a), go(b)),
        Expr::Div(a, b) => format!("({} / {})", go(a), go(b)),
        Expr::Neg(a) => format!("(-{})", go(a)),
        Expr::Sqrt(a) => format!("{}({})", d.math(s, "sqrt"), bare(go(a))),
        Expr::Call(h, args) => {
            let args: Vec<String> = args.iter().map(|a| bare(go(a))).collect();
            format!("{}_{}{}({})", n.module, h.name(), n.suffix, args.join(", "))
        }
        Expr::Part(i, j) => format!("t{i}.{}", ["x", "y", "z"][*j]),
    }
}

/// The helper a local calls, if any.
fn call(e: &Expr) -> Option<ir::Helper> {
    match e {
        Expr::Call(h, _) => Some(*h),
        _ => None,
    }
}

/// Drops the outermost parentheses of a printed expression, when they enclose all of it.
fn bare(e: String) -> String {
    if !(e.starts_with('(') && e.ends_with(')')) {
        return e;
    }
    let mut depth = 0;
    for (i, ch) in e.char_indices() {
        match ch {
            '(' => depth += 1,
            ')' => depth -= 1,
            _ => {}
        }
        if depth == 0 && i + 1 < e.len() {
            return e;
        }
    }
    e[1..e.len() - 1].to_string()
}

fn render(plan: &Plan, d: &dyn Dialect, options: &Options) -> Result<String, CodegenError> {
    let kernels: Vec<Kernel> = self::kernels(plan)?
        .into_iter()
        .filter(|k| options.ops.as_ref().is_none_or(|ops| ops.contains(k.op.name())))
        .filter(|k| options.every_type || k.params.iter().all(|&p| p < plan.declared))
        .collect();
    let fields = field_names(plan);
    let module = &plan.spec.name;
    // the declared types, and the added ones the emitted kernels take or return
    let mut used: BTreeSet<usize> = (0..plan.declared).collect();
    for k in &kernels {
        used.extend(&k.params);
        if let Output::Type(o, _) = &k.output {
            used.insert(*o);
        }
    }
    let helpers: BTreeSet<ir::Helper> = kernels.iter().flat_map(|k| k.lets.iter().filter_map(call)).collect();
    let mut out = String::new();
    for line in &options.header {
        out.push_str(&d.comment(line));
    }
    out.push_str(&d.prologue(module));
    for &s in d.scalars() {
        let sfx = d.suffix(s);
        for (i, f) in fields.iter().enumerate().filter(|(i, _)| used.contains(i)) {
            let t = &plan.spec.types[i];
            for line in &t.doc {
                out.push_str(&d.comment(line.trim()));
            }
            out.push_str(&d.comment(&format!("{}: the coefficients of {}.", t.name, f.join(", "))));
            out.push_str(&d.structure(s, &format!("{}{sfx}", type_name(plan, i)), f));
            out.push('\n');
        }
        if !helpers.is_empty() {
            out.push_str(&d.triple_def(s, module));
            for &h in &helpers {
                out.push_str(&helpers::text(d, s, module, h));
                out.push('\n');
            }
        }
        for k in &kernels {
            let params = param_names(&k.op);
            let pf: Vec<&[String]> = k.params.iter().map(|&i| fields[i].as_slice()).collect();
            let names = Names { module, suffix: sfx, params, fields: &pf };
            let print = |e: &Expr| bare(expr(d, s, e, &names));
            let (ret, result_fields, values) = match &k.output {
                Output::Type(o, es) => (
                    format!("{}{sfx}", type_name(plan, *o)),
                    Some(fields[*o].as_slice()),
                    es.iter().map(print).collect(),
                ),
                Output::Scalar(e) => (d.scalar(s).to_string(), None, vec![print(e)]),
            };
            let lets = k
                .lets
                .iter()
                .map(|e| {
                    let ty = if call(e).is_some() { d.triple(s, module) } else { d.scalar(s).to_string() };
                    (ty, print(e))
                })
                .collect();
            let f = Function {
                name: format!("{}{sfx}", function_name(plan, k)),
                params: params
                    .iter()
                    .zip(&k.params)
                    .map(|(p, &i)| (*p, format!("{}{sfx}", type_name(plan, i))))
                    .collect(),
                ret,
                lets,
                fields: result_fields,
                values,
                doc: &k.doc,
                unused: params.iter().enumerate().filter(|(i, _)| !k.reads(*i)).map(|(_, p)| *p).collect(),
            };
            out.push_str(&d.function(s, &f));
            out.push('\n');
        }
    }
    out.push_str(&d.epilogue(module));
    Ok(out)
}

/// The operation names [`Options::ops`] accepts.
pub const OP_NAMES: [&str; 21] = [
    "gp",
    "op",
    "lc",
    "rc",
    "sp",
    "regressive",
    "commutator",
    "anticommutator",
    "reverse",
    "grade_involution",
    "conjugate",
    "dual",
    "undual",
    "norm_squared",
    "sandwich",
    "apply",
    "sandwich_unit",
    "apply_unit",
    "exp",
    "log_unit",
    "normalize",
];

/// Appends `indent` + `line` + newline.
pub(crate) fn push_line(s: &mut String, indent: &str, line: &str) {
    let _ = writeln!(s, "{indent}{line}");
}
