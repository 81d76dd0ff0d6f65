//! Rubble contacts, Hopkins (1994) eqs (2)–(4): an elastic normal force proportional to the
//! overlap area, a viscous normal force from its rate of change, and a Coulomb-capped
//! tangential spring driven by incremental slip (Walton 1980). Contacts never pull.
//!
//! Forces are per metre of depth (N/m); they act at the centroid of the overlap polygon
//! along the contact normal `n` (from body `a` to body `b`) and tangent `t = n⊥`.
//!
//! Contacts born overlapping. Blocks held by a joint are exempt from contact, so where a
//! piece bends the corners of two joined blocks may interpenetrate; and a block grown at the
//! sheet's driven end may land on rubble (a sheet that rafted until its driven end reached
//! the ridge). The contact such a pair forms would be born deep and pre-loaded: the elastic
//! law (2) would push with k_ne·A at once and the viscous law (3) would read the whole area
//! as a one-step approach (k_nv·A/dt), both injecting energy no one stored. Such a contact
//! is instead born with its overlap forgiven (the contact's forgiven overlap A_f):
//! it resists only further penetration, F_e = k_ne·max(A − A_f, 0), starts its rate from
//! A₀ = A, and A_f only ever decreases (A_f ← min(A_f, A)), so once the blocks separate it
//! is an ordinary contact. The paper does not discuss this hand-over.
//!
//! Two options the 1994 paper leaves open ([`ContactParams::crushing_pressure`],
//! [`ContactParams::damping_law`]): a plastic limit on the elastic force, as the report the
//! paper defers its details to describes the contact law ("the magnitude of the contact
//! force is limited by the strength of the material. If the contact force reaches this
//! limit, further deformation is non-recoverable", Hopkins 1992), and eq (3)'s k_nv read
//! per contact. Off by default (the 1994 text: "a viscous elastic normal force model").

use super::body::Bodies;
use super::broadphase::{pair_key, unpack};
use super::geometry::{Overlap, OverlapScratch, V2, overlap_with};
use super::numerics::{ContactOnset, Dashpot, StepNumerics};

mod params;
mod tally;
pub use params::{ContactParams, DEFAULT_REFERENCE_THICKNESS, DampingLaw};
use serde::{Deserialize, Serialize};
pub use tally::ContactTally;

/// One active contact: its persistent state and the forces of the current step.
#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize)]
pub struct Contact {
    /// Key of the pair `(a, b)`, `a < b`.
    pub key: u64,
    /// Overlap area of the current step (m²), eq (2); the previous step's value drives
    /// eq (3).
    pub area: f64,
    /// Tangential force on `b` along `t` (N/m), eq (4), kept between steps.
    pub(crate) ft: f64,
    /// Elastic normal work absorbed while this contact has been active (J/m): the energy it
    /// holds as a compressed spring.
    pub(crate) stored: f64,
    /// Tangential work booked into this contact less its slip dissipation (J/m): the
    /// energy its tangential spring holds, to the step's accuracy.
    #[serde(default)]
    pub(crate) stored_t: f64,
    /// Forgiven overlap A_f (m²): the overlap a contact born overlapping (severed joint,
    /// grown block) had at birth, which the elastic law does not push against; it only
    /// decreases. Zero for every contact born by approach.
    #[serde(default)]
    pub(crate) forgiven: f64,
    /// Plastic overlap A_p (m²): overlap crushed beyond the cap p_c·L
    /// ([`ContactParams::crushing_pressure`]), not pushed against; it only grows.
    #[serde(default)]
    pub(crate) plastic: f64,
    /// Approach speed along the normal when the contact began (m/s, ≥ 0); 0 for a contact
    /// born overlapping. With `vn` and `steps` it gives the restitution of an impact.
    #[serde(default)]
    pub(crate) approach: f64,
    /// Normal relative speed of the last step (m/s, positive when separating).
    #[serde(default)]
    pub(crate) vn: f64,
    /// Steps the contact has been active.
    #[serde(default)]
    pub(crate) steps: u32,
    /// Damping ratio ζ of the contact's dashpot this step, c·sqrt(κ)/(2·sqrt(k_ne·L))
    /// (dimensionless): a diagnostic, not state.
    #[serde(skip)]
    pub(crate) zeta: f64,
    /// Point of action: the overlap centroid (m).
    pub point: V2,
    /// Unit normal from `a` to `b`.
    pub normal: V2,
    /// Elastic normal force applied on `b` (N/m, ≥ 0).
    pub(crate) fn_elastic: f64,
    /// Viscous normal force applied on `b` (N/m); negative only as much as keeps the total
    /// normal force from pulling.
    pub(crate) fn_viscous: f64,
}

