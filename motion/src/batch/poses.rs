//! [`Poses`]: many poses as eight coefficient columns, in the paper's order (eq. 4).

use super::columns::{Columns, Packed, run};
use super::{BatchError, Lanes};
use crate::Pose;
use algebra_core::scalar::LaneReal;
use algebra_core::{Field, Ring};

/// Poses (or other even elements of G_{123inf}^+: `dS/dt`, `Ψ`) in structure-of-arrays form:
/// eight columns in the paper's order `[S∅, S12, S13, S23, S1∞, S2∞, S3∞, Sω]` (eq. 4), every
/// coefficient finite (checked on construction).
///
/// ```
/// use motion::{Pose, batch::Poses};
/// let p = Poses::from_poses(&[Pose::identity(), Pose::translation(&[2.0, 0.0, 0.0])]).unwrap();
/// assert_eq!(p.column(4), &[0.0, 1.0]); // S1∞
/// assert_eq!(p.get(1), Some(Pose::translation(&[2.0, 0.0, 0.0])));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Poses<T> {
    pub(crate) cols: Columns<T, 8>,
}

impl<T: Ring> Poses<T> {
    /// The poses of a slice (array of structures). Fails for a non-finite coefficient.
    ///
    /// ```
    /// use motion::{Pose, batch::Poses};
    /// assert_eq!(Poses::from_poses(&[Pose::<f64>::identity(); 3]).unwrap().len(), 3);
    /// assert!(Poses::from_poses(&[Pose::translation(&[f64::NAN, 0.0, 0.0])]).is_err());
    /// ```
    pub fn from_poses(poses: &[Pose<T>]) -> Result<Self, BatchError> {
        Self::checked(Columns::from_rows(poses.iter().map(Pose::to_array)))
    }

    /// The poses with coefficient columns `columns[k]` in the paper's order. Fails when the
    /// columns differ in length or a coefficient is not finite.
    ///
    /// ```
    /// let mut cols: [Vec<f64>; 8] = Default::default();
    /// cols[0] = vec![1.0, 2.0];
    /// for c in &mut cols[1..] { *c = vec![0.0, 0.0]; }
    /// let p = motion::batch::Poses::from_columns(cols).unwrap();
    /// assert_eq!(p.get(1), Some(motion::Pose::identity().scale(&2.0)));
    /// ```
    pub fn from_columns(columns: [Vec<T>; 8]) -> Result<Self, BatchError> {
        if let Some((c, got)) = super::columns::first_mismatch(&columns, columns[0].len()) {
            let what =
                ["column 0", "column 1", "column 2", "column 3", "column 4", "column 5", "column 6", "column 7"][c];
            return Err(BatchError::LengthMismatch { what, expected: columns[0].len(), got });
        }
        Self::checked(Columns { cols: columns })
    }

    fn checked(cols: Columns<T, 8>) -> Result<Self, BatchError> {
        cols.check_finite("pose", |c| Pose::from_array(c).to_string())?;
        Ok(Poses { cols })
    }

    /// The number of poses.
    ///
    /// ```
    /// assert_eq!(motion::batch::Poses::from_poses(&[motion::Pose::<f64>::identity()]).unwrap().len(), 1);
    /// ```
    pub fn len(&self) -> usize {
        self.cols.len()
    }

    /// True when there are no poses.
    ///
    /// ```
    /// assert!(motion::batch::Poses::<f64>::from_poses(&[]).unwrap().is_empty());
    /// ```
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Coefficient column `k` (0 = `S∅`, ..., 7 = `Sω`).
    ///
    /// ```
    /// let p = motion::batch::Poses::from_poses(&[motion::Pose::<f64>::identity()]).unwrap();
    /// assert_eq!((p.column(0), p.column(7)), (&[1.0][..], &[0.0][..]));
    /// ```
    pub fn column(&self, k: usize) -> &[T] {
        &self.cols.cols[k]
    }

    /// Pose `i`, `None` past the end.
    ///
    /// ```
    /// let p = motion::batch::Poses::from_poses(&[motion::Pose::<f64>::identity()]).unwrap();
    /// assert_eq!((p.get(0), p.get(1)), (Some(motion::Pose::identity()), None));
    /// ```
    pub fn get(&self, i: usize) -> Option<Pose<T>> {
        self.cols.row(i).map(Pose::from_array)
    }

