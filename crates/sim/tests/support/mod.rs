//! Helpers of the simulator's integration tests: the contact law tests' worlds ([`pair`]) and
//! a small seeded generator. The root package's helpers (the command-line binary, NetCDF
//! inputs, the column step) are `tests/common/` of the repository: these tests need none of
//! them, nor anything of the crates above this one.
#![allow(dead_code)]

pub mod pair;

/// A small deterministic pseudo-random generator (SplitMix64), as `tests/common`'s.
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in 0..n.
    pub fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}
