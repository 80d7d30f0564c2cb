//! The inverse-kinematics workload of the ga-benchmark suite (Fernandes et al.), written for
//! GAM: a five-joint arm whose joint axes are conformal lines, each joint's rotor the
//! fourth-order Taylor polynomial `1 + x + x²/2 + x³/6 + x⁴/24` of `(angle/2) L` (the suite's
//! `expp`), and the gripper point carried through the chain by `S x rev(S)` (GATL's
//! `apply_rotor`, GAM's `apply`).
//!
//! The algebra is declared as GATL declares it (`e1, e2, e3, eo, einf`, `eo · einf = -1`, blade
//! basis), and the types say what the geometry is: a line through two points and infinity
//! (`Flat`), its dual (`Line`, the six bivectors of a rigid motion), motors, translators, and
//! `[1, e123inf]` for the square of a line. The planner gives each product the smallest of
//! these types that holds its result, so the structure GATL infers from its expression
//! templates is here in the declarations; only the numbers are left to run time.
//!
//! Shared by the `ik` bench (timing) and the `ik` test (checks against the runtime engine and
//! against the arm's motion known in closed form).

algebra_macros::algebra! {
    /// The conformal model in GATL's declaration, with the inverse-kinematics types.
    pub mod arm_cga {
        generators { e1, e2, e3, eo, einf }
        metric { (e1, e1) = 1, (e2, e2) = 1, (e3, e3) = 1, (eo, einf) = -1 }
        types {
            /// A conformal point `eo + x + |x|²/2 einf` (and any vector).
            Point = grade 1;
            /// `einf`.
            Infinity = [einf];
            /// A Euclidean direction.
            Direction = [e1, e2, e3];
            /// The outer product of two points.
            Bivector = grade 2;
            /// `P ∧ Q ∧ einf`: a line through two points, as a flat.
            Flat = [e12inf, e13inf, e23inf, e1oinf, e2oinf, e3oinf];
            /// The dual of a flat line: a rigid motion's generator.
            Line = [e12, e13, e23, e1inf, e2inf, e3inf];
            /// `t ∧ einf`: a translation's generator.
            TranslationLine = [e1inf, e2inf, e3inf];
            /// The square of a line: a scalar and the pseudoscalar of the motions.
            LineSquare = [1, e123inf];
            /// A rigid motion.
            Motor = [1, e12, e13, e23, e1inf, e2inf, e3inf, e123inf];
            /// A translation.
            Translator = [1, e1inf, e2inf, e3inf];
            /// The pseudoscalar `e1 ∧ e2 ∧ e3 ∧ eo ∧ einf` (its own negative inverse).
            Pseudoscalar = [e123oinf];
        }
    }
}

use algebra_core::ops::{AnticommutatorProduct, GeometricProduct, OuterProduct, ScalarProduct};
use arm_cga::{Direction, Infinity, Line, LineSquare, Motor, Point, Pseudoscalar, TranslationLine, Translator};

/// The arm's dimensions (the suite's `d1 ... d5`, `l12`, `l23`, in millimetres).
#[derive(Clone, Copy, Debug)]
pub struct Geometry {
    pub d: [f64; 5],
    pub l12: f64,
    pub l23: f64,
}

/// The suite's arm: `d = (200, 680, 150, 140, 114.2)`, `l12 = 890`, `l23 = 880`.
pub const ARM: Geometry = Geometry { d: [200.0, 680.0, 150.0, 140.0, 114.2], l12: 890.0, l23: 880.0 };

/// The joints' rotors and translator and the gripper's image: the suite's result tuple
/// `(R1, R2, R3, T2, R4, Rg, Jg_f)`.
#[derive(Clone, Copy, Debug)]
#[allow(dead_code)] // the bench hands the whole chain to `black_box`; the test reads every field
pub struct Chain {
    pub r1: Motor<f64>,
    pub r2: Motor<f64>,
    pub r3: Motor<f64>,
    pub t2: Translator<f64>,
    pub r4: Motor<f64>,
    pub rg: Motor<f64>,
    pub gripper: Point<f64>,
}

/// The conformal point of `(x, y, z)`.
#[inline(always)]
pub fn point(x: f64, y: f64, z: f64) -> Point<f64> {
    Point { e1: x, e2: y, e3: z, eo: 1.0, einf: 0.5 * (x * x + y * y + z * z) }
}

