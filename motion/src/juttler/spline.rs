//! Jüttler's Algorithm 2 (Sec. 6, eqs. (40)-(44)): the C1 spline Q-motion through positions
//! `P_0, …, P_m` with parameters `t_0 < … < t_m` and velocities `v⃗_i`, `ω⃗_i` at them
//! (given, or estimated by step 1: [`super::velocity`]).
//!
//! Segment `i` on `[t_i, t_{i+1}]`, in the local parameter `u = (t - t_i)/Δt_i`, is the
//! product (40) `Q^{(i)} = Q_trans^{(i)} * Q_rot^{(i)}` of two cubic Q-motions:
//!
//! * (41) `Q_trans^{(i)}(u) = 2 + ε Σ_j b_j^3(u) p⃗_j` with `p⃗_0 = s⃗_i`,
//!   `p⃗_1 = s⃗_i + Δt_i/3 v⃗_i`, `p⃗_2 = s⃗_{i+1} - Δt_i/3 v⃗_{i+1}`, `p⃗_3 = s⃗_{i+1}`;
//! * (44) `Q_rot^{(i)}(u) = Σ_j b_j^3(u) C_j^{(i)}` (the OCR of the paper shows a spurious
//!   "2 + ε" in front of the sum), `C_0 = R_i`, `C_1 = R_i + Δt_i/6 ω⃗_i * R_i`,
//!   `C_2 = R_{i+1} - Δt_i/6 ω⃗_{i+1} * R_{i+1}`, `C_3 = R_{i+1}`,
//!
//! so each segment is a Q-motion of degree 6. `R_i` are the rotational parts with the signs of
//! (24). Then `dQ_rot/dt(t_i) = ½ ω⃗_i * R_i`, which by (42) has angular velocity `ω⃗_i` for
//! `R_i` of any length (the `λ R_i` of (43) is 0), and the translation of `Q^{(i)}` is
//! `Σ b_j^3 p⃗_j` exactly, with velocity `v⃗_i` at `t_i`. Both neighbouring segments take the
//! same dual quaternion and the same derivative at `t_i`: the motion is C1, exactly over
//! rationals. [`SplineQMotion::hermite`] uses the rotational parts at the poses' own scale
//! (exact); [`algorithm2`] first normalises them (23), as the paper does.
//!
//! ```
//! use motion::{Motion, Pose, juttler::spline::algorithm2};
//! let poses = [
//!     Pose::<f64>::identity(),
//!     Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &1.0, &[1.0, 2.0, 0.0]).unwrap(),
//!     Pose::from_axis_angle_translation(&[1.0, 0.0, 0.0], &0.5, &[3.0, 0.0, 1.0]).unwrap(),
//! ];
//! let m = algorithm2(&poses, &[0.0, 0.4, 1.0], None).unwrap();
//! assert_eq!(m.segments().len(), 2);
//! assert_eq!(m.segments()[0].degree(), 6);
//! assert!(m.pose(&0.4).unwrap().is_equivalent(&poses[1], &1e-12).unwrap());
//! ```

use super::tr::rotation_translation;
use super::velocity::{KeyVelocity, check_finite_velocities, check_spline_parameters, estimate_velocities, hodograph};
use super::{JuttlerError, QMotion, RationalBezier};
use crate::repr::dual_quaternion::{DualQuaternion, Quaternion};
use crate::{CurveError, MapScalar, Motion, Pose};
use algebra_core::{Field, Real, Ring};

