//! (58)-(60): Angelidis' decoupled motion, the translation by `u m` followed by the rotation
//! by `uω` about the moved centre `c + u m` (59), and the trajectory (60) the paper derives for
//! it. What holds is computed from the poses of the main paper (a translation, a rotor about an
//! axis through a point, `motion::Pose` products over `Poly`), independently of (29) and (60).
//!
//! Symbolically, with `ω = θ n` for rational unit vectors `n`, `θ`, `u`, `p`, `c`, `m` symbols
//! and the rotor `ch + sh (n e123)` (`ch`, `sh` standing for `cos(uθ/2)`, `sin(uθ/2)` up to a
//! common factor, so `cos|uω| = (ch² - sh²)/w`, `sin|uω| = 2 ch sh / w`, `w = ch² + sh²`), all
//! multiplied by `w u² θ²`: the printed (60) equals the trajectory only at `u = 1`; (60) with
//! the factors `u²` on `ω × ξ` and `u` on `ξ` equals it for every `u`. At 256 bits, on a rational
//! instance (`cos|uω| = 3/5` at `u = 1/2`, where the printed and the corrected forms are exact
//! rationals): the power series of (59)'s hexanions and the library's
//! [`Decoupled`](motion::repr::hexanion::blend::Decoupled) (its pose and its trajectory) agree
//! with the corrected form; and the printed form tends to `p + ξ + ω × ξ/2`, not `p`, as `u → 0`.

use super::{DIGITS, V3, apply, cross, dot, hex, mmul, point4, series, vadd, vscale};
use crate::Checker;
use algebra_core::rational::{Q, q, ratio};
use algebra_core::{Field, MpFloat, Poly, PrecisionGuard, Real, Ring};
use motion::Pose;
use motion::repr::hexanion::blend::Decoupled;

fn var(name: &str) -> Poly {
    Poly::var(name)
}

fn vsub<T: Ring>(a: &V3<T>, b: &V3<T>) -> V3<T> {
    std::array::from_fn(|i| a[i].sub_ref(&b[i]))
}

/// The symbols of one check: the axis `n` (rational, unit), `θ = |ω|`, the rotor's `ch`, `sh`,
/// the parameter `u`, the centre `c`, the translation `m`.
struct Motion59 {
    n: V3<Poly>,
    th: Poly,
    ch: Poly,
    sh: Poly,
    u: Poly,
    c: V3<Poly>,
    m: V3<Poly>,
}

impl Motion59 {
    /// `w = ch² + sh²`, the weight of the rotor's images.
    fn w(&self) -> Poly {
        self.ch.mul_ref(&self.ch).add_ref(&self.sh.mul_ref(&self.sh))
    }

    /// The homogeneous image `(y, w)` of `p` under the pose of (59): translate by `u m`, then
    /// turn by the rotor `ch + sh (n e123)` about the axis along `n` through `c + u m`.
    fn image(&self, p: &V3<Poly>) -> [Poly; 4] {
        let um = vscale(&self.u, &self.m);
        let centre = vadd(&self.c, &um);
        let back = centre.clone().map(|x| x.neg_ref());
        let rotor = Pose::rotor_from_parts(&self.ch, &self.sh, &self.n);
        let about = &(&Pose::translation(&back) * &rotor) * &Pose::translation(&centre);
        let pose = &Pose::translation(&um) * &about;
        pose.apply_homogeneous(&[p[0].clone(), p[1].clone(), p[2].clone(), Poly::one()])
    }

    /// `(60)` cleared of denominators, with the factors `fa` on `ω × ξ` and `fb` on `ξ` (`1, 1`
    /// as printed; `u², u` corrected): `D C = D(p + um) + fa 2sh² θ² n × (n × (p - c)) + fb 2 ch
    /// sh uθ · θ n × (p - c)`, `D = w u² θ²` (the printed coefficients `(1 - cos|uω|)/|uω|²` and
    /// `sin|uω|/|uω|` times `D`).
    fn eq_60_cleared(&self, p: &V3<Poly>, fa: &Poly, fb: &Poly) -> V3<Poly> {
        let (th, ch, sh, u) = (&self.th, &self.ch, &self.sh, &self.u);
        let d = self.w().mul_ref(u).mul_ref(u).mul_ref(th).mul_ref(th);
        let omega = vscale(th, &self.n);
        let xi = cross(&omega, &vsub(p, &self.c));
        let two = Poly::from_i64(2);
        let a = two.mul_ref(sh).mul_ref(sh).mul_ref(fa);
        let b = two.mul_ref(ch).mul_ref(sh).mul_ref(u).mul_ref(th).mul_ref(fb);
        let start = vadd(p, &vscale(u, &self.m));
        std::array::from_fn(|i| d.mul_ref(&start[i]) + a.mul_ref(&cross(&omega, &xi)[i]) + b.mul_ref(&xi[i]))
    }
}

