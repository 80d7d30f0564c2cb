//! `Pose<f64>` against nalgebra's `Isometry3` and `UnitDualQuaternion` (feature `nalgebra`):
//! the same action on points, round trips both ways, and composition order
//! (`U * V` applies `U` first, nalgebra's `v * u` applies `u` first).
//!
//! Run with `cargo test -p motion --features nalgebra --test all -- nalgebra_conv::`.
#![cfg(feature = "nalgebra")]

use algebra_core::test_support::Xorshift;
use motion::Pose;
use motion::Pseudoscalar;
use nalgebra::{Isometry3, Point3, UnitDualQuaternion, UnitQuaternion, Vector3};
use std::f64::consts::PI;

const TOL: f64 = 1e-12;

/// Three values in [-scale, scale).
fn vec(rng: &mut Xorshift, scale: f64) -> [f64; 3] {
    rng.vec3().map(|x| x * scale)
}

/// Unit poses (random screws plus the edge cases: identity, pure translation, pure rotation,
/// rotation by π) and non-unit ones (`γ S` for non-singular pseudoscalars `γ`, negative scalar
/// parts included).
fn poses() -> Vec<Pose<f64>> {
    let mut rng = Xorshift(0x9e37_79b9_7f4a_7c15);
    let mut out = vec![
        Pose::identity(),
        Pose::translation(&[1.0, -2.0, 3.0]),
        Pose::rotation(&[1.0, 1.0, 0.0], &0.8).unwrap(),
        Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &PI, &[1.0, 2.0, 3.0]).unwrap(),
        Pose::from_axis_angle_translation(&[1.0, 2.0, -1.0], &-PI, &[-4.0, 0.5, 2.0]).unwrap(),
    ];
    for _ in 0..200 {
        let axis = vec(&mut rng, 1.0);
        let angle = rng.symmetric() * PI;
        let t = vec(&mut rng, 10.0);
        out.push(Pose::from_axis_angle_translation(&axis, &angle, &t).unwrap());
    }
    let unit = out.clone();
    for (i, s) in unit.iter().enumerate() {
        let a = 0.2 + 3.0 * (rng.symmetric() + 1.0);
        let a = if i % 2 == 0 { a } else { -a };
        out.push(s.scale_pseudoscalar(&Pseudoscalar::new(a, 5.0 * rng.symmetric())));
    }
    out
}

fn isometries() -> Vec<Isometry3<f64>> {
    let mut rng = Xorshift(0x2545_f491_4f6c_dd1d);
    let mut out = vec![
        Isometry3::identity(),
        Isometry3::translation(1.0, 2.0, 3.0),
        Isometry3::rotation(Vector3::new(0.0, PI, 0.0)),
    ];
    for _ in 0..200 {
        let [x, y, z] = vec(&mut rng, 10.0);
        let [a, b, c] = vec(&mut rng, PI / 3f64.sqrt());
        out.push(Isometry3::new(Vector3::new(x, y, z), Vector3::new(a, b, c)));
    }
    out
}

fn unit_dual_quaternions() -> Vec<UnitDualQuaternion<f64>> {
    isometries()
        .into_iter()
        .enumerate()
        .map(|(i, iso)| {
            let q = UnitDualQuaternion::from_isometry(&iso);
            // both signs of the same motion
            if i % 2 == 0 { q } else { UnitDualQuaternion::new_unchecked(-q.into_inner()) }
        })
        .collect()
}

fn points() -> Vec<[f64; 3]> {
    let mut rng = Xorshift(0xdead_beef_cafe_f00d);
    let mut out = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    out.extend((0..8).map(|_| vec(&mut rng, 5.0)));
    out
}

fn close3(a: &[f64; 3], b: &Point3<f64>) -> bool {
    (a[0] - b.x).abs() <= TOL && (a[1] - b.y).abs() <= TOL && (a[2] - b.z).abs() <= TOL
}

fn iso_close(a: &Isometry3<f64>, b: &Isometry3<f64>) -> bool {
    let (qa, qb) = (a.rotation.coords, b.rotation.coords);
    let same_rotation = (qa - qb).amax() <= TOL || (qa + qb).amax() <= TOL;
    same_rotation && (a.translation.vector - b.translation.vector).amax() <= TOL
}

fn udq_coeffs(q: &UnitDualQuaternion<f64>) -> [f64; 8] {
    let q = q.as_ref();
    [q.real.w, q.real.i, q.real.j, q.real.k, q.dual.w, q.dual.i, q.dual.j, q.dual.k]
}

fn udq_close(a: &UnitDualQuaternion<f64>, b: &UnitDualQuaternion<f64>, up_to_sign: bool) -> bool {
    let (a, b) = (udq_coeffs(a), udq_coeffs(b));
    let same = a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= TOL);
    let opposite = a.iter().zip(&b).all(|(x, y)| (x + y).abs() <= TOL);
    same || (up_to_sign && opposite)
}

#[test]
fn isometry_moves_points_like_the_pose() {
    for s in poses() {
        let iso = s.to_isometry().unwrap();
        let udq = s.to_unit_dual_quaternion().unwrap();
        for p in points() {
            let ours = s.transform_point(&p).unwrap();
            let np = Point3::new(p[0], p[1], p[2]);
            assert!(
                close3(&ours, &iso.transform_point(&np)),
                "{s}: {ours:?} vs isometry {:?}",
                iso.transform_point(&np)
            );
            assert!(
                close3(&ours, &udq.transform_point(&np)),
                "{s}: {ours:?} vs dual quaternion {:?}",
                udq.transform_point(&np)
            );
        }
    }
}

