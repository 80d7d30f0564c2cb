//! Wareham–Lasenby's Figs. 5 and 7 (`motion::wareham_lasenby`):
//!
//! | file | paper | motion |
//! |---|---|---|
//! | `wl_fig5.svg` | Fig. 5 | a) piecewise-linear ([`WlLinear`], Sec. 3.1) and b) quadratic ([`WlQuadratic`], Sec. 3.2) interpolation of the three poses [`FIG5_POSES`] at `t = 0, 1, 2`, overlaid |
//! | `wl_fig5a.svg`, `wl_fig5b.svg` | Fig. 5 a), b) | each on its own, as the paper's two panels |
//! | `wl_fig7.svg` | Fig. 7 | the screw path `R_λ = exp(λB)`, `0 ≤ λ ≤ 1`, of `B` with `ψ = 9π`, `t∥ = 4a + 6b`, `|t⊥| = 1` ([`fig7_generator`]), with the vectors `t⊥`, `t'∥` ([`fig7_t_par_prime`]) and `t∥` |
//!
//! The paper does not print its three "representative poses"; [`FIG5_POSES`] are ours.
//! `exp(λB)` turns by `λψ`, more than π, so it is not the linear interpolation of its end poses
//! (`ℓ` returns the generator of the smallest turn); it is drawn as the piecewise-linear
//! interpolation of `exp(kB/10)`, `k = 0..10`, whose steps `exp(B/10)` turn by `0.9π < π`, so
//! `ℓ(exp(B/10)) = B/10` and every piece is `exp(λB)` itself.

use super::{Figure, SAMPLES};
use crate::error::CliError;
use crate::plot::data::{Mark, Series, Shape, of_motion};
use crate::plot::draw::View;
use motion::Pose;
use motion::wareham_lasenby::{Generator, GeneratorParts, WlLinear, WlQuadratic, to_pose};
use std::f64::consts::PI;

