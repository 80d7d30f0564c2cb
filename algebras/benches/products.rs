//! Side-by-side product benchmarks (one process, so ratios are meaningful on a shared machine):
//!
//! * `motor_product`: the generated `g123inf::Motor * Motor` (G_{123inf}^+, 48 multiplications)
//!   against nalgebra's `DualQuaternion<f64>` product and GAM's hand-written
//!   [`DualQuaternion<f64>`] product (isomorphic algebras, same operation count);
//! * `cga_full_product`: the generated full `cga::Multivector * Multivector` (R^{4,1}, 32x32
//!   unrolled) against table-driven loops: a flat `f64` table `(a, b, k, sign)` built once from
//!   the exact tables (the floor of a table-driven product), and the runtime
//!   `algebra_core::Multivector<f64>` product (the reference implementation: exact rational table
//!   entries, a heap allocation per product).
//!
//! Every iteration multiplies a batch of pre-generated operand pairs; throughput is per product.
//! Criterion measures the kernels one after the other, which on a loaded machine lets the load
//! change between them; so after the criterion groups, `cargo bench` also prints ratios measured
//! **interleaved**: each round times every kernel of a group back to back (in rotating order),
//! and the report gives the median of the per-round ratios.
//!
//! * versor action (the report only, interleaved): `cga_null::Motor::sandwich(&Vector)` (fused),
//!   `sandwich_unit` on unit motors, and the composed `(rev(S) x) S` relative to `cga_null`
//!   `Motor * Motor`; `pga3` `apply` on a
//!   trivector point at f32 relative to the f32 motor product; against nalgebra (f64):
//!   `g123inf` `Motor * Motor` vs `DualQuaternion *`, a pose applied to a point (`pga3` `apply`
//!   on a trivector, and `apply_unit` on unit motors) vs `UnitDualQuaternion::transform_point` and
//!   `Isometry3::transform_point`,
//!   and a batch of points by one pose; closed-form `g123inf` `Bivector::exp` and `Motor::log`
//!   relative to `Motor * Motor`, and `cga_null` `PoseBivector::exp` and `Motor::log_unit`
//!   relative to the `cga_null` motor product. The `g3` action group also times two
//!   hand-written forms of the rotor action (the 3x3 matrix, two cross products) as
//!   references for the generated one (checked against it at start-up).
//!
//! Run with `cargo bench -p gam-algebras --bench products`.
#![allow(missing_docs)]

use algebra_core::test_support::Xorshift;
use algebra_core::{Algebra, Multivector, Product, Ring};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group};
use gam_algebras::{DualQuaternion, cga, cga_null, g3, g123inf, pga3};
use nalgebra::{Isometry3, Point3, Quaternion, Translation3, UnitDualQuaternion, UnitQuaternion, Vector3};
use std::hint::black_box;
use std::sync::OnceLock;
use std::time::{Duration, Instant};

algebra_macros::algebra! {
    /// The conformal model as GATL (and the ga-benchmark suite) declare it: generators
    /// `e1, e2, e3, eo, einf` with `eo · einf = -1`, in the blade basis (the default), motors
    /// on the same eight blades as `cga_null`'s: the fused action in another basis, order and
    /// metric than the predefined product-basis module.
    pub mod gatl_cga {
        generators { e1, e2, e3, eo, einf }
        metric { (e1, e1) = 1, (e2, e2) = 1, (e3, e3) = 1, (eo, einf) = -1 }
        types {
            Vector = grade 1;
            Bivector = grade 2;
            Motor = [1, e12, e13, e23, e1inf, e2inf, e3inf, e123inf];
        }
    }
}

/// Products per criterion iteration.
const BATCH: usize = 1024;
/// Products per criterion iteration for the (much slower) runtime reference.
const RUNTIME_BATCH: usize = 64;

/// One non-zero entry of a flat geometric-product table: `out[k] += sign * x[a] * y[b]`.
#[derive(Clone, Copy)]
struct Entry {
    a: u8,
    b: u8,
    k: u8,
    sign: f64,
}

/// The table-driven floor: a loop over the flattened non-zero table entries.
fn table_gp(table: &[Entry], x: &[f64; 32], y: &[f64; 32]) -> [f64; 32] {
    let mut out = [0.0; 32];
    for e in table {
        out[e.k as usize] += e.sign * x[e.a as usize] * y[e.b as usize];
    }
    out
}

