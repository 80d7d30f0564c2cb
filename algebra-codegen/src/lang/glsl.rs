//! GLSL 4.50 (`float`): structs of `float` fields (in `std430` buffers an array of them has the
//! layout of the Rust `[T<f32>]`) and functions taking them by value. No `#version` line: the
//! file is meant to be included into a shader that has one.

use super::{Dialect, Function, Scalar, push_line};

/// The GLSL dialect.
pub struct Glsl;

impl Dialect for Glsl {
    fn scalars(&self) -> &'static [Scalar] {
        &[Scalar::F32]
    }
    fn scalar(&self, _: Scalar) -> &'static str {
        "float"
    }
    fn suffix(&self, _: Scalar) -> &'static str {
        ""
    }
    fn comment(&self, text: &str) -> String {
        format!("// {text}\n")
    }
    fn prologue(&self, _module: &str) -> String {
        String::new()
    }
    fn epilogue(&self, _module: &str) -> String {
        String::new()
    }
    fn literal(&self, _: Scalar, value: &str) -> String {
        value.to_string()
    }
    fn structure(&self, _: Scalar, name: &str, fields: &[String]) -> String {
        let mut out = format!("struct {name} {{\n");
        for f in fields {
            push_line(&mut out, "    ", &format!("float {f};"));
        }
        out.push_str("};\n");
        out
    }
    fn function(&self, _: Scalar, f: &Function<'_>) -> String {
        let params: Vec<String> = f.params.iter().map(|(p, t)| format!("{t} {p}")).collect();
        let mut out = self.comment(f.doc);
        out.push_str(&format!("{} {}({}) {{\n", f.ret, f.name, params.join(", ")));
        for (i, (t, e)) in f.lets.iter().enumerate() {
            push_line(&mut out, "    ", &format!("{t} t{i} = {e};"));
        }
        match &f.fields {
            Some(_) => {
                push_line(&mut out, "    ", &format!("return {}(", f.ret));
                let n = f.values.len();
                for (i, v) in f.values.iter().enumerate() {
                    let sep = if i + 1 < n { "," } else { "" };
                    push_line(&mut out, "        ", &format!("{v}{sep}"));
                }
                push_line(&mut out, "    ", ");");
            }
            None => push_line(&mut out, "    ", &format!("return {};", f.values[0])),
        }
        out.push_str("}\n");
        out
    }
    fn math(&self, _: Scalar, f: &str) -> String {
        // GLSL's two-argument arctangent is `atan(y, x)`
        if f == "atan2" { "atan".to_string() } else { f.to_string() }
    }
    fn triple(&self, _: Scalar, _module: &str) -> String {
        "vec3".to_string()
    }
    fn triple_def(&self, _: Scalar, _module: &str) -> String {
        String::new()
    }
    fn local(&self, ty: &str, name: &str, value: &str) -> String {
        format!("{ty} {name} = {value};")
    }
    fn return_triple(&self, _: Scalar, _module: &str, [x, y, z]: [&str; 3]) -> String {
        format!("return vec3({x}, {y}, {z});")
    }
    fn helper_head(&self, _: Scalar, _module: &str, name: &str, params: &[&str]) -> String {
        let params: Vec<String> = params.iter().map(|p| format!("float {p}")).collect();
        format!("vec3 {name}({}) {{", params.join(", "))
    }
}
