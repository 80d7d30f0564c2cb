//! Every generated kernel of every predefined module against the runtime reference
//! [`algebra_core::Multivector`]:
//!
//! - every ordered pair of declared types × the eight products (trait methods), plus the
//!   operators `*`, `^`, `|` on values and references;
//! - every unary method, `norm_squared`, `inverse`, the arithmetic operators, `scale`,
//!   conversions, `Display` and `Debug`;
//! - `sandwich` and `apply` of every versor type with every declared type.
//!
//! Each check runs exactly over rationals and over `f64` (to 1e-12 relative to the operands'
//! magnitudes). Every result must also lie in its output type: `Out::try_from(&runtime_result)`
//! succeeds, so the output type chosen at expansion time really holds the product.
//!
//! **Exact scalar.** The exact checks run over `algebra_core::rational::Q` itself (a
//! `BigRational`, not `Copy`): the generator's size policy emits every kernel with more than
//! `TABLE_THRESHOLD` (128) terms, 256 in `cga` (`table_above 256;`), as a loop over a constant
//! table (the dense 5-generator products), so this target compiles in about a minute instead
//! of the quarter of an hour the unrolled `Q` kernels took. Kernels of 129-256 terms are
//! checked here in both forms: straight-line in `cga`, tables in `cga_null`'s larger types.
//!
//! Test paths read `module::lhs::rhs::{q, f64}` (the eight products),
//! `module::ty::{unary_q, unary_f64}`, `module::versors::v::{sandwich_q, sandwich_f64}`
//! and `module::ones`.

use algebra_core::ops::{
    AnticommutatorProduct, CommutatorProduct, GeometricProduct, LeftContraction, OuterProduct, RegressiveProduct,
    RightContraction, ScalarProduct,
};
use algebra_core::rational::{Q, ratio};
use algebra_core::{Algebra, Basis, Field, Multivector as Mv, MvError, Ring};
use proptest::prelude::*;
use std::any::type_name;
use std::fmt::Debug;
use std::sync::Arc;

/// Cases per property: 16, or `PROPTEST_CASES` when set (for a heavier run). The
/// full-multivector products of the 5-generator algebras are the heaviest: dense 1024-term
/// kernels against a dense reference.
fn config() -> ProptestConfig {
    let cases = std::env::var("PROPTEST_CASES").ok().and_then(|c| c.parse().ok()).unwrap_or(16);
    ProptestConfig::with_cases(cases)
}

// ---------------------------------------------------------------------------------------------
// Scalars under test and their notion of agreement
// ---------------------------------------------------------------------------------------------

/// The scalars the kernels are checked over.
trait TestScalar: Field {
    /// Exact arithmetic (results are compared with `==`).
    const EXACT: bool;
    /// What a random coefficient is drawn as (a plain value, never an arena handle).
    type Seed: Clone + Debug;
    /// A random coefficient.
    fn seed() -> BoxedStrategy<Self::Seed>;
    /// The scalar of a seed.
    fn from_seed(seed: &Self::Seed) -> Self;
    /// Called at the start of every case, before any value is made.
    fn reset() {}
    /// `generated == reference`: exactly, or within `1e-12 · max(1, scale)` in the 1-norm.
    fn check(what: &str, generated: &Mv<Self>, reference: &Mv<Self>, scale: f64);
    /// The same for one scalar.
    fn check_scalar(what: &str, generated: &Self, reference: &Self, scale: f64);
}

/// Small rationals `n/d` (`|n| <= 6`, `d <= 4`), zero one time in five.
fn small_rational() -> BoxedStrategy<Q> {
    prop_oneof![1 => Just(ratio(0, 1)), 4 => (-6i64..=6, 1i64..=4).prop_map(|(n, d)| ratio(n, d))].boxed()
}

fn check_exact<T: Ring>(what: &str, generated: &Mv<T>, reference: &Mv<T>) {
    assert_eq!(generated, reference, "{what}: generated {generated} != reference {reference}");
}

