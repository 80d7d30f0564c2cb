//! The action of a pose on points and directions: `F_S = P f_S E` (Sec. 2 of the main paper).
//!
//! `E` embeds a point `(x, y, z)` as `e0 + x e1 + y e2 + z e3` in G_{0123inf}, `f_S(x) =
//! rev(S) x S`, and `P` reads the coefficients of `e0, e1, e2, e3` and divides by that of
//! `e0`. Instead of multiplying in the 32-dimensional G_{0123inf}, the closed forms of
//! eqs. (6)-(9) give the image of `e1, e2, e3` and the vector part of the image of `e0`
//! directly from the eight coefficients of `S` (the generated `cga_null` sandwich is the
//! reference in the tests). With `rev(S) S = α + βω`, the `e0` coefficient of
//! `rev(S)(W e0 + x)S` is `αW` (Lemma 2.2(ii)), so `F_S` is the projective map
//! `(x, W) ↦ (A x + W t, αW)` and the Euclidean map `x ↦ (A x + t)/α`.
//!
//! [`Pose::transform_point`] evaluates that map in fewer operations: with `v = (S23, -S13,
//! S12)` and `c = (S1∞, S2∞, S3∞)`, `A x + t = α x + 2(S∅ m + v × m + Sω v)` for
//! `m = v × x + c` (the quaternion form of the rotation, eqs. 6-8, and eq. 9 regrouped), so a
//! point costs two cross products and one division; [`Pose::action_rows`] keeps the matrix
//! form for matrices and directions.
//!
//! Homogeneous points here are `[x, y, z, w]` (w last, as in 4x4 matrices); the paper writes
//! `(W, X, Y, Z)`.
//!
//! ```
//! use algebra_core::rational::{q, Q};
//! use motion::Pose;
//! // The non-unit pose 2(1 + e12) still acts as a quarter turn about e3 (Lemma 2.6(i)).
//! let s = Pose::<Q>::rotor_from_parts(&q(2), &q(2), &[q(0), q(0), q(1)]);
//! assert_eq!(s.transform_point(&[q(1), q(2), q(3)]).unwrap(), [q(-2), q(1), q(3)]);
//! ```

use crate::repr::vec3::cross;
use crate::{MotionError, Pose};
use algebra_core::{Field, Ring};

impl<T: Ring> Pose<T> {
    /// The rows `[A | t]` of the projective action and `α`, from eqs. (6)-(9): column `i` of
    /// `A` is the `e1, e2, e3` part of `rev(S) e_i S`; `t` is that of `rev(S) e0 S`;
    /// `α = S∅² + S12² + S13² + S23²`. Exact over exact scalars.
    ///
    /// ```
    /// let (rows, alpha) = motion::Pose::translation(&[1.0, 2.0, 3.0]).action_rows();
    /// assert_eq!(rows[1], [0.0, 1.0, 0.0, 2.0]);
    /// assert_eq!(alpha, 1.0);
    /// ```
    pub fn action_rows(&self) -> ([[T; 4]; 3], T) {
        let s = self;
        let (s0, s12, s13, s23) = (&s.scalar, &s.e12, &s.e13, &s.e23);
        let (s1, s2, s3, sw) = (&s.e1inf, &s.e2inf, &s.e3inf, &s.e123inf);
        let two = |x: T| x.add_ref(&x);
        let (q0, q12, q13, q23) = (s0.mul_ref(s0), s12.mul_ref(s12), s13.mul_ref(s13), s23.mul_ref(s23));
        // eq. (6): rev(S) e1 S
        let c1 = [
            q0.sub_ref(&q12).sub_ref(&q13).add_ref(&q23),
            two(s0.mul_ref(s12).sub_ref(&s13.mul_ref(s23))),
            two(s0.mul_ref(s13).add_ref(&s12.mul_ref(s23))),
        ];
        // eq. (7): rev(S) e2 S
        let c2 = [
            two(s0.mul_ref(s12).add_ref(&s13.mul_ref(s23))).neg_ref(),
            q0.sub_ref(&q12).add_ref(&q13).sub_ref(&q23),
            two(s0.mul_ref(s23).sub_ref(&s12.mul_ref(s13))),
        ];
        // eq. (8): rev(S) e3 S
        let c3 = [
            two(s0.mul_ref(s13).sub_ref(&s12.mul_ref(s23))).neg_ref(),
            two(s0.mul_ref(s23).add_ref(&s12.mul_ref(s13))).neg_ref(),
            q0.add_ref(&q12).sub_ref(&q13).sub_ref(&q23),
        ];
        // eq. (9): the e1, e2, e3 part of rev(S) e0 S
        let t = [
            two(s0.mul_ref(s1).sub_ref(&s12.mul_ref(s2)).sub_ref(&s13.mul_ref(s3)).add_ref(&s23.mul_ref(sw))),
            two(s0.mul_ref(s2).add_ref(&s12.mul_ref(s1)).sub_ref(&s13.mul_ref(sw)).sub_ref(&s23.mul_ref(s3))),
            two(s0.mul_ref(s3).add_ref(&s12.mul_ref(sw)).add_ref(&s13.mul_ref(s1)).add_ref(&s23.mul_ref(s2))),
        ];
        let alpha = q0 + &q12 + &q13 + &q23;
        let ([a11, a21, a31], [a12, a22, a32], [a13, a23, a33], [t1, t2, t3]) = (c1, c2, c3, t);
        let rows = [[a11, a12, a13, t1], [a21, a22, a23, t2], [a31, a32, a33, t3]];
        (rows, alpha)
    }

