//! The scalar helpers of the closed forms, written once as statements and printed by each
//! [`Dialect`]: the factors of `algebra_core::closed_form::{exp_factors, log_factors}` with the
//! same series below `θ = 10^-3` and the same constants (libm's `atan2` in place of the Rust
//! crate's polynomial `fast_atan2`).

use super::ir::Helper;
use super::{Dialect, Scalar, decimal};

enum Stmt {
    Let(&'static str, String),
    If(String, Vec<Stmt>, Vec<Stmt>),
    Return([String; 3]),
}

fn print(d: &dyn Dialect, s: Scalar, module: &str, body: &[Stmt], indent: usize, out: &mut String) {
    let pad = "    ".repeat(indent);
    for st in body {
        match st {
            Stmt::Let(name, v) => out.push_str(&format!("{pad}{}\n", d.local(d.scalar(s), name, v))),
            Stmt::If(cond, then, otherwise) => {
                out.push_str(&format!("{pad}if ({cond}) {{\n"));
                print(d, s, module, then, indent + 1, out);
                out.push_str(&format!("{pad}}} else {{\n"));
                print(d, s, module, otherwise, indent + 1, out);
                out.push_str(&format!("{pad}}}\n"));
            }
            Stmt::Return([a, b, c]) => {
                out.push_str(&format!("{pad}{}\n", d.return_triple(s, module, [a, b, c])));
            }
        }
    }
}

/// The source of one helper in `d`.
pub(super) fn text(d: &dyn Dialect, s: Scalar, module: &str, h: Helper) -> String {
    let k = |n: i64, den: i64| d.literal(s, &decimal(s, (n, den)));
    let f = |name: &str| d.math(s, name);
    let small = d.literal(s, &decimal(s, (1, 1000)));
    let (params, doc, body): (&[&str], &str, Vec<Stmt>) = match h {
        Helper::ExpFactors => (
            &["theta2"],
            "(sinc t, (cos t - sinc t) / t^2, cos t) from t^2 >= 0 (series below t = 1e-3).",
            vec![
                Stmt::Let("theta", format!("{}(theta2)", f("sqrt"))),
                Stmt::If(
                    format!("theta < {small}"),
                    vec![
                        Stmt::Let("t4", "theta2 * theta2".into()),
                        Stmt::Return([
                            format!("({one} - {} * theta2) + {} * t4", k(1, 6), k(1, 120), one = k(1, 1)),
                            format!("((-{}) + {} * theta2) - {} * t4", k(1, 3), k(1, 30), k(1, 840)),
                            format!("({one} - {} * theta2) + {} * t4", k(1, 2), k(1, 24), one = k(1, 1)),
                        ]),
                    ],
                    vec![
                        Stmt::Let("si", format!("{}(theta)", f("sin"))),
                        Stmt::Let("co", format!("{}(theta)", f("cos"))),
                        Stmt::Let("inv", format!("{} / theta", k(1, 1))),
                        Stmt::Let("sinc", "si * inv".into()),
                        Stmt::Return(["sinc".into(), "(co - sinc) * (inv * inv)".into(), "co".into()]),
                    ],
                ),
            ],
        ),
        Helper::LogFactors => (
            &["si", "co"],
            "(t / sin t, (t cos t - sin t) / sin^3 t, 0) from sin t >= 0 and cos t, t = atan2 (series below t = 1e-3).",
            vec![
                Stmt::Let("theta", format!("{}(si, co)", f("atan2"))),
                Stmt::If(
                    format!("theta < {small}"),
                    vec![
                        Stmt::Let("t2", "theta * theta".into()),
                        Stmt::Let("t4", "t2 * t2".into()),
                        Stmt::Return([
                            format!("({} + {} * t2) + {} * t4", k(1, 1), k(1, 6), k(7, 360)),
                            format!("((-{}) - {} * t2) - {} * t4", k(1, 3), k(2, 15), k(2, 63)),
                            k(0, 1),
                        ]),
                    ],
                    vec![
                        Stmt::Let("r", format!("{} / si", k(1, 1))),
                        Stmt::Let("r2", "r * r".into()),
                        Stmt::Return(["theta * r".into(), "(theta * co - si) * (r2 * r)".into(), k(0, 1)]),
                    ],
                ),
            ],
        ),
    };
    let mut out = d.comment(doc);
    let sfx = d.suffix(s);
    out.push_str(&d.helper_head(s, module, &format!("{module}_{}{sfx}", h.name()), params));
    out.push('\n');
    print(d, s, module, &body, 1, &mut out);
    out.push_str("}\n");
    out
}
