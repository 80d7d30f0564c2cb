//! Generators `B = φP + t n` (W-L Lemma 1; the paper writes `B = (ψ/2)P + t n/2` in Sec. 2.4),
//! their parts `(ψ, P, t∥, t⊥)` (Sec. 2.6) and the closed-form exponential of Theorem 3:
//!
//! ```text
//! exp(φP + tn) = [cos φ + sin φ P][1 + t⊥ n] + sinc(φ) t∥ n,
//! ```
//!
//! `t∥` the component of `t` in the plane of `P`, `t⊥ = t - t∥`. Writing `φP = -r e123` with the
//! half rotation vector `r = φ â` and `t⊥ = (t·r) r/φ²`, `φP t⊥ = -(t·r) e123`, so the same
//! rotor is, with `C = cos φ`, `S = sin φ/φ`, `K = (S - C)/φ²` (power series near `φ = 0`):
//!
//! ```text
//! exp(φP + tn) = C + S φP + (S t - K (t·r) r) n - S (t·r) e123 n,
//! ```
//!
//! which has no division and no branch: pure translations (`r = 0`) are exact and dual-number
//! derivatives stay finite there. (`(S t - K(t·r) r)` is `C t⊥ + S t∥`, the grade-2 `n` part of
//! Sec. 2.6.) `x n = Σ x_i (e_i4 + e_i5)` and `e123 n = e1234 + e1235`.
//!
//! ```
//! use motion::wareham_lasenby::Generator;
//! // exp(t n) = 1 + t n = T_{-2t}: a translation by -2t.
//! let r = Generator::new([0.0; 3], [0.5, 0.0, 0.0]).exp().unwrap();
//! assert_eq!((r.scalar, r.e14, r.e15), (1.0, 0.5, 0.5));
//! ```

use super::WlError;
use super::cga::{cross, dot, plane, unit};
use crate::series::exp_kernel;
use algebra_core::{Real, Ring};
use gam_algebras::cga::{Bivector, Motor};

/// A generator `B = φP + t n` of a displacement rotor (W-L Lemma 1): `r = φ â` is half the
/// rotation vector (`φP = -r e123`, [`super::cga::plane`]), `t` the vector of the `n` part.
/// As a `cga` bivector: `e12 = -r3`, `e13 = r2`, `e23 = -r1`, `e_i4 = e_i5 = t_i`, `e45 = 0`.
///
/// ```
/// use motion::wareham_lasenby::Generator;
/// let b = Generator::new([0.0, 0.0, 0.5], [1.0, 2.0, 3.0]);
/// assert_eq!(Generator::from_bivector(&b.to_bivector()).unwrap(), b);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Generator<T> {
    /// `r = φ â`: half the rotation angle times the unit axis (right-handed).
    pub r: [T; 3],
    /// `t` of the `t n` part.
    pub t: [T; 3],
}

/// The parts of a generator in the paper's form `B = (ψ/2) P + t n/2` (Sec. 2.4, 2.6): the
/// rotation angle `ψ = 2φ ≥ 0`, the unit axis of `P` (`P = -axis e123`; zero when `ψ = 0`), and
/// the paper's `t = 2 t_B` split into `t∥` (in the plane of `P`) and `t⊥` (along the axis; all
/// of `t` when `ψ = 0`). The rotor `exp(B)` translates by `-t⊥`, rotates by `ψ` in `P`, then
/// translates by `t'∥` (Lemma 6; the sign of the first translation is `-`, not the `+` of the
/// paper's prose: `exp(tn/2) = 1 - nt/2 = T_{-t}`).
///
/// ```
/// let p = motion::wareham_lasenby::Generator::new([0.0, 0.0, 0.25], [1.0, 0.0, 3.0]).parts();
/// assert_eq!((p.psi, p.axis, p.t_par, p.t_perp), (0.5, [0.0, 0.0, 1.0], [2.0, 0.0, 0.0], [0.0, 0.0, 6.0]));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct GeneratorParts<T> {
    /// `ψ`, the rotation angle.
    pub psi: T,
    /// The unit axis `â` of the plane `P = -â e123` (`[0, 0, 0]` when `ψ = 0`).
    pub axis: [T; 3],
    /// `t∥`, the paper's `t` in the plane of `P`.
    pub t_par: [T; 3],
    /// `t⊥`, the paper's `t` along the axis.
    pub t_perp: [T; 3],
}

impl<T: Ring> Generator<T> {
    /// The generator with half rotation vector `r` and `n` part `t`.
    ///
    /// ```
    /// let b = motion::wareham_lasenby::Generator::new([0.0, 0.0, 1.0], [0.0; 3]);
    /// assert_eq!(b.to_bivector().e12, -1.0);
    /// ```
    pub fn new(r: [T; 3], t: [T; 3]) -> Self {
        Generator { r, t }
    }

