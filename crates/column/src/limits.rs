//! The valid ranges of what a host passes to the column physics, each a named constant with
//! its reason, so that a check and its message are one fact. The simulator's own ranges (of a
//! scene, a campaign) are `pressridge::limits`, built on the same [`Range`].

/// The valid range of a parameter: bounds, unit and the reason for them, so that the check
/// and its message are one fact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Range {
    /// Smallest valid value.
    pub min: f64,
    /// Whether `min` itself is valid (else the range is open there).
    pub min_inclusive: bool,
    /// Largest valid value (inclusive).
    pub max: f64,
    /// Unit, for messages (`m`, `Pa`, ...; empty when dimensionless).
    pub unit: &'static str,
    /// Why these bounds.
    pub why: &'static str,
}

impl Range {
    /// Whether `v` lies in the range (never for NaN).
    pub fn contains(&self, v: f64) -> bool {
        (if self.min_inclusive {
            v >= self.min
        } else {
            v > self.min
        }) && v <= self.max
    }

    /// The range as text, e.g. `(0, 5] m/s`.
    pub fn describe(&self) -> String {
        let unit = if self.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", self.unit)
        };
        format!(
            "{}{}, {}]{unit}",
            if self.min_inclusive { "[" } else { "(" },
            self.min,
            self.max
        )
    }

    /// `None` when `value` lies in the range, else why not: the value, the range and its
    /// reason, e.g. `1000000 is out of range: must lie in (0, 5] m/s (...)`.
    pub fn violation(&self, value: f64) -> Option<String> {
        (!self.contains(value)).then(|| format!("{value} is out of range: {}", self.rule()))
    }

    /// The rule with its reason, e.g. `must lie in (0, 5] m/s (...)`.
    pub fn rule(&self) -> String {
        format!("must lie in {} ({})", self.describe(), self.why)
    }
}

/// Frictional factor C_f of the Rothrock strength (dimensionless, the ratio of ridging work
/// to potential-energy gain): the work pays for the gain and for what friction dissipates,
/// so C_f ≥ 1; published values are 2 (Hibler 1980) to 17 (CICE), and above 1000 W/ΔPE
/// has no physical meaning (and products of it overflow no sooner). The lower bound also
/// keeps interpolated table values off subnormal numbers that round to 0.
pub const CF: Range = Range {
    min: 1.0,
    min_inclusive: true,
    max: 1000.0,
    unit: "",
    why: "ridging work includes the potential-energy gain, so C_f >= 1; published values are \
          2-17, and above 1000 W/ΔPE has no physical meaning",
};
/// Mean thickness of a category of a gridded thickness distribution, vicen / aicen: no
/// sea ice is thicker than some tens of metres (the deepest ridge keels reach ~50 m);
/// 1000 m keeps squares and exponentials of it finite.
pub const CATEGORY_THICKNESS: Range = Range {
    min: 0.0,
    min_inclusive: true,
    max: 1000.0,
    unit: "m",
    why: "the deepest ridge keels reach ~50 m",
};

/// Lipscomb's e-folding parameter μ_rdg of a μ_rdg table (m^½; λ = μ_rdg·√h): published
/// values are 3–5 (Icepack 3, its science guide 4), the simulated ridges 1–3; 50 m^½ gives
/// 1-m ice an e-folding ridge thickness of 50 m, beyond any ridge.
pub const MU_RDG: Range = Range {
    min: 0.0,
    min_inclusive: false,
    max: 50.0,
    unit: "m^0.5",
    why: "published values are 3-5 m^0.5 and simulated ridges give 1-3; 50 m^0.5 puts the \
          e-folding thickness of 1-m ice at 50 m, beyond any ridge",
};