impl Contact {
    /// Sets the viscous normal force from `fv` (N/m) so that the normal force never pulls,
    /// caps the tangential trial force `slip` (N/m) at `mu` times the normal force, and
    /// books the slip that cap dissipates ([`ContactWork::slip`]).
    fn close(&mut self, fv: f64, mu: f64, slip: f64, k_te: f64, work: &mut ContactWork) {
        self.settle(fv, mu, slip);
        self.book_slip(slip, k_te, work);
    }

    /// The viscous force `fv` (N/m), cut so that the normal force does not pull, and the
    /// tangential force: the spring force `slip` (N/m) capped at `mu` times the normal force.
    fn settle(&mut self, fv: f64, mu: f64, slip: f64) {
        self.fn_viscous = if self.fn_elastic + fv < 0.0 {
            -self.fn_elastic
        } else {
            fv
        };
        let cap = mu * (self.fn_elastic + self.fn_viscous);
        self.ft = slip.clamp(-cap, cap);
    }

    /// The viscous and friction force of the step on `b` (N/m), along n and t.
    #[inline]
    fn viscous_and_friction(&self) -> V2 {
        self.normal * self.fn_viscous + self.normal.perp() * self.ft
    }

    /// Books the Coulomb cap's slip dissipation of the settled tangential force against the
    /// spring force `slip` (N/m), for tangential stiffness `k_te`.
    fn book_slip(&mut self, slip: f64, k_te: f64, work: &mut ContactWork) {
        let lost = (self.ft * (slip - self.ft)).abs() / k_te;
        self.stored_t -= lost;
        work.slip += lost;
    }
}

/// Totals of the work absorbed by all contacts, for the energy ledger (J/m).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub(crate) struct ContactWork {
    /// Work absorbed by elastic normal forces, eq (12) elastic part.
    pub normal_elastic: f64,
    /// Work absorbed by viscous normal forces: the inelastic dissipation Φ_i, eq (12).
    pub normal_viscous: f64,
    /// Work absorbed by tangential forces, eq (11) (slip dissipation plus what the
    /// tangential springs hold).
    pub tangential: f64,
    /// Slip dissipation of the Coulomb cap (J/m): each step a spring whose trial force F*
    /// exceeds the cap μ·F_n and is cut to F dissipates |F|·|F* − F|/k_te ≥ 0, the force
    /// times the plastic slip (μ·F_n times the slip in steady sliding). This is the
    /// frictional dissipation Φ_f of eq (11).
    #[serde(default)]
    pub slip: f64,
    /// Crushing dissipation of the cap on the elastic normal force (J/m): p_c·ΔA_p, the
    /// capped force p_c·L times the plastic approach ΔA_p/L, summed over the steps; a part
    /// of `normal_elastic` (eq (12) books it with the elastic force).
    #[serde(default)]
    pub plastic: f64,
}

/// All active contacts, sorted by pair key, with a swap buffer for the next step.
#[derive(Clone, Debug, Default)]
pub(crate) struct ContactSet {
    cur: Vec<Contact>,
    prev: Vec<Contact>,
    /// Per contact of `cur`, what the implicit dashpot's second pass needs.
    pending: Vec<Pending>,
    /// Working space of the overlap geometry.
    scratch: OverlapScratch,
    /// The candidate pairs' overlaps, computed on the threads of a pool
    /// ([`ContactSet::update`]).
    overlaps: Vec<Option<Overlap>>,
    /// Restitution and damping-ratio histograms.
    pub(crate) tally: ContactTally,
}

