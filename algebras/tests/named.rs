//! Named constructors (`algebra_codegen::named`), checked against independent formulas: a
//! Rodrigues rotation matrix for rotors and motors, coordinates for translations, incidence
//! (`∧ = 0`) for planes and lines, exactly over rationals where no angle is involved, and
//! klein's published point convention (`x e032 + y e013 + z e021 + e123`) in a module that
//! names its blades in that orientation.

use algebra_core::rational::{Q, q, ratio};
use gam_algebras::{g3, pga3};
use pga3::{OuterProduct, RegressiveProduct};

algebra_macros::algebra! {
    /// PGA in klein's orientation, planes, lines, points and motors only.
    pub mod pga_klein {
        metric builtin "pga3";
        types {
            Plane = grade 1;
            Line = [e01, e02, e03, e12, e31, e23];
            Point = [e032, e013, e021, e123];
            Motor = [1, e23, e31, e12, e01, e02, e03, e0123];
        }
    }
}

algebra_macros::algebra! {
    /// 2D PGA.
    pub mod pga2 {
        generators { e0, e1, e2 }
        metric { (e1, e1) = 1, (e2, e2) = 1 }
        types {
            Line = grade 1;
            Point = grade 2;
            Motor = even;
        }
    }
}

/// The rotation matrix by `angle` about the unit `axis` (Rodrigues).
fn rodrigues(axis: [f64; 3], angle: f64) -> [[f64; 3]; 3] {
    let n = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
    let [x, y, z] = axis.map(|a| a / n);
    let (c, s) = (angle.cos(), angle.sin());
    let t = 1.0 - c;
    [
        [c + x * x * t, x * y * t - z * s, x * z * t + y * s],
        [y * x * t + z * s, c + y * y * t, y * z * t - x * s],
        [z * x * t - y * s, z * y * t + x * s, c + z * z * t],
    ]
}

fn mul(m: &[[f64; 3]; 3], v: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| (0..3).map(|k| m[i][k] * v[k]).sum())
}

/// The Euclidean coordinates of a pga3 point (weight 1 after division).
fn coords(p: &pga3::Trivector<f64>) -> [f64; 3] {
    let back = pga3::point(&[1.0, 0.0, 0.0]);
    let o = pga3::point(&[0.0; 3]);
    // point(x) = o + Σ x_k (point(e_k) - o): read x_k off the field that point(e_k) changes
    let w = p.e123 / o.e123;
    let ex = [back, pga3::point(&[0.0, 1.0, 0.0]), pga3::point(&[0.0, 0.0, 1.0])];
    let diff = |e: &pga3::Trivector<f64>| e.to_array().iter().zip(o.to_array()).map(|(a, b)| a - b).collect::<Vec<_>>();
    std::array::from_fn(|k| {
        let d = diff(&ex[k]);
        let i = d.iter().position(|x| *x != 0.0).expect("a changed field");
        (p.to_array()[i] / w - o.to_array()[i]) / d[i]
    })
}

fn close(a: [f64; 3], b: [f64; 3], tol: f64) -> bool {
    a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= tol)
}

#[test]
fn klein_point_convention_in_klein_names() {
    // klein: a point (x, y, z) is x e032 + y e013 + z e021 + e123
    let p = pga_klein::point(&[q(2), q(-3), ratio(1, 2)]);
    assert_eq!(p.to_array(), [q(2), q(-3), ratio(1, 2), q(1)]);
    // and the canonical module agrees geometrically: e032 = -e023, e013 = +e013, e021 = -e012
    let c = pga3::point(&[q(2), q(-3), ratio(1, 2)]);
    assert_eq!((c.e023.clone(), c.e013.clone(), c.e012.clone(), c.e123.clone()), (q(-2), q(-3), ratio(-1, 2), q(1)));
}

#[test]
fn translators_move_points_and_keep_directions_exactly() {
    let (p, t) = ([q(1), q(2), q(3)], [ratio(1, 2), q(-4), q(7)]);
    let moved = pga3::translator(&t).apply(&pga3::point(&p));
    let want: [Q; 3] = std::array::from_fn(|k| &p[k] + &t[k]);
    assert_eq!(moved, pga3::point(&want));
    let d = pga3::direction(&[q(1), q(-1), q(2)]);
    assert_eq!(pga3::translator(&t).apply(&d), d);
    // klein's module: the same
    let moved = pga_klein::translator(&t).apply(&pga_klein::point(&p));
    assert_eq!(moved, pga_klein::point(&want));
    // 2D
    let moved = pga2::translator(&[q(3), q(-1)]).apply(&pga2::point(&[q(1), q(1)]));
    assert_eq!(moved, pga2::point(&[q(4), q(0)]));
}

