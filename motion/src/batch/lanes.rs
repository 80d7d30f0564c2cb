//! [`Lanes`]: a scalar that holds [`Lanes::WIDTH`] values of an element type and computes on
//! all of them at once (a SIMD vector), and the packing of `f64`/`f32` columns into lane chunks
//! and back.
//!
//! Every batch kernel is written once, generic over `L: Lanes`: it loads `WIDTH` consecutive
//! values of each column into one `L`, runs the ordinary generic pose code (generated products,
//! [`Pose::action_rows`], Bezier evaluation over [`Jet`](algebra_core::Jet)) on `L`, and stores
//! the lanes back. A plain scalar is a lane type of width 1 (`f64`, `f32`, the exact [`Q`]), so
//! the same kernel is the scalar loop; with the feature `lanes` (on by default) algebra-core's
//! SIMD scalars `F64x2`, `F64x4` (elements `f64`) and `F32x4`, `F32x8` (elements `f32`) are lane
//! types too. The last chunk of a column whose length is not a multiple
//! of the width is padded (zeros for points, the identity for poses) and only its real lanes
//! are stored.
//!
//! ```
//! use motion::batch::Lanes;
//! let x = <f64 as Lanes>::load(&[2.5]);
//! let mut out = [0.0];
//! Lanes::store(&(x * 2.0), &mut out);
//! assert_eq!((out, <f64 as Lanes>::WIDTH), ([5.0], 1));
//! ```

use algebra_core::Field;
use algebra_core::rational::Q;

/// A scalar made of [`Lanes::WIDTH`] values of [`Lanes::Elem`], computing lane by lane.
///
/// The arithmetic of the [`Field`] supertrait must be lane by lane (each lane the IEEE result
/// of the element operation), so a batch kernel over `L` gives, in every lane, exactly what the
/// scalar code gives for that element. Decisions that look at values (a reciprocal that does not
/// exist) are made per lane by [`Lanes::recip_lanes`].
///
/// ```
/// use motion::batch::Lanes;
/// fn sum_of_squares<L: Lanes>(xs: &[L::Elem]) -> L {
///     let v = L::load(xs);
///     v.clone() * v
/// }
/// assert_eq!(sum_of_squares::<f64>(&[3.0]), 9.0);
/// ```
pub trait Lanes: Field + Send + Sync {
    /// The element type of one lane.
    type Elem: Field + Send + Sync;
    /// The number of lanes.
    const WIDTH: usize;

    /// Every lane equal to `x`.
    ///
    /// ```
    /// assert_eq!(<f32 as motion::batch::Lanes>::splat(&1.5), 1.5);
    /// ```
    fn splat(x: &Self::Elem) -> Self;

    /// Lane `i` from `xs[i]`; `xs` has exactly [`Lanes::WIDTH`] elements.
    ///
    /// ```
    /// assert_eq!(<f64 as motion::batch::Lanes>::load(&[4.0]), 4.0);
    /// ```
    fn load(xs: &[Self::Elem]) -> Self;

    /// Writes lane `i` to `out[i]` for `i < out.len()` (at most [`Lanes::WIDTH`] lanes: the
    /// last chunk of a column stores only its real lanes).
    ///
    /// ```
    /// let mut out = [0.0f64];
    /// motion::batch::Lanes::store(&7.0f64, &mut out);
    /// assert_eq!(out, [7.0]);
    /// ```
    fn store(&self, out: &mut [Self::Elem]);

    /// The reciprocal lane by lane, or the index of the first lane whose element has none
    /// ([`Field::try_recip`] of that lane is `None`: zero, or a reciprocal that overflows).
    ///
    /// ```
    /// use motion::batch::Lanes;
    /// assert_eq!(Lanes::recip_lanes(&4.0f64), Ok(0.25));
    /// assert_eq!(Lanes::recip_lanes(&0.0f64), Err(0));
    /// ```
    fn recip_lanes(&self) -> Result<Self, usize>;
}

/// A plain scalar is a lane type of width 1: the batch kernels over it are the scalar loops.
macro_rules! width_one {
    ($($t:ty),*) => {$(
        impl Lanes for $t {
            type Elem = $t;
            const WIDTH: usize = 1;
            fn splat(x: &$t) -> $t {
                x.clone()
            }
            fn load(xs: &[$t]) -> $t {
                xs[0].clone()
            }
            fn store(&self, out: &mut [$t]) {
                if let Some(o) = out.first_mut() {
                    *o = self.clone();
                }
            }
            fn recip_lanes(&self) -> Result<$t, usize> {
                self.try_recip().ok_or(0)
            }
        }
    )*};
}

width_one!(f64, f32, Q);

/// algebra-core's SIMD lane scalars (feature `lanes`): arithmetic lane by lane (IEEE per lane).
#[cfg(feature = "lanes")]
macro_rules! simd {
    ($($t:ident: $e:ty, $n:literal;)*) => {$(
        impl Lanes for algebra_core::scalar::$t {
            type Elem = $e;
            const WIDTH: usize = $n;
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
            fn recip_lanes(&self) -> Result<Self, usize> {
                self.try_recip().ok_or_else(|| {
                    self.to_array().iter().position(|x| x.try_recip().is_none()).unwrap_or(0)
                })
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

/// `xs` loaded into one lane value, padded with `pad` when `xs` is shorter than the width (the
/// remainder of a column).
#[inline]
pub(crate) fn load_padded<L: Lanes>(xs: &[L::Elem], pad: &L::Elem) -> L {
    if xs.len() == L::WIDTH { L::load(xs) } else { load_remainder(xs, pad) }
}

#[cold]
fn load_remainder<L: Lanes>(xs: &[L::Elem], pad: &L::Elem) -> L {
    let mut full = xs.to_vec();
    full.resize(L::WIDTH, pad.clone());
    L::load(&full)
}
