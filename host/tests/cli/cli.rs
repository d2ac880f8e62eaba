//! End-to-end tests of the `uvt` binary: a small scene renders to every promised file with a
//! report whose numbers add up; every class of bad input exits non-zero with a message naming
//! the field, and writes nothing.

use std::path::Path;
use std::process::Command;

use serde_json::Value;
use uvt_core::bounds::registry::STRATEGIES;
use uvt_core::config::registry::{sweep, CONFIGS, DEFAULT};

fn uvt(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_uvt"))
        .args(args)
        .output()
        .expect("run uvt")
}

const SMALL: &str = r#"{"format":"uvt-scene","version":1,"viewport":[32,24],"spp":4,"tile":2,
 "samples":{"pattern":"stratified","seed":7},"coc":[0.02,-0.05],
 "triangles":[
  {"t0":[[-0.8,-0.6,0.5,1.5],[0.6,-0.5,0.5,1.5],[0.0,0.7,0.5,1.5]],"t1":[[-0.4,-0.6,0.6,1.6],[1.0,-0.5,0.6,1.6],[0.4,0.7,0.6,1.6]],"color":[250,40,40]},
  {"t0":[[-1.5,-1.0,0.9,2.0],[1.5,-1.0,0.9,2.0],[0.0,1.2,0.9,2.0]],"color":[40,200,60]},
  {"t0":[[5,5,0,-1],[6,5,0,-1],[5,6,0,-1]],"color":[1,2,3]}
 ]}"#;

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_string_lossy().into_owned()
}

#[test]
fn render_small_scene_end_to_end() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write(dir.path(), "small.json", SMALL);
    let out = dir.path().join("out");
    let o = uvt(&["render", &scene, "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for f in [
        "fixed.png",
        "f64.png",
        "diff.png",
        "heat.png",
        "report.json",
        "report.md",
    ] {
        let p = out.join(f);
        assert!(
            p.metadata().map(|m| m.len() > 0).unwrap_or(false),
            "{f} missing or empty"
        );
    }
    let img = image::open(out.join("fixed.png")).unwrap();
    assert_eq!((img.width(), img.height()), (32, 24));
    let r: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("report.json")).unwrap()).unwrap();
    let n = |v: &Value| v.as_u64().unwrap();
    let c = &r["classes"];
    // 3 triangles: one moving + defocused, one static + defocused, one behind the camera.
    assert_eq!(n(&r["triangles"]), 3);
    assert_eq!(n(&c["motion_defocus"]), 1);
    assert_eq!(n(&c["defocus"]), 1);
    assert_eq!(n(&c["culled_outside"]), 1);
    assert_eq!(
        n(&c["static"])
            + n(&c["motion"])
            + n(&c["defocus"])
            + n(&c["motion_defocus"])
            + n(&c["culled_outside"])
            + n(&c["culled_degenerate"]),
        3
    );
    for p in ["fixed", "f64", "bbox_scan"] {
        let f = &r[p];
        assert!(n(&f["tiles_skipped"]) <= n(&f["tiles_visited"]), "{p}");
        assert!(n(&f["samples_covered"]) <= n(&f["samples_tested"]), "{p}");
        let ste = n(&f["samples_covered"]) as f64 / n(&f["samples_tested"]) as f64;
        assert!(
            (ste - r["ste"][if p == "bbox_scan" {
                "bbox_scan"
            } else if p == "fixed" {
                "uvt_fixed"
            } else {
                "uvt_f64"
            }]
            .as_f64()
            .unwrap())
            .abs()
                < 1e-12
        );
    }
    // Bounds never change coverage: the bbox scan covers exactly what the bounded core covers,
    // and it tests every sample of every footprint.
    assert_eq!(
        n(&r["bbox_scan"]["samples_covered"]),
        n(&r["fixed"]["samples_covered"])
    );
    assert_eq!(
        n(&r["bbox_scan"]["samples_tested"]),
        n(&r["fixed"]["footprint_samples"])
    );
    assert!(n(&r["fixed"]["samples_tested"]) <= n(&r["bbox_scan"]["samples_tested"]));
    assert!(r["ste"]["oracle"].as_f64().unwrap() >= r["ste"]["uvt_fixed"].as_f64().unwrap());
    assert_eq!(n(&r["coverage_fixed_vs_f64"]["beyond_bound"]), 0);
    assert!(std::fs::read_to_string(out.join("report.md"))
        .unwrap()
        .contains("uvt fixed"));
}

