//! What the term-order tuners (`pairing_wisdom`, `product_wisdom`) share: compiling a
//! generated timing program and reading its ratios.

use std::path::Path;
use std::process::Command;

/// Writes `src` to `DIR/NAME.rs`, compiles it with `rustc -O` (edition 2024, baseline x86-64
/// as the benches), runs it pinned to `core` with `taskset`, and returns the second word of
/// each output line that parses as a number: one ratio per timed kernel, `expected` of them.
pub fn compile_and_time(dir: &Path, name: &str, src: &str, core: &str, expected: usize) -> Vec<f64> {
    let path = dir.join(format!("{name}.rs"));
    std::fs::write(&path, src).expect("write");
    let exe = dir.join(name);
    let status =
        Command::new("rustc").args(["-O", "--edition", "2024", "-o"]).arg(&exe).arg(&path).status().expect("rustc");
    assert!(status.success(), "rustc failed on {}", path.display());
    let out = Command::new("taskset").args(["-c", core]).arg(&exe).output().expect("run");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8_lossy(&out.stdout);
    let ratios: Vec<f64> = text.lines().filter_map(|l| l.split_whitespace().nth(1)?.parse().ok()).collect();
    assert_eq!(ratios.len(), expected, "one ratio per kernel:\n{text}");
    ratios
}

/// The generated programs' random source: `rng()` uniform in `[-1, 1)`, the same sequence in
/// every program (xorshift64, the benches' seed).
pub const RNG: &str = "let mut state = 0x1234_5678_9abc_def1u64;
    let mut rng = move || { state ^= state << 13; state ^= state >> 7; state ^= state << 17; (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0 };";
