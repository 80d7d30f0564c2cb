//! B-spline Q-motions (Jüttler Sec. 6): de Boor against the Cox–de Boor basis sum (written
//! here, an independent reference), the Bézier pieces against both, continuity `C^{p-k}` at a
//! knot of multiplicity `k`, Bézier knots giving the Bézier Q-motion, the Study condition per
//! piece, trajectories exact over rationals, typed errors.

use algebra_core::rational::{Q, q, ratio, rational_to_f64};
use gam_algebras::DualQuaternion;
use gam_algebras::dual_quaternion::Quaternion;
use motion::juttler::bspline::BSplineQMotion;
use motion::juttler::{JuttlerError, QMotion};
use motion::{Motion, Pose};

fn d(c: [i64; 8]) -> DualQuaternion<Q> {
    DualQuaternion::from_coeffs(c.map(q))
}

/// `N_j^p(t)` by the Cox–de Boor recursion (`0/0 = 0`, half-open spans).
fn basis(j: usize, p: usize, u: &[Q], t: &Q) -> Q {
    if p == 0 {
        return if u[j] <= *t && *t < u[j + 1] { q(1) } else { q(0) };
    }
    let mut sum = q(0);
    if u[j + p] != u[j] {
        sum += (t.clone() - u[j].clone()) / (u[j + p].clone() - u[j].clone()) * basis(j, p - 1, u, t);
    }
    if u[j + p + 1] != u[j + 1] {
        sum +=
            (u[j + p + 1].clone() - t.clone()) / (u[j + p + 1].clone() - u[j + 1].clone()) * basis(j + 1, p - 1, u, t);
    }
    sum
}

/// A cubic B-spline Q-motion `(2 + ε s) * R_j` (a fixed translation after a rotational B-spline:
/// on the Study quadric for every t) with a double interior knot.
fn cubic() -> BSplineQMotion<Q> {
    let rot = [[1, 0, 0, 0], [2, 1, -1, 3], [1, 2, 0, -1], [0, 1, 1, 1], [3, -1, 0, 2], [1, 1, -2, 0], [2, 0, 1, -1]];
    let shift =
        DualQuaternion::new(Quaternion::new(q(2), q(0), q(0), q(0)), Quaternion::pure(&[q(1), q(-3), ratio(1, 2)]));
    let control = rot
        .iter()
        .map(|[w, x, y, z]| &shift * &DualQuaternion::from_real(Quaternion::new(q(*w), q(*x), q(*y), q(*z))))
        .collect();
    let knots = vec![q(0), q(0), q(0), q(0), ratio(1, 3), ratio(1, 2), ratio(1, 2), q(1), q(1), q(1), q(1)];
    BSplineQMotion::new_exact(3, knots, control).unwrap()
}

#[test]
fn de_boor_and_the_pieces_equal_the_basis_sum_exactly() {
    let m = cubic();
    assert_eq!(m.pieces().breaks(), [q(0), ratio(1, 3), ratio(1, 2), q(1)]);
    for k in 0..40 {
        let t = ratio(k, 40);
        let want = m
            .control()
            .iter()
            .enumerate()
            .fold(DualQuaternion::zero(), |acc, (j, b)| &acc + &b.scale(&basis(j, 3, m.knots(), &t)));
        assert_eq!(m.eval(&t), want, "t = {t}");
        assert_eq!(m.pieces().eval(&t), want, "pieces, t = {t}");
    }
}

#[test]
fn continuity_is_c2_at_a_simple_knot_and_c1_at_a_double_one() {
    let m = cubic();
    let s = m.pieces();
    // values and first derivatives agree at both interior knots
    for (i, t) in [(1, ratio(1, 3)), (2, ratio(1, 2))] {
        assert_eq!(s.segment_jet(i - 1, &t), s.segment_jet(i, &t), "t = {t}");
    }
    // second derivatives: equal at the simple knot, not at the double one (control differences)
    let second = |i: usize, u: &Q| -> DualQuaternion<Q> {
        let c = s.segments()[i].control();
        let dt = s.breaks()[i + 1].clone() - s.breaks()[i].clone();
        let dd: Vec<DualQuaternion<Q>> = c.windows(3).map(|w| &(&w[2] - &w[1].scale(&q(2))) + &w[0]).collect();
        let f = q(6) / (dt.clone() * dt);
        (if *u == q(0) { dd[0].clone() } else { dd[1].clone() }).scale(&f)
    };
    assert_eq!(second(0, &q(1)), second(1, &q(0)));
    assert_ne!(second(1, &q(1)), second(2, &q(0)));
}

