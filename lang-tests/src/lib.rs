//! Helpers for testing the kernels the generator emits in other languages
//! (`algebra_codegen::lang`) against the Rust kernels of the same declaration: a registry of
//! the Rust kernels by operation and parameter types, random inputs, and a C driver that
//! compiles the header and runs every kernel on the same inputs.

use algebra_codegen::lang::ir::{Kernel, Output};
use algebra_codegen::lang::{field_names, function_name, type_name};
use algebra_codegen::{ModuleSpec, plan::Plan};
use algebra_core::{Algebra, Basis};
use std::collections::HashMap;
use std::fmt::Write;
use std::ops::IndexMut;

/// The product traits the generated kernels implement (for [`registry!`]).
pub use algebra_core::ops;

/// A [`Registry`] of every kernel of a generated module `$m` at scalar `$s`: the products
/// among `types`, their unary maps and norms, the actions (`sandwich`, `apply` and their unit
/// forms) of each of `versors` on each of `on` (one or more such groups: the pairs with a fused
/// kernel, `algebra_codegen::versor::keeps_operand`), and `exp`/`log_unit`/`normalize` of the
/// `closed` (bivector => even) pairs.
#[macro_export]
macro_rules! registry {
    ($m:ident, $s:ty; types [$($t:ident),*]; $(versors [$($v:ident),*] on [$($x:ident),*];)+ closed [$($b:ident => $ev:ident),*]) => {{
        let mut r = $crate::Registry::<$s>::default();
        $( registry!(@closed r, $m, $s, $b, $ev); )*
        $( r.elements.insert(stringify!($t).to_string(), $m::$t::<$s>::ELEMENTS.iter().map(|e| e.to_string()).collect()); )*
        registry!(@rows r, $m, $s; [$($t),*]; $($t),*);
        $( registry!(@unary r, $m, $s, $t); )*
        $( registry!(@actions r, $m, $s; [$($x),*]; $($v),*); )+
        r
    }};
    (@rows $r:ident, $m:ident, $s:ty; $all:tt; $($a:ident),*) => { $( registry!(@row $r, $m, $s, $a; $all); )* };
    (@row $r:ident, $m:ident, $s:ty, $a:ident; [$($b:ident),*]) => { $(
        registry!(@prod $r, $m, $s, $a, $b, "gp", GeometricProduct, gp);
        registry!(@prod $r, $m, $s, $a, $b, "op", OuterProduct, op);
        registry!(@prod $r, $m, $s, $a, $b, "lc", LeftContraction, lc);
        registry!(@prod $r, $m, $s, $a, $b, "rc", RightContraction, rc);
        registry!(@prod $r, $m, $s, $a, $b, "sp", ScalarProduct, sp);
        registry!(@prod $r, $m, $s, $a, $b, "regressive", RegressiveProduct, regressive);
        registry!(@prod $r, $m, $s, $a, $b, "commutator", CommutatorProduct, commutator);
        registry!(@prod $r, $m, $s, $a, $b, "anticommutator", AnticommutatorProduct, anticommutator);
    )* };
    (@prod $r:ident, $m:ident, $s:ty, $a:ident, $b:ident, $name:literal, $tr:ident, $f:ident) => {
        $r.add($name, &[stringify!($a), stringify!($b)], |p| {
            let (a, b): ($m::$a<$s>, $m::$b<$s>) = ($crate::load(&p[0]), $crate::load(&p[1]));
            $crate::store($crate::ops::$tr::$f(&a, &b))
        });
    };
    (@unary $r:ident, $m:ident, $s:ty, $t:ident) => {
        registry!(@un $r, $m, $s, $t, "reverse", reverse);
        registry!(@un $r, $m, $s, $t, "grade_involution", grade_involution);
        registry!(@un $r, $m, $s, $t, "conjugate", conjugate);
        registry!(@un $r, $m, $s, $t, "dual", dual);
        registry!(@un $r, $m, $s, $t, "undual", undual);
        $r.add("norm_squared", &[stringify!($t)], |p| vec![$crate::load::<$m::$t<$s>, $s>(&p[0]).norm_squared()]);
    };
    (@closed $r:ident, $m:ident, $s:ty, $b:ident, $ev:ident) => {
        $r.add("exp", &[stringify!($b)], |p| $crate::store($crate::load::<$m::$b<$s>, $s>(&p[0]).exp()));
        $r.add("log_unit", &[stringify!($ev)], |p| $crate::store($crate::load::<$m::$ev<$s>, $s>(&p[0]).log_unit().unwrap()));
        $r.add("normalize", &[stringify!($ev)], |p| $crate::store($crate::load::<$m::$ev<$s>, $s>(&p[0]).normalize().unwrap()));
    };
    (@un $r:ident, $m:ident, $s:ty, $t:ident, $name:literal, $f:ident) => {
        $r.add($name, &[stringify!($t)], |p| $crate::store($crate::load::<$m::$t<$s>, $s>(&p[0]).$f()));
    };
    (@actions $r:ident, $m:ident, $s:ty; $all:tt; $($v:ident),*) => { $( registry!(@act $r, $m, $s, $v; $all); )* };
    (@act $r:ident, $m:ident, $s:ty, $v:ident; [$($x:ident),*]) => { $(
        $r.add("sandwich", &[stringify!($v), stringify!($x)], |p| {
            let (v, x): ($m::$v<$s>, $m::$x<$s>) = ($crate::load(&p[0]), $crate::load(&p[1]));
            $crate::store(v.sandwich(&x))
        });
        $r.add("apply", &[stringify!($v), stringify!($x)], |p| {
            let (v, x): ($m::$v<$s>, $m::$x<$s>) = ($crate::load(&p[0]), $crate::load(&p[1]));
            $crate::store(v.apply(&x))
        });
        $r.add("sandwich_unit", &[stringify!($v), stringify!($x)], |p| {
            let (v, x): ($m::$v<$s>, $m::$x<$s>) = ($crate::load(&p[0]), $crate::load(&p[1]));
            $crate::store(v.sandwich_unit(&x))
        });
        $r.add("apply_unit", &[stringify!($v), stringify!($x)], |p| {
            let (v, x): ($m::$v<$s>, $m::$x<$s>) = ($crate::load(&p[0]), $crate::load(&p[1]));
            $crate::store(v.apply_unit(&x))
        });
    )* };
}

