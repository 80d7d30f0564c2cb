//! The library's Wareham–Lasenby code (`motion::wareham_lasenby`) against the paper's formulas
//! typed in here (common.rs, `ell` of motion.rs) and the runtime `cga` multivector, at 256 bits:
//! the library is never compared with itself.
//!
//! * Theorem 3: `Generator::exp` (a division-free rewriting) = the paper's form.
//! * Theorem 9: `log` = the paper's `ℓ(R)` where the theorem applies; at a pure translation
//!   and at `|φ| = π` (where the theorem's formulas fail) `exp(log R) = R` by the runtime exp.
//! * Sec. 2.2 / 4.1: `from_pose` maps a pose to `T_v R` built here from the paper's rotor and
//!   translator (`R F(x) rev(R) = F(Rot x + v)` with the paper's `F`), and `helix_point` is
//!   the position `F⁻¹(exp(λB) F(y) rev(exp(λB)))` computed with the runtime exp.

use super::common::{n, plane, scalar, sinc, theorem_3_form, up, vector};
use super::powers::{INSTANCES, instance};
use crate::Checker;
use algebra_core::{Algebra, Field, MpFloat, Multivector, Real, Ring};
use gam_algebras::cga::{Bivector, Motor};
use motion::Pose;
use motion::wareham_lasenby::{Generator, from_pose, helix_point, log};
use std::sync::Arc;

/// The generator `φP + tn` of an instance, as the library's type.
fn library_generator(b: &Multivector<MpFloat>) -> Option<Generator<MpFloat>> {
    Generator::from_bivector(&Bivector::project(b)).ok()
}

fn coeffs(m: &Motor<MpFloat>) -> Vec<MpFloat> {
    m.to_array().to_vec()
}

/// Theorem 3: the library's exp against the paper's closed form.
pub(super) fn theorem_3(c: &mut Checker, alg: &Arc<Algebra>) {
    for inst in INSTANCES {
        let (phi, p, t) = instance(alg, inst);
        let b = &p.scale(&phi) + &(&t * &n(alg));
        let form = Motor::project(&theorem_3_form(alg, (&phi.cos(), &phi.sin(), &sinc(&phi)), &p, &t));
        let label = format!("φ = {}/{}", inst.0.0, inst.0.1);
        let Some(g) = library_generator(&b) else {
            c.check(format!("library reads B as a generator, {label}"), false);
            continue;
        };
        if let Some(r) = c.ok(format!("library exp, {label}"), g.exp()) {
            c.close(
                format!("motion::wareham_lasenby exp = Theorem 3's form, {label}"),
                &coeffs(&r),
                &coeffs(&form),
                70,
            );
        }
    }
}

/// Theorem 9: the library's log against the paper's ℓ (typed in) for 0 < |φ| < π, and
/// exp(log R) = R by the runtime exp where the theorem does not apply.
pub(super) fn theorem_9(
    c: &mut Checker,
    alg: &Arc<Algebra>,
    ell: impl Fn(&Multivector<MpFloat>) -> Multivector<MpFloat>,
) {
    let nf = n::<MpFloat>(alg);
    for inst in INSTANCES.iter().filter(|i| {
        let phi = i.0.0 as f64 / i.0.1 as f64;
        phi.abs() > 0.0 && phi.abs() < std::f64::consts::PI
    }) {
        let (phi, p, t) = instance(alg, inst);
        let b = &p.scale(&phi) + &(&t * &nf);
        let label = format!("φ = {}/{}", inst.0.0, inst.0.1);
        let Some(r) = c.ok("runtime exp", b.exp()) else { continue };
        let want = Bivector::project(&ell(&r)).to_array().to_vec();
        if let Some(l) = c.ok(format!("library log, {label}"), log(&Motor::project(&r))) {
            c.close(
                format!("motion::wareham_lasenby log = the paper's ℓ(R), {label}"),
                l.to_bivector().to_array().as_ref(),
                &want,
                70,
            );
        }
    }
    let (_, p, t) = instance(alg, &INSTANCES[0]);
    let one = scalar(alg, MpFloat::one());
    let t_perp = &t - &super::common::in_plane(&t, &p);
    for (what, r) in
        [("pure translation 1 + tn", &one + &(&t * &nf)), ("|φ| = π: -(1 + t⊥ n)", -(&one + &(&t_perp * &nf)))]
    {
        let Some(l) = c.ok(format!("library log, {what}"), log(&Motor::project(&r))) else { continue };
        if let Some(back) = c.ok("runtime exp", l.to_bivector().to_multivector().exp()) {
            c.close(
                format!("runtime exp(library log R) = R, {what}"),
                &coeffs(&Motor::project(&back)),
                &coeffs(&Motor::project(&r)),
                70,
            );
        }
    }
}

/// Sec. 2.2 and 4.1: the library's rotor of a pose and its helix against constructions here.
pub(super) fn rotor_and_helix(c: &mut Checker, alg: &Arc<Algebra>) {
    let q = |a: i64, b: i64| MpFloat::from_ratio(a, b);
    let axis = [q(2, 7), q(-3, 7), q(6, 7)]; // unit
    let v = [q(1, 2), q(-2, 1), q(3, 1)];
    let x = [q(1, 3), q(2, 1), q(-1, 5)];
    let h = q(7, 10).mul_ref(&q(1, 2));
    let Some(pose) = c.ok("pose", Pose::from_axis_angle_translation(&axis, &q(7, 10), &v)) else { return };
    // the paper's rotation rotor cos(θ/2) + sin(θ/2) P with P = -â e123 (plane(â) = â e123),
    // and translator T_v = 1 + n v/2
    let rot = &scalar(alg, h.cos()) - &plane(alg, &axis).scale(&h.sin());
    let tv = &scalar(alg, MpFloat::one()) + &(&n(alg) * &vector(alg, v.clone())).scale(&q(1, 2));
    let want = &tv * &rot;
    if let Some(r) = c.ok("library from_pose", from_pose(&pose)) {
        c.close("from_pose = T_v (cos(θ/2) - sin(θ/2) â e123)", &coeffs(&r), &coeffs(&Motor::project(&want)), 70);
    }
    let image = &(&want * &up(alg, &vector(alg, x.clone()))) * &want.reverse();
    if let Some(moved) = c.ok("pose action", pose.transform_point(&x)) {
        c.close_mv("T_v R F(x) rev(T_v R) = F(pose x)", &image, &up(alg, &vector(alg, moved)), 70);
    }
    for inst in INSTANCES.iter().take(3) {
        let (phi, p, t) = instance(alg, inst);
        let b = &p.scale(&phi) + &(&t * &n(alg));
        let Some(g) = library_generator(&b) else { continue };
        let lambda = q(3, 5);
        let Some(r) = c.ok("runtime exp", b.scale(&lambda).exp()) else { continue };
        let moved = &(&r * &up(alg, &vector(alg, x.clone()))) * &r.reverse();
        // F⁻¹: x = X_{1..3} / (X5 - X4)
        let k = MpFloat::one().div_ref(&moved.coeff_by_name("e5").unwrap().sub_ref(moved.coeff_by_name("e4").unwrap()));
        let want: Vec<MpFloat> =
            ["e1", "e2", "e3"].iter().map(|e| moved.coeff_by_name(e).unwrap().mul_ref(&k)).collect();
        let got = helix_point(&g, &x, &lambda);
        c.close(
            format!("helix_point = F⁻¹(exp(λB) F(y) rev(exp(λB))), φ = {}/{}", inst.0.0, inst.0.1),
            &got,
            &want,
            70,
        );
    }
}
