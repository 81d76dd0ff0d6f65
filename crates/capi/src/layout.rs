//! Array layouts of the C ABI: a [`PressridgeGrid`] describes `ncol` columns of `ncat`
//! categories in caller-owned memory with explicit strides and lengths; this module checks it
//! and turns raw pointers into `ndarray` views without copying.

use ndarray::{ArrayView1, ArrayView2, ArrayViewMut1, ArrayViewMut2, ShapeBuilder};

use super::{
    FfiError, FfiResult, PRESSRIDGE_ERR_BAD_SIZE, PRESSRIDGE_ERR_NULL_POINTER, guard, put,
};

/// Layout of the arrays of one call: `ncol` columns of `ncat` thickness categories.
///
/// Per-category arrays (`aicen`, `vicen`) hold element (category n, column c) at offset
/// `n·cat_stride + c·col_stride` (in elements, not bytes) and are `len` elements long.
/// Per-column arrays (`aice0`, `strength`, `valid`, `convergence`, `shear`, the rates) hold
/// column c at offset `c·col_stride_1d` and are `len_1d` elements long.
///
/// - Fortran `aicen(ncat, ncol)`: `cat_stride = 1`, `col_stride = ncat`
///   ([`pressridge_grid_fortran`]);
/// - C `aicen[ncat][ncol]`: `cat_stride = ncol`, `col_stride = 1` ([`pressridge_grid_c`]);
/// - CICE `aicen(nx_block, ny_block, ncat)` of one block, columns (i, j) flattened:
///   `ncol = nx_block·ny_block`, `cat_stride = nx_block·ny_block`, `col_stride = 1`.
///
/// All values must be positive, the strides must not make two elements share memory
/// (`col_stride ≥ ncat·cat_stride` or `cat_stride ≥ ncol·col_stride`), and the last element
/// must lie inside the given length.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PressridgeGrid {
    /// Number of thickness categories (≥ 1).
    pub ncat: i64,
    /// Number of columns (grid cells, ≥ 1).
    pub ncol: i64,
    /// Elements between consecutive categories of one column in `aicen`, `vicen` (≥ 1).
    pub cat_stride: i64,
    /// Elements between consecutive columns in `aicen`, `vicen` (≥ 1).
    pub col_stride: i64,
    /// Length in elements of each of `aicen`, `vicen`.
    pub len: i64,
    /// Elements between consecutive columns of the per-column arrays (≥ 1).
    pub col_stride_1d: i64,
    /// Length in elements of each per-column array.
    pub len_1d: i64,
}

/// A checked [`PressridgeGrid`] in `usize`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Layout {
    pub ncat: usize,
    pub ncol: usize,
    cat_stride: usize,
    col_stride: usize,
    stride_1d: usize,
    /// Number of elements spanned by a 2-D array (last offset + 1).
    span_2d: usize,
    /// Number of elements spanned by a per-column array.
    span_1d: usize,
}

fn bad_size(msg: impl Into<String>) -> FfiError {
    FfiError::new(PRESSRIDGE_ERR_BAD_SIZE, msg)
}

/// Checks that `p` is not null and is aligned for `T`.
pub(crate) fn check_ptr<T>(p: *const T, what: &str) -> FfiResult<()> {
    if p.is_null() {
        return Err(FfiError::new(
            PRESSRIDGE_ERR_NULL_POINTER,
            format!("{what} is a null pointer"),
        ));
    }
    check_aligned(p, what)
}

/// Checks that `p` is aligned for `T` (null passes).
pub(crate) fn check_aligned<T>(p: *const T, what: &str) -> FfiResult<()> {
    if (p as usize) % std::mem::align_of::<T>() != 0 {
        return Err(FfiError::new(
            PRESSRIDGE_ERR_NULL_POINTER,
            format!(
                "{what} ({p:?}) is not aligned to {} bytes",
                std::mem::align_of::<T>()
            ),
        ));
    }
    Ok(())
}

