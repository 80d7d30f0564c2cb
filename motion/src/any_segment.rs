//! The runtime kind tag in one place: [`with_blend!`](crate::with_blend) maps a
//! [`SegmentKind`] (what a file format or a command line carries) to the [`Blend`](crate::Blend) type the
//! generic code takes, and [`AnyHermiteSegment`] holds a Hermite segment of either kind. Code
//! that knows its kind at compile time uses [`HermiteSegment<T, B>`] directly.
//!
//! ```
//! use motion::{EndCondition, HermiteSegment, SegmentKind, Shape};
//! let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[1.0, 0.0, 0.0], &[0.0; 3])?;
//! let kind: SegmentKind = "multiplicative".parse().unwrap();
//! let degree = motion::with_blend!(kind, B => HermiteSegment::<f64, B>::new(4, &a, &a, &Shape::unit(), &Shape::unit())?.degree());
//! assert_eq!(degree, 4);
//! # Ok::<(), motion::joins::JoinError>(())
//! ```

use crate::hermite::HermiteSegment;
use crate::joins::SegmentKind;
use crate::{Additive, AnyMotion, Bivector, CurveError, Even, Multiplicative, Pose};
use algebra_core::{Real, Ring};

/// `with_blend!(kind, B => expr)`: evaluates `expr` with the type name `B` bound to the
/// [`Blend`](crate::Blend) of the runtime `kind` ([`Additive`] or [`Multiplicative`]); the one dispatch from
/// a [`SegmentKind`] to the generic code. Both arms must give the same type.
///
/// ```
/// use motion::{Blend, SegmentKind};
/// for kind in [SegmentKind::Additive, SegmentKind::Multiplicative] {
///     assert_eq!(motion::with_blend!(kind, B => <B as Blend<f64>>::KIND), kind);
/// }
/// ```
#[macro_export]
macro_rules! with_blend {
    ($kind:expr, $b:ident => $body:expr) => {
        match $kind {
            $crate::SegmentKind::Additive => {
                type $b = $crate::Additive;
                $body
            }
            $crate::SegmentKind::Multiplicative => {
                type $b = $crate::Multiplicative;
                $body
            }
        }
    };
}

/// A [`HermiteSegment`] whose kind is known only at run time (from [`crate::spec`], the CLI,
/// [`crate::hermite::hermite_segment`]).
///
/// ```
/// use motion::{AnyHermiteSegment, EndCondition, Motion, SegmentKind, Shape, hermite};
/// let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[1.0, 0.0, 0.0], &[0.0; 3])?;
/// let seg: AnyHermiteSegment<f64> = hermite::hermite_segment(SegmentKind::Additive, 3, &a, &a, &Shape::unit(), &Shape::unit())?;
/// assert!(matches!(seg, AnyHermiteSegment::Additive(_)));
/// assert_eq!(seg.into_motion()?.domain(), [0.0, 1.0]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, PartialEq)]
pub enum AnyHermiteSegment<T: Ring> {
    /// An additive segment (eq. 17, joins by eq. 22).
    Additive(HermiteSegment<T, Additive>),
    /// A multiplicative segment (eq. 15, joins by eq. 23).
    Multiplicative(HermiteSegment<T, Multiplicative>),
}

/// `$body` with `$s` bound to the segment of either variant.
macro_rules! each {
    ($v:expr, $s:ident => $body:expr) => {
        match $v {
            AnyHermiteSegment::Additive($s) => $body,
            AnyHermiteSegment::Multiplicative($s) => $body,
        }
    };
}

impl<T: Real> AnyHermiteSegment<T> {
    /// The runtime tag of the kind.
    ///
    /// ```
    /// use motion::{EndCondition, SegmentKind, Shape, hermite};
    /// let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[0.0; 3], &[0.0; 3])?;
    /// let seg = hermite::hermite_segment(SegmentKind::Multiplicative, 3, &a, &a, &Shape::unit(), &Shape::unit())?;
    /// assert_eq!(seg.kind(), SegmentKind::Multiplicative);
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    pub fn kind(&self) -> SegmentKind {
        each!(self, s => s.kind())
    }

