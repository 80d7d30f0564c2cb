//! Scalars with named symbols (today `Poly`, behind `rug`): what the generated
//! types' `symbolic(prefix)` constructor needs to name each coefficient.

use crate::scalar::Ring;

/// A ring whose elements include named symbols.
///
/// ```
/// # #[cfg(feature = "rug")] {
/// use algebra_core::{Poly, Symbolic};
/// assert_eq!(Poly::symbol("S12").to_string(), "S12");
/// assert_eq!(Poly::coefficient("S", "1").to_string(), "S");
/// assert_eq!(Poly::coefficient("S", "e123inf").to_string(), "S123inf");
/// # }
/// ```
pub trait Symbolic: Ring {
    /// The symbol `name`.
    fn symbol(name: &str) -> Self;

    /// The coefficient symbol of basis element `element` for `prefix`
    /// ([`coefficient_name`]: `S`, `S12`, `S1inf`, ...).
    fn coefficient(prefix: &str, element: &str) -> Self {
        Self::symbol(&coefficient_name(prefix, element))
    }
}

/// The coefficient symbol of basis element `name` for `prefix`: `prefix` for the scalar `1`,
/// otherwise `prefix` followed by the labels (`e12` -> `S12`), the names the CLI prints.
///
/// ```
/// use algebra_core::symbol::coefficient_name;
/// assert_eq!(coefficient_name("S", "1"), "S");
/// assert_eq!(coefficient_name("x", "e0"), "x0");
/// ```
pub fn coefficient_name(prefix: &str, name: &str) -> String {
    match name {
        "1" => prefix.to_string(),
        _ => format!("{prefix}{}", name.strip_prefix('e').unwrap_or(name)),
    }
}

#[cfg(feature = "rug")]
impl Symbolic for crate::Poly {
    fn symbol(name: &str) -> Self {
        crate::Poly::var(name)
    }
}
