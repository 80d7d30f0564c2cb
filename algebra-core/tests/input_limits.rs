//! Range policy of algebra-core's inputs: checked masks, the decimal exponent cap (checked
//! before any digits are built), contradictory TOML metric entries (in algebra-codegen/tests/metric_toml.rs).

use algebra_core::rational::{MAX_DECIMAL_EXPONENT, RationalParseError, parse_rational, ratio};
use algebra_core::{Algebra, Basis, MetricError, Multivector, MvError, Product, Unary};

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
fn table_and_name_lookups_check_their_masks() {
    let alg = Algebra::builtin("cga").unwrap();
    let gp = alg.tables().product(Basis::Blade, Product::Geometric);
    let rev = alg.tables().unary(Basis::Blade, Unary::Reverse);
    for bad in [32, 33, 1 << 20, u32::MAX] {
        let out = Err(MvError::MaskOutOfRange { mask: bad, generators: 5 });
        assert_eq!(alg.name_of(bad), out.clone().map(|()| ""));
        assert_eq!(gp.get(bad, 0), out.clone().map(|()| &[][..]));
        assert_eq!(gp.get(1, bad), out.clone().map(|()| &[][..]));
        assert_eq!(rev.image(bad), out.map(|()| &[][..]));
    }
    // in range: e1 e1 = 1, e12 reversed = -e12, the top element's name
    assert_eq!(gp.get(1, 1).unwrap(), &[(0, ratio(1, 1))]);
    assert_eq!(rev.image(0b11).unwrap(), &[(0b11, ratio(-1, 1))]);
    assert_eq!(alg.name_of(0b11111).unwrap(), "e12345");
}

#[test]
fn gram_checks_its_indices() {
    let m = Algebra::builtin("cga").unwrap().metric().clone();
    for (i, j) in [(5, 0), (0, 5), (usize::MAX, usize::MAX)] {
        let index = if i >= 5 { i } else { j };
        assert_eq!(m.gram(i, j), Err(MetricError::IndexOutOfRange { index, generators: 5 }));
    }
    assert_eq!(m.gram(4, 4).unwrap(), &ratio(-1, 1));
    assert_eq!(m.gram(3, 3).unwrap(), &ratio(1, 1));
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
