//! The second part of Jüttler's Theorem 6 (Sec. 5): "Conversely, let a rational motion of order
//! n by its matrix representation R = R(t) be given. Then a number k satisfying 0 ≤ k ≤ n/2 and
//! 8 polynomials w0*(t), w_i(t) and d_j(t) of the above maximal degrees exist, such that
//! R(t) = ξ(t) M(t)" with `M` of (35). The paper omits the proof (it cites its ref. \[9\]); the
//! first part is `juttler/theorem-6` in [`super::interpolation`].
//!
//! `juttler/theorem-6-converse` checks it by constructing the data from `R` alone, exactly, on
//! rational motions from several sources (and a fixed and a moving frame changed, an extra
//! scalar factor), with `t` a symbol and polynomial arithmetic over Q:
//!
//! 1. `ξ` = the gcd of the entries of `R`; `R' = R/ξ`; the order `n` is the degree of `R'`
//!    (a point's trajectory `R'(1, x)` is checked to have degree `n` and no common factor);
//! 2. from `r0 = R'_00` and the rotation block `A`, the symmetric matrix `X` with
//!    `X_00 = r0 + tr A`, `X_01 = A_32 - A_23`, …, `X_12 = A_12 + A_21`, … (for `M` of (35) it
//!    is `4 w0* D Dᵀ`: checked symbolically); `X` has rank one; `D` = a non-zero row of `X`
//!    divided by the gcd of its entries, `k = deg D`;
//! 3. `w0* = r0 / |D|²` (an exact polynomial division: the heart of the converse), `w` = the
//!    first column of `R'`; then `A = w0* U(D)` with `U` of (11) typed in, the degree bounds
//!    `2k ≤ n`, `deg w0* ≤ n - 2k`, `deg w ≤ n`, and the library's
//!    [`MinimalMotion`] of these data (in Bernstein form) has the matrix `R'`, so `R = ξ M`.
//!
//! Symbolically (all coefficients symbols): the (12) matrix of a general dual quaternion `Q` is
//! (35) with `w0* = 1`, `D = Q0`, `w = 2 Vec(Qε Q~0)`, so every Q-motion of degree `m` is `ξ M`
//! with `k = m` before common factors are removed; and `X(M) = 4 w0* D Dᵀ`.
//!
//! Not checked by machine: that `|D|²` divides `r0` for *every* rational motion. It follows from
//! the primitivity of `D`: an irreducible `p` dividing `|D|²` and every entry of `U(D)` divides
//! every `d_i d_j` (linear combinations, as in `X`), hence every `d_i`; so the `p`-power of
//! `|D|²` divides `r0` because `A |D|² = r0 U(D)`.

use super::{Lcg, bernstein, binom, image12, translation5, u11};
use crate::{Checker, Method, Paper, Statement};
use algebra_core::rational::{Q, q, ratio};
use algebra_core::{MpRational, Poly, Ring};
use gam_algebras::DualQuaternion;
use gam_algebras::dual_quaternion::Quaternion;
use motion::juttler::minimal::MinimalMotion;
use num_traits::Zero;

/// The converse of Theorem 6 (after `juttler/theorem-6` in the registry).
///
/// ```
/// let s = &gam_verify::juttler::converse::STATEMENTS[0];
/// assert_eq!(s.id, "juttler/theorem-6-converse");
/// assert!(s.run().outcome.holds());
/// ```
pub const STATEMENTS: &[Statement] = &[Statement {
    id: "juttler/theorem-6-converse",
    paper: Paper::Juttler,
    label: "Theorem 6 (converse)",
    statement: "conversely, for a rational motion of order n given by its matrix R(t) there are k with \
                0 <= k <= n/2 and polynomials w0* (degree <= n-2k), w (<= n), D (<= k) with R = ξ(t) M(t), M of (35)",
    method: Method::Exact,
    hypotheses: "R(t) is a polynomial matrix of the form (10), weight first (a rational motion's matrix cleared of \
                 denominators); ξ is then the gcd of its entries, a polynomial. Checked: the construction of k, w0*, \
                 w, D from R on seven rational motions (generic and reduced-order Q-motions, (36) itself, a real \
                 factor, a translation, a Darboux motion off the Study quadric, changed frames), exactly in t; the \
                 two identities it rests on symbolically. Not machine-checked: |D|² | r0 for every motion (it \
                 follows from the primitivity of D)",
    check: theorem_6_converse,
}];

