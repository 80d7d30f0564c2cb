// The duplicate is not the last type: the error should point at the second `Vector`.
algebra_macros::algebra! {
    pub mod bad {
        generators { e1, e2, e3 }
        metric { (e1, e1) = 1, (e2, e2) = 1, (e3, e3) = 1 }
        types {
            Vector = grade 1;
            Vector = grade 2;
            Rotor = even;
            Multivector = all;
        }
    }
}

fn main() {}
