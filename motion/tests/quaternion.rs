//! Quaternions at the pose boundary, against the rotation matrix of a quaternion written by
//! hand (`R(q)` for the unit `q = w + x i + y j + z k`, the textbook formula), for the named
//! entry points and for the nalgebra and glam conversions (features `nalgebra`, `glam`).

use motion::{MotionError, Pose, Quaternion};

/// `R(q) p + t` for `q` normalised here: the standard matrix
/// `[[1-2(y²+z²), 2(xy-wz), 2(xz+wy)], [2(xy+wz), 1-2(x²+z²), 2(yz-wx)], [2(xz-wy), 2(yz+wx), 1-2(x²+y²)]]`.
fn by_hand(wxyz: [f64; 4], t: [f64; 3], p: [f64; 3]) -> [f64; 3] {
    let n = wxyz.iter().map(|c| c * c).sum::<f64>().sqrt();
    let [w, x, y, z] = wxyz.map(|c| c / n);
    let r = [
        [1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)],
        [2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x)],
        [2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y)],
    ];
    std::array::from_fn(|i| r[i][0] * p[0] + r[i][1] * p[1] + r[i][2] * p[2] + t[i])
}

/// Quaternions `[w, x, y, z]`, not normalised, of every sign pattern that matters.
const QUATS: [[f64; 4]; 6] = [
    [1.0, 0.0, 0.0, 0.0],
    [1.0, 2.0, 3.0, 4.0],
    [-0.3, 0.1, -0.7, 0.2],
    [0.0, 0.0, 0.0, 5.0],
    [0.5, -0.5, 0.5, -0.5],
    [3.0, -1.0, 0.25, 2.0],
];
const T: [f64; 3] = [1.5, -2.0, 0.25];
const POINTS: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, -2.0, 1.0], [0.3, 0.7, -1.1]];

fn assert_close(got: [f64; 3], want: [f64; 3], tol: f64, what: &str) {
    for i in 0..3 {
        assert!((got[i] - want[i]).abs() <= tol, "{what}: {got:?} vs {want:?}");
    }
}

#[test]
fn named_quaternions_rotate_as_the_hand_written_matrix() {
    for wxyz in QUATS {
        let [w, x, y, z] = wxyz;
        let named = Pose::from_quaternion(&Quaternion::new(w, x, y, z), &T).unwrap();
        let array = Pose::from_quaternion_wxyz(&wxyz, &T).unwrap();
        assert_eq!(named, array);
        #[allow(deprecated)]
        let old = Pose::from_quaternion_translation(&wxyz, &T).unwrap();
        assert_eq!(old, array);
        for p in POINTS {
            assert_close(named.transform_point(&p).unwrap(), by_hand(wxyz, T, p), 1e-14, &format!("{wxyz:?}"));
        }
    }
}

#[test]
fn the_scalar_last_order_is_a_different_rotation() {
    // the trap the names avoid: nalgebra's and glam's arrays are [x, y, z, w]
    let wxyz = [1.0, 2.0, 3.0, 4.0];
    let xyzw = [2.0, 3.0, 4.0, 1.0];
    let p = [1.0, 0.0, 0.0];
    let wrong = Pose::from_quaternion_wxyz(&xyzw, &[0.0; 3]).unwrap().transform_point(&p).unwrap();
    let right = by_hand(wxyz, [0.0; 3], p);
    assert!((0..3).any(|i| (wrong[i] - right[i]).abs() > 0.1), "{wrong:?} {right:?}");
}

#[test]
fn to_quaternion_translation_inverts_from_quaternion() {
    for wxyz in QUATS {
        let [w, x, y, z] = wxyz;
        let n = wxyz.iter().map(|c| c * c).sum::<f64>().sqrt();
        let (q, t) =
            Pose::from_quaternion(&Quaternion::new(w, x, y, z), &T).unwrap().to_quaternion_translation().unwrap();
        let back = [q.w, q.x, q.y, q.z];
        for i in 0..4 {
            assert!((back[i] - wxyz[i] / n).abs() < 1e-15, "{back:?} vs {wxyz:?}/{n}");
        }
        assert_close(t, T, 1e-14, "translation");
    }
}

#[test]
fn bad_quaternions_are_typed_errors() {
    assert_eq!(Pose::from_quaternion(&Quaternion::zero(), &[0.0; 3]), Err(MotionError::ZeroQuaternion));
    let nan = Quaternion::new(f64::NAN, 0.0, 0.0, 1.0);
    assert!(matches!(Pose::from_quaternion(&nan, &[0.0; 3]), Err(MotionError::NotFinite { .. })));
    let one = Quaternion::one();
    assert!(matches!(Pose::from_quaternion(&one, &[f64::INFINITY, 0.0, 0.0]), Err(MotionError::NotFinite { .. })));
}

