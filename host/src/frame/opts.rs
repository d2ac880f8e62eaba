//! What a frame run is asked: viewport, samples per pixel, bounds-tile size, colours, whether to
//! keep the image and the in-band oracle ([`RunOpts`]). Zmax culling is the core's type
//! parameter (`uvt_core::DepthCull`), not an option.

use crate::scene::file::Scene;
use crate::scene::tri::SceneTri;

/// Options of a frame run.
#[derive(Clone)]
pub struct RunOpts<'a> {
    /// viewport (W, H)
    pub vp: (u16, u16),
    /// samples per pixel
    pub spp: u16,
    /// bounds tile size
    pub tile: u8,
    /// triangle colors
    pub colors: &'a [[u8; 3]],
    /// background
    pub clear: [u8; 3],
    /// keep the image
    pub image: bool,
    /// label for the progress bar (shown only when the frame takes more than a second)
    pub label: &'a str,
    /// exact triangles for the in-band oracle's dense sampling (`None`: no oracle;
    /// [`super::oracle`]; the core's frames only)
    pub oracle: Option<&'a [SceneTri]>,
}

impl<'a> RunOpts<'a> {
    /// Options for `scene` with its own viewport, spp and tile size, label = its name, black
    /// background, no image, no oracle; `colors` is `scene.colors()`.
    pub fn for_scene(scene: &'a Scene, colors: &'a [[u8; 3]]) -> RunOpts<'a> {
        RunOpts {
            vp: scene.viewport,
            spp: scene.spp,
            tile: scene.tile,
            colors,
            clear: [0; 3],
            image: false,
            label: &scene.name,
            oracle: None,
        }
    }
}
