//! Validation of a [`Scene`]: every bounded parameter against its range in
//! [`crate::limits`], the ice lighter than the water, the block geometry, the number of
//! blocks, and a run that takes at least one step. Messages name the parameter and its
//! valid range.

use super::*;

/// Checks scene parameter `key` against its range ([`limits`]).
fn check(range: Range, key: &str, value: f64) -> Result<(), SceneError> {
    match range.violation(value) {
        None => Ok(()),
        Some(why) => Err(SceneError::Invalid(key.into(), why)),
    }
}

/// Checks a bevel leg (m): 0 or at least [`limits::MIN_BEVEL`].
fn check_bevel(key: &str, leg: f64) -> Result<(), SceneError> {
    if leg == 0.0 || leg >= limits::MIN_BEVEL {
        Ok(())
    } else {
        Err(SceneError::Invalid(
            key.into(),
            format!(
                "makes a bevel leg of {leg:e} m: a bevel is 0 (none) or at least {} m, as a shorter one is a degenerate edge",
                limits::MIN_BEVEL
            ),
        ))
    }
}

/// Checks a bevel's slope (tan of its angle, dimensionless) against
/// [`limits::BEVEL_SLOPE`].
fn check_slope(key: &str, slope: f64) -> Result<(), SceneError> {
    check(limits::BEVEL_SLOPE, key, slope)
}

impl Scene {
    /// Checks the scene-level parameters (the world checks its own): each bounded parameter
    /// against its range in [`limits`], the ice lighter than the water, the block geometry,
    /// and the number of blocks. The message names the parameter and its valid range.
    pub fn validate(&self) -> Result<(), SceneError> {
        use limits::*;
        let bad = |k: &str, why: &str| Err(SceneError::Invalid(k.into(), why.into()));
        if !self.duration.is_finite() {
            return bad("duration", "must be a finite number of seconds");
        }
        check(DURATION, "duration", self.duration)?;
        check(ICE_DENSITY, "ice.density", self.ice.density)?;
        if self.water.enabled {
            check(WATER_DENSITY, "water.density", self.water.density)?;
            if self.ice.density >= self.water.density {
                return Err(SceneError::Invalid(
                    "ice.density".into(),
                    format!(
                        "{} kg/m³ is not below water.density = {} kg/m³: ice denser than water sinks",
                        self.ice.density, self.water.density
                    ),
                ));
            }
        }
        if self.numerics.time_step > 0.0 && self.numerics.time_step > self.duration {
            return Err(SceneError::Invalid(
                "numerics.time_step".into(),
                format!(
                    "{} s is longer than duration = {} s: the run would take no step",
                    self.numerics.time_step, self.duration
                ),
            ));
        }
        let mut blocks = 0.0f64;
        if !(self.numerics.sample_interval > 0.0 && self.numerics.sample_interval.is_finite()) {
            return bad("numerics.sample_interval", "must be positive (s)");
        }
        if !(self.numerics.time_step >= 0.0 && self.numerics.time_step.is_finite()) {
            return bad("numerics.time_step", "must be 0 (derived) or positive (s)");
        }
        if let Some(sh) = &self.sheet {
            blocks += sheet(sh)?;
        }
        if let Some(f) = &self.floe {
            blocks += floe(f)?;
        }
        if self.floe.is_some() && self.wall.is_some() {
            return bad("wall", "a scene has a floe or a wall, not both");
        }
        if let Some(w) = &self.wall
            && !(w.top > w.bottom && w.thickness > 0.0 && w.x.is_finite())
        {
            return bad("wall", "needs top > bottom and a positive thickness");
        }
        if !(self.joint.damping_fraction >= 0.0 && self.joint.damping_fraction.is_finite()) {
            return bad("joint.damping_fraction", "must be non-negative");
        }
        if !(self.joint.crack_speed > 0.0 && self.joint.crack_speed.is_finite()) {
            return bad("joint.crack_speed", "must be positive (m/s)");
        }
        if let Some(t) = self.joint.incubation_time
            && !(t > 0.0 && t.is_finite())
        {
            return bad("joint.incubation_time", "must be positive (s) when given");
        }
        if self.numerics.fracture_step_mean && self.joint.incubation_time.is_some() {
            return bad(
                "numerics.fracture_step_mean",
                "filters the tested stress as joint.incubation_time does: set one of them",
            );
        }
        if let Some(w) = self.numerics.refine_window
            && !(w >= 0.0 && w.is_finite())
        {
            return bad(
                "numerics.refine_window",
                "must be non-negative (s) when given",
            );
        }
        if let Some(f) = self.numerics.refine_load
            && !(f > 0.0 && f <= 1.0)
        {
            return bad(
                "numerics.refine_load",
                "must be in (0, 1] (a fraction of the joints' strength) when given",
            );
        }
        if let Some(v) = self.numerics.refine_impact {
            if !(v > 0.0 && v.is_finite()) {
                return bad(
                    "numerics.refine_impact",
                    "must be positive (m/s) when given",
                );
            }
            if self.numerics.refine_window.is_none() {
                return bad(
                    "numerics.refine_impact",
                    "refines for numerics.refine_window after an impact: set the window, or switch the impacts off (\"off\")",
                );
            }
        }
        if let Some(f) = self.numerics.refine_fraction {
            if !(f > 0.0 && f <= 1.0) {
                return bad("numerics.refine_fraction", "must be in (0, 1]");
            }
            if self.numerics.refine_window.is_none() && self.numerics.refine_load.is_none() {
                return bad(
                    "numerics.refine_fraction",
                    "refines the step only with numerics.refine_window or refine_load: set one (both are \"off\")",
                );
            }
        }
        if self.output.snapshot_interval.is_nan() || self.output.snapshot_interval < 0.0 {
            return bad("output.snapshot_interval", "must be non-negative (s)");
        }
        let f = self.output.frame;
        if !(f[1] > f[0] && f[3] > f[2]) {
            return bad(
                "output.frame",
                "must be [x0, x1, y0, y1] with x1 > x0 and y1 > y0",
            );
        }
        if let Some(p) = &self.pile {
            blocks += pile(p)?;
        }
        if blocks > MAX_BLOCKS as f64 {
            return Err(SceneError::Invalid(
                "sheet.length, floe.length, pile.blocks".into(),
                format!(
                    "the scene would start with {blocks} blocks (sheet.length / sheet.block_width + floe.length / floe.block_width + pile.blocks); at most {MAX_BLOCKS} are allowed, as memory and contact search grow with them"
                ),
            ));
        }
        Ok(())
    }

