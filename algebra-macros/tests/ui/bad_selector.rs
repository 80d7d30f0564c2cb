algebra_macros::algebra! {
    pub mod bad {
        metric builtin "g3";
        types {
            Rotor = evens;
        }
    }
}

fn main() {}
