//! An independent re-derivation of the product tables, checked entry by entry against the
//! library's.
//!
//! Nothing here calls the library's table builder to produce an expected value. The
//! reference construction:
//! 1. diagonalises the Gram matrix `G` by an exact rational congruence: an invertible `P`
//!    with `P G P^T = D` diagonal (symmetric Gaussian elimination; a zero pivot is replaced
//!    by a row with a non-zero diagonal, or else paired, `f_k += f_j`, which makes the pivot
//!    `2 G_kj`), so `f_i = Σ_j P_ij e_j` are mutually orthogonal with `f_i^2 = d_i`;
//! 2. multiplies in the orthogonal basis by the bitmask rule
//!    `F_A F_B = sign(A, B) Π_{i in A∩B} d_i F_{A Δ B}`;
//! 3. maps blades by the outermorphism: `E_S = Σ_T det(P^{-1}[S, T]) F_T` and back
//!    `F_T = Σ_S det(P[T, S]) E_S` (minors), and product-basis elements by multiplying the
//!    generators `e_j = Σ_i (P^{-1})_ji f_i` left to right.

use crate::common;

use algebra_core::rational::{Q, q, ratio};
use algebra_core::{Algebra, Basis, Metric, Multivector, Product};
use common::*;
use std::sync::Arc;
use std::time::Instant;

type Mat = Vec<Vec<Q>>;
/// `(mask, coefficient)`, sorted by mask, no zeros (the library's table entry format).
type Sparse = Vec<(u32, Q)>;

// ---------------------------------------------------------------------------------------
// Exact linear algebra
// ---------------------------------------------------------------------------------------

fn identity(n: usize) -> Mat {
    (0..n).map(|i| (0..n).map(|j| q(i64::from(i == j))).collect()).collect()
}

fn mat_mul(a: &Mat, b: &Mat) -> Mat {
    let (n, m, k) = (a.len(), b[0].len(), b.len());
    (0..n).map(|i| (0..m).map(|j| (0..k).map(|l| &a[i][l] * &b[l][j]).sum()).collect()).collect()
}

fn transpose(a: &Mat) -> Mat {
    (0..a[0].len()).map(|j| a.iter().map(|row| row[j].clone()).collect()).collect()
}

/// Row echelon form in place; returns (rank, determinant sign-and-pivot product).
fn eliminate(a: &mut Mat) -> (usize, Q) {
    let (rows, cols) = (a.len(), a.first().map_or(0, Vec::len));
    let mut det = q(1);
    let mut rank = 0;
    for col in 0..cols {
        let Some(p) = (rank..rows).find(|&r| a[r][col] != q(0)) else {
            det = q(0);
            continue;
        };
        if p != rank {
            a.swap(p, rank);
            det = -det;
        }
        det *= &a[rank][col];
        let pivot = a[rank].clone();
        for row in &mut a[rank + 1..] {
            if row[col] != q(0) {
                let f = &row[col] / &pivot[col];
                for (x, p) in row.iter_mut().zip(&pivot).skip(col) {
                    *x -= &f * p;
                }
            }
        }
        rank += 1;
    }
    (rank, det)
}

fn det(a: &Mat) -> Q {
    if a.is_empty() {
        return q(1);
    }
    eliminate(&mut a.clone()).1
}

fn rank(a: &Mat) -> usize {
    eliminate(&mut a.clone()).0
}

/// Gauss-Jordan inverse (panics on a singular matrix).
fn inverse(a: &Mat) -> Mat {
    let n = a.len();
    let mut m: Mat = a.iter().zip(identity(n)).map(|(r, i)| r.iter().cloned().chain(i).collect()).collect();
    for col in 0..n {
        let p = (col..n).find(|&r| m[r][col] != q(0)).expect("invertible");
        m.swap(p, col);
        let inv = q(1) / &m[col][col];
        for x in m[col].iter_mut() {
            *x *= &inv;
        }
        let pivot = m[col].clone();
        for (r, row) in m.iter_mut().enumerate() {
            if r != col && row[col] != q(0) {
                let f = row[col].clone();
                for (x, p) in row.iter_mut().zip(&pivot) {
                    *x -= &f * p;
                }
            }
        }
    }
    m.into_iter().map(|r| r[n..].to_vec()).collect()
}

