//! Section 5: the claims the worked examples make beyond their numbers (the numbers themselves
//! are reproduced by `motion/tests/joins.rs` and `cli/tests/hermite.rs`).
//!
//! `sec-5.2-darboux`, Sec. 5.2: "as λ0 varies, S1 represents an additive Bézier motion of
//! degree 1. Generally when such a motion is applied to a body, each point in the body moves
//! around the surface of a circular cylinder (with a common axis) along a planar path which is
//! therefore an ellipse. This is a vertical Darboux motion. This also applies to S2. As this
//! example is planar, the movements related to the middle control poses are along circular
//! arcs." Points move by the runtime sandwich `rev(S)(e0 + x)S` of G_0123inf over `Poly`
//! (homogeneous image `(y0, y)`, the coefficients of `e0, e1, e2, e3`), with the parameter `λ`,
//! the point `x` and (in the example) `π` as symbols:
//!
//! * normal form, all symbolic: `W(λ) = (1 - λ) + λC`, `C = p0 + p1 e23 + q1 e1∞ + q0 ω` (a screw
//!   about the e1 axis plus an ω part). With `u = 1 - λ + λp0`, `v = λp1`: `y0 = u² + v²`; `(y2, y3)`
//!   is `(x2, x3)` turned by `φ`, `cos φ = (u² - v²)/(u² + v²)`, `sin φ = 2uv/(u² + v²)`, so every
//!   point stays on its cylinder about the axis; `p1 (y1 - y0 x1) = 2 q1 uv + 2 q0 v²`: the axial
//!   displacement `(q1/p1) sin φ + (q0/p1)(1 - cos φ)` is the same for every point and harmonic in
//!   the angle (a vertical Darboux motion); `p1 ρ² (y1 - y0 x1) = q1 (x2 y3 - x3 y2) + q0 (ρ² y0 -
//!   x2 y2 - x3 y3)`, `ρ² = x2² + x3²`: a plane through the path, not parallel to the axis (its
//!   e1 component `p1 ρ²`), so the path is an ellipse; a circle exactly when `q0 = q1 = 0`;
//! * the general case on exact instances: `(1 - λ)A + λB = A((1 - λ) + λC)`, `C = A⁻¹B`, so a
//!   point moves as `F_A(x)` under the pencil of `C`; for random rational `A, B` (non-unit, with
//!   ω parts) the axis `(c, a)` of `C` (exact linear solve) is common to all `λ`: the distance to
//!   it is constant, the axial displacement independent of the point, of the Darboux form;
//! * the example, with `π` a symbol: `S1(λ0) = 1 + λ0(ν0 + γ0)/6` (eq. 22 as the printed numbers
//!   read it, `motion::joins`) and `S2(λ3) = S3(1 - λ3(ν3 + γ3)/6)`: cylinders about the axes
//!   through `(0, 32/π, 0)` and `(0, 10, 32/π)` along e1, axial displacement `-πλ²/144` at both
//!   ends (from the ω parts of `γ0 = ½ + ½ω`, `γ3 = 1 - ½ω`): ellipses leaving the plane of the
//!   motion, not circular arcs (circular in the figure's view along the axis); for Fig. 8's
//!   multiplicative poses `S1(λ0) = exp(λ0(ν0 + γ0)/6)` (eq. 23, the printed S1) the paths are
//!   exact circular arcs: `exp(λY) = e^{λ/12}(1 + λω/12) exp(λν0/6)`, a pseudoscalar factor acts
//!   as a scalar, and `exp(μν0) = cos(μπ/4) + sin(μπ/4) ν0/(π/4)` lies in the pencil of `1 + ν0`,
//!   which has no ω part.

use crate::{Checker, Method, Paper, Statement};
use algebra_core::linalg::solve;
use algebra_core::rational::{Q, q, ratio};
use algebra_core::{Algebra, Basis, Multivector, Poly, Ring};
use motion::Pose;
use std::sync::Arc;

