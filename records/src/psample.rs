//! Planar sample-test records (`psample_in.hex` / `psample_out.hex`) of the planar static
//! configuration ([`PLANAR`]: `uvt_core::PlanarPrecision`, `core/src/sample/planar.rs`):
//! self-contained inputs of `uvt_core::sample::planar::planar_eval` — the static triangle's raw t0
//! vertices (x, y, z, w; CoC 0, t1 = t0), the viewport, **what the planar setup hands the
//! per-sample test** (the edge normals `n_k = (a, b, c)`, the orientation σ, the depth plane `G`
//! and its exponent `f`) and one sample position (xs, ys) — and its outputs: coverage, depth
//! (0 when not covered) and the exact edge values `E_k = n_k·d`. The RTL unit
//! `vectors/rtl/uvt_psample.v` reads only the setup fields, the viewport and the position (like
//! a real pipeline, it receives setup's output); the raw vertices let the checker re-run the
//! core's planar setup and compare the setup fields too.
//!
//! **Culled triangles have no record.** A triangle whose rounded vertices are degenerate
//! (`det P' = 0`: the planar setup returns no data, `Cull::Degenerate`) never reaches the
//! sample test; the generator drops it and counts it (`culled_degenerate` in the manifest's
//! `psample_coverage`), and the checker refuses a record of such a triangle by name.

use uvt_core::config::registry::{name_of, PLANAR};
use uvt_core::sample::planar;
use uvt_core::sample::planar::PlanarEval;
use uvt_core::setup::planar::PlanarEdges;
use uvt_core::{Ops, PlanarPrecision, ScreenPos, Setup, Triangle, Vertex, Viewport};

use crate::format::Rec;

/// The configuration of the records: the registry's name of [`PLANAR`].
pub const CONFIG: &str = match name_of(PLANAR) {
    Some(n) => n,
    None => panic!("the planar configuration is in the registry"),
};

/// The static triangle of `t`'s t0 vertices (CoC 0): what the planar test reads of any
/// triangle.
pub fn static_of(t: &Triangle) -> Triangle {
    let v = t.vertices(0).map(|v| {
        let [x, y, z, w, _] = v.bits();
        Vertex::from_bits([x, y, z, w, 0])
    });
    Triangle::new_static(v).expect("t0 vertices of a checked triangle are in the domain")
}

/// Input record of triangle `t` (static) with its planar setup `pl`.
pub fn enc_psample_in(t: &Triangle, vp: Viewport, pl: &PlanarEdges, pos: ScreenPos) -> Rec {
    let mut r = Rec::default();
    for v in t.vertices(0) {
        let [x, y, z, w, _] = v.bits();
        r = r.i32(x).i32(y).i32(z).i32(w);
    }
    r = r.packed(&[(vp.width() as i64, 16), (vp.height() as i64, 16)]);
    for nk in pl.n() {
        for c in nk {
            r = r.i32(c);
        }
    }
    let (g, f) = pl.depth_plane();
    r.packed(&[(pl.sigma() as i64, 2), (f as i64, 8)])
        .i32(g[0])
        .i32(g[1])
        .i32(g[2])
        .u32(pos.xs)
        .u32(pos.ys)
}

/// The core's planar setup and test of an input record: the input record as the core's setup
/// produces it (the checker compares it with the file's, field by field), the evaluation and
/// the output record. The triangle, viewport and position go through the core's checked
/// constructors; errors name the field.
pub fn run_psample(w: &[u32]) -> Result<(Rec, PlanarEval, Rec), String> {
    run_psample_probed(w, &mut uvt_core::coverage::NoProbe)
}

/// [`run_psample`], the test's decision paths reported to `pr` (`uvt_core::coverage`).
pub fn run_psample_probed(
    w: &[u32],
    pr: &mut impl uvt_core::coverage::Probe,
) -> Result<(Rec, PlanarEval, Rec), String> {
    let g = |i: usize| w.get(i).copied().unwrap_or(0);
    let vert = |k: usize| {
        let b = 4 * k;
        Vertex::from_bits([
            g(b) as i32,
            g(b + 1) as i32,
            g(b + 2) as i32,
            g(b + 3) as i32,
            0,
        ])
    };
    let tri = Triangle::new_static([vert(0), vert(1), vert(2)])
        .map_err(|e| format!("input triangle refused by the core: {e}"))?;
    let vp = Viewport::new(g(12) as u16, (g(12) >> 16) as u16)
        .map_err(|e| format!("input viewport refused: {e}"))?;
    let pos = ScreenPos {
        xs: g(26),
        ys: g(27),
    };
    let (sw, sh) = (256 * u32::from(vp.width()), 256 * u32::from(vp.height()));
    if pos.xs >= sw || pos.ys >= sh {
        return Err(format!(
            "fields xs = {}, ys = {}: outside the {}×{} viewport (xs < {sw}, ys < {sh})",
            pos.xs,
            pos.ys,
            vp.width(),
            vp.height()
        ));
    }
    let s = Setup::unculled::<PlanarPrecision>(&tri, vp);
    let pl = s.planar().ok_or(
        "the planar setup culls this triangle (det P' = 0 after the vertex rounding): a culled triangle has no record",
    )?;
    let e = planar::eval_probed(&s, pos, &mut Ops::default(), pr)
        .ok_or("planar_eval refused the record (position outside the viewport)")?;
    let out = Rec::default()
        .packed(&[(e.hit.is_some() as i64, 1)])
        .i32(e.hit.map_or(0, |h| h.depth))
        .i64(e.e[0])
        .i64(e.e[1])
        .i64(e.e[2]);
    Ok((enc_psample_in(&tri, vp, &pl, pos), e, out))
}
