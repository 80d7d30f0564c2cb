//! The NaN / infinity policy beyond `Pose` (docs/robustness.md): every constructor and sampler
//! that takes floats refuses a NaN or infinite value with a typed `NotFinite`-style error,
//! instead of building a motion that later yields NaN poses.

use gam_algebras::DualQuaternion;
use motion::joins::JoinError;
use motion::juttler::{JuttlerError, QMotion, RationalBezier};
use motion::repr::hexanion::Hexanion;
use motion::repr::hexanion::blend::HexanionLinear;
use motion::trajectory::{Trajectory, TrajectoryError, Velocities};
use motion::wareham_lasenby::{WlBivectorLinear, WlError, WlLinear, WlQuadratic};
use motion::{
    Additive, AdditiveBSpline, AdditiveBezier, CurveError, EndCondition, HermiteSegment, HermiteShapes, MotionError,
    Multiplicative, MultiplicativeBSpline, MultiplicativeBezier, Pose, Pseudoscalar, SegmentKind, Shape,
};

const BAD: [f64; 3] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];

/// The pose with coefficient `k` (of the eight) replaced by `bad`.
fn poisoned(k: usize, bad: f64) -> Pose<f64> {
    let mut c = Pose::<f64>::translation(&[1.0, 2.0, 3.0]).to_array();
    c[k] = bad;
    Pose::from_array(c)
}

fn is_not_finite(e: &MotionError) -> bool {
    matches!(e, MotionError::NotFinite { .. })
}

#[test]
fn bezier_and_bspline_constructors_refuse_non_finite_control_poses() {
    for bad in BAD {
        for k in 0..8 {
            let poses = vec![Pose::identity(), poisoned(k, bad), Pose::identity()];
            let curve = |r: Result<_, CurveError>| matches!(r.err(), Some(CurveError::Pose(e)) if is_not_finite(&e));
            assert!(curve(AdditiveBezier::new(poses.clone()).map(|_| ())), "{bad} at {k}");
            assert!(curve(MultiplicativeBezier::new(poses.clone()).map(|_| ())));
            assert!(curve(AdditiveBSpline::clamped_uniform(2, poses.clone()).map(|_| ())));
            assert!(curve(MultiplicativeBSpline::new(1, vec![0.0, 0.0, 0.5, 1.0, 1.0], poses).map(|_| ())));
        }
    }
    // finite control poses still build
    assert!(AdditiveBezier::new(vec![Pose::<f64>::identity(), poisoned(4, 1e300)]).is_ok());
}

fn end(position: [f64; 3], velocity: [f64; 3], angular: [f64; 3]) -> EndCondition<f64> {
    EndCondition::new(Pose::translation(&position), position, velocity, angular)
}

fn segment(
    a: &EndCondition<f64>,
    b: &EndCondition<f64>,
    shape: &Shape<f64>,
) -> Result<HermiteSegment<f64, Additive>, JoinError> {
    HermiteSegment::new(3, a, b, shape, &Shape::new(1.0, Pseudoscalar::new(1.0, 0.0)))
}

