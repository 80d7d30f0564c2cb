//! The branch-free exp, log, log_shortest, power and slerp over lanes (`F64x4`, `F64x2`,
//! `F32x8`, `F32x4`) against the `Real` versions (`Pose::exp`, `Pose::log`, ...) over the
//! scalar, lane by lane: to 1e-12 (f64) and 1e-5 (f32), relative to max(1, |value|), in vectors
//! that mix lanes hitting the edge cases (zero angle, pure translation, the series thresholds
//! θ² = 1 and s² = 1/4, angle π, full turn with and without translation, u0 < 0, non-unit
//! poses) with generic lanes. Derivatives through `LaneDual` over lanes against `Jet` over
//! f64, and errors decided over the whole vector.

use algebra_core::scalar::{F32x4, F32x8, F64x2, F64x4, LaneDual, LaneReal};
use algebra_core::{Jet, Real};
use motion::{Even, MotionError, Pose};
use std::f64::consts::{FRAC_PI_2, PI};

/// A lane type built from f64 lane values, read back as its scalar element.
trait Lanes: LaneReal + Copy {
    type E: Real + Copy + Into<f64>;
    const N: usize;
    const TOL: f64;
    fn from_fn(f: impl FnMut(usize) -> f64) -> Self;
    fn get(&self, i: usize) -> Self::E;
    fn elem(x: f64) -> Self::E;
}

macro_rules! lanes {
    ($t:ident, $e:ident, $n:literal, $tol:literal) => {
        impl Lanes for $t {
            type E = $e;
            const N: usize = $n;
            const TOL: f64 = $tol;
            fn from_fn(mut f: impl FnMut(usize) -> f64) -> Self {
                $t::from_fn(|i| f(i) as $e)
            }
            fn get(&self, i: usize) -> $e {
                self.lane(i)
            }
            fn elem(x: f64) -> $e {
                x as $e
            }
        }
    };
}
lanes!(F64x4, f64, 4, 1e-12);
lanes!(F64x2, f64, 2, 1e-12);
lanes!(F32x8, f32, 8, 1e-5);
lanes!(F32x4, f32, 4, 1e-5);

fn ev(c: [f64; 8]) -> Even<f64> {
    Even::new(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7])
}

/// Generators `σ + B + pω` as components, edge cases interleaved with generic ones.
fn generators() -> Vec<[f64; 8]> {
    vec![
        [0.0; 8],                                        // zero: the identity
        [0.2, 0.4, -1.3, 0.7, 0.5, -0.1, 0.9, 0.1],      // generic
        [0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.5, 0.0],        // pure translation
        [0.0, 2.5, 0.3, -0.4, 1.0, 2.0, -3.0, 0.0],      // generic, large angle
        [0.0, 1.0, 0.0, 0.0, 0.3, 0.2, 0.1, 0.0],        // θ² = 1: the series threshold
        [-0.3, -0.6, 0.2, 0.25, 0.0, 0.4, 0.0, -0.2],    // generic
        [0.0, FRAC_PI_2, 0.0, 0.0, 0.3, -0.2, 0.7, 0.0], // rotation by π
        [0.1, 0.05, 0.02, -0.03, 2.0, 0.0, 1.0, 0.3],    // generic, small angle
        [0.0, 0.0, 0.0, PI, 0.3, 0.1, -0.2, 0.0],        // a full turn (half-angle π)
        [0.0, -1.1, 0.9, 0.4, -0.2, 0.3, 0.5, 0.0],      // generic
        [0.0, 1e-9, 0.0, 0.0, 1.0, 2.0, 3.0, 0.0],       // tiny angle
        [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.7],        // ω only
    ]
}

/// Poses for log: the exps of the generators, and poses hitting the log's own edge cases.
fn poses() -> Vec<Pose<f64>> {
    let h = 3f64.sqrt() / 2.0;
    let mut out = vec![
        Pose::identity(),
        Pose::new(0.0, 1.0, 0.0, 0.0, 0.3, -0.2, 0.0, 0.0), // u0 = 0: angle π exactly
        Pose::new(-1.0, 0.0, 0.0, 0.0, 0.3, 0.1, -0.2, 0.0), // full turn with a translation
        Pose::new(h, 0.5, 0.0, 0.0, 0.1, 0.2, 0.3, 0.0),    // s² = 1/4: the series threshold
        Pose::new(-1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0), // full turn, no translation (axis e3)
        Pose::new(-0.6, 0.48, 0.64, 0.0, 0.2, -0.7, 0.1, 0.3), // u0 < 0
        Pose::new(-3.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0), // non-unit full turn
        Pose::translation(&[1.0, -2.0, 0.5]),
    ];
    for (k, g) in generators().into_iter().enumerate() {
        let s = Pose::exp(&ev(g)).unwrap();
        // every other one non-unit
        out.push(if k % 2 == 0 { s.scale(&(1.0 + k as f64)) } else { s });
    }
    out
}

