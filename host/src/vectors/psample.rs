//! The planar sample-test sets: the named groups, the boundary searches and what they cover.
//! The record codec is [`uvt_records::psample`], re-exported here.

use rand::{Rng, SeedableRng};
use serde::Serialize;
use uvt_core::sample::planar;
use uvt_core::sample::planar::PlanarEval;
use uvt_core::setup::planar::PlanarEdges;
use uvt_core::{Ops, PlanarPrecision, SamplePattern, ScreenPos, Setup, Triangle, Vertex, Viewport};

use uvt_records::format::Rec;
pub use uvt_records::psample::*;

use super::bsample::area;

/// What a planar set exercises (counted by the generator, written to the manifest as
/// `psample_coverage`, asserted by the tests).
#[derive(Clone, Debug, Default, Serialize)]
pub struct PCoverage {
    /// records
    pub records: u64,
    /// triangles with records
    pub triangles: u64,
    /// triangles offered that the planar setup culls as degenerate (no record)
    pub culled_degenerate: u64,
    /// covered samples
    pub covered: u64,
    /// records of a clockwise (σ = −1) triangle
    pub sigma_negative: u64,
    /// some E_k = 0 (the fill rule decides)
    pub ties: u64,
    /// some E_k = 0 and covered
    pub ties_covered: u64,
    /// some E_k = 0 on an edge with a = 0 (the fill rule's b decides)
    pub ties_b: u64,
    /// the triangle has a vertex with w ≤ 0 (crosses or touches the camera plane)
    pub crossing: u64,
    /// and the sample is covered
    pub crossing_covered: u64,
    /// the triangle has a vertex with w = 0
    pub w_zero: u64,
    /// a vertex rounds with the largest shift, 15
    pub shift15: u64,
    /// a vertex far off-screen: |x| or |y| > 64·|w| (guard band)
    pub guard_band: u64,
    /// depth exponent f < 0 (left shift, saturating)
    pub f_negative: u64,
    /// depth exponent f ≥ 63 (the shift leaves 0 or −1)
    pub f_ge_63: u64,
    /// f ≥ 63 and |acc| ≥ 2^62 (the shift by 63 is not the shift by 62)
    pub f_ge_63_acc_large: u64,
    /// the depth before the clamp is 2^31 − 2 (DEPTH_FAR, not clamped)
    pub depth_at_far: u64,
    /// the depth before the clamp is 2^31 − 1 (the first clamped value)
    pub depth_past_far: u64,
    /// the depth before the clamp is −2^31 (DEPTH_NEAR, not clamped)
    pub depth_at_near: u64,
    /// the depth before the clamp is −2^31 − 1 (the first clamped value)
    pub depth_past_near: u64,
    /// depth saturated at the far end
    pub depth_far: u64,
    /// depth saturated at the near end
    pub depth_near: u64,
    /// samples at a viewport corner
    pub corners: u64,
    /// records in a 2048-pixel-wide or -high viewport
    pub vp_2048: u64,
}

/// A named group of records (`psample_cases` in the manifest).
#[derive(Clone, Debug, Serialize)]
pub struct PCase {
    /// what it exercises
    pub name: String,
    /// triangles offered (culled ones included)
    pub triangles: usize,
    /// first record and one past the last (equal: the group has no record)
    pub records: [usize; 2],
}

/// Records of one planar set, with what they cover.
#[derive(Default)]
pub struct PSet {
    /// input records
    pub inp: Vec<Rec>,
    /// output records
    pub out: Vec<Rec>,
    /// coverage counts
    pub cov: PCoverage,
    /// named groups (unit sets)
    pub cases: Vec<PCase>,
}

