//! The NaN policy of the closed forms (docs/robustness.md): `exp` is an unchecked kernel (NaN
//! in, NaN out), `try_exp` and every `Result`-returning closed form refuse a NaN or infinite
//! coefficient with the runtime's "coefficients are not finite".

use algebra_core::MvError;
use gam_algebras::{g123inf, pga3};

const BAD: [f64; 3] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];

fn not_finite<X: std::fmt::Debug>(r: Result<X, MvError>, op: &str) {
    match r {
        Err(MvError::Undefined { op: o, why, .. }) => {
            assert_eq!(o, op);
            assert_eq!(why, "coefficients are not finite");
        }
        other => panic!("{op}: expected a not-finite error, got {other:?}"),
    }
}

#[test]
fn g123inf_closed_forms_refuse_non_finite_coefficients() {
    for bad in BAD {
        for k in 0..6 {
            let mut b = g123inf::Bivector::<f64>::e12() * 0.3 + g123inf::Bivector::e1inf() * 0.2;
            *b.iter_mut().nth(k).unwrap() = bad;
            not_finite(b.try_exp(), "exp");
            // the unchecked kernel: NaN out, never a finite wrong number
            assert!(b.exp().iter().any(|c| !c.is_finite()), "{b:?}");
        }
        for k in 0..8 {
            let mut m = (g123inf::Bivector::<f64>::e23() * 0.4).exp();
            *m.iter_mut().nth(k).unwrap() = bad;
            not_finite(m.normalize(), "normalize");
            not_finite(m.log(), "log");
            not_finite(m.log_unit(), "log");
            not_finite(m.sqrt(), "log");
        }
        let m = (g123inf::Bivector::<f64>::e23() * 0.4).exp();
        not_finite(m.pow(&bad), "pow");
    }
}

#[test]
fn pga3_closed_forms_refuse_non_finite_coefficients() {
    for bad in BAD {
        let mut b = pga3::Bivector::<f64>::e12() * 0.3;
        *b.iter_mut().next().unwrap() = bad;
        not_finite(b.try_exp(), "exp");
        let mut m = (pga3::Bivector::<f64>::e12() * 0.3).exp();
        *m.iter_mut().last().unwrap() = bad;
        not_finite(m.normalize(), "normalize");
        not_finite(m.log_unit(), "log");
    }
}

#[test]
fn try_exp_of_finite_input_is_exp_or_an_overflow_error() {
    let b = g123inf::Bivector::<f64>::e12() * 0.7 + g123inf::Bivector::e3inf() * -2.0;
    assert_eq!(b.try_exp().unwrap(), b.exp());
    // θ² = 2e300² overflows: the kernel gives NaN, the checked form says why
    let huge = g123inf::Bivector::<f64>::e12() * 1e300 + g123inf::Bivector::e13() * 1e300;
    assert!(huge.exp().iter().any(|c| c.is_nan()));
    match huge.try_exp() {
        Err(MvError::Undefined { why, .. }) => assert!(why.starts_with("the result is not finite"), "{why}"),
        other => panic!("{other:?}"),
    }
}
