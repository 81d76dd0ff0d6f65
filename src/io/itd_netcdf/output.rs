//! Writing per-column results (ice strength, the ridging step's fields) to NetCDF: the
//! input's column dimensions and coordinates kept, land as the fill value, CF-1.8
//! attributes, the options and the command in the history.

use super::vars::nc_err;
use super::*;

/// Description of one output field.
#[derive(Debug, Clone, Copy)]
pub struct FieldMeta<'a> {
    /// Variable name.
    pub name: &'a str,
    /// CF `units`.
    pub units: &'a str,
    /// CF `long_name`.
    pub long_name: &'a str,
    /// CF `standard_name`, where CF defines one.
    pub standard_name: Option<&'a str>,
}

/// A field on dimensions of its own (e.g. a packed tracer array `trcrn(time, ncat, ntrcr,
/// ni)`): values in the file's order of `dims`; dimensions the grid does not have are added.
#[derive(Debug, Clone)]
pub struct DimField<'a> {
    /// Variable name.
    pub name: &'a str,
    /// Dimensions (name, length) in file order.
    pub dims: Vec<(String, usize)>,
    /// Values in C order over `dims`.
    pub data: &'a [f64],
    /// Attributes (name, text), e.g. `long_name` (no `units` for fields of mixed units).
    pub attrs: Vec<(&'a str, String)>,
}

/// What to write: an optional distribution (with bounds) and any number of 2-D fields.
#[derive(Debug, Clone, Copy)]
pub struct Output<'a> {
    /// Category and spatial layout (only the dimension names and lengths are used, plus
    /// `aicen`/`vicen`/`aice0` when `write_itd` is true).
    pub grid: &'a ItdGrid,
    /// Also write `aicen`, `vicen`, `aice0` (from `grid.aice0`, else 1 − Σ aicen) and
    /// `hin_max` from `hin_max`.
    pub write_itd: bool,
    /// Category bounds to write with the distribution (m).
    pub hin_max: Option<&'a [f64]>,
    /// Extra fields on the spatial dimensions, `ncol` values each.
    pub fields: &'a [(FieldMeta<'a>, &'a [f64])],
    /// Extra fields on the category and spatial dimensions (as `aicen`), `ncat·ncol` values
    /// each in C order (category slowest); written after `fields`.
    pub category_fields: &'a [(FieldMeta<'a>, &'a [f64])],
    /// Fields on dimensions of their own, written last.
    pub dim_fields: &'a [DimField<'a>],
    /// Global attributes (name, value): options used.
    pub global: &'a [(String, String)],
    /// Fill value for masked columns (`grid.valid` false): written as `_FillValue` of every
    /// gridded variable and into the computed `aice0` of masked columns.
    pub fill: Option<f64>,
    /// A line for the global `history` (see [`history_line`]), appended to the input's.
    pub history: Option<&'a str>,
}

/// A `history` line for the command being run: the UTC time (ISO 8601) and the command line,
/// as CF recommends.
pub fn history_line() -> String {
    let args: Vec<String> = std::env::args()
        .map(|a| {
            if a.is_empty() || a.contains(char::is_whitespace) {
                format!("'{a}'")
            } else {
                a
            }
        })
        .collect();
    format!("{}: {}", crate::io::utc_now(), args.join(" "))
}

/// Writes `out` to a new file at `path` in the NetCDF 64-bit-offset format (readable by
/// every NetCDF tool; netCDF-C 4.9.0 with HDF5 1.10 prints spurious `HDF5-DIAG` messages
/// when NetCDF-4 files are read from a non-main thread), with CF attributes,
/// `Conventions = CF-1.8`, `source`/`pressridge_version` and the given global attributes.
///
/// The file is written atomically ([`crate::io::write_atomic_with`]): a writer killed or
/// failing at any moment leaves the previous file at `path` (or none), never a partial one.
pub fn write_output(path: &Path, out: &Output<'_>) -> Result<(), NetcdfError> {
    crate::io::write_atomic_with(path, |tmp| write_output_at(tmp, path, out))
}

