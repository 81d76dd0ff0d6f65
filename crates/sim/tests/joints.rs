//! Verification of the viscous-elastic joints (eq 1) and of flexural fracture against beam
//! theory.

use pressridge_sim::dem::{
    Block, BodyId, Drive, JointMaterial, Role, V2, WaterParams, World, WorldParams,
};

const H: f64 = 0.30;
const W: f64 = 0.25;
const E_TOP: f64 = 1.0e8;
const E_BOT: f64 = 6.7e7;
const SKEL: f64 = 0.06;

fn material(strength: f64) -> JointMaterial {
    JointMaterial {
        e_top: E_TOP,
        e_bottom: E_BOT,
        poisson: 0.3,
        damping_fraction: 0.1,
        strength_top: strength,
        strength_bottom: strength,
    }
}

/// Flexural rigidity per metre of depth (N·m²/m) of the joint span: E varies linearly from
/// E_BOT at s = −h/2 to E_TOP at s = +h/2, the skeletal layer carries nothing, and the
/// bending axis is the modulus-weighted centroid s̄ of the span.
fn flexural_rigidity() -> f64 {
    section().0
}

/// The joint span's flexural rigidity (N·m²/m) and its bending axis s̄ (m from mid-thickness),
/// as [`flexural_rigidity`] describes them.
fn section() -> (f64, f64) {
    let (lo, hi) = (-H / 2.0 + SKEL, H / 2.0);
    let n = 20_000;
    let ds = (hi - lo) / n as f64;
    let (mut m0, mut m1) = (0.0, 0.0);
    for k in 0..n {
        let s = lo + (k as f64 + 0.5) * ds;
        m0 += modulus(s) * ds;
        m1 += modulus(s) * s * ds;
    }
    let sbar = m1 / m0;
    let ei = (0..n)
        .map(|k| {
            let s = lo + (k as f64 + 0.5) * ds;
            modulus(s) * (s - sbar).powi(2) * ds
        })
        .sum();
    (ei, sbar)
}

/// The modulus (Pa) at height `s` (m) from mid-thickness: E_BOT at the bottom, E_TOP at the top.
fn modulus(s: f64) -> f64 {
    E_BOT + (E_TOP - E_BOT) * (s + H / 2.0) / H
}

/// A row of `n` joined W × H blocks starting with its left face at x = 0, block centres at
/// height `y`. The first block's drive is `first`; both faces' strength is `strength` (Pa).
fn row(w: &mut World, n: usize, y: f64, first: Drive, strength: f64) -> Vec<BodyId> {
    row_of(w, n, y, first, material(strength))
}

/// [`row`] with its joints of material `mat`.
fn row_of(w: &mut World, n: usize, y: f64, first: Drive, mat: JointMaterial) -> Vec<BodyId> {
    let mut ids: Vec<BodyId> = Vec::new();
    for k in 0..n {
        let block = Block {
            width: W,
            thickness: H,
            bevel: [0.0; 4],
            bevel_run: None,
        };
        let drive = if k == 0 { first } else { Drive::FREE };
        let id = w
            .add_rect(
                block,
                V2::new((k as f64 + 0.5) * W, y),
                0.0,
                drive,
                Role::Sheet,
            )
            .unwrap();
        if let Some(&p) = ids.last() {
            w.join(p, id, SKEL, mat).unwrap();
        }
        ids.push(id);
    }
    ids
}

/// A cantilever of 20 free blocks held by a fixed block bends under an end load P like an
/// Euler–Bernoulli beam: δ = P·L³/(3·EI) within 3 %, EI that of the linearly varying
/// modulus over the joint span. Each joint is a rotational spring EI/W standing for the
/// length W of beam centred on it, so the clamp of the equivalent beam is at the centre of
/// the held block and L is the distance from there to the load.
#[test]
fn cantilever_bends_like_euler_bernoulli() {
    let mut w = World::new(WorldParams {
        gravity: 0.0,
        water: None,
        global_damping: 5.0,
        ..WorldParams::default()
    })
    .unwrap();
    let ids = row(&mut w, 21, 0.0, Drive::FIXED, f64::INFINITY);
    let ei = flexural_rigidity();
    let last = *ids.last().unwrap();
    let length = w.bodies().pos[last as usize].x - w.bodies().pos[ids[0] as usize].x;
    // Small deflection: about 1 cm.
    let p = 0.01 * 3.0 * ei / length.powi(3);
    w.set_load(last, V2::new(0.0, -p));
    while w.time() < 15.0 {
        w.step();
    }
    let delta = -w.bodies().pos[last as usize].y;
    eprintln!("delta {delta}");
    let theory = p * length.powi(3) / (3.0 * ei);
    assert!(
        ((delta - theory) / theory).abs() < 0.03,
        "deflection {delta} m, Euler–Bernoulli {theory} m (EI = {ei} N·m²/m)"
    );
    assert!(w.bodies().vel[last as usize].norm() < 1e-6, "not at rest");
    // The work of the load went into the joints (held) and the damping.
    let e = w.energy();
    assert!(e.residual.abs() < 1e-9 * e.work.abs());
    assert!((e.elastic_energy - 0.5 * p * delta).abs() < 0.01 * 0.5 * p * delta);
}

