//! Helpers shared by the motion tests: component-wise distances, sample poses, and the
//! independent references (Rodrigues' formula, the generated G_{0123inf} sandwich).
#![allow(dead_code)]

use algebra_core::{Real, Ring};
use gam_algebras::cga_null;
use motion::{Bivector, Even, Pose, Pseudoscalar};

/// Even elements and bivectors, compared through their embedding in G_{123inf}^+.
pub trait AsEven<T> {
    /// The element as an even element.
    fn to_even(&self) -> Even<T>;
}

impl<T: Ring> AsEven<T> for Even<T> {
    fn to_even(&self) -> Even<T> {
        self.clone()
    }
}

impl<T: Ring> AsEven<T> for Bivector<T> {
    fn to_even(&self) -> Even<T> {
        Even::from(self)
    }
}

/// The largest component of `a - b`.
pub fn diff<T: Ring, A: AsEven<T>, B: AsEven<T>>(a: &A, b: &B) -> f64 {
    let d = &a.to_even() - &b.to_even();
    [&d.scalar, &d.e12, &d.e13, &d.e23, &d.e1inf, &d.e2inf, &d.e3inf, &d.e123inf]
        .into_iter()
        .map(Ring::magnitude)
        .fold(0.0, f64::max)
}

/// The largest component of `a`.
pub fn size<T: Ring, A: AsEven<T>>(a: &A) -> f64 {
    diff(&a.to_even(), &Even::zero())
}

/// The largest entry of `a - b` for arrays.
pub fn diff_n<T: Ring, const N: usize>(a: &[T; N], b: &[T; N]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x.sub_ref(y).magnitude()).fold(0.0, f64::max)
}

/// An exact-constant vector (a/d, b/d, c/d).
pub fn v3<T: Ring>(a: i64, b: i64, c: i64, d: i64) -> [T; 3] {
    [T::from_ratio(a, d), T::from_ratio(b, d), T::from_ratio(c, d)]
}

/// R T for an axis, angle and translation given as ratios (works over every Real).
pub fn screw<T: Real>(axis: [i64; 3], angle: T, t: [i64; 3], den: i64) -> Pose<T> {
    Pose::from_axis_angle_translation(&v3(axis[0], axis[1], axis[2], 1), &angle, &v3(t[0], t[1], t[2], den)).unwrap()
}

/// Rodrigues: p cos φ + (a × p) sin φ + a (a·p)(1 - cos φ) for a unit axis a, plus v.
pub fn rodrigues(axis: [f64; 3], phi: f64, v: [f64; 3], p: [f64; 3]) -> [f64; 3] {
    let n = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
    let a = axis.map(|x| x / n);
    let (c, s) = (phi.cos(), phi.sin());
    let cross = [a[1] * p[2] - a[2] * p[1], a[2] * p[0] - a[0] * p[2], a[0] * p[1] - a[1] * p[0]];
    let ap = a[0] * p[0] + a[1] * p[1] + a[2] * p[2];
    std::array::from_fn(|i| p[i] * c + cross[i] * s + a[i] * ap * (1.0 - c) + v[i])
}

/// `F_S(p)` computed independently: the generated G_{0123inf} (product basis) sandwich
/// `rev(S)(e0 + p)S`, then P (divide e1, e2, e3 by e0). Also returns the e0 coefficient.
pub fn cga_null_action<T: algebra_core::Field>(s: &Pose<T>, p: &[T; 3]) -> ([T; 3], T) {
    let m = s.clone();
    let big = cga_null::Motor::new(m.scalar, m.e12, m.e13, m.e23, m.e1inf, m.e2inf, m.e3inf, m.e123inf);
    let x = cga_null::Vector::new(T::one(), p[0].clone(), p[1].clone(), p[2].clone(), T::zero());
    let y = big.sandwich(&x);
    let w = y.e0.clone();
    ([y.e1.div_ref(&w), y.e2.div_ref(&w), y.e3.div_ref(&w)], w)
}

/// A spread of f64 poses: unit and non-unit, all rotation angles, with translations.
pub fn sample_poses() -> Vec<Pose<f64>> {
    let mut out = Vec::new();
    for (axis, phi, t) in [
        ([0.0, 0.0, 1.0], 0.0, [0.0, 0.0, 0.0]),
        ([1.0, 2.0, 3.0], 0.7, [1.0, -2.0, 0.5]),
        ([0.0, 1.0, 0.0], std::f64::consts::PI, [3.0, 0.0, -1.0]),
        ([1.0, 1.0, 0.0], 2.5, [0.0, 0.0, 10.0]),
        ([-1.0, 0.5, 2.0], 4.0, [-3.0, 2.0, 1.0]),
        ([0.3, -0.2, 0.9], 1e-9, [5.0, 5.0, 5.0]),
        ([1.0, 0.0, 0.0], 6.0, [0.1, 0.2, 0.3]),
    ] {
        let s = Pose::from_axis_angle_translation(&axis, &phi, &t).unwrap();
        out.push(s);
        out.push(s.scale_pseudoscalar(&motion::Pseudoscalar::new(-1.7, 0.4)));
    }
    out
}