/// The operands (`2 * BATCH` of each kind; products pair element `i` with `BATCH + i`).
struct Data {
    motors: Vec<g123inf::Motor<f64>>,
    ours: Vec<DualQuaternion<f64>>,
    theirs: Vec<nalgebra::DualQuaternion<f64>>,
    table: Vec<Entry>,
    dense: Vec<[f64; 32]>,
    runtime: Vec<Multivector<f64>>,
    generated: Vec<cga::Multivector<f64>>,
    versor: Versor,
}

/// The operands of the versor-action and closed-form groups.
struct Versor {
    cn_motors: Vec<cga_null::Motor<f64>>,
    cn_points: Vec<cga_null::Vector<f64>>,
    pga_motors32: Vec<pga3::Motor<f32>>,
    pga_points32: Vec<pga3::Trivector<f32>>,
    pga_motors: Vec<pga3::Motor<f64>>,
    pga_units: Vec<pga3::Motor<f64>>,
    cn_bivectors: Vec<cga_null::PoseBivector<f64>>,
    cn_units: Vec<cga_null::Motor<f64>>,
    /// `cga` (R^{4,1}): general even elements, rigid-motion generators and their motors.
    cga_motors: Vec<cga::Motor<f64>>,
    cga_bivectors: Vec<cga::Bivector<f64>>,
    cga_units: Vec<cga::Motor<f64>>,
    pga_points: Vec<pga3::Trivector<f64>>,
    motors: Vec<g123inf::Motor<f64>>,
    bivectors: Vec<g123inf::Bivector<f64>>,
    units: Vec<g123inf::Motor<f64>>,
    dq: Vec<nalgebra::DualQuaternion<f64>>,
    unit_dq: Vec<UnitDualQuaternion<f64>>,
    iso: Vec<Isometry3<f64>>,
    points: Vec<Point3<f64>>,
    /// The action's ratio to the motor product in each basis: GATL's conformal declaration,
    /// `cga` (diagonal R^{4,1}) on conformal points, and `g3` rotors on vectors.
    gatl_motors: Vec<gatl_cga::Motor<f64>>,
    gatl_points: Vec<gatl_cga::Vector<f64>>,
    gatl_bivectors: Vec<gatl_cga::Bivector<f64>>,
    cga_points: Vec<cga::Vector<f64>>,
    g3_rotors: Vec<g3::Rotor<f64>>,
    g3_vectors: Vec<g3::Vector<f64>>,
}

fn data() -> &'static Data {
    static DATA: OnceLock<Data> = OnceLock::new();
    DATA.get_or_init(|| {
        let mut rng = Xorshift(0x9e37_79b9_7f4a_7c15);
        let coeffs: Vec<[f64; 8]> = (0..2 * BATCH).map(|_| [(); 8].map(|_| rng.symmetric())).collect();
        let motors =
            coeffs.iter().map(|&[s, a, b, c, d, e, f, w]| g123inf::Motor::new(s, a, b, c, d, e, f, w)).collect();
        let ours = coeffs.iter().map(|&c| DualQuaternion::from_coeffs(c)).collect();
        let theirs = coeffs
            .iter()
            .map(|&[rw, rx, ry, rz, dw, dx, dy, dz]| {
                nalgebra::DualQuaternion::from_real_and_dual(
                    nalgebra::Quaternion::new(rw, rx, ry, rz),
                    nalgebra::Quaternion::new(dw, dx, dy, dz),
                )
            })
            .collect();

        let alg = Algebra::builtin("cga").expect("built-in cga");
        let gp = alg.tables().product(cga::BASIS, Product::Geometric);
        let mut table = Vec::new();
        for a in 0..32u32 {
            for b in 0..32u32 {
                for (k, coeff) in gp.get(a, b).expect("a, b < 32") {
                    table.push(Entry { a: a as u8, b: b as u8, k: *k as u8, sign: f64::from_rational(coeff) });
                }
            }
        }
        let dense: Vec<[f64; 32]> = (0..2 * BATCH).map(|_| [(); 32].map(|_| rng.symmetric())).collect();
        let runtime: Vec<Multivector<f64>> = dense
            .iter()
            .map(|c| Multivector::from_coeffs(&alg, cga::BASIS, c.to_vec()).expect("32 coefficients"))
            .collect();
        let generated: Vec<cga::Multivector<f64>> = runtime.iter().map(cga::Multivector::project).collect();

        // the implementations agree (sanity check, outside the timing)
        let reference = &runtime[0] * &runtime[BATCH];
        let by_table = table_gp(&table, &dense[0], &dense[BATCH]);
        let by_generated = (generated[0] * generated[BATCH]).to_multivector();
        for (mask, t) in by_table.iter().enumerate() {
            let r = reference.coeff(mask as u32).unwrap();
            assert!((r - t).abs() < 1e-12 && (r - by_generated.coeff(mask as u32).unwrap()).abs() < 1e-12);
        }
        Data { motors, ours, theirs, table, dense, runtime, generated, versor: versor_data() }
    })
}

