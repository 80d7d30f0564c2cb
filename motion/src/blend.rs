//! [`Blend`]: additive or multiplicative as a type parameter. A blend is the pairwise
//! combination `Φ(A, B; t)` of a de Casteljau or de Boor tableau (eq. 17 additive,
//! eq. 15 multiplicative) together with what the main paper derives from it: the control poses
//! next to the ends for given end indicatrices (eqs. 22-23) and the end indicatrices of a
//! segment (eqs. 20-21, Corollary 4.6). [`crate::Bezier`] and [`crate::BSpline`] take the blend
//! as a type parameter, so one type serves both kinds; [`Additive`] works over any [`Ring`]
//! (exact over rationals), [`Multiplicative`] needs a [`Real`].
//!
//! ```
//! use algebra_core::rational::{q, ratio, Q};
//! use motion::{Additive, Blend, Pose};
//! let a = Pose::<Q>::identity();
//! let b = Pose::translation(&[q(4), q(0), q(0)]);
//! assert_eq!(Additive::blend(&a, &b, &ratio(1, 4)).unwrap(), Pose::translation(&[q(1), q(0), q(0)]));
//! ```

use crate::joins::{self, JoinError, SegmentKind};
use crate::{Even, MotionError, Pose};
use algebra_core::{Field, Real, Ring};

