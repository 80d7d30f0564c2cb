//! The precomputed constrained kernels (`src/constraint/precomputed.txt`, read by the GMP-free
//! `algebra!` macro) are exactly what the Gröbner reduction computes today, for every
//! constrained module of the predefined algebras (`gam-algebras`) and of the DSL's tests, read
//! from their `algebra!` invocations. Regenerate with
//! `BLESS=1 cargo test -p algebra-codegen --features constraints --test constraint_table`
//! after changing a constrained declaration or the reduction.

use algebra_codegen::constraint::{methods, requests, table};
use algebra_codegen::{ModuleSpec, plan::Plan};
use algebra_core::{Algebra, Basis};

/// The files whose `algebra!` modules declare constraints: the predefined modules
/// (`gam-algebras`) and the DSL's test modules. Their declarations are read from the files
/// themselves, so this table cannot drift from them.
const SOURCES: &[&str] = &["../algebras/src/generated.rs", "../algebras/tests/constrained.rs"];

/// (builtin algebra, basis, types in the `gam codegen --types` syntax) of every `algebra!`
/// module in [`SOURCES`] with a constrained type (`where ...`), in file order.
fn modules() -> Vec<(String, Basis, String)> {
    let mut out = Vec::new();
    for file in SOURCES {
        let path = format!("{}/{file}", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
        for item in syn::parse_file(&text).unwrap_or_else(|e| panic!("{path}: {e}")).items {
            if let syn::Item::Macro(m) = item
                && m.mac.path.segments.last().is_some_and(|s| s.ident == "algebra")
                && let Some(module) = module_decl(m.mac.tokens)
                && module.2.contains(" where ")
            {
                out.push(module);
            }
        }
    }
    assert!(out.len() >= 5, "constrained modules found: {out:?}");
    out
}

/// The builtin metric, basis and `--types` text of one `algebra!` invocation's tokens; `None`
/// if it declares no `types` block. A constrained module must use `metric builtin "..."`.
fn module_decl(tokens: proc_macro2::TokenStream) -> Option<(String, Basis, String)> {
    use proc_macro2::{Delimiter, TokenTree as Tt};
    let body = tokens.into_iter().find_map(|t| match t {
        Tt::Group(g) if g.delimiter() == Delimiter::Brace => Some(g.stream()),
        _ => None,
    })?;
    let body: Vec<Tt> = body.into_iter().collect();
    let (mut metric, mut basis, mut types) = (None, Basis::Blade, None);
    for (i, t) in body.iter().enumerate() {
        match (t, body.get(i + 1), body.get(i + 2)) {
            (Tt::Ident(k), Some(Tt::Ident(b)), Some(Tt::Literal(name))) if k == "metric" && b == "builtin" => {
                metric = Some(name.to_string().trim_matches('"').to_string());
            }
            (Tt::Ident(k), Some(Tt::Ident(b)), _) if k == "basis" && b == "product" => basis = Basis::Product,
            (Tt::Ident(k), Some(Tt::Group(g)), _) if k == "types" => types = Some(types_text(g.stream())),
            _ => {}
        }
    }
    let types = types?;
    Some((metric.unwrap_or_else(|| panic!("not a builtin metric: {types}")), basis, types))
}

/// The body of the DSL's `types { ... }` (`Name = selector [where kind];`, doc comments
/// skipped) in the `--types` syntax `Name=selector [where kind];...`.
fn types_text(types: proc_macro2::TokenStream) -> String {
    use proc_macro2::TokenTree as Tt;
    let mut text = String::new();
    let mut skip_attr = false;
    for t in types {
        match t {
            // doc comments arrive as `# [doc = "..."]`
            Tt::Punct(p) if p.as_char() == '#' => skip_attr = true,
            Tt::Group(_) if skip_attr => skip_attr = false,
            Tt::Group(g) => {
                let items: Vec<String> = g.stream().into_iter().map(|t| t.to_string()).filter(|s| s != ",").collect();
                text.push_str(&items.join(","));
            }
            Tt::Punct(p) if p.as_char() == ';' => text.push(';'),
            Tt::Punct(p) => text.push(p.as_char()),
            Tt::Ident(i) if i == "where" => text.push_str(" where "),
            Tt::Ident(i) => text.push_str(&i.to_string()),
            Tt::Literal(l) => text.push_str(&l.to_string()),
        }
    }
    text
}

fn plan(alg: &str, basis: Basis, types: &str) -> Plan {
    let alg = Algebra::builtin(alg).unwrap();
    let types = ModuleSpec::parse_types(types, &alg).unwrap();
    Plan::new(ModuleSpec::new("m", alg.metric().clone(), basis, types).unwrap()).unwrap()
}

#[test]
fn the_precomputed_table_is_up_to_date() {
    let mut text = String::new();
    let mut seen = std::collections::BTreeSet::new();
    for (alg, basis, types) in modules() {
        let plan = plan(&alg, basis, &types);
        for r in requests(&plan) {
            let key = table::key(&plan.spec, r);
            if seen.insert(key.clone()) {
                let k = algebra_codegen::constraint::compute(&plan.spec, r).unwrap();
                text.push_str(&table::entry(&key, &k));
            }
        }
    }
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/src/constraint/precomputed.txt");
    if std::env::var_os("BLESS").is_some() {
        std::fs::write(path, &text).unwrap();
    }
    assert_eq!(std::fs::read_to_string(path).unwrap(), text, "regenerate with BLESS=1");
}

/// A kernel read back from the table is the computed one, spec-dependent fields included.
#[test]
fn table_kernels_equal_computed_kernels() {
    for (alg, basis, types) in modules() {
        let plan = plan(&alg, basis, &types);
        for r in requests(&plan) {
            let from_table = algebra_codegen::constraint::kernel(&plan.spec, r).unwrap();
            assert_eq!(from_table, algebra_codegen::constraint::compute(&plan.spec, r).unwrap(), "{r:?}");
        }
        assert!(methods(&plan).is_ok());
    }
}
