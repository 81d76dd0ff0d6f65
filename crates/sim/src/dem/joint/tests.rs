use super::*;
use crate::dem::body::{Drive, Shape};

/// Two joined 0.25 m × 0.30 m blocks, displaced and moving (each degree of freedom
/// its own rate, one block spun), with an outside force on each: (bodies, joint).
fn pair() -> (Bodies, Joint) {
    let mut b = Bodies::default();
    let shape = Shape::rectangle(0.25, 0.30).unwrap();
    b.push(shape, 920.0, V2::new(0.0, 0.0), 0.0, Drive::FREE);
    b.push(shape, 920.0, V2::new(0.2505, 0.001), 0.01, Drive::FREE);
    b.vel = vec![V2::new(0.03, -0.02), V2::new(-0.05, 0.04)];
    b.omega = vec![0.3, -0.7];
    let mat = JointMaterial {
        e_top: 1e8,
        e_bottom: 6.7e7,
        poisson: 0.3,
        damping_fraction: 0.1,
        strength_top: f64::INFINITY,
        strength_bottom: f64::INFINITY,
    };
    let j = Joint::new(
        0,
        1,
        crate::dem::joint::JointGeometry {
            pa: V2::new(0.125, 0.0),
            pb: V2::new(-0.125, 0.0),
            h: 0.30,
            skeletal: 0.06,
            gauge: 0.25,
        },
        mat,
    );
    (b, j)
}

/// The implicit dashpot's viscous force is the explicit formula evaluated at the mid-step
/// velocities ½(vⁿ⁻½ + vⁿ⁺½) that the step it enters produces: the centring, exact for
/// an isolated joint.
#[test]
fn implicit_dashpot_is_the_explicit_one_at_the_mid_step_velocity() {
    let dt = 4e-4;
    let (mut b, mut j) = pair();
    for i in 0..2 {
        b.update_world(i);
        b.force[i] = V2::new(3.0 - 5.0 * i as f64, -2e3);
        b.torque[i] = 40.0 * (i as f64 - 0.5);
    }
    j.apply(&mut b, 920.0, Dashpot::Implicit);
    j.apply_viscous(&mut b, dt);
    let implicit = j.forces[1];
    // The step's new velocities, and the explicit dashpot at their mean.
    let mut mid = b.clone();
    for i in 0..2 {
        let [ix, iy, iw] = b.inverse_masses(i);
        let v1 = b.vel[i] + V2::new(b.force[i].x * ix, b.force[i].y * iy) * dt;
        let w1 = b.omega[i] + b.torque[i] * iw * dt;
        mid.vel[i] = (b.vel[i] + v1) * 0.5;
        mid.omega[i] = 0.5 * (b.omega[i] + w1);
    }
    let mut jm = j;
    jm.apply(&mut mid, 920.0, Dashpot::Explicit);
    let explicit = jm.forces[1];
    let scale = explicit.fb.norm() + explicit.mb.abs();
    assert!(scale > 1e3, "a viscous force worth testing: {scale}");
    let diff = (implicit.fa - explicit.fa).norm()
        + (implicit.fb - explicit.fb).norm()
        + (implicit.ma - explicit.ma).abs()
        + (implicit.mb - explicit.mb).abs();
    assert!(
        diff <= 1e-10 * scale,
        "implicit {implicit:?} against explicit at the mid-step velocity {explicit:?}"
    );
    // And as Δt → 0 it is the explicit dashpot at the half-step velocities.
    let (mut b0, mut j0) = pair();
    let (mut b1, mut j1) = pair();
    for bb in [&mut b0, &mut b1] {
        for i in 0..2 {
            bb.update_world(i);
        }
    }
    j0.apply(&mut b0, 920.0, Dashpot::Explicit);
    j1.apply(&mut b1, 920.0, Dashpot::Implicit);
    j1.apply_viscous(&mut b1, 1e-12);
    let (e, i) = (j0.forces[1], j1.forces[1]);
    assert!((e.fb - i.fb).norm() <= 1e-6 * e.fb.norm(), "{e:?} {i:?}");
    assert!((e.mb - i.mb).abs() <= 1e-6 * e.mb.abs(), "{e:?} {i:?}");
}

/// The 4 × 4 solve against a system with a known answer, with a zero first pivot.
#[test]
fn solve4_solves_with_pivoting() {
    let a = [
        [0.0, 2.0, 1.0, 0.0],
        [1.0, 1.0, 0.0, 3.0],
        [2.0, 0.0, 4.0, 1.0],
        [0.0, 1.0, 1.0, 1.0],
    ];
    let x = [1.0, -2.0, 0.5, 3.0];
    let b: [f64; 4] = std::array::from_fn(|r| (0..4).map(|k| a[r][k] * x[k]).sum());
    let got = solve4(a, b);
    for k in 0..4 {
        assert!((got[k] - x[k]).abs() < 1e-14, "{got:?}");
    }
}
