//! `gam codegen`: the generator of the `algebra!` macro as a command, for crates that want
//! to vendor a formatted `.rs` file instead of depending on the proc-macro, and for the
//! operation counts of every kernel.

use crate::error::CliError;
use algebra_codegen::constraint::{ConstrainedKernel, Constraint, ConstraintKind, Request, kernel, requests};
use algebra_codegen::{CodegenError, ModuleSpec, plan::Plan};
use algebra_core::Basis;
use serde_json::{Value, json};

/// What `gam codegen` prints.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Emit {
    /// The formatted Rust source of the module.
    Rust,
    /// Multiplication and addition counts per kernel.
    Stats,
}

/// The language of `gam codegen`'s source (`--lang`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Lang {
    /// The Rust module (the `algebra!` macro's expansion).
    Rust,
    /// One C99 header (`double` and `float`).
    C,
    /// WGSL (`f32`).
    Wgsl,
    /// GLSL 4.50 (`float`).
    Glsl,
}

/// Where results outside every declared type land (`--fallback`; the DSL's `fallback` section).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Fallback {
    /// Automatic `Even`/`Odd` types for single-parity results, then the full multivector.
    Parity,
    /// The full multivector only (no automatic types).
    Full,
}

/// The arguments of `gam codegen`.
#[derive(Debug, clap::Args)]
pub struct CodegenArgs {
    #[arg(long, value_name = "NAME", default_value = "cga-null", help = crate::algebra_help())]
    pub algebra: String,
    /// The types: "Name=selector;..." with selectors `grade K`, `even`, `odd`, `all` or a
    /// comma list of basis names, e.g. "Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1";
    /// a selector may end in `where unit|null|simple` (constrained kernels as methods).
    #[arg(long, value_name = "TYPES")]
    pub types: String,
    /// The basis the element names refer to: blade or product.
    #[arg(long, value_name = "B", default_value = "blade")]
    pub basis: Basis,
    /// rust (formatted source) or stats (operation counts per kernel).
    #[arg(long, value_enum, value_name = "WHAT", default_value = "rust")]
    pub emit: Emit,
    /// The language of the source: rust (the default), c (one C99 header, double and float),
    /// wgsl or glsl (f32).
    #[arg(long, value_enum, value_name = "LANG", default_value = "rust")]
    pub lang: Lang,
    /// With --lang c|wgsl|glsl: only the kernels of these operations, comma-separated (gp, op,
    /// lc, rc, sp, regressive, commutator, anticommutator, reverse, grade_involution,
    /// conjugate, dual, undual, norm_squared, sandwich, apply, sandwich_unit, apply_unit, exp,
    /// log_unit, normalize). With --standalone: gp, op, lc, rc, sp, regressive, commutator,
    /// anticommutator, gp_into, sandwich, apply, sandwich_unit, apply_unit, matrix, the actions
    /// of every versor type (default: gp, and apply and apply_unit of the even types holding
    /// 1, motors and rotors).
    #[arg(long, value_name = "OPS", value_delimiter = ',')]
    pub ops: Option<Vec<String>>,
    /// With --standalone or --lang c|wgsl|glsl: also the kernels taking the types the generator
    /// adds (automatic Even/Odd, the full multivector); by default only kernels among the
    /// declared types. With --standalone and no --ops: also the actions of every versor type.
    #[arg(long)]
    pub every_type: bool,
    /// The module name (default: the algebra name, `-` as `_`). With --standalone: wrap the
    /// items in `pub mod NAME` (default: no wrapper).
    #[arg(long, value_name = "NAME")]
    pub module: Option<String>,
    /// Print JSON: for stats a list of {"op","lhs","rhs","out","mul","add"}; for rust
    /// {"module","source"}.
    #[arg(long)]
    pub json: bool,
    /// A file with no dependency: scalar and product traits inlined (for f32/f64), no
    /// conversions to the runtime multivector, items at the top level.
    #[arg(long)]
    pub standalone: bool,
    /// With --emit stats: a polynomial constraint TYPE=unit (rev(x) x = 1), TYPE=null
    /// (x x = 0) or TYPE=simple (x ∧ x = 0), repeatable, as `TYPE=... where KIND` in
    /// --types; adds rows for the kernels reduced modulo the constraints (the vanishing
    /// outputs proven and dropped) with what each saves.
    #[arg(long, value_name = "TYPE=KIND")]
    pub constrain: Vec<String>,
    /// Where a result outside every declared type lands when no type is the full
    /// multivector: parity (automatic Even/Odd types) or full (the full multivector).
    #[arg(long, value_enum, value_name = "KIND", default_value = "parity")]
    pub fallback: Fallback,
    /// The size policy's threshold (the DSL's `table_above N;`): a kernel with more than N
    /// terms is a loop over a constant table, one with at most N straight-line code
    /// (default: the generator's, see docs/codegen.md "Size policy").
    #[arg(long, value_name = "N")]
    pub table_above: Option<usize>,
}

