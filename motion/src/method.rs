//! The interpolation methods of `gam interpolate`, by name: one registry that the CLI (and any
//! caller) asks for a motion through key poses, and ONE build path for all of them,
//! [`Method::build`], returning a [`BuiltMotion`]: a [`crate::Motion`] that also knows its
//! segments (parameter interval, representation, degree, control poses / dual quaternions),
//! its rational point trajectories where the method's motions are rational, and is sampled
//! by one function ([`BuiltMotion::sample`]).
//!
//! Built: the main paper's two C1 Hermite methods (Sec. 5.3), Wareham–Lasenby's `wl-linear`
//! and `wl-quadratic`, Angelidis' `hexanion-linear`, and Jüttler's Algorithm 1
//! (`juttler-q-motion`), TRT (`juttler-trt`), minimal order (`juttler-minimal`) and
//! Algorithm 2 (`juttler-spline`): every method of the contract. A name of the contract that
//! is not implemented would be a clear "not yet" ([`LATER`], empty today) instead of "unknown".
//!
//! ```
//! use motion::method::{Method, MethodError};
//! assert_eq!("ccm-additive".parse::<Method>(), Ok(Method::CcmAdditive));
//! assert_eq!("juttler-spline".parse::<Method>(), Ok(Method::JuttlerSpline));
//! assert!(matches!("spline".parse::<Method>(), Err(MethodError::Unknown { .. })));
//! ```

mod build;
mod built;
pub mod exact;

pub use build::{BuildError, MethodInput, Parameters};
pub use built::{BuiltMotion, MethodMotion, MethodSegment, RationalSegment, SurfaceSegment};
pub use exact::{ExactMotion, ExactSample};

use crate::joins::SegmentKind;

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
    /// Wareham–Lasenby Sec. 3.3: direct piecewise linear interpolation of the bivectors
    /// `ℓ(R_i)`, then exp ([`crate::wareham_lasenby::WlBivectorLinear`]); differs from
    /// `wl-linear` between the key poses unless the generators commute.
    WlDirect,
    /// Angelidis (56): piecewise linear interpolation of the key poses' principal hexanions,
    /// then exp ([`crate::repr::hexanion::blend::HexanionLinear`]).
    HexanionLinear,
    /// Angelidis (58)-(60): between consecutive key poses the body origin moves straight while
    /// the body turns at a constant rate about it
    /// ([`crate::repr::hexanion::blend::HexanionDecoupled`]).
    HexanionDecoupled,
    /// Angelidis (57): the weighted blend of all key poses' principal hexanions with named
    /// weight functions (`lagrange`: through every key pose; `bernstein`: a Bézier curve of
    /// hexanions), then exp ([`crate::repr::hexanion::blend::HexanionBlend`]).
    HexanionBlend,
    /// Jüttler's Algorithm 1: one Q-motion of degree `2m` through the `m + 1` key poses, the
    /// elliptic rotation (23)-(25) composed with the TR translation (30)-(31)
    /// ([`crate::juttler::tr::algorithm1`]).
    JuttlerQMotion,
    /// Jüttler Sec. 3.1 (19)-(21) with Sec. 4.1: the affine rotational method (rotations of
    /// degree `m` with scalar part 1) composed with the TR translation: degree `2m`
    /// ([`crate::juttler::rotational::affine`], [`crate::juttler::tr::tr_method`]).
    JuttlerAffine,
    /// Jüttler Sec. 3.3 (27)-(28) with Sec. 4.1: the projective rotational method (degree
    /// `3m/4`, for `m + 1 = 5, 9, 13, ...` key poses) composed with the TR translation: degree
    /// `7m/4` ([`crate::juttler::projective::projective`], [`crate::juttler::tr::tr_method`]).
    JuttlerProjective,
    /// Jüttler Sec. 4.2: the elliptic rotation (22)-(25) with the TRT translations (32)-(34),
    /// split `l1 + l2 = m - 1` ([`crate::juttler::trt::trt`]).
    JuttlerTrt,
    /// Jüttler Sec. 5: the rational motion of minimal order `2m` (37)-(39) on the elliptic
    /// rotation ([`crate::juttler::minimal::minimal`]).
    JuttlerMinimal,
    /// Jüttler's Algorithm 2: the C1 spline Q-motion (40)-(44), velocities given or estimated
    /// by step 1 ([`crate::juttler::spline::algorithm2`]).
    JuttlerSpline,
    /// Jüttler Sec. 6 (the TR method with B-spline Q-motions, as the paper says Secs. 3-4
    /// generalise): rotational parts and translations interpolated by B-splines of degree `p`
    /// (spec key `degree`, default `min(3, m)`) on averaged knots, their product a B-spline
    /// Q-motion of degree `2p`, C^(p-1) ([`crate::juttler::bspline_tr::bspline_tr`]).
    JuttlerBSpline,
    /// Jüttler Sec. 6's closing remark, built here: the C1 spline whose segments are rational
    /// motions of order 6 (Algorithm 2's cubic rotations, the origin on `w/|D|²` with `w` the
    /// cubic Hermite data), velocities given or estimated by step 1
    /// ([`crate::juttler::minimal_spline::minimal_spline`]).
    JuttlerMinimalSpline,
}