/// The combination `Φ(A, B; t)` of a motion kind and the join rules that go with it (module
/// docs). Implemented by [`Additive`] and [`Multiplicative`]; the motion types are generic over
/// it ([`crate::Bezier`], [`crate::BSpline`]).
///
/// ```
/// use motion::{Additive, Blend, Multiplicative, SegmentKind};
/// assert_eq!(<Additive as Blend<f64>>::KIND, SegmentKind::Additive);
/// assert_eq!(<Multiplicative as Blend<f64>>::KIND, SegmentKind::Multiplicative);
/// ```
pub trait Blend<T: Ring>: Copy + std::fmt::Debug + PartialEq + Default + 'static {
    /// The runtime tag of this kind (for file formats and messages).
    const KIND: SegmentKind;

    /// `Φ(A, B; t)`: `(1 - t) A + t B` (eq. 17) or `A (rev(A) B)^t` (eq. 15).
    ///
    /// ```
    /// use motion::{Blend, Multiplicative, Pose};
    /// let b = Pose::translation(&[2.0, 0.0, 0.0]);
    /// let m = Multiplicative::blend(&Pose::<f64>::identity(), &b, &0.5).unwrap();
    /// assert!((m.e1inf - 0.5).abs() < 1e-15);
    /// ```
    fn blend(a: &Pose<T>, b: &Pose<T>, t: &T) -> Result<Pose<T>, MotionError>;

    /// The apex `S(t)` of the de Casteljau tableau of [`Blend::blend`] over the control poses
    /// (at least one): what [`crate::Bezier`] evaluates. Computed in place without allocation
    /// up to eight control poses; [`Additive`] runs it coefficient by coefficient. Bit for bit
    /// the apex of the tableau built column by column.
    ///
    /// ```
    /// use motion::{Additive, Blend, Pose};
    /// let c = [Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0]), Pose::translation(&[2.0, 2.0, 0.0])];
    /// assert_eq!(Additive::apex(&c, &0.5).unwrap(), Pose::translation(&[1.5, 0.5, 0.0]));
    /// ```
    fn apex(poses: &[Pose<T>], t: &T) -> Result<Pose<T>, MotionError> {
        crate::de_casteljau::de_casteljau_with(poses, t, Self::blend)
    }

    /// De Boor's algorithm over the `p + 1` control poses of a B-spline span (at least one),
    /// with the parameter `alpha(r, j)` of step `j` of level `r`: what [`crate::BSpline`]
    /// evaluates. With the Bezier knots (`alpha = t` at every step) it makes the same
    /// combinations in the same order as [`Blend::apex`], so the two agree bit for bit.
    ///
    /// ```
    /// use motion::{Additive, Blend, Pose};
    /// let c = [Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])];
    /// assert_eq!(Additive::de_boor(&c, &|_, _| 0.25).unwrap(), Pose::translation(&[0.5, 0.0, 0.0]));
    /// ```
    fn de_boor(poses: &[Pose<T>], alpha: &dyn Fn(usize, usize) -> T) -> Result<Pose<T>, MotionError> {
        crate::bspline::de_boor_with(poses.to_vec(), alpha, Self::blend)
    }

    /// The control pose `S1` next to `S0` of a degree-`n` segment whose indicatrix at `t = 0`
    /// is `psi0` (eq. 22 or 23).
    ///
    /// ```
    /// use motion::{Additive, Blend, Even, Pose};
    /// let psi = Even::new(0.0, 0.0, 0.0, 0.0, 6.0, 0.0, 0.0, 0.0);
    /// assert_eq!(Additive::start_control_pose(&Pose::identity(), &psi, 3)?, Pose::translation(&[2.0, 0.0, 0.0]));
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    fn start_control_pose(s0: &Pose<T>, psi0: &Even<T>, degree: usize) -> Result<Pose<T>, JoinError>;

    /// The control pose `S_{n-1}` next to `Sn` of a degree-`n` segment whose indicatrix at
    /// `t = 1` is `psin` (eq. 22 or 23).
    ///
    /// ```
    /// use motion::{Blend, Even, Multiplicative, Pose};
    /// let psi = Even::new(0.0, 0.0, 0.0, 0.0, 6.0, 0.0, 0.0, 0.0);
    /// assert_eq!(Multiplicative::end_control_pose(&Pose::identity(), &psi, 3)?, Pose::translation(&[-2.0, 0.0, 0.0]));
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    fn end_control_pose(sn: &Pose<T>, psin: &Even<T>, degree: usize) -> Result<Pose<T>, JoinError>;

    /// A control pose strictly inside a Hermite segment of degree `n > 3`: the point
    /// `Φ(S1, S_{n-1}; t)` of the way from `S1` to `S_{n-1}` (eq. 17, or eq. 15 in its direct
    /// form `A (rev(A) B)^t`), see [`crate::hermite`].
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio, Q};
    /// use motion::{Additive, Blend, Pose};
    /// let b = Pose::translation(&[q(3), q(0), q(0)]);
    /// let third = Additive::inner_control_pose(&Pose::<Q>::identity(), &b, &ratio(1, 3))?;
    /// assert_eq!(third, Pose::translation(&[q(1), q(0), q(0)]));
    /// # Ok::<(), motion::MotionError>(())
    /// ```
    fn inner_control_pose(s1: &Pose<T>, sm: &Pose<T>, t: &T) -> Result<Pose<T>, MotionError>;

    /// The end indicatrices `[Ψ(0), Ψ(1)]` of a Bezier segment from its control poses
    /// (eq. 20 or 21, see [`joins::end_indicatrices`]).
    ///
    /// ```
    /// use algebra_core::rational::{q, Q};
    /// use motion::{Additive, Blend, Pose};
    /// let c = [Pose::<Q>::identity(), Pose::translation(&[q(1), q(0), q(0)]), Pose::translation(&[q(2), q(0), q(0)])];
    /// let [a, b] = Additive::end_indicatrices(&c)?;
    /// assert_eq!((a.e1inf, b.e1inf), (q(2), q(2)));
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    fn end_indicatrices(controls: &[Pose<T>]) -> Result<[Even<T>; 2], JoinError>
    where
        T: Field;
}

/// The additive kind: `Φ(A, B; t) = (1 - t) A + t B` (eq. 17), joins by eq. (22); polynomial,
/// so exact over exact scalars.
///
/// ```
/// use motion::{Additive, Blend, Pose};
/// let m = Additive::blend(&Pose::<f64>::identity(), &Pose::identity().scale(&3.0), &0.5).unwrap();
/// assert_eq!(m.scalar, 2.0);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Additive;

/// The multiplicative kind: the slerp `Φ(A, B; t) = A (rev(A) B)^t` (eq. 15, evaluated in the
/// factored form of eq. 16 that stays stable level after level), joins by eq. (23).
///
/// ```
/// use motion::{Blend, Multiplicative, Pose};
/// let r = Pose::rotation(&[0.0, 0.0, 1.0], &1.0).unwrap();
/// let half = Multiplicative::blend(&Pose::identity(), &r, &0.5).unwrap();
/// assert!(half.is_equivalent(&Pose::rotation(&[0.0, 0.0, 1.0], &0.5).unwrap(), &1e-15).unwrap());
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Multiplicative;

