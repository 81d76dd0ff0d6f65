//! The discrete-element ridge simulator (Hopkins 1994, "Dynamic Ridge Model").
//!
//! One private module per mechanism, behind this front (each public name has one path,
//! `dem::Name`):
//! - `geometry` — vectors and block outlines ([`V2`], [`Poly`], [`Outline`]); convex
//!   clipping, areas, centroids, the contact chord and normal, the water line;
//! - `body` — block shapes and the state arrays ([`Block`], [`Bodies`]);
//! - `broadphase` — candidate pairs by sort-and-sweep;
//! - `contact` — the rubble contact law, eqs (2)–(4) ([`Contact`], [`ContactParams`]);
//! - `joint` — viscous-elastic joints, eq (1) ([`Joint`], [`JointMaterial`]);
//! - `fracture` — crack initiation and growth, splitting pieces;
//! - `boundary` — the pushed sheet, eqs (7)–(8), floe supports;
//! - `water` — buoyancy and drag ([`WaterParams`]);
//! - `ledger` — booking the energy budget of eqs (9)–(12) ([`crate::energy`]);
//! - `numerics` — the step's numerical options ([`Dashpot`], [`ContactOnset`]);
//! - `world` — the leapfrog step, eqs (5)–(6) ([`World`], [`WorldParams`], [`Snapshot`]).

mod body;
pub(crate) mod boundary;
pub(crate) mod broadphase;
mod contact;
pub(crate) mod fracture;
mod geometry;
mod joint;
pub(crate) mod lanes;
pub(crate) mod ledger;
pub(crate) mod numerics;
mod water;
mod world;

pub use body::{Block, Bodies, BodyId, Drive, Role, Shape, ShapeError};
pub use contact::{Contact, ContactParams, ContactTally, DEFAULT_REFERENCE_THICKNESS, DampingLaw};
pub use geometry::{MAX_VERTS, Outline, Poly, V2};
pub use joint::{Joint, JointMaterial, SurfaceStress};
pub use numerics::{ContactOnset, Dashpot};
pub use water::{DragBodies, WaterParams};
pub use world::{
    BodyState, DEFAULT_REFINE_FRACTION, DEFAULT_REFINE_IMPACT, DEFAULT_REFINE_LOAD,
    DEFAULT_REFINE_WINDOW, DEFAULT_TIME_STEP_SAFETY, Handovers, MAX_CONTACT_DASHPOT_SWEEPS,
    Snapshot, World, WorldError, WorldParams,
};

/// The contact geometry, public and hidden from the docs only for the benchmarks
/// (`benches/dem.rs`, against parry2d) and the research programs: the simulator calls its
/// crate-private forms.
#[doc(hidden)]
pub use geometry::{Overlap, intersect, overlap};

pub(crate) use geometry::below_line;
pub(crate) use world::is_zero;
