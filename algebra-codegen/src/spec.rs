//! Step 1 of the pipeline: the typed module specification ([`ModuleSpec`], [`TypeSpec`]) and
//! its validation ([`CodegenError`]).

use crate::constraint::ConstraintKind;
use algebra_core::algebra::Algebra;
use algebra_core::basis::{Basis, grade};
use algebra_core::metric::Metric;
use std::collections::BTreeMap;
use std::sync::Arc;

/// Why a module specification was rejected.
#[derive(Debug, Clone, PartialEq)]
pub enum CodegenError {
    /// No types declared.
    NoTypes,
    /// A type name that is not a Rust type identifier.
    InvalidTypeName(String),
    /// The same type name twice.
    DuplicateType(String),
    /// A type with no elements.
    EmptyType(String),
    /// An element listed twice in one type.
    DuplicateElement {
        /// The type.
        ty: String,
        /// The repeated element.
        element: String,
    },
    /// Two types with exactly the same elements (the output-type choice would be ambiguous).
    SameElements(String, String),
    /// An element that is not a basis name of the algebra.
    UnknownElement {
        /// The type.
        ty: String,
        /// The bad name.
        element: String,
        /// The algebra's labels.
        labels: String,
    },
    /// A grade outside `0..=n`.
    BadGrade {
        /// The type.
        ty: String,
        /// The grade asked for.
        grade: usize,
        /// The number of generators.
        n: usize,
    },
    /// A malformed `--types` string.
    BadTypeList(String),
    /// A reordered basis name (`e20`) in the product basis, where reordering generators is
    /// not a sign change in general.
    OrientedInProductBasis {
        /// The type.
        ty: String,
        /// The reordered name.
        element: String,
    },
    /// A `where` clause naming no known constraint.
    UnknownConstraint {
        /// The type.
        ty: String,
        /// The word after `where`.
        word: String,
    },
    /// A table coefficient that does not fit the `i64` ratio of `T::from_ratio`.
    CoefficientTooLarge(String),
    /// A recognised geometry whose named constructors cannot be built (a bug, not bad input).
    NamedConstructor(String),
}

impl std::fmt::Display for CodegenError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CodegenError::NoTypes => write!(f, "declare at least one type"),
            CodegenError::InvalidTypeName(t) => {
                write!(f, "`{t}` is not a valid type name (use an identifier starting with an uppercase letter)")
            }
            CodegenError::DuplicateType(t) => write!(f, "type `{t}` is declared twice"),
            CodegenError::EmptyType(t) => write!(f, "type `{t}` has no basis elements"),
            CodegenError::DuplicateElement { ty, element } => write!(f, "type `{ty}` lists `{element}` twice"),
            CodegenError::SameElements(a, b) => write!(f, "types `{a}` and `{b}` have the same basis elements"),
            CodegenError::UnknownElement { ty, element, labels } => {
                write!(f, "type `{ty}`: unknown basis element `{element}` (generators: {labels})")
            }
            CodegenError::BadGrade { ty, grade, n } => {
                write!(f, "type `{ty}`: grade {grade} does not exist in an algebra with {n} generators")
            }
            CodegenError::BadTypeList(t) => write!(
                f,
                "bad type list `{t}`: expected `Name=elements;Name=elements` with elements `grade K`, `even`, `odd`, `all` or a comma list of basis names"
            ),
            CodegenError::OrientedInProductBasis { ty, element } => write!(
                f,
                "type `{ty}`: `{element}` reorders the generators of a basis element; orientation-aware names need the blade basis"
            ),
            CodegenError::UnknownConstraint { ty, word } => write!(
                f,
                "type `{ty}`: unknown constraint `{word}` (expected `where unit`, `where null` or `where simple`)"
            ),
            CodegenError::CoefficientTooLarge(c) => {
                write!(f, "a table coefficient ({c}) is too large for T::from_ratio(i64, i64)")
            }
            CodegenError::NamedConstructor(why) => write!(f, "named constructors: {why}"),
        }
    }
}

