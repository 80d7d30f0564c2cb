//! Overflow-safe geometry: no finite non-zero input is turned into zero or infinity by an
//! intermediate square (axes, norms, unitize, log), checked against the same computation on
//! a moderately scaled input (an exact power-of-ten rescaling of the same geometry).

use crate::common;

use motion::{MotionError, Pose};

fn max_diff(a: &Pose<f64>, b: &Pose<f64>) -> f64 {
    a.components().iter().zip(b.components()).map(|(x, y)| (*x - *y).abs()).fold(0.0, f64::max)
}

#[test]
fn huge_and_tiny_axes_rotate() {
    let want = Pose::rotation(&[1.0, 1.0, 0.0], &1.0).unwrap();
    for s in [1e200, 1e-200, 1e308, 1e-310, f64::MAX, 5e-324] {
        let got = Pose::rotation(&[s, s, 0.0], &1.0).unwrap_or_else(|e| panic!("{s:e}: {e}"));
        assert!(max_diff(&got, &want) < 1e-15, "scale {s:e}: {got} vs {want}");
    }
    assert_eq!(Pose::rotation(&[0.0, 0.0, 0.0], &1.0).unwrap_err(), MotionError::ZeroAxis);
    assert!(matches!(Pose::rotation(&[f64::INFINITY, 0.0, 0.0], &1.0), Err(MotionError::NotFinite { .. })));
}

#[test]
fn random_axis_scales_give_the_same_rotation() {
    let mut rng = common::Xorshift(0x2545f4914f6cdd1d);
    let mut next = || common::centered(&mut rng);
    for _ in 0..500 {
        let axis = [next(), next(), next()];
        let angle = 6.0 * next();
        let want = Pose::rotation(&axis, &angle).unwrap();
        let e = (600.0 * next()).round() as i32;
        let s = 10f64.powi(e);
        let scaled = axis.map(|x| x * s);
        if scaled.iter().any(|x| !x.is_finite()) || scaled.iter().all(|x| *x == 0.0) {
            continue;
        }
        let got = Pose::rotation(&scaled, &angle).unwrap();
        assert!(max_diff(&got, &want) < 1e-14, "axis {axis:?} x 1e{e}: {got} vs {want}");
    }
}

#[test]
fn norm_unitize_and_log_of_huge_and_tiny_poses() {
    let s = Pose::from_axis_angle_translation(&[1.0, 2.0, 3.0], &0.7, &[4.0, 5.0, 6.0]).unwrap().scale(&2.0);
    let (n, u, l) = (s.norm().unwrap(), s.unitize().unwrap(), s.log().unwrap());
    for k in [1e200f64, 1e-200, 1e300, 1e-300] {
        let big = s.scale(&k);
        let nb = big.norm().unwrap_or_else(|e| panic!("{k:e}: {e}"));
        assert!((nb.scalar / k - n.scalar).abs() < 1e-14 && (nb.e123inf / k - n.e123inf).abs() < 1e-14, "{k:e}");
        assert!(max_diff(&big.unitize().unwrap(), &u) < 1e-14, "{k:e}");
        let lb = big.log().unwrap();
        assert!((lb.scalar - k.ln() - l.scalar).abs() < 1e-12, "{k:e}: {} vs {}", lb.scalar, l.scalar);
        assert!((lb.e12 - l.e12).abs() < 1e-14 && (lb.e1inf - l.e1inf).abs() < 1e-14, "{k:e}");
    }
    // a translation of 1e200 is a pose with a direction: log keeps it
    let t = Pose::translation(&[2e200, 0.0, 0.0]);
    assert_eq!(t.log().unwrap().e1inf, 1e200);
    assert_eq!(t.unitize().unwrap(), t);
}

#[test]
fn non_finite_poses_are_not_finite_errors() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let s = Pose::translation(&[bad, 0.0, 0.0]);
        assert!(matches!(s.norm(), Err(MotionError::NotFinite { .. })), "norm {bad}");
        assert!(matches!(s.unitize(), Err(MotionError::NotFinite { .. })), "unitize {bad}");
        assert!(matches!(s.log(), Err(MotionError::NotFinite { .. })), "log {bad}");
        assert!(matches!(s.power(&0.5), Err(MotionError::NotFinite { .. })), "power {bad}");
        assert!(matches!(Pose::slerp(&Pose::identity(), &s, &0.5), Err(MotionError::NotFinite { .. })), "slerp {bad}");
        assert!(matches!(s.transform_point(&[1.0, 0.0, 0.0]), Err(MotionError::NotFinite { .. })), "point {bad}");
        assert!(matches!(s.to_matrix(), Err(MotionError::NotFinite { .. })), "matrix {bad}");
        assert!(matches!(s.try_inverse(), Err(MotionError::NotFinite { .. })), "inverse {bad}");
        let r = Pose::rotation(&[0.0, 0.0, 1.0], &1.0).unwrap();
        assert!(matches!(r.transform_point(&[bad, 0.0, 0.0]), Err(MotionError::NotFinite { .. })), "point arg {bad}");
        assert!(matches!(r.transform_direction(&[bad, 0.0, 0.0]), Err(MotionError::NotFinite { .. })), "dir {bad}");
        assert!(matches!(r.power(&bad), Err(MotionError::NotFinite { .. })), "power t {bad}");
        assert!(matches!(Pose::slerp(&r, &r, &bad), Err(MotionError::NotFinite { .. })), "slerp t {bad}");
    }
}

#[test]
fn out_of_range_degrees_are_typed_errors() {
    use motion::joins::JoinError;
    use motion::{AdditiveBSpline, CurveError, EndCondition, MultiplicativeBSpline, Pseudoscalar, SegmentKind, Shape};
    let poses = vec![Pose::<f64>::identity(); 3];
    for degree in [3, 1 << 40, usize::MAX] {
        assert!(matches!(
            AdditiveBSpline::clamped_uniform(degree, poses.clone()),
            Err(CurveError::TooFewPoses { got: 3, .. })
        ));
        assert!(matches!(
            MultiplicativeBSpline::new(degree, vec![0.0; 8], poses.clone()),
            Err(CurveError::TooFewPoses { got: 3, .. })
        ));
    }
    let a =
        EndCondition::from_axis_angle(&[0.0, 0.0, 0.0], &[1.0, 0.0, 0.0], &0.0, &[1.0, 0.0, 0.0], &[0.0; 3]).unwrap();
    let b =
        EndCondition::from_axis_angle(&[1.0, 0.0, 0.0], &[1.0, 0.0, 0.0], &0.0, &[1.0, 0.0, 0.0], &[0.0; 3]).unwrap();
    let sh = Shape::new(1.0, Pseudoscalar::new(1.0, 0.0));
    for degree in [10_001, 1 << 40, usize::MAX] {
        let e = motion::hermite::hermite_segment(SegmentKind::Multiplicative, degree, &a, &b, &sh, &sh).unwrap_err();
        assert_eq!(e, JoinError::DegreeTooLarge { degree, max: 10_000 });
    }
    assert!(motion::hermite::hermite_segment(SegmentKind::Additive, 10_000, &a, &b, &sh, &sh).is_ok());
}
