//! Piecewise-linear interpolation, every routine of pressridge: on a strictly increasing axis
//! ([`bracket`], [`lerp`]), the one rule behind every table lookup: the C_f table of the
//! strength routine ([`crate::details::CfTable`]) and the simulator's ridging lookup table
//! (`pressridge::table::lookup::RidgeLookup`); and [`resample`], a run's samples onto the
//! table's volume grid (`pressridge::table::tabulate`).
//!
//! Written here rather than taken from a crate (ndarray-interp and the like) because the
//! lookups need two things such crates do not offer: the clamp flag, so that a value held at
//! the nearest end is counted and reported rather than extrapolated silently, and reading
//! the far neighbour only when its weight is non-zero, so that a missing (NaN) cell beyond
//! a node does not leak into the value at that node.

/// Checks that an axis is finite and strictly increasing; the message names the axis and
/// the first bad index.
pub fn check_axis(name: &str, xs: &[f64]) -> Result<(), String> {
    for (i, &x) in xs.iter().enumerate() {
        if !x.is_finite() {
            return Err(format!("{name}[{i}] = {x} is not finite"));
        }
        if i > 0 && x <= xs[i - 1] {
            return Err(format!(
                "{name} is not strictly increasing at index {i} ({} then {x})",
                xs[i - 1]
            ));
        }
    }
    Ok(())
}

/// Where `x` falls on the axis `xs` (non-empty, strictly increasing): the index `i` and the
/// weight `w` such that the value is `y[i]·(1 − w) + y[i + 1]·w` (w = 0 uses `y[i]` alone), and
/// whether `x` was outside the axis and clamped to its nearest end.
pub fn bracket(xs: &[f64], x: f64) -> (usize, f64, bool) {
    let last = xs.len() - 1;
    if x <= xs[0] {
        return (0, 0.0, x < xs[0]);
    }
    if x >= xs[last] {
        return (last, 0.0, x > xs[last]);
    }
    let i = xs.partition_point(|&v| v <= x) - 1;
    (i, (x - xs[i]) / (xs[i + 1] - xs[i]), false)
}

/// `a + w·(b − a)`, reading `b` only when its weight is non-zero (so a NaN beyond the
/// bracket does not leak in at a node).
pub fn lerp(a: f64, b: impl FnOnce() -> f64, w: f64) -> f64 {
    if w == 0.0 { a } else { a + w * (b() - a) }
}

/// Linear interpolation of `ys(xs)` at `x` within `[xs[0], xs[last]]`, else NaN: one run's
/// samples resampled onto the table's volume grid. Not [`bracket`] and [`lerp`]'s rule on purpose:
/// a run's samples may repeat a volume (a sheet at rest) and a volume beyond them is missing,
/// not clamped; and its operation order, (y₁ − y₀)·(x − x₀)/(x₁ − x₀), is kept so that
/// tables made before stay bit-identical.
pub fn resample(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    if xs.is_empty() || x < xs[0] || x > xs[xs.len() - 1] {
        return f64::NAN;
    }
    let k = xs.partition_point(|&v| v < x);
    if k == 0 {
        return ys[0];
    }
    let (x0, x1) = (xs[k - 1], xs[k]);
    if x1 == x0 {
        return ys[k];
    }
    ys[k - 1] + (ys[k] - ys[k - 1]) * (x - x0) / (x1 - x0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brackets_clamps_and_leaves_missing_neighbours_out() {
        let xs = [0.0, 1.0, 3.0];
        assert_eq!(bracket(&xs, -1.0), (0, 0.0, true));
        assert_eq!(bracket(&xs, 0.0), (0, 0.0, false));
        assert_eq!(bracket(&xs, 2.0), (1, 0.5, false));
        assert_eq!(bracket(&xs, 3.0), (2, 0.0, false));
        assert_eq!(bracket(&xs, 4.0), (2, 0.0, true));
        assert_eq!(lerp(2.0, || f64::NAN, 0.0), 2.0);
        assert_eq!(lerp(2.0, || 4.0, 0.25), 2.5);
        assert!(
            check_axis("h", &[0.1, 0.1])
                .unwrap_err()
                .contains("h is not strictly")
        );
        assert!(
            check_axis("h", &[f64::NAN])
                .unwrap_err()
                .contains("h[0] = NaN")
        );
    }

    #[test]
    fn resample_inside_and_outside() {
        let xs = [0.0, 1.0, 3.0];
        let ys = [0.0, 2.0, 6.0];
        assert_eq!(resample(&xs, &ys, 2.0), 4.0);
        assert_eq!(resample(&xs, &ys, 0.0), 0.0);
        assert_eq!(resample(&xs, &ys, 3.0), 6.0);
        assert!(resample(&xs, &ys, 3.5).is_nan());
    }
}