fn versor_data() -> Versor {
    let mut rng = Xorshift(0x2545_f491_4f6c_dd1d);
    let mut d = Versor {
        cn_motors: Vec::new(),
        cn_points: Vec::new(),
        pga_motors32: Vec::new(),
        pga_points32: Vec::new(),
        pga_motors: Vec::new(),
        pga_units: Vec::new(),
        cn_bivectors: Vec::new(),
        cn_units: Vec::new(),
        cga_motors: Vec::new(),
        cga_bivectors: Vec::new(),
        cga_units: Vec::new(),
        pga_points: Vec::new(),
        motors: Vec::new(),
        bivectors: Vec::new(),
        units: Vec::new(),
        dq: Vec::new(),
        unit_dq: Vec::new(),
        iso: Vec::new(),
        points: Vec::new(),
        gatl_motors: Vec::new(),
        gatl_points: Vec::new(),
        gatl_bivectors: Vec::new(),
        cga_points: Vec::new(),
        g3_rotors: Vec::new(),
        g3_vectors: Vec::new(),
    };
    for _ in 0..2 * BATCH {
        let c = [(); 8].map(|_| rng.symmetric());
        let p = [(); 3].map(|_| rng.symmetric());
        d.cn_motors.push(cga_null::Motor::from_array(c));
        let p2 = p.iter().map(|x| x * x).sum::<f64>() / 2.0;
        d.cn_points.push(cga_null::Vector::new(1.0, p[0], p[1], p[2], p2));
        d.pga_motors.push(pga3::Motor::from_array(c));
        d.pga_motors32.push(pga3::Motor::from_array(c.map(|x| x as f32)));
        d.pga_points.push(pga3::Trivector::new(p[0], p[1], p[2], 1.0));
        d.pga_points32.push(pga3::Trivector::new(p[0] as f32, p[1] as f32, p[2] as f32, 1.0));
        d.motors.push(g123inf::Motor::from_array(c));
        let b = g123inf::Bivector::from_array([c[1], c[2], c[4], c[3], c[5], c[6]]);
        let unit = b.exp();
        // the same unit motor in pga3 (einf -> e0: e_i einf = -e0i, e123inf = -e0123; pga3's
        // field order is 1, e01, e02, e12, e03, e13, e23, e0123)
        let [s0, b12, b13, b23, t1, t2, t3, w] = unit.to_array();
        d.pga_units.push(pga3::Motor::new(s0, -t1, -t2, b12, -t3, b13, b23, -w));
        d.units.push(unit);
        let mut nb = cga_null::PoseBivector::zero();
        (nb.e12, nb.e13, nb.e23, nb.e1inf, nb.e2inf, nb.e3inf) = (c[1], c[2], c[3], c[4], c[5], c[6]);
        d.cn_units.push(nb.exp());
        d.cga_motors.push(cga::Motor::from_array([(); 16].map(|_| rng.symmetric())));
        let mut gb = cga::Bivector::zero();
        (gb.e12, gb.e13, gb.e23) = (c[1], c[2], c[3]);
        (gb.e14, gb.e24, gb.e34, gb.e15, gb.e25, gb.e35) = (c[4], c[5], c[6], c[4], c[5], c[6]);
        d.cga_units.push(gb.exp().expect("finite"));
        d.cga_bivectors.push(gb);
        d.cn_bivectors.push(nb);
        d.bivectors.push(b);
        let (r, t) = (Quaternion::new(c[0], c[1], c[2], c[3]), Quaternion::new(c[4], c[5], c[6], c[7]));
        d.dq.push(nalgebra::DualQuaternion::from_real_and_dual(r, t));
        let rot = UnitQuaternion::from_quaternion(r);
        let tr = Translation3::new(c[5], c[6], c[7]);
        d.unit_dq.push(UnitDualQuaternion::from_parts(tr, rot));
        d.iso.push(Isometry3::from_parts(tr, rot));
        d.points.push(Point3::from(Vector3::new(p[0], p[1], p[2])));
        d.gatl_motors.push(gatl_cga::Motor::from_array(c));
        // ELEMENTS order e1, e2, e3, eo, einf
        d.gatl_points.push(gatl_cga::Vector::from_array([p[0], p[1], p[2], 1.0, p2]));
        d.gatl_bivectors.push(gatl_cga::Bivector::from_array([(); 10].map(|_| rng.symmetric())));
        // cga: eo = (e5 - e4)/2, einf = e4 + e5
        d.cga_points.push(cga::Vector::from_array([p[0], p[1], p[2], p2 - 0.5, p2 + 0.5]));
        d.g3_rotors.push(g3::Rotor::from_array([c[0], c[1], c[2], c[3]]));
        d.g3_vectors.push(g3::Vector::from_array(p));
    }
    // sanity: the unit kernel agrees with the general one on the unit motors
    let (u, p) = (&d.pga_units[0], &d.pga_points[0]);
    assert!(u.apply_unit(p).iter().zip(u.apply(p).iter()).all(|(a, b)| (a - b).abs() < 1e-12));
    // sanity: the fused action is the projected composed one
    let (s, x) = (&d.cn_motors[0], &d.cn_points[0]);
    let composed = cga_null::Vector::project(&((s.reverse() * x) * s).to_multivector());
    let fused = s.sandwich(x);
    assert!(fused.iter().zip(composed.iter()).all(|(a, b)| (a - b).abs() < 1e-12));
    // sanity: on unit motors the unit action is the fused one
    let (u, x) = (&d.cn_units[0], &d.cn_points[0]);
    assert!(u.sandwich_unit(x).iter().zip(u.sandwich(x).iter()).all(|(a, b)| (a - b).abs() < 1e-12));
    // sanity: GATL's declaration acts as cga_null does (the motor blades are the same
    // products of orthogonal generators; points reordered e0 first)
    let g = d.gatl_motors[0].sandwich(&d.gatl_points[0]).to_array();
    let n = d.cn_motors[0].sandwich(&d.cn_points[0]).to_array();
    assert!([g[3], g[0], g[1], g[2], g[4]].iter().zip(n).all(|(a, b)| (a - b).abs() < 1e-12));
    d
}

