//! Rigid blocks: their roles, drives, nominal rectangles and the state arrays of the time step.
//!
//! State is kept as a structure of arrays (positions, velocities, forces each in their own
//! `Vec`) so that the integrator and the force loops stream through memory. A body's
//! position is its centroid; its outline is stored relative to the centroid.

use super::geometry::{Aabb, Outline, V2};
use serde::{Deserialize, Serialize};

mod shape;
pub use shape::{Shape, ShapeError};

/// Which degrees of freedom of a body are prescribed rather than integrated.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Drive {
    /// Prescribed horizontal velocity (m/s), or free when `None`.
    pub u: Option<f64>,
    /// Prescribed vertical velocity (m/s), or free when `None`.
    pub v: Option<f64>,
    /// Prescribed angular velocity (rad/s), or free when `None`.
    pub omega: Option<f64>,
}

impl Drive {
    /// All three degrees of freedom free: an ordinary dynamic body.
    pub const FREE: Drive = Drive {
        u: None,
        v: None,
        omega: None,
    };
    /// Held in place: a fixed wall or support.
    pub const FIXED: Drive = Drive {
        u: Some(0.0),
        v: Some(0.0),
        omega: Some(0.0),
    };
    /// True when every degree of freedom is prescribed.
    pub fn is_kinematic(&self) -> bool {
        self.u.is_some() && self.v.is_some() && self.omega.is_some()
    }
}

/// What a body is in a ridging scene: it decides which boundary conditions act on it and
/// how it is drawn and counted.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Role {
    /// A free block (rubble pile, test body).
    #[default]
    Block,
    /// A component block of the pushed lead-ice sheet.
    Sheet,
    /// A component block of the thick floe.
    Floe,
    /// A block broken from the sheet or floe.
    Rubble,
    /// A held wall or support.
    Wall,
}

/// The nominal rectangle of a block and its bevels, kept so that corners can be bevelled
/// again after a fracture.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Block {
    /// Width W (m).
    pub width: f64,
    /// Thickness h (m).
    pub thickness: f64,
    /// Bevel legs (m): bottom-left, bottom-right, top-right, top-left; for a bevel that is
    /// not at 45° (`bevel_run`), its drop along the vertical face.
    pub bevel: [f64; 4],
    /// The bevels' runs along the horizontal faces (m), in the order of `bevel`, where they
    /// differ from the drops; `None` for 45° bevels (run = drop). Absent when `None`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bevel_run: Option<[f64; 4]>,
}

impl Block {
    /// A block `width × thickness` (m) with 45° bevels of legs `bevel` (m).
    pub fn new(width: f64, thickness: f64, bevel: [f64; 4]) -> Block {
        Block {
            width,
            thickness,
            bevel,
            bevel_run: None,
        }
    }
    /// The bevels' runs along the horizontal faces (m).
    pub(crate) fn runs(&self) -> [f64; 4] {
        self.bevel_run.unwrap_or(self.bevel)
    }
    /// The rectangle's centre relative to the body's centroid, in the body frame (m).
    pub(crate) fn rect_centre(&self) -> V2 {
        -Shape::bevel_centroid(self.width, self.thickness, self.bevel, self.runs())
    }
    /// The shape of this block.
    pub fn shape(&self) -> Result<Shape, ShapeError> {
        Shape::bevelled_rectangle_legs(self.width, self.thickness, self.bevel, self.runs())
    }
}

/// Index of a body in [`Bodies`].
pub type BodyId = u32;

