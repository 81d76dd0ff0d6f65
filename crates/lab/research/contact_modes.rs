//! How close the pile's contacts bring the leapfrog to its stability limit
//! (docs/notes/speed-vs-error-former-model.md,
//! "Fracture and the time step"). The stable step allows for one contact per block (with a
//! margin of √2); a block pressed by several stiff contacts at once has faster modes.
//!
//! For a saved state, each contact's ω·Δt = Δt·sqrt(k_ne·L·(κ_a + κ_b)) (L the chord, κ the
//! blocks' inverse effective masses along the normal at the contact point, over their free
//! degrees of freedom), and per block the Gershgorin-type bound sqrt(Σ (ω·Δt)²) over the
//! block's contacts, an upper estimate of ω·Δt of the modes it takes part in; the leapfrog is
//! stable below 2 and overstates the amplitude of a mode's answer to a kick by
//! 1/sqrt(1 − (ω·Δt/2)²). Prints the distribution of both, and the same for the contacts'
//! tangential springs of eq (4), ω_t·Δt = Δt·sqrt(k_te·(κ_a + κ_b)) with κ along the
//! tangent (k_te = 0.6·k_ne·L per contact), and the distribution of the chords.
//!
//! ```sh
//! cargo run --release --example contact_modes -- STATE.json [DT_S]
//! ```

use pressridge::dem::overlap;
use pressridge::dem::{V2, World};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let path = args
        .first()
        .ok_or("usage: contact_modes STATE.json [DT_S]")?;
    let snap = pressridge::io::state::load_state(std::path::Path::new(path))?;
    let w = World::from_snapshot(&snap)?;
    let dt: f64 = args.get(1).map_or(Ok(w.dt()), |s| s.parse())?;
    let b = w.bodies();
    let k_ne = w.params().contact.normal_stiffness;
    let k_te_per_chord = w.params().contact.tangential_stiffness_per_chord();
    let kappa = |i: usize, p: V2, n: V2| {
        let d = b.drive[i];
        let mut k = 0.0;
        if d.u.is_none() {
            k += n.x * n.x / b.mass[i];
        }
        if d.v.is_none() {
            k += n.y * n.y / b.mass[i];
        }
        if d.omega.is_none() {
            let rn = (p - b.pos[i]).cross(n);
            k += rn * rn / b.inertia[i];
        }
        k
    };
    let outline = |i: usize| snap.bodies[i].world_outline();
    let mut per_body = vec![0.0f64; b.len()];
    let mut per_contact = vec![];
    let mut per_body_t = vec![0.0f64; b.len()];
    let mut per_contact_t = vec![];
    let mut chords = vec![];
    for c in w.contacts() {
        let (ia, ib) = ((c.key >> 32) as usize, (c.key & 0xffff_ffff) as usize);
        let Some(ov) = overlap(&outline(ia), &outline(ib), b.pos[ia], b.pos[ib]) else {
            continue;
        };
        let z2 = dt
            * dt
            * k_ne
            * ov.chord
            * (kappa(ia, ov.centroid, ov.normal) + kappa(ib, ov.centroid, ov.normal));
        per_contact.push(z2.sqrt());
        chords.push(ov.chord);
        per_body[ia] += z2;
        per_body[ib] += z2;
        let t = ov.normal.perp();
        let k_te = k_te_per_chord * ov.chord;
        let z2 = dt * dt * k_te * (kappa(ia, ov.centroid, t) + kappa(ib, ov.centroid, t));
        per_contact_t.push(z2.sqrt());
        per_body_t[ia] += z2;
        per_body_t[ib] += z2;
    }
    let root =
        |v: &[f64]| -> Vec<f64> { v.iter().filter(|&&x| x > 0.0).map(|x| x.sqrt()).collect() };
    let (mut bodies, mut bodies_t) = (root(&per_body), root(&per_body_t));
    let show = |name: &str, v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        let q = |f: f64| v[((v.len() - 1) as f64 * f).round() as usize];
        let over = |x: f64| v.iter().filter(|&&z| z > x).count();
        println!(
            "{name}: {} | median {:.2} | 90 % {:.2} | max {:.2} | above 1: {} | above 1.5: {} | above 2: {}",
            v.len(),
            q(0.5),
            q(0.9),
            q(1.0),
            over(1.0),
            over(1.5),
            over(2.0)
        );
    };
    println!(
        "Δt = {dt:.3e} s, k_ne = {k_ne:e} N/m³, k_te = {k_te_per_chord:e} N/m³ times the chord"
    );
    show("contacts, ω·Δt", &mut per_contact);
    show("blocks in contact, sqrt(Σ (ω·Δt)²)", &mut bodies);
    show("contacts' tangential springs, ω_t·Δt", &mut per_contact_t);
    show("contacts' chords L (m)", &mut chords);
    show("blocks in contact, sqrt(Σ (ω_t·Δt)²)", &mut bodies_t);
    Ok(())
}
