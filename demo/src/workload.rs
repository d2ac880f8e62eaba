//! A frame's work as a file — the triangles, viewport, sample table and bounds-tile size of a
//! bench row (`uvt m4-workload` writes it) — and the per-stage workload the Cortex-M strategy
//! harness (`examples/m4_stages`) measures on it for every bounds strategy.
//!
//! **Format** (version [`VERSION`]): little-endian 32-bit words.
//!
//! | word | field |
//! |---|---|
//! | 0 | [`MAGIC`] (`"UVTW"`) |
//! | 1 | [`VERSION`] |
//! | 2, 3 | viewport width, height (pixels) |
//! | 4, 5 | samples per pixel S, block side N |
//! | 6 | bounds-tile size (1, 2, 4 or 8) |
//! | 7 | the position grid's fraction bits (`Precision::POS_FRAC`) the triangles lie on |
//! | 8 | `every`: the file holds every `every`-th triangle of the row (1: all) |
//! | 9, 10 | number of samples (N²·S), number of triangles T |
//! | 11 … | N²·S samples, 5 words each: sub-pixel x, sub-pixel y (u8 bits), u, v, t (raw) |
//! | … | T triangles, 30 words each: t = 0 then t = 1, vertices 0..3, each x, y, z, w, CoC raw |
//! | last | FNV-1a 32 of every byte before it |
//!
//! Generator ([`encode`]) and reader ([`Workload::parse`]) share [`HEADER_WORDS`],
//! [`SAMPLE_WORDS`] and [`TRI_WORDS`]; the reader refuses a wrong magic, version, length or
//! checksum and builds every sample and triangle through the core's checked constructors.
//!
//! **Stages** ([`stages`]): every triangle is set up once (with the strategy's preparation),
//! then its footprint is walked three times, band by band (8 rows, full width: the same tiles
//! and row spans as the host's frames, `uvt_core::raster::engine`): the tile walk alone (row spans and tile bounds), the walk with every sample of every
//! kept tile put through the box and predicate, and the walk with the sample test of every
//! admitted sample. The caller's `lap` (instructions since its last call, on the Cortex-M)
//! after each part gives setup, walk, predicate (= second − first walk: the sample loop, box
//! test and predicate) and sample test (= third − second walk) per triangle.

use core::hint::black_box;

use uvt_core::bounds::strategy::{Admit, BoundsStrategy, CellVisitor};
use uvt_core::config::formats::{Lens, SubPixel, Time};
use uvt_core::config::unit::Full;
use uvt_core::units::select::{PipelineOf, Select};
use uvt_core::{
    Error, Ops, Outcome, Pipeline, PixelRect, Precision, Sample, SamplePattern, ScreenPos,
    Triangle, Vertex, Viewport,
};

/// Word 0.
pub const MAGIC: u32 = u32::from_le_bytes(*b"UVTW");
/// Word 1.
pub const VERSION: u32 = 1;
/// Header words (0..11).
pub const HEADER_WORDS: usize = 11;
/// Words per sample.
pub const SAMPLE_WORDS: usize = 5;
/// Words per triangle.
pub const TRI_WORDS: usize = 30;
/// Rows of one band of the walk (full-width bands of any height walk the same tiles and rows).
pub const BAND: u16 = 8;

/// The bits of an `i32` as a word.
fn bits(x: i32) -> u32 {
    u32::from_le_bytes(x.to_le_bytes())
}

/// A word's bits as an `i32`.
fn signed(w: u32) -> i32 {
    i32::from_le_bytes(w.to_le_bytes())
}

/// FNV-1a 32 over bytes, continued from `h`.
fn fnv(mut h: u32, bytes: &[u8]) -> u32 {
    for b in bytes {
        h = (h ^ u32::from(*b)).wrapping_mul(0x0100_0193);
    }
    h
}
const FNV_START: u32 = 0x811c_9dc5;

