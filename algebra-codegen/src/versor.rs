//! The fused versor action: for a versor type `V` and an operand type `X`, one straight-line
//! kernel computing only `X`'s components of
//!
//! - `sandwich`: `rev(S) x S` (the main paper's `f_S(x)`, eq. (3)), and
//! - `apply`: `S x rev(S)` (the convention of klein, GATL and ganja),
//!
//! built from the exact tables in two stages: the intermediate `rev(S) x` (or `S x`) keeps only
//! the coefficients that reach an output component, and the output sums their products with
//! `S` (or `rev(S)`). The result is the projection of the full product onto `X`: it *is* the
//! action whenever `S` is a versor whose action preserves `X`'s grades (motors and rotors on
//! vectors, bivectors, points, lines, planes, motors), since the other components then vanish.
//!
//! Versor types are the declared types (other than the full multivector) whose basis elements
//! all have the same parity; every other pair keeps the composed full product.

use super::{CodegenError, ModuleSpec};
use crate::ratio::{Ratio, is_unit, to_ratio};
use algebra_core::rational::Q;
use algebra_core::tables::{Product, Unary};
use algebra_core::{Basis, Multivector};
use num_traits::Zero;
use std::collections::BTreeMap;

/// Which side of the operand carries the reverse.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Convention {
    /// `rev(S) x S` (`sandwich`, the main paper's).
    Sandwich,
    /// `S x rev(S)` (`apply`, klein/GATL/ganja).
    Apply,
}

/// One fused action kernel.
#[derive(Debug, Clone)]
pub struct ActionKernel {
    /// The convention.
    pub convention: Convention,
    /// Versor type index.
    pub versor: usize,
    /// Operand (and output) type index.
    pub operand: usize,
    /// The intermediate coefficients: each a sum of `c · s[a] · x[b]` as `(a, b, c)`.
    pub stage1: Vec<Vec<(usize, usize, Ratio)>>,
    /// Each output field: a sum of `c · t[k] · s[a]` as `(k, a, c)`.
    pub stage2: Vec<Vec<(usize, usize, Ratio)>>,
    /// The basis masks outside the operand type where the full product is structurally
    /// non-zero: the kernel drops them (they vanish for versors only).
    pub outside: Vec<u32>,
    /// Whether each stage's sums are chains (`a + b - c + d`) rather than balanced trees
    /// (`(a + b) + (d - c)`, the default): chosen per kernel by [`order_for_pairing`].
    pub chains: [bool; 2],
    /// The scalar-norm form ([`NormForm`]), when the versor type's norm is a scalar for every
    /// element and the form is cheaper: then stage 1 is the scaled commutator and stage 2 the
    /// correction, as in [`super::unit`].
    pub norm: Option<NormForm>,
    /// The versor fields used negated (bit `a`: `s[a]` enters every product as `-s[a]`, the
    /// coefficients of its terms negated to match), chosen per kernel by [`order_for_pairing`]
    /// so that neighbouring sums have the same signs (a cross product's `v = (b23, -b13,
    /// b12)`); the negation is of the versor's coefficient, off the operand's chain.
    pub flip: u32,
    /// Stage 1's constants other than ±1 multiply the operand's coefficient, bound once per
    /// (constant, field) before the intermediates (`let xc = 2 · x.eo;`, then `s.e1inf · xc`),
    /// instead of the versor's coefficient in each term (`(2 · s.e1inf) · x.eo`): one
    /// multiplication per distinct pair instead of one per term. Set by the plan for every
    /// straight-line general kernel (the conformal point actions: `2 xo` read by four
    /// intermediates).
    pub operand_constants: bool,
}

/// `out_j = n · x_j + scale · Σ stage2_j` with `n = Σ c · s[a] · s[b]` (the scalar
/// `rev(S) S` of `sandwich`, `S rev(S)` of `apply`): the identity
/// `rev(S) x S = x (rev(S) S) + (rev(S) x - x rev(S)) S`, projected onto `x`'s type, where
/// `x (rev(S) S)` projects to `n x` for every element of the versor type: the norm is a scalar
/// ([`scalar_norm`]), or its other components put nothing into `x`'s type (checked
/// symbolically, [`norm_acts_as_scalar`]). The generalised quaternion (Rodrigues) form
/// `|R|² x + 2 s (b × x) + 2 b × (b × x)` of a rotor's action is this form in `g3`; a
/// conformal motor on a point, whose norm `α + β e123inf` is not a scalar, takes it too (45
/// multiplications and 35 additions instead of 61 and 43 in `cga_null`).
#[derive(Debug, Clone, PartialEq)]
pub struct NormForm {
    /// The norm's terms `(a, b, c)`, `a <= b`: `n = Σ c · s[a] · s[b]`.
    pub terms: Vec<(usize, usize, Ratio)>,
    /// The common factor taken out of stage 1 (2 for rotors).
    pub scale: Ratio,
}

impl ActionKernel {
    /// The distinct `(|c|, operand field)` of stage 1's constants other than ±1, in order of
    /// first use: the bindings of [`ActionKernel::operand_constants`].
    pub fn operand_constant_fields(&self) -> Vec<(Ratio, usize)> {
        let mut out: Vec<(Ratio, usize)> = Vec::new();
        for &(_, b, c) in self.stage1.iter().flatten() {
            let key = ((c.0.abs(), c.1), b);
            if !is_unit(c) && !out.contains(&key) {
                out.push(key);
            }
        }
        out
    }

    /// Multiplications and additions (as [`super::plan::KernelStats`] counts them).
    pub fn counts(&self) -> (usize, usize) {
        let is_const = |c: &Ratio| !is_unit(*c);
        let consts = |s: &[Vec<(usize, usize, Ratio)>]| s.iter().flatten().filter(|t| is_const(&t.2)).count();
        let terms = |s: &[Vec<(usize, usize, Ratio)>]| -> (usize, usize) {
            let products = s.iter().map(Vec::len).sum::<usize>();
            let adds = s.iter().map(|o| o.len().saturating_sub(1)).sum();
            (products + consts(s), adds)
        };
        let (mut m1, a1) = terms(&self.stage1);
        if self.operand_constants {
            // one product per distinct (constant, operand field) instead of one per term
            m1 = m1 - consts(&self.stage1) + self.operand_constant_fields().len();
        }
        let (m2, a2) = terms(&self.stage2);
        let Some(norm) = &self.norm else { return (m1 + m2, a1 + a2) };
        // the norm, `n · x_j` per output, and `+ scale · y` per corrected output
        let nm = norm.terms.len() + norm.terms.iter().filter(|t| !is_unit(t.2)).count();
        let na = norm.terms.len().saturating_sub(1);
        let corrected = self.stage2.iter().filter(|r| !r.is_empty()).count();
        let (sm, sa) = match norm.scale {
            (1, 1) => (0, corrected),
            (2, 1) => (0, 2 * corrected),
            _ => (corrected, corrected),
        };
        (m1 + m2 + nm + self.stage2.len() + sm, a1 + a2 + na + sa)
    }
}

