//! The statements of Angelidis that `motion::repr::hexanion` implements: (22), (27), (41) and
//! the matrix -> hexanion conversion of Sec. 6. Each library result is compared with the private
//! reference of the parent module (the power series (13) of the 4x4 matrix, at 256 bits) or
//! with a property that does not use the library's formula (a fixed point, a trace).

use super::{DIGITS, V3, apply, dir4, dot, flat, hex, ident, mmul, point4, samples, series, test_point};
use crate::Checker;
use algebra_core::{Field, MpFloat, PrecisionGuard, Real, Ring};
use motion::Pose;
use motion::repr::hexanion::{Hexanion, Kind};

type M4 = super::M4<MpFloat>;

fn neg(v: &V3<MpFloat>) -> V3<MpFloat> {
    v.clone().map(|x| x.neg_ref())
}

/// (22): `<-ω, -m> * (<ω, m> * p) = p`.
pub(super) fn eq_22(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    let p = test_point();
    for (name, w, m) in samples() {
        // the reference: exp(-(ω, m)) exp((ω, m)) = I by the series
        let prod = mmul(&series(&hex(&neg(&w), &neg(&m))), &series(&hex(&w, &m)));
        c.close(format!("{name}: exp(-ω, -m) exp(ω, m) = I (series)"), &flat(&prod), &flat(&ident()), DIGITS);
        // the library: Hexanion::inverse and the point transform
        let h = Hexanion::new(w.clone(), m.clone());
        let back = h.inverse().transform_point(&h.transform_point(&p));
        c.close(format!("{name}: Hexanion::inverse undoes Hexanion::transform_point"), &back, &p, DIGITS);
        let img = apply(&series(&hex(&w, &m)), &point4(&p));
        c.close(format!("{name}: Hexanion::transform_point = series image"), &h.transform_point(&p), &img[..3], DIGITS);
    }
}

/// (27): the centre, angle and axis of a rotation hexanion, against the series exponential:
/// the centre is a fixed point, the axis a fixed direction, and `1 + 2 cos θ` the trace of the
/// rotation block.
pub(super) fn eq_27(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    for (name, w, m) in
        samples().into_iter().filter(|(_, w, m)| !dot(w, w).is_exact_zero() && dot(w, m).is_exact_zero())
    {
        let e = series(&hex(&w, &m));
        let Kind::Rotation { centre, angle, axis } = Hexanion::new(w.clone(), m.clone()).classify(&MpFloat::zero())
        else {
            c.fail(format!("{name}: not classified as a rotation"));
            continue;
        };
        c.close(
            format!("{name}: (27) centre c is fixed by exp(ω, m)"),
            &apply(&e, &point4(&centre))[..3],
            &centre,
            DIGITS,
        );
        c.close(format!("{name}: (27) axis n is fixed by exp(ω, m)"), &apply(&e, &dir4(&axis))[..3], &axis, DIGITS);
        let trace = e[0][0].add_ref(&e[1][1]).add_ref(&e[2][2]);
        let two_cos = MpFloat::from_i64(2).mul_ref(&Real::cos(&angle));
        c.close(
            format!("{name}: (27) 1 + 2 cos θ = trace of the rotation"),
            &[trace],
            &[MpFloat::one().add_ref(&two_cos)],
            DIGITS,
        );
        let n2 = dot(&axis, &axis);
        c.close(format!("{name}: (27) |n| = 1"), &[n2], &[MpFloat::one()], DIGITS);
    }
    let (name, w, m) = samples().swap_remove(4);
    c.check(
        format!("{name}: a twist (ω·m != 0) is not a rotation"),
        matches!(Hexanion::new(w, m).classify(&MpFloat::zero()), Kind::Twist { .. }),
    );
}

/// `(f(h) - f(-h))/(2h)` entrywise for `h = 10^-30`.
fn central_difference(f: impl Fn(&MpFloat) -> M4) -> M4 {
    let h = (0..30).fold(MpFloat::one(), |a, _| a.mul_ref(&MpFloat::from_ratio(1, 10)));
    let (a, b) = (f(&h), f(&h.neg_ref()));
    let inv = MpFloat::one().div_ref(&h.add_ref(&h));
    std::array::from_fn(|i| std::array::from_fn(|j| a[i][j].sub_ref(&b[i][j]).mul_ref(&inv)))
}

