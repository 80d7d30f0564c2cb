//! Basis elements as subsets of generators (bitmasks), their names and order, and the two
//! basis representations.
//!
//! A subset `S = {i < j < ...}` of generators names one basis element, `e` followed by the
//! labels in declaration order (`e12`, `e0inf`); the empty subset is `1`. What the element
//! *is* depends on the [`Basis`]:
//! - [`Basis::Blade`]: `e_i ^ e_j ^ ...`, outer products; grades are true grades.
//! - [`Basis::Product`]: `e_i e_j ...`, geometric products (the basis of Cross, Cripps and
//!   Mullineux 2022). For mutually orthogonal generators it is the blade basis; in the
//!   paper's G_{0123inf} the product `e0inf = e0 einf = -1 + e0 ^ einf` is not a blade.
//!
//! The basis order, used for printing and JSON, is by subset size, then by bitmask (the
//! largest generator first decides: `e12, e13, e23, e1inf, ...`, the order of the paper's
//! eq. (4)).

use std::fmt;
use std::str::FromStr;

/// Which elements the subsets of generators stand for.
///
/// ```
/// use algebra_core::Basis;
/// assert_eq!("product".parse::<Basis>().unwrap(), Basis::Product);
/// assert_eq!(Basis::Blade.to_string(), "blade");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Basis {
    /// Outer products of generators.
    #[default]
    Blade,
    /// Geometric products of generators.
    Product,
}

impl Basis {
    /// Both bases, blade first.
    pub const ALL: [Basis; 2] = [Basis::Blade, Basis::Product];
}

impl fmt::Display for Basis {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Basis::Blade => "blade",
            Basis::Product => "product",
        })
    }
}

/// A basis name that the algebra does not have, or an unknown basis representation.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum BasisError {
    /// Not `blade` or `product`.
    UnknownRepresentation(String),
    /// Not a basis element of the algebra.
    UnknownElement {
        /// The name asked for.
        name: String,
        /// The algebra's labels, for the message.
        labels: String,
    },
}

impl std::fmt::Display for BasisError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            BasisError::UnknownRepresentation(x) => write!(f, "unknown basis `{x}` (expected blade or product)"),
            BasisError::UnknownElement { name, labels } => {
                write!(f, "unknown basis element `{name}` (this algebra's generators are {labels})")
            }
        }
    }
}

impl std::error::Error for BasisError {}

impl FromStr for Basis {
    type Err = BasisError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s {
            "blade" => Ok(Basis::Blade),
            "product" => Ok(Basis::Product),
            _ => Err(BasisError::UnknownRepresentation(s.to_string())),
        }
    }
}

/// The size of a subset: the grade of a blade-basis element.
///
/// ```
/// assert_eq!(algebra_core::basis::grade(0b1011), 3);
/// ```
pub fn grade(mask: u32) -> usize {
    mask.count_ones() as usize
}

/// `(-1)^k` as an i64 sign for the parity of `k`.
pub(crate) fn parity_sign(k: usize) -> i64 {
    if k.is_multiple_of(2) { 1 } else { -1 }
}

/// The sign of `e_A ^ e_B` relative to `e_{A u B}` for disjoint subsets (the parity of the
/// number of pairs `a in A`, `b in B` with `a > b`), or `None` when they intersect.
///
/// ```
/// use algebra_core::basis::wedge_sign;
/// assert_eq!(wedge_sign(0b10, 0b01), Some(-1)); // e2 ^ e1 = -e12
/// assert_eq!(wedge_sign(0b01, 0b10), Some(1));
/// assert_eq!(wedge_sign(0b11, 0b10), None);
/// ```
pub fn wedge_sign(a: u32, b: u32) -> Option<i64> {
    if a & b != 0 {
        return None;
    }
    let mut swaps = 0;
    let mut rest = a;
    while rest != 0 {
        let i = rest.trailing_zeros();
        swaps += (b & ((1u32 << i) - 1)).count_ones();
        rest &= rest - 1;
    }
    Some(parity_sign(swaps as usize))
}

/// The name of a basis element: `1` or `e` + labels in declaration order.
///
/// ```
/// let labels = ["0", "1", "2", "3", "inf"].map(String::from);
/// assert_eq!(algebra_core::basis::name(0b10001, &labels), "e0inf");
/// assert_eq!(algebra_core::basis::name(0, &labels), "1");
/// ```
pub fn name(mask: u32, labels: &[String]) -> String {
    if mask == 0 {
        return "1".to_string();
    }
    let mut s = String::from("e");
    for (i, l) in labels.iter().enumerate() {
        if mask >> i & 1 == 1 {
            s.push_str(l);
        }
    }
    s
}

/// All masks of an `n`-generator algebra in basis order: by size, then by mask.
///
/// ```
/// assert_eq!(algebra_core::basis::basis_order(2), vec![0, 1, 2, 3]);
/// assert_eq!(algebra_core::basis::basis_order(3)[4..7], [3, 5, 6]);
/// ```
pub fn basis_order(n: usize) -> Vec<u32> {
    let mut v: Vec<u32> = (0..1u32 << n).collect();
    v.sort_by_key(|&m| (m.count_ones(), m));
    v
}