// Written by hand (not `thiserror`): the macro path then builds one `syn` (thiserror 2 pulls
// in syn 3 beside the macro's syn 2; issue 26 item 5).
impl std::error::Error for CodegenError {}

/// One declared type: a name, doc lines and the basis elements (masks) it holds.
#[derive(Debug, Clone, PartialEq)]
pub struct TypeSpec {
    /// The Rust type name.
    pub name: String,
    /// Doc lines to put on the struct.
    pub doc: Vec<String>,
    /// The masks of the basis elements in storage order: as declared for a list (`[e01, e02,
    /// e03, e12, e31, e23]`), the algebra's basis order for a grade selector (`grade K`,
    /// `even`, `odd`, `all`). Field `i` of the generated struct (and of `new`, `to_array`,
    /// `Index`, iteration, `Display` and the `repr(C)` layout) holds `elements[i]`.
    pub elements: Vec<u32>,
    /// Elements listed in a non-canonical orientation (`e20` for `e02`): mask → (the name
    /// as written, `-1` or `1`). The field holds the coefficient in that orientation.
    pub renamed: BTreeMap<u32, (String, i64)>,
    /// A polynomial constraint every value of the type is declared to satisfy (`where unit`:
    /// `rev(x) x = 1`; `where null`: `x x = 0`; `where simple`: `x ∧ x = 0`). The generator
    /// then emits constrained kernels as methods ([`crate::constraint::methods`]).
    pub constraint: Option<ConstraintKind>,
}

impl TypeSpec {
    /// The basis names of the fields in storage order, as declared (`e31` where the
    /// declaration reorders `e13`, [`crate::orient`]); the field of `1` is named `scalar` in
    /// generated code ([`crate::naming::field_name`]).
    ///
    /// ```
    /// use algebra_core::Algebra;
    /// use algebra_codegen::ModuleSpec;
    /// let alg = Algebra::builtin("pga3").unwrap();
    /// let t = &ModuleSpec::parse_types("Line=e01,e02,e03,e12,e31,e23", &alg).unwrap()[0];
    /// assert_eq!(t.element_names(&alg), ["e01", "e02", "e03", "e12", "e31", "e23"]);
    /// ```
    pub fn element_names(&self, algebra: &Algebra) -> Vec<String> {
        self.elements
            .iter()
            .map(|m| {
                self.renamed.get(m).map_or_else(
                    || algebra.name_of(*m).expect("a mask of the spec's algebra").to_string(),
                    |(n, _)| n.clone(),
                )
            })
            .collect()
    }

    /// The sign of each field (`-1` where the name reverses the canonical orientation,
    /// [`crate::orient`]).
    pub fn signs(&self) -> Vec<i64> {
        self.elements.iter().map(|m| self.renamed.get(m).map_or(1, |(_, s)| *s)).collect()
    }

