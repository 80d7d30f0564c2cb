//! Product traits implemented by generated multivector types (the `algebra!` macro) for every
//! pair of declared types, so that `a.lc(&b)` works whatever the operand types. The geometric
//! and outer products also get the operators `*` and `^`, and the left contraction `|`.

/// The geometric product `self * rhs`.
pub trait GeometricProduct<Rhs: ?Sized> {
    /// The smallest declared type holding the result.
    type Output;
    /// `self * rhs`.
    fn gp(&self, rhs: &Rhs) -> Self::Output;
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

/// The regressive product `self ∨ rhs`.
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
