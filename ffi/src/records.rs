//! One function per stage at record level: the words of one `*_in.hex` line in, the words of
//! one `*_out.hex` line out, bit for bit what `uvt vectors check` expects. The lengths are the
//! `UVT_*_WORDS` constants; `uvt_run` takes any kind by code with explicit lengths.

use uvt_records::kind::{self, Kind};

use crate::error::{
    guard, words, words_mut, Fail, UVT_ERR_KIND, UVT_ERR_LENGTH, UVT_ERR_MISMATCH, UVT_OK,
};

fn kind_of(code: u32) -> Result<Kind, Fail> {
    Kind::from_code(code).ok_or_else(|| {
        Fail::new(
            UVT_ERR_KIND,
            format!("unknown record kind code {code} (0..=6)"),
        )
    })
}

/// Run `kind` on `input` (with its `setup_in` record for bounds and sample) into `out`; the
/// words written.
fn run_into(
    kind: Kind,
    input: &[u32],
    setup: Option<&[u32]>,
    out: &mut [u32],
) -> Result<i32, Fail> {
    let r = kind::run(kind, input, setup).map_err(Fail::input)?;
    if out.len() < r.0.len() {
        return Err(Fail::new(
            UVT_ERR_LENGTH,
            format!(
                "output buffer of {} words, a {}_out record has {}",
                out.len(),
                kind.name(),
                r.0.len()
            ),
        ));
    }
    out[..r.0.len()].copy_from_slice(&r.0);
    Ok(r.0.len() as i32)
}

/// Run the model on input record `input` (`in_len` words) of kind `kind` (`UVT_KIND_*`) and
/// write the expected output record to `out` (`out_len` ≥ its words). Bounds and exact
/// sample-test records name a triangle: pass its `setup_in` record in `setup_in` (`setup_len`
/// words; null/0 for the other kinds). Returns the words written (> 0) or a `UVT_ERR_*` code.
///
/// # Safety
/// Each pointer is null or points to the stated number of `u32`s (readable; `out` writable).
#[no_mangle]
pub unsafe extern "C" fn uvt_run(
    kind: u32,
    input: *const u32,
    in_len: usize,
    setup_in: *const u32,
    setup_len: usize,
    out: *mut u32,
    out_len: usize,
) -> i32 {
    guard(|| {
        let k = kind_of(kind)?;
        // SAFETY: the caller's contract (this function's).
        let (i, o) = unsafe {
            (
                words(input, in_len, "input")?,
                words_mut(out, out_len, "out")?,
            )
        };
        let s = if setup_in.is_null() {
            None
        } else {
            // SAFETY: the caller's contract.
            Some(unsafe { words(setup_in, setup_len, "setup_in")? })
        };
        run_into(k, i, s, o)
    })
}

/// A fixed-length stage call: `n_in` words in, `n_out` out, 0 on success.
unsafe fn fixed(
    kind: Kind,
    input: *const u32,
    n_in: usize,
    setup: Option<*const u32>,
    out: *mut u32,
    n_out: usize,
) -> i32 {
    guard(|| {
        // SAFETY: the caller's contract (the public function's).
        let (i, o) = unsafe { (words(input, n_in, "input")?, words_mut(out, n_out, "out")?) };
        let s = match setup {
            // SAFETY: the caller's contract.
            Some(p) => Some(unsafe { words(p, crate::consts::UVT_SETUP_IN_WORDS, "setup_in")? }),
            None => None,
        };
        run_into(kind, i, s, o).map(|_| UVT_OK)
    })
}

