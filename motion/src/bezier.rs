//! Motion curves: the [`Motion`] trait shared by every motion, the curve error [`CurveError`],
//! and the Bezier motions of Sec. 4 of the main paper.
//!
//! * [`AdditiveBezier`]: `S(t) = Σ B_i^n(t) S_i` (eq. 18), evaluated by the Bernstein sum or by
//!   the de Casteljau tableau of additive combinations `(1 - t) A + t B` (eq. 17). Polynomial in
//!   `t`, so it works over any [`Ring`] (exact over rationals) and is generally not unitary.
//! * [`MultiplicativeBezier`]: the de Casteljau tableau of Fig. 2 with the slerp
//!   `Φ(A, B; t) = A (rev(A) B)^t` (eq. 15) as the pairwise combination.
//!
//! A motion is evaluated at a parameter of its scalar type; to differentiate, lift the control
//! poses to dual numbers with [`MapScalar::map_scalar`] and run the *same* evaluation code at
//! `t + ε` (see [`crate::velocity`]): no derivative formula is written by hand.
//!
//! ```
//! use motion::{AdditiveBezier, Motion, MultiplicativeBezier, Pose};
//! let a = Pose::<f64>::identity();
//! let b = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &1.0, &[1.0, 0.0, 0.0]).unwrap();
//! let c = Pose::translation(&[2.0, 1.0, 0.0]);
//! let add = AdditiveBezier::new(vec![a.clone(), b.clone(), c.clone()]).unwrap();
//! let mul = MultiplicativeBezier::new(vec![a, b, c.clone()]).unwrap();
//! // Both interpolate the end poses.
//! assert_eq!(add.pose(&1.0).unwrap(), c);
//! assert!(mul.pose(&1.0).unwrap().is_equivalent(&c, &1e-14).unwrap());
//! ```

use crate::blend::{Additive, Blend, Multiplicative};
use crate::de_casteljau::{additive_apex, tableau_with};
use crate::joins::JoinError;
use crate::{Even, MotionError, Pose};
use algebra_core::{Field, Real, Ring};
use std::convert::Infallible;

pub use crate::error::CurveError;

/// A motion `t ↦ S(t)` over a parameter interval: Bezier, B-spline, piecewise, reparametrised.
///
/// The trait asks only for a [`Ring`]: an additive motion over exact rationals is a `Motion`.
/// Changing the scalar (lifting to dual numbers to differentiate) is [`MapScalar`]; the
/// velocity functions of [`crate::velocity`] ask for `MapScalar<T, Jet<T>>`, so they work for
/// every motion whose kind works over `Jet<T>` (additive over `Q` included).
///
/// ```
/// use algebra_core::Jet;
/// use motion::{AdditiveBezier, MapScalar, Motion, Pose};
/// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])]).unwrap();
/// assert_eq!(m.domain(), [0.0, 1.0]);
/// let lifted = m.map_scalar(&|x: &f64| Jet::constant(*x));
/// let s = lifted.pose(&Jet::variable(0.5)).unwrap();
/// assert_eq!(s.e1inf, Jet::new(0.5, 1.0)); // S = 1 + t e1inf, dS/dt = e1inf
/// ```
pub trait Motion<T: Ring> {
    /// The pose `S(t)` for `t` in [`Motion::domain`]: fails outside it (and for NaN) with
    /// [`CurveError::OutOfDomain`], and where the construction meets a singular pose. Needs
    /// ordered scalars (over unordered ones use [`Motion::evaluate`]).
    ///
    /// ```
    /// use motion::{Motion, MultiplicativeBezier, Pose};
    /// let m = MultiplicativeBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])]).unwrap();
    /// let p = m.pose(&0.25).unwrap().transform_point(&[0.0, 0.0, 0.0]).unwrap();
    /// assert!((p[0] - 0.5).abs() < 1e-15);
    /// assert!(m.pose(&1.25).is_err());
    /// ```
    fn pose(&self, t: &T) -> Result<Pose<T>, CurveError>
    where
        T: PartialOrd,
    {
        check_domain(t, &self.domain())?;
        self.evaluate(t)
    }

