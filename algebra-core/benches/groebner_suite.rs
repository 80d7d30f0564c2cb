//! The Gröbner benchmark suite (docs/performance.md, "Gröbner engine against Singular"): the
//! papers' hypothesis ideals and the standard systems, each run by GAM in process and, when
//! installed, by Singular (`std` + `reduce`, degrevlex, over Q, timed by its own `rtimer`) and
//! by sympy (`groebner` + `reduced`), in the same run; it prints the times and the ratios.
//!
//! Every ideal is also written to `target/groebner-suite/NAME.sing` (Singular's input
//! language) and `NAME.py` (sympy), so the comparison can be rerun by hand. Run it with
//! `tests/bench/groebner-suite.sh` (installs Singular where missing), or
//! `cargo bench -p algebra-core --features rug --bench groebner_suite [-- NAME...]`; with
//! `--gam-only` it times GAM alone (A/B runs of the engine; `GAM_REPS=N` takes the median of up
//! to N runs instead of 5). Times are printed in ms to the microsecond. Against Singular both
//! sides report the best of five runs (Singular's script keeps the least of five `rtimer`
//! readings); alone, GAM reports the median.
#![allow(missing_docs)]

use algebra_core::ideal::{Budget, MonomialOrder, PolyRing};
use algebra_core::multivector::symbolic::Part;
use algebra_core::{Algebra, Basis, Multivector, Poly, Ring};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

type Mv = Multivector<Poly>;

/// One ideal of the suite: generators, claims to reduce (possibly none), whether sympy runs it.
struct Ideal {
    name: &'static str,
    gens: Vec<Poly>,
    claims: Vec<Poly>,
    sympy: bool,
}

fn components(m: &Mv) -> Vec<Poly> {
    m.components().into_iter().map(|(_, p)| p).collect()
}

fn pose(alg: &std::sync::Arc<Algebra>, prefix: &str) -> Mv {
    let names = ["1", "e12", "e13", "e23", "e1inf", "e2inf", "e3inf", "e123inf"];
    Multivector::symbolic(alg, Basis::Product, prefix, &Part::elements(&names)).expect("pose")
}

fn unitary(s: &Mv) -> Vec<Poly> {
    let one = Multivector::scalar(s.algebra(), s.basis(), Poly::one());
    components(&(&(&s.reverse() * s) - &one))
}

/// The docs' example (docs/cli.md, `gam prove`): X = even("S") of cga-null in the product
/// basis (16 coefficients), rev(X) X = 1, claim (rev(X) e0 X)² = 0.
fn docs_example() -> Ideal {
    let alg = Algebra::builtin("cga-null").expect("cga-null");
    let x = Multivector::symbolic(&alg, Basis::Product, "S", &Part::Even).expect("even");
    let e0 = Multivector::from_mask(&alg, Basis::Product, alg.mask_of("e0").expect("e0")).expect("e0");
    let f = &(&x.reverse() * &e0) * &x;
    Ideal { name: "docs-example", gens: unitary(&x), claims: components(&(&f * &f)), sympy: true }
}

/// Lemma 2.2 (null vectors): a pose S of G_123inf in G_0123inf, rev(S) S = 1 and x x = 0;
/// claim (rev(S) x S)² = 0.
fn lemma_2_2() -> Ideal {
    let alg = Algebra::builtin("cga-null").expect("cga-null");
    let s = pose(&alg, "S");
    let x = Multivector::symbolic(&alg, Basis::Product, "x", &Part::Grade(1)).expect("vector");
    let fx = &(&s.reverse() * &x) * &s;
    let gens = unitary(&s).into_iter().chain(components(&(&x * &x))).collect();
    Ideal { name: "lemma-2.2", gens, claims: components(&(&fx * &fx)), sympy: true }
}

