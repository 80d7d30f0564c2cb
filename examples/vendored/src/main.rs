//! Vendored kernels: `src/kernels.rs` was written by
//! `cargo run --release -p gam -- codegen --standalone --algebra g3 --types "Vector=grade1;Rotor=even"`
//! and this crate has no dependencies. Rotors of Euclidean 3-space at `f32` rotate vectors by
//! `R v rev(R)` (`apply`, the action the file keeps by default). Run: `cargo run -p gam-example-vendored`.

#[rustfmt::skip] // kept byte-for-byte as generated (the CLI test compares it)
mod kernels;

use kernels::{Rotor, Vector};

/// The rotor of the rotation by `angle` in the plane `e12` (about `e3`, from `e1` towards
/// `e2`): `R = exp(-angle/2 e12) = cos(angle/2) - sin(angle/2) e12`, acting as `R v rev(R)`.
fn rotor_about_e3(angle: f32) -> Rotor<f32> {
    let (s, c) = (angle / 2.0).sin_cos();
    Rotor::new(c, -s, 0.0, 0.0)
}

/// `R v rev(R)` in one fused kernel (the `Apply` of the file), and the same as two geometric
/// products projected onto vectors: `R rev(R) = 1` makes the other grades vanish.
fn rotate(r: &Rotor<f32>, v: &Vector<f32>) -> Vector<f32> {
    r.apply(v)
}

fn main() {
    let r = rotor_about_e3(std::f32::consts::FRAC_PI_2);
    let v = Vector::new(1.0, 0.0, 0.0);
    println!("R e1 rev(R) = {}", rotate(&r, &v));
    println!("R^-1 = {}", r.inverse().expect("a unit rotor is invertible"));
}

#[cfg(test)]
mod tests {
    use super::*;
    use kernels::GeometricProduct;

    #[test]
    fn quarter_turn_about_e3() {
        // By hand, R = c - s e12: R e1 rev(R) = (c^2 - s^2) e1 + 2cs e2 = cos(a) e1 + sin(a) e2.
        let w = rotate(&rotor_about_e3(std::f32::consts::FRAC_PI_2), &Vector::new(1.0, 0.0, 0.0));
        assert!((w.e1).abs() < 1e-6 && (w.e2 - 1.0).abs() < 1e-6 && w.e3.abs() < 1e-6, "{w}");
    }

    #[test]
    fn the_fused_action_is_the_two_products() {
        // R v rev(R) through the generated geometric product, then rev(R) by hand
        let (r, v) = (rotor_about_e3(0.3), Vector::new(0.5, -1.0, 2.0));
        let rv = r.gp(&v);
        // R v is odd (vector and trivector parts); (R v) rev(R) = (R v)(c - s e12) by components
        let (c, s) = (r.scalar, r.e12);
        let x = c * rv.e1 + s * rv.e2;
        let y = c * rv.e2 - s * rv.e1;
        let w = rotate(&r, &v);
        assert!((w.e1 - x).abs() < 1e-6 && (w.e2 - y).abs() < 1e-6 && (w.e3 - 2.0).abs() < 1e-6, "{w}");
    }

    #[test]
    fn inverse_is_the_reverse_for_a_unit_rotor() {
        let r = rotor_about_e3(0.7);
        let inv = r.inverse().unwrap();
        let rev = r.reverse();
        assert!((inv.scalar - rev.scalar).abs() < 1e-6 && (inv.e12 - rev.e12).abs() < 1e-6, "{inv} {rev}");
        assert_eq!(Rotor::<f32>::new(0.0, 0.0, 0.0, 0.0).inverse().unwrap_err().to_string(), "0 is not invertible");
    }
}