/// `det(m[rows, cols])`.
fn minor(m: &Mat, rows: &[usize], cols: &[usize]) -> Q {
    det(&rows.iter().map(|&r| cols.iter().map(|&c| m[r][c].clone()).collect()).collect())
}

fn bits(mask: u32) -> Vec<usize> {
    (0..32).filter(|i| mask >> i & 1 == 1).collect()
}

/// `P` and `d` with `P G P^T = diag(d)`, `P` invertible.
fn diagonalise(g: &Mat) -> (Mat, Vec<Q>) {
    let n = g.len();
    let mut a = g.clone();
    let mut p = identity(n);
    // f_t += c f_s: row and column t of the Gram matrix change accordingly.
    let add_row = |m: &mut Mat, t: usize, s: usize, c: &Q| {
        let src = m[s].clone();
        for (x, y) in m[t].iter_mut().zip(&src) {
            *x += c * y;
        }
    };
    let add = |a: &mut Mat, p: &mut Mat, t: usize, s: usize, c: &Q| {
        add_row(a, t, s, c);
        for row in a.iter_mut() {
            let d = c * &row[s];
            row[t] += d;
        }
        add_row(p, t, s, c);
    };
    for k in 0..n {
        if a[k][k] == q(0) {
            if let Some(j) = (k + 1..n).find(|&j| a[j][j] != q(0)) {
                a.swap(k, j);
                for row in a.iter_mut() {
                    row.swap(k, j);
                }
                p.swap(k, j);
            } else if let Some(j) = (k + 1..n).find(|&j| a[k][j] != q(0)) {
                // all later squares vanish, so B(f_k + f_j, f_k + f_j) = 2 B(f_k, f_j) != 0
                add(&mut a, &mut p, k, j, &q(1));
            } else {
                continue; // f_k is orthogonal to everything left
            }
        }
        for j in k + 1..n {
            if a[j][k] != q(0) {
                let c = -(&a[j][k] / &a[k][k]);
                add(&mut a, &mut p, j, k, &c);
            }
        }
    }
    let d = (0..n).map(|i| a[i][i].clone()).collect();
    (p, d)
}

// ---------------------------------------------------------------------------------------
// The reference algebra
// ---------------------------------------------------------------------------------------

struct Reference {
    n: usize,
    dim: usize,
    /// `Π_{i in m} d_i` for every mask `m`.
    square_products: Vec<Q>,
    /// `e_j` in F coordinates (row `j` of `P^{-1}`).
    generators: Vec<Sparse>,
    /// `E_S` in F coordinates.
    e_in_f: Vec<Sparse>,
    /// `F_T` in E coordinates.
    f_in_e: Vec<Sparse>,
    /// `P_S = e_{s1} e_{s2} ...` in F coordinates.
    p_in_f: Vec<Sparse>,
}

fn sparse(dense: Vec<Q>) -> Sparse {
    dense.into_iter().enumerate().filter(|(_, c)| *c != q(0)).map(|(m, c)| (m as u32, c)).collect()
}

/// The outermorphism of the linear map whose row `r` is the image of generator `r`:
/// `∧_{s in S} row_s = Σ_{|T| = |S|} det(m[S, T]) F_T`.
fn outermorphism(m: &Mat, dim: usize) -> Vec<Sparse> {
    (0..dim as u32)
        .map(|s| {
            let rows = bits(s);
            (0..dim as u32)
                .filter(|t| t.count_ones() == s.count_ones())
                .map(|t| (t, minor(m, &rows, &bits(t))))
                .filter(|(_, c)| *c != q(0))
                .collect()
        })
        .collect()
}

