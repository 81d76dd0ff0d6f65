//! The thickness distribution of the simulated ridges, and the two shapes host models
//! redistribute ridged ice with, fitted to it.
//!
//! **Ridged ice of a run** ([`RidgedIce::of`]): the strips of its final profile that hold
//! rubble (`observe`, module docs), each with its solid rubble thickness (area over strip
//! width, m) and the thickness of its rubble column with voids (m). Strips are 1 m wide by
//! default (the paper's), so each is one sample of equal area. The solid thickness is what a
//! host model's ridged ice is: Icepack conserves volume, so its ridged thickness is volume per
//! area; the voids are the ridge's porosity, `1 − Σ solid / Σ column`.
//!
//! **The host models' shapes** (Icepack `ridge_itd`; parent thickness h, m):
//! - Lipscomb et al. (2007), `krdg_redist = 1`: g(H) ∝ exp(−(H − H_min)/λ) for H ≥ H_min,
//!   with H_min = min(2h, h + maxraft) (maxraft = 1 m, `ItdParams::maxraft`'s default) and
//!   λ = μ_rdg·√h (μ_rdg in m^½, 3 by default in Icepack); mean H_min + λ;
//! - Hibler (1980), `krdg_redist = 0`: uniform on [H_min, 2·√(H*·h)] (H* in m, 25 by default);
//!   mean (H_min + H_max)/2.
//!
//! **The fits** match the mean: the host conserves volume through the mean ridged thickness
//! alone (Icepack's `krdg` = mean / h), so a shape whose mean differs moves area, whatever it
//! does to the tail. λ = H̄ − H_min, μ_rdg = λ/√h; H_max = 2H̄ − H_min, H* = (H_max/2)²/h. The
//! goodness of fit is the Kolmogorov–Smirnov distance between the area-weighted empirical
//! distribution and the fitted one (0: the same; 1: disjoint); strips thinner than H_min, which
//! neither shape allows, count against both. The ensemble intervals are Student-t 95 % over
//! the runs' own fits (the seed-to-seed spread), the pooled fit is over all strips at once.

use crate::itd::ItdParams;
use crate::observe::{Profile, RidgeSummary, ridged_strips};
use crate::record::RunRecord;
use crate::table::ensemble::Stat;

/// Edges of the bins of a ridging table's binned distribution (`ridged_fraction`), in units of
/// the parent thickness (H/h, dimensionless): 0 to 20 by 0.5; strips thicker than 20h fall in
/// the last bin. Relative to h, Lipscomb's shape starts at 2 and falls by e over μ_rdg/√h.
pub fn table_bin_edges() -> Vec<f64> {
    (0..=40).map(|i| 0.5 * f64::from(i)).collect()
}

/// The ridged ice of one run, or of several pooled.
#[derive(Clone, Debug, PartialEq)]
pub struct RidgedIce {
    /// Thickness of the parent (lead) ice h (m).
    pub parent_thickness: f64,
    /// Width of a strip (m).
    pub strip_width: f64,
    /// Solid rubble thickness of each ridged strip (m).
    pub ice: Vec<f64>,
    /// Thickness of each ridged strip's rubble column, voids included (m).
    pub column: Vec<f64>,
}

/// The two shapes fitted to a distribution of ridged thickness (m unless said).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapeFit {
    /// Mean ridged thickness H̄ (m).
    pub mean: f64,
    /// Thinnest ridged ice of both shapes, H_min = min(2h, h + maxraft) (m).
    pub h_min: f64,
    /// Area fraction of the strips thinner than H_min, which neither shape allows (the
    /// ridge's flanks; dimensionless).
    pub below_min: f64,
    /// Lipscomb's e-folding thickness λ = H̄ − H_min (m).
    pub lambda: f64,
    /// Lipscomb's μ_rdg = λ/√h (m^½).
    pub mu_rdg: f64,
    /// Kolmogorov–Smirnov distance of the exponential fit (dimensionless, 0–1).
    pub ks_exponential: f64,
    /// Hibler's thickest ridged ice H_max = 2H̄ − H_min (m).
    pub h_max: f64,
    /// Hibler's H* = (H_max/2)²/h (m).
    pub h_star: f64,
    /// Kolmogorov–Smirnov distance of the uniform fit (dimensionless, 0–1).
    pub ks_uniform: f64,
}

/// An error in the ridged-ice analysis, naming what is missing or wrong.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RidgedError {
    /// The profile has no ridge columns (a record written before they were kept).
    #[error(
        "the profile has no ridge columns (`ridge_ice`, `ridge_envelope`): its record was written before they were kept; run it again"
    )]
    NoColumns,
    /// No strip holds rubble.
    #[error("no strip of the profile holds rubble: nothing was ridged")]
    NoRidge,
    /// The parent thickness is not positive and finite.
    #[error("parent thickness h = {0} m: must be positive and finite")]
    Thickness(f64),
}

