//! Built-in scenes: the default scene of `uvt render` and the benchmark scenes analogous to
//! Laine 2011 Table 1 ('game': a street of boxes on a floor, ~40 px triangles; 'dense': finely
//! tessellated spheres, ~0.4 px triangles), each in the rows static, motion, motion×2, defocus,
//! defocus×2, both, both×2. ×2 doubles the shutter (the camera travels twice as far) or the
//! aperture radius.

use glam::{DMat4, DQuat, DVec3};

use super::file::Scene;
use super::mesh::{self, Camera, Instance, Pose};
use super::tri::{check_domain, SceneTri};

/// A benchmark row (Laine 2011 Table 1): the blur of the benchmark scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum Blur {
    /// no blur
    Static,
    /// camera motion
    Motion,
    /// doubled shutter
    Motion2,
    /// thin lens
    Defocus,
    /// doubled aperture
    Defocus2,
    /// motion and defocus
    Both,
    /// both doubled
    Both2,
}

impl Blur {
    /// All rows in Laine's order.
    pub const ALL: [Blur; 7] = [
        Blur::Static,
        Blur::Motion,
        Blur::Motion2,
        Blur::Defocus,
        Blur::Defocus2,
        Blur::Both,
        Blur::Both2,
    ];
    /// Label as in Laine's table.
    pub fn label(self) -> &'static str {
        match self {
            Blur::Static => "static",
            Blur::Motion => "motion",
            Blur::Motion2 => "motion x2",
            Blur::Defocus => "defocus",
            Blur::Defocus2 => "defocus x2",
            Blur::Both => "both",
            Blur::Both2 => "both x2",
        }
    }
    /// The command-line name: the label without " x" (static, motion, motion2, defocus,
    /// defocus2, both, both2).
    pub fn name(self) -> String {
        self.label().replace(" x", "")
    }
    /// The row of a command-line name ([`Blur::name`]); the error lists the names.
    pub fn from_name(name: &str) -> anyhow::Result<Blur> {
        Blur::ALL
            .into_iter()
            .find(|x| x.name() == name)
            .ok_or_else(|| {
                let all: Vec<String> = Blur::ALL.iter().map(|b| b.name()).collect();
                anyhow::anyhow!("unknown row {name:?} ({})", all.join(", "))
            })
    }
    fn motion(self) -> f64 {
        match self {
            Blur::Motion | Blur::Both => 1.0,
            Blur::Motion2 | Blur::Both2 => 2.0,
            _ => 0.0,
        }
    }
    fn aperture(self) -> f64 {
        match self {
            Blur::Defocus | Blur::Both => 1.0,
            Blur::Defocus2 | Blur::Both2 => 2.0,
            _ => 0.0,
        }
    }
}

/// Which benchmark scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum Bench {
    /// ~40 px triangles
    Game,
    /// ~0.4 px triangles
    Dense,
    /// the game street seen through a near fence of wide planks, drawn first (the occlusion
    /// rows of `uvt bench-zmax`; not a `bench-ste` row)
    Occluded,
}

impl Bench {
    /// Both scenes, in the table's order.
    pub const ALL: [Bench; 2] = [Bench::Game, Bench::Dense];
    /// Every built-in benchmark scene: the bench-ste scenes and the occlusion scene of
    /// `uvt bench-zmax` (the names `uvt scene list` and `--scene` take).
    pub const NAMED: [Bench; 3] = [Bench::Game, Bench::Dense, Bench::Occluded];
    /// The command-line name (game, dense).
    pub fn name(self) -> &'static str {
        match self {
            Bench::Game => "game",
            Bench::Dense => "dense",
            Bench::Occluded => "occluded",
        }
    }
    /// The scene of a command-line name; the error lists the names.
    pub fn from_name(name: &str) -> anyhow::Result<Bench> {
        Bench::NAMED
            .into_iter()
            .find(|b| b.name() == name)
            .ok_or_else(|| {
                let all: Vec<&str> = Bench::NAMED.iter().map(|b| b.name()).collect();
                anyhow::anyhow!("unknown scene {name:?} ({})", all.join(", "))
            })
    }
}

/// A camera pose looking from `eye` at `target`, both moved by `travel` (a pan).
fn panning(eye: DVec3, target: DVec3, travel: DVec3) -> Pose {
    Pose {
        eye: eye + travel,
        target: target + travel,
        up: DVec3::Y,
    }
}

fn inst(mesh: mesh::Mesh, m0: DMat4, m1: DMat4, color: [u8; 3]) -> Instance {
    Instance {
        mesh,
        m0,
        m1,
        color,
    }
}

fn at(p: DVec3) -> DMat4 {
    DMat4::from_translation(p)
}