impl Reference {
    fn new(metric: &Metric) -> Self {
        let n = metric.dimension();
        let dim = 1usize << n;
        let g: Mat = metric.gram_matrix().to_vec();
        let (p, d) = diagonalise(&g);
        let diag: Mat = (0..n).map(|i| (0..n).map(|j| if i == j { d[i].clone() } else { q(0) }).collect()).collect();
        assert_eq!(mat_mul(&mat_mul(&p, &g), &transpose(&p)), diag, "P G P^T must be diagonal");
        assert_ne!(det(&p), q(0), "P must be invertible");
        let pinv = inverse(&p);
        assert_eq!(mat_mul(&p, &pinv), identity(n));
        let square_products = (0..dim as u32).map(|m| bits(m).into_iter().fold(q(1), |acc, i| acc * &d[i])).collect();
        let generators =
            (0..n).map(|j| sparse(pinv[j].clone()).into_iter().map(|(i, c)| (1 << i, c)).collect()).collect();
        let mut r = Reference {
            n,
            dim,
            square_products,
            generators,
            e_in_f: outermorphism(&pinv, dim),
            f_in_e: outermorphism(&p, dim),
            p_in_f: vec![],
        };
        // P_S = P_{S \ max} e_max, i.e. the generators multiplied left to right.
        let mut p_in_f: Vec<Sparse> = vec![vec![(0, q(1))]];
        for s in 1..dim as u32 {
            let top = 31 - s.leading_zeros();
            p_in_f.push(sparse(r.f_mul(&p_in_f[(s ^ (1 << top)) as usize], &r.generators[top as usize])));
        }
        r.p_in_f = p_in_f;
        r
    }

    /// Product of two F-coordinate vectors (dense result).
    fn f_mul(&self, x: &[(u32, Q)], y: &[(u32, Q)]) -> Vec<Q> {
        let mut out = vec![q(0); self.dim];
        for (a, ca) in x {
            for (b, cb) in y {
                let sq = &self.square_products[(a & b) as usize];
                if *sq != q(0) {
                    out[(a ^ b) as usize] += ca * cb * sq * q(reorder_sign(*a, *b));
                }
            }
        }
        out
    }

    /// A linear combination `Σ c_k images[k]` (dense).
    fn combine(&self, x: &[(u32, Q)], images: &[Sparse]) -> Vec<Q> {
        let mut out = vec![q(0); self.dim];
        for (k, c) in x {
            for (m, f) in &images[*k as usize] {
                out[*m as usize] += c * f;
            }
        }
        out
    }

    fn e_to_f(&self, x: &[(u32, Q)]) -> Sparse {
        sparse(self.combine(x, &self.e_in_f))
    }

    fn f_to_e(&self, x: &[(u32, Q)]) -> Sparse {
        sparse(self.combine(x, &self.f_in_e))
    }

    /// `E_A E_B` in the blade basis.
    fn blade_gp(&self, a: u32, b: u32) -> Sparse {
        let f = self.f_mul(&self.e_in_f[a as usize], &self.e_in_f[b as usize]);
        self.f_to_e(&sparse(f))
    }

    /// `P_A P_B = e_{a1} ... e_{ak} e_{b1} ... e_{bl}` in F coordinates, multiplying the
    /// generators of `B` onto `P_A` one by one.
    fn product_gp_in_f(&self, a: u32, b: u32) -> Sparse {
        let mut x = self.p_in_f[a as usize].clone();
        for j in bits(b) {
            x = sparse(self.f_mul(&x, &self.generators[j]));
        }
        x
    }
}

// ---------------------------------------------------------------------------------------
// Checks against the library
// ---------------------------------------------------------------------------------------

/// A deterministic pseudo-random generator for the test metrics.
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        self.0 >> 33
    }
    /// An integer in `-r..=r`.
    fn small(&mut self, r: i64) -> i64 {
        (self.next() % (2 * r as u64 + 1)) as i64 - r
    }
    /// A small rational, sometimes a half or a third.
    fn rational(&mut self) -> Q {
        let den = [1, 1, 1, 2, 3][(self.next() % 5) as usize];
        ratio(self.small(3), den)
    }
}

fn letters(n: usize) -> Vec<String> {
    (0..n).map(|i| ((b'a' + i as u8) as char).to_string()).collect()
}