/// Lemma 3.4 (the registry's statement): rev(S) S = 1 and its derivative; Ψ = 2 rev(S) D is a
/// bivector.
fn lemma_3_4() -> Ideal {
    let alg = Algebra::builtin("cga-null").expect("cga-null");
    let (s, d) = (pose(&alg, "S"), pose(&alg, "D"));
    let psi = (&s.reverse() * &d).scale(&Poly::from_i64(2));
    let derivative = components(&(&(&d.reverse() * &s) + &(&s.reverse() * &d)));
    let gens = unitary(&s).into_iter().chain(derivative).collect();
    Ideal { name: "lemma-3.4", gens, claims: components(&(&psi - &psi.grade(2))), sympy: false }
}

/// The Study quadric for `k` symbolic poses of G_123inf: each on the quadric
/// (<rev(S_i) S_i>_4 = 0); claim: their product is on it too.
fn study(k: usize) -> Ideal {
    let alg = Algebra::builtin("g123inf").expect("g123inf");
    let poses: Vec<Mv> = (0..k).map(|i| pose(&alg, ["A", "B", "C"][i])).collect();
    let quadric = |s: &Mv| components(&(&s.reverse() * s).grade(4));
    let gens = poses.iter().flat_map(quadric).collect();
    let product = poses[1..].iter().fold(poses[0].clone(), |acc, s| &acc * s);
    let name = ["study-1", "study-2", "study-3"][k - 1];
    Ideal { name, gens, claims: quadric(&product), sympy: k == 1 }
}

/// A quaternion `w + x i + y j + z k` with polynomial coordinates (Jüttler's `H`).
type Quat = [Poly; 4];

fn quat_var(prefix: &str) -> Quat {
    ["0", "1", "2", "3"].map(|c| Poly::var(&format!("{prefix}{c}")))
}

/// Pure quaternion `0 + v` (Jüttler's vectors of R³ inside `H`).
fn pure(prefix: &str) -> Quat {
    let v = quat_var(prefix);
    [Poly::zero(), v[1].clone(), v[2].clone(), v[3].clone()]
}

/// Hamilton product: `(a0, a)(b0, b) = (a0 b0 - a·b, a0 b + b0 a + a × b)`.
fn qmul(a: &Quat, b: &Quat) -> Quat {
    let m = |i: usize, j: usize| a[i].clone() * &b[j];
    [
        m(0, 0) - m(1, 1) - m(2, 2) - m(3, 3),
        m(0, 1) + m(1, 0) + m(2, 3) - m(3, 2),
        m(0, 2) + m(2, 0) + m(3, 1) - m(1, 3),
        m(0, 3) + m(3, 0) + m(1, 2) - m(2, 1),
    ]
}

fn qsub(a: &Quat, b: &Quat) -> Quat {
    [0, 1, 2, 3].map(|c| a[c].clone() - &b[c])
}

fn qscale(s: &Poly, a: &Quat) -> Quat {
    [0, 1, 2, 3].map(|c| s.clone() * &a[c])
}

/// `|a|² = a ã` (a real number).
fn qnorm2(a: &Quat) -> Poly {
    a.iter().fold(Poly::zero(), |s, c| s + c.clone() * c)
}

/// Bernstein polynomial `b_j^k(t) = C(k, j) t^j (1 - t)^(k - j)`.
fn bernstein(k: usize, j: usize, t: &Poly) -> Poly {
    let binom = (0..j).fold(1i64, |b, i| b * (k - i) as i64 / (i as i64 + 1));
    let mut p = Poly::from_i64(binom);
    for _ in 0..j {
        p = p * t;
    }
    for _ in j..k {
        p = p * &(Poly::one() - t);
    }
    p
}

/// The Bézier quaternion curve `Σ_j b_j^k(t) C_j` at `t` (Jüttler (17)).
fn bezier(cs: &[Quat], t: &Poly) -> Quat {
    let k = cs.len() - 1;
    cs.iter().enumerate().fold([(); 4].map(|_| Poly::zero()), |acc, (j, c)| {
        let b = bernstein(k, j, t);
        [0, 1, 2, 3].map(|i| acc[i].clone() + b.clone() * &c[i])
    })
}