fn pack<L: Lanes>(cases: &[[f64; 8]]) -> Pose<L> {
    let c: [L; 8] = std::array::from_fn(|k| L::from_fn(|i| cases[i % cases.len()][k]));
    let [s, b12, b13, b23, b1, b2, b3, w] = c;
    Pose::new(s, b12, b13, b23, b1, b2, b3, w)
}

fn unpack<L: Lanes>(p: &Pose<L>, i: usize) -> Pose<L::E> {
    let c = p.components().map(|x| x.get(i));
    Pose::new(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7])
}

fn scalar<L: Lanes>(c: &[f64; 8]) -> Pose<L::E> {
    Pose::new(
        L::elem(c[0]),
        L::elem(c[1]),
        L::elem(c[2]),
        L::elem(c[3]),
        L::elem(c[4]),
        L::elem(c[5]),
        L::elem(c[6]),
        L::elem(c[7]),
    )
}

fn assert_lane_eq<L: Lanes>(what: &str, lanes: &Pose<L>, i: usize, want: &Pose<L::E>) {
    let got = unpack(lanes, i);
    for (k, (g, w)) in got.components().into_iter().zip(want.components()).enumerate() {
        let (g, w): (f64, f64) = ((*g).into(), (*w).into());
        assert!((g - w).abs() <= L::TOL * w.abs().max(1.0), "{what}, lane {i}, component {k}: {g} vs {w}");
    }
}

/// Runs `check` on every chunk of `L::N` cases (the last chunk wrapping around).
fn chunks<L: Lanes>(cases: &[[f64; 8]], mut check: impl FnMut(&[[f64; 8]], Pose<L>)) {
    for start in (0..cases.len()).step_by(L::N) {
        let chunk: Vec<[f64; 8]> = (0..L::N).map(|i| cases[(start + i) % cases.len()]).collect();
        check(&chunk, pack::<L>(&chunk));
    }
}

fn exp_matches<L: Lanes>() {
    chunks::<L>(&generators(), |chunk, g| {
        let e = Pose::exp_branch_free(&g).unwrap();
        for (i, c) in chunk.iter().enumerate() {
            assert_lane_eq("exp", &e, i, &Pose::exp(&scalar::<L>(c)).unwrap());
        }
    });
}

fn log_matches<L: Lanes>() {
    let cases: Vec<[f64; 8]> = poses().iter().map(|p| p.components().map(|x| *x)).collect();
    chunks::<L>(&cases, |chunk, s| {
        let (l, short) = (s.log_branch_free().unwrap(), s.log_shortest_branch_free().unwrap());
        for (i, c) in chunk.iter().enumerate() {
            let p = scalar::<L>(c);
            assert_lane_eq("log", &l, i, &p.log().unwrap());
            assert_lane_eq("log_shortest", &short, i, &p.log_shortest().unwrap());
        }
    });
}

fn power_and_slerp_match<L: Lanes>() {
    let cases: Vec<[f64; 8]> = poses().iter().map(|p| p.components().map(|x| *x)).collect();
    let ts = [0.3, 0.5, -0.7, 1.5, 0.0, 1.0, 2.0, 0.25];
    chunks::<L>(&cases, |chunk, a| {
        let t = L::from_fn(|i| ts[i % ts.len()]);
        let next: Vec<[f64; 8]> = (0..L::N).map(|i| chunk[(i + 1) % L::N]).collect();
        let b = pack::<L>(&next);
        let (pw, sl) = (a.power_branch_free(&t).unwrap(), Pose::slerp_branch_free(&a, &b, &t).unwrap());
        for i in 0..L::N {
            let (sa, sb, st) = (scalar::<L>(&chunk[i]), scalar::<L>(&next[i]), t.get(i));
            assert_lane_eq("power", &pw, i, &sa.power(&st).unwrap());
            assert_lane_eq("slerp", &sl, i, &Pose::slerp(&sa, &sb, &st).unwrap());
        }
    });
}

