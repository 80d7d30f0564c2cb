//! `gam pose`'s `cga_rotor` (Wareham–Lasenby): its action `R F(x) rev(R)` on conformal points,
//! computed by `gam eval --algebra cga` (the runtime algebra, not the motion library), against
//! `F(M x)` with `M` the Rodrigues matrix built here; `R rev(R) = 1`; the contract's sign rule.

use crate::common;

use common::{ok, rodrigues};
use serde_json::Value;

/// (axis, angle, position): generic, identity, pure translation, half turn, tiny angle, far away.
const POSES: [([f64; 3], f64, [f64; 3]); 6] = [
    ([1.0, 2.0, 2.0], 0.7, [1.0, -2.0, 4.0]),
    ([0.0, 0.0, 1.0], 0.0, [0.0, 0.0, 0.0]),
    ([0.0, 0.0, 1.0], 0.0, [3.0, -1.0, 0.5]),
    ([0.0, 1.0, 0.0], std::f64::consts::PI, [1.0, 2.0, 3.0]),
    ([1.0, -1.0, 0.5], 1e-9, [0.25, 0.0, -2.0]),
    ([-0.3, 0.4, 1.0], 2.5, [1e3, -2e3, 5e2]),
];

const X: [[f64; 3]; 3] = [[0.0, 0.0, 0.0], [0.5, -1.0, 2.0], [-3.0, 1.5, 0.25]];

/// The multivector of a `{"blade": "number"}` map as a `gam eval` expression.
fn expr(mv: &Value) -> String {
    let terms: Vec<String> = mv
        .as_object()
        .unwrap()
        .iter()
        .map(|(k, c)| {
            // the `gam eval` grammar has no exponent notation: Rust's `{}` prints plain decimals
            let c: f64 = c.as_str().unwrap().parse().unwrap();
            if k == "1" { format!("({c})") } else { format!("({c})*{k}") }
        })
        .collect();
    format!("({})", terms.join(" + "))
}

/// `F(x) = (x² n + 2x - n̄)/2`, `n = e4 + e5`, `n̄ = e4 - e5`, as a `gam eval` expression.
fn embed(x: [f64; 3]) -> String {
    let x2 = x.iter().map(|c| c * c).sum::<f64>();
    format!("(({x2})*(e4 + e5) + 2*(({})*e1 + ({})*e2 + ({})*e3) - (e4 - e5))/2", x[0], x[1], x[2])
}

/// `gam eval --algebra cga --scalar f64 --json` as blade -> number (absent blades are 0).
fn eval(e: &str) -> std::collections::BTreeMap<String, f64> {
    let out: Value = serde_json::from_str(&ok(&["eval", "--algebra", "cga", "--scalar", "f64", "--json", e])).unwrap();
    out.as_object().unwrap().iter().map(|(k, v)| (k.clone(), v.as_str().unwrap().parse().unwrap())).collect()
}

fn close(a: &std::collections::BTreeMap<String, f64>, b: &std::collections::BTreeMap<String, f64>, tol: f64) -> bool {
    a.keys().chain(b.keys()).all(|k| (a.get(k).unwrap_or(&0.0) - b.get(k).unwrap_or(&0.0)).abs() <= tol)
}

#[test]
fn cga_rotor_moves_conformal_points_like_the_matrix() {
    for (axis, angle, t) in POSES {
        let arg = format!(r#"{{"position": {t:?}, "axis": {axis:?}, "angle": {angle:e}}}"#);
        let out: Value = serde_json::from_str(&ok(&["pose", "--json", &arg])).unwrap();
        let r = expr(&out["cga_rotor"]);
        let scale = 1.0 + t.iter().map(|c| c * c).sum::<f64>();
        // unit: R rev(R) = 1
        let unit = eval(&format!("{r} * rev({r})"));
        assert!(close(&unit, &[("1".to_string(), 1.0)].into(), 1e-13 * scale), "{arg}: R rev(R) = {unit:?}");
        let m = rodrigues(axis, angle, t);
        for x in X {
            let y: [f64; 3] = std::array::from_fn(|i| (0..3).map(|j| m[i][j] * x[j]).sum::<f64>() + m[i][3]);
            let got = eval(&format!("{r} * {} * rev({r})", embed(x)));
            let want = eval(&embed(y));
            assert!(close(&got, &want, 1e-12 * scale * scale), "{arg}, x = {x:?}: {got:?} vs {want:?}");
        }
        // the sign rule: scalar part >= 0; at 0 the first non-zero coefficient is positive
        let c = &out["cga_rotor"];
        let first: f64 = c.as_object().unwrap().values().next().unwrap().as_str().unwrap().parse().unwrap();
        assert!(first > 0.0, "{arg}: {c}");
    }
}

#[test]
fn human_output_has_the_cga_rotor_line() {
    let out = ok(&["pose", r#"{"position": [1, 0, 0]}"#]);
    let line = out.lines().find(|l| l.starts_with("cga_rotor: ")).expect(&out);
    // T_t = 1 - t n/2 with t = e1: 1 - e14/2 - e15/2
    assert_eq!(line, "cga_rotor: 1 - 0.5*e14 - 0.5*e15");
}
