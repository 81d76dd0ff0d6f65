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
//!   redistribution, ice strength, the ridging step, on plain per-column slices (the crate
//!   `pressridge-column`, which a host model can depend on alone);
//! - [`io`] — files (JSON states and summaries, CSV time series, NetCDF distributions);
//! - `plot` — figures (feature `plot`, on by default with `cli`);
//! - [`table`] — regressions of ridging ensembles (work and potential energy against ridged
//!   volume, eqs 13–16) for tabulation.
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
//!
//! ## Example: a small ridging run
//!
//! ```
//! use pressridge::{observe, scene::Scene, simulation};
//!
//! // A small version of the paper's Figure 5 experiment: a lead-ice sheet 3 m long and
//! // 0.30 m thick pushed at 0.25 m/s for 3 s against a 4 m floe. Keys left out take their
//! // defaults (Hopkins 1994, Table 1; `pressridge simulate --print-scene` lists them all).
//! let scene = Scene::from_toml(
//!     r#"
//!     name = "small"
//!     duration = 3.0  # s
//!     [sheet]
//!     length = 3.0    # m
//!     [floe]
//!     length = 4.0    # m
//!     "#,
//! )?;
//! // The observer sees the world at every sample; returning false stops the run there.
//! let out = simulation::run(&scene, &mut |_world| true)?;
//!
//! // The summary. Energies are J per metre of ridge, changes since the start of the run.
//! let s = &out.summary;
//! let e = s.energy();
//! assert!(e.work > 0.0 && e.potential_energy > 0.0);
//! assert!(e.residual.abs() < 1e-6 * e.work); // the energy budget closes
//! println!(
//!     "t = {:.1} s: V = {:.3} m³/m, work/ΔPE = {:.1}, {} joints broken",
//!     s.time, s.ridged_volume, s.ratio_work_to_pe, s.blocks_broken
//! );
//!
//! // The time series, one sample every `numerics.sample_interval` (0.2 s by default); a
//! // sample's row has the columns (name, unit) of `series_columns()`, as series.csv.
//! let last = out.series.last().unwrap();
//! assert_eq!(last.row().len(), simulation::series_columns().len());
//! println!("ridging force at the end: {:.0} N/m", last.ridging_force);
//!
//! // The ridge at the end: profile in 32 strips of 1 m from x = -20 m (10 sample lines a
//! // strip), then its metrics (heights m, cross-sections m²/m, flank slopes degrees).
//! let p = observe::profile(&out.final_state, -20.0, 1.0, 32, 10);
//! let m = observe::metrics(&p, None);
//! assert!(m.max_keel_depth > 0.0 && m.keel_area > 0.0); // the rubble's keel
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
pub mod dem;
pub mod energy;
pub mod eta;
pub mod io;
/// The column physics (thickness distribution, strength, ridging step): the crate
/// `pressridge-column`, which a host can link alone.
pub use pressridge_column as itd;
pub mod limits;
pub mod observe;
#[cfg(feature = "plot")]
pub mod plot;
pub mod record;
pub mod scene;
pub mod simulation;
pub mod table;
