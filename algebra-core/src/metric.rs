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
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MetricError {
    /// No generators.
    #[error("an algebra needs at least one generator")]
    Empty,
    /// More generators than [`MAX_GENERATORS`].
    #[error("{0} generators: at most {MAX_GENERATORS} are supported")]
    TooManyGenerators(usize),
    /// A label that is empty or not ASCII alphanumeric.
    #[error("generator label `{0}` must be non-empty ASCII letters or digits")]
    InvalidLabel(String),
    /// The same label twice.
    #[error("generator label `{0}` is declared twice")]
    DuplicateLabel(String),
    /// Two different subsets of generators would get the same basis name.
    #[error("labels are ambiguous: basis name `{name}` would mean both {first} and {second}")]
    AmbiguousLabels {
        /// The name that two subsets share.
        name: String,
        /// One reading, as a list of labels.
        first: String,
        /// Another reading.
        second: String,
    },
    /// The Gram matrix is not n x n.
    #[error("the Gram matrix must be {expected}x{expected}, found a row or column count of {found}")]
    WrongSize {
        /// The number of generators.
        expected: usize,
        /// The offending row count or row length.
        found: usize,
    },
    /// `B(e_i, e_j) != B(e_j, e_i)`.
    #[error("the Gram matrix is not symmetric: B({a}, {b}) = {ab} but B({b}, {a}) = {ba}")]
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
    #[error("metric entry names unknown generator `{0}`")]
    UnknownLabel(String),
    /// No built-in algebra of that name.
    #[error("unknown algebra `{0}` (built-ins: g3, g123inf, pga3, cga, cga-null; or a path to a .toml file)")]
    UnknownAlgebra(String),
    /// A TOML description that could not be read or understood.
    #[error("bad algebra file {path}: {message}")]
    Toml {
        /// The file (or `<string>`).
        path: String,
        /// What is wrong.
        message: String,
    },
}

