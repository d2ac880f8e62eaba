//! The bounded sample-test sets: which records the unit-level and frame-level sets hold and
//! what they cover. The record codec (`Grid`, encode, decode, run) is
//! [`uvt_records::bsample`], re-exported here.

use rand::{Rng, SeedableRng};
use serde::Serialize;
use uvt_core::config::unit::Full;
use uvt_core::sample::bounded;
use uvt_core::{
    setup, BoundedPrecision, Lens, Ops, Outcome, Precision, Sample, ScreenPos, Setup, SubPixel,
    Time, Triangle, Viewport,
};

pub use uvt_records::bsample::*;
use uvt_records::format::{to_text, Rec};

use crate::scene::builtin::random_tri;

use super::cases::named_cases;

/// What a bounded set exercises (counted by the generator, written to the manifest, asserted
/// non-zero by the tests).
#[derive(Clone, Debug, Default, Serialize)]
pub struct BCoverage {
    /// records
    pub records: u64,
    /// records per triangle class (static, motion, defocus, both)
    pub class: [u64; 4],
    /// covered samples
    pub covered: u64,
    /// some E'_k = 0 (the fill-rule tie key decides)
    pub ties: u64,
    /// some E'_k = 0 and covered
    pub ties_covered: u64,
    /// some vertex has w ≤ 0 at the sample's t (orientation from Σ E'·w)
    pub rare_path: u64,
    /// rare path and covered
    pub rare_covered: u64,
    /// depth saturated at the far end
    pub depth_far: u64,
    /// depth saturated at the near end
    pub depth_near: u64,
    /// samples at a viewport corner
    pub corners: u64,
}

/// Records of one bounded set, with what they cover.
#[derive(Default)]
pub struct BSet {
    /// input records
    pub inp: Vec<Rec>,
    /// output records
    pub out: Vec<Rec>,
    /// coverage counts
    pub cov: BCoverage,
}

/// w of vertex k at the sample's t, as `bounded.rs` step 1 forms it.
fn w_at(t: &Triangle, k: usize, s: &Sample) -> i64 {
    let (w0, w1) = (
        t.vertices(0)[k].w.to_bits() as i64,
        t.vertices(1)[k].w.to_bits() as i64,
    );
    let tt = s.t().to_bits() as i64;
    (w0 * 65536 + tt * (w1 - w0) + 32768) >> 16
}

impl BSet {
    /// Add one record (inputs moved onto `g`'s grids); returns the evaluation.
    pub fn push(
        &mut self,
        t: &Triangle,
        vp: Viewport,
        g: Grid,
        pos: ScreenPos,
        s: &Sample,
    ) -> uvt_core::BoundedEval {
        let (t, s) = (g.tri(t), g.sample(s));
        let input = enc_bsample_in(&t, vp, g, pos, &s);
        let (e, out) = run_bsample(&input.0).expect("generator records are valid");
        let c = &mut self.cov;
        c.records += 1;
        c.class[t.class().index()] += 1;
        let hit = e.hit.is_some();
        c.covered += hit as u64;
        if e.e.contains(&0) {
            c.ties += 1;
            c.ties_covered += hit as u64;
        }
        if (0..3).any(|k| w_at(&t, k, &s) <= 0) {
            c.rare_path += 1;
            c.rare_covered += hit as u64;
        }
        c.depth_far +=
            (e.hit.map(|h| h.depth) == Some(uvt_core::config::formats::DEPTH_FAR)) as u64;
        c.depth_near +=
            (e.hit.map(|h| h.depth) == Some(uvt_core::config::formats::DEPTH_NEAR)) as u64;
        let (sw, sh) = (256 * u32::from(vp.width()), 256 * u32::from(vp.height()));
        c.corners += ([0, sw - 1].contains(&pos.xs) && [0, sh - 1].contains(&pos.ys)) as u64;
        self.inp.push(input);
        self.out.push(out);
        e
    }
}

fn rand_sample(rng: &mut rand_pcg::Pcg64) -> Sample {
    Sample::new(
        SubPixel::ZERO,
        SubPixel::ZERO,
        Lens::from_bits(rng.gen_range(-65536..=65536)),
        Lens::from_bits(rng.gen_range(-65536..=65536)),
        Time::from_bits(rng.gen_range(0..=65536)),
    )
    .expect("drawn inside the domain")
}

/// The footprint of the setup at precision `P` in 1/256 px, or the whole viewport for a
/// culled triangle.
pub(super) fn area<P: Precision>(t: &Triangle, vp: Viewport) -> (u32, u32, u32, u32) {
    match setup::<P, Full>(t, vp, &mut Ops::default()) {
        Outcome::Visible(s) => {
            let f = s.footprint();
            (
                256 * f.x0 as u32,
                256 * f.y0 as u32,
                256 * f.x1 as u32,
                256 * f.y1 as u32,
            )
        }
        Outcome::Culled(_) | Outcome::Refused(_) => {
            (0, 0, 256 * vp.width() as u32, 256 * vp.height() as u32)
        }
    }
}

