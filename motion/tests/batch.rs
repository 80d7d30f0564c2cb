//! Batches (`motion::batch`): every batch result equals the scalar loop over the same scalar,
//! bit for bit (the kernels run the same operations in the same order), for the scalar lane
//! type `f64`, for a four-lane test type (remainders that are not a multiple of the width),
//! over exact rationals, and for the parallel variants; bad input gives typed errors.

use crate::common;

use algebra_core::rational::{Q, q, ratio};
use algebra_core::{Field, Ring};
use common::{Xorshift as Rng, centered};
use motion::batch::{
    BatchError, Lanes, Points, Poses, Samples, par_sample_beziers, sample, sample_beziers, sample_many,
};
use motion::velocity::{pose_derivative, velocity_indicatrix};
use motion::{AdditiveBezier, Motion, MotionError, MultiplicativeBezier, Pose};
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A four-lane `f64` vector with lane-by-lane IEEE arithmetic: an independent lane type, so
/// the chunking, padding and remainder logic is checked at a width other than one.
#[derive(Clone, Copy, Debug, PartialEq)]
struct X4([f64; 4]);

impl fmt::Display for X4 {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?}", self.0)
    }
}

macro_rules! lanewise {
    ($tr:ident, $m:ident, $op:tt) => {
        impl $tr for X4 {
            type Output = X4;
            fn $m(self, r: X4) -> X4 {
                X4(std::array::from_fn(|i| self.0[i] $op r.0[i]))
            }
        }
        impl $tr<&X4> for X4 {
            type Output = X4;
            fn $m(self, r: &X4) -> X4 {
                X4(std::array::from_fn(|i| self.0[i] $op r.0[i]))
            }
        }
    };
}
lanewise!(Add, add, +);
lanewise!(Sub, sub, -);
lanewise!(Mul, mul, *);
lanewise!(Div, div, /);

impl Neg for X4 {
    type Output = X4;
    fn neg(self) -> X4 {
        X4(self.0.map(|x| -x))
    }
}

impl Ring for X4 {
    fn zero() -> Self {
        X4([0.0; 4])
    }
    fn one() -> Self {
        X4([1.0; 4])
    }
    fn from_i64(n: i64) -> Self {
        X4([f64::from_i64(n); 4])
    }
    fn from_ratio(num: i64, den: i64) -> Self {
        X4([f64::from_ratio(num, den); 4])
    }
    fn from_rational(x: &Q) -> Self {
        X4([f64::from_rational(x); 4])
    }
    fn is_exact_zero(&self) -> bool {
        self.0.iter().all(|x| *x == 0.0)
    }
    fn magnitude(&self) -> f64 {
        self.0.iter().fold(0.0, |m, x| m.max(x.abs()))
    }
    fn relative_epsilon() -> f64 {
        f64::EPSILON
    }
    fn is_finite_value(&self) -> bool {
        self.0.iter().all(|x| x.is_finite())
    }
}

impl Field for X4 {
    fn try_recip(&self) -> Option<Self> {
        self.recip_lanes().ok()
    }
}

impl Lanes for X4 {
    type Elem = f64;
    const WIDTH: usize = 4;
    fn splat(x: &f64) -> Self {
        X4([*x; 4])
    }
    fn load(xs: &[f64]) -> Self {
        X4(std::array::from_fn(|i| xs[i]))
    }
    fn store(&self, out: &mut [f64]) {
        for (o, x) in out.iter_mut().zip(self.0) {
            *o = x;
        }
    }
    fn recip_lanes(&self) -> Result<Self, usize> {
        let r: [Option<f64>; 4] = self.0.map(|x| x.try_recip());
        match r.iter().position(Option::is_none) {
            Some(lane) => Err(lane),
            None => Ok(X4(r.map(|x| x.expect("checked")))),
        }
    }
}

/// Lengths around the lane width and the parallel block (8192 rows).
const LENGTHS: [usize; 7] = [0, 1, 3, 4, 5, 1027, 8192 * 2 + 3];

fn cloud(n: usize, seed: u64) -> Vec<[f64; 3]> {
    let mut rng = Rng(seed);
    (0..n).map(|_| [centered(&mut rng) * 20.0, centered(&mut rng) * 20.0, centered(&mut rng) * 20.0]).collect()
}

