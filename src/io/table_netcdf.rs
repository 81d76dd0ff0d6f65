//! The ridging lookup table as NetCDF (CF-1.8 conventions, 64-bit-offset format, NaN marks
//! cells that no run reached).
//!
//! Two layouts, chosen by what tells the table's sets apart:
//! - **Friction grid** (the shipped table): when the sets differ only in their friction pair
//!   (every set label is `mu=…, mu_w=…`, every pair finite and distinct), the dimensions are
//!   `thickness` (m), `mu`, `mu_w` (units "1", coordinate variables) and `volume` (m³/m):
//!   `work_mean(thickness, mu, mu_w, volume)`, `cf_by_set(thickness, mu, mu_w)`,
//!   `work_fit(mu, mu_w, volume)`, `pooled_work_a(mu, mu_w)`, … A (μ, μ_w) cell that no set
//!   fills is NaN, with `runs` and `cf_runs` 0: the paper ran its friction set at one
//!   thickness only, and nothing is borrowed across cells. The global attributes `sets`,
//!   `set_mu` and `set_mu_w` list the sets in their tabulated order (the default pair
//!   first), which the reader restores.
//! - **Set list** (any other table, e.g. sets that differ in modulus or speed): dimensions
//!   `set`, `thickness`, `volume`; each set's friction pair in `mu(set)` and `mu_w(set)`,
//!   named in the `coordinates` attribute of every variable on `set`.
//!
//! In both, the 1-D variables `thickness` and `cf` (the C_f of the set at μ = 1.0, μ_w = 0.6,
//! else of the first set; its attributes `mu` and `mu_w` say which) make the file usable
//! directly as a plain C_f table; `cf_by_set` holds every set's, with `cf_std`, `cf_conf_lo`,
//! `cf_conf_hi` (95 % confidence interval of the mean) and `cf_runs`. The variable names
//! are the same in both layouts, and [`RidgeLookup::open`](crate::table::lookup::RidgeLookup)
//! reads both into the same sets.

use super::itd_netcdf::NetcdfError;
use crate::table::tabulate::RidgeTable;
use std::borrow::Cow;
use std::path::Path;

