//! Exact product tables in both basis representations.
//!
//! A product of two basis elements is in general a *sum* of basis elements with rational
//! coefficients ([`Sparse`]). The tables are built from the Gram matrix alone, for any
//! symmetric form (non-diagonal, degenerate), by two recursions that follow directly from
//! the defining relation `u v + v u = 2 B(u, v)`:
//!
//! * **Blade basis (Chevalley).** For a vector `e_i` and a blade `E_T`,
//!   `e_i E_T = e_i ⌋ E_T + e_i ^ E_T`, where the contraction is the Laplace expansion
//!   `e_i ⌋ (e_{t1} ^ ... ^ e_{tk}) = Σ_m (-1)^(m-1) B(e_i, e_{tm}) E_{T \ tm}`.
//!   With `i = min S` and `E_S = e_i ^ E_{S'} = e_i E_{S'} - e_i ⌋ E_{S'}`, the row of
//!   `E_S` follows from rows of lower subsets.
//! * **Product basis.** `e_i P_T` is `P_{T ∪ i}` when `i` precedes every index of `T`,
//!   `B(e_i, e_i) P_{T'}` when `i = min T`, and otherwise
//!   `2 B(e_i, e_{t1}) P_{T'} - e_{t1} (e_i P_{T'})` (anticommuting past `t1 = min T`).
//!   Then `P_S P_T = e_i (P_{S'} P_T)`.
//!
//! The change of basis (`P_S = E_S + lower grades`, unitriangular) comes from multiplying
//! out `e_i P_{S'}` in the blade basis, and its inverse by back substitution. The two gp
//! tables are built independently; the tests check that the change of basis carries one
//! onto the other. The outer product and the complements are combinatorial (metric-free);
//! contractions and the scalar product are grade selections of the blade-basis geometric
//! product; every other product-basis table is the blade one conjugated by the change of
//! basis.
//!
//! Tables are built lazily, each on first use, and cached.

use crate::basis::{Basis, grade, parity_sign, wedge_sign};
use crate::metric::Metric;
use crate::multivector::MvError;
use crate::rational::{Q, q, ratio};
use num_traits::Zero;
use std::fmt;
use std::str::FromStr;
use std::sync::OnceLock;

/// A sparse multivector with exact coefficients: `(mask, coefficient)` sorted by mask, no
/// zero coefficients.
pub type Sparse = Vec<(u32, Q)>;

/// The bilinear products that have tables.
///
/// ```
/// use algebra_core::Product;
/// assert_eq!("lc".parse::<Product>().unwrap(), Product::LeftContraction);
/// assert_eq!(Product::Outer.cli_name(), "op");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Product {
    /// The geometric (Clifford) product `xy`.
    Geometric,
    /// The outer (exterior) product `x ^ y` (metric-free).
    Outer,
    /// The left contraction `x ⌋ y`: on blades `<xy>_{l-k}` for grades `k <= l`, else 0.
    LeftContraction,
    /// The right contraction `x ⌊ y`: on blades `<xy>_{k-l}` for grades `k >= l`, else 0.
    RightContraction,
    /// The scalar product `<xy>_0`.
    Scalar,
    /// The regressive product `x ∨ y = undual(dual(x) ^ dual(y))` with the complements of
    /// [`Unary::Dual`] (metric-free, so it works for degenerate metrics).
    Regressive,
    /// The commutator product `(xy - yx)/2` (the paper's "outer" on bivector-vector pairs).
    Commutator,
    /// The anticommutator product `(xy + yx)/2` (the paper's "inner").
    Anticommutator,
}

impl Product {
    /// Every product, in a fixed order.
    pub const ALL: [Product; 8] = [
        Product::Geometric,
        Product::Outer,
        Product::LeftContraction,
        Product::RightContraction,
        Product::Scalar,
        Product::Regressive,
        Product::Commutator,
        Product::Anticommutator,
    ];

    /// The short name used by the CLI (`gp`, `op`, `lc`, `rc`, `sp`, `rp`, `comm`, `acomm`).
    pub fn cli_name(self) -> &'static str {
        match self {
            Product::Geometric => "gp",
            Product::Outer => "op",
            Product::LeftContraction => "lc",
            Product::RightContraction => "rc",
            Product::Scalar => "sp",
            Product::Regressive => "rp",
            Product::Commutator => "comm",
            Product::Anticommutator => "acomm",
        }
    }

    fn index(self) -> usize {
        Product::ALL.iter().position(|&p| p == self).expect("listed")
    }
}

