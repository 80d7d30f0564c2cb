//! Powers and the two pairwise interpolations of Sec. 4 of the main paper: the multiplicative
//! slerp `Φ(A, B; t) = A (rev(A) B)^t` (eq. 15; the OCR of the paper lost the bar) and the
//! additive `Φ(A, B; t) = (1 - t) A + t B` (eq. 17). The de Casteljau tableaux of Bezier
//! motions are built from these.
//!
//! ```
//! use motion::Pose;
//! let a = Pose::<f64>::identity();
//! let b = Pose::translation(&[2.0, 0.0, 0.0]);
//! let half = Pose::slerp(&a, &b, &0.5).unwrap();
//! assert!((half.transform_point(&[0.0, 0.0, 0.0]).unwrap()[0] - 1.0).abs() < 1e-15);
//! assert_eq!(Pose::lerp(&a, &b, &0.5), Pose::translation(&[1.0, 0.0, 0.0]));
//! ```

use crate::exp_log::{assemble, dot, split};
use crate::pose::is_positive;
use crate::series::{angle_factors_fixed, exp_fixed, exp_kernel_fixed, ln_fixed};
use crate::{MotionError, Pose};
use algebra_core::{Real, Ring};

impl<T: Real> Pose<T> {
    /// `S^t = exp(t log S)` with the logarithm of the element ([`Pose::log`]), so
    /// `S^0 = 1`, `S^1 = S`, `S^s S^t = S^{s+t}`, and for non-unit `S = |S| U`,
    /// `S^t = |S|^t U^t`. Fails for singular `S`.
    ///
    /// ```
    /// use motion::Pose;
    /// let r = Pose::rotation(&[0.0, 0.0, 1.0], &1.2).unwrap();
    /// let half = r.power(&0.5).unwrap();
    /// assert!(half.is_equivalent(&Pose::rotation(&[0.0, 0.0, 1.0], &0.6).unwrap(), &1e-15).unwrap());
    /// ```
    pub fn power(&self, t: &T) -> Result<Self, MotionError> {
        if let Some(p) = self.power_direct(t) {
            return Ok(p);
        }
        crate::scaled::require_finite("power", self, [t])?;
        let l = self.log()?;
        Pose::exp(&l.scale(t))
    }

    /// The slerp `A (rev(A) B)^t` of eq. (15). `S(0) = A`; `S(1) = A rev(A) B = |A|² B`, which
    /// is `B` only when `A` is unitary (otherwise an equivalent pose, the same transform; eq. 16
    /// gives `Φ(αA, βB; t) = α^{1+t} β^t Φ(A, B; t)` for pseudoscalars). The power uses the
    /// element's logarithm, so when `rev(A) B` has negative scalar part the motion turns the
    /// long way (rotation angle above π); pass `-B` (the same pose) for the short way.
    /// Fails when `rev(A) B` is singular (A or B singular).
    ///
    /// ```
    /// use motion::Pose;
    /// let a = Pose::<f64>::rotation(&[1.0, 0.0, 0.0], &0.3).unwrap();
    /// let b = Pose::from_axis_angle_translation(&[0.0, 1.0, 0.0], &2.0, &[1.0, 2.0, 3.0]).unwrap();
    /// let end = Pose::slerp(&a, &b, &1.0).unwrap();
    /// assert!((&end - &b).components().iter().all(|x| x.abs() < 1e-14f64));
    /// ```
    pub fn slerp(a: &Self, b: &Self, t: &T) -> Result<Self, MotionError> {
        if crate::series::at_most_f64::<T>() {
            // the direct path: a non-finite `a`, `b` or `t` cannot give a finite result (every
            // coefficient enters a product), so one test of the result replaces the checks
            let rel = &a.reverse() * b;
            // `rev(a) b` unit (nalgebra's only case): the power's dual-scalar weights applied to
            // `a` and `b` (no last motor product, `slerp_unit_weights`); the rest by the power
            // and the product
            let out = if rel.scalar >= T::zero() && rel.unit_to_rounding(&rel.pseudo_norm_squared()) {
                Some(Pose::slerp_unit_weights(a, b, &rel, t))
            } else {
                rel.power_direct_untested(t).map(|p| a * &p)
            };
            if let Some(out) = out.filter(Pose::is_finite) {
                return Ok(out);
            }
        }
        crate::scaled::require_finite("slerp", a, [t])?;
        crate::scaled::require_finite("slerp", b, [])?;
        let rel = &a.reverse() * b;
        Ok(a * &rel.power(t)?)
    }
}

