//! Ridge observations from a saved state: profiles in 1-m vertical strips and ridge metrics
//! (Hopkins 1994, "Effects of Friction", "Block Lengths and Ridge Slopes").
//!
//! **Profiles.** Each strip [x, x + Δx) is sampled on `lines_per_strip` vertical lines. On
//! each line the highest and the lowest point of the ice present (held walls excluded) give
//! the sail height max(top − level, 0) and the keel depth max(level − bottom, 0); a line
//! without ice counts 0. The strip value is the mean over its lines ("the mean height and
//! depth of ice in each strip"). Two profiles are kept: of all ice (sheet, floe, rubble: what
//! the paper's Figure 8 boxes show) and of rubble alone. For the ridged-ice thickness
//! distribution (`table::redistribution`), each line also gives the solid rubble on it (the sum of
//! the rubble pieces' vertical extents) and the rubble column (its lowest to its highest
//! rubble point, less the intact ice inside that span): their strip means are the ridge's
//! solid thickness and its thickness with voids.
//!
//! **Metrics** (from the rubble profile and the rubble blocks):
//! - maximum sail height and keel depth (m): the largest strip values;
//! - sail and keel cross-sections (m², per metre of ridge): of the envelope, Σ strip value ·
//!   Δx, and of solid ice, the rubble area above and below the water line;
//! - flank slopes (degrees): the paper drew lines "by eye through the major portion of each
//!   slope". Our rule: on each side of the peak strip, the strips whose value lies between
//!   20 % and 80 % of the peak, walking outward from the peak until the value first drops
//!   below 20 %; a least-squares line through their (centre, value) points; the angle is
//!   atan of its slope's magnitude. Fewer than two such strips give no slope (NaN-free: the
//!   metric is `None`);
//! - L/h: mean length of the rubble pieces over the sheet thickness.

use crate::dem::V2;
use crate::dem::{Role, Snapshot};
use serde::{Deserialize, Serialize};

/// Sail and keel profile in vertical strips.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Profile {
    /// Left edge of the first strip (m).
    pub x0: f64,
    /// Strip width (m).
    pub dx: f64,
    /// Mean sail height per strip, all ice (m).
    pub sail: Vec<f64>,
    /// Mean keel depth per strip, all ice (m).
    pub keel: Vec<f64>,
    /// Mean sail height per strip, rubble only (m).
    pub rubble_sail: Vec<f64>,
    /// Mean keel depth per strip, rubble only (m).
    pub rubble_keel: Vec<f64>,
    /// Solid rubble thickness per strip (m): the rubble's area in the strip over its width,
    /// the ridged ice as a host model books it (volume per area). Empty in records written
    /// before it was kept (2026-11-28).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub ridge_ice: Vec<f64>,
    /// Thickness of the rubble column per strip, voids included (m): on each line, from the
    /// rubble's lowest to its highest point, less the intact ice (sheet, floe) inside that
    /// span. `1 − Σ ridge_ice / Σ ridge_envelope` is the ridge's porosity. Empty in records
    /// written before it was kept.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub ridge_envelope: Vec<f64>,
}

/// Ridge metrics of one state or of an averaged profile.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct RidgeMetrics {
    /// Largest rubble sail height (strip mean) (m).
    pub max_sail_height: f64,
    /// Largest rubble keel depth (strip mean) (m).
    pub max_keel_depth: f64,
    /// Sail cross-section of the rubble envelope (m²/m).
    pub sail_area: f64,
    /// Keel cross-section of the rubble envelope (m²/m).
    pub keel_area: f64,
    /// Solid rubble area above the water line (m²/m).
    pub sail_ice_area: f64,
    /// Solid rubble area below the water line (m²/m).
    pub keel_ice_area: f64,
    /// Lead-side sail slope θ₁ (degrees).
    pub sail_slope_lead: Option<f64>,
    /// Floe-side sail slope θ₂ (degrees).
    pub sail_slope_floe: Option<f64>,
    /// Lead-side keel slope φ₁ (degrees).
    pub keel_slope_lead: Option<f64>,
    /// Floe-side keel slope φ₂ (degrees).
    pub keel_slope_floe: Option<f64>,
    /// Mean rubble piece length over sheet thickness (dimensionless); 0 without rubble.
    pub length_to_thickness: f64,
}