impl fmt::Display for Product {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.cli_name())
    }
}

/// An unknown product name.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnknownProduct(pub String);

impl std::fmt::Display for UnknownProduct {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "unknown product `{}` (expected gp, op, lc, rc, sp, rp, comm or acomm)", self.0)
    }
}

impl std::error::Error for UnknownProduct {}

impl FromStr for Product {
    type Err = UnknownProduct;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Product::ALL.into_iter().find(|p| p.cli_name() == s).ok_or_else(|| UnknownProduct(s.to_string()))
    }
}

/// The linear unary operations that have tables.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Unary {
    /// The reverse: the anti-automorphism fixing vectors (`(xy)~ = y~ x~`).
    Reverse,
    /// The grade involution: the automorphism negating vectors.
    GradeInvolution,
    /// The Clifford conjugate: reverse composed with grade involution.
    CliffordConjugate,
    /// The right complement (metric-free dual): `E_S ^ dual(E_S) = E_{all}` on blades.
    /// Works whether or not the pseudoscalar is invertible.
    Dual,
    /// The left complement, inverse of [`Unary::Dual`]: `undual(E_S) ^ E_S = E_{all}`.
    Undual,
    /// The paper's "reverse" by subset size, `e_S -> (-1)^{k(k-1)/2} e_S` in the table's own
    /// basis. Equal to [`Unary::Reverse`] in the blade basis; in the product basis of a
    /// non-orthogonal metric it is **not** an anti-automorphism.
    BasisReverse,
}

impl Unary {
    const ALL: [Unary; 6] = [
        Unary::Reverse,
        Unary::GradeInvolution,
        Unary::CliffordConjugate,
        Unary::Dual,
        Unary::Undual,
        Unary::BasisReverse,
    ];
    fn index(self) -> usize {
        Unary::ALL.iter().position(|&u| u == self).expect("listed")
    }
}

/// A bilinear product on basis elements: entry `(a, b)` is the [`Sparse`] result.
#[derive(Debug, Clone, PartialEq)]
pub struct ProductTable {
    dim: usize,
    entries: Vec<Sparse>,
}

impl ProductTable {
    /// The product of basis elements `a` and `b` (masks).
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Product, rational::q};
    /// let alg = Algebra::builtin("cga-null").unwrap();
    /// let gp = alg.tables().product(Basis::Product, Product::Geometric);
    /// // einf e0 = -2 - e0inf (product basis; e0 is bit 0, einf bit 4)
    /// assert_eq!(gp.get(0b10000, 0b00001).unwrap(), &[(0, q(-2)), (0b10001, q(-1))]);
    /// assert!(gp.get(0b100000, 0).is_err());
    /// ```
    ///
    /// [`MvError::MaskOutOfRange`] when `a` or `b` is not a mask of the algebra.
    pub fn get(&self, a: u32, b: u32) -> Result<&[(u32, Q)], MvError> {
        mask_in_range(a, self.dim)?;
        mask_in_range(b, self.dim)?;
        Ok(self.at(a, b))
    }

    /// The entry for masks the crate produced itself (`a, b < dim`).
    pub(crate) fn at(&self, a: u32, b: u32) -> &[(u32, Q)] {
        &self.entries[a as usize * self.dim + b as usize]
    }

    /// The number of basis elements.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// How many entries are non-zero (a measure of sparsity).
    pub fn nonzero_entries(&self) -> usize {
        self.entries.iter().filter(|e| !e.is_empty()).count()
    }
}

/// `Ok` when `mask` indexes a basis of `dim = 2^n` elements, else [`MvError::MaskOutOfRange`].
fn mask_in_range(mask: u32, dim: usize) -> Result<(), MvError> {
    if (mask as usize) < dim {
        Ok(())
    } else {
        Err(MvError::MaskOutOfRange { mask, generators: dim.trailing_zeros() as usize })
    }
}