    /// Checks that a run of this scene with time step `dt` (s), e.g. the stable step its
    /// world derived, takes at least one step: `dt` must be positive, finite and no longer
    /// than the duration. [`crate::simulation::run`] calls it, so every face (command line,
    /// scene file, Python, C) refuses such a run before it starts.
    pub fn check_run_length(&self, dt: f64) -> Result<(), SceneError> {
        if !(dt > 0.0 && dt.is_finite()) {
            return Err(SceneError::Invalid(
                "numerics.time_step".into(),
                format!(
                    "the time step is {dt} s: the scene has nothing that sets a stable step (no free blocks?); set numerics.time_step to a positive value below duration = {} s",
                    self.duration
                ),
            ));
        }
        if dt > self.duration {
            return Err(SceneError::Invalid(
                "duration".into(),
                format!(
                    "{} s is shorter than the time step {dt:.3e} s: the run would take no step; use a longer duration",
                    self.duration
                ),
            ));
        }
        Ok(())
    }
}

/// Checks the sheet's parameters; returns the number of blocks it starts with.
fn sheet(sh: &SheetSection) -> Result<f64, SceneError> {
    use limits::*;
    let bad = |k: &str, why: &str| Err(SceneError::Invalid(k.into(), why.into()));
    let mut blocks = 0.0f64;
    for (k, v) in [
        ("sheet.thickness", sh.thickness),
        ("sheet.block_width", sh.block_width),
        ("sheet.length", sh.length),
        ("sheet.speed", sh.speed),
        ("sheet.e_top", sh.e_top),
        ("sheet.e_bottom", sh.e_bottom),
        ("sheet.strength_top", sh.strength_top),
        ("sheet.strength_bottom", sh.strength_bottom),
    ] {
        if !(v > 0.0 && v.is_finite()) {
            return bad(k, "must be positive");
        }
    }
    check(THICKNESS, "sheet.thickness", sh.thickness)?;
    check(BLOCK_WIDTH, "sheet.block_width", sh.block_width)?;
    check(LENGTH, "sheet.length", sh.length)?;
    check(SPEED, "sheet.speed", sh.speed)?;
    check(YOUNGS_MODULUS, "sheet.e_top", sh.e_top)?;
    check(YOUNGS_MODULUS, "sheet.e_bottom", sh.e_bottom)?;
    check(TENSILE_STRENGTH, "sheet.strength_top", sh.strength_top)?;
    check(
        TENSILE_STRENGTH,
        "sheet.strength_bottom",
        sh.strength_bottom,
    )?;
    blocks += (sh.length / sh.block_width).round().max(2.0);
    for (k, v) in [
        ("sheet.skeletal_fraction", sh.skeletal_fraction),
        ("sheet.skeletal_max", sh.skeletal_max),
        ("sheet.modulus_variation", sh.modulus_variation),
        ("sheet.tip_bevel_fraction", sh.tip_bevel_fraction),
        ("sheet.corner_bevel", sh.corner_bevel),
        ("sheet.viscous_decay", sh.viscous_decay),
        ("sheet.gap", sh.gap),
        (
            "sheet.boundary_damping_fraction",
            sh.boundary_damping_fraction,
        ),
    ] {
        if !(v >= 0.0 && v.is_finite()) {
            return bad(k, "must be non-negative");
        }
    }
    if !(0.0..0.5).contains(&sh.poisson) {
        return bad("sheet.poisson", "must lie in [0, 0.5)");
    }
    if let Some(l) = sh.viscous_length
        && !(l > 0.0 && l.is_finite())
    {
        return bad("sheet.viscous_length", "must be a positive length (m)");
    }
    if sh.skeletal() >= sh.thickness {
        return bad("sheet.skeletal_fraction", "leaves no joint");
    }
    for (k, v) in [
        ("sheet.tip_bevel_fraction", sh.tip_bevel()),
        ("sheet.corner_bevel", sh.corner_bevel),
    ] {
        check_bevel(k, v)?;
    }
    if sh.tip_bevel_fraction >= 1.0 {
        return bad(
            "sheet.tip_bevel_fraction",
            "must be below 1: the bevel under the tip is a fraction of the thickness",
        );
    }
    check_slope("sheet.tip_bevel_slope", sh.tip_bevel_slope)?;
    if let Some(run) = sh.tip_bevel_run()
        && run >= sh.block_width
    {
        return Err(SceneError::Invalid(
            "sheet.tip_bevel_slope".into(),
            format!(
                "{} makes the bevel under the tip run {run:.3} m along the sheet's bottom, not shorter than sheet.block_width = {} m: use a steeper slope or a smaller sheet.tip_bevel_fraction",
                sh.tip_bevel_slope, sh.block_width
            ),
        ));
    }
    if sh.tip_bevel() >= sh.block_width {
        // The bevel leg scales with the thickness: a thick sheet needs wide blocks.
        return Err(SceneError::Invalid(
            "sheet.block_width".into(),
            format!(
                "{} m is not wider than the bevel under the sheet tip, tip_bevel_fraction × thickness = {} × {} m = {:.3} m: use blocks wider than that (the paper uses about the thickness) or a smaller sheet.tip_bevel_fraction",
                sh.block_width,
                sh.tip_bevel_fraction,
                sh.thickness,
                sh.tip_bevel()
            ),
        ));
    }
    let side = sh.block_width.min(sh.thickness);
    if 2.0 * sh.corner_bevel >= side {
        return Err(SceneError::Invalid(
            "sheet.corner_bevel".into(),
            format!(
                "{} m must be shorter than half the sheet block's smaller side, min(sheet.block_width, sheet.thickness) / 2 = {} m",
                sh.corner_bevel,
                0.5 * side
            ),
        ));
    }
    if sh.modulus_variation >= 1.0 {
        return bad("sheet.modulus_variation", "must be below 1");
    }
    if sh.length < 2.0 * sh.block_width {
        return bad("sheet.length", "must hold at least two blocks");
    }
    Ok(blocks)
}