    /// Every pose (array of structures).
    ///
    /// ```
    /// let v = vec![motion::Pose::translation(&[1.0, 2.0, 3.0]); 2];
    /// assert_eq!(motion::batch::Poses::from_poses(&v).unwrap().to_vec(), v);
    /// ```
    pub fn to_vec(&self) -> Vec<Pose<T>> {
        (0..self.len()).filter_map(|i| self.get(i)).collect()
    }

    pub(crate) fn zeros(n: usize) -> Self {
        Poses { cols: Columns::filled(n, &Pose::zero().into_array()) }
    }

    fn same_length(&self, other: usize, what: &'static str) -> Result<(), BatchError> {
        if other == self.len() {
            Ok(())
        } else {
            Err(BatchError::LengthMismatch { what, expected: self.len(), got: other })
        }
    }

    /// The columns of `self` then `other`: the 16 inputs of a pairwise kernel.
    fn pair_views<'a>(&'a self, other: &'a Self) -> [&'a [T]; 16] {
        let (a, b) = (self.cols.views(), other.cols.views());
        std::array::from_fn(|c| if c < 8 { a[c] } else { b[c - 8] })
    }
}

/// A pose from eight lane values in the paper's order.
fn pose_of<L: Ring>(c: &[L]) -> Pose<L> {
    Pose::from_array(std::array::from_fn(|k| c[k].clone()))
}

/// The padding rows of a pairwise kernel: two identities.
fn identity_pair<T: Ring>() -> [T; 16] {
    std::array::from_fn(|c| if c % 8 == 0 { T::one() } else { T::zero() })
}

impl<T: Field + Send + Sync> Poses<T> {
    /// The columns packed into chunks of `L::WIDTH` poses (the last chunk padded with the
    /// identity); [`Packed::unpack_poses`] reverses it exactly.
    ///
    /// ```
    /// let p = motion::batch::Poses::from_poses(&[motion::Pose::translation(&[1.0, 2.0, 3.0])]).unwrap();
    /// assert_eq!(p.pack::<f64>().unpack_poses(), p);
    /// ```
    pub fn pack<L: Lanes<Elem = T>>(&self) -> Packed<L, 8> {
        Packed::pack(self.cols.views(), &Pose::one().into_array())
    }

    /// The products `self[i] * other[i]` (the generated G_{123inf} product: `self[i]` applied
    /// first, Lemma 2.3), over the lane type `L` (`L = T`: the scalar loop); bit for bit
    /// `&self[i] * &other[i]`. Fails when the lengths differ.
    ///
    /// ```
    /// use motion::{Pose, batch::Poses};
    /// let a = Poses::from_poses(&[Pose::translation(&[1.0, 0.0, 0.0])]).unwrap();
    /// let b = Poses::from_poses(&[Pose::translation(&[0.0, 2.0, 0.0])]).unwrap();
    /// assert_eq!(a.compose::<f64>(&b).unwrap().get(0), Some(Pose::translation(&[1.0, 2.0, 0.0])));
    /// ```
    pub fn compose<L: Lanes<Elem = T>>(&self, other: &Self) -> Result<Self, BatchError> {
        self.compose_with::<L>(other, false)
    }

    /// [`Poses::compose`] over every core (rayon); bit for bit the serial result.
    ///
    /// ```
    /// use motion::{Pose, batch::Poses};
    /// let a = Poses::from_poses(&vec![Pose::rotation(&[0.0, 0.0, 1.0], &0.5).unwrap(); 9000]).unwrap();
    /// assert_eq!(a.par_compose::<f64>(&a).unwrap(), a.compose::<f64>(&a).unwrap());
    /// ```
    #[cfg(feature = "parallel")]
    pub fn par_compose<L: Lanes<Elem = T>>(&self, other: &Self) -> Result<Self, BatchError> {
        self.compose_with::<L>(other, true)
    }

    fn compose_with<L: Lanes<Elem = T>>(&self, other: &Self, parallel: bool) -> Result<Self, BatchError> {
        self.same_length(other.len(), "second batch of poses")?;
        let mut out = Poses::zeros(self.len());
        let f = |c: [L; 16]| Ok((pose_of(&c[..8]) * pose_of(&c[8..])).into_array());
        run(parallel, self.pair_views(other), &identity_pair(), out.cols.views_mut(), &f, |_| unreachable!())?;
        Ok(out)
    }