/// `rev(S) S = α + βω` within this many rounding errors of `1` (`α` against 1, `β` against
/// `1 + |S1∞| + |S2∞| + |S3∞| + |Sω|`, the scale of its products) makes the fused power take
/// the unit form ([`Pose::power_fused_unit`]).
const UNIT_ULPS: u32 = 8;

impl<T: Real> Pose<T> {
    /// [`Pose::power`] for ordinary input at `f64` precision or less; `None` sends the input to
    /// the careful path, which names a failure. With `S∅ ≥ 0` (the slerp's short way) `exp(t
    /// log S)` is fused into one closed form in the coefficients of `S` (see
    /// [`Pose::power_fused`]); otherwise the direct paths of `log` and `exp` in turn.
    fn power_direct(&self, t: &T) -> Option<Self> {
        let p = self.power_direct_untested(t)?;
        // the fused form is not tested where it is computed; `exp_direct` tests its own result
        if self.scalar >= T::zero() { Some(p).filter(Pose::is_finite) } else { Some(p) }
    }

    /// [`Pose::power_direct`] without the test of the result, for a caller that multiplies it
    /// into a result it tests (a non-finite coefficient of a factor makes the product
    /// non-finite: every coefficient enters a product).
    fn power_direct_untested(&self, t: &T) -> Option<Self> {
        if !crate::series::at_most_f64::<T>() {
            return None;
        }
        if self.scalar >= T::zero() {
            return self.power_fused(t);
        }
        let l = self.log_direct()?;
        Pose::exp_direct(&l.scale(t))
    }

    /// `S^t = exp(t log S)` for `S∅ ≥ 0`, with `α` tame and positive, as one closed form (the
    /// module docs of [`crate::exp_log`] for the notation): with `rev(S) S = α + βω`,
    /// `m = β/2α`, `1/√α = ρ`, the unit `U = ρ(1 - mω)S` has `u0 = ρS∅`, `s = sin θ = ρ|a|`,
    /// `c_U = ρ(c + m a)`, `q_U = ρ(q - m S∅)`, and `log S = ½ ln α + f ρ a e123 + ρ(f c +
    /// (f m + g q_U) a) einf + mω`. Its multiple by `t` has `u' = (tθ)² = (t f)² s²` and, since
    /// `a_U·c_U = u0 q_U` and `f u0 + g s² = 1`, `w' = t² f q_U`; the exp formula then gives
    /// `S^t = e^{tσ}[C' + λ (a e123 + c einf) + λ₂ a einf + (w'S' + t m C')ω]` with
    /// `λ = t ρ f S'` and `λ₂ = t ρ (S'(f m + g q_U) - f(w'T' + t m S'))`.
    ///
    /// The same operations as `log` then `exp`, without the normalised pose, its logarithm and
    /// their dot products in between: the exp kernel's polynomials start as soon as `θ²` and
    /// `f` are known, and `θ²` comes from `sin² θ = |a|²/α` and `cos² θ = S∅²/α` by one
    /// division and a polynomial (`series::angle_factors_fixed`), with no square root or
    /// arctangent on that chain. `None` for an unusual `α`; the result is not tested here.
    fn power_fused(&self, t: &T) -> Option<Self> {
        let n2 = self.pseudo_norm_squared();
        let alpha = &n2.scalar;
        if !crate::scaled::tame(alpha) || !is_positive(alpha) {
            return None;
        }
        if self.unit_to_rounding(&n2) {
            return Some(self.power_fused_unit(t));
        }
        Some(self.power_fused_general(t, alpha, &n2.e123inf))
    }

