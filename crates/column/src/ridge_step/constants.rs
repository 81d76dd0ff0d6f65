//! The constants of the complete ridging step: its thermodynamic constants
//! ([`RidgeStepParams`], Icepack's defaults, their list with units and their checks), the
//! salt-flux option of the clean-up ([`SaltFlux`]), and every constant of the step by name
//! ([`RidgeStepOptions`] as a [`NamedParams`] set: the ridging parameters `ItdParams` and
//! the thermodynamic constants, the one parser of `pressridge ridge-step --param` and of
//! Python's `ridge_step` keywords).

use super::RidgeStepOptions;
use crate::named_params::{NamedParams, ParamGroup, ParamMeta};
use crate::{ItdError, ItdParams};

/// How the zapped ice's salt flux is computed (Icepack `saltflux_option`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SaltFlux {
    /// Zapped ice carries [`RidgeStepParams::ice_ref_salinity`] (Icepack's default
    /// `"constant"`; salt is then not conserved by the clean-up).
    #[default]
    Constant,
    /// Zapped ice carries its own mean layer salinity (`"prognostic"`; conserving).
    Prognostic,
}

impl SaltFlux {
    /// Icepack's `saltflux_option` name: `constant` or `prognostic` (the command line's and
    /// Python's spelling too).
    pub fn name(self) -> &'static str {
        match self {
            SaltFlux::Constant => "constant",
            SaltFlux::Prognostic => "prognostic",
        }
    }

    /// The option called `name` (`constant` or `prognostic`).
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "constant" => Some(SaltFlux::Constant),
            "prognostic" => Some(SaltFlux::Prognostic),
            _ => None,
        }
    }
}

/// Thermodynamic constants and clean-up thresholds of the ridging step. `Default` is
/// Icepack's (`icepack_parameters.F90`, `icepack_therm_shared.F90`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RidgeStepParams {
    /// Snow density ρ_s (kg/m³). Icepack `rhos` = 330.
    pub rhos: f64,
    /// Latent heat of melting of fresh ice L_f (J/kg). Icepack `Lfresh` = Lsub − Lvap = 3.34e5.
    pub lfresh: f64,
    /// Specific heat of fresh ice (J kg⁻¹ K⁻¹). Icepack `cp_ice` = 2106.
    pub cp_ice: f64,
    /// Fraction of the snow on ridging ice that stays on the new ridge (1); the rest goes to
    /// the ocean. Icepack `fsnowrdg` = 0.5.
    pub fsnowrdg: f64,
    /// Salinity of zapped ice for [`SaltFlux::Constant`] (ppt). Icepack `ice_ref_salinity` = 4.
    pub ice_ref_salinity: f64,
    /// Salt-flux option of the clean-up.
    pub salt_flux: SaltFlux,
    /// Cell ice area (1) below which all ice is zapped. Icepack `itd_area_min` = 1e-11.
    pub itd_area_min: f64,
    /// Cell ice mass ρ_i·aice (kg/m², as Icepack computes it) below which all ice is zapped.
    /// Icepack `itd_mass_min` = 1e-10.
    pub itd_mass_min: f64,
    /// Snow thickness (m) above which the snow temperature is checked. Icepack `hs_min` = 1e-4.
    pub hs_min: f64,
    /// Lowest physical snow temperature (°C). Icepack `Tmin` = −100.
    pub tmin: f64,
}

impl Default for RidgeStepParams {
    fn default() -> Self {
        Self {
            rhos: 330.0,
            lfresh: 2.835e6 - 2.501e6,
            cp_ice: 2106.0,
            fsnowrdg: 0.5,
            ice_ref_salinity: 4.0,
            salt_flux: SaltFlux::Constant,
            itd_area_min: 1e-11,
            itd_mass_min: 1e-10,
            hs_min: 1e-4,
            tmin: -100.0,
        }
    }
}