/// A linear map on the basis: `image(a)` is the [`Sparse`] image of basis element `a`.
#[derive(Debug, Clone, PartialEq)]
pub struct LinearMap {
    images: Vec<Sparse>,
}

impl LinearMap {
    /// The image of basis element `a`.
    ///
    /// ```
    /// use algebra_core::{Algebra, rational::q};
    /// let alg = Algebra::builtin("cga-null").unwrap();
    /// // product-basis e0inf in blade coordinates: -1 + e0^einf
    /// assert_eq!(alg.tables().to_blade().image(0b10001).unwrap(), &[(0, q(-1)), (0b10001, q(1))]);
    /// assert!(alg.tables().to_blade().image(0b100000).is_err());
    /// ```
    ///
    /// [`MvError::MaskOutOfRange`] when `a` is not a mask of the algebra.
    pub fn image(&self, a: u32) -> Result<&[(u32, Q)], MvError> {
        mask_in_range(a, self.images.len())?;
        Ok(self.image_at(a))
    }

    /// The image for a mask the crate produced itself (`a < dim`).
    pub(crate) fn image_at(&self, a: u32) -> &[(u32, Q)] {
        &self.images[a as usize]
    }

    /// Applies the map to a sparse vector.
    pub fn apply(&self, x: &[(u32, Q)]) -> Sparse {
        let mut acc = Acc::new(self.images.len());
        for (m, c) in x {
            acc.add_scaled(self.image_at(*m), c);
        }
        acc.take()
    }

    fn compose(&self, inner: &LinearMap) -> LinearMap {
        LinearMap { images: inner.images.iter().map(|img| self.apply(img)).collect() }
    }

    fn diagonal(dim: usize, sign: impl Fn(u32) -> i64) -> LinearMap {
        LinearMap { images: (0..dim as u32).map(|m| vec![(m, q(sign(m)))]).collect() }
    }
}

/// A dense accumulator for sparse results.
pub(crate) struct Acc {
    vals: Vec<Q>,
    touched: Vec<u32>,
    seen: Vec<bool>,
}

impl Acc {
    pub(crate) fn new(dim: usize) -> Self {
        Acc { vals: vec![Q::zero(); dim], touched: Vec::new(), seen: vec![false; dim] }
    }
    fn slot(&mut self, m: u32) -> &mut Q {
        if !self.seen[m as usize] {
            self.seen[m as usize] = true;
            self.touched.push(m);
        }
        &mut self.vals[m as usize]
    }
    pub(crate) fn add(&mut self, m: u32, c: Q) {
        *self.slot(m) += c;
    }
    pub(crate) fn add_scaled(&mut self, x: &[(u32, Q)], f: &Q) {
        for (m, c) in x {
            *self.slot(*m) += c * f;
        }
    }
    /// The accumulated sparse vector (sorted, zeros dropped); resets the accumulator.
    pub(crate) fn take(&mut self) -> Sparse {
        self.touched.sort_unstable();
        let mut out = Vec::with_capacity(self.touched.len());
        for &m in &self.touched {
            let v = std::mem::take(&mut self.vals[m as usize]);
            self.seen[m as usize] = false;
            if !v.is_zero() {
                out.push((m, v));
            }
        }
        self.touched.clear();
        out
    }
}

/// Every table of one algebra, built on demand.
///
/// ```
/// use algebra_core::{Algebra, Basis, Product};
/// let alg = Algebra::builtin("g3").unwrap();
/// let t = alg.tables();
/// assert_eq!(t.product(Basis::Blade, Product::Geometric).dim(), 8);
/// ```
#[derive(Debug)]
pub struct Tables {
    metric: Metric,
    dim: usize,
    blade_gp: OnceLock<ProductTable>,
    to_blade: OnceLock<LinearMap>,
    from_blade: OnceLock<LinearMap>,
    products: [[OnceLock<ProductTable>; 8]; 2],
    unaries: [[OnceLock<LinearMap>; 6]; 2],
    grades: [OnceLock<Vec<LinearMap>>; 2],
}

fn basis_index(b: Basis) -> usize {
    match b {
        Basis::Blade => 0,
        Basis::Product => 1,
    }
}

