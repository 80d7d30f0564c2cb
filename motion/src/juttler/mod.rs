//! Jüttler's rational motions ("Visualization of moving objects using dual quaternion
//! curves", Secs. 2-5; issue 11), on the dual quaternions of [`crate::repr::dual_quaternion`]
//! (his conventions, the pose map stated there).
//!
//! | module | contents | paper |
//! |---|---|---|
//! | [`minimal`] | [`minimal::MinimalMotion`]: rational motions of order `n` (35)-(36); interpolation (37)-(39), order `2m` | Thm. 6, Sec. 5 |
//! | [`parametrisation`] | parameters `t_i` of the given positions: chordal, `*`-chordal, equidistant, centripetal, angular, angle + distance, explicit | eq. (15) |
//! | [`q_motion`] | [`QMotion`]: Bézier curves of dual quaternions on the Study quadric; de Casteljau, degree elevation, product formula (29), the Study condition as a polynomial; a [`crate::Motion`] | eqs. (13), (29), (8) |
//! | [`rational_trajectory`] | [`RationalBezier`]: the trajectory of a body point as a rational Bézier curve of degree `2n`; evaluation, derivative, degree elevation | eq. (12), Sec. 1 |
//! | [`additive_trajectory`] | trajectories of the main paper's additive Bézier motions ([`crate::AdditiveBezier`], a [`RationalMotion`]): degree `2n` | main paper (18), (6)-(9); (29) |
//! | [`rotational`] | interpolation of the rotational parts: affine (19)-(21), elliptic (22)-(25) with the sign rule (24) | Props. 1, 2 |
//! | [`projective`] | the projective method (27)-(28): the null space of a homogeneous system, degree `3m/4`, unique up to a real factor | Prop. 3 |
//! | [`bspline`] | [`bspline::BSplineQMotion`]: B-spline Q-motions (de Boor, pieces by blossoming, the Study condition per piece); a [`crate::Motion`] | Sec. 6 |
//! | [`bspline_tr`] | the TR method with B-spline Q-motions (averaged knots, collocation, product) | Secs. 4.1, 6 |
//! | [`spline`] | [`SplineQMotion`]: Algorithm 2, the C1 spline Q-motion (40)-(44); a [`crate::Motion`] | Sec. 6, Algorithm 2 |
//! | [`surface`] | [`surface::RationalBezierSurface`]: the kinematic (sweeping) surface `y(t, v) = M(t) x(v)` of a rational Bézier curve as a rational tensor-product Bézier surface | Sec. 5, Fig. 5b |
//! | [`tr`] | the TR method (30)-(31) and Algorithm 1 (elliptic + TR, degree `2m`) | Prop. 4, Algorithm 1 |
//! | [`trt`] | the TRT method (32)-(34): translations on both sides, split `l1 + l2 = m - 1`, independent of the moving origin | Result 5 |
//! | [`velocity`] | [`KeyVelocity`] (`v⃗_i`, `ω⃗_i`) and step 1 of Algorithm 2: velocities estimated from the connecting translations and rotations (Bessel) | Algorithm 2, (42) |
//!
//! The parametrisations that take square roots or angles need [`algebra_core::Real`]; the
//! rest is exact over [`algebra_core::rational::Q`].
//!
//! ```
//! use algebra_core::rational::{q, ratio};
//! use gam_algebras::DualQuaternion;
//! use motion::juttler::QMotion;
//! // Q(t) = 2 + ε t (0, 0, 2): the translation from (0, 0, 0) to (0, 0, 2), degree 1
//! let m = QMotion::new_exact(vec![
//!     DualQuaternion::from_coeffs([q(2), q(0), q(0), q(0), q(0), q(0), q(0), q(0)]),
//!     DualQuaternion::from_coeffs([q(2), q(0), q(0), q(0), q(0), q(0), q(0), q(2)]),
//! ]).unwrap();
//! let path = m.trajectory(&[q(0), q(0), q(0)]);
//! assert_eq!(path.point(&ratio(1, 2)).unwrap(), [q(0), q(0), q(1)]);
//! ```

