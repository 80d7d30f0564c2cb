//! Hermite interpolation through precision poses with velocities (Sec. 5.3 of the main paper):
//! one Bezier segment of degree `n ≥ 3` between consecutive precision poses, its end control
//! poses the precision poses and the next ones in given by the join rules of [`crate::joins`]
//! (eq. 22 additive, eq. 23 multiplicative) from the velocity indicatrices `Ψ = λ(ν + γ)`.
//!
//! Shape parameters are [common](HermiteShapes::Common) (the paper's Fig. 10: one `λ` for every
//! segment end; the motion stays C1), [per precision pose](HermiteShapes::PerPose) (both
//! segments meeting at a pose use its `λ`, `γ`: still C1 in the parameter), or
//! [per segment end](HermiteShapes::PerSegment) (different `λ` on the two sides of a join: G1).
//!
//! For `n > 3` the control poses strictly inside, `S2..S_{n-2}`, are not fixed by the end
//! conditions; they are spread evenly from `S1` to `S_{n-1}` with the segment's own combination
//! (`Φ(S1, S_{n-1}; (i-1)/(n-2))`, eq. 17 or eq. 15, [`Blend::inner_control_pose`]).
//!
//! The kind is the type parameter of [`HermiteSegment<T, B>`] (`B` = [`Additive`] or
//! [`Multiplicative`]); [`HermiteSegment::into_motion`] gives the typed [`Bezier<T, B>`]. Where a
//! file format carries the kind as a runtime [`SegmentKind`], [`hermite_segment`], [`hermite`]
//! and [`hermite_with_parameters`] dispatch once to the generic code and return
//! [`AnyHermiteSegment`]s.
//!
//! With [`hermite_with_parameters`] the precision poses sit at parameters `t_0 < t_1 < ...` and
//! the velocities are derivatives with respect to `t`; each segment is parametrized over
//! `[0, 1]`, so its end indicatrices are `h Ψ` for an interval of length `h` (the paper's
//! example has unit intervals, where both agree).
//!
//! ```
//! use motion::{EndCondition, SegmentKind, hermite::{self, HermiteShapes}};
//! // Three precision poses along a screw; two additive cubic segments.
//! let c = |x: f64| EndCondition::from_axis_angle(&[0.0, 0.0, x], &[0.0, 0.0, 1.0], &x, &[0.0, 0.0, 1.0], &[0.0, 0.0, 1.0]);
//! let poses = [c(0.0)?, c(1.0)?, c(2.0)?];
//! let segments = hermite::hermite(SegmentKind::Additive, 3, &poses, &HermiteShapes::unit())?;
//! assert_eq!(segments.len(), 2);
//! assert_eq!(segments[1].control_poses()[0], poses[1].pose);
//! # Ok::<(), motion::joins::JoinError>(())
//! ```

pub use crate::any_segment::AnyHermiteSegment;
use crate::joins::{EndCondition, JoinError, SegmentKind, Shape};
use crate::pose::is_positive;
#[cfg(doc)]
use crate::{Additive, Multiplicative};
use crate::{Bezier, Bivector, Blend, CurveError, Even, Pose};
use algebra_core::{Real, Ring};
use std::marker::PhantomData;

/// The shape parameters of a Hermite interpolation (see the module docs).
///
/// ```
/// use motion::{HermiteShapes, Shape};
/// let common = HermiteShapes::Common(Shape::factor(1.5)); // Fig. 10, common value 1.5
/// assert_eq!(common.for_segment(3, 9).unwrap(), [Shape::factor(1.5), Shape::factor(1.5)]);
/// let per_pose = HermiteShapes::PerPose(vec![Shape::factor(1.0), Shape::factor(2.0)]);
/// assert_eq!(per_pose.for_segment(0, 2).unwrap()[1].lambda, 2.0);
/// ```
#[derive(Clone, PartialEq)]
pub enum HermiteShapes<T> {
    /// One shape for every segment end.
    Common(Shape<T>),
    /// One shape per precision pose, used by both segments meeting there.
    PerPose(Vec<Shape<T>>),
    /// `[start, end]` shapes for each segment.
    PerSegment(Vec<[Shape<T>; 2]>),
}