/// Unit-level records for `tris` (each with its viewport): per triangle random samples over its
/// footprint, the four viewport corners (t, u, v at their extremes too), and samples found by
/// search whose rounded edge value is 0 (ties) or whose vertex has w ≤ 0 while covered.
pub fn unit(tris: &[(Triangle, Viewport)], seed: u64, g: Grid) -> BSet {
    let mut rng = rand_pcg::Pcg64::seed_from_u64(seed ^ 0xb5a3_91e0);
    let mut set = BSet::default();
    let extreme = [(0, -65536, -65536), (65536, 65536, 65536), (32768, 0, 0)];
    for (t, vp) in tris {
        let (x0, y0, x1, y1) = area::<BoundedPrecision>(t, *vp);
        let (sw, sh) = (256 * vp.width() as u32, 256 * vp.height() as u32);
        for _ in 0..8 {
            let p = ScreenPos {
                xs: rng.gen_range(x0..x1),
                ys: rng.gen_range(y0..y1),
            };
            let s = rand_sample(&mut rng);
            set.push(t, *vp, g, p, &s);
        }
        for (i, (xs, ys)) in [(0, 0), (sw - 1, 0), (0, sh - 1), (sw - 1, sh - 1)]
            .into_iter()
            .enumerate()
        {
            let (tt, u, v) = extreme[i % 3];
            let s = Sample::new(
                SubPixel::ZERO,
                SubPixel::ZERO,
                Lens::from_bits(u),
                Lens::from_bits(v),
                Time::from_bits(tt),
            )
            .expect("extremes are in the domain");
            set.push(t, *vp, g, ScreenPos { xs, ys }, &s);
            let s = rand_sample(&mut rng);
            set.push(t, *vp, g, ScreenPos { xs, ys }, &s);
        }
        // Search (not recorded unless kept): ties, and covered samples of the rare path.
        let crossing =
            (0..3).any(|k| t.vertices(0)[k].w.to_bits() <= 0 || t.vertices(1)[k].w.to_bits() <= 0);
        let (mut ties, mut rare, mut hits) = (0, 0, 0);
        for _ in 0..400 {
            if ties >= 3 && hits >= 4 && (rare >= 3 || !crossing) {
                break;
            }
            let p = ScreenPos {
                xs: rng.gen_range(x0..x1),
                ys: rng.gen_range(y0..y1),
            };
            // Coarse positions (whole and half pixels) make exact ties likelier.
            let p = if rng.gen_bool(0.5) {
                ScreenPos {
                    xs: p.xs & !127,
                    ys: p.ys & !127,
                }
            } else {
                p
            };
            let s = rand_sample(&mut rng);
            let s = if rng.gen_bool(0.5) {
                Sample::new(
                    SubPixel::ZERO,
                    SubPixel::ZERO,
                    Lens::ZERO,
                    Lens::ZERO,
                    s.t(),
                )
                .expect("lens centre")
            } else {
                s
            };
            let probe = Setup::unculled::<BoundedPrecision>(&g.tri(t), *vp);
            let Some(e) = bounded::eval(&probe, g.off, p, &g.sample(&s), &mut Ops::default())
            else {
                continue;
            };
            let rare_hit = crossing
                && e.hit.is_some()
                && (0..3).any(|k| w_at(&g.tri(t), k, &g.sample(&s)) <= 0);
            let hit = e.hit.is_some() && hits < 4;
            if (e.e.contains(&0) && ties < 3) || (rare_hit && rare < 3) || hit {
                ties += e.e.contains(&0) as u32;
                rare += rare_hit as u32;
                hits += e.hit.is_some() as u32;
                set.push(t, *vp, g, p, &s);
            }
        }
    }
    set
}

/// A unit-level bounded set of configuration `g` (the named edge cases and 48 seeded random
/// triangles of every kind, inputs rounded onto `g`'s grids), written as `bsample_in.hex` and
/// `bsample_out.hex` into `dir`: the RTL test's vectors for the unit's other parameter values.
pub fn export_grid(dir: &std::path::Path, g: Grid, seed: u64) -> anyhow::Result<BCoverage> {
    let mut rng = rand_pcg::Pcg64::seed_from_u64(seed);
    let mut tris = Vec::new();
    for (_, list, side) in named_cases() {
        let vp = Viewport::new(side, side).map_err(|e| anyhow::anyhow!("{e}"))?;
        tris.extend(list.into_iter().map(|t| (t, vp)));
    }
    for i in 0..48u32 {
        let vp = Viewport::new([8u16, 17, 32, 61][i as usize % 4], 24)
            .map_err(|e| anyhow::anyhow!("{e}"))?;
        let t = random_tri(&mut rng, i % 6)
            .to_core()
            .map_err(|e| anyhow::anyhow!("{e}"))?;
        tris.push((t, vp));
    }
    let set = unit(&tris, seed, g);
    std::fs::create_dir_all(dir)?;
    for (name, recs) in [("bsample_in.hex", &set.inp), ("bsample_out.hex", &set.out)] {
        let p = dir.join(name);
        std::fs::write(&p, to_text(recs))
            .map_err(|e| anyhow::anyhow!("writing {}: {e}", p.display()))?;
    }
    Ok(set.cov)
}
