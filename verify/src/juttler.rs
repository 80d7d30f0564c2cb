//! Jüttler, "Visualization of moving objects using dual quaternion curves", statement by
//! statement. The paper's formulas are typed in below (an independent reference) and compared
//! with GAM's [`DualQuaternion`] / [`Pose`](motion::Pose) and with a second computation:
//!
//! * `juttler/eq-8` (Plücker's relation): for the dual quaternion `Q = (2v0 + εv)(d0 + d)` of
//!   eq. (7), with all eight parameters symbolic (`Poly`): the library product equals the
//!   expanded right-hand side of (7), and `Du(Q Q~) = 0`. For a *general* symbolic `Q`,
//!   `Du(Q Q~) = 2 (q0 qε + q0·qε)`: the printed middle member of (8) lacks the factor 2 (the
//!   relation "= 0" is unaffected); the library's `norm_squared` has the factor.
//! * `juttler/eq-9`: `Trans(Q) = Q Q~0` and `Rot(Q) = Q0 / (Q0 Q~0)`. Symbolic for (7):
//!   `Trans(Q) = 2v0|D|² (2v0 + εv)` (same translation v/v0), `Rot(Q) ∝ D`,
//!   `Trans(Q) Rot(Q) = Q`. For a general symbolic `Q` the dual scalar part of `Q Q~0` is
//!   exactly the Plücker form, so `Trans(Q)` is a translation (5) iff (8) holds: a counterexample
//!   without (8) is recorded. Against the library: `2 + εv = 2 · from_translation(v)`.
//! * `juttler/eq-12`: the point map `y0 = (Q0 Q~0) x0`, `y = Du Vec(Q (2x0 + εx) Q~0)`.
//!   Symbolic for (7): `y = 4 v0 · M x` with `M`, `U` of eqs. (10), (11) typed in (the same
//!   homogeneous point), and `U Uᵀ = |D|⁴ I`. Exact rationals for random `Q` with (8): the
//!   Euclidean point `y/y0` equals `DualQuaternion::transform_point` and
//!   `Pose::transform_point` of the corresponding pose; for a `Q` without (8), (12) equals the
//!   motion of `Q` projected onto (8) (only `Vec(Qε Q~0)` enters).
//! * `juttler/eq-29`: the Bernstein product formula, symbolic in `t` for all degrees
//!   `k, l <= 4`; and the TR product `Q_trans(t) Q_rot(t)` of Bézier dual quaternion curves
//!   (rational control points) equals the Bézier curve whose control points are obtained with
//!   (29), and satisfies (8) identically in `t`.
//!
//! Propositions 1-4, Result 5 and Theorem 6 (the interpolation methods of Secs. 3-5) are in
//! [`interpolation`]; the converse part of Theorem 6 (every rational motion of order n has the
//! form (35)) in [`converse`].

pub mod converse;
pub mod interpolation;

use crate::{Checker, Method, Paper, Statement};
use algebra_core::rational::{Q, q, ratio};
use algebra_core::{Poly, Ring};
use gam_algebras::DualQuaternion;
use gam_algebras::dual_quaternion::Quaternion;

