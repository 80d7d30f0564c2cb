//! Every lane type's operations against the scalar operation, lane by lane (proptest): ring
//! and field arithmetic exactly (IEEE operations per lane), the elementary functions within a
//! few ulps of `std`, comparisons and `select` exactly; the whole-vector answers (`==`,
//! `is_exact_zero`, `magnitude`, `try_recip`) as documented; `LaneDual` over lanes against
//! `Jet` over the scalar, lane by lane; the packing of [`Lanes`] (load, store, padding, the
//! lane without a reciprocal).
#![cfg(feature = "lanes")]

use algebra_core::scalar::{Diagnostics, Elementary, F32x4, F32x8, F64x2, F64x4, LaneDual, Lanes, Mask, Select};
use algebra_core::{Field, Jet, Real, Ring};
use proptest::prelude::*;

/// `|got - want| <= ulps · ε · max(1, |want|)`.
fn close(got: f64, want: f64, eps: f64, ulps: f64) -> bool {
    (got.is_nan() && want.is_nan()) || (got - want).abs() <= ulps * eps * want.abs().max(1.0)
}

macro_rules! lane_tests {
    ($modname:ident, $lane:ident, $elem:ident, $n:literal) => {
        mod $modname {
            use super::*;

            fn lanes(range: std::ops::Range<$elem>) -> impl Strategy<Value = [$elem; $n]> {
                prop::array::uniform::<_, $n>(range)
            }

            fn check_unary(x: [$elem; $n], lane_f: impl Fn(&$lane) -> $lane, f: impl Fn($elem) -> $elem, ulps: f64) {
                let got = lane_f(&$lane::from(x)).to_array();
                for i in 0..$n {
                    let want = f(x[i]);
                    assert!(
                        close(f64::from(got[i]), f64::from(want), f64::from($elem::EPSILON), ulps),
                        "lane {i}: x = {}, got {}, want {want}",
                        x[i],
                        got[i]
                    );
                }
            }

            proptest! {
                #[test]
                fn arithmetic_is_the_scalar_arithmetic_per_lane(x in lanes(-1e3..1e3), y in lanes(-1e3..1e3)) {
                    let (a, b) = ($lane::from(x), $lane::from(y));
                    let (sum, diff, prod, neg) = (a.add_ref(&b), a.sub_ref(&b), a.mul_ref(&b), a.neg_ref());
                    let quot = a.div_ref(&b);
                    for i in 0..$n {
                        prop_assert_eq!(sum.lane(i), x[i] + y[i]);
                        prop_assert_eq!(diff.lane(i), x[i] - y[i]);
                        prop_assert_eq!(prod.lane(i), x[i] * y[i]);
                        prop_assert_eq!(quot.lane(i), x[i] / y[i]);
                        prop_assert_eq!(neg.lane(i), -x[i]);
                    }
                    prop_assert_eq!((a.clone() * b.clone()).to_array(), prod.to_array());
                    prop_assert_eq!((a.clone() + &b).to_array(), sum.to_array());
                }

                #[test]
                fn elementary_functions_match_std_per_lane(x in lanes(-50.0..50.0), p in lanes(1e-3..1e3), y in lanes(-50.0..50.0)) {
                    check_unary(x, Elementary::sin, $elem::sin, 4.0);
                    check_unary(x, Elementary::cos, $elem::cos, 4.0);
                    check_unary(x, Elementary::abs, $elem::abs, 0.0);
                    check_unary(x, Elementary::exp, $elem::exp, 4.0);
                    check_unary(p, Elementary::sqrt, $elem::sqrt, 0.0);
                    check_unary(p, Elementary::ln, $elem::ln, 4.0);
                    let got = Elementary::atan2(&$lane::from(x), &$lane::from(y)).to_array();
                    for i in 0..$n {
                        let want = x[i].atan2(y[i]);
                        prop_assert!(close(f64::from(got[i]), f64::from(want), f64::from($elem::EPSILON), 4.0));
                    }
                }

                #[test]
                fn comparisons_and_select_are_per_lane(x in lanes(-2.0..2.0), y in lanes(-2.0..2.0)) {
                    let (a, b) = ($lane::from(x), $lane::from(y));
                    let lt = a.lt_mask(&b);
                    let picked = $lane::select(&lt, &a, &b).to_array();
                    let masks = [(a.lt_mask(&b), 0), (a.le_mask(&b), 1), (a.gt_mask(&b), 2), (a.ge_mask(&b), 3), (a.eq_mask(&a), 4)];
                    for i in 0..$n {
                        prop_assert_eq!(picked[i], if x[i] < y[i] { x[i] } else { y[i] });
                        for (m, k) in masks {
                            let want = [x[i] < y[i], x[i] <= y[i], x[i] > y[i], x[i] >= y[i], true][k];
                            prop_assert_eq!(m.to_array()[i], want);
                        }
                    }
                    prop_assert_eq!(lt.any(), (0..$n).any(|i| x[i] < y[i]));
                    prop_assert_eq!(lt.all(), (0..$n).all(|i| x[i] < y[i]));
                    prop_assert_eq!((!lt).to_array(), lt.to_array().map(|b| !b));
                    prop_assert_eq!((lt & !lt).any(), false);
                    prop_assert_eq!((lt | !lt).all(), true);
                }

                #[test]
                fn diagnostics_are_max_and_min_over_lanes(x in lanes(-1e3..1e3)) {
                    let a = $lane::from(x);
                    let wide = x.map(f64::from);
                    let max = wide.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                    let min = wide.iter().copied().fold(f64::INFINITY, f64::min);
                    prop_assert_eq!(a.max_to_f64(), max);
                    prop_assert_eq!(a.min_to_f64(), min);
                    prop_assert_eq!(a.magnitude(), wide.iter().map(|v| f64::abs(*v)).fold(0.0, f64::max));
                    prop_assert_eq!(a.lane_to_f64($n), None);
                    for i in 0..$n {
                        prop_assert_eq!(a.lane_to_f64(i), Some(wide[i]));
                    }
                }

                #[test]
                fn lane_duals_are_jets_per_lane(x in lanes(0.1..3.0), dx in lanes(-2.0..2.0), y in lanes(-3.0..3.0)) {
                    let d = LaneDual::new($lane::from(x), $lane::from(dx));
                    let e = LaneDual::variable($lane::from(y));
                    let f = |t: &LaneDual<$lane>, u: &LaneDual<$lane>| {
                        t.sin().mul_ref(&u.exp()).add_ref(&t.ln().div_ref(&t.sqrt())).sub_ref(&u.atan2(t).mul_ref(&u.cos().abs()))
                    };
                    let got = f(&d, &e);
                    for i in 0..$n {
                        let (t, u) = (Jet::new(f64::from(x[i]), f64::from(dx[i])), Jet::new(f64::from(y[i]), 1.0));
                        let want = Real::sin(&t) * Real::exp(&u) + Real::ln(&t) / Real::sqrt(&t)
                            - Real::atan2(&u, &t) * Real::abs(&Real::cos(&u));
                        let eps = f64::from($elem::EPSILON);
                        prop_assert!(close(f64::from(got.re.lane(i)), want.re, eps, 64.0), "value lane {}", i);
                        prop_assert!(close(f64::from(got.eps.lane(i)), want.eps, eps, 64.0), "derivative lane {}", i);
                    }
                }
            }

            #[test]
            fn whole_vector_answers_are_every_lane_or_any_lane() {
                let mut x = [0.0 as $elem; $n];
                assert!($lane::from(x).is_exact_zero());
                x[$n - 1] = 1.0;
                let a = $lane::from(x);
                assert!(!a.is_exact_zero());
                // one zero lane: no reciprocal
                assert!(a.try_recip().is_none());
                assert_eq!($lane::splat(4.0).try_recip().unwrap().to_array(), [0.25; $n]);
                // `==` is every lane
                assert_eq!(a, $lane::from(x));
                let mut y = x;
                y[0] = 2.0;
                assert_ne!(a, $lane::from(y));
                // one non-finite lane
                y[0] = $elem::NAN;
                assert!(!$lane::from(y).is_finite_value() && $lane::from(y).magnitude().is_nan());
                assert_eq!($lane::from(y).finite_mask().to_array()[0], false);
                assert!(a.is_finite_value());
                assert_eq!(<$lane as Diagnostics>::LANES, $n);
                assert_eq!($lane::from_ratio(1, 4).to_array(), [0.25; $n]);
                assert_eq!($lane::pi().lane(0), std::f64::consts::PI as $elem);
                let shown = $lane::splat(1.5).to_string();
                assert_eq!(shown, format!("[{}]", vec!["1.5"; $n].join(", ")));
            }

            #[test]
            fn packing_loads_stores_pads_and_names_the_lane_without_a_reciprocal() {
                assert_eq!(<$lane as Lanes>::WIDTH, <$lane as Diagnostics>::LANES);
                let xs: [$elem; $n] = std::array::from_fn(|i| i as $elem + 0.5);
                let v = <$lane as Lanes>::load(&xs);
                assert_eq!(v.to_array(), xs);
                assert_eq!(<$lane as Lanes>::splat(&2.5).to_array(), [2.5; $n]);
                // a full store, and a remainder store that leaves the rest of `out` alone
                let mut out = [-1.0 as $elem; $n];
                v.store(&mut out);
                assert_eq!(out, xs);
                let mut short = [-1.0 as $elem; $n];
                v.store(&mut short[..$n - 1]);
                assert_eq!(&short[..$n - 1], &xs[..$n - 1]);
                assert_eq!(short[$n - 1], -1.0);
                // the remainder chunk padded with `pad`
                let padded = <$lane as Lanes>::load_padded(&xs[..1], &7.0);
                let mut want = [7.0 as $elem; $n];
                want[0] = xs[0];
                assert_eq!(padded.to_array(), want);
                assert_eq!(<$lane as Lanes>::load_padded(&xs, &7.0).to_array(), xs);
                // per-lane reciprocals, or the first lane without one
                assert_eq!(v.recip_lanes().unwrap().to_array(), xs.map(|x| 1.0 / x));
                for lane in 0..$n {
                    let mut z = xs;
                    z[lane] = 0.0;
                    assert_eq!($lane::from(z).recip_lanes(), Err(lane));
                }
            }
        }
    };
}