/// What is wrong with a workload file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FormatError {
    /// Shorter than its header and checksum, or not a whole number of words.
    Length,
    /// Word 0 is not [`MAGIC`].
    Magic,
    /// Word 1 is not [`VERSION`] (the word found).
    Version(u32),
    /// The sample or triangle count disagrees with the file's length or the pattern's shape.
    Counts,
    /// The checksum word disagrees with the bytes.
    Checksum,
    /// A header value out of range (its word index).
    Header(usize),
    /// The core refused a value (viewport, sample or triangle).
    Core(Error),
}

impl core::fmt::Display for FormatError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            FormatError::Length => write!(f, "workload: not a whole header, body and checksum"),
            FormatError::Magic => write!(f, "workload: word 0 is not \"UVTW\""),
            FormatError::Version(v) => write!(f, "workload: version {v}, expected {VERSION}"),
            FormatError::Counts => write!(f, "workload: counts disagree with the length"),
            FormatError::Checksum => write!(f, "workload: checksum mismatch"),
            FormatError::Header(i) => write!(f, "workload: header word {i} out of range"),
            FormatError::Core(e) => write!(f, "workload: {e}"),
        }
    }
}

/// The header of a workload.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Header {
    /// viewport
    pub vp: Viewport,
    /// samples per pixel
    pub spp: u16,
    /// pattern block side
    pub block: u16,
    /// bounds-tile size
    pub bounds_tile: u8,
    /// the triangles' position fraction bits
    pub pos_frac: u32,
    /// every `every`-th triangle of the row
    pub every: u32,
}

/// Write a workload: `emit` receives every word in order (checksum last).
pub fn encode(h: &Header, samples: &[Sample], tris: &[Triangle], mut emit: impl FnMut(u32)) {
    let mut sum = FNV_START;
    let mut put = |w: u32| {
        sum = fnv(sum, &w.to_le_bytes());
        emit(w);
    };
    let len = |n: usize| u32::try_from(n).unwrap_or(u32::MAX);
    for w in [
        MAGIC,
        VERSION,
        u32::from(h.vp.width()),
        u32::from(h.vp.height()),
        u32::from(h.spp),
        u32::from(h.block),
        u32::from(h.bounds_tile),
        h.pos_frac,
        h.every,
        len(samples.len()),
        len(tris.len()),
    ] {
        put(w);
    }
    for s in samples {
        put(u32::from(s.sx().to_bits()));
        put(u32::from(s.sy().to_bits()));
        for x in [s.u().to_bits(), s.v().to_bits(), s.t().to_bits()] {
            put(bits(x));
        }
    }
    for t in tris {
        for time in 0..2 {
            for v in t.vertices(time) {
                for x in v.bits() {
                    put(bits(x));
                }
            }
        }
    }
    emit(sum);
}

/// A checked workload over its bytes.
#[derive(Clone, Copy, Debug)]
pub struct Workload<'a> {
    header: Header,
    samples: &'a [u8],
    tris: &'a [u8],
}

/// Word `i` of `b` (little-endian; 0 past the end — the parser checks lengths first).
fn word(b: &[u8], i: usize) -> u32 {
    let at = i.saturating_mul(4);
    match b.get(at..at.saturating_add(4)) {
        Some(&[a, b, c, d]) => u32::from_le_bytes([a, b, c, d]),
        _ => 0,
    }
}

