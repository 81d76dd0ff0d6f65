//! The gridded thickness distribution read from a file ([`ItdGrid`]): its column
//! dimensions flattened to columns, the category order of the file, the coordinates to copy
//! to the outputs, and the error location of a column.

use std::path::Path;

use ndarray::{Array1, Array2, Array3};

use super::NetcdfError;
use crate::itd::ItdError;

/// A coordinate variable copied from the input to the outputs: its values, in the type the
/// input stores them in, and its attributes (`units`, `calendar`, `standard_name`,
/// `_FillValue`...), so that an output's coordinate is the input's (an `int ni` stays int).
#[derive(Debug, Clone, PartialEq)]
pub struct CoordVar {
    /// Variable name (e.g. `time`, `TLON`).
    pub name: String,
    /// Its dimensions, in file order.
    pub dims: Vec<String>,
    /// Its values in C order, in the input's type.
    pub values: CoordValues,
    /// Its attributes as the input has them (the fill value in the variable's own type).
    pub attrs: Vec<(String, netcdf::AttributeValue)>,
}

/// The values of a [`CoordVar`] in the numeric type of the input's variable.
#[derive(Debug, Clone, PartialEq)]
#[allow(missing_docs)]
pub enum CoordValues {
    F64(Vec<f64>),
    F32(Vec<f32>),
    I8(Vec<i8>),
    I16(Vec<i16>),
    I32(Vec<i32>),
    I64(Vec<i64>),
    U8(Vec<u8>),
    U16(Vec<u16>),
    U32(Vec<u32>),
    U64(Vec<u64>),
}

/// Evaluates `$body` with `$v` bound to the values of whichever variant `$values` is: the
/// one list of the ten types, for the generic code that writes them.
macro_rules! each_coord_type {
    ($values:expr, $v:ident => $body:expr) => {
        match $values {
            CoordValues::F64($v) => $body,
            CoordValues::F32($v) => $body,
            CoordValues::I8($v) => $body,
            CoordValues::I16($v) => $body,
            CoordValues::I32($v) => $body,
            CoordValues::I64($v) => $body,
            CoordValues::U8($v) => $body,
            CoordValues::U16($v) => $body,
            CoordValues::U32($v) => $body,
            CoordValues::U64($v) => $body,
        }
    };
}

impl CoordValues {
    /// Defines variable `name` on `dims` in `f` with these values' type.
    pub(crate) fn define<'f>(
        &self,
        f: &'f mut netcdf::FileMut,
        name: &str,
        dims: &[&str],
    ) -> netcdf::Result<netcdf::VariableMut<'f>> {
        fn add<'f, T: netcdf::NcTypeDescriptor>(
            f: &'f mut netcdf::FileMut,
            name: &str,
            dims: &[&str],
            _: &[T],
        ) -> netcdf::Result<netcdf::VariableMut<'f>> {
            f.add_variable::<T>(name, dims)
        }
        each_coord_type!(self, v => add(f, name, dims, v))
    }

    /// Writes the values into `var`, defined by [`CoordValues::define`].
    pub(crate) fn put(&self, var: &mut netcdf::VariableMut<'_>) -> netcdf::Result<()> {
        each_coord_type!(self, v => var.put_values(v, ..))
    }
}

