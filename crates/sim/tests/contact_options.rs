//! Verification of the contact law's open options (docs/choices.md): the plastic cap on the
//! elastic normal force (`contact.crushing_pressure`), eq (3)'s damping per contact
//! (`contact.damping_law = "contact"`), and a block pushed up a ramp, whose locking angle is
//! what the floe nose's slope (`floe.nose_slope`) decides.

use pressridge_sim::dem::{ContactParams, DampingLaw, Drive, Shape, V2, World, WorldParams};

const RHO_I: f64 = 920.0;
const K_NE: f64 = 1e8;

mod support;

/// Two 1 m × 0.3 m blocks 2 cm apart face to face, closing at 0.5 m/s each, without gravity,
/// water or friction, with the contact parameters `contact`, at one step of half the stable
/// limit: the accuracy these checks were made at. (At the default step, the full limit
/// refined for the impact, the capped contact's plastic work comes out 1.7 % low; at half
/// the limit refined after the impact, the area law's hysteresis across the step change is
/// 0.6 % of it.)
fn face_on_pair(contact: ContactParams) -> World {
    support::pair::face_on_pair(
        WorldParams {
            contact: ContactParams {
                mu: 0.0,
                mu_water: 0.0,
                ..contact
            },
            time_step_safety: 0.5,
            refine_impact: None,
            ..WorldParams::default()
        },
        0.0,
    )
}

/// An undamped face-on collision loaded past the cap p_c·h (p_c = 0.1 MPa on the 0.3-m face)
/// and unloaded. The contact is elastic–perfectly plastic: it stores at most
/// E_y = (p_c·h)²/(2·k_ne·h) = 15 J/m of the 69 J/m brought in, crushes the rest at the
/// constant force p_c·h and gives back E_y as the blocks part: restitution sqrt(E_y/KE₀) =
/// 0.466. The work of the normal forces not recovered (eq (12)'s Φ_i, here all elastic)
/// equals the plastic work booked, p_c·ΔA_p = KE₀ − E_y, to the step's accuracy; the
/// ledger closes; and the crushed overlap is the plastic approach times the face.
#[test]
fn a_capped_contact_loaded_past_its_limit_keeps_the_plastic_work() {
    let p_c = 1e5;
    let h = 0.3;
    let mut w = face_on_pair(ContactParams {
        damping_fraction: 0.0,
        crushing_pressure: p_c,
        ..ContactParams::default()
    });
    let ke0 = w.bodies().kinetic_energy();
    assert!((ke0 - 69.0).abs() < 1e-9, "{ke0}");
    let mut peak: f64 = 0.0;
    while w.time() < 0.2 {
        w.step();
        for c in w.contacts() {
            peak = peak.max(c.area);
        }
    }
    assert!(w.contacts().is_empty(), "the blocks have parted");
    let e = w.energy();
    let held = (p_c * h).powi(2) / (2.0 * K_NE * h);
    let plastic = ke0 - held;
    assert!(
        (e.plastic_dissipation - plastic).abs() < 0.01 * plastic,
        "plastic work {} J/m, elastic–plastic theory {plastic} J/m",
        e.plastic_dissipation
    );
    // Not recovered: the net elastic normal work of the cycle is the plastic work, up to the
    // area law's discrete hysteresis (booked apart).
    assert!(
        (e.normal_elastic_work - e.plastic_dissipation).abs() < 1e-3 * plastic,
        "not recovered {} J/m, plastic {} J/m",
        e.normal_elastic_work,
        e.plastic_dissipation
    );
    assert!(e.viscous_dissipation == 0.0 && e.friction_dissipation == 0.0);
    let ke1 = w.bodies().kinetic_energy();
    let restitution = (ke1 / ke0).sqrt();
    let want = (held / ke0).sqrt();
    assert!(
        (restitution - want).abs() < 0.01 * want,
        "restitution {restitution}, theory {want}"
    );
    assert!(e.residual.abs() < 1e-9 * ke0, "residual {}", e.residual);
    // The deepest overlap: the elastic part at the cap plus the crushed part, over the face.
    let deepest = (plastic / p_c + p_c * h / K_NE) / 1.0;
    assert!(
        (peak - deepest).abs() < 0.02 * deepest,
        "peak overlap {peak} m², theory {deepest} m²"
    );
}