/// Lowest and highest y (m) where the vertical line at `x` meets a convex polygon.
fn vertical_extent(v: &[V2], x: f64) -> Option<(f64, f64)> {
    let n = v.len();
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for i in 0..n {
        let (p, q) = (v[i], v[(i + 1) % n]);
        if (p.x <= x && x <= q.x) || (q.x <= x && x <= p.x) {
            let y = if (q.x - p.x).abs() < 1e-12 {
                lo = lo.min(p.y.min(q.y));
                hi = hi.max(p.y.max(q.y));
                continue;
            } else {
                p.y + (q.y - p.y) * (x - p.x) / (q.x - p.x)
            };
            lo = lo.min(y);
            hi = hi.max(y);
        }
    }
    (lo <= hi).then_some((lo, hi))
}

/// The profile of a state over `strips` strips of width `dx` (m) from `x0` (m), sampled on
/// `lines` vertical lines per strip: sail heights and keel depths in m, of all ice and of
/// rubble alone (see the module documentation, and [`metrics`] for an example).
pub fn profile(s: &Snapshot, x0: f64, dx: f64, strips: usize, lines: usize) -> Profile {
    let level = s.params.water.as_ref().map_or(0.0, |w| w.level);
    let outlines: Vec<(Role, Vec<V2>, f64, f64)> = s
        .bodies
        .iter()
        .filter(|b| b.role != Role::Wall && !b.drive.is_kinematic())
        .map(|b| {
            let o = b.world_outline();
            let v = o.verts().to_vec();
            let lo = v.iter().map(|p| p.x).fold(f64::INFINITY, f64::min);
            let hi = v.iter().map(|p| p.x).fold(f64::NEG_INFINITY, f64::max);
            (b.role, v, lo, hi)
        })
        .collect();
    let mut p = Profile {
        x0,
        dx,
        sail: vec![0.0; strips],
        keel: vec![0.0; strips],
        rubble_sail: vec![0.0; strips],
        rubble_keel: vec![0.0; strips],
        ridge_ice: vec![0.0; strips],
        ridge_envelope: vec![0.0; strips],
    };
    let lines = lines.max(1);
    // The intact ice's extents on the current line, to take out of the rubble column.
    let mut intact: Vec<(f64, f64)> = Vec::new();
    for k in 0..strips {
        for l in 0..lines {
            let x = x0 + (k as f64 + (l as f64 + 0.5) / lines as f64) * dx;
            let (mut top, mut bot) = (f64::NEG_INFINITY, f64::INFINITY);
            let (mut rtop, mut rbot) = (f64::NEG_INFINITY, f64::INFINITY);
            let mut solid = 0.0;
            intact.clear();
            for (role, v, lo, hi) in &outlines {
                if x < *lo || x > *hi {
                    continue;
                }
                if let Some((a, b)) = vertical_extent(v, x) {
                    top = top.max(b);
                    bot = bot.min(a);
                    if *role == Role::Rubble {
                        rtop = rtop.max(b);
                        rbot = rbot.min(a);
                        solid += b - a;
                    } else {
                        intact.push((a, b));
                    }
                }
            }
            let w = 1.0 / lines as f64;
            if top.is_finite() {
                p.sail[k] += w * (top - level).max(0.0);
                p.keel[k] += w * (level - bot).max(0.0);
            }
            if rtop.is_finite() {
                p.rubble_sail[k] += w * (rtop - level).max(0.0);
                p.rubble_keel[k] += w * (level - rbot).max(0.0);
                let inside: f64 = intact
                    .iter()
                    .map(|&(a, b)| (b.min(rtop) - a.max(rbot)).max(0.0))
                    .sum();
                p.ridge_ice[k] += w * solid;
                p.ridge_envelope[k] += w * (rtop - rbot - inside).max(solid);
            }
        }
    }
    p
}

/// The ridged ice of a profile in three numbers, kept at each sample time of a campaign
/// run (the whole distribution is kept for the final state, in its profile).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct RidgeSummary {
    /// Width of the strips that hold rubble (m).
    pub width: f64,
    /// Mean solid thickness of those strips (m): the ridged ice's volume over its area.
    pub mean_thickness: f64,
    /// Porosity of their rubble columns (dimensionless): 1 − Σ solid / Σ column.
    pub porosity: f64,
}

