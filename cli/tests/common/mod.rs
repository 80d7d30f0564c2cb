//! What every end-to-end test of the `gam` binary needs: run it, insist on success (stdout,
//! nothing on stderr) or on the error contract (exit status, empty stdout, exactly one
//! `error:` line), and temporary input files.
#![allow(dead_code)] // each test binary uses its own subset

use std::io::Write;
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

/// The example of shared/cli.md, verbatim (with its `//` comment).
pub const CONTRACT_EXAMPLE: &str = r#"{
  "kind": "additive",            // or "multiplicative"
  "degree": 3,
  "start": {"position": [0,0,0], "axis": [0,0,1], "angle": 0,
            "velocity": [1,1,1], "angular_velocity": [1,2,3],
            "shape": 1, "gamma": [0, 0]},
  "end":   {"position": [8,10,12], "axis": [1,2,3], "angle": 1.959,
            "velocity": [1,5,3], "angular_velocity": [2,1,1]}
}
"#;

/// Runs `gam` with `args`.
pub fn gam(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gam")).args(args).output().expect("run gam")
}

/// Runs a successful command and returns stdout without its final newline.
pub fn ok(args: &[&str]) -> String {
    let out = gam(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "gam {args:?} failed: {stderr}");
    assert!(stderr.is_empty(), "gam {args:?} wrote to stderr: {stderr}");
    let stdout = String::from_utf8(out.stdout).expect("utf-8");
    stdout.strip_suffix('\n').expect("output ends with a newline").to_string()
}

/// Asserts the error contract on `stderr` (one line starting `error: `, no panic) and returns
/// that line.
pub fn one_error_line(args: &[&str], stderr: &str) -> String {
    assert!(!stderr.contains("panicked"), "{stderr}");
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(lines.len(), 1, "gam {args:?}: expected one stderr line, got {stderr:?}");
    assert!(lines[0].starts_with("error: "), "{stderr}");
    // issue 30: an error line names the place and the reason, it does not dump values
    assert!(lines[0].chars().count() <= 300, "gam {args:?}: an error line of {} characters", lines[0].chars().count());
    lines[0].to_string()
}

/// Runs a failing command: checks the exit status, empty stdout and exactly one stderr line
/// starting `error:`, and returns that line.
pub fn fails(args: &[&str], code: i32) -> String {
    let out = gam(args);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(code), "gam {args:?}: {stderr}");
    assert!(out.stdout.is_empty(), "gam {args:?} printed {:?}", String::from_utf8_lossy(&out.stdout));
    one_error_line(args, &stderr)
}

/// A file in the temp directory (unique per test process), removed on drop.
pub struct TempFile(PathBuf);

impl TempFile {
    /// A path for a file the test (or gam) will write.
    /// Unique within the run: the test files are modules of one binary whose tests run in
    /// parallel, and two of them may use the same `name`.
    pub fn empty(name: &str) -> Self {
        static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
        let k = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        TempFile(std::env::temp_dir().join(format!("gam-cli-test-{}-{k}-{name}", std::process::id())))
    }

    /// A file holding `text`.
    pub fn new(name: &str, text: &str) -> Self {
        let f = TempFile::empty(name);
        std::fs::write(&f.0, text).expect("write temp file");
        f
    }

