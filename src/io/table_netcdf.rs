//! The ridging lookup table as NetCDF (CF-1.8 conventions, 64-bit-offset format, NaN marks
//! cells that no run reached).
//!
//! Dimensions `set`, `thickness` (m), `volume` (m³/m). Each set's friction pair is in the
//! coordinate variables `mu(set)` and `mu_w(set)` (units "1"), named in the `coordinates`
//! attribute of every variable on `set`: a host model chooses C_f by friction, not by index
//! (the sets need not form a full μ × μ_w × thickness grid — the paper ran its friction set
//! at one thickness — so they stay a list). The 1-D variables `thickness` and `cf` (the C_f
//! of the set at μ = 1.0, μ_w = 0.6, else of the first set; its attributes `mu` and `mu_w`
//! say which) make the file usable directly as a plain C_f table; `cf_by_set(set,
//! thickness)` holds every set's, with `cf_std`, `cf_conf_lo`, `cf_conf_hi` (95 % confidence
//! interval of the mean) and `cf_runs`.

use super::itd_netcdf::NetcdfError;
use crate::table::tabulate::RidgeTable;
use std::path::Path;

fn nc_err(path: &Path) -> impl Fn(netcdf::Error) -> NetcdfError + '_ {
    move |source| NetcdfError::Netcdf {
        path: path.to_path_buf(),
        source,
    }
}

/// Provenance written as global attributes.
#[derive(Clone, Debug, Default)]
pub struct Provenance {
    /// The campaign spec (TOML text).
    pub campaign_spec: String,
    /// The scene of the first run (TOML text), the base the grid varies.
    pub scene: String,
    /// The command that made the table.
    pub command: String,
    /// Creation date (ISO 8601).
    pub date: String,
    /// Runs the campaign planned.
    pub runs_planned: usize,
    /// Runs tabulated (fewer than planned only when a partial campaign was allowed).
    pub runs_tabulated: usize,
    /// The runs left out of a partial campaign (empty for a complete one).
    pub gaps: String,
}

/// Writes a [`RidgeTable`] to `path`, atomically ([`super::write_atomic_with`]).
pub fn write_ridge_table(
    path: &Path,
    t: &RidgeTable,
    prov: &Provenance,
) -> Result<(), NetcdfError> {
    super::write_atomic_with(path, |tmp| write_ridge_table_at(tmp, path, t, prov))
}

