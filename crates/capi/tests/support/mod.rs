//! What the C ABI's test files share: the message of the last failure, read through the
//! string protocol of `pressridge_last_error` as a C caller reads it.

use pressridge_capi::{PRESSRIDGE_OK, pressridge_last_error};
use std::ptr::null_mut;

/// The calling thread's last error message (the call itself must succeed).
pub fn last_error() -> String {
    let mut need = 0i64;
    // SAFETY: a null buffer of length 0 asks for the size; `need` is a live local.
    unsafe { pressridge_last_error(null_mut(), 0, &mut need) };
    let mut buf = vec![0u8; need as usize];
    // SAFETY: `buf` holds `need` bytes.
    let rc = unsafe { pressridge_last_error(buf.as_mut_ptr().cast(), need, null_mut()) };
    assert_eq!(rc, PRESSRIDGE_OK);
    buf.pop();
    String::from_utf8(buf).unwrap()
}
