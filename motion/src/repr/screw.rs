//! The screw (Chasles) decomposition of a pose, and Jüttler's distances and angle between two
//! poses (his Sec. 2).
//!
//! Every rigid motion is a rotation by `θ ∈ [0, π]` about an axis (unit `axis`, through
//! `point`, the point of the axis nearest the origin) followed by the translation `d` along
//! the axis; `pitch = d/θ`. It is read off the principal hexanion `<ω, m>` of the pose
//! ([`Hexanion::from_pose`]): `θ = |ω|`, `axis = ω/θ`, `d = (ω·m)/θ`, `point = ω × m/θ²`
//! (Angelidis (27)). Edge cases, as in `gam pose`: a pure translation has `θ = 0`,
//! `axis = t/|t|`, `point = 0`, `d = |t|`, no pitch; the identity has `axis = 0`, `d = 0`. At
//! `θ = π` the axis direction is the one of the principal hexanion (either sign is the same
//! motion; `d` changes sign with it).
//!
//! ```
//! use motion::{Pose, repr::screw::Screw};
//! let s = Pose::<f64>::from_axis_angle_translation(&[0.0, 0.0, 1.0], &1.0, &[0.0, 0.0, 3.0]).unwrap();
//! let screw = Screw::of(&s).unwrap();
//! assert!((screw.angle - 1.0).abs() < 1e-15 && (screw.translation - 3.0).abs() < 1e-15);
//! assert!((screw.pitch.unwrap() - 3.0).abs() < 1e-15);
//! ```

use crate::repr::hexanion::Hexanion;
use crate::repr::vec3::{cross, dot, norm, sub, zero};
use crate::{MotionError, Pose};
use algebra_core::Real;

/// The screw parameters of a rigid motion (module docs).
///
/// ```
/// use motion::{Pose, repr::screw::Screw};
/// let s = Screw::of(&Pose::translation(&[0.0, 0.0, -5.0])).unwrap();
/// assert_eq!((s.axis, s.angle, s.translation, s.point, s.pitch), ([0.0, 0.0, -1.0], 0.0, 5.0, [0.0; 3], None));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Screw<T> {
    /// The unit axis direction (`[0, 0, 0]` for the identity).
    pub axis: [T; 3],
    /// The rotation angle `θ ∈ [0, π]`.
    pub angle: T,
    /// The translation `d` along the axis.
    pub translation: T,
    /// The point of the axis nearest the origin.
    pub point: [T; 3],
    /// `d/θ`, `None` when `θ = 0`.
    pub pitch: Option<T>,
}

impl<T: Real> Screw<T> {
    /// The screw of a pose (module docs). Fails for singular or non-finite poses.
    ///
    /// ```
    /// use motion::{Pose, repr::screw::Screw};
    /// let id = Screw::of(&Pose::<f64>::identity()).unwrap();
    /// assert_eq!((id.axis, id.translation), ([0.0; 3], 0.0));
    /// ```
    pub fn of(s: &Pose<T>) -> Result<Self, MotionError> {
        Ok(Screw::of_hexanion(&Hexanion::from_pose(s)?))
    }

    /// The screw of the motion `exp(ω, m)` of a hexanion (with `θ = |ω|` as given, not reduced
    /// to `[0, π]`).
    ///
    /// ```
    /// use motion::repr::{hexanion::Hexanion, screw::Screw};
    /// let s = Screw::of_hexanion(&Hexanion::new([0.0, 0.0, 2.0], [2.0, 0.0, 3.0]));
    /// assert_eq!((s.point, s.translation, s.pitch), ([0.0, 1.0, 0.0], 3.0, Some(1.5)));
    /// ```
    pub fn of_hexanion(h: &Hexanion<T>) -> Self {
        let theta = norm(&h.omega);
        if theta.is_exact_zero() {
            let d = norm(&h.m);
            let axis = crate::scaled::direction(&h.m).unwrap_or_else(zero);
            return Screw { axis, angle: theta, translation: d, point: zero(), pitch: None };
        }
        // the unit axis first, then one division by θ: 1/θ² of a tiny angle (1e-200) would
        // overflow although the point (c = n × m / θ) does not
        let axis = crate::scaled::direction(&h.omega).unwrap_or_else(zero);
        let d = dot(&axis, &h.m);
        Screw {
            point: cross(&axis, &h.m).map(|c| c.div_ref(&theta)),
            pitch: Some(d.div_ref(&theta)),
            axis,
            translation: d,
            angle: theta,
        }
    }

