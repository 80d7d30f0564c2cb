//! B-spline Q-motions (Jüttler Sec. 6): definition (13) with the Bernstein polynomials replaced
//! by the B-splines `N_j^p` of degree `p` over a knot vector `u_0 ≤ … ≤ u_{n+p+1}`,
//! `Q(t) = Σ_j N_j^p(t) B_j`, on the domain `[u_p, u_{n+1}]`, on the Study quadric (8) for
//! every `t`.
//!
//! Evaluation by de Boor's algorithm; the polynomial pieces as Bézier Q-motions by blossoming
//! (`b_i = Q[u_k^{p-i}, u_{k+1}^i]` on the span `[u_k, u_{k+1}]`), which gives the Study
//! condition exactly (every piece's Study polynomial, [`QMotion::study_polynomial`]), the
//! [`crate::Motion`], and the trajectories (one rational Bézier curve of degree `2p` per span)
//! through a [`SplineQMotion`]. The product of two B-spline Q-motions
//! ([`BSplineQMotion::product`], Jüttler's "product formulae for B-spline basis functions")
//! goes through the pieces as well: (29) on each span, then the control points as blossoms,
//! instead of Mørken's formulae (his ref. \[10\]). Not here: Jüttler's interpolation methods
//! generalised to B-spline Q-motions (choice of knots, Schoenberg–Whitney collocation).
//!
//! ```
//! use algebra_core::rational::{q, ratio};
//! use gam_algebras::DualQuaternion;
//! use motion::juttler::bspline::BSplineQMotion;
//! // a rotational quadratic B-spline about z with a knot at 1/2
//! let r = |w: i64, z: i64| DualQuaternion::from_coeffs([q(w), q(0), q(0), q(z), q(0), q(0), q(0), q(0)]);
//! let knots = vec![q(0), q(0), q(0), ratio(1, 2), q(1), q(1), q(1)];
//! let m = BSplineQMotion::new_exact(2, knots, vec![r(1, 0), r(1, 1), r(0, 1), r(-1, 1)]).unwrap();
//! assert_eq!(m.pieces().segments().len(), 2);
//! assert_eq!(m.eval(&ratio(1, 2)), m.pieces().eval(&ratio(1, 2)));
//! ```

use super::{JuttlerError, QMotion, SplineQMotion, bernstein_product};
use crate::repr::dual_quaternion::DualQuaternion;
use crate::{CurveError, MapScalar, Motion, Pose};
use algebra_core::{Field, Real, Ring};
use std::cmp::Ordering;

/// A B-spline Q-motion (module docs): degree `p`, knots `u_0 ≤ … ≤ u_{n+p+1}`, control dual
/// quaternions `B_0, …, B_n`, and its polynomial pieces as Bézier Q-motions.
///
/// ```
/// use algebra_core::rational::q;
/// use gam_algebras::DualQuaternion;
/// use motion::juttler::bspline::BSplineQMotion;
/// let one = DualQuaternion::from_coeffs([q(1), q(0), q(0), q(0), q(0), q(0), q(0), q(0)]);
/// let m = BSplineQMotion::new_exact(1, vec![q(0), q(0), q(1), q(1)], vec![one.clone(), one]).unwrap();
/// assert_eq!(m.domain_interval(), [q(0), q(1)]);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineQMotion<T> {
    degree: usize,
    knots: Vec<T>,
    control: Vec<DualQuaternion<T>>,
    pieces: SplineQMotion<T>,
}

fn knot_error(why: String) -> JuttlerError {
    JuttlerError::Parameters { why }
}