/// A symmetric matrix with small random rational entries and the given diagonal.
fn random_symmetric(rng: &mut Lcg, diagonal: &[Q]) -> Mat {
    random_symmetric_with(diagonal, || rng.rational())
}

/// A symmetric matrix with off-diagonal entries from `entry` and the given diagonal.
fn random_symmetric_with(diagonal: &[Q], mut entry: impl FnMut() -> Q) -> Mat {
    let n = diagonal.len();
    // the upper triangle in row order, then mirrored
    let upper: Vec<Vec<Q>> =
        (0..n).map(|i| (i..n).map(|j| if i == j { diagonal[i].clone() } else { entry() }).collect()).collect();
    (0..n)
        .map(|i| (0..n).map(|j| if i <= j { upper[i][j - i].clone() } else { upper[j][i - j].clone() }).collect())
        .collect()
}

fn is_diagonal(g: &Mat) -> bool {
    (0..g.len()).all(|i| (0..g.len()).all(|j| i == j || g[i][j] == q(0)))
}

fn custom(name: &str, g: Mat) -> Arc<Algebra> {
    Algebra::new(name, Metric::new(letters(g.len()), g).expect("valid metric"))
}

/// The library's blade-basis gp table, every entry.
fn check_blade_gp(alg: &Algebra, r: &Reference) {
    let table = alg.tables().product(Basis::Blade, Product::Geometric);
    for a in 0..r.dim as u32 {
        for b in 0..r.dim as u32 {
            assert_eq!(
                table.get(a, b).unwrap(),
                r.blade_gp(a, b).as_slice(),
                "{}: blade basis {} {}",
                alg.name(),
                alg.name_of(a).unwrap(),
                alg.name_of(b).unwrap()
            );
        }
    }
}

/// The library's change of basis: `P_S` in blade coordinates, mapped into F, equals the
/// generators multiplied left to right; and `from_blade` inverts it.
fn check_change_of_basis(alg: &Algebra, r: &Reference) {
    let t = alg.tables();
    for s in 0..r.dim as u32 {
        let blade = t.to_blade().image(s).unwrap();
        assert_eq!(r.e_to_f(blade), r.p_in_f[s as usize], "{}: P_{} in blades", alg.name(), alg.name_of(s).unwrap());
        let back = t.from_blade().apply(blade);
        assert_eq!(back, vec![(s, q(1))], "{}: from_blade(to_blade(P_{}))", alg.name(), alg.name_of(s).unwrap());
    }
}

/// The library's product-basis gp table (a) against the reference blade products carried
/// through the library's change of basis and (b) against multiplying generators directly.
/// `pairs` restricts the entries (all when `None`).
fn check_product_gp(alg: &Algebra, r: &Reference, pairs: Option<&[(u32, u32)]>) {
    let t = alg.tables();
    let table = t.product(Basis::Product, Product::Geometric);
    let all: Vec<(u32, u32)>;
    let pairs = match pairs {
        Some(p) => p,
        None => {
            all = (0..r.dim as u32).flat_map(|a| (0..r.dim as u32).map(move |b| (a, b))).collect();
            &all
        }
    };
    for &(a, b) in pairs {
        let lib = table.get(a, b).unwrap();
        let what = format!("{}: product basis {} {}", alg.name(), alg.name_of(a).unwrap(), alg.name_of(b).unwrap());
        // (a) blade coordinates from the library's to_blade, the product by the reference
        // (through F), back to product coordinates with the library's from_blade.
        let x = r.e_to_f(t.to_blade().image(a).unwrap());
        let y = r.e_to_f(t.to_blade().image(b).unwrap());
        let blade = r.f_to_e(&sparse(r.f_mul(&x, &y)));
        assert_eq!(t.convert(&blade, Basis::Blade, Basis::Product), lib, "{what} (a)");
        // (b) the library's entry evaluated in F equals e_{a1}..e_{ak} e_{b1}..e_{bl}.
        assert_eq!(sparse(r.combine(lib, &r.p_in_f)), r.product_gp_in_f(a, b), "{what} (b)");
    }
}

