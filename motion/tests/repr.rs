//! The pose representations of `motion::repr` (issue 10): round trips pose <-> matrix <->
//! quaternion + position <-> dual quaternion <-> hexanion <-> screw over f64 (1e-12) and
//! 256-bit MPFR (1e-70) at the edge cases (identity, pure translation, angle π, angle 1e-9,
//! translation 1e6); exact rational results where the representation is rational; each closed
//! form against a second algorithm (the matrix exponential series, the pose exp/log, Rodrigues,
//! a projection formula); typed errors for bad input.

use crate::common;

use algebra_core::rational::{Q, q};
use algebra_core::{MpFloat, PrecisionGuard, Real, Ring};
use common::diff_n;
use gam_algebras::DualQuaternion;
use motion::repr::ReprError;
use motion::repr::dual_quaternion as dq;
use motion::repr::hexanion::blend::{Decoupled, HexanionLinear};
use motion::repr::hexanion::{Hexanion, Kind};
use motion::repr::quaternion::{from_quaternion_position, to_quaternion_position};
use motion::repr::screw::{Screw, angle, dist, dist_star};
use motion::repr::sign::{canonical_pose, slerp_short};
use motion::{Matrix4, Motion, Pose};

type M4<T> = Matrix4<T>;

fn flat<T: Clone>(m: &M4<T>) -> [T; 16] {
    std::array::from_fn(|k| m[k / 4][k % 4].clone())
}

fn mmul<T: Ring>(a: &M4<T>, b: &M4<T>) -> M4<T> {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..4).fold(T::zero(), |s, k| s + a[i][k].mul_ref(&b[k][j]))))
}

/// The matrix exponential by its power series (Angelidis (13)), summed until the terms are
/// below 10^-(digits): the independent reference for the closed forms.
fn series_exp<T: Real>(h: &M4<T>, digits: i32) -> M4<T> {
    let tol = (0..digits).fold(T::one(), |a, _| a.mul_ref(&T::from_ratio(1, 10)));
    let id: M4<T> = std::array::from_fn(|i| std::array::from_fn(|j| if i == j { T::one() } else { T::zero() }));
    let (mut sum, mut term) = (id.clone(), id);
    for k in 1..600i64 {
        term = mmul(&term, h).map(|r| r.map(|x| x.mul_ref(&T::from_ratio(1, k))));
        sum = std::array::from_fn(|i| std::array::from_fn(|j| sum[i][j].add_ref(&term[i][j])));
        if term.iter().flatten().all(|x| Real::abs(x) < tol) {
            break;
        }
    }
    sum
}

/// Sample poses (name, axis, angle, translation) over any Real: the edge cases of the issue.
fn cases<T: Real>() -> Vec<(&'static str, Pose<T>)> {
    let f = |x: f64| T::from_f64(x);
    let v = |a: f64, b: f64, c: f64| [f(a), f(b), f(c)];
    let pose = |axis: [T; 3], phi: T, t: [T; 3]| Pose::from_axis_angle_translation(&axis, &phi, &t).unwrap();
    vec![
        ("identity", Pose::identity()),
        ("pure translation", Pose::translation(&v(0.5, -1.0, 2.0))),
        ("angle pi", pose(v(0.0, 0.0, 1.0), T::pi(), v(0.0, 0.0, 0.0))),
        ("angle pi with translation", pose(v(1.0, 1.0, 0.0), T::pi(), v(1.0, -1.0, 3.0))),
        ("angle 1e-9", pose(v(1.0, 2.0, 3.0), f(1e-9), v(0.5, -1.0, 2.0))),
        ("translation 1e6", pose(v(0.0, 1.0, 1.0), f(0.8), v(1e6, -2e6, 5e5))),
        ("generic", pose(v(1.0, -2.0, 2.0), f(2.2), v(0.3, 0.1, -0.4))),
    ]
}

/// The scale of the translation, for tolerances relative to it.
fn scale_of<T: Real>(s: &Pose<T>) -> f64 {
    let t = s.transform_point(&[T::zero(), T::zero(), T::zero()]).unwrap();
    t.iter().map(|x| x.to_f64().abs()).fold(1.0, f64::max)
}

