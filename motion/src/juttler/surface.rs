//! The kinematic surface (surface of motion, sweeping surface) of Jüttler Sec. 5, Fig. 5b:
//! a rational Bézier curve `x(v)` of the moving space swept by a rational motion `M(t)`,
//! `y(t, v) = M(t) x(v)`, as a rational tensor-product Bézier surface of degree
//! `(deg_t, d)`: `deg_t` the motion's trajectory degree (`2n` for a Q-motion of degree `n`),
//! `d` the curve's degree.
//!
//! **Construction.** The homogeneous image of a homogeneous point `X = (w, v⃗)` is linear in
//! `X` ((12) for Q-motions, (6)-(9) of the main paper for additive ones), so the homogeneous
//! trajectory control points `H_k` are too: `H_k(w, v⃗) = (w - 1) H_k(0⃗) + H_k(v⃗)`, where
//! `H_k(x⃗)` are those of the trajectory of the affine point `x⃗` ([`RationalMotion`]). Column
//! `j` of the surface's control net is `H_k` at the curve's homogeneous control point
//! `(w_j, w_j p⃗_j)`: no division, exact over rationals, and control points at infinity
//! (`w_j = 0`) are fine.
//!
//! ```
//! use algebra_core::rational::{q, ratio};
//! use gam_algebras::DualQuaternion;
//! use motion::juttler::{QMotion, RationalBezier, surface::RationalBezierSurface};
//! // a quarter turn about z sweeping the segment from (1, 0, 0) to (1, 0, 1): a cylinder patch
//! let d = |c: [i64; 8]| DualQuaternion::from_coeffs(c.map(q));
//! let m = QMotion::new_exact(vec![d([1, 0, 0, 0, 0, 0, 0, 0]), d([1, 0, 0, 1, 0, 0, 0, 0])]).unwrap();
//! let x = RationalBezier::new(vec![[q(1), q(1), q(0), q(0)], [q(1), q(1), q(0), q(1)]]).unwrap();
//! let s = RationalBezierSurface::kinematic(&m, &x).unwrap();
//! assert_eq!(s.degrees(), (2, 1));
//! assert_eq!(s.point(&q(1), &ratio(1, 2)).unwrap(), [q(0), q(1), ratio(1, 2)]);
//! ```

use super::rational_trajectory::{affine, lerp4};
use super::{JuttlerError, RationalBezier, RationalMotion, de_casteljau_with};
use algebra_core::{Field, Ring};

/// A rational tensor-product Bézier surface in R³ on `[0, 1]²` by its homogeneous control
/// points `(w_kj, w_kj p_kj)`, weight first; row `k` along the first parameter `t`, column `j`
/// along the second `v`.
///
/// ```
/// use algebra_core::rational::{q, ratio};
/// use motion::juttler::surface::RationalBezierSurface;
/// // the bilinear patch (t, v, 0)
/// let s = RationalBezierSurface::new(vec![
///     vec![[q(1), q(0), q(0), q(0)], [q(1), q(0), q(1), q(0)]],
///     vec![[q(1), q(1), q(0), q(0)], [q(1), q(1), q(1), q(0)]],
/// ]).unwrap();
/// assert_eq!(s.point(&ratio(1, 3), &ratio(3, 4)).unwrap(), [ratio(1, 3), ratio(3, 4), q(0)]);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct RationalBezierSurface<T> {
    control: Vec<Vec<[T; 4]>>,
}

impl<T: Ring> RationalBezierSurface<T> {
    /// The surface with the control net `control` (rows of equal, non-zero length; at least
    /// one row); [`JuttlerError::TooFewPositions`] for an empty net, [`JuttlerError::Parameters`]
    /// for ragged rows.
    ///
    /// ```
    /// use motion::juttler::{JuttlerError, surface::RationalBezierSurface};
    /// let ragged = RationalBezierSurface::new(vec![vec![[1.0, 0.0, 0.0, 0.0]; 2], vec![[1.0, 0.0, 0.0, 0.0]]]);
    /// assert!(matches!(ragged, Err(JuttlerError::Parameters { .. })));
    /// assert!(RationalBezierSurface::<f64>::new(vec![]).is_err());
    /// ```
    pub fn new(control: Vec<Vec<[T; 4]>>) -> Result<Self, JuttlerError> {
        let cols = control.first().map_or(0, Vec::len);
        if cols == 0 {
            return Err(JuttlerError::TooFewPositions { need: 1, got: 0 });
        }
        if let Some(k) = control.iter().position(|r| r.len() != cols) {
            return Err(JuttlerError::Parameters {
                why: format!("control net row {k} has {} points, row 0 has {cols}", control[k].len()),
            });
        }
        Ok(RationalBezierSurface { control })
    }