/// A contact's viscous and friction inputs, kept between the passes of the implicit
/// dashpot ([`Dashpot::Implicit`]).
#[derive(Clone, Copy, Debug)]
struct Pending {
    /// k_nv·(Aⁿ − Aⁿ⁻¹)/Δt (N/m): eq (3) as written.
    rate: f64,
    /// The dashpot c = k_nv·L on the approach speed (kg/(m·s)).
    damping: f64,
    /// Friction coefficient of the contact.
    mu: f64,
    /// Tangential spring force before the Coulomb cap (N/m).
    slip: f64,
    /// The contact's tangential stiffness k_te (N/m²).
    k_te: f64,
    /// The pair's inverse effective mass along the normal κ (1/(kg/m)).
    kappa: f64,
}

/// The contact law of a step: its parameters, eq (3)'s coefficient k_nv (kg/(m²·s)) and the
/// water level (m) below which contacts take μ_w (`None` in a dry scene).
pub(crate) struct ContactLaw<'a> {
    /// Eqs (2)–(4)'s parameters.
    pub params: &'a ContactParams,
    /// Eq (3)'s k_nv (kg/(m²·s)).
    pub k_nv: f64,
    /// The water level (m), or `None`.
    pub water_level: Option<f64>,
}

/// The contact law as one step applies it to every touching pair: [`ContactLaw`] with the
/// step's Δt and onset, and the constants each pair uses, taken once per step.
struct PairLaw<'a> {
    p: &'a ContactParams,
    k_nv: f64,
    water_level: Option<f64>,
    /// The time since the last pose (s, [`StepNumerics::dt_prev`]): eq (3)'s rate and eq
    /// (4)'s increment are over it.
    dt: f64,
    onset: ContactOnset,
    k_ne: f64,
    k_te_per_chord: f64,
    p_c: f64,
}

impl<'a> PairLaw<'a> {
    fn new(law: &ContactLaw<'a>, num: &StepNumerics) -> Self {
        let p = law.params;
        PairLaw {
            p,
            k_nv: law.k_nv,
            water_level: law.water_level,
            dt: num.dt_prev,
            onset: num.contact_onset,
            k_ne: p.normal_stiffness,
            k_te_per_chord: p.tangential_stiffness_per_chord(),
            p_c: p.crushing_pressure,
        }
    }