mod open;

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
    let grid = FrictionGrid::of(t);
    let mut f = netcdf::create_with(tmp, netcdf::Options::_64BIT_OFFSET).map_err(&e)?;
    match &grid {
        Some(g) => {
            f.add_dimension("thickness", nh).map_err(&e)?;
            f.add_dimension("mu", g.mu.len()).map_err(&e)?;
            f.add_dimension("mu_w", g.mu_w.len()).map_err(&e)?;
        }
        None => {
            f.add_dimension("set", ns).map_err(&e)?;
            f.add_dimension("thickness", nh).map_err(&e)?;
        }
    }
    f.add_dimension("volume", nv).map_err(&e)?;
    let ds = t.default_set();
    // The table's variables in the set layout, as C-order slices of its arrays.
    type Var<'a> = (&'a str, &'a [&'a str], &'a str, &'a str, &'a [f64]);
    let table_vars = t.variables();
    let vars: Vec<Var> = table_vars
        .iter()
        .map(|v| {
            let data = v
                .data
                .as_slice()
                .expect("table variables are in standard layout");
            (v.name.as_str(), v.dims, v.units, v.long_name.as_str(), data)
        })
        .collect();
    // The friction grid: every variable on `set` moves to (μ, μ_w) cells.
    type OnDims<'a> = (&'a str, Vec<&'a str>, &'a str, &'a str, Cow<'a, [f64]>);
    let vars: Vec<OnDims> = match &grid {
        None => vars
            .into_iter()
            .map(|(n, d, u, l, x)| (n, d.to_vec(), u, l, Cow::Borrowed(x)))
            .collect(),
        Some(g) => vars
            .into_iter()
            .map(|(n, d, u, l, x)| match n {
                "mu" => (n, vec!["mu"], u, l, Cow::Owned(g.mu.clone())),
                "mu_w" => (n, vec!["mu_w"], u, l, Cow::Owned(g.mu_w.clone())),
                _ if d.first() == Some(&"set") => {
                    let count = matches!(n, "runs" | "cf_runs" | "ridged_runs");
                    let fill = if count { 0.0 } else { f64::NAN };
                    let (dims, data) = g.spread(&d[1..], x, fill, (nh, nv));
                    (n, dims, u, l, Cow::Owned(data))
                }
                _ => (n, d.to_vec(), u, l, Cow::Borrowed(x)),
            })
            .collect(),
    };
    for (name, dims, units, long, _) in &vars {
        let mut v = f.add_variable::<f64>(name, dims).map_err(&e)?;
        v.put_attribute("units", *units).map_err(&e)?;
        v.put_attribute("long_name", *long).map_err(&e)?;
        // CF: a coordinate variable (named as its one dimension) has no missing values.
        if dims.as_slice() != [*name] {
            v.put_attribute("_FillValue", f64::NAN).map_err(&e)?;
        }
        if grid.is_none() && dims.first() == Some(&"set") && !matches!(*name, "mu" | "mu_w") {
            v.put_attribute("coordinates", "mu mu_w").map_err(&e)?;
        }
        if *name == "cf" {
            v.put_attribute("mu", t.mu[ds]).map_err(&e)?;
            v.put_attribute("mu_w", t.mu_w[ds]).map_err(&e)?;
        }
    }
    let ridged = define_ridged_distribution(&mut f, t, grid.as_ref(), &e)?;
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
    if grid.is_some() {
        f.add_attribute("set_mu", t.mu.clone()).map_err(&e)?;
        f.add_attribute("set_mu_w", t.mu_w.clone()).map_err(&e)?;
    }
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
    if !t.scaled_keys.is_empty() {
        // Scene keys that vary with the thickness within a set, and their values per set and
        // thickness: "<set> at <h> m: key=value, ...", joined by "; ".
        f.add_attribute("scaled_keys", t.scaled_keys.join(" ").as_str())
            .map_err(&e)?;
        let mut values = Vec::new();
        for (si, set) in t.sets.iter().enumerate() {
            for (hi, h) in t.thickness.iter().enumerate() {
                if !t.scaled_values[[si, hi]].is_empty() {
                    values.push(format!("{set} at {h} m: {}", t.scaled_label(si, hi)));
                }
            }
        }
        f.add_attribute("scaled_values", values.join("; ").as_str())
            .map_err(&e)?;
    }
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
        v.put_values(data.as_ref(), ..).map_err(&e)?;
    }
    for (name, data) in &ridged {
        let mut v = f.variable_mut(name).expect("just defined");
        v.put_values(data, ..).map_err(&e)?;
    }
    f.close().map_err(&e)?;
    Ok(())
}

/// The (μ, μ_w) grid of a table whose sets differ only in their friction pair.
struct FrictionGrid {
    /// Distinct μ, ascending.
    mu: Vec<f64>,
    /// Distinct μ_w, ascending.
    mu_w: Vec<f64>,
    /// Each set's cell (index into `mu`, index into `mu_w`).
    cell: Vec<(usize, usize)>,
}

impl FrictionGrid {
    /// The grid of `t`, or `None` when a set differs from another in more than friction
    /// (its label says so), a pair is not finite, or two sets share a pair.
    fn of(t: &RidgeTable) -> Option<Self> {
        let pairs: Vec<(f64, f64)> = t.mu.iter().copied().zip(t.mu_w.iter().copied()).collect();
        if pairs.is_empty() || pairs.len() != t.sets.len() {
            return None;
        }
        for (label, &(m, w)) in t.sets.iter().zip(&pairs) {
            if !(m.is_finite() && w.is_finite()) || *label != format!("mu={m}, mu_w={w}") {
                return None;
            }
        }
        Self::from_pairs(&pairs)
    }

    /// The grid spanned by `pairs`, `None` when two are equal.
    fn from_pairs(pairs: &[(f64, f64)]) -> Option<Self> {
        let axis = |k: fn(&(f64, f64)) -> f64| {
            let mut v: Vec<f64> = pairs.iter().map(k).collect();
            v.sort_by(f64::total_cmp);
            v.dedup();
            v
        };
        let (mu, mu_w) = (axis(|p| p.0), axis(|p| p.1));
        let at = |v: &[f64], x: f64| v.iter().position(|&y| y == x);
        let cell: Vec<(usize, usize)> = pairs
            .iter()
            .map(|&(m, w)| Some((at(&mu, m)?, at(&mu_w, w)?)))
            .collect::<Option<_>>()?;
        let mut seen = cell.clone();
        seen.sort_unstable();
        seen.dedup();
        (seen.len() == cell.len()).then_some(Self { mu, mu_w, cell })
    }

