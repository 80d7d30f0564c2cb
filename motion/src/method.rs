//! The interpolation methods of `gam interpolate`, by name: one registry that the CLI (and any
//! caller) asks for a motion through key poses. Built today: the main paper's two C1 Hermite
//! methods (Sec. 5.3, [`Method::interpolate`]), and the methods through the key poses only
//! ([`Method::key_motion`]): Wareham–Lasenby's `wl-linear` and `wl-quadratic` and Angelidis'
//! `hexanion-linear`. The names of the other papers' methods are known, so asking for one is a
//! clear "not yet" instead of "unknown" (each comes with its own issue and plugs in here as a
//! new variant returning its segments).
//!
//! ```
//! use motion::method::{Method, MethodError};
//! assert_eq!("ccm-additive".parse::<Method>(), Ok(Method::CcmAdditive));
//! assert!(matches!("juttler-spline".parse::<Method>(), Err(MethodError::NotYet { .. })));
//! assert!(matches!("spline".parse::<Method>(), Err(MethodError::Unknown { .. })));
//! ```

use crate::Pose;
use crate::hermite::HermiteShapes;
use crate::joins::SegmentKind;
use crate::repr::ReprError;
use crate::repr::hexanion::blend::HexanionLinear;
use crate::trajectory::{Trajectory, TrajectoryError, Velocities};
use crate::wareham_lasenby::{WlError, WlMotion};
use crate::{CurveError, MapScalar, Motion};
use algebra_core::Real;

/// A method of `gam interpolate` that is implemented.
///
/// ```
/// use motion::{SegmentKind, method::Method};
/// assert_eq!(Method::CcmMultiplicative.kind(), SegmentKind::Multiplicative);
/// assert_eq!(Method::CcmMultiplicative.name(), "ccm-multiplicative");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Main paper Sec. 5.3: additive cubic Bezier segments (eq. 18) with C1 joins (eq. 22).
    CcmAdditive,
    /// Main paper Sec. 5.3: multiplicative cubic Bezier segments (Fig. 2) with C1 joins (eq. 23).
    CcmMultiplicative,
    /// Wareham–Lasenby Sec. 3.1: piecewise interpolation of the relative rotor
    /// ([`crate::wareham_lasenby::WlLinear`]).
    WlLinear,
    /// Wareham–Lasenby Sec. 3.2: quadratic in the bivectors `ℓ(R_i)`, smoothed for more than
    /// three poses ([`crate::wareham_lasenby::WlQuadratic`]).
    WlQuadratic,
    /// Angelidis (56): piecewise linear interpolation of the key poses' principal hexanions,
    /// then exp ([`crate::repr::hexanion::blend::HexanionLinear`]).
    HexanionLinear,
}

/// The methods the contract names that come with later issues (name, issue).
pub const LATER: [(&str, u32); 4] =
    [("juttler-q-motion", 11), ("juttler-trt", 11), ("juttler-minimal", 11), ("juttler-spline", 11)];

/// Why a method name was not accepted.
///
/// ```
/// let e = "juttler-trt".parse::<motion::method::Method>().unwrap_err();
/// assert!(e.to_string().contains("not implemented yet"));
/// ```
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum MethodError {
    /// Not a method of the contract.
    #[error(
        "unknown method `{name}` (implemented: ccm-additive, ccm-multiplicative, wl-linear, wl-quadratic, hexanion-linear)"
    )]
    Unknown {
        /// The name given.
        name: String,
    },
    /// A method of the contract that is not implemented yet.
    #[error(
        "method `{name}` is not implemented yet (it comes with issue {issue}; implemented: ccm-additive, ccm-multiplicative, wl-linear, wl-quadratic, hexanion-linear)"
    )]
    NotYet {
        /// The name given.
        name: String,
        /// The issue that brings it.
        issue: u32,
    },
}

impl std::str::FromStr for Method {
    type Err = MethodError;
    fn from_str(s: &str) -> Result<Self, MethodError> {
        Method::from_name(s).ok_or_else(|| match LATER.iter().find(|(n, _)| *n == s) {
            Some((_, issue)) => MethodError::NotYet { name: s.to_string(), issue: *issue },
            None => MethodError::Unknown { name: s.to_string() },
        })
    }
}