/// Whether type `i` is a versor type: not the full type, every element of one parity.
pub fn is_versor_type(spec: &ModuleSpec, full: usize, i: usize) -> bool {
    let els = &spec.types[i].elements;
    i != full && els.iter().all(|m| m.count_ones() % 2 == els[0].count_ones() % 2)
}

/// The fused kernels of every (versor type, operand type other than the full one) pair, in
/// both conventions.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, versor::{Convention, plan_actions}};
/// let alg = Algebra::builtin("cga-null").unwrap();
/// let types = ModuleSpec::parse_types("Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1", &alg).unwrap();
/// let spec = ModuleSpec::new("cga_null", alg.metric().clone(), Basis::Product, types).unwrap();
/// let actions = plan_actions(&spec, 2).unwrap();
/// // Motor and Vector are versor types; each acts on vectors, in both conventions, and the
/// // motor on motors. A vector (a sphere inversion) takes a motor out of the `Motor` type, so
/// // that pair has no fused kernel ([`keeps_operand`]).
/// assert_eq!(actions.len(), 6);
/// let k = actions.iter().find(|k| (k.versor, k.operand, k.convention) == (0, 1, Convention::Sandwich)).unwrap();
/// assert_eq!(k.counts(), (64, 43)); // the pose on a conformal point (motor product: 48, 40)
/// ```
pub fn plan_actions(spec: &ModuleSpec, full: usize) -> Result<Vec<ActionKernel>, CodegenError> {
    let mut out = Vec::new();
    for v in (0..spec.types.len()).filter(|&v| is_versor_type(spec, full, v)) {
        for x in (0..spec.types.len()).filter(|&x| x != full) {
            let (s, a) = (action(spec, Convention::Sandwich, v, x)?, action(spec, Convention::Apply, v, x)?);
            if keeps_operand(spec, &s) && keeps_operand(spec, &a) {
                out.extend([s, a]);
            }
        }
    }
    Ok(out)
}

/// The mean number of terms per output at or below which [`order_for_pairing`] reorders a
/// kernel's terms by its default rule (measured, docs/performance.md "Term order of the fused
/// actions").
const PAIRING_MEAN_TERMS: usize = 6;

/// The order of one stage's summands. Stage 1 sums `c · s[a] · x[b]` (versor field `a`,
/// operand field `b`), stage 2 sums `c · t[k] · s[a]` (intermediate `k`, versor field `a`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RowOrder {
    /// The tables' order: stage 1 by `(a, b)`, stage 2 by `(k, a)`.
    Tables,
    /// By the versor's field first (stage 1 `(a, b)`, stage 2 `(a, k)`); a row that would start
    /// with a negative term starts with its first positive one (no negation of the sum).
    Versor,
    /// By the other factor first (stage 1 `(b, a)`, stage 2 `(k, a)`), the same sign rule.
    Other,
    /// The positive terms first, each part in the tables' order.
    PositiveFirst,
    /// The positive terms first, each part by the versor's field.
    PositiveVersor,
    /// The positive terms first, each part by the other factor.
    PositiveOther,
    /// The tables' order, the positive terms first within each half of the row (as the
    /// motor product's measured order does within its `R x T` and `T x R` halves).
    PositiveHalves,
    /// By the versor's field, the positive terms first within each half of the row.
    PositiveHalvesVersor,
}

/// The order and shape of a fused kernel's sums: one entry of the pairing wisdom
/// ([`order_for_pairing`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TermOrder {
    /// Stage 1's summand order.
    pub stage1: RowOrder,
    /// Stage 2's summand order.
    pub stage2: RowOrder,
    /// Chains instead of balanced trees (stage 1, stage 2).
    pub chains: [bool; 2],
    /// The versor fields used negated ([`ActionKernel::flip`]).
    pub flip: u32,
    /// The order of the norm's terms in the scalar-norm form ([`NormForm`]).
    pub norm: NormOrder,
}

/// The order of the norm's terms `c · s[a] · s[b]` (summed as a balanced tree).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NormOrder {
    /// By `(a, b)`: `(s0² + s1²) + (s2² + s3²)`.
    Tables,
    /// First with last, second with second-to-last: `(s0² + s3²) + (s1² + s2²)`.
    Outside,
    /// First half beside second half: `(s0² + s2²) + (s1² + s3²)`.
    Halves,
}

impl TermOrder {
    /// The tables' order, balanced trees: the kernel as planned.
    pub const TABLES: TermOrder = TermOrder {
        stage1: RowOrder::Tables,
        stage2: RowOrder::Tables,
        chains: [false, false],
        flip: 0,
        norm: NormOrder::Tables,
    };
}

fn order_row(row: &mut [(usize, usize, Ratio)], order: RowOrder, stage2: bool) {
    // the tables' order is `(t.0, t.1)` in both stages: stage 1 `(a, b)`, stage 2 `(k, a)`
    let versor = |t: &(usize, usize, Ratio)| if stage2 { (t.1, t.0) } else { (t.0, t.1) };
    let other = |t: &(usize, usize, Ratio)| if stage2 { (t.0, t.1) } else { (t.1, t.0) };
    let neg = |t: &(usize, usize, Ratio)| t.2.0 < 0;
    match order {
        RowOrder::Tables => row.sort_by_key(|t| (t.0, t.1)),
        RowOrder::Versor => row.sort_by_key(versor),
        RowOrder::Other => row.sort_by_key(other),
        RowOrder::PositiveFirst => row.sort_by_key(|t| (neg(t), t.0, t.1)),
        RowOrder::PositiveVersor => row.sort_by_key(|t| (neg(t), versor(t))),
        RowOrder::PositiveOther => row.sort_by_key(|t| (neg(t), other(t))),
        RowOrder::PositiveHalves | RowOrder::PositiveHalvesVersor => {
            if order == RowOrder::PositiveHalves {
                row.sort_by_key(|t| (t.0, t.1));
            } else {
                row.sort_by_key(versor);
            }
            let half = row.len().div_ceil(2);
            let (a, b) = row.split_at_mut(half);
            a.sort_by_key(neg);
            b.sort_by_key(neg);
        }
    }
    if matches!(order, RowOrder::Versor | RowOrder::Other)
        && row.first().is_some_and(neg)
        && let Some(p) = row.iter().position(|t| t.2.0 > 0)
    {
        row[..=p].rotate_right(1);
    }
}

