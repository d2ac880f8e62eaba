//! The convenience scene form: meshes (Wavefront OBJ through `tobj`, or procedural) with model
//! transforms and a look-at camera at t = 0 and t = 1, a perspective projection and a thin lens,
//! turned into clip-space triangles by the host (f64, glam).
//!
//! `"camera": {"fov_y": 60, "near": 0.1, "far": 100, "aperture": 0.05, "focus": 5,
//!             "focus_range": 2, "t0": {"eye":[..], "target":[..], "up":[0,1,0]}, "t1": {…}}`
//! `"meshes": [{"obj": "file.obj"} | {"grid": {"size":[sx,sz], "cells":[nx,nz]}} |
//!             {"sphere": {"radius": r, "segments": n}},
//!             "model": {"translate":[..], "rotate":[x°,y°,z°], "scale": s}, "model_t1": {…},
//!             "color": [r,g,b]}]`
//!
//! Projection: glam's right-handed perspective (depth z/w ∈ [0, 1], w = view distance).
//! Thin lens with aperture radius A and focus distance F: a lens point u shifts clip x by
//! `u·P00·A·(w/F − 1)`, so CoC(w) = a·w + b with a = P00·A/F, b = −P00·A (signed, affine in w).
//! The same c moves y by v·c, i.e. the lens is scaled by P00/P11 vertically (the core's model).
//! **Focus range** R (Wu et al. 2014's depth of field with an in-focus range): every depth in
//! `[F₀, F₁] = [F − R/2, F + R/2]` is sharp and each side blurs as a thin lens focused at the
//! nearer end: CoC(w) = P00·A·(w/F₀ − 1) for w < F₀, 0 on `[F₀, F₁]`, P00·A·(w/F₁ − 1) for
//! w > F₁ — continuous, piecewise affine, and R = 0 is the plain thin lens. Each vertex takes
//! the CoC of its own w at each shutter end ([`Lens::coc`]); the core interpolates it like every
//! vertex value, so it is exact at the vertices, and a triangle whose vertices all lie in the
//! range at both ends has CoC 0 everywhere: the core classes it static or motion-only and the
//! cheaper unit applies.
//!
//! Keys are checked strictly ([`super::json`]), a mesh's triangle count is checked against the
//! memory budget before it is generated ([`super::budget`]); user documentation:
//! `host/scenes/README.md`.

use std::path::Path;

use anyhow::{anyhow, bail, Result};
use glam::{DMat4, DVec3, DVec4};
use serde_json::Value;

use super::budget;
use super::json::{self, num_array};
use super::tri::SceneTri;

/// A camera pose.
#[derive(Clone, Copy, Debug)]
pub struct Pose {
    /// eye position
    pub eye: DVec3,
    /// look-at point
    pub target: DVec3,
    /// up vector
    pub up: DVec3,
}

/// Camera at both ends of the shutter plus lens.
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    /// vertical field of view, degrees
    pub fov_y: f64,
    /// near plane distance
    pub near: f64,
    /// far plane distance
    pub far: f64,
    /// lens radius (0 = pinhole)
    pub aperture: f64,
    /// focus distance (the middle of the in-focus range)
    pub focus: f64,
    /// depth extent of the in-focus range around `focus` (0 = a plain thin lens)
    pub focus_range: f64,
    /// pose at t = 0
    pub t0: Pose,
    /// pose at t = 1
    pub t1: Pose,
}

/// A triangle mesh in model space.
#[derive(Clone, Debug, Default)]
pub struct Mesh {
    /// vertex positions
    pub pos: Vec<DVec3>,
    /// triangles as vertex indices
    pub tris: Vec<[u32; 3]>,
}

/// A mesh instance: model matrices at both ends and a color.
#[derive(Clone, Debug)]
pub struct Instance {
    /// geometry
    pub mesh: Mesh,
    /// model matrix at t = 0
    pub m0: DMat4,
    /// model matrix at t = 1
    pub m1: DMat4,
    /// color
    pub color: [u8; 3],
}

impl Camera {
    fn proj(&self, aspect: f64) -> DMat4 {
        DMat4::perspective_rh(self.fov_y.to_radians(), aspect, self.near, self.far)
    }

    /// The lens of this camera at `aspect` (module docs).
    pub fn lens(&self, aspect: f64) -> Lens {
        let half = self.focus_range / 2.0;
        Lens {
            k: self.proj(aspect).x_axis.x * self.aperture,
            near: self.focus - half,
            far: self.focus + half,
        }
    }

    /// View-projection at both ends.
    pub fn view_proj(&self, aspect: f64) -> (DMat4, DMat4) {
        let p = self.proj(aspect);
        let v = |q: &Pose| DMat4::look_at_rh(q.eye, q.target, q.up);
        (p * v(&self.t0), p * v(&self.t1))
    }
}