impl Tables {
    /// Empty (lazy) tables for a metric.
    ///
    /// ```
    /// let t = algebra_core::Tables::new(algebra_core::Metric::diagonal(2, 0, 0).unwrap());
    /// assert_eq!(t.dim(), 4);
    /// ```
    pub fn new(metric: Metric) -> Self {
        let dim = 1usize << metric.dimension();
        Tables {
            metric,
            dim,
            blade_gp: OnceLock::new(),
            to_blade: OnceLock::new(),
            from_blade: OnceLock::new(),
            products: Default::default(),
            unaries: Default::default(),
            grades: Default::default(),
        }
    }

    /// An estimate of the work of building one product table for `metric`, in units of one
    /// exact multiply-add, so that a caller can refuse a metric *before* the (lazy) tables are
    /// built: `4^n · 2^m`, where `m` counts the generators with a non-zero off-diagonal metric
    /// entry (a blade product then expands into up to `2^m` terms). A diagonal metric costs
    /// `4^n`; a dense one `8^n`.
    ///
    /// ```
    /// use algebra_core::{Algebra, Tables};
    /// assert_eq!(Tables::build_work(Algebra::builtin("g3").unwrap().metric()), 64.0);
    /// // cga-null: e0 and einf meet off the diagonal
    /// assert_eq!(Tables::build_work(Algebra::builtin("cga-null").unwrap().metric()), 4096.0);
    /// ```
    pub fn build_work(metric: &Metric) -> f64 {
        let n = metric.dimension();
        let coupled = (0..n).filter(|&i| (0..n).any(|j| j != i && !metric.gram_at(i, j).is_zero())).count();
        4f64.powi(n as i32) * 2f64.powi(coupled as i32)
    }

    /// The number of basis elements, `2^n`.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The metric the tables are built from.
    pub fn metric(&self) -> &Metric {
        &self.metric
    }

    /// Builds every table in both bases now (for timing, or before sharing across threads).
    ///
    /// ```
    /// let alg = algebra_core::Algebra::builtin("cga-null").unwrap();
    /// alg.tables().build_all();
    /// ```
    pub fn build_all(&self) {
        for b in Basis::ALL {
            for p in Product::ALL {
                self.product(b, p);
            }
            for u in Unary::ALL {
                self.unary(b, u);
            }
            self.grade_projection(b, 0);
        }
    }

    /// The table of `product` in `basis`.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Product, rational::q};
    /// let alg = Algebra::builtin("cga-null").unwrap();
    /// let op = alg.tables().product(Basis::Blade, Product::Outer);
    /// assert_eq!(op.get(0b10000, 0b00001).unwrap(), &[(0b10001, q(-1))]); // einf ^ e0 = -e0inf
    /// ```
    pub fn product(&self, basis: Basis, product: Product) -> &ProductTable {
        self.products[basis_index(basis)][product.index()].get_or_init(|| match (basis, product) {
            (Basis::Blade, Product::Geometric) => self.blade_gp().clone(),
            (Basis::Blade, _) => self.build_blade_product(product),
            (Basis::Product, Product::Geometric) => build_product_gp(&self.metric),
            (Basis::Product, Product::Commutator | Product::Anticommutator) => {
                symmetrize(self.product(Basis::Product, Product::Geometric), product)
            }
            (Basis::Product, _) => self.convert_product(self.product(Basis::Blade, product)),
        })
    }

    /// The matrix of a unary operation in `basis`.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Unary, rational::q};
    /// let alg = Algebra::builtin("cga-null").unwrap();
    /// // the true reverse of product-basis e0inf is einf e0 = -2 - e0inf
    /// let rev = alg.tables().unary(Basis::Product, Unary::Reverse);
    /// assert_eq!(rev.image(0b10001).unwrap(), &[(0, q(-2)), (0b10001, q(-1))]);
    /// ```
    pub fn unary(&self, basis: Basis, op: Unary) -> &LinearMap {
        self.unaries[basis_index(basis)][op.index()].get_or_init(|| {
            let n = self.metric.dimension();
            let full = (1u32 << n) - 1;
            match (basis, op) {
                (_, Unary::BasisReverse) => LinearMap::diagonal(self.dim, |m| reverse_sign(grade(m))),
                (Basis::Blade, Unary::Reverse) => LinearMap::diagonal(self.dim, |m| reverse_sign(grade(m))),
                (Basis::Blade, Unary::GradeInvolution) => LinearMap::diagonal(self.dim, |m| parity_sign(grade(m))),
                (Basis::Blade, Unary::CliffordConjugate) => {
                    LinearMap::diagonal(self.dim, |m| reverse_sign(grade(m)) * parity_sign(grade(m)))
                }
                (Basis::Blade, Unary::Dual) => LinearMap {
                    images: (0..=full)
                        .map(|m| vec![(full ^ m, q(wedge_sign(m, full ^ m).expect("disjoint")))])
                        .collect(),
                },
                (Basis::Blade, Unary::Undual) => LinearMap {
                    images: (0..=full)
                        .map(|m| vec![(full ^ m, q(wedge_sign(full ^ m, m).expect("disjoint")))])
                        .collect(),
                },
                (Basis::Product, _) => self.convert_map(self.unary(Basis::Blade, op)),
            }
        })
    }

