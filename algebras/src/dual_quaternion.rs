//! Dual quaternions, hand-written, and their isomorphism with the paper's poses
//! `G_{123inf}^+` (the generated [`g123inf::Motor`]).
//!
//! # Conventions
//!
//! * Quaternions are Hamilton's: `w + x i + y j + z k` with `i^2 = j^2 = k^2 = ijk = -1`
//!   (so `ij = k`, `jk = i`, `ki = j`). [`Quaternion`] stores `(w, x, y, z)` in that order.
//! * A dual quaternion is `q = r + ε d` with `ε^2 = 0` and `ε` commuting with everything;
//!   `r` is the *real* part and `d` the *dual* part. The product is
//!   `(r1 + ε d1)(r2 + ε d2) = r1 r2 + ε (r1 d2 + d1 r2)`: 48 multiplications and 40 additions,
//!   the same kernel as nalgebra's `DualQuaternion`.
//! * Conjugates: the *quaternion* conjugate `q* = r* + ε d*`, the *dual* conjugate
//!   `r - ε d`, and *both* `r* - ε d*`. The quaternion conjugate and the combined conjugate
//!   reverse products; the dual conjugate is an automorphism.
//! * A rigid motion `p -> R p + t` is the unit dual quaternion `q = r + ε (1/2) t r` acting on
//!   the point `p^ = 1 + ε p` by `p^ -> q p^ (r* - ε d*)` ("both" conjugate), so that `q2 q1`
//!   is `q1` followed by `q2` (see [`DualQuaternion::transform_point`]).
//!
//! # The isomorphism of the paper's Appendix 2
//!
//! Cross, Cripps and Mullineux (2022), Appendix 2, pair the basis of `G_{123inf}^+` with
//! dual quaternions (with `ω = e123inf`):
//!
//! ```text
//! 1     <-> 1          ω     <-> ε
//! e12   <-> -k         e1inf <-> ε i
//! e13   <-> +j         e2inf <-> ε j
//! e23   <-> -i         e3inf <-> ε k
//! ```
//!
//! so `phi(S) = (S_0 - S_23 i + S_13 j - S_12 k) + ε (S_ω + S_1inf i + S_2inf j + S_3inf k)`.
//! With GAM's g123inf conventions (`e1^2 = e2^2 = e3^2 = 1`, `einf^2 = 0`, so
//! `e12^2 = e13^2 = e23^2 = -1`, `e23 e13 = e12`, `e12 e3inf = ω`) the printed map is, sign for
//! sign, an **algebra homomorphism** (`phi(ab) = phi(a) phi(b)`), hence an isomorphism of
//! `G_{123inf}^+` onto the dual quaternions: no sign had to be changed. It is implemented by
//! `From<&Motor<T>> for DualQuaternion<T>` and back, and is checked exactly over rationals in
//! `tests/dual_quaternion.rs`. Under it
//!
//! * the reverse `rev(S)` is the quaternion conjugate `q*`;
//! * the automorphism `einf -> -einf` is the dual conjugate, and `rev` composed with it is the
//!   combined conjugate;
//! * `rev(S) S = α + β ω` (paper, eq. (5)) is the dual-number norm `q* q = q q*`
//!   ([`DualQuaternion::norm_squared`]);
//! * the velocity bivector `ν = Ω e123 + u einf` is `ε u - Ω`, as the appendix states.
//!
//! # Poses
//!
//! The paper's pose `S` acts by `x -> rev(S) x S` and composes as `F_{UV} = F_V F_U`, while the
//! usual dual quaternion acts by `q p^ q̄` and composes as `q_{V∘U} = q_V q_U`. The dual
//! quaternion of the *same rigid motion* as `S` is therefore not `phi(S)` but its combined
//! conjugate `phi(S)* ` with `ε -> -ε`, an **anti**-isomorphism
//! ([`DualQuaternion::from_pose`], [`DualQuaternion::to_pose`]): e.g. the paper's rotation
//! `R = cos(φ/2) + sin(φ/2) e12` (about `e3`) maps to `cos(φ/2) + sin(φ/2) k`, and its translation
//! `T = 1 + 1/2 v einf` to `1 + ε v/2`.
//!
//! [`g123inf::Motor`]: crate::g123inf::Motor

