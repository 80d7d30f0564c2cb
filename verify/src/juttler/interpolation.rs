//! Jüttler's interpolation statements (Secs. 3-5): Propositions 1-4, Result 5, Theorem 6, on
//! random rational instances. The linear systems (21)/(25), (28), (31), (34) are typed in from
//! the paper here (an independent reference); uniqueness is a rank statement about them
//! (a non-zero maximal minor, by `algebra_core::linalg::solve`), and the library's solutions
//! (`motion::juttler`) are checked against them, exactly:
//!
//! * `juttler/proposition-1` (affine): the collocation matrix of (21) is nonsingular; the
//!   library solution has `Scal C_j = 1` and `Q(t_i) = Rot(P_i)/r_i0`; half turns are refused;
//!   the result depends on the orientation of the fixed space (not proportional after a rotation).
//! * `juttler/proposition-2` (elliptic): same matrix (25); `|Q(t_i)|² = 1`, `Q(t_i) = ±R_i`; a
//!   fixed rotation of the fixed / moving space maps the result to `D Q` / `Q D` exactly.
//! * `juttler/proposition-3` (projective): `4(k+1) - 3(m+1) = 1` exactly for `k = 3m/4`; (28)
//!   typed in has rank `3(m+1)` (so its solutions are one line: unique up to a real factor); the
//!   library's solution lies in its null space and interpolates up to factors; invariance under
//!   `D` on either side up to a real factor. Found: at a half turn (27) has rank 1, not 3.
//! * `juttler/proposition-4` (TR): (31) nonsingular; interpolation; degree `k + m`; the origin
//!   moves on the polynomial curve `Σ b_j^m(t) p_j` of degree `m`; moving the origin of the
//!   moving space changes the motion.
//! * `juttler/result-5` (TRT): (34) typed in (with `U` of (11)) is nonsingular for every split
//!   of m = 4 on random positions, and for m = 2..6 singular exactly when `l1 = l2` is even;
//!   interpolation; degree `max(l1, l2) + k`; moving the origin by `c` gives exactly the
//!   control points `B_i (1 + ε c/2)`. Found: `l1, l2 ≥ 0` (the text says `≤ 0`), and (34) is
//!   singular for every pair of positions.
//! * `juttler/theorem-6` (minimal order): `M(t)` of (35) typed in equals the library's matrix
//!   as polynomials in `t`; the trajectory is `M(t)(1, x)` of exact degree `n`; the trajectory of
//!   the Q-motion (36) is the same times `4 w0* |D|⁴`; interpolation (37)-(39) has order `2m`.
//!   The converse ("every rational motion of order n is ξ M") is `juttler/theorem-6-converse` in
//!   [`super::converse`].

use super::{Lcg, bernstein, binom, u11};
use crate::{Checker, Method, Paper, Statement};
use algebra_core::linalg::solve;
use algebra_core::rational::{Q, q, ratio};
use algebra_core::{Poly, Ring};
use gam_algebras::DualQuaternion;
use gam_algebras::dual_quaternion::Quaternion;
use motion::Pose;
use motion::juttler::minimal::{MinimalMotion, minimal_method};
use motion::juttler::projective::projective;
use motion::juttler::rotational::{affine, elliptic_normalised};
use motion::juttler::tr::tr_method;
use motion::juttler::trt::trt_method;
use motion::juttler::{JuttlerError, QMotion, RationalBezier};
use motion::repr::dual_quaternion::from_dual_quaternion_exact;