    /// The hexanion `<θ n, θ c × n + d n>` of the screw (Angelidis (5)).
    ///
    /// ```
    /// use motion::repr::{hexanion::Hexanion, screw::Screw};
    /// let h = Hexanion::new([0.0, 0.0, 2.0], [2.0, 0.0, 3.0]);
    /// assert_eq!(Screw::of_hexanion(&h).to_hexanion(), h);
    /// ```
    pub fn to_hexanion(&self) -> Hexanion<T> {
        Hexanion::twist(&self.point, &self.angle, &self.axis, &self.translation)
    }

    /// The pose of the screw.
    ///
    /// ```
    /// use motion::{Pose, repr::screw::Screw};
    /// let s = Pose::from_axis_angle_translation(&[1.0, 2.0, 2.0], &0.7, &[1.0, -1.0, 0.5]).unwrap();
    /// assert!(Screw::of(&s).unwrap().to_pose().unwrap().is_equivalent(&s, &1e-15).unwrap());
    /// ```
    pub fn to_pose(&self) -> Result<Pose<T>, MotionError> {
        self.to_hexanion().to_pose()
    }
}

/// The origin of the moving frame (the image of `0`).
fn origin<T: Real>(s: &Pose<T>) -> Result<[T; 3], MotionError> {
    s.transform_point(&zero())
}

/// Jüttler's `dist(P, Q)`: the distance between the origins of the two positions (depends on
/// the choice of the moving frame's origin).
///
/// ```
/// use motion::{Pose, repr::screw::dist};
/// assert_eq!(dist(&Pose::translation(&[3.0, 0.0, 0.0]), &Pose::translation(&[0.0, 4.0, 0.0])).unwrap(), 5.0);
/// ```
pub fn dist<T: Real>(p: &Pose<T>, q: &Pose<T>) -> Result<T, MotionError> {
    Ok(norm(&sub(&origin(q)?, &origin(p)?)))
}

/// Jüttler's angle `∠(P, Q) ∈ [0, π]`: the rotation angle of the rotation from the rotational
/// part of `P` to that of `Q` (of the relative motion `P⁻¹ Q`).
///
/// ```
/// use motion::{Pose, repr::screw::angle};
/// let p = Pose::<f64>::rotation(&[0.0, 0.0, 1.0], &0.25).unwrap();
/// let q = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &1.0, &[5.0, 0.0, 0.0]).unwrap();
/// assert!((angle(&p, &q).unwrap() - 0.75).abs() < 1e-15);
/// ```
pub fn angle<T: Real>(p: &Pose<T>, q: &Pose<T>) -> Result<T, MotionError> {
    Ok(Screw::of(&relative(p, q)?)?.angle)
}

/// Jüttler's `dist*(P, Q) ≥ 0`: the length of the translation of the unique screw motion from
/// `P` to `Q` along its axis (independent of the moving frame's origin); `dist` when the two
/// rotational parts agree.
///
/// ```
/// use motion::{Pose, repr::screw::{dist, dist_star}};
/// let p = Pose::<f64>::identity();
/// let q = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &1.0, &[3.0, 0.0, 2.0]).unwrap();
/// assert!((dist_star(&p, &q).unwrap() - 2.0).abs() < 1e-14);
/// assert!(dist(&p, &q).unwrap() > 3.0);
/// ```
pub fn dist_star<T: Real>(p: &Pose<T>, q: &Pose<T>) -> Result<T, MotionError> {
    Ok(Real::abs(&Screw::of(&relative(p, q)?)?.translation))
}

/// `P⁻¹ Q` in the main paper's order (`P` first, then the relative motion: `P (P⁻¹ Q) = Q`).
fn relative<T: Real>(p: &Pose<T>, q: &Pose<T>) -> Result<Pose<T>, MotionError> {
    Ok(&p.try_inverse()? * q)
}