impl<T: Ring> Blend<T> for Additive {
    const KIND: SegmentKind = SegmentKind::Additive;

    fn blend(a: &Pose<T>, b: &Pose<T>, t: &T) -> Result<Pose<T>, MotionError> {
        Ok(Pose::lerp(a, b, t))
    }

    fn apex(poses: &[Pose<T>], t: &T) -> Result<Pose<T>, MotionError> {
        Ok(crate::de_casteljau::additive_apex(poses, t))
    }

    fn start_control_pose(s0: &Pose<T>, psi0: &Even<T>, degree: usize) -> Result<Pose<T>, JoinError> {
        joins::additive_start(s0, psi0, degree)
    }

    fn end_control_pose(sn: &Pose<T>, psin: &Even<T>, degree: usize) -> Result<Pose<T>, JoinError> {
        joins::additive_end(sn, psin, degree)
    }

    fn inner_control_pose(s1: &Pose<T>, sm: &Pose<T>, t: &T) -> Result<Pose<T>, MotionError> {
        Ok(Pose::lerp(s1, sm, t))
    }

    fn end_indicatrices(controls: &[Pose<T>]) -> Result<[Even<T>; 2], JoinError>
    where
        T: Field,
    {
        let (two_n, [s0, s1, sm, sn]) = ends(controls)?;
        let a = &s0.try_inverse()? * &(s1 - s0);
        let b = &sn.try_inverse()? * &(sn - sm);
        Ok([a.scale(&two_n), b.scale(&two_n)])
    }
}

impl<T: Real> Blend<T> for Multiplicative {
    const KIND: SegmentKind = SegmentKind::Multiplicative;

    fn blend(a: &Pose<T>, b: &Pose<T>, t: &T) -> Result<Pose<T>, MotionError> {
        crate::stable_slerp::slerp(a, b, t)
    }

    /// The slerp tableau's apex with every entry kept factored as `exp(l) U` from level to
    /// level (the control poses factored once): stable in the degree, derivatives included.
    fn apex(poses: &[Pose<T>], t: &T) -> Result<Pose<T>, MotionError> {
        crate::stable_slerp::apex(poses, t)
    }

    /// De Boor's algorithm with every entry kept factored as `exp(l) U`, as [`Blend::apex`].
    fn de_boor(poses: &[Pose<T>], alpha: &dyn Fn(usize, usize) -> T) -> Result<Pose<T>, MotionError> {
        crate::stable_slerp::de_boor(poses, alpha)
    }

    fn start_control_pose(s0: &Pose<T>, psi0: &Even<T>, degree: usize) -> Result<Pose<T>, JoinError> {
        joins::multiplicative_start(s0, psi0, degree)
    }

    fn end_control_pose(sn: &Pose<T>, psin: &Even<T>, degree: usize) -> Result<Pose<T>, JoinError> {
        joins::multiplicative_end(sn, psin, degree)
    }

    fn inner_control_pose(s1: &Pose<T>, sm: &Pose<T>, t: &T) -> Result<Pose<T>, MotionError> {
        Pose::slerp(s1, sm, t)
    }

    fn end_indicatrices(controls: &[Pose<T>]) -> Result<[Even<T>; 2], JoinError>
    where
        T: Field,
    {
        let (two_n, [s0, s1, sm, sn]) = ends(controls)?;
        let a = (&s0.reverse() * s1).log()?;
        let b = (&sn.reverse() * sm).log()?;
        Ok([a.scale(&two_n), b.scale(&two_n.neg_ref())])
    }
}

/// `2n` and `[S0, S1, S_{n-1}, Sn]` for `n + 1 ≥ 2` control poses.
fn ends<T: Ring>(controls: &[Pose<T>]) -> Result<(T, [&Pose<T>; 4]), JoinError> {
    let n = controls.len().checked_sub(1).filter(|&n| n >= 1).ok_or(JoinError::Degree { degree: 0, min: 1 })?;
    Ok((T::from_i64(2 * n as i64), [&controls[0], &controls[1], &controls[n - 1], &controls[n]]))
}
