//! Piecewise motions over parameter intervals: segments `M_k` on `[t_k, t_{k+1}]`, each
//! reparametrised linearly onto its own domain (`[0, 1]` for Bezier motions), as in the
//! paper's Sec. 4 example (an arc on `[0, 1]`, a line on `[1, 2]`) and the Hermite motions of
//! Sec. 5.3.
//!
//! * [`Reparametrized`]: one motion on a chosen interval, `t ↦ M(a + (t - t_0)/(t_1 - t_0) (b - a))`
//!   for `M` on `[a, b]`. The reparametrisation runs over the same scalar as the motion, so its
//!   chain-rule factor enters dual-number derivatives automatically.
//! * [`Piecewise`]: a list of such segments with strictly increasing breakpoints. At an interior
//!   breakpoint the segment to the right is used; [`Piecewise::piece`] gives each segment on its
//!   own closed interval, for one-sided values and derivatives at joins.
//! * [`AnyMotion`]: one type for every kind of motion, so a piecewise motion can mix kinds.
//!
//! ```
//! use motion::{AdditiveBezier, Motion, Piecewise, Pose};
//! let a = Pose::<f64>::identity();
//! let b = Pose::translation(&[1.0, 0.0, 0.0]);
//! let c = Pose::translation(&[1.0, 1.0, 0.0]);
//! let first = AdditiveBezier::new(vec![a, b.clone()]).unwrap();
//! let second = AdditiveBezier::new(vec![b, c]).unwrap();
//! let m = Piecewise::uniform(vec![first, second]).unwrap();
//! assert_eq!(m.domain(), [0.0, 2.0]);
//! assert_eq!(m.pose(&1.5).unwrap(), Pose::translation(&[1.0, 0.5, 0.0]));
//! assert!(m.pose(&2.5).is_err());
//! ```

use crate::Pose;
use crate::bezier::{AdditiveBezier, CurveError, MapScalar, Motion, MultiplicativeBezier, check_domain};
use crate::bspline::{AdditiveBSpline, MultiplicativeBSpline};
use algebra_core::{Field, Real, Ring};

/// A motion `M` on `[a, b]` run over the interval `[t_0, t_1]`:
/// `R(t) = M(a + (t - t_0)/(t_1 - t_0) · (b - a))` (`t_0 < t_1`).
///
/// ```
/// use motion::{AdditiveBezier, Motion, Pose, Reparametrized};
/// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[4.0, 0.0, 0.0])]).unwrap();
/// let r = Reparametrized::new(m, [2.0, 4.0]).unwrap();
/// assert_eq!(r.domain(), [2.0, 4.0]);
/// assert_eq!(r.pose(&3.0).unwrap(), Pose::translation(&[2.0, 0.0, 0.0]));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Reparametrized<T, M> {
    interval: [T; 2],
    inner: M,
}

impl<T: Field + PartialOrd, M: Motion<T>> Reparametrized<T, M> {
    /// `inner` run over `interval` (finite, `interval[0] < interval[1]`).
    ///
    /// ```
    /// use motion::{AdditiveBezier, Pose, Reparametrized};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity()]).unwrap();
    /// assert!(Reparametrized::new(m.clone(), [1.0, 1.0]).is_err());
    /// assert!(Reparametrized::new(m, [1.0, 3.0]).is_ok());
    /// ```
    pub fn new(inner: M, interval: [T; 2]) -> Result<Self, CurveError> {
        check_breaks(&interval)?;
        Ok(Reparametrized { interval, inner })
    }

    /// The motion being reparametrised.
    ///
    /// ```
    /// use motion::{AdditiveBezier, Pose, Reparametrized};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity()]).unwrap();
    /// assert_eq!(Reparametrized::new(m.clone(), [0.0, 2.0]).unwrap().inner(), &m);
    /// ```
    pub fn inner(&self) -> &M {
        &self.inner
    }

    /// The parameter of `inner` for the outer parameter `t` (no domain check).
    ///
    /// ```
    /// use motion::{AdditiveBezier, Pose, Reparametrized};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity()]).unwrap();
    /// assert_eq!(Reparametrized::new(m, [2.0, 6.0]).unwrap().inner_parameter(&3.0), 0.25);
    /// ```
    pub fn inner_parameter(&self, t: &T) -> T {
        inner_parameter(&self.interval, &self.inner.domain(), t)
    }
}

