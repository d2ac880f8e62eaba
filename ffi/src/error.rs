//! Return codes, the last error's message, the panic guard and the pointer checks: the only
//! `unsafe` of the crate besides the handle's ownership ([`crate::typed`]).

use std::cell::RefCell;
use std::ffi::{c_char, CStr, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Success.
pub const UVT_OK: i32 = 0;
/// An unknown kind code.
pub const UVT_ERR_KIND: i32 = -1;
/// A record or buffer of the wrong length.
pub const UVT_ERR_LENGTH: i32 = -2;
/// A null pointer where data is needed.
pub const UVT_ERR_NULL: i32 = -3;
/// An input the model refuses (a field out of its domain, off its configuration's grid, a
/// culled triangle, …): `uvt_last_error()` names the field.
pub const UVT_ERR_INPUT: i32 = -4;
/// An unknown configuration, or one the operation is not made at.
pub const UVT_ERR_CONFIG: i32 = -5;
/// Two records differ (`uvt_compare`): `uvt_last_error()` lists the fields.
pub const UVT_ERR_MISMATCH: i32 = -6;
/// A bug in uvt: the model panicked. Caught at the boundary; please report the input.
pub const UVT_ERR_INTERNAL: i32 = -7;

/// A refused call: its code and message.
#[derive(Debug)]
pub struct Fail {
    /// `UVT_ERR_*`
    pub code: i32,
    /// what was refused
    pub msg: String,
}

impl Fail {
    /// A failure of `code` with message `msg`.
    pub fn new(code: i32, msg: impl Into<String>) -> Fail {
        Fail {
            code,
            msg: msg.into(),
        }
    }
    /// An input refused by the model.
    pub fn input(msg: impl Into<String>) -> Fail {
        Fail::new(UVT_ERR_INPUT, msg)
    }
}

thread_local! {
    static LAST: RefCell<CString> = RefCell::new(CString::default());
}

fn set_last(msg: &str) {
    LAST.with(|l| {
        let mut l = l.borrow_mut();
        if msg.is_empty() && l.as_bytes().is_empty() {
            return; // the common case after a success: no allocation per call
        }
        // an interior NUL would cut the message: replace it
        *l = CString::new(msg.replace('\0', " ")).unwrap_or_default();
    });
}

/// Run `f` at the boundary: its result as a code, the message kept for `uvt_last_error`, a
/// panic caught and turned into [`UVT_ERR_INTERNAL`].
pub fn guard(f: impl FnOnce() -> Result<i32, Fail>) -> i32 {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(Ok(n)) => {
            set_last("");
            n
        }
        Ok(Err(e)) => {
            set_last(&e.msg);
            e.code
        }
        Err(p) => {
            let what = p
                .downcast_ref::<&str>()
                .map(|s| (*s).to_string())
                .or_else(|| p.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            set_last(&format!(
                "internal error (a bug in uvt, please report the input): {what}"
            ));
            UVT_ERR_INTERNAL
        }
    }
}

/// Largest slice the library reads or writes (longer lengths are a caller's bug).
const MAX_LEN: usize = 1 << 16;

/// The caller's `len` words at `p` (an empty slice for `len` 0).
///
/// # Safety
/// `p` must be null or point to `len` readable, initialised `u32`s that stay valid and unwritten
/// for the call.
pub unsafe fn words<'a>(p: *const u32, len: usize, what: &str) -> Result<&'a [u32], Fail> {
    if len == 0 {
        return Ok(&[]);
    }
    if p.is_null() {
        return Err(Fail::new(UVT_ERR_NULL, format!("{what}: null pointer")));
    }
    if len > MAX_LEN {
        return Err(Fail::new(UVT_ERR_LENGTH, format!("{what}: {len} words")));
    }
    // SAFETY: non-null, and the caller promises `len` readable words (this function's contract).
    Ok(unsafe { std::slice::from_raw_parts(p, len) })
}

/// The caller's writable buffer of `len` words at `p`.
///
/// # Safety
/// `p` must be null or point to `len` writable `u32`s, not aliased for the call.
pub unsafe fn words_mut<'a>(p: *mut u32, len: usize, what: &str) -> Result<&'a mut [u32], Fail> {
    if p.is_null() {
        return Err(Fail::new(UVT_ERR_NULL, format!("{what}: null pointer")));
    }
    if len > MAX_LEN {
        return Err(Fail::new(UVT_ERR_LENGTH, format!("{what}: {len} words")));
    }
    // SAFETY: non-null, and the caller promises `len` writable words (this function's contract).
    Ok(unsafe { std::slice::from_raw_parts_mut(p, len) })
}

/// The caller's NUL-terminated string (`None` for a null pointer).
///
/// # Safety
/// `p` must be null or point to a NUL-terminated string valid for the call.
pub unsafe fn c_str<'a>(p: *const c_char, what: &str) -> Result<Option<&'a str>, Fail> {
    if p.is_null() {
        return Ok(None);
    }
    // SAFETY: non-null and NUL-terminated (this function's contract).
    let s = unsafe { CStr::from_ptr(p) };
    s.to_str()
        .map(Some)
        .map_err(|_| Fail::input(format!("{what}: not UTF-8")))
}

/// The message of the last call on this thread that failed ("" after a success): what was
/// refused, naming the field. Valid until the next call into the library on this thread.
#[no_mangle]
pub extern "C" fn uvt_last_error() -> *const c_char {
    LAST.with(|l| l.borrow().as_ptr())
}

/// A fixed description of a return code (a static string).
#[no_mangle]
pub extern "C" fn uvt_strerror(code: i32) -> *const c_char {
    let s: &'static CStr = match code {
        UVT_OK => c"ok",
        UVT_ERR_KIND => c"unknown record kind",
        UVT_ERR_LENGTH => c"record or buffer of the wrong length",
        UVT_ERR_NULL => c"null pointer",
        UVT_ERR_INPUT => c"input refused by the model (uvt_last_error names the field)",
        UVT_ERR_CONFIG => c"unknown or unsupported configuration",
        UVT_ERR_MISMATCH => c"records differ (uvt_last_error lists the fields)",
        UVT_ERR_INTERNAL => c"internal error in uvt (a bug; please report the input)",
        _ => c"unknown return code",
    };
    s.as_ptr()
}
