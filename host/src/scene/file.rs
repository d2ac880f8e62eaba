//! Scene files (JSON, `"format":"uvt-scene"`, version 1) and the conversion to the core.
//!
//! Direct form — clip space, what every tool accepts:
//! `{"format":"uvt-scene","version":1,"viewport":[W,H],"spp":S,"tile":1,
//!   "samples":{"pattern":"sobol","seed":0},"coc":[a,b],
//!   "triangles":[{"t0":[[x,y,z,w],…×3],"t1":[…],"color":[r,g,b]}]}`
//! `t1` absent means static; `coc` absent means in focus (CoC = a·w + b per vertex and end); a
//! vertex of five numbers `[x,y,z,w,coc]` gives its CoC directly. An optional `"description"`
//! string is ignored.
//!
//! Convenience form — `"camera"` and `"meshes"` instead of `"triangles"`, see [`super::mesh`].
//! The format is documented for users in `host/scenes/README.md`.
//!
//! Every value is checked before anything is computed or written; a message names the field
//! (as a JSON path, with the triangle index) and what is wrong. Unknown and duplicate keys are
//! errors ([`super::json`]); the estimated memory must fit the budget ([`super::budget`]).

use std::path::Path;

use anyhow::{anyhow, bail, Context, Result};
use serde_json::{json, Value};
use uvt_core::{Triangle, Viewport};

use super::json::{self, color, num_array};
use super::pattern::{Pattern, PatternKind};
use super::tri::{check_domain, SceneTri};
use super::{budget, mesh};

/// A validated scene.
#[derive(Clone, Debug)]
pub struct Scene {
    /// name for reports
    pub name: String,
    /// viewport (W, H)
    pub viewport: (u16, u16),
    /// samples per pixel
    pub spp: u16,
    /// bounds tile size 1, 2, 4 or 8
    pub tile: u8,
    /// pattern kind
    pub pattern: PatternKind,
    /// pattern seed
    pub seed: u64,
    /// triangles (exact f64 values, used by the reference)
    pub tris: Vec<SceneTri>,
}

impl Scene {
    /// A scene built in code (a built-in one) under the options a scene file is loaded with:
    /// `opts`' viewport and samples per pixel replace its own, then the memory budget check every
    /// scene passes ([`budget::check`]; a file's while it is read).
    pub fn with_opts(mut self, opts: &LoadOpts) -> Result<Scene> {
        self.viewport = opts.viewport.unwrap_or(self.viewport);
        self.spp = opts.spp.unwrap_or(self.spp);
        budget::check(
            self.tris.len() as u64,
            self.viewport,
            self.spp,
            opts.mem_budget,
        )
        .map_err(|e| anyhow!("built-in scene {}: {e}", self.name))?;
        Ok(self)
    }

    /// The core viewport.
    pub fn core_viewport(&self) -> Viewport {
        Viewport::new(self.viewport.0, self.viewport.1).expect("validated viewport")
    }

    /// Core triangles (validated at load, so this cannot fail for a loaded scene).
    pub fn core_tris(&self) -> Result<Vec<Triangle>> {
        self.tris
            .iter()
            .enumerate()
            .map(|(i, t)| t.to_core().map_err(|e| anyhow!("triangles[{i}]: {e}")))
            .collect()
    }

    /// The core's inputs at precision `P` — the triangles rounded to nearest on its position
    /// grid and the sample table on its t/u/v grid — as every command running the core at a
    /// configuration takes them (`uvt render`, `uvt fit`, `uvt precision`, the frame vectors).
    pub fn inputs_at<P: uvt_core::Precision>(&self) -> Result<(Vec<Triangle>, Pattern)> {
        let core = self
            .tris
            .iter()
            .enumerate()
            .map(|(i, t)| {
                t.to_core_with::<P>()
                    .map_err(|e| anyhow!("triangles[{i}]: {e}"))
            })
            .collect::<Result<Vec<_>>>()?;
        let pat = Pattern::new(self.pattern, self.spp, self.seed).with_tuv(P::TUV_FRAC);
        Ok((core, pat))
    }

    /// Flat colors of the triangles, in order.
    pub fn colors(&self) -> Vec<[u8; 3]> {
        self.tris.iter().map(|t| t.color).collect()
    }

    /// A built-in scene: 16 spp, 1×1 bounds tiles, Sobol seed 0.
    pub fn builtin(name: impl Into<String>, viewport: (u16, u16), tris: Vec<SceneTri>) -> Scene {
        Scene {
            name: name.into(),
            viewport,
            spp: 16,
            tile: 1,
            pattern: PatternKind::Sobol,
            seed: 0,
            tris,
        }
    }

    /// Load and validate a scene file with the default options (warnings are dropped).
    pub fn load(path: &Path) -> Result<Scene> {
        Scene::load_with(path, &LoadOpts::default()).map(|l| l.scene)
    }

