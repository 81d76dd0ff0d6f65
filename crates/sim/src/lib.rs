//! # pressridge-sim
//!
//! A two-dimensional discrete-element model of a pressure ridge growing from an intact
//! lead-ice sheet pushed against a thick floe (Hopkins 1994, *J. Geophys. Res.* 99(C8),
//! 16351–16360): the scene, the world and its step, the energy ledger of eqs (9)–(12), a run
//! and its summary, the ridge observed, and the record of a finished run.
//!
//! Units are SI throughout: metres, seconds, kilograms, newtons, joules, pascals. The
//! simulator is two-dimensional with a depth of 1 m, so its "forces" are forces per metre of
//! ridge (N/m), its "areas" are volumes per metre (m²), and its energies are J/m.
//!
//! This crate is the simulator alone. Ensembles over parameter grids, the ridging tables,
//! files (JSON states, CSV series, NetCDF), figures and the command line are the crate
//! `pressridge` above it, which re-exports these modules under the same names
//! (`pressridge::dem::World` is [`dem::World`]); the thickness-distribution physics is the
//! crate `pressridge-column` below it.
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
//!
//! One level down: [`limits`] (the valid range of every bounded parameter, with its
//! reason), [`energy`] (the budget of eqs (9)–(12) as data, and the one table of its terms),
//! [`record`] (a finished run's record, `run.json`) and [`eta`] (progress estimates).
//!
//! Layers, bottom to top (no module reaches back up; `tests/layers.rs` of the workspace
//! checks it): `limits`, `eta`, `energy` → `dem` → `scene`, `observe` → `simulation` →
//! `record`.
//!
//! ## Example: a small ridging run
//!
//! ```
//! use pressridge_sim::{observe, scene::Scene, simulation};
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

#![warn(missing_docs)]

pub mod dem;
pub mod energy;
pub mod eta;
pub mod limits;
pub mod observe;
pub mod record;
pub mod scene;
pub mod simulation;
