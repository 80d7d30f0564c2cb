//! [`Algebra`]: a named metric with its basis names and (lazy) tables; the built-in algebras.

use crate::basis::{self, BasisError};
use crate::metric::{Metric, MetricError};
use crate::multivector::MvError;
use crate::rational::{Q, q};
use crate::tables::Tables;
use std::collections::HashMap;
use std::sync::Arc;

/// A Clifford algebra: a name, a [`Metric`], the names of its basis elements and its
/// [`Tables`]. Shared through `Arc` by every multivector over it.
///
/// ```
/// use algebra_core::Algebra;
/// let alg = Algebra::builtin("g123inf").unwrap();
/// assert_eq!(alg.dim(), 16);
/// assert_eq!(alg.mask_of("e123inf").unwrap(), 0b1111);
/// ```
pub struct Algebra {
    name: String,
    metric: Metric,
    names: Vec<String>,
    index: HashMap<String, u32>,
    order: Vec<u32>,
    tables: Tables,
}

/// One built-in algebra: the single description that the runtime ([`Algebra::builtin`]), the
/// CLI (`gam algebras`, `--algebra` help), the `algebra!` macro's `metric builtin "..."` and the
/// predefined modules of `gam-algebras` all read.
///
/// ```
/// use algebra_core::algebra::BUILTIN_ALGEBRAS;
/// let cga_null = BUILTIN_ALGEBRAS.iter().find(|b| b.name == "cga-null").unwrap();
/// assert_eq!(cga_null.labels, ["0", "1", "2", "3", "inf"]);
/// assert_eq!(cga_null.gram[0][4], -1); // e0 . einf = -1
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BuiltinAlgebra {
    /// The name used by `--algebra`, `Algebra::builtin` and `metric builtin`.
    pub name: &'static str,
    /// One line saying what the algebra is.
    pub description: &'static str,
    /// The generator labels (basis names are `e` + labels).
    pub labels: &'static [&'static str],
    /// The Gram matrix `B(e_i, e_j)` (integer entries; symmetric).
    pub gram: &'static [&'static [i8]],
}

impl BuiltinAlgebra {
    /// The metric of this entry.
    ///
    /// ```
    /// let g3 = &algebra_core::algebra::BUILTIN_ALGEBRAS[0];
    /// assert_eq!(g3.metric().unwrap().dimension(), 3);
    /// ```
    pub fn metric(&self) -> Result<Metric, MetricError> {
        let labels = self.labels.iter().map(|s| s.to_string()).collect();
        let gram = self.gram.iter().map(|row| row.iter().map(|&x| q(i64::from(x))).collect()).collect();
        Metric::new(labels, gram)
    }
}

/// The built-in algebras, in the order `gam algebras` lists them.
pub const BUILTIN_ALGEBRAS: &[BuiltinAlgebra] = &[
    BuiltinAlgebra {
        name: "g3",
        description: "Euclidean 3-space R^3",
        labels: &["1", "2", "3"],
        gram: &[&[1, 0, 0], &[0, 1, 0], &[0, 0, 1]],
    },
    BuiltinAlgebra {
        name: "g123inf",
        description: "the paper's G_{123inf}: R^3 with a null einf (einf^2 = 0)",
        labels: &["1", "2", "3", "inf"],
        gram: &[&[1, 0, 0, 0], &[0, 1, 0, 0], &[0, 0, 1, 0], &[0, 0, 0, 0]],
    },
    BuiltinAlgebra {
        name: "pga3",
        description: "projective geometric algebra R^{3,0,1} (e0^2 = 0)",
        labels: &["0", "1", "2", "3"],
        gram: &[&[0, 0, 0, 0], &[0, 1, 0, 0], &[0, 0, 1, 0], &[0, 0, 0, 1]],
    },
    BuiltinAlgebra {
        name: "cga",
        description: "conformal geometric algebra R^{4,1} (e4^2 = 1, e5^2 = -1)",
        labels: &["1", "2", "3", "4", "5"],
        gram: &[&[1, 0, 0, 0, 0], &[0, 1, 0, 0, 0], &[0, 0, 1, 0, 0], &[0, 0, 0, 1, 0], &[0, 0, 0, 0, -1]],
    },
    BuiltinAlgebra {
        name: "cga-null",
        description: "the paper's G_{0123inf}: conformal algebra with null e0, einf (e0 . einf = -1)",
        labels: &["0", "1", "2", "3", "inf"],
        gram: &[&[0, 0, 0, 0, -1], &[0, 1, 0, 0, 0], &[0, 0, 1, 0, 0], &[0, 0, 0, 1, 0], &[-1, 0, 0, 0, 0]],
    },
];

/// The names of the built-in algebras (read from [`BUILTIN_ALGEBRAS`]).
pub const BUILTINS: [&str; BUILTIN_ALGEBRAS.len()] = {
    let mut names = [""; BUILTIN_ALGEBRAS.len()];
    let mut i = 0;
    while i < names.len() {
        names[i] = BUILTIN_ALGEBRAS[i].name;
        i += 1;
    }
    names
};

/// The built-in names joined by `, ` (for help texts and error messages).
///
/// ```
/// assert_eq!(algebra_core::algebra::builtin_names(), "g3, g123inf, pga3, cga, cga-null");
/// ```
pub fn builtin_names() -> String {
    BUILTINS.join(", ")
}