#[test]
fn exp_over_lanes_is_the_scalar_exp_lane_by_lane() {
    exp_matches::<F64x4>();
    exp_matches::<F64x2>();
    exp_matches::<F32x8>();
    exp_matches::<F32x4>();
}

#[test]
fn log_over_lanes_is_the_scalar_log_lane_by_lane() {
    log_matches::<F64x4>();
    log_matches::<F64x2>();
    log_matches::<F32x8>();
    log_matches::<F32x4>();
}

#[test]
fn power_and_slerp_over_lanes_are_the_scalar_ones_lane_by_lane() {
    power_and_slerp_match::<F64x4>();
    power_and_slerp_match::<F32x8>();
}

#[test]
fn over_f64_the_branch_free_forms_are_the_real_ones() {
    for g in generators() {
        let e = Pose::exp_branch_free(&ev(g)).unwrap();
        let want = Pose::exp(&ev(g)).unwrap();
        assert!((e - want).components().iter().all(|x| x.abs() < 1e-15), "{g:?}");
    }
    for p in poses() {
        let (l, want) = (p.log_branch_free().unwrap(), p.log().unwrap());
        assert!((l - want).components().iter().all(|x| x.abs() <= 1e-15 * want.scalar.abs().max(1.0)), "{p}");
    }
}

#[test]
fn derivatives_through_lane_duals_are_the_jet_derivatives() {
    // d/dt exp(t g) and d/dt log(exp(t g)) at t = 0.7, four generators in one vector
    let gens = generators();
    let t0 = 0.7;
    for start in [0, 4, 8] {
        let chunk = &gens[start..start + 4];
        let comp = |k: usize| LaneDual::new(F64x4::from_fn(|i| t0 * chunk[i][k]), F64x4::from_fn(|i| chunk[i][k]));
        let g = Pose::new(comp(0), comp(1), comp(2), comp(3), comp(4), comp(5), comp(6), comp(7));
        let e = Pose::exp_branch_free(&g).unwrap();
        let l = e.log_shortest_branch_free().unwrap();
        for (i, c) in chunk.iter().enumerate() {
            let j = |k: usize| Jet::new(t0 * c[k], c[k]);
            let gs = Pose::new(j(0), j(1), j(2), j(3), j(4), j(5), j(6), j(7));
            let es = Pose::exp(&gs).unwrap();
            let ls = es.log_shortest().unwrap();
            for (got, want) in [(&e, &es), (&l, &ls)] {
                for (x, y) in got.components().into_iter().zip(want.components()) {
                    assert!((x.re.lane(i) - y.re).abs() < 1e-12, "value lane {i}: {} vs {}", x.re.lane(i), y.re);
                    assert!(
                        (x.eps.lane(i) - y.eps).abs() < 1e-12,
                        "derivative lane {i}: {} vs {}",
                        x.eps.lane(i),
                        y.eps
                    );
                }
            }
        }
    }
}

#[test]
fn one_bad_lane_fails_the_call_with_that_lanes_error() {
    let mut cases: Vec<[f64; 8]> = generators()[..4].to_vec();
    cases[2][4] = f64::NAN;
    let g = pack::<F64x4>(&cases);
    assert!(matches!(Pose::exp_branch_free(&g), Err(MotionError::NotFinite { op: "exp", .. })));
    assert!(matches!(Pose::exp(&ev(cases[2])), Err(MotionError::NotFinite { op: "exp", .. })));
    // a zero pose in one lane: singular, as the scalar log says
    let mut cases: Vec<[f64; 8]> = poses()[..4].iter().map(|p| p.components().map(|x| *x)).collect();
    cases[1] = [0.0; 8];
    let s = pack::<F64x4>(&cases);
    assert!(matches!(s.log_branch_free(), Err(MotionError::Singular { op: "log", .. })));
    assert!(matches!(ev(cases[1]).log(), Err(MotionError::Singular { op: "log", .. })));
    // overflow in one lane
    let mut cases: Vec<[f64; 8]> = generators()[..4].to_vec();
    cases[3][0] = 800.0;
    assert!(Pose::exp_branch_free(&pack::<F64x4>(&cases)).is_err() && Pose::exp(&ev(cases[3])).is_err());
}
