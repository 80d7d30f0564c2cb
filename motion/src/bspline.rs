//! B-spline motions: additive and multiplicative, with a knot vector, evaluated by de Boor's
//! algorithm (the extension of the de Casteljau tableau to knots that Sec. 4 of the main paper
//! mentions but does not spell out).
//!
//! A B-spline motion of degree `p` has control poses `S_0, ..., S_n` (`n ≥ p`) and a
//! non-decreasing knot vector `u_0 ≤ ... ≤ u_{n+p+1}` (so `n + p + 2` knots, each value repeated
//! at most `p + 1` times); its domain is `[u_p, u_{n+1}]`. On the span `u_k ≤ t < u_{k+1}`
//! de Boor's triangle combines `S_{k-p}, ..., S_k` pairwise,
//! `d ← Φ(d_{j-1}, d_j; α)` with `α = (t - u_i)/(u_{i+p+1-r} - u_i)`, where `Φ` is the
//! additive `(1 - α) A + α B` (eq. 17) or the slerp `A (rev(A) B)^α` (eq. 15). With the knots
//! `0 (p + 1 times), 1 (p + 1 times)` every `α` is `t` and de Boor *is* de Casteljau: the
//! B-spline is the Bezier motion of the same poses.
//!
//! Continuity: the additive motion is a B-spline curve in the 8 coefficients, so it is
//! `C^{p-k}` at a knot of multiplicity `k`. The multiplicative one need not be: a cubic with
//! simple knots is C1 but its second derivative jumps at the knots (`tests/velocity.rs`).
//!
//! At an interior knot the span to the right is used (so a dual-number derivative there is the
//! right-hand one); at the end of the domain the last non-empty span. [`Motion::evaluate`]
//! outside the domain continues the first or last span.
//!
//! ```
//! use motion::{AdditiveBSpline, AdditiveBezier, Motion, Pose};
//! let poses = vec![Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0]), Pose::translation(&[1.0, 1.0, 0.0])];
//! let spline = AdditiveBSpline::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0], poses.clone()).unwrap();
//! let bezier = AdditiveBezier::new(poses).unwrap();
//! assert_eq!(spline.pose(&0.3).unwrap(), bezier.pose(&0.3).unwrap());
//! ```

use crate::Pose;
use crate::bezier::{CurveError, MapScalar, Motion};
use crate::blend::{Additive, Blend, Multiplicative};
use algebra_core::{Real, Ring};

/// Degree, knots and control poses, validated.
#[derive(Clone, Debug, PartialEq)]
struct Spline<T: Ring> {
    degree: usize,
    knots: Vec<T>,
    poses: Vec<Pose<T>>,
}

impl<T: Real> Spline<T> {
    fn new(degree: usize, knots: Vec<T>, poses: Vec<Pose<T>>) -> Result<Self, CurveError> {
        // degree + 1 would overflow for usize::MAX: there are never that many poses
        if degree >= poses.len() {
            return Err(CurveError::TooFewPoses { need: degree.saturating_add(1), got: poses.len() });
        }
        let expected = poses.len() + degree + 1;
        if knots.len() != expected {
            return Err(CurveError::KnotCount { degree, poses: poses.len(), expected, got: knots.len() });
        }
        for (index, u) in knots.iter().enumerate() {
            if !u.is_finite() {
                return Err(CurveError::NotFiniteParameter { what: "knot", index, value: u.to_string() });
            }
        }
        crate::bezier::finite_poses("control pose", &poses)?;
        let mut multiplicity = 1;
        for index in 1..knots.len() {
            let (previous, value) = (&knots[index - 1], &knots[index]);
            if value < previous {
                return Err(CurveError::KnotsDecreasing {
                    index,
                    value: value.to_string(),
                    previous: previous.to_string(),
                });
            }
            multiplicity = if value == previous { multiplicity + 1 } else { 1 };
            if multiplicity > degree + 1 {
                return Err(CurveError::KnotMultiplicity { value: value.to_string(), multiplicity, degree });
            }
        }
        let (start, end) = (&knots[degree], &knots[poses.len()]);
        if start >= end {
            return Err(CurveError::EmptyDomain { start: start.to_string(), end: end.to_string() });
        }
        Ok(Spline { degree, knots, poses })
    }

    /// `0 (p + 1 times), 1/(n-p+1), ..., (n-p)/(n-p+1), 1 (p + 1 times)`.
    fn clamped_uniform(degree: usize, poses: Vec<Pose<T>>) -> Result<Self, CurveError> {
        if degree >= poses.len() {
            return Err(CurveError::TooFewPoses { need: degree.saturating_add(1), got: poses.len() });
        }
        let spans = (poses.len() - degree) as i64;
        let mut knots = vec![T::zero(); degree + 1];
        knots.extend((1..spans).map(|i| T::from_ratio(i, spans)));
        knots.extend(std::iter::repeat_with(T::one).take(degree + 1));
        Spline::new(degree, knots, poses)
    }

