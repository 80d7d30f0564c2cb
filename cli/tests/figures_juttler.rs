//! Jüttler's Figs. 1-6 in `gam figures` (cli/src/figures/juttler.rs): the committed SVGs are
//! what `gam figures` writes and have the expected number of lines; the unit cubes sit at the
//! key poses (Rodrigues matrices of the axes, angles and translations each figure reports as `keys`); the
//! trajectories equal `gam trajectory`'s rational Bézier curves of the same spec; the
//! projective method (Fig. 2) makes one extra turn that the elliptic one (Fig. 1) does not;
//! the kinematic surface's iso-curves at `v` fixed are the trajectories of `x(v)`.

use crate::common;

use common::{TempFile, ok, rodrigues};
use serde_json::Value;

type Key = ([f64; 3], f64, [f64; 3]);

/// (file, `gam interpolate` spec keys of the same motion; None for Fig. 2).
const FIGURES: [(&str, Option<&str>); 6] = [
    ("juttler_fig1.svg", Some(r#""method": "juttler-q-motion""#)),
    ("juttler_fig2.svg", None),
    ("juttler_fig3.svg", Some(r#""method": "juttler-q-motion", "parameters": "centripetal""#)),
    ("juttler_fig4.svg", Some(r#""method": "juttler-trt", "parameters": "angular-chordal", "l1": 3"#)),
    ("juttler_fig5a.svg", Some(r#""method": "juttler-minimal""#)),
    ("juttler_fig6.svg", Some(r#""method": "juttler-spline""#)),
];

/// The key poses `[axis, angle, translation]` a figure reports (`keys`).
fn keys(fig: &Value) -> Vec<Key> {
    serde_json::from_value(fig["keys"].clone()).expect("the key poses")
}

fn nums(v: &Value) -> Vec<f64> {
    v.as_array().expect("an array").iter().map(|x| x.as_f64().expect("a number")).collect()
}

fn point(v: &Value) -> [f64; 3] {
    serde_json::from_value(v.clone()).expect("[x, y, z]")
}

fn points(v: &Value) -> Vec<[f64; 3]> {
    v.as_array().expect("an array").iter().map(point).collect()
}

fn dist(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>().sqrt()
}

/// Runs `gam figures --json` once, checks every Jüttler SVG against the gallery and counts
/// its lines, and returns the data by file name (`test` names the output directory).
fn figures(test: &str) -> serde_json::Map<String, Value> {
    let dir = std::env::temp_dir().join(format!("gam-cli-test-{}-juttler-{test}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temp directory");
    let data: Value = serde_json::from_str(&ok(&["figures", "--json", "--out", dir.to_str().unwrap()])).unwrap();
    let mut out = serde_json::Map::new();
    for (file, fig) in data.as_object().expect("an object").iter().filter(|(f, _)| f.starts_with("juttler_")) {
        let svg = std::fs::read_to_string(dir.join(file)).expect("the figure was written");
        let committed = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/figures").join(file);
        let committed = std::fs::read_to_string(&committed).expect("the gallery has the figure");
        assert!(committed == svg, "docs/figures/{file} is stale: run `gam figures --out docs/figures`");
        assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"), "{file}");
        let lines = svg.matches("<polyline").count();
        let black = svg
            .match_indices("<polyline")
            .filter(|(i, _)| svg[*i..].split('>').next().unwrap().contains(r##"stroke="#000000""##))
            .count();
        let expected = match fig.get("series") {
            // per body point a speed line and a path, the angular speed, the joins, 12 edges per
            // cube, one line per mark (face markings, Fig. 5a's parabolas)
            Some(s) => {
                let s = &s[0];
                let len = |k: &str| s[k].as_array().map_or(0, Vec::len);
                2 * len("body_points") + 1 + len("joins") + 12 * len("frames") + len("marks")
            }
            // Fig. 5b, shaded: quads between neighbouring v curves, 5 samples of t long, each
            // with its two v curve pieces and the t curve pieces on its edges at the t curves'
            // parameters (every 25th sample: an inner one belongs to two quads)
            None => {
                let (nv, nk) = (fig["iso_v"].as_array().unwrap().len(), fig["iso_t"].as_array().unwrap().len());
                let nt = fig["iso_v"][0].as_array().unwrap().len();
                let quads = (nt - 1).div_ceil(5);
                let polygons = svg.matches("<polygon").count();
                assert_eq!(polygons, (nv - 1) * quads, "{file}: one shaded polygon per quad");
                let mut shades: Vec<&str> = svg
                    .lines()
                    .filter(|l| l.starts_with("<polygon"))
                    .map(|l| l.split("fill=").nth(1).unwrap())
                    .collect();
                shades.sort();
                shades.dedup();
                assert!(shades.len() > 20, "{file}: {} shades", shades.len());
                (nv - 1) * (2 * quads + 2 * nk - 2)
            }
        };
        assert_eq!(lines - black, expected, "{file}");
        out.insert(file.clone(), fig.clone());
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(out.len(), 7, "Figs. 1, 2, 3, 4, 5a, 5b, 6");
    out
}

/// One segment's rational Bézier curve: `t0`, `t1`, weights, affine control points.
type Curve = (f64, f64, Vec<f64>, Vec<[f64; 3]>);

/// `gam trajectory --json` of `spec` for the body point `x`: (t0, t1, degree, weights, points) per segment.
fn trajectory(spec: &str, x: &[f64; 3]) -> Vec<Curve> {
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let file = TempFile::new(&format!("juttler-figure-{n}.json"), spec);
    let p = format!("{},{},{}", x[0], x[1], x[2]);
    let out: Value = serde_json::from_str(&ok(&["trajectory", "--json", file.path(), "--point", &p])).unwrap();
    let segs = out["segments"].as_array().unwrap();
    segs.iter()
        .map(|s| (s["t0"].as_f64().unwrap(), s["t1"].as_f64().unwrap(), nums(&s["weights"]), points(&s["points"])))
        .collect()
}

/// The rational Bézier curves at `t` (Bernstein sum in the segment's local parameter).
fn evaluate(curves: &[Curve], t: f64) -> [f64; 3] {
    let (t0, t1, w, p) = curves.iter().find(|c| t <= c.1).unwrap_or(curves.last().unwrap());
    let u = (t - t0) / (t1 - t0);
    let d = w.len() - 1;
    let binom = |j: usize| (0..j).fold(1.0, |acc, i| acc * (d - i) as f64 / (i + 1) as f64);
    let b = |j: usize| binom(j) * u.powi(j as i32) * (1.0 - u).powi((d - j) as i32);
    let den: f64 = (0..=d).map(|j| b(j) * w[j]).sum();
    std::array::from_fn(|k| (0..=d).map(|j| b(j) * w[j] * p[j][k]).sum::<f64>() / den)
}

/// Asserts that `path[i]` is `curve(t[i])`, to `1e-12` relative to the largest
/// coordinate (the figures reach 12.5).
fn on_curves(what: &str, path: &[[f64; 3]], t: &[f64], curve: impl Fn(f64) -> [f64; 3]) {
    for (p, ti) in path.iter().zip(t) {
        let want = curve(*ti);
        let scale = 1.0 + want.iter().map(|v| v.abs()).fold(0.0, f64::max);
        assert!(dist(p, &want) < 1e-12 * scale, "{what} at t = {ti}: {p:?} vs {want:?}");
    }
}

fn spec(keys: &[Key], extra: &str) -> String {
    let poses: Vec<String> =
        keys.iter().map(|(a, phi, t)| format!(r#"{{"position": {t:?}, "axis": {a:?}, "angle": {phi}}}"#)).collect();
    format!(r#"{{{extra}, "poses": [{}]}}"#, poses.join(", "))
}

#[test]
fn cubes_at_key_poses_and_trajectories_equal_gam_trajectory() {
    let all = figures("cubes");
    for (file, extra) in FIGURES {
        let keys = &keys(&all[file]);
        let s = &all[file]["series"][0];
        let times = nums(&s["key_times"]);
        assert_eq!(times.len(), keys.len(), "{file}");
        // the cubes: at the key parameters (every other frame) and midway between them
        let frames = s["frames"].as_array().unwrap();
        assert_eq!(frames.len(), 2 * keys.len() - 1, "{file}");
        for (k, (axis, angle, t)) in keys.iter().enumerate() {
            let f = &frames[2 * k];
            assert_eq!(f["t"].as_f64(), Some(times[k]));
            let m = rodrigues(*axis, *angle, *t);
            for (c, corner) in points(&f["cube"]).iter().enumerate() {
                let x = [(c & 1) as f64, ((c >> 1) & 1) as f64, ((c >> 2) & 1) as f64];
                let want: [f64; 3] = std::array::from_fn(|i| (0..3).map(|j| m[i][j] * x[j]).sum::<f64>() + m[i][3]);
                assert!(dist(corner, &want) < 1e-9, "{file}: key pose {k}, corner {c}: {corner:?} vs {want:?}");
            }
        }
        // the trajectories: gam trajectory's curves at every sample parameter
        let t = nums(&s["t"]);
        let Some(extra) = extra else {
            // Fig. 2 (no `gam interpolate` method): the library's rational Bézier trajectories
            // (Jüttler's (12) on the control points) of projective + TR, by de Casteljau
            let m = motion::juttler::tr::tr_method(&rotational(keys, true).0, &aligned(keys), &EQUIDISTANT).unwrap();
            for (j, x) in points(&s["body_points"]).iter().enumerate() {
                let curve = m.trajectory(x);
                on_curves(&format!("{file}: point {x:?}"), &points(&s["paths"][j]), &t, |ti| curve.point(&ti).unwrap());
            }
            continue;
        };
        for (j, x) in points(&s["body_points"]).iter().enumerate() {
            let curves = trajectory(&spec(keys, extra), x);
            on_curves(&format!("{file}: point {x:?}"), &points(&s["paths"][j]), &t, |ti| evaluate(&curves, ti));
        }
    }
}

/// `∫|Ω| dt` of a figure's series over `[a, b]` by the trapezoidal rule over its samples.
fn turned(s: &Value, a: f64, b: f64) -> f64 {
    let (t, w) = (nums(&s["t"]), nums(&s["angular_speed"]));
    let inside = |i: usize| t[i - 1] >= a - 1e-12 && t[i] <= b + 1e-12;
    (1..t.len()).filter(|i| inside(*i)).map(|i| 0.5 * (w[i] + w[i - 1]) * (t[i] - t[i - 1])).sum()
}

/// The angle of the relative rotation between two key poses.
fn key_angle(p: &Key, q: &Key) -> f64 {
    let (a, b) = (rodrigues(p.0, p.1, p.2), rodrigues(q.0, q.1, q.2));
    let trace: f64 = (0..3).map(|i| (0..3).map(|j| a[j][i] * b[j][i]).sum::<f64>()).sum();
    ((trace - 1.0) / 2.0).clamp(-1.0, 1.0).acos()
}

/// The equidistant parameters of five positions.
const EQUIDISTANT: [f64; 5] = [0.0, 0.25, 0.5, 0.75, 1.0];

/// The key poses, sign-aligned (rule (24), as the figures do).
fn aligned(keys: &[Key]) -> Vec<motion::Pose<f64>> {
    let mut poses: Vec<_> =
        keys.iter().map(|(a, phi, t)| motion::Pose::from_axis_angle_translation(a, phi, t).unwrap()).collect();
    motion::trajectory::align_signs(&mut poses);
    poses
}

/// The projective (or elliptic) rotational interpolant through five key poses at
/// [`EQUIDISTANT`], and the signs of `λ_i` in `Q_rot(t_i) = λ_i R_i`: a sign change between
/// `t_i` and `t_(i+1)` means the rotation goes the long way round there (a somersault).
fn rotational(five: &[Key], proj: bool) -> (motion::juttler::QMotion<f64>, Vec<bool>) {
    use motion::juttler::{projective::projective, rotational::elliptic, tr::rotation_translation};
    let rots: Vec<_> = aligned(five).iter().map(|p| rotation_translation(p).unwrap().0).collect();
    let q = if proj { projective(&rots, &EQUIDISTANT).unwrap() } else { elliptic(&rots, &EQUIDISTANT).unwrap() };
    let signs = rots
        .iter()
        .zip(EQUIDISTANT)
        .map(|(r, ti)| {
            let e = q.eval(&ti).real;
            e.w * r.w + e.x * r.x + e.y * r.y + e.z * r.z > 0.0
        })
        .collect();
    (q, signs)
}

#[test]
fn the_projective_method_somersaults_and_the_surface_is_swept_by_x_of_v() {
    let all = figures("turns");
    let five = keys(&all["juttler_fig2.svg"]);
    assert_eq!(five, keys(&all["juttler_fig1.svg"]), "Figs. 1 and 2 share their key poses");
    // Fig. 1 (elliptic): no sign change; Fig. 2 (projective): exactly one, and on that span
    // the figure's cube turns at least 2π - θ (the long way), elsewhere less than 2π - θ.
    let flips = |s: &[bool]| s.windows(2).filter(|w| w[0] != w[1]).count();
    assert_eq!(flips(&rotational(&five, false).1), 0);
    let signs = rotational(&five, true).1;
    assert_eq!(flips(&signs), 1, "one somersault: {signs:?}");
    for (name, long) in
        [("juttler_fig1.svg", vec![false; 4]), ("juttler_fig2.svg", signs.windows(2).map(|w| w[0] != w[1]).collect())]
    {
        let s = &all[name]["series"][0];
        for i in 0..4 {
            let (a, b) = (0.25 * i as f64, 0.25 * (i + 1) as f64);
            let (turn, theta) = (turned(s, a, b), key_angle(&five[i], &five[i + 1]));
            let limit = std::f64::consts::TAU - theta;
            assert_eq!(turn >= 0.99 * limit, long[i], "{name}, [{a}, {b}]: turned {turn}, θ = {theta}");
        }
    }
    // Fig. 5b: the iso-curve at v fixed is the trajectory of x(v) = ((1 - v)² 0 + 2v(1 - v) (1/2, 0, 1) + v² (1, 0, 0))
    let surface = &all["juttler_fig5b.svg"];
    let (grid, t) = (nums(&surface["grid"]), nums(&surface["t"]));
    let spec = spec(&keys(&all["juttler_fig5a.svg"]), r#""method": "juttler-minimal""#);
    for (j, v) in grid.iter().enumerate() {
        let x = [2.0 * v * (1.0 - v) * 0.5 + v * v, 0.0, 2.0 * v * (1.0 - v)];
        let curves = trajectory(&spec, &x);
        on_curves(&format!("Fig. 5b, v = {v}"), &points(&surface["iso_v"][j]), &t, |ti| evaluate(&curves, ti));
    }
    // the iso-curves at t fixed pass through the ends of those at v fixed (one net)
    let iso_t = surface["iso_t"].as_array().unwrap();
    for (k, tk) in grid.iter().enumerate() {
        let i = t.iter().position(|x| x == tk).expect("grid values are sample values");
        for (j, v) in grid.iter().enumerate() {
            let a = point(&surface["iso_v"][j][i]);
            let b = point(&iso_t[k][t.iter().position(|x| x == v).unwrap()]);
            assert_eq!(a, b, "t = {tk}, v = {v}");
        }
    }
}

#[test]
fn the_spline_of_fig_6_has_continuous_speeds_at_its_joins() {
    let all = figures("joins");
    let s = &all["juttler_fig6.svg"]["series"][0];
    let (t, joins) = (nums(&s["t"]), nums(&s["joins"]));
    assert_eq!(joins.len(), 4);
    for curve in [nums(&s["speeds"][0]), nums(&s["speeds"][1]), nums(&s["angular_speed"])] {
        for j in &joins {
            let i = t.iter().position(|x| (x - j).abs() < 1e-12).expect("a join is a sample");
            // the value at the join extrapolated linearly from each side (a C1 motion: no jump; the
            // speeds have kinks there, worth about 0.11 at this sampling)
            let (left, right) = (2.0 * curve[i - 1] - curve[i - 2], 2.0 * curve[i + 1] - curve[i + 2]);
            assert!(
                (left - right).abs() < 0.2 && (left - curve[i]).abs() < 0.2,
                "t = {j}: {left} {} {right}",
                curve[i]
            );
        }
    }
}

#[test]
fn fig_4_stays_near_its_key_positions() {
    // Its own key positions (Figs. 1-3's make the TRT system (34) nearly singular): both
    // trajectories stay within 0.1 of the key points' bounding box, at speeds below 50.
    let figs = figures("fig4");
    let s = &figs["juttler_fig4.svg"]["series"][0];
    assert_eq!(s["degree"], 7, "max(l1, l2) + k = 3 + 4 (Result 5)");
    let keyp: Vec<[f64; 3]> = s["key_points"].as_array().unwrap().iter().flat_map(points).collect();
    let lo: [f64; 3] = std::array::from_fn(|i| keyp.iter().map(|p| p[i]).fold(f64::INFINITY, f64::min));
    let hi: [f64; 3] = std::array::from_fn(|i| keyp.iter().map(|p| p[i]).fold(f64::NEG_INFINITY, f64::max));
    for path in s["paths"].as_array().unwrap() {
        for p in points(path) {
            for i in 0..3 {
                assert!(p[i] > lo[i] - 0.1 && p[i] < hi[i] + 0.1, "{p:?} leaves the box {lo:?} {hi:?}");
            }
        }
    }
    for v in s["speeds"].as_array().unwrap().iter().flat_map(nums) {
        assert!(v < 50.0, "speed {v}");
    }
}
