use algebra_macros::algebra;

algebra! {
    pub mod g3 {
        metric builtin "g3";
        types {
            Rotor = even where round;
        }
    }
}

fn main() {}
