//! Column storage shared by [`Points`](super::Points) (3 columns) and [`Poses`](super::Poses)
//! (8 columns), the row-wise kernel driver (serial and over cores), and [`Packed`] lane chunks.

use super::Lanes;

/// `N` columns of equal length.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Columns<T, const N: usize> {
    pub(crate) cols: [Vec<T>; N],
}

impl<T: Clone, const N: usize> Columns<T, N> {
    /// `n` rows equal to `fill`.
    pub(crate) fn filled(n: usize, fill: &[T; N]) -> Self {
        Columns { cols: std::array::from_fn(|c| vec![fill[c].clone(); n]) }
    }

    /// The rows of an iterator, in order.
    pub(crate) fn from_rows(rows: impl IntoIterator<Item = [T; N]>) -> Self {
        let mut cols: [Vec<T>; N] = std::array::from_fn(|_| Vec::new());
        for row in rows {
            for (col, x) in cols.iter_mut().zip(row) {
                col.push(x);
            }
        }
        Columns { cols }
    }

    pub(crate) fn len(&self) -> usize {
        self.cols.first().map_or(0, Vec::len)
    }

    pub(crate) fn row(&self, i: usize) -> Option<[T; N]> {
        (i < self.len()).then(|| std::array::from_fn(|c| self.cols[c][i].clone()))
    }

    pub(crate) fn views(&self) -> [&[T]; N] {
        std::array::from_fn(|c| self.cols[c].as_slice())
    }

    pub(crate) fn views_mut(&mut self) -> [&mut [T]; N] {
        self.cols.each_mut().map(|c| c.as_mut_slice())
    }
}

impl<T: algebra_core::Ring, const N: usize> Columns<T, N> {
    /// `Ok` when every value is finite, else [`BatchError::NotFinite`](super::BatchError) for the
    /// first row that is not, printed by `show`.
    pub(crate) fn check_finite(
        &self,
        what: &'static str,
        show: impl Fn([T; N]) -> String,
    ) -> Result<(), super::BatchError> {
        match (0..self.len()).find(|&i| !self.cols.iter().all(|c| c[i].is_finite_value())) {
            Some(index) => {
                Err(super::BatchError::NotFinite { what, index, value: show(self.row(index).expect("index < len")) })
            }
            None => Ok(()),
        }
    }
}

/// The first column whose length differs from `n`: `(column, its length)`.
pub(crate) fn first_mismatch<T, const N: usize>(cols: &[Vec<T>; N], n: usize) -> Option<(usize, usize)> {
    cols.iter().enumerate().map(|(c, v)| (c, v.len())).find(|&(_, len)| len != n)
}

/// Runs `f` on every chunk of [`Lanes::WIDTH`] rows of `inputs` (the last chunk padded with
/// `pad`) and stores its lanes in `out`. `f` returns the failing lane on error; the result is
/// then the failing row (relative to these slices). Every input and output has `out[0]`'s length.
pub(crate) fn map_rows<L: Lanes, const I: usize, const O: usize>(
    inputs: [&[L::Elem]; I],
    pad: &[L::Elem; I],
    mut out: [&mut [L::Elem]; O],
    f: &impl Fn([L; I]) -> Result<[L; O], usize>,
) -> Result<(), usize> {
    let n = out.first().map_or(0, |o| o.len());
    let mut start = 0;
    while start < n {
        let end = n.min(start + L::WIDTH);
        let args: [L; I] = std::array::from_fn(|c| L::load_padded(&inputs[c][start..end], &pad[c]));
        let values = f(args).map_err(|lane| start + lane)?;
        for (o, v) in out.iter_mut().zip(&values) {
            v.store(&mut o[start..end]);
        }
        start = end;
    }
    Ok(())
}

/// Runs a row-wise kernel serially or over cores (`parallel`), mapping a failing row to
/// a [`BatchError`] through `describe`.
pub(crate) fn run<L: Lanes, const I: usize, const O: usize>(
    parallel: bool,
    inputs: [&[L::Elem]; I],
    pad: &[L::Elem; I],
    out: [&mut [L::Elem]; O],
    f: &(impl Fn([L; I]) -> Result<[L; O], usize> + Sync),
    describe: impl Fn(usize) -> super::BatchError,
) -> Result<(), super::BatchError> {
    #[cfg(feature = "parallel")]
    if parallel {
        return par_map_rows(inputs, pad, out, f).map_err(describe);
    }
    let _ = parallel;
    map_rows(inputs, pad, out, f).map_err(describe)
}

/// Rows per task of the parallel drivers: a multiple of every lane width, large enough that
/// scheduling costs nothing next to the work.
#[cfg(feature = "parallel")]
pub(crate) const BLOCK: usize = 8192;