/// [`write_output`] into the file `tmp`; errors name `path`.
fn write_output_at(tmp: &Path, path: &Path, out: &Output<'_>) -> Result<(), NetcdfError> {
    let e = nc_err(path);
    let g = out.grid;
    let ncol = g.ncol();
    check_shapes(path, out)?;
    let spatial: Vec<&str> = g.spatial_dims.iter().map(|d| d.0.as_str()).collect();
    let mut cat_dims: Vec<&str> = spatial.clone();
    cat_dims.insert(g.cat_axis.min(spatial.len()), g.ncat_dim.as_str());
    let bdim = format!("{}_bounds", g.ncat_dim);

    // Everything to write: (metadata, dimensions, values). Owned copies of the distribution
    // in the file's order (the classic format wants all definitions before any data).
    let a = g.to_file_order(
        g.aicen
            .as_standard_layout()
            .as_slice()
            .expect("standard layout"),
    );
    let v = g.to_file_order(
        g.vicen
            .as_standard_layout()
            .as_slice()
            .expect("standard layout"),
    );
    let cat_data: Vec<Vec<f64>> = out
        .category_fields
        .iter()
        .map(|(_, d)| g.to_file_order(d))
        .collect();
    let aice0: Vec<f64> = match &g.aice0 {
        Some(a0) => a0.to_vec(),
        None => (0..ncol)
            .map(|c| match (&g.valid, out.fill) {
                (Some(v), Some(f)) if !v[c] => f,
                _ => 1.0 - g.aicen.column(c).sum(),
            })
            .collect(),
    };
    let mut items: Vec<Item<'_>> = Vec::new();
    if out.write_itd {
        items.push((
            FieldMeta {
                name: "aicen",
                units: "1",
                long_name: "sea ice area fraction in each thickness category",
                standard_name: Some("sea_ice_area_fraction"),
            },
            cat_dims.clone(),
            &a,
        ));
        items.push((
            FieldMeta {
                name: "vicen",
                units: "m",
                long_name: "sea ice volume per unit grid-cell area in each thickness category",
                standard_name: None,
            },
            cat_dims.clone(),
            &v,
        ));
        items.push((
            FieldMeta {
                name: "aice0",
                units: "1",
                long_name: "open water fraction",
                standard_name: None,
            },
            spatial.clone(),
            &aice0,
        ));
        if let Some(h) = out.hin_max {
            items.push((
                FieldMeta {
                    name: "hin_max",
                    units: "m",
                    long_name: "thickness category bounds",
                    standard_name: None,
                },
                vec![bdim.as_str()],
                h,
            ));
        }
    }
    for (meta, data) in out.fields {
        items.push((*meta, spatial.clone(), data));
    }
    for ((meta, _), data) in out.category_fields.iter().zip(&cat_data) {
        items.push((*meta, cat_dims.clone(), data));
    }
    let has_cat = out.write_itd || !out.category_fields.is_empty();
    let (coords, coordinates) = kept_coordinates(g, &items, &spatial, has_cat);

    let mut f = netcdf::create_with(tmp, netcdf::Options::_64BIT_OFFSET).map_err(&e)?;
    for (n, l) in &g.spatial_dims {
        f.add_dimension(n, *l).map_err(&e)?;
    }
    if has_cat {
        f.add_dimension(&g.ncat_dim, g.ncat()).map_err(&e)?;
    }
    if out.write_itd {
        if let Some(h) = out.hin_max {
            f.add_dimension(&bdim, h.len()).map_err(&e)?;
        }
    }
    define_dim_fields(&mut f, path, out, coordinates.as_deref())?;
    define_items(&mut f, path, out, &items, coordinates.as_deref())?;
    for c in &coords {
        let dims: Vec<&str> = c.dims.iter().map(String::as_str).collect();
        let mut var = c.values.define(&mut f, &c.name, &dims).map_err(&e)?;
        for (k, val) in &c.attrs {
            var.put_attribute(k, val.clone()).map_err(&e)?;
        }
    }
    global_attributes(&mut f, path, out)?;
    f.enddef().map_err(&e)?;
    for (meta, _, data) in &items {
        let mut var = f.variable_mut(meta.name).expect("just defined");
        var.put_values(data, ..).map_err(&e)?;
    }
    for d in out.dim_fields {
        let mut var = f.variable_mut(d.name).expect("just defined");
        var.put_values(d.data, ..).map_err(&e)?;
    }
    for c in &coords {
        let mut var = f.variable_mut(&c.name).expect("just defined");
        c.values.put(&mut var).map_err(&e)?;
    }
    f.close().map_err(&e)?;
    Ok(())
}

/// A field to write: its metadata, dimensions and values in file order.
type Item<'a> = (FieldMeta<'a>, Vec<&'a str>, &'a [f64]);

/// The input's coordinate variables whose dimensions are all written (and that no field
/// replaces), and the `coordinates` attribute naming the auxiliary ones among them.
fn kept_coordinates<'g>(
    g: &'g ItdGrid,
    items: &[Item<'_>],
    spatial: &[&str],
    has_cat: bool,
) -> (Vec<&'g CoordVar>, Option<String>) {
    let coords: Vec<&CoordVar> = g
        .coords
        .iter()
        .filter(|c| {
            c.dims
                .iter()
                .all(|d| spatial.contains(&d.as_str()) || (has_cat && *d == g.ncat_dim))
        })
        .filter(|c| !items.iter().any(|(m, _, _)| m.name == c.name))
        .collect();
    let coordinates: Option<String> = g.coordinates.as_ref().and_then(|list| {
        let kept: Vec<&str> = list
            .split_whitespace()
            .filter(|n| coords.iter().any(|c| c.name == *n))
            .collect();
        (!kept.is_empty()).then(|| kept.join(" "))
    });
    (coords, coordinates)
}

