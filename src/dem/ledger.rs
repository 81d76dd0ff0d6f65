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
    /// Normal contact springs (elastic work not yet returned).
    pub contact_normal: f64,
    /// Tangential contact springs, F_t²/(2·k_te).
    pub contact_tangential: f64,
    /// Intact joints, ½∫(E·δ_n² + G·δ_t²)/W.
    pub joints: f64,
    /// Floe support springs.
    pub springs: f64,
}

/// The energy budget at one instant, every term in J per metre of ridge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct EnergyBudget {
    /// Time (s).
    pub time: f64,
    /// Work done by the prescribed motions (the pushed sheet), eq (9), and external loads.
    pub work: f64,
    /// Change of potential energy (gravity and buoyancy), eq (10).
    pub potential_energy: f64,
    /// Change of kinetic energy since the ledger started (blocks entering count from their
    /// entry).
    pub kinetic_energy: f64,
    /// Frictional dissipation Φ_f, eq (11): tangential contact work less the energy the
    /// tangential springs still hold.
    pub friction_dissipation: f64,
    /// Viscous (inelastic) contact dissipation Φ_i, eq (12).
    pub viscous_dissipation: f64,
    /// Dissipation by water drag.
    pub drag_dissipation: f64,
    /// Dissipation by the joints' viscosity, eq (1).
    pub joint_dissipation: f64,
    /// Dissipation by the viscous boundary forces of eqs (7)–(8), the floe dashpots and any
    /// numerical damping.
    pub boundary_dissipation: f64,
    /// Elastic energy released by cracks: joint elastic work less what intact joints hold.
    pub fracture_dissipation: f64,
    /// Elastic energy held in contacts, joints and floe springs.
    pub elastic_energy: f64,
    /// Everything not in Φ_f, Φ_i or drag: joint, boundary and fracture dissipation, elastic
    /// contact work not returned at separation, and the kinetic energy of material cut away
    /// by bevels.
    pub other_dissipation: f64,
    /// `work` minus all sinks: zero to round-off when the books are complete.
    pub residual: f64,
}

impl EnergyBudget {
    /// Builds the budget from the accumulators, the current kinetic energy and the energy
    /// held by elastic elements (J/m).
    pub fn from_parts(time: f64, acc: &Accumulators, kinetic_now: f64, st: &Stored) -> Self {
        let c = &acc.contact;
        let work = acc.work + acc.loads;
        let potential_energy = acc.gravity + acc.water.buoyancy;
        let kinetic_energy = kinetic_now - acc.kinetic_start;
        let friction_dissipation = c.tangential - st.contact_tangential;
        let elastic_energy = st.contact_normal + st.contact_tangential + st.joints + st.springs;
        let hysteresis = c.normal_elastic - st.contact_normal;
        let fracture_dissipation = acc.joints.elastic - st.joints;
        let boundary_dissipation =
            acc.boundary.damping + acc.global_damping + (acc.boundary.springs - st.springs);
        let other_dissipation = hysteresis
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
            potential_energy,
            kinetic_energy,
            friction_dissipation,
            viscous_dissipation: c.normal_viscous,
            drag_dissipation: acc.water.drag,
            joint_dissipation: acc.joints.viscous,
            boundary_dissipation,
            fracture_dissipation,
            elastic_energy,
            other_dissipation,
            residual: work - sinks,
        }
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