use crate::g123inf::Motor;
use algebra_core::multivector::display::{format_term, join_terms};
use algebra_core::{Field, Ring};
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};

/// A Hamilton quaternion `w + x i + y j + z k` (`i^2 = j^2 = k^2 = ijk = -1`): the real and
/// dual parts of a [`DualQuaternion`].
///
/// ```
/// use gam_algebras::dual_quaternion::Quaternion;
/// let i = Quaternion::new(0.0, 1.0, 0.0, 0.0);
/// let j = Quaternion::new(0.0, 0.0, 1.0, 0.0);
/// assert_eq!(&i * &j, Quaternion::new(0.0, 0.0, 0.0, 1.0)); // ij = k
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Quaternion<T> {
    /// The scalar part.
    pub w: T,
    /// The coefficient of `i`.
    pub x: T,
    /// The coefficient of `j`.
    pub y: T,
    /// The coefficient of `k`.
    pub z: T,
}

impl<T: Ring> Quaternion<T> {
    /// `w + x i + y j + z k`.
    ///
    /// ```
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// let q = Quaternion::new(1.0, 2.0, 3.0, 4.0);
    /// assert_eq!((q.w, q.x, q.y, q.z), (1.0, 2.0, 3.0, 4.0));
    /// ```
    pub fn new(w: T, x: T, y: T, z: T) -> Self {
        Quaternion { w, x, y, z }
    }

    /// Zero.
    ///
    /// ```
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// assert_eq!(Quaternion::<f64>::zero(), Quaternion::new(0.0, 0.0, 0.0, 0.0));
    /// ```
    pub fn zero() -> Self {
        Quaternion::new(T::zero(), T::zero(), T::zero(), T::zero())
    }

    /// One.
    ///
    /// ```
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// let q = Quaternion::new(1.0, 2.0, 3.0, 4.0);
    /// assert_eq!(&q * &Quaternion::one(), q);
    /// ```
    pub fn one() -> Self {
        Quaternion::new(T::one(), T::zero(), T::zero(), T::zero())
    }

    /// The pure quaternion `x i + y j + z k` of a 3-vector.
    ///
    /// ```
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// assert_eq!(Quaternion::pure(&[1.0, 2.0, 3.0]), Quaternion::new(0.0, 1.0, 2.0, 3.0));
    /// ```
    pub fn pure(v: &[T; 3]) -> Self {
        Quaternion::new(T::zero(), v[0].clone(), v[1].clone(), v[2].clone())
    }

    /// The vector part `(x, y, z)`.
    ///
    /// ```
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// assert_eq!(Quaternion::new(1.0, 2.0, 3.0, 4.0).vector(), [2.0, 3.0, 4.0]);
    /// ```
    pub fn vector(&self) -> [T; 3] {
        [self.x.clone(), self.y.clone(), self.z.clone()]
    }

    /// The conjugate `w - x i - y j - z k` (reverses products).
    ///
    /// ```
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// assert_eq!(Quaternion::new(1.0, 2.0, 3.0, 4.0).conjugate(), Quaternion::new(1.0, -2.0, -3.0, -4.0));
    /// ```
    pub fn conjugate(&self) -> Self {
        Quaternion::new(self.w.clone(), self.x.neg_ref(), self.y.neg_ref(), self.z.neg_ref())
    }

    /// The squared norm `q q* = w^2 + x^2 + y^2 + z^2`.
    ///
    /// ```
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// assert_eq!(Quaternion::new(1.0, 2.0, 3.0, 4.0).norm_squared(), 30.0);
    /// ```
    pub fn norm_squared(&self) -> T {
        self.dot(self)
    }

