//! Small helpers on 3-vectors `[T; 3]` (dot, cross, sums, scaling, length), shared by the
//! representations of this module.

use algebra_core::{Real, Ring};

pub(crate) fn dot<T: Ring>(a: &[T; 3], b: &[T; 3]) -> T {
    a[0].mul_ref(&b[0]) + a[1].mul_ref(&b[1]) + a[2].mul_ref(&b[2])
}

pub(crate) fn cross<T: Ring>(a: &[T; 3], b: &[T; 3]) -> [T; 3] {
    [
        a[1].mul_ref(&b[2]).sub_ref(&a[2].mul_ref(&b[1])),
        a[2].mul_ref(&b[0]).sub_ref(&a[0].mul_ref(&b[2])),
        a[0].mul_ref(&b[1]).sub_ref(&a[1].mul_ref(&b[0])),
    ]
}

pub(crate) fn add<T: Ring>(a: &[T; 3], b: &[T; 3]) -> [T; 3] {
    std::array::from_fn(|i| a[i].add_ref(&b[i]))
}

pub(crate) fn sub<T: Ring>(a: &[T; 3], b: &[T; 3]) -> [T; 3] {
    std::array::from_fn(|i| a[i].sub_ref(&b[i]))
}

pub(crate) fn scale<T: Ring>(s: &T, a: &[T; 3]) -> [T; 3] {
    std::array::from_fn(|i| s.mul_ref(&a[i]))
}

pub(crate) fn zero<T: Ring>() -> [T; 3] {
    [T::zero(), T::zero(), T::zero()]
}

/// `|a|`, overflow-safe.
pub(crate) fn norm<T: Real>(a: &[T; 3]) -> T {
    crate::scaled::length(a).unwrap_or_else(T::zero)
}