/// A thin lens with an in-focus range, in clip units (module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lens {
    /// `P00·A`: the CoC slope scale (0 = pinhole)
    pub k: f64,
    /// near end of the in-focus range `F − R/2` (> 0 when `k ≠ 0`)
    pub near: f64,
    /// far end `F + R/2`
    pub far: f64,
}

impl Lens {
    /// Signed CoC of a vertex at view distance `w`: negative in front of the range, 0 inside
    /// it (ends included), positive behind it.
    pub fn coc(&self, w: f64) -> f64 {
        if self.k == 0.0 {
            0.0
        } else if w < self.near {
            // k·(w/F₀ − 1), evaluated as a·w + b (a = k/F₀, b = −k: the plain lens's form)
            self.k / self.near * w - self.k
        } else if w > self.far {
            self.k / self.far * w - self.k
        } else {
            0.0
        }
    }
}

/// Clip-space triangles of instances seen by `cam` on a W×H viewport.
pub fn to_clip(cam: &Camera, inst: &[Instance], viewport: (u16, u16)) -> Vec<SceneTri> {
    let aspect = viewport.0 as f64 / viewport.1 as f64;
    let (vp0, vp1) = cam.view_proj(aspect);
    let lens = cam.lens(aspect);
    let mut out = Vec::with_capacity(inst.iter().map(|i| i.mesh.tris.len()).sum());
    for ins in inst {
        let (c0, c1) = (vp0 * ins.m0, vp1 * ins.m1);
        let clip = |m: &DMat4, p: DVec3| {
            let q: DVec4 = *m * p.extend(1.0);
            [q.x, q.y, q.z, q.w, lens.coc(q.w)]
        };
        let v0: Vec<_> = ins.mesh.pos.iter().map(|&p| clip(&c0, p)).collect();
        let v1: Vec<_> = ins.mesh.pos.iter().map(|&p| clip(&c1, p)).collect();
        let light = DVec3::new(0.4, 0.8, 0.45).normalize();
        for t in &ins.mesh.tris {
            let g = |v: &Vec<[f64; 5]>| t.map(|i| v[i as usize]);
            // Flat Lambert shade from the t = 0 world-space normal, so shapes read in the images.
            let w = t.map(|i| ins.m0.transform_point3(ins.mesh.pos[i as usize]));
            let n = (w[1] - w[0]).cross(w[2] - w[0]).normalize_or_zero();
            let k = 0.35 + 0.65 * n.dot(light).abs();
            let color = ins
                .color
                .map(|c| (c as f64 * k).round().clamp(0.0, 255.0) as u8);
            out.push(SceneTri {
                t0: g(&v0),
                t1: g(&v1),
                color,
            });
        }
    }
    out
}

/// A flat grid in the xz plane centred on the origin, `cells` quads split in two.
pub fn grid(size: (f64, f64), cells: (u32, u32)) -> Mesh {
    let (nx, nz) = cells;
    let mut m = Mesh::default();
    for j in 0..=nz {
        for i in 0..=nx {
            let x = (i as f64 / nx as f64 - 0.5) * size.0;
            let z = (j as f64 / nz as f64 - 0.5) * size.1;
            m.pos.push(DVec3::new(x, 0.0, z));
        }
    }
    let id = |i: u32, j: u32| j * (nx + 1) + i;
    for j in 0..nz {
        for i in 0..nx {
            m.tris.push([id(i, j), id(i, j + 1), id(i + 1, j)]);
            m.tris.push([id(i + 1, j), id(i, j + 1), id(i + 1, j + 1)]);
        }
    }
    m
}

/// A UV sphere with `seg` segments around and `seg/2` rings.
pub fn sphere(radius: f64, seg: u32) -> Mesh {
    let rings = (seg / 2).max(2);
    let mut m = Mesh::default();
    for r in 0..=rings {
        let th = std::f64::consts::PI * r as f64 / rings as f64;
        for s in 0..seg {
            let ph = 2.0 * std::f64::consts::PI * s as f64 / seg as f64;
            m.pos
                .push(DVec3::new(th.sin() * ph.cos(), th.cos(), th.sin() * ph.sin()) * radius);
        }
    }
    let id = |r: u32, s: u32| r * seg + s % seg;
    for r in 0..rings {
        for s in 0..seg {
            if r > 0 {
                m.tris.push([id(r, s), id(r, s + 1), id(r + 1, s)]);
            }
            if r + 1 < rings {
                m.tris.push([id(r, s + 1), id(r + 1, s + 1), id(r + 1, s)]);
            }
        }
    }
    m
}