/// Non-unit poses (generic screws scaled by a pseudoscalar), `n` of them.
fn poses(n: usize, seed: u64) -> Vec<Pose<f64>> {
    let mut rng = Rng(seed);
    (0..n)
        .map(|_| {
            let axis = [centered(&mut rng), centered(&mut rng), centered(&mut rng) + 0.7];
            let s = Pose::from_axis_angle_translation(
                &axis,
                &(centered(&mut rng) * 6.0),
                &[centered(&mut rng), centered(&mut rng), centered(&mut rng)],
            );
            s.unwrap().scale_pseudoscalar(&motion::Pseudoscalar::new(1.5 + centered(&mut rng), centered(&mut rng)))
        })
        .collect()
}

fn scalar_transform(s: &Pose<f64>, cloud: &[[f64; 3]]) -> Vec<[f64; 3]> {
    cloud.iter().map(|p| s.transform_point(p).unwrap()).collect()
}

#[test]
fn one_pose_on_a_cloud_equals_the_scalar_loop_bit_for_bit() {
    let s = poses(1, 3).pop().unwrap();
    for n in LENGTHS {
        let c = cloud(n, 11 + n as u64);
        let p = Points::from_points(&c).unwrap();
        let want = scalar_transform(&s, &c);
        assert_eq!(p.transform::<f64>(&s).unwrap().to_vec(), want, "f64, n = {n}");
        assert_eq!(p.transform::<X4>(&s).unwrap().to_vec(), want, "X4, n = {n}");
        assert_eq!(p.par_transform::<f64>(&s).unwrap().to_vec(), want, "par f64, n = {n}");
        assert_eq!(p.par_transform::<X4>(&s).unwrap().to_vec(), want, "par X4, n = {n}");
    }
}

#[test]
fn one_pose_on_a_cloud_agrees_with_the_generated_cga_sandwich() {
    // An independent reference: rev(S) x S in G_0123inf with the generated kernels.
    let s = poses(1, 5).pop().unwrap();
    let c = cloud(100, 9);
    let out = Points::from_points(&c).unwrap().par_transform::<X4>(&s).unwrap();
    for (i, p) in c.iter().enumerate() {
        let want = common::cga_null_action(&s, p).0;
        let got = out.get(i).unwrap();
        assert!(common::diff_n(&got, &want) < 1e-12 * 20.0, "{got:?} vs {want:?}");
    }
}

#[test]
fn one_pose_on_rational_points_is_exact() {
    let s =
        Pose::<Q>::rotor_from_parts(&q(2), &q(1), &[q(0), q(1), q(3)]) * Pose::translation(&[ratio(1, 2), q(-3), q(4)]);
    let c: Vec<[Q; 3]> = (0..7).map(|i| [q(i), ratio(i, 3), q(-2 * i)]).collect();
    let p = Points::from_points(&c).unwrap();
    let want: Vec<[Q; 3]> = c.iter().map(|x| s.transform_point(x).unwrap()).collect();
    assert_eq!(p.transform::<Q>(&s).unwrap().to_vec(), want);
    assert_eq!(p.par_transform::<Q>(&s).unwrap().to_vec(), want);
}

#[test]
fn bad_points_and_poses_are_typed_errors() {
    let err = Points::from_columns(vec![1.0, 2.0, 3.0], vec![0.0; 3], vec![0.0; 2]).unwrap_err();
    assert_eq!(err, BatchError::LengthMismatch { what: "z column", expected: 3, got: 2 });
    let err = Points::from_points(&[[0.0; 3], [0.0, f64::NEG_INFINITY, 0.0]]).unwrap_err();
    assert!(matches!(err, BatchError::NotFinite { what: "point", index: 1, .. }), "{err}");
    let p = Points::from_points(&cloud(10, 1)).unwrap();
    let singular = Pose::new(0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0);
    for err in [p.transform::<f64>(&singular).unwrap_err(), p.par_transform::<X4>(&singular).unwrap_err()] {
        assert!(matches!(err, BatchError::Pose { index: 0, source: MotionError::Singular { .. } }), "{err}");
    }
    let nan = Pose::translation(&[f64::NAN, 0.0, 0.0]);
    assert!(matches!(p.transform::<X4>(&nan), Err(BatchError::Pose { source: MotionError::NotFinite { .. }, .. })));
    let mut cols: [Vec<f64>; 8] = Default::default();
    cols[0] = vec![1.0; 4];
    for c in &mut cols[1..] {
        *c = vec![0.0; 4];
    }
    cols[6][2] = f64::NAN;
    assert!(matches!(Poses::from_columns(cols.clone()), Err(BatchError::NotFinite { what: "pose", index: 2, .. })));
    cols[6].pop();
    assert_eq!(
        Poses::from_columns(cols).unwrap_err(),
        BatchError::LengthMismatch { what: "column 6", expected: 4, got: 3 }
    );
}