    /// The additive interpolations `(1 - t) self[i] + t other[i]` (eq. 17, [`Pose::lerp`]) at
    /// one `t`, over the lane type `L`; bit for bit [`Pose::lerp`]. Fails when the lengths
    /// differ or `t` is not finite.
    ///
    /// ```
    /// use motion::{Pose, batch::Poses};
    /// let a = Poses::from_poses(&[Pose::identity()]).unwrap();
    /// let b = Poses::from_poses(&[Pose::translation(&[4.0, 0.0, 0.0])]).unwrap();
    /// assert_eq!(a.lerp::<f64>(&b, &0.25).unwrap().get(0), Some(Pose::translation(&[1.0, 0.0, 0.0])));
    /// ```
    pub fn lerp<L: Lanes<Elem = T>>(&self, other: &Self, t: &T) -> Result<Self, BatchError> {
        self.lerp_with::<L>(other, t, false)
    }

    /// [`Poses::lerp`] over every core (rayon); bit for bit the serial result.
    ///
    /// ```
    /// use motion::{Pose, batch::Poses};
    /// let a = Poses::from_poses(&vec![Pose::translation(&[1.0, 2.0, 3.0]); 9000]).unwrap();
    /// let b = Poses::from_poses(&vec![Pose::rotation(&[0.0, 1.0, 0.0], &1.0).unwrap(); 9000]).unwrap();
    /// assert_eq!(a.par_lerp::<f64>(&b, &0.3).unwrap(), a.lerp::<f64>(&b, &0.3).unwrap());
    /// ```
    #[cfg(feature = "parallel")]
    pub fn par_lerp<L: Lanes<Elem = T>>(&self, other: &Self, t: &T) -> Result<Self, BatchError> {
        self.lerp_with::<L>(other, t, true)
    }

    fn lerp_with<L: Lanes<Elem = T>>(&self, other: &Self, t: &T, parallel: bool) -> Result<Self, BatchError> {
        self.same_length(other.len(), "second batch of poses")?;
        if !t.is_finite_value() {
            return Err(BatchError::NotFinite { what: "parameter", index: 0, value: t.to_string() });
        }
        let t = L::splat(t);
        let mut out = Poses::zeros(self.len());
        let f = |c: [L; 16]| Ok(Pose::lerp(&pose_of(&c[..8]), &pose_of(&c[8..]), &t).into_array());
        run(parallel, self.pair_views(other), &identity_pair(), out.cols.views_mut(), &f, |_| unreachable!())?;
        Ok(out)
    }

    /// `F_{S_i}(p_i)`: pose `i` on point `i` ([`Pose::transform_point`] per element), over the
    /// lane type `L`; bit for bit the scalar results. Fails when the lengths differ, or with the
    /// index of the first singular pose.
    ///
    /// ```
    /// use motion::{Pose, batch::{Points, Poses}};
    /// let s = Poses::from_poses(&[Pose::translation(&[1.0, 0.0, 0.0]), Pose::rotation(&[0.0, 0.0, 1.0], &1.0).unwrap()]).unwrap();
    /// let p = Points::from_points(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]).unwrap();
    /// let q = s.transform_points::<f64>(&p).unwrap();
    /// assert_eq!(q.get(0), Some([1.0, 0.0, 0.0]));
    /// assert_eq!(q.get(1).unwrap(), s.get(1).unwrap().transform_point(&[1.0, 0.0, 0.0]).unwrap());
    /// ```
    pub fn transform_points<L: Lanes<Elem = T>>(
        &self,
        points: &super::Points<T>,
    ) -> Result<super::Points<T>, BatchError> {
        self.transform_points_with::<L>(points, false)
    }

    /// [`Poses::transform_points`] over every core (rayon); bit for bit the serial result, and
    /// the same error (the first singular pose).
    ///
    /// ```
    /// use motion::{Pose, batch::{Points, Poses}};
    /// let s = Poses::from_poses(&vec![Pose::rotation(&[1.0, 0.0, 0.0], &2.0).unwrap(); 9000]).unwrap();
    /// let p = Points::from_points(&vec![[1.0, 2.0, 3.0]; 9000]).unwrap();
    /// assert_eq!(s.par_transform_points::<f64>(&p).unwrap(), s.transform_points::<f64>(&p).unwrap());
    /// ```
    #[cfg(feature = "parallel")]
    pub fn par_transform_points<L: Lanes<Elem = T>>(
        &self,
        points: &super::Points<T>,
    ) -> Result<super::Points<T>, BatchError> {
        self.transform_points_with::<L>(points, true)
    }

