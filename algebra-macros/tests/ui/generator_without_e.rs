algebra_macros::algebra! {
    pub mod bad {
        generators { e1, x2 }
        metric { (e1, e1) = 1, (x2, x2) = 1 }
        types {
            Vector = grade 1;
        }
    }
}

fn main() {}