fn check_all(alg: &Algebra) {
    let r = Reference::new(alg.metric());
    assert_eq!(r.n, alg.generators());
    check_blade_gp(alg, &r);
    check_change_of_basis(alg, &r);
    check_product_gp(alg, &r, None);
}

#[test]
fn reference_congruence_diagonalises() {
    // the pairing case: e0.einf = -1 with e0^2 = einf^2 = 0
    let g = builtin("cga-null").metric().gram_matrix().to_vec();
    let (p, d) = diagonalise(&g);
    assert_eq!(d.iter().filter(|x| **x > q(0)).count(), 4, "cga-null has signature (4, 1)");
    assert_eq!(d.iter().filter(|x| **x < q(0)).count(), 1);
    assert_ne!(det(&p), q(0));
    // a zero first row and a hyperbolic pair behind it
    let g = vec![vec![q(0), q(0), q(0)], vec![q(0), q(0), q(1)], vec![q(0), q(1), q(0)]];
    let (_, d) = diagonalise(&g);
    let mut d: Vec<Q> = d;
    d.sort();
    assert_eq!(d, vec![ratio(-1, 2), q(0), q(2)]);
    // the reference bitmask rule on its own: in g3, e12 e23 = e13 and e3 e1 = -e13
    let r = Reference::new(builtin("g3").metric());
    assert_eq!(r.blade_gp(0b011, 0b110), vec![(0b101, q(1))]);
    assert_eq!(r.blade_gp(0b100, 0b001), vec![(0b101, q(-1))]);
}

#[test]
fn builtin_tables_match_the_reference() {
    for alg in builtins() {
        check_all(alg);
    }
}

#[test]
fn non_diagonal_non_degenerate_4_generators() {
    let mut rng = Lcg(0x5eed_0004);
    // e_a is null, so the diagonalisation must swap or pair
    let g = random_symmetric(&mut rng, &[q(0), q(1), ratio(-1, 2), q(2)]);
    assert!(!is_diagonal(&g));
    assert_ne!(det(&g), q(0), "non-degenerate: {g:?}");
    check_all(&custom("rand4", g));
}

#[test]
fn non_diagonal_degenerate_rank_2_4_generators() {
    let mut rng = Lcg(0x5eed_0042);
    // G = A^T diag(1, -1) A for a random 2x4 integer A has rank <= 2
    let a: Mat = (0..2).map(|_| (0..4).map(|_| q(rng.small(2))).collect()).collect();
    let d = vec![vec![q(1), q(0)], vec![q(0), q(-1)]];
    let g = mat_mul(&mat_mul(&transpose(&a), &d), &a);
    assert!(!is_diagonal(&g), "{g:?}");
    assert_eq!(rank(&g), 2, "{g:?}");
    check_all(&custom("rank2", g));
}

#[test]
fn non_diagonal_null_generators_3() {
    // zero first row (degenerate) with a hyperbolic pair: only pairing can diagonalise
    let g = vec![vec![q(0), q(0), q(0)], vec![q(0), q(0), ratio(1, 2)], vec![q(0), ratio(1, 2), q(0)]];
    check_all(&custom("null3", g));
}

#[test]
fn non_diagonal_6_generators() {
    let mut rng = Lcg(0x5eed_0006);
    // integer couplings keep the coefficients (and the test's run time) small
    let g = random_symmetric_with(&[q(0), q(0), q(1), q(-1), q(0), q(2)], || q(rng.small(1)));
    assert!(!is_diagonal(&g));
    check_all(&custom("rand6", g));
}