/// `u Π_{i<l} (t_l - t_i) - 1`: the parameters are distinct (Rabinowitsch).
fn distinct(ts: &[Poly], u: &str) -> Poly {
    let mut p = Poly::var(u);
    for l in 0..ts.len() {
        for i in 0..l {
            p = p * &(ts[l].clone() - &ts[i]);
        }
    }
    p - Poly::one()
}

/// Jüttler's Proposition 1 (the affine method), `m + 1` symbolic rotations `R_i = r_i0 + r_i`
/// at symbolic parameters `t_i`: two solutions `C`, `C'` of the system (21) (denominators
/// cleared: `r_i0 Σ_j b_j^m(t_i) Vec C_j = r_i`, `Scal C_j = 1`), the parameters distinct and
/// `r_i0 != 0` (Rabinowitsch). Claims: `C_j = C'_j` (uniqueness) and `r_i0 Q_rot(t_i) = R_i`,
/// i.e. (18) with λ_i = 1/r_i0 (20). The dependence on the fixed frame is not a membership
/// statement and is not encoded.
fn juttler_1(m: usize) -> Ideal {
    let ts: Vec<Poly> = (0..=m).map(|i| Poly::var(&format!("t{i}"))).collect();
    let rs: Vec<Quat> = (0..=m).map(|i| quat_var(&format!("r{i}"))).collect();
    let mut gens = vec![distinct(&ts, "u")];
    let mut solutions = Vec::new();
    for name in ["c", "d"] {
        let cs: Vec<Quat> = (0..=m).map(|j| quat_var(&format!("{name}{j}"))).collect();
        gens.extend(cs.iter().map(|c| c[0].clone() - Poly::one()));
        for (t, r) in ts.iter().zip(&rs) {
            let q = bezier(&cs, t);
            gens.extend((1..4).map(|c| r[0].clone() * &q[c] - &r[c]));
        }
        solutions.push(cs);
    }
    for (i, r) in rs.iter().enumerate() {
        gens.push(Poly::var(&format!("w{i}")) * &r[0] - Poly::one());
    }
    let mut claims: Vec<Poly> = solutions[0].iter().zip(&solutions[1]).flat_map(|(c, d)| qsub(c, d)).collect();
    for (t, r) in ts.iter().zip(&rs) {
        claims.extend(qsub(&qscale(&r[0], &bezier(&solutions[0], t)), r));
    }
    Ideal { name: "juttler-1", gens, claims, sympy: false }
}

/// Jüttler's Proposition 2 (the elliptic method), `m + 1` symbolic unit rotations `R_i`
/// (`|R_i|² = 1`, (23)) at distinct symbolic parameters, a symbolic unit rotation `D`: two
/// solutions `C`, `C'` of (25). Claims: `C_j = C'_j` (uniqueness); the rotated motions
/// `D Q_rot` and `Q_rot D` satisfy (25) for the data `D R_i`, `R_i D` and the normalisation
/// (22) (the paper's proof of the invariance: with uniqueness, they are the elliptic
/// interpolants of the rotated data). The invariance as `C'_j = D C_j` for `C'` solving (25)
/// for `D R_i` was out of reach of both engines (the data `D R_i` are quadratic, so grevlex
/// leads with them: Singular had no basis after two minutes, even at fixed parameters). The
/// sign choice (24) is an inequality and is not encoded.
fn juttler_2(m: usize) -> Ideal {
    let ts: Vec<Poly> = (0..=m).map(|i| Poly::var(&format!("t{i}"))).collect();
    let rs: Vec<Quat> = (0..=m).map(|i| quat_var(&format!("r{i}"))).collect();
    let d = quat_var("q");
    let mut gens = vec![distinct(&ts, "u"), qnorm2(&d) - Poly::one()];
    gens.extend(rs.iter().map(|r| qnorm2(r) - Poly::one()));
    let mut solutions = Vec::new();
    for name in ["c", "e"] {
        let cs: Vec<Quat> = (0..=m).map(|j| quat_var(&format!("{name}{j}"))).collect();
        for (t, r) in ts.iter().zip(&rs) {
            gens.extend(qsub(&bezier(&cs, t), r));
        }
        solutions.push(cs);
    }
    let mut claims: Vec<Poly> = solutions[0].iter().zip(&solutions[1]).flat_map(|(c, e)| qsub(c, e)).collect();
    for (t, r) in ts.iter().zip(&rs) {
        let q = bezier(&solutions[0], t);
        let (fixed, moving) = (qmul(&d, &q), qmul(&q, &d));
        claims.extend(qsub(&fixed, &qmul(&d, r)));
        claims.extend(qsub(&moving, &qmul(r, &d)));
        claims.push(qnorm2(&fixed) - Poly::one());
        claims.push(qnorm2(&moving) - Poly::one());
    }
    Ideal { name: "juttler-2", gens, claims, sympy: false }
}

