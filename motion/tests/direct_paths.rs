//! The pose layer's direct paths (issue 31): at `f64` the ordinary inputs of `Pose::exp`,
//! `log`, `transform_point`, `power` and `slerp` take fixed-length polynomials and one test on
//! the result instead of the careful path's checks, rescaling and term-by-term series. Each
//! is checked here against an independent reference over inputs that cross every threshold
//! of the direct paths (half-angles near 0, near `2^-10`, at `π/6`, at `π/4`, at 1, near and past `π/2`, at 2;
//! non-unit poses; large translations): the same operation in 256-bit MPFR (which takes the
//! careful path), the generated `cga_null` sandwich, and exact rationals.

use crate::common;

use algebra_core::rational::{Q, ratio};
use algebra_core::test_support::Xorshift;
use algebra_core::{MpFloat, PrecisionGuard, Real, Ring};

use common::{cga_null_action, diff, size};
use motion::{Even, Pose, Pseudoscalar, UnitPose};

/// The condition of the logarithm of `s`: it grows like `1/sin θ` near a rotation by 2π
/// (half-angle θ near π).
fn log_condition(s: &Pose<f64>) -> f64 {
    let l = s.log().unwrap();
    1.0 / l.e12.hypot(l.e13).hypot(l.e23).sin().abs().max(0.05)
}

fn to_mp(x: &Even<f64>) -> Even<MpFloat> {
    x.map_scalar(&|c: &f64| MpFloat::from_f64(*c))
}

fn to_f64(x: &Even<MpFloat>) -> Even<f64> {
    x.map_scalar(&|c: &MpFloat| c.to_f64())
}

/// Generators `σ + θ n e123 + c einf + pω` at the half-angles that bracket the thresholds.
fn generators() -> Vec<Even<f64>> {
    let mut rng = Xorshift(0x9E37_79B9_7F4A_7C15);
    let halves = [
        0.0,
        1e-12,
        2f64.powi(-11),
        2f64.powi(-10),
        2f64.powi(-9),
        0.3,
        std::f64::consts::FRAC_PI_6 - 1e-9,
        std::f64::consts::FRAC_PI_6,
        std::f64::consts::FRAC_PI_6 + 1e-9,
        0.9,
        1.0,
        1.1,
        std::f64::consts::FRAC_PI_2 - 1e-7,
        std::f64::consts::FRAC_PI_2 + 1e-7,
        2.0 - 1e-9,
        2.0 + 1e-9,
        2.5,
        3.1,
        // last, so that the draws for the half-angles above stay as they were
        std::f64::consts::FRAC_PI_4 - 1e-9,
        std::f64::consts::FRAC_PI_4 + 1e-9,
    ];
    common::generators_at(&mut rng, &halves, true)
}

#[test]
fn exp_equals_the_256_bit_careful_path() {
    let _g = PrecisionGuard::new(256);
    for g in generators() {
        let fast = Pose::exp(&g).unwrap();
        let reference = to_f64(&Pose::exp(&to_mp(&g)).unwrap());
        // a few ulp of the result (sin and cos of half-angles up to 3.1 at the largest)
        assert!(diff(&fast, &reference) <= 2e-15 * size(&reference).max(1.0), "exp({g}): {fast} vs {reference}");
    }
}

#[test]
fn log_equals_the_256_bit_careful_path() {
    let _g = PrecisionGuard::new(256);
    for g in generators() {
        // the pose rounded to f64 is the input of both sides
        let s = Pose::exp(&g).unwrap();
        let fast = s.log().unwrap();
        let reference = to_f64(&to_mp(&s).log().unwrap());
        let tol = 8e-16 * log_condition(&s) * size(&reference).max(1.0);
        assert!(diff(&fast, &reference) <= tol, "log({s}): {fast} vs {reference}");
    }
}

