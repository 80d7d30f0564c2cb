//! Branch-free closed-form exp, log, power and slerp of poses, over any
//! [`LaneReal`]: SIMD lane scalars (`algebra_core::scalar::F64x4`, `F32x8`, ..., feature `lanes`
//! of algebra-core), [`LaneDual`](algebra_core::scalar::LaneDual) over lanes, and every `Real`.
//!
//! The formulas are those of [`crate::exp_log`] (the main paper's dual-angle closed forms,
//! Appendix 2) with the same results lane by lane; where the `Real` versions branch on a value,
//! these compute every case with safe inputs and
//! [`Select::select`](algebra_core::scalar::Select::select) per lane:
//!
//! * exp: the power series of `C, S, T` for `θ² ≤ 1` (zero angle, pure translation: exact) or
//!   the closed forms in `θ`;
//! * log of the unitary part `U = u0 + a e123 + c einf + qω`: the series in `s² ≤ 1/4`, the
//!   closed form for `u0 ≥ 0` (rotation angle up to π, the angle π itself included), the
//!   cancelled form for `u0 < 0`, and the full turn `U = -1 + c einf` (axis along `c`, or e3);
//! * [`Pose::log_shortest_branch_free`]: `±S` chosen per lane by the sign of the scalar part.
//!
//! The series have a fixed number of terms, chosen from the type's epsilon (not from the
//! values), so every lane runs the same instructions. Errors are decided over the whole vector:
//! a non-finite value or a singular pose in **any** lane fails the call with the
//! [`MotionError`] the `Real` version gives for that lane.
//!
//! ```
//! use motion::{Even, Pose};
//! // over f64 the branch-free forms give the `Real` results
//! let g = Even::<f64>::new(0.0, 0.3, -0.2, 0.1, 1.0, 2.0, 3.0, 0.0);
//! let (e, f) = (Pose::exp_branch_free(&g).unwrap(), Pose::exp(&g).unwrap());
//! assert!((e - f).components().iter().all(|x| x.abs() < 1e-15f64));
//! let l = e.log_branch_free().unwrap();
//! assert!((l - g).components().iter().all(|x| x.abs() < 1e-14f64));
//! ```

use crate::exp_log::{assemble, dot, exp_scalar, exp_with_kernel, split};
use crate::scaled::require_finite;
use crate::series::{exp_series, log_series};
use crate::{Even, MotionError, Pose, Pseudoscalar};
use algebra_core::Ring;
use algebra_core::scalar::{LaneReal, Mask};

/// How many terms a series needs when its `k`-th term is at most `bound(k)` (relative to
/// order one): the first `k` with `bound(k)` below ε/64 for the type (at most 2000). Depends on
/// the type only, so every lane runs the same instructions.
fn terms<T: Ring>(bound: impl Fn(i64) -> f64) -> i64 {
    let target = T::relative_epsilon() / 64.0;
    (1..2000).find(|&k| bound(k) < target).unwrap_or(2000)
}

fn select3<T: LaneReal>(m: &T::Mask, x: &[T; 3], y: &[T; 3]) -> [T; 3] {
    std::array::from_fn(|i| T::select(m, &x[i], &y[i]))
}

/// `x` where `m` is set, `y` elsewhere, component by component.
fn select_pose<T: LaneReal>(m: &T::Mask, x: &Pose<T>, y: &Pose<T>) -> Pose<T> {
    let (x, y) = (x.components(), y.components());
    let c: [T; 8] = std::array::from_fn(|i| T::select(m, x[i], y[i]));
    let [s, b12, b13, b23, b1, b2, b3, w] = c;
    Pose::new(s, b12, b13, b23, b1, b2, b3, w)
}

/// `[cos θ, sin θ/θ, (sin θ/θ - cos θ)/θ²]` for `u = θ² ≥ 0`: series for `u ≤ 1`, closed
/// forms above, per lane.
fn exp_kernel<T: LaneReal>(u: &T) -> [T; 3] {
    let one = T::one();
    let small = u.le_mask(&one);
    let us = T::select(&small, u, &T::zero());
    // the k-th terms are at most 1/(2k)! for u ≤ 1
    let n = terms::<T>(|k| (1..=2 * k).map(|j| j as f64).product::<f64>().recip());
    let [c, s, t] = exp_series(&us, |k, _| k >= n);
    let ub = T::select(&small, &T::from_i64(2), u);
    let th = ub.sqrt();
    let cc = th.cos();
    let sc = th.sin().div_ref(&th);
    let tc = sc.sub_ref(&cc).div_ref(&ub);
    [T::select(&small, &c, &cc), T::select(&small, &s, &sc), T::select(&small, &t, &tc)]
}

