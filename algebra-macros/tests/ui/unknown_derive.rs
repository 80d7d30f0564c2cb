// `derive` accepts only `serde`.
algebra_macros::algebra! {
    pub mod bad {
        metric builtin "g3";
        derive bytemuck;
        types {
            Vector = grade 1;
        }
    }
}

fn main() {}