// ------------------------------------------------------------ univariate polynomials in t

/// Coefficients over Q, constant term first, no trailing zeros (the zero polynomial is empty).
type Up = Vec<Q>;

fn trim(mut a: Up) -> Up {
    while a.last().is_some_and(Zero::is_zero) {
        a.pop();
    }
    a
}

/// The coefficients of a polynomial in the one symbol `t`.
fn up(p: &Poly) -> Up {
    let mut out: Up = Vec::new();
    for (c, mono) in p.terms() {
        let k = match mono.as_slice() {
            [] => 0,
            [(name, e)] if name == "t" => *e as usize,
            _ => panic!("not a polynomial in t alone: {p}"),
        };
        if out.len() <= k {
            out.resize(k + 1, q(0));
        }
        out[k] = MpRational(c.clone()).to_q();
    }
    trim(out)
}

fn poly(a: &[Q]) -> Poly {
    let t = Poly::var("t");
    a.iter().rev().fold(Poly::zero(), |acc, c| acc.mul_ref(&t) + Poly::from_q(c))
}

/// The degree; `None` for the zero polynomial.
fn deg(p: &Poly) -> Option<usize> {
    up(p).len().checked_sub(1)
}

/// Quotient and remainder.
fn divrem(a: &[Q], b: &[Q]) -> (Up, Up) {
    let b = trim(b.to_vec());
    let lead = b.last().expect("division by the zero polynomial").clone();
    let mut r = trim(a.to_vec());
    let mut quo = vec![q(0); r.len().saturating_sub(b.len() - 1)];
    while r.len() >= b.len() {
        let k = r.len() - b.len();
        let f = r[r.len() - 1].clone() / &lead;
        for (i, bi) in b.iter().enumerate() {
            r[k + i] = &r[k + i] - &f * bi;
        }
        quo[k] = f;
        r = trim(r);
    }
    (trim(quo), r)
}

/// The monic gcd (empty for gcd(0, 0)).
fn gcd(a: &[Q], b: &[Q]) -> Up {
    let (mut a, mut b) = (trim(a.to_vec()), trim(b.to_vec()));
    while !b.is_empty() {
        let r = divrem(&a, &b).1;
        a = b;
        b = r;
    }
    match a.last().cloned() {
        Some(l) => a.iter().map(|c| c / &l).collect(),
        None => a,
    }
}

fn gcd_all<'a>(ps: impl IntoIterator<Item = &'a Poly>) -> Up {
    ps.into_iter().fold(Vec::new(), |g, p| gcd(&g, &up(p)))
}

/// `p / d` when `d` divides `p` exactly.
fn exact_div(p: &Poly, d: &[Q]) -> Option<Poly> {
    let (quo, rem) = divrem(&up(p), d);
    rem.is_empty().then(|| poly(&quo))
}

/// The Bernstein coefficients of degree `n` of a polynomial of degree <= n:
/// `b_i = Σ_{j<=i} C(i,j)/C(n,j) a_j`.
fn to_bernstein(p: &Poly, n: usize) -> Vec<Q> {
    let a = up(p);
    (0..=n)
        .map(|i| {
            (0..=i)
                .filter(|&j| j < a.len())
                .fold(q(0), |acc, j| acc + ratio(binom(i as u32, j as u32), binom(n as u32, j as u32)) * &a[j])
        })
        .collect()
}

// ------------------------------------------------------------ matrices

type M4 = [[Poly; 4]; 4];

fn mat_mul(a: &M4, b: &M4) -> M4 {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..4).fold(Poly::zero(), |acc, k| acc + a[i][k].mul_ref(&b[k][j])))
    })
}

