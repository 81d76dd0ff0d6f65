//! The one table of the energy-ledger terms' physics ([`LEDGER_TERMS`]): name, unit, sign
//! convention, label, equation of Hopkins (1994) and description. Every face of the ledger is
//! derived from it: the time series' columns ([`crate::simulation::series_columns`]), the
//! files that keep the terms (which ones, and how: [`super::files`]), the ensemble statistics
//! (`pressridge::table::ensemble::QUANTITIES`), the NetCDF variables of the ledger terms a
//! ridging table tabulates (`pressridge::table::tabulate::RidgeTable::variables`), the
//! dissipation gate and the residual scale.

/// The sign convention of a ledger term: what it must satisfy at every sample of a run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sign {
    /// Supplied to the system: the input side of the budget.
    Input,
    /// A dissipation: grows from zero and is never negative (the tables' gate and the
    /// tests check it at every sample).
    Dissipation,
    /// Energy held (stored, returnable): never negative.
    Held,
    /// A sink of either sign (a change of state, or a discrete-model term).
    Any,
    /// Work minus all sinks: zero to round-off when the books close.
    Closure,
}

/// One term of the energy ledger ([`LEDGER_TERMS`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LedgerTerm {
    /// Name: the CSV column, the summary and sample key, the Python series name; with
    /// `_mean` and `_std` the NetCDF variables of a tabulated term.
    pub name: &'static str,
    /// Unit, as the CSV header writes it.
    pub unit: &'static str,
    /// What the term must satisfy.
    pub sign: Sign,
    /// Short name, as tables and the NetCDF long names call it.
    pub label: &'static str,
    /// Its equation in Hopkins (1994), if it has one.
    pub equation: Option<&'static str>,
    /// One line: what it is.
    pub description: &'static str,
    /// Whether its magnitude counts towards [`super::EnergyBudget::largest_term`], the scale of
    /// relative residuals (the terms that together make up the budget, without double
    /// counting the parts of `other_dissipation` or of `work`).
    pub scale: bool,
}

impl LedgerTerm {
    /// True for a dissipation (a term that can only grow from zero).
    pub const fn is_dissipation(&self) -> bool {
        matches!(self.sign, Sign::Dissipation)
    }

    /// Its label with its equation, e.g. `ridging work, eq (9)`.
    pub fn label_with_equation(&self) -> String {
        match self.equation {
            Some(eq) => format!("{}, {eq}", self.label),
            None => self.label.to_string(),
        }
    }
}

/// What every term shares unless its row says otherwise.
const BASE: LedgerTerm = LedgerTerm {
    name: "",
    unit: "J/m",
    sign: Sign::Any,
    label: "",
    equation: None,
    description: "",
    scale: false,
};