/// Propositions 1-4, Result 5 and Theorem 6, in paper order.
pub const STATEMENTS: &[Statement] = &[
    Statement {
        id: "juttler/proposition-1",
        paper: Paper::Juttler,
        label: "Proposition 1",
        statement: "the rotational parts of m+1 positions are interpolated by a unique Q-motion of degree m with \
                    Scal Q_rot = 1 (19), from the system (21); positions with r_i0 = 0 cannot be interpolated; the \
                    result depends on the orientation of the fixed space",
        method: Method::Exact,
        hypotheses: "distinct parameters t_i (the collocation matrix is then nonsingular)",
        check: proposition_1,
    },
    Statement {
        id: "juttler/proposition-2",
        paper: Paper::Juttler,
        label: "Proposition 2",
        statement: "the rotational parts are interpolated by a unique Q-motion of degree m with Q_rot(t_i) = R_i \
                    (25), R_i normalised (23) with the signs (24); the result does not depend on the orientations \
                    of the fixed and the moving space",
        method: Method::Exact,
        hypotheses: "distinct parameters; invariance exactly for a unit D (rational unit quaternions here)",
        check: proposition_2,
    },
    Statement {
        id: "juttler/proposition-3",
        paper: Paper::Juttler,
        label: "Proposition 3",
        statement: "the rotational parts are interpolated by a Q-motion of degree k = 3m/4 satisfying (27); it is \
                    unique up to real factors and does not depend on the orientations of the fixed and moving space",
        method: Method::Exact,
        hypotheses: "m divisible by 4; 'in general': (28) of full rank 3(m+1) and no position inaccessible \
                     (Q_rot(t_i) != 0); (27) as printed needs r_i0 != 0 (at a half turn it has rank 1)",
        check: proposition_3,
    },
    Statement {
        id: "juttler/proposition-4",
        paper: Paper::Juttler,
        label: "Proposition 4",
        statement: "the m+1 positions are interpolated by a unique Q-motion (30) of degree k+m (l = m); the origin \
                    moves on a curve of degree m; in general the result depends on the origin of the moving space",
        method: Method::Exact,
        hypotheses: "distinct parameters",
        check: proposition_4,
    },
    Statement {
        id: "juttler/result-5",
        paper: Paper::Juttler,
        label: "Result 5",
        statement: "for l1 + l2 = m - 1, in general the m+1 positions are interpolated by a unique Q-motion (32) of \
                    degree max(l1, l2) + k (from (34)); the result does not depend on the origin of the moving space",
        method: Method::Exact,
        hypotheses: "l1, l2 >= 0 (the text prints <= 0); 'in general': (34) is singular whenever the relative \
                     rotations share an axis, e.g. for any two positions",
        check: result_5,
    },
    Statement {
        id: "juttler/theorem-6",
        paper: Paper::Juttler,
        label: "Theorem 6",
        statement: "for w0* (degree n-2k), w (degree n), D (degree k <= n/2) the matrix polynomial M(t) (35) of \
                    degree n is a rational motion of order n; it corresponds to the Q-motion (36) of degree k+n; \
                    interpolation (37)-(39) gives order 2m",
        method: Method::Exact,
        hypotheses: "(35) is lost in the OCR: M = [[w0* |D|², 0], [w, w0* U]] ((10) with v0 = w0*, |D|² v = w). \
                     Order n: the degree of the trajectories is checked, not their irreducibility",
        check: theorem_6,
    },
];

type Quat = Quaternion<Q>;

fn quat(c: [Q; 4]) -> Quat {
    let [w, x, y, z] = c;
    Quaternion::new(w, x, y, z)
}

fn coords(x: &Quat) -> [Q; 4] {
    [x.w.clone(), x.x.clone(), x.y.clone(), x.z.clone()]
}

/// `b_i^n(t)` at a rational `t`, typed in.
fn b(n: usize, i: usize, t: &Q) -> Q {
    let pow = |x: &Q, e: usize| (0..e).fold(q(1), |acc, _| acc * x);
    q(binom(n as u32, i as u32)) * pow(t, i) * pow(&(q(1) - t), n - i)
}

/// The collocation matrix `b_j^n(t_i)` of (21), (25), (31), (39).
fn collocation(n: usize, t: &[Q]) -> Vec<Vec<Q>> {
    t.iter().map(|t| (0..=n).map(|j| b(n, j, t)).collect()).collect()
}