#[test]
fn planes_and_lines_contain_their_points_exactly() {
    // the plane x + 2y - z = 4 contains (4, 0, 0), (0, 2, 0), (1, 1, -1), not (0, 0, 0)
    let plane = pga3::plane(&[q(1), q(2), q(-1)], &q(4));
    for p in [[q(4), q(0), q(0)], [q(0), q(2), q(0)], [q(1), q(1), q(-1)]] {
        assert!(plane.op(&pga3::point(&p)).to_array().iter().all(|c| *c == q(0)));
    }
    assert!(plane.op(&pga3::point(&[q(0), q(0), q(0)])).to_array().iter().any(|c| *c != q(0)));
    // the line through p and q contains p, q and p + 2 (q - p), not a point off it: the join
    // of the line and a point is zero exactly when the point is on the line
    let (p, r) = ([q(1), q(0), q(2)], [q(-1), q(3), q(1)]);
    let line = pga3::line_through(&p, &r);
    let far: [Q; 3] = std::array::from_fn(|k| &p[k] + q(2) * (&r[k] - &p[k]));
    for x in [p.clone(), r.clone(), far] {
        assert!(line.regressive(&pga3::point(&x)).to_array().iter().all(|c| *c == q(0)), "{x:?}");
    }
    assert!(line.regressive(&pga3::point(&[q(0), q(0), q(0)])).to_array().iter().any(|c| *c != q(0)));
    // 2D: the line x - y = 1 through (1, 0) and (3, 2)
    let l = pga2::line(&[q(1), q(-1)], &q(1));
    for x in [[q(1), q(0)], [q(3), q(2)]] {
        assert!(l.op(&pga2::point(&x)).to_array().iter().all(|c| *c == q(0)));
    }
}

#[test]
fn rotors_and_motors_match_rodrigues() {
    let axes = [[0.0, 0.0, 1.0], [1.0, 2.0, -2.0], [-0.3, 0.5, 0.1]];
    let xs = [[1.0, 0.0, 0.0], [0.5, -1.5, 2.0], [3.0, 1.0, -1.0]];
    for axis in axes {
        for angle in [0.3, 1.0, -2.5, std::f64::consts::FRAC_PI_2] {
            let m = rodrigues(axis, angle);
            let r = pga3::rotor(&axis, &angle).unwrap();
            let t = [0.5, -2.0, 1.25];
            let motor = pga3::motor(&axis, &angle, &t).unwrap();
            let p = [1.0, -1.0, 0.5];
            let about = pga3::rotor_about_line(&p, &axis, &angle).unwrap();
            let gr = g3::rotor(&axis, &angle).unwrap();
            for x in xs {
                let rx = mul(&m, x);
                assert!(close(coords(&r.apply(&pga3::point(&x))), rx, 1e-12), "rotor {axis:?} {angle}");
                let want: [f64; 3] = std::array::from_fn(|k| rx[k] + t[k]);
                assert!(close(coords(&motor.apply(&pga3::point(&x))), want, 1e-12), "motor");
                let rel = mul(&m, std::array::from_fn(|k| x[k] - p[k]));
                let want: [f64; 3] = std::array::from_fn(|k| p[k] + rel[k]);
                assert!(close(coords(&about.apply(&pga3::point(&x))), want, 1e-12), "about a line");
                let v = gr.apply(&g3::Vector::new(x[0], x[1], x[2]));
                assert!(close([v.e1, v.e2, v.e3], rx, 1e-12), "g3 rotor");
            }
        }
    }
    // a quarter turn about e3 in klein's names takes (1, 0, 0) to (0, 1, 0)
    let h = std::f64::consts::FRAC_PI_2;
    let p = pga_klein::rotor(&[0.0, 0.0, 1.0], &h).unwrap().apply(&pga_klein::point(&[1.0, 0.0, 0.0]));
    assert!(
        close([p.e032, p.e013, p.e021], [0.0, 1.0, 0.0], 1e-15) && (p.e123 - 1.0).abs() < 1e-15,
        "{:?}",
        p.to_array()
    );
    // 2D: counter-clockwise about the origin and about (1, 1)
    let p = pga2::rotor(&h).unwrap().apply(&pga2::point(&[1.0, 0.0]));
    let want = pga2::point(&[0.0, 1.0]);
    assert!(p.to_array().iter().zip(want.to_array()).all(|(a, b)| (a - b).abs() < 1e-15), "{:?}", p.to_array());
    let p = pga2::rotor_about_point(&[1.0, 1.0], &h).unwrap().apply(&pga2::point(&[2.0, 1.0]));
    let want = pga2::point(&[1.0, 2.0]);
    assert!(p.to_array().iter().zip(want.to_array()).all(|(a, b)| (a - b).abs() < 1e-14), "{:?}", p.to_array());
}