/// `r_0 Vec(q) - Scal(q) r` (Jüttler (27)): `q` is a real multiple of `r` when `r_0 != 0`.
fn projective_condition(q: &Quat, r: &Quat) -> Vec<Poly> {
    (1..4).map(|c| r[0].clone() * &q[c] - q[0].clone() * &r[c]).collect()
}

/// Jüttler's Proposition 3 (the projective method), at one interpolation point: `q =
/// Q_rot(t_i)` and `R = Rot(P_i)` symbolic quaternions satisfying (27), `r_0 != 0`
/// (Rabinowitsch), `D` a symbolic quaternion. Claims: (18) with `λ = q_0 / r_0`
/// (`r_0 q = q_0 R`), and (27) again for `D q, D R` and for `q D, R D` (the invariance under
/// the orientations of the fixed and the moving space). Uniqueness up to real factors is a
/// rank statement about (28) (`verify`'s `juttler/proposition-3`), not encoded here.
fn juttler_3() -> Ideal {
    let (q, r, d) = (quat_var("q"), quat_var("r"), quat_var("d"));
    let mut gens = projective_condition(&q, &r);
    gens.push(Poly::var("v") * &r[0] - Poly::one());
    let mut claims = qsub(&qscale(&r[0], &q), &qscale(&q[0], &r)).to_vec();
    claims.extend(projective_condition(&qmul(&d, &q), &qmul(&d, &r)));
    claims.extend(projective_condition(&qmul(&q, &d), &qmul(&r, &d)));
    Ideal { name: "juttler-3", gens, claims, sympy: false }
}

/// Jüttler's Proposition 4 (the TR method), `m + 1` symbolic positions `P_i = (2 + ε s_i) R_i`
/// at distinct symbolic parameters: a rotational motion `Q_rot` of degree `m` (symbolic
/// coefficients) with `Q_rot(t_i) = λ_i R_i` (18), two solutions `p`, `p'` of (31). Claims:
/// `p_j = p'_j` (uniqueness) and the interpolation `Q(t_i) = λ_i P_i` of the motion (30), real
/// and dual part (`2 Q_rot(t_i) = 2 λ_i R_i`, `p(t_i) Q_rot(t_i) = λ_i s_i R_i`). The degree
/// `k + m` and the dependence on the origin are not membership statements and are not encoded.
fn juttler_4(m: usize) -> Ideal {
    let ts: Vec<Poly> = (0..=m).map(|i| Poly::var(&format!("t{i}"))).collect();
    let rs: Vec<Quat> = (0..=m).map(|i| quat_var(&format!("r{i}"))).collect();
    let ss: Vec<Quat> = (0..=m).map(|i| pure(&format!("s{i}"))).collect();
    let lambda: Vec<Poly> = (0..=m).map(|i| Poly::var(&format!("l{i}"))).collect();
    let cs: Vec<Quat> = (0..=m).map(|j| quat_var(&format!("c{j}"))).collect();
    let mut gens = vec![distinct(&ts, "u")];
    for ((t, r), l) in ts.iter().zip(&rs).zip(&lambda) {
        gens.extend(qsub(&bezier(&cs, t), &qscale(l, r)));
    }
    let mut solutions = Vec::new();
    for name in ["p", "q"] {
        let ps: Vec<Quat> = (0..=m).map(|j| pure(&format!("{name}{j}"))).collect();
        for (t, s) in ts.iter().zip(&ss) {
            gens.extend(qsub(&bezier(&ps, t), s).into_iter().skip(1));
        }
        solutions.push(ps);
    }
    let mut claims: Vec<Poly> =
        solutions[0].iter().zip(&solutions[1]).flat_map(|(p, q)| qsub(p, q).into_iter().skip(1)).collect();
    for (((t, r), s), l) in ts.iter().zip(&rs).zip(&ss).zip(&lambda) {
        let rot = bezier(&cs, t);
        claims.extend(qsub(&qscale(&Poly::from_i64(2), &rot), &qscale(&Poly::from_i64(2), &qscale(l, r))));
        claims.extend(qsub(&qmul(&bezier(&solutions[0], t), &rot), &qscale(l, &qmul(s, r))));
    }
    Ideal { name: "juttler-4", gens, claims, sympy: false }
}