/// The methods the contract names that come with later issues (name, issue): none today.
pub const LATER: [(&str, u32); 0] = [];

/// The implemented methods, as listed in messages.
const IMPLEMENTED: &str = "ccm-additive, ccm-multiplicative, wl-linear, wl-quadratic, wl-direct, hexanion-linear, hexanion-decoupled, hexanion-blend, juttler-q-motion, juttler-affine, juttler-projective, juttler-trt, juttler-minimal, juttler-spline, juttler-bspline, juttler-minimal-spline";

/// Why a method name was not accepted.
///
/// ```
/// let e = "juttler-slerp".parse::<motion::method::Method>().unwrap_err();
/// assert!(e.to_string().contains("unknown method `juttler-slerp`"));
/// ```
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum MethodError {
    /// Not a method of the contract.
    #[error("unknown method `{name}` (implemented: {IMPLEMENTED})")]
    Unknown {
        /// The name given.
        name: String,
    },
    /// A method of the contract that is not implemented yet.
    #[error("method `{name}` is not implemented yet (it comes with issue {issue}; implemented: {IMPLEMENTED})")]
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
    WlDirect => "wl-direct",
    HexanionLinear => "hexanion-linear",
    HexanionDecoupled => "hexanion-decoupled",
    HexanionBlend => "hexanion-blend",
    JuttlerQMotion => "juttler-q-motion",
    JuttlerAffine => "juttler-affine",
    JuttlerProjective => "juttler-projective",
    JuttlerTrt => "juttler-trt",
    JuttlerMinimal => "juttler-minimal",
    JuttlerSpline => "juttler-spline",
    JuttlerBSpline => "juttler-bspline",
    JuttlerMinimalSpline => "juttler-minimal-spline"
});

impl Method {
    /// True for Jüttler's methods: their motions are Q-motions (or rational motions of minimal
    /// order, given by their Q-motions (36)), their segments' control data dual quaternions. The
    /// one list of the family, from which [`Method::kind`] and [`Method::is_rational`] follow.
    ///
    /// ```
    /// use motion::method::Method;
    /// assert!(Method::JuttlerBSpline.is_juttler() && !Method::CcmAdditive.is_juttler());
    /// ```
    pub fn is_juttler(self) -> bool {
        match self {
            Method::JuttlerQMotion
            | Method::JuttlerAffine
            | Method::JuttlerProjective
            | Method::JuttlerTrt
            | Method::JuttlerMinimal
            | Method::JuttlerSpline
            | Method::JuttlerBSpline
            | Method::JuttlerMinimalSpline => true,
            Method::CcmAdditive
            | Method::CcmMultiplicative
            | Method::WlLinear
            | Method::WlQuadratic
            | Method::WlDirect
            | Method::HexanionLinear
            | Method::HexanionDecoupled
            | Method::HexanionBlend => false,
        }
    }

