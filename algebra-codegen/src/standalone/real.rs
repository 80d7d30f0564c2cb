// `Real` for `f32` and `f64` through std, appended to a standalone file that has closed forms.
// Not a module of algebra-codegen: `standalone.rs` parses this text.

/// `Real` for a float type through std (the closed forms' scalar functions).
macro_rules! float_real {
    ($($t:ident),*) => {$(
        impl Real for $t {
            fn sqrt(&self) -> Self { $t::sqrt(*self) }
            fn exp(&self) -> Self { $t::exp(*self) }
            fn ln(&self) -> Self { $t::ln(*self) }
            fn sin(&self) -> Self { $t::sin(*self) }
            fn cos(&self) -> Self { $t::cos(*self) }
            fn sinh(&self) -> Self { $t::sinh(*self) }
            fn cosh(&self) -> Self { $t::cosh(*self) }
            fn atan2(&self, x: &Self) -> Self { $t::atan2(*self, *x) }
            fn atanh(&self) -> Self { $t::atanh(*self) }
            fn abs(&self) -> Self { $t::abs(*self) }
            fn to_f64(&self) -> f64 { f64::from(*self) }
            fn from_f64(x: f64) -> Self { x as $t }
            fn pi() -> Self { ::core::$t::consts::PI }
            fn is_finite(&self) -> bool { $t::is_finite(*self) }
        }
    )*};
}
float_real!(f32, f64);