/// A spline Q-motion (Jüttler Sec. 6): Q-motions `Q^{(i)}` on `[0, 1]`, segment `i` run over
/// `[t_i, t_{i+1}]` by `u = (t - t_i)/(t_{i+1} - t_i)`; at an interior `t_i` the segment to the
/// right is used. Built by Algorithm 2 ([`algorithm2`], [`SplineQMotion::hermite`]).
///
/// ```
/// use algebra_core::rational::{q, ratio};
/// use motion::{Pose, juttler::{KeyVelocity, SplineQMotion}};
/// let poses = [Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(2), q(0), q(0)])];
/// let v = vec![KeyVelocity::new([q(2), q(0), q(0)], [q(0), q(0), q(0)]); 2];
/// let m = SplineQMotion::hermite(&poses, &[q(0), q(1)], &v).unwrap();
/// let p = m.pose_exact(&ratio(1, 4)).unwrap().transform_point(&[q(0), q(0), q(0)]).unwrap();
/// assert_eq!(p, [ratio(1, 2), q(0), q(0)]);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct SplineQMotion<T> {
    breaks: Vec<T>,
    segments: Vec<QMotion<T>>,
}

impl<T: Ring> SplineQMotion<T> {
    /// Segments with their breaks (`breaks.len() = segments.len() + 1`, strictly increasing:
    /// the caller's invariant).
    pub(crate) fn from_pieces(breaks: Vec<T>, segments: Vec<QMotion<T>>) -> Self {
        SplineQMotion { breaks, segments }
    }

    /// The parameters `t_0 < … < t_m` (the segment ends).
    ///
    /// ```
    /// use motion::{Pose, juttler::spline::algorithm2};
    /// let p = [Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])];
    /// assert_eq!(algorithm2(&p, &[0.0, 2.0], None).unwrap().breaks(), [0.0, 2.0]);
    /// ```
    pub fn breaks(&self) -> &[T] {
        &self.breaks
    }

    /// The segments `Q^{(i)} = Q_trans^{(i)} * Q_rot^{(i)}` (40), each a Q-motion of degree 6
    /// on `[0, 1]` in its local parameter.
    ///
    /// ```
    /// use motion::{Pose, juttler::spline::algorithm2};
    /// let p = [Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])];
    /// assert_eq!(algorithm2(&p, &[0.0, 1.0], None).unwrap().segments()[0].degree(), 6);
    /// ```
    pub fn segments(&self) -> &[QMotion<T>] {
        &self.segments
    }

    /// The trajectory of the body point `x` as one rational Bézier curve per segment (degree
    /// 12), segment `i` in its local parameter `u ∈ [0, 1]` over `[t_i, t_{i+1}]` (Algorithm 3,
    /// step 2); exact over rationals.
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio};
    /// use motion::{Pose, juttler::{KeyVelocity, SplineQMotion}};
    /// let p = [Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(1), q(0), q(0)]), Pose::translation(&[q(1), q(1), q(0)])];
    /// let v = vec![KeyVelocity::new([q(1), q(0), q(0)], [q(0), q(0), q(1)]); 3];
    /// let m = SplineQMotion::hermite(&p, &[q(0), q(1), q(3)], &v).unwrap();
    /// let x = [q(1), q(2), q(0)];
    /// let paths = m.trajectories(&x);
    /// assert_eq!(paths[1].degree(), 12);
    /// // t = 2 is u = 1/2 in segment 1
    /// assert_eq!(paths[1].point(&ratio(1, 2)).unwrap(), m.pose_exact(&q(2)).unwrap().transform_point(&x).unwrap());
    /// ```
    pub fn trajectories(&self, x: &[T; 3]) -> Vec<RationalBezier<T>> {
        self.segments.iter().map(|s| s.trajectory(x)).collect()
    }

    /// The same spline over the scalar `U`, each coefficient and parameter mapped by `f`.
    ///
    /// ```
    /// use algebra_core::rational::{q, rational_to_f64};
    /// use motion::{Pose, juttler::{KeyVelocity, SplineQMotion}};
    /// let p = [Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(1), q(0), q(0)])];
    /// let v = vec![KeyVelocity::new([q(1), q(0), q(0)], [q(0), q(0), q(0)]); 2];
    /// let m = SplineQMotion::hermite(&p, &[q(0), q(1)], &v).unwrap();
    /// assert_eq!(m.map_ring(&rational_to_f64).breaks(), [0.0, 1.0]);
    /// ```
    pub fn map_ring<U: Ring>(&self, f: &dyn Fn(&T) -> U) -> SplineQMotion<U> {
        SplineQMotion {
            breaks: self.breaks.iter().map(f).collect(),
            segments: self.segments.iter().map(|s| s.map_ring(f)).collect(),
        }
    }
}

