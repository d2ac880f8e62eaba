//! The types of `auto`'s rule: what it may pick ([`Pick`]) and one class's tier ([`Tier`]).

use crate::bounds::composed::{hull, hull_edge};
use crate::bounds::laine::Laine2011;
use crate::bounds::strategy::BoundsStrategy;

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
    /// The registry name of the picked strategy: the strategy's own
    /// (`crate::bounds::registry`'s values).
    pub fn name(self) -> &'static str {
        match self {
            Pick::Laine => Laine2011.name(),
            Pick::Hull => hull().name(),
            Pick::HullEdge => hull_edge().name(),
        }
    }
}

/// The rule of one class, by the area `Auto::area` ranks a triangle by (its own extent,
/// pixels): hull+edge-t from `edge_from` on, else the hull from `hull_from` on, else Laine 2011.
/// `u32::MAX` turns a pick off (`edge_from = u32::MAX`: never hull+edge-t; both: always Laine
/// 2011). Every pair of values is a rule (`edge_from ≤ hull_from` leaves the hull out).
/// `edge_travel` limits hull+edge-t to triangles whose own extent is at most `edge_travel`
/// times their own box at the shutter's start (`Auto::start_area`): one that travels further
/// gets the hull instead ([`Tier::pick_travel`]); `u32::MAX`: no limit, and the start box is
/// not computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tier {
    /// the least area that gets the hull
    pub hull_from: u32,
    /// the least area that gets hull+edge-t
    pub edge_from: u32,
    /// the most own extent, as a multiple of the own box at the shutter's start, that keeps
    /// hull+edge-t (`u32::MAX`: no limit)
    pub edge_travel: u32,
}

impl Tier {
    /// Laine 2011 at every area.
    pub const LAINE: Tier = Tier {
        hull_from: u32::MAX,
        edge_from: u32::MAX,
        edge_travel: u32::MAX,
    };

    /// `pick` from `from_px` pixels on, Laine 2011 below.
    pub const fn from(pick: Pick, from_px: u32) -> Tier {
        match pick {
            Pick::Laine => Tier::LAINE,
            Pick::Hull => Tier {
                hull_from: from_px,
                edge_from: u32::MAX,
                edge_travel: u32::MAX,
            },
            Pick::HullEdge => Tier {
                hull_from: u32::MAX,
                edge_from: from_px,
                edge_travel: u32::MAX,
            },
        }
    }

    /// Whether the tier's hull+edge-t depends on the start box (`edge_travel` set).
    pub const fn reads_travel(&self) -> bool {
        self.edge_travel != u32::MAX
    }

    /// The pick for an own extent of `area` pixels whose own box at the shutter's start has
    /// `start` pixels: [`Tier::pick`], with hull+edge-t turned into the hull when `area` is
    /// more than `edge_travel × start` (saturating: a product beyond `u32` is no limit; no
    /// limit at `edge_travel = u32::MAX`).
    pub const fn pick_travel(&self, area: u32, start: u32) -> Pick {
        match self.pick(area) {
            Pick::HullEdge
                if self.reads_travel() && area > start.saturating_mul(self.edge_travel) =>
            {
                Pick::Hull
            }
            p => p,
        }
    }

    /// The pick for an own extent of `area` pixels, the start box left out.
    pub const fn pick(&self, area: u32) -> Pick {
        if area >= self.edge_from {
            Pick::HullEdge
        } else if area >= self.hull_from {
            Pick::Hull
        } else {
            Pick::Laine
        }
    }
}
