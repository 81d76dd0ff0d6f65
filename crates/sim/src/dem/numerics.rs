//! The numerical options of the step that the paper does not fix and several modules read:
//! how eq (3)'s contact dashpot and the joints' dashpot are advanced ([`Dashpot`]), how a
//! new contact reads its first rate of overlap ([`ContactOnset`]), and the one struct of a
//! step's numerics that the world passes to every force stage ([`StepNumerics`]). `world`,
//! `contact`, `joint` and `fracture` import them from here; nothing here imports them back.

use serde::{Deserialize, Serialize};

/// How the viscous normal contact force of eq (3), F_v = k_nv·(Aⁿ − Aⁿ⁻¹)/Δt, is advanced.
///
/// The overlap rate (Aⁿ − Aⁿ⁻¹)/Δt is the approach speed at n − ½ times the chord L, so
/// eq (3) is a dashpot c = k_nv·L on the normal velocity. Taken explicitly, a dashpot of
/// damping ratio ζ limits the leapfrog step to ω·Δt < 2·(sqrt(1 + ζ²) − ζ): 0.49 for the
/// stiffest contact of a ridge (ζ ≈ 1.9), a quarter of the undamped limit.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Dashpot {
    /// Eq (3) as the paper writes it, explicit in the overlap rate.
    Explicit,
    /// Eq (3) at the pair's mid-step approach speed: with u⁻ = (Aⁿ − Aⁿ⁻¹)/(Δt·L) (the
    /// paper's rate) and c = k_nv·L, F_v = c·ū where ū = u⁻ − ½·Δt·(aₙ + κ·F_v): aₙ is
    /// the relative acceleration along the normal of the two contact points under every
    /// other force of the step (gravity, buoyancy, joints, all contacts' elastic forces),
    /// κ the pair's inverse effective mass along the normal (1/m + (r×n)²/I per body, over
    /// its free degrees of freedom). Solved: F_v = (k_nv·(Aⁿ − Aⁿ⁻¹)/Δt − ½·c·Δt·aₙ)/(1 + x),
    /// x = ½·c·Δt·κ. ū is the leapfrog's mid-step approach speed, so the dashpot is centred
    /// in time; it tends to eq (3) as Δt → 0, is zero on a contact at rest, and an
    /// isolated pair is stable for ω·Δt < 2 whatever ζ.
    #[default]
    Implicit,
}

/// How a new contact's viscous force of eq (3) reads its first rate of overlap.
///
/// Eq (3) takes the rate as (Aⁿ − Aⁿ⁻¹)/Δt. A contact begins somewhere within the step, so in
/// its first step Aⁿ⁻¹ = 0 and Aⁿ/Δt is on average half the rate at which the overlap grows
/// by then: the first step of every impact is under-damped, an error of first order in Δt
/// that makes impacts more elastic at larger steps (`docs/notes/speed-vs-error-former-model.md`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ContactOnset {
    /// Eq (3) as written, from the change of area (the paper's).
    #[default]
    Area,
    /// In a contact's first step, the rate L·v_n from the chord L and the two blocks'
    /// approach speed v_n along the normal at the overlap centroid (at n − ½, as the
    /// friction law reads the tangential speed); from the second step on, eq (3) as written.
    /// Experimental.
    Velocity,
}

impl ContactOnset {
    /// True for [`ContactOnset::Area`] (a serde skip test).
    pub fn is_area(&self) -> bool {
        *self == ContactOnset::Area
    }
}

impl Dashpot {
    /// [`Dashpot::Explicit`], the joints' default (a serde default).
    pub fn explicit() -> Dashpot {
        Dashpot::Explicit
    }
    /// True for [`Dashpot::Explicit`] (a serde skip test).
    pub fn is_explicit(&self) -> bool {
        *self == Dashpot::Explicit
    }
}

/// The numerics of one time step, made by the world once per step and read by every stage
/// that needs them (contacts, joints, fracture), so that none takes them one by one.
#[derive(Clone, Copy, Debug)]
pub(crate) struct StepNumerics {
    /// The time step Δt (s): this step's drift of the poses, xⁿ⁺¹ = xⁿ + Δt·vⁿ⁺½.
    pub dt: f64,
    /// The previous step's Δt (s): the time between the last pose and this one, over which
    /// the rates of eq (3) and the tangential increment of eq (4) are read. Equal to `dt`
    /// unless the step changes ([`crate::dem::WorldParams::refine_window`]).
    pub dt_prev: f64,
    /// The kick of the velocities (s), ½·(Δtⁿ⁻¹ + Δtⁿ), the time between the two half-step
    /// velocities: vⁿ⁺½ = vⁿ⁻½ + kick·F/m keeps the leapfrog second order where the step
    /// changes. The ledger books each force's work over it. Equal to `dt` at a constant step.
    pub kick: f64,
    /// How eq (3)'s contact dashpot is advanced.
    pub contact_dashpot: Dashpot,
    /// How a new contact reads its first overlap rate.
    pub contact_onset: ContactOnset,
    /// Gauss–Seidel sweeps of the implicit contact dashpot (count).
    pub contact_dashpot_sweeps: u32,
    /// How the joints' dashpot of eq (1) is advanced.
    pub joint_dashpot: Dashpot,
    /// Incubation time of crack initiation (s), or `None` (the paper's instantaneous start).
    pub incubation_time: Option<f64>,
    /// Fracture tested on the mean stress of the last two poses (`numerics.fracture_step_mean`).
    pub fracture_step_mean: bool,
    /// Keep the largest tested stress over strength of the intact joints
    /// ([`crate::dem::WorldParams::refine_load`]).
    pub track_load: bool,
}

/// Serde form of a threshold that a scene may switch off (`numerics.refine_window`,
/// `refine_load`, `refine_impact`): a number in the threshold's unit, or the string `"off"`
/// for `None`. Always written, so a scene or record says whether it refines.
pub(crate) mod off_or_number {
    use serde::de::Error;
    use serde::{Deserialize, Deserializer, Serializer};

    /// The word that switches a threshold off.
    pub const OFF: &str = "off";

    pub fn serialize<S: Serializer>(v: &Option<f64>, s: S) -> Result<S::Ok, S::Error> {
        match v {
            Some(x) => s.serialize_f64(*x),
            None => s.serialize_str(OFF),
        }
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Option<f64>, D::Error> {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum Form {
            Number(f64),
            Word(String),
        }
        match Form::deserialize(d) {
            Ok(Form::Number(x)) => Ok(Some(x)),
            Ok(Form::Word(w)) if w == OFF => Ok(None),
            _ => Err(D::Error::custom(format!(
                "expected a number or \"{OFF}\" (the threshold switched off)"
            ))),
        }
    }
}
