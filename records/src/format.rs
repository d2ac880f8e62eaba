//! The golden-vector file format, shared by the generator and the checker.
//!
//! Every file is text: one record per line, each record the same number of 32-bit words written
//! as 8 hex digits (lower case) separated by one space, so Verilog's `$readmemh` loads a file
//! into `reg [31:0] mem [0:records*words-1]` with word `w` of record `r` at `mem[r*words + w]`.
//! Values are two's complement. A field of up to 32 bits sits in one word at a bit offset; a wider
//! field takes `ceil(width/32)` whole words, most significant word first, sign-extended.
//! The layout of every file is defined once here ([`layout`]); the manifest, the checker and the
//! README tables are generated from it.

use serde::Serialize;
use sha2::{Digest, Sha256};

/// Version of this format (bump on any layout change). 2: the bounded sample-test records
/// `bsample_{in,out}` (self-contained, no setup index). 3: the planar sample-test records
/// `psample_{in,out}` (no earlier file's layout or bytes changed; a version-2 checker refuses
/// the set by its version instead of skipping files it does not know). 4: `setup_in` names its
/// configuration (word 31, [`CONFIG_FIELDS`]), so setup, bounds and the exact sample test are of
/// any registry configuration; `setup_out` puts the architectural outputs first and gains the
/// conservative epsilon (`eps_x`, `eps_y`, `eps_w`) before the internal coefficients.
pub const FORMAT_VERSION: u32 = 4;

/// The packed configuration word of `setup_in` (LSB first): datapath (0 exact, 1 bounded,
/// 2 planar), fraction bits of positions, of t/u/v, of the bounds' grid, and the offset shift
/// (0 for an exact configuration).
pub const CONFIG_FIELDS: [(&str, u32, bool); 5] = [
    ("datapath", 2, false),
    ("pos_frac", 5, false),
    ("tuv_frac", 5, false),
    ("bnd_frac", 5, false),
    ("off_shift", 6, false),
];

/// The fields of `setup_out` a setup unit must produce (what `--arch-only` checks): visibility,
/// cull reason, class, the footprint, the time span, the lens-corner boxes (the per-tile
/// bounds' inputs) with their presence bits, and the conservative epsilon: every field of words
/// 0..=23 but the Laine 2011 presence bits `lens_x`, `lens_y`, `dual_x`, `dual_y`. The Laine
/// coefficients (those bits and words 24..=107, `lens_*`, `dual_*`) are the model's own
/// intermediate values, optional to check (the bounds unit `vectors/rtl/uvt_bounds.v` reads them).
pub const SETUP_ARCHITECTURAL: [&str; 24] = [
    "visible",
    "cull",
    "class",
    "box_x_lo",
    "box_x_hi",
    "box_y_lo",
    "box_y_hi",
    "fp_x0",
    "fp_y0",
    "fp_x1",
    "fp_y1",
    "span_lo",
    "span_hi",
    "box_x_lo0",
    "box_x_lo1",
    "box_x_hi0",
    "box_x_hi1",
    "box_y_lo0",
    "box_y_lo1",
    "box_y_hi0",
    "box_y_hi1",
    "eps_x",
    "eps_y",
    "eps_w",
];

/// One field of a record.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct RecField {
    /// name
    pub name: String,
    /// first (most significant) word
    pub word: u32,
    /// bit offset of the LSB inside the word (0 for multi-word fields)
    pub bit: u32,
    /// width in bits
    pub width: u32,
    /// two's complement signed
    pub signed: bool,
    /// fraction bits (value = raw / 2^frac)
    pub frac: u32,
}

impl RecField {
    /// Words the field spans.
    pub fn words(&self) -> u32 {
        if self.width <= 32 {
            1
        } else {
            self.width.div_ceil(32)
        }
    }
}

/// A record layout under construction.
#[derive(Default)]
pub struct Layout {
    /// fields in word order
    pub fields: Vec<RecField>,
    /// words per record
    pub words: u32,
}

impl Layout {
    /// A whole-word field (or several words for width > 32).
    pub fn w(mut self, name: &str, width: u32, signed: bool, frac: u32) -> Self {
        let f = RecField {
            name: name.into(),
            word: self.words,
            bit: 0,
            width,
            signed,
            frac,
        };
        self.words += f.words();
        self.fields.push(f);
        self
    }
    /// A word of packed sub-fields `(name, width, signed)`, LSB first.
    pub fn packed(mut self, subs: &[(&str, u32, bool)]) -> Self {
        let mut bit = 0;
        for (name, width, signed) in subs {
            self.fields.push(RecField {
                name: (*name).into(),
                word: self.words,
                bit,
                width: *width,
                signed: *signed,
                frac: 0,
            });
            bit += width;
        }
        self.words += 1;
        self
    }
}