    /// Spreads `data`, laid out (set, `rest`…) with `rest` ⊆ (thickness, inner) of `nh`
    /// thicknesses and `nv` entries of the inner axis (`volume`, or `ridged_bin`), onto the
    /// grid: dimensions (thickness?, mu, mu_w, inner?), cells without a set `fill`.
    fn spread<'a>(
        &self,
        rest: &[&'a str],
        data: &[f64],
        fill: f64,
        (nh, nv): (usize, usize),
    ) -> (Vec<&'a str>, Vec<f64>) {
        let (nm, nw) = (self.mu.len(), self.mu_w.len());
        let has = |d: &str| rest.contains(&d);
        // The inner axis after thickness: `volume`, or another of `nv` entries (`ridged_bin`).
        let inner = rest.iter().copied().find(|d| *d != "thickness");
        let outer = if has("thickness") { nh } else { 1 };
        let vol = if inner.is_some() { nv } else { 1 };
        let mut out = vec![fill; outer * nm * nw * vol];
        for (s, &(i, j)) in self.cell.iter().enumerate() {
            for o in 0..outer {
                for v in 0..vol {
                    out[((o * nm + i) * nw + j) * vol + v] = data[(s * outer + o) * vol + v];
                }
            }
        }
        let mut dims = Vec::new();
        if has("thickness") {
            dims.push("thickness");
        }
        dims.extend(["mu", "mu_w"]);
        dims.extend(inner);
        (dims, out)
    }

    /// Gathers a grid field back into set order: the inverse of [`FrictionGrid::spread`]
    /// for `outer` thickness rows (1 without) and `vol` volumes (1 without).
    fn gather(&self, data: &[f64], outer: usize, vol: usize) -> Vec<f64> {
        let (nm, nw) = (self.mu.len(), self.mu_w.len());
        let mut out = Vec::with_capacity(self.cell.len() * outer * vol);
        for &(i, j) in &self.cell {
            for o in 0..outer {
                for v in 0..vol {
                    out.push(data[((o * nm + i) * nw + j) * vol + v]);
                }
            }
        }
        out
    }
}

/// The binned ridged-ice distribution of every set and thickness (issue 34):
/// `ridged_fraction(thickness, mu, mu_w, ridged_bin)` (or `(set, thickness, ridged_bin)`),
/// the area fraction of the ridged ice per bin of H/h, with the bin centres as the coordinate
/// `ridged_bin` and their edges in `ridged_bin_bounds` (CF bounds). NaN where no run has the
/// ridge columns. Not a lookup field: [`crate::table::lookup::RidgeLookup::open`] passes it by.
/// Defines the variables (the file in define mode) and returns their values, (name, data),
/// for the caller to put once it leaves define mode.
fn define_ridged_distribution(
    f: &mut netcdf::FileMut,
    t: &RidgeTable,
    grid: Option<&FrictionGrid>,
    e: &impl Fn(netcdf::Error) -> NetcdfError,
) -> Result<Vec<(&'static str, Vec<f64>)>, NetcdfError> {
    let edges = crate::table::redistribution::table_bin_edges();
    let nb = edges.len() - 1;
    f.add_dimension("ridged_bin", nb).map_err(e)?;
    f.add_dimension("bounds2", 2).map_err(e)?;
    let centres: Vec<f64> = edges.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
    let bounds: Vec<f64> = edges.windows(2).flat_map(|w| [w[0], w[1]]).collect();
    let mut v = f
        .add_variable::<f64>("ridged_bin", &["ridged_bin"])
        .map_err(e)?;
    v.put_attribute("units", "1").map_err(e)?;
    v.put_attribute(
        "long_name",
        "solid ridged-ice thickness over parent (lead) ice thickness, H/h, bin centre",
    )
    .map_err(e)?;
    v.put_attribute("bounds", "ridged_bin_bounds").map_err(e)?;
    let mut v = f
        .add_variable::<f64>("ridged_bin_bounds", &["ridged_bin", "bounds2"])
        .map_err(e)?;
    v.put_attribute("units", "1").map_err(e)?;
    v.put_attribute("long_name", "edges of the ridged_bin bins (H/h)")
        .map_err(e)?;
    let (ns, nh) = (t.sets.len(), t.thickness.len());
    let mut data = vec![f64::NAN; ns * nh * nb];
    for ((si, hi), x) in t.ridged.indexed_iter() {
        if let Some(x) = x {
            let at = (si * nh + hi) * nb;
            data[at..at + nb].copy_from_slice(&x.pooled.table_histogram());
        }
    }
    let (dims, data): (Vec<&str>, Vec<f64>) = match grid {
        Some(g) => g.spread(&["thickness", "ridged_bin"], &data, f64::NAN, (nh, nb)),
        None => (vec!["set", "thickness", "ridged_bin"], data),
    };
    let mut v = f.add_variable::<f64>("ridged_fraction", &dims).map_err(e)?;
    v.put_attribute("units", "1").map_err(e)?;
    v.put_attribute(
        "long_name",
        "area fraction of the simulated ridged ice (the runs' strips together) per bin of H/h",
    )
    .map_err(e)?;
    v.put_attribute("_FillValue", f64::NAN).map_err(e)?;
    if grid.is_none() {
        v.put_attribute("coordinates", "mu mu_w").map_err(e)?;
    }
    Ok(vec![
        ("ridged_bin", centres),
        ("ridged_bin_bounds", bounds),
        ("ridged_fraction", data),
    ])
}

