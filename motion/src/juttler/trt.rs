//! The TRT method (Jüttler Sec. 4.2, eqs. 32-34, Result 5): the rotational Q-motion `Q_rot` of
//! degree `k` between two translational Q-motions of degrees `l1`, `l2` with `l1 + l2 = m - 1`,
//!
//! `Q(t) = [2 + ε Σ b_j^{l1}(t) p_j^(1)] * Q_rot(t) * [2 + ε Σ b_j^{l2}(t) p_j^(2)]`  (32),
//!
//! which, as `ε² = 0`, is `4 Q_rot + 2ε (a Q_rot + Q_rot b)` (`a`, `b` the two translation
//! curves) and has degree `max(l1, l2) + k`; we store it halved, `2 Q_rot + ε (a Q_rot + Q_rot b)`.
//! Its translation at `t_i` is `a + U b/|Q_rot|²`, so the interpolation conditions are the
//! linear system (34), `|Q_rot(t_i)|² a(t_i) + U(t_i) b(t_i) = |Q_rot(t_i)|² s_i`, `3(m + 1)`
//! equations for the `3(l1 + l2 + 2) = 3(m + 1)` unknowns (note: the printed Result 5 says
//! `l1, l2 ≤ 0`; it means `≥ 0`).
//!
//! Unlike the TR method (`l2 = 0` would not do: there the second factor is absent), the result
//! does not depend on the origin of the moving space: moving the origin by `c` multiplies the
//! positions and the solution on the right by `2 + ε c`, which only shifts `b` by `c`.
//!
//! ```
//! use motion::{Motion, Pose, juttler::trt::trt};
//! let poses = [
//!     Pose::<f64>::identity(),
//!     Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &1.0, &[1.0, 2.0, 0.0]).unwrap(),
//!     Pose::from_axis_angle_translation(&[1.0, 0.0, 0.0], &0.5, &[3.0, 0.0, 1.0]).unwrap(),
//! ];
//! let m = trt(&poses, &[0.0, 0.4, 1.0], 1).unwrap(); // l1 = 1, l2 = 0, k = 2
//! assert_eq!(m.degree(), 3);
//! assert!(m.pose(&0.4).unwrap().is_equivalent(&poses[1], &1e-12).unwrap());
//! ```

use super::projective::null_space;
use super::rotational::{check_count, elliptic};
use super::tr::{rotation_translation, rotations};
use super::{JuttlerError, QMotion, bernstein_values, check_finite_distinct};
use crate::Pose;
use crate::repr::dual_quaternion::{DualQuaternion, Quaternion, matrix_u};
use algebra_core::linalg::solve;
use algebra_core::{Field, Real, Ring};

/// Checks that `rot` is a rotational Q-motion `Q_rot` (17): zero dual parts.
pub(crate) fn rotation_curve<T: Ring>(rot: &QMotion<T>) -> Result<(), JuttlerError> {
    match rot.control().iter().position(|c| c.dual != Quaternion::zero()) {
        Some(index) => Err(JuttlerError::NotRotational { index }),
        None => Ok(()),
    }
}

/// `c` elevated to degree `n` (`n ≥` its degree).
pub(crate) fn elevate_to<T: Ring>(mut c: QMotion<T>, n: usize) -> QMotion<T> {
    while c.degree() < n {
        c = c.elevate();
    }
    c
}

/// The translational curve `ε Σ b_j(t) p_j` (zero real part, on the Study quadric).
fn epsilon_curve<T: Ring>(p: &[[T; 3]]) -> QMotion<T> {
    QMotion::from_control_unchecked(
        p.iter().map(|p| DualQuaternion::new(Quaternion::zero(), Quaternion::pure(p))).collect(),
    )
}

