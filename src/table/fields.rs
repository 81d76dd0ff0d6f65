//! The variables of a ridging table, each with its dimensions, units and description: one
//! list behind the NetCDF file (`crate::io::table_netcdf`) and the in-memory lookup
//! ([`RidgeTable::lookup`]), so that a table need not pass through a file to be queried. The
//! ledger terms among them (the ensemble mean and spread of work and ΔPE) take their names,
//! units and long names from the ledger's table ([`crate::energy::LEDGER_TERMS`]).

use super::fit::Band;
use super::lookup::{Axes, Field, LookupError, RidgeLookup};
use super::tabulate::{RidgeTable, SetFits};
use crate::energy::{LedgerTerm, term, term_file};
use ndarray::{Array, Array1, Array2, ArrayView1, CowArray, Dimension, IxDyn};

/// The values of a [`TableVariable`]: a view of the table's own array where the variable is
/// one of [`RidgeTable`]'s grid fields, else an array made from the table (fit
/// coefficients, bands, counts as `f64`).
pub type TableData<'a> = CowArray<'a, f64, IxDyn>;

/// One variable of a ridging table in the set layout: an array over `dims` (a subset of
/// `set`, `thickness`, `volume` in that order, the layout of [`RidgeTable`]'s grid fields),
/// NaN where no run reached.
#[derive(Clone, Debug, PartialEq)]
pub struct TableVariable<'a> {
    /// Name, as in the NetCDF file.
    pub name: String,
    /// Dimensions, outermost first.
    pub dims: &'static [&'static str],
    /// UDUNITS string.
    pub units: &'static str,
    /// Description.
    pub long_name: String,
    /// Values, one axis per entry of `dims`, in standard (C) layout.
    pub data: TableData<'a>,
}

/// A grid field of the table as it is: a view of its array.
fn view<D: Dimension>(x: &Array<f64, D>) -> TableData<'_> {
    CowArray::from(x.view().into_dyn())
}

/// A 1-D field or axis of the table (a `Vec`) as it is: a view of it.
fn axis(x: &[f64]) -> TableData<'_> {
    CowArray::from(ArrayView1::from(x).into_dyn())
}

/// An array made from the table.
fn owned<D: Dimension>(x: Array<f64, D>) -> TableData<'static> {
    CowArray::from(x.into_dyn())
}

/// (name, dims, units, long_name, values), as [`TableVariable`].
type Var<'a> = (
    &'static str,
    &'static [&'static str],
    &'static str,
    &'static str,
    TableData<'a>,
);

/// The names and long names of the ensemble mean and standard deviation of ledger term `lt`
/// over the runs, as a table's variables.
fn ensemble_names(lt: &LedgerTerm) -> [(String, String); 2] {
    [
        (
            format!("{}_mean", lt.name),
            format!("ensemble mean {}", lt.label_with_equation()),
        ),
        (
            format!("{}_std", lt.name),
            format!("ensemble standard deviation of the {}", lt.label),
        ),
    ]
}

