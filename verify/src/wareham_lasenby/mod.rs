//! Wareham and Lasenby, "Rigid-body pose and position interpolation using geometric algebra":
//! Lemmas 1-2, Theorem 3, Lemmas 5-6, Theorems 7-9.
//!
//! Conventions: the runtime algebra `cga` = R^{4,1} with e1, e2, e3 Euclidean, the paper's
//! e = e4 (e² = 1) and ē = e5 (ē² = -1), so n = e + ē = e4 + e5 and n̄ = e - ē = e4 - e5;
//! F(x) = (x² n + 2x - n̄)/2. A unit plane is P = P_u/N with P_u the plane of the Pythagorean
//! normal (2uw, 2vw, u² + v² - w²) and N = u² + v² + w², so symbolic u, v, w cover every plane
//! and φP = φ0 P_u (φ = N φ0) stays polynomial.
//!
//! What is compared:
//! * `lemma-1` (symbolic): B^k by repeated products against the stated form with the α's from
//!   the recurrences, k = 0..7, fully symbolic φ, P, t; a counterexample with the non-Euclidean
//!   blade P = e14.
//! * `lemma-2` (symbolic): α1 = α2 = 0 and the closed form of α4 (k <= 14); B^(2k), B^(2k+1)
//!   for k <= 3; and the induction step with a symbolic k (so it holds for all k).
//! * `theorem-3` (symbolic, then mpfr-256): the proof's identities tnP + Ptn = 2P t_perp n and
//!   PtnP = (t_par - t_perp) n; the closed form G(λ) at (λφ, λt) solves G' = B G, G(0) = 1
//!   (symbolic c = cos λφ, s = sin λφ with c' = -φs, s' = φc), which characterises exp(λB);
//!   and the closed form against the runtime exp (scaling and squaring) and the Taylor series
//!   to 70 digits.
//! * `lemma-5` (symbolic, exact, mpfr-256): rev(τ) τ = cos² + sin² and Lemma 5's form equals
//!   eq. (2) with symbolic cos, sin, sinc, P, t; exactly on rational points of the circle also
//!   eq. (2) = Theorem 3 at (ψ/2, t/2); and against the runtime exp at 256 bits.
//! * `lemma-6` (symbolic, exact, mpfr-256): the expression equals the translator
//!   1 + n t'_par/2 with t'_par a vector in the plane; exactly, it maps F(y) to F(y + t'_par);
//!   the sign of the prose after it.
//! * `theorem-7`, `theorem-8` (symbolic): R rev(R) = cos² + sin² and R n rev(R) = (cos² + sin²) n
//!   for Theorem 3's form with symbolic cos, sin, sinc, P, t; runtime exp(B) at 256 bits; a
//!   counterexample to Theorem 8 for the non-Euclidean P = e14.
//! * `theorem-9` (mpfr-256): ℓ(R) from the paper's formulas against B, exp(ℓ(R)) = R and the
//!   runtime log; counterexamples at ||ab|| = 0 and π.
//! * The library (`motion::wareham_lasenby`, library.rs) against these typed-in formulas in
//!   `theorem-3` (exp), `theorem-9` (log, and its edge cases by the runtime exp) and `lemma-6`
//!   (rotor of a pose, the Sec. 4.1 helix by the runtime exp).

mod common;
mod library;
mod motion;
pub(crate) mod powers;

use crate::{Method, Paper, Statement};

