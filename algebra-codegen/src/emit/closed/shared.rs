//! The closed-form methods every family shares: `try_exp` on the bivector type, `sqrt` and
//! `pow` on the even type.

use proc_macro2::TokenStream;
use quote::quote;

/// `try_exp` on a bivector type whose `exp` returns `mt`: shared by every family.
pub(crate) fn try_exp_item(mt: &proc_macro2::Ident) -> TokenStream {
    let cf = quote!(__gam_engine::closed_form);
    quote! {
        /// [`Self::exp`] after checking that every coefficient is finite:
        /// `MvError::Undefined` ("coefficients are not finite") otherwise, and "the result is
        /// not finite" when a finite bivector is too large for the scalar.
        pub fn try_exp(&self) -> ::core::result::Result<#mt<T>, __gam_engine::MvError> {
            #cf::check_finite("exp", self, self.iter())?;
            let out = self.exp();
            #cf::check_finite("exp", self, out.iter()).map_err(|_| {
                #cf::undefined("exp", self.to_string(), "the result is not finite (the bivector is too large for this scalar)")
            })?;
            Ok(out)
        }
    }
}

/// `sqrt` and `pow` on an even type with `log` and its bivector type's `exp`: shared by every
/// family.
pub(crate) fn sqrt_pow_items() -> TokenStream {
    let cf = quote!(__gam_engine::closed_form);
    let err = quote!(::core::result::Result<Self, __gam_engine::MvError>);
    quote! {
        /// The square root of `normalize(self)`: `exp(log(self)/2)`.
        pub fn sqrt(&self) -> #err {
            Ok((self.log()? * T::from_ratio(1, 2)).exp())
        }

        /// `normalize(self)^t = exp(t log(self))`.
        pub fn pow(&self, t: &T) -> #err {
            #cf::check_finite("pow", t, ::core::iter::once(t))?;
            Ok((self.log()? * t.clone()).exp())
        }
    }
}
