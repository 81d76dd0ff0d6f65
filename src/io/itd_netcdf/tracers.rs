//! Snow and tracers of a gridded distribution for the complete ridging step: under CICE
//! restart names, the layout told from the names ([`read_snow_tracers`]), or packed in one
//! array whose layout is given ([`read_packed_tracers`]: Icepack column driver's history
//! `trcrn(time, ncat, ntrcr, ni)`).

use std::path::Path;

use ndarray::{Array1, Array2, Array3, ArrayD, Axis, IxDyn};

use super::vars::{all_dims, fill_of, fmt_dims, is_fill, nc_err, read_f64};
use super::{ItdGrid, NetcdfError};
use crate::itd::details::{CiceLayoutSpec, TracerLayout};

/// Snow and tracers of a gridded distribution, for the complete ridging step. Variable names
/// are CICE restart names ([`TracerLayout::cice_restart_names`]): `vsnon` (m), `Tsfcn`,
/// `qice001`.., `sice001`.., `qsno001`.., and `iage`, `FY`, `alvl`, `vlvl`, `apnd`, `hpnd`,
/// `ipnd` where present, each with the dimensions of `aicen`.
#[derive(Debug, Clone, PartialEq)]
pub struct SnowTracers {
    /// The CICE layout found in the file (its optional tracers: `layout.cice_flags()`).
    pub layout: TracerLayout,
    /// Snow volume per unit area (m), `(ncat, ncol)`; zeros when the file has no `vsnon`.
    pub vsnon: Array2<f64>,
    /// Tracers `(ncat, ntrcr, ncol)` in the layout's order and units.
    pub trcrn: Array3<f64>,
    /// Columns with a fill value in `vsnon` or a tracer (false), if any.
    pub missing: Option<Array1<bool>>,
    /// The fill value of those variables, if any has one.
    pub fill_value: Option<f64>,
    /// Where the tracers were packed in one array ([`read_packed_tracers`]); `None`: one
    /// variable per tracer under its CICE restart name.
    pub packed: Option<PackedTracers>,
}

/// A packed tracer array as the file holds it: what is needed to write it back the same way.
#[derive(Debug, Clone, PartialEq)]
pub struct PackedTracers {
    /// The variable (e.g. `trcrn`).
    pub var: String,
    /// Its dimensions in file order: those of `aicen` with the tracer dimension inserted.
    pub dims: Vec<(String, usize)>,
    /// The position of the tracer dimension among `dims`.
    pub axis: usize,
    /// The layout it was read with.
    pub spec: CiceLayoutSpec,
}

impl PackedTracers {
    /// `trcrn` `(ncat, ntrcr, ncol)` back into the file's order of `dims`.
    pub fn to_file_order(&self, grid: &ItdGrid, trcrn: &Array3<f64>) -> Vec<f64> {
        let shape: Vec<usize> = self.dims.iter().map(|d| d.1).collect();
        let mut out = ArrayD::<f64>::zeros(IxDyn(&shape));
        for it in 0..trcrn.shape()[1] {
            let cat = trcrn
                .index_axis(Axis(1), it)
                .as_standard_layout()
                .into_owned();
            let file = grid.to_file_order(cat.as_slice().expect("standard layout"));
            let mut slot = out.index_axis_mut(Axis(self.axis), it);
            for (x, v) in slot.iter_mut().zip(file) {
                *x = v;
            }
        }
        out.iter().copied().collect()
    }
}

