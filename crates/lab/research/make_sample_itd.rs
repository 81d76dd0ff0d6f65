//! Writes the sample gridded thickness distribution `data/sample_itd.nc`.
//!
//! `cargo run --example make_sample_itd -- data/sample_itd.nc`
//!
//! Deterministic and analytic (no random numbers): a 60 × 80 grid (nj × ni) with a pack of
//! thick ice (mean up to ~4 m) against one side, thinner first-year ice elsewhere, a band of
//! leads, a marginal ice zone and open ocean. In each cell the thickness distribution is a
//! gamma distribution g(h) ∝ h·exp(−2h/h̄) of mean h̄, integrated over the five CICE default
//! categories (`kcatbound = 1`: 0, 0.6, 1.4, 2.4, 3.6, 5 m, the last open-ended). It has
//! open-water cells (aice0 = 1), full-cover cells (aice0 = 0) and `divu`/`shear` fields
//! (1/s) for the ridging step.

use std::path::PathBuf;

use ndarray::{Array1, Array2};
use pressridge::io::itd_netcdf::{FieldMeta, ItdGrid, Output, write_output};
use pressridge::itd::{CategoryBounds, category_bounds};

const NJ: usize = 60;
const NI: usize = 80;
const NCAT: usize = 5;

/// Fractions of area and of mean thickness (m) per category for g(h) ∝ h e^{−2h/h̄}.
fn gamma_split(hbar: f64, bounds: &[f64]) -> ([f64; NCAT], [f64; NCAT]) {
    let dh = 0.002;
    let hmax = 60.0;
    let mut area = [0.0; NCAT];
    let mut vol = [0.0; NCAT];
    let mut h = 0.5 * dh;
    while h < hmax {
        let g = h * (-2.0 * h / hbar).exp();
        let mut n = 0;
        while n + 1 < NCAT && h >= bounds[n + 1] {
            n += 1;
        }
        area[n] += g * dh;
        vol[n] += g * h * dh;
        h += dh;
    }
    let total: f64 = area.iter().sum();
    for n in 0..NCAT {
        area[n] /= total;
        vol[n] /= total;
    }
    (area, vol)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out: PathBuf = std::env::args_os()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("data/sample_itd.nc"));
    let bounds = category_bounds(&CategoryBounds::RoundNumbers, NCAT)?;
    let ncol = NJ * NI;
    let mut aicen = Array2::zeros((NCAT, ncol));
    let mut vicen = Array2::zeros((NCAT, ncol));
    let mut aice0 = Array1::zeros(ncol);
    let mut divu = Array1::zeros(ncol);
    let mut shear = Array1::zeros(ncol);
    let pi = std::f64::consts::PI;
    for j in 0..NJ {
        for i in 0..NI {
            let c = j * NI + i;
            let x = (i as f64 + 0.5) / NI as f64;
            let y = (j as f64 + 0.5) / NJ as f64;
            // Distance from the pack's centre, stretched to an ellipse.
            let r = (((x - 0.45) / 1.1).powi(2) + (y - 0.55).powi(2)).sqrt();
            // Concentration: full pack, a leads band, a marginal ice zone, open ocean.
            let aice: f64 = if r < 0.22 {
                1.0
            } else if r < 0.33 {
                let leads = 0.5 + 0.5 * (14.0 * pi * x).sin() * (9.0 * pi * y).cos();
                1.0 - 0.08 * leads
            } else if r < 0.46 {
                0.92 * (0.46 - r) / 0.13
            } else {
                0.0
            };
            // Mean thickness: old thick ice against the "coast" at small x, thinner outward.
            let thick = 3.4 * (-((x - 0.12).powi(2) / 0.02 + (y - 0.62).powi(2) / 0.06)).exp();
            let hbar = 0.35 + thick + 1.3 * f64::max(0.0, 1.0 - r / 0.4);
            if aice > 0.0 {
                let (af, vf) = gamma_split(hbar, &bounds);
                for n in 0..NCAT {
                    aicen[[n, c]] = aice * af[n];
                    vicen[[n, c]] = aice * vf[n];
                }
            }
            aice0[c] = if aice >= 1.0 {
                0.0
            } else {
                f64::max(0.0, 1.0 - aicen.column(c).sum())
            };
            // Deformation: convergence against the coast, divergence outward; shear >= 0.
            divu[c] = -2.0e-6 * (pi * (x - 0.1)).cos() * (0.5 + 0.5 * (2.0 * pi * y).sin());
            shear[c] = 1.0e-6 * (1.2 + (3.0 * pi * x + 2.0 * pi * y).sin());
        }
    }
    let grid = ItdGrid {
        ncat_dim: "ncat".into(),
        spatial_dims: vec![("nj".into(), NJ), ("ni".into(), NI)],
        aicen,
        vicen,
        aice0: Some(aice0),
        hin_max: Some(bounds.clone()),
        divu: None,
        shear: None,
        valid: None,
        fill_value: None,
        ..Default::default()
    };
    let fields = [
        (
            FieldMeta {
                name: "divu",
                units: "s-1",
                long_name: "divergence of the ice velocity",
                standard_name: Some("divergence_of_sea_ice_velocity"),
            },
            divu.as_slice().unwrap(),
        ),
        (
            FieldMeta {
                name: "shear",
                units: "s-1",
                long_name: "shear term of the ridging closing rate, (Delta - |divu|)/2",
                standard_name: None,
            },
            shear.as_slice().unwrap(),
        ),
    ];
    let global = [
        (
            "title".to_string(),
            "pressridge sample ice thickness distribution".to_string(),
        ),
        (
            "history".to_string(),
            "cargo run --example make_sample_itd -- data/sample_itd.nc (analytic, deterministic)"
                .to_string(),
        ),
        (
            "category_bounds".to_string(),
            "CICE kcatbound = 1".to_string(),
        ),
    ];
    write_output(
        &out,
        &Output {
            grid: &grid,
            write_itd: true,
            hin_max: Some(&bounds),
            fields: &fields,
            category_fields: &[],
            dim_fields: &[],
            global: &global,
            fill: None,
            history: None,
        },
    )?;
    println!("wrote {}", out.display());
    Ok(())
}
