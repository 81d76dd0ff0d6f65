//! Which runs make one set of the table: the same scene apart from the thickness (and the
//! block width tied to it), the keys scaled with it, the seed and the name; a run recorded
//! twice is counted once, and two runs of one set and thickness must agree in the scaled
//! keys.

use super::{TabulateError, is_friction_key, is_thickness_key, key_values};
use crate::record::RunRecord;

/// The runs of a tabulation grouped into sets.
pub(super) struct Sets<'r> {
    /// Each set's label: its friction pair and the settings that tell it from the others.
    pub sets: Vec<String>,
    /// Each set's μ and μ_w (dimensionless).
    pub mu: Vec<f64>,
    pub mu_w: Vec<f64>,
    /// The thicknesses met (m), ascending.
    pub thickness: Vec<f64>,
    /// The seeds met, ascending.
    pub seeds: Vec<u64>,
    /// (run, the run it duplicates) for each run recorded twice.
    pub duplicates: Vec<(String, String)>,
    /// The scaled keys' values of each (set, thickness bits) met, with the run that set them.
    pub scaled_seen: Vec<(usize, u64, Vec<String>, &'r RunRecord)>,
    /// The set of each kept run, in the order of `runs`.
    pub set_index: Vec<usize>,
    /// The runs kept (duplicates left out).
    pub runs: Vec<&'r RunRecord>,
}

impl<'r> Sets<'r> {
    /// Groups `recs` (runs with a sheet and at least two samples) into sets, with `scaled`
    /// the keys that vary with the thickness within a set.
    pub fn of(recs: Vec<&'r RunRecord>, scaled: &[String]) -> Result<Sets<'r>, TabulateError> {
        // A set is what the scene is apart from the thickness (and the block width tied to it),
        // the keys scaled with it, the seed and the name.
        let set_key = |r: &RunRecord| {
            let mut sc = r.scene.clone();
            sc.seed = 0;
            sc.name.clear();
            if let Some(sh) = sc.sheet.as_mut() {
                sh.thickness = 0.0;
                sh.block_width = 0.0;
            }
            if scaled.is_empty() {
                return sc.to_toml();
            }
            sc.toml_without(scaled)
        };
        // The values of the scaled keys of a run, in their order.
        let scaled_of = |r: &RunRecord| -> Vec<String> {
            scaled
                .iter()
                .map(|k| r.scene.value_at(k).unwrap_or_else(|| "-".into()))
                .collect()
        };
        // The whole scene but its name: two records of one run must agree in it.
        let whole = |r: &RunRecord| {
            let mut sc = r.scene.clone();
            sc.name.clear();
            sc.to_toml()
        };
        let is_scaled_setting = |s: &str| {
            crate::scene::split_override(s).is_some_and(|(k, _)| scaled.iter().any(|x| x == k))
        };
        let h_of = |r: &RunRecord| r.scene.sheet.as_ref().expect("filtered").thickness;
        let mut keys: Vec<String> = Vec::new();
        let mut sets: Vec<String> = Vec::new();
        let (mut mu, mut mu_w) = (Vec::new(), Vec::new());
        let mut thickness: Vec<f64> = Vec::new();
        let mut seeds: Vec<u64> = Vec::new();
        let mut duplicates = Vec::new();
        let mut seen: Vec<(usize, u64, u64, &RunRecord)> = Vec::new();
        // The scaled values of each (set, thickness) met, with the run that set them.
        let mut scaled_seen: Vec<(usize, u64, Vec<String>, &RunRecord)> = Vec::new();
        let mut set_index = Vec::with_capacity(recs.len());
        let mut kept = Vec::with_capacity(recs.len());
        for r in recs {
            let key = set_key(r);
            let si = match keys.iter().position(|k| *k == key) {
                Some(si) => si,
                None => {
                    keys.push(key);
                    let c = &r.scene.contact;
                    let mut label = vec![format!("mu={}, mu_w={}", c.mu, c.mu_water)];
                    label.extend(
                        r.settings
                            .iter()
                            .filter(|s| {
                                !is_thickness_key(s) && !is_friction_key(s) && !is_scaled_setting(s)
                            })
                            .cloned(),
                    );
                    sets.push(label.join(", "));
                    mu.push(c.mu);
                    mu_w.push(c.mu_water);
                    keys.len() - 1
                }
            };
            let h = h_of(r);
            if let Some(&(.., first)) = seen
                .iter()
                .find(|&&(s, hb, seed, _)| s == si && hb == h.to_bits() && seed == r.seed)
            {
                if whole(first) != whole(r) {
                    return Err(TabulateError::Conflict(
                        first.id.clone(),
                        r.id.clone(),
                        format!("have the same seed {} and different scenes", r.seed),
                    ));
                }
                duplicates.push((r.id.clone(), first.id.clone()));
                continue;
            }
            seen.push((si, h.to_bits(), r.seed, r));
            let values = scaled_of(r);
            match scaled_seen
                .iter()
                .find(|&&(s, hb, ..)| s == si && hb == h.to_bits())
            {
                Some((.., v, first)) if *v != values => {
                    return Err(TabulateError::Conflict(
                        first.id.clone(),
                        r.id.clone(),
                        format!(
                            "differ in the keys scaled with the thickness ({} against {})",
                            key_values(scaled, v),
                            key_values(scaled, &values)
                        ),
                    ));
                }
                Some(_) => {}
                None => scaled_seen.push((si, h.to_bits(), values, r)),
            }
            if !thickness.contains(&h) {
                thickness.push(h);
            }
            if !seeds.contains(&r.seed) {
                seeds.push(r.seed);
            }
            set_index.push(si);
            kept.push(r);
        }
        thickness.sort_by(f64::total_cmp);
        seeds.sort_unstable();
        Ok(Sets {
            sets,
            mu,
            mu_w,
            thickness,
            seeds,
            duplicates,
            scaled_seen,
            set_index,
            runs: kept,
        })
    }
}