/// Facts of Cross, Cripps and Mullineux (2022) in G_{0123inf} (the `cga-null` algebra) in
/// the product basis; expected values worked out by hand from `e0.einf = -1`,
/// `e0^2 = einf^2 = 0`.
#[test]
fn paper_facts_in_cga_null_product_basis() {
    let alg = builtin("cga-null");
    let p = Basis::Product;
    let e = |name: &str| named(&alg, p, &[(name, q(1))]);
    let (e0, einf) = (e("e0"), e("einf"));
    let s = |c: i64| scalar(&alg, p, q(c));
    assert_mv_eq(&e0.sp(&einf), &s(-1), "e0 . einf = -1");
    assert_mv_eq(&e0.anticommutator(&einf), &s(-1), "(e0 einf + einf e0)/2 = -1");
    assert_mv_eq(&(&e0 * &e0), &s(0), "e0^2 = 0");
    assert_mv_eq(&(&einf * &einf), &s(0), "einf^2 = 0");
    assert_mv_eq(&(&e0 * &einf), &e("e0inf"), "e0 einf = e0inf (product basis)");
    assert_mv_eq(&(&einf * &e0), &named(&alg, p, &[("1", q(-2)), ("e0inf", q(-1))]), "einf e0 = -2 - e0inf");
    let omega = e("e123inf");
    assert_mv_eq(
        &(&omega * &e0),
        &named(&alg, p, &[("e123", q(-2)), ("e0123inf", q(1))]),
        "omega e0 = -2 e123 + e0123inf",
    );
    assert_mv_eq(&(&e0 * &omega), &e("e0123inf"), "e0 omega = e0123inf");
    let sigma = (&(&e0 * &omega) + &(&omega * &e0)).scale(&ratio(1, 2));
    assert_mv_eq(&sigma, &named(&alg, p, &[("e123", q(-1)), ("e0123inf", q(1))]), "sigma = -e123 + e0123inf");
    // sigma is the blade pseudoscalar e0^e1^e2^e3^einf: e0 e123 einf = -e123 e0 einf
    // = -e123 (-1 + e0^einf) = e123 + e0^e1^e2^e3^einf, so sigma = -e123 + P_0123inf = E_0123inf.
    assert_mv_eq(&sigma.in_basis(Basis::Blade), &named(&alg, Basis::Blade, &[("e0123inf", q(1))]), "sigma in blades");
    // Lemma 2.2(iii): sigma commutes with every basis element (32 checks per basis)
    let mut checks = 0;
    for basis in Basis::ALL {
        for m in 0..alg.dim() as u32 {
            let x = mv(&alg, basis, &[(m, q(1))]);
            assert_mv_eq(
                &(&sigma.in_basis(basis) * &x),
                &(&x * &sigma.in_basis(basis)),
                format!("sigma {basis} {}", alg.name_of(m).unwrap()),
            );
            // sigma ^ x = <x>_0 sigma: zero for every element without a scalar part. (In the
            // product basis e0inf = -1 + e0^einf has one, so sigma ^ e0inf = -sigma.)
            let expected = sigma.in_basis(basis).scale(&x.scalar_part());
            assert_mv_eq(
                &(&sigma.in_basis(basis) ^ &x),
                &expected,
                format!("sigma ^ {basis} {}", alg.name_of(m).unwrap()),
            );
            if basis == Basis::Blade && m != 0 {
                assert!((&sigma ^ &x).is_zero(), "sigma ^ E_{} = 0", alg.name_of(m).unwrap());
            }
            checks += 1;
        }
    }
    assert_eq!(checks, 64);
    assert_mv_eq(&(&sigma ^ &e("e0inf")), &-&sigma, "sigma ^ e0inf = -sigma (product basis)");
    // the paper's subset-size reverse is not an anti-automorphism in this basis:
    // basis_reverse(e0 einf) = -e0inf, but einf e0 = -2 - e0inf.
    assert_mv_eq(&e("e0inf").basis_reverse(), &named(&alg, p, &[("e0inf", q(-1))]), "basis_reverse(e0inf)");
    assert_mv_eq(&e("e0inf").reverse(), &(&einf * &e0), "reverse(e0 einf) = einf e0");
}

/// An 8-generator non-diagonal metric with integer entries: two hyperbolic pairs
/// (`a.h = -1`, `b.g = 1`, null generators), a null `c`, and a few couplings.
fn sparse_8_generator_metric() -> Mat {
    let mut g = vec![vec![q(0); 8]; 8];
    for (i, j, v) in [(0, 7, -1), (1, 6, 1), (3, 3, 1), (4, 4, -1), (5, 5, 2), (3, 4, 1), (2, 5, 1), (6, 6, 1)] {
        g[i][j] = q(v);
        g[j][i] = q(v);
    }
    g
}

