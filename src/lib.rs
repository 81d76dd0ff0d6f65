//! # pressridge
//!
//! A two-dimensional discrete-element model of a pressure ridge growing from an intact
//! lead-ice sheet pushed against a thick floe (Hopkins 1994, *J. Geophys. Res.* 99(C8),
//! 16351–16360), and the Thorndike–Rothrock machinery that turns ridging energetics into
//! large-scale ice strength.
//!
//! Units are SI throughout. The simulator is two-dimensional with a depth of 1 m, so its
//! "forces" are forces per metre of ridge (N/m), its "areas" are volumes per metre (m²),
//! and its energies are J/m.
//!
//! Layout (data flows one way, no module reaches back up):
//! - [`dem`] — the simulator core — geometry, bodies, contacts, water, the energy ledger and
//!   the time step;
//! - [`scene`] — every parameter of a run, from TOML, with defaults and validation;
//! - [`limits`] — the valid range of every bounded parameter, with its reason;
//! - [`simulation`] — running a scene and summarising it;
//! - [`observe`] — ridge profiles and metrics from a state;
//! - [`campaign`] — seeded ensembles over parameter grids, resumable;
//! - [`itd`] — thickness-distribution physics: category bounds, participation, ridged-ice
//!   redistribution, ice strength, the ridging step, on plain per-column slices;
//! - [`io`] — files (JSON states and summaries, CSV time series, NetCDF distributions);
//! - [`plot`] — figures;
//! - [`ffi`] — the C ABI (`include/pressridge.h`) for C and Fortran host models;
//! - [`table`] — regressions of ridging ensembles (work and potential energy against ridged
//!   volume, eqs 13–16) for tabulation.
//!

pub mod campaign;
pub mod dem;
pub mod eta;
pub mod ffi;
pub(crate) mod interp;
pub mod io;
pub mod itd;
pub mod limits;
pub mod observe;
pub mod plot;
pub mod record;
pub mod scene;
pub mod simulation;
pub mod table;
