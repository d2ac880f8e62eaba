//! Precision configurations: the fraction bits of positions, t/u/v and the bounds' pixel grid,
//! and which sample test decides ([`Prec`]: exact; [`Bounded`]: the hardware-width test;
//! [`Planar`]: the bounded test plus the planar static test). Sealed: only these three generic
//! types, with their compile-time range checks, implement [`Precision`]; the named
//! configurations of the tools are listed once in [`super::registry`].

/// A precision configuration: the fraction bits of the positions (clip x, y, z, w and CoC), of
/// t/u/v, and of the bound arithmetic (the pixel grid the bounds' box coordinates are rounded to).
///
/// Narrower formats are modelled inside the default containers: a value with F < 16 fraction bits
/// is stored in its I16F16 container with its low 16 − F bits zero (the checked constructors
/// `Triangle::new_with` and `SamplePattern::new_with` refuse anything else). The sample test is
/// exact on its inputs and the bounds round to the configuration's grids, so every output is the
/// one a datapath of exactly these widths produces. The integer bits and the domain are fixed.
///
/// The trait is sealed: [`Prec`] is its only implementor, whose const assertions keep every
/// width inside the ranges the overflow proofs assume (a user impl with, say, 20 position
/// fraction bits would break them). Implementing it outside the crate does not build:
///
/// ```compile_fail,E0277
/// #[derive(Clone, Copy, Debug, Default)]
/// struct Wider;
/// impl uvt_core::Precision for Wider {
///     const POS_FRAC: u32 = 20;
///     const TUV_FRAC: u32 = 16;
///     const BOUND_FRAC: u32 = 16;
/// }
/// ```
pub trait Precision: sealed::Sealed + Copy + Default + core::fmt::Debug + 'static {
    /// fraction bits of positions and CoC (2..=16)
    const POS_FRAC: u32;
    /// fraction bits of t, u, v (2..=16)
    const TUV_FRAC: u32;
    /// fraction bits of the bounds' pixel coordinates (0..=16)
    const BOUND_FRAC: u32;
    /// The sample test's datapath: `None` = the exact test (`sample.rs`); `Some(s)` = the
    /// bounded test (`bounded.rs`) whose sample-relative offsets are rounded to a grid of `2^s`
    /// (s ∈ [`OFFSET_SHIFT_MIN`]..=[`OFFSET_SHIFT_MAX`]).
    const OFFSET_SHIFT: Option<u32> = None;
    /// Whether static triangles (class `Static`) take the planar test (`planar.rs`: each
    /// vertex rounded once to 15 bits, then the exact test on the rounded triangle) instead of
    /// `OFFSET_SHIFT`'s test. Only a
    /// [`Planar`] precision sets it; its other classes run the bounded test.
    const PLANAR: bool = false;
}

mod sealed {
    /// Private supertrait of [`super::Precision`]: only this crate can implement it.
    pub trait Sealed {}
    impl<const POS: u32, const TUV: u32, const BND: u32> Sealed for super::Prec<POS, TUV, BND> {}
    impl<const POS: u32, const TUV: u32, const BND: u32, const OFF: u32> Sealed
        for super::Bounded<POS, TUV, BND, OFF>
    {
    }
    impl<const POS: u32, const TUV: u32, const BND: u32, const OFF: u32> Sealed
        for super::Planar<POS, TUV, BND, OFF>
    {
    }
}

/// The precision with `POS`, `TUV` and `BND` fraction bits (checked at compile time).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Prec<const POS: u32, const TUV: u32, const BND: u32>;

impl<const POS: u32, const TUV: u32, const BND: u32> Precision for Prec<POS, TUV, BND> {
    const POS_FRAC: u32 = {
        assert!(POS >= 2 && POS <= 16, "POS fraction bits must be 2..=16");
        POS
    };
    const TUV_FRAC: u32 = {
        assert!(TUV >= 2 && TUV <= 16, "TUV fraction bits must be 2..=16");
        TUV
    };
    const BOUND_FRAC: u32 = {
        assert!(BND <= 16, "bound fraction bits must be 0..=16");
        BND
    };
}

/// Smallest offset-grid shift of the bounded sample test: with it every rounded offset has
/// |a'| ≤ 2^30 (see `bounded.rs`), so every multiplier operand is ≤ 32 bits.
pub const OFFSET_SHIFT_MIN: u32 = 20;

/// Largest offset-grid shift of the bounded sample test (offsets of ≥ 19 bits with sign; keeps
/// the conservative epsilon < 2^24 raw, inside the bounds' range proofs).
pub const OFFSET_SHIFT_MAX: u32 = 32;

/// A precision with the **bounded** sample test (`bounded.rs`): `POS`, `TUV`, `BND` as in
/// [`Prec`], and the sample-relative offsets rounded to a grid of `2^OFF` raw units
/// (`OFF` ∈ [`OFFSET_SHIFT_MIN`]..=[`OFFSET_SHIFT_MAX`], checked at compile time). Setup and
/// the bounds widen by the conservative epsilon the rounding needs (`setup::eps::Eps`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Bounded<const POS: u32, const TUV: u32, const BND: u32, const OFF: u32>;

