//! Symbolic elements of generated types (the generated `Type::<Poly>::symbolic(prefix)`, and
//! `Multivector::symbolic` + the type's `project`): the generated kernels over `Poly` agree
//! with the runtime product on fully symbolic inputs.

use algebra_core::multivector::symbolic::Part;
use algebra_core::{Multivector, Poly};
use gam_algebras::cga_null;

fn symbolic_motor(prefix: &str) -> cga_null::Motor<Poly> {
    let part = Part::elements(&cga_null::Motor::<Poly>::ELEMENTS);
    let m = Multivector::symbolic(&cga_null::algebra(), cga_null::BASIS, prefix, &part).unwrap();
    cga_null::Motor::project(&m)
}

#[test]
fn generated_symbolic_constructor_equals_the_runtime_route() {
    assert_eq!(cga_null::Motor::<Poly>::symbolic("S"), symbolic_motor("S"));
    let x = Multivector::symbolic(&cga_null::algebra(), cga_null::BASIS, "x", &Part::Grade(1)).unwrap();
    assert_eq!(cga_null::Vector::<Poly>::symbolic("x"), cga_null::Vector::project(&x));
    assert_eq!(cga_null::Vector::<Poly>::symbolic("x").to_string(), "x0*e0 + x1*e1 + x2*e2 + x3*e3 + xinf*einf");
}

#[test]
fn symbolic_generated_motor_has_the_cli_symbol_names() {
    let s = cga_null::Motor::<Poly>::symbolic("S");
    assert_eq!(
        s.to_string(),
        "S + S12*e12 + S13*e13 + S23*e23 + S1inf*e1inf + S2inf*e2inf + S3inf*e3inf + S123inf*e123inf"
    );
}

#[test]
fn generated_sandwich_equals_runtime_on_symbolic_inputs() {
    let s = symbolic_motor("S");
    let x = Multivector::symbolic(&cga_null::algebra(), cga_null::BASIS, "x", &Part::Grade(1)).unwrap();
    let xv = cga_null::Vector::project(&x);
    let runtime = &(&s.to_multivector().reverse() * &x) * &s.to_multivector();
    let generated =
        algebra_core::ops::GeometricProduct::gp(&algebra_core::ops::GeometricProduct::gp(&s.reverse(), &xv), &s);
    assert_eq!(Multivector::from(&generated), runtime);
}
