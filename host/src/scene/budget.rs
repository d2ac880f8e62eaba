//! Memory budget of a scene: estimated before anything large is allocated, so a scene that is
//! too big is refused with a message instead of aborting the process on an allocation failure.
//!
//! Estimate (bytes) for T triangles on a W×H viewport at S samples per pixel, with N worker
//! threads:
//!
//!   T · [`per_triangle_bytes`] + W·H · [`PER_PIXEL_BYTES`] + W·H·S · [`PER_SAMPLE_BYTES`]
//!   + N · W · 8 · S · 11 + [`FRAME_SETUP_BYTES`]
//!
//! - per triangle: the f64 scene triangle twice (the list and its growth while built), the mesh
//!   vertices and indices it came from, the core triangle, and the f64 reference's per-triangle
//!   footprint, class and band lists (the core's frame keeps no per-triangle entry: its set-up
//!   triangles live in a few chunks, [`FRAME_SETUP_BYTES`]) — sizes taken with `size_of` from
//!   this build;
//! - per pixel: three resolved images and three sample-count maps, the two derived images, the
//!   PNG buffers and the core frame's per-pixel counters (76 bytes);
//! - per sample: the core frame's depth (4 bytes) and colour (3), kept for the whole frame;
//! - per worker: one 8-row band of the f64 reference's depth (f64) and colour (3 bytes) per
//!   sample;
//! - the core frame's chunks of set-up triangles (`crate::frame::core_frame`: at most 8 chunks
//!   of 256 KiB).
//!
//! The default budget is [`DEFAULT_MEM_BUDGET`] (4 GiB); `uvt render --mem-budget 8G` raises it.
//! Scene and OBJ files are read only if they are regular files of at most [`FILE_MAX_BYTES`].

use std::io::Read;
use std::path::Path;

use anyhow::{bail, Context, Result};

/// Default memory budget of one scene: 4 GiB.
pub const DEFAULT_MEM_BUDGET: u64 = 4 << 30;

/// Largest scene or OBJ file read: 256 MiB.
pub const FILE_MAX_BYTES: u64 = 256 << 20;

/// Bytes per pixel of the images and maps `uvt render` keeps (module docs).
pub const PER_PIXEL_BYTES: u64 = 76;

/// Bytes per sample of the frames `uvt render` runs (module docs).
pub const PER_SAMPLE_BYTES: u64 = 7;

/// Bytes of the core frame's set-up triangles alive at once (module docs).
pub const FRAME_SETUP_BYTES: u64 = 8 * (256 << 10);

/// Bytes one triangle costs from mesh to frame (see the module documentation).
pub fn per_triangle_bytes() -> u64 {
    use std::mem::size_of;
    // The f64 reference's frame keeps per triangle its setup's footprint and class or its cull
    // (`crate::frame::reference`), and 4 bytes per band it meets (counted as 8).
    let entry = size_of::<Result<(uvt_core::PixelRect, uvt_core::Class), uvt_core::Cull>>();
    let mesh = size_of::<[u32; 3]>() + size_of::<glam::DVec3>() + 2 * size_of::<[f64; 5]>();
    (2 * size_of::<super::tri::SceneTri>() + mesh + size_of::<uvt_core::Triangle>() + entry + 8)
        as u64
}

/// The estimate for `tris` triangles on `viewport` at `spp` samples per pixel.
pub fn estimate(tris: u64, viewport: (u16, u16), spp: u16) -> u64 {
    let (w, h) = (viewport.0 as u64, viewport.1 as u64);
    let threads = rayon::current_num_threads() as u64;
    tris.saturating_mul(per_triangle_bytes())
        .saturating_add(w * h * PER_PIXEL_BYTES)
        .saturating_add(w * h * spp as u64 * PER_SAMPLE_BYTES)
        .saturating_add(threads * w * 8 * spp as u64 * 11)
        .saturating_add(FRAME_SETUP_BYTES)
}

/// The one budget check of every scene, built-in or from a file: `tris` triangles on `viewport`
/// at `spp` samples per pixel must fit `limit` bytes ([`estimate`]); the error names the
/// estimate and the budget.
pub fn check(tris: u64, viewport: (u16, u16), spp: u16, limit: u64) -> Result<()> {
    let need = estimate(tris, viewport, spp);
    if need > limit {
        bail!(
            "{tris} triangles on {}×{} px at {spp} spp need about {}, over the memory budget of {} \
             (raise it with --mem-budget)",
            viewport.0,
            viewport.1,
            human(need),
            human(limit)
        );
    }
    Ok(())
}

