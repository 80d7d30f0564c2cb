//! Constrained kernels (`algebra_codegen::constraint`): the reduced kernel of a unit motor
//! acting on a vector of the null-basis CGA agrees exactly (over Q) with the runtime product
//! `rev(S) x S` on unit motors, is shorter than the unconstrained kernel, and its output type is
//! the operand's (proven); it disagrees on a non-unit motor, so the constraint is really used.

use algebra_codegen::ModuleSpec;
use algebra_codegen::constraint::{
    Constraint, ConstraintError, ConstraintKind, constrained_action, constrained_product,
};
use algebra_codegen::versor::Convention;
use algebra_core::rational::{Q, ratio};
use algebra_core::test_support::Xorshift;
use algebra_core::{Algebra, Basis, Multivector, Ring};

fn cga_null() -> ModuleSpec {
    let alg = Algebra::builtin("cga-null").unwrap();
    let types =
        ModuleSpec::parse_types("Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1;Full=all", &alg).unwrap();
    ModuleSpec::new("cga_null", alg.metric().clone(), Basis::Product, types).unwrap()
}

/// A deterministic generator of small rationals.
struct Rng(Xorshift);

impl Rng {
    fn next(&mut self) -> Q {
        let x = self.0.next_u64();
        ratio((x % 19) as i64 - 9, (x >> 20) as i64 % 7 + 1)
    }
}

fn mv(spec: &ModuleSpec, terms: Vec<(&str, Q)>) -> Multivector<Q> {
    Multivector::from_terms(&spec.algebra, spec.basis, terms).unwrap()
}

/// A unit motor with rational coefficients: S = R T, R = r r / |r|² (a unit rotor) and the
/// translator T = 1 + t einf / 2.
fn unit_motor(spec: &ModuleSpec, rng: &mut Rng) -> Multivector<Q> {
    let (w, x, y, z) = (rng.next() + Q::from_i64(1), rng.next(), rng.next(), rng.next());
    let n2 = &w * &w + &x * &x + &y * &y + &z * &z;
    let r = mv(spec, vec![("1", w), ("e12", x), ("e13", y), ("e23", z)]);
    let rot = (&r * &r).scale(&(Q::one() / n2));
    let half = ratio(1, 2);
    let t = mv(
        spec,
        vec![
            ("1", Q::one()),
            ("e1inf", rng.next() * &half),
            ("e2inf", rng.next() * &half),
            ("e3inf", rng.next() * &half),
        ],
    );
    &rot * &t
}

fn fields(spec: &ModuleSpec, ty: usize, m: &Multivector<Q>) -> Vec<Q> {
    spec.types[ty].elements.iter().map(|&e| m.coeff(e).unwrap().clone()).collect()
}

/// Checks the kernel against the runtime product on every output mask (kept ones equal, all
/// others zero); returns whether they agree.
fn agrees(k: &algebra_codegen::constraint::ConstrainedKernel, s: &[Q], x: &[Q], exact: &Multivector<Q>) -> bool {
    let got = k.eval(s, x);
    (0..exact.algebra().dim() as u32).all(|m| {
        let value = got.iter().find(|(mask, _)| *mask == m).map(|(_, v)| v.clone()).unwrap_or_else(Q::zero);
        value == *exact.coeff(m).unwrap()
    })
}

