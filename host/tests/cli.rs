//! End-to-end tests of the `uvt` binary: a small scene renders to every promised file with a
//! report whose numbers add up; every class of bad input exits non-zero with a message naming
//! the field, and writes nothing.

use std::path::Path;
use std::process::Command;

use serde_json::Value;

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
    // Truncate a file: non-zero exit naming it.
    let f = out.join("sample_in.hex");
    let t = std::fs::read_to_string(&f).unwrap();
    std::fs::write(&f, &t[..t.len() - 10]).unwrap();
    let o = uvt(&["vectors", "check", out.to_str().unwrap()]);
    assert!(!o.status.success());
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        e.contains("sample_in.hex") && e.contains("corrupted or truncated"),
        "{e}"
    );
}
