//! numpy arrays as the library's column views.
//!
//! Owns the conversion of `(ncat, spatial...)` arrays to `(ncat, ncol)` views and of spatial
//! arrays to flat columns: the flattening order (C or Fortran, chosen so that the input is
//! not copied), fresh outputs laid out in the input's order, the shape and alignment checks
//! with their messages, and the location of a failing column by its spatial index.

use ndarray::{
    ArrayBase, ArrayView, ArrayViewD, ArrayViewMut, ArrayViewMut1, ArrayViewMut2, ArrayViewMutD,
    CowArray, Dimension, Ix1, Ix2, IxDyn, RawData,
};
use numpy::{PyArray1, PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;

use pressridge::itd::ItdError;

use crate::errors::{BindError, value_err};

/// Two 1-D arrays: node pairs, or lookup values with their clamp flags.
pub(crate) type Pair<'py, T> = (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<T>>);

/// How the spatial axes of an array are flattened into columns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Order {
    /// Last spatial axis fastest (C order).
    C,
    /// First spatial axis fastest (Fortran order): the spatial axes reversed, then C order.
    F,
}

/// Merges the axes `first..` of `a` into one, in row-major order (the last axis fastest),
/// without copying; `None` when the strides do not allow it. An array with no axis at
/// `first` gets one of length 1.
fn merge_tail<S: RawData>(a: ArrayBase<S, IxDyn>, first: usize) -> Option<ArrayBase<S, IxDyn>> {
    let n = a.ndim();
    if n <= first {
        return Some(a.insert_axis(ndarray::Axis(first)));
    }
    let mut a = a;
    for k in first..n - 1 {
        if !a.merge_axes(ndarray::Axis(k), ndarray::Axis(k + 1)) {
            return None;
        }
    }
    for _ in first..n - 1 {
        a = a.index_axis_move(ndarray::Axis(first), 0);
    }
    Some(a)
}

/// The axes of `a` (ndim axes, the first `lead` kept in place) in the order that flattens the
/// others in `order`.
fn flatten_perm(ndim: usize, lead: usize, order: Order) -> IxDyn {
    let mut p: Vec<usize> = (0..ndim).collect();
    if order == Order::F && ndim > lead {
        p[lead..].reverse();
    }
    IxDyn(&p)
}

/// `a` with the axes after the first `lead` flattened in `order`: a view when the layout
/// allows, else a copy.
pub(crate) fn flatten<'a, T: Clone, D: Dimension>(
    a: ArrayView<'a, T, IxDyn>,
    lead: usize,
    order: Order,
) -> CowArray<'a, T, D> {
    let perm = flatten_perm(a.ndim(), lead, order);
    let p = a.permuted_axes(perm);
    if let Some(m) = merge_tail(p.clone(), lead) {
        return CowArray::from(m.into_dimensionality::<D>().expect("merged rank"));
    }
    let mut shape: Vec<usize> = p.shape()[..lead].to_vec();
    shape.push(p.shape()[lead..].iter().product());
    let owned = p
        .to_shape((IxDyn(&shape), ndarray::Order::RowMajor))
        .expect("element count is unchanged")
        .into_owned();
    CowArray::from(owned.into_dimensionality::<D>().expect("merged rank"))
}

/// `a` (ncat, spatial...) as (ncat, ncol), the spatial axes flattened in `order`.
pub(crate) fn columns<'a>(a: ArrayViewD<'a, f64>, order: Order) -> CowArray<'a, f64, Ix2> {
    flatten(a, 1, order)
}

/// A spatial array (no category axis) flattened in `order`.
pub(crate) fn flat<'a>(a: ArrayViewD<'a, f64>, order: Order) -> CowArray<'a, f64, Ix1> {
    flatten(a, 0, order)
}

pub(crate) fn flat_bool<'a>(a: ArrayViewD<'a, bool>, order: Order) -> CowArray<'a, bool, Ix1> {
    flatten(a, 0, order)
}

/// The flattening order that makes `aicen` a view: C if its spatial axes merge in C order,
/// else F if they merge in Fortran order, else C (and a copy).
pub(crate) fn choose_order(a: &ArrayViewD<'_, f64>) -> Order {
    if a.ndim() <= 2 || columns(a.view(), Order::C).is_view() {
        Order::C
    } else if columns(a.view(), Order::F).is_view() {
        Order::F
    } else {
        Order::C
    }
}

/// A new numpy array of `shape` laid out so that flattening its spatial axes in `order` is a
/// view (C order for [`Order::C`], Fortran order for [`Order::F`]).
pub(crate) fn new_array<'py>(
    py: Python<'py>,
    shape: &[usize],
    order: Order,
) -> Bound<'py, PyArrayDyn<f64>> {
    PyArrayDyn::<f64>::zeros(py, IxDyn(shape), order == Order::F)
}