/// The claims of Section 5.
///
/// ```
/// let s = &gam_verify::cross2022::sec5::STATEMENTS[0];
/// assert_eq!(s.id, "cross2022/sec-5.2-darboux");
/// assert!(s.run().outcome.holds());
/// ```
pub const STATEMENTS: &[Statement] = &[Statement {
    id: "cross2022/sec-5.2-darboux",
    paper: Paper::Cross2022,
    label: "Sec. 5.2 (Darboux motion)",
    statement: "as λ0 varies, S1 of (22) is an additive Bézier motion of degree 1; such a motion moves each point \
                of the body on a circular cylinder (common axis) along a planar path, an ellipse: a vertical Darboux \
                motion; the same for S2; in this planar example the paths are circular arcs",
    method: Method::Symbolic,
    hypotheses: "the relative pose C = A⁻¹B must turn (p1 != 0): otherwise the points move on parallel lines; points \
                 on the axis move on a segment of it. 'Circular arcs' fails for the additive S1, S2 of (22): the ω \
                 parts of γ0, γ3 give the axial displacement -πλ²/144, so the paths are ellipses leaving the plane; \
                 the arcs are circular only in the view along the axis. Fig. 8's poses are the multiplicative (23) \
                 ones, exp(λ0(ν0 + γ0)/6): not an additive motion of degree 1, but their paths are exact circular arcs",
    check: sec_5_2_darboux,
}];

fn alg() -> Arc<Algebra> {
    crate::algebra("cga-null")
}

const NAMES: [&str; 8] = ["1", "e12", "e13", "e23", "e1inf", "e2inf", "e3inf", "e123inf"];

/// An even element of G_123inf from its eight coefficients (order of [`NAMES`]).
fn even(c: [Poly; 8]) -> Multivector<Poly> {
    Multivector::from_terms(&alg(), Basis::Product, NAMES.into_iter().zip(c)).expect("basis names")
}

fn even_of(terms: &[(&str, Poly)]) -> Multivector<Poly> {
    Multivector::from_terms(&alg(), Basis::Product, terms.iter().map(|(n, p)| (*n, p.clone()))).expect("basis names")
}

fn lift(p: &Pose<Q>) -> Multivector<Poly> {
    even(p.components().map(Poly::from_q))
}

/// `(y0, y1, y2, y3)`: the `e0, e1, e2, e3` coefficients of `rev(S)(e0 + x)S`.
fn image(s: &Multivector<Poly>, x: &[Poly; 3]) -> [Poly; 4] {
    let terms = [("e0", Poly::one()), ("e1", x[0].clone()), ("e2", x[1].clone()), ("e3", x[2].clone())];
    let y = s.sandwich(&Multivector::from_terms(&alg(), Basis::Product, terms).expect("basis names"));
    ["e0", "e1", "e2", "e3"].map(|n| y.coeff_by_name(n).expect("basis name").clone())
}

fn var(name: &str) -> Poly {
    Poly::var(name)
}

fn int(n: i64) -> Poly {
    Poly::from_i64(n)
}

fn point() -> [Poly; 3] {
    [var("x1"), var("x2"), var("x3")]
}

/// Degree at most 2 in `λ`: the third derivative vanishes.
fn quadratic_in(p: &Poly, name: &str) -> bool {
    p.derivative(name).derivative(name).derivative(name) == Poly::zero()
}

fn independent_of_point(p: &Poly) -> bool {
    ["x1", "x2", "x3"].iter().all(|x| p.derivative(x) == Poly::zero())
}

fn dot(a: &[Poly; 3], b: &[Poly; 3]) -> Poly {
    a[0].mul_ref(&b[0]) + a[1].mul_ref(&b[1]) + a[2].mul_ref(&b[2])
}

fn cross(a: &[Poly; 3], b: &[Poly; 3]) -> [Poly; 3] {
    [
        a[1].mul_ref(&b[2]).sub_ref(&a[2].mul_ref(&b[1])),
        a[2].mul_ref(&b[0]).sub_ref(&a[0].mul_ref(&b[2])),
        a[0].mul_ref(&b[1]).sub_ref(&a[1].mul_ref(&b[0])),
    ]
}

