//! [`Lanes`]: a scalar that holds [`Lanes::WIDTH`] values of an element type and computes on
//! all of them at once (a SIMD vector), with the packing of element columns into lane values
//! and back.
//!
//! A plain scalar is a lane type of width 1 (`f64`, `f32`, the exact [`Q`]), so code written
//! once over `L: Lanes` is also the scalar loop; with the feature `lanes` the SIMD scalars
//! `F64x2`, `F64x4` (elements `f64`) and `F32x4`, `F32x8` (elements `f32`) are lane types too, their
//! trait methods the inherent `splat`, `From<[T; N]>` and `to_array` (one definition each).
//! `motion::batch` writes every batch kernel over it (and re-exports it as
//! `motion::batch::Lanes`).
//!
//! Dual numbers ([`Jet`](crate::Jet), [`LaneDual`](super::LaneDual)) are not lane types of
//! dual elements: a batch of dual numbers is two columns (values and derivative parts), each
//! packed with a lane type, and a `Jet<L>` over a lane type `L` is how the batch sampler
//! differentiates.
//!
//! ```
//! use algebra_core::scalar::Lanes;
//! let x = <f64 as Lanes>::load(&[2.5]);
//! let mut out = [0.0];
//! Lanes::store(&(x * 2.0), &mut out);
//! assert_eq!((out, <f64 as Lanes>::WIDTH), ([5.0], 1));
//! ```

use super::{Field, Ring};
use crate::rational::Q;

/// A scalar made of [`Lanes::WIDTH`] values of [`Lanes::Elem`], computing lane by lane.
///
/// The arithmetic of the [`Field`] supertrait must be lane by lane (each lane the IEEE result
/// of the element operation), so code generic over `L` gives, in every lane, exactly what the
/// scalar code gives for that element. Decisions that look at values (a reciprocal that does
/// not exist) are made per lane by [`Lanes::recip_lanes`].
///
/// ```
/// use algebra_core::scalar::Lanes;
/// fn square<L: Lanes>(xs: &[L::Elem]) -> L {
///     let v = L::load(xs);
///     v.clone() * v
/// }
/// assert_eq!(square::<f64>(&[3.0]), 9.0);
/// ```
pub trait Lanes: Field + Send + Sync {
    /// The element type of one lane.
    type Elem: Field + Send + Sync;
    /// The number of lanes.
    const WIDTH: usize;

    /// Every lane equal to `x`.
    ///
    /// ```
    /// assert_eq!(<f32 as algebra_core::scalar::Lanes>::splat(&1.5), 1.5);
    /// ```
    fn splat(x: &Self::Elem) -> Self;

    /// Lane `i` from `xs[i]`; `xs` has exactly [`Lanes::WIDTH`] elements.
    ///
    /// ```
    /// assert_eq!(<f64 as algebra_core::scalar::Lanes>::load(&[4.0]), 4.0);
    /// ```
    fn load(xs: &[Self::Elem]) -> Self;

    /// Writes lane `i` to `out[i]` for `i < out.len()` (at most [`Lanes::WIDTH`] lanes: the
    /// last chunk of a column stores only its real lanes).
    ///
    /// ```
    /// let mut out = [0.0f64];
    /// algebra_core::scalar::Lanes::store(&7.0f64, &mut out);
    /// assert_eq!(out, [7.0]);
    /// ```
    fn store(&self, out: &mut [Self::Elem]);

    /// `xs` loaded into one lane value, the lanes past `xs.len()` (at most
    /// [`Lanes::WIDTH`]) equal to `pad`: the remainder chunk of a column.
    ///
    /// ```
    /// use algebra_core::scalar::Lanes;
    /// assert_eq!(<f64 as Lanes>::load_padded(&[], &1.0), 1.0);
    /// assert_eq!(<f64 as Lanes>::load_padded(&[2.0], &1.0), 2.0);
    /// ```
    #[inline]
    fn load_padded(xs: &[Self::Elem], pad: &Self::Elem) -> Self {
        if xs.len() == Self::WIDTH { Self::load(xs) } else { load_remainder(xs, pad) }
    }

    /// The reciprocal lane by lane, or the index of the first lane whose element has none
    /// ([`Field::try_recip`] of that lane is `None`: zero, or a reciprocal that overflows).
    ///
    /// ```
    /// use algebra_core::scalar::Lanes;
    /// assert_eq!(Lanes::recip_lanes(&4.0f64), Ok(0.25));
    /// assert_eq!(Lanes::recip_lanes(&0.0f64), Err(0));
    /// ```
    fn recip_lanes(&self) -> Result<Self, usize> {
        self.try_recip().ok_or_else(|| {
            let mut lanes = vec![Self::Elem::zero(); Self::WIDTH];
            self.store(&mut lanes);
            lanes.iter().position(|x| x.try_recip().is_none()).unwrap_or(0)
        })
    }
}

#[cold]
fn load_remainder<L: Lanes>(xs: &[L::Elem], pad: &L::Elem) -> L {
    let mut full = xs.to_vec();
    full.resize(L::WIDTH, pad.clone());
    L::load(&full)
}

/// A plain scalar is a lane type of width 1: code over it is the scalar loop.
macro_rules! width_one {
    ($($t:ty),*) => {$(
        impl Lanes for $t {
            type Elem = $t;
            const WIDTH: usize = 1;
            #[inline]
            fn splat(x: &$t) -> $t {
                x.clone()
            }
            #[inline]
            fn load(xs: &[$t]) -> $t {
                xs[0].clone()
            }
            #[inline]
            fn store(&self, out: &mut [$t]) {
                if let Some(o) = out.first_mut() {
                    *o = self.clone();
                }
            }
        }
    )*};
}

width_one!(f64, f32, Q);

/// The SIMD lane scalars (feature `lanes`): the trait methods are their inherent `LANES`,
/// `splat`, `From<[T; N]>` and `to_array`.
#[cfg(feature = "lanes")]
macro_rules! simd {
    ($($t:ident: $e:ty, $n:literal;)*) => {$(
        impl Lanes for super::$t {
            type Elem = $e;
            const WIDTH: usize = Self::LANES;
            #[inline]
            fn splat(x: &$e) -> Self {
                Self::splat(*x)
            }
            #[inline]
            fn load(xs: &[$e]) -> Self {
                let lanes: [$e; $n] = xs.try_into().expect("a full chunk");
                Self::from(lanes)
            }
            #[inline]
            fn store(&self, out: &mut [$e]) {
                let lanes = self.to_array();
                match <&mut [$e; $n]>::try_from(&mut *out) {
                    Ok(full) => *full = lanes,
                    // the remainder chunk: element by element (a `copy_from_slice` of a
                    // runtime length is a `memcpy` call on every chunk)
                    Err(_) => out.iter_mut().zip(lanes).for_each(|(o, x)| *o = x),
                }
            }
        }
    )*};
}

#[cfg(feature = "lanes")]
simd! {
    F64x2: f64, 2;
    F64x4: f64, 4;
    F32x4: f32, 4;
    F32x8: f32, 8;
}
