//! The contacts' diagnostics over a run: the restitution of their impacts and their damping
//! ratios, as histograms (deterministic, of fixed size, carried in saved states).

use super::Contact;
use serde::{Deserialize, Serialize};

/// Largest duration of a contact counted as an impact for the restitution tally (s): a
/// contact of the pile rings with a half period of 5–30 ms; one that lasts longer is a
/// resting or sliding contact.
pub(crate) const IMPACT_DURATION: f64 = 0.1;

/// Least approach speed of a contact counted as an impact (m/s).
pub(crate) const IMPACT_SPEED: f64 = 0.01;

/// Bins of restitution, in [0, 1.5).
const RESTITUTION_BINS: usize = 150;
/// Width of a restitution bin (dimensionless).
const RESTITUTION_BIN: f64 = 0.01;
/// Bins of log₁₀ ζ, in [−3, 2).
const ZETA_BINS: usize = 500;
/// log₁₀ ζ at the first bin's lower edge.
const ZETA_LOG_MIN: f64 = -3.0;
/// Width of a log₁₀ ζ bin: 2.3 % in ζ.
const ZETA_LOG_BIN: f64 = 0.01;

/// Histograms of the contacts' restitution at impacts and of their damping ratios, for
/// the run summary (`crate::simulation::ContactSummary`).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ContactTally {
    /// Impacts (contacts born by approach at ≥ 1 cm/s that ended within 0.1 s) by
    /// restitution e = v_out/v_in, in bins of 0.01 from 0 (the last bin holds e ≥ 1.49).
    pub restitution: Vec<u64>,
    /// Active contacts, counted at each tally ([`crate::dem::World::tally_contacts`]), by
    /// log₁₀ ζ in bins of 0.01 from −3 (the first and last bins hold what lies beyond).
    pub zeta: Vec<u64>,
}

impl ContactTally {
    fn add_restitution(&mut self, e: f64) {
        if self.restitution.is_empty() {
            self.restitution = vec![0; RESTITUTION_BINS];
        }
        let k = ((e / RESTITUTION_BIN).floor().max(0.0) as usize).min(RESTITUTION_BINS - 1);
        self.restitution[k] += 1;
    }
    pub(crate) fn add_zeta(&mut self, z: f64) {
        if z.is_nan() || z <= 0.0 {
            return;
        }
        if self.zeta.is_empty() {
            self.zeta = vec![0; ZETA_BINS];
        }
        let k = ((z.log10() - ZETA_LOG_MIN) / ZETA_LOG_BIN).floor();
        let k = (k.max(0.0) as usize).min(ZETA_BINS - 1);
        self.zeta[k] += 1;
    }
    /// The 10th, 50th and 90th percentiles of the impacts' restitution (to the bin, 0.01),
    /// or `None` without impacts.
    pub fn restitution_percentiles(&self) -> Option<[f64; 3]> {
        percentiles(&self.restitution, |k| k * RESTITUTION_BIN)
    }

    /// The 10th, 50th and 90th percentiles of the contacts' damping ratios (to the bin, a
    /// hundredth of a decade), or `None` without contacts.
    pub fn damping_ratio_percentiles(&self) -> Option<[f64; 3]> {
        percentiles(&self.zeta, |k| 10f64.powf(ZETA_LOG_MIN + k * ZETA_LOG_BIN))
    }

    /// Records the end of contact `c` (it separated): an impact's restitution.
    pub(super) fn ended(&mut self, c: &Contact, dt: f64) {
        if c.approach >= IMPACT_SPEED && f64::from(c.steps) * dt <= IMPACT_DURATION {
            self.add_restitution(c.vn.max(0.0) / c.approach);
        }
    }
}

/// The 10th, 50th and 90th percentiles of a histogram `counts` whose bin k spans
/// [edge(k), edge(k + 1)), interpolated linearly in the bin's coordinate; `None` when it is
/// empty.
fn percentiles(counts: &[u64], edge: impl Fn(f64) -> f64) -> Option<[f64; 3]> {
    let total: u64 = counts.iter().sum();
    if total == 0 {
        return None;
    }
    Some([0.1, 0.5, 0.9].map(|q| {
        let want = q * total as f64;
        let mut below = 0.0;
        for (k, &c) in counts.iter().enumerate() {
            let c = c as f64;
            if c > 0.0 && below + c >= want {
                return edge(k as f64 + (want - below) / c);
            }
            below += c;
        }
        edge(counts.len() as f64)
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Percentiles interpolate within the bins; an empty tally has none.
    #[test]
    fn percentiles_of_the_histograms() {
        let mut t = ContactTally::default();
        assert_eq!(t.restitution_percentiles(), None);
        for e in [
            0.115, 0.125, 0.135, 0.145, 0.415, 0.425, 0.435, 0.445, 0.465, 0.905,
        ] {
            t.add_restitution(e);
        }
        // One in each bin of [0.11, 0.15) and of [0.41, 0.45), one in [0.46, 0.47), one at
        // 0.905: the 10th percentile is the end of the first bin, the median the end of the
        // fifth value's, the 90th the end of the ninth's.
        let [p10, p50, p90] = t.restitution_percentiles().unwrap();
        assert!((p10 - 0.12).abs() < 1e-12, "{p10}");
        assert!((p50 - 0.42).abs() < 1e-12, "{p50}");
        assert!((p90 - 0.47).abs() < 1e-12, "{p90}");
        t.add_zeta(0.5);
        // log₁₀ 0.5 = −0.30103 lies in the bin [10^−0.31, 10^−0.30) = [0.490, 0.501).
        let z = t.damping_ratio_percentiles().unwrap();
        assert!(z.iter().all(|&x| (0.489..0.502).contains(&x)), "{z:?}");
    }
}
