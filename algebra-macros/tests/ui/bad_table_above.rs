algebra_macros::algebra! {
    pub mod bad {
        generators { e1, e2 }
        metric { (e1, e1) = 1, (e2, e2) = 1 }
        table_above many;
        types {
            Vector = grade 1;
        }
    }
}

fn main() {}