impl RidgedIce {
    /// The ridged strips of profile `p` of a run whose lead ice was `h` m thick.
    pub fn of(p: &Profile, h: f64) -> Result<RidgedIce, RidgedError> {
        if !(h.is_finite() && h > 0.0) {
            return Err(RidgedError::Thickness(h));
        }
        if p.ridge_ice.len() != p.sail.len() || p.ridge_envelope.len() != p.sail.len() {
            return Err(RidgedError::NoColumns);
        }
        let (ice, column): (Vec<f64>, Vec<f64>) = ridged_strips(p).into_iter().unzip();
        if ice.is_empty() {
            return Err(RidgedError::NoRidge);
        }
        Ok(RidgedIce {
            parent_thickness: h,
            strip_width: p.dx,
            ice,
            column,
        })
    }

    /// The ridged strips of run `r` at its sample `i` ([`crate::record::RunSample::ridge_strips`],
    /// to the millimetre), its lead ice `h` m thick: the distribution as the ridge grew.
    pub fn at_sample(r: &RunRecord, i: usize, h: f64) -> Result<RidgedIce, RidgedError> {
        if !(h.is_finite() && h > 0.0) {
            return Err(RidgedError::Thickness(h));
        }
        let s = r.samples.get(i).ok_or(RidgedError::NoColumns)?;
        if s.ridge_strips.is_empty() {
            return Err(match s.ridge {
                Some(_) => RidgedError::NoColumns,
                None => RidgedError::NoRidge,
            });
        }
        let (ice, column) = s.ridge_strips.iter().map(|x| (x[0], x[1])).unzip();
        Ok(RidgedIce {
            parent_thickness: h,
            strip_width: r.profile.dx,
            ice,
            column,
        })
    }

    /// Several runs of one parent thickness as one sample (their strips together).
    pub fn pooled(runs: &[RidgedIce]) -> Option<RidgedIce> {
        let first = runs.first()?;
        Some(RidgedIce {
            parent_thickness: first.parent_thickness,
            strip_width: first.strip_width,
            ice: runs.iter().flat_map(|r| r.ice.iter().copied()).collect(),
            column: runs.iter().flat_map(|r| r.column.iter().copied()).collect(),
        })
    }

    /// Width of the ridged strips together (m): per metre along the ridge, its area (m²/m).
    pub fn width(&self) -> f64 {
        self.summary().map_or(0.0, |s| s.width)
    }

    /// Mean solid thickness of the ridged ice (m): its volume over its area.
    pub fn mean_thickness(&self) -> f64 {
        self.summary().map_or(f64::NAN, |s| s.mean_thickness)
    }

    /// Porosity of the ridge (dimensionless): the voids' share of its rubble columns.
    pub fn porosity(&self) -> f64 {
        self.summary().map_or(f64::NAN, |s| s.porosity)
    }

    /// Width, mean solid thickness and porosity as one profile's [`RidgeSummary`] gives them
    /// (`None` without strips).
    fn summary(&self) -> Option<RidgeSummary> {
        let strips: Vec<(f64, f64)> = self
            .ice
            .iter()
            .copied()
            .zip(self.column.iter().copied())
            .collect();
        RidgeSummary::of_strips(&strips, self.strip_width)
    }

    /// Fraction of the ridged area in each bin `[edges[i], edges[i + 1])` of solid thickness
    /// (m); the last bin includes its upper edge.
    pub fn histogram(&self, edges: &[f64]) -> Vec<f64> {
        let nb = edges.len().saturating_sub(1);
        let mut f = vec![0.0; nb];
        let w = 1.0 / self.ice.len() as f64;
        for &x in &self.ice {
            if let Some(i) = (0..nb).find(|&i| {
                x >= edges[i] && (x < edges[i + 1] || (i + 1 == nb && x == edges[i + 1]))
            }) {
                f[i] += w;
            }
        }
        f
    }

    /// Fraction of the ridged area in each bin of [`table_bin_edges`] (H/h), the strips
    /// thicker than the last edge in the last bin (dimensionless; sums to 1).
    pub fn table_histogram(&self) -> Vec<f64> {
        let edges = table_bin_edges();
        let h = self.parent_thickness;
        let top = edges[edges.len() - 1] * h;
        let capped = RidgedIce {
            ice: self.ice.iter().map(|&x| x.min(top)).collect(),
            ..self.clone()
        };
        let abs: Vec<f64> = edges.iter().map(|e| e * h).collect();
        capped.histogram(&abs)
    }