    /// The Euclidean inner product of the coefficient 4-vectors, `Re(self rhs*)`.
    ///
    /// ```
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// assert_eq!(Quaternion::new(1.0, 2.0, 3.0, 4.0).dot(&Quaternion::new(1.0, 0.0, -1.0, 1.0)), 2.0);
    /// ```
    pub fn dot(&self, rhs: &Self) -> T {
        self.w.mul_ref(&rhs.w) + &self.x.mul_ref(&rhs.x) + &self.y.mul_ref(&rhs.y) + &self.z.mul_ref(&rhs.z)
    }

    /// Every coefficient multiplied by `s`.
    ///
    /// ```
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// assert_eq!(Quaternion::new(1.0, 2.0, 3.0, 4.0).scale(&2.0), Quaternion::new(2.0, 4.0, 6.0, 8.0));
    /// ```
    pub fn scale(&self, s: &T) -> Self {
        Quaternion::new(self.w.mul_ref(s), self.x.mul_ref(s), self.y.mul_ref(s), self.z.mul_ref(s))
    }

    fn map2(&self, rhs: &Self, f: impl Fn(&T, &T) -> T) -> Self {
        Quaternion::new(f(&self.w, &rhs.w), f(&self.x, &rhs.x), f(&self.y, &rhs.y), f(&self.z, &rhs.z))
    }
}

/// The Hamilton product, unrolled: 16 multiplications.
#[inline]
fn hamilton<T: Ring>(a: &Quaternion<T>, b: &Quaternion<T>) -> Quaternion<T> {
    Quaternion {
        w: a.w.mul_ref(&b.w) - &a.x.mul_ref(&b.x) - &a.y.mul_ref(&b.y) - &a.z.mul_ref(&b.z),
        x: a.w.mul_ref(&b.x) + &a.x.mul_ref(&b.w) + &a.y.mul_ref(&b.z) - &a.z.mul_ref(&b.y),
        y: a.w.mul_ref(&b.y) - &a.x.mul_ref(&b.z) + &a.y.mul_ref(&b.w) + &a.z.mul_ref(&b.x),
        z: a.w.mul_ref(&b.z) + &a.x.mul_ref(&b.y) - &a.y.mul_ref(&b.x) + &a.z.mul_ref(&b.w),
    }
}

/// `a + b`, reusing `a`'s storage.
#[inline]
fn sum<T: Ring>(a: Quaternion<T>, b: &Quaternion<T>) -> Quaternion<T> {
    Quaternion { w: a.w + &b.w, x: a.x + &b.x, y: a.y + &b.y, z: a.z + &b.z }
}

impl<T: Ring> Mul<&Quaternion<T>> for &Quaternion<T> {
    type Output = Quaternion<T>;
    /// The Hamilton product.
    ///
    /// ```
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// let j = Quaternion::new(0.0, 0.0, 1.0, 0.0);
    /// let k = Quaternion::new(0.0, 0.0, 0.0, 1.0);
    /// assert_eq!(&j * &k, Quaternion::new(0.0, 1.0, 0.0, 0.0)); // jk = i
    /// ```
    fn mul(self, rhs: &Quaternion<T>) -> Quaternion<T> {
        hamilton(self, rhs)
    }
}

impl<T: Ring> Mul for Quaternion<T> {
    type Output = Quaternion<T>;
    /// The Hamilton product.
    ///
    /// ```
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// let k = Quaternion::new(0.0, 0.0, 0.0, 1.0);
    /// assert_eq!(k.clone() * k, Quaternion::new(-1.0, 0.0, 0.0, 0.0));
    /// ```
    fn mul(self, rhs: Quaternion<T>) -> Quaternion<T> {
        hamilton(&self, &rhs)
    }
}

impl<T: Ring> fmt::Display for Quaternion<T> {
    /// `1 + 2*i - 3*k`; `0` for zero.
    ///
    /// ```
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// assert_eq!(Quaternion::new(1.0, 2.0, 0.0, -3.0).to_string(), "1 + 2*i - 3*k");
    /// ```
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let terms = [("1", &self.w), ("i", &self.x), ("j", &self.y), ("k", &self.z)];
        f.write_str(&join_terms(
            terms.iter().filter(|(_, c)| !c.is_exact_zero()).map(|(n, c)| format_term(&c.to_string(), n)),
        ))
    }
}

