// The items a standalone file needs from algebra-core, inlined (see `standalone.rs`). Not a
// module of algebra-codegen: this text is parsed and appended to every `gam codegen
// --standalone` file, and compiled through examples/vendored. Keep it in step with
// algebra-core's `Ring`, `Field`, `ops`, `linalg::solve` and `multivector::display`.

/// Scalar arithmetic the kernels use (algebra-core's `Ring`, reduced to what they call).
/// Implemented here for `f32` and `f64`; implement it for another scalar to use that.
pub trait Ring:
    Clone
    + ::core::fmt::Debug
    + ::core::fmt::Display
    + PartialEq
    + ::core::ops::Add<Output = Self>
    + ::core::ops::Sub<Output = Self>
    + ::core::ops::Mul<Output = Self>
    + ::core::ops::Neg<Output = Self>
    + for<'a> ::core::ops::Add<&'a Self, Output = Self>
    + for<'a> ::core::ops::Sub<&'a Self, Output = Self>
    + for<'a> ::core::ops::Mul<&'a Self, Output = Self>
{
    /// The additive identity.
    fn zero() -> Self;
    /// The multiplicative identity.
    fn one() -> Self;
    /// The ratio `num / den` (`den != 0`).
    fn from_ratio(num: i64, den: i64) -> Self;
    /// True only for an exact zero (used for printing and pivots, never to drop terms).
    fn is_exact_zero(&self) -> bool;
    /// A non-negative size for choosing pivots.
    fn magnitude(&self) -> f64;
    /// The relative precision: machine epsilon for floats, `0.0` for exact types.
    fn relative_epsilon() -> f64;
    /// `self + rhs` without consuming either operand.
    fn add_ref(&self, rhs: &Self) -> Self {
        self.clone() + rhs
    }
    /// `self - rhs` without consuming either operand.
    fn sub_ref(&self, rhs: &Self) -> Self {
        self.clone() - rhs
    }
    /// `self * rhs` without consuming either operand.
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.clone() * rhs
    }
    /// `-self` without consuming it.
    fn neg_ref(&self) -> Self {
        -self.clone()
    }
    /// `self += rhs`.
    fn add_assign_ref(&mut self, rhs: &Self) {
        *self = self.add_ref(rhs);
    }
    /// `self -= rhs`.
    fn sub_assign_ref(&mut self, rhs: &Self) {
        *self = self.sub_ref(rhs);
    }
}

/// Division (algebra-core's `Field`, reduced to what the kernels call).
pub trait Field: Ring {
    /// `self / rhs`.
    fn div_ref(&self, rhs: &Self) -> Self;
    /// `1 / self`, `None` for zero.
    fn try_recip(&self) -> Option<Self>;
}

macro_rules! float_scalar {
    ($($t:ty),*) => {$(
        impl Ring for $t {
            fn zero() -> Self { 0.0 }
            fn one() -> Self { 1.0 }
            fn from_ratio(num: i64, den: i64) -> Self { num as $t / den as $t }
            fn is_exact_zero(&self) -> bool { *self == 0.0 }
            fn magnitude(&self) -> f64 { f64::from(self.abs()) }
            fn relative_epsilon() -> f64 { f64::from(<$t>::EPSILON) }
            fn add_ref(&self, rhs: &Self) -> Self { self + rhs }
            fn sub_ref(&self, rhs: &Self) -> Self { self - rhs }
            fn mul_ref(&self, rhs: &Self) -> Self { self * rhs }
            fn neg_ref(&self) -> Self { -self }
        }
        impl Field for $t {
            fn div_ref(&self, rhs: &Self) -> Self { self / rhs }
            fn try_recip(&self) -> Option<Self> { if *self == 0.0 { None } else { Some(1.0 / self) } }
        }
    )*};
}
float_scalar!(f32, f64);

/// The geometric product.
pub trait GeometricProduct<Rhs: ?Sized> {
    /// The result type.
    type Output;
    /// `self rhs`.
    fn gp(&self, rhs: &Rhs) -> Self::Output;
}

/// The outer (wedge) product.
pub trait OuterProduct<Rhs: ?Sized> {
    /// The result type.
    type Output;
    /// `self ^ rhs`.
    fn op(&self, rhs: &Rhs) -> Self::Output;
}

/// The left contraction.
pub trait LeftContraction<Rhs: ?Sized> {
    /// The result type.
    type Output;
    /// `self _| rhs`.
    fn lc(&self, rhs: &Rhs) -> Self::Output;
}

/// The right contraction.
pub trait RightContraction<Rhs: ?Sized> {
    /// The result type.
    type Output;
    /// `self |_ rhs`.
    fn rc(&self, rhs: &Rhs) -> Self::Output;
}