/// Triangle setup: `input` [`UVT_SETUP_IN_WORDS`](crate::consts::UVT_SETUP_IN_WORDS) words, `out`
/// [`UVT_SETUP_OUT_WORDS`](crate::consts::UVT_SETUP_OUT_WORDS). Returns 0 or a `UVT_ERR_*` code.
///
/// # Safety
/// `input` and `out` point to that many `u32`s (readable; writable).
#[no_mangle]
pub unsafe extern "C" fn uvt_setup(input: *const u32, out: *mut u32) -> i32 {
    // SAFETY: forwarded contract.
    unsafe {
        fixed(
            Kind::Setup,
            input,
            crate::consts::UVT_SETUP_IN_WORDS,
            None,
            out,
            crate::consts::UVT_SETUP_OUT_WORDS,
        )
    }
}

/// Per-tile bounds of the triangle of `setup_in` (32 words) for tile `input` (3 words; its
/// `tri` field is ignored) into `out` (7 words). Returns 0 or a `UVT_ERR_*` code.
///
/// # Safety
/// The pointers point to that many `u32`s (readable; `out` writable).
#[no_mangle]
pub unsafe extern "C" fn uvt_bounds(setup_in: *const u32, input: *const u32, out: *mut u32) -> i32 {
    // SAFETY: forwarded contract.
    unsafe {
        fixed(
            Kind::Bounds,
            input,
            crate::consts::UVT_BOUNDS_IN_WORDS,
            Some(setup_in),
            out,
            crate::consts::UVT_BOUNDS_OUT_WORDS,
        )
    }
}

/// The per-sample interval check: `input` 9 words, `out` 1. Returns 0 or a `UVT_ERR_*` code.
///
/// # Safety
/// The pointers point to that many `u32`s (readable; `out` writable).
#[no_mangle]
pub unsafe extern "C" fn uvt_select(input: *const u32, out: *mut u32) -> i32 {
    // SAFETY: forwarded contract.
    unsafe {
        fixed(
            Kind::Select,
            input,
            crate::consts::UVT_SELECT_IN_WORDS,
            None,
            out,
            crate::consts::UVT_SELECT_OUT_WORDS,
        )
    }
}

/// The exact sample test of the triangle of `setup_in` (32 words) at sample `input` (6 words;
/// `tri` ignored) into `out` (26 words). Returns 0 or a `UVT_ERR_*` code.
///
/// # Safety
/// The pointers point to that many `u32`s (readable; `out` writable).
#[no_mangle]
pub unsafe extern "C" fn uvt_sample(setup_in: *const u32, input: *const u32, out: *mut u32) -> i32 {
    // SAFETY: forwarded contract.
    unsafe {
        fixed(
            Kind::Sample,
            input,
            crate::consts::UVT_SAMPLE_IN_WORDS,
            Some(setup_in),
            out,
            crate::consts::UVT_SAMPLE_OUT_WORDS,
        )
    }
}

/// The bounded sample test: `input` 37 words (a `bsample_in` line), `out` 14 words. Returns 0 or
/// a `UVT_ERR_*` code (a record off its configuration's grid, of the wrong class or outside the
/// viewport is refused, naming the field).
///
/// # Safety
/// The pointers point to that many `u32`s (readable; `out` writable).
#[no_mangle]
pub unsafe extern "C" fn uvt_bsample(input: *const u32, out: *mut u32) -> i32 {
    // SAFETY: forwarded contract.
    unsafe {
        fixed(
            Kind::Bsample,
            input,
            crate::consts::UVT_BSAMPLE_IN_WORDS,
            None,
            out,
            crate::consts::UVT_BSAMPLE_OUT_WORDS,
        )
    }
}

/// The planar static sample test: `input` 28 words (a `psample_in` line, its setup fields the
/// core's: `uvt_complete` fills them), `out` 8 words. Returns 0 or a `UVT_ERR_*` code.
///
/// # Safety
/// The pointers point to that many `u32`s (readable; `out` writable).
#[no_mangle]
pub unsafe extern "C" fn uvt_psample(input: *const u32, out: *mut u32) -> i32 {
    // SAFETY: forwarded contract.
    unsafe {
        fixed(
            Kind::Psample,
            input,
            crate::consts::UVT_PSAMPLE_IN_WORDS,
            None,
            out,
            crate::consts::UVT_PSAMPLE_OUT_WORDS,
        )
    }
}