impl TestScalar for Q {
    const EXACT: bool = true;
    type Seed = Q;
    fn seed() -> BoxedStrategy<Q> {
        small_rational()
    }
    fn from_seed(seed: &Q) -> Self {
        seed.clone()
    }
    fn check(what: &str, generated: &Mv<Self>, reference: &Mv<Self>, _: f64) {
        check_exact(what, generated, reference);
    }
    fn check_scalar(what: &str, generated: &Self, reference: &Self, _: f64) {
        assert_eq!(generated, reference, "{what}");
    }
}

/// The relative tolerance of the f64 checks.
const TOL: f64 = 1e-12;

impl TestScalar for f64 {
    const EXACT: bool = false;
    type Seed = f64;
    fn seed() -> BoxedStrategy<f64> {
        prop_oneof![1 => Just(0.0), 4 => -4.0..4.0f64].boxed()
    }
    fn from_seed(seed: &f64) -> Self {
        *seed
    }
    fn check(what: &str, generated: &Mv<Self>, reference: &Mv<Self>, scale: f64) {
        let err = (generated - reference).magnitude();
        assert!(
            err <= TOL * scale.max(1.0),
            "{what}: |generated - reference|_1 = {err:e} (scale {scale:e})\n generated {generated}\n reference {reference}"
        );
    }
    fn check_scalar(what: &str, generated: &Self, reference: &Self, scale: f64) {
        let err = (generated - reference).abs();
        assert!(err <= TOL * scale.max(1.0), "{what}: {generated} vs {reference} (error {err:e})");
    }
}

/// Random coefficients of a dense multivector of `algebra`.
fn arb_seeds<T: TestScalar>(algebra: &Algebra) -> impl Strategy<Value = Vec<T::Seed>> + use<T> {
    proptest::collection::vec(T::seed(), algebra.dim())
}

/// Starts a case: resets the scalar's state, then builds one runtime multivector per seed list.
fn start<T: TestScalar>(seeds: &[&[T::Seed]], algebra: &Arc<Algebra>, basis: Basis) -> Vec<Mv<T>> {
    T::reset();
    seeds
        .iter()
        .map(|s| Mv::from_coeffs(algebra, basis, s.iter().map(T::from_seed).collect()).expect("dim coefficients"))
        .collect()
}

// ---------------------------------------------------------------------------------------------
// Generic checks
// ---------------------------------------------------------------------------------------------

/// What the checks need of a generated type (implemented for every type by [`impl_gen`]).
trait Gen<T: Ring>: Clone + PartialEq + Debug + Sized {
    fn mv(&self) -> Mv<T>;
    fn exact(m: &Mv<T>) -> Result<Self, MvError>;
    fn project(m: &Mv<T>) -> Self;
}

macro_rules! impl_gen {
    ($m:ident: $($t:ident),*) => {$(
        impl<T: Ring> Gen<T> for gam_algebras::$m::$t<T> {
            fn mv(&self) -> Mv<T> {
                self.to_multivector()
            }
            fn exact(m: &Mv<T>) -> Result<Self, MvError> {
                Self::try_from(m)
            }
            fn project(m: &Mv<T>) -> Self {
                Self::project(m)
            }
        }
    )*};
}

/// `gam_algebras::generated::g3::Rotor<f64>` -> `g3::Rotor<f64>`.
fn short(name: &str) -> String {
    name.replace("gam_algebras::generated::", "").replace("kernels::", "")
}

/// A generated result `out` agrees with the runtime `reference`, and its type holds
/// `reference` (the exact conversion succeeds and gives `out` back).
fn check_result<T: TestScalar, O: Gen<T>>(what: &str, out: &O, reference: &Mv<T>, scale: f64) {
    let what = format!("{what} -> {}", short(type_name::<O>()));
    T::check(&what, &out.mv(), reference, scale);
    let back = O::exact(reference).unwrap_or_else(|e| panic!("{what}: the output type does not hold the result: {e}"));
    T::check(&what, &back.mv(), &out.mv(), scale);
}