impl<const POS: u32, const TUV: u32, const BND: u32, const OFF: u32> Precision
    for Bounded<POS, TUV, BND, OFF>
{
    const POS_FRAC: u32 = <Prec<POS, TUV, BND> as Precision>::POS_FRAC;
    const TUV_FRAC: u32 = <Prec<POS, TUV, BND> as Precision>::TUV_FRAC;
    const BOUND_FRAC: u32 = <Prec<POS, TUV, BND> as Precision>::BOUND_FRAC;
    const OFFSET_SHIFT: Option<u32> = {
        assert!(
            OFF >= OFFSET_SHIFT_MIN && OFF <= OFFSET_SHIFT_MAX,
            "OFF must be OFFSET_SHIFT_MIN..=OFFSET_SHIFT_MAX"
        );
        Some(OFF)
    };
}

/// A precision with the **planar static** test (`planar.rs`, name `planar-POS-TUV-BND-OFF`):
/// exactly [`Bounded<POS, TUV, BND, OFF>`] for the moving and defocused classes, and for static
/// triangles (class `Static`, camera-plane crossers included) the planar test — each vertex
/// rounded once to 15 bits (per-vertex shift), the exact i32 edge normals of the rounded
/// triangle, three 32 × 32 dot products per sample: watertight at edges and vertices — with a
/// per-triangle conservative epsilon (the rounding residual, `sample::planar`). An addition: the default
/// configuration is unchanged.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Planar<const POS: u32, const TUV: u32, const BND: u32, const OFF: u32>;

impl<const POS: u32, const TUV: u32, const BND: u32, const OFF: u32> Precision
    for Planar<POS, TUV, BND, OFF>
{
    const POS_FRAC: u32 = <Bounded<POS, TUV, BND, OFF> as Precision>::POS_FRAC;
    const TUV_FRAC: u32 = <Bounded<POS, TUV, BND, OFF> as Precision>::TUV_FRAC;
    const BOUND_FRAC: u32 = <Bounded<POS, TUV, BND, OFF> as Precision>::BOUND_FRAC;
    const OFFSET_SHIFT: Option<u32> = <Bounded<POS, TUV, BND, OFF> as Precision>::OFFSET_SHIFT;
    const PLANAR: bool = true;
}

/// The planar static configuration beside the default (`planar-16-16-16-20`): the default's
/// bounded test for every moving or defocused class, the planar test for static triangles.
pub type PlanarPrecision = Planar<16, 16, 16, 20>;

/// The hardware-plausible bounded configuration (`bounded-16-16-16-20`): 16 fraction bits
/// everywhere, offsets on a `2^20` grid (i32 multiplier operands, i64 products). The default.
pub type BoundedPrecision = Bounded<16, 16, 16, 20>;

/// The exact configuration (`exact-16-16-16`): 16 fraction bits everywhere and the exact sample
/// test of `sample.rs`. Always built and tested beside the default; the committed golden
/// vectors are of this configuration.
pub type Exact = Prec<16, 16, 16>;

/// The default configuration: the bounded (hardware-width) sample test, [`BoundedPrecision`].
pub type DefaultPrecision = BoundedPrecision;

/// The fraction bits of a [`Precision`], carried at run time by a setup. Only built from a
/// [`Precision`] ([`PrecisionBits::of`]), so `pos`, `tuv` ∈ 2..=16 and `bnd` ∈ 0..=16.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PrecisionBits {
    pos: u32,
    tuv: u32,
    bnd: u32,
    off: Option<u32>,
    planar: bool,
}

impl PrecisionBits {
    /// Fraction bits of positions (2..=16).
    pub const fn pos(&self) -> u32 {
        self.pos
    }
    /// Fraction bits of t, u, v (2..=16).
    pub const fn tuv(&self) -> u32 {
        self.tuv
    }
    /// Fraction bits of the bounds' pixel coordinates (0..=16).
    pub const fn bnd(&self) -> u32 {
        self.bnd
    }
    /// The offset-grid shift of the bounded sample test ([`OFFSET_SHIFT_MIN`]..=
    /// [`OFFSET_SHIFT_MAX`]), `None` for the exact test.
    pub const fn offset_shift(&self) -> Option<u32> {
        self.off
    }
    /// Whether static triangles take the planar test ([`Precision::PLANAR`]).
    pub const fn planar(&self) -> bool {
        self.planar
    }
    /// The bits of `P`.
    pub const fn of<P: Precision>() -> PrecisionBits {
        PrecisionBits {
            pos: P::POS_FRAC,
            tuv: P::TUV_FRAC,
            bnd: P::BOUND_FRAC,
            off: P::OFFSET_SHIFT,
            planar: P::PLANAR,
        }
    }
    /// The default's.
    pub const DEFAULT: PrecisionBits = PrecisionBits::of::<DefaultPrecision>();
}
