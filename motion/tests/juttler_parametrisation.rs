//! Jüttler's parametrisations (15) on hand-computed examples.

use algebra_core::rational::{Q, q, ratio};
use motion::Pose;
use motion::juttler::parametrisation::{from_steps, normalise};
use motion::juttler::{JuttlerError, Parametrisation, parameters};

fn close(a: &[f64], b: &[f64]) {
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() < 1e-15, "{a:?} vs {b:?}");
    }
}

fn screw_z(angle: f64, t: [f64; 3]) -> Pose<f64> {
    Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &angle, &t).unwrap()
}

#[test]
fn chordal_and_centripetal_on_translations() {
    let p = [[0.0, 0.0, 0.0], [3.0, 0.0, 0.0], [3.0, 4.0, 0.0]].map(|t| Pose::translation(&t));
    // dist 3 and 4
    close(&parameters(&p, &Parametrisation::Chordal).unwrap(), &[0.0, 3.0 / 7.0, 1.0]);
    let p = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 4.0, 0.0]].map(|t| Pose::translation(&t));
    // √1 and √4
    close(&parameters(&p, &Parametrisation::Centripetal).unwrap(), &[0.0, 1.0 / 3.0, 1.0]);
    close(&parameters(&p, &Parametrisation::Equidistant).unwrap(), &[0.0, 0.5, 1.0]);
}

#[test]
fn angular_star_chordal_and_angle_plus_distance() {
    // rotations about z by 0, 0.5, 2: steps 0.5 and 1.5
    let p = [0.0, 0.5, 2.0].map(|a| screw_z(a, [0.0; 3]));
    close(&parameters(&p, &Parametrisation::Angular).unwrap(), &[0.0, 0.25, 1.0]);
    // screws about the z axis: the origins move by (3,0,2) and (-3,0,6); along the axis 2 and 6
    let p = [screw_z(0.0, [0.0; 3]), screw_z(1.0, [3.0, 0.0, 2.0]), screw_z(2.0, [0.0, 0.0, 8.0])];
    close(&parameters(&p, &Parametrisation::StarChordal).unwrap(), &[0.0, 0.25, 1.0]);
    let c = 13f64.sqrt() / (13f64.sqrt() + 45f64.sqrt());
    close(&parameters(&p, &Parametrisation::Chordal).unwrap(), &[0.0, c, 1.0]);
    // angle 1 + dist 1, then angle 0 + dist 2
    let p = [screw_z(0.0, [0.0; 3]), screw_z(1.0, [1.0, 0.0, 0.0]), screw_z(1.0, [1.0, 2.0, 0.0])];
    close(&parameters(&p, &Parametrisation::AngleDistance).unwrap(), &[0.0, 0.5, 1.0]);
}

#[test]
fn star_chordal_does_not_depend_on_the_moving_origin_but_chordal_does() {
    let p = [screw_z(0.0, [0.0; 3]), screw_z(1.0, [3.0, 0.0, 2.0]), screw_z(2.5, [0.0, 1.0, 8.0])];
    // the same motion with the moving frame's origin moved to (1, 2, 0): T_c first
    let c = Pose::translation(&[1.0, 2.0, 0.0]);
    let moved = p.map(|s| c * s);
    let a = parameters(&p, &Parametrisation::StarChordal).unwrap();
    close(&parameters(&moved, &Parametrisation::StarChordal).unwrap(), &a);
    let a = parameters(&p, &Parametrisation::Chordal).unwrap();
    let b = parameters(&moved, &Parametrisation::Chordal).unwrap();
    assert!((a[1] - b[1]).abs() > 1e-3, "{a:?} {b:?}");
}

#[test]
fn explicit_parameters_are_normalised_exactly() {
    assert_eq!(normalise(&[q(2), q(3), q(6)], 3).unwrap(), [q(0), ratio(1, 4), q(1)]);
    assert_eq!(from_steps(&[ratio(1, 3), ratio(1, 6), q(1)]).unwrap(), [q(0), ratio(2, 9), ratio(1, 3), q(1)]);
    let p = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]].map(|t| Pose::translation(&t));
    close(&parameters(&p, &Parametrisation::Explicit(vec![-1.0, 3.0])).unwrap(), &[0.0, 1.0]);
}

#[test]
fn bad_input_is_a_typed_error() {
    let p = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]].map(|t| Pose::translation(&t));
    let e = parameters(&p, &Parametrisation::Explicit(vec![0.0, 1.0, 2.0])).unwrap_err();
    assert!(matches!(e, JuttlerError::Parameters { .. }), "{e}");
    let e = parameters(&p, &Parametrisation::Explicit(vec![1.0, 1.0])).unwrap_err();
    assert!(matches!(e, JuttlerError::Parameters { .. }), "{e}");
    let e = parameters(&p, &Parametrisation::Explicit(vec![0.0, f64::NAN])).unwrap_err();
    assert!(matches!(e, JuttlerError::Parameters { .. }), "{e}");
    let e = parameters(&p[..1], &Parametrisation::Chordal).unwrap_err();
    assert_eq!(e, JuttlerError::TooFewPositions { need: 2, got: 1 });
    let same = [Pose::<f64>::identity(), Pose::identity()];
    assert!(matches!(parameters(&same, &Parametrisation::Angular), Err(JuttlerError::ZeroStep { index: 0, .. })));
    assert!(matches!(from_steps::<Q>(&[q(1), q(-1)]), Err(JuttlerError::ZeroStep { index: 1, .. })));
    assert!(matches!(from_steps::<Q>(&[]), Err(JuttlerError::TooFewPositions { .. })));
}