#[test]
fn pose_i_on_point_i_equals_the_scalar_loop_bit_for_bit() {
    for n in LENGTHS {
        let (s, c) = (poses(n, 21), cloud(n, 22));
        let want: Vec<[f64; 3]> = s.iter().zip(&c).map(|(s, p)| s.transform_point(p).unwrap()).collect();
        let (s, p) = (Poses::from_poses(&s).unwrap(), Points::from_points(&c).unwrap());
        assert_eq!(s.transform_points::<f64>(&p).unwrap().to_vec(), want, "n = {n}");
        assert_eq!(s.transform_points::<X4>(&p).unwrap().to_vec(), want, "X4, n = {n}");
        assert_eq!(s.par_transform_points::<f64>(&p).unwrap().to_vec(), want, "par, n = {n}");
        assert_eq!(s.par_transform_points::<X4>(&p).unwrap().to_vec(), want, "par X4, n = {n}");
    }
}

#[test]
fn pose_i_on_point_i_names_the_first_singular_pose() {
    let n = 20_000;
    let mut s = poses(n, 31);
    let singular = Pose::new(0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0);
    s[12_001] = singular;
    s[5_002] = singular; // lane 2 of its chunk of four, in the first parallel block
    let (s, p) = (Poses::from_poses(&s).unwrap(), Points::from_points(&cloud(n, 32)).unwrap());
    for err in [
        s.transform_points::<f64>(&p).unwrap_err(),
        s.transform_points::<X4>(&p).unwrap_err(),
        s.par_transform_points::<f64>(&p).unwrap_err(),
        s.par_transform_points::<X4>(&p).unwrap_err(),
    ] {
        assert!(matches!(err, BatchError::Pose { index: 5_002, source: MotionError::Singular { .. } }), "{err}");
    }
    let short = Points::from_points(&cloud(n - 1, 1)).unwrap();
    assert_eq!(
        s.transform_points::<X4>(&short).unwrap_err(),
        BatchError::LengthMismatch { what: "points", expected: n, got: n - 1 }
    );
}

#[test]
fn compose_and_lerp_equal_the_scalar_loop_bit_for_bit() {
    for n in LENGTHS {
        let (a, b) = (poses(n, 41), poses(n, 42));
        let product: Vec<Pose<f64>> = a.iter().zip(&b).map(|(a, b)| a * b).collect();
        let lerp: Vec<Pose<f64>> = a.iter().zip(&b).map(|(a, b)| Pose::lerp(a, b, &0.3)).collect();
        let (a, b) = (Poses::from_poses(&a).unwrap(), Poses::from_poses(&b).unwrap());
        assert_eq!(a.compose::<f64>(&b).unwrap().to_vec(), product);
        assert_eq!(a.compose::<X4>(&b).unwrap().to_vec(), product);
        assert_eq!(a.par_compose::<X4>(&b).unwrap().to_vec(), product);
        assert_eq!(a.lerp::<f64>(&b, &0.3).unwrap().to_vec(), lerp);
        assert_eq!(a.lerp::<X4>(&b, &0.3).unwrap().to_vec(), lerp);
        assert_eq!(a.par_lerp::<X4>(&b, &0.3).unwrap().to_vec(), lerp);
    }
}