fn nonsingular(a: Vec<Vec<Q>>) -> bool {
    let n = a.len();
    solve(a, vec![q(1); n]).is_some()
}

/// A matrix with one column more than rows has full row rank: some maximal minor is non-zero.
fn full_row_rank(a: &[Vec<Q>]) -> bool {
    let cols = a.first().map_or(0, Vec::len);
    (0..cols).any(|drop| nonsingular(a.iter().map(|r| [&r[..drop], &r[drop + 1..]].concat()).collect()))
}

/// `a = λ b` for one `λ ≠ 0`.
fn proportional(a: &[Q], b: &[Q]) -> bool {
    let nz = |v: &[Q]| v.iter().any(|x| *x != q(0));
    nz(a) && nz(b) && (0..a.len()).all(|k| (0..a.len()).all(|l| &a[k] * &b[l] == &a[l] * &b[k]))
}

fn flat(m: &QMotion<Q>) -> Vec<Q> {
    m.control().iter().flat_map(|c| coords(&c.real)).collect()
}

/// A rotation with non-zero scalar part.
fn rotation(g: &mut Lcg) -> Quat {
    quat([q(10) + g.next().clone() * g.next(), g.next(), g.next(), g.next()])
}

/// A rational unit quaternion `a a / |a|²`.
fn unit(g: &mut Lcg) -> Quat {
    let a = rotation(g);
    (&a * &a).scale(&(q(1) / a.norm_squared()))
}

/// The position `(2 + ε s) * R` (14).
fn position(r: &Quat, s: &[Q; 3]) -> Option<Pose<Q>> {
    let dq = DualQuaternion::new(r.clone(), &Quaternion::pure(s).scale(&ratio(1, 2)) * r);
    from_dual_quaternion_exact(&dq).ok()
}

/// Distinct parameters `t_i = (i² + i)/(m² + m)`.
fn params(m: usize) -> Vec<Q> {
    let m = m as i64;
    (0..=m).map(|i| ratio(i * i + i, m * m + m)).collect()
}

/// `m + 1` random positions: rotations, translations, poses.
fn positions(g: &mut Lcg, m: usize) -> (Vec<Quat>, Vec<[Q; 3]>, Vec<Pose<Q>>) {
    let r: Vec<Quat> = (0..=m).map(|_| rotation(g)).collect();
    let s: Vec<[Q; 3]> = (0..=m).map(|_| [g.next(), g.next(), g.next()]).collect();
    let p = r.iter().zip(&s).filter_map(|(r, s)| position(r, s)).collect();
    (r, s, p)
}

fn interpolates(m: &QMotion<Q>, poses: &[Pose<Q>], t: &[Q]) -> bool {
    poses.len() == t.len() && poses.iter().zip(t).all(|(p, t)| m.pose_exact(t).is_ok_and(|x| x.is_equivalent_exact(p)))
}

fn proposition_1(c: &mut Checker) {
    let mut g = Lcg(101);
    let (r, _, _) = positions(&mut g, 3);
    let t = params(3);
    c.check(
        "(21): the collocation matrix b_j^3(t_i) is nonsingular (rank 4): a unique solution",
        nonsingular(collocation(3, &t)),
    );
    if let Some(a) = c.ok("affine method", affine(&r, &t)) {
        c.check("(19): Scal C_j = 1", a.control().iter().all(|x| x.real.w == q(1)));
        for (i, (ri, ti)) in r.iter().zip(&t).enumerate() {
            c.equal(format!("(20): Q_rot(t_{i}) = Rot(P_{i})/r_{i}0"), &a.eval(ti).real, &ri.scale(&(q(1) / &ri.w)));
        }
        let d = rotation(&mut g);
        let rotated: Vec<_> = r.iter().map(|x| &d * x).collect();
        if let Some(da) = c.ok("affine method, rotated fixed space", affine(&rotated, &t)) {
            let s = ratio(1, 3);
            c.check(
                "the result depends on the orientation of the fixed space: affine(D R_i)(1/3) is not ∝ D affine(R_i)(1/3)",
                !proportional(&coords(&da.eval(&s).real), &coords(&(&d * &a.eval(&s).real))),
            );
        }
    }
    let mut half = r.clone();
    half[2] = quat([q(0), q(1), q(2), q(2)]);
    c.check(
        "a position with r_i0 = 0 cannot be interpolated (JuttlerError::AtInfinity)",
        matches!(affine(&half, &t), Err(JuttlerError::AtInfinity { index: 2 })),
    );
}

