// The value semantics and the product operators of a standalone file, written once as macros
// instead of one copy of the same impl blocks per type (per pair). Not a module of
// algebra-codegen: `standalone.rs` parses this text, puts it at the top of every `gam codegen
// --standalone` file and invokes the macros once per type and once per product; the CLI prints
// the macros as written here (`standalone::restore_macros`). Each macro expands to what the
// `algebra!` macro emits per type (`emit/value.rs` and `emit/mod.rs`), with the same bounds.

/// The value semantics every type of this file shares (one definition instead of a copy per
/// type): `LEN`, `new`, `zero`, `one` (for a type holding the scalar), `scale`, the basis
/// elements (`Motor::e12()`), arrays (`to_array`, `into_array`, `from_array`, `each_ref`, `From`
/// both ways), `Index`/`IndexMut`, iteration (`iter`, `iter_mut`, `IntoIterator` by value and by
/// reference), `Default` (zero), `Display` (`1 + 2*e12`), `Debug` (`Motor(1 + 2*e12)`), `+`,
/// `-` and negation on values and references, `x * s` and `x / s` for a scalar `s` (also on
/// `&x`), `s * x` for `f32` and `f64`, and `+=`, `-=`, `*= s`, `/= s`. Coefficients are in
/// the order of the type's `ELEMENTS`.
macro_rules! value_type {
    ($ty:ident[$n:literal] { $($f:ident),* } basis { $($e:ident),* } $(one: $one:ident)?) => {
        impl<T: Ring> $ty<T> {
            /// The number of coefficients.
            pub const LEN: usize = $n;

            /// A value from its coefficients, in the order of [`Self::ELEMENTS`].
            #[allow(clippy::too_many_arguments)]
            pub const fn new($($f: T),*) -> Self {
                $ty { $($f),* }
            }

            /// Zero.
            pub fn zero() -> Self {
                $ty { $($f: T::zero()),* }
            }

            $(
                /// The identity element.
                pub fn one() -> Self {
                    $ty { $one: T::one(), ..Self::zero() }
                }
            )?

            $(
                #[doc = concat!("The basis element `", stringify!($e), "` (coefficient 1, every other coefficient 0).")]
                pub fn $e() -> Self {
                    $ty { $e: T::one(), ..Self::zero() }
                }
            )*

            /// Every coefficient multiplied by `s`.
            pub fn scale(&self, s: &T) -> Self {
                $ty { $($f: self.$f.mul_ref(s)),* }
            }

            /// The coefficients in the order of [`Self::ELEMENTS`] (cloned).
            pub fn to_array(&self) -> [T; $n] {
                [$(self.$f.clone()),*]
            }

            /// The coefficients in the order of [`Self::ELEMENTS`] (moved out).
            pub fn into_array(self) -> [T; $n] {
                [$(self.$f),*]
            }

            /// A value from its coefficients in the order of [`Self::ELEMENTS`].
            pub fn from_array(a: [T; $n]) -> Self {
                let [$($f),*] = a;
                $ty { $($f),* }
            }

            /// References to the coefficients, in the order of [`Self::ELEMENTS`].
            pub fn each_ref(&self) -> [&T; $n] {
                [$(&self.$f),*]
            }

            /// An iterator over references to the coefficients, in the order of [`Self::ELEMENTS`].
            pub fn iter(&self) -> ::core::array::IntoIter<&T, $n> {
                [$(&self.$f),*].into_iter()
            }

            /// An iterator over mutable references to the coefficients.
            pub fn iter_mut(&mut self) -> ::core::array::IntoIter<&mut T, $n> {
                [$(&mut self.$f),*].into_iter()
            }
        }

        impl<T: Ring> ::core::default::Default for $ty<T> {
            /// Zero.
            fn default() -> Self {
                Self::zero()
            }
        }

        impl<T: Ring> ::core::convert::From<[T; $n]> for $ty<T> {
            fn from(a: [T; $n]) -> Self {
                Self::from_array(a)
            }
        }

        impl<T: Ring> ::core::convert::From<$ty<T>> for [T; $n] {
            fn from(x: $ty<T>) -> Self {
                x.into_array()
            }
        }

        impl<T: Ring> ::core::ops::Index<usize> for $ty<T> {
            type Output = T;
            /// The coefficient at position `i` of [`Self::ELEMENTS`]; panics if `i >= LEN`, like
            /// an array.
            fn index(&self, i: usize) -> &T {
                match self.iter().nth(i) {
                    Some(c) => c,
                    None => panic!("index {} out of range for {} (length {})", i, stringify!($ty), $n),
                }
            }
        }

        impl<T: Ring> ::core::ops::IndexMut<usize> for $ty<T> {
            fn index_mut(&mut self, i: usize) -> &mut T {
                match self.iter_mut().nth(i) {
                    Some(c) => c,
                    None => panic!("index {} out of range for {} (length {})", i, stringify!($ty), $n),
                }
            }
        }

        impl<T: Ring> ::core::iter::IntoIterator for $ty<T> {
            type Item = T;
            type IntoIter = ::core::array::IntoIter<T, $n>;
            fn into_iter(self) -> Self::IntoIter {
                self.into_array().into_iter()
            }
        }

        impl<'a, T: Ring> ::core::iter::IntoIterator for &'a $ty<T> {
            type Item = &'a T;
            type IntoIter = ::core::array::IntoIter<&'a T, $n>;
            fn into_iter(self) -> Self::IntoIter {
                self.iter()
            }
        }

        impl<T: Ring> ::core::fmt::Display for $ty<T> {
            /// A sum of basis elements: `1 + 1/2*e1inf`; `0` for zero.
            fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
                let terms = Self::ELEMENTS.iter().zip(self.iter());
                let nonzero = terms.filter(|(_, c)| !c.is_exact_zero());
                f.write_str(&join_terms(nonzero.map(|(n, c)| format_term(&c.to_string(), n))))
            }
        }

        impl<T: Ring> ::core::fmt::Debug for $ty<T> {
            fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
                write!(f, "{}({})", stringify!($ty), self)
            }
        }

        impl<T: Ring> ::core::ops::Add for $ty<T> {
            type Output = Self;
            fn add(self, rhs: Self) -> Self {
                $ty { $($f: self.$f + rhs.$f),* }
            }
        }

        impl<T: Ring> ::core::ops::Add for &$ty<T> {
            type Output = $ty<T>;
            fn add(self, rhs: Self) -> $ty<T> {
                $ty { $($f: self.$f.add_ref(&rhs.$f)),* }
            }
        }

        impl<T: Ring> ::core::ops::Sub for $ty<T> {
            type Output = Self;
            fn sub(self, rhs: Self) -> Self {
                $ty { $($f: self.$f - rhs.$f),* }
            }
        }

        impl<T: Ring> ::core::ops::Sub for &$ty<T> {
            type Output = $ty<T>;
            fn sub(self, rhs: Self) -> $ty<T> {
                $ty { $($f: self.$f.sub_ref(&rhs.$f)),* }
            }
        }

        impl<T: Ring> ::core::ops::Neg for $ty<T> {
            type Output = Self;
            fn neg(self) -> Self {
                $ty { $($f: -self.$f),* }
            }
        }

        impl<T: Ring> ::core::ops::Neg for &$ty<T> {
            type Output = $ty<T>;
            fn neg(self) -> $ty<T> {
                $ty { $($f: self.$f.neg_ref()),* }
            }
        }

        impl<T: Ring> ::core::ops::Mul<T> for $ty<T> {
            type Output = Self;
            /// `x * s`: every coefficient multiplied by `s`.
            fn mul(self, s: T) -> Self {
                $ty { $($f: self.$f * &s),* }
            }
        }

        impl<T: Ring> ::core::ops::Mul<T> for &$ty<T> {
            type Output = $ty<T>;
            fn mul(self, s: T) -> $ty<T> {
                self.scale(&s)
            }
        }

        impl<T: Field> ::core::ops::Div<T> for $ty<T> {
            type Output = Self;
            /// `x / s`: every coefficient divided by `s`.
            fn div(self, s: T) -> Self {
                $ty { $($f: self.$f.div_ref(&s)),* }
            }
        }

        impl<T: Field> ::core::ops::Div<T> for &$ty<T> {
            type Output = $ty<T>;
            fn div(self, s: T) -> $ty<T> {
                $ty { $($f: self.$f.div_ref(&s)),* }
            }
        }

        impl<T: Ring> ::core::ops::AddAssign for $ty<T> {
            fn add_assign(&mut self, rhs: Self) {
                $(self.$f.add_assign_ref(&rhs.$f);)*
            }
        }

        impl<T: Ring> ::core::ops::SubAssign for $ty<T> {
            fn sub_assign(&mut self, rhs: Self) {
                $(self.$f.sub_assign_ref(&rhs.$f);)*
            }
        }

        impl<T: Ring> ::core::ops::MulAssign<T> for $ty<T> {
            fn mul_assign(&mut self, s: T) {
                $(self.$f = self.$f.mul_ref(&s);)*
            }
        }

        impl<T: Field> ::core::ops::DivAssign<T> for $ty<T> {
            fn div_assign(&mut self, s: T) {
                $(self.$f = self.$f.div_ref(&s);)*
            }
        }

        scalar_times!($ty { $($f),* } f32);
        scalar_times!($ty { $($f),* } f64);
    };
}

