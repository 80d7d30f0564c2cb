//! A game's 2D projective geometric algebra at `f32`, through the front door `gam-ga` only.
//!
//! Points are `P = e12 + x e20 + y e01` (grade 2); a motor `M` (even) moves them by the
//! sandwich `rev(M) P M`. Run: `cargo run -p gam-example-game-pga`.

use gam_ga::GeometricProduct;

gam_ga::algebra! {
    /// R(2,0,1): e0^2 = 0, e1^2 = e2^2 = 1.
    pub mod pga2 {
        generators { e0, e1, e2 }
        metric { (e1, e1) = 1, (e2, e2) = 1 }
        types {
            /// Points (grade 2).
            Point = grade 2;
            /// Motors: rotations and translations (the even subalgebra).
            Motor = even;
        }
    }
}

use pga2::{Motor, Point};

/// The point `(x, y)`: `e12 + x e20 + y e01` (field `e02` holds `-x`).
fn point(x: f32, y: f32) -> Point<f32> {
    Point::new(y, -x, 1.0)
}

/// The coordinates of a (normalised) point.
fn coords(p: &Point<f32>) -> (f32, f32) {
    (-p.e02 / p.e12, p.e01 / p.e12)
}

/// The translation by `(dx, dy)`: `T = 1 + (dx e01 + dy e02)/2`; `rev(T) P T` moves `P` by
/// `(dx, dy)` (expanded by hand in the tests).
fn translator(dx: f32, dy: f32) -> Motor<f32> {
    Motor::new(1.0, dx / 2.0, dy / 2.0, 0.0)
}

/// The rotation by `angle` about the origin: `cos(a/2) + sin(a/2) e12`.
fn rotor(angle: f32) -> Motor<f32> {
    let (s, c) = (angle / 2.0).sin_cos();
    Motor::new(c, 0.0, 0.0, s)
}

/// Moves a point by a motor: the sandwich, projected back onto points.
fn apply(m: &Motor<f32>, p: &Point<f32>) -> Point<f32> {
    m.reverse().gp(p).gp(m).project_to_point()
}

fn main() {
    // a sprite's corners, rotated a quarter turn then moved by (3, 1)
    let motion = rotor(std::f32::consts::FRAC_PI_2).gp(&translator(3.0, 1.0));
    for (x, y) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
        let (u, v) = coords(&apply(&motion, &point(x, y)));
        println!("({x}, {y}) -> ({u:.3}, {v:.3})");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: (f32, f32), b: (f32, f32)) -> bool {
        (a.0 - b.0).abs() < 1e-6 && (a.1 - b.1).abs() < 1e-6
    }

    #[test]
    fn translation_moves_points_by_the_offset() {
        // by hand: rev(T) e12 T = e12 - dx e02 + dy e01 for T = 1 + dx/2 e01 + dy/2 e02
        assert_eq!(apply(&translator(3.0, 1.0), &point(0.0, 0.0)), Point::new(1.0, -3.0, 1.0));
        assert!(close(coords(&apply(&translator(3.0, 1.0), &point(2.0, -1.0))), (5.0, 0.0)));
    }

    #[test]
    fn quarter_turn_then_translation() {
        let motion = rotor(std::f32::consts::FRAC_PI_2).gp(&translator(3.0, 1.0));
        // (1, 0) turns to (0, 1) (counter-clockwise), then moves to (3, 2)
        assert!(close(coords(&apply(&motion, &point(1.0, 0.0))), (3.0, 2.0)));
        assert!(close(coords(&apply(&motion, &point(0.0, 1.0))), (2.0, 1.0)));
    }
}
