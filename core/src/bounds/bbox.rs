//! The bounding-box scan (Laine 2011 "Bbox scan"): every sample of the footprint is tested.

use crate::bounds::strategy::{BoundsStrategy, UvtBox};
use crate::config::unit::Unit;
use crate::input::PixelRect;
use crate::setup::Setup;
use crate::stats::Ops;

/// The bounding-box scan: every sample of the footprint is tested, whatever its (u, v, t)
/// (Laine 2011 "Bbox scan": a box that covers the triangle for all (u, v, t)).
#[derive(Clone, Copy, Debug, Default)]
pub struct BboxScan;

impl BoundsStrategy for BboxScan {
    type Coeffs = ();
    type Tile = UvtBox;
    fn name(&self) -> &'static str {
        "bbox"
    }
    fn prepare<U: Unit>(&self, _: &Setup, _: &mut Ops) {}
    fn tile<U: Unit>(&self, _: &Setup, _: &(), _: PixelRect, _: &mut Ops) -> Option<UvtBox> {
        Some(UvtBox::FULL)
    }
}