/// Generator labels with the symmetric bilinear form on them.
///
/// ```
/// use algebra_core::{Metric, rational::q};
/// let m = Metric::new(
///     vec!["0".into(), "inf".into()],
///     vec![vec![q(0), q(-1)], vec![q(-1), q(0)]],
/// ).unwrap();
/// assert_eq!(m.gram(0, 1), &q(-1));
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
    /// assert_eq!(m.gram(1, 0), &q(-1));
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
    /// assert_eq!(m.gram(4, 4), &q(-1));
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

    /// `B(e_i, e_j)`.
    ///
    /// ```
    /// use algebra_core::{Metric, rational::q};
    /// assert_eq!(Metric::diagonal(1, 1, 0).unwrap().gram(1, 1), &q(-1));
    /// ```
    pub fn gram(&self, i: usize, j: usize) -> &Q {
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

    /// Reads an algebra description in TOML. Either a full matrix
    ///
    /// ```toml
    /// name = "plane"            # optional
    /// generators = ["x", "y"]
    /// gram = [[1, 0], [0, "-1/2"]]
    /// ```
    ///
    /// or the non-zero entries by label pair (unlisted pairs are 0; `(a, b)` sets both
    /// `B(a, b)` and `B(b, a)`):
    ///
    /// ```toml
    /// generators = ["0", "1", "2", "3", "inf"]
    /// metric = { "1,1" = 1, "2,2" = 1, "3,3" = 1, "0,inf" = -1 }
    /// ```
    ///
    /// Entries are integers or rational strings (`"p/q"`, exact decimals). Returns the
    /// optional name and the metric.
    ///
    /// ```
    /// let (name, m) = algebra_core::Metric::from_toml_str(
    ///     "name = \"h\"\ngenerators = [\"a\", \"b\"]\nmetric = { \"a,b\" = \"1/2\" }",
    ///     "<string>",
    /// ).unwrap();
    /// assert_eq!(name.as_deref(), Some("h"));
    /// assert_eq!(m.gram(1, 0), &algebra_core::rational::ratio(1, 2));
    /// ```
    pub fn from_toml_str(text: &str, path: &str) -> Result<(Option<String>, Metric), MetricError> {
        let err = |message: String| MetricError::Toml { path: path.to_string(), message };
        let doc: toml::Table = text.parse().map_err(|e: toml::de::Error| {
            // "TOML parse error at line L, column C" ... "reason": keep both, on one line
            let msg = e.to_string();
            let mut lines = msg.lines().map(str::trim).filter(|l| !l.is_empty());
            let first = lines.next().unwrap_or("parse error").to_string();
            match lines.rfind(|l| !l.contains('|') && !l.starts_with('^')) {
                Some(reason) => err(format!("{first}: {reason}")),
                None => err(first),
            }
        })?;
        for key in doc.keys() {
            if !["name", "generators", "gram", "metric"].contains(&key.as_str()) {
                return Err(err(format!("unknown key `{key}` (expected name, generators, gram or metric)")));
            }
        }
        let name = match doc.get("name") {
            None => None,
            Some(toml::Value::String(s)) => Some(s.clone()),
            Some(_) => return Err(err("`name` must be a string".into())),
        };
        let labels: Vec<String> = match doc.get("generators") {
            Some(toml::Value::Array(a)) => a
                .iter()
                .map(|v| match v {
                    toml::Value::String(s) => Ok(s.clone()),
                    toml::Value::Integer(i) => Ok(i.to_string()),
                    _ => Err(err("`generators` must be a list of labels".into())),
                })
                .collect::<Result<_, _>>()?,
            _ => return Err(err("missing `generators = [...]`".into())),
        };
        let n = labels.len();
        let entry = |v: &toml::Value, at: &str| -> Result<Q, MetricError> {
            match v {
                toml::Value::Integer(i) => Ok(q(*i)),
                toml::Value::String(s) => parse_rational(s).map_err(|e| err(format!("{at}: {e}"))),
                _ => Err(err(format!(
                    "{at}: entries must be integers or rational strings like \"1/2\" (floats are not exact)"
                ))),
            }
        };
        let gram = match (doc.get("gram"), doc.get("metric")) {
            (Some(_), Some(_)) => return Err(err("give either `gram` or `metric`, not both".into())),
            (None, None) => return Err(err("missing `gram = [[...]]` or `metric = { \"a,b\" = value }`".into())),
            (Some(toml::Value::Array(rows)), None) => rows
                .iter()
                .enumerate()
                .map(|(i, row)| match row {
                    toml::Value::Array(r) => r
                        .iter()
                        .enumerate()
                        .map(|(j, v)| entry(v, &format!("gram[{i}][{j}]")))
                        .collect::<Result<Vec<_>, _>>(),
                    _ => Err(err("`gram` must be a list of rows".into())),
                })
                .collect::<Result<Vec<_>, _>>()?,
            (None, Some(toml::Value::Table(t))) => {
                let mut gram = vec![vec![Q::zero(); n]; n];
                let index: HashMap<&str, usize> = labels.iter().enumerate().map(|(i, l)| (l.as_str(), i)).collect();
                let mut set: HashMap<(usize, usize), Q> = HashMap::new();
                for (key, v) in t {
                    let (a, b) =
                        key.split_once(',').ok_or_else(|| err(format!("metric key `{key}` must be \"a,b\"")))?;
                    let ia = *index.get(a.trim()).ok_or_else(|| MetricError::UnknownLabel(a.trim().into()))?;
                    let ib = *index.get(b.trim()).ok_or_else(|| MetricError::UnknownLabel(b.trim().into()))?;
                    let value = entry(v, &format!("metric \"{key}\""))?;
                    // "a,b" and "b,a" name one entry: contradictory values are an error, not "last wins"
                    if let Some(first) = set.insert((ia.min(ib), ia.max(ib)), value.clone())
                        && first != value
                    {
                        return Err(err(format!(
                            "metric \"{key}\" = {value} contradicts an earlier entry for the same pair ({first}); B is symmetric"
                        )));
                    }
                    gram[ia][ib] = value.clone();
                    gram[ib][ia] = value;
                }
                gram
            }
            _ => return Err(err("`gram` must be a matrix and `metric` a table".into())),
        };
        Ok((name, Metric::new(labels, gram)?))
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
    fn toml_forms_agree() {
        let (_, a) =
            Metric::from_toml_str("generators = [\"0\",\"1\",\"inf\"]\nmetric = { \"1,1\" = 1, \"0,inf\" = -1 }", "a")
                .unwrap();
        let (_, b) =
            Metric::from_toml_str("generators = [\"0\",\"1\",\"inf\"]\ngram = [[0,0,-1],[0,1,0],[-1,0,0]]", "b")
                .unwrap();
        assert_eq!(a, b);
        assert!(!a.is_degenerate());
        assert!(Metric::from_toml_str("generators = [\"a\"]\ngram = [[1.5]]", "c").is_err());
        assert!(Metric::from_toml_str("generators = [\"a\"]\nmetric = { \"a,z\" = 1 }", "c").is_err());
        let Err(MetricError::Toml { message, .. }) = Metric::from_toml_str("generators = [\"a\"", "c") else {
            panic!("broken TOML must be rejected")
        };
        assert!(message.contains("line 1") && message.contains(": "), "{message}");
    }

    #[test]
    fn determinant_is_exact() {
        let m = vec![vec![q(0), q(0), q(-1)], vec![q(0), q(1), q(0)], vec![q(-1), q(0), q(0)]];
        assert_eq!(determinant(&m), q(-1));
    }
}