/// Puts a kernel's terms in `order` (from any order: each row is sorted from scratch).
/// Only the order of the summands and the shape of the sums change, so every value over
/// exact scalars is the same.
pub fn apply_order(k: &mut ActionKernel, order: TermOrder) {
    // the versor's negated fields: from `k.flip` to `order.flip`
    let change = k.flip ^ order.flip;
    let negate = |c: &mut Ratio| c.0 = -c.0;
    for (a, _, c) in k.stage1.iter_mut().flatten() {
        if change >> *a & 1 == 1 {
            negate(c);
        }
    }
    for (_, a, c) in k.stage2.iter_mut().flatten() {
        if change >> *a & 1 == 1 {
            negate(c);
        }
    }
    k.flip = order.flip;
    k.stage1.iter_mut().for_each(|row| order_row(row, order.stage1, false));
    k.stage2.iter_mut().for_each(|row| order_row(row, order.stage2, true));
    k.chains = order.chains;
    if let Some(norm) = &mut k.norm {
        norm.terms.sort_by_key(|t| (t.0, t.1));
        let n = norm.terms.len();
        let perm: Vec<usize> = match order.norm {
            NormOrder::Tables => (0..n).collect(),
            NormOrder::Outside => (0..n).map(|i| if i % 2 == 0 { i / 2 } else { n - 1 - i / 2 }).collect(),
            NormOrder::Halves => (0..n).map(|i| if i % 2 == 0 { i / 2 } else { n.div_ceil(2) + i / 2 }).collect(),
        };
        norm.terms = perm.iter().map(|&i| norm.terms[i]).collect();
    }
}

/// A fingerprint of a kernel's structure: its convention, form and terms in the tables'
/// order (FNV-1a), the key of the pairing wisdom ([`WISDOM`]). Independent of the kernel's
/// current term order.
pub fn fingerprint(k: &ActionKernel) -> u64 {
    let mut canonical = k.clone();
    apply_order(&mut canonical, TermOrder::TABLES);
    let text = format!(
        "{:?} {:?} {:?} {:?}",
        canonical.convention,
        canonical.norm.as_ref().map(|n| (&n.terms, n.scale)),
        canonical.stage1,
        canonical.stage2
    );
    crate::fnv1a(&text)
}

/// Orders chosen per kernel by measurement (the "wisdom", as FFTW's): fingerprint
/// ([`fingerprint`]), the kernel it was measured on, and the order. Kernels not listed take
/// [`default_order`]. Re-derive with `cargo run --release -p algebra-codegen --example
/// pairing_wisdom` (docs/performance.md, "fifth session"): it times every candidate order of
/// the benched kernels beside their module's motor product in one `rustc -O` program (the
/// generated kernel bodies, interleaved rounds, pinned to one core) and prints the table.
/// Measured on 2-core VMs, baseline x86-64 (SSE2), rustc 1.95: an AMD EPYC for `g3`'s two
/// entries, an Intel Xeon for the others (the comments above them). Every entry is a
/// scalar-norm form ([`NormForm`]).
pub const WISDOM: &[(u64, &str, TermOrder)] = {
    use NormOrder::{Halves, Outside, Tables as NormTables};
    use RowOrder::{
        PositiveFirst, PositiveHalves, PositiveHalvesVersor, PositiveOther, PositiveVersor, Tables, Versor,
    };
    const fn o(stage1: RowOrder, stage2: RowOrder, chains: [bool; 2], flip: u32, norm: NormOrder) -> TermOrder {
        TermOrder { stage1, stage2, chains, flip, norm }
    }
    &[
        // `g3::Rotor::sandwich(&Vector)`, scalar-norm form: `-b12`, `-b23` (a cross product's
        // signs), the norm `(s² + b13²) + (b12² + b23²)`: 1.217 (default order 1.543)
        (0x4be0_8e33_f956_df99, "g3 Rotor sandwich Vector", o(Tables, PositiveFirst, [true, false], 0b1010, Halves)),
        // `g3::Rotor::apply(&Vector)`, scalar-norm form: `-s`, `-b13`, the norm
        // `(s² + b23²) + (b12² + b13²)`: 1.303 (the general kernel 1.384)
        (0xfb5b_ad7b_ab55_ccde, "g3 Rotor apply Vector", o(Tables, Versor, [true, false], 0b0101, Outside)),
        // The conformal and pga3 point actions take the norm form (`norm_acts_as_scalar`: the
        // norm `α + β e123inf`, or `α + β e0123`, puts nothing into a point), measured on an
        // Intel Xeon, 2026-12-05 (twelfth session) with `pairing_wisdom`, against the motor
        // product in its measured order (`crate::product_order::WISDOM`). The orders of their
        // general kernels, which these replace, are in docs/performance.md.
        // `cga_null::Motor::sandwich(&Vector)`, `-s -e23 -e1inf -e3inf -e123inf`: 0.991
        // (the general kernel in its best order 1.303)
        (
            0xb2cc_f7a2_4497_b931,
            "cga_null Motor sandwich Vector, norm form",
            o(Versor, PositiveVersor, [false, false], 0b1101_1001, Halves),
        ),
        // `cga_null::Motor::apply(&Vector)`, `-s -e13 -e23 -e2inf -e3inf -e123inf`: 0.982
        // (general 1.279)
        (
            0x334f_a0fe_d977_8b55,
            "cga_null Motor apply Vector, norm form",
            o(PositiveOther, PositiveVersor, [true, false], 0b1110_1101, Halves),
        ),
        // GATL's declaration `Motor::sandwich(&Vector)`, `-s -e12 -e1inf`: 0.984 (general 1.240)
        (
            0x074f_5c08_e424_5735,
            "gatl Motor sandwich Vector, norm form",
            o(PositiveHalves, PositiveFirst, [false, false], 0b1_0011, Halves),
        ),
        // GATL's declaration `Motor::apply(&Vector)`, `-s -e123inf`: 0.966 (general 1.216)
        (
            0x37db_2959_0dbb_4327,
            "gatl Motor apply Vector, norm form",
            o(Versor, Versor, [false, false], 0b1000_0001, Halves),
        ),
        // `pga3::Motor::sandwich(&Trivector)` (the point action), `-e01 -e02 -e03 -e23`: 0.496
        // (general 0.814)
        (
            0xf05e_31d1_0a25_d331,
            "pga3 Motor sandwich Trivector, norm form",
            o(Tables, PositiveVersor, [false, false], 0b101_0110, Halves),
        ),
        // `pga3::Motor::apply(&Trivector)`, `-e23 -e0123`: 0.510 (general 0.834)
        (
            0x2f5a_ffe7_e1bc_0dfc,
            "pga3 Motor apply Trivector, norm form",
            o(Tables, PositiveVersor, [false, true], 0b1100_0000, Outside),
        ),
        // `cga::Motor::sandwich(&Vector)` (16-field motors; flips not searched), norm form:
        // 0.544 (general 0.571)
        (
            0x36ac_24cd_b7d8_9fb6,
            "cga Motor sandwich Vector, norm form",
            o(PositiveFirst, PositiveHalvesVersor, [false, false], 0, NormTables),
        ),
    ]
};

/// The order of a kernel without wisdom: in kernels whose outputs have at most six terms on
/// average, stage 2 by the versor's field and `sandwich`'s stage 1 positive terms first
/// (`apply`'s in the tables' order), trees; longer kernels keep the tables' order.
pub fn default_order(k: &ActionKernel) -> TermOrder {
    let terms: usize = k.stage2.iter().map(Vec::len).sum();
    if terms > PAIRING_MEAN_TERMS * k.stage2.len() {
        return TermOrder::TABLES;
    }
    let stage1 = match k.convention {
        Convention::Sandwich => RowOrder::PositiveFirst,
        Convention::Apply => RowOrder::Tables,
    };
    TermOrder { stage1, stage2: RowOrder::Versor, chains: [false, false], flip: 0, norm: NormOrder::Tables }
}

