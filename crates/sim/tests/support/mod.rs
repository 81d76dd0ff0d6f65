//! Helpers of the simulator's integration tests: the contact law tests' worlds ([`pair`]) and
//! a small seeded generator. The repository's shared helpers (the command-line binary for
//! crates/cli's tests, NetCDF inputs, the column step) are `tests/common/`: these tests need
//! none of them, nor anything of the crates above this one.
#![allow(dead_code)]

pub mod pair;

mod rng;
#[allow(unused_imports)] // not every test binary that includes this module draws noise
pub use rng::Rng;
