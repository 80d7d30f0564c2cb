//! Value semantics of generated types: `Copy` (derived, so only when `T: Copy`), `Default`,
//! arrays, indexing, iteration, scalar multiplication and division, compound assignment,
//! basis constants, mixed value/reference operators and the optional `serde` derive.
//!
//! These items are independent of the algebra: they depend only on each type's fields.

use super::{Names, ident, product_operator, product_trait};
use crate::plan::{BinaryKernel, Plan};
use proc_macro2::TokenStream;
use quote::quote;

/// Associated functions a basis constant must not shadow (a generator label could spell one).
const RESERVED: [&str; 3] = ["exp", "elements", "eq"];

/// `#[cfg_attr(feature = "serde", derive(Serialize, Deserialize))]` when the spec asks for it.
pub(super) fn serde_attribute(plan: &Plan) -> TokenStream {
    if plan.spec.serde {
        quote!(#[cfg_attr(feature = "serde", derive(::serde::Serialize, ::serde::Deserialize))])
    } else {
        quote!()
    }
}

/// The value-semantics items of type `i`.
pub(super) fn type_items(names: &Names, i: usize) -> TokenStream {
    let ty = &names.types[i];
    let fields = &names.fields[i];
    let n = fields.len();
    let idx: Vec<usize> = (0..n).collect();
    let constants =
        names.elements[i].iter().zip(&names.masks[i]).filter(|(e, m)| **m != 0 && !RESERVED.contains(&e.as_str())).map(
            |(e, &m)| {
                let f = ident(e);
                let vals = names.masks[i].iter().map(|&x| if x == m { quote!(T::one()) } else { quote!(T::zero()) });
                let doc = format!("The basis element `{e}` (coefficient 1, every other coefficient 0).");
                quote! {
                    #[doc = #doc]
                    pub fn #f() -> Self { #ty { #(#fields: #vals),* } }
                }
            },
        );
    let floats = [quote!(f32), quote!(f64)].into_iter().map(|f| {
        quote! {
            impl ::core::ops::Mul<#ty<#f>> for #f {
                type Output = #ty<#f>;
                /// `s * x`: every coefficient multiplied by `s`.
                fn mul(self, x: #ty<#f>) -> #ty<#f> { #ty { #(#fields: self * x.#fields),* } }
            }
            impl ::core::ops::Mul<&#ty<#f>> for #f {
                type Output = #ty<#f>;
                fn mul(self, x: &#ty<#f>) -> #ty<#f> { #ty { #(#fields: self * x.#fields),* } }
            }
        }
    });
    quote! {
        impl<T: __gam_engine::Ring> #ty<T> {
            /// The number of coefficients.
            pub const LEN: usize = #n;
            #(#constants)*

            /// The coefficients in the order of [`Self::ELEMENTS`] (cloned).
            pub fn to_array(&self) -> [T; #n] { [#(::core::clone::Clone::clone(&self.#fields)),*] }

            /// The coefficients in the order of [`Self::ELEMENTS`] (moved out).
            pub fn into_array(self) -> [T; #n] { [#(self.#fields),*] }

            /// A value from its coefficients in the order of [`Self::ELEMENTS`].
            pub fn from_array(a: [T; #n]) -> Self {
                let [#(#fields),*] = a;
                #ty { #(#fields),* }
            }

            /// References to the coefficients, in the order of [`Self::ELEMENTS`].
            pub fn each_ref(&self) -> [&T; #n] { [#(&self.#fields),*] }

            /// An iterator over references to the coefficients, in the order of [`Self::ELEMENTS`].
            pub fn iter(&self) -> ::core::array::IntoIter<&T, #n> { [#(&self.#fields),*].into_iter() }

            /// An iterator over mutable references to the coefficients.
            pub fn iter_mut(&mut self) -> ::core::array::IntoIter<&mut T, #n> { [#(&mut self.#fields),*].into_iter() }
        }

        impl<T: __gam_engine::Ring> ::core::default::Default for #ty<T> {
            /// Zero.
            fn default() -> Self { Self::zero() }
        }

        impl<T: __gam_engine::Ring> ::core::convert::From<[T; #n]> for #ty<T> {
            fn from(a: [T; #n]) -> Self { Self::from_array(a) }
        }

        impl<T: __gam_engine::Ring> ::core::convert::From<#ty<T>> for [T; #n] {
            fn from(x: #ty<T>) -> Self { x.into_array() }
        }

        impl<T: __gam_engine::Ring> ::core::ops::Index<usize> for #ty<T> {
            type Output = T;
            /// The coefficient at position `i` of [`Self::ELEMENTS`]; panics if `i >= LEN`, like
            /// an array.
            fn index(&self, i: usize) -> &T {
                match i {
                    #(#idx => &self.#fields,)*
                    _ => panic!("index {} out of range for {} (length {})", i, stringify!(#ty), #n),
                }
            }
        }

        impl<T: __gam_engine::Ring> ::core::ops::IndexMut<usize> for #ty<T> {
            fn index_mut(&mut self, i: usize) -> &mut T {
                match i {
                    #(#idx => &mut self.#fields,)*
                    _ => panic!("index {} out of range for {} (length {})", i, stringify!(#ty), #n),
                }
            }
        }

        impl<T: __gam_engine::Ring> ::core::iter::IntoIterator for #ty<T> {
            type Item = T;
            type IntoIter = ::core::array::IntoIter<T, #n>;
            fn into_iter(self) -> Self::IntoIter { self.into_array().into_iter() }
        }

        impl<'a, T: __gam_engine::Ring> ::core::iter::IntoIterator for &'a #ty<T> {
            type Item = &'a T;
            type IntoIter = ::core::array::IntoIter<&'a T, #n>;
            fn into_iter(self) -> Self::IntoIter { self.iter() }
        }

        impl<T: __gam_engine::Ring> ::core::ops::Mul<T> for #ty<T> {
            type Output = Self;
            /// `x * s`: every coefficient multiplied by `s`.
            fn mul(self, s: T) -> Self { #ty { #(#fields: self.#fields * &s),* } }
        }
        impl<T: __gam_engine::Ring> ::core::ops::Mul<T> for &#ty<T> {
            type Output = #ty<T>;
            fn mul(self, s: T) -> #ty<T> { self.scale(&s) }
        }
        impl<T: __gam_engine::Field> ::core::ops::Div<T> for #ty<T> {
            type Output = Self;
            /// `x / s`: every coefficient divided by `s`.
            fn div(self, s: T) -> Self { #ty { #(#fields: self.#fields.div_ref(&s)),* } }
        }
        impl<T: __gam_engine::Field> ::core::ops::Div<T> for &#ty<T> {
            type Output = #ty<T>;
            fn div(self, s: T) -> #ty<T> { #ty { #(#fields: self.#fields.div_ref(&s)),* } }
        }
        impl<T: __gam_engine::Ring> ::core::ops::AddAssign for #ty<T> {
            fn add_assign(&mut self, rhs: Self) { #(self.#fields.add_assign_ref(&rhs.#fields);)* }
        }
        impl<T: __gam_engine::Ring> ::core::ops::SubAssign for #ty<T> {
            fn sub_assign(&mut self, rhs: Self) { #(self.#fields.sub_assign_ref(&rhs.#fields);)* }
        }
        impl<T: __gam_engine::Ring> ::core::ops::MulAssign<T> for #ty<T> {
            fn mul_assign(&mut self, s: T) { #(self.#fields = self.#fields.mul_ref(&s);)* }
        }
        impl<T: __gam_engine::Field> ::core::ops::DivAssign<T> for #ty<T> {
            fn div_assign(&mut self, s: T) { #(self.#fields = self.#fields.div_ref(&s);)* }
        }
        #(#floats)*
    }
}

/// `a * &b` and `&a * b` (and the same for `^`, `|`) for one kernel with an operator.
pub(super) fn mixed_operators(names: &Names, k: &BinaryKernel) -> TokenStream {
    let Some((op_trait, op_method)) = product_operator(k.product) else {
        return quote!();
    };
    let (trait_name, method) = product_trait(k.product);
    let (trait_name, method, op_trait, op_method) =
        (ident(trait_name), ident(method), ident(op_trait), ident(op_method));
    let (lt, rt, ot) = (&names.types[k.lhs], &names.types[k.rhs], &names.types[k.out]);
    quote! {
        impl<T: __gam_engine::Ring> ::core::ops::#op_trait<&#rt<T>> for #lt<T> {
            type Output = #ot<T>;
            fn #op_method(self, rhs: &#rt<T>) -> #ot<T> { __gam_engine::ops::#trait_name::#method(&self, rhs) }
        }
        impl<T: __gam_engine::Ring> ::core::ops::#op_trait<#rt<T>> for &#lt<T> {
            type Output = #ot<T>;
            fn #op_method(self, rhs: #rt<T>) -> #ot<T> { __gam_engine::ops::#trait_name::#method(self, &rhs) }
        }
    }
}
