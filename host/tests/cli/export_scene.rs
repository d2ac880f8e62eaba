//! `uvt vectors export --scene FILE` takes render's `--bounds`, `--spp`, `--tile` and
//! `--viewport`: the trace is of exactly what `uvt render` ran with the same options (samples
//! tested and covered, resolved pixels); bounds records only for Laine 2011, the RTL bounds
//! unit's strategy; the defaults give the committed frame set byte for byte; bad options are
//! refused by name.

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;

fn uvt(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_uvt"))
        .args(args)
        .output()
        .expect("run uvt")
}

fn ok(args: &[&str]) {
    let o = uvt(args);
    assert!(
        o.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

fn committed(set: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../vectors")
        .join(set)
}

fn json(p: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
}

/// A frame set exported with a non-default strategy, spp and bounds tile, and `uvt render` with
/// the same options: the trace's tested samples (`admitted`, or `inside` for a box-only
/// strategy) and covered samples are render's `samples_tested` and `samples_covered`, its
/// pixels are render's fixed.png; the manifest names strategy and spp; bounds records only for
/// laine2011; every set checks bit for bit.
#[test]
fn scene_export_traces_what_render_ran() {
    let dir = tempfile::tempdir().unwrap();
    let scene = committed("frame_b").join("scene.json");
    let scene = scene.to_str().unwrap();
    // hyper has a per-sample predicate, hull is box-only, laine2011 writes bounds records.
    for (bounds, spp, tile) in [("hyper", 8, 1), ("hull", 16, 4), ("laine2011", 8, 2)] {
        let tag = format!("{bounds} at {spp} spp, tile {tile}");
        let (spp_s, tile_s) = (spp.to_string(), tile.to_string());
        let opts = ["--bounds", bounds, "--spp", &spp_s, "--tile", &tile_s];
        let vec = dir.path().join(format!("v-{bounds}"));
        let out = dir.path().join(format!("r-{bounds}"));
        let mut args = vec!["vectors", "export", "--scene", scene];
        args.extend(opts);
        args.extend(["--out", vec.to_str().unwrap()]);
        ok(&args);
        let mut args = vec!["render", scene];
        args.extend(opts);
        args.extend(["--out", out.to_str().unwrap()]);
        ok(&args);
        ok(&["vectors", "check", vec.to_str().unwrap()]);

        let fixed = &json(&out.join("report.json"))["fixed"];
        let img = image::open(out.join("fixed.png")).unwrap().to_rgb8();
        let trace = std::fs::read_to_string(vec.join("trace.jsonl")).unwrap();
        let (mut tested, mut covered, mut pixels, mut culled_in_box) = (0u64, 0u64, 0u32, 0u64);
        for line in trace.lines() {
            let v: Value = serde_json::from_str(line).unwrap();
            match v["type"].as_str().unwrap() {
                "sample" => {
                    let inside = v["inside"].as_bool().unwrap();
                    let admitted = v.get("admitted").map_or(inside, |a| a.as_bool().unwrap());
                    assert!(
                        inside || !admitted,
                        "{tag}: admitted outside its box: {line}"
                    );
                    culled_in_box += u64::from(inside && !admitted);
                    tested += u64::from(admitted);
                    covered += u64::from(v["covered"].as_bool().unwrap());
                }
                "pixel" => {
                    let (x, y) = (v["px"].as_u64().unwrap(), v["py"].as_u64().unwrap());
                    let rgb: Vec<u64> = v["rgb"]
                        .as_array()
                        .unwrap()
                        .iter()
                        .map(|c| c.as_u64().unwrap())
                        .collect();
                    let want = img.get_pixel(x as u32, y as u32).0.map(u64::from);
                    assert_eq!(rgb, want, "{tag}: pixel ({x},{y})");
                    pixels += 1;
                }
                _ => {}
            }
        }
        assert_eq!(pixels, 32 * 32, "{tag}");
        assert!(tested > 0 && covered > 0, "{tag}");
        assert_eq!(tested, fixed["samples_tested"].as_u64().unwrap(), "{tag}");
        assert_eq!(covered, fixed["samples_covered"].as_u64().unwrap(), "{tag}");
        // The predicate strategy admits fewer samples than its boxes hold; box-only ones all.
        assert_eq!(
            culled_in_box > 0,
            bounds == "hyper",
            "{tag}: {culled_in_box}"
        );

        let m = json(&vec.join("manifest.json"));
        assert_eq!(m["resolve_spp"], spp, "{tag}");
        let s = json(&vec.join("scene.json"));
        assert_eq!(
            (s["spp"].as_u64(), s["tile"].as_u64()),
            (Some(spp), Some(tile))
        );
        let bounds_records = m["files"]["bounds_in.hex"]["records"].as_u64().unwrap();
        if bounds == "laine2011" {
            assert!(m.get("bounds_strategy").is_none(), "{tag}: {m}");
            assert!(bounds_records > 0, "{tag}");
        } else {
            assert_eq!(m["bounds_strategy"], bounds, "{tag}");
            assert!(
                m["bounds_records"].as_str().unwrap().starts_with("none"),
                "{tag}"
            );
            assert_eq!(bounds_records, 0, "{tag}");
        }
    }
}

/// With the default options, and with the scene's own values given explicitly, an export of a
/// committed frame set's scene is that set byte for byte.
#[test]
fn scene_export_defaults_are_the_committed_frame_set() {
    let dir = tempfile::tempdir().unwrap();
    let scene = committed("frame_a").join("scene.json");
    let scene = scene.to_str().unwrap();
    for (name, extra) in [
        ("plain", &[][..]),
        (
            "explicit",
            &[
                "--bounds",
                "laine2011",
                "--spp",
                "4",
                "--tile",
                "2",
                "--viewport",
                "32x32",
            ][..],
        ),
    ] {
        let out = dir.path().join(name);
        let mut args = vec!["vectors", "export", "--scene", scene, "--out"];
        args.push(out.to_str().unwrap());
        args.extend(extra);
        ok(&args);
        let mut n = 0;
        for e in std::fs::read_dir(committed("frame_a")).unwrap() {
            let p = e.unwrap().path();
            let f = p.file_name().unwrap();
            let fresh = std::fs::read(out.join(f)).unwrap_or_default();
            assert!(
                fresh == std::fs::read(&p).unwrap(),
                "{name}: {} differs from the committed set",
                f.to_string_lossy()
            );
            n += 1;
        }
        assert_eq!(std::fs::read_dir(&out).unwrap().count(), n, "{name}");
    }
}

/// An unknown strategy, an spp or tile out of range, and a frame option without --scene: a
/// non-zero exit naming the option, nothing written.
#[test]
fn scene_export_refuses_bad_options() {
    let dir = tempfile::tempdir().unwrap();
    let scene = committed("frame_a").join("scene.json");
    let scene = scene.to_str().unwrap();
    let out = dir.path().join("never");
    let out = out.to_str().unwrap();
    for (args, want) in [
        (
            &["--scene", scene, "--bounds", "laine"][..],
            "--bounds \"laine\": unknown bounds strategy (accepted: bbox, laine2011",
        ),
        (&["--scene", scene, "--spp", "0"][..], "'--spp <SPP>'"),
        (
            &["--scene", scene, "--spp", "65"][..],
            "65 is not in 1..=64",
        ),
        (&["--scene", scene, "--spp", "four"][..], "'--spp <SPP>'"),
        (
            &["--scene", scene, "--tile", "3"][..],
            "--tile 3: not one of 1, 2, 4, 8",
        ),
        (
            &["--scene", scene, "--viewport", "32"][..],
            "--viewport \"32\": expected WxH",
        ),
        (
            &["--bounds", "hyper"][..],
            "--bounds applies to a frame set of one scene: it needs --scene FILE",
        ),
        (
            &["--spp", "8"][..],
            "--spp applies to a frame set of one scene",
        ),
    ] {
        let mut a = vec!["vectors", "export", "--out", out];
        a.extend(args);
        let o = uvt(&a);
        let e = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success() && e.contains(want), "{args:?}: {e}");
        assert!(!Path::new(out).exists(), "{args:?} wrote {out}");
    }
}