/// A gridded thickness distribution with its column dimensions (every dimension of `aicen`
/// but the category one) flattened to `ncol` columns (C order, last dimension fastest).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ItdGrid {
    /// Name of the category dimension (e.g. `ncat`).
    pub ncat_dim: String,
    /// Column dimensions (name, length) in file order, without the category dimension
    /// (e.g. `time`, `nj`, `ni`).
    pub spatial_dims: Vec<(String, usize)>,
    /// Position of the category dimension among the dimensions of `aicen` in the file (0:
    /// first); the category fields are written in that order again.
    pub cat_axis: usize,
    /// Coordinate variables to copy to the outputs.
    pub coords: Vec<CoordVar>,
    /// The auxiliary coordinates of `aicen` that were copied (its `coordinates` attribute),
    /// e.g. `TLON TLAT`.
    pub coordinates: Option<String>,
    /// The input's global `history` attribute.
    pub history: Option<String>,
    /// Where `hin_max` came from (`hin_max`, or `NCAT` of a CICE history file).
    pub hin_max_source: Option<String>,
    /// Category area fractions (dimensionless), shape (ncat, ncol).
    pub aicen: Array2<f64>,
    /// Category ice volume per unit area (m), shape (ncat, ncol).
    pub vicen: Array2<f64>,
    /// Open-water fraction (dimensionless), if present in the file.
    pub aice0: Option<Array1<f64>>,
    /// Category bounds (m), ncat + 1 values, if the file has them (`hin_max`, or `NCAT`
    /// with 0 m prepended; see `hin_max_source`).
    pub hin_max: Option<Vec<f64>>,
    /// Velocity divergence (1/s), if present.
    pub divu: Option<Array1<f64>>,
    /// Shear term of the ridging closing rate (1/s), if present.
    pub shear: Option<Array1<f64>>,
    /// Columns holding data (false where `aicen`, `vicen` or `aice0` equals its
    /// `_FillValue`/`missing_value`, e.g. land); `None` when no value is missing.
    pub valid: Option<Array1<bool>>,
    /// The fill value of `aicen` in the input (used for masked columns on output), if any.
    pub fill_value: Option<f64>,
}

impl ItdGrid {
    /// Number of categories.
    pub fn ncat(&self) -> usize {
        self.aicen.nrows()
    }
    /// Number of columns (product of the spatial lengths).
    pub fn ncol(&self) -> usize {
        self.aicen.ncols()
    }
    /// Numbers of columns before and after the category dimension in file order: the file
    /// holds (n_before, ncat, n_after) values.
    pub fn split(&self) -> (usize, usize) {
        let k = self.cat_axis.min(self.spatial_dims.len());
        let before = self.spatial_dims[..k].iter().map(|d| d.1).product();
        let after = self.spatial_dims[k..].iter().map(|d| d.1).product();
        (before, after)
    }
    /// The dimensions of a category variable in file order (the category dimension at
    /// `cat_axis` among the column dimensions).
    pub fn category_dims(&self) -> Vec<(String, usize)> {
        let mut d = self.spatial_dims.clone();
        d.insert(
            self.cat_axis.min(d.len()),
            (self.ncat_dim.clone(), self.ncat()),
        );
        d
    }
    /// Values of a category variable in file order, turned into (ncat, ncol).
    pub fn to_category_major(&self, data: Vec<f64>) -> Array2<f64> {
        let (ncat, (before, after)) = (self.aicen.nrows(), self.split());
        let a = Array3::from_shape_vec((before, ncat, after), data)
            .expect("length checked by the library");
        a.permuted_axes([1, 0, 2])
            .as_standard_layout()
            .into_owned()
            .into_shape_with_order((ncat, before * after))
            .expect("standard layout")
    }
    /// (ncat, ncol) values in C order turned into the file order of the category variables.
    pub fn to_file_order(&self, data: &[f64]) -> Vec<f64> {
        let (ncat, (before, after)) = (self.ncat(), self.split());
        if before == 1 {
            return data.to_vec();
        }
        let a = ndarray::ArrayView3::from_shape((ncat, before, after), data)
            .expect("length checked by the caller");
        a.permuted_axes([1, 0, 2]).iter().copied().collect()
    }
    /// The spatial index of flat column `column`, formatted as `name=i, ...`.
    pub fn spatial_index(&self, column: usize) -> String {
        let mut rem = column;
        let mut idx = vec![0; self.spatial_dims.len()];
        for (k, (_, len)) in self.spatial_dims.iter().enumerate().rev() {
            idx[k] = rem % len;
            rem /= len;
        }
        self.spatial_dims
            .iter()
            .zip(idx)
            .map(|((n, _), i)| format!("{n}={i}"))
            .collect::<Vec<_>>()
            .join(", ")
    }
    /// Wraps a physics error with the file name and, for a column error, the spatial index.
    pub fn locate(&self, path: &Path, e: ItdError) -> NetcdfError {
        match e {
            ItdError::Column { column, source } => NetcdfError::Column {
                path: path.to_path_buf(),
                column,
                spatial: self.spatial_index(column),
                source,
            },
            other => NetcdfError::Itd {
                path: path.to_path_buf(),
                source: other,
            },
        }
    }
}
