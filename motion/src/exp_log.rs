//! Closed-form exp and log on G_{123inf}^+ ("dual angle" formulas).
//!
//! Write an even element as `σ + B + pω` (σ scalar, B bivector, ω = e123inf). ω is central in
//! the even subalgebra and `ω² = 0`, so `σ + pω` is a dual number and `exp(σ + pω) = e^σ(1 +
//! pω)`. Split `B = a e123 + c einf` (`a e123 = a1 e23 - a2 e13 + a3 e12`; `a`, `c` vectors of
//! R^3). Then `B² = -Θ²` with the *dual* squared angle `Θ² = u - 2wω`, `u = |a|²`,
//! `w = a·c`, and `ωB = -a einf`. Summing the exponential series by parity,
//!
//! ```text
//! exp(B) = cos Θ + (sin Θ/Θ) B,   cos Θ = C + wSω,   sin Θ/Θ = S + wTω,
//! C = cos θ,  S = sin θ/θ,  T = (S - C)/θ²,  θ = √u,
//! exp(σ + B + pω) = e^σ [ C + S a e123 + (S c - (wT + pS) a) einf + (wS + pC) ω ].
//! ```
//!
//! `C, S, T` are power series in `u` near zero rotation, so pure translations are exact and
//! dual-number derivatives stay finite there.
//!
//! The logarithm inverts this. For non-singular `S`, `log S = log|S| + log U` with
//! `|S| = √(rev(S) S)` (Lemma 2.4) and `U = S/|S|` unitary; `log|S| = ½ ln α + (β/2α) ω` for
//! `rev(S) S = α + βω` is exact. For unitary `U = u0 + a e123 + c einf + qω`, with
//! `s = |a| = sin θ`, `u0 = cos θ`, `θ = atan2(s, u0) ∈ [0, π]` (the half rotation angle):
//!
//! * `u0 ≥ 0` (rotation angle `2θ ≤ π`): `log U = f a e123 + (f c + g q a) einf` with
//!   `f = θ/sin θ`, `g = (sin θ - θ cos θ)/sin³ θ` (series in `s²` for `s² ≤ 1/4`);
//! * `u0 < 0`, `s > 0`: with `â = a/s`, `c⊥ = c - (â·c)â`, `d = -q s - (â·c) u0` (the dual part
//!   of Θ): `log U = θ â e123 + ((θ/s) c⊥ - d â) einf` — the `1/sin θ` of the first form
//!   cancels analytically here and is avoided;
//! * `U = -1 + c einf` (rotation by 2π, `s = 0`, `u0 < 0`): every axis `n` parallel to the
//!   translation works; we take `n = c/|c|`, or e3 when `c = 0`:
//!   `log U = π n e123 - c einf`.
//!
//! This is the logarithm *of the element*: `exp(log S) = S` always, the branch of the
//! runtime [`algebra_core::Multivector::log`]. The rotation angle of the transform is `2θ ∈
//! [0, 2π]`; [`Pose::log_shortest`] takes the logarithm of whichever of `±S` (the same
//! transform) has non-negative scalar part, so the rotation angle is in `[0, π]`. At a rotation
//! by exactly π (`u0 = 0`) the two are `±(π/2) n`: the sign of `S` as given decides the axis
//! direction `n` (read off the bivector part) and so the direction in which
//! [`Pose::power`] turns; with a translation along `n` the screw translation is the same
//! either way.
//!
//! ```
//! use motion::Pose;
//! let s = Pose::<f64>::from_axis_angle_translation(&[0.0, 0.0, 1.0], &1.0, &[2.0, 0.0, 0.0]).unwrap();
//! let l = s.log().unwrap();
//! assert!((l.e12 - 0.5).abs() < 1e-15); // half the rotation angle about e3
//! let back = Pose::exp(&l).unwrap();
//! assert!(back.is_equivalent(&s, &1e-15).unwrap() && (back.scalar - s.scalar).abs() < 1e-15);
//! ```

use crate::pose::is_positive;
use crate::series::{exp_fixed, exp_kernel, exp_kernel_fixed, ln_fixed, log_factors_fixed, log_kernel};
use crate::{Even, Pseudoscalar};
use crate::{MotionError, Pose};
use algebra_core::scalar::{Elementary, LaneReal};
use algebra_core::{Real, Ring};

