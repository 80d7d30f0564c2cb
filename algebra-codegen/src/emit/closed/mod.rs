//! The Rust methods of the closed forms ([`crate::closed`]): `exp`, `try_exp`, `normalize`,
//! `log`, `log_unit`, `sqrt` and `pow`, assembled from the scalar factors of
//! `algebra_core::closed_form`.

mod invariant;
mod shared;

use super::Names;
use super::sums::sum;
use crate::CodegenError;
use crate::closed::{ClosedForm, Family, ITimes, Sign, detect};
use crate::plan::Plan;
use crate::ratio::{Ratio, to_ratio};
use algebra_core::rational::Q;
use num_traits::Zero;
use proc_macro2::TokenStream;
use quote::quote;
use shared::{sqrt_pow_items, try_exp_item};

fn int(n: i64) -> Q {
    Q::from_integer(n.into())
}

/// `expr` (a `T` value), negated when `sign` is `-1` (an orientation sign).
fn signed(expr: TokenStream, sign: i64) -> TokenStream {
    if sign < 0 { quote!((-(#expr))) } else { expr }
}

/// `c · sign_i · sign_j` as a kernel constant.
fn folded(c: &Q, signs: &[i64]) -> Result<Ratio, CodegenError> {
    let s: i64 = signs.iter().product();
    to_ratio(&(c * int(s)))
}

/// Field access helpers for one closed form (canonical coefficient = sign · field).
struct Ctx<'a> {
    names: &'a Names,
    c: &'a ClosedForm,
    /// Per field of `B`: its field index in `M`.
    in_m: Vec<usize>,
}

impl Ctx<'_> {
    /// `Σ d x_b²` over `B`'s fields of `owner` (`self.f`), times `factor`; signs square away.
    fn square_form(&self, owner: usize, factor: i64) -> Result<TokenStream, CodegenError> {
        let mut terms = Vec::new();
        for (k, d) in self.c.square.iter().enumerate() {
            if d.is_zero() {
                continue;
            }
            let f = self.field(owner, k);
            terms.push((to_ratio(&(d * int(factor)))?, quote!((self.#f.mul_ref(&self.#f))), true));
        }
        Ok(sum(terms))
    }

    /// The field of `B`'s `k`-th element in `owner` (`B` or `M`) and its orientation sign.
    fn field(&self, owner: usize, k: usize) -> &proc_macro2::Ident {
        let idx = if owner == self.c.bivector { k } else { self.in_m[k] };
        &self.names.fields[owner][idx]
    }

    fn sign(&self, owner: usize, k: usize) -> i64 {
        let idx = if owner == self.c.bivector { k } else { self.in_m[k] };
        self.names.signs[owner][idx]
    }

    /// `c/2` of `B² = q + cI` on `owner`'s `B` fields.
    fn half_c(&self, owner: usize, half_c: &[(usize, usize, Q)]) -> Result<TokenStream, CodegenError> {
        let mut terms = Vec::new();
        for (a, b, c) in half_c {
            let (fa, fb) = (self.field(owner, *a), self.field(owner, *b));
            let k = folded(c, &[self.sign(owner, *a), self.sign(owner, *b)])?;
            terms.push((k, quote!((self.#fa.mul_ref(&self.#fb))), true));
        }
        Ok(sum(terms))
    }

    /// The value of `target`'s field for `B`'s element `k`: `outer · x_k + inner · (I x)_k`,
    /// where `x` is `owner`'s `B` part, each scaled by the named scalar.
    fn combine(
        &self,
        owner: usize,
        target: usize,
        k: usize,
        outer: Option<&TokenStream>,
        inner: Option<(&TokenStream, i64, &[ITimes])>,
    ) -> Result<TokenStream, CodegenError> {
        let ts = self.sign(target, k);
        let f = self.field(owner, k);
        let mut terms = Vec::new();
        if let Some(outer) = outer {
            terms.push(((ts * self.sign(owner, k), 1), quote!((#outer.mul_ref(&self.#f))), true));
        }
        if let Some((scalar, factor, i_times)) = inner {
            for (src, row) in i_times.iter().enumerate() {
                for (dst, c) in row {
                    if *dst == k {
                        let fs = self.field(owner, src);
                        let coef = folded(&(c * int(factor)), &[ts, self.sign(owner, src)])?;
                        terms.push((coef, quote!((#scalar.mul_ref(&self.#fs))), true));
                    }
                }
            }
        }
        Ok(sum(terms))
    }
}

/// The methods of one detected pair.
fn items(plan: &Plan, names: &Names, c: &ClosedForm) -> Result<TokenStream, CodegenError> {
    let (bi, mi) = (c.bivector, c.even);
    let (bt, mt) = (&names.types[bi], &names.types[mi]);
    let in_m: Vec<usize> = plan.spec.types[bi]
        .elements
        .iter()
        .map(|x| plan.spec.types[mi].elements.iter().position(|y| y == x).expect("B is inside M"))
        .collect();
    let ctx = Ctx { names, c, in_m };
    let cf = quote!(__gam_engine::closed_form);
    let mfields = &names.fields[mi];
    let scalar_field = &mfields[plan.spec.types[mi].elements.iter().position(|x| *x == 0).expect("1 in M")];
    let err = quote!(::core::result::Result<Self, __gam_engine::MvError>);
    let berr = quote!(::core::result::Result<#bt<T>, __gam_engine::MvError>);
    // exp: the factors, then every field of M
    let (factors, i_index) = match &c.family {
        Family::Invariant(inv) => return invariant::items(plan, names, c, inv),
        Family::Dual { i, .. } => {
            let theta2 = ctx.square_form(bi, -1)?;
            (
                quote!(let (sinc, k, cos) = #cf::exp_factors(&(#theta2));),
                plan.spec.types[mi].elements.iter().position(|x| x == i),
            )
        }
        Family::Scalar(sign) => {
            let qf = ctx.square_form(bi, 1)?;
            let choose = match sign {
                Sign::Elliptic => {
                    let theta2 = ctx.square_form(bi, -1)?;
                    quote! { let (sinc, _, cos) = #cf::exp_factors(&(#theta2)); }
                }
                Sign::Hyperbolic => quote! { let (sinc, cos) = #cf::exp_factors_hyperbolic(&q); },
                Sign::Mixed => quote! {
                    let (sinc, cos) = if q.to_f64() <= 0.0 {
                        let (s, _, c) = #cf::exp_factors(&(-q));
                        (s, c)
                    } else {
                        #cf::exp_factors_hyperbolic(&q)
                    };
                },
            };
            let q = if *sign == Sign::Elliptic { quote!() } else { quote!(let q = #qf;) };
            (quote!(#q #choose), None)
        }
    };
    let mut exp_fields = Vec::new();
    let mut hb = quote!(T::zero());
    let mut norm_extra = quote!();
    let mut log_inner = None;
    let (half_c_exp, i_term) = if let Family::Dual { half_c, i_times, .. } = &c.family {
        let hc = ctx.half_c(bi, half_c)?;
        let hc_m = ctx.half_c(mi, half_c)?;
        let ii = i_index.expect("I in M");
        let (fi, si) = (&mfields[ii], names.signs[mi][ii]);
        // normalize: β/2 = s p - c(B')/2; out += w (s I + I B')
        let sp = signed(quote!(self.#scalar_field.mul_ref(&self.#fi)), si);
        hb = quote!(#sp - (#hc_m));
        let w = quote!(w);
        // only the fields `I B'` reaches (no `x + 0`, which a float kernel must keep)
        let corr: Vec<TokenStream> = (0..c.square.len())
            .filter(|&k| i_times.iter().any(|row| row.iter().any(|(dst, _)| *dst == k)))
            .map(|k| {
                let f = ctx.field(mi, k);
                let v = ctx.combine(mi, mi, k, None, Some((&w, 1, i_times)))?;
                Ok(quote!(out.#f = out.#f.clone() + #v;))
            })
            .collect::<Result<_, CodegenError>>()?;
        let sw = signed(quote!(self.#scalar_field.mul_ref(&w)), si);
        norm_extra = quote! {
            out.#fi = out.#fi.clone() + #sw;
            #(#corr)*
        };
        log_inner = Some(i_times.clone());
        (quote!(let half_c = #hc; let hk = half_c.mul_ref(&k);), Some((ii, si)))
    } else {
        (quote!(), None)
    };
    for (idx, f) in mfields.iter().enumerate() {
        let mask = plan.spec.types[mi].elements[idx];
        let v = if mask == 0 {
            quote!(::core::clone::Clone::clone(&cos))
        } else if let Some((_, si)) = i_term.filter(|(ii, _)| *ii == idx) {
            signed(quote!(half_c.mul_ref(&sinc)), si)
        } else {
            let k = ctx.in_m.iter().position(|&p| p == idx).expect("a field of B");
            let hk = quote!(hk);
            let inner = match &c.family {
                Family::Dual { i_times, .. } => Some((&hk, -1, i_times.as_slice())),
                Family::Scalar(_) | Family::Invariant(_) => None,
            };
            ctx.combine(bi, mi, k, Some(&quote!(sinc)), inner)?
        };
        exp_fields.push(quote!(#f: #v));
    }
    // log_unit and log: the factors from (sin, cos), then every field of B. `log` takes the
    // factors of the element as it is (`log_factors_nonunit`, homogeneous in its scale), so it
    // needs no normalisation; it normalises first only where that scaling is out of range.
    let fallback = quote!(return self.normalize()?.log_unit(););
    let full_turn = quote! {
        if sin.to_f64() == 0.0 && self.#scalar_field.to_f64() < 0.0 {
            return Err(#cf::undefined("log", self.to_string(), "a full turn has no unique rotation axis"));
        }
    };
    let (log_body, log_full) = match &c.family {
        Family::Dual { .. } | Family::Scalar(Sign::Elliptic) | Family::Invariant(_) => {
            let sin2 = ctx.square_form(mi, -1)?;
            let head = quote!(let sin = (#sin2).sqrt(); #full_turn);
            (
                quote!(#head let (inv, kk) = #cf::log_factors(&sin, &self.#scalar_field);),
                quote! {
                    #head
                    let Some((inv, ia, kk)) = #cf::log_factors_nonunit(&sin, &self.#scalar_field, &alpha) else {
                        #fallback
                    };
                },
            )
        }
        Family::Scalar(sign) => {
            let qf = ctx.square_form(mi, 1)?;
            let hyper = quote! {
                if self.#scalar_field.to_f64() <= 0.0 {
                    return Err(#cf::undefined("log", self.to_string(), "no real logarithm (q = B² > 0 and the scalar part is not positive)"));
                }
                #cf::log_factor_hyperbolic(&q.sqrt(), &self.#scalar_field)
            };
            let pick = |elliptic: TokenStream| {
                if *sign == Sign::Hyperbolic {
                    hyper.clone()
                } else {
                    quote! {
                        if q.to_f64() <= 0.0 {
                            let sin = (-q).sqrt();
                            #full_turn
                            #elliptic
                        } else {
                            #hyper
                        }
                    }
                }
            };
            let unit = pick(quote!(#cf::log_factors(&sin, &self.#scalar_field).0));
            let full = pick(quote! {
                match #cf::log_factors_nonunit(&sin, &self.#scalar_field, &alpha) {
                    Some((inv, _, _)) => inv,
                    None => { #fallback }
                }
            });
            (quote! { let q = #qf; let inv = { #unit }; }, quote! { let q = #qf; let inv = { #full }; })
        }
    };
    let (pk, pk_full) = match (&c.family, i_term) {
        (Family::Dual { .. }, Some((ii, si))) => {
            let fi = &mfields[ii];
            let v = signed(quote!(self.#fi.mul_ref(&kk)), si);
            // log(M) = inv B' + (h inv + (p + h s) kk) I B', h = -(β/2)/α: log_unit of
            // normalize(M) = u M + w M I written in M's own coefficients
            let p = signed(quote!(self.#fi.clone()), si);
            (
                quote!(let pk = #v;),
                quote! {
                    let h = -((#hb) * ia);
                    let pk = h.mul_ref(&inv) + (#p + h.mul_ref(&self.#scalar_field)) * kk;
                },
            )
        }
        _ => (quote!(), quote!()),
    };
    let pk_name = quote!(pk);
    let log_fields = (0..c.square.len())
        .map(|k| {
            let f = &names.fields[bi][k];
            let v = ctx.combine(mi, bi, k, Some(&quote!(inv)), log_inner.as_deref().map(|r| (&pk_name, 1, r)))?;
            Ok(quote!(#f: #v))
        })
        .collect::<Result<Vec<_>, CodegenError>>()?;
    let qm = ctx.square_form(mi, 1)?;
    let norm_tail = if matches!(c.family, Family::Dual { .. }) {
        quote! {
            let half_beta = #hb;
            // u = 1/√α and w = -(β/2)/α^{3/2}, with one division
            let inv_alpha = T::one() / alpha;
            let u = inv_alpha.sqrt();
            let w = -(half_beta * u.clone()) * inv_alpha;
            let mut out = self.scale(&u);
            #norm_extra
            Ok(out)
        }
    } else {
        quote!(Ok(self.scale(&(T::one() / alpha.sqrt()))))
    };
    // The start of `normalize` and `log` (named `op`): finite coefficients, the norm `alpha`,
    // a rescaling by a power of two far from unit scale (neither depends on the scale), and a
    // positive norm.
    let prologue = |op: &str| {
        let method = proc_macro2::Ident::new(op, proc_macro2::Span::call_site());
        quote! {
            #cf::check_finite(#op, self, self.iter())?;
            let alpha = self.#scalar_field.mul_ref(&self.#scalar_field) - (#qm);
            // (no let-chain: the code compiles in the user's edition)
            if !(alpha.to_f64() >= 1e-60 && alpha.to_f64() <= 1e60) {
                if let Some(k) = #cf::rescale(self.iter()) {
                    return self.scale(&k).#method();
                }
            }
            if alpha.to_f64().is_nan() || alpha.to_f64() <= 0.0 {
                return Err(#cf::undefined(#op, self.to_string(), "the norm self rev(self) is not positive"));
            }
        }
    };
    let (normalize_prologue, log_prologue) = (prologue("normalize"), prologue("log"));
    let bdoc = format!(
        " The exponential in closed form (`algebra_core::closed_form`): a unit `{mt}`. An unchecked kernel: a NaN or infinite coefficient gives NaN coefficients (use `try_exp` for input of unknown origin)."
    );
    let (try_exp, sqrt_pow) = (try_exp_item(mt), sqrt_pow_items());
    Ok(quote! {
        impl<T: __gam_engine::Real> #bt<T> {
            #[doc = #bdoc]
            pub fn exp(&self) -> #mt<T> {
                #factors
                #half_c_exp
                #mt { #(#exp_fields),* }
            }

            #try_exp
        }

        impl<T: __gam_engine::Real> #mt<T> {
            /// `self / sqrt(self rev(self))`, the norm inverted in closed form: a unit element
            /// (`m rev(m) = 1`) when `self rev(self)` has no other part than the scalar (and the
            /// central nilpotent element, if any). Fails when the norm is not positive or a
            /// coefficient is not finite.
            pub fn normalize(&self) -> #err {
                #normalize_prologue
                #norm_tail
            }

            /// The logarithm of `normalize(self)` in closed form: the bivector `B` with
            /// `exp(B) = normalize(self)` (rotation angle `θ ∈ [0, π)`). Fails when `normalize`
            /// does, and for a full turn (`θ = π`, no unique axis).
            pub fn log(&self) -> #berr {
                #log_prologue
                #log_full
                #pk_full
                Ok(#bt { #(#log_fields),* })
            }

            /// The logarithm of an element that is already unit (`self rev(self) = 1`, as every
            /// `exp` and product of unit elements is, up to rounding): [`Self::log`] without the
            /// normalisation. For an element that is not unit the result is not a logarithm of
            /// anything. Fails for a full turn and for non-finite input.
            pub fn log_unit(&self) -> #berr {
                #cf::check_finite("log", self, self.iter())?;
                #log_body
                #pk
                Ok(#bt { #(#log_fields),* })
            }

            #sqrt_pow
        }
    })
}

/// Every closed-form impl of the module.
pub(crate) fn module_items(plan: &Plan, names: &Names) -> TokenStream {
    if !plan.spec.closed_forms {
        return TokenStream::new();
    }
    let result = detect(&plan.spec, &plan.closed)
        .and_then(|found| found.iter().map(|c| items(plan, names, c)).collect::<Result<Vec<_>, _>>());
    match result {
        Ok(items) => quote!(#(#items)*),
        Err(e) => {
            let msg = e.to_string();
            quote!(compile_error!(#msg);)
        }
    }
}
