algebra_macros::algebra! {
    pub mod bad {
        metric builtin "g3";
        types {
            Rotor = [1, e12, e13, e12];
        }
    }
}

fn main() {}
