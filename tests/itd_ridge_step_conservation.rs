//! Conservation and positivity of the complete ridging step on adversarial columns: tiny
//! categories (1e-13–1e-9), near-empty and near-full cells, area excess, huge closing rates,
//! thicknesses on and outside the category bounds, both calling conventions, with and
//! without the clean-up, the uniform, exponential and tabulated-μ_rdg redistributions. Area, ice volume, snow volume, enthalpy and salt (with the ocean
//! fluxes) are conserved to 1e-12 relative; no area, volume or snow volume is ever negative
//! or NaN, and no column fails.
//!
//! One seeded loop over 10⁶ columns (a plain generator, so the test runs in seconds in the
//! test profile's opt-level 2).

// Per-category and per-tracer tables are indexed by number, as in Icepack.
#![allow(
    clippy::needless_range_loop,
    clippy::field_reassign_with_default,
    clippy::too_many_arguments
)]

use pressridge::itd::{
    CategoryBounds, ColumnError, ColumnMut, RidgeStepOptions, StepForcing, StepWorkspace,
    category_bounds,
    details::{
        CiceTracerFlags, Closing, MuRdgTable, OceanFluxes, Participation, Redistribution, SaltFlux,
        TracerLayout,
    },
    ridge_step_column,
};

/// SplitMix64: small, seeded, reproducible.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    fn u(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.u()
    }
    /// Log-uniform in [lo, hi].
    fn log(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + (hi.ln() - lo.ln()) * self.u()).exp()
    }
    fn pick(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

struct Budget {
    area: f64,
    vice: f64,
    vsno: f64,
    heat: f64,
    salt: f64,
}

fn budget(layout: &TracerLayout, a: &[f64], v: &[f64], s: &[f64], t: &[f64], aice0: f64) -> Budget {
    let nt = layout.ntrcr();
    let (qi, nilyr) = layout.field("qice").unwrap();
    let (qs, nslyr) = layout.field("qsno").unwrap();
    let (si, _) = layout.field("sice").unwrap();
    let mut b = Budget {
        area: aice0,
        vice: 0.0,
        vsno: 0.0,
        heat: 0.0,
        salt: 0.0,
    };
    for n in 0..a.len() {
        b.area += a[n];
        b.vice += v[n];
        b.vsno += s[n];
        for k in 0..nilyr {
            b.heat += t[n * nt + qi + k] * v[n] / nilyr as f64;
            b.salt += t[n * nt + si + k] * v[n] / nilyr as f64;
        }
        for k in 0..nslyr {
            b.heat += t[n * nt + qs + k] * s[n] / nslyr as f64;
        }
    }
    b
}

fn close(what: &str, after: f64, before: f64, scale: f64, column: usize) {
    let tol = 1e-12 * scale.abs().max(f64::MIN_POSITIVE);
    assert!(
        (after - before).abs() <= tol,
        "column {column}: {what} not conserved: before {before:e}, after {after:e} \
         (difference {:e}, tolerance {tol:e})",
        after - before
    );
}

/// Draws one adversarial column into the buffers.
#[allow(clippy::too_many_arguments)]
fn draw(
    rng: &mut Rng,
    layout: &TracerLayout,
    hin: &[f64],
    a: &mut [f64],
    v: &mut [f64],
    s: &mut [f64],
    t: &mut [f64],
) -> f64 {
    let ncat = a.len();
    let nt = layout.ntrcr();
    let (qi, nilyr) = layout.field("qice").unwrap();
    let (qs, nslyr) = layout.field("qsno").unwrap();
    let (si, _) = layout.field("sice").unwrap();
    for n in 0..ncat {
        a[n] = match rng.pick(6) {
            0 => 0.0,
            1 => rng.log(1e-13, 1e-9),
            2 => rng.log(1e-9, 1e-3),
            _ => rng.range(0.0, 1.0),
        };
        let (lo, hi) = (
            hin[n],
            if n + 1 < ncat {
                hin[n + 1]
            } else {
                hin[n] + 5.0
            },
        );
        let h = match rng.pick(6) {
            0 => lo,
            1 => hi,
            2 => rng.log(1e-6, 20.0),
            _ => rng.range(lo, hi),
        };
        v[n] = a[n] * h;
        if rng.pick(20) == 0 {
            v[n] = rng.log(1e-14, 1e-10); // volume without (much) area
        }
        s[n] = if rng.pick(3) == 0 {
            0.0
        } else {
            v[n] * rng.range(0.0, 0.4)
        };
        let tr = &mut t[n * nt..(n + 1) * nt];
        tr[0] = rng.range(-30.0, 0.0);
        for k in 0..nilyr {
            tr[qi + k] = rng.range(-3.4e8, -1.0e8);
            tr[si + k] = rng.range(0.0, 12.0);
        }
        for k in 0..nslyr {
            tr[qs + k] = if rng.pick(50) == 0 {
                rng.range(-1.2e8, 1.0e6) // some unphysically warm snow
            } else {
                rng.range(-1.3e8, -1.1e8)
            };
        }
        for name in ["iage", "FY", "alvl", "vlvl", "apnd", "hpnd", "ipnd"] {
            if let Some((i, _)) = layout.field(name) {
                tr[i] = match name {
                    "iage" => rng.range(0.0, 3e7),
                    "hpnd" | "ipnd" => rng.range(0.0, 0.5),
                    _ => rng.u(),
                };
            }
        }
    }
    let sum: f64 = a.iter().sum();
    // Scale to near-empty, normal, near-full and over-full cells.
    let target = match rng.pick(6) {
        0 => rng.log(1e-13, 1e-6),
        1 => 1.0 - rng.log(1e-15, 1e-6),
        2 => rng.range(1.0, 1.4),
        3 => 1.0,
        _ => rng.range(0.0, 1.0),
    };
    if sum > 0.0 {
        let f = target / sum;
        for n in 0..ncat {
            a[n] *= f;
            v[n] *= f;
            s[n] *= f;
        }
    }
    let sum: f64 = a.iter().sum();
    match rng.pick(4) {
        0 => 0.0,
        1 => rng.log(1e-15, 1e-9),
        _ => f64::max(0.0, 1.0 - sum),
    }
}

#[test]
fn ridge_step_conserves_on_a_million_adversarial_columns() {
    let n_columns: usize = std::env::var("PRESSRIDGE_CONSERVATION_COLUMNS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1_000_000);
    let mut rng = Rng(20261123);
    let layouts = [
        TracerLayout::cice(7, 1, CiceTracerFlags::ALL).unwrap(),
        TracerLayout::cice(4, 3, CiceTracerFlags::ALL).unwrap(),
        TracerLayout::cice(1, 1, CiceTracerFlags::default()).unwrap(),
    ];
    let mut stats = [0usize; 5]; // columns, cleaned, multi-pass, zapped, no convergence
    let mut a = [0.0; 8];
    let mut v = [0.0; 8];
    let mut s = [0.0; 8];
    let mut t = vec![0.0; 8 * 23];
    let mut wss: Vec<Vec<StepWorkspace>> = layouts
        .iter()
        .map(|l| (0..=7).map(|n| StepWorkspace::new(n, l.ntrcr())).collect())
        .collect();
    for column in 0..n_columns {
        let li = rng.pick(layouts.len());
        let layout = &layouts[li];
        let nt = layout.ntrcr();
        let ncat = [1, 3, 5, 5, 7][rng.pick(5)];
        let hin = category_bounds(&CategoryBounds::RoundNumbers, ncat).unwrap();
        let (a, v, s) = (&mut a[..ncat], &mut v[..ncat], &mut s[..ncat]);
        let t = &mut t[..ncat * nt];
        let mut aice0 = draw(&mut rng, layout, &hin, a, v, s, t);
        let mut opts = RidgeStepOptions::default();
        opts.participation = if rng.pick(2) == 0 {
            Participation::Thorndike
        } else {
            Participation::Exponential
        };
        opts.redistribution = match rng.pick(3) {
            0 => Redistribution::Uniform,
            1 => Redistribution::Exponential,
            // μ_rdg per category thickness from a table (issue 34): 1–4 m^½ between 0.1 and
            // 3 m, held at the ends beyond them.
            _ => Redistribution::Table(
                MuRdgTable::new(&[0.1, 0.5, 1.5, 3.0], &[1.0, 2.0, 4.0, 1.5]).unwrap(),
            ),
        };
        opts.step.salt_flux = SaltFlux::Prognostic;
        opts.cleanup = rng.pick(4) != 0;
        opts.rebin = rng.pick(4) != 0;
        let dt = [1800.0, 3600.0, 7200.0][rng.pick(3)];
        let big = |r: &mut Rng| match r.pick(4) {
            0 => 0.0,
            1 => r.log(1e-3, 10.0) / dt, // huge: up to 10 times the cell per step
            _ => r.log(1e-9, 1e-5),
        };
        let closing = if rng.pick(2) == 0 {
            Closing::Deformation {
                convergence: big(&mut rng),
                shear: big(&mut rng),
            }
        } else {
            // SIS2: the host's rates; its top bound must hold every ridge (see docs).
            Closing::Rates {
                closing: big(&mut rng),
                opening: big(&mut rng),
            }
        };
        let mut hin_used = hin.clone();
        if matches!(closing, Closing::Rates { .. }) {
            *hin_used.last_mut().unwrap() = opts.params.big;
        }
        let forcing = StepForcing {
            closing,
            dt,
            ndtd: 1 + rng.pick(2) as u32,
            tf: -1.8,
        };
        let before = budget(layout, a, v, s, t, aice0);
        let input = format!(
            "aice0 {aice0:e}, aicen {a:?}, vicen {v:?}, vsnon {s:?}, {forcing:?}, {:?} {:?}, \
             cleanup {} rebin {}",
            opts.participation, opts.redistribution, opts.cleanup, opts.rebin
        );
        let mut aice = a.iter().sum();
        let mut fl = OceanFluxes::default();
        let ws = &mut wss[li][ncat];
        let mut col = ColumnMut {
            aicen: a,
            vicen: v,
            vsnon: s,
            trcrn: t,
            aice0: &mut aice0,
            aice: &mut aice,
        };
        let saved: Vec<f64> = col.aicen.iter().chain(col.vicen.iter()).copied().collect();
        let d = match ridge_step_column(&mut col, &hin_used, forcing, &opts, layout, &mut fl, ws) {
            Ok(d) => d,
            // Icepack's limit of 20 ridging passes: very thick ice (little area lost per
            // pass) with a large area excess. A clear error, the column unchanged.
            Err(ColumnError::NoConvergence { .. }) => {
                let now: Vec<f64> = col.aicen.iter().chain(col.vicen.iter()).copied().collect();
                assert_eq!(now, saved, "column {column}: unchanged on error");
                assert_eq!(fl, OceanFluxes::default());
                stats[4] += 1;
                continue;
            }
            Err(e) => panic!("column {column}: {e}\ninput: {input}"),
        };
        for x in a.iter().chain(v.iter()).chain(s.iter()) {
            assert!(
                x.is_finite() && *x >= 0.0,
                "column {column}: negative or NaN {x}"
            );
        }
        assert!(
            aice0 >= 0.0 && aice0.is_finite(),
            "column {column}: aice0 {aice0}"
        );
        assert!(
            t.iter().all(|x| x.is_finite()),
            "column {column}: tracer NaN"
        );
        let after = budget(layout, a, v, s, t, aice0);
        let tau = dt * forcing.ndtd as f64;
        let rhoi = opts.params.rhoi;
        let rhos = opts.step.rhos;
        // Area: the step leaves exactly the cell (to round-off with the clean-up, within
        // Icepack's puny criterion without it).
        let area_tol = if opts.cleanup {
            1e-12
        } else {
            opts.params.puny
        };
        assert!(
            (after.area - 1.0).abs() <= area_tol || before.area == 0.0,
            "column {column}: total area {} (aice {aice}, aice0 {aice0}, aicen {a:?}, {d:?}, \
             cleanup {}, {forcing:?})",
            after.area,
            opts.cleanup
        );
        close(
            "ice volume",
            after.vice + d.ice_to_ocean,
            before.vice,
            before.vice,
            column,
        );
        close(
            "snow volume",
            after.vsno + d.snow_to_ocean,
            before.vsno,
            before.vsno,
            column,
        );
        close(
            "water mass (fresh)",
            rhoi * after.vice + rhos * after.vsno + fl.fresh * tau,
            rhoi * before.vice + rhos * before.vsno,
            rhoi * before.vice + rhos * before.vsno,
            column,
        );
        close(
            "enthalpy (fhocn)",
            after.heat + fl.fhocn * tau,
            before.heat,
            before.heat,
            column,
        );
        close(
            "salt (fsalt)",
            rhoi * after.salt * 1e-3 + fl.fsalt * tau,
            rhoi * before.salt * 1e-3,
            rhoi * before.salt * 1e-3,
            column,
        );
        stats[0] += 1;
        stats[1] += opts.cleanup as usize;
        stats[2] += (d.niter > 1) as usize;
        stats[3] += ws.zapped.iter().any(|z| *z) as usize;
    }
    println!(
        "{} columns conserved, {} cleaned up, {} needed several passes, {} had categories \
         zapped, {} refused (no convergence in nitermax passes)",
        stats[0], stats[1], stats[2], stats[3], stats[4]
    );
    assert!(stats[4] * 100 < n_columns, "refusals are rare");
    assert!(
        stats[2] > 0 && stats[3] > 0,
        "the generator reaches the hard paths"
    );
}
