algebra_macros::algebra! {
    pub mod bad {
        metric builtin "g3";
        types {
            Rotor = even;
            Quaternion = [1, e12, e13, e23];
        }
    }
}

fn main() {}