    /// Eqs (2)–(4) for the touching pair `(a, b)` with overlap `ov`: this step's contact
    /// from the last step's `old` (`None`: a new contact), with its elastic normal force, and
    /// what its dashpot and friction need ([`Pending`]). Crushed overlap's work goes to
    /// `work.plastic`.
    #[inline]
    fn contact(
        &self,
        bodies: &Bodies,
        (a, b): (usize, usize),
        ov: &Overlap,
        old: Option<Contact>,
        work: &mut ContactWork,
    ) -> (Contact, Pending) {
        let (p, k_ne, dt) = (self.p, self.k_ne, self.dt);
        let o = old.unwrap_or_default();
        let forgiven = o.forgiven.min(ov.area);
        let n = ov.normal;
        let t = n.perp();
        // Eq (4) with the relative velocity at the overlap centroid at n − ½.
        let vrel = bodies.point_velocity(b, ov.centroid) - bodies.point_velocity(a, ov.centroid);
        let vn = vrel.dot(n);
        // The contact's length L: its dashpot is k_nv·L and its tangential spring
        // k_te = f·k_ne·L (eq 4, "60% of the normal value" k_ne·L).
        let chord = contact_length(ov, bodies, a, b);
        // Eq (2), less any forgiven and crushed overlap, capped at p_c·L; the crushed
        // part's work is dissipated.
        let mut plastic = o.plastic;
        let mut fe = (k_ne * (ov.area - forgiven - plastic)).max(0.0);
        let mut stored = o.stored;
        if self.p_c > 0.0 && fe > self.p_c * chord {
            let grown = (fe - self.p_c * chord) / k_ne;
            plastic += grown;
            fe = self.p_c * chord;
            stored -= self.p_c * grown;
            work.plastic += self.p_c * grown;
        }
        let kappa = bodies.inverse_mass_along(a, ov.centroid, n)
            + bodies.inverse_mass_along(b, ov.centroid, n);
        // Eq (3): the dashpot c on the approach speed, from the paper's k_nv per unit
        // chord or from this contact's own critical damping.
        let damping = match p.damping_law {
            DampingLaw::Sheet => self.k_nv * chord,
            DampingLaw::Contact if kappa > 0.0 => {
                p.damping_fraction * 2.0 * (k_ne * chord / kappa).sqrt()
            }
            DampingLaw::Contact => 0.0,
        };
        let rate = if old.is_none() && self.onset == ContactOnset::Velocity {
            damping * (-vn).max(0.0)
        } else {
            match p.damping_law {
                DampingLaw::Sheet => self.k_nv * (ov.area - o.area) / dt,
                DampingLaw::Contact => damping * (ov.area - o.area) / (chord * dt),
            }
        };
        let mu = match self.water_level {
            Some(l) if ov.centroid.y < l => p.mu_water,
            _ => p.mu,
        };
        let k_te = self.k_te_per_chord * chord;
        let slip = o.ft - k_te * dt * vrel.dot(t);
        let c = Contact {
            key: pair_key(a as u32, b as u32),
            area: ov.area,
            ft: 0.0,
            stored,
            stored_t: o.stored_t,
            forgiven,
            plastic,
            approach: if old.is_none() {
                (-vn).max(0.0)
            } else {
                o.approach
            },
            vn,
            steps: o.steps.saturating_add(1),
            zeta: damping * kappa.sqrt() / (2.0 * (k_ne * chord).sqrt()),
            point: ov.centroid,
            normal: n,
            fn_elastic: fe,
            fn_viscous: 0.0,
        };
        let q = Pending {
            rate,
            damping,
            mu,
            slip,
            k_te,
            kappa,
        };
        (c, q)
    }
}

impl ContactSet {
    /// The active contacts of the last step, sorted by key.
    pub fn contacts(&self) -> &[Contact] {
        &self.cur
    }
    /// Replaces the active contacts (restoring a saved state).
    pub fn restore(&mut self, mut c: Vec<Contact>) {
        c.sort_by_key(|c| c.key);
        self.cur = c;
    }

    /// Records the pair `key` whose bodies overlap by `area` (m²) at centroid `point` with
    /// normal `normal` without having approached (a severed joint, a grown block): the
    /// contact they form is born with that overlap forgiven and A₀ = `area` (see the module
    /// docs). Applies no force.
    pub fn hand_over(&mut self, key: u64, area: f64, point: V2, normal: V2) {
        let c = Contact {
            key,
            area,
            forgiven: area,
            point,
            normal,
            ..Contact::default()
        };
        match self.cur.binary_search_by_key(&key, |c| c.key) {
            Ok(i) => self.cur[i] = c,
            Err(i) => self.cur.insert(i, c),
        }
    }

