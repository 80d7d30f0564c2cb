//! The robotics scenario: five key poses from nalgebra `Isometry3`, at t = 0, 1, 2.5, 3.5, 5 s,
//! one C1 motion through all of them in one call (velocities estimated, at rest at the ends),
//! sampled at 1 kHz with the space and body twists and the tool point's kinematics.
//!
//! Run: `cargo run -p motion --features nalgebra --example robot [-- additive|multiplicative]`.

use motion::trajectory::{Trajectory, Velocities};
use motion::{HermiteShapes, Pose, SegmentKind};
use nalgebra::{Isometry3, Vector3};

fn main() {
    let kind = match std::env::args().nth(1).as_deref() {
        None | Some("multiplicative") => SegmentKind::Multiplicative,
        Some("additive") => SegmentKind::Additive,
        Some(other) => {
            eprintln!("error: unknown kind `{other}` (expected additive or multiplicative)");
            std::process::exit(2);
        }
    };
    let keys = [
        ([0.5, 0.0, 0.4], [0.0, 0.0, 0.0]),
        ([0.6, 0.2, 0.5], [0.0, 0.3, 0.4]),
        ([0.4, 0.5, 0.6], [0.2, 0.5, 1.2]),
        ([0.1, 0.6, 0.4], [-0.3, 0.2, 2.0]),
        ([-0.2, 0.4, 0.3], [0.0, 0.0, 2.8]),
    ];
    let poses: Vec<Pose<f64>> = keys
        .iter()
        .map(|(t, r)| Pose::from_na_isometry(&Isometry3::new(Vector3::from(*t), Vector3::from(*r))))
        .collect();
    let times = [0.0, 1.0, 2.5, 3.5, 5.0];
    let tool = [0.1, -0.05, 0.3];
    let run = || -> Result<(), motion::trajectory::TrajectoryError> {
        let tr = Trajectory::through(&poses, &times, &Velocities::CatmullRom, kind, &HermiteShapes::unit())?;
        for j in tr.joins() {
            println!("join at t = {}: C1 = {} (jump in nu {:.1e})", j.time, j.is_c1(1e-12), j.nu_jump);
        }
        let samples = tr.sample_at_rate(1000.0, &[tool])?;
        println!("{} {kind} samples at 1 kHz; every 500th:", samples.len());
        println!("{:>5} {:>28} {:>28} {:>28}", "t", "tool position", "space angular velocity", "body linear velocity");
        let f = |v: &[f64; 3]| format!("[{:8.4}, {:8.4}, {:8.4}]", v[0], v[1], v[2]);
        for s in samples.iter().step_by(500) {
            println!(
                "{:5.2} {} {} {}",
                s.t,
                f(&s.points[0].position),
                f(&s.space_twist.angular.to_array()),
                f(&s.body_twist.linear.to_array())
            );
        }
        Ok(())
    };
    if let Err(e) = run() {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}
