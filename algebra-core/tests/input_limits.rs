//! Range policy of algebra-core's inputs: checked masks, the decimal exponent cap (checked
//! before any digits are built), contradictory TOML metric entries (in algebra-codegen/tests/metric_toml.rs).

use algebra_core::rational::{MAX_DECIMAL_EXPONENT, RationalParseError, parse_rational, ratio};
use algebra_core::{Algebra, Basis, Multivector, MvError};

#[test]
fn masks_out_of_range_are_errors() {
    let alg = Algebra::builtin("cga").unwrap();
    for mask in [32, 33, 1 << 20, u32::MAX] {
        assert!(matches!(Multivector::<f64>::from_mask(&alg, Basis::Blade, mask), Err(MvError::MaskOutOfRange { .. })));
        let x = Multivector::<f64>::scalar(&alg, Basis::Blade, 1.0);
        assert!(matches!(x.coeff(mask), Err(MvError::MaskOutOfRange { mask: m, generators: 5 }) if m == mask));
    }
    for mask in 0..32 {
        assert_eq!(Multivector::<f64>::from_mask(&alg, Basis::Product, mask).unwrap().coeff(mask), Ok(&1.0));
    }
}

#[test]
fn decimal_exponents_are_capped_before_any_work() {
    let start = std::time::Instant::now();
    for text in ["1e2147483648", "1e2147483647", "1e-2147483648", "1e99999999999999999999999", "2.5E100001"] {
        assert!(matches!(parse_rational(text), Err(RationalParseError::ExponentTooLarge(_))), "{text}");
    }
    assert!(start.elapsed().as_secs() < 5, "the cap must be checked before building 10^e");
    let at_cap = parse_rational(&format!("1e-{MAX_DECIMAL_EXPONENT}")).unwrap();
    assert_eq!(at_cap * num_traits::pow(num_bigint::BigInt::from(10), MAX_DECIMAL_EXPONENT as usize), ratio(1, 1));
    assert_eq!(parse_rational("1.5e3").unwrap(), ratio(1500, 1));
    assert!(parse_rational("1e").is_err() && parse_rational("e5").is_err());
}
