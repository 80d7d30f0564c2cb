//! The closed-form `exp`, `log_unit` and `normalize` of [`crate::closed`] as language-free
//! kernels, for the two families every language can evaluate with `sqrt`, `sin`, `cos` and
//! `atan2`: bivectors squaring to a non-positive scalar (Euclidean rotors, 2D PGA, complex
//! numbers) and the dual family (3D PGA motors, the dual quaternions of `G_{123inf}^+`). The
//! hyperbolic and mixed scalar families and the invariant decomposition (CGA) are Rust only.
//!
//! The kernels are the Rust methods without their checks: no error values in a shader, so a
//! non-positive norm (`normalize`), a full turn (`log_unit`, no unique axis) or non-finite
//! input give non-finite coefficients, and the Rust methods' rescaling of elements far from
//! unit scale is left out (docs/codegen.md "Kernels in C, WGSL and GLSL").

use super::ir::{Expr, Helper, Ir, Kernel, Op, Output};
use crate::closed::{ClosedForm, Family, ITimes, Sign, detect};
use crate::plan::Plan;
use crate::ratio::{Ratio, to_ratio};
use crate::{CodegenError, sums};
use algebra_core::rational::Q;
use num_traits::Zero;

fn int(n: i64) -> Q {
    Q::from_integer(n.into())
}

fn b(e: Expr) -> Box<Expr> {
    Box::new(e)
}

fn mul(a: Expr, c: Expr) -> Expr {
    Expr::Mul(b(a), b(c))
}

fn sum(terms: Vec<(Ratio, Expr)>) -> Expr {
    sums::sum_in::<Ir>(terms.into_iter().map(|(c, e)| (c, e, true)).collect())
}

/// Field access for one closed form: parameter 0 is the kernel's input (`B` or `M`).
struct Ctx<'a> {
    c: &'a ClosedForm,
    /// Per field of `B`: its field index in `M`.
    in_m: Vec<usize>,
    signs: Vec<Vec<i64>>,
}

impl Ctx<'_> {
    fn index(&self, owner: usize, k: usize) -> usize {
        if owner == self.c.bivector { k } else { self.in_m[k] }
    }

    fn field(&self, owner: usize, k: usize) -> Expr {
        Expr::Field { param: 0, field: self.index(owner, k) }
    }

    fn sign(&self, owner: usize, k: usize) -> i64 {
        self.signs[owner][self.index(owner, k)]
    }

    /// `Σ d x_b²` over `B`'s fields of `owner`, times `factor` (signs square away).
    fn square_form(&self, owner: usize, factor: i64) -> Result<Expr, CodegenError> {
        let mut terms = Vec::new();
        for (k, d) in self.c.square.iter().enumerate().filter(|(_, d)| !d.is_zero()) {
            terms.push((to_ratio(&(d * int(factor)))?, mul(self.field(owner, k), self.field(owner, k))));
        }
        Ok(sum(terms))
    }

    /// `c/2` of `B² = q + cI` on `owner`'s `B` fields.
    fn half_c(&self, owner: usize, half_c: &[(usize, usize, Q)]) -> Result<Expr, CodegenError> {
        let mut terms = Vec::new();
        for (x, y, c) in half_c {
            let s = self.sign(owner, *x) * self.sign(owner, *y);
            terms.push((to_ratio(&(c * int(s)))?, mul(self.field(owner, *x), self.field(owner, *y))));
        }
        Ok(sum(terms))
    }

    /// `target`'s field for `B`'s element `k`: `outer · x_k + inner · (I x)_k`, `x` the `B`
    /// part of `owner` (the parameter).
    fn combine(
        &self,
        owner: usize,
        target: usize,
        k: usize,
        outer: Option<Expr>,
        inner: Option<(Expr, i64, &[ITimes])>,
    ) -> Result<Expr, CodegenError> {
        let ts = self.sign(target, k);
        let mut terms = Vec::new();
        if let Some(outer) = outer {
            terms.push(((ts * self.sign(owner, k), 1), mul(outer, self.field(owner, k))));
        }
        if let Some((scalar, factor, i_times)) = inner {
            for (src, row) in i_times.iter().enumerate() {
                for (dst, c) in row.iter().filter(|(dst, _)| *dst == k) {
                    let _ = dst;
                    let s = ts * self.sign(owner, src);
                    terms.push((to_ratio(&(c * int(factor * s)))?, mul(scalar.clone(), self.field(owner, src))));
                }
            }
        }
        Ok(sum(terms))
    }
}