#[test]
fn composition_applies_the_first_batch_first() {
    // U * V applies U first (Lemma 2.3): checked on points, an independent reading.
    let (a, b, c) = (poses(50, 51), poses(50, 52), cloud(50, 53));
    let ab = Poses::from_poses(&a).unwrap().compose::<X4>(&Poses::from_poses(&b).unwrap()).unwrap();
    for i in 0..50 {
        let want = b[i].transform_point(&a[i].transform_point(&c[i]).unwrap()).unwrap();
        let got = ab.get(i).unwrap().transform_point(&c[i]).unwrap();
        assert!(common::diff_n(&got, &want) < 1e-12 * 40.0, "{got:?} vs {want:?}");
    }
}

#[test]
fn compose_and_lerp_over_rationals_are_exact() {
    let a: Vec<Pose<Q>> = (0..5).map(|i| Pose::rotor_from_parts(&q(1), &ratio(i, 2), &[q(1), q(0), q(i)])).collect();
    let b: Vec<Pose<Q>> = (0..5).map(|i| Pose::translation(&[q(i), ratio(1, i + 1), q(-1)])).collect();
    let (pa, pb) = (Poses::from_poses(&a).unwrap(), Poses::from_poses(&b).unwrap());
    let t = ratio(2, 7);
    let product: Vec<Pose<Q>> = a.iter().zip(&b).map(|(a, b)| a * b).collect();
    let lerp: Vec<Pose<Q>> = a.iter().zip(&b).map(|(a, b)| Pose::lerp(a, b, &t)).collect();
    assert_eq!(pa.par_compose::<Q>(&pb).unwrap().to_vec(), product);
    assert_eq!(pa.lerp::<Q>(&pb, &t).unwrap().to_vec(), lerp);
}

#[test]
fn slerp_equals_the_scalar_loop_and_names_a_failing_element() {
    let n = 9000;
    let (a, mut b) = (common::unit_poses(n - 1), poses(n, 61));
    let want: Vec<Pose<f64>> = a.iter().zip(&b).map(|(a, b)| Pose::slerp(a, b, &0.7).unwrap()).collect();
    let (pa, pb) = (Poses::from_poses(&a).unwrap(), Poses::from_poses(&b).unwrap());
    assert_eq!(pa.slerp(&pb, &0.7).unwrap().to_vec(), want);
    assert_eq!(pa.par_slerp(&pb, &0.7).unwrap().to_vec(), want);
    b[8_500] = Pose::new(0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0);
    let pb = Poses::from_poses(&b).unwrap();
    for err in [pa.slerp(&pb, &0.7).unwrap_err(), pa.par_slerp(&pb, &0.7).unwrap_err()] {
        assert!(matches!(err, BatchError::Pose { index: 8_500, .. }), "{err}");
    }
    assert!(matches!(pa.lerp::<X4>(&pb, &f64::NAN), Err(BatchError::NotFinite { what: "parameter", .. })));
    let short = Poses::from_poses(&b[1..]).unwrap();
    assert!(matches!(pa.compose::<f64>(&short), Err(BatchError::LengthMismatch { expected: 9000, got: 8999, .. })));
}

#[test]
fn packing_into_lanes_and_back_keeps_every_row() {
    for n in [0, 1, 3, 4, 5, 9] {
        let c = cloud(n, 71);
        let p = Points::from_points(&c).unwrap();
        let packed = p.pack::<X4>();
        assert_eq!((packed.len(), packed.chunks()), (n, n.div_ceil(4)));
        assert_eq!(packed.unpack_points(), p);
        if n % 4 != 0 {
            // The remainder chunk: real lanes first, then the padding (the origin).
            let last = packed.chunk(n / 4).unwrap();
            assert_eq!(last[0].0[..n % 4], p.x()[n - n % 4..]);
            assert!(last[1].0[n % 4..].iter().all(|x| *x == 0.0));
        }
        let s = Poses::from_poses(&poses(n, 72)).unwrap();
        let packed = s.pack::<X4>();
        assert_eq!(packed.unpack_poses(), s);
        if n % 4 != 0 {
            let last = packed.chunk(n / 4).unwrap();
            assert!(last[0].0[n % 4..].iter().all(|x| *x == 1.0), "identity padding");
            assert_eq!(packed.column(3).len(), n.div_ceil(4));
        }
    }
}

fn cubic_motions(n: usize, seed: u64) -> Vec<AdditiveBezier<f64>> {
    (0..n).map(|i| AdditiveBezier::new(poses(4, seed + i as u64)).unwrap()).collect()
}