    /// The projection onto true grade `k` (grade of blades) in `basis`; the zero map for
    /// `k > n`.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, rational::q};
    /// let alg = Algebra::builtin("cga-null").unwrap();
    /// // <e0inf>_0 = -1 for the product-basis element e0 einf
    /// let g0 = alg.tables().grade_projection(Basis::Product, 0);
    /// assert_eq!(g0.image(0b10001).unwrap(), &[(0, q(-1))]);
    /// ```
    pub fn grade_projection(&self, basis: Basis, k: usize) -> &LinearMap {
        let n = self.metric.dimension();
        let maps = self.grades[basis_index(basis)].get_or_init(|| {
            // grades 0..=n, then the zero map for every k > n
            (0..=n + 1)
                .map(|k| {
                    let blade = LinearMap {
                        images: (0..self.dim as u32)
                            .map(|m| if grade(m) == k { vec![(m, q(1))] } else { vec![] })
                            .collect(),
                    };
                    match basis {
                        Basis::Blade => blade,
                        Basis::Product => self.convert_map(&blade),
                    }
                })
                .collect()
        });
        &maps[k.min(n + 1)]
    }

    /// Product-basis coordinates to blade-basis coordinates: `image(S)` is `e_{s1} e_{s2} ...`
    /// written in blades.
    pub fn to_blade(&self) -> &LinearMap {
        self.to_blade.get_or_init(|| {
            let n = self.metric.dimension();
            let mut images: Vec<Sparse> = vec![Vec::new(); self.dim];
            images[0] = vec![(0, q(1))];
            let mut acc = Acc::new(self.dim);
            for s in 1..self.dim as u32 {
                let i = s.trailing_zeros() as usize;
                for (m, c) in &images[(s & (s - 1)) as usize] {
                    vec_times_blade(&self.metric, n, i, *m, c, &mut acc);
                }
                images[s as usize] = acc.take();
            }
            LinearMap { images }
        })
    }

    /// Blade-basis coordinates to product-basis coordinates (inverse of [`Tables::to_blade`]).
    pub fn from_blade(&self) -> &LinearMap {
        self.from_blade.get_or_init(|| {
            let to = self.to_blade();
            let mut images: Vec<Sparse> = vec![Vec::new(); self.dim];
            let mut acc = Acc::new(self.dim);
            // P_S = E_S + Σ c_U E_U with |U| < |S|, so E_S = P_S - Σ c_U E_U.
            for s in crate::basis::basis_order(self.metric.dimension()) {
                acc.add(s, q(1));
                for (u, c) in to.image_at(s) {
                    if *u != s {
                        acc.add_scaled(&images[*u as usize], &-c);
                    }
                }
                images[s as usize] = acc.take();
            }
            LinearMap { images }
        })
    }

    /// Changes the basis of a sparse vector.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, rational::q};
    /// let alg = Algebra::builtin("cga-null").unwrap();
    /// let blade = alg.tables().convert(&[(0b10001, q(1))], Basis::Blade, Basis::Product);
    /// assert_eq!(blade, vec![(0, q(1)), (0b10001, q(1))]); // e0^einf = 1 + e0 einf
    /// ```
    pub fn convert(&self, x: &[(u32, Q)], from: Basis, to: Basis) -> Sparse {
        match (from, to) {
            (Basis::Blade, Basis::Product) => self.from_blade().apply(x),
            (Basis::Product, Basis::Blade) => self.to_blade().apply(x),
            _ => x.to_vec(),
        }
    }