/// Below the cap nothing changes: the same collision with p_c = 10 MPa (the force never
/// reaches p_c·h) gives the same state as no cap, bit for bit.
#[test]
fn a_cap_that_is_never_reached_changes_nothing() {
    let run = |p_c: f64| {
        let mut w = face_on_pair(ContactParams {
            crushing_pressure: p_c,
            ..ContactParams::default()
        });
        while w.time() < 0.2 {
            w.step();
        }
        (w.bodies().vel.clone(), w.energy())
    };
    let (v0, e0) = run(0.0);
    let (v1, e1) = run(1e7);
    assert_eq!(v0, v1);
    assert_eq!(e1.plastic_dissipation, 0.0);
    assert_eq!(e0.viscous_dissipation, e1.viscous_dissipation);
}

/// The exact restitution of a corner of 90° striking a flat face under eq (2) with the
/// dashpot of [`DampingLaw::Contact`]: overlap A = δ², chord L = 2δ, so
/// m·δ̈ = −k_ne·δ² − ζ·2·sqrt(k_ne·2δ·m)·δ̇ with the force never pulling. The problem is
/// self-similar (δ scales as v₀^(2/3)), so e depends on ζ alone. Integrated by RK4 in
/// 2·10⁵ steps of the contact's duration.
fn corner_restitution_exact(zeta: f64, m: f64, v0: f64) -> f64 {
    let f = |d: f64, v: f64| {
        let fe = K_NE * d * d;
        let fv = zeta * 2.0 * (K_NE * 2.0 * d.max(0.0) * m).sqrt() * v;
        -(fe + fv).max(0.0) / m
    };
    // Time scale of the contact: δ ~ (m·v₀²/k_ne)^(1/3) crossed at v₀.
    let tc = (m / (K_NE * v0)).powf(1.0 / 3.0);
    let dt = 10.0 * tc / 2e5;
    let (mut d, mut v) = (0.0f64, v0);
    for _ in 0..200_000 {
        let k1 = (v, f(d, v));
        let k2 = (
            v + 0.5 * dt * k1.1,
            f(d + 0.5 * dt * k1.0, v + 0.5 * dt * k1.1),
        );
        let k3 = (
            v + 0.5 * dt * k2.1,
            f(d + 0.5 * dt * k2.0, v + 0.5 * dt * k2.1),
        );
        let k4 = (v + dt * k3.1, f(d + dt * k3.0, v + dt * k3.1));
        d += dt / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
        v += dt / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
        if d < 0.0 {
            break;
        }
    }
    -v / v0
}

/// A 0.3 m square turned by 45° (a corner down) dropped at `v0` (m/s) without gravity onto a
/// fixed floor, with eq (3) per contact at damping fraction `zeta`; returns its restitution.
fn corner_drop(zeta: f64, law: DampingLaw, v0: f64) -> f64 {
    let mut w = World::new(WorldParams {
        gravity: 0.0,
        water: None,
        contact: ContactParams {
            damping_fraction: zeta,
            damping_law: law,
            mu: 0.0,
            mu_water: 0.0,
            reference_thickness: Some(0.3),
            ..ContactParams::default()
        },
        ..WorldParams::default()
    })
    .unwrap();
    w.add_block(
        Shape::rectangle(4.0, 1.0).unwrap(),
        V2::new(0.0, -0.5),
        0.0,
        Drive::FIXED,
    );
    let half_diagonal = 0.15 * 2f64.sqrt();
    let b = w.add_block(
        Shape::rectangle(0.3, 0.3).unwrap(),
        V2::new(0.0, half_diagonal + 0.002),
        std::f64::consts::FRAC_PI_4,
        Drive::FREE,
    );
    w.set_velocity(b, V2::new(0.0, -v0), 0.0);
    while w.time() < 0.3 {
        w.step();
    }
    assert!(w.contacts().is_empty(), "the block has bounced off");
    w.bodies().vel[b as usize].y / v0
}

/// With eq (3) per contact each contact has the damping ratio it is given at every chord, so
/// a corner's restitution is the exact one of its nonlinear contact (within 3 % at the
/// default step) and the same at 0.1 and 1 m/s; with the paper's k_nv per unit chord the
/// corner's damping ratio ζ = f·sqrt(L·h·ρ_i·κ) grows with the chord, so the restitution
/// falls as the impact speed rises. At half critical a corner keeps about a third of its
/// speed.
#[test]
fn a_corner_impact_has_the_restitution_of_its_own_damping() {
    let m = RHO_I * 0.09;
    for v0 in [0.1, 1.0] {
        let e = corner_drop(0.5, DampingLaw::Contact, v0);
        let want = corner_restitution_exact(0.5, m, v0);
        assert!(
            (e - want).abs() < 0.03 * want,
            "v0 = {v0} m/s: restitution {e}, exact {want}"
        );
    }
    let slow = corner_restitution_exact(0.5, m, 0.1);
    let fast = corner_restitution_exact(0.5, m, 1.0);
    assert!((slow - fast).abs() < 1e-3 * slow, "{slow} {fast}");
    assert!((0.2..0.5).contains(&slow), "{slow}");
    let (sheet_slow, sheet_fast) = (
        corner_drop(0.5, DampingLaw::Sheet, 0.1),
        corner_drop(0.5, DampingLaw::Sheet, 1.0),
    );
    assert!(
        sheet_fast < sheet_slow - 0.05,
        "sheet law: {sheet_slow} at 0.1 m/s, {sheet_fast} at 1 m/s"
    );
}

