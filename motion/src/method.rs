//! The interpolation methods of `gam interpolate`, by name: one registry that the CLI (and any
//! caller) asks for a motion through key poses. Today the main paper's two C1 Hermite methods
//! (Sec. 5.3) are built; the names of the other papers' methods are known, so asking for one is
//! a clear "not yet" instead of "unknown" (each comes with its own issue and plugs in here as a
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
use crate::trajectory::{Trajectory, TrajectoryError, Velocities};
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
}

/// The methods the contract names that come with later issues (name, issue).
pub const LATER: [(&str, u32); 5] = [
    ("juttler-q-motion", 11),
    ("juttler-trt", 11),
    ("juttler-minimal", 11),
    ("juttler-spline", 11),
    ("hexanion-linear", 10),
];

/// Why a method name was not accepted.
///
/// ```
/// let e = "juttler-trt".parse::<motion::method::Method>().unwrap_err();
/// assert!(e.to_string().contains("not implemented yet"));
/// ```
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum MethodError {
    /// Not a method of the contract.
    #[error("unknown method `{name}` (implemented: ccm-additive, ccm-multiplicative, wl-linear, wl-quadratic)")]
    Unknown {
        /// The name given.
        name: String,
    },
    /// A method of the contract that is not implemented yet.
    #[error(
        "method `{name}` is not implemented yet (it comes with issue {issue}; implemented: ccm-additive, ccm-multiplicative, wl-linear, wl-quadratic)"
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
        match s {
            "ccm-additive" => Ok(Method::CcmAdditive),
            "ccm-multiplicative" => Ok(Method::CcmMultiplicative),
            "wl-linear" => Ok(Method::WlLinear),
            "wl-quadratic" => Ok(Method::WlQuadratic),
            _ => Err(match LATER.iter().find(|(n, _)| *n == s) {
                Some((_, issue)) => MethodError::NotYet { name: s.to_string(), issue: *issue },
                None => MethodError::Unknown { name: s.to_string() },
            }),
        }
    }
}

impl Method {
    /// The name in the contract.
    ///
    /// ```
    /// assert_eq!(motion::method::Method::CcmAdditive.name(), "ccm-additive");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Method::CcmAdditive => "ccm-additive",
            Method::CcmMultiplicative => "ccm-multiplicative",
            Method::WlLinear => "wl-linear",
            Method::WlQuadratic => "wl-quadratic",
        }
    }

    /// The segment kind of a `ccm-*` method; the W-L methods (exp of generators) count as
    /// multiplicative.
    ///
    /// ```
    /// assert_eq!(motion::method::Method::CcmAdditive.kind(), motion::SegmentKind::Additive);
    /// ```
    pub fn kind(self) -> SegmentKind {
        match self {
            Method::CcmAdditive => SegmentKind::Additive,
            Method::CcmMultiplicative | Method::WlLinear | Method::WlQuadratic => SegmentKind::Multiplicative,
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
        }
    }

    /// The motion through `poses` at `times` ([`Trajectory::through`] for the `ccm-*` methods;
    /// the W-L methods are not Hermite trajectories: [`Method::wl_motion`], an input error here).
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
        if self.wl() {
            return Err(TrajectoryError::Input(format!(
                "`{}` is not a Hermite trajectory (Method::wl_motion)",
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
