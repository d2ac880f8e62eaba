//! The bit width of every intermediate, **derived by code** from a configuration's constants
//! (`COORD_LIMIT_RAW`, `TUV_ONE`, `MAX_VIEWPORT`, `SUBPIXEL_BITS`, `DEPTH_*`, `RECIP_SHIFT`,
//! the precision's fraction bits and offset shift, and the conservative epsilon [`Eps::of`]).
//!
//! Every row is an upper bound on the magnitude of one signal ([`Mag`], `m·2^e`, exact integer
//! arithmetic, rounded up where it must round) built from the bounds of its operands by the
//! same formula the code evaluates; its width is the number of bits a two's-complement register
//! needs for every value in `[−bound, bound]` (sign included: +2^29 needs 31 bits). A product
//! row also carries its multiplier: the operand widths and how many such products the stage
//! forms — the hardware cost model (`host/src/config/multipliers.rs`) reads them from here.
//!
//! `core/README.md`'s width tables are the output of [`write_markdown`] (`uvt widths`), and a
//! test fails if they differ; `width_corners.rs` drives the domain's extreme corners through each
//! stage with a shadow `i128` computation and checks every intermediate against these widths.

pub mod mag;
pub mod markdown;
pub mod ops;
pub mod row;
pub mod stages;
pub mod strategies;

#[cfg(test)]
mod tests {
    use crate::config::registry::Config;
    use crate::widths::mag::Mag;
    use crate::widths::markdown::write_readme;
    use crate::widths::row::exact_positions;
    use crate::widths::stages::table;

    fn generated() -> String {
        let mut s = String::new();
        write_readme(&mut s).unwrap();
        s
    }

    #[test]
    fn readme_table_is_generated() {
        let readme = include_str!("../../README.md");
        let begin = readme
            .find("<!-- widths:begin")
            .expect("begin marker in core/README.md");
        let body = &readme[begin..];
        let body = &body[body.find('\n').unwrap() + 1..];
        let end = body
            .find("<!-- widths:end -->")
            .expect("end marker in core/README.md");
        let want = generated();
        assert_eq!(
            body[..end].trim_end(),
            want.trim_end(),
            "core/README.md's width section differs from `uvt widths`; regenerate it"
        );
    }

    #[test]
    fn mag_hand_cases() {
        assert_eq!(Mag::pow2(29).bits(), 31, "+2^29 needs 31 bits with sign");
        assert_eq!(Mag::pow2(46).bits(), 48);
        assert_eq!(Mag::int((1 << 29) - 1).bits(), 30);
        assert_eq!(Mag::int(3).mul(Mag::pow2(155)).bits(), 158);
        assert_eq!(Mag::int(0).bits(), 1);
        assert_eq!(Mag::int(5).add(Mag::int(3)), Mag::pow2(3));
        assert_eq!(
            Mag::pow2(200).add(Mag::int(1)),
            Mag::pow2(202),
            "rounded up (both < 2^201)"
        );
        assert_eq!(Mag::int(7).shr_floor(1), Mag::int(3));
        assert_eq!(Mag::pow2(40).shr_floor(8), Mag::pow2(32));
        assert_eq!(Mag::int(6).max(Mag::int(5)), Mag::int(6));
        assert_eq!(Mag::int(3).mul(Mag::pow2(100)).to_u128(), Some(3 << 100));
        assert_eq!(Mag::pow2(130).to_u128(), None);
        assert_eq!(format!("{}", Mag::int(3).mul(Mag::pow2(56))), "3·2^56");
        assert_eq!(format!("{}", Mag::int(16320)), "16320");
    }

    #[test]
    fn config_names() {
        let c = Config::parse("bounded-16-16-16-20").unwrap();
        assert_eq!(
            c,
            Config::of::<crate::config::precision::BoundedPrecision>()
        );
        assert_eq!(format!("{c}"), "bounded-16-16-16-20");
        let e = Config::parse("exact-16-16-16").unwrap();
        assert_eq!(e, Config::of::<crate::config::precision::Exact>());
        for bad in [
            "exact-16-16",
            "exact-16-16-16-20",
            "bounded-16-16-16",
            "bounded-16-16-16-19",
            "bounded-16-16-16-33",
            "exact-17-16-16",
            "exact-1-16-16",
            "exact-16-16-17",
            "fast-16-16-16",
            "",
        ] {
            assert_eq!(Config::parse(bad), None, "{bad}");
        }
    }

    /// The entries issue 10 lists as wrong in the old hand-written table.
    #[test]
    fn corrected_entries() {
        let t = table(&Config::of::<crate::config::precision::Exact>());
        // Clip coordinates up to +2^29 raw: 31 bits with sign.
        let w = t.find("setup", "corner `w").unwrap();
        assert_eq!((w.bound, w.bits()), (Mag::pow2(29), 31));
        // 32-fraction-bit positions (defocus-only) reach 2^46: 48 bits.
        let [_, _, (name, f, p), _] = exact_positions();
        assert_eq!((name, f, p, p.bits()), ("defocus", 32, Mag::pow2(46), 48));
        // The separating-line products: 62 bits, formed in i128 by `crosses_camera_plane`.
        let s = t.find("setup", "separating-line cross").unwrap();
        assert_eq!((s.bits(), s.ty), (62, "i128"));
    }

    /// Every configuration of the sweep fits its declared containers, and the bounded sample
    /// test's multiplier operands stay ≤ 32 bits at the default's grid (issue 10, item 2).
    #[test]
    fn containers_hold_every_row() {
        for name in [
            "exact-16-16-16",
            "bounded-16-16-16-20",
            "bounded-16-16-16-24",
            "bounded-12-12-12-26",
            "bounded-8-8-8-28",
            "bounded-16-16-16-32",
        ] {
            let cfg = Config::parse(name).unwrap();
            for r in table(&cfg).rows() {
                assert!(
                    r.bits() <= r.container_bits(),
                    "{name}: {} needs {} bits in {}",
                    r.signal,
                    r.bits(),
                    r.ty
                );
            }
        }
        let t = table(&Config::of::<crate::config::precision::BoundedPrecision>());
        for r in t.rows().filter(|r| r.stage == "sample") {
            for m in r.mul.iter().flatten() {
                let rare = r.signal.starts_with("6 ");
                assert!(rare || (m.a <= 33 && m.b <= 33), "{}: {m:?}", r.signal);
            }
        }
    }
}
