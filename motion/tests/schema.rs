//! The JSON schema of pose objects and of the `gam interpolate` spec (`motion::schema`): every
//! pose form against an independent construction (Rodrigues' formula, the quaternion rotation
//! matrix, Hamilton products by hand, the closed-form exponential of se(3)), every refusal as
//! its typed error and message, duplicate keys, round trips.

use motion::Pose;
use motion::method::{BuildError, Method};
use motion::schema::interpolate::{ParameterRule, ParameterSpec, PerPose, VelocitySpec};
use motion::schema::{InterpolateSpec, PoseError, PoseObject, SchemaError, parse_json};
use serde_json::{Value, json};

type M3 = [[f64; 3]; 3];

/// Rodrigues: the rotation by `phi` about the unit axis `a`.
fn rodrigues(a: [f64; 3], phi: f64) -> M3 {
    let (s, c) = phi.sin_cos();
    let k = [[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]];
    let mut r = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            let kk: f64 = (0..3).map(|l| k[i][l] * k[l][j]).sum();
            r[i][j] = f64::from(u8::from(i == j)) + s * k[i][j] + (1.0 - c) * kk;
        }
    }
    r
}

/// The rotation matrix of the quaternion `[w, x, y, z]` (normalised first).
fn quaternion_matrix(q: [f64; 4]) -> M3 {
    let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
    let [w, x, y, z] = q.map(|c| c / n);
    [
        [1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)],
        [2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x)],
        [2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y)],
    ]
}

fn apply(r: &M3, t: [f64; 3], p: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| (0..3).map(|j| r[i][j] * p[j]).sum::<f64>() + t[i])
}

/// `pose` moves a set of test points as `x -> R x + t`, to `tol`.
fn assert_moves(pose: &Pose<f64>, r: &M3, t: [f64; 3], tol: f64) {
    for p in [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.3, -1.7, 2.5]] {
        let got = pose.transform_point(&p).unwrap();
        let want = apply(r, t, p);
        for k in 0..3 {
            assert!((got[k] - want[k]).abs() <= tol, "{p:?}: {got:?} vs {want:?}");
        }
    }
}

fn read(v: Value) -> Pose<f64> {
    PoseObject::from_value(&v).unwrap().to_pose().unwrap()
}

const I3: M3 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

#[test]
fn each_form_is_the_pose_of_an_independent_construction() {
    let axis = [1.0, 2.0, 2.0]; // |axis| = 3
    let unit = axis.map(|x| x / 3.0);
    let (phi, t) = (1.1_f64, [0.5, -2.0, 3.0]);
    let r = rodrigues(unit, phi);
    // position + axis + angle (the axis is normalised)
    assert_moves(&read(json!({"position": t, "axis": axis, "angle": phi})), &r, t, 1e-14);
    // position alone; nothing at all is the identity
    assert_moves(&read(json!({ "position": t })), &I3, t, 0.0);
    assert_moves(&read(json!({})), &I3, [0.0; 3], 0.0);
    // axis + angle without position: about the origin
    assert_moves(&read(json!({"axis": axis, "angle": phi})), &r, [0.0; 3], 1e-14);
    // a non-unit quaternion, against the quaternion matrix
    let q = [0.9, -0.3, 1.2, 0.4];
    assert_moves(&read(json!({"position": t, "quaternion": q})), &quaternion_matrix(q), t, 1e-14);
    // the quaternion of the axis-angle rotation is the same rotation (two formulas agree)
    let (s, c) = (phi / 2.0).sin_cos();
    let qa = [c, s * unit[0], s * unit[1], s * unit[2]];
    let qm = quaternion_matrix(qa);
    assert!(qm.iter().flatten().zip(r.iter().flatten()).all(|(a, b)| (a - b).abs() < 1e-15));
    // a rigid matrix
    let m: [[f64; 4]; 4] =
        std::array::from_fn(|i| if i < 3 { [r[i][0], r[i][1], r[i][2], t[i]] } else { [0.0, 0.0, 0.0, 1.0] });
    let pm = read(json!({ "matrix": m }));
    assert_moves(&pm, &r, t, 1e-14);
    let back = pm.unitize().unwrap().to_matrix().unwrap();
    assert!(back.iter().flatten().zip(m.iter().flatten()).all(|(a, b)| (a - b).abs() < 1e-14));
}

