//! Reading a gridded thickness distribution ([`read_itd`], [`read_itd_with`]): `aicen` and
//! `vicen` with their category dimension, `aice0`, the category bounds (`hin_max` or
//! CICE's `NCAT`), the land mask, the deformation, the coordinates, and the range check of
//! the volumes.

use std::path::Path;

use ndarray::{Array1, Array2};

use super::forcing::read_deformation;
use super::vars::{
    all_dims, dims_of, fill_of, fmt_dims, is_fill, nc_err, read_f64, read_spatial, required,
    str_attr,
};
use super::{CoordValues, CoordVar, ItdGrid, NetcdfError, ReadOptions, category_axis};

/// The ocean mask of CICE history files, `tmask` (1 ocean, 0 land), over the column
/// dimensions: `None` without `tmask`; otherwise per column whether it is ocean. `tmask` may
/// lack column dimensions (it has no `time`): it is then the same at every value of those.
/// A zero or fill value is land. A `tmask` with a dimension that is not a column dimension
/// of the same length is refused.
fn read_ocean_mask(
    path: &Path,
    file: &netcdf::File,
    spatial: &[(String, usize)],
) -> Result<Option<Vec<bool>>, NetcdfError> {
    let Some(v) = file.variable("tmask") else {
        return Ok(None);
    };
    let d = all_dims(&v);
    let pos: Option<Vec<usize>> = d
        .iter()
        .map(|(n, l)| spatial.iter().position(|(m, k)| m == n && k == l))
        .collect();
    let Some(pos) = pos else {
        return Err(NetcdfError::Shape {
            path: path.to_path_buf(),
            var: "tmask".into(),
            expected: format!("column dimensions of aicen, {}", fmt_dims(spatial)),
            found: fmt_dims(&d),
        });
    };
    let vals = read_f64(path, &v)?;
    let fill = fill_of(&v);
    let ncol: usize = spatial.iter().map(|s| s.1).product();
    let mut idx = vec![0usize; spatial.len()];
    let mut out = Vec::with_capacity(ncol);
    for c in 0..ncol {
        let mut rem = c;
        for k in (0..spatial.len()).rev() {
            idx[k] = rem % spatial[k].1;
            rem /= spatial[k].1;
        }
        let j = pos
            .iter()
            .zip(&d)
            .fold(0usize, |j, (&p, (_, l))| j * l + idx[p]);
        let m = vals[j];
        out.push(!(is_fill(m, fill) || m == 0.0));
    }
    Ok(Some(out))
}

/// Reads a gridded thickness distribution (see the module documentation for the layout),
/// the category dimension found by name.
pub fn read_itd(path: &Path) -> Result<ItdGrid, NetcdfError> {
    read_itd_with(path, &ReadOptions::default())
}

/// The values of coordinate `v` in its own numeric type; `None` for a non-numeric one.
fn coord_values(path: &Path, v: &netcdf::Variable<'_>) -> Result<Option<CoordValues>, NetcdfError> {
    use netcdf::types::{FloatType as F, IntType as I, NcVariableType as T};
    // `vartype` panics on a type it does not know: not numeric either.
    let t = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| v.vartype())).ok();
    let e = nc_err(path);
    Ok(Some(match t {
        Some(T::Float(F::F64)) => CoordValues::F64(v.get_values(..).map_err(e)?),
        Some(T::Float(F::F32)) => CoordValues::F32(v.get_values(..).map_err(e)?),
        Some(T::Int(I::I8)) => CoordValues::I8(v.get_values(..).map_err(e)?),
        Some(T::Int(I::I16)) => CoordValues::I16(v.get_values(..).map_err(e)?),
        Some(T::Int(I::I32)) => CoordValues::I32(v.get_values(..).map_err(e)?),
        Some(T::Int(I::I64)) => CoordValues::I64(v.get_values(..).map_err(e)?),
        Some(T::Int(I::U8)) => CoordValues::U8(v.get_values(..).map_err(e)?),
        Some(T::Int(I::U16)) => CoordValues::U16(v.get_values(..).map_err(e)?),
        Some(T::Int(I::U32)) => CoordValues::U32(v.get_values(..).map_err(e)?),
        Some(T::Int(I::U64)) => CoordValues::U64(v.get_values(..).map_err(e)?),
        _ => return Ok(None),
    }))
}

