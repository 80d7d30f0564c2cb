//! [`Metric`]: generator labels and a symmetric Gram matrix of exact rationals.
//!
//! The bilinear form `B(e_i, e_j)` is stored in full: the paper's G_{0123inf} has
//! `e0 . einf = -1` off the diagonal and `e0^2 = einf^2 = 0`, so per-generator squares would
//! not describe it.

use crate::rational::{Q, format_rational, parse_rational, q};
use num_traits::Zero;
use std::collections::HashMap;

/// The largest number of generators an algebra may have (tables are `4^n` entries).
pub const MAX_GENERATORS: usize = 10;

/// Why a metric (or an algebra description) was rejected.
#[derive(Debug, Clone, PartialEq)]
pub enum MetricError {
    /// No generators.
    Empty,
    /// More generators than [`MAX_GENERATORS`].
    TooManyGenerators(usize),
    /// A label that is empty or not ASCII alphanumeric.
    InvalidLabel(String),
    /// The same label twice.
    DuplicateLabel(String),
    /// Two different subsets of generators would get the same basis name.
    AmbiguousLabels {
        /// The name that two subsets share.
        name: String,
        /// One reading, as a list of labels.
        first: String,
        /// Another reading.
        second: String,
    },
    /// The Gram matrix is not n x n.
    WrongSize {
        /// The number of generators.
        expected: usize,
        /// The offending row count or row length.
        found: usize,
    },
    /// `B(e_i, e_j) != B(e_j, e_i)`.
    Asymmetric {
        /// First label.
        a: String,
        /// Second label.
        b: String,
        /// `B(a, b)`.
        ab: String,
        /// `B(b, a)`.
        ba: String,
    },
    /// A metric entry names a label that is not a generator.
    UnknownLabel(String),
    /// A generator index at or above the number of generators.
    IndexOutOfRange {
        /// The index asked for.
        index: usize,
        /// The number of generators.
        generators: usize,
    },
    /// No built-in algebra of that name.
    UnknownAlgebra(String),
    /// A TOML description that could not be read or understood.
    Toml {
        /// The file (or `<string>`).
        path: String,
        /// What is wrong.
        message: String,
    },
}

impl std::fmt::Display for MetricError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            MetricError::Empty => write!(f, "an algebra needs at least one generator"),
            MetricError::TooManyGenerators(x) => write!(f, "{x} generators: at most {MAX_GENERATORS} are supported"),
            MetricError::InvalidLabel(x) => {
                write!(f, "generator label `{x}` must be non-empty ASCII letters or digits")
            }
            MetricError::DuplicateLabel(x) => write!(f, "generator label `{x}` is declared twice"),
            MetricError::AmbiguousLabels { name, first, second } => {
                write!(f, "labels are ambiguous: basis name `{name}` would mean both {first} and {second}")
            }
            MetricError::WrongSize { expected, found } => {
                write!(f, "the Gram matrix must be {expected}x{expected}, found a row or column count of {found}")
            }
            MetricError::Asymmetric { a, b, ab, ba } => {
                write!(f, "the Gram matrix is not symmetric: B({a}, {b}) = {ab} but B({b}, {a}) = {ba}")
            }
            MetricError::UnknownLabel(x) => write!(f, "metric entry names unknown generator `{x}`"),
            MetricError::IndexOutOfRange { index, generators } => {
                write!(f, "generator index {index} is out of range for {generators} generators")
            }
            MetricError::UnknownAlgebra(x) => write!(
                f,
                "unknown algebra `{x}` (built-ins: {names}; or a path to a .toml file)",
                names = crate::algebra::builtin_names()
            ),
            MetricError::Toml { path, message } => write!(f, "bad algebra file {path}: {message}"),
        }
    }
}

impl std::error::Error for MetricError {}

/// Generator labels with the symmetric bilinear form on them.
///
/// ```
/// use algebra_core::{Metric, rational::q};
/// let m = Metric::new(
///     vec!["0".into(), "inf".into()],
///     vec![vec![q(0), q(-1)], vec![q(-1), q(0)]],
/// ).unwrap();
/// assert_eq!(m.gram(0, 1).unwrap(), &q(-1));
/// assert!(!m.is_diagonal());
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Metric {
    labels: Vec<String>,
    gram: Vec<Vec<Q>>,
}

