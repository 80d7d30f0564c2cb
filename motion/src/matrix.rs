//! 4x4 homogeneous matrices, both ways.
//!
//! Matrices are row-major `[[T; 4]; 4]` acting on column vectors `[x, y, z, 1]`: a rigid
//! matrix is `[[R, v], [0, 1]]` with `R` a rotation and `F(p) = R p + v`. A pose gives
//! `[[A, t], [0, α]]` from eqs. (6)-(9) (see [`crate::action`]), exact and projective, or that
//! divided by `α`, rigid. Going back, the rotation becomes a unit rotor (Shepperd's method,
//! stable for every angle) and the pose is `S = R T` with `T = 1 + ½ v einf`.
//!
//! ```
//! use motion::Pose;
//! let s = Pose::from_axis_angle_translation(&[1.0, 1.0, 0.0], &2.0, &[1.0, 2.0, 3.0]).unwrap();
//! let m = s.to_matrix().unwrap();
//! let back = Pose::from_matrix(&m, &1e-12).unwrap();
//! assert!(back.is_equivalent(&s, &1e-14).unwrap());
//! ```

use crate::pose::{check_finite_scalar, is_positive};
use crate::{MotionError, Pose};
use algebra_core::{Field, Real, Ring};

/// A row-major 4x4 matrix acting on column vectors `[x, y, z, w]`.
///
/// ```
/// let m: motion::Matrix4<f64> = motion::Pose::identity().to_matrix().unwrap();
/// assert_eq!(m[3], [0.0, 0.0, 0.0, 1.0]);
/// ```
pub type Matrix4<T> = [[T; 4]; 4];

impl<T: Ring> Pose<T> {
    /// The projective matrix `[[A, t], [0, α]]` of `F_S` (eqs. 6-9), without division: exact
    /// over exact scalars, and `to_homogeneous_matrix(UV) = to_homogeneous_matrix(V) ·
    /// to_homogeneous_matrix(U)` (Lemma 2.3).
    ///
    /// ```
    /// let m = motion::Pose::translation(&[1.0, 2.0, 3.0]).scale(&2.0).to_homogeneous_matrix();
    /// assert_eq!(m[0], [4.0, 0.0, 0.0, 4.0]);
    /// assert_eq!(m[3], [0.0, 0.0, 0.0, 4.0]);
    /// ```
    pub fn to_homogeneous_matrix(&self) -> Matrix4<T> {
        let ([r0, r1, r2], alpha) = self.action_rows();
        [r0, r1, r2, [T::zero(), T::zero(), T::zero(), alpha]]
    }
}

impl<T: Field> Pose<T> {
    /// The rigid matrix `[[A/α, t/α], [0, 1]]` of `F_S`. Fails for singular `S`.
    ///
    /// ```
    /// let m = motion::Pose::translation(&[1.0, 2.0, 3.0]).scale(&2.0).to_matrix().unwrap();
    /// assert_eq!(m[0], [1.0, 0.0, 0.0, 1.0]);
    /// assert_eq!(m[2], [0.0, 0.0, 1.0, 3.0]);
    /// ```
    pub fn to_matrix(&self) -> Result<Matrix4<T>, MotionError> {
        crate::scaled::require_finite("to_matrix", self, [])?;
        if let Some((_, s)) = crate::scaled::unusual_scale(self) {
            // the matrix does not depend on the scale of S: computed from S/2^e
            return s.to_matrix();
        }
        let (rows, alpha) = self.action_rows();
        let inv = alpha.try_recip().ok_or_else(|| self.singular("to_matrix"))?;
        let [r0, r1, r2] = rows.map(|r| r.map(|x| x.mul_ref(&inv)));
        if ![&r0, &r1, &r2].into_iter().flatten().all(Ring::is_finite_value) {
            return Err(self.overflow("to_matrix"));
        }
        Ok([r0, r1, r2, [T::zero(), T::zero(), T::zero(), T::one()]])
    }
}