#[test]
fn hermite_segments_refuse_non_finite_end_conditions_and_shapes() {
    let good = end([0.0; 3], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
    let other = end([1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0; 3]);
    let unit = Shape::new(1.0, Pseudoscalar::new(1.0, 0.0));
    assert!(segment(&good, &other, &unit).is_ok());
    let refused = |r: Result<HermiteSegment<f64, Additive>, JoinError>| matches!(r.err(), Some(JoinError::Motion(e)) if is_not_finite(&e));
    for bad in BAD {
        for i in 0..3 {
            let mut v = [1.0, 0.0, 0.0];
            v[i] = bad;
            assert!(refused(segment(&end([0.0; 3], v, [0.0; 3]), &other, &unit)), "velocity {bad}");
            assert!(refused(segment(&good, &end([0.0; 3], [0.0; 3], v), &unit)), "angular velocity {bad}");
            let mut c = good.clone();
            c.position[i] = bad;
            assert!(refused(segment(&c, &other, &unit)), "position {bad}");
        }
        let mut c = good.clone();
        c.pose = poisoned(0, bad);
        assert!(refused(segment(&good, &c, &unit)), "pose {bad}");
        for shape in [
            Shape::new(bad, Pseudoscalar::new(1.0, 0.0)),
            Shape::new(1.0, Pseudoscalar::new(bad, 0.0)),
            Shape::new(1.0, Pseudoscalar::new(1.0, bad)),
        ] {
            assert!(refused(segment(&good, &other, &shape)), "shape {bad}");
        }
        let multiplicative = HermiteSegment::<f64, Multiplicative>::new(
            4,
            &good,
            &other,
            &Shape::new(bad, Pseudoscalar::new(1.0, 0.0)),
            &unit,
        );
        assert!(matches!(multiplicative.err(), Some(JoinError::Motion(e)) if is_not_finite(&e)));
    }
}

#[test]
fn trajectories_and_samplers_refuse_non_finite_input() {
    let keys = [Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])];
    let shapes = HermiteShapes::unit();
    for bad in BAD {
        let poses = [Pose::identity(), poisoned(5, bad)];
        let r = Trajectory::through(&poses, &[0.0, 1.0], &Velocities::Zero, SegmentKind::Additive, &shapes);
        assert!(r.is_err(), "key pose {bad}");
        let r = Trajectory::through(&keys, &[0.0, bad], &Velocities::Zero, SegmentKind::Multiplicative, &shapes);
        assert!(r.is_err(), "time {bad}");
        let tr =
            Trajectory::through(&keys, &[0.0, 1.0], &Velocities::CatmullRom, SegmentKind::Additive, &shapes).unwrap();
        assert!(tr.sample(&bad, &[]).is_err(), "t = {bad}");
        let point = tr.sample(&0.5, &[[bad, 0.0, 0.0]]);
        assert!(matches!(point, Err(TrajectoryError::Motion(ref e)) if is_not_finite(e)), "{point:?}");
        assert!(tr.sample_at_rate(bad, &[]).is_err(), "rate {bad}");
    }
}

#[test]
fn wareham_lasenby_and_hexanion_motions_refuse_non_finite_keys() {
    let times = [0.0, 1.0, 2.0];
    for bad in BAD {
        let poses = [Pose::<f64>::identity(), poisoned(2, bad), Pose::translation(&[0.0, 1.0, 0.0])];
        let wl = |e: WlError| matches!(e, WlError::Curve(CurveError::Pose(ref m)) | WlError::Pose(ref m) if is_not_finite(m));
        assert!(wl(WlLinear::new(&poses, &times).unwrap_err()), "{bad}");
        assert!(wl(WlBivectorLinear::new(&poses, &times).unwrap_err()), "{bad}");
        assert!(wl(WlQuadratic::new(&poses, &times).unwrap_err()), "{bad}");
        assert!(HexanionLinear::through(&poses, &times).is_err(), "{bad}");
        assert!(matches!(Hexanion::from_pose(&poisoned(0, bad)), Err(e) if is_not_finite(&e)));
        assert!(matches!(Hexanion::new([bad, 0.0, 0.0], [0.0; 3]).to_pose(), Err(e) if is_not_finite(&e)));
        let mut m = Pose::<f64>::identity().to_matrix().unwrap();
        m[0][3] = bad;
        assert!(Hexanion::from_matrix(&m, &1e-12).is_err());
    }
}

#[test]
fn juttler_constructors_refuse_non_finite_control_points() {
    let refused = |e: JuttlerError| matches!(e, JuttlerError::Motion(ref m) if is_not_finite(m));
    for bad in BAD {
        for k in 0..8 {
            let mut c = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
            c[k] = bad;
            let control = vec![DualQuaternion::<f64>::one(), DualQuaternion::from_coeffs(c)];
            assert!(refused(QMotion::new(control.clone(), 1e-12).unwrap_err()), "{bad} at {k}");
            assert!(refused(QMotion::new(control, 0.0).unwrap_err()));
        }
        for k in 0..4 {
            let mut p = [1.0, 2.0, 3.0, 4.0];
            p[k] = bad;
            assert!(refused(RationalBezier::new(vec![[1.0, 0.0, 0.0, 0.0], p]).unwrap_err()));
        }
    }
}