/// The statements of this paper, in paper order.
pub const STATEMENTS: &[Statement] = &[
    Statement {
        id: "juttler/eq-8",
        paper: Paper::Juttler,
        label: "Eq. (8)",
        statement: "the dual quaternion Q = (2v0 + εv)(d0 + d) of eq. (7) satisfies Plücker's relation \
                    Du(Q Q~) = q0 qε + q0·qε = 0",
        method: Method::Symbolic,
        hypotheses: "the middle member is off by a factor 2: Du(Q Q~) = 2(q0 qε + q0·qε) for every Q (the \
                     relation = 0 is unaffected)",
        check: eq_8,
    },
    Statement {
        id: "juttler/eq-9",
        paper: Paper::Juttler,
        label: "Eq. (9)",
        statement: "a dual quaternion Q with (8) and Q0 != 0 is a displacement with translational part \
                    Trans(Q) = Q Q~0 and rotational part Rot(Q) = Q0/(Q0 Q~0); Q = Trans(Q) Rot(Q)",
        method: Method::Symbolic,
        hypotheses: "(8) is needed: without it Q Q~0 has a dual scalar part (not a translation (5)). Rot(Q) is \
                     'normalized' only in the sense Trans(Q) Rot(Q) = Q: Rot Rot~ = 1/(Q0 Q~0), not 1",
        check: eq_9,
    },
    Statement {
        id: "juttler/eq-12",
        paper: Paper::Juttler,
        label: "Eq. (12)",
        statement: "the image of the homogeneous point (x0, x) is y0 = (Q0 Q~0) x0, y = Du Vec(Q (2x0 + εx) Q~0), \
                    the same point as M x with M, U of eqs. (10), (11)",
        method: Method::Symbolic,
        hypotheses: "y = 4 v0 M x: the same homogeneous point, not the same coordinates. U is orthogonal only up \
                     to the factor |D|² (U Uᵀ = |D|⁴ I). (8) is not needed: a Q off the quadric acts as its projection onto it",
        check: eq_12,
    },
    Statement {
        id: "juttler/eq-29",
        paper: Paper::Juttler,
        label: "Eq. (29)",
        statement: "b_i^k(t) b_j^l(t) = C(k,i) C(l,j) / C(k+l,i+j) b_{i+j}^{k+l}(t); hence the control points of \
                    Q_trans(t) * Q_rot(t) are B_r = sum_{i+j=r} C(l,i)C(k,j)/C(k+l,r) P_i * C_j",
        method: Method::Symbolic,
        hypotheses: "",
        check: eq_29,
    },
];

type Dq<T> = DualQuaternion<T>;

fn v(name: &str) -> Poly {
    Poly::var(name)
}

fn dot3<T: Ring>(a: &[T; 3], b: &[T; 3]) -> T {
    a[0].mul_ref(&b[0]) + a[1].mul_ref(&b[1]) + a[2].mul_ref(&b[2])
}

fn cross3<T: Ring>(a: &[T; 3], b: &[T; 3]) -> [T; 3] {
    [
        a[1].mul_ref(&b[2]).sub_ref(&a[2].mul_ref(&b[1])),
        a[2].mul_ref(&b[0]).sub_ref(&a[0].mul_ref(&b[2])),
        a[0].mul_ref(&b[1]).sub_ref(&a[1].mul_ref(&b[0])),
    ]
}

/// The conjugate of eq. (4): `(q0 - q) + ε(qε - qε_vec)`, the library's quaternion conjugate.
fn tilde<T: Ring>(x: &Dq<T>) -> Dq<T> {
    x.conjugate()
}

/// The real part `Q0` as a dual quaternion with zero dual part.
fn re<T: Ring>(x: &Dq<T>) -> Dq<T> {
    Dq::from_real(x.real.clone())
}

/// The translation `2v0 + εv` of eq. (5).
pub(crate) fn translation5<T: Ring>(v0: &T, v: &[T; 3]) -> Dq<T> {
    Dq::new(Quaternion::new(v0.add_ref(v0), T::zero(), T::zero(), T::zero()), Quaternion::pure(v))
}

/// Symbolic parameters of eq. (7): `v0, v, d0, d`.
struct Params {
    v0: Poly,
    v: [Poly; 3],
    d0: Poly,
    d: [Poly; 3],
}

fn params() -> Params {
    Params { v0: v("v0"), v: [v("v1"), v("v2"), v("v3")], d0: v("d0"), d: [v("d1"), v("d2"), v("d3")] }
}

/// `Q = (2v0 + εv) * (d0 + d)` of eq. (7), computed with the library product.
fn q7(p: &Params) -> Dq<Poly> {
    let rot = Dq::from_real(Quaternion::new(p.d0.clone(), p.d[0].clone(), p.d[1].clone(), p.d[2].clone()));
    &translation5(&p.v0, &p.v) * &rot
}

