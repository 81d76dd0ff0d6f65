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
//! The table of its terms, from which every file and face of the ledger is derived, is
//! [`LEDGER_TERMS`] (`ledger/terms.rs`).

use super::boundary::BoundaryWork;
use super::contact::ContactWork;
use super::fracture::JointWork;
use super::water::WaterWork;
use serde::{Deserialize, Serialize};

pub(crate) mod terms;
pub use terms::{Keep, LEDGER_TERMS, LedgerTerm, N_TERMS, Sign, TermSet, Terms, term, term_index};

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
    /// `dem::boundary` (crate-private) and docs/model.md, "Boundary conditions".
    pub frame_work: f64,
    /// Change of potential energy (gravity and buoyancy), eq (10).
    pub potential_energy: f64,
    /// Change of kinetic energy since the ledger started (blocks entering count from their
    /// entry).
    pub kinetic_energy: f64,
    /// Frictional dissipation Φ_f, eq (11): the slip dissipation of the Coulomb cap
    /// (docs/model.md, "Energy ledger").
    pub friction_dissipation: f64,
    /// Viscous (inelastic) contact dissipation: the viscous part of Φ_i, eq (12).
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
    /// Φ_i as eq (12) defines it: the net work of the normal contact forces, viscous
    /// (`viscous_dissipation`) plus elastic (`normal_elastic_work`) (J/m). A part of the
    /// sinks above, not a sink of its own.
    pub normal_contact_work: f64,
    /// The elastic part of eq (12): the work of the elastic normal contact forces, held by
    /// active contacts (in `elastic_energy`) or left at separation (in
    /// `contact_hysteresis`) (J/m).
    pub normal_elastic_work: f64,
    /// `work` minus all sinks: zero to round-off when the books are complete.
    pub residual: f64,
}

impl EnergyBudget {
    /// Builds the budget from the accumulators, the current kinetic energy and the energy
    /// held by contacts (J/m). Joints and floe springs hold the work booked into them.
    pub(crate) fn from_parts(time: f64, acc: &Accumulators, kinetic_now: f64, st: &Stored) -> Self {
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
            normal_contact_work: c.normal_viscous + c.normal_elastic,
            normal_elastic_work: c.normal_elastic,
            residual: work - sinks,
        }
    }

    /// The terms in the order of [`LEDGER_TERMS`] (J/m): the one list of the fields behind
    /// [`Self::values`] and [`Self::from_values`].
    fn terms_mut(&mut self) -> [&mut f64; N_TERMS] {
        [
            &mut self.work,
            &mut self.frame_work,
            &mut self.potential_energy,
            &mut self.kinetic_energy,
            &mut self.friction_dissipation,
            &mut self.viscous_dissipation,
            &mut self.drag_dissipation,
            &mut self.joint_dissipation,
            &mut self.boundary_dissipation,
            &mut self.fracture_dissipation,
            &mut self.contact_hysteresis,
            &mut self.cut_away,
            &mut self.elastic_energy,
            &mut self.other_dissipation,
            &mut self.normal_contact_work,
            &mut self.normal_elastic_work,
            &mut self.residual,
        ]
    }

    /// The terms in the order of [`LEDGER_TERMS`] (J/m).
    pub fn values(&self) -> [f64; N_TERMS] {
        let mut b = *self;
        b.terms_mut().map(|x| *x)
    }

    /// The budget at time `time` (s) with the terms `values`, in the order of
    /// [`LEDGER_TERMS`] (J/m).
    pub fn from_values(time: f64, values: [f64; N_TERMS]) -> Self {
        let mut b = EnergyBudget {
            time,
            ..Default::default()
        };
        for (x, v) in b.terms_mut().into_iter().zip(values) {
            *x = v;
        }
        b
    }

    /// The dissipation terms, each of which can only grow from zero, by name (J/m).
    pub fn dissipations(&self) -> impl Iterator<Item = (&'static str, f64)> {
        LEDGER_TERMS
            .into_iter()
            .zip(self.values())
            .filter(|(t, _)| t.is_dissipation())
            .map(|(t, v)| (t.name, v))
    }

    /// The largest magnitude among the terms (J/m), the scale for relative residuals.
    pub fn largest_term(&self) -> f64 {
        LEDGER_TERMS
            .iter()
            .zip(self.values())
            .filter(|(t, _)| t.scale)
            .fold(0.0f64, |m, (_, x)| m.max(x.abs()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A budget whose term k holds k + 1, by the struct's own field names.
    fn numbered() -> EnergyBudget {
        let mut map = serde_json::Map::new();
        for (k, t) in LEDGER_TERMS.iter().enumerate() {
            // The one field whose name differs from its term (kept for old files).
            let field = if t.name == "kinetic_energy_change" {
                "kinetic_energy"
            } else {
                t.name
            };
            map.insert(field.into(), (k as f64 + 1.0).into());
        }
        serde_json::from_value(serde_json::Value::Object(map)).unwrap()
    }

    /// `values()` lays the fields out in the table's order, and the table names every field
    /// of the budget but its time once.
    #[test]
    fn values_follow_the_table_and_cover_every_field() {
        let b = numbered();
        let want: Vec<f64> = (1..=LEDGER_TERMS.len()).map(|k| k as f64).collect();
        assert_eq!(b.values().to_vec(), want);
        let fields = serde_json::to_value(b).unwrap();
        let n = fields.as_object().unwrap().len();
        assert_eq!(
            n,
            LEDGER_TERMS.len() + 1,
            "every field but `time` is a term"
        );
    }

    /// The dissipations and the residual scale come from the table's columns.
    #[test]
    fn dissipations_and_scale_come_from_the_table() {
        let b = numbered();
        let names: Vec<&str> = b.dissipations().map(|(n, _)| n).collect();
        assert_eq!(
            names,
            [
                "friction_dissipation",
                "viscous_dissipation",
                "drag_dissipation",
                "joint_dissipation",
                "boundary_dissipation",
                "fracture_dissipation"
            ]
        );
        // Of the numbered terms, other_dissipation (14) is the largest that counts.
        assert_eq!(b.largest_term(), 14.0);
        assert!(LEDGER_TERMS.iter().all(|t| !t.description.is_empty()));
    }
}