/// A coordinate variable of `file` to copy, if it is numeric and lies on `allowed` dims.
fn coord_var(
    path: &Path,
    file: &netcdf::File,
    name: &str,
    allowed: &[&str],
) -> Result<Option<CoordVar>, NetcdfError> {
    let Some(v) = file.variable(name) else {
        return Ok(None);
    };
    let dims: Vec<String> = v.dimensions().iter().map(|d| d.name()).collect();
    if dims.is_empty() || !dims.iter().all(|d| allowed.contains(&d.as_str())) {
        return Ok(None);
    }
    let Some(values) = coord_values(path, &v)? else {
        return Ok(None); // a text (or other non-numeric) coordinate: not copied
    };
    let mut attrs = Vec::new();
    for a in v.attributes() {
        let n = a.name().to_string();
        // Bounds variables are not copied; the fill value keeps the variable's type.
        if matches!(n.as_str(), "bounds" | "coordinates") {
            continue;
        }
        if let Ok(x) = a.value() {
            attrs.push((n, x));
        }
    }
    Ok(Some(CoordVar {
        name: name.into(),
        dims,
        values,
        attrs,
    }))
}

/// Category bounds (m) from `hin_max` (ncat + 1 values) or CICE history's `NCAT` (the ncat
/// upper bounds, on the category dimension; the lowest bound is 0 m), checked against each
/// other when both are present, and validated. Returns the bounds and their source.
fn read_bounds(
    path: &Path,
    file: &netcdf::File,
    cat_dim: &str,
    ncat: usize,
) -> Result<Option<(Vec<f64>, String)>, NetcdfError> {
    let from_hin_max = match file.variable("hin_max") {
        None => None,
        Some(h) => {
            let vals = read_f64(path, &h)?;
            if h.dimensions().len() != 1 || vals.len() != ncat + 1 {
                return Err(NetcdfError::Shape {
                    path: path.to_path_buf(),
                    var: "hin_max".into(),
                    expected: format!("one dimension of length ncat + 1 = {}", ncat + 1),
                    found: fmt_dims(&dims_of(&h)),
                });
            }
            Some(vals)
        }
    };
    let from_ncat = match file.variable("NCAT") {
        None => None,
        Some(v) => {
            let d = all_dims(&v);
            if d != [(cat_dim.to_string(), ncat)] {
                return Err(NetcdfError::Shape {
                    path: path.to_path_buf(),
                    var: "NCAT".into(),
                    expected: format!(
                        "({cat_dim}={ncat}): the upper bound of each category (CICE history)"
                    ),
                    found: fmt_dims(&d),
                });
            }
            let mut b = vec![0.0];
            b.extend(read_f64(path, &v)?);
            Some(b)
        }
    };
    let (vals, source) = match (from_hin_max, from_ncat) {
        (None, None) => return Ok(None),
        (Some(h), None) => (h, "hin_max from the input".to_string()),
        (None, Some(n)) => (
            n,
            "NCAT from the input (CICE history: upper bounds; lowest bound 0 m)".to_string(),
        ),
        (Some(h), Some(n)) => {
            // NCAT is often single precision: agree to its precision.
            let agree = h
                .iter()
                .zip(&n)
                .all(|(a, b)| (a - b).abs() <= 1e-6 * a.abs().max(1.0));
            if !agree {
                return Err(NetcdfError::Value {
                    path: path.to_path_buf(),
                    var: "NCAT".into(),
                    msg: format!(
                        "the category bounds disagree: hin_max is {h:?} m, NCAT (upper bounds, \
                         from 0 m) gives {n:?} m"
                    ),
                });
            }
            (h, "hin_max from the input (agrees with NCAT)".to_string())
        }
    };
    let var = if source.starts_with("NCAT") {
        "NCAT"
    } else {
        "hin_max"
    };
    crate::itd::details::validate_bounds(&vals).map_err(|e| NetcdfError::Value {
        path: path.to_path_buf(),
        var: var.into(),
        msg: e.to_string(),
    })?;
    Ok(Some((vals, source)))
}

