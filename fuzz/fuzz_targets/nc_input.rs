//! A NetCDF file built from fuzz bytes, for the reader targets: the bytes choose the
//! dimensions (names from a pool that includes the category names), the variables (names
//! from the target's pool), each variable's dimensions, type, values, `units`, `_FillValue`
//! and `coordinates`. The file is well-formed NetCDF, so what is fuzzed is pressridge's
//! reading of its structure and values, not the NetCDF C library's parser.

#![allow(dead_code)]

use std::path::{Path, PathBuf};

pub use crate::bytes::Bytes;

/// Values a sea-ice file holds (fill values included), for [`Bytes::f64_from`].
pub const NICE: [f64; 16] = [
    0.0,
    1e-12,
    0.01,
    0.1,
    0.25,
    0.5,
    1.0,
    2.5,
    3.0,
    10.0,
    -1.8,
    1e30,
    -9999.0,
    9.969_209_968_386_869e36,
    1e-6,
    4.0,
];

/// A scratch file of this process.
pub fn scratch(name: &str) -> PathBuf {
    let dir = Path::new("/dev/shm");
    let dir = if dir.is_dir() {
        dir.to_path_buf()
    } else {
        std::env::temp_dir()
    };
    dir.join(format!("pressridge-fuzz-{name}-{}.nc", std::process::id()))
}

/// Writes a file at `path` from the bytes: up to four dimensions, then up to `vars.len()`
/// variables drawn from `vars`. Returns false when the NetCDF library refuses the structure
/// (a duplicate name, say): nothing to read then.
pub fn write(path: &Path, d: &mut Bytes<'_>, dims: &[&str], vars: &[&str], units: &[&str]) -> bool {
    let _ = std::fs::remove_file(path);
    let Ok(mut f) = netcdf::create_with(path, netcdf::Options::_64BIT_OFFSET) else {
        return false;
    };
    let ndim = 1 + usize::from(d.byte() % 4);
    let mut made: Vec<(&str, usize)> = Vec::new();
    for _ in 0..ndim {
        let name = *d.pick(dims);
        if made.iter().any(|m| m.0 == name) {
            continue;
        }
        let len = 1 + usize::from(d.byte() % 4);
        if f.add_dimension(name, len).is_err() {
            return false;
        }
        made.push((name, len));
    }
    let nvar = usize::from(d.byte()) % (vars.len() + 1);
    let mut defined: Vec<(String, Vec<(&str, usize)>, u8)> = Vec::new();
    for _ in 0..nvar {
        let name = *d.pick(vars);
        if defined.iter().any(|v| v.0 == name) {
            continue;
        }
        // Dimensions: 0 to 4 of those made, in any order, none twice.
        let mut vd: Vec<(&str, usize)> = Vec::new();
        for _ in 0..d.byte() % 5 {
            let m = *d.pick(&made);
            if !vd.iter().any(|x| x.0 == m.0) {
                vd.push(m);
            }
        }
        let names: Vec<&str> = vd.iter().map(|x| x.0).collect();
        let ty = d.byte() % 4;
        let var = match ty {
            0 => f.add_variable::<f64>(name, &names),
            1 => f.add_variable::<f32>(name, &names),
            2 => f.add_variable::<i32>(name, &names),
            _ => f.add_variable::<i16>(name, &names),
        };
        let Ok(mut var) = var else { return false };
        let attrs = d.byte();
        if attrs & 1 != 0 {
            let _ = var.put_attribute("units", *d.pick(units));
        }
        if attrs & 2 != 0 {
            let fill = d.f64_from(&NICE);
            let _ = match ty {
                0 => var.put_attribute("_FillValue", fill),
                1 => var.put_attribute("_FillValue", fill as f32),
                2 => var.put_attribute("_FillValue", fill as i32),
                _ => var.put_attribute("_FillValue", fill as i16),
            };
        }
        if attrs & 4 != 0 {
            let _ = var.put_attribute("missing_value", d.f64_from(&NICE));
        }
        if attrs & 8 != 0 {
            let _ = var.put_attribute("coordinates", *d.pick(&["TLON TLAT", "ni", "x", ""]));
        }
        defined.push((name.to_string(), vd, ty));
    }
    if f.enddef().is_err() {
        return false;
    }
    for (name, vd, ty) in &defined {
        let n: usize = vd.iter().map(|x| x.1).product();
        let vals: Vec<f64> = (0..n).map(|_| d.f64_from(&NICE)).collect();
        let mut var = f.variable_mut(name).expect("just defined");
        let ok = match ty {
            0 => var.put_values(&vals, ..).is_ok(),
            1 => var
                .put_values(&vals.iter().map(|x| *x as f32).collect::<Vec<_>>(), ..)
                .is_ok(),
            2 => var
                .put_values(&vals.iter().map(|x| *x as i32).collect::<Vec<_>>(), ..)
                .is_ok(),
            _ => var
                .put_values(&vals.iter().map(|x| *x as i16).collect::<Vec<_>>(), ..)
                .is_ok(),
        };
        if !ok {
            return false;
        }
    }
    f.close().is_ok()
}