/// A kernel run over the first `n` operand pairs of a batch.
type Kernel = fn(&Data, usize);

fn motor_generated(d: &Data, n: usize) {
    let (xs, ys) = d.motors.split_at(BATCH);
    for (x, y) in xs.iter().zip(ys).take(n) {
        black_box(black_box(x) * black_box(y));
    }
}

fn motor_nalgebra(d: &Data, n: usize) {
    let (xs, ys) = d.theirs.split_at(BATCH);
    for (x, y) in xs.iter().zip(ys).take(n) {
        black_box(*black_box(x) * *black_box(y));
    }
}

fn motor_dual_quaternion(d: &Data, n: usize) {
    let (xs, ys) = d.ours.split_at(BATCH);
    for (x, y) in xs.iter().zip(ys).take(n) {
        black_box(black_box(x) * black_box(y));
    }
}

fn cga_generated(d: &Data, n: usize) {
    let (xs, ys) = d.generated.split_at(BATCH);
    for (x, y) in xs.iter().zip(ys).take(n) {
        black_box(black_box(x) * black_box(y));
    }
}

fn cga_table(d: &Data, n: usize) {
    let (xs, ys) = d.dense.split_at(BATCH);
    for (x, y) in xs.iter().zip(ys).take(n) {
        black_box(table_gp(black_box(&d.table), black_box(x), black_box(y)));
    }
}

fn cga_runtime(d: &Data, n: usize) {
    let (xs, ys) = d.runtime.split_at(BATCH);
    for (x, y) in xs.iter().zip(ys).take(n) {
        black_box(black_box(x) * black_box(y));
    }
}

