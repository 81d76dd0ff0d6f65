//! Helpers of the simulator's integration tests: the contact law tests' worlds ([`pair`]) and
//! a small seeded generator. The root package's helpers (the command-line binary, NetCDF
//! inputs, the column step) are `tests/common/` of the repository: these tests need none of
//! them, nor anything of the crates above this one.
#![allow(dead_code)]

pub mod pair;

mod rng;
#[allow(unused_imports)] // not every test binary that includes this module draws noise
pub use rng::Rng;