lane_tests!(f32x4, F32x4, f32, 4);
lane_tests!(f32x8, F32x8, f32, 8);
lane_tests!(f64x2, F64x2, f64, 2);
lane_tests!(f64x4, F64x4, f64, 4);

#[test]
fn scalars_keep_their_meaning_through_the_blanket_impls() {
    // f64: one lane, bool masks, the Real functions.
    assert_eq!(<f64 as Diagnostics>::LANES, 1);
    assert!(1.0f64.lt_mask(&2.0) && !f64::NAN.lt_mask(&2.0) && !f64::NAN.eq_mask(&f64::NAN));
    assert_eq!(Elementary::exp(&1.0f64), 1.0f64.exp());
    // num-dual: comparisons on the real part, as its `<`.
    let d = num_dual::Dual64::new(1.0, 5.0);
    assert!(d.eq_mask(&num_dual::Dual64::new(1.0, -3.0)));
    assert_eq!(Elementary::sin(&d).eps, 1.0f64.cos() * 5.0);
    // Jet: one lane whose value is the value part.
    assert_eq!(Jet::new(2.0, 7.0).lane_to_f64(0), Some(2.0));
    assert!(<bool as Mask>::splat(true).all());
    // the scalars are lane types of width 1; exact rationals too
    assert_eq!((<f64 as Lanes>::WIDTH, <f32 as Lanes>::WIDTH), (1, 1));
    let third = algebra_core::rational::ratio(1, 3);
    assert_eq!(
        <algebra_core::rational::Q as Lanes>::load(std::slice::from_ref(&third)).recip_lanes(),
        Ok(algebra_core::rational::q(3))
    );
    assert_eq!(Lanes::recip_lanes(&algebra_core::rational::q(0)), Err(0));
}
