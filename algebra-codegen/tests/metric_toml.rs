//! The TOML algebra format's range policy: contradictory metric entries are rejected.

use algebra_codegen::metric_toml::metric_from_toml_str;
use algebra_core::rational::ratio;

#[test]
fn contradictory_toml_metric_entries_are_rejected() {
    let text = "generators = [\"a\", \"b\"]\nmetric = { \"a,b\" = 1, \"b,a\" = 2 }";
    let e = metric_from_toml_str(text, "x.toml").unwrap_err().to_string();
    assert!(e.contains("contradicts"), "{e}");
    // the same value twice is consistent
    let text = "generators = [\"a\", \"b\"]\nmetric = { \"a,a\" = 1, \"a,b\" = \"1/2\", \"b,a\" = \"2/4\" }";
    let (_, m) = metric_from_toml_str(text, "x.toml").unwrap();
    assert_eq!(m.gram(0, 1).unwrap(), &ratio(1, 2));
}
