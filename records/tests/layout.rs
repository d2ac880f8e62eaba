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
