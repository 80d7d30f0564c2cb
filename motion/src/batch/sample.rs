//! Sampling motions at many parameters at once: values `S(t)` and derivatives `dS/dt`, for one
//! motion or many, over lanes (`L::WIDTH` parameters per evaluation) and over cores.
//!
//! The motion is lifted once to the lane type (every control coefficient splatted over the
//! lanes, through [`MapScalar`]) and evaluated at `L::WIDTH` consecutive parameters at a time;
//! for derivatives it is lifted to [`Jet<L>`] and evaluated at `t + ε` (the same code, no
//! derivative formula), exactly as [`velocity::pose_derivative`](crate::velocity::pose_derivative)
//! does for one parameter.

use super::columns::map_rows;
use super::{BatchError, Lanes, Poses};
use crate::bezier::check_domain;
use crate::{MapScalar, Motion, Pose};
use algebra_core::{Field, Jet, Ring};

/// Poses and their parameter derivatives `dS/dt` sampled from `motions` motions at
/// `parameters` parameters each, row `m · parameters + k` for motion `m` at parameter `k`.
///
/// ```
/// use motion::{AdditiveBezier, Pose, batch::sample_many};
/// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])]).unwrap();
/// let s = sample_many::<f64, _>(&[m.clone(), m], &[0.0, 0.5]).unwrap();
/// assert_eq!((s.motions(), s.parameters()), (2, 2));
/// assert_eq!(s.pose(1, 1), Some(Pose::translation(&[1.0, 0.0, 0.0])));
/// assert_eq!(s.derivative(1, 1).unwrap().e1inf, 1.0);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Samples<T> {
    poses: Poses<T>,
    derivatives: Poses<T>,
    parameters: usize,
}

impl<T: Ring> Samples<T> {
    /// The sampled poses `S(t)`, row `m · parameters + k`.
    ///
    /// ```
    /// use motion::{AdditiveBezier, Pose, batch::sample_many};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity()]).unwrap();
    /// assert_eq!(sample_many::<f64, _>(&[m], &[0.0, 1.0]).unwrap().poses().len(), 2);
    /// ```
    pub fn poses(&self) -> &Poses<T> {
        &self.poses
    }

    /// The derivatives `dS/dt`, row `m · parameters + k`.
    ///
    /// ```
    /// use motion::{AdditiveBezier, Pose, batch::sample_many};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity()]).unwrap();
    /// assert_eq!(sample_many::<f64, _>(&[m], &[0.5]).unwrap().derivatives().get(0), Some(Pose::zero()));
    /// ```
    pub fn derivatives(&self) -> &Poses<T> {
        &self.derivatives
    }

    /// The number of parameters per motion.
    ///
    /// ```
    /// use motion::{AdditiveBezier, Pose, batch::sample_many};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity()]).unwrap();
    /// assert_eq!(sample_many::<f64, _>(&[m], &[0.0, 0.5, 1.0]).unwrap().parameters(), 3);
    /// ```
    pub fn parameters(&self) -> usize {
        self.parameters
    }

    /// The number of motions.
    ///
    /// ```
    /// use motion::{AdditiveBezier, Pose, batch::sample_many};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity()]).unwrap();
    /// assert_eq!(sample_many::<f64, _>(&[m.clone(), m], &[0.5]).unwrap().motions(), 2);
    /// ```
    pub fn motions(&self) -> usize {
        self.poses.len().checked_div(self.parameters).unwrap_or(0)
    }

    /// `S(t_k)` of motion `m`, `None` out of range.
    ///
    /// ```
    /// use motion::{AdditiveBezier, Pose, batch::sample_many};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity()]).unwrap();
    /// assert_eq!(sample_many::<f64, _>(&[m], &[0.5]).unwrap().pose(0, 0), Some(Pose::identity()));
    /// ```
    pub fn pose(&self, m: usize, k: usize) -> Option<Pose<T>> {
        (k < self.parameters).then(|| self.poses.get(m * self.parameters + k)).flatten()
    }

    /// `dS/dt` at `t_k` of motion `m`, `None` out of range.
    ///
    /// ```
    /// use motion::{AdditiveBezier, Pose, batch::sample_many};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])]).unwrap();
    /// assert_eq!(sample_many::<f64, _>(&[m], &[0.5]).unwrap().derivative(0, 0).unwrap().e1inf, 1.0);
    /// ```
    pub fn derivative(&self, m: usize, k: usize) -> Option<Pose<T>> {
        (k < self.parameters).then(|| self.derivatives.get(m * self.parameters + k)).flatten()
    }
}