/// Reorders the terms of a fused kernel for LLVM's SLP vectoriser, which packs two adjacent
/// outputs (and two adjacent intermediates) into one SSE register when their expression trees
/// have the same shape. Only the order of the summands (and the shape of the sums: trees or
/// chains) changes, so every value over exact scalars is the same (and the other languages'
/// kernels, printed from the same terms, keep adding in the Rust kernel's order).
///
/// A kernel listed in [`WISDOM`] (by its [`fingerprint`]) takes the order measured fastest
/// for it; every other kernel [`default_order`]:
///
/// - Stage 2 (each output a sum of `t[k] · s[a]`): the terms in the order of the versor field
///   `a` (then `k`), so term `i` of two neighbouring outputs multiplies the same versor
///   coefficient (one broadcast) by two intermediates, instead of the intermediate-major order
///   of the tables, where it multiplies one intermediate by two versor fields in no particular
///   order.
///   A row that would start with a negative term starts with its first positive one instead
///   (no negation of the whole sum).
/// - Stage 1 of `sandwich` (`rev(S) x`, where the reverse scatters the signs): the positive
///   terms first (stable), so neighbouring intermediates more often have the same tree of
///   additions and subtractions. `apply`'s stage 1 (`S x`) keeps its order: sorting it was
///   slower.
///
/// Applied only when the outputs have at most 6 terms on average (`PAIRING_MEAN_TERMS`): the
/// conformal point actions (4-8 terms) and `g3`'s rotor action (4) got faster, `pga3`'s
/// point action (4-8, mean 7) and `cga`'s 16-term outputs slower, where the tables' order
/// already gives neighbouring outputs the same deep trees.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, plan::Plan, versor::Convention};
/// let alg = Algebra::builtin("g3").unwrap();
/// let types = ModuleSpec::parse_types("Vector=grade1;Rotor=even", &alg).unwrap();
/// let plan = Plan::new(ModuleSpec::new("g3", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
/// let k = plan.actions.iter().find(|k| (k.versor, k.operand, k.convention) == (1, 1, Convention::Sandwich)).unwrap();
/// // each output's terms by the rotor's field
/// assert!(k.stage2.iter().all(|row| row.windows(2).all(|w| w[0].1 <= w[1].1)));
/// // each intermediate's positive terms first
/// assert!(k.stage1.iter().all(|row| row.windows(2).all(|w| w[0].2.0 > 0 || w[1].2.0 < 0)));
/// ```
///
/// A table-driven kernel (above the size threshold, [`crate::size`]) takes [`default_order`]:
/// the table loops read the versor's fields as they are, so they cannot negate one.
pub fn order_for_pairing(k: &mut ActionKernel, table_driven: bool) {
    let f = fingerprint(k);
    let wisdom = WISDOM.iter().find(|w| w.0 == f).filter(|_| !table_driven);
    let order = wisdom.map_or_else(|| default_order(k), |w| w.2);
    apply_order(k, order);
}

/// Whether the norm of the versor type `v` in `convention` (`rev(S) S` for `sandwich`,
/// `S rev(S)` for `apply`) is a scalar for *every* element `S` of the type, decided exactly:
/// the product is expanded from the exact rational tables as a polynomial in the type's
/// coefficients (the monomials `s_a s_b`), and every component but the scalar must be the zero
/// polynomial. True for `g3`'s rotors
/// (quaternions) and for vectors; false for motors with a translation part, whose norm has a
/// pseudoscalar part (`α + β ω`) unless they are versors.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, versor::{Convention, scalar_norm}};
/// let g3 = Algebra::builtin("g3").unwrap();
/// let types = ModuleSpec::parse_types("Rotor=even", &g3).unwrap();
/// let spec = ModuleSpec::new("g3", g3.metric().clone(), Basis::Blade, types).unwrap();
/// assert!(scalar_norm(&spec, 0, Convention::Sandwich) && scalar_norm(&spec, 0, Convention::Apply));
/// let pga = Algebra::builtin("pga3").unwrap();
/// let types = ModuleSpec::parse_types("Motor=even", &pga).unwrap();
/// let spec = ModuleSpec::new("pga3", pga.metric().clone(), Basis::Blade, types).unwrap();
/// assert!(!scalar_norm(&spec, 0, Convention::Sandwich)); // `rev(M) M = α + β e0123`
/// ```
pub fn scalar_norm(spec: &ModuleSpec, v: usize, convention: Convention) -> bool {
    norm_polynomial(spec, v, convention).iter().all(|(&k, p)| k == 0 || p.values().all(Zero::is_zero))
}

/// Whether `x N` projected onto the operand type `x` is `n · x` for every element `S` of the
/// versor type `v` and every `x`, where `N` is the norm (`rev(S) S` for `sandwich`, `S rev(S)`
/// for `apply`) and `n` its scalar part: the norm's other components, whatever their
/// coefficients, put nothing into `x`'s type. Decided exactly, from `N` as a polynomial in the
/// versor's coefficients ([`scalar_norm`]'s expansion) multiplied by each of `x`'s basis
/// elements. This is what the scalar-norm form ([`NormForm`]) needs: its identity
/// `rev(S) x S = x (rev(S) S) + (rev(S) x - x rev(S)) S` holds for every `S`, and only `x`'s
/// components of it are kept. It holds when the norm is a scalar ([`scalar_norm`]), and also
/// for motors with a translation part, whose norm `α + β I` has a pseudoscalar-like part of
/// grade 4 that turns a vector (or a point of 3D PGA, a trivector) into other grades.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, versor::{Convention, norm_acts_as_scalar, scalar_norm}};
/// let alg = Algebra::builtin("cga-null").unwrap();
/// let types = ModuleSpec::parse_types("Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1;Bivector=grade2", &alg).unwrap();
/// let spec = ModuleSpec::new("c", alg.metric().clone(), Basis::Product, types).unwrap();
/// // `rev(M) M = α + β e123inf` is not a scalar, but `x e123inf` has no vector part
/// assert!(!scalar_norm(&spec, 0, Convention::Sandwich));
/// assert!(norm_acts_as_scalar(&spec, 0, 1, Convention::Sandwich));
/// assert!(norm_acts_as_scalar(&spec, 0, 1, Convention::Apply));
/// // a bivector times `e123inf` has a bivector part (`e12 e123inf = -e3inf`)
/// assert!(!norm_acts_as_scalar(&spec, 0, 2, Convention::Sandwich));
/// ```
pub fn norm_acts_as_scalar(spec: &ModuleSpec, v: usize, x: usize, convention: Convention) -> bool {
    let gp = spec.algebra.tables().product(spec.basis, Product::Geometric);
    let xm = &spec.types[x].elements;
    // Σ over the norm's non-scalar components k: x_b e_b · P_k(s) e_k, kept where it lands in X
    let mut image: BTreeMap<(u32, usize, (usize, usize)), Q> = BTreeMap::new();
    for (&k, p) in norm_polynomial(spec, v, convention).iter().filter(|(k, _)| **k != 0) {
        for (b, &mb) in xm.iter().enumerate() {
            for (j, c) in gp.get(mb, k).expect("a mask of the spec's algebra") {
                if xm.contains(j) {
                    for (&mono, pc) in p {
                        *image.entry((*j, b, mono)).or_insert_with(Q::zero) += c * pc;
                    }
                }
            }
        }
    }
    image.values().all(Zero::is_zero)
}

