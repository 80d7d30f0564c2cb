//! Lane scalars (feature `lanes`): [`F32x4`], [`F32x8`], [`F64x2`], [`F64x4`], newtypes over the
//! `wide` crate's SIMD vectors. One value of a lane type is 2, 4 or 8 independent scalars; a
//! generated kernel over it (straight-line code, no comparisons) computes 2, 4 or 8 products
//! at once.
//!
//! They are [`Ring`]s and [`Field`]s with every operation lane by lane, and
//! [`LaneReal`](super::LaneReal)s ([`Elementary`], [`Select`], [`Diagnostics`]); never
//! `PartialOrd`, never [`Real`](crate::Real). The few whole-vector answers the traits ask
//! for are documented where they are made:
//!
//! * `==` and [`Ring::is_exact_zero`]: true when it holds in **every** lane;
//! * [`Ring::magnitude`]: the **largest** lane's `|x|` (NaN if a lane is NaN);
//!   [`Ring::relative_epsilon`]: the element type's;
//! * [`Ring::is_finite_value`]: every lane finite; [`Field::try_recip`]: `None` when **any**
//!   lane is zero or has a non-finite reciprocal;
//! * `Display`: the lanes in brackets, `[1, 2, 3, 4]`.
//!
//! Elementary functions are `wide`'s polynomial approximations (a few ulps from the `std`
//! functions on the ranges the tests cover: |x| ≤ 100 for sin/cos, exp without overflow,
//! positive ln, sqrt; checked lane by lane against `std` by proptest).
//!
//! ```
//! use algebra_core::scalar::{F64x4, Select};
//! use algebra_core::Ring;
//! let x = F64x4::from([1.0, 2.0, 3.0, 4.0]);
//! let y = x.mul_ref(&x) - F64x4::splat(2.0);
//! assert_eq!(y.to_array(), [-1.0, 2.0, 7.0, 14.0]);
//! let m = y.lt_mask(&F64x4::zero());
//! assert_eq!(F64x4::select(&m, &F64x4::zero(), &y).to_array(), [0.0, 2.0, 7.0, 14.0]);
//! assert!(!y.is_exact_zero() && y.magnitude() == 14.0);
//! ```

use super::{Diagnostics, Elementary, Field, Mask, Ring, Select};
use crate::rational::{Q, rational_to_f64};
use std::fmt;
use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