fn vars(prefix: &str, n: usize) -> Vec<Poly> {
    (0..n).map(|i| Poly::var(&format!("{prefix}{i}"))).collect()
}

/// cyclic-n: the elementary cyclic sums of degree 1..n-1 and x_0 ... x_{n-1} - 1.
fn cyclic(n: usize) -> Vec<Poly> {
    let x = vars("x", n);
    let mut eqs: Vec<Poly> = (1..n)
        .map(|k| (0..n).fold(Poly::zero(), |s, i| s + (0..k).fold(Poly::one(), |t, j| t * x[(i + j) % n].clone())))
        .collect();
    eqs.push(x.iter().fold(Poly::one(), |t, v| t * v.clone()) - Poly::one());
    eqs
}

/// katsura-n in u_0..u_n (as tests/fixtures/sympy/groebner.py defines it).
fn katsura(n: usize) -> Vec<Poly> {
    let u = vars("u", n + 1);
    let at = |i: i64| if i.unsigned_abs() as usize <= n { u[i.unsigned_abs() as usize].clone() } else { Poly::zero() };
    let n_i = n as i64;
    let mut eqs = vec![(-n_i..=n_i).fold(Poly::zero(), |s, i| s + at(i)) - Poly::one()];
    for m in 0..n_i {
        eqs.push((-n_i..=n_i).fold(Poly::zero(), |s, i| s + at(i) * at(m - i)) - at(m));
    }
    eqs
}

/// The number of intervals `m` of the Jüttler ideals (`m + 1` positions).
const JUTTLER_M: usize = 1;

fn suite() -> Vec<Ideal> {
    let std = |name, gens, sympy| Ideal { name, gens, claims: vec![], sympy };
    vec![
        docs_example(),
        lemma_2_2(),
        lemma_3_4(),
        study(1),
        study(2),
        study(3),
        juttler_1(JUTTLER_M),
        juttler_2(JUTTLER_M),
        juttler_3(),
        juttler_4(JUTTLER_M),
        std("cyclic-5", cyclic(5), true),
        std("cyclic-6", cyclic(6), false),
        std("katsura-5", katsura(5), true),
        std("katsura-6", katsura(6), false),
    ]
}

fn ring_of(ideal: &Ideal) -> PolyRing {
    let all: Vec<Poly> = ideal.gens.iter().chain(&ideal.claims).cloned().collect();
    PolyRing::of(&all, MonomialOrder::GrevLex)
}