#[test]
fn outputs_are_unit() {
    for s in poses() {
        let iso = s.to_isometry().unwrap();
        assert!((iso.rotation.norm() - 1.0).abs() <= TOL);
        let (real, dual) = (s.to_unit_dual_quaternion().unwrap().real, s.to_unit_dual_quaternion().unwrap().dual);
        assert!((real.norm() - 1.0).abs() <= TOL, "{s}");
        assert!(real.coords.dot(&dual.coords).abs() <= TOL, "{s}: real · dual must vanish");
    }
}

#[test]
fn pose_isometry_pose_is_equivalent() {
    for s in poses() {
        let back = Pose::from_isometry(&s.to_isometry().unwrap());
        assert!(back.is_unitary(&TOL), "{back}");
        assert!(back.is_equivalent(&s, &TOL).unwrap(), "{s} -> {back}");
        assert!(Pose::from(&Isometry3::try_from(&s).unwrap()).is_equivalent(&s, &TOL).unwrap());
    }
}

#[test]
fn isometry_pose_isometry_is_identity() {
    for iso in isometries() {
        let s = Pose::from_isometry(&iso);
        assert!(s.is_unitary(&TOL));
        let back = s.to_isometry().unwrap();
        assert!(iso_close(&iso, &back), "{iso} -> {s} -> {back}");
        let m = (iso.to_homogeneous() - back.to_homogeneous()).amax();
        assert!(m <= TOL, "{iso}: homogeneous matrices differ by {m}");
        // and the isometry's matrix is the pose's rigid matrix
        let ours = s.to_matrix().unwrap();
        let theirs = iso.to_homogeneous();
        for (i, row) in ours.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                assert!((x - theirs[(i, j)]).abs() <= TOL);
            }
        }
    }
}

#[test]
fn pose_dual_quaternion_pose_is_equivalent() {
    for s in poses() {
        let back = Pose::from_unit_dual_quaternion(&s.to_unit_dual_quaternion().unwrap());
        assert!(back.is_unitary(&TOL), "{back}");
        assert!(back.is_equivalent(&s, &TOL).unwrap(), "{s} -> {back}");
        assert!(Pose::from(&UnitDualQuaternion::try_from(&s).unwrap()).is_equivalent(&s, &TOL).unwrap());
    }
}

#[test]
fn dual_quaternion_pose_dual_quaternion_is_identity() {
    for q in unit_dual_quaternions() {
        let s = Pose::from_unit_dual_quaternion(&q);
        assert!(s.is_unitary(&TOL));
        let back = s.to_unit_dual_quaternion().unwrap();
        // the sign is kept, so the coefficients agree exactly up to rounding
        assert!(udq_close(&q, &back, false), "{q} -> {s} -> {back}");
        // and the isometry of the dual quaternion is the pose's
        assert!(iso_close(&q.to_isometry(), &s.to_isometry().unwrap()));
    }
}

#[test]
fn unit_pose_maps_to_the_isomorphic_dual_quaternion() {
    // The paper's rotation cos(φ/2) + sin(φ/2) e12 (about e3) is cos(φ/2) + sin(φ/2) k, and
    // the translation 1 + ½ v einf is 1 + ε v/2 (gam_algebras::dual_quaternion).
    let phi = 0.7f64;
    let r = Pose::rotation(&[0.0, 0.0, 1.0], &phi).unwrap().to_unit_dual_quaternion().unwrap();
    let expected = UnitDualQuaternion::from_rotation(UnitQuaternion::from_axis_angle(&Vector3::z_axis(), phi));
    assert!(udq_close(&r, &expected, false), "{r} vs {expected}");
    let t = Pose::translation(&[2.0, -4.0, 6.0]).to_unit_dual_quaternion().unwrap();
    assert_eq!(udq_coeffs(&t), [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, -2.0, 3.0]);
}

#[test]
fn composition_order_matches() {
    let ps = poses();
    for (u, v) in ps.iter().zip(ps.iter().rev()) {
        let uv = u * v; // U first, then V
        let (iu, iv) = (u.to_isometry().unwrap(), v.to_isometry().unwrap());
        assert!(iso_close(&uv.to_isometry().unwrap(), &(iv * iu)), "{u} * {v}");
        let (qu, qv) = (u.to_unit_dual_quaternion().unwrap(), v.to_unit_dual_quaternion().unwrap());
        assert!(udq_close(&uv.to_unit_dual_quaternion().unwrap(), &(qv * qu), true), "{u} * {v}");
        for p in points() {
            let ours = uv.transform_point(&p).unwrap();
            assert!(close3(&ours, &(iv * iu).transform_point(&Point3::new(p[0], p[1], p[2]))));
        }
        // and back: the product of isometries is the pose product
        let back = Pose::from_isometry(&(iv * iu));
        assert!(back.is_equivalent(&uv, &TOL).unwrap());
    }
}

#[test]
fn singular_and_non_finite_poses_are_rejected() {
    let singular = Pose::new(0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0);
    assert!(singular.to_isometry().is_err());
    assert!(singular.to_unit_dual_quaternion().is_err());
    let nan = Pose::translation(&[f64::NAN, 0.0, 0.0]);
    assert!(nan.to_isometry().is_err());
    assert!(UnitDualQuaternion::try_from(&nan).is_err());
}