impl Layout {
    /// Checks a grid description.
    pub(crate) fn new(g: &PressridgeGrid) -> FfiResult<Self> {
        for (name, v) in [
            ("ncat", g.ncat),
            ("ncol", g.ncol),
            ("cat_stride", g.cat_stride),
            ("col_stride", g.col_stride),
            ("len", g.len),
            ("col_stride_1d", g.col_stride_1d),
            ("len_1d", g.len_1d),
        ] {
            if v <= 0 {
                return Err(bad_size(format!("grid.{name} = {v} must be positive")));
            }
        }
        let u = |v: i64| v as u128;
        let (ncat, ncol) = (u(g.ncat), u(g.ncol));
        let (cs, ls, s1) = (u(g.cat_stride), u(g.col_stride), u(g.col_stride_1d));
        if !(ncat == 1 || ncol == 1 || ls >= ncat * cs || cs >= ncol * ls) {
            return Err(bad_size(format!(
                "grid strides overlap: cat_stride = {cs}, col_stride = {ls} for ncat = {ncat}, \
                 ncol = {ncol} (need col_stride >= ncat*cat_stride or cat_stride >= \
                 ncol*col_stride)"
            )));
        }
        let span_2d = (ncat - 1) * cs + (ncol - 1) * ls + 1;
        if span_2d > u(g.len) {
            return Err(bad_size(format!(
                "grid.len = {} is too short: ncat = {ncat}, ncol = {ncol} with cat_stride = \
                 {cs}, col_stride = {ls} reach element {}",
                g.len,
                span_2d - 1
            )));
        }
        let span_1d = (ncol - 1) * s1 + 1;
        if span_1d > u(g.len_1d) {
            return Err(bad_size(format!(
                "grid.len_1d = {} is too short: ncol = {ncol} with col_stride_1d = {s1} reach \
                 element {}",
                g.len_1d,
                span_1d - 1
            )));
        }
        let max = isize::MAX as u128 / 8;
        if span_2d > max || span_1d > max {
            return Err(bad_size("grid spans more memory than can be addressed"));
        }
        Ok(Self {
            ncat: ncat as usize,
            ncol: ncol as usize,
            cat_stride: cs as usize,
            col_stride: ls as usize,
            stride_1d: s1 as usize,
            span_2d: span_2d as usize,
            span_1d: span_1d as usize,
        })
    }

    /// Reads and checks the grid behind a caller's pointer.
    ///
    /// # Safety
    /// `g` must be null or point to a valid `PressridgeGrid`.
    pub(crate) unsafe fn from_ptr(g: *const PressridgeGrid) -> FfiResult<Self> {
        check_ptr(g, "grid")?;
        // SAFETY: checked non-null and aligned; validity is the caller's promise.
        Self::new(unsafe { &*g })
    }

    /// The byte range a 2-D array occupies.
    pub(crate) fn region_2d<T>(&self, p: *const T, name: &'static str) -> Region {
        Region::new(p, self.span_2d, name)
    }

    /// The byte range a per-column array occupies.
    pub(crate) fn region_1d<T>(&self, p: *const T, name: &'static str) -> Region {
        Region::new(p, self.span_1d, name)
    }

    /// A read-only `(ncat, ncol)` view.
    ///
    /// # Safety
    /// `p` must be valid for reads of the whole layout for `'a` (checked: null, alignment).
    pub(crate) unsafe fn view2<'a>(
        &self,
        p: *const f64,
        name: &str,
    ) -> FfiResult<ArrayView2<'a, f64>> {
        check_ptr(p, name)?;
        let shape = (self.ncat, self.ncol).strides((self.cat_stride, self.col_stride));
        // SAFETY: the layout was checked to stay inside the caller's `len` elements.
        Ok(unsafe { ArrayView2::from_shape_ptr(shape, p) })
    }

    /// A mutable `(ncat, ncol)` view.
    ///
    /// # Safety
    /// As [`Layout::view2`], for writes, and no other live reference to the memory.
    pub(crate) unsafe fn view2_mut<'a>(
        &self,
        p: *mut f64,
        name: &str,
    ) -> FfiResult<ArrayViewMut2<'a, f64>> {
        check_ptr(p, name)?;
        let shape = (self.ncat, self.ncol).strides((self.cat_stride, self.col_stride));
        // SAFETY: as `view2`; the strides were checked not to overlap.
        Ok(unsafe { ArrayViewMut2::from_shape_ptr(shape, p) })
    }

    /// A read-only per-column view of `T`.
    ///
    /// # Safety
    /// As [`Layout::view2`].
    pub(crate) unsafe fn view1<'a, T>(
        &self,
        p: *const T,
        name: &str,
    ) -> FfiResult<ArrayView1<'a, T>> {
        check_ptr(p, name)?;
        let shape = self.ncol.strides(self.stride_1d);
        // SAFETY: the layout was checked to stay inside the caller's `len_1d` elements.
        Ok(unsafe { ArrayView1::from_shape_ptr(shape, p) })
    }

    /// A mutable per-column view.
    ///
    /// # Safety
    /// As [`Layout::view2_mut`].
    pub(crate) unsafe fn view1_mut<'a>(
        &self,
        p: *mut f64,
        name: &str,
    ) -> FfiResult<ArrayViewMut1<'a, f64>> {
        check_ptr(p, name)?;
        let shape = self.ncol.strides(self.stride_1d);
        // SAFETY: as `view1`.
        Ok(unsafe { ArrayViewMut1::from_shape_ptr(shape, p) })
    }
}

