//! `diff.png` end to end, on a scene with known differences: a small scene rendered at the
//! narrowest configuration of the sweep, where the core's image and the f64 reference's differ.
//! Every pixel of the written map has the colour of its largest R, G, B difference recomputed
//! from `fixed.png` and `f64.png` (`uvt_host::render::diff`), the map is enlarged to a readable
//! size, a legend strip lies below it, and `report.md`'s caption says what the code does.

use std::process::Command;

use uvt_core::config::registry::sweep;
use uvt_host::render::diff::{diff_color, scale_for, LEGEND_H};

const SCENE: &str = r#"{"format":"uvt-scene","version":1,"viewport":[48,32],"spp":4,"tile":2,
 "samples":{"pattern":"stratified","seed":5},"coc":[0.03,-0.06],
 "triangles":[
  {"t0":[[-0.8,-0.6,0.5,1.5],[0.6,-0.5,0.5,1.5],[0.0,0.7,0.5,1.5]],"t1":[[-0.4,-0.6,0.6,1.6],[1.0,-0.5,0.6,1.6],[0.4,0.7,0.6,1.6]],"color":[250,40,40]},
  {"t0":[[-1.5,-1.0,0.9,2.0],[1.5,-1.0,0.9,2.0],[0.0,1.2,0.9,2.0]],"color":[40,200,60]},
  {"t0":[[-0.3,-0.9,0.3,0.7],[0.9,0.1,0.4,0.9],[-0.6,0.8,0.2,0.6]],"color":[30,60,240]}
 ]}"#;

fn rgb(p: &std::path::Path) -> image::RgbImage {
    image::open(p)
        .unwrap_or_else(|e| panic!("{}: {e}", p.display()))
        .to_rgb8()
}

#[test]
fn diff_png_shows_every_difference_on_its_monotone_scale() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("s.json");
    std::fs::write(&scene, SCENE).unwrap();
    let out = dir.path().join("o");
    let narrowest = sweep().last().unwrap().name;
    let o = Command::new(env!("CARGO_BIN_EXE_uvt"))
        .args(["render", scene.to_str().unwrap(), "--out"])
        .arg(&out)
        .args(["--precision", narrowest])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (fixed, f64i, diff) = (
        rgb(&out.join("fixed.png")),
        rgb(&out.join("f64.png")),
        rgb(&out.join("diff.png")),
    );
    let (w, h) = (fixed.width(), fixed.height());
    assert_eq!((w, h), (48, 32), "fixed.png stays at the viewport's size");
    let k = scale_for(48, 32);
    assert_eq!(k, 6);
    assert_eq!(diff.height(), h * k + LEGEND_H);
    assert!(diff.width() >= w * k);
    let mut differing = 0;
    let mut levels = std::collections::BTreeSet::new();
    for y in 0..h {
        for x in 0..w {
            let (a, b) = (fixed.get_pixel(x, y).0, f64i.get_pixel(x, y).0);
            let d = (0..3).map(|c| a[c].abs_diff(b[c])).max().unwrap();
            differing += usize::from(d > 0);
            levels.insert(d);
            for (dx, dy) in [(0, 0), (k - 1, k - 1)] {
                let got = diff.get_pixel(x * k + dx, y * k + dy).0;
                assert_eq!(
                    got,
                    diff_color(d),
                    "pixel ({x}, {y}): difference {d} ({d:#04x}) levels, colour {got:?}"
                );
            }
        }
    }
    println!(
        "{differing} of {} pixels differ at {narrowest}; levels {levels:?}",
        w * h
    );
    assert!(differing > 0, "the scene has no difference at {narrowest}");
    assert!(levels.len() > 2, "one difference level only: {levels:?}");
    // The legend strip is drawn (caption and scale): some pixel below the map is not background.
    let drawn = (h * k..diff.height())
        .flat_map(|y| (0..diff.width()).map(move |x| (x, y)))
        .filter(|&(x, y)| diff.get_pixel(x, y).0 != [40, 40, 40])
        .count();
    assert!(drawn > 500, "legend: {drawn} drawn pixels");
    let md = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(
        md.contains("largest R, G, B difference")
            && md.contains("strictly")
            && md.contains(&format!("enlarged ×{k}")),
        "{md}"
    );
    assert!(!md.contains("orange"), "{md}");
}
