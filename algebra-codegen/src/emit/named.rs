//! The named constructors of [`crate::named`] as module-level functions: `point`, `plane`,
//! `translator`, `rotor`, ... each returning the smallest declared type that holds it.

use super::Names;
use super::sums::{SumTerm, sum};
use crate::named::{Atom, Constructor, Down, Param, constructors, down};
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
        Atom::Cosh => quote!(ch),
        Atom::Sinh => quote!(sh),
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
    let trig = c.params.iter().any(|p| matches!(p, Param::Angle | Param::Axis(_) | Param::Scale));
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
                        __gam_engine::closed_form::check_finite(#name_str, &#what, #arg.iter())?;
                    ));
                }
                arrays += 1;
            }
            Param::Axis(len) => {
                args.push(quote!(axis: &[T; #len]));
                checks.push(quote!(__gam_engine::closed_form::check_finite(#name_str, &"axis", axis.iter())?;));
                let us = (0..*len).map(|k| format_ident!("u{}", k));
                let idx = 0..*len;
                lets.push(quote! {
                    let norm2 = axis.iter().fold(T::zero(), |acc, a| acc + &a.mul_ref(a));
                    if !(norm2 > T::zero()) || !__gam_engine::Ring::is_finite_value(&norm2) {
                        return Err(__gam_engine::closed_form::undefined(#name_str, "axis".to_string(), "the axis is zero (or too large for this scalar)"));
                    }
                    let inv = T::one().div_ref(&__gam_engine::Real::sqrt(&norm2));
                    #(let #us = axis[#idx].mul_ref(&inv);)*
                });
            }
            Param::Scale => {
                args.push(quote!(scale: &T));
                checks.push(
                    quote!(__gam_engine::closed_form::check_finite(#name_str, &"scale", ::core::iter::once(scale))?;),
                );
                lets.push(quote! {
                    if !(*scale > T::zero()) {
                        return Err(__gam_engine::closed_form::undefined(#name_str, "scale".to_string(), "the scale is not positive"));
                    }
                    let root = __gam_engine::Real::sqrt(scale);
                    let inv = T::one().div_ref(&root);
                    let ch = (root.clone() + &inv).mul_ref(&T::from_ratio(1, 2));
                    let sh = (root - &inv).mul_ref(&T::from_ratio(1, 2));
                });
            }
            Param::Angle => {
                args.push(quote!(angle: &T));
                checks.push(
                    quote!(__gam_engine::closed_form::check_finite(#name_str, &"angle", ::core::iter::once(angle))?;),
                );
                lets.push(quote! {
                    let half = angle.mul_ref(&T::from_ratio(1, 2));
                    let (c, s) = (__gam_engine::Real::cos(&half), __gam_engine::Real::sin(&half));
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
            pub fn #name<T: __gam_engine::Real>(#(#args),*) -> ::core::result::Result<#ty<T>, __gam_engine::MvError> {
                #(#checks)*
                #(#lets)*
                Ok(#body)
            }
        }
    } else {
        quote! {
            #[doc = #doc]
            pub fn #name<T: __gam_engine::Ring>(#(#args),*) -> #ty<T> {
                #(#lets)*
                #body
            }
        }
    })
}

/// `down` (conformal modules): the Euclidean point of a conformal point.
fn down_item(names: &Names, d: &Down) -> Option<TokenStream> {
    let ty = &names.types[d.input];
    let fields = &names.fields[d.input];
    let signs = &names.signs[d.input];
    let linear = |coefs: &[algebra_core::rational::Q]| -> Option<TokenStream> {
        let mut terms: Vec<SumTerm> = Vec::new();
        for ((c, f), s) in coefs.iter().zip(fields).zip(signs) {
            if !num_traits::Zero::is_zero(c) {
                let c = if *s < 0 { -c.clone() } else { c.clone() };
                terms.push((to_ratio(&c).ok()?, quote!(x.#f), false));
            }
        }
        Some(sum(terms))
    };
    let weight = linear(&d.weight)?;
    let coords = d.coords.iter().map(|c| linear(c)).collect::<Option<Vec<_>>>()?;
    let n = coords.len();
    Some(quote! {
        /// The Euclidean point of the conformal point `x` (any weight): `x_k = (x · g_k) / (-x · ∞)`,
        /// so `down(&up(&p)) == p`. An error when `x · ∞ = 0` (a point at infinity, a plane)
        /// or `x` is not finite.
        pub fn down<T: __gam_engine::Field>(x: &#ty<T>) -> ::core::result::Result<[T; #n], __gam_engine::MvError> {
            if !x.iter().all(__gam_engine::Ring::is_finite_value) {
                return Err(__gam_engine::closed_form::undefined("down", "x".to_string(), "coefficients are not finite"));
            }
            let w = #weight;
            let inv = w.try_recip().filter(__gam_engine::Ring::is_finite_value).ok_or_else(|| {
                __gam_engine::closed_form::undefined("down", "x".to_string(), "its weight -x · ∞ is zero (not a finite point)")
            })?;
            Ok([#(#coords.mul_ref(&inv)),*])
        }
    })
}

/// Every named constructor of the plan's algebra (none when it is not recognised).
pub(super) fn module_items(plan: &Plan, names: &Names) -> TokenStream {
    let Ok(all) = constructors(&plan.spec, plan.declared) else { return quote!() };
    let items = all.iter().filter_map(|c| function(names, c));
    let down = down(&plan.spec, &all).and_then(|d| down_item(names, &d));
    quote!(#(#items)* #down)
}
