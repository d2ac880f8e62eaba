//! The record lengths kept as constants in `Kind` are the layouts' (`format::layout`).

use uvt_records::format::layout;
use uvt_records::kind::Kind;

#[test]
fn kind_lengths_are_the_layouts() {
    for k in Kind::ALL {
        for spp in [1, 4, 16, 64] {
            let file = format!("{}_in", k.name());
            assert_eq!(
                k.words_in(spp),
                layout(&file, spp).words,
                "{file} at spp {spp}"
            );
        }
        let file = format!("{}_out", k.name());
        assert_eq!(k.words_out(), layout(&file, 0).words, "{file}");
    }
}

/// A changed sub-word field is the only one `diff` names: its siblings in the same word are
/// shown by their own bits (`covered` changed, `det_sign` not).
#[test]
fn diff_names_only_the_changed_sub_word_field() {
    let mut a = vec![0u32; 14];
    a[0] = 0b011; // covered 1, det_sign 1
    let mut b = a.clone();
    b[0] = 0b010; // covered 0, det_sign 1
    let d = uvt_records::kind::diff("bsample_out", &a, &b, None);
    assert_eq!(
        d,
        vec!["field covered: expected 0x1 = 1, observed 0x0 = 0".to_string()]
    );
    b[0] = 0b101; // covered 1, det_sign −2 (2-bit two's complement)
    let d = uvt_records::kind::diff("bsample_out", &a, &b, None);
    assert_eq!(
        d,
        vec!["field det_sign: expected 0x1 = 1, observed 0x2 = -2".to_string()]
    );
}