/// The normal form, fully symbolic.
fn normal_form(c: &mut Checker) {
    let (lam, p0, p1, q0, q1) = (var("λ"), var("p0"), var("p1"), var("q0"), var("q1"));
    let one_minus = Poly::one().sub_ref(&lam);
    let cc = even_of(&[("1", p0.clone()), ("e23", p1.clone()), ("e1inf", q1.clone()), ("e123inf", q0.clone())]);
    let w = &Multivector::scalar(&alg(), Basis::Product, one_minus) + &cc.scale(&lam);
    let x = point();
    let y = image(&w, &x);
    let u = Poly::one().sub_ref(&lam).add_ref(&lam.mul_ref(&p0));
    let v = lam.mul_ref(&p1);
    let (uu, vv, uv) = (u.mul_ref(&u), v.mul_ref(&v), u.mul_ref(&v));
    let two = |p: Poly| p.add_ref(&p);
    c.equal("normal form: y0 = u² + v²", &y[0], &uu.add_ref(&vv));
    c.equal(
        "normal form: (y2, y3) = (x2, x3) turned by φ about e1: y2 = (u² - v²) x2 - 2uv x3",
        &y[2],
        &uu.sub_ref(&vv).mul_ref(&x[1]).sub_ref(&two(uv.clone()).mul_ref(&x[2])),
    );
    c.equal(
        "normal form: y3 = 2uv x2 + (u² - v²) x3",
        &y[3],
        &two(uv.clone()).mul_ref(&x[1]).add_ref(&uu.sub_ref(&vv).mul_ref(&x[2])),
    );
    let rho2 = x[1].mul_ref(&x[1]) + x[2].mul_ref(&x[2]);
    c.equal(
        "normal form: the cylinder y2² + y3² = y0² (x2² + x3²) about the common axis e1",
        &(y[2].mul_ref(&y[2]) + y[3].mul_ref(&y[3])),
        &y[0].mul_ref(&y[0]).mul_ref(&rho2),
    );
    let axial = y[1].sub_ref(&y[0].mul_ref(&x[0]));
    c.equal(
        "normal form: p1 (y1 - y0 x1) = 2 q1 uv + 2 q0 v², i.e. the axial displacement (q1/p1) sin φ + (q0/p1)(1 - cos φ)",
        &p1.mul_ref(&axial),
        &two(q1.mul_ref(&uv)).add_ref(&two(q0.mul_ref(&vv))),
    );
    c.check(
        "normal form: the axial displacement is the same for every point (vertical Darboux motion)",
        independent_of_point(&axial),
    );
    let plane = q1
        .mul_ref(&x[1].mul_ref(&y[3]).sub_ref(&x[2].mul_ref(&y[2])))
        .add_ref(&q0.mul_ref(&rho2.mul_ref(&y[0]).sub_ref(&x[1].mul_ref(&y[2])).sub_ref(&x[2].mul_ref(&y[3]))));
    c.equal(
        "normal form: the path lies in the plane p1 ρ² (y1 - y0 x1) = q1 (x2 y3 - x3 y2) + q0 (ρ² y0 - x2 y2 - x3 y3)",
        &p1.mul_ref(&rho2).mul_ref(&axial),
        &plane,
    );
    c.check("normal form: the path is a conic (degree 2 in λ)", y.iter().all(|e| quadratic_in(e, "λ")));
    let zero = |p: &Poly| p.substitute("q0", &Poly::zero()).substitute("q1", &Poly::zero());
    c.equal("normal form: q0 = q1 = 0 gives circles (no axial displacement)", &zero(&axial), &Poly::zero());
    let only_q0 = axial.substitute("q1", &Poly::zero()).substitute("q0", &Poly::one());
    c.counterexample(
        "every pencil moves points on circles",
        only_q0 == Poly::zero(),
        format!("C = p0 + p1 e23 + ω: the axial displacement times u² + v² is {only_q0}"),
    );
}

/// Random poses with every coefficient non-zero (non-unit, with ω parts).
fn random_pose(g: &mut crate::juttler::Lcg) -> Pose<Q> {
    let mut k: Vec<Q> = (0..8).map(|_| g.next()).collect();
    k[0] = &k[0] + q(3);
    Pose::new(
        k[0].clone(),
        k[1].clone(),
        k[2].clone(),
        k[3].clone(),
        k[4].clone(),
        k[5].clone(),
        k[6].clone(),
        k[7].clone(),
    )
}

