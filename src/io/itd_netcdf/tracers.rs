//! Snow and tracers of a gridded distribution for the complete ridging step
//! ([`read_snow_tracers`]), under CICE restart names, the layout told from the names.

use std::path::Path;

use ndarray::{Array1, Array2, Array3};

use super::vars::{all_dims, fill_of, fmt_dims, is_fill, nc_err, read_f64};
use super::{ItdGrid, NetcdfError};
use crate::itd::{CiceTracerFlags, TracerLayout};

/// Snow and tracers of a gridded distribution, for the complete ridging step. Variable names
/// are CICE restart names ([`TracerLayout::cice_restart_names`]): `vsnon` (m), `Tsfcn`,
/// `qice001`.., `sice001`.., `qsno001`.., and `iage`, `FY`, `alvl`, `vlvl`, `apnd`, `hpnd`,
/// `ipnd` where present, each with the dimensions of `aicen`.
#[derive(Debug, Clone, PartialEq)]
pub struct SnowTracers {
    /// The CICE layout found in the file.
    pub layout: TracerLayout,
    /// The optional tracers found.
    pub flags: CiceTracerFlags,
    /// Snow volume per unit area (m), `(ncat, ncol)`; zeros when the file has no `vsnon`.
    pub vsnon: Array2<f64>,
    /// Tracers `(ncat, ntrcr, ncol)` in the layout's order and units.
    pub trcrn: Array3<f64>,
    /// Columns with a fill value in `vsnon` or a tracer (false), if any.
    pub missing: Option<Array1<bool>>,
    /// The fill value of those variables, if any has one.
    pub fill_value: Option<f64>,
}

/// Reads the snow and tracers that go with `grid` (read from the same file by
/// [`read_itd`](super::read_itd)): `Ok(None)` when the file has none of `vsnon`, `Tsfcn`,
/// `qice001`, `sice001`, `qsno001` (then only area and volume can be ridged). The layout is
/// told from the variable names by [`TracerLayout::detect_cice`] (the one detection, which
/// Python's `xr.ridge_step` uses too). Errors name the missing or malformed variable.
pub fn read_snow_tracers(path: &Path, grid: &ItdGrid) -> Result<Option<SnowTracers>, NetcdfError> {
    let file = netcdf::open(path).map_err(nc_err(path))?;
    let has = |n: &str| file.variable(n).is_some();
    let Some((layout, flags)) =
        TracerLayout::detect_cice(&has).map_err(|e| NetcdfError::Value {
            path: path.to_path_buf(),
            var: e.var.clone(),
            msg: e.to_string(),
        })?
    else {
        return Ok(None);
    };
    let names = layout.cice_restart_names();
    let (ncat, ncol) = (grid.ncat(), grid.ncol());
    let dims = grid.category_dims();
    let mut fill_value = None;
    let mut missing = vec![false; ncol];
    let mut read_cat = |name: &str| -> Result<Array2<f64>, NetcdfError> {
        let v = file.variable(name).expect("presence checked");
        let d = all_dims(&v);
        if d != dims {
            return Err(NetcdfError::Shape {
                path: path.to_path_buf(),
                var: name.into(),
                expected: fmt_dims(&dims),
                found: fmt_dims(&d),
            });
        }
        let fill = fill_of(&v);
        fill_value = fill_value.or(fill);
        let a = grid.to_category_major(read_f64(path, &v)?);
        for (c, m) in missing.iter_mut().enumerate() {
            if a.column(c).iter().any(|&x| is_fill(x, fill)) {
                *m = true;
            }
        }
        Ok(a)
    };
    let vsnon = if has("vsnon") {
        read_cat("vsnon")?
    } else {
        Array2::zeros((ncat, ncol))
    };
    let nt = layout.ntrcr();
    let mut trcrn = Array3::zeros((ncat, nt, ncol));
    for (it, name) in names.iter().enumerate() {
        let a = read_cat(name)?;
        trcrn.index_axis_mut(ndarray::Axis(1), it).assign(&a);
    }
    let any_missing = missing.iter().any(|m| *m);
    Ok(Some(SnowTracers {
        layout,
        flags,
        vsnon,
        trcrn,
        missing: any_missing.then(|| missing.into_iter().map(|m| !m).collect()),
        fill_value,
    }))
}