/// Checks the floe's parameters and its nose ramp; returns the number of blocks it starts
/// with.
fn floe(f: &FloeSection) -> Result<f64, SceneError> {
    use limits::*;
    let bad = |k: &str, why: &str| Err(SceneError::Invalid(k.into(), why.into()));
    let mut blocks = 0.0f64;
    for (k, v) in [
        ("floe.thickness", f.thickness),
        ("floe.length", f.length),
        ("floe.block_width", f.block_width),
        ("floe.e_top", f.e_top),
        ("floe.e_bottom", f.e_bottom),
        ("floe.strength_top", f.strength_top),
        ("floe.strength_bottom", f.strength_bottom),
    ] {
        if !(v > 0.0 && v.is_finite()) {
            return bad(k, "must be positive");
        }
    }
    check(THICKNESS, "floe.thickness", f.thickness)?;
    check(BLOCK_WIDTH, "floe.block_width", f.block_width)?;
    check(LENGTH, "floe.length", f.length)?;
    check(YOUNGS_MODULUS, "floe.e_top", f.e_top)?;
    check(YOUNGS_MODULUS, "floe.e_bottom", f.e_bottom)?;
    check(TENSILE_STRENGTH, "floe.strength_top", f.strength_top)?;
    check(TENSILE_STRENGTH, "floe.strength_bottom", f.strength_bottom)?;
    blocks += f.block_count() as f64;
    for (k, v) in [
        ("floe.support_stiffness", f.support_stiffness),
        ("floe.support_damping_fraction", f.support_damping_fraction),
        ("floe.nose_bevel", f.nose_bevel),
        ("floe.corner_bevel", f.corner_bevel),
    ] {
        if !(v >= 0.0 && v.is_finite()) {
            return bad(k, "must be non-negative");
        }
    }
    if !(0.0..0.5).contains(&f.poisson) {
        return bad("floe.poisson", "must lie in [0, 0.5)");
    }
    check_bevel("floe.nose_bevel", f.nose_bevel)?;
    check_bevel("floe.corner_bevel", f.corner_bevel)?;
    check_slope("floe.nose_slope", f.nose_slope)?;
    let side = f.block_width.min(f.thickness);
    // At 45° the nose block is one block wide; at another slope it is as wide as its
    // run needs and only the floe's thickness bounds the drop.
    let nose_side = if f.nose_slope == 1.0 {
        side
    } else {
        f.thickness
    };
    if f.nose_bevel >= nose_side {
        return Err(SceneError::Invalid(
            "floe.nose_bevel".into(),
            format!(
                "{} m must be shorter than {}",
                f.nose_bevel,
                if f.nose_slope == 1.0 {
                    format!(
                        "the floe block's smaller side, min(floe.block_width, floe.thickness) = {side} m"
                    )
                } else {
                    format!("floe.thickness = {} m", f.thickness)
                }
            ),
        ));
    }
    if 2.0 * f.corner_bevel >= side {
        return Err(SceneError::Invalid(
            "floe.corner_bevel".into(),
            format!(
                "{} m must be shorter than half the floe block's smaller side, min(floe.block_width, floe.thickness) / 2 = {} m",
                f.corner_bevel,
                0.5 * side
            ),
        ));
    }
    let held = f.block_count();
    if f.nose_block_widths() > held {
        return bad(
            "floe.length",
            &format!(
                "{} m holds {held} floe block(s) of floe.block_width = {} m, fewer than \
                 the {} the nose block needs for its ramp's run of {:.2} m \
                 (floe.nose_bevel / floe.nose_slope)",
                f.length,
                f.block_width,
                f.nose_block_widths(),
                f.nose_run()
            ),
        );
    }
    Ok(blocks)
}

