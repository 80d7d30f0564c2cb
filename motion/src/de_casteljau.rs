//! De Casteljau's algorithm, written once for every motion: the apex of the tableau computed in
//! place in one column ([`apex`], over any element type and any fallible pairwise combination),
//! the whole tableau for Fig. 2-style output ([`tableau_with`]), and the additive apex
//! coefficient by coefficient ([`additive_apex`]). The main paper's Bezier motions
//! ([`crate::bezier`], through [`crate::blend::Blend`]) and Jüttler's rational motions and
//! surfaces ([`crate::juttler`]) both evaluate through [`apex`].

use crate::Pose;
use algebra_core::Ring;
use std::convert::Infallible;

/// Control points up to this many (degree ≤ 7) are evaluated in an array on the stack; more in
/// one `Vec`.
pub(crate) const STACK_POSES: usize = 8;

/// The apex of de Casteljau's tableau over `points` with the pairwise `combine(left, right)`,
/// computed in place in one column: entry `i` of level `k` overwrites entry `i` of level
/// `k - 1` once entries `i` and `i + 1` were read. The same `combine` calls on the same
/// arguments in the same order as the tableau ([`tableau_with`]), so the apex is bit for bit the
/// tableau's; without allocation up to [`STACK_POSES`] points. `points` is not empty (every
/// caller checks at construction).
pub(crate) fn apex<C: Clone, E>(points: &[C], mut combine: impl FnMut(&C, &C) -> Result<C, E>) -> Result<C, E> {
    if points.len() <= STACK_POSES {
        let mut column: [Option<C>; STACK_POSES] = std::array::from_fn(|i| points.get(i).cloned());
        apex_in_place(&mut column[..points.len()], &mut combine)
    } else {
        let mut column: Vec<Option<C>> = points.iter().cloned().map(Some).collect();
        apex_in_place(&mut column, &mut combine)
    }
}

fn apex_in_place<C, E>(column: &mut [Option<C>], combine: &mut impl FnMut(&C, &C) -> Result<C, E>) -> Result<C, E> {
    for len in (1..column.len()).rev() {
        for i in 0..len {
            let (Some(a), Some(b)) = (&column[i], &column[i + 1]) else { unreachable!("entries 0..=len are set") };
            column[i] = Some(combine(a, b)?);
        }
    }
    Ok(column.first_mut().and_then(Option::take).expect("a motion has at least one control point"))
}

/// [`apex`] over poses with a combination that also takes the parameter `t`.
pub(crate) fn de_casteljau_with<T: Ring, E>(
    poses: &[Pose<T>],
    t: &T,
    combine: impl Fn(&Pose<T>, &Pose<T>, &T) -> Result<Pose<T>, E>,
) -> Result<Pose<T>, E> {
    apex(poses, |a, b| combine(a, b, t))
}

/// The de Casteljau tableau with a pairwise combination: column 0 is the control poses,
/// column `k` holds `S_{i..i+k}(t)`, the last column the single pose `S(t)`.
pub(crate) fn tableau_with<T: Ring, E>(
    poses: &[Pose<T>],
    t: &T,
    combine: impl Fn(&Pose<T>, &Pose<T>, &T) -> Result<Pose<T>, E>,
) -> Result<Vec<Vec<Pose<T>>>, E> {
    let mut columns = vec![poses.to_vec()];
    while columns[columns.len() - 1].len() > 1 {
        let last = &columns[columns.len() - 1];
        let next = last.windows(2).map(|w| combine(&w[0], &w[1], t)).collect::<Result<Vec<_>, E>>()?;
        columns.push(next);
    }
    Ok(columns)
}

/// The apex of the additive tableau (eq. 17 at every level) coefficient by coefficient: each
/// of the eight coefficients is its own scalar de Casteljau in an array on the stack, with the
/// operations of [`Pose::lerp`] (`a (1 - t) + b t`), so the result is bit for bit the pose
/// tableau's apex while the working set is a few scalars instead of whole poses (no pose is
/// moved or copied per level). More than [`STACK_POSES`] control poses take the pose tableau.
pub(crate) fn additive_apex<T: Ring>(poses: &[Pose<T>], t: &T) -> Pose<T> {
    if poses.len() > STACK_POSES {
        let Ok(pose) = de_casteljau_with::<T, Infallible>(poses, t, |a, b, t| Ok(Pose::lerp(a, b, t)));
        return pose;
    }
    let one_minus_t = T::one().sub_ref(t);
    let [c0, c1, c2, c3, c4, c5, c6, c7] = std::array::from_fn(|c| {
        let mut column: [T; STACK_POSES] =
            std::array::from_fn(|i| poses.get(i).map_or_else(T::zero, |p| p.components()[c].clone()));
        for len in (1..poses.len()).rev() {
            for i in 0..len {
                column[i] = column[i].mul_ref(&one_minus_t).add_ref(&column[i + 1].mul_ref(t));
            }
        }
        let [apex, ..] = column;
        apex
    });
    Pose::new(c0, c1, c2, c3, c4, c5, c6, c7)
}