/// The ridged strips of profile `p`, those holding rubble, in strip order: (solid rubble
/// thickness, rubble-column thickness) (m), the column never below the solid. Empty when the
/// profile has no ridge columns (a record written before they were kept) or no rubble.
pub fn ridged_strips(p: &Profile) -> Vec<(f64, f64)> {
    p.ridge_ice
        .iter()
        .zip(&p.ridge_envelope)
        .filter(|(i, _)| **i > 0.0)
        .map(|(i, c)| (*i, c.max(*i)))
        .collect()
}

impl RidgeSummary {
    /// The summary of profile `p`; `None` when it has no ridge columns or no rubble.
    pub fn of(p: &Profile) -> Option<RidgeSummary> {
        Self::of_strips(&ridged_strips(p), p.dx)
    }

    /// The summary of ridged strips `(solid, column)` (m; as [`ridged_strips`] gives them)
    /// of width `dx` (m); `None` for none.
    pub fn of_strips(strips: &[(f64, f64)], dx: f64) -> Option<RidgeSummary> {
        if strips.is_empty() {
            return None;
        }
        let solid: f64 = strips.iter().map(|r| r.0).sum();
        let column: f64 = strips.iter().map(|r| r.1).sum();
        Some(RidgeSummary {
            width: strips.len() as f64 * dx,
            mean_thickness: solid / strips.len() as f64,
            porosity: 1.0 - solid / column,
        })
    }
}

/// The strip-by-strip mean of several profiles on the same strips (the ensemble profile).
pub fn mean_profile(ps: &[Profile]) -> Option<Profile> {
    let first = ps.first()?;
    let n = first.sail.len();
    if ps
        .iter()
        .any(|p| p.sail.len() != n || p.x0 != first.x0 || p.dx != first.dx)
    {
        return None;
    }
    let k = 1.0 / ps.len() as f64;
    let avg = |f: fn(&Profile) -> &Vec<f64>| -> Vec<f64> {
        (0..n)
            .map(|i| ps.iter().map(|p| f(p)[i]).sum::<f64>() * k)
            .collect()
    };
    // The ridge columns only where every profile has them (records before they were kept
    // have none).
    let ridged = ps
        .iter()
        .all(|p| p.ridge_ice.len() == n && p.ridge_envelope.len() == n);
    Some(Profile {
        x0: first.x0,
        dx: first.dx,
        sail: avg(|p| &p.sail),
        keel: avg(|p| &p.keel),
        rubble_sail: avg(|p| &p.rubble_sail),
        rubble_keel: avg(|p| &p.rubble_keel),
        ridge_ice: if ridged {
            avg(|p| &p.ridge_ice)
        } else {
            Vec::new()
        },
        ridge_envelope: if ridged {
            avg(|p| &p.ridge_envelope)
        } else {
            Vec::new()
        },
    })
}

/// The strip-by-strip sample standard deviation (n − 1; 0 for one profile) of several
/// profiles on the same strips (m): the seed spread around [`mean_profile`].
pub fn profile_spread(ps: &[Profile]) -> Option<Profile> {
    let mean = mean_profile(ps)?;
    let n = mean.sail.len();
    let k = if ps.len() > 1 {
        1.0 / (ps.len() - 1) as f64
    } else {
        0.0
    };
    let sd = |f: fn(&Profile) -> &Vec<f64>| -> Vec<f64> {
        (0..n)
            .map(|i| {
                let m = f(&mean)[i];
                (ps.iter().map(|p| (f(p)[i] - m).powi(2)).sum::<f64>() * k).sqrt()
            })
            .collect()
    };
    Some(Profile {
        x0: mean.x0,
        dx: mean.dx,
        sail: sd(|p| &p.sail),
        keel: sd(|p| &p.keel),
        rubble_sail: sd(|p| &p.rubble_sail),
        rubble_keel: sd(|p| &p.rubble_keel),
        ridge_ice: if mean.ridge_ice.is_empty() {
            Vec::new()
        } else {
            sd(|p| &p.ridge_ice)
        },
        ridge_envelope: if mean.ridge_envelope.is_empty() {
            Vec::new()
        } else {
            sd(|p| &p.ridge_envelope)
        },
    })
}