impl<T: Ring> HermiteShapes<T> {
    /// `Common(Shape::unit())`: `Ψ = ν` everywhere (C1 with the prescribed velocities).
    ///
    /// ```
    /// assert_eq!(motion::HermiteShapes::<f64>::unit(), motion::HermiteShapes::Common(motion::Shape::unit()));
    /// ```
    pub fn unit() -> Self {
        HermiteShapes::Common(Shape::unit())
    }

    /// The `[start, end]` shapes of segment `k` of an interpolation through `poses` precision
    /// poses, or an error when a list has the wrong length.
    ///
    /// ```
    /// let s = motion::HermiteShapes::<f64>::PerPose(vec![motion::Shape::unit()]);
    /// assert!(s.for_segment(0, 3).is_err()); // needs one shape per pose
    /// ```
    pub fn for_segment(&self, k: usize, poses: usize) -> Result<[Shape<T>; 2], JoinError> {
        let segments = poses.saturating_sub(1);
        match self {
            HermiteShapes::Common(s) => Ok([s.clone(), s.clone()]),
            HermiteShapes::PerPose(v) if v.len() == poses && k + 1 < poses => Ok([v[k].clone(), v[k + 1].clone()]),
            HermiteShapes::PerPose(v) => {
                Err(JoinError::Input(format!("{} per-pose shapes given for {poses} precision poses", v.len())))
            }
            HermiteShapes::PerSegment(v) if v.len() == segments && k < segments => Ok(v[k].clone()),
            HermiteShapes::PerSegment(v) => {
                Err(JoinError::Input(format!("{} per-segment shapes given for {segments} segments", v.len())))
            }
        }
    }
}

/// One segment of a Hermite interpolation, its kind the type parameter `B` ([`Additive`] or
/// [`Multiplicative`], see [`Blend`]). Build it with [`HermiteSegment::new`] (or, for a
/// runtime [`SegmentKind`] from a file format, with [`hermite_segment`], which dispatches once
/// and gives an [`AnyHermiteSegment`]).
///
/// ```
/// use motion::{Additive, EndCondition, HermiteSegment, Shape};
/// let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[3.0, 0.0, 0.0], &[0.0; 3])?;
/// let b = EndCondition::from_axis_angle(&[3.0, 0.0, 0.0], &[0.0, 0.0, 1.0], &0.0, &[3.0, 0.0, 0.0], &[0.0; 3])?;
/// let seg = HermiteSegment::<f64, Additive>::new(3, &a, &b, &Shape::unit(), &Shape::unit())?;
/// // Uniform translation: the control poses are translations by 0, 1, 2, 3.
/// let x: Vec<f64> = seg.control_poses().iter().map(|s| 2.0 * s.e1inf).collect();
/// assert_eq!(x, [0.0, 1.0, 2.0, 3.0]);
/// assert_eq!(seg.degree(), 3);
/// # Ok::<(), motion::joins::JoinError>(())
/// ```
#[derive(Clone, PartialEq)]
pub struct HermiteSegment<T, B> {
    control_poses: Vec<Pose<T>>,
    velocity_bivectors: [Bivector<T>; 2],
    velocity_indicatrices: [Even<T>; 2],
    blend: PhantomData<B>,
}

impl<T, B> HermiteSegment<T, B> {
    /// The degree `n` (one less than the number of control poses).
    ///
    /// ```
    /// use motion::{EndCondition, HermiteSegment, Multiplicative, Shape};
    /// let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[1.0, 0.0, 0.0], &[0.0; 3])?;
    /// let seg = HermiteSegment::<f64, Multiplicative>::new(5, &a, &a, &Shape::unit(), &Shape::unit())?;
    /// assert_eq!(seg.degree(), 5);
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    pub fn degree(&self) -> usize {
        self.control_poses.len().saturating_sub(1)
    }

    /// `S0..Sn`.
    ///
    /// ```
    /// use motion::{Additive, EndCondition, HermiteSegment, Shape};
    /// let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[0.0; 3], &[0.0; 3])?;
    /// let seg = HermiteSegment::<f64, Additive>::new(3, &a, &a, &Shape::unit(), &Shape::unit())?;
    /// assert_eq!(seg.control_poses()[1], a.pose); // at rest: S1 = S0
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    pub fn control_poses(&self) -> &[Pose<T>] {
        &self.control_poses
    }