/// Runs `gam codegen`.
pub fn codegen(args: &CodegenArgs) -> Result<String, CliError> {
    let alg = crate::budget::algebra(&args.algebra)?;
    let module = args.module.clone().unwrap_or_else(|| {
        let stem = std::path::Path::new(alg.name()).file_stem().and_then(|s| s.to_str()).unwrap_or("generated");
        stem.chars().map(|c| if c.is_ascii_alphanumeric() { c.to_ascii_lowercase() } else { '_' }).collect()
    });
    // raw identifiers (`r#type`) parse but cannot name a generated module: refuse them here
    if module.starts_with("r#") || syn::parse_str::<syn::Ident>(&module).is_err() {
        return Err(CliError::usage(format!("`{module}` is not a valid module name (use --module NAME)")));
    }
    let bad = |e: CodegenError| CliError::usage(e.to_string());
    let types = ModuleSpec::parse_types(&args.types, &alg).map_err(bad)?;
    // a type named like a Rust keyword (`Self`, `fn`) made the generated code unparsable
    if let Some(t) = types.iter().find(|t| t.name.starts_with("r#") || syn::parse_str::<syn::Ident>(&t.name).is_err()) {
        return Err(CliError::usage(format!(
            "--types: `{}` is a Rust keyword or not an identifier; choose another type name",
            t.name
        )));
    }
    let mut spec = ModuleSpec::new(&module, alg.metric().clone(), args.basis, types).map_err(bad)?;
    spec.parity_types = args.fallback == Fallback::Parity;
    if let Some(n) = args.table_above {
        spec.table_above = n;
    }
    spec.doc = vec![
        format!(
            "Generated by `gam codegen --algebra {} --basis {}{} --types \"{}\"`.",
            args.algebra,
            args.basis,
            generator_options(args),
            args.types
        ),
        format!("Metric: {}. Do not edit: regenerate instead.", alg.describe_metric()),
    ];
    let mut plan = Plan::new(spec).map_err(bad)?;
    let constraints = parse_constraints(&args.constrain, &plan)?;
    if !constraints.is_empty() && args.emit != Emit::Stats {
        return Err(CliError::usage("--constrain is only used with --emit stats".to_string()));
    }
    // `--constrain TYPE=KIND` is `TYPE=... where KIND` in --types
    for c in &constraints {
        plan.spec.types[c.ty].constraint = Some(c.kind);
    }
    let declared = plan.spec.types.iter().any(|t| t.constraint.is_some());
    if args.lang != Lang::Rust && args.standalone {
        return Err(CliError::usage("--standalone is for --lang rust (C, WGSL and GLSL output has no dependency)"));
    }
    if (args.ops.is_some() || args.every_type)
        && ((args.lang == Lang::Rust && !args.standalone) || args.emit != Emit::Rust)
    {
        return Err(CliError::usage("--ops and --every-type are used with --standalone or --lang c, wgsl or glsl"));
    }
    match args.emit {
        Emit::Rust if args.lang != Lang::Rust => {
            let source = other_language(args, &plan)?;
            Ok(if args.json {
                json!({ "module": module, "lang": lang_name(args.lang), "source": source }).to_string()
            } else {
                source
            })
        }
        Emit::Rust => {
            let internal = |e: syn::Error| CliError::usage(format!("internal: generated code does not parse: {e}"));
            let source = if args.standalone {
                if declared {
                    return Err(CliError::usage(
                        "--standalone does not support `where` constraints yet (drop --standalone)".to_string(),
                    ));
                }
                let ops = parse_ops(args, &algebra_codegen::standalone::STANDALONE_OPS)?;
                standalone_source(args, &plan, &ops).map_err(internal)?
            } else {
                let mut items = algebra_codegen::emit::module_items(&plan);
                items.extend(
                    algebra_codegen::constraint::methods(&plan)
                        .map_err(|e| CliError::usage(format!("--types: {e}")))?,
                );
                let file: syn::File =
                    syn::parse2(algebra_codegen::emit::module_with(&plan, items)).map_err(internal)?;
                prettyplease::unparse(&file)
            };
            Ok(if args.json { json!({ "module": module, "source": source }).to_string() } else { source })
        }
        Emit::Stats => {
            let stats = plan.stats();
            let constrained = constrained_rows(&plan)?;
            if args.json {
                let list: Vec<Value> = stats
                    .iter()
                    .map(|s| match &s.rhs {
                        Some(rhs) => {
                            json!({"op": s.op, "lhs": s.lhs, "rhs": rhs, "out": s.out, "mul": s.mul, "add": s.add})
                        }
                        None => json!({"op": s.op, "lhs": s.lhs, "out": s.out, "mul": s.mul, "add": s.add}),
                    })
                    .chain(constrained.iter().map(|k| k.json()))
                    .collect();
                return Ok(Value::Array(list).to_string());
            }
            let mut rows = vec![["op", "lhs", "rhs", "out", "mul", "add"].map(String::from).to_vec()];
            for s in &stats {
                rows.push(vec![
                    s.op.clone(),
                    s.lhs.clone(),
                    s.rhs.clone().unwrap_or_else(|| "-".into()),
                    s.out.clone(),
                    s.mul.to_string(),
                    s.add.to_string(),
                ]);
            }
            rows.extend(constrained.iter().map(ConstrainedRow::text));
            Ok(crate::output::text_table(&rows))
        }
    }
}

