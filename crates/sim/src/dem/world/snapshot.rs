//! Saving and restoring a [`World`]: [`Snapshot`], a complete serialisable copy of the
//! state from which stepping continues bit for bit.

use super::*;

impl World {
    /// A complete, serialisable copy of the state: restoring it and stepping gives the
    /// same results bit for bit as stepping this world.
    pub fn snapshot(&self) -> Snapshot {
        let b = &self.bodies;
        Snapshot {
            format: SNAPSHOT_FORMAT,
            time: self.time,
            steps: self.steps,
            dt: self.dt,
            params: self.params.clone(),
            bodies: (0..b.len())
                .map(|i| BodyState {
                    shape: b.shape[i],
                    pos: b.pos[i],
                    theta: b.theta[i],
                    vel: b.vel[i],
                    omega: b.omega[i],
                    drive: b.drive[i],
                    role: b.role[i],
                    block: b.block[i],
                })
                .collect(),
            contacts: self.contacts.contacts().to_vec(),
            joints: self.joints.joints().to_vec(),
            boundary: self.boundary.clone(),
            loads: self.loads.clone(),
            blocks_broken: self.blocks_broken,
            handovers: self.handovers,
            ledger: self.acc,
            contact_tally: self.contacts.tally.clone(),
            refine: (self.params.refine_window.is_some() || self.params.refine_load.is_some())
                .then(|| RefineClock {
                    last_dt: self.last_dt,
                    until: self.refine_until.is_finite().then_some(self.refine_until),
                    load: self.joints.max_load(),
                }),
        }
    }

    /// Rebuilds a world from a [`Snapshot`].
    pub fn from_snapshot(s: &Snapshot) -> Result<World, WorldError> {
        if s.format != SNAPSHOT_FORMAT {
            return Err(WorldError::State(format!(
                "format {} is not the supported {SNAPSHOT_FORMAT}",
                s.format
            )));
        }
        let mut w = World::new(s.params.clone())?;
        for bs in &s.bodies {
            let i = w
                .bodies
                .push(bs.shape, w.params.ice_density, bs.pos, bs.theta, bs.drive);
            w.bodies.vel[i as usize] = bs.vel;
            w.bodies.omega[i as usize] = bs.omega;
            w.bodies.role[i as usize] = bs.role;
            w.bodies.block[i as usize] = bs.block;
        }
        if s.joints
            .iter()
            .any(|j| j.a as u64 >= nb_of(s) || j.b as u64 >= nb_of(s))
        {
            return Err(WorldError::State("a joint names a missing body".into()));
        }
        w.joints.restore(s.joints.clone());
        w.boundary = s.boundary.clone();
        w.loads = s.loads.clone();
        w.blocks_broken = s.blocks_broken;
        w.handovers = s.handovers;
        let nb = w.bodies.len() as u64;
        if s.contacts
            .iter()
            .any(|c| (c.key >> 32) >= nb || (c.key & 0xffff_ffff) >= nb)
        {
            return Err(WorldError::State("a contact names a missing body".into()));
        }
        w.contacts.restore(s.contacts.clone());
        w.contacts.tally = s.contact_tally.clone();
        w.acc = s.ledger;
        w.time = s.time;
        w.steps = s.steps;
        w.dt = s.dt;
        if let Some(r) = s.refine {
            if !(r.last_dt.is_finite() && r.last_dt >= 0.0) {
                return Err(WorldError::State(format!(
                    "the refined step's last step {} s is not a step",
                    r.last_dt
                )));
            }
            w.last_dt = r.last_dt;
            w.refine_until = r.until.unwrap_or(f64::NEG_INFINITY);
            w.joints.set_max_load(r.load);
        }
        Ok(w)
    }
}

/// Version of the [`Snapshot`] layout.
pub(crate) const SNAPSHOT_FORMAT: u32 = 2;

fn nb_of(s: &Snapshot) -> u64 {
    s.bodies.len() as u64
}

/// One body in a [`Snapshot`].
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyState {
    /// Outline relative to the centroid.
    pub shape: Shape,
    /// Centroid (m).
    pub pos: V2,
    /// Orientation (rad).
    pub theta: f64,
    /// Velocity at the last half step (m/s).
    pub vel: V2,
    /// Angular velocity at the last half step (rad/s).
    pub omega: f64,
    /// Prescribed degrees of freedom.
    pub drive: Drive,
    /// Role in the scene.
    #[serde(default)]
    pub role: Role,
    /// Nominal rectangle and bevels, for rectangular blocks.
    #[serde(default)]
    pub block: Option<Block>,
}

impl BodyState {
    /// The body's outline in world coordinates (m).
    pub fn world_outline(&self) -> crate::dem::geometry::Outline {
        let (s, c) = self.theta.sin_cos();
        let mut o = crate::dem::geometry::Outline::default();
        o.set_transformed(self.shape.outline(), c, s, self.pos);
        o
    }
}

/// The complete state of a [`World`], serialisable (JSON files: `pressridge::io::state`).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Snapshot {
    /// Layout version, [`SNAPSHOT_FORMAT`].
    pub(crate) format: u32,
    /// Simulated time (s).
    pub time: f64,
    /// Steps taken.
    pub steps: u64,
    /// Time step (s).
    pub dt: f64,
    /// Parameters.
    pub params: WorldParams,
    /// Bodies.
    pub bodies: Vec<BodyState>,
    /// Active contacts with their history.
    pub(crate) contacts: Vec<Contact>,
    /// Joints with their cracks.
    pub joints: Vec<Joint>,
    /// Boundary conditions.
    pub(crate) boundary: Boundary,
    /// External loads.
    pub(crate) loads: Vec<(BodyId, V2)>,
    /// Joints severed so far.
    pub blocks_broken: u64,
    /// Contacts born overlapping so far (absent in older snapshots, which predate the
    /// hand-over).
    #[serde(default)]
    pub(crate) handovers: Handovers,
    /// Ledger integrals.
    pub(crate) ledger: Accumulators,
    /// The contacts' restitution and damping-ratio histograms (absent in older snapshots).
    #[serde(default)]
    pub(crate) contact_tally: ContactTally,
    /// The clock of the step refined around fracture ([`WorldParams::refine_window`],
    /// [`WorldParams::refine_load`]), so
    /// that a restart inside a refined window repeats the bits of the unbroken run; absent
    /// for a world without it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) refine: Option<RefineClock>,
}

/// Where a step refined around fracture stands ([`WorldParams::refine_window`]).
#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RefineClock {
    /// The last step's Δt (s), 0 before the first step.
    last_dt: f64,
    /// The time (s) until which steps are refined after the last severed joint; none before
    /// the first.
    until: Option<f64>,
    /// The joints' largest stress over strength at the last step (dimensionless;
    /// [`WorldParams::refine_load`]).
    #[serde(default)]
    load: f64,
}