    fn blade_gp(&self) -> &ProductTable {
        self.blade_gp.get_or_init(|| build_blade_gp(&self.metric))
    }

    fn build_blade_product(&self, product: Product) -> ProductTable {
        let gp = self.blade_gp();
        let dim = self.dim;
        let select = |a: u32, b: u32, k: Option<usize>| -> Sparse {
            match k {
                Some(k) => gp.at(a, b).iter().filter(|(m, _)| grade(*m) == k).cloned().collect(),
                None => Vec::new(),
            }
        };
        let dual = self.unary(Basis::Blade, Unary::Dual);
        let undual = self.unary(Basis::Blade, Unary::Undual);
        let mut entries = Vec::with_capacity(dim * dim);
        for a in 0..dim as u32 {
            for b in 0..dim as u32 {
                let (ka, kb) = (grade(a), grade(b));
                entries.push(match product {
                    Product::Geometric => gp.at(a, b).to_vec(),
                    Product::Outer => wedge_sign(a, b).map(|s| vec![(a | b, q(s))]).unwrap_or_default(),
                    Product::LeftContraction => select(a, b, kb.checked_sub(ka)),
                    Product::RightContraction => select(a, b, ka.checked_sub(kb)),
                    Product::Scalar => select(a, b, Some(0)),
                    Product::Regressive => {
                        let (da, db) = (&dual.image_at(a)[0], &dual.image_at(b)[0]);
                        match wedge_sign(da.0, db.0) {
                            Some(s) => undual.apply(&[(da.0 | db.0, &da.1 * &db.1 * q(s))]),
                            None => Vec::new(),
                        }
                    }
                    Product::Commutator | Product::Anticommutator => Vec::new(),
                });
            }
        }
        let table = ProductTable { dim, entries };
        match product {
            Product::Commutator | Product::Anticommutator => symmetrize(gp, product),
            _ => table,
        }
    }

    /// A blade-basis product table carried to the product basis:
    /// `P_a ∘ P_b = from( Σ_j c_bj (Σ_i c_ai E_i ∘ E_j) )`, summing over the left factor once
    /// per row (separably) rather than once per entry.
    fn convert_product(&self, blade: &ProductTable) -> ProductTable {
        let (to, from) = (self.to_blade(), self.from_blade());
        let mut acc = Acc::new(self.dim);
        let mut entries = Vec::with_capacity(self.dim * self.dim);
        for a in 0..self.dim as u32 {
            // row[j] = P_a ∘ E_j in blade coordinates
            let row: Vec<Sparse> = (0..self.dim as u32)
                .map(|j| {
                    for (i, ci) in to.image_at(a) {
                        acc.add_scaled(blade.at(*i, j), ci);
                    }
                    acc.take()
                })
                .collect();
            for b in 0..self.dim as u32 {
                for (j, cj) in to.image_at(b) {
                    acc.add_scaled(&row[*j as usize], cj);
                }
                entries.push(from.apply(&acc.take()));
            }
        }
        ProductTable { dim: self.dim, entries }
    }

    /// A blade-basis linear map carried to the product basis.
    fn convert_map(&self, blade: &LinearMap) -> LinearMap {
        self.from_blade().compose(&blade.compose(self.to_blade()))
    }
}

fn reverse_sign(k: usize) -> i64 {
    if (k / 2).is_multiple_of(2) { 1 } else { -1 }
}

/// `(xy ∓ yx)/2` from a geometric-product table.
fn symmetrize(gp: &ProductTable, product: Product) -> ProductTable {
    let sign = if product == Product::Commutator { -1 } else { 1 };
    let half = ratio(1, 2);
    let mut acc = Acc::new(gp.dim);
    let mut entries = Vec::with_capacity(gp.dim * gp.dim);
    for a in 0..gp.dim as u32 {
        for b in 0..gp.dim as u32 {
            acc.add_scaled(gp.at(a, b), &half);
            acc.add_scaled(gp.at(b, a), &(&half * q(sign)));
            entries.push(acc.take());
        }
    }
    ProductTable { dim: gp.dim, entries }
}

