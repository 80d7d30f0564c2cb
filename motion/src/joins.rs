//! Joins between motion segments (Secs. 3-4 of the main paper): the velocity bivector of an
//! end condition (Theorem 3.2), the velocity indicatrix `Ψ = λ(ν + γ)` with a shape factor
//! `λ` and a pseudoscalar `γ`, the control poses next to the ends of a degree-`n` segment that
//! give it a prescribed end indicatrix (eqs. 22-23), and a continuity check between segments.
//!
//! **Velocity bivector.** A body point instantaneously at `r` with velocity `v`, and a body
//! angular velocity `Ω`, give (Theorem 3.2, eq. 14)
//!
//! ```text
//! ν = Ω e123 + u einf,   u = v - Ω × r   (the velocity of the body point at the origin),
//! Ω e123 = Ω1 e23 - Ω2 e13 + Ω3 e12.
//! ```
//!
//! **Velocity indicatrix.** `Ψ = λ(ν + γ)` with `γ = α + βω`: the reading of eqs. (22)-(23)
//! that reproduces the printed numbers of Sec. 5.2 (where `Ψ0 = λ0(ν0 + γ0)`; the literal
//! `λ0 Ψ0 + γ0` of eq. 22 does not reproduce the `λ0 = 4` poses).
//!
//! **Control poses** of a degree-`n` segment `S0..Sn` (n ≥ 1) with end indicatrices `Ψ0`, `Ψn`:
//!
//! ```text
//! additive:        S1 = S0 (1 + Ψ0/(2n)),     S_{n-1} = Sn (1 - Ψn/(2n)),
//! multiplicative:  S1 = S0 exp(Ψ0/(2n)),      S_{n-1} = Sn exp(-Ψn/(2n)).
//! ```
//!
//! By Corollary 4.6 the additive segment then has `Ψ(0) = Ψ0` and `Ψ(1) = Ψn` exactly, for any
//! non-singular `S0`, `Sn`. The multiplicative one has `Ψ(0) = Ψ0` when `S0` is unitary (in
//! general up to the pseudoscalar `2n log(rev(S0) S0)`), and `Ψ(1) = Ψn` when every control pose
//! is unitary (`γ = 0` at both ends); a non-zero `γ` makes `S1` or `S_{n-1}` non-unit, and then
//! the tableau ends at a pseudoscalar multiple of `Sn` (eq. 16) and only the bivector part of
//! `Ψ(1)` is `λn νn`. For multiplicative segments `γ` changes no transform at all (Lemma 4.1);
//! it is a design freedom of additive segments. A *C1 join* uses `λ = 1` on both sides
//! (any `γ`: a jump in `Ψ` that is a pseudoscalar leaves the velocities continuous); a
//! *G1 join* has different positive `λ` on the two sides, so `ν` jumps by a positive factor.
//!
//! ```
//! use motion::joins::{self, EndCondition, SegmentKind, Shape};
//! // Sec. 5.1 of the paper, start: at rest at the origin, v = (1,1,1), Ω = (1,2,3).
//! let start = EndCondition::from_axis_angle(&[0.0, 0.0, 0.0], &[0.0, 0.0, 1.0], &0.0, &[1.0, 1.0, 1.0], &[1.0, 2.0, 3.0])?;
//! let psi = start.velocity_indicatrix(&Shape::unit());
//! let s1 = joins::start_control_pose(SegmentKind::Additive, &start.pose, &psi, 3)?;
//! assert_eq!(s1.e12, 0.5); // printed: S1 = 1.000 + 0.500 e12 - 0.333 e13 + ...
//! # Ok::<(), motion::joins::JoinError>(())
//! ```

use crate::blend::Blend;
use crate::pose::is_positive;
use crate::{Bivector, Even, Pseudoscalar, Vec3};
use crate::{MotionError, Pose};
use algebra_core::{Real, Ring};