/// Asserts that two poses are the same motion (4x4 matrices agree to `tol` relative).
fn same<T: Real>(what: &str, a: &Pose<T>, b: &Pose<T>, tol: f64) {
    let d = diff_n(&flat(&a.to_matrix().unwrap()), &flat(&b.to_matrix().unwrap()));
    assert!(d <= tol * scale_of(a), "{what}: matrices differ by {d:e}");
}

fn round_trips<T: Real>(tol: f64, digits: i32) {
    for (name, s) in cases::<T>() {
        let s = canonical_pose(&s);
        let mat = s.to_matrix().unwrap();
        let from_m = Pose::from_matrix(&mat, &T::from_f64(1e-9)).unwrap();
        same(&format!("{name}: matrix"), &s, &from_m, tol);
        let (q, t) = to_quaternion_position(&s).unwrap();
        let from_q = from_quaternion_position(&q, &t).unwrap();
        same(&format!("{name}: quaternion"), &s, &from_q, tol);
        let d = dq::to_dual_quaternion(&s).unwrap();
        let from_d = dq::from_dual_quaternion(&d, &T::from_f64(1e-9)).unwrap();
        same(&format!("{name}: dual quaternion"), &s, &from_d, tol);
        let h = Hexanion::from_pose(&s).unwrap();
        same(&format!("{name}: hexanion"), &s, &h.to_pose().unwrap(), tol);
        let w = Real::sqrt(
            &(h.omega[0].mul_ref(&h.omega[0]) + h.omega[1].mul_ref(&h.omega[1]) + h.omega[2].mul_ref(&h.omega[2])),
        );
        assert!(w <= T::pi().mul_ref(&T::from_f64(1.0 + 1e-15)), "{name}: principal branch |ω| = {w}");
        let sc = Screw::of(&s).unwrap();
        same(&format!("{name}: screw"), &s, &sc.to_pose().unwrap(), tol);
        // the chain pose -> matrix -> quaternion -> dual quaternion -> hexanion -> screw -> pose
        let (q2, t2) = to_quaternion_position(&Pose::from_matrix(&mat, &T::from_f64(1e-9)).unwrap()).unwrap();
        let d2 = dq::to_dual_quaternion(&from_quaternion_position(&q2, &t2).unwrap()).unwrap();
        let h2 = Hexanion::from_pose(&dq::from_dual_quaternion(&d2, &T::from_f64(1e-9)).unwrap()).unwrap();
        let end = Screw::of_hexanion(&h2).to_pose().unwrap();
        same(&format!("{name}: chain"), &s, &end, tol);
        // the closed form (66) against the series (13) and against the pose's matrix
        let closed = flat(&h.exp_matrix());
        let series = flat(&series_exp(&h.matrix(), digits + 10));
        let sz = scale_of(&s);
        assert!(diff_n(&closed, &series) <= tol * sz, "{name}: (66) vs series {:e}", diff_n(&closed, &series));
        assert!(diff_n(&closed, &flat(&mat)) <= tol * sz, "{name}: (66) vs pose");
        // point and direction transforms (16), (18) against the matrix
        let p = [T::from_f64(0.25), T::from_f64(-1.5), T::from_f64(2.0)];
        let hp = h.transform_point(&p);
        let sp = s.transform_point(&p).unwrap();
        assert!(diff_n(&hp, &sp) <= tol * sz, "{name}: point (35)");
        assert!(diff_n(&h.transform_direction(&p), &s.transform_direction(&p).unwrap()) <= tol * 4.0, "{name}: (36)");
        // Jüttler's (12) against F_S
        let y = dq::point_image(&d, &[T::one(), p[0].clone(), p[1].clone(), p[2].clone()]);
        let y3: [T; 3] = std::array::from_fn(|i| y[i + 1].div_ref(&y[0]));
        assert!(diff_n(&y3, &sp) <= tol * sz, "{name}: (12)");
        // Jüttler's (6) and (11) against the pose's rotation block
        let (axis, phi) = dq::axis_angle(&d.real).unwrap();
        let u = dq::matrix_u(&d.real);
        let rot = if phi.is_exact_zero() { Pose::identity() } else { Pose::rotation(&axis, &phi).unwrap() };
        let rm = rot.to_matrix().unwrap();
        for i in 0..3 {
            assert!(
                diff_n(&u[i], &[mat[i][0].clone(), mat[i][1].clone(), mat[i][2].clone()]) <= tol * 4.0,
                "{name}: (11)"
            );
            assert!(diff_n(&[rm[i][0].clone(), rm[i][1].clone(), rm[i][2].clone()], &u[i]) <= tol * 4.0, "{name}: (6)");
        }
        // Jüttler's (10) against the pose's matrix (weight first)
        let jm = dq::matrix_m(&d);
        for i in 0..3 {
            let row: [T; 4] = std::array::from_fn(|j| jm[i + 1][(j + 1) % 4].div_ref(&jm[0][0]));
            assert!(diff_n(&row, &mat[i]) <= tol * sz, "{name}: (10) row {i}");
        }
    }
}