    /// Tests the candidate `pairs`, updates every contact's force from eqs (2)–(4) with the
    /// half-step velocities stored in `bodies`, and adds the forces to the bodies.
    /// `water_level` (m) selects μ_w for contacts centred below it; `dashpot` says how
    /// eq (3) is advanced ([`Dashpot`]).
    pub(crate) fn update(
        &mut self,
        bodies: &mut Bodies,
        pairs: &[u64],
        law: &ContactLaw<'_>,
        num: &StepNumerics,
        work: &mut ContactWork,
        pool: Option<&rayon::ThreadPool>,
    ) {
        let (dt, kick, dashpot, sweeps) = (
            num.dt,
            num.kick,
            num.contact_dashpot,
            num.contact_dashpot_sweeps,
        );
        let law = PairLaw::new(law, num);
        // The overlap geometry, the bulk of the work, pair by pair on the pool's threads;
        // everything that sums follows in pair order below, so the bits do not depend on
        // the number of threads.
        if let Some(pool) = pool {
            use rayon::prelude::*;
            let b: &Bodies = bodies;
            pool.install(|| {
                pairs
                    .par_iter()
                    .map_init(OverlapScratch::default, |scratch, &key| {
                        let (a, c) = unpack(key);
                        let (a, c) = (a as usize, c as usize);
                        overlap_with(&b.world[a], &b.world[c], b.pos[a], b.pos[c], scratch)
                    })
                    .collect_into_vec(&mut self.overlaps);
            });
        }
        std::mem::swap(&mut self.cur, &mut self.prev);
        self.cur.clear();
        self.pending.clear();
        let mut j = 0;
        for (k, &key) in pairs.iter().enumerate() {
            // Contacts of the last step whose pair is no longer a candidate have separated;
            // the elastic work they held stays booked and shows as `contact_hysteresis`.
            while j < self.prev.len() && self.prev[j].key < key {
                self.tally.ended(&self.prev[j], dt);
                j += 1;
            }
            let old = if j < self.prev.len() && self.prev[j].key == key {
                j += 1;
                Some(self.prev[j - 1])
            } else {
                None
            };
            let (a, b) = unpack(key);
            let (a, b) = (a as usize, b as usize);
            let overlap = match pool {
                Some(_) => self.overlaps[k],
                None => overlap_with(
                    &bodies.world[a],
                    &bodies.world[b],
                    bodies.pos[a],
                    bodies.pos[b],
                    &mut self.scratch,
                ),
            };
            let Some(ov) = overlap else {
                if let Some(o) = &old {
                    self.tally.ended(o, dt);
                }
                continue;
            };
            let (c, q) = law.contact(bodies, (a, b), &ov, old, work);
            let mut c = c;
            let (n, fe) = (c.normal, c.fn_elastic);
            match dashpot {
                Dashpot::Explicit => {
                    c.close(q.rate, q.mu, q.slip, q.k_te, work);
                    let f = n * (fe + c.fn_viscous) + n.perp() * c.ft;
                    apply_pair(bodies, key, f, ov.centroid);
                }
                Dashpot::Implicit => {
                    // The dashpot c; its viscous and friction forces wait for every other
                    // force of the step (pass 2 below).
                    apply_pair(bodies, key, n * fe, ov.centroid);
                    self.pending.push(q);
                }
            }
            self.cur.push(c);
        }
        while j < self.prev.len() {
            self.tally.ended(&self.prev[j], dt);
            j += 1;
        }
        if dashpot == Dashpot::Implicit && sweeps > 0 {
            self.sweep_dashpots(bodies, kick, sweeps, work);
        } else if dashpot == Dashpot::Implicit {
            // Pass 2: every force but the contacts' viscous and friction forces is in
            // `bodies.force`. The pair's mid-step approach speed is
            // ū = u⁻ − ½·Δt·(aₙ + κ·F_v), aₙ the relative acceleration along n of the
            // contact points from those forces; F_v = c·ū, solved for F_v.
            for (c, q) in self.cur.iter_mut().zip(&self.pending) {
                let fv = centred_viscous(bodies, c, q, kick);
                c.close(fv, q.mu, q.slip, q.k_te, work);
            }
            // Pass 3: apply them.
            for c in &self.cur {
                apply_pair(bodies, c.key, c.viscous_and_friction(), c.point);
            }
        }
    }

    /// The implicit dashpot by `sweeps` Gauss–Seidel sweeps over the contacts
    /// ([`crate::dem::WorldParams::contact_dashpot_sweeps`]): in order, each contact's
    /// viscous force is solved as in pass 2 of [`ContactSet::update`] but with the forces of
    /// the contacts before it (this sweep) and after it (the last sweep) already in
    /// `bodies`, and its own force is applied at once, replacing its last one. The system
    /// (C⁻¹ + ½·Δt·K)·F = C⁻¹·rate − ½·Δt·a (C the dashpots, K the contacts' coupling
    /// through the bodies' inverse masses) is symmetric positive definite, so the sweeps
    /// converge to the coupled solution (for the viscous force; friction follows each
    /// iterate). The Coulomb slip of the final forces is booked once.
    fn sweep_dashpots(
        &mut self,
        bodies: &mut Bodies,
        dt: f64,
        sweeps: u32,
        work: &mut ContactWork,
    ) {
        for sweep in 0..sweeps {
            for (c, q) in self.cur.iter_mut().zip(&self.pending) {
                if sweep > 0 {
                    apply_pair(bodies, c.key, -c.viscous_and_friction(), c.point);
                }
                let fv = centred_viscous(bodies, c, q, dt);
                c.settle(fv, q.mu, q.slip);
                apply_pair(bodies, c.key, c.viscous_and_friction(), c.point);
            }
        }
        for (c, q) in self.cur.iter_mut().zip(&self.pending) {
            c.book_slip(q.slip, q.k_te, work);
        }
    }

