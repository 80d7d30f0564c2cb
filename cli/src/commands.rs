//! The subcommands. Each returns its whole output as a string (printed only on success, so a
//! failure never leaves partial output) or a [`CliError`].

use crate::error::CliError;
use crate::eval::Evaluator;
use crate::expr;
use crate::output::{mv_human, mv_json, text_table};
use crate::scalar::{CliScalar, ScalarKind};
use algebra_core::rational::{Q, format_rational};
use algebra_core::{Basis, MpFloat, Multivector, Poly, PrecisionGuard, Product, algebra::BUILTINS};
use serde_json::{Value, json};

/// A short description of a built-in algebra.
fn description(name: &str) -> &'static str {
    match name {
        "g3" => "R^3, Euclidean space",
        "g123inf" => "the paper's G_{123inf} (even subalgebra: dual quaternions)",
        "pga3" => "R^{3,0,1}, projective geometric algebra",
        "cga" => "R^{4,1}, conformal algebra with e4^2 = 1, e5^2 = -1",
        "cga-null" => "the paper's G_{0123inf}: null vectors e0, einf with e0.einf = -1 (default)",
        _ => "",
    }
}

/// `gam algebras [--json] [ALGEBRA...]`: the built-ins (or the named algebras) with their
/// labels and metrics.
pub fn algebras(names: &[String], json: bool) -> Result<String, CliError> {
    let names: Vec<String> =
        if names.is_empty() { BUILTINS.iter().map(|s| s.to_string()).collect() } else { names.to_vec() };
    let algs = names.iter().map(|n| crate::budget::algebra(n)).collect::<Result<Vec<_>, _>>()?;
    if json {
        let list: Vec<Value> = algs
            .iter()
            .map(|a| {
                let m = a.metric();
                let gram: Vec<Vec<String>> =
                    m.gram_matrix().iter().map(|row| row.iter().map(format_rational).collect()).collect();
                let basis: Vec<&str> = a.basis_order().iter().filter_map(|&k| a.name_of(k).ok()).collect();
                json!({
                    "name": a.name(),
                    "description": description(a.name()),
                    "labels": m.labels(),
                    "gram": gram,
                    "dimension": m.dimension(),
                    "basis": basis,
                })
            })
            .collect();
        return Ok(Value::Array(list).to_string());
    }
    let width = algs.iter().map(|a| a.name().len()).max().unwrap_or(0);
    let blocks: Vec<String> = algs
        .iter()
        .map(|a| {
            let labels = a.metric().labels().join(", ");
            let about = description(a.name());
            let head = if about.is_empty() { a.name().to_string() } else { format!("{:width$}  {about}", a.name()) };
            format!("{}\n  labels: {labels}\n  metric: {}", head.trim_end(), a.describe_metric())
        })
        .collect();
    Ok(blocks.join("\n"))
}

/// The options of `gam eval`.
#[derive(Debug, Clone)]
pub struct EvalArgs {
    /// `--algebra`: a built-in name or a TOML path.
    pub algebra: String,
    /// `--basis`.
    pub basis: Basis,
    /// `--scalar`.
    pub scalar: ScalarKind,
    /// `--json`.
    pub json: bool,
    /// The expression.
    pub expr: String,
}

/// `gam eval`: parse, evaluate over the chosen scalar, print in the chosen basis.
pub fn eval(args: &EvalArgs) -> Result<String, CliError> {
    eval_text(args, &expression_text(&args.expr)?)
}

/// `gam eval` of the expression `text` itself (`args.expr` is not read: no `@FILE`, no stdin).
pub fn eval_text(args: &EvalArgs, text: &str) -> Result<String, CliError> {
    let alg = crate::budget::algebra(&args.algebra)?;
    let ast = expr::parse(text, &alg)?;
    let ev = Evaluator::new(&alg, args.basis);
    match args.scalar {
        ScalarKind::Rational => render(&ev.eval::<Q>(&ast)?, args.json),
        ScalarKind::Poly => render(&ev.eval::<Poly>(&ast)?, args.json),
        ScalarKind::F64 => render(&ev.eval::<f64>(&ast)?, args.json),
        ScalarKind::Mpfr(bits) => {
            let _precision = PrecisionGuard::new(bits);
            render(&ev.eval::<MpFloat>(&ast)?, args.json)
        }
    }
}