/// The eight products of `a` and `b` against the runtime reference.
fn check_products<T: TestScalar, A, B: Gen<T>>(a: &A, b: &B)
where
    A: Gen<T>
        + GeometricProduct<B, Output: Gen<T>>
        + OuterProduct<B, Output: Gen<T>>
        + LeftContraction<B, Output: Gen<T>>
        + RightContraction<B, Output: Gen<T>>
        + ScalarProduct<B, Output: Gen<T>>
        + RegressiveProduct<B, Output: Gen<T>>
        + CommutatorProduct<B, Output: Gen<T>>
        + AnticommutatorProduct<B, Output: Gen<T>>,
{
    let (x, y) = (a.mv(), b.mv());
    let scale = x.magnitude() * y.magnitude();
    let pair = format!("{} ∘ {}", short(type_name::<A>()), short(type_name::<B>()));
    check_result(&format!("gp {pair}"), &a.gp(b), &x.gp(&y), scale);
    check_result(&format!("op {pair}"), &a.op(b), &x.op(&y), scale);
    check_result(&format!("lc {pair}"), &a.lc(b), &x.lc(&y), scale);
    check_result(&format!("rc {pair}"), &a.rc(b), &x.rc(&y), scale);
    check_result(&format!("sp {pair}"), &a.sp(b), &x.sp(&y), scale);
    check_result(&format!("regressive {pair}"), &a.regressive(b), &x.regressive(&y), scale);
    check_result(&format!("commutator {pair}"), &a.commutator(b), &x.commutator(&y), scale);
    check_result(&format!("anticommutator {pair}"), &a.anticommutator(b), &x.anticommutator(&y), scale);
}

/// The generated and runtime inverses agree (both fail, or both succeed and agree), and a
/// successful inverse is two-sided. Over floats the runtime inverse (a dense solve) carries
/// rounding noise outside the type, so only the values are compared there.
fn check_inverse<T: TestScalar, O: Gen<T>>(what: &str, x: &Mv<T>, generated: Result<O, MvError>) {
    let one = Mv::scalar(x.algebra(), x.basis(), T::one());
    match (generated, x.inverse()) {
        (Ok(g), Ok(r)) => {
            // float error grows with the condition number |x| |x^-1|
            let cond = x.magnitude() * r.magnitude();
            if T::EXACT {
                check_result(what, &g, &r, 0.0);
            } else {
                T::check(what, &g.mv(), &r, r.magnitude() * cond);
            }
            T::check(&format!("{what}: x x^-1 = 1"), &(x * &g.mv()), &one, cond);
            T::check(&format!("{what}: x^-1 x = 1"), &(&g.mv() * x), &one, cond);
        }
        (Err(_), Err(_)) => {}
        (g, r) => panic!("{what}: generated {g:?} but runtime {r:?} for {x}"),
    }
}

// ---------------------------------------------------------------------------------------------
// Test generation: one module per algebra, per type, per pair
// ---------------------------------------------------------------------------------------------

/// Every type but the full one embeds into the full `Multivector` type with `From`.
macro_rules! embed_into_full {
    (Multivector, $x:ident, $xr:ident) => {
        assert_eq!(Multivector::<T>::ELEMENTS.len(), algebra().dim(), "the full type holds every element");
    };
    ($t:ident, $x:ident, $xr:ident) => {
        assert_eq!(Multivector::from(&$x).mv(), $xr, "embedding into the full type");
    };
}

