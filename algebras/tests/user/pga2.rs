//! A user's 2D PGA `R^{2,0,1}`, shared by `tests/closed_user.rs` and `benches/closed.rs`:
//! every bivector squares to a scalar (`-e12²`), translations to 0.

algebra_macros::algebra! {
    /// 2D PGA R^{2,0,1}, declared by a user.
    pub mod pga2 {
        generators { e0, e1, e2 }
        metric { (e1, e1) = 1, (e2, e2) = 1 }
        types {
            Line = grade 2;
            Motor = even;
        }
    }
}