/// Why a join or Hermite construction failed.
///
/// ```
/// use motion::joins::{self, JoinError, SegmentKind};
/// use motion::{Even, Pose};
/// let e = joins::start_control_pose(SegmentKind::Additive, &Pose::<f64>::identity(), &Even::zero(), 0);
/// assert!(matches!(e, Err(JoinError::Degree { degree: 0, min: 1 })));
/// ```
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum JoinError {
    /// A segment degree below the minimum (1 for one end, 3 for both ends: the two end
    /// conditions fix `S0, S1, S_{n-1}, Sn`, which must be four different control poses).
    #[error("the degree must be at least {min} (got {degree})")]
    Degree {
        /// The degree asked for.
        degree: usize,
        /// The smallest degree allowed here.
        min: usize,
    },
    /// A segment degree above [`crate::hermite::MAX_SEGMENT_DEGREE`] (its control poses would
    /// not fit in memory, and evaluation costs `O(n²)` slerps).
    #[error("the degree must be at most {max} (got {degree})")]
    DegreeTooLarge {
        /// The degree asked for.
        degree: usize,
        /// The largest degree allowed.
        max: usize,
    },
    /// Fewer than two precision poses, a list of the wrong length, or a bad parameter list.
    #[error("{0}")]
    Input(String),
    /// A pose operation failed (singular pose, overflow in exp, ...).
    #[error(transparent)]
    Motion(#[from] MotionError),
}

/// How a segment combines its control poses (Sec. 4 of the paper).
///
/// ```
/// use motion::SegmentKind;
/// assert_eq!(SegmentKind::Additive.name(), "additive");
/// assert_eq!("multiplicative".parse::<SegmentKind>(), Ok(SegmentKind::Multiplicative));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SegmentKind {
    /// Additive Bezier motion, `Φ(A, B; t) = (1 - t)A + tB` (eqs. 17-18): joins by eq. (22).
    Additive,
    /// Multiplicative (slerp) Bezier motion, `Φ(A, B; t) = A (rev(A) B)^t` (eq. 15, Fig. 2):
    /// joins by eq. (23).
    Multiplicative,
}

crate::names::named!("motion::SegmentKind", SegmentKind { Additive => "additive", Multiplicative => "multiplicative" });

impl std::str::FromStr for SegmentKind {
    type Err = String;
    /// `additive` or `multiplicative`.
    fn from_str(s: &str) -> Result<Self, String> {
        SegmentKind::from_name(s)
            .ok_or_else(|| format!("unknown segment kind `{s}` (expected additive or multiplicative)"))
    }
}

/// The shape parameters of one segment end: the scalar shape factor `λ` and the pseudoscalar
/// `γ = α + βω`, giving `Ψ = λ(ν + γ)`. [`Shape::unit`] (`λ = 1`, `γ = 0`) makes `Ψ = ν`.
///
/// ```
/// use motion::{Pseudoscalar, Shape};
/// let s = Shape::new(4.0, Pseudoscalar::new(0.5, 0.5)); // Sec. 5.2: λ0 = 4, γ0 = ½ + ½ω
/// assert_eq!(s.lambda, 4.0);
/// assert_eq!(Shape::<f64>::unit(), Shape::new(1.0, Pseudoscalar::zero()));
/// ```
#[derive(Clone, PartialEq)]
pub struct Shape<T> {
    /// The shape factor `λ` (positive for a G1 join; `1` keeps the prescribed speed).
    pub lambda: T,
    /// The pseudoscalar `γ = α + βω` added to the velocity bivector.
    pub gamma: Pseudoscalar<T>,
}

impl<T: Ring> Shape<T> {
    /// `λ` and `γ`.
    ///
    /// ```
    /// let s = motion::Shape::new(2.0, motion::Pseudoscalar::new(1.0, -0.5));
    /// assert_eq!(s.gamma.e123inf, -0.5);
    /// ```
    pub fn new(lambda: T, gamma: Pseudoscalar<T>) -> Self {
        Shape { lambda, gamma }
    }

    /// `λ = 1`, `γ = 0`: `Ψ = ν`, the C1 default.
    ///
    /// ```
    /// assert_eq!(motion::Shape::<f64>::unit().lambda, 1.0);
    /// ```
    pub fn unit() -> Self {
        Shape { lambda: T::one(), gamma: Pseudoscalar::zero() }
    }

    /// The shape factor `λ` alone (`γ = 0`).
    ///
    /// ```
    /// let s = motion::Shape::factor(0.5);
    /// assert_eq!((s.lambda, s.gamma.scalar), (0.5, 0.0));
    /// ```
    pub fn factor(lambda: T) -> Self {
        Shape { lambda, gamma: Pseudoscalar::zero() }
    }

    /// `Ψ = λ(ν + γ)` for the velocity bivector `nu` ([`shaped_indicatrix`]).
    ///
    /// ```
    /// use motion::{Bivector, Pseudoscalar, Shape};
    /// let nu = Bivector::new(0.0, 0.0, 1.0, 0.0, 0.0, 2.0);
    /// let psi = Shape::new(2.0, Pseudoscalar::new(0.5, 1.0)).indicatrix(&nu);
    /// assert_eq!((psi.scalar, psi.e23, psi.e3inf, psi.e123inf), (1.0, 2.0, 4.0, 2.0));
    /// ```
    pub fn indicatrix(&self, nu: &Bivector<T>) -> Even<T> {
        shaped_indicatrix(nu, &self.lambda, &self.gamma)
    }

