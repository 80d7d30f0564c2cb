//! The kernels of the types a module adds on its own (the full `Multivector` and the parity
//! type `Odd` of a 3D PGA that declares only `Plane`, `Line`, `Point` and `Motor`): since the
//! size policy makes them loops over packed term tables (`algebra_core::kernels`), every one of
//! them is checked here, exactly over rationals, against the runtime engine's products (the
//! multiplication tables of `algebra_core`, not the generator's plan): the eight products for
//! every pair of the six types, `gp_into` onto every type, the fused actions and the action
//! matrices of every pair involving an automatic type. The straight-line kernels of the declared
//! types are checked the same way, and must give the same values.

use algebra_core::Multivector as Mv;
use algebra_core::rational::{Q, ratio};
use algebra_macros::algebra;

algebra! {
    /// 3D PGA as the user declares it.
    pub mod pga {
        metric builtin "pga3";
        types {
            Plane = grade 1;
            Line = grade 2;
            Point = grade 3;
            Motor = even;
        }
    }
}

use pga::*;

/// Small rationals from a fixed linear congruential sequence (zero about one time in seven).
struct Rationals(u64);

impl Rationals {
    fn next(&mut self) -> Q {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        let r = self.0 >> 33;
        ratio((r % 13) as i64 - 6, (r / 13 % 4 + 1) as i64)
    }
}

/// A value of a generated type with coefficients from the sequence.
macro_rules! value {
    ($t:ident, $r:expr) => {{
        let mut x = $t::<Q>::zero();
        for slot in x.iter_mut() {
            *slot = $r.next();
        }
        x
    }};
}

/// Every product of `a` and `b` equals the runtime product of their multivectors.
macro_rules! products {
    ($a:expr, $b:expr) => {{
        let (a, b) = (&$a, &$b);
        let (am, bm): (Mv<Q>, Mv<Q>) = (a.to_multivector(), b.to_multivector());
        assert_eq!(a.gp(b).to_multivector(), am.gp(&bm));
        assert_eq!((a * b).to_multivector(), am.gp(&bm));
        assert_eq!(a.op(b).to_multivector(), am.op(&bm));
        assert_eq!(a.lc(b).to_multivector(), am.lc(&bm));
        assert_eq!(a.rc(b).to_multivector(), am.rc(&bm));
        assert_eq!(a.sp(b).to_multivector(), am.sp(&bm));
        assert_eq!(a.regressive(b).to_multivector(), am.regressive(&bm));
        assert_eq!(a.commutator(b).to_multivector(), am.commutator(&bm));
        assert_eq!(a.anticommutator(b).to_multivector(), am.anticommutator(&bm));
    }};
}

/// `gp_into` onto each listed type is the projection of the runtime product.
macro_rules! typed {
    ($a:expr, $b:expr; $($out:ident),*) => {{
        let (a, b) = (&$a, &$b);
        let full: Mv<Q> = a.to_multivector().gp(&b.to_multivector());
        $(
            let r: $out<Q> = a.gp_into(b);
            assert_eq!(r, $out::project(&full));
        )*
    }};
}

/// The fused actions of `v` on `x` are the projections of the runtime sandwiches.
macro_rules! actions {
    ($v:expr, $x:expr, $xt:ident) => {{
        let (v, x) = (&$v, &$x);
        let (vm, xm): (Mv<Q>, Mv<Q>) = (v.to_multivector(), x.to_multivector());
        assert_eq!(v.apply(x), $xt::project(&vm.gp(&xm).gp(&vm.reverse())));
        assert_eq!(v.sandwich(x), $xt::project(&vm.reverse().gp(&xm).gp(&vm)));
    }};
}

/// The fused actions of a general multivector `v`, whose results are full multivectors: the
/// runtime sandwiches themselves.
macro_rules! full_actions {
    ($v:expr, $x:expr) => {{
        let (v, x) = (&$v, &$x);
        let (vm, xm): (Mv<Q>, Mv<Q>) = (v.to_multivector(), x.to_multivector());
        assert_eq!(v.apply(x).to_multivector(), vm.gp(&xm).gp(&vm.reverse()));
        assert_eq!(v.sandwich(x).to_multivector(), vm.reverse().gp(&xm).gp(&vm));
    }};
}

/// The action matrices of `v` on `x` give the fused actions.
macro_rules! matrices {
    ($v:expr, $x:expr, $vt:ident, $xt:ident) => {{
        let (v, x) = (&$v, &$x);
        let am = <$vt<Q> as ActionMatrix<$xt<Q>>>::apply_matrix(v);
        let sm = <$vt<Q> as ActionMatrix<$xt<Q>>>::sandwich_matrix(v);
        assert_eq!(<$vt<Q> as ActionMatrix<$xt<Q>>>::transform(&am, x), v.apply(x));
        assert_eq!(<$vt<Q> as ActionMatrix<$xt<Q>>>::transform(&sm, x), v.sandwich(x));
    }};
}

#[test]
fn the_automatic_types_are_the_full_multivector_and_the_odd_part() {
    assert_eq!(Multivector::<Q>::LEN, 16);
    assert_eq!(Odd::<Q>::LEN, 8);
    // a product of two declared types lands in the automatic odd type
    let mut r = Rationals(1);
    let (m, p) = (value!(Motor, r), value!(Plane, r));
    let _: Odd<Q> = m.gp(&p);
}

