//! The WGSL and GLSL kernels, validated by naga (the shader compiler of wgpu and Firefox; here
//! wgpu's, so that the workspace's test build does not compile it):
//! every kernel of four declarations parses and passes naga's validator, and each struct has
//! the size of the Rust `repr(C)` type of `f32` (no padding), so a storage buffer of them has
//! the layout of a `[T<f32>]` slice. `kernels.rs` runs them on a GPU.

use algebra_codegen::lang::{Lang, Options, emit};
use algebra_codegen::plan::Plan;
use algebra_core::Basis;
use gam_lang_tests::plan;

fn plans() -> Vec<Plan> {
    vec![
        plan("pga3", Basis::Blade, "Motor=even;Point=grade3;Line=grade2;Plane=grade1", "pga"),
        plan(
            "pga3",
            Basis::Blade,
            "Plane=grade1;Line=e01,e02,e03,e12,e31,e23;Point=e021,e013,e032,e123;Motor=1,e01,e02,e03,e12,e31,e23,e0123",
            "ganja",
        ),
        plan(
            "g123inf",
            Basis::Blade,
            "Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1;Bivector=grade2",
            "g123inf",
        ),
        plan("g3", Basis::Blade, "Rotor=even;Vector=grade1;Bivector=grade2", "g3"),
        plan("cga-null", Basis::Product, "Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1", "cga_null"),
    ]
}

fn every() -> Options {
    Options { every_type: true, ..Options::default() }
}

fn validate(module: &wgpu::naga::Module, what: &str) -> wgpu::naga::valid::ModuleInfo {
    wgpu::naga::valid::Validator::new(
        wgpu::naga::valid::ValidationFlags::all(),
        wgpu::naga::valid::Capabilities::default(),
    )
    .validate(module)
    .unwrap_or_else(|e| panic!("{what} does not validate: {e:?}"))
}

/// Every kernel of the plan is a function of the module (with the closed forms, whose
/// helpers are functions too).
fn every_kernel_is_a_function(plan: &Plan, module: &wgpu::naga::Module) {
    let names: std::collections::HashSet<&str> =
        module.functions.iter().filter_map(|(_, f)| f.name.as_deref()).filter(|n| *n != "main").collect();
    let kernels = algebra_codegen::lang::kernels(plan).unwrap();
    for k in &kernels {
        let name = algebra_codegen::lang::function_name(plan, k);
        assert!(names.contains(name.as_str()), "{name} is missing");
    }
    let closed = kernels.iter().any(|k| k.op.name() == "exp");
    assert_eq!(names.len(), kernels.len() + if closed { 2 } else { 0 }, "{}: kernels and helpers", plan.spec.name);
}

#[test]
fn wgsl_kernels_validate_and_structs_are_packed() {
    for plan in plans() {
        let source = emit(&plan, Lang::Wgsl, &every()).unwrap();
        let module = wgpu::naga::front::wgsl::parse_str(&source)
            .unwrap_or_else(|e| panic!("{} WGSL: {}", plan.spec.name, e.emit_to_string(&source)));
        validate(&module, &format!("{} WGSL", plan.spec.name));
        every_kernel_is_a_function(&plan, &module);
        let mut layouter = wgpu::naga::proc::Layouter::default();
        layouter.update(module.to_ctx()).unwrap();
        for (i, t) in plan.spec.types.iter().enumerate() {
            let name = algebra_codegen::lang::type_name(&plan, i);
            let (handle, _) = module.types.iter().find(|(_, ty)| ty.name.as_deref() == Some(name.as_str())).unwrap();
            assert_eq!(layouter[handle].size as usize, 4 * t.elements.len(), "{name}: no padding");
        }
    }
}

#[test]
fn glsl_kernels_validate() {
    for plan in plans() {
        let source = emit(&plan, Lang::Glsl, &every()).unwrap();
        // the file is included into a shader with a version line and an entry point
        let shader = format!("#version 450\nlayout(local_size_x = 1) in;\n{source}\nvoid main() {{}}\n");
        let module = wgpu::naga::front::glsl::Frontend::default()
            .parse(&wgpu::naga::front::glsl::Options::from(wgpu::naga::ShaderStage::Compute), &shader)
            .unwrap_or_else(|e| panic!("{} GLSL: {}", plan.spec.name, e.emit_to_string(&shader)));
        validate(&module, &format!("{} GLSL", plan.spec.name));
        every_kernel_is_a_function(&plan, &module);
    }
}

/// The block of `lang` in docs/codegen.md's "Kernels in C, WGSL and GLSL", with the generated
/// file (named by its first line, `pga3 Motor=even;Point=grade3`) in place of its comment.
fn doc_shader(fence: &str, lang: Lang) -> String {
    let doc = include_str!("../../../docs/codegen.md");
    let start = doc.find(&format!("```{fence}\n")).expect("a block") + fence.len() + 4;
    let block = &doc[start..start + doc[start..].find("```").expect("its end")];
    let plan = plan("pga3", Basis::Blade, "Motor=even;Point=grade3", "pga");
    let source =
        emit(&plan, lang, &Options { ops: Some(["apply_unit".to_string()].into()), ..Options::default() }).unwrap();
    assert!(block.contains("// (the generated file"), "the block names where the file goes");
    block
        .lines()
        .map(|l| if l.starts_with("// (the generated file") { source.clone() } else { format!("{l}\n") })
        .collect()
}

#[test]
fn the_shaders_of_the_docs_validate() {
    let wgsl = doc_shader("wgsl", Lang::Wgsl);
    let module = wgpu::naga::front::wgsl::parse_str(&wgsl).unwrap_or_else(|e| panic!("{}", e.emit_to_string(&wgsl)));
    validate(&module, "the WGSL example");
    let glsl = doc_shader("glsl", Lang::Glsl);
    let module = wgpu::naga::front::glsl::Frontend::default()
        .parse(&wgpu::naga::front::glsl::Options::from(wgpu::naga::ShaderStage::Compute), &glsl)
        .unwrap_or_else(|e| panic!("{}", e.emit_to_string(&glsl)));
    validate(&module, "the GLSL example");
}