fn parameters(n: usize) -> Vec<f64> {
    (0..n).map(|k| k as f64 / (n - 1).max(1) as f64).collect()
}

fn check_samples(s: &Samples<f64>, motions: &[AdditiveBezier<f64>], ts: &[f64]) {
    assert_eq!((s.motions(), s.parameters()), (motions.len(), ts.len()));
    for (m, motion) in motions.iter().enumerate() {
        for (k, t) in ts.iter().enumerate() {
            let (p, dp) = pose_derivative(motion, t).unwrap();
            assert_eq!(s.pose(m, k), Some(p), "motion {m}, t = {t}");
            assert_eq!(s.derivative(m, k), Some(dp), "motion {m}, t = {t}");
        }
    }
}

#[test]
fn sampling_many_motions_equals_pose_derivative_bit_for_bit() {
    let motions = cubic_motions(13, 81);
    for nt in [1, 4, 7, 100] {
        let ts = parameters(nt);
        check_samples(&sample_many::<f64, _>(&motions, &ts).unwrap(), &motions, &ts);
        check_samples(&sample_many::<X4, _>(&motions, &ts).unwrap(), &motions, &ts);
        check_samples(&motion::batch::par_sample_many::<X4, _>(&motions, &ts).unwrap(), &motions, &ts);
    }
}

#[test]
fn sampling_with_motions_across_lanes_equals_pose_derivative_bit_for_bit() {
    // motion counts around the width 4 (a padded last group), and a group mixing degrees
    // (cubic and quadratic: sampled motion by motion)
    for n in [1, 3, 4, 9] {
        let motions = cubic_motions(n, 85);
        for nt in [1, 7] {
            let ts = parameters(nt);
            check_samples(&sample_beziers::<X4, _>(&motions, &ts).unwrap(), &motions, &ts);
            check_samples(&par_sample_beziers::<X4, _>(&motions, &ts).unwrap(), &motions, &ts);
            check_samples(&sample_beziers::<f64, _>(&motions, &ts).unwrap(), &motions, &ts);
        }
    }
    let mut mixed = cubic_motions(6, 87);
    mixed[2] = AdditiveBezier::new(poses(3, 89)).unwrap();
    let ts = parameters(5);
    check_samples(&sample_beziers::<X4, _>(&mixed, &ts).unwrap(), &mixed, &ts);
    assert_eq!(sample_beziers::<X4, _>(&mixed, &[]).unwrap().poses().len(), 0);
}

#[test]
fn sampling_with_motions_across_lanes_names_the_first_failure() {
    let motions = cubic_motions(10, 99);
    let ts = [0.0, 0.5, f64::NAN, 2.0];
    for err in
        [sample_beziers::<X4, _>(&motions, &ts).unwrap_err(), par_sample_beziers::<X4, _>(&motions, &ts).unwrap_err()]
    {
        assert!(matches!(err, BatchError::Curve { motion: 0, parameter: 2, .. }), "{err}");
    }
}

#[test]
fn sampled_derivatives_agree_with_central_differences() {
    // An independent check of dS/dt: (S(t + h) - S(t - h)) / 2h for the cubic, to h².
    let motions = cubic_motions(3, 91);
    let ts = [0.2, 0.5, 0.9];
    let s = sample_many::<X4, _>(&motions, &ts).unwrap();
    let h = 1e-5;
    for (m, motion) in motions.iter().enumerate() {
        for (k, t) in ts.iter().enumerate() {
            let fd = (motion.evaluate(&(t + h)).unwrap() - motion.evaluate(&(t - h)).unwrap()).scale(&(0.5 / h));
            assert!(common::diff(&s.derivative(m, k).unwrap(), &fd) < 1e-8);
        }
    }
}