fn general(c: &mut Checker) {
    let mut g = crate::juttler::Lcg(5252);
    let lam = var("λ");
    let x = point();
    for k in 0..3 {
        let (a, b) = (random_pose(&mut g), random_pose(&mut g));
        let Some(ainv) = c.ok(format!("instance {k}: A⁻¹"), a.try_inverse()) else { continue };
        let cc = &ainv * &b;
        c.equal_mv(format!("instance {k}: A C = B for C = A⁻¹B"), &(&lift(&a) * &lift(&cc)), &lift(&b));
        // the axis of C: direction a (the rotation axis), point c with (R - I + a aᵀ) c = -s⊥
        let cm = lift(&cc);
        let img = |p: [Poly; 3], w: Poly| {
            let terms = [("e0", w), ("e1", p[0].clone()), ("e2", p[1].clone()), ("e3", p[2].clone())];
            let y = cm.sandwich(&Multivector::from_terms(&alg(), Basis::Product, terms).expect("basis"));
            ["e0", "e1", "e2", "e3"].map(|n| to_q(y.coeff_by_name(n).expect("basis")))
        };
        let unit = |i: usize| std::array::from_fn(|j| if i == j { Poly::one() } else { Poly::zero() });
        let origin = img([Poly::zero(), Poly::zero(), Poly::zero()], Poly::one());
        let alpha = origin[0].clone();
        let s: [Q; 3] = std::array::from_fn(|i| &origin[i + 1] / &alpha);
        let cols: Vec<[Q; 3]> = (0..3)
            .map(|j| {
                let y = img(unit(j), Poly::zero());
                std::array::from_fn(|i| &y[i + 1] / &alpha)
            })
            .collect();
        let comps = cc.components();
        let ax = [comps[3].clone(), -comps[2].clone(), comps[1].clone()];
        let aa = ax.iter().fold(q(0), |acc, e| acc + e * e);
        let sa = (0..3).fold(q(0), |acc, i| acc + &s[i] * &ax[i]);
        let mat: Vec<Vec<Q>> = (0..3)
            .map(|i| (0..3).map(|j| &cols[j][i] - if i == j { q(1) } else { q(0) } + &ax[i] * &ax[j]).collect())
            .collect();
        let rhs: Vec<Q> = (0..3).map(|i| -(&s[i] - &sa / &aa * &ax[i])).collect();
        let Some(cp) = c.ok(format!("instance {k}: the axis point of C"), solve(mat, rhs).ok_or("singular")) else {
            continue;
        };
        let moved: Vec<Q> =
            (0..3).map(|i| (0..3).fold(s[i].clone(), |acc, j| acc + &cols[j][i] * &cp[j]) - &cp[i]).collect();
        let par = (0..3).all(|i| &moved[(i + 1) % 3] * &ax[(i + 2) % 3] == &moved[(i + 2) % 3] * &ax[(i + 1) % 3]);
        c.check(format!("instance {k}: F_C(c) - c is along the axis a (c is on C's screw axis)"), par);
        // the trajectory of x under S(λ) = (1 - λ)A + λB, and its start F_A(x)
        let s_lam = &lift(&a).scale(&Poly::one().sub_ref(&lam)) + &lift(&b).scale(&lam);
        let y = image(&s_lam, &x);
        let ya = image(&lift(&a), &x);
        let inv_alpha_a = Poly::from_q(&(q(1) / to_q(&ya[0])));
        let xa: [Poly; 3] = std::array::from_fn(|i| ya[i + 1].mul_ref(&inv_alpha_a));
        let (axp, cpp) = (ax.clone().map(|e| c_(&e)), [c_(&cp[0]), c_(&cp[1]), c_(&cp[2])]);
        let off: [Poly; 3] = std::array::from_fn(|i| y[i + 1].sub_ref(&y[0].mul_ref(&cpp[i])));
        let off0: [Poly; 3] = std::array::from_fn(|i| xa[i].sub_ref(&cpp[i]));
        let (d, d0) = (cross(&off, &axp), cross(&off0, &axp));
        c.equal(
            format!("instance {k}: |(y - y0 c) × a|² = y0² |(F_A(x) - c) × a|² (a cylinder about C's axis)"),
            &dot(&d, &d),
            &y[0].mul_ref(&y[0]).mul_ref(&dot(&d0, &d0)),
        );
        let yx: [Poly; 3] = std::array::from_fn(|i| y[i + 1].sub_ref(&y[0].mul_ref(&xa[i])));
        let axial = dot(&yx, &axp);
        c.check(format!("instance {k}: a · (y - y0 F_A(x)) is the same for every point"), independent_of_point(&axial));
        // y0 = α_A (u² + λ² |a|²): the angle of the pencil, u = 1 - λ + λ C∅
        let u = Poly::one().sub_ref(&lam).add_ref(&lam.mul_ref(&c_(comps[0])));
        let alpha_a = ya[0].clone();
        c.equal(
            format!("instance {k}: y0 = α_A (u² + λ²|a|²), u = 1 - λ + λ C∅"),
            &y[0],
            &alpha_a.mul_ref(&u.mul_ref(&u).add_ref(&lam.mul_ref(&lam).mul_ref(&c_(&aa)))),
        );
        c.check(
            format!(
                "instance {k}: the axial displacement times y0 has no constant term and degree <= 2 in λ (Darboux form)"
            ),
            quadratic_in(&axial, "λ") && axial.substitute("λ", &Poly::zero()) == Poly::zero(),
        );
    }
}

