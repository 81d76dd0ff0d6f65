//! What `ridge-step` was told, for the step and for the record: the parameter overrides of
//! --param-file and --param, and the global attributes common to both steps.

use pressridge::itd::{ItdParams, RidgeOptions, RidgeStepOptions, details::RidgeStepParams};

use super::Args;
use crate::{BoxError, params};

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

/// Reads --param-file, then --param (which wins): each NAME=VALUE names a constant of the
/// complete step (the library's [`RidgeStepOptions`] set: an `ItdParams` or a
/// `RidgeStepParams` name).
pub(super) fn parse_all_params(args: &Args) -> Result<AllParams, BoxError> {
    let mut c = RidgeStepOptions::default();
    let given = params::apply(
        &mut c,
        &params::settings(args.param_file.as_deref(), &args.params)?,
    )?;
    let mut step_overrides: Vec<String> = Vec::new();
    for (name, _) in &given {
        if RidgeStepParams::FIELDS.iter().any(|f| f.name == *name)
            && !step_overrides.iter().any(|n| n == name)
        {
            step_overrides.push(name.to_string());
        }
    }
    let described: Vec<String> = given.iter().map(|(n, v)| format!("{n}={v}")).collect();
    Ok(AllParams {
        itd: c.params,
        step: c.step,
        step_overrides,
        described: if described.is_empty() {
            "none".into()
        } else {
            described.join(", ")
        },
    })
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
    g.extend(crate::strength::describe_mu_rdg(&o.redistribution));
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
