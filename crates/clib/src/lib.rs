//! `libpressridge.so` and `libpressridge.a`: the C ABI of `pressridge-capi` (header
//! `include/pressridge.h`, Fortran module in `fortran-bridge/`, `docs/c-api.md`), linked as
//! the C library. Every `#[no_mangle] extern "C"` function of that crate is exported from here.

#![warn(missing_docs)]

pub use pressridge_capi::*;
