//! [`Points`]: a point cloud as three columns `x, y, z`, and its transformation by one pose.

use super::columns::{Columns, Packed, run};
use super::{BatchError, Lanes};
use crate::Pose;
use algebra_core::{Field, Ring};

/// Points of R^3 in structure-of-arrays form: columns `x`, `y`, `z` of equal length, every
/// coordinate finite (checked on construction).
///
/// ```
/// use motion::batch::Points;
/// let p = Points::from_points(&[[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]).unwrap();
/// assert_eq!((p.len(), p.y()), (2, &[2.0, 5.0][..]));
/// assert_eq!(p.get(1), Some([4.0, 5.0, 6.0]));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Points<T> {
    pub(crate) cols: Columns<T, 3>,
}

const AXES: [&str; 3] = ["x column", "y column", "z column"];

impl<T: Ring> Points<T> {
    /// The points with coordinates `x[i], y[i], z[i]`. Fails when the columns differ in length
    /// or a coordinate is not finite.
    ///
    /// ```
    /// let p = motion::batch::Points::from_columns(vec![1.0, 2.0], vec![3.0, 4.0], vec![5.0, 6.0]).unwrap();
    /// assert_eq!(p.get(0), Some([1.0, 3.0, 5.0]));
    /// ```
    pub fn from_columns(x: Vec<T>, y: Vec<T>, z: Vec<T>) -> Result<Self, BatchError> {
        let cols = [x, y, z];
        if let Some((c, got)) = super::columns::first_mismatch(&cols, cols[0].len()) {
            return Err(BatchError::LengthMismatch { what: AXES[c], expected: cols[0].len(), got });
        }
        Self::checked(Columns { cols })
    }

    /// The points of a slice of `[x, y, z]` (an array of structures). Fails for a non-finite
    /// coordinate.
    ///
    /// ```
    /// let p = motion::batch::Points::from_points(&[[0.5, 0.0, 1.0]]).unwrap();
    /// assert_eq!(p.x(), &[0.5]);
    /// assert!(motion::batch::Points::from_points(&[[f64::INFINITY, 0.0, 0.0]]).is_err());
    /// ```
    pub fn from_points(points: &[[T; 3]]) -> Result<Self, BatchError> {
        Self::checked(Columns::from_rows(points.iter().cloned()))
    }

    fn checked(cols: Columns<T, 3>) -> Result<Self, BatchError> {
        cols.check_finite("point", |p| format!("{p:?}"))?;
        Ok(Points { cols })
    }

    /// The number of points.
    ///
    /// ```
    /// assert_eq!(motion::batch::Points::from_points(&[[0.0; 3]; 4]).unwrap().len(), 4);
    /// ```
    pub fn len(&self) -> usize {
        self.cols.len()
    }

    /// True when there are no points.
    ///
    /// ```
    /// assert!(motion::batch::Points::<f64>::from_points(&[]).unwrap().is_empty());
    /// ```
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The `x` coordinates.
    ///
    /// ```
    /// assert_eq!(motion::batch::Points::from_points(&[[1.0, 2.0, 3.0]]).unwrap().x(), &[1.0]);
    /// ```
    pub fn x(&self) -> &[T] {
        &self.cols.cols[0]
    }

    /// The `y` coordinates.
    ///
    /// ```
    /// assert_eq!(motion::batch::Points::from_points(&[[1.0, 2.0, 3.0]]).unwrap().y(), &[2.0]);
    /// ```
    pub fn y(&self) -> &[T] {
        &self.cols.cols[1]
    }

    /// The `z` coordinates.
    ///
    /// ```
    /// assert_eq!(motion::batch::Points::from_points(&[[1.0, 2.0, 3.0]]).unwrap().z(), &[3.0]);
    /// ```
    pub fn z(&self) -> &[T] {
        &self.cols.cols[2]
    }

    /// Point `i` as `[x, y, z]`, `None` past the end.
    ///
    /// ```
    /// let p = motion::batch::Points::from_points(&[[1.0, 2.0, 3.0]]).unwrap();
    /// assert_eq!((p.get(0), p.get(1)), (Some([1.0, 2.0, 3.0]), None));
    /// ```
    pub fn get(&self, i: usize) -> Option<[T; 3]> {
        self.cols.row(i)
    }

