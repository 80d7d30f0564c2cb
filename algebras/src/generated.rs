//! The `algebra!` declarations of the predefined algebras. Everything inside each module is
//! generated at compile time; see `algebra_codegen` for what each type gets.

use algebra_macros::algebra;

#[cfg(feature = "g3")]
algebra! {
    /// Euclidean 3-space R^3 (labels 1, 2, 3).
    pub mod g3 {
        derive serde;
        metric builtin "g3";
        types {
            /// Scalars.
            Scalar = grade 0;
            /// Vectors.
            Vector = grade 1;
            /// Bivectors.
            Bivector = grade 2;
            /// The pseudoscalar.
            Trivector = grade 3;
            /// Rotors: the even subalgebra (quaternions).
            Rotor = even;
            /// Every element.
            Multivector = all;
        }
    }
}

algebra! {
    /// The main paper's G_{123inf} (labels 1, 2, 3, inf; einf^2 = 0). Its even subalgebra is
    /// the paper's poses and is isomorphic to the dual quaternions (Appendix 2).
    pub mod g123inf {
        derive serde;
        metric builtin "g123inf";
        types {
            /// Vectors.
            Vector = grade 1;
            /// Bivectors (velocity bivectors nu = Omega e123 + u einf live here).
            Bivector = grade 2;
            /// Pseudoscalars `alpha + beta omega` (omega = e123inf), eq. (5).
            Pseudoscalar = [1, e123inf];
            /// Poses: the even subalgebra G_{123inf}^+ in the paper's order (eq. 4). `where unit`
            /// adds the `*_unit_*` kernels, valid for unit poses only (rev(S) S = 1).
            Motor = [1, e12, e13, e23, e1inf, e2inf, e3inf, e123inf] where unit;
            /// Every element.
            Multivector = all;
        }
    }
}

#[cfg(feature = "pga3")]
algebra! {
    /// Projective geometric algebra R^{3,0,1} (labels 0, 1, 2, 3; e0^2 = 0).
    pub mod pga3 {
        derive serde;
        metric builtin "pga3";
        types {
            /// Vectors (planes).
            Vector = grade 1;
            /// Bivectors (lines).
            Bivector = grade 2;
            /// Trivectors (points).
            Trivector = grade 3;
            /// Motors: the even subalgebra. `where unit` adds the `*_unit_*` kernels, valid for
            /// unit motors only (rev(M) M = 1).
            Motor = even where unit;
            /// Every element.
            Multivector = all;
        }
    }
}

algebra! {
    /// Conformal geometric algebra R^{4,1} (labels 1..5; e4^2 = 1, e5^2 = -1), as in
    /// Wareham and Lasenby.
    pub mod cga {
        derive serde;
        metric builtin "cga";
        // closed_form_cga.rs keeps its hand-written exp/log (Result-returning, the displacement
        // subalgebra through g123inf); the generated invariant-decomposition forms would collide
        closed_forms off;
        // straight-line kernels up to 256 terms (the 16 x 16 motor product, the motor's actions):
        // 4.7-6.4 x faster at f64 than the table loop (docs/performance.md, "Size policy threshold")
        table_above 256;
        types {
            /// Vectors (points, spheres, planes).
            Vector = grade 1;
            /// Bivectors (generators of rotors and translators).
            Bivector = grade 2;
            /// Versors of even grade: rotors, translators, motors.
            Motor = even;
            /// Odd versors.
            OddVersor = odd;
            /// Every element.
            Multivector = all;
        }
    }
}

#[cfg(feature = "cga-null")]
algebra! {
    /// The main paper's G_{0123inf} in its product basis (e0 . einf = -1, e0^2 = einf^2 = 0):
    /// basis elements are geometric products of generators.
    pub mod cga_null {
        derive serde;
        metric builtin "cga-null";
        basis product;
        types {
            /// Vectors.
            Vector = grade 1;
            /// Poses of G_{123inf}^+ inside G_{0123inf}. `where unit` adds the `*_unit_*`
            /// kernels, valid for unit poses only (rev(S) S = 1).
            Motor = [1, e12, e13, e23, e1inf, e2inf, e3inf, e123inf] where unit;
            /// The bivectors of the poses, `Omega e123 + u einf` (the Lie algebra of `Motor`:
            /// `PoseBivector::exp` is a `Motor`, `Motor::log` a `PoseBivector`).
            PoseBivector = [e12, e13, e23, e1inf, e2inf, e3inf];
            /// Every element.
            Multivector = all;
        }
    }
}