/// The three key poses of Fig. 5 at `t = 0, 1, 2`: (position, rotation axis, angle).
pub(crate) const FIG5_POSES: [([f64; 3], [f64; 3], f64); 3] = [
    ([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 0.0),
    ([4.0, 3.0, 0.0], [0.0, 0.0, 1.0], 1.5),
    ([8.0, 0.0, 1.0], [1.0, 1.0, 1.0], 1.2),
];

/// The parts of Fig. 7's generator: `ψ = 9π` in the plane `P = a b` with `a = e1`, `b = e2`
/// (the library's `P = -axis e123` is `e1 e2` for the axis `-e3`), `t∥ = 4a + 6b`, `t⊥ = e3`.
pub(crate) fn fig7_parts() -> GeneratorParts<f64> {
    GeneratorParts { psi: 9.0 * PI, axis: [0.0, 0.0, -1.0], t_par: [4.0, 6.0, 0.0], t_perp: [0.0, 0.0, 1.0] }
}

/// Fig. 7's generator `B = (ψ/2) P + (t∥ + t⊥) n/2`.
pub(crate) fn fig7_generator() -> Result<Generator<f64>, CliError> {
    Generator::from_parts(&fig7_parts()).map_err(|e| CliError::math(format!("the W-L Fig. 7 generator: {e}")))
}

fn math<E: std::fmt::Display>(e: E) -> CliError {
    CliError::math(format!("a Wareham-Lasenby figure: {e}"))
}

/// The series of a W-L motion through key poses at `times`, its joins the inner times when
/// `joins` (the pieces of Fig. 7 are one smooth screw motion: no joins).
fn series<M: motion::MapScalar<f64, motion::algebra_core::Jet<motion::algebra_core::Jet<f64>>>>(
    label: &str,
    motion: &M,
    times: Vec<f64>,
    (frames, joins): (usize, bool),
) -> Result<Series, CliError> {
    let shape = Shape {
        label: label.into(),
        method: label.into(),
        segments: times.len() - 1,
        degree: 0,
        tableau: crate::budget::Tableau::Linear,
        joins: if joins { times[1..times.len() - 1].to_vec() } else { vec![] },
        key_times: times,
    };
    of_motion(shape, motion, vec![[0.0; 3]], SAMPLES, frames)
}

/// The in-plane translation `t'∥` of `exp(λB)` at `λ = 1` by the paper's formula (Sec. 4.1):
/// `t'∥ = -(2s/ψ) [a (tᵃ c + tᵇ s) + b (tᵇ c - tᵃ s)]`, `c, s = cos, sin(ψ/2)`, with `a = e1`,
/// `b = e2` (the plane of Fig. 7's `P`).
pub(crate) fn fig7_t_par_prime() -> [f64; 3] {
    let p = fig7_parts();
    let (c, s) = ((p.psi / 2.0).cos(), (p.psi / 2.0).sin());
    let (ta, tb) = (p.t_par[0], p.t_par[1]);
    let k = -2.0 * s / p.psi;
    [k * (ta * c + tb * s), k * (tb * c - ta * s), 0.0]
}

/// Fig. 7's vectors: `-t⊥` from the origin (`exp(B)` translates by `-t⊥`: the paper's prose
/// says `+t⊥`, docs/verification.md), then `t'∥` from its tip (so it ends where the path ends:
/// "translate along -t⊥, rotate by ψ, translate along t'∥"), and `t∥` from the origin, drawn at
/// an eighth of its length (it is 14 times as long as `t'∥`).
fn fig7_arrows() -> Vec<Mark> {
    let p = fig7_parts();
    let tp = fig7_t_par_prime();
    let down = p.t_perp.map(|x| -x);
    let end: [f64; 3] = std::array::from_fn(|i| down[i] + tp[i]);
    let arrow = |from: [f64; 3], to: [f64; 3], label: &str| Mark {
        t: 1.0,
        kind: "arrow",
        points: vec![from, to],
        label: Some(label.to_string()),
    };
    vec![arrow([0.0; 3], down, "-t⊥"), arrow(down, end, "t'∥"), arrow([0.0; 3], p.t_par.map(|x| x / 8.0), "t∥ / 8")]
}

/// W-L Figs. 5 and 7.
pub(super) fn figures() -> Result<Vec<Figure>, CliError> {
    let poses = FIG5_POSES
        .iter()
        .map(|(p, a, phi)| Pose::from_axis_angle_translation(a, phi, p).map_err(math))
        .collect::<Result<Vec<_>, _>>()?;
    let times = vec![0.0, 1.0, 2.0];
    let linear = WlLinear::new(&poses, &times).map_err(math)?;
    let quadratic = WlQuadratic::new(&poses, &times).map_err(math)?;
    let fig5 = vec![
        series("a) piecewise linear", &linear, times.clone(), (5, true))?,
        series("b) quadratic", &quadratic, times, (5, true))?,
    ];
    // the paper's two panels, each on its own (the overlay above compares them)
    let (fig5a, fig5b) = (vec![fig5[0].clone()], vec![fig5[1].clone()]);
    let b = fig7_generator()?;
    let keys = (0..=10).map(|k| b.scale(&(f64::from(k) / 10.0)).exp().map(|r| to_pose(&r)));
    let keys = keys.collect::<Result<Vec<_>, _>>().map_err(math)?;
    let lambdas: Vec<f64> = (0..=10).map(|k| f64::from(k) / 10.0).collect();
    let screw = WlLinear::new(&keys, &lambdas).map_err(math)?;
    let mut fig7 = vec![series("exp(λB)", &screw, lambdas, (11, false))?];
    fig7[0].marks = fig7_arrows();
    Ok(vec![
        (
            "wl_fig5.svg",
            "Wareham–Lasenby Fig. 5: a) piecewise-linear and b) quadratic interpolation of three poses".into(),
            View::Xy,
            fig5,
        ),
        (
            "wl_fig5a.svg",
            "Wareham–Lasenby Fig. 5a: piecewise-linear interpolation of three poses".into(),
            View::Xy,
            fig5a,
        ),
        ("wl_fig5b.svg", "Wareham–Lasenby Fig. 5b: quadratic interpolation of three poses".into(), View::Xy, fig5b),
        (
            "wl_fig7.svg",
            "Wareham–Lasenby Fig. 7: the screw path of exp(λB), t∥ = 4a + 6b, ψ = 9π, |t⊥| = 1".into(),
            View::ThreeD,
            fig7,
        ),
    ])
}