#[test]
fn round_trips_f64() {
    round_trips::<f64>(1e-12, 14);
}

#[test]
fn round_trips_mpfr_256() {
    let _g = PrecisionGuard::new(256);
    round_trips::<MpFloat>(1e-70, 72);
}

#[test]
fn sec6_conversion_agrees_with_the_pose_logarithm() {
    for (name, s) in cases::<f64>() {
        if name == "angle 1e-9" {
            continue; // (47) divides by 2(1 - cos θ) n_k²: documented loss ~ ε/θ²
        }
        let mat = s.to_matrix().unwrap();
        let a = Hexanion::from_matrix_sec6(&mat, &1e-9).unwrap();
        let b = Hexanion::from_pose(&s).unwrap();
        // both are logarithms of the same motion: compare their motions, and at |ω| < π the values
        same(name, &a.to_pose().unwrap(), &s, 1e-12);
        if !name.starts_with("angle pi") {
            let d = diff_n(&[a.omega, a.m].concat().try_into().unwrap_or([0.0; 6]), &{
                let v: [f64; 6] = [b.omega, b.m].concat().try_into().unwrap();
                v
            });
            assert!(d <= 1e-9 * scale_of(&s), "{name}: {d:e}");
        }
    }
}

#[test]
fn sec6_conversion_at_256_bits() {
    let _g = PrecisionGuard::new(256);
    for (name, s) in cases::<MpFloat>() {
        if name == "angle 1e-9" {
            continue;
        }
        let a = Hexanion::from_matrix_sec6(&s.to_matrix().unwrap(), &MpFloat::from_f64(1e-9)).unwrap();
        same(name, &a.to_pose().unwrap(), &s, 1e-60);
    }
}

