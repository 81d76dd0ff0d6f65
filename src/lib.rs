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
//! - [`dem`]: the simulator core — geometry, bodies, contacts, water, the energy ledger and
//!   the time step.
//! - [`itd`]: thickness-distribution physics (category bounds, participation, ridged-ice
//!   redistribution, ice strength, the ridging step) on plain per-column slices.
//! - [`io`]: NetCDF reading and writing of gridded thickness distributions.

pub mod dem;
pub mod io;
pub mod itd;
pub mod plot;
