//! Physical constants and tunable parameters of the thickness-distribution physics.
//!
//! Every value is a named, overridable field of [`ItdParams`] whose [`Default`] is the
//! CICE/Icepack default (`icepack_parameters.F90`, `icepack_mechred.F90`). Units are SI.
//! Overrides by name (`--param`, Python's keywords) go through [`NamedParams`].

use super::mu_rdg::MuRdgTable;
use super::named_params::{NamedParams, ParamGroup, ParamMeta};

/// Parameters of participation, redistribution, strength and the ridging step.
///
/// `ItdParams::default()` reproduces CICE/Icepack; change any field to override it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ItdParams {
    /// Density of sea ice ρ_i (kg/m³). CICE `rhoi` = 917.
    pub rhoi: f64,
    /// Density of sea water ρ_w (kg/m³). CICE `rhow` = 1026.
    pub rhow: f64,
    /// Gravitational acceleration g (m/s²). CICE `gravit` = 9.80616.
    pub gravit: f64,
    /// Thorndike et al. (1975) participation cut-off G* (dimensionless). CICE `Gstar` = 0.15.
    pub gstar: f64,
    /// Lipscomb et al. (2007) exponential participation scale a* (dimensionless).
    /// CICE `astar` = 0.05.
    pub astar: f64,
    /// Hibler (1980) ridge thickness scale H* (m) of the uniform redistribution.
    /// CICE `Hstar` = 25.
    pub hstar: f64,
    /// Largest thickness of ice that rafts rather than ridges (m): h_min = min(2h, h + maxraft).
    /// CICE `maxraft` = 1.
    pub maxraft: f64,
    /// Lipscomb et al. (2007) e-folding parameter μ (m^½) of the exponential redistribution,
    /// λ = μ·√h. CICE `mu_rdg` = 3.
    pub mu_rdg: f64,
    /// Fraction of the shear deformation energy that goes into ridging, C_s
    /// (dimensionless; Flato and Hibler 1995). CICE `Cs` = 0.25.
    pub cs: f64,
    /// Hibler (1979) strength parameter P* (N/m²). CICE `Pstar` = 2.75e4.
    pub pstar: f64,
    /// Hibler (1979) concentration parameter C* (dimensionless). CICE `Cstar` = 20.
    pub cstar: f64,
    /// Smallest area treated as non-zero (dimensionless). CICE `puny` = 1e-11.
    pub puny: f64,
    /// Largest argument of the exponentials of the redistribution (underflow guard).
    /// CICE `exp_argmax` = 100.
    pub exp_argmax: f64,
    /// Upper bound (m) given to the thickest category in the ridging step so that all ridged
    /// ice fits below it (CICE `ridge_prep`: `big` = 1e8).
    pub big: f64,
    /// Maximum number of ridging iterations. CICE `nitermax` = 20.
    pub nitermax: usize,
    /// pressridge (not CICE): tolerance on |aice0 + Σ aicen − 1| for the strength routine.
    /// A ridging step always leaves a total area of 1, so a larger departure is bad input.
    /// Default 1e-6 (accepts single-precision files).
    pub area_tolerance: f64,
    /// pressridge (not CICE): largest total area aice0 + Σ aicen accepted as input of a
    /// ridging step (what advection can leave behind). Default 2.
    pub max_area_before_ridging: f64,
}

impl Default for ItdParams {
    fn default() -> Self {
        Self {
            rhoi: 917.0,
            rhow: 1026.0,
            gravit: 9.80616,
            gstar: 0.15,
            astar: 0.05,
            hstar: 25.0,
            maxraft: 1.0,
            mu_rdg: 3.0,
            cs: 0.25,
            pstar: 2.75e4,
            cstar: 20.0,
            puny: 1.0e-11,
            exp_argmax: 100.0,
            big: 1.0e8,
            nitermax: 20,
            area_tolerance: 1.0e-6,
            max_area_before_ridging: 2.0,
        }
    }
}