/// [`write_ridge_table`] into the file `tmp` (renamed by the caller); errors name `path`.
fn write_ridge_table_at(
    tmp: &Path,
    path: &Path,
    t: &RidgeTable,
    prov: &Provenance,
) -> Result<(), NetcdfError> {
    let e = nc_err(path);
    let (ns, nh, nv) = (t.sets.len(), t.thickness.len(), t.volume.len());
    let mut f = netcdf::create_with(tmp, netcdf::Options::_64BIT_OFFSET).map_err(&e)?;
    f.add_dimension("set", ns).map_err(&e)?;
    f.add_dimension("thickness", nh).map_err(&e)?;
    f.add_dimension("volume", nv).map_err(&e)?;
    type Var<'a> = (&'a str, &'a [&'a str], &'a str, &'a str, Vec<f64>);
    let flat3 =
        |x: &Vec<Vec<Vec<f64>>>| x.iter().flatten().flatten().copied().collect::<Vec<f64>>();
    let flat2 = |x: &Vec<Vec<f64>>| x.iter().flatten().copied().collect::<Vec<f64>>();
    let coef = |g: &dyn Fn(&super::super::table::tabulate::SetFits) -> f64| -> Vec<f64> {
        t.fits
            .iter()
            .flatten()
            .map(|x| x.as_ref().map_or(f64::NAN, g))
            .collect()
    };
    let pooled = |g: &dyn Fn(&super::super::table::tabulate::SetFits) -> f64| -> Vec<f64> {
        t.pooled
            .iter()
            .map(|x| x.as_ref().map_or(f64::NAN, g))
            .collect()
    };
    let band = |g: &dyn Fn(&crate::table::fit::Band) -> &Vec<f64>| -> Vec<f64> {
        t.work_band
            .iter()
            .flat_map(|b| match b {
                Some(b) => g(b).clone(),
                None => vec![f64::NAN; nv],
            })
            .collect()
    };
    let s3: &[&str] = &["set", "thickness", "volume"];
    let s2: &[&str] = &["set", "thickness"];
    let sv: &[&str] = &["set", "volume"];
    let s1: &[&str] = &["set"];
    let ds = t.default_set();
    let vars: Vec<Var> = vec![
        (
            "mu",
            s1,
            "1",
            "friction coefficient between ice blocks above the water line",
            t.mu.clone(),
        ),
        (
            "mu_w",
            s1,
            "1",
            "friction coefficient between ice blocks below the water line",
            t.mu_w.clone(),
        ),
        (
            "thickness",
            &["thickness"],
            "m",
            "lead-ice sheet thickness",
            t.thickness.clone(),
        ),
        (
            "volume",
            &["volume"],
            "m3 m-1",
            "ridged-ice volume per metre of ridge V = U h t",
            t.volume.clone(),
        ),
        (
            "work_mean",
            s3,
            "J m-1",
            "ensemble mean ridging work, eq (9)",
            flat3(&t.work_mean),
        ),
        (
            "work_std",
            s3,
            "J m-1",
            "ensemble standard deviation of the ridging work",
            flat3(&t.work_std),
        ),
        (
            "potential_energy_mean",
            s3,
            "J m-1",
            "ensemble mean potential energy change, eq (10)",
            flat3(&t.pe_mean),
        ),
        (
            "potential_energy_std",
            s3,
            "J m-1",
            "ensemble standard deviation of the potential energy change",
            flat3(&t.pe_std),
        ),
        (
            "ratio_mean",
            s3,
            "1",
            "ensemble mean of work over potential energy change",
            flat3(&t.ratio_mean),
        ),
        (
            "force_mean",
            s3,
            "N m-1",
            "ensemble mean ridging force over the sampling interval",
            flat3(&t.force_mean),
        ),
        (
            "runs",
            s3,
            "1",
            "number of runs behind each ensemble value",
            t.runs
                .iter()
                .flatten()
                .flatten()
                .map(|&n| n as f64)
                .collect(),
        ),
        (
            "force_fit",
            s3,
            "N m-1",
            "ridging force from the pooled work fit, eq (15), within the volumes the runs of each thickness reached",
            flat3(&t.force_fit),
        ),
        (
            "work_a",
            s2,
            "J m-5",
            "work fit W = V(a V + b), coefficient a, eq (13)",
            coef(&|x| x.work.a),
        ),
        (
            "work_b",
            s2,
            "J m-3",
            "work fit coefficient b, eq (13)",
            coef(&|x| x.work.b),
        ),
        (
            "work_a_se",
            s2,
            "J m-5",
            "standard error of work_a",
            coef(&|x| x.work.standard_errors()[0]),
        ),
        (
            "work_b_se",
            s2,
            "J m-3",
            "standard error of work_b",
            coef(&|x| x.work.standard_errors()[1]),
        ),
        (
            "potential_energy_a",
            s2,
            "J m-5",
            "potential energy fit PE = V(a V + b), coefficient a, eq (14)",
            coef(&|x| x.potential_energy.a),
        ),
        (
            "potential_energy_b",
            s2,
            "J m-3",
            "potential energy fit coefficient b, eq (14)",
            coef(&|x| x.potential_energy.b),
        ),
        (
            "cf_by_set",
            s2,
            "1",
            "C_f: ensemble mean of final work over potential energy change",
            flat2(&t.cf),
        ),
        (
            "cf_std",
            s2,
            "1",
            "sample standard deviation of the runs' final work over potential energy change",
            flat2(&t.cf_std),
        ),
        (
            "cf_conf_lo",
            s2,
            "1",
            "lower end of the 95 % confidence interval of cf_by_set (Student t)",
            t.cf_conf.iter().flatten().map(|c| c.0).collect(),
        ),
        (
            "cf_conf_hi",
            s2,
            "1",
            "upper end of the 95 % confidence interval of cf_by_set (Student t)",
            t.cf_conf.iter().flatten().map(|c| c.1).collect(),
        ),
        (
            "cf_runs",
            s2,
            "1",
            "number of runs behind cf_by_set",
            t.cf_runs.iter().flatten().map(|&n| f64::from(n)).collect(),
        ),
        (
            "cf",
            &["thickness"],
            "1",
            "C_f at the friction of the attributes mu and mu_w: ratio of ridging work to potential energy change",
            t.cf[ds].clone(),
        ),
        (
            "pooled_work_a",
            s1,
            "J m-5",
            "work fit pooled over thicknesses, coefficient a, eq (13)",
            pooled(&|x| x.work.a),
        ),
        (
            "pooled_work_b",
            s1,
            "J m-3",
            "work fit pooled over thicknesses, coefficient b, eq (13)",
            pooled(&|x| x.work.b),
        ),
        (
            "pooled_work_a_se",
            s1,
            "J m-5",
            "standard error of pooled_work_a",
            pooled(&|x| x.work.standard_errors()[0]),
        ),
        (
            "pooled_work_b_se",
            s1,
            "J m-3",
            "standard error of pooled_work_b",
            pooled(&|x| x.work.standard_errors()[1]),
        ),
        (
            "pooled_potential_energy_a",
            s1,
            "J m-5",
            "pooled potential energy fit, coefficient a, eq (14)",
            pooled(&|x| x.potential_energy.a),
        ),
        (
            "pooled_potential_energy_b",
            s1,
            "J m-3",
            "pooled potential energy fit, coefficient b, eq (14)",
            pooled(&|x| x.potential_energy.b),
        ),
        (
            "work_fit",
            sv,
            "J m-1",
            "pooled work fit, eq (13)",
            band(&|b| &b.fit),
        ),
        (
            "work_conf_lo",
            sv,
            "J m-1",
            "lower edge of the 95 % confidence band of the pooled work fit",
            band(&|b| &b.conf_lo),
        ),
        (
            "work_conf_hi",
            sv,
            "J m-1",
            "upper edge of the 95 % confidence band of the pooled work fit",
            band(&|b| &b.conf_hi),
        ),
        (
            "work_pred_lo",
            sv,
            "J m-1",
            "lower edge of the 95 % prediction band of the pooled work fit",
            band(&|b| &b.pred_lo),
        ),
        (
            "work_pred_hi",
            sv,
            "J m-1",
            "upper edge of the 95 % prediction band of the pooled work fit",
            band(&|b| &b.pred_hi),
        ),
        (
            "ratio_fit",
            sv,
            "1",
            "dWork/dPE from the pooled fits, eq (16)",
            flat2(&t.ratio_fit),
        ),
    ];
    for (name, dims, units, long, _) in &vars {
        let mut v = f.add_variable::<f64>(name, dims).map_err(&e)?;
        v.put_attribute("units", *units).map_err(&e)?;
        v.put_attribute("long_name", *long).map_err(&e)?;
        v.put_attribute("_FillValue", f64::NAN).map_err(&e)?;
        if dims.first() == Some(&"set") && !matches!(*name, "mu" | "mu_w") {
            v.put_attribute("coordinates", "mu mu_w").map_err(&e)?;
        }
        if *name == "cf" {
            v.put_attribute("mu", t.mu[ds]).map_err(&e)?;
            v.put_attribute("mu_w", t.mu_w[ds]).map_err(&e)?;
        }
    }
    f.add_attribute("Conventions", "CF-1.8").map_err(&e)?;
    f.add_attribute(
        "title",
        "pressridge ridging lookup table (Hopkins 1994, eqs 13-17)",
    )
    .map_err(&e)?;
    f.add_attribute("pressridge_version", env!("CARGO_PKG_VERSION"))
        .map_err(&e)?;
    f.add_attribute("sets", t.sets.join("; ").as_str())
        .map_err(&e)?;
    let seeds: Vec<String> = t.seeds.iter().map(u64::to_string).collect();
    f.add_attribute("seeds", seeds.join(" ").as_str())
        .map_err(&e)?;
    let excluded: Vec<String> = t
        .excluded
        .iter()
        .map(|(id, why)| format!("{id}: {why}"))
        .collect();
    f.add_attribute("excluded_runs", excluded.join("; ").as_str())
        .map_err(&e)?;
    f.add_attribute("campaign_spec", prov.campaign_spec.as_str())
        .map_err(&e)?;
    f.add_attribute("scene", prov.scene.as_str()).map_err(&e)?;
    // Runs are counted as i32 (the NetCDF classic integer attribute type).
    let count = |n: usize| i32::try_from(n).unwrap_or(i32::MAX);
    f.add_attribute("runs_planned", count(prov.runs_planned))
        .map_err(&e)?;
    f.add_attribute("runs_tabulated", count(prov.runs_tabulated))
        .map_err(&e)?;
    f.add_attribute(
        "partial",
        if prov.gaps.is_empty() {
            "no: every planned run tabulated".to_string()
        } else {
            format!("yes: {}", prov.gaps)
        }
        .as_str(),
    )
    .map_err(&e)?;
    f.add_attribute(
        "history",
        format!("{} {}", prov.date, prov.command).as_str(),
    )
    .map_err(&e)?;
    f.enddef().map_err(&e)?;
    for (name, _, _, _, data) in &vars {
        let mut v = f.variable_mut(name).expect("just defined");
        v.put_values(data, ..).map_err(&e)?;
    }
    f.close().map_err(&e)?;
    let _ = (ns, nh);
    Ok(())
}