/// A dense 8-generator non-diagonal metric with small rational entries (the worst case for
/// coefficient growth).
fn dense_8_generator_metric(rng: &mut Lcg) -> Mat {
    random_symmetric(rng, &[q(1), q(0), q(-1), q(2), q(0), q(1), ratio(1, 2), q(0)])
}

/// Spot checks of an 8-generator algebra against the reference: `pairs` random entries of
/// both gp tables, the whole outer-product table, one product through the multivector.
fn spot_check_8(alg: &Arc<Algebra>, rng: &mut Lcg) {
    let r = Reference::new(alg.metric());
    let dim = alg.dim() as u32;
    let pairs: Vec<(u32, u32)> = (0..48).map(|_| (rng.next() as u32 % dim, rng.next() as u32 % dim)).collect();
    let table = alg.tables().product(Basis::Blade, Product::Geometric);
    for &(a, b) in &pairs {
        assert_eq!(
            table.get(a, b).unwrap(),
            r.blade_gp(a, b).as_slice(),
            "{}: {} {}",
            alg.name(),
            alg.name_of(a).unwrap(),
            alg.name_of(b).unwrap()
        );
    }
    check_product_gp(alg, &r, Some(&pairs));
    let op = alg.tables().product(Basis::Blade, Product::Outer);
    for a in 0..dim {
        for b in 0..dim {
            let expected = if a & b == 0 { vec![(a | b, q(reorder_sign(a, b)))] } else { vec![] };
            assert_eq!(op.get(a, b).unwrap(), expected.as_slice());
        }
    }
    let (a, b) = (0b1011_0101, 0b0110_1110);
    let x = Multivector::<Q>::from_mask(alg, Basis::Product, a).unwrap();
    let y = Multivector::<Q>::from_mask(alg, Basis::Product, b).unwrap();
    let direct = sparse(r.combine(&sparse((&x * &y).coeffs().to_vec()), &r.p_in_f));
    assert_eq!(direct, r.product_gp_in_f(a, b), "{}: P_A P_B through Multivector", alg.name());
}

/// Times building each table (printed with `--nocapture`; nothing is asserted about time).
fn build_all_timed(alg: &Algebra) {
    let t = alg.tables();
    let start = Instant::now();
    let mut last = start;
    let mut lap = |what: String| {
        let now = Instant::now();
        eprintln!("  {}: {what}: {:.3}s", alg.name(), (now - last).as_secs_f64());
        last = now;
    };
    for basis in Basis::ALL {
        for p in Product::ALL {
            t.product(basis, p);
            lap(format!("{basis} {p}"));
        }
    }
    t.build_all();
    lap("rest of build_all (unary maps, grade projections)".into());
    eprintln!("  {}: build_all total {:.3}s", alg.name(), start.elapsed().as_secs_f64());
}

/// Builds every table of an 8-generator non-diagonal algebra with integer entries and
/// spot-checks them against the reference (a few seconds in the test profile).
#[test]
fn eight_generators_build_all_tables() {
    let alg = custom("sparse8", sparse_8_generator_metric());
    build_all_timed(&alg);
    spot_check_8(&alg, &mut Lcg(0x5eed_0008));
}

/// The same for a dense random rational 8-generator metric, where the coefficients grow
/// large: about 1.5 minutes for `build_all` (most of it in the product-basis tables obtained
/// by conjugating the blade ones), so it is ignored by default.
#[test]
#[ignore = "slow (minutes): cargo test --release -p algebra-core --test all -- --ignored --nocapture reference::"]
fn eight_generators_dense_build_all_tables() {
    let mut rng = Lcg(0x5eed_0008);
    let g = dense_8_generator_metric(&mut rng);
    assert!(!is_diagonal(&g));
    let alg = custom("dense8", g);
    build_all_timed(&alg);
    spot_check_8(&alg, &mut rng);
}