#[test]
fn unit_motor_on_a_point_agrees_exactly_and_is_shorter() {
    let spec = cga_null();
    let unit = [Constraint { ty: 0, kind: ConstraintKind::Unit }];
    let k = constrained_action(&spec, Convention::Sandwich, 0, 1, &unit).unwrap();
    // Output type: proven a Vector; without the constraint the product has a σ part (Full).
    assert_eq!(k.output_type, Some(1));
    assert_eq!(k.full.output_type, Some(2));
    assert!(!k.vanishing.is_empty());
    let (c, f) = (k.stats(), k.full.stats());
    assert_eq!(c.outputs, 5);
    println!("cga-null unit motor sandwich on a vector: {c:?} vs {f:?}; vanishing {:?}", k.vanishing);
    assert!(c.mul < f.mul && c.terms < f.terms, "{c:?} vs {f:?}");
    assert_eq!(k.relies_on, ["Motor: rev(x) x = 1"]);
    let mut rng = Rng(Xorshift(0x9e37_79b9_7f4a_7c15));
    for _ in 0..40 {
        let s = unit_motor(&spec, &mut rng);
        assert_eq!(&s.reverse() * &s, mv(&spec, vec![("1", Q::one())]), "the sample is a unit motor");
        let x = mv(&spec, ["e0", "e1", "e2", "e3", "einf"].iter().map(|n| (*n, rng.next())).collect());
        let exact = &(&s.reverse() * &x) * &s;
        assert!(agrees(&k, &fields(&spec, 0, &s), &fields(&spec, 1, &x), &exact));
    }
    // S = 1 + e123inf is not unit (rev(S) S = 1 + 2 e123inf): its action on e0 has the σ part
    // the constrained kernel drops, so the kernel is wrong there (it relies on the constraint).
    let s = mv(&spec, vec![("1", Q::one()), ("e123inf", Q::one())]);
    let x = mv(&spec, vec![("e0", Q::one()), ("e1", Q::from_i64(3))]);
    let exact = &(&s.reverse() * &x) * &s;
    assert!(k.vanishing.iter().any(|&m| *exact.coeff(m).unwrap() != Q::zero()));
    assert!(!agrees(&k, &fields(&spec, 0, &s), &fields(&spec, 1, &x), &exact));
}

/// The generated constrained kernel, committed (regenerate with `BLESS=1`).
mod generated {
    use algebra_core::Ring;
    include!("generated/unit_motor_sandwich.rs");
}

fn unit_motor_kernel() -> (ModuleSpec, algebra_codegen::constraint::ConstrainedKernel) {
    let spec = cga_null();
    let k = constrained_action(&spec, Convention::Sandwich, 0, 1, &[Constraint { ty: 0, kind: ConstraintKind::Unit }]);
    (spec, k.unwrap())
}

#[test]
fn generated_file_is_up_to_date() {
    let (_, k) = unit_motor_kernel();
    let file: syn::File = syn::parse2(k.tokens("unit_motor_sandwich", 8, 5)).unwrap();
    let text = prettyplease::unparse(&file);
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/generated/unit_motor_sandwich.rs");
    if std::env::var_os("BLESS").is_some() {
        std::fs::write(path, &text).unwrap();
    }
    assert_eq!(std::fs::read_to_string(path).unwrap(), text, "regenerate with BLESS=1");
}

#[test]
fn generated_kernel_agrees_with_the_runtime_product_on_unit_motors() {
    let (spec, k) = unit_motor_kernel();
    let mut rng = Rng(Xorshift(0x2545_f491_4f6c_dd1d));
    for _ in 0..40 {
        let s = unit_motor(&spec, &mut rng);
        let x = mv(&spec, ["e0", "e1", "e2", "e3", "einf"].iter().map(|n| (*n, rng.next())).collect());
        let exact = &(&s.reverse() * &x) * &s;
        let (sf, xf) = (fields(&spec, 0, &s), fields(&spec, 1, &x));
        let out = generated::unit_motor_sandwich(&sf.try_into().unwrap(), &xf.try_into().unwrap());
        for ((mask, _), v) in k.outputs.iter().zip(out) {
            assert_eq!(v, *exact.coeff(*mask).unwrap());
        }
        // the generated outputs are exactly the operand's components
        assert_eq!(k.outputs.iter().map(|o| o.0).collect::<Vec<_>>(), spec.types[1].elements);
    }
}

#[test]
fn unit_rotor_apply_in_g3() {
    let alg = Algebra::builtin("g3").unwrap();
    let types = ModuleSpec::parse_types("Rotor=even;Vector=grade1;Full=all", &alg).unwrap();
    let spec = ModuleSpec::new("g3", alg.metric().clone(), Basis::Blade, types).unwrap();
    let unit = [Constraint { ty: 0, kind: ConstraintKind::Unit }];
    let k = constrained_action(&spec, Convention::Apply, 0, 1, &unit).unwrap();
    // In G3 R x rev(R) has no trivector part for any even R: both outputs are vectors.
    assert_eq!((k.output_type, k.full.output_type), (Some(1), Some(1)));
    println!("g3 rotor apply: {:?} vs {:?}", k.stats(), k.full.stats());
    // The unit constraint saves nothing in this layout (1 - 2(y² + z²) costs what w² + x² - y² - z² does).
    assert!(k.stats().mul <= k.full.stats().mul);
    // R = (3 + 4 e12)/5 rotates e1 to (-7 e1 + 24 e2)/25 under R x rev(R).
    let r = [ratio(3, 5), ratio(4, 5), Q::zero(), Q::zero()];
    let out = k.eval(&r, &[Q::one(), Q::zero(), Q::zero()]);
    let rm = Multivector::from_terms(&alg, Basis::Blade, vec![("1", ratio(3, 5)), ("e12", ratio(4, 5))]).unwrap();
    let e1 = Multivector::from_terms(&alg, Basis::Blade, vec![("e1", Q::one())]).unwrap();
    let exact = &(&rm * &e1) * &rm.reverse();
    for (mask, v) in out {
        assert_eq!(v, *exact.coeff(mask).unwrap());
    }
}

