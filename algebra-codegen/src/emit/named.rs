//! The named constructors of [`crate::named`] as module-level functions: `point`, `plane`,
//! `translator`, `rotor`, ... each returning the smallest declared type that holds it.

use super::Names;
use super::sums::{SumTerm, sum};
use crate::named::{Atom, Constructor, Param, constructors};
use crate::plan::Plan;
use crate::ratio::to_ratio;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// The variable holding `atom`.
fn atom(a: Atom) -> TokenStream {
    match a {
        Atom::Param(p, k) => {
            let v = format_ident!("p{}_{}", p, k);
            quote!(#v)
        }
        Atom::Cos => quote!(c),
        Atom::Sin => quote!(s),
        Atom::Unit(k) => {
            let v = format_ident!("u{}", k);
            quote!(#v)
        }
    }
}

/// The product of `atoms` as a `T` value (`T::one()` for none).
fn monomial(atoms: &[Atom]) -> TokenStream {
    match atoms {
        [] => quote!(T::one()),
        [a] => {
            let a = atom(*a);
            quote!(#a.clone())
        }
        [a, rest @ ..] => {
            let a = atom(*a);
            rest.iter().fold(quote!(#a), |acc, b| {
                let b = atom(*b);
                quote!(#acc.mul_ref(&#b))
            })
        }
    }
}

fn function(names: &Names, c: &Constructor) -> Option<TokenStream> {
    let ty = &names.types[c.out];
    let name = format_ident!("{}", c.name);
    let name_str = c.name;
    let mut arrays = 0usize;
    let mut args = Vec::new();
    let mut lets = Vec::new();
    let mut checks = Vec::new();
    let trig = c.params.iter().any(|p| matches!(p, Param::Angle | Param::Axis(_)));
    for p in &c.params {
        match p {
            Param::Array(n, len) => {
                let arg = format_ident!("{}", n);
                if *len == 1 {
                    args.push(quote!(#arg: &T));
                    let v = format_ident!("p{}_0", arrays);
                    lets.push(quote!(let #v = #arg.clone();));
                } else {
                    args.push(quote!(#arg: &[T; #len]));
                    for k in 0..*len {
                        let v = format_ident!("p{}_{}", arrays, k);
                        lets.push(quote!(let #v = #arg[#k].clone();));
                    }
                }
                if trig {
                    let what = n.to_string();
                    checks.push(quote!(
                        ::algebra_core::closed_form::check_finite(#name_str, &#what, #arg.iter())?;
                    ));
                }
                arrays += 1;
            }
            Param::Axis(len) => {
                args.push(quote!(axis: &[T; #len]));
                checks.push(quote!(::algebra_core::closed_form::check_finite(#name_str, &"axis", axis.iter())?;));
                let us = (0..*len).map(|k| format_ident!("u{}", k));
                let idx = 0..*len;
                lets.push(quote! {
                    let norm2 = axis.iter().fold(T::zero(), |acc, a| acc + &a.mul_ref(a));
                    if !(norm2 > T::zero()) || !::algebra_core::Ring::is_finite_value(&norm2) {
                        return Err(::algebra_core::closed_form::undefined(#name_str, "axis".to_string(), "the axis is zero (or too large for this scalar)"));
                    }
                    let inv = T::one().div_ref(&::algebra_core::Real::sqrt(&norm2));
                    #(let #us = axis[#idx].mul_ref(&inv);)*
                });
            }
            Param::Angle => {
                args.push(quote!(angle: &T));
                checks.push(
                    quote!(::algebra_core::closed_form::check_finite(#name_str, &"angle", ::core::iter::once(angle))?;),
                );
                lets.push(quote! {
                    let half = angle.mul_ref(&T::from_ratio(1, 2));
                    let (c, s) = (::algebra_core::Real::cos(&half), ::algebra_core::Real::sin(&half));
                });
            }
        }
    }
    let fields = &names.fields[c.out];
    let mut values = Vec::new();
    for (k, terms) in c.fields.iter().enumerate() {
        let sign = names.signs[c.out][k];
        let mut summands: Vec<SumTerm> = Vec::new();
        for (atoms, coef) in terms {
            let q = if sign < 0 { -coef.clone() } else { coef.clone() };
            summands.push((to_ratio(&q).ok()?, monomial(atoms), true));
        }
        values.push(sum(summands));
    }
    let doc = format!(" {}", c.doc);
    let body = quote!(#ty { #(#fields: #values),* });
    Some(if trig {
        quote! {
            #[doc = #doc]
            #[allow(clippy::too_many_arguments)]
            pub fn #name<T: ::algebra_core::Real>(#(#args),*) -> ::core::result::Result<#ty<T>, ::algebra_core::MvError> {
                #(#checks)*
                #(#lets)*
                Ok(#body)
            }
        }
    } else {
        quote! {
            #[doc = #doc]
            pub fn #name<T: ::algebra_core::Ring>(#(#args),*) -> #ty<T> {
                #(#lets)*
                #body
            }
        }
    })
}

/// Every named constructor of the plan's algebra (none when it is not recognised).
pub(super) fn module_items(plan: &Plan, names: &Names) -> TokenStream {
    let Ok(all) = constructors(&plan.spec, plan.declared) else { return quote!() };
    let items = all.iter().filter_map(|c| function(names, c));
    quote!(#(#items)*)
}
