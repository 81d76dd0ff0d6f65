//! Closing and opening of `ridge-step` per column: the deformation (CICE: convergence and
//! shear terms from the options or the file) or the host's rates (SIS2: variables of the
//! file in 1/s).

use ndarray::Array1;
use pressridge::io::itd_netcdf::{CellUnits, FileClosing, ItdGrid, read_cell_field};

use super::Args;
use crate::BoxError;

/// The host's closing and opening rates (1/s) per column, from the variables named by
/// --closing-var and --opening-var (SIS2).
pub(super) fn host_rates(args: &Args, grid: &ItdGrid) -> Result<FileClosing, BoxError> {
    let read = |flag: &str, given: &Option<String>, default: &str, what: &str| {
        let name = given.clone().unwrap_or_else(|| default.to_string());
        match read_cell_field(&args.input, grid, &name, CellUnits::PerSecond)? {
            Some(f) => Ok::<_, BoxError>((name, f)),
            None => Err(format!(
                "--rates host: {} has no variable `{name}` (the host's {what} rate, s-1); \
                 name it with {flag}",
                args.input.display()
            )
            .into()),
        }
    };
    let closing = read("--closing-var", &args.closing_var, "closing", "net closing")?;
    let opening = read("--opening-var", &args.opening_var, "opening", "opening")?;
    Ok(FileClosing::Rates { closing, opening })
}

/// Convergence and shear terms (1/s) per column from the options or the file (CICE).
pub(super) fn deformation(args: &Args, grid: &ItdGrid) -> Result<FileClosing, BoxError> {
    let ncol = grid.ncol();
    let conv: Array1<f64> = match (args.convergence, &grid.divu) {
        (Some(c), _) => Array1::from_elem(ncol, c),
        (None, Some(d)) => {
            // A NaN or infinite divergence in a column with data is an error, not "no
            // convergence" (f64::max would turn NaN into 0).
            for (c, x) in d.iter().enumerate() {
                let masked = grid.valid.as_ref().is_some_and(|v| !v[c]);
                if !masked && !x.is_finite() {
                    return Err(format!(
                        "{}: variable `divu`: column {c} at ({}) is {x}: the divergence must be finite (1/s)",
                        args.input.display(),
                        grid.spatial_index(c)
                    )
                    .into());
                }
            }
            d.mapv(|x| f64::max(-x, 0.0))
        }
        (None, None) => {
            return Err("no convergence: pass --convergence or put `divu` in the input".into());
        }
    };
    let shear: Array1<f64> = match (args.shear, &grid.shear) {
        (Some(s), _) => Array1::from_elem(ncol, s),
        (None, Some(s)) => {
            for (c, x) in s.iter().enumerate() {
                let masked = grid.valid.as_ref().is_some_and(|v| !v[c]);
                if !(masked || x.is_finite() && *x >= 0.0) {
                    return Err(format!(
                        "{}: variable `shear`: column {c} at ({}) is {x}: the shear term must be finite and non-negative (1/s)",
                        args.input.display(),
                        grid.spatial_index(c)
                    )
                    .into());
                }
            }
            s.clone()
        }
        (None, None) => {
            eprintln!("pressridge: note: no --shear and no `shear` in the input; using 0");
            Array1::zeros(ncol)
        }
    };
    Ok(FileClosing::Deformation {
        convergence: conv,
        shear,
    })
}