/// The unary methods, arithmetic, conversions and printing of one type.
macro_rules! unary_tests {
    ($t:ident) => {
        fn check_unary<T: TestScalar>(xs: &[T::Seed], ys: &[T::Seed], s: &T::Seed) {
            let m = start::<T>(&[xs, ys], &algebra(), BASIS);
            let s = T::from_seed(s);
            let (x, y) = ($t::project(&m[0]), $t::project(&m[1]));
            let (xr, yr) = (x.mv(), y.mv());
            let name = stringify!($t);
            let mx = xr.magnitude();
            check_result(&format!("{name}::reverse"), &x.reverse(), &xr.reverse(), mx);
            check_result(&format!("{name}::grade_involution"), &x.grade_involution(), &xr.grade_involution(), mx);
            check_result(&format!("{name}::conjugate"), &x.conjugate(), &xr.conjugate(), mx);
            check_result(&format!("{name}::dual"), &x.dual(), &xr.dual(), mx);
            check_result(&format!("{name}::undual"), &x.undual(), &xr.undual(), mx);
            let norm = xr.sp(&xr.reverse()).scalar_part();
            T::check_scalar(&format!("{name}::norm_squared"), &x.norm_squared(), &norm, mx * mx);
            check_inverse(&format!("{name}::inverse"), &xr, x.inverse());
            // arithmetic
            let mxy = mx + yr.magnitude();
            let sum = &xr + &yr;
            check_result(&format!("{name} + (refs)"), &(&x + &y), &sum, mxy);
            check_result(&format!("{name} + (values)"), &(x.clone() + y.clone()), &sum, mxy);
            let diff = &xr - &yr;
            check_result(&format!("{name} - (refs)"), &(&x - &y), &diff, mxy);
            check_result(&format!("{name} - (values)"), &(x.clone() - y.clone()), &diff, mxy);
            check_result(&format!("{name} neg (ref)"), &(-&x), &(-&xr), mx);
            check_result(&format!("{name} neg (value)"), &(-x.clone()), &(-&xr), mx);
            check_result(&format!("{name}::scale"), &x.scale(&s), &xr.scale(&s), mx * s.magnitude());
            // construction, projection and conversion
            assert_eq!(x, $t::try_from(&xr).expect("a value converts back to its type"));
            assert_eq!($t::<T>::ELEMENTS.len(), $t::<T>::MASKS.len());
            for (name, &mask) in $t::<T>::ELEMENTS.iter().zip(&$t::<T>::MASKS) {
                assert_eq!(algebra().mask_of(name).expect("a basis name"), mask);
                assert_eq!(xr.coeff(mask).unwrap(), m[0].coeff(mask).unwrap(), "project keeps {name}");
            }
            assert!($t::<T>::zero().mv().is_zero());
            embed_into_full!($t, x, xr);
            assert_eq!(Mv::from(&x), xr);
            assert_eq!(x.to_string(), xr.to_string(), "Display");
            assert_eq!(format!("{x:?}"), format!("{name}({x})"), "Debug");
        }

        proptest! {
            #![proptest_config(config())]
            #[test]
            fn unary_q(x in seeds::<Q>(), y in seeds::<Q>(), s in Q::seed()) {
                check_unary::<Q>(&x, &y, &s);
            }
            #[test]
            fn unary_f64(x in seeds::<f64>(), y in seeds::<f64>(), s in f64::seed()) {
                check_unary::<f64>(&x, &y, &s);
            }
        }
    };
}

/// The products of `$a` with every declared type, one module per right operand.
macro_rules! pair_tests {
    ($a:ident; [$(($b:ident, $bm:ident)),*]) => {$(
        mod $bm {
            use super::*;

            fn check<T: TestScalar>(xs: &[T::Seed], ys: &[T::Seed]) {
                let m = start::<T>(&[xs, ys], &algebra(), BASIS);
                let (a, b) = ($a::project(&m[0]), $b::project(&m[1]));
                check_products(&a, &b);
                // the operators are the trait methods, on references and on values
                let gp = a.gp(&b);
                assert_eq!(&a * &b, gp);
                assert_eq!(a.clone() * b.clone(), gp);
                let op = a.op(&b);
                assert_eq!(&a ^ &b, op);
                assert_eq!(a.clone() ^ b.clone(), op);
                let lc = a.lc(&b);
                assert_eq!(&a | &b, lc);
                assert_eq!(a.clone() | b.clone(), lc);
            }

            proptest! {
                #![proptest_config(config())]
                #[test]
                fn q(x in seeds::<Q>(), y in seeds::<Q>()) {
                    check::<Q>(&x, &y);
                }
                #[test]
                fn f64(x in seeds::<f64>(), y in seeds::<f64>()) {
                    check::<f64>(&x, &y);
                }
            }
        }
    )*};
}