/// The right-hand side of (7), typed in: `2v0d0 + 2v0 d + ε(-v·d + d0 v + v × d)`.
fn q7_expanded(p: &Params) -> Dq<Poly> {
    let two_v0 = p.v0.add_ref(&p.v0);
    let vxd = cross3(&p.v, &p.d);
    let dual_vec: [Poly; 3] = std::array::from_fn(|i| p.d0.mul_ref(&p.v[i]).add_ref(&vxd[i]));
    Dq::new(
        Quaternion::new(
            two_v0.mul_ref(&p.d0),
            two_v0.mul_ref(&p.d[0]),
            two_v0.mul_ref(&p.d[1]),
            two_v0.mul_ref(&p.d[2]),
        ),
        Quaternion::new(dot3(&p.v, &p.d).neg_ref(), dual_vec[0].clone(), dual_vec[1].clone(), dual_vec[2].clone()),
    )
}

/// The Plücker form `q0 qε + q0·qε` as printed in (8).
fn plucker<T: Ring>(x: &Dq<T>) -> T {
    x.real.dot(&x.dual)
}

/// A general dual quaternion with eight symbolic coefficients.
fn general_symbolic() -> Dq<Poly> {
    Dq::from_coeffs(["a0", "a1", "a2", "a3", "b0", "b1", "b2", "b3"].map(v))
}

fn eq_8(c: &mut Checker) {
    let p = params();
    let qq = q7(&p);
    c.equal("(7): library product (2v0 + εv)(d0 + d) = the expanded right-hand side", &qq, &q7_expanded(&p));
    let n = &qq * &tilde(&qq);
    c.equal("(8): Du(Q Q~) = 0 for Q of (7)", &n.dual, &Quaternion::zero());
    c.equal("(8): q0 qε + q0·qε = 0 for Q of (7)", &plucker(&qq), &Poly::zero());
    c.equal("(8): library norm_squared dual part = 0 for Q of (7)", &qq.norm_squared().1, &Poly::zero());
    // The middle member for a general Q.
    let g = general_symbolic();
    let ng = &g * &tilde(&g);
    let twice = plucker(&g).add_ref(&plucker(&g));
    c.equal(
        "Du(Q Q~) = 2(q0 qε + q0·qε) for a general symbolic Q",
        &ng.dual,
        &Quaternion::new(twice, Poly::zero(), Poly::zero(), Poly::zero()),
    );
    let one_eps = Dq::<Q>::dual_number(q(1), q(1));
    let du = (&one_eps * &tilde(&one_eps)).dual.w;
    c.counterexample(
        "the printed Du(Q Q~) = q0 qε + q0·qε (without the factor 2)",
        du == plucker(&one_eps),
        format!("Q = 1 + ε: Du(Q Q~) = {du}, q0 qε + q0·qε = {}; OCR/typo: the factor 2 is missing", plucker(&one_eps)),
    );
}

/// A small deterministic rational generator for exact instances.
pub(crate) struct Lcg(pub(crate) u64);

impl Lcg {
    pub(crate) fn next(&mut self) -> Q {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        let n = ((self.0 >> 33) % 19) as i64 - 9;
        let d = ((self.0 >> 20) % 5) as i64 + 1;
        ratio(n, d)
    }

    fn dq(&mut self) -> Dq<Q> {
        Dq::from_coeffs(std::array::from_fn(|_| self.next()))
    }
}

/// `Q` made to satisfy (8) by removing the Q0-component of the dual part (exact).
fn project_plucker(x: &Dq<Q>) -> Dq<Q> {
    let k = plucker(x) / x.real.norm_squared();
    let dual = Quaternion::new(
        x.dual.w.clone() - &k * &x.real.w,
        x.dual.x.clone() - &k * &x.real.x,
        x.dual.y.clone() - &k * &x.real.y,
        x.dual.z.clone() - &k * &x.real.z,
    );
    Dq::new(x.real.clone(), dual)
}

