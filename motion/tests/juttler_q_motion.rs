//! Q-motions (Jüttler eq. 13): de Casteljau against the Bernstein sum, the product formula
//! (29) against the pointwise product, degree elevation, the Study polynomial against the
//! pointwise relation (8), and the pose against the rotation matrix U (11) plus translation.

use algebra_core::Jet;
use algebra_core::rational::{Q, q, ratio, rational_to_f64};
use gam_algebras::DualQuaternion;
use gam_algebras::dual_quaternion::Quaternion;
use motion::juttler::{JuttlerError, QMotion};
use motion::repr::dual_quaternion::{matrix_u, study_residual};
use motion::{CurveError, MapScalar, Motion, MotionError};

fn quat(c: [i64; 4]) -> Quaternion<Q> {
    let [w, x, y, z] = c.map(q);
    Quaternion::new(w, x, y, z)
}

/// A rotational Q-motion of degree 2 (no dual part).
fn rotation() -> QMotion<Q> {
    let c = [[1, 0, 0, 0], [2, 1, -1, 3], [1, 2, 0, -1]];
    QMotion::new_exact(c.iter().map(|c| DualQuaternion::from_real(quat(*c))).collect()).unwrap()
}

fn offsets() -> [[Q; 3]; 3] {
    [[q(0), q(0), q(0)], [q(3), ratio(-1, 2), q(1)], [q(1), q(4), ratio(2, 3)]]
}

/// The translational Q-motion `2 + ε Σ b_j p_j` of (30), degree 2.
fn translation() -> QMotion<Q> {
    let c = offsets().iter().map(|p| DualQuaternion::new(quat([2, 0, 0, 0]), Quaternion::pure(p))).collect();
    QMotion::new_exact(c).unwrap()
}

fn params() -> Vec<Q> {
    vec![q(0), ratio(1, 7), ratio(1, 3), ratio(1, 2), ratio(5, 6), q(1), ratio(-1, 2), ratio(3, 2)]
}

fn bernstein(n: usize, i: usize, t: &Q) -> Q {
    let binom = (0..i).fold(q(1), |acc, k| acc * q((n - k) as i64) / q((k + 1) as i64));
    let mut b = binom;
    for _ in 0..i {
        b *= t;
    }
    for _ in i..n {
        b *= q(1) - t;
    }
    b
}

fn bernstein_sum(c: &[DualQuaternion<Q>], t: &Q) -> DualQuaternion<Q> {
    let n = c.len() - 1;
    c.iter().enumerate().fold(DualQuaternion::zero(), |acc, (i, b)| &acc + &b.scale(&bernstein(n, i, t)))
}

#[test]
fn de_casteljau_is_the_bernstein_sum() {
    let m = translation().product(&rotation());
    for t in params() {
        assert_eq!(m.eval(&t), bernstein_sum(m.control(), &t));
    }
}

#[test]
fn product_formula_is_the_pointwise_product_and_a_q_motion() {
    let (tr, rot) = (translation(), rotation());
    let m = tr.product(&rot);
    assert_eq!(m.degree(), 4);
    for t in params() {
        assert_eq!(m.eval(&t), &tr.eval(&t) * &rot.eval(&t));
    }
    // the product stays on the Study quadric, exactly
    assert!(m.study_polynomial().iter().all(|s| *s == q(0)));
    assert!(QMotion::new_exact(m.control().to_vec()).is_ok());
    // and so does the other order (a different motion)
    let n = rot.product(&tr);
    assert_ne!(n, m);
    assert!(n.study_polynomial().iter().all(|s| *s == q(0)));
}

#[test]
fn degree_elevation_keeps_the_curve() {
    let m = translation().product(&rotation());
    let e = m.elevate().elevate();
    assert_eq!(e.degree(), 6);
    assert_eq!(e.control()[0], m.control()[0]);
    assert_eq!(e.control()[6], m.control()[4]);
    for t in params() {
        assert_eq!(e.eval(&t), m.eval(&t));
    }
}

