//! Sec. 5.3 of the main paper: Hermite interpolation of the motion of Jaklič et al. through
//! the nine precision poses at `t = 1, 2, ..., 9`, with eight cubic segments.
//!
//! The data (precision poses, end conditions) are `motion::paper::jaklic`. The motion: the reference point of the body follows
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

use motion::joins;
use motion::paper::jaklic::segments;
use motion::{Bivector, Pose, SegmentKind};

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
    let segs = match segments(kind, lambda) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(1);
        }
    };
    println!("Jaklič et al. motion, t = 1..9: {} {kind} cubic segments, common shape factor λ = {lambda}", segs.len());
    for (k, seg) in segs.iter().enumerate() {
        println!("\nsegment {} (t = {} .. {})", k + 1, k + 1, k + 2);
        for (i, s) in seg.control_poses().iter().enumerate() {
            println!("  S{i} = {}", format_pose(s));
        }
    }
    println!();
    for (k, pair) in segs.windows(2).enumerate() {
        let check = joins::check_segment_join(
            (pair[0].kind(), pair[0].control_poses()),
            (pair[1].kind(), pair[1].control_poses()),
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
