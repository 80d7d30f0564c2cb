//! The C1 spline motion whose segments are rational motions of order 6: Jüttler's closing remark
//! of Sec. 6 ("Similar to section 4, a C1-spline motion whose segments are rational motions of
//! order 6 can be constructed, too"), for which the paper gives no formulas. Ours:
//!
//! - the rotational part of segment `i` is Algorithm 2's cubic `D⁽ⁱ⁾` (44): `C_0 = R_i`,
//!   `C_1 = R_i + Δt/6 ω_i R_i`, `C_2 = R_(i+1) - Δt/6 ω_(i+1) R_(i+1)`, `C_3 = R_(i+1)`, so `k = 3`
//!   and the rotations join C1 with the given angular velocities;
//! - with `w0* = 1` (degree `n - 2k = 0`), the matrix (35) is `M(u) = [[N, 0], [w, U(D)]]`,
//!   `N = |D|²`, of order `n = 6`; the origin moves on `w(u)/N(u)`, so `w` is the cubic (degree
//!   elevated to 6) with `w = N s` and `w' = N' s + N Δt v` at both ends: the origin's
//!   positions and velocities `s_i`, `v_i` are met, and the motion is C1 at the joins.
//!
//! The segments are [`MinimalMotion`]s of order 6 (their Q-motions (36) have degree 9, the
//! Q-motion spline's segments degree 6 but order 12): every trajectory is a rational curve of
//! degree 6 per segment. Exact over rationals.
//!
//! ```
//! use algebra_core::rational::q;
//! use motion::{Pose, juttler::{KeyVelocity, minimal_spline::minimal_spline}};
//! let poses = [Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(1), q(0), q(0)])];
//! let v = vec![KeyVelocity::new([q(1), q(0), q(0)], [q(0), q(0), q(1)]); 2];
//! let segments = minimal_spline(&poses, &[q(0), q(1)], &v).unwrap();
//! assert_eq!(segments[0].order(), 6);
//! assert!(segments[0].pose_exact(&q(1)).unwrap().is_equivalent_exact(&poses[1]));
//! ```

use super::minimal::MinimalMotion;
use super::spline::aligned_parts;
use super::velocity::check_spline_parameters;
use super::{JuttlerError, KeyVelocity, elevate_with};
use crate::Pose;
use crate::repr::dual_quaternion::Quaternion;
use algebra_core::Field;

/// The C1 spline of rational motions of order 6 through `poses` at `params` with the given
/// velocities (module docs): one [`MinimalMotion`] per interval, on its local parameter
/// `u = (t - t_i)/(t_(i+1) - t_i)`. The poses' rotational parts are used at their own scale
/// (unit poses: as [`super::spline::algorithm2`] normalises them) with the signs of (24).
/// Fails as [`super::SplineQMotion::hermite`] does.
///
/// ```
/// use algebra_core::rational::q;
/// use motion::{Pose, juttler::{JuttlerError, KeyVelocity, minimal_spline::minimal_spline}};
/// let p = [Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(1), q(0), q(0)])];
/// let v = vec![KeyVelocity::new([q(0), q(0), q(0)], [q(0), q(0), q(0)]); 2];
/// assert!(matches!(minimal_spline(&p, &[q(1), q(0)], &v), Err(JuttlerError::Parameters { .. })));
/// ```
pub fn minimal_spline<T: Field + PartialOrd>(
    poses: &[Pose<T>],
    params: &[T],
    velocities: &[KeyVelocity<T>],
) -> Result<Vec<MinimalMotion<T>>, JuttlerError> {
    check_spline_parameters(poses.len(), params)?;
    if velocities.len() != poses.len() {
        let why = format!("{} velocities for {} positions", velocities.len(), poses.len());
        return Err(JuttlerError::Parameters { why });
    }
    let parts = aligned_parts(poses)?;
    (0..poses.len() - 1)
        .map(|i| {
            let dt = params[i + 1].sub_ref(&params[i]);
            let ((r0, s0), (r1, s1)) = (&parts[i], &parts[i + 1]);
            let (v0, v1) = (&velocities[i], &velocities[i + 1]);
            let sixth = dt.mul_ref(&T::from_ratio(1, 6));
            let turn = |r: &Quaternion<T>, w: &[T; 3], sign: i64| {
                combine(r, &(&Quaternion::pure(w) * r), &sixth.mul_ref(&T::from_i64(sign)))
            };
            let d = vec![r0.clone(), turn(r0, &v0.angular_velocity, 1), turn(r1, &v1.angular_velocity, -1), r1.clone()];
            // N = |D|² and dN/du at the ends (D' = 3 (C_1 - C_0), 3 (C_3 - C_2))
            let six = T::from_i64(6);
            let (n0, n1) = (r0.norm_squared(), r1.norm_squared());
            let minus = T::one().neg_ref();
            let dn0 = six.mul_ref(&r0.dot(&combine(&d[1], &d[0], &minus)));
            let dn1 = six.mul_ref(&r1.dot(&combine(&d[3], &d[2], &minus)));
            // w = N s, w' = N' s + N Δt v at the ends; the cubic Hermite in Bernstein form
            let third = T::from_ratio(1, 3);
            let end = |n: &T, dn: &T, s: &[T; 3], v: &[T; 3], sign: i64| -> ([T; 3], [T; 3]) {
                let w: [T; 3] = std::array::from_fn(|k| n.mul_ref(&s[k]));
                let dw: [T; 3] = std::array::from_fn(|k| dn.mul_ref(&s[k]).add_ref(&n.mul_ref(&dt).mul_ref(&v[k])));
                let inner = std::array::from_fn(|k| w[k].add_ref(&dw[k].mul_ref(&third).mul_ref(&T::from_i64(sign))));
                (w, inner)
            };
            let (a0, a1) = end(&n0, &dn0, s0, &v0.velocity, 1);
            let (b3, b2) = end(&n1, &dn1, s1, &v1.velocity, -1);
            let mut w = vec![a0, a1, b2, b3];
            while w.len() < 7 {
                w = elevate_with(&w, |a: &[T; 3], s: &T, b: &[T; 3], t: &T| {
                    std::array::from_fn(|k| a[k].mul_ref(s).add_ref(&b[k].mul_ref(t)))
                });
            }
            MinimalMotion::new(vec![T::one()], w, d)
        })
        .collect()
}

/// `a + c b`.
fn combine<T: Field>(a: &Quaternion<T>, b: &Quaternion<T>, c: &T) -> Quaternion<T> {
    let f = |x: &T, y: &T| x.add_ref(&y.mul_ref(c));
    Quaternion::new(f(&a.w, &b.w), f(&a.x, &b.x), f(&a.y, &b.y), f(&a.z, &b.z))
}