/// `n + 1` unit poses of a varied motion (all rotation angles below π between neighbours).
pub fn unit_poses(n: usize) -> Vec<Pose<f64>> {
    (0..=n)
        .map(|i| {
            let x = i as f64;
            Pose::from_axis_angle_translation(
                &[1.0 + 0.3 * x, -0.5 + x * x * 0.1, 0.7 - 0.2 * x],
                &(0.4 + 0.35 * x),
                &[x, 1.5 - 0.5 * x * x, 0.3 * x],
            )
            .unwrap()
        })
        .collect()
}

/// The same poses multiplied by varied non-singular pseudoscalars (non-unit, equivalent).
pub fn non_unit(poses: &[Pose<f64>]) -> Vec<Pose<f64>> {
    poses
        .iter()
        .enumerate()
        .map(|(i, p)| p.scale_pseudoscalar(&Pseudoscalar::new(1.3 + 0.4 * i as f64, 0.5 - 0.3 * i as f64)))
        .collect()
}

// ---------------------------------------------------------------- dual-number references
// Independent evaluations of Bézier motions over `Dual64` (a local Bernstein sum and a local
// slerp tableau), used to check end indicatrices of constructed segments.

/// A pose lifted to constant dual numbers.
pub fn lift(s: &Pose<f64>) -> Pose<num_dual::Dual64> {
    s.map_scalar(&|x: &f64| num_dual::Dual64::from(*x))
}

/// The value and the derivative (ε part) of a pose over dual numbers.
pub fn value_and_derivative(s: &Pose<num_dual::Dual64>) -> (Pose<f64>, Even<f64>) {
    let m = s;
    let parts = [&m.scalar, &m.e12, &m.e13, &m.e23, &m.e1inf, &m.e2inf, &m.e3inf, &m.e123inf];
    let mk = |c: [f64; 8]| Even::new(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]);
    ((mk(parts.map(|x| x.re))), mk(parts.map(|x| x.eps)))
}

/// `Ψ(t) = 2 S(t)⁻¹ S'(t)` of a pose evaluated over a dual number `t + ε`.
pub fn indicatrix(s: &Pose<num_dual::Dual64>) -> Even<f64> {
    let (value, derivative) = value_and_derivative(s);
    (value.try_inverse().unwrap() * derivative).scale(&2.0)
}

/// The binomial coefficient as a float.
pub fn binomial(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
}

/// The additive Bézier motion (eq. 18) by its Bernstein sum, over dual numbers.
pub fn bernstein(controls: &[Pose<f64>], t: &num_dual::Dual64) -> Pose<num_dual::Dual64> {
    use num_dual::DualNum;
    let n = controls.len() - 1;
    let one_minus = num_dual::Dual64::from(1.0) - *t;
    let mut sum = Even::<num_dual::Dual64>::zero();
    for (i, c) in controls.iter().enumerate() {
        let w = one_minus.powi((n - i) as i32) * t.powi(i as i32) * binomial(n, i);
        sum += lift(c).scale(&w);
    }
    sum
}

/// The multiplicative Bézier motion by its de Casteljau tableau of slerps (Fig. 2).
pub fn de_casteljau(controls: &[Pose<f64>], t: &num_dual::Dual64) -> Pose<num_dual::Dual64> {
    let mut level: Vec<Pose<num_dual::Dual64>> = controls.iter().map(lift).collect();
    while level.len() > 1 {
        level = level.windows(2).map(|w| Pose::slerp(&w[0], &w[1], t).unwrap()).collect();
    }
    level.pop().unwrap()
}

/// The workspace's deterministic generator (`algebra_core::test_support`).
#[allow(unused_imports)] // not every test file of this crate draws random instances
pub use algebra_core::test_support::Xorshift;

/// The next value of `rng` in [-0.5, 0.5).
#[allow(dead_code)] // not every test file of this crate draws random instances
pub fn centered(rng: &mut Xorshift) -> f64 {
    rng.unit() - 0.5
}

/// Generators `σ + θ n e123 + c einf + p ω` at each half-angle `θ` of `halves`, six per angle
/// with random unit axes `n` (from `rng`), translations up to 2 (10⁴ for every sixth), and,
/// with `non_unit`, a scale `σ` and a pseudoscalar part `p` for every second. The draws per
/// angle are fixed, so appending half-angles keeps the earlier generators.
pub fn generators_at(rng: &mut algebra_core::test_support::Xorshift, halves: &[f64], non_unit: bool) -> Vec<Even<f64>> {
    let mut out = Vec::new();
    for &half in halves {
        for k in 0..6 {
            let mut d = || rng.symmetric();
            let n = [d(), d(), d() + 0.1];
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            let a = n.map(|x| half * x / len);
            let big = if k == 5 { 1e4 } else { 2.0 };
            let c = [big * d(), big * d(), big * d()];
            let (sigma, p) = if non_unit && k % 2 == 1 { (0.5 * d(), d()) } else { (0.0, 0.0) };
            out.push(Even::new(sigma, a[2], -a[1], a[0], c[0], c[1], c[2], p));
        }
    }
    out
}
