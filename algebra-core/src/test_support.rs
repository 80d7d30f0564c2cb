//! Deterministic random instances for tests and benches (feature `test-support`, off by
//! default, so a kernel user's build never contains it): one xorshift64 generator shared by
//! every crate's tests instead of a copy per test file. Property tests use proptest; this is
//! for fixed-seed samples outside it (benches, fuzz tables, random poses).
//!
//! ```
//! use algebra_core::test_support::Xorshift;
//! let mut rng = Xorshift(0x9e37_79b9_7f4a_7c15);
//! let x = rng.symmetric();
//! assert!((-1.0..1.0).contains(&x));
//! assert!(rng.below(6) < 6);
//! // the same seed gives the same sequence
//! assert_eq!(Xorshift(7).next_u64(), Xorshift(7).next_u64());
//! ```

/// Marsaglia's xorshift64 (shifts 13, 7, 17). The seed must not be zero (zero is a fixed point).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Xorshift(pub u64);

impl Xorshift {
    /// The next raw 64-bit state.
    ///
    /// ```
    /// // 1 -> 1 ^ 1 << 13 = 8193 -> 8193 ^ 8193 >> 7 = 8257 -> 8257 ^ 8257 << 17
    /// assert_eq!(algebra_core::test_support::Xorshift(1).next_u64(), 8257 ^ (8257 << 17));
    /// ```
    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    /// Uniform in `[0, 1)`: the top 53 bits of the next state over `2^53`.
    ///
    /// ```
    /// let u = algebra_core::test_support::Xorshift(3).unit();
    /// assert!((0.0..1.0).contains(&u));
    /// ```
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in `[-1, 1)` (`2 unit - 1`, exactly).
    ///
    /// ```
    /// let (mut a, mut b) = (algebra_core::test_support::Xorshift(5), algebra_core::test_support::Xorshift(5));
    /// assert_eq!(a.symmetric(), 2.0 * b.unit() - 1.0);
    /// ```
    pub fn symmetric(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }

    /// Three [`Self::symmetric`] values.
    ///
    /// ```
    /// let v = algebra_core::test_support::Xorshift(11).vec3();
    /// assert!(v.iter().all(|x| (-1.0..1.0).contains(x)));
    /// ```
    pub fn vec3(&mut self) -> [f64; 3] {
        [self.symmetric(), self.symmetric(), self.symmetric()]
    }

    /// An index below `n` (`next_u64 % n`; `n > 0`).
    ///
    /// ```
    /// assert!(algebra_core::test_support::Xorshift(9).below(10) < 10);
    /// ```
    pub fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n as u64) as usize
    }

    /// One element of a non-empty slice, chosen by [`Self::below`].
    ///
    /// ```
    /// let x = algebra_core::test_support::Xorshift(13).pick(&["a", "b"]);
    /// assert!(x == "a" || x == "b");
    /// ```
    pub fn pick<'a, X: ?Sized>(&mut self, xs: &[&'a X]) -> &'a X {
        xs[self.below(xs.len())]
    }
}
