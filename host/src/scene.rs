//! Scene files (JSON, `"format":"uvt-scene"`, version 1) and the conversion to the core.
//!
//! Direct form — clip space, what every tool accepts:
//! `{"format":"uvt-scene","version":1,"viewport":[W,H],"spp":S,"tile":1,
//!   "samples":{"pattern":"sobol","seed":0},"coc":[a,b],
//!   "triangles":[{"t0":[[x,y,z,w],…×3],"t1":[…],"color":[r,g,b]}]}`
//! `t1` absent means static; `coc` absent means in focus (CoC = a·w + b per vertex and end).
//!
//! Convenience form — `"camera"` and `"meshes"` instead of `"triangles"`, see [`crate::mesh`].
//!
//! Every value is checked before anything is computed or written; a message names the field
//! (as a JSON path, with the triangle index) and what is wrong.

use anyhow::{anyhow, bail, Context, Result};
use serde_json::Value;
use uvt_core::{Coord, Triangle, Vertex, Viewport};

use crate::mesh;

/// Which sample pattern.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum PatternKind {
    /// Owen-scrambled 5D Sobol (Burley 2020), one scramble seed per pixel of the block
    Sobol,
    /// independent uniform random
    Random,
    /// Latin-hypercube stratified per pixel in every dimension
    Stratified,
}

/// One triangle in clip space, f64: `[x, y, z, w, coc]` per vertex at both ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneTri {
    /// shutter open
    pub t0: [[f64; 5]; 3],
    /// shutter close
    pub t1: [[f64; 5]; 3],
    /// flat color
    pub color: [u8; 3],
}

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

/// The core's coordinate domain, in value.
pub const DOMAIN: f64 = 8192.0;

/// Round an f64 to I16F16 (nearest, ties away from zero); the caller has checked the domain.
pub fn quantize(v: f64) -> Coord {
    Coord::from_bits((v * 65536.0).round() as i32)
}

impl SceneTri {
    /// The core triangle (coordinates rounded to nearest I16F16).
    pub fn to_core(&self) -> Result<Triangle, uvt_core::Error> {
        let q = |a: [f64; 5]| Vertex {
            x: quantize(a[0]),
            y: quantize(a[1]),
            z: quantize(a[2]),
            w: quantize(a[3]),
            coc: quantize(a[4]),
        };
        Triangle::new(self.t0.map(q), self.t1.map(q))
    }

    /// The core triangle at precision `P`: coordinates rounded to nearest on `P`'s grid.
    pub fn to_core_with<P: uvt_core::Precision>(&self) -> Result<Triangle, uvt_core::Error> {
        let step = (1i64 << (16 - P::POS_FRAC)) as f64 / 65536.0;
        let q = |x: f64| Coord::from_bits(((x / step).round() * step * 65536.0) as i32);
        let v = |a: [f64; 5]| Vertex {
            x: q(a[0]),
            y: q(a[1]),
            z: q(a[2]),
            w: q(a[3]),
            coc: q(a[4]),
        };
        Triangle::new_with::<P>(self.t0.map(v), self.t1.map(v))
    }

    /// The f64 values the core actually sees (after quantization), for the reference when it is
    /// asked to run on identical inputs.
    pub fn quantized(&self) -> SceneTri {
        let q = |a: [f64; 5]| a.map(|v| quantize(v).to_num::<f64>());
        SceneTri {
            t0: self.t0.map(q),
            t1: self.t1.map(q),
            color: self.color,
        }
    }
}

impl Scene {
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

    /// Load and validate a scene file.
    pub fn load(path: &std::path::Path) -> Result<Scene> {
        let text = std::fs::read_to_string(path)
            .with_context(|| format!("cannot read scene file {}", path.display()))?;
        let name = path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_else(|| "scene".into());
        let base = path.parent().map(|p| p.to_path_buf()).unwrap_or_default();
        Scene::parse(&text, &name, &base).with_context(|| format!("scene file {}", path.display()))
    }