    /// The shape with `λ` multiplied by `h` (`γ` kept): the end indicatrix of a segment
    /// reparametrized from an interval of length `h` to `[0, 1]` is `h Ψ`.
    ///
    /// ```
    /// assert_eq!(motion::Shape::factor(1.5).stretched(&2.0).lambda, 3.0);
    /// ```
    pub fn stretched(&self, h: &T) -> Self {
        Shape { lambda: self.lambda.mul_ref(h), gamma: self.gamma.clone() }
    }
}

/// The velocity bivector `ν = Ω e123 + u einf` with `u = v - Ω × r` (Theorem 3.2 and eq. 14)
/// of an end condition, as an even element with zero scalar and ω parts: `angular_velocity` is
/// `Ω`, `velocity` the velocity `v` of a body point instantaneously at `position` `r`, and `u`
/// the velocity of the body point at the origin. Exact over exact scalars. (The velocity
/// bivector *of a motion* at a parameter value is [`crate::velocity::velocity_bivector`].)
///
/// ```
/// use motion::joins::end_velocity_bivector;
/// // Sec. 5.2, end: r = (0, 10, 0), v = (0, 4, 0), Ω = (π/8, 0, 0).
/// let w = std::f64::consts::PI / 8.0;
/// let nu = end_velocity_bivector(&[w, 0.0, 0.0], &[0.0, 4.0, 0.0], &[0.0, 10.0, 0.0]);
/// assert_eq!((nu.e23, nu.e2inf), (w, 4.0));
/// assert!((nu.e3inf + 3.927).abs() < 5e-4); // printed: ν3 = 0.393 e23 + 4.000 e2inf - 3.927 e3inf
/// ```
pub fn end_velocity_bivector<T: Ring>(angular_velocity: &[T; 3], velocity: &[T; 3], position: &[T; 3]) -> Bivector<T> {
    let omega = Vec3::from(angular_velocity);
    let u = Vec3::from(velocity).sub(&omega.cross(&Vec3::from(position)));
    Bivector::from_parts(&omega, &u)
}

/// The velocity indicatrix `Ψ = λ(ν + γ)` (the reading of eqs. 22-23 that reproduces Sec. 5.2);
/// only the bivector part of `nu` is used (its scalar and ω parts are ignored).
///
/// ```
/// use motion::joins::shaped_indicatrix;
/// use motion::{Bivector, Even, Pseudoscalar};
/// let nu = Bivector::new(0.0, 0.0, -0.25, 0.0, 0.0, 8.0);
/// let psi = shaped_indicatrix(&nu, &4.0, &Pseudoscalar::new(0.5, 0.5));
/// assert_eq!(psi, Even::new(2.0, 0.0, 0.0, -1.0, 0.0, 0.0, 32.0, 2.0));
/// ```
pub fn shaped_indicatrix<T: Ring>(nu: &Bivector<T>, lambda: &T, gamma: &Pseudoscalar<T>) -> Even<T> {
    let l = |x: &T| x.mul_ref(lambda);
    Even::new(
        l(&gamma.scalar),
        l(&nu.e12),
        l(&nu.e13),
        l(&nu.e23),
        l(&nu.e1inf),
        l(&nu.e2inf),
        l(&nu.e3inf),
        l(&gamma.e123inf),
    )
}

/// The end conditions at a precision pose: the pose, and the velocity `velocity` of the body
/// point instantaneously at `position` together with the body's angular velocity
/// `angular_velocity` (in the fixed frame, as in Theorem 3.2).
///
/// [`EndCondition::from_axis_angle`] is the paper's form (Secs. 5.1-5.2): `S = R T`, the rotation
/// about the axis through the origin followed by the translation to `position`, so that
/// `position` is where the body origin (the reference point) goes. The fields are independent:
/// `position` may be any body point whose velocity is known (Corollary 3.3).
///
/// ```
/// use motion::EndCondition;
/// // Sec. 5.2, start.
/// let c = EndCondition::from_axis_angle(&[0.0; 3], &[1.0, 0.0, 0.0], &0.0, &[0.0, 0.0, 8.0],
///     &[-std::f64::consts::FRAC_PI_4, 0.0, 0.0])?;
/// let nu = c.velocity_bivector(); // printed: ν0 = -0.785 e23 + 8.000 e3inf
/// assert_eq!((nu.e3inf, (nu.e23 * 1000.0).round()), (8.0, -785.0));
/// # Ok::<(), motion::MotionError>(())
/// ```
#[derive(Clone, PartialEq)]
pub struct EndCondition<T> {
    /// The precision pose `S` (unitary in the paper's construction; eqs. 22-23 assume it).
    pub pose: Pose<T>,
    /// `r`: where the body point whose velocity is given is (normally the image of the body
    /// origin, the translation of `S = R T`).
    pub position: [T; 3],
    /// `v`: the velocity of that body point.
    pub velocity: [T; 3],
    /// `Ω`: the angular velocity of the body.
    pub angular_velocity: [T; 3],
}