impl RidgeTable {
    /// Every variable of the table, in file order (the set layout; the NetCDF writer spreads
    /// the `set` axis onto a (μ, μ_w) grid where the sets differ only in friction).
    pub fn variables<'a>(&'a self) -> Vec<TableVariable<'a>> {
        let t = self;
        let (ns, nv) = (t.sets.len(), t.volume.len());
        let coef =
            |g: &dyn Fn(&SetFits) -> f64| owned(t.fits.map(|x| x.as_ref().map_or(f64::NAN, g)));
        let pooled = |g: &dyn Fn(&SetFits) -> f64| {
            owned(Array1::from_iter(
                t.pooled.iter().map(|x| x.as_ref().map_or(f64::NAN, g)),
            ))
        };
        let band = |g: &dyn Fn(&Band) -> &Vec<f64>| {
            let mut x = Array2::from_elem((ns, nv), f64::NAN);
            for (mut row, b) in x.rows_mut().into_iter().zip(&t.work_band) {
                if let Some(b) = b {
                    row.assign(&ArrayView1::from(g(b)));
                }
            }
            owned(x)
        };
        let ridged = |g: &dyn Fn(&super::redistribution::RidgedEnsemble) -> f64| {
            owned(t.ridged.map(|e| e.as_ref().map_or(f64::NAN, g)))
        };
        const S3: &[&str] = &["set", "thickness", "volume"];
        const S2: &[&str] = &["set", "thickness"];
        const SV: &[&str] = &["set", "volume"];
        const S1: &[&str] = &["set"];
        let ds = t.default_set();
        let head: Vec<Var> = vec![
            (
                "mu",
                S1,
                "1",
                "friction coefficient between ice blocks above the water line",
                axis(&t.mu),
            ),
            (
                "mu_w",
                S1,
                "1",
                "friction coefficient between ice blocks below the water line",
                axis(&t.mu_w),
            ),
            (
                "thickness",
                &["thickness"],
                "m",
                "lead-ice sheet thickness",
                axis(&t.thickness),
            ),
            (
                "volume",
                &["volume"],
                "m3 m-1",
                "ridged-ice volume per metre of ridge V = U h t",
                axis(&t.volume),
            ),
        ];
        let rest: Vec<Var> = vec![
            (
                "ratio_mean",
                S3,
                "1",
                "ensemble mean of work over potential energy change",
                view(&t.ratio_mean),
            ),
            (
                "force_mean",
                S3,
                "N m-1",
                "ensemble mean ridging force over the sampling interval",
                view(&t.force_mean),
            ),
            (
                "runs",
                S3,
                "1",
                "number of runs behind each ensemble value",
                owned(t.runs.mapv(f64::from)),
            ),
            (
                "force_fit",
                S3,
                "N m-1",
                "ridging force from the pooled work fit, eq (15), within the volumes the runs of each thickness reached",
                view(&t.force_fit),
            ),
            (
                "work_a",
                S2,
                "J m-5",
                "work fit W = V(a V + b), coefficient a, eq (13)",
                coef(&|x| x.work.a),
            ),
            (
                "work_b",
                S2,
                "J m-3",
                "work fit coefficient b, eq (13)",
                coef(&|x| x.work.b),
            ),
            (
                "work_a_se",
                S2,
                "J m-5",
                "standard error of work_a",
                coef(&|x| x.work.standard_errors()[0]),
            ),
            (
                "work_b_se",
                S2,
                "J m-3",
                "standard error of work_b",
                coef(&|x| x.work.standard_errors()[1]),
            ),
            (
                "potential_energy_a",
                S2,
                "J m-5",
                "potential energy fit PE = V(a V + b), coefficient a, eq (14)",
                coef(&|x| x.potential_energy.a),
            ),
            (
                "potential_energy_b",
                S2,
                "J m-3",
                "potential energy fit coefficient b, eq (14)",
                coef(&|x| x.potential_energy.b),
            ),
            (
                "cf_by_set",
                S2,
                "1",
                "C_f: ensemble mean of final work over potential energy change",
                view(&t.cf),
            ),
            (
                "cf_std",
                S2,
                "1",
                "sample standard deviation of the runs' final work over potential energy change",
                view(&t.cf_std),
            ),
            (
                "cf_conf_lo",
                S2,
                "1",
                "lower end of the 95 % confidence interval of cf_by_set (Student t)",
                owned(t.cf_conf.map(|c| c.0)),
            ),
            (
                "cf_conf_hi",
                S2,
                "1",
                "upper end of the 95 % confidence interval of cf_by_set (Student t)",
                owned(t.cf_conf.map(|c| c.1)),
            ),
            (
                "cf_runs",
                S2,
                "1",
                "number of runs behind cf_by_set",
                owned(t.cf_runs.mapv(f64::from)),
            ),
            (
                "ridged_runs",
                S2,
                "1",
                "number of runs behind the ridged-ice fields (records with the ridge columns)",
                owned(
                    t.ridged
                        .map(|e| e.as_ref().map_or(0.0, |e| e.lambda.n as f64)),
                ),
            ),
            (
                "ridged_thickness",
                S2,
                "m",
                "ensemble mean of the mean solid thickness of the ridged ice (the strips of the final profile holding rubble)",
                ridged(&|e| e.mean_thickness.mean),
            ),
            (
                "ridged_porosity",
                S2,
                "1",
                "ensemble mean of the porosity of the ridged ice (voids over rubble-column thickness)",
                ridged(&|e| e.porosity.mean),
            ),
            (
                "mu_rdg",
                S2,
                "m^0.5",
                "ensemble mean of Lipscomb's e-folding parameter fitted to the ridged ice, (mean thickness - min(2h, h + 1 m))/sqrt(h); NaN where that mean is not positive (ridged ice on average no thicker than min(2h, h + 1 m): no exponential from there has its mean)",
                ridged(&|e| e.host_mu_rdg().unwrap_or(f64::NAN)),
            ),
            (
                "mu_rdg_std",
                S2,
                "m^0.5",
                "ensemble standard deviation of mu_rdg over the runs",
                ridged(&|e| e.mu_rdg.std),
            ),
            (
                "h_star",
                S2,
                "m",
                "ensemble mean of Hibler's H* fitted to the ridged ice, ((2 mean thickness - min(2h, h + 1 m))/2)^2/h",
                ridged(&|e| e.h_star.mean),
            ),
            (
                "h_star_std",
                S2,
                "m",
                "ensemble standard deviation of h_star over the runs",
                ridged(&|e| e.h_star.std),
            ),
            (
                "ks_exponential",
                S2,
                "1",
                "Kolmogorov-Smirnov distance of the exponential fitted to the runs' ridged strips together",
                ridged(&|e| e.fit.ks_exponential),
            ),
            (
                "ks_uniform",
                S2,
                "1",
                "Kolmogorov-Smirnov distance of the uniform fitted to the runs' ridged strips together",
                ridged(&|e| e.fit.ks_uniform),
            ),
            (
                "cf",
                &["thickness"],
                "1",
                "C_f at the friction of the attributes mu and mu_w: ratio of ridging work to potential energy change",
                CowArray::from(t.cf.row(ds).into_dyn()),
            ),
            (
                "pooled_work_a",
                S1,
                "J m-5",
                "work fit pooled over thicknesses, coefficient a, eq (13)",
                pooled(&|x| x.work.a),
            ),
            (
                "pooled_work_b",
                S1,
                "J m-3",
                "work fit pooled over thicknesses, coefficient b, eq (13)",
                pooled(&|x| x.work.b),
            ),
            (
                "pooled_work_a_se",
                S1,
                "J m-5",
                "standard error of pooled_work_a",
                pooled(&|x| x.work.standard_errors()[0]),
            ),
            (
                "pooled_work_b_se",
                S1,
                "J m-3",
                "standard error of pooled_work_b",
                pooled(&|x| x.work.standard_errors()[1]),
            ),
            (
                "pooled_potential_energy_a",
                S1,
                "J m-5",
                "pooled potential energy fit, coefficient a, eq (14)",
                pooled(&|x| x.potential_energy.a),
            ),
            (
                "pooled_potential_energy_b",
                S1,
                "J m-3",
                "pooled potential energy fit, coefficient b, eq (14)",
                pooled(&|x| x.potential_energy.b),
            ),
            (
                "work_fit",
                SV,
                "J m-1",
                "pooled work fit, eq (13)",
                band(&|b| &b.fit),
            ),
            (
                "work_conf_lo",
                SV,
                "J m-1",
                "lower edge of the 95 % confidence band of the pooled work fit",
                band(&|b| &b.conf_lo),
            ),
            (
                "work_conf_hi",
                SV,
                "J m-1",
                "upper edge of the 95 % confidence band of the pooled work fit",
                band(&|b| &b.conf_hi),
            ),
            (
                "work_pred_lo",
                SV,
                "J m-1",
                "lower edge of the 95 % prediction band of the pooled work fit",
                band(&|b| &b.pred_lo),
            ),
            (
                "work_pred_hi",
                SV,
                "J m-1",
                "upper edge of the 95 % prediction band of the pooled work fit",
                band(&|b| &b.pred_hi),
            ),
            (
                "ratio_fit",
                SV,
                "1",
                "dWork/dPE from the pooled fits, eq (16)",
                view(&t.ratio_fit),
            ),
        ];
        let var = |(name, dims, units, long_name, data): Var<'a>| TableVariable {
            name: name.into(),
            dims,
            units,
            long_name: long_name.into(),
            data,
        };
        // The ledger terms tabulated over the runs (work and ΔPE, which eqs (13)–(14) fit):
        // their ensemble mean and spread, named and described by the ledger's table.
        let ensemble = [
            (const { term("work") }, &t.work_mean, &t.work_std),
            (const { term("potential_energy") }, &t.pe_mean, &t.pe_std),
        ];
        let ledger = ensemble.into_iter().flat_map(|(lt, mean, std)| {
            ensemble_names(&lt)
                .into_iter()
                .zip([mean, std])
                .map(move |((name, long_name), x)| TableVariable {
                    name,
                    dims: S3,
                    units: term_file(lt.name).udunits,
                    long_name,
                    data: view(x),
                })
        });
        let mut vars: Vec<TableVariable> = head.into_iter().map(var).collect();
        vars.extend(ledger);
        vars.extend(rest.into_iter().map(var));
        vars
    }

    /// The table as a [`RidgeLookup`] without a file: the same fields, axes and set labels
    /// as [`RidgeLookup::open`] gives for the file [`crate::io::table_netcdf::write_ridge_table`]
    /// writes (in either layout); of the attributes only those the table itself holds
    /// (`sets`, `seeds`, `excluded_runs`), not the provenance the file adds.
    pub fn lookup(&self) -> Result<RidgeLookup, LookupError> {
        let mut fields = Vec::new();
        for v in self.variables() {
            if matches!(v.name.as_str(), "thickness" | "volume") {
                continue;
            }
            let on = |x: &str| v.dims.contains(&x);
            let axes = Axes {
                set: on("set"),
                thickness: on("thickness"),
                volume: on("volume"),
            };
            fields.push((
                v.name,
                Field::new(axes, v.units, &v.long_name, v.data.into_owned()),
            ));
        }
        let seeds: Vec<String> = self.seeds.iter().map(u64::to_string).collect();
        let excluded: Vec<String> = self
            .excluded
            .iter()
            .map(|(id, why)| format!("{id}: {why}"))
            .collect();
        let attributes = [
            ("sets", self.sets.join("; ")),
            ("seeds", seeds.join(" ")),
            ("excluded_runs", excluded.join("; ")),
        ]
        .into_iter()
        .map(|(k, v)| (k.to_string(), v))
        .collect();
        RidgeLookup::new(
            self.sets.clone(),
            self.thickness.clone(),
            self.volume.clone(),
            fields,
            attributes,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The NetCDF names, units and long names of the tabulated ledger terms, made from the
    /// ledger's table, stay those of the tables written before.
    #[test]
    fn tabulated_ledger_terms_keep_their_netcdf_names() {
        let names = |n: &str| {
            let t = term(n);
            let [(a, b), (c, d)] = ensemble_names(&t);
            (term_file(n).udunits, [a, b, c, d])
        };
        assert_eq!(
            names("work"),
            (
                "J m-1",
                [
                    "work_mean",
                    "ensemble mean ridging work, eq (9)",
                    "work_std",
                    "ensemble standard deviation of the ridging work"
                ]
                .map(String::from)
            )
        );
        assert_eq!(
            names("potential_energy"),
            (
                "J m-1",
                [
                    "potential_energy_mean",
                    "ensemble mean potential energy change, eq (10)",
                    "potential_energy_std",
                    "ensemble standard deviation of the potential energy change"
                ]
                .map(String::from)
            )
        );
    }
}