    /// The construction evaluated at any `t`, without the domain check: outside the domain it
    /// continues the formula (polynomial, power or end span). Used by reparametrisations, where
    /// rounding may put an end of an interval a few ulps outside the inner domain; clamping
    /// instead would drop the derivative part of a dual-number parameter.
    ///
    /// ```
    /// use motion::{AdditiveBezier, Motion, Pose};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])]).unwrap();
    /// assert_eq!(m.evaluate(&2.0).unwrap(), Pose::translation(&[4.0, 0.0, 0.0]));
    /// ```
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError>;

    /// The parameter interval `[start, end]` (closed).
    ///
    /// ```
    /// use motion::{Motion, MultiplicativeBezier, Pose};
    /// let m = MultiplicativeBezier::new(vec![Pose::<f64>::identity()]).unwrap();
    /// assert_eq!(m.domain(), [0.0, 1.0]);
    /// ```
    fn domain(&self) -> [T; 2];
}

/// The same motion over the scalar `U`: every scalar (control-pose coefficient, knot,
/// breakpoint) mapped by a function that should embed `T` in `U` (e.g. `x ↦ Jet::constant(x)`).
/// Lifting to dual numbers and evaluating at `t + ε` gives `S(t)` and `dS/dt` from the same
/// code (see [`crate::velocity`]).
///
/// ```
/// use algebra_core::Jet;
/// use motion::{MapScalar, Motion, MultiplicativeBezier, Pose};
/// let m = MultiplicativeBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])]).unwrap();
/// let d = m.map_scalar(&|x: &f64| Jet::constant(*x)).pose(&Jet::variable(0.3)).unwrap();
/// assert!((d.e1inf.eps - 1.0).abs() < 1e-15);
/// ```
pub trait MapScalar<T: Ring, U: Ring>: Motion<T> {
    /// The motion over `U`.
    type Mapped: Motion<U>;

    /// The motion with every scalar mapped by `f`.
    ///
    /// ```
    /// use algebra_core::rational::{q, rational_to_f64, Q};
    /// use motion::{AdditiveBezier, MapScalar, Motion, Pose};
    /// let m = AdditiveBezier::new(vec![Pose::<Q>::identity(), Pose::translation(&[q(2), q(0), q(0)])]).unwrap();
    /// let f = m.map_scalar(&|x: &Q| rational_to_f64(x));
    /// assert_eq!(f.evaluate(&0.5).unwrap(), Pose::translation(&[1.0, 0.0, 0.0]));
    /// ```
    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> Self::Mapped;
}

impl<T: Ring> Pose<T> {
    /// The same pose over another scalar, each coefficient mapped by `f` (e.g. lifting to dual
    /// numbers).
    ///
    /// ```
    /// use algebra_core::Jet;
    /// let p = motion::Pose::translation(&[2.0, 0.0, 0.0]).map_scalar(&|x: &f64| Jet::constant(*x));
    /// assert_eq!(p.e1inf, Jet::constant(1.0));
    /// ```
    pub fn map_scalar<U: Ring>(&self, f: &dyn Fn(&T) -> U) -> Pose<U> {
        map_even(self, f)
    }
}

/// An even element with each coefficient mapped by `f`.
pub(crate) fn map_even<T: Ring, U: Ring>(m: &Pose<T>, f: &dyn Fn(&T) -> U) -> Pose<U> {
    Pose::new(f(&m.scalar), f(&m.e12), f(&m.e13), f(&m.e23), f(&m.e1inf), f(&m.e2inf), f(&m.e3inf), f(&m.e123inf))
}

/// `Ok` when `start ≤ t ≤ end` (false for NaN), else [`CurveError::OutOfDomain`].
pub(crate) fn check_domain<T: Ring + PartialOrd>(t: &T, domain: &[T; 2]) -> Result<(), CurveError> {
    if *t >= domain[0] && *t <= domain[1] {
        Ok(())
    } else {
        Err(CurveError::OutOfDomain { t: t.to_string(), start: domain[0].to_string(), end: domain[1].to_string() })
    }
}

fn unit_interval<T: Ring>() -> [T; 2] {
    [T::zero(), T::one()]
}

