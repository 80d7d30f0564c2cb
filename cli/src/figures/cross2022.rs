//! The main paper's Figs. 6-10 (Sec. 5, Cross, Cripps and Mullineux 2022) from the paper
//! module's data, drawn with the L-shaped block
//! ([`Body::LBlock`](crate::plot::draw::Body::LBlock)) at the frame parameters:
//!
//! | file | paper | motion |
//! |---|---|---|
//! | `fig6.svg` | Fig. 6 | the multiplicative cubic of Sec. 5.1 (`motion::paper::sec_5_1`) |
//! | `fig7.svg` | Fig. 7 | the additive cubic of the same end conditions |
//! | `fig8.svg` | Fig. 8 | the multiplicative cubic of Sec. 5.2 (`sec_5_2`) for shape factors `λ0, λ3 ∈ {1, 4}` |
//! | `fig9.svg` | Fig. 9 | the additive cubic of Sec. 5.2, the same shape factors |
//! | `fig10.svg` | Fig. 10 | the additive Hermite motion through the nine Jaklič poses (`jaklic`), common `λ = 1, 0.5, 1.5` |
//!
//! The body point is the body origin (the corner of the L), the reference point of the
//! papers' end conditions. Every block's L faces are shaded (the paper's Fig. 10 "shaded
//! blocks"); Fig. 8 also has the paper's dashed arcs, the paths of the middle control poses
//! as the shape factors vary ([`control_arcs`]).

use super::{Figure, SAMPLES};
use crate::budget::Tableau;
use crate::error::CliError;
use crate::plot::data::{Mark, Series, Shape, evenly, of_motion};
use crate::plot::draw::View;
use motion::paper::{jaklic, sec_5_1, sec_5_2};
use motion::spec::{HermiteSpec, SpecKind};
use motion::{Piecewise, SegmentKind};

/// The files drawn with the L-shaped block.
pub(super) const L_BLOCK_FILES: [&str; 5] = ["fig6.svg", "fig7.svg", "fig8.svg", "fig9.svg", "fig10.svg"];

/// The shape factors `(λ0, λ3)` overlaid in Figs. 8 and 9.
pub(crate) const SHAPES: [(f64, f64); 4] = [(1.0, 1.0), (4.0, 1.0), (1.0, 4.0), (4.0, 4.0)];

/// The common shape factors overlaid in Fig. 10 (the first carries the blocks).
pub(crate) const COMMON: [f64; 3] = [1.0, 0.5, 1.5];

fn math<E: std::fmt::Display>(what: &str) -> impl Fn(E) -> CliError + '_ {
    move |e| CliError::math(format!("{what}: {e}"))
}

/// One Hermite segment over `[0, 1]` from `spec`, with `frames` blocks.
fn segment(label: String, spec: &HermiteSpec, frames: usize) -> Result<Series, CliError> {
    let seg = spec.segment().map_err(math("the Sec. 5 segment"))?;
    let method = seg.kind().to_string();
    let tableau = Tableau::of_segment(seg.kind());
    let motion = seg.into_motion().map_err(math("the Sec. 5 segment"))?;
    let shape = Shape { label, method, segments: 1, degree: 3, tableau, key_times: vec![0.0, 1.0], joins: vec![] };
    of_motion(shape, &motion, vec![[0.0; 3]], SAMPLES, frames)
}

/// The Jaklič motion through the nine precision poses (`t = 1..9`), additive, common shape
/// factor `lambda`, with a block at each precision pose when `blocks`.
fn jaklic_motion(lambda: f64, blocks: bool) -> Result<Series, CliError> {
    jaklic_frames(lambda, if blocks { 9 } else { 0 })
}

/// What the companion of Fig. 10 measures its motions against.
pub(crate) const EXACT: &str = "the motion of Jaklic et al.";

/// The companion of Fig. 10 (not in the paper): for each common shape factor, the distance
/// of the body point (the reference point) from the exact path `c(t)` and the rotation angle
/// between the Hermite motion's orientation and the exact `q(t)`, at every sample; and the
/// exact motion itself (zero error), so the path panel compares the paths.
pub(crate) fn fig10_error() -> Result<(Vec<Series>, String), CliError> {
    let mut out = Vec::new();
    for lambda in COMMON {
        let mut s = jaklic_frames(lambda, SAMPLES)?;
        let (mut dist, mut angle) = (Vec::with_capacity(SAMPLES), Vec::with_capacity(SAMPLES));
        for f in &s.frames {
            let exact = jaklic::pose(&f.t).map_err(math("the exact Jaklic motion"))?;
            let at = |p: [f64; 3]| exact.transform_point(&p).map_err(math("the exact Jaklic motion"));
            let o = at([0.0; 3])?;
            dist.push((0..3).map(|i| (f.origin[i] - o[i]).powi(2)).sum::<f64>().sqrt());
            // |R_h - R_e|_F = 2√2 sin(θ/2) for the rotation angle θ between them
            let mut frob = 0.0;
            for (k, e) in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]].into_iter().enumerate() {
                let ek = at(e)?;
                frob += (0..3).map(|i| ((f.axes[k][i] - f.origin[i]) - (ek[i] - o[i])).powi(2)).sum::<f64>();
            }
            angle.push(2.0 * (frob.sqrt() / (2.0 * std::f64::consts::SQRT_2)).min(1.0).asin());
        }
        (s.speeds, s.angular_speed) = (vec![dist], angle);
        s.frames.clear();
        out.push(s);
    }
    let mut exact = out[0].clone();
    exact.label = EXACT.to_string();
    exact.method = "exact".into();
    exact.paths = vec![exact.t.iter().map(jaklic::path).collect()];
    exact.speeds = vec![vec![0.0; exact.t.len()]];
    exact.angular_speed = vec![0.0; exact.t.len()];
    out.push(exact);
    let title = "Fig. 10 (companion): the Hermite motions against the exact motion of Jaklič et al.".to_string();
    Ok((out, title))
}