/// Defines each field with its CF attributes, the fill value and the coordinates (not on
/// the category bounds).
fn define_items(
    f: &mut netcdf::FileMut,
    path: &Path,
    out: &Output<'_>,
    items: &[Item<'_>],
    coordinates: Option<&str>,
) -> Result<(), NetcdfError> {
    let e = nc_err(path);
    for (meta, dims, _) in items {
        let mut var = f.add_variable::<f64>(meta.name, dims).map_err(&e)?;
        var.put_attribute("units", meta.units).map_err(&e)?;
        var.put_attribute("long_name", meta.long_name).map_err(&e)?;
        if let Some(s) = meta.standard_name {
            var.put_attribute("standard_name", s).map_err(&e)?;
        }
        if let Some(fill) = out.fill
            && meta.name != "hin_max"
        {
            var.put_attribute("_FillValue", fill).map_err(&e)?;
        }
        if let Some(c) = coordinates
            && meta.name != "hin_max"
        {
            var.put_attribute("coordinates", c).map_err(&e)?;
        }
    }
    Ok(())
}

/// Refuses an output whose fields do not have the grid's shape, naming the field.
fn check_shapes(path: &Path, out: &Output<'_>) -> Result<(), NetcdfError> {
    let g = out.grid;
    let ncol = g.ncol();
    for (meta, data) in out.category_fields {
        if data.len() != ncol * g.ncat() {
            return Err(NetcdfError::Shape {
                path: path.to_path_buf(),
                var: meta.name.into(),
                expected: format!("{} values", ncol * g.ncat()),
                found: format!("{} values", data.len()),
            });
        }
    }
    for (meta, data) in out.fields {
        if data.len() != ncol {
            return Err(NetcdfError::Shape {
                path: path.to_path_buf(),
                var: meta.name.into(),
                expected: format!("{ncol} values"),
                found: format!("{} values", data.len()),
            });
        }
    }
    for d in out.dim_fields {
        let n: usize = d.dims.iter().map(|x| x.1).product();
        if d.data.len() != n {
            return Err(NetcdfError::Shape {
                path: path.to_path_buf(),
                var: d.name.into(),
                expected: format!("{n} values ({})", fmt_dims(&d.dims)),
                found: format!("{} values", d.data.len()),
            });
        }
    }
    Ok(())
}

/// Defines the dimensions and variables of the output's fields of their own dimensions
/// (`out.dim_fields`), with the fill value and the coordinates attribute `coordinates`.
fn define_dim_fields(
    f: &mut netcdf::FileMut,
    path: &Path,
    out: &Output<'_>,
    coordinates: Option<&str>,
) -> Result<(), NetcdfError> {
    let e = nc_err(path);
    for d in out.dim_fields {
        for (n, l) in &d.dims {
            match f.dimension(n) {
                Some(have) if have.len() == *l => {}
                Some(have) => {
                    return Err(NetcdfError::Shape {
                        path: path.to_path_buf(),
                        var: d.name.into(),
                        expected: format!("dimension {n}={}", have.len()),
                        found: format!("{n}={l}"),
                    });
                }
                None => {
                    f.add_dimension(n, *l).map_err(&e)?;
                }
            }
        }
        let names: Vec<&str> = d.dims.iter().map(|x| x.0.as_str()).collect();
        let mut var = f.add_variable::<f64>(d.name, &names).map_err(&e)?;
        for (k, v) in &d.attrs {
            var.put_attribute(k, v.as_str()).map_err(&e)?;
        }
        if let Some(fill) = out.fill {
            var.put_attribute("_FillValue", fill).map_err(&e)?;
        }
        if let Some(c) = coordinates {
            var.put_attribute("coordinates", c).map_err(&e)?;
        }
    }
    Ok(())
}

/// The global attributes: `Conventions`, `source`, `pressridge_version`, the output's own,
/// and `history` (the input's with this step's line appended).
fn global_attributes(
    f: &mut netcdf::FileMut,
    path: &Path,
    out: &Output<'_>,
) -> Result<(), NetcdfError> {
    let e = nc_err(path);
    let g = out.grid;
    f.add_attribute("Conventions", "CF-1.8").map_err(&e)?;
    f.add_attribute(
        "source",
        format!("pressridge {}", env!("CARGO_PKG_VERSION")),
    )
    .map_err(&e)?;
    f.add_attribute("pressridge_version", env!("CARGO_PKG_VERSION"))
        .map_err(&e)?;
    for (k, val) in out.global {
        f.add_attribute(k, val.as_str()).map_err(&e)?;
    }
    let history = match (&g.history, out.history) {
        (Some(old), Some(new)) if !old.is_empty() => Some(format!("{old}\n{new}")),
        (_, Some(new)) => Some(new.to_string()),
        (old, None) => old.clone(),
    };
    if let Some(h) = history {
        f.add_attribute("history", h).map_err(&e)?;
    }
    Ok(())
}

/// NetCDF's default fill value for doubles (`NC_FILL_DOUBLE`).
pub const NC_FILL_DOUBLE: f64 = 9.969_209_968_386_869e36;

/// Metadata of the `strength` output field (N/m).
pub const STRENGTH_META: FieldMeta<'static> = FieldMeta {
    name: "strength",
    units: "N m-1",
    long_name: "compressive ice strength P",
    // The CF standard name, as CMIP6 SIMIP's `sicompstren` (canonical units N m-1).
    standard_name: Some("compressive_strength_of_sea_ice"),
};
