//! The NetCDF thickness-distribution reader (`read_itd_with`) and what reads beside it —
//! snow and tracers under restart names or packed (`read_snow_tracers`,
//! `read_packed_tracers`), a per-cell field (`read_cell_field`), the strength's writer — on
//! well-formed files of arbitrary structure and values (`nc_input.rs`): every outcome is a
//! value or an error, never a panic; what is read has the shapes it claims.
#![no_main]

#[path = "bytes.rs"]
mod bytes;
#[path = "nc_input.rs"]
mod nc_input;

use libfuzzer_sys::fuzz_target;
use nc_input::{Bytes, scratch, write};
use pressridge::io::itd_netcdf::{
    CellUnits, Output, ReadOptions, read_cell_field, read_itd_with, read_packed_tracers,
    read_snow_tracers, write_output,
};
use pressridge::itd::details::CiceLayoutSpec;

const DIMS: &[&str] = &["nc", "ncat", "ct", "time", "nj", "ni", "ntrcr", "nc_bounds"];
const VARS: &[&str] = &[
    "aicen", "vicen", "aice0", "hin_max", "NCAT", "divu", "shear", "tmask", "vsnon", "Tsfcn",
    "qice001", "qsno001", "sice001", "iage", "trcrn", "Tf", "TLON", "ni", "time",
];
const UNITS: &[&str] = &[
    "s-1",
    "%/day",
    "1/s",
    "degC",
    "K",
    "m",
    "1",
    "",
    "days since 0001",
];

fuzz_target!(|input: &[u8]| {
    let mut d = Bytes(input);
    let path = scratch("itd");
    let opts = ReadOptions {
        category_dim: match d.byte() % 4 {
            0 => Some("ct".into()),
            1 => Some("time".into()),
            _ => None,
        },
        without_deformation: d.byte() & 1 == 1,
    };
    let spec: CiceLayoutSpec = d
        .pick(&[
            "nilyr=1,nslyr=1",
            "icedrv",
            "nilyr=1,nslyr=1,tr_iage,tr_lvl",
        ])
        .parse()
        .expect("a valid layout");
    if !write(&path, &mut d, DIMS, VARS, UNITS) {
        return;
    }
    let Ok(grid) = read_itd_with(&path, &opts) else {
        return;
    };
    let (ncat, ncol) = (grid.ncat(), grid.ncol());
    assert_eq!(grid.vicen.dim(), (ncat, ncol));
    assert_eq!(
        grid.spatial_dims.iter().map(|x| x.1).product::<usize>(),
        ncol
    );
    if let Some(h) = &grid.hin_max {
        assert_eq!(h.len(), ncat + 1);
    }
    for x in [&grid.aice0, &grid.divu, &grid.shear].into_iter().flatten() {
        assert_eq!(x.len(), ncol);
    }
    if let Ok(Some(st)) = read_snow_tracers(&path, &grid) {
        assert_eq!(st.trcrn.dim(), (ncat, st.layout.ntrcr(), ncol));
    }
    if let Ok(st) = read_packed_tracers(&path, &grid, "trcrn", &spec) {
        assert_eq!(st.trcrn.dim(), (ncat, st.layout.ntrcr(), ncol));
        let p = st.packed.as_ref().expect("packed");
        assert_eq!(
            p.to_file_order(&grid, &st.trcrn).len(),
            ncat * ncol * st.layout.ntrcr()
        );
    }
    if let Ok(Some(f)) = read_cell_field(&path, &grid, "Tf", CellUnits::DegC) {
        assert_eq!(f.values.len(), ncol);
    }
    // The writer keeps the coordinates with their types.
    let out = scratch("itd-out");
    let _ = write_output(
        &out,
        &Output {
            grid: &grid,
            write_itd: true,
            hin_max: grid.hin_max.as_deref(),
            fields: &[],
            category_fields: &[],
            dim_fields: &[],
            global: &[],
            fill: grid.valid.as_ref().map(|_| 1e30),
            history: Some("fuzz"),
        },
    );
});