/// The norm of the versor type `v` (`rev(S) S` for `sandwich`, `S rev(S)` for `apply`) as a
/// polynomial per basis mask: the coefficient of the monomial `s_a s_a'`, keyed `(min, max)`.
fn norm_polynomial(spec: &ModuleSpec, v: usize, convention: Convention) -> BTreeMap<u32, BTreeMap<(usize, usize), Q>> {
    let tables = spec.algebra.tables();
    let (gp, rev) = (tables.product(spec.basis, Product::Geometric), tables.unary(spec.basis, Unary::Reverse));
    let vm = &spec.types[v].elements;
    // the product as a polynomial per basis mask: monomial `s_a s_a'` keyed `(min, max)`
    let mut poly: BTreeMap<u32, BTreeMap<(usize, usize), Q>> = BTreeMap::new();
    for (a, &ma) in vm.iter().enumerate() {
        for (b, &mb) in vm.iter().enumerate() {
            let (left, right) = match convention {
                Convention::Sandwich => (
                    rev.image(ma).expect("a mask of the spec's algebra").to_vec(),
                    vec![(mb, Q::from_integer(1.into()))],
                ),
                Convention::Apply => (
                    vec![(ma, Q::from_integer(1.into()))],
                    rev.image(mb).expect("a mask of the spec's algebra").to_vec(),
                ),
            };
            for (l, cl) in &left {
                for (r, cr) in &right {
                    for (k, c) in gp.get(*l, *r).expect("a mask of the spec's algebra") {
                        *poly.entry(*k).or_default().entry((a.min(b), a.max(b))).or_insert_with(Q::zero) += cl * cr * c;
                    }
                }
            }
        }
    }
    poly
}

/// The share of the general kernel's operations (multiplications plus additions) at or below
/// which the plan takes the scalar-norm form ([`norm_form`]) without a measured order: 4/5.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, plan::Plan, versor::{Convention, NORM_FORM_SAVING}};
/// // 3D PGA with klein's orientation: not in the wisdom, yet its point action takes the form
/// let alg = Algebra::builtin("pga3").unwrap();
/// let types = ModuleSpec::parse_types("Point=e032,e013,e021,e123;Motor=1,e23,e31,e12,e01,e02,e03,e0123", &alg).unwrap();
/// let plan = Plan::new(ModuleSpec::new("k", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
/// let k = plan.actions.iter().find(|k| (k.versor, k.operand, k.convention) == (1, 0, Convention::Apply)).unwrap();
/// assert!(k.norm.is_some());
/// let (num, den) = NORM_FORM_SAVING;
/// assert!((k.counts().0 + k.counts().1) * den <= 84 * num); // the general kernel: 84
/// ```
pub const NORM_FORM_SAVING: (usize, usize) = (4, 5);

/// Replaces each fused kernel of `plan` by its scalar-norm form ([`norm_form`]) when the
/// form is exact for every element of the versor type ([`norm_acts_as_scalar`]), the general
/// kernel is straight-line code (not table-driven, [`crate::size`]), and the form needs
/// fewer operations (multiplications plus additions), with either its term order measured
/// ([`WISDOM`]) or at least a fifth fewer operations ([`NORM_FORM_SAVING`]). The form is exact
/// over any ring for every element of the type, as the general kernel is.
///
/// The second condition is what was measured: in the default order the form was *slower*
/// than the general kernel where it saves little (`g3`'s rotor on a vector, 40 operations
/// against 41: 1.54x the rotor product against 1.40x; 1.21x with the measured order, a cross
/// product's signs), and faster, by 13-42 %, wherever it saves a seventh or more (the
/// conformal point actions, `pga3`'s motor on a point and on a plane, `cga`'s 16-field
/// motors; docs/performance.md, "twelfth session"). So a declaration the wisdom does not know
/// (another orientation, metric or basis) gets the form where it saves a fifth. Run after the
/// action matrices are composed (they use the general form).
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, plan::Plan, versor::{self, Convention}};
/// let alg = Algebra::builtin("g3").unwrap();
/// let types = ModuleSpec::parse_types("Vector=grade1;Rotor=even", &alg).unwrap();
/// let plan = Plan::new(ModuleSpec::new("g3", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
/// let k = plan.actions.iter().find(|k| (k.versor, k.operand, k.convention) == (1, 0, Convention::Sandwich)).unwrap();
/// let form = versor::norm_form(&plan, k).unwrap().unwrap();
/// let norm = form.norm.as_ref().unwrap();
/// assert_eq!((norm.terms.len(), norm.scale), (4, (2, 1))); // s² + b12² + b13² + b23², 2
/// assert_eq!(form.counts(), (22, 18)); // the general kernel: 24, 18
/// // the plan takes it for this kernel: cheaper, and its order is in the wisdom
/// assert!(k.norm.is_some());
/// ```
pub(crate) fn norm_forms(plan: &mut crate::plan::Plan) -> Result<(), CodegenError> {
    for i in 0..plan.actions.len() {
        let k = &plan.actions[i];
        let Some(form) = norm_form(plan, k)? else { continue };
        let cost = |k: &ActionKernel| {
            let (m, a) = k.counts();
            m + a
        };
        let (new, old) = (cost(&form), cost(k));
        let (num, den) = NORM_FORM_SAVING;
        let measured = || WISDOM.iter().any(|w| w.0 == fingerprint(&form));
        if new < old && (new * den <= old * num || measured()) {
            plan.actions[i] = form;
        }
    }
    Ok(())
}

/// The scalar-norm form ([`NormForm`]) of a planned fused kernel, in the tables' order, when
/// it is exact for every element of the versor type ([`norm_acts_as_scalar`]) and the kernel is
/// straight-line code; `None` otherwise. The plan uses it only where it is cheaper and either
/// its order was measured ([`WISDOM`]) or it saves a fifth of the operations
/// ([`NORM_FORM_SAVING`]); `examples/pairing_wisdom.rs` times both forms.
///
/// # Errors
/// A coefficient does not fit `i64/i64`.
pub fn norm_form(plan: &crate::plan::Plan, k: &ActionKernel) -> Result<Option<ActionKernel>, CodegenError> {
    let lens = k.stage1.iter().chain(&k.stage2).map(Vec::len);
    if crate::size::table_driven(plan.spec.table_above, plan.declared, &[k.versor, k.operand], lens)
        || !norm_acts_as_scalar(&plan.spec, k.versor, k.operand, k.convention)
    {
        return Ok(None);
    }
    let u = super::unit::unit_kernel(&plan.spec, k.convention, k.versor, k.operand)?;
    let terms = plan.norm[k.versor].iter().map(|t| (t.lhs, t.rhs, t.coef)).collect();
    Ok(Some(ActionKernel { outside: k.outside.clone(), norm: Some(NormForm { terms, scale: u.scale }), ..u.kernel }))
}