/// A 0.5 m × 0.3 m block (rotation held) resting on a fixed plank tilted by `alpha` (rad),
/// dry with friction `mu`, pushed horizontally towards the uphill side by `p` (N/m) from
/// t = 0.05 s. Returns how far it moved up the slope between 0.25 s and 0.75 s (m).
fn pushed_up_ramp(mu: f64, alpha: f64, p: f64) -> f64 {
    let mut w = support::pair::dry(mu, WorldParams::default().gravity);
    let up = V2::new(alpha.cos(), alpha.sin());
    let n = up.perp();
    w.add_block(
        Shape::rectangle(20.0, 1.0).unwrap(),
        V2::default(),
        alpha,
        Drive::FIXED,
    );
    let b = w.add_block(
        Shape::rectangle(0.5, 0.3).unwrap(),
        n * (0.5 + 0.15 - 1e-4),
        alpha,
        Drive {
            u: None,
            v: None,
            omega: Some(0.0),
        },
    );
    while w.time() < 0.05 {
        w.step();
    }
    w.set_load(b, V2::new(p, 0.0));
    while w.time() < 0.25 {
        w.step();
    }
    let s0 = w.bodies().pos[b as usize].dot(up);
    while w.time() < 0.75 {
        w.step();
    }
    w.bodies().pos[b as usize].dot(up) - s0
}

/// A block pushed horizontally up a ramp of angle α with friction μ moves once
/// P·(cos α − μ·sin α) > G·(sin α + μ·cos α) and then accelerates at
/// (P·(cos α − μ·sin α) − G·(sin α + μ·cos α))/m; for tan α ≥ 1/μ no push moves it, the
/// harder it pushes the harder it presses (the locking angle, 45° at μ = 1). At μ = 1:
/// 30° and 40° (needing 3.7 G and 11.5 G) hold under 0.9 times their threshold and slide
/// under 1.5 times it, with the friction their acceleration implies, (P·cos α − G·sin α −
/// m·a)/(G·cos α + P·sin α), within 1 % of μ (near the locking angle the acceleration is a
/// small difference of large forces, so μ is the quantity to check); 50° holds under 50 G.
#[test]
fn a_block_pushed_up_a_ramp_locks_at_tan_alpha_one_over_mu() {
    let mu = 1.0;
    let g = RHO_I * 0.5 * 0.3 * 9.81;
    let m = RHO_I * 0.5 * 0.3;
    // A block that holds only rings on its tangential spring k_te = 0.6·k_ne·L (L the 0.5-m
    // face): within twice the static deflection of the push along the slope.
    let creep = |p: f64, a: f64| 2.0 * p * a.cos() / (0.6 * K_NE * 0.5);
    for deg in [30.0f64, 40.0] {
        let a = deg.to_radians();
        let threshold = g * (a.sin() + mu * a.cos()) / (a.cos() - mu * a.sin());
        let held = pushed_up_ramp(mu, a, 0.9 * threshold);
        assert!(
            held.abs() < creep(0.9 * threshold, a),
            "{deg}°: moved {held} m under 0.9× the threshold"
        );
        let p = 1.5 * threshold;
        let moved = pushed_up_ramp(mu, a, p);
        // From rest at 0.05 s: distance between 0.25 and 0.75 s under constant acceleration.
        let acc = 2.0 * moved / (0.7f64.powi(2) - 0.2f64.powi(2));
        let friction = (p * a.cos() - g * a.sin() - m * acc) / (g * a.cos() + p * a.sin());
        assert!(
            moved > 0.05 && (friction - mu).abs() < 0.01 * mu,
            "{deg}°: moved {moved} m, friction {friction} against μ = {mu}"
        );
    }
    let a = 50f64.to_radians();
    let locked = pushed_up_ramp(mu, a, 50.0 * g);
    assert!(
        locked.abs() < creep(50.0 * g, a),
        "50°: moved {locked} m under 50 G"
    );
}
