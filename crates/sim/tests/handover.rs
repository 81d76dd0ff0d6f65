//! Contacts born overlapping (`pressridge_sim::dem::contact`, "Contacts born from a severed
//! joint"): blocks whose joint severs while their corners interpenetrate, and a sheet block
//! grown where rubble already lies, must not be pushed apart by a pre-loaded contact. The
//! signature of a pre-loaded contact is energy from nowhere: a contact born with area A
//! pushes with k_ne·A and k_nv·A/dt at once, so the viscous contact "dissipation" turns
//! negative and the blocks fly apart. With the overlap forgiven they stay put.

use pressridge_sim::dem::{Block, BodyId, Drive, JointMaterial, Role, V2, World, WorldParams};
use pressridge_sim::scene::Scene;

const H: f64 = 0.30;
const W: f64 = 0.25;

fn block() -> Block {
    Block {
        width: W,
        thickness: H,
        bevel: [0.0; 4],
        bevel_run: None,
    }
}

/// Two joined blocks, the right one turned clockwise by 0.2 rad about the top of the joint
/// face so that its lower-left corner lies inside the left block (overlap ≈ ½·h²·tan 0.2 ≈
/// 9e-3 m²), with a joint of 1 Pa strength cracking at a crack speed that severs it in one
/// step. No gravity, no water: the only energy is what the strained joint holds at the
/// start (`held`, its closed-form ½∫(E·δ_n² + G·δ_t²)/W; the ledger counts the joint's
/// booked work from the start, so releasing that strain shows up as negative fracture
/// dissipation here, which a world built unstrained never has). The step is fixed at
/// 1e-4 s so that the blocks barely move before the joint severs.
#[test]
fn severed_joint_with_overlapping_blocks_injects_no_energy() {
    let mut w = World::new(WorldParams {
        gravity: 0.0,
        water: None,
        crack_speed: 1.0e6,
        ..WorldParams::default()
    })
    .unwrap();
    let a = w
        .add_rect(
            block(),
            V2::new(0.5 * W, 0.0),
            0.0,
            Drive::FIXED,
            Role::Rubble,
        )
        .unwrap();
    let th: f64 = -0.2;
    let pivot = V2::new(W, 0.5 * H);
    let (s, c) = th.sin_cos();
    let centre = pivot + V2::new(0.5 * W, -0.5 * H).rotate(c, s);
    let b = w
        .add_rect(block(), centre, th, Drive::FREE, Role::Rubble)
        .unwrap();
    let mat = JointMaterial {
        e_top: 1.0e8,
        e_bottom: 6.7e7,
        poisson: 0.3,
        damping_fraction: 0.1,
        strength_top: 1.0,
        strength_bottom: 1.0,
    };
    w.join(a, b, 0.06, mat).unwrap();
    w.set_time_step(1e-4).unwrap();
    let held: f64 = w.joints().iter().map(|j| j.stored_energy(w.bodies())).sum();
    assert!(held > 0.0);
    let mut ke_max: f64 = 0.0;
    for _ in 0..2000 {
        w.step();
        let e = w.energy();
        ke_max = ke_max.max(e.kinetic_energy);
        assert!(
            e.viscous_dissipation >= -1e-9 * held.max(1.0),
            "viscous contact dissipation {} < 0 at t = {}",
            e.viscous_dissipation,
            w.time()
        );
    }
    assert_eq!(w.blocks_broken(), 1);
    let ho = w.handovers();
    assert_eq!(ho.count, 1, "{ho:?}");
    // The overlap the geometry gives: the triangle cut by the turned corner.
    let expect = 0.5 * H * H * (-th).tan();
    assert!(
        (ho.max_area - expect).abs() < 0.1 * expect,
        "forgiven {} m², expected ≈ {expect} m²",
        ho.max_area
    );
    // All the kinetic energy there ever is comes from the joint's elastic energy (which the
    // crack mostly releases), never from the contact.
    let e = w.energy();
    eprintln!("joint held {held} J/m, largest KE {ke_max} J/m, {e:?}");
    assert!(ke_max <= held, "KE {ke_max} J/m > joint energy {held} J/m");
    assert!(e.residual.abs() < 1e-9 * held.max(e.work.abs()));
}

/// A sheet against a wall whose joints crack under any stress; a free rubble block floats
/// where the sheet's next block will grow (overlapping that slot by 0.15 m × h). When the
/// sheet breaks it grows blocks at its driven end, one of them through the rubble block.
#[test]
fn block_grown_through_rubble_injects_no_energy() {
    let scene = Scene::from_toml(
        r#"
        name = "grown-through-rubble"
        duration = 1.0
        [sheet]
        thickness = 0.30
        block_width = 0.25
        length = 2.0
        strength_top = 1.0e3
        strength_bottom = 1.0e3
        [wall]
        "#,
    )
    .unwrap();
    let mut w = scene.build().unwrap();
    // The sheet's blocks from left to right: the driven block first, the tip last.
    let b = w.bodies();
    let mut sheet: Vec<BodyId> = (0..b.len() as BodyId)
        .filter(|&i| b.role[i as usize] == Role::Sheet)
        .collect();
    sheet.sort_by(|&i, &j| b.pos[i as usize].x.total_cmp(&b.pos[j as usize].x));
    let (first, tip) = (sheet[0], *sheet.last().unwrap());
    let p0 = w.bodies().pos[first as usize];
    // 0.1 m clear of the driven block now; 0.15 m inside the slot of the next grown block.
    let rubble = w
        .add_rect(
            block(),
            V2::new(p0.x - W - 0.1, p0.y),
            0.0,
            Drive::FREE,
            Role::Rubble,
        )
        .unwrap();
    // Lift the tip to bend the sheet and break it.
    w.set_load(tip, V2::new(0.0, 2.0e3));
    let mut ke_max: f64 = 0.0;
    let mut steps = 0;
    while w.blocks_broken() == 0 || steps < 2000 {
        w.step();
        steps += 1;
        let e = w.energy();
        ke_max = ke_max.max(e.kinetic_energy);
        assert!(
            e.viscous_dissipation >= -1e-6 * e.work.abs().max(1.0),
            "viscous contact dissipation {} < 0 at t = {}",
            e.viscous_dissipation,
            w.time()
        );
        assert!(steps < 200_000, "the sheet never broke");
    }
    let ho = w.handovers();
    assert!(ho.count >= 1, "no hand-over: {ho:?}");
    assert!(ho.max_area > 0.5 * 0.15 * H, "{ho:?}");
    // The rubble block was not shot away: it moved less than a block width.
    let moved = (w.bodies().pos[rubble as usize] - V2::new(p0.x - W - 0.1, p0.y)).norm();
    let e = w.energy();
    eprintln!("rubble moved {moved} m, largest KE {ke_max} J/m, {e:?}");
    assert!(moved < W, "the rubble block moved {moved} m");
    assert!(e.residual.abs() < 1e-6 * e.work.abs().max(1.0));
}
