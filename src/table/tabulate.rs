//! From campaign records to a lookup table of ridging energetics (Hopkins 1994, eqs 13–17).
//!
//! Runs are grouped into *sets* by their resolved scenes: two runs are in one set when their
//! scenes agree in everything but the sheet thickness, the block width tied to it, the seed
//! and the name — e.g. one set per friction pair. [`tabulate_scaled`] names further scene
//! keys that vary with the thickness within a set (the floe and sheet lengths of a scene
//! scaled with the sheet, `data/campaigns/thickness-scaled.toml`): they too are left out of
//! the comparison, the runs of one set and thickness must agree in them, and the table
//! records their values per set and thickness ([`RidgeTable::scaled_values`]). Runs of
//! several campaigns can be tabulated together (the thickness set and the friction set share
//! their μ = 1.0, μ_w = 0.6 runs at 0.30 m); a run met twice (same set, thickness and seed)
//! must have the same scene, and is then (by determinism, the same result) counted once; two
//! different scenes there are an error. Each set carries its friction pair
//! ([`RidgeTable::mu`], [`RidgeTable::mu_w`]), the coordinates by which host models choose
//! a set. Within a set:
//!
//! - every run's samples (W, ΔPE, mean force against ridged volume V = U·h·t) are
//!   interpolated linearly onto a common volume grid, within the volumes the run reached (a
//!   run's end is its nominal volume U·h·T, to half a step's volume U·h·Δt/2, so that each
//!   setting's final volume holds every run of it); the ensemble mean and standard deviation
//!   over the runs of each thickness are tabulated, with the number of runs behind each value
//!   (cells no run reached hold NaN, the CF fill value);
//! - eqs (13)–(14) are fitted by least squares through the origin ([`super::fit`]) per
//!   thickness and pooled over all thicknesses of the set (the paper's Figure 12), with
//!   standard errors and 95 % confidence and prediction bands of the pooled work curve; the
//!   force of eq (15) and the ratio dW/dPE of eq (16) follow from the pooled fits;
//! - C_f per thickness is the ensemble mean of the runs' final W/ΔPE: the ratio the strength
//!   routine multiplies the potential-energy term by, with its sample standard deviation and
//!   the 95 % confidence interval of the mean (Student t, n − 1 degrees of freedom).

use super::ensemble::{Stat, dissipation_violation};
use super::fit::{Band, FitError, QuadFit, fit_through_origin, force, ratio, student_t_quantile};
use super::redistribution::{RidgedEnsemble, RidgedIce};
use crate::record::RunRecord;
use ndarray::{Array2, Array3};

mod sets;
mod warnings;
use sets::Sets;
pub use warnings::fit_warnings;

/// The fits of one group of samples (J/m against m³/m).
#[derive(Clone, Debug, PartialEq)]
pub struct SetFits {
    /// Work, eq (13): W = V(a·V + b).
    pub work: QuadFit,
    /// Potential energy, eq (14): PE = V(a·V + b).
    pub potential_energy: QuadFit,
}