#[test]
fn power_and_slerp_equal_the_256_bit_careful_path() {
    let _g = PrecisionGuard::new(256);
    let gs = generators();
    for (i, g) in gs.iter().enumerate() {
        let a = Pose::exp(g).unwrap();
        let b = Pose::exp(&gs[(i * 7 + 3) % gs.len()]).unwrap();
        for t in [0.0, 0.25, 0.5, 1.0, 1.7] {
            let tm = MpFloat::from_f64(t);
            let p = a.power(&t).unwrap();
            let reference = to_f64(&to_mp(&a).power(&tm).unwrap());
            // relative to the input: the power of a pose with translation 10^4 has its rounding
            let input = size(&a).max(1.0) * log_condition(&a);
            assert!(diff(&p, &reference) <= 1e-14 * input, "power({a}, {t}): {p} vs {reference}");
            let s = Pose::slerp(&a, &b, &t).unwrap();
            let reference = to_f64(&Pose::slerp(&to_mp(&a), &to_mp(&b), &tm).unwrap());
            let rel = a.reverse() * b;
            let input = size(&a).max(1.0) * size(&b).max(1.0) * log_condition(&rel);
            assert!(diff(&s, &reference) <= 1e-14 * input, "slerp({a}, {b}, {t}): {s} vs {reference}");
        }
    }
}

#[test]
fn transform_point_equals_the_generated_cga_sandwich() {
    let mut rng = Xorshift(0x2545_F491_4F6C_DD1D);
    for g in generators() {
        // non-unit poses too: 0.3 to 3 times a pseudoscalar with a dual part
        let mut d = || rng.symmetric();
        let gamma = Pseudoscalar::new(1.65 + 1.35 * d(), d());
        let s = Pose::exp(&g).unwrap().scale_pseudoscalar(&gamma);
        let p = [5.0 * d(), 5.0 * d(), 5.0 * d()];
        let fast = s.transform_point(&p).unwrap();
        let (reference, _) = cga_null_action(&s, &p);
        let scale = reference.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        for k in 0..3 {
            assert!((fast[k] - reference[k]).abs() <= 4e-15 * scale, "{s} on {p:?}: {fast:?} vs {reference:?}");
        }
    }
}

#[test]
fn transform_point_is_exact_over_the_rationals() {
    let mut rng = Xorshift(7);
    for _ in 0..200 {
        let mut r = || ratio((rng.next_u64() % 41) as i64 - 20, (rng.next_u64() % 7 + 1) as i64);
        let s = Pose::<Q>::from_array(std::array::from_fn(|_| r()));
        let p = [r(), r(), r()];
        if s.pseudo_norm_squared().scalar.is_exact_zero() {
            assert!(s.transform_point(&p).is_err(), "{s} is singular");
            continue;
        }
        assert_eq!(s.transform_point(&p).unwrap(), cga_null_action(&s, &p).0, "{s} on {p:?}");
    }
}

/// `Pose::log` of plain `f64` poses skips the test of its result when every coefficient is
/// finite and below `2^200` (the result is then bounded a priori): translations on both sides
/// of that bound, and rotational parts scaled to the edges of the direct path's range
/// (`α = 2^±480`), against the 256-bit careful path. Where the reference is finite in `f64`
/// the fast result equals it; where it is not, the fast path declines with an error.
#[test]
fn log_of_large_translations_equals_the_careful_path_or_fails() {
    let _g = PrecisionGuard::new(256);
    for half in [0.3, 0.9, 1.4] {
        for t in [1e3, 1e59, 1.6e60, 1.7e60, 1e100, 1e250, 1e300, 1.7e308] {
            for k in [1.0, 2f64.powi(-240), 2f64.powi(240)] {
                let s = Pose::from_axis_angle_translation(&[0.6, -0.8, 0.0], &(2.0 * half), &[t, -0.5 * t, 0.25 * t])
                    .unwrap()
                    .scale(&k);
                if !s.is_finite() {
                    continue;
                }
                let reference = to_f64(&to_mp(&s).log().unwrap());
                let fast = s.log();
                if size(&reference).is_finite() {
                    let fast = fast.unwrap_or_else(|e| panic!("log({s}) failed: {e}"));
                    assert!(diff(&fast, &reference) <= 1e-15 * size(&reference), "log({s}): {fast} vs {reference}");
                } else {
                    assert!(fast.is_err(), "log({s}) = {fast:?}, reference {reference}");
                }
            }
        }
    }
}

