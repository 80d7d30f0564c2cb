//! Hexanions from poses and from matrices.
//!
//! * [`Hexanion::from_pose`]: the principal logarithm `2 log(±S)` of the main paper's pose
//!   (`motion::exp_log`, the sign of `S` with non-negative scalar part), so `|ω| ∈ [0, π]`; at
//!   `|ω| = π` the sign of `S` as given picks `±ω` (both are the same motion).
//! * [`Hexanion::from_matrix`]: the same through [`Pose::from_matrix`].
//! * [`Hexanion::from_matrix_sec6`]: Angelidis' own algorithm of Sec. 6 (eqs. 43-53), as
//!   printed, with these choices where the paper leaves one open: of the three cases of (47)
//!   and (50) the one with the **largest** denominator `1 ± x_x ± y_y ± z_z` is taken (the
//!   paper takes any non-zero one); `v` in (53) is the basis vector least aligned with `n`;
//!   the branch of (52) is the principal one, `θ ∈ [0, π]` (`θ < 0` from `atan2` is turned
//!   into `-θ` with `n ↦ -n`). When all three denominators vanish exactly (no rotation) the
//!   result is the translation `<0, o>`. The denominators are `2(1 - cos θ) n_k²`, so the
//!   algorithm loses about `ε/θ²` relative accuracy at small angles (prefer `from_matrix`).
//!
//! ```
//! use motion::repr::hexanion::Hexanion;
//! let m = [[0.0f64, -1.0, 0.0, 1.0], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 2.0], [0.0, 0.0, 0.0, 1.0]];
//! let a = Hexanion::from_matrix(&m, &1e-12).unwrap();
//! let b = Hexanion::from_matrix_sec6(&m, &1e-12).unwrap();
//! assert!(a.omega.iter().chain(&a.m).zip(b.omega.iter().chain(&b.m)).all(|(x, y)| (x - y).abs() < 1e-15));
//! ```

use super::Hexanion;
use crate::repr::vec3::{cross, dot, norm, scale, sub};
use crate::{Matrix4, MotionError, Pose};
use algebra_core::Real;

impl<T: Real> Hexanion<T> {
    /// The principal hexanion of a pose (module docs): `exp(from_pose(S))` is the motion of `S`
    /// and `|ω| ≤ π`. Non-unit poses give the hexanion of their unitization. Fails for singular
    /// or non-finite poses.
    ///
    /// ```
    /// use motion::{Pose, repr::hexanion::Hexanion};
    /// let s = Pose::<f64>::from_axis_angle_translation(&[0.0, 0.0, 1.0], &0.5, &[0.0, 0.0, 2.0]).unwrap();
    /// let h = Hexanion::from_pose(&s).unwrap();
    /// assert!((h.omega[2] - 0.5).abs() < 1e-15 && (h.m[2] - 2.0).abs() < 1e-15);
    /// ```
    pub fn from_pose(s: &Pose<T>) -> Result<Self, MotionError> {
        // the log is an even element (the same generated type as the pose)
        let l = (s.log_shortest()?).to_array();
        let two = T::from_i64(2);
        let [_, b12, b13, b23, c1, c2, c3, _] = l;
        Ok(Hexanion::new(scale(&two, &[b23, b13.neg_ref(), b12]), scale(&two, &[c1, c2, c3])))
    }

    /// The principal hexanion of a rigid 4x4 matrix, through [`Pose::from_matrix`] (same
    /// checks and tolerance) and [`Hexanion::from_pose`].
    ///
    /// ```
    /// use motion::repr::hexanion::Hexanion;
    /// let id = [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];
    /// assert_eq!(Hexanion::from_matrix(&id, &1e-12).unwrap(), Hexanion::zero());
    /// ```
    pub fn from_matrix(m: &Matrix4<T>, tol: &T) -> Result<Self, MotionError> {
        Hexanion::from_pose(&Pose::from_matrix(m, tol)?)
    }