/// [`jaklic_motion`] with `frames` evenly spaced body frames.
fn jaklic_frames(lambda: f64, frames: usize) -> Result<Series, CliError> {
    let segs = jaklic::segments(SegmentKind::Additive, lambda).map_err(math("the Jaklic motion"))?;
    let segs = segs.into_iter().map(|s| s.into_motion()).collect::<Result<Vec<_>, _>>();
    let segs = segs.map_err(math("the Jaklic motion"))?;
    let times: Vec<f64> = (1..=9).map(f64::from).collect();
    let motion = Piecewise::new(times.clone(), segs).map_err(math("the Jaklic motion"))?;
    let shape = Shape {
        label: format!("λ = {lambda}"),
        method: "additive".into(),
        segments: 8,
        degree: 3,
        tableau: Tableau::Linear,
        joins: times[1..8].to_vec(),
        key_times: times,
    };
    of_motion(shape, &motion, vec![[0.0; 3]], SAMPLES, frames)
}

/// The shape factors along Fig. 8's dashed arcs: 61 values from 1 to 4.
pub(crate) const ARC_POINTS: usize = 61;

/// Fig. 8's dashed arcs: the paths of the body origin under the middle control poses `S_1`
/// as `λ0` runs over `[1, 4]` (`λ3 = 1`; `t = 0`) and `S_2` as `λ3` does (`λ0 = 1`; `t = 1`).
/// Fig. 8 is the multiplicative segment: its middle control poses are
/// `S_1 = exp(λ0 (ν0 + γ0)/6)` (and the like for `S_2`), whose pseudoscalar factor moves no
/// point and whose `exp(μ ν0)` lies in the pencil of `1 + ν0`, so these paths are exact
/// circular arcs. (The paper's Sec. 5.2 says "additive Bézier motion of degree 1": for the
/// additive poses of (22) the paths are ellipses leaving the plane; statement
/// `cross2022/sec-5.2-darboux`, docs/verification.md.)
pub(crate) fn control_arcs(kind: SpecKind) -> Result<Vec<Mark>, CliError> {
    let at = |l0: f64, l3: f64, i: usize| {
        let seg = sec_5_2::spec(kind, l0, l3).segment().map_err(math("the Sec. 5.2 segment"))?;
        seg.control_poses()[i].transform_point(&[0.0; 3]).map_err(math("a Sec. 5.2 control pose"))
    };
    let lambdas = evenly(1.0, 4.0, ARC_POINTS);
    let s1 = lambdas.iter().map(|l| at(*l, 1.0, 1)).collect::<Result<_, _>>()?;
    let s2 = lambdas.iter().map(|l| at(1.0, *l, 2)).collect::<Result<_, _>>()?;
    Ok(vec![
        Mark { t: 0.0, kind: "arc", points: s1, label: None },
        Mark { t: 1.0, kind: "arc", points: s2, label: None },
    ])
}

/// Figs. 8 and 9: the Sec. 5.2 segment of `kind` for every `(λ0, λ3)` of [`SHAPES`], the
/// blocks at the ends (common to all) on the first only, with the dashed arcs of the middle
/// control poses when `arcs` (Fig. 8).
fn shapes(kind: SpecKind, arcs: bool) -> Result<Vec<Series>, CliError> {
    let one = |(i, (l0, l3)): (usize, &(f64, f64))| {
        let label = format!("λ₀ = {l0}, λ₃ = {l3}");
        segment(label, &sec_5_2::spec(kind, *l0, *l3), if i == 0 { 2 } else { 0 })
    };
    let mut all: Vec<Series> = SHAPES.iter().enumerate().map(one).collect::<Result<_, _>>()?;
    if arcs {
        all[0].marks = control_arcs(kind)?;
    }
    Ok(all)
}

/// The figures of Sec. 5.
pub(super) fn figures() -> Result<Vec<Figure>, CliError> {
    let sec51 = |kind| segment(SegmentKind::from(kind).to_string(), &sec_5_1::spec(kind, sec_5_1::PRINTED_ANGLE), 6);
    let fig10 = COMMON.iter().enumerate().map(|(i, l)| jaklic_motion(*l, i == 0)).collect::<Result<_, _>>()?;
    Ok(vec![
        (
            "fig6.svg",
            "Fig. 6: multiplicative cubic motion (Sec. 5.1)".into(),
            View::ThreeD,
            vec![sec51(SpecKind::Multiplicative)?],
        ),
        ("fig7.svg", "Fig. 7: additive cubic motion (Sec. 5.1)".into(), View::ThreeD, vec![sec51(SpecKind::Additive)?]),
        (
            "fig8.svg",
            "Fig. 8: multiplicative cubic motion varying shape factors (y-z plane)".into(),
            View::Yz,
            shapes(SpecKind::Multiplicative, true)?,
        ),
        (
            "fig9.svg",
            "Fig. 9: additive cubic motion varying shape factors (y-z plane)".into(),
            View::Yz,
            shapes(SpecKind::Additive, false)?,
        ),
        (
            "fig10.svg",
            "Fig. 10: additive Hermite interpolation through nine precision poses, common shape factors".into(),
            View::ThreeD,
            fig10,
        ),
    ])
}