/// A freshly made `out` with the axes after the first `lead` flattened in `order`.
pub(crate) fn flatten_mut<'a, D: Dimension>(
    a: ArrayViewMutD<'a, f64>,
    lead: usize,
    order: Order,
) -> ArrayViewMut<'a, f64, D> {
    let perm = flatten_perm(a.ndim(), lead, order);
    let p = a.permuted_axes(perm);
    merge_tail(p, lead)
        .expect("a freshly made array in the chosen order flattens without a copy")
        .into_dimensionality::<D>()
        .expect("merged rank")
}

pub(crate) fn columns_mut<'a>(a: ArrayViewMutD<'a, f64>, order: Order) -> ArrayViewMut2<'a, f64> {
    flatten_mut(a, 1, order)
}

pub(crate) fn flat_mut<'a>(a: ArrayViewMutD<'a, f64>, order: Order) -> ArrayViewMut1<'a, f64> {
    flatten_mut(a, 0, order)
}

/// The spatial index of flat column `c` (flattened in `order`), as `(i, j, ...)`.
fn spatial_index(spatial: &[usize], order: Order, c: usize) -> String {
    let mut dims: Vec<usize> = spatial.to_vec();
    if order == Order::F {
        dims.reverse();
    }
    let mut idx = vec![0; dims.len()];
    let mut rem = c;
    for k in (0..dims.len()).rev() {
        idx[k] = rem % dims[k];
        rem /= dims[k];
    }
    if order == Order::F {
        idx.reverse();
    }
    let parts: Vec<String> = idx.iter().map(|i| i.to_string()).collect();
    if parts.len() == 1 {
        format!("({},)", parts[0])
    } else {
        format!("({})", parts.join(", "))
    }
}

/// A physics error with the column located by its index in the caller's spatial axes.
pub(crate) fn itd_err(e: ItdError, spatial: &[usize], order: Order) -> BindError {
    match e {
        ItdError::Column { column, source } => {
            if spatial.is_empty() {
                value_err(source)
            } else {
                value_err(format!(
                    "at spatial index {}: {source}",
                    spatial_index(spatial, order, column)
                ))
            }
        }
        other => value_err(other),
    }
}

/// Refuses an array whose data are not aligned for its element type (numpy allows such
/// views, e.g. arrays unpickled from a byte buffer by dask.distributed): reading it as an
/// ndarray view would be undefined behaviour. The Python wrappers pass aligned copies.
pub(crate) fn check_aligned<T: numpy::Element, D: ndarray::Dimension>(
    var: &str,
    x: &numpy::PyReadonlyArray<'_, T, D>,
) -> PyResult<()> {
    if (x.data() as usize) % std::mem::align_of::<T>() != 0 {
        return Err(value_err(format!(
            "{var}: the array's data are not aligned for its dtype; pass an aligned copy \
             (numpy.require(x, requirements=\"A\"))"
        ))
        .into());
    }
    Ok(())
}

/// [`check_aligned`], then [`check_shape`].
pub(crate) fn check_array<T: numpy::Element>(
    var: &str,
    x: &PyReadonlyArrayDyn<'_, T>,
    expected: &[usize],
    what: &str,
) -> PyResult<()> {
    check_aligned(var, x)?;
    check_shape(var, x.shape(), expected, what)
}

fn check_shape(var: &str, found: &[usize], expected: &[usize], what: &str) -> PyResult<()> {
    if found != expected {
        return Err(value_err(format!(
            "{var} has shape {}, expected {what} {}",
            shape_str(found),
            shape_str(expected)
        ))
        .into());
    }
    Ok(())
}

fn shape_str(s: &[usize]) -> String {
    match s.len() {
        1 => format!("({},)", s[0]),
        _ => format!(
            "({})",
            s.iter()
                .map(|x| x.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// Checks aicen/vicen and returns the spatial shape.
pub(crate) fn category_shapes(
    aicen: &PyReadonlyArrayDyn<'_, f64>,
    vicen: &PyReadonlyArrayDyn<'_, f64>,
) -> PyResult<Vec<usize>> {
    check_aligned("aicen", aicen)?;
    let shape = aicen.shape().to_vec();
    if shape.is_empty() || shape[0] == 0 {
        return Err(value_err(format!(
            "aicen has shape {}; it needs the category axis first, of length >= 1, then any spatial axes",
            shape_str(&shape)
        ))
        .into());
    }
    check_array("vicen", vicen, &shape, "the shape of aicen")?;
    Ok(shape[1..].to_vec())
}
