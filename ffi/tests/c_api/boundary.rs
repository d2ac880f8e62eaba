//! The C boundary: every function returns a code instead of panicking on random words, null
//! pointers, short buffers and unknown kinds; the records through the C functions are the
//! committed vectors bit for bit; the typed API gives the records' coverage, depth and edge
//! values; `uvt_compare` names the differing field. `UVT_SEED` seeds the random words.

use std::ffi::{CStr, CString};
use std::path::PathBuf;
use std::ptr::{null, null_mut};

use uvt_ffi::records::*;
use uvt_ffi::stream::uvt_gen;
use uvt_ffi::typed::*;
use uvt_ffi::*;
use uvt_records::format::{layout, parse};
use uvt_records::kind::Kind;

fn last() -> String {
    // SAFETY: uvt_last_error returns a valid NUL-terminated string.
    unsafe { CStr::from_ptr(uvt_last_error()) }
        .to_string_lossy()
        .into_owned()
}

fn seed() -> u64 {
    std::env::var("UVT_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1)
}

/// Records of `file` in the committed unit-level set (the default configuration).
fn committed(file: &str) -> Vec<Vec<u32>> {
    committed_in("unit", file)
}

/// Records of `file` in the committed set `set` (`unit_exact`: the exact configuration, whose
/// sample records are the exact sample test's).
fn committed_in(set: &str, file: &str) -> Vec<Vec<u32>> {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../vectors")
        .join(set)
        .join(format!("{file}.hex"));
    let text = std::fs::read_to_string(&p).unwrap();
    parse(&text, layout(file, 16).words, file).unwrap()
}

#[test]
fn the_constants_are_the_layouts() {
    for (k, i, o) in [
        (Kind::Setup, UVT_SETUP_IN_WORDS, UVT_SETUP_OUT_WORDS),
        (Kind::Bounds, UVT_BOUNDS_IN_WORDS, UVT_BOUNDS_OUT_WORDS),
        (Kind::Select, UVT_SELECT_IN_WORDS, UVT_SELECT_OUT_WORDS),
        (Kind::Sample, UVT_SAMPLE_IN_WORDS, UVT_SAMPLE_OUT_WORDS),
        (Kind::Bsample, UVT_BSAMPLE_IN_WORDS, UVT_BSAMPLE_OUT_WORDS),
        (Kind::Psample, UVT_PSAMPLE_IN_WORDS, UVT_PSAMPLE_OUT_WORDS),
    ] {
        assert_eq!(
            (k.words_in(0) as usize, k.words_out() as usize),
            (i, o),
            "{k:?}"
        );
        assert!(o <= UVT_MAX_WORDS && i <= UVT_MAX_WORDS);
        let (mut a, mut b) = (0, 0);
        // SAFETY: two writable u32s.
        assert_eq!(unsafe { uvt_words(k.code(), 0, &mut a, &mut b) }, UVT_OK);
        assert_eq!((a as usize, b as usize), (i, o));
    }
    assert_eq!(Kind::Resolve.words_out() as usize, UVT_RESOLVE_OUT_WORDS);
    let longest = Kind::ALL
        .iter()
        .map(|k| k.words_out().max(k.words_in(UVT_MAX_SPP)))
        .max();
    assert_eq!(
        longest,
        Some(UVT_MAX_WORDS as u32),
        "UVT_MAX_WORDS is the longest record"
    );
    assert_eq!(
        [
            UVT_KIND_SETUP,
            UVT_KIND_BOUNDS,
            UVT_KIND_SELECT,
            UVT_KIND_SAMPLE,
            UVT_KIND_BSAMPLE,
            UVT_KIND_PSAMPLE,
            UVT_KIND_RESOLVE
        ],
        Kind::ALL.map(|k| k.code())
    );
    assert_eq!(uvt_format_version(), uvt_records::format::FORMAT_VERSION);
}

#[test]
fn committed_records_through_the_c_functions() {
    let setups = committed("setup_in");
    let (si, so) = (committed("bsample_in"), committed("bsample_out"));
    for (i, o) in si.iter().zip(&so) {
        let mut out = [0u32; UVT_BSAMPLE_OUT_WORDS];
        // SAFETY: buffers of the stated lengths.
        assert_eq!(
            unsafe { uvt_bsample(i.as_ptr(), out.as_mut_ptr()) },
            UVT_OK,
            "{}",
            last()
        );
        assert_eq!(&out[..], &o[..]);
    }
    for (i, o) in committed("psample_in")
        .iter()
        .zip(&committed("psample_out"))
    {
        let mut out = [0u32; UVT_PSAMPLE_OUT_WORDS];
        // SAFETY: buffers of the stated lengths.
        assert_eq!(
            unsafe { uvt_psample(i.as_ptr(), out.as_mut_ptr()) },
            UVT_OK,
            "{}",
            last()
        );
        assert_eq!(&out[..], &o[..]);
    }
    let exact_setups = committed_in("unit_exact", "setup_in");
    for (i, o) in committed_in("unit_exact", "sample_in")
        .iter()
        .zip(&committed_in("unit_exact", "sample_out"))
        .take(2000)
    {
        let mut out = [0u32; UVT_SAMPLE_OUT_WORDS];
        let s = &exact_setups[i[0] as usize];
        // SAFETY: buffers of the stated lengths.
        assert_eq!(
            unsafe { uvt_sample(s.as_ptr(), i.as_ptr(), out.as_mut_ptr()) },
            UVT_OK,
            "{}",
            last()
        );
        assert_eq!(&out[..], &o[..]);
    }
    for (i, o) in committed("bounds_in")
        .iter()
        .zip(&committed("bounds_out"))
        .take(2000)
    {
        let mut out = [0u32; 8];
        let s = &setups[i[0] as usize];
        // SAFETY: a setup record, an input record, an 8-word buffer.
        let n = unsafe {
            uvt_run(
                UVT_KIND_BOUNDS,
                i.as_ptr(),
                i.len(),
                s.as_ptr(),
                s.len(),
                out.as_mut_ptr(),
                8,
            )
        };
        assert_eq!(n, UVT_BOUNDS_OUT_WORDS as i32, "{}", last());
        assert_eq!(&out[..7], &o[..]);
    }
}

#[test]
fn typed_api_agrees_with_the_records() {
    let (si, so) = (committed("bsample_in"), committed("bsample_out"));
    for (i, o) in si.iter().zip(&so) {
        let mut h = null_mut();
        // SAFETY: 30 readable words, a null config, a writable handle pointer.
        let r = unsafe {
            uvt_tri_new(
                i.as_ptr().cast(),
                i[30] as u16,
                (i[30] >> 16) as u16,
                null(),
                &mut h,
            )
        };
        assert_eq!(r, UVT_OK, "{}", last());
        let mut hit = UvtHit::default();
        // SAFETY: a live handle and a writable result.
        let r = unsafe {
            uvt_tri_sample(
                h,
                i[32],
                i[33],
                i[34] as i32,
                i[35] as i32,
                i[36] as i32,
                &mut hit,
            )
        };
        assert_eq!(r, UVT_OK, "{}", last());
        assert_eq!(hit.covered as u32, o[0] & 1);
        assert_eq!(hit.depth as u32, o[1]);
        for k in 0..3 {
            assert_eq!(
                hit.e[k],
                ((u64::from(o[8 + 2 * k]) << 32) | u64::from(o[9 + 2 * k])) as i64
            );
        }
        // SAFETY: the handle of uvt_tri_new, freed once.
        unsafe { uvt_tri_free(h) };
    }
    let mut h = null_mut();
    let exact = CString::new("exact-16-16-16").unwrap();
    // SAFETY: as above.
    let r = unsafe { uvt_tri_new(si[0].as_ptr().cast(), 64, 64, exact.as_ptr(), &mut h) };
    assert_eq!(r, UVT_ERR_CONFIG);
    assert!(last().contains("exact"), "{}", last());
}

#[test]
fn compare_names_the_field() {
    let o = &committed("bsample_out")[0];
    let mut bad = o.clone();
    bad[1] ^= 1; // depth
                 // SAFETY: two records of the stated length.
    let r = unsafe { uvt_compare(UVT_KIND_BSAMPLE, o.as_ptr(), bad.as_ptr(), o.len(), 0) };
    assert_eq!(r, UVT_ERR_MISMATCH);
    assert!(last().contains("field depth"), "{}", last());
    let mut edge = o.clone();
    edge[9] ^= 1; // e0: internal, not architectural
                  // SAFETY: as above.
    assert_eq!(
        unsafe { uvt_compare(UVT_KIND_BSAMPLE, o.as_ptr(), edge.as_ptr(), o.len(), 1) },
        UVT_OK
    );
    // SAFETY: as above.
    assert_eq!(
        unsafe { uvt_compare(UVT_KIND_BSAMPLE, o.as_ptr(), edge.as_ptr(), o.len(), 0) },
        UVT_ERR_MISMATCH
    );
    assert!(last().contains("field e0"), "{}", last());
}

#[test]
fn no_panic_crosses_the_boundary() {
    let mut x = seed() | 1;
    let mut next = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        x as u32
    };
    let mut codes = std::collections::BTreeMap::new();
    for round in 0..20_000 {
        let kind = next() % 9; // 7 and 8: unknown kinds
        let len = (next() % 110) as usize;
        let mut input: Vec<u32> = (0..len).map(|_| next()).collect();
        let setup: Vec<u32> = (0..32).map(|_| next()).collect();
        let mut out = vec![0u32; (next() % 110) as usize];
        // SAFETY: every pointer has the length passed with it.
        let r = unsafe {
            match round % 4 {
                0 => uvt_run(
                    kind,
                    input.as_ptr(),
                    len,
                    setup.as_ptr(),
                    31,
                    out.as_mut_ptr(),
                    out.len(),
                ),
                1 => uvt_complete(kind, input.as_mut_ptr(), len),
                2 => uvt_compare(kind, input.as_ptr(), input.as_ptr(), len, 1),
                _ => uvt_gen(
                    kind,
                    null(),
                    u64::from(next()),
                    u64::from(next()),
                    next() % 70,
                    out.as_mut_ptr(),
                    out.len(),
                ),
            }
        };
        assert_ne!(r, UVT_ERR_INTERNAL, "round {round}: {}", last());
        *codes.entry(r.min(1)).or_insert(0u32) += 1;
    }
    // valid records of random words exist only by luck: most are refused, each with a message
    assert!(
        codes.contains_key(&UVT_ERR_INPUT)
            && codes.contains_key(&UVT_ERR_LENGTH)
            && codes.contains_key(&UVT_ERR_KIND),
        "{codes:?}"
    );
    // null pointers and short buffers
    let mut out = [0u32; 4];
    // SAFETY: null pointers are allowed and refused; `out` has 4 words.
    unsafe {
        assert_eq!(uvt_bsample(null(), out.as_mut_ptr()), UVT_ERR_NULL);
        assert_eq!(
            uvt_run(
                UVT_KIND_BSAMPLE,
                committed("bsample_in")[0].as_ptr(),
                37,
                null(),
                0,
                out.as_mut_ptr(),
                4
            ),
            UVT_ERR_LENGTH
        );
        assert_eq!(
            uvt_run(
                UVT_KIND_SAMPLE,
                committed_in("unit_exact", "sample_in")[0].as_ptr(),
                6,
                null(),
                0,
                out.as_mut_ptr(),
                4
            ),
            UVT_ERR_INPUT
        );
        assert!(last().contains("setup_in"), "{}", last());
        assert_eq!(
            uvt_tri_sample(null(), 0, 0, 0, 0, 0, null_mut()),
            UVT_ERR_NULL
        );
        assert_eq!(uvt_tri_class(null()), UVT_ERR_NULL);
        uvt_tri_free(null_mut());
        for c in [UVT_OK, UVT_ERR_KIND, UVT_ERR_INPUT, UVT_ERR_INTERNAL, 99] {
            assert!(!CStr::from_ptr(uvt_strerror(c)).to_bytes().is_empty());
        }
    }
    // an off-grid record is refused naming the field
    let mut r = committed("bsample_in")[0].clone();
    r[31] ^= 1; // class
                // SAFETY: 37 and 14 words.
    let mut out14 = [0u32; UVT_BSAMPLE_OUT_WORDS];
    // SAFETY: 37 and 14 words.
    assert_eq!(
        unsafe { uvt_bsample(r.as_ptr(), out14.as_mut_ptr()) },
        UVT_ERR_INPUT
    );
    assert!(last().contains("class"), "{}", last());
}

