//! The generated C header against klein (C++, SSE) and nalgebra, per element, on the two
//! kernels every motion loop calls: motor x motor and a motor on a point (each element with its
//! own motor).
//!
//! ```text
//! KLEIN_DIR=/path/to/klein/public cargo bench -p gam-lang-tests --bench c_kernels
//! ```
//!
//! The header (`gam codegen --lang c`, pga3 `Motor=even;Point=grade3`) and klein are timed in
//! one C++ program compiled here (`g++ $CXXFLAGS`, default `-O3 -march=native`; klein needs at
//! least `-msse4.1`; interleaved rounds, medians); nalgebra
//! (`UnitDualQuaternion<f32>` product and `transform_point`) in this process with the same
//! loop shape. Without `KLEIN_DIR` (klein is not vendored: `git clone
//! https://github.com/jeremyong/klein`) the klein rows are left out.

use algebra_codegen::lang::{Lang, Options, emit};
use nalgebra::{Point3, Quaternion, UnitDualQuaternion, UnitQuaternion, Vector3};
use std::hint::black_box;
use std::time::Instant;

const N: usize = 1024;
const ROUNDS: usize = 201;
const REPS: usize = 50;

const DRIVER: &str = r#"
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include <algorithm>
#include "pga.h"
#ifdef WITH_KLEIN
#include <klein/klein.hpp>
#endif
static const int N = 1024, ROUNDS = 201, REPS = 50;
static float rnd() { return (float)std::rand() / RAND_MAX * 2.0f - 1.0f; }
template <class F> static double ns(F f) {
    auto t0 = std::chrono::steady_clock::now();
    for (int r = 0; r < REPS; r++) f();
    auto t1 = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::nano>(t1 - t0).count() / (REPS * N);
}
static double median(std::vector<double> v) { std::sort(v.begin(), v.end()); return v[v.size() / 2]; }
int main() {
    std::vector<pga_Motorf> ma(N), mb(N), mo(N);
    std::vector<pga_Motor> da(N), db(N), dout(N);
    std::vector<pga_Pointf> pa(N), po(N);
    std::vector<pga_Point> dpa(N), dpo(N);
#ifdef WITH_KLEIN
    std::vector<kln::motor> ka(N), kb(N), ko(N);
    std::vector<kln::point> kp(N), kpo(N);
#endif
    for (int i = 0; i < N; i++) {
        float m[8], n[8], p[3];
        for (float& x : m) x = rnd();
        for (float& x : n) x = rnd();
        for (float& x : p) x = rnd();
        ma[i] = {m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7]};
        mb[i] = {n[0], n[1], n[2], n[3], n[4], n[5], n[6], n[7]};
        da[i] = {m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7]};
        db[i] = {n[0], n[1], n[2], n[3], n[4], n[5], n[6], n[7]};
        pa[i] = {p[0], p[1], p[2], 1.0f};
        dpa[i] = {p[0], p[1], p[2], 1.0};
#ifdef WITH_KLEIN
        ka[i] = kln::motor(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7]);
        kb[i] = kln::motor(n[0], n[1], n[2], n[3], n[4], n[5], n[6], n[7]);
        kp[i] = kln::point(p[0], p[1], p[2]);
#endif
    }
    std::vector<double> t[6];
    for (int r = 0; r < ROUNDS; r++) {
        t[0].push_back(ns([&] { for (int i = 0; i < N; i++) mo[i] = pga_motor_gp_motorf(ma[i], mb[i]); }));
        t[1].push_back(ns([&] { for (int i = 0; i < N; i++) dout[i] = pga_motor_gp_motor(da[i], db[i]); }));
        t[2].push_back(ns([&] { for (int i = 0; i < N; i++) po[i] = pga_motor_apply_unit_pointf(ma[i], pa[i]); }));
        t[3].push_back(ns([&] { for (int i = 0; i < N; i++) dpo[i] = pga_motor_apply_unit_point(da[i], dpa[i]); }));
#ifdef WITH_KLEIN
        t[4].push_back(ns([&] { for (int i = 0; i < N; i++) ko[i] = ka[i] * kb[i]; }));
        t[5].push_back(ns([&] { for (int i = 0; i < N; i++) kpo[i] = ka[i](kp[i]); }));
#endif
        asm volatile("" : : "r"(mo.data()), "r"(dout.data()), "r"(po.data()), "r"(dpo.data()) : "memory");
#ifdef WITH_KLEIN
        asm volatile("" : : "r"(ko.data()), "r"(kpo.data()) : "memory");
#endif
    }
    const char* names[6] = {"c_gp_f32", "c_gp_f64", "c_point_f32", "c_point_f64", "klein_gp", "klein_point"};
    for (int k = 0; k < 6; k++) if (!t[k].empty()) std::printf("%s %.4f\n", names[k], median(t[k]));
    return 0;
}
"#;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn per_element(f: &mut impl FnMut()) -> f64 {
    let start = Instant::now();
    for _ in 0..REPS {
        f();
    }
    start.elapsed().as_secs_f64() * 1e9 / (REPS * N) as f64
}