fn proposition_2(c: &mut Checker) {
    let mut g = Lcg(202);
    let r: Vec<Quat> = (0..4).map(|_| unit(&mut g)).collect();
    let t = params(3);
    c.check("(25): the collocation matrix is nonsingular: a unique solution", nonsingular(collocation(3, &t)));
    let Some(e) = c.ok("elliptic method", elliptic_normalised(&r, &t)) else { return };
    for (i, (ri, ti)) in r.iter().zip(&t).enumerate() {
        let v = e.eval(ti).real;
        c.check(format!("(25): Q_rot(t_{i}) = ±R_{i}"), v == *ri || v == ri.scale(&q(-1)));
        c.equal(format!("(22): |Q_rot(t_{i})|² = 1"), &v.norm_squared(), &q(1));
    }
    let d = unit(&mut g);
    let fixed: Vec<_> = r.iter().map(|x| &d * x).collect();
    let moving: Vec<_> = r.iter().map(|x| x * &d).collect();
    if let Some(f) = c.ok("elliptic, rotated fixed space", elliptic_normalised(&fixed, &t)) {
        let expect: Vec<_> = e.control().iter().map(|x| &d * &x.real).collect();
        let got: Vec<_> = f.control().iter().map(|x| x.real.clone()).collect();
        c.equal("fixed space rotated by D: the result is D Q_rot (control points)", &got, &expect);
    }
    if let Some(f) = c.ok("elliptic, rotated moving space", elliptic_normalised(&moving, &t)) {
        let expect: Vec<_> = e.control().iter().map(|x| &x.real * &d).collect();
        let got: Vec<_> = f.control().iter().map(|x| x.real.clone()).collect();
        c.equal("moving space rotated by D: the result is Q_rot D (control points)", &got, &expect);
    }
}

/// The system (28) as printed (27): rows `b_l^k(t_i) [r_i0 Vec C_l - Scal C_l r_i]`, columns
/// `C_0.w, C_0.x, …`.
fn system_28(r: &[Quat], t: &[Q], k: usize) -> Vec<Vec<Q>> {
    let mut rows = Vec::new();
    for (ri, ti) in r.iter().zip(t) {
        let v = ri.vector();
        for (j, vj) in v.iter().enumerate() {
            let mut row = vec![q(0); 4 * (k + 1)];
            for l in 0..=k {
                row[4 * l] = -(b(k, l, ti) * vj);
                row[4 * l + 1 + j] = b(k, l, ti) * &ri.w;
            }
            rows.push(row);
        }
    }
    rows
}

