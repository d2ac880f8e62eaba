//! The seeded record streams of `uvt vectors gen`, one record at a time: what a testbench calls
//! to draw its own stimulus (record `index` of the stream of kind, configuration and seed is the
//! same wherever and in whatever order it is drawn).

use std::ffi::c_char;

use uvt_records::kind::Kind;
use uvt_records::stream::Stream;

use crate::error::{c_str, guard, words_mut, Fail, UVT_ERR_CONFIG, UVT_ERR_KIND, UVT_ERR_LENGTH};

/// Input record `index` of the seeded stream of kind `kind` at configuration `config` (null: the
/// kind's default) with seed `seed` and `spp` samples per resolve record (ignored by the other
/// kinds; pass 16) into `out` (`out_len` words). Returns the words written (> 0) or a
/// `UVT_ERR_*` code (bounds and sample records have no self-contained stream:
/// `UVT_ERR_KIND`).
///
/// # Safety
/// `config` is null or a NUL-terminated string; `out` points to `out_len` writable `u32`s.
#[no_mangle]
pub unsafe extern "C" fn uvt_gen(
    kind: u32,
    config: *const c_char,
    seed: u64,
    index: u64,
    spp: u32,
    out: *mut u32,
    out_len: usize,
) -> i32 {
    guard(|| {
        let k = Kind::from_code(kind)
            .ok_or_else(|| Fail::new(UVT_ERR_KIND, format!("unknown record kind code {kind}")))?;
        // SAFETY: the caller's contract.
        let (c, o) = unsafe { (c_str(config, "config")?, words_mut(out, out_len, "out")?) };
        let code = if k.needs_setup() {
            UVT_ERR_KIND
        } else {
            UVT_ERR_CONFIG
        };
        let s = Stream::new(k, c, seed, spp).map_err(|e| Fail::new(code, e))?;
        let (r, _) = s.record(index);
        if o.len() < r.0.len() {
            return Err(Fail::new(
                UVT_ERR_LENGTH,
                format!(
                    "output buffer of {} words, a {}_in record has {}",
                    o.len(),
                    k.name(),
                    r.0.len()
                ),
            ));
        }
        o[..r.0.len()].copy_from_slice(&r.0);
        Ok(r.0.len() as i32)
    })
}