/// `a` (with `a e123` = the rotational bivector part) and `c` (the einf part) of an even element.
pub(crate) fn split<T: Ring>(m: &Even<T>) -> ([T; 3], [T; 3]) {
    ([m.e23.clone(), m.e13.neg_ref(), m.e12.clone()], [m.e1inf.clone(), m.e2inf.clone(), m.e3inf.clone()])
}

pub(crate) fn dot<T: Ring>(x: &[T; 3], y: &[T; 3]) -> T {
    x[0].mul_ref(&y[0]) + x[1].mul_ref(&y[1]) + x[2].mul_ref(&y[2])
}

/// The even element `σ + a e123 + c einf + pω`.
pub(crate) fn assemble<T: Ring>(sigma: T, a: [T; 3], c: [T; 3], p: T) -> Even<T> {
    let [a1, a2, a3] = a;
    let [c1, c2, c3] = c;
    Even::new(sigma, a3, a2.neg_ref(), a1, c1, c2, c3, p)
}

fn not_finite<T: Ring>(op: &'static str, m: &Even<T>) -> MotionError {
    MotionError::NotFinite { op, value: m.to_string() }
}

impl<T: Real> Pose<T> {
    /// The exponential of any even element (closed form, see the module docs). Fails only for
    /// non-finite input or overflow.
    ///
    /// ```
    /// use motion::Even;
    /// use motion::Pose;
    /// // exp(½ v einf) = 1 + ½ v einf, a translation by v, exactly.
    /// let t = Pose::exp(&Even::new(0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.5, 0.0)).unwrap();
    /// assert_eq!(t, Pose::translation(&[1.0, 2.0, 3.0]));
    /// // exp((φ/2) e12) = cos(φ/2) + sin(φ/2) e12: rotation by φ about e3.
    /// let r = Pose::exp(&Even::new(0.0, 0.25, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)).unwrap();
    /// assert_eq!(r, Pose::rotation(&[0.0, 0.0, 1.0], &0.5).unwrap());
    /// ```
    pub fn exp(generator: &Even<T>) -> Result<Self, MotionError> {
        let g = generator;
        // Ordinary input at f64 precision or less: fixed polynomials, and no e^σ for σ = 0;
        // one test of the result (σ = -∞ is the one non-finite input with a finite image).
        if crate::series::at_most_f64::<T>() && Real::is_finite(&g.scalar) {
            let out = exp_with_kernel(g, exp_kernel_fixed, exp_fixed);
            if out.is_finite() {
                return Ok(out);
            }
        }
        if ![&g.scalar, &g.e12, &g.e13, &g.e23, &g.e1inf, &g.e2inf, &g.e3inf, &g.e123inf]
            .into_iter()
            .all(Real::is_finite)
        {
            return Err(not_finite("exp", g));
        }
        let out = exp_with_kernel(g, exp_kernel, exp_scalar);
        out.check_finite("exp").map_err(|_| not_finite("exp", g))?;
        Ok(out)
    }

    /// [`Pose::exp`]'s direct path alone: `None` where it would take the careful path (higher
    /// precision than `f64`, a non-finite scalar part, a non-finite result).
    pub(crate) fn exp_direct(generator: &Even<T>) -> Option<Self> {
        if !crate::series::at_most_f64::<T>() || !Real::is_finite(&generator.scalar) {
            return None;
        }
        let out = exp_with_kernel(generator, exp_kernel_fixed, exp_fixed);
        out.is_finite().then_some(out)
    }

    /// The logarithm of the element (module docs): `exp(log S) = S`, rotational half-angle
    /// in `[0, π]`; the scalar and ω parts are `log|S|`, zero for unitary `S`. Fails for
    /// singular or non-finite `S`.
    ///
    /// ```
    /// use motion::Pose;
    /// // Pure translation: log(1 + ½ v einf) = ½ v einf, exactly.
    /// let l = Pose::translation(&[2.0, 4.0, 6.0]).log().unwrap();
    /// assert_eq!((l.e1inf, l.e2inf, l.e3inf, l.scalar, l.e12), (1.0, 2.0, 3.0, 0.0, 0.0));
    /// // Non-unit: log(2S) = ln 2 + log S.
    /// let l2 = Pose::translation(&[2.0, 4.0, 6.0]).scale(&2.0).log().unwrap();
    /// assert!((l2.scalar - 2f64.ln()).abs() < 1e-15 && (l2.e1inf - 1.0).abs() < 1e-15);
    /// assert!(Pose::<f64>::identity().scale(&0.0).log().is_err());
    /// ```
    pub fn log(&self) -> Result<Even<T>, MotionError> {
        match self.log_direct() {
            Some(l) => Ok(l),
            None => self.log_careful(),
        }
    }

