//! Scene-file parsing at the library level: strict keys, one integer reader, warnings, the
//! memory budget and the exported built-in scenes reading back bit for bit.

use std::path::Path;

use uvt_host::scene::file::{LoadOpts, Scene};

const BASE: &str = r#""format":"uvt-scene","version":1"#;

fn parse(body: &str) -> anyhow::Result<uvt_host::scene::file::Loaded> {
    Scene::parse_with(
        &format!("{{{BASE},{body}}}"),
        "t",
        Path::new("."),
        &LoadOpts::default(),
    )
}

fn err(body: &str) -> String {
    match parse(body) {
        Ok(_) => panic!("accepted: {body}"),
        Err(e) => format!("{e:#}"),
    }
}

const TRI: &str = r#"{"t0":[[-0.5,-0.5,0.5,1],[0.5,-0.5,0.5,1],[0,0.5,0.5,1]]}"#;

#[test]
fn unknown_keys_name_the_path_and_the_nearest_key() {
    let cases = [
        (format!(r#""viewport":[8,8],"sp":4,"triangles":[{TRI}]"#), "sp: unknown key; did you mean \"spp\"?"),
        (
            r#""viewport":[8,8],"triangles":[{"t0":[[0,0,0,1],[1,0,0,1],[0,1,0,1]],"colour":[1,2,3]}]"#.into(),
            "triangles[0].colour: unknown key; did you mean \"color\"?",
        ),
        (
            format!(r#""viewport":[8,8],"samples":{{"sead":3}},"triangles":[{TRI}]"#),
            "samples.sead: unknown key; did you mean \"seed\"?",
        ),
        (
            r#""viewport":[8,8],"camera":{"t0":{}},"meshes":[{"sphere":{"segmnets":12}}]"#.into(),
            "meshes[0].sphere.segmnets: unknown key; did you mean \"segments\"?",
        ),
        (
            r#""viewport":[8,8],"camera":{"fovy":50,"t0":{}},"meshes":[]"#.into(),
            "camera.fovy: unknown key; did you mean \"fov_y\"?",
        ),
        (
            r#""viewport":[8,8],"camera":{"t0":{"eye":[0,0,1],"taget":[0,0,0]}},"meshes":[]"#.into(),
            "camera.t0.taget: unknown key; did you mean \"target\"?",
        ),
        (
            r#""viewport":[8,8],"camera":{"t0":{}},"meshes":[{"sphere":{},"model":{"scael":2}}]"#.into(),
            "meshes[0].model.scael: unknown key; did you mean \"scale\"?",
        ),
        (
            format!(r#""viewport":[8,8],"xyzzy":1,"triangles":[{TRI}]"#),
            "xyzzy: unknown key; known keys: format, version",
        ),
    ];
    for (body, want) in cases {
        let e = err(&body);
        assert!(
            e.contains(want),
            "{body}\n  message: {e}\n  expected: {want}"
        );
    }
}

#[test]
fn duplicate_keys_are_errors() {
    for (body, want) in [
        (
            format!(r#""viewport":[8,8],"spp":4,"spp":16,"triangles":[{TRI}]"#),
            "the scene: duplicate key \"spp\"",
        ),
        (
            r#""viewport":[8,8],"camera":{"t0":{}},"meshes":[{"sphere":{"segments":8,"segments":9}}]"#.into(),
            "meshes[0].sphere: duplicate key \"segments\"",
        ),
    ] {
        let e = err(&body);
        assert!(e.contains(want) && e.contains("line 1"), "{e}");
    }
}

#[test]
fn integers_are_read_alike_everywhere() {
    // 4 and 4.0 are the same number everywhere...
    let a = parse(&format!(
        r#""viewport":[8,6],"spp":4,"tile":2,"triangles":[{TRI}]"#
    ))
    .unwrap();
    let b = parse(&format!(
        r#""viewport":[8.0,6.0],"spp":4.0,"tile":2.0,"samples":{{"seed":0.0}},"triangles":[{TRI}]"#
    ))
    .unwrap();
    assert_eq!(
        (a.scene.viewport, a.scene.spp, a.scene.tile),
        (b.scene.viewport, b.scene.spp, b.scene.tile)
    );
    assert_eq!(b.scene.spp, 4);
    // ...and a fraction is refused everywhere, with the same wording.
    for (field, body) in [
        ("viewport[0]", r#""viewport":[8.5,6]"#.to_string()),
        ("spp", r#""viewport":[8,6],"spp":4.5"#.into()),
        (
            "samples.seed",
            r#""viewport":[8,6],"samples":{"seed":1.5}"#.into(),
        ),
        ("version", r#""viewport":[8,6],"version":1.5"#.into()),
    ] {
        let body = if field == "version" {
            // replace the version given by BASE
            let e = format!("{{\"format\":\"uvt-scene\",{body},\"triangles\":[{TRI}]}}");
            let e = Scene::parse(&e, "t", Path::new(".")).unwrap_err();
            assert!(format!("{e:#}").contains("version"), "{e:#}");
            continue;
        } else {
            format!("{body},\"triangles\":[{TRI}]")
        };
        let e = err(&body);
        assert!(
            e.starts_with(&format!("{field}: ")) && e.contains("whole number"),
            "{e}"
        );
    }
    let e = err(
        r#""viewport":[8,6],"triangles":[{"t0":[[0,0,0,1],[1,0,0,1],[0,1,0,1]],"color":[1,2,3.5]}]"#,
    );
    assert!(
        e.contains("triangles[0].color[2]") && e.contains("whole number"),
        "{e}"
    );
    let e = err(r#""viewport":[8,6],"camera":{"t0":{}},"meshes":[{"sphere":{"segments":12.5}}]"#);
    assert!(
        e.contains("meshes[0].sphere.segments") && e.contains("whole number"),
        "{e}"
    );
    // Mesh colors were clamped silently before; now they are checked like triangle colors.
    let e =
        err(r#""viewport":[8,6],"camera":{"t0":{}},"meshes":[{"sphere":{},"color":[300,0,0]}]"#);
    assert!(e.contains("meshes[0].color[0]"), "{e}");
}

#[test]
fn empty_triangle_list_is_a_warning() {
    let l = parse(r#""viewport":[8,6],"triangles":[]"#).unwrap();
    assert!(l.scene.tris.is_empty());
    assert_eq!(l.warnings.len(), 1);
    assert!(l.warnings[0].contains("triangles") && l.warnings[0].contains("empty"));
    let l = parse(r#""viewport":[8,6],"camera":{"t0":{}},"meshes":[]"#).unwrap();
    assert!(l.warnings[0].starts_with("meshes"));
    assert!(parse(&format!(r#""viewport":[8,6],"triangles":[{TRI}]"#))
        .unwrap()
        .warnings
        .is_empty());
}

#[test]
fn mesh_entries_need_exactly_one_shape() {
    let e = err(
        r#""viewport":[8,6],"camera":{"t0":{}},"meshes":[{"sphere":{},"grid":{"size":[1,1],"cells":[1,1]}}]"#,
    );
    assert!(
        e.contains("meshes[0]: give one of obj, grid, sphere, not grid and sphere"),
        "{e}"
    );
    let e = err(r#""viewport":[8,6],"camera":{"t0":{}},"meshes":[{"obj":3}]"#);
    assert!(e.contains("meshes[0].obj: expected a file name"), "{e}");
    let e = err(r#""viewport":[8,6],"coc":[0,0],"camera":{"t0":{}},"meshes":[]"#);
    assert!(e.starts_with("coc: not used with meshes"), "{e}");
}

#[test]
fn per_vertex_coc_overrides_the_global_one() {
    let l = parse(
        r#""viewport":[8,6],"coc":[0.5,0.25],"triangles":[{"t0":[[0,0,0,2],[1,0,0,2,0.125],[0,1,0,2]]}]"#,
    )
    .unwrap();
    let t = l.scene.tris[0];
    assert_eq!([t.t0[0][4], t.t0[1][4], t.t0[2][4]], [1.25, 0.125, 1.25]);
    let e = err(r#""viewport":[8,6],"triangles":[{"t0":[[0,0,0,2],[1,0,0],[0,1,0,2]]}]"#);
    assert!(
        e.contains("triangles[0].t0[1]: expected 4 numbers, got 3 (or 5"),
        "{e}"
    );
}

#[test]
fn memory_budget_refuses_before_allocating() {
    // The issue's examples: each would allocate gigabytes; each is refused at once, naming the
    // mesh and the estimate.
    for (mesh, path, tris) in [
        (
            r#"{"sphere":{"segments":4096}}"#,
            "meshes[0].sphere",
            "16769024 triangles",
        ),
        (
            r#"{"grid":{"size":[1,1],"cells":[2048,2048]}}"#,
            "meshes[0].grid",
            "8388608 triangles",
        ),
    ] {
        let e = err(&format!(
            r#""viewport":[320,180],"camera":{{"t0":{{}}}},"meshes":[{mesh}]"#
        ));
        assert!(
            e.starts_with(path)
                && e.contains(tris)
                && e.contains("GiB")
                && e.contains("--mem-budget"),
            "{e}"
        );
    }
    // Running totals: two meshes that fit alone but not together name the second one.
    let opts = LoadOpts {
        mem_budget: uvt_host::scene::budget::estimate(2000, (8, 6), 16),
        ..LoadOpts::default()
    };
    let two = format!(
        r#"{{{BASE},"viewport":[8,6],"camera":{{"t0":{{}}}},"meshes":[{{"grid":{{"size":[1,1],"cells":[30,30]}}}},{{"grid":{{"size":[1,1],"cells":[30,30]}}}}]}}"#
    );
    let e = Scene::parse_with(&two, "t", Path::new("."), &opts).unwrap_err();
    assert!(
        format!("{e}").starts_with("meshes[1].grid: 3600 triangles"),
        "{e}"
    );
    // The direct form is checked too.
    let opts = LoadOpts {
        mem_budget: 1000,
        ..LoadOpts::default()
    };
    let e = Scene::parse_with(
        &format!(r#"{{{BASE},"viewport":[8,6],"triangles":[{TRI}]}}"#),
        "t",
        Path::new("."),
        &opts,
    )
    .unwrap_err();
    assert!(format!("{e}").starts_with("triangles: 1 triangles"), "{e}");
}

#[test]
fn obj_files_must_be_regular_and_small() {
    let dir = tempfile::tempdir().unwrap();
    let scene = |obj: &str| {
        format!(
            r#"{{{BASE},"viewport":[8,6],"camera":{{"t0":{{}}}},"meshes":[{{"obj":"{obj}"}}]}}"#
        )
    };
    let e = Scene::parse(&scene("/dev/zero"), "t", dir.path()).unwrap_err();
    assert!(
        format!("{e:#}")
            .contains("meshes[0].obj: cannot read OBJ file /dev/zero: not a regular file"),
        "{e:#}"
    );
    // A sparse file over the limit: refused from its size, never read.
    let big = dir.path().join("big.obj");
    std::fs::File::create(&big)
        .unwrap()
        .set_len(uvt_host::scene::budget::FILE_MAX_BYTES + 1)
        .unwrap();
    let e = Scene::parse(&scene("big.obj"), "t", dir.path()).unwrap_err();
    assert!(
        format!("{e:#}").contains("big.obj is 256.00 MiB (limit 256.00 MiB)"),
        "{e:#}"
    );
    // A material library is not followed.
    std::fs::write(
        dir.path().join("q.obj"),
        "mtllib /dev/zero\nv 0 0 -3\nv 1 0 -3\nv 0 1 -3\nf 1 2 3\n",
    )
    .unwrap();
    let l = Scene::parse_with(&scene("q.obj"), "t", dir.path(), &LoadOpts::default()).unwrap();
    assert_eq!(l.scene.tris.len(), 1);
}

#[test]
fn exported_builtin_scenes_read_back_bit_for_bit() {
    for s in [
        uvt_host::scene::builtin::default_scene(),
        uvt_host::scene::builtin::bench_scene(
            uvt_host::scene::builtin::Bench::Game,
            uvt_host::scene::builtin::Blur::Both,
            true,
        ),
    ] {
        let text = serde_json::to_string(&s.to_json()).unwrap();
        let back = Scene::parse(&text, &s.name, Path::new(".")).unwrap();
        assert_eq!(back.viewport, s.viewport);
        assert_eq!((back.spp, back.tile, back.seed), (s.spp, s.tile, s.seed));
        assert_eq!(back.pattern, s.pattern);
        assert_eq!(back.tris.len(), s.tris.len());
        for (i, (a, b)) in s.tris.iter().zip(&back.tris).enumerate() {
            let bits = |t: &uvt_host::scene::tri::SceneTri| {
                t.t0.iter()
                    .chain(&t.t1)
                    .flat_map(|v| v.map(f64::to_bits))
                    .collect::<Vec<_>>()
            };
            assert_eq!(bits(a), bits(b), "{} triangle {i}", s.name);
            assert_eq!(a.color, b.color);
        }
    }
}
