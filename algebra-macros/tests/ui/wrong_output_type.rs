// The output type is chosen at expansion time: in g3 a vector times a vector is a rotor, and
// using it as a vector is a type error.
algebra_macros::algebra! {
    pub mod g3 {
        metric builtin "g3";
        types {
            Vector = grade 1;
            Rotor = even;
        }
    }
}

fn main() {
    let v = g3::Vector::<f64>::new(1.0, 2.0, 3.0);
    let _w: g3::Vector<f64> = &v * &v;
}