    /// Lipscomb's and Hibler's shapes fitted to the solid thicknesses (module docs).
    pub fn fit(&self) -> ShapeFit {
        let h = self.parent_thickness;
        let mean = self.mean_thickness();
        let h_min = (2.0 * h).min(h + ItdParams::default().maxraft);
        let lambda = mean - h_min;
        let h_max = 2.0 * mean - h_min;
        let exponential = |x: f64| {
            if x < h_min || lambda <= 0.0 {
                f64::from(u8::from(x >= h_min))
            } else {
                1.0 - (-(x - h_min) / lambda).exp()
            }
        };
        let uniform = |x: f64| ((x - h_min) / (h_max - h_min)).clamp(0.0, 1.0);
        ShapeFit {
            mean,
            h_min,
            below_min: self.ice.iter().filter(|&&x| x < h_min).count() as f64
                / self.ice.len() as f64,
            lambda,
            mu_rdg: lambda / h.sqrt(),
            ks_exponential: ks_distance(&self.ice, exponential),
            h_max,
            h_star: (h_max / 2.0).powi(2) / h,
            ks_uniform: ks_distance(&self.ice, uniform),
        }
    }
}

/// The Kolmogorov–Smirnov distance sup |F_n(x) − F(x)| between the empirical distribution of
/// `xs` (equal weights) and the distribution function `cdf` (dimensionless).
pub fn ks_distance(xs: &[f64], cdf: impl Fn(f64) -> f64) -> f64 {
    let mut s = xs.to_vec();
    s.sort_by(f64::total_cmp);
    let n = s.len() as f64;
    s.iter()
        .enumerate()
        .map(|(i, &x)| {
            let f = cdf(x);
            (f - i as f64 / n).abs().max((f - (i + 1) as f64 / n).abs())
        })
        .fold(0.0, f64::max)
}

/// The ridged ice of an ensemble of runs of one parent thickness: the pooled fit and the
/// seed-to-seed statistics of each run's own.
#[derive(Clone, Debug, PartialEq)]
pub struct RidgedEnsemble {
    /// The runs' strips together.
    pub pooled: RidgedIce,
    /// The shapes fitted to the pooled strips.
    pub fit: ShapeFit,
    /// Mean solid thickness per run (m).
    pub mean_thickness: Stat,
    /// Porosity per run (dimensionless).
    pub porosity: Stat,
    /// Ridged width per run (m).
    pub width: Stat,
    /// λ per run (m).
    pub lambda: Stat,
    /// μ_rdg per run (m^½).
    pub mu_rdg: Stat,
    /// H* per run (m).
    pub h_star: Stat,
}

impl RidgedEnsemble {
    /// The ensemble of `runs` (`None` when empty).
    pub fn of(runs: &[RidgedIce]) -> Option<RidgedEnsemble> {
        let pooled = RidgedIce::pooled(runs)?;
        let fits: Vec<ShapeFit> = runs.iter().map(RidgedIce::fit).collect();
        let stat = |f: &dyn Fn(&ShapeFit) -> f64| Stat::of(&fits.iter().map(f).collect::<Vec<_>>());
        Some(RidgedEnsemble {
            fit: pooled.fit(),
            mean_thickness: stat(&|f| f.mean),
            porosity: Stat::of(&runs.iter().map(RidgedIce::porosity).collect::<Vec<_>>()),
            width: Stat::of(&runs.iter().map(RidgedIce::width).collect::<Vec<_>>()),
            lambda: stat(&|f| f.lambda),
            mu_rdg: stat(&|f| f.mu_rdg),
            h_star: stat(&|f| f.h_star),
            pooled,
        })
    }
}

impl RidgedEnsemble {
    /// The μ_rdg a host can redistribute with (m^½): the mean over the runs' own fits where it
    /// is positive, `None` where it is not. An exponential that starts at H_min has a mean above
    /// H_min, so ridged ice whose mean is no thicker than H_min (at the thick end, where one
    /// or two layers of blocks spread the ridge wide) has no Lipscomb shape of its mean; the
    /// table writes NaN there, and a host's table lookup takes the thicknesses that have one.
    pub fn host_mu_rdg(&self) -> Option<f64> {
        (self.mu_rdg.mean > 0.0).then_some(self.mu_rdg.mean)
    }