pub mod additive_trajectory;
pub mod bspline;
pub mod bspline_tr;
pub mod minimal;
pub mod minimal_spline;
pub mod parametrisation;
pub mod projective;
pub mod q_motion;
pub mod rational_trajectory;
pub mod rotational;
pub mod spline;
pub mod surface;
pub mod tr;
pub mod trt;
pub mod velocity;

pub use parametrisation::{Parametrisation, parameters};
pub use q_motion::QMotion;
pub use rational_trajectory::{RationalBezier, RationalMotion};
pub use spline::SplineQMotion;
pub use velocity::KeyVelocity;

use crate::MotionError;
use crate::repr::ReprError;
use algebra_core::rational::{Q, q};
use algebra_core::{Field, Ring};

/// Why a construction of this module failed.
///
/// ```
/// let e = motion::juttler::JuttlerError::TooFewPositions { need: 2, got: 1 };
/// assert_eq!(e.to_string(), "needs at least 2 positions, got 1");
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum JuttlerError {
    /// Fewer positions (or control points) than the construction needs.
    #[error("needs at least {need} positions, got {got}")]
    TooFewPositions {
        /// The minimum.
        need: usize,
        /// What was given.
        got: usize,
    },
    /// Parameters that are not `m + 1` finite, strictly increasing values.
    #[error("parameters: {why}")]
    Parameters {
        /// What is wrong.
        why: String,
    },
    /// A parametrisation step `Δt_i` of (15) that is zero or negative (e.g. two positions
    /// with the same origin under the chordal parametrisation).
    #[error("the parameter step between positions {index} and {} is {value}, not positive", index + 1)]
    ZeroStep {
        /// The index `i` of `Δt_i`.
        index: usize,
        /// The step, printed.
        value: String,
    },
    /// A dual-quaternion Bézier curve off the Study quadric: the Bernstein coefficient
    /// `index` of the Study polynomial `Scal(Q⁰ Q̃^ε)` is not (close to) zero.
    #[error("not a Q-motion: Plücker's relation (8) fails, Study polynomial coefficient {index} is {value}")]
    NotQMotion {
        /// The Bernstein index of the offending coefficient.
        index: usize,
        /// Its value, printed.
        value: String,
    },
    /// A trajectory control point (or point of the curve) with weight zero (at infinity).
    #[error("the rational Bézier curve has weight zero at {what}")]
    ZeroWeight {
        /// Where: "control point i" or "t = ...".
        what: String,
    },
    /// A rotation with `r_{i,0} = 0` (a half turn), at infinity for the affine method (19)-(21).
    #[error("rotation {index} is a half turn (zero scalar part): at infinity for the affine method")]
    AtInfinity {
        /// Its index.
        index: usize,
    },
    /// A zero quaternion where a rotation was expected.
    #[error("rotation {index} is the zero quaternion")]
    ZeroQuaternion {
        /// Its index.
        index: usize,
    },
    /// The projective method (28) with `k = 3m/4` needs `m` divisible by 4 (`m + 1` positions).
    #[error("the projective method needs m + 1 positions with m divisible by 4 (k = 3m/4), got {positions}")]
    ProjectiveCount {
        /// The number of positions given.
        positions: usize,
    },
    /// A homogeneous system (28) whose solutions form a space of dimension `dimension > 1`:
    /// the interpolant is not unique up to a real factor.
    #[error("the homogeneous system (28) has a {dimension}-dimensional solution space: not unique up to a real factor")]
    NotUnique {
        /// The dimension of the null space.
        dimension: usize,
    },
    /// A homogeneous system (28) with only the trivial solution `C_j = 0`.
    #[error("the homogeneous system (28) has only the trivial solution")]
    OnlyTrivial,
    /// A position that the projective method cannot reach: `Q_rot(t_i) = 0` (Jüttler: "inaccessible").
    #[error("position {index} is inaccessible: the projective interpolant vanishes at its parameter")]
    Inaccessible {
        /// Its index.
        index: usize,
    },
    /// A singular linear system of an interpolation method (e.g. TRT's (34) when positions
    /// share an orientation).
    #[error("the linear system {system} is singular (rank {rank} of {unknowns} unknowns): {why}")]
    SingularSystem {
        /// The paper's equation number, e.g. "(34)".
        system: &'static str,
        /// The rank found.
        rank: usize,
        /// The number of unknowns.
        unknowns: usize,
        /// The likely reason.
        why: &'static str,
    },
    /// A linear system that is singular in the scalar's precision although its parameters are
    /// distinct (many positions, or parameters too close: the pivots fall below the precision's
    /// threshold); exact rationals solve it.
    #[error(
        "the linear system {system} ({unknowns} unknowns) is numerically singular: the parameters are distinct, but too close or too many for this precision"
    )]
    NumericallySingular {
        /// The system, e.g. the Bernstein collocation `Σ_j b_j^m(t_i) C_j = R_i`.
        system: &'static str,
        /// The number of unknowns per component.
        unknowns: usize,
    },
    /// A split `l1 + l2 = m - 1` of the TRT method with `l1 > m - 1`.
    #[error("TRT split: l1 = {l1} exceeds m - 1 = {max}")]
    Split {
        /// The given `l1`.
        l1: usize,
        /// `m - 1`.
        max: usize,
    },
    /// A rotational motion with a non-zero dual part where a pure rotation `Q_rot` (17) was expected.
    #[error("the rotational motion has a non-zero dual part at control point {index}")]
    NotRotational {
        /// The first offending control point.
        index: usize,
    },
    /// A pose operation failed.
    #[error(transparent)]
    Motion(#[from] MotionError),
    /// A dual quaternion <-> pose conversion failed.
    #[error(transparent)]
    Repr(#[from] ReprError),
}

/// [`MotionError::NotFinite`] (operation `op`) for the first control point with a NaN or
/// infinite coordinate.
pub(crate) fn check_finite<T: Ring, const N: usize>(
    op: &'static str,
    mut points: impl Iterator<Item = [T; N]>,
) -> Result<(), JuttlerError> {
    match points.find(|p| !p.iter().all(Ring::is_finite_value)) {
        Some(p) => Err(MotionError::NotFinite { op, value: format!("{p:?}") }.into()),
        None => Ok(()),
    }
}

/// `C(n, k)` as an exact rational.
pub(crate) fn binomial(n: usize, k: usize) -> Q {
    (0..k).fold(q(1), |acc, i| acc * q((n - i) as i64) / q((i + 1) as i64))
}

/// The Bernstein polynomials `b_0^k(t), …, b_k^k(t)` at `t` (exact over rationals).
///
/// ```
/// use algebra_core::rational::{q, ratio};
/// let b = motion::juttler::bernstein_values(2, &ratio(1, 2));
/// assert_eq!(b, [ratio(1, 4), ratio(1, 2), ratio(1, 4)]);
/// ```
pub fn bernstein_values<T: Ring>(k: usize, t: &T) -> Vec<T> {
    let pow = |x: &T, e: usize| (0..e).fold(T::one(), |acc, _| acc.mul_ref(x));
    let s = T::one().sub_ref(t);
    (0..=k).map(|j| T::from_rational(&binomial(k, j)).mul_ref(&pow(t, j)).mul_ref(&pow(&s, k - j))).collect()
}

/// The factor of the product formula (29): `b_i^k b_j^l = C(k,i) C(l,j)/C(k+l,i+j) b_{i+j}^{k+l}`,
/// exact.
///
/// ```
/// use algebra_core::rational::ratio;
/// // b_0^1 b_1^1 = (1-t) t = ½ b_1^2
/// assert_eq!(motion::juttler::product_factor::<algebra_core::rational::Q>(1, 0, 1, 1), ratio(1, 2));
/// ```
pub fn product_factor<T: Ring>(k: usize, i: usize, l: usize, j: usize) -> T {
    T::from_rational(&(binomial(k, i) * binomial(l, j) / binomial(k + l, i + j)))
}

/// The Bernstein coefficients of a product of two Bézier polynomials (29): `c_m = Σ_{i+j=m}
/// factor(i, j) mul(a_i, b_j)`, for any bilinear `mul`.
pub(crate) fn bernstein_product<A, B, C: Clone, T: Ring>(
    a: &[A],
    b: &[B],
    zero: C,
    mul: impl Fn(&A, &B) -> C,
    add_scaled: impl Fn(&C, &C, &T) -> C,
) -> Vec<C> {
    let (k, l) = (a.len() - 1, b.len() - 1);
    let mut out = vec![zero; k + l + 1];
    for (i, ai) in a.iter().enumerate() {
        for (j, bj) in b.iter().enumerate() {
            let f = product_factor::<T>(k, i, l, j);
            out[i + j] = add_scaled(&out[i + j], &mul(ai, bj), &f);
        }
    }
    out
}

/// Degree elevation of Bernstein coefficients: `c'_i = i/(n+1) c_{i-1} + (1 - i/(n+1)) c_i`.
pub(crate) fn elevate_with<C: Clone, T: Ring>(c: &[C], combine: impl Fn(&C, &T, &C, &T) -> C) -> Vec<C> {
    let n = c.len() - 1;
    let d = (n + 1) as i64;
    (0..=n + 1)
        .map(|i| {
            if i == 0 {
                c[0].clone()
            } else if i == n + 1 {
                c[n].clone()
            } else {
                let a = T::from_ratio(i as i64, d);
                let b = T::from_ratio(d - i as i64, d);
                combine(&c[i - 1], &a, &c[i], &b)
            }
        })
        .collect()
}

/// De Casteljau's algorithm on Bernstein coefficients with `lerp(a, b, 1 - t, t)`.
/// The shared in-place apex ([`crate::de_casteljau::apex`]: no allocation up to degree 7).
pub(crate) fn de_casteljau_with<C: Clone, T: Ring>(c: &[C], t: &T, lerp: impl Fn(&C, &C, &T, &T) -> C) -> C {
    let s = T::one().sub_ref(t);
    let Ok(apex) = crate::de_casteljau::apex::<C, std::convert::Infallible>(c, |a, b| Ok(lerp(a, b, &s, t)));
    apex
}

/// `1/x` or [`JuttlerError::ZeroWeight`].
pub(crate) fn recip_or<T: Field>(x: &T, what: impl FnOnce() -> String) -> Result<T, JuttlerError> {
    x.try_recip().ok_or_else(|| JuttlerError::ZeroWeight { what: what() })
}

/// Fails ([`JuttlerError::Parameters`]) unless every value and parameter is finite and the
/// parameters are pairwise distinct (for the methods whose systems would otherwise fail with
/// a less telling reason, or silently produce NaN).
pub(crate) fn check_finite_distinct<'a, T: Ring + 'a>(
    params: &[T],
    values: impl IntoIterator<Item = &'a T>,
) -> Result<(), JuttlerError> {
    let why = |why: String| Err(JuttlerError::Parameters { why });
    if let Some(i) = params.iter().position(|t| !t.is_finite_value()) {
        return why(format!("parameter {i} is not finite"));
    }
    if values.into_iter().any(|x| !x.is_finite_value()) {
        return why("a position has a coefficient that is not finite".into());
    }
    if let Some((j, i)) = first_repeat(params) {
        return why(format!("parameters {j} and {i} are equal"));
    }
    Ok(())
}

/// The first pair `(j, i)`, `j < i`, of equal parameters.
pub(crate) fn first_repeat<T: PartialEq>(params: &[T]) -> Option<(usize, usize)> {
    params.iter().enumerate().find_map(|(i, a)| params[..i].iter().position(|b| b == a).map(|j| (j, i)))
}