/// The largest expression read from a file or stdin, in bytes.
const MAX_EXPRESSION_BYTES: u64 = 1 << 20;

/// The expression itself, or the contents of `FILE` for `@FILE`, or of stdin for `-`
/// (at most [`MAX_EXPRESSION_BYTES`]).
fn expression_text(arg: &str) -> Result<String, CliError> {
    use std::io::Read;
    let (mut reader, what): (Box<dyn Read>, String) = match arg {
        "-" => (Box::new(std::io::stdin()), "stdin".to_string()),
        _ => match arg.strip_prefix('@') {
            Some(path) => (
                Box::new(std::fs::File::open(path).map_err(|e| CliError::usage(format!("cannot read `{path}`: {e}")))?),
                format!("`{path}`"),
            ),
            None => return Ok(arg.to_string()),
        },
    };
    let mut bytes = Vec::new();
    reader
        .by_ref()
        .take(MAX_EXPRESSION_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| CliError::usage(format!("cannot read {what}: {e}")))?;
    if bytes.len() as u64 > MAX_EXPRESSION_BYTES {
        return Err(CliError::usage(format!("{what}: the expression is longer than {MAX_EXPRESSION_BYTES} bytes")));
    }
    String::from_utf8(bytes).map_err(|_| CliError::usage(format!("{what} is not UTF-8 text")))
}

fn render<T: CliScalar>(x: &Multivector<T>, json: bool) -> Result<String, CliError> {
    Ok(if json { mv_json(x).to_string() } else { mv_human(x) })
}

/// `gam table`: the product table of `product` on the basis elements of `basis`.
pub fn table(algebra: &str, basis: Basis, product: Product, json: bool) -> Result<String, CliError> {
    let alg = crate::budget::algebra(algebra)?;
    let order = alg.basis_order();
    let tab = alg.tables().product(basis, product);
    // every mask below comes from the algebra's own basis order, so these never fail
    let name = |a: u32| alg.name_of(a).map_err(|e| CliError::usage(e.to_string()));
    let entry = |a: u32, b: u32| -> Result<Multivector<Q>, CliError> {
        let mut m = Multivector::zero(&alg, basis);
        for (k, c) in tab.get(a, b).map_err(|e| CliError::usage(e.to_string()))? {
            m.coeffs_mut()[*k as usize] = c.clone();
        }
        Ok(m)
    };
    if json {
        let mut list = Vec::with_capacity(order.len() * order.len());
        for &a in order {
            for &b in order {
                list.push(json!({"a": name(a)?, "b": name(b)?, "result": mv_json(&entry(a, b)?)}));
            }
        }
        return Ok(Value::Array(list).to_string());
    }
    let mut rows: Vec<Vec<String>> = Vec::with_capacity(order.len() + 1);
    let header = order.iter().map(|&b| name(b).map(str::to_string)).collect::<Result<Vec<_>, _>>()?;
    rows.push(std::iter::once(String::new()).chain(header).collect());
    for &a in order {
        let cells = order.iter().map(|&b| entry(a, b).map(|m| mv_human(&m))).collect::<Result<Vec<_>, _>>()?;
        rows.push(std::iter::once(name(a)?.to_string()).chain(cells).collect());
    }
    let title = format!(
        "{} table of {} in the {basis} basis: cell = {}(row, column)",
        product_title(product),
        alg.name(),
        product.cli_name()
    );
    Ok(format!("{title}\n{}", text_table(&rows)))
}

fn product_title(p: Product) -> &'static str {
    match p {
        Product::Geometric => "gp (geometric product)",
        Product::Outer => "op (outer product)",
        Product::LeftContraction => "lc (left contraction)",
        Product::RightContraction => "rc (right contraction)",
        Product::Scalar => "sp (scalar product)",
        Product::Regressive => "rp (regressive product)",
        Product::Commutator => "comm ((xy - yx)/2)",
        Product::Anticommutator => "acomm ((xy + yx)/2)",
    }
}