    /// The ensemble as named numbers, the faces' one spelling (Python's `redistribution`):
    /// `runs`, `strips`; for `width` (m), `mean_thickness` (m), `porosity`, `lambda` (m),
    /// `mu_rdg` (m^½) and `h_star` (m) the mean over the runs' own fits, `<name>_std` and
    /// `<name>_ci95` (half-width of the 95 % Student-t interval); `pooled_mu_rdg`,
    /// `pooled_h_star`, `below_h_min`, `ks_exponential`, `ks_uniform` of the pooled fit.
    pub fn columns(&self) -> Vec<(String, f64)> {
        let mut c = vec![
            ("runs".to_string(), self.lambda.n as f64),
            ("strips".to_string(), self.pooled.ice.len() as f64),
        ];
        for (name, s) in [
            ("width", &self.width),
            ("mean_thickness", &self.mean_thickness),
            ("porosity", &self.porosity),
            ("lambda", &self.lambda),
            ("mu_rdg", &self.mu_rdg),
            ("h_star", &self.h_star),
        ] {
            c.push((name.to_string(), s.mean));
            c.push((format!("{name}_std"), s.std));
            c.push((format!("{name}_ci95"), s.half_width_95()));
        }
        for (name, v) in [
            ("pooled_mu_rdg", self.fit.mu_rdg),
            ("pooled_h_star", self.fit.h_star),
            ("below_h_min", self.fit.below_min),
            ("ks_exponential", self.fit.ks_exponential),
            ("ks_uniform", self.fit.ks_uniform),
        ] {
            c.push((name.to_string(), v));
        }
        c
    }
}

/// The setting an ensemble of campaign runs shares: lead-ice thickness (m) and the friction
/// coefficients above and below the water line (dimensionless).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Setting {
    /// Lead-ice thickness h (m).
    pub thickness: f64,
    /// Friction coefficient μ above the water line.
    pub mu: f64,
    /// Friction coefficient μ_w below it.
    pub mu_water: f64,
}

/// The ridged-ice ensembles of campaign runs, one per [`Setting`] (ordered by μ, μ_w, then h),
/// and the number of runs left out because their records have no ridge columns.
pub fn ensembles(records: &[RunRecord]) -> (Vec<(Setting, RidgedEnsemble)>, usize) {
    let mut groups: Vec<(Setting, Vec<RidgedIce>)> = Vec::new();
    let mut without = 0;
    for r in records {
        let Some(sheet) = &r.scene.sheet else {
            continue;
        };
        let key = Setting {
            thickness: sheet.thickness,
            mu: r.scene.contact.mu,
            mu_water: r.scene.contact.mu_water,
        };
        match RidgedIce::of(&r.profile, sheet.thickness) {
            Ok(ice) => match groups.iter_mut().find(|(k, _)| *k == key) {
                Some((_, v)) => v.push(ice),
                None => groups.push((key, vec![ice])),
            },
            Err(RidgedError::NoColumns) => without += 1,
            Err(_) => {}
        }
    }
    groups.sort_by(|(a, _), (b, _)| {
        (a.mu.total_cmp(&b.mu))
            .then(a.mu_water.total_cmp(&b.mu_water))
            .then(a.thickness.total_cmp(&b.thickness))
    });
    let rows = groups
        .into_iter()
        .filter_map(|(k, v)| RidgedEnsemble::of(&v).map(|e| (k, e)))
        .collect();
    (rows, without)
}

/// A Markdown table of ridged-ice ensembles: per setting the runs, the ridged width, the mean
/// solid thickness and porosity, and each shape's parameter (mean ± 95 % over the runs' own
/// fits, then the pooled fit) with its Kolmogorov–Smirnov distance on the pooled strips.
pub fn markdown(rows: &[(Setting, RidgedEnsemble)]) -> String {
    let pm = |s: &Stat, d: usize| s.mean_ci95(d);
    let mut t = String::from(
        "| h (m) | μ | μ_w | runs | strips | ridged width (m) | mean H (m) | porosity | below H_min | λ (m) | μ_rdg (m^½): runs; pooled | KS exp. | H* (m): runs; pooled | KS unif. |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for (k, e) in rows {
        t += &format!(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {:.2} | {} | {}; {:.2} | {:.2} | {}; {:.1} | {:.2} |\n",
            k.thickness,
            k.mu,
            k.mu_water,
            e.lambda.n,
            e.pooled.ice.len(),
            pm(&e.width, 1),
            pm(&e.mean_thickness, 2),
            pm(&e.porosity, 2),
            e.fit.below_min,
            pm(&e.lambda, 2),
            pm(&e.mu_rdg, 2),
            e.fit.mu_rdg,
            e.fit.ks_exponential,
            pm(&e.h_star, 1),
            e.fit.h_star,
            e.fit.ks_uniform,
        );
    }
    t
}

#[cfg(test)]
mod tests;
