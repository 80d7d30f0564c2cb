//! Kinematic (sweeping) surfaces `y(t, v) = M(t) x(v)` (Jüttler Sec. 5, Fig. 5b) as rational
//! tensor-product Bézier surfaces: exactly equal over rationals to transforming the curve's
//! point by the motion's pose, for a Q-motion and an additive Bézier motion, with a curve
//! control point at infinity; the positions `t = const` are the moved curve.

use algebra_core::rational::{Q, q, ratio};
use gam_algebras::DualQuaternion;
use gam_algebras::dual_quaternion::Quaternion;
use motion::juttler::rotational::affine;
use motion::juttler::surface::RationalBezierSurface;
use motion::juttler::tr::{rotation_translation, tr_method};
use motion::juttler::{JuttlerError, QMotion, RationalBezier};
use motion::{AdditiveBezier, Motion, Pose};

/// The TR method (30)-(31) on the affine rotational interpolant (19)-(21) through three rational
/// poses: a Q-motion of degree 4, exact.
fn q_motion() -> QMotion<Q> {
    let poses: Vec<Pose<Q>> =
        [(1, 0, [0, 0, 1], [0, 0, 0]), (2, 1, [1, -1, 2], [3, -1, 1]), (3, -2, [0, 1, 1], [1, 4, 2])]
            .iter()
            .map(|(c, s, a, t)| Pose::rotor_from_parts(&q(*c), &q(*s), &a.map(q)) * Pose::translation(&t.map(q)))
            .collect();
    let params = [q(0), ratio(2, 5), q(1)];
    let rots: Vec<_> = poses.iter().map(|p| rotation_translation(p).unwrap().0).collect();
    tr_method(&affine(&rots, &params).unwrap(), &poses, &params).unwrap()
}

/// A parabola of the moving space (Fig. 5): `(v, v², 1)` for `v ∈ [-1, 1]` as a quadratic.
fn parabola() -> RationalBezier<Q> {
    RationalBezier::new(vec![[q(1), q(-1), q(1), q(1)], [q(1), q(0), q(-1), q(1)], [q(1), q(1), q(1), q(1)]]).unwrap()
}

/// A half circle of radius 2 about (0, 0, 1) in the plane z = 1, from (2, 0, 1) through
/// (0, 2, 1) to (-2, 0, 1): a rational quadratic with weights 1, 0, 1 (the middle control
/// point at infinity, in the direction (0, 1, 0)).
fn half_circle() -> RationalBezier<Q> {
    RationalBezier::new(vec![[q(1), q(2), q(0), q(1)], [q(0), q(0), q(2), q(0)], [q(1), q(-2), q(0), q(1)]]).unwrap()
}

fn grid() -> Vec<(Q, Q)> {
    let mut g = Vec::new();
    for a in -1..=6 {
        for b in -1..=5 {
            g.push((ratio(a, 5), ratio(b, 4)));
        }
    }
    g
}

fn check(surface: &RationalBezierSurface<Q>, curve: &RationalBezier<Q>, pose: impl Fn(&Q) -> Pose<Q>) {
    for (t, v) in grid() {
        let want = pose(&t).transform_point(&curve.point(&v).unwrap()).unwrap();
        assert_eq!(surface.point(&t, &v).unwrap(), want, "(t, v) = ({t}, {v})");
    }
    // a position of the swept curve is the moved curve
    let t = ratio(2, 7);
    let c = surface.curve_at(&t).unwrap();
    for v in [q(0), ratio(1, 3), q(1)] {
        assert_eq!(c.point(&v).unwrap(), pose(&t).transform_point(&curve.point(&v).unwrap()).unwrap());
    }
}

#[test]
fn q_motion_sweeps_exactly() {
    let m = q_motion();
    for curve in [parabola(), half_circle()] {
        let s = RationalBezierSurface::kinematic(&m, &curve).unwrap();
        assert_eq!(s.degrees(), (8, 2));
        check(&s, &curve, |t| m.pose_exact(t).unwrap());
    }
}

#[test]
fn additive_bezier_motion_sweeps_exactly() {
    let c = [[1, 0, 0, 0, 0, 0, 0, 0], [2, 1, -1, 0, 3, 0, 1, 1], [1, 0, 2, -1, -2, 1, 4, -1]];
    let m = AdditiveBezier::new(c.iter().map(|c| Pose::from_array(c.map(q))).collect()).unwrap();
    for curve in [parabola(), half_circle()] {
        let s = RationalBezierSurface::kinematic(&m, &curve).unwrap();
        assert_eq!(s.degrees(), (4, 2));
        check(&s, &curve, |t| m.evaluate(t).unwrap());
    }
}

#[test]
fn bad_nets_and_zero_weights_are_typed_errors() {
    assert!(matches!(RationalBezierSurface::<Q>::new(vec![]), Err(JuttlerError::TooFewPositions { .. })));
    assert!(matches!(RationalBezierSurface::<Q>::new(vec![vec![]]), Err(JuttlerError::TooFewPositions { .. })));
    let row = vec![[q(1), q(0), q(0), q(0)]; 2];
    let ragged = RationalBezierSurface::new(vec![row.clone(), row[..1].to_vec()]);
    assert!(matches!(ragged, Err(JuttlerError::Parameters { .. })));
    // a rotation R(t) = (1 - t) - t through zero at t = 1/2: the surface has a pole there
    let one = Quaternion::new(q(1), q(0), q(0), q(0));
    let c = vec![DualQuaternion::from_real(one.clone()), DualQuaternion::from_real(one.scale(&q(-1)))];
    let s = RationalBezierSurface::kinematic(&QMotion::new_exact(c).unwrap(), &parabola()).unwrap();
    assert!(matches!(s.point(&ratio(1, 2), &q(0)), Err(JuttlerError::ZeroWeight { .. })));
}