fn proposition_3(c: &mut Checker) {
    for m in [4usize, 8, 12] {
        c.equal(
            format!("m = {m}, k = 3m/4: 4(k+1) - 3(m+1) = 1 unknown more than equations"),
            &(4 * (3 * m / 4 + 1)),
            &(3 * (m + 1) + 1),
        );
    }
    let mut g = Lcg(303);
    let r: Vec<Quat> = (0..5).map(|_| rotation(&mut g)).collect();
    let t = params(4);
    let a = system_28(&r, &t, 3);
    c.check(
        "(28) typed in, 15 x 16: rank 15 (a non-zero 15 x 15 minor): solutions unique up to a real factor",
        full_row_rank(&a),
    );
    if let Some(p) = c.ok("projective method", projective(&r, &t)) {
        let x = flat(&p);
        let ax: Vec<Q> = a.iter().map(|row| row.iter().zip(&x).fold(q(0), |acc, (u, v)| acc + u * v)).collect();
        c.check(
            "the library's solution is a non-zero null vector of (28)",
            ax.iter().all(|v| *v == q(0)) && x.iter().any(|v| *v != q(0)),
        );
        for (i, (ri, ti)) in r.iter().zip(&t).enumerate() {
            c.check(format!("(18): Q_rot(t_{i}) = λ_{i} R_{i}"), proportional(&coords(&p.eval(ti).real), &coords(ri)));
        }
        let d = rotation(&mut g);
        let fixed: Vec<_> = r.iter().map(|x| &d * x).collect();
        let moving: Vec<_> = r.iter().map(|x| x * &d).collect();
        let df: Vec<Q> = p.control().iter().flat_map(|x| coords(&(&d * &x.real))).collect();
        let dm: Vec<Q> = p.control().iter().flat_map(|x| coords(&(&x.real * &d))).collect();
        if let Some(f) = c.ok("projective, rotated fixed space", projective(&fixed, &t)) {
            c.check("fixed space rotated by D: the result is λ D Q_rot", proportional(&flat(&f), &df));
        }
        if let Some(f) = c.ok("projective, rotated moving space", projective(&moving, &t)) {
            c.check("moving space rotated by D: the result is λ Q_rot D", proportional(&flat(&f), &dm));
        }
    }
    // a half turn: the three equations (27) are -r_j Scal Q(t_i) = 0, all proportional
    let half = [quat([q(0), q(1), q(2), q(2)])];
    let rows = system_28(&half, &[ratio(1, 2)], 0);
    let rank1 = rows.iter().all(|u| rows.iter().all(|v| proportional(u, v)));
    c.counterexample(
        "(27) states Q(t_i) ∥ R_i for every rotation",
        !rank1,
        "R = i + 2j + 2k (r_0 = 0): the three rows of (27) are multiples of Scal Q(t_i) = 0 (rank 1, Vec Q(t_i) free); \
         motion::juttler::projective uses the minors at the first non-zero coordinate instead",
    );
    let mut r2 = r.clone();
    r2[2] = half[0].clone();
    if let Some(p) = c.ok("projective method with a half turn", projective(&r2, &t)) {
        c.check(
            "the library interpolates the half turn up to a factor",
            proportional(&coords(&p.eval(&t[2]).real), &coords(&r2[2])),
        );
    }
}

/// The columns `p_j` of `Σ_j b_j^m(t_i) p_j = rhs_i` (31), (39), solved with the typed matrix.
fn solve_31(t: &[Q], rhs: &[[Q; 3]]) -> Option<Vec<[Q; 3]>> {
    let m = t.len() - 1;
    let cols: Vec<Vec<Q>> =
        (0..3).map(|k| solve(collocation(m, t), rhs.iter().map(|r| r[k].clone()).collect())).collect::<Option<_>>()?;
    Some((0..=m).map(|j| [cols[0][j].clone(), cols[1][j].clone(), cols[2][j].clone()]).collect())
}