#[test]
fn bezier_knots_give_the_bezier_q_motion() {
    let c = vec![d([1, 0, 0, 0, 0, 0, 0, 0]), d([1, 0, 0, 1, 0, 0, 0, 0]), d([0, 0, 1, 1, 0, 0, 0, 0])];
    let b = BSplineQMotion::new_exact(2, vec![q(0), q(0), q(0), q(1), q(1), q(1)], c.clone()).unwrap();
    let bezier = QMotion::new_exact(c).unwrap();
    assert_eq!(b.pieces().segments(), std::slice::from_ref(&bezier));
    for k in 0..=10 {
        assert_eq!(b.eval(&ratio(k, 10)), bezier.eval(&ratio(k, 10)));
    }
}

#[test]
fn trajectories_of_the_pieces_are_exact_and_the_motion_runs_in_f64() {
    let m = cubic();
    let x = [ratio(1, 2), q(-3), q(2)];
    let paths = m.pieces().trajectories(&x);
    assert!(paths.iter().all(|p| p.degree() == 6));
    let f = m.map_ring(&rational_to_f64);
    let xf = x.clone().map(|c| rational_to_f64(&c));
    for k in 0..=30 {
        let t = ratio(k, 30);
        let (i, u) = m.pieces().local(&t);
        let want = m.pieces().pose_exact(&t).unwrap().transform_point(&x).unwrap();
        assert_eq!(paths[i].point(&u).unwrap(), want, "t = {t}");
        let got: [f64; 3] = f.pose(&rational_to_f64(&t)).unwrap().transform_point(&xf).unwrap();
        assert!((0..3).all(|j| (got[j] - rational_to_f64(&want[j])).abs() < 1e-12), "t = {t}");
    }
    assert_eq!(f.domain(), [0.0, 1.0]);
    let p: Pose<f64> = f.pose(&1.0).unwrap();
    assert!(p.is_equivalent(&f.pieces().segments()[2].pose(&1.0).unwrap(), &1e-15).unwrap());
}

#[test]
fn off_the_quadric_and_bad_knots_are_typed_errors() {
    let (one, eps) = (d([1, 0, 0, 0, 0, 0, 0, 0]), d([0, 0, 0, 0, 1, 0, 0, 0]));
    let k = |v: &[i64]| v.iter().map(|x| q(*x)).collect::<Vec<Q>>();
    // (1 - t) + ε t on the second span only: NotQMotion
    let c = vec![one.clone(), one.clone(), eps];
    assert!(matches!(BSplineQMotion::new_exact(1, k(&[0, 0, 1, 2, 2]), c), Err(JuttlerError::NotQMotion { .. })));
    let c = vec![one.clone(); 3];
    assert!(matches!(
        BSplineQMotion::new_exact(3, k(&[0, 0, 1, 1, 1, 1, 1]), c.clone()),
        Err(JuttlerError::TooFewPositions { .. })
    ));
    assert!(matches!(BSplineQMotion::new_exact(1, k(&[0, 0, 1, 1]), c.clone()), Err(JuttlerError::Parameters { .. })));
    assert!(matches!(
        BSplineQMotion::new_exact(1, k(&[0, 0, 2, 1, 2]), c.clone()),
        Err(JuttlerError::Parameters { .. })
    ));
    assert!(matches!(
        BSplineQMotion::new_exact(1, k(&[0, 1, 1, 1, 2]), c.clone()),
        Err(JuttlerError::Parameters { .. })
    ));
    assert!(matches!(BSplineQMotion::new_exact(1, k(&[0, 1, 1, 1, 1]), c), Err(JuttlerError::Parameters { .. })));
    let nan = BSplineQMotion::new(0, vec![0.0, f64::NAN], vec![DualQuaternion::one()], 1e-12);
    assert!(matches!(nan, Err(JuttlerError::Parameters { .. })));
}