/// Flank slopes (degrees) of a strip profile: (lead side, floe side); see the module docs.
pub(crate) fn flank_slopes(values: &[f64], x0: f64, dx: f64) -> (Option<f64>, Option<f64>) {
    let Some((peak_i, &peak)) = values.iter().enumerate().max_by(|a, b| a.1.total_cmp(b.1)) else {
        return (None, None);
    };
    if peak <= 0.0 {
        return (None, None);
    }
    let side = |dir: isize| {
        let mut pts = Vec::new();
        let mut i = peak_i as isize;
        loop {
            i += dir;
            if i < 0 || i as usize >= values.len() {
                break;
            }
            let v = values[i as usize];
            if v < 0.2 * peak {
                break;
            }
            if v <= 0.8 * peak {
                pts.push((x0 + (i as f64 + 0.5) * dx, v));
            }
        }
        if pts.len() < 2 {
            return None;
        }
        let n = pts.len() as f64;
        let mx = pts.iter().map(|p| p.0).sum::<f64>() / n;
        let my = pts.iter().map(|p| p.1).sum::<f64>() / n;
        let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
        let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
        (sxx > 0.0).then(|| (sxy / sxx).abs().atan().to_degrees())
    };
    (side(-1), side(1))
}

/// Metrics of a profile, with the solid rubble areas and piece lengths of the state they
/// came from (`None` for an averaged profile: those fields are then 0 and should be
/// averaged from the runs). `state` is the state, its rubble piece lengths (m; the run
/// summary's `rubble_block_lengths`) and the sheet thickness (m).
///
/// ```
/// use pressridge_sim::{observe, scene::Scene, simulation};
///
/// // A 3 m sheet (0.30 m thick) pushed against a 4 m floe for 3 s.
/// let scene = Scene::from_toml("duration = 3.0\n[sheet]\nlength = 3.0\n[floe]\nlength = 4.0")?;
/// let out = simulation::run(&scene, &mut |_| true)?;
/// // The profile in 32 strips of 1 m from x = -20 m, 10 sample lines a strip (the
/// // defaults of a campaign's `[profile]`): sail heights and keel depths in m.
/// let p = observe::profile(&out.final_state, -20.0, 1.0, 32, 10);
/// assert_eq!(p.keel.len(), 32);
/// let lengths = &out.summary.rubble_block_lengths;
/// let m = observe::metrics(&p, Some((&out.final_state, lengths, 0.30)));
/// println!(
///     "sail {:.2} m, keel {:.2} m, rubble below water {:.3} m²/m, L/h = {:.1}",
///     m.max_sail_height, m.max_keel_depth, m.keel_ice_area, m.length_to_thickness,
/// );
/// // Flank slopes (degrees) need two strips between 20 % and 80 % of the peak: None here.
/// println!("keel slopes {:?}, {:?}", m.keel_slope_lead, m.keel_slope_floe);
/// assert!(m.max_keel_depth > 0.0 && m.keel_ice_area > 0.0); // rubble went under the floe
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn metrics(p: &Profile, state: Option<(&Snapshot, &[f64], f64)>) -> RidgeMetrics {
    let max = |v: &[f64]| v.iter().copied().fold(0.0, f64::max);
    let (sail_slope_lead, sail_slope_floe) = flank_slopes(&p.rubble_sail, p.x0, p.dx);
    let (keel_slope_lead, keel_slope_floe) = flank_slopes(&p.rubble_keel, p.x0, p.dx);
    let mut m = RidgeMetrics {
        max_sail_height: max(&p.rubble_sail),
        max_keel_depth: max(&p.rubble_keel),
        sail_area: p.rubble_sail.iter().sum::<f64>() * p.dx,
        keel_area: p.rubble_keel.iter().sum::<f64>() * p.dx,
        sail_slope_lead,
        sail_slope_floe,
        keel_slope_lead,
        keel_slope_floe,
        ..RidgeMetrics::default()
    };
    if let Some((s, lengths, thickness)) = state {
        let level = s.params.water.as_ref().map_or(0.0, |w| w.level);
        for b in s.bodies.iter().filter(|b| b.role == Role::Rubble) {
            let (below, _) = crate::dem::below_line(&b.world_outline(), level);
            m.keel_ice_area += below;
            m.sail_ice_area += b.shape.area() - below;
        }
        if !lengths.is_empty() && thickness > 0.0 {
            m.length_to_thickness = lengths.iter().sum::<f64>() / lengths.len() as f64 / thickness;
        }
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slopes_of_a_triangle() {
        // A sail rising 1 m per strip (45°) to 5 m, falling 0.5 m per strip (26.6°).
        let v = [
            0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 4.5, 4.0, 3.5, 3.0, 2.5, 2.0, 1.5, 1.0, 0.5, 0.0,
        ];
        let (lead, floe) = flank_slopes(&v, -8.0, 1.0);
        assert!((lead.unwrap() - 45.0).abs() < 1e-9);
        assert!((floe.unwrap() - 0.5f64.atan().to_degrees()).abs() < 1e-9);
        assert_eq!(flank_slopes(&[0.0; 4], 0.0, 1.0), (None, None));
    }

    #[test]
    fn spread_of_two_profiles() {
        let p = |v: f64| Profile {
            x0: -1.0,
            dx: 1.0,
            sail: vec![v, 2.0 * v],
            keel: vec![v; 2],
            rubble_sail: vec![0.0; 2],
            rubble_keel: vec![v; 2],
            ridge_ice: Vec::new(),
            ridge_envelope: Vec::new(),
        };
        let m = mean_profile(&[p(1.0), p(3.0)]).unwrap();
        let s = profile_spread(&[p(1.0), p(3.0)]).unwrap();
        assert_eq!(m.sail, vec![2.0, 4.0]);
        assert_eq!(s.sail, vec![2f64.sqrt(), 8f64.sqrt()]);
        assert_eq!(s.rubble_sail, vec![0.0; 2]);
        assert_eq!(profile_spread(&[p(1.0)]).unwrap().keel, vec![0.0; 2]);
    }

    /// A floe 2 m thick with rubble on it (two 0.3-m pieces, 0.1 m apart) and under it (one):
    /// the solid rubble is 0.9 m, its column 3.0 m less the floe's 2.0 m = 1.0 m, so the
    /// porosity is the 0.1-m gap over 1.0 m; outside the rubble both are 0.
    #[test]
    fn ridge_columns_of_rubble_stacked_around_a_floe() {
        use crate::dem::{Block, Drive, World, WorldParams};
        let mut w = World::new(WorldParams::default()).unwrap();
        let rect = |width, thickness| Block {
            width,
            thickness,
            bevel: [0.0; 4],
            bevel_run: None,
        };
        let mut add = |b: Block, x: f64, y: f64, role| {
            w.add_rect(b, V2::new(x, y), 0.0, Drive::FREE, role)
                .unwrap();
        };
        add(rect(8.0, 2.0), 4.0, -0.8, Role::Floe);
        add(rect(4.0, 0.3), 2.0, 0.35, Role::Rubble);
        add(rect(4.0, 0.3), 2.0, 0.75, Role::Rubble);
        add(rect(4.0, 0.3), 2.0, -1.95, Role::Rubble);
        let p = profile(&w.snapshot(), 0.0, 1.0, 6, 10);
        for k in 0..4 {
            assert!(
                (p.ridge_ice[k] - 0.9).abs() < 1e-12,
                "{k}: {:?}",
                p.ridge_ice
            );
            assert!(
                (p.ridge_envelope[k] - 1.0).abs() < 1e-12,
                "{:?}",
                p.ridge_envelope
            );
        }
        assert_eq!(&p.ridge_ice[4..], &[0.0, 0.0]);
        assert_eq!(&p.ridge_envelope[4..], &[0.0, 0.0]);
        assert_eq!(ridged_strips(&p).len(), 4);
        let s = RidgeSummary::of(&p).unwrap();
        assert_eq!(s.width, 4.0);
        assert!((s.mean_thickness - 0.9).abs() < 1e-12 && (s.porosity - 0.1).abs() < 1e-12);
        assert_eq!(RidgeSummary::of(&Profile::default()), None);
    }

    #[test]
    fn vertical_extent_of_a_square() {
        let sq = [
            V2::new(0.0, -1.0),
            V2::new(1.0, -1.0),
            V2::new(1.0, 0.5),
            V2::new(0.0, 0.5),
        ];
        assert_eq!(vertical_extent(&sq, 0.5), Some((-1.0, 0.5)));
        assert_eq!(vertical_extent(&sq, 2.0), None);
    }
}