    /// [`Pose::log`] for the inputs its direct path declines: out of line, so that the common
    /// case's code is the direct path's alone.
    #[inline(never)]
    fn log_careful(&self) -> Result<Even<T>, MotionError> {
        self.check_finite("log")?;
        // log(m S') = ln m + log S' for m > 0: the squares of S' = S/m stay in range.
        let (scale, s) = crate::scaled::rotational_scale(self).ok_or_else(|| self.singular("log"))?;
        let n2 = s.pseudo_norm_squared();
        let alpha = &n2.scalar;
        if !is_positive(alpha) {
            return Err(self.singular("log"));
        }
        // 1/|S| = (1/√α)(1 - mω) with m = β/(2α); log|S| = ½ ln α + mω.
        let m = n2.e123inf.div_ref(&alpha.add_ref(alpha));
        let inv_root = T::one().div_ref(&Real::sqrt(alpha));
        let inv_norm = Pseudoscalar::new(inv_root.clone(), m.mul_ref(&inv_root).neg_ref());
        let unit = &inv_norm * &s;
        let mut l = unit_log(&unit);
        l.scalar = Real::ln(alpha).mul_ref(&T::from_ratio(1, 2)).add_ref(&Real::ln(&scale));
        l.e123inf = m;
        if ![&l.scalar, &l.e12, &l.e13, &l.e23, &l.e1inf, &l.e2inf, &l.e3inf, &l.e123inf]
            .into_iter()
            .all(Real::is_finite)
        {
            return Err(not_finite("log", self));
        }
        Ok(l)
    }

    /// [`Pose::log`] for ordinary input at `f64` precision or less: `rev(S) S = α + βω` with `α`
    /// tame (no rescaling needed), the fixed-length factors of `log_factors_fixed`, and one
    /// test of the result; `None` sends everything else (non-finite, singular, far from unit
    /// scale, higher precision) to the careful path. A non-finite coefficient makes `α` or
    /// the result non-finite.
    pub(crate) fn log_direct(&self) -> Option<Even<T>> {
        if !crate::series::at_most_f64::<T>() {
            return None;
        }
        let alpha = &self.alpha();
        if !crate::scaled::tame(alpha) || !is_positive(alpha) {
            return None;
        }
        // the half-angle from S itself (scale-invariant)
        let (a, c) = split(self);
        let s_raw2 = dot(&a, &a);
        let s_raw = Real::sqrt(&s_raw2);
        let th = s_raw.fast_atan2(&self.scalar);
        if self.scalar >= T::zero() && s_raw2.to_f64() > crate::series::SMALL_X * alpha.to_f64() {
            return self.log_direct_acute(alpha, &a, &c, &s_raw2, &s_raw, &th);
        }
        // one division: 1/√α, and β/(2α) = (β/2) (1/√α)² (the same bits as ½ β (1/√α)²:
        // scaling by 2 and ½ is exact)
        let inv_root = T::one().div_ref(&Real::sqrt(alpha));
        let s = s_raw.mul_ref(&inv_root);
        let m = self.half_beta().mul_ref(&inv_root).mul_ref(&inv_root);
        let mut l = if self.scalar >= T::zero() {
            // `unit_log_with` of U = (r - m r ω) S (r = 1/√α) without forming U: U's parts are
            // a_U = r a, c_U = r (c + m a), U∅ = r S∅, U_ω = r (Sω - m S∅) (ω S has einf part
            // -a), so its log f a_U, f c_U + g U_ω a_U is F a, F c + H a with F = f r and
            // H = F m + g r² (Sω - m S∅): seven products instead of the normalisation's twelve
            let r2 = inv_root.mul_ref(&inv_root);
            let (u0, x) = (self.scalar.mul_ref(&inv_root), s_raw2.mul_ref(&r2));
            let (f, g) = log_factors_fixed(&u0, &x, &s, &th);
            let big_f = f.mul_ref(&inv_root);
            let u_omega = self.e123inf.sub_ref(&m.mul_ref(&self.scalar));
            let h = big_f.mul_ref(&m).add_ref(&g.mul_ref(&r2).mul_ref(&u_omega));
            let c_out = std::array::from_fn(|i| c[i].mul_ref(&big_f).add_ref(&a[i].mul_ref(&h)));
            assemble(T::zero(), a.map(|x| x.mul_ref(&big_f)), c_out, T::zero())
        } else {
            self.log_direct_obtuse(&inv_root, &m, &s, &th)
        };
        l.scalar = ln_fixed(alpha).mul_ref(&T::from_ratio(1, 2));
        l.e123inf = m;
        l.is_finite().then_some(l)
    }

