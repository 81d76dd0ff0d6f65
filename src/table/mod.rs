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
//! - [`choices`] — the measured effect of each open modelling choice (probe campaigns
//!   against a baseline);
//! - [`findings`] — the paper's stated findings tested on ensembles (the statement table of
//!   `pressridge findings`);
//! - [`rafting`] — which runs rafted over the floe instead of ridging against it;
//! - [`redistribution`] — the thickness distribution of the simulated ridged ice, with
//!   Lipscomb's exponential (μ_rdg) and Hibler's uniform (H*) fitted to it;
//! - [`fit::student_t_cdf`], [`fit::student_t_quantile`] — Student's t CDF and quantile for
//!   the confidence intervals;
//! - [`lookup`] — interpolation in a tabulated campaign (clamped and flagged outside its
//!   range, NaN where no run reached), read back from NetCDF by `RidgeLookup::open`.

pub mod choices;
pub mod ensemble;
pub mod fields;
pub mod findings;
pub mod fit;
pub mod lookup;
pub mod rafting;
pub mod redistribution;
pub(crate) mod student_t;
pub mod tabulate;

/// A `summary.json` of a run at t = 1 s without its ledger terms, for the tests of the
/// readers here (a copy of `pressridge_sim::simulation`'s, which is private to its tests).
#[cfg(test)]
pub(crate) fn summary_without_ledger() -> serde_json::Value {
    serde_json::json!({
        "scene": "x", "seed": 1, "version": "v", "time": 1.0, "steps": 1, "dt": 1.0,
        "wall_seconds": 0.0, "bodies": 0, "work_eq9": 0.5, "max_relative_residual": 0.0,
        "ratio_work_to_pe": 0.0, "ridged_volume": 0.0, "blocks_broken": 0,
        "rubble_block_lengths": []
    })
}
