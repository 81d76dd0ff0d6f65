//! What `ridge-step` was told, for the step and for the record: the parameter overrides of
//! --param-file and --param, and the global attributes common to both steps.

use pressridge::itd::{ItdParams, RidgeOptions, RidgeStepParams};

use super::Args;
use crate::BoxError;

/// The parameters of --param-file and --param.
pub(super) struct AllParams {
    /// Ridging parameters.
    pub(super) itd: ItdParams,
    /// Thermodynamic constants of the complete step (salt flux set later).
    pub(super) step: RidgeStepParams,
    /// Names of the step constants overridden (they need the complete step).
    pub(super) step_overrides: Vec<String>,
    /// The overrides as given, for the `parameter_overrides` attribute.
    pub(super) described: String,
}

/// Reads --param-file, then --param (which wins): each NAME=VALUE names an `ItdParams` or a
/// `RidgeStepParams` constant.
pub(super) fn parse_all_params(args: &Args) -> Result<AllParams, BoxError> {
    let mut items: Vec<(String, String)> = Vec::new();
    if let Some(path) = &args.param_file {
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("--param-file {}: {e}", path.display()))?;
        for (k, line) in text.lines().enumerate() {
            let line = line.split('#').next().unwrap_or("").trim();
            if !line.is_empty() {
                items.push((format!("{}:{}", path.display(), k + 1), line.to_string()));
            }
        }
    }
    for p in &args.params {
        items.push((format!("--param {p}"), p.clone()));
    }
    let mut out = AllParams {
        itd: ItdParams::default(),
        step: RidgeStepParams::default(),
        step_overrides: Vec::new(),
        described: String::new(),
    };
    let mut described = Vec::new();
    for (whence, item) in &items {
        let (name, value) = item
            .split_once('=')
            .ok_or_else(|| format!("{whence}: expected NAME=VALUE"))?;
        let (name, value) = (name.trim(), value.trim());
        let x: f64 = value
            .parse()
            .map_err(|_| format!("{whence}: `{value}` is not a number"))?;
        if ItdParams::NAMES.contains(&name) {
            out.itd.set(name, x).map_err(|e| format!("{whence}: {e}"))?;
        } else if RidgeStepParams::FIELDS.iter().any(|f| f.name == name) {
            out.step
                .set(name, x)
                .map_err(|e| format!("{whence}: {e}"))?;
            if !out.step_overrides.iter().any(|n| n == name) {
                out.step_overrides.push(name.to_string());
            }
        } else {
            let step: Vec<&str> = RidgeStepParams::FIELDS.iter().map(|f| f.name).collect();
            return Err(format!(
                "{whence}: unknown parameter `{name}`; ridging parameters: {}; constants of \
                 the complete step: {}",
                ItdParams::NAMES.join(", "),
                step.join(", ")
            )
            .into());
        }
        described.push(format!("{name}={value}"));
    }
    out.described = if described.is_empty() {
        "none".into()
    } else {
        described.join(", ")
    };
    Ok(out)
}

/// The global attributes common to both steps; `host`: the variables of the host's rates.
pub(super) fn global_attrs(
    args: &Args,
    o: &RidgeOptions,
    host: Option<(&str, &str)>,
    overrides: &str,
) -> Vec<(String, String)> {
    let mut g = vec![
        (
            "participation".to_string(),
            o.participation.name().to_string(),
        ),
        (
            "redistribution".to_string(),
            o.redistribution.name().to_string(),
        ),
        ("dt".to_string(), format!("{} s", args.dt)),
    ];
    match host {
        None => {
            g.push((
                "rates".into(),
                "deformation (CICE: closing and opening derived from convergence and shear)".into(),
            ));
            g.push((
                "convergence".to_string(),
                args.convergence
                    .map_or("max(-divu, 0) from input".into(), |c| format!("{c} s-1")),
            ));
            g.push((
                "shear".to_string(),
                args.shear
                    .map_or("from input (or 0)".into(), |s| format!("{s} s-1")),
            ));
        }
        Some((c, op)) => {
            g.push((
                "rates".into(),
                "host (SIS2: the host's closing and opening rates, category bounds as given)"
                    .into(),
            ));
            g.push(("closing_rate".into(), format!("input variable `{c}` (s-1)")));
            g.push((
                "opening_rate".into(),
                format!("input variable `{op}` (s-1)"),
            ));
        }
    }
    g.push(("input".to_string(), args.input.display().to_string()));
    g.push(("parameter_overrides".into(), overrides.to_string()));
    g
}
