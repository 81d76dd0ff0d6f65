//! What a batched strength call counts: the columns, and those whose C_f or μ_rdg table
//! lookups were clamped at the table's ends.

use super::{CF_CLAMPED_MATERIAL_SHARE, ColumnStrength};

/// Summary of a batched call.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BatchSummary {
    /// Columns computed.
    pub columns: usize,
    /// Columns where a C_f table was queried outside its range (values clamped).
    pub cf_clamped_columns: usize,
    /// Of these, the columns where the clamped categories carry at least
    /// [`CF_CLAMPED_MATERIAL_SHARE`] of P ([`ColumnStrength::cf_clamped_share`]).
    pub cf_clamped_material_columns: usize,
    /// The largest [`ColumnStrength::cf_clamped_share`] of any column (dimensionless, 0–1).
    pub cf_clamped_share_max: f64,
    /// Columns where a μ_rdg table was queried outside its range for a ridging category
    /// ([`ColumnStrength::mu_rdg_clamped`]).
    pub mu_rdg_clamped_columns: usize,
}

impl BatchSummary {
    /// Counts one column's result.
    pub(super) fn add(&mut self, r: &ColumnStrength) {
        self.cf_clamped_columns += usize::from(r.cf_clamped);
        self.cf_clamped_material_columns +=
            usize::from(r.cf_clamped_share >= CF_CLAMPED_MATERIAL_SHARE);
        self.cf_clamped_share_max = self.cf_clamped_share_max.max(r.cf_clamped_share);
        self.mu_rdg_clamped_columns += usize::from(r.mu_rdg_clamped);
    }
}