    fn transform_points_with<L: Lanes<Elem = T>>(
        &self,
        points: &super::Points<T>,
        parallel: bool,
    ) -> Result<super::Points<T>, BatchError> {
        self.same_length(points.len(), "points")?;
        let (s, p) = (self.cols.views(), points.cols.views());
        let inputs: [&[T]; 11] = std::array::from_fn(|c| if c < 8 { s[c] } else { p[c - 8] });
        let pad: [T; 11] = std::array::from_fn(|c| if c == 0 { T::one() } else { T::zero() });
        let mut out = super::Points { cols: Columns::filled(self.len(), &std::array::from_fn(|_| T::zero())) };
        let f = |c: [L; 11]| {
            let pose = pose_of(&c[..8]);
            let inv = pose.alpha().recip_lanes()?;
            Ok(pose.image_with(&[c[8].clone(), c[9].clone(), c[10].clone()], &inv))
        };
        let describe = |i: usize| {
            let pose = self.get(i).expect("a failing row exists");
            BatchError::Pose { index: i, source: pose.singular("transform_point") }
        };
        run(parallel, inputs, &pad, out.cols.views_mut(), &f, describe)?;
        Ok(out)
    }
}

impl<T: Field + Send + Sync> Poses<T> {
    /// The slerps `self[i] (rev(self[i]) other[i])^t` (eq. 15) over the lane type `L`, by the
    /// branch-free closed forms ([`Pose::slerp_branch_free`]: every edge case computed and
    /// chosen per lane), so SIMD lanes can mix zero angles, pure translations and generic
    /// poses. Agrees with [`Pose::slerp`] to rounding (1e-12 relative in the tests), not bit
    /// for bit. Fails when the lengths differ, `t` is not finite, or a slerp fails (with the
    /// index of the first failing element).
    ///
    /// ```
    /// use motion::{Pose, batch::Poses};
    /// let a = Poses::from_poses(&[Pose::identity(), Pose::translation(&[1.0, 0.0, 0.0])]).unwrap();
    /// let b = Poses::from_poses(&[Pose::rotation(&[0.0, 0.0, 1.0], &1.0).unwrap(), Pose::translation(&[3.0, 0.0, 0.0])]).unwrap();
    /// let m = a.slerp_lanes::<f64>(&b, &0.5).unwrap();
    /// assert!(m.get(0).unwrap().is_equivalent(&Pose::rotation(&[0.0, 0.0, 1.0], &0.5).unwrap(), &1e-15).unwrap());
    /// assert_eq!(m.get(1), Some(Pose::translation(&[2.0, 0.0, 0.0])));
    /// ```
    pub fn slerp_lanes<L: Lanes<Elem = T> + LaneReal>(&self, other: &Self, t: &T) -> Result<Self, BatchError>
    where
        T: LaneReal,
    {
        self.slerp_lanes_with::<L>(other, t, false)
    }

    /// [`Poses::slerp_lanes`] over every core (rayon); bit for bit the serial result.
    ///
    /// ```
    /// use motion::{Pose, batch::Poses};
    /// let a = Poses::from_poses(&vec![Pose::translation(&[1.0, 0.0, 0.0]); 9000]).unwrap();
    /// let b = Poses::from_poses(&vec![Pose::rotation(&[0.0, 0.0, 1.0], &1.0).unwrap(); 9000]).unwrap();
    /// assert_eq!(a.par_slerp_lanes::<f64>(&b, &0.3).unwrap(), a.slerp_lanes::<f64>(&b, &0.3).unwrap());
    /// ```
    #[cfg(feature = "parallel")]
    pub fn par_slerp_lanes<L: Lanes<Elem = T> + LaneReal>(&self, other: &Self, t: &T) -> Result<Self, BatchError>
    where
        T: LaneReal,
    {
        self.slerp_lanes_with::<L>(other, t, true)
    }

