//! A world's physical and numerical parameters ([`WorldParams`], with their units, defaults
//! and checks) and the errors of building and stepping a world ([`WorldError`]).

use super::super::body::ShapeError;
use super::super::contact::ContactParams;
use super::super::numerics::{ContactOnset, Dashpot, off_or_number};
use super::super::water::WaterParams;
use serde::{Deserialize, Serialize};

/// Physical and numerical parameters of a world.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct WorldParams {
    /// Acceleration of gravity g (m/s²). Default 9.81.
    pub gravity: f64,
    /// Ice density ρ_i (kg/m³). Default 920 (Hopkins 1994, Table 1).
    pub ice_density: f64,
    /// Contact law, eqs (2)–(4).
    pub contact: ContactParams,
    /// The water, or `None` for a dry scene (no buoyancy, no drag, μ everywhere).
    pub water: Option<WaterParams>,
    /// Safety factor on the stable time step of [`World::stable_time_step`](super::World::stable_time_step)
    /// (dimensionless, in (0, 1]). Default [`DEFAULT_TIME_STEP_SAFETY`].
    pub time_step_safety: f64,
    /// A fixed time step (s) overriding the derived one, or `None`. It must not exceed the
    /// stable limit of [`World::stable_time_step`](super::World::stable_time_step).
    pub time_step: Option<f64>,
    /// How the viscous normal force of eq (3) is advanced in time. Default
    /// [`Dashpot::Implicit`].
    #[serde(default)]
    pub contact_dashpot: Dashpot,
    /// How the joints' viscous stress of eq (1) is advanced in time. Default
    /// [`Dashpot::Explicit`] (the paper's form, at the half-step velocities); `Implicit`
    /// centres it at the mid-step velocities (see `Joint::apply_viscous` and
    /// docs/model.md, "Joint dashpot in time"). Absent from states and scenes when explicit.
    #[serde(
        default = "Dashpot::explicit",
        skip_serializing_if = "Dashpot::is_explicit"
    )]
    pub joint_dashpot: Dashpot,
    /// How a new contact reads its first overlap rate in eq (3). Default
    /// [`ContactOnset::Area`] (the paper's). Absent from states and scenes when the default.
    #[serde(default, skip_serializing_if = "ContactOnset::is_area")]
    pub contact_onset: ContactOnset,
    /// Gauss–Seidel sweeps of the implicit contact dashpot (dimensionless count, at most
    /// [`MAX_CONTACT_DASHPOT_SWEEPS`]). Default 0: each contact's viscous force is solved
    /// with the other contacts' viscous and friction forces left out (a Jacobi step, as
    /// [`Dashpot::Implicit`] describes); n ≥ 1 sweeps the contacts n times in order, each
    /// seeing the others' latest viscous and friction forces, towards the coupled solution
    /// for a block with several contacts (docs/model.md, "Several contacts on one block");
    /// absent from states and scenes when 0.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub contact_dashpot_sweeps: u32,
    /// Speed at which a crack crosses a joint (m/s). Default 50 m/s; see
    /// docs/model.md ("Fracture").
    pub crack_speed: f64,
    /// Incubation time of crack initiation (s), or `None` for the paper's instantaneous
    /// test; see [`crate::scene::JointSection::incubation_time`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub incubation_time: Option<f64>,
    /// Test fracture on the mean of the elastic stresses of the last two poses instead of
    /// the last one; see [`crate::scene::NumericsSection::fracture_step_mean`].
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub fracture_step_mean: bool,
    /// A refined step around fracture: while a joint is cracking, and for this long (s)
    /// after a joint severs, the world steps by [`WorldParams::refine_fraction`] of its
    /// step; `None` ("off") steps by the one step throughout. Default
    /// [`DEFAULT_REFINE_WINDOW`]. See [`crate::scene::NumericsSection::refine_window`].
    #[serde(with = "off_or_number")]
    pub refine_window: Option<f64>,
    /// A refined step ahead of fracture: while some intact joint's tested stress exceeds this
    /// fraction of its strength (dimensionless, in (0, 1]) the world steps by
    /// [`WorldParams::refine_fraction`] of its step; `None` ("off"): no such refinement.
    /// Default [`DEFAULT_REFINE_LOAD`]. See [`crate::scene::NumericsSection::refine_load`].
    #[serde(with = "off_or_number")]
    pub refine_load: Option<f64>,
    /// A refined step after impacts: with [`WorldParams::refine_window`], a contact born
    /// with an approach speed above this (m/s) refines the step for that window as a
    /// severed joint does; `None` ("off"): no such refinement. Default
    /// [`DEFAULT_REFINE_IMPACT`]. See [`crate::scene::NumericsSection::refine_impact`].
    #[serde(with = "off_or_number")]
    pub refine_impact: Option<f64>,
    /// The refined step as a fraction of the step (dimensionless, in (0, 1]), with
    /// [`WorldParams::refine_window`] or [`WorldParams::refine_load`]; `None`: a quarter
    /// (0.25, the step study's reference at the full limit).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub refine_fraction: Option<f64>,
    /// Mass-proportional numerical damping γ (1/s): F = −γ·m·v, M = −γ·I·ω. Default 0;
    /// used only to relax verification scenes to their static state.
    pub global_damping: f64,
}