#[test]
fn exact_over_rationals() {
    // Rot/Trs split (32)-(33), the matrix form, Jüttler's U, M, (8), (9), (12), projection, signs
    let h = Hexanion::new([q(1), q(2), q(-2)], [q(3), q(0), q(1)]);
    let (rot, trs) = h.rot_trs().unwrap();
    assert_eq!(&rot + &trs, h);
    let wm: Q = (0..3).map(|i| rot.omega[i].clone() * rot.m[i].clone()).fold(q(0), |a, b| a + b);
    assert_eq!(wm, q(0));
    assert_eq!(Hexanion::from_matrix_form(&h.matrix()), h);
    assert!(Hexanion::new([q(0), q(0), q(0)], [q(1), q(0), q(0)]).rot_trs().is_none());
    // a non-unit rotor (1 + e12 scaled) and a translation, exactly
    let s = Pose::<Q>::rotor_from_parts(&q(1), &q(2), &[q(0), q(1), q(0)]) * Pose::translation(&[q(1), q(2), q(3)]);
    let d = dq::to_dual_quaternion_exact(&s);
    assert_eq!(dq::study_residual(&d), q(0));
    for p in [[q(1), q(0), q(0)], [q(2), q(-3), q(5)]] {
        let y = dq::point_image(&d, &[q(1), p[0].clone(), p[1].clone(), p[2].clone()]);
        let img: [Q; 3] = std::array::from_fn(|i| y[i + 1].clone() / y[0].clone());
        assert_eq!(img, s.transform_point(&p).unwrap());
        let m = dq::matrix_m(&d);
        let via_m: [Q; 3] = std::array::from_fn(|i| {
            (m[i + 1][0].clone() + (0..3).fold(q(0), |a, j| a + m[i + 1][j + 1].clone() * p[j].clone()))
                / m[0][0].clone()
        });
        assert_eq!(via_m, img);
    }
    // pose <-> dual quaternion and Jüttler's M (10) against the pose's matrix, exactly
    assert_eq!(dq::from_dual_quaternion_exact(&d).unwrap(), s);
    assert!(matches!(
        dq::from_dual_quaternion_exact(&DualQuaternion::from_coeffs([q(1), q(0), q(0), q(0), q(1), q(0), q(0), q(0)])),
        Err(ReprError::OffStudyQuadric { .. })
    ));
    let (jm, sm) = (dq::matrix_m(&d), s.to_matrix().unwrap());
    for i in 0..3 {
        let row: [Q; 4] = std::array::from_fn(|j| jm[i + 1][(j + 1) % 4].clone() / jm[0][0].clone());
        assert_eq!(row, sm[i]);
    }
    let tr = dq::trans(&d);
    assert_eq!(tr.real.vector(), [q(0), q(0), q(0)]);
    let off = DualQuaternion::from_coeffs([q(1), q(2), q(0), q(1), q(3), q(-1), q(4), q(2)]);
    assert_ne!(dq::study_residual(&off), q(0));
    let on = dq::project_to_study(&off).unwrap();
    assert_eq!(dq::study_residual(&on), q(0));
    assert_eq!(on.real, off.real);
}

#[test]
fn screw_and_juttler_distances_against_second_methods() {
    let p = Pose::from_axis_angle_translation(&[0.3, -0.2, 0.9], &0.7, &[1.0, 2.0, -1.0]).unwrap();
    let qp = Pose::from_axis_angle_translation(&[-0.5, 0.4, 0.2], &2.1, &[0.5, -3.0, 4.0]).unwrap();
    let o = |s: &Pose<f64>| s.transform_point(&[0.0; 3]).unwrap();
    let (op, oq) = (o(&p), o(&qp));
    let delta = [oq[0] - op[0], oq[1] - op[1], oq[2] - op[2]];
    assert!((dist(&p, &qp).unwrap() - (delta.iter().map(|x| x * x).sum::<f64>()).sqrt()).abs() < 1e-14);
    // dist*: project the origin displacement onto the axis of R_q R_p^T (read from the matrices)
    let (mp, mq) = (p.to_matrix().unwrap(), qp.to_matrix().unwrap());
    let r: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| mq[i][k] * mp[j][k]).sum()));
    let axis = [r[2][1] - r[1][2], r[0][2] - r[2][0], r[1][0] - r[0][1]];
    let n = (axis.iter().map(|x| x * x).sum::<f64>()).sqrt();
    let proj = (0..3).map(|i| delta[i] * axis[i] / n).sum::<f64>().abs();
    assert!((dist_star(&p, &qp).unwrap() - proj).abs() < 1e-13);
    // angle: from the trace of R_q R_p^T
    let tr = r[0][0] + r[1][1] + r[2][2];
    assert!((angle(&p, &qp).unwrap() - ((tr - 1.0) / 2.0).acos()).abs() < 1e-13);
    // the screw of a pose: every point moves by d along the axis, the axis point is fixed up to d n
    let sc = Screw::of(&qp).unwrap();
    let moved = qp.transform_point(&sc.point).unwrap();
    let expect: [f64; 3] = std::array::from_fn(|i| sc.point[i] + sc.translation * sc.axis[i]);
    assert!(diff_n(&moved, &expect) < 1e-13);
    assert!((sc.point.iter().zip(&sc.axis).map(|(a, b)| a * b).sum::<f64>()).abs() < 1e-14);
    // edge cases of the contract
    let id = Screw::of(&Pose::<f64>::identity()).unwrap();
    assert_eq!((id.axis, id.angle, id.translation, id.point, id.pitch), ([0.0; 3], 0.0, 0.0, [0.0; 3], None));
    let pi = Screw::of(&Pose::rotation(&[0.0, 1.0, 0.0], &std::f64::consts::PI).unwrap()).unwrap();
    assert!((pi.angle - std::f64::consts::PI).abs() < 1e-15 && pi.axis[1].abs() > 0.999_999);
}