    /// [`Pose::log_direct`] for `S∅ ≥ 0` and `|a|² > 2^-20 α` (`a e123` the rotational
    /// bivector part, `s_raw = |a|`, `th` the half-angle): `1/√α` and `1/|a|` from one division
    /// `d = 1/(|a| √α)` (`1/√α = |a| d`, `1/|a| = √α d`), and the factors of `unit_log_with`
    /// of `U = (r - m r ω) S` (`r = 1/√α`, `m = β/(2α)`) without forming `U`: its log
    /// `f a_U e123 + (f c_U + g U_ω a_U) einf` is `F a e123 + (F c + H a) einf` with `F = θ/|a|`,
    /// `H = F m + G (Sω - m S∅)` and `G = g/α = (|a| - θ S∅)/|a|³` (the numerator by its series
    /// in `θ` up to `θ = π/6`, `4|a|² ≤ α`: no cancellation), each an exact regrouping of the
    /// unit element's factors.
    #[inline]
    fn log_direct_acute(&self, alpha: &T, a: &[T; 3], c: &[T; 3], s_raw2: &T, s_raw: &T, th: &T) -> Option<Even<T>> {
        let root = Real::sqrt(alpha);
        let d = T::one().div_ref(&s_raw.mul_ref(&root));
        let (inv_root, q) = (s_raw.mul_ref(&d), root.mul_ref(&d));
        let m = self.half_beta().mul_ref(&inv_root).mul_ref(&inv_root);
        let series = s_raw2.mul_ref(&T::from_f64(4.0)) <= *alpha;
        let num = crate::series::sin_minus_theta_cos_raw(th, s_raw, &self.scalar, &root, series);
        let big_f = th.mul_ref(&q);
        let g = num.mul_ref(&q.mul_ref(&q).mul_ref(&q));
        let u_omega = self.e123inf.sub_ref(&m.mul_ref(&self.scalar));
        let h = big_f.mul_ref(&m).add_ref(&g.mul_ref(&u_omega));
        let c_out = std::array::from_fn(|i| c[i].mul_ref(&big_f).add_ref(&a[i].mul_ref(&h)));
        let mut l = assemble(T::zero(), a.clone().map(|x| x.mul_ref(&big_f)), c_out, T::zero());
        l.scalar = ln_fixed(alpha).mul_ref(&T::from_ratio(1, 2));
        l.e123inf = m;
        (self.modest_f64() || l.all_finite_value()).then_some(l)
    }

    /// [`Pose::log_direct`]'s bivector part for `S∅ < 0` (a rotation by more than π), given
    /// `1/√α`, `m = β/(2α)`, `sin θ` and `θ`: the normalised element's [`unit_log_with`].
    /// Out of line, so that the common case's registers are its own.
    #[inline(never)]
    fn log_direct_obtuse(&self, inv_root: &T, m: &T, s: &T, th: &T) -> Even<T> {
        let unit = &Pseudoscalar::new(inv_root.clone(), m.mul_ref(inv_root).neg_ref()) * self;
        unit_log_with(&unit, |u0, x| log_factors_fixed(u0, x, s, th))
    }

    /// The logarithm of whichever of `±S` has non-negative scalar part (the same transform,
    /// Theorem 2.8): the transform's rotation angle is in `[0, π]`, and `exp(log_shortest S) =
    /// ±S`. At exactly π the sign of `S` as given is kept (module docs).
    ///
    /// ```
    /// use motion::Pose;
    /// let s = Pose::rotation(&[0.0, 0.0, 1.0], &(1.5 * std::f64::consts::PI)).unwrap();
    /// assert!((s.log().unwrap().e12 - 0.75 * std::f64::consts::PI).abs() < 1e-15);
    /// assert!((s.log_shortest().unwrap().e12 + 0.25 * std::f64::consts::PI).abs() < 1e-15);
    /// ```
    pub fn log_shortest(&self) -> Result<Even<T>, MotionError> {
        if self.scalar < T::zero() { (-self).log() } else { self.log() }
    }
}