/// The scalar product.
pub trait ScalarProduct<Rhs: ?Sized> {
    /// The result type.
    type Output;
    /// `<self rhs>_0`.
    fn sp(&self, rhs: &Rhs) -> Self::Output;
}

/// The regressive (meet) product.
pub trait RegressiveProduct<Rhs: ?Sized> {
    /// The result type.
    type Output;
    /// `self v rhs`.
    fn regressive(&self, rhs: &Rhs) -> Self::Output;
}

/// The commutator product `(ab - ba)/2`.
pub trait CommutatorProduct<Rhs: ?Sized> {
    /// The result type.
    type Output;
    /// `(self rhs - rhs self)/2`.
    fn commutator(&self, rhs: &Rhs) -> Self::Output;
}

/// The anticommutator product `(ab + ba)/2`.
pub trait AnticommutatorProduct<Rhs: ?Sized> {
    /// The result type.
    type Output;
    /// `(self rhs + rhs self)/2`.
    fn anticommutator(&self, rhs: &Rhs) -> Self::Output;
}

/// The sandwich `rev(S) x S` (fused kernels typed to `x`'s type for versor types).
pub trait Sandwich<X: ?Sized> {
    /// The result type.
    type Output;
    /// `rev(self) x self`.
    fn sandwich(&self, x: &X) -> Self::Output;
}

/// The versor action `S x rev(S)` (the klein/GATL/ganja convention).
pub trait Apply<X: ?Sized> {
    /// The result type.
    type Output;
    /// `self x rev(self)`.
    fn apply(&self, x: &X) -> Self::Output;
}

/// Why an operation failed.
#[derive(Debug, Clone, PartialEq)]
pub enum MvError {
    /// The element has no inverse (it is a zero divisor).
    NotInvertible(String),
}

impl ::core::fmt::Display for MvError {
    fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
        match self {
            MvError::NotInvertible(x) => write!(f, "{x} is not invertible"),
        }
    }
}

impl ::std::error::Error for MvError {}

/// Solves `l y = rhs` by Gaussian elimination with partial pivoting; `None` when singular.
#[allow(clippy::needless_range_loop)]
fn solve<T: Field>(mut l: Vec<Vec<T>>, mut rhs: Vec<T>) -> Option<Vec<T>> {
    let n = rhs.len();
    let scale = l.iter().flatten().map(Ring::magnitude).fold(0.0, f64::max);
    let tol = 64.0 * T::relative_epsilon() * n as f64 * scale;
    for col in 0..n {
        let pivot = (col..n)
            .filter(|&r| !l[r][col].is_exact_zero())
            .max_by(|&a, &b| l[a][col].magnitude().total_cmp(&l[b][col].magnitude()))?;
        if l[pivot][col].magnitude() <= tol {
            return None;
        }
        l.swap(pivot, col);
        rhs.swap(pivot, col);
        let inv = l[col][col].try_recip()?;
        for r in col + 1..n {
            if l[r][col].is_exact_zero() {
                continue;
            }
            let f = l[r][col].mul_ref(&inv);
            for c in col..n {
                let d = f.mul_ref(&l[col][c]);
                l[r][c] = l[r][c].sub_ref(&d);
            }
            let d = f.mul_ref(&rhs[col]);
            rhs[r] = rhs[r].sub_ref(&d);
        }
    }
    let mut y = vec![T::zero(); n];
    for row in (0..n).rev() {
        let mut acc = rhs[row].clone();
        for c in row + 1..n {
            acc = acc.sub_ref(&l[row][c].mul_ref(&y[c]));
        }
        y[row] = acc.div_ref(&l[row][row]);
    }
    Some(y)
}

/// One term `c*name` as the CLI prints it: `e12`, `-e12`, `1.5*e12`, or `c` for the scalar.
fn format_term(coeff: &str, name: &str) -> String {
    if name == "1" {
        return coeff.to_string();
    }
    let plain = coeff.parse::<f64>().is_ok()
        || coeff.split_once('/').is_some_and(|(p, q)| p.parse::<i64>().is_ok() && q.parse::<u64>().is_ok());
    match coeff {
        "1" => name.to_string(),
        "-1" => format!("-{name}"),
        c if !plain && c.get(1..).is_some_and(|rest| rest.contains([' ', '+', '-'])) => format!("({c})*{name}"),
        c => format!("{c}*{name}"),
    }
}

/// Terms joined with ` + ` / ` - `; `0` when there are none.
fn join_terms(terms: impl IntoIterator<Item = String>) -> String {
    let mut out = String::new();
    for t in terms {
        if out.is_empty() {
            out = t;
        } else if let Some(rest) = t.strip_prefix('-') {
            out.push_str(" - ");
            out.push_str(rest);
        } else {
            out.push_str(" + ");
            out.push_str(&t);
        }
    }
    if out.is_empty() { "0".to_string() } else { out }
}
