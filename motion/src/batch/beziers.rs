//! Sampling many Bézier motions with the motions across the lanes: lane `i` is motion `i` of a
//! group of [`Lanes::WIDTH`] motions, every lane at the same parameter. The other packing,
//! [`sample_many`](super::sample_many), puts `WIDTH` parameters of one motion in the lanes;
//! both give the same samples bit for bit (see docs/performance.md for which is faster).

use super::sample::{Block, check_parameters, sample_one};
use super::{BatchError, Lanes, Samples};
use crate::blend::Blend;
use crate::{Bezier, Motion, Pose};
use algebra_core::{Jet, Ring};

/// `S(t_k)` and `dS/dt` of every motion at every parameter, as [`sample_many`](super::sample_many)
/// (row `m · parameters + k`, bit for bit the same samples and the same first error), with
/// [`Lanes::WIDTH`] motions per evaluation: lane `i` holds motion `i` of the group, lifted to
/// `Jet<L>` once per group. A group whose motions differ in degree (or that fails) is sampled
/// motion by motion as [`sample_many`](super::sample_many) does.
///
/// ```
/// use motion::{AdditiveBezier, Pose, batch::{sample_beziers, sample_many}};
/// let a = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])]).unwrap();
/// let b = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::rotation(&[0.0, 0.0, 1.0], &1.0).unwrap()]).unwrap();
/// let ms = [a, b.clone(), b];
/// let ts = [0.0, 0.3, 1.0];
/// assert_eq!(sample_beziers::<f64, _>(&ms, &ts).unwrap(), sample_many::<f64, _>(&ms, &ts).unwrap());
/// ```
pub fn sample_beziers<L, B>(motions: &[Bezier<L::Elem, B>], ts: &[L::Elem]) -> Result<Samples<L::Elem>, BatchError>
where
    L: Lanes,
    L::Elem: PartialOrd,
    B: Blend<L::Elem> + Blend<Jet<L>>,
{
    let mut out = Samples::zeros(motions.len(), ts.len());
    let mut blocks = out.blocks();
    for (g, (group, outs)) in motions.chunks(L::WIDTH).zip(blocks.chunks_mut(L::WIDTH)).enumerate() {
        sample_group(g * L::WIDTH, group, ts, outs)?;
    }
    drop(blocks);
    Ok(out)
}

/// [`sample_beziers`] with the groups of motions spread over every core (rayon); bit for bit
/// the serial result, and the same error.
///
/// ```
/// use motion::{AdditiveBezier, Pose, batch::{par_sample_beziers, sample_many}};
/// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])]).unwrap();
/// let ms = vec![m; 50];
/// assert_eq!(par_sample_beziers::<f64, _>(&ms, &[0.0, 0.5]).unwrap(), sample_many::<f64, _>(&ms, &[0.0, 0.5]).unwrap());
/// ```
#[cfg(feature = "parallel")]
pub fn par_sample_beziers<L, B>(motions: &[Bezier<L::Elem, B>], ts: &[L::Elem]) -> Result<Samples<L::Elem>, BatchError>
where
    L: Lanes,
    L::Elem: PartialOrd,
    B: Blend<L::Elem> + Blend<Jet<L>> + Sync,
{
    use rayon::prelude::*;
    let mut out = Samples::zeros(motions.len(), ts.len());
    let mut blocks = out.blocks();
    let results: Vec<Result<(), BatchError>> = motions
        .par_chunks(L::WIDTH)
        .zip(blocks.par_chunks_mut(L::WIDTH))
        .enumerate()
        .map(|(g, (group, outs))| sample_group(g * L::WIDTH, group, ts, outs))
        .collect();
    drop(blocks);
    results.into_iter().collect::<Result<(), _>>()?;
    Ok(out)
}

/// One group of at most `L::WIDTH` motions (the first is motion `first`) into its output
/// blocks: across the lanes when the group allows it, else motion by motion.
fn sample_group<L, B>(
    first: usize,
    group: &[Bezier<L::Elem, B>],
    ts: &[L::Elem],
    outs: &mut [Block<'_, L::Elem>],
) -> Result<(), BatchError>
where
    L: Lanes,
    L::Elem: PartialOrd,
    B: Blend<L::Elem> + Blend<Jet<L>>,
{
    let degree = group[0].degree();
    let packable = group.iter().all(|m| m.degree() == degree && check_parameters(m, ts, 0).is_ok());
    if packable && across_lanes::<L, B>(group, ts, outs).is_some() {
        return Ok(());
    }
    for (i, (motion, (values, derivatives))) in group.iter().zip(outs.iter_mut()).enumerate() {
        let values = values.each_mut().map(|c| &mut **c);
        let derivatives = derivatives.each_mut().map(|c| &mut **c);
        sample_one(first + i, motion, ts, values, derivatives)?;
    }
    Ok(())
}

/// The group's motions of equal degree in the lanes (the last group padded with its first
/// motion), evaluated over `Jet<L>` at every parameter; `None` when an evaluation fails.
fn across_lanes<L, B>(group: &[Bezier<L::Elem, B>], ts: &[L::Elem], outs: &mut [Block<'_, L::Elem>]) -> Option<()>
where
    L: Lanes,
    B: Blend<L::Elem> + Blend<Jet<L>>,
{
    let mut lanes: Vec<L::Elem> = Vec::with_capacity(L::WIDTH);
    let controls = (0..=group[0].degree()).map(|j| {
        Pose::from_array(std::array::from_fn(|c| {
            lanes.clear();
            lanes.extend(group.iter().map(|m| m.poses()[j].components()[c].clone()));
            Jet::constant(L::load_padded(&lanes, lanes.first().expect("a group has a motion")))
        }))
    });
    let lifted = Bezier::<Jet<L>, B>::new(controls.collect()).ok()?;
    lanes.resize(L::WIDTH, L::Elem::zero());
    for (k, t) in ts.iter().enumerate() {
        let s = lifted.evaluate(&Jet::variable(L::splat(t))).ok()?.into_array();
        for (c, x) in s.into_iter().enumerate() {
            x.re.store(&mut lanes);
            for ((values, _), v) in outs.iter_mut().zip(&lanes) {
                values[c][k] = v.clone();
            }
            x.eps.store(&mut lanes);
            for ((_, derivatives), d) in outs.iter_mut().zip(&lanes) {
                derivatives[c][k] = d.clone();
            }
        }
    }
    Some(())
}
