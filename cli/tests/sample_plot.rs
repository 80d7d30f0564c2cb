//! `gam sample` and `gam plot`: the contract's example spec sampled (end positions, end
//! speeds against the end conditions: the body-origin velocity at t = 0 is `shape` times the
//! spec's start velocity), agreement with the `motion` library computed independently, a
//! `body_point`, the sample-count rules, the SVG, and the error rules (one `error:` line,
//! exit 2).

use crate::common;

use common::{CONTRACT_EXAMPLE, TempFile, fails, ok};
use motion::hermite::hermite_segment;
use motion::paper;
use motion::spec::SpecKind;
use motion::velocity::velocity;
use motion::{AdditiveBezier, Motion, MultiplicativeBezier, SegmentKind, Shape};
use serde_json::Value;

/// Sec. 5.2 of the paper (`motion::paper`) with λ0 = 4, λ3 = 1 and pseudoscalars, as `kind`,
/// with `extra` (`"key": value,`) put first.
fn sec52(kind: &str, extra: &str) -> String {
    let kind = if kind == "additive" { SpecKind::Additive } else { SpecKind::Multiplicative };
    let json = serde_json::to_string(&paper::sec_5_2::spec(kind, 4.0, 1.0)).unwrap();
    format!("{{{extra}{}", &json[1..])
}

