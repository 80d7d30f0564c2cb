algebra_macros::algebra! {
    pub mod bad {
        metric builtin "g4";
        types {
            Vector = grade 1;
        }
    }
}

fn main() {}