impl Metric {
    /// A metric from labels and a full Gram matrix, validated: labels non-empty, alphanumeric,
    /// distinct and unambiguous when concatenated into basis names; matrix square and symmetric.
    ///
    /// ```
    /// use algebra_core::{Metric, MetricError, rational::q};
    /// let bad = Metric::new(vec!["a".into(), "b".into()], vec![vec![q(1), q(2)], vec![q(3), q(1)]]);
    /// assert!(matches!(bad, Err(MetricError::Asymmetric { .. })));
    /// ```
    pub fn new(labels: Vec<String>, gram: Vec<Vec<Q>>) -> Result<Self, MetricError> {
        let n = labels.len();
        if n == 0 {
            return Err(MetricError::Empty);
        }
        if n > MAX_GENERATORS {
            return Err(MetricError::TooManyGenerators(n));
        }
        for (i, l) in labels.iter().enumerate() {
            if l.is_empty() || !l.bytes().all(|b| b.is_ascii_alphanumeric()) {
                return Err(MetricError::InvalidLabel(l.clone()));
            }
            if labels[..i].contains(l) {
                return Err(MetricError::DuplicateLabel(l.clone()));
            }
        }
        if gram.len() != n {
            return Err(MetricError::WrongSize { expected: n, found: gram.len() });
        }
        if let Some(row) = gram.iter().find(|r| r.len() != n) {
            return Err(MetricError::WrongSize { expected: n, found: row.len() });
        }
        for i in 0..n {
            for j in i + 1..n {
                if gram[i][j] != gram[j][i] {
                    return Err(MetricError::Asymmetric {
                        a: labels[i].clone(),
                        b: labels[j].clone(),
                        ab: format_rational(&gram[i][j]),
                        ba: format_rational(&gram[j][i]),
                    });
                }
            }
        }
        check_unambiguous(&labels)?;
        Ok(Metric { labels, gram })
    }

    /// A metric from labels and a Gram matrix of rational literals (`"1"`, `"-1/2"`); used by
    /// generated code.
    ///
    /// ```
    /// use algebra_core::{Metric, rational::q};
    /// let m = Metric::from_strs(&["0", "inf"], &[&["0", "-1"], &["-1", "0"]]).unwrap();
    /// assert_eq!(m.gram(1, 0).unwrap(), &q(-1));
    /// ```
    pub fn from_strs(labels: &[&str], gram: &[&[&str]]) -> Result<Self, MetricError> {
        let parse = |s: &str| {
            parse_rational(s).map_err(|e| MetricError::Toml { path: "<literal>".into(), message: e.to_string() })
        };
        let gram = gram.iter().map(|row| row.iter().map(|s| parse(s)).collect()).collect::<Result<_, _>>()?;
        Metric::new(labels.iter().map(|s| s.to_string()).collect(), gram)
    }

    /// The diagonal signature (p, q, r): `p` generators squaring to +1, then `q` to -1, then
    /// `r` to 0, labelled `1, 2, ..., p+q+r`.
    ///
    /// ```
    /// use algebra_core::{Metric, rational::q};
    /// let m = Metric::diagonal(4, 1, 0).unwrap();
    /// assert_eq!(m.gram(4, 4).unwrap(), &q(-1));
    /// assert_eq!(m.labels()[4], "5");
    /// ```
    pub fn diagonal(p: usize, q_: usize, r: usize) -> Result<Self, MetricError> {
        let labels = (1..=p + q_ + r).map(|i| i.to_string()).collect();
        let squares: Vec<Q> = std::iter::repeat_n(q(1), p)
            .chain(std::iter::repeat_n(q(-1), q_))
            .chain(std::iter::repeat_n(q(0), r))
            .collect();
        Metric::from_squares(labels, squares)
    }

    /// An orthogonal metric from labels and the square of each generator.
    ///
    /// ```
    /// use algebra_core::{Metric, rational::q};
    /// let pga = Metric::from_squares(vec!["0".into(), "1".into()], vec![q(0), q(1)]).unwrap();
    /// assert!(pga.is_diagonal());
    /// assert!(pga.is_degenerate());
    /// ```
    pub fn from_squares(labels: Vec<String>, squares: Vec<Q>) -> Result<Self, MetricError> {
        let n = squares.len();
        let gram =
            (0..n).map(|i| (0..n).map(|j| if i == j { squares[i].clone() } else { Q::zero() }).collect()).collect();
        Metric::new(labels, gram)
    }

    /// The number of generators.
    ///
    /// ```
    /// assert_eq!(algebra_core::Metric::diagonal(3, 0, 0).unwrap().dimension(), 3);
    /// ```
    pub fn dimension(&self) -> usize {
        self.labels.len()
    }

    /// The generator labels in declaration order.
    ///
    /// ```
    /// assert_eq!(algebra_core::Metric::diagonal(2, 0, 0).unwrap().labels(), ["1", "2"]);
    /// ```
    pub fn labels(&self) -> &[String] {
        &self.labels
    }

    /// `B(e_i, e_j)`; [`MetricError::IndexOutOfRange`] when `i` or `j` is not a generator index.
    ///
    /// ```
    /// use algebra_core::{Metric, rational::q};
    /// let m = Metric::diagonal(1, 1, 0).unwrap();
    /// assert_eq!(m.gram(1, 1).unwrap(), &q(-1));
    /// assert!(m.gram(0, 2).is_err());
    /// ```
    pub fn gram(&self, i: usize, j: usize) -> Result<&Q, MetricError> {
        let generators = self.dimension();
        let index = if i >= generators { i } else { j };
        self.gram.get(i).and_then(|row| row.get(j)).ok_or(MetricError::IndexOutOfRange { index, generators })
    }