/// `c / |c|` per lane, e3 where `c = 0` (scaled by the largest component first, as
/// `scaled::direction`).
fn direction_or_e3<T: LaneReal>(c: &[T; 3]) -> [T; 3] {
    let abs = c.clone().map(|x| x.abs());
    let m01 = T::select(&abs[0].gt_mask(&abs[1]), &abs[0], &abs[1]);
    let m = T::select(&m01.gt_mask(&abs[2]), &m01, &abs[2]);
    let zero = T::zero();
    let has = m.gt_mask(&zero);
    let inv = T::one().div_ref(&T::select(&has, &m, &T::one()));
    let y = c.clone().map(|x| x.mul_ref(&inv));
    let len = dot(&y, &y).sqrt();
    let len = T::select(&has, &len, &T::one());
    let n = y.map(|x| x.div_ref(&len));
    select3(&has, &n, &[zero.clone(), zero, T::one()])
}

/// The logarithm of a unitary even element, the three cases of [`crate::exp_log`] per lane.
fn unit_log<T: LaneReal>(u: &Even<T>) -> Even<T> {
    let (a, c) = split(u);
    let (u0, q) = (&u.scalar, &u.e123inf);
    let x = dot(&a, &a);
    let zero = T::zero();
    // rotation up to π (u0 ≥ 0): series for x ≤ 1/4, closed form above
    let series = x.le_mask(&T::from_ratio(1, 4));
    // c_k ≤ 1, so for x ≤ 1/4 the k-th terms are at most 2k 4^(1-k)
    let n = terms::<T>(|k| (2 * k) as f64 * 0.25f64.powi(k as i32 - 1));
    let [fs, hs] = log_series(&T::select(&series, &x, &zero), |k, _, _| k >= n);
    let positive = x.gt_mask(&zero);
    let xb = T::select(&positive, &x, &T::one());
    let s = xb.sqrt();
    let th = s.atan2(u0);
    let inv_s = T::one().div_ref(&s);
    let fc = th.mul_ref(&inv_s);
    let gc = s.sub_ref(&th.mul_ref(u0)).div_ref(&s.mul_ref(&xb));
    let f = T::select(&series, &fs, &fc);
    let gq = T::select(&series, &hs.mul_ref(u0), &gc).mul_ref(q);
    let a_near = a.clone().map(|x| x.mul_ref(&f));
    let c_near: [T; 3] = std::array::from_fn(|i| c[i].mul_ref(&f).add_ref(&a[i].mul_ref(&gq)));
    // u0 < 0, s > 0: the 1/sin θ cancelled
    let n = a.clone().map(|x| x.mul_ref(&inv_s));
    let nc = dot(&n, &c);
    let d = q.mul_ref(&s).add_ref(&nc.mul_ref(u0)).neg_ref();
    let a_far = n.clone().map(|x| x.mul_ref(&th));
    let c_far: [T; 3] =
        std::array::from_fn(|i| c[i].sub_ref(&nc.mul_ref(&n[i])).mul_ref(&fc).sub_ref(&d.mul_ref(&n[i])));
    // U = -1 + c einf: a full turn about an axis along the translation
    let pi = T::pi();
    let a_turn = direction_or_e3(&c).map(|x| x.mul_ref(&pi));
    let c_turn = c.clone().map(|x| x.neg_ref());
    let near = u0.ge_mask(&zero);
    let a_out = select3(&near, &a_near, &select3(&positive, &a_far, &a_turn));
    let c_out = select3(&near, &c_near, &select3(&positive, &c_far, &c_turn));
    assemble(zero.clone(), a_out, c_out, zero)
}

impl<T: LaneReal> Pose<T> {
    /// [`Pose::exp`] without branches on the values (module docs): the same result lane by
    /// lane. Fails when any lane is non-finite or overflows.
    ///
    /// ```
    /// use motion::{Even, Pose};
    /// let t = Pose::exp_branch_free(&Even::new(0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.5, 0.0)).unwrap();
    /// assert_eq!(t, Pose::translation(&[1.0, 2.0, 3.0]));
    /// ```
    pub fn exp_branch_free(generator: &Even<T>) -> Result<Self, MotionError> {
        let g = generator;
        require_finite("exp", g, [])?;
        let out = exp_with_kernel(g, exp_kernel, exp_scalar);
        require_finite("exp", &out, []).map_err(|_| MotionError::NotFinite { op: "exp", value: g.to_string() })?;
        Ok(out)
    }