impl<'a> Workload<'a> {
    /// Check magic, version, counts and checksum, and the header's values.
    pub fn parse(bytes: &'a [u8]) -> Result<Workload<'a>, FormatError> {
        if bytes.len() % 4 != 0 || bytes.len() < (HEADER_WORDS + 1) * 4 {
            return Err(FormatError::Length);
        }
        if word(bytes, 0) != MAGIC {
            return Err(FormatError::Magic);
        }
        if word(bytes, 1) != VERSION {
            return Err(FormatError::Version(word(bytes, 1)));
        }
        let words = bytes.len() / 4;
        let body = words.saturating_sub(1);
        let (ns, nt) = (word(bytes, 9) as usize, word(bytes, 10) as usize);
        let need = ns
            .checked_mul(SAMPLE_WORDS)
            .and_then(|a| a.checked_add(nt.checked_mul(TRI_WORDS)?))
            .and_then(|a| a.checked_add(HEADER_WORDS));
        if need != Some(body) {
            return Err(FormatError::Counts);
        }
        // body < bytes.len() / 4: in range.
        let (head, rest) = bytes.split_at(body.saturating_mul(4));
        if fnv(FNV_START, head) != word(rest, 0) {
            return Err(FormatError::Checksum);
        }
        let small = |i: usize, max: u32| {
            let w = word(bytes, i);
            if w == 0 || w > max {
                Err(FormatError::Header(i))
            } else {
                Ok(w)
            }
        };
        let short = |i: usize, max: u16| {
            small(i, u32::from(max))
                .and_then(|w| u16::try_from(w).map_err(|_| FormatError::Header(i)))
        };
        let vp = Viewport::new(short(2, 2048)?, short(3, 2048)?).map_err(FormatError::Core)?;
        let bounds_tile = u8::try_from(short(6, 8)?).map_err(|_| FormatError::Header(6))?;
        if !bounds_tile.is_power_of_two() {
            return Err(FormatError::Header(6));
        }
        let header = Header {
            vp,
            spp: short(4, 64)?,
            block: short(5, 64)?,
            bounds_tile,
            pos_frac: small(7, 16)?,
            every: small(8, u32::MAX)?,
        };
        // The counts were checked against the length above: both splits are in range.
        let (samples, tris) = head
            .get(HEADER_WORDS.saturating_mul(4)..)
            .unwrap_or(&[])
            .split_at(ns.saturating_mul(SAMPLE_WORDS).saturating_mul(4));
        Ok(Workload {
            header,
            samples,
            tris,
        })
    }

    /// The header.
    pub fn header(&self) -> &Header {
        &self.header
    }

    /// The samples, through [`Sample::new`].
    pub fn samples(&self) -> impl Iterator<Item = Result<Sample, FormatError>> + 'a {
        self.samples.chunks_exact(SAMPLE_WORDS * 4).map(|c| {
            let w = |i| word(c, i);
            let sub = |x: u32| u8::try_from(x).map(SubPixel::from_bits);
            let (Ok(sx), Ok(sy)) = (sub(w(0)), sub(w(1))) else {
                return Err(FormatError::Counts);
            };
            Sample::new(
                sx,
                sy,
                Lens::from_bits(signed(w(2))),
                Lens::from_bits(signed(w(3))),
                Time::from_bits(signed(w(4))),
            )
            .map_err(FormatError::Core)
        })
    }

    /// The triangles, through [`Triangle::new_with`] at precision `P` (its position grid must
    /// be the file's).
    pub fn triangles<P: Precision>(
        &self,
    ) -> impl Iterator<Item = Result<Triangle, FormatError>> + 'a {
        let grid_ok = P::POS_FRAC == self.header.pos_frac;
        self.tris.chunks_exact(TRI_WORDS * 4).map(move |c| {
            if !grid_ok {
                return Err(FormatError::Header(7));
            }
            let v = |time: usize, k: usize| {
                let at = time.saturating_mul(3).saturating_add(k).saturating_mul(5);
                Vertex::from_bits([0, 1, 2, 3, 4].map(|i| signed(word(c, at.saturating_add(i)))))
            };
            Triangle::new_with::<P>([v(0, 0), v(0, 1), v(0, 2)], [v(1, 0), v(1, 1), v(1, 2)])
                .map_err(FormatError::Core)
        })
    }
}

