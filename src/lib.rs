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
//! - the simulator, the crate `pressridge-sim` re-exported under the same names
//!   (`pressridge::dem::World` is `pressridge_sim::dem::World`): [`dem`] (geometry, bodies,
//!   contacts, water, the energy ledger and the time step), [`scene`] (every parameter of a
//!   run, from TOML, with defaults and validation), [`limits`] (the valid range of every
//!   bounded parameter, with its reason), [`energy`] (the budget of eqs 9–12 as data),
//!   [`simulation`] (running a scene and summarising it), [`observe`] (ridge profiles and
//!   metrics from a state), [`record`] (a finished run's record) and [`eta`] (progress
//!   estimates);
//! - [`itd`] — thickness-distribution physics: category bounds, participation, ridged-ice
//!   redistribution, ice strength, the ridging step, on plain per-column slices (the crate
//!   `pressridge-column`, which a host model can depend on alone);
//! - [`table`] — regressions of ridging ensembles (work and potential energy against ridged
//!   volume, eqs 13–16) for tabulation;
//! - [`io`] — files (JSON states and summaries, CSV time series, NetCDF distributions);
//! - [`campaign`] — seeded ensembles over parameter grids, resumable;
//! - `plot` — figures (feature `plot`, off by default; the command line turns it on).
//!
//! Above this crate: the command line `pressridge`, the crate `pressridge-cli` (`crates/cli`,
//! one module per command, no physics), and the C ABI (`crates/capi`). This crate's default
//! features are none: a host or a library user builds no argument parser, progress bars or
//! plotting stack.
//!
//! ## Where to start
//!
//! - A run: a [`scene::Scene`] (TOML, defaults, `key=value` overrides, validation) run by
//!   [`simulation::run`], which returns the [`simulation::Summary`] (energies J/m, times s,
//!   ridged volume m³/m), the sampled time series and the final state ([`dem::Snapshot`]).
//! - Observation: [`observe::profile`] (sail heights and keel depths, m) and
//!   [`observe::metrics`] of a state.
//! - A world built by hand (verification scenes): [`dem::World`], stepped with
//!   [`dem::World::step`] and read through `&` accessors ([`dem::World::bodies`],
//!   [`dem::World::energy`], [`dem::World::snapshot`]).
//! - Files: [`io::state`] (JSON states and summaries), [`io::series`] (the CSV time series).
//! - Ensembles and tables: [`campaign`], [`campaign::tabulation::tabulate_campaigns`],
//!   [`table::fit`] (eqs 13–16), [`table::lookup::RidgeLookup`] (interpolation in a table).
//! - Thickness-distribution physics, on plain per-column slices or `(ncat, ncol)` arrays:
//!   ice strength P (N/m) [`itd::strength_column`] / [`itd::strength_batch`]; the ridging step
//!   of areas and volumes [`itd::ridge_column`] / [`itd::ridge_batch`], and the complete step
//!   with tracers, snow and ocean fluxes [`itd::ridge_step_column`] /
//!   [`itd::ridge_step_batch()`].
//! - C and Fortran hosts: the crate `pressridge-capi` (`crates/capi`, the C ABI and its
//!   header `include/pressridge.h`), built as `libpressridge.{so,a}` by `crates/clib`.
//! - The command line: the crate `pressridge-cli` (`crates/cli/src/main.rs`, one file per
//!   command; `cargo build --release --bin pressridge`; `docs/cli.md`).
//!
//! ## Example: a run and its files
//!
//! The simulator's own front (`pressridge-sim`, `crates/sim/src/lib.rs`) runs one and reads
//! its summary, series and ridge; through this crate the same code reads
//! `use pressridge::{observe, scene::Scene, simulation};`. The files are this crate's
//! ([`io::series`], [`io::state`]):
//!
//! ```
//! use pressridge::{io, scene::Scene, simulation};
//!
//! // 0.4 s of a 2 m sheet pushed against a 3 m floe (lengths in m).
//! let scene = Scene::from_toml("duration = 0.4\n[sheet]\nlength = 2.0\n[floe]\nlength = 3.0")?;
//! let out = simulation::run(&scene, &mut |_world| true)?;
//! let dir = std::env::temp_dir().join(format!("pressridge-doc-{}", std::process::id()));
//! std::fs::create_dir_all(&dir)?;
//! io::series::write_series_csv(&dir.join("series.csv"), &out.series)?; // `name (unit)` columns
//! io::state::save_state(&dir.join("final.json"), &out.final_state)?; // the world, restartable
//! let _state = io::state::load_state(&dir.join("final.json"))?;
//! std::fs::remove_dir_all(&dir)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! ## Example: ice strength from the shipped ridging table
//!
//! ```
//! use pressridge::itd::{Cf, StrengthOptions, Workspace, strength_column};
//! use pressridge::table::lookup::RidgeLookup;
//! use std::sync::Arc;
//!
//! // The simulator's table (`pressridge tabulate`), at friction μ = 1.0 above and
//! // μ_w = 0.6 below the water line (dimensionless).
//! let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data/ridging_table.nc");
//! let table = RidgeLookup::open(&path)?;
//! let set = table.friction_set(1.0, 0.6)?;
//! let work = table.value("work_mean", set, 0.3, 1.0)?; // J/m at h = 0.3 m, V = 1 m³/m
//! println!("work {:.3e} J/m (clamped to the table: {})", work.value, work.clamped);
//!
//! // Its C_f (work over potential energy, by ridging-ice thickness) in the Rothrock
//! // strength of one column of five categories: areas (dimensionless), volumes (m).
//! let opts = StrengthOptions {
//!     cf: Cf::Table(Arc::new(table.cf_table(set)?)),
//!     ..StrengthOptions::default()
//! };
//! let (aicen, vicen) = ([0.2, 0.3, 0.2, 0.15, 0.05], [0.06, 0.3, 0.38, 0.45, 0.2]);
//! let p = strength_column(&aicen, &vicen, None, &opts, &mut Workspace::new(5))?;
//! assert!(p.strength > 0.0); // N/m
//! // cf_clamped: some category lay outside the table's thickness range.
//! println!("P = {:.0} N/m, C_f clamped: {}", p.strength, p.cf_clamped);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!

#![warn(missing_docs)]

pub mod campaign;
pub mod io;
/// The column physics (thickness distribution, strength, ridging step): the crate
/// `pressridge-column`, which a host can link alone.
pub use pressridge_column as itd;
#[cfg(feature = "plot")]
pub mod plot;
pub mod table;
// The simulator: the crate `pressridge-sim`, its modules under their old paths (each module
// documented there).
pub use pressridge_sim::{dem, energy, eta, limits, observe, record, scene, simulation};