/// A tabulated campaign.
///
/// The grid fields are ndarray arrays over the axes `(set, thickness, volume)`, or the
/// subset named on each, always in that order and in standard (C, volume fastest) layout:
/// axis 0 indexes [`RidgeTable::sets`], axis `thickness` indexes [`RidgeTable::thickness`]
/// and axis `volume` indexes [`RidgeTable::volume`]. This is the layout of the table's
/// variables ([`RidgeTable::variables`]), of the in-memory lookup
/// ([`crate::table::lookup::Field::data`]) and of the NetCDF set layout; cells no run
/// reached hold NaN (counts hold 0).
#[derive(Clone, Debug, PartialEq)]
pub struct RidgeTable {
    /// Set labels: the friction pair, then the first run's other settings than thickness
    /// (`key=value` joined by `, `).
    pub sets: Vec<String>,
    /// Friction coefficient above the water line μ of each set (dimensionless).
    pub mu: Vec<f64>,
    /// Friction coefficient below the water line μ_w of each set (dimensionless).
    pub mu_w: Vec<f64>,
    /// Sheet thicknesses (m).
    pub thickness: Vec<f64>,
    /// Ridged-volume grid (m³/m).
    pub volume: Vec<f64>,
    /// Ensemble mean of the work over the runs, `(set, thickness, volume)` (J/m).
    pub work_mean: Array3<f64>,
    /// Standard deviation of the work over the runs, `(set, thickness, volume)` (J/m).
    pub work_std: Array3<f64>,
    /// Mean potential energy, `(set, thickness, volume)` (J/m).
    pub pe_mean: Array3<f64>,
    /// Standard deviation of the potential energy, `(set, thickness, volume)` (J/m).
    pub pe_std: Array3<f64>,
    /// Mean W/ΔPE, `(set, thickness, volume)` (dimensionless).
    pub ratio_mean: Array3<f64>,
    /// Mean ridging force over the sampling interval, `(set, thickness, volume)` (N/m).
    pub force_mean: Array3<f64>,
    /// Number of runs behind each value, `(set, thickness, volume)`.
    pub runs: Array3<u32>,
    /// Fits per set and thickness, `(set, thickness)` (`None` where there were too few
    /// samples).
    pub fits: Array2<Option<SetFits>>,
    /// Fits per set pooled over thicknesses.
    pub pooled: Vec<Option<SetFits>>,
    /// Bands of the pooled work fit per set on the volume grid.
    pub work_band: Vec<Option<Band>>,
    /// Force of eq (15) from the pooled work fit, `(set, thickness, volume)` (N/m); NaN at
    /// volumes no run of that thickness reached.
    pub force_fit: Array3<f64>,
    /// dW/dPE of eq (16) from the pooled fits, `(set, volume)` (dimensionless).
    pub ratio_fit: Array2<f64>,
    /// C_f = mean final W/ΔPE, `(set, thickness)` (dimensionless).
    pub cf: Array2<f64>,
    /// Sample standard deviation of the final W/ΔPE over the runs, `(set, thickness)`
    /// (dimensionless).
    pub cf_std: Array2<f64>,
    /// Lower and upper ends of the 95 % confidence interval of C_f, `(set, thickness)`
    /// (Student t on the runs' final W/ΔPE; NaN with fewer than two runs; dimensionless).
    pub cf_conf: Array2<(f64, f64)>,
    /// Runs behind each C_f, `(set, thickness)`.
    pub cf_runs: Array2<u32>,
    /// Each run's final W/ΔPE, `(set, thickness)`, in the runs' order (the seed spread
    /// behind `cf`, as many as `cf_runs`; dimensionless).
    pub cf_finals: Array2<Vec<f64>>,
    /// The simulated ridged ice per `(set, thickness)`: the thickness distribution of the
    /// runs' final profiles with Lipscomb's and Hibler's shapes fitted
    /// ([`super::redistribution`]); `None` where no run's record has the ridge columns.
    pub ridged: Array2<Option<RidgedEnsemble>>,
    /// The set of every run tabulated: (run id, set index).
    pub run_set: Vec<(String, usize)>,
    /// Seeds used.
    pub seeds: Vec<u64>,
    /// Runs left out, with the reason: those whose dissipation went negative
    /// ([`super::ensemble::dissipation_violation`]).
    pub excluded: Vec<(String, String)>,
    /// Runs met twice (another campaign's record of the same set, thickness and seed),
    /// counted once: (id left out, id kept).
    pub duplicates: Vec<(String, String)>,
    /// The scene keys scaled with the thickness within a set ([`tabulate_scaled`]; empty for
    /// [`tabulate`]), e.g. `floe.thickness`.
    pub scaled_keys: Vec<String>,
    /// Their values per set and thickness, `(set, thickness)`: one TOML value per key of
    /// [`RidgeTable::scaled_keys`], in its order (`-` where a run's scene lacks the key);
    /// empty where the set has no run of that thickness, or when no key is scaled.
    pub scaled_values: Array2<Vec<String>>,
}

impl RidgeTable {
    /// The scaled keys' values at set `s` and thickness index `h` as `key=value` joined by
    /// `, ` ([`RidgeTable::scaled_values`]); empty where there are none.
    pub fn scaled_label(&self, s: usize, h: usize) -> String {
        key_values(&self.scaled_keys, &self.scaled_values[[s, h]])
    }
}