/// The [`ItdParams`] fields, in field order (a fixed-size array so that
/// [`ItdParams::NAMES`] can be computed from it at compile time).
const ITD_FIELDS: [ParamMeta; 17] = [
    ParamMeta::new("rhoi", "kg m-3", "density of sea ice (CICE rhoi)"),
    ParamMeta::new("rhow", "kg m-3", "density of sea water (CICE rhow)"),
    ParamMeta::new(
        "gravit",
        "m s-2",
        "gravitational acceleration (CICE gravit)",
    ),
    ParamMeta::new(
        "gstar",
        "1",
        "participation cut-off G* of Thorndike et al. 1975 (CICE Gstar)",
    ),
    ParamMeta::new(
        "astar",
        "1",
        "exponential participation scale a* of Lipscomb et al. 2007 (CICE astar)",
    ),
    ParamMeta::new(
        "hstar",
        "m",
        "ridge thickness scale H* of the uniform redistribution, Hibler 1980 (CICE Hstar)",
    ),
    ParamMeta::new(
        "maxraft",
        "m",
        "largest thickness of ice that rafts rather than ridges (CICE maxraft)",
    ),
    ParamMeta::new(
        "mu_rdg",
        "m^0.5",
        "e-folding parameter mu of the exponential redistribution, Lipscomb et al. 2007 (CICE mu_rdg)",
    ),
    ParamMeta::new(
        "cs",
        "1",
        "fraction C_s of the shear deformation energy that goes into ridging (CICE Cs)",
    ),
    ParamMeta::new(
        "pstar",
        "N m-2",
        "strength parameter P* of Hibler 1979 (CICE Pstar)",
    ),
    ParamMeta::new(
        "cstar",
        "1",
        "concentration parameter C* of Hibler 1979 (CICE Cstar)",
    ),
    ParamMeta::new("puny", "1", "smallest area treated as non-zero (CICE puny)"),
    ParamMeta::new(
        "exp_argmax",
        "1",
        "largest argument of the exponentials of the redistribution (CICE exp_argmax)",
    ),
    ParamMeta::new(
        "big",
        "m",
        "upper bound given to the thickest category in the ridging step (CICE big, ridge_prep)",
    ),
    ParamMeta::new(
        "nitermax",
        "1",
        "maximum number of ridging iterations, a whole number (CICE nitermax)",
    ),
    ParamMeta::new(
        "area_tolerance",
        "1",
        "tolerance on |aice0 + sum(aicen) - 1| of the strength input (pressridge)",
    ),
    ParamMeta::new(
        "max_area_before_ridging",
        "1",
        "largest total area aice0 + sum(aicen) accepted by the ridging step (pressridge)",
    ),
];

/// The names of `fields`, in order.
const fn names_of<const N: usize>(fields: &[ParamMeta; N]) -> [&'static str; N] {
    let mut out = [""; N];
    let mut i = 0;
    while i < N {
        out[i] = fields[i].name;
        i += 1;
    }
    out
}

const ITD_NAMES: [&str; ITD_FIELDS.len()] = names_of(&ITD_FIELDS);

impl ItdParams {
    /// The parameters, in field order: the one list the faces take their names from
    /// (`NAMES`, `set`/`get`, the command line's `--param`, Python's `PARAMETERS` and
    /// `DEFAULT_PARAMETERS`). The C struct `PressridgeParams` and the Fortran type
    /// `pressridge_params` are checked against it by `tests/params_faces.rs`.
    pub const FIELDS: &'static [ParamMeta] = &ITD_FIELDS;