#[test]
fn product_is_the_pointwise_product_with_the_expected_knots() {
    // the rotational cubic (knots 1/3 simple, 1/2 double) times a translational quadratic
    // (knots 1/4, 1/2 simple): degree 5, multiplicities 4 at 1/4 (C1), 3 at 1/3 (C2), 4 at 1/2 (C1)
    let rot = {
        let c = cubic();
        let strip = c.control().iter().map(|b| DualQuaternion::from_real(b.real.clone())).collect();
        BSplineQMotion::new_exact(3, c.knots().to_vec(), strip).unwrap()
    };
    let p = [[0, 0, 0], [1, 2, 0], [3, -1, 1], [2, 2, 2], [0, 1, 4]];
    let tr_control = p
        .iter()
        .map(|v| DualQuaternion::new(Quaternion::new(q(2), q(0), q(0), q(0)), Quaternion::pure(&v.map(q))))
        .collect();
    let tr =
        BSplineQMotion::new_exact(2, vec![q(0), q(0), q(0), ratio(1, 4), ratio(1, 2), q(1), q(1), q(1)], tr_control)
            .unwrap();
    let m = tr.product(&rot).unwrap();
    assert_eq!(m.degree(), 5);
    let want: Vec<Q> = [(q(0), 6), (ratio(1, 4), 4), (ratio(1, 3), 3), (ratio(1, 2), 4), (q(1), 6)]
        .iter()
        .flat_map(|(x, n)| vec![x.clone(); *n])
        .collect();
    assert_eq!(m.knots(), want);
    for k in 0..=40 {
        let t = ratio(k, 40);
        assert_eq!(m.eval(&t), &tr.eval(&t) * &rot.eval(&t), "t = {t}");
    }
    // value and first derivative continuous across the pieces at 1/4 and 1/3
    let s = m.pieces();
    assert_eq!(s.segment_jet(0, &ratio(1, 4)), s.segment_jet(1, &ratio(1, 4)));
    assert_eq!(s.segment_jet(1, &ratio(1, 3)), s.segment_jet(2, &ratio(1, 3)));
    // different domains are a typed error
    let other = BSplineQMotion::new_exact(0, vec![q(0), q(2)], vec![d([1, 0, 0, 0, 0, 0, 0, 0])]).unwrap();
    assert!(matches!(m.product(&other), Err(JuttlerError::Parameters { .. })));
}

/// Rational poses: unit rotations from Pythagorean quadruples `(a² + b² + c² + d² = e²)` after
/// translations.
fn unit_poses() -> Vec<Pose<Q>> {
    let data = [
        ([1, 0, 0, 0], 1, [0, 0, 0]),
        ([1, 2, 2, 4], 5, [1, 2, -1]),
        ([2, 3, 6, 0], 7, [3, 0, 2]),
        ([6, 2, 3, 0], 7, [4, -2, 1]),
        ([1, 4, 8, 0], 9, [5, 1, 0]),
        ([2, 6, 9, 0], 11, [6, 3, 2]),
    ];
    data.iter()
        .map(|([w, x, y, z], e, t)| {
            let r = Pose::rotor_from_parts(&ratio(*w, *e), &q(1), &[ratio(*x, *e), ratio(*y, *e), ratio(*z, *e)]);
            r * Pose::translation(&t.map(q))
        })
        .collect()
}

#[test]
fn bspline_tr_interpolates_exactly_and_is_the_tr_method_for_bezier_knots() {
    use motion::juttler::bspline_tr::bspline_tr;
    use motion::juttler::rotational::elliptic_normalised;
    use motion::juttler::tr::{rotation_translation, tr_method};
    let poses = unit_poses();
    let params = [q(0), ratio(1, 7), ratio(2, 7), ratio(1, 2), ratio(4, 5), q(1)];
    for p in [1, 2, 3] {
        let m = bspline_tr(&poses, &params, p).unwrap();
        assert_eq!(m.degree(), 2 * p);
        for (i, t) in params.iter().enumerate() {
            assert!(m.pieces().pose_exact(t).unwrap().is_equivalent_exact(&poses[i]), "p = {p}, t_{i}");
        }
    }
    // p = m: Bézier knots, the TR method on the elliptic interpolant of the unit rotations
    let m = bspline_tr(&poses, &params, 5).unwrap();
    let rots: Vec<_> = poses.iter().map(|p| rotation_translation(p).unwrap().0).collect();
    let tr = tr_method(&elliptic_normalised(&rots, &params).unwrap(), &poses, &params).unwrap();
    for k in 0..=20 {
        assert_eq!(m.eval(&ratio(k, 20)), tr.eval(&ratio(k, 20)));
    }
    // degree out of range
    assert!(matches!(bspline_tr(&poses, &params, 0), Err(JuttlerError::Parameters { .. })));
    assert!(matches!(bspline_tr(&poses, &params, 6), Err(JuttlerError::Parameters { .. })));
}