/// A benchmark scene; `quick` is a quarter of the resolution with a quarter of the tessellation
/// per axis, so triangle sizes in pixels stay comparable.
pub fn bench_scene(kind: Bench, row: Blur, quick: bool) -> Scene {
    let q = if quick { 4 } else { 1 };
    let viewport = (960 / q as u16, 540 / q as u16);
    let (eye, target) = match kind {
        Bench::Game | Bench::Occluded => (DVec3::new(0.0, 1.7, 9.0), DVec3::new(0.0, 1.2, 0.0)),
        Bench::Dense => (DVec3::new(0.0, 1.0, 7.0), DVec3::new(0.0, 0.6, 0.0)),
    };
    // Camera motion: a pan to the right with a little forward travel.
    let travel = DVec3::new(0.35, 0.0, -0.25) * row.motion();
    let cam = Camera {
        fov_y: 55.0,
        near: 0.1,
        far: 200.0,
        aperture: 0.06 * row.aperture(),
        focus: match kind {
            Bench::Game | Bench::Occluded => 8.0,
            Bench::Dense => 7.0,
        },
        focus_range: 0.0,
        t0: panning(eye, target, DVec3::ZERO),
        t1: panning(eye, target, travel),
    };
    let mut list = Vec::new();
    if kind == Bench::Occluded {
        // Five planks 1.1 m wide with 0.5 m gaps, 3.5 m in front of the camera, submitted
        // first (front to back): ~60% of the screen hides the street.
        let n = (12 / q as u32).max(1);
        for i in 0..5 {
            let p = at(DVec3::new(-3.2 + i as f64 * 1.6, 1.5, 5.5));
            let c = [110 + i as u8 * 20, 80, 60];
            list.push(inst(
                subdivided_box(DVec3::new(0.55, 2.2, 0.05), n),
                p,
                p,
                c,
            ));
        }
    }
    match kind {
        Bench::Game | Bench::Occluded => {
            let cells = 84 / q as u32;
            list.push(inst(
                mesh::grid((60.0, 60.0), (cells, cells)),
                at(DVec3::new(0.0, 0.0, -20.0)),
                at(DVec3::new(0.0, 0.0, -20.0)),
                [120, 130, 110],
            ));
            // Two rows of boxes along a street, subdivided so their faces are ~40 px triangles.
            for side in [-1.0, 1.0] {
                for i in 0..8 {
                    let z = 4.0 - i as f64 * 5.0;
                    let hgt = 1.0 + ((i * 7 + (side as i32 + 1) * 3) % 5) as f64 * 0.6;
                    let m =
                        subdivided_box(DVec3::new(1.2, hgt, 1.5), (10 + q as u32 / 2) / q as u32);
                    let p = at(DVec3::new(side * 4.0, hgt, z));
                    let c = [150 + (i * 11 % 90) as u8, 100 + (i * 23 % 120) as u8, 90];
                    list.push(inst(m, p, p, c));
                }
            }
        }
        Bench::Dense => {
            let seg = 320 / q as u32;
            for (i, x) in [-2.4, -0.8, 0.8, 2.4].into_iter().enumerate() {
                let p = at(DVec3::new(x, 0.7, -(i as f64 % 2.0) * 1.5));
                let rot = DMat4::from_quat(DQuat::from_rotation_y(0.3 * i as f64));
                list.push(inst(
                    mesh::sphere(0.55, seg),
                    p * rot,
                    p * rot,
                    [200 - 30 * i as u8, 80 + 40 * i as u8, 120],
                ));
            }
            list.push(inst(
                mesh::grid((30.0, 30.0), (480 / q as u32, 480 / q as u32)),
                DMat4::IDENTITY,
                DMat4::IDENTITY,
                [90, 90, 100],
            ));
        }
    }
    let tris = mesh::to_clip(&cam, &list, viewport);
    let name = format!("{}/{}", kind.name(), row.label());
    let scene = Scene::builtin(name, viewport, tris);
    check_domain(&scene.tris).expect("built-in scene inside the domain");
    scene
}

/// A box whose faces are `n×n` grids (so its triangles have a chosen size).
fn subdivided_box(h: DVec3, n: u32) -> mesh::Mesh {
    let mut out = mesh::Mesh::default();
    let n = n.max(1);
    let faces: [(DVec3, DVec3, DVec3); 6] = [
        (DVec3::X, DVec3::Z, DVec3::Y),
        (DVec3::NEG_X, DVec3::Y, DVec3::Z),
        (DVec3::Y, DVec3::X, DVec3::Z),
        (DVec3::NEG_Y, DVec3::Z, DVec3::X),
        (DVec3::Z, DVec3::Y, DVec3::X),
        (DVec3::NEG_Z, DVec3::X, DVec3::Y),
    ];
    for (nrm, a, b) in faces {
        let base = out.pos.len() as u32;
        for j in 0..=n {
            for i in 0..=n {
                let (s, t) = (
                    2.0 * i as f64 / n as f64 - 1.0,
                    2.0 * j as f64 / n as f64 - 1.0,
                );
                out.pos.push((nrm + a * s + b * t) * h);
            }
        }
        for j in 0..n {
            for i in 0..n {
                let id = |i: u32, j: u32| base + j * (n + 1) + i;
                out.tris.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
                out.tris.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
            }
        }
    }
    out
}