fn at_least_one<T>(poses: &[T]) -> Result<(), CurveError> {
    if poses.is_empty() { Err(CurveError::TooFewPoses { need: 1, got: 0 }) } else { Ok(()) }
}

/// [`MotionError::NotFinite`] (operation `op`) for the first pose with a NaN or infinite
/// coefficient.
pub(crate) fn finite_poses<'a, T: Ring + 'a>(
    op: &'static str,
    poses: impl IntoIterator<Item = &'a Pose<T>>,
) -> Result<(), MotionError> {
    match poses.into_iter().find(|p| !p.iter().all(Ring::is_finite_value)) {
        Some(p) => Err(MotionError::NotFinite { op, value: p.to_string() }),
        None => Ok(()),
    }
}

/// A Bezier motion of degree `n` on `[0, 1]` with the pairwise combination of the blend `B`
/// ([`Additive`]: eq. 18, [`Multiplicative`]: Fig. 2 with eq. 15), from `n + 1 ≥ 1` control
/// poses (unit or not). [`AdditiveBezier`] and [`MultiplicativeBezier`] name the two kinds.
///
/// ```
/// use motion::{Additive, Bezier, Motion, Multiplicative, Pose};
/// let poses = vec![Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])];
/// let a = Bezier::<f64, Additive>::new(poses.clone()).unwrap();
/// let m = Bezier::<f64, Multiplicative>::new(poses).unwrap();
/// // A pure translation: both kinds agree.
/// assert_eq!(a.pose(&0.5).unwrap(), m.pose(&0.5).unwrap());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Bezier<T: Ring, B> {
    poses: Vec<Pose<T>>,
    blend: B,
}

/// The additive Bezier motion `S(t) = Σ_{i=0}^{n} C(n, i) (1 - t)^{n-i} t^i S_i` (eq. 18) of
/// degree `n` on `[0, 1]`, from `n + 1 ≥ 1` control poses (unit or not).
///
/// Polynomial in `t`, so evaluation needs only a [`Ring`]: exact over rationals and
/// polynomials. `S(0) = S_0` and `S(1) = S_n` exactly. `S(t)` is generally not unitary and is
/// singular (the zero transform) where it passes through a singular element; the velocity
/// functions report that as an error.
///
/// ```
/// use algebra_core::rational::{q, ratio, Q};
/// use motion::{AdditiveBezier, Pose};
/// let m = AdditiveBezier::new(vec![
///     Pose::<Q>::identity(),
///     Pose::translation(&[q(2), q(0), q(0)]),
///     Pose::translation(&[q(2), q(2), q(0)]),
/// ]).unwrap();
/// let half = ratio(1, 2);
/// assert_eq!(m.bernstein(&half), m.de_casteljau(&half));
/// assert_eq!(m.bernstein(&half), Pose::translation(&[ratio(3, 2), ratio(1, 2), q(0)]));
/// ```
pub type AdditiveBezier<T> = Bezier<T, Additive>;

/// The multiplicative Bezier motion of degree `n` on `[0, 1]`: the de Casteljau tableau of
/// Fig. 2 with the slerp `Φ(A, B; t) = A (rev(A) B)^t` (eq. 15, [`Pose::slerp`]) as the
/// pairwise combination.
///
/// Control poses are used as given (the paper's definition). With unitary control poses the
/// motion is unitary, `S(0) = S_0`, `S(1) = S_n`, and reversing the poses reverses the motion.
/// With non-unit poses every tableau entry is a pseudoscalar multiple of the unitized one
/// (eq. 16, Lemma 4.1): the same transforms, but `S(1)` is only *equivalent* to `S_n`, the
/// reversal holds only up to equivalence, and Theorem 4.5(ii)'s formula at `t = 1` fails
/// (see the tests); [`MultiplicativeBezier::unitized`] avoids all of that.
///
/// ```
/// use motion::{Motion, MultiplicativeBezier, Pose};
/// let r = Pose::rotation(&[0.0, 0.0, 1.0], &std::f64::consts::FRAC_PI_2).unwrap();
/// let m = MultiplicativeBezier::new(vec![Pose::identity(), r.clone()]).unwrap();
/// let half = m.pose(&0.5).unwrap();
/// assert!(half.is_equivalent(&Pose::rotation(&[0.0, 0.0, 1.0], &std::f64::consts::FRAC_PI_4).unwrap(), &1e-15).unwrap());
/// ```
pub type MultiplicativeBezier<T> = Bezier<T, Multiplicative>;

