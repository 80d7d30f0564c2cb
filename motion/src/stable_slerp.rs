//! A numerically stable evaluation of the multiplicative (slerp) de Casteljau tableau.
//!
//! Every entry is taken as `exp(l) · U`: `U` unitary and `l` the logarithm of the pseudoscalar
//! factor (Lemma 2.4). By eq. (16), `Φ(αA, βB; t) = α^{1+t} β^t Φ(A, B; t)`, so the factors
//! combine *linearly* in the logarithm, `l ← (1 + t) l_A + t l_B`, and only unitary poses
//! are slerped; each slerp result is unitized again, so the rounding of one level does not
//! feed a drift off the unit poses into the next (with the plain recursion the norm error grew
//! exponentially with the degree: 4e-7 at degree 20, failure from about 40). The factors
//! are applied to the unitized slerp of each pair.
//!
//! A whole tableau ([`apex`], [`tableau`]) keeps every entry factored from level to level:
//! the control poses are factored once, and each level combines the factors linearly and
//! slerps the unit parts. Factoring each level's expanded pose again (as the pairwise
//! [`slerp`] does) would take the logarithm of a unitized pose's norm, which is zero up to
//! rounding, and eq. (16) multiplies that rounding by `1 + 2t` per level: harmless for the
//! value (it is tested as negligible and dropped), but a dual number's derivative parts of that
//! rounding grow with the degree's powers and are not negligible next to the value, so from
//! degree about 150 the second derivatives (`gam plot`'s accelerations) overflowed or
//! underflowed to a zero pose.

use crate::MotionError;
use crate::de_casteljau::apex as apex_with;
use crate::pose::{Pose, Pseudoscalar};
use algebra_core::{Real, Ring};

#[derive(Clone)]
struct Factored<T: Ring> {
    unit: Pose<T>,
    log_factor: Pseudoscalar<T>,
}

impl<T: Real> Factored<T> {
    /// `S = exp(l) U`. A pose that is unitary to within rounding (`|l| ≤ 8ε`, the ω part
    /// relative to the pose's size) gets `l = 0` exactly: eq. (16) raises the factors to the
    /// powers `1 + t` and `t` at every level, so rounding noise in `l` would otherwise grow
    /// like `(1 + 2t)^n` with the degree `n`.
    fn new(s: &Pose<T>) -> Result<Self, MotionError> {
        let mut l = s.norm()?.ln()?;
        let one = T::one();
        if l.scalar.is_negligible(&one, 8) {
            l.scalar = T::zero();
        }
        let size = one.add_ref(&crate::scaled::largest_abs(s.components()));
        if l.e123inf.is_negligible(&size, 8) {
            l.e123inf = T::zero();
        }
        Ok(Factored { unit: s.unitize()?, log_factor: l })
    }

    fn slerp(&self, other: &Self, t: &T) -> Result<Self, MotionError> {
        let unit = Pose::slerp(&self.unit, &other.unit, t)?.unitize()?;
        let s = T::one().add_ref(t);
        let (a, b) = (&self.log_factor, &other.log_factor);
        let log_factor = Pseudoscalar::new(
            a.scalar.mul_ref(&s).add_ref(&b.scalar.mul_ref(t)),
            a.e123inf.mul_ref(&s).add_ref(&b.e123inf.mul_ref(t)),
        );
        Ok(Factored { unit, log_factor })
    }

    fn expand(&self) -> Pose<T> {
        self.unit.scale_pseudoscalar(&self.log_factor.exp())
    }
}

/// The slerp `Φ(A, B; t) = A (rev(A) B)^t` (eq. 15) evaluated as
/// `exp((1 + t) l_A + t l_B) · Φ(U_A, U_B; t)` with `A = exp(l_A) U_A`, `B = exp(l_B) U_B`
/// (eq. 16) and the unitary result unitized again: the same value as [`Pose::slerp`] in exact
/// arithmetic, without the drift off unit poses when it is applied level after level in a
/// de Casteljau or de Boor tableau.
pub(crate) fn slerp<T: Real>(a: &Pose<T>, b: &Pose<T>, t: &T) -> Result<Pose<T>, MotionError> {
    crate::scaled::require_finite("slerp", a, [t])?;
    Ok(Factored::new(a)?.slerp(&Factored::new(b)?, t)?.expand())
}

/// The apex `S(t)` of the slerp tableau over `poses` (at least one), every entry kept factored
/// (module docs): the value of the pairwise [`slerp`]'s tableau in exact arithmetic.
pub(crate) fn apex<T: Real>(poses: &[Pose<T>], t: &T) -> Result<Pose<T>, MotionError> {
    if let [single] = poses {
        return Ok(single.clone());
    }
    finite_parameter(t)?;
    let factored = poses.iter().map(Factored::new).collect::<Result<Vec<_>, _>>()?;
    Ok(apex_with(&factored, |a, b| a.slerp(b, t))?.expand())
}

/// The whole slerp tableau (column 0 the control poses, column `k` the entries
/// `S_{i..i+k}(t)`), every entry kept factored (module docs) and expanded for the output.
pub(crate) fn tableau<T: Real>(poses: &[Pose<T>], t: &T) -> Result<Vec<Vec<Pose<T>>>, MotionError> {
    finite_parameter(t)?;
    let mut column = poses.iter().map(Factored::new).collect::<Result<Vec<_>, _>>()?;
    let mut columns = vec![poses.to_vec()];
    while column.len() > 1 {
        column = column.windows(2).map(|w| w[0].slerp(&w[1], t)).collect::<Result<Vec<_>, _>>()?;
        columns.push(column.iter().map(Factored::expand).collect());
    }
    Ok(columns)
}

/// De Boor's algorithm over a span's control poses with every entry kept factored (module
/// docs); one control pose (degree 0) is returned as it is.
pub(crate) fn de_boor<T: Real>(poses: &[Pose<T>], alpha: &dyn Fn(usize, usize) -> T) -> Result<Pose<T>, MotionError> {
    if let [single] = poses {
        return Ok(single.clone());
    }
    let factored = poses.iter().map(Factored::new).collect::<Result<Vec<_>, _>>()?;
    let apex = crate::bspline::de_boor_with(factored, alpha, |a, b, t| {
        finite_parameter(t)?;
        a.slerp(b, t)
    })?;
    Ok(apex.expand())
}

/// [`MotionError::NotFinite`] for a non-finite slerp parameter (any part, for dual numbers),
/// naming the parameter: the tableaux check it once, not with every control pose.
fn finite_parameter<T: Real>(t: &T) -> Result<(), MotionError> {
    if t.is_finite_value() { Ok(()) } else { Err(MotionError::NotFinite { op: "slerp", value: t.to_string() }) }
}
