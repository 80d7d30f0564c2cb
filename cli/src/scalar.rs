//! The scalar types of `--scalar` and what the evaluator needs from each: reading number
//! literals, variables (only `poly`), printing coefficients, and the operations that not every
//! scalar supports (division, inverse, exp/log/sqrt).

use algebra_core::rational::{Q, format_rational, parse_rational};
use algebra_core::{Field, MpFloat, MpRational, Multivector, MvError, Poly, Product, Real, Ring};
use num_traits::Zero;
use std::str::FromStr;

/// The largest total degree of a `poly` result (exponents are stored in 32 bits).
pub const MAX_DEGREE: u64 = 1_000_000;

/// The largest `mpfr:BITS` precision accepted.
pub const MAX_MPFR_BITS: u32 = 1_000_000;

/// The value of `--scalar`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ScalarKind {
    /// Exact rationals.
    Rational,
    /// Polynomials over the rationals.
    Poly,
    /// IEEE doubles.
    F64,
    /// MPFR floats with this many bits.
    Mpfr(u32),
}

impl FromStr for ScalarKind {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "rational" => Ok(ScalarKind::Rational),
            "poly" => Ok(ScalarKind::Poly),
            "f64" => Ok(ScalarKind::F64),
            _ => match s.strip_prefix("mpfr:") {
                Some(bits) => match bits.parse::<u32>() {
                    Ok(b) if (2..=MAX_MPFR_BITS).contains(&b) => Ok(ScalarKind::Mpfr(b)),
                    _ => {
                        Err(format!("mpfr precision `{bits}` must be a whole number of bits from 2 to {MAX_MPFR_BITS}"))
                    }
                },
                None => Err(format!("unknown scalar `{s}` (expected rational, poly, f64 or mpfr:BITS)")),
            },
        }
    }
}

/// Why a scalar-specific operation failed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Failure {
    /// The scalar type cannot do this (a usage error, exit status 2).
    Unsupported(String),
    /// The operation is not defined for this value (exit status 1).
    Math(String),
}

impl From<MvError> for Failure {
    fn from(e: MvError) -> Self {
        Failure::Math(e.to_string())
    }
}

/// A scalar the CLI can evaluate over.
pub trait CliScalar: Ring + 'static {
    /// The `--scalar` name, for messages.
    const NAME: &'static str;

    /// The value of a number literal (`3`, `0.25`).
    fn number(text: &str) -> Result<Self, String>;

    /// The polynomial variable `name`; `None` for scalars without variables.
    fn variable(_name: &str) -> Option<Self> {
        None
    }

    /// The coefficient string of the JSON output.
    fn format(&self) -> String {
        self.to_string()
    }

    /// False for infinities and NaN.
    fn finite(&self) -> bool {
        true
    }

    /// `self / d` for a scalar `d`.
    fn div_scalar(&self, d: &Self) -> Result<Self, Failure>;

    /// The inverse of a multivector.
    fn inverse(x: &Multivector<Self>) -> Result<Multivector<Self>, Failure>;

    /// The partial derivative by the variable `var` (`diff(x, var)`).
    fn derivative(&self, _var: &str) -> Result<Self, Failure> {
        Err(Failure::Unsupported("it needs --scalar poly".to_string()))
    }

    /// The work units of `product(a, b)` beyond the table lookups: zero for fixed-size
    /// scalars, the term products of a `poly` product (see [`crate::budget`]).
    fn product_work(_a: &Multivector<Self>, _b: &Multivector<Self>, _product: Product) -> f64 {
        0.0
    }

    /// The size in bits of the largest coefficient of `x` (numerator and denominator) for the
    /// exact scalars, 0 for fixed-size ones: what a power `x ** k` multiplies by `k`.
    fn size_bits(_x: &Multivector<Self>) -> f64 {
        0.0
    }

    /// An upper bound of the bytes of `product(a, b)`'s coefficients beyond the fixed size of a
    /// multivector: zero for fixed-size scalars; for `poly`, one term per term product.
    fn product_bytes(_a: &Multivector<Self>, _b: &Multivector<Self>, _product: Product) -> f64 {
        0.0
    }

    /// The work units of inverting the non-scalar `x` exactly: zero for fixed-size scalars;
    /// for the exact ones `dim² × (bits / 64)²` (every step of the exact inverse meets
    /// coefficients of about `bits` bits, and a rational operation on them costs a gcd,
    /// quadratic in their limbs), so a 100,000-digit coefficient is refused before the work.
    fn inverse_work(x: &Multivector<Self>) -> f64 {
        let (dim, limbs) = (x.coeffs().len() as f64, Self::size_bits(x) / 64.0);
        dim * dim * limbs * limbs
    }

    /// The largest total degree of a coefficient of `x` (0 for the scalars without variables):
    /// products whose degree would pass [`MAX_DEGREE`] are refused.
    fn degree(_x: &Multivector<Self>) -> u64 {
        0
    }

    /// `exp`, `log` or `sqrt` of a multivector.
    fn elementary(_f: Elementary, _x: &Multivector<Self>) -> Result<Multivector<Self>, Failure> {
        Err(Failure::Unsupported("it needs --scalar f64 or mpfr:BITS".to_string()))
    }
}

