//! What follows a fracture in a [`World`]: the broken faces bevelled, what broke off the
//! sheet turned into rubble with its overlaps handed over to contacts, and the sheet grown
//! at its driven end so that it keeps its length (Hopkins 1994, "Boundary Conditions on the
//! Sheet and Floe").

use super::*;

impl World {
    /// Handles joints severed in the last step: bevels the corners of the broken faces,
    /// turns what broke off the sheet into rubble, and grows the sheet at its left end.
    pub(super) fn after_fracture(&mut self) {
        // Outlines at the new positions, once: the hand-overs below test overlaps, and
        // reshaping or adding a body keeps its own outline current.
        for i in 0..self.bodies.len() {
            self.bodies.update_world(i);
        }
        let severed: Vec<usize> = self.joints.severed().to_vec();
        for k in severed {
            self.blocks_broken += 1;
            let j = self.joints.joints()[k];
            let (a, b) = (j.a as usize, j.b as usize);
            let mut on_sheet = None;
            if let Some(sh) = &self.boundary.sheet
                && self.bodies.role[a] == Role::Sheet
                && self.bodies.role[b] == Role::Sheet
            {
                on_sheet = sh.blocks.iter().position(|&x| x == j.a);
            }
            let (corner, tip, tip_run) = if let Some(sh) = &self.boundary.sheet {
                (
                    sh.corner_bevel,
                    sh.tip_bevel,
                    sh.tip_bevel_run.unwrap_or(sh.tip_bevel),
                )
            } else if let Some(fl) = &self.boundary.floe {
                (fl.corner_bevel, 0.0, 0.0)
            } else {
                (0.0, 0.0, 0.0)
            };
            match on_sheet {
                Some(pos) => {
                    // The new sheet tip gets the tip bevel underneath (point B); the piece
                    // that broke off becomes rubble with bevelled corners.
                    self.bevel_legs(
                        a,
                        [0.0, tip.max(corner), corner, 0.0],
                        [0.0, tip_run.max(corner), corner, 0.0],
                    );
                    self.bevel(b, [corner, 0.0, 0.0, corner]);
                    let sh = self.boundary.sheet.as_mut().expect("sheet present");
                    let lost: Vec<BodyId> = sh.blocks.drain(pos + 1..).collect();
                    for &id in &lost {
                        self.bodies.role[id as usize] = Role::Rubble;
                    }
                    for _ in 0..lost.len() {
                        self.grow_sheet();
                    }
                }
                None => {
                    self.bevel(a, [0.0, corner, corner, 0.0]);
                    self.bevel(b, [corner, 0.0, 0.0, corner]);
                }
            }
            // Blocks that were joined may overlap (joined blocks are exempt from contact):
            // their contact is born with that overlap forgiven, see `contact`.
            self.hand_over(a, b);
        }
    }

    /// Hands the overlap of bodies `a` and `b` (outlines current), if any, to a contact
    /// born with that overlap forgiven (see [`crate::dem::contact`]), and counts it.
    fn hand_over(&mut self, a: usize, b: usize) {
        let (lo, hi) = (a.min(b), a.max(b));
        let bd = &self.bodies;
        if let Some(ov) = overlap(&bd.world[lo], &bd.world[hi], bd.pos[lo], bd.pos[hi]) {
            self.contacts.hand_over(
                pair_key(lo as u32, hi as u32),
                ov.area,
                ov.centroid,
                ov.normal,
            );
            self.handovers.count += 1;
            self.handovers.max_area = self.handovers.max_area.max(ov.area);
        }
    }

    /// Raises the 45° bevel legs of block `i` to at least `legs` (m), re-cutting its shape.
    fn bevel(&mut self, i: usize, legs: [f64; 4]) {
        self.bevel_legs(i, legs, legs);
    }

    /// Raises the bevels of block `i` to at least the drops `drop` and runs `run` (m),
    /// re-cutting its shape.
    fn bevel_legs(&mut self, i: usize, drop: [f64; 4], run: [f64; 4]) {
        let Some(old) = self.bodies.block[i] else {
            return;
        };
        let mut new = old;
        let mut runs = old.runs();
        for k in 0..4 {
            new.bevel[k] = new.bevel[k].max(drop[k]);
            runs[k] = runs[k].max(run[k]);
        }
        new.bevel_run = (runs != new.bevel).then_some(runs);
        if new == old {
            return;
        }
        let Ok(shape) = new.shape() else {
            // A block too small for the bevel keeps its corners.
            return;
        };
        let shift = old.rect_centre() - new.rect_centre();
        let dke = self
            .bodies
            .reshape(i, shape, shift, self.params.ice_density);
        self.acc.cut_away -= dke;
        self.bodies.block[i] = Some(new);
        for j in self.joints.joints_mut() {
            if j.a as usize == i {
                j.pa = j.pa - shift;
            }
            if j.b as usize == i {
                j.pb = j.pb - shift;
            }
        }
    }

    /// Adds a block at the left end of the sheet, joined to the current leftmost block, and
    /// hands it the drive. Its kinetic energy enters the ledger as inflow, not work.
    fn grow_sheet(&mut self) {
        let Some(sh) = self.boundary.sheet.as_ref() else {
            return;
        };
        let first = sh.blocks[0] as usize;
        let (w, h, u, clamp) = (sh.width, sh.thickness, sh.speed, sh.clamp);
        let k = sh.joints_made;
        let mut mat = sh.material;
        let f = sh.modulus_factor(k);
        mat.e_top *= f;
        mat.e_bottom *= f;
        let skeletal = sh.skeletal;
        let b = &self.bodies;
        let th = b.theta[first];
        let (s, c) = th.sin_cos();
        let rect_first = b.pos[first]
            + b.block[first]
                .map_or(V2::default(), |x| x.rect_centre())
                .rotate(c, s);
        let centre = rect_first - V2::new(w, 0.0).rotate(c, s);
        let v = b.vel[first] + (centre - b.pos[first]).perp() * b.omega[first];
        let omega = b.omega[first];
        let block = Block {
            width: w,
            thickness: h,
            bevel: [0.0; 4],
            bevel_run: None,
        };
        let drive = Drive {
            u: Some(u),
            v: clamp.then_some(0.0),
            omega: clamp.then_some(0.0),
        };
        let Ok(id) = self.add_rect(block, centre, th, drive, Role::Sheet) else {
            return;
        };
        // The new block's kinetic energy is inflow, not work.
        let ke0 = self.body_kinetic_energy(id as usize);
        let (vy, om) = if clamp { (0.0, 0.0) } else { (v.y, omega) };
        self.bodies.vel[id as usize] = V2::new(u, vy);
        self.bodies.omega[id as usize] = om;
        self.acc.kinetic_start += self.body_kinetic_energy(id as usize) - ke0;
        self.bodies.drive[first] = Drive::FREE;
        let _ = self.join(id, first as BodyId, skeletal, mat);
        let sh = self.boundary.sheet.as_mut().expect("sheet present");
        sh.joints_made += 1;
        sh.blocks.insert(0, id);
        // A block grown where rubble already lies (a sheet that rafted far enough for its
        // driven end to reach the ridge) starts with its overlaps forgiven, see `contact`.
        // Outlines are current here (see `after_fracture`).
        let id = id as usize;
        for i in 0..self.bodies.len() {
            if i == id || i == first {
                continue;
            }
            if self.bodies.aabb[i].overlaps(&self.bodies.aabb[id]) {
                self.hand_over(i, id);
            }
        }
    }
}