impl<T: Field + PartialOrd> SplineQMotion<T> {
    /// Steps 2-4 of Algorithm 2 with the given velocities (one [`KeyVelocity`] per position,
    /// `d/dt`, fixed frame): segments (40) from (41) and (44), the rotational parts `R_i` of the
    /// poses at their own scale with the signs of (24); exact over rationals. Fails for fewer
    /// than two positions, parameters that are not one per position and strictly increasing,
    /// a velocity count that differs, or a pose with a zero rotational part.
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use motion::{Pose, juttler::{JuttlerError, KeyVelocity, SplineQMotion}};
    /// let p = [Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(1), q(0), q(0)])];
    /// let v = vec![KeyVelocity::new([q(1), q(0), q(0)], [q(0), q(0), q(0)]); 2];
    /// assert!(matches!(SplineQMotion::hermite(&p, &[q(1), q(0)], &v), Err(JuttlerError::Parameters { .. })));
    /// assert!(matches!(SplineQMotion::hermite(&p, &[q(0), q(1)], &v[..1]), Err(JuttlerError::Parameters { .. })));
    /// ```
    pub fn hermite(poses: &[Pose<T>], params: &[T], velocities: &[KeyVelocity<T>]) -> Result<Self, JuttlerError> {
        check_spline_parameters(poses.len(), params)?;
        if velocities.len() != poses.len() {
            return Err(JuttlerError::Parameters {
                why: format!("{} velocities for {} positions", velocities.len(), poses.len()),
            });
        }
        let parts = aligned_parts(poses)?;
        let segments = (0..poses.len() - 1)
            .map(|i| {
                segment(
                    params[i + 1].sub_ref(&params[i]),
                    [&parts[i], &parts[i + 1]],
                    [&velocities[i], &velocities[i + 1]],
                )
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(SplineQMotion { breaks: params.to_vec(), segments })
    }

    /// The index `i` of the segment used at `t` (`t_i ≤ t < t_{i+1}`, the last one from `t_m`
    /// on, the first one below `t_0`) and the local parameter `u = (t - t_i)/Δt_i`.
    ///
    /// ```
    /// use motion::{Pose, juttler::spline::algorithm2};
    /// let p = [Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0]), Pose::translation(&[1.0, 1.0, 0.0])];
    /// let m = algorithm2(&p, &[0.0, 1.0, 3.0], None).unwrap();
    /// assert_eq!(m.local(&2.0), (1, 0.5));
    /// assert_eq!(m.local(&3.0), (1, 1.0));
    /// ```
    pub fn local(&self, t: &T) -> (usize, T) {
        let i = (1..self.segments.len()).rev().find(|&i| self.breaks[i] <= *t).unwrap_or(0);
        (i, self.local_in(i, t))
    }

    /// The local parameter of `t` in segment `i` (extrapolating outside `[t_i, t_{i+1}]`).
    fn local_in(&self, i: usize, t: &T) -> T {
        let dt = self.breaks[i + 1].sub_ref(&self.breaks[i]);
        t.sub_ref(&self.breaks[i]).mul_ref(&dt.try_recip().unwrap_or_else(T::zero))
    }

    /// `Q(t)` and `dQ/dt(t)` of segment `i` (one-sided at its ends; any `t`), exact over
    /// rationals; `None` for `i` out of range.
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use motion::{Pose, juttler::{KeyVelocity, SplineQMotion}};
    /// let p = [Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(1), q(0), q(0)]), Pose::translation(&[q(1), q(1), q(0)])];
    /// let v = vec![KeyVelocity::new([q(1), q(0), q(0)], [q(0), q(0), q(0)]); 3];
    /// let m = SplineQMotion::hermite(&p, &[q(0), q(1), q(2)], &v).unwrap();
    /// assert_eq!(m.segment_jet(0, &q(1)), m.segment_jet(1, &q(1))); // C1 at t_1
    /// ```
    pub fn segment_jet(&self, i: usize, t: &T) -> Option<(DualQuaternion<T>, DualQuaternion<T>)> {
        let seg = self.segments.get(i)?;
        let u = self.local_in(i, t);
        let du = self.breaks[i + 1].sub_ref(&self.breaks[i]).try_recip().unwrap_or_else(T::zero);
        Some((seg.eval(&u), hodograph(seg.control(), &u).scale(&du)))
    }

    /// `Q(t)` (the segment of [`SplineQMotion::local`]), exact over rationals.
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use motion::{Pose, juttler::{KeyVelocity, SplineQMotion}};
    /// let p = [Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(1), q(0), q(0)])];
    /// let v = vec![KeyVelocity::new([q(1), q(0), q(0)], [q(0), q(0), q(0)]); 2];
    /// let m = SplineQMotion::hermite(&p, &[q(0), q(1)], &v).unwrap();
    /// assert_eq!(m.eval(&q(1)).dual.x, q(1)); // (2 + ε (1, 0, 0)) * 1
    /// ```
    pub fn eval(&self, t: &T) -> DualQuaternion<T> {
        let (i, u) = self.local(t);
        self.segments[i].eval(&u)
    }

    /// The pose at `t` through the exact dual quaternion -> pose map (see
    /// [`QMotion::pose_exact`]); exact over rationals.
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio};
    /// use motion::{Pose, juttler::{KeyVelocity, SplineQMotion}};
    /// let p = [Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(1), q(0), q(0)])];
    /// let v = vec![KeyVelocity::new([q(1), q(0), q(0)], [q(0), q(0), q(0)]); 2];
    /// let m = SplineQMotion::hermite(&p, &[q(0), q(1)], &v).unwrap();
    /// assert!(m.pose_exact(&q(1)).unwrap().is_equivalent_exact(&p[1]));
    /// ```
    pub fn pose_exact(&self, t: &T) -> Result<Pose<T>, JuttlerError> {
        let (i, u) = self.local(t);
        self.segments[i].pose_exact(&u)
    }
}

/// A rotational part `R_i` and a translation `s_i` of a position (14).
pub(crate) type Parts<T> = (Quaternion<T>, [T; 3]);

/// The rotational parts `R_i` (at the poses' own scale, signs by (24): each nearer its
/// predecessor) and translations `s_i` of the poses (14).
pub(crate) fn aligned_parts<T: Field + PartialOrd>(poses: &[Pose<T>]) -> Result<Vec<Parts<T>>, JuttlerError> {
    let mut parts: Vec<Parts<T>> = Vec::with_capacity(poses.len());
    for p in poses {
        let (mut r, s) = rotation_translation(p)?;
        if parts.last().is_some_and(|(prev, _)| prev.dot(&r) < T::zero()) {
            r = r.scale(&T::one().neg_ref());
        }
        parts.push((r, s));
    }
    Ok(parts)
}

/// Segment `i` of (40) from `Δt_i`, the rotational parts and translations at both ends and
/// the velocities there.
fn segment<T: Field>(dt: T, ends: [&Parts<T>; 2], vel: [&KeyVelocity<T>; 2]) -> Result<QMotion<T>, JuttlerError> {
    let third = dt.mul_ref(&T::from_ratio(1, 3));
    let sixth = dt.mul_ref(&T::from_ratio(1, 6));
    let [(r0, s0), (r1, s1)] = ends;
    let off = |s: &[T; 3], v: &[T; 3], sign: &T| -> [T; 3] {
        std::array::from_fn(|k| s[k].add_ref(&v[k].mul_ref(&third).mul_ref(sign)))
    };
    let (plus, minus) = (T::one(), T::one().neg_ref());
    // (41)
    let p = [s0.clone(), off(s0, &vel[0].velocity, &plus), off(s1, &vel[1].velocity, &minus), s1.clone()];
    let two = Quaternion::new(T::from_i64(2), T::zero(), T::zero(), T::zero());
    let trans = QMotion::new_exact(p.iter().map(|p| DualQuaternion::new(two.clone(), Quaternion::pure(p))).collect())?;
    // (44), without the OCR's "2 + ε"
    let turn = |r: &Quaternion<T>, w: &[T; 3], sign: &T| -> DualQuaternion<T> {
        let dr = (&Quaternion::pure(w) * r).scale(&sixth.mul_ref(sign));
        DualQuaternion::from_real(r.clone()) + DualQuaternion::from_real(dr)
    };
    let c = vec![
        DualQuaternion::from_real(r0.clone()),
        turn(r0, &vel[0].angular_velocity, &plus),
        turn(r1, &vel[1].angular_velocity, &minus),
        DualQuaternion::from_real(r1.clone()),
    ];
    Ok(trans.product(&QMotion::new_exact(c)?))
}

/// Algorithm 2: the C1 spline Q-motion through `poses` at `params` (at least two, strictly
/// increasing, finite), the rotational parts normalised (23) and sign-aligned (24); with
/// `velocities` the given `v⃗_i`, `ω⃗_i` (one per pose, finite), else step 1's estimate
/// ([`estimate_velocities`]). Segments of degree 6.
///
/// ```
/// use motion::{Motion, Pose, juttler::{JuttlerError, KeyVelocity, spline::algorithm2}};
/// let p = [Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])];
/// let v = vec![KeyVelocity::new([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]); 2];
/// let m = algorithm2(&p, &[0.0, 1.0], Some(&v)).unwrap();
/// assert!(m.pose(&1.0).unwrap().is_equivalent(&p[1], &1e-15).unwrap());
/// assert!(matches!(algorithm2(&p, &[0.0, f64::NAN], None), Err(JuttlerError::Parameters { .. })));
/// ```
pub fn algorithm2<T: Real>(
    poses: &[Pose<T>],
    params: &[T],
    velocities: Option<&[KeyVelocity<T>]>,
) -> Result<SplineQMotion<T>, JuttlerError> {
    check_spline_parameters(poses.len(), params)?;
    if let Some(i) = params.iter().position(|t| !Real::is_finite(t)) {
        return Err(JuttlerError::Parameters { why: format!("t_{i} = {} is not finite", params[i]) });
    }
    let unit = poses.iter().map(Pose::unitize).collect::<Result<Vec<_>, _>>()?;
    let spline = match velocities {
        Some(v) => {
            check_finite_velocities(v)?;
            SplineQMotion::hermite(&unit, params, v)
        }
        None => SplineQMotion::hermite(&unit, params, &estimate_velocities(&unit, params)?),
    }?;
    // parameters 1e-300 apart: the estimated velocities (steps over Δt) are finite, but the
    // segments' products of them overflow; refused rather than evaluated to inf/NaN
    let finite = |c: &DualQuaternion<T>| {
        [&c.real, &c.dual].into_iter().flat_map(|h| [&h.w, &h.x, &h.y, &h.z]).all(|x| Real::is_finite(x))
    };
    if let Some(i) = spline.segments().iter().position(|q| !q.control().iter().all(finite)) {
        return Err(JuttlerError::Parameters {
            why: format!(
                "segment {i} (between t_{i} and t_{}) overflows: the parameters are too close, or the velocities too large, for this precision",
                i + 1
            ),
        });
    }
    Ok(spline)
}

/// A spline Q-motion is a [`Motion`] on `[t_0, t_m]`: the pose of the segment's `Q(u)`
/// ([`QMotion`]'s `Motion`), `u` the local parameter of [`SplineQMotion::local`].
impl<T: Real> Motion<T> for SplineQMotion<T> {
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        let (i, u) = self.local(t);
        self.segments[i].evaluate(&u)
    }

    fn domain(&self) -> [T; 2] {
        [self.breaks[0].clone(), self.breaks[self.breaks.len() - 1].clone()]
    }
}

impl<T: Real, U: Real> MapScalar<T, U> for SplineQMotion<T> {
    type Mapped = SplineQMotion<U>;
    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> SplineQMotion<U> {
        self.map_ring(f)
    }
}
