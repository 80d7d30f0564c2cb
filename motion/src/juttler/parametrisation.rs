//! The parameters `0 = t_0 < t_1 < … < t_m = 1` of the given positions (Jüttler eq. 15):
//! `Δt_i = t_{i+1} - t_i` proportional to a distance or angle between neighbouring positions
//! ([`crate::repr::screw::dist`], [`crate::repr::screw::dist_star`],
//! [`crate::repr::screw::angle`]), or given explicitly.
//!
//! [`from_steps`] (steps -> normalised parameters) and [`normalise`] (explicit parameters) are
//! exact over rationals; [`parameters`] measures the steps with square roots and angles.
//!
//! ```
//! use motion::{Pose, juttler::{Parametrisation, parameters}};
//! let poses = [[0.0, 0.0, 0.0], [3.0, 0.0, 0.0], [3.0, 4.0, 0.0]].map(|t| Pose::<f64>::translation(&t));
//! assert_eq!(parameters(&poses, &Parametrisation::Chordal).unwrap(), [0.0, 3.0 / 7.0, 1.0]);
//! ```

use super::JuttlerError;
use crate::Pose;
use crate::repr::screw::{angle, dist, dist_star};
use algebra_core::{Field, Real};

/// A choice of parameters for the given positions (eq. 15).
///
/// ```
/// use motion::juttler::Parametrisation;
/// let p = Parametrisation::<f64>::Explicit(vec![0.0, 0.25, 1.0]);
/// assert!(matches!(p, Parametrisation::Explicit(_)));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum Parametrisation<T> {
    /// `Δt_i ~ dist(P_i, P_{i+1})`: distance between the origins of the moving frame.
    Chordal,
    /// `Δt_i ~ dist*(P_i, P_{i+1})`: the translation of the screw motion along its axis.
    StarChordal,
    /// `Δt_i = constant`.
    Equidistant,
    /// `Δt_i ~ √dist(P_i, P_{i+1})`.
    Centripetal,
    /// `Δt_i ~ ∠(P_i, P_{i+1})`: the angle of the relative rotation.
    Angular,
    /// `Δt_i ~ ∠(P_i, P_{i+1}) + dist(P_i, P_{i+1})` (radians plus length units, as printed).
    AngleDistance,
    /// Given parameters, one per position, strictly increasing; mapped affinely onto `[0, 1]`.
    Explicit(Vec<T>),
}

/// The parameters `t_0 = 0, t_{i+1} = t_i + Δt_i / Σ Δt` of positive steps, exactly (over
/// rationals too). Fails for no steps or a step that is not positive.
///
/// ```
/// use algebra_core::rational::{q, ratio};
/// let t = motion::juttler::parametrisation::from_steps(&[q(1), q(3)]).unwrap();
/// assert_eq!(t, [q(0), ratio(1, 4), q(1)]);
/// ```
pub fn from_steps<T: Field + PartialOrd>(steps: &[T]) -> Result<Vec<T>, JuttlerError> {
    if steps.is_empty() {
        return Err(JuttlerError::TooFewPositions { need: 2, got: 1 });
    }
    if let Some(i) = steps.iter().position(|s| !positive(s)) {
        return Err(JuttlerError::ZeroStep { index: i, value: steps[i].to_string() });
    }
    let total = steps.iter().fold(T::zero(), |acc, s| acc.add_ref(s));
    let inv = total.try_recip().ok_or_else(|| JuttlerError::Parameters { why: "the steps sum to infinity".into() })?;
    let mut t = vec![T::zero()];
    let mut acc = T::zero();
    for s in &steps[..steps.len() - 1] {
        acc = acc.add_ref(s);
        t.push(acc.mul_ref(&inv));
    }
    t.push(T::one());
    Ok(t)
}

/// Explicit parameters `u_0 < … < u_m` mapped affinely onto `[0, 1]`: `(u_i - u_0)/(u_m - u_0)`,
/// exactly. Fails unless there are `m + 1 ≥ 2` strictly increasing values.
///
/// ```
/// use algebra_core::rational::{q, ratio};
/// let t = motion::juttler::parametrisation::normalise(&[q(2), q(3), q(6)], 3).unwrap();
/// assert_eq!(t, [q(0), ratio(1, 4), q(1)]);
/// ```
pub fn normalise<T: Field + PartialOrd>(u: &[T], positions: usize) -> Result<Vec<T>, JuttlerError> {
    if u.len() != positions {
        return Err(JuttlerError::Parameters { why: format!("{} parameters for {positions} positions", u.len()) });
    }
    let steps: Vec<T> = u.windows(2).map(|w| w[1].sub_ref(&w[0])).collect();
    if let Some(i) = steps.iter().position(|s| !positive(s)) {
        return Err(JuttlerError::Parameters { why: format!("parameter {} is not larger than parameter {i}", i + 1) });
    }
    from_steps(&steps)
}

/// The parameters of `poses` by the rule `kind` (eq. 15), normalised to `t_0 = 0`, `t_m = 1`.
/// Fails for fewer than two poses, singular poses, non-finite values, or a zero step (two
/// neighbouring positions that the rule cannot tell apart, e.g. equal origins for
/// [`Parametrisation::Chordal`]).
///
/// ```
/// use motion::{Pose, juttler::{JuttlerError, Parametrisation, parameters}};
/// let same = [Pose::<f64>::identity(), Pose::rotation(&[0.0, 0.0, 1.0], &1.0).unwrap()];
/// assert!(matches!(parameters(&same, &Parametrisation::Chordal), Err(JuttlerError::ZeroStep { index: 0, .. })));
/// assert_eq!(parameters(&same, &Parametrisation::Angular).unwrap(), [0.0, 1.0]);
/// ```
pub fn parameters<T: Real>(poses: &[Pose<T>], kind: &Parametrisation<T>) -> Result<Vec<T>, JuttlerError> {
    if poses.len() < 2 {
        return Err(JuttlerError::TooFewPositions { need: 2, got: poses.len() });
    }
    if let Parametrisation::Explicit(u) = kind {
        if let Some(i) = u.iter().position(|x| !x.is_finite()) {
            return Err(JuttlerError::Parameters { why: format!("parameter {i} is not finite") });
        }
        return normalise(u, poses.len());
    }
    let steps = poses.windows(2).map(|w| step(&w[0], &w[1], kind)).collect::<Result<Vec<T>, JuttlerError>>()?;
    if let Some(i) = steps.iter().position(|s| !s.is_finite()) {
        return Err(JuttlerError::Parameters { why: format!("step {i} is not finite") });
    }
    from_steps(&steps)
}

/// `s > 0` (false for NaN).
fn positive<T: PartialOrd + algebra_core::Ring>(s: &T) -> bool {
    s.partial_cmp(&T::zero()) == Some(std::cmp::Ordering::Greater)
}

/// `Δt_i` (up to the common factor) for one pair of positions.
fn step<T: Real>(p: &Pose<T>, q: &Pose<T>, kind: &Parametrisation<T>) -> Result<T, JuttlerError> {
    Ok(match kind {
        Parametrisation::Chordal => dist(p, q)?,
        Parametrisation::StarChordal => dist_star(p, q)?,
        Parametrisation::Equidistant => T::one(),
        Parametrisation::Centripetal => Real::sqrt(&dist(p, q)?),
        Parametrisation::Angular => angle(p, q)?,
        Parametrisation::AngleDistance => angle(p, q)?.add_ref(&dist(p, q)?),
        Parametrisation::Explicit(_) => {
            return Err(JuttlerError::Parameters { why: "explicit parameters have no steps".into() });
        }
    })
}