fn main() {
    // the C++ program: the generated header and klein
    let plan = gam_lang_tests::plan("pga3", algebra_core::Basis::Blade, "Motor=even;Point=grade3", "pga");
    let options = Options { ops: Some(["gp".to_string(), "apply_unit".to_string()].into()), ..Options::default() };
    let header = emit(&plan, Lang::C, &options).expect("the header");
    let dir = std::env::temp_dir().join(format!("gam-c-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("pga.h"), header).unwrap();
    std::fs::write(dir.join("bench.cpp"), DRIVER).unwrap();
    let mut cmd = std::process::Command::new(std::env::var("CXX").unwrap_or_else(|_| "g++".into()));
    let flags = std::env::var("CXXFLAGS").unwrap_or_else(|_| "-O3 -march=native".into());
    cmd.arg("-std=c++17").args(flags.split_whitespace()).arg("-o").arg(dir.join("bench")).arg(dir.join("bench.cpp"));
    cmd.arg(format!("-I{}", dir.display()));
    let klein = std::env::var("KLEIN_DIR").ok();
    if let Some(k) = &klein {
        cmd.arg(format!("-I{k}")).arg("-DWITH_KLEIN");
    }
    assert!(cmd.status().expect("a C++ compiler (g++ or $CXX)").success(), "the C++ driver compiles");
    let out = std::process::Command::new(dir.join("bench")).output().expect("the C++ driver runs");
    let text = String::from_utf8(out.stdout).unwrap();
    let get = |name: &str| -> Option<f64> {
        text.lines().find_map(|l| l.strip_prefix(name).and_then(|r| r.trim().parse().ok()))
    };
    // nalgebra, same loop shape, in this process
    let rnd = {
        let mut n = gam_lang_tests::Numbers::new(7);
        move || n.next_f64() as f32 * 0.5
    };
    let mut rnd = rnd;
    let mut dq = || {
        let q = UnitQuaternion::from_quaternion(Quaternion::new(rnd(), rnd(), rnd(), rnd()));
        UnitDualQuaternion::from_parts(Vector3::new(rnd(), rnd(), rnd()).into(), q)
    };
    let a: Vec<UnitDualQuaternion<f32>> = (0..N).map(|_| dq()).collect();
    let b: Vec<UnitDualQuaternion<f32>> = (0..N).map(|_| dq()).collect();
    let p: Vec<Point3<f32>> = (0..N).map(|i| Point3::new(i as f32 * 1e-3, 0.5, -0.25)).collect();
    let mut o = vec![UnitDualQuaternion::identity(); N];
    let mut po = vec![Point3::origin(); N];
    let (mut ng, mut np) = (Vec::new(), Vec::new());
    for _ in 0..ROUNDS {
        ng.push(per_element(&mut || {
            let (a, b) = (black_box(&a), black_box(&b));
            for ((o, a), b) in o.iter_mut().zip(a).zip(b) {
                *o = a * b;
            }
            black_box(&o);
        }));
        np.push(per_element(&mut || {
            let (a, p) = (black_box(&a), black_box(&p));
            for ((o, a), p) in po.iter_mut().zip(a).zip(p) {
                *o = a.transform_point(p);
            }
            black_box(&po);
        }));
    }
    let (ng, np) = (median(ng), median(np));
    println!("per element, ns (medians of {ROUNDS} rounds of {REPS} x {N}); C++ flags: {flags}");
    println!("{:<34} {:>8} {:>10} {:>10}", "kernel", "ns", "/ klein", "/ nalgebra");
    let row = |name: &str, ns: f64, klein: Option<f64>, nalg: f64| {
        let k = klein.map_or("-".to_string(), |k| format!("{:.2}x", ns / k));
        println!("{name:<34} {ns:>8.3} {k:>10} {:>10}", format!("{:.2}x", ns / nalg));
    };
    let (kg, kp) = (get("klein_gp"), get("klein_point"));
    row("C motor x motor f32", get("c_gp_f32").unwrap(), kg, ng);
    row("C motor x motor f64", get("c_gp_f64").unwrap(), kg, ng);
    if let Some(k) = kg {
        row("klein motor * motor (SSE)", k, kg, ng);
    }
    row("nalgebra UnitDualQuaternion<f32> *", ng, kg, ng);
    row("C motor on point f32 (apply_unit)", get("c_point_f32").unwrap(), kp, np);
    row("C motor on point f64 (apply_unit)", get("c_point_f64").unwrap(), kp, np);
    if let Some(k) = kp {
        row("klein motor(point) (SSE)", k, kp, np);
    }
    row("nalgebra transform_point f32", np, kp, np);
    if klein.is_none() {
        println!("(klein rows left out: set KLEIN_DIR to klein's `public` directory)");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