    /// Names accepted by [`ItdParams::set`] (the field names, those of [`ItdParams::FIELDS`]).
    pub const NAMES: &'static [&'static str] = &ITD_NAMES;

    /// The value of the parameter `name` (an [`ItdParams::FIELDS`] name), in its units;
    /// `nitermax` as a float.
    pub fn get(&self, name: &str) -> Option<f64> {
        Some(match name {
            "rhoi" => self.rhoi,
            "rhow" => self.rhow,
            "gravit" => self.gravit,
            "gstar" => self.gstar,
            "astar" => self.astar,
            "hstar" => self.hstar,
            "maxraft" => self.maxraft,
            "mu_rdg" => self.mu_rdg,
            "cs" => self.cs,
            "pstar" => self.pstar,
            "cstar" => self.cstar,
            "puny" => self.puny,
            "exp_argmax" => self.exp_argmax,
            "big" => self.big,
            "nitermax" => self.nitermax as f64,
            "area_tolerance" => self.area_tolerance,
            "max_area_before_ridging" => self.max_area_before_ridging,
            _ => return None,
        })
    }

    /// Overrides one parameter by its field name (an [`ItdParams::FIELDS`] name, e.g.
    /// `"mu_rdg"`, units as listed there).
    /// Rejects unknown names and values that are not finite and positive (`cs` and
    /// `maxraft` may be 0; `nitermax` must be a whole number ≥ 1; `rhow` must exceed `rhoi`).
    pub fn set(&mut self, name: &str, value: f64) -> Result<(), super::ItdError> {
        let bad = |reason: &'static str| super::ItdError::Parameter {
            name: Self::NAMES
                .iter()
                .find(|n| **n == name)
                .copied()
                .unwrap_or("unknown"),
            value,
            reason: reason.into(),
        };
        if !value.is_finite() {
            return Err(bad("must be finite"));
        }
        let may_be_zero = matches!(name, "cs" | "maxraft");
        if value < 0.0 || (value == 0.0 && !may_be_zero) {
            return Err(bad("must be positive"));
        }
        // Work on a copy so that a rejected value leaves `self` unchanged.
        let mut new = *self;
        match name {
            "rhoi" => new.rhoi = value,
            "rhow" => new.rhow = value,
            "gravit" => new.gravit = value,
            "gstar" => new.gstar = value,
            "astar" => new.astar = value,
            "hstar" => new.hstar = value,
            "maxraft" => new.maxraft = value,
            "mu_rdg" => new.mu_rdg = value,
            "cs" => new.cs = value,
            "pstar" => new.pstar = value,
            "cstar" => new.cstar = value,
            "puny" => new.puny = value,
            "exp_argmax" => new.exp_argmax = value,
            "big" => new.big = value,
            "nitermax" => {
                if value.fract() != 0.0 || value < 1.0 {
                    return Err(bad("must be a whole number >= 1"));
                }
                new.nitermax = value as usize;
            }
            "area_tolerance" => new.area_tolerance = value,
            "max_area_before_ridging" => new.max_area_before_ridging = value,
            _ => return Err(bad("unknown parameter name (see ItdParams::NAMES)")),
        }
        if new.rhow <= new.rhoi {
            return Err(bad("rhow must exceed rhoi"));
        }
        *self = new;
        Ok(())
    }

    /// Rothrock (1975) potential-energy coefficient C_p = g·ρ_i·(ρ_w − ρ_i)/(2ρ_w) (kg m⁻² s⁻²,
    /// i.e. N/m³), evaluated in the same order as Icepack's `Cp` so results match to the bit.
    pub fn cp(&self) -> f64 {
        0.5 * self.gravit * (self.rhow - self.rhoi) * self.rhoi / self.rhow
    }
}

impl NamedParams for ItdParams {
    const GROUPS: &'static [ParamGroup] = &[ParamGroup {
        label: "valid names",
        fields: ItdParams::FIELDS,
    }];

    fn get(&self, name: &str) -> Option<f64> {
        ItdParams::get(self, name)
    }

    fn set(&mut self, name: &str, value: f64) -> Result<(), super::ItdError> {
        ItdParams::set(self, name, value)
    }
}

/// Participation function b(h) (Thorndike et al. 1975; Lipscomb et al. 2007).
/// CICE `krdg_partic`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Participation {
    /// Thorndike et al. (1975): b = (2/G*)(1 − G/G*) for G < G* (CICE `krdg_partic = 0`).
    Thorndike,
    /// Lipscomb et al. (2007): b ∝ exp(−G/a*) (CICE `krdg_partic = 1`, the default).
    #[default]
    Exponential,
}