#[test]
fn classification_and_inverse() {
    let rot = Hexanion::twist(&[1.0, 2.0, 0.0], &1.3, &[0.0, 0.0, 1.0], &0.0);
    match rot.classify(&1e-12) {
        Kind::Rotation { centre, angle, axis } => {
            assert!(
                diff_n(&centre, &[1.0, 2.0, 0.0]) < 1e-15 && (angle - 1.3).abs() < 1e-15 && axis == [0.0, 0.0, 1.0]
            );
            // the centre is fixed by the motion (the second method: the pose's action)
            let c = rot.to_pose().unwrap().transform_point(&centre).unwrap();
            assert!(diff_n(&c, &centre) < 1e-14);
        }
        k => panic!("{k:?}"),
    }
    let tw = Hexanion::new([0.3, -0.2, 0.9], [1.0, 2.0, -1.0]);
    assert!(matches!(tw.classify(&1e-12), Kind::Twist { .. }));
    // (22): the inverse undoes the motion, against the pose inverse
    let s = tw.to_pose().unwrap();
    same("inverse", &tw.inverse().to_pose().unwrap(), &s.inverse().unwrap(), 1e-14);
}

#[test]
fn hexanion_linear_motion_and_blends() {
    let poses = [
        Pose::<f64>::identity(),
        Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &1.0, &[1.0, 0.0, 0.0]).unwrap(),
        Pose::from_axis_angle_translation(&[1.0, 0.0, 0.0], &2.0, &[1.0, 1.0, 0.5]).unwrap(),
    ];
    let m = HexanionLinear::through(&poses, &[0.0, 0.5, 2.0]).unwrap();
    for (t, s) in [0.0, 0.5, 2.0].iter().zip(&poses) {
        same("key pose", &m.pose(t).unwrap(), s, 1e-14);
    }
    // (56) at u = 1/2 of the second segment equals the blend (57) with equal weights
    let h = m.hexanion_at(&1.25);
    let b = Hexanion::blend(&[(1.0, m.hexanions()[1].clone()), (1.0, m.hexanions()[2].clone())]).unwrap();
    assert!(
        diff_n(&[h.omega, h.m].concat().try_into().unwrap_or([0.0; 6]), &{
            let v: [f64; 6] = [b.omega, b.m].concat().try_into().unwrap();
            v
        }) < 1e-15
    );
    assert!(m.pose(&2.5).is_err());
    assert!(matches!(HexanionLinear::through(&poses, &[0.0, 1.0]), Err(ReprError::Times { .. })));
    assert!(matches!(
        Hexanion::<f64>::blend(&[(1.0, Hexanion::zero()), (-1.0, Hexanion::zero())]),
        Err(ReprError::ZeroWeight)
    ));
    // (60) (u factors restored) against the pose of (59), at several u
    let d = Decoupled { omega: [0.3, -0.4, 1.1], m: [1.0, 2.0, -0.5], centre: [0.5, 0.5, 0.0] };
    for u in [0.0, 0.3, 0.75, 1.0] {
        let p = [0.2, -1.0, 0.7];
        let a = d.trajectory(&p, &u);
        let b = d.pose(&u).unwrap().transform_point(&p).unwrap();
        assert!(diff_n(&a, &b) < 1e-14, "u = {u}");
    }
}

