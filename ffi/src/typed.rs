//! The typed API, for callers who do not want records: a triangle, its viewport and a
//! configuration make a handle (setup once); the handle and a sample give coverage, depth and the
//! edge values, as the configuration's sample test computes them — the bounded test of
//! `bounded-…` configurations, and of a `planar-…` one's moving and defocused triangles; the
//! planar test of a `planar-…` configuration's static triangles. Exact configurations have
//! 192-bit edge values: use the records (`uvt_sample`). The logic is `uvt_records::typed`'s, shared
//! with the Python module; this file is its C boundary.

use std::ffi::c_char;

use uvt_records::typed::{Hit, Tri, TypedError, TRI_WORDS};

use crate::error::{c_str, guard, words, Fail, UVT_ERR_CONFIG, UVT_ERR_NULL, UVT_OK};

/// A triangle set up at one configuration (opaque to C; made by `uvt_tri_new`, freed by
/// `uvt_tri_free`).
// `uvt_records::typed::Tri`, the one implementation the Python module shares.
pub struct UvtTri {
    tri: Tri,
}

/// The result of one sample test.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct UvtHit {
    /// 1 when the sample is covered
    pub covered: i32,
    /// orientation: the bounded test's sign of Σ E'·w, the planar test's σ (−1, 0, 1)
    pub det_sign: i32,
    /// depth (`DEPTH_FRAC` = 24 fraction bits), 0 when not covered
    pub depth: i32,
    /// edge values E'_k (bounded: on the offset grid) or E_k (planar: exact)
    pub e: [i64; 3],
}

impl From<Hit> for UvtHit {
    fn from(h: Hit) -> UvtHit {
        UvtHit {
            covered: i32::from(h.covered),
            det_sign: h.det_sign,
            depth: h.depth,
            e: h.e,
        }
    }
}

impl From<TypedError> for Fail {
    fn from(e: TypedError) -> Fail {
        match e {
            TypedError::Config(m) => Fail::new(UVT_ERR_CONFIG, m),
            TypedError::Input(m) => Fail::input(m),
        }
    }
}

/// Set up a triangle: `verts` is 30 raw I16F16 words (a `bsample_in` record's words 0..29: key
/// frame 0 vertices 0..2 with x, y, z, w, CoC each, then key frame 1), the viewport `vp_w` ×
/// `vp_h`, `config` a registry name (null: the default, `bounded-16-16-16-20`). On success
/// `*out` holds a handle for `uvt_tri_sample`, freed by `uvt_tri_free`. Returns 0 or a
/// `UVT_ERR_*` code (an exact configuration: `UVT_ERR_CONFIG`).
///
/// # Safety
/// `verts` points to 30 readable words, `config` is null or a NUL-terminated string, `out` is a
/// writable pointer.
#[no_mangle]
pub unsafe extern "C" fn uvt_tri_new(
    verts: *const i32,
    vp_w: u16,
    vp_h: u16,
    config: *const c_char,
    out: *mut *mut UvtTri,
) -> i32 {
    guard(|| {
        if out.is_null() {
            return Err(Fail::new(UVT_ERR_NULL, "out: null pointer"));
        }
        // SAFETY: the caller's contract.
        let (v, c) = unsafe {
            (
                words(verts.cast(), TRI_WORDS, "verts")?,
                c_str(config, "config")?,
            )
        };
        let v: &[u32; TRI_WORDS] = v
            .try_into()
            .map_err(|_| Fail::input("verts: not 30 words"))?;
        let t = UvtTri {
            tri: Tri::new(v, vp_w, vp_h, c)?,
        };
        // SAFETY: `out` is non-null and writable (the caller's contract); the box is released
        // by `uvt_tri_free`.
        unsafe { *out = Box::into_raw(Box::new(t)) };
        Ok(UVT_OK)
    })
}

/// The sample test of handle `tri` at position (`xs`, `ys`) in 1/256 px and `t`, `u`, `v` (raw,
/// 16 fraction bits, on the configuration's grid; ignored by the planar test) into `hit`.
/// Returns 0 or a `UVT_ERR_*` code.
///
/// # Safety
/// `tri` is a live handle of `uvt_tri_new` (or null), `hit` a writable pointer.
#[no_mangle]
pub unsafe extern "C" fn uvt_tri_sample(
    tri: *const UvtTri,
    xs: u32,
    ys: u32,
    t: i32,
    u: i32,
    v: i32,
    hit: *mut UvtHit,
) -> i32 {
    guard(|| {
        if tri.is_null() || hit.is_null() {
            return Err(Fail::new(UVT_ERR_NULL, "tri or hit: null pointer"));
        }
        // SAFETY: a live handle (the caller's contract).
        let h = unsafe { &*tri }.tri.sample(xs, ys, t, u, v)?;
        // SAFETY: non-null and writable (the caller's contract).
        unsafe { *hit = h.into() };
        Ok(UVT_OK)
    })
}

/// The class of handle `tri` (0 static, 1 motion, 2 defocus, 3 both; bit 0 motion, bit 1
/// defocus), or `UVT_ERR_NULL`.
///
/// # Safety
/// `tri` is a live handle of `uvt_tri_new` or null.
#[no_mangle]
pub unsafe extern "C" fn uvt_tri_class(tri: *const UvtTri) -> i32 {
    guard(|| {
        if tri.is_null() {
            return Err(Fail::new(UVT_ERR_NULL, "tri: null pointer"));
        }
        // SAFETY: a live handle (the caller's contract).
        Ok(unsafe { &*tri }.tri.class().index() as i32)
    })
}

/// Free a handle of `uvt_tri_new` (null: nothing).
///
/// # Safety
/// `tri` is null or a handle of `uvt_tri_new` not freed before; it is invalid afterwards.
#[no_mangle]
pub unsafe extern "C" fn uvt_tri_free(tri: *mut UvtTri) {
    if !tri.is_null() {
        // SAFETY: made by `Box::into_raw` in `uvt_tri_new`, freed once (the caller's contract).
        drop(unsafe { Box::from_raw(tri) });
    }
}
