//! A test fixture shared by the simulator's tests and the tables' readers in the crate
//! `pressridge` (which includes this file by path, as test code cannot cross crates).

/// A `summary.json` of a run at t = 1 s without its ledger terms, for tests.
pub(crate) fn summary_without_ledger() -> serde_json::Value {
    serde_json::json!({
        "scene": "x", "seed": 1, "version": "v", "time": 1.0, "steps": 1, "dt": 1.0,
        "wall_seconds": 0.0, "bodies": 0, "work_eq9": 0.5, "max_relative_residual": 0.0,
        "ratio_work_to_pe": 0.0, "ridged_volume": 0.0, "blocks_broken": 0,
        "rubble_block_lengths": []
    })
}