#[test]
fn every_product_of_every_pair_agrees_with_the_runtime_engine() {
    let mut r = Rationals(7);
    for _ in 0..4 {
        let (pl, li, pt, mo) = (value!(Plane, r), value!(Line, r), value!(Point, r), value!(Motor, r));
        let (od, mv) = (value!(Odd, r), value!(Multivector, r));
        macro_rules! rows {
            ($($a:ident),*) => {$(
                products!($a, pl); products!($a, li); products!($a, pt);
                products!($a, mo); products!($a, od); products!($a, mv);
            )*};
        }
        rows!(pl, li, pt, mo, od, mv);
    }
}

#[test]
fn typed_products_onto_every_type_agree_with_the_runtime_engine() {
    let mut r = Rationals(11);
    let (pl, li, mo) = (value!(Plane, r), value!(Line, r), value!(Motor, r));
    let (od, mv) = (value!(Odd, r), value!(Multivector, r));
    typed!(mv, mv; Plane, Line, Point, Motor, Odd);
    typed!(mv, mo; Plane, Line, Point, Motor, Odd);
    typed!(od, mo; Plane, Point, Multivector);
    typed!(mo, od; Plane, Point, Multivector);
    typed!(od, od; Line, Motor, Multivector);
    typed!(pl, li; Plane, Point, Multivector);
    typed!(mo, mo; Line, Multivector);
}

#[test]
fn actions_of_and_on_automatic_types_agree_with_the_runtime_engine() {
    let mut r = Rationals(13);
    let (pl, li, pt, mo) = (value!(Plane, r), value!(Line, r), value!(Point, r), value!(Motor, r));
    let (od, mv) = (value!(Odd, r), value!(Multivector, r));
    actions!(od, pl, Plane);
    actions!(od, li, Line);
    actions!(od, pt, Point);
    actions!(od, mo, Motor);
    actions!(od, od, Odd);
    actions!(od, mv, Multivector);
    full_actions!(mv, pt);
    full_actions!(mv, mv);
    actions!(mo, od, Odd);
    actions!(mo, mv, Multivector);
    actions!(pl, mv, Multivector);
    // declared on declared: straight-line kernels, the same reference
    actions!(mo, pt, Point);
    actions!(pl, li, Line);
}

#[test]
fn action_matrices_of_and_on_the_odd_type_agree_with_the_fused_actions() {
    let mut r = Rationals(17);
    let (pl, li, pt, mo, od) = (value!(Plane, r), value!(Line, r), value!(Point, r), value!(Motor, r), value!(Odd, r));
    matrices!(od, pl, Odd, Plane);
    matrices!(od, li, Odd, Line);
    matrices!(od, pt, Odd, Point);
    matrices!(od, mo, Odd, Motor);
    matrices!(od, od, Odd, Odd);
    matrices!(mo, od, Motor, Odd);
    matrices!(pl, od, Plane, Odd);
    // declared on declared: straight-line matrices
    matrices!(mo, pt, Motor, Point);
    matrices!(pt, li, Point, Line);
}

#[test]
fn kernels_over_automatic_types_agree_in_floating_point() {
    // the table loop adds in four interleaved chains: within a few ulps of the exact value
    let mut r = Rationals(19);
    let (mo, mv) = (value!(Motor, r), value!(Multivector, r));
    let f = |x: &Q| x.numer().to_string().parse::<f64>().unwrap() / x.denom().to_string().parse::<f64>().unwrap();
    let (mof, mvf) = (
        Motor::<f64>::from_array(mo.to_array().map(|c| f(&c))),
        Multivector::<f64>::from_array(mv.to_array().map(|c| f(&c))),
    );
    let (exact, float) = (mv.gp(&mo), mvf.gp(&mof));
    for (e, x) in exact.iter().zip(float.iter()) {
        assert!((f(e) - x).abs() <= 1e-12 * (1.0 + f(e).abs()), "{} vs {x}", f(e));
    }
}

algebra! {
    /// 3D PGA with a type that is part of a grade: planes through the origin.
    pub mod partial {
        metric builtin "pga3";
        types {
            Motor = even;
            Direction = [e1, e2, e3];
        }
    }
}

/// A versor that moves an operand out of its declared type (a motor takes a plane through the
/// origin, declared as `Direction = [e1, e2, e3]`, to a plane off it) has no fused kernel for
/// that pair: `apply` and `sandwich` are the full products, whose type holds the `e0` part a
/// projection onto `Direction` would silently drop.
#[test]
fn actions_that_leave_the_operand_type_keep_the_whole_image() {
    let mut r = Rationals(23);
    for _ in 0..8 {
        use partial::{Direction, Motor};
        let (m, d) = (value!(Motor, r), value!(Direction, r));
        let (mm, dm): (Mv<Q>, Mv<Q>) = (m.to_multivector(), d.to_multivector());
        assert_eq!(m.apply(&d).to_multivector(), mm.gp(&dm).gp(&mm.reverse()));
        assert_eq!(m.sandwich(&d).to_multivector(), mm.reverse().gp(&dm).gp(&mm));
    }
    // the translation by 2 along e1 (`1 + e01` in pga3's convention up to sign) moves the
    // plane x = 0 off the origin: the image has an e0 part
    let mut t = partial::Motor::<Q>::one();
    t.e01 = ratio(1, 1);
    let x0 = partial::Direction::<Q> { e1: ratio(1, 1), e2: ratio(0, 1), e3: ratio(0, 1) };
    let image = t.apply(&x0).to_multivector();
    assert_ne!(*image.coeff_by_name("e0").unwrap(), ratio(0, 1), "{image:?}");
}
