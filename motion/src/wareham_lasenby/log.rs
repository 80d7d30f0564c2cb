//! The logarithm `ℓ(R)` of a displacement rotor (W-L Theorem 9), with the cases the theorem
//! leaves out. Write a unit displacement rotor as (Sec. 2.6, `B = φP + tn`)
//!
//! ```text
//! <R>_0 = cos φ,   <R>_2 = sin φ P + (cos φ t⊥ + sinc φ t∥) n,   <R>_4 = sin φ P t⊥ n,
//! ```
//!
//! i.e. `cga` coefficients `c = R∅`, `s r̂ = (-R23, R13, -R12)` with `s = sin φ ≥ 0`,
//! `w_i = R_i4 (= R_i5) = cos φ t⊥ + sinc φ t∥`, `q = R1234 (= R1235) = -s (t·r̂)`. Then
//! `φ = atan2(s, c) ∈ [0, π]` (the theorem's `cos⁻¹ <R>_0`), and for `0 < φ < π`
//!
//! ```text
//! r = φ r̂,   t·r̂ = c (w·r̂) - s q,   t∥ = (w - (w·r̂) r̂) φ/s,   t = t∥ + (t·r̂) r̂,
//! ```
//!
//! the theorem's `ab`, `c⊥ n`, `c∥ n` in coordinates (`t·r̂` from both the grade-2 and the
//! grade-4 part, so it stays accurate near `φ = π/2` and near `0`). The cases outside
//! `0 < φ < π`:
//!
//! * `s = 0`, `c > 0` (**pure translation**, the theorem's 0/0): `ℓ(R) = w n`, `r = 0`.
//! * `s = 0`, `c < 0` (**`|φ| = π`**, `R = -(1 + t⊥ n)`; the theorem's formulas give 0):
//!   `t∥` and the orientation of `P` are lost; we take `r̂ = w/|w|` (or `e3` when `w = 0`),
//!   `r = π r̂`, `t = -w`: then `exp(ℓ(R)) = R` again.
//!
//! `exp(ℓ(R)) = R` for every unit displacement rotor; `ℓ(exp B) = B` for `|r| < π`. A rotor
//! with negative scalar part (`φ > π/2`, rotation angle `ψ = 2φ > π`) gives the long way
//! round; `-R` is the same displacement ([`super::convert`] keeps the sign it is given).
//!
//! ```
//! use motion::wareham_lasenby::{Generator, log};
//! let b = Generator::new([0.1, -0.4, 0.2], [1.0, 2.0, -3.0]);
//! let l = log(&b.exp().unwrap()).unwrap();
//! assert!(l.r.iter().zip(&b.r).chain(l.t.iter().zip(&b.t)).all(|(x, y)| f64::abs(x - y) < 1e-14));
//! ```

use super::WlError;
use super::cga::dot;
use super::generator::{Generator, tolerance};
use algebra_core::Real;
use gam_algebras::cga::Motor;

/// `ℓ(R)` (module docs). Fails ([`WlError::NotADisplacementRotor`]) unless `R` is a unit
/// displacement rotor to `√ε` (`e45`, `e1245`, `e1345`, `e2345` zero, `e_i4 = e_i5`,
/// `e1234 = e1235`, `cos² φ + sin² φ = 1`), or for non-finite input.
///
/// ```
/// use motion::wareham_lasenby::{cga::translator, log};
/// let l = log(&translator(&[2.0, 0.0, 0.0])).unwrap(); // T_a = exp(-a n/2)
/// assert_eq!((l.r, l.t), ([0.0; 3], [-1.0, 0.0, 0.0]));
/// assert!(log(&(translator(&[2.0, 0.0, 0.0]) * 2.0)).is_err());
/// ```
pub fn log<T: Real>(rotor: &Motor<T>) -> Result<Generator<T>, WlError> {
    let m = rotor;
    let bad = || WlError::NotADisplacementRotor { value: m.to_string() };
    if !m.iter().all(Real::is_finite) {
        return Err(bad());
    }
    let tol = tolerance(m.iter());
    let (c, rs) = (m.scalar.clone(), [m.e23.neg_ref(), m.e13.clone(), m.e12.neg_ref()]);
    let s2 = dot(&rs, &rs);
    let off = [
        m.e45.clone(),
        m.e1245.clone(),
        m.e1345.clone(),
        m.e2345.clone(),
        m.e14.sub_ref(&m.e15),
        m.e24.sub_ref(&m.e25),
        m.e34.sub_ref(&m.e35),
        m.e1234.sub_ref(&m.e1235),
        c.mul_ref(&c).add_ref(&s2).sub_ref(&T::one()),
    ];
    if off.iter().any(|x| Real::abs(x) > tol) {
        return Err(bad());
    }
    let half = T::from_ratio(1, 2);
    let avg = |x: &T, y: &T| x.add_ref(y).mul_ref(&half);
    let w = [avg(&m.e14, &m.e15), avg(&m.e24, &m.e25), avg(&m.e34, &m.e35)];
    let q = avg(&m.e1234, &m.e1235);
    let zero = T::zero();
    if s2 > zero {
        let s = Real::sqrt(&s2);
        let phi = s.atan2(&c);
        let inv_s = T::one().div_ref(&s);
        let rh = rs.map(|x| x.mul_ref(&inv_s));
        let wr = dot(&w, &rh);
        let along = c.mul_ref(&wr).sub_ref(&s.mul_ref(&q));
        let f = phi.mul_ref(&inv_s);
        let t = std::array::from_fn(|i| w[i].sub_ref(&wr.mul_ref(&rh[i])).mul_ref(&f).add_ref(&along.mul_ref(&rh[i])));
        return Ok(Generator { r: rh.map(|x| x.mul_ref(&phi)), t });
    }
    if c > zero {
        return Ok(Generator { r: std::array::from_fn(|_| T::zero()), t: w });
    }
    // |φ| = π: R = -(1 + t⊥ n) = -1 - w n with w = -t⊥.
    let rh = super::cga::unit(&w).unwrap_or_else(|| [T::zero(), T::zero(), T::one()]);
    let pi = T::pi();
    Ok(Generator { r: rh.map(|x| x.mul_ref(&pi)), t: w.map(|x| x.neg_ref()) })
}
