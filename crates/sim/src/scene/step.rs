//! The step scheme of a scene ([`StepScheme`]): the part of [`NumericsSection`] that says how
//! long a step is and where it is refined, which an ensemble must not mix
//! (docs/speed-vs-error.md).

use super::NumericsSection;
use crate::dem::DEFAULT_REFINE_FRACTION;
use std::fmt;

/// How a scene steps: the safety factor on the stable limit and the refinements around
/// fracture and impacts, each as [`NumericsSection`] documents it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepScheme {
    /// `numerics.time_step_safety` (dimensionless).
    pub time_step_safety: f64,
    /// `numerics.refine_window` (s), or off.
    pub refine_window: Option<f64>,
    /// `numerics.refine_load` (dimensionless), or off.
    pub refine_load: Option<f64>,
    /// `numerics.refine_impact` (m/s), or off.
    pub refine_impact: Option<f64>,
    /// `numerics.refine_fraction` (dimensionless), or the default quarter.
    pub refine_fraction: Option<f64>,
}

impl StepScheme {
    /// The keys of [`NumericsSection`] that make the scheme, as a scene names them.
    pub const KEYS: [&'static str; 5] = [
        "time_step_safety",
        "refine_window",
        "refine_load",
        "refine_impact",
        "refine_fraction",
    ];
}

impl NumericsSection {
    /// This section's step scheme.
    pub fn step_scheme(&self) -> StepScheme {
        StepScheme {
            time_step_safety: self.time_step_safety,
            refine_window: self.refine_window,
            refine_load: self.refine_load,
            refine_impact: self.refine_impact,
            refine_fraction: self.refine_fraction,
        }
    }

    /// Sets this section's step scheme to `s`.
    pub fn set_step_scheme(&mut self, s: StepScheme) {
        self.time_step_safety = s.time_step_safety;
        self.refine_window = s.refine_window;
        self.refine_load = s.refine_load;
        self.refine_impact = s.refine_impact;
        self.refine_fraction = s.refine_fraction;
    }
}

impl fmt::Display for StepScheme {
    /// E.g. "0.5 of the stable limit" or "the full stable limit, refined to 0.25 of it
    /// (window 0.05 s, load 0.9, impacts 0.6 m/s)".
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.time_step_safety == 1.0 {
            write!(f, "the full stable limit")?;
        } else {
            write!(f, "{} of the stable limit", self.time_step_safety)?;
        }
        let mut parts = vec![];
        if let Some(w) = self.refine_window {
            parts.push(format!("window {w} s"));
        }
        if let Some(l) = self.refine_load {
            parts.push(format!("load {l}"));
        }
        if let Some(v) = self.refine_impact.filter(|_| self.refine_window.is_some()) {
            parts.push(format!("impacts {v} m/s"));
        }
        if parts.is_empty() {
            return Ok(());
        }
        let q = self.refine_fraction.unwrap_or(DEFAULT_REFINE_FRACTION);
        write!(f, ", refined to {q} of it ({})", parts.join(", "))
    }
}