/// Counts and instructions of [`stages`] over a workload.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StageCost {
    /// triangles set up
    pub triangles: u64,
    /// visible ones
    pub visible: u64,
    /// bounds tiles visited (footprint cells, in and out of the row spans)
    pub tiles: u64,
    /// samples of kept tiles put through the box and predicate
    pub admits: u64,
    /// samples tested
    pub tested: u64,
    /// samples covered
    pub covered: u64,
    /// the core's operation counts of the last walk (setup, bounds, rows, predicate, sample)
    pub ops: [u64; 5],
    /// instructions: setup, tile walk, predicate, sample test (from `lap`)
    pub insn: [u64; 4],
}

impl StageCost {
    /// Add `o`'s counts, ops and instructions.
    pub fn add(&mut self, o: &StageCost) {
        for (a, b) in [
            (&mut self.triangles, o.triangles),
            (&mut self.visible, o.visible),
            (&mut self.tiles, o.tiles),
            (&mut self.admits, o.admits),
            (&mut self.tested, o.tested),
            (&mut self.covered, o.covered),
        ] {
            *a = a.saturating_add(b);
        }
        for (a, b) in self.ops.iter_mut().zip(o.ops) {
            *a = a.saturating_add(b);
        }
        for (a, b) in self.insn.iter_mut().zip(o.insn) {
            *a = a.saturating_add(b);
        }
    }
}

/// One triangle's [`StageCost`] (its `insn` left 0), the signed instruction laps of its parts
/// (setup, walk, walk + predicate − walk, full walk − walk + predicate) and its footprint
/// (`None`: culled).
#[derive(Clone, Copy, Debug, Default)]
pub struct TriCost {
    /// counts and core ops
    pub cost: StageCost,
    /// instruction laps (module docs; may be negative by one `lap` resolution)
    pub laps: [i64; 4],
    /// footprint of a visible triangle
    pub footprint: Option<PixelRect>,
}

/// One pass of [`stage_one`]'s walk over a triangle's cells: pass 0 the tile walk alone, pass 1
/// with every sample of a kept tile put through the tile's [`Admit`], pass 2 with the sample
/// test of every admitted sample; counts tiles, admits, tested and covered samples.
struct Passes<'a, 'p, L: Pipeline> {
    entry: &'a L::Entry,
    pattern: &'a SamplePattern<'p>,
    pass: usize,
    n: [u64; 4],
}

impl<L: Pipeline> CellVisitor for Passes<'_, '_, L> {
    fn cell<T: Admit>(&mut self, cell: PixelRect, tile: Option<T>, ops: &mut Ops) {
        let [tiles, admits, tested, covered] = &mut self.n;
        *tiles = tiles.wrapping_add(1);
        let Some(tile) = tile else {
            return;
        };
        // Every pass does the work of the passes before it with the same instructions: the
        // kept tile through `black_box` in all three; in passes 1 and 2 every admit's answer
        // branched on and counted, the count through `black_box` once per cell (so the answer
        // cannot be dropped); only pass 2 goes on to the sample test. (Before, pass 1 alone put
        // every admit's answer through `black_box`, which spills the loop's registers: the
        // difference charged that to the predicate and took it off the sample test, near zero
        // on the full-size dense rows with ten to twenty admits per test.)
        let tile = black_box(tile);
        if self.pass == 0 {
            return;
        }
        for py in cell.y0..cell.y1 {
            for px in cell.x0..cell.x1 {
                for s in self.pattern.pixel(px, py) {
                    *admits = admits.wrapping_add(1);
                    if !tile.admit(s, ops) {
                        continue;
                    }
                    *tested = tested.wrapping_add(1);
                    if self.pass == 1 {
                        continue;
                    }
                    let hit = L::test(self.entry, ScreenPos::of(px, py, s), s, ops);
                    L::count(hit.is_some(), ops);
                    *covered = covered.wrapping_add(u64::from(hit.is_some()));
                }
            }
        }
        black_box(*tested);
    }
}

