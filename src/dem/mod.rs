//! The discrete-element ridge simulator (Hopkins 1994, "Dynamic Ridge Model").
//!
//! One module per mechanism:
//! - [`geometry`] — convex clipping, areas, centroids, boundary crossings, the water line;
//! - [`body`] — block shapes and the state arrays;
//! - [`broadphase`] — candidate pairs by sort-and-sweep;
//! - [`contact`] — the rubble contact law, eqs (2)–(4);
//! - [`water`] — buoyancy and drag;
//! - [`ledger`] — the energy budget, eqs (9)–(12);
//! - [`world`] — the leapfrog step, eqs (5)–(6).

pub mod body;
pub mod broadphase;
pub mod contact;
pub mod geometry;
pub mod ledger;
pub mod water;
pub mod world;

pub use body::{Bodies, BodyId, Drive, Shape, ShapeError};
pub use contact::{Contact, ContactParams};
pub use geometry::V2;
pub use ledger::EnergyBudget;
pub use water::WaterParams;
pub use world::{Snapshot, World, WorldError, WorldParams};
