//! The files that keep the energy-ledger terms: which file keeps which term
//! ([`LEDGER_FILES`], a row per term of [`LEDGER_TERMS`] in its order), how a unit is spelled
//! there, and the map entries through which a file reads and writes its terms ([`Terms`]).
//! The terms' physics (name, unit, sign, equation) is [`super::terms`]'s.

use super::EnergyBudget;
use super::terms::{LEDGER_TERMS, N_TERMS};
use serde::de::{self, IgnoredAny, MapAccess, Visitor};
use serde::ser::SerializeMap;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::fmt;
use std::marker::PhantomData;

/// Whether a file keeps a term ([`TermFile::summary`], [`TermFile::sample`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Keep {
    /// Not kept.
    No,
    /// Always written; required when read.
    Required,
    /// Always written; files written before the term was kept lack it and read it as 0.
    Added,
}

/// How the files keep one ledger term ([`LEDGER_FILES`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TermFile {
    /// The term's name ([`super::LedgerTerm::name`]), the key of its row.
    pub name: &'static str,
    /// Its unit as a UDUNITS string, as NetCDF attributes write it.
    pub udunits: &'static str,
    /// Whether the run summary keeps it ([`crate::simulation::Summary`]).
    pub summary: Keep,
    /// Whether a campaign's samples keep it ([`crate::record::RunSample`]): work and ΔPE,
    /// which the tables fit, and every dissipation, which their gate checks.
    pub sample: Keep,
}

/// What every row shares unless it says otherwise.
const FILE_BASE: TermFile = TermFile {
    name: "",
    udunits: "J m-1",
    summary: Keep::Required,
    sample: Keep::No,
};

/// How the files keep each term of [`LEDGER_TERMS`], in its order (checked when compiled).
pub const LEDGER_FILES: [TermFile; N_TERMS] = [
    TermFile {
        name: "work",
        sample: Keep::Required,
        ..FILE_BASE
    },
    TermFile {
        name: "frame_work",
        summary: Keep::Added,
        ..FILE_BASE
    },
    TermFile {
        name: "potential_energy",
        sample: Keep::Required,
        ..FILE_BASE
    },
    TermFile {
        name: "kinetic_energy_change",
        ..FILE_BASE
    },
    TermFile {
        name: "friction_dissipation",
        sample: Keep::Required,
        ..FILE_BASE
    },
    TermFile {
        name: "viscous_dissipation",
        sample: Keep::Required,
        ..FILE_BASE
    },
    TermFile {
        name: "drag_dissipation",
        sample: Keep::Added,
        ..FILE_BASE
    },
    TermFile {
        name: "joint_dissipation",
        sample: Keep::Added,
        ..FILE_BASE
    },
    TermFile {
        name: "boundary_dissipation",
        sample: Keep::Added,
        ..FILE_BASE
    },
    TermFile {
        name: "fracture_dissipation",
        sample: Keep::Added,
        ..FILE_BASE
    },
    TermFile {
        name: "plastic_dissipation",
        summary: Keep::Added,
        sample: Keep::Added,
        ..FILE_BASE
    },
    TermFile {
        name: "contact_hysteresis",
        summary: Keep::Added,
        ..FILE_BASE
    },
    TermFile {
        name: "cut_away",
        summary: Keep::Added,
        ..FILE_BASE
    },
    TermFile {
        name: "elastic_energy",
        ..FILE_BASE
    },
    TermFile {
        name: "other_dissipation",
        ..FILE_BASE
    },
    TermFile {
        name: "normal_contact_work",
        summary: Keep::Added,
        sample: Keep::Added,
        ..FILE_BASE
    },
    TermFile {
        name: "normal_elastic_work",
        summary: Keep::Added,
        sample: Keep::Added,
        ..FILE_BASE
    },
    TermFile {
        name: "residual",
        ..FILE_BASE
    },
];

/// How the files keep the term named `name` (see [`super::term_index`]).
pub const fn term_file(name: &str) -> TermFile {
    LEDGER_FILES[super::terms::term_index(name)]
}

// Each row of LEDGER_FILES is the term of LEDGER_TERMS in the same place.
const _: () = {
    let mut k = 0;
    while k < N_TERMS {
        assert!(
            super::terms::str_eq(LEDGER_FILES[k].name, LEDGER_TERMS[k].name),
            "LEDGER_FILES out of step with LEDGER_TERMS"
        );
        k += 1;
    }
};

/// The terms a file keeps: a column of [`LEDGER_FILES`] (a marker type per file).
pub trait TermSet: Clone + Copy + fmt::Debug + Default + PartialEq {
    /// Whether the file keeps the term of index `k` in [`LEDGER_TERMS`].
    fn keep(k: usize) -> Keep;
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
        for (k, v) in values.iter_mut().enumerate() {
            if S::keep(k) == Keep::No {
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
        for (k, (v, x)) in values.iter_mut().zip(&self.values).enumerate() {
            if S::keep(k) != Keep::No {
                *v = *x;
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
            .enumerate()
            .position(|(k, t)| S::keep(k) != Keep::No && t.name == key)
    }
}

impl<S: TermSet> Serialize for Terms<S> {
    fn serialize<Z: Serializer>(&self, z: Z) -> Result<Z::Ok, Z::Error> {
        let n = (0..N_TERMS).filter(|&k| S::keep(k) != Keep::No).count();
        let mut map = z.serialize_map(Some(n))?;
        for (k, (t, v)) in LEDGER_TERMS.iter().zip(&self.values).enumerate() {
            if S::keep(k) != Keep::No {
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
        for (k, ((v, g), t)) in values.iter_mut().zip(got).zip(&LEDGER_TERMS).enumerate() {
            *v = match (g, S::keep(k)) {
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
    use super::super::terms::LedgerTerm;
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
        keep: fn(usize) -> Keep,
        energy: fn(&T) -> EnergyBudget,
    ) -> String
    where
        T: Serialize + DeserializeOwned + PartialEq + fmt::Debug,
    {
        let kept: Vec<(usize, &LedgerTerm)> = LEDGER_TERMS
            .iter()
            .enumerate()
            .filter(|&(k, _)| keep(k) != Keep::No)
            .collect();
        let mut full = json.clone();
        for &(k, t) in &kept {
            full[t.name] = (k as f64 + 1.0).into();
        }
        let x: T = serde_json::from_value(full.clone()).unwrap();
        for (k, (t, v)) in LEDGER_TERMS.iter().zip(energy(&x).values()).enumerate() {
            let want = if keep(k) == Keep::No {
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
        for (_, t) in LEDGER_TERMS
            .iter()
            .enumerate()
            .filter(|&(k, _)| keep(k) == Keep::No)
        {
            assert!(!text.contains(&format!("\"{}\":", t.name)), "{}", t.name);
        }
        assert_eq!(serde_json::from_str::<T>(&text).unwrap(), x);
        for &(k, t) in &kept {
            let mut less = full.clone();
            less.as_object_mut().unwrap().remove(t.name).unwrap();
            match (serde_json::from_value::<T>(less), keep(k)) {
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

    /// Every dissipation is kept by the samples, so the tables' gate sees it at every sample.
    #[test]
    fn every_dissipation_is_sampled() {
        for (t, f) in LEDGER_TERMS.iter().zip(&LEDGER_FILES) {
            assert!(!t.is_dissipation() || f.sample != Keep::No, "{}", t.name);
        }
    }
}
