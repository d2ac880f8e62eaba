//! The coverage bins: one table, each bin with its stable name (`kind.what`), the record kind
//! whose test reports it, and, for a bin no input can reach, the reason. Every door (the CLI's
//! `--coverage`, the C library, the Python module, the campaign) lists bins from here.

macro_rules! bins {
    ($($(#[doc = $doc:literal])* $v:ident = $name:literal, $kind:literal, $why:expr;)*) => {
        /// One decision path of a sample test (the module table).
        #[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
        pub enum Bin {
            $($(#[doc = $doc])* $v,)*
        }

        impl Bin {
            /// Every bin, in index order.
            pub const ALL: &'static [Bin] = &[$(Bin::$v,)*];
            /// How many bins.
            pub const COUNT: usize = Bin::ALL.len();

            /// The stable name, `kind.what`.
            #[must_use]
            #[inline]
            pub const fn name(self) -> &'static str {
                match self {
                    $(Bin::$v => $name,)*
                }
            }

            /// The record kind (`uvt vectors layout`) whose test reports the bin.
            #[must_use]
            #[inline]
            pub const fn kind(self) -> &'static str {
                match self {
                    $(Bin::$v => $kind,)*
                }
            }

            /// Why no input reaches the bin; `None` for a reachable bin.
            #[must_use]
            #[inline]
            pub const fn unreachable(self) -> Option<&'static str> {
                match self {
                    $(Bin::$v => $why,)*
                }
            }
        }
    };
}

const NONE: Option<&str> = None;

bins! {
    /// bounded test, a static triangle
    BsClassStatic = "bsample.class.static", "bsample", NONE;
    /// bounded test, a motion-only triangle
    BsClassMotion = "bsample.class.motion", "bsample", NONE;
    /// bounded test, a defocus-only triangle
    BsClassDefocus = "bsample.class.defocus", "bsample", NONE;
    /// bounded test, a triangle with motion and defocus
    BsClassBoth = "bsample.class.both", "bsample", NONE;
    /// the fast datapath (`Fast::new` accepted the sample)
    BsPathFast = "bsample.path.fast", "bsample", NONE;
    /// the general datapath (T = 2^15, U or V = 2^16, a 2048-pixel side at S = 20)
    BsPathGeneral = "bsample.path.general", "bsample", NONE;
    /// step 1, the lerp's rounding discarded nothing
    BsLerpExact = "bsample.lerp.exact", "bsample", NONE;
    /// step 1, the lerp rounded down
    BsLerpDown = "bsample.lerp.down", "bsample", NONE;
    /// step 1, the lerp rounded up (ties included)
    BsLerpUp = "bsample.lerp.up", "bsample", NONE;
    /// step 2, the lens offset's rounding discarded nothing
    BsLensExact = "bsample.lens.exact", "bsample", NONE;
    /// step 2, the lens offset rounded down
    BsLensDown = "bsample.lens.down", "bsample", NONE;
    /// step 2, the lens offset rounded up (ties included)
    BsLensUp = "bsample.lens.up", "bsample", NONE;
    /// step 4, the grid rounding of a', b' discarded nothing
    BsGridExact = "bsample.grid.exact", "bsample", NONE;
    /// step 4, a', b' rounded down
    BsGridDown = "bsample.grid.down", "bsample", NONE;
    /// step 4, a', b' rounded up (ties included)
    BsGridUp = "bsample.grid.up", "bsample", NONE;
    /// step 5, an edge value E' < 0
    BsEdgeNeg = "bsample.edge.negative", "bsample", NONE;
    /// step 5, an edge value E' = 0 (a fill-rule tie)
    BsEdgeZero = "bsample.edge.zero", "bsample", NONE;
    /// step 5, an edge value E' > 0
    BsEdgePos = "bsample.edge.positive", "bsample", NONE;
    /// step 6, the common path: every w > 0 and no E' = 0
    BsDecideFast = "bsample.decide.fast", "bsample", NONE;
    /// step 6, every w > 0 and some E' = 0: the common sign of the E'
    BsDecideTie = "bsample.decide.tie", "bsample", NONE;
    /// step 6, the rare path: some w <= 0, the sign of Σ E'·w
    BsDecideRare = "bsample.decide.w_le_0", "bsample", NONE;
    /// step 6, orientation negative
    BsOrientNeg = "bsample.orient.negative", "bsample", NONE;
    /// step 6, orientation 0 (mixed or all-zero edge signs, or det' = 0): not covered
    BsOrientZero = "bsample.orient.zero", "bsample", NONE;
    /// step 6, orientation positive
    BsOrientPos = "bsample.orient.positive", "bsample", NONE;
    /// step 7, the tie key puts the sample inside the edge
    BsTieInside = "bsample.tie.inside", "bsample", NONE;
    /// step 7, the tie key puts the sample outside the edge
    BsTieOutside = "bsample.tie.outside", "bsample", NONE;
    /// step 7, the tie key is 0 (the edge's two vertices coincide as (a', b', w))
    BsTieCoincident = "bsample.tie.coincident", "bsample", Some(
        "two coincident vertices make every E' = 0 and det' = 0, so the orientation is 0 and \
         the fill rule is never asked (decide_slow asks it only for a non-zero orientation)"
    );
    /// the sample is covered
    BsCovered = "bsample.covered", "bsample", NONE;
    /// the sample is not covered
    BsMissed = "bsample.missed", "bsample", NONE;
    /// step 8, den <= 0: depth saturated far
    BsDepthDen = "bsample.depth.den_le_0", "bsample", NONE;
    /// step 8, num >= 2^7·den: depth saturated far
    BsDepthFar = "bsample.depth.far", "bsample", NONE;
    /// step 8, num <= -2^7·den: depth saturated near
    BsDepthNear = "bsample.depth.near", "bsample", NONE;
    /// step 8, the quotient 2^31 - 1 clamped to DEPTH_FAR
    BsDepthTop = "bsample.depth.top_clamp", "bsample", NONE;
    /// step 8, the quotient in range
    BsDepthIn = "bsample.depth.in_range", "bsample", NONE;
    /// planar test, an edge value E < 0
    PsEdgeNeg = "psample.edge.negative", "psample", NONE;
    /// planar test, an edge value E = 0 (a fill-rule tie)
    PsEdgeZero = "psample.edge.zero", "psample", NONE;
    /// planar test, an edge value E > 0
    PsEdgePos = "psample.edge.positive", "psample", NONE;
    /// planar test, orientation σ > 0
    PsOrientPos = "psample.orient.positive", "psample", NONE;
    /// planar test, orientation σ < 0
    PsOrientNeg = "psample.orient.negative", "psample", NONE;
    /// planar fill rule decided by the normal's a: inside
    PsTieAInside = "psample.tie.a_inside", "psample", NONE;
    /// planar fill rule decided by the normal's a: outside
    PsTieAOutside = "psample.tie.a_outside", "psample", NONE;
    /// planar fill rule with a = 0, decided by b: inside
    PsTieBInside = "psample.tie.b_inside", "psample", NONE;
    /// planar fill rule with a = 0, decided by b: outside
    PsTieBOutside = "psample.tie.b_outside", "psample", NONE;
    /// planar fill rule with a = b = 0: outside
    PsTieNone = "psample.tie.a_b_zero", "psample", Some(
        "a = b = 0 makes E = c·256WH, zero only for c = 0, a zero normal: its two vertices \
         coincide in the plane, det P' = 0, and setup culls the triangle as degenerate"
    );
    /// the sample is covered
    PsCovered = "psample.covered", "psample", NONE;
    /// the sample is not covered
    PsMissed = "psample.missed", "psample", NONE;
    /// depth, f in 0..63: a floor shift
    PsDepthShift = "psample.depth.shift", "psample", NONE;
    /// depth, f >= 63: the shift capped at 63
    PsDepthShiftCap = "psample.depth.shift_cap", "psample", NONE;
    /// depth, f < 0 with acc = 0
    PsDepthZero = "psample.depth.scale_zero", "psample", NONE;
    /// depth, f < 0: acc·2^-f exact
    PsDepthScale = "psample.depth.scale", "psample", NONE;
    /// depth, f < 0: acc·2^-f overflows i64 and saturates
    PsDepthScaleSat = "psample.depth.scale_saturated", "psample", NONE;
    /// depth clamped to DEPTH_NEAR
    PsDepthNear = "psample.depth.near", "psample", NONE;
    /// depth clamped to DEPTH_FAR
    PsDepthFar = "psample.depth.far", "psample", NONE;
    /// depth in range
    PsDepthIn = "psample.depth.in_range", "psample", NONE;
}

impl Bin {
    /// The bin's position in [`Bin::ALL`] (and in [`super::Counts::n`]).
    #[must_use]
    #[inline]
    pub const fn index(self) -> usize {
        self as usize
    }

    /// The bin called `name`, if any.
    #[must_use]
    #[inline]
    pub fn from_name(name: &str) -> Option<Bin> {
        Bin::ALL.iter().copied().find(|b| b.name() == name)
    }

    /// The record kinds that have bins, in [`Bin::ALL`]'s order.
    pub const KINDS: [&'static str; 2] = ["bsample", "psample"];
}