/// Name, units and meaning of one settable constant of [`RidgeStepParams`] (the type the
/// [`ItdParams`] fields are listed with too).
pub type StepParamMeta = ParamMeta;

impl RidgeStepParams {
    /// The numeric constants, in field order: the one list the faces (command line
    /// `--param`, Python keywords, output attributes) take their names and units from.
    /// [`RidgeStepParams::salt_flux`] is an option, not a number, and is not in it.
    pub const FIELDS: &'static [StepParamMeta] = &[
        ParamMeta::new("rhos", "kg m-3", "snow density (Icepack rhos)"),
        ParamMeta::new(
            "lfresh",
            "J kg-1",
            "latent heat of melting of fresh ice (Icepack Lfresh)",
        ),
        ParamMeta::new(
            "cp_ice",
            "J kg-1 K-1",
            "specific heat of fresh ice (Icepack cp_ice)",
        ),
        ParamMeta::new(
            "fsnowrdg",
            "1",
            "fraction of the snow on ridging ice that stays on the ridge (Icepack fsnowrdg)",
        ),
        ParamMeta::new(
            "ice_ref_salinity",
            "ppt",
            "salinity of zapped ice with the constant salt flux (Icepack ice_ref_salinity)",
        ),
        ParamMeta::new(
            "itd_area_min",
            "1",
            "cell ice area below which all ice is zapped (Icepack itd_area_min)",
        ),
        ParamMeta::new(
            "itd_mass_min",
            "kg m-2",
            "cell ice mass below which all ice is zapped (Icepack itd_mass_min)",
        ),
        ParamMeta::new(
            "hs_min",
            "m",
            "snow thickness above which the snow temperature is checked (Icepack hs_min)",
        ),
        ParamMeta::new(
            "tmin",
            "degC",
            "lowest physical snow temperature (Icepack Tmin)",
        ),
    ];

    /// The value of the constant `name` (a [`RidgeStepParams::FIELDS`] name), in its units.
    pub fn get(&self, name: &str) -> Option<f64> {
        Some(match name {
            "rhos" => self.rhos,
            "lfresh" => self.lfresh,
            "cp_ice" => self.cp_ice,
            "fsnowrdg" => self.fsnowrdg,
            "ice_ref_salinity" => self.ice_ref_salinity,
            "itd_area_min" => self.itd_area_min,
            "itd_mass_min" => self.itd_mass_min,
            "hs_min" => self.hs_min,
            "tmin" => self.tmin,
            _ => return None,
        })
    }

    /// Sets the constant `name` (a [`RidgeStepParams::FIELDS`] name, units as listed there).
    /// Rejects unknown names and values [`RidgeStepParams::validate`] refuses; a rejected
    /// value leaves `self` unchanged.
    pub fn set(&mut self, name: &str, value: f64) -> Result<(), ItdError> {
        let mut new = *self;
        let slot = match name {
            "rhos" => &mut new.rhos,
            "lfresh" => &mut new.lfresh,
            "cp_ice" => &mut new.cp_ice,
            "fsnowrdg" => &mut new.fsnowrdg,
            "ice_ref_salinity" => &mut new.ice_ref_salinity,
            "itd_area_min" => &mut new.itd_area_min,
            "itd_mass_min" => &mut new.itd_mass_min,
            "hs_min" => &mut new.hs_min,
            "tmin" => &mut new.tmin,
            _ => {
                return Err(ItdError::Parameter {
                    name: "unknown",
                    value,
                    reason: "unknown ridging-step constant (see RidgeStepParams::FIELDS)".into(),
                });
            }
        };
        *slot = value;
        new.validate()?;
        *self = new;
        Ok(())
    }

    /// Checks every value (finite; densities, heats and thresholds positive; `fsnowrdg` in
    /// [0, 1]; `ice_ref_salinity` ≥ 0).
    pub fn validate(&self) -> Result<(), ItdError> {
        let bad = |name: &'static str, value: f64, reason: &'static str| {
            Err(ItdError::Parameter {
                name,
                value,
                reason: reason.into(),
            })
        };
        for (name, v) in [
            ("rhos", self.rhos),
            ("lfresh", self.lfresh),
            ("cp_ice", self.cp_ice),
            ("itd_area_min", self.itd_area_min),
            ("itd_mass_min", self.itd_mass_min),
            ("hs_min", self.hs_min),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return bad(name, v, "must be finite and positive");
            }
        }
        if !(self.fsnowrdg >= 0.0 && self.fsnowrdg <= 1.0) {
            return bad("fsnowrdg", self.fsnowrdg, "must be in [0, 1]");
        }
        if !(self.ice_ref_salinity.is_finite() && self.ice_ref_salinity >= 0.0) {
            return bad("ice_ref_salinity", self.ice_ref_salinity, "must be >= 0");
        }
        if !self.tmin.is_finite() {
            return bad("tmin", self.tmin, "must be finite");
        }
        Ok(())
    }
}