impl<T: Field + PartialOrd, M: Motion<T>> Motion<T> for Reparametrized<T, M> {
    /// `inner` at the mapped parameter, by [`Motion::evaluate`]: an end of the interval that
    /// rounding maps a few ulps outside the inner domain is no error.
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        self.inner.evaluate(&self.inner_parameter(t))
    }

    fn domain(&self) -> [T; 2] {
        self.interval.clone()
    }
}

impl<T: Field + PartialOrd, U: Field + PartialOrd, M: MapScalar<T, U>> MapScalar<T, U> for Reparametrized<T, M> {
    type Mapped = Reparametrized<U, M::Mapped>;

    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> Self::Mapped {
        Reparametrized { interval: [f(&self.interval[0]), f(&self.interval[1])], inner: self.inner.map_scalar(f) }
    }
}

/// A piecewise motion: segment `k` runs over `[t_k, t_{k+1}]` (breakpoints `t_0 < ... < t_m`),
/// reparametrised onto its own domain. `S(t)` uses the segment with `t_k ≤ t < t_{k+1}` (the
/// last segment also at `t_m`); outside `[t_0, t_m]` evaluation fails with
/// [`CurveError::OutOfDomain`]. Segments need not join continuously: see the joins module for
/// constructing C1 and G1 joins.
///
/// ```
/// use motion::{CurveError, MultiplicativeBezier, Motion, Piecewise, Pose};
/// let seg = MultiplicativeBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])]).unwrap();
/// let m = Piecewise::new(vec![0.0, 0.5, 2.0], vec![seg.clone(), seg]).unwrap();
/// let s = m.pose(&1.25).unwrap(); // halfway through the second segment
/// assert!((s.e1inf - 0.25).abs() < 1e-15);
/// assert!(matches!(m.pose(&-0.1), Err(CurveError::OutOfDomain { .. })));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Piecewise<T, M> {
    breaks: Vec<T>,
    segments: Vec<M>,
}

impl<T: Field + PartialOrd, M: Motion<T>> Piecewise<T, M> {
    /// Segments with breakpoints `t_0 < t_1 < ... < t_m` (`m` = number of segments ≥ 1;
    /// finite, strictly increasing). Typed errors otherwise.
    ///
    /// ```
    /// use motion::{AdditiveBezier, CurveError, Piecewise, Pose};
    /// let seg = AdditiveBezier::new(vec![Pose::<f64>::identity()]).unwrap();
    /// assert!(matches!(Piecewise::new(vec![0.0, 1.0], vec![seg.clone(), seg.clone()]), Err(CurveError::BreakCount { .. })));
    /// assert!(matches!(
    ///     Piecewise::new(vec![0.0, 1.0, 1.0], vec![seg.clone(), seg]),
    ///     Err(CurveError::BreaksNotIncreasing { index: 2, .. })
    /// ));
    /// ```
    pub fn new(breaks: Vec<T>, segments: Vec<M>) -> Result<Self, CurveError> {
        if segments.is_empty() {
            return Err(CurveError::NoSegments);
        }
        if breaks.len() != segments.len() + 1 {
            return Err(CurveError::BreakCount { segments: segments.len(), got: breaks.len() });
        }
        check_breaks(&breaks)?;
        Ok(Piecewise { breaks, segments })
    }

    /// Segment `k` on `[k, k + 1]`: the motion runs over `[0, m]`.
    ///
    /// ```
    /// use motion::{AdditiveBezier, Motion, Piecewise, Pose};
    /// let seg = AdditiveBezier::new(vec![Pose::<f64>::identity()]).unwrap();
    /// assert_eq!(Piecewise::uniform(vec![seg.clone(), seg.clone(), seg]).unwrap().domain(), [0.0, 3.0]);
    /// ```
    pub fn uniform(segments: Vec<M>) -> Result<Self, CurveError> {
        let breaks = (0..=segments.len()).map(|k| T::from_i64(k as i64)).collect();
        Piecewise::new(breaks, segments)
    }

    /// The breakpoints `t_0 < ... < t_m`.
    ///
    /// ```
    /// use motion::{AdditiveBezier, Piecewise, Pose};
    /// let seg = AdditiveBezier::new(vec![Pose::<f64>::identity()]).unwrap();
    /// assert_eq!(Piecewise::new(vec![1.0, 3.0], vec![seg]).unwrap().breaks(), [1.0, 3.0]);
    /// ```
    pub fn breaks(&self) -> &[T] {
        &self.breaks
    }

