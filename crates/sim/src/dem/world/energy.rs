//! What a world's state is worth: its energy budget (eqs (10)–(12)), its potential energy
//! and the ridging force of eq (9).

use super::*;

impl World {
    /// The energy budget now (J/m).
    pub fn energy(&self) -> EnergyBudget {
        let (sn, st) = self.contacts.stored_energy();
        let stored = Stored {
            contact_normal: sn,
            contact_tangential: st,
        };
        budget(self.time, &self.acc, self.bodies.kinetic_energy(), &stored)
    }

    /// The ridging force of eq (9) (N/m): minus the x component of the contact forces
    /// that bodies of other roles exert on the sheet, i.e. the resistance the sheet pushes
    /// against (positive when the ridge resists the push).
    pub fn ridging_force(&self) -> f64 {
        let r = &self.bodies.role;
        let mut fx = 0.0;
        for c in self.contacts.contacts() {
            let (a, b) = ((c.key >> 32) as usize, (c.key & 0xffff_ffff) as usize);
            let (sa, sb) = (r[a] == Role::Sheet, r[b] == Role::Sheet);
            if sa == sb {
                continue;
            }
            let f = c.normal * (c.fn_elastic + c.fn_viscous) + c.normal.perp() * c.ft;
            fx += if sb { f.x } else { -f.x };
        }
        -fx
    }

    /// Potential energy of the current state (J/m): Σ ρ_i·g·A·y_c − ρ_w·g·A_s·y_s over the
    /// bodies that are not held, with y_s the depth of the submerged centroid (the work to
    /// lift each block and to displace its water). Its change between two instants equals
    /// the ΔPE booked by eq (10) up to the discretisation error of the step.
    pub fn potential_energy(&self) -> f64 {
        let b = &self.bodies;
        let g = self.params.gravity;
        let mut pe = 0.0;
        for i in 0..b.len() {
            if b.drive[i].is_kinematic() {
                continue;
            }
            pe += b.mass[i] * g * b.pos[i].y;
            if let Some(w) = &self.params.water {
                let (s, c) = b.theta[i].sin_cos();
                let mut o = super::super::geometry::Outline::default();
                o.set_transformed(b.shape[i].outline(), c, s, b.pos[i]);
                let (a, cen) = below_line(&o, w.level);
                pe -= w.density * g * a * (cen.y - w.level);
            }
        }
        pe
    }
}