/// The TRT method (32)-(34) on a rotational Q-motion `rot` (zero dual parts) that interpolates
/// the rotational parts at `params` (e.g. [`super::rotational::affine`],
/// [`super::rotational::elliptic_normalised`], [`super::projective::projective`]): `Q(t_i) =
/// λ_i P_i`, degree `max(l1, l2) + k` with `l2 = m - 1 - l1`; exact over rationals. Fails for
/// fewer than two positions, `l1 > m - 1` ([`JuttlerError::Split`]), a `rot` with a dual part
/// ([`JuttlerError::NotRotational`]) and a singular system (34)
/// ([`JuttlerError::SingularSystem`]). (34) is singular whenever all relative rotations share
/// an axis `v` (planar motions, and any two positions): `b` constant along that axis and
/// `a = -Rot(t_i) b` solve the homogeneous system. It is also singular for *every* set of
/// positions when `l1 = l2` is even (`m = 1, 5, 9, ...`): measured over random rational
/// positions for `m ≤ 9` (the `juttler/result-5` statement checks `m ≤ 6`), not proved; every
/// other split was nonsingular in general position.
///
/// ```
/// use algebra_core::rational::q;
/// use motion::{Pose, juttler::{rotational::affine, tr::rotation_translation, trt::trt_method}};
/// let poses = [
///     Pose::translation(&[q(0), q(0), q(0)]),
///     Pose::rotor_from_parts(&q(1), &q(1), &[q(0), q(0), q(1)]) * Pose::translation(&[q(2), q(0), q(0)]),
///     Pose::rotor_from_parts(&q(2), &q(1), &[q(1), q(0), q(0)]) * Pose::translation(&[q(0), q(1), q(3)]),
/// ];
/// let t = [q(0), q(1) / q(2), q(1)];
/// let rots: Vec<_> = poses.iter().map(|p| rotation_translation(p).unwrap().0).collect();
/// let m = trt_method(&affine(&rots, &t).unwrap(), &poses, &t, 1).unwrap();
/// assert!((0..3).all(|i| m.pose_exact(&t[i]).unwrap().is_equivalent_exact(&poses[i])));
/// ```
pub fn trt_method<T: Field>(
    rot: &QMotion<T>,
    poses: &[Pose<T>],
    params: &[T],
    l1: usize,
) -> Result<QMotion<T>, JuttlerError> {
    check_count(poses.len(), params)?;
    if poses.len() < 2 {
        return Err(JuttlerError::TooFewPositions { need: 2, got: poses.len() });
    }
    let m = poses.len() - 1;
    if l1 > m - 1 {
        return Err(JuttlerError::Split { l1, max: m - 1 });
    }
    rotation_curve(rot)?;
    check_finite_distinct(params, poses.iter().flat_map(Pose::components))?;
    let l2 = m - 1 - l1;
    let s = poses.iter().map(|p| Ok(rotation_translation(p)?.1)).collect::<Result<Vec<_>, JuttlerError>>()?;
    // unknowns: p^(1)_0 .. p^(1)_l1, then p^(2)_0 .. p^(2)_l2, three coordinates each
    let n = 3 * (m + 1);
    let mut a = vec![vec![T::zero(); n]; n];
    let mut rhs = vec![T::zero(); n];
    for (i, (t, si)) in params.iter().zip(&s).enumerate() {
        let r = rot.eval(t).real;
        let (norm, u) = (r.norm_squared(), matrix_u(&r));
        let (b1, b2) = (bernstein_values(l1, t), bernstein_values(l2, t));
        for row in 0..3 {
            let eq = 3 * i + row;
            for (j, b) in b1.iter().enumerate() {
                a[eq][3 * j + row] = norm.mul_ref(b);
            }
            for (j, b) in b2.iter().enumerate() {
                for c in 0..3 {
                    a[eq][3 * (l1 + 1 + j) + c] = u[row][c].mul_ref(b);
                }
            }
            rhs[eq] = norm.mul_ref(&si[row]);
        }
    }
    let why = if l1 == l2 && l1.is_multiple_of(2) {
        "with l1 = l2 even, (34) is singular for every set of positions (found for m = 1, 5, 9): choose another l1"
    } else {
        "the positions do not determine both translation curves (their relative rotations share an axis, as in a planar motion)"
    };
    let x = solve(a.clone(), rhs).ok_or_else(|| JuttlerError::SingularSystem {
        system: "(34)",
        rank: n - null_space(&a, n).len(),
        unknowns: n,
        why,
    })?;
    let p: Vec<[T; 3]> = x.chunks(3).map(|c| [c[0].clone(), c[1].clone(), c[2].clone()]).collect();
    let (p1, p2) = p.split_at(l1 + 1);
    let deg = l1.max(l2) + rot.degree();
    let terms = [rot.map_ring(&|x| x.add_ref(x)), epsilon_curve(p1).product(rot), rot.product(&epsilon_curve(p2))]
        .map(|c| elevate_to(c, deg));
    let control =
        (0..=deg).map(|i| &(&terms[0].control()[i] + &terms[1].control()[i]) + &terms[2].control()[i]).collect();
    Ok(QMotion::from_control_unchecked(control))
}

/// The TRT method with the elliptic method (22)-(25) for the rotational parts (`k = m`): a
/// Q-motion of degree `max(l1, m - 1 - l1) + m` with `Q(t_i) = λ_i P_i` (Result 5), independent
/// of the origin of the moving space. `params`: one per position, distinct (e.g. from
/// [`super::parameters`]).
///
/// ```
/// use motion::{Pose, juttler::{JuttlerError, trt::trt}};
/// let p = [Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])];
/// assert_eq!(trt(&p, &[0.0, 1.0], 1), Err(JuttlerError::Split { l1: 1, max: 0 }));
/// ```
pub fn trt<T: Real>(poses: &[Pose<T>], params: &[T], l1: usize) -> Result<QMotion<T>, JuttlerError> {
    check_count(poses.len(), params)?;
    let rots = rotations(poses)?;
    trt_method(&elliptic(&rots, params)?, poses, params, l1)
}
