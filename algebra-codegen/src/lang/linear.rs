//! The linear kernels as [`super::ir`] programs: products, unary maps, norms, fused and
//! unit-versor actions, built from the [`Plan`] in the same statement order and with the same
//! summation shapes as the Rust kernels ([`crate::sums`]), so each computes the same
//! floating-point result in every language that evaluates `+`, `-` and `*` as written (C
//! without contraction of multiply-adds; docs/codegen.md "Kernels in C, WGSL and GLSL").

use super::ir::{Expr, Ir, Kernel, Op, Output, add, field, mul};
use crate::CodegenError;
use crate::naming::{product_name, unary_name};
use crate::plan::{BinaryKernel, Plan, Term as PlanTerm};
use crate::ratio::Ratio;
use crate::sums::{Build, Term, chunked_sum_in, sum_in, tree_sum_in};
use crate::unit::{UnitKernel, plan_unit_actions};
use crate::versor::{ActionKernel, Convention};
use std::collections::{BTreeMap, BTreeSet};

/// Every kernel of a plan, in the order of the Rust module: the binary products (every pair
/// of types, every product), the unary maps and norms per type, the fused actions and the
/// unit-versor actions. Pairs without a fused action (a versor type on the full multivector)
/// have no action kernel here: compose two geometric products.
pub(super) fn kernels(plan: &Plan) -> Result<Vec<Kernel>, CodegenError> {
    let name = |i: usize| plan.spec.types[i].name.as_str();
    let mut out: Vec<Kernel> = plan.binary.iter().map(|k| binary(plan, k)).collect();
    for ty in 0..plan.spec.types.len() {
        for k in plan.unary.iter().filter(|k| k.ty == ty) {
            let fields = k
                .outputs
                .iter()
                .map(|terms| sum_in::<Ir>(terms.iter().map(|&(a, c)| (c, field(0, a), false)).collect()))
                .collect();
            out.push(Kernel {
                op: Op::Unary(unary_name(k.op)),
                params: vec![ty],
                lets: Vec::new(),
                output: Output::Type(k.out, fields),
                doc: format!("The {} of a {}.", unary_name(k.op).replace('_', " "), name(ty)),
            });
        }
        out.push(norm(ty, &plan.norm[ty], name(ty)));
    }
    for k in &plan.actions {
        out.push(action(plan, k, name(k.versor), name(k.operand)));
    }
    for u in plan_unit_actions(&plan.spec, &plan.actions)? {
        out.push(unit_action(plan, &u, name(u.kernel.versor), name(u.kernel.operand)));
    }
    Ok(out)
}

/// A binary product: the distinct field products bound once (in field order), each output a
/// [`chunked_sum_in`]; above the size threshold the table form's four interleaved accumulators
/// ([`crate::size`]), written out.
fn binary(plan: &Plan, k: &BinaryKernel) -> Kernel {
    let (product, lhs, rhs) = (k.product, k.lhs, k.rhs);
    let doc =
        format!("`{}` of a {} and a {}.", product_name(product), plan.spec.types[lhs].name, plan.spec.types[rhs].name);
    let large =
        crate::size::table_driven(plan.spec.table_above, plan.declared, &[lhs, rhs], k.outputs.iter().map(Vec::len));
    // the distinct field products, bound in field order (the Rust kernel's `p{a}_{b}`)
    let pairs: BTreeSet<(usize, usize)> =
        if large { BTreeSet::new() } else { k.outputs.iter().flatten().map(|t| (t.lhs, t.rhs)).collect() };
    let local: BTreeMap<(usize, usize), usize> = pairs.iter().enumerate().map(|(i, &p)| (p, i)).collect();
    let lets = pairs.iter().map(|&(a, b)| mul(field(0, a), field(1, b))).collect();
    let fields = k
        .outputs
        .iter()
        .map(|terms| {
            if large {
                table_sum(terms.iter().map(|t| (field(0, t.lhs), field(1, t.rhs), t.coef)).collect())
            } else {
                chunked_sum_in::<Ir>(
                    terms.iter().map(|t| (t.coef, Expr::Local(local[&(t.lhs, t.rhs)]), true)).collect(),
                    k.chain,
                )
            }
        })
        .collect();
    Kernel { op: Op::Product(product), params: vec![lhs, rhs], lets, output: Output::Type(k.out, fields), doc }
}

