//! Verification of buoyancy and the leapfrog integrator against floating-body theory.

use pressridge_sim::dem::{Drive, Shape, V2, WaterParams, World, WorldParams};

const RHO_I: f64 = 920.0;
const RHO_W: f64 = 1010.0;
const G: f64 = 9.81;

fn floating_block(h: f64, drag: WaterParams, y0: f64) -> World {
    let params = WorldParams {
        water: Some(drag),
        ..WorldParams::default()
    };
    let mut w = World::new(params).unwrap();
    w.add_block(
        Shape::rectangle(1.0, h).unwrap(),
        V2::new(0.0, y0),
        0.0,
        Drive::FREE,
    );
    w
}

/// A block settles to the draft d = h·ρ_i/ρ_w (Archimedes) within 0.1 %.
#[test]
fn floating_block_settles_to_archimedes_draft() {
    let h = 0.3;
    let water = WaterParams {
        drag_coefficient: 0.0,
        // Strong linear drag: settles in a few heave periods; equilibrium is unaffected.
        linear_drag: 2.0e3,
        ..WaterParams::default()
    };
    // Dropped from 5 cm above its floating position.
    let draft = h * RHO_I / RHO_W;
    let mut w = floating_block(h, water, h / 2.0 - draft + 0.05);
    while w.time() < 20.0 {
        w.step();
    }
    let bottom = w.bodies().pos[0].y - h / 2.0;
    let got = -bottom;
    assert!(
        ((got - draft) / draft).abs() < 1e-3,
        "draft {got} m, Archimedes {draft} m"
    );
    assert!(w.bodies().vel[0].norm() < 1e-6);
}