/// A dual quaternion `q = r + ε d` (`ε^2 = 0`, Hamilton quaternions `r`, `d`); see the
/// [module documentation](self) for the conventions and the isomorphism with
/// [`g123inf::Motor`](crate::g123inf::Motor).
///
/// ```
/// use gam_algebras::DualQuaternion;
/// use gam_algebras::dual_quaternion::Quaternion;
/// use algebra_core::rational::{Q, q, ratio};
/// // a rotation by π about z, then a translation by (2, 0, 0)
/// let rot = DualQuaternion::from_real(Quaternion::new(q(0), q(0), q(0), q(1)));
/// let tr = DualQuaternion::from_translation(&[q(2), q(0), q(0)]);
/// let motion = &tr * &rot;
/// assert_eq!(motion.transform_point(&[q(1), q(1), q(0)]).unwrap(), [q(1), q(-1), q(0)]);
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct DualQuaternion<T> {
    /// The real part `r`.
    pub real: Quaternion<T>,
    /// The dual part `d` (the coefficient of `ε`).
    pub dual: Quaternion<T>,
}

impl<T: Ring> DualQuaternion<T> {
    /// `real + ε dual`.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// let q = DualQuaternion::new(Quaternion::new(1.0, 0.0, 0.0, 0.0), Quaternion::new(0.0, 1.0, 2.0, 3.0));
    /// assert_eq!(q.to_string(), "1 + ε*i + 2*ε*j + 3*ε*k");
    /// ```
    pub fn new(real: Quaternion<T>, dual: Quaternion<T>) -> Self {
        DualQuaternion { real, dual }
    }

    /// From the eight coefficients `(r_w, r_x, r_y, r_z, d_w, d_x, d_y, d_z)`.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// let q = DualQuaternion::from_coeffs([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]);
    /// assert_eq!((q.real.z, q.dual.w), (4.0, 5.0));
    /// ```
    pub fn from_coeffs(c: [T; 8]) -> Self {
        let [rw, rx, ry, rz, dw, dx, dy, dz] = c;
        DualQuaternion::new(Quaternion::new(rw, rx, ry, rz), Quaternion::new(dw, dx, dy, dz))
    }

    /// The eight coefficients `(r_w, r_x, r_y, r_z, d_w, d_x, d_y, d_z)`.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// let c = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0];
    /// assert_eq!(DualQuaternion::from_coeffs(c).coeffs(), c);
    /// ```
    pub fn coeffs(&self) -> [T; 8] {
        let (r, d) = (&self.real, &self.dual);
        [r.w.clone(), r.x.clone(), r.y.clone(), r.z.clone(), d.w.clone(), d.x.clone(), d.y.clone(), d.z.clone()]
    }

    /// Zero.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// assert_eq!(DualQuaternion::<f64>::zero().to_string(), "0");
    /// ```
    pub fn zero() -> Self {
        DualQuaternion::new(Quaternion::zero(), Quaternion::zero())
    }

    /// One (the identity motion).
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// let q = DualQuaternion::from_coeffs([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]);
    /// assert_eq!(&q * &DualQuaternion::one(), q);
    /// ```
    pub fn one() -> Self {
        DualQuaternion::new(Quaternion::one(), Quaternion::zero())
    }

    /// `r + ε 0`: for a unit `r`, the rotation `p -> r p r*`.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// let q = DualQuaternion::from_real(Quaternion::new(1.0, 2.0, 3.0, 4.0));
    /// assert_eq!(q.dual, Quaternion::zero());
    /// ```
    pub fn from_real(real: Quaternion<T>) -> Self {
        DualQuaternion::new(real, Quaternion::zero())
    }

    /// The dual number `a + ε b` (a dual quaternion with zero vector parts).
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// assert_eq!(DualQuaternion::dual_number(2.0, 3.0).to_string(), "2 + 3*ε");
    /// ```
    pub fn dual_number(a: T, b: T) -> Self {
        DualQuaternion::new(
            Quaternion::new(a, T::zero(), T::zero(), T::zero()),
            Quaternion::new(b, T::zero(), T::zero(), T::zero()),
        )
    }

