//! The C_f table readers (`read_cf_table`, `read_cf_table_at_friction`) on well-formed
//! NetCDF files of arbitrary structure and values (`nc_input.rs`: `thickness`, `cf`, the
//! friction coordinates and a ridging table's variables): a value or an error, never a panic;
//! a table accepted has strictly increasing finite thicknesses and gives a finite, positive
//! C_f at any thickness.
#![no_main]

#[path = "bytes.rs"]
mod bytes;
#[path = "nc_input.rs"]
mod nc_input;

use libfuzzer_sys::fuzz_target;
use nc_input::{Bytes, scratch, write};
use pressridge::io::itd_netcdf::{read_cf_table, read_cf_table_at_friction};
use pressridge::itd::details::{CfProvider, CfTable};

const DIMS: &[&str] = &["thickness", "node", "set", "volume", "mu"];
const VARS: &[&str] = &["thickness", "cf", "mu", "mu_w", "volume", "cf_fit", "W"];
const UNITS: &[&str] = &["m", "1", "", "cm", "m3 m-1"];

fn check(t: &CfTable) {
    let h = t.thickness();
    assert!(!h.is_empty() && h.len() == t.values().len());
    assert!(h.iter().all(|x| x.is_finite()));
    assert!(
        h.windows(2).all(|w| w[0] < w[1]),
        "thickness not increasing: {h:?}"
    );
    for x in [
        0.0,
        1e-3,
        h[0],
        0.5 * (h[0] + h[h.len() - 1]),
        1e3,
        f64::MAX,
    ] {
        let c = t.lookup(x).value;
        assert!(c.is_finite() && c > 0.0, "C_f {c} at {x} m");
    }
}

fuzz_target!(|input: &[u8]| {
    let mut d = Bytes(input);
    let path = scratch("cf");
    let friction = match d.byte() % 3 {
        0 => None,
        1 => Some((1.0, 0.6)),
        _ => Some((d.f64_from(&nc_input::NICE), d.f64_from(&nc_input::NICE))),
    };
    if !write(&path, &mut d, DIMS, VARS, UNITS) {
        return;
    }
    if let Ok(t) = read_cf_table(&path) {
        check(&t);
    }
    if let Ok(t) = read_cf_table_at_friction(&path, friction) {
        check(&t);
    }
});