#[test]
fn null_and_simple_constraints_and_errors() {
    // The product x y of two null vectors (x x = y y = 0 each; x y itself stays general).
    let spec = cga_null();
    let null = [Constraint { ty: 1, kind: ConstraintKind::Null }];
    let k = constrained_product(&spec, 1, 1, &null).unwrap();
    assert_eq!(k.relies_on, ["Vector: x x = 0"]);
    assert!(k.stats().mul <= k.full.stats().mul);
    // exact on conformal points up(p) = e0 + p + p²/2 einf (null)
    let mut rng = Rng(Xorshift(77));
    let up = |rng: &mut Rng| {
        let p: Vec<Q> = (0..3).map(|_| rng.next()).collect();
        let p2 = p.iter().fold(Q::zero(), |acc, c| acc + c * c);
        mv(
            &spec,
            vec![
                ("e0", Q::one()),
                ("e1", p[0].clone()),
                ("e2", p[1].clone()),
                ("e3", p[2].clone()),
                ("einf", p2 * ratio(1, 2)),
            ],
        )
    };
    for _ in 0..20 {
        let (x, y) = (up(&mut rng), up(&mut rng));
        assert!((&x * &x).is_zero() && (&y * &y).is_zero());
        assert!(agrees(&k, &fields(&spec, 1, &x), &fields(&spec, 1, &y), &(&x * &y)));
    }
    // A PGA line with the Plücker condition: L ∧ L = 0 makes the line's square a scalar.
    let pga = Algebra::builtin("pga3").unwrap();
    let types = ModuleSpec::parse_types("Line=grade2;Even=even", &pga).unwrap();
    let spec = ModuleSpec::new("pga", pga.metric().clone(), Basis::Blade, types).unwrap();
    let simple = [Constraint { ty: 0, kind: ConstraintKind::Simple }];
    let k = constrained_product(&spec, 0, 0, &simple).unwrap();
    assert!(k.stats().terms <= k.full.stats().terms);
    // exact on lines L = a ∧ b (simple bivectors)
    let mut rng = Rng(Xorshift(99));
    let vector = |rng: &mut Rng| {
        let terms: Vec<(&str, Q)> = ["e0", "e1", "e2", "e3"].iter().map(|n| (*n, rng.next())).collect();
        Multivector::from_terms(&spec.algebra, spec.basis, terms).unwrap()
    };
    for _ in 0..20 {
        let (l1, l2) = (vector(&mut rng).op(&vector(&mut rng)), vector(&mut rng).op(&vector(&mut rng)));
        assert!(l1.op(&l1).is_zero());
        assert!(agrees(&k, &fields(&spec, 0, &l1), &fields(&spec, 0, &l2), &(&l1 * &l2)));
    }
    // A scalar type both null and unit: inconsistent.
    let alg = Algebra::builtin("g3").unwrap();
    let types = ModuleSpec::parse_types("S=1;V=grade1", &alg).unwrap();
    let spec = ModuleSpec::new("g3", alg.metric().clone(), Basis::Blade, types).unwrap();
    let both = [Constraint { ty: 0, kind: ConstraintKind::Null }, Constraint { ty: 0, kind: ConstraintKind::Unit }];
    assert_eq!(constrained_product(&spec, 0, 1, &both).unwrap_err(), ConstraintError::Inconsistent);
    let missing = [Constraint { ty: 7, kind: ConstraintKind::Unit }];
    assert_eq!(constrained_product(&spec, 0, 1, &missing).unwrap_err(), ConstraintError::NoType(7));
    assert_eq!(constrained_product(&spec, 0, 9, &[]).unwrap_err(), ConstraintError::NoType(9));
}
