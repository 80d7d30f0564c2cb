//! Running the generated WGSL and GLSL kernels as compute shaders through wgpu (Vulkan; a
//! software driver such as Mesa's lavapipe is enough), for the tests and the benchmark of
//! this crate.

use algebra_codegen::lang::ir::{Kernel, Output};
use algebra_codegen::lang::{field_names, function_name, type_name};
use algebra_codegen::plan::Plan;
use std::fmt::Write;
use std::future::Future;
use std::pin::pin;
use std::sync::Arc;
use std::task::{Context, Poll, Wake, Waker};

/// A device and its queue.
pub struct Gpu {
    /// The device.
    pub device: wgpu::Device,
    /// Its queue.
    pub queue: wgpu::Queue,
    /// The adapter's name (e.g. `llvmpipe (LLVM 15.0.7, 256 bits)`).
    pub name: String,
}

struct Noop;
impl Wake for Noop {
    fn wake(self: Arc<Self>) {}
}

/// Polls a future to completion on this thread (wgpu's native futures resolve when the
/// device is polled; no executor is needed).
pub fn block_on<F: Future>(f: F) -> F::Output {
    let waker = Waker::from(Arc::new(Noop));
    let mut cx = Context::from_waker(&waker);
    let mut f = pin!(f);
    loop {
        if let Poll::Ready(v) = f.as_mut().poll(&mut cx) {
            return v;
        }
        std::thread::yield_now();
    }
}

impl Gpu {
    /// The first Vulkan adapter, or a message saying why there is none.
    pub fn new() -> Result<Gpu, String> {
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
            backends: wgpu::Backends::VULKAN,
            ..wgpu::InstanceDescriptor::new_without_display_handle()
        });
        let adapter = block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default()))
            .map_err(|e| format!("no Vulkan adapter ({e}); install a driver, e.g. mesa-vulkan-drivers"))?;
        let name = adapter.get_info().name;
        let (device, queue) =
            block_on(adapter.request_device(&wgpu::DeviceDescriptor::default())).map_err(|e| e.to_string())?;
        Ok(Gpu { device, queue, name })
    }

    /// A storage buffer holding `data`.
    pub fn buffer(&self, data: &[f32], writable: bool) -> wgpu::Buffer {
        let bytes: Vec<u8> = data.iter().flat_map(|x| x.to_le_bytes()).collect();
        let usage = if writable {
            wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC | wgpu::BufferUsages::COPY_DST
        } else {
            wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST
        };
        let buffer = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: (bytes.len().max(4)) as u64,
            usage,
            mapped_at_creation: false,
        });
        self.queue.write_buffer(&buffer, 0, &bytes);
        buffer
    }

    /// The layout of three storage buffers: two read-only inputs and one output.
    pub fn layout(&self) -> wgpu::BindGroupLayout {
        let entry = |binding: u32, read_only: bool| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Storage { read_only },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        self.device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: None,
            entries: &[entry(0, true), entry(1, true), entry(2, false)],
        })
    }

    /// A compute pipeline for `entry` of `module` with [`Self::layout`].
    pub fn pipeline(
        &self,
        module: &wgpu::ShaderModule,
        entry: &str,
        layout: &wgpu::BindGroupLayout,
    ) -> wgpu::ComputePipeline {
        let pipeline_layout = self.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: None,
            bind_group_layouts: &[Some(layout)],
            immediate_size: 0,
        });
        self.device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(entry),
            layout: Some(&pipeline_layout),
            module,
            entry_point: Some(entry),
            compilation_options: Default::default(),
            cache: None,
        })
    }

    /// Dispatches `groups` workgroups of `pipeline` on the three buffers and waits.
    pub fn dispatch(
        &self,
        pipeline: &wgpu::ComputePipeline,
        layout: &wgpu::BindGroupLayout,
        buffers: [&wgpu::Buffer; 3],
        groups: u32,
    ) {
        let bind = self.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: buffers[0].as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: buffers[1].as_entire_binding() },
                wgpu::BindGroupEntry { binding: 2, resource: buffers[2].as_entire_binding() },
            ],
        });
        let mut encoder = self.device.create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor::default());
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, &bind, &[]);
            pass.dispatch_workgroups(groups, 1, 1);
        }
        self.queue.submit([encoder.finish()]);
        self.device.poll(wgpu::PollType::wait_indefinitely()).expect("the device finishes");
    }

    /// The contents of a buffer as `f32`s.
    pub fn read(&self, buffer: &wgpu::Buffer) -> Vec<f32> {
        let size = buffer.size();
        let staging = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let mut encoder = self.device.create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
        encoder.copy_buffer_to_buffer(buffer, 0, &staging, 0, size);
        self.queue.submit([encoder.finish()]);
        let slice = staging.slice(..);
        slice.map_async(wgpu::MapMode::Read, |r| r.expect("the buffer maps"));
        self.device.poll(wgpu::PollType::wait_indefinitely()).expect("the device finishes");
        let data = slice.get_mapped_range().expect("the mapped range");
        let out = data.chunks_exact(4).map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect();
        drop(data);
        staging.unmap();
        out
    }
}

