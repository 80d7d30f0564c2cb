//! Trajectories of body points under the main paper's additive Bézier motions
//! (`S(t) = Σ b_i^n(t) S_i`, its eq. (18)) as rational Bézier curves of degree `2n` (6 for a
//! cubic): the projective action `F_S(x) = (A x + t, α)` (its eqs. (6)-(9),
//! [`Pose::apply_homogeneous`]) is a quadratic form `Y(S)` in the eight coefficients of `S`,
//! so along `S(t)` it is a product of two Bézier polynomials of degree `n`, and the product
//! formula (29) (Jüttler) gives its homogeneous control points
//! `H_k = Σ_{i+j=k} C(n,i) C(n,j)/C(2n,k) Y(S_i, S_j)` with the polar form
//! `Y(S, T) = (Y(S + T) - Y(S) - Y(T))/2`. Exact over rationals, for any control poses (unit or
//! not, with or without an `e123∞` part).
//!
//! ```
//! use algebra_core::rational::{q, ratio};
//! use motion::{AdditiveBezier, Motion, Pose, juttler::RationalMotion};
//! let m = AdditiveBezier::new(vec![
//!     Pose::identity(),
//!     Pose::rotor_from_parts(&q(1), &q(1), &[q(0), q(0), q(1)]),
//!     Pose::translation(&[q(2), q(0), q(1)]),
//! ]).unwrap();
//! let x = [q(1), q(2), q(3)];
//! let path = m.rational_trajectory(&x).unwrap();
//! assert_eq!(path.degree(), 4);
//! let t = ratio(1, 3);
//! assert_eq!(path.point(&t).unwrap(), m.evaluate(&t).unwrap().transform_point(&x).unwrap());
//! ```

use super::{JuttlerError, RationalBezier, RationalMotion, bernstein_product};
use crate::{AdditiveBezier, Pose};
use algebra_core::Ring;

/// `F_S` on the point `x` as homogeneous coordinates, weight first: `(α, A x + t)`.
fn image<T: Ring>(s: &Pose<T>, x: &[T; 4]) -> [T; 4] {
    let [a, b, c, w] = s.apply_homogeneous(x);
    [w, a, b, c]
}

/// The polar form `Y(S, T)` of the quadratic action on the point `x` (homogeneous, `w` last as
/// in [`Pose::apply_homogeneous`]); `Y(S, S) = Y(S)`.
fn polar<T: Ring>(s: &Pose<T>, t: &Pose<T>, x: &[T; 4]) -> [T; 4] {
    let half = T::from_ratio(1, 2);
    let (st, ss, tt) = (image(&(s.clone() + t.clone()), x), image(s, x), image(t, x));
    std::array::from_fn(|k| st[k].sub_ref(&ss[k]).sub_ref(&tt[k]).mul_ref(&half))
}

/// The trajectory of the body point `x` under the additive Bézier motion as a rational Bézier
/// curve of degree `2n` on `[0, 1]` (module docs): exact over rationals; its point at `t` is
/// `F_{S(t)}(x)` wherever `S(t)` is not singular. Never fails (a Bézier motion has a pose).
///
/// ```
/// use algebra_core::rational::{q, ratio};
/// use motion::{AdditiveBezier, Pose, juttler::RationalMotion};
/// // a translation from 0 to (2, 0, 0): the trajectory is a line, weights 1
/// let m = AdditiveBezier::new(vec![Pose::identity(), Pose::translation(&[q(2), q(0), q(0)])]).unwrap();
/// let path = m.rational_trajectory(&[q(0), q(0), q(0)]).unwrap();
/// assert_eq!(path.weights(), [q(1), q(1), q(1)]);
/// assert_eq!(path.point(&ratio(1, 4)).unwrap(), [ratio(1, 2), q(0), q(0)]);
/// ```
impl<T: Ring> RationalMotion<T> for AdditiveBezier<T> {
    fn rational_trajectory(&self, x: &[T; 3]) -> Result<RationalBezier<T>, JuttlerError> {
        let h = [x[0].clone(), x[1].clone(), x[2].clone(), T::one()];
        let control = bernstein_product(
            self.poses(),
            self.poses(),
            std::array::from_fn(|_| T::zero()),
            |a, b| polar(a, b, &h),
            |acc: &[T; 4], y: &[T; 4], f: &T| std::array::from_fn(|k| acc[k].add_ref(&y[k].mul_ref(f))),
        );
        RationalBezier::new(control)
    }
}