    fn slerp_lanes_with<L: Lanes<Elem = T> + LaneReal>(
        &self,
        other: &Self,
        t: &T,
        parallel: bool,
    ) -> Result<Self, BatchError>
    where
        T: LaneReal,
    {
        self.same_length(other.len(), "second batch of poses")?;
        if !t.is_finite_value() {
            return Err(BatchError::NotFinite { what: "parameter", index: 0, value: t.to_string() });
        }
        let tl = L::splat(t);
        let mut out = Poses::zeros(self.len());
        // A failing chunk fails as a whole; `describe` finds the element with the scalar code.
        let f = |c: [L; 16]| {
            Pose::slerp_branch_free(&pose_of(&c[..8]), &pose_of(&c[8..]), &tl).map(Pose::into_array).map_err(|_| 0)
        };
        let describe = |start: usize| {
            (start..self.len())
                .find_map(|i| {
                    let (a, b) = (self.get(i)?, other.get(i)?);
                    Pose::slerp_branch_free(&a, &b, t).err().map(|source| BatchError::Pose { index: i, source })
                })
                .unwrap_or(BatchError::NotFinite { what: "slerp of the chunk at", index: start, value: t.to_string() })
        };
        run(parallel, self.pair_views(other), &identity_pair(), out.cols.views_mut(), &f, describe)?;
        Ok(out)
    }
}

impl<T: algebra_core::Real + Lanes<Elem = T>> Poses<T> {
    /// The slerps `self[i] (rev(self[i]) other[i])^t` (eq. 15, [`Pose::slerp`]) at one `t`;
    /// bit for bit [`Pose::slerp`]. The slerp branches on values (zero angle, pure
    /// translation), so it runs over the scalar `T` only. Fails when the lengths differ, `t` is
    /// not finite, or a slerp fails (with the element's index).
    ///
    /// ```
    /// use motion::{Pose, batch::Poses};
    /// let a = Poses::from_poses(&[Pose::identity()]).unwrap();
    /// let b = Poses::from_poses(&[Pose::rotation(&[0.0, 0.0, 1.0], &1.0).unwrap()]).unwrap();
    /// let m = a.slerp(&b, &0.5).unwrap().get(0).unwrap();
    /// assert!(m.is_equivalent(&Pose::rotation(&[0.0, 0.0, 1.0], &0.5).unwrap(), &1e-15).unwrap());
    /// ```
    pub fn slerp(&self, other: &Self, t: &T) -> Result<Self, BatchError> {
        self.slerp_with(other, t, false)
    }

    /// [`Poses::slerp`] over every core (rayon); bit for bit the serial result.
    ///
    /// ```
    /// use motion::{Pose, batch::Poses};
    /// let a = Poses::from_poses(&vec![Pose::translation(&[1.0, 0.0, 0.0]); 9000]).unwrap();
    /// let b = Poses::from_poses(&vec![Pose::rotation(&[0.0, 0.0, 1.0], &1.0).unwrap(); 9000]).unwrap();
    /// assert_eq!(a.par_slerp(&b, &0.3).unwrap(), a.slerp(&b, &0.3).unwrap());
    /// ```
    #[cfg(feature = "parallel")]
    pub fn par_slerp(&self, other: &Self, t: &T) -> Result<Self, BatchError> {
        self.slerp_with(other, t, true)
    }

    fn slerp_with(&self, other: &Self, t: &T, parallel: bool) -> Result<Self, BatchError> {
        self.same_length(other.len(), "second batch of poses")?;
        if !t.is_finite_value() {
            return Err(BatchError::NotFinite { what: "parameter", index: 0, value: t.to_string() });
        }
        let mut out = Poses::zeros(self.len());
        let f = |c: [T; 16]| Pose::slerp(&pose_of(&c[..8]), &pose_of(&c[8..]), t).map(Pose::into_array).map_err(|_| 0);
        let describe = |i: usize| {
            let (a, b) = (self.get(i).expect("row exists"), other.get(i).expect("row exists"));
            let source = Pose::slerp(&a, &b, t).expect_err("failed in the kernel");
            BatchError::Pose { index: i, source }
        };
        run::<T, 16, 8>(parallel, self.pair_views(other), &identity_pair(), out.cols.views_mut(), &f, describe)?;
        Ok(out)
    }
}

impl<L: Lanes> Packed<L, 8> {
    /// The poses again, without the padding.
    ///
    /// ```
    /// let p = motion::batch::Poses::from_poses(&[motion::Pose::translation(&[1.0, 2.0, 3.0]); 3]).unwrap();
    /// assert_eq!(p.pack::<f64>().unpack_poses(), p);
    /// ```
    pub fn unpack_poses(&self) -> Poses<L::Elem> {
        Poses { cols: self.unpack(&Pose::one().into_array()) }
    }
}
