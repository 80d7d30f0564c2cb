//! A user's conformal algebra `R^{4,1}` in the diagonal basis (`e4² = 1`, `e5² = -1`), shared
//! by `tests/closed_inv.rs` and `benches/closed_inv.rs`: its bivectors get the closed forms of
//! the invariant decomposition (`algebra_codegen::closed_inv`).

algebra_macros::algebra! {
    /// CGA R^{4,1}, declared by a user.
    pub mod cga41 {
        generators { e1, e2, e3, e4, e5 }
        metric { (e1, e1) = 1, (e2, e2) = 1, (e3, e3) = 1, (e4, e4) = 1, (e5, e5) = -1 }
        types {
            Bivector = grade 2;
            Motor = even;
        }
    }
}
