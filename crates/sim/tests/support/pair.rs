//! The contact law tests' worlds: a dry world with one friction coefficient, and two blocks
//! meeting face to face.

use pressridge_sim::dem::{ContactParams, Drive, Shape, V2, World, WorldParams};

/// An empty world without water, with friction `mu` above and below the water line and
/// gravity `gravity` (m/s²); everything else at its default.
pub fn dry(mu: f64, gravity: f64) -> World {
    World::new(WorldParams {
        gravity,
        water: None,
        contact: ContactParams {
            mu,
            mu_water: mu,
            ..ContactParams::default()
        },
        ..WorldParams::default()
    })
    .unwrap()
}

/// Two 1 m × 0.3 m blocks 2 cm apart face to face (the left one set back a further `shift`,
/// m), closing at 0.5 m/s each, in a world without gravity or water; the rest of the
/// parameters, the contact law's included, from `params`.
pub fn face_on_pair(params: WorldParams, shift: f64) -> World {
    let mut w = World::new(WorldParams {
        gravity: 0.0,
        water: None,
        ..params
    })
    .unwrap();
    let a = w.add_block(
        Shape::rectangle(1.0, 0.3).unwrap(),
        V2::new(-0.51 - shift, 0.0),
        0.0,
        Drive::FREE,
    );
    let b = w.add_block(
        Shape::rectangle(1.0, 0.3).unwrap(),
        V2::new(0.51, 0.0),
        0.0,
        Drive::FREE,
    );
    w.set_velocity(a, V2::new(0.5, 0.0), 0.0);
    w.set_velocity(b, V2::new(-0.5, 0.0), 0.0);
    w
}