/// Whether a fused kernel is the action of every versor of its type: each component it drops
/// (outside the operand type) has a grade the operand type does not have, so it vanishes for
/// every versor, whose action preserves grades. A dropped component of one of the operand's
/// own grades is a real part of the image: a translation moves the plane `e1` of 3D PGA,
/// declared as `Direction = [e1, e2, e3]`, to `e1 + d e0`, and a projection onto `Direction`
/// would silently lose `d`. Such a pair gets no fused kernel (nor a unit one, nor an action
/// matrix): its `sandwich` and `apply` are the composed full products, whose type holds the
/// whole image. Grades are those of the blade expansion, so a product-basis element such as
/// `e0 einf` (grades 0 and 2) counts as both.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, versor::{keeps_operand, plan_actions}};
/// let alg = Algebra::builtin("pga3").unwrap();
/// let types = ModuleSpec::parse_types("Motor=even;Plane=grade1;Direction=e1,e2,e3", &alg).unwrap();
/// let spec = ModuleSpec::new("p", alg.metric().clone(), Basis::Blade, types).unwrap();
/// let actions = plan_actions(&spec, 3).unwrap();
/// // the motor acts on planes through a fused kernel, on `Direction` through full products
/// // (so do planes: a reflection in a plane off the origin moves `e1` off it); reflections in
/// // `Direction`s keep a `Direction` one
/// assert!(actions.iter().any(|k| (k.versor, k.operand) == (0, 1)));
/// assert!(!actions.iter().any(|k| k.operand == 2 && k.versor != 2));
/// assert!(actions.iter().any(|k| (k.versor, k.operand) == (2, 2)));
/// assert!(actions.iter().all(|k| keeps_operand(&spec, k)));
/// ```
pub fn keeps_operand(spec: &ModuleSpec, k: &ActionKernel) -> bool {
    let grades = |mask: u32| -> Vec<u32> {
        let m = Multivector::<Q>::from_mask(&spec.algebra, spec.basis, mask).expect("a mask of the spec's algebra");
        m.in_basis(Basis::Blade).terms().filter(|(_, _, c)| !c.is_zero()).map(|(b, _, _)| b.count_ones()).collect()
    };
    let own: Vec<u32> = spec.types[k.operand].elements.iter().flat_map(|&m| grades(m)).collect();
    k.outside.iter().all(|&m| grades(m).iter().all(|g| !own.contains(g)))
}

/// Whether a type is a kinematic versor type (a motor or rotor): every basis element even, and
/// the scalar `1` among them (so it holds the identity motion). Their action matrices stay
/// straight-line code (`emit::matrix`, the batch transforms); the default standalone file keeps
/// the actions of these types only, and bivector types (`Line`) and odd versors (reflections in
/// planes, point reflections) act there through `--ops` or `--every-type`.
///
/// ```
/// use algebra_codegen::versor::is_kinematic;
/// assert!(is_kinematic(&[0, 0b011, 0b101, 0b110])); // 1, e12, e13, e23: a rotor
/// assert!(!is_kinematic(&[0b011, 0b101, 0b110])); // bivectors: no identity
/// assert!(!is_kinematic(&[0, 0b001])); // 1 + e1: not even
/// ```
pub fn is_kinematic(elements: &[u32]) -> bool {
    elements.contains(&0) && elements.iter().all(|m| m.count_ones() % 2 == 0)
}

fn action(spec: &ModuleSpec, convention: Convention, v: usize, x: usize) -> Result<ActionKernel, CodegenError> {
    action_kernel(spec, convention, v, x, false)
}

/// Whether the blade of `mask` is also the geometric product of its generators: every pair of
/// them is orthogonal, so the element is the same in the blade and the product basis.
fn same_in_both_bases(spec: &ModuleSpec, mask: u32) -> bool {
    let metric = spec.algebra.metric();
    let gens: Vec<usize> = (0..32).filter(|i| mask >> i & 1 == 1).collect();
    gens.iter().enumerate().all(|(n, &i)| gens[n + 1..].iter().all(|&j| metric.gram(i, j).is_ok_and(Zero::is_zero)))
}

/// The two stages of an action; with `commutator`, stage 1 is `L(S) x - x L(S)` instead of
/// `L(S) x` (the unit-versor form of [`super::unit`]).
///
/// In a blade basis with a non-diagonal metric (GATL's conformal `eo, einf`), the intermediate
/// `L(S) x` expanded in blades such as `e1 ∧ eo ∧ einf` multiplies out into more terms than in
/// the product basis (`e1 eo einf`), where a null pair's products stay single terms. When
/// every field of `S` and `x` is the same element in both bases (their generators pairwise
/// orthogonal: motors and points of the conformal model), the intermediate may be taken in
/// either: the kernel with fewer operations is kept (the module's own basis on a tie), its
/// inputs and outputs unchanged. The components dropped outside `x` are named in the
/// module's basis.
pub(super) fn action_kernel(
    spec: &ModuleSpec,
    convention: Convention,
    v: usize,
    x: usize,
    commutator: bool,
) -> Result<ActionKernel, CodegenError> {
    let own = action_kernel_in(spec, spec.basis, convention, v, x, commutator)?;
    let (vm, xm) = (&spec.types[v].elements, &spec.types[x].elements);
    let other = match spec.basis {
        Basis::Blade => Basis::Product,
        Basis::Product => return Ok(own),
    };
    if spec.algebra.metric().is_diagonal() || !vm.iter().chain(xm).all(|&m| same_in_both_bases(spec, m)) {
        return Ok(own);
    }
    let alt = action_kernel_in(spec, other, convention, v, x, commutator)?;
    let cost = |k: &ActionKernel| {
        let (m, a) = k.counts();
        m + a
    };
    Ok(if cost(&alt) < cost(&own) { ActionKernel { outside: own.outside, ..alt } } else { own })
}

