//! The μ_rdg of a ridging table as the redistribution's table (issue 34): one friction set's
//! `mu_rdg` against thickness.

use super::{LookupError, RidgeLookup};
use crate::itd::MuRdgTable;
use ndarray::Axis;

impl RidgeLookup {
    /// The μ_rdg of set `set` as a [`MuRdgTable`] for the exponential redistribution
    /// ([`crate::itd::Redistribution::Table`]): the thicknesses whose `mu_rdg` is not NaN,
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
        if set >= self.sets.len() {
            return Err(LookupError::Set {
                set,
                nsets: self.sets.len(),
            });
        }
        let row = f.data.index_axis(Axis(0), set);
        let row = row
            .as_slice()
            .expect("standard layout, by RidgeLookup::new");
        MuRdgTable::from_nodes(&self.thickness, row)
            .map_err(|e| LookupError::Invalid(format!("mu_rdg of set {set}: {e}")))
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
    }
}