/// One output of a table-driven kernel ([`crate::size::table_loop`]): the products `a · b`
/// with their constants dealt round-robin to four accumulators starting at zero (the remainder
/// to the first), then `(a0 + a1) + (a2 + a3)`.
fn table_sum(terms: Vec<(Expr, Expr, Ratio)>) -> Expr {
    let mut acc: [Expr; 4] = std::array::from_fn(|_| Ir::zero());
    let quads = terms.len() / 4 * 4;
    for (i, (a, b, c)) in terms.into_iter().enumerate() {
        let slot = if i < quads { i % 4 } else { 0 };
        let p = mul(a, b);
        let sum = std::mem::replace(&mut acc[slot], Ir::zero());
        acc[slot] = match c {
            (1, 1) => add(sum, p, false),
            (-1, 1) => add(sum, p, true),
            c => add(sum, mul(Expr::Const(c), p), false),
        };
    }
    let [a0, a1, a2, a3] = acc;
    add(add(a0, a1, false), add(a2, a3, false), false)
}

/// The outputs of a table-driven two-stage kernel, per output row of `(i, j, c)` terms.
fn table_rows(rows: &[Vec<(usize, usize, Ratio)>], a: impl Fn(usize) -> Expr, b: impl Fn(usize) -> Expr) -> Vec<Expr> {
    rows.iter().map(|row| table_sum(row.iter().map(|&(i, j, c)| (a(i), b(j), c)).collect())).collect()
}

fn norm(ty: usize, terms: &[PlanTerm], name: &str) -> Kernel {
    let lets = terms.iter().map(|t| mul(field(0, t.lhs), field(0, t.rhs))).collect();
    let value = sum_in::<Ir>(terms.iter().enumerate().map(|(n, t)| (t.coef, Expr::Local(n), true)).collect());
    Kernel {
        op: Op::NormSquared,
        params: vec![ty],
        lets,
        output: Output::Scalar(value),
        doc: format!("The squared norm <x rev(x)>_0 of a {name} (may be negative or zero)."),
    }
}

/// `c · s[a]` as `(±1, |c| · s[a])`: the constant multiplies the versor's coefficient
/// (as [`crate::versor`]'s kernels do); a field used negated ([`ActionKernel::flip`]) is
/// `-s[a]`.
fn scaled(c: Ratio, a: usize, flip: u32) -> (Ratio, Expr) {
    let (n, d) = c;
    let f = if flip >> a & 1 == 1 { <Ir as Build>::neg(field(0, a)) } else { field(0, a) };
    if crate::ratio::is_unit(c) { (c, f) } else { ((n.signum(), 1), mul(Expr::Const((n.abs(), d)), f)) }
}

/// The first stage's locals: the operand's constants first when the kernel binds them
/// ([`ActionKernel::operand_constants`]), then the intermediates.
fn stage1(k: &ActionKernel) -> Vec<Expr> {
    let consts = if k.operand_constants { k.operand_constant_fields() } else { Vec::new() };
    let mut lets: Vec<Expr> = consts.iter().map(|&(c, b)| mul(Expr::Const(c), field(1, b))).collect();
    let temps = k.stage1.iter().map(|terms| {
        let summands: Vec<Term<Expr>> = terms
            .iter()
            .map(|&(a, b, c)| {
                if k.operand_constants && !crate::ratio::is_unit(c) {
                    let (_, s) = scaled((1, 1), a, k.flip);
                    let local = consts.iter().position(|&x| x == ((c.0.abs(), c.1), b)).expect("bound");
                    return ((c.0.signum(), 1), mul(s, Expr::Local(local)), true);
                }
                let (c, s) = scaled(c, a, k.flip);
                (c, mul(s, field(1, b)), true)
            })
            .collect();
        if k.chains[0] { sum_in::<Ir>(summands) } else { tree_sum_in::<Ir>(summands) }
    });
    lets.extend(temps);
    lets
}

fn stage2(terms: &[(usize, usize, Ratio)]) -> Expr {
    stage2_shaped(terms, false, 0)
}

/// A stage-2 sum as a chain (`chain`) or a balanced tree (the Rust kernel's shape).
fn stage2_shaped(terms: &[(usize, usize, Ratio)], chain: bool, flip: u32) -> Expr {
    let terms = terms
        .iter()
        .map(|&(i, a, c)| {
            let (c, s) = scaled(c, a, flip);
            (c, mul(Expr::Local(i), s), true)
        })
        .collect();
    if chain { sum_in::<Ir>(terms) } else { tree_sum_in::<Ir>(terms) }
}

/// The outputs of a straight-line general kernel: each stage-2 sum over the intermediates'
/// locals ([`stage1`]'s numbering: after the operand's constants).
fn stage2_outputs(k: &ActionKernel) -> Vec<Expr> {
    let first = if k.operand_constants { k.operand_constant_fields().len() } else { 0 };
    k.stage2
        .iter()
        .map(|terms| {
            let renumbered: Vec<_> = terms.iter().map(|&(i, a, c)| (first + i, a, c)).collect();
            stage2_shaped(&renumbered, k.chains[1], k.flip)
        })
        .collect()
}