fn symbolic(c: &mut Checker) {
    let p = [var("p1"), var("p2"), var("p3")];
    let units: [[Q; 3]; 3] =
        [[q(1), q(0), q(0)], [ratio(2, 7), ratio(3, 7), ratio(6, 7)], [ratio(4, 9), ratio(-4, 9), ratio(7, 9)]];
    for nq in &units {
        let mo = Motion59 {
            n: nq.clone().map(|x| Poly::from_q(&x)),
            th: var("θ"),
            ch: var("ch"),
            sh: var("sh"),
            u: var("u"),
            c: [var("c1"), var("c2"), var("c3")],
            m: [var("m1"), var("m2"), var("m3")],
        };
        let (th, ch, sh, u) = (&mo.th, &mo.ch, &mo.sh, &mo.u);
        let label = format!("n = ({}, {}, {})", nq[0], nq[1], nq[2]);
        let y = mo.image(&p);
        c.equal(format!("{label}: the weight of (59)'s image is w = ch² + sh²"), &y[3], &mo.w());
        let truth: V3<Poly> = std::array::from_fn(|i| y[i].mul_ref(u).mul_ref(u).mul_ref(th).mul_ref(th));
        let uu = u.mul_ref(u);
        c.equal(
            format!("{label}: (59) moves p along (60) with the factors u² on ω × ξ and u on ξ, for all u"),
            &truth,
            &mo.eq_60_cleared(&p, &uu, u),
        );
        let one = Poly::one();
        let printed = mo.eq_60_cleared(&p, &one, &one);
        let at1 = |v: &V3<Poly>| v.clone().map(|x| x.substitute("u", &one));
        c.equal(format!("{label}: the printed (60) holds at u = 1, the end pose (58)"), &at1(&printed), &at1(&truth));
        let diff = vsub(&printed, &truth);
        // the difference: (1 - u²) (1 - cos|uω|)/|uω|² ω × ξ + (1 - u) sin|uω|/|uω| ξ, cleared
        let omega = vscale(th, &mo.n);
        let xi = cross(&omega, &vsub(&p, &mo.c));
        let two = Poly::from_i64(2);
        let ka = two.mul_ref(sh).mul_ref(sh).mul_ref(&one.sub_ref(&uu));
        let kb = two.mul_ref(ch).mul_ref(sh).mul_ref(u).mul_ref(th).mul_ref(&one.sub_ref(u));
        let expect: V3<Poly> = std::array::from_fn(|i| ka.mul_ref(&cross(&omega, &xi)[i]) + kb.mul_ref(&xi[i]));
        c.equal(
            format!("{label}: printed - trajectory = (1 - u²)(1 - cos|uω|)/|uω|² ω × ξ + (1 - u) sin|uω|/|uω| ξ"),
            &diff,
            &expect,
        );
        c.counterexample(
            format!("{label}: the printed (60) for every u"),
            diff.iter().all(|x| *x == Poly::zero()),
            "the printed form lacks the factors u² on ω × ξ and u on ξ (they are right only at u = 1)",
        );
        // the centre moves straight: from c to c + m
        let yc = mo.image(&mo.c);
        let straight: V3<Poly> = std::array::from_fn(|i| mo.w().mul_ref(&mo.c[i].add_ref(&u.mul_ref(&mo.m[i]))));
        c.equal(
            format!("{label}: the centre c moves straight to c + m: C(c, u) = c + u m"),
            &[yc[0].clone(), yc[1].clone(), yc[2].clone()],
            &straight,
        );
    }
}

/// A rational instance and its trajectory point, true and as printed.
struct Instance {
    n: V3<Q>,
    p: V3<Q>,
    c: V3<Q>,
    m: V3<Q>,
    truth: V3<Q>,
    printed: V3<Q>,
}

/// The rational instance `u = 1/2`, `ω = θ n`, `n = (2, 3, 6)/7`, `θ = 4 atan(1/2)` (so
/// `cos|uω| = 3/5`, `sin|uω| = 4/5`): the trajectory and the printed form, exactly.
fn instance() -> Instance {
    let n = [ratio(2, 7), ratio(3, 7), ratio(6, 7)];
    let (p, cc, m) = ([q(1), q(-2), ratio(1, 2)], [ratio(1, 3), q(1), q(-1)], [q(2), ratio(-1, 2), q(3)]);
    let u = ratio(1, 2);
    let (cos, sin) = (ratio(3, 5), ratio(4, 5));
    let r = vsub(&p, &cc);
    let (nr, nnr) = (cross(&n, &r), cross(&n, &cross(&n, &r)));
    // (1 - cos)/|uω|² ω × ξ = (1 - cos)/u² n × (n × r) as printed; times u² corrected; likewise sin
    let start = vadd(&p, &vscale(&u, &m));
    let a_printed = (q(1) - &cos) / (&u * &u);
    let b_printed = &sin / &u;
    let printed = vadd(&start, &vadd(&vscale(&a_printed, &nnr), &vscale(&b_printed, &nr)));
    let truth = vadd(&start, &vadd(&vscale(&(q(1) - &cos), &nnr), &vscale(&sin, &nr)));
    Instance { n, p, c: cc, m, truth, printed }
}

