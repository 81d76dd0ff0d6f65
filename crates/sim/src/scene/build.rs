//! From a [`Scene`] to a [`World`]: the world parameters, the pushed sheet and its joints,
//! the floe on its supports (Hopkins 1994, Figure 1 and "Boundary Conditions on the Sheet and
//! Floe"), a wall, or a rubble pile.

use super::*;

impl Scene {
    /// The world parameters of this scene.
    pub(crate) fn world_params(&self) -> WorldParams {
        let mut contact = self.contact.clone();
        if contact.reference_thickness.is_none()
            && let Some(sh) = &self.sheet
        {
            contact.reference_thickness = Some(sh.thickness);
        }
        WorldParams {
            gravity: self.ice.gravity,
            ice_density: self.ice.density,
            contact,
            crack_speed: self.joint.crack_speed,
            incubation_time: self.joint.incubation_time,
            fracture_step_mean: self.numerics.fracture_step_mean,
            refine_window: self.numerics.refine_window,
            refine_load: self.numerics.refine_load,
            refine_impact: self.numerics.refine_impact,
            refine_fraction: self.numerics.refine_fraction,
            water: self.water.enabled.then_some(WaterParams {
                level: self.water.level,
                density: self.water.density,
                drag_coefficient: self.water.drag_coefficient,
                linear_drag: self.water.linear_drag,
                drag_bodies: self.water.drag_bodies,
                shielding_contacts: self.water.shielding_contacts,
            }),
            time_step_safety: self.numerics.time_step_safety,
            time_step: (self.numerics.time_step > 0.0).then_some(self.numerics.time_step),
            contact_dashpot: self.numerics.contact_dashpot,
            joint_dashpot: self.numerics.joint_dashpot,
            contact_onset: self.numerics.contact_onset,
            contact_dashpot_sweeps: self.numerics.contact_dashpot_sweeps,
            ..WorldParams::default()
        }
    }

    /// Builds the world at time zero.
    pub fn build(&self) -> Result<World, SceneError> {
        self.validate()?;
        let mut world = World::new(self.world_params())?;
        // Δt is derived once, from the complete world (not after every block and joint).
        world.defer_time_step();
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(self.seed);
        let level = self.water.level;
        if let Some(p) = &self.pile {
            build_pile(&mut world, p, level, &mut rng)?;
        }
        if let Some(f) = &self.floe {
            self.build_floe(&mut world, f)?;
        }
        if let Some(w) = &self.wall {
            let shape = Shape::rectangle(w.thickness, w.top - w.bottom)
                .map_err(|e| SceneError::Invalid("wall".into(), e.to_string()))?;
            let id = world.add_block(
                shape,
                V2::new(w.x + 0.5 * w.thickness, 0.5 * (w.top + w.bottom)),
                0.0,
                Drive::FIXED,
            );
            world.bodies.role[id as usize] = Role::Wall;
        }
        if let Some(sh) = &self.sheet {
            self.build_sheet(&mut world, sh)?;
        }
        world.finish_time_step()?;
        Ok(world)
    }

    /// Height of the centre of a floating slab of thickness `h` (m) at rest.
    fn floating_centre(&self, h: f64) -> f64 {
        let level = self.water.level;
        if self.water.enabled {
            level + 0.5 * h - h * self.ice.density / self.water.density
        } else {
            level + 0.5 * h
        }
    }

    fn build_sheet(&self, world: &mut World, sh: &SheetSection) -> Result<(), SceneError> {
        let n = (sh.length / sh.block_width).round().max(2.0) as usize;
        let yc = self.floating_centre(sh.thickness);
        let mat = JointMaterial {
            e_top: sh.e_top,
            e_bottom: sh.e_bottom,
            poisson: sh.poisson,
            damping_fraction: self.joint.damping_fraction,
            strength_top: sh.strength_top,
            strength_bottom: sh.strength_bottom,
        };
        let front = self
            .floe
            .as_ref()
            .map(|_| 0.0)
            .or(self.wall.as_ref().map(|w| w.x))
            .unwrap_or(0.0)
            - sh.gap;
        let mut boundary = SheetBoundary {
            speed: sh.speed,
            clamp: sh.clamp_driven_end,
            width: sh.block_width,
            thickness: sh.thickness,
            skeletal: sh.skeletal(),
            material: mat,
            modulus_variation: sh.modulus_variation,
            seed: self.seed,
            joints_made: 0,
            tip_bevel: sh.tip_bevel(),
            tip_bevel_run: sh.tip_bevel_run(),
            corner_bevel: sh.corner_bevel,
            decay: sh.viscous_decay,
            viscosity: sh.boundary_viscosity(&self.contact, self.ice.density),
            blocks: Vec::with_capacity(n),
        };
        for k in 0..n {
            let tip = k + 1 == n;
            let bevel = if tip {
                [0.0, sh.tip_bevel(), 0.0, 0.0]
            } else {
                [0.0; 4]
            };
            let block = Block {
                width: sh.block_width,
                thickness: sh.thickness,
                bevel,
                bevel_run: sh
                    .tip_bevel_run()
                    .filter(|_| tip)
                    .map(|r| [0.0, r, 0.0, 0.0]),
            };
            let drive = if k == 0 { sh.drive() } else { Drive::FREE };
            let x = front - (n - k) as f64 * sh.block_width + 0.5 * sh.block_width;
            let id = world.add_rect(block, V2::new(x, yc), 0.0, drive, Role::Sheet)?;
            if let Some(&prev) = boundary.blocks.last() {
                let f = boundary.modulus_factor(boundary.joints_made);
                let m = JointMaterial {
                    e_top: mat.e_top * f,
                    e_bottom: mat.e_bottom * f,
                    ..mat
                };
                world.join(prev, id, sh.skeletal(), m)?;
                boundary.joints_made += 1;
            }
            boundary.blocks.push(id);
        }
        world.boundary.sheet = Some(boundary);
        Ok(())
    }