    /// Parse and validate scene JSON. `base` resolves relative mesh paths.
    pub fn parse(text: &str, name: &str, base: &std::path::Path) -> Result<Scene> {
        let v: Value = serde_json::from_str(text).map_err(|e| anyhow!("malformed JSON: {e}"))?;
        let obj = v
            .as_object()
            .ok_or_else(|| anyhow!("the scene must be a JSON object"))?;
        match obj.get("format").and_then(Value::as_str) {
            Some("uvt-scene") => {}
            other => bail!(
                "format: expected \"uvt-scene\", got {}",
                show(other.map(|s| Value::String(s.into())).as_ref())
            ),
        }
        match obj.get("version").and_then(Value::as_u64) {
            Some(1) => {}
            _ => bail!(
                "version: unknown version {} (this uvt reads version 1)",
                show(obj.get("version"))
            ),
        }
        let vp = obj
            .get("viewport")
            .ok_or_else(|| anyhow!("viewport: missing"))?;
        let vp = num_array(vp, 2, "viewport")?;
        let dim = |x: f64, f: &str| -> Result<u16> {
            if x.fract() != 0.0 || !(1.0..=2048.0).contains(&x) {
                bail!("{f}: {x} is not a whole number of pixels in 1..=2048 (the viewport must not be empty)");
            }
            Ok(x as u16)
        };
        let viewport = (dim(vp[0], "viewport[0]")?, dim(vp[1], "viewport[1]")?);
        let spp = match obj.get("spp") {
            None => 16,
            Some(x) => match x.as_u64() {
                Some(s @ 1..=64) => s as u16,
                _ => bail!("spp: {} is not a whole number in 1..=64", show(Some(x))),
            },
        };
        let tile = match obj.get("tile") {
            None => 1,
            Some(x) => match x.as_u64() {
                Some(t @ (1 | 2 | 4 | 8)) => t as u8,
                _ => bail!("tile: {} is not one of 1, 2, 4, 8", show(Some(x))),
            },
        };
        let (pattern, seed) = match obj.get("samples") {
            None => (PatternKind::Sobol, 0),
            Some(s) => {
                let kind = match s.get("pattern").and_then(Value::as_str) {
                    Some("sobol") | None => PatternKind::Sobol,
                    Some("random") => PatternKind::Random,
                    Some("stratified") => PatternKind::Stratified,
                    Some(o) => bail!(
                        "samples.pattern: unknown pattern \"{o}\" (sobol, random, stratified)"
                    ),
                };
                let seed = match s.get("seed") {
                    None => 0,
                    Some(x) => x.as_u64().ok_or_else(|| {
                        anyhow!(
                            "samples.seed: {} is not a non-negative integer",
                            show(Some(x))
                        )
                    })?,
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
        let tris = match (obj.get("triangles"), obj.get("meshes")) {
            (Some(t), None) => parse_triangles(t, coc)?,
            (None, Some(m)) => {
                let cam = obj
                    .get("camera")
                    .ok_or_else(|| anyhow!("camera: missing (the mesh form needs a camera)"))?;
                mesh::build(cam, m, viewport, base)?
            }
            (Some(_), Some(_)) => bail!("triangles and meshes: give one of them, not both"),
            (None, None) => bail!("triangles: missing (or give camera and meshes)"),
        };
        check_domain(&tris)?;
        Ok(Scene {
            name: name.into(),
            viewport,
            spp,
            tile,
            pattern,
            seed,
            tris,
        })
    }
}

fn show(v: Option<&Value>) -> String {
    match v {
        None => "nothing".into(),
        Some(v) => {
            let s = v.to_string();
            if s.len() > 40 {
                format!("{}…", &s[..40])
            } else {
                s
            }
        }
    }
}

/// A JSON array of exactly `n` finite numbers.
pub fn num_array(v: &Value, n: usize, field: &str) -> Result<Vec<f64>> {
    let a = v.as_array().ok_or_else(|| {
        anyhow!(
            "{field}: expected an array of {n} numbers, got {}",
            show(Some(v))
        )
    })?;
    if a.len() != n {
        bail!("{field}: expected {n} numbers, got {}", a.len());
    }
    a.iter()
        .enumerate()
        .map(|(i, x)| {
            let f = x
                .as_f64()
                .ok_or_else(|| anyhow!("{field}[{i}]: {} is not a number", show(Some(x))))?;
            if !f.is_finite() {
                bail!("{field}[{i}]: {f} is not finite (NaN and infinity are refused)");
            }
            Ok(f)
        })
        .collect()
}

fn parse_vertices(v: &Value, field: &str) -> Result<[[f64; 4]; 3]> {
    let a = v
        .as_array()
        .ok_or_else(|| anyhow!("{field}: expected 3 vertices [x,y,z,w]"))?;
    if a.len() != 3 {
        bail!("{field}: expected 3 vertices, got {}", a.len());
    }
    let mut out = [[0.0; 4]; 3];
    for (k, (src, dst)) in a.iter().zip(out.iter_mut()).enumerate() {
        let n = num_array(src, 4, &format!("{field}[{k}]"))?;
        dst.copy_from_slice(&n);
    }
    Ok(out)
}

fn parse_triangles(v: &Value, coc: Option<(f64, f64)>) -> Result<Vec<SceneTri>> {
    let a = v
        .as_array()
        .ok_or_else(|| anyhow!("triangles: expected an array"))?;
    let mut out = Vec::with_capacity(a.len());
    for (i, t) in a.iter().enumerate() {
        let f = format!("triangles[{i}]");
        let o = t
            .as_object()
            .ok_or_else(|| anyhow!("{f}: expected an object with t0, t1, color"))?;
        let t0 = parse_vertices(
            o.get("t0").ok_or_else(|| anyhow!("{f}.t0: missing"))?,
            &format!("{f}.t0"),
        )?;
        let t1 = match o.get("t1") {
            Some(x) => parse_vertices(x, &format!("{f}.t1"))?,
            None => t0,
        };
        let color = match o.get("color") {
            None => [200, 200, 200],
            Some(c) => {
                let n = num_array(c, 3, &format!("{f}.color"))?;
                let mut rgb = [0u8; 3];
                for (j, (x, d)) in n.iter().zip(rgb.iter_mut()).enumerate() {
                    if x.fract() != 0.0 || !(0.0..=255.0).contains(x) {
                        bail!("{f}.color[{j}]: {x} is not a whole number in 0..=255");
                    }
                    *d = *x as u8;
                }
                rgb
            }
        };
        let with_coc = |p: [f64; 4]| {
            [
                p[0],
                p[1],
                p[2],
                p[3],
                coc.map_or(0.0, |(a, b)| a * p[3] + b),
            ]
        };
        out.push(SceneTri {
            t0: t0.map(with_coc),
            t1: t1.map(with_coc),
            color,
        });
    }
    Ok(out)
}

/// Every coordinate and CoC inside the core's domain (after rounding).
pub fn check_domain(tris: &[SceneTri]) -> Result<()> {
    const NAMES: [&str; 5] = ["x", "y", "z", "w", "coc"];
    for (i, t) in tris.iter().enumerate() {
        for (end, verts) in [&t.t0, &t.t1].into_iter().enumerate() {
            for (k, v) in verts.iter().enumerate() {
                for (f, x) in v.iter().enumerate() {
                    if !x.is_finite() {
                        bail!("triangles[{i}].t{end}[{k}].{}: {x} is not finite", NAMES[f]);
                    }
                    if quantize(x.clamp(-1e6, 1e6)).to_bits().unsigned_abs() > 1 << 29
                        || x.abs() > DOMAIN
                    {
                        bail!(
                            "triangles[{i}].t{end}[{k}].{}: {x} is outside the core's domain |v| <= {DOMAIN}",
                            NAMES[f]
                        );
                    }
                }
            }
        }
    }
    Ok(())
}