    fn domain(&self) -> [T; 2] {
        [self.knots[self.degree].clone(), self.knots[self.poses.len()].clone()]
    }

    /// The largest `k` in `p..=n` with `u_k ≤ t` and `u_k < u_{k+1}`; the first non-empty span
    /// below the domain.
    fn span(&self, t: &T) -> usize {
        let u = &self.knots;
        let mut spans = (self.degree..self.poses.len()).filter(|&k| u[k] < u[k + 1]);
        let first = spans.next().expect("validated: the domain is not empty");
        spans.rev().find(|&k| u[k] <= *t).unwrap_or(first)
    }

    /// `S(t)` by de Boor's algorithm with the blend `B` ([`Blend::de_boor`]).
    fn de_boor<B: Blend<T>>(&self, t: &T) -> Result<Pose<T>, CurveError> {
        let (p, k, u) = (self.degree, self.span(t), &self.knots);
        let alpha = |r: usize, j: usize| {
            let (lo, hi) = (&u[j + k - p], &u[j + 1 + k - r]);
            t.sub_ref(lo).div_ref(&hi.sub_ref(lo))
        };
        Ok(B::de_boor(&self.poses[k - p..=k], &alpha)?)
    }

    fn map_scalar<U: Ring>(&self, f: &dyn Fn(&T) -> U) -> Spline<U> {
        Spline {
            degree: self.degree,
            knots: self.knots.iter().map(f).collect(),
            poses: self.poses.iter().map(|p| p.map_scalar(f)).collect(),
        }
    }
}

/// A B-spline motion of degree `p` with knots, evaluated by de Boor's algorithm with the
/// pairwise combination of the blend `B` ([`Additive`]: eq. 17, a piecewise polynomial in `t`,
/// not unitary in general; [`Multiplicative`]: the slerp of eq. 15, unitary when the control
/// poses are). [`AdditiveBSpline`] and [`MultiplicativeBSpline`] name the two kinds.
///
/// ```
/// use motion::{Additive, BSpline, Motion, Pose};
/// let poses: Vec<_> = (0..5).map(|i| Pose::<f64>::translation(&[f64::from(i), 0.0, 0.0])).collect();
/// let m = BSpline::<f64, Additive>::clamped_uniform(3, poses).unwrap();
/// // Control points on a line, evenly spaced: the motion is a translation along it.
/// let s = m.pose(&0.5).unwrap();
/// assert!((s.e1inf - 1.0).abs() < 1e-15 && (s.scalar - 1.0).abs() < 1e-15);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BSpline<T: Ring, B> {
    spline: Spline<T>,
    blend: B,
}

/// The additive B-spline motion: de Boor's algorithm with `(1 - α) A + α B` (eq. 17).
///
/// ```
/// use motion::{AdditiveBSpline, CurveError, Pose};
/// let poses = vec![Pose::<f64>::identity(); 3];
/// assert!(AdditiveBSpline::new(1, vec![0.0, 0.0, 0.5, 1.0, 1.0], poses.clone()).is_ok());
/// assert!(matches!(AdditiveBSpline::new(1, vec![0.0, 0.5, 1.0], poses.clone()), Err(CurveError::KnotCount { .. })));
/// assert!(matches!(
///     AdditiveBSpline::new(1, vec![0.0, 0.0, 0.7, 0.5, 1.0], poses),
///     Err(CurveError::KnotsDecreasing { index: 3, .. })
/// ));
/// ```
pub type AdditiveBSpline<T> = BSpline<T, Additive>;

/// The multiplicative B-spline motion: de Boor's algorithm with the slerp `A (rev(A) B)^α`
/// (eq. 15). Unitary when the control poses are.
///
/// ```
/// use motion::{Motion, MultiplicativeBSpline, Pose};
/// let poses: Vec<_> = (0..4).map(|i| Pose::<f64>::rotation(&[0.0, 0.0, 1.0], &(0.3 * f64::from(i))).unwrap()).collect();
/// let m = MultiplicativeBSpline::clamped_uniform(2, poses).unwrap();
/// let s = m.pose(&0.5).unwrap();
/// assert!(s.is_unitary(&1e-15));
/// // Rotations about one axis commute: the angle is the B-spline of the angles, 0.45 here.
/// assert!(s.is_equivalent(&Pose::rotation(&[0.0, 0.0, 1.0], &0.45).unwrap(), &1e-15).unwrap());
/// ```
pub type MultiplicativeBSpline<T> = BSpline<T, Multiplicative>;