/// The state of all bodies, one entry per body in each array.
#[derive(Clone, Debug, Default)]
pub struct Bodies {
    /// Centroid position (m).
    pub pos: Vec<V2>,
    /// Orientation (rad, counter-clockwise).
    pub theta: Vec<f64>,
    /// Centroid velocity (m/s), at the half step n − ½ before a step and n + ½ after it.
    pub vel: Vec<V2>,
    /// Angular velocity (rad/s), staggered like `vel`.
    pub omega: Vec<f64>,
    /// Mass per metre of depth (kg/m).
    pub mass: Vec<f64>,
    /// Moment of inertia about the centroid per metre of depth (kg·m²/m).
    pub inertia: Vec<f64>,
    /// Shape relative to the centroid.
    pub shape: Vec<Shape>,
    /// Prescribed degrees of freedom.
    pub drive: Vec<Drive>,
    /// Role in the scene.
    pub role: Vec<Role>,
    /// Nominal rectangle and bevels, for blocks made as rectangles.
    pub block: Vec<Option<Block>>,
    /// Unit x axis of each body, (cos θ, sin θ), at the current orientation.
    pub(crate) axis: Vec<V2>,
    /// Outline in world coordinates at the current positions (m).
    pub(crate) world: Vec<Outline>,
    /// Bounding box of `world` (m).
    pub(crate) aabb: Vec<Aabb>,
    /// Resultant force of the current step (N/m).
    pub(crate) force: Vec<V2>,
    /// Resultant moment of the current step about the centroid (N·m/m).
    pub(crate) torque: Vec<f64>,
}

impl Bodies {
    /// Number of bodies.
    pub fn len(&self) -> usize {
        self.pos.len()
    }
    /// True when there is no body.
    pub fn is_empty(&self) -> bool {
        self.pos.is_empty()
    }

    /// Adds a body of the given shape and density (kg/m³) at centroid `pos` (m) with
    /// orientation `theta` (rad), at rest. Returns its index.
    pub(crate) fn push(
        &mut self,
        shape: Shape,
        density: f64,
        pos: V2,
        theta: f64,
        drive: Drive,
    ) -> BodyId {
        let id = self.pos.len() as BodyId;
        self.pos.push(pos);
        self.theta.push(theta);
        self.vel
            .push(V2::new(drive.u.unwrap_or(0.0), drive.v.unwrap_or(0.0)));
        self.omega.push(drive.omega.unwrap_or(0.0));
        self.mass.push(density * shape.area());
        self.inertia.push(density * shape.polar_moment());
        self.shape.push(shape);
        self.drive.push(drive);
        self.role.push(Role::Block);
        self.block.push(None);
        self.axis.push(V2::new(1.0, 0.0));
        self.world.push(Outline::default());
        self.aabb.push(Aabb::default());
        self.force.push(V2::default());
        self.torque.push(0.0);
        self.update_world(id as usize);
        id
    }

    /// Replaces the shape of body `i` by `shape`, whose centroid lies at `shift` (m, body
    /// frame) from the old one: the pose and velocity move to the new centroid and the mass
    /// properties follow the new area. Returns the change of kinetic energy (J/m), which the
    /// caller books (material cut away takes its kinetic energy with it).
    pub(crate) fn reshape(&mut self, i: usize, shape: Shape, shift: V2, density: f64) -> f64 {
        let ke = |b: &Bodies| {
            0.5 * b.mass[i] * b.vel[i].dot(b.vel[i]) + 0.5 * b.inertia[i] * b.omega[i] * b.omega[i]
        };
        let before = ke(self);
        let (s, c) = self.theta[i].sin_cos();
        let r = shift.rotate(c, s);
        self.pos[i] = self.pos[i] + r;
        self.vel[i] = self.vel[i] + r.perp() * self.omega[i];
        self.mass[i] = density * shape.area();
        self.inertia[i] = density * shape.polar_moment();
        self.shape[i] = shape;
        self.update_world(i);
        ke(self) - before
    }

    /// Recomputes every body's world outline and bounding box from its pose
    /// ([`Bodies::update_world`]), on the threads of `pool` when given (each body is its own:
    /// the same bits on any number of threads).
    pub(crate) fn update_all(&mut self, pool: Option<&rayon::ThreadPool>) {
        let Some(pool) = pool else {
            for i in 0..self.len() {
                self.update_world(i);
            }
            return;
        };
        use rayon::prelude::*;
        let (shape, theta, pos) = (&self.shape, &self.theta, &self.pos);
        pool.install(|| {
            self.axis
                .par_iter_mut()
                .zip(self.world.par_iter_mut())
                .zip(self.aabb.par_iter_mut())
                .enumerate()
                .for_each(|(i, ((axis, world), aabb))| {
                    let (s, c) = theta[i].sin_cos();
                    *axis = V2::new(c, s);
                    world.set_transformed(shape[i].outline(), c, s, pos[i]);
                    *aabb = Aabb::of(world.verts());
                });
        });
    }