    /// The degree `n` ([`HermiteSegment::degree`]).
    ///
    /// ```
    /// use motion::{EndCondition, SegmentKind, Shape, hermite};
    /// let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[0.0; 3], &[0.0; 3])?;
    /// let seg = hermite::hermite_segment(SegmentKind::Additive, 6, &a, &a, &Shape::unit(), &Shape::unit())?;
    /// assert_eq!(seg.degree(), 6);
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    pub fn degree(&self) -> usize {
        each!(self, s => s.degree())
    }

    /// `S0..Sn` ([`HermiteSegment::control_poses`]).
    ///
    /// ```
    /// use motion::{EndCondition, SegmentKind, Shape, hermite};
    /// let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[0.0; 3], &[0.0; 3])?;
    /// let seg = hermite::hermite_segment(SegmentKind::Additive, 3, &a, &a, &Shape::unit(), &Shape::unit())?;
    /// assert_eq!(seg.control_poses().len(), 4);
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    pub fn control_poses(&self) -> &[Pose<T>] {
        each!(self, s => s.control_poses())
    }

    /// `[ν0, νn]` ([`HermiteSegment::velocity_bivectors`]).
    ///
    /// ```
    /// use motion::{EndCondition, SegmentKind, Shape, hermite};
    /// let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[0.0, 5.0, 0.0], &[0.0; 3])?;
    /// let seg = hermite::hermite_segment(SegmentKind::Additive, 3, &a, &a, &Shape::unit(), &Shape::unit())?;
    /// assert_eq!(seg.velocity_bivectors()[1].e2inf, 5.0);
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    pub fn velocity_bivectors(&self) -> &[Bivector<T>; 2] {
        each!(self, s => s.velocity_bivectors())
    }

    /// `[Ψ0, Ψn]` ([`HermiteSegment::velocity_indicatrices`]).
    ///
    /// ```
    /// use motion::{EndCondition, SegmentKind, Shape, hermite};
    /// let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[0.0, 5.0, 0.0], &[0.0; 3])?;
    /// let seg = hermite::hermite_segment(SegmentKind::Additive, 3, &a, &a, &Shape::factor(2.0), &Shape::unit())?;
    /// assert_eq!(seg.velocity_indicatrices()[0].e2inf, 10.0);
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    pub fn velocity_indicatrices(&self) -> &[Even<T>; 2] {
        each!(self, s => s.velocity_indicatrices())
    }

    /// The segment as a motion on `[0, 1]` ([`HermiteSegment::into_motion`], as an
    /// [`AnyMotion`]).
    ///
    /// ```
    /// use motion::{EndCondition, Motion, SegmentKind, Shape, hermite};
    /// let a = EndCondition::from_axis_angle(&[0.0; 3], &[0.0, 0.0, 1.0], &0.0, &[1.0, 0.0, 0.0], &[0.0; 3])?;
    /// let b = EndCondition::from_axis_angle(&[2.0, 0.0, 0.0], &[0.0, 0.0, 1.0], &0.0, &[1.0, 0.0, 0.0], &[0.0; 3])?;
    /// let seg = hermite::hermite_segment(SegmentKind::Multiplicative, 3, &a, &b, &Shape::unit(), &Shape::unit())?;
    /// let m = seg.clone().into_motion()?;
    /// assert!(m.pose(&1.0)?.is_equivalent(&seg.control_poses()[3], &1e-12)?);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn into_motion(self) -> Result<AnyMotion<T>, CurveError> {
        Ok(each!(self, s => s.into_motion()?.into()))
    }
}

impl<T: Ring> From<HermiteSegment<T, Additive>> for AnyHermiteSegment<T> {
    fn from(s: HermiteSegment<T, Additive>) -> Self {
        AnyHermiteSegment::Additive(s)
    }
}

impl<T: Ring> From<HermiteSegment<T, Multiplicative>> for AnyHermiteSegment<T> {
    fn from(s: HermiteSegment<T, Multiplicative>) -> Self {
        AnyHermiteSegment::Multiplicative(s)
    }
}

impl<T: Ring> std::fmt::Debug for AnyHermiteSegment<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        each!(self, s => s.fmt(f))
    }
}