    /// A type from a selector: `grade K` (or `gradeK`), `grades K,L`, `even`, `odd`, `all`,
    /// or a comma-separated list of basis names (`1, e12, e1inf`). Grades count generators in
    /// the chosen basis (the paper's notion in the product basis). A listed name may reorder
    /// the generators (`e20`, `e31`: the blade in that orientation, see [`crate::orient`]).
    ///
    /// ```
    /// use algebra_core::Algebra;
    /// use algebra_codegen::TypeSpec;
    /// let alg = Algebra::builtin("g123inf").unwrap();
    /// let v = TypeSpec::parse("Vector", "grade 1", &alg).unwrap();
    /// assert_eq!(v.elements.len(), 4);
    /// let m = TypeSpec::parse("Motor", "1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf", &alg).unwrap();
    /// assert_eq!(m.elements, TypeSpec::parse("Motor", "even", &alg).unwrap().elements);
    /// // a declared constraint follows the selector
    /// let unit = TypeSpec::parse("Motor", "even where unit", &alg).unwrap();
    /// assert_eq!(unit.constraint, Some(algebra_codegen::constraint::ConstraintKind::Unit));
    /// assert!(TypeSpec::parse("Motor", "even where round", &alg).is_err());
    /// ```
    pub fn parse(name: &str, selector: &str, algebra: &Algebra) -> Result<TypeSpec, CodegenError> {
        if let Some((sel, word)) = selector.split_once(" where ") {
            let kind = ConstraintKind::parse(word.trim()).ok_or_else(|| CodegenError::UnknownConstraint {
                ty: name.to_string(),
                word: word.trim().to_string(),
            })?;
            let mut t = TypeSpec::parse(name, sel, algebra)?;
            t.constraint = Some(kind);
            return Ok(t);
        }
        let n = algebra.generators();
        let sel = selector.trim();
        let by_grades = |grades: &[usize]| -> Result<Vec<u32>, CodegenError> {
            for &g in grades {
                if g > n {
                    return Err(CodegenError::BadGrade { ty: name.to_string(), grade: g, n });
                }
            }
            Ok(algebra.basis_order().iter().copied().filter(|&m| grades.contains(&grade(m))).collect())
        };
        let elements = if let Some(rest) = sel.strip_prefix("grades") {
            let gs: Result<Vec<usize>, _> = rest.split(',').map(|g| g.trim().parse::<usize>()).collect();
            by_grades(&gs.map_err(|_| CodegenError::BadTypeList(selector.to_string()))?)?
        } else if let Some(rest) = sel.strip_prefix("grade") {
            let g = rest.trim().parse::<usize>().map_err(|_| CodegenError::BadTypeList(selector.to_string()))?;
            by_grades(&[g])?
        } else if sel == "even" {
            by_grades(&(0..=n).step_by(2).collect::<Vec<_>>())?
        } else if sel == "odd" {
            by_grades(&(1..=n).step_by(2).collect::<Vec<_>>())?
        } else if sel == "all" {
            algebra.basis_order().to_vec()
        } else {
            let mut masks = Vec::new();
            let mut renamed = BTreeMap::new();
            for el in sel.split(',').map(str::trim) {
                let (m, sign) = match algebra.mask_of(el) {
                    Ok(m) => (m, 1),
                    Err(_) => {
                        crate::orient::oriented_mask(algebra, el).ok_or_else(|| CodegenError::UnknownElement {
                            ty: name.to_string(),
                            element: el.to_string(),
                            labels: algebra.metric().labels().join(", "),
                        })?
                    }
                };
                if masks.contains(&m) {
                    return Err(CodegenError::DuplicateElement { ty: name.to_string(), element: el.to_string() });
                }
                if algebra.name_of(m).is_ok_and(|name| el != name) {
                    renamed.insert(m, (el.to_string(), sign));
                }
                masks.push(m);
            }
            // the declared order is the storage order (fields, `new`, arrays, `repr(C)`)
            let mut t = TypeSpec::new(name, masks)?;
            t.renamed = renamed;
            return Ok(t);
        };
        TypeSpec::new(name, elements)
    }

    /// A type from masks, stored in the order given.
    ///
    /// ```
    /// let t = algebra_codegen::TypeSpec::new("Scalar", vec![0]).unwrap();
    /// assert_eq!(t.elements, [0]);
    /// ```
    pub fn new(name: &str, elements: Vec<u32>) -> Result<TypeSpec, CodegenError> {
        let valid = name.chars().next().is_some_and(|c| c.is_ascii_uppercase())
            && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
        if !valid {
            return Err(CodegenError::InvalidTypeName(name.to_string()));
        }
        if elements.is_empty() {
            return Err(CodegenError::EmptyType(name.to_string()));
        }
        Ok(TypeSpec { name: name.to_string(), doc: Vec::new(), elements, renamed: BTreeMap::new(), constraint: None })
    }
}

