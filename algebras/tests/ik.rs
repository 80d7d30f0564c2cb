//! The inverse-kinematics chain of the `ik` bench (ga-benchmark's workload over the generated
//! kernels of GATL's conformal declaration), checked against a second computation of the same
//! chain over the runtime engine (`algebra_core::Multivector`: the exact tables, literal
//! geometric products, the Taylor polynomial with full products `x x`, `x x x`, `x x x x`, the
//! dual through the computed inverse of the pseudoscalar), and against the arm's motion in
//! closed form where it is known.
#![allow(missing_docs)]
#[path = "../benches/ik/arm.rs"]
mod arm;

use algebra_core::Multivector as Mv;
use arm::arm_cga::{Infinity, Point, Pseudoscalar};

fn add(a: &Mv<f64>, b: &Mv<f64>) -> Mv<f64> {
    a.try_add(b).unwrap()
}

/// The suite's `expp`, literally: `1 + x + x x/2 + x x x/6 + x x x x/24`.
fn taylor(x: &Mv<f64>) -> Mv<f64> {
    let one = Mv::scalar(x.algebra(), x.basis(), 1.0);
    let x2 = x.gp(x);
    let x3 = x2.gp(x);
    let x4 = x3.gp(x);
    [x.clone(), x2.scale(&0.5), x3.scale(&(1.0 / 6.0)), x4.scale(&(1.0 / 24.0))].iter().fold(one, |s, t| add(&s, t))
}

fn apply(s: &Mv<f64>, x: &Mv<f64>) -> Mv<f64> {
    s.gp(x).gp(&s.reverse())
}

/// The chain over the runtime engine; returns its seven results as multivectors.
fn runtime_chain(a: &[f64; 5], g: &arm::Geometry) -> Vec<Mv<f64>> {
    let [d1, d2, d3, d4, d5] = g.d;
    let (l12, l23) = (g.l12, g.l23);
    let pt = |x: f64, y: f64, z: f64| arm::point(x, y, z).to_multivector();
    let ni = Infinity { einf: 1.0 }.to_multivector();
    let i_inv = Pseudoscalar { e123oinf: 1.0 }.to_multivector().inverse().unwrap();
    let line = |p: &Mv<f64>, q: &Mv<f64>| p.op(q).op(&ni).gp(&i_inv);
    let (j1, j2) = (pt(d1, 0.0, d2), pt(d1, 0.0, d2 + l12));
    let (j3, jg) = (pt(d1 + l23, 0.0, d2 + l12 + d3), pt(d1 + l23 + d4 + d5, 0.0, d2 + l12 + d3));
    let r1 = taylor(&line(&pt(0.0, 0.0, 0.0), &pt(0.0, 0.0, 1.0)).scale(&(a[0] / 2.0)));
    let r2 = taylor(&apply(&r1, &line(&j1, &pt(d1, 1.0, d2))).scale(&(a[1] / 2.0)));
    let j2_f = apply(&r2.gp(&r1), &j2);
    let r3 = taylor(&apply(&r2.gp(&r1), &line(&j2, &pt(d1, 1.0, d2 + l12))).scale(&(a[2] / 2.0)));
    let j2_r = apply(&r1, &j2);
    let t = j2_f.try_sub(&j2_r).unwrap().grade(1);
    // the Euclidean part of the difference (its eo and einf parts dropped, as the suite's
    // `sp(x, e_i) e_i` sum does)
    let t =
        Mv::from_terms(t.algebra(), t.basis(), ["e1", "e2", "e3"].map(|n| (n, *t.coeff_by_name(n).unwrap()))).unwrap();
    let t2 = taylor(&t.op(&ni).scale(&-0.5));
    let r3t2r1 = r3.gp(&t2).gp(&r1);
    let l4 = line(&j3, &jg);
    let l4 = l4.scale(&(1.0 / l4.sp(&l4.reverse()).scalar_part().abs().sqrt()));
    let r4 = taylor(&apply(&r3t2r1, &l4).scale(&(a[3] / 2.0)));
    let lg = apply(&r4.gp(&r3t2r1), &line(&j3, &pt(d1 + l23, 1.0, d2 + l12 + d3)));
    let rg = taylor(&lg.scale(&(a[4] / 2.0)));
    let gripper = apply(&rg.gp(&r3).gp(&t2).gp(&r1), &jg);
    vec![r1, r2, r3, t2, r4, rg, gripper]
}

/// Coefficient-wise agreement to `tol` relative to the larger's largest coefficient.
fn close(a: &Mv<f64>, b: &Mv<f64>, tol: f64, what: &str) {
    let scale = a.coeffs().iter().chain(b.coeffs()).fold(1.0f64, |m, c| m.max(c.abs()));
    for (i, (x, y)) in a.coeffs().iter().zip(b.coeffs()).enumerate() {
        assert!((x - y).abs() <= tol * scale, "{what}: coefficient {i}: {x} vs {y}");
    }
}