/// Reads `vsnon` (zeros when absent) and the tracers packed in the variable `var` (Icepack
/// column driver's history: `trcrn(time, ncat, ntrcr, ni)`) in the layout `spec`
/// ([`CiceLayoutSpec`], Icepack's packing order). `var` must have the dimensions of `aicen`
/// with one more, the tracer dimension, anywhere among them, as long as the layout's tracer
/// count. Errors name the variable, its dimensions and the layout.
pub fn read_packed_tracers(
    path: &Path,
    grid: &ItdGrid,
    var: &str,
    spec: &CiceLayoutSpec,
) -> Result<SnowTracers, NetcdfError> {
    let value_err = |msg: String| NetcdfError::Value {
        path: path.to_path_buf(),
        var: var.into(),
        msg,
    };
    let layout = spec
        .layout()
        .map_err(|e| value_err(format!("the layout `{spec}`: {e}")))?;
    let file = netcdf::open(path).map_err(nc_err(path))?;
    let v = file
        .variable(var)
        .ok_or_else(|| NetcdfError::MissingVariable {
            path: path.to_path_buf(),
            var: var.into(),
        })?;
    let dims = all_dims(&v);
    let cat_dims = grid.category_dims();
    let axis = (0..dims.len()).find(|&p| {
        let mut rest = dims.clone();
        rest.remove(p);
        rest == cat_dims
    });
    let Some(axis) = axis else {
        return Err(NetcdfError::Shape {
            path: path.to_path_buf(),
            var: var.into(),
            expected: format!(
                "those of aicen {} with one tracer dimension inserted",
                fmt_dims(&cat_dims)
            ),
            found: fmt_dims(&dims),
        });
    };
    let nt = layout.ntrcr();
    let names = layout.cice_restart_names();
    if dims[axis].1 != nt {
        let more = if dims[axis].1 > nt {
            " (Icepack packs biogeochemical tracers last: name them too, e.g. \
             `tr_brine,z_tracers,nblyr=7,tr_zaero,n_zaero=3`)"
        } else {
            ""
        };
        return Err(value_err(format!(
            "its tracer dimension `{}` holds {} tracers, but the layout `{spec}` has {nt} \
             ({}): give the switches that are on in the host's tracer_nml{more}",
            dims[axis].0,
            dims[axis].1,
            names.join(" ")
        )));
    }
    let fill = fill_of(&v);
    let shape: Vec<usize> = dims.iter().map(|d| d.1).collect();
    let all = ArrayD::from_shape_vec(IxDyn(&shape), read_f64(path, &v)?)
        .expect("the library returns the variable's size");
    let (ncat, ncol) = (grid.ncat(), grid.ncol());
    let mut trcrn = Array3::zeros((ncat, nt, ncol));
    let mut missing = vec![false; ncol];
    for it in 0..nt {
        let a = grid.to_category_major(all.index_axis(Axis(axis), it).iter().copied().collect());
        for (c, m) in missing.iter_mut().enumerate() {
            if a.column(c).iter().any(|&x| is_fill(x, fill)) {
                *m = true;
            }
        }
        trcrn.index_axis_mut(Axis(1), it).assign(&a);
    }
    let mut fill_value = fill;
    let vsnon = match file.variable("vsnon") {
        None => Array2::zeros((ncat, ncol)),
        Some(s) => read_category(path, grid, &s, &mut missing, &mut fill_value)?,
    };
    let any_missing = missing.iter().any(|m| *m);
    Ok(SnowTracers {
        layout,
        vsnon,
        trcrn,
        missing: any_missing.then(|| missing.into_iter().map(|m| !m).collect()),
        fill_value,
        packed: Some(PackedTracers {
            var: var.into(),
            dims,
            axis,
            spec: *spec,
        }),
    })
}

/// Reads the snow and tracers that go with `grid` (read from the same file by
/// [`read_itd`](super::read_itd)): `Ok(None)` when the file has none of `vsnon`, `Tsfcn`,
/// `qice001`, `sice001`, `qsno001` (then only area and volume can be ridged). The layout is
/// told from the variable names by [`TracerLayout::detect_cice`] (the one detection, which
/// Python's `xr.ridge_step` uses too). Errors name the missing or malformed variable.
pub fn read_snow_tracers(path: &Path, grid: &ItdGrid) -> Result<Option<SnowTracers>, NetcdfError> {
    let file = netcdf::open(path).map_err(nc_err(path))?;
    let has = |n: &str| file.variable(n).is_some();
    let Some((layout, _)) = TracerLayout::detect_cice(&has).map_err(|e| NetcdfError::Value {
        path: path.to_path_buf(),
        var: e.var.clone(),
        msg: e.to_string(),
    })?
    else {
        return Ok(None);
    };
    let names = layout.cice_restart_names();
    let (ncat, ncol) = (grid.ncat(), grid.ncol());
    let mut fill_value = None;
    let mut missing = vec![false; ncol];
    let mut read_cat = |name: &str| -> Result<Array2<f64>, NetcdfError> {
        let v = file.variable(name).expect("presence checked");
        read_category(path, grid, &v, &mut missing, &mut fill_value)
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
        vsnon,
        trcrn,
        missing: any_missing.then(|| missing.into_iter().map(|m| !m).collect()),
        fill_value,
        packed: None,
    }))
}

/// A variable with the dimensions of `aicen` as `(ncat, ncol)`; its fill value, if any,
/// becomes `fill_value` where none was found yet, and marks the columns where it occurs in
/// `missing`. An error names the variable and its dimensions.
fn read_category(
    path: &Path,
    grid: &ItdGrid,
    v: &netcdf::Variable<'_>,
    missing: &mut [bool],
    fill_value: &mut Option<f64>,
) -> Result<Array2<f64>, NetcdfError> {
    let (d, dims) = (all_dims(v), grid.category_dims());
    if d != dims {
        return Err(NetcdfError::Shape {
            path: path.to_path_buf(),
            var: v.name(),
            expected: fmt_dims(&dims),
            found: fmt_dims(&d),
        });
    }
    let fill = fill_of(v);
    *fill_value = fill_value.or(fill);
    let a = grid.to_category_major(read_f64(path, v)?);
    for (c, m) in missing.iter_mut().enumerate() {
        if a.column(c).iter().any(|&x| is_fill(x, fill)) {
            *m = true;
        }
    }
    Ok(a)
}
