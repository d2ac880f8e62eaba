//! The types of `auto`'s rule: what it may pick ([`Pick`]) and one class's tier ([`Tier`]).

/// A strategy `auto` may pick for a triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pick {
    /// Laine 2011
    Laine,
    /// swept-hull tile culling in front of Laine 2011 ("hull")
    Hull,
    /// hull culling in front of the edge-direction time bound ("hull+edge-t")
    HullEdge,
}

impl Pick {
    /// Every pick, in order of setup cost.
    pub const ALL: [Pick; 3] = [Pick::Laine, Pick::Hull, Pick::HullEdge];
    /// The registry name of the picked strategy.
    pub const fn name(self) -> &'static str {
        match self {
            Pick::Laine => "laine2011",
            Pick::Hull => "hull",
            Pick::HullEdge => "hull+edge-t",
        }
    }
}

/// The rule of one class: below `from_px` footprint pixels Laine 2011, from there on `heavy`
/// (`from_px = u32::MAX`: always Laine 2011).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tier {
    /// the strategy of large triangles
    pub heavy: Pick,
    /// the least footprint area (pixels) that gets `heavy`
    pub from_px: u32,
}

impl Tier {
    /// The pick for a footprint of `area` pixels.
    pub const fn pick(&self, area: u32) -> Pick {
        if area >= self.from_px {
            self.heavy
        } else {
            Pick::Laine
        }
    }
}