/// The matrix of (12) (weight first): column 0 the image of the origin `(1, 0)`, column `j`
/// that of the direction `(0, e_j)`.
fn matrix_12(qq: &DualQuaternion<Poly>) -> M4 {
    let zero = [Poly::zero(), Poly::zero(), Poly::zero()];
    let e = |j: usize| std::array::from_fn(|i| if i == j { Poly::one() } else { Poly::zero() });
    let cols = [
        image12(qq, &Poly::one(), &zero),
        image12(qq, &Poly::zero(), &e(0)),
        image12(qq, &Poly::zero(), &e(1)),
        image12(qq, &Poly::zero(), &e(2)),
    ];
    std::array::from_fn(|i| std::array::from_fn(|j| if i == 0 { cols[j].0.clone() } else { cols[j].1[i - 1].clone() }))
}

/// `M` of (35) typed in: `[[w0* |D|², 0], [w, w0* U(D)]]`.
fn m35(w0: &Poly, w: &[Poly; 3], d: &Quaternion<Poly>) -> M4 {
    let u = u11(&d.w, &d.vector());
    let z = Poly::zero;
    let row = |i: usize| [w[i].clone(), w0.mul_ref(&u[i][0]), w0.mul_ref(&u[i][1]), w0.mul_ref(&u[i][2])];
    [[w0.mul_ref(&d.norm_squared()), z(), z(), z()], row(0), row(1), row(2)]
}

/// `X` read off a matrix of the form (10): `4 w0* D Dᵀ` for `M` of (35).
fn x_matrix(m: &M4) -> [[Poly; 4]; 4] {
    let a = |i: usize, j: usize| &m[i][j];
    let r0 = &m[0][0];
    let (s01, s02, s03) = (a(3, 2).sub_ref(a(2, 3)), a(1, 3).sub_ref(a(3, 1)), a(2, 1).sub_ref(a(1, 2)));
    let (s12, s13, s23) = (a(1, 2).add_ref(a(2, 1)), a(1, 3).add_ref(a(3, 1)), a(2, 3).add_ref(a(3, 2)));
    let diag = |s: [i64; 3]| {
        (1..4).fold(r0.clone(), |acc, i| if s[i - 1] > 0 { acc.add_ref(a(i, i)) } else { acc.sub_ref(a(i, i)) })
    };
    [
        [diag([1, 1, 1]), s01.clone(), s02.clone(), s03.clone()],
        [s01, diag([1, -1, -1]), s12.clone(), s13.clone()],
        [s02, s12, diag([-1, 1, -1]), s23.clone()],
        [s03, s13, s23, diag([-1, -1, 1])],
    ]
}

/// A constant rigid change of frame `[[1, 0], [s, V]]`, `V = U(E)/|E|²` (exact).
fn frame(e: &Quaternion<Q>, s: &[Q; 3]) -> M4 {
    let u = u11(&e.w, &e.vector());
    let n = e.norm_squared();
    let c = |x: &Q| Poly::from_q(x);
    std::array::from_fn(|i| {
        std::array::from_fn(|j| match (i, j) {
            (0, 0) => Poly::one(),
            (0, _) => Poly::zero(),
            (_, 0) => c(&s[i - 1]),
            _ => c(&(&u[i - 1][j - 1] / &n)),
        })
    })
}

// ------------------------------------------------------------ instances

fn rand_poly(g: &mut Lcg, d: usize) -> Poly {
    let mut c: Vec<Q> = (0..=d).map(|_| g.next()).collect();
    if c[d].is_zero() {
        c[d] = q(1);
    }
    poly(&c)
}

fn rand_quat(g: &mut Lcg, d: usize) -> Quaternion<Poly> {
    Quaternion::new(rand_poly(g, d), rand_poly(g, d), rand_poly(g, d), rand_poly(g, d))
}

fn rand_vec(g: &mut Lcg, d: usize) -> [Poly; 3] {
    [rand_poly(g, d), rand_poly(g, d), rand_poly(g, d)]
}

fn constant_vec(g: &mut Lcg) -> [Poly; 3] {
    [g.next(), g.next(), g.next()].map(|x| Poly::from_q(&x))
}

/// A rational motion given by its matrix, with the order `n`, the `k` and the degree of `ξ`
/// worked out by hand for it (the expectations the construction must meet).
struct Instance {
    name: &'static str,
    r: M4,
    n: usize,
    k: usize,
    xi_degree: usize,
}