    /// The translation by `t`: `1 + ε (t_x i + t_y j + t_z k)/2`.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// use algebra_core::rational::{q, ratio};
    /// let t = DualQuaternion::from_translation(&[q(1), q(0), q(0)]);
    /// assert_eq!(t.to_string(), "1 + 1/2*ε*i");
    /// ```
    pub fn from_translation(t: &[T; 3]) -> Self {
        let half = T::from_ratio(1, 2);
        DualQuaternion::new(Quaternion::one(), Quaternion::pure(t).scale(&half))
    }

    /// The embedded point `1 + ε (p_x i + p_y j + p_z k)`.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// assert_eq!(DualQuaternion::from_point(&[1.0, 2.0, 3.0]).to_string(), "1 + ε*i + 2*ε*j + 3*ε*k");
    /// ```
    pub fn from_point(p: &[T; 3]) -> Self {
        DualQuaternion::new(Quaternion::one(), Quaternion::pure(p))
    }

    /// The quaternion conjugate `q* = r* + ε d*` (reverses products; the image of the reverse
    /// of the paper's `G_{123inf}^+`).
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// let q = DualQuaternion::from_coeffs([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]);
    /// assert_eq!(q.conjugate(), DualQuaternion::from_coeffs([1.0, -2.0, -3.0, -4.0, 5.0, -6.0, -7.0, -8.0]));
    /// ```
    pub fn conjugate(&self) -> Self {
        DualQuaternion::new(self.real.conjugate(), self.dual.conjugate())
    }

    /// The dual conjugate `r - ε d` (an automorphism; the image of `einf -> -einf`).
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// let q = DualQuaternion::from_coeffs([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]);
    /// assert_eq!(q.dual_conjugate(), DualQuaternion::from_coeffs([1.0, 2.0, 3.0, 4.0, -5.0, -6.0, -7.0, -8.0]));
    /// ```
    pub fn dual_conjugate(&self) -> Self {
        DualQuaternion::new(
            self.real.clone(),
            Quaternion::new(self.dual.w.neg_ref(), self.dual.x.neg_ref(), self.dual.y.neg_ref(), self.dual.z.neg_ref()),
        )
    }

    /// Both conjugates at once, `r* - ε d*` (reverses products): a unit `q` maps the point
    /// `1 + ε p` to `q (1 + ε p) (r* - ε d*)`.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// let q = DualQuaternion::from_coeffs([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]);
    /// assert_eq!(q.conjugate_both(), DualQuaternion::from_coeffs([1.0, -2.0, -3.0, -4.0, -5.0, 6.0, 7.0, 8.0]));
    /// ```
    pub fn conjugate_both(&self) -> Self {
        DualQuaternion::new(
            self.real.conjugate(),
            Quaternion::new(self.dual.w.neg_ref(), self.dual.x.clone(), self.dual.y.clone(), self.dual.z.clone()),
        )
    }

    /// The squared norm, a dual number `(a, b)` meaning `a + ε b`:
    /// `q q* = r r* + ε (r d* + d r*) = |r|^2 + ε 2 (r · d)` (equal to `q* q`). It is the image
    /// of the paper's `rev(S) S = α + β ω` (eq. (5)); `q` is a unit dual quaternion when it is
    /// `(1, 0)`.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// let q = DualQuaternion::from_coeffs([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]);
    /// assert_eq!(q.norm_squared(), (30.0, 2.0 * (5.0 + 12.0 + 21.0 + 32.0)));
    /// let n = &q * &q.conjugate();
    /// assert_eq!(n, DualQuaternion::dual_number(30.0, 140.0));
    /// ```
    pub fn norm_squared(&self) -> (T, T) {
        let rd = self.real.dot(&self.dual);
        (self.real.norm_squared(), rd.add_ref(&rd))
    }

    /// Every coefficient multiplied by `s`.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// let q = DualQuaternion::from_coeffs([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]);
    /// assert_eq!(q.scale(&-1.0), -q);
    /// ```
    pub fn scale(&self, s: &T) -> Self {
        DualQuaternion::new(self.real.scale(s), self.dual.scale(s))
    }