/// Setup, then the three walks (module docs) of one triangle through pipeline `pipe`.
pub fn stage_one<L: Pipeline>(
    pipe: &L,
    tri: &Triangle,
    vp: Viewport,
    bt: u16,
    pattern: &SamplePattern<'_>,
    lap: &mut impl FnMut() -> u64,
) -> TriCost {
    let lap_i = |l: &mut dyn FnMut() -> u64| i64::try_from(l()).unwrap_or(i64::MAX);
    let mut t = TriCost::default();
    let c = &mut t.cost;
    let mut ops = Ops::default();
    c.triangles = 1;
    let _ = lap();
    let out = pipe.setup(black_box(tri), vp, &mut ops);
    t.laps[0] = lap_i(lap);
    c.ops[0] = ops.setup;
    let Outcome::Visible(e) = out else {
        return t;
    };
    c.visible = 1;
    let fp = L::footprint(&e);
    t.footprint = Some(fp);
    let mut spent = [0i64; 3];
    for (pass, slot) in spent.iter_mut().enumerate() {
        let mut ops = Ops::default();
        let mut v = Passes::<L> {
            entry: &e,
            pattern,
            pass,
            n: [0; 4],
        };
        let _ = lap();
        let mut y = fp.y0.saturating_sub(fp.y0.checked_rem(BAND).unwrap_or(0));
        while y < fp.y1 {
            let band = PixelRect {
                x0: 0,
                y0: y,
                x1: vp.width(),
                y1: y.saturating_add(BAND).min(vp.height()),
            };
            let region = fp.intersect(&band);
            pipe.walk(&e, region, bt, &mut ops, &mut v);
            y = y.saturating_add(BAND);
        }
        *slot = lap_i(lap);
        if pass == 2 {
            [c.tiles, c.admits, c.tested, c.covered] = v.n;
            c.ops[1] = ops.bounds;
            c.ops[2] = ops.rows;
            c.ops[3] = ops.predicate;
            c.ops[4] = ops.sample;
        }
    }
    let [w0, w1, w2] = spent;
    t.laps[1] = w0;
    t.laps[2] = w1.saturating_sub(w0);
    t.laps[3] = w2.saturating_sub(w1);
    t
}

/// Every triangle of `w` with strategy `b` at precision `P` on the full unit ([`stage_one`]),
/// summed per class of the triangle ([`uvt_core::Class::index`]; a culled triangle counts its
/// setup in its class): counts, and the instructions `lap` reports (instructions since its
/// previous call; the host passes a closure returning 0). A stage's instructions may come out
/// below the true figure by up to one `lap` resolution per triangle; the sums are clamped at 0.
pub fn stages<P, B>(
    b: B,
    w: &Workload<'_>,
    pattern: &SamplePattern<'_>,
    lap: &mut impl FnMut() -> u64,
) -> Result<[StageCost; 4], FormatError>
where
    B: BoundsStrategy,
    (P, Full): Select<B>,
    P: Precision,
{
    let pipe = PipelineOf::<B, P, Full>::new(b);
    let vp = w.header.vp;
    let bt = u16::from(w.header.bounds_tile);
    let mut all = [StageCost::default(); 4];
    let mut parts = [[0i64; 4]; 4];
    for tri in w.triangles::<P>() {
        let tri = tri?;
        let k = tri.class().index();
        let (Some(c), Some(part)) = (all.get_mut(k), parts.get_mut(k)) else {
            continue;
        };
        let t = stage_one(&pipe, &tri, vp, bt, pattern, lap);
        c.add(&t.cost);
        for (a, b) in part.iter_mut().zip(t.laps) {
            *a = a.saturating_add(b);
        }
    }
    for (c, part) in all.iter_mut().zip(parts) {
        c.insn = part.map(|x| u64::try_from(x).unwrap_or(0));
    }
    Ok(all)
}