#[cfg(feature = "nalgebra")]
#[test]
fn nalgebra_unit_quaternions_and_isometries_rotate_as_the_hand_written_matrix() {
    use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};
    for wxyz in QUATS {
        let [w, x, y, z] = wxyz;
        let q = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(w, x, y, z));
        let t = Vector3::from(T);
        let s = Pose::from_na_rotation_translation(&q, &t);
        let iso = Pose::from_na_isometry(&Isometry3::from_parts(Translation3::from(t), q));
        assert!(s.is_equivalent(&iso, &1e-15).unwrap());
        for p in POINTS {
            assert_close(s.transform_point(&p).unwrap(), by_hand(wxyz, T, p), 1e-14, &format!("{wxyz:?}"));
        }
        let r = Pose::from(&q);
        assert_close(r.transform_point(&POINTS[2]).unwrap(), by_hand(wxyz, [0.0; 3], POINTS[2]), 1e-14, "rotation");
    }
}

#[cfg(feature = "glam")]
mod glam_conversions {
    use super::*;
    use glam::{Affine3A, DAffine3, DMat4, DQuat, DVec3, Mat4, Quat, Vec3};

    #[test]
    fn glam_quaternions_rotate_as_the_hand_written_matrix() {
        for wxyz in QUATS {
            let [w, x, y, z] = wxyz;
            let s = Pose::<f64>::from_glam_quat_translation(&DQuat::from_xyzw(x, y, z, w), &DVec3::from(T)).unwrap();
            for p in POINTS {
                assert_close(s.transform_point(&p).unwrap(), by_hand(wxyz, T, p), 1e-14, &format!("{wxyz:?}"));
            }
            let q32 = Quat::from_xyzw(x as f32, y as f32, z as f32, w as f32);
            let s32 = Pose::<f32>::from_glam_quat_translation(&q32, &Vec3::from(T.map(|c| c as f32))).unwrap();
            let p = s32.transform_point(&[0.3, 0.7, -1.1]).unwrap().map(f64::from);
            assert_close(p, by_hand(wxyz, T, [0.3f32, 0.7f32, -1.1f32].map(f64::from)), 1e-5, "f32");
        }
    }

    #[test]
    fn glam_matrices_agree_with_the_pose_both_ways() {
        for wxyz in QUATS {
            let [w, x, y, z] = wxyz;
            let q = DQuat::from_xyzw(x, y, z, w).normalize();
            let m = DMat4::from_rotation_translation(q, DVec3::from(T));
            let from_mat = Pose::<f64>::try_from(&m).unwrap();
            let from_affine = Pose::<f64>::try_from(&DAffine3::from_rotation_translation(q, DVec3::from(T))).unwrap();
            assert!(from_mat.is_equivalent(&from_affine, &1e-14).unwrap());
            for p in POINTS {
                assert_close(from_mat.transform_point(&p).unwrap(), by_hand(wxyz, T, p), 1e-13, "mat4");
            }
            let back = from_mat.to_glam_mat4().unwrap();
            assert!(back.abs_diff_eq(m, 1e-14), "{back} vs {m}");
            assert!(from_mat.to_glam_affine().unwrap().abs_diff_eq(DAffine3::from_mat4(m), 1e-14));
            let (q2, t2) = from_mat.to_glam_quat_translation().unwrap();
            assert!(q2.abs_diff_eq(q, 1e-14) || q2.abs_diff_eq(-q, 1e-14), "{q2} vs {q}");
            assert!(t2.abs_diff_eq(DVec3::from(T), 1e-14));
        }
        let m = Mat4::from_rotation_translation(Quat::from_rotation_x(0.4), Vec3::new(1.0, 2.0, 3.0));
        let s = Pose::<f32>::try_from(&m).unwrap();
        assert!(s.to_glam_mat4().unwrap().abs_diff_eq(m, 1e-6));
        let a = Affine3A::from_mat4(m);
        assert!(Pose::<f32>::try_from(&a).unwrap().is_equivalent(&s, &1e-6).unwrap());
    }

    #[test]
    fn non_rigid_or_non_finite_glam_values_are_refused() {
        let not_rigid = |r: Result<Pose<f64>, MotionError>| matches!(r, Err(MotionError::NotRigid { .. }));
        assert!(not_rigid(Pose::try_from(&DMat4::from_scale(DVec3::new(1.0, 1.0, 2.0)))));
        assert!(not_rigid(Pose::try_from(&DMat4::from_scale(DVec3::new(1.0, 1.0, -1.0)))));
        let mut projective = DMat4::IDENTITY;
        projective.x_axis.w = 0.5; // bottom row [0.5, 0, 0, 1]
        assert!(not_rigid(Pose::try_from(&projective)));
        assert!(not_rigid(Pose::try_from(&DAffine3::from_cols_array(&[
            1.0, 0.5, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0
        ]))));
        let nan = DQuat::from_xyzw(f64::NAN, 0.0, 0.0, 1.0);
        assert!(matches!(Pose::<f64>::try_from(&nan), Err(MotionError::NotFinite { .. })));
        assert_eq!(Pose::<f64>::try_from(&DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0)), Err(MotionError::ZeroQuaternion));
    }
}
