//! Coverage from the model: the bins of `uvt_core::coverage` (names, kinds, the reason of an
//! unreachable one) and the counts the core's tests report while deciding records — the same
//! counting as `uvt vectors gen|ver --coverage` and `uvt.coverage` (`uvt_records::coverage`).

use std::ffi::{c_char, CString};
use std::sync::OnceLock;

use uvt_core::coverage::Bin;
use uvt_records::coverage;
use uvt_records::kind::Kind;

use crate::error::{guard, words, words_mut, Fail, UVT_ERR_KIND, UVT_ERR_LENGTH};

/// The bins' names and reasons as C strings (made once; they live as long as the library).
fn c_strings() -> &'static [(CString, Option<CString>)] {
    static S: OnceLock<Vec<(CString, Option<CString>)>> = OnceLock::new();
    S.get_or_init(|| {
        Bin::ALL
            .iter()
            .map(|b| {
                let c = |s: &str| CString::new(s).unwrap_or_default();
                (c(b.name()), b.unreachable().map(c))
            })
            .collect()
    })
}

/// The number of coverage bins (indices 0..this; the counts arrays of [`uvt_coverage`] have
/// this length).
#[no_mangle]
pub extern "C" fn uvt_coverage_bins() -> u32 {
    Bin::COUNT as u32
}

/// The name of bin `index` (`kind.what`, a NUL-terminated static string), or null for an index
/// out of range.
#[no_mangle]
pub extern "C" fn uvt_coverage_bin_name(index: u32) -> *const c_char {
    c_strings()
        .get(index as usize)
        .map_or(std::ptr::null(), |(n, _)| n.as_ptr())
}

/// The record kind (`UVT_KIND_*`) whose test reports bin `index`, or `UVT_ERR_KIND` for an index
/// out of range.
#[no_mangle]
pub extern "C" fn uvt_coverage_bin_kind(index: u32) -> i32 {
    Bin::ALL
        .get(index as usize)
        .and_then(|b| Kind::parse(b.kind()).ok())
        .map_or(UVT_ERR_KIND, |k| k.code() as i32)
}

/// Why no input reaches bin `index` (a NUL-terminated static string), or null for a reachable
/// bin or an index out of range.
#[no_mangle]
pub extern "C" fn uvt_coverage_bin_unreachable(index: u32) -> *const c_char {
    c_strings()
        .get(index as usize)
        .and_then(|(_, w)| w.as_ref())
        .map_or(std::ptr::null(), |w| w.as_ptr())
}

/// Add to `counts` (`counts_len` ≥ [`uvt_coverage_bins`] words, indexed by bin) the bins the
/// model's test takes deciding the `n_records` input records of kind `kind` (`UVT_KIND_BSAMPLE`
/// or `UVT_KIND_PSAMPLE`) stored one after the other in `records` (`records_len` = `n_records`
/// times the kind's input words, at most 2^16 words per call: the counts add up, so a long set
/// is counted by calls in turn). Returns the number of bins (> 0) or a `UVT_ERR_*` code (a
/// record the model refuses: `UVT_ERR_INPUT`, naming its index).
///
/// # Safety
/// `records` points to `records_len` readable `u32`s and `counts` to `counts_len` writable ones.
#[no_mangle]
pub unsafe extern "C" fn uvt_coverage(
    kind: u32,
    records: *const u32,
    records_len: usize,
    n_records: usize,
    counts: *mut u32,
    counts_len: usize,
) -> i32 {
    guard(|| {
        let k = Kind::from_code(kind)
            .ok_or_else(|| Fail::new(UVT_ERR_KIND, format!("unknown record kind code {kind}")))?;
        if !coverage::has_bins(k) {
            return Err(Fail::new(
                UVT_ERR_KIND,
                format!("records of kind {} have no coverage bins", k.name()),
            ));
        }
        // SAFETY: the caller's contract (this function's).
        let (r, c) = unsafe {
            (
                words(records, records_len, "records")?,
                words_mut(counts, counts_len, "counts")?,
            )
        };
        let w = k.words_in(0) as usize;
        if n_records.checked_mul(w) != Some(r.len()) {
            return Err(Fail::new(
                UVT_ERR_LENGTH,
                format!(
                    "{} words for {n_records} {}_in records of {w} words",
                    r.len(),
                    k.name()
                ),
            ));
        }
        if c.len() < Bin::COUNT {
            return Err(Fail::new(
                UVT_ERR_LENGTH,
                format!("counts of {} words, there are {} bins", c.len(), Bin::COUNT),
            ));
        }
        let got = coverage::records(k, r.chunks_exact(w.max(1))).map_err(Fail::input)?;
        for (d, s) in c.iter_mut().zip(got.n.iter()) {
            *d = d.saturating_add(*s);
        }
        Ok(Bin::COUNT as i32)
    })
}
