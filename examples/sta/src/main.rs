//! Spacetime algebra Cl(1,3) at `f64` through the front door `gam-ga`: a Lorentz boost as a
//! rotor `R = cosh(phi/2) + sinh(phi/2) g0 g1` acting on four-vectors by `rev(R) x R`.
//! Run: `cargo run -p gam-example-sta`.

use gam_ga::GeometricProduct;

gam_ga::algebra! {
    /// Spacetime algebra: g0^2 = 1, g1^2 = g2^2 = g3^2 = -1 (generators e0..e3).
    pub mod sta {
        generators { e0, e1, e2, e3 }
        metric { (e0, e0) = 1, (e1, e1) = -1, (e2, e2) = -1, (e3, e3) = -1 }
        types {
            /// Four-vectors `t g0 + x g1 + y g2 + z g3`.
            Vector = grade 1;
            /// Rotors (the even subalgebra): boosts and rotations.
            Rotor = even;
        }
    }
}

use sta::{Rotor, Vector};

/// The boost along `g1` with velocity `v` (|v| < 1, units c = 1).
fn boost(v: f64) -> Rotor<f64> {
    let half = v.atanh() / 2.0;
    let mut r = Rotor::one();
    r.scalar = half.cosh();
    r.e01 = half.sinh();
    r
}

/// `rev(R) x R`, projected back onto vectors.
fn apply(r: &Rotor<f64>, x: &Vector<f64>) -> Vector<f64> {
    r.reverse().gp(x).gp(r).project_to_vector()
}

fn main() {
    let rest = Vector::new(1.0, 0.0, 0.0, 0.0);
    let moving = apply(&boost(0.6), &rest);
    println!("the rest frame's time axis seen at v = 0.6: {moving}");
    println!("its square (proper time, invariant): {}", moving.norm_squared());
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn boost_gives_gamma_and_gamma_v() {
        // By hand, with R = c + s g0g1: rev(R) g0 R = (c^2 + s^2) g0 + 2cs g1
        // = cosh(phi) g0 + sinh(phi) g1; at v = tanh(phi) = 0.6 that is gamma = 1.25 and
        // gamma v = 0.75.
        let x = apply(&boost(0.6), &Vector::new(1.0, 0.0, 0.0, 0.0));
        assert!((x.e0 - 1.25).abs() < 1e-12, "{x}");
        assert!((x.e1 - 0.75).abs() < 1e-12, "{x}");
        assert!(x.e2.abs() < 1e-15 && x.e3.abs() < 1e-15);
        assert!((x.norm_squared() - 1.0).abs() < 1e-12);
    }
}
