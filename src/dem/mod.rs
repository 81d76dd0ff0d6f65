//! The discrete-element ridge simulator (Hopkins 1994, "Dynamic Ridge Model").
//!
//! One module per mechanism:
//! - [`geometry`] — vectors and block outlines (public); convex clipping, areas, centroids,
//!   the contact chord and normal, the water line (crate-private);
//! - [`body`] — block shapes and the state arrays;
//! - `broadphase` — candidate pairs by sort-and-sweep (crate-private);
//! - [`contact`] — the rubble contact law, eqs (2)–(4);
//! - [`joint`] — viscous-elastic joints, eq (1);
//! - `fracture` — crack initiation and growth, splitting pieces (crate-private);
//! - `boundary` — the pushed sheet, eqs (7)–(8), floe supports (crate-private);
//! - [`water`] — buoyancy and drag;
//! - `ledger` — booking the energy budget of eqs (9)–(12) ([`crate::energy`]) (crate-private);
//! - [`world`] — the leapfrog step, eqs (5)–(6).

pub mod body;
pub(crate) mod boundary;
pub(crate) mod broadphase;
pub mod contact;
pub(crate) mod fracture;
pub mod geometry;
pub mod joint;
pub(crate) mod lanes;
pub(crate) mod ledger;
mod numerics;
pub mod water;
pub mod world;

pub use body::{Block, Bodies, BodyId, Drive, Role, Shape, ShapeError};
pub use contact::{Contact, ContactParams};
pub use geometry::V2;
pub use joint::{Joint, JointMaterial};
pub use numerics::{ContactOnset, Dashpot};
pub use water::{DragBodies, WaterParams};
pub use world::{Snapshot, World, WorldError, WorldParams};
