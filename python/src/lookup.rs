//! Lookup tables: `RidgeLookup`, a table file that `pressridge tabulate` wrote, opened for
//! lookups (wrapped by `pressridge.Table` in `_table.py`).

use std::path::PathBuf;
use std::sync::Arc;

use numpy::{PyArray1, PyArrayDyn};
use pyo3::prelude::*;

use pressridge::table::lookup::{LookupError, RidgeLookup};

use crate::arrays::{Pair, check_aligned};
use crate::errors::{BindError, detached, file_missing, value_err};

fn lookup_err(e: LookupError) -> BindError {
    value_err(e)
}

/// `lookup(i)` (value, clamped) for every i in 0..n, off the interpreter lock; returns
/// (values, clamped).
fn lookup_each<'py>(
    py: Python<'py>,
    n: usize,
    lookup: impl Fn(usize) -> Result<(f64, bool), LookupError> + Send,
) -> PyResult<Pair<'py, bool>> {
    let (vals, clamped): (Vec<f64>, Vec<bool>) = detached(py, move || {
        (0..n)
            .map(|i| lookup(i).map_err(lookup_err))
            .collect::<Result<_, _>>()
    })?;
    Ok((
        PyArray1::from_vec(py, vals),
        PyArray1::from_vec(py, clamped),
    ))
}

/// A ridging lookup table (`pressridge::table::lookup::RidgeLookup`) opened from the NetCDF
/// file that `pressridge tabulate` writes. Wrapped by `pressridge.Table`.
#[pyclass(frozen, name = "RidgeLookup", module = "pressridge._core")]
pub(crate) struct PyRidgeLookup {
    inner: Arc<RidgeLookup>,
}

#[pymethods]
impl PyRidgeLookup {
    /// Reads a table file.
    #[staticmethod]
    fn open(py: Python<'_>, path: PathBuf) -> PyResult<Self> {
        let t = detached(py, || {
            file_missing(&path)?;
            RidgeLookup::open(&path).map_err(BindError::from)
        })?;
        Ok(Self { inner: Arc::new(t) })
    }

    /// Set labels.
    fn sets(&self) -> Vec<String> {
        self.inner.sets().to_vec()
    }

    /// The friction pair (μ, μ_w) of each set (dimensionless), or None for a table made
    /// before friction coordinates were written.
    fn friction(&self) -> Option<Vec<(f64, f64)>> {
        self.inner.friction()
    }

    /// The set at friction (`mu`, `mu_w`); ValueError listing the pairs the table has.
    fn friction_set(&self, mu: f64, mu_w: f64) -> PyResult<usize> {
        Ok(self.inner.friction_set(mu, mu_w).map_err(lookup_err)?)
    }

    /// Thickness axis (m).
    fn thickness<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, self.inner.thickness())
    }

    /// Volume axis (m³/m).
    fn volume<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, self.inner.volume())
    }

    /// Field names, sorted.
    fn variables(&self) -> Vec<String> {
        self.inner.variables().map(str::to_string).collect()
    }

    /// A global attribute, or None.
    fn attribute(&self, name: &str) -> Option<String> {
        self.inner.attribute(name).map(str::to_string)
    }

    /// (axis names, units, long_name, values with the field's shape) of a field.
    #[allow(clippy::type_complexity)]
    fn field<'py>(
        &self,
        py: Python<'py>,
        name: &str,
    ) -> PyResult<(
        Vec<&'static str>,
        String,
        String,
        Bound<'py, PyArrayDyn<f64>>,
    )> {
        let f = self.inner.field(name).ok_or_else(|| {
            value_err(format!(
                "the table has no field `{name}` (it has: {})",
                self.inner.variables().collect::<Vec<_>>().join(", ")
            ))
        })?;
        // The field's array is already laid out on its axes (set, thickness, volume).
        let data = f.data.clone();
        Ok((
            f.axes.names(),
            f.units.clone(),
            f.long_name.clone(),
            PyArrayDyn::from_owned_array(py, data),
        ))
    }

    /// Field `name` of set `set` interpolated at every (thickness, volume) pair of two
    /// equally long 1-D arrays; returns (values, clamped).
    fn value<'py>(
        &self,
        py: Python<'py>,
        name: &str,
        set: usize,
        thickness: numpy::PyReadonlyArray1<'py, f64>,
        volume: numpy::PyReadonlyArray1<'py, f64>,
    ) -> PyResult<Pair<'py, bool>> {
        check_aligned("thickness", &thickness)?;
        check_aligned("volume", &volume)?;
        let h = thickness.as_array();
        let v = volume.as_array();
        if h.len() != v.len() {
            return Err(value_err("thickness and volume differ in length").into());
        }
        let t = &self.inner;
        lookup_each(py, h.len(), |i| {
            t.value(name, set, h[i], v[i]).map(|l| (l.value, l.clamped))
        })
    }

    /// C_f of set `set` at every thickness (m) of a 1-D array; returns (values, clamped).
    fn cf<'py>(
        &self,
        py: Python<'py>,
        set: usize,
        thickness: numpy::PyReadonlyArray1<'py, f64>,
    ) -> PyResult<Pair<'py, bool>> {
        check_aligned("thickness", &thickness)?;
        let h = thickness.as_array();
        let t = &self.inner;
        lookup_each(py, h.len(), |i| {
            t.cf(set, h[i]).map(|l| (l.value, l.clamped))
        })
    }

    /// The nodes (thickness in m, C_f) of set `set`'s C_f table for the strength routine.
    fn cf_nodes<'py>(&self, py: Python<'py>, set: usize) -> PyResult<Pair<'py, f64>> {
        let c = self.inner.cf_table(set).map_err(lookup_err)?;
        Ok((
            PyArray1::from_slice(py, c.thickness()),
            PyArray1::from_slice(py, c.values()),
        ))
    }
}