/// The line through two points: the metric dual `(p ∧ q ∧ einf) I⁻¹` (GATL's `dual`; `I⁻¹ = -I`).
#[inline(always)]
fn line(p: &Point<f64>, q: &Point<f64>) -> Line<f64> {
    p.op(q).op(&Infinity { einf: 1.0 }).gp(&Pseudoscalar { e123oinf: -1.0 })
}

/// The suite's `expp` of a line generator: `1 + x + x²/2 + x³/6 + x⁴/24`, with `x² = acomm(x, x)`
/// (a line's square has no bivector part).
#[inline(always)]
fn taylor4(x: &Line<f64>) -> Motor<f64> {
    let x2: LineSquare<f64> = x.anticommutator(x);
    let x3: Line<f64> = x2.gp(x);
    let x4: LineSquare<f64> = x2.gp(&x2);
    let (c2, c3, c4) = (0.5, 1.0 / 6.0, 1.0 / 24.0);
    Motor {
        scalar: 1.0 + c2 * x2.scalar + c4 * x4.scalar,
        e12: x.e12 + c3 * x3.e12,
        e13: x.e13 + c3 * x3.e13,
        e23: x.e23 + c3 * x3.e23,
        e1inf: x.e1inf + c3 * x3.e1inf,
        e2inf: x.e2inf + c3 * x3.e2inf,
        e3inf: x.e3inf + c3 * x3.e3inf,
        e123inf: c2 * x2.e123inf + c4 * x4.e123inf,
    }
}

/// The suite's `expp` of a translation generator: the same polynomial, whose higher terms
/// vanish by type (`(t einf)² = 0`).
#[inline(always)]
fn taylor4_translation(x: &TranslationLine<f64>) -> Translator<f64> {
    Translator { scalar: 1.0, e1inf: x.e1inf, e2inf: x.e2inf, e3inf: x.e3inf }
}

/// The chain for joint angles `a` and dimensions `g`. Inlined, so that with constant `g` the
/// compiler folds the arm's fixed points and lines (the suite's compile-time geometry).
#[inline(always)]
pub fn chain(a: &[f64; 5], g: &Geometry) -> Chain {
    let [d1, d2, d3, d4, d5] = g.d;
    let (l12, l23) = (g.l12, g.l23);
    let j1 = point(d1, 0.0, d2);
    let j2 = point(d1, 0.0, d2 + l12);
    let j3 = point(d1 + l23, 0.0, d2 + l12 + d3);
    let jg = point(d1 + l23 + d4 + d5, 0.0, d2 + l12 + d3);
    let lz = line(&point(0.0, 0.0, 0.0), &point(0.0, 0.0, 1.0));
    let r1 = taylor4(&(lz * (0.5 * a[0])));
    let l2 = r1.apply(&line(&j1, &point(d1, 1.0, d2)));
    let r2 = taylor4(&(l2 * (0.5 * a[1])));
    let r21 = r2.gp(&r1);
    let j2_f = r21.apply(&j2);
    let l3 = r21.apply(&line(&j2, &point(d1, 1.0, d2 + l12)));
    let r3 = taylor4(&(l3 * (0.5 * a[2])));
    let j2_r = r1.apply(&j2);
    let t2 = Direction { e1: j2_f.e1 - j2_r.e1, e2: j2_f.e2 - j2_r.e2, e3: j2_f.e3 - j2_r.e3 };
    let t2 = taylor4_translation(&(t2.op(&Infinity { einf: 1.0 }) * -0.5));
    let r3t2r1 = r3.gp(&t2).gp(&r1);
    let l4 = line(&j3, &jg);
    let l4 = r3t2r1.apply(&(l4 * (1.0 / l4.sp(&l4.reverse()).scalar.abs().sqrt())));
    let r4 = taylor4(&(l4 * (0.5 * a[3])));
    let r4r3t2r1 = r4.gp(&r3t2r1);
    let lg = r4r3t2r1.apply(&line(&j3, &point(d1 + l23, 1.0, d2 + l12 + d3)));
    let rg = taylor4(&(lg * (0.5 * a[4])));
    let gripper = rg.gp(&r3).gp(&t2).gp(&r1).apply(&jg);
    Chain { r1, r2, r3, t2, r4, rg, gripper }
}