/// `key=value` pairs joined by `, `.
fn key_values(keys: &[String], values: &[String]) -> String {
    keys.iter()
        .zip(values)
        .map(|(k, v)| format!("{k}={v}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The friction pair of Hopkins (1994)'s thickness set and of CICE's ridging energetics
/// default in this crate: μ = 1.0 above and μ_w = 0.6 below the water line.
pub const DEFAULT_FRICTION: (f64, f64) = (1.0, 0.6);

impl RidgeTable {
    /// The set index of the tabulated run `id`, if it was tabulated (not left out by the
    /// gate, not a duplicate).
    pub fn set_of(&self, id: &str) -> Option<usize> {
        self.run_set.iter().find(|(r, _)| r == id).map(|&(_, s)| s)
    }

    /// The set at friction (`mu`, `mu_w`) (dimensionless; equal to 1e-9), if any.
    pub fn friction_set(&self, mu: f64, mu_w: f64) -> Option<usize> {
        (0..self.sets.len())
            .find(|&s| (self.mu[s] - mu).abs() <= 1e-9 && (self.mu_w[s] - mu_w).abs() <= 1e-9)
    }

    /// The set behind the table's 1-D `cf` (the file read as a plain C_f table): the one at
    /// [`DEFAULT_FRICTION`] when there is one, else the first.
    pub fn default_set(&self) -> usize {
        self.friction_set(DEFAULT_FRICTION.0, DEFAULT_FRICTION.1)
            .unwrap_or(0)
    }
}

/// Errors of tabulation.
#[derive(Debug, thiserror::Error)]
pub enum TabulateError {
    /// No usable run.
    #[error("no finished run with a sheet to tabulate")]
    Empty,
    /// A fit failed.
    #[error("fit: {0}")]
    Fit(#[from] FitError),
    /// A key given as scaled with the thickness is not a scene key, or is one that may not
    /// vary within a set.
    #[error("scaled key `{0}`: {1}")]
    ScaledKey(String, String),
    /// Two runs of one set and thickness disagree: the same seed with different scenes, or
    /// different values of a key scaled with the thickness.
    #[error(
        "runs `{0}` and `{1}` are in one set at one thickness but {2}: tabulate them into separate tables"
    )]
    Conflict(String, String, String),
}

/// The scene keys that may not be scaled with the thickness: the thickness and block width
/// (always part of the thickness coordinate), the friction pair (it defines the sets), the
/// seed and the name.
const NOT_SCALABLE: [&str; 6] = [
    "sheet.thickness",
    "sheet.block_width",
    "contact.mu",
    "contact.mu_water",
    "seed",
    "name",
];

fn is_thickness_key(s: &str) -> bool {
    s.starts_with("sheet.thickness=") || s.starts_with("sheet.block_width=")
}

fn is_friction_key(s: &str) -> bool {
    s.starts_with("contact.mu=") || s.starts_with("contact.mu_water=")
}

/// The volume a run was set to ridge (m³/m): U·h·T of its scene, or its last sample's volume
/// when the scene's values do not give one.
fn nominal_volume(r: &RunRecord) -> f64 {
    let v = r
        .scene
        .sheet
        .as_ref()
        .map_or(0.0, |s| s.speed * s.thickness * r.scene.duration);
    if v > 0.0 && v.is_finite() {
        v
    } else {
        r.samples.last().map_or(0.0, |s| s.volume)
    }
}

/// A run's samples on the table's volume axis: their ridged volumes (m³/m), the last at the
/// run's nominal volume U·h·T when the run reached its duration, and the work, potential
/// energy (J/m) and mean force (N/m) there.
///
/// A run stops within half a step of T, so its last sample lies up to U·h·Δt/2 short of (or
/// past) U·h·T; read as it is, the run's end would fall off a grid point placed at U·h·T
/// (the shipped table's final volumes held 0–3 of their 7–12 runs until 2026-12-01). And the
/// end U·h·T and that grid point k·V_max/(n − 1) are one volume computed two ways, which
/// roundoff can part by an ulp: for h = 1.15 m at 0.25 m/s for 400 s, U·h·T is
/// 114.99999999999999 m³/m against the grid point 115 of the 0–600 m³/m axis in 241 points.
/// So a grid point at most [`RunOnAxis::tol`] past the run's end counts at the end, with
/// its last sample's values: the record's own resolution there, half the volume one time
/// step ridges, U·h·Δt/2 (about 1e-5 m³/m for a 0.30 m sheet at 0.25 m/s and
/// Δt = 2.6e-4 s, against 2.5 m³/m between the shipped table's volumes), and never less than
/// four ulps of the end's volume. A grid point farther out is a volume the run did not reach
/// (NaN).
struct RunOnAxis {
    /// The samples' ridged volumes (m³/m), ascending.
    volume: Vec<f64>,
    /// How far past the last volume a grid point still counts at the run's end (m³/m).
    tol: f64,
    /// Work at each sample (J/m).
    work: Vec<f64>,
    /// Potential energy at each sample (J/m).
    pe: Vec<f64>,
    /// Mean ridging force over the interval ending at each sample (N/m).
    force: Vec<f64>,
}

impl RunOnAxis {
    fn of(r: &RunRecord) -> RunOnAxis {
        let mut volume: Vec<f64> = r.samples.iter().map(|s| s.volume).collect();
        if let (Some(last), Some(x)) = (r.samples.last(), volume.last_mut())
            && (last.time - r.scene.duration).abs() <= r.summary.dt
        {
            *x = nominal_volume(r);
        }
        let end = volume.last().copied().unwrap_or(0.0);
        let step = r
            .scene
            .sheet
            .as_ref()
            .map_or(0.0, |s| 0.5 * s.speed * s.thickness * r.summary.dt);
        let roundoff = 4.0 * f64::EPSILON * end.abs();
        let tol = if step.is_finite() {
            step.max(roundoff)
        } else {
            roundoff
        };
        RunOnAxis {
            volume,
            tol,
            work: r.samples.iter().map(|s| s.energy().work).collect(),
            pe: r
                .samples
                .iter()
                .map(|s| s.energy().potential_energy)
                .collect(),
            force: r.samples.iter().map(|s| s.mean_force).collect(),
        }
    }

    /// `ys` (one value per sample) at grid volume `v` (m³/m): linear between the samples,
    /// the last value within [`RunOnAxis::tol`] past the end, NaN outside.
    fn at(&self, ys: &[f64], v: f64) -> f64 {
        match (self.volume.last(), ys.last()) {
            (Some(&end), Some(&y)) if v > end && v - end <= self.tol => y,
            _ => crate::itd::interp::resample(&self.volume, ys, v),
        }
    }
}

/// Tabulates campaign records on a volume grid of `points` points from 0 to the largest
/// volume a run was set to reach, U·h·T of its scene. Runs whose dissipation went negative (a numerical energy source, see
/// [`dissipation_violation`]) are left out and listed in [`RidgeTable::excluded`].
pub fn tabulate(records: &[RunRecord], points: usize) -> Result<RidgeTable, TabulateError> {
    tabulate_scaled(records, points, &[])
}

/// [`tabulate`] with scene keys `scaled` (dotted, e.g. `floe.thickness`) that vary with the
/// thickness within a set: left out of the comparison that groups runs into sets (as the
/// thickness and block width are), so that runs whose scenes scale these with the sheet (and
/// runs that hold them fixed) make one set. The runs of one set and thickness must agree in
/// them ([`TabulateError::Conflict`] otherwise); their values are recorded per set and
/// thickness in [`RidgeTable::scaled_values`]. A key no run's scene has, or one of the
/// thickness, block width, friction pair, seed or name, is refused.
pub fn tabulate_scaled(
    records: &[RunRecord],
    points: usize,
    scaled: &[String],
) -> Result<RidgeTable, TabulateError> {
    for k in scaled {
        if NOT_SCALABLE.contains(&k.as_str()) {
            return Err(TabulateError::ScaledKey(
                k.clone(),
                "the thickness and block width always go with the thickness, and the friction pair, seed and name may not vary within a set".into(),
            ));
        }
        let known = records.iter().any(|r| r.scene.value_at(k).is_some());
        if !known {
            return Err(TabulateError::ScaledKey(
                k.clone(),
                "no run's scene has this key".into(),
            ));
        }
    }
    let mut excluded = Vec::new();
    let recs: Vec<&RunRecord> = records
        .iter()
        .filter(|r| r.scene.sheet.is_some() && r.samples.len() >= 2)
        .filter(|r| match dissipation_violation(r) {
            Some(why) => {
                excluded.push((r.id.clone(), why));
                false
            }
            None => true,
        })
        .collect();
    if recs.is_empty() {
        return Err(TabulateError::Empty);
    }
    let Sets {
        sets,
        mu,
        mu_w,
        thickness,
        seeds,
        duplicates,
        scaled_seen,
        set_index,
        runs: recs,
    } = Sets::of(recs, scaled)?;
    let h_of = |r: &RunRecord| r.scene.sheet.as_ref().expect("filtered").thickness;
    // The grid ends at the largest volume a run was set to reach, U·h·T: its points are
    // then round numbers (k·2.5 m³/m for 0–600 in 241), and every run's end is one of them.
    let vmax = recs.iter().map(|r| nominal_volume(r)).fold(0.0, f64::max);
    let points = points.max(2);
    let volume: Vec<f64> = (0..points)
        .map(|k| vmax * k as f64 / (points - 1) as f64)
        .collect();
    let (ns, nh, nv) = (sets.len(), thickness.len(), points);
    let grid = || Array3::from_elem((ns, nh, nv), f64::NAN);
    let mut t = RidgeTable {
        sets: sets.clone(),
        mu,
        mu_w,
        thickness: thickness.clone(),
        volume: volume.clone(),
        work_mean: grid(),
        work_std: grid(),
        pe_mean: grid(),
        pe_std: grid(),
        ratio_mean: grid(),
        force_mean: grid(),
        runs: Array3::zeros((ns, nh, nv)),
        fits: Array2::from_elem((ns, nh), None),
        pooled: vec![None; ns],
        work_band: vec![None; ns],
        force_fit: grid(),
        ratio_fit: Array2::from_elem((ns, nv), f64::NAN),
        cf: Array2::from_elem((ns, nh), f64::NAN),
        cf_std: Array2::from_elem((ns, nh), f64::NAN),
        cf_conf: Array2::from_elem((ns, nh), (f64::NAN, f64::NAN)),
        cf_runs: Array2::zeros((ns, nh)),
        cf_finals: Array2::from_elem((ns, nh), Vec::new()),
        ridged: Array2::from_elem((ns, nh), None),
        run_set: recs
            .iter()
            .zip(&set_index)
            .map(|(r, &si)| (r.id.clone(), si))
            .collect(),
        seeds,
        excluded,
        duplicates,
        scaled_keys: scaled.to_vec(),
        scaled_values: Array2::from_elem((ns, nh), Vec::new()),
    };
    for (si, hb, v, _) in &scaled_seen {
        let hi = thickness
            .iter()
            .position(|h| h.to_bits() == *hb)
            .expect("a thickness met");
        t.scaled_values[[*si, hi]] = v.clone();
    }
    for si in 0..ns {
        let (mut pv, mut pw, mut pp) = (Vec::new(), Vec::new(), Vec::new());
        for (hi, &h) in thickness.iter().enumerate() {
            let group: Vec<&&RunRecord> = recs
                .iter()
                .zip(&set_index)
                .filter(|&(r, &s)| s == si && h_of(r) == h)
                .map(|(r, _)| r)
                .collect();
            if group.is_empty() {
                continue;
            }
            let (fv, fw, fp) = fill_setting(&mut t, [si, hi], h, &group, &volume);
            pv.extend(fv);
            pw.extend(fw);
            pp.extend(fp);
        }
        if let (Ok(work), Ok(pe)) = (fit_through_origin(&pv, &pw), fit_through_origin(&pv, &pp)) {
            t.work_band[si] = Some(Band::new(&work, &volume, 0.95));
            for (vi, &v) in volume.iter().enumerate() {
                t.ratio_fit[[si, vi]] = ratio(&work, &pe, v);
                for (hi, &h) in thickness.iter().enumerate() {
                    // Only where this thickness's runs reached: eq (15) holds for primary
                    // ridge growth, which a thin sheet may have left at larger volumes.
                    if t.runs[[si, hi, vi]] > 0 {
                        t.force_fit[[si, hi, vi]] = force(&work, h, v);
                    }
                }
            }
            t.pooled[si] = Some(SetFits {
                work,
                potential_energy: pe,
            });
        }
    }
    Ok(t)
}

/// Fills the table's cells of set and thickness `[si, hi]` (thickness `h`, m) from the runs
/// `group`: the ensemble statistics at each volume, C_f from the final W/ΔPE, the ridged ice,
/// and the fits of eqs (13)–(14) over every sample with V > 0, whose samples (volume, work,
/// potential energy) it returns for the set's pooled fit.
fn fill_setting(
    t: &mut RidgeTable,
    [si, hi]: [usize; 2],
    h: f64,
    group: &[&&RunRecord],
    volume: &[f64],
) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let mean_std = |xs: &[f64]| -> (f64, f64) {
        let s = Stat::of(xs);
        (s.mean, s.std)
    };
    let on_axis: Vec<RunOnAxis> = group.iter().map(|r| RunOnAxis::of(r)).collect();
    for (vi, &v) in volume.iter().enumerate() {
        let (mut w, mut p, mut q, mut f) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        for r in &on_axis {
            let (wv, pv_) = (r.at(&r.work, v), r.at(&r.pe, v));
            if wv.is_finite() && pv_.is_finite() {
                w.push(wv);
                p.push(pv_);
                if pv_ > 0.0 {
                    q.push(wv / pv_);
                }
                let fv = r.at(&r.force, v);
                if fv.is_finite() && v > 0.0 {
                    f.push(fv);
                }
            }
        }
        let c = [si, hi, vi];
        if !w.is_empty() {
            t.runs[c] = w.len() as u32;
            (t.work_mean[c], t.work_std[c]) = mean_std(&w);
            (t.pe_mean[c], t.pe_std[c]) = mean_std(&p);
        }
        if !q.is_empty() {
            t.ratio_mean[c] = mean_std(&q).0;
        }
        if !f.is_empty() {
            t.force_mean[c] = mean_std(&f).0;
        }
    }
    // Fits over every sample of every run of this thickness (V > 0).
    let (mut fv, mut fw, mut fp) = (Vec::new(), Vec::new(), Vec::new());
    let mut finals = Vec::new();
    for r in group {
        for s in r.samples.iter().filter(|s| s.volume > 0.0) {
            let e = s.energy();
            fv.push(s.volume);
            fw.push(e.work);
            fp.push(e.potential_energy);
        }
        let last = r.samples.last().expect("≥ 2 samples").energy();
        if last.potential_energy > 0.0 {
            finals.push(last.work / last.potential_energy);
        }
    }
    if !finals.is_empty() {
        let st = Stat::of(&finals);
        t.cf[[si, hi]] = st.mean;
        t.cf_std[[si, hi]] = st.std;
        t.cf_runs[[si, hi]] = st.n as u32;
        if st.n > 1 {
            let half = student_t_quantile(0.975, (st.n - 1) as f64) * st.std / (st.n as f64).sqrt();
            t.cf_conf[[si, hi]] = (st.mean - half, st.mean + half);
        }
    }
    t.cf_finals[[si, hi]] = finals;
    let ridged: Vec<RidgedIce> = group
        .iter()
        .filter_map(|r| RidgedIce::of(&r.profile, h).ok())
        .collect();
    t.ridged[[si, hi]] = RidgedEnsemble::of(&ridged);
    if let (Ok(work), Ok(pe)) = (fit_through_origin(&fv, &fw), fit_through_origin(&fv, &fp)) {
        t.fits[[si, hi]] = Some(SetFits {
            work,
            potential_energy: pe,
        });
    }
    (fv, fw, fp)
}

#[cfg(test)]
mod tests;
