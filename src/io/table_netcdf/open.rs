//! Reading a ridging table back ([`RidgeLookup::open`]): its axes, the friction grid or the
//! set list, and every variable on an ordered subset of (`set`, `thickness`, `volume`) as a
//! field.

use std::collections::BTreeMap;
use std::path::Path;

use ndarray::{Array1, ArrayD, IxDyn};

use super::{FrictionGrid, nc_err};
use crate::io::itd_netcdf::NetcdfError;
use crate::table::lookup::{Axes, Field, RidgeLookup};

/// A table's friction grid and its sets' (μ, μ_w) pairs in their tabulated order.
type GridPairs = (FrictionGrid, Vec<(f64, f64)>);

fn missing(path: &Path, var: &str) -> NetcdfError {
    NetcdfError::MissingVariable {
        path: path.to_path_buf(),
        var: var.into(),
    }
}

/// A coordinate variable on its own dimension only.
fn axis(file: &netcdf::File, path: &Path, name: &str) -> Result<Vec<f64>, NetcdfError> {
    let v = file.variable(name).ok_or_else(|| missing(path, name))?;
    let d: Vec<String> = v.dimensions().iter().map(|d| d.name()).collect();
    if d != [name] {
        return Err(NetcdfError::Shape {
            path: path.to_path_buf(),
            var: name.into(),
            expected: format!("({name})"),
            found: format!("({})", d.join(", ")),
        });
    }
    v.get_values::<f64, _>(..).map_err(nc_err(path))
}

/// The friction-grid layout, if the file has it: the sets are (μ, μ_w) cells, listed in the
/// attributes `set_mu`, `set_mu_w` (every cell, row by row, when a file lacks them).
fn friction_grid(file: &netcdf::File, path: &Path) -> Result<Option<GridPairs>, NetcdfError> {
    if file.dimension("set").is_some() || file.dimension("mu").is_none() {
        return Ok(None);
    }
    let (mu, mu_w) = (axis(file, path, "mu")?, axis(file, path, "mu_w")?);
    let doubles = |a: &str| match file.attribute(a).map(|x| x.value()) {
        Some(Ok(netcdf::AttributeValue::Doubles(v))) => Some(v),
        Some(Ok(netcdf::AttributeValue::Double(v))) => Some(vec![v]),
        _ => None,
    };
    let pairs: Vec<(f64, f64)> = match (doubles("set_mu"), doubles("set_mu_w")) {
        (Some(m), Some(w)) if m.len() == w.len() => m.into_iter().zip(w).collect(),
        _ => mu
            .iter()
            .flat_map(|&m| mu_w.iter().map(move |&w| (m, w)))
            .collect(),
    };
    let g = FrictionGrid::from_pairs(&pairs)
        .filter(|g| g.mu == mu && g.mu_w == mu_w)
        .ok_or_else(|| NetcdfError::Shape {
            path: path.to_path_buf(),
            var: "set_mu, set_mu_w".into(),
            expected: "distinct (mu, mu_w) pairs spanning the mu and mu_w axes".into(),
            found: format!("{pairs:?}"),
        })?;
    Ok(Some((g, pairs)))
}

/// The sets' names: the `sets` attribute when it names every set, else the friction pairs,
/// else `set k`.
fn set_names(labels: Vec<String>, nsets: usize, grid: Option<&GridPairs>) -> Vec<String> {
    match grid {
        _ if labels.len() == nsets => labels,
        Some((_, pairs)) => pairs
            .iter()
            .map(|(m, w)| format!("mu={m}, mu_w={w}"))
            .collect(),
        None => (0..nsets).map(|k| format!("set {k}")).collect(),
    }
}

/// Each set's μ and μ_w as fields on the set axis (the friction grid stores them as axes).
fn friction_fields(pairs: &[(f64, f64)]) -> Vec<(String, Field)> {
    [
        (
            "mu",
            "friction coefficient between ice blocks above the water line",
            0,
        ),
        (
            "mu_w",
            "friction coefficient between ice blocks below the water line",
            1,
        ),
    ]
    .into_iter()
    .map(|(name, long, k)| {
        let data: Array1<f64> = pairs
            .iter()
            .map(|p| if k == 0 { p.0 } else { p.1 })
            .collect();
        (
            name.to_string(),
            Field::new(Axes::SET, "1", long, data.into_dyn()),
        )
    })
    .collect()
}

