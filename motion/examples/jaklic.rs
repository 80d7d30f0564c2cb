//! Sec. 5.3 of the main paper: Hermite interpolation of the motion of Jaklič et al. through
//! the nine precision poses at `t = 1, 2, ..., 9`, with eight cubic segments.
//!
//! The motion: the reference point of the body follows
//! `c(t) = 3 ln(t+1) cos t e1 + 3 ln(t+1) sin t e2 + 3(t+1) e3`, and the body turns about it by
//! the (non-unit) quaternion, in the paper's geometric-algebra form,
//! `q(t) = t + [t + cos(πt/4)] e23 + [sin(πt/4)] e31 + [cos(πt/10)] e12`.
//! The precision pose is `S(t) = R(t) T(c(t))` with `R = q/|q|` (unitary, as eqs. 22-23
//! assume); the velocity of the reference point is `c'(t)` and the angular velocity `Ω(t)` is
//! read off `2 R⁻¹ R' = Ω e123` (Theorem 3.2 with the origin fixed), both derivatives by dual
//! numbers. The velocity indicatrix at each division is `Ψ = λ ν` (`γ = 0`), and each segment's
//! inner control poses come from eq. (22) (additive) or eq. (23) (multiplicative).
//!
//! Run: `cargo run -p motion --example jaklic [-- [additive|multiplicative] [LAMBDA]]`
//! (default: additive, λ = 1, the upper part of the paper's Fig. 10; the figure also shows the
//! common values 0.5 and 1.5). Prints the control poses of every segment and checks that each
//! join is C1 (zero jump in the velocity bivector, Corollary 4.6).

use motion::hermite::{self, HermiteSegment, HermiteShapes};
use motion::joins;
use motion::{Bivector, EndCondition, Even, Pose, SegmentKind, Shape};
use num_dual::{Dual64, DualNum};
use std::f64::consts::PI;

/// The reference-point path `c(t)` of Jaklič et al.
pub fn path(t: Dual64) -> [Dual64; 3] {
    let r = (t + 1.0).ln() * 3.0;
    [r * t.cos(), r * t.sin(), (t + 1.0) * 3.0]
}

/// The rotation quaternion `q(t)` as an element of G_{123inf}^+ (not unitary).
pub fn quaternion(t: Dual64) -> Pose<Dual64> {
    let z = Dual64::from(0.0);
    let e23 = t + (t * (PI / 4.0)).cos();
    let e31 = (t * (PI / 4.0)).sin();
    let e12 = (t * (PI / 10.0)).cos();
    Pose::new(t, e12, -e31, e23, z, z, z, z)
}

/// The value and the derivative parts of a pose over dual numbers.
fn split(s: &Pose<Dual64>) -> (Pose<f64>, Even<f64>) {
    let m = s;
    let parts = [&m.scalar, &m.e12, &m.e13, &m.e23, &m.e1inf, &m.e2inf, &m.e3inf, &m.e123inf];
    let mk = |c: [f64; 8]| Even::new(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]);
    ((mk(parts.map(|x| x.re))), mk(parts.map(|x| x.eps)))
}

/// The precision pose `S(t) = R(t) T(c(t))` over dual numbers (`t + ε` gives `S'(t)` too).
pub fn pose(t: Dual64) -> Pose<Dual64> {
    let rotor = quaternion(t).unitize().expect("q(t) is never zero for t > 0");
    &rotor * &Pose::translation(&path(t))
}

/// The end condition at parameter `t`: `S(t)`, the position `c(t)`, the velocity `c'(t)` and the
/// angular velocity `Ω(t)` from `2 R⁻¹ R' = Ω e123`.
pub fn end_condition(t: f64) -> EndCondition<f64> {
    let td = Dual64::new(t, 1.0);
    let (rotor, rotor_dot) = split(&quaternion(td).unitize().expect("q(t) is never zero for t > 0"));
    let w = (&rotor.try_inverse().expect("unit rotor") * &rotor_dot).scale(&2.0);
    let omega = [w.e23, -w.e13, w.e12];
    let c = path(td);
    EndCondition::new(split(&pose(td)).0, c.map(|x| x.re), c.map(|x| x.eps), omega)
}

/// The nine precision poses at `t = 1, ..., 9`.
pub fn precision_poses() -> Vec<EndCondition<f64>> {
    (1..=9).map(|t| end_condition(f64::from(t))).collect()
}

/// The eight cubic segments with a common shape factor `lambda` (`γ = 0`).
pub fn segments(kind: SegmentKind, lambda: f64) -> Vec<HermiteSegment<f64>> {
    hermite::hermite(kind, 3, &precision_poses(), &HermiteShapes::Common(Shape::factor(lambda)))
        .expect("the Jaklič precision poses are non-singular")
}

fn format_pose(s: &Pose<f64>) -> String {
    let names = ["", "e12", "e13", "e23", "e1inf", "e2inf", "e3inf", "ω"];
    let mut out = String::new();
    for (x, name) in s.components().into_iter().zip(names) {
        let text = format!("{:.4}", x.abs());
        let negative = *x < 0.0 && text != "0.0000";
        out.push_str(&match (out.is_empty(), negative) {
            (true, _) => format!("{}{text}{name}", if negative { "-" } else { "" }),
            (false, true) => format!(" - {text}{name}"),
            (false, false) => format!(" + {text}{name}"),
        });
    }
    out
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let kind = match args.first().map(String::as_str) {
        None | Some("additive") => SegmentKind::Additive,
        Some("multiplicative") => SegmentKind::Multiplicative,
        Some(other) => {
            eprintln!("error: unknown kind `{other}` (expected additive or multiplicative)");
            std::process::exit(2);
        }
    };
    let lambda = match args.get(1).map(|s| s.parse::<f64>()) {
        None => 1.0,
        Some(Ok(l)) if l > 0.0 && l.is_finite() => l,
        Some(_) => {
            eprintln!("error: the shape factor must be a positive number");
            std::process::exit(2);
        }
    };
    let segs = segments(kind, lambda);
    println!("Jaklič et al. motion, t = 1..9: {} {kind} cubic segments, common shape factor λ = {lambda}", segs.len());
    for (k, seg) in segs.iter().enumerate() {
        println!("\nsegment {} (t = {} .. {})", k + 1, k + 1, k + 2);
        for (i, s) in seg.control_poses.iter().enumerate() {
            println!("  S{i} = {}", format_pose(s));
        }
    }
    println!();
    for (k, pair) in segs.windows(2).enumerate() {
        let check = joins::check_segment_join(
            (pair[0].kind, &pair[0].control_poses),
            (pair[1].kind, &pair[1].control_poses),
            &1e-9,
        )
        .expect("non-singular control poses");
        let jump = check.nu_jump.components_max_abs();
        println!("join at t = {}: {:?}, largest |jump in ν| = {jump:.1e}", k + 2, check.continuity);
    }
}

/// The largest absolute component.
trait MaxAbs {
    fn components_max_abs(&self) -> f64;
}

impl MaxAbs for Bivector<f64> {
    fn components_max_abs(&self) -> f64 {
        [self.e12, self.e13, self.e23, self.e1inf, self.e2inf, self.e3inf].into_iter().fold(0.0, |m, x| m.max(x.abs()))
    }
}
