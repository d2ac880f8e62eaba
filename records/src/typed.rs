//! The typed API, for callers who do not want records: a triangle, its viewport and a
//! configuration make a [`Tri`] (setup once); a triangle and a sample give a [`Hit`] (coverage,
//! depth and the edge values) as the configuration's sample test computes them — the bounded
//! test of `bounded-…` configurations, and of a `planar-…` one's moving and defocused triangles;
//! the planar test of a `planar-…` configuration's static triangles. Exact configurations have
//! 192-bit edge values: use the records (`sample`). The one implementation behind the C library's
//! `uvt_tri_new` / `uvt_tri_sample` and the Python module's `uvt.Triangle`.

use uvt_core::config::registry::{self, Config};
use uvt_core::sample::{bounded, planar};
use uvt_core::{
    Class, Lens, Ops, PlanarPrecision, Sample, ScreenPos, Setup, SubPixel, Time, Triangle, Vertex,
    Viewport,
};

use crate::bsample::Grid;

/// Raw words of a triangle: key frame 0 vertices 0..2 with x, y, z, w, CoC each (I16F16), then
/// key frame 1 (a `bsample_in` record's words 0..29).
pub const TRI_WORDS: usize = 30;

/// Why a typed call was refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TypedError {
    /// an unknown configuration, or one the typed API is not made at (exact)
    Config(String),
    /// an input the model refuses; the message names the field and its raw bits
    Input(String),
}

impl core::fmt::Display for TypedError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            TypedError::Config(m) | TypedError::Input(m) => f.write_str(m),
        }
    }
}

/// A triangle set up at one configuration.
#[derive(Clone, Debug)]
pub struct Tri {
    setup: Setup,
    grid: Grid,
    planar: bool,
}

/// The result of one sample test.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Hit {
    /// the sample is covered
    pub covered: bool,
    /// orientation: the bounded test's sign of Σ E'·w, the planar test's σ (−1, 0, 1)
    pub det_sign: i32,
    /// depth (`DEPTH_FRAC` = 24 fraction bits), 0 when not covered
    pub depth: i32,
    /// edge values E'_k (bounded: on the offset grid) or E_k (planar: exact)
    pub e: [i64; 3],
}

/// The registry configuration named `config` (`None`: the default).
pub fn config_named(config: Option<&str>) -> Result<Config, TypedError> {
    match config {
        None => Ok(registry::DEFAULT),
        Some(n) => registry::find(n)
            .ok_or_else(|| TypedError::Config(format!("unknown configuration `{n}`"))),
    }
}

impl Tri {
    /// Set up the triangle of raw words `verts` ([`TRI_WORDS`]) in a `vp_w` × `vp_h` viewport at
    /// configuration `config` (a registry name; `None`: the default, `bounded-16-16-16-20`).
    pub fn new(
        verts: &[u32; TRI_WORDS],
        vp_w: u16,
        vp_h: u16,
        config: Option<&str>,
    ) -> Result<Tri, TypedError> {
        let cfg = config_named(config)?;
        let grid = Grid::from_config(cfg).map_err(TypedError::Config)?;
        let g = |i: usize| verts[i] as i32;
        let vert = |b: usize| Vertex::from_bits([g(b), g(b + 1), g(b + 2), g(b + 3), g(b + 4)]);
        let tri = Triangle::new([vert(0), vert(5), vert(10)], [vert(15), vert(20), vert(25)])
            .map_err(|e| TypedError::Input(format!("triangle refused by the core: {e}")))?;
        if grid.tri(&tri) != tri {
            // The first word with bits below the grid's LSB, named as the record layout names it.
            const COORD: [&str; 5] = ["x", "y", "z", "w", "coc"];
            let which =
                (0..TRI_WORDS)
                    .find(|&i| off_grid(g(i), grid.pos))
                    .map_or(String::new(), |i| {
                        format!(
                            ": t{}_v{}_{} = 0x{:08x} has bits below 2^-{}",
                            i / 15,
                            (i % 15) / 5,
                            COORD[i % 5],
                            verts[i],
                            grid.pos
                        )
                    });
            return Err(TypedError::Input(format!(
                "triangle not on the {}-fraction-bit position grid of {cfg}{which}",
                grid.pos
            )));
        }
        let vp = Viewport::new(vp_w, vp_h)
            .map_err(|e| TypedError::Input(format!("viewport refused: {e}")))?;
        let planar = cfg.planar() && tri.class() == Class::Static;
        let setup = if planar {
            let s = Setup::unculled::<PlanarPrecision>(&tri, vp);
            if s.planar().is_none() {
                return Err(TypedError::Input(
                    "the planar setup culls this triangle (det P' = 0 after the vertex rounding): it has no sample tests".into(),
                ));
            }
            s
        } else {
            // the bounded test reads the triangle, class and viewport of the setup only; the
            // shift is the configuration's (as `run_bsample` does)
            Setup::unculled::<uvt_core::BoundedPrecision>(&tri, vp)
        };
        Ok(Tri {
            setup,
            grid,
            planar,
        })
    }