impl PSet {
    /// Add one record of the static triangle `t`; `None` (nothing added) when the planar setup
    /// culls it.
    pub fn push(&mut self, t: &Triangle, vp: Viewport, pos: ScreenPos) -> Option<PlanarEval> {
        let pl = Setup::unculled::<PlanarPrecision>(t, vp).planar()?;
        let (input, e, out) =
            run_psample(&enc_psample_in(t, vp, &pl, pos).0).expect("generator records are valid");
        let c = &mut self.cov;
        c.records += 1;
        let hit = e.hit.is_some();
        c.covered += hit as u64;
        c.sigma_negative += (pl.sigma() < 0) as u64;
        if e.e.contains(&0) {
            c.ties += 1;
            c.ties_covered += hit as u64;
            c.ties_b += (0..3).any(|k| e.e[k] == 0 && pl.n()[k][0] == 0) as u64;
        }
        let v = t.vertices(0).map(|v| v.bits());
        if v.iter().any(|b| b[3] <= 0) {
            c.crossing += 1;
            c.crossing_covered += hit as u64;
        }
        c.w_zero += v.iter().any(|b| b[3] == 0) as u64;
        c.shift15 += pl.shifts().contains(&15) as u64;
        c.guard_band += v.iter().any(|b| {
            let m = i64::from(b[0].unsigned_abs().max(b[1].unsigned_abs()));
            m > 64 * i64::from(b[3].unsigned_abs())
        }) as u64;
        let f = pl.depth_plane().1;
        c.f_negative += (f < 0) as u64;
        c.f_ge_63 += (f >= 63) as u64;
        c.f_ge_63_acc_large +=
            (hit && f >= 63 && acc(&pl, vp, pos).unsigned_abs() >= 1 << 62) as u64;
        if hit {
            let u = depth_unclamped(&pl, vp, pos);
            let far = i128::from(uvt_core::config::formats::DEPTH_FAR);
            let near = i128::from(uvt_core::config::formats::DEPTH_NEAR);
            c.depth_at_far += (u == far) as u64;
            c.depth_past_far += (u == far + 1) as u64;
            c.depth_at_near += (u == near) as u64;
            c.depth_past_near += (u == near - 1) as u64;
        }
        c.depth_far +=
            (e.hit.map(|h| h.depth) == Some(uvt_core::config::formats::DEPTH_FAR)) as u64;
        c.depth_near +=
            (e.hit.map(|h| h.depth) == Some(uvt_core::config::formats::DEPTH_NEAR)) as u64;
        let (sw, sh) = (256 * u32::from(vp.width()), 256 * u32::from(vp.height()));
        c.corners += ([0, sw - 1].contains(&pos.xs) && [0, sh - 1].contains(&pos.ys)) as u64;
        c.vp_2048 += (vp.width() == 2048 || vp.height() == 2048) as u64;
        self.inp.push(input);
        self.out.push(out);
        Some(e)
    }
}

/// `acc = G · d` of the depth plane at `pos` (`planar.rs` "Depth"; |acc| < 2^63), in i128.
pub fn acc(pl: &PlanarEdges, vp: Viewport, pos: ScreenPos) -> i128 {
    let (w, h) = (i128::from(vp.width()), i128::from(vp.height()));
    let d = [
        (2 * i128::from(pos.xs) - 256 * w) * h,
        (256 * h - 2 * i128::from(pos.ys)) * w,
        256 * w * h,
    ];
    let (g, _) = pl.depth_plane();
    (0..3).map(|i| i128::from(g[i]) * d[i]).sum()
}

/// The depth before the clamp to [DEPTH_NEAR, DEPTH_FAR], exact: `⌊acc / 2^min(f, 63)⌋` for
/// f ≥ 0, `acc·2^(−f)` for f < 0 (f ≥ −62 from setup: < 2^125).
pub fn depth_unclamped(pl: &PlanarEdges, vp: Viewport, pos: ScreenPos) -> i128 {
    let a = acc(pl, vp, pos);
    let f = pl.depth_plane().1;
    if f >= 0 {
        a >> f.min(63)
    } else {
        a << (-f).min(64)
    }
}

