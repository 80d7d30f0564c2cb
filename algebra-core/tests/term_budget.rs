//! Budgets before work: a `Poly` product, alone or inside a multivector product, is refused
//! with a typed error before it forms more term products than allowed, and the estimate is
//! exact when nothing cancels and an upper bound on the result's terms otherwise. The table
//! work of a metric grows as `4^n` (diagonal) to `8^n` (dense).

use algebra_core::multivector::symbolic::Part;
use algebra_core::poly::TermBudget;
use algebra_core::rational::q;
use algebra_core::{Algebra, Basis, Metric, Multivector, MvError, Poly, Product, Ring, Tables};

fn sum_of_vars(prefix: &str, n: usize) -> Poly {
    (0..n).map(|i| Poly::var(&format!("{prefix}{i}"))).fold(Poly::zero(), |a, b| a + b)
}

#[test]
fn poly_products_are_refused_before_work() {
    let (x, y) = (sum_of_vars("x", 40), sum_of_vars("y", 25));
    // distinct monomials x_i y_j: the estimate 40 x 25 is the exact term count
    assert_eq!(x.checked_mul(&y, 1000).unwrap().term_count(), 1000);
    assert_eq!(x.checked_mul(&y, 999), Err(TermBudget { estimate: 1000, budget: 999 }));
    // (x0 + ... + x39)^2 has 40*41/2 distinct monomials: fewer than the 1600 term products
    let sq = x.checked_mul(&x, 1600).unwrap();
    assert_eq!(sq.term_count(), 820);
    assert_eq!(sq, x.clone() * x.clone());
    // 3000 x 3000 term products against a budget of a million: refused, nothing formed
    let z = sum_of_vars("z", 3000);
    assert_eq!(z.checked_mul(&z, 1_000_000), Err(TermBudget { estimate: 9_000_000, budget: 1_000_000 }));
}

#[test]
fn multivector_estimate_is_exact_without_cancellation() {
    // g3 vectors a, b with symbolic coefficients: a b has 9 distinct monomials a_i b_j
    let g3 = Algebra::builtin("g3").unwrap();
    let a = Multivector::symbolic(&g3, Basis::Blade, "a", &Part::Grade(1)).unwrap();
    let b = Multivector::symbolic(&g3, Basis::Blade, "b", &Part::Grade(1)).unwrap();
    assert_eq!(a.product_terms(&b, Product::Geometric).unwrap(), 9);
    let ab = a.checked_product(&b, Product::Geometric, 9).unwrap();
    assert_eq!(ab.coeffs().iter().map(Poly::term_count).sum::<usize>(), 9);
    assert_eq!(ab, &a * &b);
    // the outer product meets only the 6 off-diagonal pairs
    assert_eq!(a.product_terms(&b, Product::Outer).unwrap(), 6);
    match a.checked_product(&b, Product::Geometric, 8) {
        Err(MvError::TooManyTerms(t)) => assert_eq!(t, TermBudget { estimate: 9, budget: 8 }),
        other => panic!("{other:?}"),
    }
}

#[test]
fn multivector_estimate_bounds_the_result() {
    // general even elements of cga-null in the product basis (tables with several entries)
    let alg = Algebra::builtin("cga-null").unwrap();
    for (part, basis) in [(Part::Even, Basis::Product), (Part::All, Basis::Blade), (Part::Grade(2), Basis::Product)] {
        let s = Multivector::symbolic(&alg, basis, "S", &part).unwrap();
        let t = Multivector::symbolic(&alg, basis, "T", &part).unwrap();
        let st = &s * &t;
        let estimate = s.product_terms(&t, Product::Geometric).unwrap();
        let terms: usize = st.coeffs().iter().map(Poly::term_count).sum();
        assert!(terms as u128 <= estimate && estimate > 0, "{part:?}: {terms} terms, estimate {estimate}");
        assert_eq!(s.checked_product(&t, Product::Geometric, estimate as u64).unwrap(), st);
    }
}

#[test]
fn table_work_grows_with_the_coupled_generators() {
    let dense = |n: usize| {
        let gram = (0..n).map(|i| (0..n).map(|j| if i == j { q(2) } else { q(1) }).collect()).collect();
        Metric::new((0..n).map(|i| format!("a{i}")).collect(), gram).unwrap()
    };
    for n in 1..=10 {
        let diagonal = Metric::diagonal(n, 0, 0).unwrap();
        assert_eq!(Tables::build_work(&diagonal), 4f64.powi(n as i32));
        let expected = if n == 1 { 4.0 } else { 8f64.powi(n as i32) };
        assert_eq!(Tables::build_work(&dense(n)), expected, "n = {n}");
    }
}