    /// The path as a command-line argument.
    pub fn path(&self) -> &str {
        self.0.to_str().expect("utf-8 path")
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

/// How long one fuzzed run may take before it counts as a hang.
pub const TIMEOUT: std::time::Duration = std::time::Duration::from_secs(30);

/// The address-space cap of every fuzzed run (`ulimit -v`, in KiB): 4 GB, so that a run that
/// would exhaust memory fails here (as an abort or a refusal) instead of swapping the machine.
pub const MEMORY_CAP_KIB: u64 = 4_000_000;

/// Runs gam with a timeout and checks the contract; returns the exit code. Output goes to
/// files (a full pipe would block the child while this thread waits on it).
pub fn run_contract(args: &[&str], stdin: &[u8]) -> i32 {
    run_capped(args, stdin, false).0
}

/// Runs gam under [`MEMORY_CAP_KIB`] and [`TIMEOUT`] and checks the contract: exit 0 with no
/// `inf` or `NaN` in its output and no panic, or exit 1/2 with exactly one `error:` line and
/// an empty stdout (unless `report_on_failure`: `gam prove` and `gam verify` print their
/// report, then the error line); never a signal (an abort, an allocation failure under the
/// cap) or a timeout. Returns the exit code and stdout.
pub fn run_capped(args: &[&str], stdin: &[u8], report_on_failure: bool) -> (i32, String) {
    static COUNTER: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let k = COUNTER.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let (out_file, err_file) = (TempFile::empty(&format!("fuzz-out-{k}")), TempFile::empty(&format!("fuzz-err-{k}")));
    // `exec`: the shell becomes gam, so the kill below reaches it
    let mut child = Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v {MEMORY_CAP_KIB} && exec \"$0\" \"$@\""))
        .arg(env!("CARGO_BIN_EXE_gam"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(std::fs::File::create(out_file.path()).expect("stdout file"))
        .stderr(std::fs::File::create(err_file.path()).expect("stderr file"))
        .spawn()
        .expect("run gam under sh");
    let mut input = child.stdin.take().expect("stdin");
    let _ = input.write_all(stdin);
    drop(input);
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("wait") {
            break status;
        }
        if start.elapsed() > TIMEOUT {
            let _ = child.kill();
            let files: Vec<String> = args.iter().filter_map(|a| std::fs::read_to_string(a).ok()).collect();
            panic!("gam {args:?} timed out after {TIMEOUT:?}; input files: {files:?}");
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    let stdout = String::from_utf8_lossy(&std::fs::read(out_file.path()).expect("stdout")).into_owned();
    let stderr = std::fs::read_to_string(err_file.path()).expect("stderr");
    let code = status.code().unwrap_or_else(|| panic!("gam {args:?} was killed by a signal: {stderr}"));
    match code {
        0 => assert!(!stderr.contains("panicked"), "{stderr}"),
        1 | 2 => {
            one_error_line(args, &stderr);
            assert!(stdout.is_empty() || report_on_failure, "gam {args:?} failed but printed to stdout");
        }
        _ => panic!("gam {args:?}: exit {code}: {stderr}"),
    }
    // (generated source code and the algebras' descriptions are text, not numbers: `f64::NAN`
    // may be in the one, the generator label `inf` in the other)
    let text = args.first() == Some(&"algebras") || (args.first() == Some(&"codegen") && !args.contains(&"stats"));
    if !text {
        assert_no_non_finite(args, &stdout);
    }
    (code, stdout)
}

/// No `inf`, `-inf`, `NaN` or `nan` token in `text` (names such as `einf`, `e1inf` are one
/// token and pass).
pub fn assert_no_non_finite(args: &[&str], text: &str) {
    let bad = text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).find(|t| {
        let t = t.to_ascii_lowercase();
        t == "inf" || t == "nan"
    });
    assert!(bad.is_none(), "gam {args:?} printed {bad:?}: {}", &text[..text.len().min(400)]);
}

/// A JSON 4x4 matrix (the `matrix` of `gam pose` and of the samples of `gam interpolate`).
pub fn matrix(v: &serde_json::Value) -> [[f64; 4]; 4] {
    serde_json::from_value(v.clone()).expect("4x4 matrix")
}

/// The largest entrywise difference of two 4x4 matrices.
pub fn max_diff(a: &[[f64; 4]; 4], b: &[[f64; 4]; 4]) -> f64 {
    (0..4).flat_map(|i| (0..4).map(move |j| (a[i][j] - b[i][j]).abs())).fold(0.0, f64::max)
}

/// `R x + t` as a 4x4 matrix from axis, angle, position (Rodrigues).
pub fn rodrigues(axis: [f64; 3], phi: f64, t: [f64; 3]) -> [[f64; 4]; 4] {
    let n = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
    let [x, y, z] = axis.map(|a| a / n);
    let (s, c) = phi.sin_cos();
    let k = 1.0 - c;
    [
        [c + x * x * k, x * y * k - z * s, x * z * k + y * s, t[0]],
        [y * x * k + z * s, c + y * y * k, y * z * k - x * s, t[1]],
        [z * x * k - y * s, z * y * k + x * s, c + z * z * k, t[2]],
        [0.0, 0.0, 0.0, 1.0],
    ]
}

/// Checks the `velocities` of `gam interpolate --json` samples (evenly spaced, step `h`)
/// against central differences of their `points`, at the sample indices `ks` (each with
/// neighbours), to `1e-4` relative: the velocities come from dual numbers in the library.
pub fn assert_velocities_match_differences(label: &str, samples: &[serde_json::Value], h: f64, ks: &[usize]) {
    let p = |j: usize| -> Vec<[f64; 3]> { serde_json::from_value(samples[j]["points"].clone()).unwrap() };
    for &k in ks {
        let vel: Vec<[f64; 3]> = serde_json::from_value(samples[k]["velocities"].clone()).unwrap();
        let (a, b) = (p(k + 1), p(k - 1));
        for (q, v) in vel.iter().enumerate() {
            for r in 0..3 {
                let fd = (a[q][r] - b[q][r]) / (2.0 * h);
                assert!(
                    (fd - v[r]).abs() < 1e-4 * (1.0 + v[r].abs()),
                    "{label} sample {k} point {q}: {fd} vs {}",
                    v[r]
                );
            }
        }
    }
}

/// The rigid matrix of the rotation by the quaternion `[w, x, y, z]` (any non-zero scale), then
/// the translation `t`, by [`rodrigues`] (the half-angle from `q`'s scalar and vector parts).
pub fn rodrigues_wxyz(q: [f64; 4], t: [f64; 3]) -> [[f64; 4]; 4] {
    let n = q.iter().map(|c| c * c).sum::<f64>().sqrt();
    let sin = (q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt() / n;
    let axis = if sin > 0.0 { [q[1], q[2], q[3]] } else { [0.0, 0.0, 1.0] };
    rodrigues(axis, 2.0 * sin.atan2(q[0] / n), t)
}

/// A JSON coefficient (a `"p/q"` string or a number) as an exact rational.
pub fn exact(v: &serde_json::Value) -> algebra_core::rational::Q {
    use algebra_core::rational::parse_rational;
    match v {
        serde_json::Value::String(s) => parse_rational(s).expect("a rational"),
        serde_json::Value::Number(n) => parse_rational(&n.to_string()).expect("a number"),
        _ => panic!("not a number: {v}"),
    }
}

/// One segment of `gam trajectory --json --scalar rational`, its rational curve
/// `p(u) = P(u)/W(u)` at `u = 1` (`at_end`) or `u = 0`, exactly: the point, then its derivative
/// per unit of `t`, `p' = (P' W - P W')/W² / (t1 - t0)`, with `P' = ±n (P_a - P_b)` from the two
/// control points at that end (the Bernstein end derivative). Equal values on both sides of a
/// break are C1 there.
pub fn curve_end(seg: &serde_json::Value, at_end: bool) -> Vec<algebra_core::rational::Q> {
    use algebra_core::rational::Q;
    let w: Vec<Q> = seg["weights"].as_array().unwrap().iter().map(exact).collect();
    let p: Vec<Vec<Q>> =
        seg["points"].as_array().unwrap().iter().map(|x| x.as_array().unwrap().iter().map(exact).collect()).collect();
    let n = w.len() - 1;
    let h = exact(&seg["t1"]) - exact(&seg["t0"]);
    let (a, b) = if at_end { (n, n - 1) } else { (0, 1) };
    let s = Q::from_integer((if at_end { n as i64 } else { -(n as i64) }).into());
    let dw = &s * (&w[a] - &w[b]);
    let rates = p[a].iter().zip(&p[b]).map(|(xa, xb)| {
        let pa = &w[a] * xa;
        ((&s * (&pa - &w[b] * xb)) * &w[a] - &pa * &dw) / (&w[a] * &w[a]) / &h
    });
    p[a].iter().cloned().chain(rates).collect()
}

/// The segments of `gam trajectory --json --scalar rational SPEC --point POINT`, after checking
/// with [`curve_end`] that the rational curve is exactly C1 at every break.
pub fn exact_c1_segments(spec: &str, point: &str) -> Vec<serde_json::Value> {
    let out = ok(&["trajectory", "--json", "--scalar", "rational", spec, "--point", point]);
    let tr: serde_json::Value = serde_json::from_str(&out).unwrap();
    let segs = tr["segments"].as_array().unwrap().clone();
    for (k, w) in segs.windows(2).enumerate() {
        assert_eq!(curve_end(&w[0], true), curve_end(&w[1], false), "not C1 at break {}", k + 1);
    }
    segs
}