impl<T: Ring, B: Default> Bezier<T, B> {
    /// The motion with control poses `S_0, ..., S_n` (at least one, every coefficient finite:
    /// [`MotionError::NotFinite`] otherwise).
    ///
    /// ```
    /// use motion::{AdditiveBezier, CurveError, MotionError, Pose};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(); 4]).unwrap();
    /// assert_eq!(m.degree(), 3);
    /// let nan = Pose::translation(&[f64::NAN, 0.0, 0.0]);
    /// assert!(matches!(AdditiveBezier::new(vec![nan]), Err(CurveError::Pose(MotionError::NotFinite { .. }))));
    /// ```
    pub fn new(poses: Vec<Pose<T>>) -> Result<Self, CurveError> {
        at_least_one(&poses)?;
        finite_poses("control pose", &poses)?;
        Ok(Bezier { poses, blend: B::default() })
    }

    /// The control poses.
    ///
    /// ```
    /// let m = motion::MultiplicativeBezier::new(vec![motion::Pose::<f64>::identity(); 2]).unwrap();
    /// assert_eq!(m.poses().len(), 2);
    /// ```
    pub fn poses(&self) -> &[Pose<T>] {
        &self.poses
    }

    /// The degree `n` (number of control poses minus one).
    ///
    /// ```
    /// assert_eq!(motion::AdditiveBezier::new(vec![motion::Pose::<f64>::identity()]).unwrap().degree(), 0);
    /// ```
    pub fn degree(&self) -> usize {
        self.poses.len() - 1
    }

    /// The control poses in reverse order: `S_{n..0}(1 - t) = S_{0..n}(t)` for every `t` for
    /// additive motions (the Bernstein basis is symmetric), exactly over exact scalars; for
    /// multiplicative ones with unitary control poses (the paper's proof of Theorem 4.5 at
    /// `t = 1`), and for non-unit ones only up to a pseudoscalar factor (the same transform).
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio, Q};
    /// use motion::{AdditiveBezier, MultiplicativeBezier, Pose};
    /// let m = AdditiveBezier::new(vec![Pose::<Q>::identity(), Pose::translation(&[q(3), q(0), q(0)])]).unwrap();
    /// assert_eq!(m.reversed().bernstein(&ratio(1, 3)), m.bernstein(&ratio(2, 3)));
    /// let b = Pose::from_axis_angle_translation(&[1.0, 0.0, 0.0], &1.0, &[0.0, 2.0, 0.0]).unwrap();
    /// let m = MultiplicativeBezier::new(vec![Pose::<f64>::identity(), b]).unwrap();
    /// let (x, y) = (m.de_casteljau(&0.3).unwrap(), m.reversed().de_casteljau(&0.7).unwrap());
    /// assert!((&x - &y).components().iter().all(|c| c.abs() < 1e-15));
    /// ```
    pub fn reversed(&self) -> Self {
        Bezier { poses: self.poses.iter().rev().cloned().collect(), blend: B::default() }
    }
}

impl<T: Ring, B: Blend<T>> Bezier<T, B> {
    /// The end indicatrices `[Ψ(0), Ψ(1)]` (eq. 20 or 21, [`Blend::end_indicatrices`]).
    ///
    /// ```
    /// use algebra_core::rational::{q, Q};
    /// use motion::{AdditiveBezier, Pose};
    /// let m = AdditiveBezier::new(vec![Pose::<Q>::identity(), Pose::translation(&[q(2), q(0), q(0)])]).unwrap();
    /// assert_eq!(m.end_indicatrices()?[0].e1inf, q(2));
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    pub fn end_indicatrices(&self) -> Result<[Even<T>; 2], JoinError>
    where
        T: Field,
    {
        B::end_indicatrices(&self.poses)
    }
}

