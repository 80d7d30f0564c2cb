//! C99: one header of `static inline` functions over structs passed by value, in `double`
//! and `float` (names ending in `f`). Valid C++ too (no compound literals or designated
//! initialisers).

use super::{Dialect, Function, Scalar, push_line};

/// The C dialect.
pub struct C;

impl Dialect for C {
    fn scalars(&self) -> &'static [Scalar] {
        &[Scalar::F64, Scalar::F32]
    }
    fn scalar(&self, s: Scalar) -> &'static str {
        match s {
            Scalar::F64 => "double",
            Scalar::F32 => "float",
        }
    }
    fn suffix(&self, s: Scalar) -> &'static str {
        match s {
            Scalar::F64 => "",
            Scalar::F32 => "f",
        }
    }
    fn comment(&self, text: &str) -> String {
        format!("/* {} */\n", text.replace("*/", "* /"))
    }
    fn prologue(&self, module: &str) -> String {
        let guard = format!("GAM_{}_H", module.to_ascii_uppercase());
        format!("#ifndef {guard}\n#define {guard}\n\n")
    }
    fn epilogue(&self, module: &str) -> String {
        format!("#endif /* GAM_{}_H */\n", module.to_ascii_uppercase())
    }
    fn literal(&self, s: Scalar, value: &str) -> String {
        match s {
            Scalar::F64 => value.to_string(),
            Scalar::F32 => format!("{value}f"),
        }
    }
    fn structure(&self, s: Scalar, name: &str, fields: &[String]) -> String {
        let ty = self.scalar(s);
        let mut out = format!("typedef struct {name} {{\n");
        for f in fields {
            push_line(&mut out, "    ", &format!("{ty} {f};"));
        }
        out.push_str(&format!("}} {name};\n"));
        out
    }
    fn function(&self, _: Scalar, f: &Function<'_>) -> String {
        let params: Vec<String> = f.params.iter().map(|(p, t)| format!("{t} {p}")).collect();
        let mut out = self.comment(f.doc);
        out.push_str(&format!("static inline {} {}({}) {{\n", f.ret, f.name, params.join(", ")));
        for p in &f.unused {
            push_line(&mut out, "    ", &format!("(void){p};"));
        }
        for (i, (t, e)) in f.lets.iter().enumerate() {
            push_line(&mut out, "    ", &format!("const {t} t{i} = {e};"));
        }
        match &f.fields {
            Some(fields) => {
                push_line(&mut out, "    ", &format!("{} r;", f.ret));
                for (field, v) in fields.iter().zip(&f.values) {
                    push_line(&mut out, "    ", &format!("r.{field} = {v};"));
                }
                push_line(&mut out, "    ", "return r;");
            }
            None => push_line(&mut out, "    ", &format!("return {};", f.values[0])),
        }
        out.push_str("}\n");
        out
    }
    fn math(&self, s: Scalar, f: &str) -> String {
        match s {
            Scalar::F64 => f.to_string(),
            Scalar::F32 => format!("{f}f"),
        }
    }
    fn triple(&self, s: Scalar, module: &str) -> String {
        format!("{module}_Triple{}", self.suffix(s))
    }
    fn triple_def(&self, s: Scalar, module: &str) -> String {
        let t = self.triple(s, module);
        format!("#include <math.h>\n\ntypedef struct {t} {{\n    {} x, y, z;\n}} {t};\n\n", self.scalar(s))
    }
    fn local(&self, ty: &str, name: &str, value: &str) -> String {
        format!("const {ty} {name} = {value};")
    }
    fn return_triple(&self, s: Scalar, module: &str, [x, y, z]: [&str; 3]) -> String {
        format!("{{ {} out; out.x = {x}; out.y = {y}; out.z = {z}; return out; }}", self.triple(s, module))
    }
    fn helper_head(&self, s: Scalar, module: &str, name: &str, params: &[&str]) -> String {
        let ty = self.scalar(s);
        let params: Vec<String> = params.iter().map(|p| format!("{ty} {p}")).collect();
        format!("static inline {} {name}({}) {{", self.triple(s, module), params.join(", "))
    }
}