    /// The kinematic surface `y(t, v) = M(t) x(v)` of the curve `x` under the motion `m`
    /// (module docs); fails where `m`'s trajectories fail. The motion's trajectory control
    /// points must be affine in the body point and of one degree for every point, as those of
    /// the product-formula constructions are (Q-motions, additive Bézier motions).
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio};
    /// use motion::{AdditiveBezier, Motion, Pose, juttler::{RationalBezier, surface::RationalBezierSurface}};
    /// let m = AdditiveBezier::new(vec![Pose::identity(), Pose::translation(&[q(0), q(0), q(2)])]).unwrap();
    /// let x = RationalBezier::new(vec![[q(1), q(0), q(0), q(0)], [q(1), q(1), q(0), q(0)]]).unwrap();
    /// let s = RationalBezierSurface::kinematic(&m, &x).unwrap();
    /// assert_eq!(s.point(&ratio(1, 2), &ratio(1, 4)).unwrap(), [ratio(1, 4), q(0), q(1)]);
    /// ```
    pub fn kinematic<M: RationalMotion<T> + ?Sized>(m: &M, x: &RationalBezier<T>) -> Result<Self, JuttlerError> {
        let origin = m.rational_trajectory(&[T::zero(), T::zero(), T::zero()])?;
        let columns = x
            .control()
            .iter()
            .map(|c| {
                let path = m.rational_trajectory(&[c[1].clone(), c[2].clone(), c[3].clone()])?;
                if path.degree() != origin.degree() {
                    return Err(JuttlerError::Parameters {
                        why: format!("trajectories of degree {} and {}", origin.degree(), path.degree()),
                    });
                }
                let w1 = c[0].sub_ref(&T::one());
                Ok(path
                    .control()
                    .iter()
                    .zip(origin.control())
                    .map(|(h, o)| std::array::from_fn(|k| h[k].add_ref(&o[k].mul_ref(&w1))))
                    .collect::<Vec<[T; 4]>>())
            })
            .collect::<Result<Vec<_>, JuttlerError>>()?;
        let rows = (0..=origin.degree()).map(|k| columns.iter().map(|c| c[k].clone()).collect()).collect();
        RationalBezierSurface::new(rows)
    }

    /// The homogeneous control net, row `k` along `t`.
    ///
    /// ```
    /// use motion::juttler::surface::RationalBezierSurface;
    /// let s = RationalBezierSurface::new(vec![vec![[1.0, 0.0, 0.0, 0.0]]]).unwrap();
    /// assert_eq!(s.control(), [vec![[1.0, 0.0, 0.0, 0.0]]]);
    /// ```
    pub fn control(&self) -> &[Vec<[T; 4]>] {
        &self.control
    }

    /// The degrees `(in t, in v)`.
    ///
    /// ```
    /// use motion::juttler::surface::RationalBezierSurface;
    /// let s = RationalBezierSurface::new(vec![vec![[1.0, 0.0, 0.0, 0.0]; 3]; 2]).unwrap();
    /// assert_eq!(s.degrees(), (1, 2));
    /// ```
    pub fn degrees(&self) -> (usize, usize) {
        (self.control.len() - 1, self.control[0].len() - 1)
    }

    /// The homogeneous point `(w, w y)` at `(t, v)` by de Casteljau in `v` along each row, then
    /// in `t`.
    ///
    /// ```
    /// use motion::juttler::surface::RationalBezierSurface;
    /// let s = RationalBezierSurface::new(vec![vec![[1.0, 0.0, 0.0, 0.0], [3.0, 3.0, 0.0, 0.0]]]).unwrap();
    /// assert_eq!(s.homogeneous(&0.0, &0.5), [2.0, 1.5, 0.0, 0.0]);
    /// ```
    pub fn homogeneous(&self, t: &T, v: &T) -> [T; 4] {
        let column: Vec<[T; 4]> = self.control.iter().map(|row| de_casteljau_with(row, v, lerp4)).collect();
        de_casteljau_with(&column, t, lerp4)
    }

    /// The curve `v ↦ y(t, v)` at a fixed `t` (a position of the swept curve), degree `d`.
    ///
    /// ```
    /// use motion::juttler::surface::RationalBezierSurface;
    /// let s = RationalBezierSurface::new(vec![vec![[1.0, 0.0, 0.0, 0.0]; 2], vec![[1.0, 1.0, 0.0, 0.0]; 2]]).unwrap();
    /// assert_eq!(s.curve_at(&0.5).unwrap().point(&0.3).unwrap(), [0.5, 0.0, 0.0]);
    /// ```
    pub fn curve_at(&self, t: &T) -> Result<RationalBezier<T>, JuttlerError> {
        let cols = self.control[0].len();
        let control = (0..cols)
            .map(|j| {
                let column: Vec<[T; 4]> = self.control.iter().map(|row| row[j].clone()).collect();
                de_casteljau_with(&column, t, lerp4)
            })
            .collect();
        RationalBezier::new(control)
    }
}

impl<T: Field> RationalBezierSurface<T> {
    /// The point `y(t, v)`; fails where the weight is zero.
    ///
    /// ```
    /// use motion::juttler::surface::RationalBezierSurface;
    /// let s = RationalBezierSurface::new(vec![vec![[1.0, 0.0, 0.0, 0.0], [-1.0, 0.0, 0.0, 0.0]]]).unwrap();
    /// assert!(s.point(&0.0, &0.5).is_err());
    /// ```
    pub fn point(&self, t: &T, v: &T) -> Result<[T; 3], JuttlerError> {
        affine(&self.homogeneous(t, v), || format!("(t, v) = ({t}, {v})"))
    }
}