/// Whether an action kernel is table-driven in Rust ([`crate::size::table_driven`]).
fn large_action(plan: &Plan, k: &ActionKernel) -> bool {
    let lens = k.stage1.iter().chain(&k.stage2).map(Vec::len);
    crate::size::table_driven(plan.spec.table_above, plan.declared, &[k.versor, k.operand], lens)
}

/// The two stages of an action: straight-line, or the table form's accumulators.
fn stages(plan: &Plan, k: &ActionKernel) -> (Vec<Expr>, Vec<Expr>) {
    if large_action(plan, k) {
        let t = table_rows(&k.stage1, |a| field(0, a), |b| field(1, b));
        let out = table_rows(&k.stage2, Expr::Local, |a| field(0, a));
        (t, out)
    } else if let Some(norm) = &k.norm {
        // the scalar-norm form, as the Rust kernel: the intermediates, then `n`, then
        // `n · x_j + scale · y_j` (`y + y` for the scale 2)
        let mut lets = stage1(k);
        let n = sum_in_tree(norm.terms.iter().map(|&(a, b, c)| (c, mul(field(0, a), field(0, b)), true)).collect());
        lets.push(n);
        let n = Expr::Local(lets.len() - 1);
        let out = k
            .stage2
            .iter()
            .enumerate()
            .map(|(j, terms)| {
                let nx = mul(n.clone(), field(1, j));
                if terms.is_empty() {
                    return nx;
                }
                let y = stage2_shaped(terms, k.chains[1], k.flip);
                match norm.scale {
                    (1, 1) => add(nx, y, false),
                    (2, 1) => {
                        lets.push(y);
                        let y = Expr::Local(lets.len() - 1);
                        add(nx, add(y.clone(), y, false), false)
                    }
                    c => add(nx, mul(Expr::Const(c), y), false),
                }
            })
            .collect();
        (lets, out)
    } else {
        (stage1(k), stage2_outputs(k))
    }
}

fn sum_in_tree(terms: Vec<Term<Expr>>) -> Expr {
    tree_sum_in::<Ir>(terms)
}

fn action(plan: &Plan, k: &ActionKernel, versor: &str, operand: &str) -> Kernel {
    let product = match k.convention {
        Convention::Sandwich => "rev(S) x S",
        Convention::Apply => "S x rev(S)",
    };
    let (lets, outputs) = stages(plan, k);
    let doc = if k.outside.is_empty() {
        format!("{product} for a {versor} S and a {operand} x, in one fused kernel.")
    } else {
        format!("{product} for a {versor} S and a {operand} x, projected onto {operand} (exact when S is a versor).")
    };
    Kernel {
        op: Op::Action(k.convention),
        params: vec![k.versor, k.operand],
        lets,
        output: Output::Type(k.operand, outputs),
        doc,
    }
}

/// A unit-versor action; a table-sized one is the general action (as in Rust).
fn unit_action(plan: &Plan, u: &UnitKernel, versor: &str, operand: &str) -> Kernel {
    let k = &u.kernel;
    if large_action(plan, k) {
        let general = plan
            .actions
            .iter()
            .find(|a| (a.versor, a.operand, a.convention) == (k.versor, k.operand, k.convention))
            .expect("every unit kernel has a general one");
        let mut g = action(plan, general, versor, operand);
        g.op = Op::UnitAction(k.convention);
        g.doc = format!("{} (the general action: this pair is above the size threshold)", g.doc);
        return g;
    }
    let mut lets = stage1(k);
    let fields = k
        .stage2
        .iter()
        .enumerate()
        .map(|(j, terms)| {
            let x = field(1, j);
            if terms.is_empty() {
                return x;
            }
            let y = stage2(terms);
            match u.scale {
                (1, 1) => add(x, y, false),
                (2, 1) => {
                    // `x + y + y` (the Rust kernel's order) with `y` computed once
                    lets.push(y);
                    let y = Expr::Local(lets.len() - 1);
                    add(add(x, y.clone(), false), y, false)
                }
                c => add(x, mul(Expr::Const(c), y), false),
            }
        })
        .collect();
    let what = match k.convention {
        Convention::Sandwich => "rev(S) x S",
        Convention::Apply => "S x rev(S)",
    };
    Kernel {
        op: Op::UnitAction(k.convention),
        params: vec![k.versor, k.operand],
        lets,
        output: Output::Type(k.operand, fields),
        doc: format!("{what} for a unit {versor} S (S rev(S) = 1) and a {operand} x; not the action otherwise."),
    }
}
