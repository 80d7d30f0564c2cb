//! Reduced Gröbner bases and normal forms against sympy's `groebner` and `reduced`
//! (fixture: tests/fixtures/sympy/groebner.json, written by the committed script
//! tests/fixtures/sympy/groebner.py).

use crate::sympy_fixture;

use algebra_core::ideal::{Budget, MonomialOrder, PolyRing};
use algebra_core::{Poly, Ring};
use sympy_fixture::{order, poly, systems, variables};

#[test]
fn reduced_bases_and_normal_forms_match_sympy() {
    let systems = systems();
    assert!(systems.len() >= 7);
    for s in &systems {
        let name = s["name"].as_str().unwrap();
        let vars = variables(s);
        let ring = PolyRing::new(&vars, order(s));
        let gens: Vec<Poly> = s["generators"].as_array().unwrap().iter().map(|g| poly(&vars, g)).collect();
        let expected: Vec<Poly> = s["basis"].as_array().unwrap().iter().map(|g| poly(&vars, g)).collect();
        let g = ring.groebner(&gens, &Budget::default()).unwrap();
        assert_eq!(g.polys(), expected, "{name}: reduced basis");
        let nf = g.normal_form(&poly(&vars, &s["target"])).unwrap();
        assert_eq!(nf, poly(&vars, &s["normal_form"]), "{name}: normal form");
    }
}

#[test]
fn cyclic_4_published_basis() {
    // The reduced grevlex basis of cyclic-4 (a > b > c > d) as printed in the literature
    // (e.g. the standard benchmark tables; typed in by hand, independent of the fixture).
    let (a, b, c, d) = (Poly::var("a"), Poly::var("b"), Poly::var("c"), Poly::var("d"));
    let one = Poly::one();
    let k = |n: i64| Poly::from_i64(n);
    let cyclic = [
        a.clone() + b.clone() + c.clone() + d.clone(),
        a.clone() * b.clone() + b.clone() * c.clone() + c.clone() * d.clone() + d.clone() * a.clone(),
        a.clone() * b.clone() * c.clone()
            + b.clone() * c.clone() * d.clone()
            + c.clone() * d.clone() * a.clone()
            + d.clone() * a.clone() * b.clone(),
        a.clone() * b.clone() * c.clone() * d.clone() - one.clone(),
    ];
    let published = [
        a.clone() + b.clone() + c.clone() + d.clone(),
        b.pow_u32(2) + k(2) * b.clone() * d.clone() + d.pow_u32(2),
        b.clone() * c.pow_u32(2) + c.pow_u32(2) * d.clone() - b.clone() * d.pow_u32(2) - d.pow_u32(3),
        b.clone() * c.clone() * d.pow_u32(2) + c.pow_u32(2) * d.pow_u32(2) - b.clone() * d.pow_u32(3)
            + c.clone() * d.pow_u32(3)
            - d.pow_u32(4)
            - one.clone(),
        b.clone() * d.pow_u32(4) + d.pow_u32(5) - b.clone() - d.clone(),
        c.pow_u32(3) * d.pow_u32(2) + c.pow_u32(2) * d.pow_u32(3) - c.clone() - d.clone(),
        c.pow_u32(2) * d.pow_u32(4) + b.clone() * c.clone() - b.clone() * d.clone() + c.clone() * d.clone()
            - k(2) * d.pow_u32(2),
    ];
    let ring = PolyRing::new(["a", "b", "c", "d"], MonomialOrder::GrevLex);
    let g = ring.groebner(&cyclic, &Budget::default()).unwrap();
    assert_eq!(g.polys(), published);
}