impl Default for WorldParams {
    fn default() -> Self {
        Self {
            gravity: 9.81,
            ice_density: 920.0,
            contact: ContactParams::default(),
            water: Some(WaterParams::default()),
            time_step_safety: DEFAULT_TIME_STEP_SAFETY,
            time_step: None,
            contact_dashpot: Dashpot::default(),
            joint_dashpot: Dashpot::Explicit,
            contact_onset: ContactOnset::Area,
            contact_dashpot_sweeps: 0,
            crack_speed: 50.0,
            incubation_time: None,
            fracture_step_mean: false,
            refine_window: Some(DEFAULT_REFINE_WINDOW),
            refine_load: Some(DEFAULT_REFINE_LOAD),
            refine_impact: Some(DEFAULT_REFINE_IMPACT),
            refine_fraction: None,
            global_damping: 0.0,
        }
    }
}

/// Default refined step around fracture as a fraction of the step (dimensionless):
/// a quarter, the step study's reference at the full limit ([`WorldParams::refine_fraction`]).
pub const DEFAULT_REFINE_FRACTION: f64 = 0.25;

/// Largest number of Gauss–Seidel sweeps of the contact dashpot a scene may ask for
/// ([`WorldParams::contact_dashpot_sweeps`]): more is a mistake, not accuracy.
pub const MAX_CONTACT_DASHPOT_SWEEPS: u32 = 50;

/// A serde skip test for counts that are absent when zero.
pub(crate) fn is_zero(n: &u32) -> bool {
    *n == 0
}

/// Default safety factor on the stable time step (dimensionless): the full stable limit,
/// refined around fracture and impacts ([`DEFAULT_REFINE_WINDOW`], [`DEFAULT_REFINE_LOAD`],
/// [`DEFAULT_REFINE_IMPACT`]): at 41 seeds (61 at 0.30 m) against a quarter of the limit it
/// shifts none of the judged ensemble means beyond its test, for 0.62 of the steps of half
/// the limit, the default from 2026-11-28 to 2026-12-07 (docs/speed-vs-error.md).
pub const DEFAULT_TIME_STEP_SAFETY: f64 = 1.0;

/// Default refinement window (s): the step is refined while a joint cracks and for 50 ms
/// after a joint severs or an impact ([`WorldParams::refine_window`]); the tip cascade of a
/// breaking sheet falls within it (docs/speed-vs-error.md).
pub const DEFAULT_REFINE_WINDOW: f64 = 0.05;

/// Default load that refines the step ahead of fracture (dimensionless, of a joint's
/// strength; [`WorldParams::refine_load`]): 0.9, 2.7 % more steps at the full limit.
pub const DEFAULT_REFINE_LOAD: f64 = 0.9;

/// Default approach speed of a new contact that refines the step (m/s;
/// [`WorldParams::refine_impact`]): 0.6, about 10 % more steps; it takes away the 0.45-m
/// sheet's excess of rubble broken into single blocks (docs/speed-vs-error.md).
pub const DEFAULT_REFINE_IMPACT: f64 = 0.6;

/// An error in a world's parameters or bodies.
#[derive(Clone, Debug, thiserror::Error, PartialEq)]
pub enum WorldError {
    /// A parameter is out of its physical range.
    #[error("parameter `{name}` = {value} is invalid: {why}")]
    Param {
        /// Parameter name.
        name: &'static str,
        /// Its value.
        value: f64,
        /// What is required.
        why: &'static str,
    },
    /// A saved state does not fit this build.
    #[error("invalid saved state: {0}")]
    State(String),
    /// A block could not be made.
    #[error("block: {0}")]
    Shape(#[from] ShapeError),
    /// A fixed time step above the stable limit.
    #[error(
        "time step {dt:.4e} s is above the stable limit {limit:.4e} s of this scene \
         (the stiffest joint and contact, see docs/model.md \"Time step\"); use at most \
         {limit:.4e} s or leave the time step to be derived"
    )]
    Unstable {
        /// The requested time step (s).
        dt: f64,
        /// The stable limit (s).
        limit: f64,
    },
    /// The state turned non-finite.
    #[error(
        "the run turned non-finite at step {step} (t = {time:.6} s): body {body} has a \
         non-finite {what}; no results were written"
    )]
    NonFinite {
        /// The step that produced the non-finite value.
        step: u64,
        /// Simulated time at the end of that step (s).
        time: f64,
        /// The first body found with a non-finite value.
        body: usize,
        /// Which value: velocity, angular velocity, position or orientation.
        what: &'static str,
    },
}