/// The output columns cut into blocks of `block` rows: one `[&mut [T]; N]` per block.
#[cfg(feature = "parallel")]
pub(crate) fn split_views<T, const N: usize>(views: [&mut [T]; N], block: usize) -> Vec<[&mut [T]; N]> {
    let mut chunks = views.map(|c| c.chunks_mut(block));
    let mut blocks = Vec::new();
    loop {
        let next: [Option<&mut [T]>; N] = std::array::from_fn(|c| chunks[c].next());
        if next.iter().any(Option::is_none) {
            return blocks;
        }
        blocks.push(next.map(|c| c.expect("checked above")));
    }
}

/// [`map_rows`] over blocks of [`BLOCK`] rows on rayon's thread pool. On failure, the smallest
/// failing row is reported (the same as the serial driver).
#[cfg(feature = "parallel")]
pub(crate) fn par_map_rows<L: Lanes, const I: usize, const O: usize>(
    inputs: [&[L::Elem]; I],
    pad: &[L::Elem; I],
    out: [&mut [L::Elem]; O],
    f: &(impl Fn([L; I]) -> Result<[L; O], usize> + Sync),
) -> Result<(), usize> {
    use rayon::prelude::*;
    let results: Vec<Result<(), usize>> = split_views(out, BLOCK)
        .into_par_iter()
        .enumerate()
        .map(|(b, block)| {
            let start = b * BLOCK;
            let end = start + block.first().map_or(0, |o| o.len());
            map_rows(inputs.map(|c| &c[start..end]), pad, block, f).map_err(|row| start + row)
        })
        .collect();
    results.into_iter().collect()
}

/// Columns packed into lane chunks: chunk `k` holds rows `k·W .. k·W + W` (`W` =
/// [`Lanes::WIDTH`]), the last chunk padded when the row count is not a multiple of `W`
/// (zeros for points, the identity for poses). Made by [`Points::pack`](super::Points::pack)
/// and [`Poses::pack`](super::Poses::pack); back with `unpack`.
///
/// ```
/// use motion::batch::Points;
/// let p = Points::from_points(&[[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]).unwrap();
/// let packed = p.pack::<f64>();
/// assert_eq!((packed.len(), packed.chunks()), (2, 2));
/// assert_eq!(packed.chunk(1), Some([4.0, 5.0, 6.0]));
/// assert_eq!(packed.unpack_points(), p);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Packed<L, const N: usize> {
    pub(crate) cols: Columns<L, N>,
    pub(crate) len: usize,
}

impl<L: Lanes, const N: usize> Packed<L, N> {
    pub(crate) fn pack(views: [&[L::Elem]; N], pad: &[L::Elem; N]) -> Self {
        let len = views.first().map_or(0, |c| c.len());
        let chunks = (0..len).step_by(L::WIDTH).map(|start| {
            let end = len.min(start + L::WIDTH);
            std::array::from_fn(|c| L::load_padded(&views[c][start..end], &pad[c]))
        });
        Packed { cols: Columns::from_rows(chunks), len }
    }

    pub(crate) fn unpack(&self, fill: &[L::Elem; N]) -> Columns<L::Elem, N> {
        let mut out = Columns::filled(self.len, fill);
        let mut views = out.views_mut();
        for (k, start) in (0..self.len).step_by(L::WIDTH).enumerate() {
            let end = self.len.min(start + L::WIDTH);
            for (o, col) in views.iter_mut().zip(&self.cols.cols) {
                col[k].store(&mut o[start..end]);
            }
        }
        out
    }

    /// The number of rows (elements), without the padding.
    ///
    /// ```
    /// let p = motion::batch::Points::from_points(&[[0.0; 3]; 5]).unwrap();
    /// assert_eq!(p.pack::<f64>().len(), 5);
    /// ```
    pub fn len(&self) -> usize {
        self.len
    }

    /// True when there are no rows.
    ///
    /// ```
    /// let p = motion::batch::Points::<f64>::from_points(&[]).unwrap();
    /// assert!(p.pack::<f64>().is_empty());
    /// ```
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The number of chunks, `⌈len / W⌉`.
    ///
    /// ```
    /// let p = motion::batch::Points::from_points(&[[0.0; 3]; 5]).unwrap();
    /// assert_eq!(p.pack::<f64>().chunks(), 5);
    /// ```
    pub fn chunks(&self) -> usize {
        self.cols.len()
    }

    /// Chunk `k`: one lane value per column.
    ///
    /// ```
    /// let p = motion::batch::Points::from_points(&[[1.0, 2.0, 3.0]]).unwrap();
    /// assert_eq!(p.pack::<f64>().chunk(0), Some([1.0, 2.0, 3.0]));
    /// assert_eq!(p.pack::<f64>().chunk(1), None);
    /// ```
    pub fn chunk(&self, k: usize) -> Option<[L; N]> {
        self.cols.row(k)
    }

    /// The lane values of column `c` (one per chunk).
    ///
    /// ```
    /// let p = motion::batch::Points::from_points(&[[1.0, 2.0, 3.0]]).unwrap();
    /// assert_eq!(p.pack::<f64>().column(2), &[3.0]);
    /// ```
    pub fn column(&self, c: usize) -> &[L] {
        &self.cols.cols[c]
    }
}