/// Records found by search at the depth clamp's boundaries (the unclamped depth 2^31 − 2,
/// 2^31 − 1, −2^31, −2^31 − 1) on triangles whose z/w is within a few LSB of ±128 across the
/// screen, and covered samples with f ≥ 63 and |acc| ≥ 2^62 (where a shift by 62 instead of 63
/// would differ: it needs G_x ≈ G_y ≈ G_w near 2^31 and the sample at a corner where d_x, d_y,
/// d_w ≈ 2^30 share their sign) on screen-covering triangles in the plane z = γ·(x + y + w),
/// γ ∈ [2^-28, 2^-25] (depth below one LSB), at the viewport's top right corner: at most `per`
/// records per target.
pub fn boundary_search(set: &mut PSet, rng: &mut rand_pcg::Pcg64, per: u64) {
    let far = i128::from(uvt_core::config::formats::DEPTH_FAR);
    let near = i128::from(uvt_core::config::formats::DEPTH_NEAR);
    let targets = [far, far + 1, near, near - 1];
    let mut found = [0u64; 5];
    for i in 0..3000 {
        if found.iter().all(|&n| n >= per) {
            break;
        }
        let kind = i % 3;
        if (kind == 2 && found[4] >= per) || (kind < 2 && found[..4].iter().all(|&n| n >= per)) {
            continue;
        }
        let (vp, v) = if kind < 2 {
            // kind 0: far, w = 2^22, z = 2^29 − r (r < 4): z/w·2^24 ∈ [2^31 − 16, 2^31];
            // kind 1: near, w = 2^22 − 2^8 (on its vertex's rounding grid, so that the rounded
            // triangle keeps it), z = −2^29 + r (r ∈ 2^15 ± 16): z/w·2^24 ≈ −2^31 ± 64.
            let (w, z0, sign, r) = if kind == 0 {
                (1i32 << 22, 1i32 << 29, -1, 0..4)
            } else {
                ((1 << 22) - 256, -(1 << 29), 1, 32752..32784)
            };
            let v = [(-1i32, -1i32), (1, -1), (0, 1)].map(|(x, y)| {
                let z = z0 + sign * rng.gen_range(r.clone());
                Vertex::from_bits([2 * x * w, 2 * y * w, z, w, 0])
            });
            (Viewport::new(64, 64).expect("64 × 64"), v)
        } else {
            let g = rng.gen_range(1.0..8.0) / f64::from(1u32 << 28);
            let v = [(-4i64, -4i64), (4, -4), (0, 4)].map(|(x, y)| {
                let w = (1i64 << 27) - rng.gen_range(0..1 << 20);
                let (x, y) = (x * w, y * w);
                let z = (g * (x + y + w) as f64).floor() as i32;
                Vertex::from_bits([x as i32, y as i32, z, w as i32, 0])
            });
            (Viewport::new(2048, 2048).expect("2048"), v)
        };
        let Ok(t) = Triangle::new_static(v) else {
            continue;
        };
        let probe = Setup::unculled::<PlanarPrecision>(&t, vp);
        let Some(pl) = probe.planar() else { continue };
        let (sw, sh) = (256 * u32::from(vp.width()), 256 * u32::from(vp.height()));
        for k in 0..40 {
            let pos = if kind == 2 && k < 4 {
                ScreenPos {
                    xs: sw - 1 - k * 64,
                    ys: k * 64,
                }
            } else {
                ScreenPos {
                    xs: rng.gen_range(0..sw),
                    ys: rng.gen_range(0..sh),
                }
            };
            let Some(e) = planar::eval(&probe, pos, &mut Ops::default()) else {
                continue;
            };
            if e.hit.is_none() {
                continue;
            }
            let slot = if kind == 2 {
                let f = pl.depth_plane().1;
                (f >= 63 && acc(&pl, vp, pos).unsigned_abs() >= 1 << 62).then_some(4)
            } else {
                let u = depth_unclamped(&pl, vp, pos);
                targets.iter().position(|&x| x == u)
            };
            if let Some(k) = slot {
                if found[k] < per {
                    found[k] += 1;
                    set.cov.triangles += 1;
                    set.push(&t, vp, pos);
                }
            }
        }
    }
}