    /// The image of the paper's pose `S` (acting by `x -> rev(S) x S`) as the dual quaternion of
    /// the **same rigid motion** in the usual convention (`p^ -> q p^ (r* - ε d*)`,
    /// `q_{V∘U} = q_V q_U`): `q = conjugate_both(phi(S))`, i.e.
    /// `r = S_0 + S_23 i - S_13 j + S_12 k`, `d = -S_ω + S_1inf i + S_2inf j + S_3inf k`.
    /// An anti-isomorphism: `from_pose(U V) = from_pose(V) from_pose(U)`, matching
    /// `F_{UV} = F_V F_U`. Non-unit poses map to non-unit dual quaternions of the same motion.
    ///
    /// ```
    /// use gam_algebras::{DualQuaternion, g123inf::Motor};
    /// use algebra_core::rational::{q, ratio};
    /// // the paper's translation T = 1 + 1/2 (3 e1) einf
    /// let t = Motor::new(q(1), q(0), q(0), q(0), ratio(3, 2), q(0), q(0), q(0));
    /// assert_eq!(DualQuaternion::from_pose(&t), DualQuaternion::from_translation(&[q(3), q(0), q(0)]));
    /// ```
    pub fn from_pose(s: &Motor<T>) -> Self {
        DualQuaternion::from(s).conjugate_both()
    }

    /// The paper's pose of the same rigid motion: the inverse of [`DualQuaternion::from_pose`].
    ///
    /// ```
    /// use gam_algebras::{DualQuaternion, g123inf::Motor};
    /// let s = Motor::new(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0);
    /// assert_eq!(DualQuaternion::from_pose(&s).to_pose(), s);
    /// ```
    pub fn to_pose(&self) -> Motor<T> {
        Motor::from(&self.conjugate_both())
    }
}

impl<T: Field> DualQuaternion<T> {
    /// The image of the point `p` under the rigid motion of `self`:
    /// `q (1 + ε p) (r* - ε d*) = |r|^2 + ε (r p r* + d r* - r d*)`, divided by `|r|^2`, so
    /// non-unit dual quaternions act as their normalisations (as in the paper's `F_S`).
    /// `None` when `|r|^2 = 0` (no rigid motion).
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// use gam_algebras::dual_quaternion::Quaternion;
    /// // a quarter turn about z (unnormalised: r = 1 + k), then a translation by (0, 0, 1)
    /// let rot = DualQuaternion::from_real(Quaternion::new(1.0f64, 0.0, 0.0, 1.0));
    /// let motion = &DualQuaternion::from_translation(&[0.0, 0.0, 1.0]) * &rot;
    /// let p = motion.transform_point(&[1.0, 0.0, 0.0]).unwrap();
    /// assert!((p[0] - 0.0).abs() < 1e-15 && (p[1] - 1.0).abs() < 1e-15 && (p[2] - 1.0).abs() < 1e-15);
    /// ```
    pub fn transform_point(&self, p: &[T; 3]) -> Option<[T; 3]> {
        let image = &(self * &DualQuaternion::from_point(p)) * &self.conjugate_both();
        let inv = image.real.w.try_recip()?;
        Some([image.dual.x.mul_ref(&inv), image.dual.y.mul_ref(&inv), image.dual.z.mul_ref(&inv)])
    }
}

impl<T: Ring> Mul<&DualQuaternion<T>> for &DualQuaternion<T> {
    type Output = DualQuaternion<T>;
    /// `(r1 + ε d1)(r2 + ε d2) = r1 r2 + ε (r1 d2 + d1 r2)`: three unrolled Hamilton products
    /// and a sum, 48 multiplications and 40 additions.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// let a = DualQuaternion::from_coeffs([0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]); // i
    /// let b = DualQuaternion::from_coeffs([0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0]); // ε j
    /// assert_eq!(&a * &b, DualQuaternion::from_coeffs([0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0])); // ε k
    /// ```
    #[inline]
    fn mul(self, rhs: &DualQuaternion<T>) -> DualQuaternion<T> {
        DualQuaternion {
            real: hamilton(&self.real, &rhs.real),
            dual: sum(hamilton(&self.real, &rhs.dual), &hamilton(&self.dual, &rhs.real)),
        }
    }
}