impl WorldParams {
    /// The numerics of a step of `dt` (s) that the force stages read.
    pub(crate) fn step_numerics(
        &self,
        dt: f64,
        dt_prev: f64,
    ) -> super::super::numerics::StepNumerics {
        super::super::numerics::StepNumerics {
            dt,
            dt_prev,
            // (dt + dt)/2 is dt to the bit: a constant step is the scheme it always was.
            kick: 0.5 * (dt_prev + dt),
            contact_dashpot: self.contact_dashpot,
            contact_onset: self.contact_onset,
            contact_dashpot_sweeps: self.contact_dashpot_sweeps,
            joint_dashpot: self.joint_dashpot,
            incubation_time: self.incubation_time,
            fracture_step_mean: self.fracture_step_mean,
            track_load: self.refine_load.is_some(),
        }
    }

    /// Checks every parameter; the message names the first offending one.
    pub(crate) fn validate(&self) -> Result<(), WorldError> {
        let pos = |name, value: f64| {
            if value > 0.0 && value.is_finite() {
                Ok(())
            } else {
                Err(WorldError::Param {
                    name,
                    value,
                    why: "must be positive and finite",
                })
            }
        };
        let nonneg = |name, value: f64| {
            if value >= 0.0 && value.is_finite() {
                Ok(())
            } else {
                Err(WorldError::Param {
                    name,
                    value,
                    why: "must be non-negative and finite",
                })
            }
        };
        nonneg("gravity", self.gravity)?;
        pos("ice_density", self.ice_density)?;
        let c = &self.contact;
        pos("contact.normal_stiffness", c.normal_stiffness)?;
        nonneg("contact.damping_fraction", c.damping_fraction)?;
        pos("contact.tangential_fraction", c.tangential_fraction)?;
        pos("contact.reference_thickness", c.thickness())?;
        nonneg("contact.mu", c.mu)?;
        nonneg("contact.mu_water", c.mu_water)?;
        nonneg("contact.crushing_pressure", c.crushing_pressure)?;
        if let Some(w) = &self.water {
            pos("water.density", w.density)?;
            nonneg("water.drag_coefficient", w.drag_coefficient)?;
            nonneg("water.linear_drag", w.linear_drag)?;
            if !w.level.is_finite() {
                return Err(WorldError::Param {
                    name: "water.level",
                    value: w.level,
                    why: "must be finite",
                });
            }
        }
        pos("time_step_safety", self.time_step_safety)?;
        if let Some(w) = self.refine_window {
            nonneg("refine_window", w)?;
        }
        // Fractions in (0, 1]: of the joints' strength, and of the step.
        let fraction = |name: &'static str, f: f64, why: &'static str| {
            pos(name, f)?;
            if f > 1.0 {
                return Err(WorldError::Param {
                    name,
                    value: f,
                    why,
                });
            }
            Ok(())
        };
        if let Some(f) = self.refine_load {
            fraction(
                "refine_load",
                f,
                "must be at most 1 (a fraction of the joints' strength)",
            )?;
        }
        if let Some(v) = self.refine_impact {
            pos("refine_impact", v)?;
            if self.refine_window.is_none() {
                return Err(WorldError::Param {
                    name: "refine_impact",
                    value: v,
                    why: "refines for refine_window after an impact: set refine_window too",
                });
            }
        }
        if let Some(f) = self.refine_fraction {
            fraction(
                "refine_fraction",
                f,
                "must be at most 1 (a refined step is not longer than the step)",
            )?;
        }
        if self.time_step_safety > 1.0 {
            return Err(WorldError::Param {
                name: "time_step_safety",
                value: self.time_step_safety,
                why: "must lie in (0, 1]: the stable time step is a limit",
            });
        }
        pos("crack_speed", self.crack_speed)?;
        if let Some(t) = self.incubation_time {
            pos("incubation_time", t)?;
            if self.fracture_step_mean {
                return Err(WorldError::Param {
                    name: "fracture_step_mean",
                    value: 1.0,
                    why: "filters the tested stress as incubation_time does: set one of them",
                });
            }
        }
        nonneg("global_damping", self.global_damping)?;
        if self.contact_dashpot_sweeps > MAX_CONTACT_DASHPOT_SWEEPS {
            return Err(WorldError::Param {
                name: "contact_dashpot_sweeps",
                value: f64::from(self.contact_dashpot_sweeps),
                why: "must lie in 0..=50 (0: each contact solved alone, the default)",
            });
        }
        if let Some(dt) = self.time_step {
            pos("time_step", dt)?;
        }
        Ok(())
    }
}