/// Reads a gridded thickness distribution (see the module documentation for the layout).
pub fn read_itd_with(path: &Path, opts: &ReadOptions) -> Result<ItdGrid, NetcdfError> {
    let file = netcdf::open(path).map_err(nc_err(path))?;
    let get = |name: &str| required(path, &file, name);
    let av = get("aicen")?;
    let vv = get("vicen")?;
    let ad = all_dims(&av);
    let vd = all_dims(&vv);
    if ad.is_empty() {
        return Err(NetcdfError::Shape {
            path: path.to_path_buf(),
            var: "aicen".into(),
            expected: "(a category dimension, column dimensions...)".into(),
            found: "a scalar".into(),
        });
    }
    if vd != ad {
        return Err(NetcdfError::Shape {
            path: path.to_path_buf(),
            var: "vicen".into(),
            expected: fmt_dims(&ad),
            found: fmt_dims(&vd),
        });
    }
    let cat_axis = category_axis(path, "aicen", &ad, opts.category_dim.as_deref())?;
    let (ncat_dim, ncat) = ad[cat_axis].clone();
    let mut spatial: Vec<(String, usize)> = ad.clone();
    spatial.remove(cat_axis);
    let ncol: usize = spatial.iter().map(|d| d.1).product();
    let mut grid = ItdGrid {
        ncat_dim: ncat_dim.clone(),
        spatial_dims: spatial.clone(),
        cat_axis,
        aicen: Array2::zeros((ncat, ncol)),
        ..Default::default()
    };
    let aicen = grid.to_category_major(read_f64(path, &av)?);
    let vicen = grid.to_category_major(read_f64(path, &vv)?);
    let (afill, vfill) = (fill_of(&av), fill_of(&vv));
    let a0fill = file.variable("aice0").as_ref().and_then(fill_of);
    let bounds = read_bounds(path, &file, &ncat_dim, ncat)?;
    let aice0 = read_spatial(path, &file, "aice0", &spatial)?;
    let ocean = read_ocean_mask(path, &file, &spatial)?;
    let valid: Array1<bool> = (0..ncol)
        .map(|c| {
            ocean.as_ref().is_none_or(|o| o[c])
                && !(aicen.column(c).iter().any(|&x| is_fill(x, afill))
                    || vicen.column(c).iter().any(|&x| is_fill(x, vfill))
                    || aice0.as_ref().is_some_and(|a| is_fill(a[c], a0fill)))
        })
        .collect();
    let (divu, shear) = if opts.without_deformation {
        (None, None)
    } else {
        read_deformation(path, &file, &spatial)?
    };
    // Coordinates: those of the column dimensions, and aicen's auxiliary ones.
    let names: Vec<&str> = spatial.iter().map(|d| d.0.as_str()).collect();
    let mut coords = Vec::new();
    for n in &names {
        if let Some(c) = coord_var(path, &file, n, &names)? {
            coords.push(c);
        }
    }
    let mut aux = Vec::new();
    if let Some(list) = str_attr(&av, "coordinates") {
        for n in list.split_whitespace() {
            if coords.iter().any(|c| c.name == n) {
                continue;
            }
            if let Some(c) = coord_var(path, &file, n, &names)? {
                coords.push(c);
                aux.push(n.to_string());
            }
        }
    }
    let history = file
        .attribute("history")
        .and_then(|a| a.value().ok())
        .and_then(|x| String::try_from(x).ok());
    let (hin_max, hin_max_source) = match bounds {
        Some((b, s)) => (Some(b), Some(s)),
        None => (None, None),
    };
    grid.aicen = aicen;
    grid.vicen = vicen;
    grid.aice0 = aice0;
    grid.divu = divu;
    grid.shear = shear;
    grid.hin_max = hin_max;
    grid.hin_max_source = hin_max_source;
    grid.coords = coords;
    grid.coordinates = (!aux.is_empty()).then(|| aux.join(" "));
    grid.history = history;
    grid.fill_value = afill.or(vfill).or(a0fill);
    grid.valid = if valid.iter().all(|&v| v) {
        None
    } else {
        Some(valid)
    };
    check_volume_range(path, &grid)?;
    Ok(grid)
}

/// Refuses a category volume beyond [`crate::itd::limits::CATEGORY_THICKNESS`] (vicen ≤ vicen /
/// aicen, so a larger vicen means thicker ice than any), which would overflow the squares
/// and exponentials of the strength and ridging formulas into inf or NaN. Masked columns are
/// not checked; NaN, infinite and negative values are the physics' to name.
fn check_volume_range(path: &Path, g: &ItdGrid) -> Result<(), NetcdfError> {
    let range = crate::itd::limits::CATEGORY_THICKNESS;
    for c in 0..g.ncol() {
        if g.valid.as_ref().is_some_and(|v| !v[c]) {
            continue;
        }
        for (k, &x) in g.vicen.column(c).iter().enumerate() {
            if x.is_finite()
                && x > range.max
                && let Some(why) = range.violation(x)
            {
                return Err(NetcdfError::Value {
                    path: path.to_path_buf(),
                    var: "vicen".into(),
                    msg: format!(
                        "column {c} at ({}), category {k}: {why}",
                        g.spatial_index(c)
                    ),
                });
            }
        }
    }
    Ok(())
}