    /// Books the work of this step's contact forces with the mid-step velocities
    /// `vbar`, `wbar` (average of the velocities before and after the step), so that the
    /// ledger and the kinetic energy agree exactly (see `dem::ledger`).
    pub fn book_work(
        &mut self,
        bodies: &Bodies,
        vbar: &[V2],
        wbar: &[f64],
        dt: f64,
        work: &mut ContactWork,
    ) {
        for c in self.cur.iter_mut() {
            let (a, b) = unpack(c.key);
            let (a, b) = (a as usize, b as usize);
            let va = vbar[a] + (c.point - bodies.pos[a]).perp() * wbar[a];
            let vb = vbar[b] + (c.point - bodies.pos[b]).perp() * wbar[b];
            let v = vb - va;
            let vn = v.dot(c.normal);
            let vt = v.dot(c.normal.perp());
            let de = -c.fn_elastic * vn * dt;
            c.stored += de;
            work.normal_elastic += de;
            work.normal_viscous += -c.fn_viscous * vn * dt;
            let dt_work = -c.ft * vt * dt;
            c.stored_t += dt_work;
            work.tangential += dt_work;
        }
    }

    /// Adds the damping ratio of every active contact to the tally.
    pub(crate) fn tally_zeta(&mut self) {
        for c in &self.cur {
            self.tally.add_zeta(c.zeta);
        }
    }

    /// Energy held by the active contacts (J/m): elastic normal work not yet returned, and
    /// the tangential work booked less slip dissipation (the tangential springs' energy
    /// F_t²/(2·k_te) to the step's accuracy).
    pub fn stored_energy(&self) -> (f64, f64) {
        let mut en = 0.0;
        let mut et = 0.0;
        for c in &self.cur {
            en += c.stored;
            et += c.stored_t;
        }
        (en, et)
    }
}
/// Adds the force `f` (N/m) on the pair `key`'s body b and −`f` on its body a, at `at` (m).
#[inline]
fn apply_pair(bodies: &mut Bodies, key: u64, f: V2, at: V2) {
    let (a, b) = unpack(key);
    bodies.apply(b as usize, f, at);
    bodies.apply(a as usize, -f, at);
}

/// The viscous force (N/m) of contact `c` centred at its mid-step approach speed, with
/// every force now in `bodies` other than its own viscous and friction forces:
/// F_v = (k_nv·(Aⁿ − Aⁿ⁻¹)/Δt − ½·c·Δt·aₙ)/(1 + ½·c·Δt·κ) ([`Dashpot::Implicit`]).
#[inline]
fn centred_viscous(bodies: &Bodies, c: &Contact, q: &Pending, dt: f64) -> f64 {
    let (a, b) = unpack(c.key);
    let (a, b) = (a as usize, b as usize);
    let n = c.normal;
    let an = (bodies.point_acceleration(b, c.point) - bodies.point_acceleration(a, c.point)).dot(n);
    let x = 0.5 * q.damping * dt * q.kappa;
    (q.rate - 0.5 * q.damping * dt * an) / (1.0 + x)
}

/// The length L of a contact surface (m) for the dashpot c = k_nv·L and the tangential
/// spring k_te = f·k_ne·L of eq (4): the chord, or, where
/// the chord is undefined (one block inside the other), the smaller block's diameter.
fn contact_length(ov: &Overlap, bodies: &Bodies, a: usize, b: usize) -> f64 {
    if ov.chord > 0.0 {
        ov.chord
    } else {
        2.0 * bodies.shape[a].radius().min(bodies.shape[b].radius())
    }
}