fn proposition_4(c: &mut Checker) {
    let mut g = Lcg(404);
    let (r, s, poses) = positions(&mut g, 3);
    let t = params(3);
    c.check("(31): the collocation matrix is nonsingular: a unique solution", nonsingular(collocation(3, &t)));
    let Some(rot) = c.ok("affine rotations", affine(&r, &t)) else { return };
    let Some(tr) = c.ok("TR method", tr_method(&rot, &poses, &t)) else { return };
    c.equal("degree k + m", &tr.degree(), &6);
    c.check("Q(t_i) = λ_i P_i", interpolates(&tr, &poses, &t));
    if let Some(p) = c.ok("(31) solved with the typed matrix", solve_31(&t, &s).ok_or("singular")) {
        let origin = tr.trajectory(&[q(0), q(0), q(0)]);
        let ok = (0..=12).all(|i| {
            let u = ratio(i, 12) + ratio(1, 25);
            let poly: [Q; 3] = std::array::from_fn(|k| (0..=3).fold(q(0), |acc, j| acc + b(3, j, &u) * &p[j][k]));
            origin.point(&u).is_ok_and(|y| y == poly)
        });
        c.check("the origin moves on Σ b_j^m(t) p_j (degree m = 3), at 13 rational t", ok);
    }
    let shift = [ratio(1, 2), q(-2), ratio(3, 4)];
    let moved: Vec<_> = poses.iter().map(|p| &Pose::translation(&shift) * p).collect();
    if let Some(tr2) = c.ok("TR method, moved origin", tr_method(&rot, &moved, &t)) {
        let u = ratio(1, 3);
        let same = match (tr2.pose_exact(&u), tr.pose_exact(&u)) {
            (Ok(a), Ok(b)) => a.is_equivalent_exact(&(&Pose::translation(&shift) * &b)),
            _ => true,
        };
        c.check("the result depends on the origin of the moving space (t = 1/3)", !same);
    }
}

/// The system (34) typed in: `|Q(t_i)|² Σ b^{l1}_j p1_j + Σ b^{l2}_j U(t_i) p2_j = |Q(t_i)|² s_i`.
fn system_34(rot: &QMotion<Q>, t: &[Q], l1: usize, l2: usize) -> Vec<Vec<Q>> {
    let n = 3 * (l1 + l2 + 2);
    let mut a = Vec::new();
    for ti in t {
        let d = rot.eval(ti).real;
        let (norm, u) = (d.norm_squared(), u11(&d.w, &d.vector()));
        for r in 0..3 {
            let mut row = vec![q(0); n];
            for j in 0..=l1 {
                row[3 * j + r] = &norm * &b(l1, j, ti);
            }
            for j in 0..=l2 {
                for k in 0..3 {
                    row[3 * (l1 + 1 + j) + k] = &u[r][k] * &b(l2, j, ti);
                }
            }
            a.push(row);
        }
    }
    a
}