impl<T: Field> Samples<T> {
    /// The velocity indicatrices `Ψ = 2 S⁻¹ dS/dt` (eq. 11) of every sample
    /// ([`velocity::indicatrix_from_derivative`](crate::velocity::indicatrix_from_derivative)).
    /// Fails with the row of the first singular `S`.
    ///
    /// ```
    /// use motion::{AdditiveBezier, Pose, batch::sample_many};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::identity().scale(&2.0)]).unwrap();
    /// let psi = sample_many::<f64, _>(&[m], &[1.0]).unwrap().indicatrices().unwrap();
    /// assert_eq!(psi.get(0).unwrap().scalar, 1.0); // S = 1 + t: Ψ = 2/(1 + t)
    /// ```
    pub fn indicatrices(&self) -> Result<Poses<T>, BatchError> {
        let rows = (0..self.poses.len()).map(|i| {
            let (s, ds) = (self.poses.get(i).expect("row"), self.derivatives.get(i).expect("row"));
            crate::velocity::indicatrix_from_derivative(&s, &ds)
                .map(Pose::into_array)
                .map_err(|source| BatchError::Pose { index: i, source })
        });
        Ok(Poses { cols: super::columns::Columns::from_rows(rows.collect::<Result<Vec<_>, _>>()?) })
    }
}

/// `S(t_k)` for every parameter `t_k`, evaluated `L::WIDTH` parameters at a time (`L = T`: the
/// scalar loop of [`Motion::pose`]); bit for bit `motion.pose(&t_k)`. Fails with the index of
/// the first parameter outside the domain (or NaN) or where the evaluation fails.
///
/// ```
/// use motion::{AdditiveBezier, Motion, Pose, batch::sample};
/// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])]).unwrap();
/// let s = sample::<f64, _>(&m, &[0.0, 0.25, 1.0]).unwrap();
/// assert_eq!(s.get(1), Some(m.pose(&0.25).unwrap()));
/// assert!(sample::<f64, _>(&m, &[0.5, 2.0]).is_err());
/// ```
pub fn sample<L, M>(motion: &M, ts: &[L::Elem]) -> Result<Poses<L::Elem>, BatchError>
where
    L: Lanes,
    L::Elem: PartialOrd,
    M: MapScalar<L::Elem, L>,
{
    check_parameters(motion, ts, 0)?;
    let lifted = motion.map_scalar(&|x| L::splat(x));
    let mut out = Poses::zeros(ts.len());
    let f = |[t]: [L; 1]| lifted.evaluate(&t).map(Pose::into_array).map_err(|_| 0);
    map_rows([ts], &[ts.first().cloned().unwrap_or_else(L::Elem::zero)], out.cols.views_mut(), &f)
        .map_err(|k| first_failure(motion, ts, k, 0))?;
    Ok(out)
}

/// `S(t_k)` and `dS/dt` at every parameter of every motion, evaluated `L::WIDTH` parameters
/// at a time over dual numbers `Jet<L>` (`L = T`: the scalar loop); bit for bit
/// [`velocity::pose_derivative`](crate::velocity::pose_derivative) per sample. Fails with the
/// motion and parameter index of the first failure (a parameter outside the domain, a failed
/// evaluation).
///
/// ```
/// use motion::{AdditiveBezier, Pose, batch::sample_many, velocity::pose_derivative};
/// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::rotation(&[0.0, 0.0, 1.0], &1.0).unwrap()]).unwrap();
/// let s = sample_many::<f64, _>(&[m.clone()], &[0.0, 0.3, 0.6]).unwrap();
/// let (p, dp) = pose_derivative(&m, &0.3).unwrap();
/// assert_eq!((s.pose(0, 1), s.derivative(0, 1)), (Some(p), Some(dp)));
/// ```
pub fn sample_many<L, M>(motions: &[M], ts: &[L::Elem]) -> Result<Samples<L::Elem>, BatchError>
where
    L: Lanes,
    L::Elem: PartialOrd,
    M: MapScalar<L::Elem, Jet<L>>,
{
    let mut out = Samples::zeros(motions.len(), ts.len());
    for (m, (motion, (values, derivatives))) in motions.iter().zip(out.blocks()).enumerate() {
        sample_one(m, motion, ts, values, derivatives)?;
    }
    Ok(out)
}