/// The undamped heave period of a floating block is 2π·sqrt(ρ_i·h/(ρ_w·g)) within 2 %.
#[test]
fn heave_period_matches_theory() {
    let h = 0.3;
    let water = WaterParams {
        drag_coefficient: 0.0,
        linear_drag: 0.0,
        ..WaterParams::default()
    };
    let draft = h * RHO_I / RHO_W;
    let y_eq = h / 2.0 - draft;
    let mut w = floating_block(h, water, y_eq + 0.01);
    // Upward crossings of the equilibrium level.
    let mut crossings = Vec::new();
    let mut prev = w.bodies().pos[0].y - y_eq;
    while w.time() < 10.0 {
        w.step();
        let cur = w.bodies().pos[0].y - y_eq;
        if prev < 0.0 && cur >= 0.0 {
            // Linear interpolation of the crossing time.
            crossings.push(w.time() - w.dt() * cur / (cur - prev));
        }
        prev = cur;
    }
    assert!(crossings.len() >= 5, "only {} periods", crossings.len());
    let period = (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
    let theory = 2.0 * std::f64::consts::PI * (RHO_I * h / (RHO_W * G)).sqrt();
    assert!(
        ((period - theory) / theory).abs() < 0.02,
        "period {period} s, theory {theory} s"
    );
    // Undamped: the amplitude is kept and the budget closes (work = 0).
    let e = w.energy();
    assert!(e.residual.abs() < 1e-9 * e.largest_term().max(1.0));
}

/// ΔPE booked from eq (10) agrees with the potential energy of the state.
#[test]
fn booked_potential_energy_matches_state_function() {
    let h = 0.3;
    let water = WaterParams {
        drag_coefficient: 1.0,
        linear_drag: 50.0,
        ..WaterParams::default()
    };
    let mut w = floating_block(h, water, 1.0);
    let pe0 = w.potential_energy();
    while w.time() < 5.0 {
        w.step();
    }
    let booked = w.energy().potential_energy;
    let state = w.potential_energy() - pe0;
    assert!(
        (booked - state).abs() < 1e-3 * state.abs(),
        "booked {booked} J/m, state {state} J/m"
    );
    assert!(w.energy().drag_dissipation > 0.0);
}

/// Drag acts on free blocks and rubble; sheet and floe blocks are damped by their own
/// boundary forces instead (eqs 7–8, the floe's dashpots), so they feel none, unless
/// `drag_bodies = All`. Where it acts, a floating block sliding at v₀ slows as quadratic
/// drag on its draft d says: m·dv/dt = −½·ρ_w·C_d·d·v², so v(t) = v₀/(1 + k·v₀·t/m) with
/// k = ½·ρ_w·C_d·d and m = ρ_i·h per metre, and the drag dissipates ½·m·(v₀² − v(t)²).
#[test]
fn drag_acts_on_rubble_not_on_sheet_blocks() {
    use pressridge_sim::dem::{Block, DragBodies, Role};
    let mut dissipated = Vec::new();
    let (h, v0, t_end) = (0.3, 0.5, 1.0);
    let runs = [
        (Role::Rubble, DragBodies::Rubble),
        (Role::Sheet, DragBodies::Rubble),
        (Role::Sheet, DragBodies::All),
        (Role::Floe, DragBodies::All),
    ];
    for (role, bodies) in runs {
        let params = WorldParams {
            water: Some(WaterParams {
                drag_bodies: bodies,
                ..WaterParams::default()
            }),
            ..WorldParams::default()
        };
        let mut w = World::new(params).unwrap();
        let block = Block {
            width: 1.0,
            thickness: h,
            bevel: [0.0; 4],
            bevel_run: None,
        };
        let y = h / 2.0 - h * RHO_I / RHO_W;
        let id = w
            .add_rect(block, V2::new(0.0, y), 0.0, Drive::FREE, role)
            .unwrap();
        w.set_velocity(id, V2::new(v0, 0.0), 0.0);
        while w.time() < t_end {
            w.step();
        }
        dissipated.push((w.energy().drag_dissipation, w.time()));
    }
    let m = RHO_I * h;
    let k = 0.5 * RHO_W * 1.0 * h * RHO_I / RHO_W;
    let expected = |t: f64| {
        let v = v0 / (1.0 + k * v0 * t / m);
        0.5 * m * (v0 * v0 - v * v)
    };
    // Rubble, and every body under `All`: the analytical loss (about 20 J/m) to 0.5 %.
    for i in [0, 2, 3] {
        let (d, t) = dissipated[i];
        let e = expected(t);
        assert!((d - e).abs() < 5e-3 * e, "run {i}: {d} J/m against {e} J/m");
    }
    // A sheet block under the default keeps its speed.
    assert_eq!(dissipated[1].0, 0.0);
}

/// A 1 m × 0.3 m block held under water without gravity, spun at ω₀ = 2 rad/s at angle
/// `theta` (rad) about its centroid; returns ω (rad/s) after 2 s.
fn spin_down(theta: f64) -> f64 {
    let mut w = World::new(WorldParams {
        gravity: 0.0,
        ..WorldParams::default()
    })
    .unwrap();
    let b = w.add_block(
        Shape::rectangle(1.0, 0.3).unwrap(),
        V2::new(0.0, -3.0),
        theta,
        Drive {
            u: Some(0.0),
            v: Some(0.0),
            omega: None,
        },
    );
    w.set_velocity(b, V2::default(), 2.0);
    while w.time() < 2.0 {
        w.step();
    }
    w.bodies().omega[b as usize]
}

/// The spin drag of a submerged block is the quadratic pressure ½·ρ_w·C_d·v_n² on its faces
/// summed as a moment, M = −½·ρ_w·C_d·J·|ω|·ω with J = (a⁴ + b⁴)/32 for an a × b rectangle
/// (the plate's strip-theory moment ρ_w·C_d·a⁴/64·ω² when b → 0). So I·dω/dt = −k·ω² and
/// ω(t) = ω₀/(1 + k·ω₀·t/I), whatever way the block is turned: within 0.1 % of that, and the
/// same to 1e-9 at 0°, 30°, 45° and 90°. (The former moment took the diagonal of the
/// world-axis bounding box and spun this block down 2.4 times as hard at 45° as level.)
#[test]
fn the_spin_drag_moment_does_not_depend_on_the_blocks_turn() {
    let (a, b) = (1.0f64, 0.3f64);
    let inertia = RHO_I * a * b * (a * a + b * b) / 12.0;
    let k = 0.5 * RHO_W * 1.0 * (a.powi(4) + b.powi(4)) / 32.0;
    let want = 2.0 / (1.0 + k * 2.0 * 2.0 / inertia);
    let level = spin_down(0.0);
    assert!(
        (level - want).abs() < 1e-3 * want,
        "ω after 2 s {level} rad/s, theory {want} rad/s"
    );
    for deg in [30.0f64, 45.0, 90.0] {
        let turned = spin_down(deg.to_radians());
        assert!(
            (turned - level).abs() < 1e-9 * level,
            "{deg}°: {turned} rad/s against {level} rad/s level"
        );
    }
}