    /// Recomputes the world outline and bounding box of body `i` from its pose.
    #[inline]
    pub(crate) fn update_world(&mut self, i: usize) {
        let (s, c) = self.theta[i].sin_cos();
        self.axis[i] = V2::new(c, s);
        let p = self.pos[i];
        self.world[i].set_transformed(self.shape[i].outline(), c, s, p);
        self.aabb[i] = Aabb::of(self.world[i].verts());
    }

    /// Velocity (m/s) of the material point at `p` (m) of body `i`, from the stored
    /// (half-step) velocities.
    #[inline]
    pub(crate) fn point_velocity(&self, i: usize, p: V2) -> V2 {
        self.vel[i] + (p - self.pos[i]).perp() * self.omega[i]
    }

    /// Inverse effective mass (m/kg per metre of depth, i.e. 1/(kg/m)) of body `i` for a
    /// force along the unit vector `n` at point `p` (m): 1/m + (r×n)²/I over the degrees
    /// of freedom that are free (a prescribed one has infinite mass).
    #[inline]
    pub(crate) fn inverse_mass_along(&self, i: usize, p: V2, n: V2) -> f64 {
        let d = self.drive[i];
        let m = self.mass[i];
        let mut k = 0.0;
        if d.u.is_none() {
            k += n.x * n.x / m;
        }
        if d.v.is_none() {
            k += n.y * n.y / m;
        }
        if d.omega.is_none() {
            let rn = (p - self.pos[i]).cross(n);
            k += rn * rn / self.inertia[i];
        }
        k
    }

    /// Acceleration (m/s²) of the material point at `p` (m) of body `i` under the force
    /// and moment accumulated so far, over its free degrees of freedom (a prescribed one
    /// does not accelerate); the centripetal term is left out.
    #[inline]
    pub(crate) fn point_acceleration(&self, i: usize, p: V2) -> V2 {
        let d = self.drive[i];
        let f = self.force[i];
        let m = self.mass[i];
        let ax = if d.u.is_none() { f.x / m } else { 0.0 };
        let ay = if d.v.is_none() { f.y / m } else { 0.0 };
        let alpha = if d.omega.is_none() {
            self.torque[i] / self.inertia[i]
        } else {
            0.0
        };
        V2::new(ax, ay) + (p - self.pos[i]).perp() * alpha
    }

    /// Inverse masses of body `i` for its three degrees of freedom (1/(kg/m) for x and y,
    /// 1/(kg·m²/m) for the rotation), zero for a prescribed one.
    #[inline]
    pub(crate) fn inverse_masses(&self, i: usize) -> [f64; 3] {
        let d = self.drive[i];
        let im = 1.0 / self.mass[i];
        [
            if d.u.is_none() { im } else { 0.0 },
            if d.v.is_none() { im } else { 0.0 },
            if d.omega.is_none() {
                1.0 / self.inertia[i]
            } else {
                0.0
            },
        ]
    }

    /// Acceleration of body `i` (m/s², m/s², rad/s²) under the force and moment
    /// accumulated so far, zero along a prescribed degree of freedom: force times the
    /// inverse masses the joint dashpot's solve also uses. [`Bodies::point_acceleration`]
    /// divides by the mass instead and is not built on this, which would change the default
    /// contact dashpot's last bits.
    #[inline]
    pub(crate) fn acceleration(&self, i: usize) -> [f64; 3] {
        let [ix, iy, iw] = self.inverse_masses(i);
        [
            self.force[i].x * ix,
            self.force[i].y * iy,
            self.torque[i] * iw,
        ]
    }

    /// Adds force `f` (N/m) acting at point `p` (m) to body `i`.
    #[inline]
    pub(crate) fn apply(&mut self, i: usize, f: V2, p: V2) {
        self.force[i] = self.force[i] + f;
        self.torque[i] += (p - self.pos[i]).cross(f);
    }

    /// Kinetic energy (J/m) of all bodies at the stored velocities.
    pub fn kinetic_energy(&self) -> f64 {
        let mut e = 0.0;
        for i in 0..self.len() {
            e += 0.5 * self.mass[i] * self.vel[i].dot(self.vel[i])
                + 0.5 * self.inertia[i] * self.omega[i] * self.omega[i];
        }
        e
    }
}