/// Checks the rubble pile's parameters; returns the number of blocks it starts with.
fn pile(p: &PileSection) -> Result<f64, SceneError> {
    use limits::*;
    let bad = |k: &str, why: &str| Err(SceneError::Invalid(k.into(), why.into()));
    let mut blocks = 0.0f64;
    if p.columns == 0 {
        return bad("pile.columns", "must be at least 1");
    }
    for (k, v) in [
        ("pile.width", p.width),
        ("pile.thickness", p.thickness),
        ("pile.basin_width", p.basin_width),
    ] {
        if !(v > 0.0 && v.is_finite()) {
            return bad(k, "must be positive (m)");
        }
    }
    for (k, v) in [
        ("pile.gap", p.gap),
        ("pile.jitter", p.jitter),
        ("pile.tilt", p.tilt),
    ] {
        if !(v >= 0.0 && v.is_finite()) {
            return bad(k, "must be non-negative");
        }
    }
    if !p.base.is_finite() {
        return bad("pile.base", "must be finite (m)");
    }
    check(THICKNESS, "pile.thickness", p.thickness)?;
    check(BLOCK_WIDTH, "pile.width", p.width)?;
    if p.blocks > MAX_BLOCKS {
        return Err(SceneError::Invalid(
            "pile.blocks".into(),
            format!(
                "{} is out of range: must lie in [0, {MAX_BLOCKS}] (memory and contact search grow with the number of blocks)",
                p.blocks
            ),
        ));
    }
    blocks += p.blocks as f64;
    let need = p.columns as f64 * (p.width + p.gap) + p.gap;
    if p.walls && need > p.basin_width {
        return bad(
            "pile.basin_width",
            "is narrower than the columns of the initial stack",
        );
    }
    Ok(blocks)
}