fn eq_9(c: &mut Checker) {
    let p = params();
    let qq = q7(&p);
    let d2 = p.d0.mul_ref(&p.d0) + dot3(&p.d, &p.d);
    let two_v0 = p.v0.add_ref(&p.v0);
    let trans = &qq * &tilde(&re(&qq));
    c.equal(
        "(9): Trans(Q) = Q Q~0 = 2v0|D|² (2v0 + εv) for Q of (7)",
        &trans,
        &translation5(&p.v0, &p.v).scale(&two_v0.mul_ref(&d2)),
    );
    // Rot(Q) (Q0 Q~0) = Q0 = 2v0 D: Rot(Q) is proportional to D.
    let q0n = qq.real.norm_squared();
    c.equal("(9): Q0 Q~0 = 4v0²|D|²", &q0n, &two_v0.mul_ref(&two_v0).mul_ref(&d2));
    let d = Quaternion::new(p.d0.clone(), p.d[0].clone(), p.d[1].clone(), p.d[2].clone());
    c.equal("(9): Rot(Q)·(Q0 Q~0) = Q0 = 2v0 (d0 + d)", &qq.real, &d.scale(&two_v0));
    // Trans(Q) * Rot(Q) = Q, cleared of the scalar denominator Q0 Q~0.
    let g = general_symbolic();
    let tr = &(&g * &tilde(&re(&g))) * &re(&g);
    c.equal("(9): Trans(Q) Rot(Q) (Q0 Q~0) = Q (Q0 Q~0) for a general Q", &tr, &g.scale(&g.real.norm_squared()));
    // For a general Q, Q Q~0 = |Q0|² + ε(Qε Q~0): its dual scalar part is the Plücker form.
    let tg = &g * &tilde(&re(&g));
    c.equal(
        "Trans(Q) has real part Q0 Q~0 (a real number)",
        &tg.real,
        &Quaternion::new(g.real.norm_squared(), Poly::zero(), Poly::zero(), Poly::zero()),
    );
    c.equal("the dual scalar part of Q Q~0 is q0 qε + q0·qε (zero iff (8))", &tg.dual.w, &plucker(&g));
    // Library translation convention: 2 + εv = 2 · (1 + ε v/2).
    c.equal(
        "2 + εv = 2 from_translation(v)",
        &translation5(&Poly::one(), &p.v),
        &Dq::from_translation(&p.v).scale(&Poly::from_i64(2)),
    );
    // Exact instances: with (8), Trans(Q) is of the form (5); Rot(Q)Rot(Q)~ = 1/(Q0 Q~0).
    let mut rng = Lcg(9);
    for k in 0..4 {
        let raw = rng.dq();
        let good = project_plucker(&raw);
        let t = &good * &tilde(&re(&good));
        c.equal(format!("instance {k}: Trans(Q) with (8) has zero dual scalar part"), &t.dual.w, &q(0));
        let n0 = good.real.norm_squared();
        let rot = good.real.scale(&(q(1) / &n0));
        c.equal(format!("instance {k}: Rot(Q) Rot(Q)~ = 1/(Q0 Q~0)"), &rot.norm_squared(), &(q(1) / &n0));
        if k == 0 {
            let tr = &raw * &tilde(&re(&raw));
            c.counterexample(
                "Trans(Q) = Q Q~0 is a translation (5) without (8)",
                tr.dual.w == q(0),
                format!("Q = {raw}: dual scalar part of Q Q~0 = {}", tr.dual.w),
            );
            c.note("Rot(Q) of (9) satisfies Rot Rot~ = 1/(Q0 Q~0): 'normalized' means Trans(Q) Rot(Q) = Q; the Euler-parameter normalization (6) would be Q0/sqrt(Q0 Q~0)");
        }
    }
}

