//! The path of a body point under the linear interpolation `R_λ = exp(λB)` (W-L Sec. 4.1), in
//! closed form. For `B = φP + tn` (`r = φ â`, [`Generator`]) the rotor factors into commuting
//! pieces, `exp(B) = exp(t⊥ n) T_c exp(φP) rev(T_c)` with the axis point
//! `c = (t∥ ⌋ P)/φ = (t∥ × r)/φ²`, so `exp(λB)` is the screw motion (Chasles) of angle
//! `θ = 2λφ` about the axis `â` through `c`, with the translation `-2λ t⊥` along it:
//! `y(λ) = c + Rot(â, θ)(y - c) - 2λ t⊥`. Without the `1/φ` (so it holds at `φ = 0` and over
//! dual numbers), with `S = sin θ/θ`, `V = (1 - cos θ)/θ²`, `K = (1 - S)/θ²`:
//!
//! ```text
//! y(λ) = y cos θ + 2λ S (r × y) + 4λ² V (r (r·y) + t × r) - 2λ S t - 8λ³ K (t·r) r.
//! ```
//!
//! For `y = 0` this is the paper's `r_λ` (the cylindrical helix of Fig. 7) with its `t⊥` term
//! of sign `-` (the paper's prose has `+λ t⊥`; its `exp(tn/2)` translates by `-t`, see
//! [`super::GeneratorParts`]).
//!
//! ```
//! use motion::wareham_lasenby::{Generator, cga::{embed, embed_inverse}, helix_point};
//! let b = Generator::new([0.2, 0.1, -0.3], [1.0, -1.0, 0.5]);
//! let y = [0.3, 0.4, 0.5];
//! let lambda = 0.7;
//! let by_rotor = embed_inverse(&b.scale(&lambda).exp().unwrap().apply(&embed(&y))).unwrap();
//! let closed = helix_point(&b, &y, &lambda);
//! assert!(by_rotor.iter().zip(&closed).all(|(a, c)| f64::abs(a - c) < 1e-14));
//! ```

use super::Generator;
use super::cga::{cross, dot};
use crate::series::exp_kernel;
use algebra_core::Real;

/// The position at `λ` of the point `y` under `exp(λB)` (module docs): `y(0) = y`, and `y(1)`
/// is the image of `y` under `exp(B)`.
///
/// ```
/// use motion::wareham_lasenby::{Generator, helix_point};
/// // pure translation: exp(λ tn) moves by -2λt
/// assert_eq!(helix_point(&Generator::new([0.0; 3], [1.0, 0.0, 0.0]), &[0.0; 3], &0.5), [-1.0, 0.0, 0.0]);
/// ```
pub fn helix_point<T: Real>(b: &Generator<T>, y: &[T; 3], lambda: &T) -> [T; 3] {
    let two = T::from_i64(2);
    let l2 = lambda.mul_ref(&two);
    let u = dot(&b.r, &b.r).mul_ref(&l2).mul_ref(&l2);
    let [cos, s, _] = exp_kernel(&u);
    let [v, k] = helix_kernel(&u);
    let (txr, tr) = b.cross_dot();
    let rxy = cross(&b.r, y);
    let ry = dot(&b.r, y);
    let a1 = l2.mul_ref(&s);
    let a2 = l2.mul_ref(&l2).mul_ref(&v);
    let a3 = l2.mul_ref(&l2).mul_ref(&l2).mul_ref(&k).mul_ref(&tr);
    std::array::from_fn(|i| {
        let inner = b.r[i].mul_ref(&ry).add_ref(&txr[i]);
        y[i].mul_ref(&cos)
            .add_ref(&a1.mul_ref(&rxy[i]))
            .add_ref(&a2.mul_ref(&inner))
            .sub_ref(&a1.mul_ref(&b.t[i]))
            .sub_ref(&a3.mul_ref(&b.r[i]))
    })
}

/// `[(1 - cos θ)/θ², (1 - sin θ/θ)/θ²]` for `u = θ² ≥ 0`: series `Σ (-u)^k/(2k+2)!` and
/// `Σ (-u)^k/(2k+3)!` for `u ≤ 1` (exact at 0, finite derivatives), closed form above.
fn helix_kernel<T: Real>(u: &T) -> [T; 2] {
    if *u > T::one() {
        let th = Real::sqrt(u);
        let v = T::one().sub_ref(&Real::cos(&th)).div_ref(u);
        let k = T::one().sub_ref(&Real::sin(&th).div_ref(&th)).div_ref(u);
        return [v, k];
    }
    let neg_u = u.neg_ref();
    let (mut tv, mut tk) = (T::from_ratio(1, 2), T::from_ratio(1, 6));
    let (mut v, mut k) = (tv.clone(), tk.clone());
    for j in 1..2000i64 {
        tv = tv.mul_ref(&neg_u).mul_ref(&T::from_ratio(1, (2 * j + 1) * (2 * j + 2)));
        tk = tk.mul_ref(&neg_u).mul_ref(&T::from_ratio(1, (2 * j + 2) * (2 * j + 3)));
        v.add_assign_ref(&tv);
        k.add_assign_ref(&tk);
        let eps = T::from_ratio(1, 16);
        if tv.is_negligible(&eps, 1) && tk.is_negligible(&eps, 1) {
            break;
        }
    }
    [v, k]
}

#[cfg(test)]
mod tests {
    #[test]
    fn helix_kernel_series_meets_closed_form() {
        for u in [0.999_999f64, 1.000_001, 0.25] {
            let [v, k] = super::helix_kernel(&u);
            let th = u.sqrt();
            assert!((v - (1.0 - th.cos()) / u).abs() < 1e-12, "{u}");
            assert!((k - (1.0 - th.sin() / th) / u).abs() < 1e-10, "{u}");
        }
        assert_eq!(super::helix_kernel(&0.0f64), [0.5, 1.0 / 6.0]);
    }
}
