//! One scene triangle (clip space, f64, both ends of the shutter) and what the host does to hand
//! it to the core: the rounding to I16F16 ([`quantize`]) and the check against the core's
//! coordinate domain ([`DOMAIN`], [`check_domain`]).

use anyhow::{bail, Result};
use uvt_core::{Coord, Triangle, Vertex};

/// One triangle in clip space, f64: `[x, y, z, w, coc]` per vertex at both ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneTri {
    /// shutter open
    pub t0: [[f64; 5]; 3],
    /// shutter close
    pub t1: [[f64; 5]; 3],
    /// flat color
    pub color: [u8; 3],
}

/// The core's coordinate domain, in value.
pub const DOMAIN: f64 = 8192.0;

/// Round an f64 to I16F16 (nearest, ties away from zero); the caller has checked the domain.
pub fn quantize(v: f64) -> Coord {
    Coord::from_bits((v * 65536.0).round() as i32)
}

impl SceneTri {
    /// The core triangle (coordinates rounded to nearest I16F16).
    pub fn to_core(&self) -> Result<Triangle, uvt_core::Error> {
        let q = |a: [f64; 5]| Vertex {
            x: quantize(a[0]),
            y: quantize(a[1]),
            z: quantize(a[2]),
            w: quantize(a[3]),
            coc: quantize(a[4]),
        };
        Triangle::new(self.t0.map(q), self.t1.map(q))
    }

    /// The core triangle at precision `P`: coordinates rounded to nearest on `P`'s grid.
    pub fn to_core_with<P: uvt_core::Precision>(&self) -> Result<Triangle, uvt_core::Error> {
        let step = (1i64 << (16 - P::POS_FRAC)) as f64 / 65536.0;
        let q = |x: f64| Coord::from_bits(((x / step).round() * step * 65536.0) as i32);
        let v = |a: [f64; 5]| Vertex {
            x: q(a[0]),
            y: q(a[1]),
            z: q(a[2]),
            w: q(a[3]),
            coc: q(a[4]),
        };
        Triangle::new_with::<P>(self.t0.map(v), self.t1.map(v))
    }
}

/// Every coordinate and CoC inside the core's domain (after rounding).
pub fn check_domain(tris: &[SceneTri]) -> Result<()> {
    const NAMES: [&str; 5] = ["x", "y", "z", "w", "coc"];
    for (i, t) in tris.iter().enumerate() {
        for (end, verts) in [&t.t0, &t.t1].into_iter().enumerate() {
            for (k, v) in verts.iter().enumerate() {
                for (f, x) in v.iter().enumerate() {
                    if !x.is_finite() {
                        bail!("triangles[{i}].t{end}[{k}].{}: {x} is not finite", NAMES[f]);
                    }
                    if quantize(x.clamp(-1e6, 1e6)).to_bits().unsigned_abs() > 1 << 29
                        || x.abs() > DOMAIN
                    {
                        bail!(
                            "triangles[{i}].t{end}[{k}].{}: {x} is outside the core's domain |v| <= {DOMAIN}",
                            NAMES[f]
                        );
                    }
                }
            }
        }
    }
    Ok(())
}