    /// The zero generator (`exp(0) = 1`).
    ///
    /// ```
    /// assert_eq!(motion::wareham_lasenby::Generator::<f64>::zero().exp().unwrap().scalar, 1.0);
    /// ```
    pub fn zero() -> Self {
        Generator { r: std::array::from_fn(|_| T::zero()), t: std::array::from_fn(|_| T::zero()) }
    }

    /// `a B + b C` (the generators form a linear space: the interpolation of Sec. 3).
    ///
    /// ```
    /// use motion::wareham_lasenby::Generator;
    /// let b = Generator::new([1.0, 0.0, 0.0], [0.0, 2.0, 0.0]);
    /// assert_eq!(Generator::combine(&0.5, &b, &2.0, &b), Generator::new([2.5, 0.0, 0.0], [0.0, 5.0, 0.0]));
    /// ```
    pub fn combine(a: &T, b: &Self, c: &T, d: &Self) -> Self {
        let f =
            |x: &[T; 3], y: &[T; 3]| -> [T; 3] { std::array::from_fn(|i| a.mul_ref(&x[i]).add_ref(&c.mul_ref(&y[i]))) };
        Generator { r: f(&b.r, &d.r), t: f(&b.t, &d.t) }
    }

    /// `s B`.
    ///
    /// ```
    /// let b = motion::wareham_lasenby::Generator::new([1.0, 0.0, 0.0], [0.0, 2.0, 0.0]).scale(&0.5);
    /// assert_eq!(b.t, [0.0, 1.0, 0.0]);
    /// ```
    pub fn scale(&self, s: &T) -> Self {
        Generator { r: self.r.each_ref().map(|x| x.mul_ref(s)), t: self.t.each_ref().map(|x| x.mul_ref(s)) }
    }

    /// The generator as a `cga` bivector.
    ///
    /// ```
    /// let b = motion::wareham_lasenby::Generator::new([0.0; 3], [1.0, 0.0, 0.0]).to_bivector();
    /// assert_eq!((b.e14, b.e15, b.e45), (1.0, 1.0, 0.0));
    /// ```
    pub fn to_bivector(&self) -> Bivector<T> {
        let mut b = plane(&self.r);
        let [t1, t2, t3] = self.t.clone();
        (b.e14, b.e24, b.e34) = (t1.clone(), t2.clone(), t3.clone());
        (b.e15, b.e25, b.e35) = (t1, t2, t3);
        b
    }

    /// The same generator over another scalar.
    ///
    /// ```
    /// use motion::wareham_lasenby::Generator;
    /// assert_eq!(Generator::new([1.0f64; 3], [2.0; 3]).map_scalar(&|x: &f64| *x as f32).t, [2.0f32; 3]);
    /// ```
    pub fn map_scalar<U: Ring>(&self, f: &dyn Fn(&T) -> U) -> Generator<U> {
        Generator { r: self.r.each_ref().map(f), t: self.t.each_ref().map(f) }
    }
}

impl<T: Real> Generator<T> {
    /// Reads a `cga` bivector of the form `φP + t n` (`P` Euclidean, Sec. 2.3): `e45 = 0` and
    /// `e_i4 = e_i5`, to `√ε` of the largest coefficient; `t_i = (e_i4 + e_i5)/2`. Any other
    /// bivector is [`WlError::NotAGenerator`] (Theorem 8 fails for them).
    ///
    /// ```
    /// use gam_algebras::cga::Bivector;
    /// use motion::wareham_lasenby::Generator;
    /// assert!(Generator::from_bivector(&Bivector::<f64>::e45()).is_err());
    /// assert_eq!(Generator::from_bivector(&(Bivector::<f64>::e14() + Bivector::e15())).unwrap().t, [1.0, 0.0, 0.0]);
    /// ```
    pub fn from_bivector(b: &Bivector<T>) -> Result<Self, WlError> {
        let tol = tolerance(b.iter());
        let off = [b.e45.clone(), b.e14.sub_ref(&b.e15), b.e24.sub_ref(&b.e25), b.e34.sub_ref(&b.e35)];
        if !b.iter().all(Real::is_finite) || off.iter().any(|x| Real::abs(x) > tol) {
            return Err(WlError::NotAGenerator { value: b.to_string() });
        }
        let half = T::from_ratio(1, 2);
        let avg = |x: &T, y: &T| x.add_ref(y).mul_ref(&half);
        Ok(Generator {
            r: [b.e23.neg_ref(), b.e13.clone(), b.e12.neg_ref()],
            t: [avg(&b.e14, &b.e15), avg(&b.e24, &b.e25), avg(&b.e34, &b.e35)],
        })
    }

