//! The Rust methods of the invariant-decomposition closed forms ([`crate::closed_inv`]).

use super::shared::{sqrt_pow_items, try_exp_item};
use crate::CodegenError;
use crate::closed::ClosedForm;
use crate::closed_inv::{Invariant, Quadratic};
use crate::emit::Names;
use crate::emit::sums::sum;
use crate::plan::Plan;
use crate::ratio::to_ratio;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// `Σ c x_i x_j` over local variables named `prefix{i}`.
fn form(f: &Quadratic, prefix: &str) -> Result<TokenStream, CodegenError> {
    let mut terms = Vec::new();
    for (i, j, c) in f {
        let (x, y) = (format_ident!("{prefix}{i}"), format_ident!("{prefix}{j}"));
        terms.push((to_ratio(c)?, quote!((#x.mul_ref(&#y))), true));
    }
    Ok(sum(terms))
}

/// `let x{k} = <canonical coefficient>` for the fields of `owner` at `idx` (orientation signs
/// folded in), one `let` per element.
fn load(names: &Names, owner: usize, idx: &[usize], prefix: &str) -> TokenStream {
    let lets = idx.iter().enumerate().map(|(k, &i)| {
        let (v, f) = (format_ident!("{prefix}{k}"), &names.fields[owner][i]);
        if names.signs[owner][i] < 0 { quote!(let #v = -self.#f.clone();) } else { quote!(let #v = self.#f.clone();) }
    });
    quote!(#(#lets)*)
}

/// The invariants of a bivector held in locals `prefix{k}`: `s`, `Q` in `w{a}`, `Q²` in `qq`,
/// `(B Q)_k` in `bq{k}`.
fn invariants(inv: &Invariant, nb: usize, prefix: &str) -> Result<TokenStream, CodegenError> {
    let s = form(&inv.s, prefix)?;
    let qs = inv
        .q
        .iter()
        .enumerate()
        .map(|(a, f)| {
            let v = format_ident!("w{a}");
            let e = form(f, prefix)?;
            Ok(quote!(let #v = #e;))
        })
        .collect::<Result<Vec<_>, CodegenError>>()?;
    let q4 = form(&inv.q4, "w")?;
    let bqs = (0..nb)
        .map(|k| {
            let v = format_ident!("bq{k}");
            let mut terms = Vec::new();
            for (i, a, c) in &inv.bq[k] {
                let (x, y) = (format_ident!("{prefix}{i}"), format_ident!("w{a}"));
                terms.push((to_ratio(c)?, quote!((#x.mul_ref(&#y))), true));
            }
            let e = sum(terms);
            Ok(quote!(let #v = #e;))
        })
        .collect::<Result<Vec<_>, CodegenError>>()?;
    Ok(quote! {
        let s = #s;
        #(#qs)*
        let qq = #q4;
        #(#bqs)*
    })
}

/// The methods of one invariant-decomposition pair.
pub(crate) fn items(plan: &Plan, names: &Names, c: &ClosedForm, inv: &Invariant) -> Result<TokenStream, CodegenError> {
    let (bi, mi) = (c.bivector, c.even);
    let (bt, mt) = (&names.types[bi], &names.types[mi]);
    let (bm, mm) = (&plan.spec.types[bi].elements, &plan.spec.types[mi].elements);
    let nb = bm.len();
    let b_in_b: Vec<usize> = (0..nb).collect();
    let b_in_m: Vec<usize> = bm.iter().map(|x| mm.iter().position(|y| y == x).expect("B in M")).collect();
    let w_in_m: Vec<usize> = inv.quad.iter().map(|x| mm.iter().position(|y| y == x).expect("W in M")).collect();
    let scalar_idx = mm.iter().position(|x| *x == 0).expect("1 in M");
    let cf = quote!(__gam_engine::closed_form);
    let load_b = load(names, bi, &b_in_b, "b");
    let inv_b = invariants(inv, nb, "b")?;
    // exp: every field of M
    let out = |idx: usize, v: TokenStream| {
        let f = &names.fields[mi][idx];
        if names.signs[mi][idx] < 0 { quote!(#f: -(#v)) } else { quote!(#f: #v) }
    };
    let mut exp_fields = vec![TokenStream::new(); mm.len()];
    exp_fields[scalar_idx] = out(scalar_idx, quote!(cc));
    for (k, &idx) in b_in_m.iter().enumerate() {
        let (b, bq) = (format_ident!("b{k}"), format_ident!("bq{k}"));
        exp_fields[idx] = out(idx, quote!(d1.mul_ref(&#b) - hd2.mul_ref(&#bq)));
    }
    for (a, &idx) in w_in_m.iter().enumerate() {
        let w = format_ident!("w{a}");
        exp_fields[idx] = out(idx, quote!(hss.mul_ref(&#w)));
    }
    let n_m = mm.len();
    let bdoc = format!(
        " The exponential in closed form by the invariant decomposition \
         (`algebra_core::closed_form::invariant_exp_factors`): a unit `{mt}`. When the two \
         invariants `λ1, λ2` are complex (possible only in signatures such as `(2, 2)`) the \
         runtime series (`to_multivector().exp()`) is used instead. An unchecked kernel: a NaN \
         or infinite coefficient gives NaN coefficients (use `try_exp` for input of unknown origin)."
    );
    // log_unit: c, B' of self, then every field of B
    let load_c = load(names, mi, &[scalar_idx], "c");
    let scalar_field = &names.fields[mi][scalar_idx];
    let load_bm = load(names, mi, &b_in_m, "b");
    let log_fields: Vec<TokenStream> = (0..nb)
        .map(|k| {
            let (f, b, bq) = (&names.fields[bi][k], format_ident!("b{k}"), format_ident!("bq{k}"));
            let v = quote!(f.mul_ref(&#b) - g.mul_ref(&#bq));
            if names.signs[bi][k] < 0 { quote!(#f: -(#v)) } else { quote!(#f: #v) }
        })
        .collect();
    let berr = quote!(::core::result::Result<#bt<T>, __gam_engine::MvError>);
    let err = quote!(::core::result::Result<Self, __gam_engine::MvError>);
    let (try_exp, sqrt_pow) = (try_exp_item(mt), sqrt_pow_items());
    let m_items = quote! {
        impl<T: __gam_engine::Real> #mt<T> {
            /// `self / sqrt(self rev(self))` when `self rev(self)` is a positive scalar (up to
            /// rounding: every other part within `256 ε Σ coefficient²`), so the result is unit;
            /// elements far from unit scale are first rescaled by a power of two.
            /// `self rev(self)` is the module's own product. Fails when the norm is not
            /// positive, when `self rev(self)` has a 4-vector part (not a multiple of a versor),
            /// or a coefficient is not finite.
            pub fn normalize(&self) -> #err {
                #cf::check_finite("normalize", self, self.iter())?;
                // the result does not depend on the scale: far from 1, rescale by a power of two
                if let ::core::option::Option::Some(k) = #cf::rescale(self.iter()) {
                    return self.scale(&k).normalize();
                }
                let n: #mt<T> = self * &self.reverse();
                let alpha = n.#scalar_field.clone();
                if alpha.to_f64().is_nan() || alpha.to_f64() <= 0.0 {
                    return Err(#cf::undefined("normalize", self.to_string(), "the norm self rev(self) is not positive"));
                }
                let scale: f64 = self.iter().map(|x| x.to_f64() * x.to_f64()).sum();
                let rest = n.iter().enumerate().filter(|(i, _)| *i != #scalar_idx).map(|(_, x)| x.to_f64().abs()).fold(0.0, f64::max);
                if rest > 256.0 * T::relative_epsilon() * scale {
                    return Err(#cf::undefined("normalize", self.to_string(), "self rev(self) is not a scalar (not a multiple of a versor)"));
                }
                Ok(self.scale(&(T::one() / alpha.sqrt())))
            }

            /// The logarithm of `normalize(self)`: the bivector `B` with
            /// `exp(B) = normalize(self)`, in the branch of [`Self::log_unit`]. Fails when
            /// `normalize` or `log_unit` does.
            pub fn log(&self) -> #berr {
                self.normalize()?.log_unit()
            }

            /// The logarithm of an element that is already unit (`self rev(self) = 1`), in
            /// closed form by the invariant decomposition
            /// (`algebra_core::closed_form::invariant_log_factors`). The branch: boosts
            /// (hyperbolic planes) keep a positive `cosh`; of two rotation planes the returned
            /// angles satisfy `θ1 + θ2 <= π`, each `θ_i ∈ [0, π)` (the smaller of the two
            /// logarithms). Where the closed form is inaccurate (complex invariants, nearly
            /// isoclinic rotations, a plane at a quarter turn) the runtime series
            /// (`to_multivector().log()`) is used. Fails for non-finite input, a full turn in
            /// one plane, two rotation angles summing to `π`, and elements with no real
            /// logarithm. For an element that is not unit the result is not a logarithm of
            /// anything.
            pub fn log_unit(&self) -> #berr {
                #cf::check_finite("log", self, self.iter())?;
                #load_c
                #load_bm
                #inv_b
                match #cf::invariant_log_factors(&c0, &s, &qq) {
                    ::core::result::Result::Err(why) => Err(#cf::undefined("log", self.to_string(), why)),
                    ::core::result::Result::Ok(::core::option::Option::Some((f, g))) => Ok(#bt { #(#log_fields),* }),
                    ::core::result::Result::Ok(::core::option::Option::None) => {
                        Ok(#bt::project(&self.to_multivector().log()?))
                    }
                }
            }

            #sqrt_pow
        }
    };
    Ok(quote! {
        #m_items

        impl<T: __gam_engine::Real> #bt<T> {
            #[doc = #bdoc]
            pub fn exp(&self) -> #mt<T> {
                #load_b
                #inv_b
                match #cf::invariant_exp_factors(&s, &qq) {
                    ::core::option::Option::Some((cc, d1, d2, ss)) => {
                        let half = T::from_ratio(1, 2);
                        let (hd2, hss) = (d2 * half.clone(), ss * half);
                        #mt { #(#exp_fields),* }
                    }
                    ::core::option::Option::None => match self.to_multivector().exp() {
                        ::core::result::Result::Ok(m) => #mt::project(&m),
                        ::core::result::Result::Err(_) => #mt::from_array([(); #n_m].map(|_| T::from_f64(f64::NAN))),
                    },
                }
            }

            #try_exp
        }
    })
}
