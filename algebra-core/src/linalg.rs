//! Small dense linear solves over a [`Field`], shared by the runtime inverse and generated
//! kernels' `inverse`.

use crate::scalar::Field;

/// Solves `l · y = rhs` by Gaussian elimination with partial pivoting. Pivots are compared
/// and tested in the scalar's own precision and range ([`cmp_magnitude`](crate::Ring::cmp_magnitude),
/// [`is_negligible`](crate::Ring::is_negligible)): for exact fields only an exact zero is a zero pivot, however
/// small the others are; for floats a pivot below `64 · ε · n · max|entry|` counts as zero.
/// Returns `None` for a singular matrix.
///
/// ```
/// use algebra_core::{linalg::solve, rational::{q, ratio}};
/// let l = vec![vec![q(2), q(1)], vec![q(1), q(3)]];
/// assert_eq!(solve(l, vec![q(1), q(0)]), Some(vec![ratio(3, 5), ratio(-1, 5)]));
/// assert_eq!(solve(vec![vec![q(1), q(2)], vec![q(2), q(4)]], vec![q(1), q(0)]), None);
/// ```
#[allow(clippy::needless_range_loop)] // row operations read clearest with indices
pub fn solve<T: Field>(mut l: Vec<Vec<T>>, mut rhs: Vec<T>) -> Option<Vec<T>> {
    let n = rhs.len();
    if n == 0 {
        return Some(Vec::new());
    }
    let scale = l.iter().flatten().reduce(|a, b| if b.cmp_magnitude(a).is_gt() { b } else { a })?.clone();
    let ulps = u32::try_from(n).unwrap_or(u32::MAX).saturating_mul(64);
    for col in 0..n {
        let pivot =
            (col..n).filter(|&r| !l[r][col].is_exact_zero()).max_by(|&a, &b| l[a][col].cmp_magnitude(&l[b][col]))?;
        if l[pivot][col].is_negligible(&scale, ulps) {
            return None;
        }
        l.swap(pivot, col);
        rhs.swap(pivot, col);
        let inv = l[col][col].try_recip()?;
        for r in col + 1..n {
            if l[r][col].is_exact_zero() {
                continue;
            }
            let f = l[r][col].mul_ref(&inv);
            for c in col..n {
                let d = f.mul_ref(&l[col][c]);
                l[r][c].sub_assign_ref(&d);
            }
            let d = f.mul_ref(&rhs[col]);
            rhs[r].sub_assign_ref(&d);
        }
    }
    let mut y = vec![T::zero(); n];
    for row in (0..n).rev() {
        let mut acc = rhs[row].clone();
        for c in row + 1..n {
            acc.sub_assign_ref(&l[row][c].mul_ref(&y[c]));
        }
        y[row] = acc.div_ref(&l[row][row]);
    }
    Some(y)
}