fn instances() -> Vec<Instance> {
    let mut g = Lcg(6061);
    let t = Poly::var("t");
    let dq = |d: &Quaternion<Poly>| DualQuaternion::from_real(d.clone());
    let mut out = Vec::new();
    // 1. a generic Q-motion of degree 2: (1 + εa) D (1 + εb), D of degree 2: order 2m = 4, k = m
    let d = rand_quat(&mut g, 2);
    let (a, b) = (constant_vec(&mut g), constant_vec(&mut g));
    let half = Poly::from_ratio(1, 2);
    let left = DualQuaternion::new(Quaternion::one(), Quaternion::pure(&a).scale(&half));
    let right = DualQuaternion::new(Quaternion::one(), Quaternion::pure(&b).scale(&half));
    let generic = &(&left * &dq(&d)) * &right;
    out.push(Instance { name: "(1 + εa) D (1 + εb), deg D = 2", r: matrix_12(&generic), n: 4, k: 2, xi_degree: 0 });
    // 2. (2 v0 + ε v) D with deg v0 = 1, deg v = 2, deg D = 1: R = 4 v0 [[v0|D|², 0], [|D|² v, v0 U]]
    let (v0, v, d1) = (rand_poly(&mut g, 1), rand_vec(&mut g, 2), rand_quat(&mut g, 1));
    let tr = &translation5(&v0, &v) * &dq(&d1);
    out.push(Instance { name: "(2v0 + εv) D, degrees 1, 2, 1", r: matrix_12(&tr), n: 4, k: 1, xi_degree: 1 });
    // 3. the Q-motion (36) of w0* (degree 1), w (degree 3), D (degree 1): order n = 3, k = 1, ξ = 4 w0* |D|⁴
    let (w0, w, d3) = (rand_poly(&mut g, 1), rand_vec(&mut g, 3), rand_quat(&mut g, 1));
    let q36 = &translation5(&w0.mul_ref(&d3.norm_squared()), &w) * &dq(&d3);
    out.push(Instance { name: "the Q-motion (36) of degree k + n = 4", r: matrix_12(&q36), n: 3, k: 1, xi_degree: 5 });
    // 4. a real factor: (t² + 1) times instance 1: the same motion, ξ gains (t² + 1)²
    let factor = t.mul_ref(&t) + Poly::one();
    out.push(Instance {
        name: "(t² + 1) (1 + εa) D (1 + εb)",
        r: matrix_12(&generic.scale(&factor)),
        n: 4,
        k: 2,
        xi_degree: 4,
    });
    // 5. a translation 2 + ε v(t), deg v = 3: k = 0
    let shift =
        DualQuaternion::new(Quaternion::one().scale(&Poly::from_i64(2)), Quaternion::pure(&rand_vec(&mut g, 3)));
    out.push(Instance { name: "translation 2 + εv(t), deg v = 3", r: matrix_12(&shift), n: 3, k: 0, xi_degree: 0 });
    // 6. (1 - t) + t C, C off the Study quadric (a Darboux motion, Sec. 5.2 of the main paper): order 2
    let cc = DualQuaternion::from_coeffs(std::array::from_fn(|_| Poly::from_q(&g.next())));
    let one_minus = Poly::one().sub_ref(&t);
    let darboux = &DualQuaternion::one().scale(&one_minus) + &cc.scale(&t);
    out.push(Instance { name: "(1 - t) + t C, C off the quadric", r: matrix_12(&darboux), n: 2, k: 1, xi_degree: 0 });
    // 7. instance 2 seen from other fixed and moving frames, times (t - 3)
    let e1 = Quaternion::new(q(1), q(2), q(-1), ratio(1, 2));
    let e2 = Quaternion::new(q(3), q(0), q(1), q(-2));
    let k1 = frame(&e1, &[q(1), ratio(-2, 3), q(5)]);
    let k2 = frame(&e2, &[ratio(1, 2), q(4), q(-1)]);
    let h = t.sub_ref(&Poly::from_i64(3));
    let seen = mat_mul(&mat_mul(&k1, &matrix_12(&tr)), &k2).map(|row| row.map(|x| x.mul_ref(&h)));
    out.push(Instance { name: "(t - 3) K1 R K2 for R of instance 2", r: seen, n: 4, k: 1, xi_degree: 2 });
    out
}