impl<T: Real, B: Default> BSpline<T, B> {
    /// A motion of degree `degree` with the given knots (`poses.len() + degree + 1` of them,
    /// finite, non-decreasing, each value at most `degree + 1` times, `u_p < u_{n+1}`) and
    /// control poses (at least `degree + 1`). Typed errors for each violation.
    ///
    /// ```
    /// use motion::{CurveError, MultiplicativeBSpline, Pose};
    /// let poses = vec![Pose::<f64>::identity(); 3];
    /// assert!(matches!(
    ///     MultiplicativeBSpline::new(1, vec![0.0, 0.0, 0.0, 0.0, 1.0], poses),
    ///     Err(CurveError::KnotMultiplicity { multiplicity: 3, .. })
    /// ));
    /// ```
    pub fn new(degree: usize, knots: Vec<T>, poses: Vec<Pose<T>>) -> Result<Self, CurveError> {
        Ok(BSpline { spline: Spline::new(degree, knots, poses)?, blend: B::default() })
    }

    /// Clamped uniform knots on `[0, 1]`: `0` and `1` repeated `degree + 1` times, the interior
    /// knots evenly spaced. With `degree + 1` poses this is the Bezier motion.
    ///
    /// ```
    /// use motion::{AdditiveBSpline, Motion, Pose};
    /// let m = AdditiveBSpline::clamped_uniform(1, vec![Pose::<f64>::identity(); 3]).unwrap();
    /// assert_eq!(m.knots(), [0.0, 0.0, 0.5, 1.0, 1.0]);
    /// assert_eq!(m.domain(), [0.0, 1.0]);
    /// ```
    pub fn clamped_uniform(degree: usize, poses: Vec<Pose<T>>) -> Result<Self, CurveError> {
        Ok(BSpline { spline: Spline::clamped_uniform(degree, poses)?, blend: B::default() })
    }
}

impl<T: Ring, B> BSpline<T, B> {
    /// The degree `p`.
    ///
    /// ```
    /// let m = motion::AdditiveBSpline::clamped_uniform(2, vec![motion::Pose::<f64>::identity(); 5]).unwrap();
    /// assert_eq!(m.degree(), 2);
    /// ```
    pub fn degree(&self) -> usize {
        self.spline.degree
    }

    /// The knot vector `u_0, ..., u_{n+p+1}`.
    ///
    /// ```
    /// let m = motion::MultiplicativeBSpline::clamped_uniform(2, vec![motion::Pose::<f64>::identity(); 4]).unwrap();
    /// assert_eq!(m.knots(), [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]);
    /// ```
    pub fn knots(&self) -> &[T] {
        &self.spline.knots
    }

    /// The control poses `S_0, ..., S_n`.
    ///
    /// ```
    /// let m = motion::AdditiveBSpline::clamped_uniform(1, vec![motion::Pose::<f64>::identity(); 3]).unwrap();
    /// assert_eq!(m.poses().len(), 3);
    /// ```
    pub fn poses(&self) -> &[Pose<T>] {
        &self.spline.poses
    }
}

impl<T: Real, B: Blend<T>> Motion<T> for BSpline<T, B> {
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        self.spline.de_boor::<B>(t)
    }

    fn domain(&self) -> [T; 2] {
        self.spline.domain()
    }
}

impl<T: Real, U: Real, B: Blend<T> + Blend<U>> MapScalar<T, U> for BSpline<T, B> {
    type Mapped = BSpline<U, B>;

    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> BSpline<U, B> {
        BSpline { spline: self.spline.map_scalar(f), blend: self.blend }
    }
}

/// De Boor's algorithm over the `p + 1` control entries `d` of a span (already lifted to the
/// element type `C`), with the step parameters `alpha(r, j)` and the pairwise `combine`: level
/// `r` overwrites `d[j]` with `combine(d[j - 1], d[j], alpha(r, j))` for `j = p..r`.
pub(crate) fn de_boor_with<T, C, E>(
    mut d: Vec<C>,
    alpha: &dyn Fn(usize, usize) -> T,
    combine: impl Fn(&C, &C, &T) -> Result<C, E>,
) -> Result<C, E> {
    let p = d.len() - 1;
    for r in 1..=p {
        for j in (r..=p).rev() {
            d[j] = combine(&d[j - 1], &d[j], &alpha(r, j))?;
        }
    }
    Ok(d.swap_remove(p))
}
