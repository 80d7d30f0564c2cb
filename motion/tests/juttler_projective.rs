//! Jüttler's projective method (27)-(28), Proposition 3: interpolation up to real factors
//! exactly over rationals, invariance under fixed rotations of the fixed and of the moving
//! space (exactly, as curves up to one real factor), half turns, and the typed errors for a
//! wrong count, a non-unique or trivial solution and an inaccessible position.

use algebra_core::rational::{Q, q, ratio};
use gam_algebras::dual_quaternion::Quaternion;
use motion::juttler::projective::{null_space, projective, projective_with_degree, system};
use motion::juttler::{JuttlerError, QMotion};

fn quat(c: [i64; 4]) -> Quaternion<Q> {
    Quaternion::new(q(c[0]), q(c[1]), q(c[2]), q(c[3]))
}

fn coords(x: &Quaternion<Q>) -> [Q; 4] {
    [x.w.clone(), x.x.clone(), x.y.clone(), x.z.clone()]
}

/// `a = λ b` for one `λ ≠ 0` (all 2x2 minors vanish, neither is zero).
fn proportional(a: &[Q], b: &[Q]) -> bool {
    let nonzero = |v: &[Q]| v.iter().any(|x| *x != q(0));
    nonzero(a) && nonzero(b) && (0..a.len()).all(|k| (0..a.len()).all(|l| &a[k] * &b[l] == &a[l] * &b[k]))
}

fn flat(m: &QMotion<Q>) -> Vec<Q> {
    m.control().iter().flat_map(|c| coords(&c.real)).collect()
}

fn five() -> (Vec<Quaternion<Q>>, Vec<Q>) {
    let r = [[1, 0, 0, 0], [2, 1, 0, -1], [0, 1, 1, 0], [1, -3, 2, 1], [2, -1, 0, 3]].map(quat).to_vec();
    (r, vec![q(0), ratio(1, 5), ratio(1, 2), ratio(2, 3), q(1)])
}

#[test]
fn projective_interpolates_up_to_real_factors_exactly() {
    let (r, t) = five();
    let rot = projective(&r, &t).unwrap();
    assert_eq!(rot.degree(), 3); // k = 3m/4
    assert!(rot.control().iter().all(|c| c.dual == Quaternion::zero()));
    assert_eq!(rot.eval(&t[0]).real, r[0]);
    for (ri, ti) in r.iter().zip(&t) {
        assert!(proportional(&coords(&rot.eval(ti).real), &coords(ri)));
    }
    // the solution spans the null space of (28): the system has rank 15 of 16 unknowns
    let a = system(&r, &t, 3).unwrap();
    assert_eq!((a.len(), null_space(&a, 16).len()), (15, 1));
    // nine rotations: degree 6
    let r9: Vec<_> = (0..9i64).map(|i| quat([1 + i % 3, i - 4, (i * i) % 5, 2 - (i % 4)])).collect();
    let t9: Vec<Q> = (0..9).map(|i| ratio(i, 8)).collect();
    let rot9 = projective(&r9, &t9).unwrap();
    assert_eq!(rot9.degree(), 6);
    for (ri, ti) in r9.iter().zip(&t9) {
        assert!(proportional(&coords(&rot9.eval(ti).real), &coords(ri)));
    }
}

#[test]
fn projective_reaches_half_turns() {
    // r_{i,0} = 0: Jüttler's (27) alone leaves Vec Q(t_i) free there; the minors we use do not
    let mut r = five().0;
    r[2] = quat([0, 1, 2, 2]);
    r[4] = quat([0, 0, 0, 1]);
    let t = five().1;
    let rot = projective(&r, &t).unwrap();
    for (ri, ti) in r.iter().zip(&t) {
        assert!(proportional(&coords(&rot.eval(ti).real), &coords(ri)));
    }
}

#[test]
fn proposition_3_invariance_under_fixed_rotations() {
    let (r, t) = five();
    let rot = projective(&r, &t).unwrap();
    // non-unit D too: the method is invariant under every linear map of H
    for d in [quat([1, 2, -1, 3]), Quaternion::new(ratio(3, 5), q(0), ratio(4, 5), q(0))] {
        let fixed: Vec<_> = r.iter().map(|x| &d * x).collect();
        let moving: Vec<_> = r.iter().map(|x| x * &d).collect();
        let expect_fixed: Vec<Q> = rot.control().iter().flat_map(|c| coords(&(&d * &c.real))).collect();
        let expect_moving: Vec<Q> = rot.control().iter().flat_map(|c| coords(&(&c.real * &d))).collect();
        assert!(proportional(&flat(&projective(&fixed, &t).unwrap()), &expect_fixed));
        assert!(proportional(&flat(&projective(&moving, &t).unwrap()), &expect_moving));
    }
}

#[test]
fn projective_errors_are_typed() {
    let (r, t) = five();
    assert_eq!(projective(&r[..4], &t[..4]), Err(JuttlerError::ProjectiveCount { positions: 4 }));
    assert_eq!(projective_with_degree(&r, &t, 4), Err(JuttlerError::NotUnique { dimension: 5 }));
    assert_eq!(projective_with_degree(&r, &t, 1), Err(JuttlerError::OnlyTrivial));
    let mut z = r.clone();
    z[3] = Quaternion::zero();
    assert_eq!(projective(&z, &t), Err(JuttlerError::ZeroQuaternion { index: 3 }));
    assert!(matches!(projective(&r, &t[..4]), Err(JuttlerError::Parameters { .. })));
}

#[test]
fn a_position_where_the_interpolant_vanishes_is_inaccessible() {
    // Q(t) = (t - 1/2) A(t), A quadratic: the data Q(t_i) (i != 2) plus any R_2 are solved by Q,
    // which vanishes at t_2 = 1/2
    let a = [quat([1, 2, 0, -1]), quat([3, -1, 2, 1]), quat([-2, 1, 1, 4])];
    let qf = |s: &Q| {
        let (c, f) = (a.iter().map(coords).collect::<Vec<_>>(), s - &ratio(1, 2));
        let v: [Q; 4] = std::array::from_fn(|j| (&c[0][j] + &(&c[1][j] * s) + &c[2][j] * s * s) * &f);
        let [w, x, y, z] = v;
        Quaternion::new(w, x, y, z)
    };
    let (_, t) = five();
    let mut r: Vec<_> = t.iter().map(qf).collect();
    r[2] = quat([1, 0, 0, 0]); // off the plane of A(t) (the data at i != 2 lie in span(A_0, A_1, A_2))
    assert_eq!(projective(&r, &t), Err(JuttlerError::Inaccessible { index: 2 }));
}

#[test]
fn projective_in_f64_interpolates() {
    let r: [Quaternion<f64>; 5] = [
        [1.0, 0.0, 0.0, 0.0],
        [0.9, 0.3, 0.0, -0.2],
        [0.5, 0.5, 0.5, 0.1],
        [0.1, -0.7, 0.2, 0.6],
        [0.0, 0.2, -0.4, 0.9],
    ]
    .map(|[w, x, y, z]| Quaternion::new(w, x, y, z));
    let t = [0.0, 0.2, 0.45, 0.7, 1.0];
    let rot = projective(&r, &t).unwrap();
    for (ri, ti) in r.iter().zip(&t) {
        let v = rot.eval(ti).real;
        // |v ∧ r| relative to |v||r|: the sine of the angle between them in H
        let cos2: f64 = v.dot(ri).powi(2) / (v.norm_squared() * ri.norm_squared());
        assert!((1.0 - cos2).abs() < 1e-12, "{cos2}");
    }
}