fn tri_fields(l: Layout) -> Layout {
    let mut l = l;
    for t in 0..2 {
        for k in 0..3 {
            for f in ["x", "y", "z", "w", "coc"] {
                l = l.w(&format!("t{t}_v{k}_{f}"), 32, true, 16);
            }
        }
    }
    l
}

/// The stages and their files.
pub const STAGES: [&str; 7] = [
    "setup", "bounds", "select", "sample", "bsample", "psample", "resolve",
];

/// Layout of `<stage>_in` or `<stage>_out`; `spp` sets the resolve width.
pub fn layout(file: &str, spp: u32) -> Layout {
    let l = Layout::default();
    match file {
        "setup_in" => tri_fields(l)
            .packed(&[("viewport_w", 16, false), ("viewport_h", 16, false)])
            .packed(&CONFIG_FIELDS),
        "setup_out" => {
            let mut l = l
                .packed(&[
                    ("visible", 1, false),
                    ("cull", 2, false),
                    ("class", 2, false),
                    ("box_x_lo", 1, false),
                    ("box_x_hi", 1, false),
                    ("box_y_lo", 1, false),
                    ("box_y_hi", 1, false),
                    ("lens_x", 1, false),
                    ("lens_y", 1, false),
                    ("dual_x", 1, false),
                    ("dual_y", 1, false),
                ])
                .packed(&[("fp_x0", 16, false), ("fp_y0", 16, false)])
                .packed(&[("fp_x1", 16, false), ("fp_y1", 16, false)])
                .w("span_lo", 32, true, 16)
                .w("span_hi", 32, true, 16);
            for a in ["x", "y"] {
                for side in ["lo", "hi"] {
                    for c in 0..2 {
                        l = l.w(&format!("box_{a}_{side}{c}"), 64, true, 16);
                    }
                }
            }
            l = l
                .w("eps_x", 32, true, 16)
                .w("eps_y", 32, true, 16)
                .w("eps_w", 32, true, 16);
            for a in ["x", "y"] {
                for side in ["lo", "hi"] {
                    l = l
                        .w(&format!("lens_{a}_{side}_base"), 64, true, 16)
                        .w(&format!("lens_{a}_{side}_d"), 64, true, 16)
                        .w(&format!("lens_{a}_{side}_rup"), 128, true, 80)
                        .w(&format!("lens_{a}_{side}_rdn"), 128, true, 80);
                }
            }
            for a in ["x", "y"] {
                l = l.w(&format!("dual_{a}_xi_a"), 32, true, 0).w(
                    &format!("dual_{a}_xi_b"),
                    32,
                    true,
                    0,
                );
                for m in ["lo", "hi"] {
                    for t in 0..2 {
                        for e in ["a", "b"] {
                            l = l.w(&format!("dual_{a}_{m}_t{t}_{e}"), 64, true, 16);
                        }
                    }
                }
            }
            l
        }
        "bounds_in" => l
            .w("tri", 32, false, 0)
            .packed(&[("x0", 16, false), ("y0", 16, false)])
            .packed(&[("x1", 16, false), ("y1", 16, false)]),
        "bounds_out" => l
            .packed(&[("nonempty", 1, false)])
            .w("u_lo", 32, true, 16)
            .w("u_hi", 32, true, 16)
            .w("v_lo", 32, true, 16)
            .w("v_hi", 32, true, 16)
            .w("t_lo", 32, true, 16)
            .w("t_hi", 32, true, 16),
        "select_in" => l
            .w("u_lo", 32, true, 16)
            .w("u_hi", 32, true, 16)
            .w("v_lo", 32, true, 16)
            .w("v_hi", 32, true, 16)
            .w("t_lo", 32, true, 16)
            .w("t_hi", 32, true, 16)
            .w("u", 32, true, 16)
            .w("v", 32, true, 16)
            .w("t", 32, true, 16),
        "select_out" => l.packed(&[("inside", 1, false)]),
        "sample_in" => l
            .w("tri", 32, false, 0)
            .packed(&[("px", 16, false), ("py", 16, false)])
            .packed(&[("sx", 8, false), ("sy", 8, false)])
            .w("u", 32, true, 16)
            .w("v", 32, true, 16)
            .w("t", 32, true, 16),
        "sample_out" => l
            .packed(&[("covered", 1, false), ("det_sign", 2, true)])
            .w("depth", 32, true, 24)
            .w("e0", 192, true, 0)
            .w("e1", 192, true, 0)
            .w("e2", 192, true, 0)
            .w("det", 192, true, 0),
        "bsample_in" => tri_fields(l)
            .packed(&[("viewport_w", 16, false), ("viewport_h", 16, false)])
            .packed(&[
                ("class", 2, false),
                ("off_shift", 6, false),
                ("pos_frac", 5, false),
                ("tuv_frac", 5, false),
            ])
            .w("xs", 32, false, 8)
            .w("ys", 32, false, 8)
            .w("t", 32, true, 16)
            .w("u", 32, true, 16)
            .w("v", 32, true, 16),
        "bsample_out" => l
            .packed(&[("covered", 1, false), ("det_sign", 2, true)])
            .w("depth", 32, true, 24)
            .w("a0", 32, true, 0)
            .w("b0", 32, true, 0)
            .w("a1", 32, true, 0)
            .w("b1", 32, true, 0)
            .w("a2", 32, true, 0)
            .w("b2", 32, true, 0)
            .w("e0", 64, true, 0)
            .w("e1", 64, true, 0)
            .w("e2", 64, true, 0),
        "psample_in" => {
            let mut l = l;
            for k in 0..3 {
                for f in ["x", "y", "z", "w"] {
                    l = l.w(&format!("v{k}_{f}"), 32, true, 16);
                }
            }
            l = l.packed(&[("viewport_w", 16, false), ("viewport_h", 16, false)]);
            for k in 0..3 {
                for f in ["a", "b", "c"] {
                    l = l.w(&format!("n{k}_{f}"), 32, true, 0);
                }
            }
            l.packed(&[("sigma", 2, true), ("f", 8, true)])
                .w("g0", 32, true, 0)
                .w("g1", 32, true, 0)
                .w("g2", 32, true, 0)
                .w("xs", 32, false, 8)
                .w("ys", 32, false, 8)
        }
        "psample_out" => l
            .packed(&[("covered", 1, false)])
            .w("depth", 32, true, 24)
            .w("e0", 64, true, 0)
            .w("e1", 64, true, 0)
            .w("e2", 64, true, 0),
        "resolve_in" => {
            let mut l = l;
            for s in 0..spp {
                l = l.packed(&[
                    (&format!("s{s}_b"), 8, false),
                    (&format!("s{s}_g"), 8, false),
                    (&format!("s{s}_r"), 8, false),
                ]);
            }
            l
        }
        "resolve_out" => l.packed(&[("b", 8, false), ("g", 8, false), ("r", 8, false)]),
        _ => Layout::default(),
    }
}