/// The transcendental functions, defined only over real scalars.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Elementary {
    /// The exponential.
    Exp,
    /// The principal logarithm.
    Log,
    /// The principal square root.
    Sqrt,
}

fn divide_field<T: Field>(x: &T, d: &T) -> Result<T, Failure> {
    match d.try_recip() {
        None => Err(Failure::Math("division by zero".to_string())),
        Some(_) => Ok(x.div_ref(d)),
    }
}

impl CliScalar for Q {
    const NAME: &'static str = "rational";
    fn size_bits(x: &Multivector<Self>) -> f64 {
        x.coeffs().iter().map(|c| (c.numer().bits() + c.denom().bits()) as f64).fold(0.0, f64::max)
    }
    /// Per table entry met by two non-zero coefficients of `b_i` and `b_j` bits, one exact
    /// multiply-add whose gcd is quadratic in the limbs: `((b_i + b_j)/64)²` limb pairs
    /// ([`crate::budget::LIMB_PAIRS_PER_UNIT`] to a unit). Ordinary coefficients cost about
    /// nothing; two 100,000-digit ones about 3.6e6 units (1.2 s).
    fn product_work(a: &Multivector<Self>, b: &Multivector<Self>, product: Product) -> f64 {
        let bits = |x: &Multivector<Self>| -> Vec<(u32, f64)> {
            let nonzero = x.coeffs().iter().enumerate().filter(|(_, c)| !c.is_zero());
            nonzero.map(|(k, c)| (k as u32, (c.numer().bits() + c.denom().bits()) as f64)).collect()
        };
        let table = a.algebra().tables().product(a.basis(), product);
        let (xs, ys) = (bits(a), bits(b));
        let mut work = 0.0;
        for (i, bi) in &xs {
            for (j, bj) in &ys {
                // a mismatch of algebras or bases is reported by the product itself
                let entries = table.get(*i, *j).map_or(1, <[_]>::len) as f64;
                let limbs = (bi + bj) / 64.0;
                work += entries * limbs * limbs / crate::budget::LIMB_PAIRS_PER_UNIT;
            }
        }
        work
    }
    fn number(text: &str) -> Result<Self, String> {
        parse_rational(text).map_err(|e| e.to_string())
    }
    fn format(&self) -> String {
        format_rational(self)
    }
    fn div_scalar(&self, d: &Self) -> Result<Self, Failure> {
        divide_field(self, d)
    }
    fn inverse(x: &Multivector<Self>) -> Result<Multivector<Self>, Failure> {
        Ok(x.inverse()?)
    }
}

impl CliScalar for Poly {
    const NAME: &'static str = "poly";
    fn number(text: &str) -> Result<Self, String> {
        parse_rational(text).map(|q| Poly::from_q(&q)).map_err(|e| e.to_string())
    }
    fn variable(name: &str) -> Option<Self> {
        Some(Poly::var(name))
    }
    fn size_bits(x: &Multivector<Self>) -> f64 {
        x.coeffs()
            .iter()
            .flat_map(|p| p.terms().map(|(c, _)| (c.numer().significant_bits() + c.denom().significant_bits()) as f64))
            .fold(0.0, f64::max)
    }
    fn degree(x: &Multivector<Self>) -> u64 {
        x.coeffs().iter().map(|p| u64::from(p.degree())).max().unwrap_or(0)
    }
    fn product_work(a: &Multivector<Self>, b: &Multivector<Self>, product: Product) -> f64 {
        // an algebra mismatch is reported by the product itself
        a.product_terms(b, product).map_or(0.0, |t| t as f64 * crate::budget::UNITS_PER_TERM_PRODUCT)
    }
    fn product_bytes(a: &Multivector<Self>, b: &Multivector<Self>, product: Product) -> f64 {
        let vars = |x: &Multivector<Self>| x.coeffs().iter().map(Poly::max_term_variables).max().unwrap_or(0);
        let terms = a.product_terms(b, product).map_or(0.0, |t| t as f64);
        terms * crate::budget::poly_term_bytes(vars(a) + vars(b))
    }
    fn derivative(&self, var: &str) -> Result<Self, Failure> {
        Ok(Poly::derivative(self, var))
    }
    fn div_scalar(&self, d: &Self) -> Result<Self, Failure> {
        let c = poly_constant(d).ok_or_else(|| {
            Failure::Unsupported(format!(
                "division by the non-constant polynomial `{d}` (poly divides only by constants)"
            ))
        })?;
        if c.is_zero() {
            return Err(Failure::Math("division by zero".to_string()));
        }
        Ok(self.mul_ref(&Poly::from_q(&c.recip())))
    }
    /// Only elements with constant coefficients: inverted exactly over the rationals.
    fn inverse(x: &Multivector<Self>) -> Result<Multivector<Self>, Failure> {
        let mut coeffs = Vec::with_capacity(x.coeffs().len());
        for c in x.coeffs() {
            coeffs.push(poly_constant(c).ok_or_else(|| {
                Failure::Unsupported(format!(
                    "{x} has non-constant coefficients (poly inverts only elements with constant coefficients)"
                ))
            })?);
        }
        let exact = Multivector::from_coeffs(x.algebra(), x.basis(), coeffs)?;
        Ok(exact.inverse()?.map_coeffs(Poly::from_q))
    }
}

