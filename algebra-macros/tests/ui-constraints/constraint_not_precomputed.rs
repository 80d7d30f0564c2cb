use algebra_macros::algebra;

// A unit rotor of G3 is not in the precomputed table. Built without algebra-macros'
// `constraints` feature: a compile error naming the kernel and the remedies (the .stderr file);
// with it: the kernel is computed at expansion time and this compiles (tests/ui.rs).
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