impl<T: Ring, B: Blend<T>> Motion<T> for Bezier<T, B> {
    /// `S(t)`: the apex of the de Casteljau tableau of [`Blend::blend`] ([`Blend::apex`]; for
    /// additive motions the Bernstein sum agrees).
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        Ok(B::apex(&self.poses, t)?)
    }

    fn domain(&self) -> [T; 2] {
        unit_interval()
    }
}

impl<T: Ring, U: Ring, B: Blend<T> + Blend<U>> MapScalar<T, U> for Bezier<T, B> {
    type Mapped = Bezier<U, B>;

    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> Bezier<U, B> {
        Bezier { poses: self.poses.iter().map(|p| p.map_scalar(f)).collect(), blend: self.blend }
    }
}

impl<T: Ring> Bezier<T, Additive> {
    /// `S(t)` by the Bernstein sum of eq. (18), for any `t` (extrapolates outside `[0, 1]`).
    /// Binomial coefficients are built as exact ratios.
    ///
    /// ```
    /// use motion::{AdditiveBezier, Pose};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[4.0, 0.0, 0.0])]).unwrap();
    /// assert_eq!(m.bernstein(&0.25), Pose::translation(&[1.0, 0.0, 0.0]));
    /// ```
    pub fn bernstein(&self, t: &T) -> Pose<T> {
        let n = self.degree();
        let s = T::one().sub_ref(t);
        let mut t_pow = Vec::with_capacity(n + 1);
        let mut s_pow = Vec::with_capacity(n + 1);
        t_pow.push(T::one());
        s_pow.push(T::one());
        for i in 1..=n {
            t_pow.push(t_pow[i - 1].mul_ref(t));
            s_pow.push(s_pow[i - 1].mul_ref(&s));
        }
        let mut binomial = T::one();
        let mut sum = Pose::zero();
        for (i, pose) in self.poses.iter().enumerate() {
            if i > 0 {
                binomial = binomial.mul_ref(&T::from_ratio((n + 1 - i) as i64, i as i64));
            }
            let weight = binomial.mul_ref(&s_pow[n - i]).mul_ref(&t_pow[i]);
            sum += pose.scale(&weight);
        }
        sum
    }

    /// `S(t)` by the de Casteljau tableau of additive combinations `(1 - t) A + t B`
    /// (Fig. 2 with eq. 17), for any `t`.
    ///
    /// ```
    /// use motion::{AdditiveBezier, Pose};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[4.0, 0.0, 0.0])]).unwrap();
    /// assert_eq!(m.de_casteljau(&0.25), Pose::translation(&[1.0, 0.0, 0.0]));
    /// ```
    pub fn de_casteljau(&self, t: &T) -> Pose<T> {
        additive_apex(&self.poses, t)
    }

    /// The whole de Casteljau tableau at `t`: column 0 is the control poses, column `k` holds
    /// `S_{i,...,i+k}(t)` for `i = 0..=n-k`, the last column is `[S(t)]` (Fig. 2).
    ///
    /// ```
    /// use motion::{AdditiveBezier, Pose};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(); 4]).unwrap();
    /// let tab = m.tableau(&0.5);
    /// assert_eq!(tab.iter().map(Vec::len).collect::<Vec<_>>(), [4, 3, 2, 1]);
    /// ```
    pub fn tableau(&self, t: &T) -> Vec<Vec<Pose<T>>> {
        let Ok(columns) = tableau_with::<T, Infallible>(&self.poses, t, |a, b, t| Ok(Pose::lerp(a, b, t)));
        columns
    }