fn action_kernel_in(
    spec: &ModuleSpec,
    basis: Basis,
    convention: Convention,
    v: usize,
    x: usize,
    commutator: bool,
) -> Result<ActionKernel, CodegenError> {
    let tables = spec.algebra.tables();
    let gp = tables.product(basis, Product::Geometric);
    let rev = tables.unary(basis, Unary::Reverse);
    let (vm, xm) = (&spec.types[v].elements, &spec.types[x].elements);
    // the versor's field `a` as a sum of basis elements, reversed or not
    let image = |a: usize, reversed: bool| -> Vec<(u32, Q)> {
        if reversed {
            rev.image(vm[a]).expect("a mask of the spec's algebra").to_vec()
        } else {
            vec![(vm[a], Q::from_integer(1.into()))]
        }
    };
    let (left_rev, right_rev) = match convention {
        Convention::Sandwich => (true, false),
        Convention::Apply => (false, true),
    };
    // stage 1: t = L(S) x, keyed by basis mask
    let mut t: BTreeMap<u32, BTreeMap<(usize, usize), Q>> = BTreeMap::new();
    for a in 0..vm.len() {
        for (m, r) in image(a, left_rev) {
            for (b, &mb) in xm.iter().enumerate() {
                for (k, c) in gp.get(m, mb).expect("a mask of the spec's algebra") {
                    *t.entry(*k).or_default().entry((a, b)).or_insert_with(Q::zero) += &r * c;
                }
                if commutator {
                    for (k, c) in gp.get(mb, m).expect("a mask of the spec's algebra") {
                        *t.entry(*k).or_default().entry((a, b)).or_insert_with(Q::zero) -= &r * c;
                    }
                }
            }
        }
    }
    t.values_mut().for_each(|e| e.retain(|_, c| !c.is_zero()));
    t.retain(|_, e| !e.is_empty());
    // stage 2: out_j = Σ t_k R(S)_a, keyed by (j, k, a)
    let mut o: BTreeMap<u32, BTreeMap<(u32, usize), Q>> = BTreeMap::new();
    for &k in t.keys() {
        for a in 0..vm.len() {
            for (m, r) in image(a, right_rev) {
                for (j, c) in gp.get(k, m).expect("a mask of the spec's algebra") {
                    *o.entry(*j).or_default().entry((k, a)).or_insert_with(Q::zero) += &r * c;
                }
            }
        }
    }
    o.values_mut().for_each(|e| e.retain(|_, c| !c.is_zero()));
    // a component outside X is dropped when its polynomial in (s, x) is not identically zero
    // (`s_a s_a'` commute, so `(a, a', b)` and `(a', a, b)` are one monomial)
    let nonzero = |e: &BTreeMap<(u32, usize), Q>| {
        let mut poly: BTreeMap<(usize, usize, usize), Q> = BTreeMap::new();
        for (&(k, a), c) in e {
            for (&(a1, b), c1) in &t[&k] {
                *poly.entry((a.min(a1), a.max(a1), b)).or_insert_with(Q::zero) += c * c1;
            }
        }
        poly.values().any(|c| !c.is_zero())
    };
    let outside: Vec<u32> = o.iter().filter(|(j, e)| !xm.contains(j) && nonzero(e)).map(|(j, _)| *j).collect();
    o.retain(|j, _| xm.contains(j));
    let used: Vec<u32> = t.keys().copied().filter(|k| o.values().any(|e| e.keys().any(|(kk, _)| kk == k))).collect();
    let stage1 = used
        .iter()
        .map(|k| t[k].iter().map(|(&(a, b), c)| Ok((a, b, to_ratio(c)?))).collect::<Result<Vec<_>, _>>())
        .collect::<Result<Vec<_>, _>>()?;
    let stage2 = xm
        .iter()
        .map(|j| {
            o.get(j)
                .map(|e| {
                    e.iter()
                        .map(|(&(k, a), c)| {
                            let ki = used.iter().position(|u| *u == k).expect("used intermediate");
                            Ok((ki, a, to_ratio(c)?))
                        })
                        .collect::<Result<Vec<_>, _>>()
                })
                .unwrap_or(Ok(Vec::new()))
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(ActionKernel {
        convention,
        versor: v,
        operand: x,
        stage1,
        stage2,
        outside,
        chains: [false; 2],
        norm: None,
        flip: 0,
        operand_constants: false,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spec::TypeSpec;
    use algebra_core::{Algebra, Metric, Multivector};

    /// `PositiveHalves` sorts each half of a row by sign and keeps the tables' order within
    /// each sign; `PositiveHalvesVersor` the same from the versor's field order.
    #[test]
    fn halves_sort_signs_within_each_half() {
        let row: Vec<(usize, usize, Ratio)> =
            vec![(0, 1, (-1, 1)), (1, 0, (1, 1)), (2, 3, (-1, 1)), (0, 0, (1, 2)), (3, 2, (1, 1)), (1, 1, (-2, 1))];
        let mut t = row.clone();
        order_row(&mut t, RowOrder::PositiveHalves, false);
        // tables' order (0,0) (0,1) (1,0) | (1,1) (2,3) (3,2), then signs within each half
        let want = [(0, 0), (1, 0), (0, 1), (3, 2), (1, 1), (2, 3)];
        assert_eq!(t.iter().map(|x| (x.0, x.1)).collect::<Vec<_>>(), want);
        let mut v = row;
        order_row(&mut v, RowOrder::PositiveHalvesVersor, true);
        // stage 2's versor field is the second index: (0,0) (1,0) (0,1) | (1,1) (3,2) (2,3),
        // then signs within each half
        let want = [(0, 0), (1, 0), (0, 1), (3, 2), (1, 1), (2, 3)];
        assert_eq!(v.iter().map(|x| (x.0, x.1)).collect::<Vec<_>>(), want);
        // where the two orders put a term in different halves
        let row: Vec<(usize, usize, Ratio)> = vec![(0, 5, (1, 1)), (1, 0, (1, 1)), (2, 1, (1, 1)), (3, 2, (1, 1))];
        let (mut t, mut v) = (row.clone(), row);
        order_row(&mut t, RowOrder::PositiveHalves, true);
        order_row(&mut v, RowOrder::PositiveHalvesVersor, true);
        assert_eq!(t.iter().map(|x| (x.0, x.1)).collect::<Vec<_>>(), [(0, 5), (1, 0), (2, 1), (3, 2)]);
        assert_eq!(v.iter().map(|x| (x.0, x.1)).collect::<Vec<_>>(), [(1, 0), (2, 1), (3, 2), (0, 5)]);
    }

    /// A planned kernel evaluated over `Q` as the emitters print it: flipped versor fields
    /// enter negated (their coefficients are stored negated), and the scalar-norm form adds
    /// `n · x_j` to the scaled correction.
    fn eval_q(k: &ActionKernel, s: &[Q], x: &[Q]) -> Vec<Q> {
        let r = |c: Ratio| Q::new(c.0.into(), c.1.into());
        let sf: Vec<Q> =
            s.iter().enumerate().map(|(a, v)| if k.flip >> a & 1 == 1 { -v.clone() } else { v.clone() }).collect();
        let t: Vec<Q> = k.stage1.iter().map(|row| row.iter().map(|&(a, b, c)| r(c) * &sf[a] * &x[b]).sum()).collect();
        let y = k.stage2.iter().map(|row| row.iter().map(|&(i, a, c)| r(c) * &t[i] * &sf[a]).sum::<Q>());
        match &k.norm {
            None => y.collect(),
            Some(norm) => {
                let n: Q = norm.terms.iter().map(|&(a, b, c)| r(c) * &s[a] * &s[b]).sum();
                y.zip(x).map(|(y, xj)| &n * xj + r(norm.scale) * y).collect()
            }
        }
    }

    /// Every planned fused kernel (the wisdom's orders and flips, the scalar-norm forms) of
    /// the benched declarations and of the reflections gives exactly the operand's part of the
    /// runtime `rev(S) x S` / `S x rev(S)` over `Q`, for arbitrary (non-versor) elements.
    #[test]
    fn planned_kernels_are_the_projected_products_over_q() {
        let z = "0";
        let gram: [&[&str]; 5] =
            [&["1", z, z, z, z], &[z, "1", z, z, z], &[z, z, "1", z, z], &[z, z, z, z, "-1"], &[z, z, z, "-1", z]];
        let gatl = Metric::from_strs(&["1", "2", "3", "o", "inf"], &gram).unwrap();
        let motor = "Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf";
        let builtin = |n: &str| Algebra::builtin(n).unwrap().metric().clone();
        let specs = [
            (gatl, Basis::Blade, format!("Vector=grade1;{motor}"), None),
            (builtin("cga-null"), Basis::Product, format!("Vector=grade1;{motor}"), None),
            (builtin("g3"), Basis::Blade, "Vector=grade1;Bivector=grade2;Rotor=even".to_string(), None),
            (builtin("pga3"), Basis::Blade, "Vector=grade1;Trivector=grade3;Motor=even".to_string(), None),
            // as the predefined `cga` module: straight-line kernels up to 256 terms
            (builtin("cga"), Basis::Blade, "Vector=grade1;Motor=even".to_string(), Some(256)),
        ];
        let (mut flipped, mut normed, mut wise) = (0, 0, 0);
        for (metric, basis, types, table_above) in specs {
            let alg = Algebra::new("m", metric.clone());
            let types = ModuleSpec::parse_types(&types, &alg).unwrap();
            let mut spec = ModuleSpec::new("m", metric, basis, types).unwrap();
            spec.table_above = table_above.unwrap_or(spec.table_above);
            let plan = crate::plan::Plan::new(spec).unwrap();
            let spec = &plan.spec;
            let mv = |t: &TypeSpec, c: &[Q]| {
                let mut coeffs = vec![Q::zero(); spec.algebra.dim()];
                for ((m, v), sign) in t.elements.iter().zip(c).zip(t.signs()) {
                    coeffs[*m as usize] = v * Q::from_integer(sign.into());
                }
                Multivector::from_coeffs(&spec.algebra, basis, coeffs).unwrap()
            };
            for (n, k) in plan.actions.iter().enumerate() {
                let (vt, xt) = (&spec.types[k.versor], &spec.types[k.operand]);
                let q = |i: usize| {
                    Q::new(
                        ((i * 7 + n * 3) % 11).cast_signed().wrapping_sub(5).into(),
                        ((i % 3) + 1).cast_signed().into(),
                    )
                };
                let s: Vec<Q> = (0..vt.elements.len()).map(q).collect();
                let x: Vec<Q> = (0..xt.elements.len()).map(|i| q(i + 13)).collect();
                let (sm, xm) = (mv(vt, &s), mv(xt, &x));
                let reference = match k.convention {
                    Convention::Sandwich => &(&sm.reverse() * &xm) * &sm,
                    Convention::Apply => &(&sm * &xm) * &sm.reverse(),
                };
                let out = eval_q(k, &s, &x);
                for (j, (m, sign)) in xt.elements.iter().zip(xt.signs()).enumerate() {
                    let want = reference.coeff(*m).unwrap() * Q::from_integer(sign.into());
                    assert_eq!(
                        out[j], want,
                        "{} {:?} {} on {}: component {m:#b}",
                        spec.name, k.convention, vt.name, xt.name
                    );
                }
                flipped += usize::from(k.flip != 0);
                normed += usize::from(k.norm.is_some());
                wise += usize::from(WISDOM.iter().any(|w| w.0 == fingerprint(k)));
            }
        }
        // the wisdom's nine kernels, all in the scalar-norm form: `g3`'s rotor on a vector,
        // the conformal point actions of GATL's declaration and `cga_null`, `pga3`'s on a
        // point (both conventions each, every one with flips) and `cga`'s `sandwich`; ten more
        // in the form by the saving rule (`NORM_FORM_SAVING`), in the default order
        assert_eq!((wise, flipped, normed), (9, 8, 19));
    }

    /// GATL's conformal declaration (blade basis, `eo · einf = -1`): the intermediate is taken
    /// in the product basis (fewer operations), and the kernel still gives the blade-basis
    /// action computed by the runtime product `rev(S) x S` / `S x rev(S)` (exact rationals).
    #[test]
    fn null_pair_in_a_blade_basis_takes_the_cheaper_intermediate() {
        let z = "0";
        let gram: [&[&str]; 5] =
            [&["1", z, z, z, z], &[z, "1", z, z, z], &[z, z, "1", z, z], &[z, z, z, z, "-1"], &[z, z, z, "-1", z]];
        let metric = Metric::from_strs(&["1", "2", "3", "o", "inf"], &gram).unwrap();
        let alg = Algebra::new("gatl", metric.clone());
        let types =
            ModuleSpec::parse_types("Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1", &alg).unwrap();
        let spec = ModuleSpec::new("gatl", metric, Basis::Blade, types).unwrap();
        let alg = spec.algebra.clone();
        let q = |n: i64| Q::from_integer(n.into());
        let s: Vec<Q> = [3, -1, 2, 5, -4, 7, 1, -2].into_iter().map(q).collect();
        let x: Vec<Q> = [2, -3, 1, 4, -5].into_iter().map(q).collect();
        let mv = |t: &TypeSpec, c: &[Q]| {
            let mut coeffs = vec![Q::zero(); alg.dim()];
            for (m, v) in t.elements.iter().zip(c) {
                coeffs[*m as usize] = v.clone();
            }
            Multivector::from_coeffs(&alg, Basis::Blade, coeffs).unwrap()
        };
        let (sm, xm) = (mv(&spec.types[0], &s), mv(&spec.types[1], &x));
        for convention in [Convention::Sandwich, Convention::Apply] {
            let k = action_kernel(&spec, convention, 0, 1, false).unwrap();
            let blade = action_kernel_in(&spec, Basis::Blade, convention, 0, 1, false).unwrap();
            let (total, blade_total) = (k.counts().0 + k.counts().1, blade.counts().0 + blade.counts().1);
            assert!(total < blade_total, "{convention:?}: {total} vs {blade_total}");
            let r = |c: (i64, i64)| Q::new(c.0.into(), c.1.into());
            let t: Vec<Q> =
                k.stage1.iter().map(|row| row.iter().map(|&(a, b, c)| r(c) * &s[a] * &x[b]).sum()).collect();
            let out: Vec<Q> =
                k.stage2.iter().map(|row| row.iter().map(|&(i, a, c)| r(c) * &t[i] * &s[a]).sum()).collect();
            let reference = match convention {
                Convention::Sandwich => &(&sm.reverse() * &xm) * &sm,
                Convention::Apply => &(&sm * &xm) * &sm.reverse(),
            };
            for (j, m) in spec.types[1].elements.iter().enumerate() {
                assert_eq!(&out[j], reference.coeff(*m).unwrap(), "{convention:?} component {m:#b}");
            }
        }
    }
}
