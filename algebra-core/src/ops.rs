//! Product traits implemented by generated multivector types (the `algebra!` macro) for every
//! pair of declared types, so that `a.lc(&b)` works whatever the operand types. The geometric
//! and outer products also get the operators `*` and `^`, the left contraction `|` and the
//! regressive product (the join) `&`.

/// The geometric product `self * rhs`.
pub trait GeometricProduct<Rhs: ?Sized> {
    /// The smallest declared type holding the result.
    type Output;
    /// `self * rhs`.
    fn gp(&self, rhs: &Rhs) -> Self::Output;
}

/// The geometric product computed only on the components of a type `Out` chosen by the
/// caller: the projection of `self * rhs` onto `Out` (coefficients outside `Out` are dropped,
/// and never computed). Generated for every pair of declared types and every declared `Out`
/// sharing a basis element with the product's support; the result type selects the kernel
/// (`let r: Rotor<f64> = a.gp_into(&b);`).
pub trait GeometricProductInto<Rhs: ?Sized, Out> {
    /// `<self * rhs>_Out`.
    fn gp_into(&self, rhs: &Rhs) -> Out;
}

/// The outer product `self ^ rhs`.
pub trait OuterProduct<Rhs: ?Sized> {
    /// The smallest declared type holding the result.
    type Output;
    /// `self ^ rhs`.
    fn op(&self, rhs: &Rhs) -> Self::Output;
}

/// The left contraction `self ⌋ rhs` (also the operator `|`).
pub trait LeftContraction<Rhs: ?Sized> {
    /// The smallest declared type holding the result.
    type Output;
    /// `self ⌋ rhs`.
    fn lc(&self, rhs: &Rhs) -> Self::Output;
}

/// The right contraction `self ⌊ rhs`.
pub trait RightContraction<Rhs: ?Sized> {
    /// The smallest declared type holding the result.
    type Output;
    /// `self ⌊ rhs`.
    fn rc(&self, rhs: &Rhs) -> Self::Output;
}

/// The scalar product `<self rhs>_0`.
pub trait ScalarProduct<Rhs: ?Sized> {
    /// The smallest declared type holding the result.
    type Output;
    /// `<self rhs>_0`.
    fn sp(&self, rhs: &Rhs) -> Self::Output;
}

/// The regressive product (the join) `self ∨ rhs = undual(dual(self) ^ dual(rhs))`, with the
/// metric-free complements of `dual` (so it needs no invertible pseudoscalar); also the
/// operator `&` and the generated types' `join` method.
pub trait RegressiveProduct<Rhs: ?Sized> {
    /// The smallest declared type holding the result.
    type Output;
    /// `self ∨ rhs`.
    fn regressive(&self, rhs: &Rhs) -> Self::Output;
}

/// The commutator product `(self rhs - rhs self)/2` (the main paper's `∧`).
pub trait CommutatorProduct<Rhs: ?Sized> {
    /// The smallest declared type holding the result.
    type Output;
    /// `(self rhs - rhs self)/2`.
    fn commutator(&self, rhs: &Rhs) -> Self::Output;
}

/// The anticommutator product `(self rhs + rhs self)/2` (the main paper's `·`).
pub trait AnticommutatorProduct<Rhs: ?Sized> {
    /// The smallest declared type holding the result.
    type Output;
    /// `(self rhs + rhs self)/2`.
    fn anticommutator(&self, rhs: &Rhs) -> Self::Output;
}

/// The main paper's sandwich `f_S(x) = rev(S) x S` (eq. 3). For a versor type `S` and a
/// declared operand type `X` the generated impl is one fused kernel returning `X`: the
/// projection of `rev(S) x S` onto `X`, which is the action itself whenever `S` is a versor
/// whose action preserves `X`'s grades (motors and rotors on vectors, bivectors, motors).
/// Other pairs return the full product's type.
pub trait Sandwich<X: ?Sized> {
    /// `X` for a fused kernel, else the smallest declared type holding `rev(S) x S`.
    type Output;
    /// `rev(self) x self`.
    fn sandwich(&self, x: &X) -> Self::Output;
}

/// The versor action `S x rev(S)` in the convention of klein, GATL and ganja (the reverse of
/// [`Sandwich`]'s: `s.apply(x) == s.reverse().sandwich(x)`), fused and typed as
/// [`Sandwich`] is.
pub trait Apply<X: ?Sized> {
    /// `X` for a fused kernel, else the smallest declared type holding `S x rev(S)`.
    type Output;
    /// `self x rev(self)`.
    fn apply(&self, x: &X) -> Self::Output;
}

/// The versor action on `X` as a matrix, for transforming many values by one versor: the
/// action is linear in `x`, so `transform(&s.apply_matrix(), &x) == s.apply(&x)` (and the
/// same for `sandwich`), exactly, with the matrix (entries quadratic in `self`) computed once.
/// Generated for each fused action whose matrix is small (motors and rotors on points,
/// vectors, lines, planes).
pub trait ActionMatrix<X> {
    /// `[[T; LEN]; LEN]` for `X` of `LEN` coefficients, row = output coefficient.
    type Matrix;
    /// The matrix of `x ↦ <rev(self) x self>_X` ([`Sandwich`]).
    fn sandwich_matrix(&self) -> Self::Matrix;
    /// The matrix of `x ↦ <self x rev(self)>_X` ([`Apply`]).
    fn apply_matrix(&self) -> Self::Matrix;
    /// The matrix applied to `x` (skipping entries that are structurally zero).
    fn transform(m: &Self::Matrix, x: &X) -> X;
}

/// The versor action for *unit* versors (`S rev(S) = 1`), typed and fused as [`Apply`] and
/// [`Sandwich`] but cheaper: since `x S rev(S) = x`, the action is `x + (S x - x S) rev(S)`,
/// and the commutator drops every part of `S` that commutes with `x`. Exact over any ring when
/// `S rev(S) = 1` holds exactly; for other versors the result is not the action. Generated for
/// every pair with a fused kernel (`apply_unit`/`sandwich_unit`; an example is in `gam_algebras`'
/// crate docs).
pub trait UnitAction<X> {
    /// `rev(self) x self` ([`Sandwich`]) for a unit `self`.
    fn sandwich_unit(&self, x: &X) -> X;
    /// `self x rev(self)` ([`Apply`]) for a unit `self`.
    fn apply_unit(&self, x: &X) -> X;
}