impl<T: Ring> EndCondition<T> {
    /// The four fields as given.
    ///
    /// ```
    /// use motion::{EndCondition, Pose};
    /// let c = EndCondition::new(Pose::translation(&[1.0, 0.0, 0.0]), [1.0, 0.0, 0.0], [0.0; 3], [0.0, 0.0, 1.0]);
    /// assert_eq!(c.velocity_bivector().e2inf, 0.0 - 1.0); // u = v - Ω × r = (0, -1, 0)
    /// ```
    pub fn new(pose: Pose<T>, position: [T; 3], velocity: [T; 3], angular_velocity: [T; 3]) -> Self {
        EndCondition { pose, position, velocity, angular_velocity }
    }

    /// `ν = Ω e123 + (v - Ω × r) einf` (see [`end_velocity_bivector`]).
    ///
    /// ```
    /// use motion::{EndCondition, Pose};
    /// let c = EndCondition::new(Pose::<f64>::identity(), [0.0; 3], [1.0, 1.0, 1.0], [1.0, 2.0, 3.0]);
    /// let nu = c.velocity_bivector();
    /// assert_eq!((nu.e12, nu.e13, nu.e23, nu.e1inf), (3.0, -2.0, 1.0, 1.0));
    /// ```
    pub fn velocity_bivector(&self) -> Bivector<T> {
        end_velocity_bivector(&self.angular_velocity, &self.velocity, &self.position)
    }

    /// `Ψ = λ(ν + γ)` for the given shape.
    ///
    /// ```
    /// use motion::{EndCondition, Pose, Shape};
    /// let c = EndCondition::new(Pose::<f64>::identity(), [0.0; 3], [1.0, 0.0, 0.0], [0.0; 3]);
    /// assert_eq!(c.velocity_indicatrix(&Shape::factor(2.0)).e1inf, 2.0);
    /// ```
    pub fn velocity_indicatrix(&self, shape: &Shape<T>) -> Even<T> {
        shape.indicatrix(&self.velocity_bivector())
    }
}

impl<T: Real> EndCondition<T> {
    /// The paper's end condition: `S = R T` with `R` the rotation by `angle` about `axis`
    /// (through the origin, normalised here) and `T` the translation to `position`; `velocity`
    /// is the velocity of the reference point (at `position`) and `angular_velocity` is `Ω`.
    /// Fails for a zero or non-finite axis and non-finite input.
    ///
    /// ```
    /// use motion::EndCondition;
    /// let c = EndCondition::from_axis_angle(&[8.0, 10.0, 12.0], &[1.0, 2.0, 3.0], &1.959, &[1.0, 5.0, 3.0], &[2.0, 1.0, 1.0])?;
    /// assert_eq!(format!("{:.3}", c.pose.scalar), "0.557"); // Sec. 5.1, S3
    /// assert!(EndCondition::from_axis_angle(&[0.0; 3], &[0.0; 3], &0.0, &[0.0; 3], &[0.0; 3]).is_err());
    /// # Ok::<(), motion::MotionError>(())
    /// ```
    pub fn from_axis_angle(
        position: &[T; 3],
        axis: &[T; 3],
        angle: &T,
        velocity: &[T; 3],
        angular_velocity: &[T; 3],
    ) -> Result<Self, MotionError> {
        for x in velocity.iter().chain(angular_velocity) {
            if !x.is_finite() {
                return Err(MotionError::NotFinite { op: "end condition", value: x.to_string() });
            }
        }
        let pose = Pose::from_axis_angle_translation(axis, angle, position)?;
        Ok(EndCondition {
            pose,
            position: position.clone(),
            velocity: velocity.clone(),
            angular_velocity: angular_velocity.clone(),
        })
    }

