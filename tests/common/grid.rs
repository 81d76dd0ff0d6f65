//! A small gridded distribution and the sample file, for the NetCDF tests of the library
//! (tests/itd_netcdf.rs) and of the command line (crates/cli/tests/itd_netcdf.rs).

use std::path::{Path, PathBuf};

use ndarray::{Array1, Array2};
use pressridge::io::itd_netcdf::{ItdGrid, Output, write_output};

/// The shipped sample distribution, `data/sample_itd.nc`.
pub fn sample() -> PathBuf {
    super::repo().join("data/sample_itd.nc")
}

/// A 2 × 3 grid, 2 categories; column (j=1, i=2) gets `bad` in aicen category 1.
pub fn small_grid(bad: Option<f64>) -> ItdGrid {
    let mut aicen = Array2::from_elem((2, 6), 0.4);
    if let Some(b) = bad {
        aicen[[1, 5]] = b;
    }
    ItdGrid {
        ncat_dim: "nc".into(),
        spatial_dims: vec![("y".into(), 2), ("x".into(), 3)],
        aicen,
        vicen: Array2::from_elem((2, 6), 0.6),
        aice0: Some(Array1::from_elem(6, 0.2)),
        hin_max: None,
        divu: None,
        shear: None,
        valid: None,
        fill_value: None,
        ..Default::default()
    }
}

/// Writes `g` with its distribution and the bounds 0, 1, 3 m, no fields.
pub fn write_grid(path: &Path, g: &ItdGrid) {
    write_output(
        path,
        &Output {
            grid: g,
            write_itd: true,
            hin_max: Some(&[0.0, 1.0, 3.0]),
            fields: &[],
            category_fields: &[],
            dim_fields: &[],
            global: &[],
            fill: None,
            history: None,
        },
    )
    .unwrap();
}
