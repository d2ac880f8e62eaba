//! Per-stage workloads for cost measurement: each runs one stage of the demo scene `reps` times
//! through the pipeline `uvt_core::units::select` picks for precision `P` on unit `U`, on the
//! prims unit `V` accepts, and returns how many stage calls it made (setups, tile steps, sample
//! tests). `U = V` is unit `U`'s own work; `U = Full` with a narrower `V` is the full unit on the
//! same work; `U = V = Full` the whole scene (the precision sweep). The `*_empty` workloads are
//! the same loops with the stage replaced by handing its arguments to `black_box`: the measuring
//! loop's own cost per call, to subtract.

use core::hint::black_box;

use uvt_core::config::unit::Unit;
use uvt_core::setup::Outcome;
use uvt_core::units::pipeline::Pipeline;
use uvt_core::units::select::{PipelineOf, Select};
use uvt_core::{Error, Laine2011, Ops, SamplePattern, ScreenPos};

use crate::scene::{unit_prims, viewport, BLOCK, SAMPLE_TABLE, SPP_U16};

/// Passes over the sample window per rep in [`samples`]: the triangles are set up once per
/// call, inside the caller's timing, so with few passes the setups (≈ 30–50 k instructions each
/// on the Cortex-M4F) would be charged to the sample test (≈ 90 instructions per call at 2
/// passes); at `2 × 16` passes they weigh < 6 per call.
pub const SAMPLE_PASSES: u32 = 16;

/// The pipeline of `(P, U)` with Laine 2011 bounds (the demo's strategy).
fn pipeline<P, U>() -> PipelineOf<Laine2011, P, U>
where
    (P, U): Select<Laine2011>,
{
    PipelineOf::<Laine2011, P, U>::new(Laine2011)
}

/// Setup (with the strategy's per-triangle preparation on the general pipeline) of the prims
/// `V` accepts, `reps` times, on `U` at `P`.
pub fn setup<P, U: Unit, V: Unit>(reps: u32) -> Result<u64, Error>
where
    (P, U): Select<Laine2011>,
{
    let pipe = pipeline::<P, U>();
    let prims = unit_prims::<V>()?;
    let vp = viewport()?;
    let mut ops = Ops::default();
    let mut calls = 0u64;
    for _ in 0..reps {
        for p in prims.iter() {
            // The outcome by reference: the harness does not copy the unit's result.
            let out = pipe.setup(black_box(&p.tri), vp, &mut ops);
            black_box(&out);
            calls = calls.saturating_add(1);
        }
    }
    Ok(calls)
}

/// The tile step of every 2×2 bounds tile of every visible prim's footprint, `reps` times.
pub fn bounds<P, U: Unit, V: Unit>(reps: u32) -> Result<u64, Error>
where
    (P, U): Select<Laine2011>,
{
    bounds_loop::<P, U, V, false>(reps)
}

/// The harness alone: [`bounds`]'s loop (the same setups, cells and call count) with the tile
/// step replaced by handing its arguments to `black_box`.
pub fn bounds_empty<P, U: Unit, V: Unit>(reps: u32) -> Result<u64, Error>
where
    (P, U): Select<Laine2011>,
{
    bounds_loop::<P, U, V, true>(reps)
}

/// The tile-step workload of [`bounds`]; `EMPTY`: the step replaced by `black_box`.
fn bounds_loop<P, U: Unit, V: Unit, const EMPTY: bool>(reps: u32) -> Result<u64, Error>
where
    (P, U): Select<Laine2011>,
{
    let pipe = pipeline::<P, U>();
    let prims = unit_prims::<V>()?;
    let vp = viewport()?;
    let mut ops = Ops::default();
    let mut calls = 0u64;
    for p in prims.iter() {
        let Outcome::Visible(e) = pipe.setup(&p.tri, vp, &mut ops) else {
            continue;
        };
        let fp = PipelineOf::<Laine2011, P, U>::footprint(&e);
        for _ in 0..reps {
            for cell in fp.cells(2) {
                if EMPTY {
                    black_box((black_box(&e), cell));
                } else {
                    black_box(pipe.tile(black_box(&e), cell, &mut ops));
                }
                calls = calls.saturating_add(1);
            }
        }
    }
    Ok(calls)
}

/// Sample tests of every sample of the 8×8 pixel window (12..20)² for every visible prim `V`
/// accepts, `reps × SAMPLE_PASSES` times, on `U` at `P`.
pub fn samples<P, U: Unit, V: Unit>(reps: u32) -> Result<u64, Error>
where
    (P, U): Select<Laine2011>,
{
    samples_loop::<P, U, V, false>(reps)
}

/// The harness alone: [`samples`]'s loop (the same setups, window, passes and call count) with
/// the sample test replaced by handing its arguments to `black_box` — the measuring loop's own
/// cost per call (the same loop for every unit and path).
pub fn samples_empty<P, U: Unit, V: Unit>(reps: u32) -> Result<u64, Error>
where
    (P, U): Select<Laine2011>,
{
    samples_loop::<P, U, V, true>(reps)
}

/// The sample-test workload of [`samples`]; `EMPTY`: the test replaced by `black_box`.
fn samples_loop<P, U: Unit, V: Unit, const EMPTY: bool>(reps: u32) -> Result<u64, Error>
where
    (P, U): Select<Laine2011>,
{
    let pipe = pipeline::<P, U>();
    let prims = unit_prims::<V>()?;
    let vp = viewport()?;
    let pattern = SamplePattern::new(BLOCK, SPP_U16, &SAMPLE_TABLE)?;
    let mut ops = Ops::default();
    let mut calls = 0u64;
    for p in prims.iter() {
        let Outcome::Visible(e) = pipe.setup(&p.tri, vp, &mut ops) else {
            continue;
        };
        for _ in 0..reps.saturating_mul(SAMPLE_PASSES) {
            for py in 12..20u16 {
                for px in 12..20u16 {
                    for smp in pattern.pixel(px, py) {
                        let pos = ScreenPos::of(px, py, smp);
                        if EMPTY {
                            black_box((black_box(&e), pos, smp));
                        } else {
                            black_box(PipelineOf::<Laine2011, P, U>::test(
                                black_box(&e),
                                pos,
                                smp,
                                &mut ops,
                            ));
                        }
                        calls = calls.saturating_add(1);
                    }
                }
            }
        }
    }
    Ok(calls)
}