    /// An end condition whose reference point is the body origin: `position` is its image
    /// `F_S(0)` under `pose`. Fails for a singular pose.
    ///
    /// ```
    /// use motion::{EndCondition, Pose};
    /// let s = Pose::<f64>::from_axis_angle_translation(&[0.0, 0.0, 1.0], &1.0, &[1.0, 2.0, 3.0])?;
    /// let c = EndCondition::at_body_origin(s, [0.0; 3], [0.0, 0.0, 1.0])?;
    /// assert!((c.position[1] - 2.0).abs() < 1e-15);
    /// # Ok::<(), motion::MotionError>(())
    /// ```
    pub fn at_body_origin(pose: Pose<T>, velocity: [T; 3], angular_velocity: [T; 3]) -> Result<Self, MotionError> {
        let position = pose.transform_point(&[T::zero(), T::zero(), T::zero()])?;
        Ok(EndCondition { pose, position, velocity, angular_velocity })
    }
}

fn check_degree(degree: usize, min: usize) -> Result<(), JoinError> {
    if degree < min { Err(JoinError::Degree { degree, min }) } else { Ok(()) }
}

/// `1/(2n)` as an exact constant.
fn inv_2n<T: Ring>(degree: usize) -> T {
    T::from_ratio(1, 2 * degree as i64)
}

/// Additive start (eq. 22 as read in Sec. 5.2): `S1 = S0 (1 + Ψ0/(2n))` for a segment of
/// degree `n ≥ 1`. Then `Ψ(0) = 2n S0⁻¹(S1 - S0) = Ψ0` exactly (Corollary 4.6(i)). Exact over
/// exact scalars.
///
/// ```
/// use algebra_core::rational::{q, ratio};
/// use motion::{Even, Pose, joins};
/// let psi = Even::new(q(0), q(3), q(0), q(0), q(6), q(0), q(0), q(0));
/// let s1 = joins::additive_start(&Pose::identity(), &psi, 3)?;
/// assert_eq!(s1.e12, ratio(1, 2));
/// assert_eq!(s1.e1inf, q(1));
/// # Ok::<(), motion::joins::JoinError>(())
/// ```
pub fn additive_start<T: Ring>(s0: &Pose<T>, psi0: &Even<T>, degree: usize) -> Result<Pose<T>, JoinError> {
    check_degree(degree, 1)?;
    let factor = &Even::one() + &psi0.scale(&inv_2n(degree));
    Ok(s0 * &factor)
}

/// Additive end (eq. 22 as read in Sec. 5.2): `S_{n-1} = Sn (1 - Ψn/(2n))`, so that
/// `Ψ(1) = 2n Sn⁻¹(Sn - S_{n-1}) = Ψn` exactly (Corollary 4.6(i)).
///
/// ```
/// use algebra_core::rational::{q, ratio};
/// use motion::{Even, Pose, joins};
/// let psi = Even::new(q(0), q(0), q(0), q(0), q(6), q(0), q(0), q(0));
/// let s2 = joins::additive_end(&Pose::identity(), &psi, 3)?;
/// assert_eq!(s2.e1inf, q(-1));
/// # Ok::<(), motion::joins::JoinError>(())
/// ```
pub fn additive_end<T: Ring>(sn: &Pose<T>, psin: &Even<T>, degree: usize) -> Result<Pose<T>, JoinError> {
    check_degree(degree, 1)?;
    let factor = &Even::one() - &psin.scale(&inv_2n(degree));
    Ok(sn * &factor)
}

/// Multiplicative start (eq. 23): `S1 = S0 exp(Ψ0/(2n))`. With `S0` unitary,
/// `Ψ(0) = 2n log(rev(S0) S1) = Ψ0` (Corollary 4.6(ii), when the rotational half-angle of
/// `Ψ0/(2n)` is below π).
///
/// ```
/// use motion::{Even, Pose, joins};
/// let psi = Even::new(0.0, 0.0, 0.0, 0.0, 6.0, 0.0, 0.0, 0.0);
/// let s1 = joins::multiplicative_start(&Pose::identity(), &psi, 3)?;
/// assert_eq!(s1, Pose::translation(&[2.0, 0.0, 0.0]));
/// # Ok::<(), motion::joins::JoinError>(())
/// ```
pub fn multiplicative_start<T: Real>(s0: &Pose<T>, psi0: &Even<T>, degree: usize) -> Result<Pose<T>, JoinError> {
    check_degree(degree, 1)?;
    Ok(s0 * &Pose::exp(&psi0.scale(&inv_2n(degree)))?)
}