    /// `[ν0, νn]`: the velocity bivectors of the two end conditions (with respect to the
    /// interpolation parameter `t`).
    ///
    /// ```
    /// use motion::{Additive, EndCondition, HermiteSegment, Shape};
    /// let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[1.0, 0.0, 0.0], &[0.0; 3])?;
    /// let seg = HermiteSegment::<f64, Additive>::new(3, &a, &a, &Shape::unit(), &Shape::unit())?;
    /// assert_eq!(seg.velocity_bivectors()[0].e1inf, 1.0);
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    pub fn velocity_bivectors(&self) -> &[Bivector<T>; 2] {
        &self.velocity_bivectors
    }

    /// `[Ψ0, Ψn]`: the velocity indicatrices the segment has at its ends (with respect to its
    /// own parameter in `[0, 1]`; `h λ(ν + γ)` for an interval of length `h`).
    ///
    /// ```
    /// use motion::{Additive, EndCondition, HermiteSegment, Shape};
    /// let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[1.0, 0.0, 0.0], &[0.0; 3])?;
    /// let seg = HermiteSegment::<f64, Additive>::new(3, &a, &a, &Shape::factor(2.0), &Shape::unit())?;
    /// assert_eq!(seg.velocity_indicatrices()[0].e1inf, 2.0); // Ψ = λ ν, λ = 2
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    pub fn velocity_indicatrices(&self) -> &[Even<T>; 2] {
        &self.velocity_indicatrices
    }
}

impl<T: Ring, B: Blend<T>> HermiteSegment<T, B> {
    /// The runtime tag of the segment's kind (`B::KIND`).
    ///
    /// ```
    /// use motion::{EndCondition, HermiteSegment, Multiplicative, SegmentKind, Shape};
    /// let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[1.0, 0.0, 0.0], &[0.0; 3])?;
    /// let seg = HermiteSegment::<f64, Multiplicative>::new(3, &a, &a, &Shape::unit(), &Shape::unit())?;
    /// assert_eq!(seg.kind(), SegmentKind::Multiplicative);
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    pub fn kind(&self) -> SegmentKind {
        B::KIND
    }

    /// The segment as a motion on `[0, 1]`: the [`Bezier`] of its control poses with the
    /// segment's blend `B`.
    ///
    /// ```
    /// use motion::{Additive, Bezier, EndCondition, HermiteSegment, Motion, Shape};
    /// let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[1.0, 0.0, 0.0], &[0.0; 3])?;
    /// let b = EndCondition::from_axis_angle(&[2.0, 0.0, 0.0], &[0.0, 0.0, 1.0], &0.0, &[1.0, 0.0, 0.0], &[0.0; 3])?;
    /// let seg = HermiteSegment::<f64, Additive>::new(3, &a, &b, &Shape::unit(), &Shape::unit())?;
    /// let m: Bezier<f64, Additive> = seg.clone().into_motion()?;
    /// assert_eq!(m.pose(&1.0)?, seg.control_poses()[3]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn into_motion(self) -> Result<Bezier<T, B>, CurveError> {
        Bezier::new(self.control_poses)
    }
}