#[test]
fn signs() {
    let a = Pose::rotation(&[0.0, 0.0, 1.0], &3.0).unwrap();
    // -b is the same motion as b, but rev(a)(-b) has a negative scalar part: the plain slerp
    // turns the long way (2π - 0.4 rad instead of 0.4)
    let b = -&Pose::rotation(&[0.0, 0.0, 1.0], &3.4).unwrap();
    let mid = slerp_short(&a, &b, &0.5).unwrap();
    same("short slerp", &mid, &Pose::rotation(&[0.0, 0.0, 1.0], &3.2).unwrap(), 1e-14);
    let long = Pose::slerp(&a, &b, &0.5).unwrap();
    assert!(!long.is_equivalent(&mid, &1e-6).unwrap());
    same("long slerp", &long, &Pose::rotation(&[0.0, 0.0, 1.0], &(3.2 + std::f64::consts::PI)).unwrap(), 1e-14);
    assert!((canonical_pose(&-&a)).to_array()[0] >= 0.0);
    let zero_scalar = canonical_pose(&-&Pose::rotation(&[0.0, 0.0, 1.0], &std::f64::consts::PI).unwrap());
    assert!(zero_scalar.to_array()[1] > 0.0);
}

#[test]
fn bad_input_is_a_typed_error() {
    let off = DualQuaternion::from_coeffs([1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
    assert!(matches!(dq::from_dual_quaternion(&off, &1e-9), Err(ReprError::OffStudyQuadric { .. })));
    let zero = DualQuaternion::from_coeffs([0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
    assert!(matches!(dq::from_dual_quaternion(&zero, &1e-9), Err(ReprError::ZeroRealPart)));
    let nan = DualQuaternion::from_coeffs([f64::NAN, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
    assert!(matches!(dq::from_dual_quaternion(&nan, &1e-9), Err(ReprError::NotFinite)));
    let shear = [[1.0, 0.5, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];
    assert!(Hexanion::from_matrix_sec6(&shear, &1e-9).is_err());
    assert!(Hexanion::from_matrix(&shear, &1e-9).is_err());
    assert!(Hexanion::new([f64::NAN, 0.0, 0.0], [0.0; 3]).to_pose().is_err());
    assert!(from_quaternion_position(&[0.0; 4], &[0.0; 3]).is_err());
}

#[test]
fn hexanion_motions_have_dual_number_velocities() {
    // velocities of HexanionLinear and Decoupled through the Motion trait (dual numbers),
    // against central differences of the point trajectory
    let poses = [
        Pose::<f64>::identity(),
        Pose::from_axis_angle_translation(&[0.2, 0.1, 1.0], &1.4, &[1.0, -0.5, 0.25]).unwrap(),
    ];
    let lin = HexanionLinear::through(&poses, &[0.0, 2.0]).unwrap();
    let dec = Decoupled { omega: [0.3, -0.4, 1.1], m: [1.0, 2.0, -0.5], centre: [0.5, 0.5, 0.0] };
    let p = [0.4, -0.3, 1.2];
    let h = 1e-6;
    let check = |pose_at: &dyn Fn(f64) -> Pose<f64>, v: motion::velocity::Velocity<f64>, t: f64| {
        let q = pose_at(t).transform_point(&p).unwrap();
        let fd: [f64; 3] = std::array::from_fn(|i| {
            (pose_at(t + h).transform_point(&p).unwrap()[i] - pose_at(t - h).transform_point(&p).unwrap()[i])
                / (2.0 * h)
        });
        assert!(diff_n(&v.point_velocity(&q).to_array(), &fd) < 1e-8, "t = {t}");
    };
    for t in [0.3, 1.0, 1.7] {
        check(&|s| lin.pose(&s).unwrap(), motion::velocity::velocity(&lin, &t).unwrap(), t);
    }
    for u in [0.2, 0.5, 0.9] {
        check(&|s| dec.pose(&s).unwrap(), motion::velocity::velocity(&dec, &u).unwrap(), u);
    }
}