/// The image of (12): `(y0, y)` for the homogeneous point `(x0, x)`.
pub(crate) fn image12<T: Ring>(qq: &Dq<T>, x0: &T, x: &[T; 3]) -> (T, [T; 3]) {
    let y0 = qq.real.norm_squared().mul_ref(x0);
    let pt = translation5(x0, x);
    let w = &(qq * &pt) * &tilde(&re(qq));
    (y0, w.dual.vector())
}

/// U of eq. (11), typed in.
pub(crate) fn u11<T: Ring>(d0: &T, d: &[T; 3]) -> [[T; 3]; 3] {
    let two = |x: T| x.add_ref(&x);
    let (s0, s1, s2, s3) = (d0.mul_ref(d0), d[0].mul_ref(&d[0]), d[1].mul_ref(&d[1]), d[2].mul_ref(&d[2]));
    let m = |a: &T, b: &T| a.mul_ref(b);
    [
        [
            s0.add_ref(&s1).sub_ref(&s2).sub_ref(&s3),
            two(m(&d[0], &d[1]).sub_ref(&m(d0, &d[2]))),
            two(m(d0, &d[1]).add_ref(&m(&d[0], &d[2]))),
        ],
        [
            two(m(d0, &d[2]).add_ref(&m(&d[0], &d[1]))),
            s0.add_ref(&s2).sub_ref(&s1).sub_ref(&s3),
            two(m(&d[1], &d[2]).sub_ref(&m(d0, &d[0]))),
        ],
        [
            two(m(&d[0], &d[2]).sub_ref(&m(d0, &d[1]))),
            two(m(d0, &d[0]).add_ref(&m(&d[1], &d[2]))),
            s0.add_ref(&s3).sub_ref(&s1).sub_ref(&s2),
        ],
    ]
}

fn eq_12(c: &mut Checker) {
    let p = params();
    let qq = q7(&p);
    let (x0, x) = (v("x0"), [v("x1"), v("x2"), v("x3")]);
    let (y0, y) = image12(&qq, &x0, &x);
    // M x of (10): (|D|² v0 x0, |D|² x0 v + v0 U x).
    let d2 = p.d0.mul_ref(&p.d0) + dot3(&p.d, &p.d);
    let u = u11(&p.d0, &p.d);
    let mx0 = d2.mul_ref(&p.v0).mul_ref(&x0);
    let mx: [Poly; 3] =
        std::array::from_fn(|i| d2.mul_ref(&p.v[i]).mul_ref(&x0).add_ref(&p.v0.mul_ref(&dot3(&u[i], &x))));
    let f = Poly::from_i64(4).mul_ref(&p.v0);
    c.equal("(12) vs (10): y0 = 4v0 (M x)_0", &y0, &f.mul_ref(&mx0));
    c.equal("(12) vs (10): y = 4v0 (M x)_vec", &y, &mx.map(|e| f.mul_ref(&e)));
    let d4 = d2.mul_ref(&d2);
    let uut: [[Poly; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| dot3(&u[i], &u[j])));
    let expect: [[Poly; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|j| if i == j { d4.clone() } else { Poly::zero() }));
    c.equal("(11): U Uᵀ = |D|⁴ I", &uut, &expect);
    // Without (8): (12) still defines a rigid motion, the one of Q with its dual part projected onto (8).
    let raw = Lcg(120).dq();
    let x: [Q; 3] = [q(1), q(-2), ratio(1, 3)];
    let (y0, y) = image12(&raw, &q(1), &x);
    let ours = y.map(|e| e / &y0);
    let projected = project_plucker(&raw).transform_point(&x);
    c.equal("(12) for Q without (8) = the motion of Q projected onto (8)", &Some(ours), &projected);
    // (The findings are in the statement's `hypotheses`: 4 v0 M x, U U^T = |D|^4 I, (8) not needed.)
    // Exact instances with (8): the Euclidean image equals the library's.
    let mut rng = Lcg(12);
    for k in 0..4 {
        let good = project_plucker(&rng.dq());
        let x: [Q; 3] = std::array::from_fn(|_| rng.next());
        let (y0, y) = image12(&good, &q(1), &x);
        let ours = y.map(|e| e / &y0);
        if let Some(lib) = good.transform_point(&x) {
            c.equal(format!("instance {k}: (12) = DualQuaternion::transform_point"), &ours, &lib);
        } else {
            c.fail(format!("instance {k}: transform_point returned None"));
        }
        let pose = motion::Pose::from_motor(good.to_pose());
        if let Some(lib) = c.ok(format!("instance {k}: Pose::transform_point"), pose.transform_point(&x)) {
            c.equal(format!("instance {k}: (12) = Pose::transform_point of the same motion"), &ours, &lib);
        }
    }
}