/// Water of the paper's density (kg/m³) for the floating-sheet tests.
const RHO_W: f64 = 1010.0;

/// A world of still water without drag and with light global damping, for a sheet lifted
/// quasi-statically; and the height (m) of a floating H-thick block's centre in it.
fn still_water() -> (World, f64) {
    let w = World::new(WorldParams {
        water: Some(WaterParams {
            density: RHO_W,
            drag_coefficient: 0.0,
            ..WaterParams::default()
        }),
        global_damping: 3.0,
        ..WorldParams::default()
    })
    .unwrap();
    (w, H / 2.0 - H * 920.0 / RHO_W)
}

/// A floating sheet lifted at its free end, slowly, first cracks where the moment of a
/// semi-infinite beam on an elastic foundation peaks (Hetényi 1946): at π/(4β) from the
/// load, β = (ρ_w·g/(4·EI))^¼ — within 20 %.
///
/// Buoyancy is a linear (Winkler) foundation only while every block stays partly
/// submerged: a 0.30 m sheet floods once pushed down 2.7 cm, and leaves the water once
/// lifted by its 0.27 m draft. At Table 1's strengths the breaking load lifts the tip
/// ≈ 0.37 m (the next test), beyond both, so this test lifts the tip (the larger margin) and
/// uses a 100 kPa strength: the place of the moment peak does not depend on the strength.
#[test]
fn floating_sheet_first_breaks_at_hetenyi_distance() {
    let (mut w, yc) = still_water();
    let n = 120; // 30 m: far longer than 1/β ≈ 2.5 m.
    let ids = row(&mut w, n, yc, Drive::FREE, 100e3);
    let tip = *ids.last().unwrap();
    let x_load = w.bodies().pos[tip as usize].x;
    let rate = 500.0; // N/m per s: quasi-static next to the ~1 s heave period.
    let mut first: Option<f64> = None;
    while w.time() < 60.0 && first.is_none() {
        for _ in 0..50 {
            w.set_load(tip, V2::new(0.0, rate * w.time()));
            w.step();
        }
        // The earliest crack: once one joint cracks, the next starts within milliseconds
        // (its load is shed onto its neighbours), often within the same 50 steps.
        if let Some(j) = w
            .joints()
            .iter()
            .filter(|j| j.crack_started >= 0.0)
            .min_by(|p, q| p.crack_started.total_cmp(&q.crack_started))
        {
            let a = j.a as usize;
            let (s, c) = w.bodies().theta[a].sin_cos();
            first = Some(x_load - (w.bodies().pos[a] + j.pa.rotate(c, s)).x);
        }
    }
    let lift = w.bodies().pos[tip as usize].y - yc;
    assert!(
        lift > 0.0 && lift < 0.2,
        "tip lift {lift} m left the linear range"
    );
    let got = first.expect("the sheet never cracked");
    eprintln!("first crack at {got} m, lift {lift} m");
    let beta = (RHO_W * 9.81 / (4.0 * flexural_rigidity())).powf(0.25);
    let theory = std::f64::consts::PI / (4.0 * beta);
    assert!(
        ((got - theory) / theory).abs() < 0.2,
        "first crack {got} m from the load, Hetényi π/(4β) = {theory} m"
    );
}