/// `expr`, negated for an orientation sign of `-1`.
fn signed(e: Expr, sign: i64) -> Expr {
    if sign < 0 { Expr::Neg(b(e)) } else { e }
}

/// The `exp`, `log_unit` and `normalize` kernels of every closed-form pair the languages
/// support (none when the module turned closed forms off).
pub(super) fn kernels(plan: &Plan) -> Result<Vec<Kernel>, CodegenError> {
    if !plan.spec.closed_forms {
        return Ok(Vec::new());
    }
    let mut out = Vec::new();
    for c in detect(&plan.spec, &plan.closed)? {
        if matches!(c.family, Family::Dual { .. } | Family::Scalar(Sign::Elliptic)) {
            out.extend(pair(plan, &c)?);
        }
    }
    Ok(out)
}

fn pair(plan: &Plan, c: &ClosedForm) -> Result<Vec<Kernel>, CodegenError> {
    let (bi, mi) = (c.bivector, c.even);
    let types = &plan.spec.types;
    let in_m: Vec<usize> =
        types[bi].elements.iter().map(|x| types[mi].elements.iter().position(|y| y == x).expect("B in M")).collect();
    let ctx = Ctx { c, in_m, signs: types.iter().map(crate::TypeSpec::signs).collect() };
    let m_fields = types[mi].elements.len();
    let one = types[mi].elements.iter().position(|x| *x == 0).expect("1 in M");
    let scalar = Expr::Field { param: 0, field: one };
    let dual = match &c.family {
        Family::Dual { i, half_c, i_times } => {
            let ii = types[mi].elements.iter().position(|x| x == i).expect("I in M");
            Some((ii, ctx.signs[mi][ii], half_c, i_times))
        }
        _ => None,
    };
    let (bn, mn) = (&types[bi].name, &types[mi].name);

    // exp: B -> M
    let mut lets = vec![ctx.square_form(bi, -1)?, Expr::Call(Helper::ExpFactors, vec![Expr::Local(0)])];
    let (sinc, k, cos) = (Expr::Part(1, 0), Expr::Part(1, 1), Expr::Part(1, 2));
    let mut hk = None;
    if let Some((_, _, half_c, _)) = &dual {
        lets.push(ctx.half_c(bi, half_c)?); // 2: c/2
        lets.push(mul(Expr::Local(2), k)); // 3: (c/2) k
        hk = Some(Expr::Local(3));
    }
    let mut exp_fields = Vec::new();
    for idx in 0..m_fields {
        let v = if idx == one {
            cos.clone()
        } else if let Some((ii, si, _, _)) = dual.as_ref().filter(|d| d.0 == idx) {
            let _ = ii;
            signed(mul(Expr::Local(2), sinc.clone()), *si)
        } else {
            let k = ctx.in_m.iter().position(|&p| p == idx).expect("a field of B");
            let inner = dual.as_ref().map(|d| (hk.clone().expect("dual"), -1, d.3.as_slice()));
            ctx.combine(bi, mi, k, Some(sinc.clone()), inner)?
        };
        exp_fields.push(v);
    }
    let exp = Kernel {
        op: Op::Exp,
        params: vec![bi],
        lets,
        output: Output::Type(mi, exp_fields),
        doc: format!("exp of a {bn}: a unit {mn} (closed form; non-finite input gives non-finite output)."),
    };

    // log_unit: M -> B
    let mut lets = vec![
        Expr::Sqrt(b(ctx.square_form(mi, -1)?)),
        Expr::Call(Helper::LogFactors, vec![Expr::Local(0), scalar.clone()]),
    ];
    let inv = Expr::Part(1, 0);
    let mut pk = None;
    if let Some((ii, si, _, _)) = &dual {
        lets.push(signed(mul(Expr::Field { param: 0, field: *ii }, Expr::Part(1, 1)), *si));
        pk = Some(Expr::Local(2));
    }
    let log_fields = (0..c.square.len())
        .map(|k| {
            ctx.combine(
                mi,
                bi,
                k,
                Some(inv.clone()),
                dual.as_ref().map(|d| (pk.clone().expect("dual"), 1, d.3.as_slice())),
            )
        })
        .collect::<Result<Vec<_>, _>>()?;
    let log = Kernel {
        op: Op::LogUnit,
        params: vec![mi],
        lets,
        output: Output::Type(bi, log_fields),
        doc: format!(
            "log of a unit {mn} (m rev(m) = 1): the {bn} B with exp(B) = m, angle in [0, pi); a full turn gives non-finite output."
        ),
    };

    // normalize: M -> M
    let alpha = sums::sum_in::<Ir>(vec![
        ((1, 1), mul(scalar.clone(), scalar.clone()), true),
        ((-1, 1), ctx.square_form(mi, 1)?, true),
    ]);
    let mut lets = vec![alpha]; // 0: alpha
    let normalize_fields = match &dual {
        None => {
            // the Rust kernel's `1 / sqrt(alpha)`
            lets.push(Expr::Sqrt(b(Expr::Local(0)))); // 1
            lets.push(Expr::Div(b(Expr::Const((1, 1))), b(Expr::Local(1)))); // 2
            (0..m_fields).map(|f| mul(Expr::Field { param: 0, field: f }, Expr::Local(2))).collect()
        }
        Some((ii, si, half_c, i_times)) => {
            // β/2 = s p - c(B')/2; u = 1/√α, w = -(β/2) u / α; out = u M + w (s I + I B')
            let p = Expr::Field { param: 0, field: *ii };
            let half_beta = Expr::Sub(b(signed(mul(scalar.clone(), p), *si)), b(ctx.half_c(mi, half_c)?));
            lets.push(Expr::Div(b(Expr::Const((1, 1))), b(Expr::Local(0)))); // 1: 1/alpha
            lets.push(half_beta); // 2
            lets.push(Expr::Sqrt(b(Expr::Local(1)))); // 3: u
            lets.push(mul(Expr::Neg(b(mul(Expr::Local(2), Expr::Local(3)))), Expr::Local(1))); // 4: w
            let w = Expr::Local(4);
            let mut fields = Vec::new();
            for f in 0..m_fields {
                let mut v = mul(Expr::Field { param: 0, field: f }, Expr::Local(3));
                if f == *ii {
                    v = Expr::Add(b(v), b(signed(mul(scalar.clone(), w.clone()), *si)));
                } else if let Some(k) = ctx.in_m.iter().position(|&p| p == f)
                    && i_times.iter().any(|row| row.iter().any(|(dst, _)| *dst == k))
                {
                    v = Expr::Add(b(v), b(ctx.combine(mi, mi, k, None, Some((w.clone(), 1, i_times)))?));
                }
                fields.push(v);
            }
            fields
        }
    };
    let normalize = Kernel {
        op: Op::Normalize,
        params: vec![mi],
        lets,
        output: Output::Type(mi, normalize_fields),
        doc: format!("m / sqrt(m rev(m)) for a {mn}: a unit {mn}; a non-positive norm gives non-finite output."),
    };
    Ok(vec![exp, log, normalize])
}