#[test]
fn motor_form_is_the_papers_s_equals_r_t() {
    // T = 1 + 1/2 v einf: the origin goes to v
    let v = [1.0, 2.0, 3.0];
    let tr = read(json!({"motor": {"1": 1, "e1inf": 0.5, "e2inf": 1.0, "e3inf": 1.5}}));
    assert_moves(&tr, &I3, v, 0.0);
    // R = cos(phi/2) + sin(phi/2) (a e123) with a = e3: a e123 = e12; decimal strings accepted
    let phi = std::f64::consts::FRAC_PI_3;
    let (s, c) = (phi / 2.0).sin_cos();
    let rot = read(json!({"motor": {"1": c.to_string(), "e12": format!(" {s} ")}}));
    assert_moves(&rot, &rodrigues([0.0, 0.0, 1.0], phi), [0.0; 3], 1e-15);
    // a non-unit motor is the same pose as its unit multiple
    let big = read(json!({"motor": {"1": 2.0 * c, "e12": 2.0 * s}}));
    assert!(big.is_equivalent(&rot, &1e-15).unwrap());
}

/// Hamilton product of quaternions `[w, x, y, z]`.
fn hamilton(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

#[test]
fn dual_quaternion_form_is_q_plus_eps_half_t_q() {
    let unit = [0.0, 0.6, 0.8];
    let (phi, t) = (2.0_f64, [1.0, -1.0, 0.25]);
    let (s, c) = (phi / 2.0).sin_cos();
    let q = [c, s * unit[0], s * unit[1], s * unit[2]];
    let d = hamilton([0.0, t[0], t[1], t[2]], q).map(|x| x / 2.0);
    let dq: Vec<f64> = q.iter().chain(&d).copied().collect();
    let r = rodrigues(unit, phi);
    assert_moves(&read(json!({ "dual_quaternion": dq })), &r, t, 1e-14);
    // proportional dual quaternions are the same pose
    let scaled: Vec<f64> = dq.iter().map(|x| -3.0 * x).collect();
    assert_moves(&read(json!({ "dual_quaternion": scaled })), &r, t, 1e-14);
}

/// The closed-form exponential of the twist `(omega, m)` of se(3): `R` by Rodrigues,
/// `t = V m` with `V = I + (1 - cos θ)/θ² [ω] + (θ - sin θ)/θ³ [ω]²`.
fn se3_exp(omega: [f64; 3], m: [f64; 3]) -> (M3, [f64; 3]) {
    let theta = omega.iter().map(|x| x * x).sum::<f64>().sqrt();
    let w = [[0.0, -omega[2], omega[1]], [omega[2], 0.0, -omega[0]], [-omega[1], omega[0], 0.0]];
    let (a, b) = ((1.0 - theta.cos()) / (theta * theta), (theta - theta.sin()) / theta.powi(3));
    let v: M3 = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let ww: f64 = (0..3).map(|l| w[i][l] * w[l][j]).sum();
            f64::from(u8::from(i == j)) + a * w[i][j] + b * ww
        })
    });
    (rodrigues(omega.map(|x| x / theta), theta), apply(&v, [0.0; 3], m))
}

#[test]
fn hexanion_form_is_the_exponential_of_the_twist() {
    // omega = 0: a translation by m
    assert_moves(&read(json!({"hexanion": {"omega": [0, 0, 0], "m": [1, 2, 3]}})), &I3, [1.0, 2.0, 3.0], 1e-15);
    // a general twist against the closed form
    let (omega, m) = ([0.3, -0.4, 1.2], [0.5, 1.5, -0.7]);
    let (r, t) = se3_exp(omega, m);
    assert_moves(&read(json!({"hexanion": {"omega": omega, "m": m}})), &r, t, 1e-14);
}

/// `from_value(v)` fails with `want`, whose message at `poses[4]` is `message`.
fn refused(v: Value, want: PoseError, message: &str) {
    let e = PoseObject::from_value(&v).and_then(|p| p.to_pose()).unwrap_err();
    assert_eq!(e, want, "{v}");
    assert_eq!(e.at("poses[4]").to_string(), message, "{v}");
}

