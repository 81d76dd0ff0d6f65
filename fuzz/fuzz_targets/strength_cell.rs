//! The per-cell strength entry point of the C ABI (`pressridge_strength_cell`) on arbitrary
//! columns and options: it returns a status code, never crashes, and a strength it reports
//! as computed is finite.
#![no_main]

use libfuzzer_sys::fuzz_target;
use pressridge_capi::PRESSRIDGE_OK;
use pressridge_capi::itd::{PressridgeOptions, pressridge_strength_cell};

/// The next f64 of the input (its 8 bytes as they come), or 0 when it runs out.
fn next(data: &mut &[u8]) -> f64 {
    let (head, rest) = data.split_at(data.len().min(8));
    *data = rest;
    let mut b = [0u8; 8];
    b[..head.len()].copy_from_slice(head);
    f64::from_le_bytes(b)
}

fuzz_target!(|input: &[u8]| {
    let Some((&first, mut data)) = input.split_first() else {
        return;
    };
    // 0 to 20 categories (0 must be refused), then the option codes and C_f, then the column.
    let ncat = usize::from(first % 21);
    let mut o = PressridgeOptions::default();
    if let Some((&codes, rest)) = data.split_first() {
        o.participation = i32::from(codes & 3);
        o.redistribution = i32::from((codes >> 2) & 3);
        o.strength_law = i32::from((codes >> 4) & 3);
        data = rest;
        o.cf = next(&mut data);
    }
    let aice0 = next(&mut data);
    let a: Vec<f64> = (0..ncat).map(|_| next(&mut data)).collect();
    let v: Vec<f64> = (0..ncat).map(|_| next(&mut data)).collect();
    let mut p = f64::NAN;
    // SAFETY: `a` and `v` hold `ncat` values, `o` and `p` are live locals.
    let rc =
        unsafe { pressridge_strength_cell(ncat as i64, a.as_ptr(), v.as_ptr(), aice0, &o, &mut p) };
    if rc == PRESSRIDGE_OK {
        assert!(p.is_finite(), "strength {p} reported as computed");
    }
});
