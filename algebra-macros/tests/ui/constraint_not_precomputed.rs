use algebra_macros::algebra;

// A unit rotor of G3 is not in the precomputed table, and this crate is built without its
// `constraints` feature: a compile error naming the kernel and the remedies.
algebra! {
    pub mod g3 {
        metric builtin "g3";
        types {
            Vector = grade 1;
            Rotor = even where unit;
        }
    }
}

fn main() {}