/// One module per declared type: its unary tests and its products with every type.
macro_rules! type_tests {
    ([$(($t:ident, $tm:ident)),*]; $all:tt) => {$(
        mod $tm {
            use super::*;
            unary_tests!($t);
            pair_tests!($t; $all);
        }
    )*};
}

/// `reference` projected onto the type of `out` (the identity when that type holds it).
fn projected<T: Ring, O: Gen<T>>(_: &O, reference: &Mv<T>) -> Mv<T> {
    O::project(reference).mv()
}

/// `v.sandwich(x)` and `v.apply(x)` for a versor type `$v` and every declared type: the fused
/// kernels (typed to `x`'s type) are the projections of the runtime `rev(v) x v` and
/// `v x rev(v)`; the other pairs are the full products.
macro_rules! sandwich_tests {
    ($v:ident, $vm:ident; [$(($t:ident, $tm:ident)),*]) => {
        mod $vm {
            use super::*;

            fn check<T: TestScalar>(vs: &[T::Seed], xs: &[T::Seed]) {
                let m = start::<T>(&[vs, xs], &algebra(), BASIS);
                let v = $v::project(&m[0]);
                let vr = v.mv();
                $(
                    let x = $t::project(&m[1]);
                    let xr = x.mv();
                    let what = format!("{}::sandwich({})", stringify!($v), stringify!($t));
                    let scale = vr.magnitude().powi(2) * xr.magnitude();
                    let s = v.sandwich(&x);
                    check_result(&what, &s, &projected(&s, &vr.sandwich(&xr)), scale);
                    let a = v.apply(&x);
                    let reference = &(&vr * &xr) * &vr.reverse();
                    check_result(&format!("{what}: apply"), &a, &projected(&a, &reference), scale);
                )*
            }

            proptest! {
                #![proptest_config(config())]
                #[test]
                fn sandwich_q(v in seeds::<Q>(), x in seeds::<Q>()) {
                    check::<Q>(&v, &x);
                }
                #[test]
                fn sandwich_f64(v in seeds::<f64>(), x in seeds::<f64>()) {
                    check::<f64>(&v, &x);
                }
            }
        }
    };
}

/// All the tests of one predefined module. `ones`: the types holding `1` (they have `one()`);
/// `actions`: the versor types whose `sandwich` and `apply` are checked with every type.
macro_rules! module_tests {
    ($m:ident, ones [$($one:ident),*], actions [$(($w:ident, $wm:ident)),*], types $types:tt) => {
        module_tests!(@impl $m; $types);
        mod $m {
            use super::*;
            use gam_algebras::$m::*;

            /// Random coefficients of a dense multivector of this module's algebra.
            fn seeds<T: TestScalar>() -> impl Strategy<Value = Vec<T::Seed>> {
                arb_seeds::<T>(&algebra())
            }

            type_tests!($types; $types);

            mod versors {
                use super::*;
                $(sandwich_tests!($w, $wm; $types);)*
            }

            /// `one()` of the types holding `1` is the identity.
            #[test]
            fn ones() {
                $(
                    let one = $one::<Q>::one();
                    assert_eq!(one.to_multivector(), Mv::scalar(&algebra(), BASIS, ratio(1, 1)));
                    assert_eq!(one.inverse().expect("1 is invertible").to_multivector(), one.to_multivector());
                    assert_eq!(one.to_string(), "1");
                )*
            }
        }
    };
    (@impl $m:ident; [$(($t:ident, $tm:ident)),*]) => {
        impl_gen!($m: $($t),*);
    };
}

module_tests!(
    g3,
    ones [Scalar, Rotor, Multivector],
    actions [(Scalar, scalar), (Vector, vector), (Bivector, bivector), (Trivector, trivector), (Rotor, rotor)],
    types [
        (Scalar, scalar),
        (Vector, vector),
        (Bivector, bivector),
        (Trivector, trivector),
        (Rotor, rotor),
        (Multivector, multivector)
    ]
);

