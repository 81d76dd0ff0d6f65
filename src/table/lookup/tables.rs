//! A set's row of a ridging table as the table a host-model routine takes: C_f for the
//! Rothrock strength ([`CfTable`]) and μ_rdg for the exponential redistribution
//! ([`MuRdgTable`], issue 34), each over the table's thicknesses, NaN cells left out.

use super::{Field, LookupError, RidgeLookup};
use crate::itd::details::{CfLookup, CfTable, MuRdgTable};
use ndarray::Axis;

impl RidgeLookup {
    /// C_f (dimensionless, the ensemble mean of the final W/ΔPE) of set `set` for ridging ice
    /// of thickness `thickness` (m), from the field `cf_by_set`.
    pub fn cf(&self, set: usize, thickness: f64) -> Result<CfLookup, LookupError> {
        let l = self.value("cf_by_set", set, thickness, 0.0)?;
        Ok(CfLookup {
            value: l.value,
            clamped: l.clamped,
        })
    }

    /// The C_f at friction (`mu`, `mu_w`) as a [`CfTable`] for the strength routine:
    /// [`RidgeLookup::friction_set`], then [`RidgeLookup::cf_table`].
    pub fn cf_table_at_friction(&self, mu: f64, mu_w: f64) -> Result<CfTable, LookupError> {
        self.cf_table(self.friction_set(mu, mu_w)?)
    }

    /// Set `set`'s row of a field on (set, thickness): its values at the table's thicknesses.
    fn set_row<'a>(&self, f: &'a Field, set: usize) -> Result<&'a [f64], LookupError> {
        if set >= self.sets.len() {
            return Err(LookupError::Set {
                set,
                nsets: self.sets.len(),
            });
        }
        let row = f.data.index_axis(Axis(0), set);
        Ok(row
            .to_slice()
            .expect("standard layout, by RidgeLookup::new"))
    }

    /// The C_f of set `set` as a [`CfTable`] for the strength routine: the thicknesses whose
    /// C_f is not NaN (a cell no run reached), by the one rule of [`CfTable::from_nodes`]
    /// (any other value not finite and positive is an error), labelled with the set's
    /// friction when the table has it.
    pub fn cf_table(&self, set: usize) -> Result<CfTable, LookupError> {
        let f = self
            .fields
            .get("cf_by_set")
            .ok_or_else(|| LookupError::UnknownField {
                name: "cf_by_set".into(),
                known: self.variables().collect::<Vec<_>>().join(", "),
            })?;
        let t = CfTable::from_nodes(&self.thickness, self.set_row(f, set)?)
            .map_err(|e| LookupError::Invalid(format!("cf_by_set of set {set}: {e}")))?;
        Ok(match self.friction() {
            Some(pairs) => t.with_friction(pairs[set].0, pairs[set].1),
            None => t,
        })
    }

    /// The μ_rdg of set `set` as a [`MuRdgTable`] for the exponential redistribution
    /// ([`crate::itd::details::Redistribution::Table`]): the thicknesses whose `mu_rdg` is not NaN,
    /// by the one rule of [`MuRdgTable::from_nodes`]. A table made from records without
    /// ridge columns has no `mu_rdg`: the error says so.
    pub fn mu_rdg_table(&self, set: usize) -> Result<MuRdgTable, LookupError> {
        let f = self.fields.get("mu_rdg").ok_or_else(|| {
            LookupError::Invalid(
                "the table has no `mu_rdg`: its runs kept no ridge columns (records written \
                 before 2026-11-28); tabulate records that have them"
                    .into(),
            )
        })?;
        let row = self.set_row(f, set)?;
        MuRdgTable::from_nodes(&self.thickness, row).map_err(|e| {
            let why = if row.iter().all(|m| m.is_nan()) {
                format!(
                    "{e}: none of the set's runs kept ridge columns (ridged_runs = 0); run its \
                     campaign again with a binary that keeps them"
                )
            } else {
                e.to_string()
            };
            LookupError::Invalid(format!("mu_rdg of set {set}: {why}"))
        })
    }

    /// [`RidgeLookup::mu_rdg_table`] of the set with friction μ above and μ_w below the water
    /// line (dimensionless).
    pub fn mu_rdg_table_at_friction(&self, mu: f64, mu_w: f64) -> Result<MuRdgTable, LookupError> {
        self.mu_rdg_table(self.friction_set(mu, mu_w)?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::lookup::{Axes, Field};
    use ndarray::Array;
    use std::collections::BTreeMap;

    #[test]
    fn a_sets_mu_rdg_is_its_nodes_with_data() {
        let mu = vec![2.0, f64::NAN, 1.5, 1.8, 1.9, 2.1];
        let t = RidgeLookup::new(
            vec!["a".into(), "b".into()],
            vec![0.2, 0.3, 0.5],
            vec![0.0, 1.0],
            vec![(
                "mu_rdg".into(),
                Field::new(
                    Axes::SET_THICKNESS,
                    "m^0.5",
                    "mu",
                    Array::from_shape_vec((2, 3), mu).unwrap().into_dyn(),
                ),
            )],
            BTreeMap::new(),
        )
        .unwrap();
        let a = t.mu_rdg_table(0).unwrap();
        assert_eq!(
            (a.thickness(), a.values()),
            (&[0.2, 0.5][..], &[2.0, 1.5][..])
        );
        assert_eq!(t.mu_rdg_table(1).unwrap().values(), [1.8, 1.9, 2.1]);
        assert!(matches!(t.mu_rdg_table(2), Err(LookupError::Set { .. })));
        let none = RidgeLookup::new(
            vec!["a".into()],
            vec![0.2],
            vec![0.0],
            vec![],
            BTreeMap::new(),
        )
        .unwrap();
        let e = none.mu_rdg_table(0).unwrap_err().to_string();
        assert!(
            e.contains("no `mu_rdg`") && e.contains("ridge columns"),
            "{e}"
        );
        let nan = RidgeLookup::new(
            vec!["a".into()],
            vec![0.2, 0.3],
            vec![0.0],
            vec![(
                "mu_rdg".into(),
                Field::new(
                    Axes::SET_THICKNESS,
                    "m^0.5",
                    "mu",
                    Array::from_elem((1, 2), f64::NAN).into_dyn(),
                ),
            )],
            BTreeMap::new(),
        )
        .unwrap();
        let e = nan.mu_rdg_table(0).unwrap_err().to_string();
        assert!(e.contains("ridged_runs = 0"), "{e}");
    }
}