#[test]
fn every_pose_refusal_is_typed_with_the_cli_message() {
    let shape = |key: &str, expected| PoseError::Shape { key: key.into(), expected };
    refused(json!([1, 2]), PoseError::NotAnObject, "`poses[4]` must be a pose object");
    refused(
        json!({"position": [0, 0, 0], "angel": 1}),
        PoseError::UnexpectedKey { key: "angel".into(), allowed: &["position", "axis", "angle"] },
        "`poses[4]`: unexpected key `angel` (this pose form has [\"position\", \"axis\", \"angle\"])",
    );
    refused(
        json!({"hexanion": {"omega": [0, 0, 1], "m": [0, 0, 0]}, "position": [1, 2, 3]}),
        PoseError::UnexpectedKey { key: "position".into(), allowed: &["hexanion"] },
        "`poses[4]`: unexpected key `position` (this pose form has [\"hexanion\"])",
    );
    refused(
        json!({"motor": {"1": 1}, "position": [0, 0, 0]}),
        PoseError::UnexpectedKey { key: "position".into(), allowed: &["motor"] },
        "`poses[4]`: unexpected key `position` (this pose form has [\"motor\"])",
    );
    refused(
        json!({"position": [0, 0]}),
        shape("position", "a list of 3 numbers"),
        "`poses[4].position` must be a list of 3 numbers",
    );
    refused(json!({"axis": [0, 0, 1], "angle": "1"}), shape("angle", "a number"), "`poses[4].angle` must be a number");
    refused(json!({"axis": [0, 0, 1]}), PoseError::AxisWithoutAngle, "`poses[4]`: `axis` and `angle` go together");
    // the identity rotation as `gam pose` prints it (axis [0, 0, 0], angle 0) reads back
    let identity = PoseObject::from_value(&json!({"position": [1, 2, 3], "axis": [0, 0, 0], "angle": 0})).unwrap();
    assert_eq!(identity.to_pose().unwrap(), Pose::translation(&[1.0, 2.0, 3.0]));
    let e = PoseObject::from_value(&json!({"axis": [0, 0, 0], "angle": 1})).unwrap().to_pose().unwrap_err();
    assert_eq!(e, PoseError::Axis(motion::MotionError::ZeroAxis));
    assert_eq!(e.at("poses[0]").to_string(), "`poses[0].axis`: the rotation axis has length zero");
    refused(
        json!({"quaternion": [1, 0, 0]}),
        shape("quaternion", "[w, x, y, z]"),
        "`poses[4].quaternion` must be [w, x, y, z]",
    );
    refused(
        json!({"quaternion": [0, 0, 0, 0]}),
        PoseError::ZeroQuaternion,
        "`poses[4].quaternion` must be non-zero and finite",
    );
    refused(
        json!({"matrix": [[1, 0, 0, 0]]}),
        shape("matrix", "4 rows of 4 numbers"),
        "`poses[4].matrix` must be 4 rows of 4 numbers",
    );
    let e = PoseObject::from_value(&json!({"matrix": [[1, 0.5, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}))
        .unwrap()
        .to_pose()
        .unwrap_err();
    assert!(matches!(e, PoseError::Matrix(motion::MotionError::NotRigid { .. })), "{e:?}");
    assert!(e.at("poses[4]").to_string().starts_with("`poses[4]`: the matrix is not a rigid-body transform"));
    refused(
        json!({"motor": [1]}),
        shape("motor", "a multivector object"),
        "`poses[4].motor` must be a multivector object",
    );
    refused(
        json!({"motor": {"e4": 1}}),
        PoseError::NotABlade { blade: "e4".into() },
        "`poses[4].motor`: `e4` is not a blade of g123inf^+",
    );
    refused(
        json!({"motor": {"e12": "x"}}),
        shape("motor.e12", "a finite number"),
        "`poses[4].motor.e12` must be a finite number",
    );
    refused(
        json!({"motor": {"1": "inf"}}),
        shape("motor.1", "a finite number"),
        "`poses[4].motor.1` must be a finite number",
    );
    refused(
        json!({"motor": {"e1inf": 1}}),
        PoseError::SingularMotor,
        "`poses[4].motor` is singular (rev(S) S has zero scalar part)",
    );
    refused(
        json!({"dual_quaternion": [1, 0, 0]}),
        shape("dual_quaternion", "[w, x, y, z, dw, dx, dy, dz]"),
        "`poses[4].dual_quaternion` must be [w, x, y, z, dw, dx, dy, dz]",
    );
    refused(
        json!({"dual_quaternion": [0, 0, 0, 0, 0, 1, 0, 0]}),
        PoseError::DualQuaternion(motion::repr::ReprError::ZeroRealPart),
        "`poses[4].dual_quaternion`: the dual quaternion has a zero real part (no rigid motion)",
    );
    let e =
        PoseObject::from_value(&json!({"dual_quaternion": [1, 0, 0, 0, 1, 0, 0, 0]})).unwrap().to_pose().unwrap_err();
    assert!(matches!(e, PoseError::DualQuaternion(motion::repr::ReprError::OffStudyQuadric { .. })));
    refused(
        json!({"hexanion": {"omega": [0, 0, 1]}}),
        shape("hexanion", "{\"omega\": [x, y, z], \"m\": [x, y, z]}"),
        "`poses[4].hexanion` must be {\"omega\": [x, y, z], \"m\": [x, y, z]}",
    );
}

#[test]
fn duplicate_keys_are_refused_naming_the_key() {
    // in a pose object given as text, at any depth
    for (text, key) in [
        (r#"{"axis": [0, 0, 1], "angle": 1, "angle": 2}"#, "angle"),
        (r#"{"hexanion": {"omega": [0, 0, 1], "m": [0, 0, 0], "m": [1, 0, 0]}}"#, "m"),
        (r#"{"motor": {"1": 1, "e12": 0, "e12": 1}}"#, "e12"),
    ] {
        let e = PoseObject::from_json(text, "pose").unwrap_err();
        assert!(
            matches!(&e, SchemaError::InvalidPose(m) if m.starts_with(&format!("duplicate key `{key}` at line 1"))),
            "{e:?}"
        );
        assert!(e.is_input());
    }
    // through serde_json's own reader of the type too
    let e = serde_json::from_str::<PoseObject>(r#"{"position": [0, 0, 0], "position": [1, 0, 0]}"#).unwrap_err();
    assert!(e.to_string().starts_with("duplicate key `position`"), "{e}");
    // in a spec: in a pose, in `parameters`/`shape`/`gamma`, in a velocity, at the top
    let two = r#"{"position": [0, 0, 0]}, {"position": [1, 0, 0]}"#;
    for (text, key) in [
        (format!(r#"{{"method": "ccm-additive", "poses": [{two}, {{"motor": {{"1": 1, "1": 2}}}}]}}"#), "key `1`"),
        (format!(r#"{{"method": "ccm-additive", "poses": [{two}], "method": "wl-linear"}}"#), "field `method`"),
        (
            format!(
                r#"{{"method": "ccm-additive", "poses": [{two}], "velocities": [{{"velocity": [0, 0, 0], "angular_velocity": [0, 0, 0], "velocity": [1, 0, 0]}}, {{"velocity": [0, 0, 0], "angular_velocity": [0, 0, 0]}}]}}"#
            ),
            "field `velocity`",
        ),
    ] {
        let e = InterpolateSpec::from_json(&text).unwrap_err();
        assert!(matches!(&e, SchemaError::Invalid(m) if m.starts_with(&format!("duplicate {key}"))), "{e:?}");
    }
    // and in any JSON read by `parse_json`
    assert!(
        matches!(parse_json(r#"{"segments": [{"t0": 0, "t0": 1}]}"#), Err(SchemaError::Invalid(m)) if m.starts_with("duplicate key `t0`"))
    );
}

fn spec(extra: &str) -> Result<InterpolateSpec, SchemaError> {
    InterpolateSpec::from_json(&format!(
        r#"{{"method": "ccm-additive", "poses": [{{"position": [0, 0, 0]}}, {{"position": [1, 0, 0]}}]{extra}}}"#
    ))
}

#[test]
fn every_spec_refusal_is_typed_with_the_cli_message() {
    let cases: Vec<(&str, SchemaError, &str)> = vec![
        (r#", "shape": 0"#, SchemaError::ShapeValue { got: 0.0 }, "`shape` must be positive (got 0)"),
        (r#", "shape": [1, 2, 3]"#, SchemaError::ShapeForm, "`shape` must be a number or one number per pose"),
        (r#", "shape": "big""#, SchemaError::ShapeForm, "`shape` must be a number or one number per pose"),
        (
            r#", "shape": [1, -1e-300]"#,
            SchemaError::ShapeValue { got: -1e-300 },
            "`shape` must be positive (got -1e-300)",
        ),
        (r#", "gamma": [1]"#, SchemaError::GammaForm, "`gamma` must be [alpha, beta] or one such pair per pose"),
        (r#", "gamma": [[1, 0]]"#, SchemaError::GammaForm, "`gamma` must be [alpha, beta] or one such pair per pose"),
        (r#", "samples": 1"#, SchemaError::Samples { got: 1 }, "`samples` must be 0 or from 2 to 1000000 (got 1)"),
        (
            r#", "samples": 1000001"#,
            SchemaError::Samples { got: 1_000_001 },
            "`samples` must be 0 or from 2 to 1000000 (got 1000001)",
        ),
        (
            r#", "parameters": "arc""#,
            SchemaError::UnknownRule { got: "arc".into() },
            "`parameters`: unknown rule `arc` (uniform, chordal, star-chordal, centripetal, angular, angular-chordal, or a list)",
        ),
        (r#", "parameters": [0, "1"]"#, SchemaError::ParameterList, "`parameters` must be a list of numbers"),
        (
            r#", "parameters": {"a": 1}"#,
            SchemaError::ParameterType { got: r#"{"a":1}"#.into() },
            r#"`parameters` must be a rule name or a list (got {"a":1})"#,
        ),
        (
            r#", "velocities": [{"velocity": [0, 0, 0], "angular_velocity": [0, 0, 0]}]"#,
            SchemaError::VelocityCount { got: 1, poses: 2 },
            "`velocities` has 1 entries for 2 poses",
        ),
        (
            r#", "l1": 1"#,
            SchemaError::Build {
                method: Method::CcmAdditive,
                source: BuildError::Unused { key: "l1", method: Method::CcmAdditive },
            },
            "`l1` is not used by `ccm-additive` (it uses velocities, shape, gamma)",
        ),
    ];
    for (extra, want, message) in cases {
        let e = spec(extra).unwrap_err();
        assert_eq!(e, want, "{extra}");
        assert_eq!(e.to_string(), message, "{extra}");
        assert!(e.is_input());
    }
    let trt = r#"{"method": "juttler-trt", "l1": -1, "poses": [{}, {"position": [1, 0, 0]}]}"#;
    assert_eq!(InterpolateSpec::from_json(trt).unwrap_err(), SchemaError::L1 { got: -1 });
    let e = InterpolateSpec::from_json(r#"{"method": "spline", "poses": []}"#).unwrap_err();
    assert!(matches!(&e, SchemaError::Method(_)) && e.to_string().starts_with("unknown method `spline`"), "{e}");
    let e = InterpolateSpec::from_json(r#"{"method": "wl-linear", "poses": [{}]}"#).unwrap_err();
    assert_eq!(e.to_string(), "at least two poses are needed (got 1)");
    let e = InterpolateSpec::from_json(r#"{"method": "wl-linear", "poses": [{}, {"axis": [0, 0, 0], "angle": 1}]}"#)
        .unwrap_err();
    assert_eq!(e.to_string(), "`poses[1].axis`: the rotation axis has length zero");
    let e = InterpolateSpec::from_json(r#"{"method": "wl-linear", "poses": [{}, 3]}"#).unwrap_err();
    assert_eq!(e.to_string(), "`poses[1]` must be a pose object");
    // serde's own refusals, with line and column from text, without from a value
    let e = spec(r#", "sample": 3"#).unwrap_err();
    assert!(
        matches!(&e, SchemaError::Invalid(m) if m.starts_with("unknown field `sample`") && m.contains("line 1")),
        "{e:?}"
    );
    let e = InterpolateSpec::from_value(&json!({"method": "wl-linear", "poses": [{}, {}], "samples": -1})).unwrap_err();
    assert!(matches!(&e, SchemaError::Invalid(m) if m.contains("-1")), "{e:?}");
    assert!(matches!(InterpolateSpec::from_json("{\"method\": "), Err(SchemaError::Json(_))));
    // a method's own numerical failure is not an input error and is named after the method
    let e = InterpolateSpec::from_json(
        r#"{"method": "juttler-trt", "poses": [{}, {"position": [1, 0, 0], "axis": [0, 0, 1], "angle": 1}]}"#,
    )
    .unwrap()
    .build()
    .unwrap_err();
    assert!(
        !e.is_input() && e.to_string().starts_with("juttler-trt: ") && e.to_string().contains("(34) is singular"),
        "{e}"
    );
}

#[test]
fn a_spec_reads_into_its_types_and_builds() {
    let spec = InterpolateSpec::from_value(&json!({
        "method": "ccm-additive",
        "poses": [{"position": [0, 0, 0]}, {"position": [1, 0, 0], "axis": [0, 0, 1], "angle": 0.5}, {"matrix": [[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}],
        "parameters": "chordal",
        "velocities": [{"velocity": [1, 0, 0], "angular_velocity": [0, 0, 0]}, {"velocity": [1, 0, 0], "angular_velocity": [0, 0, 1]}, {"velocity": [1, 0, 0], "angular_velocity": [0, 0, 0]}],
        "shape": [1, 2, 1], "gamma": [0.5, 0], "samples": 5, "body_points": [[0, 0, 1]]
    }))
    .unwrap();
    assert_eq!(spec.parameters, ParameterSpec::Rule(ParameterRule::Chordal));
    assert_eq!(spec.shape, Some(PerPose::Each(vec![1.0, 2.0, 1.0])));
    assert_eq!(spec.gamma, Some(PerPose::Common([0.5, 0.0])));
    let input = spec.method_input().unwrap();
    // the twist of the middle key: u = v - Ω × p with p = (1, 0, 0), Ω = (0, 0, 1): u = (1, -1, 0)
    let tw = &input.velocities.as_ref().unwrap()[1];
    assert_eq!((tw.angular.to_array(), tw.linear.to_array()), ([0.0, 0.0, 1.0], [1.0, -1.0, 0.0]));
    assert!(matches!(&input.shapes, Some(motion::HermiteShapes::PerPose(s)) if s.len() == 3 && s[1].lambda == 2.0));
    let built = spec.build().unwrap();
    // chordal parameters: steps |p1 - p0| = 1 and |p2 - p1| = 1
    assert_eq!(built.times(), &[0.0, 0.5, 1.0]);
    // the motion passes through the key poses
    let at = built.sample(&0.5, &[[0.0; 3]]).unwrap();
    assert!((at.points[0].position[0] - 1.0).abs() < 1e-14 && at.points[0].position[1].abs() < 1e-14);
    assert_eq!(spec.body_points(), vec![[0.0, 0.0, 1.0]]);
    // the twist of a velocity spec, by hand
    let v = VelocitySpec { velocity: [0.0, 0.0, 1.0], angular_velocity: [1.0, 0.0, 0.0] };
    let tw = v.twist(&Pose::translation(&[0.0, 2.0, 0.0])).unwrap();
    // u = (0, 0, 1) - (1, 0, 0) × (0, 2, 0) = (0, 0, 1) - (0, 0, 2)
    assert_eq!(tw.linear.to_array(), [0.0, 0.0, -1.0]);
}

#[test]
fn round_trips() {
    let objects = [
        PoseObject::Translation { position: [1.0, -2.0, 0.5] },
        PoseObject::AxisAngle { position: [0.0, 1.0, 0.0], axis: [0.0, 0.0, 2.0], angle: -0.25 },
        PoseObject::Quaternion { position: [3.0, 0.0, 0.0], quaternion: [0.5, 0.5, -0.5, 0.5] },
        PoseObject::Matrix([[0.0, -1.0, 0.0, 1.0], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]]),
        PoseObject::Motor([0.8, 0.6, 0.0, 0.0, 0.1, 0.0, -0.2, 0.0]),
        PoseObject::DualQuaternion([1.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0]),
        PoseObject::Hexanion { omega: [0.0, 0.0, 1.0], m: [1.0, 0.0, 0.0] },
    ];
    for p in &objects {
        // object -> JSON -> object, through serde and through the value functions
        let text = serde_json::to_string(p).unwrap();
        assert_eq!(&serde_json::from_str::<PoseObject>(&text).unwrap(), p, "{text}");
        assert_eq!(&PoseObject::from_json(&text, "pose").unwrap(), p);
        // object -> pose -> motor object -> the same pose
        let s = p.to_pose().unwrap();
        let again = PoseObject::from(&s).to_pose().unwrap();
        assert_eq!(again, s);
    }
    // a spec -> JSON -> spec
    let spec = spec(
        r#", "parameters": [0, 0.25], "shape": 2, "gamma": [[0, 1], [1, 0]], "velocities": [{"velocity": [1, 0, 0], "angular_velocity": [0, 0, 0]}, {"velocity": [1, 0, 0], "angular_velocity": [0, 0, 0]}], "samples": 3, "body_points": [[1, 2, 3]]"#,
    )
    .unwrap();
    let value = serde_json::to_value(&spec).unwrap();
    assert_eq!(InterpolateSpec::from_value(&value).unwrap(), spec);
    assert_eq!(serde_json::from_value::<InterpolateSpec>(value.clone()).unwrap(), spec);
    assert_eq!(value["gamma"], json!([[0.0, 1.0], [1.0, 0.0]]));
    assert_eq!(value["parameters"], json!([0.0, 0.25]));
    // the typed deserializer refuses as `from_json` does
    let e =
        serde_json::from_str::<InterpolateSpec>(r#"{"method": "wl-linear", "poses": [{}], "samples": 0}"#).unwrap_err();
    assert!(e.to_string().starts_with("at least two poses are needed (got 1)"), "{e}");
}

#[test]
fn control_data_reads_and_refuses_with_the_cli_messages() {
    use motion::schema::ControlSpec;
    let seg = |t0: f64, t1: f64, rep: &str| json!({"t0": t0, "t1": t1, "representation": rep, "degree": 1, "control_poses": [{"1": 1}, {"1": "2", "e3inf": 1}]});
    // extra keys (as `gam interpolate --json` prints them) are ignored
    let ok = ControlSpec::from_value(&json!({"method": "x", "segments": [seg(0.0, 1.0, "additive-bezier"), seg(1.0, 3.0, "additive-bezier")], "body_points": [[1, 2, 3]]})).unwrap();
    assert_eq!((ok.segments.len(), ok.segments[1].t1, ok.body_points.clone()), (2, 3.0, vec![[1.0, 2.0, 3.0]]));
    // 2 + e3inf = 2 (1 + 1/2 (0, 0, 1) einf): the translation by (0, 0, 1)
    assert_eq!(ok.segments[0].control_poses[1].transform_point(&[0.0; 3]).unwrap(), [0.0, 0.0, 1.0]);
    let cases: Vec<(Value, &str)> = vec![
        (json!({"segments": []}), "`segments` must be a non-empty list"),
        (
            json!({"segments": [{"t0": 0, "t1": 1, "control_poses": [{"1": 1}]}]}),
            "`segments[0].representation` must be a string",
        ),
        (
            json!({"segments": [{"t0": 0, "t1": 1, "representation": "additive-bezier", "control_poses": []}]}),
            "`segments[0].control_poses` must be a non-empty list of motors",
        ),
        (
            json!({"segments": [{"t0": "0", "t1": 1, "representation": "additive-bezier", "control_poses": [{"1": 1}]}]}),
            "`segments[0].t0` must be a finite number",
        ),
        (
            json!({"segments": [{"t0": 0, "t1": 1, "representation": "additive-bezier", "control_poses": [{"e1inf": 1}]}]}),
            "`segments[0].control_poses[0].motor` is singular (rev(S) S has zero scalar part)",
        ),
        (
            json!({"segments": [seg(0.0, 1.0, "additive-bezier"), seg(1.0, 2.0, "multiplicative-bezier")]}),
            "`segments[1].representation` is `multiplicative-bezier`, but segment 0's is `additive-bezier`: one kind per plot",
        ),
        (
            json!({"segments": [seg(0.0, 1.0, "additive-bezier"), seg(1.5, 2.0, "additive-bezier")]}),
            "`segments[1].t0` must equal `segments[0].t1` (no gaps)",
        ),
        (
            json!({"segments": [seg(0.0, 1.0, "additive-bezier")], "body_points": [[1, 2]]}),
            "`body_points` must be a list of [x, y, z]",
        ),
    ];
    for (v, message) in cases {
        let e = ControlSpec::from_value(&v).unwrap_err();
        assert_eq!(e.to_string(), message, "{v}");
        assert!(e.is_input());
    }
}