/// A module to generate.
#[derive(Debug, Clone)]
pub struct ModuleSpec {
    /// The module name (`cga_null`).
    pub name: String,
    /// Doc lines for the module.
    pub doc: Vec<String>,
    /// The algebra.
    pub algebra: Arc<Algebra>,
    /// The basis the types' elements (and field names) refer to.
    pub basis: Basis,
    /// The declared types.
    pub types: Vec<TypeSpec>,
    /// Derive `serde::Serialize`/`Deserialize` on every type under
    /// `#[cfg_attr(feature = "serde", ...)]` (the declaring crate then has a `serde` feature
    /// enabling its `serde` dependency).
    pub serde: bool,
    /// Whether a module without the full multivector gets the automatic `Even`/`Odd` output
    /// types ([`crate::fallback`]); `false` sends every product landing outside the declared
    /// types to the full multivector (the DSL's `fallback full;`). Default `true`.
    pub parity_types: bool,
    /// Whether detected closed forms (`exp`, `log`, `normalize`, ... in [`crate::closed`]) are
    /// emitted; `false` (the DSL's `closed_forms off;`) leaves them out, for a crate that gives
    /// the types its own methods of those names. Default `true`.
    pub closed_forms: bool,
    /// The size policy's threshold: a kernel with more terms than this is a loop over a
    /// constant table instead of straight-line code (the DSL's `table_above N;`, `gam codegen
    /// --table-above N`). Default [`crate::size::TABLE_THRESHOLD`].
    pub table_above: usize,
}

impl ModuleSpec {
    /// A module spec from a metric, validating the types.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis};
    /// use algebra_codegen::{ModuleSpec, TypeSpec};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let types = vec![TypeSpec::parse("Vector", "grade 1", &alg).unwrap()];
    /// let spec = ModuleSpec::new("g3", alg.metric().clone(), Basis::Blade, types).unwrap();
    /// assert_eq!(spec.types.len(), 1);
    /// ```
    pub fn new(name: &str, metric: Metric, basis: Basis, types: Vec<TypeSpec>) -> Result<Self, CodegenError> {
        let algebra = Algebra::new(name, metric);
        if types.is_empty() {
            return Err(CodegenError::NoTypes);
        }
        for (i, t) in types.iter().enumerate() {
            if let (Basis::Product, Some((name, _))) = (basis, t.renamed.values().next()) {
                return Err(CodegenError::OrientedInProductBasis { ty: t.name.clone(), element: name.clone() });
            }
            for other in &types[..i] {
                if other.name == t.name {
                    return Err(CodegenError::DuplicateType(t.name.clone()));
                }
                let (mut a, mut b) = (other.elements.clone(), t.elements.clone());
                a.sort_unstable();
                b.sort_unstable();
                if a == b {
                    return Err(CodegenError::SameElements(other.name.clone(), t.name.clone()));
                }
            }
        }
        Ok(ModuleSpec {
            name: name.to_string(),
            doc: Vec::new(),
            algebra,
            basis,
            types,
            serde: false,
            parity_types: true,
            closed_forms: true,
            table_above: crate::size::TABLE_THRESHOLD,
        })
    }

    /// Parses the `gam codegen --types` syntax: `Motor=1,e12,e13;Vector=grade1`.
    ///
    /// ```
    /// use algebra_core::Algebra;
    /// use algebra_codegen::ModuleSpec;
    /// let alg = Algebra::builtin("g123inf").unwrap();
    /// let types = ModuleSpec::parse_types("Motor=even;Vector=grade1", &alg).unwrap();
    /// assert_eq!(types[0].elements.len(), 8);
    /// assert!(ModuleSpec::parse_types("Motor", &alg).is_err());
    /// ```
    pub fn parse_types(text: &str, algebra: &Algebra) -> Result<Vec<TypeSpec>, CodegenError> {
        text.split(';')
            .map(str::trim)
            .filter(|s| !s.is_empty())
            .map(|decl| {
                let (name, sel) = decl.split_once('=').ok_or_else(|| CodegenError::BadTypeList(text.to_string()))?;
                TypeSpec::parse(name.trim(), sel, algebra)
            })
            .collect()
    }
}