impl<T: Real, B: Blend<T>> HermiteSegment<T, B> {
    /// One segment of degree `n ≥ 3` from `start` to `end`: `S0 = start.pose`, `Sn = end.pose`,
    /// `S1` and `S_{n-1}` from the end indicatrices `Ψ0 = λ0(ν0 + γ0)` and `Ψn = λn(νn + γn)`
    /// by eq. (22) or (23) ([`Blend::start_control_pose`], [`Blend::end_control_pose`]); for
    /// `n > 3` the poses in between by [`Blend::inner_control_pose`] (module docs). This is
    /// what `gam hermite` computes. A NaN or infinite value in the end conditions or shapes is
    /// [`crate::MotionError::NotFinite`] (wrapped in [`JoinError::Motion`]).
    ///
    /// ```
    /// use motion::{Additive, EndCondition, HermiteSegment, Pseudoscalar, Shape};
    /// use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, FRAC_PI_8};
    /// // Sec. 5.2 of the paper, additive, λ0 = 4.
    /// let a = EndCondition::from_axis_angle(&[0.0; 3], &[1.0, 0.0, 0.0], &0.0, &[0.0, 0.0, 8.0], &[-FRAC_PI_4, 0.0, 0.0])?;
    /// let b = EndCondition::from_axis_angle(&[0.0, 10.0, 0.0], &[1.0, 0.0, 0.0], &-FRAC_PI_2, &[0.0, 4.0, 0.0], &[FRAC_PI_8, 0.0, 0.0])?;
    /// let seg = HermiteSegment::<f64, Additive>::new(3, &a, &b,
    ///     &Shape::new(4.0, Pseudoscalar::new(0.5, 0.5)), &Shape::new(1.0, Pseudoscalar::new(1.0, -0.5)))?;
    /// let s1 = seg.control_poses()[1];
    /// // printed: S1 = 1.333 - 0.524 e23 + 5.333 e3inf + 0.333 ω
    /// assert_eq!([s1.scalar, s1.e23, s1.e3inf, s1.e123inf].map(|x| format!("{x:.3}")), ["1.333", "-0.524", "5.333", "0.333"]);
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    pub fn new(
        degree: usize,
        start: &EndCondition<T>,
        end: &EndCondition<T>,
        start_shape: &Shape<T>,
        end_shape: &Shape<T>,
    ) -> Result<Self, JoinError> {
        if degree < 3 {
            return Err(JoinError::Degree { degree, min: 3 });
        }
        if degree > MAX_SEGMENT_DEGREE {
            return Err(JoinError::DegreeTooLarge { degree, max: MAX_SEGMENT_DEGREE });
        }
        check_finite_inputs([start, end], [start_shape, end_shape])?;
        let nu = [start.velocity_bivector(), end.velocity_bivector()];
        let psi = [start_shape.indicatrix(&nu[0]), end_shape.indicatrix(&nu[1])];
        let s1 = B::start_control_pose(&start.pose, &psi[0], degree)?;
        let sm = B::end_control_pose(&end.pose, &psi[1], degree)?;
        let mut control_poses = Vec::with_capacity(degree + 1);
        control_poses.push(start.pose.clone());
        control_poses.push(s1.clone());
        let inner = degree - 2; // Φ(S1, S_{n-1}; i/inner) for 0 < i < inner
        for i in 1..inner {
            control_poses.push(B::inner_control_pose(&s1, &sm, &T::from_ratio(i as i64, inner as i64))?);
        }
        control_poses.push(sm);
        control_poses.push(end.pose.clone());
        Ok(HermiteSegment { control_poses, velocity_bivectors: nu, velocity_indicatrices: psi, blend: PhantomData })
    }

    /// Hermite interpolation through `conditions` (at least two) at unit parameter spacing, as
    /// in Sec. 5.3 (`t = 1, 2, ..., 9`): one segment of degree `n ≥ 3` per consecutive pair.
    ///
    /// ```
    /// use motion::{Continuity, EndCondition, HermiteSegment, HermiteShapes, Multiplicative, joins};
    /// let c = |x: f64| EndCondition::from_axis_angle(&[x, x * x, 0.0], &[1.0, 1.0, 0.0], &x, &[1.0, 2.0 * x, 0.0], &[0.5, 0.5, 0.0]);
    /// let poses = [c(0.0)?, c(1.0)?, c(2.0)?];
    /// let segs = HermiteSegment::<f64, Multiplicative>::through(3, &poses, &HermiteShapes::unit())?;
    /// let j = joins::check_segment_join((segs[0].kind(), segs[0].control_poses()), (segs[1].kind(), segs[1].control_poses()), &1e-9)?;
    /// assert_eq!(j.continuity, Continuity::C1);
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    pub fn through(
        degree: usize,
        conditions: &[EndCondition<T>],
        shapes: &HermiteShapes<T>,
    ) -> Result<Vec<Self>, JoinError> {
        check_count(conditions)?;
        (0..conditions.len() - 1)
            .map(|k| {
                let [a, b] = shapes.for_segment(k, conditions.len())?;
                Self::new(degree, &conditions[k], &conditions[k + 1], &a, &b)
            })
            .collect()
    }