    /// Load and validate a scene file (a regular file of at most
    /// [`budget::FILE_MAX_BYTES`]); errors name the file.
    pub fn load_with(path: &Path, opts: &LoadOpts) -> Result<Loaded> {
        let bytes = budget::read_limited(path, budget::FILE_MAX_BYTES, "scene file")?;
        let text = String::from_utf8(bytes)
            .map_err(|_| anyhow!("scene file {}: not UTF-8 text", path.display()))?;
        let name = path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_else(|| "scene".into());
        let base = path.parent().map(|p| p.to_path_buf()).unwrap_or_default();
        Scene::parse_with(&text, &name, &base, opts)
            .with_context(|| format!("scene file {}", path.display()))
    }

    /// Parse and validate scene JSON with the default options. `base` resolves relative mesh
    /// paths.
    pub fn parse(text: &str, name: &str, base: &Path) -> Result<Scene> {
        Scene::parse_with(text, name, base, &LoadOpts::default()).map(|l| l.scene)
    }

    /// Parse and validate scene JSON: strict keys, the memory budget, the overrides of `opts`.
    pub fn parse_with(text: &str, name: &str, base: &Path, opts: &LoadOpts) -> Result<Loaded> {
        let v = json::parse_strict(text)?;
        let obj = json::object(&v, "", TOP_KEYS)?;
        match obj.get("format").and_then(Value::as_str) {
            Some("uvt-scene") => {}
            _ => bail!(
                "format: expected \"uvt-scene\", got {}",
                json::show(obj.get("format"))
            ),
        }
        match obj.get("version") {
            Some(x) if json::integer(x, "version", 1, 1).is_ok() => {}
            x => bail!(
                "version: unknown version {} (this uvt reads version 1)",
                json::show(x)
            ),
        }
        if let Some(d) = obj.get("description") {
            if !d.is_string() {
                bail!(
                    "description: expected a string, got {}",
                    json::show(Some(d))
                );
            }
        }
        let vp = obj
            .get("viewport")
            .ok_or_else(|| anyhow!("viewport: missing"))?;
        let vp = vp
            .as_array()
            .filter(|a| a.len() == 2)
            .ok_or_else(|| anyhow!("viewport: expected [W, H], got {}", json::show(Some(vp))))?;
        let dim = |i: usize| json::integer(&vp[i], &format!("viewport[{i}]"), 1, 2048);
        let file_viewport = (dim(0)? as u16, dim(1)? as u16);
        let viewport = opts.viewport.unwrap_or(file_viewport);
        let spp = match obj.get("spp") {
            None => 16,
            Some(x) => json::integer(x, "spp", 1, 64)? as u16,
        };
        let spp = opts.spp.unwrap_or(spp);
        let tile = match obj.get("tile") {
            None => 1,
            Some(x) => match json::integer(x, "tile", 1, 8) {
                Ok(t @ (1 | 2 | 4 | 8)) => t as u8,
                _ => bail!("tile: {} is not one of 1, 2, 4, 8", json::show(Some(x))),
            },
        };
        let (pattern, seed) = match obj.get("samples") {
            None => (PatternKind::Sobol, 0),
            Some(s) => {
                let s = json::object(s, "samples", &["pattern", "seed"])?;
                let kind = match s.get("pattern") {
                    None => PatternKind::Sobol,
                    Some(p) => PatternKind::from_name(p.as_str().unwrap_or(""))
                        .map_err(|e| anyhow!("samples.pattern: {e}"))?,
                };
                let seed = match s.get("seed") {
                    None => 0,
                    Some(x) => json::integer(x, "samples.seed", 0, u64::MAX)?,
                };
                (kind, seed)
            }
        };
        let coc = match obj.get("coc") {
            None => None,
            Some(c) => {
                let c = num_array(c, 2, "coc")?;
                Some((c[0], c[1]))
            }
        };
        let check = |tris: u64, field: &str| -> Result<()> {
            budget::check(tris, viewport, spp, opts.mem_budget).map_err(|e| anyhow!("{field}: {e}"))
        };
        let mut warnings = Vec::new();
        let tris = match (obj.get("triangles"), obj.get("meshes")) {
            (Some(t), None) => {
                if obj.contains_key("camera") {
                    bail!("camera: only used with meshes (the triangles are in clip space)");
                }
                let tris = parse_triangles(t, coc, &check)?;
                if tris.is_empty() {
                    warnings.push("triangles: the list is empty; the frame will be blank".into());
                }
                tris
            }
            (None, Some(m)) => {
                if coc.is_some() {
                    bail!("coc: not used with meshes (the camera's aperture and focus set it)");
                }
                let cam = obj
                    .get("camera")
                    .ok_or_else(|| anyhow!("camera: missing (the mesh form needs a camera)"))?;
                let tris = mesh::build(cam, m, viewport, base, &check)?;
                if tris.is_empty() {
                    warnings.push("meshes: no triangles; the frame will be blank".into());
                }
                tris
            }
            (Some(_), Some(_)) => bail!("triangles and meshes: give one of them, not both"),
            (None, None) => bail!("triangles: missing (or give camera and meshes)"),
        };
        check_domain(&tris)?;
        Ok(Loaded {
            scene: Scene {
                name: name.into(),
                viewport,
                spp,
                tile,
                pattern,
                seed,
                tris,
            },
            warnings,
        })
    }