impl<T: Ring> Mul for DualQuaternion<T> {
    type Output = DualQuaternion<T>;
    /// The dual-quaternion product (see the impl for references).
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// let e = DualQuaternion::dual_number(0.0, 1.0);
    /// assert_eq!(e.clone() * e, DualQuaternion::zero()); // ε^2 = 0
    /// ```
    #[inline]
    fn mul(self, rhs: DualQuaternion<T>) -> DualQuaternion<T> {
        &self * &rhs
    }
}

impl<T: Ring> Add<&DualQuaternion<T>> for &DualQuaternion<T> {
    type Output = DualQuaternion<T>;
    /// Componentwise sum.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// let a = DualQuaternion::from_coeffs([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]);
    /// assert_eq!(&a + &a, a.scale(&2.0));
    /// ```
    fn add(self, rhs: &DualQuaternion<T>) -> DualQuaternion<T> {
        DualQuaternion::new(self.real.map2(&rhs.real, T::add_ref), self.dual.map2(&rhs.dual, T::add_ref))
    }
}

impl<T: Ring> Add for DualQuaternion<T> {
    type Output = DualQuaternion<T>;
    /// Componentwise sum.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// assert_eq!(DualQuaternion::one() + DualQuaternion::zero(), DualQuaternion::<f64>::one());
    /// ```
    fn add(self, rhs: DualQuaternion<T>) -> DualQuaternion<T> {
        &self + &rhs
    }
}

impl<T: Ring> Sub<&DualQuaternion<T>> for &DualQuaternion<T> {
    type Output = DualQuaternion<T>;
    /// Componentwise difference.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// let a = DualQuaternion::from_coeffs([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]);
    /// assert_eq!(&a - &a, DualQuaternion::zero());
    /// ```
    fn sub(self, rhs: &DualQuaternion<T>) -> DualQuaternion<T> {
        DualQuaternion::new(self.real.map2(&rhs.real, T::sub_ref), self.dual.map2(&rhs.dual, T::sub_ref))
    }
}

impl<T: Ring> Sub for DualQuaternion<T> {
    type Output = DualQuaternion<T>;
    /// Componentwise difference.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// assert_eq!(DualQuaternion::one() - DualQuaternion::one(), DualQuaternion::<f64>::zero());
    /// ```
    fn sub(self, rhs: DualQuaternion<T>) -> DualQuaternion<T> {
        &self - &rhs
    }
}

impl<T: Ring> Neg for &DualQuaternion<T> {
    type Output = DualQuaternion<T>;
    /// Componentwise negation.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// let a = DualQuaternion::from_coeffs([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]);
    /// assert_eq!(&a + &(-&a), DualQuaternion::zero());
    /// ```
    fn neg(self) -> DualQuaternion<T> {
        let n = |q: &Quaternion<T>| Quaternion::new(q.w.neg_ref(), q.x.neg_ref(), q.y.neg_ref(), q.z.neg_ref());
        DualQuaternion::new(n(&self.real), n(&self.dual))
    }
}

impl<T: Ring> Neg for DualQuaternion<T> {
    type Output = DualQuaternion<T>;
    /// Componentwise negation.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// assert_eq!(-DualQuaternion::<f64>::one(), DualQuaternion::dual_number(-1.0, 0.0));
    /// ```
    fn neg(self) -> DualQuaternion<T> {
        -&self
    }
}