impl<T: Field + PartialOrd> BSplineQMotion<T> {
    /// The B-spline Q-motion of degree `degree` with `knots` and `control` (`n + 1 ≥ p + 1`
    /// control points, `n + p + 2` non-decreasing knots, each value at most `p + 1` times,
    /// `u_p < u_{n+1}`), if every polynomial piece is on the Study quadric up to `tol` (as in
    /// [`QMotion::new`]; `tol = 0`: exactly). Typed errors otherwise.
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use gam_algebras::DualQuaternion;
    /// use motion::juttler::{JuttlerError, bspline::BSplineQMotion};
    /// let d = |c: [i64; 8]| DualQuaternion::from_coeffs(c.map(q));
    /// let (one, eps) = (d([1, 0, 0, 0, 0, 0, 0, 0]), d([0, 0, 0, 0, 1, 0, 0, 0]));
    /// let knots = vec![q(0), q(0), q(1), q(1)];
    /// assert!(matches!(BSplineQMotion::new(1, knots.clone(), vec![one.clone(), eps], 0.0), Err(JuttlerError::NotQMotion { .. })));
    /// assert!(matches!(BSplineQMotion::new(1, vec![q(0), q(1), q(0), q(1)], vec![one.clone(), one], 0.0), Err(JuttlerError::Parameters { .. })));
    /// ```
    pub fn new(degree: usize, knots: Vec<T>, control: Vec<DualQuaternion<T>>, tol: f64) -> Result<Self, JuttlerError> {
        let n1 = control.len();
        if n1 <= degree {
            return Err(JuttlerError::TooFewPositions { need: degree.saturating_add(1), got: n1 });
        }
        if knots.len() != n1 + degree + 1 {
            return Err(knot_error(format!(
                "degree {degree} with {n1} control points needs {} knots, got {}",
                n1 + degree + 1,
                knots.len()
            )));
        }
        let mut multiplicity = 1;
        for (i, w) in knots.windows(2).enumerate() {
            match w[0].partial_cmp(&w[1]) {
                Some(Ordering::Less) => multiplicity = 1,
                Some(Ordering::Equal) => multiplicity += 1,
                _ => return Err(knot_error(format!("knots u_{i} = {} and u_{} = {} decrease", w[0], i + 1, w[1]))),
            }
            if multiplicity > degree + 1 {
                return Err(knot_error(format!("knot {} repeated more than {} times", w[1], degree + 1)));
            }
        }
        if knots[degree] >= knots[n1] {
            return Err(knot_error(format!("empty domain [u_p, u_(n+1)] = [{}, {}]", knots[degree], knots[n1])));
        }
        let mut m =
            BSplineQMotion { degree, knots, control, pieces: SplineQMotion::from_pieces(Vec::new(), Vec::new()) };
        let (mut breaks, mut segments) = (Vec::new(), Vec::new());
        for k in (degree..n1).filter(|&k| m.knots[k] < m.knots[k + 1]) {
            let (a, b) = (&m.knots[k], &m.knots[k + 1]);
            let piece = (0..=degree)
                .map(|i| {
                    let args: Vec<T> =
                        (0..degree).map(|r| if r < degree - i { a.clone() } else { b.clone() }).collect();
                    m.blossom(k, &args)
                })
                .collect();
            segments.push(QMotion::new(piece, tol)?);
            if breaks.is_empty() {
                breaks.push(a.clone());
            }
            breaks.push(b.clone());
        }
        m.pieces = SplineQMotion::from_pieces(breaks, segments);
        Ok(m)
    }

    /// [`BSplineQMotion::new`] with `tol = 0` (exact scalars).
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use gam_algebras::DualQuaternion;
    /// let one = DualQuaternion::from_coeffs([q(1), q(0), q(0), q(0), q(0), q(0), q(0), q(0)]);
    /// let m = motion::juttler::bspline::BSplineQMotion::new_exact(0, vec![q(0), q(1)], vec![one]).unwrap();
    /// assert_eq!(m.degree(), 0);
    /// ```
    pub fn new_exact(degree: usize, knots: Vec<T>, control: Vec<DualQuaternion<T>>) -> Result<Self, JuttlerError> {
        Self::new(degree, knots, control, 0.0)
    }