fn c_(x: &Q) -> Poly {
    Poly::from_q(x)
}

/// The value of a constant polynomial.
fn to_q(p: &Poly) -> Q {
    algebra_core::MpRational(p.as_constant().expect("a constant")).to_q()
}

/// The example of Sec. 5.2 with π a symbol.
fn example(c: &mut Checker) {
    let (lam, pi) = (var("λ"), var("π"));
    let x = point();
    let frac = |n: i64, d: i64| c_(&ratio(n, d));
    // ν0 = -π/4 e23 + 8 e3∞, γ0 = 1/2 + ω/2; S1(λ0) = 1 + λ0 (ν0 + γ0)/6
    let nu0 = even_of(&[("e23", pi.mul_ref(&frac(-1, 4))), ("e3inf", int(8))]);
    let gamma0 = even_of(&[("1", frac(1, 2)), ("e123inf", frac(1, 2))]);
    let one = Multivector::scalar(&alg(), Basis::Product, Poly::one());
    let y_step = (&nu0 + &gamma0).scale(&frac(1, 6));
    let s1 = &one + &y_step.scale(&lam);
    c.equal_mv(
        "S1(λ0) = (1 - λ0) S1(0) + λ0 S1(1): an additive Bézier motion of degree 1 in λ0",
        &s1,
        &(&one.scale(&Poly::one().sub_ref(&lam)) + &(&one + &y_step).scale(&lam)),
    );
    let y = image(&s1, &x);
    let off = |p: &[Poly; 4]| {
        let (a, b) = (pi.mul_ref(&p[2]).sub_ref(&int(32).mul_ref(&p[0])), pi.mul_ref(&p[3]));
        a.mul_ref(&a) + b.mul_ref(&b)
    };
    let start = [Poly::one(), x[0].clone(), x[1].clone(), x[2].clone()];
    c.equal(
        "S1: the cylinder about the axis through (0, 32/π, 0) along e1: (π y2 - 32 y0)² + (π y3)² = y0² ((π x2 - 32)² + (π x3)²)",
        &off(&y),
        &y[0].mul_ref(&y[0]).mul_ref(&off(&start)),
    );
    let axial1 = y[1].sub_ref(&y[0].mul_ref(&x[0]));
    c.equal(
        "S1: the axial displacement 144 (y1 - y0 x1) = -π λ0² (every point)",
        &axial1.mul_ref(&int(144)),
        &pi.mul_ref(&lam).mul_ref(&lam).neg_ref(),
    );
    c.check("S1: the paths are conics (degree 2 in λ0)", y.iter().all(|e| quadratic_in(e, "λ")));
    let at4 = {
        let pi_f = std::f64::consts::PI;
        let (u, v) = (1.0 + 4.0 / 12.0, 4.0 * pi_f / 24.0);
        -pi_f * 16.0 / 144.0 / (u * u + v * v)
    };
    c.counterexample(
        "the additive S1(λ0) moves points along circular arcs",
        axial1 == Poly::zero(),
        format!(
            "S1(λ0) = 1 + λ0(ν0 + γ0)/6: every point moves along e1 by -πλ0²/(144 y0) (the ω part of γ0), e.g. {at4:.4} at \
             λ0 = 4: ellipses out of the plane x = 0 of the end poses, circular only in the view along e1"
        ),
    );
    // S2(λ3) = S3 (1 - λ3 (ν3 + γ3)/6), S3 = (√2/2)(1 - e23 + 5 e2∞ + 5 e3∞) (a scale does not move points)
    let s3 = even_of(&[("1", int(1)), ("e23", int(-1)), ("e2inf", int(5)), ("e3inf", int(5))]);
    let nu3 = even_of(&[("e23", pi.mul_ref(&frac(1, 8))), ("e2inf", int(4)), ("e3inf", pi.mul_ref(&frac(-5, 4)))]);
    let gamma3 = even_of(&[("1", int(1)), ("e123inf", frac(-1, 2))]);
    let s2 = &s3 * &(&one - &(&nu3 + &gamma3).scale(&frac(1, 6)).scale(&lam));
    let y = image(&s2, &x);
    let y3s = image(&s3, &x);
    let off2 = |p: &[Poly; 4]| {
        let (a, b) = (
            pi.mul_ref(&p[2]).sub_ref(&int(10).mul_ref(&pi).mul_ref(&p[0])),
            pi.mul_ref(&p[3]).sub_ref(&int(32).mul_ref(&p[0])),
        );
        a.mul_ref(&a) + b.mul_ref(&b)
    };
    // y0 carries α(S3') = 2: compare with the start F_S3(x), whose weight is 2 as well
    c.equal(
        "S2: the cylinder about the axis through (0, 10, 32/π) along e1, with the start F_S3(x)",
        &off2(&y).mul_ref(&y3s[0]).mul_ref(&y3s[0]),
        &y[0].mul_ref(&y[0]).mul_ref(&off2(&y3s)),
    );
    let axial2 = y[1].mul_ref(&y3s[0]).sub_ref(&y[0].mul_ref(&y3s[1]));
    c.equal(
        "S2: the axial displacement 144 (y1 - y0 x1') = -π λ3² (x1' = F_S3(x)_1; both sides times α(S3'))",
        &axial2.mul_ref(&int(144)),
        &pi.mul_ref(&lam).mul_ref(&lam).mul_ref(&y3s[0]).neg_ref(),
    );
    // Fig. 8, multiplicative: S1(λ0) = exp(λ0 Y), Y = (ν0 + γ0)/6 = (1 + ω)/12 + ν0/6
    let omega = even_of(&[("e123inf", Poly::one())]);
    c.equal_mv("Y = (1 + ω)/12 + ν0/6", &y_step, &(&(&one + &omega).scale(&frac(1, 12)) + &nu0.scale(&frac(1, 6))));
    c.equal_mv("ω ν0 = ν0 ω and ω² = 0: exp(λY) = e^{λ/12} (1 + λω/12) exp(λν0/6)", &(&omega * &nu0), &(&nu0 * &omega));
    c.equal_mv("ω² = 0", &(&omega * &omega), &one.scale(&Poly::zero()));
    c.equal_mv(
        "ν0² = -(π/4)²: exp(μν0) = cos(μπ/4) + sin(μπ/4) ν0/(π/4), in the pencil of 1 and ν0",
        &(&nu0 * &nu0),
        &one.scale(&pi.mul_ref(&pi).mul_ref(&frac(-1, 16))),
    );
    let gsym = even(["S", "S12", "S13", "S23", "S1inf", "S2inf", "S3inf", "Sw"].map(var));
    let factor = even_of(&[("1", var("a")), ("e123inf", var("b"))]);
    let ys = image(&gsym, &x);
    let scaled = image(&(&factor * &gsym), &x);
    c.equal(
        "a pseudoscalar factor (a + bω) S moves points as S: the image is a² times that of S",
        &scaled,
        &ys.clone().map(|e| e.mul_ref(&var("a")).mul_ref(&var("a"))),
    );
    let mu = var("μ");
    let pencil = &one + &nu0.scale(&mu);
    let yp = image(&pencil, &x);
    c.equal(
        "1 + μν0 (no ω part): no axial displacement, so Fig. 8's multiplicative S1(λ0) moves points on circular arcs",
        &yp[1].sub_ref(&yp[0].mul_ref(&x[0])),
        &Poly::zero(),
    );
    c.equal(
        "1 + μν0: on the same cylinder as the additive S1",
        &off(&yp),
        &yp[0].mul_ref(&yp[0]).mul_ref(&off(&start)),
    );
}

fn sec_5_2_darboux(c: &mut Checker) {
    normal_form(c);
    general(c);
    example(c);
}