/// A record being built, word by word in layout order.
#[derive(Default, Clone, Debug, PartialEq, Eq)]
pub struct Rec(pub Vec<u32>);

impl Rec {
    /// Append a 32-bit word.
    pub fn u32(mut self, v: u32) -> Self {
        self.0.push(v);
        self
    }
    /// Append an i32.
    pub fn i32(self, v: i32) -> Self {
        self.u32(v as u32)
    }
    /// Append an i64 (2 words, MS first).
    pub fn i64(self, v: i64) -> Self {
        self.u32((v >> 32) as u32).u32(v as u32)
    }
    /// Append an i128 (4 words).
    pub fn i128(self, v: i128) -> Self {
        self.i64((v >> 64) as i64).i64(v as i64)
    }
    /// Append a 192-bit value `hi·2^64 + lo` (6 words).
    pub fn wide(self, hi: i128, lo: u64) -> Self {
        self.i128(hi).i64(lo as i64)
    }
    /// Append a word of packed sub-fields `(value, width)`, LSB first.
    pub fn packed(self, subs: &[(i64, u32)]) -> Self {
        let mut w = 0u32;
        let mut bit = 0;
        for &(v, width) in subs {
            let mask = if width >= 32 {
                u32::MAX
            } else {
                (1u32 << width) - 1
            };
            w |= ((v as u32) & mask) << bit;
            bit += width;
        }
        self.u32(w)
    }
}