/// The shading language of a test module.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shader {
    /// WGSL.
    Wgsl,
    /// GLSL 4.50 (translated by wgpu's naga front end).
    Glsl,
}

/// One entry point per kernel, `k0`, `k1`, ...: invocation `i < count` reads its operands'
/// fields from the flat `f32` buffers `a` and `b` (binding 0 and 1), calls the kernel and
/// writes the result's fields to `o` (binding 2). Workgroups of 64.
pub fn test_shader(plan: &Plan, kernels: &[Kernel], source: &str, lang: Shader, count: usize) -> String {
    let mut s = String::new();
    match lang {
        Shader::Wgsl => {
            s.push_str(source);
            s.push_str(
                "@group(0) @binding(0) var<storage, read> a: array<f32>;\n\
                 @group(0) @binding(1) var<storage, read> b: array<f32>;\n\
                 @group(0) @binding(2) var<storage, read_write> o: array<f32>;\n",
            );
        }
        Shader::Glsl => {
            s.push_str("#version 450\nlayout(local_size_x = 64) in;\n");
            s.push_str(source);
            s.push_str(
                "layout(std430, set = 0, binding = 0) readonly buffer A { float a[]; };\n\
                 layout(std430, set = 0, binding = 1) readonly buffer B { float b[]; };\n\
                 layout(std430, set = 0, binding = 2) buffer O { float o[]; };\n",
            );
        }
    }
    let fields = field_names(plan);
    for (n, k) in kernels.iter().enumerate() {
        let mut body = String::new();
        let buffers = ["a", "b"];
        let mut args = Vec::new();
        for (p, &ty) in k.params.iter().enumerate() {
            let f = &fields[ty];
            let reads: Vec<String> = (0..f.len()).map(|j| format!("{}[i * {}u + {j}u]", buffers[p], f.len())).collect();
            let tn = type_name(plan, ty);
            match lang {
                Shader::Wgsl => writeln!(body, "    let x{p} = {tn}({});", reads.join(", ")),
                Shader::Glsl => writeln!(body, "    {tn} x{p} = {tn}({});", reads.join(", ")),
            }
            .unwrap();
            args.push(format!("x{p}"));
        }
        let call = format!("{}({})", function_name(plan, k), args.join(", "));
        match &k.output {
            Output::Type(o, _) => {
                let f = &fields[*o];
                match lang {
                    Shader::Wgsl => writeln!(body, "    let r = {call};"),
                    Shader::Glsl => writeln!(body, "    {} r = {call};", type_name(plan, *o)),
                }
                .unwrap();
                for (j, name) in f.iter().enumerate() {
                    writeln!(body, "    o[i * {}u + {j}u] = r.{name};", f.len()).unwrap();
                }
            }
            Output::Scalar(_) => writeln!(body, "    o[i] = {call};").unwrap(),
        }
        match lang {
            Shader::Wgsl => write!(
                s,
                "@compute @workgroup_size(64)\nfn k{n}(@builtin(global_invocation_id) id: vec3<u32>) {{\n    let i = id.x;\n    if (i >= {count}u) {{ return; }}\n{body}}}\n"
            ),
            // GLSL has one entry point per module: `main` calls the kernel chosen by a define
            Shader::Glsl => write!(
                s,
                "#if KERNEL == {n}\nvoid main() {{\n    uint i = gl_GlobalInvocationID.x;\n    if (i >= {count}u) {{ return; }}\n{body}}}\n#endif\n"
            ),
        }
        .unwrap();
    }
    s
}