    /// [`Pose::log`] without branches on the values: the logarithm of the element
    /// (`exp(log S) = S`), the same result lane by lane. Fails when any lane is non-finite or
    /// singular.
    ///
    /// ```
    /// use motion::Pose;
    /// let s = Pose::<f64>::rotation(&[0.0, 0.0, 1.0], &std::f64::consts::PI).unwrap();
    /// assert!((s.log_branch_free().unwrap().e12 - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    /// assert!(Pose::<f64>::identity().scale(&0.0).log_branch_free().is_err());
    /// ```
    pub fn log_branch_free(&self) -> Result<Even<T>, MotionError> {
        require_finite("log", self, [])?;
        // S = m S' with m the largest |component| of the rotational part (scaled::rotational_scale)
        let c = self.components();
        let abs: [T; 4] = std::array::from_fn(|i| c[i].abs());
        let m01 = T::select(&abs[0].gt_mask(&abs[1]), &abs[0], &abs[1]);
        let m23 = T::select(&abs[2].gt_mask(&abs[3]), &abs[2], &abs[3]);
        let scale = T::select(&m01.gt_mask(&m23), &m01, &m23);
        let zero = T::zero();
        if !scale.gt_mask(&zero).all() {
            return Err(self.singular("log"));
        }
        let s = self.scale(&T::one().div_ref(&scale));
        let n2 = s.pseudo_norm_squared();
        let alpha = &n2.scalar;
        if !alpha.gt_mask(&zero).all() {
            return Err(self.singular("log"));
        }
        let m = n2.e123inf.div_ref(&alpha.add_ref(alpha));
        let inv_root = T::one().div_ref(&alpha.sqrt());
        let inv_norm = Pseudoscalar::new(inv_root.clone(), m.mul_ref(&inv_root).neg_ref());
        let mut l = unit_log(&(&inv_norm * &s));
        l.scalar = alpha.ln().mul_ref(&T::from_ratio(1, 2)).add_ref(&scale.ln());
        l.e123inf = m;
        require_finite("log", &l, []).map_err(|_| MotionError::NotFinite { op: "log", value: self.to_string() })?;
        Ok(l)
    }

    /// [`Pose::log_shortest`] without branches: the logarithm of whichever of `±S` has
    /// non-negative scalar part, chosen per lane.
    ///
    /// ```
    /// use motion::Pose;
    /// let s = Pose::rotation(&[0.0, 0.0, 1.0], &(1.5 * std::f64::consts::PI)).unwrap();
    /// assert!((s.log_shortest_branch_free().unwrap().e12 + 0.25 * std::f64::consts::PI).abs() < 1e-15);
    /// ```
    pub fn log_shortest_branch_free(&self) -> Result<Even<T>, MotionError> {
        let negative = self.scalar.lt_mask(&T::zero());
        select_pose(&negative, &-self, self).log_branch_free()
    }

    /// [`Pose::power`] without branches: `S^t = exp(t log S)` per lane.
    ///
    /// ```
    /// use motion::Pose;
    /// let r = Pose::rotation(&[0.0, 0.0, 1.0], &1.2).unwrap();
    /// let half = r.power_branch_free(&0.5).unwrap();
    /// assert!(half.is_equivalent(&Pose::rotation(&[0.0, 0.0, 1.0], &0.6).unwrap(), &1e-15).unwrap());
    /// ```
    pub fn power_branch_free(&self, t: &T) -> Result<Self, MotionError> {
        require_finite("power", self, [t])?;
        Pose::exp_branch_free(&self.log_branch_free()?.scale(t))
    }

    /// [`Pose::slerp`] `A (rev(A) B)^t` (eq. 15) without branches, per lane.
    ///
    /// ```
    /// use motion::Pose;
    /// let a = Pose::<f64>::identity();
    /// let b = Pose::translation(&[2.0, 0.0, 0.0]);
    /// let half = Pose::slerp_branch_free(&a, &b, &0.5).unwrap();
    /// assert_eq!(half, Pose::slerp(&a, &b, &0.5).unwrap());
    /// ```
    pub fn slerp_branch_free(a: &Self, b: &Self, t: &T) -> Result<Self, MotionError> {
        require_finite("slerp", a, [t])?;
        require_finite("slerp", b, [])?;
        let rel = &a.reverse() * b;
        Ok(a * &rel.power_branch_free(t)?)
    }
}
