//! [`Algebra`]: a named metric with its basis names and (lazy) tables; the built-in algebras.

use crate::basis::{self, BasisError};
use crate::metric::{Metric, MetricError};
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

/// The names of the built-in algebras.
pub const BUILTINS: [&str; 5] = ["g3", "g123inf", "pga3", "cga", "cga-null"];

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

    /// A built-in algebra by its CLI name:
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
    /// assert!(Algebra::builtin("cga-null").unwrap().metric().gram(0, 4) < &algebra_core::rational::q(0));
    /// assert!(matches!(Algebra::builtin("nope"), Err(MetricError::UnknownAlgebra(_))));
    /// ```
    pub fn builtin(name: &str) -> Result<Arc<Self>, MetricError> {
        let labels = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        let metric = match name {
            "g3" => Metric::from_squares(labels(&["1", "2", "3"]), vec![q(1); 3])?,
            "g123inf" => Metric::from_squares(labels(&["1", "2", "3", "inf"]), vec![q(1), q(1), q(1), q(0)])?,
            "pga3" => Metric::from_squares(labels(&["0", "1", "2", "3"]), vec![q(0), q(1), q(1), q(1)])?,
            "cga" => Metric::from_squares(labels(&["1", "2", "3", "4", "5"]), vec![q(1), q(1), q(1), q(1), q(-1)])?,
            "cga-null" => {
                let mut g = vec![vec![q(0); 5]; 5];
                for (i, row) in g.iter_mut().enumerate().take(4).skip(1) {
                    row[i] = q(1);
                }
                g[0][4] = q(-1);
                g[4][0] = q(-1);
                Metric::new(labels(&["0", "1", "2", "3", "inf"]), g)?
            }
            _ => return Err(MetricError::UnknownAlgebra(name.to_string())),
        };
        Ok(Algebra::new(name, metric))
    }

    /// A built-in name, or else a path to a TOML description (see
    /// [`Metric::from_toml_str`]); the CLI's `--algebra` argument.
    ///
    /// ```
    /// let alg = algebra_core::Algebra::from_name_or_path("pga3").unwrap();
    /// assert!(alg.metric().is_degenerate());
    /// ```
    pub fn from_name_or_path(arg: &str) -> Result<Arc<Self>, MetricError> {
        if BUILTINS.contains(&arg) {
            return Algebra::builtin(arg);
        }
        if !arg.ends_with(".toml") && !std::path::Path::new(arg).exists() {
            return Err(MetricError::UnknownAlgebra(arg.to_string()));
        }
        let text = std::fs::read_to_string(arg)
            .map_err(|e| MetricError::Toml { path: arg.to_string(), message: e.to_string() })?;
        let (name, metric) = Metric::from_toml_str(&text, arg)?;
        Ok(Algebra::new(name.unwrap_or_else(|| arg.to_string()), metric))
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

    /// The name of a basis element.
    ///
    /// ```
    /// let alg = algebra_core::Algebra::builtin("cga-null").unwrap();
    /// assert_eq!(alg.name_of(0b11111), "e0123inf");
    /// ```
    pub fn name_of(&self, mask: u32) -> &str {
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
        let mut parts: Vec<String> = (0..n).map(|i| format!("e{}.e{} = {}", l[i], l[i], fmt(m.gram(i, i)))).collect();
        for i in 0..n {
            for j in i + 1..n {
                if *m.gram(i, j) != q(0) {
                    parts.push(format!("e{}.e{} = {}", l[i], l[j], fmt(m.gram(i, j))));
                }
            }
        }
        parts.join(", ")
    }
}