/// A small rational as an MPFR float (numerator and denominator fit in `i64` here).
fn mp(x: &Q) -> MpFloat {
    use num_traits::ToPrimitive;
    let (n, d) = (x.numer().to_i64().expect("a small rational"), x.denom().to_i64().expect("a small rational"));
    MpFloat::from_ratio(n, d)
}

/// `10^-k`.
fn tenth_pow(k: u32) -> MpFloat {
    (0..k).fold(MpFloat::one(), |acc, _| acc.mul_ref(&MpFloat::from_ratio(1, 10)))
}

fn numeric(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    let Instance { n, p, c: cc, m, truth, printed } = instance();
    c.check("u = 1/2, cos|uω| = 3/5: the printed (60) differs from the trajectory (exact rationals)", printed != truth);
    let theta = MpFloat::from_i64(4).mul_ref(&Real::atan2(&MpFloat::one(), &MpFloat::from_i64(2)));
    let u = MpFloat::from_ratio(1, 2);
    let (nf, pf, cf, mf) = (n.map(|x| mp(&x)), p.map(|x| mp(&x)), cc.map(|x| mp(&x)), m.map(|x| mp(&x)));
    let omega = vscale(&theta, &nf);
    let truth_f = truth.map(|x| mp(&x));
    c.close(
        "cos|uω| = 3/5 at u = 1/2 for θ = 4 atan(1/2)",
        &[Real::cos(&u.mul_ref(&theta))],
        &[mp(&ratio(3, 5))],
        DIGITS,
    );
    // the power series of (59): exp(<uω, (c + um) × uω>) exp(<0, um>)
    let (uw, um) = (vscale(&u, &omega), vscale(&u, &mf));
    let zero = [MpFloat::zero(), MpFloat::zero(), MpFloat::zero()];
    let rot = series(&hex(&uw, &cross(&vadd(&cf, &um), &uw)));
    let shift = series(&hex(&zero, &um));
    let img = apply(&mmul(&rot, &shift), &point4(&pf));
    c.close("the power series of (59) moves p to the corrected (60)", &img[..3], &truth_f, DIGITS);
    let d = Decoupled { omega: omega.clone(), m: mf.clone(), centre: cf.clone() };
    c.close("Decoupled::trajectory = the corrected (60)", &d.trajectory(&pf, &u), &truth_f, DIGITS);
    if let Some(pose) = c.ok("Decoupled::pose_at", d.pose_at(&u))
        && let Some(img) = c.ok("Decoupled::pose_at(u).transform_point", pose.transform_point(&pf))
    {
        c.close("Decoupled::pose_at(u) moves p to the corrected (60)", &img, &truth_f, DIGITS);
    }
    // the printed (60) as u -> 0: p + ξ + ω × ξ/2 (the limits |ω|²/2 · 1/|ω|² ... of its coefficients)
    // u = 10^-20: 1 - cos|uω| ~ 10^-40 keeps ~36 of the 77 digits; the error of the limit is O(u)
    let tiny = tenth_pow(20);
    let uw = vscale(&tiny, &omega);
    let th = Real::sqrt(&dot(&uw, &uw));
    let (a, b) = (MpFloat::one().sub_ref(&Real::cos(&th)).div_ref(&th.mul_ref(&th)), Real::sin(&th).div_ref(&th));
    let xi = cross(&omega, &vsub(&pf, &cf));
    let printed_small =
        vadd(&vadd(&pf, &vscale(&tiny, &mf)), &vadd(&vscale(&a, &cross(&omega, &xi)), &vscale(&b, &xi)));
    let limit = vadd(&pf, &vadd(&xi, &vscale(&MpFloat::from_ratio(1, 2), &cross(&omega, &xi))));
    c.close("the printed (60) at u = 10^-20 is p + ξ + ω × ξ/2 (to 15 digits), not p", &printed_small, &limit, 15);
    c.counterexample(
        "the printed (60) starts at p (C(p, 0) = p)",
        super::agrees(&printed_small, &pf),
        "as u -> 0 the printed C(p, u) tends to p + ξ + ω × ξ/2 (ξ = ω × (p - c)): the end pose's rotation, not the start",
    );
}

pub(super) fn eq_60(c: &mut Checker) {
    symbolic(c);
    numeric(c);
}
