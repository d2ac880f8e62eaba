//! Sample tables: an N×N pixel block × S samples, repeated over the screen, each sample with
//! sub-pixel (x, y) ∈ [0,1), lens (u, v) ∈ [-1,1] and time t ∈ [0,1). Kept twice: the exact f64
//! values (used by the f64 reference) and their quantization to the core's formats (sub-pixel
//! floored to 1/256, t/u/v rounded to nearest 2^-16 and clamped).

use anyhow::{anyhow, Result};
use rand::{Rng, SeedableRng};
use uvt_core::{Lens, Sample, SamplePattern, SubPixel, Time};

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

impl PatternKind {
    /// Every pattern by its scene-file and command-line name.
    pub const NAMES: [(&'static str, PatternKind); 3] = [
        ("sobol", PatternKind::Sobol),
        ("random", PatternKind::Random),
        ("stratified", PatternKind::Stratified),
    ];

    /// The pattern called `name`; the error lists the accepted names.
    pub fn from_name(name: &str) -> Result<PatternKind> {
        Self::NAMES
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, k)| *k)
            .ok_or_else(|| anyhow!("unknown pattern {name:?} (sobol, random, stratified)"))
    }
}

/// Block side of every table uvt generates.
pub const BLOCK: u16 = 8;

/// A generated table.
#[derive(Clone, Debug)]
pub struct Pattern {
    /// block side N
    pub block: u16,
    /// samples per pixel S
    pub spp: u16,
    /// exact values `[sx, sy, u, v, t]`
    pub exact: Vec<[f64; 5]>,
    /// quantized for the core
    pub quant: Vec<Sample>,
}

/// Quantize one exact sample to the core's formats.
pub fn quantize_sample(s: &[f64; 5]) -> Sample {
    let sub = |x: f64| SubPixel::from_bits((x * 256.0).floor().clamp(0.0, 255.0) as u8);
    let tuv = |x: f64, lo: f64| (x * 65536.0).round().clamp(lo * 65536.0, 65536.0) as i32;
    Sample::new(
        sub(s[0]),
        sub(s[1]),
        Lens::from_bits(tuv(s[2], -1.0)),
        Lens::from_bits(tuv(s[3], -1.0)),
        Time::from_bits(tuv(s[4], 0.0)),
    )
    .expect("clamped to the sample domain")
}

impl Pattern {
    /// Generate a table.
    pub fn new(kind: PatternKind, spp: u16, seed: u64) -> Pattern {
        let n = BLOCK as usize * BLOCK as usize;
        let s = spp as usize;
        let mut exact = Vec::with_capacity(n * s);
        let mut rng = rand_pcg::Pcg64::seed_from_u64(seed);
        for pixel in 0..n {
            match kind {
                PatternKind::Sobol => {
                    // One Owen scramble per pixel (seed mixes the table seed and pixel index).
                    let ps = (seed as u32).wrapping_mul(0x9e37_79b9)
                        ^ (pixel as u32).wrapping_mul(0x85eb_ca6b);
                    for i in 0..s {
                        let d = |dim: u32| sobol_burley::sample(i as u32, dim, ps) as f64;
                        exact.push([d(0), d(1), 2.0 * d(2) - 1.0, 2.0 * d(3) - 1.0, d(4)]);
                    }
                }
                PatternKind::Random => {
                    for _ in 0..s {
                        let mut r = || rng.gen::<f64>();
                        exact.push([r(), r(), 2.0 * r() - 1.0, 2.0 * r() - 1.0, r()]);
                    }
                }
                PatternKind::Stratified => {
                    // Latin hypercube: each dimension has one sample per stratum of width 1/S.
                    let mut dims = [[0.0; 64]; 5];
                    for d in dims.iter_mut() {
                        let mut perm: Vec<usize> = (0..s).collect();
                        for i in (1..s).rev() {
                            perm.swap(i, rng.gen_range(0..=i));
                        }
                        for (i, p) in perm.iter().enumerate() {
                            d[i] = (*p as f64 + rng.gen::<f64>()) / s as f64;
                        }
                    }
                    let [d0, d1, d2, d3, d4] = &dims;
                    for ((((a, b), c), d), e) in d0.iter().zip(d1).zip(d2).zip(d3).zip(d4).take(s) {
                        exact.push([*a, *b, 2.0 * c - 1.0, 2.0 * d - 1.0, *e]);
                    }
                }
            }
        }
        let quant = exact.iter().map(quantize_sample).collect();
        Pattern {
            block: BLOCK,
            spp,
            exact,
            quant,
        }
    }

    /// The same table quantized to `tuv` fraction bits for t/u/v (round to nearest on that grid).
    pub fn with_tuv(&self, tuv: u32) -> Pattern {
        let step = 1i32 << (16 - tuv);
        let snap = |x: Lens, lo: i32| {
            Lens::from_bits(
                ((x.to_bits() as f64 / step as f64).round() as i32 * step).clamp(lo, 65536),
            )
        };
        let quant = self
            .quant
            .iter()
            .map(|s| {
                Sample::new(
                    s.sx(),
                    s.sy(),
                    snap(s.u(), -65536),
                    snap(s.v(), -65536),
                    snap(s.t(), 0),
                )
                .expect("snapped inside the sample domain")
            })
            .collect();
        Pattern {
            quant,
            ..self.clone()
        }
    }

    /// The core's view of the table.
    pub fn core(&self) -> SamplePattern<'_> {
        SamplePattern::new(self.block, self.spp, &self.quant)
            .expect("generated table is in the domain")
    }

    /// Index of sample `s` of pixel (x, y) in both tables.
    #[inline]
    pub fn index(&self, x: u16, y: u16, s: usize) -> usize {
        let n = self.block as usize;
        ((y as usize % n) * n + (x as usize % n)) * self.spp as usize + s
    }
}
