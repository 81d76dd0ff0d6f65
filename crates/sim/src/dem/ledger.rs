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
//!
//! The budget it gives, [`EnergyBudget`], and the table of its terms from which every file
//! and face of the ledger is derived, [`crate::energy::LEDGER_TERMS`], are in
//! [`crate::energy`]: data every layer above reads, where this module books them.

use super::boundary::BoundaryWork;
use super::contact::ContactWork;
use super::fracture::JointWork;
use super::water::WaterWork;
use crate::energy::EnergyBudget;
use serde::{Deserialize, Serialize};

/// Running integrals of the step, from which an [`EnergyBudget`] is derived.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub(crate) struct Accumulators {
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
pub(crate) struct Stored {
    /// Normal contact springs (elastic work booked and not yet returned).
    pub contact_normal: f64,
    /// Tangential contact springs: tangential work booked less slip dissipation.
    pub contact_tangential: f64,
}

/// The budget from the accumulators, the current kinetic energy and the energy held by
/// contacts (J/m). Joints and floe springs hold the work booked into them.
pub(crate) fn budget(time: f64, acc: &Accumulators, kinetic_now: f64, st: &Stored) -> EnergyBudget {
    let c = &acc.contact;
    let work = acc.work + acc.loads + acc.boundary.frame;
    let potential_energy = acc.gravity + acc.water.buoyancy;
    let kinetic_energy = kinetic_now - acc.kinetic_start;
    let friction_dissipation = c.slip;
    let elastic_energy =
        st.contact_normal + st.contact_tangential + acc.joints.held() + acc.boundary.springs;
    let contact_hysteresis = (c.normal_elastic + c.tangential - c.slip - c.plastic)
        - (st.contact_normal + st.contact_tangential);
    let fracture_dissipation = acc.joints.released;
    let boundary_dissipation = acc.boundary.damping + acc.global_damping;
    let other_dissipation = contact_hysteresis
        + c.plastic
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
        plastic_dissipation: c.plastic,
        contact_hysteresis,
        cut_away: acc.cut_away,
        elastic_energy,
        other_dissipation,
        normal_contact_work: c.normal_viscous + c.normal_elastic,
        normal_elastic_work: c.normal_elastic,
        residual: work - sinks,
    }
}
