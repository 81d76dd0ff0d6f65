//! C_f tables in NetCDF: a plain table (1-D `thickness`, `cf`) or the C_f of a ridging table
//! of `pressridge tabulate` at a friction pair; writing a plain one.

use super::vars::{dims_of, nc_err, read_f64, required};
use super::*;
use crate::itd::details::{CfTable, MuRdgTable};

/// Reads the C_f at a friction pair (μ, μ_w; dimensionless) from `path`: from a ridging
/// table of `pressridge tabulate` (with friction coordinates `mu` and `mu_w`), the set at
/// `friction`, by default [`crate::table::tabulate::DEFAULT_FRICTION`] (μ = 1.0, μ_w = 0.6,
/// Hopkins 1994's thickness set); from a plain C_f table (1-D `thickness`, `cf`), its one
/// curve, labelled with the friction of the `cf` attributes `mu`, `mu_w` when present. A
/// friction asked for that the file does not have, or cannot vouch for, is an error naming
/// the pairs it has: C_f is never taken at another friction than the one asked for.
pub fn read_cf_table_at_friction(
    path: &Path,
    friction: Option<(f64, f64)>,
) -> Result<CfTable, NetcdfError> {
    let err = |msg: String| NetcdfError::Value {
        path: path.to_path_buf(),
        var: "mu".into(),
        msg,
    };
    // One look at the file: its layout, and the friction a plain table's `cf` declares.
    let (has_sets, has_friction, own) = {
        let file = netcdf::open(path).map_err(nc_err(path))?;
        let v = file.variable("cf");
        let get = |a: &str| match v.as_ref().and_then(|v| v.attribute_value(a)) {
            Some(Ok(netcdf::AttributeValue::Double(x))) => Some(x),
            _ => None,
        };
        (
            file.variable("cf_by_set").is_some(),
            file.variable("mu").is_some(),
            get("mu").zip(get("mu_w")),
        )
    };
    // A table of `pressridge tabulate`; one made before it wrote friction coordinates is
    // read as a plain table unless a friction is asked for (then refused, saying why).
    if has_sets && (has_friction || friction.is_some()) {
        let (mu, mu_w) = friction.unwrap_or(crate::table::tabulate::DEFAULT_FRICTION);
        let t = crate::table::lookup::RidgeLookup::open(path)?;
        return t
            .cf_table_at_friction(mu, mu_w)
            .map_err(|e| err(e.to_string()));
    }
    let table = read_cf_table(path)?;
    match (friction, own) {
        (None, None) => Ok(table),
        (_, Some((a, b))) => {
            if let Some((mu, mu_w)) = friction
                && ((a - mu).abs() > 1e-9 || (b - mu_w).abs() > 1e-9)
            {
                return Err(err(format!(
                    "the C_f table is for friction mu = {a}, mu_w = {b}, not the mu = {mu}, mu_w = {mu_w} asked for"
                )));
            }
            Ok(table.with_friction(a, b))
        }
        (Some((mu, mu_w)), None) => Err(err(format!(
            "a plain C_f table without friction coordinates cannot give C_f at mu = {mu}, mu_w = {mu_w}; use a ridging table of `pressridge tabulate`"
        ))),
    }
}

/// Reads a C_f table: 1-D variables `thickness` (m) and `cf` (dimensionless) of equal
/// length, thickness strictly increasing; a NaN C_f is a node without data and is left out
/// ([`CfTable::from_nodes`]). See [`CfTable`] for interpolation and clamping.
pub fn read_cf_table(path: &Path) -> Result<CfTable, NetcdfError> {
    let file = netcdf::open(path).map_err(nc_err(path))?;
    let mut cols = Vec::new();
    for name in ["thickness", "cf"] {
        let v = required(path, &file, name)?;
        if v.dimensions().len() != 1 {
            return Err(NetcdfError::Shape {
                path: path.to_path_buf(),
                var: name.into(),
                expected: "one dimension".into(),
                found: fmt_dims(&dims_of(&v)),
            });
        }
        cols.push(read_f64(path, &v)?);
    }
    let cf = cols.pop().unwrap_or_default();
    let thickness = cols.pop().unwrap_or_default();
    CfTable::from_nodes(&thickness, &cf).map_err(|source| NetcdfError::Itd {
        path: path.to_path_buf(),
        source,
    })
}

/// The μ_rdg (m^½) against thickness of a ridging table written by `pressridge tabulate`, at
/// the friction pair `friction` (μ above, μ_w below the water line; default
/// [`crate::table::tabulate::DEFAULT_FRICTION`]), for the exponential redistribution with a
/// table ([`crate::itd::details::Redistribution::Table`]). Errors name the file and say what is
/// missing (a table without `mu_rdg`, a friction pair it does not hold).
pub fn read_mu_rdg_table_at_friction(
    path: &Path,
    friction: Option<(f64, f64)>,
) -> Result<MuRdgTable, NetcdfError> {
    let (mu, mu_w) = friction.unwrap_or(crate::table::tabulate::DEFAULT_FRICTION);
    let t = crate::table::lookup::RidgeLookup::open(path)?;
    t.mu_rdg_table_at_friction(mu, mu_w)
        .map_err(|e| NetcdfError::Value {
            path: path.to_path_buf(),
            var: "mu_rdg".into(),
            msg: e.to_string(),
        })
}

/// Writes a C_f table file (`thickness` in m, `cf` dimensionless), 64-bit-offset format.
pub fn write_cf_table(path: &Path, table: &CfTable) -> Result<(), NetcdfError> {
    crate::io::write_atomic_with(path, |tmp| write_cf_table_at(tmp, path, table))
}

/// [`write_cf_table`] into the file `tmp`; errors name `path`.
fn write_cf_table_at(tmp: &Path, path: &Path, table: &CfTable) -> Result<(), NetcdfError> {
    let e = nc_err(path);
    let mut f = netcdf::create_with(tmp, netcdf::Options::_64BIT_OFFSET).map_err(&e)?;
    f.add_dimension("node", table.thickness().len())
        .map_err(&e)?;
    let mut v = f.add_variable::<f64>("thickness", &["node"]).map_err(&e)?;
    v.put_attribute("units", "m").map_err(&e)?;
    v.put_attribute("long_name", "thickness of the ridging ice")
        .map_err(&e)?;
    let mut v = f.add_variable::<f64>("cf", &["node"]).map_err(&e)?;
    v.put_attribute("units", "1").map_err(&e)?;
    v.put_attribute(
        "long_name",
        "ratio of ridging work to potential energy change C_f",
    )
    .map_err(&e)?;
    f.add_attribute("Conventions", "CF-1.8").map_err(&e)?;
    f.enddef().map_err(&e)?;
    for (name, data) in [("thickness", table.thickness()), ("cf", table.values())] {
        let mut v = f.variable_mut(name).expect("just defined");
        v.put_values(data, ..).map_err(&e)?;
    }
    f.close().map_err(&e)?;
    Ok(())
}