crate::names::named!("motion::method::Method", Method {
    CcmAdditive => "ccm-additive",
    CcmMultiplicative => "ccm-multiplicative",
    WlLinear => "wl-linear",
    WlQuadratic => "wl-quadratic",
    HexanionLinear => "hexanion-linear"
});

impl Method {
    /// The segment kind of a `ccm-*` method; the W-L and hexanion methods (exp of generators)
    /// count as multiplicative.
    ///
    /// ```
    /// assert_eq!(motion::method::Method::CcmAdditive.kind(), motion::SegmentKind::Additive);
    /// ```
    pub fn kind(self) -> SegmentKind {
        match self {
            Method::CcmAdditive => SegmentKind::Additive,
            Method::CcmMultiplicative | Method::WlLinear | Method::WlQuadratic | Method::HexanionLinear => {
                SegmentKind::Multiplicative
            }
        }
    }

    /// What the control data of each segment mean (`segments[].representation` of the contract).
    ///
    /// ```
    /// assert_eq!(motion::method::Method::CcmAdditive.representation(), "additive-bezier");
    /// ```
    pub fn representation(self) -> &'static str {
        match self {
            Method::CcmAdditive => "additive-bezier",
            Method::CcmMultiplicative => "multiplicative-bezier",
            Method::WlLinear => "wl-relative-rotor",
            Method::WlQuadratic => "wl-bivector-quadratic",
            Method::HexanionLinear => "hexanion-linear",
        }
    }

    /// The motion through `poses` at `times` ([`Trajectory::through`] for the `ccm-*` methods;
    /// the W-L and hexanion methods are not Hermite trajectories: [`Method::key_motion`], an
    /// input error here).
    ///
    /// ```
    /// use motion::{HermiteShapes, Pose, method::Method, trajectory::Velocities};
    /// let poses = [Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])];
    /// let tr = Method::CcmAdditive.interpolate(&poses, &[0.0, 1.0], &Velocities::CatmullRom, &HermiteShapes::unit())?;
    /// assert_eq!(tr.segments().len(), 1);
    /// # Ok::<(), motion::trajectory::TrajectoryError>(())
    /// ```
    pub fn interpolate<T: Real>(
        self,
        poses: &[Pose<T>],
        times: &[T],
        velocities: &Velocities<T>,
        shapes: &HermiteShapes<T>,
    ) -> Result<Trajectory<T>, TrajectoryError> {
        if self.through_keys() {
            return Err(TrajectoryError::Input(format!(
                "`{}` is not a Hermite trajectory (Method::key_motion)",
                self.name()
            )));
        }
        Trajectory::through(poses, times, velocities, self.kind(), shapes)
    }

    /// True for the Wareham–Lasenby methods (built by [`Method::wl_motion`]).
    ///
    /// ```
    /// assert!(motion::method::Method::WlQuadratic.wl() && !motion::method::Method::CcmAdditive.wl());
    /// ```
    pub fn wl(self) -> bool {
        matches!(self, Method::WlLinear | Method::WlQuadratic)
    }

    /// The Wareham–Lasenby motion through `poses` at `times` (`None` for the other methods).
    ///
    /// ```
    /// use motion::{Motion, Pose, method::Method};
    /// let poses = [Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])];
    /// let m = Method::WlLinear.wl_motion(&poses, &[0.0, 1.0]).unwrap()?;
    /// assert!(m.pose(&1.0)?.is_equivalent(&poses[1], &1e-15)?);
    /// assert!(Method::WlQuadratic.wl_motion(&poses, &[0.0, 1.0]).unwrap().is_err()); // needs 3 poses
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn wl_motion<T: Real>(
        self,
        poses: &[Pose<T>],
        times: &[T],
    ) -> Option<Result<crate::wareham_lasenby::WlMotion<T>, crate::wareham_lasenby::WlError>> {
        use crate::wareham_lasenby::{WlLinear, WlMotion, WlQuadratic};
        match self {
            Method::WlLinear => Some(WlLinear::new(poses, times).map(WlMotion::Linear)),
            Method::WlQuadratic => Some(WlQuadratic::new(poses, times).map(WlMotion::Quadratic)),
            _ => None,
        }
    }
}