    fn build_floe(&self, world: &mut World, f: &FloeSection) -> Result<(), SceneError> {
        // The nose block is as many block widths wide as the ramp's run (and a corner bevel
        // either side) needs; one width at 45°.
        let nose_run = f.nose_run();
        let widths = f.nose_block_widths();
        let n = f.block_count().max(widths) + 1 - widths;
        let yc = self.floating_centre(f.thickness);
        let skeletal = f.thickness.min(0.3) * 0.2;
        let skeletal = skeletal.min(0.06);
        let mat = JointMaterial {
            e_top: f.e_top,
            e_bottom: f.e_bottom,
            poisson: f.poisson,
            damping_fraction: self.joint.damping_fraction,
            strength_top: f.strength_top,
            strength_bottom: f.strength_bottom,
        };
        let g = self.ice.gravity;
        let rho_w = if self.water.enabled {
            self.water.density
        } else {
            0.0
        };
        let mut support = FloeSupport {
            blocks: Vec::with_capacity(n),
            stiffness: Vec::with_capacity(n),
            damping: Vec::with_capacity(n),
            corner_bevel: f.corner_bevel,
        };
        let mut prev = None;
        let mut left = 0.0;
        for k in 0..n {
            let bevel = if k == 0 {
                [0.0, 0.0, 0.0, f.nose_bevel]
            } else {
                [0.0; 4]
            };
            let width = if k == 0 {
                widths as f64 * f.block_width
            } else {
                f.block_width
            };
            let block = Block {
                width,
                thickness: f.thickness,
                bevel,
                bevel_run: (k == 0 && nose_run != f.nose_bevel)
                    .then_some([0.0, 0.0, 0.0, nose_run]),
            };
            let drive = if f.pin && k + 1 == n {
                Drive {
                    u: Some(0.0),
                    v: Some(0.0),
                    omega: None,
                }
            } else {
                Drive::FREE
            };
            let x = if widths == 1 {
                (k as f64 + 0.5) * f.block_width
            } else {
                left + 0.5 * width
            };
            left += width;
            let id = world.add_rect(block, V2::new(x, yc), 0.0, drive, Role::Floe)?;
            if let Some(p) = prev {
                world.join(p, id, skeletal, mat)?;
            }
            prev = Some(id);
            let i = id as usize;
            let k_s = f.support_stiffness * width;
            let m = world.bodies.mass[i];
            let k_total = k_s + rho_w * g * width;
            support.blocks.push((id, world.bodies.pos[i].y));
            support.stiffness.push(k_s);
            support
                .damping
                .push(f.support_damping_fraction * 2.0 * (k_total * m).sqrt());
        }
        world.boundary.floe = Some(support);
        Ok(())
    }
}

/// A uniform random number in [−1, 1).
fn symmetric(rng: &mut Xoshiro256PlusPlus) -> f64 {
    (rng.next_u64() >> 11) as f64 * (2.0 / (1u64 << 53) as f64) - 1.0
}

fn build_pile(
    world: &mut World,
    p: &PileSection,
    level: f64,
    rng: &mut Xoshiro256PlusPlus,
) -> Result<(), SceneError> {
    let shape = Shape::rectangle(p.width, p.thickness)
        .map_err(|e| SceneError::Invalid("pile".into(), e.to_string()))?;
    let pitch_x = p.width + p.gap;
    let pitch_y = p.thickness + p.gap;
    let x0 = -0.5 * (p.columns as f64 * pitch_x - p.gap) + 0.5 * p.width;
    for k in 0..p.blocks {
        let (row, col) = (k / p.columns, k % p.columns);
        let x = x0 + col as f64 * pitch_x + p.jitter.min(0.45 * p.gap) * symmetric(rng);
        let y = level + p.base + 0.5 * p.thickness + row as f64 * pitch_y;
        let tilt = p.tilt * symmetric(rng);
        world.add_block(shape, V2::new(x, y), tilt, Drive::FREE);
    }
    if p.walls {
        let rows = p.blocks.div_ceil(p.columns) as f64;
        let top = level + p.base + rows * pitch_y + 1.0;
        let bottom = level - 2.0 * rows * p.thickness - 2.0;
        let t = 0.5;
        let wall = Shape::rectangle(t, top - bottom)
            .map_err(|e| SceneError::Invalid("pile walls".into(), e.to_string()))?;
        let yc = 0.5 * (top + bottom);
        let xw = 0.5 * p.basin_width + 0.5 * t;
        world.add_block(wall, V2::new(-xw, yc), 0.0, Drive::FIXED);
        world.add_block(wall, V2::new(xw, yc), 0.0, Drive::FIXED);
    }
    Ok(())
}
