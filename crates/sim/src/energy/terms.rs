//! The one table of the energy-ledger terms ([`LEDGER_TERMS`]): name, unit, sign convention,
//! description and the files that keep each term. Every face of the ledger is derived from
//! it: the time series' columns ([`crate::simulation::series_columns`]), the run summary
//! (`summary.json`) and a campaign's samples (`run.json`) through [`Terms`], the ensemble
//! statistics (`pressridge::table::ensemble::QUANTITIES`), the NetCDF variables of the ledger
//! terms a ridging table tabulates (`pressridge::table::tabulate::RidgeTable::variables`), the
//! dissipation gate and the residual scale.

use super::EnergyBudget;
use serde::de::{self, IgnoredAny, MapAccess, Visitor};
use serde::ser::SerializeMap;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::fmt;
use std::marker::PhantomData;

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

/// Whether a file keeps a term ([`LedgerTerm::summary`], [`LedgerTerm::sample`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Keep {
    /// Not kept.
    No,
    /// Always written; required when read.
    Required,
    /// Always written; files written before the term was kept lack it and read it as 0.
    Added,
}

/// One term of the energy ledger ([`LEDGER_TERMS`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LedgerTerm {
    /// Name: the CSV column, the summary and sample key, the Python series name; with
    /// `_mean` and `_std` the NetCDF variables of a tabulated term.
    pub name: &'static str,
    /// Unit, as the CSV header writes it.
    pub unit: &'static str,
    /// Unit as a UDUNITS string, as NetCDF attributes write it.
    pub udunits: &'static str,
    /// What the term must satisfy.
    pub sign: Sign,
    /// Short name, as tables and the NetCDF long names call it.
    pub label: &'static str,
    /// Its equation in Hopkins (1994), if it has one.
    pub equation: Option<&'static str>,
    /// One line: what it is.
    pub description: &'static str,
    /// Whether its magnitude counts towards [`EnergyBudget::largest_term`], the scale of
    /// relative residuals (the terms that together make up the budget, without double
    /// counting the parts of `other_dissipation` or of `work`).
    pub scale: bool,
    /// Whether the run summary keeps it ([`crate::simulation::Summary`]).
    pub summary: Keep,
    /// Whether a campaign's samples keep it ([`crate::record::RunSample`]): work and ΔPE,
    /// which the tables fit, and every dissipation, which their gate checks.
    pub sample: Keep,
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
    udunits: "J m-1",
    sign: Sign::Any,
    label: "",
    equation: None,
    description: "",
    scale: false,
    summary: Keep::Required,
    sample: Keep::No,
};

