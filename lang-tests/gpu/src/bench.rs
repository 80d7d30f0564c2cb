//! `gpu-bench`: moving 10^6 points by one motor in a WGSL compute shader, the generated
//! `pga_motor_apply_unit_point` against the same transform written by hand with a 4x4 matrix
//! (`m * p`), in the same run on the same device: interleaved rounds, medians, the ratio.
//!
//! ```text
//! cargo run --release --manifest-path lang-tests/gpu/Cargo.toml --bin gpu-bench [POINTS] [ROUNDS]
//! ```
//!
//! Both shaders read and write 16 bytes per point (a PGA point `e012, e013, e023, e123` and a
//! homogeneous `vec4` have the same layout); the motor is the unit motor of a rotation by 0.7
//! rad about a tilted axis and a translation, and its matrix is the one `apply_unit` computes.

use algebra_codegen::lang::{Lang, Options, emit};
use gam_gpu_tests::Gpu;
use std::time::Instant;

algebra_macros::algebra! {
    /// 3D PGA, for the motor, its matrix and the check of the shaders' output.
    pub mod pga {
        metric builtin "pga3";
        types { Motor = even; Point = grade 3; Bivector = grade 2; }
    }
}

fn shader(gpu: &Gpu, source: String) -> wgpu::ShaderModule {
    gpu.device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: None,
        source: wgpu::ShaderSource::Wgsl(source.into()),
    })
}

const MAIN: &str = "@compute @workgroup_size(64)\nfn main(@builtin(global_invocation_id) id: vec3<u32>) {\n    let i = id.x;\n    if (i >= arrayLength(&points)) { return; }\n";

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1_000_000);
    let rounds: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(21);
    let gpu = match Gpu::new() {
        Ok(g) => g,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(1);
        }
    };
    // the motor: exp of a line (rotation about a tilted axis through a point, and a slide)
    let line = pga::Bivector::<f32>::from_array([0.3, -0.2, 0.35, 0.1, -0.15, 0.25]);
    let motor: pga::Motor<f32> = line.exp();
    // its action on the basis points, as the columns of a matrix (homogeneous coordinates)
    let mut m = [0.0f32; 16];
    for col in 0..4 {
        let mut e = [0.0f32; 4];
        e[col] = 1.0;
        let image = motor.apply_unit(&pga::Point::from_array(e)).to_array();
        m[col * 4..col * 4 + 4].copy_from_slice(&image);
    }
    let points: Vec<f32> = (0..n)
        .flat_map(|i| {
            let t = i as f32 * 1e-6;
            [t.sin(), (3.0 * t).cos(), t - 0.5, 1.0]
        })
        .collect();

    let plan = gam_lang_tests::plan("pga3", algebra_core::Basis::Blade, "Motor=even;Point=grade3", "pga");
    let options = Options { ops: Some(["apply_unit".to_string()].into()), ..Options::default() };
    let generated = emit(&plan, Lang::Wgsl, &options).expect("WGSL");
    let ours = shader(
        &gpu,
        format!(
            "{generated}@group(0) @binding(0) var<storage, read> motor: array<pga_Motor>;\n\
             @group(0) @binding(1) var<storage, read> points: array<pga_Point>;\n\
             @group(0) @binding(2) var<storage, read_write> out: array<pga_Point>;\n\
             {MAIN}    out[i] = pga_motor_apply_unit_point(motor[0], points[i]);\n}}\n"
        ),
    );
    let by_hand = shader(
        &gpu,
        format!(
            "@group(0) @binding(0) var<storage, read> m: array<mat4x4<f32>>;\n\
             @group(0) @binding(1) var<storage, read> points: array<vec4<f32>>;\n\
             @group(0) @binding(2) var<storage, read_write> out: array<vec4<f32>>;\n\
             {MAIN}    out[i] = m[0] * points[i];\n}}\n"
        ),
    );
    let layout = gpu.layout();
    let (p_ours, p_hand) = (gpu.pipeline(&ours, "main", &layout), gpu.pipeline(&by_hand, "main", &layout));
    let input = gpu.buffer(&points, false);
    let (motor_buf, matrix_buf) = (gpu.buffer(&motor.to_array(), false), gpu.buffer(&m, false));
    let out = gpu.buffer(&vec![0.0; 4 * n], true);
    let groups = n.div_ceil(64) as u32;
    // both give the Rust result
    for (p, uniform) in [(&p_ours, &motor_buf), (&p_hand, &matrix_buf)] {
        gpu.dispatch(p, &layout, [uniform, &input, &out], groups);
        let got = gpu.read(&out);
        for i in [0, n / 2, n - 1] {
            let want =
                motor.apply_unit(&pga::Point::from_array(points[4 * i..4 * i + 4].try_into().unwrap())).to_array();
            let ok = got[4 * i..4 * i + 4].iter().zip(want).all(|(g, w)| (g - w).abs() <= 1e-5 * (1.0 + w.abs()));
            assert!(ok, "point {i}: {:?} vs {want:?}", &got[4 * i..4 * i + 4]);
        }
    }
    let time = |p: &wgpu::ComputePipeline, uniform: &wgpu::Buffer| {
        let start = Instant::now();
        gpu.dispatch(p, &layout, [uniform, &input, &out], groups);
        start.elapsed().as_secs_f64()
    };
    let (mut a, mut b) = (Vec::new(), Vec::new());
    for _ in 0..3 {
        time(&p_ours, &motor_buf);
        time(&p_hand, &matrix_buf);
    }
    for r in 0..rounds {
        // alternate which goes first
        if r % 2 == 0 {
            a.push(time(&p_ours, &motor_buf));
            b.push(time(&p_hand, &matrix_buf));
        } else {
            b.push(time(&p_hand, &matrix_buf));
            a.push(time(&p_ours, &motor_buf));
        }
    }
    let (ta, tb) = (median(a), median(b));
    println!("device: {}", gpu.name);
    println!("points: {n}, rounds: {rounds} (medians of dispatch + wait)");
    println!("generated pga_motor_apply_unit_point: {:.3} ms ({:.2} ns/point)", ta * 1e3, ta * 1e9 / n as f64);
    println!("hand-written mat4x4 * vec4:          {:.3} ms ({:.2} ns/point)", tb * 1e3, tb * 1e9 / n as f64);
    println!("ratio generated / matrix: {:.3}x", ta / tb);
}