/// One parsed sample.
#[derive(Debug)]
struct Sample {
    t: f64,
    pose: Value,
    position: [f64; 3],
    linear_speed: f64,
    angular_speed: f64,
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// `gam sample --json` on a spec text, parsed (and its shape checked).
fn sample_json(name: &str, text: &str, n: usize) -> Vec<Sample> {
    let spec = TempFile::new(name, text);
    let out = ok(&["sample", spec.path(), "--samples", &n.to_string(), "--json"]);
    let value: Value = serde_json::from_str(&out).expect("valid JSON");
    let obj = value.as_object().expect("an object");
    assert_eq!(obj.keys().collect::<Vec<_>>(), ["samples"]);
    let list = value["samples"].as_array().expect("a list");
    assert_eq!(list.len(), n);
    list.iter()
        .map(|s| {
            let keys: Vec<&String> = s.as_object().expect("object").keys().collect();
            assert_eq!(keys, ["t", "pose", "position", "linear_speed", "angular_speed"]);
            let p = s["position"].as_array().expect("position list");
            assert_eq!(p.len(), 3);
            Sample {
                t: num(&s["t"]),
                pose: s["pose"].clone(),
                position: [num(&p[0]), num(&p[1]), num(&p[2])],
                linear_speed: num(&s["linear_speed"]),
                angular_speed: num(&s["angular_speed"]),
            }
        })
        .collect()
}

fn norm(v: &[f64; 3]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * (1.0 + b.abs())
}

fn assert_close3(a: &[f64; 3], b: &[f64; 3], tol: f64) {
    assert!(a.iter().zip(b).all(|(x, y)| close(*x, *y, tol)), "{a:?} != {b:?}");
}

#[test]
fn contract_example_ends_match_the_spec() {
    let s = sample_json("contract.json", CONTRACT_EXAMPLE, 11);
    assert_eq!(s.first().unwrap().t, 0.0);
    assert_eq!(s.last().unwrap().t, 1.0);
    for (i, x) in s.iter().enumerate() {
        assert!(close(x.t, i as f64 / 10.0, 1e-15));
    }
    assert_close3(&s[0].position, &[0.0, 0.0, 0.0], 1e-9);
    assert_close3(&s[10].position, &[8.0, 10.0, 12.0], 1e-9);
    // shape 1 at both ends: the body-origin speed and |Ω| are those of the end conditions.
    assert!(close(s[0].linear_speed, norm(&[1.0, 1.0, 1.0]), 1e-12), "{}", s[0].linear_speed);
    assert!(close(s[0].angular_speed, norm(&[1.0, 2.0, 3.0]), 1e-12));
    assert!(close(s[10].linear_speed, norm(&[1.0, 5.0, 3.0]), 1e-12));
    assert!(close(s[10].angular_speed, norm(&[2.0, 1.0, 1.0]), 1e-12));
    assert_eq!(s[0].pose, serde_json::json!({"1": "1"}));
}

#[test]
fn start_speed_is_shape_times_start_velocity() {
    // Sec. 5.2 with λ0 = 4 (and γ0 ≠ 0): Ψ(0) = λ0 (ν0 + γ0), so the velocity of the body origin
    // at t = 0 is λ0 v0 = 4 · [0, 0, 8] and |Ω(0)| = 4 · π/4; at t = 1, λ3 = 1.
    for kind in ["additive", "multiplicative"] {
        let s = sample_json(&format!("sec52-{kind}.json"), &sec52(kind, ""), 5);
        assert!(close(s[0].linear_speed, 32.0, 1e-12), "{kind}: {}", s[0].linear_speed);
        assert!(close(s[0].angular_speed, std::f64::consts::PI, 1e-12), "{kind}: {}", s[0].angular_speed);
        assert!(close(s[4].linear_speed, 4.0, 1e-9), "{kind}: {}", s[4].linear_speed);
        assert!(close(s[4].angular_speed, std::f64::consts::FRAC_PI_8, 1e-9), "{kind}: {}", s[4].angular_speed);
        assert_close3(&s[0].position, &[0.0, 0.0, 0.0], 1e-9);
        assert_close3(&s[4].position, &[0.0, 10.0, 0.0], 1e-9);
    }
}

/// Every sample against the motion library, computed independently of the binary.
#[test]
fn body_point_samples_agree_with_the_library() {
    let body = [1.0, -2.0, 0.5];
    let text = sec52("multiplicative", r#" "body_point": [1, -2, 0.5],"#);
    let s = sample_json("sec52-body.json", &text, 9);
    let (a, b) = paper::sec_5_2::end_conditions();
    let [g0, g3] = paper::sec_5_2::gammas();
    let seg =
        hermite_segment(SegmentKind::Multiplicative, 3, &a, &b, &Shape::new(4.0, g0), &Shape::new(1.0, g3)).unwrap();
    let m = MultiplicativeBezier::new(seg.control_poses().to_vec()).unwrap();
    for x in &s {
        let v = velocity(&m, &x.t).unwrap();
        let (q, qv) = v.body_point_velocity(&body).unwrap();
        assert_close3(&x.position, &q, 1e-12);
        assert!(close(x.linear_speed, norm(&qv), 1e-12));
        assert!(close(x.angular_speed, norm(&v.twist().angular.to_array()), 1e-12));
        assert_close3(&x.position, &m.pose(&x.t).unwrap().transform_point(&body).unwrap(), 1e-12);
    }
    // The ends: the body point carried by the end poses.
    assert_close3(&s[0].position, &a.pose.transform_point(&body).unwrap(), 1e-9);
    assert_close3(&s[8].position, &b.pose.transform_point(&body).unwrap(), 1e-9);
    // The additive kind too: the contract example with the same body point, 5 samples.
    let (a, b) = paper::sec_5_1::end_conditions(paper::sec_5_1::PRINTED_ANGLE, paper::sec_5_1::AXIS);
    let seg = hermite_segment(SegmentKind::Additive, 3, &a, &b, &Shape::unit(), &Shape::unit()).unwrap();
    let m = AdditiveBezier::new(seg.control_poses().to_vec()).unwrap();
    let text = CONTRACT_EXAMPLE.replace("\"degree\": 3,", "\"degree\": 3, \"body_point\": [1, -2, 0.5],");
    let s = sample_json("contract-body.json", &text, 5);
    for x in &s {
        let v = velocity(&m, &x.t).unwrap();
        let (q, qv) = v.body_point_velocity(&body).unwrap();
        assert_close3(&x.position, &q, 1e-12);
        assert!(close(x.linear_speed, norm(&qv), 1e-12));
        assert!(close(x.angular_speed, norm(&v.twist().angular.to_array()), 1e-12));
    }
    assert_close3(&s[4].position, &b.pose.transform_point(&body).unwrap(), 1e-9);
    assert_close3(&s[0].position, &body, 1e-12);
    // ν0 = Ω e123 + u einf with the origin at 0: v(q) = v0 + Ω × q.
    let (w, v0) = ([1.0, 2.0, 3.0], [1.0, 1.0, 1.0]);
    let cross = [w[1] * body[2] - w[2] * body[1], w[2] * body[0] - w[0] * body[2], w[0] * body[1] - w[1] * body[0]];
    let expected = [v0[0] + cross[0], v0[1] + cross[1], v0[2] + cross[2]];
    assert!(close(s[0].linear_speed, norm(&expected), 1e-12), "{} vs {}", s[0].linear_speed, norm(&expected));
}

#[test]
fn sample_counts() {
    let spec = TempFile::new("counts.json", CONTRACT_EXAMPLE);
    let s = sample_json("counts2.json", CONTRACT_EXAMPLE, 2);
    assert_eq!((s[0].t, s[1].t), (0.0, 1.0));
    for n in ["1", "0"] {
        let line = fails(&["sample", spec.path(), "--samples", n], 2);
        assert!(line.contains("--samples"), "{line}");
    }
    fails(&["sample", spec.path(), "--samples", "-3"], 2);
    fails(&["sample", spec.path(), "--samples", "x"], 2);
    fails(&["sample", spec.path()], 2);
    fails(&["plot", spec.path(), "--out", "x.svg", "--samples", "1"], 2);
}

#[test]
fn human_form_is_a_table() {
    let spec = TempFile::new("human.json", CONTRACT_EXAMPLE);
    let out = ok(&["sample", spec.path(), "--samples", "3"]);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 1 + 2 + 3, "{out}");
    assert_eq!(lines[0], "additive segment of degree 3, body point [0, 0, 0], 3 samples");
    assert!(lines[1].starts_with("t   | x") && lines[1].contains("linear speed") && lines[1].contains("angular speed"));
    assert!(lines[3].starts_with("0   | 0"), "{out}");
    assert!(lines[5].starts_with("1   | 8"), "{out}");
    // Aligned: the `|` in the same column everywhere but the rule.
    let bar = lines[1].find('|').unwrap();
    assert!(lines.iter().skip(3).all(|l| l.find('|') == Some(bar)), "{out}");
}

#[test]
fn spec_errors() {
    let bad = TempFile::new("bad-body.json", &sec52("additive", r#" "body_point": [1, 2],"#));
    let line = fails(&["sample", bad.path(), "--samples", "3"], 2);
    assert!(line.contains("invalid spec"), "{line}");
    fails(&["sample", "/nonexistent/gam-spec.json", "--samples", "3"], 2);
    // `gam hermite` keeps its contract: `body_point` is not one of its fields.
    let body = TempFile::new("hermite-body.json", &sec52("additive", r#" "body_point": [1, 2, 3],"#));
    let line = fails(&["hermite", body.path()], 2);
    assert!(line.contains("body_point"), "{line}");
}

#[test]
fn plot_writes_an_svg() {
    let spec = TempFile::new("plot.json", &sec52("multiplicative", r#" "body_point": [0, 1, 0],"#));
    let out = TempFile::empty("plot.svg");
    let msg = ok(&["plot", spec.path(), "--out", out.path(), "--samples", "50"]);
    assert!(msg.starts_with("wrote "), "{msg}");
    let svg = std::fs::read_to_string(out.path()).expect("the SVG was written");
    assert!(svg.starts_with("<svg"), "{}", &svg[..svg.len().min(100)]);
    assert!(svg.trim_end().ends_with("</svg>"));
    for text in [
        "multiplicative segment of degree 3, body point [0, 1, 0]",
        "linear speed (solid) and angular speed (dashed)",
        "path of the body point",
        "linear speed |v|",
        "angular speed |Ω|",
        ">t</text>",
        ">x</text>",
        ">y</text>",
    ] {
        assert!(svg.contains(text), "the SVG lacks {text:?}");
    }
    assert!(svg.contains("<polyline"), "no line series");
    // The default sample count.
    ok(&["plot", spec.path(), "--out", out.path()]);
    assert!(std::fs::read_to_string(out.path()).unwrap().starts_with("<svg"));
}

#[test]
fn plot_to_a_bad_path_is_exit_2() {
    let spec = TempFile::new("plot-bad.json", CONTRACT_EXAMPLE);
    let line = fails(&["plot", spec.path(), "--out", "/nonexistent-dir/gam/out.svg"], 2);
    assert!(line.contains("cannot write `/nonexistent-dir/gam/out.svg`"), "{line}");
    let dir = std::env::temp_dir();
    fails(&["plot", spec.path(), "--out", dir.to_str().unwrap()], 2);
    fails(&["plot", spec.path()], 2);
}

#[test]
fn streamed_json_writes_nothing_when_a_later_sample_fails() {
    // t = 0 is finite, t = 0.01 overflows: the streamed output must not have started
    let text = CONTRACT_EXAMPLE.replace("[8,10,12]", "[1e306,10,12]").replace("[0,0,0]", "[-1e306,0,0]");
    let spec = TempFile::new("stream-overflow.json", &text);
    let line = fails(&["sample", spec.path(), "--samples", "101", "--json"], 1);
    assert!(line.contains("at t = 0.01 is not finite"), "{line}");
    // the text table is streamed too (issue 30): nothing printed either (`fails` checks stdout)
    let line = fails(&["sample", spec.path(), "--samples", "101"], 1);
    assert!(line.contains("at t = 0.01 is not finite"), "{line}");
    // and the streamed JSON of a good spec is the same as the text table's values
    let good = TempFile::new("stream-good.json", CONTRACT_EXAMPLE);
    let json: Value = serde_json::from_str(&ok(&["sample", good.path(), "--samples", "3", "--json"])).unwrap();
    let table = ok(&["sample", good.path(), "--samples", "3"]);
    let last_row: Vec<&str> = table.lines().last().unwrap().split_whitespace().collect();
    let x = json["samples"][2]["position"][0].as_f64().unwrap();
    assert_eq!((last_row[2].parse::<f64>().unwrap(), x), (8.0, 8.0)); // the spec's end position
}