    /// Degree elevation: the same motion with `n + 2` control poses
    /// `S'_i = (i/(n+1)) S_{i-1} + (1 - i/(n+1)) S_i` (exact over exact scalars).
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio, Q};
    /// use motion::{AdditiveBezier, Pose};
    /// let m = AdditiveBezier::new(vec![Pose::<Q>::identity(), Pose::translation(&[q(3), q(0), q(0)])]).unwrap();
    /// let e = m.elevated();
    /// assert_eq!(e.degree(), 2);
    /// assert_eq!(e.bernstein(&ratio(1, 5)), m.bernstein(&ratio(1, 5)));
    /// ```
    pub fn elevated(&self) -> Self {
        let m = self.poses.len() as i64; // n + 1
        let mut poses = Vec::with_capacity(self.poses.len() + 1);
        poses.push(self.poses[0].clone());
        for i in 1..self.poses.len() {
            let w = T::from_ratio(i as i64, m);
            poses.push(&self.poses[i - 1].scale(&w) + &self.poses[i].scale(&T::one().sub_ref(&w)));
        }
        poses.push(self.poses[self.poses.len() - 1].clone());
        Bezier { poses, blend: Additive }
    }

    /// The same motion over another scalar (each control-pose coefficient mapped by `f`), for
    /// any [`Ring`] target (e.g. `Jet<Q>` for exact derivatives over the rationals).
    ///
    /// ```
    /// use algebra_core::Jet;
    /// use algebra_core::rational::{q, Q};
    /// use motion::{AdditiveBezier, Pose};
    /// let m = AdditiveBezier::new(vec![Pose::<Q>::identity(), Pose::translation(&[q(2), q(0), q(0)])]).unwrap();
    /// let d = m.map_ring(&|x: &Q| Jet::constant(x.clone())).bernstein(&Jet::variable(q(0)));
    /// assert_eq!(d.e1inf.eps, q(1)); // dS/dt = S_1 - S_0
    /// ```
    pub fn map_ring<U: Ring>(&self, f: &dyn Fn(&T) -> U) -> Bezier<U, Additive> {
        MapScalar::map_scalar(self, f)
    }
}

impl<T: Real> Bezier<T, Multiplicative> {
    /// `S(t)`: the apex of the slerp tableau, for any `t` (extrapolates outside `[0, 1]`).
    /// Fails when a slerp meets a singular pose.
    ///
    /// ```
    /// use motion::{MultiplicativeBezier, Pose};
    /// let m = MultiplicativeBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[4.0, 0.0, 0.0])]).unwrap();
    /// let s = m.de_casteljau(&0.25).unwrap();
    /// assert!((s.e1inf - 0.5).abs() < 1e-15);
    /// ```
    pub fn de_casteljau(&self, t: &T) -> Result<Pose<T>, CurveError> {
        // factored as exp(l) U with U unitized at every level: stable in the degree
        Ok(crate::stable_slerp::apex(&self.poses, t)?)
    }

    /// The whole slerp tableau at `t` (Fig. 2): column 0 is the control poses, column `k` holds
    /// `S_{i,...,i+k}(t)`, the last column `[S(t)]`.
    ///
    /// ```
    /// use motion::{MultiplicativeBezier, Pose};
    /// let m = MultiplicativeBezier::new(vec![Pose::<f64>::identity(); 4]).unwrap();
    /// let tab = m.tableau(&0.5).unwrap();
    /// assert_eq!(tab.iter().map(Vec::len).collect::<Vec<_>>(), [4, 3, 2, 1]);
    /// ```
    pub fn tableau(&self, t: &T) -> Result<Vec<Vec<Pose<T>>>, CurveError> {
        Ok(crate::stable_slerp::tableau(&self.poses, t)?)
    }

    /// The motion with every control pose unitized (`S_i/|S_i|`, Lemma 2.6(i)): the same
    /// transforms (Lemma 4.1), a unitary motion, and the end formulas of Theorem 4.5(ii) hold.
    /// Fails for a singular control pose.
    ///
    /// ```
    /// use motion::{Motion, MultiplicativeBezier, Pose};
    /// let m = MultiplicativeBezier::new(vec![Pose::<f64>::identity().scale(&2.0), Pose::translation(&[1.0, 0.0, 0.0])]).unwrap();
    /// assert!(m.unitized().unwrap().pose(&0.4).unwrap().is_unitary(&1e-15));
    /// ```
    pub fn unitized(&self) -> Result<Self, CurveError> {
        let poses = self.poses.iter().map(Pose::unitize).collect::<Result<Vec<_>, _>>()?;
        Ok(Bezier { poses, blend: Multiplicative })
    }
}