/// GAM's times (basis + normal forms) over up to 5 runs (`GAM_REPS` in the environment: that
/// many, for steadier medians of the tiny ideals and for profiles) within about 2 s: the median
/// and the best; the basis size and whether every claim reduced to zero.
fn run_gam(ideal: &Ideal, budget: &Budget) -> Result<([Duration; 2], usize, bool), String> {
    let ring = ring_of(ideal);
    let mut times = Vec::new();
    let mut shape = (0, true);
    let start = Instant::now();
    let reps: usize = std::env::var("GAM_REPS").ok().and_then(|s| s.parse().ok()).unwrap_or(5);
    while times.len() < reps && (times.is_empty() || start.elapsed() < Duration::from_secs(2)) {
        let t = Instant::now();
        let g = ring.groebner(&ideal.gens, budget).map_err(|e| e.to_string())?;
        let zero = ideal.claims.iter().all(|c| g.contains(c).unwrap_or(false));
        times.push(t.elapsed());
        shape = (g.len(), zero);
    }
    times.sort();
    Ok(([times[times.len() / 2], times[0]], shape.0, shape.1))
}

/// A polynomial in Singular's (`python = false`) or sympy's syntax.
fn text(p: &Poly, python: bool) -> String {
    let pow = if python { "**" } else { "^" };
    let mut out = String::new();
    for (c, m) in p.terms() {
        let mono: Vec<String> =
            m.iter().map(|(v, e)| if *e == 1 { v.clone() } else { format!("{v}{pow}{e}") }).collect();
        let coeff = match (c.denom() == &1, python) {
            (true, _) => format!("{}", c.numer()),
            (false, false) => format!("({}/{})", c.numer(), c.denom()),
            (false, true) => format!("Rational({}, {})", c.numer(), c.denom()),
        };
        let _ = write!(out, " + ({coeff})");
        for f in mono {
            let _ = write!(out, "*{f}");
        }
    }
    if out.is_empty() { "0".into() } else { out[3..].to_string() }
}

fn write_singular(ideal: &Ideal, ring: &PolyRing, dir: &Path) -> PathBuf {
    let gens: Vec<String> = ideal.gens.iter().map(|p| text(p, false)).collect();
    let mut s = format!("ring r = 0, ({}), dp;\n", ring.variables().join(", "));
    let _ = writeln!(s, "ideal i = {};", gens.join(",\n  "));
    if !ideal.claims.is_empty() {
        let claims: Vec<String> = ideal.claims.iter().map(|p| text(p, false)).collect();
        let _ = writeln!(s, "ideal c = {};", claims.join(",\n  "));
    }
    s.push_str("system(\"--ticks-per-sec\", 1000000);\nint best = -1; int k; int t; ideal g; ideal n;\n");
    s.push_str("for (k = 1; k <= 5; k++) {\n  t = rtimer;\n  g = std(i);\n");
    if !ideal.claims.is_empty() {
        s.push_str("  n = reduce(c, g);\n");
    }
    s.push_str("  t = rtimer - t;\n  if (best < 0 || t < best) { best = t; }\n}\n");
    let zero = if ideal.claims.is_empty() { "1" } else { "size(n) == 0" };
    let _ =
        writeln!(s, "print(\"SINGULAR \" + string(best) + \" \" + string(size(g)) + \" \" + string({zero}));\nquit;");
    let path = dir.join(format!("{}.sing", ideal.name));
    std::fs::write(&path, s).expect("write .sing");
    path
}

fn write_sympy(ideal: &Ideal, ring: &PolyRing, dir: &Path) -> PathBuf {
    let gens: Vec<String> = ideal.gens.iter().map(|p| text(p, true)).collect();
    let claims: Vec<String> = ideal.claims.iter().map(|p| text(p, true)).collect();
    let v = ring.variables();
    let s = format!(
        "import time\nfrom sympy import symbols, groebner, reduced, Rational\n{} = symbols('{}', seq=True)\n\
         G = [{}]\nC = [{}]\nt = time.perf_counter()\nB = groebner(G, *{}, order='grevlex')\n\
         zero = all(reduced(c, list(B.exprs), *{}, order='grevlex')[1] == 0 for c in C)\n\
         print('SYMPY', int((time.perf_counter() - t) * 1e6), len(B.exprs), int(zero))\n",
        v.join(", ") + ",",
        v.join(" "),
        gens.join(",\n  "),
        claims.join(",\n  "),
        format_args!("[{}]", v.join(", ")),
        format_args!("[{}]", v.join(", ")),
    );
    let path = dir.join(format!("{}.py", ideal.name));
    std::fs::write(&path, s).expect("write .py");
    path
}