macro_rules! pairs {
    ($name:ident, $xs:ident, $ys:ident, |$x:ident, $y:ident| $body:expr) => {
        fn $name(d: &Data, n: usize) {
            for ($x, $y) in d.versor.$xs[..n].iter().zip(&d.versor.$ys[BATCH..BATCH + n]) {
                let ($x, $y) = (black_box($x), black_box($y));
                black_box($body);
            }
        }
    };
}

pairs!(cn_motor_product, cn_motors, cn_motors, |x, y| x * y);
pairs!(cn_sandwich_fused, cn_motors, cn_points, |s, p| s.sandwich(p));
pairs!(cn_sandwich_composed, cn_motors, cn_points, |s, p| (s.reverse() * p) * s);
pairs!(cn_sandwich_unit, cn_units, cn_points, |s, p| s.sandwich_unit(p));
pairs!(pga32_motor_product, pga_motors32, pga_motors32, |x, y| x * y);
pairs!(pga32_apply_point, pga_motors32, pga_points32, |s, p| s.apply(p));
pairs!(g123_motor_product, motors, motors, |x, y| x * y);
pairs!(na_dq_product, dq, dq, |x, y| *x * *y);
pairs!(pga_apply_point, pga_motors, pga_points, |s, p| s.apply(p));
pairs!(pga_apply_unit_point, pga_units, pga_points, |s, p| s.apply_unit(p));
pairs!(na_unit_dq_point, unit_dq, points, |s, p| s.transform_point(p));
pairs!(na_iso_point, iso, points, |s, p| s.transform_point(p));
pairs!(cga_motor_product, cga_motors, cga_motors, |x, y| x * y);
pairs!(cga_sandwich_point, cga_motors, cga_points, |s, p| s.sandwich(p));
pairs!(gatl_motor_product, gatl_motors, gatl_motors, |x, y| x * y);
pairs!(gatl_sandwich_point, gatl_motors, gatl_points, |s, p| s.sandwich(p));
pairs!(gatl_apply_point, gatl_motors, gatl_points, |s, p| s.apply(p));
pairs!(gatl_bivector_product, gatl_bivectors, gatl_bivectors, |x, y| x * y);
pairs!(pga_motor_product, pga_motors, pga_motors, |x, y| x * y);
pairs!(pga_sandwich_point, pga_motors, pga_points, |s, p| s.sandwich(p));
pairs!(g3_rotor_product, g3_rotors, g3_rotors, |x, y| x * y);
pairs!(g3_sandwich_vector, g3_rotors, g3_vectors, |s, p| s.sandwich(p));
/// Reference rows for issue 31 (target B), hand-written, not generated: `rev(R) x R` for a
/// rotor `R = w + B` by the 3x3 matrix of `R`'s quadratic products (19 multiplications).
#[inline(always)]
fn g3_matrix_form(s: &g3::Rotor<f64>, x: &g3::Vector<f64>) -> g3::Vector<f64> {
    let [w, e12, e13, e23] = s.to_array();
    let (v0, v1, v2) = (e23, -e13, e12);
    let x = x.to_array();
    let (t0, t1, t2) = (v0 + v0, v1 + v1, v2 + v2);
    let (ww, d0, d1, d2) = (w * w, v0 * v0, v1 * v1, v2 * v2);
    let (a01, a02, a12) = (t0 * v1, t0 * v2, t1 * v2);
    let (w0, w1, w2) = (w * t0, w * t1, w * t2);
    let m = [
        [(ww + d0) - (d1 + d2), a01 - w2, a02 + w1],
        [a01 + w2, (ww + d1) - (d0 + d2), a12 - w0],
        [a02 - w1, a12 + w0, (ww + d2) - (d0 + d1)],
    ];
    g3::Vector::from_array(std::array::from_fn(|i| m[i][0] * x[0] + m[i][1] * x[1] + m[i][2] * x[2]))
}
/// The same action by two cross products, as `motion`'s point action: with `v = (B23, -B13,
/// B12)`, `m = v × x`, `rev(R) x R = α x + 2(w m + v × m)` (22 multiplications).
#[inline(always)]
fn g3_cross_form(s: &g3::Rotor<f64>, x: &g3::Vector<f64>) -> g3::Vector<f64> {
    let [w, e12, e13, e23] = s.to_array();
    let v = [e23, -e13, e12];
    let x = x.to_array();
    let cr =
        |a: &[f64; 3], b: &[f64; 3]| [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    let alpha = (w * w + v[0] * v[0]) + (v[1] * v[1] + v[2] * v[2]);
    let m = cr(&v, &x);
    let vm = cr(&v, &m);
    g3::Vector::from_array(std::array::from_fn(|i| {
        let h = w * m[i] + vm[i];
        alpha * x[i] + (h + h)
    }))
}
pairs!(g3_sandwich_matrix, g3_rotors, g3_vectors, |s, p| g3_matrix_form(s, p));
pairs!(g3_sandwich_cross, g3_rotors, g3_vectors, |s, p| g3_cross_form(s, p));

pairs!(cn_apply_point, cn_motors, cn_points, |s, p| s.apply(p));

fn motor_exp(d: &Data, n: usize) {
    for b in &d.versor.bivectors[..n] {
        black_box(black_box(b).exp());
    }
}

fn motor_log(d: &Data, n: usize) {
    for m in &d.versor.units[..n] {
        black_box(black_box(m).log().ok());
    }
}

fn motor_log_unit(d: &Data, n: usize) {
    for m in &d.versor.units[..n] {
        black_box(black_box(m).log_unit().ok());
    }
}

fn cn_exp(d: &Data, n: usize) {
    for b in &d.versor.cn_bivectors[..n] {
        black_box(black_box(b).exp());
    }
}

fn cn_log_unit(d: &Data, n: usize) {
    for m in &d.versor.cn_units[..n] {
        black_box(black_box(m).log_unit().ok());
    }
}

fn cga_exp(d: &Data, n: usize) {
    for b in &d.versor.cga_bivectors[..n] {
        black_box(black_box(b).exp().ok());
    }
}

fn cga_exp_series(d: &Data, n: usize) {
    for b in &d.versor.cga_bivectors[..n] {
        black_box(black_box(b).to_multivector().exp().ok());
    }
}

fn cga_log(d: &Data, n: usize) {
    for m in &d.versor.cga_units[..n] {
        black_box(black_box(m).log().ok());
    }
}

fn cga_log_series(d: &Data, n: usize) {
    for m in &d.versor.cga_units[..n] {
        black_box(black_box(m).to_multivector().log().ok());
    }
}

/// One pose, a batch of points.
fn pga_batch(d: &Data, n: usize) {
    let s = black_box(&d.versor.pga_motors[0]);
    for p in &d.versor.pga_points[..n] {
        black_box(s.apply(black_box(p)));
    }
}

/// One pose, a batch of points, through the action's matrix (computed once per batch).
fn pga_batch_matrix(d: &Data, n: usize) {
    let s = black_box(&d.versor.pga_motors[0]);
    let m = s.apply_matrix::<pga3::Trivector<f64>>();
    for p in &d.versor.pga_points[..n] {
        black_box(pga3::Motor::transform(&m, black_box(p)));
    }
}

fn na_iso_batch(d: &Data, n: usize) {
    let s = black_box(&d.versor.iso[0]);
    for p in &d.versor.points[..n] {
        black_box(s.transform_point(black_box(p)));
    }
}

const MOTOR_KERNELS: [(&str, Kernel); 3] = [
    ("gam_generated_g123inf_motor", motor_generated),
    ("nalgebra_dual_quaternion", motor_nalgebra),
    ("gam_dual_quaternion", motor_dual_quaternion),
];

fn motor_products(c: &mut Criterion) {
    let d = data();
    let mut group = c.benchmark_group("motor_product");
    group.throughput(Throughput::Elements(BATCH as u64));
    for (name, kernel) in MOTOR_KERNELS {
        group.bench_function(name, |b| b.iter(|| kernel(d, BATCH)));
    }
    group.finish();
}

fn cga_products(c: &mut Criterion) {
    let d = data();
    let mut group = c.benchmark_group("cga_full_product");
    group.throughput(Throughput::Elements(BATCH as u64));
    group.bench_function("gam_generated_cga_multivector", |b| b.iter(|| cga_generated(d, BATCH)));
    group.bench_function("table_driven_flat_f64", |b| b.iter(|| cga_table(d, BATCH)));
    group.throughput(Throughput::Elements(RUNTIME_BATCH as u64));
    group.bench_function(BenchmarkId::new("runtime_multivector_reference", RUNTIME_BATCH), |b| {
        b.iter(|| cga_runtime(d, RUNTIME_BATCH))
    });
    group.finish();
}

/// Times the kernels of one group interleaved: `rounds` rounds, each timing every kernel once
/// on `n` products (`reps` times over), in an order rotated per round. Prints the median time per
/// product of each kernel and, for each kernel, the median over rounds of its time divided by
/// the first kernel's time in the same round.
fn interleaved(title: &str, kernels: &[(&str, Kernel, usize)], rounds: usize, reps: usize) {
    let d = data();
    let mut times: Vec<Vec<f64>> = vec![Vec::with_capacity(rounds); kernels.len()];
    for round in 0..rounds {
        for j in 0..kernels.len() {
            let i = (j + round) % kernels.len();
            let (_, kernel, n) = kernels[i];
            let start = Instant::now();
            for _ in 0..reps {
                kernel(d, n);
            }
            times[i].push(start.elapsed().as_secs_f64() * 1e9 / (reps * n) as f64);
        }
    }
    let median = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    println!("\ninterleaved ({rounds} rounds): {title}");
    println!("  {:<40} {:>12} {:>12} {:>16}", "kernel", "median ns", "min ns", "ratio to first");
    for (i, (name, _, _)) in kernels.iter().enumerate() {
        let ratios = times[i].iter().zip(&times[0]).map(|(t, t0)| t / t0).collect();
        let min = times[i].iter().copied().fold(f64::INFINITY, f64::min);
        println!("  {name:<40} {:>12.2} {:>12.2} {:>16.3}", median(times[i].clone()), min, median(ratios));
    }
}

fn interleaved_report() {
    let motors: Vec<(&str, Kernel, usize)> = MOTOR_KERNELS.iter().map(|&(n, k)| (n, k, BATCH)).collect();
    interleaved("G_{123inf}^+ motor product vs dual quaternions (f64)", &motors, 2000, 4);
    interleaved(
        "cga (R^{4,1}) full multivector product (f64)",
        &[
            ("gam_generated_cga_multivector", cga_generated, 64),
            ("table_driven_flat_f64", cga_table, 64),
            ("runtime_multivector_reference", cga_runtime, 64),
        ],
        400,
        1,
    );
}

/// The versor-action, nalgebra and closed-form groups (docs/performance.md).
const VERSOR_GROUPS: [(&str, &[(&str, Kernel)]); 11] = [
    (
        "fused action / motor product: cga_null (product basis, e0 first)",
        &[
            ("cga_null Motor * Motor", cn_motor_product),
            ("cga_null Motor.sandwich(Vector)", cn_sandwich_fused),
            ("cga_null Motor.apply(Vector)", cn_apply_point),
        ],
    ),
    (
        "fused action / motor product: GATL's declaration (blade basis, e1 e2 e3 eo einf)",
        &[
            ("gatl_cga Motor * Motor", gatl_motor_product),
            ("gatl_cga Motor.sandwich(Vector)", gatl_sandwich_point),
            ("gatl_cga Motor.apply(Vector)", gatl_apply_point),
            ("gatl_cga Bivector * Bivector", gatl_bivector_product),
        ],
    ),
    (
        "fused action / motor product: cga (diagonal R^{4,1}, 16-component motors)",
        &[("cga Motor * Motor", cga_motor_product), ("cga Motor.sandwich(Vector)", cga_sandwich_point)],
    ),
    (
        "fused action / motor product: pga3 (f64, points as trivectors)",
        &[("pga3 Motor * Motor", pga_motor_product), ("pga3 Motor.sandwich(Trivector)", pga_sandwich_point)],
    ),
    (
        "fused action / motor product: g3 (rotors on vectors)",
        &[
            ("g3 Rotor * Rotor", g3_rotor_product),
            ("g3 Rotor.sandwich(Vector)", g3_sandwich_vector),
            ("g3 matrix form", g3_sandwich_matrix),
            ("g3 cross form", g3_sandwich_cross),
        ],
    ),
    (
        "conformal point (cga_null, f64)",
        &[
            ("cga_null Motor * Motor", cn_motor_product),
            ("cga_null Motor.sandwich(Vector), fused", cn_sandwich_fused),
            ("cga_null Motor.sandwich_unit(Vector), unit motors", cn_sandwich_unit),
            ("cga_null (rev(S) x) S, composed full kernels", cn_sandwich_composed),
        ],
    ),
    (
        "PGA point at f32",
        &[
            ("pga3 Motor<f32> * Motor<f32>", pga32_motor_product),
            ("pga3 Motor<f32>.apply(Trivector)", pga32_apply_point),
        ],
    ),
    (
        "against nalgebra (f64)",
        &[
            ("nalgebra DualQuaternion *", na_dq_product),
            ("g123inf Motor * Motor", g123_motor_product),
            ("nalgebra UnitDualQuaternion::transform_point", na_unit_dq_point),
            ("pga3 Motor.apply(Trivector point)", pga_apply_point),
            ("pga3 Motor.apply_unit(Trivector point)", pga_apply_unit_point),
            ("nalgebra Isometry3::transform_point", na_iso_point),
        ],
    ),
    (
        "closed-form motor exp and log (g123inf, f64)",
        &[
            ("g123inf Motor * Motor", g123_motor_product),
            ("g123inf Bivector::exp", motor_exp),
            ("g123inf Motor::log (unit motors)", motor_log),
            ("g123inf Motor::log_unit", motor_log_unit),
        ],
    ),
    (
        "closed-form pose exp and log in G_{0123inf} (cga_null, f64)",
        &[
            ("cga_null Motor * Motor", cn_motor_product),
            ("cga_null PoseBivector::exp", cn_exp),
            ("cga_null Motor::log_unit", cn_log_unit),
        ],
    ),
    (
        "a batch of points by one pose (f64)",
        &[
            ("nalgebra Isometry3::transform_point", na_iso_batch),
            ("pga3 Motor.apply(Trivector)", pga_batch),
            ("pga3 apply_matrix once, then transform", pga_batch_matrix),
        ],
    ),
];

fn versor_report() {
    // `GAM_REPORT_ONLY=fused` runs only the groups whose title contains it (A/B runs)
    let only = std::env::var("GAM_REPORT_ONLY").ok();
    for (title, kernels) in VERSOR_GROUPS {
        if only.as_ref().is_some_and(|o| !title.contains(o.as_str())) {
            continue;
        }
        let kernels: Vec<(&str, Kernel, usize)> = kernels.iter().map(|&(n, k)| (n, k, BATCH)).collect();
        interleaved(title, &kernels, 2000, 1);
    }
    if only.is_some() {
        return;
    }
    interleaved(
        "closed-form rigid motions in R^{4,1} (cga, f64)",
        &[
            ("cga Motor * Motor (16 x 16)", cga_motor_product, BATCH),
            ("cga Bivector::exp (rigid motions)", cga_exp, BATCH),
            ("cga runtime series exp", cga_exp_series, RUNTIME_BATCH),
            ("cga Motor::log (rigid motions)", cga_log, BATCH),
            ("cga runtime series log", cga_log_series, RUNTIME_BATCH),
        ],
        200,
        1,
    );
}

fn config() -> Criterion {
    Criterion::default().warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(4)).sample_size(40)
}