    /// Hermite interpolation with the precision poses at the strictly increasing `parameters`
    /// (one per condition): velocities are derivatives with respect to `t`, and segment `k`,
    /// over `[t_k, t_{k+1}]` of length `h`, uses the end indicatrices `h λ(ν + γ)` for its own
    /// parameter in `[0, 1]`.
    ///
    /// ```
    /// use motion::{Additive, EndCondition, HermiteSegment, HermiteShapes};
    /// let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[1.0, 0.0, 0.0], &[0.0; 3])?;
    /// let b = EndCondition::from_axis_angle(&[2.0, 0.0, 0.0], &[0.0, 0.0, 1.0], &0.0, &[1.0, 0.0, 0.0], &[0.0; 3])?;
    /// let segs = HermiteSegment::<f64, Additive>::through_at(3, &[a.clone(), b.clone()], &[0.0, 2.0], &HermiteShapes::unit())?;
    /// assert_eq!(segs[0].velocity_indicatrices()[0].e1inf, 2.0); // h v with h = 2
    /// assert_eq!(segs[0].velocity_bivectors()[0].e1inf, 1.0); // ν itself is per unit of t
    /// assert!(HermiteSegment::<f64, Additive>::through_at(3, &[a, b], &[1.0, 1.0], &HermiteShapes::unit()).is_err());
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    pub fn through_at(
        degree: usize,
        conditions: &[EndCondition<T>],
        parameters: &[T],
        shapes: &HermiteShapes<T>,
    ) -> Result<Vec<Self>, JoinError> {
        check_count(conditions)?;
        if parameters.len() != conditions.len() {
            return Err(JoinError::Input(format!(
                "{} parameters given for {} precision poses",
                parameters.len(),
                conditions.len()
            )));
        }
        (0..conditions.len() - 1)
            .map(|k| {
                let h = parameters[k + 1].sub_ref(&parameters[k]);
                if !(is_positive(&h) && h.is_finite()) {
                    return Err(JoinError::Input(format!(
                        "the parameters must be finite and strictly increasing ({} then {})",
                        parameters[k],
                        parameters[k + 1]
                    )));
                }
                let [a, b] = shapes.for_segment(k, conditions.len())?;
                // ν stays per unit of t; only the indicatrices (and so S1, S_{n-1}) are scaled by h.
                Self::new(degree, &conditions[k], &conditions[k + 1], &a.stretched(&h), &b.stretched(&h))
            })
            .collect()
    }
}

/// The largest segment degree [`HermiteSegment::new`] accepts (the CLI's `gam hermite` range):
/// checked before the `degree + 1` control poses are allocated.
///
/// ```
/// assert_eq!(motion::hermite::MAX_SEGMENT_DEGREE, 10_000);
/// ```
pub const MAX_SEGMENT_DEGREE: usize = 10_000;

/// [`HermiteSegment::new`] with the kind given at run time (a file format's tag): dispatches
/// once ([`crate::with_blend!`]) and gives the [`AnyHermiteSegment`] of that kind.
///
/// ```
/// use motion::{EndCondition, SegmentKind, Shape, hermite};
/// let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[3.0, 0.0, 0.0], &[0.0; 3])?;
/// let seg = hermite::hermite_segment(SegmentKind::Multiplicative, 4, &a, &a, &Shape::unit(), &Shape::unit())?;
/// assert_eq!((seg.kind(), seg.degree()), (SegmentKind::Multiplicative, 4));
/// # Ok::<(), motion::joins::JoinError>(())
/// ```
pub fn hermite_segment<T: Real>(
    kind: SegmentKind,
    degree: usize,
    start: &EndCondition<T>,
    end: &EndCondition<T>,
    start_shape: &Shape<T>,
    end_shape: &Shape<T>,
) -> Result<AnyHermiteSegment<T>, JoinError> {
    crate::with_blend!(kind, B => Ok(HermiteSegment::<T, B>::new(degree, start, end, start_shape, end_shape)?.into()))
}

