//! Monomial orders on exponent vectors: lex, grevlex, and the block (elimination) order.

use std::cmp::Ordering;

/// A monomial order on the variables of a [`super::PolyRing`], in the ring's variable order
/// (`x_0 > x_1 > ...`).
///
/// ```
/// use algebra_core::ideal::{MonomialOrder, PolyRing};
/// use algebra_core::Poly;
/// let (x, y) = (Poly::var("x"), Poly::var("y"));
/// // x*y**2 vs x**2: grevlex looks at the degree first, lex at the exponent of x.
/// let f = x.clone() * y.clone() * y.clone() + x.clone() * x.clone();
/// let grevlex = PolyRing::new(["x", "y"], MonomialOrder::GrevLex);
/// let lex = PolyRing::new(["x", "y"], MonomialOrder::Lex);
/// assert_eq!(grevlex.leading_term(&f).unwrap().unwrap().to_string(), "x*y**2");
/// assert_eq!(lex.leading_term(&f).unwrap().unwrap().to_string(), "x**2");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MonomialOrder {
    /// Lexicographic: the larger exponent of the first variable where they differ wins.
    Lex,
    /// Graded reverse lexicographic: larger total degree wins; on a tie, the smaller exponent
    /// of the *last* variable where they differ wins.
    GrevLex,
    /// Block order for elimination: grevlex on the first `first` variables, ties broken by
    /// grevlex on the rest. A Gröbner basis in this order, intersected with the polynomials in
    /// the last variables only, is a basis of the elimination ideal.
    Elimination {
        /// How many leading variables are eliminated.
        first: usize,
    },
}

/// A monomial as a dense exponent vector with its total degree.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) struct Mono {
    pub(crate) e: Box<[u32]>,
    pub(crate) deg: u32,
}

impl Mono {
    pub(crate) fn one(n: usize) -> Self {
        Mono { e: vec![0; n].into_boxed_slice(), deg: 0 }
    }

    pub(crate) fn from_exps(e: Vec<u32>) -> Self {
        let deg = e.iter().sum();
        Mono { e: e.into_boxed_slice(), deg }
    }

    pub(crate) fn mul(&self, o: &Mono) -> Mono {
        Mono { e: self.e.iter().zip(o.e.iter()).map(|(a, b)| a + b).collect(), deg: self.deg + o.deg }
    }

    /// `self | o`.
    pub(crate) fn divides(&self, o: &Mono) -> bool {
        self.deg <= o.deg && self.e.iter().zip(o.e.iter()).all(|(a, b)| a <= b)
    }

    /// `o / self`, assuming `self | o`.
    pub(crate) fn quotient_of(&self, o: &Mono) -> Mono {
        Mono { e: o.e.iter().zip(self.e.iter()).map(|(a, b)| a - b).collect(), deg: o.deg - self.deg }
    }

    pub(crate) fn lcm(&self, o: &Mono) -> Mono {
        Mono::from_exps(self.e.iter().zip(o.e.iter()).map(|(a, b)| *a.max(b)).collect())
    }

    pub(crate) fn coprime(&self, o: &Mono) -> bool {
        self.e.iter().zip(o.e.iter()).all(|(a, b)| *a == 0 || *b == 0)
    }

    /// Bit `i % 64` set when variable `i` occurs: a cheap necessary test for divisibility.
    pub(crate) fn mask(&self) -> u64 {
        self.e.iter().enumerate().filter(|(_, e)| **e > 0).fold(0, |m, (i, _)| m | 1 << (i % 64))
    }
}

fn grevlex(a: &[u32], b: &[u32]) -> Ordering {
    let (da, db): (u32, u32) = (a.iter().sum(), b.iter().sum());
    da.cmp(&db).then_with(|| {
        for (x, y) in a.iter().zip(b.iter()).rev() {
            if x != y {
                return y.cmp(x);
            }
        }
        Ordering::Equal
    })
}

impl MonomialOrder {
    /// Compares two monomials (`Greater` = `a` is the larger, i.e. leads).
    pub(crate) fn cmp(&self, a: &Mono, b: &Mono) -> Ordering {
        match *self {
            MonomialOrder::Lex => a.e.cmp(&b.e),
            MonomialOrder::GrevLex => a.deg.cmp(&b.deg).then_with(|| {
                for (x, y) in a.e.iter().zip(b.e.iter()).rev() {
                    if x != y {
                        return y.cmp(x);
                    }
                }
                Ordering::Equal
            }),
            MonomialOrder::Elimination { first } => {
                let k = first.min(a.e.len());
                grevlex(&a.e[..k], &b.e[..k]).then_with(|| grevlex(&a.e[k..], &b.e[k..]))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn m(e: &[u32]) -> Mono {
        Mono::from_exps(e.to_vec())
    }

    #[test]
    fn textbook_comparisons() {
        // Cox, Little, O'Shea, Ch. 2 §2: x y^2 z^4 vs x^3 y^2 ... examples.
        use Ordering::*;
        assert_eq!(MonomialOrder::Lex.cmp(&m(&[1, 2, 0]), &m(&[0, 3, 4])), Greater);
        assert_eq!(MonomialOrder::Lex.cmp(&m(&[3, 2, 4]), &m(&[3, 2, 1])), Greater);
        assert_eq!(MonomialOrder::GrevLex.cmp(&m(&[4, 7, 1]), &m(&[4, 2, 3])), Greater);
        assert_eq!(MonomialOrder::GrevLex.cmp(&m(&[1, 5, 2]), &m(&[4, 1, 3])), Greater);
        // Elimination of x: any monomial with x beats any without.
        let e = MonomialOrder::Elimination { first: 1 };
        assert_eq!(e.cmp(&m(&[1, 0, 0]), &m(&[0, 5, 5])), Greater);
        assert_eq!(e.cmp(&m(&[1, 0, 1]), &m(&[1, 1, 0])), Less);
    }
}