    /// `rev(S) S = α + βω` is `1` up to rounding ([`UNIT_ULPS`]; every part, for dual numbers,
    /// so a derivative of the norm is kept): the factors of `α` and `β` would change the power
    /// by no more than that rounding, and the unit form may leave them out.
    #[inline]
    fn unit_to_rounding(&self, n2: &crate::Pseudoscalar<T>) -> bool {
        let one = T::one();
        let beta_scale = [&self.e1inf, &self.e2inf, &self.e3inf, &self.e123inf]
            .into_iter()
            .fold(one.clone(), |acc, x| acc.add_ref(&Real::abs(x)));
        n2.scalar.sub_ref(&one).is_negligible(&one, UNIT_ULPS) && n2.e123inf.is_negligible(&beta_scale, UNIT_ULPS)
    }

    /// The direct path of [`crate::UnitPose::slerp`] (`a`, `b` unit): `rev(a) b` unit to
    /// rounding with non-negative scalar part, at `f64` precision or less, by the weights'
    /// form ([`Pose::slerp_unit_weights`]) and one test of the result (a non-finite `t` enters
    /// every coefficient's product); `None` sends the rest to [`Pose::slerp`].
    pub(crate) fn slerp_unit_direct(a: &Self, b: &Self, t: &T) -> Option<Self> {
        if !crate::series::at_most_f64::<T>() {
            return None;
        }
        let rel = &a.reverse() * b;
        // unit keys whose `rev(a) b` is unit to rounding (what the weights' form assumes, past
        // `t = ½`); the rest go to `Pose::slerp`, which takes the power and the product
        if rel.scalar < T::zero() || !rel.unit_to_rounding(&rel.pseudo_norm_squared()) {
            return None;
        }
        Some(Pose::slerp_unit_weights(a, b, &rel, t)).filter(Pose::is_finite)
    }

    /// [`Pose::power_fused`] for a unit `S` (`α = 1`, `β = 0`; `S∅ ≥ 0`): `ρ = 1`, `m = 0`
    /// and `e^{tσ} = 1`, so no square root, division, `ln` or `exp` of `α` ([`Pose::power`]
    /// of a unit pose). The result is not tested here.
    #[inline(never)]
    pub(crate) fn power_fused_unit(&self, t: &T) -> Self {
        power_from_weights(self, unit_weights(self, t))
    }

    /// The closed form of [`Pose::power_fused`] for a non-unit `S` with `rev(S) S = α + βω`,
    /// out of line: with the unit form beside it in one function, the registers spill (slerp
    /// 1.13x nalgebra against 1.07x).
    #[inline(never)]
    fn power_fused_general(&self, t: &T, alpha: &T, beta: &T) -> Self {
        let s = self;
        let (a, _) = split(s);
        let xr = dot(&a, &a);
        // x = sin² θ and y = cos² θ of the unit S/√α by one division (no square root on the
        // way to θ², which starts the exp kernel); ρ = 1/√α beside the angle's polynomial
        let inv_alpha = T::one().div_ref(alpha);
        let rho = Real::sqrt(&inv_alpha);
        let half = T::from_ratio(1, 2);
        let x = xr.mul_ref(&inv_alpha);
        let y = s.scalar.mul_ref(&s.scalar).mul_ref(&inv_alpha);
        let u0 = s.scalar.mul_ref(&rho);
        let sin = Real::sqrt(&xr).mul_ref(&rho);
        let (th2, f, g) = angle_factors_fixed(&x, &y, &u0, &sin);
        let tf = t.mul_ref(&f);
        // u' = (tθ)² = t² θ²: θ² comes without a square root, whose derivative at a pure
        // translation would make a dual number's result non-finite
        let u1 = t.mul_ref(t).mul_ref(&th2);
        let [cc, sn, tt] = exp_kernel_fixed(&u1);
        let m = beta.mul_ref(&inv_alpha).mul_ref(&half);
        let q_u = s.e123inf.sub_ref(&m.mul_ref(&s.scalar)).mul_ref(&rho);
        let w1 = t.mul_ref(&tf).mul_ref(&q_u);
        let p1 = t.mul_ref(&m);
        let e = exp_fixed(&ln_fixed(alpha).mul_ref(&half).mul_ref(t));
        let et = e.mul_ref(t).mul_ref(&rho);
        let lam = et.mul_ref(&sn).mul_ref(&f);
        let k = f.mul_ref(&m).add_ref(&g.mul_ref(&q_u));
        let lam2 = et.mul_ref(&sn.mul_ref(&k).sub_ref(&f.mul_ref(&w1.mul_ref(&tt).add_ref(&p1.mul_ref(&sn)))));
        let omega = e.mul_ref(&w1.mul_ref(&sn).add_ref(&p1.mul_ref(&cc)));
        power_from_weights(s, [e.mul_ref(&cc), lam, lam2, omega])
    }
}

