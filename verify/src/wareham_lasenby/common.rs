//! Shared constructions: the paper's vectors e, ē, n, n̄ in `cga` (e = e4, ē = e5), planes
//! from a Pythagorean normal, the conformal embedding F and the closed forms typed in from
//! the paper.

use algebra_core::{Algebra, Basis, Multivector, Real, Ring};
use std::sync::Arc;

/// The runtime algebra R^{4,1}: e1, e2, e3 Euclidean, e4 = the paper's e (e² = 1),
/// e5 = the paper's ē (ē² = -1).
pub(super) fn cga() -> Arc<Algebra> {
    crate::algebra("cga")
}

/// A multivector from blade names (all names used here exist in `cga`).
pub(super) fn mv<T: Ring>(alg: &Arc<Algebra>, terms: Vec<(&str, T)>) -> Multivector<T> {
    Multivector::from_terms(alg, Basis::Blade, terms).expect("the blade names exist in cga")
}

/// The scalar `s`.
pub(super) fn scalar<T: Ring>(alg: &Arc<Algebra>, s: T) -> Multivector<T> {
    Multivector::scalar(alg, Basis::Blade, s)
}

/// n = e + ē = e4 + e5.
pub(super) fn n<T: Ring>(alg: &Arc<Algebra>) -> Multivector<T> {
    mv(alg, vec![("e4", T::one()), ("e5", T::one())])
}

/// n̄ = e - ē = e4 - e5.
pub(super) fn nbar<T: Ring>(alg: &Arc<Algebra>) -> Multivector<T> {
    mv(alg, vec![("e4", T::one()), ("e5", -T::one())])
}

/// The paper's e = e4.
pub(super) fn e<T: Ring>(alg: &Arc<Algebra>) -> Multivector<T> {
    mv(alg, vec![("e4", T::one())])
}

/// The Euclidean vector x1 e1 + x2 e2 + x3 e3.
pub(super) fn vector<T: Ring>(alg: &Arc<Algebra>, x: [T; 3]) -> Multivector<T> {
    let [a, b, c] = x;
    mv(alg, vec![("e1", a), ("e2", b), ("e3", c)])
}

/// The plane bivector with normal m: m1 e23 + m2 e31 + m3 e12 (it squares to -|m|²).
pub(super) fn plane<T: Ring>(alg: &Arc<Algebra>, m: &[T; 3]) -> Multivector<T> {
    mv(alg, vec![("e23", m[0].clone()), ("e13", m[1].neg_ref()), ("e12", m[2].clone())])
}

/// The Pythagorean normal m = (2uw, 2vw, u² + v² - w²) and its length N = u² + v² + w²:
/// every unit plane is plane(m)/N for some u, v, w (so P_u = plane(m) has P_u² = -N²).
pub(super) fn pythagorean<T: Ring>(u: &T, v: &T, w: &T) -> ([T; 3], T) {
    let two = T::from_i64(2);
    let (uu, vv, ww) = (u.mul_ref(u), v.mul_ref(v), w.mul_ref(w));
    let m = [two.mul_ref(u).mul_ref(w), two.mul_ref(v).mul_ref(w), uu.add_ref(&vv).sub_ref(&ww)];
    (m, uu.add_ref(&vv).add_ref(&ww))
}

/// The conformal embedding F(x) = (x² n + 2x - n̄)/2 (λ = 1).
pub(super) fn up<T: Ring>(alg: &Arc<Algebra>, x: &Multivector<T>) -> Multivector<T> {
    let x2 = (x * x).scalar_part();
    let half = T::from_ratio(1, 2);
    &(&n(alg).scale(&x2.mul_ref(&half)) + x) - &nbar(alg).scale(&half)
}

/// The component of the vector t in the plane of the unit 2-blade P (P² = -1):
/// t_par = (t⌋P) P^{-1} = -(t⌋P) P.
pub(super) fn in_plane<T: Ring>(t: &Multivector<T>, p: &Multivector<T>) -> Multivector<T> {
    -(&t.lc(p) * p)
}

/// sinc z = sin z / z (1 at z = 0).
pub(super) fn sinc<T: Real>(z: &T) -> T {
    if z.is_exact_zero() { T::one() } else { z.sin().div_ref(z) }
}

/// The closed form of Theorem 3: exp(φP + tn) = [cos φ + sin φ P][1 + t_perp n] + sinc(φ) t_par n,
/// typed in from the paper, from cos φ, sin φ and sinc φ.
pub(super) fn theorem_3_form<T: Ring>(
    alg: &Arc<Algebra>,
    (cos, sin, sinc): (&T, &T, &T),
    p: &Multivector<T>,
    t: &Multivector<T>,
) -> Multivector<T> {
    let nn = n(alg);
    let t_par = in_plane(t, p);
    let t_perp = t - &t_par;
    let rot = &scalar(alg, cos.clone()) + &p.scale(sin);
    &(&rot * &(&scalar(alg, T::one()) + &(&t_perp * &nn))) + &(&t_par * &nn).scale(sinc)
}

/// The twist of Definition 4: τ(ψ, P, a) = [cos(ψ/2) + sin(ψ/2) P][1 + n a/2], from
/// c = cos(ψ/2) and s = sin(ψ/2).
pub(super) fn twist<T: Ring>(
    alg: &Arc<Algebra>,
    (c, s): (&T, &T),
    p: &Multivector<T>,
    a: &Multivector<T>,
) -> Multivector<T> {
    let rot = &scalar(alg, c.clone()) + &p.scale(s);
    let trans = &scalar(alg, T::one()) + &(&n(alg) * a).scale(&T::from_ratio(1, 2));
    &rot * &trans
}
