//! The names of generated code, the same in every language: a field is named after its basis
//! element (`scalar` for `1`), a type's functions use its name in snake case, and each product
//! and unary map has one method name.

use algebra_core::tables::{Product, Unary};

/// The field name of a basis element: `scalar` for `1`, else the basis name (`e12`).
pub fn field_name(name: &str) -> String {
    if name == "1" { "scalar".to_string() } else { name.to_string() }
}

/// `PoseBivector` as `pose_bivector`.
pub fn snake(name: &str) -> String {
    let mut out = String::new();
    for (i, c) in name.chars().enumerate() {
        if c.is_ascii_uppercase() {
            if i > 0 {
                out.push('_');
            }
            out.push(c.to_ascii_lowercase());
        } else {
            out.push(c);
        }
    }
    out
}

/// The method name of a product in generated code (`gp`, `op`, `lc`, `rc`, `sp`,
/// `regressive`, `commutator`, `anticommutator`).
pub fn product_name(p: Product) -> &'static str {
    match p {
        Product::Geometric => "gp",
        Product::Outer => "op",
        Product::LeftContraction => "lc",
        Product::RightContraction => "rc",
        Product::Scalar => "sp",
        Product::Regressive => "regressive",
        Product::Commutator => "commutator",
        Product::Anticommutator => "anticommutator",
    }
}

/// The method name of a unary operation in generated code.
pub fn unary_name(op: Unary) -> &'static str {
    match op {
        Unary::Reverse => "reverse",
        Unary::GradeInvolution => "grade_involution",
        Unary::CliffordConjugate => "conjugate",
        Unary::Dual => "dual",
        Unary::Undual => "undual",
        Unary::BasisReverse => "basis_reverse",
    }
}

/// The unary operations that get kernels.
pub const UNARY_OPS: [Unary; 5] =
    [Unary::Reverse, Unary::GradeInvolution, Unary::CliffordConjugate, Unary::Dual, Unary::Undual];