    /// The closed-form exponential of Theorem 3 (module docs), a unit displacement rotor. Fails
    /// only for non-finite input or overflow.
    ///
    /// ```
    /// use motion::wareham_lasenby::{Generator, cga::rotor};
    /// // exp(φP) = cos φ + sin φ P: the rotation by 2φ.
    /// let r = Generator::new([0.0, 0.0, 0.3], [0.0; 3]).exp().unwrap();
    /// let want = rotor(&[0.0, 0.0, 1.0], &0.6).unwrap();
    /// assert!(r.to_array().iter().zip(want.to_array()).all(|(a, b)| f64::abs(a - b) < 1e-16));
    /// ```
    pub fn exp(&self) -> Result<Motor<T>, WlError> {
        let not_finite = || WlError::NotFinite { op: "exp", value: format!("{:?}", self.to_bivector().to_array()) };
        if !self.r.iter().chain(&self.t).all(Real::is_finite) {
            return Err(not_finite());
        }
        let [c, s, k] = exp_kernel(&dot(&self.r, &self.r));
        let tr = dot(&self.t, &self.r);
        let ktr = k.mul_ref(&tr);
        let w: [T; 3] = std::array::from_fn(|i| s.mul_ref(&self.t[i]).sub_ref(&ktr.mul_ref(&self.r[i])));
        let p = plane(&self.r);
        let mut m = Motor::zero();
        m.scalar = c;
        (m.e12, m.e13, m.e23) = (p.e12.mul_ref(&s), p.e13.mul_ref(&s), p.e23.mul_ref(&s));
        (m.e14, m.e24, m.e34) = (w[0].clone(), w[1].clone(), w[2].clone());
        (m.e15, m.e25, m.e35) = (w[0].clone(), w[1].clone(), w[2].clone());
        let q = s.mul_ref(&tr).neg_ref();
        (m.e1234, m.e1235) = (q.clone(), q);
        if !m.iter().all(Real::is_finite) {
            return Err(not_finite());
        }
        Ok(m)
    }

    /// The parts `(ψ, P, t∥, t⊥)` of Sec. 2.6 ([`GeneratorParts`]).
    ///
    /// ```
    /// let p = motion::wareham_lasenby::Generator::new([0.0; 3], [1.0, 2.0, 3.0]).parts();
    /// assert_eq!((p.psi, p.axis, p.t_perp), (0.0, [0.0; 3], [2.0, 4.0, 6.0]));
    /// ```
    pub fn parts(&self) -> GeneratorParts<T> {
        let two = T::from_i64(2);
        let t2 = self.t.each_ref().map(|x| x.mul_ref(&two));
        let phi = Real::sqrt(&dot(&self.r, &self.r));
        match unit(&self.r) {
            Some(a) => {
                let along = dot(&t2, &a);
                let t_perp = a.each_ref().map(|x| x.mul_ref(&along));
                let t_par = std::array::from_fn(|i| t2[i].sub_ref(&t_perp[i]));
                GeneratorParts { psi: phi.mul_ref(&two), axis: a, t_par, t_perp }
            }
            None => GeneratorParts {
                psi: phi.mul_ref(&two),
                axis: std::array::from_fn(|_| T::zero()),
                t_par: std::array::from_fn(|_| T::zero()),
                t_perp: t2,
            },
        }
    }

    /// The generator from the paper's parts: `B = (ψ/2) P + (t∥ + t⊥) n/2` (the axis is
    /// normalised; a zero axis is allowed only with `ψ = 0`).
    ///
    /// ```
    /// use motion::wareham_lasenby::Generator;
    /// let b = Generator::new([0.1, -0.2, 0.3], [1.0, 2.0, 3.0]);
    /// let back = Generator::from_parts(&b.parts()).unwrap();
    /// assert!(back.r.iter().zip(&b.r).chain(back.t.iter().zip(&b.t)).all(|(x, y)| f64::abs(x - y) < 1e-15));
    /// ```
    pub fn from_parts(p: &GeneratorParts<T>) -> Result<Self, WlError> {
        let half = T::from_ratio(1, 2);
        let a = match unit(&p.axis) {
            Some(a) => a,
            None if p.psi.is_exact_zero() => std::array::from_fn(|_| T::zero()),
            None => return Err(WlError::ZeroAxis { value: format!("{:?}", p.axis) }),
        };
        let phi = p.psi.mul_ref(&half);
        Ok(Generator {
            r: a.map(|x| x.mul_ref(&phi)),
            t: std::array::from_fn(|i| p.t_par[i].add_ref(&p.t_perp[i]).mul_ref(&half)),
        })
    }

    /// `t × r` and `t·r`, used by the helix.
    pub(crate) fn cross_dot(&self) -> ([T; 3], T) {
        (cross(&self.t, &self.r), dot(&self.t, &self.r))
    }
}

/// `√ε (1 + max |x|)`: the slack allowed for rounding in the structural checks.
pub(crate) fn tolerance<'a, T: Real + 'a>(xs: impl Iterator<Item = &'a T>) -> T {
    let m = xs.map(Real::abs).fold(T::zero(), |a, b| if b > a { b } else { a });
    Real::sqrt(&T::epsilon()).mul_ref(&T::one().add_ref(&m))
}