impl<T: Ring> fmt::Display for DualQuaternion<T> {
    /// `1 + 2*i + 1/2*ε*j`: the eight terms `1, i, j, k, ε, ε*i, ε*j, ε*k`; `0` for zero.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// assert_eq!(DualQuaternion::from_coeffs([1.0, 0.0, 0.0, -2.0, 0.0, 0.0, 5.0, 0.0]).to_string(), "1 - 2*k + 5*ε*j");
    /// ```
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (r, d) = (&self.real, &self.dual);
        let terms = [
            ("1", &r.w),
            ("i", &r.x),
            ("j", &r.y),
            ("k", &r.z),
            ("ε", &d.w),
            ("ε*i", &d.x),
            ("ε*j", &d.y),
            ("ε*k", &d.z),
        ];
        f.write_str(&join_terms(
            terms.iter().filter(|(_, c)| !c.is_exact_zero()).map(|(n, c)| format_term(&c.to_string(), n)),
        ))
    }
}

impl<T: Ring> From<&Motor<T>> for DualQuaternion<T> {
    /// The isomorphism `phi` of the paper's Appendix 2 (an algebra homomorphism):
    /// `phi(S) = (S_0 - S_23 i + S_13 j - S_12 k) + ε (S_ω + S_1inf i + S_2inf j + S_3inf k)`.
    ///
    /// ```
    /// use gam_algebras::{DualQuaternion, g123inf::Motor};
    /// let e12 = Motor::new(0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    /// let e3inf = Motor::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    /// assert_eq!(DualQuaternion::from(&e12).to_string(), "-k");
    /// assert_eq!(DualQuaternion::from(&e3inf).to_string(), "ε*k");
    /// // e12 e3inf = e123inf = ω <-> (-k)(ε k) = ε
    /// assert_eq!(DualQuaternion::from(&(&e12 * &e3inf)), DualQuaternion::dual_number(0.0, 1.0));
    /// ```
    fn from(s: &Motor<T>) -> Self {
        DualQuaternion {
            real: Quaternion::new(s.scalar.clone(), s.e23.neg_ref(), s.e13.clone(), s.e12.neg_ref()),
            dual: Quaternion::new(s.e123inf.clone(), s.e1inf.clone(), s.e2inf.clone(), s.e3inf.clone()),
        }
    }
}

impl<T: Ring> From<Motor<T>> for DualQuaternion<T> {
    /// The isomorphism of the paper's Appendix 2 (see the impl for references).
    ///
    /// ```
    /// use gam_algebras::{DualQuaternion, g123inf::Motor};
    /// let s = Motor::new(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0);
    /// assert_eq!(DualQuaternion::from(s).coeffs(), [1.0, -4.0, 3.0, -2.0, 8.0, 5.0, 6.0, 7.0]);
    /// ```
    fn from(s: Motor<T>) -> Self {
        DualQuaternion::from(&s)
    }
}

impl<T: Ring> From<&DualQuaternion<T>> for Motor<T> {
    /// The inverse of the Appendix 2 isomorphism: `S_0 = r_w`, `S_12 = -r_z`, `S_13 = r_y`,
    /// `S_23 = -r_x`, `S_iinf = d_(x, y, z)`, `S_ω = d_w`.
    ///
    /// ```
    /// use gam_algebras::{DualQuaternion, g123inf::Motor};
    /// let q = DualQuaternion::from_coeffs([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]);
    /// assert_eq!(DualQuaternion::from(&Motor::from(&q)), q);
    /// ```
    fn from(q: &DualQuaternion<T>) -> Self {
        let (r, d) = (&q.real, &q.dual);
        Motor {
            scalar: r.w.clone(),
            e12: r.z.neg_ref(),
            e13: r.y.clone(),
            e23: r.x.neg_ref(),
            e1inf: d.x.clone(),
            e2inf: d.y.clone(),
            e3inf: d.z.clone(),
            e123inf: d.w.clone(),
        }
    }
}

impl<T: Ring> From<DualQuaternion<T>> for Motor<T> {
    /// The inverse of the Appendix 2 isomorphism (see the impl for references).
    ///
    /// ```
    /// use gam_algebras::{DualQuaternion, g123inf::Motor};
    /// let q = DualQuaternion::from_coeffs([1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]); // 1 + ε
    /// assert_eq!(Motor::from(q), Motor::new(1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)); // 1 + ω
    /// ```
    fn from(q: DualQuaternion<T>) -> Self {
        Motor::from(&q)
    }
}
