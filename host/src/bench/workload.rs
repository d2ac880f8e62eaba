//! `uvt m4-workload`: a bench row's own work as the Cortex-M strategy harness takes it
//! (`uvt_demo::workload`: format, reader and stage workload) — the row's triangles on the
//! default configuration's position grid (every `every`-th one), its sample table on the t/u/v
//! grid and bounds tile 1, exactly the inputs of `bench-ste`'s cost table.

use uvt_core::{Precision, Triangle};
use uvt_demo::workload::{encode, Header};

use crate::scene::builtin::{bench_scene, Bench, Blur};
use crate::scene::pattern::Pattern;

/// The workload file of bench row (`kind`, `row`) at the quick or full size, keeping every
/// `every`-th triangle (from the first; `every` ≥ 1).
pub fn bench_workload(kind: Bench, row: Blur, quick: bool, every: u32) -> anyhow::Result<Vec<u8>> {
    type P = uvt_core::DefaultPrecision;
    anyhow::ensure!(every >= 1, "--every must be at least 1");
    let s = bench_scene(kind, row, quick);
    let tris: Vec<Triangle> = s
        .tris
        .iter()
        .step_by(every as usize)
        .map(|t| t.to_core_with::<P>())
        .collect::<Result<_, _>>()
        .map_err(|e| anyhow::anyhow!("bench scene: {e}"))?;
    let pattern = Pattern::new(s.pattern, s.spp, s.seed).with_tuv(P::TUV_FRAC);
    let h = Header {
        vp: s.core_viewport(),
        spp: pattern.spp,
        block: pattern.block,
        bounds_tile: 1,
        pos_frac: P::POS_FRAC,
        every,
    };
    let mut out = Vec::new();
    encode(&h, &pattern.quant, &tris, |w| out.extend(w.to_le_bytes()));
    Ok(out)
}