/// Every term of an [`EnergyBudget`] but its time, in the order of [`EnergyBudget::values`]
/// and of every file that keeps them (docs/model.md, "Energy ledger").
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
        sample: Keep::Required,
        ..BASE
    },
    LedgerTerm {
        name: "frame_work",
        sign: Sign::Input,
        label: "work of the moving frame",
        equation: Some("eqs (7)-(8)"),
        description: "the part of work done by the frame of eqs (7)-(8) moving at U",
        summary: Keep::Added,
        ..BASE
    },
    LedgerTerm {
        name: "potential_energy",
        label: "potential energy change",
        equation: Some("eq (10)"),
        description: "potential energy change: the work done against gravity and buoyancy",
        scale: true,
        sample: Keep::Required,
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
        sample: Keep::Required,
        ..BASE
    },
    LedgerTerm {
        name: "viscous_dissipation",
        sign: Sign::Dissipation,
        label: "viscous contact dissipation",
        equation: Some("eq (12)"),
        description: "work of the viscous normal contact forces: the viscous part of eq (12)",
        scale: true,
        sample: Keep::Required,
        ..BASE
    },
    LedgerTerm {
        name: "drag_dissipation",
        sign: Sign::Dissipation,
        label: "water drag dissipation",
        description: "work of the water drag forces and moments",
        scale: true,
        sample: Keep::Added,
        ..BASE
    },
    LedgerTerm {
        name: "joint_dissipation",
        sign: Sign::Dissipation,
        label: "joint viscous dissipation",
        equation: Some("eq (1)"),
        description: "work of the joints' viscous stresses",
        sample: Keep::Added,
        ..BASE
    },
    LedgerTerm {
        name: "boundary_dissipation",
        sign: Sign::Dissipation,
        label: "boundary dissipation",
        equation: Some("eqs (7)-(8)"),
        description: "dissipation of the dashpots of eqs (7)-(8) relative to their frame \
                      moving at U, of the floe dashpots and of any numerical damping",
        sample: Keep::Added,
        ..BASE
    },
    LedgerTerm {
        name: "fracture_dissipation",
        sign: Sign::Dissipation,
        label: "fracture dissipation",
        description: "elastic energy joints held when they were severed",
        sample: Keep::Added,
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
        summary: Keep::Added,
        sample: Keep::Added,
        ..BASE
    },
    LedgerTerm {
        name: "contact_hysteresis",
        label: "contact hysteresis",
        description: "elastic contact work not returned at separation (no fixed sign)",
        summary: Keep::Added,
        ..BASE
    },
    LedgerTerm {
        name: "cut_away",
        label: "cut-away kinetic energy",
        description: "kinetic energy change of blocks re-cut by bevels after fractures (no \
                      fixed sign)",
        summary: Keep::Added,
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
        summary: Keep::Added,
        sample: Keep::Added,
        ..BASE
    },
    LedgerTerm {
        name: "normal_elastic_work",
        label: "elastic normal contact work",
        equation: Some("eq (12)"),
        description: "the elastic part of eq (12): work of the elastic normal contact forces, \
                      held by active contacts, dissipated by crushing or left as hysteresis \
                      at separation",
        summary: Keep::Added,
        sample: Keep::Added,
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

const fn str_eq(a: &str, b: &str) -> bool {
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

/// The terms a file keeps: a column of [`LEDGER_TERMS`] (a marker type per file).
pub trait TermSet: Clone + Copy + fmt::Debug + Default + PartialEq {
    /// Whether the file keeps term `t`.
    fn keep(t: &LedgerTerm) -> Keep;
}

/// The ledger terms one file keeps (J/m), read and written as one map entry per term under
/// its name, in the order of [`LEDGER_TERMS`]: flattened into the file's other fields
/// (`#[serde(flatten)]`), it is that file's part of the ledger without a list of its own.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Terms<S> {
    /// Every term's value by table index (J/m), 0 where `S` does not keep it.
    values: [f64; N_TERMS],
    set: PhantomData<S>,
}

impl<S: TermSet> Terms<S> {
    /// The terms of `e` that `S` keeps (J/m).
    pub fn of(e: &EnergyBudget) -> Self {
        let mut values = e.values();
        for (v, t) in values.iter_mut().zip(&LEDGER_TERMS) {
            if S::keep(t) == Keep::No {
                *v = 0.0;
            }
        }
        Terms {
            values,
            set: PhantomData,
        }
    }

    /// Writes the terms `S` keeps into `values` (by table index, J/m), the others untouched.
    pub fn write_into(&self, values: &mut [f64; N_TERMS]) {
        for (k, t) in LEDGER_TERMS.iter().enumerate() {
            if S::keep(t) != Keep::No {
                values[k] = self.values[k];
            }
        }
    }

    /// The terms `S` keeps as a budget at time `time` (s), the others 0 (J/m).
    pub fn energy(&self, time: f64) -> EnergyBudget {
        let mut values = [0.0; N_TERMS];
        self.write_into(&mut values);
        EnergyBudget::from_values(time, values)
    }

    /// The table index of the term `S` keeps under `key`.
    fn index(key: &str) -> Option<usize> {
        LEDGER_TERMS
            .iter()
            .position(|t| S::keep(t) != Keep::No && t.name == key)
    }
}

impl<S: TermSet> Serialize for Terms<S> {
    fn serialize<Z: Serializer>(&self, z: Z) -> Result<Z::Ok, Z::Error> {
        let n = LEDGER_TERMS
            .iter()
            .filter(|t| S::keep(t) != Keep::No)
            .count();
        let mut map = z.serialize_map(Some(n))?;
        for (t, v) in LEDGER_TERMS.iter().zip(&self.values) {
            if S::keep(t) != Keep::No {
                map.serialize_entry(t.name, v)?;
            }
        }
        map.end()
    }
}

impl<'de, S: TermSet> Deserialize<'de> for Terms<S> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_map(TermsVisitor::<S>(PhantomData))
    }
}

struct TermsVisitor<S>(PhantomData<S>);