pub(crate) fn binom(n: u32, k: u32) -> i64 {
    (0..k).fold(1i64, |acc, i| acc * i64::from(n - i) / i64::from(i + 1))
}

pub(crate) fn bernstein(n: u32, i: u32, t: &Poly) -> Poly {
    let one_minus = Poly::one().sub_ref(t);
    Poly::from_i64(binom(n, i)).mul_ref(&t.pow_u32(i)).mul_ref(&one_minus.pow_u32(n - i))
}

/// A Bézier curve with dual quaternion control points, as a polynomial in `t`.
fn bezier(points: &[Dq<Poly>], t: &Poly) -> Dq<Poly> {
    let n = (points.len() - 1) as u32;
    points.iter().enumerate().fold(Dq::zero(), |acc, (i, b)| &acc + &b.scale(&bernstein(n, i as u32, t)))
}

fn lift(x: &Dq<Q>) -> Dq<Poly> {
    Dq::from_coeffs(x.coeffs().map(|e| Poly::from_q(&e)))
}

fn eq_29(c: &mut Checker) {
    let t = v("t");
    for k in 0..=4u32 {
        for l in 0..=4u32 {
            for i in 0..=k {
                for j in 0..=l {
                    let lhs =
                        bernstein(k, i, &t).mul_ref(&bernstein(l, j, &t)).mul_ref(&Poly::from_i64(binom(k + l, i + j)));
                    let rhs = bernstein(k + l, i + j, &t).mul_ref(&Poly::from_i64(binom(k, i) * binom(l, j)));
                    c.equal(format!("(29): k={k} l={l} i={i} j={j}, cleared of C(k+l,i+j)"), &lhs, &rhs);
                }
            }
        }
    }
    // TR product: Q_trans of degree l = 2 (control points 2 + ε p_j), Q_rot of degree k = 3.
    let mut rng = Lcg(29);
    let (l, k) = (2u32, 3u32);
    let trans: Vec<Dq<Q>> = (0..=l).map(|_| translation5(&q(1), &std::array::from_fn(|_| rng.next()))).collect();
    let rot: Vec<Dq<Q>> = (0..=k).map(|_| Dq::from_real(rng.dq().real)).collect();
    let mut b: Vec<Dq<Q>> = vec![Dq::zero(); (k + l + 1) as usize];
    for (i, pi) in trans.iter().enumerate() {
        for (j, cj) in rot.iter().enumerate() {
            let (i, j) = (i as u32, j as u32);
            let w = ratio(binom(l, i) * binom(k, j), binom(k + l, i + j));
            let r = (i + j) as usize;
            b[r] = &b[r] + &(pi * cj).scale(&w);
        }
    }
    let tl: Vec<Dq<Poly>> = trans.iter().map(lift).collect();
    let rl: Vec<Dq<Poly>> = rot.iter().map(lift).collect();
    let prod = &bezier(&tl, &t) * &bezier(&rl, &t);
    let bl: Vec<Dq<Poly>> = b.iter().map(lift).collect();
    c.equal("(29): Q_trans(t) Q_rot(t) = Bézier curve with control points from (29)", &prod, &bezier(&bl, &t));
    c.equal("the product is a Q-motion: Plücker form (8) vanishes identically in t", &plucker(&prod), &Poly::zero());
}