#[test]
fn bad_axes_and_angles_are_typed_errors() {
    assert!(pga3::rotor(&[0.0; 3], &1.0).is_err());
    assert!(pga3::rotor(&[1.0, 0.0, 0.0], &f64::NAN).is_err());
    assert!(pga3::motor(&[1.0, 0.0, 0.0], &1.0, &[f64::INFINITY, 0.0, 0.0]).is_err());
    assert!(g3::rotor(&[1e300, 1e300, 0.0], &1.0).is_err(), "|axis|² overflows");
    assert!(pga2::rotor(&f64::INFINITY).is_err());
}

/// The conformal checks on one module: `$m` a path to a conformal module with `Vector`.
macro_rules! conformal_checks {
    ($m:ident) => {{
        use gam_algebras::$m;
        use $m::ScalarProduct;
        let p = [q(1), ratio(-1, 2), q(3)];
        let r = [q(-2), q(0), ratio(1, 3)];
        // down ∘ up is the identity, exactly; up(p) · up(r) = -|p - r|²/2
        assert_eq!($m::down(&$m::up(&p)).unwrap(), p);
        assert_eq!($m::point(&p), $m::up(&p));
        let d2: Q = (0..3).map(|k| (&p[k] - &r[k]) * (&p[k] - &r[k])).sum();
        assert_eq!($m::up(&p).sp(&$m::up(&r)).scalar, -d2 / q(2));
        // a point of weight 3 still goes down to p
        assert_eq!($m::down(&($m::up(&p) * q(3))).unwrap(), p);
        // the sphere about r of radius 2 holds r + (0, 2, 0) and not r
        let sphere = $m::sphere(&r, &q(2));
        let on = [r[0].clone(), &r[1] + q(2), r[2].clone()];
        assert_eq!($m::up(&on).sp(&sphere).scalar, q(0));
        assert_ne!($m::up(&r).sp(&sphere).scalar, q(0));
        // up(x) · plane(n, d) = n · x - d
        let plane = $m::plane(&[q(1), q(2), q(-1)], &q(4));
        assert_eq!($m::up(&p).sp(&plane).scalar, q(1) - q(1) - q(3) - q(4));
        // translators move points exactly
        let t = [ratio(1, 2), q(-4), q(7)];
        let want: [Q; 3] = std::array::from_fn(|k| &p[k] + &t[k]);
        assert_eq!($m::down(&$m::translator(&t).apply(&$m::up(&p))).unwrap(), want);
        // motors and rotations about a line against Rodrigues, dilators scale about the origin
        let (axis, angle, tf) = ([1.0, 2.0, -2.0], 0.7, [0.5, -2.0, 1.25]);
        let m = rodrigues(axis, angle);
        let x = [0.5, -1.5, 2.0];
        let got = $m::down(&$m::motor(&axis, &angle, &tf).unwrap().apply(&$m::up(&x))).unwrap();
        let rx = mul(&m, x);
        assert!(close(got, std::array::from_fn(|k| rx[k] + tf[k]), 1e-12), "{got:?}");
        let c = [1.0, -1.0, 0.5];
        let got = $m::down(&$m::rotor_about_line(&c, &axis, &angle).unwrap().apply(&$m::up(&x))).unwrap();
        let rel = mul(&m, std::array::from_fn(|k| x[k] - c[k]));
        assert!(close(got, std::array::from_fn(|k| c[k] + rel[k]), 1e-12), "{got:?}");
        // (in cga_null the dilator is in no declared versor type: its action lands in the full
        // multivector, projected back onto the vectors)
        let moved = $m::dilator(&2.5).unwrap().apply(&$m::up(&x)).to_multivector();
        let got = $m::down(&$m::Vector::project(&moved)).unwrap();
        assert!(close(got, x.map(|v| 2.5 * v), 1e-12), "{got:?}");
        assert!($m::dilator(&0.0).is_err() && $m::dilator(&-1.0).is_err() && $m::dilator(&f64::NAN).is_err());
        assert!($m::down(&$m::plane(&[1.0, 0.0, 0.0], &1.0)).is_err(), "a plane has no finite point");
    }};
}

#[test]
fn conformal_constructors_in_both_bases() {
    conformal_checks!(cga);
    conformal_checks!(cga_null);
}
