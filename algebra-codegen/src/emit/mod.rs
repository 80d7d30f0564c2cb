//! Token emission: a [`Plan`] becomes a Rust module.
//!
//! Generated items refer to the engine through one alias, `__gam_engine::...`
//! ([`crate::paths::ENGINE`]). The `algebra!` macro imports it once
//! ([`crate::paths::engine_use`]: `::algebra_core` by default, the front door's
//! `$crate::__engine`); [`module_with`] (`gam codegen`) writes the paths out as
//! `::algebra_core::...`. Either way a crate that uses the macro directly, or vendors the
//! emitted module, depends on `algebra-core` (without its `rug` feature if it wants no GMP).

use crate::naming::product_name;
pub use crate::naming::{field_name, snake};
use crate::plan::{BinaryKernel, Plan, Term, UnaryKernel, unary_name};
use algebra_core::basis::Basis;
use algebra_core::rational::format_rational;
use algebra_core::tables::Product;
use proc_macro2::{Ident, Span, TokenStream};
use quote::{format_ident, quote};
use std::collections::BTreeMap;

mod closed;
mod matrix;
mod named;
pub(crate) mod size;
pub(crate) mod sums;
pub(crate) mod unit;
mod value;
mod versor;

use sums::{SumTerm, chunked_sum, sum};

/// The trait and method of each product.
pub(super) fn product_trait(p: Product) -> (&'static str, &'static str) {
    match p {
        Product::Geometric => ("GeometricProduct", product_name(p)),
        Product::Outer => ("OuterProduct", product_name(p)),
        Product::LeftContraction => ("LeftContraction", product_name(p)),
        Product::RightContraction => ("RightContraction", product_name(p)),
        Product::Scalar => ("ScalarProduct", product_name(p)),
        Product::Regressive => ("RegressiveProduct", product_name(p)),
        Product::Commutator => ("CommutatorProduct", product_name(p)),
        Product::Anticommutator => ("AnticommutatorProduct", product_name(p)),
    }
}

/// The operator trait (if any) of each product: `*` geometric, `^` outer, `|` left
/// contraction, `&` the join (regressive product, as in klein and ganja).
pub(super) fn product_operator(p: Product) -> Option<(&'static str, &'static str)> {
    match p {
        Product::Geometric => Some(("Mul", "mul")),
        Product::Outer => Some(("BitXor", "bitxor")),
        Product::LeftContraction => Some(("BitOr", "bitor")),
        Product::Regressive => Some(("BitAnd", "bitand")),
        _ => None,
    }
}

pub(super) fn ident(s: &str) -> Ident {
    Ident::new(s, Span::call_site())
}

/// The straight-line body of a fused action kernel as the `Sandwich`/`Apply` impls emit it
/// (`self` the versor, `x` the operand, the scalar `T`, engine paths `__gam_engine::`), for
/// the tool that times term orders (`algebra-codegen/examples/pairing_wisdom.rs`).
#[doc(hidden)]
pub fn action_body(plan: &Plan, k: &crate::versor::ActionKernel) -> TokenStream {
    versor::unrolled_body(&Names::new(plan), k)
}

/// The body of a binary product kernel as its impl emits it (`self` and `rhs` the operands,
/// straight-line or table-driven by the plan's size policy), for the tool that times term
/// orders (`algebra-codegen/examples/product_wisdom.rs`).
#[doc(hidden)]
pub fn product_body(plan: &Plan, k: &BinaryKernel) -> TokenStream {
    kernel_body(&Names::new(plan), k, &[k.lhs, k.rhs])
}

/// The fields, element names and orientation signs of every type of a plan.
pub(super) struct Names {
    pub(super) types: Vec<Ident>,
    pub(super) fields: Vec<Vec<Ident>>,
    /// The element names as declared (`e20` where the user reordered `e02`).
    pub(super) elements: Vec<Vec<String>>,
    pub(super) masks: Vec<Vec<u32>>,
    /// Per field: `-1` when its name reverses the canonical orientation.
    pub(super) signs: Vec<Vec<i64>>,
    /// The size policy's threshold ([`crate::ModuleSpec::table_above`]).
    pub(super) table_above: usize,
    /// How many types the user declared ([`Plan::declared`]); the others are automatic.
    pub(super) declared: usize,
}

