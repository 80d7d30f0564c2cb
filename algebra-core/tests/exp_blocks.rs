//! exp of large non-simple f64 bivectors by closed forms per commuting block, against an
//! independent computation: the general MPFR method (scaling and squaring with a Taylor
//! series) at 256 bits on the same (exactly representable) argument. Before the block
//! decomposition these arguments were refused as ill-conditioned.

use crate::common;

use algebra_core::{Algebra, Basis, F64_GENERAL_BOUND, Metric, MpFloat, Multivector, PrecisionGuard, Real};
use common::Xorshift;
use std::sync::Arc;

/// `B0 + θ e12`: every bivector coefficient random in [-1, 1], plus a large rotation angle θ.
fn random_bivector(alg: &Arc<Algebra>, rng: &mut Xorshift, theta: f64) -> Multivector<f64> {
    let mut b = Multivector::<f64>::zero(alg, Basis::Blade);
    for &m in alg.basis_order().iter().filter(|m| m.count_ones() == 2) {
        *b.coeff_mut(m).unwrap() = 2.0 * rng.unit() - 1.0;
    }
    *b.coeff_mut(0b11).unwrap() += theta;
    b
}

fn check(alg: &Arc<Algebra>, seed: u64) -> usize {
    let _g = PrecisionGuard::new(256);
    let mut rng = Xorshift(seed);
    let mut checked = 0;
    for _ in 0..12 {
        let theta = 2e5 * 10f64.powf(rng.unit() * 1.3); // 2e5 .. 4e6
        let b = random_bivector(alg, &mut rng, theta);
        let sq = &b * &b;
        assert!(!sq.grade(4).is_zero(), "non-simple: B² has a 4-vector part");
        let got = b.exp().unwrap_or_else(|e| panic!("{} θ {theta:e}: {e}", alg.name()));
        let want = b.map_coeffs(|c| MpFloat::from_f64(*c)).exp().unwrap();
        let scale = want.coeffs().iter().map(|w| w.to_f64().abs()).fold(0.0, f64::max);
        let err = got.coeffs().iter().zip(want.coeffs()).map(|(g, w)| (g - w.to_f64()).abs()).fold(0.0, f64::max);
        assert!(err <= F64_GENERAL_BOUND * scale, "{} θ {theta:e}: error {err:e} (scale {scale:e})", alg.name());
        checked += 1;
    }
    checked
}

#[test]
fn g4_large_non_simple_bivectors_match_mpfr() {
    let labels = (1..=4).map(|i| i.to_string()).collect();
    let g4 = Algebra::new("g4", Metric::from_squares(labels, vec![algebra_core::rational::q(1); 4]).unwrap());
    assert_eq!(check(&g4, 0x2545f4914f6cdd1d), 12);
}

#[test]
fn cga_large_non_simple_bivectors_match_mpfr() {
    assert_eq!(check(&Algebra::builtin("cga").unwrap(), 0x9e3779b97f4a7c15), 12);
}

#[test]
fn huge_arguments_are_still_refused_and_blocks_match_libm() {
    let labels = (1..=4).map(|i| i.to_string()).collect();
    let g4 = Algebra::new("g4", Metric::from_squares(labels, vec![algebra_core::rational::q(1); 4]).unwrap());
    // equal angles in two planes (λ₁ = λ₂, no unique split): left to the general method,
    // which is accurate here: (cos θ + e12 sin θ)(cos θ + e34 sin θ)
    let iso = Multivector::from_terms(&g4, Basis::Blade, [("e12", 1e6), ("e34", 1e6)]).unwrap();
    let got = iso.exp().unwrap();
    assert!((got.coeff(0).unwrap() - 1e6f64.cos().powi(2)).abs() < 1e-9);
    // angles past 2^26 are known to less than the bound: refused
    let huge = Multivector::from_terms(&g4, Basis::Blade, [("e12", 1e9), ("e34", 2e9)]).unwrap();
    assert!(huge.exp().unwrap_err().to_string().contains("ill-conditioned"));
    // a scalar part multiplies by e^a
    let b = Multivector::from_terms(&g4, Basis::Blade, [("e12", 3e5), ("e34", 7e5)]).unwrap();
    let ab = Multivector::from_terms(&g4, Basis::Blade, [("1", 0.5), ("e12", 3e5), ("e34", 7e5)]).unwrap();
    let (x, y) = (b.exp().unwrap(), ab.exp().unwrap());
    let e = Real::exp(&0.5f64);
    for (p, q) in x.coeffs().iter().zip(y.coeffs()) {
        assert!((p * e - q).abs() <= 4.0 * f64::EPSILON * e, "{p} {q}");
    }
    // against the product of the two plane rotations (libm cos and sin)
    let (c1, s1, c2, s2) = (3e5f64.cos(), 3e5f64.sin(), 7e5f64.cos(), 7e5f64.sin());
    let want = [("1", c1 * c2), ("e12", s1 * c2), ("e34", c1 * s2), ("e1234", s1 * s2)];
    for (name, w) in want {
        let g = *x.coeff_by_name(name).unwrap();
        assert!((g - w).abs() < 1e-9, "{name}: {g} vs {w}");
    }
}
