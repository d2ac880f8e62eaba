//! The committed vector sets (`vectors/unit`, `vectors/unit_exact`, `vectors/frame_a`,
//! `vectors/frame_b`): their seed
//! and scenes, and the exports that write them ([`export_default`]) or a set for any scene file
//! ([`export_scene`]).

use std::path::Path;

use anyhow::Result;

use uvt_core::bounds::strategy::BoundsStrategy;
use uvt_core::config::registry::{self, Config};
use uvt_core::Laine2011;

use crate::scene::file::Scene;

use super::export;

/// Default seed of the committed unit-level set.
pub const DEFAULT_SEED: u64 = 1;

/// The committed sets with sample-test records, as folders of `vectors/`.
pub const SETS: [&str; 4] = ["unit", "unit_exact", "frame_a", "frame_b"];

/// Frame-level scene A: static and moving triangles, in focus (32×32, 4 spp, 2×2 bounds tiles).
pub const FRAME_A: &str = r#"{"format":"uvt-scene","version":1,"viewport":[32,32],"spp":4,"tile":2,
 "samples":{"pattern":"sobol","seed":3},
 "triangles":[
  {"t0":[[-1.2,-1.0,0.9,2.0],[1.2,-1.0,0.9,2.0],[0.0,0.2,0.9,2.0]],"color":[90,110,80]},
  {"t0":[[-0.9,-0.2,0.3,1.0],[-0.5,-0.25,0.3,1.0],[-0.7,0.3,0.3,1.0]],"t1":[[0.3,-0.1,0.35,1.1],[0.7,-0.15,0.35,1.1],[0.5,0.4,0.35,1.1]],"color":[230,60,40]},
  {"t0":[[0.1,0.3,0.4,1.5],[0.6,0.35,0.4,1.5],[0.35,0.9,0.4,1.5]],"t1":[[0.1,-0.3,0.4,1.5],[0.6,-0.25,0.4,1.5],[0.35,0.3,0.4,1.5]],"color":[40,120,230]},
  {"t0":[[0.6,0.35,0.4,1.5],[0.35,0.9,0.4,1.5],[0.9,0.9,0.4,1.5]],"t1":[[0.6,-0.25,0.4,1.5],[0.35,0.3,0.4,1.5],[0.9,0.3,0.4,1.5]],"color":[40,200,230]},
  {"t0":[[3.0,3.0,0.5,1.0],[4.0,3.0,0.5,1.0],[3.0,4.0,0.5,1.0]],"color":[255,0,0]}
 ]}"#;

/// Frame-level scene B: motion and defocus together, one triangle crossing the camera plane
/// (32×32, 4 spp, 1×1 bounds tiles).
pub const FRAME_B: &str = r#"{"format":"uvt-scene","version":1,"viewport":[32,32],"spp":4,"tile":1,
 "samples":{"pattern":"sobol","seed":5},"coc":[0.04,-0.08],
 "triangles":[
  {"t0":[[-1.4,-1.1,1.0,2.5],[1.4,-1.1,1.0,2.5],[0.0,0.4,1.0,2.5]],"t1":[[-1.2,-1.1,1.0,2.5],[1.6,-1.1,1.0,2.5],[0.2,0.4,1.0,2.5]],"color":[110,120,100]},
  {"t0":[[-0.8,-0.3,0.2,0.8],[-0.4,-0.3,0.2,0.8],[-0.6,0.1,0.2,0.8]],"t1":[[0.2,0.0,0.3,1.2],[0.6,0.0,0.3,1.2],[0.4,0.4,0.3,1.2]],"color":[240,200,40]},
  {"t0":[[-0.3,0.2,0.1,0.6],[0.3,0.2,0.1,0.6],[0.0,0.6,0.1,0.6]],"t1":[[-0.3,0.2,0.1,-0.4],[0.3,0.2,0.1,-0.4],[0.0,0.6,0.1,-0.2]],"color":[200,60,220]},
  {"t0":[[0.2,-0.8,0.5,1.6],[0.9,-0.7,0.5,1.6],[0.5,-0.1,0.5,1.6]],"color":[70,140,220]}
 ]}"#;

/// Export into `dir` the unit-level set and the two frame-level sets at configuration `cfg`
/// (`unit/`, `frame_a/`, `frame_b/`); without one, the committed sets: those at the default
/// configuration and the unit-level set at the exact one (`unit_exact/`, whose `sample_*`
/// records are the exact sample test's).
pub fn export_default(dir: &Path, seed: u64, cfg: Option<Config>) -> Result<()> {
    let at = cfg.unwrap_or(registry::DEFAULT);
    let unit = export::unit(seed, at)?;
    export::write(&unit, &dir.join("unit"), "unit", seed)?;
    if cfg.is_none() {
        let exact = export::unit(seed, registry::EXACT)?;
        export::write(&exact, &dir.join("unit_exact"), "unit", seed)?;
    }
    for (name, text) in [("frame_a", FRAME_A), ("frame_b", FRAME_B)] {
        let scene = Scene::parse(text, name, Path::new("."))?;
        let set = export::frame(&scene, text, at, Laine2011.name())?;
        export::write(&set, &dir.join(name), "frame", scene.seed)?;
    }
    Ok(())
}

/// Export into `dir` frame-level vectors of `scene`, loaded from the scene file `path` under the
/// options `uvt render` takes (`--spp`, `--tile`, `--viewport`), with bounds strategy `strategy`
/// (a name of [`STRATEGIES`](uvt_core::bounds::registry::STRATEGIES)) at configuration `cfg`:
/// what `uvt render` runs with the same options ([`export::frame`]). The set's `scene.json` is
/// the file's text when the options leave its viewport, samples per pixel and bounds tile as
/// they are; otherwise the scene as it ran ([`Scene::to_json`]: direct form, the options
/// applied).
pub fn export_scene(
    path: &Path,
    scene: &Scene,
    dir: &Path,
    cfg: Config,
    strategy: &'static str,
) -> Result<()> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| anyhow::anyhow!("cannot read scene file {}: {e}", path.display()))?;
    let file = Scene::load(path)?;
    let ran = |s: &Scene| (s.viewport, s.spp, s.tile);
    let text = if ran(&file) == ran(scene) {
        text
    } else {
        let mut j = scene.to_json();
        j["description"] = serde_json::json!(format!(
            "scene file {} as uvt vectors export ran it: viewport {}x{}, {} spp, bounds tile {}",
            path.display(),
            scene.viewport.0,
            scene.viewport.1,
            scene.spp,
            scene.tile
        ));
        serde_json::to_string(&j)? + "\n"
    };
    let set = export::frame(scene, &text, cfg, strategy)?;
    export::write(&set, dir, "frame", scene.seed)
}