impl std::fmt::Debug for Algebra {
    /// The name and the metric, not the tables.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Algebra({}: {})", self.name, self.describe_metric())
    }
}

impl Algebra {
    /// An algebra from a validated metric.
    ///
    /// ```
    /// use algebra_core::{Algebra, Metric};
    /// let sta = Algebra::new("sta", Metric::diagonal(1, 3, 0).unwrap());
    /// assert_eq!(sta.name(), "sta");
    /// ```
    pub fn new(name: impl Into<String>, metric: Metric) -> Arc<Self> {
        let n = metric.dimension();
        let names: Vec<String> = (0..1u32 << n).map(|m| basis::name(m, metric.labels())).collect();
        let index = names.iter().enumerate().map(|(m, s)| (s.clone(), m as u32)).collect();
        Arc::new(Algebra {
            name: name.into(),
            order: basis::basis_order(n),
            tables: Tables::new(metric.clone()),
            metric,
            names,
            index,
        })
    }

    /// A built-in algebra by its CLI name (the entries of [`BUILTIN_ALGEBRAS`]):
    /// - `g3`: R^3, labels 1, 2, 3.
    /// - `g123inf`: the paper's G_{123inf}, labels 1, 2, 3, inf; `e1^2 = e2^2 = e3^2 = 1`,
    ///   `einf^2 = 0`.
    /// - `pga3`: R^{3,0,1}, labels 0, 1, 2, 3; `e0^2 = 0`.
    /// - `cga`: R^{4,1}, labels 1..5; `e4^2 = 1`, `e5^2 = -1`.
    /// - `cga-null`: the paper's G_{0123inf}, labels 0, 1, 2, 3, inf; `e0 . einf = -1`,
    ///   `e0^2 = einf^2 = 0`.
    ///
    /// ```
    /// use algebra_core::{Algebra, MetricError};
    /// assert!(Algebra::builtin("cga-null").unwrap().metric().gram(0, 4).unwrap() < &algebra_core::rational::q(0));
    /// assert!(matches!(Algebra::builtin("nope"), Err(MetricError::UnknownAlgebra(_))));
    /// ```
    pub fn builtin(name: &str) -> Result<Arc<Self>, MetricError> {
        let entry = BUILTIN_ALGEBRAS
            .iter()
            .find(|b| b.name == name)
            .ok_or_else(|| MetricError::UnknownAlgebra(name.to_string()))?;
        Ok(Algebra::new(name, entry.metric()?))
    }

    /// The algebra's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The metric.
    pub fn metric(&self) -> &Metric {
        &self.metric
    }

    /// The number of generators.
    pub fn generators(&self) -> usize {
        self.metric.dimension()
    }

    /// The number of basis elements, `2^n`.
    pub fn dim(&self) -> usize {
        self.names.len()
    }

    /// The tables (built on first use of each).
    pub fn tables(&self) -> &Tables {
        &self.tables
    }

    /// The name of a basis element; [`MvError::MaskOutOfRange`] for a mask with a bit at or
    /// above the number of generators.
    ///
    /// ```
    /// let alg = algebra_core::Algebra::builtin("cga-null").unwrap();
    /// assert_eq!(alg.name_of(0b11111).unwrap(), "e0123inf");
    /// assert!(alg.name_of(0b100000).is_err());
    /// ```
    pub fn name_of(&self, mask: u32) -> Result<&str, MvError> {
        self.names
            .get(mask as usize)
            .map(String::as_str)
            .ok_or(MvError::MaskOutOfRange { mask, generators: self.metric.dimension() })
    }

    /// The name of a basis element of this algebra (a mask the crate produced itself).
    pub(crate) fn name_at(&self, mask: u32) -> &str {
        &self.names[mask as usize]
    }

    /// The mask of a basis name (`1`, `e12`, ...).
    ///
    /// ```
    /// let alg = algebra_core::Algebra::builtin("cga-null").unwrap();
    /// assert_eq!(alg.mask_of("e0inf").unwrap(), 0b10001);
    /// assert!(alg.mask_of("e4").is_err());
    /// ```
    pub fn mask_of(&self, name: &str) -> Result<u32, BasisError> {
        self.index.get(name).copied().ok_or_else(|| BasisError::UnknownElement {
            name: name.to_string(),
            labels: self.metric.labels().join(", "),
        })
    }

    /// All masks in basis order (by subset size, then mask).
    pub fn basis_order(&self) -> &[u32] {
        &self.order
    }

    /// A one-line description of the metric: squares and non-zero off-diagonal entries.
    ///
    /// ```
    /// let alg = algebra_core::Algebra::builtin("cga-null").unwrap();
    /// assert_eq!(alg.describe_metric(), "e0.e0 = 0, e1.e1 = 1, e2.e2 = 1, e3.e3 = 1, einf.einf = 0, e0.einf = -1");
    /// ```
    pub fn describe_metric(&self) -> String {
        let m = &self.metric;
        let l = m.labels();
        let n = m.dimension();
        let fmt = |x: &Q| crate::rational::format_rational(x);
        let mut parts: Vec<String> =
            (0..n).map(|i| format!("e{}.e{} = {}", l[i], l[i], fmt(m.gram_at(i, i)))).collect();
        for i in 0..n {
            for j in i + 1..n {
                if *m.gram_at(i, j) != q(0) {
                    parts.push(format!("e{}.e{} = {}", l[i], l[j], fmt(m.gram_at(i, j))));
                }
            }
        }
        parts.join(", ")
    }
}
