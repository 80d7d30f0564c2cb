//! WGSL (`f32`): structs of `f32` fields (alignment 4, no padding, so an `array<T>` in a
//! storage buffer has the layout of the Rust `[T<f32>]`) and functions taking them by value.

use super::{Dialect, Function, Scalar, push_line};

/// The WGSL dialect.
pub struct Wgsl;

impl Dialect for Wgsl {
    fn scalars(&self) -> &'static [Scalar] {
        &[Scalar::F32]
    }
    fn scalar(&self, _: Scalar) -> &'static str {
        "f32"
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
        format!("{value}f")
    }
    fn structure(&self, _: Scalar, name: &str, fields: &[String]) -> String {
        let mut out = format!("struct {name} {{\n");
        for f in fields {
            push_line(&mut out, "    ", &format!("{f}: f32,"));
        }
        out.push_str("}\n");
        out
    }
    fn function(&self, _: Scalar, f: &Function<'_>) -> String {
        let params: Vec<String> = f.params.iter().map(|(p, t)| format!("{p}: {t}")).collect();
        let mut out = self.comment(f.doc);
        out.push_str(&format!("fn {}({}) -> {} {{\n", f.name, params.join(", "), f.ret));
        for (i, (_, e)) in f.lets.iter().enumerate() {
            push_line(&mut out, "    ", &format!("let t{i} = {e};"));
        }
        match &f.fields {
            Some(_) => {
                push_line(&mut out, "    ", &format!("return {}(", f.ret));
                for v in &f.values {
                    push_line(&mut out, "        ", &format!("{v},"));
                }
                push_line(&mut out, "    ", ");");
            }
            None => push_line(&mut out, "    ", &format!("return {};", f.values[0])),
        }
        out.push_str("}\n");
        out
    }
    fn math(&self, _: Scalar, f: &str) -> String {
        f.to_string()
    }
    fn triple(&self, _: Scalar, _module: &str) -> String {
        "vec3<f32>".to_string()
    }
    fn triple_def(&self, _: Scalar, _module: &str) -> String {
        String::new()
    }
    fn local(&self, _ty: &str, name: &str, value: &str) -> String {
        format!("let {name} = {value};")
    }
    fn return_triple(&self, _: Scalar, _module: &str, [x, y, z]: [&str; 3]) -> String {
        format!("return vec3<f32>({x}, {y}, {z});")
    }
    fn helper_head(&self, _: Scalar, _module: &str, name: &str, params: &[&str]) -> String {
        let params: Vec<String> = params.iter().map(|p| format!("{p}: f32")).collect();
        format!("fn {name}({}) -> vec3<f32> {{", params.join(", "))
    }
}