    /// The segments, each on its own domain.
    ///
    /// ```
    /// use motion::{AdditiveBezier, Piecewise, Pose};
    /// let seg = AdditiveBezier::new(vec![Pose::<f64>::identity()]).unwrap();
    /// assert_eq!(Piecewise::uniform(vec![seg.clone(), seg]).unwrap().segments().len(), 2);
    /// ```
    pub fn segments(&self) -> &[M] {
        &self.segments
    }

    /// The index `k` of the segment used at `t` (`t_k ≤ t < t_{k+1}`, the last one at `t_m`).
    /// Fails outside `[t_0, t_m]`.
    ///
    /// ```
    /// use motion::{AdditiveBezier, Piecewise, Pose};
    /// let seg = AdditiveBezier::new(vec![Pose::<f64>::identity()]).unwrap();
    /// let m = Piecewise::uniform(vec![seg.clone(), seg]).unwrap();
    /// assert_eq!([0.0, 0.5, 1.0, 2.0].map(|t| m.segment_index(&t).unwrap()), [0, 0, 1, 1]);
    /// assert!(m.segment_index(&2.1).is_err());
    /// ```
    pub fn segment_index(&self, t: &T) -> Result<usize, CurveError> {
        let m = self.segments.len();
        check_domain(t, &[self.breaks[0].clone(), self.breaks[m].clone()])?;
        Ok((0..m).rev().find(|&k| self.breaks[k] <= *t).unwrap_or(0))
    }

    /// Segment `k` alone on its closed interval `[t_k, t_{k+1}]`: for the one-sided pose and
    /// derivatives at the ends of a segment (at a join, `piece(k)` at `t_{k+1}` is the value
    /// from the left, `piece(k + 1)` the value from the right).
    ///
    /// ```
    /// use motion::{AdditiveBezier, Motion, Piecewise, Pose};
    /// let a = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])]).unwrap();
    /// let b = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[0.0, 1.0, 0.0])]).unwrap();
    /// let m = Piecewise::uniform(vec![a, b]).unwrap();
    /// assert_eq!(m.piece(0).unwrap().pose(&1.0).unwrap(), Pose::translation(&[1.0, 0.0, 0.0]));
    /// assert_eq!(m.pose(&1.0).unwrap(), Pose::identity());
    /// ```
    pub fn piece(&self, k: usize) -> Option<Reparametrized<T, M>>
    where
        M: Clone,
    {
        let inner = self.segments.get(k)?.clone();
        Some(Reparametrized { interval: [self.breaks[k].clone(), self.breaks[k + 1].clone()], inner })
    }
}

impl<T: Field + PartialOrd, M: Motion<T>> Motion<T> for Piecewise<T, M> {
    /// The segment with `t_k ≤ t < t_{k+1}` (the first below `t_0`, the last from `t_m` on),
    /// at its reparametrised parameter.
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        let k = (1..self.segments.len()).rev().find(|&k| self.breaks[k] <= *t).unwrap_or(0);
        let seg = &self.segments[k];
        seg.evaluate(&inner_parameter(&[self.breaks[k].clone(), self.breaks[k + 1].clone()], &seg.domain(), t))
    }

    fn domain(&self) -> [T; 2] {
        [self.breaks[0].clone(), self.breaks[self.breaks.len() - 1].clone()]
    }
}

impl<T: Field + PartialOrd, U: Field + PartialOrd, M: MapScalar<T, U>> MapScalar<T, U> for Piecewise<T, M> {
    type Mapped = Piecewise<U, M::Mapped>;

    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> Self::Mapped {
        Piecewise {
            breaks: self.breaks.iter().map(f).collect(),
            segments: self.segments.iter().map(|s| s.map_scalar(f)).collect(),
        }
    }
}