/// Thickness distribution of newly ridged ice. CICE `krdg_redist`.
// The table variant holds its nodes inline (about 520 bytes) so that the options stay `Copy`
// for a host's per-cell calls; a box would make every options struct own a heap value.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Redistribution {
    /// Hibler (1980): uniform between h_min = min(2h, h + maxraft) and 2√(H*·h)
    /// (CICE `krdg_redist = 0`).
    Uniform,
    /// Lipscomb et al. (2007): exp(−(h_r − h_min)/λ) for h_r ≥ h_min, λ = μ√h
    /// (CICE `krdg_redist = 1`, the default).
    #[default]
    Exponential,
    /// Lipscomb's exponential with μ_rdg per category thickness h from a table of simulated
    /// ridges (m^½; [`MuRdgTable`], clamped at its ends and counted): λ = μ_rdg(h)·√h.
    Table(MuRdgTable),
}

/// Ice strength formula. CICE `kstrength`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum StrengthFormula {
    /// Rothrock (1975) energetics with a frictional factor C_f (CICE `kstrength = 1`, default).
    #[default]
    Rothrock,
    /// Hibler (1979): P = P*·h·exp(−C*(1 − A)) (CICE `kstrength = 0`).
    Hibler1979,
}

impl Participation {
    /// Every option, in the order the faces list them.
    pub const ALL: [Participation; 2] = [Participation::Thorndike, Participation::Exponential];

    /// The option called `name` (its [`Participation::name`]; the command line's and Python's
    /// spelling).
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "thorndike" => Some(Participation::Thorndike),
            "exponential" => Some(Participation::Exponential),
            _ => None,
        }
    }

    /// Short lower-case name used in the CLI and in NetCDF attributes.
    pub fn name(self) -> &'static str {
        match self {
            Participation::Thorndike => "thorndike",
            Participation::Exponential => "exponential",
        }
    }
}

impl Redistribution {
    /// Every option, in the order the faces list them.
    pub const ALL: [Redistribution; 2] = [Redistribution::Uniform, Redistribution::Exponential];

    /// The option called `name` (its [`Redistribution::name`]; the command line's and Python's
    /// spelling).
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "uniform" => Some(Redistribution::Uniform),
            "exponential" => Some(Redistribution::Exponential),
            _ => None,
        }
    }

    /// Short lower-case name used in the CLI and in NetCDF attributes.
    pub fn name(&self) -> &'static str {
        match self {
            Redistribution::Uniform => "uniform",
            Redistribution::Exponential => "exponential",
            Redistribution::Table(_) => "table",
        }
    }

    /// Whether the ridged ice is spread exponentially (Lipscomb et al. 2007), with one μ_rdg
    /// or a table of them.
    pub fn is_exponential(&self) -> bool {
        matches!(self, Redistribution::Exponential | Redistribution::Table(_))
    }

    /// The μ_rdg table, if the redistribution is [`Redistribution::Table`].
    pub fn mu_rdg_table(&self) -> Option<&MuRdgTable> {
        match self {
            Redistribution::Table(t) => Some(t),
            _ => None,
        }
    }
}

impl StrengthFormula {
    /// Every option, in the order the faces list them.
    pub const ALL: [StrengthFormula; 2] = [StrengthFormula::Rothrock, StrengthFormula::Hibler1979];