/// Unit-level records for the named groups of static triangles `groups` (each triangle with
/// its viewport): per triangle 4 random positions over its footprint, the four viewport
/// corners, and positions found by search (coarse positions, whole, quarter and 1/256 pixels)
/// whose edge value is 0 (up to 3 ties) or that are covered (up to 3 hits). A triangle the
/// planar setup culls is counted, not recorded.
pub fn unit(groups: &[(String, Vec<(Triangle, Viewport)>)], seed: u64) -> PSet {
    let mut rng = rand_pcg::Pcg64::seed_from_u64(seed ^ 0x9a7a_5e7f);
    let mut set = PSet::default();
    for (name, tris) in groups {
        let first = set.inp.len();
        for (t, vp) in tris {
            unit_tri(&mut set, &mut rng, t, *vp);
        }
        set.cases.push(PCase {
            name: name.clone(),
            triangles: tris.len(),
            records: [first, set.inp.len()],
        });
    }
    set
}

fn unit_tri(set: &mut PSet, rng: &mut rand_pcg::Pcg64, t: &Triangle, vp: Viewport) {
    {
        let vp = &vp;
        if Setup::unculled::<PlanarPrecision>(t, *vp)
            .planar()
            .is_none()
        {
            set.cov.culled_degenerate += 1;
            return;
        }
        set.cov.triangles += 1;
        let (x0, y0, x1, y1) = area::<PlanarPrecision>(t, *vp);
        let (sw, sh) = (256 * vp.width() as u32, 256 * vp.height() as u32);
        for _ in 0..4 {
            let p = ScreenPos {
                xs: rng.gen_range(x0..x1),
                ys: rng.gen_range(y0..y1),
            };
            set.push(t, *vp, p);
        }
        for (xs, ys) in [(0, 0), (sw - 1, 0), (0, sh - 1), (sw - 1, sh - 1)] {
            set.push(t, *vp, ScreenPos { xs, ys });
        }
        let probe = Setup::unculled::<PlanarPrecision>(t, *vp);
        let (mut ties, mut hits) = (0, 0);
        for _ in 0..600 {
            if ties >= 3 && hits >= 3 {
                break;
            }
            let p = ScreenPos {
                xs: rng.gen_range(x0..x1),
                ys: rng.gen_range(y0..y1),
            };
            let mask = [!127u32, !31, !0][rng.gen_range(0..3)];
            let p = ScreenPos {
                xs: p.xs & mask,
                ys: p.ys & mask,
            };
            let Some(e) = planar::eval(&probe, p, &mut Ops::default()) else {
                continue;
            };
            let tie = e.e.contains(&0) && ties < 3;
            let hit = e.hit.is_some() && hits < 3;
            if tie || hit {
                ties += e.e.contains(&0) as u32;
                hits += e.hit.is_some() as u32;
                set.push(t, *vp, p);
            }
        }
    }
}

/// Frame-level records: the static triangles of a scene (its other triangles run the bounded
/// test; their t0 frames are not used) with the scene's own samples, at most `per_tri` per
/// triangle, evenly strided over its footprint's (pixel, sample) list.
pub fn frame(tris: &[Triangle], vp: Viewport, pattern: &SamplePattern<'_>, per_tri: usize) -> PSet {
    let mut set = PSet::default();
    for t in tris {
        if t.class() != uvt_core::Class::Static {
            continue;
        }
        if Setup::unculled::<PlanarPrecision>(t, vp).planar().is_none() {
            set.cov.culled_degenerate += 1;
            continue;
        }
        set.cov.triangles += 1;
        let (x0, y0, x1, y1) = area::<PlanarPrecision>(t, vp);
        let mut all = Vec::new();
        for py in (y0 / 256) as u16..(y1 / 256) as u16 {
            for px in (x0 / 256) as u16..(x1 / 256) as u16 {
                for s in pattern.pixel(px, py) {
                    all.push(ScreenPos::of(px, py, s));
                }
            }
        }
        let step = all.len().div_ceil(per_tri).max(1);
        for p in all.iter().step_by(step) {
            set.push(t, vp, *p);
        }
    }
    set
}
