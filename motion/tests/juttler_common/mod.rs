//! Helpers shared by the Jüttler tests.
#![allow(dead_code)]

/// The largest component-wise distance between a trajectory's point and the reference point
/// (the point's image under the sampled motion) at 1000 parameters evenly over `[0, 1]`.
pub fn worst_at_1000(path: impl Fn(&f64) -> [f64; 3], reference: impl Fn(&f64) -> [f64; 3]) -> f64 {
    (0..1000)
        .map(|k| {
            let t = k as f64 / 999.0;
            let (a, b) = (path(&t), reference(&t));
            (0..3).map(|i| (a[i] - b[i]).abs()).fold(0.0, f64::max)
        })
        .fold(0.0, f64::max)
}