impl crate::table::lookup::RidgeLookup {
    /// Reads a table written by [`write_ridge_table`] (`pressridge tabulate`): every variable
    /// on the dimensions (`set`, `thickness`, `volume`) or an ordered subset of them becomes a
    /// field, string global attributes become the provenance. Errors name the file and the
    /// missing or malformed variable.
    pub fn open(path: &Path) -> Result<Self, NetcdfError> {
        use crate::table::lookup::{Axes, Field, RidgeLookup};
        let e = nc_err(path);
        let file = netcdf::open(path).map_err(&e)?;
        let missing = |var: &str| NetcdfError::MissingVariable {
            path: path.to_path_buf(),
            var: var.into(),
        };
        let axis = |name: &str| -> Result<Vec<f64>, NetcdfError> {
            let v = file.variable(name).ok_or_else(|| missing(name))?;
            let d: Vec<String> = v.dimensions().iter().map(|d| d.name()).collect();
            if d != [name] {
                return Err(NetcdfError::Shape {
                    path: path.to_path_buf(),
                    var: name.into(),
                    expected: format!("({name})"),
                    found: format!("({})", d.join(", ")),
                });
            }
            v.get_values::<f64, _>(..).map_err(&e)
        };
        let thickness = axis("thickness")?;
        let volume = axis("volume")?;
        let nsets = file.dimension("set").ok_or_else(|| missing("set"))?.len();
        let mut attributes = std::collections::BTreeMap::new();
        for a in file.attributes() {
            if let Ok(netcdf::AttributeValue::Str(s)) = a.value() {
                attributes.insert(a.name().to_string(), s);
            }
        }
        let mut sets: Vec<String> = attributes
            .get("sets")
            .map(|s| s.split("; ").map(str::to_string).collect())
            .unwrap_or_default();
        if sets.len() != nsets {
            sets = (0..nsets).map(|k| format!("set {k}")).collect();
        }
        let mut fields = Vec::new();
        for v in file.variables() {
            let name = v.name();
            if name == "thickness" || name == "volume" {
                continue;
            }
            let d: Vec<String> = v.dimensions().iter().map(|d| d.name()).collect();
            let axes = Axes {
                set: d.iter().any(|x| x == "set"),
                thickness: d.iter().any(|x| x == "thickness"),
                volume: d.iter().any(|x| x == "volume"),
            };
            if d.is_empty() || axes.names() != d {
                continue; // not a lookup field (another layout)
            }
            let text = |a: &str| match v.attribute_value(a) {
                Some(Ok(netcdf::AttributeValue::Str(s))) => s,
                _ => String::new(),
            };
            let data = v.get_values::<f64, _>(..).map_err(&e)?;
            fields.push((
                name,
                Field::new(axes, &text("units"), &text("long_name"), data),
            ));
        }
        RidgeLookup::new(sets, thickness, volume, fields, attributes).map_err(|err| {
            NetcdfError::Shape {
                path: path.to_path_buf(),
                var: "(table)".into(),
                expected: "a consistent ridging table".into(),
                found: err.to_string(),
            }
        })
    }
}