/// `S^t` from its weights `[σ', λ, λ₂, Ω]`: `σ' + λ a e123 + (λ c + λ₂ a) einf + Ωω` for
/// `S = S∅ + a e123 + c einf + Sω ω` (the shape of every fused power).
#[inline(always)]
fn power_from_weights<T: Real>(s: &Pose<T>, [sigma, lam, lam2, omega]: [T; 4]) -> Pose<T> {
    let (a, c) = split(s);
    let c_out = std::array::from_fn(|i| c[i].mul_ref(&lam).add_ref(&a[i].mul_ref(&lam2)));
    assemble(sigma, a.map(|x| x.mul_ref(&lam)), c_out, omega)
}

/// The unit power's weights `[cos, λ, λ₂, Ω]` ([`power_from_weights`]) for a unit
/// `S = S∅ + a e123 + c einf + Sω ω` with `S∅ ≥ 0` (`α = 1`, `m = 0`, `e = 1`: `q_U = Sω`,
/// `λ = t f sin`, `λ₂ = t (sin g q_U - f w' T)`, `Ω = w' sin` with `w' = t² f Sω`), the exp
/// kernel's `[cos, sin, T]` taken at `u' = (tθ)²`.
#[inline(always)]
fn unit_weights<T: Real>(s: &Pose<T>, t: &T) -> [T; 4] {
    let (a, _) = split(s);
    let xr = dot(&a, &a);
    // sin² θ = |a|², cos² θ = S∅² (α = 1): θ² without a square root on its chain
    let (th2, f, g) = angle_factors_fixed(&xr, &s.scalar.mul_ref(&s.scalar), &s.scalar, &Real::sqrt(&xr));
    let tf = t.mul_ref(&f);
    let u1 = t.mul_ref(t).mul_ref(&th2);
    let [cc, sn, tt] = exp_kernel_fixed(&u1);
    let w1 = t.mul_ref(&tf).mul_ref(&s.e123inf);
    let lam = tf.mul_ref(&sn);
    let lam2 = t.mul_ref(&sn.mul_ref(&g.mul_ref(&s.e123inf)).sub_ref(&f.mul_ref(&w1.mul_ref(&tt))));
    let omega = w1.mul_ref(&sn);
    [cc, lam, lam2, omega]
}

/// `d·X` for a dual scalar `d = d0 + d1 ω` (`ω = e123inf`, central in the even subalgebra,
/// `ω²= 0`): `ω (σ + a e123 + c einf + pω) = σω - a einf`, so 12 products instead of a motor
/// product's 64.
#[inline(always)]
fn dual_scale<T: Ring>(d0: &T, d1: &T, x: &Pose<T>) -> [T; 8] {
    [
        d0.mul_ref(&x.scalar),
        d0.mul_ref(&x.e12),
        d0.mul_ref(&x.e13),
        d0.mul_ref(&x.e23),
        // c' = d0 c - d1 a with a = (e23, -e13, e12)
        d0.mul_ref(&x.e1inf).sub_ref(&d1.mul_ref(&x.e23)),
        d0.mul_ref(&x.e2inf).add_ref(&d1.mul_ref(&x.e13)),
        d0.mul_ref(&x.e3inf).sub_ref(&d1.mul_ref(&x.e12)),
        d0.mul_ref(&x.e123inf).add_ref(&d1.mul_ref(&x.scalar)),
    ]
}