/// Adds `c · e_i E_T` (blade basis) to `acc`.
fn vec_times_blade(metric: &Metric, n: usize, i: usize, t: u32, c: &Q, acc: &mut Acc) {
    // e_i ⌋ E_T: Laplace expansion along the first factor.
    let mut pos = 0;
    for j in 0..n {
        if t >> j & 1 == 1 {
            let b = metric.gram_at(i, j);
            if !b.is_zero() {
                acc.add(t ^ (1 << j), c * b * q(parity_sign(pos)));
            }
            pos += 1;
        }
    }
    // e_i ^ E_T.
    if let Some(s) = wedge_sign(1 << i, t) {
        acc.add(t | 1 << i, c * q(s));
    }
}

/// The row recursion shared by both geometric-product tables: row `∅` is the identity, and
/// the row of `S = {i} ∪ S'` (`i = min S`) is computed entry by entry from rows of smaller
/// subsets by `entry(rows, i, S', T, acc)`.
fn build_rows(n: usize, mut entry: impl FnMut(&[Vec<Sparse>], usize, u32, usize, &mut Acc) -> Sparse) -> ProductTable {
    let dim = 1usize << n;
    let mut rows: Vec<Vec<Sparse>> = Vec::with_capacity(dim);
    rows.push((0..dim as u32).map(|t| vec![(t, q(1))]).collect());
    let mut acc = Acc::new(dim);
    for s in 1..dim as u32 {
        let i = s.trailing_zeros() as usize;
        let s1 = s & (s - 1);
        let row = (0..dim).map(|t| entry(&rows, i, s1, t, &mut acc)).collect();
        rows.push(row);
    }
    ProductTable { dim, entries: rows.into_iter().flatten().collect() }
}

/// The geometric product in the blade basis (Chevalley recursion, see the module docs):
/// `E_S E_T = e_i (E_{S'} E_T) - (e_i ⌋ E_{S'}) E_T`.
fn build_blade_gp(metric: &Metric) -> ProductTable {
    let n = metric.dimension();
    build_rows(n, |rows, i, s1, t, acc| {
        for (m, c) in &rows[s1 as usize][t] {
            vec_times_blade(metric, n, i, *m, c, acc);
        }
        // - e_i ⌋ E_{S'} = - Σ_pos (-1)^pos B(e_i, e_j) E_{S' \ j}
        for (pos, j) in (0..n).filter(|&j| s1 >> j & 1 == 1).enumerate() {
            let b = metric.gram_at(i, j);
            if !b.is_zero() {
                acc.add_scaled(&rows[(s1 ^ (1 << j)) as usize][t], &-(b * q(parity_sign(pos))));
            }
        }
        acc.take()
    })
}

/// `e_i P_T` in the product basis (see the module docs).
fn vec_times_product(metric: &Metric, i: usize, t: u32) -> Sparse {
    if t == 0 || (i as u32) < t.trailing_zeros() {
        return vec![(t | 1 << i, q(1))];
    }
    let t1 = t.trailing_zeros() as usize;
    let rest = t ^ (1 << t1);
    if i == t1 {
        let b = metric.gram_at(i, i);
        return if b.is_zero() { vec![] } else { vec![(rest, b.clone())] };
    }
    // e_i e_t1 P_rest = 2 B(i, t1) P_rest - e_t1 (e_i P_rest); every index of e_i P_rest
    // exceeds t1, so e_t1 just prepends.
    let mut out: Sparse = vec![];
    let b = metric.gram_at(i, t1);
    if !b.is_zero() {
        out.push((rest, b * q(2)));
    }
    for (m, c) in vec_times_product(metric, i, rest) {
        out.push((m | 1 << t1, -c));
    }
    out.sort_by_key(|(m, _)| *m);
    out
}

/// The geometric product in the product basis: `P_S P_T = e_i (P_{S'} P_T)`.
fn build_product_gp(metric: &Metric) -> ProductTable {
    build_rows(metric.dimension(), |rows, i, s1, t, acc| {
        for (m, c) in &rows[s1 as usize][t] {
            acc.add_scaled(&vec_times_product(metric, i, *m), c);
        }
        acc.take()
    })
}