/// An axis-aligned box of half extents `h` centred on the origin.
pub fn cuboid(h: DVec3) -> Mesh {
    let mut m = Mesh::default();
    for i in 0..8u32 {
        let s = |b: u32| if i & b != 0 { 1.0 } else { -1.0 };
        m.pos.push(DVec3::new(s(1) * h.x, s(2) * h.y, s(4) * h.z));
    }
    let faces = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    for f in faces {
        m.tris.push([f[0], f[1], f[2]]);
        m.tris.push([f[0], f[2], f[3]]);
    }
    m
}

fn vec3(v: Option<&Value>, field: &str, default: DVec3) -> Result<DVec3> {
    match v {
        None => Ok(default),
        Some(v) => {
            let a = num_array(v, 3, field)?;
            Ok(DVec3::new(a[0], a[1], a[2]))
        }
    }
}

fn number(v: Option<&Value>, field: &str, default: f64) -> Result<f64> {
    match v {
        None => Ok(default),
        Some(x) => {
            let f = x
                .as_f64()
                .ok_or_else(|| anyhow!("{field}: {} is not a number", json::show(Some(x))))?;
            if !f.is_finite() {
                bail!("{field}: not finite");
            }
            Ok(f)
        }
    }
}

fn pose(v: Option<&Value>, field: &str) -> Result<Pose> {
    let v = v.ok_or_else(|| anyhow!("{field}: missing"))?;
    let o = json::object(v, field, &["eye", "target", "up"])?;
    Ok(Pose {
        eye: vec3(o.get("eye"), &format!("{field}.eye"), DVec3::ZERO)?,
        target: vec3(o.get("target"), &format!("{field}.target"), DVec3::NEG_Z)?,
        up: vec3(o.get("up"), &format!("{field}.up"), DVec3::Y)?,
    })
}

fn model(v: Option<&Value>, field: &str) -> Result<DMat4> {
    let Some(v) = v else {
        return Ok(DMat4::IDENTITY);
    };
    let o = json::object(v, field, &["translate", "rotate", "scale"])?;
    let t = vec3(
        o.get("translate"),
        &format!("{field}.translate"),
        DVec3::ZERO,
    )?;
    let r = vec3(o.get("rotate"), &format!("{field}.rotate"), DVec3::ZERO)?;
    let s = number(o.get("scale"), &format!("{field}.scale"), 1.0)?;
    let rot = glam::DQuat::from_euler(
        glam::EulerRot::XYZ,
        r.x.to_radians(),
        r.y.to_radians(),
        r.z.to_radians(),
    );
    Ok(DMat4::from_scale_rotation_translation(
        DVec3::splat(s),
        rot,
        t,
    ))
}

/// Load an OBJ file: a regular file of at most [`budget::FILE_MAX_BYTES`]; material libraries
/// are not read.
fn load_obj(path: &Path, field: &str) -> Result<Mesh> {
    let bytes = budget::read_limited(path, budget::FILE_MAX_BYTES, "OBJ file")
        .map_err(|e| anyhow!("{field}: {e:#}"))?;
    let opts = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ..Default::default()
    };
    let (models, _) = tobj::load_obj_buf(&mut bytes.as_slice(), &opts, |_| {
        Err(tobj::LoadError::OpenFileFailed)
    })
    .map_err(|e| anyhow!("{field}: cannot load {}: {e}", path.display()))?;
    let mut m = Mesh::default();
    for model in models {
        let base = m.pos.len() as u32;
        let p = &model.mesh.positions;
        for c in p.chunks_exact(3) {
            m.pos
                .push(DVec3::new(c[0] as f64, c[1] as f64, c[2] as f64));
        }
        for t in model.mesh.indices.chunks_exact(3) {
            m.tris.push([base + t[0], base + t[1], base + t[2]]);
        }
    }
    if m.tris.is_empty() {
        bail!("{field}: {} has no triangles", path.display());
    }
    Ok(m)
}

/// Triangles of [`sphere`]`(_, seg)`.
pub fn sphere_triangles(seg: u32) -> u64 {
    let rings = (seg / 2).max(2) as u64;
    seg as u64 * (2 * rings - 2)
}

/// Keys of a mesh entry.
const MESH_KEYS: &[&str] = &["obj", "grid", "sphere", "model", "model_t1", "color"];