/// A floating sheet of Table 1 (tensile strength 750 kPa at the top, 350 kPa at the bottom)
/// lifted slowly at its free end first cracks at the tip lift of Hetényi's (1946)
/// semi-infinite beam on a Winkler foundation k = ρ_w·g: the end load P lifts the tip by
/// 2Pβ/k and bends the beam most, M = 0.3224·P/β (bottom in tension), at π/(4β), so the
/// bottom fibre of the joint span reaches its strength σ_b at the lift
/// w = σ_b·EI/(E_b·c_b) / (0.3224·√(k·EI)), E_b and c_b the modulus and the distance from the
/// bending axis at the span's bottom (the skeletal layer carries nothing). Within 5 % at the
/// paper's three lead-ice moduli: 0.37, 0.19 and 0.12 m at 0.1, 0.4 and 1 GPa, falling as
/// E^(−½). A lift at its tip alone breaks the 0.30-m sheet of 0.1 GPa before it has climbed
/// the ≈ 0.45 m (its draft plus the 2-m floe's freeboard) onto the floe (`docs/choices.md`,
/// "Low friction").
#[test]
fn floating_sheet_lifted_at_its_end_cracks_at_hetenyis_lift() {
    let k = RHO_W * 9.81;
    let (ei_ref, sbar) = section();
    let span_bottom = -H / 2.0 + SKEL;
    for e_top in [1.0e8, 4.0e8, 1.0e9] {
        let scale = e_top / E_TOP;
        let (mut w, yc) = still_water();
        let mat = JointMaterial {
            e_top,
            e_bottom: E_BOT * scale,
            strength_top: 750e3,
            strength_bottom: 350e3,
            ..material(0.0)
        };
        let ids = row_of(&mut w, 120, yc, Drive::FREE, mat);
        let tip = *ids.last().unwrap();
        let rate = 200.0; // N/m per s: quasi-static next to the ~1 s heave period.
        let mut lift = None;
        while w.time() < 100.0 && lift.is_none() {
            for _ in 0..50 {
                w.set_load(tip, V2::new(0.0, rate * w.time()));
                w.step();
            }
            if w.joints().iter().any(|j| j.crack_started >= 0.0) {
                lift = Some(w.bodies().pos[tip as usize].y - yc);
            }
        }
        let got = lift.expect("the sheet never cracked");
        let ei = ei_ref * scale;
        let moment = 350e3 * ei / (modulus(span_bottom) * scale * (sbar - span_bottom));
        let theory = moment / (0.3224 * (k * ei).sqrt());
        eprintln!(
            "E_top {e_top:e} Pa: tip lift at the first crack {got:.3} m, Hetényi {theory:.3} m"
        );
        assert!(
            ((got - theory) / theory).abs() < 0.05,
            "E_top {e_top:e} Pa: cracked at a lift of {got} m, Hetényi {theory} m"
        );
    }
}

/// A crack crosses a joint at the crack speed, over many steps, while the rest of the joint
/// carries the load; then the blocks part and interact by contact only.
#[test]
fn crack_takes_many_steps_to_cross_a_joint() {
    let mut w = World::new(WorldParams {
        gravity: 0.0,
        water: None,
        ..WorldParams::default()
    })
    .unwrap();
    let ids = row(&mut w, 2, 0.0, Drive::FIXED, 350e3);
    // A pull well above what the joint can take: 1 MPa over the 0.24 m span.
    w.set_load(ids[1], V2::new(1.0e6 * (H - SKEL), 0.0));
    let mut started = None;
    let mut severed = None;
    while w.time() < 0.5 && severed.is_none() {
        w.step();
        let j = &w.joints()[0];
        if started.is_none() && j.crack_started >= 0.0 {
            started = Some(w.steps());
        }
        if !j.is_intact() {
            severed = Some(w.steps());
        }
    }
    let (s0, s1) = (started.unwrap(), severed.unwrap());
    let steps = s1 - s0;
    let span = H - SKEL;
    let speed = w.params().crack_speed;
    // Both faces crack under uniform tension: the cracks meet in the middle.
    // At the step the crack was taken in (refined to a fraction of Δt while it cracks).
    let at_most = (span / (speed * w.last_step())).ceil() as u64 + 1;
    assert!(steps >= 5, "crack crossed in {steps} steps");
    assert!(
        steps <= at_most,
        "crack took {steps} steps, more than {at_most}"
    );
    assert_eq!(w.blocks_broken(), 1);
    // Once severed the pull separates the blocks: no joint force any more.
    for _ in 0..2000 {
        w.step();
    }
    assert!(w.bodies().pos[ids[1] as usize].x > 0.75 * W + 0.01);
    let e = w.energy();
    assert!(e.fracture_dissipation > 0.0, "{e:?}");
    assert!(e.residual.abs() < 1e-9 * e.work);
}
