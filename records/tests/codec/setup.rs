//! Setup records at a configuration: the configuration word round-trips for every registry
//! entry and is refused by name outside it; a triangle off the configuration's position grid is
//! refused; the record's configuration is the one the core sets up at (the epsilon is zero at an
//! exact configuration only); the architectural fields come first and `--arch-only` compares
//! exactly them.

use uvt_core::config::registry::{self, CONFIGS};
use uvt_core::{Triangle, Vertex, Viewport};
use uvt_records::format::{layout, SETUP_ARCHITECTURAL};
use uvt_records::kind::{self, Kind};
use uvt_records::stages::{config_word, dec_config, enc_setup_in};

/// A moving, defocused triangle on every position grid down to 2 fraction bits.
fn tri() -> Triangle {
    let v = |x: i32, y: i32, w: i32, c: i32| {
        Vertex::from_bits([x << 14, y << 14, 1 << 14, w << 14, c << 14])
    };
    Triangle::new(
        [v(-2, -2, 4, 1), v(2, -2, 4, 1), v(0, 2, 4, 1)],
        [v(-1, -2, 4, 2), v(3, -2, 4, 2), v(1, 2, 5, 2)],
    )
    .unwrap()
}

#[test]
fn the_configuration_word_round_trips_and_is_refused_outside_the_registry() {
    for e in CONFIGS {
        let w = config_word(e.config).0[0];
        assert_eq!(dec_config(w), Ok(e.config), "{} = {w:#010x}", e.name);
    }
    // exact-9-9-9 parses but is not in the registry; datapath 3 does not exist; bits above 22.
    let nine = uvt_core::config::registry::Config::parse("exact-9-9-9").unwrap();
    for (w, what) in [
        (config_word(nine).0[0], "exact-9-9-9"),
        (config_word(registry::DEFAULT).0[0] | 3, "datapath 3"),
        (
            config_word(registry::DEFAULT).0[0] | 1 << 23,
            "bounded-16-16-16-20",
        ),
    ] {
        let e = dec_config(w).unwrap_err();
        assert!(
            e.contains(what) && e.contains("not a registry configuration"),
            "{w:#010x}: {e}"
        );
    }
}

#[test]
fn setup_runs_at_the_records_configuration() {
    let vp = Viewport::new(64, 48).unwrap();
    let t = tri();
    let eps = |name: &str| {
        let c = registry::find(name).unwrap();
        let out = kind::run(Kind::Setup, &enc_setup_in(&t, vp, c).0, None).unwrap();
        let l = layout("setup_out", 0);
        let word = |f: &str| out.0[l.fields.iter().find(|x| x.name == f).unwrap().word as usize];
        assert_eq!(out.0[0] & 1, 1, "{name}: visible");
        [word("eps_x"), word("eps_y"), word("eps_w")]
    };
    assert_eq!(eps("exact-16-16-16"), [0, 0, 0]);
    assert_eq!(eps("exact-8-8-4"), [0, 0, 0]);
    let d = eps("bounded-16-16-16-20");
    assert!(d[0] > 0 && d[1] > 0 && d[2] == 1, "{d:?}");
    let coarse = eps("bounded-8-8-8-28");
    assert!(coarse[0] > d[0], "{coarse:?} vs {d:?}");
    // Off the grid of 2 position fraction bits (x = 2^-16): refused naming the coordinate.
    let mut off = enc_setup_in(&t, vp, registry::find("exact-6-6-2").unwrap());
    off.0[0] |= 1;
    let e = kind::run(Kind::Setup, &off.0, None).unwrap_err();
    assert!(e.contains("exact-6-6-2") && e.contains("grid"), "{e}");
    // The exact sample test refuses a bounded setup.
    let s = enc_setup_in(&t, vp, registry::DEFAULT).0;
    let e = kind::run(Kind::Sample, &[0, 0, 0, 0, 0, 0], Some(&s)).unwrap_err();
    assert!(e.contains("exact sample test"), "{e}");
}

#[test]
fn architectural_fields_come_first_and_arch_only_compares_exactly_them() {
    let l = layout("setup_out", 0);
    let arch: Vec<_> = l
        .fields
        .iter()
        .filter(|f| SETUP_ARCHITECTURAL.contains(&f.name.as_str()))
        .collect();
    assert_eq!(
        arch.len(),
        SETUP_ARCHITECTURAL.len(),
        "every name is a field"
    );
    assert!(arch.iter().all(|f| f.word < 24));
    assert!(l
        .fields
        .iter()
        .filter(|f| f.word >= 24)
        .all(|f| f.name.starts_with("lens_") || f.name.starts_with("dual_")));
    let vp = Viewport::new(64, 48).unwrap();
    let s = enc_setup_in(&tri(), vp, registry::DEFAULT).0;
    let out = kind::run(Kind::Setup, &s, None).unwrap().0;
    let only = Kind::Setup.architectural();
    // A changed Laine coefficient (last word) passes in architectural mode, not in full.
    let mut coef = out.clone();
    *coef.last_mut().unwrap() ^= 1;
    assert!(kind::diff("setup_out", &out, &coef, only).is_empty());
    assert_eq!(kind::diff("setup_out", &out, &coef, None).len(), 1);
    // A changed epsilon fails in both, naming it.
    let mut e = out.clone();
    e[21] ^= 1;
    let d = kind::diff("setup_out", &out, &e, only);
    assert!(d.len() == 1 && d[0].starts_with("field eps_x"), "{d:?}");
}