#[test]
fn sampling_values_and_indicatrices_equal_the_scalar_code() {
    let motions = cubic_motions(2, 95);
    let ts = parameters(11);
    for motion in &motions {
        let want: Vec<Pose<f64>> = ts.iter().map(|t| motion.pose(t).unwrap()).collect();
        assert_eq!(sample::<f64, _>(motion, &ts).unwrap().to_vec(), want);
        assert_eq!(sample::<X4, _>(motion, &ts).unwrap().to_vec(), want);
    }
    let psi = sample_many::<X4, _>(&motions, &ts).unwrap().indicatrices().unwrap();
    for (m, motion) in motions.iter().enumerate() {
        for (k, t) in ts.iter().enumerate() {
            assert_eq!(psi.get(m * ts.len() + k), Some(velocity_indicatrix(motion, t).unwrap()));
        }
    }
    // Multiplicative motions run over the scalar lane type (their slerps branch on values).
    let mul = MultiplicativeBezier::new(common::unit_poses(4)).unwrap();
    let s = sample_many::<f64, _>(std::slice::from_ref(&mul), &ts).unwrap();
    for (k, t) in ts.iter().enumerate() {
        let (p, dp) = pose_derivative(&mul, t).unwrap();
        assert_eq!((s.pose(0, k), s.derivative(0, k)), (Some(p), Some(dp)));
    }
}

#[test]
fn sampling_outside_the_domain_names_motion_and_parameter() {
    let motions = cubic_motions(30, 99);
    let ts = [0.0, 0.5, f64::NAN, 2.0];
    for err in [
        sample_many::<X4, _>(&motions, &ts).unwrap_err(),
        motion::batch::par_sample_many::<f64, _>(&motions, &ts).unwrap_err(),
    ] {
        assert!(matches!(err, BatchError::Curve { motion: 0, parameter: 2, .. }), "{err}");
    }
    assert!(matches!(sample::<X4, _>(&motions[0], &[1.5]), Err(BatchError::Curve { parameter: 0, .. })));
}

#[test]
fn sampling_reports_a_singular_sample() {
    // S(t) = (1 - t) + t (-1): singular at t = 1/2, so Ψ there is an error naming the row.
    let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::identity().scale(&-1.0)]).unwrap();
    let s = sample_many::<X4, _>(&[m], &[0.0, 0.25, 0.5, 1.0]).unwrap();
    assert!(matches!(s.indicatrices(), Err(BatchError::Pose { index: 2, source: MotionError::Singular { .. } })));
}

/// The batch kernels over a SIMD lane type `L` against the scalar loop over its element type,
/// bit for bit, at every length (remainders included), serial and parallel.
fn check_simd<L: Lanes>(to_elem: impl Fn(f64) -> L::Elem)
where
    L::Elem: algebra_core::Real + PartialOrd + Copy,
{
    let conv_pose = |s: &Pose<f64>| s.map_scalar(&|x: &f64| to_elem(*x));
    let conv_point = |p: &[f64; 3]| p.map(&to_elem);
    let t = to_elem(0.3);
    for n in LENGTHS {
        let (a, b, c) = (poses(n, 101), poses(n, 102), cloud(n, 103));
        let a: Vec<Pose<L::Elem>> = a.iter().map(conv_pose).collect();
        let b: Vec<Pose<L::Elem>> = b.iter().map(conv_pose).collect();
        let c: Vec<[L::Elem; 3]> = c.iter().map(conv_point).collect();
        let one: Vec<[L::Elem; 3]> = c.iter().map(|p| a[0].transform_point(p).unwrap()).collect();
        let each: Vec<[L::Elem; 3]> = a.iter().zip(&c).map(|(s, p)| s.transform_point(p).unwrap()).collect();
        let product: Vec<Pose<L::Elem>> = a.iter().zip(&b).map(|(x, y)| x * y).collect();
        let lerp: Vec<Pose<L::Elem>> = a.iter().zip(&b).map(|(x, y)| Pose::lerp(x, y, &t)).collect();
        let (pa, pb, pc) =
            (Poses::from_poses(&a).unwrap(), Poses::from_poses(&b).unwrap(), Points::from_points(&c).unwrap());
        if n > 0 {
            assert_eq!(pc.transform::<L>(&a[0]).unwrap().to_vec(), one, "n = {n}");
            assert_eq!(pc.par_transform::<L>(&a[0]).unwrap().to_vec(), one, "n = {n}");
        }
        assert_eq!(pa.transform_points::<L>(&pc).unwrap().to_vec(), each, "n = {n}");
        assert_eq!(pa.par_transform_points::<L>(&pc).unwrap().to_vec(), each, "n = {n}");
        assert_eq!(pa.compose::<L>(&pb).unwrap().to_vec(), product, "n = {n}");
        assert_eq!(pa.par_lerp::<L>(&pb, &t).unwrap().to_vec(), lerp, "n = {n}");
        assert_eq!(pc.pack::<L>().unpack_points(), pc);
        assert_eq!(pa.pack::<L>().unpack_poses(), pa);
    }
    let motions: Vec<AdditiveBezier<L::Elem>> = cubic_motions(5, 111)
        .iter()
        .map(|m| AdditiveBezier::new(m.poses().iter().map(conv_pose).collect()).unwrap())
        .collect();
    for nt in [1, 3, 10] {
        let ts: Vec<L::Elem> = parameters(nt).into_iter().map(&to_elem).collect();
        let s = motion::batch::par_sample_many::<L, _>(&motions, &ts).unwrap();
        let across = sample_beziers::<L, _>(&motions, &ts).unwrap();
        for (m, motion) in motions.iter().enumerate() {
            for (k, t) in ts.iter().enumerate() {
                let (p, dp) = pose_derivative(motion, t).unwrap();
                assert_eq!((s.pose(m, k), s.derivative(m, k)), (Some(p), Some(dp)));
                assert_eq!((across.pose(m, k), across.derivative(m, k)), (Some(p), Some(dp)));
            }
        }
    }
}