fn result_5(c: &mut Checker) {
    let mut g = Lcg(505);
    let (r, _, poses) = positions(&mut g, 4);
    let t = params(4);
    let Some(rot) = c.ok("affine rotations (k = 4)", affine(&r, &t)) else { return };
    let shift = [ratio(1, 3), q(2), ratio(-5, 2)];
    let moved: Vec<_> = poses.iter().map(|p| &Pose::translation(&shift) * p).collect();
    let right = DualQuaternion::new(Quaternion::one(), Quaternion::pure(&shift).scale(&ratio(1, 2)));
    for l1 in 0..4 {
        let l2 = 3 - l1;
        c.check(format!("l1 = {l1}: (34) typed in, 15 x 15, is nonsingular"), nonsingular(system_34(&rot, &t, l1, l2)));
        let Some(m) = c.ok(format!("l1 = {l1}: TRT"), trt_method(&rot, &poses, &t, l1)) else { continue };
        c.equal(format!("l1 = {l1}: degree max(l1, l2) + k"), &m.degree(), &(l1.max(l2) + 4));
        c.check(format!("l1 = {l1}: Q(t_i) = λ_i P_i"), interpolates(&m, &poses, &t));
        if let Some(m2) = c.ok(format!("l1 = {l1}: TRT, moved origin"), trt_method(&rot, &moved, &t, l1)) {
            let expect: Vec<_> = m.control().iter().map(|x| x * &right).collect();
            c.equal(
                format!("l1 = {l1}: origin moved by c: control points B_i (1 + ε c/2)"),
                &m2.control().to_vec(),
                &expect,
            );
        }
    }
    // two positions: (34) is 6 x 6 and singular
    let two = affine(&r[..2], &[q(0), q(1)]);
    if let Some(two) = c.ok("affine, two positions", two) {
        c.counterexample(
            "(34) is nonsingular for m = 1 (l1 = l2 = 0)",
            nonsingular(system_34(&two, &[q(0), q(1)], 0, 0)),
            "any two positions: b along the relative rotation axis and a = -Rot(t_i) b solve the homogeneous system",
        );
    }
    // Which splits are singular for positions in general position: every split of m = 2..6
    // over two random rational position sets (uniform and random parameters). Measured further
    // (m up to 9, six sets each): singular exactly when l1 = l2 is even (m = 1, 5, 9), with a
    // one-dimensional null space; nonsingular for every other split.
    for m in 2..=6usize {
        for (seed, uniform) in [(7001u64, true), (7002, false)] {
            let mut g = Lcg(seed + 31 * m as u64);
            let (r, _, _) = positions(&mut g, m);
            let t: Vec<Q> = if uniform {
                params(m)
            } else {
                let mut acc = q(0);
                (0..=m)
                    .map(|_| {
                        acc = &acc + num_traits::Signed::abs(&g.next()) + ratio(1, 7);
                        acc.clone()
                    })
                    .collect()
            };
            let Some(rot) = c.ok(format!("m = {m}: affine rotations"), affine(&r, &t)) else { continue };
            for l1 in 0..m {
                let l2 = m - 1 - l1;
                let even_equal = l1 == l2 && l1.is_multiple_of(2);
                c.check(
                    format!(
                        "m = {m}, l1 = {l1}, {} parameters: (34) is singular iff l1 = l2 is even",
                        if uniform { "uniform" } else { "random" }
                    ),
                    nonsingular(system_34(&rot, &t, l1, l2)) != even_equal,
                );
            }
        }
    }
    c.note("Result 5 prints l1, l2 <= 0; with l1 + l2 = m - 1 it means l1, l2 >= 0");
    c.note(
        "'in general' fails for whole splits: (34) is singular for every set of positions when l1 = l2 is even (m = 1, 5, 9, ...; measured for m <= 9, not proved); the juttler-trt error says so",
    );
}

/// The Bernstein-form curve with control points `h` as polynomials in `t`.
fn bezier_poly(h: &[[Q; 4]], t: &Poly) -> [Poly; 4] {
    let n = h.len() - 1;
    std::array::from_fn(|k| {
        h.iter()
            .enumerate()
            .fold(Poly::zero(), |acc, (i, hi)| acc + bernstein(n as u32, i as u32, t).mul_ref(&Poly::from_q(&hi[k])))
    })
}

fn poly_of<T: Clone>(c: &[T], t: &Poly, lift: impl Fn(&T) -> Poly) -> Poly {
    let n = c.len() - 1;
    c.iter().enumerate().fold(Poly::zero(), |acc, (i, x)| acc + bernstein(n as u32, i as u32, t).mul_ref(&lift(x)))
}