/// Multiplicative end (eq. 23): `S_{n-1} = Sn exp(-Ψn/(2n))`, so that with `Sn` unitary
/// `Ψ(1) = -2n log(rev(Sn) S_{n-1}) = Ψn` (Corollary 4.6(ii)).
///
/// ```
/// use motion::{Even, Pose, joins};
/// let psi = Even::new(0.0, 0.0, 0.0, 0.0, 6.0, 0.0, 0.0, 0.0);
/// let s2 = joins::multiplicative_end(&Pose::identity(), &psi, 3)?;
/// assert_eq!(s2, Pose::translation(&[-2.0, 0.0, 0.0]));
/// # Ok::<(), motion::joins::JoinError>(())
/// ```
pub fn multiplicative_end<T: Real>(sn: &Pose<T>, psin: &Even<T>, degree: usize) -> Result<Pose<T>, JoinError> {
    check_degree(degree, 1)?;
    let m = psin.scale(&inv_2n::<T>(degree)).scale(&T::one().neg_ref());
    Ok(sn * &Pose::exp(&m)?)
}

/// The control pose `S1` next to the start `S0` of a degree-`n` segment of the given kind whose
/// velocity indicatrix at `t = 0` is to be `psi0`: [`additive_start`] or
/// [`multiplicative_start`].
///
/// ```
/// use motion::{Even, Pose, SegmentKind, joins};
/// let psi = Even::new(0.0, 0.0, 0.0, 0.0, 6.0, 0.0, 0.0, 0.0); // a pure translation velocity
/// let a = joins::start_control_pose(SegmentKind::Additive, &Pose::identity(), &psi, 3)?;
/// let m = joins::start_control_pose(SegmentKind::Multiplicative, &Pose::identity(), &psi, 3)?;
/// assert_eq!(a, m); // 1 + e1inf either way
/// # Ok::<(), motion::joins::JoinError>(())
/// ```
pub fn start_control_pose<T: Real>(
    kind: SegmentKind,
    s0: &Pose<T>,
    psi0: &Even<T>,
    degree: usize,
) -> Result<Pose<T>, JoinError> {
    crate::with_blend!(kind, B => B::start_control_pose(s0, psi0, degree))
}

/// The control pose `S_{n-1}` next to the end `Sn` of a degree-`n` segment of the given kind
/// whose velocity indicatrix at `t = 1` is to be `psin`: [`additive_end`] or
/// [`multiplicative_end`].
///
/// ```
/// use motion::{Even, Pose, SegmentKind, joins};
/// let psi = Even::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 3.0, 0.0);
/// let s = joins::end_control_pose(SegmentKind::Additive, &Pose::identity(), &psi, 3)?;
/// assert_eq!(s, Pose::translation(&[0.0, 0.0, -1.0]));
/// # Ok::<(), motion::joins::JoinError>(())
/// ```
pub fn end_control_pose<T: Real>(
    kind: SegmentKind,
    sn: &Pose<T>,
    psin: &Even<T>,
    degree: usize,
) -> Result<Pose<T>, JoinError> {
    crate::with_blend!(kind, B => B::end_control_pose(sn, psin, degree))
}

/// The velocity indicatrices `[Ψ(0), Ψ(1)]` at the ends of a Bezier segment from its control
/// poses `S0..Sn` (Corollary 4.6): additive `2n S0⁻¹(S1 - S0)` and `2n Sn⁻¹(Sn - S_{n-1})`
/// (eq. 20); multiplicative `2n log(rev(S0) S1)` and `-2n log(rev(Sn) S_{n-1})` (eq. 21; the
/// end value assumes the reversal symmetry of Theorem 4.5, which holds for unitary control
/// poses; with non-unit ones it is exact in the bivector part ν, which is what continuity
/// depends on). Needs at least two control poses; fails for singular ones.
///
/// ```
/// use motion::{Pose, SegmentKind, joins};
/// let controls = [Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0]), Pose::translation(&[2.0, 0.0, 0.0])];
/// let [a, b] = joins::end_indicatrices(SegmentKind::Additive, &controls)?;
/// assert_eq!((a.e1inf, b.e1inf), (2.0, 2.0)); // 2n · ½ · 1 with n = 2
/// # Ok::<(), motion::joins::JoinError>(())
/// ```
pub fn end_indicatrices<T: Real>(kind: SegmentKind, controls: &[Pose<T>]) -> Result<[Even<T>; 2], JoinError> {
    crate::with_blend!(kind, B => B::end_indicatrices(controls))
}

