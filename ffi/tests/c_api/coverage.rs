//! `uvt_coverage` and the bin table: the counts of the committed unit set's sample-test records
//! through the C functions equal `uvt_records::coverage`'s (the core's own), and the calls
//! refuse what they must.

use std::ffi::CStr;
use std::path::PathBuf;

use uvt_core::coverage::Bin;
use uvt_ffi::coverage::{
    uvt_coverage, uvt_coverage_bin_kind, uvt_coverage_bin_name, uvt_coverage_bin_unreachable,
    uvt_coverage_bins,
};
use uvt_ffi::{UVT_ERR_KIND, UVT_ERR_LENGTH};
use uvt_records::coverage;
use uvt_records::format::parse;
use uvt_records::kind::Kind;

fn unit_records(kind: Kind) -> Vec<Vec<u32>> {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../vectors/unit")
        .join(format!("{}_in.hex", kind.name()));
    let text = std::fs::read_to_string(&path).expect("the committed unit set");
    parse(&text, kind.words_in(0), "in").expect("committed records parse")
}

#[test]
fn bin_table_is_the_registry() {
    assert_eq!(uvt_coverage_bins() as usize, Bin::COUNT);
    for (i, b) in Bin::ALL.iter().enumerate() {
        let i = i as u32;
        // SAFETY: a non-null name is a static NUL-terminated string.
        let name = unsafe { CStr::from_ptr(uvt_coverage_bin_name(i)) };
        assert_eq!(name.to_str().unwrap(), b.name());
        assert_eq!(
            uvt_coverage_bin_kind(i),
            Kind::parse(b.kind()).unwrap().code() as i32
        );
        assert_eq!(
            uvt_coverage_bin_unreachable(i).is_null(),
            b.unreachable().is_none()
        );
    }
    assert!(uvt_coverage_bin_name(Bin::COUNT as u32).is_null());
    assert_eq!(uvt_coverage_bin_kind(Bin::COUNT as u32), UVT_ERR_KIND);
}

#[test]
fn counts_of_the_unit_set_are_the_cores() {
    for kind in [Kind::Bsample, Kind::Psample] {
        let recs = unit_records(kind);
        let want = coverage::records(kind, recs.iter().map(Vec::as_slice)).unwrap();
        let mut got = vec![0u32; Bin::COUNT];
        // Calls of up to 1000 records (a call reads at most 2^16 words), the counts adding up.
        for part in recs.chunks(1000) {
            let flat: Vec<u32> = part.concat();
            // SAFETY: both buffers have the lengths passed.
            let r = unsafe {
                uvt_coverage(
                    kind.code(),
                    flat.as_ptr(),
                    flat.len(),
                    part.len(),
                    got.as_mut_ptr(),
                    got.len(),
                )
            };
            assert_eq!(r, Bin::COUNT as i32, "{}", kind.name());
        }
        let flat: Vec<u32> = recs[..10].concat();
        let recs = &recs[..10];
        assert_eq!(got, want.n.to_vec(), "{}", kind.name());
        assert!(got.iter().any(|&n| n > 0));
        // A short counts buffer and a record count that does not match the words are refused.
        // SAFETY: as above.
        unsafe {
            let short = uvt_coverage(
                kind.code(),
                flat.as_ptr(),
                flat.len(),
                recs.len(),
                got.as_mut_ptr(),
                1,
            );
            assert_eq!(short, UVT_ERR_LENGTH);
            let odd = uvt_coverage(
                kind.code(),
                flat.as_ptr(),
                flat.len() - 1,
                recs.len(),
                got.as_mut_ptr(),
                got.len(),
            );
            assert_eq!(odd, UVT_ERR_LENGTH);
        }
    }
    // A kind without bins is refused.
    let mut got = vec![0u32; Bin::COUNT];
    // SAFETY: an empty record buffer and a counts buffer of its length.
    let r = unsafe {
        uvt_coverage(
            Kind::Select.code(),
            [0u32; 1].as_ptr(),
            0,
            0,
            got.as_mut_ptr(),
            got.len(),
        )
    };
    assert_eq!(r, UVT_ERR_KIND);
}