    /// The triangle's class (static, motion, defocus, both).
    pub fn class(&self) -> Class {
        self.setup.class()
    }

    /// Whether the planar test runs (a `planar-…` configuration's static triangle).
    pub fn planar(&self) -> bool {
        self.planar
    }

    /// The sample test at position (`xs`, `ys`) in 1/256 px and `t`, `u`, `v` (raw, 16 fraction
    /// bits, on the configuration's grid; ignored by the planar test).
    pub fn sample(&self, xs: u32, ys: u32, t: i32, u: i32, v: i32) -> Result<Hit, TypedError> {
        let pos = ScreenPos { xs, ys };
        let mut ops = Ops::default();
        let outside = || {
            TypedError::Input(format!(
                "position xs = {xs}, ys = {ys} outside the viewport"
            ))
        };
        if self.planar {
            let e = planar::eval(&self.setup, pos, &mut ops).ok_or_else(outside)?;
            let sigma = self.setup.planar().map_or(0, |p| p.sigma());
            return Ok(Hit {
                covered: e.hit.is_some(),
                det_sign: sigma,
                depth: e.hit.map_or(0, |h| h.depth),
                e: e.e,
            });
        }
        let s = Sample::new(
            SubPixel::ZERO,
            SubPixel::ZERO,
            Lens::from_bits(u),
            Lens::from_bits(v),
            Time::from_bits(t),
        )
        .map_err(|e| TypedError::Input(format!("sample refused by the core: {e}")))?;
        if self.grid.sample(&s) != s {
            let which: Vec<String> = [("t", t), ("u", u), ("v", v)]
                .iter()
                .filter(|(_, x)| off_grid(*x, self.grid.tuv))
                .map(|(n, x)| format!("{n} = 0x{:08x}", *x as u32))
                .collect();
            return Err(TypedError::Input(format!(
                "t, u or v not on the {}-fraction-bit grid: {} has bits below 2^-{}",
                self.grid.tuv,
                which.join(", "),
                self.grid.tuv
            )));
        }
        let e = bounded::eval(&self.setup, self.grid.off, pos, &s, &mut ops).ok_or_else(outside)?;
        Ok(Hit {
            covered: e.hit.is_some(),
            det_sign: e.det_sign as i32,
            depth: e.hit.map_or(0, |h| h.depth),
            e: e.e,
        })
    }
}

/// Raw 16.16 value `v` has bits below the LSB of a grid of `frac` fraction bits (`frac` ≤ 16;
/// the mask `2^(16 − frac) − 1` is computed without a shift that could overflow).
fn off_grid(v: i32, frac: u32) -> bool {
    let mask = 1u32
        .checked_shl(16u32.saturating_sub(frac))
        .map_or(u32::MAX, |b| b - 1);
    (v as u32) & mask != 0
}
