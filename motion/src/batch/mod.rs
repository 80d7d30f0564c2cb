//! Batches: many poses and points at once, across SIMD lanes and cores.
//!
//! * [`Points`] (columns `x, y, z`) and [`Poses`] (eight coefficient columns in the paper's
//!   order) store batches as structures of arrays, checked on construction (equal lengths,
//!   finite values: [`BatchError`]).
//! * Every operation is written once over a lane type `L: `[`Lanes`] whose element is the
//!   batch's scalar: `L = f64` (or any scalar) is the scalar loop, a SIMD lane type computes
//!   `L::WIDTH` elements per instruction. The results are bit for bit those of the scalar pose
//!   code ([`Pose::transform_point`](crate::Pose::transform_point), the generated product,
//!   [`Pose::lerp`](crate::Pose::lerp), [`Motion::evaluate`](crate::Motion::evaluate)), remainders
//!   included (the last chunk is padded and only its real lanes stored).
//! * `par_*` variants (feature `parallel`, on by default) split the rows into blocks over
//!   rayon's thread pool; they return the serial results and the serial errors.
//! * [`Packed`]: columns packed into lane chunks and back, for code of your own over `L`.
//!
//! | operation | serial | over cores |
//! |---|---|---|
//! | one pose on a point cloud | [`Points::transform`] | [`Points::par_transform`] |
//! | pose `i` on point `i` | [`Poses::transform_points`] | [`Poses::par_transform_points`] |
//! | `a[i] * b[i]` | [`Poses::compose`] | [`Poses::par_compose`] |
//! | `(1 - t) a[i] + t b[i]` (eq. 17) | [`Poses::lerp`] | [`Poses::par_lerp`] |
//! | slerp (eq. 15), bit for bit [`Pose::slerp`](crate::Pose::slerp), scalar only | [`Poses::slerp`] | [`Poses::par_slerp`] |
//! | slerp, branch-free over lanes ([`Pose::slerp_branch_free`](crate::Pose::slerp_branch_free)) | [`Poses::slerp_lanes`] | [`Poses::par_slerp_lanes`] |
//! | one motion at many parameters | [`sample`] | |
//! | many motions at many parameters, with `dS/dt` | [`sample_many`] | [`par_sample_many`] |
//! | the same for Bézier motions, motion `i` in lane `i` | [`sample_beziers`] | [`par_sample_beziers`] |
//!
//! ```
//! use motion::{Pose, batch::Points};
//! let s = Pose::from_axis_angle_translation(&[0.0, 1.0, 0.0], &0.7, &[1.0, 2.0, 3.0]).unwrap();
//! let cloud: Vec<[f64; 3]> = (0..1000).map(|i| [i as f64, 1.0, -2.0]).collect();
//! let p = Points::from_points(&cloud).unwrap();
//! let q = p.transform::<f64>(&s).unwrap();
//! assert_eq!(q.get(7).unwrap(), s.transform_point(&cloud[7]).unwrap());
//! ```

mod beziers;
mod columns;
mod error;
mod points;
mod poses;
mod sample;

/// The lane type of every batch kernel: `algebra_core::scalar::Lanes`
/// (lane width and packing live in the scalar layer), re-exported here under its first path.
pub use algebra_core::scalar::Lanes;
#[cfg(feature = "parallel")]
pub use beziers::par_sample_beziers;
pub use beziers::sample_beziers;
pub use columns::Packed;
pub use error::BatchError;
pub use points::Points;
pub use poses::Poses;
#[cfg(feature = "parallel")]
pub use sample::par_sample_many;
pub use sample::{Samples, sample, sample_many};