#[test]
fn render_mesh_form_with_obj() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        "quad.obj",
        "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nf 1 2 3 4\n",
    );
    let scene = write(
        dir.path(),
        "mesh.json",
        r#"{"format":"uvt-scene","version":1,"viewport":[40,30],"spp":4,
      "camera":{"fov_y":60,"near":0.1,"far":50,"aperture":0.03,"focus":4,
                "t0":{"eye":[0,2,5],"target":[0,0,0]},"t1":{"eye":[0.3,2,5],"target":[0.3,0,0]}},
      "meshes":[{"obj":"quad.obj","model":{"scale":2},"color":[200,200,50]},
                {"sphere":{"radius":0.7,"segments":12},"model":{"translate":[0,0.7,0]},"model_t1":{"translate":[0.5,0.7,0]}},
                {"grid":{"size":[4,4],"cells":[4,4]},"model":{"translate":[0,-0.01,0]}}]}"#,
    );
    let out = dir.path().join("o");
    let o = uvt(&["render", &scene, "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("report.json")).unwrap()).unwrap();
    assert_eq!(
        r["triangles"].as_u64().unwrap(),
        2 + 12 * 6 * 2 - 2 * 12 + 32
    );
    assert!(r["fixed"]["samples_covered"].as_u64().unwrap() > 1000);
}

/// Each bad-input class: (scene text, words the message must contain).
fn bad(text: &str, needles: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    let scene = write(dir.path(), "bad.json", text);
    let out = dir.path().join("out");
    let o = uvt(&["render", &scene, "--out", out.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success(), "accepted bad input: {text}");
    for n in needles {
        assert!(err.contains(n), "message {err:?} lacks {n:?}");
    }
    assert!(
        !out.exists() || std::fs::read_dir(&out).unwrap().next().is_none(),
        "output written for bad input"
    );
}

fn with(field: &str, value: &str) -> String {
    let mut v: Value = serde_json::from_str(SMALL).unwrap();
    let parsed: Value = serde_json::from_str(value).unwrap();
    let mut cur = &mut v;
    let parts: Vec<&str> = field.split('.').collect();
    for (i, p) in parts.iter().enumerate() {
        let last = i + 1 == parts.len();
        cur = match p.parse::<usize>() {
            Ok(k) => &mut cur[k],
            Err(_) => {
                if last {
                    cur[*p] = parsed.clone();
                    return v.to_string();
                }
                &mut cur[*p]
            }
        };
        if last {
            *cur = parsed.clone();
        }
    }
    v.to_string()
}

#[test]
fn bad_malformed_json() {
    bad("{\"format\":\"uvt-scene\",", &["malformed JSON"]);
}
#[test]
fn bad_format_and_version() {
    bad(&with("format", "\"other\""), &["format"]);
    bad(&with("version", "2"), &["version", "unknown version"]);
}
#[test]
fn bad_nan_or_infinity() {
    // JSON has no NaN; a number too large for f64 parses as an error or infinity: refused either way.
    bad(
        &SMALL.replace("-0.8,-0.6,0.5,1.5", "-0.8,-0.6,0.5,1e999"),
        &["number out of range", "line 4"],
    );
    bad(
        &SMALL.replace("-0.8,-0.6,0.5,1.5", "-0.8,-0.6,0.5,NaN"),
        &["malformed JSON"],
    );
}
#[test]
fn bad_array_lengths() {
    bad(
        &with("triangles.0.t0.1", "[1,2,3]"),
        &["triangles[0].t0[1]", "expected 4 numbers"],
    );
    bad(
        &with("triangles.1.t0", "[[0,0,0,1],[1,0,0,1]]"),
        &["triangles[1].t0", "3 vertices"],
    );
    bad(&with("viewport", "[32]"), &["viewport"]);
    bad(&with("triangles.0.color", "[1,2]"), &["triangles[0].color"]);
}
#[test]
fn bad_out_of_domain() {
    bad(
        &with("triangles.1.t0.2", "[0,9000,0,1]"),
        &["triangles[1].t0[2].y", "domain"],
    );
    bad(
        &with("coc", "[0, 9000]"),
        &["triangles[0]", "coc", "domain"],
    );
}
#[test]
fn bad_empty_viewport_and_parameters() {
    bad(&with("viewport", "[0,24]"), &["viewport[0]"]);
    bad(&with("viewport", "[32,4096]"), &["viewport[1]"]);
    bad(&with("spp", "0"), &["spp"]);
    bad(&with("tile", "3"), &["tile"]);
    bad(
        &with("samples", "{\"pattern\":\"halton\"}"),
        &["samples.pattern"],
    );
}
#[test]
fn bad_missing_file() {
    let o = uvt(&["render", "/nonexistent/scene.json", "--out", "/tmp/never"]);
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("cannot read scene file"));
}

#[test]
fn vectors_export_and_check_cli() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write(dir.path(), "small.json", SMALL);
    let out = dir.path().join("v");
    let o = uvt(&[
        "vectors",
        "export",
        "--scene",
        &scene,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = uvt(&["vectors", "check", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains("match the core bit for bit"));
    // At another configuration: the manifest names it, the per-sample records are its test's,
    // and the set checks; an unknown name is refused with the accepted ones.
    let exact = dir.path().join("exact");
    let o = uvt(&[
        "vectors",
        "export",
        "--scene",
        &scene,
        "--config",
        "exact-12-12-8",
        "--out",
        exact.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let m = std::fs::read_to_string(exact.join("manifest.json")).unwrap();
    assert!(m.contains("\"config\": \"exact-12-12-8\""), "{m}");
    assert!(std::fs::read_to_string(exact.join("bsample_in.hex"))
        .unwrap()
        .is_empty());
    assert!(!std::fs::read_to_string(exact.join("sample_in.hex"))
        .unwrap()
        .is_empty());
    let o = uvt(&["vectors", "check", exact.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = uvt(&[
        "vectors",
        "export",
        "--config",
        "exact-9-9-9",
        "--out",
        "/tmp/never",
    ]);
    assert!(!o.status.success());
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        e.contains("--config \"exact-9-9-9\"") && e.contains("bounded-16-16-16-20"),
        "{e}"
    );
    // Truncate a file: non-zero exit naming it.
    let f = out.join("bsample_in.hex");
    let t = std::fs::read_to_string(&f).unwrap();
    std::fs::write(&f, &t[..t.len() - 10]).unwrap();
    let o = uvt(&["vectors", "check", out.to_str().unwrap()]);
    assert!(!o.status.success());
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        e.contains("bsample_in.hex") && e.contains("corrupted or truncated"),
        "{e}"
    );
}

#[test]
fn bad_unknown_and_duplicate_keys_name_the_file() {
    // `"sp": 4` rendered at 16 spp before; now an error naming the key and the nearest one.
    bad(
        &SMALL.replace("\"spp\":4", "\"sp\":4"),
        &["bad.json", "sp: unknown key; did you mean \"spp\"?"],
    );
    bad(
        &SMALL.replace("\"color\":[1,2,3]", "\"colour\":[1,2,3]"),
        &["triangles[2].colour: unknown key; did you mean \"color\"?"],
    );
    bad(
        &SMALL.replace("\"tile\":2", "\"tile\":2,\"tile\":4"),
        &["bad.json", "duplicate key \"tile\""],
    );
}

#[test]
fn bad_resource_limits_fail_fast() {
    let cam = r#""camera":{"t0":{"eye":[0,1,5],"target":[0,0,0]}}"#;
    for (mesh, needles) in [
        (
            r#"{"sphere":{"segments":4096}}"#,
            &[
                "meshes[0].sphere",
                "16769024 triangles",
                "over the memory budget of 4.00 GiB",
            ][..],
        ),
        (
            r#"{"grid":{"size":[4,4],"cells":[2048,2048]}}"#,
            &["meshes[0].grid", "8388608 triangles", "--mem-budget"][..],
        ),
        (
            r#"{"obj":"/dev/zero"}"#,
            &["meshes[0].obj", "/dev/zero", "not a regular file"][..],
        ),
        // A missing file: the reason is named, not only the file.
        (
            r#"{"obj":"/nonexistent/missing.obj"}"#,
            &[
                "meshes[0].obj",
                "cannot read OBJ file /nonexistent/missing.obj",
                "No such file or directory",
            ][..],
        ),
    ] {
        bad(
            &format!(
                r#"{{"format":"uvt-scene","version":1,"viewport":[320,180],{cam},"meshes":[{mesh}]}}"#
            ),
            needles,
        );
    }
    // The budget flag: a tiny budget refuses the small scene, a bad size is named.
    let dir = tempfile::tempdir().unwrap();
    let scene = write(dir.path(), "small.json", SMALL);
    let o = uvt(&[
        "render",
        &scene,
        "--mem-budget",
        "1K",
        "--out",
        "/nonexistent/x",
    ]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && e.contains("triangles: 3 triangles") && e.contains("1.00 KiB"),
        "{e}"
    );
    let o = uvt(&[
        "render",
        &scene,
        "--mem-budget",
        "lots",
        "--out",
        "/nonexistent/x",
    ]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success() && e.contains("--mem-budget"), "{e}");
    // The built-in scene passes the same check: refused at its own size and at 2048×2048, 64 spp
    // (it used to render regardless of the budget), with nothing written.
    for extra in [&[][..], &["--viewport", "2048x2048", "--spp", "64"][..]] {
        let out = dir.path().join("builtin-out");
        let mut args = vec![
            "render",
            "--mem-budget",
            "1M",
            "--out",
            out.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        let o = uvt(&args);
        let e = String::from_utf8_lossy(&o.stderr);
        assert!(
            !o.status.success()
                && e.contains("built-in scene default: ")
                && e.contains("over the memory budget of 1.00 MiB"),
            "{extra:?}: {e}"
        );
        assert!(
            !out.exists(),
            "{extra:?}: the refused render wrote {}",
            out.display()
        );
    }
    let e = String::from_utf8_lossy(
        &uvt(&[
            "render",
            "--mem-budget",
            "1M",
            "--viewport",
            "2048x2048",
            "--spp",
            "64",
            "--out",
            "/nonexistent/x",
        ])
        .stderr,
    )
    .into_owned();
    assert!(e.contains("on 2048×2048 px at 64 spp"), "{e}");
}

#[test]
fn empty_scene_warns_and_renders() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write(
        dir.path(),
        "empty.json",
        r#"{"format":"uvt-scene","version":1,"viewport":[8,8],"spp":1,"triangles":[]}"#,
    );
    let out = dir.path().join("o");
    let o = uvt(&["render", &scene, "--out", out.to_str().unwrap()]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{e}");
    assert!(
        e.contains("warning: ") && e.contains("empty.json") && e.contains("empty"),
        "{e}"
    );
    assert!(out.join("report.md").exists());
}

/// Every name `--precision` accepts, as its error lists them: `default`, then the registry's.
fn precision_names() -> String {
    std::iter::once("default")
        .chain(CONFIGS.iter().map(|e| e.name))
        .collect::<Vec<_>>()
        .join(", ")
}

fn report(dir: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("report.json")).unwrap()).unwrap()
}

#[test]
fn render_options_override_the_scene() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write(dir.path(), "small.json", SMALL);
    let out = dir.path().join("o");
    let o = uvt(&[
        "render",
        &scene,
        "--out",
        out.to_str().unwrap(),
        "--spp",
        "2",
        "--tile",
        "4",
        "--viewport",
        "16x12",
        "--seed",
        "9",
        "--bounds",
        "bbox",
        "--precision",
        "exact-8-8-4",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r = report(&out);
    assert_eq!(r["viewport"], serde_json::json!([16, 12]));
    assert_eq!(
        (r["spp"].as_u64(), r["tile"].as_u64(), r["seed"].as_u64()),
        (Some(2), Some(4), Some(9))
    );
    assert_eq!(
        (r["bounds"].as_str(), r["precision"].as_str()),
        (Some("bbox"), Some("exact-8-8-4"))
    );
    // With bbox bounds the core tests every footprint sample, like the bbox scan.
    assert_eq!(
        r["fixed"]["samples_tested"],
        r["bbox_scan"]["samples_tested"]
    );
    // The comparison checks the core's own bounds (here the bbox scan) at every precision.
    assert_eq!(r["coverage_fixed_vs_f64"]["violations"].as_u64(), Some(0));
    assert_eq!(r["coverage_fixed_vs_f64"]["beyond_bound"].as_u64(), Some(0));
    assert_eq!(image::open(out.join("fixed.png")).unwrap().width(), 16);
    // Bad values list what is accepted.
    let strategies = STRATEGIES.join(", ");
    let configs = precision_names();
    for (args, needles) in [
        (&["--bounds", "laine"][..], &["--bounds", &strategies][..]),
        (
            &["--precision", "10/10/10"][..],
            &["--precision", &configs][..],
        ),
        (
            &["--precision", "exact-9-9-9"][..],
            &["--precision", &configs][..],
        ),
        (&["--viewport", "16*12"][..], &["--viewport", "WxH"][..]),
        (&["--viewport", "0x12"][..], &["--viewport"][..]),
        (&["--spp", "65"][..], &["--spp", "65", "1..=64"][..]),
        // A negative value is a bad value (its real range named), not an option.
        (&["--spp", "-4"][..], &["--spp", "-4", "1..=64"][..]),
        (&["--spp=-4"][..], &["--spp", "-4", "1..=64"][..]),
        (&["--spp", "0"][..], &["--spp", "1..=64"][..]),
        (&["--tile", "3"][..], &["--tile 3"][..]),
        (&["--tile", "-1"][..], &["--tile", "-1"][..]),
    ] {
        let o2 = dir.path().join("never");
        let mut a = vec!["render", scene.as_str(), "--out", o2.to_str().unwrap()];
        a.extend_from_slice(args);
        let o = uvt(&a);
        let e = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success(), "{args:?} accepted");
        for n in needles {
            assert!(e.contains(n), "{args:?}: {e:?} lacks {n:?}");
        }
        assert!(
            !e.contains("0..=65535") && !e.contains("-- -"),
            "{args:?}: {e:?}"
        );
        assert!(!o2.exists());
    }
}

#[test]
fn report_explains_itself_and_nulls_what_is_not_counted() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write(dir.path(), "small.json", SMALL);
    let out = dir.path().join("o");
    let o = uvt(&["render", &scene, "--out", out.to_str().unwrap()]);
    assert!(o.status.success());
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        e.contains("[1/4]") && e.contains("oracle") && e.contains("[4/4] comparing"),
        "{e}"
    );
    let r = report(&out);
    for k in ["ops_setup", "ops_bounds", "ops_sample"] {
        assert!(r["f64"][k].is_null(), "f64.{k} = {}", r["f64"][k]);
        assert!(r["fixed"][k].is_u64(), "fixed.{k}");
    }
    assert!(r["bbox_scan"]["ops_sample"].as_u64().unwrap() > 0);
    assert!(r["fixed"]["ops_sample"].as_u64().unwrap() > 0);
    let md = std::fs::read_to_string(out.join("report.md")).unwrap();
    for n in [
        "`fixed.png`",
        "`f64.png`",
        "`diff.png`",
        "`heat.png`",
        "**STE**",
        "tiles skipped",
        "**Oracle**",
        "**Wall ms**",
    ] {
        assert!(md.contains(n), "report.md lacks {n}");
    }
    // The heat map carries its legend below the map, the 32×24 map enlarged ×8 to a readable
    // size, with white (the scale's maximum) at the right end of the colour bar.
    let heat = image::open(out.join("heat.png")).unwrap().to_rgb8();
    let k = uvt_host::render::diff::scale_for(32, 24);
    assert_eq!(k, 8);
    assert_eq!(
        (heat.width(), heat.height()),
        (32 * k, 24 * k + uvt_host::render::heatmap::LEGEND_H)
    );
    assert_eq!(
        heat.get_pixel(heat.width() - 5, 24 * k + 18).0,
        [255, 255, 255]
    );
}

#[test]
fn example_scenes_render() {
    let dir = tempfile::tempdir().unwrap();
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut n = 0;
    for e in std::fs::read_dir(&scenes).unwrap() {
        let p = e.unwrap().path();
        if !p.extension().is_some_and(|x| x == "json") {
            continue;
        }
        let out = dir.path().join(p.file_stem().unwrap());
        let o = uvt(&[
            "render",
            p.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            o.status.success() && !err.contains("warning"),
            "{}: {err}",
            p.display()
        );
        let r = report(&out);
        assert!(
            r["fixed"]["samples_covered"].as_u64().unwrap() > 0,
            "{}",
            p.display()
        );
        assert_eq!(r["coverage_fixed_vs_f64"]["beyond_bound"].as_u64(), Some(0));
        n += 1;
    }
    assert_eq!(n, 4, "host/scenes holds four example scenes");
}

#[test]
fn scene_export_writes_a_loadable_scene() {
    let dir = tempfile::tempdir().unwrap();
    let o = uvt(&["scene", "list"]);
    let list = String::from_utf8_lossy(&o.stdout);
    assert!(list.lines().any(|l| l == "default") && list.lines().any(|l| l == "dense-both2"));
    // Every listed `-quick` name exports (the full-size ones are the same code at 4× the size);
    // `default` has no quick form.
    assert!(list.lines().any(|l| l == "game-motion-quick"), "{list}");
    assert!(!list.lines().any(|l| l == "default-quick"), "{list}");
    assert_eq!(list.lines().count(), 43, "{list}");
    for name in list.lines().filter(|l| l.ends_with("-quick")) {
        let o = uvt(&[
            "scene",
            "export",
            name,
            "--out",
            dir.path().join("x.json").to_str().unwrap(),
        ]);
        assert!(
            o.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
    }
    let f = dir.path().join("g.json");
    let o = uvt(&[
        "scene",
        "export",
        "game-motion-quick",
        "--out",
        f.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s = uvt_host::scene::file::Scene::load(&f).unwrap();
    let b = uvt_host::scene::builtin::bench_scene(
        uvt_host::scene::builtin::Bench::Game,
        uvt_host::scene::builtin::Blur::Motion,
        true,
    );
    assert_eq!((s.viewport, s.tris.len()), (b.viewport, b.tris.len()));
    assert_eq!(s.tris, b.tris);
    let o = uvt(&["scene", "export", "defualt"]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && e.contains("did you mean \"default\""),
        "{e}"
    );
}

#[test]
fn closed_stdout_exits_quietly() {
    use std::io::Write;
    use std::process::Stdio;
    // Deterministic: the shell waits for a line on stdin before it starts uvt, and the test
    // closes the read end of uvt's stdout before sending it, so every write gets EPIPE (like
    // `uvt vectors layout | head -1` once head has exited).
    for args in [
        &["vectors", "layout"][..],
        &["scene", "export", "default"][..],
    ] {
        let mut c = Command::new("sh")
            .args([
                "-c",
                "read go; exec \"$0\" \"$@\"",
                env!("CARGO_BIN_EXE_uvt"),
            ])
            .args(args)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        drop(c.stdout.take());
        writeln!(c.stdin.take().unwrap(), "go").unwrap();
        let o = c.wait_with_output().unwrap();
        let e = String::from_utf8_lossy(&o.stderr);
        assert!(
            o.status.success() && e.is_empty(),
            "{args:?}: {:?} {e}",
            o.status
        );
    }
}

#[test]
fn bench_ste_prints_row_progress() {
    // At a configuration outside the old `--precision` list (any registry name runs).
    let o = uvt(&[
        "bench-ste",
        "--quick",
        "--scene",
        "game",
        "--row",
        "static",
        "--precision",
        "exact-6-6-2",
    ]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{e}");
    // Plain lines, also when stderr is not a terminal (here: a pipe).
    assert!(
        e.lines().any(|l| l == "bench-ste: row 1 of 1: Game static"),
        "{e}"
    );
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("| GAME |"), "{out}");
    assert!(out.starts_with("Core precision exact-6-6-2\n"), "{out}");
}

#[test]
fn bench_ste_without_the_limit_leaves_its_columns_out() {
    let args = ["bench-ste", "--quick", "--scene", "game", "--row", "static"];
    let o = uvt(&[&args[..], &["--no-limit"]].concat());
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // Not computed is not 0: no limit column, no "0/px" header, no zero-filled cells.
    assert!(out.contains("| GAME |"), "{out}");
    assert!(
        !out.contains("limit") && !out.contains("0/px") && !out.contains("dense box"),
        "{out}"
    );
    let header = out
        .lines()
        .find(|l| l.starts_with("| Scene | Bbox"))
        .unwrap();
    let row = out.lines().find(|l| l.starts_with("| GAME |")).unwrap();
    assert_eq!(
        header.matches('|').count(),
        row.matches('|').count(),
        "{out}"
    );
}

#[test]
fn file_errors_name_their_path() {
    let o = uvt(&["stress", "nosuchdir"]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && e.contains("nosuchdir") && e.contains("No such file"),
        "{e}"
    );
    let dir = tempfile::tempdir().unwrap();
    let file = write(dir.path(), "afile", "x");
    for args in [
        &["render", "--out", file.as_str()][..],
        &["precision", "--quick", "--out", file.as_str()][..],
        &["vectors", "export", "--out", file.as_str()][..],
    ] {
        let o = uvt(args);
        let e = String::from_utf8_lossy(&o.stderr);
        assert!(
            !o.status.success()
                && e.contains(&format!("--out {file}: exists and is not a directory")),
            "{args:?}: {e}"
        );
    }
    let o = uvt(&[
        "render",
        dir.path().to_str().unwrap(),
        "--out",
        "/nonexistent/x",
    ]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && e.contains("not a regular file"),
        "{e}"
    );
}

/// The old `POS/TUV/BND` tuple form of `--precision` is refused by `uvt render` and `uvt
/// bench-ste`, naming every accepted name (and what the tuple is called now); nothing is
/// written.
#[test]
fn precision_tuple_form_is_refused_with_the_names() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("never");
    for args in [
        &[
            "render",
            "--out",
            out.to_str().unwrap(),
            "--precision",
            "16/16/16",
        ][..],
        &["bench-ste", "--quick", "--precision", "16/16/16"][..],
    ] {
        let o = uvt(args);
        let e = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success(), "{args:?} accepted");
        assert!(
            e.contains("--precision \"16/16/16\"") && e.contains(&precision_names()),
            "{args:?}: {e}"
        );
        assert!(
            e.contains(&format!("now default ({DEFAULT})")),
            "{args:?}: {e}"
        );
        assert!(o.stdout.is_empty(), "{args:?}");
    }
    assert!(!out.exists());
}

/// A render of a tiny scene (16×12, 1 spp) with extra options; the report.
fn tiny_render(dir: &Path, scene: &str, name: &str, extra: &[&str]) -> Value {
    let out = dir.join(name);
    let mut a = vec![
        "render",
        scene,
        "--out",
        out.to_str().unwrap(),
        "--viewport",
        "16x12",
        "--spp",
        "1",
    ];
    a.extend_from_slice(extra);
    let o = uvt(&a);
    assert!(
        o.status.success(),
        "{extra:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    report(&out)
}

/// `uvt render --bounds` takes every strategy of the registry (what `bench-ste` and `uvt fit`
/// name), and `--precision` every configuration of the registry and `default`; the report
/// names them. Bounds never change coverage: every strategy covers what the bbox scan covers.
#[test]
fn render_takes_every_strategy_and_configuration() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write(dir.path(), "small.json", SMALL);
    for s in STRATEGIES {
        let r = tiny_render(dir.path(), &scene, s, &["--bounds", s]);
        assert_eq!(r["bounds"].as_str(), Some(s));
        assert_eq!(
            r["fixed"]["samples_covered"], r["bbox_scan"]["samples_covered"],
            "{s}"
        );
        assert!(
            r["fixed"]["samples_tested"].as_u64() <= r["bbox_scan"]["samples_tested"].as_u64(),
            "{s}"
        );
        let md = std::fs::read_to_string(dir.path().join(s).join("report.md")).unwrap();
        let label = match s {
            "laine2011" => "Laine 2011",
            "bbox" => "bounding-box scan",
            other => other,
        };
        assert!(md.contains(&format!("with {label} bounds.")), "{s}: {md}");
    }
    for (name, cfg) in
        std::iter::once(("default", DEFAULT)).chain(CONFIGS.iter().map(|e| (e.name, e.config)))
    {
        let r = tiny_render(
            dir.path(),
            &scene,
            &format!("p-{name}"),
            &["--precision", name],
        );
        assert_eq!(
            r["precision"].as_str(),
            Some(cfg.to_string().as_str()),
            "{name}"
        );
        assert_eq!(
            r["coverage_fixed_vs_f64"]["beyond_bound"].as_u64(),
            Some(0),
            "{name}"
        );
        // Every configuration splits the differences by side and by statement and checks the
        // core's own bounds.
        let c = &r["coverage_fixed_vs_f64"];
        assert_eq!(c["violations"].as_u64(), Some(0), "{name}");
        assert_eq!(c["beyond_statement"].as_u64(), Some(0), "{name}");
        assert_eq!(
            c["differ"].as_u64(),
            Some(c["fixed_only"].as_u64().unwrap() + c["f64_only"].as_u64().unwrap()),
            "{name}"
        );
        assert_eq!(
            c["differ"].as_u64(),
            Some(c["differ_px"].as_u64().unwrap() + c["differ_clip"].as_u64().unwrap()),
            "{name}"
        );
    }
}

/// `uvt bench-ste --precision` takes every configuration of the registry and `default` (checked
/// without running the table: the bad `--row` after it stops the run once `--precision` passed).
#[test]
fn bench_ste_takes_every_configuration() {
    for name in std::iter::once("default").chain(CONFIGS.iter().map(|e| e.name)) {
        let o = uvt(&[
            "bench-ste",
            "--quick",
            "--precision",
            name,
            "--row",
            "nosuch",
        ]);
        let e = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success(), "{name}");
        assert!(e.contains("--row: unknown row \"nosuch\""), "{name}: {e}");
        assert!(!e.contains("--precision"), "{name}: {e}");
    }
}

/// `uvt configs` prints the registry: every configuration with its kind, the sweep's marked;
/// `--sweep` only the sweep's names (what `demo/m4_report.sh --sweep` runs), `--strategies` the
/// bounds strategies.
#[test]
fn configs_prints_the_registries() {
    let text = |args: &[&str]| {
        let o = uvt(args);
        assert!(o.status.success(), "{args:?}");
        String::from_utf8(o.stdout).unwrap()
    };
    let all = text(&["configs"]);
    let lines: Vec<Vec<&str>> = all
        .lines()
        .map(|l| l.split_whitespace().collect())
        .collect();
    assert_eq!(lines.len(), CONFIGS.len(), "{all}");
    for (l, e) in lines.iter().zip(CONFIGS) {
        assert_eq!(l[0], e.name);
        assert_eq!(l[1], e.name.split('-').next().unwrap());
        assert_eq!(l[2] == "sweep", e.sweep, "{all}");
        assert_eq!(l.get(3) == Some(&"default"), e.config == DEFAULT, "{all}");
    }
    let names: Vec<String> = sweep().map(|e| e.name.to_string() + "\n").collect();
    assert_eq!(text(&["configs", "--sweep"]), names.concat());
    assert_eq!(
        text(&["configs", "--strategies"]),
        STRATEGIES.map(|n| n.to_string() + "\n").concat()
    );
}