impl<'de, S: TermSet> Visitor<'de> for TermsVisitor<S> {
    type Value = Terms<S>;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a map of energy-ledger terms")
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Terms<S>, A::Error> {
        let mut got = [None; N_TERMS];
        while let Some(key) = map.next_key::<String>()? {
            match Terms::<S>::index(&key) {
                Some(k) if got[k].is_some() => {
                    return Err(de::Error::duplicate_field(LEDGER_TERMS[k].name));
                }
                Some(k) => got[k] = Some(map.next_value::<f64>()?),
                None => {
                    map.next_value::<IgnoredAny>()?;
                }
            }
        }
        let mut values = [0.0; N_TERMS];
        for ((v, g), t) in values.iter_mut().zip(got).zip(&LEDGER_TERMS) {
            *v = match (g, S::keep(t)) {
                (Some(x), _) => x,
                (None, Keep::Required) => return Err(de::Error::missing_field(t.name)),
                (None, _) => 0.0,
            };
        }
        Ok(Terms {
            values,
            set: PhantomData,
        })
    }
}

/// Checks of a file that keeps ledger terms through [`Terms`], for the tests of each file.
#[cfg(test)]
pub(crate) mod check {
    use super::*;
    use serde::de::DeserializeOwned;

    /// The position of `"key":` in `text`, which must hold it once.
    pub fn key_at(text: &str, key: &str) -> usize {
        let pat = format!("\"{key}\":");
        assert_eq!(text.matches(&pat).count(), 1, "{key} once in {text}");
        text.find(&pat).unwrap()
    }

    /// Checks a file type `T` against the column `keep` of the table, from `json`, a file
    /// without ledger terms: with term k set to k + 1, it reads every kept term by its name
    /// (and 0 for the others), writes each once under its name in the table's order and
    /// reads back what it wrote; without a kept term it fails if the term is required and
    /// reads 0 if it was added later; a term's old name still reads. Returns the file as
    /// written, for the file's own checks.
    pub fn file<T>(
        json: serde_json::Value,
        keep: fn(&LedgerTerm) -> Keep,
        energy: fn(&T) -> EnergyBudget,
    ) -> String
    where
        T: Serialize + DeserializeOwned + PartialEq + fmt::Debug,
    {
        let kept: Vec<(usize, &LedgerTerm)> = LEDGER_TERMS
            .iter()
            .enumerate()
            .filter(|(_, t)| keep(t) != Keep::No)
            .collect();
        let mut full = json.clone();
        for &(k, t) in &kept {
            full[t.name] = (k as f64 + 1.0).into();
        }
        let x: T = serde_json::from_value(full.clone()).unwrap();
        for (k, (t, v)) in LEDGER_TERMS.iter().zip(energy(&x).values()).enumerate() {
            let want = if keep(t) == Keep::No {
                0.0
            } else {
                k as f64 + 1.0
            };
            assert_eq!(v, want, "{}", t.name);
        }
        let text = serde_json::to_string_pretty(&x).unwrap();
        let places: Vec<usize> = kept.iter().map(|(_, t)| key_at(&text, t.name)).collect();
        assert!(
            places.windows(2).all(|w| w[0] < w[1]),
            "table order: {text}"
        );
        for t in LEDGER_TERMS.iter().filter(|t| keep(t) == Keep::No) {
            assert!(!text.contains(&format!("\"{}\":", t.name)), "{}", t.name);
        }
        assert_eq!(serde_json::from_str::<T>(&text).unwrap(), x);
        for &(k, t) in &kept {
            let mut less = full.clone();
            less.as_object_mut().unwrap().remove(t.name).unwrap();
            match (serde_json::from_value::<T>(less), keep(t)) {
                (Err(e), Keep::Required) => assert!(e.to_string().contains(t.name), "{e}"),
                (Ok(x), Keep::Added) => assert_eq!(energy(&x).values()[k], 0.0),
                (r, keep) => panic!("{}: {keep:?} but {r:?}", t.name),
            }
        }
        text
    }
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

    /// Every dissipation is kept by the samples, so the tables' gate sees it at every sample;
    /// the table's names are unique, and every row is complete.
    #[test]
    fn the_table_is_complete() {
        for t in &LEDGER_TERMS {
            assert!(!t.is_dissipation() || t.sample != Keep::No, "{}", t.name);
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