/// [`HermiteSegment::through`] with the kind given at run time (one dispatch).
///
/// ```
/// use motion::{EndCondition, HermiteShapes, SegmentKind, hermite};
/// let c = |x: f64| EndCondition::from_axis_angle(&[x, 0.0, 0.0], &[0.0, 0.0, 1.0], &0.0, &[1.0, 0.0, 0.0], &[0.0; 3]);
/// let segs = hermite::hermite(SegmentKind::Additive, 3, &[c(0.0)?, c(1.0)?, c(2.0)?], &HermiteShapes::unit())?;
/// assert_eq!(segs[1].control_poses()[0], c(1.0)?.pose);
/// # Ok::<(), motion::joins::JoinError>(())
/// ```
pub fn hermite<T: Real>(
    kind: SegmentKind,
    degree: usize,
    conditions: &[EndCondition<T>],
    shapes: &HermiteShapes<T>,
) -> Result<Vec<AnyHermiteSegment<T>>, JoinError> {
    crate::with_blend!(kind, B => Ok(tagged(HermiteSegment::<T, B>::through(degree, conditions, shapes)?)))
}

/// [`HermiteSegment::through_at`] with the kind given at run time (one dispatch).
///
/// ```
/// use motion::{EndCondition, HermiteShapes, SegmentKind, hermite};
/// let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[1.0, 0.0, 0.0], &[0.0; 3])?;
/// let segs = hermite::hermite_with_parameters(SegmentKind::Multiplicative, 3, &[a.clone(), a], &[0.0, 2.0], &HermiteShapes::unit())?;
/// assert_eq!(segs[0].velocity_indicatrices()[0].e1inf, 2.0);
/// # Ok::<(), motion::joins::JoinError>(())
/// ```
pub fn hermite_with_parameters<T: Real>(
    kind: SegmentKind,
    degree: usize,
    conditions: &[EndCondition<T>],
    parameters: &[T],
    shapes: &HermiteShapes<T>,
) -> Result<Vec<AnyHermiteSegment<T>>, JoinError> {
    crate::with_blend!(kind, B => Ok(tagged(HermiteSegment::<T, B>::through_at(degree, conditions, parameters, shapes)?)))
}

fn tagged<T: Ring, S: Into<AnyHermiteSegment<T>>>(segments: Vec<S>) -> Vec<AnyHermiteSegment<T>> {
    segments.into_iter().map(Into::into).collect()
}

fn check_count<T>(conditions: &[EndCondition<T>]) -> Result<(), JoinError> {
    if conditions.len() < 2 {
        return Err(JoinError::Input(format!("at least two precision poses are needed (got {})", conditions.len())));
    }
    Ok(())
}

impl<T: Ring> std::fmt::Debug for HermiteShapes<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            HermiteShapes::Common(s) => f.debug_tuple("Common").field(s).finish(),
            HermiteShapes::PerPose(v) => f.debug_tuple("PerPose").field(v).finish(),
            HermiteShapes::PerSegment(v) => f.debug_tuple("PerSegment").field(v).finish(),
        }
    }
}

impl<T: Ring, B: std::fmt::Debug + Default> std::fmt::Debug for HermiteSegment<T, B> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("HermiteSegment")
            .field("blend", &B::default())
            .field("control_poses", &self.control_poses)
            .field("velocity_bivectors", &self.velocity_bivectors)
            .field("velocity_indicatrices", &self.velocity_indicatrices)
            .finish()
    }
}

/// [`crate::MotionError::NotFinite`] unless every value of the end conditions and shapes is finite
/// (the fields are public, so [`EndCondition::new`] and [`Shape::new`] take anything).
fn check_finite_inputs<T: Real>(ends: [&EndCondition<T>; 2], shapes: [&Shape<T>; 2]) -> Result<(), JoinError> {
    crate::bezier::finite_poses("end condition", ends.map(|c| &c.pose))?;
    for c in ends {
        for x in c.position.iter().chain(&c.velocity).chain(&c.angular_velocity) {
            crate::pose::check_finite_scalar("end condition", x)?;
        }
    }
    for s in shapes {
        for x in [&s.lambda, &s.gamma.scalar, &s.gamma.e123inf] {
            crate::pose::check_finite_scalar("shape", x)?;
        }
    }
    Ok(())
}
