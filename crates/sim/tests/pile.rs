//! A pile of 200 blocks dropped into water between two walls: the whole contact, buoyancy
//! and ledger machinery at once.

use pressridge_sim::dem::World;
use pressridge_sim::scene::Scene;

/// Largest overlap between any two blocks as a fraction of the smaller block's area, and
/// whether any block's centroid lies inside another block.
fn worst_interpenetration(w: &World) -> (f64, bool) {
    let b = w.bodies();
    let snap = w.snapshot();
    let mut worst: f64 = 0.0;
    let mut centroid_inside = false;
    for c in w.contacts() {
        let (i, j) = ((c.key >> 32) as usize, (c.key & 0xffff_ffff) as usize);
        let smaller = b.shape[i].area().min(b.shape[j].area());
        worst = worst.max(c.area / smaller);
        for (p, q) in [(i, j), (j, i)] {
            let poly = snap.bodies[q].world_outline();
            let v = poly.verts();
            let inside =
                (0..v.len()).all(|k| (v[(k + 1) % v.len()] - v[k]).cross(b.pos[p] - v[k]) > 0.0);
            centroid_inside |= inside;
        }
    }
    (worst, centroid_inside)
}

#[test]
fn pile_of_200_blocks_settles_in_water_with_a_closed_budget() {
    let scene = Scene::rubble_pile()
        .with_overrides(&["duration=8.0"])
        .unwrap();
    assert!(scene.pile.as_ref().unwrap().blocks >= 200);
    let mut world = scene.build().unwrap();
    let n = world.bodies().len();
    let mut max_ke: f64 = 0.0;
    let mut worst: f64 = 0.0;
    let mut max_rel_residual: f64 = 0.0;
    while world.time() < scene.duration {
        for _ in 0..200 {
            world.step();
        }
        let e = world.energy();
        max_ke = max_ke.max(world.bodies().kinetic_energy());
        max_rel_residual = max_rel_residual.max(e.residual.abs() / e.largest_term());
        let (over, inside) = worst_interpenetration(&world);
        worst = worst.max(over);
        assert!(
            !inside,
            "a block centroid entered another block at t = {}",
            world.time()
        );
        for i in 0..n {
            let p = world.bodies().pos[i];
            assert!(p.x.is_finite() && p.y.is_finite() && world.bodies().theta[i].is_finite());
        }
    }
    assert!(worst < 0.05, "overlap reached {:.3} of a block", worst);
    assert!(max_rel_residual < 5e-3, "residual {max_rel_residual}");
    // Settled: little kinetic energy left compared with the fall.
    let ke = world.bodies().kinetic_energy();
    assert!(ke < 0.02 * max_ke, "KE {ke} J/m of peak {max_ke} J/m");
    // The blocks are afloat between the walls, none lost below the pile.
    let level = 0.0;
    for i in 0..n - 2 {
        let p = world.bodies().pos[i];
        assert!(p.x.abs() < 2.0, "block {i} left the basin: {p:?}");
        assert!(p.y > level - 8.0 && p.y < level + 4.0, "block {i} at {p:?}");
    }
    // Energy went where it should: potential energy was released (ΔPE < 0) and
    // dissipated by contacts and drag.
    let e = world.energy();
    assert!(e.potential_energy < 0.0);
    let sinks = e.friction_dissipation + e.viscous_dissipation + e.drag_dissipation;
    assert!(sinks > 0.9 * -e.potential_energy, "{e:?}");
    eprintln!(
        "dt {} steps {} worst overlap {worst:.4} residual {max_rel_residual:.2e} KE end/peak {:.2e} {e:?}",
        world.dt(),
        world.steps(),
        ke / max_ke
    );
}