criterion_group! {
    name = benches;
    config = config();
    targets = motor_products, cga_products
}

fn main() {
    // the hand-written g3 reference forms agree with the generated sandwich
    {
        let mut rng = Xorshift(0x1234_5678_9abc_def1);
        for _ in 0..100 {
            let c: Vec<f64> = (0..7).map(|_| rng.symmetric()).collect();
            let r = g3::Rotor::from_array([c[0], c[1], c[2], c[3]]);
            let x = g3::Vector::from_array([c[4], c[5], c[6]]);
            let (a, b, e) =
                (r.sandwich(&x).to_array(), g3_matrix_form(&r, &x).to_array(), g3_cross_form(&r, &x).to_array());
            let close = a.iter().zip(&b).zip(&e).all(|((a, b), e)| (a - b).abs() < 1e-12 && (a - e).abs() < 1e-12);
            assert!(close, "g3 hand-written forms disagree with the fused sandwich: {a:?} {b:?} {e:?}");
        }
    }
    benches();
    Criterion::default().configure_from_args().final_summary();
    // `cargo bench` passes `--bench`; skip the report when the bench is run as a test.
    if std::env::args().any(|a| a == "--bench") {
        if std::env::var_os("GAM_REPORT_ONLY").is_none() {
            interleaved_report();
        }
        versor_report();
    }
}
