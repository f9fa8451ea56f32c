//! A deterministic generator for the library's unit tests (xorshift64): the
//! same cases on every run, no dependency.

/// Xorshift64 state.
pub(crate) struct TestRng(u64);

impl TestRng {
    /// A generator from a nonzero seed.
    pub(crate) fn new(seed: u64) -> Self {
        TestRng(seed.max(1))
    }
    /// A uniform-ish integer in `[-m, m]`.
    pub(crate) fn int(&mut self, m: i64) -> i64 {
        let s = &mut self.0;
        *s ^= *s << 13;
        *s ^= *s >> 7;
        *s ^= *s << 17;
        (*s % (2 * m as u64 + 1)) as i64 - m
    }
}