    /// The blossom (polar form) of the piece on the span `k` at `args` (`p` values), by de
    /// Boor's triangle with one argument per level.
    fn blossom(&self, k: usize, args: &[T]) -> DualQuaternion<T> {
        let (p, u) = (self.degree, &self.knots);
        let mut d: Vec<DualQuaternion<T>> = self.control[k - p..=k].to_vec();
        for (r, x) in (1..=p).zip(args) {
            for j in (r..=p).rev() {
                let (lo, hi) = (&u[j + k - p], &u[j + 1 + k - r]);
                // hi > lo: hi ≥ u_{k+1} > u_k ≥ lo on a non-empty span
                let alpha = x.sub_ref(lo).mul_ref(&hi.sub_ref(lo).try_recip().unwrap_or_else(T::zero));
                d[j] = &d[j - 1].scale(&T::one().sub_ref(&alpha)) + &d[j].scale(&alpha);
            }
        }
        d.swap_remove(p)
    }

    /// The product `Q(t) = self(t) * other(t)` as a B-spline Q-motion of degree `p + q` on the
    /// common domain (clamped knots; at an interior knot the multiplicity `p + q - c`, `c` the
    /// lower continuity order of the two factors there), exact over rationals: each control
    /// point `c_j` is the blossom at `u_{j+1}, …, u_{j+p+q}` of the product piece on a span of
    /// its support, the piece by the product formula (29) of the two factors restricted to that
    /// span. Applies `other`'s displacement first, as [`QMotion::product`]. Fails for different
    /// domains.
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio};
    /// use gam_algebras::DualQuaternion;
    /// use motion::juttler::bspline::BSplineQMotion;
    /// let d = |c: [i64; 8]| DualQuaternion::from_coeffs(c.map(q));
    /// let k = vec![q(0), q(0), ratio(1, 2), q(1), q(1)];
    /// let rot = BSplineQMotion::new_exact(1, k.clone(), vec![d([1, 0, 0, 0, 0, 0, 0, 0]), d([1, 0, 0, 1, 0, 0, 0, 0]), d([0, 0, 0, 1, 0, 0, 0, 0])]).unwrap();
    /// let tr = BSplineQMotion::new_exact(1, k, vec![d([2, 0, 0, 0, 0, 0, 0, 0]), d([2, 0, 0, 0, 0, 1, 0, 0]), d([2, 0, 0, 0, 0, 1, 1, 0])]).unwrap();
    /// let m = tr.product(&rot).unwrap();
    /// assert_eq!(m.degree(), 2);
    /// assert_eq!(m.eval(&ratio(1, 3)), &tr.eval(&ratio(1, 3)) * &rot.eval(&ratio(1, 3)));
    /// ```
    pub fn product(&self, other: &Self) -> Result<Self, JuttlerError> {
        let dom = self.domain_interval();
        if dom != other.domain_interval() {
            return Err(knot_error("the factors of a B-spline product need the same domain".into()));
        }
        let d = self.degree + other.degree;
        let mut inner: Vec<T> =
            self.knots.iter().chain(&other.knots).filter(|u| dom[0] < **u && **u < dom[1]).cloned().collect();
        inner.sort_by(|a, b| a.partial_cmp(b).unwrap_or(Ordering::Equal));
        inner.dedup();
        // continuity order at x: p - multiplicity (or none for a knot of the other factor only)
        let order = |m: &Self, x: &T| match m.knots.iter().filter(|u| *u == x).count() {
            0 => usize::MAX,
            k => (m.degree + 1).saturating_sub(k),
        };
        let mut knots = vec![dom[0].clone(); d + 1];
        for x in &inner {
            // multiplicity d - c with c = min order - 1 (order counts from C^-1 = 0)
            let c = order(self, x).min(order(other, x));
            knots.extend(std::iter::repeat_n(x.clone(), (d + 1).saturating_sub(c).max(1)));
        }
        knots.extend(std::iter::repeat_n(dom[1].clone(), d + 1));
        let n1 = knots.len() - d - 1;
        let control = (0..n1)
            .map(|j| {
                let k = (j.max(d)..=(j + d).min(n1 - 1)).find(|&k| knots[k] < knots[k + 1]).unwrap_or(d);
                let (a, b) = (&knots[k], &knots[k + 1]);
                let piece = bernstein_product(
                    &restrict(&self.pieces, a, b),
                    &restrict(&other.pieces, a, b),
                    DualQuaternion::zero(),
                    |x, y| x * y,
                    |acc, x, f: &T| acc + &x.scale(f),
                );
                let inv = b.sub_ref(a).try_recip().unwrap_or_else(T::zero);
                let args: Vec<T> = knots[j + 1..=j + d].iter().map(|u| u.sub_ref(a).mul_ref(&inv)).collect();
                bezier_blossom(&piece, &args)
            })
            .collect();
        // a product of Q-motions is one: tol = 1 bounds every Study coefficient (see QMotion::new)
        Self::new(d, knots, control, 1.0)
    }

    /// `Q(t) = Σ N_j^p(t) B_j` by de Boor's algorithm on the span of `t` (the right one at an
    /// interior knot; the first or last one outside the domain); exact over rationals.
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio};
    /// use gam_algebras::DualQuaternion;
    /// let d = |w: i64| DualQuaternion::from_coeffs([q(w), q(0), q(0), q(0), q(0), q(0), q(0), q(0)]);
    /// let m = motion::juttler::bspline::BSplineQMotion::new_exact(1, vec![q(0), q(0), q(1), q(1)], vec![d(1), d(3)]).unwrap();
    /// assert_eq!(m.eval(&ratio(1, 2)), d(2));
    /// ```
    pub fn eval(&self, t: &T) -> DualQuaternion<T> {
        let k = span(&self.knots, self.degree, self.control.len(), t);
        self.blossom(k, &vec![t.clone(); self.degree])
    }
}

