//! Tabulation of ridging ensembles for large-scale ice models.
//!
//! - [`ensemble`] — per grid point, mean and spread over the seeds of the final energy
//!   budget, W/ΔPE and the ridge metrics;
//! - [`fit`] — least-squares fits of work and potential energy against ridged volume
//!   (Hopkins 1994, eqs 13–16), with confidence and prediction bands;
//! - [`tabulate`] — campaign records to a lookup table (ensemble statistics on a volume
//!   grid, fits per thickness and pooled, C_f per thickness);
//! - [`crate::campaign::tabulation`] — campaign directories to a table: the pipeline of
//!   `pressridge tabulate` and Python's `tabulate` (reading, pooling, rafting exclusion,
//!   provenance);
//! - [`rafting`] — which runs rafted over the floe instead of ridging against it;
//! - [`redistribution`] — the thickness distribution of the simulated ridged ice, with
//!   Lipscomb's exponential (μ_rdg) and Hibler's uniform (H*) fitted to it;
//! - [`fit::student_t_cdf`], [`fit::student_t_quantile`] — Student's t CDF and quantile for
//!   the confidence intervals;
//! - [`lookup`] — interpolation in a tabulated campaign (clamped and flagged outside its
//!   range, NaN where no run reached), read back from NetCDF by `RidgeLookup::open`.

pub mod ensemble;
pub mod fields;
pub mod fit;
pub mod lookup;
pub mod rafting;
pub mod redistribution;
pub(crate) mod student_t;
pub mod tabulate;

// The simulator's fixture of a `summary.json` without its ledger terms, for the tests of the
// readers here (one file, included by path: test code cannot cross crates).
#[cfg(test)]
#[path = "../../crates/sim/src/simulation/summary_fixture.rs"]
mod summary_fixture;
#[cfg(test)]
pub(crate) use summary_fixture::summary_without_ledger;