    /// The projective map of `S` on a homogeneous point `[x, y, z, w]` (`w = 0`: a direction):
    /// the `e1, e2, e3, e0` coefficients of `rev(S)(w e0 + x e1 + y e2 + z e3)S`. No division,
    /// so exact over exact scalars, and `F_{UV} = F_V F_U` holds coefficient by coefficient
    /// (Lemma 2.3).
    ///
    /// ```
    /// let s = motion::Pose::translation(&[1.0, 0.0, 0.0]).scale(&2.0);
    /// assert_eq!(s.apply_homogeneous(&[1.0, 1.0, 1.0, 1.0]), [8.0, 4.0, 4.0, 4.0]);
    /// ```
    pub fn apply_homogeneous(&self, p: &[T; 4]) -> [T; 4] {
        let (rows, alpha) = self.action_rows();
        let image = rows.map(|r| r[0].mul_ref(&p[0]) + r[1].mul_ref(&p[1]) + r[2].mul_ref(&p[2]) + r[3].mul_ref(&p[3]));
        let [x, y, z] = image;
        [x, y, z, alpha.mul_ref(&p[3])]
    }
}

impl<T: Ring> Pose<T> {
    /// `F_S(p)` given `inv = 1/α`, by the fewest operations: with `v = (S23, -S13, S12)` (so
    /// that `rev(S) x S` rotates like the quaternion `S∅ + v`), `c = (S1∞, S2∞, S3∞)` and
    /// `m = v × p + c`, eqs. (6)-(9) regroup as `α F_S(p) = α p + 2(S∅ m + v × m + Sω v)`:
    /// 21 products after `2/α`. The one formula of every point action (the scalar
    /// [`Pose::transform_point`] and the batches), so they agree bit for bit.
    pub(crate) fn image_with(&self, p: &[T; 3], inv: &T) -> [T; 3] {
        self.image_with_twice(p, &inv.add_ref(inv))
    }

    /// [`Pose::image_with`] given `k = 2/α` (for floats the same bits as `1/α + 1/α`).
    #[inline]
    fn image_with_twice(&self, p: &[T; 3], k: &T) -> [T; 3] {
        let d = self.half_displacement(p);
        std::array::from_fn(|i| p[i].add_ref(&k.mul_ref(&d[i])))
    }

    /// `F_S(p)` for a unit `S` (`α = 1`): [`Pose::image_with`] with `1/α = 1`, so
    /// `p + 2(S∅ m + v × m + Sω v)`, 18 products and no division ([`crate::UnitPose`]).
    #[inline]
    pub(crate) fn image_unit(&self, p: &[T; 3]) -> [T; 3] {
        let d = self.half_displacement(p);
        std::array::from_fn(|i| p[i].add_ref(&d[i].add_ref(&d[i])))
    }

    /// `S∅ m + v × m + Sω v` with `m = v × p + c` (see [`Pose::image_with`]): half of
    /// `α F_S(p) - α p`.
    #[inline]
    fn half_displacement(&self, p: &[T; 3]) -> [T; 3] {
        let s = self;
        let v = [s.e23.clone(), s.e13.neg_ref(), s.e12.clone()];
        let vp = cross(&v, p);
        let m = [vp[0].add_ref(&s.e1inf), vp[1].add_ref(&s.e2inf), vp[2].add_ref(&s.e3inf)];
        let vm = cross(&v, &m);
        std::array::from_fn(|i| s.scalar.mul_ref(&m[i]).add_ref(&vm[i]).add_ref(&s.e123inf.mul_ref(&v[i])))
    }
}