    /// The scene as a direct-form scene file (clip space, per-vertex CoC where non-zero), which
    /// [`Scene::parse`] reads back to the same f64 values bit for bit.
    pub fn to_json(&self) -> Value {
        let vert = |p: &[f64; 5]| {
            if p[4] == 0.0 {
                json!([p[0], p[1], p[2], p[3]])
            } else {
                json!(p)
            }
        };
        let tris: Vec<Value> = self
            .tris
            .iter()
            .map(|t| {
                let mut o = json!({"t0": t.t0.iter().map(vert).collect::<Vec<_>>()});
                if t.t1 != t.t0 {
                    o["t1"] = t.t1.iter().map(vert).collect();
                }
                o["color"] = json!(t.color);
                o
            })
            .collect();
        json!({
            "format": "uvt-scene",
            "version": 1,
            "description": format!("built-in scene {} exported by uvt {}", self.name, env!("CARGO_PKG_VERSION")),
            "viewport": [self.viewport.0, self.viewport.1],
            "spp": self.spp,
            "tile": self.tile,
            "samples": {"pattern": self.pattern, "seed": self.seed},
            "triangles": tris,
        })
    }
}

/// Keys of the top-level scene object.
const TOP_KEYS: &[&str] = &[
    "format",
    "version",
    "description",
    "viewport",
    "spp",
    "tile",
    "samples",
    "coc",
    "triangles",
    "camera",
    "meshes",
];

/// Options of [`Scene::load_with`]: the memory budget and the overrides that change how a
/// scene file is built (the others — tile, pattern, seed — are plain fields of [`Scene`]).
#[derive(Clone, Copy, Debug)]
pub struct LoadOpts {
    /// memory budget in bytes ([`budget::estimate`] must not exceed it)
    pub mem_budget: u64,
    /// viewport instead of the file's (the mesh form projects with its aspect ratio)
    pub viewport: Option<(u16, u16)>,
    /// samples per pixel instead of the file's
    pub spp: Option<u16>,
}

impl Default for LoadOpts {
    fn default() -> Self {
        LoadOpts {
            mem_budget: budget::DEFAULT_MEM_BUDGET,
            viewport: None,
            spp: None,
        }
    }
}

/// A loaded scene and the warnings about it (e.g. an empty triangle list).
#[derive(Clone, Debug)]
pub struct Loaded {
    /// the scene
    pub scene: Scene,
    /// warnings for the user
    pub warnings: Vec<String>,
}

/// Three vertices of 4 numbers `[x,y,z,w]` (CoC from the scene's `coc`) or 5 `[x,y,z,w,coc]`.
fn parse_vertices(v: &Value, field: &str, coc: Option<(f64, f64)>) -> Result<[[f64; 5]; 3]> {
    let a = v
        .as_array()
        .ok_or_else(|| anyhow!("{field}: expected 3 vertices [x,y,z,w]"))?;
    if a.len() != 3 {
        bail!("{field}: expected 3 vertices, got {}", a.len());
    }
    let mut out = [[0.0; 5]; 3];
    for (k, (src, dst)) in a.iter().zip(out.iter_mut()).enumerate() {
        let f = format!("{field}[{k}]");
        let n = match src.as_array().map(Vec::len) {
            Some(5) => num_array(src, 5, &f)?,
            _ => {
                let mut n = num_array(src, 4, &f)
                    .map_err(|e| anyhow!("{e} (or 5 with the vertex's CoC)"))?;
                n.push(coc.map_or(0.0, |(a, b)| a * n[3] + b));
                n
            }
        };
        dst.copy_from_slice(&n);
    }
    Ok(out)
}

fn parse_triangles(
    v: &Value,
    coc: Option<(f64, f64)>,
    check: &dyn Fn(u64, &str) -> Result<()>,
) -> Result<Vec<SceneTri>> {
    let a = v
        .as_array()
        .ok_or_else(|| anyhow!("triangles: expected an array"))?;
    check(a.len() as u64, "triangles")?;
    let mut out = Vec::with_capacity(a.len());
    for (i, t) in a.iter().enumerate() {
        let f = format!("triangles[{i}]");
        let o = json::object(t, &f, &["t0", "t1", "color"])?;
        let t0 = parse_vertices(
            o.get("t0").ok_or_else(|| anyhow!("{f}.t0: missing"))?,
            &format!("{f}.t0"),
            coc,
        )?;
        let t1 = match o.get("t1") {
            Some(x) => parse_vertices(x, &format!("{f}.t1"), coc)?,
            None => t0,
        };
        let color = match o.get("color") {
            None => [200, 200, 200],
            Some(c) => color(c, &format!("{f}.color"))?,
        };
        out.push(SceneTri { t0, t1, color });
    }
    Ok(out)
}