impl Names {
    pub(super) fn new(plan: &Plan) -> Names {
        let alg = &plan.spec.algebra;
        let types = plan.spec.types.iter().map(|t| ident(&t.name)).collect();
        let elements: Vec<Vec<String>> = plan.spec.types.iter().map(|t| t.element_names(alg)).collect();
        let fields = elements.iter().map(|es| es.iter().map(|e| ident(&field_name(e))).collect()).collect();
        let masks = plan.spec.types.iter().map(|t| t.elements.clone()).collect();
        let signs = plan.spec.types.iter().map(crate::TypeSpec::signs).collect();
        Names { types, fields, elements, masks, signs, table_above: plan.spec.table_above, declared: plan.declared }
    }

    /// Whether a kernel over these types is table-driven ([`crate::size::table_driven`]).
    pub(super) fn is_large<I: IntoIterator<Item = usize>>(&self, types: &[usize], lens: I) -> bool {
        crate::size::table_driven(self.table_above, self.declared, types, lens)
    }

    /// `expr` (a `T` place), cloned, negated when `sign` is `-1`.
    pub(super) fn signed(expr: TokenStream, sign: i64) -> TokenStream {
        if sign < 0 { quote!(__gam_engine::Ring::neg_ref(&#expr)) } else { quote!(::core::clone::Clone::clone(&#expr)) }
    }
}

/// The whole module: `pub mod NAME { ... }`.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, emit, plan::Plan};
/// let alg = Algebra::builtin("g3").unwrap();
/// let types = ModuleSpec::parse_types("Vector=grade1;Rotor=even", &alg).unwrap();
/// let spec = ModuleSpec::new("g3", alg.metric().clone(), Basis::Blade, types).unwrap();
/// let code = emit::module(&Plan::new(spec).unwrap()).to_string();
/// assert!(code.contains("pub struct Rotor"));
/// ```
pub fn module(plan: &Plan) -> TokenStream {
    module_with(plan, module_items(plan))
}

/// `pub mod NAME { ... }` around the given items (the module's, plus e.g. the constrained
/// methods of [`crate::constraint::methods`]), with every engine path written out as
/// `::algebra_core::...` (the form a vendoring crate reads; the macro imports the alias
/// instead, [`crate::paths::engine_use`]).
pub fn module_with(plan: &Plan, items: TokenStream) -> TokenStream {
    let name = ident(&plan.spec.name);
    let docs = plan.spec.doc.iter().map(|d| quote!(#![doc = #d]));
    let items = crate::paths::with_engine_path(items, &quote!(::algebra_core));
    quote! {
        #[allow(clippy::all, unused_parens, unused_mut, unused_variables, non_snake_case)]
        pub mod #name {
            #(#docs)*
            #items
        }
    }
}

/// The module's items (without the `mod` wrapper).
pub fn module_items(plan: &Plan) -> TokenStream {
    let names = Names::new(plan);
    let alg = &plan.spec.algebra;
    let labels: Vec<&str> = alg.metric().labels().iter().map(String::as_str).collect();
    let n = labels.len();
    let gram: Vec<TokenStream> = (0..n)
        .map(|i| {
            let row: Vec<String> =
                (0..n).map(|j| format_rational(alg.metric().gram(i, j).expect("i, j < n"))).collect();
            quote!(&[#(#row),*])
        })
        .collect();
    let alg_name = alg.name();
    let basis = match plan.spec.basis {
        Basis::Blade => quote!(__gam_engine::Basis::Blade),
        Basis::Product => quote!(__gam_engine::Basis::Product),
    };
    let structs = (0..names.types.len()).map(|i| type_items(plan, &names, i));
    let binaries = plan.binary.iter().map(|k| binary_items(&names, k));
    let typed = plan.typed.iter().map(|k| typed_items(&names, k));
    let conversions = conversion_items(&names);
    let actions = versor::module_items(plan, &names);
    let matrices = matrix::module_items(plan, &names);
    let units = unit::module_items(plan, &names);
    let closed = closed::module_items(plan, &names);
    let named = named::module_items(plan, &names);
    quote! {
        pub use __gam_engine::ops::{
            ActionMatrix, AnticommutatorProduct, Apply, CommutatorProduct, GeometricProduct, GeometricProductInto,
            LeftContraction, OuterProduct, RegressiveProduct, RightContraction, Sandwich, ScalarProduct,
        };
        pub use __gam_engine::ops::UnitAction;
        pub use __gam_engine::{Field, Ring};

        /// The basis the types' fields refer to.
        pub const BASIS: __gam_engine::Basis = #basis;

        /// The runtime algebra of this module (for conversions to and from
        /// [`::algebra_core::Multivector`]), built once.
        pub fn algebra() -> ::std::sync::Arc<__gam_engine::Algebra> {
            static ALGEBRA: ::std::sync::OnceLock<::std::sync::Arc<__gam_engine::Algebra>> =
                ::std::sync::OnceLock::new();
            ALGEBRA
                .get_or_init(|| {
                    let metric = __gam_engine::Metric::from_strs(&[#(#labels),*], &[#(#gram),*])
                        .expect("the metric was validated at generation");
                    __gam_engine::Algebra::new(#alg_name, metric)
                })
                .clone()
        }

        #(#structs)*
        #(#binaries)*
        #(#typed)*
        #conversions
        #actions
        #matrices
        #units
        #closed
        #named
    }
}

fn type_items(plan: &Plan, names: &Names, i: usize) -> TokenStream {
    let t = &plan.spec.types[i];
    let ty = &names.types[i];
    let fields = &names.fields[i];
    let elements = &names.elements[i];
    let masks = &names.masks[i];
    let count = fields.len();
    let to_runtime: Vec<TokenStream> =
        fields.iter().zip(&names.signs[i]).map(|(f, &s)| Names::signed(quote!(self.#f), s)).collect();
    let from_runtime: Vec<TokenStream> =
        masks.iter().zip(&names.signs[i]).map(|(m, &s)| Names::signed(quote!(m.coeffs()[#m as usize]), s)).collect();
    let basis_doc = format!(
        "Basis elements ({} basis): {}.",
        plan.spec.basis,
        elements.iter().map(|e| format!("`{e}`")).collect::<Vec<_>>().join(", ")
    );
    let docs = t.doc.iter().map(|d| quote!(#[doc = #d]));
    let field_docs = elements.iter().map(|e| format!("Coefficient of `{e}`."));
    let new_doc = format!(
        " A value from its coefficients, in the order of [`Self::ELEMENTS`]: the arguments are the \
         coefficients of {}, in this order. A `const fn`, for geometry known at compile time \
         (`const AXIS: Line<f64> = Line::new(...);`), which the inlined kernels fold.",
        elements.iter().map(|e| format!("`{e}`")).collect::<Vec<_>>().join(", ")
    );
    let one = if masks.contains(&0) {
        let vals = masks.iter().map(|&m| if m == 0 { quote!(T::one()) } else { quote!(T::zero()) });
        quote! {
            /// The identity element.
            pub fn one() -> Self { #ty { #(#fields: #vals),* } }
        }
    } else {
        quote!()
    };
    let unaries = plan.unary.iter().filter(|k| k.ty == i).map(|k| unary_method(names, k));
    let norm = norm_method(names, i, &plan.norm[i]);
    let inverse = inverse_method(plan, names, i);
    let serde_derive = value::serde_attribute(plan);
    let values = value::type_items(names, i);
    quote! {
        #(#docs)*
        #[doc = #basis_doc]
        #[derive(Clone, Copy, PartialEq)]
        #[repr(C)]
        #serde_derive
        pub struct #ty<T> {
            #(#[doc = #field_docs] pub #fields: T,)*
        }

        impl<T: __gam_engine::Ring> #ty<T> {
            /// The basis names of the fields, in order.
            pub const ELEMENTS: [&'static str; #count] = [#(#elements),*];
            /// The bitmasks of the fields' basis elements, in order.
            pub const MASKS: [u32; #count] = [#(#masks),*];

            #[doc = #new_doc]
            #[allow(clippy::too_many_arguments)]
            pub const fn new(#(#fields: T),*) -> Self { #ty { #(#fields),* } }

            /// Zero.
            pub fn zero() -> Self { #ty { #(#fields: T::zero()),* } }

            #one

            /// Every coefficient multiplied by `s`.
            pub fn scale(&self, s: &T) -> Self { #ty { #(#fields: self.#fields.mul_ref(s)),* } }

            /// The same element as a runtime multivector of [`algebra()`].
            pub fn to_multivector(&self) -> __gam_engine::Multivector<T> {
                let mut m = __gam_engine::Multivector::zero(&algebra(), BASIS);
                #(m.coeffs_mut()[#masks as usize] = #to_runtime;)*
                m
            }

            /// The projection of a runtime multivector onto this type: its coefficients on this
            /// type's basis elements (in [`BASIS`]); every other coefficient is dropped.
            ///
            /// # Panics
            /// When `m` belongs to an algebra with fewer basis elements than [`algebra()`]; use
            /// [`Self::try_project`] for multivectors of unknown origin.
            pub fn project(m: &__gam_engine::Multivector<T>) -> Self {
                let m = m.in_basis(BASIS);
                #ty { #(#fields: #from_runtime),* }
            }

            /// [`Self::project`] after checking that `m` belongs to [`algebra()`] (same metric):
            /// `MvError::AlgebraMismatch` otherwise, so a multivector of another (smaller or
            /// larger) algebra is refused instead of indexed.
            pub fn try_project(
                m: &__gam_engine::Multivector<T>,
            ) -> ::core::result::Result<Self, __gam_engine::MvError> {
                Self::check_algebra(m)?;
                Ok(Self::project(m))
            }

            /// `Ok` when `m` belongs to [`algebra()`] (the same metric).
            fn check_algebra(m: &__gam_engine::Multivector<T>) -> ::core::result::Result<(), __gam_engine::MvError> {
                let own = algebra();
                if ::std::sync::Arc::ptr_eq(m.algebra(), &own) || m.algebra().metric() == own.metric() {
                    Ok(())
                } else {
                    Err(__gam_engine::MvError::AlgebraMismatch {
                        left: ::std::string::String::from(m.algebra().name()),
                        right: ::std::string::String::from(own.name()),
                    })
                }
            }

            /// A general element with symbolic coefficients named `prefix` + the basis label
            /// (`m`, `m12`, ... for the prefix `m`), for scalars with symbols (`Poly`). Avoid
            /// the prefixes `S`, `E`, `I`, `N`, `O`, `Q`, `C` if the results go to sympy.
            pub fn symbolic(prefix: &str) -> Self
            where
                T: __gam_engine::Symbolic,
            {
                #ty { #(#fields: <T as __gam_engine::Symbolic>::coefficient(prefix, #elements)),* }
            }

            /// The sandwich `f_S(x) = rev(S) x S` of the main paper (eq. 3); a fused kernel typed
            /// to `x`'s type when `Self` is a versor type (see the `Sandwich` trait).
            pub fn sandwich<X>(&self, x: &X) -> <Self as __gam_engine::ops::Sandwich<X>>::Output
            where
                Self: __gam_engine::ops::Sandwich<X>,
            {
                __gam_engine::ops::Sandwich::sandwich(self, x)
            }

            /// The action `S x rev(S)` (the klein/GATL/ganja convention); a fused kernel typed to
            /// `x`'s type when `Self` is a versor type (see the `Apply` trait).
            pub fn apply<X>(&self, x: &X) -> <Self as __gam_engine::ops::Apply<X>>::Output
            where
                Self: __gam_engine::ops::Apply<X>,
            {
                __gam_engine::ops::Apply::apply(self, x)
            }

            /// `self x rev(self)` for a unit versor (`self rev(self) = 1`), cheaper than
            /// [`Self::apply`]: `x + (self x - x self) rev(self)`. Not the action otherwise.
            pub fn apply_unit<X>(&self, x: &X) -> X
            where
                Self: __gam_engine::ops::UnitAction<X>,
            {
                __gam_engine::ops::UnitAction::apply_unit(self, x)
            }

            /// `rev(self) x self` for a unit versor, as `x + (rev(self) x - x rev(self)) self`.
            pub fn sandwich_unit<X>(&self, x: &X) -> X
            where
                Self: __gam_engine::ops::UnitAction<X>,
            {
                __gam_engine::ops::UnitAction::sandwich_unit(self, x)
            }

            /// The matrix of the action `x ↦ self x rev(self)` on `X` (see `ActionMatrix`):
            /// `let m = motor.apply_matrix::<Point<f64>>();` then `Motor::transform(&m, &p)`
            /// per point equals `motor.apply(&p)`.
            pub fn apply_matrix<X>(&self) -> <Self as __gam_engine::ops::ActionMatrix<X>>::Matrix
            where
                Self: __gam_engine::ops::ActionMatrix<X>,
            {
                __gam_engine::ops::ActionMatrix::apply_matrix(self)
            }

            /// The matrix of the action `x ↦ rev(self) x self` on `X` (see `ActionMatrix`).
            pub fn sandwich_matrix<X>(&self) -> <Self as __gam_engine::ops::ActionMatrix<X>>::Matrix
            where
                Self: __gam_engine::ops::ActionMatrix<X>,
            {
                __gam_engine::ops::ActionMatrix::sandwich_matrix(self)
            }

            /// An action matrix of this type applied to `x` (see `ActionMatrix`).
            pub fn transform<X>(m: &<Self as __gam_engine::ops::ActionMatrix<X>>::Matrix, x: &X) -> X
            where
                Self: __gam_engine::ops::ActionMatrix<X>,
            {
                <Self as __gam_engine::ops::ActionMatrix<X>>::transform(m, x)
            }

            /// The join `self ∨ x` (the regressive product, also `self & x`):
            /// `undual(dual(self) ^ dual(x))` with the metric-free complements of `dual`, so it
            /// is the same in degenerate metrics (PGA) as in non-degenerate ones.
            pub fn join<X>(&self, x: &X) -> <Self as __gam_engine::ops::RegressiveProduct<X>>::Output
            where
                Self: __gam_engine::ops::RegressiveProduct<X>,
            {
                __gam_engine::ops::RegressiveProduct::regressive(self, x)
            }

            /// The geometric product computed only on `O`'s components (the projection of
            /// `self * x` onto `O`): `let r: Rotor<f64> = a.gp_into(&b);` or
            /// `a.gp_into::<Rotor<f64>, _>(&b)`. See `GeometricProductInto`.
            pub fn gp_into<O, X>(&self, x: &X) -> O
            where
                Self: __gam_engine::ops::GeometricProductInto<X, O>,
            {
                __gam_engine::ops::GeometricProductInto::gp_into(self, x)
            }

            #(#unaries)*
            #norm
        }

        #inverse
        #values

        impl<T: __gam_engine::Ring> ::core::convert::TryFrom<&__gam_engine::Multivector<T>> for #ty<T> {
            type Error = __gam_engine::MvError;
            /// Exact conversion: fails if the multivector has a non-zero coefficient outside this type.
            fn try_from(m: &__gam_engine::Multivector<T>) -> ::core::result::Result<Self, Self::Error> {
                Self::check_algebra(m)?;
                let converted = m.in_basis(BASIS);
                for (mask, name, _) in converted.terms() {
                    if !Self::MASKS.contains(&mask) {
                        return Err(__gam_engine::MvError::OutsideType {
                            ty: ::std::string::String::from(stringify!(#ty)),
                            element: ::std::string::String::from(name),
                        });
                    }
                }
                Ok(Self::project(&converted))
            }
        }

        impl<T: __gam_engine::Ring> ::core::convert::From<&#ty<T>> for __gam_engine::Multivector<T> {
            fn from(x: &#ty<T>) -> Self { x.to_multivector() }
        }

        impl<T: __gam_engine::Ring> ::core::fmt::Display for #ty<T> {
            /// A sum of basis elements: `1 + 1/2*e1inf`; `0` for zero.
            fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
                let terms = [#((#elements, &self.#fields)),*];
                f.write_str(&__gam_engine::multivector::display::join_terms(
                    terms.iter().filter(|(_, c)| !__gam_engine::Ring::is_exact_zero(*c)).map(|(n, c)| {
                        __gam_engine::multivector::display::format_term(&::std::string::ToString::to_string(c), n)
                    }),
                ))
            }
        }

        impl<T: __gam_engine::Ring> ::core::fmt::Debug for #ty<T> {
            fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
                write!(f, "{}({})", stringify!(#ty), self)
            }
        }

        impl<T: __gam_engine::Ring> ::core::ops::Add for #ty<T> {
            type Output = Self;
            fn add(self, rhs: Self) -> Self { #ty { #(#fields: self.#fields + rhs.#fields),* } }
        }
        impl<T: __gam_engine::Ring> ::core::ops::Add for &#ty<T> {
            type Output = #ty<T>;
            fn add(self, rhs: Self) -> #ty<T> { #ty { #(#fields: self.#fields.add_ref(&rhs.#fields)),* } }
        }
        impl<T: __gam_engine::Ring> ::core::ops::Sub for #ty<T> {
            type Output = Self;
            fn sub(self, rhs: Self) -> Self { #ty { #(#fields: self.#fields - rhs.#fields),* } }
        }
        impl<T: __gam_engine::Ring> ::core::ops::Sub for &#ty<T> {
            type Output = #ty<T>;
            fn sub(self, rhs: Self) -> #ty<T> { #ty { #(#fields: self.#fields.sub_ref(&rhs.#fields)),* } }
        }
        impl<T: __gam_engine::Ring> ::core::ops::Neg for #ty<T> {
            type Output = Self;
            fn neg(self) -> Self { #ty { #(#fields: -self.#fields),* } }
        }
        impl<T: __gam_engine::Ring> ::core::ops::Neg for &#ty<T> {
            type Output = #ty<T>;
            fn neg(self) -> #ty<T> { #ty { #(#fields: self.#fields.neg_ref()),* } }
        }
    }
}

fn unary_method(names: &Names, k: &UnaryKernel) -> TokenStream {
    let method = ident(unary_name(k.op));
    let out = &names.types[k.out];
    let in_fields = &names.fields[k.ty];
    let out_fields = &names.fields[k.out];
    let exprs = k.outputs.iter().map(|terms| {
        sum(terms
            .iter()
            .map(|(a, c)| {
                let f = &in_fields[*a];
                (*c, quote!(self.#f), false)
            })
            .collect())
    });
    let doc = format!("The {} (a linear map; output type chosen at generation).", unary_name(k.op).replace('_', " "));
    quote! {
        #[doc = #doc]
        pub fn #method(&self) -> #out<T> { #out { #(#out_fields: #exprs),* } }
    }
}

fn norm_method(names: &Names, i: usize, terms: &[Term]) -> TokenStream {
    let fields = &names.fields[i];
    let mut binds = Vec::new();
    let mut parts = Vec::new();
    for (n, t) in terms.iter().enumerate() {
        let p = format_ident!("n{}", n);
        let (a, b) = (&fields[t.lhs], &fields[t.rhs]);
        binds.push(quote!(let #p = self.#a.mul_ref(&self.#b);));
        parts.push((t.coef, quote!(#p), true));
    }
    let expr = sum(parts);
    quote! {
        /// The squared norm `<x rev(x)>_0` (a scalar; may be negative or zero in
        /// non-Euclidean or degenerate metrics).
        pub fn norm_squared(&self) -> T {
            #(#binds)*
            #expr
        }
    }
}

fn inverse_method(plan: &Plan, names: &Names, i: usize) -> TokenStream {
    let ty = &names.types[i];
    if !plan.closed[i] {
        let full = &names.types[plan.full];
        return quote! {
            impl<T: __gam_engine::Field> #ty<T> {
                /// The inverse, computed in the whole algebra (this type is not a subalgebra).
                pub fn inverse(&self) -> ::core::result::Result<#full<T>, __gam_engine::MvError> {
                    Ok(#full::project(&self.to_multivector().inverse()?))
                }
            }
        };
    }
    // Inside a subalgebra containing 1 the inverse stays in it: solve self * y = 1 there.
    let k = plan.kernel(Product::Geometric, i, i);
    let masks = &names.masks[i];
    let fields = &names.fields[i];
    let m = masks.len();
    let mut entries: BTreeMap<(usize, usize), Vec<SumTerm>> = BTreeMap::new();
    for (ko, terms) in k.outputs.iter().enumerate() {
        let row = masks.iter().position(|&mm| mm == names.masks[k.out][ko]).expect("closed type");
        for t in terms {
            let f = &fields[t.lhs];
            entries.entry((row, t.rhs)).or_default().push((t.coef, quote!(self.#f), false));
        }
    }
    let large = names.is_large(&[i], k.outputs.iter().map(Vec::len));
    let fill = if large {
        let mut flat = Vec::new();
        for (ko, terms) in k.outputs.iter().enumerate() {
            let row = masks.iter().position(|&mm| mm == names.masks[k.out][ko]).expect("closed type");
            flat.extend(terms.iter().map(|t| (t.lhs, t.rhs, row, t.coef)));
        }
        size::matrix_fill(&flat)
    } else {
        let sets = entries.into_iter().map(|((r, c), terms)| {
            let e = sum(terms);
            quote!(l[#r][#c] = #e;)
        });
        quote!(#(#sets)*)
    };
    let one_row = masks.iter().position(|&mm| mm == 0).expect("contains 1");
    quote! {
        impl<T: __gam_engine::Field> #ty<T> {
            /// The inverse, which stays in this type (a subalgebra containing 1): solves
            /// `self * y = 1` within it. Fails for zero divisors.
            pub fn inverse(&self) -> ::core::result::Result<Self, __gam_engine::MvError> {
                let mut l: ::std::vec::Vec<::std::vec::Vec<T>> = ::std::vec![::std::vec![T::zero(); #m]; #m];
                #fill
                let mut rhs = ::std::vec![T::zero(); #m];
                rhs[#one_row] = T::one();
                let y = __gam_engine::linalg::solve(l, rhs)
                    .ok_or_else(|| __gam_engine::MvError::NotInvertible(::std::string::ToString::to_string(self)))?;
                let mut it = y.into_iter();
                Ok(#ty { #(#fields: it.next().expect("one value per field")),* })
            }
        }
    }
}

/// The body of a binary kernel: straight-line code, or a table loop above the size threshold
/// or over an automatic type among `types` ([`Names::is_large`]).
fn kernel_body(names: &Names, k: &BinaryKernel, types: &[usize]) -> TokenStream {
    if names.is_large(types, k.outputs.iter().map(Vec::len)) {
        return size::binary_body(names, k);
    }
    let (lf, rf, of) = (&names.fields[k.lhs], &names.fields[k.rhs], &names.fields[k.out]);
    let ot = &names.types[k.out];
    let mut uses: BTreeMap<(usize, usize), usize> = BTreeMap::new();
    for t in k.outputs.iter().flatten() {
        *uses.entry((t.lhs, t.rhs)).or_default() += 1;
    }
    let binds = uses.keys().map(|&(a, b)| {
        let p = format_ident!("p{}_{}", a, b);
        let (fa, fb) = (&lf[a], &rf[b]);
        quote!(let #p = self.#fa.mul_ref(&rhs.#fb);)
    });
    let mut moved = std::collections::BTreeSet::new();
    let exprs: Vec<TokenStream> = k
        .outputs
        .iter()
        .map(|terms| {
            chunked_sum(
                terms
                    .iter()
                    .map(|t| {
                        let p = format_ident!("p{}_{}", t.lhs, t.rhs);
                        let movable = uses[&(t.lhs, t.rhs)] == 1 && moved.insert((t.lhs, t.rhs));
                        (t.coef, quote!(#p), movable)
                    })
                    .collect(),
                k.chain,
            )
        })
        .collect();
    quote! {
        #(#binds)*
        #ot { #(#of: #exprs),* }
    }
}

fn binary_items(names: &Names, k: &BinaryKernel) -> TokenStream {
    let (lt, rt, ot) = (&names.types[k.lhs], &names.types[k.rhs], &names.types[k.out]);
    let (trait_name, method) = product_trait(k.product);
    let (trait_name, method) = (ident(trait_name), ident(method));
    let operator = product_operator(k.product).map(|(op_trait, op_method)| {
        let (op_trait, op_method) = (ident(op_trait), ident(op_method));
        quote! {
            impl<T: __gam_engine::Ring> ::core::ops::#op_trait<&#rt<T>> for &#lt<T> {
                type Output = #ot<T>;
                fn #op_method(self, rhs: &#rt<T>) -> #ot<T> { __gam_engine::ops::#trait_name::#method(self, rhs) }
            }
            impl<T: __gam_engine::Ring> ::core::ops::#op_trait<#rt<T>> for #lt<T> {
                type Output = #ot<T>;
                fn #op_method(self, rhs: #rt<T>) -> #ot<T> { __gam_engine::ops::#trait_name::#method(&self, &rhs) }
            }
        }
    });
    let mixed = value::mixed_operators(names, k);
    // a product of declared types stays straight-line when it lands in an automatic type
    // (`Motor * Plane` in an odd type the plan added)
    let body = kernel_body(names, k, &[k.lhs, k.rhs]);
    let typed = if k.product == Product::Geometric {
        // `gp_into` with the natural output type is `gp` itself
        quote! {
            impl<T: __gam_engine::Ring> __gam_engine::ops::GeometricProductInto<#rt<T>, #ot<T>> for #lt<T> {
                #[inline]
                fn gp_into(&self, rhs: &#rt<T>) -> #ot<T> { __gam_engine::ops::GeometricProduct::gp(self, rhs) }
            }
        }
    } else {
        quote!()
    };
    quote! {
        impl<T: __gam_engine::Ring> __gam_engine::ops::#trait_name<#rt<T>> for #lt<T> {
            type Output = #ot<T>;
            #[inline]
            fn #method(&self, rhs: &#rt<T>) -> #ot<T> {
                #body
            }
        }
        #typed
        #operator
        #mixed
    }
}

/// An output-typed geometric product (`GeometricProductInto<Rhs, Out>`): only `Out`'s terms.
fn typed_items(names: &Names, k: &BinaryKernel) -> TokenStream {
    let (lt, rt, ot) = (&names.types[k.lhs], &names.types[k.rhs], &names.types[k.out]);
    let body = kernel_body(names, k, &[k.lhs, k.rhs, k.out]);
    quote! {
        impl<T: __gam_engine::Ring> __gam_engine::ops::GeometricProductInto<#rt<T>, #ot<T>> for #lt<T> {
            #[inline]
            fn gp_into(&self, rhs: &#rt<T>) -> #ot<T> {
                #body
            }
        }
    }
}

/// `From` embeddings (A ⊂ B) and named projections (`project_to_b`) between declared types.
fn conversion_items(names: &Names) -> TokenStream {
    let mut items = Vec::new();
    for a in 0..names.types.len() {
        for b in 0..names.types.len() {
            if a == b {
                continue;
            }
            let (ta, tb) = (&names.types[a], &names.types[b]);
            let (ma, mb) = (&names.masks[a], &names.masks[b]);
            let fb = &names.fields[b];
            // the value of each target field, read from `recv`
            let vals = |recv: TokenStream| -> Vec<TokenStream> {
                mb.iter()
                    .zip(&names.signs[b])
                    .map(|(m, sb)| match ma.iter().position(|x| x == m) {
                        Some(p) => {
                            let f = &names.fields[a][p];
                            Names::signed(quote!(#recv.#f), names.signs[a][p] * sb)
                        }
                        None => quote!(T::zero()),
                    })
                    .collect()
            };
            if ma.iter().all(|m| mb.contains(m)) {
                let vals = vals(quote!(x));
                items.push(quote! {
                    impl<T: __gam_engine::Ring> ::core::convert::From<&#ta<T>> for #tb<T> {
                        /// The embedding (every basis element of the source is in the target).
                        fn from(x: &#ta<T>) -> Self { #tb { #(#fb: #vals),* } }
                    }
                });
            } else {
                let vals = vals(quote!(self));
                let method = format_ident!("project_to_{}", snake(&tb.to_string()));
                let doc = format!("The projection onto [`{tb}`]: shared coefficients kept, the others dropped.");
                items.push(quote! {
                    impl<T: __gam_engine::Ring> #ta<T> {
                        #[doc = #doc]
                        pub fn #method(&self) -> #tb<T> { #tb { #(#fb: #vals),* } }
                    }
                });
            }
        }
    }
    quote!(#(#items)*)
}