/// The statements of this paper, in paper order.
pub const STATEMENTS: &[Statement] = &[
    Statement {
        id: "wareham-lasenby/lemma-1",
        paper: Paper::WarehamLasenby,
        label: "Lemma 1",
        statement: "for B = φP + tn (t in R^3, P a 2-blade with P² = -1) and k >= 0: B^k = φ^k P^k + α1_k φPtn + \
                    α2_k φ² PtnP + α3_k φ tnP + α4_k tn with α1_k = -φ² α2_(k-1), α2_k = α1_(k-1), α3_k = α4_(k-1), \
                    α4_k = φ^(k-1) P^(k-1) - φ² α3_(k-1), all α_0 = 0",
        method: Method::Symbolic,
        hypotheses: "P must be Euclidean (P n = n P, from Sec. 2.3), not just P² = -1: fails for P = e1 e; the α's \
                     are multivector-valued (left factors)",
        check: powers::lemma_1,
    },
    Statement {
        id: "wareham-lasenby/lemma-2",
        paper: Paper::WarehamLasenby,
        label: "Lemma 2",
        statement: "B^(2k) = (-1)^k φ^(2k) - k (-1)^k φ^(2k-1) [tnP + Ptn] and B^(2k+1) = (-1)^k φ^(2k+1) P + \
                    k φ^(2k) (-1)^k [tn - PtnP] + (-1)^k φ^(2k) tn",
        method: Method::Symbolic,
        hypotheses: "",
        check: powers::lemma_2,
    },
    Statement {
        id: "wareham-lasenby/theorem-3",
        paper: Paper::WarehamLasenby,
        label: "Theorem 3",
        statement: "exp(φP + tn) = [cos φ + sin φ P][1 + t_perp n] + sinc(φ) t_par n, t_par the component of t in \
                    the plane of P and t_perp = t - t_par",
        method: Method::Symbolic,
        hypotheses: "",
        check: powers::theorem_3,
    },
    Statement {
        id: "wareham-lasenby/lemma-5",
        paper: Paper::WarehamLasenby,
        label: "Lemma 5",
        statement: "exp(ψ/2 P + tn/2) = [1 + sinc(ψ/2) t_par n/2 rev(τ(ψ, P, -t_perp))] τ(ψ, P, -t_perp) with the \
                    twist τ(ψ, P, a) = [cos(ψ/2) + sin(ψ/2) P][1 + na/2]",
        method: Method::Symbolic,
        hypotheses: "",
        check: motion::lemma_5,
    },
    Statement {
        id: "wareham-lasenby/lemma-6",
        paper: Paper::WarehamLasenby,
        label: "Lemma 6",
        statement: "1 + sinc(ψ/2) t_par n/2 rev(τ(ψ, P, -t_perp)) is a rotor translating along \
                    t'_par = -sinc(ψ/2) t_par (cos(ψ/2) - sin(ψ/2) P)",
        method: Method::Symbolic,
        hypotheses: "",
        check: motion::lemma_6,
    },
    Statement {
        id: "wareham-lasenby/theorem-7",
        paper: Paper::WarehamLasenby,
        label: "Theorem 7",
        statement: "R = exp(B), B of the form of Lemma 1, satisfies R rev(R) = 1",
        method: Method::Symbolic,
        hypotheses: "",
        check: motion::theorem_7,
    },
    Statement {
        id: "wareham-lasenby/theorem-8",
        paper: Paper::WarehamLasenby,
        label: "Theorem 8",
        statement: "R = exp(B), B of the form of Lemma 1, satisfies R n rev(R) = n",
        method: Method::Symbolic,
        hypotheses: "P Euclidean (P n = n P): fails for P = e1 e although P² = -1",
        check: motion::theorem_8,
    },
    Statement {
        id: "wareham-lasenby/theorem-9",
        paper: Paper::WarehamLasenby,
        label: "Theorem 9",
        statement: "ℓ(R) = ab + c_perp n + c_par n with ||ab|| = acos<R>_0, ab = (<R>_2 n)·e / sinc||ab||, \
                    c_perp n = -ab <R>_4 / (||ab||² sinc||ab||), c_par n = -ab <ab <R>_2>_2 / (||ab||² sinc||ab||) \
                    satisfies exp(ℓ(R)) = R",
        method: Method::MpFloat,
        hypotheses: "0 < ||ab|| < π (<R>_0 in (-1, 1)): the formulas are 0/0 for a pure translation and give 0 for \
                     ||ab|| = π; ℓ(exp B) = B only for 0 < |φ| < π",
        check: motion::theorem_9,
    },
];