/// The value of a constant polynomial.
fn poly_constant(p: &Poly) -> Option<Q> {
    p.as_constant().map(|r| MpRational(r).to_q())
}

/// The shortest round-trip decimal, plain for moderate magnitudes and in exponent form
/// (`1.2246467991473532e-16`) outside `1e-7 <= |x| < 1e16`, like JavaScript (one rule with the
/// messages of the motion format: `motion::schema::format_f64`).
pub use motion::schema::format_f64;

impl CliScalar for f64 {
    const NAME: &'static str = "f64";
    fn number(text: &str) -> Result<Self, String> {
        text.parse::<f64>().map_err(|e| format!("`{text}`: {e}"))
    }
    fn format(&self) -> String {
        format_f64(*self)
    }
    fn finite(&self) -> bool {
        self.is_finite()
    }
    fn div_scalar(&self, d: &Self) -> Result<Self, Failure> {
        divide_field(self, d)
    }
    fn inverse(x: &Multivector<Self>) -> Result<Multivector<Self>, Failure> {
        Ok(x.inverse()?)
    }
    fn elementary(f: Elementary, x: &Multivector<Self>) -> Result<Multivector<Self>, Failure> {
        real_elementary(f, x)
    }
}

impl CliScalar for MpFloat {
    const NAME: &'static str = "mpfr";
    /// Exact rational value rounded once to the current default precision.
    fn number(text: &str) -> Result<Self, String> {
        parse_rational(text).map(|q| MpFloat::from_rational(&q)).map_err(|e| e.to_string())
    }
    fn finite(&self) -> bool {
        Real::is_finite(self)
    }
    fn div_scalar(&self, d: &Self) -> Result<Self, Failure> {
        divide_field(self, d)
    }
    fn inverse(x: &Multivector<Self>) -> Result<Multivector<Self>, Failure> {
        Ok(x.inverse()?)
    }
    fn elementary(f: Elementary, x: &Multivector<Self>) -> Result<Multivector<Self>, Failure> {
        real_elementary(f, x)
    }
}

/// exp/log/sqrt over a real scalar: the scalar functions for a pure scalar (correctly rounded
/// where the scalar type is), otherwise the multivector algorithms of algebra-core.
fn real_elementary<T: Real + CliScalar>(f: Elementary, x: &Multivector<T>) -> Result<Multivector<T>, Failure> {
    let is_scalar = x.coeffs().iter().skip(1).all(Ring::is_exact_zero);
    let out = if is_scalar {
        let a = &x.coeffs()[0];
        let zero = T::zero();
        let value = match f {
            Elementary::Exp => Real::exp(a),
            Elementary::Log if *a > zero => Real::ln(a),
            Elementary::Log => {
                return Err(Failure::Math(format!(
                    "log is not defined for {}: it needs a positive scalar",
                    a.format()
                )));
            }
            Elementary::Sqrt if *a >= zero => Real::sqrt(a),
            Elementary::Sqrt => {
                return Err(Failure::Math(format!("sqrt is not defined for {}: it needs a scalar >= 0", a.format())));
            }
        };
        Multivector::scalar(x.algebra(), x.basis(), value)
    } else {
        match f {
            Elementary::Exp => x.exp()?,
            Elementary::Log => x.log()?,
            Elementary::Sqrt => x.sqrt()?,
        }
    };
    if out.coeffs().iter().all(CliScalar::finite) {
        Ok(out)
    } else {
        Err(Failure::Math("the result is not finite".to_string()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scalar_kinds() {
        assert_eq!("mpfr:256".parse::<ScalarKind>(), Ok(ScalarKind::Mpfr(256)));
        assert!("mpfr:1".parse::<ScalarKind>().is_err());
        assert!("mpfr:x".parse::<ScalarKind>().is_err());
        assert!("mpfr:1000001".parse::<ScalarKind>().is_err());
        assert!("float".parse::<ScalarKind>().is_err());
    }

    #[test]
    fn f64_format() {
        assert_eq!(format_f64(0.5), "0.5");
        assert_eq!(format_f64(1.0), "1");
        assert_eq!(format_f64(-2.0), "-2");
        assert_eq!(format_f64(1.2246467991473532e-16), "1.2246467991473532e-16");
        assert_eq!(format_f64(1e20), "1e20");
        assert_eq!(format_f64(0.1 + 0.2), "0.30000000000000004");
    }

    #[test]
    fn poly_constants() {
        let x = Poly::var("x");
        assert!(matches!(x.div_scalar(&x), Err(Failure::Unsupported(_))));
        assert!(matches!(x.div_scalar(&Poly::zero()), Err(Failure::Math(_))));
        assert_eq!(x.div_scalar(&Poly::from_i64(2)).unwrap().to_string(), "1/2*x");
    }
}