/// The name `--lang` reads (clap's, so it cannot drift from the parser).
fn lang_name(lang: Lang) -> String {
    clap::ValueEnum::to_possible_value(&lang).expect("no variant is skipped").get_name().to_string()
}

/// The command that regenerates a file (`gam codegen --lang c`, `gam codegen --standalone`):
/// `head` and every option that changes its text, in one order.
fn regeneration_command(args: &CodegenArgs, head: &str) -> String {
    let mut command = format!("gam codegen {head} --algebra {} --basis {}", args.algebra, args.basis);
    if let Some(m) = &args.module {
        command.push_str(&format!(" --module {m}"));
    }
    command.push_str(&generator_options(args));
    command.push_str(&selection_options(args));
    command.push_str(&format!(" --types \"{}\"", args.types));
    command
}

/// The C header, WGSL or GLSL source of the plan's kernels, headed by the command that
/// regenerates it.
fn other_language(args: &CodegenArgs, plan: &Plan) -> Result<String, CliError> {
    use algebra_codegen::lang;
    let target = match args.lang {
        Lang::C => lang::Lang::C,
        Lang::Wgsl => lang::Lang::Wgsl,
        Lang::Glsl => lang::Lang::Glsl,
        Lang::Rust => unreachable!("the Rust source is emitted by the caller"),
    };
    let ops = parse_ops(args, &lang::OP_NAMES)?;
    let command = regeneration_command(args, &format!("--lang {}", lang_name(args.lang)));
    let mut header = vec![format!("@generated by {command}"), "Do not edit: regenerate instead.".to_string()];
    header.extend(plan.spec.doc.iter().skip(1).cloned());
    let options = lang::Options { ops, header, every_type: args.every_type };
    lang::emit(plan, target, &options).map_err(|e| CliError::usage(format!("--types: {e}")))
}

/// `--ops` and `--every-type` as they appear in a generated file's regeneration command.
fn selection_options(args: &CodegenArgs) -> String {
    let mut options = String::new();
    if let Some(ops) = &args.ops {
        options.push_str(&format!(" --ops {}", ops.join(",")));
    }
    if args.every_type {
        options.push_str(" --every-type");
    }
    options
}

/// The options that change what the generator emits (`--fallback full`, `--table-above N`), as
/// they appear in the regeneration command of a generated file's header.
fn generator_options(args: &CodegenArgs) -> String {
    let mut options = String::new();
    if args.fallback == Fallback::Full {
        options.push_str(" --fallback full");
    }
    if let Some(n) = args.table_above {
        options.push_str(&format!(" --table-above {n}"));
    }
    options
}