/// `s * x` for a value or reference `x` of a type of this file and a scalar `s` of a float
/// type (every coefficient multiplied by `s`).
macro_rules! scalar_times {
    ($ty:ident { $($f:ident),* } $float:ident) => {
        impl ::core::ops::Mul<$ty<$float>> for $float {
            type Output = $ty<$float>;
            /// `s * x`: every coefficient multiplied by `s`.
            fn mul(self, x: $ty<$float>) -> $ty<$float> {
                $ty { $($f: self * x.$f),* }
            }
        }

        impl ::core::ops::Mul<&$ty<$float>> for $float {
            type Output = $ty<$float>;
            fn mul(self, x: &$ty<$float>) -> $ty<$float> {
                $ty { $($f: self * x.$f),* }
            }
        }
    };
}

/// The operator of a product (`*` for the geometric product, `^` outer, `|` left contraction,
/// `&` the join) on values and references, for every listed `Lhs op Rhs = Out`: `a * b`,
/// `&a * &b`, `a * &b` and `&a * b` all call the product's kernel (`GeometricProduct::gp`).
macro_rules! product_operators {
    ($op:ident::$method:ident => $product:ident::$kernel:ident: $($lhs:ident $sym:tt $rhs:ident = $out:ident),* $(,)?) => {$(
        impl<T: Ring> ::core::ops::$op<&$rhs<T>> for &$lhs<T> {
            type Output = $out<T>;
            fn $method(self, rhs: &$rhs<T>) -> $out<T> {
                $product::$kernel(self, rhs)
            }
        }

        impl<T: Ring> ::core::ops::$op<$rhs<T>> for $lhs<T> {
            type Output = $out<T>;
            fn $method(self, rhs: $rhs<T>) -> $out<T> {
                $product::$kernel(&self, &rhs)
            }
        }

        impl<T: Ring> ::core::ops::$op<&$rhs<T>> for $lhs<T> {
            type Output = $out<T>;
            fn $method(self, rhs: &$rhs<T>) -> $out<T> {
                $product::$kernel(&self, rhs)
            }
        }

        impl<T: Ring> ::core::ops::$op<$rhs<T>> for &$lhs<T> {
            type Output = $out<T>;
            fn $method(self, rhs: $rhs<T>) -> $out<T> {
                $product::$kernel(self, &rhs)
            }
        }
    )*};
}