macro_rules! lane_type {
    ($name:ident, $mask:ident, $wide:ident, $elem:ident, $n:literal, $doc:literal) => {
        #[doc = $doc]
        ///
        /// ```
        #[doc = concat!("use algebra_core::scalar::", stringify!($name), ";")]
        #[doc = concat!("let x = ", stringify!($name), "::splat(2.0);")]
        #[doc = concat!("assert_eq!((x * x).to_array(), [4.0; ", stringify!($n), "]);")]
        #[doc = concat!("assert_eq!(", stringify!($name), "::from_fn(|i| i as ", stringify!($elem), ").lane(1), 1.0);")]
        /// ```
        #[derive(Clone, Copy, Debug, Default)]
        pub struct $name(pub wide::$wide);

        /// One bit per lane of a
        #[doc = concat!("[`", stringify!($name), "`]")]
        /// comparison (all-ones or all-zeros lanes of the same width).
        #[derive(Clone, Copy, Debug)]
        pub struct $mask(wide::$wide);

        impl $name {
            /// How many lanes.
            pub const LANES: usize = $n;
            /// `x` in every lane.
            #[inline]
            pub fn splat(x: $elem) -> Self {
                Self(wide::$wide::splat(x))
            }
            /// The lanes as an array.
            #[inline]
            pub fn to_array(self) -> [$elem; $n] {
                self.0.to_array()
            }
            /// Lane `i` (`i < LANES`).
            #[inline]
            pub fn lane(self, i: usize) -> $elem {
                self.0.to_array()[i]
            }
            /// The value whose lane `i` is `f(i)`.
            #[inline]
            pub fn from_fn(f: impl FnMut(usize) -> $elem) -> Self {
                Self::from(std::array::from_fn::<$elem, $n, _>(f))
            }
            /// `f` applied lane by lane.
            #[inline]
            pub fn map(self, mut f: impl FnMut($elem) -> $elem) -> Self {
                Self::from(self.to_array().map(&mut f))
            }
        }

        impl From<[$elem; $n]> for $name {
            #[inline]
            fn from(lanes: [$elem; $n]) -> Self {
                Self(wide::$wide::from(lanes))
            }
        }

        impl From<$name> for [$elem; $n] {
            #[inline]
            fn from(x: $name) -> Self {
                x.to_array()
            }
        }

        impl $mask {
            /// The mask as one bool per lane.
            #[inline]
            pub fn to_array(self) -> [bool; $n] {
                self.0.to_array().map(|x| x.to_bits() != 0)
            }
        }

        impl From<[bool; $n]> for $mask {
            #[inline]
            fn from(lanes: [bool; $n]) -> Self {
                let bits = lanes.map(|b| $elem::from_bits(if b { !0 } else { 0 }));
                Self(wide::$wide::from(bits))
            }
        }

        impl PartialEq for $mask {
            #[inline]
            fn eq(&self, other: &Self) -> bool {
                self.to_array() == other.to_array()
            }
        }

        impl BitAnd for $mask {
            type Output = Self;
            #[inline]
            fn bitand(self, rhs: Self) -> Self {
                Self(self.0 & rhs.0)
            }
        }
        impl BitOr for $mask {
            type Output = Self;
            #[inline]
            fn bitor(self, rhs: Self) -> Self {
                Self(self.0 | rhs.0)
            }
        }
        impl Not for $mask {
            type Output = Self;
            #[inline]
            fn not(self) -> Self {
                Self(!self.0)
            }
        }

        impl Mask for $mask {
            #[inline]
            fn splat(value: bool) -> Self {
                Self::from([value; $n])
            }
            #[inline]
            fn all(&self) -> bool {
                self.0.all()
            }
            #[inline]
            fn any(&self) -> bool {
                self.0.any()
            }
        }

        /// True when equal in every lane (NaN lanes are unequal).
        impl PartialEq for $name {
            #[inline]
            fn eq(&self, other: &Self) -> bool {
                self.to_array() == other.to_array()
            }
        }

        /// The lanes in brackets: `[1, 2, 3, 4]`.
        impl fmt::Display for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(f, "[")?;
                for (i, x) in self.to_array().iter().enumerate() {
                    if i > 0 {
                        write!(f, ", ")?;
                    }
                    write!(f, "{x}")?;
                }
                write!(f, "]")
            }
        }

        lane_binop!($name, Add, add);
        lane_binop!($name, Sub, sub);
        lane_binop!($name, Mul, mul);
        lane_binop!($name, Div, div);

        impl Neg for $name {
            type Output = Self;
            #[inline]
            fn neg(self) -> Self {
                Self(-self.0)
            }
        }

        impl Ring for $name {
            #[inline]
            fn zero() -> Self {
                Self::splat(0.0)
            }
            #[inline]
            fn one() -> Self {
                Self::splat(1.0)
            }
            #[inline]
            fn from_i64(n: i64) -> Self {
                Self::splat(n as $elem)
            }
            #[inline]
            fn from_ratio(num: i64, den: i64) -> Self {
                Self::splat((num as f64 / den as f64) as $elem)
            }
            #[inline]
            fn from_rational(q: &Q) -> Self {
                Self::splat(rational_to_f64(q) as $elem)
            }
            /// Every lane is zero.
            #[inline]
            fn is_exact_zero(&self) -> bool {
                self.to_array().iter().all(|x| *x == 0.0)
            }
            /// The largest lane's `|x|` (NaN when a lane is NaN).
            #[inline]
            fn magnitude(&self) -> f64 {
                self.abs().max_to_f64()
            }
            #[inline]
            fn relative_epsilon() -> f64 {
                f64::from($elem::EPSILON)
            }
            /// Every lane is finite.
            #[inline]
            fn is_finite_value(&self) -> bool {
                self.0.is_finite().all()
            }
            #[inline]
            fn add_ref(&self, rhs: &Self) -> Self {
                *self + *rhs
            }
            #[inline]
            fn sub_ref(&self, rhs: &Self) -> Self {
                *self - *rhs
            }
            #[inline]
            fn mul_ref(&self, rhs: &Self) -> Self {
                *self * *rhs
            }
            #[inline]
            fn neg_ref(&self) -> Self {
                -*self
            }
            #[inline]
            fn add_assign_ref(&mut self, rhs: &Self) {
                *self = *self + *rhs;
            }
            #[inline]
            fn sub_assign_ref(&mut self, rhs: &Self) {
                *self = *self - *rhs;
            }
        }

        impl Field for $name {
            /// `None` when any lane is zero or has a non-finite reciprocal.
            #[inline]
            fn try_recip(&self) -> Option<Self> {
                let r = Self::one() / *self;
                let zero = self.0.simd_eq(wide::$wide::ZERO).any();
                (!zero && r.0.is_finite().all()).then_some(r)
            }
            #[inline]
            fn div_ref(&self, rhs: &Self) -> Self {
                *self / *rhs
            }
        }

        impl Elementary for $name {
            #[inline]
            fn sqrt(&self) -> Self {
                Self(self.0.sqrt())
            }
            #[inline]
            fn exp(&self) -> Self {
                Self(self.0.exp())
            }
            #[inline]
            fn ln(&self) -> Self {
                Self(self.0.ln())
            }
            #[inline]
            fn sin(&self) -> Self {
                Self(self.0.sin())
            }
            #[inline]
            fn cos(&self) -> Self {
                Self(self.0.cos())
            }
            #[inline]
            fn atan2(&self, x: &Self) -> Self {
                Self(self.0.atan2(x.0))
            }
            #[inline]
            fn abs(&self) -> Self {
                Self(self.0.abs())
            }
            #[inline]
            fn from_f64(x: f64) -> Self {
                Self::splat(x as $elem)
            }
            #[inline]
            fn pi() -> Self {
                Self::splat(std::f64::consts::PI as $elem)
            }
        }

        impl Select for $name {
            type Mask = $mask;
            #[inline]
            fn select(mask: &$mask, if_true: &Self, if_false: &Self) -> Self {
                Self(mask.0.select(if_true.0, if_false.0))
            }
            #[inline]
            fn lt_mask(&self, other: &Self) -> $mask {
                $mask(self.0.simd_lt(other.0))
            }
            #[inline]
            fn le_mask(&self, other: &Self) -> $mask {
                $mask(self.0.simd_le(other.0))
            }
            #[inline]
            fn eq_mask(&self, other: &Self) -> $mask {
                $mask(self.0.simd_eq(other.0))
            }
            #[inline]
            fn finite_mask(&self) -> $mask {
                $mask(self.0.is_finite())
            }
        }

        impl Diagnostics for $name {
            const LANES: usize = Self::LANES;
            #[inline]
            fn lane_to_f64(&self, lane: usize) -> Option<f64> {
                self.to_array().get(lane).map(|x| f64::from(*x))
            }
        }
    };
}

/// `Op<Self>`, `Op<&Self>` for a lane type, lane by lane.
macro_rules! lane_binop {
    ($name:ident, $tr:ident, $f:ident) => {
        impl $tr for $name {
            type Output = Self;
            #[inline]
            fn $f(self, rhs: Self) -> Self {
                Self($tr::$f(self.0, rhs.0))
            }
        }
        impl<'a> $tr<&'a $name> for $name {
            type Output = Self;
            #[inline]
            fn $f(self, rhs: &'a Self) -> Self {
                Self($tr::$f(self.0, rhs.0))
            }
        }
    };
}

lane_type!(F32x4, MaskF32x4, f32x4, f32, 4, "Four `f32` lanes (128-bit SIMD).");
lane_type!(F32x8, MaskF32x8, f32x8, f32, 8, "Eight `f32` lanes (256-bit SIMD).");
lane_type!(F64x2, MaskF64x2, f64x2, f64, 2, "Two `f64` lanes (128-bit SIMD).");
lane_type!(F64x4, MaskF64x4, f64x4, f64, 4, "Four `f64` lanes (256-bit SIMD).");