impl NamedParams for RidgeStepParams {
    const GROUPS: &'static [ParamGroup] = &[ParamGroup {
        label: "valid names",
        fields: RidgeStepParams::FIELDS,
    }];

    fn get(&self, name: &str) -> Option<f64> {
        RidgeStepParams::get(self, name)
    }

    fn set(&mut self, name: &str, value: f64) -> Result<(), ItdError> {
        RidgeStepParams::set(self, name, value)
    }
}

/// Every constant of the complete step by name: the ridging parameters (`params`, an
/// [`ItdParams`] name) and the thermodynamic constants (`step`, a [`RidgeStepParams`] name).
/// The options that are not numbers (participation, salt flux, ...) are not among them.
impl NamedParams for RidgeStepOptions {
    const GROUPS: &'static [ParamGroup] = &[
        ParamGroup {
            label: "ridging parameters",
            fields: ItdParams::FIELDS,
        },
        ParamGroup {
            label: "constants of the complete step",
            fields: RidgeStepParams::FIELDS,
        },
    ];

    fn get(&self, name: &str) -> Option<f64> {
        self.params.get(name).or_else(|| self.step.get(name))
    }

    fn set(&mut self, name: &str, value: f64) -> Result<(), ItdError> {
        if ItdParams::NAMES.contains(&name) {
            self.params.set(name, value)
        } else {
            self.step.set(name, value)
        }
    }
}

#[cfg(test)]
mod step_param_tests {
    use super::*;

    /// Every listed constant reads and writes its own field; bad values are refused by name
    /// and leave the parameters unchanged.
    #[test]
    fn fields_list_get_and_set_agree() {
        let d = RidgeStepParams::default();
        for f in RidgeStepParams::FIELDS {
            let v = d.get(f.name).unwrap();
            let mut p = d;
            p.set(f.name, v * 0.5 + 0.25).unwrap();
            assert_eq!(p.get(f.name), Some(v * 0.5 + 0.25), "{}", f.name);
            for g in RidgeStepParams::FIELDS.iter().filter(|g| g.name != f.name) {
                assert_eq!(p.get(g.name), d.get(g.name), "{} moved {}", f.name, g.name);
            }
        }
        let mut p = d;
        let e = p.set("rhos", -1.0).unwrap_err().to_string();
        assert!(e.contains("rhos"), "{e}");
        assert!(
            p.set("fsnowrdg", 1.5)
                .unwrap_err()
                .to_string()
                .contains("fsnowrdg")
        );
        assert!(p.set("nope", 1.0).is_err());
        assert_eq!(p, d);
        assert_eq!(
            SaltFlux::from_name("prognostic"),
            Some(SaltFlux::Prognostic)
        );
        assert_eq!(
            SaltFlux::from_name(SaltFlux::Constant.name()),
            Some(SaltFlux::Constant)
        );
    }
}