/// `a + (t - t_0)/(t_1 - t_0) · (b - a)`: the parameter on `[a, b]` for `t` on `[t_0, t_1]`.
fn inner_parameter<T: Field>(interval: &[T; 2], domain: &[T; 2], t: &T) -> T {
    let [t0, t1] = interval;
    let [a, b] = domain;
    let len = t1.sub_ref(t0);
    let s = if len.is_finite_value() {
        t.sub_ref(t0).div_ref(&len)
    } else {
        // [-1e308, 1e308]: the length overflows, the length of the halved interval does not
        let h = T::from_ratio(1, 2);
        let (t, t0, t1) = (t.mul_ref(&h), t0.mul_ref(&h), t1.mul_ref(&h));
        t.sub_ref(&t0).div_ref(&t1.sub_ref(&t0))
    };
    a.add_ref(&s.mul_ref(&b.sub_ref(a)))
}

/// Finite and strictly increasing.
fn check_breaks<T: Ring + PartialOrd>(breaks: &[T]) -> Result<(), CurveError> {
    for (index, t) in breaks.iter().enumerate() {
        if !t.is_finite_value() {
            return Err(CurveError::NotFiniteParameter { what: "breakpoint", index, value: t.to_string() });
        }
        if index > 0 && *t <= breaks[index - 1] {
            return Err(CurveError::BreaksNotIncreasing {
                index,
                value: t.to_string(),
                previous: breaks[index - 1].to_string(),
            });
        }
    }
    Ok(())
}

/// Any of the motions of this crate, as one type: segments of a [`Piecewise`] motion may then
/// mix kinds (e.g. an additive arc followed by a multiplicative segment).
///
/// ```
/// use motion::{AdditiveBezier, AnyMotion, Motion, MultiplicativeBezier, Piecewise, Pose};
/// let b = Pose::<f64>::translation(&[1.0, 0.0, 0.0]);
/// let first: AnyMotion<f64> = AdditiveBezier::new(vec![Pose::identity(), b.clone()]).unwrap().into();
/// let second = MultiplicativeBezier::new(vec![b, Pose::translation(&[2.0, 0.0, 0.0])]).unwrap().into();
/// let m = Piecewise::uniform(vec![first, second]).unwrap();
/// assert!((m.pose(&1.5).unwrap().e1inf - 0.75).abs() < 1e-15);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub enum AnyMotion<T: Ring> {
    /// An additive Bezier motion (eq. 18).
    AdditiveBezier(AdditiveBezier<T>),
    /// A multiplicative Bezier motion (Fig. 2).
    MultiplicativeBezier(MultiplicativeBezier<T>),
    /// An additive B-spline motion.
    AdditiveBSpline(AdditiveBSpline<T>),
    /// A multiplicative B-spline motion.
    MultiplicativeBSpline(MultiplicativeBSpline<T>),
}

macro_rules! any_motion_from {
    ($($variant:ident),*) => {$(
        impl<T: Ring> From<$variant<T>> for AnyMotion<T> {
            fn from(m: $variant<T>) -> Self {
                AnyMotion::$variant(m)
            }
        }
    )*};
}

any_motion_from!(AdditiveBezier, MultiplicativeBezier, AdditiveBSpline, MultiplicativeBSpline);

impl<T: Real> Motion<T> for AnyMotion<T> {
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        match self {
            AnyMotion::AdditiveBezier(m) => m.evaluate(t),
            AnyMotion::MultiplicativeBezier(m) => m.evaluate(t),
            AnyMotion::AdditiveBSpline(m) => m.evaluate(t),
            AnyMotion::MultiplicativeBSpline(m) => m.evaluate(t),
        }
    }

    fn domain(&self) -> [T; 2] {
        match self {
            AnyMotion::AdditiveBezier(m) => m.domain(),
            AnyMotion::MultiplicativeBezier(m) => m.domain(),
            AnyMotion::AdditiveBSpline(m) => m.domain(),
            AnyMotion::MultiplicativeBSpline(m) => m.domain(),
        }
    }
}

impl<T: Real, U: Real> MapScalar<T, U> for AnyMotion<T> {
    type Mapped = AnyMotion<U>;

    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> AnyMotion<U> {
        match self {
            AnyMotion::AdditiveBezier(m) => AnyMotion::AdditiveBezier(m.map_scalar(f)),
            AnyMotion::MultiplicativeBezier(m) => AnyMotion::MultiplicativeBezier(m.map_scalar(f)),
            AnyMotion::AdditiveBSpline(m) => AnyMotion::AdditiveBSpline(m.map_scalar(f)),
            AnyMotion::MultiplicativeBSpline(m) => AnyMotion::MultiplicativeBSpline(m.map_scalar(f)),
        }
    }
}