fn angles() -> Vec<[f64; 5]> {
    // GATL's angle set (below), then joints alone, then a spread
    let mut v = vec![GATL_ANGLES, [0.0; 5], [0.7, 0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0, -1.3]];
    for k in 0..20 {
        let f = |j: usize| ((k * 5 + j) as f64 * 0.7311).sin() * 3.1;
        v.push([f(0), f(1), f(2), f(3), f(4)]);
    }
    v
}

#[test]
fn the_generated_chain_is_the_runtime_engines() {
    for a in angles() {
        let c = arm::chain(&a, &arm::ARM);
        let r = runtime_chain(&a, &arm::ARM);
        let ours = [
            c.r1.to_multivector(),
            c.r2.to_multivector(),
            c.r3.to_multivector(),
            c.t2.to_multivector(),
            c.r4.to_multivector(),
            c.rg.to_multivector(),
            c.gripper.to_multivector(),
        ];
        for (k, (x, y)) in ours.iter().zip(&r).enumerate() {
            close(x, y, 1e-13, &format!("result {k} at {a:?}"));
        }
    }
}

/// The first angle set of the C++ harness that timed GATL (docs/performance.md, "Inverse
/// kinematics against GATL").
const GATL_ANGLES: [f64; 5] = [
    1.602_376_746_954_504_5,
    0.873_117_153_407_500_2,
    1.583_471_860_697_607_3,
    -2.284_207_546_788_295,
    2.532_529_109_170_216,
];

/// GATL's own result for [`GATL_ANGLES`] with the arm's dimensions as run-time doubles, as its
/// `operator<<` printed it (six significant digits): an independent implementation of the
/// chain (its own expression templates, `dual`, `apply_rotor` and `expp`), so this pins the
/// conventions (the metric dual, `S x rev(S)`, the sign of each rotor), not just the kernels.
#[test]
fn the_gripper_is_where_gatl_puts_it() {
    let p = arm::chain(&GATL_ANGLES, &arm::ARM).gripper;
    let gatl = [-109.547, 508.41, 1856.95, 0.955351, 1.94627e6];
    for (ours, theirs) in [p.e1, p.e2, p.e3, p.eo, p.einf].into_iter().zip(gatl) {
        assert!((ours - theirs).abs() <= 5e-6 * theirs.abs(), "{p:?}");
    }
    let r4 = arm::chain(&GATL_ANGLES, &arm::ARM).r4;
    let gatl = [0.425277, -0.89121, 0.00282083, -7.6974e-05, -558.752, 15.247];
    for (ours, theirs) in [r4.scalar, r4.e12, r4.e13, r4.e23, r4.e1inf, r4.e2inf].into_iter().zip(gatl) {
        assert!((ours - theirs).abs() <= 5e-6 * theirs.abs(), "{r4:?}");
    }
}

#[test]
fn zero_angles_leave_the_gripper_where_it_is() {
    let c = arm::chain(&[0.0; 5], &arm::ARM);
    let g = arm::ARM;
    let jg = arm::point(g.d[0] + g.l23 + g.d[3] + g.d[4], 0.0, g.d[1] + g.l12 + g.d[2]);
    assert_eq!(c.gripper, jg);
    for r in [c.r1, c.r2, c.r3, c.r4, c.rg] {
        assert_eq!(r.scalar, 1.0);
        assert!(r.iter().skip(1).all(|x| *x == 0.0), "{r:?}");
    }
}

/// The base joint alone turns the arm about the z axis: the gripper's image is the closed-form
/// image of the rotor `1 + x + ... + x⁴/24` with `x = (θ/2) e12`-part, i.e. a rotation by the
/// angle whose cosine and sine are the truncated series, scaled by the rotor's squared norm.
#[test]
fn the_base_joint_alone_is_a_rotation_about_z() {
    let th: f64 = 0.7;
    let c = arm::chain(&[th, 0.0, 0.0, 0.0, 0.0], &arm::ARM);
    let h = th / 2.0;
    // the rotor's coefficients in closed form: cos and sin series of θ/2 to fourth order
    let (s, b) = (1.0 - h * h / 2.0 + h.powi(4) / 24.0, h - h.powi(3) / 6.0);
    assert!((c.r1.scalar - s).abs() < 1e-15);
    assert!((c.r1.e12.abs() - b).abs() < 1e-15);
    let n2 = s * s + b * b;
    let (cos, sin) = ((s * s - b * b) / n2, 2.0 * s * b / n2);
    let g = arm::ARM;
    let (x, z) = (g.d[0] + g.l23 + g.d[3] + g.d[4], g.d[1] + g.l12 + g.d[2]);
    let p: Point<f64> = c.gripper;
    // S x rev(S) scales a point by S rev(S) = |S|² (the truncated rotor is not unit), so the
    // Euclidean part is compared after dividing by eo
    let (px, py, pz) = (p.e1 / p.eo, p.e2 / p.eo, p.e3 / p.eo);
    assert!((p.eo - n2).abs() < 1e-15, "{p:?}");
    assert!((px - x * cos).abs() < 1e-9 && (py.abs() - x * sin).abs() < 1e-9 && (pz - z).abs() < 1e-9, "{p:?}");
}