/// (41): `d/dh M^h |_{h=0} = (ω, m)` for `M = exp(ω, m)`, with `M^h` the library's pose power
/// of the pose of the matrix `M` (`Pose::from_matrix`, so the principal logarithm), by a central difference at 256 bits (error
/// `O(h²) = 10^-60`); the reference is the series of `exp(h (ω, m))`, differenced the same way.
pub(super) fn eq_41(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    const DIFF_DIGITS: u32 = 55;
    for (name, w, m) in samples() {
        let hm = hex(&w, &m);
        let reference =
            central_difference(|h| series(&hex(&w.clone().map(|x| x.mul_ref(h)), &m.clone().map(|x| x.mul_ref(h)))));
        c.close(
            format!("{name}: d/dh exp(h (ω, m)) at 0 = (ω, m) (series)"),
            &flat(&reference),
            &flat(&hm),
            DIFF_DIGITS,
        );
        // the pose of the matrix M (Pose::from_matrix: scalar part >= 0, so the logarithm in
        // Pose::power is the principal one of the matrix)
        let from_matrix = Pose::from_matrix(&series(&hm), &MpFloat::from_f64(1e-60));
        let Some(pose) = c.ok(format!("{name}: Pose::from_matrix"), from_matrix) else {
            continue;
        };
        let power = |h: &MpFloat| pose.power(h).and_then(|p| p.to_matrix()).unwrap_or_else(|_| ident());
        let lib = central_difference(power);
        let principal = dot(&w, &w) < MpFloat::pi().mul_ref(&MpFloat::pi());
        if principal {
            c.close(format!("{name}: d/dh M^h at 0 = (ω, m) (Pose::power)"), &flat(&lib), &flat(&hm), DIFF_DIGITS);
        } else {
            c.counterexample(
                format!("{name}: (41) with |ω| > π"),
                {
                    let mut scratch = Checker::new();
                    scratch.close("", &flat(&lib), &flat(&hm), DIFF_DIGITS);
                    scratch.finish().holds()
                },
                "M^h = exp(h log M) uses the principal logarithm: for |ω| > π the derivative is the principal hexanion, not (ω, m)",
            );
        }
    }
}

/// Sec. 6: the matrix -> hexanion conversion (43)-(53) of `exp(ω, m)` (series) gives back
/// `<ω, m>` when `|ω| < π` (principal branch), agrees with `Hexanion::from_pose` (the pose
/// logarithm, a second method), and its exponential (series) is the matrix.
pub(super) fn sec_6(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    let tol = MpFloat::from_f64(1e-60);
    for (name, w, m) in samples() {
        let e = series(&hex(&w, &m));
        let Some(h) = c.ok(format!("{name}: Hexanion::from_matrix_sec6"), Hexanion::from_matrix_sec6(&e, &tol)) else {
            continue;
        };
        c.close(format!("{name}: exp(Sec. 6 hexanion) = M (series)"), &flat(&series(&h.matrix())), &flat(&e), DIGITS);
        if dot(&w, &w) < MpFloat::pi().mul_ref(&MpFloat::pi()) {
            c.close(
                format!("{name}: Sec. 6 recovers <ω, m> (|ω| < π)"),
                &[h.omega.clone(), h.m.clone()].concat(),
                &[w.clone(), m.clone()].concat(),
                DIGITS,
            );
        }
        if let Some(lib) = c.ok(format!("{name}: Hexanion::from_matrix"), Hexanion::from_matrix(&e, &tol)) {
            c.close(
                format!("{name}: Sec. 6 = the pose logarithm"),
                &[h.omega, h.m].concat(),
                &[lib.omega, lib.m].concat(),
                DIGITS,
            );
        }
    }
    c.note(
        "choices where the paper leaves one open: the case of (47)/(50) with the largest denominator, v of (53) the basis \
         vector least aligned with n, θ ∈ [0, π] (principal branch)",
    );
}