/// The table's axes and layout, as every field is read against them.
struct Layout<'a> {
    path: &'a Path,
    thickness: &'a [f64],
    volume: &'a [f64],
    nsets: usize,
    grid: Option<&'a GridPairs>,
}

/// A variable as a lookup field, `None` when it is not on an ordered subset of the table's
/// axes (another layout) or is an axis itself.
fn read_field(v: &netcdf::Variable<'_>, l: &Layout<'_>) -> Result<Option<Field>, NetcdfError> {
    let name = v.name();
    if matches!(name.as_str(), "thickness" | "volume")
        || (l.grid.is_some() && matches!(name.as_str(), "mu" | "mu_w"))
    {
        return Ok(None);
    }
    let d: Vec<String> = v.dimensions().iter().map(|d| d.name()).collect();
    let on = |x: &str| d.iter().any(|y| y == x);
    let axes = Axes {
        set: on("set") || (l.grid.is_some() && on("mu")),
        thickness: on("thickness"),
        volume: on("volume"),
    };
    let expected: Vec<String> = match l.grid {
        Some(_) if axes.set => {
            let mut x = Vec::new();
            if axes.thickness {
                x.push("thickness".to_string());
            }
            x.extend(["mu".to_string(), "mu_w".to_string()]);
            if axes.volume {
                x.push("volume".to_string());
            }
            x
        }
        _ => axes.names().iter().map(|x| x.to_string()).collect(),
    };
    if d.is_empty() || expected != d {
        return Ok(None);
    }
    let text = |a: &str| match v.attribute_value(a) {
        Some(Ok(netcdf::AttributeValue::Str(s))) => s,
        _ => String::new(),
    };
    let mut data = v.get_values::<f64, _>(..).map_err(nc_err(l.path))?;
    if let Some((g, _)) = l.grid
        && axes.set
    {
        let outer = if axes.thickness { l.thickness.len() } else { 1 };
        let vol = if axes.volume { l.volume.len() } else { 1 };
        data = g.gather(&data, outer, vol);
    }
    // The set layout: one array axis per axis of the field, set first.
    let shape: Vec<usize> = [
        (axes.set, l.nsets),
        (axes.thickness, l.thickness.len()),
        (axes.volume, l.volume.len()),
    ]
    .into_iter()
    .filter_map(|(on, n)| on.then_some(n))
    .collect();
    let found = data.len();
    let data = ArrayD::from_shape_vec(IxDyn(&shape), data).map_err(|_| NetcdfError::Shape {
        path: l.path.to_path_buf(),
        var: name.clone(),
        expected: format!("{} values on {:?}", shape.iter().product::<usize>(), shape),
        found: format!("{found} values"),
    })?;
    Ok(Some(Field::new(
        axes,
        &text("units"),
        &text("long_name"),
        data,
    )))
}

impl RidgeLookup {
    /// Reads a table written by [`write_ridge_table`](super::write_ridge_table) (`pressridge
    /// tabulate`): every variable on the dimensions (`set`, `thickness`, `volume`) or an
    /// ordered subset of them becomes a field, string global attributes become the
    /// provenance. Errors name the file and the missing or malformed variable.
    pub fn open(path: &Path) -> Result<Self, NetcdfError> {
        let file = netcdf::open(path).map_err(nc_err(path))?;
        let thickness = axis(&file, path, "thickness")?;
        let volume = axis(&file, path, "volume")?;
        let mut attributes = BTreeMap::new();
        for a in file.attributes() {
            if let Ok(netcdf::AttributeValue::Str(s)) = a.value() {
                attributes.insert(a.name().to_string(), s);
            }
        }
        let labels: Vec<String> = attributes
            .get("sets")
            .map(|s| s.split("; ").map(str::to_string).collect())
            .unwrap_or_default();
        let grid = friction_grid(&file, path)?;
        let nsets = match &grid {
            Some((g, _)) => g.cell.len(),
            None => file
                .dimension("set")
                .ok_or_else(|| missing(path, "set"))?
                .len(),
        };
        let sets = set_names(labels, nsets, grid.as_ref());
        let mut fields = grid
            .as_ref()
            .map_or_else(Vec::new, |(_, pairs)| friction_fields(pairs));
        let layout = Layout {
            path,
            thickness: &thickness,
            volume: &volume,
            nsets,
            grid: grid.as_ref(),
        };
        for v in file.variables() {
            if let Some(f) = read_field(&v, &layout)? {
                fields.push((v.name(), f));
            }
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
