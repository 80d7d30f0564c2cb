//! Spacetime algebra Cl(1,3) at `f64` through the front door `gam-ga`: a Lorentz boost as a
//! rotor `R = cosh(phi/2) + sinh(phi/2) g0 g1` acting on four-vectors by `rev(R) x R`, and
//! the same rotor from the generated closed-form `Bivector::exp` (the invariant decomposition:
//! boosts, rotations and their commuting products), with `log` back to the generator.
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
            /// Bivectors: generators of Lorentz transformations (`e01`: a boost along g1).
            Bivector = grade 2;
            /// Rotors (the even subalgebra): boosts and rotations.
            Rotor = even;
        }
    }
}

use sta::{Bivector, Rotor, Vector};

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
    // the same boost as exp(phi/2 g0g1), composed with a rotation in the g2g3 plane that
    // commutes with it (a "loxodromic" rotor), and its logarithm
    let generator = Bivector::e01() * (0.6f64.atanh() / 2.0) + Bivector::e23() * 0.4;
    let rotor = generator.exp();
    println!("exp of {generator}: {rotor}");
    match rotor.log() {
        Ok(back) => println!("and its log: {back}"),
        Err(e) => println!("no logarithm: {e}"),
    }
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

    #[test]
    fn closed_form_exp_is_the_boost_and_log_inverts_it() {
        let half = 0.6f64.atanh() / 2.0;
        let r = (Bivector::e01() * half).exp();
        let b = boost(0.6);
        assert!(r.iter().zip(b.iter()).all(|(x, y)| (x - y).abs() < 1e-15), "{r} vs {b}");
        // a boost and a commuting rotation: exp against the runtime series, log back
        let g = Bivector::e01() * half + Bivector::e23() * 0.4;
        let series = Rotor::project(&g.to_multivector().exp().unwrap());
        assert!(g.exp().iter().zip(series.iter()).all(|(x, y)| (x - y).abs() < 1e-13));
        let back = g.exp().log().unwrap();
        assert!(back.iter().zip(g.iter()).all(|(x, y)| (x - y).abs() < 1e-13), "{back}");
    }
}
