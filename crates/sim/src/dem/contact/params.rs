//! The contact law's parameters, eqs (2)–(4): stiffnesses, eq (3)'s damping and its reading,
//! the friction and the optional plastic limit.

use serde::{Deserialize, Serialize};

/// Whose critical damping eq (3)'s k_nv is a fraction of.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum DampingLaw {
    /// As the paper writes it: k_nv = f·2·sqrt(k_ne·h·ρ_i), the critical damping per unit
    /// chord of a slab of the parent sheet's thickness h pressed flat on a rigid face, the
    /// same for every contact (dashpot c = k_nv·L on the approach speed). A contact of chord
    /// L between bodies of inverse effective normal mass κ then has the damping ratio
    /// ζ = f·sqrt(L·h·ρ_i·κ): about 0.1 at a 1-cm corner chord against a 0.9-m piece.
    #[default]
    Sheet,
    /// Each contact gets the fraction f of its own critical damping, c = f·2·sqrt(k_ne·L/κ)
    /// (k_ne·L its normal stiffness per metre of approach, 1/κ its effective mass along
    /// the normal): ζ = f at every chord.
    Contact,
}

impl DampingLaw {
    /// True for [`DampingLaw::Sheet`] (a serde skip test).
    pub fn is_sheet(&self) -> bool {
        *self == DampingLaw::Sheet
    }
}

/// A serde skip test for a value that is absent when zero.
pub(crate) fn is_zero_f64(x: &f64) -> bool {
    *x == 0.0
}

/// Parameters of the contact law. Defaults follow Hopkins (1994), Table 1 and the text of
/// "Numerical Ridge Growth Experiments".
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ContactParams {
    /// Normal elastic stiffness k_ne (N/m³): force per metre of depth per m² of overlap,
    /// eq (2). Default 1e8 (Table 1).
    pub normal_stiffness: f64,
    /// Fraction of the critical damping 2·sqrt(k_ne·h·ρ_i) used for k_nv, eq (3).
    /// Default 0.5 ("50% of the critical damping value").
    pub damping_fraction: f64,
    /// Tangential stiffness k_te of eq (4) as a fraction of the contact's own normal
    /// stiffness: k_te = `tangential_fraction`·k_ne·L (N/m² per metre of slip), L the
    /// contact's chord, as in every incremental-slip contact law (Cundall–Strack's k_s/k_n).
    /// Default 0.6 ("60% of the normal value", Hopkins 1994).
    pub tangential_fraction: f64,
    /// Thickness h of the parent sheet (m) in k_nv = f·2·sqrt(k_ne·h·ρ_i), eq (3). Unset (the
    /// default), scenes take their sheet's thickness, or [`DEFAULT_REFERENCE_THICKNESS`] when
    /// they have no sheet.
    pub reference_thickness: Option<f64>,
    /// Friction coefficient μ for contacts whose overlap centroid is above the water line
    /// (dimensionless). Default 1.0 (the value the paper adopts after its friction study).
    pub mu: f64,
    /// Friction coefficient μ_w for contacts whose overlap centroid is below the water line
    /// (dimensionless). Default 0.6.
    pub mu_water: f64,
    /// Whose critical damping `damping_fraction` refers to ([`DampingLaw`]). Default
    /// [`DampingLaw::Sheet`], eq (3) as written ("2(k_ne·h·ρ_i)^½, where h is the thickness
    /// and ρ_i the density of the parent sheet"); absent from scenes at the default. Read per
    /// contact on twelve seeds (docs/choices.md) it raises W at μ = 0.4 by 194 kJ/m
    /// [+38, +350] and moves none of the other sinks at μ = 0.4 or 1.0.
    #[serde(default, skip_serializing_if = "DampingLaw::is_sheet")]
    pub damping_law: DampingLaw,
    /// Crushing pressure p_c (Pa) that caps the elastic normal force of eq (2) at p_c·L, the
    /// pressure on the contact's chord L over the 1-m depth: overlap pressed beyond the cap
    /// is crushed, kept as the contact's plastic overlap A_p (F_e = k_ne·(A − A_p) after),
    /// and its work p_c·ΔA_p is dissipated (`plastic_dissipation`, part of eq (12)'s Φ_i).
    /// Default 0: no cap (the 1994 paper's "viscous elastic normal force model"); absent
    /// from scenes at the default. At 1 MPa it crushes 0.06 % of W at the Figure 5 point and
    /// moves no other quantity (four seeds, docs/choices.md).
    #[serde(default, skip_serializing_if = "is_zero_f64")]
    pub crushing_pressure: f64,
}

impl Default for ContactParams {
    fn default() -> Self {
        Self {
            normal_stiffness: 1e8,
            damping_fraction: 0.5,
            tangential_fraction: 0.6,
            reference_thickness: None,
            mu: 1.0,
            mu_water: 0.6,
            damping_law: DampingLaw::Sheet,
            crushing_pressure: 0.0,
        }
    }
}

/// Reference thickness of scenes without a sheet: 0.30 m, the sheet of the paper's Figure 5.
pub const DEFAULT_REFERENCE_THICKNESS: f64 = 0.30;

impl ContactParams {
    /// The reference thickness h in use (m).
    pub(crate) fn thickness(&self) -> f64 {
        self.reference_thickness
            .unwrap_or(DEFAULT_REFERENCE_THICKNESS)
    }
    /// Viscous normal coefficient k_nv (kg/(m²·s)): `damping_fraction · 2·sqrt(k_ne·h·ρ_i)`
    /// for ice density `rho_i` (kg/m³), eq (3).
    pub fn viscous_coefficient(&self, rho_i: f64) -> f64 {
        self.damping_fraction * 2.0 * (self.normal_stiffness * self.thickness() * rho_i).sqrt()
    }
    /// Tangential stiffness of eq (4) per metre of a contact's chord L (N/m³): a contact's
    /// k_te = `tangential_fraction`·k_ne·L (N/m²), 60 % of its normal stiffness k_ne·L.
    pub fn tangential_stiffness_per_chord(&self) -> f64 {
        self.tangential_fraction * self.normal_stiffness
    }
}