/// `exp(σ + a e123 + c einf + pω)` (module docs) from the kernel `[C, S, T]` at `u = |a|²`:
/// shared by [`Pose::exp`] and the branch-free [`Pose::exp_branch_free`].
/// `e^σ` is `exp_sigma(σ)`: [`exp_scalar`], or the direct path's `series::exp_fixed`.
pub(crate) fn exp_with_kernel<T: LaneReal>(
    g: &Even<T>,
    kernel: impl FnOnce(&T) -> [T; 3],
    exp_sigma: impl FnOnce(&T) -> T,
) -> Even<T> {
    let (a, c) = split(g);
    let (u, w) = (dot(&a, &a), dot(&a, &c));
    let [cc, ss, tt] = kernel(&u);
    let p = &g.e123inf;
    let es = exp_sigma(&g.scalar);
    let ess = es.mul_ref(&ss);
    // einf part: e^σ (S c - (wT + pS) a)
    let k = w.mul_ref(&tt).add_ref(&p.mul_ref(&ss)).mul_ref(&es);
    let c_out: [T; 3] = std::array::from_fn(|i| c[i].mul_ref(&ess).sub_ref(&a[i].mul_ref(&k)));
    let a_out = a.map(|x| x.mul_ref(&ess));
    let omega = w.mul_ref(&ess).add_ref(&p.mul_ref(&cc).mul_ref(&es));
    assemble(es.mul_ref(&cc), a_out, c_out, omega)
}

/// `e^σ`, and exactly 1 for `σ = 0` (every lane and part zero).
pub(crate) fn exp_scalar<T: LaneReal>(sigma: &T) -> T {
    if sigma.is_exact_zero() { T::one() } else { Elementary::exp(sigma) }
}

/// The logarithm (a bivector) of a unitary even element (module docs for the three cases).
fn unit_log<T: Real>(u: &Even<T>) -> Even<T> {
    unit_log_with(u, |u0, x| {
        if *x <= T::from_ratio(1, 4) {
            let [f, h] = log_kernel(x);
            (f, h.mul_ref(u0))
        } else {
            let s = Real::sqrt(x);
            let th = Real::atan2(&s, u0);
            let g = s.sub_ref(&th.mul_ref(u0)).div_ref(&s.mul_ref(x));
            (th.div_ref(&s), g)
        }
    })
}

/// [`unit_log`] with the factors `(f, g)` of the first case (`u0 ≥ 0`) from `factors(u0, x)`,
/// `x = |a|²`: the careful series or the fixed-length ones.
fn unit_log_with<T: Real>(u: &Even<T>, factors: impl FnOnce(&T, &T) -> (T, T)) -> Even<T> {
    let (a, c) = split(u);
    let (u0, q) = (&u.scalar, &u.e123inf);
    let x = dot(&a, &a);
    let zero = T::zero();
    if *u0 >= zero {
        let (f, g) = factors(u0, &x);
        let gq = g.mul_ref(q);
        let c_out = std::array::from_fn(|i| c[i].mul_ref(&f).add_ref(&a[i].mul_ref(&gq)));
        return assemble(zero, a.map(|x| x.mul_ref(&f)), c_out, T::zero());
    }
    if x > zero {
        let s = Real::sqrt(&x);
        let th = Real::atan2(&s, u0);
        let inv_s = T::one().div_ref(&s);
        let n = a.map(|x| x.mul_ref(&inv_s));
        let nc = dot(&n, &c);
        let d = q.mul_ref(&s).add_ref(&nc.mul_ref(u0)).neg_ref();
        let th_over_s = th.mul_ref(&inv_s);
        let c_out =
            std::array::from_fn(|i| c[i].sub_ref(&nc.mul_ref(&n[i])).mul_ref(&th_over_s).sub_ref(&d.mul_ref(&n[i])));
        return assemble(zero, n.map(|x| x.mul_ref(&th)), c_out, T::zero());
    }
    // U = -1 + c einf: rotation by 2π about an axis along the translation.
    let n = crate::scaled::direction(&c).unwrap_or_else(|| [T::zero(), T::zero(), T::one()]);
    let pi = T::pi();
    assemble(zero, n.map(|x| x.mul_ref(&pi)), c.map(|x| x.neg_ref()), T::zero())
}