/// `bytes` for people: `1.50 GiB`, `12.0 MiB`, `900 B`.
pub fn human(bytes: u64) -> String {
    const U: [&str; 4] = ["B", "KiB", "MiB", "GiB"];
    let mut x = bytes as f64;
    let mut u = 0;
    while x >= 1024.0 && u + 1 < U.len() {
        x /= 1024.0;
        u += 1;
    }
    if u == 0 {
        format!("{bytes} B")
    } else {
        format!("{x:.2} {}", U[u])
    }
}

/// Parse a size: a whole number of bytes with an optional binary unit K, M, G, T (also KiB…,
/// case-insensitive): `512M`, `8G`, `1048576`.
pub fn parse_size(s: &str) -> Result<u64> {
    let t = s.trim();
    let split = t.find(|c: char| !c.is_ascii_digit()).unwrap_or(t.len());
    let (num, unit) = t.split_at(split);
    let shift = match unit.to_ascii_lowercase().as_str() {
        "" | "b" => 0,
        "k" | "kib" | "kb" => 10,
        "m" | "mib" | "mb" => 20,
        "g" | "gib" | "gb" => 30,
        "t" | "tib" | "tb" => 40,
        _ => bail!("size {s:?}: unknown unit {unit:?} (use e.g. 512M, 8G, or a number of bytes)"),
    };
    let n: u64 = num
        .parse()
        .with_context(|| format!("size {s:?}: expected a whole number with K, M, G or T"))?;
    n.checked_mul(1u64 << shift)
        .filter(|&b| b > 0)
        .with_context(|| format!("size {s:?}: must be between 1 byte and 16 EiB"))
}

/// Read a file that must be a regular file of at most `limit` bytes; errors name the path.
pub fn read_limited(path: &Path, limit: u64, what: &str) -> Result<Vec<u8>> {
    // The OS's reason is part of the message (callers may print only its first line).
    let meta = std::fs::metadata(path)
        .map_err(|e| anyhow::anyhow!("cannot read {what} {}: {e}", path.display()))?;
    if !meta.is_file() {
        bail!("cannot read {what} {}: not a regular file", path.display());
    }
    if meta.len() > limit {
        bail!(
            "{what} {} is {} (limit {})",
            path.display(),
            human(meta.len()),
            human(limit)
        );
    }
    let mut buf = Vec::with_capacity(meta.len() as usize);
    std::fs::File::open(path)
        .and_then(|f| f.take(limit + 1).read_to_end(&mut buf))
        .map_err(|e| anyhow::anyhow!("cannot read {what} {}: {e}", path.display()))?;
    if buf.len() as u64 > limit {
        bail!("{what} {} grew beyond {}", path.display(), human(limit));
    }
    Ok(buf)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes() {
        assert_eq!(parse_size("512M").unwrap(), 512 << 20);
        assert_eq!(parse_size("8G").unwrap(), 8 << 30);
        assert_eq!(parse_size("8gib").unwrap(), 8 << 30);
        assert_eq!(parse_size("1048576").unwrap(), 1 << 20);
        for bad in ["", "G", "1.5G", "-1G", "8X", "0", "99999999999T"] {
            assert!(parse_size(bad).is_err(), "{bad}");
        }
        assert_eq!(human(900), "900 B");
        assert_eq!(human(3 << 29), "1.50 GiB");
    }

    #[test]
    fn estimate_grows_with_every_term() {
        let base = estimate(1000, (64, 64), 4);
        assert!(estimate(2000, (64, 64), 4) - base == 1000 * per_triangle_bytes());
        assert!(estimate(1000, (128, 64), 4) > base);
        assert!(estimate(1000, (64, 64), 8) > base);
        // The examples all exceed the default budget.
        assert!(estimate(16_769_024, (320, 180), 16) > DEFAULT_MEM_BUDGET);
        assert!(estimate(2 * 2048 * 2048, (320, 180), 16) > DEFAULT_MEM_BUDGET);
    }
}
