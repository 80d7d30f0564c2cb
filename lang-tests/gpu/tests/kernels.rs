//! The generated WGSL and GLSL kernels run as compute shaders (wgpu, Vulkan) against the Rust
//! `f32` kernels of the same declaration: every WGSL kernel among the declared types of 3D PGA
//! (with its closed forms) and of the dual quaternions of `g123inf`, and the GLSL kernels of
//! the main operations, on 64 random inputs each, within `f32` rounding (a GPU may fuse
//! multiply-adds and has its own `sin`, `cos` and `atan2`).
//!
//! Needs a Vulkan driver; on a machine without a GPU, Mesa's lavapipe
//! (`apt-get install mesa-vulkan-drivers`, which `.ci/run` installs).

use algebra_codegen::lang::ir::Kernel;
use algebra_codegen::lang::kernels;
use algebra_codegen::lang::{Lang, Options, emit, function_name};
use algebra_codegen::plan::Plan;
use algebra_core::Basis;
use gam_gpu_tests::{Gpu, Shader, test_shader};
use gam_lang_tests::{Numbers, Registry, arguments, is_closed, plan, registry};

algebra_macros::algebra! {
    /// 3D PGA.
    pub mod pga {
        metric builtin "pga3";
        types { Motor = even; Point = grade 3; Line = grade 2; Plane = grade 1; }
    }
}

algebra_macros::algebra! {
    /// Dual quaternions in the conformal subalgebra.
    pub mod g123inf {
        metric builtin "g123inf";
        types { Motor = [1, e12, e13, e23, e1inf, e2inf, e3inf, e123inf]; Vector = grade 1; Bivector = grade 2; }
    }
}

const COUNT: usize = 64;

/// The inputs of one kernel (flat, `COUNT` values of each parameter) and the Rust results.
fn inputs(plan: &Plan, reg: &Registry<f32>, k: &Kernel, numbers: &mut Numbers) -> ([Vec<f32>; 2], Vec<Vec<f32>>) {
    let mut flat = [Vec::new(), Vec::new()];
    let mut want = Vec::new();
    let rust = reg.get(plan, k).unwrap_or_else(|| panic!("no Rust kernel for {}", function_name(plan, k)));
    for sample in 0..COUNT {
        // one sample in eight of a closed form takes the series branch
        let args = arguments(plan, reg, k, numbers, sample % 8 == 0, |x| x as f32);
        for (p, a) in args.iter().enumerate() {
            flat[p].extend(a);
        }
        want.push(rust(&args));
    }
    (flat, want)
}

/// Runs `chosen` kernels of the plan in `lang` and compares; returns how many ran.
fn run(gpu: &Gpu, plan: &Plan, reg: &Registry<f32>, lang: Shader, chosen: impl Fn(&Kernel) -> bool) -> usize {
    let all: Vec<Kernel> =
        kernels(plan).unwrap().into_iter().filter(|k| k.params.iter().all(|&p| p < plan.declared)).collect();
    let source = emit(plan, if lang == Shader::Wgsl { Lang::Wgsl } else { Lang::Glsl }, &Options::default()).unwrap();
    let shader = test_shader(plan, &all, &source, lang, COUNT);
    let layout = gpu.layout();
    let wgsl = (lang == Shader::Wgsl).then(|| {
        gpu.device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: None,
            source: wgpu::ShaderSource::Wgsl(shader.clone().into()),
        })
    });
    let mut numbers = Numbers::new(0x9e3);
    let mut ran = 0;
    for (n, k) in all.iter().enumerate().filter(|(_, k)| chosen(k)) {
        let name = function_name(plan, k);
        let ([a, b], want) = inputs(plan, reg, k, &mut numbers);
        let out_len = COUNT * want[0].len();
        let bufs = [gpu.buffer(&a, false), gpu.buffer(&b, false), gpu.buffer(&vec![f32::NAN; out_len], true)];
        let glsl;
        let module = match &wgsl {
            Some(m) => m,
            None => {
                let define = n.to_string();
                glsl = gpu.device.create_shader_module(wgpu::ShaderModuleDescriptor {
                    label: None,
                    source: wgpu::ShaderSource::Glsl {
                        shader: shader.clone().into(),
                        stage: wgpu::naga::ShaderStage::Compute,
                        defines: &[("KERNEL", define.as_str())],
                    },
                });
                &glsl
            }
        };
        let entry = if lang == Shader::Wgsl { format!("k{n}") } else { "main".to_string() };
        let pipeline = gpu.pipeline(module, &entry, &layout);
        gpu.dispatch(&pipeline, &layout, [&bufs[0], &bufs[1], &bufs[2]], COUNT.div_ceil(64) as u32);
        let got = gpu.read(&bufs[2]);
        let tol = if is_closed(k.op.name()) { 3e-5 } else { 4e-6 };
        for (i, w) in want.iter().enumerate() {
            let g = &got[i * w.len()..(i + 1) * w.len()];
            let scale = w.iter().map(|x| x.abs()).fold(1.0f32, f32::max);
            let ok = g.iter().zip(w).all(|(x, y)| (x - y).abs() <= tol * scale);
            assert!(ok, "{lang:?} {name}, sample {i}: GPU {g:?} vs Rust {w:?}");
        }
        ran += 1;
    }
    ran
}

fn gpu() -> Gpu {
    Gpu::new().unwrap_or_else(|e| panic!("{e}"))
}

fn pga_plan() -> Plan {
    plan("pga3", Basis::Blade, "Motor=even;Point=grade3;Line=grade2;Plane=grade1", "pga")
}

fn g123inf_plan() -> Plan {
    plan(
        "g123inf",
        Basis::Blade,
        "Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1;Bivector=grade2",
        "g123inf",
    )
}

#[test]
fn wgsl_kernels_on_the_gpu_equal_the_rust_kernels() {
    let gpu = gpu();
    let r = registry!(pga, f32; types [Motor, Point, Line, Plane, Odd, Multivector]; versors [Motor, Point, Line, Plane, Odd] on [Motor, Point, Line, Plane, Odd]; closed [Line => Motor]);
    let n = run(&gpu, &pga_plan(), &r, Shader::Wgsl, |_| true);
    assert!(n > 200, "{n} kernels ran");
    let r = registry!(g123inf, f32; types [Motor, Vector, Bivector, Odd, Multivector]; versors [Motor, Vector, Bivector, Odd] on [Motor, Vector, Bivector, Odd]; closed [Bivector => Motor]);
    run(&gpu, &g123inf_plan(), &r, Shader::Wgsl, |_| true);
}

#[test]
fn glsl_kernels_on_the_gpu_equal_the_rust_kernels() {
    let gpu = gpu();
    let r = registry!(pga, f32; types [Motor, Point, Line, Plane, Odd, Multivector]; versors [Motor, Point, Line, Plane, Odd] on [Motor, Point, Line, Plane, Odd]; closed [Line => Motor]);
    let main = |k: &Kernel| {
        matches!(
            k.op.name(),
            "gp" | "apply" | "apply_unit" | "sandwich" | "exp" | "log_unit" | "normalize" | "norm_squared"
        ) && k.params[0] == 0
    };
    let n = run(&gpu, &pga_plan(), &r, Shader::Glsl, main);
    assert!(n >= 15, "{n} kernels ran");
}
