//! The energy budget, Hopkins (1994) eqs (9)–(12), per metre of ridge (J/m).
//!
//! Every term is booked from the forces actually applied in the step, with the mid-step
//! velocity v̄ⁿ = (vⁿ⁻½ + vⁿ⁺½)/2. For the leapfrog update vⁿ⁺½ = vⁿ⁻½ + Δt·Fⁿ/m this is
//! the one velocity for which ½m(vⁿ⁺½)² − ½m(vⁿ⁻½)² = Δt·Fⁿ·v̄ⁿ holds exactly, so the
//! budget closes to round-off when — and only when — every force is booked in some term.
//! The residual therefore checks the bookkeeping; the discretisation error of the run is
//! measured separately (e.g. ΔPE from eq (10) against the potential energy of the state,
//! [`crate::dem::World::potential_energy`]).
//!
//! Sign convention: every sink is the work the bodies did *against* that force, so all
//! dissipations are positive and `work = ΔPE + ΔKE + dissipations + stored + residual`.

use super::boundary::BoundaryWork;
use super::contact::ContactWork;
use super::fracture::JointWork;
use super::water::WaterWork;
use serde::{Deserialize, Serialize};

/// Running integrals of the step, from which an [`EnergyBudget`] is derived.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Accumulators {
    /// Work done on the system by prescribed motions (the pushed sheet), eq (9) (J/m).
    pub work: f64,
    /// Work done against gravity: the gravity part of ΔPE, eq (10) (J/m).
    pub gravity: f64,
    /// Water forces (J/m).
    pub water: WaterWork,
    /// Contact forces (J/m).
    pub contact: ContactWork,
    /// Joint forces (J/m).
    pub joints: JointWork,
    /// Boundary forces: eqs (7)–(8), floe supports (J/m).
    pub boundary: BoundaryWork,
    /// Work of external loads (verification scenes) (J/m).
    pub loads: f64,
    /// Work of the optional mass-proportional numerical damping (J/m).
    pub global_damping: f64,
    /// Kinetic energy removed with material cut off by bevels after fractures (J/m).
    pub cut_away: f64,
    /// Kinetic energy at the start of the ledger plus that of blocks that entered later
    /// (the sheet grows at its left end) (J/m).
    pub kinetic_start: f64,
}

/// Energy held in elastic elements at one instant (J/m).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stored {
    /// Normal contact springs (elastic work booked and not yet returned).
    pub contact_normal: f64,
    /// Tangential contact springs: tangential work booked less slip dissipation.
    pub contact_tangential: f64,
}

/// The energy budget at one instant, every term in J per metre of ridge.
///
/// Inputs: `work`. Sinks: `potential_energy`, `kinetic_energy`, `elastic_energy` (held, can
/// be returned) and the dissipations, each of which can only grow from zero:
/// `friction_dissipation`, `viscous_dissipation`, `drag_dissipation`, `joint_dissipation`,
/// `boundary_dissipation`, `fracture_dissipation`; and two terms of the discrete model
/// without a physical sign, `contact_hysteresis` and `cut_away`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct EnergyBudget {
    /// Time (s).
    pub time: f64,
    /// Work done on the system by the push (J/m): the driver that holds the sheet's end
    /// block at U (eq 9 as a power balance), the frame of eq (7) moving at U
    /// (`frame_work`), and external loads.
    pub work: f64,
    /// The part of `work` done by the frame of eqs (7)–(8) moving at U (J/m): see
    /// [`crate::dem::boundary::BoundaryWork`].
    pub frame_work: f64,
    /// Change of potential energy (gravity and buoyancy), eq (10).
    pub potential_energy: f64,
    /// Change of kinetic energy since the ledger started (blocks entering count from their
    /// entry).
    pub kinetic_energy: f64,
    /// Frictional dissipation Φ_f, eq (11): the slip dissipation of the Coulomb cap
    /// ([`crate::dem::contact::ContactWork::slip`]).
    pub friction_dissipation: f64,
    /// Viscous (inelastic) contact dissipation Φ_i, eq (12).
    pub viscous_dissipation: f64,
    /// Dissipation by water drag.
    pub drag_dissipation: f64,
    /// Dissipation by the joints' viscosity, eq (1).
    pub joint_dissipation: f64,
    /// Dissipation by the dashpots of eqs (7)–(8) (relative to their frame moving at U),
    /// the floe dashpots and any numerical damping.
    pub boundary_dissipation: f64,
    /// Elastic energy joints held when they were severed (released by cracks).
    pub fracture_dissipation: f64,
    /// Elastic work left in contacts when they separated, normal and tangential: zero for
    /// a conservative contact law; the area law of eq (2) with a normal that turns with the
    /// overlap is not exactly conservative, so this has no fixed sign.
    pub contact_hysteresis: f64,
    /// Kinetic-energy change of blocks re-cut by bevels after fractures (the material cut
    /// away takes its momentum with it); no fixed sign.
    pub cut_away: f64,
    /// Elastic energy held in contacts, joints and floe springs.
    pub elastic_energy: f64,
    /// Everything not in Φ_f, Φ_i or drag: joint, boundary and fracture dissipation,
    /// contact hysteresis and cut-away kinetic energy.
    pub other_dissipation: f64,
    /// `work` minus all sinks: zero to round-off when the books are complete.
    pub residual: f64,
}