#[test]
fn gen_is_the_stream() {
    let s = uvt_records::stream::Stream::new(Kind::Psample, None, 7, 16).unwrap();
    for i in 0..50 {
        let mut out = [0u32; UVT_MAX_WORDS];
        // SAFETY: a buffer of UVT_MAX_WORDS words.
        let n = unsafe {
            uvt_gen(
                UVT_KIND_PSAMPLE,
                null(),
                7,
                i,
                16,
                out.as_mut_ptr(),
                out.len(),
            )
        };
        assert_eq!(n, UVT_PSAMPLE_IN_WORDS as i32, "{}", last());
        assert_eq!(&out[..n as usize], &s.record(i).0 .0[..]);
    }
    let bad = CString::new("bounded-16-16-16-20").unwrap();
    let mut out = [0u32; UVT_MAX_WORDS];
    // SAFETY: as above.
    assert_eq!(
        unsafe {
            uvt_gen(
                UVT_KIND_PSAMPLE,
                bad.as_ptr(),
                7,
                0,
                16,
                out.as_mut_ptr(),
                out.len(),
            )
        },
        UVT_ERR_CONFIG
    );
    // SAFETY: as above.
    assert_eq!(
        unsafe {
            uvt_gen(
                UVT_KIND_BOUNDS,
                null(),
                7,
                0,
                16,
                out.as_mut_ptr(),
                out.len(),
            )
        },
        UVT_ERR_KIND
    );
}