/// Raw value of a field as a signed big integer (as i128 for ≤ 128 bits; wider fields are
/// returned as their top 128 bits plus a flag that lower bits exist — enough for messages).
pub fn field_value(f: &RecField, words: &[u32]) -> (i128, Option<u64>) {
    if f.width <= 32 {
        let w = words.get(f.word as usize).copied().unwrap_or(0);
        let raw = (w >> f.bit) as u64
            & if f.width == 32 {
                u32::MAX as u64
            } else {
                (1u64 << f.width) - 1
            };
        let v = if f.signed && f.width < 64 && raw >> (f.width - 1) & 1 == 1 {
            raw as i128 - (1i128 << f.width)
        } else {
            raw as i128
        };
        return (v, None);
    }
    let n = f.words() as usize;
    let ws: Vec<u32> = (0..n)
        .map(|i| words.get(f.word as usize + i).copied().unwrap_or(0))
        .collect();
    let take = n.min(4);
    let mut v: i128 = if ws[0] >> 31 == 1 && f.signed { -1 } else { 0 };
    for w in &ws[..take] {
        v = (v << 32) | *w as i128;
    }
    let rest = if n > 4 {
        Some(ws[4..].iter().fold(0u64, |a, w| (a << 32) | *w as u64))
    } else {
        None
    };
    (v, rest)
}

/// A field's raw value as hex and decoded, for messages.
pub fn show_field(f: &RecField, words: &[u32]) -> String {
    let (v, rest) = field_value(f, words);
    if f.width < 32 {
        // a sub-word field: its own bits, not its word's
        let w = words.get(f.word as usize).copied().unwrap_or(0);
        let raw = (w >> f.bit) & ((1u32 << f.width) - 1);
        let digits = f.width.div_ceil(4) as usize;
        return format!("0x{raw:0digits$x} = {v}");
    }
    let n = f.words() as usize;
    let hex: Vec<String> = (0..n)
        .map(|i| {
            format!(
                "{:08x}",
                words.get(f.word as usize + i).copied().unwrap_or(0)
            )
        })
        .collect();
    let dec = match rest {
        Some(lo) => format!("{v}·2^64 + {lo}"),
        None if f.frac > 0 => format!("{} ({v}/2^{})", v as f64 / 2f64.powi(f.frac as i32), f.frac),
        None => format!("{v}"),
    };
    format!("0x{} = {dec}", hex.join("_"))
}

/// A file's text from its records.
pub fn to_text(records: &[Rec]) -> String {
    let mut s = String::new();
    for r in records {
        let line: Vec<String> = r.0.iter().map(|w| format!("{w:08x}")).collect();
        s += &line.join(" ");
        s.push('\n');
    }
    s
}

/// Parse a file's text into records of `words` words; errors name the line.
pub fn parse(text: &str, words: u32, file: &str) -> Result<Vec<Vec<u32>>, String> {
    text.lines()
        .enumerate()
        .map(|(i, line)| {
            let ws: Result<Vec<u32>, _> = line
                .split(' ')
                .map(|h| u32::from_str_radix(h, 16))
                .collect();
            match ws {
                Ok(ws) if ws.len() == words as usize && line.split(' ').all(|h| h.len() == 8) => {
                    Ok(ws)
                }
                Ok(ws) => Err(format!(
                    "{file} line {}: {} words, expected {words}",
                    i + 1,
                    ws.len()
                )),
                Err(e) => Err(format!("{file} line {}: not hex: {e}", i + 1)),
            }
        })
        .collect()
}

/// Lower-case hex SHA-256.
pub fn sha256(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// Markdown bit-layout table of one file (MSB..LSB per word).
pub fn layout_md(file: &str, spp: u32) -> String {
    let l = layout(file, spp);
    let mut s = format!("`{file}.hex`: {} words per record\n\n| word | bits (MSB..LSB) | field | signed | frac |\n|---|---|---|---|---|\n", l.words);
    let mut fields: Vec<&RecField> = l.fields.iter().collect();
    fields.sort_by_key(|f| (f.word, std::cmp::Reverse(f.bit)));
    for f in fields {
        let (w, bits) = if f.width > 32 {
            (
                format!("{}..{}", f.word, f.word + f.words() - 1),
                format!("{}..0 ({} words, MS word first)", f.width - 1, f.words()),
            )
        } else {
            (
                format!("{}", f.word),
                if f.width == 1 {
                    format!("{}", f.bit)
                } else {
                    format!("{}..{}", f.bit + f.width - 1, f.bit)
                },
            )
        };
        s += &format!(
            "| {w} | {bits} | {} | {} | {} |\n",
            f.name,
            if f.signed { "yes" } else { "no" },
            f.frac
        );
    }
    s
}