impl<T: Real> Pose<T> {
    /// `a (rev(a) b)^t` for a unit `rel = rev(a) b` with `rel∅ ≥ 0`, without the last motor
    /// product. The power lies in the dual plane of `rel`: `rel^t = A + B rel` with the dual
    /// scalars `A = (cos - λ rel∅) + (Ω - λ relω + λ₂ rel∅) ω` and `B = λ - λ₂ ω` (the weights
    /// of [`unit_weights`] at `t`), and `a rel = a rev(a) b = N_a b` with
    /// `N_a = a rev(a) = α_a + β_a ω` (`α_a = a∅² + |a e123|²`, `β_a = 2 (a∅ aω - a·c)`). So
    /// `a rel^t = A a + (B N_a) b`: two dual scalings (24 products) in place of the power's
    /// assembly and a motor product.
    ///
    /// `A → 0` as `t → 1`, where `cos - λ rel∅` cancels; past `t = ½` the weights come from
    /// the other end, `a rel^t = N_a b rev(rel)^{1-t}` (`N_a N_b = 1` for a unit `rel`), whose
    /// weights at `1 - t` are the same functions of `rel∅`, `|rel e123|` and `relω` (`rev`
    /// changes none of them): `a rel^t = B' a + (N_a A') b`. The weight that vanishes at an
    /// end is always a `λ` (a product, `t f sin`), never a difference.
    #[inline(always)]
    fn slerp_unit_weights(a: &Self, b: &Self, rel: &Self, t: &T) -> Self {
        let s = rel;
        let late = *t > T::from_ratio(1, 2);
        // 1 - t is exact for t in [½, 1] (Sterbenz)
        let t = if late { T::one().sub_ref(t) } else { t.clone() };
        let [cc, lam, lam2, omega] = unit_weights(s, &t);
        // A = a0 + a1 ω, B = lam - lam2 ω
        let a0 = cc.sub_ref(&lam.mul_ref(&s.scalar));
        let a1 = omega.sub_ref(&lam.mul_ref(&s.e123inf)).add_ref(&lam2.mul_ref(&s.scalar));
        // N_a = alpha + beta ω
        let (aa, ac) = split(a);
        let alpha = a.scalar.mul_ref(&a.scalar).add_ref(&dot(&aa, &aa));
        let beta = a.scalar.mul_ref(&a.e123inf).sub_ref(&dot(&aa, &ac));
        let beta = beta.add_ref(&beta);
        let (x, y) = if late {
            // B' a + (N_a A') b
            let (n0, n1) = (alpha.mul_ref(&a0), alpha.mul_ref(&a1).add_ref(&beta.mul_ref(&a0)));
            (dual_scale(&lam, &lam2.neg_ref(), a), dual_scale(&n0, &n1, b))
        } else {
            // A a + (B N_a) b
            let (n0, n1) = (lam.mul_ref(&alpha), lam.mul_ref(&beta).sub_ref(&lam2.mul_ref(&alpha)));
            (dual_scale(&a0, &a1, a), dual_scale(&n0, &n1, b))
        };
        let [s0, s1, s2, s3, s4, s5, s6, s7] = std::array::from_fn(|i| x[i].add_ref(&y[i]));
        Pose::new(s0, s1, s2, s3, s4, s5, s6, s7)
    }
}

impl<T: Ring> Pose<T> {
    /// The additive interpolation `(1 - t) A + t B` of eq. (17): polynomial in `t`, exact over
    /// exact scalars; generally not unitary, and singular where it passes through a singular
    /// pseudoscalar (the zero transform).
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio, Q};
    /// use motion::Pose;
    /// let a = Pose::<Q>::identity();
    /// let b = Pose::rotor_from_parts(&q(0), &q(1), &[q(0), q(0), q(1)]); // e12: half turn
    /// let m = Pose::lerp(&a, &b, &ratio(1, 2)); // ½(1 + e12): quarter turn, |S|² = ½
    /// assert_eq!(m.transform_point(&[q(1), q(0), q(0)]).unwrap(), [q(0), q(1), q(0)]);
    /// ```
    pub fn lerp(a: &Self, b: &Self, t: &T) -> Self {
        let one_minus_t = T::one().sub_ref(t);
        &a.scale(&one_minus_t) + &b.scale(t)
    }
}