// ------------------------------------------------------------ the check

fn symbolic(c: &mut Checker) {
    let v = Poly::var;
    let gq = DualQuaternion::from_coeffs(["a0", "a1", "a2", "a3", "b0", "b1", "b2", "b3"].map(v));
    let w = (&gq.dual * &gq.real.conjugate()).vector().map(|x| x.add_ref(&x));
    c.equal(
        "symbolic Q: the matrix of (12) = M of (35) with w0* = 1, D = Q0, w = 2 Vec(Qε Q~0)",
        &matrix_12(&gq),
        &m35(&Poly::one(), &w, &gq.real),
    );
    let d = Quaternion::new(v("d0"), v("d1"), v("d2"), v("d3"));
    let (w0, wv) = (v("w0"), [v("w1"), v("w2"), v("w3")]);
    let dc = [d.w.clone(), d.x.clone(), d.y.clone(), d.z.clone()];
    let four = Poly::from_i64(4).mul_ref(&w0);
    let expect: [[Poly; 4]; 4] = std::array::from_fn(|i| std::array::from_fn(|j| four.mul_ref(&dc[i]).mul_ref(&dc[j])));
    c.equal("symbolic w0*, w, D: X(M) = 4 w0* D Dᵀ (D is read off M)", &x_matrix(&m35(&w0, &wv, &d)), &expect);
}

fn converse(c: &mut Checker, inst: &Instance) {
    let name = inst.name;
    let r = &inst.r;
    c.check(format!("{name}: R has the form (10): R_0j = 0 for j = 1, 2, 3"), (1..4).all(|j| r[0][j] == Poly::zero()));
    // 1. ξ and the order n
    let xi = gcd_all(r.iter().flatten());
    c.equal(format!("{name}: deg ξ (gcd of the entries)"), &(xi.len() - 1), &inst.xi_degree);
    let Some(rp) = r
        .iter()
        .map(|row| row.iter().map(|x| exact_div(x, &xi)).collect::<Option<Vec<_>>>())
        .collect::<Option<Vec<_>>>()
    else {
        c.fail(format!("{name}: ξ does not divide R"));
        return;
    };
    let rp: M4 = std::array::from_fn(|i| std::array::from_fn(|j| rp[i][j].clone()));
    let n = rp.iter().flatten().filter_map(deg).max().unwrap_or(0);
    c.equal(format!("{name}: order n = deg R/ξ"), &n, &inst.n);
    let x = [ratio(1, 2), q(-1), q(3)].map(|e| Poly::from_q(&e));
    let traj: [Poly; 4] = std::array::from_fn(|i| {
        rp[i][0].clone() + (0..3).fold(Poly::zero(), |acc, j| acc + rp[i][j + 1].mul_ref(&x[j]))
    });
    let common = gcd_all(traj.iter());
    c.check(
        format!("{name}: the trajectory of (1/2, -1, 3) is irreducible (no common factor) of degree n"),
        common.len() == 1 && traj.iter().filter_map(deg).max() == Some(n),
    );
    // 2. D from X
    let xm = x_matrix(&rp);
    let rank_one = (0..4).all(|i| {
        (0..4).all(|j| (0..4).all(|k| (0..4).all(|l| xm[i][j].mul_ref(&xm[k][l]) == xm[i][l].mul_ref(&xm[k][j]))))
    });
    c.check(format!("{name}: X has rank one (R/ξ is a rotation of quaternion form)"), rank_one);
    let Some(row) = (0..4).find(|&i| xm[i][i] != Poly::zero()) else {
        c.fail(format!("{name}: X = 0"));
        return;
    };
    let g_row = gcd_all(xm[row].iter());
    let dd: Vec<Poly> = xm[row].iter().map(|x| exact_div(x, &g_row).expect("the gcd divides")).collect();
    let d = Quaternion::new(dd[0].clone(), dd[1].clone(), dd[2].clone(), dd[3].clone());
    let k = dd.iter().filter_map(deg).max().unwrap_or(0);
    c.equal(format!("{name}: k = deg D"), &k, &inst.k);
    c.check(format!("{name}: 0 <= k <= n/2"), 2 * k <= n);
    // 3. w0* = r0 / |D|², w, and R/ξ = M of (35)
    let Some(w0) = exact_div(&rp[0][0], &up(&d.norm_squared())) else {
        c.fail(format!("{name}: |D|² does not divide r0 (the converse would fail)"));
        return;
    };
    let w = [rp[1][0].clone(), rp[2][0].clone(), rp[3][0].clone()];
    c.check(format!("{name}: deg w0* <= n - 2k"), deg(&w0).unwrap_or(0) <= n - 2 * k);
    c.check(format!("{name}: deg w <= n"), w.iter().filter_map(deg).all(|e| e <= n));
    c.equal(format!("{name}: R/ξ = M(w0*, w, D) of (35), typed in"), &rp, &m35(&w0, &w, &d));
    // the library's MinimalMotion of the same data, in Bernstein form
    let wb: Vec<[Q; 3]> = {
        let cols = w.clone().map(|wi| to_bernstein(&wi, n));
        (0..=n).map(|i| [cols[0][i].clone(), cols[1][i].clone(), cols[2][i].clone()]).collect()
    };
    let dcols = [&d.w, &d.x, &d.y, &d.z].map(|x| to_bernstein(x, k));
    let db: Vec<Quaternion<Q>> = (0..=k)
        .map(|i| Quaternion::new(dcols[0][i].clone(), dcols[1][i].clone(), dcols[2][i].clone(), dcols[3][i].clone()))
        .collect();
    let w0b = to_bernstein(&w0, n - 2 * k);
    let Some(m) = c.ok(format!("{name}: MinimalMotion::new"), MinimalMotion::new(w0b.clone(), wb.clone(), db.clone()))
    else {
        return;
    };
    c.equal(format!("{name}: MinimalMotion::order = n"), &m.order(), &n);
    let lift = |x: &Q| Poly::from_q(x);
    let pm = MinimalMotion::new(
        w0b.iter().map(lift).collect(),
        wb.iter().map(|x| x.clone().map(|e| lift(&e))).collect(),
        db.iter().map(|x| Quaternion::new(lift(&x.w), lift(&x.x), lift(&x.y), lift(&x.z))).collect(),
    );
    if let Some(pm) = c.ok(format!("{name}: MinimalMotion over Poly"), pm) {
        let mt = pm.matrix(&Poly::var("t"));
        let xi_p = poly(&xi);
        let scaled = mt.clone().map(|row| row.map(|e| e.mul_ref(&xi_p)));
        c.equal(format!("{name}: R = ξ M(t), M = MinimalMotion::matrix"), r, &scaled);
    }
    c.note(format!("{name}: n = {n}, k = {k}, deg w0* = {}, deg ξ = {}", deg(&w0).unwrap_or(0), xi.len() - 1));
}