impl Method {
    /// True for the methods that interpolate the key poses only (no velocities or shapes):
    /// the W-L methods and `hexanion-linear`, built by [`Method::key_motion`].
    ///
    /// ```
    /// use motion::method::Method;
    /// assert!(Method::HexanionLinear.through_keys() && Method::WlLinear.through_keys());
    /// assert!(!Method::CcmAdditive.through_keys());
    /// ```
    pub fn through_keys(self) -> bool {
        self.wl() || self == Method::HexanionLinear
    }

    /// The motion of a [`Method::through_keys`] method through `poses` at `times` (`None` for
    /// the Hermite methods).
    ///
    /// ```
    /// use motion::{Motion, Pose, method::Method};
    /// let poses = [Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])];
    /// let m = Method::HexanionLinear.key_motion(&poses, &[0.0, 1.0]).unwrap()?;
    /// let p = m.pose(&0.5)?.transform_point(&[0.0; 3])?;
    /// assert!((p[0] - 1.0).abs() < 1e-15);
    /// assert!(Method::CcmAdditive.key_motion(&poses, &[0.0, 1.0]).is_none());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn key_motion<T: Real>(self, poses: &[Pose<T>], times: &[T]) -> Option<Result<KeyMotion<T>, KeyMotionError>> {
        if self == Method::HexanionLinear {
            return Some(HexanionLinear::through(poses, times).map(KeyMotion::Hexanion).map_err(KeyMotionError::Repr));
        }
        self.wl_motion(poses, times).map(|r| r.map(KeyMotion::Wl).map_err(KeyMotionError::Wl))
    }
}

/// The motion of a method that interpolates key poses only ([`Method::key_motion`]).
///
/// ```
/// use motion::{Motion, Pose, method::{KeyMotion, Method}};
/// let poses = [Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])];
/// let m = Method::WlLinear.key_motion(&poses, &[0.0, 2.0]).unwrap().unwrap();
/// assert!(matches!(m, KeyMotion::Wl(_)));
/// assert_eq!(m.domain(), [0.0, 2.0]);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum KeyMotion<T: Real> {
    /// `wl-linear`, `wl-quadratic`.
    Wl(WlMotion<T>),
    /// `hexanion-linear`.
    Hexanion(HexanionLinear<T>),
}

/// Why [`Method::key_motion`] failed.
///
/// ```
/// use motion::{Pose, method::{KeyMotionError, Method}};
/// let p = [Pose::<f64>::identity(), Pose::identity()];
/// let e = Method::HexanionLinear.key_motion(&p, &[1.0, 1.0]).unwrap().unwrap_err();
/// assert!(e.is_input());
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum KeyMotionError {
    /// From a W-L method.
    #[error(transparent)]
    Wl(WlError),
    /// From `hexanion-linear`.
    #[error(transparent)]
    Repr(ReprError),
}

impl KeyMotionError {
    /// True when the key poses or times are bad input (too few poses, times not increasing),
    /// false for a numerical failure (a singular or non-finite pose).
    ///
    /// ```
    /// use motion::{CurveError, method::KeyMotionError, wareham_lasenby::WlError};
    /// assert!(KeyMotionError::Wl(WlError::Curve(CurveError::TooFewPoses { need: 3, got: 2 })).is_input());
    /// ```
    pub fn is_input(&self) -> bool {
        matches!(
            self,
            KeyMotionError::Wl(WlError::Curve(_)) | KeyMotionError::Repr(ReprError::Curve(_) | ReprError::Times { .. })
        )
    }
}

impl<T: Real> Motion<T> for KeyMotion<T> {
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        match self {
            KeyMotion::Wl(m) => m.evaluate(t),
            KeyMotion::Hexanion(m) => m.evaluate(t),
        }
    }
    fn domain(&self) -> [T; 2] {
        match self {
            KeyMotion::Wl(m) => m.domain(),
            KeyMotion::Hexanion(m) => m.domain(),
        }
    }
}

impl<T: Real, U: Real> MapScalar<T, U> for KeyMotion<T> {
    type Mapped = KeyMotion<U>;
    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> KeyMotion<U> {
        match self {
            KeyMotion::Wl(m) => KeyMotion::Wl(m.map_scalar(f)),
            KeyMotion::Hexanion(m) => KeyMotion::Hexanion(m.map_scalar(f)),
        }
    }
}