fn theorem_6(c: &mut Checker) {
    let mut g = Lcg(606);
    let (n, k) = (5usize, 2usize);
    let w0: Vec<Q> = (0..=n - 2 * k).map(|_| q(5) + g.next()).collect();
    let w: Vec<[Q; 3]> = (0..=n).map(|_| [g.next(), g.next(), g.next()]).collect();
    let d: Vec<Quat> = (0..=k).map(|_| rotation(&mut g)).collect();
    let Some(m) = c.ok("MinimalMotion::new", MinimalMotion::new(w0.clone(), w.clone(), d.clone())) else { return };
    let t = Poly::var("t");
    let lift = |x: &Q| Poly::from_q(x);
    let dq: Vec<Quaternion<Poly>> =
        d.iter().map(|x| Quaternion::new(lift(&x.w), lift(&x.x), lift(&x.y), lift(&x.z))).collect();
    let pm =
        MinimalMotion::new(w0.iter().map(lift).collect(), w.iter().map(|x| x.clone().map(|v| lift(&v))).collect(), dq);
    let Some(pm) = c.ok("MinimalMotion over Poly", pm) else { return };
    // (35) typed in
    let w0t = poly_of(&w0, &t, lift);
    let wt: [Poly; 3] = std::array::from_fn(|i| poly_of(&w, &t, |x| lift(&x[i])));
    let dt: [Poly; 4] = std::array::from_fn(|i| poly_of(&d, &t, |x| lift(&coords(x)[i])));
    let norm = dt.iter().fold(Poly::zero(), |acc, x| acc + x.mul_ref(x));
    let u = u11(&dt[0], &[dt[1].clone(), dt[2].clone(), dt[3].clone()]);
    let z = Poly::zero;
    let row = |i: usize| [wt[i].clone(), w0t.mul_ref(&u[i][0]), w0t.mul_ref(&u[i][1]), w0t.mul_ref(&u[i][2])];
    let m35 = [[w0t.mul_ref(&norm), z(), z(), z()], row(0), row(1), row(2)];
    c.equal("M(t) of (35), typed in, = MinimalMotion::matrix(t) as polynomials in t", &pm.matrix(&t), &m35);
    let degree = m35.iter().flatten().map(Poly::degree).max();
    c.equal("M(t) has degree n = 5", &degree, &Some(5));
    let x = [ratio(1, 2), q(-1), q(3)];
    let traj = bezier_poly(m.trajectory(&x).control(), &t);
    let mx: [Poly; 4] = std::array::from_fn(|r| {
        let l = |v: &Q| Poly::from_q(v);
        m35[r][0].clone() + m35[r][1].mul_ref(&l(&x[0])) + m35[r][2].mul_ref(&l(&x[1])) + m35[r][3].mul_ref(&l(&x[2]))
    });
    c.equal("the trajectory (library, Bernstein form) = M(t) (1, x) as polynomials", &traj, &mx);
    c.equal("the trajectory has exact degree n = 5", &traj.iter().map(Poly::degree).max(), &Some(5));
    let qm = m.q_motion();
    c.equal("the Q-motion (36) has degree k + n = 7", &qm.degree(), &7);
    let qtraj = bezier_poly(RationalBezier::control(&qm.trajectory(&x)), &t);
    let factor = Poly::from_i64(4).mul_ref(&w0t).mul_ref(&norm).mul_ref(&norm);
    let scaled: [Poly; 4] = std::array::from_fn(|i| traj[i].mul_ref(&factor));
    c.equal("the trajectory of (36) (degree 2(k+n) = 14) = 4 w0* |D|⁴ times that of M(t)", &qtraj, &scaled);
    // interpolation (37)-(39): order 2m
    let (r, _, poses) = positions(&mut g, 3);
    let tp = params(3);
    let Some(rot) = c.ok("affine rotations (k = 3)", affine(&r, &tp)) else { return };
    if let Some(mm) = c.ok("minimal-order interpolation", minimal_method(&rot, &poses, &tp)) {
        c.equal("(37)-(39): order 2m = 6", &mm.order(), &6);
        let y = bezier_poly(mm.trajectory(&x).control(), &t);
        c.equal("its trajectory has exact degree 2m = 6", &y.iter().map(Poly::degree).max(), &Some(6));
        c.equal("its Q-motion (36) has degree 3m = 9", &mm.q_motion().degree(), &9);
        let ok = poses.iter().zip(&tp).all(|(p, ti)| mm.pose_exact(ti).is_ok_and(|a| a.is_equivalent_exact(p)));
        c.check("M(t_i) = P_i", ok);
    }
}