/// `Pose::transform_point` at `f64` tests `α` (tame) and the coordinates' sum (finite):
/// images that overflow in exactly one coordinate (each of the three in turn), translations
/// and points up to `1.7e308`, rotational scales `2^±240` and `2^±260` (outside the tame
/// range: the careful path), against the 256-bit careful path.
/// Where the reference is finite in `f64` the fast result equals it; where it is not, the fast
/// path declines with `NotFinite`. A NaN or infinite coordinate of the point, in any place,
/// fails the same way.
#[test]
fn transform_point_overflowing_in_one_coordinate_equals_the_careful_path_or_fails() {
    let _g = PrecisionGuard::new(256);
    let mp = |x: f64| MpFloat::from_f64(x);
    let mut checked = [0usize; 2];
    for axis in 0..3 {
        for t in [1.0, 1e300, 8e307, 9e307, 1.7e308] {
            for x in [0.5, 1e300, 8e307, 9e307, 1.7e308] {
                for k in [1.0, 2f64.powi(-240), 2f64.powi(240), 2f64.powi(-260), 2f64.powi(260)] {
                    let mut shift = [0.0; 3];
                    shift[axis] = t;
                    // a quarter turn about the axis itself: the other coordinates stay small
                    let mut n = [0.0; 3];
                    n[axis] = 1.0;
                    let s =
                        Pose::from_axis_angle_translation(&n, &std::f64::consts::FRAC_PI_2, &shift).unwrap().scale(&k);
                    let mut p = [0.25, -0.5, 0.75];
                    p[axis] = x;
                    if !s.is_finite() {
                        continue;
                    }
                    let reference = to_mp(&s).transform_point(&p.map(mp)).unwrap().map(|c| c.to_f64());
                    let fast = s.transform_point(&p);
                    // `α = k²` within `2^±500`: the direct path; else the careful one, which
                    // may decline an image within a factor 4 of `f64::MAX` (its rescaled pose
                    // has `α` in [1, 4), so `α t` overflows first)
                    let direct = k.log2().abs() <= 250.0;
                    if !direct && fast.is_err() && reference.iter().any(|c| c.abs() > 4e307) {
                        continue;
                    }
                    if reference.iter().all(|c| c.is_finite()) {
                        let fast = fast.unwrap_or_else(|e| panic!("{s} on {p:?} failed: {e}"));
                        for (f, r) in fast.iter().zip(&reference) {
                            assert!(
                                (f - r).abs() <= 4e-16 * (1.0 + r.abs()) * 4.0,
                                "{s} on {p:?}: {fast:?} vs {reference:?}"
                            );
                        }
                        checked[0] += 1;
                    } else {
                        assert!(
                            matches!(fast, Err(motion::MotionError::NotFinite { .. })),
                            "{s} on {p:?} = {fast:?}, reference {reference:?}"
                        );
                        checked[1] += 1;
                    }
                }
            }
        }
        let s = Pose::from_axis_angle_translation(&[0.0, 0.6, 0.8], &1.0, &[1.0, 2.0, 3.0]).unwrap();
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let mut p = [1.0, 2.0, 3.0];
            p[axis] = bad;
            assert!(matches!(s.transform_point(&p), Err(motion::MotionError::NotFinite { .. })), "{p:?}");
        }
    }
    // both outcomes occur, on each side of the tame range
    assert!(checked[0] > 100 && checked[1] > 30, "{checked:?}");
}