module_tests!(
    g123inf,
    ones [Pseudoscalar, Motor, Multivector],
    actions [(Vector, vector), (Bivector, bivector), (Pseudoscalar, pseudoscalar), (Motor, motor)],
    types [
        (Vector, vector),
        (Bivector, bivector),
        (Pseudoscalar, pseudoscalar),
        (Motor, motor),
        (Multivector, multivector)
    ]
);

module_tests!(
    pga3,
    ones [Motor, Multivector],
    actions [(Vector, vector), (Bivector, bivector), (Trivector, trivector), (Motor, motor)],
    types [
        (Vector, vector),
        (Bivector, bivector),
        (Trivector, trivector),
        (Motor, motor),
        (Multivector, multivector)
    ]
);

module_tests!(
    cga,
    ones [Motor, Multivector],
    actions [(Vector, vector), (Bivector, bivector), (Motor, motor), (OddVersor, odd_versor)],
    types [
        (Vector, vector),
        (Bivector, bivector),
        (Motor, motor),
        (OddVersor, odd_versor),
        (Multivector, multivector)
    ]
);

module_tests!(
    cga_null,
    ones [Motor, Multivector],
    actions [(Vector, vector), (Motor, motor), (PoseBivector, pose_bivector)],
    types [(Vector, vector), (Motor, motor), (PoseBivector, pose_bivector), (Multivector, multivector)]
);

/// Every declared type of every module is covered above (a type added to `generated.rs` must
/// be added here too), and each module declares its full type itself (`Multivector = all`),
/// so the generator appends none.
#[test]
fn every_declared_type_is_listed() {
    let listed: [(&str, &[&str]); 5] = [
        ("g3", &["Scalar", "Vector", "Bivector", "Trivector", "Rotor", "Multivector"]),
        ("g123inf", &["Vector", "Bivector", "Pseudoscalar", "Motor", "Multivector"]),
        ("pga3", &["Vector", "Bivector", "Trivector", "Motor", "Multivector"]),
        ("cga", &["Vector", "Bivector", "Motor", "OddVersor", "Multivector"]),
        ("cga_null", &["Vector", "Motor", "PoseBivector", "Multivector"]),
    ];
    let source = include_str!("../src/generated.rs");
    for (module, types) in listed {
        let start = source.find(&format!("pub mod {module} {{")).expect("module declared");
        let body = &source[start..];
        let body = &body[..body.find("\n}\n").unwrap_or(body.len())];
        let declared: Vec<&str> = body
            .lines()
            .map(str::trim)
            .filter(|l| !l.starts_with("//") && l.contains(" = ") && l.ends_with(';'))
            .map(|l| l.split(" = ").next().expect("a name"))
            .collect();
        assert_eq!(declared, types, "{module}: update kernels.rs when generated.rs changes");
        assert!(body.contains("Multivector = all;"), "{module} declares its full type");
    }
}

/// The fused versor action keeps the operand's type: a versor sandwich of a vector is a
/// `Vector` (the values are checked above against the projected runtime sandwich).
#[test]
fn a_versor_sandwich_of_a_vector_is_typed_as_a_vector() {
    fn type_of<T>(_: &T) -> String {
        short(type_name::<T>())
    }
    use gam_algebras::{cga, cga_null, g3, g123inf, pga3};
    let outputs = [
        type_of(&g3::Rotor::<f64>::one().sandwich(&g3::Vector::zero())),
        type_of(&g123inf::Motor::<f64>::one().sandwich(&g123inf::Vector::zero())),
        type_of(&pga3::Motor::<f64>::one().sandwich(&pga3::Vector::zero())),
        type_of(&cga::Motor::<f64>::one().sandwich(&cga::Vector::zero())),
        type_of(&cga_null::Motor::<f64>::one().sandwich(&cga_null::Vector::zero())),
    ];
    for out in outputs {
        assert!(out.contains("::Vector<"), "{out}");
    }
}