#[test]
fn simd_lane_types_equal_the_scalar_loop_bit_for_bit() {
    use algebra_core::scalar::{F32x4, F32x8, F64x2, F64x4};
    check_simd::<F64x2>(|x| x);
    check_simd::<F64x4>(|x| x);
    check_simd::<F32x4>(|x| x as f32);
    check_simd::<F32x8>(|x| x as f32);
}

#[test]
fn simd_lanes_name_the_singular_lane() {
    use algebra_core::scalar::F64x4;
    let singular = Pose::new(0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0);
    for i in [0, 1, 2, 3, 6, 9] {
        let mut s = poses(10, 121);
        s[i] = singular;
        let (s, p) = (Poses::from_poses(&s).unwrap(), Points::from_points(&cloud(10, 122)).unwrap());
        let err = s.transform_points::<F64x4>(&p).unwrap_err();
        assert!(matches!(err, BatchError::Pose { index, .. } if index == i), "{err}");
    }
}

#[test]
fn slerp_over_lanes_agrees_with_the_scalar_slerp_with_mixed_edge_cases() {
    use algebra_core::scalar::{F64x2, F64x4};
    // Generic pairs, with every third pair an edge case: equal poses (zero relative angle), a
    // pure translation, a relative half turn minus a little.
    let n = 8192 + 7;
    let (a, mut b) = (poses(n, 131), poses(n, 132));
    for i in (0..n).step_by(3) {
        match (i / 3) % 3 {
            0 => b[i] = a[i],
            1 => b[i] = a[i] * Pose::translation(&[1.0, -2.0, 0.5]),
            _ => b[i] = a[i] * Pose::rotation(&[0.0, 1.0, 0.0], &(std::f64::consts::PI - 1e-6)).unwrap(),
        }
    }
    let want: Vec<Pose<f64>> = a.iter().zip(&b).map(|(x, y)| Pose::slerp(x, y, &0.3).unwrap()).collect();
    let (pa, pb) = (Poses::from_poses(&a).unwrap(), Poses::from_poses(&b).unwrap());
    for got in [
        pa.slerp_lanes::<f64>(&pb, &0.3).unwrap(),
        pa.slerp_lanes::<F64x2>(&pb, &0.3).unwrap(),
        pa.par_slerp_lanes::<F64x4>(&pb, &0.3).unwrap(),
    ] {
        for (i, w) in want.iter().enumerate() {
            let g = got.get(i).unwrap();
            assert!(common::diff(&g, w) <= 1e-12 * common::size(w).max(1.0), "{i}: {g} vs {w}");
        }
    }
    b[4_001] = Pose::new(0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0);
    let pb = Poses::from_poses(&b).unwrap();
    for err in [pa.slerp_lanes::<F64x4>(&pb, &0.3).unwrap_err(), pa.par_slerp_lanes::<F64x2>(&pb, &0.3).unwrap_err()] {
        assert!(matches!(err, BatchError::Pose { index: 4_001, .. }), "{err}");
    }
}