impl<T: Real> Pose<T> {
    /// The unit pose `S = R T` of a rigid matrix `[[R, v], [0, 1]]`: fails with
    /// [`MotionError::BadTolerance`] unless `tol` is finite and non-negative, with
    /// [`MotionError::NotRigid`] unless the bottom row is `[0, 0, 0, 1]`, `RᵀR = I` (each entry)
    /// within `tol`, and `det R > 0`. Of the two unit poses `±S` the one with non-negative
    /// scalar part is returned.
    ///
    /// ```
    /// let m = [[0.0f64, -1.0, 0.0, 1.0], [1.0, 0.0, 0.0, 2.0], [0.0, 0.0, 1.0, 3.0], [0.0, 0.0, 0.0, 1.0]];
    /// let s = motion::Pose::from_matrix(&m, &1e-12).unwrap();
    /// let p = s.transform_point(&[1.0, 0.0, 0.0]).unwrap(); // quarter turn about e3, then (1, 2, 3)
    /// assert!((p[0] - 1.0).abs() < 1e-15 && (p[1] - 3.0).abs() < 1e-15 && (p[2] - 3.0).abs() < 1e-15);
    /// let mut shear = m;
    /// shear[0][1] = -1.5;
    /// assert!(motion::Pose::from_matrix(&shear, &1e-12).is_err());
    /// assert!(matches!(motion::Pose::from_matrix(&shear, &f64::INFINITY), Err(motion::MotionError::BadTolerance { .. })));
    /// ```
    pub fn from_matrix(m: &Matrix4<T>, tol: &T) -> Result<Self, MotionError> {
        for x in m.iter().flatten() {
            check_finite_scalar("from_matrix", x)?;
        }
        // not (tol >= 0) also catches NaN
        if !(Real::is_finite(tol) && *tol >= T::zero()) {
            return Err(MotionError::BadTolerance { op: "from_matrix", value: tol.to_string() });
        }
        let not_rigid = |why: String| MotionError::NotRigid { why };
        let close = |x: &T, y: &T| Real::abs(&x.sub_ref(y)) <= *tol;
        let bottom = [T::zero(), T::zero(), T::zero(), T::one()];
        if !m[3].iter().zip(&bottom).all(|(x, y)| close(x, y)) {
            return Err(not_rigid(format!(
                "the bottom row is [{}, {}, {}, {}], not [0, 0, 0, 1]",
                m[3][0], m[3][1], m[3][2], m[3][3]
            )));
        }
        for i in 0..3 {
            for j in 0..3 {
                let dot = m[0][i].mul_ref(&m[0][j]) + m[1][i].mul_ref(&m[1][j]) + m[2][i].mul_ref(&m[2][j]);
                let delta = if i == j { T::one() } else { T::zero() };
                if !close(&dot, &delta) {
                    return Err(not_rigid(format!("columns {i} and {j} of the 3x3 part have dot product {dot}")));
                }
            }
        }
        let det = m[0][0].mul_ref(&m[1][1].mul_ref(&m[2][2]).sub_ref(&m[1][2].mul_ref(&m[2][1])))
            - m[0][1].mul_ref(&m[1][0].mul_ref(&m[2][2]).sub_ref(&m[1][2].mul_ref(&m[2][0])))
            + m[0][2].mul_ref(&m[1][0].mul_ref(&m[2][1]).sub_ref(&m[1][1].mul_ref(&m[2][0])));
        if !is_positive(&det) {
            return Err(not_rigid(format!("the 3x3 part has determinant {det} (a reflection)")));
        }
        let rotor = rotor_from_rotation(m);
        let v = [m[0][3].clone(), m[1][3].clone(), m[2][3].clone()];
        Ok(rotor * Pose::translation(&v))
    }
}

/// The unit rotor `w + x e23 - y e13 + z e12` of the rotation in the upper-left 3x3 block
/// (quaternion `(w, x, y, z)` by Shepperd's method: divide by the largest of `4w², 4x², 4y²,
/// 4z²`), then normalised so rounding in `m` does not leave a non-unit rotor.
fn rotor_from_rotation<T: Real>(m: &Matrix4<T>) -> Pose<T> {
    let one = T::one();
    let quarter = T::from_ratio(1, 4);
    let (m00, m11, m22) = (&m[0][0], &m[1][1], &m[2][2]);
    // 4w² = 1 + tr, 4x² = 1 + m00 - m11 - m22, ...
    let four_sq = [
        one.add_ref(m00).add_ref(m11).add_ref(m22),
        one.add_ref(m00).sub_ref(m11).sub_ref(m22),
        one.sub_ref(m00).add_ref(m11).sub_ref(m22),
        one.sub_ref(m00).sub_ref(m11).add_ref(m22),
    ];
    let mut k = 0;
    for i in 1..4 {
        if four_sq[i] > four_sq[k] {
            k = i;
        }
    }
    let big = Real::sqrt(&four_sq[k]).mul_ref(&T::from_ratio(1, 2)); // the largest of |w|, |x|, |y|, |z|
    let inv = quarter.div_ref(&big); // 1/(4 big)
    let f = |x: T| x.mul_ref(&inv);
    let d = |a: &T, b: &T| f(a.sub_ref(b));
    let s = |a: &T, b: &T| f(a.add_ref(b));
    let (w, x, y, z) = match k {
        0 => (big, d(&m[2][1], &m[1][2]), d(&m[0][2], &m[2][0]), d(&m[1][0], &m[0][1])),
        1 => (d(&m[2][1], &m[1][2]), big, s(&m[0][1], &m[1][0]), s(&m[0][2], &m[2][0])),
        2 => (d(&m[0][2], &m[2][0]), s(&m[0][1], &m[1][0]), big, s(&m[1][2], &m[2][1])),
        _ => (d(&m[1][0], &m[0][1]), s(&m[0][2], &m[2][0]), s(&m[1][2], &m[2][1]), big),
    };
    let (w, x, y, z) = if w < T::zero() { (w.neg_ref(), x.neg_ref(), y.neg_ref(), z.neg_ref()) } else { (w, x, y, z) };
    let n = Real::sqrt(&(w.mul_ref(&w) + x.mul_ref(&x) + y.mul_ref(&y) + z.mul_ref(&z)));
    let inv_n = one.div_ref(&n);
    let [w, x, y, z] = [w, x, y, z].map(|c| c.mul_ref(&inv_n));
    Pose::rotor_from_parts(&w, &T::one(), &[x, y, z])
}