/// How two segments meet at a join (the classification of [`check_join`]).
///
/// ```
/// use motion::Continuity;
/// let c: Continuity<f64> = Continuity::G1 { factor: 2.0 };
/// assert!(c.is_g1() && !c.is_c1());
/// assert!(Continuity::<f64>::C1.is_g1());
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum Continuity<T> {
    /// The poses on the two sides are not equivalent (different transforms).
    Discontinuous,
    /// Continuous pose; the velocity bivectors are not positive multiples of each other.
    C0,
    /// Continuous pose and `ν_right = factor · ν_left` with `factor > 0` (`factor ≠ 1`): the
    /// linear and angular velocities change by a common positive factor.
    G1 {
        /// The factor `k` in `ν_right = k ν_left`.
        factor: T,
    },
    /// Continuous pose and continuous velocity bivector (`Ψ` may jump by a pseudoscalar).
    C1,
}

impl<T> Continuity<T> {
    /// True for [`Continuity::C1`].
    ///
    /// ```
    /// assert!(motion::Continuity::<f64>::C1.is_c1());
    /// ```
    pub fn is_c1(&self) -> bool {
        matches!(self, Continuity::C1)
    }

    /// True for [`Continuity::G1`] and [`Continuity::C1`] (C1 implies G1).
    ///
    /// ```
    /// assert!(!motion::Continuity::<f64>::C0.is_g1());
    /// ```
    pub fn is_g1(&self) -> bool {
        matches!(self, Continuity::G1 { .. } | Continuity::C1)
    }
}

/// The jumps at a join and their classification (see [`check_join`]).
///
/// ```
/// use motion::{Bivector, Even, Pose, joins};
/// let nu = Even::from(&Bivector::new(1.0, 0.0, 0.0, 1.0, 0.0, 0.0));
/// let j = joins::check_join(&Pose::identity(), &nu, &Pose::identity(), &nu.scale(&3.0), &1e-12)?;
/// assert_eq!(j.nu_jump.e12, 2.0);
/// assert_eq!(j.continuity, motion::Continuity::G1 { factor: 3.0 });
/// # Ok::<(), motion::MotionError>(())
/// ```
#[derive(Clone, PartialEq)]
pub struct JoinCheck<T> {
    /// `S_right(0) - S_left(1)` (zero for a join through the same control pose).
    pub pose_jump: Even<T>,
    /// `ν_right - ν_left`: zero for C1.
    pub nu_jump: Bivector<T>,
    /// `Ψ_right - Ψ_left` (a pseudoscalar for C1 with different `γ` on the two sides).
    pub indicatrix_jump: Even<T>,
    /// The classification.
    pub continuity: Continuity<T>,
}

fn bivector_components<T>(b: &Bivector<T>) -> [&T; 6] {
    [&b.e12, &b.e13, &b.e23, &b.e1inf, &b.e2inf, &b.e3inf]
}

fn max_abs<'a, T: Real + 'a>(xs: impl IntoIterator<Item = &'a T>) -> T {
    xs.into_iter().map(Real::abs).fold(T::zero(), |m, x| if x > m { x } else { m })
}