    /// The option called `name` (its [`StrengthFormula::name`]; the command line's and Python's
    /// spelling).
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "rothrock" => Some(StrengthFormula::Rothrock),
            "hibler" => Some(StrengthFormula::Hibler1979),
            _ => None,
        }
    }

    /// Short lower-case name used in the CLI and in NetCDF attributes.
    pub fn name(self) -> &'static str {
        match self {
            StrengthFormula::Rothrock => "rothrock",
            StrengthFormula::Hibler1979 => "hibler",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::details::ParamError;

    /// The field list, `get` and `set` agree with each other and with the struct's own
    /// fields (read, names and values, from its `Debug` form).
    #[test]
    fn fields_list_get_set_and_struct_agree() {
        let d = ItdParams::default();
        assert_eq!(
            ItdParams::NAMES,
            ItdParams::FIELDS.iter().map(|f| f.name).collect::<Vec<_>>()
        );
        // A distinct, valid value in every field.
        let mut p = d;
        for (i, f) in ItdParams::FIELDS.iter().enumerate() {
            let v = d.get(f.name).unwrap();
            let new = if f.name == "nitermax" {
                v + 1.0
            } else {
                v * (1.0 + 0.01 * (i + 1) as f64)
            };
            let before = p;
            p.set(f.name, new).unwrap();
            assert_eq!(p.get(f.name), Some(new), "{}", f.name);
            for g in ItdParams::FIELDS.iter().filter(|g| g.name != f.name) {
                assert_eq!(
                    p.get(g.name),
                    before.get(g.name),
                    "{} moved {}",
                    f.name,
                    g.name
                );
            }
        }
        // The struct's fields, in order, with the values `get` gives.
        let debug = format!("{p:?}");
        let body = debug
            .strip_prefix("ItdParams { ")
            .and_then(|b| b.strip_suffix(" }"))
            .unwrap_or_else(|| panic!("unexpected Debug form {debug}"));
        let fields: Vec<(&str, f64)> = body
            .split(", ")
            .map(|kv| {
                let (k, v) = kv.split_once(": ").unwrap();
                (k, v.parse().unwrap())
            })
            .collect();
        assert_eq!(
            fields.iter().map(|(k, _)| *k).collect::<Vec<_>>(),
            ItdParams::NAMES,
            "ItdParams::FIELDS must list every field, in field order"
        );
        for (k, v) in fields {
            assert_eq!(p.get(k), Some(v), "{k}");
        }
        for f in ItdParams::FIELDS {
            assert!(
                !f.units.is_empty() && !f.description.is_empty(),
                "{}",
                f.name
            );
        }
        assert_eq!(d.get("nope"), None);
        let mut q = d;
        assert!(q.set("nope", 1.0).is_err());
        assert_eq!(q, d);
    }

    /// The option names round-trip, and the named overrides parse as the faces need.
    #[test]
    fn names_and_settings_parse() {
        for p in Participation::ALL {
            assert_eq!(Participation::from_name(p.name()), Some(p));
        }
        for r in Redistribution::ALL {
            assert_eq!(Redistribution::from_name(r.name()), Some(r));
        }
        for f in StrengthFormula::ALL {
            assert_eq!(StrengthFormula::from_name(f.name()), Some(f));
        }
        assert_eq!(Participation::from_name("linear"), None);
        let p = ItdParams::from_settings(&[" mu_rdg = 4", "cs=0.5"]).unwrap();
        assert_eq!((p.mu_rdg, p.cs), (4.0, 0.5));
        assert_eq!(
            ItdParams::from_pairs([("mu_rdg", 4.0), ("cs", 0.5)]).unwrap(),
            p
        );
        let e = ItdParams::from_settings(&["mu_rgd=4"])
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with(
                "unknown parameter `mu_rgd` (did you mean `mu_rdg`?); valid names: rhoi, "
            ),
            "{e}"
        );
        let e = ItdParams::from_pairs([("zzzzzzzz", 1.0)])
            .unwrap_err()
            .to_string();
        assert!(!e.contains("did you mean"), "{e}");
        assert_eq!(
            ItdParams::from_settings(&["mu_rdg"]).unwrap_err(),
            ParamError::Malformed {
                item: "mu_rdg".into()
            }
        );
        assert!(matches!(
            ItdParams::from_settings(&["mu_rdg=x"]),
            Err(ParamError::NotANumber { .. })
        ));
        assert!(matches!(
            ItdParams::from_settings(&["mu_rdg=-1"]),
            Err(ParamError::Invalid(_))
        ));
    }
}