/// [`sample_many`] with the motions spread over every core (rayon); bit for bit the serial
/// result, and the same error (the first failing motion).
///
/// ```
/// use motion::{AdditiveBezier, Pose, batch::{par_sample_many, sample_many}};
/// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])]).unwrap();
/// let ms = vec![m; 50];
/// assert_eq!(par_sample_many::<f64, _>(&ms, &[0.0, 0.5]).unwrap(), sample_many::<f64, _>(&ms, &[0.0, 0.5]).unwrap());
/// ```
#[cfg(feature = "parallel")]
pub fn par_sample_many<L, M>(motions: &[M], ts: &[L::Elem]) -> Result<Samples<L::Elem>, BatchError>
where
    L: Lanes,
    L::Elem: PartialOrd,
    M: MapScalar<L::Elem, Jet<L>> + Sync,
{
    use rayon::prelude::*;
    let mut out = Samples::zeros(motions.len(), ts.len());
    let results: Vec<Result<(), BatchError>> = out
        .blocks()
        .into_par_iter()
        .zip(motions.par_iter())
        .enumerate()
        .map(|(m, ((values, derivatives), motion))| sample_one(m, motion, ts, values, derivatives))
        .collect();
    results.into_iter().collect::<Result<(), _>>()?;
    Ok(out)
}

pub(super) type Block<'a, T> = ([&'a mut [T]; 8], [&'a mut [T]; 8]);

impl<T: Ring> Samples<T> {
    pub(super) fn zeros(motions: usize, parameters: usize) -> Self {
        Samples {
            poses: Poses::zeros(motions * parameters),
            derivatives: Poses::zeros(motions * parameters),
            parameters,
        }
    }

    /// The output rows of each motion: `(values, derivatives)` columns.
    pub(super) fn blocks(&mut self) -> Vec<Block<'_, T>> {
        let n = self.parameters.max(1);
        let values = self.poses.cols.views_mut().map(|c| c.chunks_mut(n));
        let derivatives = self.derivatives.cols.views_mut().map(|c| c.chunks_mut(n));
        let mut values = values;
        let mut derivatives = derivatives;
        let mut blocks = Vec::new();
        while let (Some(v), Some(d)) = (next_row(&mut values), next_row(&mut derivatives)) {
            blocks.push((v, d));
        }
        blocks
    }
}

fn next_row<'a, T>(chunks: &mut [std::slice::ChunksMut<'a, T>; 8]) -> Option<[&'a mut [T]; 8]> {
    let next: [Option<&'a mut [T]>; 8] = std::array::from_fn(|c| chunks[c].next());
    if next.iter().any(Option::is_none) { None } else { Some(next.map(|c| c.expect("checked"))) }
}

/// One motion at every parameter, values and derivatives, into its block of rows.
pub(super) fn sample_one<L, M>(
    index: usize,
    motion: &M,
    ts: &[L::Elem],
    values: [&mut [L::Elem]; 8],
    derivatives: [&mut [L::Elem]; 8],
) -> Result<(), BatchError>
where
    L: Lanes,
    L::Elem: PartialOrd,
    M: MapScalar<L::Elem, Jet<L>>,
{
    check_parameters(motion, ts, index)?;
    let lifted = motion.map_scalar(&|x| Jet::constant(L::splat(x)));
    let [v0, v1, v2, v3, v4, v5, v6, v7] = values;
    let [d0, d1, d2, d3, d4, d5, d6, d7] = derivatives;
    let out = [v0, v1, v2, v3, v4, v5, v6, v7, d0, d1, d2, d3, d4, d5, d6, d7];
    let f = |[t]: [L; 1]| {
        let s = lifted.evaluate(&Jet::variable(t)).map_err(|_| 0usize)?;
        let s = s.into_array();
        Ok(std::array::from_fn(|c| if c < 8 { s[c].re.clone() } else { s[c - 8].eps.clone() }))
    };
    map_rows([ts], &[ts.first().cloned().unwrap_or_else(L::Elem::zero)], out, &f)
        .map_err(|k| first_failure(motion, ts, k, index))
}

/// Every parameter finite and in the motion's domain, else the first that is not.
pub(super) fn check_parameters<T: Ring + PartialOrd, M: Motion<T>>(
    motion: &M,
    ts: &[T],
    index: usize,
) -> Result<(), BatchError> {
    let domain = motion.domain();
    for (k, t) in ts.iter().enumerate() {
        check_domain(t, &domain).map_err(|source| BatchError::Curve { motion: index, parameter: k, source })?;
    }
    Ok(())
}

/// The error of the scalar evaluation at the first failing parameter of the chunk starting at
/// row `k` (a lane chunk fails as a whole; the scalar code names the parameter and the reason).
fn first_failure<T: Ring + PartialOrd, M: Motion<T>>(motion: &M, ts: &[T], k: usize, index: usize) -> BatchError {
    for (j, t) in ts.iter().enumerate().skip(k) {
        if let Err(source) = motion.evaluate(t) {
            return BatchError::Curve { motion: index, parameter: j, source };
        }
    }
    let source = crate::MotionError::NotFinite { op: "sample", value: "a lane evaluation".into() };
    BatchError::Curve { motion: index, parameter: k, source: source.into() }
}