/// Runs `cmd` with a time limit; the first output line starting with `tag`, split.
fn external(mut cmd: Command, tag: &str, limit: Duration) -> Option<Vec<u128>> {
    let mut child = cmd.stdout(std::process::Stdio::piped()).stderr(std::process::Stdio::null()).spawn().ok()?;
    let start = Instant::now();
    loop {
        if child.try_wait().ok()?.is_some() {
            break;
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            return None;
        }
        std::thread::sleep(Duration::from_millis(5));
    }
    let out = child.wait_with_output().ok()?;
    let text = String::from_utf8_lossy(&out.stdout);
    let line = text.lines().find(|l| l.starts_with(tag))?;
    line.split_whitespace().skip(1).map(|x| x.parse().ok()).collect()
}

fn main() {
    let filter: Vec<String> = std::env::args().skip(1).filter(|a| !a.starts_with('-')).collect();
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/groebner-suite");
    std::fs::create_dir_all(&dir).expect("output directory");
    let budget = Budget { time: Some(Duration::from_secs(120)), ..Budget::default() };
    // `--gam-only`: GAM's times alone (A/B runs of the engine), no Singular or sympy
    let gam_only = std::env::args().any(|a| a == "--gam-only");
    let singular = !gam_only && Command::new("Singular").arg("--version").output().is_ok();
    println!("ideal          vars gens basis  GAM ms      Singular ms  GAM/Singular  sympy ms     sympy/GAM");
    for ideal in suite().into_iter().filter(|i| filter.is_empty() || filter.iter().any(|f| i.name.contains(f.as_str())))
    {
        let ring = ring_of(&ideal);
        let sing_file = write_singular(&ideal, &ring, &dir);
        let py_file = write_sympy(&ideal, &ring, &dir);
        let gam = run_gam(&ideal, &budget);
        let sing = singular
            .then(|| {
                let mut c = Command::new("Singular");
                c.arg("-q").arg(&sing_file);
                external(c, "SINGULAR", Duration::from_secs(300))
            })
            .flatten();
        let sympy = (ideal.sympy && !gam_only)
            .then(|| {
                let mut c = Command::new("python3");
                c.arg(&py_file);
                external(c, "SYMPY", Duration::from_secs(300))
            })
            .flatten();
        let (gam_ms, basis, zero) = match &gam {
            // against Singular the best of five, as its script takes (`best` over five `rtimer`
            // runs); alone (A/B runs of the engine) the median
            Ok(([median, best], b, z)) => {
                let t = if gam_only { median } else { best };
                (t.as_secs_f64() * 1e3, b.to_string(), *z)
            }
            Err(e) => {
                println!("{:<14} GAM: {e}", ideal.name);
                continue;
            }
        };
        let sing_ms = sing.as_ref().map(|v| v[0] as f64 / 1e3);
        let sympy_ms = sympy.as_ref().map(|v| v[0] as f64 / 1e3);
        if let Some(v) = &sing
            && (v[1].to_string() != basis || (v[2] == 1) != zero)
        {
            println!(
                "{:<14} MISMATCH: Singular basis {} zero {}, GAM basis {basis} zero {zero}",
                ideal.name, v[1], v[2]
            );
        }
        let fmt = |x: Option<f64>| x.map_or("-".to_string(), |x| format!("{x:.3}"));
        println!(
            "{:<14} {:>4} {:>4} {:>5}  {:>9.3}  {:>11}  {:>12}  {:>9}  {:>10}",
            ideal.name,
            ring.variables().len(),
            ideal.gens.len(),
            basis,
            gam_ms,
            fmt(sing_ms),
            sing_ms.map_or("-".into(), |s| format!("{:.1}x", gam_ms / s)),
            fmt(sympy_ms),
            sympy_ms.map_or("-".into(), |s| format!("{:.0}x", s / gam_ms)),
        );
    }
}