    /// Every point as `[x, y, z]` (array of structures).
    ///
    /// ```
    /// let pts = [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]];
    /// assert_eq!(motion::batch::Points::from_points(&pts).unwrap().to_vec(), pts);
    /// ```
    pub fn to_vec(&self) -> Vec<[T; 3]> {
        (0..self.len()).filter_map(|i| self.get(i)).collect()
    }
}

impl<T: Field + Send + Sync> Points<T> {
    /// The columns packed into chunks of `L::WIDTH` points (the last chunk padded with the
    /// origin); [`Packed::unpack_points`] reverses it exactly.
    ///
    /// ```
    /// let p = motion::batch::Points::from_points(&[[1.0f32, 2.0, 3.0]]).unwrap();
    /// assert_eq!(p.pack::<f32>().unpack_points(), p);
    /// ```
    pub fn pack<L: Lanes<Elem = T>>(&self) -> Packed<L, 3> {
        Packed::pack(self.cols.views(), &std::array::from_fn(|_| T::zero()))
    }

    /// `F_S(p)` for every point `p`, one pose `S` for all ([`Pose::transform_point`]), computed
    /// over the lane type `L`: `L = T` is the scalar loop, a SIMD lane type transforms
    /// `L::WIDTH` points per instruction. `1/α` is computed once, and each point takes the
    /// formula of [`Pose::transform_point`] (two cross products, 15 multiplications once the
    /// pose's own products are hoisted), in the same order, so every result is bit for bit the
    /// scalar one. Fails for a singular or non-finite pose.
    ///
    /// ```
    /// use motion::{Pose, batch::Points};
    /// let s = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &0.3, &[1.0, 2.0, 3.0]).unwrap();
    /// let p = Points::from_points(&[[1.0, 0.0, 0.0], [0.0, 1.0, 2.0]]).unwrap();
    /// let q = p.transform::<f64>(&s).unwrap();
    /// assert_eq!(q.get(1).unwrap(), s.transform_point(&[0.0, 1.0, 2.0]).unwrap());
    /// ```
    pub fn transform<L: Lanes<Elem = T>>(&self, pose: &Pose<T>) -> Result<Points<T>, BatchError> {
        self.transform_with::<L>(pose, false)
    }

    /// [`Points::transform`] with the points split into blocks over rayon's thread pool (every
    /// core); bit for bit the serial result.
    ///
    /// ```
    /// use motion::{Pose, batch::Points};
    /// let s = Pose::translation(&[1.0, 0.0, 0.0]);
    /// let p = Points::from_points(&vec![[1.0, 2.0, 3.0]; 10_000]).unwrap();
    /// assert_eq!(p.par_transform::<f64>(&s).unwrap(), p.transform::<f64>(&s).unwrap());
    /// ```
    #[cfg(feature = "parallel")]
    pub fn par_transform<L: Lanes<Elem = T>>(&self, pose: &Pose<T>) -> Result<Points<T>, BatchError> {
        self.transform_with::<L>(pose, true)
    }

    fn transform_with<L: Lanes<Elem = T>>(&self, pose: &Pose<T>, parallel: bool) -> Result<Points<T>, BatchError> {
        let pose_error = |source| BatchError::Pose { index: 0, source };
        crate::scaled::require_finite("transform_point", pose, []).map_err(pose_error)?;
        // Pose::transform_point's formula with the pose's values in every lane: bit for bit the
        // scalar loop (the pose's own products are hoisted out of the loop by the compiler)
        let inv = pose.alpha().try_recip().ok_or_else(|| pose_error(pose.singular("transform_point")))?;
        let lanes = Pose::<L>::from_array(std::array::from_fn(|k| L::splat(pose.components()[k])));
        let inv = L::splat(&inv);
        let f = move |p: [L; 3]| Ok(lanes.image_with(&p, &inv));
        let zero: [T; 3] = std::array::from_fn(|_| T::zero());
        let mut out = Points { cols: Columns::filled(self.len(), &zero) };
        run(parallel, self.cols.views(), &zero, out.cols.views_mut(), &f, |_| unreachable!("one pose, checked above"))?;
        Ok(out)
    }
}

impl<L: Lanes> Packed<L, 3> {
    /// The points again, without the padding.
    ///
    /// ```
    /// let p = motion::batch::Points::from_points(&[[1.0, 2.0, 3.0]; 3]).unwrap();
    /// assert_eq!(p.pack::<f64>().unpack_points(), p);
    /// ```
    pub fn unpack_points(&self) -> Points<L::Elem> {
        Points { cols: self.unpack(&std::array::from_fn(|_| L::Elem::zero())) }
    }
}