/// Every term of an [`super::EnergyBudget`] but its time, in the order of
/// [`super::EnergyBudget::values`] and of every file that keeps them (docs/model.md, "Energy
/// ledger"; how the files keep them: [`super::LEDGER_FILES`]).
pub const LEDGER_TERMS: [LedgerTerm; 18] = [
    LedgerTerm {
        name: "work",
        sign: Sign::Input,
        label: "ridging work",
        equation: Some("eq (9)"),
        description: "work done on the system by the push: the driver that holds the sheet's \
                      end block at U (eq (9) as a power balance), the frame of eqs (7)-(8) \
                      moving at U, and external loads",
        scale: true,
        ..BASE
    },
    LedgerTerm {
        name: "frame_work",
        sign: Sign::Input,
        label: "work of the moving frame",
        equation: Some("eqs (7)-(8)"),
        description: "the part of work done by the frame of eqs (7)-(8) moving at U",
        ..BASE
    },
    LedgerTerm {
        name: "potential_energy",
        label: "potential energy change",
        equation: Some("eq (10)"),
        description: "potential energy change: the work done against gravity and buoyancy",
        scale: true,
        ..BASE
    },
    LedgerTerm {
        name: "kinetic_energy_change",
        label: "kinetic energy change",
        description: "kinetic energy change since the start (blocks that enter later count \
                      from their entry)",
        scale: true,
        ..BASE
    },
    LedgerTerm {
        name: "friction_dissipation",
        sign: Sign::Dissipation,
        label: "frictional dissipation",
        equation: Some("eq (11)"),
        description: "slip dissipation of the Coulomb cap on the tangential contact forces",
        scale: true,
        ..BASE
    },
    LedgerTerm {
        name: "viscous_dissipation",
        sign: Sign::Dissipation,
        label: "viscous contact dissipation",
        equation: Some("eq (12)"),
        description: "work of the viscous normal contact forces: the viscous part of eq (12)",
        scale: true,
        ..BASE
    },
    LedgerTerm {
        name: "drag_dissipation",
        sign: Sign::Dissipation,
        label: "water drag dissipation",
        description: "work of the water drag forces and moments",
        scale: true,
        ..BASE
    },
    LedgerTerm {
        name: "joint_dissipation",
        sign: Sign::Dissipation,
        label: "joint viscous dissipation",
        equation: Some("eq (1)"),
        description: "work of the joints' viscous stresses",
        ..BASE
    },
    LedgerTerm {
        name: "boundary_dissipation",
        sign: Sign::Dissipation,
        label: "boundary dissipation",
        equation: Some("eqs (7)-(8)"),
        description: "dissipation of the dashpots of eqs (7)-(8) relative to their frame \
                      moving at U, of the floe dashpots and of any numerical damping",
        ..BASE
    },
    LedgerTerm {
        name: "fracture_dissipation",
        sign: Sign::Dissipation,
        label: "fracture dissipation",
        description: "elastic energy joints held when they were severed",
        ..BASE
    },
    LedgerTerm {
        name: "plastic_dissipation",
        sign: Sign::Dissipation,
        label: "plastic contact dissipation",
        equation: Some("eq (12)"),
        description: "crushing at contacts: work of the elastic normal forces held at the \
                      crushing cap while the overlap grew (zero without a cap); a part of \
                      normal_elastic_work",
        ..BASE
    },
    LedgerTerm {
        name: "contact_hysteresis",
        label: "contact hysteresis",
        description: "elastic contact work not returned at separation (no fixed sign)",
        ..BASE
    },
    LedgerTerm {
        name: "cut_away",
        label: "cut-away kinetic energy",
        description: "kinetic energy change of blocks re-cut by bevels after fractures (no \
                      fixed sign)",
        ..BASE
    },
    LedgerTerm {
        name: "elastic_energy",
        sign: Sign::Held,
        label: "elastic energy held",
        description: "elastic energy held by contacts, joints and floe springs",
        scale: true,
        ..BASE
    },
    LedgerTerm {
        name: "other_dissipation",
        label: "other dissipation",
        description: "joint, boundary, fracture and plastic dissipation, contact \
                      hysteresis and cut-away kinetic energy",
        scale: true,
        ..BASE
    },
    LedgerTerm {
        name: "normal_contact_work",
        label: "net normal contact work",
        equation: Some("eq (12)"),
        description: "Phi_i as eq (12) defines it: the net work of the normal contact forces, \
                      viscous (viscous_dissipation) and elastic (normal_elastic_work); a \
                      part of other terms, not a sink of its own",
        ..BASE
    },
    LedgerTerm {
        name: "normal_elastic_work",
        label: "elastic normal contact work",
        equation: Some("eq (12)"),
        description: "the elastic part of eq (12): work of the elastic normal contact forces, \
                      held by active contacts, dissipated by crushing or left as hysteresis \
                      at separation",
        ..BASE
    },
    LedgerTerm {
        name: "residual",
        sign: Sign::Closure,
        label: "residual",
        description: "work minus all sinks: zero to round-off when the books close",
        ..BASE
    },
];

/// Number of ledger terms.
pub const N_TERMS: usize = LEDGER_TERMS.len();

/// The index in [`LEDGER_TERMS`] of the term named `name`; in a constant, a name that is not
/// a term fails to compile.
pub const fn term_index(name: &str) -> usize {
    let mut k = 0;
    while k < N_TERMS {
        if str_eq(LEDGER_TERMS[k].name, name) {
            return k;
        }
        k += 1;
    }
    panic!("not a ledger term")
}

/// The term named `name` (see [`term_index`]).
pub const fn term(name: &str) -> LedgerTerm {
    LEDGER_TERMS[term_index(name)]
}

pub(super) const fn str_eq(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The table of terms in docs/model.md ("Energy ledger") lists the terms of the table,
    /// in its order.
    #[test]
    fn the_model_documents_every_term_in_order() {
        let doc =
            std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/model.md"))
                .unwrap();
        let section = doc
            .split("\n## Energy ledger")
            .nth(1)
            .expect("the ledger section");
        let section = section.split("\n## ").next().unwrap();
        let names: Vec<&str> = section
            .lines()
            .filter_map(|l| l.strip_prefix("| `"))
            .map(|l| l.split('`').next().unwrap())
            .collect();
        let want: Vec<&str> = LEDGER_TERMS.iter().map(|t| t.name).collect();
        assert_eq!(names, want);
    }

    /// The table's names are unique, and every row is complete.
    #[test]
    fn the_table_is_complete() {
        for t in &LEDGER_TERMS {
            assert!(
                !t.label.is_empty() && !t.description.is_empty(),
                "{}",
                t.name
            );
            assert_eq!(term(t.name), *t);
        }
        let mut names: Vec<&str> = LEDGER_TERMS.iter().map(|t| t.name).collect();
        let n = names.len();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), n);
    }
}