#[cfg(test)]
mod tests {
    use super::FrictionGrid;

    #[test]
    fn friction_grid_spreads_and_gathers_in_set_order() {
        // Three sets on a 2 × 2 grid, the default pair first; (0.6, 0.3) has no set.
        let pairs = [(1.0, 0.6), (0.6, 0.6), (1.0, 0.3)];
        let g = FrictionGrid::from_pairs(&pairs).unwrap();
        assert_eq!(
            (g.mu.as_slice(), g.mu_w.as_slice()),
            (&[0.6, 1.0][..], &[0.3, 0.6][..])
        );
        assert_eq!(g.cell, vec![(1, 1), (0, 1), (1, 0)]);
        // (set, thickness = 2, volume = 3), value = 100·set + 10·h + v.
        let data: Vec<f64> = (0..3)
            .flat_map(|s| {
                (0..2).flat_map(move |h| (0..3).map(move |v| (100 * s + 10 * h + v) as f64))
            })
            .collect();
        let (dims, grid) = g.spread(&["thickness", "volume"], &data, f64::NAN, (2, 3));
        assert_eq!(dims, ["thickness", "mu", "mu_w", "volume"]);
        assert_eq!(grid.len(), 2 * 2 * 2 * 3);
        // (h = 1, μ = 0.6, μ_w = 0.6) is set 1; (h = 0, μ = 0.6, μ_w = 0.3) has no set.
        let at = |h: usize, i: usize, j: usize, v: usize| grid[((h * 2 + i) * 2 + j) * 3 + v];
        assert_eq!(at(1, 0, 1, 2), 112.0);
        assert!(grid[..3].iter().all(|x| x.is_nan()));
        assert_eq!(g.gather(&grid, 2, 3), data);
        // (set) alone → (mu, mu_w), counts filled with 0.
        let (dims, grid) = g.spread(&[], &[7.0, 8.0, 9.0], 0.0, (2, 3));
        assert_eq!(dims, ["mu", "mu_w"]);
        assert_eq!(grid, vec![0.0, 8.0, 9.0, 7.0]);
        assert_eq!(g.gather(&grid, 1, 1), vec![7.0, 8.0, 9.0]);
    }

    #[test]
    fn sets_sharing_a_friction_pair_have_no_grid() {
        assert!(FrictionGrid::from_pairs(&[(1.0, 0.6), (1.0, 0.6)]).is_none());
        assert!(FrictionGrid::from_pairs(&[]).is_some_and(|g| g.cell.is_empty()));
    }
}
