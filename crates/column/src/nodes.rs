//! The one rule for a table of values against the category ice thickness, read by both the
//! C_f table ([`super::CfTable`]) and the μ_rdg table ([`super::MuRdgTable`]): the nodes'
//! checks and the leaving out of nodes no run reached.

use crate::interp::{bracket, check_axis, lerp};
use crate::limits::Range;

/// Checks table nodes: thicknesses (m) finite, strictly increasing and in
/// [`crate::limits::CATEGORY_THICKNESS`]; as many values, each in `range` (finite but
/// absurd nodes would overflow the interpolation or what the value feeds); at least one
/// node. The message names `name` and the first bad index.
pub(super) fn check(
    thickness: &[f64],
    name: &str,
    values: &[f64],
    range: Range,
) -> Result<(), String> {
    if thickness.is_empty() {
        return Err("the table has no nodes".into());
    }
    same_length(thickness, name, values)?;
    check_axis("thickness", thickness)?;
    for (name, values, range) in [
        ("thickness", thickness, crate::limits::CATEGORY_THICKNESS),
        (name, values, range),
    ] {
        if let Some((i, why)) = values
            .iter()
            .enumerate()
            .find_map(|(i, &v)| range.violation(v).map(|why| (i, why)))
        {
            return Err(format!("{name}[{i}] = {why}"));
        }
    }
    Ok(())
}

/// The nodes whose value is not NaN (a NaN marks a thickness no run of the table reached,
/// or whose runs kept no data for it); at least one must remain of a non-empty table.
pub(super) fn known(
    thickness: &[f64],
    name: &str,
    values: &[f64],
) -> Result<(Vec<f64>, Vec<f64>), String> {
    same_length(thickness, name, values)?;
    let (h, v): (Vec<f64>, Vec<f64>) = thickness
        .iter()
        .zip(values)
        .filter(|(_, v)| !v.is_nan())
        .map(|(&h, &v)| (h, v))
        .unzip();
    if h.is_empty() && !thickness.is_empty() {
        return Err(format!("every {name} is NaN (no node has data)"));
    }
    Ok((h, v))
}

fn same_length(thickness: &[f64], name: &str, values: &[f64]) -> Result<(), String> {
    if thickness.len() == values.len() {
        return Ok(());
    }
    Err(format!(
        "thickness has {} values but {name} has {}",
        thickness.len(),
        values.len()
    ))
}

/// The value at thickness `h` (m) on checked nodes: linear between them, held at the end
/// value outside, with whether it was held (clamped). A NaN `h` gives the first node's
/// value, flagged clamped.
#[inline]
pub(super) fn lookup(thickness: &[f64], values: &[f64], h: f64) -> (f64, bool) {
    if h.is_nan() {
        return (values[0], true);
    }
    let (i, w, clamped) = bracket(thickness, h);
    (lerp(values[i], || values[i + 1], w), clamped)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::limits::CF;

    #[test]
    fn nodes_are_checked_and_looked_up_by_one_rule() {
        let h = [0.2, 0.4, 1.0];
        let v = [2.0, 3.0, 1.0];
        assert!(check(&h, "v", &v, CF).is_ok());
        assert!(check(&[], "v", &[], CF).unwrap_err().contains("no nodes"));
        assert!(check(&h, "v", &v[..2], CF).unwrap_err().contains("v has 2"));
        assert!(
            check(&[0.4, 0.2], "v", &[1.0, 1.0], CF)
                .unwrap_err()
                .contains("increasing")
        );
        assert!(
            check(&[0.2], "v", &[-1.0], CF)
                .unwrap_err()
                .contains("v[0]")
        );
        assert_eq!(lookup(&h, &v, 0.3), (2.5, false));
        assert_eq!(lookup(&h, &v, 0.2), (2.0, false));
        assert_eq!(lookup(&h, &v, 1.0), (1.0, false));
        assert_eq!(lookup(&h, &v, 0.1), (2.0, true));
        assert_eq!(lookup(&h, &v, 7.0), (1.0, true));
        assert_eq!(lookup(&h, &v, f64::NAN), (2.0, true));
        let (kh, kv) = known(&h, "v", &[1.0, f64::NAN, 2.0]).unwrap();
        assert_eq!((kh, kv), (vec![0.2, 1.0], vec![1.0, 2.0]));
        assert!(
            known(&[0.2], "v", &[f64::NAN])
                .unwrap_err()
                .contains("every v")
        );
    }
}