fn theorem_6_converse(c: &mut Checker) {
    symbolic(c);
    // the Bernstein conversion against the typed Bernstein polynomials
    let p = poly(&[q(2), ratio(-1, 3), q(5), q(1)]);
    let t = Poly::var("t");
    let b = to_bernstein(&p, 4);
    let back = b
        .iter()
        .enumerate()
        .fold(Poly::zero(), |acc, (i, bi)| acc + bernstein(4, i as u32, &t).mul_ref(&Poly::from_q(bi)));
    c.equal("power -> Bernstein (degree 4) and back", &back, &p);
    let all = instances();
    for inst in &all {
        converse(c, inst);
    }
    // The construction can fail: a mirrored motion (fixed frame reflected in y = 0) has the
    // shape (10) but an improper rotation block, and X is not of rank one.
    let mut mirrored = all[5].r.clone();
    mirrored[2] = mirrored[2].clone().map(|x| x.neg_ref());
    let x = x_matrix(&mirrored);
    let rank_one = (0..4).all(|i| (0..4).all(|j| x[i][i].mul_ref(&x[j][j]) == x[i][j].mul_ref(&x[i][j])));
    c.counterexample(
        "X has rank one for every matrix of the shape (10)",
        rank_one,
        "the Darboux motion of instance 6 mirrored in y = 0 (det < 0): X_ii X_jj != X_ij² (a motion, i.e. a proper \
         rotation block, is needed)",
    );
}
