//! The energy budget of a ridging run, Hopkins (1994) eqs (9)–(12), per metre of ridge
//! (J/m): [`EnergyBudget`], and the one table of its terms, [`LEDGER_TERMS`]
//! (`energy/terms.rs`), from which every file and face of the budget is derived.
//!
//! Data only: the simulator books it (`dem::ledger`, crate-private, with the sign convention
//! and the mid-step velocity of the booking); the run summary, a campaign's samples, the
//! ensemble statistics and the ridging table read and write it.

use serde::{Deserialize, Serialize};

pub(crate) mod files;
pub(crate) mod terms;
pub use files::{Keep, LEDGER_FILES, TermFile, TermSet, Terms, term_file};
pub use terms::{LEDGER_TERMS, LedgerTerm, N_TERMS, Sign, term, term_index};

/// The energy budget at one instant, every term in J per metre of ridge.
///
/// Inputs: `work`. Sinks: `potential_energy`, `kinetic_energy`, `elastic_energy` (held, can
/// be returned) and the dissipations, each of which can only grow from zero:
/// `friction_dissipation`, `viscous_dissipation`, `drag_dissipation`, `joint_dissipation`,
/// `boundary_dissipation`, `fracture_dissipation`, `plastic_dissipation`; and two terms of the discrete model
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
    /// Crushing at contacts: the work of the elastic normal forces held at the cap p_c·L
    /// while the overlap grew beyond it (`contact.crushing_pressure`), a part of eq (12)'s
    /// Φ_i (J/m). Zero without a cap.
    pub plastic_dissipation: f64,
    /// Elastic work left in contacts when they separated, normal and tangential: zero for
    /// a conservative contact law; the area law of eq (2) with a normal that turns with the
    /// overlap is not exactly conservative, so this has no fixed sign.
    pub contact_hysteresis: f64,
    /// Kinetic-energy change of blocks re-cut by bevels after fractures (the material cut
    /// away takes its momentum with it); no fixed sign.
    pub cut_away: f64,
    /// Elastic energy held in contacts, joints and floe springs.
    pub elastic_energy: f64,
    /// Everything not in Φ_f, the viscous part of Φ_i or drag: joint, boundary, fracture and
    /// plastic dissipation, contact hysteresis and cut-away kinetic energy.
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
            &mut self.plastic_dissipation,
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
                "fracture_dissipation",
                "plastic_dissipation"
            ]
        );
        // Of the numbered terms, other_dissipation (15) is the largest that counts.
        assert_eq!(b.largest_term(), 15.0);
        assert!(LEDGER_TERMS.iter().all(|t| !t.description.is_empty()));
    }
}