/// Images whose coordinates are all finite but whose sum overflows: the sum test of
/// `Pose::transform_point` declines them, and the careful path must still return them, equal to
/// the 256-bit action (each coordinate's error within 4 roundings of its size), not an error.
#[test]
fn transform_point_images_whose_sum_overflows_are_returned() {
    let _g = PrecisionGuard::new(256);
    let big = 1.7e308;
    let turn = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &0.1, &[0.0, 0.0, 1.0]).unwrap();
    let cases = [
        (Pose::identity(), [big, big, 0.5]),
        (Pose::identity(), [big, 0.25, big]),
        (Pose::identity(), [-big, -big, -big]),
        (Pose::translation(&[5e307, 5e307, -5e307]), [1e308, 1e308, -1e308]),
        (turn, [1.2e308, 1.2e308, 0.0]),
        (turn.scale(&3.0), [1.2e308, 1.2e308, -1.0]),
    ];
    for (s, p) in cases {
        let reference = to_mp(&s).transform_point(&p.map(MpFloat::from_f64)).unwrap().map(|c| c.to_f64());
        assert!(reference.iter().all(|c| c.is_finite()), "case {s} on {p:?}: {reference:?}");
        assert!(!(reference[0] + reference[1] + reference[2]).is_finite(), "the sum must overflow: {reference:?}");
        let fast = s.transform_point(&p).unwrap_or_else(|e| panic!("{s} on {p:?} failed: {e}"));
        for (f, r) in fast.iter().zip(&reference) {
            assert!((f - r).abs() <= 4.0 * f64::EPSILON * r.abs().max(1.0), "{s} on {p:?}: {fast:?} vs {reference:?}");
        }
    }
}

/// The slerp of unit poses (`rev(a) b` unit with non-negative scalar part: the direct path
/// that skips the last motor product, `a rel^t = A a + (B N_a) b` with dual-scalar weights,
/// and its mirror form past `t = ½`) against the 256-bit careful path `a (rev(a) b)^t`:
/// 2400 random pairs with translations of 0.1 to 1000 and rotations up to 3.1 rad, at the
/// ends, near them, on both sides of `½` and outside `[0, 1]`. The error is at most 4
/// roundings of the inputs' size times the weights' size `|t| + |1 - t|` (1 inside `[0, 1]`,
/// 2.4 at t = 1.7). Measured, in those units: `Pose::slerp` 1.9, `UnitPose::slerp` 2.6; the
/// previous form (the power, then a motor product) 2.5 and 3.0.
#[test]
fn unit_slerp_equals_the_256_bit_careful_path() {
    let _g = PrecisionGuard::new(256);
    let mut rng = Xorshift(0x1234_5678_9ABC_DEF1);
    let ts = [0.0, 0.001, 0.1, 0.25, 0.4, 0.5, 0.6, 0.75, 0.9, 0.99, 0.999, 1.0, -0.5, 1.7];
    let mut direct = 0;
    for case in 0..3000 {
        let scale = [0.1, 1.0, 10.0, 1000.0][case % 4];
        let mut pose = || {
            let axis = [rng.symmetric(), rng.symmetric(), rng.symmetric()];
            let n = axis.iter().map(|x| x * x).sum::<f64>().sqrt();
            let (angle, d) =
                (3.1 * rng.symmetric(), [scale * rng.symmetric(), scale * rng.symmetric(), scale * rng.symmetric()]);
            Pose::from_axis_angle_translation(&axis.map(|x| x / n), &angle, &d).unwrap()
        };
        let (a, b) = (pose(), pose());
        if (a.reverse() * b).scalar < 0.0 {
            continue;
        }
        direct += 1;
        let (ua, ub) = (a.to_unit().unwrap(), b.to_unit().unwrap());
        let input = size(&a).max(1.0) * size(&b).max(1.0);
        for t in ts {
            let tol = 4.0 * f64::EPSILON * input * (t.abs() + (1.0 - t).abs());
            let reference = to_f64(&Pose::slerp(&to_mp(&a), &to_mp(&b), &MpFloat::from_f64(t)).unwrap());
            let s = Pose::slerp(&a, &b, &t).unwrap();
            assert!(diff(&s, &reference) <= tol, "slerp({a}, {b}, {t}): {s} vs {reference}");
            // `to_unit` rescales the keys by their rounding-level norms: the reference is theirs
            let u = UnitPose::slerp(&ua, &ub, &t).unwrap();
            let (ma, mb) = (to_mp(ua.as_pose()), to_mp(ub.as_pose()));
            let reference = to_f64(&Pose::slerp(&ma, &mb, &MpFloat::from_f64(t)).unwrap());
            assert!(
                diff(u.as_pose(), &reference) <= tol,
                "unit slerp({}, {}, {t}): {} vs {reference}",
                ua.as_pose(),
                ub.as_pose(),
                u.as_pose()
            );
        }
    }
    assert!(direct > 2000, "{direct} pairs on the direct path");
}