/// The plan of a declaration given as `gam codegen --types` text.
///
/// ```
/// let plan = gam_lang_tests::plan("g3", algebra_core::Basis::Blade, "Rotor=even", "g3");
/// assert_eq!(plan.spec.types[0].name, "Rotor");
/// ```
pub fn plan(algebra: &str, basis: Basis, types: &str, module: &str) -> Plan {
    let alg = Algebra::builtin(algebra).expect("a built-in algebra");
    let types = ModuleSpec::parse_types(types, &alg).expect("valid types");
    Plan::new(ModuleSpec::new(module, alg.metric().clone(), basis, types).expect("a valid spec")).expect("a plan")
}

/// A Rust kernel: the parameters' fields in, the result's fields out.
pub type RustKernel<S> = Box<dyn Fn(&[Vec<S>]) -> Vec<S>>;

/// The Rust kernels of one module, keyed by operation name and parameter type names.
pub struct Registry<S> {
    /// The kernels.
    pub kernels: HashMap<(String, Vec<String>), RustKernel<S>>,
    /// Each type's basis names in storage order (`ELEMENTS`).
    pub elements: HashMap<String, Vec<String>>,
}

impl<S> Default for Registry<S> {
    fn default() -> Self {
        Registry { kernels: HashMap::new(), elements: HashMap::new() }
    }
}

impl<S: Copy + 'static> Registry<S> {
    /// Registers a kernel.
    pub fn add(&mut self, op: &str, params: &[&str], f: impl Fn(&[Vec<S>]) -> Vec<S> + 'static) {
        self.kernels.insert((op.to_string(), params.iter().map(|p| p.to_string()).collect()), Box::new(f));
    }

    /// The Rust kernel of an emitted kernel.
    pub fn get(&self, plan: &Plan, k: &Kernel) -> Option<&RustKernel<S>> {
        let params = k.params.iter().map(|&i| plan.spec.types[i].name.clone()).collect();
        self.kernels.get(&(k.op.name().to_string(), params))
    }
}

/// A value of a generated type from its fields.
pub fn load<A: Default + IndexMut<usize, Output = S>, S: Copy>(fields: &[S]) -> A {
    let mut a = A::default();
    for (i, x) in fields.iter().enumerate() {
        a[i] = *x;
    }
    a
}

/// The fields of a generated value.
pub fn store<O: IntoIterator<Item = S>, S>(o: O) -> Vec<S> {
    o.into_iter().collect()
}

/// Deterministic pseudo-random numbers in `[-2, 2)` (splitmix64), so a failure reproduces.
pub struct Numbers(u64);

impl Numbers {
    /// A sequence from a seed.
    pub fn new(seed: u64) -> Numbers {
        Numbers(seed)
    }

    /// The next number.
    pub fn next_f64(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64 * 4.0 - 2.0
    }
}

/// Whether `op` is a closed form (`exp`, `log_unit`, `normalize`): its kernels call `sqrt`,
/// `sin`, `cos` and `atan2`, so other languages agree within rounding, not bit for bit.
pub fn is_closed(op: &str) -> bool {
    matches!(op, "exp" | "log_unit" | "normalize")
}

/// The arguments of one call of `k`: every field from `numbers` (in `[-2, 2)`). For a closed
/// form the input is scaled by `1e-4` when `small` (the factors' series branch) and the scalar
/// part of an even input set to 1 (so the angle is the sample's); `log_unit` gets the registry's
/// `normalize` of that (a unit element, its domain).
pub fn arguments<S: Copy + 'static>(
    plan: &Plan,
    reg: &Registry<S>,
    k: &Kernel,
    numbers: &mut Numbers,
    small: bool,
    from_f64: impl Fn(f64) -> S,
) -> Vec<Vec<S>> {
    let closed = is_closed(k.op.name());
    let scale = if closed && small { 1e-4 } else { 1.0 };
    let (params, _) = shape(plan, k);
    let mut args: Vec<Vec<S>> =
        params.iter().map(|&n| (0..n).map(|_| from_f64(scale * numbers.next_f64())).collect()).collect();
    if closed && let Some(one) = plan.spec.types[k.params[0]].elements.iter().position(|m| *m == 0) {
        args[0][one] = from_f64(1.0);
    }
    if k.op.name() == "log_unit" {
        let key = ("normalize".to_string(), vec![plan.spec.types[k.params[0]].name.clone()]);
        args[0] = reg.kernels.get(&key).expect("normalize registered with log_unit")(&args);
    }
    args
}