/// The span `k` used at `t` (`u_k ≤ t < u_{k+1}`, non-empty, `p ≤ k ≤ n`): the right one at an
/// interior knot, the first or last one outside the domain (valid knots for `n + 1` control
/// points of degree `p`).
pub(crate) fn span<T: PartialOrd>(u: &[T], p: usize, n1: usize, t: &T) -> usize {
    let mut spans = (p..n1).filter(|&k| u[k] < u[k + 1]);
    let first = spans.next().unwrap_or(p);
    spans.rev().find(|&k| u[k] <= *t).unwrap_or(first)
}

/// The blossom of the Bézier polynomial with `control` (local parameter) at `args`, one per
/// level of de Casteljau's triangle.
fn bezier_blossom<T: Ring>(control: &[DualQuaternion<T>], args: &[T]) -> DualQuaternion<T> {
    let mut col = control.to_vec();
    for (len, x) in (1..col.len()).rev().zip(args) {
        let s = T::one().sub_ref(x);
        for i in 0..len {
            col[i] = &col[i].scale(&s) + &col[i + 1].scale(x);
        }
    }
    col.swap_remove(0)
}

/// The Bézier control points, on `[a, b]`, of the piece of `pieces` containing that interval.
fn restrict<T: Field + PartialOrd>(pieces: &SplineQMotion<T>, a: &T, b: &T) -> Vec<DualQuaternion<T>> {
    let (i, a_local) = pieces.local(a);
    let (lo, hi) = (&pieces.breaks()[i], &pieces.breaks()[i + 1]);
    let b_local = b.sub_ref(lo).mul_ref(&hi.sub_ref(lo).try_recip().unwrap_or_else(T::zero));
    let c = pieces.segments()[i].control();
    let n = c.len() - 1;
    (0..=n)
        .map(|r| {
            let args: Vec<T> = (0..n).map(|l| if l < n - r { a_local.clone() } else { b_local.clone() }).collect();
            bezier_blossom(c, &args)
        })
        .collect()
}

impl<T: Ring> BSplineQMotion<T> {
    /// The degree `p`.
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use gam_algebras::DualQuaternion;
    /// let one = DualQuaternion::from_coeffs([q(1), q(0), q(0), q(0), q(0), q(0), q(0), q(0)]);
    /// let m = motion::juttler::bspline::BSplineQMotion::new_exact(1, vec![q(0), q(0), q(1), q(1)], vec![one.clone(), one]).unwrap();
    /// assert_eq!(m.degree(), 1);
    /// ```
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The knots `u_0, …, u_{n+p+1}`.
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use gam_algebras::DualQuaternion;
    /// let one = DualQuaternion::from_coeffs([q(1), q(0), q(0), q(0), q(0), q(0), q(0), q(0)]);
    /// let m = motion::juttler::bspline::BSplineQMotion::new_exact(0, vec![q(0), q(1)], vec![one]).unwrap();
    /// assert_eq!(m.knots(), [q(0), q(1)]);
    /// ```
    pub fn knots(&self) -> &[T] {
        &self.knots
    }