/// A random clip-space triangle of kind 0..6: static, moving, defocused, both, crossing the
/// camera plane, huge (coordinates anywhere in ±8000). Used by the golden-vector generator and
/// the tests.
pub fn random_tri(rng: &mut impl rand::Rng, kind: u32) -> SceneTri {
    let mut r = |lo: f64, hi: f64| rng.gen_range(lo..hi);
    if kind == 4 {
        let mut p = || {
            let w = r(-3.0, 3.0);
            [r(-3.0, 3.0), r(-3.0, 3.0), 0.5 * w, w, 0.0]
        };
        return st([p(), p(), p()], [p(), p(), p()]);
    }
    if kind == 5 {
        let mut p = || {
            [
                r(-8000.0, 8000.0),
                r(-8000.0, 8000.0),
                r(-8000.0, 8000.0),
                r(-8000.0, 8000.0),
                r(-8000.0, 8000.0),
            ]
        };
        return st([p(), p(), p()], [p(), p(), p()]);
    }
    let (cx, cy, w, s) = (r(-1.2, 1.2), r(-1.2, 1.2), r(0.5, 6.0), r(0.05, 0.8));
    let (mx, my, mw) = (r(-1.5, 1.5), r(-1.5, 1.5), r(-0.5, 0.5));
    let (a, b) = (r(-0.15, 0.15), r(-0.3, 0.3));
    let defocus = kind == 2 || kind == 3;
    let motion = kind == 1 || kind == 3;
    let c = |w: f64| if defocus { a * w + b } else { 0.0 };
    let mut t0 = [[0.0; 5]; 3];
    let mut t1 = [[0.0; 5]; 3];
    for k in 0..3 {
        let (nx, ny, wk) = (
            cx + s * r(-1.0, 1.0),
            cy + s * r(-1.0, 1.0),
            w * (1.0 + 0.3 * r(-1.0, 1.0)),
        );
        t0[k] = [nx * wk, ny * wk, 0.5 * wk, wk, c(wk)];
        let w1 = wk * (1.0 + mw);
        t1[k] = if motion {
            [(nx + mx) * w1, (ny + my) * w1, 0.5 * w1, w1, c(w1)]
        } else {
            t0[k]
        };
    }
    st(t0, t1)
}

fn st(t0: [[f64; 5]; 3], t1: [[f64; 5]; 3]) -> SceneTri {
    SceneTri {
        t0,
        t1,
        color: [255, 255, 255],
    }
}

/// The default scene of `uvt render`: a floor, boxes and spheres, a panning camera with a thin
/// lens, and one sphere flying across the frame (motion + defocus together).
pub fn default_scene() -> Scene {
    let viewport = (320, 180);
    let eye = DVec3::new(0.0, 1.6, 7.0);
    let target = DVec3::new(0.0, 0.8, 0.0);
    let travel = DVec3::new(0.15, 0.0, 0.0);
    let cam = Camera {
        fov_y: 55.0,
        near: 0.1,
        far: 100.0,
        aperture: 0.05,
        focus: 6.0,
        focus_range: 0.0,
        t0: panning(eye, target, DVec3::ZERO),
        t1: panning(eye, target, travel),
    };
    let mut list = vec![inst(
        mesh::grid((24.0, 24.0), (24, 24)),
        DMat4::IDENTITY,
        DMat4::IDENTITY,
        [110, 120, 100],
    )];
    for (i, x) in [-2.5, 0.0, 2.5].into_iter().enumerate() {
        let p = at(DVec3::new(x, 0.6, -2.0 * i as f64 + 1.0));
        list.push(inst(
            mesh::cuboid(DVec3::splat(0.6)),
            p,
            p,
            [200, 120 + 40 * i as u8, 60],
        ));
    }
    let s0 = at(DVec3::new(-2.0, 1.4, 2.0));
    let s1 = at(DVec3::new(2.0, 1.6, 2.0));
    list.push(inst(mesh::sphere(0.5, 24), s0, s1, [70, 140, 220]));
    let p = at(DVec3::new(1.2, 0.5, 3.5));
    list.push(inst(mesh::sphere(0.5, 20), p, p, [230, 230, 230]));
    let tris = mesh::to_clip(&cam, &list, viewport);
    Scene::builtin("default", viewport, tris)
}