/// The bytes a caller's buffer spans, for the aliasing checks.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Region {
    start: usize,
    end: usize,
    name: &'static str,
}

impl Region {
    pub(crate) fn new<T>(p: *const T, elements: usize, name: &'static str) -> Self {
        let start = p as usize;
        Self {
            start,
            end: start.saturating_add(elements.saturating_mul(std::mem::size_of::<T>())),
            name,
        }
    }
}

/// Fails when any buffer in `written` shares memory with another buffer of `written` or of
/// `read` (null pointers are skipped).
pub(crate) fn check_disjoint(written: &[Region], read: &[Region]) -> FfiResult<()> {
    for (i, w) in written.iter().enumerate() {
        if w.start == 0 {
            continue;
        }
        for o in written[i + 1..].iter().chain(read) {
            if o.start != 0 && w.start < o.end && o.start < w.end {
                return Err(bad_size(format!(
                    "buffers `{}` and `{}` overlap; outputs must not share memory with other \
                     arguments",
                    w.name, o.name
                )));
            }
        }
    }
    Ok(())
}

/// Fills `*grid` for Fortran arrays `aicen(ncat, ncol)` and per-column arrays `x(ncol)`,
/// all contiguous: `cat_stride = 1`, `col_stride = ncat`, `len = ncat·ncol`,
/// `col_stride_1d = 1`, `len_1d = ncol`.
///
/// # Safety
/// `grid` must be valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_grid_fortran(
    ncat: i64,
    ncol: i64,
    grid: *mut PressridgeGrid,
) -> i32 {
    guard(|| {
        let g = PressridgeGrid {
            ncat,
            ncol,
            cat_stride: 1,
            col_stride: ncat,
            len: ncat.saturating_mul(ncol),
            col_stride_1d: 1,
            len_1d: ncol,
        };
        Layout::new(&g)?;
        // SAFETY: caller promise, checked by `put`.
        unsafe { put(grid, g, "grid") }
    })
}

/// Fills `*grid` for C arrays `aicen[ncat][ncol]` (row-major, categories outer) and
/// per-column arrays `x[ncol]`, all contiguous: `cat_stride = ncol`, `col_stride = 1`.
///
/// # Safety
/// `grid` must be valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_grid_c(ncat: i64, ncol: i64, grid: *mut PressridgeGrid) -> i32 {
    guard(|| {
        let g = PressridgeGrid {
            ncat,
            ncol,
            cat_stride: ncol,
            col_stride: 1,
            len: ncat.saturating_mul(ncol),
            col_stride_1d: 1,
            len_1d: ncol,
        };
        Layout::new(&g)?;
        // SAFETY: caller promise, checked by `put`.
        unsafe { put(grid, g, "grid") }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(ncat: i64, ncol: i64, cs: i64, ls: i64, len: i64) -> PressridgeGrid {
        PressridgeGrid {
            ncat,
            ncol,
            cat_stride: cs,
            col_stride: ls,
            len,
            col_stride_1d: 1,
            len_1d: ncol,
        }
    }

    #[test]
    fn layouts() {
        assert!(Layout::new(&grid(5, 10, 1, 5, 50)).is_ok());
        assert!(Layout::new(&grid(5, 10, 10, 1, 50)).is_ok());
        assert!(Layout::new(&grid(5, 10, 1, 5, 49)).is_err());
        assert!(
            Layout::new(&grid(5, 10, 1, 1, 50)).is_err(),
            "overlapping strides"
        );
        assert!(Layout::new(&grid(0, 10, 1, 5, 50)).is_err());
        assert!(Layout::new(&grid(5, -1, 1, 5, 50)).is_err());
        assert!(Layout::new(&grid(5, 10, 1, i64::MAX, i64::MAX)).is_err());
        // One column or one category: any positive strides.
        assert!(Layout::new(&grid(1, 10, 7, 1, 10)).is_ok());
    }

    #[test]
    fn disjoint() {
        let a = [0.0f64; 10];
        let r1 = Region::new(a.as_ptr(), 5, "a");
        let r2 = Region::new(a[5..].as_ptr(), 5, "b");
        let r3 = Region::new(a[4..].as_ptr(), 2, "c");
        assert!(check_disjoint(&[r1, r2], &[]).is_ok());
        assert!(check_disjoint(&[r1], &[r3]).is_err());
        assert!(check_disjoint(&[r2], &[r3]).is_err());
    }
}