    /// The control dual quaternions `B_0, …, B_n`.
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use gam_algebras::DualQuaternion;
    /// let one = DualQuaternion::from_coeffs([q(1), q(0), q(0), q(0), q(0), q(0), q(0), q(0)]);
    /// let m = motion::juttler::bspline::BSplineQMotion::new_exact(0, vec![q(0), q(1)], vec![one.clone()]).unwrap();
    /// assert_eq!(m.control(), [one]);
    /// ```
    pub fn control(&self) -> &[DualQuaternion<T>] {
        &self.control
    }

    /// The domain `[u_p, u_{n+1}]`.
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use gam_algebras::DualQuaternion;
    /// let one = DualQuaternion::from_coeffs([q(1), q(0), q(0), q(0), q(0), q(0), q(0), q(0)]);
    /// let m = motion::juttler::bspline::BSplineQMotion::new_exact(0, vec![q(2), q(5)], vec![one]).unwrap();
    /// assert_eq!(m.domain_interval(), [q(2), q(5)]);
    /// ```
    pub fn domain_interval(&self) -> [T; 2] {
        [self.knots[self.degree].clone(), self.knots[self.control.len()].clone()]
    }

    /// The same B-spline Q-motion over the scalar `U`, each coefficient and knot mapped by `f`.
    ///
    /// ```
    /// use algebra_core::rational::{q, rational_to_f64};
    /// use gam_algebras::DualQuaternion;
    /// let one = DualQuaternion::from_coeffs([q(1), q(0), q(0), q(0), q(0), q(0), q(0), q(0)]);
    /// let m = motion::juttler::bspline::BSplineQMotion::new_exact(0, vec![q(0), q(1)], vec![one]).unwrap();
    /// assert_eq!(m.map_ring(&rational_to_f64).knots(), [0.0, 1.0]);
    /// ```
    pub fn map_ring<U: Ring>(&self, f: &dyn Fn(&T) -> U) -> BSplineQMotion<U> {
        BSplineQMotion {
            degree: self.degree,
            knots: self.knots.iter().map(f).collect(),
            control: self.control.iter().map(|b| DualQuaternion::from_coeffs(b.coeffs().map(|x| f(&x)))).collect(),
            pieces: self.pieces.map_ring(f),
        }
    }

    /// The polynomial pieces, one Bézier Q-motion of degree `p` per non-empty span, as a
    /// [`SplineQMotion`] (its breaks are the distinct knots of the domain): evaluation, one-sided
    /// derivatives and trajectories ([`SplineQMotion::trajectories`], degree `2p`).
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio};
    /// use gam_algebras::DualQuaternion;
    /// let d = |w: i64| DualQuaternion::from_coeffs([q(w), q(0), q(0), q(0), q(0), q(0), q(0), q(0)]);
    /// let m = motion::juttler::bspline::BSplineQMotion::new_exact(1, vec![q(0), q(0), q(1), q(2), q(2)], vec![d(1), d(3), d(2)]).unwrap();
    /// assert_eq!(m.pieces().breaks(), [q(0), q(1), q(2)]);
    /// ```
    pub fn pieces(&self) -> &SplineQMotion<T> {
        &self.pieces
    }
}

/// A B-spline Q-motion is a [`Motion`] on `[u_p, u_{n+1}]`: that of its pieces.
impl<T: Real> Motion<T> for BSplineQMotion<T> {
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        self.pieces.evaluate(t)
    }

    fn domain(&self) -> [T; 2] {
        self.domain_interval()
    }
}

impl<T: Real, U: Real> MapScalar<T, U> for BSplineQMotion<T> {
    type Mapped = BSplineQMotion<U>;
    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> BSplineQMotion<U> {
        self.map_ring(f)
    }
}