/// Build clip-space triangles from the JSON camera and meshes. `check(n, path)` is called with
/// the running triangle count before each mesh is generated (after loading, for OBJ files) and
/// refuses a scene over the memory budget.
pub fn build(
    cam: &Value,
    meshes: &Value,
    viewport: (u16, u16),
    base: &Path,
    check: &dyn Fn(u64, &str) -> Result<()>,
) -> Result<Vec<SceneTri>> {
    let c = json::object(
        cam,
        "camera",
        &[
            "fov_y",
            "near",
            "far",
            "aperture",
            "focus",
            "focus_range",
            "t0",
            "t1",
        ],
    )?;
    let t0 = pose(c.get("t0"), "camera.t0")?;
    let camera = Camera {
        fov_y: number(c.get("fov_y"), "camera.fov_y", 60.0)?,
        near: number(c.get("near"), "camera.near", 0.1)?,
        far: number(c.get("far"), "camera.far", 100.0)?,
        aperture: number(c.get("aperture"), "camera.aperture", 0.0)?,
        focus: number(c.get("focus"), "camera.focus", 1.0)?,
        focus_range: number(c.get("focus_range"), "camera.focus_range", 0.0)?,
        t0,
        t1: if c.contains_key("t1") {
            pose(c.get("t1"), "camera.t1")?
        } else {
            t0
        },
    };
    if !(camera.fov_y > 0.0 && camera.fov_y < 180.0) {
        bail!("camera.fov_y: {} is not in (0, 180)", camera.fov_y);
    }
    if !(camera.near > 0.0 && camera.far > camera.near) {
        bail!("camera.near/far: need 0 < near < far");
    }
    if camera.aperture != 0.0 && camera.focus <= 0.0 {
        bail!("camera.focus: must be positive when aperture is set");
    }
    if camera.focus_range.is_nan() || camera.focus_range < 0.0 {
        bail!("camera.focus_range: {} is negative", camera.focus_range);
    }
    if camera.aperture != 0.0 && camera.focus_range >= 2.0 * camera.focus {
        bail!(
            "camera.focus_range: {} must be less than twice the focus distance {} (the range \
             [focus − range/2, focus + range/2] must start in front of the camera)",
            camera.focus_range,
            camera.focus
        );
    }
    let list = meshes
        .as_array()
        .ok_or_else(|| anyhow!("meshes: expected an array"))?;
    let mut inst = Vec::new();
    let mut total = 0u64;
    for (i, m) in list.iter().enumerate() {
        let f = format!("meshes[{i}]");
        let o = json::object(m, &f, MESH_KEYS)?;
        let kinds: Vec<&str> = ["obj", "grid", "sphere"]
            .into_iter()
            .filter(|k| o.contains_key(*k))
            .collect();
        let mesh = match kinds.as_slice() {
            ["obj"] => {
                let p = o["obj"].as_str().ok_or_else(|| {
                    anyhow!(
                        "{f}.obj: expected a file name, got {}",
                        json::show(o.get("obj"))
                    )
                })?;
                let mesh = load_obj(&base.join(p), &format!("{f}.obj"))?;
                total += mesh.tris.len() as u64;
                check(total, &format!("{f}.obj"))?;
                mesh
            }
            ["grid"] => {
                let g = json::object(&o["grid"], &format!("{f}.grid"), &["size", "cells"])?;
                let s = num_array(
                    g.get("size").unwrap_or(&Value::Null),
                    2,
                    &format!("{f}.grid.size"),
                )?;
                let cells = g
                    .get("cells")
                    .and_then(Value::as_array)
                    .filter(|a| a.len() == 2)
                    .ok_or_else(|| anyhow!("{f}.grid.cells: expected [nx, nz]"))?;
                let n =
                    |k: usize| json::integer(&cells[k], &format!("{f}.grid.cells[{k}]"), 1, 2048);
                let (nx, nz) = (n(0)? as u32, n(1)? as u32);
                total += 2 * nx as u64 * nz as u64;
                check(total, &format!("{f}.grid"))?;
                grid((s[0], s[1]), (nx, nz))
            }
            ["sphere"] => {
                let sp = &o["sphere"];
                let s = json::object(sp, &format!("{f}.sphere"), &["radius", "segments"])?;
                let r = number(s.get("radius"), &format!("{f}.sphere.radius"), 1.0)?;
                let n = match s.get("segments") {
                    None => 16,
                    Some(x) => json::integer(x, &format!("{f}.sphere.segments"), 3, 4096)? as u32,
                };
                total += sphere_triangles(n);
                check(total, &format!("{f}.sphere"))?;
                sphere(r, n)
            }
            [] => bail!("{f}: needs one of obj, grid, sphere"),
            more => bail!(
                "{f}: give one of obj, grid, sphere, not {}",
                more.join(" and ")
            ),
        };
        let m0 = model(o.get("model"), &format!("{f}.model"))?;
        let m1 = if o.contains_key("model_t1") {
            model(o.get("model_t1"), &format!("{f}.model_t1"))?
        } else {
            m0
        };
        let color = match o.get("color") {
            None => [200, 200, 200],
            Some(c) => json::color(c, &format!("{f}.color"))?,
        };
        inst.push(Instance {
            mesh,
            m0,
            m1,
            color,
        });
    }
    Ok(to_clip(&camera, &inst, viewport))
}