#[test]
fn study_polynomial_is_the_pointwise_relation() {
    // a curve off the quadric: the polynomial evaluated as a Bernstein sum equals (8) at t
    let d = |c: [i64; 8]| DualQuaternion::from_coeffs(c.map(q));
    let c = vec![d([1, 2, 0, 1, 3, 0, 1, 0]), d([0, 1, 1, 0, 1, -1, 2, 5]), d([2, 0, 1, 1, 0, 4, 0, -1])];
    let e = QMotion::new_exact(c.clone()).unwrap_err();
    assert!(matches!(e, JuttlerError::NotQMotion { .. }), "{e}");
    let m = QMotion::new(c, f64::INFINITY).unwrap();
    let s = m.study_polynomial();
    assert_eq!(s.len(), 5);
    for t in params() {
        let poly = s.iter().enumerate().fold(q(0), |acc, (i, x)| acc + x * bernstein(4, i, &t));
        assert_eq!(poly, study_residual(&m.eval(&t)));
    }
    // a Q-motion perturbed in one dual coefficient leaves the quadric
    let mut c = translation().product(&rotation()).control().to_vec();
    c[2].dual.w += ratio(1, 1000);
    assert!(matches!(QMotion::new_exact(c), Err(JuttlerError::NotQMotion { index: 2, .. })));
    assert_eq!(QMotion::<Q>::new_exact(vec![]).unwrap_err(), JuttlerError::TooFewPositions { need: 1, got: 0 });
}

/// `Q_trans * Q_rot` rotates by `U(R(t))/|R(t)|²` (eq. 11), then translates by `p(t)`.
fn expected_point(t: &Q, x: &[Q; 3]) -> [Q; 3] {
    let r = rotation().eval(t).real;
    let u = matrix_u(&r);
    let n = r.norm_squared();
    let p = bernstein_sum(&offsets().map(|p| DualQuaternion::new(Quaternion::zero(), Quaternion::pure(&p))), t).dual;
    let p = p.vector();
    std::array::from_fn(|i| (0..3).fold(q(0), |acc, j| acc + &u[i][j] * &x[j]) / &n + &p[i])
}

#[test]
fn pose_exact_is_rotation_then_translation() {
    let m = translation().product(&rotation());
    let x = [q(1), ratio(-2, 3), q(5)];
    for t in params() {
        let pose = m.pose_exact(&t).unwrap();
        assert_eq!(pose.transform_point(&x).unwrap(), expected_point(&t, &x), "t = {t}");
    }
}

#[test]
fn motion_trait_in_f64_and_dual_numbers() {
    let m = translation().product(&rotation());
    let mf = m.map_ring(&rational_to_f64);
    let x = [q(1), ratio(-2, 3), q(5)];
    let xf = x.clone().map(|c| rational_to_f64(&c));
    for k in 0..=20 {
        let t = ratio(k, 20);
        let want = expected_point(&t, &x).map(|c| rational_to_f64(&c));
        let got = mf.pose(&rational_to_f64(&t)).unwrap().transform_point(&xf).unwrap();
        assert!((0..3).all(|i| (got[i] - want[i]).abs() < 1e-13), "{got:?} {want:?}");
    }
    assert!(matches!(mf.pose(&1.5), Err(CurveError::OutOfDomain { .. })));
    // the velocity by a dual-number parameter against the exact derivative over Jet<Q>
    let mj = m.map_ring(&|c: &Q| Jet::constant(c.clone()));
    let xj = x.clone().map(Jet::constant);
    let mfj = mf.map_scalar(&|c: &f64| Jet::constant(*c));
    let xfj = xf.map(Jet::constant);
    for t in [ratio(1, 5), ratio(2, 3)] {
        let exact = mj.pose_exact(&Jet::variable(t.clone())).unwrap().transform_point(&xj).unwrap();
        let float = mfj.pose(&Jet::variable(rational_to_f64(&t))).unwrap().transform_point(&xfj).unwrap();
        for i in 0..3 {
            let (e, f) = (rational_to_f64(&exact[i].eps), float[i].eps);
            assert!((e - f).abs() < 1e-12 * (1.0 + e.abs()), "{e} {f}");
        }
    }
}

#[test]
fn a_pole_is_an_error_not_a_nan() {
    // R(t) = (1 - t) - t: zero at t = 1/2
    let c = vec![DualQuaternion::from_real(quat([1, 0, 0, 0])), DualQuaternion::from_real(quat([-1, 0, 0, 0]))];
    let m = QMotion::new_exact(c).unwrap();
    assert!(matches!(m.pose_exact(&ratio(1, 2)), Err(JuttlerError::Repr(_))));
    let mf = m.map_ring(&rational_to_f64);
    assert!(matches!(mf.pose(&0.5), Err(CurveError::Pose(MotionError::Singular { .. }))));
    assert!(mf.pose(&0.25).is_ok());
}