    /// `B(e_i, e_j)` for indices the crate produced itself (`i, j < n`).
    pub(crate) fn gram_at(&self, i: usize, j: usize) -> &Q {
        &self.gram[i][j]
    }

    /// The whole Gram matrix.
    ///
    /// ```
    /// assert_eq!(algebra_core::Metric::diagonal(2, 0, 0).unwrap().gram_matrix().len(), 2);
    /// ```
    pub fn gram_matrix(&self) -> &[Vec<Q>] {
        &self.gram
    }

    /// True when all off-diagonal entries vanish.
    ///
    /// ```
    /// assert!(algebra_core::Metric::diagonal(3, 0, 0).unwrap().is_diagonal());
    /// ```
    pub fn is_diagonal(&self) -> bool {
        let n = self.dimension();
        (0..n).all(|i| (0..n).all(|j| i == j || self.gram[i][j].is_zero()))
    }

    /// True when the form is degenerate (its determinant is zero), e.g. PGA.
    ///
    /// ```
    /// assert!(algebra_core::Metric::diagonal(3, 0, 1).unwrap().is_degenerate());
    /// assert!(!algebra_core::Metric::diagonal(4, 1, 0).unwrap().is_degenerate());
    /// ```
    pub fn is_degenerate(&self) -> bool {
        determinant(&self.gram).is_zero()
    }

    /// The index of a generator label.
    ///
    /// ```
    /// assert_eq!(algebra_core::Metric::diagonal(3, 0, 0).unwrap().label_index("2"), Some(1));
    /// ```
    pub fn label_index(&self, label: &str) -> Option<usize> {
        self.labels.iter().position(|l| l == label)
    }
}

/// Rejects label sets for which two subsets concatenate to the same basis name.
fn check_unambiguous(labels: &[String]) -> Result<(), MetricError> {
    let n = labels.len();
    let mut seen: HashMap<String, u32> = HashMap::with_capacity(1 << n);
    for mask in 1u32..(1 << n) {
        let name: String = (0..n).filter(|i| mask >> i & 1 == 1).map(|i| labels[i].as_str()).collect();
        if let Some(&other) = seen.get(&name) {
            let show = |m: u32| {
                let parts: Vec<&str> = (0..n).filter(|i| m >> i & 1 == 1).map(|i| labels[i].as_str()).collect();
                format!("[{}]", parts.join(", "))
            };
            return Err(MetricError::AmbiguousLabels {
                name: format!("e{name}"),
                first: show(other),
                second: show(mask),
            });
        }
        seen.insert(name, mask);
    }
    Ok(())
}

/// The determinant of a rational matrix by exact Gaussian elimination.
#[allow(clippy::needless_range_loop)] // row operations read clearest with indices
pub(crate) fn determinant(m: &[Vec<Q>]) -> Q {
    let n = m.len();
    let mut a: Vec<Vec<Q>> = m.to_vec();
    let mut det = q(1);
    for col in 0..n {
        let Some(p) = (col..n).find(|&r| !a[r][col].is_zero()) else {
            return Q::zero();
        };
        if p != col {
            a.swap(p, col);
            det = -det;
        }
        det *= &a[col][col];
        for r in col + 1..n {
            if !a[r][col].is_zero() {
                let f = &a[r][col] / &a[col][col];
                for c in col..n {
                    let d = &f * &a[col][c];
                    a[r][c] -= d;
                }
            }
        }
    }
    det
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_bad_input() {
        let l = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        assert_eq!(Metric::new(vec![], vec![]), Err(MetricError::Empty));
        assert!(matches!(Metric::from_squares(l(&["a", "a"]), vec![q(1), q(1)]), Err(MetricError::DuplicateLabel(_))));
        assert!(matches!(Metric::from_squares(l(&["a", ""]), vec![q(1), q(1)]), Err(MetricError::InvalidLabel(_))));
        assert!(matches!(Metric::from_squares(l(&["a-b"]), vec![q(1)]), Err(MetricError::InvalidLabel(_))));
        // "1" + "12" and "11" + "2" both spell e112.
        let amb = Metric::from_squares(l(&["1", "12", "11", "2"]), vec![q(1); 4]);
        assert!(matches!(amb, Err(MetricError::AmbiguousLabels { .. })), "{amb:?}");
        assert!(matches!(
            Metric::new(l(&["a", "b"]), vec![vec![q(1)], vec![q(1)]]),
            Err(MetricError::WrongSize { .. })
        ));
        assert!(matches!(Metric::new(l(&["a"]), vec![vec![q(1)], vec![q(1)]]), Err(MetricError::WrongSize { .. })));
    }

    #[test]
    fn determinant_is_exact() {
        let m = vec![vec![q(0), q(0), q(-1)], vec![q(0), q(1), q(0)], vec![q(-1), q(0), q(0)]];
        assert_eq!(determinant(&m), q(-1));
    }
}