    /// Angelidis' matrix -> hexanion conversion of Sec. 6 (module docs for the choices): the
    /// matrix is first checked to be rigid within `tol` as by [`Pose::from_matrix`].
    ///
    /// ```
    /// use motion::repr::hexanion::Hexanion;
    /// let h = Hexanion::new([0.0f64, 0.0, 2.0], [2.0, 0.0, 3.0]);
    /// let back = Hexanion::from_matrix_sec6(&h.exp_matrix(), &1e-12).unwrap();
    /// assert!(h.omega.iter().chain(&h.m).zip(back.omega.iter().chain(&back.m)).all(|(x, y)| (x - y).abs() < 1e-14));
    /// ```
    pub fn from_matrix_sec6(mat: &Matrix4<T>, tol: &T) -> Result<Self, MotionError> {
        Pose::from_matrix(mat, tol)?;
        let e = |i: usize, j: usize| mat[i][j].clone();
        let col = |j: usize| [e(0, j), e(1, j), e(2, j)];
        let (x, y, z, o) = (col(0), col(1), col(2), col(3));
        let one = T::one();
        // the denominators of (47) and (50)
        let den = [
            one.add_ref(&x[0]).sub_ref(&y[1]).sub_ref(&z[2]),
            one.sub_ref(&x[0]).add_ref(&y[1]).sub_ref(&z[2]),
            one.sub_ref(&x[0]).sub_ref(&y[1]).add_ref(&z[2]),
        ];
        let k = (1..3).fold(0, |k, i| if den[i] > den[k] { i } else { k });
        if den[k] <= T::zero() {
            return Ok(Hexanion::new(crate::repr::vec3::zero(), o));
        }
        // (47): n0
        let n0 = match k {
            0 => [x[0].add_ref(&one).sub_ref(&y[1]).sub_ref(&z[2]), x[1].add_ref(&y[0]), x[2].add_ref(&z[0])],
            1 => [y[0].add_ref(&x[1]), y[1].add_ref(&one).sub_ref(&x[0]).sub_ref(&z[2]), y[2].add_ref(&z[1])],
            _ => [z[0].add_ref(&x[2]), z[1].add_ref(&y[2]), z[2].add_ref(&one).sub_ref(&x[0]).sub_ref(&y[1])],
        };
        let mut n = scale(&one.div_ref(&norm(&n0)), &n0); // (46)
        // (52)-(53): θ from a unit u ⊥ n
        let j = (1..3).fold(0, |j, i| if Real::abs(&n[i]) < Real::abs(&n[j]) { i } else { j });
        let v: [T; 3] = std::array::from_fn(|i| if i == j { T::one() } else { T::zero() });
        let u0 = sub(&v, &scale(&dot(&v, &n), &n));
        let u = scale(&one.div_ref(&norm(&u0)), &u0);
        let mu: [T; 3] =
            std::array::from_fn(|i| x[i].mul_ref(&u[0]).add_ref(&y[i].mul_ref(&u[1])).add_ref(&z[i].mul_ref(&u[2])));
        let mut theta = Real::atan2(&dot(&cross(&n, &u), &mu), &dot(&u, &mu));
        if theta < T::zero() {
            theta = theta.neg_ref();
            n = n.map(|c| c.neg_ref());
        }
        let t = dot(&o, &n); // (49)
        let s = sub(&o, &scale(&t, &n)); // (51)
        let inv = one.div_ref(&den[k]);
        let c = match k {
            // (50)
            0 => [
                T::zero(),
                s[2].mul_ref(&z[1]).add_ref(&s[1].mul_ref(&one.sub_ref(&z[2]))),
                s[1].mul_ref(&y[2]).add_ref(&s[2].mul_ref(&one.sub_ref(&y[1]))),
            ],
            1 => [
                s[2].mul_ref(&z[0]).add_ref(&s[0].mul_ref(&one.sub_ref(&z[2]))),
                T::zero(),
                s[0].mul_ref(&x[2]).add_ref(&s[2].mul_ref(&one.sub_ref(&x[0]))),
            ],
            _ => [
                s[1].mul_ref(&y[0]).add_ref(&s[0].mul_ref(&one.sub_ref(&y[1]))),
                s[0].mul_ref(&x[1]).add_ref(&s[1].mul_ref(&one.sub_ref(&x[0]))),
                T::zero(),
            ],
        };
        let c = scale(&inv, &c);
        Ok(Hexanion::twist(&c, &theta, &n, &t)) // (44)
    }
}