/// The `--standalone` file: a header naming the regeneration command, then the items.
fn standalone_source(
    args: &CodegenArgs,
    plan: &Plan,
    ops: &Option<std::collections::BTreeSet<String>>,
) -> Result<String, syn::Error> {
    let command = regeneration_command(args, "--standalone");
    let header = [
        format!("Generated by `{command}`: no dependencies (scalar and product traits inlined below)."),
        format!("Metric: {}.", plan.spec.algebra.describe_metric()),
        format!("Do not edit: regenerate with `cargo run --release -p gam -- {}`.", command.trim_start_matches("gam ")),
    ];
    let selection = algebra_codegen::standalone::Selection { ops: ops.clone(), every_type: args.every_type };
    let file = algebra_codegen::standalone::file_with(plan, &header, args.module.as_deref(), &selection)?;
    let text = algebra_codegen::standalone::layout(&prettyplease::unparse(&file));
    Ok(format!("// @generated by gam codegen --standalone\n{text}"))
}

/// `--ops` as a set, every name checked against `known`.
fn parse_ops(args: &CodegenArgs, known: &[&str]) -> Result<Option<std::collections::BTreeSet<String>>, CliError> {
    let Some(list) = &args.ops else { return Ok(None) };
    let mut set = std::collections::BTreeSet::new();
    for op in list.iter().map(|o| o.trim()) {
        if !known.contains(&op) {
            return Err(CliError::usage(format!("--ops: unknown operation `{op}` (one of {})", known.join(", "))));
        }
        set.insert(op.to_string());
    }
    Ok(Some(set))
}

/// `TYPE=unit|null|simple` (repeatable) as constraints on the plan's types.
fn parse_constraints(list: &[String], plan: &Plan) -> Result<Vec<Constraint>, CliError> {
    let usage = |m: String| CliError::usage(m);
    list.iter()
        .map(|item| {
            let (name, kind) = item
                .split_once('=')
                .ok_or_else(|| usage(format!("--constrain `{item}`: expected TYPE=unit|null|simple")))?;
            let ty = plan.spec.types.iter().position(|t| t.name == name.trim());
            let ty = ty.ok_or_else(|| usage(format!("--constrain `{item}`: no type `{}`", name.trim())))?;
            let kind = match kind.trim() {
                "unit" => ConstraintKind::Unit,
                "null" => ConstraintKind::Null,
                "simple" => ConstraintKind::Simple,
                other => return Err(usage(format!("--constrain `{item}`: `{other}` is not unit, null or simple"))),
            };
            Ok(Constraint { ty, kind })
        })
        .collect()
}

/// One `--emit stats` row of a constrained kernel.
struct ConstrainedRow {
    op: &'static str,
    lhs: String,
    rhs: String,
    kernel: ConstrainedKernel,
    out: String,
    unconstrained_out: String,
}

impl ConstrainedRow {
    fn text(&self) -> Vec<String> {
        let (c, f) = (self.kernel.stats(), self.kernel.full.stats());
        vec![
            format!(
                "{} [{}] saves {} mul, {} terms",
                self.op,
                self.kernel.relies_on.join(", "),
                f.mul.saturating_sub(c.mul),
                f.terms.saturating_sub(c.terms)
            ),
            self.lhs.clone(),
            self.rhs.clone(),
            self.out.clone(),
            c.mul.to_string(),
            c.add.to_string(),
        ]
    }

    fn json(&self) -> Value {
        let (c, f) = (self.kernel.stats(), self.kernel.full.stats());
        json!({"op": self.op, "lhs": self.lhs, "rhs": self.rhs, "out": self.out, "mul": c.mul, "add": c.add,
               "constraints": self.kernel.relies_on, "terms": c.terms, "setup_mul": c.setup_mul, "apply_mul": c.apply_mul,
               "saved": {"mul": f.mul.saturating_sub(c.mul), "terms": f.terms.saturating_sub(c.terms)},
               "unconstrained": {"out": self.unconstrained_out, "mul": f.mul, "add": f.add, "terms": f.terms}})
    }
}

/// Every constrained kernel the declared constraints call for (`where` in --types or
/// --constrain): the unit versors' sandwich and apply on every other non-full type, the squares
/// of null and simple types.
fn constrained_rows(plan: &Plan) -> Result<Vec<ConstrainedRow>, CliError> {
    let spec = &plan.spec;
    let name = |t: Option<usize>| t.map_or_else(|| "-".to_string(), |t| spec.types[t].name.clone());
    requests(plan)
        .into_iter()
        .map(|r: Request| {
            let kernel = kernel(spec, r).map_err(|e| CliError::usage(format!("constraints: {e}")))?;
            Ok(ConstrainedRow {
                op: r.op.name(),
                lhs: spec.types[r.left].name.clone(),
                rhs: spec.types[r.right].name.clone(),
                out: name(kernel.output_type),
                unconstrained_out: name(kernel.full.output_type),
                kernel,
            })
        })
        .collect()
}