/// The number of fields of every parameter and of the result of a kernel.
pub fn shape(plan: &Plan, k: &Kernel) -> (Vec<usize>, usize) {
    let n = |i: usize| plan.spec.types[i].elements.len();
    let out = match &k.output {
        Output::Type(o, _) => n(*o),
        Output::Scalar(_) => 1,
    };
    (k.params.iter().map(|&i| n(i)).collect(), out)
}

/// A C program that includes `header`, reads `samples` inputs per kernel from standard input
/// (the fields as the hexadecimal bits of `double`s, or of `float`s with `float`), calls each
/// kernel and prints the result's fields the same way, one line per call.
pub fn c_driver(plan: &Plan, kernels: &[Kernel], header: &str, samples: usize, float: bool) -> String {
    let (scalar, bits, fmt, sfx) =
        if float { ("float", "unsigned int", "%x", "f") } else { ("double", "unsigned long long", "%llx", "") };
    // on short input `get` complains and returns 0; the Rust side then sees a short output
    let mut c = format!(
        "#include <stdio.h>\n#include <string.h>\n#include \"{header}\"\n\
         static {scalar} get(void) {{ {bits} u = 0; {scalar} v; if (scanf(\"{fmt}\", &u) != 1) fprintf(stderr, \"short input\\n\"); memcpy(&v, &u, sizeof v); return v; }}\n\
         static void put({scalar} v) {{ {bits} u; memcpy(&u, &v, sizeof v); printf(\"{fmt} \", u); }}\n\
         int main(void) {{\n    int i;\n"
    );
    let fields = field_names(plan);
    for k in kernels {
        let _ = writeln!(c, "    for (i = 0; i < {samples}; i++) {{");
        let mut args = Vec::new();
        for (p, &ty) in k.params.iter().enumerate() {
            let _ = writeln!(c, "        {}{sfx} a{p};", type_name(plan, ty));
            for f in &fields[ty] {
                let _ = writeln!(c, "        a{p}.{f} = get();");
            }
            args.push(format!("a{p}"));
        }
        let call = format!("{}{sfx}({})", function_name(plan, k), args.join(", "));
        match &k.output {
            Output::Type(o, _) => {
                let _ = writeln!(c, "        {{ {}{sfx} r = {call};", type_name(plan, *o));
                for f in &fields[*o] {
                    let _ = writeln!(c, "          put(r.{f});");
                }
                let _ = writeln!(c, "        }}");
            }
            Output::Scalar(_) => {
                let _ = writeln!(c, "        put({call});");
            }
        }
        let _ = writeln!(c, "        printf(\"\\n\");\n    }}");
    }
    c.push_str("    return 0;\n}\n");
    c
}

/// Compiles `files` (name, text) in a fresh directory with the system C compiler (`CC`, else
/// `cc`), C99 at optimisation level `opt` (`-O0`, `-O2`: the results do not depend on it),
/// without contraction of multiply-adds, linked with libm, runs the program on `input` and
/// returns its output.
///
/// # Panics
/// When the compiler is missing, the code does not compile or the program fails.
pub fn compile_and_run(name: &str, files: &[(&str, &str)], main: &str, input: &str, opt: &str) -> String {
    use std::io::Write as _;
    let dir = std::env::temp_dir().join(format!("gam-lang-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    for (file, text) in files {
        std::fs::write(dir.join(file), text).expect("write a source file");
    }
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".to_string());
    let exe = dir.join("run");
    let status = std::process::Command::new(&cc)
        .args(["-std=c99", opt, "-ffp-contract=off", "-Wall", "-Wextra", "-Werror", "-pedantic", "-o"])
        .arg(&exe)
        .arg(dir.join(main))
        .arg("-lm")
        .status()
        .unwrap_or_else(|e| panic!("the C compiler `{cc}` did not start: {e}"));
    assert!(status.success(), "{main} did not compile (sources in {})", dir.display());
    let mut child = std::process::Command::new(&exe)
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .expect("run the compiled program");
    let mut stdin = child.stdin.take().expect("stdin");
    let input = input.to_string();
    let writer = std::thread::spawn(move || stdin.write_all(input.as_bytes()));
    let out = child.wait_with_output().expect("the program's output");
    writer.join().expect("the writer").expect("write the input");
    assert!(out.status.success(), "the program failed");
    let _ = std::fs::remove_dir_all(&dir);
    String::from_utf8(out.stdout).expect("ASCII output")
}
