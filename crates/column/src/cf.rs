//! The frictional factor C_f of the Rothrock (1975) strength: the ratio of the total work
//! done in ridging (friction included) to the change in potential energy.
//!
//! C_f is either a constant — Hibler (1980) used 2, Flato (1991) 15, CICE/Icepack's default
//! `Cf` is 17 — or a function of the thickness of the ice in the ridging category, supplied
//! by a lookup table (the tabulation issue fills it with the simulator's work ratios).

use std::sync::Arc;

use super::ItdError;
use crate::limits;

/// Named constant values of C_f (dimensionless).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CfPreset {
    /// Hibler (1980): C_f = 2.
    Hibler1980,
    /// Flato (1991): C_f = 15.
    Flato1991,
    /// CICE/Icepack default `Cf` = 17.
    Cice,
}

impl CfPreset {
    /// The value of the preset (dimensionless).
    pub fn value(self) -> f64 {
        match self {
            CfPreset::Hibler1980 => 2.0,
            CfPreset::Flato1991 => 15.0,
            CfPreset::Cice => 17.0,
        }
    }
}

/// A C_f lookup result: the value (dimensionless) and whether the thickness lay outside the
/// table so that the value was clamped to the nearest end.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CfLookup {
    /// C_f (dimensionless).
    pub value: f64,
    /// True when the thickness was outside the table's range.
    pub clamped: bool,
}

/// Anything that gives C_f (dimensionless) as a function of the ridging category's ice
/// thickness (m). Implementations must be cheap and thread-safe.
pub trait CfProvider: Send + Sync + std::fmt::Debug {
    /// C_f for ridging ice of thickness `h_ridging_category` (m).
    fn cf(&self, h_ridging_category: f64) -> f64 {
        self.lookup(h_ridging_category).value
    }
    /// C_f with the out-of-range flag.
    fn lookup(&self, h_ridging_category: f64) -> CfLookup;
}

/// A piecewise-linear table of C_f (dimensionless) against ridging-ice thickness (m).
///
/// Between nodes the value is interpolated linearly; outside `[thickness[0], thickness[last]]`
/// it is clamped to the end value and the lookup is flagged `clamped`.
#[derive(Debug, Clone, PartialEq)]
pub struct CfTable {
    thickness: Vec<f64>,
    cf: Vec<f64>,
    friction: Option<(f64, f64)>,
}

impl CfTable {
    /// Builds a table from node thicknesses (m; strictly increasing, in
    /// [`limits::CATEGORY_THICKNESS`]) and C_f values (dimensionless, in [`limits::CF`]).
    /// At least one node.
    pub fn new(thickness: Vec<f64>, cf: Vec<f64>) -> Result<Self, ItdError> {
        super::nodes::check(&thickness, "cf", &cf, limits::CF).map_err(ItdError::CfTable)?;
        Ok(Self {
            thickness,
            cf,
            friction: None,
        })
    }

    /// A table from nodes some of which may have no data, the one rule of every reader of
    /// C_f (a `thickness`/`cf` file, a ridging table's `cf_by_set`): a NaN C_f marks a
    /// thickness no run reached and that node is left out; every other value must be finite
    /// and positive, as in [`CfTable::new`], and at least one node must remain.
    pub fn from_nodes(thickness: &[f64], cf: &[f64]) -> Result<Self, ItdError> {
        let (h, c) = super::nodes::known(thickness, "cf", cf).map_err(ItdError::CfTable)?;
        Self::new(h, c)
    }

    /// The same table labelled with the friction pair of the simulations behind it: μ above
    /// and μ_w below the water line (dimensionless). Shown by [`Cf::describe`], so every
    /// output that records its C_f says which friction it assumed.
    pub fn with_friction(mut self, mu: f64, mu_w: f64) -> Self {
        self.friction = Some((mu, mu_w));
        self
    }

    /// The friction pair (μ, μ_w) of the table (dimensionless), when known.
    pub fn friction(&self) -> Option<(f64, f64)> {
        self.friction
    }

    /// Node thicknesses (m).
    pub fn thickness(&self) -> &[f64] {
        &self.thickness
    }

    /// Node values of C_f (dimensionless).
    pub fn values(&self) -> &[f64] {
        &self.cf
    }
}

impl CfProvider for CfTable {
    fn lookup(&self, h: f64) -> CfLookup {
        let (value, clamped) = super::nodes::lookup(&self.thickness, &self.cf, h);
        CfLookup { value, clamped }
    }
}

/// The C_f used by the Rothrock strength.
#[derive(Debug, Clone)]
pub enum Cf {
    /// A constant (dimensionless); gives CICE's numbers to the bit.
    Constant(f64),
    /// A piecewise-linear table in the ridging-category thickness.
    Table(Arc<CfTable>),
    /// Any other provider.
    Custom(Arc<dyn CfProvider>),
}

impl Default for Cf {
    /// CICE's default, C_f = 17.
    fn default() -> Self {
        Cf::Constant(CfPreset::Cice.value())
    }
}

impl From<CfPreset> for Cf {
    fn from(p: CfPreset) -> Self {
        Cf::Constant(p.value())
    }
}

impl Cf {
    /// A short description for NetCDF attributes and logs.
    pub fn describe(&self) -> String {
        match self {
            Cf::Constant(c) => format!("constant {c}"),
            Cf::Table(t) => format!(
                "table of {} nodes, thickness {} to {} m{}",
                t.thickness.len(),
                t.thickness[0],
                t.thickness[t.thickness.len() - 1],
                match t.friction {
                    Some((mu, mu_w)) => format!(", friction mu = {mu}, mu_w = {mu_w}"),
                    None => String::new(),
                }
            ),
            Cf::Custom(p) => format!("custom provider {p:?}"),
        }
    }

    pub(crate) fn validate(&self) -> Result<(), ItdError> {
        if let Cf::Constant(c) = *self
            && !limits::CF.contains(c)
        {
            return Err(ItdError::Parameter {
                name: "cf",
                value: c,
                reason: limits::CF.rule().into(),
            });
        }
        Ok(())
    }
}