    /// The segment kind: additive for `ccm-additive` and the Jüttler methods (a Q-motion
    /// `Σ b_i(t) B_i` is the additive Bézier motion of the motors of its control dual
    /// quaternions: the map between them is linear), multiplicative for `ccm-multiplicative`;
    /// the W-L and hexanion methods (exp of generators) count as multiplicative.
    ///
    /// ```
    /// use motion::{SegmentKind, method::Method};
    /// assert_eq!(Method::CcmAdditive.kind(), SegmentKind::Additive);
    /// assert_eq!(Method::JuttlerQMotion.kind(), SegmentKind::Additive);
    /// ```
    pub fn kind(self) -> SegmentKind {
        if self == Method::CcmAdditive || self.is_juttler() {
            SegmentKind::Additive
        } else {
            SegmentKind::Multiplicative
        }
    }

    /// What the control data of each segment mean (`segments[].representation` of the contract).
    ///
    /// ```
    /// use motion::method::Method;
    /// assert_eq!(Method::CcmAdditive.representation(), "additive-bezier");
    /// assert_eq!(Method::JuttlerQMotion.representation(), "dual-quaternion-bezier");
    /// ```
    pub fn representation(self) -> &'static str {
        match self {
            Method::CcmAdditive => "additive-bezier",
            Method::CcmMultiplicative => "multiplicative-bezier",
            Method::WlLinear => "wl-relative-rotor",
            Method::WlQuadratic => "wl-bivector-quadratic",
            Method::WlDirect => "wl-bivector-linear",
            Method::HexanionLinear => "hexanion-linear",
            Method::HexanionDecoupled => "hexanion-decoupled",
            Method::HexanionBlend => "hexanion-blend",
            Method::JuttlerQMotion
            | Method::JuttlerAffine
            | Method::JuttlerProjective
            | Method::JuttlerTrt
            | Method::JuttlerMinimal
            | Method::JuttlerSpline
            | Method::JuttlerBSpline
            | Method::JuttlerMinimalSpline => "dual-quaternion-bezier",
        }
    }

    /// The optional inputs the method reads besides the key poses and their parameters, by
    /// their `gam interpolate` spec keys (`velocities`, `shape`, `gamma`, `l1`, `weights`, `degree`); an input
    /// given to a method that does not read it is refused ([`BuildError::Unused`]).
    ///
    /// ```
    /// use motion::method::Method;
    /// assert_eq!(Method::CcmAdditive.inputs(), ["velocities", "shape", "gamma"]);
    /// assert!(Method::WlLinear.inputs().is_empty() && Method::JuttlerQMotion.inputs().is_empty());
    /// assert_eq!(Method::JuttlerTrt.inputs(), ["l1"]);
    /// ```
    pub fn inputs(self) -> &'static [&'static str] {
        match self {
            Method::CcmAdditive | Method::CcmMultiplicative => &["velocities", "shape", "gamma"],
            Method::JuttlerTrt => &["l1"],
            Method::JuttlerSpline | Method::JuttlerMinimalSpline => &["velocities"],
            Method::HexanionBlend => &["weights"],
            Method::JuttlerBSpline => &["degree"],
            Method::WlLinear
            | Method::WlQuadratic
            | Method::WlDirect
            | Method::HexanionLinear
            | Method::HexanionDecoupled
            | Method::JuttlerQMotion
            | Method::JuttlerAffine
            | Method::JuttlerProjective
            | Method::JuttlerMinimal => &[],
        }
    }

    /// True when every motion of the method has rational point trajectories (`gam trajectory`
    /// accepts it): `ccm-additive` (an additive Bézier motion of degree `n` moves points on
    /// rational curves of degree `2n`) and the Jüttler methods; not the multiplicative, W-L
    /// and hexanion methods (exp of generators).
    ///
    /// ```
    /// use motion::method::Method;
    /// assert!(Method::JuttlerQMotion.is_rational() && !Method::WlLinear.is_rational());
    /// ```
    pub fn is_rational(self) -> bool {
        self.kind() == SegmentKind::Additive
    }
}