/// The pixel resolve of `spp` colors (`input`, one word each, 1 ≤ spp ≤ 64) into `out` (1 word).
/// Returns 0 or a `UVT_ERR_*` code.
///
/// # Safety
/// `input` points to `spp` `u32`s, `out` to one writable `u32`.
#[no_mangle]
pub unsafe extern "C" fn uvt_resolve(input: *const u32, spp: u32, out: *mut u32) -> i32 {
    // SAFETY: forwarded contract.
    unsafe {
        fixed(
            Kind::Resolve,
            input,
            spp as usize,
            None,
            out,
            crate::consts::UVT_RESOLVE_OUT_WORDS,
        )
    }
}

/// Fill the derived fields of input record `input` (`len` words) of kind `kind` in place: a
/// bounded record's `class`, a planar record's setup fields (normals, σ, depth plane). Other
/// kinds are left as they are. Returns 0 or a `UVT_ERR_*` code.
///
/// # Safety
/// `input` points to `len` readable and writable `u32`s.
#[no_mangle]
pub unsafe extern "C" fn uvt_complete(kind: u32, input: *mut u32, len: usize) -> i32 {
    guard(|| {
        let k = kind_of(kind)?;
        // SAFETY: the caller's contract.
        let i = unsafe { words_mut(input, len, "input")? };
        kind::complete(k, i).map_err(Fail::input)?;
        Ok(UVT_OK)
    })
}

/// Compare output records `expected` and `observed` (`len` words each) of kind `kind`: every
/// field, or with `arch_only` ≠ 0 only the architectural ones (a sample test's `covered` and
/// `depth`, the interval check's `inside`). Returns 0 when they agree, `UVT_ERR_MISMATCH` with
/// `uvt_last_error()` listing each differing field (expected and observed, hex and decoded).
///
/// # Safety
/// `expected` and `observed` point to `len` readable `u32`s.
#[no_mangle]
pub unsafe extern "C" fn uvt_compare(
    kind: u32,
    expected: *const u32,
    observed: *const u32,
    len: usize,
    arch_only: u32,
) -> i32 {
    guard(|| {
        let k = kind_of(kind)?;
        if len != k.words_out() as usize {
            return Err(Fail::new(
                UVT_ERR_LENGTH,
                format!(
                    "{len} words, a {}_out record has {}",
                    k.name(),
                    k.words_out()
                ),
            ));
        }
        // SAFETY: the caller's contract.
        let (e, o) = unsafe {
            (
                words(expected, len, "expected")?,
                words(observed, len, "observed")?,
            )
        };
        let only = if arch_only != 0 {
            k.architectural()
        } else {
            None
        };
        let d = kind::diff(&format!("{}_out", k.name()), e, o, only);
        if d.is_empty() {
            Ok(UVT_OK)
        } else {
            Err(Fail::new(UVT_ERR_MISMATCH, d.join("; ")))
        }
    })
}

/// Words of an input record (`spp` samples for resolve) and of an output record of kind
/// `kind`, into `in_words` and `out_words` (either may be null). Returns 0 or `UVT_ERR_KIND`.
///
/// # Safety
/// `in_words` and `out_words` are null or point to a writable `u32` each.
#[no_mangle]
pub unsafe extern "C" fn uvt_words(
    kind: u32,
    spp: u32,
    in_words: *mut u32,
    out_words: *mut u32,
) -> i32 {
    guard(|| {
        let k = kind_of(kind)?;
        for (p, v) in [(in_words, k.words_in(spp)), (out_words, k.words_out())] {
            if !p.is_null() {
                // SAFETY: non-null and writable (the caller's contract).
                unsafe { *p = v };
            }
        }
        Ok(UVT_OK)
    })
}