/// Every term of an [`EnergyBudget`] but its time, in the order of
/// [`EnergyBudget::values`]: name, unit and whether it is a dissipation (a term that can
/// only grow from zero). The time series, the summaries and the Python face derive their
/// columns from this list.
pub const LEDGER_TERMS: [(&str, &str, bool); 15] = [
    ("work", "J/m", false),
    ("frame_work", "J/m", false),
    ("potential_energy", "J/m", false),
    ("kinetic_energy_change", "J/m", false),
    ("friction_dissipation", "J/m", true),
    ("viscous_dissipation", "J/m", true),
    ("drag_dissipation", "J/m", true),
    ("joint_dissipation", "J/m", true),
    ("boundary_dissipation", "J/m", true),
    ("fracture_dissipation", "J/m", true),
    ("contact_hysteresis", "J/m", false),
    ("cut_away", "J/m", false),
    ("elastic_energy", "J/m", false),
    ("other_dissipation", "J/m", false),
    ("residual", "J/m", false),
];

impl EnergyBudget {
    /// Builds the budget from the accumulators, the current kinetic energy and the energy
    /// held by contacts (J/m). Joints and floe springs hold the work booked into them.
    pub fn from_parts(time: f64, acc: &Accumulators, kinetic_now: f64, st: &Stored) -> Self {
        let c = &acc.contact;
        let work = acc.work + acc.loads + acc.boundary.frame;
        let potential_energy = acc.gravity + acc.water.buoyancy;
        let kinetic_energy = kinetic_now - acc.kinetic_start;
        let friction_dissipation = c.slip;
        let elastic_energy =
            st.contact_normal + st.contact_tangential + acc.joints.held() + acc.boundary.springs;
        let contact_hysteresis = (c.normal_elastic + c.tangential - c.slip)
            - (st.contact_normal + st.contact_tangential);
        let fracture_dissipation = acc.joints.released;
        let boundary_dissipation = acc.boundary.damping + acc.global_damping;
        let other_dissipation = contact_hysteresis
            + fracture_dissipation
            + acc.joints.viscous
            + boundary_dissipation
            + acc.cut_away;
        let sinks = potential_energy
            + kinetic_energy
            + friction_dissipation
            + c.normal_viscous
            + acc.water.drag
            + elastic_energy
            + other_dissipation;
        EnergyBudget {
            time,
            work,
            frame_work: acc.boundary.frame,
            potential_energy,
            kinetic_energy,
            friction_dissipation,
            viscous_dissipation: c.normal_viscous,
            drag_dissipation: acc.water.drag,
            joint_dissipation: acc.joints.viscous,
            boundary_dissipation,
            fracture_dissipation,
            contact_hysteresis,
            cut_away: acc.cut_away,
            elastic_energy,
            other_dissipation,
            residual: work - sinks,
        }
    }

    /// The terms in the order of [`LEDGER_TERMS`] (J/m).
    pub fn values(&self) -> [f64; LEDGER_TERMS.len()] {
        [
            self.work,
            self.frame_work,
            self.potential_energy,
            self.kinetic_energy,
            self.friction_dissipation,
            self.viscous_dissipation,
            self.drag_dissipation,
            self.joint_dissipation,
            self.boundary_dissipation,
            self.fracture_dissipation,
            self.contact_hysteresis,
            self.cut_away,
            self.elastic_energy,
            self.other_dissipation,
            self.residual,
        ]
    }

    /// The dissipation terms, each of which can only grow from zero, by name (J/m).
    pub fn dissipations(&self) -> impl Iterator<Item = (&'static str, f64)> {
        LEDGER_TERMS
            .into_iter()
            .zip(self.values())
            .filter(|((_, _, d), _)| *d)
            .map(|((name, _, _), v)| (name, v))
    }

    /// The largest magnitude among the terms (J/m), the scale for relative residuals.
    pub fn largest_term(&self) -> f64 {
        [
            self.work,
            self.potential_energy,
            self.kinetic_energy,
            self.friction_dissipation,
            self.viscous_dissipation,
            self.drag_dissipation,
            self.elastic_energy,
            self.other_dissipation,
        ]
        .iter()
        .fold(0.0f64, |m, x| m.max(x.abs()))
    }
}