impl<T: Field> Pose<T> {
    /// `F_S(p)` for a point `p` of R^3: `(A p + t)/α`. Fails for singular `S` (zero transform).
    ///
    /// Ordinary input takes one test (`α` tame: within `2^±500` for floats, non-zero for exact
    /// scalars; the result finite) and no other check; everything else (non-finite, singular,
    /// far from unit scale, overflowing) goes to the careful path, which names the failure.
    /// A non-finite input cannot give a finite result: every coefficient of `S` and of `p`
    /// enters a product.
    ///
    /// ```
    /// let s = motion::Pose::rotation(&[0.0, 0.0, 1.0], &std::f64::consts::FRAC_PI_2).unwrap();
    /// let p = s.transform_point(&[1.0, 0.0, 5.0]).unwrap();
    /// assert!(p[0].abs() < 1e-15 && (p[1] - 1.0).abs() < 1e-15 && (p[2] - 5.0).abs() < 1e-15);
    /// ```
    // Inlined at the caller's site: the call, the returned `Result` in memory and its
    // discriminant test cost 2-5 % of the action (docs/performance.md, "thirteenth session");
    // the careful path stays out of line.
    #[inline(always)]
    pub fn transform_point(&self, p: &[T; 3]) -> Result<[T; 3], MotionError> {
        let alpha = self.alpha();
        // 2/α in one step: one addition less on the point's chain than 1/α + 1/α
        let two = T::from_i64(2);
        if T::relative_epsilon() == 0.0 {
            // exact scalars: α = 0 is the only case to decline (nothing overflows)
            if alpha.is_exact_zero() {
                return self.transform_point_careful(p);
            }
            return Ok(self.image_with_twice(p, &two.div_ref(&alpha)));
        }
        // floats: the image first (a zero or tiny α gives infinities, never a trap), then the
        // tests, off the division's chain: α tame (1/α a normal number) and each coordinate
        // finite. The careful path names whatever failed.
        let out = self.image_with_twice(p, &two.div_ref(&alpha));
        let direct = if crate::series::plain_f64::<T>() {
            // The coordinates' sum is finite when every coordinate is, and infinite or NaN
            // when one is not (or when three finite ones overflow in the sum: the careful path
            // then gives the same bits). One integer test on its bits: `|sum| + (2^63 - ∞)`
            // has its sign bit set exactly when `|sum|` is infinite or NaN. Measured 2-4 %
            // faster than folding `Σ (o_i - o_i)` into `α`'s test, which must wait for the
            // division; `α`'s own test branches before it (docs/performance.md, "thirteenth
            // session"). Dual numbers and jets keep the separate tests: their `magnitude` is a
            // largest part that does not propagate NaN.
            const C: u64 = (1 << 63) - f64::INFINITY.to_bits();
            let sum = out[0].add_ref(&out[1]).add_ref(&out[2]);
            let over = sum.magnitude().to_bits().wrapping_add(C);
            (over >> 63 == 0) & crate::scaled::tame(&alpha)
        } else {
            let finite = out[0].is_finite_value() & out[1].is_finite_value() & out[2].is_finite_value();
            crate::scaled::tame(&alpha) & finite
        };
        if direct {
            return Ok(out);
        }
        self.transform_point_careful(p)
    }

    /// [`Pose::transform_point`] for the inputs the direct path declines.
    #[cold]
    #[inline(never)]
    fn transform_point_careful(&self, p: &[T; 3]) -> Result<[T; 3], MotionError> {
        crate::scaled::require_finite("transform_point", self, p)?;
        if let Some((_, s)) = crate::scaled::unusual_scale(self) {
            // F_S does not depend on the scale of S: act with S/2^e (1e300 S, 1e-300 S)
            return s.transform_point_careful(p);
        }
        let inv = self.alpha().try_recip().ok_or_else(|| self.singular("transform_point"))?;
        let out = self.image_with(p, &inv);
        if out.iter().all(Ring::is_finite_value) { Ok(out) } else { Err(self.overflow("transform_point")) }
    }

    /// The image `A d / α` of a direction (a point at infinity, `W = 0`): the rotation part
    /// only. Fails for singular `S`.
    ///
    /// ```
    /// let s = motion::Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &std::f64::consts::PI, &[5.0, 5.0, 5.0]).unwrap();
    /// let d = s.transform_direction(&[1.0, 0.0, 0.0]).unwrap();
    /// assert!((d[0] + 1.0).abs() < 1e-15 && d[1].abs() < 1e-15 && d[2] == 0.0);
    /// ```
    pub fn transform_direction(&self, d: &[T; 3]) -> Result<[T; 3], MotionError> {
        crate::scaled::require_finite("transform_direction", self, d)?;
        if let Some((_, s)) = crate::scaled::unusual_scale(self) {
            return s.transform_direction(d);
        }
        let (rows, alpha) = self.action_rows();
        let inv = alpha.try_recip().ok_or_else(|| self.singular("transform_direction"))?;
        let out = rows.map(|r| (r[0].mul_ref(&d[0]) + r[1].mul_ref(&d[1]) + r[2].mul_ref(&d[2])).mul_ref(&inv));
        if out.iter().all(Ring::is_finite_value) { Ok(out) } else { Err(self.overflow("transform_direction")) }
    }
}
