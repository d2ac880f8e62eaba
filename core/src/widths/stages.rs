//! The width table of a configuration, stage by stage: setup, bounds, the sample test of its kind,
//! tile (module docs of [`crate::widths`]).

use crate::config::formats::{DEPTH_EDGE_BITS, DEPTH_FRAC, RECIP_SHIFT, SUBPIXEL_BITS, TUV_FRAC};
use crate::config::registry::Config;
use crate::widths::mag::Mag;
use crate::widths::row::eps_max;
use crate::widths::row::exact_positions;
use crate::widths::row::ext;
use crate::widths::row::lim;
use crate::widths::row::one;
use crate::widths::row::opw;
use crate::widths::row::Mul;
use crate::widths::row::Row;
use crate::widths::row::Table;
use crate::widths::row::BOUNDED_DEPTH_EDGE_BITS;

/// The width table of configuration `cfg`: setup, bounds, the sample test of its kind, tile.
// The plain operators here count multipliers (small constants, < 2^10) and subtract 1 from a
// shift ≥ 20 (`Bounded`'s offset shift, `TUV_FRAC`); the bounds themselves use `Mag`'s
// saturating arithmetic.
#[allow(clippy::arithmetic_side_effects)]
pub fn table(cfg: &Config) -> Table {
    let mut t = Table {
        rows: [None; Table::CAP],
    };
    let (ex, ew) = eps_max(cfg);
    let (ex, ew) = (Mag::int(u128::from(ex)), Mag::int(u128::from(ew)));
    let bounded = cfg.off().is_some();
    let w_corners: u32 = if bounded { 2 } else { 1 };
    let c = lim();
    let e = ext();
    let ew13 = e.bits();
    let r = |stage, signal, bound, ty, note, mul| Row {
        stage,
        signal,
        bound,
        ty,
        note,
        mul,
    };
    let mul = |a: u32, b: u32, count: u32| [Some(Mul { a, b, count }), None];
    let two = |x: Mul, y: Mul| [Some(x), Some(y)];

    // ---- setup ----
    let a_c = c.add(c).add(ex);
    let w_e = c.add(ew);
    t.push(r(
        "setup",
        "corner `a ± \\|c\\| ± ε_x`",
        a_c,
        "i64",
        "exact",
        [None, None],
    ));
    t.push(r(
        "setup",
        "corner `w ± ε_w`",
        w_e,
        "i64",
        "exact",
        [None, None],
    ));
    let n_pts = 6 * w_corners;
    let pairs = n_pts * (n_pts - 1) / 2 * 2 * 2; // per side, two sides, two axes
                                                 // Worst case (no early exit): per pair the cross product takes two a×w, the dot product
                                                 // one a×a and one w×w.
    t.push(r(
        "setup",
        "separating-line cross `a_i·w_j − w_i·a_j`",
        a_c.mul(w_e).times(2),
        "i128",
        "exact",
        mul(a_c.bits(), w_e.bits(), 2 * pairs),
    ));
    t.push(r(
        "setup",
        "separating-line dot `a_i·a_j + w_i·w_j`",
        a_c.mul(a_c).add(w_e.mul(w_e)),
        "i128",
        "exact",
        two(
            Mul {
                a: a_c.bits(),
                b: a_c.bits(),
                count: pairs,
            },
            Mul {
                a: w_e.bits(),
                b: w_e.bits(),
                count: pairs,
            },
        ),
    ));
    let aw = c.add(c).add(ex).add(c).add(ew);
    let num = aw.mul(e).mul(Mag::pow2(cfg.bnd()));
    t.push(r(
        "setup",
        "projection numerator `(a + u·cs ± ε_x + w ± ε_w)·E·2^BND`",
        num,
        "i128",
        "exact (2^BND: shift)",
        mul(aw.bits(), ew13, 2 * 2 * 2 * 6 * w_corners * 2),
    ));
    t.push(r(
        "setup",
        "box coordinate `X = num / 2w` (BND frac px)",
        num.shr_floor(1),
        "i64",
        "floor (min) / ceil (max); divide",
        [None, None],
    ));
    let dist = c.add(c).add(c).add(ex).add(ew);
    t.push(r(
        "setup",
        "frustum distance `w ± a + \\|c\\| + ε`",
        dist,
        "i128",
        "exact",
        [None, None],
    ));
    t.push(r(
        "setup",
        "frustum solve numerator `n·2^16` (0 ≤ n < d ≤ 2·dist)",
        dist.times(2).mul(one()),
        "i128",
        "ceil/floor outward; divide",
        [None, None],
    ));
    if !bounded {
        let pxy = c.times(3).add(c.times(3));
        let pw = c.times(3);
        let evals = 4 * 2 * 2;
        t.push(r(
            "setup",
            "degeneracy minors `y·w`, `x·w`, `x·y` (t ∈ {0,⅓,⅔,1}·3)",
            pxy.mul(pxy).times(2),
            "i128",
            "exact",
            mul(pxy.bits(), pxy.bits(), 6 * evals),
        ));
        t.push(r(
            "setup",
            "degeneracy det `Σ ±x·(y·w − w·y)`",
            pxy.mul(pxy).mul(pw).times(6),
            "i128",
            "exact",
            mul(pxy.bits(), pxy.mul(pxy).times(2).bits(), 3 * evals),
        ));
    }
    t.push(r(
        "setup",
        "static edge normal `n = P×P` (static class)",
        c.mul(c).times(2),
        "i128",
        "exact",
        mul(c.bits(), c.bits(), 18),
    ));

    // ---- bounds, per triangle (Laine2011::prepare) ----
    let slope = num.shr_floor(1).times(2);
    t.push(r(
        "bounds/tri",
        "lens slope `d = m⁺ − m⁻`",
        slope,
        "i64",
        "exact",
        [None, None],
    ));
    let recip = Mag::pow2(RECIP_SHIFT);
    t.push(r(
        "bounds/tri",
        "reciprocal `2^80/\\|d\\|` (up and down)",
        recip,
        "i128",
        "ceil / floor; divide",
        [None, None],
    ));
    let delta = c
        .times(2)
        .mul(e)
        .add(c.times(2).mul(e))
        .add(c.add(ex).add(ew).mul(e));
    t.push(r(
        "bounds/tri",
        "dual δ = `(a+w)·E − 2wξ ∓ (\\|c\\| + ε_x + ε_w)·E`",
        delta,
        "i64",
        "exact",
        // per axis: 6 vertex-ends × 2 footprint ends × ((a+w)·E and w·ξ) + 6 biases
        mul(c.times(2).bits(), ew13, 2 * (6 * 2 * 2 + 6)),
    ));
    // ---- bounds, per tile ----
    t.push(r(
        "bounds/tile",
        "lens solve `n·r` (0 ≤ n < \\|d\\|)",
        recip.add(slope),
        "i128",
        "then ÷2^64, ceil/floor",
        mul(slope.bits(), recip.bits(), 4),
    ));
    let line = delta.mul(e);
    // `laine::dual_t`: each of the 4 lines per axis once, at the tile end its slope picks, as
    // `v0·D + (v1 − v0)·(x − ξa)`: per axis 4 products δ × E and 4 of the slope (≤ 2δ) × E.
    t.push(r(
        "bounds/tile",
        "bounding line `δ_a·D + (δ_b − δ_a)·(x − ξa)`, one end per line",
        line,
        "i128",
        "exact (no division)",
        two(
            Mul {
                a: delta.bits(),
                b: ew13,
                count: 2 * 4,
            },
            Mul {
                a: delta.times(2).bits(),
                b: ew13,
                count: 2 * 4,
            },
        ),
    ));
    t.push(r(
        "bounds/tile",
        "t solve numerator `n·2^16` (0 ≤ n < d ≤ 2·line)",
        line.times(2).mul(one()),
        "i128",
        "ceil/floor outward; divide",
        [None, None],
    ));

    // ---- sample test ----
    let sub = Mag::pow2(SUBPIXEL_BITS);
    let t_op = opw(one(), 16u32.saturating_sub(cfg.tuv())); // T, U, V on the TUV grid
    let dq = c.times(2); // r − q
    let lerp = c.mul(one());
    match cfg.off() {
        None => {
            let d = sub.mul(e).mul(e);
            let gx = sub.mul(e); // |2xs − 256W| ≤ 256W
            t.push(r(
                "sample",
                "direction `d`",
                d,
                "i64",
                "exact",
                mul(gx.bits(), ew13, 3),
            ));
            t.push(r(
                "sample",
                "lerp `q·2^16 + T·(r − q)`",
                lerp,
                "i64",
                "exact",
                mul(t_op, opw(dq, 16u32.saturating_sub(cfg.pos())), 15),
            ));
            let [_, _, _, (_, _, p)] = exact_positions();
            t.push(r(
                "sample",
                "vertex P at (t,u,v), 48 frac (both)",
                p,
                "i64",
                "exact",
                mul(t_op, lerp.bits(), 6),
            ));
            let n = p.mul(p).times(2);
            t.push(r(
                "sample",
                "edge normal `n = P×P`",
                n,
                "i128",
                "exact",
                mul(p.bits(), p.bits(), 18),
            ));
            let ev = n.mul(d).times(3);
            t.push(r(
                "sample",
                "edge value `E = n·d`",
                ev,
                "`Wide` (192)",
                "exact",
                mul(n.bits(), d.bits(), 9),
            ));
            let det = p.mul(n).times(3);
            t.push(r(
                "sample",
                "`det = P0·n0`",
                det,
                "`Wide` (192)",
                "exact",
                mul(p.bits(), n.bits(), 3),
            ));
            // 2^DEPTH_EDGE_BITS − 1 with DEPTH_EDGE_BITS ≤ 32: a constant shift, checked by the compiler.
            const ES: u128 = (1u128 << DEPTH_EDGE_BITS) - 1;
            let es = Mag::int(ES);
            let dn = es.mul(p).times(3);
            t.push(r(
                "sample",
                "depth `Σ E'·z`, `Σ E'·w` (E' = E floored to 32 significant bits, \\|E'\\| < 2^32)",
                dn,
                "i128",
                "floor",
                mul(es.bits(), p.bits(), 6),
            ));
            t.push(r(
                "sample",
                "depth quotient numerator `num·2^24`",
                dn.mul(Mag::pow2(DEPTH_FRAC)),
                "i128",
                "floor, saturate; divide",
                [None, None],
            ));
        }
        Some(s) => {
            t.push(r(
                "sample",
                "1 lerp `f0·2^16 + T·(f1 − f0)`",
                lerp,
                "i64",
                "exact",
                mul(t_op, opw(dq, 16u32.saturating_sub(cfg.pos())), 15),
            ));
            let ft = lerp.add(Mag::pow2(TUV_FRAC - 1)).shr_floor(TUV_FRAC);
            t.push(r(
                "sample",
                "1 lerped `f_t = rnd16(…)`",
                ft,
                "i64",
                "nearest, ties up",
                [None, None],
            ));
            t.push(r(
                "sample",
                "2 lens product `U·c_t`",
                one().mul(ft),
                "i64",
                "exact",
                mul(t_op, ft.bits(), 6),
            ));
            let x = ft.add(
                one()
                    .mul(ft)
                    .add(Mag::pow2(TUV_FRAC - 1))
                    .shr_floor(TUV_FRAC),
            );
            t.push(r(
                "sample",
                "2 `x = x_t + rnd16(U·c_t)`",
                x,
                "i64",
                "nearest, ties up",
                [None, None],
            ));
            let sw = sub.mul(e);
            let aa = sw.mul(x).add(sw.mul(ft));
            // The multipliers: W·x (the factor 256 is wiring, W ≤ 2^11) and
            // (2xs − 256W)·w (|2xs − 256W| ≤ 256W), six of each.
            t.push(r(
                "sample",
                "3 offset `A = 256W·x − (2xs − 256W)·w`",
                aa,
                "i64",
                "exact",
                two(
                    Mul {
                        a: ew13,
                        b: x.bits(),
                        count: 6,
                    },
                    Mul {
                        a: sw.bits(),
                        b: ft.bits(),
                        count: 6,
                    },
                ),
            ));
            let half = Mag::pow2(s.saturating_sub(1));
            t.push(r(
                "sample",
                "4 `A + 2^(S−1)`",
                aa.add(half),
                "i64",
                "exact",
                [None, None],
            ));
            let ap = aa.add(half).shr_floor(s);
            t.push(r(
                "sample",
                "4 rounded offset `a' = rnd_S(A)`",
                ap,
                "i64",
                "nearest, ties up",
                [None, None],
            ));
            let ep = ap.mul(ap).times(2);
            t.push(r(
                "sample",
                "5 edge `E' = a'·b' − a'·b'`",
                ep,
                "i64",
                "exact",
                mul(ap.bits(), ap.bits(), 6),
            ));
            t.push(r(
                "sample",
                "6 orientation (rare path) `Σ E'·w`",
                ep.mul(ft).times(3),
                "i128",
                "exact",
                mul(ep.bits(), ft.bits(), 3),
            ));
            // 2^BOUNDED_DEPTH_EDGE_BITS − 1 with BOUNDED_DEPTH_EDGE_BITS ≤ 32: a constant shift, checked by the compiler.
            const ES: u128 = (1u128 << BOUNDED_DEPTH_EDGE_BITS) - 1;
            let es = Mag::int(ES);
            let dn = es.mul(ft).times(3);
            t.push(r(
                "sample",
                "8 depth `Σ E''·z`, `Σ E''·w` (\\|E''\\| < 2^24)",
                dn,
                "i64",
                "floor",
                mul(es.bits(), ft.bits(), 6),
            ));
            t.push(r(
                "sample",
                "8 depth quotient numerator `num·2^24`",
                dn.mul(Mag::pow2(DEPTH_FRAC)),
                "i128",
                "floor, saturate; divide",
                [None, None],
            ));
        }
    }
    t.push(r(
        "tile",
        "resolve sum of S ≤ 64 channels",
        Mag::int(64 * 255),
        "u32",
        "`(Σ + S/2)/S`",
        [None, None],
    ));
    // ---- Zmax culling (optional, `raster::zmax`) ----
    let two_z = c.times(2).add(Mag::int(1));
    t.push(r(
        "zmax",
        "floor numerator `(2z − 1)·2^24`, per vertex and shutter end",
        two_z.mul(Mag::pow2(DEPTH_FRAC)),
        "i64",
        "exact (2^24: shift)",
        [None, None],
    ));
    t.push(r(
        "zmax",
        "floor divisor `2w ± 1` (w ≥ 1 raw, else no floor)",
        two_z,
        "i64",
        "exact (±1: half an LSB each of z, w)",
        [None, None],
    ));
    t.push(r(
        "zmax",
        "depth floor `min ⌊num/den⌋`, clamped to the depth range",
        Mag::int((1 << 31) - 1),
        "i32",
        "floor; divide (6 per triangle)",
        [None, None],
    ));
    t.push(r(
        "zmax",
        "Zmax register per pixel (`ZMAX_BITS`, max of its S depths); tile max, `floor ≥ max`",
        Mag::int((1 << 31) - 1),
        "i32",
        "exact; refreshed on each write",
        [None, None],
    ));
    t
}