/// Checks a join between a segment ending at `left_end` with velocity indicatrix `left_psi`
/// and one starting at `right_start` with `right_psi`.
///
/// The poses are continuous when they are equivalent within `tol` ([`Pose::is_equivalent`]:
/// the same transform; multiplicative segments may end at a pseudoscalar multiple of their last
/// control pose). With `ν` the bivector parts and `s` the largest component of `ν_left`,
/// `ν_right`: C1 when every component of `ν_right - ν_left` is within `tol·s`; G1 with factor
/// `k = (ν_left·ν_right)/(ν_left·ν_left)` (component-wise dot products) when `k > 0` and
/// `ν_right - k ν_left` is within `tol·s`; otherwise C0. Fails for singular poses.
///
/// ```
/// use motion::{Bivector, Continuity, Even, Pose, joins};
/// let s = Pose::<f64>::identity();
/// let nu = Even::from(&Bivector::new(1.0, 2.0, 0.0, 0.0, 0.0, 5.0));
/// let with_gamma = &nu + &Even::new(0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 2.0);
/// assert_eq!(joins::check_join(&s, &nu, &s, &with_gamma, &1e-12)?.continuity, Continuity::C1);
/// assert_eq!(joins::check_join(&s, &nu, &s, &nu.scale(&-1.0), &1e-12)?.continuity, Continuity::C0);
/// let t = Pose::translation(&[1.0, 0.0, 0.0]);
/// assert_eq!(joins::check_join(&s, &nu, &t, &nu, &1e-12)?.continuity, Continuity::Discontinuous);
/// # Ok::<(), motion::MotionError>(())
/// ```
pub fn check_join<T: Real>(
    left_end: &Pose<T>,
    left_psi: &Even<T>,
    right_start: &Pose<T>,
    right_psi: &Even<T>,
    tol: &T,
) -> Result<JoinCheck<T>, MotionError> {
    let pose_jump = right_start - left_end;
    let indicatrix_jump = right_psi - left_psi;
    let a = left_psi.project_to_bivector();
    let b = right_psi.project_to_bivector();
    let nu_jump = &b - &a;
    let continuity = if !left_end.is_equivalent(right_start, tol)? {
        Continuity::Discontinuous
    } else {
        let scale = max_abs(bivector_components(&a).into_iter().chain(bivector_components(&b)));
        let bound = tol.mul_ref(&scale);
        if max_abs(bivector_components(&nu_jump)) <= bound {
            Continuity::C1
        } else {
            let dot = |x: &Bivector<T>, y: &Bivector<T>| {
                bivector_components(x)
                    .into_iter()
                    .zip(bivector_components(y))
                    .fold(T::zero(), |acc, (p, q)| acc.add_ref(&p.mul_ref(q)))
            };
            let aa = dot(&a, &a);
            let factor = if is_positive(&aa) { dot(&a, &b).div_ref(&aa) } else { T::zero() };
            let residual = &b - &a.scale(&factor);
            if is_positive(&factor) && max_abs(bivector_components(&residual)) <= bound {
                Continuity::G1 { factor }
            } else {
                Continuity::C0
            }
        }
    };
    Ok(JoinCheck { pose_jump, nu_jump, indicatrix_jump, continuity })
}

/// [`check_join`] between two Bezier segments given by their control poses: the last control
/// pose of `left` against the first of `right`, with the end indicatrices of Corollary 4.6
/// ([`end_indicatrices`]).
///
/// ```
/// use motion::{Continuity, EndCondition, SegmentKind, Shape, hermite};
/// let c = |x: f64| EndCondition::from_axis_angle(&[x, 0.0, 0.0], &[0.0, 0.0, 1.0], &x, &[1.0, 0.0, 0.0], &[0.0, 0.0, 1.0]);
/// let (a, b, d) = (c(0.0)?, c(1.0)?, c(2.0)?);
/// let left = hermite::hermite_segment(SegmentKind::Additive, 3, &a, &b, &Shape::unit(), &Shape::unit())?;
/// let right = hermite::hermite_segment(SegmentKind::Additive, 3, &b, &d, &Shape::factor(2.0), &Shape::unit())?;
/// let j = motion::joins::check_segment_join(
///     (SegmentKind::Additive, left.control_poses()), (SegmentKind::Additive, right.control_poses()), &1e-12)?;
/// assert!(matches!(j.continuity, Continuity::G1 { factor } if (factor - 2.0).abs() < 1e-12));
/// # Ok::<(), motion::joins::JoinError>(())
/// ```
pub fn check_segment_join<T: Real>(
    left: (SegmentKind, &[Pose<T>]),
    right: (SegmentKind, &[Pose<T>]),
    tol: &T,
) -> Result<JoinCheck<T>, JoinError> {
    let [_, left_psi] = end_indicatrices(left.0, left.1)?;
    let [right_psi, _] = end_indicatrices(right.0, right.1)?;
    let (left_end, right_start) = (&left.1[left.1.len() - 1], &right.1[0]);
    Ok(check_join(left_end, &left_psi, right_start, &right_psi, tol)?)
}

impl<T: Ring> std::fmt::Debug for Shape<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Shape").field("lambda", &self.lambda).field("gamma", &self.gamma).finish()
    }
}

impl<T: Ring> std::fmt::Debug for EndCondition<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("EndCondition")
            .field("pose", &self.pose)
            .field("position", &self.position)
            .field("velocity", &self.velocity)
            .field("angular_velocity", &self.angular_velocity)
            .finish()
    }
}

impl<T: Ring> std::fmt::Debug for JoinCheck<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("JoinCheck")
            .field("pose_jump", &self.pose_jump)
            .field("nu_jump", &self.nu_jump)
            .field("indicatrix_jump", &self.indicatrix_jump)
            .field("continuity", &self.continuity)
            .finish()
    }
}
